//! The x4 kernels' first pass over the quadric: the classes of the
//! [filter](super::stages) from sums taken pairwise, and both roots in
//! the form `(−β ∓ √Δ)/2α`, sorted, which no division waits for after the
//! square root. Lanes it leaves (α = 0, a root that cancels, an `α̂`
//! that cancels, a product out of range) go to the filter's quotients.
//!
//! # The bound
//!
//! In the notation of [`crate::sphere::stages`] (`u = 2⁻⁵³`, `γₙ =
//! nu/(1 − nu)`, hats for computed values, `E` for error bounds), with f32
//! inputs exact in f64. Every term of α, β and γ is a coefficient times one
//! or two inputs: `k·x` is exact (two f32 values), `k·x·y` rounds once. A
//! sum taken by any tree of additions is within `Σ|tᵢ|γₙ` of the exact
//! sum of its exact terms `tᵢ`, `n` the most roundings any term meets on
//! its way (its own and one per addition; Higham, *Accuracy and Stability
//! of Numerical Algorithms*, §3.1 and §4.2). Here:
//!
//! * α, six terms in a tree of depth three: `E_α = γ₄ m_α`;
//! * β, its three square terms summed (depth two) and doubled (exact),
//!   its six cross terms (depth three) and its three linear ones (exact
//!   products, depth two) summed, and the three sums added: five additions
//!   at most, `E_β = γ₆ m_β`, `m_β` counting the square terms twice;
//! * γ, its six quadratic terms (depth three) and its three linear ones
//!   with the constant (exact, depth two) summed, and the two added:
//!   `E_γ = γ₅ m_γ`;
//!
//! with `m` the sum of the terms' magnitudes, summed by the same trees
//! (`pairwise`).
//! The pass uses twice these: `E_α = 8u m_α`, `E_β = 12u m_β`, `E_γ = 10u
//! m_γ`, which also covers the roundings of the `m` themselves.
//!
//! * `Δ = β² − 4αγ` (`4α̂` exact): `|β̂² − β²| ≤ E_β(2|β̂| + E_β)`,
//!   `|α̂γ̂ − αγ| ≤ |α̂|E_γ + (|γ̂| + E_γ)E_α`, and three roundings, of
//!   `β̂²`, of `4α̂γ̂` and of the difference, at most `2u(β̂² + 4|α̂γ̂|)` to
//!   first order. With `|β̂| ≤ m_β`, `|α̂| ≤ m_α`, `|γ̂| ≤ m_γ` (a computed
//!   sum is at most the computed sum of magnitudes), that is `u(14 m_β² +
//!   44 m_α m_γ)` to first order: `12u` from `β̂`, `36u` from `α̂` and `γ̂`,
//!   `2u` and `8u` from the roundings. The pass uses twice that, **`E_Δ =
//!   u(28 m_β² + 88 m_α m_γ)`**, for the terms of order `u²` and the
//!   roundings of its own evaluation.
//! * The classes as in the filter: `|α̂| > E_α` certifies a quadratic, then
//!   `Δ̂ > E_Δ` two roots and `Δ̂ < −E_Δ` none. `m_α = 0` means α = 0
//!   exactly (a nonzero term is at least `2⁻⁴⁴⁷`): the pass leaves such a
//!   line (a linear root, no root or the whole line) to the quotients,
//!   and computes no `E_γ`, which enters only the proof of `E_Δ`.
//!
//! The roots where two are certified, so `|α̂| > E_α` (α̂ has α's sign)
//! and `Δ̂ > E_Δ ≥ 0`. With `σ = sign(α̂)` and `β' = σβ` (exact), the
//! roots are `t = (−β' ∓ √Δ)/2|α|`, the smaller first.
//!
//! * `ŝ = fl(√Δ̂)`: `|√Δ − √Δ̂| ≤ E_Δ/√Δ̂` (`Δ ≥ 0`), and one rounding, so
//!   `E_s = E_Δ/ŝ + 2uŝ` (the `1 + u` between `√Δ̂` and `ŝ` is in the
//!   widening below).
//! * `n̂ = fl(−β̂' ∓ ŝ)` against `n = −β' ∓ √Δ`: `|n̂ − n| ≤ 1.01u|n̂| + E_β
//!   + E_s`.
//! * One division, `ρ = 1/(2α̂Δ̂)`, started with the square root, gives
//!   `ι = |Δ̂ρ|`, `1/2|α̂|` within `γ₃`, and `ŝ|ρ|`, `1/(2|α̂|ŝ)` within
//!   `γ₅` (`ŝ² = Δ̂(1 + θ₂)`): `E_s/2|α̂|` is `ŝ|ρ|(E_Δ + 2uΔ̂)`, which
//!   waits on the square root for one product alone.
//! * `t̂ = fl(n̂ι)` is within `γ₄|x|` of `x = n̂/2|α̂|`. With `w = E_α/|α̂|`,
//!   `x − t = (n̂ − n)/2|α̂| + t(|α| − |α̂|)/|α̂|`, so `|x − t| ≤ A + w|t| ≤
//!   A + w|x| + w|x − t|`, `A = |n̂ − n|/2|α̂|`: `|x − t| ≤ (A + w|x|)/(1 −
//!   w)`, and the pass certifies only where `w < 2⁻¹⁰` (`α̂` cancelling
//!   by less than about 40 bits), bounding `1/(1 − w)` by `1 + 2⁻⁹`.
//!
//! Altogether `|t̂ − t| ≤ |t̂|((1 + 2⁻⁹)w + 5.6u) + (1 + 2⁻⁹)(E_β +
//! E_s)/2|α̂|` to first order (`4.01u` from `t̂`'s roundings, `1.01u(1 +
//! 2⁻⁹)` from `n̂`'s). The pass uses `r = (1 + 2⁻⁹)w + 20u` and `a = (1 +
//! 2⁻⁹)(E_β + E_s)/2|α̂|`, each factor widened by `1 + 2⁻³⁰`, which covers the
//! roundings of `ι`, `ŝ|ρ|` and of the bound's own evaluation. Two
//! factors multiply the bounds, for the tests that shrink each on its
//! own: `shrink` those of the classes (`E_α` against `α̂`, `E_Δ` against
//! `Δ̂`), `roots` those of the roots (`E_α` in `w`, `E_β`, `E_Δ` in
//! `E_s`, `2uŝ` and `20u`); the kernels pass 1 for both.
//!
//! Rounding is monotone, `ŝ ≥ 0` and `ι > 0`, so the first root is at
//! most the second without a comparison. A root that cancels (`|n̂|` far
//! below `|β̂|`, a root near 0 against the other) has a bound too wide
//! to certify; an exact root 0 gives `n̂ = ±0` with `a > 0`, which never
//! certifies.
//!
//! # Range
//!
//! A nonzero term is at least `2⁻⁴⁴⁷` and at most `2³⁸⁴` (f32 values), so
//! a multiple of `2⁻⁴⁹⁹`, and so is every sum of terms: a nonzero `α̂`,
//! `β̂` or `γ̂` lies between `2⁻⁴⁹⁹` and `2³⁸⁸`. So `β̂²` and `4α̂γ̂` are
//! normal (or 0), and the rounding model above holds for `Δ̂` and every
//! quantity of the classes, for every finite input. `2α̂Δ̂` may leave f64's
//! range: the pass certifies roots only where `2⁻¹⁰⁰⁰ < |2α̂Δ̂| < 2¹⁰⁰⁰`,
//! so that `ρ` is normal and finite, and `ι` lies between `2⁻³⁸⁹` and
//! `2⁴⁹⁸`. A positive `Δ̂` has `ŝ ≥ 2⁻⁵³⁷`; a nonzero `n̂` is at least the
//! smaller ulp of `β̂` and `ŝ`, `2⁻⁵⁸⁹`, so `t̂ = fl(n̂ι)` is normal; so are
//! `w`, `ŝ|ρ|(E_Δ + 2uΔ̂)` (at least `2uŝι`) and `E_βι` where not 0. A
//! non-finite input makes a magnitude sum infinite or NaN, which certifies
//! nothing.

use crate::num::certify::{SLACK, U};
use crate::num::real::Real;

/// The classes of the first pass, as the [module](self) derives them,
/// and what its roots need.
pub(crate) struct Classes<L: Real> {
    alpha: L,
    beta: L,
    disc: L,
    /// `E_α`, `E_β` and `E_Δ` as the roots take them.
    ea: L,
    eb: L,
    ed: L,
    /// Certified: two roots (which still need certifying).
    pub(crate) two: L::Mask,
    /// Certified: no root.
    pub(crate) none: L::Mask,
    /// α = 0 exactly (`m_α = 0`): left to the quotients.
    pub(crate) lin: L::Mask,
}

impl<L: Real> Classes<L> {
    /// The lanes with α = 0 exactly whose `|β̂|` passes the filter's test
    /// for the linear root, `|β̂| > E_β = 24u m_β` (twice this pass's root
    /// bound `E_β`): the only α = 0 lanes the quotients can decide. The
    /// others (β = 0 too: no root, or the line on the surface) go to the
    /// scalar stages without them.
    #[inline(always)]
    pub(crate) fn linear(&self) -> L::Mask {
        self.lin & self.beta.abs().gt(self.eb + self.eb)
    }
}

/// A sum and the sum of its terms' magnitudes.
#[derive(Clone, Copy)]
struct Summed<L>(L, L);

impl<L: Real> Summed<L> {
    /// One term.
    #[inline(always)]
    fn of(x: L) -> Summed<L> {
        Summed(x, x.abs())
    }
    /// Two sums added.
    #[inline(always)]
    fn and(self, o: Summed<L>) -> Summed<L> {
        Summed(self.0 + o.0, self.1 + o.1)
    }
}

/// `N` terms summed by neighbours in pairs, level by level: `⌈log₂ N⌉`
/// additions on the way of every term, where a sum from left to right
/// has up to `N − 1`. Written out for the sizes the pass needs (3, 4 and
/// 6), as a loop over the array would not always be unrolled.
#[inline(always)]
fn pairwise<L: Real, const N: usize>(t: [L; N]) -> Summed<L> {
    let x = |i: usize| Summed::of(t[i]);
    match N {
        3 => x(0).and(x(1)).and(x(2)),
        4 => x(0).and(x(1)).and(x(2).and(x(3))),
        6 => x(0).and(x(1)).and(x(2).and(x(3))).and(x(4).and(x(5))),
        _ => unreachable!("no sum of {N} terms"),
    }
}

/// The classes of the line `o + t d` on the quadric `k`, their bounds
/// multiplied by `shrink` and those kept for the roots by `roots`: the
/// filter's decisions with the [module](self)'s sums and bounds. The
/// products `k·x` shared by several terms are taken once.
#[inline(always)]
pub(crate) fn classes<L: Real>(
    k: &[L; 10],
    o: [L; 3],
    d: [L; 3],
    shrink: f64,
    roots: f64,
) -> Classes<L> {
    // The exact products of two f32 values, each used by two terms or more.
    let (k0d0, k0o0) = (k[0] * d[0], k[0] * o[0]);
    let (k1d1, k1o1) = (k[1] * d[1], k[1] * o[1]);
    let (k2d2, k2o2) = (k[2] * d[2], k[2] * o[2]);
    let (k3d0, k3o0) = (k[3] * d[0], k[3] * o[0]);
    let (k4d0, k4o0) = (k[4] * d[0], k[4] * o[0]);
    let (k5d1, k5o1) = (k[5] * d[1], k[5] * o[1]);
    let linear = |v: [L; 3]| [k[6] * v[0], k[7] * v[1], k[8] * v[2]];
    let Summed(alpha, ma) = pairwise([
        k0d0 * d[0],
        k1d1 * d[1],
        k2d2 * d[2],
        k3d0 * d[1],
        k4d0 * d[2],
        k5d1 * d[2],
    ]);
    // β's square terms before their factor 2, its cross terms, its
    // linear ones.
    let Summed(sq, msq) = pairwise([k0o0 * d[0], k1o1 * d[1], k2o2 * d[2]]);
    let Summed(cross, mcross) = pairwise([
        k3o0 * d[1],
        k3d0 * o[1],
        k4o0 * d[2],
        k4d0 * o[2],
        k5o1 * d[2],
        k5d1 * o[2],
    ]);
    let Summed(lin, mlin) = pairwise(linear(d));
    let beta = (sq + sq) + (cross + lin);
    let mb = (msq + msq) + (mcross + mlin);
    let Summed(quad, mquad) = pairwise([
        k0o0 * o[0],
        k1o1 * o[1],
        k2o2 * o[2],
        k3o0 * o[1],
        k4o0 * o[2],
        k5o1 * o[2],
    ]);
    let [l0, l1, l2] = linear(o);
    let Summed(rest, mrest) = pairwise([l0, l1, l2, k[9]]);
    let (gamma, mg) = (quad + rest, mquad + mrest);

    // The roots' bounds, then the classes': with the two factors equal (1
    // in the kernels), the same expressions, taken once.
    let cr = |x: f64| L::splat(x * U * roots);
    let zero = L::splat(0.0);
    let (ea, eb) = (cr(8.0) * ma, cr(12.0) * mb);
    let disc = beta * beta - L::splat(4.0) * alpha * gamma;
    let ed = cr(28.0) * mb * mb + cr(88.0) * ma * mg;
    let c = |x: f64| L::splat(x * U * shrink);
    let (ea_class, ed_class) = (c(8.0) * ma, c(28.0) * mb * mb + c(88.0) * ma * mg);
    let quadratic = alpha.abs().gt(ea_class);
    Classes {
        alpha,
        beta,
        disc,
        ea,
        eb,
        ed,
        two: quadratic & disc.gt(ed_class),
        none: quadratic & (-ed_class).gt(disc),
        lin: ma.eq(zero),
    }
}

/// Both roots, sorted, with one bound `|t|·r + a` for both.
pub(crate) struct Sorted<L: Real> {
    /// The smaller root.
    pub(crate) lo: L,
    /// The larger root.
    pub(crate) hi: L,
    /// The relative part of either root's bound.
    pub(crate) r: L,
    /// The absolute part of either root's bound.
    pub(crate) a: L,
}

/// The roots `(−β ∓ √Δ)/2α`, sorted, and their bound, as the
/// [module](self) derives them, every bound multiplied by `roots` (the
/// factor [`classes`] took for them too); meaningful in the lanes
/// [`Classes::two`] certifies.
#[inline(always)]
pub(crate) fn sorted<L: Real>(k: &Classes<L>, roots: f64) -> Sorted<L> {
    let c = |x: f64| L::splat(x * U * roots);
    let one = L::splat(1.0);
    let (alpha, disc) = (k.alpha, k.disc);
    let p = (alpha + alpha) * disc;
    let pa = p.abs();
    let in_range = pa.gt(L::splat(2f64.powi(-1000))) & L::splat(2f64.powi(1000)).gt(pa);
    let rho = one / p;
    // ι = 1/2|α̂|, and β' = σβ.
    let ia = (disc * rho).abs();
    let beta = k.beta * one.copysign(alpha);
    // w = E_α/|α̂|, and 1 + 2w ≤ 1 + 2⁻⁹ where w < 2⁻¹⁰, widened.
    let w = k.ea * ia * L::splat(2.0 * SLACK);
    let g = 1.0 + 2f64.powi(-9);
    let r = L::select(
        L::splat(2f64.powi(-10)).gt(w) & in_range,
        w * L::splat(g * SLACK) + c(20.0),
        L::splat(f64::INFINITY),
    );
    // E_s/2|α̂| but for the factor ŝ, and E_β/2|α̂|, each times 1 + 2⁻⁹.
    let es = rho.abs() * ((k.ed + c(2.0) * disc) * L::splat(g * SLACK * SLACK));
    let eb = k.eb * ia * L::splat(g * SLACK);
    let s = disc.sqrt();
    Sorted {
        lo: (-beta - s) * ia,
        hi: (s - beta) * ia,
        r,
        a: eb + s * es,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Lines grazing the sphere `x² + y² + z² = R²` from 2.5 to 3.2 radii
    /// away, passing the centre at a distance tuned through the last bits
    /// of the direction, so that `Δ` is a few thousand `u·m_β²` or less:
    /// there the discriminant's bound `E_Δ` leads the roots' bound (its
    /// part `E_Δ/2|α̂|ŝ` is larger than `E_β/2|α̂|` and than the relative
    /// part), and its two terms `28u·m_β²` and `88u·m_α·m_γ` are nearly
    /// equal, so a slip in either (a sign, a product for the sum) leaves
    /// the bound below the roots' error. The first pass certifies two
    /// roots on a sixth of these lines (and leaves most others), with
    /// `E_Δ` leading on nearly all; every answer, its own and x4's, is the
    /// oracle's.
    #[test]
    fn grazing_lines_whose_roots_the_discriminants_bound_leads() {
        use crate::quadric::x4::{Quadric4, first_pass_shrunk, intersect, intersect_baseline};
        use crate::quadric::{Quadric, QuadricHit};
        use crate::{Ray, ray4::Ray4};
        use glam::Vec3;
        let mut next = crate::num::xorshift(0x1234_5678_9abc_def1);
        let (mut two, mut led) = (0, 0);
        let n = 20_000;
        let mut cases = Vec::with_capacity(n);
        for _ in 0..n {
            let r = next();
            let rr = 0.5 + (r % 1000) as f32 / 1000.0;
            let q = rr * rr;
            let radius = f64::from(q).sqrt();
            // Inside the sphere by 1 to 64 ulps of y, from 2.5 to 3.2 radii
            // back along x; the direction's y turns the line out to pass
            // the centre at about R, within a few of its own ulps.
            let j = ((r >> 10) % 64 + 1) as f32;
            let oy = (radius as f32) * (1.0 - j * 2f32.powi(-24));
            let ox = -rr * (2.5 + ((r >> 30) % 4096) as f32 / 4096.0 * 0.7);
            let dy = ((radius - f64::from(oy)) / -f64::from(ox)) as f32;
            let dy = f32::from_bits((dy.to_bits() as i32 + ((r >> 50) % 5) as i32 - 2) as u32);
            let quadric = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -q]);
            let ray = Ray::new(Vec3::new(ox, oy, 0.0), Vec3::new(1.0, dy, 0.0));
            let want = crate::quadric::exact::intersect(&ray, &quadric).unwrap();
            let got = first_pass_shrunk(&ray, &quadric, 1.0, 1.0);
            if let Some(got) = got {
                assert_eq!(got, want, "{ray:?} {quadric:?}");
            }
            if let Some(QuadricHit::Two(..)) = got {
                two += 1;
                let w = |v: Vec3| v.to_array().map(f64::from);
                let k = quadric.coeffs.map(f64::from);
                let c = classes(&k, w(ray.origin), w(ray.dir), 1.0, 1.0);
                let sorted = sorted(&c, 1.0);
                let (s, two_alpha) = (c.disc.sqrt(), 2.0 * c.alpha.abs());
                let e_delta = c.ed / (two_alpha * s);
                led +=
                    usize::from(e_delta > c.eb / two_alpha && e_delta > sorted.r * sorted.hi.abs());
            }
            cases.push((ray, quadric, want));
        }
        for c in cases.chunks_exact(4) {
            let (r4, q4) = (
                Ray4::from_rays([0, 1, 2, 3].map(|i| c[i].0)),
                Quadric4::from_quadrics([0, 1, 2, 3].map(|i| c[i].1)),
            );
            let want = [0, 1, 2, 3].map(|i| c[i].2);
            assert_eq!(intersect(&r4, &q4).lanes(), want);
            assert_eq!(intersect_baseline(&r4, &q4).lanes(), want);
        }
        assert!(two > n / 10 && led > two * 9 / 10, "{two} {led}");
    }

    /// The pass's bounds are the derivation's, computed here again from
    /// the terms of α, β and γ: `E_α = 8u m_α`, `E_β = 12u m_β` (with
    /// `m_β` counting the square terms twice), `E_Δ = u(28 m_β² + 88 m_α
    /// m_γ)`, all with `u` scaled by `roots`; the classes against `shrink`
    /// times these; and the roots' `r = (1 + 2⁻⁹)w·SLACK + 20u`, `w =
    /// 2·SLACK·E_α/2|α̂|`, and `a = (1 + 2⁻⁹)SLACK(E_β/2|α̂| + ŝ(E_Δ +
    /// 2uΔ̂)SLACK/|2α̂Δ̂|)`. On one lane and four, over lines whose
    /// directions run from `2⁻²⁰` to `2²⁰` long, so that `α̂`, `Δ̂` and
    /// their product range far from 1, with `roots` and `shrink` 1 or 1/4
    /// apart: a slip in a term, a factor or a scale shows. The committed
    /// cases lead with `w`, the class bound or `E_Δ` (above), so the other
    /// terms are guarded here.
    #[test]
    fn the_pass_bounds_are_the_derivations() {
        use crate::num::real::F64x4;
        let quadrics: [[f64; 10]; 3] = [
            [1.0, -1.0, 1.0, 0.1, 0.0, 0.05, 0.0, 0.2, 0.0, -0.5],
            [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -4.0],
            [2.0, 0.5, 1.0, 0.25, -0.5, 0.125, 1.0, -2.0, 0.5, -30.0],
        ];
        let close = |got: f64, want: f64, what: &str| {
            let ok = got == want || ((got - want) / want).abs() < 1e-14;
            assert!(ok, "{what}: {got:e}, not {want:e}");
        };
        let o: [f64; 3] = [0.3, 0.2, -5.0];
        let mut lines = Vec::new();
        for e in (-20..=20).step_by(5) {
            let l = 2f64.powi(e);
            for k in quadrics {
                lines.push((k, [-0.05 * l, 0.02 * l, l].map(|x| x as f32 as f64)));
            }
        }
        // On x² − y² + z² = 0.5, α = 1 − 1 + 2⁻⁴⁰ exactly, from terms of
        // 1: w ≈ 2⁻⁹ (2⁻¹¹ with `roots` 1/4), past the pass's limit 2⁻¹⁰,
        // so r is infinite, with two roots all the same.
        let cancelling = [1.0, -1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -0.5];
        lines.push((cancelling, [1.0, 1.0, 2f64.powi(-20)]));
        let (mut seen, mut past) = (0, 0);
        for (shrink, roots) in [(1.0, 1.0), (0.25, 1.0), (1.0, 0.25)] {
            for &(k, d) in &lines {
                {
                    // The terms, as the report's conditioning takes them,
                    // β's square terms doubled.
                    let (at, bt, gt) = crate::quadric::terms64(&k, &o, &d);
                    let m = |t: &[f64]| t.iter().map(|x| x.abs()).sum::<f64>();
                    let (ma, mb, mg) = (m(&at), m(&bt), m(&gt));
                    let u = U * roots;
                    let (ea, eb, ed) = (
                        8.0 * u * ma,
                        12.0 * u * mb,
                        u * (28.0 * mb * mb + 88.0 * ma * mg),
                    );
                    let one = classes::<f64>(&k, o, d, shrink, roots);
                    let w4 = |v: [f64; 3]| v.map(F64x4::splat);
                    let four = classes(&k.map(F64x4::splat), w4(o), w4(d), shrink, roots);
                    let (a1, s1) = (sorted(&one, roots), sorted(&four, roots));
                    let lanes = [
                        (
                            one.alpha, one.disc, one.ea, one.eb, one.ed, one.two, a1.r, a1.a,
                        ),
                        (
                            four.alpha.to_array()[0],
                            four.disc.to_array()[0],
                            four.ea.to_array()[0],
                            four.eb.to_array()[0],
                            four.ed.to_array()[0],
                            four.two.lanes()[0],
                            s1.r.to_array()[0],
                            s1.a.to_array()[0],
                        ),
                    ];
                    for (alpha, disc, got_ea, got_eb, got_ed, two, r, a) in lanes {
                        let at = format!("{d:?}, {k:?}, shrink {shrink}, roots {roots}");
                        close(got_ea, ea, &format!("E_α, {at}"));
                        close(got_eb, eb, &format!("E_β, {at}"));
                        close(got_ed, ed, &format!("E_Δ, {at}"));
                        let quadratic = alpha.abs() > ea / roots * shrink;
                        assert_eq!(two, quadratic && disc > ed / roots * shrink, "two, {at}");
                        if !two {
                            continue;
                        }
                        let (g, ia) = (1.0 + 2f64.powi(-9), 0.5 / alpha.abs());
                        let w = 2.0 * SLACK * ea * ia;
                        let p = 2.0 * alpha * disc;
                        let in_range = p.abs() > 2f64.powi(-1000) && p.abs() < 2f64.powi(1000);
                        let want_r = if w < 2f64.powi(-10) && in_range {
                            w * g * SLACK + 20.0 * u
                        } else {
                            f64::INFINITY
                        };
                        close(r, want_r, &format!("r, {at}"));
                        past += usize::from(r == f64::INFINITY);
                        let es = disc.sqrt() * (ed + 2.0 * u * disc) * SLACK / p.abs();
                        close(a, g * SLACK * (eb * ia + es), &format!("a, {at}"));
                        seen += 1;
                    }
                }
            }
        }
        // The cancelling line, on one lane and four, at `roots` 1.
        assert!(seen >= 100 && past == 4, "{seen} {past}");
    }
}
