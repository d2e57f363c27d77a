//! The scalar reference: [`super::kernel::solve`] at `f32` — α, β, γ in
//! double-word arithmetic, then pbrt-v4's `Quadratic` with its α = 0 branch —
//! classified with plain branches.

use super::{Quadric, QuadricHit, kernel};
use crate::Ray;

/// Intersects a line with a quadric: class and roots over `t ∈ ℝ`.
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit, reference::intersect}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let across = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X);
/// assert_eq!(intersect(&across, &cyl), QuadricHit::Two(4.0, 6.0));
/// // Parallel to the axis, on the surface: α = β = γ = 0.
/// let along = Ray::new(Vec3::new(1.0, 0.0, 0.0), Vec3::Z);
/// assert_eq!(intersect(&along, &cyl), QuadricHit::All);
/// ```
pub fn intersect(ray: &Ray, quadric: &Quadric) -> QuadricHit {
    let p = kernel::solve(&quadric.coeffs, ray.origin.to_array(), ray.dir.to_array());
    if p.alpha == 0.0 {
        if p.beta != 0.0 {
            QuadricHit::One(p.linear)
        } else if p.gamma == 0.0 {
            QuadricHit::All
        } else {
            QuadricHit::None
        }
    } else if !(p.disc >= 0.0) {
        QuadricHit::None
    } else if p.disc == 0.0 {
        QuadricHit::One(p.double)
    } else {
        QuadricHit::Two(p.t0, p.t1)
    }
}
