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
//!   [`certify`], and every part widened by
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

use super::PlaneHit;
use crate::num::certify::{SLACK, U, certify, div, quotient_bound};
use crate::num::dd::{Acc, quotient, two_sum};
use crate::num::real::Real;
use crate::num::tracked::Tracked;

/// The filter's result: the certified classes and the root with its bound.
#[derive(Clone, Copy, Debug)]
pub struct Filtered<L: Real> {
    /// Certified: one hit (`d·n ≠ 0`); `t` still needs
    /// [`certify`].
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
    let x = sums(o, d, a, n, shrink);
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

/// [`filter`] with the root's bound in a form that waits less on the
/// quotient, for the x4 kernels: certified only where `x = E_den/|d̂en| ≤
/// 2⁻¹⁰`, which leaves out lines within about `2⁻⁴¹` of parallel (those go
/// to the scalar stages). There `1/(1 − x) ≤ 1 + 2⁻⁹ = G`, and the
/// [module](self)'s bound, with `x|t̂| ≤ E_den|n̂um|/d̂en²` (to the
/// roundings of `t̂` and of the reciprocal, which the slack covers),
/// becomes `e = 6u|t̂| + G·|1/d̂en|·(E_den|n̂um|·|1/d̂en| + E_num)`: after
/// the reciprocal, three operations rather than the ten of
/// [`quotient_bound`].
///
/// The product `E_den|n̂um|/d̂en²` may underflow. A nonzero `n̂um` is at
/// least `2⁻³⁵⁰` (a sum of f64 values of at least `2⁻²⁹⁸`) and `|d̂en| ≤
/// 2²⁵⁸`, so a nonzero `t̂` is at least `2⁻⁶⁰⁸` and `6u|t̂|` at least
/// `2⁻⁶⁵⁹`: what an underflow loses (below `2⁻¹⁰²²`) is far inside the
/// slack of `e`. A zero `n̂um` makes `E_num` and the product 0 exactly.
///
/// ```
/// use rayoracle::num::certify::certify;
/// use rayoracle::plane::stages::{filter, filter_direct};
/// let (o, d, a, n) = ([0.0; 3], [0.1, 0.0, 3.0], [0.0, 0.0, 1.0], [0.0, 0.3, 1.0]);
/// let (f, g) = (filter::<f64>(o, d, a, n, 1.0), filter_direct::<f64>(o, d, a, n, 1.0));
/// assert!(g.hit && g.t == f.t && certify(g.t, g.r, g.a));
/// // d·n = (1 + 2⁻²³)(1 − 2⁻²³) − 1 = −2⁻⁴⁶, parallel but for 2⁻⁴⁷ of
/// // the terms: the class is certain, the quotient is left to `filter`.
/// let e = 2f64.powi(-23);
/// let (d, n) = ([1.0 + e, -1.0, 0.0], [1.0 - e, 1.0, 0.0]);
/// assert!(filter::<f64>(o, d, a, n, 1.0).hit && !filter_direct::<f64>(o, d, a, n, 1.0).hit);
/// ```
#[inline(always)]
pub fn filter_direct<L: Real>(
    o: [L; 3],
    d: [L; 3],
    a: [L; 3],
    n: [L; 3],
    shrink: f64,
) -> Filtered<L> {
    let x = sums(o, d, a, n, shrink);
    let g = L::splat((1.0 + 2f64.powi(-9)) * SLACK);
    let ia = x.inv.abs();
    Filtered {
        hit: x.den.abs().gt(x.e_den * L::splat(1024.0)),
        parallel: x.parallel,
        in_plane: x.in_plane,
        t: x.t,
        r: L::splat(6.0 * U * shrink),
        a: ia * (x.e_den * g * x.num.abs() * ia + x.e_num * g),
    }
}

/// What both filters share: the sums, their bounds, the certified
/// parallel classes, and the quotient.
struct Sums<L: Real> {
    num: L,
    den: L,
    e_num: L,
    e_den: L,
    parallel: L::Mask,
    in_plane: L::Mask,
    inv: L,
    t: L,
}

#[inline(always)]
fn sums<L: Real>(o: [L; 3], d: [L; 3], a: [L; 3], n: [L; 3], shrink: f64) -> Sums<L> {
    let k = |x: f64| L::splat(x * U * shrink);
    let zero = L::splat(0.0);
    let w = [a[0] - o[0], a[1] - o[1], a[2] - o[2]];
    let wn = [w[0] * n[0], w[1] * n[1], w[2] * n[2]];
    let dn = [d[0] * n[0], d[1] * n[1], d[2] * n[2]];
    let num = wn[0] + wn[1] + wn[2];
    let den = dn[0] + dn[1] + dn[2];
    let m_num = wn[0].abs() + wn[1].abs() + wn[2].abs();
    let m_den = dn[0].abs() + dn[1].abs() + dn[2].abs();
    let (e_num, e_den) = (k(8.0) * m_num, k(4.0) * m_den);
    let den_zero = m_den.eq(zero);
    let inv = L::splat(1.0) / den;
    Sums {
        num,
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

/// The second stage: the filter's arithmetic tracked for exactness
/// ([`Tracked`]). Where no operation rounded, `num` and `den` are exact, so
/// the class follows from their signs, and the root `num/den` rounds once,
/// within `u|t|` (certified with `2u`). `None` where an operation rounded
/// or the root sits next to an f32 rounding boundary.
///
/// ```
/// use rayoracle::plane::{PlaneHit, stages::tracked};
/// // d·n = 1 − 1 = 0 term by term, and (a − o)·n = 0: in the plane.
/// let h = tracked([0.0, 0.0, 1.0], [1.0, 1.0, 0.0], [0.0; 3], [1.0, -1.0, 0.0]);
/// assert_eq!(h, Some(PlaneHit::InPlane));
/// // a − o = 1 − 2⁻⁶⁰ rounds: not for this stage.
/// assert_eq!(tracked([2f64.powi(-60), 0.0, 0.0], [1.0; 3], [1.0, 0.0, 0.0], [1.0; 3]), None);
/// ```
pub fn tracked(o: [f64; 3], d: [f64; 3], a: [f64; 3], n: [f64; 3]) -> Option<PlaneHit> {
    let mut x = Tracked::new();
    let w = [x.sub(a[0], o[0]), x.sub(a[1], o[1]), x.sub(a[2], o[2])];
    let num = x.dot(w, n);
    let den = x.dot(d, n);
    if !x.exact() {
        return None;
    }
    if den == 0.0 {
        return Some(if num == 0.0 {
            PlaneHit::InPlane
        } else {
            PlaneHit::Parallel
        });
    }
    let t = div(num, den);
    certify(t, 2.0 * U, 0.0).then_some(PlaneHit::Hit(t as f32))
}

/// The double-word stage ([`crate::num::dd`]): `a − o` split exactly into
/// two words by TwoSum, then `num = Σ(aᵢ − oᵢ)nᵢ` and `den = Σdᵢnᵢ` as
/// sums of exact products (multiples of `2⁻²⁹⁸`, so TwoProduct is exact).
/// Where no low word rounded, both are exact, and so are their signs and
/// zeros; otherwise their bounds decide or nothing does. The root
/// `num/den` is certified from the leading words with `|lo| + err` as
/// their bounds ([`quotient`]). Every bound is multiplied by `shrink`.
///
/// ```
/// use rayoracle::plane::{PlaneHit, stages::{double_word, tracked}};
/// // d·n = 0.1f32·0.3f32 − 0.3f32·0.1f32 = 0 exactly; a − o rounds in f64.
/// let (x, y) = (0.1f32 as f64, 0.3f32 as f64);
/// let (o, a) = ([1e-30f32 as f64, 0.0, 0.0], [1e30f32 as f64, 0.0, 0.0]);
/// assert_eq!(tracked(o, [x, y, 0.0], a, [y, -x, 0.0]), None);
/// assert_eq!(double_word(o, [x, y, 0.0], a, [y, -x, 0.0], 1.0), Some(PlaneHit::Parallel));
/// ```
pub fn double_word(
    o: [f64; 3],
    d: [f64; 3],
    a: [f64; 3],
    n: [f64; 3],
    shrink: f64,
) -> Option<PlaneHit> {
    let (mut num, mut den) = (Acc::new(), Acc::new());
    for i in 0..3 {
        let (wh, wl) = two_sum(a[i], -o[i]);
        num.add_prod(wh, n[i]);
        num.add_prod(wl, n[i]);
        den.add(d[i] * n[i]);
    }
    let (num, den) = (num.finish(shrink), den.finish(shrink));
    if den.is_zero() {
        return if num.is_zero() {
            Some(PlaneHit::InPlane)
        } else {
            num.sign_known().then_some(PlaneHit::Parallel)
        };
    }
    if !den.sign_known() {
        return None;
    }
    quotient(num.approx(), den.approx(), shrink).map(PlaneHit::Hit)
}
