//! Double-word arithmetic on f64: the kernels' stage after the tracked one,
//! which settles the exact zeros whose f64 arithmetic rounds (tangents,
//! in-plane rays, α = 0, lines on a surface, roots exactly 0) without big
//! integers, and certifies what f64 alone cannot (a far tiny sphere, a
//! nearly parallel plane).
//!
//! * [`two_sum`] (Knuth's TwoSum) returns `a + b` and its rounding error,
//!   exactly, for any finite `a`, `b` whose sum does not overflow.
//! * [`two_prod`] (Dekker's TwoProduct over Veltkamp's split, no FMA, so
//!   no libm call on builds without the `fma` feature) returns `ab` and its
//!   rounding error, exactly, where the split does not overflow (`|a|`,
//!   `|b| < 2⁹⁹⁵`) and `a` and `b` are integer multiples of `2⁻ⁱ` and
//!   `2⁻ʲ` with `i + j ≤ 1074`: then every partial product of the
//!   algorithm is a multiple of `2⁻¹⁰⁷⁴` with at most 53 significant bits,
//!   so representable, subnormal or not, and the steps Dekker proves exact
//!   stay exact (*A floating-point technique for extending the available
//!   precision*, Numer. Math. 18, 1971). An overflow gives ±∞ or NaN.
//! * [`Acc`] sums such terms: the high parts through TwoSum, their errors
//!   (and the products' errors) in a low word whose own additions are
//!   TwoSums too. Where none of those rounded, `hi + lo` is the exact sum,
//!   so its sign and its zero are exact; otherwise [`Acc::finish`] bounds
//!   the error by the sum of the magnitudes of the low word's rounding
//!   errors, which TwoSum gives exactly (see [below](#the-sums-bounds)).
//!   [`Acc::wide`] sums the low word's own errors in a third word the same
//!   way, for the discriminants, whose exact zeros can span more than two
//!   words; [`Acc::finish`] renormalises the three words exactly into two
//!   and a remainder, which joins the bound.
//! * [`GridAcc`] is [`Acc`] for values known to lie on one grid (integer
//!   multiples of a power of two `g`, which the caller derives from the
//!   data): one comparison, `Σ|eᵢ| < 2⁵²g`, proves its low word exact in
//!   place of a TwoSum per addition; otherwise its bound is the low word's
//!   running error bound.
//! * [`Product`] chooses how TwoProduct runs: [`Dekker`] (plain
//!   arithmetic, any build) or [`Fused`] (one fused multiply-add, for code
//!   compiled with the `fma` target feature, entered with an [`Fma`]
//!   token). Both return the same exact pair.
//!
//! The kernels feed it polynomials in f32 data: the sphere's and plane's
//! values are multiples of `2⁻²⁹⁸`, the quadric's of `2⁻⁴⁴⁷`, and sums,
//! TwoSum errors and roundings of such multiples stay multiples (a rounding
//! keeps a value on a grid coarser than its own, or leaves it alone), so
//! every product they form meets [`two_prod`]'s conditions.
//!
//! # The sums' bounds
//!
//! An f64 addition `ŝ = fl(a + b)` is off by `r = a + b − ŝ`, `|r| ≤
//! u|ŝ|` (to nearest: `|ŝ|` is at least the power of two below `|a + b|`,
//! and `|r|` at most `u` of that; a subnormal `ŝ` is exact). A word summed
//! by such additions, in any order, misses the exact sum of its terms by
//! `Σₖ rₖ` over its additions, so by at most
//!
//! ```text
//! Σₖ |rₖ| ≤ u Σₖ |ŝₖ|,
//! ```
//!
//! the running error bound (Higham §3.3, §4.2). For a recursive sum of `n`
//! terms `xᵢ`, `|ŝₖ| ≤ (1 + γₖ₋₁) Σᵢ≤ₖ |xᵢ|`, so it is never more than
//! about `nu Σ|xᵢ|`, the `γₙ`-style bound, and far less where the sum
//! cancels: a partial sum near 0 adds almost nothing. The last word of a
//! sum (the low word, or in [`Acc::wide`] the third) is bounded so:
//!
//! * [`Acc`] adds to it by TwoSum, which gives each `rₖ` exactly: the
//!   bound is `m = Σ|rₖ|` itself, 0 exactly where no addition rounded.
//! * [`GridAcc`] adds to it plainly, two roundings a pair (`f̂ = fl(e +
//!   e')`, then `ŝ = fl(l + f̂)`): the bound is `m = u Σ(|f̂ₖ| + |ŝₖ|)`.
//!   The product by `u` is exact: an addition of multiples of `g` rounds
//!   only where `|ŝ| ≥ 2⁵³g`, so wherever the error is not 0 the sum of
//!   magnitudes is at least `2⁵³g`, and `u` of it at least `g`, a normal
//!   f64.
//!
//! The `n` magnitudes are non-negative, so their computed sum `m̂` has `m
//! ≤ (1 + γₙ₋₁)m̂`, `γₙ₋₁ ≤ 2(n − 1)u`; [`Acc::finish`] takes `m̂(1 +
//! 2nu)`, whose two roundings, and the three of `(|d| + m̂(1 + 2nu) +
//! extra)·SLACK`, [`SLACK`] covers (a subnormal sum of magnitudes is
//! exact, and a product by a factor above 1 rounds no lower than its
//! operand).
//!
//! ```
//! use rayoracle::num::dd::Acc;
//! // 0.1·0.1 − 0.01 in f64 terms: not 0, and the sum knows it exactly.
//! let mut x = Acc::new();
//! x.add_prod(0.1, 0.1);
//! x.add(-0.01);
//! let v = x.finish();
//! assert!(v.err == 0.0 && v.hi != 0.0 && v.sign_known());
//! // 3·(1/3)·... : a sum that cancels to exactly 0.
//! let mut z = Acc::new();
//! z.add_prod(1.0 / 3.0, 3.0);
//! z.add_prod(-1.0 / 3.0, 3.0);
//! assert!(z.finish().is_zero());
//! ```

use super::certify::{SLACK, U, certify, div, quotient_bound};
use super::real::Real;

/// Veltkamp's splitter for f64, `2²⁷ + 1`.
const SPLITTER: f64 = 134_217_729.0;

/// `a + b` and its rounding error, exactly (Knuth's TwoSum), on one lane
/// or on four.
///
/// ```
/// use rayoracle::num::dd::two_sum;
/// assert_eq!(two_sum(1.0, 2f64.powi(-60)), (1.0, 2f64.powi(-60)));
/// ```
#[inline(always)]
pub fn two_sum<L: Real>(a: L, b: L) -> (L, L) {
    let s = a + b;
    let bb = s - a;
    (s, (a - (s - bb)) + (b - bb))
}

/// Veltkamp's split of `a` into two halves of at most 26 significant bits,
/// `hi + lo = a` exactly (for `|a| < 2⁹⁹⁵`).
///
/// ```
/// use rayoracle::num::dd::split;
/// let a = 1.0 + f64::EPSILON;
/// let (hi, lo) = split(a);
/// assert_eq!((hi, lo), (1.0, f64::EPSILON));
/// ```
#[inline(always)]
pub fn split(a: f64) -> (f64, f64) {
    let c = SPLITTER * a;
    let hi = c - (c - a);
    (hi, a - hi)
}

/// `ab` and its rounding error, exactly under the conditions of the
/// [module](self) (Dekker's TwoProduct).
///
/// ```
/// use rayoracle::num::dd::two_prod;
/// let a = 1.0 + f64::EPSILON;
/// assert_eq!(two_prod(a, a), (1.0 + 2.0 * f64::EPSILON, f64::EPSILON * f64::EPSILON));
/// let (p, e) = two_prod(1e300, 1e300);
/// assert!(p.is_infinite() && !e.is_finite());
/// ```
#[inline(always)]
pub fn two_prod(a: f64, b: f64) -> (f64, f64) {
    let p = a * b;
    let (ah, al) = split(a);
    let (bh, bl) = split(b);
    (p, ((ah * bh - p) + ah * bl + al * bh) + al * bl)
}

/// How a [`two_prod`] is computed: the result is the same exact pair
/// either way, so the choice changes only the speed.
pub trait Product: Copy {
    /// `ab` and its rounding error, exactly under the conditions of the
    /// [module](self).
    fn two_prod(a: f64, b: f64) -> (f64, f64);
}

/// [`two_prod`] by Dekker's algorithm: plain arithmetic, on any build.
///
/// ```
/// use rayoracle::num::dd::{Dekker, Product, two_prod};
/// assert_eq!(Dekker::two_prod(0.1, 0.3), two_prod(0.1, 0.3));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Dekker;

impl Product for Dekker {
    #[inline(always)]
    fn two_prod(a: f64, b: f64) -> (f64, f64) {
        two_prod(a, b)
    }
}

/// [`two_prod`] as `p = ab`, `e = fma(a, b, −p)`: the fused multiply-add
/// rounds `ab − p` once, and that difference is representable under the
/// [module](self)'s conditions (it is a multiple of `2⁻¹⁰⁷⁴` below
/// `ulp(p)`), so `e` is the exact error, the same bits as Dekker's.
/// Dekker's split also fails for `|a|` or `|b| ≥ 2⁹⁹⁵`, where the fused
/// form still finds the error; the callers' products stay far below that.
/// One instruction where the CPU has FMA; only run inside a function
/// compiled with the `fma` target feature ([`Fma`]), since elsewhere
/// `mul_add` is a call to libm's `fma`, correct but slow.
///
/// ```
/// use rayoracle::num::dd::{Fused, Product, two_prod};
/// for (a, b) in [(0.1, 0.3), (1.0 + f64::EPSILON, 3.0), (1e300, 1e300)] {
///     let (p, e) = Fused::two_prod(a, b);
///     let (q, f) = two_prod(a, b);
///     assert!(p == q && (e == f || !(e.is_finite() || f.is_finite())));
/// }
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Fused;

impl Product for Fused {
    #[inline(always)]
    fn two_prod(a: f64, b: f64) -> (f64, f64) {
        let p = a * b;
        (p, a.mul_add(b, -p))
    }
}

/// TwoProduct as the build's target features allow: fused where they
/// include FMA, Dekker's otherwise.
#[cfg(all(target_feature = "fma", any(feature = "sphere", feature = "quadric")))]
pub(crate) type BuildProduct = Fused;
#[cfg(all(
    not(target_feature = "fma"),
    any(feature = "sphere", feature = "quadric")
))]
pub(crate) type BuildProduct = Dekker;

/// Proof that the running CPU has the FMA instructions: only
/// [`Fma::detect`] makes one. The later stages of the sphere and quadric
/// kernels take a copy of themselves compiled with the `fma` target
/// feature, over [`Fused`], when it does.
///
/// ```
/// use rayoracle::num::dd::Fma;
/// # #[cfg(target_arch = "x86_64")]
/// assert_eq!(Fma::detect().is_some(), is_x86_feature_detected!("fma"));
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Fma(());

impl Fma {
    /// The token, where the CPU has FMA (cached by the standard library: a
    /// load and a test per call); always on a build whose target has it.
    #[inline(always)]
    pub fn detect() -> Option<Fma> {
        #[cfg(target_feature = "fma")]
        let on = true;
        #[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
        let on = is_x86_feature_detected!("fma");
        #[cfg(not(any(target_arch = "x86_64", target_feature = "fma")))]
        let on = false;
        on.then_some(Fma(()))
    }
}

/// A double-word value `hi + lo` (`|lo| ≤ u|hi|`) within `err` of the
/// exact one; `err = 0` where it is exact.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Dd {
    /// The leading word, the value rounded to f64.
    pub hi: f64,
    /// The trailing word.
    pub lo: f64,
    /// A bound on `|exact − (hi + lo)|`.
    pub err: f64,
}

impl Dd {
    /// Whether the exact value's sign is `hi`'s: `|hi + lo| ≥ (1 − u)|hi|
    /// > err`, which `|hi| > 2 err` ensures.
    #[inline(always)]
    pub fn sign_known(&self) -> bool {
        self.hi.abs() > 2.0 * self.err
    }
    /// Whether the exact value is 0.
    #[inline(always)]
    pub fn is_zero(&self) -> bool {
        self.err == 0.0 && self.hi == 0.0
    }
    /// `hi` with a bound on its distance from the exact value.
    #[inline(always)]
    pub fn approx(&self) -> Approx {
        Approx {
            v: self.hi,
            e: self.lo.abs() + self.err,
        }
    }
    /// The same words with the error bound multiplied by `shrink`: for a
    /// stage whose bounds are built unshrunk and shrunk once where they
    /// decide a class.
    ///
    /// ```
    /// use rayoracle::num::dd::Dd;
    /// let x = Dd { hi: 1.0, lo: 0.0, err: 0.75 };
    /// assert!(!x.sign_known() && x.shrunk(0.5).sign_known());
    /// ```
    #[inline(always)]
    pub fn shrunk(self, shrink: f64) -> Dd {
        Dd {
            err: self.err * shrink,
            ..self
        }
    }
    /// The value times `k`, a power of two (or its negation) that keeps
    /// every word in the normal range: exact.
    #[inline(always)]
    pub fn scale(self, k: f64) -> Dd {
        Dd {
            hi: self.hi * k,
            lo: self.lo * k,
            err: self.err * k.abs(),
        }
    }
}

/// An f64 value `v` within `e` of an exact one.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Approx {
    /// The value.
    pub v: f64,
    /// A bound on its error.
    pub e: f64,
}

/// The negated value, with the same bound.
///
/// ```
/// use rayoracle::num::dd::Approx;
/// assert_eq!(-Approx { v: 2.0, e: 1e-9 }, Approx { v: -2.0, e: 1e-9 });
/// ```
impl core::ops::Neg for Approx {
    type Output = Approx;
    #[inline(always)]
    fn neg(self) -> Approx {
        Approx { v: -self.v, ..self }
    }
}

/// A sum of exact terms kept in two words: see the [module](self).
#[derive(Clone, Copy, Debug)]
pub struct Acc {
    hi: f64,
    lo: f64,
    lo2: f64,
    wide: bool,
    /// [`GridAcc`]'s `Σ|eᵢ|`, for its grid test.
    mag: f64,
    /// The last word's bound before its widening: `Σ|rₖ|`, or
    /// [`GridAcc`]'s `Σ(|f̂ₖ| + |ŝₖ|)`.
    run: f64,
    /// The count of magnitudes in `run`.
    n: u32,
    exact: bool,
    extra: f64,
}

impl Default for Acc {
    fn default() -> Self {
        Acc::new()
    }
}

impl Acc {
    /// The empty sum: exactly 0.
    pub fn new() -> Acc {
        Acc {
            hi: 0.0,
            lo: 0.0,
            lo2: 0.0,
            wide: false,
            mag: 0.0,
            run: 0.0,
            n: 0,
            exact: true,
            extra: 0.0,
        }
    }
    /// The empty sum with a third word: the low word's own rounding errors
    /// are summed in it (checked with TwoSum), so a sum whose exact value
    /// spans up to about 159 bits stays exact. For the discriminants, whose
    /// exact zeros need it.
    pub fn wide() -> Acc {
        Acc {
            wide: true,
            ..Acc::new()
        }
    }
    /// Adds `e` to the low word (in [`Acc::wide`], its rounding error to
    /// the third), noting whether the last word's addition rounded and by
    /// how much.
    #[inline(always)]
    fn low(&mut self, e: f64) {
        let (s, r) = two_sum(self.lo, e);
        let r = if self.wide {
            let (s2, r2) = two_sum(self.lo2, r);
            self.lo2 = s2;
            r2
        } else {
            r
        };
        self.exact &= r == 0.0;
        self.run += r.abs();
        self.lo = s;
        self.n += 1;
    }
    /// Adds `x` exactly.
    #[inline(always)]
    pub fn add(&mut self, x: f64) {
        let (s, e) = two_sum(self.hi, x);
        self.hi = s;
        self.low(e);
    }
    /// Adds `p + e`, a product's two words.
    #[inline(always)]
    pub fn add_pair(&mut self, (p, e): (f64, f64)) {
        self.add(p);
        self.low(e);
    }
    /// Adds `ab` exactly (under [`two_prod`]'s conditions).
    #[inline(always)]
    pub fn add_prod(&mut self, a: f64, b: f64) {
        self.add_pair(two_prod(a, b));
    }
    /// Adds the product of two double-word values, its four partial
    /// products exactly, and their errors to the bound: the exact product
    /// `xy` differs from `x̃ỹ` (`x̃ = hi + lo`) by at most `|x̃|E_y +
    /// E_x(|ỹ| + E_y)`, with `|x̃| ≤ (1 + u)|x.hi|`; the bound counts twice
    /// that, for the `1 + u` and its own roundings.
    #[inline(always)]
    pub fn add_dd_prod(&mut self, x: Dd, y: Dd) {
        self.add_prod(x.hi, y.hi);
        self.add_prod(x.hi, y.lo);
        self.add_prod(x.lo, y.hi);
        self.add_prod(x.lo, y.lo);
        self.extra += 2.0 * (x.hi.abs() * y.err + x.err * (y.hi.abs() + y.err));
    }
    /// The sum, with its bound as derived (a stage shrinks it with
    /// [`Dd::shrunk`] where it decides, for the tests that show a bound
    /// too small is caught). The words are renormalised by TwoSum into
    /// `hi + lo + d` exactly, with `|lo| ≤ u|hi|` and `|d|` added to the
    /// bound (0 where two words hold the sum). The last word (the low
    /// word, or in [`Acc::wide`] the third) misses its exact sum by
    /// `Σrₖ`, its additions' rounding errors, which TwoSum finds exactly:
    /// the bound is `Σ|rₖ|(1 + 2nu)` for its `n` additions (the `2nu` for
    /// the roundings of `Σ|rₖ|` itself, [module](self#the-sums-bounds)),
    /// 0 where no addition rounded, plus the errors of the inputs of
    /// [`Acc::add_dd_prod`].
    ///
    /// ```
    /// use rayoracle::num::dd::Acc;
    /// // 1 + 2⁻⁸⁰ + 2⁻¹⁴⁰ − 1: the low word drops 2⁻¹⁴⁰, once.
    /// let mut x = Acc::new();
    /// for t in [1.0, 2f64.powi(-80), 2f64.powi(-140), -1.0] {
    ///     x.add(t);
    /// }
    /// let v = x.finish();
    /// assert_eq!((v.hi, v.lo), (2f64.powi(-80), 0.0));
    /// assert!(v.err >= 2f64.powi(-140) && v.err < 2f64.powi(-139));
    /// ```
    #[inline(always)]
    pub fn finish(self) -> Dd {
        let (hi, lo, d) = if self.wide {
            // hi + lo + lo2 = h + c + b = h + l + d = hi' + lo' + d, exactly.
            let (a, b) = two_sum(self.lo, self.lo2);
            let (h, c) = two_sum(self.hi, a);
            let (l, d) = two_sum(c, b);
            let (hi, lo) = two_sum(h, l);
            (hi, lo, d)
        } else {
            // The same with lo2 = 0: b = d = 0 and l = c, so one TwoSum.
            let (hi, lo) = two_sum(self.hi, self.lo);
            (hi, lo, 0.0)
        };
        Dd {
            hi,
            lo,
            err: (d.abs() + self.chain() + self.extra) * SLACK,
        }
    }
    /// The bound on the last word's error: 0 where it is exact, else the
    /// sum of magnitudes widened for its own roundings, `m̂(1 + 2nu)`.
    #[inline(always)]
    fn chain(&self) -> f64 {
        if self.exact {
            0.0
        } else {
            self.run * (1.0 + 2.0 * f64::from(self.n) * U)
        }
    }
}

/// A sum of exact pairs `p + e` whose values all lie on one grid, the
/// integer multiples of a power of two `g` given to [`GridAcc::finish`]:
/// the high parts through TwoSum, every error into a low word by plain
/// additions. TwoSum errors and roundings of multiples of `g` are
/// multiples of `g` (a rounding lands on a grid coarser than `g` or does
/// nothing), so every value entering the low word is one; where the sum
/// of their magnitudes `m` stays below `2⁵²g`, every partial sum, in any
/// order, is a multiple of `g` below `2⁵³g`, representable, and the low
/// word is exact. That one comparison replaces [`Acc`]'s TwoSum check of
/// each low addition, and the pairs' two errors go in as one addition,
/// which halves the low word's dependency chain. Otherwise the bound is
/// the low word's running error bound, `u Σ(|f̂ₖ| + |ŝₖ|)` over the sums
/// `f̂ₖ` of each pair's errors and the partial sums `ŝₖ` of the word
/// ([module](self#the-sums-bounds)).
///
/// ```
/// use rayoracle::num::dd::{GridAcc, two_prod};
/// // (1 + 2⁻⁵²)² − 1 = 2⁻⁵¹ + 2⁻¹⁰⁴, on the grid 2⁻¹⁰⁴: exact.
/// let a = 1.0 + f64::EPSILON;
/// let mut x = GridAcc::new();
/// x.add_pair(two_prod(a, a));
/// x.add_pair((-1.0, 0.0));
/// let v = x.finish(2f64.powi(-104));
/// assert_eq!((v.hi, v.lo, v.err), (2f64.powi(-51), 2f64.powi(-104), 0.0));
/// // Told of a finer grid, the test fails: a bound, no certain value.
/// assert!(x.finish(2f64.powi(-200)).err > 0.0);
/// ```
///
/// [`GridAcc::wide`] keeps a third word, as [`Acc::wide`] does: the low
/// word's additions are TwoSums whose errors go to it by plain additions,
/// and the grid test is on the magnitudes of those errors.
#[derive(Clone, Copy, Debug, Default)]
pub struct GridAcc(Acc);

impl GridAcc {
    /// The empty sum: exactly 0.
    pub fn new() -> GridAcc {
        GridAcc(Acc::new())
    }
    /// The empty sum with a third word.
    pub fn wide() -> GridAcc {
        GridAcc(Acc::wide())
    }
    /// Adds `p + e`, both multiples of the grid.
    #[inline(always)]
    pub fn add_pair(&mut self, pair: (f64, f64)) {
        self.add::<true>(pair);
    }
    /// [`GridAcc::add_pair`] without the running error bound, for a sum
    /// that only [`GridAcc::finish_exact`] finishes: the bound serves only
    /// where the grid test fails, and a caller that sums again with
    /// [`GridAcc::add_pair`] there spares four operations a pair
    /// elsewhere.
    #[inline(always)]
    pub fn add_pair_unbounded(&mut self, pair: (f64, f64)) {
        self.add::<false>(pair);
    }
    /// [`GridAcc::add_pair`], the running error bound kept only where
    /// `RUN`: the words and the grid test's magnitudes do not depend on
    /// it.
    #[inline(always)]
    fn add<const RUN: bool>(&mut self, (p, e): (f64, f64)) {
        let x = &mut self.0;
        let (s, e1) = two_sum(x.hi, p);
        x.hi = s;
        // The last word takes e + e1 (in the wide sum, the low word's two
        // rounding errors): f, then its partial sum, each rounded once.
        let (f, part) = if x.wide {
            let (f, r0) = two_sum(e, e1);
            let (l, r1) = two_sum(x.lo, f);
            x.lo = l;
            let g = r0 + r1;
            x.lo2 += g;
            x.mag += r0.abs() + r1.abs();
            (g, x.lo2)
        } else {
            let f = e + e1;
            x.lo += f;
            x.mag += e.abs() + e1.abs();
            (f, x.lo)
        };
        if RUN {
            x.run += f.abs() + part.abs();
            x.n += 2;
        }
    }
    /// Adds the product of two double-word values as [`Acc::add_dd_prod`]
    /// does, its products' errors found by `P`; the words must be
    /// multiples of grids whose product is the sum's.
    #[inline(always)]
    pub fn add_dd_prod_by<P: Product>(&mut self, x: Dd, y: Dd) {
        self.add_pair(P::two_prod(x.hi, y.hi));
        self.add_pair(P::two_prod(x.hi, y.lo));
        self.add_pair(P::two_prod(x.lo, y.hi));
        self.add_pair(P::two_prod(x.lo, y.lo));
        self.0.extra += 2.0 * (x.hi.abs() * y.err + x.err * (y.hi.abs() + y.err));
    }
    /// Adds `x²` as [`GridAcc::add_dd_prod_by`] adds `x·x`, with the two
    /// cross products as one, `(2x.hi)·x.lo` (the doubling is exact).
    ///
    /// ```
    /// use rayoracle::num::dd::{Dd, Dekker, GridAcc};
    /// // (3 + 2⁻⁶⁰)² − 9 = 6·2⁻⁶⁰ + 2⁻¹²⁰, on the grid 2⁻¹²⁰: exact.
    /// let x = Dd { hi: 3.0, lo: 2f64.powi(-60), err: 0.0 };
    /// let mut s = GridAcc::wide();
    /// s.add_square_by::<Dekker>(x);
    /// s.add_pair((-9.0, 0.0));
    /// let v = s.finish(2f64.powi(-120));
    /// assert_eq!((v.hi, v.lo, v.err), (6.0 * 2f64.powi(-60), 2f64.powi(-120), 0.0));
    /// ```
    #[inline(always)]
    pub fn add_square_by<P: Product>(&mut self, x: Dd) {
        self.add_pair(P::two_prod(x.hi, x.hi));
        self.add_pair(P::two_prod(x.hi + x.hi, x.lo));
        self.add_pair(P::two_prod(x.lo, x.lo));
        self.0.extra += 2.0 * (x.hi.abs() * x.err + x.err * (x.hi.abs() + x.err));
    }
    /// The sum, exact (`err = 0`) where the last word's values sum below
    /// `2⁵²·grid` in magnitude (the computed `m`, within `2nu` of the
    /// true one, is widened by [`SLACK`] for the test), else with the
    /// running error bound `u Σ(|f̂ₖ| + |ŝₖ|)`, widened as in
    /// [`Acc::finish`]; renormalised and bounded as by [`Acc::finish`].
    /// `grid` must be a normal power of two that divides every value
    /// added.
    ///
    /// ```
    /// use rayoracle::num::dd::GridAcc;
    /// // 1 + 2⁻⁸⁰ + 2⁻¹⁴⁰ − 1 on the grid 2⁻¹⁴⁰, too fine for the test:
    /// // the low word drops 2⁻¹⁴⁰, within u of its partial sum 2⁻⁸⁰.
    /// let mut x = GridAcc::new();
    /// for t in [1.0, 2f64.powi(-80), 2f64.powi(-140), -1.0] {
    ///     x.add_pair((t, 0.0));
    /// }
    /// let v = x.finish(2f64.powi(-140));
    /// assert_eq!((v.hi, v.lo), (2f64.powi(-80), 0.0));
    /// assert!(v.err >= 2f64.powi(-140) && v.err < 2f64.powi(-130));
    /// ```
    #[inline(always)]
    pub fn finish(self, grid: f64) -> Dd {
        self.acc(grid).finish()
    }
    /// The sum where the grid test proves its last word exact: the words
    /// and bound of [`GridAcc::finish`], which does not read the running
    /// bound there (`err` is 0 for a sum of pairs alone); `None` where the
    /// test fails, and a sum of [`GridAcc::add_pair_unbounded`] then needs
    /// summing again with [`GridAcc::add_pair`] for its bound. Two-word
    /// sums only: [`GridAcc::wide`]'s third word joins the bound.
    ///
    /// ```
    /// use rayoracle::num::dd::GridAcc;
    /// let p = [(1.0, 0.0), (2f64.powi(-80), 0.0), (2f64.powi(-140), 0.0), (-1.0, 0.0)];
    /// let (mut x, mut y) = (GridAcc::new(), GridAcc::new());
    /// for q in p {
    ///     x.add_pair(q);
    ///     y.add_pair_unbounded(q);
    /// }
    /// assert_eq!(y.finish_exact(2f64.powi(-80)), Some(x.finish(2f64.powi(-80))));
    /// assert_eq!(y.finish_exact(2f64.powi(-140)), None);
    /// ```
    #[inline(always)]
    pub fn finish_exact(self, grid: f64) -> Option<Dd> {
        debug_assert!(!self.0.wide);
        let acc = self.acc(grid);
        let (hi, lo) = two_sum(acc.hi, acc.lo);
        let err = acc.extra * SLACK;
        acc.exact.then_some(Dd { hi, lo, err })
    }
    /// The sum as an [`Acc`] with its last word's test and bound: exact
    /// by the grid test, else `u Σ(|f̂ₖ| + |ŝₖ|)`.
    #[inline(always)]
    fn acc(self, grid: f64) -> Acc {
        let mut acc = self.0;
        acc.exact = acc.mag * SLACK < grid * 4_503_599_627_370_496.0;
        acc.run *= U;
        acc
    }
}

/// The two roots of `at² + 2bt + c` (`Δ = b² − ac` certified positive,
/// `a` certified nonzero), from f64 approximations with error bounds: `s =
/// √Δ̂`, `q = −(b̂ + sign(b̂)s)`, roots `q/a` and `c/q`, each certified,
/// sorted; `None` where either root is undecided. Every bound is multiplied
/// by `shrink`.
///
/// * `|√Δ − √Δ̂| ≤ E_Δ/√Δ̂`, and `ŝ` rounds once: `E_s = E_Δ/ŝ + 2uŝ`.
/// * `|q̂| = fl(|b̂| + ŝ)` rounds once, with no cancellation: `E_q = E_b +
///   E_s + 2u|q̂|`.
/// * Each root is one division of values with bounds,
///   [`quotient_bound`], with `4u` for the division's own rounding (the
///   proof needs `u`, and `u` more for the rounding of the reciprocal the
///   bound is computed from).
///
/// ```
/// use rayoracle::num::dd::{Approx, two_roots};
/// let x = |v: f64| Approx { v, e: 1e-30 };
/// // t² − 10t + 24 = (t − 4)(t − 6): a = 1, b = −5, c = 24, Δ = 1.
/// assert_eq!(two_roots(x(1.0), x(-5.0), x(24.0), x(1.0), 1.0), Some((4.0, 6.0)));
/// ```
#[inline(always)]
pub fn two_roots(a: Approx, b: Approx, c: Approx, disc: Approx, shrink: f64) -> Option<(f32, f32)> {
    let u = U * shrink;
    let s = disc.v.sqrt();
    let es = disc.e * shrink / s * SLACK + 2.0 * u * s;
    let q = -(b.v + s.copysign(b.v));
    let eq = (b.e * shrink + es + 2.0 * u * q.abs()) * SLACK;
    let t0 = q / a.v;
    let (r0, a0) = quotient_bound(a.e * shrink, eq, 1.0 / a.v, 4.0 * u);
    let t1 = div(c.v, q);
    let (r1, a1) = quotient_bound(eq, c.e * shrink, 1.0 / q, 4.0 * u);
    if !(disc.v > 0.0 && certify(t0, r0, a0) && certify(t1, r1, a1)) {
        return None;
    }
    // Disjoint enclosures are in the exact order; overlapping ones round
    // to the same f32.
    let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
    Some((t0 as f32, t1 as f32))
}

/// The root `x/y` from approximations with bounds, rounded once and
/// certified ([`quotient_bound`] with `4u` for the roundings of the
/// quotient and of the reciprocal its bound uses), `+0` for an exact 0;
/// every bound multiplied by `shrink`.
///
/// ```
/// use rayoracle::num::dd::{Approx, quotient};
/// let x = Approx { v: 1.0, e: 0.0 };
/// let y = Approx { v: 3.0, e: 1e-300 };
/// assert_eq!(quotient(x, y, 1.0), Some(1.0 / 3.0));
/// assert_eq!(quotient(Approx { v: 0.0, e: 0.0 }, Approx { v: -3.0, e: 0.0 }, 1.0), Some(0.0));
/// ```
#[inline(always)]
pub fn quotient(x: Approx, y: Approx, shrink: f64) -> Option<f32> {
    let t = div(x.v, y.v);
    let (r, a) = quotient_bound(y.e * shrink, x.e * shrink, 1.0 / y.v, 4.0 * U * shrink);
    certify(t, r, a).then_some(t as f32)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Dyadic;
    use crate::exact::dyadic::sum;
    use proptest::prelude::*;

    /// An f32 value of the grid below as an integer count of `2⁻⁴⁰`.
    fn scaled(x: f32) -> i128 {
        (x as f64 * 2f64.powi(40)) as i128
    }

    /// f32 values below `2²⁰` in magnitude on a grid of `2⁻⁴⁰`: sums of
    /// eight products of them fit `i128` counts of `2⁻⁸⁰`.
    fn grid() -> impl Strategy<Value = f32> {
        (-(1i64 << 40)..(1i64 << 40), -40i32..0)
            .prop_map(|(m, e)| ((m >> 20) as f64 * 2f64.powi(e)) as f32)
    }

    proptest! {
        /// TwoSum and TwoProduct are exact: checked in i128 on a grid.
        #[test]
        fn eft_exact(a in grid(), b in grid()) {
            let (x, y) = (a as f64, b as f64);
            let (s, e) = two_sum(x, y);
            let one = |v: f64| (v * 2f64.powi(40)) as i128;
            prop_assert_eq!(one(s) + one(e), scaled(a) + scaled(b));
            let (p, q) = two_prod(x, y);
            let two = |v: f64| (v * 2f64.powi(80)) as i128;
            prop_assert_eq!(two(p) + two(q), scaled(a) * scaled(b));
        }

        /// The sign an [`Acc`] certifies is the exact sign of `Σ aᵢbᵢ`, and
        /// an exact one is exact.
        #[test]
        fn acc_sign(v in prop::collection::vec((grid(), grid()), 1..8)) {
            let mut acc = Acc::new();
            let mut exact = 0i128;
            for &(a, b) in &v {
                acc.add_prod(a as f64, b as f64);
                exact += scaled(a) * scaled(b);
            }
            let d = acc.finish();
            if d.is_zero() {
                prop_assert_eq!(exact, 0);
            }
            if d.sign_known() {
                prop_assert_eq!(d.hi.signum() as i128, exact.signum());
            }
            if d.err == 0.0 {
                let two = |x: f64| (x * 2f64.powi(80)) as i128;
                prop_assert_eq!(two(d.hi) + two(d.lo), exact);
            }
        }

        /// The same for [`GridAcc`], narrow and wide, told the grid of
        /// the products, `2⁻⁸⁰`: where it claims exactness (its grid
        /// test), the words are the exact sum.
        #[test]
        fn grid_acc_sign(v in prop::collection::vec((grid(), grid()), 1..8), wide: bool) {
            let mut acc = if wide { GridAcc::wide() } else { GridAcc::new() };
            let mut exact = 0i128;
            for &(a, b) in &v {
                acc.add_pair(two_prod(a as f64, b as f64));
                exact += scaled(a) * scaled(b);
            }
            let d = acc.finish(2f64.powi(-80));
            if d.is_zero() {
                prop_assert_eq!(exact, 0);
            }
            if d.sign_known() {
                prop_assert_eq!(d.hi.signum() as i128, exact.signum());
            }
            let two = |x: f64| (x * 2f64.powi(80)) as i128;
            if d.err == 0.0 {
                prop_assert_eq!(two(d.hi) + two(d.lo), exact);
            } else {
                let miss = (exact - two(d.hi) - two(d.lo)).unsigned_abs() as f64;
                prop_assert!(miss <= d.err * 2f64.powi(80));
            }
        }
    }

    /// The `γₙ`-style bound on [`Acc`]'s last word, `2nu Σ|eᵢ|` over the
    /// `n` values `eᵢ` it adds, for `pairs` added by [`Acc::add_pair`]
    /// (and, narrow, by [`GridAcc::add_pair`], whose low word adds the same
    /// values).
    fn gamma_bound(pairs: &[(f64, f64)], wide: bool) -> f64 {
        let (mut hi, mut lo, mut mag) = (0.0, 0.0, 0.0f64);
        for &(p, e) in pairs {
            let (s, e1) = two_sum(hi, p);
            hi = s;
            for x in [e1, e] {
                let (l, r) = two_sum(lo, x);
                lo = l;
                mag += if wide { r.abs() } else { x.abs() };
            }
        }
        2.0 * (2 * pairs.len()) as f64 * U * mag
    }

    /// Whether `d.hi + d.lo` is within `d.err` of `x`, decided exactly;
    /// and that distance.
    fn covers(x: &Dyadic, d: Dd) -> (bool, f64) {
        let miss = x - &(&Dyadic::from_f64(d.hi) + &Dyadic::from_f64(d.lo));
        let miss = if miss.signum() < 0 { -miss } else { miss };
        (miss <= Dyadic::from_f64(d.err), miss.to_f64())
    }

    /// Multiples of `2⁻²⁰⁰` of up to 53 bits, below `2⁴⁰`: sums of them
    /// span up to 240 bits, and round in a low word, or a third.
    fn spread() -> impl Strategy<Value = f64> {
        (-(1i64 << 53)..(1i64 << 53), -200i32..-13).prop_map(|(m, e)| m as f64 * 2f64.powi(e))
    }

    proptest! {
        /// Narrow and wide, [`Acc`] and [`GridAcc`] (on the grid
        /// `2⁻²⁰⁰`): the bound covers the error, measured exactly in
        /// dyadic rationals, on sums that cancel (pairs `a`, then `b`,
        /// then `−a` in reverse), and the last word's part of it is at
        /// most the `γₙ`-style `2nu Σ|eᵢ|`.
        #[test]
        fn running_bound_covers_and_is_within_gamma(
            a in prop::collection::vec((spread(), spread()), 1..6),
            b in prop::collection::vec((spread(), spread()), 0..6),
        ) {
            let pairs: Vec<(f64, f64)> = a
                .iter()
                .chain(&b)
                .map(|&(x, y)| two_sum(x, y))
                .chain(a.iter().rev().map(|&(x, y)| {
                    let (p, e) = two_sum(x, y);
                    (-p, -e)
                }))
                .collect();
            let words: Vec<Dyadic> = pairs
                .iter()
                .flat_map(|&(p, e)| [Dyadic::from_f64(p), Dyadic::from_f64(e)])
                .collect();
            let exact = sum(&words);
            for wide in [false, true] {
                let mut acc = if wide { Acc::wide() } else { Acc::new() };
                pairs.iter().for_each(|&p| acc.add_pair(p));
                let (ok, miss) = covers(&exact, acc.finish());
                prop_assert!(ok, "Acc, wide {}: off by {:e}, {:?}", wide, miss, acc.finish());
                prop_assert!(acc.chain() <= gamma_bound(&pairs, wide));
                let mut g = if wide { GridAcc::wide() } else { GridAcc::new() };
                pairs.iter().for_each(|&p| g.add_pair(p));
                let grid = 2f64.powi(-200);
                let (ok, miss) = covers(&exact, g.finish(grid));
                prop_assert!(ok, "GridAcc, wide {}: off by {:e}, {:?}", wide, miss, g.finish(grid));
                let x = g.0;
                prop_assert!(g.acc(grid).chain() <= 2.0 * f64::from(x.n) * U * x.mag);
            }
        }
    }

    /// A sum whose low word takes `2⁻⁶⁰` and gives it back, then adds
    /// twenty small terms: one rounding, of `2⁻¹³⁰`, while `2⁻⁶⁰` sits in
    /// the low word. [`Acc`]'s bound is that rounding (it sees each one);
    /// [`GridAcc`]'s, `u` times the partial sums, counts `2⁻⁶⁰` only while
    /// it is there; the `γₙ`-style bound counts it for every addition.
    #[test]
    fn running_bound_is_tighter_on_cancelling_sums() {
        let mut terms = vec![1.0, 2f64.powi(-60), 2f64.powi(-130), -2f64.powi(-60)];
        terms.extend([3.0 * 2f64.powi(-130); 20]);
        terms.push(-1.0);
        let pairs: Vec<(f64, f64)> = terms.iter().map(|&t| (t, 0.0)).collect();
        let exact = Dyadic::new(61, -130);
        let old = gamma_bound(&pairs, false);
        let mut acc = Acc::new();
        let mut g = GridAcc::new();
        for &p in &pairs {
            acc.add_pair(p);
            g.add_pair(p);
        }
        let (d, e) = (acc.finish(), g.finish(2f64.powi(-130)));
        for x in [d, e] {
            let (ok, miss) = covers(&exact, x);
            assert!(ok && miss == 2f64.powi(-130), "{x:?}");
            assert!(x.err * 32.0 < old, "{x:?}, {old:e}");
        }
        assert!(d.err < 2.0 * 2f64.powi(-130), "{d:?}");
    }

    /// [`GridAcc`] on a cancelling sum whose low word needs more than 53
    /// bits above the grid: the narrow one gives a bound that covers the
    /// truth, the wide one is exact.
    #[test]
    fn grid_acc_wide_keeps_a_third_word() {
        let terms = [1.0, 2f64.powi(-60), 2f64.powi(-120)];
        let run = |mut acc: GridAcc| {
            terms.iter().for_each(|&x| acc.add_pair((x, 0.0)));
            terms.iter().for_each(|&x| acc.add_pair((-x, 0.0)));
            acc.finish(2f64.powi(-120))
        };
        let (narrow, wide) = (run(GridAcc::new()), run(GridAcc::wide()));
        assert!(!narrow.is_zero() && (narrow.hi + narrow.lo).abs() <= narrow.err);
        assert!(wide.is_zero(), "{wide:?}");
    }

    /// A cancelling sum whose low word rounds: not exact, and its bound
    /// covers the truth.
    #[test]
    fn inexact_low_word_is_bounded() {
        let mut acc = Acc::new();
        acc.add(1.0);
        acc.add(2f64.powi(-80));
        acc.add(2f64.powi(-140));
        acc.add(-1.0);
        let d = acc.finish();
        assert!(d.err > 0.0 && !d.is_zero());
        // The exact sum is 2⁻⁸⁰ + 2⁻¹⁴⁰; the words miss the second part.
        let miss = (2f64.powi(-140) - (d.hi - 2f64.powi(-80)) - d.lo).abs();
        assert!(miss > 0.0 && miss <= d.err);
        assert!(d.sign_known() && d.hi > 0.0);
        // Shrunk to nothing, the bound no longer covers.
        assert!(miss > acc.finish().shrunk(0.0).err);
    }

    /// A sum spanning 120 bits: the narrow sum's low word rounds (a bound,
    /// no certain zero); the wide one's third word keeps it exact.
    #[test]
    fn wide_sums_stay_exact() {
        let terms = [1.0, 2f64.powi(-60), 2f64.powi(-120)];
        let run = |mut acc: Acc| {
            terms.iter().for_each(|&x| acc.add(x));
            terms.iter().for_each(|&x| acc.add(-x));
            acc.finish()
        };
        let (narrow, wide) = (run(Acc::new()), run(Acc::wide()));
        assert!(!narrow.is_zero() && narrow.err > 0.0);
        assert!(wide.is_zero(), "{wide:?}");
        // Without the cancellation the wide sum is exact and nonzero.
        let mut acc = Acc::wide();
        terms.iter().for_each(|&x| acc.add(x));
        let d = acc.finish();
        assert_eq!((d.hi, d.lo), (1.0, 2f64.powi(-60)));
        assert!(d.err > 0.0 && d.err < 2f64.powi(-119) && d.sign_known());
    }

    /// A product of inexact values carries their errors.
    #[test]
    fn dd_product_error() {
        let x = Dd {
            hi: 3.0,
            lo: 0.0,
            err: 1e-20,
        };
        let mut acc = Acc::new();
        acc.add_dd_prod(x, x);
        let d = acc.finish();
        assert_eq!(d.hi, 9.0);
        assert!(d.err >= 6e-20 && d.err < 1e-18);
        assert!(x.scale(-4.0).hi == -12.0 && x.scale(-4.0).err == 4e-20);
    }

    /// Overflow certifies nothing.
    #[test]
    fn overflow_is_not_exact() {
        let mut acc = Acc::new();
        acc.add_prod(1e300, 1e300);
        let d = acc.finish();
        assert!(!d.is_zero() && !d.sign_known());
    }
}
