//! Exact power-of-two prescaling, so that `f32` arithmetic on a vector
//! neither overflows nor sinks into the subnormal range (the render normals
//! use it before normalising).
//!
//! Scaling by `2^k` is exact (barring underflow of components that are
//! negligible anyway next to the largest one), and leaves a direction
//! unchanged.
//!
//! The scale is read off the largest magnitude's exponent bits and applied
//! as one multiplication by a power of two; the only integer work is one
//! subtraction, which matters for the SIMD path on baseline x86-64 (SSE2
//! has no packed 32-bit min/max).

use super::Lane;

/// The power of two that brings a set of values into range.
///
/// ```
/// use rayoracle::num::scale::Scale;
/// let s = Scale::of_max(&[3.0f32, -1e3, 0.5]);
/// assert_eq!(s.k, 9);
/// assert_eq!(s.apply(-1e3), -1e3 / 512.0);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Scale<L: Lane> {
    /// `2^−k`: multiplying by it brings the largest magnitude into `[1, 2)`
    /// (into `[2⁻²³, 1)` if it is subnormal, `[2, 4)` if it is `≥ 2¹²⁷`).
    pub down: L,
    /// `k`.
    pub k: L::Int,
}

impl<L: Lane> Scale<L> {
    /// The scale of `max |xᵢ|`.
    ///
    /// ```
    /// use rayoracle::num::scale::Scale;
    /// assert_eq!(Scale::of_max(&[0.0f32, 0.0]).k, -126);
    /// ```
    #[inline(always)]
    pub fn of_max(xs: &[L]) -> Self {
        let mut m = xs[0].abs();
        for &x in &xs[1..] {
            m = x.abs().max(m);
        }
        let p = m.pow2_floor();
        Scale {
            down: p.recip_pow2(),
            k: p.pow2_exponent(),
        }
    }

    /// `x · 2^−k`, exact.
    ///
    /// ```
    /// use rayoracle::num::scale::Scale;
    /// assert_eq!(Scale::of_max(&[8.0f32]).apply(12.0), 1.5);
    /// ```
    #[inline(always)]
    pub fn apply(&self, x: L) -> L {
        x * self.down
    }

    /// `v · 2^−k`, component-wise.
    ///
    /// ```
    /// use rayoracle::num::scale::Scale;
    /// assert_eq!(Scale::of_max(&[4.0f32]).apply3([4.0, 2.0, 1.0]), [1.0, 0.5, 0.25]);
    /// ```
    #[inline(always)]
    pub fn apply3(&self, v: [L; 3]) -> [L; 3] {
        [v[0] * self.down, v[1] * self.down, v[2] * self.down]
    }
}

/// The scale of a vector and the vector scaled by it.
///
/// ```
/// use rayoracle::num::scale::normalized3;
/// let (v, s) = normalized3([0.0f32, 6.0, -3.0]);
/// assert_eq!((v, s.k), ([0.0, 1.5, -0.75], 2));
/// ```
#[inline(always)]
pub fn normalized3<L: Lane>(v: [L; 3]) -> ([L; 3], Scale<L>) {
    let s = Scale::of_max(&v);
    (s.apply3(v), s)
}
