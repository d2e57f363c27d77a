//! The 256-bit tier of dyadic mantissas: `bnum`'s `I256` kept to
//! `|m| < 2^255`, so that negation never overflows and the tier holds the
//! same values for either sign. Every operation is exact or returns `None`.

use bnum::cast::As;
use dashu_int::{IBig, Sign, UBig};

/// A signed integer with `|m| < 2^255`.
pub(super) type Wide = bnum::types::I256;

/// The largest length of a magnitude.
pub(super) const BITS: u32 = 255;

/// `m`, if `|m| < 2^255` (that is, unless it is `I256::MIN`).
fn fits(m: Wide) -> Option<Wide> {
    (m != Wide::MIN).then_some(m)
}

pub(super) fn from_i128(m: i128) -> Wide {
    m.as_()
}

/// The value, if an `i128` holds it and its negation.
pub(super) fn to_i128(m: Wide) -> Option<i128> {
    // The truncation, if it converts back to `m` (a comparison of bytes,
    // cheaper than counting the sign bits).
    let s: i128 = m.as_();
    (s != i128::MIN && from_i128(s) == m).then_some(s)
}

/// The value of `m`, if `|m| < 2^255`.
pub(super) fn from_ibig(m: &IBig) -> Option<Wide> {
    let (sign, words) = m.as_sign_words();
    let mut bytes = [0; 32];
    let le = words.iter().flat_map(|w| w.to_le_bytes());
    for (i, b) in le.enumerate() {
        match bytes.get_mut(i) {
            Some(slot) => *slot = b,
            None if b != 0 => return None,
            None => {}
        }
    }
    let m = Wide::from_le_bytes(bytes);
    // With the top bit set, the magnitude is 2^255 or more.
    if m.is_negative() {
        return None;
    }
    Some(if sign == Sign::Negative { -m } else { m })
}

pub(super) fn to_ibig(m: Wide) -> IBig {
    let sign = if m.is_negative() {
        Sign::Negative
    } else {
        Sign::Positive
    };
    IBig::from_parts(sign, UBig::from_le_bytes(&m.unsigned_abs().to_le_bytes()))
}

/// −1, 0 or 1.
pub(super) fn signum(m: Wide) -> i32 {
    i32::from(m.is_positive()) - i32::from(m.is_negative())
}

/// The length of the magnitude in bits (0 for zero).
pub(super) fn len(m: Wide) -> u32 {
    if !m.is_negative() {
        return Wide::BITS - m.leading_zeros();
    }
    // The leading ones end where `!m = −m − 1` begins, one bit short of
    // `−m` when that is a power of two.
    let ones = m.leading_ones();
    Wide::BITS - ones + u32::from(ones + m.trailing_zeros() == Wide::BITS)
}

/// `m · 2^s`, if it fits: if the `s + 1` leading bits all equal the sign
/// bit, and the result is not `I256::MIN`.
pub(super) fn shl(m: Wide, s: u32) -> Option<Wide> {
    if m.is_zero() {
        return Some(m);
    }
    let sign_bits = if m.is_negative() {
        m.leading_ones()
    } else {
        m.leading_zeros()
    };
    if s >= sign_bits {
        return None;
    }
    m.checked_shl(s).and_then(fits)
}

/// `a + b`, if it fits.
pub(super) fn add(a: Wide, b: Wide) -> Option<Wide> {
    a.checked_add(b).and_then(fits)
}

/// `a · b`, if the lengths of the factors add up to 255 bits or fewer
/// (and so the product fits).
pub(super) fn mul(a: Wide, b: Wide) -> Option<Wide> {
    (len(a) + len(b) <= BITS).then(|| a.wrapping_mul(b))
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_int::ops::BitTest;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    /// A value of 0 to 255 bits, 255 bits long one time in three.
    fn random(r: &mut SmallRng) -> IBig {
        let bits = if r.random_bool(0.3) {
            255
        } else {
            r.random_range(0..=255usize)
        };
        let m = IBig::from(r.random::<u128>()) << 128 | IBig::from(r.random::<u128>());
        let m = (m >> (256 - bits)) | (IBig::from(bits > 0) << bits.saturating_sub(1));
        if r.random_bool(0.5) { -m } else { m }
    }

    /// A magnitude of `2^255` or more is refused, whatever its bytes past
    /// the 32nd: here each of them nonzero, or the least beyond the tier.
    #[test]
    fn from_ibig_refuses_every_value_past_the_tier() {
        let one = || IBig::from(1u8);
        let past = [
            IBig::from(0x0101_0101_0101_0101u64) << 256,
            (one() << 256) + one(),
            one() << 255,
        ];
        for m in past {
            assert_eq!(from_ibig(&m), None, "{m}");
            assert_eq!(from_ibig(&-m.clone()), None, "-{m}");
        }
        let top = (one() << 255) - one();
        assert!(from_ibig(&top).is_some() && from_ibig(&-top).is_some());
    }

    /// The conversions round-trip every value of the tier and refuse every
    /// other; sums, products and shifts agree with big integers or decline
    /// exactly when the exact result has 256 bits or more (products: when
    /// the factors' lengths add up to more than 255).
    #[test]
    fn operations_match_big_integers() {
        let mut r = SmallRng::seed_from_u64(256);
        let fits = |m: &IBig| m.bit_len() <= 255;
        let mut declined = [0; 3];
        for _ in 0..50_000 {
            let (x, y) = (random(&mut r), random(&mut r));
            let a = from_ibig(&x).expect("255 bits fit");
            let b = from_ibig(&y).expect("255 bits fit");
            assert_eq!(to_ibig(a), x);
            assert_eq!(len(a) as usize, x.bit_len());
            let sign = match x.sign() {
                _ if x.is_zero() => 0,
                Sign::Negative => -1,
                Sign::Positive => 1,
            };
            assert_eq!(signum(a), sign);
            assert_eq!(from_ibig(&(&x << 1)).is_some(), x.bit_len() < 255);
            assert_eq!(
                to_i128(a),
                i128::try_from(&x).ok().filter(|m| *m != i128::MIN)
            );
            let s = r.random_range(0..256u32);
            let shifted = &x << s as usize;
            let checked = [
                (add(a, b), &x + &y, !fits(&(&x + &y))),
                (mul(a, b), &x * &y, x.bit_len() + y.bit_len() > 255),
                (shl(a, s), shifted.clone(), !fits(&shifted)),
            ];
            for (i, (got, want, declines)) in checked.into_iter().enumerate() {
                match got {
                    Some(m) => assert_eq!(to_ibig(m), want),
                    None => declined[i] += 1,
                }
                assert_eq!(got.is_none(), declines, "{x} {y} {s}");
            }
            if signum(a) != 0 {
                assert_eq!(shl(a, u32::MAX), None);
            }
        }
        assert!(declined.iter().all(|&n| n > 1_000), "{declined:?}");
    }

    /// The ends of the tier: ±(2^255 − 1) fit, −2^255 (which `I256` holds)
    /// does not, whether converted, summed or multiplied.
    #[test]
    fn the_tier_is_symmetric() {
        let top: IBig = (IBig::ONE << 255) - 1;
        for m in [top.clone(), -&top] {
            assert_eq!(to_ibig(from_ibig(&m).unwrap()), m);
        }
        assert_eq!(from_ibig(&(IBig::ONE << 255)), None);
        assert_eq!(from_ibig(&-(IBig::ONE << 255)), None);
        assert_eq!(from_ibig(&(IBig::ONE << 300)), None);
        let max = from_ibig(&top).unwrap();
        let one = from_i128(1);
        assert_eq!(add(-max, -one), None);
        assert_eq!(add(max, one), None);
        assert_eq!(add(-max, one).map(to_ibig), Some(IBig::ONE - &top));
        let half = from_ibig(&-(IBig::ONE << 254)).unwrap();
        assert_eq!(mul(half, from_i128(2)), None);
        assert_eq!(mul(half, from_i128(-2)), None);
        assert_eq!(shl(half, 1), None);
        assert_eq!(to_i128(from_i128(i128::MIN)), None);
        assert_eq!(to_i128(from_i128(-i128::MAX)), Some(-i128::MAX));
        assert_eq!(shl(from_i128(0), u32::MAX), Some(from_i128(0)));
    }
}
