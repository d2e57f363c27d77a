//! The perspective camera.
//!
//! # The derivation, as corrected
//!
//! From the position, a view direction `dir`, an `up` vector, the vertical
//! field of view `angle` and the resolution `resX × resY`:
//!
//! ```text
//! focus = |dir|,  f = dir,  h = tan(angle/2),  aspect = resX / resY
//! x = aspect · focus · h · (dir × up) / |dir × up|
//! y = focus · h · (dir × x) / |dir × x|
//! ray.dir(X, Y) = f + 2((X + ½)/resX − ½) · x + 2((Y + ½)/resY − ½) · y
//! ```
//!
//! The direction is not normalised. Row 0 is the top: with `dir = −z`,
//! `up = +y`, `x` points right (+x) and `y` points down (−y), so `Y = 0`
//! gives the largest `+y` component.
//!
//! Departures from the usual hand derivation, and why:
//!
//! * It is often written with `y` defined through `x` and `x` through
//!   `y`'s direction, which is circular; `x` comes first (from `dir × up`), then `y` from `dir × x`.
//! * Its `f = focus · dir/|dir|` is just `dir`; the code uses `dir`
//!   and avoids a rounding.
//! * The pixel offset `2((X + ½)/resX − ½)` is the exact rational
//!   `u = (2X + 1 − resX)/resX` (`v` likewise), never rounded by the
//!   kernels; its integer numerator is exact even in f32 up to the limit
//!   [`MAX_RESOLUTION`] `= 2²³`.
//! * Construction rejects what has no meaning ([`CameraError`]): a zero or
//!   non-finite `dir`/`up`, `dir` parallel to `up`, `angle` outside `(0, π)`,
//!   a zero resolution.
//!
//! # Accuracy ([`reference`](mod@reference))
//!
//! Every component of every ray direction, and of the basis `x` and `y`,
//! is the real value of the formulas above correctly rounded to `f32`
//! (nearest, ties to even), with `u`, `v` and `aspect` exact rationals and
//! `h` the real tangent of the `f32` half angle: [`exact`] states the
//! definition, the treatment of exact zeros, and why the oracle's Ziv loop
//! ends. Per camera the basis is evaluated in f64 with a proven bound
//! ([`basis`](mod@basis)), and enclosed over big integers ([`tan`]) only
//! where that leaves a component undecided; per pixel an f64 evaluation
//! with a proven bound ([`filter`]) decides nearly every component, and the
//! oracle the rest. The reference and the four-lane
//! kernels ([`x4`](mod@x4)) therefore agree with [`exact::ray`] bit for bit.
//!
//! # NaN and infinite inputs
//!
//! A NaN or infinite component of `dir` or `up`, and a NaN or infinite
//! `angle`, are rejected at construction ([`CameraError::DirNonFinite`],
//! [`CameraError::UpNonFinite`], [`CameraError::AngleOutOfRange`]), by the
//! reference, the four-lane kernels and the oracle alike; no ray is made.
//! A finite camera whose basis rounds to ±∞ is rejected too
//! ([`CameraError::BasisOverflow`]); a direction component whose real value
//! is beyond `f32::MAX` (plus half an ulp) is ±∞, as rounding defines.

pub mod basis;
pub mod exact;
pub mod filter;
pub mod plain;
pub mod reference;
pub mod tan;
pub mod textbook;
pub mod x4;

use glam::Vec3;

pub use reference::Camera;

/// The largest accepted `resX` or `resY`: pixel centres `2X + 1 − res` are
/// exact integers in f32 up to here.
pub const MAX_RESOLUTION: u32 = 1 << 23;

/// The camera's inputs, as a scene or an `eval` line gives them.
///
/// ```
/// use rayoracle::camera::CameraParams;
/// use glam::Vec3;
/// let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [64, 48]);
/// assert!(p.build().is_ok());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraParams {
    /// The eye position, every ray's origin.
    pub position: Vec3,
    /// The view direction; its length is the focal distance.
    pub dir: Vec3,
    /// The up vector; need not be orthogonal to `dir`.
    pub up: Vec3,
    /// Vertical field of view in radians, in `(0, π)`.
    pub angle: f32,
    /// `[resX, resY]`.
    pub res: [u32; 2],
}

impl CameraParams {
    /// The parameters, unchecked.
    ///
    /// ```
    /// use rayoracle::camera::CameraParams;
    /// use glam::Vec3;
    /// assert_eq!(CameraParams::new(Vec3::ZERO, Vec3::X, Vec3::Y, 1.0, [1, 1]).res, [1, 1]);
    /// ```
    pub const fn new(position: Vec3, dir: Vec3, up: Vec3, angle: f32, res: [u32; 2]) -> Self {
        CameraParams {
            position,
            dir,
            up,
            angle,
            res,
        }
    }

    /// Validates and builds the reference camera.
    ///
    /// ```
    /// use rayoracle::camera::{CameraParams, CameraError};
    /// use glam::Vec3;
    /// let p = CameraParams::new(Vec3::ZERO, Vec3::Y, Vec3::Y, 1.0, [4, 4]);
    /// assert_eq!(p.build().unwrap_err(), CameraError::DirParallelToUp);
    /// ```
    pub fn build(&self) -> Result<Camera, CameraError> {
        Camera::new(self)
    }
}

/// Why a camera could not be built. [`CameraError::field`] names the input.
///
/// ```
/// use rayoracle::camera::CameraError;
/// assert_eq!(CameraError::ZeroResolution.field(), "res");
/// assert!(CameraError::ZeroResolution.to_string().contains("res"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CameraError {
    /// `dir` is zero.
    DirZero,
    /// `dir` has a NaN or infinite component.
    DirNonFinite,
    /// `up` is zero.
    UpZero,
    /// `up` has a NaN or infinite component.
    UpNonFinite,
    /// `dir × up = 0`: no horizontal axis.
    DirParallelToUp,
    /// The field of view is not in `(0, π)`.
    AngleOutOfRange(f32),
    /// `resX` or `resY` is 0.
    ZeroResolution,
    /// `resX` or `resY` exceeds [`MAX_RESOLUTION`].
    ResolutionTooLarge(u32),
    /// The basis overflowed f32 (`|dir| · tan(angle/2) · aspect` too large).
    BasisOverflow,
}

impl CameraError {
    /// The input field the error is about.
    ///
    /// ```
    /// use rayoracle::camera::CameraError;
    /// assert_eq!(CameraError::AngleOutOfRange(4.0).field(), "angle");
    /// ```
    pub fn field(&self) -> &'static str {
        match self {
            CameraError::DirZero | CameraError::DirNonFinite => "dir",
            CameraError::UpZero | CameraError::UpNonFinite => "up",
            CameraError::DirParallelToUp => "up",
            CameraError::AngleOutOfRange(_) => "angle",
            CameraError::ZeroResolution | CameraError::ResolutionTooLarge(_) => "res",
            CameraError::BasisOverflow => "dir",
        }
    }
}

impl core::fmt::Display for CameraError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let field = self.field();
        match self {
            CameraError::DirZero => write!(f, "{field}: is zero"),
            CameraError::DirNonFinite => write!(f, "{field}: has a NaN or infinite component"),
            CameraError::UpZero => write!(f, "{field}: is zero"),
            CameraError::UpNonFinite => write!(f, "{field}: has a NaN or infinite component"),
            CameraError::DirParallelToUp => write!(
                f,
                "{field}: is parallel to dir, so there is no horizontal axis"
            ),
            CameraError::AngleOutOfRange(a) => {
                write!(f, "{field}: {a} is outside the open interval (0, π)")
            }
            CameraError::ZeroResolution => write!(f, "{field}: a resolution of 0"),
            CameraError::ResolutionTooLarge(r) => {
                write!(f, "{field}: {r} exceeds the limit {MAX_RESOLUTION}")
            }
            CameraError::BasisOverflow => {
                write!(f, "{field}: |dir|·tan(angle/2)·aspect overflows f32")
            }
        }
    }
}

impl std::error::Error for CameraError {}

/// `Sᵢ = |fᵢ| + |u xᵢ| + |v yᵢ|` in f64 for pixel `(px, py)`: the size of
/// the terms a component sums, which may cancel. The gate judges cameras
/// other than rayoracle's own with an allowance of ulps of `Sᵢ`
/// ([`crate::check`]).
///
/// ```
/// use rayoracle::camera::{CameraParams, component_scale};
/// use glam::Vec3;
/// let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [2, 2]);
/// let s = component_scale(&p.build().unwrap(), 0, 0);
/// assert!(s[2] >= 1.0);
/// ```
pub fn component_scale(cam: &Camera, px: u32, py: u32) -> [f64; 3] {
    let (u, v) = reference::pixel_offsets(cam.params.res, px, py);
    let (f, x, y) = (cam.params.dir, cam.x, cam.y);
    [0, 1, 2].map(|i| {
        (f[i] as f64).abs() + (u as f64 * x[i] as f64).abs() + (v as f64 * y[i] as f64).abs()
    })
}
