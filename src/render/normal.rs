//! Surface normals at a hit, written once over [`Lane`] so the reference
//! (f32) and x4 (`f32x4`) renders give the same bits.
//!
//! Normals are for looking at, not part of the oracle: they are plain f32
//! (`p = o + t d`, then the primitive's gradient at `p`), made unit length
//! after an exact power-of-two prescale (so neither tiny nor huge gradients
//! overflow or vanish in `|v|²`), and turned to face the ray (`n·d ≤ 0`),
//! which makes the picture independent of the sign convention of a plane's
//! normal or a quadric's coefficients. Where the gradient is zero or not
//! finite (a cone's apex; a double plane, whose gradient vanishes on the
//! surface) the normal is `(0, 0, 0)`.

use crate::num::Lane;
use crate::num::scale::normalized3;

/// The hit point `o + t d`, componentwise in plain f32.
///
/// ```
/// use rayoracle::render::normal::hit_point;
/// assert_eq!(hit_point([1.0f32, 0.0, 0.0], [0.0, 2.0, 0.0], 0.5), [1.0, 1.0, 0.0]);
/// ```
#[inline(always)]
pub fn hit_point<L: Lane>(o: [L; 3], d: [L; 3], t: L) -> [L; 3] {
    [o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]]
}

/// A sphere's outward direction at `p`: `p − c`.
///
/// ```
/// use rayoracle::render::normal::sphere;
/// assert_eq!(sphere([1.0f32, 2.0, 3.0], [1.0, 0.0, 0.0]), [0.0, 2.0, 3.0]);
/// ```
#[inline(always)]
pub fn sphere<L: Lane>(p: [L; 3], c: [L; 3]) -> [L; 3] {
    [p[0] - c[0], p[1] - c[1], p[2] - c[2]]
}

/// A quadric's gradient at `p`:
/// `(2Ax + Dy + Ez + G, 2By + Dx + Fz + H, 2Cz + Ex + Fy + I)`.
///
/// ```
/// use rayoracle::render::normal::quadric;
/// // x² + y² − 1 at (1, 0, 5): gradient (2, 0, 0).
/// let k = [1.0f32, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// assert_eq!(quadric(&k, [1.0, 0.0, 5.0]), [2.0, 0.0, 0.0]);
/// // Every term, with k = 1..10 at (2, 3, 5): x is 4 + 12 + 25 + 7,
/// // y is 12 + 8 + 30 + 8, z is 30 + 10 + 18 + 9.
/// let k = [1.0f32, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0, 10.0];
/// assert_eq!(quadric(&k, [2.0, 3.0, 5.0]), [48.0, 58.0, 67.0]);
/// ```
#[inline(always)]
pub fn quadric<L: Lane>(k: &[L; 10], p: [L; 3]) -> [L; 3] {
    let two = L::splat(2.0);
    let [x, y, z] = p;
    [
        two * k[0] * x + k[3] * y + k[4] * z + k[6],
        two * k[1] * y + k[3] * x + k[5] * z + k[7],
        two * k[2] * z + k[4] * x + k[5] * y + k[8],
    ]
}

/// `v` made unit length and turned to face `d` (`result·d ≤ 0`); `(0, 0, 0)`
/// where `v` is zero or not finite.
///
/// ```
/// use rayoracle::render::normal::facing_unit;
/// assert_eq!(facing_unit([0.0f32, 3.0, 0.0], [0.0, 1.0, 0.0]), [0.0, -1.0, 0.0]);
/// assert_eq!(facing_unit([0.0f32, 0.0, 1e-30], [1.0, 0.0, 0.0]), [0.0, 0.0, 1.0]);
/// assert_eq!(facing_unit([0.0f32; 3], [1.0, 0.0, 0.0]), [0.0; 3]);
/// ```
#[inline(always)]
pub fn facing_unit<L: Lane>(v: [L; 3], d: [L; 3]) -> [L; 3] {
    // Both prescaled by a power of two (exact), so neither the dot product
    // nor the squared length can overflow or lose everything to underflow.
    let (u, _) = normalized3(v);
    let (e, _) = normalized3(d);
    let dot = u[0] * e[0] + u[1] * e[1] + u[2] * e[2];
    let zero = L::splat(0.0);
    let sign = L::select_gt(dot, zero, L::splat(-1.0), L::splat(1.0));
    let len = (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]).sqrt();
    let unit = |x: L| (sign * x / len).finite_or_zero();
    [unit(u[0]), unit(u[1]), unit(u[2])]
}
