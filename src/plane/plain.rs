//! The plane in `f64`: `t = ((a − o)·n)/(d·n)`, with every
//! operation in plain `f64` and the root rounded once to `f32`.
//!
//! **A baseline for `rayoracle report`, not an oracle and not for
//! production.** It answers "what does the reference's certification
//! cost?": the same arithmetic as the reference's
//! [filter](super::stages) (the difference `a − o`, the two dot products,
//! one quotient), without the error bound. A product of two `f32`s
//! (`10⁻⁹⁰` to `10⁷⁷`) is always in `f64`'s range.
//!
//! Each product `dᵢnᵢ` is exact in `f64` (24 + 24 bits), so `d·n` carries
//! two roundings of about `2⁻⁵³` relative to `Σ|dᵢnᵢ|`; `a − o` is exact
//! unless the two exponents are more than 29 apart. The class comes from the
//! `f64` signs of `d·n` and `(a − o)·n`, so it matches the exact one outside
//! a parallel band of roughly `2⁻⁵² Σ|dᵢnᵢ|`; a well-conditioned root is
//! within 1 ulp (the `f64` error is far below an `f32` ulp, and the final
//! rounding can land on either side of a midpoint).

use super::{Plane, PlaneHit};
use crate::Ray;

/// Intersects a ray (as a whole line) with a plane in `f64`: `dn = d·n` and
/// `num = (a − o)·n` in plain `f64`; `dn = 0` gives
/// [`PlaneHit::InPlane`] when `num = 0` and [`PlaneHit::Parallel`]
/// otherwise; else `Hit((num/dn) as f32)`.
///
/// ```
/// use rayoracle::{Ray, plane::{Plane, PlaneHit, plain::intersect}};
/// use glam::Vec3;
/// let ground = Plane::new(Vec3::ZERO, Vec3::Y);
/// let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, -4.0, 0.0));
/// assert_eq!(intersect(&ray, &ground), PlaneHit::Hit(0.5));
/// assert_eq!(intersect(&Ray::new(Vec3::Y, Vec3::X), &ground), PlaneHit::Parallel);
/// // 1/3, rounded once: the correctly rounded root, as the oracle says.
/// let p = Plane::new(Vec3::ZERO, Vec3::new(0.0, 3.0, 0.0));
/// let r = Ray::new(Vec3::Y, Vec3::new(0.0, -3.0, 0.0));
/// assert_eq!(Ok(intersect(&r, &p)), rayoracle::plane::exact::intersect(&r, &p));
/// assert_eq!(intersect(&r, &p), PlaneHit::Hit(1.0 / 3.0));
/// ```
pub fn intersect(ray: &Ray, plane: &Plane) -> PlaneHit {
    let n = plane.normal.as_dvec3();
    let dn = ray.dir.as_dvec3().dot(n);
    let num = (plane.point.as_dvec3() - ray.origin.as_dvec3()).dot(n);
    if dn == 0.0 {
        if num == 0.0 {
            PlaneHit::InPlane
        } else {
            PlaneHit::Parallel
        }
    } else {
        PlaneHit::Hit((num / dn) as f32)
    }
}
