//! f64 arithmetic that proves itself exact: every operation also checks,
//! with an error-free transformation, that it did not round. When none
//! did, the computed values are the exact ones, so their signs and zeros
//! are exact: the second stage of the kernels, which settles the exact
//! zeros of small-integer and dyadic data (tangents, in-plane rays, α = 0,
//! lines on a surface) without big integers.
//!
//! * a sum rounds exactly when Knuth's TwoSum error `(a − (s − b')) + (b −
//!   b')`, `b' = s − a`, is nonzero;
//! * a product rounds exactly when `fma(a, b, −p)` is nonzero (the fused
//!   multiply-add computes `ab − p` exactly here, since `ab − p` is
//!   representable whenever `p` did not overflow; an overflow gives NaN).
//!
//! ```
//! use rayoracle::num::tracked::Tracked;
//! let mut x = Tracked::new();
//! let s = x.add(1.0, 2.0f64.powi(-52));
//! assert!(x.exact() && s == 1.0 + f64::EPSILON);
//! x.add(1.0, 2.0f64.powi(-60));
//! assert!(!x.exact());
//! ```

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
    /// ```
    #[inline(always)]
    pub fn mul(&mut self, a: f64, b: f64) -> f64 {
        let p = a * b;
        self.exact &= a.mul_add(b, -p) == 0.0;
        p
    }
    /// `Σ xᵢyᵢ` over three pairs, noting whether it rounded.
    #[inline(always)]
    pub fn dot(&mut self, x: [f64; 3], y: [f64; 3]) -> f64 {
        let p = [0, 1, 2].map(|i| self.mul(x[i], y[i]));
        let s = self.add(p[0], p[1]);
        self.add(s, p[2])
    }
}
