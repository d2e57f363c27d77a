//! The filter: the quadric's first stage, written once over [`Real`] and
//! run at `f64` by [`super::reference`](mod@super::reference) and at
//! [`F64x4`](crate::num::real::F64x4) by [`super::x4`].
//!
//! # The bound
//!
//! In the notation of [`crate::sphere::stages`] (`u = 2⁻⁵³`, `γₙ`, hats for
//! computed values, `E` for error bounds), with f32 inputs exact in f64.
//! Every term of α, β and γ is a coefficient times one or two inputs: `k·x`
//! is exact (two f32 values), `k·x·y` rounds once, and the factor 2 of β's
//! square terms is exact. Summed left to right:
//!
//! * α, 6 terms: `E_α = γ₆ m_α`;
//! * β, 12 terms: `E_β = γ₁₂ m_β`;
//! * γ, 10 terms: `E_γ = γ₁₀ m_γ`;
//!
//! with `m` the sum of the terms' magnitudes. The filter uses twice these:
//! `E_α = 12u m_α`, `E_β = 24u m_β`, `E_γ = 20u m_γ`.
//!
//! * `Δ = β² − 4αγ`: `|β̂² − β²| ≤ E_β(2|β̂| + E_β)`, `|α̂γ̂ − αγ| ≤ |α̂|E_γ
//!   + (|γ̂| + E_γ)E_α`, and three roundings of at most `u(β̂² + 4|α̂γ̂|)`.
//!   With `|β̂| ≤ m_β`, `|α̂| ≤ m_α`, `|γ̂| ≤ m_γ`, that is at most
//!   `u(50 m_β² + 136 m_α m_γ)` to first order; the filter uses
//!   **`E_Δ = u(100 m_β² + 300 m_α m_γ)`**.
//! * `|α̂| > E_α` certifies a quadratic, then `Δ̂ > E_Δ` two roots and
//!   `Δ̂ < −E_Δ` none. A double root is never certified here.
//! * `m_α = 0` means α is exactly 0 (a nonzero term is at least `2⁻⁴⁴⁷`):
//!   then `|β̂| > E_β` certifies the linear root `−γ/β`; `m_β = 0` with
//!   `|γ̂| > E_γ` certifies no root, and `m_β = m_γ = 0` the whole line.
//!
//! The roots after pbrt-v4's `Quadratic`: `s = √Δ`, `q = −½(β +
//! sign(β̂)s)`, roots `q/α` and `γ/q`. Where α = 0 exactly, `Δ̂ = β̂²`, so
//! `ŝ = |β̂|` (the square root of a rounded square is exact) and `q̂ = −β̂`:
//! `γ/q` is then the linear root `−γ/β`, with `E_q = E_β`. Otherwise
//! `E_s = E_Δ/ŝ + 2u ŝ` and `E_q = ½(E_β + E_s) + 2u|q̂|`.
//!
//! The roots need `1/α̂` (α̂ taken as 1 where α = 0), `1/q̂` and `1/ŝ`. On
//! one lane they are three divisions, which run in parallel; on four, where
//! division throughput is what counts, they come from one, `ρ = 1/(q̂α̂ŝ)`:
//! `1/α̂ = q̂ŝρ`, `1/q̂ = α̂ŝρ`, `1/ŝ = q̂α̂ρ`, each within `4u` relatively.
//! That product is of degree nine in the inputs and may leave f64's range,
//! so on four lanes the filter certifies roots only where `2⁻¹⁰⁰⁰ <
//! |q̂α̂ŝ| < 2¹⁰⁰⁰`. The quotients, computed as products with the
//! reciprocals, are each within `5u|t̂|` of `x̂/ŷ`, and `|x̂/ŷ − x/y| ≤
//! (|x̂/ŷ| E_y/|ŷ| + E_x/|ŷ|) / (1 − E_y/|ŷ|)`; the filter certifies a root
//! only where `E_y/|ŷ| < 1/4`, and bounds `1/(1 − x)` by `1 + 2x`. Each
//! bound is split into a part relative to the root and an absolute part,
//! for [`certify`], and every part is widened
//! by `1 + 2⁻³⁰` for the roundings of its own evaluation; the roots'
//! roundings, `9u` in all, count `20u`. A root exactly 0 (`γ = 0` term by
//! term) is `+0`.
//!
//! # Range
//!
//! `β²` and `αγ` are products of six f32 values at most: between `2⁻⁸⁹⁴`
//! and `2⁷⁶⁸` in magnitude, so no overflow and no underflow into f64's
//! subnormals for any finite input. A non-finite input certifies nothing.

use super::QuadricHit;
use crate::num::certify::{SLACK, U, certify, div, quotient_bound};
use crate::num::dd::{Acc, quotient, two_prod, two_roots};
use crate::num::real::Real;
use crate::num::tracked::Tracked;

/// The filter's result: the certified classes and the roots with their
/// bounds.
#[derive(Clone, Copy, Debug)]
pub struct Filtered<L: Real> {
    /// Certified: two roots `t0`, `t1` (unsorted; each still needs
    /// [`certify`]).
    pub two: L::Mask,
    /// Certified: one linear root `t1` (α = 0).
    pub linear: L::Mask,
    /// Certified: no root.
    pub none: L::Mask,
    /// Certified: the line lies on the surface.
    pub all: L::Mask,
    /// `q/α`.
    pub t0: L,
    /// The relative part of `t0`'s error bound.
    pub r0: L,
    /// The absolute part of `t0`'s error bound.
    pub a0: L,
    /// `γ/q`, which is the linear root `−γ/β` where α = 0.
    pub t1: L,
    /// The relative part of `t1`'s error bound.
    pub r1: L,
    /// The absolute part of `t1`'s error bound.
    pub a1: L,
}

/// A sum of terms and of their magnitudes.
#[inline(always)]
fn sum<L: Real, const N: usize>(t: [L; N]) -> (L, L) {
    let mut s = t[0];
    let mut m = t[0].abs();
    for x in &t[1..] {
        s = s + *x;
        m = m + x.abs();
    }
    (s, m)
}

/// The terms of α, β and γ of the line `o + t d` on the quadric `k`, each
/// term `t(c, x, y) = c·x·y` (with `y = 1` for the linear ones), β's square
/// terms doubled: written once for the filter and the tracked stage.
#[inline(always)]
#[allow(clippy::type_complexity)]
fn terms<L: Copy + core::ops::Add<Output = L>>(
    k: &[L; 10],
    o: [L; 3],
    d: [L; 3],
    one: L,
    mut t: impl FnMut(L, L, L) -> L,
) -> ([L; 6], [L; 12], [L; 10]) {
    let alpha = [
        t(k[0], d[0], d[0]),
        t(k[1], d[1], d[1]),
        t(k[2], d[2], d[2]),
        t(k[3], d[0], d[1]),
        t(k[4], d[0], d[2]),
        t(k[5], d[1], d[2]),
    ];
    // Doubling is exact (x + x), or overflows, which every later step sees.
    let two = |x: L| x + x;
    let beta = [
        two(t(k[0], o[0], d[0])),
        two(t(k[1], o[1], d[1])),
        two(t(k[2], o[2], d[2])),
        t(k[3], o[0], d[1]),
        t(k[3], d[0], o[1]),
        t(k[4], o[0], d[2]),
        t(k[4], d[0], o[2]),
        t(k[5], o[1], d[2]),
        t(k[5], d[1], o[2]),
        t(k[6], d[0], one),
        t(k[7], d[1], one),
        t(k[8], d[2], one),
    ];
    let gamma = [
        t(k[0], o[0], o[0]),
        t(k[1], o[1], o[1]),
        t(k[2], o[2], o[2]),
        t(k[3], o[0], o[1]),
        t(k[4], o[0], o[2]),
        t(k[5], o[1], o[2]),
        t(k[6], o[0], one),
        t(k[7], o[1], one),
        t(k[8], o[2], one),
        k[9],
    ];
    (alpha, beta, gamma)
}

/// α, β and γ of the line `o + t d` on the quadric `k`, each with the sum
/// of its terms' magnitudes.
///
/// ```
/// use rayoracle::quadric::stages::coefficients;
/// // The unit sphere from (0, 0, −5) along z: t² − 10t + 24.
/// let k = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// let [a, b, c] = coefficients::<f64>(&k, [0.0, 0.0, -5.0], [0.0, 0.0, 1.0]);
/// assert_eq!((a, b, c), ((1.0, 1.0), (-10.0, 10.0), (24.0, 26.0)));
/// ```
#[inline(always)]
pub fn coefficients<L: Real>(k: &[L; 10], o: [L; 3], d: [L; 3]) -> [(L, L); 3] {
    let (a, b, g) = terms(k, o, d, L::splat(1.0), |c, x, y| c * x * y);
    [sum(a), sum(b), sum(g)]
}

/// Runs the filter on a line `o + t d` and the quadric `k`, every bound
/// multiplied by `shrink` (1 in the kernels).
///
/// ```
/// use rayoracle::quadric::stages::filter;
/// let cyl = [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// let f = filter::<f64>(&cyl, [-5.0, 0.0, 0.0], [1.0, 0.0, 0.0], 1.0);
/// assert!(f.two && (f.t0, f.t1) == (6.0, 4.0));
/// // The paraboloid z = x² + y² along its axis: α = 0, the root t1.
/// let bowl = [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0];
/// let f = filter::<f64>(&bowl, [0.0, 0.0, -2.0], [0.0, 0.0, 1.0], 1.0);
/// assert!(f.linear && f.t1 == 2.0);
/// // Along the axis α = β = 0, and γ = −1: no root, certain.
/// let f = filter::<f64>(&cyl, [0.0; 3], [0.0, 0.0, 1.0], 1.0);
/// assert!(f.none && !f.two && !f.linear && !f.all);
/// ```
#[inline(always)]
pub fn filter<L: Real>(k: &[L; 10], o: [L; 3], d: [L; 3], shrink: f64) -> Filtered<L> {
    let c = |x: f64| L::splat(x * U * shrink);
    let (zero, half, inf) = (L::splat(0.0), L::splat(0.5), L::splat(f64::INFINITY));
    let [(alpha, ma), (beta, mb), (gamma, mg)] = coefficients(k, o, d);
    let (ea, eb, eg) = (c(12.0) * ma, c(24.0) * mb, c(20.0) * mg);
    let four = L::splat(4.0);
    let disc = beta * beta - four * alpha * gamma;
    let ed = c(100.0) * mb * mb + c(300.0) * ma * mg;

    let quad = alpha.abs().gt(ea);
    let lin = ma.eq(zero);
    let beta_clear = beta.abs().gt(eb);
    let beta_zero = mb.eq(zero);
    let two = quad & disc.gt(ed);
    let linear = lin & beta_clear;
    let none = (quad & (-ed).gt(disc)) | (lin & beta_zero & gamma.abs().gt(eg));
    let all = lin & beta_zero & mg.eq(zero);

    let one = L::splat(1.0);
    let alpha = L::select(lin, one, alpha);
    let s = disc.sqrt();
    let q = -(beta + s.copysign(beta)) * half;
    let (ia, iq, is, in_range) = if L::FEW_DIVISIONS {
        let p = q * alpha * s;
        let pa = p.abs();
        let in_range = pa.gt(L::splat(2f64.powi(-1000))) & L::splat(2f64.powi(1000)).gt(pa);
        let rho = one / p;
        (q * s * rho, alpha * s * rho, q * alpha * rho, in_range)
    } else {
        (one / alpha, one / q, one / s, zero.eq(zero))
    };
    let slack = L::splat(SLACK);
    let es = ed * is * slack + c(2.0) * s;
    let eq = L::select(lin, eb, (eb + es) * half + c(2.0) * q.abs());
    let bound = |ey: L, ex: L, iy: L| {
        let (r, a) = quotient_bound(ey, ex, iy, 20.0 * U * shrink);
        (L::select(in_range, r, inf), a)
    };
    let t0 = q * ia;
    let (r0, a0) = bound(ea, eq, ia);
    let t1 = gamma * iq + zero;
    let (r1, a1) = bound(eq, eg, iq);
    Filtered {
        two,
        linear,
        none,
        all,
        t0,
        r0,
        a0,
        t1,
        r1,
        a1,
    }
}

/// The second stage: α, β, γ and `β² − 4αγ` tracked for exactness
/// ([`Tracked`]), each term `k·x·y` as `k·x` (a product of two f32
/// values, exact in f64) times `y`, checked. Where no
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
    let mut x = Tracked::new();
    // `c·p` is a product of two f32 values: exact in f64, unchecked.
    let (alpha, beta, gamma) = terms(k, o, d, 1.0, |c, p, q| x.mul(c * p, q));
    // Most data that is not small integers or dyadic rounds here already.
    if !x.exact() {
        return None;
    }
    let mut sum = |v: &[f64]| v.iter().fold(0.0, |s, &y| x.add(s, y));
    let (alpha, beta, gamma) = (sum(&alpha), sum(&beta), sum(&gamma));
    let b2 = x.mul(beta, beta);
    let ag = x.mul(4.0 * alpha, gamma);
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
struct Pair(f64, f64);

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
/// Where no low word rounded, α, β, γ and `Δ` are exact, and so are their
/// signs and zeros: α = 0 (the linear root `−γ/β`, or the whole line, or
/// nothing), a double root `−β/2α` (pbrt-v4's `Quadratic` branches);
/// otherwise their bounds decide the signs or nothing does. The roots are
/// certified from the leading words with `|lo| + err` as their bounds
/// ([`quotient`], [`two_roots`] with `b = β/2`). Every bound is multiplied
/// by `shrink`.
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
    let (kp, op, dp) = (pairs(k), pairs(&o), pairs(&d));
    let (alpha, beta, gamma) = terms(&kp, op, dp, Pair(1.0, 0.0), |c, x, y| {
        let (h, l) = two_prod(c.0 * x.0, y.0);
        Pair(h, l)
    });
    let sum = |v: &[Pair]| {
        let mut acc = Acc::new();
        v.iter().for_each(|t| acc.add_pair((t.0, t.1)));
        acc.finish(shrink)
    };
    let (alpha, beta, gamma) = (sum(&alpha), sum(&beta), sum(&gamma));
    if alpha.is_zero() {
        return if beta.is_zero() {
            if gamma.is_zero() {
                Some(QuadricHit::All)
            } else {
                gamma.sign_known().then_some(QuadricHit::None)
            }
        } else if beta.sign_known() {
            let t = quotient(-gamma.approx(), beta.approx(), shrink)?;
            Some(QuadricHit::One(t))
        } else {
            None
        };
    }
    if !alpha.sign_known() {
        return None;
    }
    let b = beta.scale(0.5);
    let mut disc = Acc::wide();
    disc.add_dd_prod(b, b);
    disc.add_dd_prod(alpha.scale(-1.0), gamma);
    let disc = disc.finish(shrink);
    if disc.is_zero() {
        let t = quotient(-b.approx(), alpha.approx(), shrink)?;
        return Some(QuadricHit::One(t));
    }
    if !disc.sign_known() {
        return None;
    }
    if disc.hi < 0.0 {
        return Some(QuadricHit::None);
    }
    let (t0, t1) = two_roots(
        alpha.approx(),
        b.approx(),
        gamma.approx(),
        disc.approx(),
        shrink,
    )?;
    Some(QuadricHit::Two(t0, t1))
}
