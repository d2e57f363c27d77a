//! The plane's arithmetic, written once over [`Lane`] and instantiated at
//! `f32` by [`super::reference`](mod@super::reference) and at `f32x4` by [`super::x4`] (see
//! [`crate::sphere::kernel`] for why).

use crate::num::ff::{dot3, dot3_ff};
use crate::num::scale::{Scale, normalized3};
use crate::num::{Ff, Lane};

/// What the classification needs: the leading parts of `d·n` and
/// `(a − o)·n` (only their zero-ness is used) and the root.
#[derive(Clone, Copy, Debug)]
pub struct Parts<L> {
    /// `d·n`, prescaled.
    pub den: L,
    /// `(a − o)·n`, prescaled.
    pub num: L,
    /// `t = ((a − o)·n)/(d·n)` in the caller's units.
    pub t: L,
}

/// Computes [`Parts`] for a line `o + t d` and the plane through `a` with
/// normal `n`.
///
/// ```
/// use rayoracle::plane::kernel::solve;
/// let p = solve([0.0f32, 2.0, 0.0], [1.0, -4.0, 0.0], [0.0; 3], [0.0, 1.0, 0.0]);
/// assert_eq!(p.t, 0.5);
/// ```
#[inline(always)]
pub fn solve<L: Lane>(o: [L; 3], d: [L; 3], a: [L; 3], n: [L; 3]) -> Parts<L> {
    // Exact prescaling: t does not depend on |n|; t ∝ 1/|d|; t ∝ |a − o|.
    let (n, _) = normalized3(n);
    let (d, sd) = normalized3(d);
    let sa = Scale::of_max(&[a[0], a[1], a[2], o[0], o[1], o[2]]);
    let (a, o) = (sa.apply3(a), sa.apply3(o));

    // a − o exactly, then (a − o)·n and d·n in double-word arithmetic.
    let w = [
        Ff::sum(a[0], -o[0]),
        Ff::sum(a[1], -o[1]),
        Ff::sum(a[2], -o[2]),
    ];
    let num = dot3_ff(w, n);
    let den = dot3(d, n);
    Parts {
        den: den.hi,
        num: num.hi,
        t: (num / den).round().ldexp(sa.k - sd.k),
    }
}
