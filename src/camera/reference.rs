//! The reference camera: the basis in f64 with a proven bound once per
//! camera ([`basis`](mod@basis), or the big-integer enclosures where that
//! leaves a component undecided), each pixel's direction in f64 with a
//! proven bound ([`filter`]), and the rare undecided component from the
//! oracle ([`super::exact`]). Every component
//! is correctly rounded.

use super::{CameraError, CameraParams, MAX_RESOLUTION, basis, filter};
use crate::Ray;
use crate::num::certify::widen_bits;
use crate::num::real::{F64x4, Real};
use glam::Vec3;

/// A validated camera with its basis: `x` (right, half-width) and `y` (down,
/// half-height), in world units scaled by `|dir|`, each component correctly
/// rounded from its real value.
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
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    /// The inputs.
    pub params: CameraParams,
    /// The horizontal half-extent vector.
    pub x: Vec3,
    /// The vertical half-extent vector (pointing down the image).
    pub y: Vec3,
    /// `xᵢ/resX` and `yᵢ/resY` to within `2⁻⁵²` relatively, for
    /// [`filter::component`] (NaN where out of its range).
    pub(super) unit: [[f64; 3]; 2],
    /// `dir` in f64, widened from its bits.
    pub(super) d64: [f64; 3],
    /// The filter's bound terms, `err[j][i]` for component `i`
    /// ([`filter::bound_terms`]).
    pub(super) err: [[f64; 3]; 3],
    /// The filter's bound for every pixel of the image ([`filter::bound`]
    /// at the largest numerators).
    pub(super) e_image: [f64; 3],
    /// Whether some `unit` value is NaN: then every pixel is settled
    /// ([`Camera::settle`]).
    pub(super) slow: bool,
}

/// Cameras are equal when their inputs are: everything else is built from
/// them (and the per-unit basis may hold NaN, which `==` would not match).
impl PartialEq for Camera {
    fn eq(&self, o: &Camera) -> bool {
        self.params == o.params
    }
}

/// The zero test is on the bits, ORed together (which the optimiser does
/// not turn back into float comparisons): denormals-are-zero would read a
/// vector of subnormal components as zero.
fn check_vec(v: Vec3, zero: CameraError, nonfinite: CameraError) -> Result<(), CameraError> {
    let [a, b, c] = v.to_array().map(f32::to_bits);
    if !v.is_finite() {
        Err(nonfinite)
    } else if (a | b | c) << 1 == 0 {
        Err(zero)
    } else {
        Ok(())
    }
}

/// `u = (2X + 1 − resX)/resX` and `v` likewise, rounded once to `f32`: the
/// usual `2((X + ½)/res − ½)` as numbers, for the scale `Sᵢ`
/// ([`super::component_scale`]); the kernels use the exact values.
///
/// ```
/// use rayoracle::camera::reference::pixel_offsets;
/// assert_eq!(pixel_offsets([4, 2], 0, 1), (-0.75, 0.5));
/// ```
pub fn pixel_offsets(res: [u32; 2], px: u32, py: u32) -> (f32, f32) {
    (filter::offset(px, res[0]), filter::offset(py, res[1]))
}

/// The basis from the big-integer enclosures, where [`basis::basis`]
/// leaves a component undecided (or `dir × up = 0`).
#[cold]
#[inline(never)]
fn slow_basis(p: &CameraParams) -> Result<basis::Basis, CameraError> {
    // A camera the f64 stage leaves undecided is often built again at
    // once (its rays judged pixel by pixel): the last one is kept.
    type Key = ([u32; 3], [u32; 3], u32, [u32; 2]);
    thread_local! {
        static LAST: core::cell::Cell<Option<(Key, Result<basis::Basis, CameraError>)>> =
            const { core::cell::Cell::new(None) };
    }
    let bits = |v: Vec3| v.to_array().map(f32::to_bits);
    let key = (bits(p.dir), bits(p.up), p.angle.to_bits(), p.res);
    if let Some((k, b)) = LAST.get()
        && k == key
    {
        return b;
    }
    let b = if super::exact::Exact::new(p).parallel() {
        Err(CameraError::DirParallelToUp)
    } else {
        super::exact::with_approx(p, basis_of)
    };
    LAST.set(Some((key, b)));
    b
}

/// The basis from the oracle's enclosures.
fn basis_of(
    e: &super::exact::Exact,
    a: &super::exact::Approx,
) -> Result<basis::Basis, CameraError> {
    let mut unit = [[0.0; 3]; 2];
    let (mut x, mut y) = ([0.0; 3], [0.0; 3]);
    for i in 0..3 {
        (x[i], y[i]) = e.round_basis(a, i);
        let (bx, by) = e.unit_basis(a, i);
        // Zero exactly where the real value is; NaN (never certified)
        // where it is too small for the kernel's bound.
        for (k, b) in [bx, by].iter().enumerate() {
            let f = b.lo.to_f64();
            let zero = b.lo.signum() == 0 && b.hi.signum() == 0;
            unit[k][i] = if zero {
                0.0
            } else if f.abs() >= 2f64.powi(-1000) {
                f
            } else {
                f64::NAN
            };
        }
    }
    Ok(basis::Basis { x, y, unit })
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
        // `angle > 0` on the bits, as for `dir` and `up` above.
        let positive = (1..0x8000_0000).contains(&p.angle.to_bits());
        if !(positive && p.angle < core::f32::consts::PI) {
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
        let basis::Basis { x, y, unit } = match basis::basis(p, 1.0) {
            Some(b) => b,
            None => slow_basis(p)?,
        };
        let (x, y) = (Vec3::from_array(x), Vec3::from_array(y));
        if !(x.is_finite() && y.is_finite()) {
            return Err(CameraError::BasisOverflow);
        }
        let d = p.dir.to_array();
        let t: [[f64; 3]; 3] =
            core::array::from_fn(|i| filter::bound_terms(d[i], unit[0][i], unit[1][i]));
        let corner = p.res.map(|r| filter::numerator(0, r));
        Ok(Camera {
            params: *p,
            x,
            y,
            unit,
            d64: d.map(|d| widen_bits(d.to_bits())),
            err: core::array::from_fn(|j| t.map(|e| e[j])),
            e_image: t.map(|t| filter::bound(corner, t)),
            slow: unit.as_flattened().iter().any(|u| u.is_nan()),
        })
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
    #[inline(always)]
    pub fn ray(&self, px: u32, py: u32) -> Ray {
        Ray::new(
            self.params.position,
            Vec3::from_array(self.dir(px, py, 1.0)),
        )
    }

    /// The direction for pixel `(px, py)`, with the filter's bound scaled by
    /// `shrink` (1 in [`Camera::ray`]). Always inlined, as `ray` is: where
    /// LLVM left it out of line in the kernels bench's loop,
    /// `camera/reference/per-ray` ran at 53 to 67 Mrays/s, against 72 to
    /// 138 inlined (runs minutes apart, one build each).
    #[inline(always)]
    pub(crate) fn dir(&self, px: u32, py: u32, shrink: f64) -> [f32; 3] {
        let [rx, ry] = self.params.res;
        let n = [filter::numerator(px, rx), filter::numerator(py, ry)];
        // The three components in the lanes of one F64x4 (two SSE2
        // registers in a default build), the fourth lane idle.
        let lanes = |v: [f64; 3]| F64x4::from([v[0], v[1], v[2], 0.0]);
        let s = <F64x4 as Real>::splat;
        let e = if px < rx && py < ry {
            lanes(self.e_image)
        } else {
            filter::bound(n.map(s), self.err.map(lanes))
        };
        let (out, ok) = filter::component(
            lanes(self.d64),
            [lanes(self.unit[0]), lanes(self.unit[1])],
            n.map(s),
            e * s(shrink),
        );
        // Decided, and neither 0 nor subnormal (where flush-to-zero, or an
        // exact zero, may matter).
        let good = ok & !filter::tiny(out);
        let [o0, o1, o2, _] = out.to_array();
        let mut out = [o0, o1, o2];
        if good.to_bitmask() & 0b111 != 0b111 || self.slow {
            let ok = ok.to_bitmask();
            self.settle(&mut out, [0, 1, 2].map(|i| ok & 1 << i != 0), n);
        }
        out
    }

    /// The components of one pixel that the filter leaves undecided or
    /// that are 0 or subnormal (all three where the camera is `slow`):
    /// `dᵢ` where that is exact ([`filter::exact`]), else the oracle where
    /// the filter's answer does not stand. `ok` is the filter's verdict,
    /// `n` the pixel's numerators.
    #[cold]
    #[inline(never)]
    pub(crate) fn settle(&self, out: &mut [f32; 3], ok: [bool; 3], n: [f64; 2]) {
        let d = self.params.dir.to_array();
        let flushed = filter::flushed(out);
        let mut undecided = [false; 3];
        for i in 0..3 {
            let b = [self.unit[0][i], self.unit[1][i]];
            if filter::exact(b, n) {
                out[i] = d[i];
            } else {
                undecided[i] = flushed || !ok[i] || b[0].is_nan() || b[1].is_nan();
            }
        }
        if undecided.contains(&true) {
            self.escalate(out, undecided, n);
        }
    }

    /// The undecided components of one pixel, from the oracle; `n` holds
    /// the pixel's numerators ([`filter::numerator`], integers below `2³⁴`
    /// in magnitude, so exact in f64).
    #[cold]
    #[inline(never)]
    pub(crate) fn escalate(&self, out: &mut [f32; 3], undecided: [bool; 3], n: [f64; 2]) {
        let (nx, ny) = (n[0] as i64, n[1] as i64);
        super::exact::with_approx(&self.params, |e, a| {
            for i in (0..3).filter(|&i| undecided[i]) {
                out[i] = e.round_component(a, i, nx, ny);
            }
        });
    }

    /// [`Camera::ray`] with the filter's bound multiplied by `shrink`: with
    /// `shrink < 1` it certifies what the bound does not, and some
    /// components come out wrong (`tests/props_camera.rs` finds them).
    ///
    /// ```
    /// use rayoracle::camera::CameraParams;
    /// use glam::Vec3;
    /// let cam = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [8, 6]).build().unwrap();
    /// assert_eq!(cam.ray_shrunk(3, 2, 1.0), cam.ray(3, 2));
    /// ```
    pub fn ray_shrunk(&self, px: u32, py: u32, shrink: f64) -> Ray {
        Ray::new(
            self.params.position,
            Vec3::from_array(self.dir(px, py, shrink)),
        )
    }
}
