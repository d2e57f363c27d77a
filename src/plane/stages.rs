//! The filter: the plane's first stage, written once over [`Real`] and run
//! at `f64` by [`super::reference`](mod@super::reference) and at
//! [`F64x4`](crate::num::real::F64x4) by [`super::x4`].
//!
//! # The bound
//!
//! In the notation of [`crate::sphere::stages`] (`u = 2⁻⁵³`, `γₙ`, hats for
//! computed values, `E` for error bounds), with f32 inputs exact in f64:
//!
//! * `ŵᵢ = fl(aᵢ − oᵢ)`, one rounding; `num = Σ ŵᵢnᵢ`: a rounded product
//!   and two additions, `E_num = γ₄ m_num` with `m_num = Σ|ŵᵢnᵢ|`;
//! * `den = Σ dᵢnᵢ`: products of f32 values are exact, two additions:
//!   `E_den = γ₂ m_den`, `m_den = Σ|dᵢnᵢ|`;
//! * `t = num/den`, computed as `n̂um·(1/d̂en)` within `2u|t̂|` of
//!   `n̂um/d̂en`: `|n̂/d̂ − n/d| ≤ (|n̂/d̂| x + E_num/|d̂|) / (1 − x)` with
//!   `x = E_den/|d̂en|`. The root is certified only where `x < 1/4`, with
//!   `1/(1 − x)` bounded by `1 + 2x`: `e = (x(1 + 2x) + 6u)|t̂| + (1 +
//!   2x)E_num/|d̂en|`, split into its relative and absolute parts for
//!   [`certify`](crate::num::certify::certify), and every part widened by
//!   `1 + 2⁻³⁰` for the roundings of its own evaluation.
//!
//! The filter uses `E_num = 8u m_num` and `E_den = 4u m_den`, twice the
//! proof's constants. `|d̂en| > E_den` certifies a hit. A magnitude sum of
//! exactly 0 means every term is 0 (a nonzero product of f32 values, or of
//! `ŵᵢ` and `nᵢ`, is at least `2⁻²⁹⁸`), so the sum is exactly 0: `m_den = 0`
//! with `|n̂um| > E_num` certifies a parallel line, and `m_den = m_num = 0` a
//! line in the plane. A root exactly 0 (`m_num = 0`) is `+0`, as the oracle
//! rounds it. The rest, such as a line parallel in exact arithmetic but not
//! term by term, goes to the next stage.
//!
//! # Passes
//!
//! Both kernels first run [`filter_relative`]: where neither sum cancels
//! by a factor of [`K`] or more, the bound above becomes a constant
//! relative to `t̂`, and nothing but the certificate's two products waits
//! on the division. A line it leaves goes to [`filter_compensated`],
//! which sums `d·n` with one compensation: a line near parallel to the
//! plane keeps the same constant bound, and a `d·n` of exactly 0 is seen
//! as such, for [`exact_num`] to tell a line in the plane from one off it.
//! [`filter`], with the full quotient bound, and the later stages take
//! the rest: [`tight`], which sums `d·n` exactly in f64 words, and
//! [`double_word`], which sums both dot products in double words and
//! settles the in-plane and parallel lines whatever the data.

use crate::num::certify::{SLACK, U, least_subnormal_pair, quotient_bound};
use crate::num::dd::two_sum;
use crate::num::real::Real;

mod after;

pub use after::{double_word, tight};

/// The filter's result: the certified classes and the root with its bound.
#[derive(Clone, Copy, Debug)]
pub struct Filtered<L: Real> {
    /// Certified: one hit (`d·n ≠ 0`); `t` still needs
    /// [`certify`](crate::num::certify::certify).
    pub hit: L::Mask,
    /// Certified: parallel and off the plane.
    pub parallel: L::Mask,
    /// Certified: the line lies in the plane.
    pub in_plane: L::Mask,
    /// `num/den`.
    pub t: L,
    /// The relative part of `t`'s error bound.
    pub r: L,
    /// The absolute part of `t`'s error bound.
    pub a: L,
}

/// Runs the filter on a line `o + t d` and the plane through `a` with
/// normal `n`, every bound multiplied by `shrink` (1 in the kernels).
///
/// ```
/// use rayoracle::plane::stages::filter;
/// let f = filter::<f64>([0.0; 3], [0.0, 0.0, 2.0], [0.0, 0.0, 3.0], [0.0, 0.0, 1.0], 1.0);
/// assert!(f.hit && f.t == 1.5);
/// let f = filter::<f64>([0.0; 3], [1.0, 0.0, 0.0], [0.0, 0.0, 3.0], [0.0, 0.0, 1.0], 1.0);
/// assert!(f.parallel && !f.hit && !f.in_plane);
/// ```
#[inline(always)]
pub fn filter<L: Real>(o: [L; 3], d: [L; 3], a: [L; 3], n: [L; 3], shrink: f64) -> Filtered<L> {
    filter_terms(terms(o, d, a, n), shrink)
}

/// [`filter`] from the [`terms`] already computed.
#[inline(always)]
pub(crate) fn filter_terms<L: Real>(x: Terms<L>, shrink: f64) -> Filtered<L> {
    let x = sums(x, shrink);
    let (r, a) = quotient_bound(x.e_den, x.e_num, x.inv, 6.0 * U * shrink);
    Filtered {
        hit: x.den.abs().gt(x.e_den),
        parallel: x.parallel,
        in_plane: x.in_plane,
        t: x.t,
        r,
        a,
    }
}

/// The largest cancellation the [first pass](filter_relative) accepts in
/// either sum, `K = 2¹⁰`: a sum's magnitude sum `m̂` may be up to `K` times
/// its value.
pub const K: f64 = 1024.0;

/// The first pass of both kernels: the filter's sums, and the root `t̂ =
/// fl(n̂um/d̂en)` with a bound relative to it, where neither sum cancels by
/// a factor of [`K`] or more. No part of the bound waits on the
/// division: after it comes only the bit test of
/// [`certify_relative`](crate::num::certify::certify_relative).
///
/// # The bound
///
/// In the notation of the [module](self), with `p̂ᵢ = fl(ŵᵢnᵢ)`, `M =
/// Σ|p̂ᵢ|` and `m̂_num` its computed value (`M ≤ (1 + γ₂)m̂_num`): each
/// `p̂ᵢ` is within `(2u + u²)/(1 − u)²|p̂ᵢ|` of `(aᵢ − oᵢ)nᵢ` (the
/// difference and the product round once each), and each of the two
/// additions is within `u` of its result, the first's at most `(1 +
/// u)(|p̂₀| + |p̂₁|)`, so `|n̂um − num| < 3.0002u M + u|n̂um|`. The
/// products of `d·n` are exact, so its error is that of its two
/// additions: with `ŝ₁ = fl(d₀n₀ + d₁n₁)` and `d̂en = fl(ŝ₁ + d₂n₂)`,
/// `|d̂en − den| ≤ u|ŝ₁| + u|d̂en|`, a running bound with no magnitude
/// sum. Where `fl((K − 1)|d̂en|) > |ŝ₁|` and `m̂_num < K|n̂um|`:
///
/// * `x = E_den/|d̂en| < (1 + u)uK < 1.001uK`: one hit, certain;
/// * `E_num/|n̂um| < (3.0003K + 1)u`, so the quotient's bound of the
///   module is at most `|n̂um/d̂en|(1.001K + 3.0003K + 1)u/(1 − x) <
///   (4.002K + 1.01)u|n̂um/d̂en|`;
/// * the division rounds once, `|t̂ − n̂um/d̂en| ≤ u|n̂um/d̂en|`, and
///   `|n̂um/d̂en| ≤ (1 + 2u)|t̂|`.
///
/// So `|t̂ − t| < (4.002K + 2.02)u|t̂| < 4.01Ku|t̂|`, and the pass uses
/// **`r = 6Ku`**, one and a half times the proof's constant, exact in
/// f64. `K|n̂um|` is exact (a scaling by a power of two, far from
/// overflow).
///
/// A parallel line (`d̂en = 0`), a root exactly 0 (`m̂_num = 0`, whose
/// `t̂` may be −0 where the oracle's answer is +0), a NaN input and an
/// infinite one fail the comparisons (`0 > 0`, `∞ > ∞` and any comparison
/// with NaN are false), so no zero, infinite or NaN `t̂` is certified.
/// Nor is a root below `2⁻¹²⁵` in magnitude: the pass also asks `|t̂| ≥
/// 2⁻¹²⁵` (the scalar kernel's paired pass, from the bits of `t̂`'s
/// exponent, which must also not be all ones), so the certificate's test
/// of `t̂`'s bits holds there, its `f32` is normal, and flush-to-zero,
/// which acts only on subnormal results,
/// cannot touch it ([`needs_probe`](crate::num::certify::needs_probe)).
/// `K` is computed at run time as `2⁻¹⁴⁹·2¹⁵⁹`, the `2⁻¹⁴⁹` the least
/// subnormal `f32` converted there ([`Real::least_subnormal`],
/// [`least_subnormal_pair`]): under denormals-are-zero, which reads a
/// subnormal input as 0, it is 0, no `0·|n̂um| > m̂_num` holds, and the
/// pass certifies nothing. A kernel need not ask the environment for a
/// root this pass certifies. Every
/// line the pass leaves goes to [`filter_compensated`] and [`filter`],
/// after the kernel's check of the environment.
///
/// ```
/// use rayoracle::num::certify::certify_relative;
/// use rayoracle::plane::stages::{filter, filter_relative};
/// let (o, d, a, n) = ([0.0; 3], [0.1, 0.0, 3.0], [0.0, 0.0, 1.0], [0.0, 0.3, 1.0]);
/// let (f, g) = (filter::<f64>(o, d, a, n, 1.0), filter_relative::<f64>(o, d, a, n, 1.0));
/// assert!(g.hit && certify_relative(g.t, g.r) && g.t as f32 == f.t as f32);
/// // d·n = (1 + 2⁻²³)(1 − 2⁻²³) − 1 = −2⁻⁴⁶ cancels 47 bits, but its
/// // partial sum is exact, and the running bound says so.
/// let (e, a) = (2f64.powi(-23), [1.0, 0.0, 0.0]);
/// let (d, n) = ([1.0 + e, -1.0, 0.0], [1.0 - e, 1.0, 0.0]);
/// assert!(filter_relative::<f64>(o, d, a, n, 1.0).hit);
/// // d·n = 1 + 2⁻⁶⁰ − (1 − 2⁻²⁰): the partial sum 1 + 2⁻⁶⁰ rounds, and
/// // the sum is 2²⁰ times smaller. The first pass leaves it, the full
/// // filter certifies the hit.
/// let (d, n) = ([1.0, 2f64.powi(-30), 1.0], [1.0, 2f64.powi(-30), 2f64.powi(-20) - 1.0]);
/// assert!(filter::<f64>(o, d, a, n, 1.0).hit && !filter_relative::<f64>(o, d, a, n, 1.0).hit);
/// ```
#[inline(always)]
pub fn filter_relative<L: Real>(
    o: [L; 3],
    d: [L; 3],
    a: [L; 3],
    n: [L; 3],
    shrink: f64,
) -> Relative<L> {
    relative_terms(&first_terms(o, d, a, n), shrink)
}

/// The first pass's relative bound on the root, `6Ku`: see
/// [`filter_relative`].
pub const R: f64 = 6.0 * K * U;

/// [`first_terms`] and [`relative_terms`] for one line at f64, with the
/// two sums side by side in the two lanes of one `f64x2` (`num` in the
/// first, `den` in the second): the same operations in the same order, so
/// the same bits. The inputs' x and y are read as pairs, as a compiler
/// packs plain f64's, and their products transposed into the sums' lanes.
/// The comparisons are asked the other way, where each fails (`≥`, false
/// for a NaN), and one test of the mask takes both: a NaN that passes
/// them came from a NaN `n̂um`, `d̂en`, `m̂_num` or `ŝ₁` (any NaN term
/// makes its sums NaN), or from `0·∞` under DAZ with `|n̂um|` or `|d̂en|`
/// infinite, and leaves `t̂` a NaN, infinite or 0, which the test of its
/// exponent turns away, as the generic pass's comparisons do.
///
/// It gives its lanes ([`Pairs`]) rather than the sums: a kernel reads
/// the sums and the products `dᵢnᵢ` out of them only where the pass
/// leaves a line, and a line the pass certifies pays for no shuffle.
#[inline(always)]
pub(crate) fn first_pair(
    o: [f64; 3],
    d: [f64; 3],
    a: [f64; 3],
    n: [f64; 3],
    shrink: f64,
) -> (Pairs, Relative<f64>) {
    use wide::f64x2;
    // The components x and y in one register each, their products
    // transposed into the pairs [ŵ₀n₀, d₀n₀] and [ŵ₁n₁, d₁n₁].
    let v = |x: [f64; 3]| f64x2::from([x[0], x[1]]);
    let (nxy, wxy) = (v(n), v(a) - v(o));
    let [p0, p1] = f64x2::transpose([wxy * nxy, v(d) * nxy]);
    let p2 = f64x2::from([a[2] - o[2], d[2]]) * f64x2::splat(n[2]);
    let s1 = p0 + p1;
    let s = s1 + p2;
    let m = p0.abs() + p1.abs() + p2.abs();
    let [num, den] = s.to_array();
    // [K, K − 1], or 0 under DAZ. A lane fails where its comparison is
    // false: a NaN passes here, and leaves t̂ a NaN, infinite or 0, which
    // the test of its exponent turns away.
    let k = least_subnormal_pair() * f64x2::from([2f64.powi(159), (K - 1.0) * 2f64.powi(149)]);
    let fails = low_high(m, s1.abs()).simd_ge(k * s.abs());
    let t = num / den;
    let f = Relative {
        hit: fails.to_bitmask() == 0 && (EXP_MIN..0x7ff).contains(&(t.to_bits() >> 52 & 0x7ff)),
        t,
        r: R * shrink,
    };
    (
        Pairs {
            s,
            s1,
            m,
            p: [p0, p1, p2],
        },
        f,
    )
}

/// `[x₀, y₁]`: one `movsd` on x86-64, where building the pair from
/// scalars takes a shuffle of each.
#[inline(always)]
fn low_high(x: wide::f64x2, y: wide::f64x2) -> wide::f64x2 {
    #[cfg(target_arch = "x86_64")]
    {
        use wide::bytemuck::cast;
        cast(safe_arch::copy_replace_low_f64_m128d(cast(y), cast(x)))
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        wide::f64x2::from([x.to_array()[0], y.to_array()[1]])
    }
}

/// [`first_pair`]'s lanes: `[n̂um, d̂en]`, `[ŵ₀n₀ + ŵ₁n₁, ŝ₁]`, the two
/// magnitude sums, and the pairs of products `[ŵᵢnᵢ, dᵢnᵢ]`.
#[derive(Clone, Copy)]
pub(crate) struct Pairs {
    s: wide::f64x2,
    s1: wide::f64x2,
    m: wide::f64x2,
    p: [wide::f64x2; 3],
}

impl Pairs {
    /// The sums as [`first_terms`] gives them. Read where the pass leaves
    /// a line, this takes the products of `d·n` from their lanes there,
    /// not on the path of a line the pass certifies.
    #[inline(always)]
    pub(crate) fn first(&self) -> First<f64> {
        let ([num, den], [_, lead], [m_num, _]) =
            (self.s.to_array(), self.s1.to_array(), self.m.to_array());
        First {
            num,
            den,
            m_num,
            lead,
            dn: self.p.map(|v| v.to_array()[1]),
        }
    }
}

/// The biased exponent of `2⁻¹²⁵`, the least root the first pass
/// certifies.
const EXP_MIN: u64 = 1023 - 125;

/// [`filter_relative`] from the [`first_terms`] already computed.
#[inline(always)]
pub(crate) fn relative_terms<L: Real>(x: &First<L>, shrink: f64) -> Relative<L> {
    relative_terms_with(x, L::least_subnormal(), shrink)
}

/// [`relative_terms`] with `least` for [`Real::least_subnormal`]: a caller
/// that has found DAZ off, or no input subnormal, may pass `2⁻¹⁴⁹` itself,
/// and the pass then certifies under DAZ what it certifies without.
#[inline(always)]
pub(crate) fn relative_terms_with<L: Real>(x: &First<L>, least: L, shrink: f64) -> Relative<L> {
    // K, or 0 under DAZ; the largest f64 below 2⁻¹²⁵.
    let k = least * L::splat(2f64.powi(159));
    let (k1, below) = (L::splat(K - 1.0), L::splat(2f64.powi(-125).next_down()));
    let t = x.num / x.den;
    Relative {
        hit: (k1 * x.den.abs()).gt(x.lead.abs())
            & (k * x.num.abs()).gt(x.m_num)
            & t.abs().gt(below),
        t,
        r: R * shrink,
    }
}

/// The second pass: [`filter_relative`] over `d·n` summed with one
/// compensation, so that a line near parallel to the plane, whose `d·n`
/// cancels however far, still gets a relative bound known before the
/// division wherever the compensation is smaller than the sum. `num` is
/// the first pass's and must not cancel by [`K`] or more.
///
/// # The bound
///
/// The products `pᵢ = dᵢnᵢ` of f32 values are exact, below `2²⁵⁶` (so no
/// sum of them overflows) and multiples of `2⁻²⁹⁸`, as is every sum and
/// rounding error below: none is subnormal, and flush-to-zero changes
/// none. Knuth's TwoSum gives `(s₁, e₁) = TwoSum(p₀, p₁)` and `(s₂, e₂) =
/// TwoSum(s₁, p₂)`, so `den = s₂ + e₁ + e₂` exactly. With `ĉ = fl(e₁ + e₂)`
/// and `ĥ = fl(s₂ + ĉ)`, and round to nearest within `u` of its result
/// (`|fl(x) − x| ≤ u|fl(x)|`),
///
/// `|ĥ − den| ≤ u|ĥ| + u|ĉ|`.
///
/// Where `|ĉ| < 4|ĥ|`, `E_den < 5u|ĥ|`: a bound relative to `ĥ` whatever
/// the cancellation, with no magnitude sum at all. (`|ĉ|` may equal
/// `|ĥ|`: where `p₁` is lost next to `p₀ = −p₂`, `s₂ = 0` and `ĥ = ĉ =
/// e₁`.) With `num`'s bound of the first pass, `E_num < 4.01uK|n̂um|`,
/// the quotient's bound of the [module](self) is at most `|n̂um/ĥ|(5 +
/// 4.01K)u(1 + 11u)`, and with the division's own rounding `|t̂ − t| <
/// (4.02K + 6.02)u|t̂|`: the first pass's **`r = 6Ku`** covers it. The
/// first pass's other comparisons keep out zero, subnormal, infinite and
/// NaN roots (and, as there, every hit under denormals-are-zero), and `ĥ
/// = 0` fails `|ĉ| < 4|ĥ|`. The classes it certifies without a root,
/// `den_zero` and `parallel`, assume the inputs stand.
///
/// ```
/// use rayoracle::num::certify::certify_relative;
/// use rayoracle::plane::stages::{filter_compensated, filter_relative};
/// // d·n = 1 + 2⁻⁶⁰ − (1 − 2⁻²⁴) = 2⁻²⁴ + 2⁻⁶⁰, whose partial sum 1 + 2⁻⁶⁰
/// // rounds to 1: the root is 1/(2⁻²⁴ + 2⁻⁶⁰), just below 2²⁴.
/// let (o, a) = ([0.0; 3], [1.0, 0.0, 0.0]);
/// let (d, n) = ([1.0, 2f64.powi(-30), 1.0], [1.0, 2f64.powi(-30), 2f64.powi(-24) - 1.0]);
/// assert!(!filter_relative::<f64>(o, d, a, n, 1.0).hit);
/// let g = filter_compensated::<f64>(o, d, a, n, 1.0).relative;
/// assert!(g.hit && certify_relative(g.t, g.r) && g.t as f32 == 2f32.powi(24));
/// ```
#[inline(always)]
pub fn filter_compensated<L: Real>(
    o: [L; 3],
    d: [L; 3],
    a: [L; 3],
    n: [L; 3],
    shrink: f64,
) -> Compensated<L> {
    let x = first_terms(o, d, a, n);
    compensated_terms(x.num, x.m_num, x.dn, L::least_subnormal(), shrink)
}

/// [`filter_compensated`] from the first pass's `num` and its magnitude
/// sum, already computed, with `least` for [`Real::least_subnormal`]: a
/// caller that has found denormals-are-zero off, or no input subnormal,
/// may pass `2⁻¹⁴⁹` itself, and the pass then certifies under DAZ what it
/// certifies without (every value it meets is normal).
#[inline(always)]
pub(crate) fn compensated_terms<L: Real>(
    num: L,
    m_num: L,
    p: [L; 3],
    least: L,
    shrink: f64,
) -> Compensated<L> {
    let (s1, e1) = two_sum(p[0], p[1]);
    let (s2, e2) = two_sum(s1, p[2]);
    let c = e1 + e2;
    let h = s2 + c;
    let (k, tiny) = (L::splat(K), L::splat(2f64.powi(-274)));
    let (num_abs, den, zero) = (num.abs(), h.abs(), L::splat(0.0));
    let den_zero = h.eq(zero) & c.eq(zero);
    let small = (least * num_abs).gt(tiny * den);
    Compensated {
        relative: Relative {
            hit: (L::splat(4.0) * den).gt(c.abs()) & (k * num_abs).gt(m_num) & small,
            t: num / h,
            r: R * shrink,
        },
        den_zero,
        parallel: den_zero & num_abs.gt(L::splat(8.0 * U * SLACK * shrink) * m_num),
    }
}

/// The [second pass](filter_compensated)'s result: its hits, and the
/// lines it shows parallel in exact arithmetic.
#[derive(Clone, Copy, Debug)]
pub struct Compensated<L: Real> {
    /// The hits, as [`filter_relative`] gives them.
    pub relative: Relative<L>,
    /// Certified: `d·n = 0` exactly. Where `ĉ = 0`, `e₁ + e₂ = 0` exactly
    /// (a sum that rounds to 0 is 0), so `ĥ = s₂ = den`.
    pub den_zero: L::Mask,
    /// Certified: `d·n = 0` and `|n̂um| > 8u m̂_num`, the filter's `E_num`
    /// (widened by `1 + 2⁻³⁰`): parallel and off the plane.
    pub parallel: L::Mask,
}

/// `(a − o)·n` where it is exact: as `Σaᵢnᵢ − Σoᵢnᵢ`, six products of f32
/// values, exact in f64, summed with every sum checked to be exact by
/// Knuth's TwoSum (its error is 0). The mask says where no sum rounded;
/// there the value is exact, and its zeros are the lines in the plane,
/// for a line with `d·n = 0`. Every value is a multiple of `2⁻²⁹⁸`, so
/// flush-to-zero changes none.
///
/// ```
/// use rayoracle::plane::stages::exact_num;
/// assert_eq!(exact_num::<f64>([0.0, 0.0, 3.0], [3.0, 0.0, 0.0], [1.0, -1.0, 1.0]), (true, 0.0));
/// assert_eq!(exact_num::<f64>([0.0; 3], [1.0, 0.0, 0.0], [1.0, 2f64.powi(-60), 0.0]), (true, 1.0));
/// assert!(!exact_num::<f64>([1e-30, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 0.0, 0.0]).0);
/// ```
#[inline(always)]
pub fn exact_num<L: Real>(o: [L; 3], a: [L; 3], n: [L; 3]) -> (L::Mask, L) {
    let zero = L::splat(0.0);
    let (q0, e0) = two_sum(a[0] * n[0], -(o[0] * n[0]));
    let (q1, e1) = two_sum(a[1] * n[1], -(o[1] * n[1]));
    let (q2, e2) = two_sum(a[2] * n[2], -(o[2] * n[2]));
    let (s, e3) = two_sum(q0, q1);
    let (s, e4) = two_sum(s, q2);
    let exact = e0.eq(zero) & e1.eq(zero) & e2.eq(zero) & e3.eq(zero) & e4.eq(zero);
    (exact, s)
}

/// The [first pass](filter_relative)'s result.
#[derive(Clone, Copy, Debug)]
pub struct Relative<L: Real> {
    /// Certified: one hit, with `t`'s error at most `|t|·r` and `|t| ≥
    /// 2⁻¹²⁵`; the root still needs
    /// [`certify_relative`](crate::num::certify::certify_relative).
    pub hit: L::Mask,
    /// `num/den`.
    pub t: L,
    /// The bound on `t`'s error, relative to `|t|`, the same in every
    /// lane.
    pub r: f64,
}

/// The sums and their magnitude sums: `num = Σŵᵢnᵢ`, `den = Σdᵢnᵢ`.
#[derive(Clone, Copy)]
pub(crate) struct Terms<L: Real> {
    pub(crate) num: L,
    pub(crate) den: L,
    pub(crate) m_num: L,
    pub(crate) m_den: L,
}

impl Terms<f64> {
    /// Whether `d·n` cancels so far that [`filter`], its bounds multiplied
    /// by `shrink`, cannot certify the line's nonzero root: where
    /// `shrink·m̂_den > 2²⁹|d̂en|`, its bound is over `x|t̂| = 4u
    /// shrink·m̂_den/|d̂en|·|t̂| > 2⁻²²|t̂|`, an enclosure wider than the
    /// gaps between f32 rounding midpoints near any normal root. It
    /// decides no class without its root (parallel and in-plane lines have
    /// `m̂_den = 0`), and an exact root 0 (`m̂_num = 0`) is left to it. A
    /// kernel may go straight to the later stages, which decide every line
    /// the filter could (only a root whose `f32` is infinite or subnormal
    /// could have certified there).
    #[inline(always)]
    pub(crate) fn hopeless(&self, shrink: f64) -> bool {
        shrink * self.m_den > 2f64.powi(29) * self.den.abs() && self.m_num > 0.0
    }
}

/// Every pass's sums, computed once by a kernel that may run several.
#[inline(always)]
pub(crate) fn terms<L: Real>(o: [L; 3], d: [L; 3], a: [L; 3], n: [L; 3]) -> Terms<L> {
    first_terms(o, d, a, n).terms()
}

/// The [first pass](filter_relative)'s sums: `num = Σŵᵢnᵢ`, `den =
/// Σdᵢnᵢ`, `num`'s magnitude sum, and `den`'s first partial sum.
#[inline(always)]
pub(crate) fn first_terms<L: Real>(o: [L; 3], d: [L; 3], a: [L; 3], n: [L; 3]) -> First<L> {
    let w = [a[0] - o[0], a[1] - o[1], a[2] - o[2]];
    let wn = [w[0] * n[0], w[1] * n[1], w[2] * n[2]];
    let dn = [d[0] * n[0], d[1] * n[1], d[2] * n[2]];
    let lead = dn[0] + dn[1];
    First {
        num: wn[0] + wn[1] + wn[2],
        den: lead + dn[2],
        m_num: wn[0].abs() + wn[1].abs() + wn[2].abs(),
        lead,
        dn,
    }
}

/// The [first pass](filter_relative)'s sums.
#[derive(Clone, Copy)]
pub(crate) struct First<L: Real> {
    pub(crate) num: L,
    pub(crate) den: L,
    pub(crate) m_num: L,
    /// `ŝ₁ = fl(d₀n₀ + d₁n₁)`.
    pub(crate) lead: L,
    /// The products `dᵢnᵢ`, exact.
    pub(crate) dn: [L; 3],
}

impl<L: Real> First<L> {
    /// The later passes' [`Terms`]: these sums and `d·n`'s magnitude sum.
    #[inline(always)]
    pub(crate) fn terms(self) -> Terms<L> {
        let p = self.dn;
        Terms {
            num: self.num,
            den: self.den,
            m_num: self.m_num,
            m_den: p[0].abs() + p[1].abs() + p[2].abs(),
        }
    }
}

/// [`filter`]'s sums, their bounds, the certified parallel classes, and
/// the quotient.
struct Sums<L: Real> {
    den: L,
    e_num: L,
    e_den: L,
    parallel: L::Mask,
    in_plane: L::Mask,
    inv: L,
    t: L,
}

#[inline(always)]
fn sums<L: Real>(x: Terms<L>, shrink: f64) -> Sums<L> {
    let k = |x: f64| L::splat(x * U * shrink);
    let zero = L::splat(0.0);
    let Terms {
        num,
        den,
        m_num,
        m_den,
    } = x;
    let (e_num, e_den) = (k(8.0) * m_num, k(4.0) * m_den);
    let den_zero = m_den.eq(zero);
    let inv = L::splat(1.0) / den;
    Sums {
        den,
        e_num,
        e_den,
        parallel: den_zero & num.abs().gt(e_num),
        in_plane: den_zero & m_num.eq(zero),
        inv,
        // + 0 makes an exactly zero root +0 whatever the sign of den.
        t: num * inv + zero,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::certify::certify_relative;
    use proptest::prelude::*;

    /// Values whose products and sums cancel, round and tie, and any f32.
    fn value() -> impl Strategy<Value = f64> {
        let e = f64::from(f32::EPSILON);
        let edge = [
            0.0,
            1.0,
            1.0 + e,
            1.0 - e / 2.0,
            3.0,
            2f64.powi(-30),
            2f64.powi(-20) - 1.0,
            1e-40,
        ];
        prop_oneof![
            (0..edge.len(), any::<bool>()).prop_map(move |(i, neg)| if neg {
                -edge[i]
            } else {
                edge[i]
            }),
            any::<f32>().prop_map(f64::from),
        ]
    }

    /// The first pass leaves a line whose `n̂um` cancels by [`K`] (`m̂_num
    /// = K|n̂um|`) or whose `d̂en` cancels its first partial sum by `K − 1`
    /// (`|ŝ₁| = (K − 1)|d̂en|`), and takes one just inside either limit:
    /// the paired-lane pass and the generic one alike. Every sum here is
    /// exact, so the limits are met exactly.
    #[test]
    fn the_first_pass_stops_at_its_cancellation_limits() {
        let pass = |o, d, a, n| {
            let (paired, generic) = (
                first_pair(o, d, a, n, 1.0).1,
                filter_relative(o, d, a, n, 1.0),
            );
            assert_eq!(paired.hit, generic.hit, "{o:?} {d:?} {a:?} {n:?}");
            generic.hit && certify_relative(generic.t, generic.r)
        };
        let z = [0.0; 3];
        // num = a₀ + a₁ = 1 against m_num = |a₀| + |a₁|; d·n = 1.
        for (a0, hit) in [(512.5, false), (512.25, true)] {
            assert_eq!(
                pass(z, [1.0, 0.0, 0.0], [a0, 1.0 - a0, 0.0], [1.0, 1.0, 0.0]),
                hit,
                "{a0}"
            );
        }
        // d·n = ŝ₁ + d₂ = 1 with ŝ₁ = d₀; num = 1.
        for (d0, hit) in [(K - 1.0, false), (K - 1.5, true)] {
            let d = [d0, 0.0, 1.0 - d0];
            assert_eq!(pass(z, d, [1.0, 0.0, 0.0], [1.0; 3]), hit, "{d0}");
        }
    }

    /// Every bound of the full filter scales with `shrink`: at a factor
    /// `s < 1`, each part is at most `s` times its value at 1 (the
    /// quotient's `1 + 2x` shrinks too), on lines from well to badly
    /// conditioned.
    #[test]
    fn the_full_filters_bounds_scale_with_shrink() {
        let mut next = crate::num::xorshift(29);
        let mut seen = 0;
        for _ in 0..2000 {
            let mut v = || f64::from((next() % 2001) as f32 / 1000.0 - 1.0);
            let (o, d, a, n) = (
                [v(), v(), v()],
                [v(), v(), v()],
                [v(), v(), v()],
                [v(), v(), v()],
            );
            let f = filter::<f64>(o, d, a, n, 1.0);
            if !f.hit || !f.r.is_finite() {
                continue;
            }
            seen += 1;
            for s in [0.5, 0.25, 1.0 / 64.0] {
                let g = filter::<f64>(o, d, a, n, s);
                assert!(g.hit && g.t == f.t, "{o:?} {d:?} {a:?} {n:?}");
                assert!(
                    g.r <= s * f.r && g.a <= s * f.a,
                    "{s}: {:e} {:e}, {:e} {:e}",
                    g.r,
                    f.r,
                    g.a,
                    f.a
                );
            }
        }
        assert!(seen > 1000, "{seen}");
    }

    /// The second pass's test for a parallel line scales with `shrink`:
    /// `d·n = 0` exactly, and `n̂um = 12u` against `m̂_num ≈ 2` (`1 − 1 +
    /// 12u`), between the bound `8u m̂_num` at 1 and at 1/2.
    #[test]
    fn the_second_passs_parallel_test_scales_with_shrink() {
        let (o, d, n) = ([0.0; 3], [1.0, -1.0, 0.0], [1.0; 3]);
        let a = [1.0, -1.0, 12.0 * U];
        let at = |s| filter_compensated::<f64>(o, d, a, n, s);
        assert!(at(1.0).den_zero && !at(1.0).parallel);
        assert!(at(0.5).parallel && at(0.25).parallel);
    }

    proptest! {
        /// The paired-lane first pass is the generic one, bit for bit.
        #[test]
        fn first_pair_is_the_generic_first_pass(
            v in proptest::collection::vec(value(), 12),
            shrink in prop_oneof![Just(1.0), 0.0..1.0],
        ) {
            let t = |i: usize| [v[i], v[i + 1], v[i + 2]];
            let (o, d, a, n) = (t(0), t(3), t(6), t(9));
            let (x, f) = first_pair(o, d, a, n, shrink);
            let x = x.first();
            let (y, g) = (first_terms(o, d, a, n), filter_relative(o, d, a, n, shrink));
            let bits = |x: &First<f64>| [x.num, x.den, x.m_num, x.lead].map(f64::to_bits);
            let nan = [y.num, y.den, y.m_num, y.lead].iter().any(|v| v.is_nan());
            prop_assert!(bits(&x) == bits(&y) || [x.num, x.den].iter().any(|v| v.is_nan()));
            prop_assert_eq!(x.dn.map(f64::to_bits), y.dn.map(f64::to_bits));
            let pass = (K - 1.0) * y.den.abs() > y.lead.abs() && K * y.num.abs() > y.m_num;
            prop_assert!(!f.hit || pass || nan);
            prop_assert_eq!(f.hit, g.hit);
            prop_assert!(f.t.to_bits() == g.t.to_bits() || (f.t.is_nan() && g.t.is_nan()));
            prop_assert_eq!(f.r, g.r);
        }
    }
}
