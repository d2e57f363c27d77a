//! Exact power-of-two prescaling, so that the double-word arithmetic never
//! overflows, never sinks into the subnormal range, and never splits a number
//! above `2^115` (see [`super::eft::split`]).
//!
//! Scaling by `2^k` is exact (barring underflow of components that are
//! negligible anyway next to the largest one), and every kernel knows how its
//! roots transform: a plane's `t` is unchanged by scaling `n`, every root
//! scales by `2^−k` when `d` is scaled by `2^k`, and by `2^k` when all
//! positions and lengths are.

use super::Lane;

/// `⌊log₂ max|xᵢ|⌋`: the exponent that brings the largest magnitude into
/// `[1, 2)`. Zero when the maximum is zero or not finite.
///
/// ```
/// use rayoracle::num::scale::exponent_of_max;
/// assert_eq!(exponent_of_max(&[3.0f32, -1e3, 0.5]), 9);
/// ```
#[inline(always)]
pub fn exponent_of_max<L: Lane>(xs: &[L]) -> L::Int {
    let mut m = xs[0].abs();
    for &x in &xs[1..] {
        m = x.abs().max(m);
    }
    m.ilogb()
}

/// `v · 2^e`, component-wise.
///
/// ```
/// use rayoracle::num::scale::ldexp3;
/// assert_eq!(ldexp3([1.0f32, 2.0, 3.0], -1), [0.5, 1.0, 1.5]);
/// ```
#[inline(always)]
pub fn ldexp3<L: Lane>(v: [L; 3], e: L::Int) -> [L; 3] {
    [v[0].ldexp(e), v[1].ldexp(e), v[2].ldexp(e)]
}
