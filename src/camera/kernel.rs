//! The per-pixel filter, written once over [`Real`] and run at `f64` by
//! [`super::Camera::ray`] and at [`F64x4`](crate::num::real::F64x4) by the
//! four-pixel functions in [`super::x4`].
//!
//! Component `i` is `cᵢ = dᵢ + nx·bxᵢ + ny·byᵢ` with `bxᵢ = xᵢ/resX` and
//! `byᵢ = yᵢ/resY` the exact basis per unit of the pixel numerators
//! ([`super::exact`]). The camera stores `b̂ = bxᵢ(1 + δ₁)`,
//! `|δ₁| ≤ 2⁻⁵²` ([`BASIS_REL`]), nonzero only where `bxᵢ` is and then at
//! least `2⁻¹⁰⁰⁰` (or NaN, which certifies nothing), so with `|nx| ≥ 1`
//! nothing below underflows. In f64, `t = nx·b̂` is within
//! `|t|(2⁻⁵² + 2⁻⁵³)(1 + 2⁻⁵⁰)` of `nx·bxᵢ`, likewise `s`, and
//! `r = (dᵢ + t) + s` adds two roundings, each at most `u` of its result
//! (`u = 2⁻⁵³`; a subnormal sum is exact). So
//!
//! ```text
//! |r − cᵢ| ≤ (|t| + |s|)(2⁻⁵² + 2⁻⁵³)(1 + 2⁻⁵⁰) + u·|dᵢ + t| + u·|r|
//! ```
//!
//! and [`certify`] decides the rounding from it. Where `t` and `s` are
//! both exactly 0, so are `nx·bxᵢ` and `ny·byᵢ`, and `cᵢ = dᵢ` (its sign of
//! zero kept, as [`super::exact`] defines). Elsewhere an undecided lane goes
//! to [`super::exact`].

use crate::num::Real;
use crate::num::certify::{SLACK, U, certify};

/// The relative error of the stored basis per unit, `2⁻⁵²`: an enclosure
/// at 96 bits or more, approximated in f64 (see [`super::tan::Fx::to_f64`]).
pub const BASIS_REL: f64 = f64::EPSILON;

/// `(value, decided)` for one component: see the module docs. `shrink`
/// scales the bound (1 for the kernels; tests shrink it to show it is
/// needed).
///
/// ```
/// use rayoracle::camera::kernel::component;
/// let (r, ok) = component(-1.0f64, 0.25, 0.5, 1.0, 0.0, 1.0);
/// assert!(ok && r == -0.75);
/// // Both terms exactly 0: dᵢ itself, −0 kept.
/// let (r, ok) = component(-0.0f64, 0.25, 0.5, 0.0, 0.0, 1.0);
/// assert!(ok && r.to_bits() == (-0.0f64).to_bits());
/// ```
#[inline(always)]
pub fn component<L: Real>(d: L, bx: L, by: L, nx: L, ny: L, shrink: f64) -> (L, L::Mask) {
    let zero = L::splat(0.0);
    let (t, s) = (nx * bx, ny * by);
    let p = d + t;
    let r = p + s;
    let terms = L::splat((BASIS_REL + U) * (1.0 + 2f64.powi(-50)) * SLACK * shrink);
    let a = (t.abs() + s.abs()) * terms + p.abs() * L::splat(U * SLACK * shrink);
    let exact = t.eq(zero) & s.eq(zero);
    let ok = exact | certify(r, L::splat(U * SLACK * shrink), a);
    (L::select(exact, d, r), ok)
}

/// `2p + 1 − res`, exact in f64.
///
/// ```
/// use rayoracle::camera::kernel::numerator;
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
/// use rayoracle::camera::kernel::offset;
/// assert_eq!(offset(0, 4), -0.75);
/// ```
#[inline(always)]
pub fn offset(p: u32, res: u32) -> f32 {
    (2 * p as i64 + 1 - res as i64) as f32 / res as f32
}
