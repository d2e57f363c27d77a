//! The per-pixel filter, on four f64 lanes: the three components of one
//! pixel in [`super::Camera::ray`], one component of four pixels in
//! [`super::x4`].
//!
//! Component `i` is `cᵢ = dᵢ + nx·bxᵢ + ny·byᵢ` with `bxᵢ = xᵢ/resX` and
//! `byᵢ = yᵢ/resY` the exact basis per unit of the pixel numerators
//! ([`super::exact`]). The camera stores `b̂ = bxᵢ(1 + δ₁)`,
//! `|δ₁| ≤ δ = 2⁻⁴⁴` ([`BASIS_REL`]), nonzero only where `bxᵢ` is and then
//! at least `2⁻¹⁰⁰⁰` (or NaN where smaller; such a camera sends every
//! pixel through [`exact`] and the oracle for that component), so with
//! `|nx| ≥ 1` nothing below underflows. In f64, `t = nx·b̂` is within
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
//! rounding from it.
//! That test adds `2⁻⁵¹|r|` for the roundings of the enclosure's own ends;
//! with `|r| ≤ S(1 + u)²` it is folded into the constant per unit of `S`
//! as `2⁻⁵⁰`: [`K`].
//!
//! The pixel never computes `S`. With `|t| ≤ |nx|·|b̂x|(1 + u)`,
//! `S ≤ (|dᵢ| + |nx|·|b̂x| + |ny|·|b̂y|)(1 + u)`, so the camera keeps the
//! terms `E = [K′|dᵢ| + 2⁻¹⁰⁰⁰, K′|b̂x| + 2⁻¹⁰⁰⁰, K′|b̂y| + 2⁻¹⁰⁰⁰]`
//! ([`bound_terms`], `K′ = K·SLACK`; a basis term that is 0 stays 0) and
//! a pixel takes `e = (E₀ + |nx|·E₁) + |ny|·E₂` ([`bound`]): two products
//! and two sums of non-negative terms, which with the `(1 + u)` above and
//! the rounding of `K′|·|` lose at most `(1 + u)⁶` relatively, inside the
//! second `SLACK`. Rounding is monotone, so `e` at the largest `|nx|` and
//! `|ny|` of the image bounds every pixel in it: the camera keeps that
//! one value per component and computes `e` only for a pixel outside.
//!
//! Every operand above is 0 or at least `2⁻¹⁰⁰⁰` in magnitude (`dᵢ` is
//! widened from its bits, [`widen_bits`]): denormals-are-zero finds no
//! subnormal to read as 0, and nothing underflows but a sum that cancels
//! to below `2⁻¹⁰²²`, which flush-to-zero may make 0. That moves `r` by
//! less than `2⁻¹⁰²²` per sum, far inside the `2⁻¹⁰⁰⁰` in `E₀`, which also
//! keeps `e > 0`.
//!
//! Where both ends of `[r − e, r + e]` round to the same f32, `r` lies
//! between them and that f32 is the answer; the low end's rounding is
//! returned, and `r`'s is never computed. Since `e > 0`, an enclosure of
//! a component that is exactly 0 straddles it and is never certified:
//! that happens only where `nx·bxᵢ = ny·byᵢ = 0` and `dᵢ = ±0`, and
//! there [`exact`] gives `dᵢ` with its sign of zero, as [`super::exact`]
//! defines. A result that is 0 or subnormal is checked against
//! flush-to-zero ([`flushed`]). Elsewhere an undecided component goes to
//! [`super::exact`].

use crate::num::certify::{SLACK, U, flush_prone, subnormals_work, widen_bits};
use crate::num::real::{F64x4, Real, Real4};
use wide::{f32x4, i32x4};

/// The relative error of the stored basis per unit, `2⁻⁴⁴`: the f64
/// basis of [`super::basis`] (which refuses a component its bound does not
/// keep within this), or the oracle's enclosure at
/// [`FIRST_BITS`](super::exact::FIRST_BITS)` + 8 = 56` bits approximated
/// in f64 (within `2⁻⁵⁰`, [`super::tan::Fx::to_f64`]).
pub const BASIS_REL: f64 = 1.0 / (1u64 << 44) as f64;

/// `(δ + 3u)(1 + 2⁻⁴³)`, widened by [`SLACK`], and `2⁻⁵⁰` for the ends of
/// the enclosure: the bound per unit of `S`.
pub const K: f64 =
    (BASIS_REL + 3.0 * U) * (1.0 + 1.0 / (1u64 << 43) as f64) * SLACK + 1.0 / (1u64 << 50) as f64;

/// `2⁻¹⁰⁰⁰`, added to every nonzero bound term: it keeps `e > 0` and
/// every term normal, and covers a sum flushed to 0.
const FLOOR: f64 = f64::from_bits(((1023 - 1000) as u64) << 52);

/// A camera's bound terms for component `i` ([module docs](self)): `[K′|dᵢ|
/// + 2⁻¹⁰⁰⁰, K′|b̂x| + 2⁻¹⁰⁰⁰, K′|b̂y| + 2⁻¹⁰⁰⁰]`, a basis term that is 0
/// left 0. `dᵢ` is read from its bits, whatever the environment.
///
/// ```
/// use rayoracle::camera::filter::{K, bound_terms};
/// let [e0, e1, e2] = bound_terms(-2.0, 0.5, 0.0);
/// assert!(e0 > 2.0 * K && e1 > 0.5 * K && e2 == 0.0);
/// assert!(bound_terms(0.0, 1.0, 1.0)[0] > 0.0);
/// ```
pub fn bound_terms(d: f32, bx: f64, by: f64) -> [f64; 3] {
    let k = K * SLACK;
    let term = |b: f64| if b == 0.0 { 0.0 } else { k * b.abs() + FLOOR };
    [
        k * widen_bits(d.to_bits()).abs() + FLOOR,
        term(bx),
        term(by),
    ]
}

/// The bound `e` for numerators `n = [nx, ny]` from a camera's
/// [`bound_terms`] `t`: `(t₀ + |nx|·t₁) + |ny|·t₂`.
///
/// ```
/// use rayoracle::camera::filter::{bound, bound_terms};
/// let t = bound_terms(1.0, 0.25, 0.5);
/// assert!(bound([3.0, -1.0], t) > bound([1.0, 1.0], t));
/// ```
#[inline(always)]
pub fn bound<L: Real>(n: [L; 2], t: [L; 3]) -> L {
    (t[0] + n[0].abs() * t[1]) + n[1].abs() * t[2]
}

/// One component for four lanes ([module docs](self)): `dᵢ`, `[b̂x, b̂y]`,
/// the numerators `[nx, ny]` and the bound `e` give the rounding of
/// `r − e` and the lanes (−1) where it equals that of `r + e`, bit for
/// bit: there it is the correctly rounded component. A NaN operand must
/// be kept out: two NaN ends would match.
///
/// ```
/// use rayoracle::camera::filter::{bound, bound_terms, component};
/// use rayoracle::num::real::{F64x4, Real};
/// let s = <F64x4 as Real>::splat;
/// let n = [F64x4::from([1.0, -1.0, 3.0, 0.0]), s(0.0)];
/// let e = bound(n, bound_terms(-1.0, 0.25, 0.5).map(s));
/// let (c, ok) = component(s(-1.0), [s(0.25), s(0.5)], n, e);
/// assert_eq!(c.to_array(), [-0.75, -1.25, -0.25, -1.0]);
/// assert_eq!(ok.to_array(), [-1; 4]);
/// // A component that is exactly 0 is never decided here.
/// let e = bound(n, bound_terms(0.0, 0.25, 0.5).map(s));
/// let (c, ok) = component(s(0.0), [s(0.25), s(0.5)], n, e);
/// assert_eq!(ok.to_array()[3], 0);
/// ```
#[inline(always)]
pub fn component(d: F64x4, b: [F64x4; 2], n: [F64x4; 2], e: F64x4) -> (f32x4, i32x4) {
    let r = (d + n[0] * b[0]) + n[1] * b[1];
    let (lo, hi) = ((r - e).narrow(), (r + e).narrow());
    let bits = |x: f32x4| -> i32x4 { wide::bytemuck::cast(x) };
    (lo, bits(lo).simd_eq(bits(hi)))
}

/// Whether component `i` is exactly `dᵢ`: `nx·bxᵢ = ny·byᵢ = 0`, read
/// from the stored basis per unit (0 exactly where the real one is; a
/// product of nonzero factors is at least `2⁻¹⁰⁰⁰`, and a NaN is never 0).
///
/// ```
/// use rayoracle::camera::filter::exact;
/// assert!(exact([0.0, 0.5], [3.0, 0.0]));
/// assert!(!exact([0.25, 0.5], [3.0, 0.0]) && !exact([f64::NAN, 0.0], [1.0, 1.0]));
/// ```
#[inline(always)]
pub fn exact(b: [f64; 2], n: [f64; 2]) -> bool {
    n[0] * b[0] == 0.0 && n[1] * b[1] == 0.0
}

/// The lanes of `x` that are 0 or subnormal, by their bits: −1 there, 0
/// elsewhere.
///
/// ```
/// use rayoracle::camera::filter::tiny;
/// use wide::f32x4;
/// let m = tiny(f32x4::from([0.0, -1e-40, 1.0, f32::INFINITY]));
/// assert_eq!(m.to_array(), [-1, -1, 0, 0]);
/// ```
#[inline(always)]
pub fn tiny(x: f32x4) -> i32x4 {
    let bits: i32x4 = wide::bytemuck::cast(x);
    (bits & i32x4::splat(0x7f80_0000)).simd_eq(i32x4::ZERO)
}

/// Whether flush-to-zero may have changed a pixel's filtered direction:
/// a component that is 0 or subnormal, where subnormals are flushed
/// ([`subnormals_work`]). The filter's own arithmetic meets neither
/// flag (above), so only its narrowing to f32 does; such a pixel goes to
/// the oracle, but for its exact components.
///
/// ```
/// use rayoracle::camera::filter::flushed;
/// use rayoracle::num::certify::subnormals_work;
/// assert!(!flushed(&[0.25, 0.5, -1.0]));
/// assert_eq!(flushed(&[0.0, 0.5, -1.0]), !subnormals_work());
/// ```
#[inline(always)]
pub fn flushed(out: &[f32; 3]) -> bool {
    flush_prone(out) && !subnormals_work()
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

/// [`numerator`] for four pixels, in f64 lanes, computed in vector
/// registers: `p` converts exactly (offset by `2³¹` to fit `i32`), and the
/// products and sums of integers below `2³⁴` are exact.
///
/// ```
/// use rayoracle::camera::filter::{numerator, numerators};
/// let p = [0, 3, 7, u32::MAX];
/// assert_eq!(numerators(p, 8).to_array(), p.map(|p| numerator(p, 8)));
/// ```
#[inline(always)]
pub fn numerators(p: [u32; 4], res: u32) -> F64x4 {
    let biased = wide::u32x4::from(p) ^ wide::u32x4::splat(0x8000_0000);
    let x = F64x4::from_i32(wide::bytemuck::cast(biased)) + F64x4::splat(2f64.powi(31));
    x * F64x4::splat(2.0) + F64x4::splat(1.0 - f64::from(res))
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
