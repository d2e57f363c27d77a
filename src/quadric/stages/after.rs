//! The later stages ([`later`]): what runs after the [filter](super)
//! leaves a line undecided, before the exact oracle. The order and each
//! stage's part are listed in the [filter's module](super).

use super::{Left, QUADRATIC, classes_paired, grid, grids, sorted_from, terms};
#[cfg(target_arch = "x86_64")]
use crate::num::avx::Avx2;
use crate::num::certify::{SLACK, U, certify, div};
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
use crate::num::dd::Fma;
#[cfg(any(target_arch = "x86_64", target_feature = "fma"))]
use crate::num::dd::Fused;
use crate::num::dd::{
    Acc, Approx, BuildProduct, Dd, Dekker, GridAcc, Product, quotient, two_roots, two_sum,
};
use crate::num::real::Real;
use crate::num::tracked::Tracked;
use crate::quadric::QuadricHit;
use crate::stage::Stage;

/// The terms of α, β and γ, each exactly as two words ([`Pair`]): `k·x`
/// is exact (two f32 values), its product with `y` is split by
/// TwoProduct (`P`), exact since every such product is a multiple of
/// `2⁻⁴⁴⁷` below `2³⁸⁴`. Computed once for both later stages.
/// With them, a grid every term lies on ([`grid()`]).
#[derive(Clone, Copy)]
pub(super) struct ExactTerms(
    pub(super) [Pair; 6],
    pub(super) [Pair; 12],
    pub(super) [Pair; 10],
    pub(super) f64,
);

impl ExactTerms {
    #[inline(always)]
    pub(super) fn new<P: Product>(k: &[f64; 10], o: [f64; 3], d: [f64; 3]) -> ExactTerms {
        ExactTerms::on::<P>(k, o, d, grid(k, o, d))
    }
    /// [`ExactTerms::new`] with the data's [`grid()`] already found.
    #[inline(always)]
    fn on<P: Product>(k: &[f64; 10], o: [f64; 3], d: [f64; 3], grid: f64) -> ExactTerms {
        let (kp, op, dp) = (pairs(k), pairs(&o), pairs(&d));
        let (a, b, g) = terms(&kp, op, dp, Pair(1.0, 0.0), |c, x, y| {
            let (h, l) = P::two_prod(c.0 * x.0, y.0);
            Pair(h, l)
        });
        ExactTerms(a, b, g, grid)
    }
}

/// The second stage: α, β, γ and `β² − 4αγ` tracked for exactness
/// ([`Tracked`]), each term `k·x·y` as `k·x` (a product of two f32
/// values, exact in f64) times `y`, checked. The sums of the terms need no
/// check where the sum of their magnitudes is below `2⁵²g`, `g` the data's
/// [`grid()`]; elsewhere they are summed in double words ([`GridAcc`]),
/// exact where the errors' magnitudes sum below `2⁵²g`, and a sum is one
/// f64 where its low word is then 0. Where no
/// operation rounded, the class follows from signs, as in pbrt-v4's
/// `Quadratic` with its α = 0 branch: a linear root `−γ/β` or a double
/// root `−β/2α` rounds once (certified with `2u`); two roots `q/α` and
/// `γ/q` from `s = √Δ` are within `4u` (certified with `8u`). `None` where
/// an operation rounded or a root sits next to an f32 rounding boundary.
///
/// ```
/// use rayoracle::quadric::{QuadricHit, stages::tracked};
/// // The cone x² + y² − z² = 0 through its apex: a double root at 0.
/// let cone = [1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
/// assert_eq!(tracked(&cone, [-1.0, 0.0, -2.0], [1.0, 0.0, 2.0]), Some(QuadricHit::One(1.0)));
/// // A line on the cylinder x² + y² = 1: every t.
/// let cyl = [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// assert_eq!(tracked(&cyl, [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]), Some(QuadricHit::All));
/// ```
pub fn tracked(k: &[f64; 10], o: [f64; 3], d: [f64; 3]) -> Option<QuadricHit> {
    tracked_in::<Dekker>(&ExactTerms::new::<Dekker>(k, o, d), 1.0).0
}

/// What [`tracked_in`] leaves [`double_word_of`]: α, β and γ as far as it
/// summed them.
#[derive(Clone, Copy, Debug)]
enum Sums {
    /// Not summed: a term rounded.
    Terms,
    /// Each one f64, exactly: the sums on the grid, or checked.
    Exact([f64; 3]),
    /// Each as double words with its bound, summed as the double-word
    /// stage sums the terms first ([`GridAcc`]): data whose terms fail the
    /// grid test, which their errors may still pass.
    Words([Dd; 3]),
}

/// [`tracked`] on the exact terms: a term rounded in f64 exactly where its
/// low word is nonzero (a nonzero exact product of three f32 values is at
/// least `2⁻⁴⁴⁷`, far above [`Tracked::mul`]'s `2⁻⁹⁰⁰`; a non-finite
/// input makes a low word NaN). With the answer, α, β and γ where they
/// were computed exactly (and are finite), so that [`double_word`] need
/// not sum their terms again where this stage gives no answer: as one
/// exact f64 each, or, where the terms fail the grid test, as the double
/// words of [`GridAcc`] (bounds multiplied by `shrink`), which prove a sum
/// exact in one f64 where they are exact and the low word is 0.
#[inline(always)]
fn tracked_in<P: Product>(t: &ExactTerms, shrink: f64) -> (Option<QuadricHit>, Sums) {
    match tracked_by::<P, false>(t, shrink) {
        Some(r) => r,
        None => (None, Sums::Terms),
    }
}

/// [`tracked_in`]; where `FAST`, the sums of [`grid_sums`] without their
/// running bounds, and `None` where a grid test fails.
#[inline(always)]
fn tracked_by<P: Product, const FAST: bool>(
    t: &ExactTerms,
    shrink: f64,
) -> Option<(Option<QuadricHit>, Sums)> {
    // Most data that is not small integers or dyadic rounds here already.
    let mut rounded = false;
    let mut any = |v: &[Pair]| v.iter().for_each(|p| rounded |= p.1 != 0.0);
    any(&t.0);
    any(&t.1);
    any(&t.2);
    if rounded {
        return Some((None, Sums::Terms));
    }
    let mut x = Tracked::new();
    // The terms are multiples of the grid g: where their magnitudes sum
    // below 2⁵²g, every partial sum, in any order, is a multiple of g
    // below 2⁵³g, exact, and plain sums need no check (the sum of
    // magnitudes is within 28u of its computed value, covered by SLACK).
    // Two interleaved chains halve the wait on the additions.
    let plain = |v: &[Pair]| {
        let (mut s, mut m) = ([0.0; 2], [0.0; 2]);
        for (i, y) in v.iter().enumerate() {
            s[i % 2] += y.0;
            m[i % 2] += y.0.abs();
        }
        (s[0] + s[1], m[0] + m[1])
    };
    let ((a, ma), (b, mb), (g, mg)) = (plain(&t.0), plain(&t.1), plain(&t.2));
    let (alpha, beta, gamma) = if (ma + mb + mg) * SLACK < t.3 * 4_503_599_627_370_496.0 {
        (a, b, g)
    } else {
        // Double words, whose errors need only sum below 2⁵²g: where the
        // sums do not fit one f64 (most data of spread exponents), the
        // double-word stage takes the words as they are.
        // Not `array::map`, which is not always inlined.
        let words = grid_sums::<FAST>(t)?;
        if !words.iter().all(|w| w.err == 0.0 && w.lo == 0.0) {
            let shrunk = |w: Dd| Dd {
                err: w.err * shrink,
                ..w
            };
            let words = [shrunk(words[0]), shrunk(words[1]), shrunk(words[2])];
            return Some((None, Sums::Words(words)));
        }
        (words[0].hi, words[1].hi, words[2].hi)
    };
    let sums = [alpha, beta, gamma];
    let sums = if sums.iter().all(|v| v.is_finite()) {
        Sums::Exact(sums)
    } else {
        Sums::Terms
    };
    Some((tracked_roots::<P>(&mut x, alpha, beta, gamma), sums))
}

/// α, β and γ as [`GridAcc`]s sum their exact terms on the data's grid,
/// with their bounds; where `FAST`, without the running bounds, which
/// serve only where a grid test fails: then the sums where every test
/// passes (`err = 0`, the same words), `None` elsewhere.
#[inline(always)]
fn grid_sums<const FAST: bool>(t: &ExactTerms) -> Option<[Dd; 3]> {
    if FAST {
        let exact = |v: &[Pair]| {
            let mut acc = GridAcc::new();
            v.iter().for_each(|p| acc.add_pair_unbounded((p.0, p.1)));
            acc.finish_exact(t.3)
        };
        let (a, b, g) = (exact(&t.0), exact(&t.1), exact(&t.2));
        Some([a?, b?, g?])
    } else {
        let word = |v: &[Pair]| {
            let mut acc = GridAcc::new();
            v.iter().for_each(|p| acc.add_pair((p.0, p.1)));
            acc.finish(t.3)
        };
        Some([word(&t.0), word(&t.1), word(&t.2)])
    }
}

/// The rest of [`tracked`] from α, β and γ, the tracker `x` noting
/// whether any operation rounded.
#[inline(always)]
fn tracked_roots<P: Product>(
    x: &mut Tracked,
    alpha: f64,
    beta: f64,
    gamma: f64,
) -> Option<QuadricHit> {
    let b2 = x.mul_by::<P>(beta, beta);
    let ag = x.mul_by::<P>(4.0 * alpha, gamma);
    let disc = x.sub(b2, ag);
    // The doubled β terms and 4α are exact unless they overflow, which the
    // checks below see as a non-finite value.
    if !x.exact() || !disc.is_finite() || !beta.is_finite() {
        return None;
    }
    let one = |t: f64| certify(t, 2.0 * U, 0.0).then_some(QuadricHit::One(t as f32));
    if alpha == 0.0 {
        return match (beta == 0.0, gamma == 0.0) {
            (true, true) => Some(QuadricHit::All),
            (true, false) => Some(QuadricHit::None),
            _ => one(div(-gamma, beta)),
        };
    }
    if disc < 0.0 {
        return Some(QuadricHit::None);
    }
    if disc == 0.0 {
        return one(div(-beta, 2.0 * alpha));
    }
    let q = -0.5 * (beta + disc.sqrt().copysign(beta));
    let (t0, t1) = (q / alpha, div(gamma, q));
    let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
    let ok = certify(t0, 8.0 * U, 0.0) && certify(t1, 8.0 * U, 0.0);
    ok.then_some(QuadricHit::Two(t0 as f32, t1 as f32))
}

/// A term `c·x·y` as two words: `c·x` is exact (two f32 values), its
/// product with `y` is split by TwoProduct. `+` serves only β's doubling,
/// which is exact word by word.
#[derive(Clone, Copy)]
pub(super) struct Pair(pub(super) f64, pub(super) f64);

impl core::ops::Add for Pair {
    type Output = Pair;
    #[inline(always)]
    fn add(self, o: Pair) -> Pair {
        Pair(self.0 + o.0, self.1 + o.1)
    }
}

/// Each value as a pair with a zero low word, by a plain loop (`array::map`
/// is not always inlined).
#[inline(always)]
fn pairs<const N: usize>(x: &[f64; N]) -> [Pair; N] {
    let mut p = [Pair(0.0, 0.0); N];
    for (p, x) in p.iter_mut().zip(x) {
        p.0 = *x;
    }
    p
}

/// The double-word stage ([`crate::num::dd`]): every term `k·x·y` of α, β
/// and γ exactly as two words (a multiple of `2⁻⁴⁴⁷`), each coefficient
/// their sum in two words, and `Δ/4 = (β/2)² − αγ` as the sum of the exact
/// products of their words (multiples of `2⁻⁸⁹⁶`, so TwoProduct is exact).
/// The sums are [`GridAcc`]s on the grid of the data ([`grid()`]), and
/// [`Acc`]s, which check each low addition, where that grid is too fine
/// to prove them exact. `Δ` is first taken from the leading words
/// ([`disc_near`]) and summed exactly only where that leaves its sign or
/// the roots undecided.
/// Where no low word rounded, α, β, γ and `Δ` are exact, and so are their
/// signs and zeros: α = 0 (the linear root `−γ/β`, or the whole line, or
/// nothing), a double root `−β/2α` (pbrt-v4's `Quadratic` branches);
/// otherwise their bounds decide the signs or nothing does. The roots are
/// certified from the leading words with `|lo| + err` as their bounds
/// ([`quotient`]; two roots in the filter's sorted form `(−β ∓ √Δ)/2α`, where
/// it certifies them, else by [`two_roots`] with `b = β/2`). Every bound
/// is multiplied by `shrink`.
///
/// ```
/// use rayoracle::quadric::{QuadricHit, stages::{double_word, tracked}};
/// // The double plane (x − z)² = x² − 2xz + z² = 0, crossed at 0.1f32
/// // along (0.3f32, 0, 0.1f32): Δ = 0 exactly, but β² rounds in f64.
/// let k = [1.0, 0.0, 1.0, 0.0, -2.0, 0.0, 0.0, 0.0, 0.0, 0.0];
/// let (o, d) = ([0.1f32 as f64, 0.0, 0.0], [0.3f32 as f64, 0.0, 0.1f32 as f64]);
/// assert_eq!(tracked(&k, o, d), None);
/// let h = double_word(&k, o, d, 1.0);
/// assert!(matches!(h, Some(QuadricHit::One(t)) if t < 0.0));
/// ```
pub fn double_word(k: &[f64; 10], o: [f64; 3], d: [f64; 3], shrink: f64) -> Option<QuadricHit> {
    double_word_of::<Dekker>(&ExactTerms::new::<Dekker>(k, o, d), Sums::Terms, shrink)
}

/// [`double_word`] on the exact terms, and on α, β and γ as far as
/// [`tracked`] summed them ([`Sums`]), which it does not sum again.
#[inline(always)]
fn double_word_of<P: Product>(t: &ExactTerms, sums: Sums, shrink: f64) -> Option<QuadricHit> {
    let coefficients = dd_sums::<false>(t, sums)?;
    double_word_rest::<P>(t, coefficients, shrink)
}

/// α, β and γ for [`double_word_of`] from what [`tracked_in`] left it;
/// where `FAST`, summed by [`grid_sums`] without running bounds, `None`
/// where a grid test fails.
#[inline(always)]
fn dd_sums<const FAST: bool>(t: &ExactTerms, sums: Sums) -> Option<(Dd, Dd, Dd)> {
    Some(match sums {
        Sums::Exact(v) => {
            let [alpha, beta, gamma] = v.map(|hi| Dd {
                hi,
                lo: 0.0,
                err: 0.0,
            });
            (alpha, beta, gamma)
        }
        Sums::Words([a, b, g]) => (a, b, g),
        Sums::Terms => {
            let [a, b, g] = grid_sums::<FAST>(t)?;
            (a, b, g)
        }
    })
}

/// [`double_word_of`] from α, β and γ.
#[inline(always)]
fn double_word_rest<P: Product>(
    t: &ExactTerms,
    (alpha, beta, gamma): (Dd, Dd, Dd),
    shrink: f64,
) -> Option<QuadricHit> {
    // Where the grid test fails (data of widely spread exponents), the
    // sums again with every low addition checked.
    let (alpha, beta, gamma) = if alpha.err == 0.0 && beta.err == 0.0 && gamma.err == 0.0 {
        (alpha, beta, gamma)
    } else {
        let sum = |v: &[Pair]| {
            let mut acc = Acc::new();
            v.iter().for_each(|p| acc.add_pair((p.0, p.1)));
            acc.finish()
        };
        (sum(&t.0), sum(&t.1), sum(&t.2))
    };
    let single = |x: &Dd| x.lo == 0.0 && x.err == 0.0;
    let exact = single(&alpha) && single(&beta) && single(&gamma);
    double_word_coefficients::<P>(t.3, exact, (alpha, beta, gamma), shrink)
}

/// The double-word stage from α, β and γ as double words with their
/// bounds (`exact` where each is one f64, exactly), on the data's
/// [`grid()`].
///
/// Where each is one exact f64, `Δ/4 = (β/2)² − αγ` is first taken from
/// the two products' TwoProduct words ([`single_word_disc`]), which
/// decides the sign and gives the roots wherever `Δ ≠ 0`; an exact `Δ =
/// 0` takes the exact sum below.
#[inline(always)]
fn double_word_coefficients<P: Product>(
    grid: f64,
    exact: bool,
    (alpha, beta, gamma): (Dd, Dd, Dd),
    shrink: f64,
) -> Option<QuadricHit> {
    let h = match decide_words::<P>(exact, (alpha, beta, gamma), shrink) {
        Some(h) => return h,
        None => beta.scale(0.5),
    };
    // β/2's words are multiples of g/2, α's and γ's of g: the products,
    // of g²/4 (at least 2⁻⁸⁹⁶, a normal f64).
    let mut disc = GridAcc::wide();
    if exact {
        // One word each: the two exact products alone.
        disc.add_pair(P::two_prod(h.hi, h.hi));
        disc.add_pair(P::two_prod(-alpha.hi, gamma.hi));
    } else {
        disc.add_square_by::<P>(h);
        disc.add_dd_prod_by::<P>(alpha.scale(-1.0), gamma);
    }
    let mut disc = disc.finish(grid * grid * 0.25);
    // As for the coefficients: where exact data fails the grid test, the
    // sum with every low addition checked.
    if disc.err != 0.0 && alpha.err == 0.0 && beta.err == 0.0 && gamma.err == 0.0 {
        let mut acc = Acc::wide();
        acc.add_dd_prod(h, h);
        acc.add_dd_prod(alpha.scale(-1.0), gamma);
        disc = acc.finish();
    }
    let class = disc.shrunk(shrink);
    if class.is_zero() {
        let t = quotient(-h.approx(), alpha.approx(), shrink)?;
        return Some(QuadricHit::One(t));
    }
    if !class.sign_known() {
        return None;
    }
    if disc.hi < 0.0 {
        return Some(QuadricHit::None);
    }
    let (a, b, c) = (alpha.approx(), h.approx(), gamma.approx());
    let (t0, t1) = two_roots(a, b, c, disc.approx(), shrink)?;
    Some(QuadricHit::Two(t0, t1))
}

/// The double-word stage's classes and roots from α, β and γ as double
/// words with their bounds (`exact` where each is one f64, exactly),
/// without the exact sum of `Δ`: `Some` with the stage's answer (`None`
/// in it where the stage cannot decide), or `None` where only the exact
/// sum of `Δ` can. α's zero and sign, and β's and γ's where α = 0, from
/// their bounds; then `Δ` from the leading words ([`disc_near`]) where
/// the sums are not exact, from [`single_word_disc`] where they are. Two
/// roots from the leading words first as the filter's sorted form takes
/// them ([`sorted_from`], with `β = 2b`, `Δ = 4(b² − ac)` and their
/// bounds scaled exactly), where no division waits on the square root,
/// else by [`two_roots`].
#[inline(always)]
fn decide_words<P: Product>(
    exact: bool,
    (alpha, beta, gamma): (Dd, Dd, Dd),
    shrink: f64,
) -> Option<Option<QuadricHit>> {
    // The bounds as derived; `shrink` scales each once, where it decides:
    // the classes through `shrunk`, the roots in `quotient`, `disc_near`'s
    // test and `two_roots`.
    let (sa, sb, sg) = (
        alpha.shrunk(shrink),
        beta.shrunk(shrink),
        gamma.shrunk(shrink),
    );
    if sa.is_zero() {
        return Some(if sb.is_zero() {
            if sg.is_zero() {
                Some(QuadricHit::All)
            } else {
                sg.sign_known().then_some(QuadricHit::None)
            }
        } else if sb.sign_known() {
            quotient(-gamma.approx(), beta.approx(), shrink).map(QuadricHit::One)
        } else {
            None
        });
    }
    if !sa.sign_known() {
        return Some(None);
    }
    let b = beta.scale(0.5);
    let (a, bb, c) = (alpha.approx(), b.approx(), gamma.approx());
    // Most Δ are far from 0 once α, β and γ are this close: decided from
    // the leading words; the exact sum below only where that fails, and
    // at once where α, β and γ are single exact words (two products,
    // above).
    let near = disc_near(a, bb, c, 1.0);
    if !exact && near.v.abs() > 2.0 * near.e * shrink {
        if near.v < 0.0 {
            return Some(Some(QuadricHit::None));
        }
        // The filter's sorted roots first (no division waits on the
        // square root), from β = 2b and Δ = 4(b² − ac), scaled exactly.
        let bounds = noted3((a.e * shrink, 2.0 * bb.e * shrink, 4.0 * near.e * shrink));
        if let Some((t0, t1)) = sorted_from(a.v, 2.0 * bb.v, 4.0 * near.v, bounds, shrink) {
            let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
            return Some(Some(QuadricHit::Two(t0 as f32, t1 as f32)));
        }
        if let Some((t0, t1)) = two_roots(a, bb, c, near, shrink) {
            return Some(Some(QuadricHit::Two(t0, t1)));
        }
    }
    if exact {
        let disc = single_word_disc::<P>(alpha.hi, b.hi, gamma.hi);
        if disc.v.abs() > noted(disc.e * shrink) {
            if disc.v < 0.0 {
                return Some(Some(QuadricHit::None));
            }
            if let Some((t0, t1)) = two_roots(a, bb, c, disc, shrink) {
                return Some(Some(QuadricHit::Two(t0, t1)));
            }
        }
    }
    None
}

/// `Δ/4 = b² − ac` for single exact words `a`, `b` and `c` (the data's
/// products, multiples of `g²/4 ≥ 2⁻⁸⁹⁶`: no underflow), from the
/// TwoProduct words `h₁ + l₁ = b²` and `h₂ + l₂ = ac`: `Δ/4 = (h₁ − h₂) +
/// (l₁ − l₂)`, three roundings. Each rounds to nearest, so it is within
/// `u` of its own result: `E = u(|d̂ₕ| + |d̂ₗ| + |Δ̂|)` for the two
/// differences and their sum (the bound's own roundings in [`SLACK`]).
/// Where `Δ = 0` the two products' words are equal (TwoProduct's split of
/// a value is unique), so `Δ̂ = 0`, which no bound decides.
#[inline(always)]
fn single_word_disc<P: Product>(a: f64, b: f64, c: f64) -> Approx {
    let (h1, l1) = P::two_prod(b, b);
    let (h2, l2) = P::two_prod(a, c);
    let (dh, dl) = (h1 - h2, l1 - l2);
    let v = dh + dl;
    let e = U * (dh.abs() + dl.abs() + v.abs()) * SLACK;
    Approx { v, e }
}

/// `Δ/4 = b² − ac` in f64 from approximations with bounds, and a bound on
/// its error (multiplied by `shrink`). With `|b − b̂| ≤ e_b` and so on,
/// `|b² − b̂²| ≤ e_b(2|b̂| + e_b)` and `|ac − âĉ| ≤ |â|e_c + e_a(|ĉ| +
/// e_c)`; the two products and the difference round three times, within
/// `(2u + u²)(b̂² + |âĉ|)`, counted `3u`. The bound's own roundings (a
/// dozen operations) are covered by [`SLACK`]. The products are of degree
/// six in f32 data, so neither overflows nor leaves the normal range
/// (see Range above), and a value certain of its sign (`|Δ̂| > 2E`, with
/// `E ≥ 3u b̂²`) is normal too.
///
/// ```
/// use rayoracle::num::dd::Approx;
/// # use rayoracle::quadric::stages::disc_near;
/// let x = |v: f64| Approx { v, e: 1e-20 };
/// // t² − 10t + 24: b = −5, Δ/4 = 25 − 24 = 1.
/// let d = disc_near(x(1.0), x(-5.0), x(24.0), 1.0);
/// assert!(d.v == 1.0 && d.e > 1e-19 && d.e < 1e-13);
/// ```
#[doc(hidden)]
#[inline(always)]
pub fn disc_near(a: Approx, b: Approx, c: Approx, shrink: f64) -> Approx {
    let (b2, ac) = (b.v * b.v, a.v * c.v);
    let v = b2 - ac;
    let data = b.e * (2.0 * b.v.abs() + b.e) + a.v.abs() * c.e + a.e * (c.v.abs() + c.e);
    let e = (data + 3.0 * U * (b2 + ac.abs())) * SLACK * shrink;
    Approx { v, e }
}

/// The tight stage: α in double words, and β and γ as the filter left them,
/// within its `E_β = 24u m_β` and `E_γ = 20u m_γ`. That settles a line
/// nearly parallel to an axis of a cylinder or a paraboloid, whose α
/// cancels below the filter's `E_α` while β and γ are clear of their
/// bounds. A coefficient whose terms' magnitudes sum below `2⁵²g` (`g`
/// its own grid, [`grids()`]) is exact as the filter summed it (every term
/// a multiple of `g`, every partial sum below `2⁵³g`), and its bound is
/// 0; otherwise α is the sum of its six terms in double words, each term
/// exact by TwoProduct, on α's grid ([`GridAcc`]: exact where its grid
/// test passes, within its running bound elsewhere). The grids are the
/// coefficients' own, not the data's: on a line along a cylinder's
/// integer axis from an origin of many bits, α = β = 0 is proven here,
/// next to a γ whose terms round.
///
/// * α = β = 0, both exact: no root where `|γ̂| > E_γ`, every `t` where
///   γ is exactly 0 too;
/// * α = 0 exactly and `|β̂| > E_β`: the linear root `−γ/β`, the
///   [`quotient`] of values with bounds;
/// * α's sign certain: `Δ/4 = (β/2)² − αγ` by [`disc_near`], no root
///   where it is certainly negative, else the roots by [`two_roots`],
///   certified.
///
/// Every bound is multiplied by `shrink` where it decides. `None` where
/// nothing is certain.
///
/// ```
/// use rayoracle::quadric::{QuadricHit, stages::tight};
/// // The cylinder x² + y² = 1 along (1, 0, 2⁻³⁰) from (−2, 0, 0) after
/// // a rotation that makes α = 1 − 2⁻⁶⁰… cancel in f64: here α = 2⁻⁶⁰
/// // outright, along (2⁻³⁰, 0, 1).
/// let cyl = [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// let h = tight(&cyl, [-2.0, 0.0, 0.0], [2f64.powi(-30), 0.0, 1.0], 1.0);
/// assert!(matches!(h, Some(QuadricHit::Two(..))));
/// ```
pub fn tight(k: &[f64; 10], o: [f64; 3], d: [f64; 3], shrink: f64) -> Option<QuadricHit> {
    let left = classes_paired(k, o, d, 1.0).left();
    tight_by::<Dekker>(k, o, d, &left, shrink)
}

/// [`tight`] from what the filter left, the products' errors found by `P`.
#[inline(always)]
fn tight_by<P: Product>(
    k: &[f64; 10],
    o: [f64; 3],
    d: [f64; 3],
    left: &Left,
    shrink: f64,
) -> Option<QuadricHit> {
    let g = grids(k, o, d);
    let [xa, xb, xg] = left.exact(g);
    let ((alpha, _), (beta, mb), (gamma, mg)) = (left.alpha, left.beta, left.gamma);
    let bound = |exact: bool, e: f64| if exact { 0.0 } else { e };
    let (eb, eg) = (bound(xb, 24.0 * U * mb), bound(xg, 20.0 * U * mg));
    if xa && xb && alpha == 0.0 && beta == 0.0 {
        return if gamma.abs() > noted(eg * shrink) {
            Some(QuadricHit::None)
        } else {
            (xg && gamma == 0.0).then_some(QuadricHit::All)
        };
    }
    // Whatever α is, the root near `−γ/β` is within about `E_γ/|γ̂| +
    // E_β/|β̂|` of it relatively, which must be below 2⁻²⁴ for it to
    // certify: where it is not (β or γ may be 0, or cancels), the double
    // words, without computing α.
    let (b24, g24) = (eb * 16_777_216.0, eg * 16_777_216.0);
    if !(beta.abs() > b24 && gamma.abs() >= g24) {
        return None;
    }
    let alpha = if xa {
        Dd {
            hi: alpha,
            lo: 0.0,
            err: 0.0,
        }
    } else {
        let mut acc = GridAcc::new();
        for &(c, i, j) in &QUADRATIC {
            acc.add_pair(P::two_prod(k[c] * d[i], d[j]));
        }
        acc.finish(g[0])
    };
    let sa = alpha.shrunk(shrink);
    if sa.is_zero() {
        let (x, y) = (Approx { v: -gamma, e: eg }, Approx { v: beta, e: eb });
        return quotient(x, y, shrink).map(QuadricHit::One);
    }
    if !sa.sign_known() {
        return None;
    }
    let a = alpha.approx();
    let (b, c) = (
        Approx {
            v: 0.5 * beta,
            e: 0.5 * eb,
        },
        Approx { v: gamma, e: eg },
    );
    let near = disc_near(a, b, c, 1.0);
    if !(near.v.abs() > noted(2.0 * near.e * shrink)) {
        return None;
    }
    if near.v < 0.0 {
        return Some(QuadricHit::None);
    }
    two_roots(a, b, c, near, shrink).map(|(t0, t1)| QuadricHit::Two(t0, t1))
}

/// The stages after the filter, with the products' errors found by `P`,
/// and the stage that answered: [`words`] where [`words_first`] says so,
/// the perfect square, [`later_head`], then [`tracked`] and
/// [`double_word`] on one computation of the exact terms.
#[inline(always)]
fn later_by<P: Product>(
    k: &[f64; 10],
    o: [f64; 3],
    d: [f64; 3],
    left: Left,
    shrink: f64,
) -> Option<(QuadricHit, Stage)> {
    if words_first(&left) {
        let m = [left.alpha.1, left.beta.1, left.gamma.1];
        if let Some(h) = words_by::<P>(k, o, d, m, shrink) {
            return Some((h, Stage::Tight));
        }
    }
    if let Some(h) = crate::quadric::square::intersect(k, o, d, shrink) {
        return Some((h, Stage::Tight));
    }
    let g = match later_head::<P>(k, o, d, left, shrink) {
        Ok(h) => return h,
        Err(g) => g,
    };
    let t = ExactTerms::on::<P>(k, o, d, g);
    // The sums without their running bounds first; the rare data whose
    // grid tests fail takes both stages again with them.
    let sums = match tracked_by::<P, true>(&t, shrink) {
        Some((Some(h), _)) => return Some((h, Stage::Tracked)),
        Some((None, sums)) => dd_sums::<true>(&t, sums),
        None => None,
    };
    match sums {
        Some(c) => double_word_rest::<P>(&t, c, shrink),
        None => return later_bounded::<P>(&t, shrink),
    }
    .map(|h| (h, Stage::DoubleWord))
}

/// [`later_by`]'s exact sums on a CPU with AVX2 and FMA, after
/// [`later_head`]: α, β and γ summed exactly on four lanes
/// ([`crate::quadric::words`]), then [`tracked`]'s roots where each is one f64,
/// and the [`double_word`] stage on them. The same sums as [`later_by`]'s,
/// so the same answers. The inputs are widened again here, from
/// `inputs`, rather than passed on: the head's widened values, spilled
/// and read back at other widths, stalled store forwarding (cone-apex 29
/// against 46 ns a ray in some builds).
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline(never)]
fn later_avx<I>(_: Avx2, inputs: &I, g: f64, shrink: f64) -> Option<(QuadricHit, Stage)>
where
    I: Fn() -> ([f64; 10], [f64; 3], [f64; 3]),
{
    let (k, o, d) = inputs();
    let Some([a, b, c]) = crate::quadric::words::exact(&k, o, d, g) else {
        return later_bounded::<Fused>(&ExactTerms::on::<Fused>(&k, o, d, g), shrink);
    };
    let single = a.lo == 0.0 && b.lo == 0.0 && c.lo == 0.0;
    if single && let Some(h) = tracked_roots::<Fused>(&mut Tracked::new(), a.hi, b.hi, c.hi) {
        return Some((h, Stage::Tracked));
    }
    double_word_coefficients::<Fused>(g, single, (a, b, c), shrink).map(|h| (h, Stage::DoubleWord))
}

/// [`words`] inside the copy compiled for AVX2 and FMA, its sums on four
/// lanes ([`crate::quadric::words::bounded`]; the same words as
/// [`bounded_words`]), the inputs widened again from `inputs`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline(never)]
fn words_avx<I>(_: Avx2, inputs: &I, m: [f64; 3], shrink: f64) -> Option<QuadricHit>
where
    I: Fn() -> ([f64; 10], [f64; 3], [f64; 3]),
{
    let (k, o, d) = inputs();
    decide_words::<Fused>(
        false,
        crate::quadric::words::bounded(&k, o, d, m).into(),
        shrink,
    )
    .flatten()
}

/// The words stage: α, β and γ in double words with their bounds, then
/// the classes and the roots as the double-word stage takes them from
/// inexact words: α's sign from its bound, `Δ/4 = (β/2)² − αγ` from the
/// leading words ([`disc_near`]), the roots in the filter's sorted form
/// or by [`two_roots`]. The
/// coefficients are within about `u²` of their terms' magnitudes, where
/// the filter's are within `E_α`, `E_β`: it settles lines nearly
/// parallel to a rotated cylinder's axis, whose α and β cancel. It
/// decides no exact zero (its bounds are positive wherever a sum has a
/// nonzero term), which the later stages settle. Every bound is
/// multiplied by `shrink`. `None` where nothing is certain.
///
/// # The sums
///
/// Four sums, as on four lanes (`quadric::words`), one per quadratic
/// coefficient's terms of α, β (two halves) and γ: each term split by
/// TwoProduct (exact, see [`double_word`]), the terms and the linear
/// words added pairwise (`((t₀ + t₁) + (t₂ + t₃)) + ((t₄ + t₅) + (l₀ + l₁))`,
/// then `+ (l₂ + J)`), the leading words by TwoSum and
/// every error into the low word by plain additions; β's halves joined by
/// one more TwoSum; no grid and no check per addition.
///
/// Each coefficient is exactly its leading word plus the low values:
/// TwoProduct's errors, each within `u` of its term's product, and
/// TwoSum's, each within `u` of a sum of leading words of a subset of the
/// terms, which is at most `m(1 + 20u)`, `m` the filter's sum of the terms' magnitudes
/// (`m_α`, `m_β`, `m_γ`, within `10u` of the exact ones). A lane has six
/// products and nine TwoSums, and β's two lanes one TwoSum more to join
/// them: the low values' magnitudes sum below `10u·m` for α and γ and
/// `20u·m` for β. Summed in any order, `n` values are within `γₙ₋₁`
/// times their magnitudes' sum of their sum; `n ≤ 31`, and `γ₃₀·20u <
/// 620u²`. So **`E = 1024u²m`**, widened by [`SLACK`]; the renormalising
/// TwoSum is exact. `m = 0` gives `E = 0`, rightly: every term is 0, and
/// every word. The errors found on cancelling data reach a few `u²m`.
///
/// The reference runs it first after the filter where α̂, γ̂ and `Δ̂` are
/// nonzero and `|Δ̂| > 2⁻²⁰β̂²/4`, as they are where nothing is exactly 0;
/// it counts as the tight stage.
///
/// ```
/// use rayoracle::quadric::{QuadricHit, stages::words};
/// // The cylinder of radius 1 around the axis (1, 1, 0), along that
/// // axis tilted by ε = 2⁻²⁰: α = ½ + ½(1 + ε)² − (1 + ε) = ε²/2 cancels
/// // from terms near 1, the roots are ±√(3/2)/ε.
/// let cyl = [0.5, 0.5, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// let (o, d) = ([0.0, 0.0, 0.5], [1.0, 1.0 + 2f64.powi(-20), 0.0]);
/// let t = 1.5f64.sqrt() * 2f64.powi(20);
/// assert_eq!(words(&cyl, o, d, 1.0), Some(QuadricHit::Two(-t as f32, t as f32)));
/// ```
pub fn words(k: &[f64; 10], o: [f64; 3], d: [f64; 3], shrink: f64) -> Option<QuadricHit> {
    let left = classes_paired(k, o, d, 1.0).left();
    let m = [left.alpha.1, left.beta.1, left.gamma.1];
    words_by::<Dekker>(k, o, d, m, shrink)
}

/// [`words`] with the products' errors found by `P`, from the filter's
/// magnitude sums `m`.
#[inline(always)]
fn words_by<P: Product>(
    k: &[f64; 10],
    o: [f64; 3],
    d: [f64; 3],
    m: [f64; 3],
    shrink: f64,
) -> Option<QuadricHit> {
    decide_words::<P>(false, bounded_words::<P>(k, o, d, m).into(), shrink).flatten()
}

/// Whether the reference tries [`words`] first: α̂, γ̂ and `Δ̂` nonzero,
/// and `Δ̂/4 = (β̂/2)² − α̂γ̂` above `2⁻²⁰(β̂/2)²` in magnitude. Exact zeros
/// (α = 0, a line on the surface, a double root) come out as exact zeros
/// of small-integer and dyadic data, or, for a double plane, as a `Δ̂`
/// of rounding errors far below `(β̂/2)²`: these take the stages that
/// decide them first. A guess, which only orders the stages.
#[inline(always)]
fn words_first(left: &Left) -> bool {
    let (a, b, c) = (left.alpha.0, 0.5 * left.beta.0, left.gamma.0);
    let bb = b * b;
    a != 0.0 && c != 0.0 && (bb - a * c).abs() > bb * 2f64.powi(-20)
}

/// α, β and γ of the line `o + t d` on the quadric `k` in double words
/// with the bounds of [`words`], from `m`, the filter's sums of their
/// terms' magnitudes, the products' errors found by `P`: the same
/// operations in the same order on every lane as the four-lane code, so
/// the same words.
#[inline(always)]
pub(crate) fn bounded_words<P: Product>(
    k: &[f64; 10],
    o: [f64; 3],
    d: [f64; 3],
    m: [f64; 3],
) -> [Dd; 3] {
    let (mut hi, mut lo) = ([0.0; 4], [0.0; 4]);
    for l in 0..4 {
        let mut t = [(0.0, 0.0); 6];
        for (t, &(c, i, j)) in t.iter_mut().zip(&QUADRATIC) {
            let x = [k[c] * d[i], k[c] * o[i], k[c] * d[i], k[c] * o[i]];
            let y = [d[j], d[j], o[j], o[j]];
            *t = P::two_prod(x[l], y[l]);
        }
        let lin = |i: usize| [0.0, k[6 + i] * d[i], 0.0, k[6 + i] * o[i]][l];
        (hi[l], lo[l]) = tree_sum(t, [lin(0), lin(1), lin(2)], [0.0, 0.0, 0.0, k[9]][l]);
    }
    bounded_lanes(hi, lo, m)
}

/// One lane's sum (or four at once) of six TwoProduct pairs `t`, three
/// exact words `lin` and one more, `j`: a leading word and a low word.
/// Pairwise, so that each leading word passes through four TwoSums rather
/// than nine: `((t₀ + t₁) + (t₂ + t₃)) + ((t₄ + t₅) + (l₀ + l₁))`, then `+
/// (l₂ + j)`. Each `+` of two partial sums is TwoSum of their leading
/// words, its error added to the sum of their low words. The same
/// operations on one lane and on four, so the same words. (Written
/// without closures, which are not always inlined into a function
/// compiled for AVX2.)
#[inline(always)]
pub(crate) fn tree_sum<L: Real>(t: [(L, L); 6], lin: [L; 3], j: L) -> (L, L) {
    let (a, b, c) = (
        add_words(t[0], t[1]),
        add_words(t[2], t[3]),
        add_words(t[4], t[5]),
    );
    let (l01, l2j) = (two_sum(lin[0], lin[1]), two_sum(lin[2], j));
    add_words(add_words(add_words(a, b), add_words(c, l01)), l2j)
}

/// Two unevaluated sums `h + l` added: TwoSum of the leading words, its
/// error added to the sum of the low words.
#[inline(always)]
fn add_words<L: Real>((h1, l1): (L, L), (h2, l2): (L, L)) -> (L, L) {
    let (s, e) = two_sum(h1, h2);
    (s, (l1 + l2) + e)
}

/// α, β and γ from the four lanes' leading and low words (α, β's two
/// halves, γ): β's halves joined by one more TwoSum, its error to the
/// low word, and each sum renormalised with the bound of [`words`].
#[inline(always)]
pub(crate) fn bounded_lanes(hi: [f64; 4], lo: [f64; 4], m: [f64; 3]) -> [Dd; 3] {
    let (bh, e) = two_sum(hi[1], hi[2]);
    let bl = (lo[1] + lo[2]) + e;
    // A function, not a closure: closures are not always inlined into a
    // function compiled for AVX2.
    #[inline(always)]
    fn word(hi: f64, lo: f64, m: f64) -> Dd {
        let (hi, lo) = two_sum(hi, lo);
        Dd {
            hi,
            lo,
            err: 1024.0 * U * U * m * SLACK,
        }
    }
    [
        word(hi[0], lo[0], m[0]),
        word(bh, bl, m[1]),
        word(hi[3], lo[3], m[2]),
    ]
}

/// The stages after the filter that need the data's [`grid()`], with the
/// products' errors found by `P`: where the filter's
/// α̂, β̂ and γ̂ are exact, [`tracked`]'s roots and then [`double_word`]
/// on them; the [`tight`] stage. `Ok` with what they decide, or `Err`
/// with the data's [`grid()`] for the stages that sum the exact terms.
///
/// The filter's sums are exact where `(m_α + m_β + m_γ)(1 + 2⁻³⁰) <
/// 2⁵²g`, `g` the data's [`grid()`]: every term is a multiple of `g`, and
/// the computed magnitudes, each a sum of rounded products, are within
/// `28u` of the exact ones, so the exact terms' magnitudes sum below
/// `2⁵²g`. Then each term is below `2⁵³g` and representable, so its
/// product did not round, and so is every partial sum, in any order.
#[inline(always)]
#[allow(clippy::type_complexity)]
fn later_head<P: Product>(
    k: &[f64; 10],
    o: [f64; 3],
    d: [f64; 3],
    left: Left,
    shrink: f64,
) -> Result<Option<(QuadricHit, Stage)>, f64> {
    let g = grid(k, o, d);
    let ((alpha, ma), (beta, mb), (gamma, mg)) = (left.alpha, left.beta, left.gamma);
    if (ma + mb + mg) * SLACK < g * 4_503_599_627_370_496.0 {
        if let Some(h) = tracked_roots::<P>(&mut Tracked::new(), alpha, beta, gamma) {
            return Ok(Some((h, Stage::Tracked)));
        }
        let one = |hi: f64| Dd {
            hi,
            lo: 0.0,
            err: 0.0,
        };
        let sums = (one(alpha), one(beta), one(gamma));
        return Ok(
            double_word_coefficients::<P>(g, true, sums, shrink).map(|h| (h, Stage::DoubleWord))
        );
    }
    if let Some(h) = tight_by::<P>(k, o, d, &left, shrink) {
        return Ok(Some((h, Stage::Tight)));
    }
    Err(g)
}

/// [`later_by`] with the running bounds of every sum, out of line: for
/// the data whose grid tests fail. Outside the copy compiled for FMA,
/// [`Fused`]'s `mul_add` is a call to libm's
/// `fma` here: the same exact pairs, slower, on rare data.
#[cold]
#[inline(never)]
fn later_bounded<P: Product>(t: &ExactTerms, shrink: f64) -> Option<(QuadricHit, Stage)> {
    match tracked_in::<P>(t, shrink) {
        (Some(h), _) => Some((h, Stage::Tracked)),
        (None, exact) => double_word_of::<P>(t, exact, shrink).map(|h| (h, Stage::DoubleWord)),
    }
}

/// The stages after the filter, with the stage that answered: the
/// [`words`] stage where nothing looks exactly 0 (counted as tight); a
/// perfect square ([`crate::quadric::square`]); [`tracked`]'s roots where the
/// filter's sums are exact; the [`tight`] stage; then [`tracked`] and
/// [`double_word`] on one computation of the exact terms. Each answer is
/// the exact class and correctly rounded roots, so any two stages that
/// answer agree. On a CPU with AVX2 and FMA ([`Avx2`]) the words and the
/// exact terms are summed on four lanes (`quadric::words`), and on one with FMA alone
/// ([`Fma`]) a copy compiled for it runs; either's TwoProduct is one fused
/// multiply-add ([`Fused`]; the same exact pairs, so the same bits).
///
/// ```
/// use rayoracle::{quadric::{QuadricHit, stages::later}, stage::Stage};
/// let cone = [1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
/// let h = later(&cone, [-1.0, 0.0, -2.0], [1.0, 0.0, 2.0], 1.0);
/// assert_eq!(h, Some((QuadricHit::One(1.0), Stage::Tracked)));
/// let k = [1.0, 0.0, 1.0, 0.0, -2.0, 0.0, 0.0, 0.0, 0.0, 0.0];
/// let (o, d) = ([0.1f32 as f64, 0.0, 0.0], [0.3f32 as f64, 0.0, 0.1f32 as f64]);
/// // A double plane: a perfect square, whose Δ is 0 on every line.
/// assert!(matches!(later(&k, o, d, 1.0), Some((QuadricHit::One(_), Stage::Tight))));
/// ```
pub fn later(k: &[f64; 10], o: [f64; 3], d: [f64; 3], shrink: f64) -> Option<(QuadricHit, Stage)> {
    later_of(
        || (*k, o, d),
        classes_paired(k, o, d, 1.0).left(),
        shrink,
        |h| h,
    )
}

/// [`later`] on the inputs that `inputs` gives, called inside the copy
/// that runs: the reference passes its `f32` data, widened there, since
/// `f64` values stored by one function and read back by the other as
/// vectors would stall store forwarding.
#[inline(always)]
pub(crate) fn later_of<I, S, R>(inputs: I, left: Left, shrink: f64, settle: S) -> R
where
    I: Fn() -> ([f64; 10], [f64; 3], [f64; 3]),
    S: Fn(Option<(QuadricHit, Stage)>) -> R,
{
    #[cfg(target_arch = "x86_64")]
    if let Some(avx2) = Avx2::detect() {
        #[target_feature(enable = "avx2,fma")]
        #[allow(clippy::too_many_arguments)]
        fn run<I, S, R>(
            avx2: Avx2,
            inputs: I,
            alpha: (f64, f64),
            beta: (f64, f64),
            gamma: (f64, f64),
            shrink: f64,
            settle: S,
        ) -> R
        where
            I: Fn() -> ([f64; 10], [f64; 3], [f64; 3]),
            S: Fn(Option<(QuadricHit, Stage)>) -> R,
        {
            let left = Left { alpha, beta, gamma };
            if words_first(&left) {
                let m = [alpha.1, beta.1, gamma.1];
                if let Some(h) = words_avx(avx2, &inputs, m, shrink) {
                    return settle(Some((h, Stage::Tight)));
                }
            }
            let (k, o, d) = inputs();
            if let Some(h) = crate::quadric::square::intersect(&k, o, d, shrink) {
                return settle(Some((h, Stage::Tight)));
            }
            match later_head::<Fused>(&k, o, d, left, shrink) {
                Ok(h) => settle(h),
                Err(g) => settle(later_avx(avx2, &inputs, g, shrink)),
            }
        }
        // SAFETY: the token exists only where the CPU has AVX2 and FMA,
        // the features `run` is compiled for. In `rayoracle report`
        // (default build, AMD EPYC, interleaved with a build that takes
        // the copy below, for FMA alone), the reference took 37.9 against
        // 51.5 ns/ray on quadric/alpha-zero-cylinder, 83.1 against 102.0 on
        // alpha-near-zero-rotated and 39.3 against 45.3 on double-plane.
        return unsafe {
            run(
                avx2, inputs, left.alpha, left.beta, left.gamma, shrink, settle,
            )
        };
    }
    #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
    if let Some(fma) = Fma::detect() {
        #[target_feature(enable = "fma")]
        #[allow(clippy::too_many_arguments)]
        fn run<I, S, R>(
            _: Fma,
            inputs: I,
            alpha: (f64, f64),
            beta: (f64, f64),
            gamma: (f64, f64),
            shrink: f64,
            settle: S,
        ) -> R
        where
            I: Fn() -> ([f64; 10], [f64; 3], [f64; 3]),
            S: Fn(Option<(QuadricHit, Stage)>) -> R,
        {
            let (k, o, d) = inputs();
            let left = Left { alpha, beta, gamma };
            settle(later_by::<Fused>(&k, o, d, left, shrink))
        }
        // SAFETY: the token exists only where the CPU has FMA, the one
        // feature `run` is compiled for. In `rayoracle report` (default
        // build, AMD EPYC, one run each with and without this copy), the
        // reference took 228.7 against 257.0 ns/ray on
        // quadric/double-plane, 200.2 against 219.2 on
        // alpha-near-zero-rotated and 122.6 against 144.1 on cone-apex.
        return unsafe {
            run(
                fma, inputs, left.alpha, left.beta, left.gamma, shrink, settle,
            )
        };
    }
    let (k, o, d) = inputs();
    settle(later_by::<BuildProduct>(&k, o, d, left, shrink))
}

/// `b`, a bound a stage decides with, noted for the tests, which check
/// it against its derivation: at `shrink` 1 a wrong factor or placement of
/// `shrink` only widens such a bound, which no answer shows.
#[inline(always)]
fn noted(b: f64) -> f64 {
    #[cfg(test)]
    tests::note(&[b]);
    b
}

/// [`noted`] for the three bounds [`sorted_from`] takes.
#[inline(always)]
fn noted3(b: (f64, f64, f64)) -> (f64, f64, f64) {
    #[cfg(test)]
    tests::note(&[b.0, b.1, b.2]);
    b
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Ray;
    use crate::quadric::{Quadric, exact};
    use glam::Vec3;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};
    use std::cell::RefCell;

    thread_local!(static NOTED: RefCell<Option<Vec<f64>>> = const { RefCell::new(None) });

    /// Records bounds that [`noted`] and [`noted3`] pass through, inside
    /// [`noted_during`].
    pub(super) fn note(b: &[f64]) {
        NOTED.with(|n| {
            if let Some(v) = n.borrow_mut().as_mut() {
                v.extend_from_slice(b);
            }
        });
    }

    /// `f`'s result and the bounds noted while it ran, in order.
    fn noted_during<R>(f: impl FnOnce() -> R) -> (R, Vec<f64>) {
        NOTED.with(|n| n.replace(Some(Vec::new())));
        let r = f();
        (r, NOTED.with(|n| n.take()).unwrap_or_default())
    }

    /// The cylinder of radius 1 around the axis (1, 1, 0), along that
    /// axis from origins of 24 bits: α = β = 0 from terms that cancel,
    /// provable on α's and β's grids ([`grids()`]) but not on the data's,
    /// next to γ's rounded terms. The tight stage settles the miss (γ
    /// clear of its bound), where it had left it to the exact sums; the
    /// reference counts it there, and agrees with the oracle.
    #[test]
    fn a_line_along_an_integer_axis_is_missed_in_the_tight_stage() {
        let k = [0.5, 0.5, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
        let q = Quadric::new(k.map(|x| x as f32));
        let d = [1.0, 1.0, 0.0];
        for o in [[0.1f32, 0.7, 0.3], [3.3, -2.9, 1e-3], [-0.04, 0.045, 7.7]] {
            let ow = o.map(f64::from);
            assert!(grid(&k, ow, d) * 2f64.powi(52) < 2.0, "{o:?}");
            assert_eq!(tight(&k, ow, d, 1.0), Some(QuadricHit::None), "{o:?}");
            let r = Ray::new(Vec3::from(o), Vec3::new(1.0, 1.0, 0.0));
            let got = crate::quadric::reference::intersect_staged(&r, &q);
            assert_eq!(got, (QuadricHit::None, Stage::Tight), "{o:?}");
            assert_eq!(exact::intersect(&r, &q), Ok(QuadricHit::None), "{o:?}");
        }
    }

    /// The same cylinder, along a direction of 21 bits, `1 + 2⁻²⁰` in
    /// `x` and `y`, from integer origins a thousand out: the data's grid
    /// (`2⁻⁴¹`) is too fine for γ's magnitudes (about 2·10⁶), γ's own
    /// (`2⁻¹`) is not, so γ is exact too, and the tight stage settles the
    /// line on the surface (γ = 0) as well as the miss (γ = 3).
    #[test]
    fn an_exact_gamma_on_its_own_grid_settles_a_line_on_the_surface() {
        let k = [0.5, 0.5, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
        let q = Quadric::new(k.map(|x| x as f32));
        let e = 1.0 + 2f32.powi(-20);
        let d = Vec3::new(e, e, 0.0);
        for (z, want) in [(1.0, QuadricHit::All), (2.0, QuadricHit::None)] {
            let r = Ray::new(Vec3::new(1000.0, 1000.0, z), d);
            let (o, dw) = (r.origin.as_dvec3().to_array(), d.as_dvec3().to_array());
            let [_, _, gc] = grids(&k, o, dw);
            assert!(grid(&k, o, dw) < gc, "{z}");
            assert_eq!(tight(&k, o, dw, 1.0), Some(want), "{z}");
            let got = crate::quadric::reference::intersect_staged(&r, &q);
            assert_eq!(got, (want, Stage::Tight), "{z}");
            assert_eq!(exact::intersect(&r, &q), Ok(want), "{z}");
        }
    }

    /// The four-lane exact sums (`words::exact`) are the scalar ones
    /// ([`grid_sums`]): wherever both prove their words exact, the same
    /// words, on f32 data of every kind (zeros, subnormals, small integers,
    /// powers of two, any bits) and on integer quadrics crossed by rays of
    /// spread exponents; and both prove most, and fail some, alike.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn the_four_lane_sums_are_the_scalar_sums() {
        use crate::num::avx::Avx2;
        let Some(avx2) = Avx2::detect() else {
            println!("no AVX2 and FMA: the four-lane sums are not run here");
            return;
        };
        #[target_feature(enable = "avx2,fma")]
        fn four(_: Avx2, k: &[f64; 10], o: [f64; 3], d: [f64; 3]) -> Option<[Dd; 3]> {
            crate::quadric::words::exact(k, o, d, grid(k, o, d))
        }
        let mut rng = SmallRng::seed_from_u64(0x4_1a7e5);
        let any = |rng: &mut SmallRng| match rng.random_range(0..6) {
            0 => 0.0,
            1 => f64::from(f32::from_bits(rng.random_range(1..1 << 23))),
            2 => f64::from(rng.random_range(-64i32..64)),
            3 => 2f64.powi(rng.random_range(-60..60)),
            _ => f64::from(f32::from_bits(
                rng.random::<u32>() & !(0xff << 23) | rng.random_range(60..190) << 23,
            )),
        };
        let (mut both, mut neither, mut one) = (0, 0, 0);
        for n in 0..40_000 {
            let (k, o, d) = if n % 2 == 0 {
                let k: [f64; 10] = core::array::from_fn(|_| any(&mut rng));
                (
                    k,
                    [0; 3].map(|_| any(&mut rng)),
                    [0; 3].map(|_| any(&mut rng)),
                )
            } else {
                let k = [0; 10].map(|_| f64::from(rng.random_range(-9i32..10)));
                let spread = |rng: &mut SmallRng| {
                    let m = rng.random_range(-(1i32 << 23)..1 << 23) as f32;
                    f64::from(m * 2f32.powi(rng.random_range(-40..0)))
                };
                (
                    k,
                    [0; 3].map(|_| spread(&mut rng)),
                    [0; 3].map(|_| spread(&mut rng)),
                )
            };
            // SAFETY: the token exists only where AVX2 and FMA were
            // detected, the features `four` is compiled for.
            let got = unsafe { four(avx2, &k, o, d) };
            let want = grid_sums::<true>(&ExactTerms::new::<Dekker>(&k, o, d));
            match (got, want) {
                (Some(a), Some(b)) => {
                    assert_eq!(a, b, "{k:?} {o:?} {d:?}");
                    both += 1;
                }
                (None, None) => neither += 1,
                _ => one += 1,
            }
        }
        assert!(
            both > 10_000 && neither > 1_000 && one * 100 < both,
            "{both} {neither} {one}"
        );
    }

    /// [`single_word_disc`]'s bound holds, `|Δ̂ − Δ| ≤ E` against the
    /// exact `Δ/4 = b² − ac` in dyadic rationals, on single words: `a` and
    /// `b` products of two f32 values, `c` another such product or, in
    /// half the cases, `b²/a` moved by a few units in the last place, so
    /// that `b² ≈ ac`; and it is
    /// not four times too wide: some errors exceed `E/4`, so a bound
    /// shrunk to a quarter would certify wrong values. A `Δ̂` whose sign
    /// the bound decides has the exact sign.
    #[test]
    fn the_single_word_discriminant_is_within_its_bound() {
        use crate::exact::Dyadic;
        let mut rng = SmallRng::seed_from_u64(0x5_1d15c);
        let f = |rng: &mut SmallRng| {
            let m = rng.random_range(1u32..1 << 24) as f32;
            let s = if rng.random() { -1.0 } else { 1.0 };
            f64::from(s * m * 2f32.powi(rng.random_range(-40..0)))
        };
        let (mut over_quarter, mut decided) = (0, 0);
        for n in 0..20_000 {
            let (a, b) = (f(&mut rng) * f(&mut rng), f(&mut rng) * f(&mut rng));
            let c = if n % 2 == 0 {
                // b²/a to a few units in the last place: Δ near 0.
                let q = b * b / a;
                f64::from_bits(q.to_bits().wrapping_add_signed(rng.random_range(-3..4)))
            } else {
                f(&mut rng) * f(&mut rng)
            };
            let disc = single_word_disc::<Dekker>(a, b, c);
            let d = |x: f64| Dyadic::from_f64(x);
            let exact = &(&d(b) * &d(b)) - &(&d(a) * &d(c));
            let err = &d(disc.v) - &exact;
            let err = if err.signum() < 0 { -err } else { err };
            assert!(err <= d(disc.e), "{a:e} {b:e} {c:e}");
            over_quarter += usize::from(err > d(0.25 * disc.e));
            if disc.v.abs() > disc.e {
                assert_eq!(disc.v.signum() as i32, exact.signum(), "{a:e} {b:e} {c:e}");
                decided += 1;
            }
        }
        assert!(
            over_quarter > 100 && decided > 10_000,
            "{over_quarter} {decided}"
        );
    }

    /// The words stage's sums ([`bounded_words`]) are within their bound
    /// of the exact α, β and γ (dyadic), on f32 data of every kind, on
    /// lines nearly parallel to the axis of a rotated integer cylinder
    /// (α and β cancel) and on the stiff catalogue; and the four-lane
    /// sums (`words::bounded`) are the same words, bit for bit.
    #[test]
    fn the_bounded_words_are_within_their_bound() {
        use crate::exact::Dyadic;
        #[cfg(target_arch = "x86_64")]
        #[target_feature(enable = "avx2,fma")]
        fn four(
            _: crate::num::avx::Avx2,
            k: &[f64; 10],
            o: [f64; 3],
            d: [f64; 3],
            m: [f64; 3],
        ) -> [Dd; 3] {
            crate::quadric::words::bounded(k, o, d, m)
        }
        let mut rng = SmallRng::seed_from_u64(0xb0_4d5);
        let any = |rng: &mut SmallRng| match rng.random_range(0..5) {
            0 => 0.0,
            1 => f64::from(f32::from_bits(rng.random_range(1..1 << 23))),
            2 => f64::from(rng.random_range(-64i32..64)),
            _ => f64::from(f32::from_bits(
                rng.random::<u32>() & !(0xff << 23) | rng.random_range(60..190) << 23,
            )),
        };
        let mut cases = near_axis_lines(&mut rng, 10_000);
        for _ in 0..10_000 {
            let k: [f64; 10] = core::array::from_fn(|_| any(&mut rng));
            cases.push((
                k,
                [0; 3].map(|_| any(&mut rng)),
                [0; 3].map(|_| any(&mut rng)),
            ));
        }
        for (r, q) in catalogue() {
            let w = |v: Vec3| v.to_array().map(f64::from);
            cases.push((q.coeffs.map(f64::from), w(r.origin), w(r.dir)));
        }
        let dy = |x: f64| Dyadic::from_f64(x);
        let (mut inexact, mut cancelling) = (0, 0);
        for (k, o, d) in &cases {
            let (k, o, d) = (k, *o, *d);
            let left = classes_paired(k, o, d, 1.0).left();
            let m = [left.alpha.1, left.beta.1, left.gamma.1];
            let got = bounded_words::<Dekker>(k, o, d, m);
            #[cfg(target_arch = "x86_64")]
            if let Some(avx2) = crate::num::avx::Avx2::detect() {
                // SAFETY: the token exists only where AVX2 and FMA were
                // detected, the features `four` is compiled for.
                assert_eq!(unsafe { four(avx2, k, o, d, m) }, got, "{k:?} {o:?} {d:?}");
            }
            let term = |c: usize, x: f64, y: f64| &(&dy(k[c]) * &dy(x)) * &dy(y);
            let (mut alpha, mut beta, mut gamma) = (dy(0.0), dy(0.0), dy(0.0));
            for &(c, i, j) in &QUADRATIC {
                alpha = &alpha + &term(c, d[i], d[j]);
                beta = &(&beta + &term(c, o[i], d[j])) + &term(c, d[i], o[j]);
                gamma = &gamma + &term(c, o[i], o[j]);
            }
            for i in 0..3 {
                beta = &beta + &term(6 + i, d[i], 1.0);
                gamma = &gamma + &term(6 + i, o[i], 1.0);
            }
            gamma = &gamma + &dy(k[9]);
            for (w, exact) in got.iter().zip([alpha, beta, gamma]) {
                let err = &(&dy(w.hi) + &dy(w.lo)) - &exact;
                let err = if err.signum() < 0 { -err } else { err };
                assert!(err <= dy(w.err), "{k:?} {o:?} {d:?}: {w:?}");
                inexact += usize::from(err.signum() != 0);
            }
            cancelling += usize::from(got[0].hi.abs() < 1e-6 * m[0]);
        }
        assert!(
            inexact > 1000 && cancelling > 1000,
            "{inexact} {cancelling}"
        );
    }

    /// `n` lines nearly along the axis of the cylinder `(a·x)² + (b·x)² =
    /// r`, `a ⊥ b` integer vectors, so that the axis `a × b` is off the
    /// coordinate axes and α, a sum of terms near 1, cancels to about
    /// the square of the tilt, 2⁻⁴ to 2⁻²⁴.
    fn near_axis_lines(rng: &mut SmallRng, n: usize) -> Vec<([f64; 10], [f64; 3], [f64; 3])> {
        let (a, b) = ([1.0f32, 2.0, 2.0], [2.0f32, 1.0, -2.0]);
        let axis = [-6.0f32, 6.0, -3.0];
        let q = |i: usize, j: usize| a[i] * a[j] + b[i] * b[j];
        (0..n)
            .map(|_| {
                let k = [
                    q(0, 0),
                    q(1, 1),
                    q(2, 2),
                    2.0 * q(0, 1),
                    2.0 * q(0, 2),
                    2.0 * q(1, 2),
                    0.0,
                    0.0,
                    0.0,
                    -(rng.random_range(1..50) as f32),
                ]
                .map(f64::from);
                let tilt = 2f32.powi(-rng.random_range(4..24));
                let d = core::array::from_fn(|i| {
                    f64::from(axis[i] * (1.0 + tilt * rng.random_range(-1.0f32..1.0)))
                });
                let o = [0; 3].map(|_| f64::from(rng.random_range(-40.0f32..40.0)));
                (k, o, d)
            })
            .collect()
    }

    /// The later stages as CPUs without AVX2 and FMA run them
    /// ([`later_by`] with Dekker's TwoProduct, and the words summed one
    /// lane at a time) give the same answers from the same stages as
    /// [`later`] here, on lines nearly along a rotated cylinder's axis
    /// ([`near_axis_lines`]) and the stiff catalogue's quadric cases.
    #[test]
    fn the_later_stages_are_the_same_on_every_cpu() {
        let mut words = 0;
        let w = |v: Vec3| v.to_array().map(f64::from);
        let catalogue = catalogue()
            .into_iter()
            .map(|(r, q)| (q.coeffs.map(f64::from), w(r.origin), w(r.dir)));
        let mut rng = SmallRng::seed_from_u64(0x1a7e5);
        for (k, o, d) in near_axis_lines(&mut rng, 2_000)
            .into_iter()
            .chain(catalogue)
        {
            let c = classes_paired(&k, o, d, 1.0);
            let got = later_by::<Dekker>(&k, o, d, c.left(), 1.0);
            assert_eq!(got, later(&k, o, d, 1.0), "{k:?} {o:?} {d:?}");
            words +=
                usize::from(words_first(&c.left()) && got.is_some_and(|h| h.1 == Stage::Tight));
        }
        assert!(words > 100, "{words}");
    }

    /// The stiff catalogue's quadric cases, in a build with every kind
    /// (none in others).
    fn catalogue() -> Vec<(Ray, Quadric)> {
        #[cfg(all(feature = "plane", feature = "sphere"))]
        return crate::report::Catalogue::builtin()
            .expect("the built-in catalogue")
            .families
            .iter()
            .flat_map(|f| &f.cases)
            .filter_map(|c| match c {
                crate::case::Case::Quadric(r, q) => Some((*r, *q)),
                _ => None,
            })
            .collect();
        #[cfg(not(all(feature = "plane", feature = "sphere")))]
        Vec::new()
    }

    /// The coefficients of the double plane `(n·p − e)² = 0`.
    fn double_plane(n: [f32; 3], e: f32) -> [f32; 10] {
        [
            n[0] * n[0],
            n[1] * n[1],
            n[2] * n[2],
            2.0 * n[0] * n[1],
            2.0 * n[0] * n[2],
            2.0 * n[1] * n[2],
            -2.0 * e * n[0],
            -2.0 * e * n[1],
            -2.0 * e * n[2],
            e * e,
        ]
    }

    /// On each case where the tracked stage gives no answer and leaves
    /// sums that `kind` accepts, the double-word stage from those sums:
    /// the oracle's answer where it gives one, and, where `same` (else
    /// where both answer), what it gives from the terms. Returns how many
    /// cases were left such sums, and how many of those it answered.
    fn from_tracked_sums(
        cases: &[(Ray, Quadric)],
        kind: fn(&Sums) -> bool,
        same: bool,
    ) -> (usize, usize) {
        let (mut left, mut answered) = (0, 0);
        for (r, q) in cases {
            let w = |v: Vec3| v.to_array().map(f64::from);
            let (k, o, d) = (q.coeffs.map(f64::from), w(r.origin), w(r.dir));
            let t = ExactTerms::new::<Dekker>(&k, o, d);
            let (None, sums) = tracked_in::<Dekker>(&t, 1.0) else {
                continue;
            };
            if !kind(&sums) {
                continue;
            }
            left += 1;
            let from_sums = double_word_of::<Dekker>(&t, sums, 1.0);
            let from_terms = double_word_of::<Dekker>(&t, Sums::Terms, 1.0);
            match (from_sums, from_terms) {
                (Some(a), Some(b)) => {
                    assert!(crate::hit::same_bits(&a, &b), "{r:?} {q:?}: {a:?} {b:?}")
                }
                (a, b) => assert!(!same || a == b, "{r:?} {q:?}: {a:?} {b:?}"),
            }
            if let Some(a) = from_sums {
                answered += 1;
                let want = exact::intersect(r, q).expect("finite");
                assert!(
                    crate::hit::same_bits(&a, &want),
                    "{r:?} {q:?}: {a:?} {want:?}"
                );
            }
        }
        (left, answered)
    }

    /// Where the tracked stage gives no answer but proves α, β and γ exact,
    /// the double-word stage on those single words answers as it does from
    /// the terms (where both answer), and as the oracle does: on the stiff
    /// catalogue's quadric cases and on small-integer quadrics (double
    /// planes, cones through their apex, cylinders) crossed by rays with
    /// few-bit inputs, where the sums are exact and their products are not
    /// (the catalogue only in a build with every kind).
    #[test]
    fn double_word_on_exact_sums_matches_the_terms_and_the_oracle() {
        let mut cases = catalogue();
        let mut rng = SmallRng::seed_from_u64(0xd0b1e);
        let few = |rng: &mut SmallRng| rng.random_range(-(1i32 << 20)..1 << 20) as f32 / 4096.0;
        for _ in 0..4000 {
            let n = [0, 1, 2].map(|_| rng.random_range(-3i32..4) as f32);
            let e = rng.random_range(-3i32..4) as f32;
            // (n·p − e)² = 0, or a cone or cylinder with the same normal.
            let k = match rng.random_range(0..3) {
                0 => double_plane(n, e),
                1 => [n[0], n[1], -n[2].abs(), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                _ => [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -e * e],
            };
            let o = Vec3::new(few(&mut rng), few(&mut rng), few(&mut rng));
            let d = Vec3::new(few(&mut rng), few(&mut rng), few(&mut rng));
            cases.push((Ray::new(o, d), Quadric::new(k)));
        }
        let exact = |s: &Sums| matches!(s, Sums::Exact(_));
        let (left, answered) = from_tracked_sums(&cases, exact, false);
        assert!(
            left > 1000 && answered * 10 > left * 9,
            "{answered} of {left}"
        );
    }

    /// Where the terms fail the grid test, the tracked stage leaves the
    /// double-word stage its double words, with which it answers exactly
    /// as it does from the terms, and as the oracle does: on the
    /// catalogue's quadric cases (a build with every kind), where the
    /// double planes take this way, and on integer double planes crossed
    /// by rays of spread exponents, most of which it answers (the rest
    /// reach the oracle).
    #[test]
    fn double_word_on_the_tracked_words_matches_the_terms_and_the_oracle() {
        let mut cases = catalogue();
        let mut rng = SmallRng::seed_from_u64(0x90_4d5);
        let spread = |rng: &mut SmallRng| {
            let m = rng.random_range(-(1i32 << 23)..1 << 23) as f32;
            m * 2f32.powi(rng.random_range(-40..0))
        };
        for _ in 0..2000 {
            let n = [0, 1, 2].map(|_| rng.random_range(-3i32..4) as f32);
            let e = rng.random_range(-3i32..4) as f32;
            let o = Vec3::new(spread(&mut rng), spread(&mut rng), spread(&mut rng));
            let d = Vec3::new(spread(&mut rng), spread(&mut rng), spread(&mut rng));
            cases.push((Ray::new(o, d), Quadric::new(double_plane(n, e))));
        }
        let words = |s: &Sums| matches!(s, Sums::Words(_));
        let (left, answered) = from_tracked_sums(&cases, words, true);
        assert!(left > 1000 && answered * 2 > left, "{answered} of {left}");
        // The words' bounds are multiplied by `shrink`, as the shrunk
        // bounds' tests need, and some are not 0.
        let mut bounded = 0;
        for (r, q) in &cases {
            let w = |v: Vec3| v.to_array().map(f64::from);
            let t = ExactTerms::new::<Dekker>(&q.coeffs.map(f64::from), w(r.origin), w(r.dir));
            let (Sums::Words(one), Sums::Words(quarter)) = (
                tracked_in::<Dekker>(&t, 1.0).1,
                tracked_in::<Dekker>(&t, 0.25).1,
            ) else {
                continue;
            };
            for (a, b) in one.iter().zip(&quarter) {
                assert_eq!(
                    (a.hi, a.lo, a.err * 0.25),
                    (b.hi, b.lo, b.err),
                    "{r:?} {q:?}"
                );
                bounded += usize::from(a.err > 0.0);
            }
        }
        assert!(bounded > 0);
    }

    /// The tracked stage decides the exact zeros it is for, as the oracle
    /// does: a double root at a cone's apex, a line on a cylinder, a root
    /// exactly 0 from a sphere's surface, a linear root (α = 0), and a
    /// miss whose `Δ` is exactly negative.
    #[test]
    fn tracked_decides_the_exact_zeros() {
        let sphere = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
        let cases = [
            (
                [1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                [-1.0, 0.0, -2.0],
                [1.0, 0.0, 2.0],
                QuadricHit::One(1.0),
            ),
            (
                [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0],
                [1.0, 0.0, 0.0],
                [0.0, 0.0, 1.0],
                QuadricHit::All,
            ),
            (
                sphere,
                [1.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                QuadricHit::Two(-2.0, 0.0),
            ),
            (
                [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, -2.0],
                [0.0, 0.0, 0.0],
                [0.0, 1.0, 0.0],
                QuadricHit::One(2.0),
            ),
            (sphere, [0.0, 2.0, 0.0], [1.0, 0.0, 0.0], QuadricHit::None),
        ];
        for (k, o, d, want) in cases {
            assert_eq!(tracked(&k, o, d), Some(want), "{k:?} {o:?} {d:?}");
            let r = Ray::new(
                Vec3::from_array(o.map(|x| x as f32)),
                Vec3::from_array(d.map(|x| x as f32)),
            );
            assert_eq!(
                exact::intersect(&r, &Quadric::new(k.map(|x| x as f32))),
                Ok(want)
            );
        }
    }

    /// Exact terms whose plain sums would round, magnitudes `2⁵⁴` next to
    /// 1 on the grid 1, are summed on the grid instead: α = `−2⁵⁴ + 1 +
    /// 2⁵⁴` = 1 and β likewise with α = 0, each with γ = −1 and γ = 0;
    /// summed plainly, each is 0, and the class changes. The reference,
    /// whose later stages start from the filter's sums where they are
    /// provably exact, answers the same.
    #[test]
    fn tracked_sums_terms_that_would_round_on_the_grid() {
        let big = 2f64.powi(54);
        let cases = [
            (
                [-big, 1.0, 0.0, big, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0],
                [1.0, 1.0, 0.0],
                QuadricHit::Two(-1.0, 1.0),
            ),
            (
                [-big, 1.0, 0.0, big, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
                [1.0, 1.0, 0.0],
                QuadricHit::One(0.0),
            ),
            (
                [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -big, big, -1.0],
                [1.0, 1.0, 1.0],
                QuadricHit::One(1.0),
            ),
            (
                [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -big, big, 0.0],
                [1.0, 1.0, 1.0],
                QuadricHit::One(0.0),
            ),
        ];
        for (k, d, want) in cases {
            let o = [0.0; 3];
            assert!(grid(&k, o, d) <= 1.0, "{k:?}");
            assert_eq!(tracked(&k, o, d), Some(want), "{k:?}");
            let r = Ray::new(Vec3::ZERO, Vec3::from_array(d.map(|x| x as f32)));
            let q = Quadric::new(k.map(|x| x as f32));
            assert_eq!(exact::intersect(&r, &q), Ok(want));
            // The reference's shortcut for exact filter sums
            // (`later_head`) must not take these either.
            let (got, stage) = crate::quadric::reference::intersect_staged(&r, &q);
            assert_eq!(got, want, "{k:?}: {stage:?}");
        }
    }

    /// Where the tracked stage hands the double-word stage its sums as
    /// words with bounds (exact terms of spread exponents, which the grid
    /// cannot prove), each bound is the unshrunk one times `shrink`.
    #[test]
    fn the_tracked_words_bounds_scale_with_shrink() {
        let p = |e| 2f64.powi(e);
        let k = [
            p(60),
            3.0 * p(-60),
            5.0 * p(-20),
            7.0,
            3.0 * p(30),
            p(-40),
            p(60),
            p(-60),
            3.0,
            -1.0,
        ];
        let (o, d) = ([0.0, 0.0, 0.0], [1.0, 1.0, 1.0]);
        let t = ExactTerms::new::<Dekker>(&k, o, d);
        let words = |shrink| match tracked_in::<Dekker>(&t, shrink) {
            (None, Sums::Words(w)) => w,
            other => panic!("not words: {other:?}"),
        };
        let (one, quarter) = (words(1.0), words(0.25));
        assert!(one.iter().any(|w| w.err > 0.0), "{one:?}");
        for (a, b) in one.iter().zip(&quarter) {
            assert_eq!((b.hi, b.lo, b.err), (a.hi, a.lo, a.err * 0.25));
        }
    }

    /// `disc_near`'s and `single_word_disc`'s bounds are their
    /// derivations' (`(e_b(2|b̂| + e_b) + |â|e_c + e_a(|ĉ| + e_c) + 3u(b̂² +
    /// |âĉ|))·SLACK·shrink`, and `u(|d̂ₕ| + |d̂ₗ| + |Δ̂|)·SLACK`, the latter
    /// bit for bit, as its low words are too small for a tolerance to
    /// see), on values and bounds of either sign and many scales, at
    /// `shrink` 1 and 1/4; and the single-word value is the sum of the
    /// TwoProduct words' differences.
    #[test]
    fn the_discriminants_bounds_are_the_derivations() {
        let mut r = SmallRng::seed_from_u64(0xd15c);
        let mut x = |scale: i32| {
            let v = r.random_range(-1.0..1.0) * 2f64.powi(r.random_range(-scale..=scale));
            Approx {
                v,
                e: v.abs() * 2f64.powi(r.random_range(-50..-10)),
            }
        };
        for _ in 0..2_000 {
            let (a, b, c) = (x(30), x(30), x(30));
            for shrink in [1.0, 0.25] {
                let got = disc_near(a, b, c, shrink);
                let (b2, ac) = (b.v * b.v, a.v * c.v);
                let data =
                    b.e * (2.0 * b.v.abs() + b.e) + a.v.abs() * c.e + a.e * (c.v.abs() + c.e);
                let want = (data + 3.0 * U * (b2 + ac.abs())) * SLACK * shrink;
                assert_eq!(got.v, b2 - ac);
                assert!(
                    ((got.e - want) / want).abs() < 1e-14,
                    "{got:?}, not {want:e}"
                );
            }
            let got = single_word_disc::<Dekker>(a.v, b.v, c.v);
            let (h1, l1) = Dekker::two_prod(b.v, b.v);
            let (h2, l2) = Dekker::two_prod(a.v, c.v);
            let (dh, dl) = (h1 - h2, l1 - l2);
            let want = U * (dh.abs() + dl.abs() + (dh + dl).abs()) * SLACK;
            assert_eq!((got.v, got.e), (dh + dl, want));
        }
    }

    /// The words stage goes first only where α̂ and γ̂ are nonzero and
    /// `Δ̂/4 = (β̂/2)² − α̂γ̂` is above `2⁻²⁰(β̂/2)²`: with β̂ = 6, α̂ = 1,
    /// γ̂ = 9(1 − 2⁻ʲ) just past, on and inside that threshold, and with
    /// α̂ or γ̂ zero.
    #[test]
    fn the_words_stage_goes_first_only_clear_of_exact_zeros() {
        let first = |a: f64, b: f64, c: f64| {
            words_first(&Left {
                alpha: (a, 1.0),
                beta: (b, 1.0),
                gamma: (c, 1.0),
            })
        };
        let near = |j: i32| 9.0 * (1.0 - 2f64.powi(-j));
        assert!(first(1.0, 6.0, near(19)));
        assert!(!first(1.0, 6.0, near(20)));
        assert!(!first(1.0, 6.0, near(21)));
        assert!(first(1.0, 6.0, 1.0));
        assert!(!first(0.0, 6.0, 1.0));
        assert!(!first(1.0, 6.0, 0.0));
    }

    /// The words stage decides with its bounds as derived, each times
    /// `shrink` once: the three it hands [`sorted_from`] (`E_α`, `2E_b`
    /// and `4E_Δ` of the leading words, [`disc_near`]) where the words
    /// are not exact, and `E_Δ` of [`single_word_disc`] where they are.
    #[test]
    fn the_words_decisions_bounds_are_the_derivations() {
        let dd = |hi: f64, lo: f64, err: f64| Dd { hi, lo, err };
        let mut r = SmallRng::seed_from_u64(0xb0d5);
        let mut sorted = 0;
        for i in 0..500 {
            // Roots near 1 and 5 (α t² + β t + γ with β = −6α, γ = 5α),
            // at many scales, with low words and errors at many depths.
            let scale = 2f64.powi(r.random_range(-40..40));
            let mut w = |v: f64| {
                let (lo, err) = if i == 0 {
                    (1e-17 * v, 1e-19 * v.abs())
                } else {
                    let depth = |r: &mut SmallRng| 2f64.powi(r.random_range(-70..-30));
                    (v * depth(&mut r), v.abs() * depth(&mut r))
                };
                dd(v, lo, err)
            };
            let (alpha, beta, gamma) = (w(scale), w(-6.0 * scale), w(5.0 * scale));
            let (a, bb) = (alpha.approx(), beta.scale(0.5).approx());
            let near = disc_near(a, bb, gamma.approx(), 1.0);
            for shrink in [1.0, 0.25] {
                let (got, notes) =
                    noted_during(|| decide_words::<Dekker>(false, (alpha, beta, gamma), shrink));
                assert!(matches!(got, Some(Some(QuadricHit::Two(..)))), "{got:?}");
                if !notes.is_empty() {
                    let want = [a.e, 2.0 * bb.e, 4.0 * near.e].map(|e| e * shrink);
                    assert_eq!(notes, want, "{alpha:?} {beta:?} {gamma:?} at {shrink}");
                    sorted += 1;
                }
            }
        }
        assert!(sorted > 900, "{sorted} of 1000 took the sorted roots");

        // Single exact words: Δ/4 = 9 − 5.
        let exact = (dd(1.0, 0.0, 0.0), dd(-6.0, 0.0, 0.0), dd(5.0, 0.0, 0.0));
        let e = single_word_disc::<Dekker>(1.0, -3.0, 5.0).e;
        assert!(e > 0.0);
        for shrink in [1.0, 0.25] {
            let (got, notes) = noted_during(|| decide_words::<Dekker>(true, exact, shrink));
            assert_eq!(got, Some(Some(QuadricHit::Two(1.0, 5.0))));
            assert_eq!(notes, [e * shrink], "at {shrink}");
        }
    }

    /// The tight stage decides with its bounds as derived, each times
    /// `shrink` once: `E_γ = 20u·m_γ` where α̂ = β̂ = 0 exactly (a quadric
    /// constant along the line), and `2E_Δ` of [`disc_near`] on α, β/2
    /// and γ with `E_β = 24u·m_β`, where β and γ are clear of 0.
    #[test]
    fn the_tight_stages_bounds_are_the_derivations() {
        let k = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
        let (o, d) = ([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]);
        let p = |e| 2f64.powi(e);
        let g = grids(&k, o, d);
        // Constant along the line, γ̂ inexact: it decides nothing.
        let constant = Left {
            alpha: (0.0, 1.0),
            beta: (0.0, 1.0),
            gamma: (3.0, p(60)),
        };
        assert_eq!(constant.exact(g), [true, true, false]);
        // α exact, β far from 0 but inexact, γ exact.
        let line = Left {
            alpha: (1.0, 1.0),
            beta: (p(40), p(53)),
            gamma: (3.0, 1.0),
        };
        assert_eq!(line.exact(g), [true, false, true]);
        let eb = 24.0 * U * p(53);
        let (a, b, c) = (
            Approx { v: 1.0, e: 0.0 },
            Approx {
                v: p(39),
                e: 0.5 * eb,
            },
            Approx { v: 3.0, e: 0.0 },
        );
        let near = disc_near(a, b, c, 1.0);
        for shrink in [1.0, 0.25] {
            let (got, notes) = noted_during(|| tight_by::<Dekker>(&k, o, d, &constant, shrink));
            assert_eq!(got, None);
            assert_eq!(notes, [20.0 * U * p(60) * shrink], "at {shrink}");
            let (_, notes) = noted_during(|| tight_by::<Dekker>(&k, o, d, &line, shrink));
            assert_eq!(notes, [2.0 * near.e * shrink], "at {shrink}");
        }
    }

    /// Along a line where α̂ = β̂ = 0 exactly (the quadric constant on it),
    /// the tight stage answers `All` only where γ̂ = 0 exactly: a γ̂ of 0
    /// summed from rounded terms may be a tiny γ of either sign, which it
    /// leaves undecided; a γ̂ clear of its bound misses.
    #[test]
    fn a_constant_quadric_holds_everywhere_only_where_gamma_is_exactly_zero() {
        let k = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
        let (o, d) = ([0.0, 0.0, -5.0], [0.0, 0.0, 1.0]);
        let g = grids(&k, o, d);
        let p = |e| 2f64.powi(e);
        for (gamma, want) in [
            ((0.0, 1.0), Some(QuadricHit::All)),
            ((0.0, p(60)), None),
            ((3.0, 1.0), Some(QuadricHit::None)),
            ((p(60), p(60)), Some(QuadricHit::None)),
        ] {
            let left = Left {
                alpha: (0.0, 1.0),
                beta: (0.0, 1.0),
                gamma,
            };
            assert_eq!(left.exact(g)[..2], [true, true]);
            assert_eq!(tight_by::<Dekker>(&k, o, d, &left, 1.0), want, "{gamma:?}");
        }
    }

    /// The tracked stage's two roots answer only where both certify:
    /// with exact α = 1, β = −(2 + 2⁻²⁴) and γ = 1 + 2⁻²⁴, the roots are 1
    /// and the midpoint 1 + 2⁻²⁴ between two `f32` values, computed
    /// exactly, which no enclosure rounds; with γ = 1 + 2⁻²³ both are
    /// `f32` values.
    #[test]
    fn tracked_roots_answer_only_where_both_roots_certify() {
        let roots = |r1: f64| {
            let mut x = Tracked::new();
            let got = tracked_roots::<Dekker>(&mut x, 1.0, -(1.0 + r1), r1);
            assert!(x.exact());
            got
        };
        let (mid, next) = (1.0 + 2f64.powi(-24), 1.0 + 2f64.powi(-23));
        assert_eq!(roots(mid), None);
        assert_eq!(roots(next), Some(QuadricHit::Two(1.0, next as f32)));
    }
}
