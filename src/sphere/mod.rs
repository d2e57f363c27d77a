//! Ray–sphere intersection (seed Ex. 1.2b).
//!
//! # The derivation, as corrected
//!
//! With `f = o − C`, putting `p = o + t d` into `|p − C|² = R²` gives
//!
//! ```text
//! a t² + 2 b t + c = 0,   a = d·d,   b = f·d,   c = f·f − R².
//! ```
//!
//! The seed gets here (up to a sign typo in the z term), then slips:
//!
//! * its discriminant `M = (d·f)² − d²·f² + R²` is missing the factor `d·d`
//!   on `R²`. The quarter discriminant is `Δ = b² − a c = b² − a(f·f) + a R²`,
//!   and the seed's `M` equals it only when `|d| = 1`. The code is correct for
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
//! # The numerically careful form ([`reference`](mod@reference))
//!
//! * **Ray Tracing Gems ch. 7** (Haines, Günther & Akenine-Möller, *Precision
//!   improvements for ray/sphere intersection*): compute the discriminant from
//!   the closest-approach vector `l = f − (b/a) d` as `Δ = a (R² − |l|²)`,
//!   which does not cancel for a far sphere as `b² − ac` does; then
//!   `q = −(b + sign(b)√Δ)`, `t₀ = c/q`, `t₁ = q/a`. Here it is used in a
//!   division-free form, `a Δ = (aR)² − |a f − b d|²`, so that an exactly
//!   tangent input gives exactly 0 whenever both squares are exact in
//!   double-word arithmetic, i.e. while `a·R` (after prescaling) needs at
//!   most 24 bits: true for small-integer data (the property tests use
//!   Pythagorean quadruples up to 64); beyond that a tangent may come out as
//!   a near-miss or a near-double root, inside the documented band.
//! * **Compensated `c = |f|² − R²`** for origins close to the surface: `f` is
//!   formed exactly (TwoSum of `o` and `−C`), and `|f|² − R²` in double-word
//!   arithmetic from exact squares.
//! * Everything is double-word (see [`crate::num::ff`]), after exact
//!   power-of-two prescaling of `d` and of the positions, so `R = 10⁷` at a
//!   distance of `10⁷`, `|d|` from `10⁻¹⁰` to `10¹⁰`, and subnormal inputs
//!   stay in range.
//!
//! # Accuracy
//!
//! * **Classification** matches the exact one wherever the exact
//!   `|aΔ| > band` ([`band`]): `2⁻⁴⁰` times the magnitudes the two terms
//!   `(aR)²` and `|af − bd|²` are made of.
//! * **Roots**: within `1 + κ·2⁻¹⁸` ulps of the correctly rounded root
//!   ([`ROOT_ULPS`]), where `κ` is the root's condition number
//!   ([`condition`]); for every well-conditioned root that is 1 ulp, and the
//!   tests find 0 in almost all cases.

pub mod double;
pub mod exact;
pub mod kernel;
pub mod reference;
pub mod textbook;
pub mod x4;

use crate::Ray;
use crate::hit::{Intersection, Roots};
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
    fn class(&self) -> &'static str {
        match self {
            SphereHit::None => "none",
            SphereHit::Tangent(_) => "tangent",
            SphereHit::Two(..) => "two",
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

/// The documented root error bound, in ulps, for condition number `kappa`.
///
/// ```
/// assert_eq!(rayoracle::sphere::ROOT_ULPS(2.0).floor(), 1.0);
/// ```
#[allow(non_snake_case)]
pub fn ROOT_ULPS(kappa: f64) -> f64 {
    1.0 + kappa * 2f64.powi(-18)
}

/// Exact-valued helpers in f64 for the bounds: `(a, b, c, aΔ)` and the band.
fn f64_terms(ray: &Ray, s: &Sphere) -> ([f64; 3], [f64; 3], f64) {
    let f = [0, 1, 2].map(|i| ray.origin[i] as f64 - s.center[i] as f64);
    let d = [0, 1, 2].map(|i| ray.dir[i] as f64);
    (f, d, s.radius as f64)
}

/// The accuracy domain of [`reference::intersect`](mod@reference): with the
/// kernel's prescaling (`d` and `(f, R)` by the power of two of their
/// largest magnitudes), `Σ|fᵢdᵢ|` is 0 or within `[2⁻⁵⁰, 2⁵⁰]`
/// ([`crate::num::scale::in_range`]); `a = d·d` and `|f|² + R²` are in range
/// by construction. What the prescaling of `(o, C, R)` rounds away must be
/// negligible against `max(|f|, R)` ([`crate::num::scale::crush_loss`]). Outside it `b = f·d` and its square lose the exactness
/// of their products to underflow, and the bounds are not promised.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, in_domain}};
/// use glam::Vec3;
/// let s = Sphere::new(Vec3::ZERO, 1.0);
/// assert!(in_domain(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), &s));
/// assert!(!in_domain(&Ray::new(Vec3::new(1.0, 0.0, 1e-20), Vec3::Z), &s));
/// // Far but not too far: f/|f| is what must be in range.
/// assert!(in_domain(&Ray::new(Vec3::new(0.0, 0.0, -1e20), Vec3::Z), &s));
/// // f·d/|f| = 3e-20 < 2⁻⁵⁰: b underflows its exactness.
/// assert!(!in_domain(&Ray::new(Vec3::new(1e20, 3.0, 0.0), Vec3::Y), &s));
/// // Beside 1e30, the prescaling rounds 1e-20 to 0. Whether it is the
/// // origin's, the centre's or the radius's, that is all of max(|f|, R):
/// let big = Vec3::new(1e30, 0.0, 0.0);
/// let tiny = Vec3::new(1e30, 0.0, 1e-20);
/// assert!(!in_domain(&Ray::new(big, Vec3::Z), &Sphere::new(tiny, 1e-20)));
/// assert!(!in_domain(&Ray::new(tiny, Vec3::Z), &Sphere::new(big, 0.0)));
/// assert!(!in_domain(&Ray::new(big, Vec3::Z), &Sphere::new(big, 1e-20)));
/// ```
pub fn in_domain(ray: &Ray, s: &Sphere) -> bool {
    use crate::num::scale::{Scale, crush_loss, in_range, negligible};
    // What prescaling (o, C, R) rounds away must be negligible against
    // max(|f|, R), the scale of everything computed from f = o − C.
    let (o, c) = (ray.origin.to_array(), s.center.to_array());
    let ss = Scale::of_max(&[o[0], o[1], o[2], c[0], c[1], c[2], s.radius]);
    let loss: f64 = (0..3)
        .map(|i| crush_loss(o[i], ss) + crush_loss(c[i], ss))
        .sum::<f64>()
        + crush_loss(s.radius, ss);
    let (f, d, r) = f64_terms(ray, s);
    let m = f.iter().fold(r.abs(), |m, x| m.max(x.abs()));
    if m == 0.0 {
        return true;
    }
    if !negligible(loss, m * 2f64.powi(-ss.k)) {
        return false;
    }
    let d = d.map(|x| x * 2f64.powi(-Scale::of_max(&ray.dir.to_array()).k));
    let f = f.map(|x| x / m);
    in_range((0..3).map(|i| (f[i] * d[i]).abs()).sum(), -50, 50)
}

/// The classification band: the reference's class is only promised to match
/// the exact one when the exact `|aΔ|` exceeds this.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, band}};
/// use glam::Vec3;
/// let b = band(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), &Sphere::new(Vec3::ZERO, 1.0));
/// assert!(b < 1e-10);
/// // By hand, for f = (0, 0, −5), d = (0, 0, 2), R = 2: a = 4, Σ|fᵢdᵢ| = 10,
/// // ((aR)² + (4·5 + 10·2)²)·2⁻⁴⁰.
/// let b = band(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, 2.0)), &Sphere::new(Vec3::ZERO, 2.0));
/// assert_eq!(b, (64.0 + 1600.0) * 2f64.powi(-40));
/// ```
pub fn band(ray: &Ray, s: &Sphere) -> f64 {
    let (f, d, r) = f64_terms(ray, s);
    let a: f64 = d.iter().map(|x| x * x).sum();
    let babs: f64 = (0..3).map(|i| (f[i] * d[i]).abs()).sum();
    let l: f64 = (0..3)
        .map(|i| (a * f[i]).abs() + (babs * d[i]).abs())
        .map(|x| x * x)
        .sum();
    ((a * r).powi(2) + l) * 2f64.powi(-40)
}

/// `aΔ = (aR)² − |a f − b d|²` in f64 (a sign-faithful approximation where it
/// is far from the band; the tests use the exact value).
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, scaled_discriminant}};
/// use glam::Vec3;
/// let r = Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z);
/// assert_eq!(scaled_discriminant(&r, &Sphere::new(Vec3::ZERO, 1.0)), 0.0);
/// // Through the centre with |d| = 2, R = 2: a = 4, a f − b d = 0, aΔ = (aR)².
/// let r = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, 2.0));
/// assert_eq!(scaled_discriminant(&r, &Sphere::new(Vec3::ZERO, 2.0)), 64.0);
/// ```
pub fn scaled_discriminant(ray: &Ray, s: &Sphere) -> f64 {
    let (f, d, r) = f64_terms(ray, s);
    let a: f64 = d.iter().map(|x| x * x).sum();
    let b: f64 = (0..3).map(|i| f[i] * d[i]).sum();
    let l: f64 = (0..3).map(|i| a * f[i] - b * d[i]).map(|x| x * x).sum();
    (a * r).powi(2) - l
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
