//! The camera in `f64`: the reference's construction (corrected) with the basis and every per-pixel direction in plain `f64`,
//! each direction component rounded once to `f32`.
//!
//! **A variant for `rayoracle report`, not an oracle and not for
//! production.** It answers "what if the reference had simply been written
//! in double precision?". The steps are those of
//! [`super::reference`](mod@super::reference) (see the [module docs](super)):
//! `f = dir`, `x̂ = (dir × up)/|dir × up|`, `ŷ = (dir × x̂)/|dir × x̂|`,
//! `y = (focus · h) · ŷ`, `x = ((focus · h) · aspect) · x̂` with
//! `h = tan(angle/2)`, built once per camera; per pixel the offsets
//! `u = (2X + 1 − resX)/resX`, `v` likewise, and `(f + u·x) + v·y`. Here
//! every one of those is a plain `f64`, the basis is kept in `f64` rather
//! than rounded to `f32`, and nothing is prescaled: `f64`'s range holds
//! every square and cross product of finite `f32` vectors.
//!
//! **This is close to the oracle, not equal to it.** The oracle,
//! [`super::exact`], rounds each component's real value once; here the
//! basis and the sum carry a few `f64` roundings first. Expect each
//! component to be the oracle's, or one `f32` ulp of `Sᵢ = |fᵢ| + |u xᵢ| +
//! |v yᵢ|` from it where the `f64` value and the real one straddle a
//! rounding boundary.

use super::{CameraError, CameraParams};
use crate::Ray;
use glam::DVec3;

/// A camera with its basis in `f64`.
///
/// ```
/// use rayoracle::camera::{CameraParams, plain::Camera};
/// use glam::{DVec3, Vec3};
/// let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, std::f32::consts::FRAC_PI_2, [2, 2]);
/// let cam = Camera::new(&p).unwrap();
/// // 90° vertical field of view, square: half extents of 1 at distance 1.
/// // (f32's π/2 is 4·10⁻⁸ short of π/2.)
/// assert!((cam.x - DVec3::X).length() < 1e-7);
/// assert!((cam.y + DVec3::Y).length() < 1e-7);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The inputs.
    pub params: CameraParams,
    /// The horizontal half-extent vector, in `f64`.
    pub x: DVec3,
    /// The vertical half-extent vector (pointing down the image), in `f64`.
    pub y: DVec3,
}

impl Camera {
    /// Validates `p` exactly as the reference does (by building the
    /// reference camera, [`CameraParams::build`], and discarding it), then
    /// builds the `f64` basis.
    ///
    /// ```
    /// use rayoracle::camera::{CameraError, CameraParams, plain::Camera};
    /// use glam::Vec3;
    /// let bad = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 4.0, [4, 4]);
    /// assert_eq!(Camera::new(&bad).unwrap_err(), CameraError::AngleOutOfRange(4.0));
    /// // Where the textbook camera's |dir|² underflows, f64 has the range.
    /// let tiny = CameraParams::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -1e-25), Vec3::Y, 1.0, [4, 4]);
    /// assert_eq!(Camera::new(&tiny).unwrap().ray(2, 2).dir.z, -1e-25);
    /// ```
    pub fn new(p: &CameraParams) -> Result<Camera, CameraError> {
        p.build()?;
        let dir = p.dir.as_dvec3();
        let focus = dir.length();
        let h = (p.angle as f64 / 2.0).tan();
        let aspect = p.res[0] as f64 / p.res[1] as f64;
        let xc = dir.cross(p.up.as_dvec3());
        let x_hat = xc / xc.length();
        let yc = dir.cross(x_hat);
        let y_hat = yc / yc.length();
        let len_y = focus * h;
        Ok(Camera {
            params: *p,
            x: (len_y * aspect) * x_hat,
            y: len_y * y_hat,
        })
    }

    /// The ray through the centre of pixel `(px, py)` (row 0 is the top):
    /// `(f + u·x) + v·y` in `f64` with `u = (2X + 1 − resX)/resX`, each
    /// component rounded once to `f32`.
    ///
    /// ```
    /// use rayoracle::camera::{CameraParams, plain::Camera, exact};
    /// use glam::Vec3;
    /// let p = CameraParams::new(Vec3::ONE, Vec3::new(0.3, -0.2, -1.0), Vec3::Y, 1.0, [640, 480]);
    /// let cam = Camera::new(&p).unwrap();
    /// assert_eq!(cam.ray(0, 0).origin, Vec3::ONE);
    /// // Here the two agree to the bit.
    /// assert_eq!(cam.ray(17, 400), exact::ray(&p, 17, 400).unwrap());
    /// ```
    pub fn ray(&self, px: u32, py: u32) -> Ray {
        let offset = |p: u32, res: u32| (2.0 * p as f64 + 1.0 - res as f64) / res as f64;
        let [rx, ry] = self.params.res;
        let (u, v) = (offset(px, rx), offset(py, ry));
        let d = (self.params.dir.as_dvec3() + u * self.x) + v * self.y;
        Ray::new(self.params.position, d.as_vec3())
    }
}
