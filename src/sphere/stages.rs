//! The filter: the sphere's first stage, written once over [`Real`] and
//! run at `f64` by [`super::reference`](mod@super::reference) and at
//! [`F64x4`](crate::num::real::F64x4) by [`super::x4`]. It evaluates the
//! textbook quadratic in f64 with a bound on every error, and certifies only
//! what the bound decides; the rest goes to the later stages.
//!
//! # The bound
//!
//! The inputs are f32, so exact in f64. Write `u = 2⁻⁵³` and `γₙ = nu/(1 −
//! nu)`; a value that went through `n` roundings from exact data is within
//! `γₙ` of it, relatively, and a computed sum of such terms is within `γₙ`
//! times the sum of their magnitudes, `n` counting the roundings on the
//! longest path (Higham, *Accuracy and Stability of Numerical Algorithms*,
//! §3.1). Hats are computed values, `E` a bound on a computed value's error.
//!
//! * `f̂ᵢ = fl(oᵢ − Cᵢ)`, one rounding.
//! * `a = Σdᵢ²`: the squares of f32 values are exact, two additions:
//!   `E_a = γ₂ a`. And `a = 0` exactly when `d = 0`, since `dᵢ² ≥ 2⁻²⁹⁸`.
//! * `b = Σfᵢdᵢ`: one rounding in `f̂ᵢ`, one in the product, two additions:
//!   `E_b = γ₄ m_b` with `m_b = Σ|f̂ᵢdᵢ|`.
//! * `c = Σfᵢ² − R²`: `f̂ᵢ²` carries three roundings (two from `f̂ᵢ`, one
//!   its own), the two additions of the nonnegative `f̂ᵢ²` one each
//!   relative to their sum `f̂f`, and the subtraction of the exact `R²`
//!   one relative to `ĉ`: `|ĉ − c| ≤ 5u f̂f + u|ĉ|` to first order. The
//!   classes take the coarser `γ₆ m_c`, `m_c = f̂f + R²`, which the
//!   argument for `Δ` below needs only through `|ĉ| ≤ m_c`.
//! * `Δ = b² − ac`: `|b̂² − b²| ≤ E_b(2|b̂| + E_b)`, `|âĉ − ac| ≤ â E_c +
//!   (|ĉ| + E_c) E_a`, and the two products and the difference round once
//!   each, by at most `u(b̂² + |âĉ|)` together with the difference's own.
//!   With `|b̂| ≤ m_b` and `|ĉ| ≤ m_c` this is at most `10u(m_b² + â m_c)`
//!   to first order (`8u m_b²` from `b̂`, `8u â m_c` from `â` and `ĉ`, `u`
//!   for the products' roundings and `u` for the difference's), and the
//!   filter uses **`E_Δ = 20u(m_b² + â m_c)`**: twice the proof's
//!   constant, so that the second-order terms (of order `u²`) and the
//!   roundings of the magnitudes themselves (a few `u` relatively) are
//!   covered.
//!
//! `Δ̂ > E_Δ` certifies two roots and `Δ̂ < −E_Δ` none. A tangent (`Δ = 0`)
//! is never certified here.
//!
//! For the roots (after Ray Tracing Gems ch. 7 and pbrt-v4), `s = √Δ`,
//! `q = −(b + sign(b̂)s)`, and the roots are `q/a` and `c/q`, sorted; the
//! sign is taken from `b̂` even where `b`'s own is uncertain, which only
//! costs accuracy, never validity, since both signs give the same roots.
//! The roots need `1/â`, `1/q̂` and `1/ŝ`. On one lane they are three
//! divisions, which run in parallel; on four, where division throughput is
//! what counts, they come from one, `ρ = 1/(q̂âŝ)`: `1/â = q̂ŝρ`, `1/q̂ =
//! âŝρ`, `1/ŝ = q̂âρ`. Either way each is within `4u` relatively.
//!
//! * `ŝ = fl(√Δ̂)`: `|√Δ − √Δ̂| ≤ E_Δ/√Δ̂` (from `√x − √(x − e) ≤ e/√x`),
//!   so `E_s = E_Δ/ŝ + 2u ŝ`.
//! * `|q̂| = fl(|b̂| + ŝ)` (no cancellation): `E_q = E_b + E_s + 2u|q̂|`.
//! * `t₀ = q/a`, computed as `q̂·(1/â)`, within `5u|t̂₀|` of `q̂/â`; and
//!   `|q̂/â − q/a| ≤ (|q̂/â| E_a + E_q) / (â − E_a)`, where `E_a/(â − E_a)`
//!   is `4u` to first order. So `e₀ = 10u|t̂₀| + E_q/â`.
//! * `t₁ = c/q`, computed as `ĉ·(1/q̂)`, within `5u|t̂₁|` of `ĉ/q̂`; and
//!   `|ĉ/q̂ − c/q| ≤ (|ĉ/q̂| x + E_c/|q̂|) / (1 − x)` with `x = E_q/|q̂|`.
//!   The filter certifies `t₁` only where `x < 1/4`, and bounds `1/(1 − x)`
//!   by `1 + 2x`: `e₁ = (x(1 + 2x) + 10u)|t̂₁| + (1 + 2x)E_c/|q̂|`.
//!
//! Each bound is split, for [`certify`](crate::num::certify::certify), into
//! a part relative to the root and an absolute part; every quantity the
//! bounds are made of is widened by `1 + 2⁻³⁰`, which covers the roundings
//! of their own evaluation and of the reciprocals. Every constant above is
//! at least twice what the proof needs: `E_a = 4u â`, `E_b = 8u m_b`,
//! `E_c = 10u f̂f + 2u|ĉ|`, and `20u` where the roots' roundings need `9u`.
//!
//! # Range
//!
//! The quantities of `Δ` are products of at most four inputs (`b²`, `ac`),
//! and a product of up to six f32 values lies between `2⁻⁸⁹⁴` and `2⁷⁶⁸` in
//! magnitude: no overflow, and no underflow into f64's subnormals, so the
//! relative error model holds for every finite input. The one product of
//! degree six, `q̂âŝ`, is used only where two roots are certified, and
//! there `Δ̂ ≥ 2⁻⁶⁵⁰` (a nonzero difference of two f64 values of at least
//! `2⁻⁵⁹⁶`), so `ŝ ≥ 2⁻³²⁵`, `|q̂| ≥ ŝ` and `â ≥ 2⁻²⁹⁸` keep it above
//! `2⁻⁹⁴⁸`; `|q̂| ≤ 2²⁶⁰`, `ŝ ≤ 2²⁶⁰` and `â ≤ 2²⁵⁸` keep it below `2⁷⁷⁸`.
//! An infinite input makes a magnitude sum infinite, and a NaN makes `Δ̂`
//! NaN; neither certifies anything.
//!
//! # After the filter
//!
//! The reference takes what the filter leaves to the later stages, each
//! with its own bound derived beside it, and last to the exact oracle:
//!
//! * [`grid_exact`]: small-integer and dyadic data, on which the filter's
//!   f64 arithmetic is provably exact;
//! * [`tracked`]: the filter's values with every operation checked for
//!   exactness, so that a tangent or a root exactly 0 follows from signs;
//! * [`tight`]: the discriminant in the Ray Tracing Gems form, whose
//!   error grows with `R·|f|`, for far tiny spheres;
//! * [`compensated`]: `c` computed compensated, where it cancels near
//!   `R²`;
//! * [`double_word`]: every quantity in two words, after the words stage
//!   ([`super::words`]).

use crate::num::certify::{SLACK, U, quotient_bound};
use crate::num::dd::Approx;
use crate::num::real::Real;

mod after;
pub mod misses;

pub(crate) use after::{c_cancels, compensated_from, double_word_by, grid_from};
pub use after::{compensated, double_word, grid_exact, tight, tracked};

/// The filter's result: the classes it certified, and both roots (in
/// computation order) with their error bounds, each `|t|·r + a`.
#[derive(Clone, Copy, Debug)]
pub struct Filtered<L: Real> {
    /// Certified: no root (no line, or `Δ < 0`).
    pub none: L::Mask,
    /// Certified: two roots (`Δ > 0`); the roots still need
    /// [`certify`](crate::num::certify::certify).
    pub two: L::Mask,
    /// `q/a`.
    pub t0: L,
    /// The relative part of `t0`'s error bound.
    pub r0: L,
    /// The absolute part of `t0`'s error bound.
    pub a0: L,
    /// `c/q`.
    pub t1: L,
    /// The relative part of `t1`'s error bound.
    pub r1: L,
    /// The absolute part of `t1`'s error bound.
    pub a1: L,
}

/// The quantities the filter and the tight stage share: `f = o − C`, `a =
/// d·d`, `b = f·d`, `m_b = Σ|fᵢdᵢ|`, `f·f` and `R²`, in f64 as written.
#[derive(Clone, Copy)]
struct Dots<L> {
    f: [L; 3],
    a: L,
    b: L,
    mb: L,
    ff: L,
    rr: L,
}

#[inline(always)]
fn dots<L: Real>(o: [L; 3], d: [L; 3], c: [L; 3], r: L) -> Dots<L> {
    let f = [o[0] - c[0], o[1] - c[1], o[2] - c[2]];
    let a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
    let fd = [f[0] * d[0], f[1] * d[1], f[2] * d[2]];
    let b = fd[0] + fd[1] + fd[2];
    let mb = fd[0].abs() + fd[1].abs() + fd[2].abs();
    let ff = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
    let rr = r * r;
    Dots {
        f,
        a,
        b,
        mb,
        ff,
        rr,
    }
}

/// The quadratic and the classes both filters certify: `c = f·f − R²`,
/// `m_c = f·f + R²`, `Δ̂ = b² − ac` and `E_Δ = 20u(m_b² + â m_c)`, then no
/// root where `a = 0` or `Δ̂ < −E_Δ`, two where `Δ̂ > E_Δ`.
#[derive(Clone, Copy)]
pub(crate) struct Classes<L: Real> {
    a: L,
    b: L,
    mb: L,
    ff: L,
    mc: L,
    cq: L,
    /// `Δ̂`.
    pub(crate) disc: L,
    ed: L,
    /// Certified: no root.
    pub(crate) none: L::Mask,
    /// Certified: two roots.
    pub(crate) two: L::Mask,
}

impl Classes<f64> {
    /// The same classes, with the class known to be open (neither mask
    /// set), as the caller has just tested.
    #[inline(always)]
    pub(crate) fn open(self) -> Classes<f64> {
        Classes {
            none: false,
            two: false,
            ..self
        }
    }
    /// Whether the direction is not zero (`â > 0`): a line.
    #[inline(always)]
    pub(crate) fn line(&self) -> bool {
        self.a > 0.0
    }
    /// `a`, `b` and `c` as the filter computed them, with its bounds `E_a
    /// = 4uâ`, `E_b = 8u m_b` and `E_c = 10u f̂f + 2u|ĉ|`
    /// ([module](self)), widened by [`SLACK`].
    #[inline(always)]
    pub(crate) fn quadratic(&self) -> [Approx; 3] {
        let x = |v: f64, e: f64| Approx { v, e: e * SLACK };
        [
            x(self.a, 4.0 * U * self.a),
            x(self.b, 8.0 * U * self.mb),
            x(self.cq, e_c(self.ff, self.cq, 1.0)),
        ]
    }
}

#[inline(always)]
pub(crate) fn classes<L: Real>(o: [L; 3], d: [L; 3], c: [L; 3], r: L, shrink: f64) -> Classes<L> {
    let Dots {
        a, b, mb, ff, rr, ..
    } = dots(o, d, c, r);
    let cq = ff - rr;
    let mc = ff + rr;
    let disc = b * b - a * cq;
    let ed = L::splat(20.0 * U * shrink) * (mb * mb + a * mc);
    let line = a.gt(L::splat(0.0));
    Classes {
        a,
        b,
        mb,
        ff,
        mc,
        cq,
        disc,
        ed,
        none: !line | (-ed).gt(disc),
        two: line & disc.gt(ed),
    }
}

/// Runs the filter on a line `o + t d` and a sphere `(c, r)`, with every
/// bound multiplied by `shrink` (1 in the kernels; the tests pass less to
/// show that a bound too small is caught).
///
/// ```
/// use rayoracle::sphere::stages::filter;
/// let f = filter::<f64>([0.0, 0.0, -5.0], [0.0, 0.0, 1.0], [0.0; 3], 1.0, 1.0);
/// assert!(f.two && !f.none);
/// assert_eq!((f.t0, f.t1), (6.0, 4.0)); // q/a and c/q
/// let e0 = f.t0 * f.r0 + f.a0;
/// assert!(e0 > 0.0 && e0 < 1e-12);
/// ```
///
/// [`certify`](crate::num::certify::certify): crate::num::certify::certify
#[inline(always)]
pub fn filter<L: Real>(o: [L; 3], d: [L; 3], c: [L; 3], r: L, shrink: f64) -> Filtered<L> {
    filter_from(classes(o, d, c, r, shrink), shrink)
}

/// `E_c = 10u f̂f + 2u|ĉ|` ([module](self)), times `shrink`.
#[inline(always)]
fn e_c<L: Real>(ff: L, c: L, shrink: f64) -> L {
    L::splat(10.0 * U * shrink) * ff + L::splat(2.0 * U * shrink) * c.abs()
}

/// [`filter`] from the [`classes`] already computed.
#[inline(always)]
pub(crate) fn filter_from<L: Real>(classes: Classes<L>, shrink: f64) -> Filtered<L> {
    let k = |x: f64| L::splat(x * U * shrink);
    let u2 = L::splat(2.0 * U * shrink);
    let Classes {
        a,
        b,
        mb,
        ff,
        cq,
        disc,
        ed,
        none,
        two,
        ..
    } = classes;

    // E_a = 4u·â enters only through the constant of r0.
    let (eb, ec) = (k(8.0) * mb, e_c(ff, cq, shrink));
    let (one, slack) = (L::splat(1.0), L::splat(SLACK));
    let s = disc.sqrt();
    let q = -(b + s.copysign(b));
    let (ia, iq, is) = if L::FEW_DIVISIONS {
        let rho = one / (q * a * s);
        (q * s * rho, a * s * rho, q * a * rho)
    } else {
        (one / a, one / q, one / s)
    };
    let es = ed * is * slack + u2 * s;
    let eq = eb + es + u2 * q.abs();
    let t0 = q * ia;
    let a0 = eq * ia * slack;
    let t1 = cq * iq;
    let (r1, a1) = quotient_bound(eq, ec, iq, 20.0 * U * shrink);
    Filtered {
        none,
        two,
        t0,
        r0: k(20.0),
        a0,
        t1,
        r1,
        a1,
    }
}

/// The filter's first pass in the x4 kernels: the same classes as
/// [`filter`], and both roots in the textbook form `(−b ∓ ŝ)/â`, sorted,
/// with one error bound `|t|·r + a` for both.
#[derive(Clone, Copy, Debug)]
pub struct Sorted<L: Real> {
    /// Certified: no root, as in [`Filtered::none`].
    pub none: L::Mask,
    /// Certified: two roots, as in [`Filtered::two`].
    pub two: L::Mask,
    /// `(−b − ŝ)/a`, the smaller root.
    pub lo: L,
    /// `(−b + ŝ)/a`, the larger root.
    pub hi: L,
    /// The relative part of either root's error bound.
    pub r: L,
    /// The absolute part of either root's error bound.
    pub a: L,
}

/// [`filter`] with the roots as `(−b ∓ ŝ)/â`: no quotient waits for the
/// square root, so the longest chain of dependent operations is shorter
/// by a division and the products around it. The price is cancellation in
/// the root nearer `−b/a`: where it is far smaller than the other (`c`
/// near 0, an origin near the sphere), its bound is too wide to certify,
/// and the x4 kernels fall back on [`filter`]'s `c/q`.
///
/// # The bound
///
/// In the notation of the [module](self), on the lanes where `Δ̂ > E_Δ`
/// (so `Δ̂ > 0`): one division `ρ = 1/(âΔ̂)`, started with the square root,
/// gives `1/â = Δ̂ρ` within `3u`, and `1/(ŝâ) = ŝρ` within `4u`, so that
/// `E_s/â = (E_Δ/ŝ + 2uŝ)/â` is evaluated as `ŝρ(E_Δ + 2uΔ̂)`, which waits
/// on the division alone. With `n̂ = fl(−b̂ ∓ ŝ)` against `n = −b ∓ √Δ`: `|n̂ − n| ≤ u|n̂| +
/// E_b + E_s`, `E_s = E_Δ/ŝ + 2uŝ` as in the filter. The root `t̂ =
/// fl(n̂·(1/â))` is within `4u|t̂|` of `n̂/â`, and `|n̂/â − n/a| ≤ (|n̂|
/// E_a/a + |n̂ − n|)/â`, with `E_a/a ≤ 2u`: `e = 7u|t̂| + (E_b + E_s)/â`
/// to first order. The pass uses `r = 20u` and `a = (E_b + E_s)/â`, with
/// `E_b = 8u m_b`, `E_Δ = 20u(m_b² + âm_c)` and every part widened by `1
/// + 2⁻³⁰`, as in the filter.
///
/// Rounding is monotone and `ŝ ≥ 0`, `1/â > 0`, so `lo ≤ hi` without a
/// comparison. An exact root 0 gives `n̂ = ±0` with `a > 0`, which never
/// certifies.
///
/// # Range
///
/// Where two roots are certified, `âΔ̂` lies between `2⁻⁹⁴⁸` and `2⁷⁷⁸`
/// (the bounds of `q̂âŝ` in the module's range section), so `ρ`, `1/â` and
/// `1/Δ̂` are normal and finite; `ρ(E_Δ + 2uΔ̂) ≥ 2u/â` is at least
/// `2⁻³¹¹`, as `â < 2²⁵⁸`, so it does not underflow.
///
/// ```
/// use rayoracle::num::certify::certify;
/// use rayoracle::sphere::stages::filter_sorted;
/// let f = filter_sorted::<f64>([0.0, 0.0, -5.0], [0.0, 0.0, 1.0], [0.0; 3], 1.0, 1.0);
/// assert!(f.two && !f.none);
/// assert_eq!((f.lo, f.hi), (4.0, 6.0));
/// assert!(certify(f.lo, f.r, f.a) && certify(f.hi, f.r, f.a));
/// // From on the sphere: the root 0 is all cancellation.
/// let f = filter_sorted::<f64>([0.0, 0.0, -1.0], [0.0, 0.0, 1.0], [0.0; 3], 1.0, 1.0);
/// assert!(f.two && !certify(f.lo, f.r, f.a));
/// ```
#[inline(always)]
pub fn filter_sorted<L: Real>(o: [L; 3], d: [L; 3], c: [L; 3], r: L, shrink: f64) -> Sorted<L> {
    sorted(classes(o, d, c, r, shrink), shrink)
}

/// [`filter_sorted`] from the [`classes`] already computed, so that the
/// reference can return on a certain class before the roots.
#[inline(always)]
pub(crate) fn sorted<L: Real>(classes: Classes<L>, shrink: f64) -> Sorted<L> {
    let k = |x: f64| L::splat(x * U * shrink);
    let Classes {
        a,
        b,
        mb,
        disc,
        ed,
        none,
        two,
        ..
    } = classes;

    let slack = L::splat(SLACK);
    // ρ = 1/(âΔ̂), and 1/â.
    let (rho, ia) = if L::FEW_DIVISIONS {
        let rho = L::splat(1.0) / (a * disc);
        (rho, disc * rho)
    } else {
        let (ia, idisc) = (L::splat(1.0) / a, L::splat(1.0) / disc);
        (ia * idisc, ia)
    };
    // Everything but ŝ, ready while the square root runs: (E_b + E_s)/â =
    // E_b/â + ŝρ(E_Δ + 2uΔ̂), waiting on ρ alone.
    let eb = k(8.0) * mb * ia * slack;
    let es = rho * ((ed + k(2.0) * disc) * slack);
    let s = disc.sqrt();
    Sorted {
        none,
        two,
        lo: (-b - s) * ia,
        hi: (-b + s) * ia,
        r: k(20.0),
        a: eb + s * es,
    }
}

#[cfg(all(test, feature = "plane", feature = "quadric"))]
mod tests {

    /// The sorted pass's bound is the derivation's, `r = 20u` and `a =
    /// (8u m_b/â + ŝ(E_Δ + 2uΔ̂)/(âΔ̂))·SLACK` with `u` scaled by `shrink`,
    /// on one lane (three divisions) and on four (one): over directions
    /// from `2⁻²⁰` to `2²⁰` long, so that `â`, `Δ̂` and their product range
    /// far from 1, where a wrong reciprocal or a product taken for a
    /// quotient shows.
    #[test]
    fn the_sorted_pass_bound_is_the_derivations() {
        use super::{SLACK, U, filter_sorted};
        use crate::num::real::{F64x4, Real};
        for ((shrink, o, dir, c, r), k) in two_root_lines() {
            let u = U * shrink;
            let (a, disc) = (k.a, k.disc);
            let es = disc.sqrt() * (k.ed + 2.0 * u * disc) / (a * disc);
            let want = (8.0 * u * k.mb / a + es) * SLACK;
            let one = filter_sorted::<f64>(o, dir, c, r, shrink);
            let w = |v: [f64; 3]| v.map(F64x4::splat);
            let four = filter_sorted(w(o), w(dir), w(c), F64x4::splat(r), shrink);
            for (got, lanes) in [(one.a, "one"), (four.a.to_array()[0], "four")] {
                assert!(
                    ((got - want) / want).abs() < 1e-14,
                    "{lanes}, {o:?} {dir:?}, R = {r}, shrink {shrink}: {got:e}, not {want:e}"
                );
            }
            assert_eq!((one.r, four.r.to_array()[0]), (20.0 * u, 20.0 * u));
        }
    }

    /// A line for the bound tests: `(shrink, o, d, C, R)`.
    pub(super) type Line = (f64, [f64; 3], [f64; 3], [f64; 3], f64);

    /// Lines for the bound tests whose two roots the classes certify,
    /// with those classes: towards three spheres' centres from outside, a
    /// little off, with directions from `2⁻²⁰` to `2²⁰` long, at `shrink`
    /// 1 and 1/4.
    pub(super) fn two_root_lines() -> Vec<(Line, super::Classes<f64>)> {
        let cases: [([f64; 3], f64); 3] = [
            ([0.3, 0.2, -5.0], 1.0),
            ([1e3, -2e3, 4e3], 7e2),
            ([1e-3, 0.0, 0.5], 2e-3),
        ];
        let mut lines = Vec::new();
        for shrink in [1.0, 0.25] {
            for e in (-20..=20).step_by(5) {
                let l = 2f64.powi(e);
                for (o, rad) in cases {
                    let o = o.map(|x| x as f32 as f64);
                    let n = (o[0] * o[0] + o[1] * o[1] + o[2] * o[2]).sqrt();
                    let aim = [0.1 * rad - o[0], -o[1], 0.05 * rad - o[2]];
                    let dir = aim.map(|x| (x * l / n) as f32 as f64);
                    let (c, r) = ([0.0; 3], rad as f32 as f64);
                    let k = super::classes::<f64>(o, dir, c, r, shrink);
                    if k.two {
                        lines.push(((shrink, o, dir, c, r), k));
                    }
                }
            }
        }
        assert!(lines.len() >= 40, "{}", lines.len());
        lines
    }

    /// The filter's bounds are the derivation's: `r₀ = 20u`, `a₀ =
    /// E_q/â·SLACK`, and `t₁`'s from [`quotient_bound`](super::quotient_bound)
    /// with `E_q = E_b + E_s + 2u|q̂|`, `E_b = 8u m_b`, `E_s =
    /// E_Δ·SLACK/ŝ + 2uŝ` and `E_c = 10u f̂f + 2u|ĉ|`, `u` scaled by
    /// `shrink`; on one lane (three divisions) and four (one), over the
    /// lines of [`two_root_lines`].
    #[test]
    fn the_filters_bounds_are_the_derivations() {
        use super::{SLACK, U, filter, quotient_bound};
        use crate::num::real::{F64x4, Real};
        let close = |got: f64, want: f64, what: &str| {
            let ok = got == want || ((got - want) / want).abs() < 1e-14;
            assert!(ok, "{what}: {got:e}, not {want:e}");
        };
        for ((shrink, o, dir, c, r), k) in two_root_lines() {
            let u = U * shrink;
            let s = k.disc.sqrt();
            let q = -(k.b + s.copysign(k.b));
            let eq = 8.0 * u * k.mb + (k.ed * SLACK / s + 2.0 * u * s) + 2.0 * u * q.abs();
            let ec = 10.0 * u * k.ff + 2.0 * u * k.cq.abs();
            let (r1, a1) = quotient_bound(eq, ec, 1.0 / q, 20.0 * u);
            let one = filter::<f64>(o, dir, c, r, shrink);
            let w = |v: [f64; 3]| v.map(F64x4::splat);
            let four = filter(w(o), w(dir), w(c), F64x4::splat(r), shrink);
            let at = format!("{o:?} {dir:?} R = {r}, shrink {shrink}");
            let lane = |x: F64x4| x.to_array()[0];
            for (got, lanes) in [
                ([one.r0, one.a0, one.r1, one.a1], "one"),
                (
                    [lane(four.r0), lane(four.a0), lane(four.r1), lane(four.a1)],
                    "four",
                ),
            ] {
                close(got[0], 20.0 * u, &format!("r0, {lanes}, {at}"));
                close(got[1], eq / k.a * SLACK, &format!("a0, {lanes}, {at}"));
                close(got[2], r1, &format!("r1, {lanes}, {at}"));
                close(got[3], a1, &format!("a1, {lanes}, {at}"));
            }
        }
    }
}
