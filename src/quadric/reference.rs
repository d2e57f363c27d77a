//! The scalar reference: the [filter](super::stages) at `f64`, then the
//! later stages ([`crate::stage`]) for whatever it leaves undecided, the
//! exact oracle last.

use super::packed::Packed;
use super::{Quadric, QuadricHit, exact, stages};
use crate::Ray;
use crate::num::certify::{certify, denormals_are_zero, flush_prone, needs_probe, subnormals_work};
use crate::stage::Stage;

/// Intersects a line with a quadric: the exact class over `t ∈ ℝ`, and the
/// roots correctly rounded to `f32`. A NaN or infinite input gives
/// [`QuadricHit::None`].
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit, reference::intersect}};
/// use glam::Vec3;
/// // The unit cylinder x² + y² = 1.
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// assert_eq!(intersect(&Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X), &cyl), QuadricHit::Two(4.0, 6.0));
/// // Parallel to the axis, on the surface: every t.
/// assert_eq!(intersect(&Ray::new(Vec3::X, Vec3::Z), &cyl), QuadricHit::All);
/// // The paraboloid z = x² + y² along its axis: α = 0, one root.
/// let bowl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0]);
/// assert_eq!(intersect(&Ray::new(Vec3::new(0.0, 0.0, -2.0), Vec3::Z), &bowl), QuadricHit::One(2.0));
/// ```
#[inline]
pub fn intersect(ray: &Ray, quadric: &Quadric) -> QuadricHit {
    intersect_staged(ray, quadric).0
}

/// [`intersect`], and the [`Stage`] that decided it.
///
/// ```
/// use rayoracle::{Ray, stage::Stage, quadric::{Quadric, QuadricHit, reference::intersect_staged}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let r = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X);
/// assert_eq!(intersect_staged(&r, &cyl), (QuadricHit::Two(4.0, 6.0), Stage::Filter));
/// ```
#[inline]
pub fn intersect_staged(ray: &Ray, quadric: &Quadric) -> (QuadricHit, Stage) {
    intersect_shrunk(ray, quadric, 1.0)
}

/// [`intersect_staged`] with every stage's bounds multiplied by `shrink`:
/// for the tests that show a bound too small gives wrong answers.
#[doc(hidden)]
#[inline(always)]
pub fn intersect_shrunk(ray: &Ray, quadric: &Quadric, shrink: f64) -> (QuadricHit, Stage) {
    // The environment meets an input only through DAZ, and a result only
    // through FTZ where it is subnormal ([`needs_probe`]): the inputs are
    // scanned only under DAZ, and the register read only for such a
    // result.
    let inputs = inputs(ray, quadric);
    if denormals_are_zero() && needs_probe(&inputs, &[]) {
        return (exact_stage(ray, quadric), Stage::Exact);
    }
    let w = |v: glam::Vec3| v.as_dvec3().to_array();
    let (k, o, d) = (widen(&quadric.coeffs), w(ray.origin), w(ray.dir));
    let c = stages::classes_paired(&k, o, d, shrink);
    if c.two
        && let Some((t0, t1)) = stages::sorted(&c, shrink)
    {
        return two(ray, quadric, t0, t1);
    }
    rest(ray, quadric, c, shrink)
}

/// What [`stages::sorted`] leaves: the filter's other classes, then its
/// quotients, then the later stages. Apart from the fast path, so that
/// the tests of the other classes are made only here.
#[inline(always)]
fn rest(ray: &Ray, quadric: &Quadric, c: stages::Classes<f64>, shrink: f64) -> (QuadricHit, Stage) {
    if !(c.two || c.linear()) {
        return if c.none() {
            (QuadricHit::None, Stage::Filter)
        } else if c.all() {
            (QuadricHit::All, Stage::Filter)
        } else {
            later(ray, quadric, c.left(), shrink)
        };
    }
    quotients(ray, quadric, c, shrink).unpack()
}

/// The roots by [`stages::roots`], as `q/α` and `γ/q`: for the linear
/// class, and for two roots that [`stages::sorted`] did not certify. The
/// answer [`Packed`], as [`later_in`]'s.
#[inline(never)]
fn quotients(ray: &Ray, quadric: &Quadric, c: stages::Classes<f64>, shrink: f64) -> Packed {
    let f = stages::roots(&c, shrink);
    if f.two && certify(f.t0, f.r0, f.a0) && certify(f.t1, f.r1, f.a1) {
        Packed::of(two(ray, quadric, f.t0, f.t1))
    } else if f.linear && certify(f.t1, f.r1, f.a1) {
        if needs_probe(&[], &[f.t1]) && !subnormals_work() {
            return Packed::of((exact_stage(ray, quadric), Stage::Exact));
        }
        Packed::of((QuadricHit::One(f.t1 as f32), Stage::Filter))
    } else if f.none {
        Packed::of((QuadricHit::None, Stage::Filter))
    } else if f.all {
        Packed::of((QuadricHit::All, Stage::Filter))
    } else {
        let left = c.left();
        later_in(ray, quadric, left.alpha, left.beta, left.gamma, shrink)
    }
}

/// Two certified roots, sorted, or the oracle's answer where FTZ could
/// have flushed one.
#[inline(always)]
fn two(ray: &Ray, quadric: &Quadric, t0: f64, t1: f64) -> (QuadricHit, Stage) {
    if needs_probe(&[], &[t0, t1]) && !subnormals_work() {
        return (exact_stage(ray, quadric), Stage::Exact);
    }
    // Disjoint enclosures are in the exact order; overlapping ones round
    // to the same f32.
    let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
    (QuadricHit::Two(t0 as f32, t1 as f32), Stage::Filter)
}

/// [`stages::later`] on inputs already checked by [`needs_probe`], widened
/// here rather than passed: the fast path would otherwise store the
/// widened inputs to memory on every call, for a call it rarely makes.
/// Then the exact oracle where it gives nothing or a result that FTZ could
/// have flushed. The filter's sums ([`stages::Left`]) come as three
/// pairs, in registers.
#[inline(always)]
fn later(ray: &Ray, quadric: &Quadric, left: stages::Left, shrink: f64) -> (QuadricHit, Stage) {
    later_in(ray, quadric, left.alpha, left.beta, left.gamma, shrink).unpack()
}

/// [`later`], out of line, its answer [`Packed`] (see there why).
#[cold]
#[inline(never)]
fn later_in(
    ray: &Ray,
    quadric: &Quadric,
    alpha: (f64, f64),
    beta: (f64, f64),
    gamma: (f64, f64),
    shrink: f64,
) -> Packed {
    let left = stages::Left { alpha, beta, gamma };
    let w = |v: glam::Vec3| v.as_dvec3().to_array();
    let inputs = || (widen(&quadric.coeffs), w(ray.origin), w(ray.dir));
    later_with(inputs, || (*ray, *quadric), left, shrink)
}

/// [`later`] on the inputs that `inputs` widens where they lie (each
/// stage calls it again rather than keep widened values, see
/// [`stages::later_of`]); `line` gives them as a ray and a quadric, for
/// the oracle.
#[inline(always)]
fn later_with<I>(
    inputs: I,
    line: impl Fn() -> (Ray, Quadric),
    left: stages::Left,
    shrink: f64,
) -> Packed
where
    I: Fn() -> ([f64; 10], [f64; 3], [f64; 3]),
{
    let exact = || {
        let (ray, quadric) = line();
        (exact_stage(&ray, &quadric), Stage::Exact)
    };
    // The answer is settled inside the copy that runs, and returned from
    // there: an `Option` passed back through memory, stored field by
    // field and read back whole, stalled store forwarding.
    stages::later_of(inputs, left, shrink, |h| {
        Packed::of(match h {
            Some((h, _)) if prone(h) && !subnormals_work() => exact(),
            Some(hs) => hs,
            None => exact(),
        })
    })
}

/// [`flush_prone`] on the roots, read from the answer where it lies
/// rather than gathered into a slice.
#[inline(always)]
fn prone(h: QuadricHit) -> bool {
    match h {
        QuadricHit::One(t) => flush_prone(&[t]),
        QuadricHit::Two(a, b) => flush_prone(&[a, b]),
        QuadricHit::None | QuadricHit::All => false,
    }
}

/// The whole reference for lane `i` of x4's packets (`coeffs` the
/// quadrics' coefficients widened, lane by lane): the filter, then the
/// stages after it ([`stages::later`]) and the exact oracle. The later
/// stages, too, assume subnormals work where an input or a result is
/// subnormal ([`needs_probe`], [`flush_prone`]), so this checks for
/// itself: x4 sends its undecided lanes here, and all of them when FTZ or
/// DAZ is on. The inputs are read from the packets where they lie: a ray
/// and a quadric built on the stack and read back at other widths stalled
/// store forwarding on every lane (`rayoracle report`, x4 on
/// quadric/line-on-surface: 72 against 37 ns a ray). The answer comes back
/// [`Packed`], in registers.
#[cold]
#[inline(never)]
pub(crate) fn escalate_lane(rays: &crate::ray4::Ray4, coeffs: &[[f64; 4]; 10], i: usize) -> Packed {
    // Written out: `array::map` is not always inlined.
    let lane = |v: &[wide::f32x4; 3]| {
        let x = |j: usize| v[j].as_array()[i];
        [x(0), x(1), x(2)]
    };
    let line = || {
        let (o, d) = (lane(&rays.origin), lane(&rays.dir));
        let mut k = [0.0; 10];
        for (k, w) in k.iter_mut().zip(coeffs) {
            *k = crate::num::certify::narrow_exact(w[i]);
        }
        (
            Ray::new(glam::Vec3::from(o), glam::Vec3::from(d)),
            Quadric::new(k),
        )
    };
    let inputs = || {
        let mut k = [0.0; 10];
        for (k, w) in k.iter_mut().zip(coeffs) {
            *k = w[i];
        }
        let w = |v: &[wide::f32x4; 3]| {
            let x = lane(v);
            [f64::from(x[0]), f64::from(x[1]), f64::from(x[2])]
        };
        (k, w(&rays.origin), w(&rays.dir))
    };
    if denormals_are_zero() {
        let (ray, quadric) = line();
        if needs_probe(&self::inputs(&ray, &quadric), &[]) {
            return Packed::of((exact_stage(&ray, &quadric), Stage::Exact));
        }
    }
    let (k, o, d) = inputs();
    later_with(
        inputs,
        line,
        stages::classes_paired(&k, o, d, 1.0).left(),
        1.0,
    )
}

/// The coefficients in f64, by a plain loop: `array::map` is not always
/// inlined, and a call per case costs a fifth of a fast path.
#[inline(always)]
fn widen(c: &[f32; 10]) -> [f64; 10] {
    let mut k = [0.0; 10];
    for (k, c) in k.iter_mut().zip(c) {
        *k = f64::from(*c);
    }
    k
}

/// The inputs, for [`needs_probe`].
#[inline(always)]
fn inputs(ray: &Ray, quadric: &Quadric) -> [f32; 16] {
    let (o, d, k) = (ray.origin, ray.dir, &quadric.coeffs);
    [
        o.x, o.y, o.z, d.x, d.y, d.z, k[0], k[1], k[2], k[3], k[4], k[5], k[6], k[7], k[8], k[9],
    ]
}

/// The last stage: the exact oracle; [`QuadricHit::None`] for a non-finite
/// input.
fn exact_stage(ray: &Ray, quadric: &Quadric) -> QuadricHit {
    exact::intersect(ray, quadric).unwrap_or(QuadricHit::None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// x4's way into the scalar stages for one line, in lane 0.
    fn escalate(ray: &Ray, quadric: &Quadric) -> (QuadricHit, Stage) {
        let q = super::super::x4::Quadric4::splat(quadric);
        escalate_lane(&crate::ray4::Ray4::splat(*ray), q.f64_lanes(), 0).unpack()
    }

    /// A unit sphere written as a quadric, touched by a line at `t =
    /// 2⁻¹⁴⁰`, a subnormal f32 that the tracked stage finds from a
    /// subnormal origin. x4's way into the later stages
    /// ([`escalate_lane`], here in lane 0) takes the reference's stage
    /// (it probes the inputs only under DAZ); under flush-to-zero, where rounding the root to f32 gives 0, the
    /// oracle answers instead, as it does under denormals-are-zero.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn a_subnormal_root_of_a_later_stage_is_kept_from_ftz() {
        let t = 2f32.powi(-140);
        let q = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let r = Ray::new(Vec3::new(0.0, 1.0, -t), Vec3::Z);
        let want = (QuadricHit::One(t), Stage::Tracked);
        assert_eq!(intersect_staged(&r, &q), want);
        assert_eq!(escalate(&r, &q), want);
        let ftz =
            crate::num::certify::in_environment(true, false, move || intersect_staged(&r, &q));
        assert_eq!(ftz, (QuadricHit::One(t), Stage::Exact));
        // Under DAZ the origin would read as 0, and the root as 0: both
        // ways in probe the inputs and ask the oracle.
        let daz = crate::num::certify::in_environment(false, true, move || {
            (intersect_staged(&r, &q), escalate(&r, &q))
        });
        let exact = (QuadricHit::One(t), Stage::Exact);
        assert_eq!(daz, (exact, exact));
    }

    /// The same sphere and a line that misses it by `2⁻¹⁴⁹`, the least
    /// subnormal, in its origin's `x`: the double-word stage proves the
    /// miss.
    /// Under DAZ that `x` would read as 0 and the line would touch the
    /// sphere at `t = 5`, a normal root that nothing downstream would
    /// question: only the probe of the inputs sends it to the oracle.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn under_daz_a_subnormal_input_goes_to_the_oracle() {
        let q = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let r = Ray::new(Vec3::new(f32::from_bits(1), 1.0, -5.0), Vec3::Z);
        let want = (QuadricHit::None, Stage::DoubleWord);
        assert_eq!((intersect_staged(&r, &q), escalate(&r, &q)), (want, want));
        let daz = crate::num::certify::in_environment(false, true, move || {
            (intersect_staged(&r, &q), escalate(&r, &q))
        });
        let exact = (QuadricHit::None, Stage::Exact);
        assert_eq!(daz, (exact, exact));
    }
}
