//! Double-word ("float-float") numbers: an unevaluated sum `hi + lo` of two
//! lanes with `hi = fl(hi + lo)`, giving about 48 bits of significand.
//!
//! The algorithms are those of Joldes, Muller & Popescu (ACM TOMS 44(2), 2017)
//! with the FMA-based products replaced by Dekker's [`two_prod`], so they run
//! unchanged on builds without FMA:
//!
//! | operation  | algorithm                                   | relative error bound |
//! |------------|---------------------------------------------|----------------------|
//! | `Ff + Ff`  | AccurateDWPlusDW (JMP 2017)                 | 3u² + 13u³           |
//! | `Ff × f32` | DWTimesFP1 (JMP 2017)                       | 1.5u² + 4u³          |
//! | `Ff × Ff`  | Dekker's `mul2` (1971), JMP's DWTimesDW1 shape | ≈ 7u²             |
//! | `Ff ÷ Ff`  | DWDivDW1 (JMP 2017)                         | 15u² + 56u³          |
//! | `√Ff`      | one Karp–Markstein step, as QD's `sqrt`     | ≈ 4u²                |
//!
//! with `u = 2⁻²⁴`. Rounding an `Ff` result to one lane is just taking `hi`,
//! which is the nearest float to `hi + lo`; a kernel whose intermediate values
//! are all double-word therefore returns roots that are correctly rounded
//! except within about `2⁻²⁰` ulp of a rounding boundary, or where the root is
//! ill-conditioned.

use super::Lane;
use super::eft::{fast_two_sum, two_prod, two_sum};
use core::ops::{Add, Div, Mul, Neg, Sub};

/// A double-word number `hi + lo`.
///
/// ```
/// use rayoracle::num::Ff;
/// let third = Ff::from(1.0f32) / Ff::from(3.0f32);
/// // 1/3 to about 48 bits: hi is the correctly rounded f32.
/// assert_eq!(third.hi, 1.0f32 / 3.0);
/// assert!(((third.hi as f64 + third.lo as f64) - 1.0 / 3.0).abs() < 1e-14);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ff<L> {
    /// The leading part, `fl(hi + lo)`.
    pub hi: L,
    /// The trailing part, `|lo| ≤ ulp(hi)/2`.
    pub lo: L,
}

impl<L: Lane> From<L> for Ff<L> {
    #[inline(always)]
    fn from(hi: L) -> Self {
        Ff {
            hi,
            lo: L::splat(0.0),
        }
    }
}

impl<L: Lane> Ff<L> {
    /// The exact sum of two lanes (Knuth's TwoSum).
    ///
    /// ```
    /// use rayoracle::num::Ff;
    /// let d = Ff::sum(1.0f32, -1e-9);
    /// assert_eq!(d.hi as f64 + d.lo as f64, 1.0 - 1e-9f32 as f64);
    /// ```
    #[inline(always)]
    pub fn sum(a: L, b: L) -> Self {
        let (hi, lo) = two_sum(a, b);
        Ff { hi, lo }
    }

    /// The exact product of two lanes (Dekker's TwoProduct).
    ///
    /// ```
    /// use rayoracle::num::Ff;
    /// let p = Ff::product(3.0f32 + f32::EPSILON, 3.0);
    /// assert_eq!(p.hi as f64 + p.lo as f64, (3.0f32 + f32::EPSILON) as f64 * 3.0);
    /// ```
    #[inline(always)]
    pub fn product(a: L, b: L) -> Self {
        let (hi, lo) = two_prod(a, b);
        Ff { hi, lo }
    }

    /// `x²`, exact (a [`Ff::product`] of `x` with itself).
    ///
    /// ```
    /// use rayoracle::num::Ff;
    /// assert_eq!(Ff::square(3.0f32).hi, 9.0);
    /// ```
    #[inline(always)]
    pub fn square(a: L) -> Self {
        Self::product(a, a)
    }

    /// `self × x` for a single lane `x` (DWTimesFP1).
    ///
    /// ```
    /// use rayoracle::num::Ff;
    /// assert_eq!(Ff::from(1.5f32).scale(2.0).hi, 3.0);
    /// ```
    #[inline(always)]
    pub fn scale(self, x: L) -> Self {
        let (ch, cl1) = two_prod(self.hi, x);
        let cl2 = self.lo * x;
        let (th, tl1) = fast_two_sum(ch, cl2);
        let tl2 = tl1 + cl1;
        let (hi, lo) = fast_two_sum(th, tl2);
        Ff { hi, lo }
    }

    /// `√self`, one Karp–Markstein correction of the `f32` square root:
    /// `s = √hi`, `r = (self − s²)/(2s)`, result `s + r`. A zero or negative
    /// `hi` gives `√hi` (the correction, 0/0, is dropped).
    ///
    /// ```
    /// use rayoracle::num::Ff;
    /// let r = Ff::from(2.0f32).sqrt();
    /// assert!(((r.hi as f64 + r.lo as f64) - 2f64.sqrt()).abs() < 1e-14);
    /// ```
    #[inline(always)]
    pub fn sqrt(self) -> Self {
        let s = self.hi.sqrt();
        let (p, e) = two_prod(s, s);
        let r = (((self.hi - p) - e) + self.lo) / (s + s);
        let (hi, lo) = fast_two_sum(s, r.finite_or_zero());
        Ff { hi, lo }
    }

    /// `self` with the sign of `s` applied: `−self` where `s` has its sign
    /// bit set (including `−0`), `self` otherwise. Exact.
    ///
    /// ```
    /// use rayoracle::num::Ff;
    /// assert_eq!(Ff::from(2.0f32).with_sign_of(-0.0).hi, -2.0);
    /// ```
    #[inline(always)]
    pub fn with_sign_of(self, s: L) -> Self {
        let sign = L::splat(1.0).copysign(s);
        Ff {
            hi: self.hi * sign,
            lo: self.lo * sign,
        }
    }

    /// The value rounded to one lane: `hi`.
    ///
    /// ```
    /// use rayoracle::num::Ff;
    /// assert_eq!(Ff::sum(1.0f32, 1e-9).round(), 1.0);
    /// ```
    #[inline(always)]
    pub fn round(self) -> L {
        self.hi
    }
}

impl<L: Lane> Neg for Ff<L> {
    type Output = Self;
    #[inline(always)]
    fn neg(self) -> Self {
        Ff {
            hi: -self.hi,
            lo: -self.lo,
        }
    }
}

impl<L: Lane> Add for Ff<L> {
    type Output = Self;
    /// AccurateDWPlusDW (JMP 2017).
    #[inline(always)]
    fn add(self, y: Self) -> Self {
        let (sh, sl) = two_sum(self.hi, y.hi);
        let (th, tl) = two_sum(self.lo, y.lo);
        let c = sl + th;
        let (vh, vl) = fast_two_sum(sh, c);
        let w = tl + vl;
        let (hi, lo) = fast_two_sum(vh, w);
        Ff { hi, lo }
    }
}

impl<L: Lane> Sub for Ff<L> {
    type Output = Self;
    #[inline(always)]
    fn sub(self, y: Self) -> Self {
        self + (-y)
    }
}

impl<L: Lane> Mul for Ff<L> {
    type Output = Self;
    /// Dekker's `mul2`: the exact product of the leading parts plus the cross
    /// terms, renormalised.
    #[inline(always)]
    fn mul(self, y: Self) -> Self {
        let (ch, cl1) = two_prod(self.hi, y.hi);
        let tl = self.hi * y.lo + self.lo * y.hi;
        let cl2 = cl1 + tl;
        let (hi, lo) = fast_two_sum(ch, cl2);
        Ff { hi, lo }
    }
}

impl<L: Lane> Div for Ff<L> {
    type Output = Self;
    /// DWDivDW1 (JMP 2017): a quotient of the leading parts and one
    /// correction. A non-finite first quotient (division by zero, overflow)
    /// is returned as it is, with a zero trailing part.
    #[inline(always)]
    fn div(self, y: Self) -> Self {
        let th = self.hi / y.hi;
        let r = y.scale(th);
        let pih = self.hi - r.hi;
        let dl = self.lo - r.lo;
        let d = pih + dl;
        let tl = (d / y.hi).finite_or_zero();
        let (hi, lo) = fast_two_sum(th, tl);
        // fast_two_sum(inf, x) is (inf, NaN); keep the quotient usable.
        Ff {
            hi,
            lo: lo.finite_or_zero(),
        }
    }
}

/// `Σ aᵢ·bᵢ` of two 3-vectors of lanes, each product exact and the sum in
/// double-word arithmetic: as accurate as the dot product evaluated in twice
/// the working precision and then rounded (Ogita, Rump & Oishi, *Accurate
/// sum and dot product*, SIAM J. Sci. Comput. 26(6), 2005, Dot2).
///
/// ```
/// use rayoracle::num::ff::dot3;
/// let d = dot3([1e8f32, 1.0, -1e8], [1.0f32, 1.0, 1.0]);
/// assert_eq!(d.hi, 1.0);
/// ```
#[inline(always)]
pub fn dot3<L: Lane>(a: [L; 3], b: [L; 3]) -> Ff<L> {
    Ff::product(a[0], b[0]) + Ff::product(a[1], b[1]) + Ff::product(a[2], b[2])
}

/// `Σ aᵢ·bᵢ` where `a` is a 3-vector of double-words and `b` of lanes.
///
/// ```
/// use rayoracle::num::{Ff, ff::dot3_ff};
/// let a = [Ff::sum(1.0f32, 1e-9), Ff::from(0.0), Ff::from(0.0)];
/// assert_eq!(dot3_ff(a, [2.0f32, 0.0, 0.0]).hi, 2.0);
/// ```
#[inline(always)]
pub fn dot3_ff<L: Lane>(a: [Ff<L>; 3], b: [L; 3]) -> Ff<L> {
    a[0].scale(b[0]) + a[1].scale(b[1]) + a[2].scale(b[2])
}

/// `Σ aᵢ²` of a 3-vector of double-words.
///
/// ```
/// use rayoracle::num::{Ff, ff::norm2_ff};
/// let a = [Ff::from(3.0f32), Ff::from(4.0), Ff::from(0.0)];
/// assert_eq!(norm2_ff(a).hi, 25.0);
/// ```
#[inline(always)]
pub fn norm2_ff<L: Lane>(a: [Ff<L>; 3]) -> Ff<L> {
    a[0] * a[0] + a[1] * a[1] + a[2] * a[2]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn val(x: Ff<f32>) -> f64 {
        x.hi as f64 + x.lo as f64
    }

    #[test]
    fn operations_are_accurate_to_about_2_pow_minus_44() {
        let xs = [
            Ff::sum(1.0f32, 1e-9),
            Ff::sum(-2.7182817f32, 8.742278e-8),
            Ff::sum(12345.678f32, -3.3e-5),
            Ff::sum(7.0e-12f32, 1.0e-20),
        ];
        let tol = 2f64.powi(-44);
        for &a in &xs {
            for &b in &xs {
                let (va, vb) = (val(a), val(b));
                let rel = |got: f64, want: f64| ((got - want) / want).abs();
                assert!(rel(val(a + b), va + vb) < tol || (va + vb).abs() < 1e-30);
                assert!(rel(val(a * b), va * vb) < tol, "{va}*{vb}");
                assert!(rel(val(a / b), va / vb) < tol, "{va}/{vb}");
            }
            if val(a) > 0.0 {
                assert!(((val(a.sqrt()) - val(a).sqrt()) / val(a).sqrt()).abs() < tol);
            }
        }
    }

    #[test]
    fn division_by_zero_and_sqrt_of_zero_stay_finite_where_they_should() {
        let z = Ff::from(0.0f32);
        assert_eq!(z.sqrt().hi, 0.0);
        let q = Ff::from(1.0f32) / z;
        assert_eq!(q.hi, f32::INFINITY);
        assert_eq!(q.lo, 0.0);
    }
}
