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
//! square terms is exact. Summed left to right (the scalar reference sums
//! them pairwise, through fewer roundings still: `classes_paired`):
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
//!   `Δ̂ < −E_Δ` none. A double root is never certified here. The filter
//!   asks more of α̂, `|α̂| > 2²⁴E_α`: otherwise `q̂/α̂` (and every form
//!   of the roots here) is within no less than `E_α/|α̂| ≥ 2⁻²⁴` of the
//!   exact root relatively, so its enclosure spans an f32 spacing, and
//!   with it a rounding boundary, but for roots in f32's subnormal range
//!   or beyond its largest value. No root would certify: such lines,
//!   nearly parallel to an axis whose α cancels, go to the later stages
//!   at once. (`|α̂|·2⁻²⁴` is exact: a nonzero α̂ is at least `2⁻⁴⁴⁷`.)
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
//! The roots need `1/α̂` (α̂ taken as 1 where α = 0), `1/q̂` and `1/ŝ`.
//! Both kernels first try the form `(−β ∓ s)/2α`, whose divisions do not
//! wait on `ŝ`: the scalar reference in `sorted`, x4 in
//! [`super::lanes`]; these quotients are what they fall back to. On
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
#[cfg(target_arch = "x86_64")]
use crate::num::avx::Avx2;
use crate::num::certify::{SLACK, U, certify, div, quotient_bound};
#[cfg(all(target_arch = "x86_64", not(target_feature = "fma")))]
use crate::num::dd::Fma;
#[cfg(any(target_arch = "x86_64", target_feature = "fma"))]
use crate::num::dd::Fused;
use crate::num::dd::{
    Acc, Approx, BuildProduct, Dd, Dekker, GridAcc, Product, quotient, two_roots, two_sum,
};
use crate::num::real::Real;
use crate::num::tracked::Tracked;
use crate::stage::Stage;

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
    roots(&classes(k, o, d, shrink), shrink)
}

/// The filter's first half: α, β, γ, `Δ` and their bounds, and the
/// classes they certify. The reference computes the roots ([`roots`])
/// only where the class is two or linear, so that a case left to the
/// later stages costs no division.
pub(crate) struct Classes<L: Real> {
    alpha: L,
    beta: L,
    gamma: L,
    disc: L,
    ea: L,
    eb: L,
    eg: L,
    ed: L,
    ma: L,
    mb: L,
    mg: L,
    /// A quadratic whose roots may certify (see the module's bound).
    quad: L::Mask,
    /// Certified: two roots (which still need [`certify`]).
    pub(crate) two: L::Mask,
}

/// The classes other than two, tested where they are asked for: on the
/// scalar reference's fast path, which [`sorted`] ends, none of them is.
impl<L: Real> Classes<L> {
    /// `α = 0` exactly: every term of α is 0.
    #[inline(always)]
    fn lin(&self) -> L::Mask {
        self.ma.eq(L::splat(0.0))
    }
    /// Certified: α = 0 and β ≠ 0, one root.
    #[inline(always)]
    pub(crate) fn linear(&self) -> L::Mask {
        self.lin() & self.beta.abs().gt(self.eb)
    }
    /// Certified: no root.
    #[inline(always)]
    pub(crate) fn none(&self) -> L::Mask {
        let constant = self.lin() & self.mb.eq(L::splat(0.0));
        (self.quad & (-self.ed).gt(self.disc)) | (constant & self.gamma.abs().gt(self.eg))
    }
    /// Certified: every `t`.
    #[inline(always)]
    pub(crate) fn all(&self) -> L::Mask {
        self.lin() & self.mb.eq(L::splat(0.0)) & self.mg.eq(L::splat(0.0))
    }
}

impl Classes<f64> {
    /// What the later stages take from the filter.
    #[inline(always)]
    pub(crate) fn left(&self) -> Left {
        Left {
            alpha: (self.alpha, self.ma),
            beta: (self.beta, self.mb),
            gamma: (self.gamma, self.mg),
        }
    }
}

impl Left {
    /// Which of α̂, β̂ and γ̂ are exact as the filter summed them, on
    /// their [`grids`] `g`: those whose terms' magnitudes sum below
    /// `2⁵²g` ([`later_head`]).
    #[inline(always)]
    pub(crate) fn exact(&self, [ga, gb, gc]: [f64; 3]) -> [bool; 3] {
        let limit = |g: f64| g * 4_503_599_627_370_496.0;
        [
            self.alpha.1 * SLACK < limit(ga),
            self.beta.1 * SLACK < limit(gb),
            self.gamma.1 * SLACK < limit(gc),
        ]
    }
}

/// What the filter leaves the later stages: α̂, β̂ and γ̂, each with the
/// sum of its terms' magnitudes (`m_α`, `m_β`, `m_γ`), from
/// [`classes_paired`], which bounds them by its `E_α`, `E_β` and `E_γ`.
/// Passed between functions that are not inlined as six `f64` arguments,
/// in registers: a struct goes through memory, where a copy by vector
/// loads of fields stored one by one stalls store forwarding.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Left {
    pub(crate) alpha: (f64, f64),
    pub(crate) beta: (f64, f64),
    pub(crate) gamma: (f64, f64),
}

#[inline(always)]
pub(crate) fn classes<L: Real>(k: &[L; 10], o: [L; 3], d: [L; 3], shrink: f64) -> Classes<L> {
    classify(coefficients(k, o, d), shrink)
}

/// [`classes`] for one lane, the scalar reference's: the same terms,
/// evaluated in the two lanes of an `f64x2` (SSE2, which every x86-64 CPU
/// has; elsewhere two f64 values) and summed pairwise.
///
/// With `X = (d_x, o_x)`, `Y` and `Z` alike, and `X' = (o_x, d_x)`:
///
/// * `A·X·X + B·Y·Y + C·Z·Z + D·X·Y + E·X·Z + F·Y·Z` holds α's six
///   terms in its first lane and γ's six quadratic ones in its second;
/// * `A·X·X' + … + F·Y·Z'` holds β's twelve products `k·x·y`: each square
///   term `A·o_x·d_x` once in each lane (`(A·d_x)·o_x` and `(A·o_x)·d_x`
///   are the same exact product, rounded once), so the sum of the lanes
///   holds it twice, as β does, and each cross term's two products one in
///   each lane;
/// * `G·X + H·Y + I·Z` holds β's three linear terms and γ's, exact.
///
/// Six terms summed as `((t₀ + t₁) + (t₂ + t₃)) + (t₄ + t₅)` pass
/// through three additions each, where the sum left to right takes five
/// for the first two, and the chain of dependent additions is three long
/// rather than five. Then `β̂ = (B₀ + L₀) + B₁` and `γ̂ = (Q₁ + L₁) + J`:
/// a term of α passes through at most 4 roundings (its product's and three
/// additions), one of β through 6 and one of γ through 6, within the `6`,
/// `12` and `10` of the [module's bound](self); the magnitudes are summed
/// the same way. The sums and their magnitudes differ from [`classes`]'s
/// only by the order of the additions, so a non-finite term makes the same
/// sums infinite or NaN.
#[inline(always)]
pub(crate) fn classes_paired(k: &[f64; 10], o: [f64; 3], d: [f64; 3], shrink: f64) -> Classes<f64> {
    use wide::f64x2 as P;
    let kk = |i: usize| P::splat(k[i]);
    let pair = |a: f64, b: f64| P::from([a, b]);
    let (x, y, z) = (pair(d[0], o[0]), pair(d[1], o[1]), pair(d[2], o[2]));
    let (xs, ys, zs) = (pair(o[0], d[0]), pair(o[1], d[1]), pair(o[2], d[2]));
    // α's and γ's quadratic terms, `k·v·v`, and β's, `k·v·v'`.
    let (v, vs) = ([x, y, z], [xs, ys, zs]);
    let (mut quad, mut bil) = ([P::ZERO; 6], [P::ZERO; 6]);
    for (n, &(c, i, j)) in QUADRATIC.iter().enumerate() {
        quad[n] = kk(c) * v[i] * v[j];
        bil[n] = kk(c) * v[i] * vs[j];
    }
    let ((q, mq), (b, mb)) = (sum6(quad), sum6(bil));
    let (l, ml) = sum3([kk(6) * x, kk(7) * y, kk(8) * z]);
    // Lane by lane, not `array::map`, which is not always inlined: through
    // memory, the lanes cost store-forwarding stalls.
    let (q, mq, b, mb) = (q.to_array(), mq.to_array(), b.to_array(), mb.to_array());
    let w = (pair(b[0], q[1]) + l).to_array();
    let mw = (pair(mb[0], mq[1]) + ml).to_array();
    classify(
        [
            (q[0], mq[0]),
            (w[0] + b[1], mw[0] + mb[1]),
            (w[1] + k[9], mw[1] + k[9].abs()),
        ],
        shrink,
    )
}

/// The quadratic terms: the coefficient and the two inputs of each, `k·x·y`
/// (α's with `x` and `y` from the direction).
pub(crate) const QUADRATIC: [(usize, usize, usize); 6] = [
    (0, 0, 0),
    (1, 1, 1),
    (2, 2, 2),
    (3, 0, 1),
    (4, 0, 2),
    (5, 1, 2),
];

/// Six terms' sum and the sum of their magnitudes, pairwise.
#[inline(always)]
fn sum6(t: [wide::f64x2; 6]) -> (wide::f64x2, wide::f64x2) {
    let s = ((t[0] + t[1]) + (t[2] + t[3])) + (t[4] + t[5]);
    let m = ((t[0].abs() + t[1].abs()) + (t[2].abs() + t[3].abs())) + (t[4].abs() + t[5].abs());
    (s, m)
}

/// Three terms' sum and the sum of their magnitudes.
#[inline(always)]
fn sum3(t: [wide::f64x2; 3]) -> (wide::f64x2, wide::f64x2) {
    ((t[0] + t[1]) + t[2], (t[0].abs() + t[1].abs()) + t[2].abs())
}

/// The classes from α, β, γ and their magnitude sums.
#[inline(always)]
fn classify<L: Real>(coefficients: [(L, L); 3], shrink: f64) -> Classes<L> {
    let c = |x: f64| L::splat(x * U * shrink);
    let [(alpha, ma), (beta, mb), (gamma, mg)] = coefficients;
    let (ea, eb, eg) = (c(12.0) * ma, c(24.0) * mb, c(20.0) * mg);
    let four = L::splat(4.0);
    let disc = beta * beta - four * alpha * gamma;
    let ed = c(100.0) * mb * mb + c(300.0) * ma * mg;

    // A quadratic whose roots may certify (see the module's bound).
    let quad = (alpha.abs() * L::splat(2f64.powi(-24))).gt(ea);
    Classes {
        alpha,
        beta,
        gamma,
        disc,
        ea,
        eb,
        eg,
        ed,
        ma,
        mb,
        mg,
        quad,
        two: quad & disc.gt(ed),
    }
}

/// The filter's second half: the roots and their bounds from the
/// [`classes`].
#[inline(always)]
pub(crate) fn roots<L: Real>(k: &Classes<L>, shrink: f64) -> Filtered<L> {
    let c = |x: f64| L::splat(x * U * shrink);
    let (zero, half, inf) = (L::splat(0.0), L::splat(0.5), L::splat(f64::INFINITY));
    let (beta, gamma, disc, lin) = (k.beta, k.gamma, k.disc, k.lin());
    let (ea, eb, eg, ed) = (k.ea, k.eb, k.eg, k.ed);
    let one = L::splat(1.0);
    let alpha = L::select(lin, one, k.alpha);
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
        two: k.two,
        linear: k.linear(),
        none: k.none(),
        all: k.all(),
        t0,
        r0,
        a0,
        t1,
        r1,
        a1,
    }
}

/// The scalar reference's roots where the [`classes`] certify two, both
/// as `(−β̂ ∓ ŝ)/(2α̂)`, certified: `Some((t₀, t₁))` with `t₀ = q̂/α̂`, the
/// root whose numerator does not cancel, as [`roots`] computes it, and
/// `t₁` the other, where both certify; `None` otherwise. `1/α̂` and `1/Δ̂`
/// are divided while the square root runs, so that no division waits on
/// `ŝ` and the bound waits on it for one product and one sum; [`roots`]
/// waits on `ŝ` for `1/q̂` and `1/ŝ`, and its bounds on both. (x4's
/// first pass, [`super::lanes`], takes the same form with one division
/// for both reciprocals, as division throughput counts more than latency
/// on four lanes, and [`roots`] for the lanes it leaves.)
///
/// `t₁`'s numerator cancels: `|t₁/t₀| = ||β̂| − ŝ|/(|β̂| + ŝ)`, below
/// 1/16 where `Δ̂/β̂²` lies between `(15/17)²` and `(17/15)²`. There its
/// bound, relative to it, is over 16 times `t₀`'s, and `γ/q` of [`roots`]
/// is the form to take: `None`, without trying. (That test only chooses
/// the form.)
///
/// # The bound
///
/// In the notation of the [module](self), where [`Classes::two`] (so
/// `|α̂| > E_α` and `Δ̂ > E_Δ ≥ 0`):
///
/// * `1/α̂` and `1/Δ̂` are each within `u` relatively; `ŝ = fl(√Δ̂)`, and
///   `E_s = E_Δ/ŝ + 2uŝ` as for [`roots`], evaluated as `ŝ(E_Δ·fl(1/Δ̂) +
///   2u)`: `1/ŝ = ŝ/ŝ²` and `ŝ² ≥ Δ̂(1 − u)²`, so the product is within
///   `4u` of `E_Δ/ŝ` relatively, and the widening by `1 + 2⁻³⁰` covers it.
/// * `n̂ = fl(|β̂| ± ŝ)` against `n = |β| ± √Δ`, up to the sign of `β̂`
///   (which pairs the same two roots whatever it is): `|n̂ − n| ≤ u|n̂| +
///   E_β + E_s`. The roots are `n̂·h` with `h = −sign(β̂)·½·fl(1/α̂)` (the
///   halving and the sign exact).
/// * `t̂ = fl(n̂h)` is within `2.01u|t̂|` of `∓n̂/(2α̂)`, and with `x =
///   E_α/|α̂|`, `|n̂/(2α̂) − n/(2α)|` is at most `(|n̂/(2α̂)|x + |n̂ −
///   n|/(2|α̂|))/(1 − x)`, the bound of [`quotient_bound`] with `E_y = E_α`
///   and `E_x = |n̂ − n|/2`. Where `x < 1/4`, with `1/(1 − x)` bounded by
///   `1 + 2x` and `u|n̂|/(2|α̂|) ≤ 1.01u|t̂|`: `e ≤ (x(1 + 2x) + 5u)|t̂| +
///   (1 + 2x)(E_β + E_s)/(2|α̂|)`.
///
/// The filter uses `r = x(1 + 2x) + 20u` and `a = (1 + 2x)(E_β +
/// E_s)/(2|α̂|)`, every part widened by `1 + 2⁻³⁰` and multiplied by
/// `shrink`, as [`roots`] does, and certifies each root as [`certify`]
/// does. `a` is split as `P + ŝQ`, `P` and `Q` ready before the square
/// root. For `t₀` this is [`roots`]'s bound on `q̂/α̂`, less its
/// `2u|q̂|/|α̂|`, which the `20u` covers. Where `x ≥ 1/4` the filter takes
/// `r = 1`, which certifies nothing: the enclosure's ends `t̂(1 ∓ w) ∓ a`,
/// `w > 1`, have opposite signs. So does a root that comes out ±0, since
/// `a > 0` (it holds `uŝ|fl(1/α̂)|`): the exact root 0 is left to
/// [`roots`].
///
/// # Range
///
/// f32 values are multiples of `2⁻¹⁴⁹`, so every term, and `α̂`, `β̂` and
/// `γ̂`, are multiples of `2⁻⁴⁴⁷`, and `β̂²` and `4α̂γ̂`, where nonzero
/// (so at least `2⁻⁸⁹⁴`), multiples of `2⁻⁹⁴⁶`: `|α̂|` lies between
/// `2⁻⁴⁴⁷` and `2³⁹⁰`, and `Δ̂ > 0` is at least `2⁻⁹⁴⁶`. So `1/α̂` and
/// `1/Δ̂` are finite and normal, the roots finite, `E_Δ/Δ̂ < 1`, every end of an
/// enclosure is finite (the comparison of bits needs no test for NaN),
/// and `a ≥ uŝ|fl(1/α̂)|`, with `ŝ ≥ 2⁻⁴⁷³`, is at least `2⁻⁹¹⁶` for
/// `shrink = 1`: no underflow.
#[inline(always)]
pub(crate) fn sorted(k: &Classes<f64>, shrink: f64) -> Option<(f64, f64)> {
    let bounds = (k.ea, k.eb, k.ed);
    sorted_from(k.alpha, k.beta, k.disc, bounds, shrink)
}

/// [`sorted`] from α̂, β̂ and `Δ̂ = β̂² − 4α̂γ̂` with their bounds `(E_α,
/// E_β, E_Δ)` (multiplied by `shrink` already), wherever they come from:
/// the bound above holds for any such values with `|α̂| > E_α` and `Δ̂ >
/// E_Δ`, and certifies nothing where `E_α/|α̂| ≥ 1/4`.
#[inline(always)]
pub(crate) fn sorted_from(
    alpha: f64,
    beta: f64,
    disc: f64,
    bounds: (f64, f64, f64),
    shrink: f64,
) -> Option<(f64, f64)> {
    let SortedTerms {
        t0,
        t1,
        r,
        a,
        apart,
    } = sorted_terms(alpha, beta, disc, bounds, shrink);
    let w = r + 2f64.powi(-51);
    // `certify`, both roots at once, every end finite (Range above).
    let (a0, a1) = (a.copysign(t0), a.copysign(t1));
    let same = |lo: f64, hi: f64| (lo as f32).to_bits() == (hi as f32).to_bits();
    let ok = same(t0 * (1.0 - w) - a0, t0 * (1.0 + w) + a0)
        & same(t1 * (1.0 - w) - a1, t1 * (1.0 + w) + a1);
    (apart & ok).then_some((t0, t1))
}

/// What [`sorted_from`] decides from: both roots, their one bound `|t|·r
/// + a`, and whether `Δ̂/β̂²` lies outside `[(15/17)², (17/15)²]`, so that
/// `t₁` is the form to take.
#[derive(Clone, Copy, Debug)]
struct SortedTerms {
    t0: f64,
    t1: f64,
    r: f64,
    a: f64,
    apart: bool,
}

/// [`sorted_from`]'s roots and bound, as its derivation gives them.
#[inline(always)]
fn sorted_terms(
    alpha: f64,
    beta: f64,
    disc: f64,
    (ea, eb, ed): (f64, f64, f64),
    shrink: f64,
) -> SortedTerms {
    const SIGN: u64 = 1 << 63;
    let c = |x: f64| x * U * shrink;
    // Both divisions and the square root start together.
    let (ia, id) = (1.0 / alpha, 1.0 / disc);
    let s = disc.sqrt();
    let bb = beta * beta;
    let apart = 289.0 * disc <= 225.0 * bb || 225.0 * disc >= 289.0 * bb;
    let x = ea * ia.abs() * SLACK;
    let g = (1.0 + x + x) * SLACK;
    let r = if x < 0.25 { x * g + c(20.0) } else { 1.0 };
    let hg = 0.5 * ia.abs() * g * SLACK;
    let (p, q) = (eb * hg, (ed * id * SLACK + c(2.0)) * hg);
    let h = f64::from_bits((0.5 * ia).to_bits() ^ (beta.to_bits() & SIGN) ^ SIGN);
    let ab = beta.abs();
    SortedTerms {
        t0: (ab + s) * h,
        t1: (ab - s) * h,
        r,
        a: p + s * q,
        apart,
    }
}

/// The terms of α, β and γ, each exactly as two words ([`Pair`]): `k·x`
/// is exact (two f32 values), its product with `y` is split by
/// TwoProduct (`P`), exact since every such product is a multiple of
/// `2⁻⁴⁴⁷` below `2³⁸⁴`. Computed once for both later stages.
/// With them, a grid every term lies on ([`grid`]).
#[derive(Clone, Copy)]
struct ExactTerms([Pair; 6], [Pair; 12], [Pair; 10], f64);

impl ExactTerms {
    #[inline(always)]
    fn new<P: Product>(k: &[f64; 10], o: [f64; 3], d: [f64; 3]) -> ExactTerms {
        ExactTerms::on::<P>(k, o, d, grid(k, o, d))
    }
    /// [`ExactTerms::new`] with the data's [`grid`] already found.
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

/// The exponent of the lowest set bit of a nonzero `x` widened from f32
/// (`x = m·2ᵉ` with `m` odd), less `−1022`, so that 0 (which lies on
/// every grid) wraps to `u32::MAX` and an unsigned minimum passes over
/// it: f32 data widens to normal f64 values of biased exponent at least
/// `874`, so the exponent field plus the trailing zeros of the
/// significand (with its implicit bit) is at least 874 for those, and 52
/// for 0. Meaningless, but harmless, for a non-finite `x`, whose terms
/// make every sum NaN.
#[inline(always)]
fn low_key(x: f64) -> u32 {
    // No branch on 0, which the data's zero coefficients would
    // mispredict; the implicit bit bounds the trailing zeros, and the
    // sign and exponent above it leave them alone.
    let b = x.to_bits();
    let e = ((b << 1) >> 53) as u32;
    (e + (b | 1 << 52).trailing_zeros()).wrapping_sub(53)
}

/// [`low_key`] as the exponent itself, 2000 for 0.
#[cfg(test)]
fn low_bit(x: f64) -> i32 {
    match low_key(x) {
        u32::MAX => 2000,
        k => k as i32 - 1022,
    }
}

/// A power of two `g` that divides every term `k·x·y` of α, β and γ: with
/// `2^κ` the least lowest set bit of the coefficients and `2^ν` that of
/// the origin, the direction and 1, every term is a multiple of `2^(κ +
/// 2ν)` (`ν ≤ 0`, and a term has at most two factors besides its
/// coefficient; a zero factor makes the term 0, on every grid). The
/// exponent is at least `−149·3` for f32 data; it is capped at 400, which
/// only applies where every coefficient is 0 (then every term is, and any
/// grid holds them) or not finite (then every sum is NaN), so that `g²`
/// is a normal f64 too.
///
/// ```
/// # use rayoracle::quadric::stages::grid;
/// // Coefficients 3 and 0.5 (2⁻¹), data 0.75 (lowest bit 2⁻²): 2⁻⁵.
/// let k = [3.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
/// assert_eq!(grid(&k, [0.75, 2.0, 0.0], [1.0, 0.0, 0.0]), 2f64.powi(-5));
/// ```
#[doc(hidden)]
#[inline(always)]
pub fn grid(k: &[f64; 10], o: [f64; 3], d: [f64; 3]) -> f64 {
    // Minima by pairs, not one chain: their latency is on the way to
    // every later test.
    let m = |a: f64, b: f64| low_key(a).min(low_key(b));
    let kappa = (m(k[0], k[1]).min(m(k[2], k[3])))
        .min(m(k[4], k[5]).min(m(k[6], k[7])))
        .min(m(k[8], k[9]));
    // 1 (key 1022) among the data: ν ≤ 0.
    let nu = (m(o[0], o[1]).min(m(o[2], d[0]))).min(m(d[1], d[2]).min(1022));
    let e = (i64::from(kappa) + 2 * i64::from(nu) - 3066).clamp(-1000, 400);
    f64::from_bits(((1023 + e) as u64) << 52)
}

/// A power of two for each of α, β and γ that divides its terms, and so
/// is at least [`grid`]: with `2^κ_q`, `2^κ_l` and `2^κ_c` the least lowest
/// set bits of the quadratic, the linear and the constant coefficients,
/// and `2^ν_o`, `2^ν_d` those of the origin and the direction, α's terms
/// `k·dᵢ·dⱼ` are multiples of `2^(κ_q + 2ν_d)`; β's, `k·oᵢ·dⱼ` (some
/// doubled) and `k·dᵢ`, of `2^min(κ_q + ν_o + ν_d, κ_l + ν_d)`; γ's,
/// `k·oᵢ·oⱼ`, `k·oᵢ` and the constant, of `2^min(κ_q + 2ν_o, κ_l + ν_o,
/// κ_c)`. Each exponent is capped as [`grid`]'s: a group of factors all 0
/// makes its terms 0. An origin of many bits next to a direction of few,
/// as on a line along a cylinder's integer axis, leaves α's and β's grids
/// far coarser than the data's, so that they prove those sums exact where
/// γ's terms round.
///
/// ```
/// # use rayoracle::quadric::stages::{grid, grids};
/// // The cylinder x² + y² = 1 along its axis from an origin of 24 bits.
/// let k = [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// let (o, d) = ([0.1f32 as f64, 0.0, 0.0], [0.0, 0.0, 2.0]);
/// let lo = 2f64.powi(-27);
/// assert_eq!(grids(&k, o, d), [4.0, 2.0 * lo, lo * lo]);
/// assert_eq!(grid(&k, o, d), lo * lo);
/// ```
#[doc(hidden)]
#[inline(always)]
pub fn grids(k: &[f64; 10], o: [f64; 3], d: [f64; 3]) -> [f64; 3] {
    let m = |a: f64, b: f64| low_key(a).min(low_key(b));
    let e = |k: u32| i64::from(k) - 1022;
    let (kq, kl, kc) = (
        e(m(k[0], k[1]).min(m(k[2], k[3])).min(m(k[4], k[5]))),
        e(m(k[6], k[7]).min(low_key(k[8]))),
        e(low_key(k[9])),
    );
    let (no, nd) = (
        e(m(o[0], o[1]).min(low_key(o[2]))),
        e(m(d[0], d[1]).min(low_key(d[2]))),
    );
    let pow2 = |e: i64| f64::from_bits(((1023 + e.clamp(-1000, 400)) as u64) << 52);
    [
        pow2(kq + 2 * nd),
        pow2((kq + no + nd).min(kl + nd)),
        pow2((kq + 2 * no).min(kl + no).min(kc)),
    ]
}

/// The second stage: α, β, γ and `β² − 4αγ` tracked for exactness
/// ([`Tracked`]), each term `k·x·y` as `k·x` (a product of two f32
/// values, exact in f64) times `y`, checked. The sums of the terms need no
/// check where the sum of their magnitudes is below `2⁵²g`, `g` the data's
/// [`grid`]; elsewhere they are summed in double words ([`GridAcc`]),
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
/// The sums are [`GridAcc`]s on the grid of the data ([`grid`]), and
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
/// [`grid`].
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
        let bounds = (a.e * shrink, 2.0 * bb.e * shrink, 4.0 * near.e * shrink);
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
        if disc.v.abs() > disc.e * shrink {
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
/// its own grid, [`grids`]) is exact as the filter summed it (every term
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
        return if gamma.abs() > eg * shrink {
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
    if !(near.v.abs() > 2.0 * near.e * shrink) {
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
    if let Some(h) = super::square::intersect(k, o, d, shrink) {
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
/// ([`super::words`]), then [`tracked`]'s roots where each is one f64,
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
    let Some([a, b, c]) = super::words::exact(&k, o, d, g) else {
        return later_bounded::<Fused>(&ExactTerms::on::<Fused>(&k, o, d, g), shrink);
    };
    let single = a.lo == 0.0 && b.lo == 0.0 && c.lo == 0.0;
    if single && let Some(h) = tracked_roots::<Fused>(&mut Tracked::new(), a.hi, b.hi, c.hi) {
        return Some((h, Stage::Tracked));
    }
    double_word_coefficients::<Fused>(g, single, (a, b, c), shrink).map(|h| (h, Stage::DoubleWord))
}

/// [`words`] inside the copy compiled for AVX2 and FMA, its sums on four
/// lanes ([`super::words::bounded`]; the same words as
/// [`bounded_words`]), the inputs widened again from `inputs`.
#[cfg(target_arch = "x86_64")]
#[target_feature(enable = "avx2,fma")]
#[inline(never)]
fn words_avx<I>(_: Avx2, inputs: &I, m: [f64; 3], shrink: f64) -> Option<QuadricHit>
where
    I: Fn() -> ([f64; 10], [f64; 3], [f64; 3]),
{
    let (k, o, d) = inputs();
    decide_words::<Fused>(false, super::words::bounded(&k, o, d, m).into(), shrink).flatten()
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

/// The stages after the filter that need the data's [`grid`], with the
/// products' errors found by `P`: where the filter's
/// α̂, β̂ and γ̂ are exact, [`tracked`]'s roots and then [`double_word`]
/// on them; the [`tight`] stage. `Ok` with what they decide, or `Err`
/// with the data's [`grid`] for the stages that sum the exact terms.
///
/// The filter's sums are exact where `(m_α + m_β + m_γ)(1 + 2⁻³⁰) <
/// 2⁵²g`, `g` the data's [`grid`]: every term is a multiple of `g`, and
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
/// [`Fused`](crate::num::dd::Fused)'s `mul_add` is a call to libm's
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
/// perfect square ([`super::square`]); [`tracked`]'s roots where the
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
            if let Some(h) = super::square::intersect(&k, o, d, shrink) {
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Ray;
    use crate::quadric::{Quadric, exact};
    use glam::Vec3;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    /// The exponent of the lowest set bit by a bit scan, for comparison:
    /// `|x| = m·2ᵉ`, `m` odd.
    fn low_exponent(x: f32) -> i32 {
        let b = x.to_bits() & !(1 << 31);
        let (e, f) = ((b >> 23) as i32, b & ((1 << 23) - 1));
        // A subnormal's fraction is read with the exponent of 2⁻¹²⁶.
        let m = if e == 0 { f } else { f | 1 << 23 };
        e.max(1) - 150 + m.trailing_zeros() as i32
    }

    /// `2ᵉ` for `e` from −1074 to 1023, subnormals included.
    fn pow2(e: i32) -> f64 {
        if e < -1022 {
            f64::from_bits(1 << (e + 1074))
        } else {
            f64::from_bits(((e + 1023) as u64) << 52)
        }
    }

    /// The lowest set bit of the values f32 data widens to: both zeros,
    /// the extremes of the range, and every other kind of f32 value at
    /// random, against a bit scan of the f32 encoding.
    #[test]
    fn low_bit_finds_the_lowest_set_bit() {
        let cases = [
            (1.0, 0),
            (-1.0, 0),
            (0.75, -2),
            (-3.0 * 2f32.powi(-5), -5),
            (1.0 + f32::EPSILON, -23),
            (f32::MAX, 104),
            (f32::from_bits(1), -149),
            (-f32::from_bits(6), -148),
            (f32::MIN_POSITIVE, -126),
            (0.0, 2000),
            (-0.0, 2000),
        ];
        for (x, want) in cases {
            assert_eq!(low_bit(f64::from(x)), want, "{x:e}");
        }
        let mut rng = SmallRng::seed_from_u64(0x10_b17);
        for _ in 0..100_000 {
            let x = f32::from_bits(
                rng.random::<u32>() & !(0xff << 23) | rng.random_range(0..0xff) << 23,
            );
            if x != 0.0 {
                assert_eq!(low_bit(f64::from(x)), low_exponent(x), "{x:e}");
            }
        }
    }

    /// The grid is `2^(κ + 2ν)` with the exponents found by bit scans, on
    /// f32 data of every magnitude, zeros, subnormals and values just above
    /// the least normal f32 among it (whose lowest bits are subnormal f32
    /// weights); the same under flush-to-zero, in which the later stages
    /// run, and under denormals-are-zero too where no input is subnormal
    /// (a subnormal input sends the reference to the oracle there).
    #[test]
    fn grid_is_the_least_lowest_bits() {
        type Case = ([f64; 10], [f64; 3], [f64; 3]);
        let mut rng = SmallRng::seed_from_u64(0x6_21d);
        let f = |rng: &mut SmallRng| match rng.random_range(0..9) {
            0 => 0.0,
            1 => f64::from(f32::from_bits(rng.random_range(1..1 << 23))),
            2 => f64::from(f32::from_bits(rng.random_range(1 << 23..27 << 23))),
            3 => 2f64.powi(rng.random_range(-149..128)),
            4 => f64::from(rng.random_range(-64i32..64)),
            _ => {
                let x = f32::from_bits(
                    rng.random::<u32>() & !(0xff << 23) | rng.random_range(0..0xff) << 23,
                );
                f64::from(x)
            }
        };
        let cases: Vec<Case> = (0..20_000)
            .map(|_| {
                let k: [f64; 10] = core::array::from_fn(|_| f(&mut rng));
                (k, [0; 3].map(|_| f(&mut rng)), [0; 3].map(|_| f(&mut rng)))
            })
            .collect();
        let want: Vec<f64> = cases
            .iter()
            .map(|(k, o, d)| {
                let scan = |x: f64| {
                    if x == 0.0 {
                        2000
                    } else {
                        low_exponent(x as f32)
                    }
                };
                let kappa = k.iter().map(|&c| scan(c)).min().unwrap();
                let nu = o.iter().chain(d).map(|&x| scan(x)).min().unwrap().min(0);
                pow2((kappa + 2 * nu).clamp(-1000, 400))
            })
            .collect();
        let grids = |c: &[Case]| {
            c.iter()
                .map(|(k, o, d)| grid(k, *o, *d))
                .collect::<Vec<_>>()
        };
        let check = |got: Vec<f64>, daz: bool, mode: &str| {
            for ((c, g), w) in cases.iter().zip(got).zip(&want) {
                let subnormal = |x: &f64| *x != 0.0 && x.abs() < f64::from(f32::MIN_POSITIVE);
                if daz && c.0.iter().chain(&c.1).chain(&c.2).any(subnormal) {
                    continue;
                }
                assert_eq!(g, *w, "{mode}: {c:?}");
            }
        };
        check(grids(&cases), false, "default");
        #[cfg(target_arch = "x86_64")]
        for (ftz, daz) in [(true, false), (true, true)] {
            let c = cases.clone();
            let got = crate::num::certify::in_environment(ftz, daz, move || grids(&c));
            check(got, daz, &format!("FTZ {ftz}, DAZ {daz}"));
        }
    }

    /// Each coefficient's grid ([`grids`]) is the least lowest set bit of
    /// its own factors' groups, divides every exact term of its
    /// coefficient (both words of each TwoProduct pair), and is at least
    /// the data's [`grid`], on data of every kind where whole groups (the
    /// direction, the origin, the quadratic, linear or constant
    /// coefficients) are often 0.
    #[test]
    fn each_coefficient_s_grid_divides_its_terms() {
        let mut rng = SmallRng::seed_from_u64(0x6_21d5);
        let f = |rng: &mut SmallRng| match rng.random_range(0..8) {
            0 => 0.0,
            1 => f64::from(f32::from_bits(rng.random_range(1..1 << 23))),
            2 => 2f64.powi(rng.random_range(-149..128)),
            3 => f64::from(rng.random_range(-64i32..64)),
            _ => f64::from(f32::from_bits(
                rng.random::<u32>() & !(0xff << 23) | rng.random_range(1..0xff) << 23,
            )),
        };
        let scan = |x: &[f64]| {
            x.iter()
                .map(|&x| {
                    if x == 0.0 {
                        2000
                    } else {
                        low_exponent(x as f32)
                    }
                })
                .min()
                .unwrap()
        };
        let mut coarser = 0;
        for n in 0..20_000 {
            let mut k: [f64; 10] = core::array::from_fn(|_| f(&mut rng));
            let (mut o, mut d) = ([0; 3].map(|_| f(&mut rng)), [0; 3].map(|_| f(&mut rng)));
            // One group zeroed in each of five cases.
            match n % 8 {
                0 => d = [0.0; 3],
                1 => o = [0.0; 3],
                2 => k[..6].fill(0.0),
                3 => k[6..9].fill(0.0),
                4 => k[9] = 0.0,
                _ => {}
            }
            let (kq, kl, kc, no, nd) = (
                scan(&k[..6]),
                scan(&k[6..9]),
                scan(&k[9..]),
                scan(&o),
                scan(&d),
            );
            let want = [
                kq + 2 * nd,
                (kq + no + nd).min(kl + nd),
                (kq + 2 * no).min(kl + no).min(kc),
            ]
            .map(|e| pow2(e.clamp(-1000, 400)));
            let got = grids(&k, o, d);
            assert_eq!(got, want, "{k:?} {o:?} {d:?}");
            let g = grid(&k, o, d);
            assert!(got.iter().all(|&x| x >= g), "{k:?} {o:?} {d:?}");
            coarser += usize::from(got.iter().any(|&x| x > g));
            let t = ExactTerms::new::<Dekker>(&k, o, d);
            let terms: [&[Pair]; 3] = [&t.0, &t.1, &t.2];
            for (terms, g) in terms.iter().zip(got) {
                for p in terms.iter() {
                    for x in [p.0, p.1].into_iter().filter(|x| x.is_finite()) {
                        assert_eq!((x / g).fract(), 0.0, "{x:e} on {g:e}: {k:?} {o:?} {d:?}");
                    }
                }
            }
        }
        // The point of them: most data has some coefficient's grid above
        // the data's.
        assert!(coarser > 10_000, "{coarser}");
    }

    /// The cylinder of radius 1 around the axis (1, 1, 0), along that
    /// axis from origins of 24 bits: α = β = 0 from terms that cancel,
    /// provable on α's and β's grids ([`grids`]) but not on the data's,
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
            super::super::words::exact(k, o, d, grid(k, o, d))
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
            super::super::words::bounded(k, o, d, m)
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

    /// The filter's bounds, recomputed from the [module's](self)
    /// derivation: `E_α = 12u m_α`, `E_β = 24u m_β`, `E_γ = 20u m_γ`, `E_Δ
    /// = u(100 m_β² + 300 m_α m_γ)`, `u` scaled by `shrink`, and the
    /// classes they certify; then [`roots`]' quotients and their bounds
    /// ([`quotient_bound`] with `E_q`, `E_s` as derived), and
    /// [`sorted_terms`]' `r`, `a` and form test. On one lane
    /// ([`classes`], [`classes_paired`]) and four, with `shrink` 1 and 1/4,
    /// over lines whose directions run from `2⁻²⁰` to `2²⁰` long, lines
    /// from just off a sphere (where `Δ̂ ≈ β̂²`, so the form test fails) and
    /// lines with every class: a slip in a term, a factor or a scale
    /// shows.
    #[test]
    fn the_filter_bounds_are_the_derivations() {
        use crate::num::real::F64x4;
        let close = |got: f64, want: f64, what: &str| {
            let ok = got == want || ((got - want) / want).abs() < 1e-14;
            assert!(ok, "{what}: {got:e}, not {want:e}");
        };
        let quadrics: [[f64; 10]; 4] = [
            [1.0, -1.0, 1.0, 0.1, 0.0, 0.05, 0.0, 0.2, 0.0, -0.5],
            [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -4.0],
            [2.0, 0.5, 1.0, 0.25, -0.5, 0.125, 1.0, -2.0, 0.5, -30.0],
            [-1.0, 3.0, 0.5, 0.0, 1.5, 0.0, -0.25, 0.0, 2.0, 7.0],
        ];
        let f32s = |v: [f64; 3]| v.map(|x| x as f32 as f64);
        let mut lines = Vec::new();
        for e in (-20..=20).step_by(5) {
            let l = 2f64.powi(e);
            for k in quadrics {
                lines.push((k, [0.3, 0.2, -5.0], f32s([-0.05 * l, 0.02 * l, l])));
                lines.push((k, [0.3, 0.2, -5.0], f32s([0.7 * l, -0.4 * l, 0.1 * l])));
            }
        }
        // From just off the sphere of radius 2: γ̂ ≈ 0, Δ̂ ≈ β̂².
        let sphere = quadrics[1];
        for z in [2.0000002f32, 2.0001, 2.01, 2.3] {
            lines.push((sphere, [0.0, 0.0, -f64::from(z)], [0.0, 0.1, 1.0]));
        }
        // α = 0: the paraboloid z = x² + y² along its axis (linear); the
        // cylinder along its axis (α = β = 0, γ = −1: none); the plane
        // z = 0 along a line in it (every t).
        let bowl = [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0];
        let cyl = [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
        let plane = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0];
        lines.push((bowl, [0.0, 0.0, -2.0], [0.0, 0.0, 1.0]));
        lines.push((cyl, [0.0; 3], [0.0, 0.0, 1.0]));
        lines.push((plane, [0.0; 3], [1.0, 0.0, 0.0]));
        // x² − y² + z² = 0.5 with α = 1 − 1 + 2⁻⁴⁰: no certain quadratic.
        let cancelling = [1.0, -1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -0.5];
        lines.push((cancelling, [0.0, 0.0, -3.0], [1.0, 1.0, 2f64.powi(-20)]));
        // From a point of the sphere, γ̂ = +0, both ways: the root γ̂/q̂ is
        // +0 whatever q̂'s sign.
        for z in [1.0, -1.0] {
            lines.push((sphere, [0.0, 0.0, -2.0], [0.0, 0.0, z]));
        }
        // A hyperboloid with every input scaled far from 1: `q̂α̂ŝ` of
        // about `2¹⁰⁴⁰` and `2⁻¹⁰⁴⁰`, out of the four lanes' range.
        for (e, f) in [(120, 100), (-120, -100)] {
            let (k, l) = (2f64.powi(e), 2f64.powi(f));
            let hyper = [k, k, -k, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
            lines.push((
                hyper,
                [0.3 * l, 0.2 * l, -5.0 * l].map(|x| x as f32 as f64),
                [0.0, 0.0, k],
            ));
        }

        let mut seen = [0usize; 9];
        for shrink in [1.0, 0.25] {
            let u = U * shrink;
            for &(k, o, d) in &lines {
                let at = format!("{k:?}, {o:?}, {d:?}, shrink {shrink}");
                let (at3, bt, gt) = crate::quadric::terms64(&k, &o, &d);
                let m = |t: &[f64]| t.iter().map(|x| x.abs()).sum::<f64>();
                let (ma, mb, mg) = (m(&at3), m(&bt), m(&gt));
                let w4 = |v: [f64; 3]| v.map(F64x4::splat);
                let four = classes(&k.map(F64x4::splat), w4(o), w4(d), shrink);
                let lane = |x: F64x4| x.to_array()[0];
                let ones = [
                    classes::<f64>(&k, o, d, shrink),
                    classes_paired(&k, o, d, shrink),
                ];
                for (n, c) in ones.iter().enumerate() {
                    let at = format!("{at}, one lane {n}");
                    close(c.ma, ma, &format!("m_α, {at}"));
                    close(c.mb, mb, &format!("m_β, {at}"));
                    close(c.mg, mg, &format!("m_γ, {at}"));
                    close(c.ea, 12.0 * u * ma, &format!("E_α, {at}"));
                    close(c.eb, 24.0 * u * mb, &format!("E_β, {at}"));
                    close(c.eg, 20.0 * u * mg, &format!("E_γ, {at}"));
                    close(
                        c.ed,
                        u * (100.0 * mb * mb + 300.0 * ma * mg),
                        &format!("E_Δ, {at}"),
                    );
                    let disc = c.beta * c.beta - 4.0 * c.alpha * c.gamma;
                    assert_eq!(c.disc.to_bits(), disc.to_bits(), "Δ̂, {at}");
                    let quad = c.alpha.abs() * 2f64.powi(-24) > c.ea;
                    assert_eq!(c.quad, quad, "quad, {at}");
                    assert_eq!(c.two, quad && disc > c.ed, "two, {at}");
                    let lin = ma == 0.0;
                    assert_eq!(c.linear(), lin && c.beta.abs() > c.eb, "linear, {at}");
                    let constant = lin && mb == 0.0;
                    let none = (quad && -c.ed > disc) || (constant && c.gamma.abs() > c.eg);
                    assert_eq!(c.none(), none, "none, {at}");
                    assert_eq!(c.all(), constant && mg == 0.0, "all, {at}");
                    seen[0] += usize::from(c.two);
                    seen[1] += usize::from(c.linear());
                    seen[2] += usize::from(c.none());
                    seen[3] += usize::from(c.all());
                }
                // Four lanes, the same sums in the same order as one.
                let c = &ones[0];
                let fields = [
                    (four.alpha, c.alpha),
                    (four.beta, c.beta),
                    (four.gamma, c.gamma),
                    (four.disc, c.disc),
                    (four.ea, c.ea),
                    (four.eb, c.eb),
                    (four.eg, c.eg),
                    (four.ed, c.ed),
                ];
                for (i, (x, y)) in fields.into_iter().enumerate() {
                    assert_eq!(lane(x).to_bits(), y.to_bits(), "field {i}, {at}");
                }
                assert_eq!(four.two.lanes()[0], c.two, "two, four lanes, {at}");

                // The roots and their bounds, where the class is two or
                // linear (elsewhere the roots are not read).
                if !(c.two || c.linear()) {
                    continue;
                }
                let (r1, r4) = (roots(c, shrink), roots(&four, shrink));
                let lin = c.linear();
                let alpha = if lin { 1.0 } else { c.alpha };
                let s = c.disc.sqrt();
                let q = -(c.beta + s.copysign(c.beta)) * 0.5;
                let es = c.ed / s * SLACK + 2.0 * u * s;
                let eq = if lin {
                    c.eb
                } else {
                    (c.eb + es) * 0.5 + 2.0 * u * q.abs()
                };
                let (ra, aa) = quotient_bound(c.ea, eq, 1.0 / alpha, 20.0 * u);
                let (rq, aq) = quotient_bound(eq, c.eg, 1.0 / q, 20.0 * u);
                let p = (q * alpha * s).abs();
                let in_range = p > 2f64.powi(-1000) && p < 2f64.powi(1000);
                let got = [
                    (r1.t0, r1.r0, r1.a0, r1.t1, r1.r1, r1.a1, true),
                    (
                        lane(r4.t0),
                        lane(r4.r0),
                        lane(r4.a0),
                        lane(r4.t1),
                        lane(r4.r1),
                        lane(r4.a1),
                        in_range,
                    ),
                ];
                for (t0, r0, a0, t1, rr1, a1, in_range) in got {
                    if !in_range {
                        assert!(r0 == f64::INFINITY && rr1 == r0, "range, {at}");
                        seen[7] += 1;
                        continue;
                    }
                    if c.gamma == 0.0 {
                        assert_eq!(t1.to_bits(), 0, "t1 = +0, {at}");
                        seen[8] += 1;
                    }
                    if !lin {
                        close(t0, q / alpha, &format!("t0, {at}"));
                        close(r0, ra, &format!("r0, {at}"));
                        close(a0, aa, &format!("a0, {at}"));
                    }
                    close(t1, c.gamma / q, &format!("t1, {at}"));
                    close(rr1, rq, &format!("r1, {at}"));
                    close(a1, aq, &format!("a1, {at}"));
                }
                assert_eq!(r1.linear, lin, "{at}");
                if lin {
                    continue;
                }

                // The scalar reference's first form, `(−β̂ ∓ ŝ)/2α̂`.
                let t = sorted_terms(c.alpha, c.beta, c.disc, (c.ea, c.eb, c.ed), shrink);
                let x = c.ea / c.alpha.abs() * SLACK;
                let g = (1.0 + 2.0 * x) * SLACK;
                close(t.r, x * g + 20.0 * u, &format!("r, {at}"));
                let h = 0.5 / c.alpha.abs() * g * SLACK;
                close(
                    t.a,
                    h * (c.eb + s * (c.ed / c.disc * SLACK + 2.0 * u)),
                    &format!("a, {at}"),
                );
                let near = -c.beta.signum() * 0.5 / c.alpha;
                close(t.t0, (c.beta.abs() + s) * near, &format!("t₀, {at}"));
                close(t.t1, (c.beta.abs() - s) * near, &format!("t₁, {at}"));
                let ratio = c.disc / (c.beta * c.beta);
                let apart = !(ratio > 225.0 / 289.0 && ratio < 289.0 / 225.0);
                assert_eq!(t.apart, apart, "apart, {at}");
                let ok = certify(t.t0, t.r, t.a) && certify(t.t1, t.r, t.a);
                let want = (apart && ok).then_some((t.t0, t.t1));
                assert_eq!(sorted(c, shrink), want, "sorted, {at}");
                seen[4] += usize::from(apart && ok);
                seen[5] += usize::from(!apart);
            }
        }
        // Past `E_α/|α̂| = 1/4` the form certifies nothing (r = 1); below,
        // `r = x(1 + 2x) + 20u` widened.
        let x = 0.2 * SLACK;
        for (ea, want) in [(0.3, 1.0), (0.2, x * (1.0 + 2.0 * x) * SLACK + 20.0 * U)] {
            let t = sorted_terms(1.0, -3.0, 1.0, (ea, 0.0, 0.0), 1.0);
            close(t.r, want, &format!("r at E_α {ea}"));
            seen[6] += 1;
        }
        assert!(
            seen[0] > 100 && seen[1] > 0 && seen[2] > 0 && seen[3] > 0,
            "{seen:?}"
        );
        assert!(seen[4] > 50 && seen[5] >= 4, "{seen:?}");
        // Out of range on four lanes: two lines at two shrinks; +0 from
        // γ̂ = +0: two lines, two shrinks, one lane and four.
        assert!(seen[7] == 4 && seen[8] == 8, "{seen:?}");
    }

    /// [`sorted_from`]'s certificate is [`certify`]'s on both roots, to
    /// the bit: roots built exact (`α̂ = 1`, `β̂ = −2B`, `Δ̂ = ŝ²`) at
    /// `j·h` from the midpoint `1 + 2⁻²⁴`, `j` from −40 to 40, on either
    /// side of the enclosure's edge, where a sign or a term of the
    /// certificate moves the answer. First with no error in α̂, β̂ or Δ̂,
    /// so that the enclosure is the roundings' alone (`20u + 2⁻⁵¹`
    /// relative, `h = 2⁻⁵²`), then with `E_α`, `E_β` and `E_Δ` in turn
    /// leading it (`h = 2⁻⁴⁸`).
    #[test]
    fn the_first_forms_certificate_is_certify() {
        let mid = 1.0 + 2f64.powi(-24);
        // The other root, `t ± ŝ`, an f32 value (1 ± 2⁻¹⁰ ± … ± 2⁻²³, or
        // 1 − 2⁻¹⁰): certified throughout.
        let s = 2f64.powi(-10) + 2f64.powi(-24);
        let p = |e: i32| 2f64.powi(e);
        let scans = [
            ((0.0, 0.0, 0.0), p(-52)),
            ((p(-45), 0.0, 0.0), p(-48)),
            ((0.0, p(-44), 0.0), p(-48)),
            ((0.0, 0.0, p(-54)), p(-48)),
        ];
        for (bounds, step) in scans {
            let (mut certified, mut refused) = (0, 0);
            for near in [true, false] {
                for j in -40..=40 {
                    let t = mid + f64::from(j) * step;
                    // t₀ = B + ŝ/2 (near) or t₁ = B − ŝ/2, exactly.
                    let b = if near { t - s / 2.0 } else { t + s / 2.0 };
                    let got = sorted_from(1.0, -2.0 * b, s * s, bounds, 1.0);
                    let want = if near {
                        (t, b - s / 2.0)
                    } else {
                        (b + s / 2.0, t)
                    };
                    let w = sorted_terms(1.0, -2.0 * b, s * s, bounds, 1.0);
                    assert_eq!((w.t0, w.t1), want, "j {j}");
                    let ok = w.apart && certify(w.t0, w.r, w.a) && certify(w.t1, w.r, w.a);
                    assert_eq!(got, ok.then_some(want), "j {j}, near {near}, {bounds:?}");
                    certified += usize::from(ok);
                    refused += usize::from(!ok);
                }
            }
            // Both sides of the edge, on both roots: |j| up to about 12
            // (8 with a bound leading) is refused, the rest certified.
            assert!(
                certified > 100 && refused > 30,
                "{certified} {refused}, {bounds:?}"
            );
        }
    }
}
