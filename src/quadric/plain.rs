//! The quadric in plain `f64`: the corrected formulation (solved by
//! pbrt-v4's `Quadratic`) with every operation in `f64`, each
//! root rounded once to `f32`, and no error bound.
//!
//! **A baseline for `rayoracle report`, not an oracle and not for
//! production.** It answers "what does the reference's certification
//! cost?". The steps (see the [module docs](super)):
//!
//! * α, β, γ of the corrected expansion, term by term (the same evaluation
//!   as [`super::textbook`], at `f64`);
//! * `α = 0`: the linear root `−γ/β`, or, when `β = 0` too,
//!   [`QuadricHit::All`] for `γ = 0` and [`QuadricHit::None`] otherwise;
//! * otherwise `Δ = β² − 4αγ`, `q = −½(β + sign(β)√Δ)`, `t₀ = q/α`,
//!   `t₁ = γ/q`, sorted; `Δ = 0` gives `One(−β/2α)`.
//!
//! The discriminant is a plain `β·β − 4α·γ` (no fused multiply-add as
//! pbrt's `DifferenceOfProducts` uses), and nothing is prescaled: a term of
//! γ is at most a product of three `f32`s and `β²` of
//! degree 6, so every quantity stays in `f64`'s normal range for finite
//! `f32` inputs.
//!
//! Each term `k·x·y` is rounded once (`k·x` is exact in `f64`), so α, β and
//! γ are accurate to a few `2⁻⁵³` of the sum of their terms' magnitudes.
//! The class comes from the `f64` signs of α and Δ, and matches the exact
//! one outside a band of that width; a well-conditioned root is within 1 ulp
//! (the `f64` error is far below an `f32` ulp, and the final rounding can
//! land on either side of a midpoint). An `α` that is 0 exactly is
//! recognised when its terms vanish or cancel exactly in `f64`, as they do
//! for a ray parallel to a cylinder's axis.

use super::{Quadric, QuadricHit, textbook::coefficients};
use crate::Ray;

/// Intersects a line with a quadric: the reference's pbrt-v4 solve in plain
/// `f64`, each root rounded once to `f32`.
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit, exact, plain::intersect}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let across = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X);
/// assert_eq!(intersect(&across, &cyl), QuadricHit::Two(4.0, 6.0));
/// // α = 0: a paraboloid z = x² + y², along its axis, one root.
/// let para = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0]);
/// let up = Ray::new(Vec3::new(0.5, 0.0, -3.0), Vec3::Z);
/// assert_eq!(intersect(&up, &para), QuadricHit::One(3.25));
/// // A graze (β² = 4αγ exactly) with α = 4: the double root −β/2α.
/// let graze = Ray::new(Vec3::new(-5.0, 1.0, 0.0), Vec3::new(2.0, 0.0, 0.0));
/// assert_eq!(intersect(&graze, &cyl), QuadricHit::One(2.5));
/// // α ≈ 0, where the textbook formula cancels: the correctly rounded roots.
/// let q = Quadric::new([1e-6, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.7]);
/// let r = Ray::new(Vec3::ZERO, Vec3::X);
/// assert_eq!(intersect(&r, &q), QuadricHit::Two(-999999.3, -0.70000046));
/// assert_eq!(Ok(intersect(&r, &q)), exact::intersect(&r, &q));
/// ```
pub fn intersect(ray: &Ray, quadric: &Quadric) -> QuadricHit {
    let up = |v: [f32; 3]| v.map(f64::from);
    let (alpha, beta, gamma) = coefficients(
        quadric.coeffs.map(f64::from),
        up(ray.origin.to_array()),
        up(ray.dir.to_array()),
    );
    if alpha == 0.0 {
        return if beta != 0.0 {
            QuadricHit::One((-gamma / beta) as f32)
        } else if gamma == 0.0 {
            QuadricHit::All
        } else {
            QuadricHit::None
        };
    }
    let disc = beta * beta - 4.0 * alpha * gamma;
    if !(disc >= 0.0) {
        QuadricHit::None // no real root (NaN included)
    } else if disc == 0.0 {
        QuadricHit::One((-beta / (2.0 * alpha)) as f32)
    } else {
        let q = -0.5 * (beta + disc.sqrt().copysign(beta));
        let (t0, t1) = (q / alpha, gamma / q);
        // Sorted as the reference sorts: NaN roots stay in computation order.
        let (t0, t1) = if t0 > t1 { (t1, t0) } else { (t0, t1) };
        QuadricHit::Two(t0 as f32, t1 as f32)
    }
}
