//! Correct rounding to `f32` of a real number known only through exact
//! comparisons.
//!
//! Every point the rounding compares with is a finite `f32`, a midpoint
//! between two neighbouring ones (25 significant bits, from `2⁻¹⁵⁰` up),
//! zero, or the overflow threshold `2^128 − 2^103`: all exactly `f64`s. So
//! the comparisons are asked at `f64` points ([`round_to_f32_at`]), which
//! an oracle can take as they are or convert to a [`Dyadic`] exactly
//! ([`round_to_f32`]).

use super::Dyadic;
use core::cmp::Ordering;

/// The largest finite key; keys order the finite floats, `key(±0) = 0`.
const MAX_KEY: i64 = 0x7f7f_ffff;

/// The key of a float: its position on the ordered line of floats.
use crate::ulp::ordinal as key_of;

fn float_of(k: i64) -> f32 {
    if k < 0 {
        -f32::from_bits((-k) as u32)
    } else {
        f32::from_bits(k as u32)
    }
}

/// The value of the float with key `k`, formed from integers (a
/// conversion from `f32` would read a subnormal as 0 under
/// denormals-are-zero).
fn value_of(k: i64) -> f64 {
    if k < 0 {
        return -value_of(-k);
    }
    let biased = (k >> 23) as i32;
    let hidden = if biased > 0 { 0x80_0000 } else { 0 };
    ((k & 0x7f_ffff) + hidden) as f64 * pow2(biased.max(1) - 150)
}

/// The midpoint between the floats with keys `k` and `k + 1`, exactly:
/// `(2M + 1)·2^(e−1)` for the float `M·2^e` of a key `k ≥ 0` (its
/// successor is `(M + 1)·2^e`, across a binade too), mirrored below zero.
/// It has 25 significant bits and its exponent is at least −150, so the
/// `f64` holds it exactly.
fn midpoint(k: i64) -> f64 {
    if k < 0 {
        return -midpoint(-k - 1);
    }
    let biased = (k >> 23) as i32;
    let hidden = if biased > 0 { 0x80_0000 } else { 0 };
    (2 * ((k & 0x7f_ffff) + hidden) + 1) as f64 * pow2(biased.max(1) - 151)
}

/// `2^e`, for `e` in the normal range, from its bits.
fn pow2(e: i32) -> f64 {
    f64::from_bits(((e + 1023) as u64) << 52)
}

/// `f32::MAX + ulp(f32::MAX)/2 = 2^128 − 2^103`: from here on, round to ∞.
const OVERFLOW_THRESHOLD: f64 = 340_282_356_779_733_661_637_539_395_458_142_568_448.0;

/// The `f32` nearest to a real number `x`, ties to even, overflowing to ±∞
/// as IEEE 754 does; `x` is given by `cmp(m)`, the exact ordering of `x`
/// against a dyadic `m`, and `guess` is any approximation of it (only the
/// number of comparisons depends on how good it is).
///
/// A result of zero carries the sign of `x` (−0 for a negative `x` that
/// rounds to zero).
///
/// ```
/// use rayoracle::exact::{Dyadic, round_to_f32};
/// // 1/3 correctly rounded: compare 1 with 3m.
/// let third = round_to_f32(|m| Dyadic::new(1, 0).cmp(&(m * &Dyadic::new(3, 0))), 0.3);
/// assert_eq!(third, 1.0f32 / 3.0);
/// ```
pub fn round_to_f32(cmp: impl Fn(&Dyadic) -> Ordering, guess: f64) -> f32 {
    round_to_f32_at(|m| cmp(&Dyadic::from_f64(m)), guess)
}

/// [`round_to_f32`] with the points given as the `f64`s they are (module
/// docs): `cmp(m)` is the exact ordering of `x` against `m`.
///
/// ```
/// use core::cmp::Ordering::Greater;
/// use rayoracle::exact::round::round_to_f32_at;
/// // √2 correctly rounded: above every m ≤ 0, else as 2 is to m² (exact
/// // in f64 for these m).
/// let sqrt2 = |m: f64| if m <= 0.0 { Greater } else { 2.0f64.total_cmp(&(m * m)) };
/// let r = round_to_f32_at(sqrt2, 1.4);
/// assert_eq!(r, 2f32.sqrt());
/// ```
pub fn round_to_f32_at(cmp: impl Fn(f64) -> Ordering, guess: f64) -> f32 {
    #[cfg(test)]
    let calls = comparisons::Call::default();
    #[cfg(test)]
    let cmp = |m: f64| {
        calls.tick();
        cmp(m)
    };
    round_at_guess(&cmp, guess).unwrap_or_else(|| search(&cmp, guess))
}

/// The float of the guess itself, when `x` lies strictly between the
/// midpoints on either side of it (two comparisons, three for a zero);
/// `None` when it does not, or when the guess is not inside the finite
/// floats' keys.
fn round_at_guess(cmp: &impl Fn(f64) -> Ordering, guess: f64) -> Option<f32> {
    // NaN and ±∞ (as f32) have keys beyond MAX_KEY.
    let g = key_of(guess as f32);
    if g.abs() >= MAX_KEY
        || cmp(midpoint(g)) != Ordering::Less
        || cmp(midpoint(g - 1)) != Ordering::Greater
    {
        return None;
    }
    Some(signed(g, cmp))
}

/// The float with key `k`, with the sign of `x` if it is zero.
fn signed(k: i64, cmp: &impl Fn(f64) -> Ordering) -> f32 {
    if k == 0 && cmp(0.0) == Ordering::Less {
        -0.0
    } else {
        float_of(k)
    }
}

/// [`round_to_f32`] by a gallop from the guess to the floor of `x` and a
/// bisection, then the midpoint above the floor.
fn search(cmp: &impl Fn(f64) -> Ordering, guess: f64) -> f32 {
    let limit = OVERFLOW_THRESHOLD;
    if cmp(limit) != Ordering::Less {
        return f32::INFINITY;
    }
    if cmp(-limit) != Ordering::Greater {
        return f32::NEG_INFINITY;
    }
    // Between −(2^128 − 2^103) and −MAX there is no float below x to be its
    // floor, and the nearest is −MAX.
    if cmp(value_of(-MAX_KEY)) == Ordering::Less {
        return -f32::MAX;
    }
    // floor: the largest key whose value is ≤ x. -MAX_KEY qualifies now.
    let le = |k: i64| cmp(value_of(k)) != Ordering::Less;
    let g = if guess.is_finite() {
        key_of(guess as f32).clamp(-MAX_KEY, MAX_KEY)
    } else {
        0
    };
    let (mut lo, mut hi); // value(lo) ≤ x < value(hi), or hi = MAX_KEY + 1
    if le(g) {
        lo = g;
        let mut step = 1;
        loop {
            let next = (g + step).min(MAX_KEY + 1);
            if next > MAX_KEY || !le(next) {
                hi = next;
                break;
            }
            lo = next;
            step *= 2;
        }
    } else {
        hi = g;
        let mut step = 1;
        loop {
            let next = (g - step).max(-MAX_KEY);
            if le(next) {
                lo = next;
                break;
            }
            hi = next;
            step *= 2;
        }
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if le(mid) { lo = mid } else { hi = mid }
    }
    let k = if lo == MAX_KEY || cmp(value_of(lo)) == Ordering::Equal {
        lo
    } else {
        match cmp(midpoint(lo)) {
            Ordering::Less => lo,
            Ordering::Greater => lo + 1,
            Ordering::Equal => {
                if lo.unsigned_abs() % 2 == 0 {
                    lo
                } else {
                    lo + 1
                }
            }
        }
    };
    signed(k, cmp)
}

/// How many exact comparisons `round_to_f32` made on this thread (unit
/// tests only): its callers' guesses are only worth their speed, and this
/// is how a test sees it. A call that makes more than [`comparisons::CAP`]
/// panics: the search does not converge (a loop that never ends would
/// otherwise hang the test instead of failing it).
#[cfg(test)]
pub(crate) mod comparisons {
    use std::cell::Cell;
    thread_local!(static N: Cell<usize> = const { Cell::new(0) });

    /// Far above the 3 + 33 + 32 + 2 a search can need over 2³² keys.
    pub(crate) const CAP: usize = 200;

    /// One call's comparisons.
    #[derive(Default)]
    pub(crate) struct Call(Cell<usize>);

    impl Call {
        pub(crate) fn tick(&self) {
            self.0.set(self.0.get() + 1);
            assert!(
                self.0.get() <= CAP,
                "round_to_f32 made more than {CAP} comparisons"
            );
            N.with(|n| n.set(n.get() + 1));
        }
    }

    /// The comparisons made by `f`.
    pub(crate) fn during(f: impl FnOnce()) -> usize {
        let before = N.with(Cell::get);
        f();
        N.with(Cell::get) - before
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// x = p/q with q > 0 (both dyadic).
    fn ratio(p: Dyadic, q: Dyadic, guess: f64) -> f32 {
        round_to_f32(|m| p.cmp(&(m * &q)), guess)
    }

    /// Midpoints are the mean of their two floats, across binades, the
    /// subnormal boundary and zero.
    #[test]
    fn midpoints_are_means() {
        use rand::rngs::SmallRng;
        use rand::{Rng, SeedableRng};
        let mut r = SmallRng::seed_from_u64(3);
        let edges = [
            0,
            1,
            0x7f_fffe,
            0x7f_ffff,
            0x80_0000,
            0xff_ffff,
            MAX_KEY - 1,
        ];
        let keys = edges
            .into_iter()
            .flat_map(|k| [k, -k - 1])
            .chain((0..2_000).map(|_| r.random_range(-MAX_KEY..MAX_KEY)));
        for k in keys {
            let v = |k| Dyadic::from_f64(value_of(k));
            let mean = (&v(k) + &v(k + 1)).mul_pow2(-1);
            assert_eq!(Dyadic::from_f64(midpoint(k)), mean, "{k:#x}");
        }
        assert_eq!(midpoint(-1), -(2f64.powi(-150)));
        assert_eq!(midpoint(0x7f_ffff), 0xff_ffff as f64 * 2f64.powi(-150));
        let threshold = &Dyadic::new(1, 128) - &Dyadic::new(1, 103);
        assert_eq!(Dyadic::from_f64(OVERFLOW_THRESHOLD), threshold);
    }

    /// The two comparisons at the guess give what the full search gives,
    /// for `x` on a float, on a midpoint (a tie, which they leave to the
    /// search), just off either, around zero and near ±MAX, from guesses on
    /// `x`, on its neighbours and a few floats away.
    #[test]
    fn the_guess_shortcut_agrees_with_the_search() {
        use rand::rngs::SmallRng;
        use rand::{Rng, SeedableRng};
        let mut r = SmallRng::seed_from_u64(0x5ea_4c4);
        let mut shortcut = 0;
        for i in 0..20_000 {
            let k = match i % 4 {
                0 => r.random_range(-MAX_KEY + 1..MAX_KEY),
                1 => r.random_range(-4..4),
                2 => MAX_KEY - r.random_range(1..4),
                _ => -MAX_KEY + r.random_range(1..4),
            };
            let tiny = Dyadic::new(r.random_range(-3..=3), -200);
            let (value, mid) = (Dyadic::from_f64(value_of(k)), Dyadic::from_f64(midpoint(k)));
            let x = match r.random_range(0..4) {
                0 => value,
                1 => mid,
                2 => &mid + &tiny,
                _ => &value + &tiny,
            };
            let cmp = |m: f64| x.cmp(&Dyadic::from_f64(m));
            let want = search(&cmp, 0.0);
            for dk in [0, 1, -1, 2, -3] {
                let guess = f64::from(float_of((k + dk).clamp(-MAX_KEY, MAX_KEY)));
                if round_at_guess(&cmp, guess).is_some() {
                    shortcut += 1;
                }
                let got = round_to_f32_at(cmp, guess);
                assert_eq!(got.to_bits(), want.to_bits(), "{x:?} from {guess:e}");
            }
        }
        // The shortcut was taken, and not always.
        assert!((5_000..80_000).contains(&shortcut), "{shortcut}");
    }

    #[test]
    fn representable_values_round_to_themselves_from_any_guess() {
        for x in [
            1.0f32,
            -2.5,
            f32::MAX,
            -f32::MAX,
            f32::from_bits(1),
            1e-40,
            3.0e30,
            0.1,
        ] {
            for guess in [0.0, x as f64, -1e30, f64::NAN, 1e300] {
                assert_eq!(
                    ratio(Dyadic::from_f32(x), Dyadic::new(1, 0), guess).to_bits(),
                    x.to_bits(),
                    "{x:e} from {guess}"
                );
            }
        }
    }

    /// Any guess, however bad, costs at most a gallop and a bisection over
    /// the 2³² keys, and gives the same float; a guess on the answer
    /// settles it in a few comparisons.
    #[test]
    fn the_search_is_logarithmic_from_any_guess_and_short_from_a_good_one() {
        let third = |p: i64| (Dyadic::new(p, 0), Dyadic::new(3, 0));
        let xs = [
            third(1),
            third(-1),
            third(1_000_000_007),
            (Dyadic::new(1, -140), Dyadic::new(3, 0)),
            (Dyadic::new(-7, 120), Dyadic::new(3, 0)),
        ];
        for (p, q) in xs {
            let good = (p.to_f64()) / (q.to_f64());
            let mut want = 0.0f32;
            let n = comparisons::during(|| want = ratio(p.clone(), q.clone(), good));
            assert!(n <= 8, "{want:e} from its own value: {n} comparisons");
            for guess in [
                0.0,
                -good,
                good * 1e30,
                f64::NAN,
                f64::INFINITY,
                -1e300,
                1e-300,
            ] {
                let mut got = 0.0f32;
                let n = comparisons::during(|| got = ratio(p.clone(), q.clone(), guess));
                assert_eq!(got.to_bits(), want.to_bits(), "{want:e} from {guess:e}");
                assert!(n <= 72, "{want:e} from {guess:e}: {n} comparisons");
            }
            // The search itself, which the shortcut spares here, starts
            // from the guess too: a few floats off costs a short gallop.
            for off in [-3, 2, 5] {
                let n = std::cell::Cell::new(0);
                let cmp = |m: f64| {
                    n.set(n.get() + 1);
                    p.cmp(&(&Dyadic::from_f64(m) * &q))
                };
                let near = float_of((key_of(want) + off).clamp(-MAX_KEY, MAX_KEY));
                let got = search(&cmp, f64::from(near));
                assert_eq!(got.to_bits(), want.to_bits(), "{want:e} from {near:e}");
                assert!(
                    n.get() <= 14,
                    "{want:e} from {near:e}: {} comparisons",
                    n.get()
                );
            }
        }
    }

    #[test]
    fn ties_go_to_even_and_overflow_follows_ieee() {
        // 1 + 2^-24 is halfway between 1 and 1 + 2^-23: even is 1.
        let half_up = &Dyadic::new(1, 0) + &Dyadic::new(1, -24);
        assert_eq!(ratio(half_up, Dyadic::new(1, 0), 1.0), 1.0);
        // 1 + 3·2^-24 is halfway between 1+2^-23 (odd) and 1+2^-22 (even).
        let x = &Dyadic::new(1, 0) + &Dyadic::new(3, -24);
        assert_eq!(ratio(x, Dyadic::new(1, 0), 1.0), 1.0 + 2f32.powi(-22));
        // The threshold written out here, not taken from the code under test
        // (cargo-mutants: a threshold of 2^128 + 2^103 passed otherwise).
        let threshold = &Dyadic::new(1, 128) - &Dyadic::new(1, 103);
        assert_eq!(
            ratio(threshold.clone(), Dyadic::new(1, 0), 0.0),
            f32::INFINITY
        );
        let between = &Dyadic::new(1, 128) - &Dyadic::new(1, 102);
        assert_eq!(ratio(between, Dyadic::new(1, 0), 0.0), f32::INFINITY);
        let below = &threshold - &Dyadic::new(1, 0);
        assert_eq!(ratio(below.clone(), Dyadic::new(1, 0), 0.0), f32::MAX);
        // Its mirror image used to send the downward search past −MAX
        // forever (found by eval's random-input test).
        for guess in [0.0, -1e38, -3.4e38, f64::NAN] {
            assert_eq!(ratio(-below.clone(), Dyadic::new(1, 0), guess), -f32::MAX);
        }
        assert_eq!(ratio(-threshold, Dyadic::new(1, 0), 0.0), f32::NEG_INFINITY);
        // Half the smallest subnormal is a tie between 0 and 2^-149: even is 0.
        assert_eq!(
            ratio(Dyadic::new(1, -150), Dyadic::new(1, 0), 0.0).to_bits(),
            0
        );
        assert_eq!(
            ratio(Dyadic::new(-3, -151), Dyadic::new(1, 0), 0.0),
            -f32::from_bits(1)
        );
        assert_eq!(
            ratio(Dyadic::new(-1, -151), Dyadic::new(1, 0), 0.0).to_bits(),
            (-0.0f32).to_bits()
        );
    }

    #[test]
    fn quotients_match_the_hardware_division() {
        // IEEE division is correctly rounded, so it is an independent check.
        let xs = [
            1.0f32,
            3.0,
            7.0,
            0.1,
            -1e-30,
            6.02e23,
            f32::from_bits(12345),
            1.0e-38,
        ];
        for &a in &xs {
            for &b in &xs {
                let (p, q) = (Dyadic::from_f32(a), Dyadic::from_f32(b));
                let (p, q) = if b < 0.0 { (-&p, -&q) } else { (p, q) };
                let want = a / b;
                assert_eq!(
                    ratio(p.clone(), q.clone(), 0.0).to_bits(),
                    want.to_bits(),
                    "{a:e}/{b:e}"
                );
                assert_eq!(ratio(p, q, want as f64 * 1.5).to_bits(), want.to_bits());
            }
        }
    }
}
