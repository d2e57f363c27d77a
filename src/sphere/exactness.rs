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

/// Whether every value has at most 26 significant bits: the low 27 bits
/// of each significand are 0 (for 0 too). The square of such a value, and
/// its product with an f32 value, are exact where in range.
///
/// ```
/// use rayoracle::sphere::exactness::at_most_26_bits;
/// assert!(at_most_26_bits([3.0, 0.0, -((1u64 << 25 | 1) as f64)]));
/// assert!(!at_most_26_bits([3.0, (1u64 << 26 | 1) as f64, 0.5]));
/// ```
#[inline(always)]
pub fn at_most_26_bits(x: [f64; 3]) -> bool {
    (x[0].to_bits() | x[1].to_bits() | x[2].to_bits()) & ((1 << 27) - 1) == 0
}

/// A bound on the span of a set of f32 values in binary orders of
/// magnitude: with `2ᴸ` the weight of the lowest set bit over the nonzero
/// values and `2ᴴ` a power of two above all of them, every value is an
/// integer multiple of `2ᴸ` below `2ᴴ`, and this is `H − L`. From the
/// bits alone, in a few integer operations a value (flush-to-zero does not
/// touch integer arithmetic): a normal value of biased exponent `e` and
/// significand `m` (with its implicit bit) is `m·2^(e − 150)`, below
/// `2^(e − 126)` and a multiple of `2^(e − 150 + z)`, `z` the trailing
/// zeros of `m`; so `max e − min (e + z) + 24` is the span exactly. A
/// subnormal is `m·2⁻¹⁴⁹` below `2⁻¹²⁶`, and taken as if `e = 0`, which
/// puts its lowest bit one place lower and widens the bound by one. A
/// zero drops out of the minimum. 0 when every value is 0; over 128 for
/// an infinite or NaN value (`e = 255`).
///
/// ```
/// use rayoracle::sphere::exactness::span_bound;
/// // 3 and −0.5: multiples of 2⁻¹ below 2², span 3.
/// assert_eq!(span_bound(&[3.0, 0.0, -0.5]), 3);
/// assert_eq!(span_bound(&[0.1]), 24);
/// // 2112 = 2¹¹ + 2⁶ and 1.5: multiples of 2⁻¹ below 2¹², span 13,
/// // though 2112 spans 6 bits alone and 1.5 lies 10 binades below it.
/// assert_eq!(span_bound(&[2112.0, 1.5]), 13);
/// assert_eq!(span_bound(&[0.0, -0.0]), 0);
/// assert!(span_bound(&[1.0, f32::INFINITY]) > 128);
/// assert!(span_bound(&[f32::NAN, 0.0]) > 128);
/// // 2⁻¹⁴⁹ to 1: span 150, one more for the subnormal.
/// assert_eq!(span_bound(&[f32::from_bits(1), 1.0]), 151);
/// ```
#[inline(always)]
pub fn span_bound(x: &[f32]) -> u32 {
    let (mut high, mut low) = (0u32, u32::MAX);
    for v in x {
        let bits = v.to_bits() & 0x7fff_ffff;
        let e = bits >> 23;
        high = high.max(e);
        // e + z, or u32::MAX for a zero, without a branch.
        let key = (e + (bits | 1 << 23).trailing_zeros()) | u32::from(bits == 0).wrapping_neg();
        low = low.min(key);
    }
    if low == u32::MAX {
        0
    } else if high == 0xff {
        0x200
    } else {
        high + 24 - low
    }
}

/// Whether `x + y` rounds to itself (false for a non-finite operand).
#[inline(always)]
pub fn add_exact(x: f64, y: f64) -> bool {
    two_sum(x, y).1 == 0.0
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::xorshift;

    /// [`span_bound`] is the true span, on sets of normal values with 1 to
    /// 24 bits, zeros and both signs, many spanning more than 24 binades.
    #[test]
    fn span_bound_covers_the_span() {
        let mut next = xorshift(0x9e37_79b9_7f4a_7c15);
        let mut wide = 0;
        for _ in 0..20_000 {
            let n = 1 + next() % 7;
            let v: Vec<f32> = (0..n)
                .map(|_| {
                    let r = next();
                    let bits = (r % 24) as u32;
                    let m = (r >> 8) as u32 & ((1 << bits) - 1) | 1 << bits >> 1;
                    let e = ((r >> 40) % 40) as i32 - 20;
                    let x = m as f32 * 2f32.powi(e);
                    if r >> 63 == 1 {
                        -x
                    } else if r.is_multiple_of(11) {
                        0.0
                    } else {
                        x
                    }
                })
                .collect();
            // The true span, from the f64 values' exponents.
            let nz: Vec<f64> = v
                .iter()
                .filter(|x| **x != 0.0)
                .map(|&x| f64::from(x.abs()))
                .collect();
            let Some(high) = nz.iter().map(|x| x.log2().floor() as i32 + 1).max() else {
                assert_eq!(span_bound(&v), 0);
                continue;
            };
            let low = nz
                .iter()
                .map(|x| {
                    (x.to_bits() & ((1 << 52) - 1) | 1 << 52).trailing_zeros() as i32
                        + x.log2().floor() as i32
                        - 52
                })
                .min()
                .unwrap();
            let (span, bound) = ((high - low) as u32, span_bound(&v));
            // No subnormal here: the bound is the span itself.
            assert_eq!(bound, span, "{v:?}");
            wide += usize::from(span > 24);
        }
        assert!(wide > 1000, "{wide}");
    }

    /// [`at_most_26_bits`] is [`sig_bits`] at most 26 in every value, on
    /// triples of values with 1 to 53 bits at any exponent, zeros and both
    /// signs among them; and the products the tracked stage takes as exact
    /// where it holds (`fᵢdᵢ` with an f32 `dᵢ`, `fᵢ²`) are.
    #[test]
    fn at_most_26_bits_counts_every_value() {
        let mut next = xorshift(0x2545_f491_4f6c_dd1d);
        let mut value = |bits: u32| {
            let r = next();
            let m = if bits == 0 {
                0
            } else {
                (r >> 11) & ((1u64 << (bits - 1)) - 1) | 1 << (bits - 1) | 1
            };
            let x = m as f64 * 2f64.powi((r % 80) as i32 - 40 - bits as i32);
            if r >> 63 == 1 { -x } else { x }
        };
        let (mut held, mut failed) = (0, 0);
        for i in 0..20_000u32 {
            // Mostly near the limit, 24 to 28 bits; a zero now and then.
            let bits = |k: u32| match (i >> (4 * k)) % 8 {
                0 => 0,
                1 => 1 + (i + k) % 53,
                n => 22 + n.min(6),
            };
            let f = [value(bits(0)), value(bits(1)), value(bits(2))];
            let want = f.iter().all(|&x| sig_bits(x) <= 26);
            assert_eq!(at_most_26_bits(f), want, "{f:?}");
            if want {
                held += 1;
                let d = (0.1f32 + i as f32) as f64;
                for x in f {
                    assert_eq!(two_prod(x, d).1, 0.0, "{x} · {d}");
                    assert_eq!(two_prod(x, x).1, 0.0, "{x}²");
                }
            } else {
                failed += 1;
            }
        }
        assert!(held > 1000 && failed > 1000, "{held} {failed}");
    }

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
