//! The perspective camera (seed Ex. 1.1).
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
//! Departures from the seed, and why:
//!
//! * The seed defines `y` through `x` and `x` through `y`'s direction in the
//!   wrong order; `x` comes first (from `dir × up`), then `y` from `dir × x`.
//! * The seed's `f = focus · dir/|dir|` is just `dir`; the code uses `dir`
//!   and avoids a rounding.
//! * The pixel offset `2((X + ½)/resX − ½)` is computed as
//!   `(2X + 1 − resX)/resX`: the numerator is an exact integer (hence the
//!   limit [`MAX_RESOLUTION`] `= 2²³`), so the offset is rounded once.
//! * Construction rejects what has no meaning ([`CameraError`]): a zero or
//!   non-finite `dir`/`up`, `dir` parallel to `up`, `angle` outside `(0, π)`,
//!   a zero resolution.
//!
//! # Accuracy ([`reference`](mod@reference))
//!
//! The basis (`x`, `y`) is built once per camera in double-word arithmetic
//! from exactly prescaled `dir` and `up`, with `tan` evaluated in f64 (so the
//! basis does not depend on the platform's `tanf`), powers of two kept out of
//! the double-word products, and the last product of each basis component
//! taken in f64 from the exact double-word values and rounded once at its
//! true magnitude ([`in_domain`] says where this is accurate). Per pixel the direction is `(fᵢ + u·xᵢ) + v·yᵢ` in plain f32,
//! three roundings. Each component is within [`COMPONENT_ULPS`] ulps of
//! `Sᵢ = |fᵢ| + |u xᵢ| + |v yᵢ|` of the oracle's (f64) value: the terms may
//! cancel, so the bound is relative to their size, not to the result.

pub mod double;
pub mod exact;
pub mod kernel;
pub mod reference;
pub mod textbook;
pub mod x4;

use glam::Vec3;

pub use reference::Camera;

/// The largest accepted `resX` or `resY`: pixel centres `2X + 1 − res` are
/// exact integers in f32 up to here.
pub const MAX_RESOLUTION: u32 = 1 << 23;

/// Each ray direction component is within this many ulps of
/// `Sᵢ = |fᵢ| + |u xᵢ| + |v yᵢ|` of the oracle's value, for `Sᵢ < 2¹²⁷`
/// (a partial sum can reach `Sᵢ`, and above that overflow although the
/// result would not) (see the module docs:
/// 1 ulp for the basis, ½ for the offset, ½ for each of the three products
/// and sums, rounded up, plus ½ for the oracle's own rounding).
pub const COMPONENT_ULPS: f64 = 4.0;

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

/// The accuracy domain of the reference camera's construction: with `dir`
/// and `up` each prescaled by the power of two of its largest component (as
/// the construction does), the cross product `dir' × up'` must be at least
/// `2⁻⁵⁰` long (so its double-word square is not subnormal), and what the
/// prescaling rounds away must be negligible against it
/// ([`crate::num::scale::crush_loss`]). A `dir` of `(0, −7·10⁻⁹, 3·10³⁸)`
/// loses its small component to the prescaling, and an `up` nearly parallel
/// to it leaves only that component in the cross product. The non-zero
/// components of `dir' × up'` and of the unit axes `x̂` and `ŷ` must also be
/// at least `2⁻¹⁰⁰`.
///
/// ```
/// use rayoracle::camera::{CameraParams, in_domain};
/// use glam::Vec3;
/// assert!(in_domain(&CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [4, 4])));
/// let far = CameraParams::new(Vec3::ZERO, Vec3::new(0.0, -6.7e-9, 3e38), Vec3::new(1.6e-39, 1.2e-38, 63.6), 1.0, [4, 4]);
/// assert!(!in_domain(&far));
/// ```
pub fn in_domain(p: &CameraParams) -> bool {
    use crate::num::scale::{Scale, crush_loss, in_range, negligible};
    let (d, u) = (p.dir.to_array(), p.up.to_array());
    let (sd, su) = (Scale::of_max(&d), Scale::of_max(&u));
    let exact = |v: [f32; 3], s: Scale<f32>| v.map(|x| x as f64 * 2f64.powi(-s.k));
    let (de, ue) = (exact(d, sd), exact(u, su));
    let cross = [
        de[1] * ue[2] - de[2] * ue[1],
        de[2] * ue[0] - de[0] * ue[2],
        de[0] * ue[1] - de[1] * ue[0],
    ];
    let len = cross.iter().map(|c| c * c).sum::<f64>().sqrt();
    let loss: f64 = (0..3)
        .map(|i| crush_loss(d[i], sd) * 2.0 + crush_loss(u[i], su) * 2.0)
        .sum();
    if !(in_range(len, -50, 50) && negligible(loss, len)) {
        return false;
    }
    // The unit axes x̂ = (dir × up)/|…| and ŷ = (dir × x̂)/|…| are built in
    // f32 double-words: a non-zero component below 2⁻¹⁰⁰ is built in or near
    // the subnormal range and loses its relative precision.
    let xh = cross.map(|c| c / len);
    let yc = [
        de[1] * xh[2] - de[2] * xh[1],
        de[2] * xh[0] - de[0] * xh[2],
        de[0] * xh[1] - de[1] * xh[0],
    ];
    let ylen = yc.iter().map(|c| c * c).sum::<f64>().sqrt();
    let tiny = |c: f64| c != 0.0 && c.abs() < 2f64.powi(-100);
    // A cross-product component formed in the subnormal range (from a
    // prescaled component that became subnormal) has lost bits too.
    !(cross.iter().any(|&c| tiny(c))
        || xh.iter().any(|&c| tiny(c))
        || yc.iter().any(|&c| tiny(c / ylen)))
}

/// `Sᵢ = |fᵢ| + |u xᵢ| + |v yᵢ|` in f64 for pixel `(px, py)`: the scale the
/// component bound [`COMPONENT_ULPS`] is relative to.
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

#[cfg(test)]
mod tests {
    use super::{CameraParams, in_domain};
    use glam::Vec3;

    fn domain(dir: [f32; 3], up: [f32; 3]) -> bool {
        in_domain(&CameraParams::new(
            Vec3::ZERO,
            Vec3::from(dir),
            Vec3::from(up),
            1.0,
            [4, 4],
        ))
    }

    /// `dir × up` where a component is two tiny products: exactly 0 when
    /// they cancel (in the domain), and a non-zero value below 2⁻¹⁰⁰ when
    /// they do not (outside it: built near the subnormal range).
    #[test]
    fn a_cross_product_component_of_two_tiny_products() {
        let p = |e: i32| 2f32.powi(e);
        let dir = [1.0, p(-60), p(-70)];
        // x: 2⁻⁶⁰·2⁻⁵⁰ − 2⁻⁷⁰·2⁻⁴⁰ = 0.
        assert!(domain(dir, [1.0, p(-40), p(-50)]));
        // x: 2⁻⁶⁰·2⁻⁵⁰ − 2⁻⁷⁰·2⁻⁴¹ = 2⁻¹¹¹.
        assert!(!domain(dir, [1.0, p(-41), p(-50)]));
        // The same one axis on, in y: 2⁻⁶⁰·2⁻⁵⁰ − 2⁻⁷⁰·2⁻⁴⁰ = 0.
        assert!(domain([p(-70), 1.0, p(-60)], [p(-50), 1.0, p(-40)]));
    }

    /// Each step of `in_domain` decides one of these cases alone (found by
    /// running the function's mutants over powers of two, then worked by
    /// hand). `x̂ = dir × up / |…|` and `ŷ = dir × x̂`, both of the prescaled
    /// vectors; "tiny" is non-zero and below 2⁻¹⁰⁰.
    #[test]
    fn each_step_of_the_domain_decides_a_case_alone() {
        let p = |e: i32| 2f32.powi(e);
        let cases: [([f32; 3], [f32; 3], bool, &str); 12] = [
            // dir·2⁻¹⁰⁰ = ((1+2⁻²²)·2⁻¹⁰⁰, 0, −1.5): x̂ = (0, −1, 0), and
            // ŷ = (−1.5, 0, −(1+2⁻²²)·2⁻¹⁰⁰), whose z over |ŷ| is tiny.
            (
                [1.0 + p(-22), 0.0, -1.5 * p(100)],
                [1.0, 0.0, 0.0],
                false,
                "ŷ.z tiny",
            ),
            // The same in ŷ.z through the other product: ŷ = (0, −1, 1.5·2⁻¹³⁰).
            (
                [0.0, 1.5 * p(-130), 1.0],
                [0.0, 1.0, 0.0],
                false,
                "ŷ.z tiny, dir.y",
            ),
            // ŷ.y = −2⁻¹⁰¹/√2 while ŷ.x = 1/√2 + 1/√2 is a sum, not a cancellation.
            ([p(-101), 1.0, 1.0], [-p(-101), 0.0, 0.0], false, "ŷ.y tiny"),
            // x̂ ≈ (0, 0, 1), ŷ = (1.5·2⁻¹²⁹, −1, 0).
            (
                [1.0, 1.5 * p(-129), 0.0],
                [-1.5 * p(-50), 1.0, 0.0],
                false,
                "ŷ.x tiny",
            ),
            // up·2⁵⁰ = (0, 0, 1.25): x̂ = (1, −1, 0)/√2 and
            // ŷ = (dir.z/√2, dir.z/√2, −√2) with dir.z/√2 over |ŷ| = 1.25·2⁻¹¹¹.
            (
                [1.0, 1.0, 1.25 * p(-110)],
                [0.0, 0.0, 1.25 * p(-50)],
                false,
                "ŷ.x, ŷ.y tiny",
            ),
            // dir·2⁻¹⁰⁰ = (−1.5, 0, 2⁻¹⁰⁰): dir × up = (2⁻¹⁰⁰, 0, 1.5) is not
            // tiny, but x̂ = (2⁻¹⁰⁰/1.5, 0, 1) is.
            (
                [-1.5 * p(100), 0.0, 1.0],
                [0.0, -1.0, 0.0],
                false,
                "x̂.x tiny",
            ),
            // Exactly 2⁻¹⁰⁰ is not tiny: dir × up = (2⁻¹⁰⁰, 0, −1), ŷ = (−1, 0, −2⁻¹⁰⁰).
            ([0.0, 1.0, 0.0], [1.0, 0.0, p(-100)], true, "2⁻¹⁰⁰ exactly"),
            (
                [0.0, 1.25 * p(-100), 1.0],
                [0.0, 1.0, 0.0],
                true,
                "ŷ.z = 1.25·2⁻¹⁰⁰",
            ),
            // dir·2⁻¹⁰⁰ = (0, 1, 2⁻¹⁰⁰), up·2⁶⁰ = (−1, 0, 0):
            // x̂ = (0, −2⁻¹⁰⁰, 1) and ŷ = (1, 0, 0).
            (
                [0.0, p(100), 1.0],
                [-p(-60), 0.0, 0.0],
                true,
                "x̂.y = −2⁻¹⁰⁰",
            ),
            // dir × up = (−2⁻⁷⁰, 1, 2⁻⁷⁰ + 2⁻¹⁰¹), ŷ ≈ (−1, −2⁻⁶⁹, 1).
            (
                [1.0, -p(-101), 1.0],
                [1.0, p(-70), 0.0],
                true,
                "nothing below 2⁻¹⁰⁰",
            ),
            // z of dir × up: 2⁻⁶⁰·2⁻⁵⁰ − 2⁻⁷⁰·2⁻⁴⁰ = 0, as the test above in x and y.
            (
                [p(-60), p(-70), 1.0],
                [p(-40), p(-50), 1.0],
                true,
                "z cancels exactly",
            ),
            // dir ∥ up exactly, so dir × up = 0, but up·2⁻¹⁰⁰ rounds its z
            // (1+2⁻²²)·2⁻¹³⁰ in the subnormal range: the loss is not negligible
            // against |dir × up| = 0, and it is dir's scale 2⁰ that is exact.
            (
                [1.0, 0.0, p(-130)],
                [p(100) * (1.0 + p(-22)), 0.0, (1.0 + p(-22)) * p(-30)],
                false,
                "up crushed, dir exact",
            ),
        ];
        for (dir, up, want, why) in cases {
            assert_eq!(domain(dir, up), want, "{why}: dir {dir:?}, up {up:?}");
        }
    }
}
