//! Certified rounding: the `f32` a real number rounds to, from an f64
//! approximation `t` and a proven bound `e ≥ |t − x|` on its error.
//!
//! Rounding to `f32` is monotone, so if both ends of `[t − e, t + e]` round
//! to the same `f32`, so does every real in between, the exact `x`
//! included. That one test covers subnormal results, ±0 (the two zeros have
//! different bits, so an enclosure that straddles 0 is never certified) and
//! overflow to ±∞ without special cases; a NaN anywhere fails it.
//!
//! The ends are themselves computed in f64, rounded to nearest, so the
//! radius is widened first: `e' = (e + 2⁻⁵¹|t|)(1 + 2⁻⁴⁰)`. The `2⁻⁵¹|t|`
//! term covers the rounding of `t ∓ e'` (at most `2⁻⁵³|t ∓ e'|`); the factor
//! covers the rounding of the few dozen operations that evaluated `e` from
//! its formula, each a relative `2⁻⁵³`, and of `e'` itself.

use super::real::Real;

/// The unit roundoff of f64, `u = 2⁻⁵³`.
pub const U: f64 = f64::EPSILON / 2.0;

/// Whether every real within `e` of `t` rounds to one `f32`, lane by lane;
/// where it does, that `f32` is `t as f32`.
///
/// ```
/// use rayoracle::num::certify::certify;
/// // 1/3 to within 1e-12: every such real rounds to 1/3f32.
/// assert!(certify(1.0 / 3.0, 1e-12));
/// // Straddling the midpoint between 1 and the next f32: undecided.
/// let mid = 1.0 + f32::EPSILON as f64 / 2.0;
/// assert!(!certify(mid, 1e-12));
/// // Straddling 0: +0 and −0 differ.
/// assert!(!certify(0.0, 1e-300));
/// assert!(certify(0.0, 0.0));
/// assert!(!certify(f64::NAN, 0.0));
/// ```
#[inline(always)]
pub fn certify<L: Real>(t: L, e: L) -> L::Mask {
    let e = (e + t.abs() * L::splat(2f64.powi(-51))) * L::splat(1.0 + 2f64.powi(-40));
    let nonneg = e.gt(L::splat(0.0)) | e.eq(L::splat(0.0));
    L::same_f32(t - e, t + e) & nonneg
}
