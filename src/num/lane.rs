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
    /// `self` where it is finite, `+0` where it is ±∞ or NaN.
    fn finite_or_zero(self) -> Self;
    /// The magnitude of `self` with the sign bit of `sign`.
    fn copysign(self, sign: Self) -> Self;
    /// `⌊log₂|x|⌋` for finite non-zero `x` (subnormals included); `0` for
    /// zero, ±∞ and NaN, so that scaling by it is then a no-op.
    fn ilogb(self) -> Self::Int;
    /// `x · 2^e`, exact unless the result overflows or is subnormal.
    ///
    /// `e` may lie anywhere in `[-600, 600]`: the scale is applied as three
    /// factors `2^e₁ · 2^e₂ · 2^e₃`, each a normal number, in one direction,
    /// so the only rounding is the one the final result needs.
    fn ldexp(self, e: Self::Int) -> Self;
    /// Broadcasts an integer constant.
    fn splat_int(e: i32) -> Self::Int;
    /// Lane-wise integer maximum.
    fn max_int(a: Self::Int, b: Self::Int) -> Self::Int;
}

const SIGN: u32 = 0x8000_0000;

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
    fn finite_or_zero(self) -> Self {
        if self.is_finite() { self } else { 0.0 }
    }
    #[inline]
    fn copysign(self, sign: Self) -> Self {
        f32::from_bits((self.to_bits() & !SIGN) | (sign.to_bits() & SIGN))
    }
    #[inline]
    fn ilogb(self) -> i32 {
        let a = Lane::abs(self);
        if !(a.is_finite() && a != 0.0) {
            return 0;
        }
        if a < f32::MIN_POSITIVE {
            // Subnormal: 2^32 lifts it into the normal range exactly.
            let b = a * 4_294_967_296.0;
            ((b.to_bits() >> 23) as i32 - 127) - 32
        } else {
            (a.to_bits() >> 23) as i32 - 127
        }
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
    fn splat_int(e: i32) -> i32 {
        e
    }
    #[inline]
    fn max_int(a: i32, b: i32) -> i32 {
        a.max(b)
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
    fn finite_or_zero(self) -> Self {
        self.is_finite().select(self, f32x4::ZERO)
    }
    #[inline]
    fn copysign(self, sign: Self) -> Self {
        let s: f32x4 = wide::bytemuck::cast(wide::u32x4::splat(SIGN));
        (self & !s) | (sign & s)
    }
    #[inline]
    fn ilogb(self) -> i32x4 {
        let a = Lane::abs(self);
        let normal_bits: i32x4 = wide::bytemuck::cast(a);
        let lifted: i32x4 = wide::bytemuck::cast(a * f32x4::splat(4_294_967_296.0));
        let e_normal = (normal_bits >> 23) - i32x4::splat(127);
        let e_sub = (lifted >> 23) - i32x4::splat(127 + 32);
        let is_sub: i32x4 = wide::bytemuck::cast(a.simd_lt(f32x4::splat(f32::MIN_POSITIVE)));
        let e = is_sub.select(e_sub, e_normal);
        let ok: i32x4 = wide::bytemuck::cast(a.is_finite() & a.simd_ne(f32x4::ZERO));
        ok.select(e, i32x4::ZERO)
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
    fn splat_int(e: i32) -> i32x4 {
        i32x4::splat(e)
    }
    #[inline]
    fn max_int(a: i32x4, b: i32x4) -> i32x4 {
        a.max(b)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ilogb_matches_definition() {
        for &(x, e) in &[
            (1.0f32, 0),
            (1.5, 0),
            (2.0, 1),
            (0.75, -1),
            (f32::MAX, 127),
            (f32::MIN_POSITIVE, -126),
            (f32::from_bits(1), -149),
            (f32::from_bits(0x0040_0000), -127),
            (0.0, 0),
            (f32::INFINITY, 0),
            (f32::NAN, 0),
        ] {
            assert_eq!(Lane::ilogb(x), e, "ilogb({x:e})");
            assert_eq!(Lane::ilogb(-x), e, "ilogb(-{x:e})");
            let v = Lane::ilogb(f32x4::splat(x)).to_array();
            assert_eq!(v, [e; 4], "x4 ilogb({x:e})");
        }
    }

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
}
