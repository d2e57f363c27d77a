//! 256-bit integers on the stack, in sign and magnitude: the mantissas of
//! dyadics too long for an `i128` and short enough to spare a heap
//! allocation (products of two ~100-bit values, sums across ~200 bits of
//! exponent). Every operation is exact or returns `None`.

use core::cmp::Ordering;
use dashu_int::{IBig, Sign, UBig, Word};

/// A signed integer with `|m| < 2^255`; zero is never negative.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) struct Wide {
    neg: bool,
    hi: u128,
    lo: u128,
}

impl Wide {
    /// The largest length of a magnitude.
    pub(super) const BITS: u32 = 255;

    fn new(neg: bool, hi: u128, lo: u128) -> Option<Wide> {
        let zero = hi == 0 && lo == 0;
        (hi >> 127 == 0).then_some(Wide {
            neg: neg && !zero,
            hi,
            lo,
        })
    }

    pub(super) fn from_i128(m: i128) -> Wide {
        Wide {
            neg: m < 0,
            hi: 0,
            lo: m.unsigned_abs(),
        }
    }

    /// The value, if an `i128` holds it.
    pub(super) fn to_i128(self) -> Option<i128> {
        if self.hi != 0 {
            return None;
        }
        let m = i128::try_from(self.lo).ok()?;
        Some(if self.neg { -m } else { m })
    }

    /// The value of `m`, if `|m| < 2^255`.
    pub(super) fn from_ibig(m: &IBig) -> Option<Wide> {
        let (sign, words) = m.as_sign_words();
        let (mut hi, mut lo) = (0u128, 0u128);
        // A word is 64 or 32 bits: none straddles bit 128.
        for (i, &w) in words.iter().enumerate() {
            let (bit, w) = (i as u32 * Word::BITS, u128::from(w));
            match bit {
                0..128 => lo |= w << bit,
                128..256 => hi |= w << (bit - 128),
                _ if w != 0 => return None,
                _ => {}
            }
        }
        Wide::new(sign == Sign::Negative, hi, lo)
    }

    pub(super) fn to_ibig(self) -> IBig {
        let mut bytes = [0; 32];
        bytes[..16].copy_from_slice(&self.lo.to_le_bytes());
        bytes[16..].copy_from_slice(&self.hi.to_le_bytes());
        let sign = if self.neg {
            Sign::Negative
        } else {
            Sign::Positive
        };
        IBig::from_parts(sign, UBig::from_le_bytes(&bytes))
    }

    pub(super) fn signum(self) -> i32 {
        if self.neg {
            -1
        } else {
            i32::from(self.hi != 0 || self.lo != 0)
        }
    }

    /// The length of the magnitude in bits (0 for zero).
    pub(super) fn len(self) -> u32 {
        if self.hi != 0 {
            256 - self.hi.leading_zeros()
        } else {
            128 - self.lo.leading_zeros()
        }
    }

    /// The number of trailing zero bits (0 for zero).
    pub(super) fn trailing_zeros(self) -> u32 {
        match (self.lo, self.hi) {
            (0, 0) => 0,
            (0, hi) => 128 + hi.trailing_zeros(),
            (lo, _) => lo.trailing_zeros(),
        }
    }

    pub(super) fn neg(self) -> Wide {
        Wide::new(!self.neg, self.hi, self.lo).expect("same magnitude")
    }

    /// The magnitude shifted right by `s < 256` (rounded down), with the
    /// sign kept.
    fn shr_mag(self, s: u32) -> Wide {
        let (hi, lo) = match s {
            0 => (self.hi, self.lo),
            1..128 => (self.hi >> s, (self.lo >> s) | (self.hi << (128 - s))),
            _ => (0, self.hi >> (s - 128)),
        };
        Wide::new(self.neg, hi, lo).expect("shorter")
    }

    /// `self / 2^s` for `s ≤ trailing_zeros`.
    pub(super) fn shr_exact(self, s: u32) -> Wide {
        debug_assert!(s <= self.trailing_zeros() || self.signum() == 0);
        self.shr_mag(s)
    }

    /// `floor(self / 2^s)`, for a quotient that fits in an `i128`.
    pub(super) fn shr_floor_i128(self, s: u32) -> i128 {
        let q = self.shr_mag(s);
        let back = q.shl(s).expect("no longer than self");
        let dropped = (back.hi, back.lo) != (self.hi, self.lo);
        let q = q.to_i128().expect("short quotient");
        if self.neg && dropped { q - 1 } else { q }
    }

    /// `self · 2^s`, if it fits.
    pub(super) fn shl(self, s: u32) -> Option<Wide> {
        if self.signum() == 0 {
            return Some(self);
        }
        if s > Self::BITS - self.len() {
            return None;
        }
        let (hi, lo) = match s {
            0 => (self.hi, self.lo),
            1..128 => ((self.hi << s) | (self.lo >> (128 - s)), self.lo << s),
            _ => (self.lo << (s - 128), 0),
        };
        Wide::new(self.neg, hi, lo)
    }

    fn cmp_mag(self, o: Wide) -> Ordering {
        (self.hi, self.lo).cmp(&(o.hi, o.lo))
    }

    /// `self + o`, if it fits.
    pub(super) fn add(self, o: Wide) -> Option<Wide> {
        if self.neg == o.neg {
            let (lo, carry) = self.lo.overflowing_add(o.lo);
            let hi = self.hi.checked_add(o.hi)?.checked_add(u128::from(carry))?;
            return Wide::new(self.neg, hi, lo);
        }
        // Opposite signs: the larger magnitude less the smaller one.
        let (big, small) = match self.cmp_mag(o) {
            Ordering::Less => (o, self),
            _ => (self, o),
        };
        let (lo, borrow) = big.lo.overflowing_sub(small.lo);
        let hi = big.hi - small.hi - u128::from(borrow);
        Wide::new(big.neg, hi, lo)
    }

    /// `self · o`, if it fits (the lengths alone decide: a product whose
    /// factors' lengths add up to more than 255 bits is refused).
    pub(super) fn mul(self, o: Wide) -> Option<Wide> {
        if self.len() + o.len() > Self::BITS {
            return None;
        }
        let limbs = |w: Wide| {
            [
                w.lo as u64,
                (w.lo >> 64) as u64,
                w.hi as u64,
                (w.hi >> 64) as u64,
            ]
        };
        let (a, b) = (limbs(self), limbs(o));
        let mut r = [0u64; 4];
        for i in 0..4 {
            let mut carry = 0u128;
            for j in 0..4 - i {
                let t = u128::from(a[i]) * u128::from(b[j]) + u128::from(r[i + j]) + carry;
                r[i + j] = t as u64;
                carry = t >> 64;
            }
        }
        let join = |l: u64, h: u64| u128::from(l) | (u128::from(h) << 64);
        Wide::new(self.neg != o.neg, join(r[2], r[3]), join(r[0], r[1]))
    }
}

/// `a·2^ea` against `b·2^eb` without overflow: by sign, then by the place
/// of the leading bit, and only for equal places (where the shift is short
/// enough to fit) by the aligned magnitudes.
pub(super) fn cmp(a: Wide, ea: i32, b: Wide, eb: i32) -> Ordering {
    let (sa, sb) = (a.signum(), b.signum());
    if sa != sb || sa == 0 {
        return sa.cmp(&sb);
    }
    let top = |m: Wide, e: i32| e as i64 + m.len() as i64;
    let aligned = |m: Wide, s: i32| {
        // Equal leading places: |s| < 255 and the shifted length is the other's.
        m.shl(s as u32).expect("aligned magnitudes fit")
    };
    let mag = match top(a, ea).cmp(&top(b, eb)) {
        Ordering::Equal if ea >= eb => aligned(a, ea - eb).cmp_mag(b),
        Ordering::Equal => a.cmp_mag(aligned(b, eb - ea)),
        unequal => unequal,
    };
    if sa > 0 { mag } else { mag.reverse() }
}

#[cfg(test)]
mod tests {
    use super::*;
    use dashu_int::ops::BitTest;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    fn random(r: &mut SmallRng) -> Wide {
        let bits = if r.random_bool(0.3) {
            255
        } else {
            r.random_range(0..=255u32)
        };
        let (hi, lo): (u128, u128) = (r.random(), r.random());
        let w = Wide::new(r.random_bool(0.5), hi >> 1, lo).unwrap();
        w.shr_mag(255 - bits)
    }

    /// Every operation agrees with big integers, or declines exactly when
    /// the exact result has 256 bits or more (mul: when the factors'
    /// lengths add up to more than 255).
    #[test]
    fn operations_match_big_integers() {
        let mut r = SmallRng::seed_from_u64(256);
        let fits = |m: &IBig| m.bit_len() <= 255;
        let mut declined = [0; 3];
        for _ in 0..50_000 {
            let (a, b) = (random(&mut r), random(&mut r));
            let (x, y) = (a.to_ibig(), b.to_ibig());
            assert_eq!(Wide::from_ibig(&x), Some(a));
            let sign = match x.sign() {
                _ if x.is_zero() => 0,
                dashu_int::Sign::Negative => -1,
                dashu_int::Sign::Positive => 1,
            };
            assert_eq!(a.signum(), sign);
            assert_eq!(a.len() as usize, x.bit_len());
            assert_eq!(a.neg().to_ibig(), -&x);
            let sum = &x + &y;
            match a.add(b) {
                Some(s) => assert_eq!(s.to_ibig(), sum),
                None => {
                    assert!(!fits(&sum));
                    declined[0] += 1;
                }
            }
            let p = &x * &y;
            match a.mul(b) {
                Some(m) => assert_eq!(m.to_ibig(), p),
                None => {
                    assert!(a.len() + b.len() > 255);
                    declined[1] += 1;
                }
            }
            if a.signum() != 0 {
                assert_eq!(a.shl(u32::MAX), None);
            }
            let s = r.random_range(0..256u32);
            let shifted = &x << s as usize;
            match a.shl(s) {
                Some(m) => assert_eq!(m.to_ibig(), shifted),
                None => {
                    assert!(!fits(&shifted));
                    declined[2] += 1;
                }
            }
            let q = a.shr_mag(s);
            let toward_zero =
                IBig::from(dashu_int::ops::UnsignedAbs::unsigned_abs(x.clone()) >> s as usize);
            assert_eq!(q.to_ibig(), if a.neg { -toward_zero } else { toward_zero });
            if q.len() < 127 {
                assert_eq!(IBig::from(a.shr_floor_i128(s)), &x >> s as usize);
            }
            let tz = a.trailing_zeros();
            assert_eq!(tz as usize, x.trailing_zeros().unwrap_or(0));
            assert_eq!(a.shr_exact(tz).to_ibig() << tz as usize, x);
            assert_eq!(
                a.to_i128(),
                i128::try_from(&x).ok().filter(|m| *m != i128::MIN)
            );
            let (ea, eb) = (r.random_range(-300..300), r.random_range(-300..300));
            let want = if ea >= eb {
                (&x << (ea - eb) as usize).cmp(&y)
            } else {
                x.cmp(&(&y << (eb - ea) as usize))
            };
            assert_eq!(cmp(a, ea, b, eb), want, "{a:?} {ea} {b:?} {eb}");
            assert_eq!(cmp(a, ea, a, ea), Ordering::Equal);
            // Equal leading places: the same value shifted, and one more.
            let k = r.random_range(0..8);
            if let Some(b) = a.shl(k).filter(|_| a.signum() != 0) {
                assert_eq!(cmp(a, ea, b, ea - k as i32), Ordering::Equal);
                let one = Wide::from_i128(i128::from(a.signum()));
                let b1 = b.add(one).unwrap();
                let want = if a.neg {
                    Ordering::Less
                } else {
                    Ordering::Greater
                };
                assert_eq!(cmp(b1, ea - k as i32, a, ea), want, "{a:?} {k}");
            }
        }
        assert!(declined.iter().all(|&n| n > 1_000), "{declined:?}");
    }
}
