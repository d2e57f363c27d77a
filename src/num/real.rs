//! The [`Real`] trait: what a filtered kernel needs from its number type,
//! implemented for `f64` (the scalar reference), [`F64x4`] (four lanes),
//! the AVX lanes of [`super::avx`] on x86-64, and [`Pair`] of any of them
//! (two packets at once).
//!
//! Every operation is one correctly rounded IEEE-754 operation per lane, so
//! a lane of [`F64x4`] gives the bits `f64` gives, whatever target features
//! the build or the run-time dispatch enables.
//!
//! ```
//! use rayoracle::num::real::{F64x4, Real};
//! let x = F64x4::from([1.0, 4.0, 9.0, 16.0]);
//! assert_eq!(x.sqrt().to_array(), [1.0, 2.0, 3.0, 4.0]);
//! assert_eq!(Real::sqrt(9.0f64), 3.0);
//! ```

use core::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};
use wide::{f32x4, f64x4, i32x4, i64x4};

/// A lane type of f64 values: `f64` or [`F64x4`].
pub trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
    /// Whether division is dear enough, against multiplication, that a
    /// kernel should take one reciprocal of a product rather than several
    /// quotients: true for four lanes, where throughput counts; false for
    /// one, where the latency of a chain of products counts more.
    const FEW_DIVISIONS: bool;
    /// The lane mask: `bool` or [`M4`].
    type Mask: Copy
        + BitAnd<Output = Self::Mask>
        + BitOr<Output = Self::Mask>
        + Not<Output = Self::Mask>;
    /// Broadcasts a constant.
    fn splat(x: f64) -> Self;
    /// Correctly rounded square root.
    fn sqrt(self) -> Self;
    /// `|x|`.
    fn abs(self) -> Self;
    /// The magnitude of `self` with the sign of `sign`.
    fn copysign(self, sign: Self) -> Self;
    /// `self > other`, lane by lane (false with a NaN).
    fn gt(self, other: Self) -> Self::Mask;
    /// `self == other`, lane by lane (false with a NaN).
    fn eq(self, other: Self) -> Self::Mask;
    /// `m ? a : b`, lane by lane.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// Whether `lo` and `hi` round to the same `f32`, bit for bit (so −0
    /// and +0 differ, and a NaN never matches).
    fn same_f32(lo: Self, hi: Self) -> Self::Mask;
    /// Whether `lo` and `hi` round to equal `f32` values, compared as
    /// floats: a NaN never matches, and −0 matches +0. The same as
    /// [`Real::same_f32`] where `lo` and `hi` cannot have different signs,
    /// at one comparison instead of two.
    fn equal_f32(lo: Self, hi: Self) -> Self::Mask;
    /// Whether the last 29 bits of each lane's f64 pattern, those that
    /// rounding to f32 drops, are more than `m` from `0x1000_0000`, the
    /// pattern of a rounding midpoint, counted modulo `2²⁹`: exact integer
    /// operations, the test of
    /// [`certify_relative`](crate::num::certify::certify_relative).
    fn off_midpoint(self, m: i64) -> Self::Mask;
    /// [`denormals_are_zero`](crate::num::certify::denormals_are_zero),
    /// probed in this type's instruction encoding (VEX for the AVX types).
    #[inline(always)]
    fn denormals_are_zero() -> bool {
        crate::num::certify::denormals_are_zero()
    }
    /// [`least_subnormal`](crate::num::certify::least_subnormal) in every
    /// lane, converted in this type's instruction encoding: `2⁻¹⁴⁹`, or 0
    /// under denormals-are-zero.
    #[inline(always)]
    fn least_subnormal() -> Self {
        Self::splat(crate::num::certify::least_subnormal::<false>())
    }
}

impl Real for f64 {
    const FEW_DIVISIONS: bool = false;
    type Mask = bool;
    #[inline(always)]
    fn splat(x: f64) -> f64 {
        x
    }
    #[inline(always)]
    fn sqrt(self) -> f64 {
        f64::sqrt(self)
    }
    #[inline(always)]
    fn abs(self) -> f64 {
        f64::abs(self)
    }
    #[inline(always)]
    fn copysign(self, sign: f64) -> f64 {
        f64::copysign(self, sign)
    }
    #[inline(always)]
    fn gt(self, other: f64) -> bool {
        self > other
    }
    #[inline(always)]
    fn eq(self, other: f64) -> bool {
        self == other
    }
    #[inline(always)]
    fn select(m: bool, a: f64, b: f64) -> f64 {
        if m { a } else { b }
    }
    #[inline(always)]
    fn same_f32(lo: f64, hi: f64) -> bool {
        (lo as f32).to_bits() == (hi as f32).to_bits() && !lo.is_nan()
    }
    #[inline(always)]
    fn equal_f32(lo: f64, hi: f64) -> bool {
        lo as f32 == hi as f32
    }
    #[inline(always)]
    fn off_midpoint(self, m: i64) -> bool {
        let x = self.to_bits().wrapping_sub((MIDPOINT - m) as u64) & DROPPED;
        x > 2 * m as u64
    }
}

/// The bits of an f64 that rounding to f32 drops (in f32's normal range).
const DROPPED: u64 = (1 << 29) - 1;
/// Those bits at an f32 rounding midpoint: one half of an f32 ulp.
const MIDPOINT: i64 = 1 << 28;

/// Four `f64` lanes (`wide::f64x4`: one AVX register where the build
/// enables AVX, two SSE2 registers otherwise).
///
/// ```
/// use rayoracle::num::real::F64x4;
/// let x = F64x4::from([1.0, 2.0, 3.0, 4.0]);
/// assert_eq!((x + x).to_array(), [2.0, 4.0, 6.0, 8.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct F64x4(pub f64x4);

/// Four lane masks (all ones or all zeros per lane).
///
/// ```
/// use rayoracle::num::real::{F64x4, Real};
/// let m = F64x4::from([1.0, 2.0, 3.0, 4.0]).gt(F64x4::splat(2.5));
/// assert_eq!(m.lanes(), [false, false, true, true]);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct M4(pub f64x4);

impl From<[f64; 4]> for F64x4 {
    #[inline(always)]
    fn from(x: [f64; 4]) -> F64x4 {
        F64x4(f64x4::from(x))
    }
}

impl F64x4 {
    /// Widens four `f32` lanes exactly.
    ///
    /// ```
    /// use rayoracle::num::real::F64x4;
    /// assert_eq!(F64x4::from_f32([0.1; 4]).to_array(), [0.1f32 as f64; 4]);
    /// ```
    #[inline(always)]
    pub fn from_f32(x: [f32; 4]) -> F64x4 {
        F64x4::from(x.map(f64::from))
    }
    /// The four lanes.
    #[inline(always)]
    pub fn to_array(self) -> [f64; 4] {
        self.0.to_array()
    }
    /// Each lane rounded to `f32`.
    ///
    /// ```
    /// use rayoracle::num::real::F64x4;
    /// assert_eq!(F64x4::from([0.1; 4]).to_f32(), [0.1f32; 4]);
    /// ```
    #[inline(always)]
    pub fn to_f32(self) -> [f32; 4] {
        self.to_array().map(|x| x as f32)
    }
}

/// A four-lane [`Real`], with what the x4 kernels need besides arithmetic:
/// moving between their `f32x4` inputs and outputs and the `f64` lanes,
/// and reading masks. Implemented by [`F64x4`] and, on x86-64, by the AVX
/// lanes of [`super::avx`].
///
/// ```
/// use rayoracle::num::real::{F64x4, Real, Real4};
/// use wide::f32x4;
/// let x = F64x4::widen(f32x4::from([0.1, 2.0, -3.0, 1e-40]));
/// assert_eq!(x.narrow().to_array(), [0.1, 2.0, -3.0, 1e-40]);
/// let m = x.gt(F64x4::splat(1.0));
/// assert_eq!(F64x4::mask_i32(m).to_array(), [0, -1, 0, 0]);
/// assert!(!F64x4::all(m) && F64x4::all(m | !m));
/// ```
pub trait Real4: Real {
    /// Widens four `f32` lanes, exactly.
    fn widen(x: f32x4) -> Self;
    /// Each lane rounded to `f32` (to nearest, ties to even, as `as f32`).
    fn narrow(self) -> f32x4;
    /// The mask as `i32` lanes: −1 where set, 0 where clear.
    fn mask_i32(m: Self::Mask) -> i32x4;
    /// Whether every lane of `m` is set.
    fn all(m: Self::Mask) -> bool;
    /// Four lanes from memory.
    fn load(x: &[f64; 4]) -> Self;
    /// `a` in the lanes of `m` set (−1), `b` where clear (0), on `f32`
    /// lanes of the same width as the mask's.
    #[inline(always)]
    fn blend_f32(m: i32x4, a: f32x4, b: f32x4) -> f32x4 {
        use wide::bytemuck::cast;
        cast(m.bitselect(cast(a), cast(b)))
    }
}

/// Two values of a lane type side by side, operated on together: eight
/// lanes from two four-lane packets. Each operation is the two operations
/// of `L`, so a lane gives the bits it gives in `L`; written as one
/// expression, the two packets' chains of dependent operations interleave,
/// which keeps more of the CPU's floating-point units busy.
///
/// ```
/// use rayoracle::num::real::{F64x4, Pair, Real};
/// let x = Pair(F64x4::splat(4.0), F64x4::splat(9.0));
/// let y = x.sqrt();
/// assert_eq!((y.0.to_array(), y.1.to_array()), ([2.0; 4], [3.0; 4]));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Pair<T>(pub T, pub T);

macro_rules! pairwise {
    ($tr:ident, $f:ident) => {
        impl<T: $tr<Output = T>> $tr for Pair<T> {
            type Output = Pair<T>;
            #[inline(always)]
            fn $f(self, o: Pair<T>) -> Pair<T> {
                Pair(self.0.$f(o.0), self.1.$f(o.1))
            }
        }
    };
}
pairwise!(Add, add);
pairwise!(Sub, sub);
pairwise!(Mul, mul);
pairwise!(Div, div);
pairwise!(BitAnd, bitand);
pairwise!(BitOr, bitor);

impl<T: Neg<Output = T>> Neg for Pair<T> {
    type Output = Pair<T>;
    #[inline(always)]
    fn neg(self) -> Pair<T> {
        Pair(-self.0, -self.1)
    }
}

impl<T: Not<Output = T>> Not for Pair<T> {
    type Output = Pair<T>;
    #[inline(always)]
    fn not(self) -> Pair<T> {
        Pair(!self.0, !self.1)
    }
}

impl<L: Real> Real for Pair<L> {
    const FEW_DIVISIONS: bool = L::FEW_DIVISIONS;
    #[inline(always)]
    fn denormals_are_zero() -> bool {
        L::denormals_are_zero()
    }
    #[inline(always)]
    fn least_subnormal() -> Pair<L> {
        let x = L::least_subnormal();
        Pair(x, x)
    }
    type Mask = Pair<L::Mask>;
    #[inline(always)]
    fn splat(x: f64) -> Pair<L> {
        Pair(L::splat(x), L::splat(x))
    }
    #[inline(always)]
    fn sqrt(self) -> Pair<L> {
        Pair(self.0.sqrt(), self.1.sqrt())
    }
    #[inline(always)]
    fn abs(self) -> Pair<L> {
        Pair(self.0.abs(), self.1.abs())
    }
    #[inline(always)]
    fn copysign(self, sign: Pair<L>) -> Pair<L> {
        Pair(self.0.copysign(sign.0), self.1.copysign(sign.1))
    }
    #[inline(always)]
    fn gt(self, other: Pair<L>) -> Pair<L::Mask> {
        Pair(self.0.gt(other.0), self.1.gt(other.1))
    }
    #[inline(always)]
    fn eq(self, other: Pair<L>) -> Pair<L::Mask> {
        Pair(self.0.eq(other.0), self.1.eq(other.1))
    }
    #[inline(always)]
    fn select(m: Pair<L::Mask>, a: Pair<L>, b: Pair<L>) -> Pair<L> {
        Pair(L::select(m.0, a.0, b.0), L::select(m.1, a.1, b.1))
    }
    #[inline(always)]
    fn same_f32(lo: Pair<L>, hi: Pair<L>) -> Pair<L::Mask> {
        Pair(L::same_f32(lo.0, hi.0), L::same_f32(lo.1, hi.1))
    }
    #[inline(always)]
    fn equal_f32(lo: Pair<L>, hi: Pair<L>) -> Pair<L::Mask> {
        Pair(L::equal_f32(lo.0, hi.0), L::equal_f32(lo.1, hi.1))
    }
    #[inline(always)]
    fn off_midpoint(self, m: i64) -> Pair<L::Mask> {
        Pair(self.0.off_midpoint(m), self.1.off_midpoint(m))
    }
}

/// Eight `f64` lanes that split into two [`Real4`] halves: the x4
/// kernels' batch paths run two packets at a time on one `Real8` and
/// finish each packet on its half. Implemented by [`Pair`] of any
/// [`Real4`] and, on x86-64, by the AVX-512 lanes of [`super::avx512`].
///
/// ```
/// use rayoracle::num::real::{F64x4, Pair, Real8};
/// use wide::f32x4;
/// let [o, ..] = Pair::<F64x4>::widen3(&[f32x4::splat(1.0); 3], &[f32x4::splat(2.0); 3]);
/// let [a, b] = o.halves();
/// assert_eq!((a.to_array(), b.to_array()), ([1.0; 4], [2.0; 4]));
/// ```
pub trait Real8: Real {
    /// The four-lane half.
    type Half: Real4;
    /// Two packets of three `f32x4` (a point or a direction of two
    /// [`crate::ray4::Ray4`]) widened side by side, `a` in the low half.
    fn widen3(a: &[f32x4; 3], b: &[f32x4; 3]) -> [Self; 3];
    /// The same four lanes in both halves.
    fn twice(x: Self::Half) -> Self;
    /// The low and the high half.
    fn halves(self) -> [Self::Half; 2];
    /// The low and the high half of a mask.
    fn mask_halves(m: Self::Mask) -> [<Self::Half as Real>::Mask; 2];
    /// Whether every lane of `m` is set.
    fn all(m: Self::Mask) -> bool;
}

impl<L: Real4> Real8 for Pair<L> {
    type Half = L;
    #[inline(always)]
    fn widen3(a: &[f32x4; 3], b: &[f32x4; 3]) -> [Pair<L>; 3] {
        let w = |x, y| Pair(L::widen(x), L::widen(y));
        [w(a[0], b[0]), w(a[1], b[1]), w(a[2], b[2])]
    }
    #[inline(always)]
    fn twice(x: L) -> Pair<L> {
        Pair(x, x)
    }
    #[inline(always)]
    fn halves(self) -> [L; 2] {
        [self.0, self.1]
    }
    #[inline(always)]
    fn mask_halves(m: Pair<L::Mask>) -> [L::Mask; 2] {
        [m.0, m.1]
    }
    #[inline(always)]
    fn all(m: Pair<L::Mask>) -> bool {
        L::all(m.0) && L::all(m.1)
    }
}

#[cfg(target_arch = "x86_64")]
mod sse2 {
    //! [`Real4`] for [`F64x4`] by SSE2 conversions, part of baseline x86-64
    //! (so the intrinsics are safe to call): `wide::f64x4` is two
    //! `__m128d`, or one `__m256d` where the build enables AVX, 32 bytes
    //! either way.
    use super::*;
    use safe_arch::{m128, m128d};
    use wide::bytemuck::cast;

    impl F64x4 {
        /// Four `i32` lanes, exactly (`cvtdq2pd`, never through memory).
        ///
        /// ```
        /// use rayoracle::num::real::F64x4;
        /// use wide::i32x4;
        /// let x = F64x4::from_i32(i32x4::from([1, -2, i32::MIN, i32::MAX]));
        /// assert_eq!(x.to_array(), [1.0, -2.0, -2147483648.0, 2147483647.0]);
        /// ```
        #[inline(always)]
        pub fn from_i32(x: i32x4) -> F64x4 {
            let v: safe_arch::m128i = cast(x);
            let hi = safe_arch::unpack_high_i64_m128i(v, v);
            let f = safe_arch::convert_to_m128d_from_lower2_i32_m128i;
            F64x4(cast([f(v), f(hi)]))
        }
    }

    impl Real4 for F64x4 {
        #[inline(always)]
        fn load(x: &[f64; 4]) -> F64x4 {
            F64x4::from(*x)
        }
        #[inline(always)]
        fn widen(x: f32x4) -> F64x4 {
            let v: m128 = cast(x);
            let hi = safe_arch::move_high_low_m128(v, v);
            let f = safe_arch::convert_to_m128d_from_lower2_m128;
            F64x4(cast([f(v), f(hi)]))
        }
        #[inline(always)]
        fn narrow(self) -> f32x4 {
            let [lo, hi]: [m128d; 2] = cast(self.0);
            let f = safe_arch::convert_to_m128_from_m128d;
            cast(safe_arch::move_low_high_m128(f(lo), f(hi)))
        }
        #[inline(always)]
        fn mask_i32(m: M4) -> i32x4 {
            let [lo, hi]: [m128; 2] = cast(m.0);
            cast(safe_arch::shuffle_abi_f32_all_m128::<0b10_00_10_00>(lo, hi))
        }
        #[inline(always)]
        fn all(m: M4) -> bool {
            m.0.to_bitmask() == 0b1111
        }
    }

    /// Where each lane of `x`, below `2³¹`, exceeds `k`: its low 32 bits
    /// compared, as SSE2 compares no 64-bit integers.
    #[inline(always)]
    pub(super) fn low_gt(x: i64x4, k: i32) -> M4 {
        let h: [safe_arch::m128i; 2] = cast(x);
        let k = safe_arch::set_splat_i32_m128i(k);
        let f = |v| {
            let low = safe_arch::shuffle_ai_f32_all_m128i::<0b10_10_00_00>(v);
            safe_arch::cmp_gt_mask_i32_m128i(low, k)
        };
        M4(cast([f(h[0]), f(h[1])]))
    }

    /// Each 32-bit mask lane repeated to 64 bits.
    #[inline(always)]
    pub(super) fn widen_mask(m: i32x4) -> M4 {
        let m: m128 = cast(m);
        let (lo, hi) = (
            safe_arch::unpack_low_m128(m, m),
            safe_arch::unpack_high_m128(m, m),
        );
        M4(cast([lo, hi]))
    }
}

#[cfg(not(target_arch = "x86_64"))]
mod portable {
    //! [`Real4`] for [`F64x4`] lane by lane, off x86-64.
    use super::*;

    impl F64x4 {
        /// Four `i32` lanes, exactly.
        #[inline(always)]
        pub fn from_i32(x: i32x4) -> F64x4 {
            F64x4::from(x.to_array().map(f64::from))
        }
    }

    impl Real4 for F64x4 {
        #[inline(always)]
        fn load(x: &[f64; 4]) -> F64x4 {
            F64x4::from(*x)
        }
        #[inline(always)]
        fn widen(x: f32x4) -> F64x4 {
            F64x4::from_f32(x.to_array())
        }
        #[inline(always)]
        fn narrow(self) -> f32x4 {
            f32x4::from(self.to_f32())
        }
        #[inline(always)]
        fn mask_i32(m: M4) -> i32x4 {
            i32x4::from(m.lanes().map(|b| -i32::from(b)))
        }
        #[inline(always)]
        fn all(m: M4) -> bool {
            m.all()
        }
    }

    /// Where each lane of `x` exceeds `k`.
    #[inline(always)]
    pub(super) fn low_gt(x: i64x4, k: i32) -> M4 {
        M4(wide::bytemuck::cast(x.simd_gt(i64x4::splat(k.into()))))
    }

    /// Each 32-bit mask lane repeated to 64 bits.
    #[inline(always)]
    pub(super) fn widen_mask(m: i32x4) -> M4 {
        M4(f64x4::from(
            m.to_array().map(|x| f64::from_bits(x as i64 as u64)),
        ))
    }
}

#[cfg(not(target_arch = "x86_64"))]
use portable::{low_gt, widen_mask};
#[cfg(target_arch = "x86_64")]
use sse2::{low_gt, widen_mask};

macro_rules! lanewise {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for F64x4 {
            type Output = F64x4;
            #[inline(always)]
            fn $f(self, o: F64x4) -> F64x4 {
                F64x4(self.0 $op o.0)
            }
        }
    };
}
lanewise!(Add, add, +);
lanewise!(Sub, sub, -);
lanewise!(Mul, mul, *);
lanewise!(Div, div, /);

impl Neg for F64x4 {
    type Output = F64x4;
    #[inline(always)]
    fn neg(self) -> F64x4 {
        F64x4(-self.0)
    }
}

macro_rules! maskwise {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for M4 {
            type Output = M4;
            #[inline(always)]
            fn $f(self, o: M4) -> M4 {
                M4(self.0 $op o.0)
            }
        }
    };
}
maskwise!(BitAnd, bitand, &);
maskwise!(BitOr, bitor, |);

impl Not for M4 {
    type Output = M4;
    #[inline(always)]
    fn not(self) -> M4 {
        M4(!self.0)
    }
}

impl M4 {
    /// Whether every lane is set.
    ///
    /// ```
    /// use rayoracle::num::real::{F64x4, Real};
    /// let x = F64x4::from([1.0, 2.0, 3.0, 4.0]);
    /// assert!(x.gt(F64x4::splat(0.0)).all() && !x.gt(F64x4::splat(1.0)).all());
    /// ```
    #[inline(always)]
    pub fn all(self) -> bool {
        self.0.to_bitmask() == 0b1111
    }
    /// `self` if `keep`, else no lane.
    ///
    /// ```
    /// use rayoracle::num::real::{F64x4, Real};
    /// let m = F64x4::splat(1.0).gt(F64x4::splat(0.0));
    /// assert_eq!((m.only_if(true).lanes(), m.only_if(false).lanes()), ([true; 4], [false; 4]));
    /// ```
    #[inline(always)]
    pub fn only_if(self, keep: bool) -> M4 {
        if keep { self } else { M4(f64x4::ZERO) }
    }
    /// The lanes as booleans.
    #[inline(always)]
    pub fn lanes(self) -> [bool; 4] {
        let m = self.0.to_bitmask();
        [0, 1, 2, 3].map(|i| m >> i & 1 == 1)
    }
}

impl Real for F64x4 {
    const FEW_DIVISIONS: bool = true;
    type Mask = M4;
    #[inline(always)]
    fn splat(x: f64) -> F64x4 {
        F64x4(f64x4::splat(x))
    }
    #[inline(always)]
    fn sqrt(self) -> F64x4 {
        F64x4(self.0.sqrt())
    }
    #[inline(always)]
    fn abs(self) -> F64x4 {
        F64x4(self.0.abs())
    }
    #[inline(always)]
    fn copysign(self, sign: F64x4) -> F64x4 {
        let s = f64x4::splat(-0.0);
        F64x4((self.0 & !s) | (sign.0 & s))
    }
    #[inline(always)]
    fn gt(self, other: F64x4) -> M4 {
        M4(self.0.simd_gt(other.0))
    }
    #[inline(always)]
    fn eq(self, other: F64x4) -> M4 {
        M4(self.0.simd_eq(other.0))
    }
    #[inline(always)]
    fn select(m: M4, a: F64x4, b: F64x4) -> F64x4 {
        F64x4(m.0.bitselect(a.0, b.0))
    }
    #[inline(always)]
    fn same_f32(lo: F64x4, hi: F64x4) -> M4 {
        // Equal as floats (so no NaN) and as bits (so not −0 against +0),
        // compared as four f32 lanes.
        let (a, b) = (lo.narrow(), hi.narrow());
        let bits: i32x4 = wide::bytemuck::cast::<f32x4, i32x4>(a)
            .simd_eq(wide::bytemuck::cast::<f32x4, i32x4>(b));
        widen_mask(bits & wide::bytemuck::cast::<f32x4, i32x4>(a.simd_eq(b)))
    }
    #[inline(always)]
    fn equal_f32(lo: F64x4, hi: F64x4) -> M4 {
        widen_mask(wide::bytemuck::cast(lo.narrow().simd_eq(hi.narrow())))
    }
    #[inline(always)]
    fn off_midpoint(self, m: i64) -> M4 {
        let b: i64x4 = wide::bytemuck::cast(self.0);
        let x = (b - i64x4::splat(MIDPOINT - m)) & i64x4::splat(DROPPED as i64);
        low_gt(x, m as i32 * 2)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The four-lane mask ops give, lane by lane, what `f64` gives; the
    /// zeros and NaN are the cases a float comparison gets wrong.
    #[test]
    fn lanes_agree_with_the_scalar_rules() {
        let xs = [0.0, -0.0, 1.0, -1.0, f64::NAN, 1e-40, -1e-40, 3.0];
        for &a in &xs {
            for &b in &xs {
                let (va, vb) = (F64x4::splat(a), F64x4::splat(b));
                let want = <f64 as Real>::same_f32(a, b);
                assert_eq!(F64x4::same_f32(va, vb).lanes(), [want; 4], "{a} {b}");
                let eq = a as f32 == b as f32;
                assert_eq!(<f64 as Real>::equal_f32(a, b), eq, "{a} {b}");
                assert_eq!(F64x4::equal_f32(va, vb).lanes(), [eq; 4], "{a} {b}");
                assert_eq!(va.gt(vb).lanes(), [a > b; 4], "{a} {b}");
                assert_eq!(va.eq(vb).lanes(), [a == b; 4], "{a} {b}");
                let c = F64x4::copysign(va, vb).to_array()[0];
                assert_eq!(c.to_bits(), a.copysign(b).to_bits(), "{a} {b}");
            }
        }
    }
}
