//! The per-pixel filter, written once over [`Real`] and run at `f64` by
//! [`super::Camera::ray`] and at [`F64x4`](crate::num::real::F64x4) by the
//! four-pixel functions in [`super::x4`].
//!
//! Component `i` is `cᵢ = dᵢ + nx·bxᵢ + ny·byᵢ` with `bxᵢ = xᵢ/resX` and
//! `byᵢ = yᵢ/resY` the exact basis per unit of the pixel numerators
//! ([`super::exact`]). The camera stores `b̂ = bxᵢ(1 + δ₁)`,
//! `|δ₁| ≤ δ = 2⁻⁴⁴` ([`BASIS_REL`]), nonzero only where `bxᵢ` is and then
//! at least `2⁻¹⁰⁰⁰` (or NaN, which certifies nothing), so with `|nx| ≥ 1`
//! nothing below underflows. In f64, `t = nx·b̂` is within
//! `α|t|`, `α = (δ + u)(1 + 2⁻⁴³)`, of `nx·bxᵢ` (`u = 2⁻⁵³`; the factor
//! covers `1/(1 − δ)` and `1 + u`), likewise `s`; `p = dᵢ + t` and
//! `r = p + s` add roundings of at most `u|p|` and `u|r|` (a subnormal sum
//! is exact). With `|p| ≤ (|dᵢ| + |t|)(1 + u)` and `|r| ≤ S(1 + u)²`,
//! `S = |dᵢ| + |t| + |s|`,
//!
//! ```text
//! |r − cᵢ| ≤ α(|t| + |s|) + u|p| + u|r| ≤ (δ + 3u)(1 + 2⁻⁴³)·S
//! ```
//!
//! and [`certify`](crate::num::certify::certify)'s test decides the
//! rounding from it (the two roundings of `S` itself are in [`SLACK`]).
//! That test adds `2⁻⁵¹|r|` for the roundings of the enclosure's own ends;
//! with `|r| ≤ S(1 + u)²` it is folded into the constant per unit of `S`
//! as `2⁻⁵⁰`. Where `t` and `s` are both exactly 0, so are `nx·bxᵢ` and
//! `ny·byᵢ`, and `cᵢ = dᵢ` (its sign of zero kept, as
//! [`super::exact`] defines). Elsewhere an undecided lane goes to
//! [`super::exact`].

use crate::num::Real;
use crate::num::certify::{
    SLACK, U, denormals_are_zero, flush_prone, needs_probe, subnormals_work,
};

/// The relative error of the stored basis per unit, `2⁻⁴⁴`: the f64
/// basis of [`super::basis`] (which refuses a component its bound does not
/// keep within this), or the oracle's enclosure at
/// [`FIRST_BITS`](super::exact::FIRST_BITS)` + 8 = 56` bits approximated
/// in f64 (within `2⁻⁵⁰`, [`super::tan::Fx::to_f64`]).
pub const BASIS_REL: f64 = 1.0 / (1u64 << 44) as f64;

/// `(δ + 3u)(1 + 2⁻⁴³)`, widened by [`SLACK`], and `2⁻⁵⁰` for the ends of
/// the enclosure: the bound per unit of `S`.
const K: f64 =
    (BASIS_REL + 3.0 * U) * (1.0 + 1.0 / (1u64 << 43) as f64) * SLACK + 1.0 / (1u64 << 50) as f64;

/// `(value, decided)` for one component: see the module docs. `shrink`
/// scales the bound (1 for the kernels; tests shrink it to show it is
/// needed).
///
/// ```
/// use rayoracle::camera::filter::component;
/// let (r, ok) = component(-1.0f64, 0.25, 0.5, 1.0, 0.0, 1.0);
/// assert!(ok && r == -0.75);
/// // Both terms exactly 0: dᵢ itself, −0 kept.
/// let (r, ok) = component(-0.0f64, 0.25, 0.5, 0.0, 0.0, 1.0);
/// assert!(ok && r.to_bits() == (-0.0f64).to_bits());
/// ```
#[inline(always)]
pub fn component<L: Real>(d: L, bx: L, by: L, nx: L, ny: L, shrink: f64) -> (L, L::Mask) {
    let (t, s) = (nx * bx, ny * by);
    let r = (d + t) + s;
    let ts = t.abs() + s.abs();
    let k = K * shrink;
    let exact = ts.eq(L::splat(0.0));
    let e = (d.abs() + ts) * L::splat(k);
    let ok = exact | L::same_f32(r - e, r + e);
    (L::select(exact, d, r), ok)
}

/// Whether the floating-point environment may have changed a pixel's
/// filtered direction: a subnormal `dir` component where
/// denormals-are-zero reads it as 0 ([`denormals_are_zero`]), or a result
/// that is 0 or subnormal where flush-to-zero may have made it of a
/// subnormal one ([`subnormals_work`]). The filter itself never underflows
/// in f64 (above), so only these two places meet the environment; such a
/// pixel goes to the oracle whole.
///
/// ```
/// use rayoracle::camera::filter::flushed;
/// use rayoracle::num::certify::subnormals_work;
/// assert!(!flushed(&[0.5, 1.0, -1.0], &[0.25, 0.5, -1.0]));
/// assert_eq!(flushed(&[0.5, 1.0, -1.0], &[0.0, 0.5, -1.0]), !subnormals_work());
/// ```
#[inline(always)]
pub fn flushed(dir: &[f32; 3], out: &[f32; 3]) -> bool {
    (denormals_are_zero() && needs_probe(dir, &[])) || (flush_prone(out) && !subnormals_work())
}

/// `2p + 1 − res`, exact in f64.
///
/// ```
/// use rayoracle::camera::filter::numerator;
/// assert_eq!(numerator(0, 4), -3.0);
/// ```
#[inline(always)]
pub fn numerator(p: u32, res: u32) -> f64 {
    (2 * p as i64 + 1 - res as i64) as f64
}

/// `(2p + 1 − res)/res` rounded once to f32: the pixel offset `u` or `v`,
/// for code that wants it as a number (the kernels never round it).
///
/// ```
/// use rayoracle::camera::filter::offset;
/// assert_eq!(offset(0, 4), -0.75);
/// ```
#[inline(always)]
pub fn offset(p: u32, res: u32) -> f32 {
    (2 * p as i64 + 1 - res as i64) as f32 / res as f32
}
