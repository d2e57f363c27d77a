//! The camera oracle: the seed's formulas in f64 (29 bits more than f32),
//! rounded once to f32 at the end. `tan`, `sqrt` and the divisions leave the
//! result irrational, so "exact" here means a stated precision of about
//! `2⁻⁵⁰` relative per basis component, far below f32's `2⁻²⁴`.

use super::{CameraError, CameraParams};
use crate::Ray;
use glam::{DVec3, Vec3};

/// The ray for pixel `(px, py)` computed in f64 and rounded to f32. Fails
/// exactly when the reference's construction does.
///
/// ```
/// use rayoracle::camera::{CameraParams, exact::ray};
/// use glam::Vec3;
/// let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [3, 3]);
/// assert_eq!(ray(&p, 1, 1).unwrap().dir, -Vec3::Z);
/// ```
pub fn ray(p: &CameraParams, px: u32, py: u32) -> Result<Ray, CameraError> {
    p.build()?;
    let dir = p.dir.as_dvec3();
    let up = p.up.as_dvec3();
    let focus = dir.length();
    let h = (p.angle as f64 / 2.0).tan();
    let aspect = p.res[0] as f64 / p.res[1] as f64;
    let x_hat = dir.cross(up).normalize();
    let y_hat = dir.cross(x_hat).normalize();
    let x = aspect * focus * h * x_hat;
    let y = focus * h * y_hat;
    let u = (2.0 * px as f64 + 1.0) / p.res[0] as f64 - 1.0;
    let v = (2.0 * py as f64 + 1.0) / p.res[1] as f64 - 1.0;
    let d: DVec3 = dir + u * x + v * y;
    Ok(Ray::new(
        p.position,
        Vec3::new(d.x as f32, d.y as f32, d.z as f32),
    ))
}
