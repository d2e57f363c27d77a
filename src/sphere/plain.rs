//! The sphere in plain `f64`: the corrected formulation (solved after Ray
//! Tracing Gems ch. 7) with every operation in `f64` and
//! each root rounded once to `f32`, and no error bound.
//!
//! **A baseline for `rayoracle report`, not an oracle and not for
//! production.** It answers "what does the reference's certification
//! cost?": with `f = o − C` and the quadratic `a t² + 2b t + c = 0`,
//!
//! ```text
//! a = d·d,  b = f·d,  c = f·f − R²
//! aΔ = (aR)² − |a f − b d|²                (RTG ch. 7, division-free)
//! q = −(b + sign(b)·√(aΔ/a)),  t₀ = c/q,  t₁ = q/a
//! ```
//!
//! The largest quantity, `(aR)²`, is of degree 6 in the inputs, and for any
//! finite `f32` inputs it stays between `10⁻²⁷⁰` and `10²³²`, inside
//! `f64`'s normal range.
//!
//! The class is read from the `f64` signs: `a = 0` or `aΔ < 0` (or NaN)
//! none, `aΔ = 0` tangent (`−b/a`), otherwise two roots, sorted. It matches
//! the exact class outside a near-tangent band of a few `2⁻⁵³` of the
//! magnitudes `aΔ` is made of; a well-conditioned root is within 1 ulp (the
//! `f64` error is far below an `f32` ulp, but the final rounding can land
//! on either side of a midpoint). An exact tangent stays exact only while
//! the two squares of `aΔ` are exact in `f64`.

use super::{Sphere, SphereHit};
use crate::Ray;

/// Intersects a line with a sphere: the reference's RTG ch. 7 solve in
/// plain `f64`, each root rounded once to `f32`.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit, exact, plain::intersect}};
/// use glam::Vec3;
/// let unit = Sphere::new(Vec3::ZERO, 1.0);
/// let r = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, 2.0));
/// assert_eq!(intersect(&r, &unit), SphereHit::Two(2.0, 3.0));
/// // R = 1 at 10⁴, where the textbook formula sees a tangent:
/// let far = Ray::new(Vec3::new(0.0, 0.0, -1e4), Vec3::Z);
/// assert_eq!(intersect(&far, &unit), SphereHit::Two(9999.0, 10001.0));
/// // A line touching the sphere at (0, 1, 0):
/// let touch = Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z);
/// assert_eq!(intersect(&touch, &unit), SphereHit::Tangent(5.0));
/// assert_eq!(exact::intersect(&touch, &unit), Ok(SphereHit::Tangent(5.0)));
/// ```
pub fn intersect(ray: &Ray, sphere: &Sphere) -> SphereHit {
    let f = ray.origin.as_dvec3() - sphere.center.as_dvec3();
    let d = ray.dir.as_dvec3();
    let r = sphere.radius as f64;
    let a = d.dot(d);
    let b = f.dot(d);
    let c = f.dot(f) - r * r;
    let disc = (a * r) * (a * r) - (a * f - b * d).length_squared();
    if a == 0.0 || !(disc >= 0.0) {
        SphereHit::None // no line (d = 0), or no real root (NaN included)
    } else if disc == 0.0 {
        SphereHit::Tangent((-b / a) as f32)
    } else {
        let q = -(b + (disc / a).sqrt().copysign(b));
        let (t0, t1) = (c / q, q / a);
        // Sorted as the reference sorts: NaN roots stay in computation order.
        let (t0, t1) = if t0 > t1 { (t1, t0) } else { (t0, t1) };
        SphereHit::Two(t0 as f32, t1 as f32)
    }
}
