//! Rigorous enclosures at any precision: dyadic intervals over big
//! integers, with `tan`, `√` and `1/√` bounded on both sides, and the test
//! that an enclosure decides its `f32` rounding.
//!
//! A [`Fx`] is an exact dyadic `m·2^e`. Sums and products of them are
//! formed exactly; [`Iv::round`] then rounds the lower end down and the upper
//! end up to `p` significant bits, so every interval contains the real
//! number it stands for, whatever `p`.
//!
//! # `tan`
//!
//! For `t ∈ (0, π/2)`, `tan t = t·S/C` with
//! `S = sin t / t = Σ (−1)ᵏ t²ᵏ/(2k + 1)!` and `C = cos t = Σ (−1)ᵏ t²ᵏ/(2k)!`.
//! Since `t² < (π/2)² < 2.47`, the terms of `S` shrink from the first
//! (ratio `t²/((2k + 2)(2k + 3)) < 1`) and those of `C` from the second
//! (ratio `t²/((2k + 1)(2k + 2)) < 1` for `k ≥ 1`): both series alternate
//! with decreasing terms past their first, so each tail is at most its first
//! term in magnitude. The sums stop once that term is below `2^−(p + 32)`;
//! as `S > 0.6` and `C = sin(π/2 − t) > 2⁻²⁵` for every `t` half an `f32`
//! below π (the largest is `π − 1.5·10⁻⁷`), the tail is then below
//! `2^−(p + 7)` of either, relatively. Each term is bounded on both sides
//! from the previous one's bounds, with floor and ceiling divisions.
//!
//! ```
//! use rayoracle::camera::tan::{Fx, tan_half};
//! // tan(1/2) = 0.54630248984379051325517946578028538329755172017979…
//! let h = tan_half(1.0, 100);
//! assert!((h.lo.to_f64() - 0.5463024898437905).abs() < 1e-16);
//! assert!(h.width_bits() < -95);
//! ```

use crate::num::certify::{narrow_exact, widen_bits};
use core::cmp::Ordering;
use dashu_int::ops::{BitTest, UnsignedAbs};
use dashu_int::{IBig, UBig};

/// An exact dyadic number `m·2^e`.
#[derive(Clone, Debug)]
pub struct Fx {
    m: IBig,
    e: i64,
}

/// The bit length of `|m|` (0 for 0).
fn bits(m: &IBig) -> i64 {
    let (_, w) = m.as_sign_words();
    w.last().map_or(0, |l| {
        (w.len() * dashu_int::Word::BITS as usize) as i64 - l.leading_zeros() as i64
    })
}

/// `2^e` as an f64, for `e` in the normal range.
fn pow2(e: i64) -> f64 {
    f64::from_bits(((e.clamp(-1022, 1023) + 1023) as u64) << 52)
}

impl Fx {
    /// Zero.
    pub fn zero() -> Fx {
        Fx {
            m: IBig::ZERO,
            e: 0,
        }
    }

    /// `m·2^e`.
    pub fn new(m: impl Into<IBig>, e: i64) -> Fx {
        Fx { m: m.into(), e }
    }

    /// The exact value of a finite `f64` (an `f32` converts exactly to it).
    ///
    /// ```
    /// use rayoracle::camera::tan::Fx;
    /// assert_eq!(Fx::from_f64(-0.375).to_f64(), -0.375);
    /// ```
    pub fn from_f64(x: f64) -> Fx {
        debug_assert!(x.is_finite());
        let b = x.to_bits();
        let exp = ((b >> 52) & 0x7ff) as i64;
        let frac = (b & ((1 << 52) - 1)) as i64;
        let (m, e) = if exp == 0 {
            (frac, -1074)
        } else {
            (frac | 1 << 52, exp - 1075)
        };
        // Without trailing zeros (an f32 has 29 of them), so that sums and
        // products stay short.
        let tz = m.trailing_zeros().min(63) as i64;
        let (m, e) = if m == 0 { (0, 0) } else { (m >> tz, e + tz) };
        Fx::new(if x < 0.0 { -m } else { m }, e)
    }

    /// The sign: −1, 0 or 1.
    pub fn signum(&self) -> i32 {
        match self.m.cmp(&IBig::ZERO) {
            Ordering::Less => -1,
            Ordering::Equal => 0,
            Ordering::Greater => 1,
        }
    }

    /// An f64 within about `2⁻⁵²` of the value, relatively, where that is
    /// a normal f64.
    pub fn to_f64(&self) -> f64 {
        let sh = (bits(&self.m) - 60).max(0);
        let m = &self.m >> sh as usize;
        let e = self.e + sh;
        let m = i64::try_from(m).expect("at most 60 bits") as f64;
        // Two steps, so that neither factor leaves f64's range early.
        let half = e / 2;
        m * pow2(half) * pow2(e - half)
    }

    /// The value as an `f64`, if it is one exactly: at most 53
    /// significant bits, and normal.
    ///
    /// ```
    /// use rayoracle::camera::tan::Fx;
    /// assert_eq!(Fx::new(-3, -2).to_f64_exact(), Some(-0.75));
    /// assert_eq!(Fx::new((1i64 << 54) + 1, 0).to_f64_exact(), None);
    /// assert_eq!(Fx::new(1, -1074).to_f64_exact(), None);
    /// ```
    pub fn to_f64_exact(&self) -> Option<f64> {
        let b = bits(&self.m);
        let normal = -1022 <= self.e && self.e + b <= 1023;
        if b > 53 || !normal {
            return None;
        }
        // |m| < 2⁵³ converts exactly, and so does its product by 2^e.
        Some(i64::try_from(&self.m).ok()? as f64 * pow2(self.e))
    }

    /// The highest set bit's position: `|x| ∈ [2^b, 2^(b+1))`; very
    /// negative for zero.
    pub fn exponent(&self) -> i64 {
        if self.signum() == 0 {
            i64::MIN / 4
        } else {
            bits(&self.m) - 1 + self.e
        }
    }

    fn align(&self, o: &Fx) -> (IBig, IBig, i64) {
        let e = self.e.min(o.e);
        (
            &self.m << (self.e - e) as usize,
            &o.m << (o.e - e) as usize,
            e,
        )
    }

    /// The exact sum.
    pub fn add(&self, o: &Fx) -> Fx {
        let (a, b, e) = self.align(o);
        Fx::new(a + b, e)
    }

    /// The exact difference.
    pub fn sub(&self, o: &Fx) -> Fx {
        let (a, b, e) = self.align(o);
        Fx::new(a - b, e)
    }

    /// The exact product.
    pub fn mul(&self, o: &Fx) -> Fx {
        Fx::new(&self.m * &o.m, self.e + o.e)
    }

    /// `−x`.
    pub fn neg(&self) -> Fx {
        Fx::new(-&self.m, self.e)
    }

    /// The largest dyadic of `p` significant bits at most `x`.
    pub fn floor(&self, p: u32) -> Fx {
        let sh = bits(&self.m) - p as i64;
        if sh <= 0 {
            return self.clone();
        }
        Fx::new(&self.m >> sh as usize, self.e + sh)
    }

    /// The smallest dyadic of `p` significant bits at least `x`.
    pub fn ceil(&self, p: u32) -> Fx {
        let sh = bits(&self.m) - p as i64;
        if sh <= 0 {
            return self.clone();
        }
        let cut = self.m.trailing_zeros().is_some_and(|z| (z as i64) < sh);
        Fx::new(
            (&self.m >> sh as usize) + IBig::from(cut as u8),
            self.e + sh,
        )
    }

    /// `⌊a/b⌋` or `⌈a/b⌉` (`up`) to `p` bits, for `a ≥ 0`, `b > 0`.
    fn div(a: &Fx, b: &Fx, p: u32, up: bool) -> Fx {
        let s = (p as i64 + 2 + bits(&b.m) - bits(&a.m)).max(0);
        let (n, d) = ((&a.m).unsigned_abs() << s as usize, (&b.m).unsigned_abs());
        let (q, r) = (&n / &d, &n % &d);
        let q = if up && r != UBig::ZERO {
            q + UBig::ONE
        } else {
            q
        };
        Fx::new(IBig::from(q), a.e - s - b.e)
    }
}

impl PartialEq for Fx {
    fn eq(&self, o: &Fx) -> bool {
        self.cmp(o) == Ordering::Equal
    }
}

impl Eq for Fx {}

impl PartialOrd for Fx {
    fn partial_cmp(&self, o: &Fx) -> Option<Ordering> {
        Some(self.cmp(o))
    }
}

/// By sign, then by the highest set bit, and only for equal signs and
/// highest bits by the aligned significands.
impl Ord for Fx {
    fn cmp(&self, o: &Fx) -> Ordering {
        let (s, t) = (self.signum(), o.signum());
        if s != t || s == 0 {
            return s.cmp(&t);
        }
        let by_size = self.exponent().cmp(&o.exponent());
        if by_size != Ordering::Equal {
            return if s > 0 { by_size } else { by_size.reverse() };
        }
        let (a, b, _) = self.align(o);
        a.cmp(&b)
    }
}

/// A closed interval `[lo, hi]` of dyadics.
#[derive(Clone, Debug)]
pub struct Iv {
    /// The lower end.
    pub lo: Fx,
    /// The upper end.
    pub hi: Fx,
}

impl Iv {
    /// The point interval `[x, x]`.
    pub fn point(x: Fx) -> Iv {
        Iv {
            lo: x.clone(),
            hi: x,
        }
    }

    /// Outward rounding to `p` bits.
    pub fn round(&self, p: u32) -> Iv {
        Iv {
            lo: self.lo.floor(p),
            hi: self.hi.ceil(p),
        }
    }

    /// The exact sum, rounded outward to `p` bits.
    pub fn add(&self, o: &Iv, p: u32) -> Iv {
        Iv {
            lo: self.lo.add(&o.lo).floor(p),
            hi: self.hi.add(&o.hi).ceil(p),
        }
    }

    /// The product, rounded outward to `p` bits: the least and greatest of
    /// the four exact products of ends (two of them, where the signs of
    /// both intervals are known).
    pub fn mul(&self, o: &Iv, p: u32) -> Iv {
        let sign = |x: &Iv| match (x.lo.signum(), x.hi.signum()) {
            (l, _) if l >= 0 => 1,
            (_, h) if h <= 0 => -1,
            _ => 0,
        };
        let (a, b) = match (sign(self), sign(o)) {
            (1, 1) => (self.lo.mul(&o.lo), self.hi.mul(&o.hi)),
            (1, -1) => (self.hi.mul(&o.lo), self.lo.mul(&o.hi)),
            (-1, 1) => (self.lo.mul(&o.hi), self.hi.mul(&o.lo)),
            (-1, -1) => (self.hi.mul(&o.hi), self.lo.mul(&o.lo)),
            _ => return self.mul4(o, p),
        };
        Iv {
            lo: a.floor(p),
            hi: b.ceil(p),
        }
    }

    fn mul4(&self, o: &Iv, p: u32) -> Iv {
        let c = [
            self.lo.mul(&o.lo),
            self.lo.mul(&o.hi),
            self.hi.mul(&o.lo),
            self.hi.mul(&o.hi),
        ];
        let lo = c.iter().min().expect("four");
        let hi = c.iter().max().expect("four");
        Iv {
            lo: lo.floor(p),
            hi: hi.ceil(p),
        }
    }

    /// `self / o` for `self ≥ 0` and `o > 0`, rounded outward to `p` bits.
    pub fn div_pos(&self, o: &Iv, p: u32) -> Iv {
        Iv {
            lo: Fx::div(&self.lo, &o.hi, p, false),
            hi: Fx::div(&self.hi, &o.lo, p, true),
        }
    }

    /// `log₂((hi − lo)/|lo|)`, roughly: how many bits the ends agree to
    /// (very negative for a point, `+∞`-ish where `lo = 0`).
    pub fn width_bits(&self) -> i64 {
        let w = self.hi.sub(&self.lo);
        if w.signum() == 0 {
            return i64::MIN / 4;
        }
        w.exponent() - self.lo.exponent()
    }
}

/// `√x` for `x ≥ 0`, enclosed to `p` bits: `r = ⌊√(x·4ᵏ)⌋` of an integer
/// with at least `2p` bits gives `r ≤ √(x·4ᵏ) ≤ r + 1`.
///
/// ```
/// use rayoracle::camera::tan::{Fx, sqrt};
/// let r = sqrt(&Fx::from_f64(2.0), 80);
/// assert!(r.lo.to_f64() <= std::f64::consts::SQRT_2 && std::f64::consts::SQRT_2 <= r.hi.to_f64());
/// assert!(r.width_bits() < -78);
/// let four = sqrt(&Fx::from_f64(0.25), 80);
/// assert!(four.lo == four.hi && four.lo.to_f64() == 0.5);
/// ```
pub fn sqrt(x: &Fx, p: u32) -> Iv {
    // A longer argument is first rounded down and up to 2p + 8 bits
    // (the root is monotone): the roots of the two ends enclose its root.
    let cap = 2 * p + 8;
    if bits(&x.m) > cap as i64 {
        return Iv {
            lo: sqrt_exact(&x.floor(cap), p).lo,
            hi: sqrt_exact(&x.ceil(cap), p).hi,
        };
    }
    sqrt_exact(x, p)
}

/// [`sqrt`] of the exact argument.
fn sqrt_exact(x: &Fx, p: u32) -> Iv {
    debug_assert!(x.signum() >= 0);
    let (mut m, mut e) = ((&x.m).unsigned_abs(), x.e);
    if e.rem_euclid(2) != 0 {
        m <<= 1;
        e -= 1;
    }
    let k = (p as i64 + 2 - m.bit_len() as i64 / 2).max(0);
    let n = m << (2 * k) as usize;
    let r = dashu_int::ops::SquareRoot::sqrt(&n);
    let exact = &r * &r == n;
    let up = if exact { r.clone() } else { &r + UBig::ONE };
    let e = e / 2 - k;
    Iv {
        lo: Fx::new(IBig::from(r), e),
        hi: Fx::new(IBig::from(up), e),
    }
}

/// `1/√x` for `x > 0`, enclosed to `p` bits.
pub fn rsqrt(x: &Fx, p: u32) -> Iv {
    Iv::point(Fx::new(1, 0)).div_pos(&sqrt(x, p + 4), p)
}

/// `Σₖ (−1)ᵏ aₖ` with `a₀ = 1`, `aₖ = aₖ₋₁·m²/(4ˢ·dₖ)`, enclosed in
/// fixed point: integers counting `2^−w`. Each term's lower and upper
/// bounds come from the previous one's by one multiplication by the word
/// `m²` and one floor (or ceiling) division by `2^(2s)·dₖ`, done as a
/// shift and a word division: `⌊⌊a/b⌋/c⌋ = ⌊a/(bc)⌋` for positive
/// integers, and likewise for ceilings, so each bound is the exact term's
/// floor (ceiling) of the previous bound's. The partial sums are exact;
/// the enclosure is the partial sum plus or minus the first omitted
/// term, once that is below `2^−(p + 32)` (the caller guarantees
/// the terms decrease past the first). `den(k)` is `dₖ`.
fn alternating(m2: u64, s: usize, w: usize, p: u32, den: impl Fn(u64) -> u64) -> (IBig, IBig) {
    let one = UBig::ONE << w;
    let tiny = UBig::ONE << w.saturating_sub(p as usize + 32);
    let (mut lo, mut hi) = (one.clone(), one);
    let (mut sum_lo, mut sum_hi) = (IBig::from(lo.clone()), IBig::from(hi.clone()));
    for k in 1.. {
        let d = den(k);
        lo = ((lo * m2) >> (2 * s)) / d;
        let x = hi * m2;
        let cut = x.trailing_zeros().is_some_and(|z| z < 2 * s);
        let x = (x >> (2 * s)) + UBig::from(cut as u8);
        hi = if (&x % d) == 0 {
            x / d
        } else {
            x / d + UBig::ONE
        };
        if hi < tiny {
            return (sum_lo - IBig::from(hi.clone()), sum_hi + IBig::from(hi));
        }
        if k % 2 == 1 {
            sum_lo -= IBig::from(hi.clone());
            sum_hi -= IBig::from(lo.clone());
        } else {
            sum_lo += IBig::from(lo.clone());
            sum_hi += IBig::from(hi.clone());
        }
    }
    unreachable!("the terms fall below any bound")
}

/// `tan(angle/2)` for an `f32` angle in `(0, π)`, enclosed to about `p`
/// bits (see the module docs).
///
/// ```
/// use rayoracle::camera::tan::tan_half;
/// // tan(π/4) is 1; f32's π/2 is 4.4·10⁻⁸ beyond π/2, and the
/// // tangent's slope there is 1: tan = 1.0000000437113909572…
/// let h = tan_half(std::f32::consts::FRAC_PI_2, 120);
/// assert!(h.lo.to_f64() > 1.0 + 4.3e-8 && h.hi.to_f64() < 1.0 + 4.4e-8);
/// ```
pub fn tan_half(angle: f32, p: u32) -> Iv {
    // On the bits, as `Camera::new` tests it: denormals-are-zero reads a
    // subnormal angle as 0 in a float comparison.
    debug_assert!((1..core::f32::consts::PI.to_bits()).contains(&angle.to_bits()));
    // angle/2 = m·2^−s exactly, m < 2²⁴ (s > 0: the angle is below 4).
    let b = angle.to_bits();
    let (exp, frac) = ((b >> 23) as i64, (b & 0x7f_ffff) as u64);
    let (m, e) = if exp == 0 {
        (frac, -149)
    } else {
        (frac | 1 << 23, exp - 150)
    };
    let s = (1 - e) as usize;
    let w = p as usize + 40;
    let m2 = m * m;
    let (s_lo, s_hi) = alternating(m2, s, w, p, |k| (2 * k) * (2 * k + 1));
    let (c_lo, c_hi) = alternating(m2, s, w, p, |k| (2 * k - 1) * (2 * k));
    let fixed = |lo: IBig, hi: IBig| Iv {
        lo: Fx::new(lo, -(w as i64)),
        hi: Fx::new(hi, -(w as i64)),
    };
    let t = Fx::new(m as i64, -(s as i64));
    Iv::point(t)
        .mul(&fixed(s_lo, s_hi), p + 8)
        .div_pos(&fixed(c_lo, c_hi), p + 4)
}

/// The `f32` every real in `x` rounds to (nearest, ties to even,
/// overflowing to ±∞), when they all round to the same one.
///
/// Each `f32` `c` owns the open interval between the midpoints to its
/// neighbours (`±(2¹²⁸ − 2¹⁰³)` beyond `±f32::MAX`); `x` decides `c` when
/// it lies strictly inside. Zero is split at 0 itself: `(0, 2⁻¹⁵⁰)` rounds
/// to `+0`, `(−2⁻¹⁵⁰, 0)` to `−0`. The candidates are the `f32` nearest an
/// f64 approximation of `x.lo` and its two neighbours, one of which owns
/// `x.lo`. A midpoint itself is never decided, so the caller must know its
/// real number is not one (or narrow to a point elsewhere).
///
/// ```
/// use rayoracle::camera::tan::{Fx, Iv, decide};
/// let third = Iv { lo: Fx::new(1, 0).sub(&Fx::new(1, -60)), hi: Fx::new(1, 0) };
/// assert_eq!(decide(&third), Some(1.0));
/// let mid = Fx::from_f64(1.0 + f32::EPSILON as f64 / 2.0);
/// assert_eq!(decide(&Iv::point(mid)), None);
/// assert_eq!(decide(&Iv::point(Fx::new(-1, -200))), Some(-0.0));
/// assert_eq!(decide(&Iv::point(Fx::new(1, 200))), Some(f32::INFINITY));
/// ```
pub fn decide(x: &Iv) -> Option<f32> {
    // The candidates as bits, their neighbours and values found with
    // integer arithmetic ([`widen_bits`]): the exact path must meet
    // neither flush-to-zero nor denormals-are-zero, and a float holding a
    // subnormal could be compared as one.
    const SIGN: u32 = 0x8000_0000;
    const INF: u32 = 0x7f80_0000;
    const MAX: u32 = 0x7f7f_ffff;
    let up = |b: u32| match b {
        SIGN => 1,
        _ if b & SIGN == 0 => b + 1,
        _ => b - 1,
    };
    let down = |b: u32| match b {
        0 => SIGN | 1,
        _ if b & SIGN == 0 => b - 1,
        _ => b + 1,
    };
    let threshold = 2f64.powi(128) - 2f64.powi(103);
    let sign = |b: u32| if b & SIGN == 0 { 1.0 } else { -1.0 };
    let mid = |a: u32, b: u32| (widen_bits(a) + widen_bits(b)) / 2.0;
    let owner = |b: u32| -> (f64, f64) {
        let below = if b == SIGN | INF {
            f64::NEG_INFINITY
        } else if b == SIGN | MAX || b == INF {
            sign(b) * threshold
        } else {
            mid(b, down(b))
        };
        let above = if b == INF {
            f64::INFINITY
        } else if b == MAX || b == SIGN | INF {
            sign(b) * threshold
        } else {
            mid(b, up(b))
        };
        (below, above)
    };
    let inside = |lo: f64, hi: f64| {
        (lo == f64::NEG_INFINITY || Fx::from_f64(lo) < x.lo)
            && (hi == f64::INFINITY || x.hi < Fx::from_f64(hi))
    };
    let guess = narrow_exact(x.lo.to_f64()).to_bits();
    for b in [guess, up(guess), down(guess)] {
        if b & !SIGN > INF {
            continue; // NaN
        }
        if b & !SIGN == 0 {
            let tiny = 2f64.powi(-150);
            if inside(0.0, tiny) && x.lo.signum() > 0 {
                return Some(0.0);
            }
            if inside(-tiny, 0.0) && x.hi.signum() < 0 {
                return Some(-0.0);
            }
            continue;
        }
        let (below, above) = owner(b);
        if inside(below, above) {
            return Some(f32::from_bits(b));
        }
    }
    None
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decide_never_decides_a_midpoint_or_a_straddle() {
        for c in [1.0f32, 1e-40, -3.5, f32::MIN_POSITIVE, -f32::MIN_POSITIVE] {
            let mid = Fx::from_f64((c as f64 + c.next_up() as f64) / 2.0);
            assert_eq!(decide(&Iv::point(mid.clone())), None, "{c}");
            let eps = Fx::new(1, -200);
            assert_eq!(decide(&Iv::point(mid.sub(&eps))), Some(c), "{c}");
            assert_eq!(decide(&Iv::point(mid.add(&eps))), Some(c.next_up()));
        }
        // Beyond f32::MAX, the overflow threshold 2¹²⁸ − 2¹⁰³.
        let t = Fx::new(1, 128).sub(&Fx::new(1, 103));
        let eps = Fx::new(1, -200);
        assert_eq!(decide(&Iv::point(t.clone())), None);
        assert_eq!(decide(&Iv::point(t.sub(&eps))), Some(f32::MAX));
        assert_eq!(decide(&Iv::point(t.add(&eps))), Some(f32::INFINITY));
        assert_eq!(decide(&Iv::point(t.neg().add(&eps))), Some(-f32::MAX));
        assert_eq!(
            decide(&Iv::point(t.neg().sub(&eps))),
            Some(f32::NEG_INFINITY)
        );
        let z = Iv {
            lo: Fx::new(-1, -300),
            hi: Fx::new(1, -300),
        };
        assert_eq!(decide(&z), None);
        assert_eq!(decide(&Iv::point(Fx::zero())), None);
    }

    /// The sign cases of [`Iv::mul`] give the four-product enclosure, and
    /// the shortcuts of the comparison its aligned result.
    #[test]
    fn products_and_comparisons_by_sign() {
        let v = [-5i64, -3, -1, 0, 1, 2, 7];
        let e = [-70i64, 0, 3];
        let fx: Vec<Fx> = v
            .iter()
            .flat_map(|&m| e.iter().map(move |&e| Fx::new(m, e)))
            .collect();
        let wide: Vec<Fx> = [-1000i64, -999, -7, 7, 999, 1000, 1 << 40, -(1 << 40) - 3]
            .iter()
            .map(|&m| Fx::new(m, -5))
            .collect();
        for a in fx.iter().chain(&wide) {
            for p in 1..12 {
                let (f, c) = (a.floor(p), a.ceil(p));
                assert!(
                    f <= *a && *a <= c && c == a.neg().floor(p).neg(),
                    "{a:?} {p}"
                );
            }
        }
        for a in &fx {
            for b in &fx {
                let (x, y, _) = a.align(b);
                assert_eq!(a.cmp(b), x.cmp(&y), "{a:?} {b:?}");
            }
        }
        for a in &fx {
            for b in fx.iter().filter(|b| *a <= **b) {
                let x = Iv {
                    lo: a.clone(),
                    hi: b.clone(),
                };
                for c in &fx {
                    for d in fx.iter().filter(|d| *c <= **d) {
                        let y = Iv {
                            lo: c.clone(),
                            hi: d.clone(),
                        };
                        let (m, m4) = (x.mul(&y, 60), x.mul4(&y, 60));
                        assert!(m.lo == m4.lo && m.hi == m4.hi, "{x:?} {y:?}");
                    }
                }
            }
        }
    }
}
