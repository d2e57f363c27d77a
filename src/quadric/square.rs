//! Quadrics that are perfect squares: the double plane `(n·p − e)² = 0`,
//! on which every line's discriminant is exactly 0.
//!
//! # The test
//!
//! Write the quadric as `P̃ᵀQP̃` with `P̃ = (x, y, z, 1)` and the symmetric
//! `Q = [[A, D/2, E/2, G/2], [D/2, B, F/2, H/2], [E/2, F/2, C, I/2], [G/2,
//! H/2, I/2, J]]`. `Q` has rank 1 exactly where some `Qᵢᵢ ≠ 0` and
//! `QᵢᵢQⱼₖ = QᵢⱼQᵢₖ` for every `j` and `k`: then `Q = rrᵀ/Qᵢᵢ` with `r` the
//! row `i` (and conversely, `Q = s vvᵀ` gives `QᵢᵢQⱼₖ = s²vᵢ²vⱼvₖ =
//! QᵢⱼQᵢₖ`). Each entry is an f32 value or half of one, so each product of
//! two is exact in f64 (48 significant bits, exponents far inside f64's
//! range), and each equality is exact. Nonzero `Qᵢᵢ` is taken as the first.
//!
//! # The roots
//!
//! On the line `P̃(t) = (o, 1) + t(d, 0)`, the quadric is `(a t + b)²/Qᵢᵢ`
//! with `a = r·(d, 0)` and `b = r·(o, 1)`: `α = a²/Qᵢᵢ`, `β = 2ab/Qᵢᵢ`,
//! `γ = b²/Qᵢᵢ`, and `β² − 4αγ = 0` for every line. So:
//!
//! * `a ≠ 0`: the double root `−b/a`, [`QuadricHit::One`];
//! * `a = 0`: `α = β = 0`, and `γ = 0` (the line lies on the surface,
//!   [`QuadricHit::All`]) exactly where `b = 0`; otherwise no root.
//!
//! `a` and `b` are sums of three and four exact products: summed into
//! double words by [`Acc`], which proves them exact (or bounds them), and
//! the root is their [`quotient`], certified. With `a` and `b` exact, the
//! quotient of their leading words is within `3u|t|` of the root, inside
//! the `2⁻⁵¹|t|` that [`certify`](crate::num::certify::certify) adds to
//! every enclosure: the bounds, and so `shrink`, never decide what this
//! stage answers, and `tests/stage_bounds.rs` shows it right at every
//! factor. That replaces the filter's
//! bound on `Δ`, which cannot prove `Δ = 0`, and the double-word stage's
//! exact sum of `Δ` from exact α, β and γ, which costs some thirty
//! exact products.

use super::QuadricHit;
use crate::num::dd::{Acc, quotient};

/// The intersection of the line `o + t d` with the quadric `k` where `k`
/// is a perfect square (rank 1, the [module](self)'s test), `None` where
/// it is not, where an input is not finite, or where the root is not
/// certified; the quotient's bound multiplied by `shrink`.
///
/// ```
/// use rayoracle::quadric::{QuadricHit, square::intersect};
/// // (x − z − 1)²: crossed at t = 1 along x from the origin.
/// let k = [1.0, 0.0, 1.0, 0.0, -2.0, 0.0, -2.0, 0.0, 2.0, 1.0];
/// assert_eq!(intersect(&k, [0.0; 3], [1.0, 0.0, 0.0], 1.0), Some(QuadricHit::One(1.0)));
/// // Inside the plane: every t; beside it and parallel: none.
/// assert_eq!(intersect(&k, [1.0, 0.0, 0.0], [1.0, 0.0, 1.0], 1.0), Some(QuadricHit::All));
/// assert_eq!(intersect(&k, [0.0; 3], [1.0, 0.0, 1.0], 1.0), Some(QuadricHit::None));
/// // The unit sphere has rank 4.
/// let s = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// assert_eq!(intersect(&s, [0.0; 3], [1.0, 0.0, 0.0], 1.0), None);
/// ```
#[inline(always)]
pub fn intersect(k: &[f64; 10], o: [f64; 3], d: [f64; 3], shrink: f64) -> Option<QuadricHit> {
    let q = matrix(k);
    let i = (0..4).find(|&i| q[i][i] != 0.0)?;
    // The pairs (j, k), j ≤ k, neither i; a NaN product fails the test,
    // an infinite one is caught below.
    for j in 0..4 {
        for l in j..4 {
            if j != i && l != i && q[i][i] * q[j][l] != q[i][j] * q[i][l] {
                return None;
            }
        }
    }
    if !k.iter().chain(&o).chain(&d).all(|x| x.is_finite()) {
        return None;
    }
    let r = q[i];
    let (mut a, mut b) = (Acc::new(), Acc::new());
    for j in 0..3 {
        a.add(r[j] * d[j]);
        b.add(r[j] * o[j]);
    }
    b.add(r[3]);
    let (a, b) = (a.finish(), b.finish());
    let (sa, sb) = (a.shrunk(shrink), b.shrunk(shrink));
    if sa.is_zero() {
        return if sb.is_zero() {
            Some(QuadricHit::All)
        } else {
            sb.sign_known().then_some(QuadricHit::None)
        };
    }
    if !sa.sign_known() {
        return None;
    }
    quotient(-b.approx(), a.approx(), shrink).map(QuadricHit::One)
}

/// The symmetric matrix `Q` of the [module](self), exact in f64.
#[inline(always)]
fn matrix(k: &[f64; 10]) -> [[f64; 4]; 4] {
    let h = |x: f64| 0.5 * x;
    [
        [k[0], h(k[3]), h(k[4]), h(k[6])],
        [h(k[3]), k[1], h(k[5]), h(k[7])],
        [h(k[4]), h(k[5]), k[2], h(k[8])],
        [h(k[6]), h(k[7]), h(k[8]), k[9]],
    ]
}
