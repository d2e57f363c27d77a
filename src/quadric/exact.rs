//! The exact oracle: α, β, γ as exact dyadics, then the exact quadratic.

use super::{Quadric, QuadricHit};
use crate::Ray;
use crate::exact::dyadic::{sum, vec3};
use crate::exact::{Dyadic, ExactQuadratic, NonFinite, Quadratic};

/// The exact quadratic `α t² + β t + γ` of a ray and a quadric.
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, exact::quadratic}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let q = quadratic(&Ray::new(Vec3::ZERO, Vec3::Z), &cyl).unwrap();
/// // Along the axis from inside: 0t² + 0t − 1 (a sign the normalisation
/// // of Quadratic::new leaves alone when α = β = 0).
/// assert!(q.alpha.is_zero() && q.beta.is_zero() && q.gamma.to_f64() == -1.0);
/// // Across it from x = −5: t² − 10t + 24.
/// let q = quadratic(&Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X), &cyl).unwrap();
/// assert_eq!([q.alpha, q.beta, q.gamma].map(|x| x.to_f64()), [1.0, -10.0, 24.0]);
/// ```
pub fn quadratic(ray: &Ray, quadric: &Quadric) -> Result<Quadratic, NonFinite> {
    let o = vec3(ray.origin.to_array())?;
    let d = vec3(ray.dir.to_array())?;
    let mut k = Vec::with_capacity(10);
    for &c in &quadric.coeffs {
        k.push(Dyadic::try_from_f32(c)?);
    }
    let t = |c: &Dyadic, x: &Dyadic, y: &Dyadic| &(c * x) * y;
    let alpha = [
        t(&k[0], &d[0], &d[0]),
        t(&k[1], &d[1], &d[1]),
        t(&k[2], &d[2], &d[2]),
        t(&k[3], &d[0], &d[1]),
        t(&k[4], &d[0], &d[2]),
        t(&k[5], &d[1], &d[2]),
    ];
    let beta = [
        t(&k[0], &o[0], &d[0]).mul_pow2(1),
        t(&k[1], &o[1], &d[1]).mul_pow2(1),
        t(&k[2], &o[2], &d[2]).mul_pow2(1),
        t(&k[3], &o[0], &d[1]),
        t(&k[3], &d[0], &o[1]),
        t(&k[4], &o[0], &d[2]),
        t(&k[4], &d[0], &o[2]),
        t(&k[5], &o[1], &d[2]),
        t(&k[5], &d[1], &o[2]),
        &k[6] * &d[0],
        &k[7] * &d[1],
        &k[8] * &d[2],
    ];
    let gamma = [
        t(&k[0], &o[0], &o[0]),
        t(&k[1], &o[1], &o[1]),
        t(&k[2], &o[2], &o[2]),
        t(&k[3], &o[0], &o[1]),
        t(&k[4], &o[0], &o[2]),
        t(&k[5], &o[1], &o[2]),
        &k[6] * &o[0],
        &k[7] * &o[1],
        &k[8] * &o[2],
        k[9].clone(),
    ];
    Ok(Quadratic::new(sum(&alpha), sum(&beta), sum(&gamma)))
}

/// The exact answer, or [`NonFinite`] when an input is NaN or infinite.
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit, exact::intersect}};
/// use glam::Vec3;
/// // The paraboloid z = x² + y², hit along its axis: α = 0, one root.
/// let p = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0]);
/// let r = Ray::new(Vec3::new(0.0, 0.0, -2.0), Vec3::Z);
/// assert_eq!(intersect(&r, &p), Ok(QuadricHit::One(2.0)));
/// ```
pub fn intersect(ray: &Ray, quadric: &Quadric) -> Result<QuadricHit, NonFinite> {
    Ok(classify(&quadratic(ray, quadric)?))
}

/// The quadric result of an exact [`quadratic`] (so a caller that needs
/// both computes the quadratic once).
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit, exact}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let q = exact::quadratic(&Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X), &cyl).unwrap();
/// assert_eq!(exact::classify(&q), QuadricHit::Two(4.0, 6.0));
/// ```
pub fn classify(q: &Quadratic) -> QuadricHit {
    match q.solve() {
        ExactQuadratic::None => QuadricHit::None,
        ExactQuadratic::One(t) => QuadricHit::One(t),
        ExactQuadratic::Two(t0, t1) => QuadricHit::Two(t0, t1),
        ExactQuadratic::All => QuadricHit::All,
    }
}
