//! The scalar reference: the [filter](super::stages) at `f64`, then the
//! later stages ([`crate::stage`]) for whatever it leaves undecided, the
//! exact oracle last.

use super::{Plane, PlaneHit, exact, stages};
use crate::Ray;
use crate::hit::Intersection;
use crate::num::certify::{
    certify, certify_relative, denormals_are_zero, flush_prone, needs_probe, subnormals_work,
};
use crate::num::dd::two_sum;
use crate::stage::Stage;

/// Intersects a line with a plane: the exact class over `t ∈ ℝ`, and the
/// root correctly rounded to `f32`. A NaN or infinite input gives
/// [`PlaneHit::Parallel`], no point.
///
/// ```
/// use rayoracle::{Ray, plane::{Plane, PlaneHit, reference::intersect}};
/// use glam::Vec3;
/// let p = Plane::new(Vec3::new(0.0, 0.0, 3.0), Vec3::Z);
/// assert_eq!(intersect(&Ray::new(Vec3::ZERO, Vec3::Z), &p), PlaneHit::Hit(3.0));
/// assert_eq!(intersect(&Ray::new(Vec3::ZERO, Vec3::X), &p), PlaneHit::Parallel);
/// assert_eq!(intersect(&Ray::new(Vec3::new(0.0, 0.0, 3.0), Vec3::X), &p), PlaneHit::InPlane);
/// // Parallel in exact arithmetic only: d·n = 1 − 1 + 0.
/// let tilted = Plane::new(Vec3::ZERO, Vec3::new(1.0, -1.0, 0.0));
/// assert_eq!(intersect(&Ray::new(Vec3::Z, Vec3::new(1.0, 1.0, 0.0)), &tilted), PlaneHit::InPlane);
/// ```
#[inline]
pub fn intersect(ray: &Ray, plane: &Plane) -> PlaneHit {
    match first_pass(ray, plane, 1.0) {
        Ok(h) => h,
        Err(x) => {
            let [p0, p1, p2] = x.dn;
            second_pass(ray, plane, x.num, x.den, x.m_num, p0, p1, p2, 1.0)
        }
    }
}

/// [`intersect`], and the [`Stage`] that decided it.
///
/// ```
/// use rayoracle::{Ray, stage::Stage, plane::{Plane, PlaneHit, reference::intersect_staged}};
/// use glam::Vec3;
/// let p = Plane::new(Vec3::new(0.0, 0.0, 3.0), Vec3::Z);
/// assert_eq!(intersect_staged(&Ray::new(Vec3::ZERO, Vec3::Z), &p), (PlaneHit::Hit(3.0), Stage::Filter));
/// ```
#[inline]
pub fn intersect_staged(ray: &Ray, plane: &Plane) -> (PlaneHit, Stage) {
    intersect_shrunk(ray, plane, 1.0)
}

/// [`intersect_staged`] with every stage's bounds multiplied by `shrink`:
/// for the tests that show a bound too small gives wrong answers.
#[doc(hidden)]
#[inline(always)]
pub fn intersect_shrunk(ray: &Ray, plane: &Plane, shrink: f64) -> (PlaneHit, Stage) {
    match first_pass(ray, plane, shrink) {
        Ok(h) => (h, Stage::Filter),
        Err(x) => {
            let [p0, p1, p2] = x.dn;
            second_pass(ray, plane, x.num, x.den, x.m_num, p0, p1, p2, shrink)
        }
    }
}

/// The first pass: the root it certifies, or its sums for the passes
/// after it.
#[inline(always)]
fn first_pass(ray: &Ray, plane: &Plane, shrink: f64) -> Result<PlaneHit, stages::First<f64>> {
    // The environment meets an input only through DAZ, and a result only
    // through FTZ where it is subnormal ([`needs_probe`]). The first pass
    // certifies no subnormal root, and nothing under DAZ; after it, the
    // inputs are scanned only under DAZ (where clean ones take the first
    // pass again, as without DAZ), and the full filter reads the register
    // only for a subnormal root.
    let w = |v: glam::Vec3| v.as_dvec3().to_array();
    let (o, d, a, n) = (w(ray.origin), w(ray.dir), w(plane.point), w(plane.normal));
    // The first pass, whose bound needs nothing after the division; the
    // second pass and the full filter only for what it leaves, from the
    // same sums.
    let (pairs, f) = stages::first_pair(o, d, a, n, shrink);
    // The pass's class is known before its quotient: a line it leaves
    // does not wait on the division (which the CPU starts anyway, on the
    // predicted path).
    if f.hit {
        // A root the pass certifies is normal as an f32: no flush to ask
        // about.
        if certify_relative(f.t, f.r) {
            return Ok(PlaneHit::Hit(f.t as f32));
        }
    }
    Err(pairs.first())
}

/// What a caller takes from the passes after the first: [`intersect`]
/// the answer alone, which comes back in a register (the pair goes
/// through memory); [`intersect_staged`] the stage too.
trait Answer {
    fn of(hs: (PlaneHit, Stage)) -> Self;
}

impl Answer for PlaneHit {
    #[inline(always)]
    fn of(hs: (PlaneHit, Stage)) -> Self {
        hs.0
    }
}

impl Answer for (PlaneHit, Stage) {
    #[inline(always)]
    fn of(hs: (PlaneHit, Stage)) -> Self {
        hs
    }
}

crate::num::cold::keeps_vector_registers! {
    /// The second pass, out of line (inlined, it slowed the first pass by
    /// about a seventh), then the rest, out of line again. In the calling
    /// convention that saves the caller's vector registers
    /// ([`crate::num::cold`]), so that a loop around an inlined
    /// [`intersect`] keeps the plane in registers. The first pass's sums
    /// and the products `dᵢnᵢ` come as scalars: a struct or an array of
    /// them is built in memory on the hot path. A line whose sums both
    /// came out 0, as on a line in the plane, is settled by [`zero_sums`]
    /// where it can be.
    #[cold]
    #[inline(never)]
    #[allow(clippy::too_many_arguments)]
    fn second_pass<A: Answer>(
        ray: &Ray,
        plane: &Plane,
        num: f64,
        den: f64,
        m_num: f64,
        p0: f64,
        p1: f64,
        p2: f64,
        shrink: f64,
    ) -> A {
        A::of(passes(ray, plane, num, den, m_num, [p0, p1, p2], shrink))
    }
}

/// The body of [`second_pass`].
#[inline(always)]
fn passes(
    ray: &Ray,
    plane: &Plane,
    num: f64,
    den: f64,
    m_num: f64,
    dn: [f64; 3],
    shrink: f64,
) -> (PlaneHit, Stage) {
    let x = stages::First {
        num,
        den,
        m_num,
        // Read by the first pass only, which runs again only under DAZ.
        lead: 0.0,
        dn,
    };
    if denormals_are_zero() {
        if needs_probe(&inputs(ray, plane), &[]) {
            return (exact_stage(ray, plane), Stage::Exact);
        }
        // No input is subnormal, so DAZ meets none, and the first pass,
        // which certifies nothing under DAZ, runs again with the least
        // subnormal itself: it certifies what it certifies without DAZ.
        let x = stages::First {
            lead: dn[0] + dn[1],
            ..x
        };
        let f = stages::relative_terms_with(&x, 2f64.powi(-149), shrink);
        if f.hit && certify_relative(f.t, f.r) {
            return (PlaneHit::Hit(f.t as f32), Stage::Filter);
        }
    }
    // Both sums ±0, one branch for the two.
    if (num.to_bits() | den.to_bits()) << 1 == 0
        && let Some(hs) = zero_sums(ray, plane, m_num, dn)
    {
        return hs;
    }
    match compensated(ray, plane, &x, shrink) {
        Some(hs) => hs,
        None => filter_then_escalate(ray, plane, x.terms(), shrink),
    }
}

/// A line whose sums the first pass computed as 0, as on a line in the
/// plane, decided as [`compensated`] decides it, without its hit test:
/// `fl(ŝ₁ + d₂n₂) = 0` means `ŝ₁ = −d₂n₂` exactly (no sum of these
/// multiples of `2⁻²⁹⁸` rounds to 0 unless it is 0), so `d·n` is the
/// rounding error of `ŝ₁ = fl(d₀n₀ + d₁n₁)`, which TwoSum gives exactly.
/// Where it is 0, `(a − o)·n` comes from [`stages::exact_num`]. `None`
/// where neither settles the line.
#[inline(always)]
fn zero_sums(ray: &Ray, plane: &Plane, m_num: f64, p: [f64; 3]) -> Option<(PlaneHit, Stage)> {
    if two_sum(p[0], p[1]).1 != 0.0 {
        return None;
    }
    // Every term of both sums ±0, one branch for the four.
    if (p[0].to_bits() | p[1].to_bits() | p[2].to_bits() | m_num.to_bits()) << 1 == 0 {
        return Some((PlaneHit::InPlane, Stage::Filter));
    }
    let w = |v: glam::Vec3| v.as_dvec3().to_array();
    let (exact, num) = stages::exact_num(w(ray.origin), w(plane.point), w(plane.normal));
    exact.then_some((
        if num == 0.0 {
            PlaneHit::InPlane
        } else {
            PlaneHit::Parallel
        },
        Stage::Tight,
    ))
}

/// The [second pass](stages::filter_compensated), from the first pass's
/// sums: a hit certified with `d·n` summed once compensated, or a line
/// with `d·n = 0` exactly, off the plane by the filter's bound or in it by
/// [`stages::exact_num`]. A line whose terms of `d·n` are all 0, and of
/// `(a − o)·n` too or off the plane by the bound, is counted to the filter,
/// whose own rule decides it; the rest to the tight stage, whose exact sum
/// this shortens.
#[inline(always)]
fn compensated(
    ray: &Ray,
    plane: &Plane,
    x: &stages::First<f64>,
    shrink: f64,
) -> Option<(PlaneHit, Stage)> {
    // The inputs stand (the callers' check of the environment): the
    // least subnormal is itself.
    let c = stages::compensated_terms(x.num, x.m_num, x.dn, 2f64.powi(-149), shrink);
    let f = c.relative;
    // A hit has d·n ≠ 0, so some term of it is not 0: the check below
    // waits for the lines this leaves.
    if f.hit && certify_relative(f.t, f.r) {
        return Some((PlaneHit::Hit(f.t as f32), Stage::Tight));
    }
    let p = x.dn;
    let m_den = p[0].abs() + p[1].abs() + p[2].abs();
    if m_den == 0.0 && x.m_num == 0.0 {
        // Every term of both sums is 0: the filter's rule, without the
        // exact sum.
        return Some((PlaneHit::InPlane, Stage::Filter));
    }
    if f.hit {
        // A hit whose root this bound cannot place: the full filter's.
        return None;
    } else if c.parallel {
        let stage = if m_den == 0.0 {
            Stage::Filter
        } else {
            Stage::Tight
        };
        return Some((PlaneHit::Parallel, stage));
    } else if c.den_zero {
        let w = |v: glam::Vec3| v.as_dvec3().to_array();
        let (exact, num) = stages::exact_num(w(ray.origin), w(plane.point), w(plane.normal));
        if !exact {
            return None;
        }
        return Some(if num == 0.0 {
            (PlaneHit::InPlane, Stage::Tight)
        } else {
            (PlaneHit::Parallel, Stage::Tight)
        });
    }
    None
}

/// The full [filter](stages::filter), for a line the first pass leaves
/// (sums that cancel, a parallel line, a root near a rounding boundary or
/// subnormal), then the later stages. The inputs are known to stand: DAZ
/// is off or none is subnormal. A line whose `d·n` cancels so far that
/// the filter cannot certify its root ([`stages::Terms::hopeless`]) goes
/// straight to the later stages.
#[cold]
#[inline(never)]
fn filter_then_escalate(
    ray: &Ray,
    plane: &Plane,
    x: stages::Terms<f64>,
    shrink: f64,
) -> (PlaneHit, Stage) {
    if x.hopeless(shrink) {
        return later_stages(ray, plane, shrink);
    }
    let f = stages::filter_terms(x, shrink);
    if f.hit && certify(f.t, f.r, f.a) {
        if needs_probe(&[], &[f.t]) && !subnormals_work() {
            return (exact_stage(ray, plane), Stage::Exact);
        }
        (PlaneHit::Hit(f.t as f32), Stage::Filter)
    } else if f.parallel {
        (PlaneHit::Parallel, Stage::Filter)
    } else if f.in_plane {
        (PlaneHit::InPlane, Stage::Filter)
    } else {
        later_stages(ray, plane, shrink)
    }
}

/// The stages after the filter: `d·n` summed exactly
/// ([`stages::tight`]), double-word arithmetic on exact products, which
/// settles the exact zeros ([`stages::double_word`]), then the exact
/// oracle. The later stages,
/// too, assume subnormals work where an input or a result is subnormal
/// ([`needs_probe`], [`flush_prone`]), so this checks for itself: x4 sends
/// its undecided lanes here, and all of them when FTZ or DAZ is on.
#[cold]
#[inline(never)]
pub(crate) fn escalate(ray: &Ray, plane: &Plane) -> (PlaneHit, Stage) {
    if denormals_are_zero() && needs_probe(&inputs(ray, plane), &[]) {
        return (exact_stage(ray, plane), Stage::Exact);
    }
    let w = |v: glam::Vec3| v.as_dvec3().to_array();
    let (o, d, a, n) = (w(ray.origin), w(ray.dir), w(plane.point), w(plane.normal));
    if let Some(hs) = compensated(ray, plane, &stages::first_terms(o, d, a, n), 1.0) {
        return hs;
    }
    later_stages(ray, plane, 1.0)
}

/// The stages after the filter, their bounds multiplied by `shrink`, for
/// inputs known to stand (DAZ off, or no input subnormal).
#[inline(always)]
fn later_stages(ray: &Ray, plane: &Plane, shrink: f64) -> (PlaneHit, Stage) {
    let w = |v: glam::Vec3| v.as_dvec3().to_array();
    let (o, d, a, n) = (w(ray.origin), w(ray.dir), w(plane.point), w(plane.normal));
    let staged = (stages::tight(o, d, a, n, shrink).map(|h| (h, Stage::Tight)))
        .or_else(|| stages::double_word(o, d, a, n, shrink).map(|h| (h, Stage::DoubleWord)));
    match staged {
        Some((h, _)) if flush_prone(h.roots().as_slice()) && !subnormals_work() => {
            (exact_stage(ray, plane), Stage::Exact)
        }
        Some(hs) => hs,
        None => (exact_stage(ray, plane), Stage::Exact),
    }
}

/// The inputs, for [`needs_probe`].
#[inline(always)]
fn inputs(ray: &Ray, plane: &Plane) -> [f32; 12] {
    let (o, d, a, n) = (ray.origin, ray.dir, plane.point, plane.normal);
    [o.x, o.y, o.z, d.x, d.y, d.z, a.x, a.y, a.z, n.x, n.y, n.z]
}

/// The last stage: the exact oracle; [`PlaneHit::Parallel`] for a
/// non-finite input.
fn exact_stage(ray: &Ray, plane: &Plane) -> PlaneHit {
    exact::intersect(ray, plane).unwrap_or(PlaneHit::Parallel)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// x4's way into the later stages, [`escalate`], probes the inputs
    /// only under DAZ, as the reference does: a line the tight stage
    /// decides is decided there, with a subnormal input or without.
    #[test]
    fn escalate_takes_the_stages_the_reference_takes() {
        // d·n = 1 + 2⁻⁶⁰ − (1 − 2⁻²⁰), past the first pass: its partial
        // sum rounds.
        let s = 2f32.powi(-30);
        let p = Plane::new(Vec3::X, Vec3::new(1.0, s, 2f32.powi(-20) - 1.0));
        let want = PlaneHit::Hit(2f32.powi(20));
        for z in [0.0, 1e-40] {
            let r = Ray::new(Vec3::new(0.0, z, 0.0), Vec3::new(1.0, s, 1.0));
            assert_eq!(escalate(&r, &p), (want, Stage::Tight), "z = {z:e}");
            assert_eq!(intersect_staged(&r, &p), (want, Stage::Tight), "z = {z:e}");
        }
    }

    /// Under DAZ, a line with no subnormal input is decided as without
    /// it, by the same stage: the first pass runs again for it, with the
    /// least subnormal itself. A subnormal input goes to the exact oracle,
    /// with the same answer.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn under_daz_clean_lines_take_the_stages_they_take_without_it() {
        use crate::num::certify::in_environment;
        let p = Plane::new(Vec3::new(0.0, -1.0, 0.0), Vec3::new(0.05, 1.0, 0.02));
        let mut rays: Vec<Ray> = (0..256)
            .map(|i| {
                let (x, y) = ((i % 16) as f32 / 8.0 - 1.0, (i / 16) as f32 / 8.0 - 1.0);
                Ray::new(Vec3::new(0.0, 1.0, 6.0), Vec3::new(x, y - 0.15, -1.0))
            })
            .collect();
        // A ray with a subnormal component, which DAZ would read as 0.
        let tiny = f32::from_bits(3);
        rays.push(Ray::new(
            Vec3::new(tiny, 1.0, 6.0),
            Vec3::new(0.1, -1.0, -1.0),
        ));
        let run = move || -> Vec<_> { rays.iter().map(|r| intersect_staged(r, &p)).collect() };
        let (plain, daz) = (run(), in_environment(false, true, run));
        let filtered = plain.iter().filter(|(_, s)| *s == Stage::Filter).count();
        assert!(filtered >= 250, "{filtered}");
        let (last, rest) = daz.split_last().unwrap();
        for (i, (got, want)) in rest.iter().zip(&plain).enumerate() {
            assert_eq!(got, want, "ray {i}");
        }
        assert_eq!(*last, (plain.last().unwrap().0, Stage::Exact));
    }

    /// The second pass decides every line of the stiff catalogue's
    /// near-parallel and in-plane families (`d·n` cancelling by up to
    /// `10³⁰`, or exactly 0), as the oracle does: none reaches the full
    /// filter's later stages.
    #[test]
    fn the_second_pass_decides_the_stiff_plane_families() {
        use crate::case::{Case, Kind, parse_line};
        let mut seen = 0;
        for line in crate::fixtures::stiff(Kind::Plane).lines() {
            let c = parse_line(line).expect("a stiff case");
            let family = c.family.unwrap_or_default();
            if family != "plane/near-parallel" && family != "plane/in-plane" {
                continue;
            }
            let Case::Plane(r, p) = c.case else {
                panic!("{family}: not a plane")
            };
            let (h, stage) = intersect_staged(&r, &p);
            assert_eq!(Ok(h), exact::intersect(&r, &p), "{family}: {r:?} {p:?}");
            assert!(
                matches!(stage, Stage::Filter | Stage::Tight),
                "{family}: {stage:?}"
            );
            let (o, d, a, n) = (
                r.origin.as_dvec3().to_array(),
                r.dir.as_dvec3().to_array(),
                p.point.as_dvec3().to_array(),
                p.normal.as_dvec3().to_array(),
            );
            let x = stages::first_terms(o, d, a, n);
            let first = stages::relative_terms(&x, 1.0);
            assert!(
                first.hit || compensated(&r, &p, &x, 1.0) == Some((h, stage)),
                "{family}: {r:?} {p:?}"
            );
            seen += 1;
        }
        assert_eq!(seen, 512);
    }

    /// The full filter takes a line whose `n̂um` cancels past both passes
    /// (by `2¹³`) and whose `d·n`, `2⁻⁴⁰`, is small but does not cancel:
    /// [`stages::Terms::hopeless`] reads cancellation, not magnitude.
    #[test]
    fn a_small_d_dot_n_that_does_not_cancel_reaches_the_filter() {
        let e = 2f32.powi(-20);
        // n̂um = (2²⁰ + 2⁸)·2⁻²⁰ − 1 = 2⁻¹², against m̂_num ≈ 2.
        let p = Plane::new(
            Vec3::new(2f32.powi(20) + 256.0, -1.0, 0.0),
            Vec3::new(e, 1.0, 0.0),
        );
        let r = Ray::new(Vec3::ZERO, Vec3::new(e, 0.0, 0.0));
        let want = PlaneHit::Hit(2f32.powi(28));
        assert_eq!(Ok(want), exact::intersect(&r, &p));
        assert_eq!(intersect_staged(&r, &p), (want, Stage::Filter));
    }
}
