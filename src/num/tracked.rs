//! f64 arithmetic that proves itself exact: every operation also checks,
//! with an error-free transformation, that it did not round. When none
//! did, the computed values are the exact ones, so their signs and zeros
//! are exact: the second stage of the kernels, which settles the exact
//! zeros of small-integer and dyadic data (tangents, in-plane rays, α = 0,
//! lines on a surface) without big integers.
//!
//! * a sum rounds exactly when Knuth's TwoSum error `(a − (s − b')) + (b −
//!   b')`, `b' = s − a`, is nonzero;
//! * a product rounds exactly when Dekker's TwoProduct error
//!   ([`two_prod`](super::dd::two_prod)) is nonzero, or the product is below `2⁻⁹⁰⁰` without a
//!   zero factor. Above that, every partial product of Dekker's algorithm
//!   is a multiple of `ulp(a)·ulp(b) ≥ 2⁻¹⁰⁶|ab| > 2⁻¹⁰⁷⁴`, so
//!   representable, and the error is exact; an overflow (or a split that
//!   overflows, `|a| ≥ 2⁹⁹⁵`) gives a non-finite error. The kernels' exact
//!   products of f32 data are at least `2⁻⁸⁹⁴`. TwoProduct is plain
//!   arithmetic, where `mul_add` calls libm's `fma` on builds without the
//!   `fma` target feature: several times slower.
//!
//! ```
//! use rayoracle::num::tracked::Tracked;
//! let mut x = Tracked::new();
//! let s = x.add(1.0, 2.0f64.powi(-52));
//! assert!(x.exact() && s == 1.0 + f64::EPSILON);
//! x.add(1.0, 2.0f64.powi(-60));
//! assert!(!x.exact());
//! ```

use super::dd::{Dekker, Product};

/// The least product magnitude [`Tracked::mul`] vouches for, `2⁻⁹⁰⁰`.
const TINY: f64 = f64::from_bits((1023 - 900) << 52);

/// Whether every operation so far was exact.
#[derive(Clone, Copy, Debug)]
pub struct Tracked {
    exact: bool,
}

impl Default for Tracked {
    fn default() -> Self {
        Tracked::new()
    }
}

impl Tracked {
    /// Nothing computed yet: exact.
    pub fn new() -> Tracked {
        Tracked { exact: true }
    }
    /// Whether every operation so far was exact.
    pub fn exact(&self) -> bool {
        self.exact
    }
    /// `a + b`, noting whether it rounded.
    #[inline(always)]
    pub fn add(&mut self, a: f64, b: f64) -> f64 {
        let s = a + b;
        let bb = s - a;
        let err = (a - (s - bb)) + (b - bb);
        self.exact &= err == 0.0;
        s
    }
    /// `a − b`, noting whether it rounded.
    #[inline(always)]
    pub fn sub(&mut self, a: f64, b: f64) -> f64 {
        self.add(a, -b)
    }
    /// `a · b`, noting whether it rounded (or overflowed).
    ///
    /// ```
    /// use rayoracle::num::tracked::Tracked;
    /// let mut x = Tracked::new();
    /// x.mul(3.0, 1.0 / 3.0);
    /// assert!(!x.exact());
    /// let mut y = Tracked::new();
    /// assert_eq!(y.mul(1e300, 1e300), f64::INFINITY);
    /// assert!(!y.exact());
    /// // Underflow rounds.
    /// let mut z = Tracked::new();
    /// z.mul(1e-200, 1e-200);
    /// assert!(!z.exact());
    /// let mut w = Tracked::new();
    /// assert_eq!(w.mul(0.0, 1e-300), 0.0);
    /// assert!(w.exact());
    /// ```
    #[inline(always)]
    pub fn mul(&mut self, a: f64, b: f64) -> f64 {
        self.mul_by::<Dekker>(a, b)
    }
    /// [`Tracked::mul`] with the product's error found by `P`.
    ///
    /// ```
    /// use rayoracle::num::{dd::Fused, tracked::Tracked};
    /// let mut x = Tracked::new();
    /// assert_eq!(x.mul_by::<Fused>(3.0, 0.5), 1.5);
    /// assert!(x.exact());
    /// x.mul_by::<Fused>(3.0, 0.1);
    /// assert!(!x.exact());
    /// ```
    #[inline(always)]
    pub fn mul_by<P: Product>(&mut self, a: f64, b: f64) -> f64 {
        let (p, e) = P::two_prod(a, b);
        self.exact &= e == 0.0 && (p.abs() >= TINY || a == 0.0 || b == 0.0);
        p
    }
    /// `Σ xᵢyᵢ` over three pairs, noting whether it rounded.
    #[inline(always)]
    pub fn dot(&mut self, x: [f64; 3], y: [f64; 3]) -> f64 {
        let p = [
            self.mul(x[0], y[0]),
            self.mul(x[1], y[1]),
            self.mul(x[2], y[2]),
        ];
        let s = self.add(p[0], p[1]);
        self.add(s, p[2])
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn tiny_is_two_to_the_minus_900() {
        assert_eq!(super::TINY, 2f64.powi(-900));
    }
}
