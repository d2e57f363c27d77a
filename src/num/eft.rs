//! Error-free transformations: the exact rounding error of a sum or product,
//! as a second floating-point number.
//!
//! Without an FMA the product error needs Dekker's TwoProduct over Veltkamp's
//! splitting (T. J. Dekker, *A floating-point technique for extending the
//! available precision*, Numer. Math. 18, 1971). It costs 17 flops instead of
//! FMA's 2, but it is the same 17 flops on every build, which is what
//! bit-identity between the scalar and SIMD kernels needs.

use super::Lane;

/// Knuth's TwoSum: `s = fl(a + b)` and `e` with `s + e = a + b` exactly.
/// No precondition on the magnitudes (Knuth, TAOCP vol. 2, §4.2.2).
///
/// ```
/// use rayoracle::num::eft::two_sum;
/// let (s, e) = two_sum(1.0f32, 1e-10);
/// assert_eq!((s, e), (1.0, 1e-10));
/// ```
#[inline(always)]
pub fn two_sum<L: Lane>(a: L, b: L) -> (L, L) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// Dekker's FastTwoSum: as [`two_sum`] when `|a| ≥ |b|` (or `a` is zero).
///
/// ```
/// use rayoracle::num::eft::fast_two_sum;
/// assert_eq!(fast_two_sum(1.0f32, 2f32.powi(-30)), (1.0, 2f32.powi(-30)));
/// ```
#[inline(always)]
pub fn fast_two_sum<L: Lane>(a: L, b: L) -> (L, L) {
    let s = a + b;
    let e = b - (s - a);
    (s, e)
}

/// Veltkamp's split of a 24-bit significand into two 12-bit halves,
/// `a = hi + lo` exactly, for `|a| < 2^115` (beyond that `4097·a` overflows).
///
/// ```
/// use rayoracle::num::eft::split;
/// let (hi, lo) = split(1.0f32 + f32::EPSILON);
/// assert_eq!(hi + lo, 1.0 + f32::EPSILON);
/// ```
#[inline(always)]
pub fn split<L: Lane>(a: L) -> (L, L) {
    let c = L::splat(4097.0) * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// Dekker's TwoProduct: `p = fl(a·b)` and `e` with `p + e = a·b` exactly,
/// provided no step overflows and `e` is not below the subnormal range.
///
/// Where the split overflows (`|a|` or `|b| ≥ 2^115`) the error term is
/// replaced by `0`, so the pair degrades to the plain product instead of NaN.
///
/// ```
/// use rayoracle::num::eft::two_prod;
/// let x = 1.0f32 + f32::EPSILON;
/// let (p, e) = two_prod(x, x);
/// assert_eq!(p, 1.0 + 2.0 * f32::EPSILON);
/// assert_eq!(e, f32::EPSILON * f32::EPSILON);
/// ```
#[inline(always)]
pub fn two_prod<L: Lane>(a: L, b: L) -> (L, L) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    let e = (((ah * bh - p) + ah * bl) + al * bh) + al * bl;
    (p, e.finite_or_zero())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_prod_is_exact_in_f64() {
        let xs = [
            1.0f32 + f32::EPSILON,
            2.7182817,
            -2.7182817e10,
            1.2345e-10,
            6.5e15,
        ];
        for &a in &xs {
            for &b in &xs {
                let (p, e) = two_prod(a, b);
                assert_eq!(p as f64 + e as f64, a as f64 * b as f64, "{a:e}·{b:e}");
            }
        }
    }

    #[test]
    fn two_sum_is_exact_in_f64() {
        let xs = [
            1.0f32,
            2.7182817e-9,
            -2.7182817e10,
            1.2345e-20,
            6.5e30,
            -1.0,
        ];
        for &a in &xs {
            for &b in &xs {
                let (s, e) = two_sum(a, b);
                assert_eq!(s as f64 + e as f64, a as f64 + b as f64, "{a:e}+{b:e}");
            }
        }
    }

    #[test]
    fn two_prod_degrades_to_the_plain_product_on_split_overflow() {
        let (p, e) = two_prod(3e38f32, 0.5);
        assert_eq!((p, e), (1.5e38, 0.0));
    }
}
