//! The [`Lane`] trait: what a kernel needs from its number type.

use core::ops::{Add, Div, Mul, Neg, Sub};
use wide::{f32x4, i32x4};

/// A floating-point lane type: `f32` for the scalar reference, `f32x4` for the
/// SIMD kernels.
///
/// Every method is specified so that the `f32x4` implementation gives, lane by
/// lane, exactly the bits the `f32` implementation gives. The NaN behaviour of
/// [`Lane::max`] in particular is spelled out instead of borrowed from
/// `f32::max`, whose NaN rule differs from SSE's `maxps`.
///
/// ```
/// use rayoracle::num::Lane;
/// let x: f32 = Lane::splat(3.0);
/// assert_eq!(Lane::max(x, 5.0), 5.0);
/// ```
pub trait Lane:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// The matching integer lane (`i32` or `i32x4`), used for exponents.
    type Int: Copy + Add<Output = Self::Int> + Sub<Output = Self::Int> + Neg<Output = Self::Int>;

    /// Broadcasts a constant.
    fn splat(x: f32) -> Self;
    /// Correctly rounded square root.
    fn sqrt(self) -> Self;
    /// `|x|`, by clearing the sign bit.
    fn abs(self) -> Self;
    /// `self > other ? self : other`: when either is NaN, `other`. This is
    /// SSE's `maxps` rule, written out so the scalar path matches it.
    fn max(self, other: Self) -> Self;
    /// `self < other ? self : other`: when either is NaN, `other` (SSE's
    /// `minps` rule).
    fn min(self, other: Self) -> Self;
    /// `self` where it is finite, `+0` where it is ±∞ or NaN: decided by
    /// `self − self == 0`, which is false exactly for ±∞ and NaN.
    fn finite_or_zero(self) -> Self;
    /// For `x ≥ 0`: the power of two `2^k ≤ x < 2^(k+1)`, clamped to
    /// `[2⁻¹²⁶, 2¹²⁶]` (subnormals and zero give `2⁻¹²⁶`, ∞ and NaN `2¹²⁶`).
    /// It is `x` with its significand bits cleared, then clamped.
    fn pow2_floor(self) -> Self;
    /// For a power of two `2^k` with `k` in `[−126, 126]`: `2^−k`, exactly,
    /// by integer arithmetic on the bits (`0x7f000000 − bits`).
    fn recip_pow2(self) -> Self;
    /// For a power of two `2^k` (normal): `k`.
    fn pow2_exponent(self) -> Self::Int;
    /// `x · 2^e`, exact unless the result overflows or is subnormal.
    ///
    /// `e` may lie anywhere in `[-600, 600]`: the scale is applied as three
    /// factors `2^e₁ · 2^e₂ · 2^e₃`, each a normal number, in one direction,
    /// so the only rounding is the one the final result needs.
    fn ldexp(self, e: Self::Int) -> Self;
    /// `if a > b { x } else { y }`, lane by lane (false for NaN).
    fn select_gt(a: Self, b: Self, x: Self, y: Self) -> Self;
}

const SIGN: u32 = 0x8000_0000;
const EXP: u32 = 0x7f80_0000;
/// 2^126.
const P126: f32 = f32::from_bits(0x7e80_0000);

/// `2^e` for `e` in `[-126, 127]`, built from its bits.
#[inline]
fn exp2i(e: i32) -> f32 {
    f32::from_bits(((e + 127) as u32) << 23)
}

impl Lane for f32 {
    type Int = i32;

    #[inline]
    fn splat(x: f32) -> Self {
        x
    }
    #[inline]
    fn sqrt(self) -> Self {
        f32::sqrt(self)
    }
    #[inline]
    fn abs(self) -> Self {
        f32::from_bits(self.to_bits() & !SIGN)
    }
    #[inline]
    fn max(self, other: Self) -> Self {
        if self > other { self } else { other }
    }
    #[inline]
    fn min(self, other: Self) -> Self {
        if self < other { self } else { other }
    }
    #[inline]
    #[allow(clippy::eq_op)] // x − x is 0 for finite x and NaN otherwise: the test itself.
    fn finite_or_zero(self) -> Self {
        if self - self == 0.0 { self } else { 0.0 }
    }
    #[inline]
    fn pow2_floor(self) -> Self {
        let p = f32::from_bits(self.to_bits() & EXP);
        Lane::min(Lane::max(p, f32::MIN_POSITIVE), P126)
    }
    #[inline]
    fn recip_pow2(self) -> Self {
        f32::from_bits(0x7f00_0000 - self.to_bits())
    }
    #[inline]
    fn pow2_exponent(self) -> i32 {
        (self.to_bits() >> 23) as i32 - 127
    }
    #[inline]
    fn ldexp(self, e: i32) -> Self {
        let e1 = e.clamp(-126, 127);
        let r1 = e - e1;
        let e2 = r1.clamp(-126, 127);
        let e3 = (r1 - e2).clamp(-126, 127);
        self * exp2i(e1) * exp2i(e2) * exp2i(e3)
    }
    #[inline]
    fn select_gt(a: Self, b: Self, x: Self, y: Self) -> Self {
        if a > b { x } else { y }
    }
}

#[inline]
fn exp2i_x4(e: i32x4) -> f32x4 {
    wide::bytemuck::cast((e + i32x4::splat(127)) << 23)
}

#[inline]
fn clamp_x4(e: i32x4) -> i32x4 {
    e.max(i32x4::splat(-126)).min(i32x4::splat(127))
}

impl Lane for f32x4 {
    type Int = i32x4;

    #[inline]
    fn splat(x: f32) -> Self {
        f32x4::splat(x)
    }
    #[inline]
    fn sqrt(self) -> Self {
        f32x4::sqrt(self)
    }
    #[inline]
    fn abs(self) -> Self {
        let m: f32x4 = wide::bytemuck::cast(wide::u32x4::splat(!SIGN));
        self & m
    }
    #[inline]
    fn max(self, other: Self) -> Self {
        self.simd_gt(other).select(self, other)
    }
    #[inline]
    fn min(self, other: Self) -> Self {
        self.simd_lt(other).select(self, other)
    }
    #[inline]
    #[allow(clippy::eq_op)] // x − x is 0 for finite x and NaN otherwise: the test itself.
    fn finite_or_zero(self) -> Self {
        // The mask is all ones where finite; and-ing keeps x, else +0.
        self & (self - self).simd_eq(f32x4::ZERO)
    }
    #[inline]
    fn pow2_floor(self) -> Self {
        let e: f32x4 = wide::bytemuck::cast(wide::u32x4::splat(EXP));
        Lane::min(
            Lane::max(self & e, f32x4::splat(f32::MIN_POSITIVE)),
            f32x4::splat(P126),
        )
    }
    #[inline]
    fn recip_pow2(self) -> Self {
        let b: i32x4 = wide::bytemuck::cast(self);
        wide::bytemuck::cast(i32x4::splat(0x7f00_0000) - b)
    }
    #[inline]
    fn pow2_exponent(self) -> i32x4 {
        let b: i32x4 = wide::bytemuck::cast(self);
        (b >> 23) - i32x4::splat(127)
    }
    #[inline]
    fn ldexp(self, e: i32x4) -> Self {
        let e1 = clamp_x4(e);
        let r1 = e - e1;
        let e2 = clamp_x4(r1);
        let e3 = clamp_x4(r1 - e2);
        self * exp2i_x4(e1) * exp2i_x4(e2) * exp2i_x4(e3)
    }
    #[inline]
    fn select_gt(a: Self, b: Self, x: Self, y: Self) -> Self {
        a.simd_gt(b).select(x, y)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ldexp_is_exact_across_the_range() {
        let tiny = f32::from_bits(1);
        assert_eq!(Lane::ldexp(tiny, 149 + 127), 2f32.powi(127));
        assert_eq!(
            Lane::ldexp(f32::MAX, -253),
            (f32::MAX as f64 * 2f64.powi(-253)) as f32
        );
        assert_eq!(Lane::ldexp(1.0f32, 128), f32::INFINITY);
        assert_eq!(Lane::ldexp(1.0f32, -150), 0.0);
        for e in [-300, -150, -20, 0, 5, 130, 260] {
            for x in [1.0f32, -3.25, 1e-30, 7e30, f32::from_bits(77)] {
                let s = Lane::ldexp(x, e);
                let v = Lane::ldexp(f32x4::splat(x), i32x4::splat(e)).to_array();
                assert_eq!(v.map(f32::to_bits), [s.to_bits(); 4]);
            }
        }
    }

    #[test]
    fn pow2_helpers_agree_on_both_paths() {
        for x in [
            0.0f32,
            1.0,
            1.5,
            3.0,
            1e-40,
            f32::from_bits(1),
            1e30,
            f32::MAX,
            f32::INFINITY,
            f32::NAN,
            2f32.powi(126),
            2f32.powi(127),
        ] {
            let p = Lane::pow2_floor(x);
            let want = if x.is_nan() || x >= 2f32.powi(126) {
                2f32.powi(126)
            } else if x < f32::MIN_POSITIVE {
                f32::MIN_POSITIVE
            } else {
                2f32.powi(x.log2().floor() as i32)
            };
            assert_eq!(p, want, "pow2_floor({x:e})");
            assert_eq!(Lane::recip_pow2(p), 1.0 / p);
            assert_eq!(2f32.powi(Lane::pow2_exponent(p)), p);
            let v = f32x4::splat(x);
            assert_eq!(Lane::pow2_floor(v).to_array(), [p; 4]);
            assert_eq!(
                Lane::recip_pow2(Lane::pow2_floor(v)).to_array(),
                [1.0 / p; 4]
            );
            assert_eq!(
                Lane::pow2_exponent(Lane::pow2_floor(v)).to_array(),
                [Lane::pow2_exponent(p); 4]
            );
            let f = Lane::finite_or_zero(x);
            assert_eq!(
                Lane::finite_or_zero(v).to_array().map(f32::to_bits),
                [f.to_bits(); 4]
            );
            assert_eq!(f, if x.is_finite() { x } else { 0.0 });
        }
    }

    #[test]
    fn max_uses_the_maxps_nan_rule_on_both_paths() {
        let n = f32::NAN;
        assert!(Lane::max(1.0f32, n).is_nan());
        assert_eq!(Lane::max(n, 1.0f32), 1.0);
        let v = Lane::max(
            f32x4::from([1.0, n, 2.0, -0.0]),
            f32x4::from([n, 1.0, 1.0, 0.0]),
        );
        let s = [
            Lane::max(1.0f32, n),
            Lane::max(n, 1.0),
            Lane::max(2.0, 1.0),
            Lane::max(-0.0f32, 0.0),
        ];
        assert_eq!(v.to_array().map(f32::to_bits), s.map(f32::to_bits));
    }

    /// min takes `other` on ties and NaN on both paths, which is what
    /// makes `min(−0, +0)` the same bits on both (cargo-mutants: `<=` in the
    /// scalar min passed every other test).
    #[test]
    fn min_uses_the_minps_rule_on_both_paths() {
        let n = f32::NAN;
        let pairs = [
            (-0.0f32, 0.0f32),
            (0.0, -0.0),
            (1.0, n),
            (n, 1.0),
            (2.0, 1.0),
            (1.0, 2.0),
        ];
        let v = Lane::min(
            f32x4::from([pairs[0].0, pairs[1].0, pairs[2].0, pairs[3].0]),
            f32x4::from([pairs[0].1, pairs[1].1, pairs[2].1, pairs[3].1]),
        );
        let s = pairs.map(|(a, b)| Lane::min(a, b).to_bits());
        assert_eq!(v.to_array().map(f32::to_bits), [s[0], s[1], s[2], s[3]]);
        assert_eq!(s[0], 0.0f32.to_bits());
        assert_eq!(s[1], (-0.0f32).to_bits());
        assert!(f32::from_bits(s[2]).is_nan());
        assert_eq!([s[3], s[4], s[5]], [1.0f32, 1.0, 1.0].map(f32::to_bits));
    }

    /// select_gt takes `x` only where `a > b`: not on ties (±0 included)
    /// nor NaN, alike on both paths. The render's facing test turns a
    /// normal only where it points along the ray (`dot > 0`), and keeps
    /// one at exactly 0.
    #[test]
    fn select_gt_takes_x_only_above_on_both_paths() {
        let n = f32::NAN;
        let cases = [
            (1.0f32, 0.0f32, true),
            (0.0, 0.0, false),
            (-0.0, 0.0, false),
            (0.0, -0.0, false),
            (0.0, 1.0, false),
            (n, 0.0, false),
            (0.0, n, false),
            (2.0, -3.0, true),
        ];
        for half in [&cases[..4], &cases[4..]] {
            let lanes =
                |k: fn(&(f32, f32, bool)) -> f32| f32x4::from([0, 1, 2, 3].map(|i| k(&half[i])));
            let v = Lane::select_gt(
                lanes(|c| c.0),
                lanes(|c| c.1),
                f32x4::splat(1.0),
                f32x4::splat(2.0),
            );
            let want = [0, 1, 2, 3].map(|i| if half[i].2 { 1.0 } else { 2.0 });
            let s = [0, 1, 2, 3].map(|i| Lane::select_gt(half[i].0, half[i].1, 1.0f32, 2.0));
            assert_eq!(v.to_array(), want);
            assert_eq!(s, want);
        }
    }
}
