//! Exact classification and correctly rounded roots of `α t² + β t + γ = 0`
//! with dyadic coefficients, shared by the sphere and quadric oracles (and,
//! with `α = 0`, the plane's).
//!
//! The signs that decide are those of `α`, `β`, `γ`, the discriminant
//! `β² − 4αγ`, and of `p(m) = (αm + β)m + γ`, `2αm + β` or `βm + γ` at the
//! points `m` the rounding asks about ([`round_to_f32_at`]). They are
//! evaluated on [`Expansion`]s when the coefficients admit it, and on
//! dyadics otherwise, with the same results.
//!
//! # Why the expansions are exact here
//!
//! A coefficient is admitted when its lowest set bit is at `2⁻⁵²⁰` or
//! above and its magnitude below `2⁴⁸⁰` ([`super::expansion::LOW`],
//! [`super::expansion::HIGH`]); the plane's, the sphere's and the
//! quadric's always are (products of two or three `f32`s: lowest bits from
//! `2⁻⁴⁴⁷`, magnitudes below `2³⁹⁰`). Every point `m` has its lowest bit
//! at `2⁻¹⁵⁰` or above and `|m| ≤ 2¹²⁸`. So every product formed, `β²`, `αγ`, `αm`, `βm` and
//! `(αm + β)m`, has factors whose lowest bits add up to `−1040` or more and
//! a magnitude below `2⁹⁶²`: each partial product is exact
//! ([`super::expansion::two_prod`]), and no sum overflows. An expansion
//! that outgrows its capacity sends that comparison (or the whole solve)
//! to the dyadics, and so does a floating-point environment that flushes
//! subnormals ([`super::expansion::subnormals_work`]). Each sign is first
//! asked of an `f64` filter with a proven error bound (`Near`), which
//! tells nearly all of them; coefficients of more than four components
//! even after Compress (dense mantissas, which the products would pay for
//! quadratically) go to the dyadics for the signs it does not tell.

use super::expansion::Expansion;
use super::round::round_to_f32_at;
use super::{Dyadic, round_to_f32};
use core::cmp::Ordering;

/// A quadratic `α t² + β t + γ` with exact dyadic coefficients.
///
/// ```
/// use rayoracle::exact::{Dyadic, ExactQuadratic, Quadratic};
/// // t² − 2 = 0: roots ±√2, correctly rounded.
/// let q = Quadratic::new(Dyadic::new(1, 0), Dyadic::ZERO, Dyadic::new(-2, 0));
/// assert_eq!(q.solve(), ExactQuadratic::Two(-2f32.sqrt(), 2f32.sqrt()));
/// ```
#[derive(Clone)]
pub struct Quadratic {
    /// α, normalised to be ≥ 0 (the equation is multiplied by −1 if needed).
    pub alpha: Dyadic,
    /// β, with the same normalisation.
    pub beta: Dyadic,
    /// γ, with the same normalisation.
    pub gamma: Dyadic,
    /// α, β, γ as expansions, when the constructor had them.
    expansions: Option<[Expansion; 3]>,
}

impl core::fmt::Debug for Quadratic {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("Quadratic")
            .field("alpha", &self.alpha)
            .field("beta", &self.beta)
            .field("gamma", &self.gamma)
            .finish()
    }
}

/// The exact answer: classification and correctly rounded roots.
///
/// ```
/// use rayoracle::exact::ExactQuadratic;
/// assert_eq!(ExactQuadratic::Two(1.0, 2.0).roots(), vec![1.0, 2.0]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum ExactQuadratic {
    /// No real root.
    None,
    /// A double root (discriminant exactly 0) or the root of a linear
    /// equation (α = 0, β ≠ 0).
    One(f32),
    /// Two distinct real roots, `t0 < t1` exactly (they may round to the same
    /// `f32`).
    Two(f32, f32),
    /// Every `t` (α = β = γ = 0).
    All,
}

impl ExactQuadratic {
    /// The roots, ascending.
    ///
    /// ```
    /// use rayoracle::exact::ExactQuadratic;
    /// assert!(ExactQuadratic::All.roots().is_empty());
    /// ```
    pub fn roots(&self) -> Vec<f32> {
        match *self {
            ExactQuadratic::One(t) => vec![t],
            ExactQuadratic::Two(a, b) => vec![a, b],
            _ => vec![],
        }
    }
}

impl Quadratic {
    /// The quadratic with these coefficients.
    ///
    /// ```
    /// use rayoracle::exact::{Dyadic, Quadratic};
    /// let q = Quadratic::new(Dyadic::new(-1, 0), Dyadic::ZERO, Dyadic::new(4, 0));
    /// assert_eq!(q.alpha.signum(), 1); // normalised
    /// ```
    pub fn new(alpha: Dyadic, beta: Dyadic, gamma: Dyadic) -> Self {
        if alpha.signum() < 0 || (alpha.is_zero() && beta.signum() < 0) {
            Quadratic {
                alpha: -alpha,
                beta: -beta,
                gamma: -gamma,
                expansions: None,
            }
        } else {
            Quadratic {
                alpha,
                beta,
                gamma,
                expansions: None,
            }
        }
    }

    /// The quadratic with coefficients given as expansions (normalised as
    /// [`Quadratic::new`] does), which [`Quadratic::solve`] then uses as
    /// they are.
    #[cfg(any(feature = "sphere", feature = "quadric"))]
    pub(crate) fn from_expansions(alpha: Expansion, beta: Expansion, gamma: Expansion) -> Self {
        Quadratic::of_normalised(normalised([alpha, beta, gamma]))
    }

    /// The quadratic of coefficients already normalised.
    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    fn of_normalised(e: [Expansion; 3]) -> Self {
        Quadratic {
            alpha: Dyadic::from_expansion(&e[0]),
            beta: Dyadic::from_expansion(&e[1]),
            gamma: Dyadic::from_expansion(&e[2]),
            expansions: Some(e),
        }
    }

    /// `β² − 4αγ`, exactly.
    ///
    /// ```
    /// use rayoracle::exact::{Dyadic, Quadratic};
    /// let q = Quadratic::new(Dyadic::new(1, 0), Dyadic::new(2, 0), Dyadic::new(1, 0));
    /// assert!(q.discriminant().is_zero());
    /// ```
    pub fn discriminant(&self) -> Dyadic {
        &(&self.beta * &self.beta) - &(&self.alpha * &self.gamma).mul_pow2(2)
    }

    /// The ordering of the smaller root (`upper` false) or the larger one
    /// against `m`, for α > 0 and two real roots; `neg` is `[−β, −γ]`.
    /// `m` lies against the vertex `−β/2α` as `2αm` does against `−β`; a
    /// root on the other side is settled by that, else by the sign of
    /// `p(m) = (αm + β)m + γ`, which is how `(αm + β)m` compares to `−γ`
    /// (p < 0 strictly between the roots).
    fn root_against(&self, neg: &[Dyadic; 2], m: &Dyadic, upper: bool) -> Ordering {
        let am = &self.alpha * m;
        let side = am.mul_pow2(1).cmp(&neg[0]);
        match (side, upper) {
            (Ordering::Greater, false) => Ordering::Less,
            (Ordering::Less, true) => Ordering::Greater,
            _ => {
                let p = (&(&am + &self.beta) * m).cmp(&neg[1]);
                if upper { p.reverse() } else { p }
            }
        }
    }

    /// Classifies and returns the correctly rounded roots.
    ///
    /// ```
    /// use rayoracle::exact::{Dyadic, ExactQuadratic, Quadratic};
    /// // 0·t² + 2t − 1: the linear root 1/2.
    /// let q = Quadratic::new(Dyadic::ZERO, Dyadic::new(2, 0), Dyadic::new(-1, 0));
    /// assert_eq!(q.solve(), ExactQuadratic::One(0.5));
    /// ```
    pub fn solve(&self) -> ExactQuadratic {
        let fast = self
            .expansions
            .map(|e| e.map(Some))
            .unwrap_or_else(|| [&self.alpha, &self.beta, &self.gamma].map(Dyadic::expansion));
        if let Some(r) = solve_fast(fast.each_ref().map(Option::as_ref), &Slow::Have(self)) {
            return r;
        }
        self.solve_dyadic()
    }

    /// [`Quadratic::solve`] on dyadics alone.
    fn solve_dyadic(&self) -> ExactQuadratic {
        let (a, b, c) = (self.alpha.to_f64(), self.beta.to_f64(), self.gamma.to_f64());
        if self.alpha.is_zero() {
            if self.beta.is_zero() {
                return if self.gamma.is_zero() {
                    ExactQuadratic::All
                } else {
                    ExactQuadratic::None
                };
            }
            // β > 0 after normalisation: t ≷ m ⇔ −γ ≷ β m.
            let neg_gamma = -&self.gamma;
            let t = round_to_f32(|m| neg_gamma.cmp(&(&self.beta * m)), -c / b);
            return ExactQuadratic::One(t);
        }
        let disc = self.discriminant();
        match disc.signum() {
            -1 => ExactQuadratic::None,
            0 => {
                // The vertex −β/(2α), with α > 0: t ≷ m ⇔ −β ≷ 2α m.
                let neg_beta = -&self.beta;
                let t = round_to_f32(
                    |m| neg_beta.cmp(&(&self.alpha * m).mul_pow2(1)),
                    -b / (2.0 * a),
                );
                ExactQuadratic::One(t)
            }
            _ => {
                let (g0, g1) = guess_roots(a, b, c, disc.to_f64());
                let neg = [-&self.beta, -&self.gamma];
                let t0 = round_to_f32(|m| self.root_against(&neg, m, false), g0);
                let t1 = round_to_f32(|m| self.root_against(&neg, m, true), g1);
                ExactQuadratic::Two(t0, t1)
            }
        }
    }
}

/// The dyadic coefficients for the comparisons an expansion cannot hold:
/// those of a [`Quadratic`] at hand, or formed from normalised expansions
/// on first use (most quadratics never need them).
enum Slow<'a> {
    Have(&'a Quadratic),
    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    Lazy(&'a [Expansion; 3], &'a core::cell::OnceCell<Quadratic>),
}

impl Slow<'_> {
    fn get(&self) -> &Quadratic {
        match self {
            Slow::Have(q) => q,
            #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
            Slow::Lazy(e, q) => q.get_or_init(|| Quadratic::of_normalised(**e)),
        }
    }
}

/// `α`, `β`, `γ` multiplied by −1 where [`Quadratic::new`] would.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn normalised(mut e: [Expansion; 3]) -> [Expansion; 3] {
    let flip = e[0].sign() < 0 || (e[0].sign() == 0 && e[1].sign() < 0);
    if flip {
        e.iter_mut().for_each(Expansion::negate);
    }
    e
}

/// What [`Quadratic::from_expansions`]`(α, β, γ).solve()` gives, without
/// forming the dyadic coefficients unless a comparison outgrows the
/// expansions.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
pub(crate) fn solve_expansions(
    alpha: Expansion,
    beta: Expansion,
    gamma: Expansion,
) -> ExactQuadratic {
    let e = normalised([alpha, beta, gamma]);
    let cell = core::cell::OnceCell::new();
    let slow = Slow::Lazy(&e, &cell);
    if let Some(r) = solve_fast(e.each_ref().map(Some), &slow) {
        return r;
    }
    slow.get().solve_dyadic()
}

/// [`Quadratic::solve`] on the expansions `fast`, if each is there,
/// subnormals work, and the discriminant fits.
fn solve_fast(fast: [Option<&Expansion>; 3], slow: &Slow) -> Option<ExactQuadratic> {
    #[cfg(test)]
    let fast = fast.map(|e| e.filter(|_| !super::dyadic::tests::BIG_ONLY.with(|b| b.get())));
    let [Some(a), Some(b), Some(c)] = fast else {
        return None;
    };
    if !super::expansion::subnormals_work() {
        return None;
    }
    // The long ones compressed; the rest used where they are (an
    // expansion is a few hundred bytes, and copies cost more than the
    // arithmetic on a short one).
    let long = |x: &Expansion| (x.components().len() > SHORT).then(|| x.compress());
    let kept = [long(a), long(b), long(c)];
    let [a, b, c] =
        [(a, &kept[0]), (b, &kept[1]), (c, &kept[2])].map(|(x, k)| k.as_ref().unwrap_or(x));
    // Long expansions (dense mantissas) cost quadratically in the exact
    // products; dyadics hold those better.
    let short = [a, b, c].iter().all(|x| x.components().len() <= SHORT);
    solve_on_expansions([a, b, c], short, slow)
}

/// [`Quadratic::solve`] on expansions: `None` only if the discriminant
/// outgrows an expansion (or is not told by the filter, unless `short`); a
/// comparison that does goes to the dyadics. Every sign is first asked of
/// the `f64` filter ([`Near`]), and formed on the expansions only where
/// that cannot tell and they are `short`, on the dyadics otherwise.
fn solve_on_expansions(
    [a, b, c]: [&Expansion; 3],
    short: bool,
    slow: &Slow,
) -> Option<ExactQuadratic> {
    let exact = |x: Option<Expansion>| x.filter(|_| short);
    let dy = Dyadic::from_f64;
    let [na, nb, nc] = [a, b, c].map(Near::of);
    let (fa, fb, fc) = (na.v, nb.v, nc.v);
    if a.sign() == 0 {
        if b.sign() == 0 {
            return Some(if c.sign() == 0 {
                ExactQuadratic::All
            } else {
                ExactQuadratic::None
            });
        }
        // β > 0 after normalisation: t ≷ m ⇔ −γ ≷ β m, as 0 ≷ βm + γ.
        let neg_c = c.neg();
        let t = round_to_f32_at(
            |m| {
                let sum = Near::sum([(nb, m), (nc, 1.0)]);
                sum.map(Ordering::reverse).unwrap_or_else(|| {
                    exact(b.scale(m))
                        .and_then(|bm| neg_c.compare(&bm))
                        .unwrap_or_else(|| {
                            let q = slow.get();
                            (-&q.gamma).cmp(&(&q.beta * &dy(m)))
                        })
                })
            },
            -fc / fb,
        );
        return Some(ExactQuadratic::One(t));
    }
    // β² − 4αγ: its sign from the filter where that tells, its value
    // (for the starting guesses) from the filter's f64 then.
    let (sure, fd) = Near::discriminant(&[na, nb, nc]);
    let (sign, fd) = match sure {
        Some(s) => (s, fd),
        None => {
            let disc = exact(b.mul(b))?.sub(&a.mul(c)?.mul_pow2(2))?;
            (disc.sign().cmp(&0), disc.approx())
        }
    };
    Some(match sign {
        Ordering::Less => ExactQuadratic::None,
        Ordering::Equal => {
            // The vertex −β/(2α), with α > 0: t ≷ m ⇔ −β ≷ 2α m, as
            // 0 ≷ 2αm + β.
            let neg_b = b.neg();
            let t = round_to_f32_at(
                |m| {
                    let sum = Near::sum([(na, 2.0 * m), (nb, 1.0)]);
                    sum.map(Ordering::reverse).unwrap_or_else(|| {
                        exact(a.scale(2.0 * m))
                            .and_then(|am| neg_b.compare(&am))
                            .unwrap_or_else(|| {
                                let q = slow.get();
                                (-&q.beta).cmp(&(&q.alpha * &dy(m)).mul_pow2(1))
                            })
                    })
                },
                -fb / (2.0 * fa),
            );
            ExactQuadratic::One(t)
        }
        Ordering::Greater => {
            let (g0, g1) = guess_roots(fa, fb, fc, fd);
            let neg = [b.neg(), c.neg()];
            let near = [na, nb, nc];
            let root = |upper: bool, guess: f64| {
                round_to_f32_at(
                    |m| {
                        let exp = short.then_some((a, b, &neg));
                        root_against_expansions(exp, &near, m, upper).unwrap_or_else(|| {
                            let q = slow.get();
                            let neg = [-&q.beta, -&q.gamma];
                            q.root_against(&neg, &dy(m), upper)
                        })
                    },
                    guess,
                )
            };
            ExactQuadratic::Two(root(false, g0), root(true, g1))
        }
    })
}

/// `2⁻⁴⁹`: the filter's error bound per unit of the magnitudes summed
/// ([`Near`]).
const FILTER: f64 = 1.0 / (1u64 << 49) as f64;
/// `2⁻⁹⁰⁰`: the filter's allowance for underflow.
const TINY: f64 = f64::from_bits((1023 - 900) << 52);

/// An expansion seen in `f64`, for the sign filter: `v`, its components
/// summed (smallest first), and `mag`, their magnitudes summed.
///
/// # Why the filter's signs are exact
///
/// With `u = 2⁻⁵³`: the components are nonoverlapping and increasing, so
/// those below `cₖ` sum in magnitude to less than `|cₖ|`, each partial sum
/// `sₖ` is below `2|cₖ|` (and a little), and summing them smallest first
/// errs by at most `u·Σ|sₖ| < 2.01u·mag` from the value `x`, however many
/// components there are (within `3u·mag`, as used below).
/// A sum `Σ xᵢ·kᵢ` of two or three coefficients times exact `f64`
/// factors (`1`, `m`, `2m`, `m²` formed by Horner's rule), evaluated in
/// `f64` with at most four roundings, is then within
/// `(γ₄ + γ₃)·Σ magᵢ·|kᵢ| < 7.1u·Σ magᵢ·|kᵢ|` of the exact sum, and the
/// discriminant `β² − 4αγ` (three roundings, and the coefficient errors
/// multiplied out) within `9.1u·(mag_β² + 4·mag_α·mag_γ)`. [`FILTER`] is
/// `16u`, over twice either, which also covers the rounding of the bound
/// itself. A result that underflows is off by at most `2⁻¹⁰⁷⁵`, which the
/// factors (`|m| ≤ 2¹²⁸`) magnify to below `2⁻⁹⁴⁰`, under [`TINY`]. No
/// value overflows: magnitudes are below `2⁴⁸⁰` ([`super::expansion::HIGH`])
/// and `m²` at most `2²⁵⁶`. So an `f64` result beyond its bound has the
/// exact sign, as long as subnormals work (the solver asks first).
#[derive(Clone, Copy)]
struct Near {
    v: f64,
    mag: f64,
}

impl Near {
    fn of(e: &Expansion) -> Near {
        Near {
            v: e.approx(),
            mag: e.components().iter().map(|x| x.abs()).sum(),
        }
    }

    /// The sign of `p(m) = (αm + β)m + γ`, by Horner's rule, if the filter
    /// tells it.
    fn horner(&[a, b, c]: &[Near; 3], m: f64) -> Option<Ordering> {
        let v = (a.v * m + b.v) * m + c.v;
        let mag = (a.mag * m.abs() + b.mag) * m.abs() + c.mag;
        sure_sign(v, FILTER * mag + TINY)
    }

    /// The sign of `β² − 4αγ`, if the filter tells it, and its `f64` value.
    fn discriminant(&[a, b, c]: &[Near; 3]) -> (Option<Ordering>, f64) {
        let v = b.v * b.v - 4.0 * a.v * c.v;
        (
            sure_sign(v, FILTER * (b.mag * b.mag + 4.0 * a.mag * c.mag) + TINY),
            v,
        )
    }

    /// The sign of `Σ xᵢ·kᵢ`, if the filter tells it.
    fn sum<const N: usize>(terms: [(Near, f64); N]) -> Option<Ordering> {
        let v = terms.iter().fold(0.0, |s, (x, k)| s + x.v * k);
        let mag = terms.iter().fold(0.0, |s, (x, k)| s + x.mag * k.abs());
        sure_sign(v, FILTER * mag + TINY)
    }
}

/// The sign of a value computed as `v` within `err` of it, when
/// `|v| > err` (never for NaN).
fn sure_sign(v: f64, err: f64) -> Option<Ordering> {
    if v > err {
        Some(Ordering::Greater)
    } else if v < -err {
        Some(Ordering::Less)
    } else {
        None
    }
}

/// [`Quadratic::root_against`] by the filter, `near` being its view of
/// `[α, β, γ]`, and where it cannot tell on the expansions `exp`,
/// `(α, β, [−β, −γ])`, if given.
fn root_against_expansions(
    exp: Option<(&Expansion, &Expansion, &[Expansion; 2])>,
    near: &[Near; 3],
    m: f64,
    upper: bool,
) -> Option<Ordering> {
    let [na, nb, _] = *near;
    // 2αm against −β: the sign of 2αm + β.
    let side = match Near::sum([(na, 2.0 * m), (nb, 1.0)]) {
        Some(s) => s,
        None => {
            let (a, _, neg) = exp?;
            a.scale(m)?.mul_pow2(1).compare(&neg[0])?
        }
    };
    Some(match (side, upper) {
        (Ordering::Greater, false) => Ordering::Less,
        (Ordering::Less, true) => Ordering::Greater,
        _ => {
            // (αm + β)m against −γ: the sign of p(m).
            let p = match Near::horner(near, m) {
                Some(p) => p,
                None => {
                    let (a, b, neg) = exp?;
                    a.scale(m)?.add(b)?.scale(m)?.compare(&neg[1])?
                }
            };
            if upper { p.reverse() } else { p }
        }
    })
}

/// The most components a coefficient may have for [`Quadratic::solve`] to
/// work on expansions.
const SHORT: usize = 4;

/// Starting guesses in f64 with the cancellation-free formula.
fn guess_roots(a: f64, b: f64, c: f64, disc: f64) -> (f64, f64) {
    let q = -0.5 * (b + disc.sqrt().copysign(b));
    let (r0, r1) = (q / a, c / q);
    if r0 <= r1 { (r0, r1) } else { (r1, r0) }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::dyadic::tests::big_only;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    fn dy(x: f32) -> Dyadic {
        Dyadic::from_f32(x)
    }

    /// A float with a random sign, mantissa and exponent in `lo..hi`
    /// (subnormal below −126), or sometimes a small integer or zero.
    fn random_f32(r: &mut SmallRng, lo: i32, hi: i32) -> f32 {
        if r.random_bool(0.2) {
            return r.random_range(-4..=4) as f32;
        }
        let e = r.random_range(lo..hi);
        let x = r.random_range(1.0..2.0f32) * 2f32.powi(e.max(-126));
        let x = if e < -126 { x * 2f32.powi(e + 126) } else { x };
        if r.random_bool(0.5) { -x } else { x }
    }

    /// The quadratic of a random ray and sphere (`|d|² t² + 2(f·d) t +
    /// |f|² − r²`, `f = o − c`), at one of several scales: ordinary, far
    /// (origin 1e7 away), subnormal and near 1e30.
    fn random_quadratic(r: &mut SmallRng) -> Quadratic {
        use crate::exact::dyadic::{dot, sub3};
        let (lo, hi) = [(-8, 4), (-30, 24), (-149, -120), (90, 104)][r.random_range(0..4)];
        let mut v = |lo, hi| [(); 3].map(|_| dy(random_f32(r, lo, hi)));
        let (o, d, c) = (v(lo, hi), v(lo, hi), v(lo, hi));
        let f = sub3(&o, &c);
        let rad = &f[r.random_range(0..3)] + &d[0];
        let gamma = &dot(&f, &f) - &(&rad * &rad);
        Quadratic::new(dot(&d, &d), dot(&f, &d).mul_pow2(1), gamma)
    }

    fn bits(q: ExactQuadratic) -> String {
        match q {
            ExactQuadratic::One(t) => format!("One({:#x})", t.to_bits()),
            ExactQuadratic::Two(a, b) => format!("Two({:#x}, {:#x})", a.to_bits(), b.to_bits()),
            other => format!("{other:?}"),
        }
    }

    /// `root_against` orders a root against `m` as the signs of `2αm + β`
    /// and `p(m)`, formed by plain sums on big integers, do.
    #[test]
    fn root_against_follows_the_signs_of_the_polynomial() {
        let mut r = SmallRng::seed_from_u64(11);
        let mut sides = [0; 3];
        for _ in 0..3_000 {
            let q = random_quadratic(&mut r);
            if q.alpha.is_zero() || q.discriminant().signum() <= 0 {
                continue;
            }
            let neg = [-&q.beta, -&q.gamma];
            let (g0, g1) = guess_roots(
                q.alpha.to_f64(),
                q.beta.to_f64(),
                q.gamma.to_f64(),
                q.discriminant().to_f64(),
            );
            for g in [g0, g1, 0.0, g0 * 1.0000001, g1 * 0.9999999] {
                let Ok(m) = Dyadic::try_from_f32(g as f32) else {
                    continue;
                };
                let (side, p) = big_only(|| {
                    let am = &q.alpha * &m;
                    let side = (&am.mul_pow2(1) + &q.beta).signum();
                    (side, (&(&(&am + &q.beta) * &m) + &q.gamma).signum())
                });
                let want0 = if side > 0 { Ordering::Less } else { p.cmp(&0) };
                let want1 = if side < 0 {
                    Ordering::Greater
                } else {
                    0.cmp(&p)
                };
                assert_eq!(q.root_against(&neg, &m, false), want0, "{q:?} {g}");
                assert_eq!(q.root_against(&neg, &m, true), want1, "{q:?} {g}");
                sides[(side + 1) as usize] += 1;
            }
        }
        // Both sides of the vertex, each a shortcut for one root.
        assert!(sides[0] > 500 && sides[2] > 500, "{sides:?}");
    }

    /// The sign filter's signs are the exact ones: `p(m)`, `2αm + β` and
    /// the discriminant, over random quadratics at every scale and points
    /// at, beside and between their roots' floats, and at `f64`s next to
    /// the roots, where `p(m)` is near the bound (a bound 2⁹ times too
    /// small fails here); it tells most signs, and declines some near the
    /// roots.
    #[test]
    fn the_filter_tells_only_exact_signs() {
        let mut r = SmallRng::seed_from_u64(13);
        let (mut told, mut declined) = (0, 0);
        let mut check = |got: Option<Ordering>, want: i32| match got {
            Some(g) => {
                assert_eq!(g, want.cmp(&0));
                told += 1;
            }
            None => declined += 1,
        };
        for _ in 0..3_000 {
            let q = random_quadratic(&mut r);
            let e = [&q.alpha, &q.beta, &q.gamma].map(Dyadic::expansion);
            let [Some(a), Some(b), Some(c)] = e else {
                continue;
            };
            let near = [a, b, c].map(|x| Near::of(&x));
            let disc = big_only(|| q.discriminant().signum());
            check(Near::discriminant(&near).0, disc);
            let mut points = vec![0.0, r.random_range(-4.0..4.0f32) as f64];
            // f64 roots, where |p(m)| is near the filter's bound.
            if q.alpha.signum() != 0 && disc > 0 {
                let (g0, g1) = guess_roots(
                    near[0].v,
                    near[1].v,
                    near[2].v,
                    near[1].v * near[1].v - 4.0 * near[0].v * near[2].v,
                );
                for g in [g0, g1] {
                    points.extend([g, g.next_up(), g.next_down()]);
                }
            }
            for t in q.solve().roots() {
                let (lo, hi) = (t.next_down() as f64, t.next_up() as f64);
                points.extend([
                    t as f64,
                    lo,
                    hi,
                    (lo + t as f64) / 2.0,
                    (hi + t as f64) / 2.0,
                ]);
            }
            for m in points.into_iter().filter(|m| m.is_finite()) {
                let dm = Dyadic::from_f64(m);
                let (p, side) = big_only(|| {
                    let am = &q.alpha * &dm;
                    (
                        (&(&(&am + &q.beta) * &dm) + &q.gamma).signum(),
                        (&am.mul_pow2(1) + &q.beta).signum(),
                    )
                });
                check(Near::horner(&near, m), p);
                check(Near::sum([(near[0], 2.0 * m), (near[1], 1.0)]), side);
            }
        }
        assert!(told > 4 * declined && declined > 1_000, "{told} {declined}");
    }

    /// The filter's bounds are the derivation's: each of `p(m)`, `Σxᵢkᵢ`
    /// and `β² − 4αγ` is told where its `f64` value lies beyond `FILTER`
    /// times its magnitudes (formed as the module says) plus `TINY`, and
    /// declined within, at a tenth either side; a value below `TINY` is
    /// never told. The magnitudes and the points are spread (`|m|` up to
    /// `2²⁰`, magnitudes from `2⁻¹⁰` to `2¹⁰`), so that a slip in how they
    /// combine moves the bound by far more than a tenth.
    #[test]
    fn the_filters_bounds_are_the_derivations() {
        let n = |v: f64, mag: f64| Near { v, mag };
        // Each case with its value set to `scale` times the derived bound.
        let at = |scale: f64, m: f64, mags: [f64; 3]| {
            let [ma, mb, mc] = mags;
            let horner = (ma * m.abs() + mb) * m.abs() + mc;
            let sum = ma * (2.0 * m).abs() + mb;
            let disc = mb * mb + 4.0 * ma * mc;
            let v = |mag: f64| scale * (FILTER * mag + TINY);
            // p(m) = v: all of it in γ; 2αm + β = v: all of it in β; the
            // discriminant −4α̂γ̂ = v with β̂ = 0, α̂ = ½.
            let p = Near::horner(&[n(0.0, ma), n(0.0, mb), n(v(horner), mc)], m);
            let side = Near::sum([(n(0.0, ma), 2.0 * m), (n(v(sum), mb), 1.0)]);
            let d = Near::discriminant(&[n(0.5, ma), n(0.0, mb), n(-v(disc) / 2.0, mc)]);
            [p, side, d.0]
        };
        let mags = [
            [1.0, 0.0, 0.0],
            [2f64.powi(10), 1.0, 2f64.powi(-10)],
            [1.0, 2f64.powi(10), 3.0],
        ];
        for m in [1.0, -3.0, 2f64.powi(20), -2f64.powi(-7)] {
            for mags in mags {
                let what = format!("m = {m}, magnitudes {mags:?}");
                assert_eq!(at(1.1, m, mags), [Some(Ordering::Greater); 3], "{what}");
                assert_eq!(at(0.9, m, mags), [None; 3], "{what}");
                assert_eq!(at(-1.1, m, mags), [Some(Ordering::Less); 3], "{what}");
            }
        }
        // Nothing below TINY = 2⁻⁹⁰⁰, however small the magnitudes.
        let tiny = |v: f64| Near::sum([(n(v, 0.0), 1.0)]);
        assert_eq!(tiny(2f64.powi(-901)), None);
        assert_eq!(tiny(-(2f64.powi(-901))), None);
        assert_eq!(tiny(2f64.powi(-899)), Some(Ordering::Greater));
        // The discriminant's value comes back with its sign, β̂² in it.
        let (sign, v) = Near::discriminant(&[n(1.0, 1.0), n(3.0, 3.0), n(2.0, 2.0)]);
        assert_eq!((sign, v), (Some(Ordering::Greater), 1.0));
    }

    /// Where every coefficient is short once compressed, the solve is
    /// decided on expansions alone: no dyadic product, over random
    /// quadratics at every scale, tangents and double roots among them;
    /// and the comparisons the filter cannot tell, at roots near a
    /// midpoint and at exact double roots, are among them.
    #[test]
    fn short_expansions_decide_without_dyadics() {
        use crate::exact::dyadic::tests::products_during;
        let mut r = SmallRng::seed_from_u64(14);
        let (mut short, mut long) = (0, 0);
        for _ in 0..3_000 {
            let q = random_quadratic(&mut r);
            let e = [&q.alpha, &q.beta, &q.gamma].map(Dyadic::expansion);
            let [Some(a), Some(b), Some(c)] = e else {
                continue;
            };
            if [a, b, c]
                .iter()
                .any(|x| x.compress().components().len() > SHORT)
            {
                continue;
            }
            long += usize::from([a, b, c].iter().any(|x| x.components().len() > SHORT));
            short += 1;
            let (got, n) = products_during(|| q.solve());
            assert_eq!(n, 0, "{q:?}: {got:?} formed {n} dyadic products");
        }
        // Most are short, and some only once compressed.
        assert!(
            short > 2_000 && long > 50,
            "{short} short, {long} long before compression"
        );
    }

    /// Solving on `i128` mantissas gives bit for bit what solving on big
    /// integers alone gives, at every scale.
    #[test]
    fn solve_matches_big_integers() {
        let mut r = SmallRng::seed_from_u64(12);
        let mut two = 0;
        for _ in 0..3_000 {
            let q = random_quadratic(&mut r);
            let got = q.solve();
            assert_eq!(bits(got), bits(big_only(|| q.solve())), "{q:?}");
            two += usize::from(matches!(got, ExactQuadratic::Two(..)));
        }
        assert!(two > 500, "{two}");
    }

    /// (t − r0)(t − r1)·s with exactly representable roots must give them back.
    #[test]
    fn representable_roots_come_back_exactly() {
        let pairs = [
            (1.0f32, 2.0f32),
            (-3.5, 1e-7),
            (0.0, 5.0),
            (-1e20, 1e-20),
            (1.0, 1.0 + f32::EPSILON),
        ];
        for (r0, r1) in pairs {
            for s in [1.0f32, -3.0, 1e-30] {
                let (r0d, r1d, sd) = (dy(r0), dy(r1), dy(s));
                let beta = -&(&(&r0d + &r1d) * &sd);
                let gamma = &(&r0d * &r1d) * &sd;
                let q = Quadratic::new(sd, beta, gamma);
                assert_eq!(q.solve(), ExactQuadratic::Two(r0, r1), "{r0} {r1} {s}");
            }
        }
    }

    /// The f64 guesses only decide how long the exact search takes, so
    /// that is what is tested: a good guess is within an ulp or two of
    /// each root, and the search then settles in a few comparisons where
    /// a guess of 0 (or a wrong sign) needs 60 or more. Over these
    /// quadratics (two roots, a double root, a linear one, roots far
    /// apart) each root costs at most 12, on the expansions and on the
    /// dyadics alone (`solve_dyadic`'s guesses are its own).
    #[test]
    fn good_guesses_make_the_search_short() {
        use crate::exact::dyadic::tests::big_only;
        use crate::exact::round::comparisons;
        let q = |a: f32, b: f32, c: f32| Quadratic::new(dy(a), dy(b), dy(c));
        let cases = [
            (q(1.0, -3.0, 2.0), 2),
            (q(3.0, 7.0, -11.0), 2),
            (q(1.0, -1e8, 1.0), 2),
            (q(2.0, -8.0, 8.0), 1),
            (q(4.0, -12.0, 9.0), 1),
            (q(0.0, 3.0, -7.0), 1),
            (q(0.0, 5.0, 2.0), 1),
        ];
        for (quad, roots) in cases {
            for dyadic in [false, true] {
                let mut out = ExactQuadratic::None;
                let solve = || out = quad.solve();
                let n = if dyadic {
                    big_only(|| comparisons::during(solve))
                } else {
                    comparisons::during(solve)
                };
                assert_eq!(out.roots().len(), roots, "{out:?}");
                assert!(n <= 12 * roots, "{out:?}, dyadic {dyadic}: {n} comparisons");
            }
        }
    }

    /// The debug form names the three coefficients, as normalised, and
    /// not the expansions kept beside them.
    #[test]
    fn the_debug_form_shows_the_normalised_coefficients() {
        let q = Quadratic::new(dy(-2.0), dy(3.0), dy(0.5));
        let want = format!(
            "Quadratic {{ alpha: {:?}, beta: {:?}, gamma: {:?} }}",
            dy(2.0),
            dy(-3.0),
            dy(-0.5)
        );
        assert_eq!(format!("{q:?}"), want);
    }

    #[test]
    fn degenerate_classes() {
        let q = |a: f32, b: f32, c: f32| Quadratic::new(dy(a), dy(b), dy(c)).solve();
        assert_eq!(q(0.0, 0.0, 0.0), ExactQuadratic::All);
        assert_eq!(q(0.0, 0.0, 1.0), ExactQuadratic::None);
        assert_eq!(q(0.0, -4.0, 1.0), ExactQuadratic::One(0.25));
        assert_eq!(q(1.0, -2.0, 1.0), ExactQuadratic::One(1.0));
        assert_eq!(q(1.0, 0.0, 1.0), ExactQuadratic::None);
        assert_eq!(q(-1.0, 0.0, 1.0), ExactQuadratic::Two(-1.0, 1.0));
    }

    #[test]
    fn irrational_roots_are_correctly_rounded() {
        // t² − 2 and t² − 3: compare with f64 sqrt, which is accurate enough
        // here that its rounding to f32 is the correct rounding.
        for k in [2.0f32, 3.0, 5.0, 1e10] {
            let r = Quadratic::new(dy(1.0), Dyadic::ZERO, -dy(k)).solve();
            let s = (k as f64).sqrt() as f32;
            assert_eq!(r, ExactQuadratic::Two(-s, s));
        }
    }
}
