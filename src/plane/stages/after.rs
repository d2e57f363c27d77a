//! The plane's later stages: what runs after the [filter](super) leaves
//! a line undecided, before the exact oracle.

use crate::num::certify::{SLACK, U};
use crate::num::dd::{Acc, Approx, quotient, two_sum};
use crate::num::tracked::Tracked;
use crate::plane::PlaneHit;

/// The tight stage: the filter's `num` and bound `E_num`, over `den`
/// summed exactly. The products `pᵢ = dᵢnᵢ` of f32 values are exact in
/// f64, and two TwoSums and a third on their errors write `den = Σpᵢ` as
/// `h + l + r` exactly:
///
/// * `(s₁, e₁) = TwoSum(p₀, p₁)`, `(s₂, e₂) = TwoSum(s₁, p₂)`, so `den =
///   s₂ + e₁ + e₂`;
/// * `(l, r) = TwoSum(e₁, e₂)` and `(h, l') = TwoSum(s₂, l)`, so `den = h +
///   l' + r`, and `h` is within `E_den = |l'| + |r|` of it.
///
/// A line near parallel to the plane is where the filter's `E_den = 4u
/// m_den` is too wide for the quotient; here `E_den` is of the order of
/// `u|den|` however much `Σpᵢ` cancels. `h = 0` with `r = 0` is an exact
/// zero (where `h` is 0, `s₂ = −l` exactly and `l' = 0`), so the line is
/// parallel, and off the plane if `|n̂um| > E_num`; in the plane if
/// `num`, computed again with every operation checked to be exact
/// ([`Tracked`]), is 0 (the in-plane lines of small-integer and dyadic
/// data), and off it if that exact `num` is not. A hit, where `|h| >
/// 2E_den`, has its root `n̂um/h` certified by [`quotient`] with the
/// filter's `E_num = 8u m_num` and this `E_den`. Every bound is widened by
/// `1 + 2⁻³⁰` and multiplied by `shrink`. `None` where the class or the
/// root is undecided: a root that cancels in `num`, a line that may lie in
/// the plane.
///
/// ```
/// use rayoracle::plane::{PlaneHit, stages::{filter, tight}};
/// // d·n = (1 + 2⁻²³)(1 − 2⁻²³) − 1 = −2⁻⁴⁶ cancels 47 bits; the root is 2⁴⁶.
/// let e = 2f64.powi(-23);
/// let (o, d, a, n) = ([0.0; 3], [1.0 + e, -1.0, 0.0], [1.0, 0.0, 0.0], [1.0 - e, 1.0, 0.0]);
/// assert_eq!(tight(o, d, a, n, 1.0), Some(PlaneHit::Hit(-(2f32.powi(46) - 2f32.powi(23)))));
/// // Parallel, 1 off the plane.
/// let h = tight([0.0; 3], [1.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, -1.0, 1.0], 1.0);
/// assert_eq!(h, Some(PlaneHit::Parallel));
/// // In the plane: d·n = 1 − 1 and (a − o)·n = 3 − 3.
/// let h = tight([0.0, 0.0, 3.0], [1.0, 1.0, 0.0], [3.0, 0.0, 0.0], [1.0, -1.0, 1.0], 1.0);
/// assert_eq!(h, Some(PlaneHit::InPlane));
/// ```
#[inline(always)]
pub fn tight(o: [f64; 3], d: [f64; 3], a: [f64; 3], n: [f64; 3], shrink: f64) -> Option<PlaneHit> {
    let (s1, e1) = two_sum(d[0] * n[0], d[1] * n[1]);
    let (s2, e2) = two_sum(s1, d[2] * n[2]);
    let (l, r) = two_sum(e1, e2);
    let (h, l2) = two_sum(s2, l);
    let e_den = (l2.abs() + r.abs()) * SLACK;
    let wn = [0, 1, 2].map(|i| (a[i] - o[i]) * n[i]);
    let num = wn[0] + wn[1] + wn[2];
    let e_num = 8.0 * U * (wn[0].abs() + wn[1].abs() + wn[2].abs()) * SLACK;
    if h == 0.0 && r == 0.0 {
        if num.abs() > e_num * shrink {
            return Some(PlaneHit::Parallel);
        }
        // In the plane or just off it: `num` again, proving itself exact.
        let mut x = Tracked::new();
        // Not `map`: a closure holding `&mut x` is not inlined.
        let w = [x.sub(a[0], o[0]), x.sub(a[1], o[1]), x.sub(a[2], o[2])];
        let num = x.dot(w, n);
        return x.exact().then_some(if num == 0.0 {
            PlaneHit::InPlane
        } else {
            PlaneHit::Parallel
        });
    }
    if h.abs() <= 2.0 * e_den * shrink {
        return None;
    }
    let x = |v: f64, e: f64| Approx { v, e };
    quotient(x(num, e_num), x(h, e_den), shrink).map(PlaneHit::Hit)
}

/// The double-word stage ([`crate::num::dd`]): `num = Σaᵢnᵢ − Σoᵢnᵢ` and
/// `den = Σdᵢnᵢ` as sums of products of two f32 values, each exact in f64
/// and a multiple of `2⁻²⁹⁸` (so no TwoProduct is needed), accumulated in
/// double words ([`Acc`]). Where no low word rounded, both sums are exact,
/// and so are their signs and zeros: this settles the in-plane and parallel
/// lines whatever the data, small integers or not. Otherwise their bounds
/// decide or nothing does. Splitting `(a − o)·n` into `a·n − o·n` costs
/// nothing in accuracy here: the bound of a double word is of the order of
/// `u²` times the magnitudes, so a cancellation of up to about 2⁵⁰ still
/// leaves the root a relative error far below `u`. The root `num/den` is
/// certified from the leading words with `|lo| + err` as their bounds
/// ([`quotient`]). Every bound is multiplied by `shrink`.
///
/// ```
/// use rayoracle::plane::{PlaneHit, stages::double_word};
/// // d·n = 0.1f32·0.3f32 − 0.3f32·0.1f32 = 0 exactly; a − o rounds in f64.
/// let (x, y) = (0.1f32 as f64, 0.3f32 as f64);
/// let (o, a) = ([1e-30f32 as f64, 0.0, 0.0], [1e30f32 as f64, 0.0, 0.0]);
/// assert_eq!(double_word(o, [x, y, 0.0], a, [y, -x, 0.0], 1.0), Some(PlaneHit::Parallel));
/// // d·n = 1 − 1 = 0 term by term, and (a − o)·n = 0: in the plane.
/// let h = double_word([0.0, 0.0, 1.0], [1.0, 1.0, 0.0], [0.0; 3], [1.0, -1.0, 0.0], 1.0);
/// assert_eq!(h, Some(PlaneHit::InPlane));
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
        num.add(a[i] * n[i]);
        num.add(-(o[i] * n[i]));
        den.add(d[i] * n[i]);
    }
    // The bounds as derived; `shrink` scales each once, where it decides:
    // the classes through `shrunk`, the root in `quotient`.
    let (num, den) = (num.finish(), den.finish());
    let (sn, sd) = (num.shrunk(shrink), den.shrunk(shrink));
    if sd.is_zero() {
        return if sn.is_zero() {
            Some(PlaneHit::InPlane)
        } else {
            sn.sign_known().then_some(PlaneHit::Parallel)
        };
    }
    if !sd.sign_known() {
        return None;
    }
    quotient(num.approx(), den.approx(), shrink).map(PlaneHit::Hit)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tight stage on lines with `d·n = 0` exactly (`d = (1, −1, 0)`,
    /// `n = (1, 1, 1)`): in the plane, where `n̂um`, summed again with every
    /// operation checked, is 0; and off it by `12u` in `n̂um` against `m̂_num
    /// ≈ 2`, with `a − o` rounding (`1 − 10⁻³⁰`), so that only the bound
    /// `E_num = 8u m̂_num` decides: parallel where the bound is halved, left
    /// undecided at 1.
    #[test]
    fn the_tight_stage_settles_exact_zeros_of_d_dot_n() {
        let (d, n) = ([1.0, -1.0, 0.0], [1.0; 3]);
        let on = tight([0.0, 0.0, 3.0], d, [1.0, -1.0, 3.0], n, 1.0);
        assert_eq!(on, Some(PlaneHit::InPlane));
        let o = [f64::from(1e-30f32), 0.0, 0.0];
        let a = [1.0, -1.0, 12.0 * U];
        assert_eq!(tight(o, d, a, n, 0.5), Some(PlaneHit::Parallel));
        assert_eq!(tight(o, d, a, n, 1.0), None);
        // The same line off the plane by 1: parallel at any factor.
        let a = [1.0, -1.0, 1.0];
        assert_eq!(tight(o, d, a, n, 1.0), Some(PlaneHit::Parallel));
    }
}
