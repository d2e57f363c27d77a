//! The reference camera: a double-word basis built once, plain f32 per pixel.

use super::{CameraError, CameraParams, MAX_RESOLUTION, kernel};
use crate::Ray;
use crate::num::Ff;
use crate::num::scale::normalized3;
use glam::Vec3;

/// A validated camera with its basis: `x` (right, half-width) and `y` (down,
/// half-height), in world units scaled by `|dir|`.
///
/// ```
/// use rayoracle::camera::CameraParams;
/// use glam::Vec3;
/// let cam = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, std::f32::consts::FRAC_PI_2, [2, 2])
///     .build()
///     .unwrap();
/// // 90° vertical field of view, square: half extents of 1 at distance 1.
/// assert!((cam.x - Vec3::X).length() < 1e-6);
/// assert!((cam.y + Vec3::Y).length() < 1e-6);
/// // Row 0 is the top: its ray points up.
/// assert!(cam.ray(0, 0).dir.y > 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Camera {
    /// The inputs.
    pub params: CameraParams,
    /// The horizontal half-extent vector.
    pub x: Vec3,
    /// The vertical half-extent vector (pointing down the image).
    pub y: Vec3,
}

fn ff3(v: [f32; 3]) -> [Ff<f32>; 3] {
    v.map(Ff::from)
}

/// `a × b` of double-word vectors.
fn cross_ff(a: [Ff<f32>; 3], b: [Ff<f32>; 3]) -> [Ff<f32>; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// `v/|v|` in double-word; `None` when `|v| = 0`. `v` is first scaled by
/// the power of two of its largest component (exactly, and without changing
/// `v/|v|`), so that `|v|²` is neither subnormal nor overflowing: a cross
/// product of nearly parallel vectors can be `10⁻²¹` and its square `10⁻⁴²`.
fn normalize_ff(v: [Ff<f32>; 3]) -> Option<[Ff<f32>; 3]> {
    let s = crate::num::scale::Scale::of_max(&[v[0].hi, v[1].hi, v[2].hi]);
    let v = v.map(|c| Ff {
        hi: s.apply(c.hi),
        lo: s.apply(c.lo),
    });
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    (n.hi > 0.0).then(|| v.map(|c| c / n))
}

fn check_vec(v: Vec3, zero: CameraError, nonfinite: CameraError) -> Result<(), CameraError> {
    if !v.is_finite() {
        Err(nonfinite)
    } else if v == Vec3::ZERO {
        Err(zero)
    } else {
        Ok(())
    }
}

/// `u = (2X + 1 − resX)/resX` and `v` likewise: the seed's
/// `2((X + ½)/res − ½)` with an exact numerator and one rounding.
///
/// ```
/// use rayoracle::camera::reference::pixel_offsets;
/// assert_eq!(pixel_offsets([4, 2], 0, 1), (-0.75, 0.5));
/// ```
pub fn pixel_offsets(res: [u32; 2], px: u32, py: u32) -> (f32, f32) {
    (kernel::offset(px, res[0]), kernel::offset(py, res[1]))
}

impl Camera {
    /// Validates `p` and builds the basis.
    ///
    /// ```
    /// use rayoracle::camera::{Camera, CameraParams, CameraError};
    /// use glam::Vec3;
    /// let bad = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 0.0, [4, 4]);
    /// assert_eq!(Camera::new(&bad).unwrap_err(), CameraError::AngleOutOfRange(0.0));
    /// ```
    pub fn new(p: &CameraParams) -> Result<Camera, CameraError> {
        check_vec(p.dir, CameraError::DirZero, CameraError::DirNonFinite)?;
        check_vec(p.up, CameraError::UpZero, CameraError::UpNonFinite)?;
        // Every f32 below PI (which is above π) is below π.
        if !(p.angle > 0.0 && p.angle < core::f32::consts::PI) {
            return Err(CameraError::AngleOutOfRange(p.angle));
        }
        for r in p.res {
            if r == 0 {
                return Err(CameraError::ZeroResolution);
            }
            if r > MAX_RESOLUTION {
                return Err(CameraError::ResolutionTooLarge(r));
            }
        }
        // Exact prescaling: only the directions of dir and up matter for the
        // axes; |dir| = |dir'|·2^kd.
        let (d, sd) = normalized3(p.dir.to_array());
        let kd = sd.k;
        let dir = ff3(d);
        let up = ff3(normalized3(p.up.to_array()).0);

        let x_hat = normalize_ff(cross_ff(dir, up)).ok_or(CameraError::DirParallelToUp)?;
        let y_hat = normalize_ff(cross_ff(dir, x_hat)).ok_or(CameraError::DirParallelToUp)?;

        let focus = (dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]).sqrt();
        // tan(angle/2) in f64, independent of the platform's tanf. Its
        // binary exponent, together with the prescale 2^kd of |dir|, is kept
        // apart from the double-word products (whose significand stays in
        // [1, 2), never subnormal), and each basis component is rounded once,
        // at its true magnitude, from the exact f64 value of its double-word.
        let h64 = (p.angle as f64 / 2.0).tan();
        let eh = ((h64.to_bits() >> 52) & 0x7ff) as i32 - 1023;
        let hm = h64 * 2f64.powi(-eh);
        let h = Ff {
            hi: hm as f32,
            lo: (hm - (hm as f32) as f64) as f32,
        };
        let aspect = Ff::from(p.res[0] as f32) / Ff::from(p.res[1] as f32);
        let len_y = focus * h;
        let len_x = len_y * aspect;
        // The last product in f64, from the exact values of the double-words:
        // f64's range keeps it out of the subnormals that a product at the
        // prescaled magnitude could fall into; one rounding to f32.
        let scale = 2f64.powi(kd + eh);
        let f64_of = |v: Ff<f32>| v.hi as f64 + v.lo as f64;
        let (lx, ly) = (f64_of(len_x) * scale, f64_of(len_y) * scale);
        let x = x_hat.map(|c| (f64_of(c) * lx) as f32);
        let y = y_hat.map(|c| (f64_of(c) * ly) as f32);
        let (x, y) = (Vec3::from_array(x), Vec3::from_array(y));
        if !(x.is_finite() && y.is_finite()) {
            return Err(CameraError::BasisOverflow);
        }
        Ok(Camera { params: *p, x, y })
    }

    /// The ray through the centre of pixel `(px, py)`; row 0 is the top.
    /// Pixels outside the image extrapolate the same formula.
    ///
    /// ```
    /// use rayoracle::camera::CameraParams;
    /// use glam::Vec3;
    /// let cam = CameraParams::new(Vec3::ONE, -Vec3::Z, Vec3::Y, 1.0, [3, 3]).build().unwrap();
    /// let centre = cam.ray(1, 1);
    /// assert_eq!(centre.origin, Vec3::ONE);
    /// assert_eq!(centre.dir, -Vec3::Z);
    /// ```
    pub fn ray(&self, px: u32, py: u32) -> Ray {
        let (u, v) = pixel_offsets(self.params.res, px, py);
        let dir = kernel::pixel_dir(
            self.params.dir.to_array(),
            self.x.to_array(),
            self.y.to_array(),
            u,
            v,
        );
        Ray::new(self.params.position, Vec3::from_array(dir))
    }
}
