//! The textbook camera: the hand derivation in plain `f32`, in the
//! corrected order.
//!
//! **A baseline for `rayoracle report`, not an oracle and not for
//! production.** It is what a typical user writes from the derivation once `x`
//! and `y` are put in the right order (`x` from `dir × up`, then `y` from
//! `dir × x`; see the [module docs](super)), with no numerical care:
//!
//! ```text
//! focus = |dir|,  aspect = resX/resY,  h = tan(angle/2)   (f32::tan)
//! x = (aspect · focus) · h · (dir × up)/|dir × up|
//! y = focus · h · (dir × x)/|dir × x|
//! f = focus · dir/|dir|
//! ray.dir = f + 2((X + 0.5)/resX − 0.5)·x + 2((Y + 0.5)/resY − 0.5)·y
//! ```
//!
//! Every step is one plain `f32` operation, evaluated left to right; the
//! normalisations are a square root and a division. It keeps the derivation's
//! `f = focus · dir/|dir|`, which is `dir` with extra roundings, and its
//! pixel offset, which rounds the quotient `(X + 0.5)/resX` and then the
//! difference (`X + 0.5` and the doubling are exact below `2²³`). `tan` is
//! the platform's `tanf`. It exists so
//! that the report can show what [`super::reference`](mod@super::reference)
//! buys, measured against [`super::exact`]. Where it goes wrong:
//!
//! * `|dir × up|²` and `|dir|²` go subnormal (losing bits), then to 0, for
//!   `|dir|` below about `10⁻¹⁹`, and overflow above about `10¹⁹`, giving
//!   NaN or ∞ in the basis where the reference, which prescales, has one;
//! * near-parallel `dir` and `up` make `dir × up` a cancelling difference;
//! * the pixel offset rounds `(X + 0.5)/resX` before subtracting `0.5`, an
//!   absolute error of up to `2⁻²⁴` in `u`, large against a small `u` near
//!   the centre column; where `|x| ≫ |f|` (wide angles, wide images) it is
//!   many ulps of `Sᵢ = |fᵢ| + |u xᵢ| + |v yᵢ|`
//!   ([`super::component_scale`]).
//!
//! `tests/variants.rs` measures up to 6 ulps of `Sᵢ` for fields of view of
//! 0.2 to 2 rad and aspect ratios of ½ to 2, and up to 32 for angles up to 3
//! rad and any aspect ratio (the reference is correctly rounded: 0).

use super::{CameraError, CameraParams};
use crate::Ray;
use glam::Vec3;

/// A camera built the textbook way, in plain `f32`.
///
/// ```
/// use rayoracle::camera::{CameraParams, textbook::Camera};
/// use glam::Vec3;
/// let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, std::f32::consts::FRAC_PI_2, [2, 2]);
/// let cam = Camera::new(&p).unwrap();
/// // 90° vertical field of view, square: half extents of 1 at distance 1.
/// assert!((cam.x - Vec3::X).length() < 1e-6);
/// assert!((cam.y + Vec3::Y).length() < 1e-6);
/// assert_eq!(cam.f, -Vec3::Z);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The inputs.
    pub params: CameraParams,
    /// `f = focus · dir/|dir|`, the derivation's (rounded) way of writing `dir`.
    pub f: Vec3,
    /// The horizontal half-extent vector.
    pub x: Vec3,
    /// The vertical half-extent vector (pointing down the image).
    pub y: Vec3,
}

impl Camera {
    /// Validates `p` exactly as the reference does (by building the
    /// reference camera, [`CameraParams::build`], and discarding it), then
    /// builds the textbook basis. A parameter set the reference accepts may
    /// still give this basis a NaN or ∞ (see the module docs): that is the
    /// baseline's honest result, not an error.
    ///
    /// ```
    /// use rayoracle::camera::{CameraError, CameraParams, textbook::Camera};
    /// use glam::Vec3;
    /// let bad = CameraParams::new(Vec3::ZERO, Vec3::Y, Vec3::Y, 1.0, [4, 4]);
    /// assert_eq!(Camera::new(&bad).unwrap_err(), CameraError::DirParallelToUp);
    /// // |dir|² underflows: the reference prescales, the textbook divides by 0.
    /// let tiny = CameraParams::new(Vec3::ZERO, Vec3::new(0.0, 0.0, -1e-25), Vec3::Y, 1.0, [4, 4]);
    /// assert!(tiny.build().is_ok());
    /// assert!(Camera::new(&tiny).unwrap().f.is_nan());
    /// ```
    pub fn new(p: &CameraParams) -> Result<Camera, CameraError> {
        p.build()?;
        let dir = p.dir;
        let focus = dir.length();
        let aspect = p.res[0] as f32 / p.res[1] as f32;
        let h = (p.angle / 2.0).tan();
        let xc = dir.cross(p.up);
        let x = aspect * focus * h * (xc / xc.length());
        let yc = dir.cross(x);
        let y = focus * h * (yc / yc.length());
        let f = focus * (dir / dir.length());
        Ok(Camera {
            params: *p,
            f,
            x,
            y,
        })
    }

    /// The ray through the centre of pixel `(px, py)` (row 0 is the top):
    /// `f + 2((X + 0.5)/resX − 0.5)·x + 2((Y + 0.5)/resY − 0.5)·y`, left to
    /// right in plain `f32`.
    ///
    /// ```
    /// use rayoracle::camera::{CameraParams, textbook::Camera};
    /// use glam::Vec3;
    /// let p = CameraParams::new(Vec3::ONE, -Vec3::Z, Vec3::Y, 1.0, [3, 3]);
    /// let cam = Camera::new(&p).unwrap();
    /// assert_eq!(cam.ray(1, 1).origin, Vec3::ONE);
    /// assert_eq!(cam.ray(1, 1).dir, -Vec3::Z);
    /// // Row 0 is the top: its ray points up.
    /// assert!(cam.ray(1, 0).dir.y > 0.0);
    /// ```
    pub fn ray(&self, px: u32, py: u32) -> Ray {
        let [rx, ry] = self.params.res;
        let u = 2.0 * ((px as f32 + 0.5) / rx as f32 - 0.5);
        let v = 2.0 * ((py as f32 + 0.5) / ry as f32 - 0.5);
        Ray::new(self.params.position, self.f + u * self.x + v * self.y)
    }
}
