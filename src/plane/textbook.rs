//! The textbook plane: `t = ((a − o)·n)/(d·n)`, exactly as written, in
//! plain `f32`.
//!
//! **A baseline for `rayoracle report`, not an oracle and not for
//! production.** It is what a typical user writes from the derivation:
//! the algebra is right (its three cases are), but there is no numerical
//! care: `a − o` is rounded, both dot products are plain `f32` sums of
//! rounded products, and nothing is prescaled. It exists so that the
//! report can show what [`super::reference`](mod@super::reference) buys over
//! it, measured against [`super::exact`].
//!
//! What to expect from it:
//!
//! * a few ulps on well-conditioned hits (up to 4 where `κ < 4`, in
//!   `tests/variants.rs`);
//! * near-parallel rays lose the classification and the root together:
//!   `d·n` is a cancelling sum whose rounding error is of order
//!   `2⁻²⁴ Σ|dᵢnᵢ|`, so a ray that close to parallel can come out parallel or
//!   hitting, and its `t` anywhere (exact zeros survive only where the
//!   products and sums are exact, as for small integers);
//! * products that underflow (subnormal normals) or overflow (planes at
//!   `10³⁰`) give 0, ∞ or NaN where the reference still has the answer.

use super::{Plane, PlaneHit};
use crate::Ray;

/// Intersects a ray (as a whole line) with a plane, the textbook way in plain
/// `f32`: `dn = d·n`; if `dn = 0`, [`PlaneHit::InPlane`] when
/// `(a − o)·n = 0` and [`PlaneHit::Parallel`] otherwise; else
/// `Hit(((a − o)·n)/dn)`. A NaN input gives a NaN hit, or
/// [`PlaneHit::Parallel`] when `dn` is still 0.
///
/// ```
/// use rayoracle::{Ray, plane::{Plane, PlaneHit, textbook::intersect}};
/// use glam::Vec3;
/// let ground = Plane::new(Vec3::ZERO, Vec3::Y);
/// let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, -4.0, 0.0));
/// assert_eq!(intersect(&ray, &ground), PlaneHit::Hit(0.5));
/// assert_eq!(intersect(&Ray::new(Vec3::Y, Vec3::X), &ground), PlaneHit::Parallel);
/// assert_eq!(intersect(&Ray::new(Vec3::ZERO, Vec3::X), &ground), PlaneHit::InPlane);
/// // A subnormal normal: (a − o)·n = −10⁻⁵⁰ underflows to 0, so the
/// // textbook form puts the hit at the origin; the reference does not.
/// let tiny = Plane::new(Vec3::ZERO, Vec3::new(0.0, 1e-40, 0.0));
/// let down = Ray::new(Vec3::new(0.0, 1e-10, 0.0), -Vec3::Y);
/// assert_eq!(intersect(&down, &tiny), PlaneHit::Hit(0.0));
/// assert_eq!(rayoracle::plane::reference::intersect(&down, &tiny), PlaneHit::Hit(1e-10));
/// ```
pub fn intersect(ray: &Ray, plane: &Plane) -> PlaneHit {
    let n = plane.normal;
    let dn = ray.dir.dot(n);
    let num = (plane.point - ray.origin).dot(n);
    if dn == 0.0 {
        if num == 0.0 {
            PlaneHit::InPlane
        } else {
            PlaneHit::Parallel
        }
    } else {
        PlaneHit::Hit(num / dn)
    }
}
