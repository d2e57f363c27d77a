//! The per-pixel camera arithmetic, written once over [`Lane`] and
//! instantiated at `f32` by [`super::Camera::ray`] and at `f32x4` by the
//! four-pixel functions in [`super::x4`].

use crate::num::Lane;

/// `(2p + 1 − res) / res`: the seed's `2((p + ½)/res − ½)` with an exact
/// integer numerator (for `res ≤ 2²³`) and one rounding.
///
/// ```
/// use rayoracle::camera::kernel::offset;
/// assert_eq!(offset(0, 4), -0.75);
/// ```
#[inline(always)]
pub fn offset(p: u32, res: u32) -> f32 {
    (2 * p as i64 + 1 - res as i64) as f32 / res as f32
}

/// `dir = (f + u·x) + v·y`, component by component, in that order.
///
/// ```
/// use rayoracle::camera::kernel::pixel_dir;
/// let d = pixel_dir([0.0f32, 0.0, -1.0], [1.0, 0.0, 0.0], [0.0, -1.0, 0.0], 0.5, -0.5);
/// assert_eq!(d, [0.5, 0.5, -1.0]);
/// ```
#[inline(always)]
pub fn pixel_dir<L: Lane>(f: [L; 3], x: [L; 3], y: [L; 3], u: L, v: L) -> [L; 3] {
    [
        (f[0] + u * x[0]) + v * y[0],
        (f[1] + u * x[1]) + v * y[1],
        (f[2] + u * x[2]) + v * y[2],
    ]
}
