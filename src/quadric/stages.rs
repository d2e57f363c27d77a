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
//! for [`certify`](crate::num::certify::certify), and every part is widened
//! by `1 + 2⁻³⁰` for the roundings of its own evaluation; the roots'
//! roundings, `9u` in all, count `20u`. A root exactly 0 (`γ = 0` term by
//! term) is `+0`.
//!
//! # Range
//!
//! `β²` and `αγ` are products of six f32 values at most: between `2⁻⁸⁹⁴`
//! and `2⁷⁶⁸` in magnitude, so no overflow and no underflow into f64's
//! subnormals for any finite input. A non-finite input certifies nothing.
//!
//! # After the filter
//!
//! What the filter leaves goes to the later stages, in the order
//! [`later()`] takes them, and last to the exact oracle:
//!
//! * [`words`]: α, β and γ in double words within `1024u²m`, for lines
//!   nearly parallel to a rotated axis, where nothing is exactly 0;
//! * a perfect square ([`super::square`]), whose `Δ` is 0 on every line;
//! * [`tracked`]: α, β, γ and `Δ` in f64 with every operation checked for
//!   exactness, so that the exact zeros (α = 0, a double root, a line on
//!   the surface) follow from signs;
//! * [`tight`]: α in double words next to the filter's β and γ;
//! * [`double_word`]: every term exact as two words, the coefficients and
//!   `Δ` summed on the data's [`grid()`] or with each low addition checked.
//!
//! Each bound is derived at its stage. Each answer is the exact class
//! with correctly rounded roots, so any two stages that answer agree.

use crate::num::certify::{SLACK, U, quotient_bound};
use crate::num::real::Real;

mod after;
mod grid;

pub(crate) use after::{bounded_lanes, later_of, tree_sum};
pub use after::{disc_near, double_word, later, tight, tracked, words};
pub use grid::{grid, grids};

/// The filter's result: the certified classes and the roots with their
/// bounds.
#[derive(Clone, Copy, Debug)]
pub struct Filtered<L: Real> {
    /// Certified: two roots `t0`, `t1` (unsorted; each still needs
    /// [`certify`](crate::num::certify::certify)).
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
    /// Certified: two roots (which still need [`certify`](crate::num::certify::certify)).
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
    /// their [`grids()`] `g`: those whose terms' magnitudes sum below
    /// `2⁵²g` (as the later stages test it).
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
/// `shrink`, as [`roots`] does, and certifies each root as [`certify`](crate::num::certify::certify)
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::certify::certify;

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
