//! Exact dyadic rationals `m · 2^e` over `dashu_int::IBig`.

use super::NonFinite;
use core::cmp::Ordering;
use core::ops::{Add, Mul, Neg, Sub};
use dashu_int::IBig;
use dashu_int::ops::{BitTest, UnsignedAbs};

/// An exact dyadic rational `mant · 2^exp`.
///
/// No normalisation is done: the value is what matters, and equality and
/// ordering compare values.
///
/// ```
/// use rayoracle::exact::Dyadic;
/// let x = Dyadic::from_f32(0.1);
/// let y = Dyadic::from_f32(0.2);
/// // 0.1f32 + 0.2f32 exactly, which is not 0.3f32:
/// assert_ne!(&x + &y, Dyadic::from_f32(0.3));
/// assert_eq!((&x + &y).to_f64(), 0.1f32 as f64 + 0.2f32 as f64);
/// ```
#[derive(Clone, Debug)]
pub struct Dyadic {
    mant: IBig,
    exp: i32,
}

impl Dyadic {
    /// Zero.
    pub const ZERO: Dyadic = Dyadic {
        mant: IBig::ZERO,
        exp: 0,
    };

    /// The exact value of a finite `f32`.
    ///
    /// # Panics
    /// If `x` is NaN or infinite; see [`Dyadic::try_from_f32`].
    ///
    /// ```
    /// use rayoracle::exact::Dyadic;
    /// assert_eq!(Dyadic::from_f32(-1.5), Dyadic::new(-3, -1));
    /// ```
    pub fn from_f32(x: f32) -> Dyadic {
        Self::try_from_f32(x).expect("Dyadic::from_f32 of a non-finite value")
    }

    /// The exact value of `x`, or [`NonFinite`] for NaN and ±∞.
    ///
    /// ```
    /// use rayoracle::exact::Dyadic;
    /// assert!(Dyadic::try_from_f32(f32::INFINITY).is_err());
    /// assert_eq!(Dyadic::try_from_f32(f32::from_bits(1)).unwrap(), Dyadic::new(1, -149));
    /// ```
    pub fn try_from_f32(x: f32) -> Result<Dyadic, NonFinite> {
        if !x.is_finite() {
            return Err(NonFinite);
        }
        let bits = x.to_bits();
        let biased = ((bits >> 23) & 0xff) as i32;
        let frac = (bits & 0x7f_ffff) as i64;
        let (m, e) = if biased == 0 {
            (frac, -149)
        } else {
            // The hidden bit (`+`, not `|`: the same value, as frac < 2²³,
            // but a mutation of it changes the result).
            (frac + 0x80_0000, biased - 150)
        };
        let m = if bits >> 31 == 1 { -m } else { m };
        Ok(Dyadic::new(m, e))
    }

    /// The exact value of a finite `f64`.
    ///
    /// ```
    /// use rayoracle::exact::Dyadic;
    /// assert_eq!(Dyadic::from_f64(0.75), Dyadic::new(3, -2));
    /// assert_eq!(Dyadic::from_f64(-0.75), Dyadic::new(-3, -2));
    /// // The smallest subnormal.
    /// assert_eq!(Dyadic::from_f64(f64::from_bits(1)), Dyadic::new(1, -1074));
    /// ```
    pub fn from_f64(x: f64) -> Dyadic {
        assert!(x.is_finite(), "Dyadic::from_f64 of a non-finite value");
        let bits = x.to_bits();
        let biased = ((bits >> 52) & 0x7ff) as i32;
        let frac = (bits & 0x000f_ffff_ffff_ffff) as i64;
        let (m, e) = if biased == 0 {
            (frac, -1074)
        } else {
            (frac + 0x0010_0000_0000_0000, biased - 1075)
        };
        Dyadic::new(if bits >> 63 == 1 { -m } else { m }, e)
    }

    /// `mant · 2^exp`.
    ///
    /// ```
    /// use rayoracle::exact::Dyadic;
    /// assert_eq!(Dyadic::new(5, 2).to_f64(), 20.0);
    /// ```
    pub fn new(mant: i64, exp: i32) -> Dyadic {
        Dyadic {
            mant: IBig::from(mant),
            exp,
        }
    }

    /// −1, 0 or 1.
    ///
    /// ```
    /// use rayoracle::exact::Dyadic;
    /// assert_eq!(Dyadic::new(-7, 100).signum(), -1);
    /// ```
    pub fn signum(&self) -> i32 {
        if self.mant.is_zero() {
            0
        } else if self.mant.sign() == dashu_int::Sign::Negative {
            -1
        } else {
            1
        }
    }

    /// Whether the value is zero.
    ///
    /// ```
    /// use rayoracle::exact::Dyadic;
    /// assert!(Dyadic::new(0, 17).is_zero());
    /// ```
    pub fn is_zero(&self) -> bool {
        self.mant.is_zero()
    }

    /// `self · 2^k`, exact.
    ///
    /// ```
    /// use rayoracle::exact::Dyadic;
    /// assert_eq!(Dyadic::new(3, 0).mul_pow2(-1), Dyadic::new(3, -1));
    /// ```
    pub fn mul_pow2(&self, k: i32) -> Dyadic {
        Dyadic {
            mant: self.mant.clone(),
            exp: self.exp + k,
        }
    }

    /// The nearest `f64` (an approximation for starting guesses and reports;
    /// never used to decide anything). Saturates to ±∞ and flushes to ±0.
    ///
    /// ```
    /// use rayoracle::exact::Dyadic;
    /// assert_eq!(Dyadic::new(1, -1).to_f64(), 0.5);
    /// ```
    pub fn to_f64(&self) -> f64 {
        if self.mant.is_zero() {
            return 0.0;
        }
        // Keep the leading 64 bits; truncating the rest costs < 2^-63.
        let len = BitTest::bit_len(&UnsignedAbs::unsigned_abs(self.mant.clone())) as i64;
        let drop = (len - 64).max(0);
        let top = (&self.mant >> drop as usize).to_f64().value();
        ldexp_f64(top, self.exp as i64 + drop)
    }
}

/// `x · 2^e` in f64 without intermediate overflow or underflow.
fn ldexp_f64(mut x: f64, mut e: i64) -> f64 {
    while e > 1000 {
        x *= 2f64.powi(1000);
        e -= 1000;
        if x.is_infinite() {
            return x;
        }
    }
    while e < -1000 {
        x *= 2f64.powi(-1000);
        e += 1000;
        if x == 0.0 {
            return x;
        }
    }
    x * 2f64.powi(e as i32)
}

impl PartialEq for Dyadic {
    fn eq(&self, other: &Self) -> bool {
        self.cmp(other) == Ordering::Equal
    }
}

impl Eq for Dyadic {}

impl PartialOrd for Dyadic {
    fn partial_cmp(&self, other: &Self) -> Option<Ordering> {
        Some(self.cmp(other))
    }
}

impl Ord for Dyadic {
    fn cmp(&self, other: &Self) -> Ordering {
        match self.exp.cmp(&other.exp) {
            Ordering::Equal => self.mant.cmp(&other.mant),
            Ordering::Greater => (&self.mant << (self.exp - other.exp) as usize).cmp(&other.mant),
            Ordering::Less => self
                .mant
                .cmp(&(&other.mant << (other.exp - self.exp) as usize)),
        }
    }
}

impl Add for &Dyadic {
    type Output = Dyadic;
    fn add(self, o: &Dyadic) -> Dyadic {
        // Shift only the operand with the larger exponent; borrow the other.
        match self.exp.cmp(&o.exp) {
            Ordering::Equal => Dyadic {
                mant: &self.mant + &o.mant,
                exp: self.exp,
            },
            Ordering::Greater => Dyadic {
                mant: (&self.mant << (self.exp - o.exp) as usize) + &o.mant,
                exp: o.exp,
            },
            Ordering::Less => Dyadic {
                mant: &self.mant + (&o.mant << (o.exp - self.exp) as usize),
                exp: self.exp,
            },
        }
    }
}

impl Sub for &Dyadic {
    type Output = Dyadic;
    fn sub(self, o: &Dyadic) -> Dyadic {
        match self.exp.cmp(&o.exp) {
            Ordering::Equal => Dyadic {
                mant: &self.mant - &o.mant,
                exp: self.exp,
            },
            Ordering::Greater => Dyadic {
                mant: (&self.mant << (self.exp - o.exp) as usize) - &o.mant,
                exp: o.exp,
            },
            Ordering::Less => Dyadic {
                mant: &self.mant - (&o.mant << (o.exp - self.exp) as usize),
                exp: self.exp,
            },
        }
    }
}

impl Mul for &Dyadic {
    type Output = Dyadic;
    fn mul(self, o: &Dyadic) -> Dyadic {
        Dyadic {
            mant: &self.mant * &o.mant,
            exp: self.exp + o.exp,
        }
    }
}

impl Neg for &Dyadic {
    type Output = Dyadic;
    fn neg(self) -> Dyadic {
        Dyadic {
            mant: -&self.mant,
            exp: self.exp,
        }
    }
}

macro_rules! owned_ops {
    ($($tr:ident $f:ident),*) => {$(
        impl core::ops::$tr for Dyadic {
            type Output = Dyadic;
            fn $f(self, o: Dyadic) -> Dyadic { (&self).$f(&o) }
        }
        impl core::ops::$tr<&Dyadic> for Dyadic {
            type Output = Dyadic;
            fn $f(self, o: &Dyadic) -> Dyadic { (&self).$f(o) }
        }
    )*};
}
owned_ops!(Add add, Sub sub, Mul mul);

impl Neg for Dyadic {
    type Output = Dyadic;
    fn neg(self) -> Dyadic {
        Dyadic {
            mant: -self.mant,
            exp: self.exp,
        }
    }
}

/// The exact dot product of two 3-vectors of dyadics.
///
/// ```
/// use rayoracle::exact::{Dyadic, dyadic::dot};
/// let a = [1.0f32, 2.0, 3.0].map(Dyadic::from_f32);
/// assert_eq!(dot(&a, &a), Dyadic::new(14, 0));
/// ```
pub fn dot(a: &[Dyadic; 3], b: &[Dyadic; 3]) -> Dyadic {
    &(&(&a[0] * &b[0]) + &(&a[1] * &b[1])) + &(&a[2] * &b[2])
}

/// The exact values of an `f32` 3-vector, or [`NonFinite`].
///
/// ```
/// use rayoracle::exact::dyadic::vec3;
/// assert!(vec3([1.0, f32::NAN, 0.0]).is_err());
/// ```
pub fn vec3(v: [f32; 3]) -> Result<[Dyadic; 3], NonFinite> {
    Ok([
        Dyadic::try_from_f32(v[0])?,
        Dyadic::try_from_f32(v[1])?,
        Dyadic::try_from_f32(v[2])?,
    ])
}

/// `a − b`, exactly, component-wise.
///
/// ```
/// use rayoracle::exact::{Dyadic, dyadic::sub3};
/// let a = [3.0f32, 2.0, 1.0].map(Dyadic::from_f32);
/// assert_eq!(sub3(&a, &a)[1], Dyadic::ZERO);
/// ```
pub fn sub3(a: &[Dyadic; 3], b: &[Dyadic; 3]) -> [Dyadic; 3] {
    [&a[0] - &b[0], &a[1] - &b[1], &a[2] - &b[2]]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `to_f64` scales in steps of 2¹⁰⁰⁰ so that neither the scale factor
    /// nor an `i32` exponent overflows; each case below fails if a step is
    /// skipped, reversed or taken the wrong way.
    #[test]
    fn to_f64_at_the_ends_of_the_range() {
        assert_eq!(Dyadic::new(1, 1023).to_f64(), 2f64.powi(1023));
        assert_eq!(Dyadic::new(3, 1022).to_f64(), 1.5 * 2f64.powi(1023));
        assert_eq!(Dyadic::new(1, 5000).to_f64(), f64::INFINITY);
        assert_eq!(Dyadic::new(-1, 5000).to_f64(), f64::NEG_INFINITY);
        // 1.5 · 2⁻¹⁰⁷⁴ rounds (to even) to the second subnormal.
        assert_eq!(Dyadic::new(3, -1075).to_f64(), f64::from_bits(2));
        assert_eq!(Dyadic::new(1, -1074).to_f64(), f64::from_bits(1));
        assert_eq!(Dyadic::new(1, -1100).to_f64(), 0.0);
        assert_eq!(Dyadic::new(-1, -5000).to_f64(), 0.0);
        // A 126-bit mantissa at the largest exponent: the exponent of its
        // top 64 bits no longer fits in an i32.
        let big = &Dyadic::new(i64::MAX, i32::MAX) * &Dyadic::new(i64::MAX, 0);
        assert_eq!(big.to_f64(), f64::INFINITY);
    }

    #[test]
    fn f32_round_trips_through_f64() {
        for x in [
            0.0f32,
            -0.0,
            1.0,
            -3.5,
            f32::MAX,
            f32::MIN_POSITIVE,
            f32::from_bits(1),
            1e-40,
            123456.79,
        ] {
            assert_eq!(Dyadic::from_f32(x).to_f64(), x as f64, "{x:e}");
            assert_eq!(Dyadic::from_f64(x as f64), Dyadic::from_f32(x));
        }
    }

    #[test]
    fn arithmetic_is_exact() {
        let a = Dyadic::from_f32(f32::MAX);
        let b = Dyadic::from_f32(f32::from_bits(1));
        let s = &(&a + &b) - &a;
        assert_eq!(s, b);
        assert_eq!((&a * &b).signum(), 1);
        assert_eq!((&b * &b).to_f64(), 2f64.powi(-298));
        assert!(a > b && -&a < b);
    }
}
