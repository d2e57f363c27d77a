//! The scalar reference: [`super::kernel::solve`] at `f32` — the seed's
//! `t = ((a − o)·n)/(d·n)` with exact differences, double-word dot products
//! and one final rounding — classified with plain branches.

use super::{Plane, PlaneHit, kernel};
use crate::Ray;

/// Intersects a ray (as a whole line) with a plane.
///
/// ```
/// use rayoracle::{Ray, plane::{Plane, PlaneHit, reference::intersect}};
/// use glam::Vec3;
/// let ground = Plane::new(Vec3::ZERO, Vec3::Y);
/// let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, -4.0, 0.0));
/// assert_eq!(intersect(&ray, &ground), PlaneHit::Hit(0.5));
/// let flat = Ray::new(Vec3::Y, Vec3::X);
/// assert_eq!(intersect(&flat, &ground), PlaneHit::Parallel);
/// ```
pub fn intersect(ray: &Ray, plane: &Plane) -> PlaneHit {
    let p = kernel::solve(
        ray.origin.to_array(),
        ray.dir.to_array(),
        plane.point.to_array(),
        plane.normal.to_array(),
    );
    if p.den != 0.0 {
        PlaneHit::Hit(p.t)
    } else if p.num == 0.0 {
        PlaneHit::InPlane
    } else {
        PlaneHit::Parallel
    }
}
