//! The textbook quadric: the hand expansion with its algebra corrected,
//! solved by the usual root formula in plain `f32`.
//!
//! **A baseline for `rayoracle report`, not an oracle and not for
//! production.** It is what a typical user writes once the hand expansion
//! is fixed (`i t d_z` for `o t d_z`, β in one piece; see the
//! [module docs](super)): α, β, γ as plain `f32` sums of plain products, and
//! then the usual
//!
//! ```text
//! t₁,₂ = −β/2α ± √(β²/4α² − γ/α)
//! ```
//!
//! with only the guard a naive user adds, for `α = 0` exactly: the linear
//! root `−γ/β`, or, when `β = 0` too, [`QuadricHit::All`] for `γ = 0` and
//! [`QuadricHit::None`] otherwise. There is deliberately no guard for
//! `α ≈ 0`. It exists so that the report can show what pbrt-v4's `Quadratic`
//! with a proven bound ([`super::reference`](mod@super::reference)) buys,
//! measured against [`super::exact`]. Where it goes wrong:
//!
//! * **α ≈ 0** (a ray nearly parallel to a cylinder's axis, nearly along a
//!   paraboloid's): `β²/4α²` and `γ/α` are huge and nearly equal, and the
//!   root near the origin, `−β/2α + √…`, cancels away (the example on
//!   [`intersect`] is 3·10⁵ ulps off, 18 of its 24 bits); `4α²` underflows
//!   to 0 for `|α| < 10⁻²³`, and the division gives ∞ or NaN;
//! * α, β and γ themselves cancel (γ for an origin near the surface, α for
//!   a direction near an asymptote), with no compensation;
//! * the class comes from a discriminant that carries all of that error.
//!
//! On easy cases it is within a few ulps, but not within one:
//! `tests/variants.rs` measures up to 14 ulps for a unit sphere (as a
//! quadric) 5 away, whose discriminant cancels by about 25, and up to 7 on
//! the `α = 0` branch.

use super::{Quadric, QuadricHit};
use crate::Ray;
use core::ops::{Add, Mul};

/// α, β, γ of the corrected expansion, evaluated term by term, left to
/// right, in whatever float type `T` is: `f32` here, `f64` in
/// [`super::plain`]. `k` is `[A, …, J]`; `2x` is formed as `x + x`.
/// Always inlined: out of line, its arrays pass through memory, written
/// as scalars and read back as vectors, and the stalls on store
/// forwarding made the `f64` baseline take 2.5 times its time in some
/// builds and not in others.
#[inline(always)]
pub(crate) fn coefficients<T>(k: [T; 10], o: [T; 3], d: [T; 3]) -> (T, T, T)
where
    T: Copy + Add<Output = T> + Mul<Output = T>,
{
    let [a, b, c, dd, e, f, g, h, i, j] = k;
    let [ox, oy, oz] = o;
    let [dx, dy, dz] = d;
    let alpha = a * dx * dx + b * dy * dy + c * dz * dz + dd * dx * dy + e * dx * dz + f * dy * dz;
    let squares = a * ox * dx + b * oy * dy + c * oz * dz;
    let beta = squares
        + squares
        + dd * (ox * dy + dx * oy)
        + e * (ox * dz + dx * oz)
        + f * (oy * dz + dy * oz)
        + g * dx
        + h * dy
        + i * dz;
    let gamma = a * ox * ox
        + b * oy * oy
        + c * oz * oz
        + dd * ox * oy
        + e * ox * oz
        + f * oy * oz
        + g * ox
        + h * oy
        + i * oz
        + j;
    (alpha, beta, gamma)
}

/// Intersects a line with a quadric by the usual
/// `t = −β/2α ± √(β²/4α² − γ/α)` in plain `f32`, with the one guard for
/// `α = 0` exactly. The discriminant `β²/4α² − γ/α` classifies: `< 0`
/// [`QuadricHit::None`], `= 0` `One(−β/2α)`, otherwise `Two`, smaller root
/// first. A NaN discriminant falls through to `Two(NaN, NaN)`.
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit, exact, textbook::intersect}};
/// use rayoracle::ulp::ulps;
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let across = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X);
/// assert_eq!(intersect(&across, &cyl), QuadricHit::Two(4.0, 6.0));
/// // Parallel to the axis, on the surface: α = β = γ = 0, caught exactly.
/// let along = Ray::new(Vec3::new(1.0, 0.0, 0.0), Vec3::Z);
/// assert_eq!(intersect(&along, &cyl), QuadricHit::All);
/// // A graze (β²/4α² − γ/α = 25 − 25) and a miss (25 − 28).
/// let graze = Ray::new(Vec3::new(-5.0, 1.0, 0.0), Vec3::X);
/// assert_eq!(intersect(&graze, &cyl), QuadricHit::One(5.0));
/// let miss = Ray::new(Vec3::new(-5.0, 2.0, 0.0), Vec3::X);
/// assert_eq!(intersect(&miss, &cyl), QuadricHit::None);
/// // α ≈ 0: 10⁻⁶x² + x + 0.7 = 0 has roots near −10⁶ and −0.7. The one
/// // near −0.7 is −β/2α + √… ≈ −500000 + 499999.3, and next to 5·10⁵ an
/// // f32 has steps of 1/32: 3·10⁵ ulps off.
/// let q = Quadric::new([1e-6, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.7]);
/// let r = Ray::new(Vec3::ZERO, Vec3::X);
/// assert_eq!(exact::intersect(&r, &q), Ok(QuadricHit::Two(-999999.3, -0.70000046)));
/// assert_eq!(intersect(&r, &q), QuadricHit::Two(-999999.25, -0.71875));
/// assert!(ulps(-0.70000046, -0.71875) > 300_000);
/// ```
pub fn intersect(ray: &Ray, quadric: &Quadric) -> QuadricHit {
    let (alpha, beta, gamma) =
        coefficients(quadric.coeffs, ray.origin.to_array(), ray.dir.to_array());
    if alpha == 0.0 {
        return if beta != 0.0 {
            QuadricHit::One(-gamma / beta)
        } else if gamma == 0.0 {
            QuadricHit::All
        } else {
            QuadricHit::None
        };
    }
    let h = -beta / (2.0 * alpha);
    let disc = beta * beta / (4.0 * alpha * alpha) - gamma / alpha;
    if disc < 0.0 {
        QuadricHit::None
    } else if disc == 0.0 {
        QuadricHit::One(h)
    } else {
        // √disc > 0, and rounding is monotone: already ascending.
        let s = disc.sqrt();
        QuadricHit::Two(h - s, h + s)
    }
}
