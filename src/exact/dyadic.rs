//! Exact dyadic rationals `m · 2^e`: the mantissa is an `i128` or a 256-bit
//! integer on the stack while it fits and a `dashu_int::IBig` beyond that.

use super::NonFinite;
use super::expansion::{self, Expansion};
use super::wide::{self, Wide};
use core::cmp::Ordering;
use core::ops::{Add, Mul, Neg, Sub};
use dashu_int::IBig;
use dashu_int::ops::{BitTest, UnsignedAbs};

/// An exact dyadic rational `mant · 2^exp`.
///
/// The representation is not canonical (a mantissa on the stack has its
/// trailing zero bits moved into the exponent, a big one need not): the
/// value is what matters, and equality and ordering compare values.
///
/// ```
/// use rayoracle::exact::Dyadic;
/// let x = Dyadic::from_f32(0.1);
/// let y = Dyadic::from_f32(0.2);
/// // 0.1f32 + 0.2f32 exactly, which is not 0.3f32:
/// assert_ne!(&x + &y, Dyadic::from_f32(0.3));
/// assert_eq!((&x + &y).to_f64(), 0.1f32 as f64 + 0.2f32 as f64);
/// ```
#[derive(Clone)]
pub struct Dyadic {
    mant: Mant,
    exp: i32,
}

/// A mantissa in the narrowest of three widths that holds its odd part
/// (every result is stored so): `i128`, 256 bits, or a big integer.
#[derive(Clone)]
enum Mant {
    Small(i128),
    Wide(Wide),
    Big(IBig),
}

impl core::fmt::Debug for Dyadic {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let mut d = f.debug_struct("Dyadic");
        match &self.mant {
            Mant::Small(m) => d.field("mant", m),
            Mant::Wide(m) => d.field("mant", &format_args!("{}", wide::to_ibig(*m))),
            Mant::Big(m) => d.field("mant", &format_args!("{m}")),
        };
        d.field("exp", &self.exp).finish()
    }
}

impl Dyadic {
    /// Zero.
    pub const ZERO: Dyadic = Dyadic {
        mant: Mant::Small(0),
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
        Dyadic::small(mant.into(), exp)
    }

    /// `m · 2^e` with the trailing zero bits of `m` moved into the exponent
    /// (as far as an `i32` allows); zero is `0 · 2^0`.
    fn small(m: i128, e: i32) -> Dyadic {
        if m == 0 {
            return Dyadic::ZERO;
        }
        let tz = m.trailing_zeros();
        match e.checked_add(tz as i32) {
            Some(exp) => Dyadic {
                mant: Mant::Small(m >> tz),
                exp,
            },
            None => Dyadic {
                mant: Mant::Small(m),
                exp: e,
            },
        }
    }

    /// `m · 2^e` with the trailing zero bits of `m` moved into the exponent
    /// (as far as an `i32` allows), in an `i128` if it then fits.
    fn wide(m: Wide, e: i32) -> Dyadic {
        if m.is_zero() {
            return Dyadic::ZERO;
        }
        let tz = m.trailing_zeros();
        let (m, e) = match e.checked_add(tz as i32) {
            Some(exp) if tz > 0 => (m >> tz, exp),
            _ => (m, e),
        };
        match wide::to_i128(m) {
            Some(s) => Dyadic::small(s, e),
            None => Dyadic {
                mant: Mant::Wide(m),
                exp: e,
            },
        }
    }

    /// `m · 2^e`, on the stack if its odd part fits in 255 bits.
    fn big(m: IBig, e: i32) -> Dyadic {
        if let Ok(s) = i128::try_from(&m) {
            return Dyadic::small(s, e);
        }
        let tz = m.trailing_zeros().unwrap_or(0);
        if m.bit_len() - tz <= wide::BITS as usize
            && let Some(exp) = e.checked_add(tz as i32)
        {
            let odd = wide::from_ibig(&(&m >> tz)).expect("255 bits fit");
            return Dyadic::wide(odd, exp);
        }
        Dyadic {
            mant: Mant::Big(m),
            exp: e,
        }
    }

    /// The `i128` mantissa, if the value has one (never in a test run
    /// inside `tests::big_only`, which checks the fixed-width arithmetic
    /// against the big-integer one).
    fn fixed(&self) -> Option<i128> {
        #[cfg(test)]
        if tests::BIG_ONLY.with(core::cell::Cell::get) {
            return None;
        }
        match self.mant {
            Mant::Small(m) => Some(m),
            _ => None,
        }
    }

    /// The mantissa as a 256-bit integer, if it is one or an `i128` (with
    /// the same exception as [`Dyadic::fixed`]).
    fn wide_mant(&self) -> Option<Wide> {
        #[cfg(test)]
        if tests::BIG_ONLY.with(core::cell::Cell::get) {
            return None;
        }
        match self.mant {
            Mant::Small(m) => Some(wide::from_i128(m)),
            Mant::Wide(m) => Some(m),
            Mant::Big(_) => None,
        }
    }

    /// The mantissa as a big integer.
    fn ibig(&self) -> std::borrow::Cow<'_, IBig> {
        match &self.mant {
            Mant::Small(m) => std::borrow::Cow::Owned(IBig::from(*m)),
            Mant::Wide(m) => std::borrow::Cow::Owned(wide::to_ibig(*m)),
            Mant::Big(m) => std::borrow::Cow::Borrowed(m),
        }
    }

    /// The exact value of an expansion (the sum of its components).
    ///
    /// ```
    /// use rayoracle::exact::{Dyadic, expansion::Expansion};
    /// let e = Expansion::from_f64(1e-30).grow(1e30).unwrap();
    /// assert_eq!(Dyadic::from_expansion(&e), &Dyadic::from_f64(1e30) + &Dyadic::from_f64(1e-30));
    /// ```
    pub fn from_expansion(e: &Expansion) -> Dyadic {
        let parts = || e.components().iter().map(|&x| f64_parts(x));
        match e.components() {
            [] => Dyadic::ZERO,
            &[x] => {
                let (m, e) = f64_parts(x);
                Dyadic::small(m, e)
            }
            c => sum_parts(parts, c.len()).unwrap_or_else(|| {
                parts().fold(Dyadic::ZERO, |acc, (m, e)| &acc + &Dyadic::small(m, e))
            }),
        }
    }

    /// The value as an [`Expansion`], if its lowest set bit is at
    /// `2^expansion::LOW` or above and its magnitude below
    /// `2^expansion::HIGH`, and it has at most `expansion::CAP` nonzero
    /// 32-bit chunks (never inside `tests::big_only`). Each chunk of the
    /// mantissa's magnitude is one component: exact, as it has 32 bits and
    /// its scale is in the normal range, and nonoverlapping with the
    /// others, as the chunks are disjoint bit ranges, lowest first.
    pub(crate) fn expansion(&self) -> Option<Expansion> {
        #[cfg(test)]
        if tests::BIG_ONLY.with(core::cell::Cell::get) {
            return None;
        }
        let mut words = [0u64; 32];
        let (negative, n) = match &self.mant {
            Mant::Small(m) => {
                let a = m.unsigned_abs();
                words[..2].copy_from_slice(&[a as u64, (a >> 64) as u64]);
                (*m < 0, 2)
            }
            Mant::Wide(m) => {
                let bytes = m.unsigned_abs().to_le_bytes();
                for (w, b) in words.iter_mut().zip(bytes.chunks_exact(8)) {
                    *w = u64::from_le_bytes(b.try_into().expect("8 bytes"));
                }
                (m.is_negative(), 4)
            }
            Mant::Big(m) => {
                let (sign, w) = m.as_sign_words();
                words.get_mut(..w.len())?.copy_from_slice(w);
                (sign == dashu_int::Sign::Negative, w.len())
            }
        };
        let mut out = Expansion::ZERO;
        for (i, &w) in words[..n].iter().enumerate() {
            for (j, chunk) in [w & 0xffff_ffff, w >> 32].into_iter().enumerate() {
                if chunk == 0 {
                    continue;
                }
                let at = self.exp as i64 + 64 * i as i64 + 32 * j as i64;
                let low = at + chunk.trailing_zeros() as i64;
                if low < expansion::LOW as i64 || at + 32 > expansion::HIGH as i64 {
                    return None;
                }
                let x = chunk as f64 * pow2(at as i32);
                out.push(if negative { -x } else { x })?;
            }
        }
        Some(out)
    }

    /// −1, 0 or 1.
    ///
    /// ```
    /// use rayoracle::exact::Dyadic;
    /// assert_eq!(Dyadic::new(-7, 100).signum(), -1);
    /// ```
    pub fn signum(&self) -> i32 {
        if let Some(m) = self.fixed() {
            return m.signum() as i32;
        }
        if let Some(m) = self.wide_mant() {
            return wide::signum(m);
        }
        let m = self.ibig();
        if m.is_zero() {
            0
        } else if m.sign() == dashu_int::Sign::Negative {
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
        self.signum() == 0
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
        // Keep the leading 64 bits (rounded down); dropping the rest costs
        // < 2^-63. The value alone decides the result, whatever the
        // representation: the kept bits and the scale are the same.
        // (top bits, bits dropped), an `i128` mantissa without a 256-bit
        // conversion.
        let top = if let Some(m) = self.fixed() {
            let drop = (128 - m.unsigned_abs().leading_zeros()).saturating_sub(64);
            Some((m >> drop, drop))
        } else if let Some(m) = self.wide_mant() {
            let drop = wide::len(m).saturating_sub(64);
            Some((wide::to_i128(m >> drop).expect("64 bits"), drop))
        } else {
            None
        };
        if let Some((top, drop)) = top {
            if top == 0 {
                return 0.0;
            }
            // u64 → f64 rounds as i128 → f64 does (to nearest, ties to
            // even, the same for either sign), without a library call.
            let top = u64::try_from(top.unsigned_abs())
                .map_or(top as f64, |t| if top < 0 { -(t as f64) } else { t as f64 });
            return ldexp_f64(top, self.exp as i64 + drop as i64);
        }
        let m = self.ibig();
        if m.is_zero() {
            return 0.0;
        }
        let len = BitTest::bit_len(&UnsignedAbs::unsigned_abs(m.as_ref().clone())) as i64;
        let drop = (len - 64).max(0);
        let top = (m.as_ref() >> drop as usize).to_f64().value();
        ldexp_f64(top, self.exp as i64 + drop)
    }
}

/// A finite `f64` as `(m, e)` with value `m · 2^e`.
fn f64_parts(x: f64) -> (i128, i32) {
    let bits = x.to_bits();
    let biased = ((bits >> 52) & 0x7ff) as i32;
    let frac = (bits & 0x000f_ffff_ffff_ffff) as i128;
    let (m, e) = if biased == 0 {
        (frac, -1074)
    } else {
        (frac + 0x0010_0000_0000_0000, biased - 1075)
    };
    (if bits >> 63 == 1 { -m } else { m }, e)
}

/// `x · 2^e` in f64 without intermediate overflow or underflow.
fn ldexp_f64(mut x: f64, mut e: i64) -> f64 {
    while e > 1000 {
        x *= pow2(1000);
        e -= 1000;
        if x.is_infinite() {
            return x;
        }
    }
    while e < -1000 {
        x *= pow2(-1000);
        e += 1000;
        if x == 0.0 {
            return x;
        }
    }
    x * pow2(e as i32)
}

/// `2^e` for `|e| ≤ 1000`, from its bits (the value `2f64.powi(e)` has,
/// without its library call).
fn pow2(e: i32) -> f64 {
    debug_assert!((-1000..=1000).contains(&e));
    f64::from_bits(((e + 1023) as u64) << 52)
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
        if let (Some(a), Some(b)) = (self.fixed(), other.fixed()) {
            return cmp_fixed(a, self.exp, b, other.exp);
        }
        cmp_wider(self, other)
    }
}

/// [`Ord::cmp`] for a mantissa wider than an `i128`, out of line so that
/// the `i128` path stays short.
#[cold]
#[inline(never)]
fn cmp_wider(this: &Dyadic, other: &Dyadic) -> Ordering {
    if let (Some(a), Some(b)) = (this.wide_mant(), other.wide_mant()) {
        return cmp_wide(a, this.exp, b, other.exp);
    }
    // By sign and the place of the leading bit first, which spares the
    // long shifts of far-apart exponents.
    let (sa, sb) = (this.signum(), other.signum());
    if sa != sb || sa == 0 {
        return sa.cmp(&sb);
    }
    let top = |x: &Dyadic| {
        let len = match &x.mant {
            Mant::Small(m) => 128 - m.unsigned_abs().leading_zeros() as usize,
            Mant::Wide(m) => wide::len(*m) as usize,
            Mant::Big(m) => m.bit_len(),
        };
        x.exp as i64 + len as i64
    };
    let mag = top(this).cmp(&top(other));
    if mag != Ordering::Equal {
        return if sa > 0 { mag } else { mag.reverse() };
    }
    let (a, b) = (this.ibig(), other.ibig());
    match this.exp.cmp(&other.exp) {
        Ordering::Equal => a.cmp(&b),
        Ordering::Greater => (a.as_ref() << (this.exp - other.exp) as usize).cmp(&b),
        Ordering::Less => a
            .as_ref()
            .cmp(&(b.as_ref() << (other.exp - this.exp) as usize)),
    }
}

/// `a·2^ea` against `b·2^eb` without overflow: by sign, then by the place
/// of the leading bit, and only for equal places (where the shift is short
/// and cannot overflow a `u128`) by the aligned magnitudes.
fn cmp_fixed(a: i128, ea: i32, b: i128, eb: i32) -> Ordering {
    let (sa, sb) = (a.signum(), b.signum());
    if sa != sb || sa == 0 {
        return sa.cmp(&sb);
    }
    let (ma, mb) = (a.unsigned_abs(), b.unsigned_abs());
    let top = |m: u128, e: i32| e as i64 + (128 - m.leading_zeros()) as i64;
    let mag = match top(ma, ea).cmp(&top(mb, eb)) {
        Ordering::Equal if ea >= eb => (ma << (ea - eb)).cmp(&mb),
        Ordering::Equal => ma.cmp(&(mb << (eb - ea))),
        unequal => unequal,
    };
    if sa > 0 { mag } else { mag.reverse() }
}

/// [`cmp_fixed`] on 256-bit mantissas.
fn cmp_wide(a: Wide, ea: i32, b: Wide, eb: i32) -> Ordering {
    let (sa, sb) = (wide::signum(a), wide::signum(b));
    if sa != sb || sa == 0 {
        return sa.cmp(&sb);
    }
    let top = |m: Wide, e: i32| e as i64 + wide::len(m) as i64;
    // Equal leading places: the shift is below 255 and the shifted
    // mantissa as long as the other.
    let aligned = |m: Wide, s: i32| wide::shl(m, s as u32).expect("aligned mantissas fit");
    match top(a, ea).cmp(&top(b, eb)) {
        Ordering::Equal if ea >= eb => aligned(a, ea - eb).cmp(&b),
        Ordering::Equal => a.cmp(&aligned(b, eb - ea)),
        unequal if sa > 0 => unequal,
        unequal => unequal.reverse(),
    }
}

/// `m · 2^s` if it fits in an `i128`.
fn shl_fixed(m: i128, s: i64) -> Option<i128> {
    let r = m.checked_shl(u32::try_from(s).ok()?)?;
    (r >> s == m).then_some(r)
}

/// `a·2^ea − b·2^eb` if `SUB`, else the sum, on `i128` mantissas, if the
/// aligned operands and the result fit. A zero operand takes the other's
/// exponent, so it never needs a shift.
fn add_fixed<const SUB: bool>((a, ea): (i128, i32), (b, eb): (i128, i32)) -> Option<Dyadic> {
    let (ea, eb) = match (a, b) {
        (0, _) => (eb, eb),
        (_, 0) => (ea, ea),
        _ => (ea, eb),
    };
    let d = ea as i64 - eb as i64;
    let (a, b, e) = match d.cmp(&0) {
        Ordering::Equal => (a, b, ea),
        Ordering::Greater => (shl_fixed(a, d)?, b, eb),
        Ordering::Less => (a, shl_fixed(b, -d)?, ea),
    };
    let r = if SUB {
        a.checked_sub(b)
    } else {
        a.checked_add(b)
    };
    Some(Dyadic::small(r?, e))
}

/// `a·2^ea + b·2^eb` on 256-bit mantissas, if the aligned operands and the
/// sum fit; a zero operand takes the other's exponent, as in [`add_fixed`].
fn add_wide((a, ea): (Wide, i32), (b, eb): (Wide, i32)) -> Option<Dyadic> {
    let (ea, eb) = match (a.is_zero(), b.is_zero()) {
        (true, _) => (eb, eb),
        (_, true) => (ea, ea),
        _ => (ea, eb),
    };
    let d = ea as i64 - eb as i64;
    let shift = |m: Wide, d: i64| wide::shl(m, u32::try_from(d).ok()?);
    let (a, b, e) = match d.cmp(&0) {
        Ordering::Equal => (a, b, ea),
        Ordering::Greater => (shift(a, d)?, b, eb),
        Ordering::Less => (a, shift(b, -d)?, ea),
    };
    Some(Dyadic::wide(wide::add(a, b)?, e))
}

/// `x − y` if `SUB`, else `x + y`: on `i128` mantissas when they fit,
/// else on 256-bit ones, else on big integers, shifting only the operand with the larger exponent.
fn add_or_sub<const SUB: bool>(x: &Dyadic, y: &Dyadic) -> Dyadic {
    if let (Some(a), Some(b)) = (x.fixed(), y.fixed())
        && let Some(r) = add_fixed::<SUB>((a, x.exp), (b, y.exp))
    {
        #[cfg(test)]
        tests::count_sum(0);
        return r;
    }
    add_or_sub_wider::<SUB>(x, y)
}

/// [`add_or_sub`] once the `i128` mantissas do not do, out of line.
#[cold]
#[inline(never)]
fn add_or_sub_wider<const SUB: bool>(x: &Dyadic, y: &Dyadic) -> Dyadic {
    if let (Some(a), Some(b)) = (x.wide_mant(), y.wide_mant())
        && let Some(r) = add_wide((a, x.exp), (if SUB { -b } else { b }, y.exp))
    {
        #[cfg(test)]
        tests::count_sum(1);
        return r;
    }
    let (a, b) = (x.ibig(), y.ibig());
    let (a, b, e) = match x.exp.cmp(&y.exp) {
        Ordering::Equal => (a, b, x.exp),
        Ordering::Greater => (
            std::borrow::Cow::Owned(a.as_ref() << (x.exp - y.exp) as usize),
            b,
            y.exp,
        ),
        Ordering::Less => (
            a,
            std::borrow::Cow::Owned(b.as_ref() << (y.exp - x.exp) as usize),
            x.exp,
        ),
    };
    let m = if SUB {
        a.as_ref() - b.as_ref()
    } else {
        a.as_ref() + b.as_ref()
    };
    #[cfg(test)]
    tests::count_sum(2);
    Dyadic::big(m, e)
}

impl Add for &Dyadic {
    type Output = Dyadic;
    fn add(self, o: &Dyadic) -> Dyadic {
        add_or_sub::<false>(self, o)
    }
}

impl Sub for &Dyadic {
    type Output = Dyadic;
    fn sub(self, o: &Dyadic) -> Dyadic {
        add_or_sub::<true>(self, o)
    }
}

impl Mul for &Dyadic {
    type Output = Dyadic;
    fn mul(self, o: &Dyadic) -> Dyadic {
        #[cfg(test)]
        tests::PRODUCTS.with(|n| n.set(n.get() + 1));
        let exp = self.exp + o.exp;
        if let (Some(a), Some(b)) = (self.fixed(), o.fixed()) {
            // Below 2^127 by the lengths alone; else the checked product.
            let len = |m: i128| 128 - m.unsigned_abs().leading_zeros();
            let p = if len(a) + len(b) <= 127 {
                Some(a.wrapping_mul(b))
            } else {
                a.checked_mul(b)
            };
            if let Some(p) = p {
                return Dyadic::small(p, exp);
            }
        }
        mul_wider(self, o, exp)
    }
}

/// `x · y = m · 2^exp` once the `i128` mantissas do not do, out of line.
#[cold]
#[inline(never)]
fn mul_wider(x: &Dyadic, y: &Dyadic, exp: i32) -> Dyadic {
    if let (Some(a), Some(b)) = (x.wide_mant(), y.wide_mant())
        && let Some(p) = wide::mul(a, b)
    {
        return Dyadic::wide(p, exp);
    }
    Dyadic::big(x.ibig().as_ref() * y.ibig().as_ref(), exp)
}

impl Neg for &Dyadic {
    type Output = Dyadic;
    fn neg(self) -> Dyadic {
        if let Some(m) = self.fixed().and_then(i128::checked_neg) {
            return Dyadic {
                mant: Mant::Small(m),
                exp: self.exp,
            };
        }
        if let Some(m) = self.wide_mant() {
            return Dyadic::wide(-m, self.exp);
        }
        Dyadic::big(-self.ibig().as_ref(), self.exp)
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
        -&self
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
    sum(&[&a[0] * &b[0], &a[1] * &b[1], &a[2] * &b[2]])
}

/// Limbs of [`sum`]'s accumulator: 2048 bits, enough for any sum of
/// products of up to four f32 values (their exponents span under 1,200
/// bits).
const ACC_LIMBS: usize = 32;

/// The exact sum of dyadics. Where every mantissa is an `i128` and the
/// terms span at most 2,040 bits, they are added into one two's-complement
/// accumulator on the stack, aligned at the smallest exponent, and only
/// the total is normalised: no intermediate sum is formed, stored wide or
/// allocated. Otherwise the terms are added in turn.
///
/// ```
/// use rayoracle::exact::{Dyadic, dyadic::sum};
/// let t = [Dyadic::new(3, 400), Dyadic::new(-1, -300), Dyadic::new(-3, 400)];
/// assert_eq!(sum(&t), Dyadic::new(-1, -300));
/// assert_eq!(sum(&[]), Dyadic::ZERO);
/// ```
pub fn sum(terms: &[Dyadic]) -> Dyadic {
    sum_fixed(terms).unwrap_or_else(|| terms.iter().fold(Dyadic::ZERO, |acc, x| &acc + x))
}

/// [`sum`] on the stack accumulator, if the terms allow it: an `i128`
/// where the aligned total has room in one, else limbs.
fn sum_fixed(terms: &[Dyadic]) -> Option<Dyadic> {
    if !terms.iter().all(|t| t.fixed().is_some()) {
        return None;
    }
    let parts = || terms.iter().map(|t| (t.fixed().unwrap_or(0), t.exp));
    sum_parts(parts, terms.len())
}

/// The exact sum of the `len` parts `(m, e)`, each `m · 2^e`, that `parts`
/// gives (it is called twice), on the stack accumulator, if they span at
/// most 2,040 bits and number at most 64.
fn sum_parts<I: Iterator<Item = (i128, i32)>>(parts: impl Fn() -> I, len: usize) -> Option<Dyadic> {
    let mut lo = i64::MAX;
    let mut hi = i64::MIN;
    for (m, e) in parts() {
        if m != 0 {
            lo = lo.min(e as i64);
            hi = hi.max(e as i64 + 128 - m.unsigned_abs().leading_zeros() as i64);
        }
    }
    if lo == i64::MAX {
        return Some(Dyadic::ZERO);
    }
    // Room for the terms, the carries of up to 2⁶ of them, and the sign.
    if hi - lo + 8 > (ACC_LIMBS * 64) as i64 || len > 64 {
        return None;
    }
    let width = (hi - lo + 8) as usize;
    if width <= 127 {
        // The aligned terms and their total fit in an i128 as they are.
        let mut total = 0i128;
        for (m, e) in parts() {
            if m != 0 {
                total += m << (e as i64 - lo);
            }
        }
        return Some(Dyadic::small(total, i32::try_from(lo).ok()?));
    }
    let mut full = [0u64; ACC_LIMBS];
    let acc = &mut full[..width.div_ceil(64)];
    for (m, e) in parts() {
        if m != 0 {
            add_shifted(acc, m, (e as i64 - lo) as usize);
        }
    }
    let negative = acc[acc.len() - 1] >> 63 == 1;
    if negative {
        // Two's complement negation: invert, add 1.
        let mut carry = true;
        for w in acc.iter_mut() {
            let (v, c) = (!*w).overflowing_add(u64::from(carry));
            *w = v;
            carry = c;
        }
    }
    let Some(first) = acc.iter().position(|&w| w != 0) else {
        return Some(Dyadic::ZERO);
    };
    let last = acc.iter().rposition(|&w| w != 0).expect("a nonzero limb");
    let exp = i32::try_from(lo + 64 * first as i64).ok()?;
    let words = &acc[first..=last];
    if words.len() <= 2 {
        let mag = words[0] as u128 | (words.get(1).copied().unwrap_or(0) as u128) << 64;
        if let Ok(m) = i128::try_from(mag) {
            return Some(Dyadic::small(if negative { -m } else { m }, exp));
        }
    }
    // Below 2^255: a 256-bit mantissa, without a big integer.
    if words.len() <= 4 && words.get(3).is_none_or(|w| w >> 63 == 0) {
        let mut bytes = [0u8; 32];
        for (chunk, w) in bytes.chunks_exact_mut(8).zip(words) {
            chunk.copy_from_slice(&w.to_le_bytes());
        }
        let m = Wide::from_le_bytes(bytes);
        return Some(Dyadic::wide(if negative { -m } else { m }, exp));
    }
    let sign = if negative {
        dashu_int::Sign::Negative
    } else {
        dashu_int::Sign::Positive
    };
    Some(Dyadic::big(
        IBig::from_parts(sign, dashu_int::UBig::from_words(words)),
        exp,
    ))
}

/// `acc += m · 2^shift` in two's complement, the accumulator wide enough
/// (the limbs of `m · 2^shift` past its end are zero).
fn add_shifted(acc: &mut [u64], m: i128, shift: usize) {
    let (limb, bit) = (shift / 64, shift % 64);
    let mag = m.unsigned_abs();
    // The magnitude shifted by `bit`, in three limbs.
    let parts = [
        (mag << bit) as u64,
        ((mag << bit) >> 64) as u64,
        if bit == 0 {
            0
        } else {
            (mag >> (128 - bit)) as u64
        },
    ];
    // Add with carry, or subtract with borrow.
    let step: fn(u64, u64, u64) -> (u64, u64) = if m > 0 {
        |w, p, c| {
            let (v, c1) = w.overflowing_add(p);
            let (v, c2) = v.overflowing_add(c);
            (v, u64::from(c1 | c2))
        }
    } else {
        |w, p, b| {
            let (v, b1) = w.overflowing_sub(p);
            let (v, b2) = v.overflowing_sub(b);
            (v, u64::from(b1 | b2))
        }
    };
    let mut carry = 0;
    for (i, w) in acc[limb..].iter_mut().enumerate() {
        if i >= 3 && carry == 0 {
            break;
        }
        (*w, carry) = step(*w, parts.get(i).copied().unwrap_or(0), carry);
    }
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
pub(crate) mod tests {
    use super::*;
    use core::cell::Cell;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    thread_local!(pub(crate) static BIG_ONLY: Cell<bool> = const { Cell::new(false) });
    thread_local!(pub(crate) static PRODUCTS: Cell<usize> = const { Cell::new(0) });
    thread_local!(static SUMS: Cell<[usize; 3]> = const { Cell::new([0; 3]) });

    /// Counts one sum or difference of two dyadics formed on `i128`
    /// mantissas (`width` 0), 256-bit ones (1) or big integers (2).
    pub(crate) fn count_sum(width: usize) {
        SUMS.with(|n| {
            let mut c = n.get();
            c[width] += 1;
            n.set(c);
        });
    }

    /// The sums and differences of two dyadics that `f` forms, by width.
    fn sums_during<R>(f: impl FnOnce() -> R) -> (R, [usize; 3]) {
        let before = SUMS.with(Cell::get);
        let r = f();
        let after = SUMS.with(Cell::get);
        (r, [0, 1, 2].map(|w| after[w] - before[w]))
    }

    /// The dyadic products `f` forms: 0 where the oracle decides on
    /// expansions alone.
    pub(crate) fn products_during<R>(f: impl FnOnce() -> R) -> (R, usize) {
        let before = PRODUCTS.with(Cell::get);
        let r = f();
        (r, PRODUCTS.with(Cell::get) - before)
    }

    /// `f()` with every operation done on big integers, as if no mantissa
    /// fitted in an `i128`: the reference for the fixed-width arithmetic.
    pub(crate) fn big_only<R>(f: impl FnOnce() -> R) -> R {
        struct Reset;
        impl Drop for Reset {
            fn drop(&mut self) {
                BIG_ONLY.with(|b| b.set(false));
            }
        }
        BIG_ONLY.with(|b| b.set(true));
        let _reset = Reset;
        f()
    }

    /// A finite float as the fuzz targets make them: any bits, a small
    /// integer, a special value, or a wide-range value.
    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    pub(crate) fn fuzz_like_f32(r: &mut SmallRng) -> f32 {
        match r.random_range(0..4) {
            0 => f32::from_bits(r.random::<u32>() & 0xff7f_ffff),
            1 => r.random_range(-8..=8) as f32,
            2 => [0.0, 1e30, -1e-30, f32::MAX, f32::from_bits(1), 0.5][r.random_range(0..6)],
            _ => r.random_range(-1.0..1.0f32) * 2f32.powi(r.random_range(-140..120)),
        }
    }

    /// The value as (odd mantissa, exponent), or (0, 0): equal exactly for
    /// equal values, computed on big integers alone.
    fn parts(x: &Dyadic) -> (IBig, i64) {
        let m = x.ibig().into_owned();
        match m.trailing_zeros() {
            None => (m, 0),
            Some(tz) => (m >> tz, x.exp as i64 + tz as i64),
        }
    }

    /// A dyadic whose mantissa has 1 to about 250 bits (so that sums and
    /// products land on both sides of 2^127) and whose exponent is near
    /// zero, near another's, subnormal (f32 and f64) or huge.
    fn random(r: &mut SmallRng) -> Dyadic {
        let bits = [1, 8, 24, 53, 63, 64][r.random_range(0..6)];
        let mut m = || {
            let x = r.random::<i64>() >> (64 - bits);
            if x == 0 { 1 } else { x }
        };
        let (m0, m1, m2) = (m(), m(), m());
        let e = match r.random_range(0..6) {
            0 => r.random_range(-4..4),
            1 => r.random_range(-160..-140),
            2 => r.random_range(-1100..-1060),
            3 => r.random_range(90..110),
            4 => r.random_range(-300..300),
            _ => r.random_range(-60..60),
        };
        let mant = match r.random_range(0..5) {
            0 => Dyadic::new(0, r.random_range(-5..5)),
            1 => Dyadic::new(m0, 0),
            2 => &Dyadic::new(m0, 0) * &Dyadic::new(m1, r.random_range(0..64)),
            3 => &(&Dyadic::new(m0, 0) * &Dyadic::new(m1, 0)) * &Dyadic::new(m2, 0),
            _ => &Dyadic::new(m0, 70) + &Dyadic::new(m1, 0),
        };
        mant.mul_pow2(e)
    }

    /// [`sum`] on the stack accumulator gives, bit for bit, what adding
    /// in turn on big integers gives: for 0 to 12 random terms (cancelling
    /// ones included, and spans the accumulator cannot take), every term
    /// also negated, so totals of either sign, zero among them.
    #[test]
    fn sum_matches_big_integers() {
        let mut r = SmallRng::seed_from_u64(0x5u64 << 40 | 0x0123);
        let (mut on_stack, mut zero) = (0, 0);
        for _ in 0..20_000 {
            let n = r.random_range(0..=12);
            let mut terms: Vec<Dyadic> = (0..n).map(|_| random(&mut r)).collect();
            if n > 1 && r.random_bool(0.3) {
                let k = r.random_range(1..n);
                terms[k] = -&terms[0];
            }
            let got = sum(&terms);
            let want = big_only(|| terms.iter().fold(Dyadic::ZERO, |acc, x| &acc + x));
            assert_eq!(parts(&got), parts(&want), "{terms:?}");
            assert_eq!(got.to_f64().to_bits(), want.to_f64().to_bits());
            on_stack += usize::from(sum_fixed(&terms).is_some());
            zero += usize::from(got.is_zero());
            let neg: Vec<Dyadic> = terms.iter().map(|t| -t).collect();
            assert_eq!(parts(&sum(&neg)), parts(&-&want), "{terms:?}");
        }
        assert!(on_stack > 5_000 && zero > 100, "{on_stack} {zero}");
    }

    /// Every operation on random dyadics gives the same value, ordering,
    /// sign and `f64` with `i128` and 256-bit mantissas as on big integers
    /// alone, on operands and results that fit, overflow mid-way or never
    /// fit.
    #[test]
    fn fixed_width_arithmetic_matches_big_integers() {
        let mut r = SmallRng::seed_from_u64(0x0dd_a1c);
        let (mut fixed, mut fell_back, mut wide) = (0, 0, 0);
        // Sums and products of operands on the stack, at least one of them
        // 256-bit: results on the stack, and results too long for it.
        let (mut wide_ops, mut wide_overflowed) = (0, 0);
        for _ in 0..60_000 {
            let (x, y) = (random(&mut r), random(&mut r));
            let k = r.random_range(-200..200);
            let fast = (
                [&x + &y, &x - &y, &x * &y, -&x, x.mul_pow2(k)],
                (x.cmp(&y), x == y, x.signum(), x.is_zero()),
                [x.to_f64(), (&x * &y).to_f64(), (&x + &y).to_f64()].map(f64::to_bits),
            );
            let slow = big_only(|| {
                (
                    [&x + &y, &x - &y, &x * &y, -&x, x.mul_pow2(k)],
                    (x.cmp(&y), x == y, x.signum(), x.is_zero()),
                    [x.to_f64(), (&x * &y).to_f64(), (&x + &y).to_f64()].map(f64::to_bits),
                )
            });
            assert_eq!(fast.1, slow.1, "{x:?} {y:?}");
            // The ordering is the sign of the difference.
            let diff = big_only(|| (&x - &y).signum());
            assert_eq!(fast.1.0, diff.cmp(&0), "{x:?} {y:?}");
            assert_eq!(fast.2, slow.2, "{x:?} {y:?}");
            for (a, b) in fast.0.iter().zip(&slow.0) {
                assert_eq!(parts(a), parts(b), "{x:?} {y:?}");
                // A result is held in the narrowest width its odd part
                // fits in.
                let len = parts(a).0.bit_len();
                let width = match a.mant {
                    Mant::Small(_) => 127,
                    Mant::Wide(_) => 255,
                    Mant::Big(_) => usize::MAX,
                };
                let want = [127, 255, usize::MAX].into_iter().find(|&w| len <= w);
                assert_eq!(Some(width), want, "{a:?}");
                wide += usize::from(width == 255);
            }
            let both_small = |a: &Dyadic| matches!(a.mant, Mant::Small(_));
            if both_small(&x) && both_small(&y) {
                fixed += 1;
                if !both_small(&fast.0[0]) || !both_small(&fast.0[2]) {
                    fell_back += 1;
                }
            }
            let is_wide = |a: &Dyadic| matches!(a.mant, Mant::Wide(_));
            let is_big = |a: &Dyadic| matches!(a.mant, Mant::Big(_));
            if !is_big(&x) && !is_big(&y) && (is_wide(&x) || is_wide(&y)) {
                for a in [&fast.0[0], &fast.0[1], &fast.0[2]] {
                    wide_ops += usize::from(!is_big(a));
                    wide_overflowed += usize::from(is_big(a));
                }
            }
        }
        // Every path was taken, and some sums and products overflowed.
        assert!(fixed > 20_000 && fell_back > 2_000, "{fixed} {fell_back}");
        assert!(wide > 20_000, "{wide}");
        assert!(
            wide_ops > 20_000 && wide_overflowed > 10_000,
            "{wide_ops} {wide_overflowed}"
        );
    }

    /// Ordering near the edges of the fixed-width comparison: equal leading
    /// places with exponents up to 127 apart, mantissas of 127 and 128 bits
    /// (`i128::MIN`) left unnormalised, opposite signs and zero.
    #[test]
    fn comparison_at_equal_leading_places() {
        let raw = |m: i128, exp: i32| Dyadic {
            mant: Mant::Small(m),
            exp,
        };
        let top = (1i128 << 126) + 1;
        let cases = [
            (raw(top, 0), raw(1, 126), Ordering::Greater),
            (raw(top, -126), raw(1, 0), Ordering::Greater),
            (raw(-top, 0), raw(-1, 126), Ordering::Less),
            (
                raw(i128::MAX - 1, 0),
                raw(i128::MAX >> 1, 1),
                Ordering::Equal,
            ),
            (raw(i128::MIN, 0), raw(-1, 127), Ordering::Equal),
            (raw(i128::MIN, -127), raw(-top, -126), Ordering::Greater),
            (raw(-i128::MAX, 0), raw(1, 127), Ordering::Less),
            (raw(3, 5), raw(-3, 5), Ordering::Greater),
            (Dyadic::ZERO, raw(-1, -1000), Ordering::Greater),
            (raw(0, 7), Dyadic::ZERO, Ordering::Equal),
        ];
        for (x, y, want) in cases {
            assert_eq!(x.cmp(&y), want, "{x:?} {y:?}");
            assert_eq!(y.cmp(&x), want.reverse(), "{x:?} {y:?}");
            assert_eq!(big_only(|| x.cmp(&y)), want, "{x:?} {y:?}");
        }
    }

    /// Ordering of 256-bit mantissas at equal leading places, left
    /// unnormalised: a mantissa against itself shifted (equal) and against
    /// that with one added (larger in magnitude), of either sign.
    #[test]
    fn wide_comparison_at_equal_leading_places() {
        let mut r = SmallRng::seed_from_u64(255);
        let raw = |m: &IBig, exp: i32| Dyadic {
            mant: Mant::Wide(wide::from_ibig(m).expect("255 bits fit")),
            exp,
        };
        for _ in 0..5_000 {
            let bits = r.random_range(128..=255usize);
            let m = IBig::from(r.random::<u128>()) << 128 | IBig::from(r.random::<u128>());
            let m = (m >> (256 - bits)) | IBig::ONE << (bits - 1) | IBig::ONE;
            let m = if r.random_bool(0.5) { -m } else { m };
            let (e, k) = (r.random_range(-300..300), r.random_range(0..=255 - bits));
            let x = raw(&m, e);
            let shifted = &m << k;
            let away = &shifted + m.signum();
            let cases = [
                (raw(&shifted, e - k as i32), Ordering::Equal),
                (raw(&away, e - k as i32), x.signum().cmp(&0).reverse()),
            ];
            for (y, want) in cases {
                assert_eq!(x.cmp(&y), want, "{x:?} {y:?}");
                assert_eq!(y.cmp(&x), want.reverse(), "{x:?} {y:?}");
                assert_eq!(big_only(|| x.cmp(&y)), want, "{x:?} {y:?}");
            }
        }
    }

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

    /// `to_f64` at ties of the rounding to 53 bits, with the bits beyond the
    /// leading 64 zero or not, of either sign and at every width: the same
    /// `f64` as on big integers, which rounds a negative tail downwards.
    #[test]
    fn to_f64_at_ties_matches_big_integers() {
        let tie = Dyadic::small(((1 << 52) + 1) << 11 | 1 << 10, 0);
        for k in [0, 1, 40, 63, 64, 100, 150, 200, 300] {
            for tail in [0, 1, -1, 3] {
                for sign in [1, -1] {
                    let x = &(&tie * &Dyadic::new(sign, k)) + &Dyadic::new(tail, 0);
                    let want = big_only(|| x.to_f64());
                    assert_eq!(x.to_f64().to_bits(), want.to_bits(), "{x:?}");
                }
            }
        }
        // The tie itself goes to even; just above it, up.
        assert_eq!(tie.to_f64(), (((1u64 << 52) + 2) << 11) as f64);
        let above = &tie.mul_pow2(100) + &Dyadic::new(1, 0);
        assert_eq!(
            above.to_f64(),
            (((1u64 << 52) + 2) << 11) as f64 * 2f64.powi(100)
        );
        assert_eq!((-&above).to_f64(), -above.to_f64());
    }

    #[test]
    fn pow2_is_powi() {
        for e in -1000..=1000 {
            assert_eq!(pow2(e), 2f64.powi(e), "{e}");
        }
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

    /// A mantissa is kept in the narrowest form its odd part fits, the
    /// trailing zeros moved into the exponent: an `i128`, 255 bits on the
    /// stack (`Wide`, which the fixed-width paths read through
    /// `wide_mant`), or a big integer; and the debug form shows it in
    /// decimal in each.
    #[test]
    fn mantissas_take_the_narrowest_form_that_fits() {
        let one = IBig::from(1u8);
        let small = Dyadic::big(IBig::from(3u8) << 300, 0);
        assert!(matches!(small.mant, Mant::Small(3)) && small.exp == 300);
        assert_eq!(format!("{small:?}"), "Dyadic { mant: 3, exp: 300 }");
        // 200 odd bits, 300 in all: wide.
        let odd = (&one << 200) - &one;
        let wide = Dyadic::big(&odd << 100, -7);
        assert!(matches!(wide.mant, Mant::Wide(_)) && wide.exp == 93);
        assert_eq!(
            wide.wide_mant().map(super::wide::to_ibig),
            Some(odd.clone())
        );
        assert_eq!(
            format!("{wide:?}"),
            format!("Dyadic {{ mant: {odd}, exp: 93 }}")
        );
        // 300 odd bits: big.
        let odd = (&one << 300) - &one;
        let big = Dyadic::big(odd.clone(), 5);
        assert!(matches!(big.mant, Mant::Big(_)) && big.wide_mant().is_none());
        assert_eq!(
            format!("{big:?}"),
            format!("Dyadic {{ mant: {odd}, exp: 5 }}")
        );
    }

    /// `expansion` admits exactly the values its contract names: lowest
    /// set bit at `2^LOW` or above, magnitude below `2^HIGH`, and one
    /// component per nonzero 32-bit chunk of the mantissa.
    #[test]
    fn expansion_admits_the_stated_range() {
        use super::expansion::{HIGH, LOW};
        let admitted = |d: &Dyadic| {
            let e = d.expansion()?;
            assert_eq!(&Dyadic::from_expansion(&e), d);
            Some(e.components().len())
        };
        assert_eq!(admitted(&Dyadic::ZERO), Some(0));
        assert_eq!(admitted(&Dyadic::new(1, LOW)), Some(1));
        assert_eq!(admitted(&Dyadic::new(-1, LOW - 1)), None);
        assert_eq!(admitted(&Dyadic::new(0xffff_ffff, HIGH - 32)), Some(1));
        assert_eq!(admitted(&Dyadic::new(-1, HIGH - 33)), Some(1));
        assert_eq!(admitted(&Dyadic::new(1, HIGH)), None);
        // A big mantissa keeps its trailing zeros, so its lowest set bit,
        // not its exponent, is what must reach `2^LOW`.
        let one = IBig::from(1u8);
        let odd = (&one << 300) + &one;
        let big = Dyadic::big(&odd << 20, LOW - 10);
        assert!(matches!(big.mant, Mant::Big(_)));
        assert_eq!(admitted(&big), Some(2));
        assert_eq!(admitted(&Dyadic::big(&odd << 20, LOW - 21)), None);
    }

    /// Components too far apart for the fixed accumulator are summed one
    /// by one, to the same value.
    #[test]
    fn from_expansion_sums_spans_wider_than_the_accumulator() {
        let tiny = f64::from_bits(1);
        let e = Expansion::from_f64(tiny)
            .grow(-1e300)
            .unwrap()
            .grow(2.0)
            .unwrap();
        assert_eq!(e.components().len(), 3);
        let want = &(&Dyadic::from_f64(tiny) + &Dyadic::from_f64(-1e300)) + &Dyadic::from_f64(2.0);
        assert_eq!(Dyadic::from_expansion(&e), want);
        assert_eq!(want.signum(), -1);
    }

    /// A sum or difference takes the narrowest mantissa that holds the
    /// aligned operands: `i128` where they fit, whichever operand carries
    /// the larger exponent and even when one is zero far from the other,
    /// then 256 bits, then big integers.
    #[test]
    fn sums_take_the_narrowest_mantissa_that_holds_them() {
        let d = Dyadic::new;
        let wide = &d(1, 3000) + &d(1, 3200);
        assert!(matches!(wide.mant, Mant::Wide(_)));
        let cases = [
            (d(3, 0), d(5, 0), 0),
            (d(3, 7), d(5, -9), 0),
            (d(3, -9), d(5, 7), 0),
            (Dyadic::ZERO, d(5, -3000), 0),
            (d(5, -3000), Dyadic::ZERO, 0),
            (d(1, 200), d(1, 0), 1),
            (d(1, 0), d(1, 200), 1),
            (wide.clone(), d(7, 3100), 1),
            (d(7, 3100), wide.clone(), 1),
            (Dyadic::ZERO, wide.clone(), 1),
            (wide.clone(), Dyadic::ZERO, 1),
            (d(1, 0), d(1, 600), 2),
        ];
        for (x, y, width) in cases {
            let mut want = [0; 3];
            want[width] = 1;
            for sub in [false, true] {
                let op = |x: &Dyadic, y: &Dyadic| if sub { x - y } else { x + y };
                let (got, sums) = sums_during(|| op(&x, &y));
                assert_eq!(sums, want, "{x:?} {y:?} sub {sub}");
                assert_eq!(got, big_only(|| op(&x, &y)), "{x:?} {y:?} sub {sub}");
            }
        }
    }

    /// `sum` adds up to 64 terms spanning up to 2,040 bits on its stack
    /// accumulator, forming no sum of two dyadics, and past either limit
    /// adds them in turn, to the same value.
    #[test]
    fn sum_uses_the_accumulator_up_to_its_stated_limits() {
        let d = Dyadic::new;
        let spanning = |span: i32| {
            let lo = -1100;
            vec![d(1, lo), d(-3, lo + span / 2), d(-1, lo + span - 1)]
        };
        let many = |n: usize| vec![Dyadic::small(i128::MAX, 5); n];
        for (terms, accumulated) in [
            (spanning(2040), true),
            (spanning(2041), false),
            (spanning(2048), false),
            (many(64), true),
            (many(65), false),
            (many(300), false),
        ] {
            let (got, sums) = sums_during(|| sum(&terms));
            assert_eq!(sums == [0; 3], accumulated, "{} terms", terms.len());
            assert_eq!(got, big_only(|| sum(&terms)), "{} terms", terms.len());
        }
        assert_eq!(
            sum(&many(300)),
            Dyadic::big(IBig::from(i128::MAX) * IBig::from(300u16), 5)
        );
    }
}
