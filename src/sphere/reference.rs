//! The scalar reference: the [filter](super::stages) at `f64` (its sorted
//! roots `(−b ∓ √Δ)/a` first, then `q/a` and `c/q` where the root near 0
//! cancels), then the later stages ([`crate::stage`]) for whatever it
//! leaves undecided, the exact oracle last.

use super::{Sphere, SphereHit, exact, stages};
use crate::Ray;
use crate::hit::Intersection;
use crate::num::certify::{certify, denormals_are_zero, flush_prone, needs_probe, subnormals_work};
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
use crate::num::dd::Fma;
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
use crate::num::dd::Fused;
use crate::num::dd::{BuildProduct, Product};
use crate::stage::Stage;

/// Intersects a line with a sphere: the exact class and both roots over
/// `t ∈ ℝ`, each correctly rounded to `f32`. A NaN or infinite input gives
/// [`SphereHit::None`].
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit, reference::intersect}};
/// use glam::Vec3;
/// let s = Sphere::new(Vec3::ZERO, 1.0);
/// // |d| = 2: a discriminant without the d·d factor on R² would be wrong here.
/// let r = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, 2.0));
/// assert_eq!(intersect(&r, &s), SphereHit::Two(2.0, 3.0));
/// // Origin inside: one root behind the origin.
/// let inside = Ray::new(Vec3::ZERO, Vec3::Z);
/// assert_eq!(intersect(&inside, &s), SphereHit::Two(-1.0, 1.0));
/// // Grazing the top: an exact tangent.
/// let graze = Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z);
/// assert_eq!(intersect(&graze, &s), SphereHit::Tangent(5.0));
/// ```
#[inline]
pub fn intersect(ray: &Ray, sphere: &Sphere) -> SphereHit {
    intersect_staged(ray, sphere).0
}

/// [`intersect`], and the [`Stage`] that decided it.
///
/// ```
/// use rayoracle::{Ray, stage::Stage, sphere::{Sphere, SphereHit, reference::intersect_staged}};
/// use glam::Vec3;
/// let r = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
/// let s = Sphere::new(Vec3::ZERO, 1.0);
/// assert_eq!(intersect_staged(&r, &s), (SphereHit::Two(4.0, 6.0), Stage::Filter));
/// ```
#[inline]
pub fn intersect_staged(ray: &Ray, sphere: &Sphere) -> (SphereHit, Stage) {
    intersect_shrunk(ray, sphere, 1.0)
}

/// [`intersect_staged`] with every stage's bounds multiplied by `shrink`:
/// for the tests that show a bound too small gives wrong answers.
#[doc(hidden)]
#[inline(always)]
pub fn intersect_shrunk(ray: &Ray, sphere: &Sphere, shrink: f64) -> (SphereHit, Stage) {
    // The environment meets an input only through DAZ, and a result only
    // through FTZ where it is subnormal ([`needs_probe`]): the inputs are
    // scanned only under DAZ, and the register read only for such a
    // result.
    let inputs = inputs(ray, sphere);
    if denormals_are_zero() && needs_probe(&inputs, &[]) {
        return (exact_stage(ray, sphere), Stage::Exact);
    }
    let (o, d, c, r) = widen(ray, sphere);
    let k = stages::classes(o, d, c, r, shrink);
    if k.none {
        return (SphereHit::None, Stage::Filter);
    }
    // An undecided class (a near or exact tangent) has no roots to try.
    // The classes go to the later stages by value, both masks known clear,
    // so that the fast path tests them by branches and keeps the rest in
    // registers, rather than store them all for a call it rarely makes.
    if !k.two {
        return later(ray, sphere, (o, d, c, r), k.open(), shrink);
    }
    // The sorted roots first, as x4 does (two divisions rather than
    // three); the quotient form where the root near 0 cancels.
    let g = stages::sorted(k, shrink);
    if certify(g.lo, g.r, g.a) && certify(g.hi, g.r, g.a) {
        if needs_probe(&[], &[g.lo, g.hi]) && !subnormals_work() {
            return (exact_stage(ray, sphere), Stage::Exact);
        }
        return (SphereHit::Two(g.lo as f32, g.hi as f32), Stage::Filter);
    }
    let f = stages::filter_from(k, shrink);
    if certify(f.t0, f.r0, f.a0) && certify(f.t1, f.r1, f.a1) {
        if needs_probe(&[], &[f.t0, f.t1]) && !subnormals_work() {
            return (exact_stage(ray, sphere), Stage::Exact);
        }
        // Disjoint enclosures are in the exact order; overlapping ones
        // round to the same f32.
        let (t0, t1) = if f.t0 <= f.t1 {
            (f.t0, f.t1)
        } else {
            (f.t1, f.t0)
        };
        return (SphereHit::Two(t0 as f32, t1 as f32), Stage::Filter);
    }
    uncertified(ray, sphere, shrink)
}

/// [`later`] for a line whose two roots the filter left undecided: the
/// inputs widened and the classes formed again, rather than kept from the
/// fast path, which would hold them there past the roots on every call.
/// With this and the classes passed by value above, the kernels bench
/// (4,096 primary rays, one `--quick` run each way) put the reference at
/// 104.1 Mrays/s (criterion's median) and 107.1 (the fastest interleaved
/// pass), against 89.2 and 90.4; `rayoracle report` (four runs each,
/// alternated) kept every stiff sphere family within a few per cent of
/// its time before.
#[cold]
#[inline(never)]
fn uncertified(ray: &Ray, sphere: &Sphere, shrink: f64) -> (SphereHit, Stage) {
    let (o, d, c, r) = widen(ray, sphere);
    later(
        ray,
        sphere,
        (o, d, c, r),
        stages::classes(o, d, c, r, shrink),
        shrink,
    )
}

/// [`escalate_lane`] on one line, in lane 0.
#[cfg(test)]
fn escalate(ray: &Ray, sphere: &Sphere, env: bool) -> (SphereHit, Stage) {
    let (r4, s4) = (
        crate::ray4::Ray4::splat(*ray),
        super::x4::Sphere4::splat(sphere),
    );
    escalate_lane(&r4, &s4, 0, env)
}

/// The whole reference for lane `i` of x4's packets: the filter, then the
/// stages after it: f64 arithmetic proven exact by the data's span
/// ([`stages::grid_exact`]) or operation by operation
/// ([`stages::tracked`]), f64 arithmetic with a tighter bound
/// ([`stages::compensated`], [`stages::tight`]), double-word arithmetic
/// ([`words`](super::words::words), [`stages::double_word`]), then the
/// exact oracle. The later stages,
/// too, assume subnormals work where an input or a result is subnormal
/// ([`needs_probe`], [`flush_prone`]), so this checks for itself: x4 sends
/// its undecided lanes here, and all of them when FTZ or DAZ is on.
///
/// `env` is what x4 read from [`subnormals_work`] for the packet: where it
/// is true, no input needs the probe. The inputs are widened from the
/// packets where they lie: a ray and a sphere built on the stack and
/// widened at once are read back at other widths, which stalls store
/// forwarding (`rayoracle report`, x4 on sphere/exact-tangent: 38 against
/// 30 ns a ray).
#[cold]
#[inline(never)]
pub(crate) fn escalate_lane(
    rays: &crate::ray4::Ray4,
    s: &super::x4::Sphere4,
    i: usize,
    env: bool,
) -> (SphereHit, Stage) {
    let lane = |v: &[wide::f32x4; 3]| {
        let x = |j: usize| v[j].as_array()[i];
        glam::Vec3::new(x(0), x(1), x(2))
    };
    let ray = Ray::new(lane(&rays.origin), lane(&rays.dir));
    let sphere = Sphere::new(lane(&s.center), s.radius.as_array()[i]);
    if !env && denormals_are_zero() && needs_probe(&inputs(&ray, &sphere), &[]) {
        return (exact_stage(&ray, &sphere), Stage::Exact);
    }
    let w = |v: glam::Vec3| v.as_dvec3().to_array();
    let (o, d, c, r) = (
        w(lane(&rays.origin)),
        w(lane(&rays.dir)),
        w(lane(&s.center)),
        f64::from(s.radius.as_array()[i]),
    );
    let k = stages::classes(o, d, c, r, 1.0);
    later(&ray, &sphere, (o, d, c, r), k, 1.0)
}

/// The line and the sphere in f64: `o`, `d`, `C` and `R`.
type Wide = ([f64; 3], [f64; 3], [f64; 3], f64);

#[inline(always)]
fn widen(ray: &Ray, sphere: &Sphere) -> Wide {
    let w = |v: glam::Vec3| v.as_dvec3().to_array();
    (
        w(ray.origin),
        w(ray.dir),
        w(sphere.center),
        f64::from(sphere.radius),
    )
}

/// The stages after the filter ([`escalate_lane`]'s) on inputs already
/// widened and probed, with the filter's
/// classes `k` (by value: see [`uncertified`]) and the bounds of its
/// stages multiplied by `shrink`; on a CPU with FMA
/// ([`Fma`](crate::num::dd::Fma)), a copy compiled for it,
/// whose double-word stage finds the products' errors by fused
/// multiply-adds ([`Fused`](crate::num::dd::Fused)): the same exact pairs,
/// so the same bits.
#[cold]
#[inline(never)]
fn later(
    ray: &Ray,
    sphere: &Sphere,
    wide: Wide,
    k: stages::Classes<f64>,
    shrink: f64,
) -> (SphereHit, Stage) {
    // Exact data on a narrow grid where Δ̂ = 0 (as at an exact tangent;
    // elsewhere the grid is rarely narrow enough to pay for its test),
    // first and outside the copy compiled for FMA: `rayoracle report`'s
    // harness on sphere/exact-tangent, 28 against 31 ns a line.
    if k.disc == 0.0 {
        let (o, d, c) = (
            ray.origin.to_array(),
            ray.dir.to_array(),
            sphere.center.to_array(),
        );
        if let Some(h) = stages::grid_from(&k, o, d, c, sphere.radius) {
            return settled(Some((h, Stage::Tracked)), ray, sphere);
        }
    }
    let k = &k;
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if let Some(fma) = Fma::detect() {
        #[target_feature(enable = "fma")]
        fn run(
            _: Fma,
            ray: &Ray,
            sphere: &Sphere,
            wide: Wide,
            k: &stages::Classes<f64>,
            shrink: f64,
        ) -> (SphereHit, Stage) {
            later_by::<Fused>(ray, sphere, wide, k, shrink)
        }
        // SAFETY: the token exists only where the CPU has FMA, the one
        // feature `run` is compiled for. In `rayoracle report` on a
        // catalogue of `sphere/near-tangent` and `quadric/double-plane`
        // (default build, Xeon with AVX-512, 15 runs alternated with a
        // build without this copy), the reference's median on
        // near-tangent was 75.1 against 78.1 ns/ray.
        return unsafe { run(fma, ray, sphere, wide, k, shrink) };
    }
    later_by::<BuildProduct>(ray, sphere, wide, k, shrink)
}

/// [`later`] with the products' errors found by `P`.
#[inline(always)]
fn later_by<P: Product>(
    ray: &Ray,
    sphere: &Sphere,
    (o, d, c, r): Wide,
    k: &stages::Classes<f64>,
    shrink: f64,
) -> (SphereHit, Stage) {
    // Cheapest and likeliest first, after the grid ([`later`]): a
    // cancelling c where the class is certified, the words stage where Δ̂
    // ≠ 0 (far spheres, near tangents), exact data, the words stage where
    // Δ̂ = 0 (a near tangent whose b̂² and âĉ round alike, or an exact one
    // of inexact products), then the rest (but see `flat`).
    let cancels = stages::c_cancels(k);
    // Where Δ̂ = 0 and the class is open (a near tangent), the tight form
    // rarely decides and the double-word stage is tried before it.
    let flat = k.disc == 0.0 && !k.two;
    let tight = || stages::tight(o, d, c, r, shrink).map(|h| (h, Stage::Tight));
    let comp = || stages::compensated_from(k, o, c, r, shrink).map(|h| (h, Stage::Tight));
    let words =
        || super::words::words_by::<P>(k, o, d, c, r, shrink).map(|h| (h, Stage::DoubleWord));
    let staged = (if cancels { comp() } else { None })
        .or_else(|| if k.disc != 0.0 { words() } else { None })
        .or_else(|| stages::tracked(o, d, c, r).map(|h| (h, Stage::Tracked)))
        .or_else(|| if k.disc == 0.0 { words() } else { None })
        .or_else(|| if flat { None } else { tight() })
        .or_else(|| if cancels || !k.two { None } else { comp() })
        .or_else(|| stages::double_word_by::<P>(o, d, c, r, shrink).map(|h| (h, Stage::DoubleWord)))
        .or_else(|| if flat { tight() } else { None });
    settled(staged, ray, sphere)
}

/// A later stage's answer, or the exact oracle's where there is none or
/// where a root may be subnormal and subnormals do not work
/// ([`flush_prone`]).
#[inline(always)]
fn settled(staged: Option<(SphereHit, Stage)>, ray: &Ray, sphere: &Sphere) -> (SphereHit, Stage) {
    match staged {
        Some((h, _)) if flush_prone(h.roots().as_slice()) && !subnormals_work() => {
            (exact_stage(ray, sphere), Stage::Exact)
        }
        Some(hs) => hs,
        None => (exact_stage(ray, sphere), Stage::Exact),
    }
}

/// The inputs, for [`needs_probe`].
#[inline(always)]
fn inputs(ray: &Ray, sphere: &Sphere) -> [f32; 10] {
    let (o, d, c) = (ray.origin, ray.dir, sphere.center);
    [o.x, o.y, o.z, d.x, d.y, d.z, c.x, c.y, c.z, sphere.radius]
}

/// The last stage: the exact oracle; [`SphereHit::None`] for a non-finite
/// input.
fn exact_stage(ray: &Ray, sphere: &Sphere) -> SphereHit {
    exact::intersect(ray, sphere).unwrap_or(SphereHit::None)
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    /// x4's way into the later stages, [`escalate`], probes the inputs
    /// only where x4 has not read the environment (`env` false), and only
    /// under DAZ: in the default environment it takes the stages the
    /// reference takes, with a subnormal input or without; under DAZ,
    /// which reads the centre's `1e-40` as 0 and so makes the line an exact
    /// tangent, it asks the oracle, which says the line misses.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn escalate_probes_the_inputs_only_under_daz() {
        let r = Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z);
        let tangent = Sphere::new(Vec3::ZERO, 1.0);
        let near = Sphere::new(Vec3::new(1e-40, 0.0, 0.0), 1.0);
        for env in [false, true] {
            let want = (SphereHit::Tangent(5.0), Stage::Tracked);
            assert_eq!(escalate(&r, &tangent, env), want, "env {env}");
            assert_eq!(intersect_staged(&r, &tangent), want);
            let want = (SphereHit::None, Stage::DoubleWord);
            assert_eq!(escalate(&r, &near, env), want, "env {env}");
            assert_eq!(intersect_staged(&r, &near), want);
        }
        let daz =
            crate::num::certify::in_environment(false, true, move || escalate(&r, &near, false));
        assert_eq!(daz, (SphereHit::None, Stage::Exact));
    }
}
