//! Cheap proofs that an f64 operation did not round, for the sphere's
//! tracked stage ([`super::stages::tracked`]), which works on polynomials
//! in f32 data.
//!
//! * A product `xy` of two finite f64 values with `s(x)` and `s(y)`
//!   significant bits is exact when `s(x) + s(y) ≤ 53` and the product
//!   neither overflows nor leaves the normal range: the exact product is an
//!   integer of at most `s(x) + s(y)` bits times a power of two.
//!   [`mul_exact`] reads `s` from the bits (53 minus the trailing zeros of
//!   the 53-bit significand) and falls back on Dekker's TwoProduct
//!   ([`two_prod`]) only where that count is too large: the product of two
//!   f32 values, 24 bits each, never needs it. The sphere's products of f32
//!   data are multiples of `2⁻⁵⁹⁶` and below `2⁵²⁰`, so in range.
//! * A sum is exact where Knuth's TwoSum error ([`two_sum`]) is 0; an
//!   infinite or NaN operand makes the error NaN, so the proof fails.
//!
//! ```
//! use rayoracle::sphere::exactness::{mul_exact, sig_bits};
//! assert_eq!(sig_bits(3.0), 2);
//! assert_eq!(sig_bits(0.1f32 as f64), 24);
//! assert!(mul_exact(0.1f32 as f64, 0.1f32 as f64));
//! assert!(!mul_exact(0.1, 0.1));
//! // 53 bits times 2 bits, but the product is exact: TwoProduct says so.
//! assert!(mul_exact(1.0 + f64::EPSILON, 4.0));
//! ```

use crate::num::dd::{two_prod, two_sum};

/// The significant bits of a finite nonzero f64 from its bits (1 for 0).
#[inline(always)]
pub fn sig_bits(x: f64) -> u32 {
    53 - ((x.to_bits() | 1 << 52).trailing_zeros())
}

/// Whether `x·y` rounds to itself, by the bit count, else by TwoProduct;
/// for the sphere's data, whose products stay in range (see the
/// [module](self)).
#[inline(always)]
pub fn mul_exact(x: f64, y: f64) -> bool {
    sig_bits(x) + sig_bits(y) <= 53 || two_prod(x, y).1 == 0.0
}

/// Whether `x + y` rounds to itself (false for a non-finite operand).
#[inline(always)]
pub fn add_exact(x: f64, y: f64) -> bool {
    two_sum(x, y).1 == 0.0
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The bit count against the product's own rounding, on products of
    /// values with 1 to 53 bits: it never calls a rounded product exact.
    #[test]
    fn bit_count_is_sufficient() {
        let mut seen = (0, 0);
        for i in 1..54u32 {
            for j in 1..54u32 {
                let x = ((1u64 << (i - 1)) | 1) as f64;
                let y = ((1u64 << (j - 1)) | 1) as f64;
                let exact = two_prod(x, y).1 == 0.0;
                let by_bits = sig_bits(x) + sig_bits(y) <= 53;
                assert!(!by_bits || exact, "{i} {j}");
                assert_eq!(mul_exact(x, y), exact, "{i} {j}");
                if by_bits {
                    seen.0 += 1;
                } else {
                    seen.1 += 1;
                }
            }
        }
        assert!(seen.0 > 0 && seen.1 > 0);
        assert_eq!(
            (sig_bits(0.0), sig_bits(-0.5), sig_bits(f64::MAX)),
            (1, 1, 53)
        );
        assert!(!add_exact(f64::INFINITY, 1.0) && !add_exact(f64::NAN, 0.0));
        assert!(add_exact(1.0, 2.0) && !add_exact(1.0, 1e-30));
    }
}
