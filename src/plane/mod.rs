//! Ray–plane intersection (seed Ex. 1.2a).
//!
//! # The derivation, as corrected
//!
//! The plane through `a` with normal `n` is `(p − a)·n = 0`. Putting the ray
//! `p = o + t d` in gives `(o − a)·n + t (d·n) = 0`, so
//!
//! * `d·n ≠ 0`: one hit, `t = ((a − o)·n) / (d·n)`;
//! * `d·n = 0` and `(a − o)·n ≠ 0`: the ray is parallel and off the plane;
//! * `d·n = 0` and `(a − o)·n = 0`: the ray lies in the plane, every `t`.
//!
//! The seed has these three cases right. Two things it does not say, which the
//! code handles:
//!
//! * **A zero normal** makes every ray satisfy `0 = 0`; it is classified
//!   [`PlaneHit::InPlane`] by the same rule (both dot products are 0). `eval`
//!   reports it as such; scenes reject it.
//! * **Range.** `(a − o)·n` and `d·n` are computed after exact power-of-two
//!   scaling of `n`, `d` and the pair `(a, o)`, which leaves `t` unchanged up
//!   to a known power of two, so subnormal normals and planes at `10³⁰` are
//!   handled, not just moderate inputs.
//!
//! # Accuracy ([`reference`](mod@reference))
//!
//! `a − o` is formed exactly (TwoSum), both dot products are double-word
//! (exact products, AccurateDWPlusDW sums) and the quotient is a double-word
//! division rounded once. So:
//!
//! * **Classification** matches the exact one unless
//!   `|d·n| ≤ 2⁻⁴⁴ Σ|dᵢnᵢ|` (the *parallel band*; near-parallel rays are
//!   ill-conditioned, [`band`] computes it). Exact zeros that come from exact
//!   products, such as axis-aligned or small-integer inputs, are exact.
//! * **The root** is within 1 ulp of the correctly rounded `t` wherever
//!   `κ = Σ|dᵢnᵢ| / |d·n| + Σ|(aᵢ−oᵢ)nᵢ| / |(a−o)·n|` is below `2¹⁸`; in
//!   general within `1 + κ·2⁻¹⁸` ulps ([`ROOT_ULPS`], asserted by the tests).

pub mod double;
pub mod exact;
pub mod kernel;
pub mod reference;
pub mod textbook;
pub mod x4;

use crate::hit::{Intersection, Roots};
use glam::Vec3;

/// A plane through `point` with normal `normal` (any length).
///
/// ```
/// use rayoracle::plane::Plane;
/// use glam::Vec3;
/// let ground = Plane::new(Vec3::ZERO, Vec3::Y);
/// assert_eq!(ground.normal, Vec3::Y);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// A point `a` on the plane.
    pub point: Vec3,
    /// The normal `n`; need not be unit length.
    pub normal: Vec3,
}

impl Plane {
    /// The plane through `point` with normal `normal`.
    ///
    /// ```
    /// use rayoracle::plane::Plane;
    /// use glam::Vec3;
    /// assert_eq!(Plane::new(Vec3::ONE, Vec3::Z).point, Vec3::ONE);
    /// ```
    pub const fn new(point: Vec3, normal: Vec3) -> Plane {
        Plane { point, normal }
    }
}

/// The result over the whole line (`t ∈ ℝ`).
///
/// ```
/// use rayoracle::plane::PlaneHit;
/// use rayoracle::hit::Intersection;
/// assert_eq!(PlaneHit::Hit(-2.0).nearest(0.0, f32::INFINITY), None);
/// assert_eq!(PlaneHit::InPlane.nearest(0.5, 1.0), Some(0.5));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PlaneHit {
    /// One intersection at `t`.
    Hit(f32),
    /// `d·n = 0`, the ray is off the plane: no intersection.
    Parallel,
    /// `d·n = 0` and the origin is on the plane: every `t`.
    InPlane,
}

impl Intersection for PlaneHit {
    fn class(&self) -> &'static str {
        match self {
            PlaneHit::Hit(_) => "hit",
            PlaneHit::Parallel => "parallel",
            PlaneHit::InPlane => "in_plane",
        }
    }
    fn roots(&self) -> Roots {
        match *self {
            PlaneHit::Hit(t) => Roots::one(t),
            _ => Roots::none(),
        }
    }
    fn is_everywhere(&self) -> bool {
        matches!(self, PlaneHit::InPlane)
    }
}

/// The documented root error bound of [`reference::intersect`], in ulps, for
/// a root of condition number `kappa` (see the module docs).
///
/// ```
/// assert_eq!(rayoracle::plane::ROOT_ULPS(1.0).floor(), 1.0);
/// ```
#[allow(non_snake_case)]
pub fn ROOT_ULPS(kappa: f64) -> f64 {
    1.0 + kappa * 2f64.powi(-18)
}

/// The parallel band: the reference's classification is only promised to
/// match the exact one when `|d·n| > band(ray, plane)`.
///
/// ```
/// use rayoracle::{Ray, plane::{Plane, band}};
/// use glam::Vec3;
/// let b = band(&Ray::new(Vec3::ZERO, Vec3::X), &Plane::new(Vec3::ZERO, Vec3::ONE));
/// assert!(b > 0.0 && b < 1e-12);
/// ```
pub fn band(ray: &Ray, plane: &Plane) -> f64 {
    let s: f64 = (0..3)
        .map(|i| (ray.dir[i] as f64 * plane.normal[i] as f64).abs())
        .sum();
    s * 2f64.powi(-44)
}

use crate::Ray;

/// The accuracy domain of [`reference::intersect`](mod@reference): with the
/// kernel's own prescaling (`n`, `d` and the pair `(a, o)` each by the power
/// of two of its largest magnitude, `a` and `o` rounded as the kernel rounds
/// them), the sums `Σ|dᵢnᵢ|` and `Σ|(aᵢ − oᵢ)nᵢ|` are each 0 or within
/// `[2⁻⁷⁰, 2¹⁰⁰]` ([`crate::num::scale::in_range`]): a term too small for an
/// exact product is then negligible against its sum. What the prescaling of
/// `(a, o)` rounds away must be negligible against `Σ|(aᵢ − oᵢ)nᵢ|`
/// ([`crate::num::scale::crush_loss`]). Outside it the class and
/// root bounds are not promised: a component `2¹²⁶` times smaller than its
/// group's largest is rounded away by the prescaling, and matters when it
/// meets the only non-zero component of the normal.
///
/// ```
/// use rayoracle::{Ray, plane::{Plane, in_domain}};
/// use glam::Vec3;
/// let p = Plane::new(Vec3::ZERO, Vec3::Z);
/// assert!(in_domain(&Ray::new(Vec3::new(0.0, -5.0, 2.0), Vec3::Z), &p));
/// assert!(!in_domain(&Ray::new(Vec3::new(0.0, -5.0, 2.3e-41), Vec3::Z), &p));
/// // An origin exactly on the plane is in it: w·n is exactly 0.
/// let tiny = Plane::new(Vec3::new(1.0, 0.0, 1e-30), Vec3::Z);
/// assert!(in_domain(&Ray::new(Vec3::new(0.0, 0.0, 1e-30), Vec3::ONE), &tiny));
/// // Beside 1e30 the prescaling rounds 1e-20 to 0, and what it rounds away
/// // is all of Σ|(aᵢ − oᵢ)nᵢ| (which is 0 exactly): outside.
/// let far = Plane::new(Vec3::new(1e30, 1.0, 1e-20), Vec3::new(0.0, 1.0, 1.0));
/// assert!(!in_domain(&Ray::new(Vec3::new(0.0, 1.0, 1e-20), Vec3::Y), &far));
/// ```
pub fn in_domain(ray: &Ray, plane: &Plane) -> bool {
    use crate::num::scale::{Scale, crush_loss, in_range, negligible};
    let n = plane.normal.to_array();
    let d = ray.dir.to_array();
    let (a, o) = (plane.point.to_array(), ray.origin.to_array());
    let up = |v: [f32; 3]| -> [f64; 3] {
        let s = Scale::of_max(&v);
        v.map(|x| x as f64 * 2f64.powi(-s.k))
    };
    let (n, d) = (up(n), up(d));
    let sa = Scale::of_max(&[a[0], a[1], a[2], o[0], o[1], o[2]]);
    let w = [0, 1, 2].map(|i| sa.apply(a[i]) as f64 - sa.apply(o[i]) as f64);
    let w_exact = [0, 1, 2].map(|i| (a[i] as f64 - o[i] as f64) * 2f64.powi(-sa.k));
    let s_num: f64 = (0..3).map(|i| (w[i] * n[i]).abs()).sum();
    let s_exact: f64 = (0..3).map(|i| (w_exact[i] * n[i]).abs()).sum();
    let loss: f64 = (0..3)
        .map(|i| (crush_loss(a[i], sa) + crush_loss(o[i], sa)) * n[i].abs())
        .sum();
    let s_den: f64 = (0..3).map(|i| (d[i] * n[i]).abs()).sum();
    negligible(loss, s_exact) && in_range(s_num, -70, 100) && in_range(s_den, -70, 100)
}
