//! The textbook sphere: the hand derivation with its algebra corrected, solved by
//! the classic quadratic formula in plain `f32`.
//!
//! **A baseline for `rayoracle report`, not an oracle and not for
//! production.** It is what a typical user writes once the derivation's slips are
//! fixed (the `d·d` factor on `R²`, the sign typo in the z term, the class
//! over the whole line), with no numerical care:
//!
//! ```text
//! f = o − C,  a = d·d,  b = 2 f·d,  c = f·f − R²,  disc = b² − 4ac
//! t = (−b ± √disc) / 2a
//! ```
//!
//! It exists so that the report can show what the reference's Ray Tracing
//! Gems ch. 7 formulation ([`super::reference`](mod@super::reference), see
//! the [module docs](super)) buys, measured against [`super::exact`]. Where
//! it goes wrong, as any form of the classic formula does:
//!
//! * **a far, small sphere**: `b²` and `4ac` are both about `4|f|⁴` and
//!   cancel, so the discriminant, and with it the class, is lost once
//!   their rounding errors, a few `2⁻²⁴|f|²`, reach `R²`: `|f|/R` of a few
//!   thousand (the example on [`intersect`] misclassifies
//!   a plain hit at `10⁴` as a tangent);
//! * **a root near 0** (the origin close to the surface, `c ≈ 0`):
//!   `√disc ≈ |b|`, so one of `−b ± √disc` cancels, and that root keeps its
//!   absolute accuracy but loses its relative accuracy;
//! * `b²` and `4ac` overflow once `|f|·|d|` passes about `10¹⁹`, and
//!   underflow for tiny inputs.
//!
//! Even easy cases lose a little: for a unit sphere 5 away, `b² − 4ac`
//! cancels by about `|f|²/R² = 25`, and `tests/variants.rs` measures roots up
//! to 15 ulps off (the reference: 0).

use super::{Sphere, SphereHit};
use crate::Ray;

/// Intersects a line with a sphere by `t = (−b ± √(b² − 4ac))/2a` in plain
/// `f32`: `a = 0` (no line) and `disc < 0` give [`SphereHit::None`],
/// `disc = 0` gives `Tangent(−b/2a)`, and otherwise `Two` with the smaller
/// root first. A NaN discriminant falls through to `Two(NaN, NaN)`.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit, exact, textbook::intersect}};
/// use glam::Vec3;
/// let unit = Sphere::new(Vec3::ZERO, 1.0);
/// let r = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, 2.0));
/// assert_eq!(intersect(&r, &unit), SphereHit::Two(2.0, 3.0));
/// // R = 1 at a distance of 10⁴: f·f − R² = 10⁸ − 1 rounds to 10⁸, so
/// // b² − 4ac = 4·10⁸ − 4·10⁸ = 0 and a clean hit comes out as a tangent.
/// let far = Ray::new(Vec3::new(0.0, 0.0, -1e4), Vec3::Z);
/// assert_eq!(exact::intersect(&far, &unit), Ok(SphereHit::Two(9999.0, 10001.0)));
/// assert_eq!(intersect(&far, &unit), SphereHit::Tangent(1e4));
/// // R = 2, |d| = 2: a = 4, b = −20, c = 21, b² − 4ac = 64, all exact.
/// let two = Sphere::new(Vec3::ZERO, 2.0);
/// assert_eq!(intersect(&r, &two), SphereHit::Two(1.5, 3.5));
/// let miss = Ray::new(Vec3::new(0.0, 5.0, -5.0), Vec3::Z);
/// assert_eq!(intersect(&miss, &unit), SphereHit::None);
/// ```
pub fn intersect(ray: &Ray, sphere: &Sphere) -> SphereHit {
    let f = ray.origin - sphere.center;
    let d = ray.dir;
    let a = d.dot(d);
    let b = 2.0 * f.dot(d);
    let c = f.dot(f) - sphere.radius * sphere.radius;
    let disc = b * b - 4.0 * a * c;
    if a == 0.0 || disc < 0.0 {
        SphereHit::None
    } else if disc == 0.0 {
        SphereHit::Tangent(-b / (2.0 * a))
    } else {
        // a > 0 and √disc ≥ 0, and rounding is monotone: already ascending.
        let s = disc.sqrt();
        SphereHit::Two((-b - s) / (2.0 * a), (-b + s) / (2.0 * a))
    }
}
