//! The quadric's arithmetic, written once over [`Lane`] and instantiated at
//! `f32` by [`super::reference`](mod@super::reference) and at `f32x4` by [`super::x4`] (see
//! [`crate::sphere::kernel`] for why).

use crate::num::scale::{Scale, normalized3};
use crate::num::{Ff, Lane};

/// `k · x · y` to double-word accuracy: the exact `x·y`, scaled by `k`.
#[inline(always)]
fn term<L: Lane>(k: L, x: L, y: L) -> Ff<L> {
    Ff::product(x, y).scale(k)
}

/// α, β, γ of the ray against the coefficients `k`, in double-word
/// arithmetic (the seed's expansion, with its `o t d_z → i t d_z` typo
/// fixed).
///
/// ```
/// use rayoracle::quadric::kernel::coefficients;
/// let cyl = [1.0f32, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// let (a, b, c) = coefficients(&cyl, [-5.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
/// assert_eq!((a.hi, b.hi, c.hi), (1.0, -10.0, 24.0));
/// ```
#[inline(always)]
pub fn coefficients<L: Lane>(k: &[L; 10], o: [L; 3], d: [L; 3]) -> (Ff<L>, Ff<L>, Ff<L>) {
    let two = L::splat(2.0);
    let alpha = term(k[0], d[0], d[0])
        + term(k[1], d[1], d[1])
        + term(k[2], d[2], d[2])
        + term(k[3], d[0], d[1])
        + term(k[4], d[0], d[2])
        + term(k[5], d[1], d[2]);
    let beta = (term(k[0], o[0], d[0]) + term(k[1], o[1], d[1]) + term(k[2], o[2], d[2]))
        .scale(two)
        + term(k[3], o[0], d[1])
        + term(k[3], d[0], o[1])
        + term(k[4], o[0], d[2])
        + term(k[4], d[0], o[2])
        + term(k[5], o[1], d[2])
        + term(k[5], d[1], o[2])
        + Ff::product(k[6], d[0])
        + Ff::product(k[7], d[1])
        + Ff::product(k[8], d[2]);
    let gamma = term(k[0], o[0], o[0])
        + term(k[1], o[1], o[1])
        + term(k[2], o[2], o[2])
        + term(k[3], o[0], o[1])
        + term(k[4], o[0], o[2])
        + term(k[5], o[1], o[2])
        + Ff::product(k[6], o[0])
        + Ff::product(k[7], o[1])
        + Ff::product(k[8], o[2])
        + Ff::from(k[9]);
    (alpha, beta, gamma)
}

/// What the classification needs (leading parts of α, β, γ and the
/// discriminant; only signs and zero-ness are used) and every candidate
/// root, in the caller's units.
#[derive(Clone, Copy, Debug)]
pub struct Parts<L> {
    /// α.
    pub alpha: L,
    /// β.
    pub beta: L,
    /// γ.
    pub gamma: L,
    /// β² − 4αγ.
    pub disc: L,
    /// `−γ/β`, the root when α = 0.
    pub linear: L,
    /// `−β/2α`, the double root.
    pub double: L,
    /// The smaller root.
    pub t0: L,
    /// The larger root.
    pub t1: L,
}

/// Computes [`Parts`]: pbrt-v4's `Quadratic` in double-word arithmetic after
/// exact prescaling of the coefficients (the surface is unchanged) and of
/// `d` (roots scale back by `2^−kd`).
///
/// ```
/// use rayoracle::quadric::kernel::solve;
/// let cyl = [1.0f32, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// let p = solve(&cyl, [-5.0, 0.0, 0.0], [1.0, 0.0, 0.0]);
/// assert_eq!((p.t0, p.t1), (4.0, 6.0));
/// ```
#[inline(always)]
pub fn solve<L: Lane>(coeffs: &[L; 10], o: [L; 3], d: [L; 3]) -> Parts<L> {
    let sq = Scale::of_max(coeffs);
    let k = coeffs.map(|x| sq.apply(x));
    let (d, sd) = normalized3(d);
    let (alpha, beta, gamma) = coefficients(&k, o, d);
    let e = -sd.k;

    // pbrt-v4: DifferenceOfProducts(b, b, 4a, c), here exact products and a
    // double-word difference.
    let disc = beta * beta - (alpha * gamma).scale(L::splat(4.0));
    // pbrt-v4: q = −½(b + sign(b)√Δ), t₀ = q/a, t₁ = c/q.
    let q = -(beta + disc.sqrt().with_sign_of(beta.hi)).scale(L::splat(0.5));
    let u0 = (q / alpha).round().ldexp(e);
    let u1 = (gamma / q).round().ldexp(e);
    Parts {
        alpha: alpha.hi,
        beta: beta.hi,
        gamma: gamma.hi,
        disc: disc.hi,
        linear: (-(gamma / beta)).round().ldexp(e),
        double: (-(beta / alpha.scale(L::splat(2.0)))).round().ldexp(e),
        t0: L::select_gt(u0, u1, u1, u0),
        t1: L::select_gt(u0, u1, u0, u1),
    }
}
