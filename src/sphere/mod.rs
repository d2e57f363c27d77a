//! Ray–sphere intersection.
//!
//! # The derivation, as corrected
//!
//! With `f = o − C`, putting `p = o + t d` into `|p − C|² = R²` gives
//!
//! ```text
//! a t² + 2 b t + c = 0,   a = d·d,   b = f·d,   c = f·f − R².
//! ```
//!
//! A common hand derivation gets this far (often with a sign slip in one
//! component of `f`), then goes wrong in three places:
//!
//! * it writes the discriminant as `M = (d·f)² − d²·f² + R²`, missing the
//!   factor `d·d` on `R²`. The quarter discriminant is `Δ = b² − a c = b² −
//!   a(f·f) + a R²`, and `M` equals it only when `|d| = 1`. The code is correct for
//!   directions of any length;
//! * its case analysis ties the class to the signs of `t₁, t₂` and so leaves
//!   out a ray origin inside the sphere (`t₀ < 0 < t₁`) and a sphere behind
//!   the ray (`t₀ ≤ t₁ < 0`). Here the result is over the whole line, `t ∈ ℝ`:
//!   `Δ < 0` none, `Δ = 0` tangent, `Δ > 0` two roots, whatever their signs;
//!   [`crate::hit::Intersection::nearest`] then picks what a ray tracer wants;
//! * `t = (−b ± √Δ)/a` cancels catastrophically for the root nearer the
//!   origin when `|b| ≫ √Δ` (a far, small sphere).
//!
//! A zero direction is not a line: [`SphereHit::None`]. The radius enters
//! only as `R²`, so `−R` is the same sphere.
//!
//! # Accuracy
//!
//! [`reference::intersect`](mod@reference) and [`x4`] return the exact class
//! and both roots correctly rounded to `f32`, for every finite input. The
//! [filter](stages) evaluates the quadratic in f64 with the error bound
//! derived there and certifies what it decides; what it leaves (a near or
//! exact tangent, a root near 0 or too close to a rounding boundary) goes
//! to the later stages: exact f64 arithmetic, tighter forms ([`stages`]),
//! two words ([`words`], then the double-word stage), and the exact
//! oracle ([`exact`]) last. The root formulas avoid cancellation as in Ray
//! Tracing Gems ch. 7 (Haines, Günther & Akenine-Möller, *Precision
//! improvements for ray/sphere intersection*): `q = −(b + sign(b)√Δ)`,
//! `t₀ = q/a`, `t₁ = c/q`.
//!
//! [`condition`] and [`condition_at`] give each root's condition number,
//! which the gate uses to judge outside kernels and the reports show.

pub mod exact;
pub mod exactness;
pub mod plain;
pub mod reference;
pub mod stages;
pub mod textbook;
pub mod words;
pub mod x4;

use crate::Ray;
use crate::hit::{Class, Intersection, Roots};
use glam::Vec3;

/// A sphere with centre `center` and radius `radius`.
///
/// ```
/// use rayoracle::sphere::Sphere;
/// use glam::Vec3;
/// let s = Sphere::new(Vec3::ZERO, 2.0);
/// assert_eq!(s.radius, 2.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// The centre `C`.
    pub center: Vec3,
    /// The radius `R` (only `R²` matters).
    pub radius: f32,
}

impl Sphere {
    /// The sphere with this centre and radius.
    ///
    /// ```
    /// use rayoracle::sphere::Sphere;
    /// use glam::Vec3;
    /// assert_eq!(Sphere::new(Vec3::X, 1.0).center, Vec3::X);
    /// ```
    pub const fn new(center: Vec3, radius: f32) -> Sphere {
        Sphere { center, radius }
    }
}

/// The result over the whole line (`t ∈ ℝ`).
///
/// ```
/// use rayoracle::sphere::SphereHit;
/// use rayoracle::hit::Intersection;
/// // Origin inside: one root behind, one ahead.
/// assert_eq!(SphereHit::Two(-1.0, 1.0).nearest(0.0, 10.0), Some(1.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SphereHit {
    /// The line misses the sphere.
    None,
    /// The line touches the sphere at `t` (a double root).
    Tangent(f32),
    /// The line crosses the sphere at `t0 ≤ t1`.
    Two(f32, f32),
}

impl Intersection for SphereHit {
    fn class(&self) -> Class {
        match self {
            SphereHit::None => Class::None,
            SphereHit::Tangent(_) => Class::Tangent,
            SphereHit::Two(..) => Class::Two,
        }
    }
    fn roots(&self) -> Roots {
        match *self {
            SphereHit::None => Roots::none(),
            SphereHit::Tangent(t) => Roots::one(t),
            SphereHit::Two(t0, t1) => Roots::two(t0, t1),
        }
    }
}

/// The inputs in f64, for the condition numbers: `f = o − C`, `d` and `R`.
fn f64_terms(ray: &Ray, s: &Sphere) -> ([f64; 3], [f64; 3], f64) {
    let f = [0, 1, 2].map(|i| ray.origin[i] as f64 - s.center[i] as f64);
    let d = [0, 1, 2].map(|i| ray.dir[i] as f64);
    (f, d, s.radius as f64)
}

/// The componentwise relative condition number of each root (`κ = Σ|xᵢ
/// ∂t/∂xᵢ| / |t|` over all ten inputs), in f64: how many ulps a root moves
/// when every input moves by one relative rounding. Infinite at a tangent.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, condition}};
/// use glam::Vec3;
/// let k = condition(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), &Sphere::new(Vec3::ZERO, 1.0));
/// assert!(k[0] > 1.0 && k[0] < 4.0);
/// // With |d| = 2 and R = 2 the roots are 1.5 and 3.5, and each gets
/// // condition_at's number.
/// use rayoracle::sphere::condition_at;
/// let r = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, 2.0));
/// let s = Sphere::new(Vec3::ZERO, 2.0);
/// assert_eq!(condition(&r, &s), [condition_at(&r, &s, 1.5), condition_at(&r, &s, 3.5)]);
/// // A tangent (Δ = 0 exactly) has no finite condition number.
/// let tangent = Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z);
/// assert_eq!(condition(&tangent, &Sphere::new(Vec3::ZERO, 1.0)), [f64::INFINITY; 2]);
/// // Even where Δ = 0 in f64 but −b/a is inexact, so ∂g/∂t is not 0 there.
/// let tangent = Ray::new(Vec3::new(0.0, 1.0, -3.0), Vec3::new(0.0, 0.0, 0.3));
/// assert_eq!(condition(&tangent, &Sphere::new(Vec3::ZERO, 1.0)), [f64::INFINITY; 2]);
/// ```
pub fn condition(ray: &Ray, s: &Sphere) -> [f64; 2] {
    let (f, d, r) = f64_terms(ray, s);
    let a: f64 = d.iter().map(|x| x * x).sum();
    let b: f64 = (0..3).map(|i| f[i] * d[i]).sum();
    let c: f64 = f.iter().map(|x| x * x).sum::<f64>() - r * r;
    let disc = b * b - a * c;
    if !(disc > 0.0) || a == 0.0 {
        return [f64::INFINITY; 2];
    }
    let sq = disc.sqrt();
    [(-b - sq) / a, (-b + sq) / a].map(|t| condition_at(ray, s, t))
}

/// [`condition`] at a given root `t` (the tests pass the oracle's exact
/// roots, since re-deriving them in f64 can fail where `o − C` is not exact
/// in f64). Infinite at `t = 0`, where no relative bound exists.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, condition_at}};
/// use glam::Vec3;
/// let k = condition_at(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), &Sphere::new(Vec3::ZERO, 1.0), 4.0);
/// assert!(k > 1.0 && k < 4.0);
/// // By hand, o = (0, 0, −4), d = (0, 0, 2), C = (0, 0, 1), R = 2 at the
/// // root t = 1.5: p = f + t d = (0, 0, −2), so the o, C, d and R terms are
/// // 16, 4, 12 and 8, over |∂g/∂t|·t = 8·1.5.
/// let r = Ray::new(Vec3::new(0.0, 0.0, -4.0), Vec3::new(0.0, 0.0, 2.0));
/// let s = Sphere::new(Vec3::Z, 2.0);
/// assert_eq!(condition_at(&r, &s, 1.5), 40.0 / 12.0);
/// assert_eq!(condition_at(&r, &s, f64::INFINITY), f64::INFINITY);
/// assert_eq!(condition_at(&r, &s, f64::NAN), f64::INFINITY);
/// ```
pub fn condition_at(ray: &Ray, s: &Sphere, t: f64) -> f64 {
    if t == 0.0 || !t.is_finite() {
        return f64::INFINITY;
    }
    let (f, d, r) = f64_terms(ray, s);
    let o = [0, 1, 2].map(|i| ray.origin[i] as f64);
    let cc = [0, 1, 2].map(|i| s.center[i] as f64);
    // Implicit differentiation of g(t) = |f + t d|² − R² = 0:
    // ∂t/∂x = −(∂g/∂x)/(∂g/∂t), ∂g/∂t = 2 (f + t d)·d.
    let p = [0, 1, 2].map(|i| f[i] + t * d[i]);
    let gt = 2.0 * (0..3).map(|i| p[i] * d[i]).sum::<f64>();
    let mut sum = 0.0;
    for i in 0..3 {
        sum += (o[i] * 2.0 * p[i]).abs(); // ∂g/∂oᵢ = 2pᵢ
        sum += (cc[i] * 2.0 * p[i]).abs(); // ∂g/∂Cᵢ = −2pᵢ
        sum += (d[i] * 2.0 * p[i] * t).abs(); // ∂g/∂dᵢ = 2pᵢ t
    }
    sum += (r * 2.0 * r).abs(); // ∂g/∂R = −2R
    sum / (gt.abs() * t.abs())
}
