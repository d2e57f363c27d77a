//! The sphere's arithmetic, written once over [`Lane`] and instantiated at
//! `f32` by [`super::reference`](mod@super::reference) and at `f32x4` by [`super::x4`]: the two
//! paths run the same IEEE operations in the same order, so they agree bit
//! for bit on every input (see [`crate::num`]). Only the classification —
//! branches on one path, masks on the other — is written twice.

use crate::num::ff::{dot3, dot3_ff, norm2_ff};
use crate::num::scale::{Scale, normalized3};
use crate::num::{Ff, Lane};

/// Everything the classification needs, already unscaled to the caller's
/// units: `a = d·d` (only its zero-ness is used), `disc = aΔ` (only its
/// sign), the tangent root `−b/a`, and the two roots sorted `t0 ≤ t1`
/// (NaN roots are left in computation order).
#[derive(Clone, Copy, Debug)]
pub struct Parts<L> {
    /// The leading part of `a = d·d` after prescaling.
    pub a: L,
    /// The leading part of `aΔ = (aR)² − |a f − b d|²` after prescaling.
    pub disc: L,
    /// `−b/a`, the double root.
    pub tangent: L,
    /// The smaller root.
    pub t0: L,
    /// The larger root.
    pub t1: L,
}

/// Computes [`Parts`] for a line `o + t d` and a sphere `(c, r)`.
///
/// ```
/// use rayoracle::sphere::kernel::solve;
/// let p = solve([0.0f32, 0.0, -5.0], [0.0, 0.0, 1.0], [0.0; 3], 1.0);
/// assert_eq!((p.t0, p.t1), (4.0, 6.0));
/// ```
#[inline(always)]
pub fn solve<L: Lane>(o: [L; 3], d: [L; 3], c: [L; 3], r: L) -> Parts<L> {
    // Prescale d into [1, 2) (roots scale by 2^-kd) and the positions so that
    // o − C cannot overflow (roots scale by 2^ks).
    let (d, sd) = normalized3(d);
    let ss = Scale::of_max(&[o[0], o[1], o[2], c[0], c[1], c[2], r]);
    let (o, c, r) = (ss.apply3(o), ss.apply3(c), ss.apply(r));

    // f = o − C exactly, then rescale f and R together into [1, 2).
    let f = [
        Ff::sum(o[0], -c[0]),
        Ff::sum(o[1], -c[1]),
        Ff::sum(o[2], -c[2]),
    ];
    let sf = Scale::of_max(&[f[0].hi, f[1].hi, f[2].hi, r]);
    let f = f.map(|x| Ff {
        hi: sf.apply(x.hi),
        lo: sf.apply(x.lo),
    });
    let r = sf.apply(r);

    let a = dot3(d, d);
    let b = dot3_ff(f, d);
    // Compensated c = |f|² − R² (exact f, exact squares, double-word sum).
    let cq = norm2_ff(f) - Ff::square(r);

    // RTG ch. 7, division-free: aΔ = (aR)² − |a f − b d|².
    let l = [
        a * f[0] - b.scale(d[0]),
        a * f[1] - b.scale(d[1]),
        a * f[2] - b.scale(d[2]),
    ];
    let ar = a.scale(r);
    let disc = ar * ar - norm2_ff(l);

    let e = ss.k + sf.k - sd.k;
    let tangent = (-(b / a)).round().ldexp(e);
    // RTG ch. 7: q = −(b + sign(b)·√Δ), t₀ = c/q, t₁ = q/a.
    let q = -(b + (disc / a).sqrt().with_sign_of(b.hi));
    let u0 = (cq / q).round().ldexp(e);
    let u1 = (q / a).round().ldexp(e);
    Parts {
        a: a.hi,
        disc: disc.hi,
        tangent,
        t0: L::select_gt(u0, u1, u1, u0),
        t1: L::select_gt(u0, u1, u0, u1),
    }
}
