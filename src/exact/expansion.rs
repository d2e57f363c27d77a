//! Exact sums and products on floating-point expansions (Shewchuk,
//! "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric
//! Predicates", 1997): a value is the exact sum of a few `f64` components,
//! nonoverlapping and in increasing magnitude.
//!
//! The quantities of the plane, sphere and quadric oracles span hundreds of
//! bits between their largest and smallest terms (`1e30² + 1e-30²`), which
//! a dense mantissa stores bit by bit and an expansion in two components.
//!
//! # Why every operation is exact
//!
//! * [`two_sum`] (Knuth's six operations) gives `a + b = s + e` exactly for
//!   any finite `a`, `b` whose sum does not overflow: rounding to nearest,
//!   an addition that underflows is exact.
//! * [`two_prod`] gives `a·b = p + e` with `p = fl(a·b)` and `e` by a fused
//!   multiply-add, which is exact when `e` is representable. If the lowest
//!   set bits of `a` and `b` are at `2^la` and `2^lb`, then `a·b` is
//!   `N·2^(la+lb)` with `|N| < 2¹⁰⁶` and so is `p`, so `e = N'·2^(la+lb)`
//!   with `|N'| < 2⁵³`: representable whenever `la + lb ≥ −1074`.
//! * Sums keep the lattice: if `a` and `b` are multiples of `2^l`, so are
//!   `s` and `e` (a rounded sum is a multiple of its own ulp, or exact).
//! * [`Expansion::grow`] is Shewchuk's Grow-Expansion with zero
//!   elimination (his Theorem 10): from a nonoverlapping expansion in
//!   increasing magnitude it makes one again. Every other operation is a
//!   sequence of `grow`s of exactly formed terms, so every expansion here
//!   is nonoverlapping, and its sign is the sign of its largest component
//!   (the smaller ones sum to less than its lowest bit).
//!
//! All of this needs subnormal arithmetic as IEEE 754 defines it: with
//! flush-to-zero or denormals-are-zero on, a tiny component or a
//! subnormal `f32` input would read as 0. [`subnormals_work`] tells, and
//! the callers use the expansions only when it holds.
//!
//! The callers ([`super::quadratic`]) admit only values whose lowest bit
//! is at `2^LOW` or above and whose magnitude is below `2^HIGH`, which
//! bounds every product they form inside the range above (see there).
//! An expansion that would exceed [`CAP`] components returns `None`, and
//! the caller falls back to dyadic arithmetic.

use core::cmp::Ordering;

/// The most components an expansion holds.
pub const CAP: usize = 24;

/// The lowest set bit an admitted value may have: `2^LOW`.
pub const LOW: i32 = -520;
/// An admitted value is below `2^HIGH` in magnitude.
pub const HIGH: i32 = 480;

/// Whether subnormal numbers are read and produced as IEEE 754 says: not
/// so under denormals-are-zero (a subnormal input reads as 0) or
/// flush-to-zero (a subnormal result becomes 0). Asked at run time, as the
/// floating-point environment can change, by
/// [`crate::num::certify::subnormals_work`]: on x86-64 a read of MXCSR,
/// where computing with a subnormal would cost a microcode assist on
/// every call of the oracle.
///
/// ```
/// assert!(rayoracle::exact::expansion::subnormals_work());
/// ```
#[inline]
pub fn subnormals_work() -> bool {
    crate::num::certify::subnormals_work()
}

/// `a + b = s + e` exactly (Knuth's TwoSum).
///
/// ```
/// use rayoracle::exact::expansion::two_sum;
/// assert_eq!(two_sum(1.0, 1e-30), (1.0, 1e-30));
/// ```
#[inline]
pub fn two_sum(a: f64, b: f64) -> (f64, f64) {
    let s = a + b;
    let bb = s - a;
    let e = (a - (s - bb)) + (b - bb);
    (s, e)
}

/// `a·b = p + e` exactly, when the lowest set bits of `a` and `b` add up
/// to `2^−1074` or more and `a·b` does not overflow (module docs).
///
/// ```
/// use rayoracle::exact::expansion::two_prod;
/// let x = 1.0 + f64::EPSILON;
/// assert_eq!(two_prod(x, x), (1.0 + 2.0 * f64::EPSILON, f64::EPSILON * f64::EPSILON));
/// ```
#[inline]
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    (p, a.mul_add(b, -p))
}

/// An exact sum of nonoverlapping `f64` components, smallest first, none
/// of them zero (zero is the empty expansion).
///
/// ```
/// use rayoracle::exact::expansion::Expansion;
/// let x = Expansion::from_f64(1e30).add(&Expansion::from_f64(1e-30)).unwrap();
/// let y = x.add(&Expansion::from_f64(-1e30)).unwrap();
/// assert_eq!(y.components(), &[1e-30]);
/// assert_eq!(x.mul(&x).unwrap().sign(), 1);
/// ```
#[derive(Clone, Copy)]
pub struct Expansion {
    c: [f64; CAP],
    n: usize,
}

impl core::fmt::Debug for Expansion {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_list().entries(self.components()).finish()
    }
}

impl Expansion {
    /// Zero.
    pub const ZERO: Expansion = Expansion {
        c: [0.0; CAP],
        n: 0,
    };

    /// The value of one finite `f64`.
    pub fn from_f64(x: f64) -> Expansion {
        let mut e = Expansion::ZERO;
        if x != 0.0 {
            e.c[0] = x;
            e.n = 1;
        }
        e
    }

    /// The components, smallest first.
    pub fn components(&self) -> &[f64] {
        &self.c[..self.n]
    }

    /// Appends a component known to be larger than and nonoverlapping with
    /// every component so far (the construction from a mantissa's chunks).
    pub(crate) fn push(&mut self, x: f64) -> Option<()> {
        if x != 0.0 {
            *self.c.get_mut(self.n)? = x;
            self.n += 1;
        }
        Some(())
    }

    /// `self + b` (Grow-Expansion with zero elimination).
    pub fn grow(&self, b: f64) -> Option<Expansion> {
        let mut out = *self;
        out.grow_mut(b)?;
        Some(out)
    }

    /// `self += b`, in place: the `i`-th output component is written after
    /// the `i`-th input one is read, never before.
    pub fn grow_mut(&mut self, b: f64) -> Option<()> {
        let mut q = b;
        let mut j = 0;
        for i in 0..self.n {
            let (s, h) = two_sum(q, self.c[i]);
            if h != 0.0 {
                self.c[j] = h;
                j += 1;
            }
            q = s;
        }
        if q != 0.0 {
            *self.c.get_mut(j)? = q;
            j += 1;
        }
        self.n = j;
        Some(())
    }

    /// `self += x·y`, exactly (under the bounds of the module docs).
    pub fn add_product(&mut self, x: f64, y: f64) -> Option<()> {
        let (p, e) = two_prod(x, y);
        if p == 0.0 {
            // An exact product of 0: `x` or `y` is 0, and so is `e`.
            return Some(());
        }
        if self.n == 0 {
            // `|e| ≤ ulp(p)/2`, below the lowest set bit of `p`: `[e, p]`
            // is already nonoverlapping.
            self.push(e)?;
            return self.push(p);
        }
        self.grow_mut(e)?;
        self.grow_mut(p)
    }

    /// `self + other`, exactly.
    pub fn add(&self, other: &Expansion) -> Option<Expansion> {
        let mut out = *self;
        for &x in other.components() {
            out.grow_mut(x)?;
        }
        Some(out)
    }

    /// `self = −self`, in place.
    pub fn negate(&mut self) {
        self.c[..self.n].iter_mut().for_each(|x| *x = -*x);
    }

    /// `−self`.
    pub fn neg(&self) -> Expansion {
        let mut out = *self;
        out.c[..out.n].iter_mut().for_each(|x| *x = -*x);
        out
    }

    /// `self − other`, exactly.
    pub fn sub(&self, other: &Expansion) -> Option<Expansion> {
        let mut out = *self;
        for &x in other.components() {
            out.grow_mut(-x)?;
        }
        Some(out)
    }

    /// `self · 2^k` for a small `k` (`|k| ≤ 1000`; every component scaled
    /// exactly while it stays in the normal range, which the callers'
    /// bounds ensure).
    pub fn mul_pow2(&self, k: i32) -> Expansion {
        let f = f64::from_bits(((k + 1023) as u64) << 52);
        let mut out = *self;
        out.c[..out.n].iter_mut().for_each(|x| *x *= f);
        out
    }

    /// `self · b`, exactly (under the bounds of the module docs).
    pub fn scale(&self, b: f64) -> Option<Expansion> {
        let mut out = Expansion::ZERO;
        for &x in self.components() {
            out.add_product(x, b)?;
        }
        Some(out)
    }

    /// `self · other`, exactly (under the bounds of the module docs).
    pub fn mul(&self, other: &Expansion) -> Option<Expansion> {
        let mut out = Expansion::ZERO;
        for &y in other.components() {
            for &x in self.components() {
                out.add_product(x, y)?;
            }
        }
        Some(out)
    }

    /// The same value in fewer components: Shewchuk's Compress (his
    /// Theorem 23: the result is nonoverlapping), with [`two_sum`] for his
    /// Fast-Two-Sum, whose ordering precondition his proof ensures and
    /// which gives the same two results when it holds.
    pub fn compress(&self) -> Expansion {
        let m = self.n;
        if m < 2 {
            return *self;
        }
        let mut g = [0.0; CAP];
        let mut bottom = m - 1;
        let mut q = self.c[m - 1];
        for i in (0..m - 1).rev() {
            let (s, t) = two_sum(q, self.c[i]);
            if t != 0.0 {
                g[bottom] = s;
                bottom -= 1;
                q = t;
            } else {
                q = s;
            }
        }
        g[bottom] = q;
        let mut out = Expansion::ZERO;
        for &x in &g[bottom + 1..m] {
            let (s, t) = two_sum(x, q);
            if t != 0.0 {
                out.c[out.n] = t;
                out.n += 1;
            }
            q = s;
        }
        if q != 0.0 {
            out.c[out.n] = q;
            out.n += 1;
        }
        out
    }

    /// −1, 0 or 1: the sign of the largest component.
    pub fn sign(&self) -> i32 {
        match self.components().last() {
            None => 0,
            Some(&x) if x > 0.0 => 1,
            Some(_) => -1,
        }
    }

    /// `self` against `other`, exactly.
    pub fn compare(&self, other: &Expansion) -> Option<Ordering> {
        Some(self.sub(other)?.sign().cmp(&0))
    }

    /// An approximation (the components summed in `f64`, smallest first):
    /// for starting guesses only.
    pub fn approx(&self) -> f64 {
        self.components().iter().sum()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Dyadic;
    use crate::exact::dyadic::tests::big_only;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    fn value(e: &Expansion) -> Dyadic {
        big_only(|| {
            e.components()
                .iter()
                .fold(Dyadic::ZERO, |acc, &x| &acc + &Dyadic::from_f64(x))
        })
    }

    /// A float of 1 to 53 bits at an exponent from −400 to 400, or zero.
    fn random(r: &mut SmallRng) -> f64 {
        if r.random_bool(0.1) {
            return 0.0;
        }
        let bits = [1, 8, 24, 53][r.random_range(0..4)];
        let m = (r.random::<u64>() >> (64 - bits)) | 1;
        let x = m as f64 * 2f64.powi(r.random_range(-400..400));
        if r.random_bool(0.5) { -x } else { x }
    }

    fn random_expansion(r: &mut SmallRng) -> Expansion {
        (0..r.random_range(0..5)).fold(Expansion::ZERO, |acc, _| acc.grow(random(r)).unwrap())
    }

    /// Every operation gives the exact value (checked on big integers),
    /// and every result is nonoverlapping in increasing magnitude, so its
    /// sign is the sign of the exact value.
    #[test]
    fn operations_are_exact_and_nonoverlapping() {
        let mut r = SmallRng::seed_from_u64(1997);
        let nonoverlapping = |e: &Expansion| {
            e.components().windows(2).all(|w| {
                // Both normal here: the exponent, and the lowest set bit.
                let exp = |x: f64| ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023;
                let low_bit = |x: f64| exp(x) - 52 + x.to_bits().trailing_zeros().min(52) as i32;
                // The top bit of the smaller below the lowest bit of the
                // larger.
                exp(w[0]) < low_bit(w[1])
            })
        };
        let mut cancelled = 0;
        for _ in 0..5_000 {
            let (x, y) = (random_expansion(&mut r), random_expansion(&mut r));
            let (vx, vy) = (value(&x), value(&y));
            let b = random(&mut r);
            let results = [
                (x.add(&y).unwrap(), big_only(|| &vx + &vy)),
                (x.sub(&y).unwrap(), big_only(|| &vx - &vy)),
                (x.mul(&y).unwrap(), big_only(|| &vx * &vy)),
                (x.scale(b).unwrap(), big_only(|| &vx * &Dyadic::from_f64(b))),
                (x.sub(&x).unwrap(), Dyadic::ZERO),
                (x.mul_pow2(3), big_only(|| vx.mul_pow2(3))),
                (x.mul(&y).unwrap().compress(), big_only(|| &vx * &vy)),
                (x.add(&y).unwrap().compress(), big_only(|| &vx + &vy)),
            ];
            for (got, want) in results {
                assert!(big_only(|| value(&got) == want), "{x:?} {y:?} {b}");
                assert!(nonoverlapping(&got), "{got:?}");
                assert_eq!(got.sign(), big_only(|| want.signum()), "{got:?}");
            }
            assert_eq!(x.compare(&y), Some(big_only(|| vx.cmp(&vy))));
            cancelled += usize::from(x.sub(&y).unwrap().sign() == 0);
        }
        assert!(cancelled > 10, "{cancelled}");
    }

    /// A float is one component, and 0 none; Compress merges two
    /// components whose sum is exact, down to one; the debug form lists
    /// the components, smallest first.
    #[test]
    fn single_floats_and_exact_sums_take_the_fewest_components() {
        assert!(Expansion::from_f64(0.0).components().is_empty());
        assert!(Expansion::from_f64(-0.0).components().is_empty());
        for x in [1.0, -3.5, f64::MIN_POSITIVE, -1e300] {
            assert_eq!(Expansion::from_f64(x).components(), &[x]);
        }
        let mut e = Expansion::ZERO;
        e.push(1.0).unwrap();
        e.push(2.0).unwrap();
        assert_eq!(e.components(), &[1.0, 2.0]);
        assert_eq!(e.compress().components(), &[3.0]);
        // 1 + 2⁵³ is not an f64: the two stay.
        let mut far = Expansion::ZERO;
        far.push(1.0).unwrap();
        far.push(2f64.powi(53)).unwrap();
        assert_eq!(far.compress().components(), far.components());
        assert_eq!(format!("{e:?}"), "[1.0, 2.0]");
    }

    /// An expansion declines a component past [`CAP`] instead of losing
    /// it; a full one still takes a sum that needs no new component.
    #[test]
    fn a_full_expansion_declines() {
        // 2^k from its bits, subnormal or normal.
        let p2 = |k: i32| match k {
            ..-1022 => f64::from_bits(1 << (k + 1074)),
            _ => f64::from_bits(((k + 1023) as u64) << 52),
        };
        let mut e = Expansion::ZERO;
        // One-bit components 53 places apart: nonoverlapping, none merges.
        for k in 0..CAP as i32 {
            e.push(p2(-1074 + 53 * k)).unwrap();
        }
        assert_eq!(e.components().len(), CAP);
        let mut full = e;
        assert!(full.push(1.0).is_none());
        let sum = e.grow(p2(-1074)).unwrap();
        let want = big_only(|| &value(&e) + &Dyadic::from_f64(p2(-1074)));
        assert!(big_only(|| value(&sum) == want));
        assert_eq!(e.grow(-p2(-1074)).unwrap().components().len(), CAP - 1);
    }
}
