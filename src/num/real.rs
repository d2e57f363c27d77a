//! The [`Real`] trait: what a filtered kernel needs from its number type,
//! implemented for `f64` (the scalar reference) and [`F64x4`] (four lanes).
//!
//! Every operation is one correctly rounded IEEE-754 operation per lane, so
//! a lane of [`F64x4`] gives the bits `f64` gives, whatever target features
//! the build or the run-time dispatch enables.
//!
//! ```
//! use rayoracle::num::real::{F64x4, Real};
//! let x = F64x4::from([1.0, 4.0, 9.0, 16.0]);
//! assert_eq!(x.sqrt().0, [1.0, 2.0, 3.0, 4.0]);
//! assert_eq!(Real::sqrt(9.0f64), 3.0);
//! ```

use core::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

/// A lane type of f64 values: `f64` or [`F64x4`].
pub trait Real:
    Copy
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Neg<Output = Self>
{
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
}

impl Real for f64 {
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
}

/// Four `f64` lanes. Plain arrays, operated on lane by lane: LLVM turns each
/// operation into SSE2 pairs in a default build and into one AVX register
/// where the caller is compiled (or dispatched) for it.
///
/// ```
/// use rayoracle::num::real::F64x4;
/// let x = F64x4::from([1.0, 2.0, 3.0, 4.0]);
/// assert_eq!((x + x).0, [2.0, 4.0, 6.0, 8.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct F64x4(pub [f64; 4]);

/// Four lane masks.
///
/// ```
/// use rayoracle::num::real::{F64x4, M4, Real};
/// let m = F64x4::from([1.0, 2.0, 3.0, 4.0]).gt(F64x4::splat(2.5));
/// assert_eq!(m, M4([false, false, true, true]));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct M4(pub [bool; 4]);

impl From<[f64; 4]> for F64x4 {
    #[inline(always)]
    fn from(x: [f64; 4]) -> F64x4 {
        F64x4(x)
    }
}

impl F64x4 {
    /// Widens four `f32` lanes exactly.
    ///
    /// ```
    /// use rayoracle::num::real::F64x4;
    /// assert_eq!(F64x4::from_f32([0.1; 4]).0, [0.1f32 as f64; 4]);
    /// ```
    #[inline(always)]
    pub fn from_f32(x: [f32; 4]) -> F64x4 {
        F64x4(x.map(f64::from))
    }
    /// Each lane rounded to `f32`.
    ///
    /// ```
    /// use rayoracle::num::real::F64x4;
    /// assert_eq!(F64x4::from([0.1; 4]).to_f32(), [0.1f32; 4]);
    /// ```
    #[inline(always)]
    pub fn to_f32(self) -> [f32; 4] {
        self.0.map(|x| x as f32)
    }
}

macro_rules! lanewise {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for F64x4 {
            type Output = F64x4;
            #[inline(always)]
            fn $f(self, o: F64x4) -> F64x4 {
                let (a, b) = (self.0, o.0);
                F64x4([a[0] $op b[0], a[1] $op b[1], a[2] $op b[2], a[3] $op b[3]])
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
        F64x4(self.0.map(|x| -x))
    }
}

macro_rules! maskwise {
    ($tr:ident, $f:ident, $op:tt) => {
        impl $tr for M4 {
            type Output = M4;
            #[inline(always)]
            fn $f(self, o: M4) -> M4 {
                let (a, b) = (self.0, o.0);
                M4([a[0] $op b[0], a[1] $op b[1], a[2] $op b[2], a[3] $op b[3]])
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
        M4(self.0.map(|x| !x))
    }
}

impl M4 {
    /// Whether every lane is set.
    ///
    /// ```
    /// use rayoracle::num::real::M4;
    /// assert!(M4([true; 4]).all() && !M4([true, false, true, true]).all());
    /// ```
    #[inline(always)]
    pub fn all(self) -> bool {
        self.0[0] & self.0[1] & self.0[2] & self.0[3]
    }
}

#[inline(always)]
fn zip<T>(a: F64x4, b: F64x4, f: impl Fn(f64, f64) -> T) -> [T; 4] {
    [
        f(a.0[0], b.0[0]),
        f(a.0[1], b.0[1]),
        f(a.0[2], b.0[2]),
        f(a.0[3], b.0[3]),
    ]
}

impl Real for F64x4 {
    type Mask = M4;
    #[inline(always)]
    fn splat(x: f64) -> F64x4 {
        F64x4([x; 4])
    }
    #[inline(always)]
    fn sqrt(self) -> F64x4 {
        F64x4(self.0.map(f64::sqrt))
    }
    #[inline(always)]
    fn abs(self) -> F64x4 {
        F64x4(self.0.map(f64::abs))
    }
    #[inline(always)]
    fn copysign(self, sign: F64x4) -> F64x4 {
        F64x4(zip(self, sign, f64::copysign))
    }
    #[inline(always)]
    fn gt(self, other: F64x4) -> M4 {
        M4(zip(self, other, |a, b| a > b))
    }
    #[inline(always)]
    fn eq(self, other: F64x4) -> M4 {
        M4(zip(self, other, |a, b| a == b))
    }
    #[inline(always)]
    fn select(m: M4, a: F64x4, b: F64x4) -> F64x4 {
        let s = |i: usize| if m.0[i] { a.0[i] } else { b.0[i] };
        F64x4([s(0), s(1), s(2), s(3)])
    }
    #[inline(always)]
    fn same_f32(lo: F64x4, hi: F64x4) -> M4 {
        M4(zip(lo, hi, <f64 as Real>::same_f32))
    }
}
