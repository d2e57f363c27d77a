//! The scalar reference: [`super::kernel::solve`] at `f32`, classified with
//! plain branches.

use super::{Sphere, SphereHit, kernel};
use crate::Ray;

/// Intersects a line with a sphere: the class and both roots over `t ∈ ℝ`.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit, reference::intersect}};
/// use glam::Vec3;
/// let s = Sphere::new(Vec3::ZERO, 1.0);
/// // |d| = 2: the seed's discriminant would be wrong here.
/// let r = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, 2.0));
/// assert_eq!(intersect(&r, &s), SphereHit::Two(2.0, 3.0));
/// // Origin inside: one root behind the origin.
/// let inside = Ray::new(Vec3::ZERO, Vec3::Z);
/// assert_eq!(intersect(&inside, &s), SphereHit::Two(-1.0, 1.0));
/// ```
pub fn intersect(ray: &Ray, sphere: &Sphere) -> SphereHit {
    let p = kernel::solve(
        ray.origin.to_array(),
        ray.dir.to_array(),
        sphere.center.to_array(),
        sphere.radius,
    );
    if p.a == 0.0 || !(p.disc >= 0.0) {
        SphereHit::None // no line (d = 0), or no real root (NaN included)
    } else if p.disc == 0.0 {
        SphereHit::Tangent(p.tangent)
    } else {
        SphereHit::Two(p.t0, p.t1)
    }
}
