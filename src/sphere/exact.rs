//! The exact oracle: `a`, `b`, `c` as exact dyadics, the class from the exact
//! sign of `b² − ac`, and the correctly rounded roots.

use super::{Sphere, SphereHit};
use crate::Ray;
use crate::exact::dyadic::{dot, sub3, vec3};
use crate::exact::{Dyadic, ExactQuadratic, NonFinite, Quadratic};

/// The exact quadratic `a t² + 2b t + c` of a ray and a sphere.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, exact::quadratic}};
/// use glam::Vec3;
/// let q = quadratic(&Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z), &Sphere::new(Vec3::ZERO, 1.0)).unwrap();
/// assert!(q.discriminant().is_zero()); // grazing the top of the sphere
/// ```
pub fn quadratic(ray: &Ray, sphere: &Sphere) -> Result<Quadratic, NonFinite> {
    let o = vec3(ray.origin.to_array())?;
    let d = vec3(ray.dir.to_array())?;
    let c = vec3(sphere.center.to_array())?;
    let r = Dyadic::try_from_f32(sphere.radius)?;
    let f = sub3(&o, &c);
    let a = dot(&d, &d);
    let b2 = dot(&f, &d).mul_pow2(1);
    let cc = &dot(&f, &f) - &(&r * &r);
    Ok(Quadratic::new(a, b2, cc))
}

/// The exact answer, or [`NonFinite`] when an input is NaN or infinite.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit, exact::intersect}};
/// use glam::Vec3;
/// let s = Sphere::new(Vec3::ZERO, 1.0);
/// let r = Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z);
/// assert_eq!(intersect(&r, &s), Ok(SphereHit::Tangent(5.0)));
/// ```
pub fn intersect(ray: &Ray, sphere: &Sphere) -> Result<SphereHit, NonFinite> {
    Ok(classify(&quadratic(ray, sphere)?))
}

/// The sphere result of an exact [`quadratic`] (so a caller that needs both
/// computes the quadratic once).
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit, exact}};
/// use glam::Vec3;
/// let q = exact::quadratic(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), &Sphere::new(Vec3::ZERO, 1.0)).unwrap();
/// assert_eq!(exact::classify(&q), SphereHit::Two(4.0, 6.0));
/// ```
pub fn classify(q: &Quadratic) -> SphereHit {
    match q.solve() {
        // α = 0 only for d = 0, which is not a line.
        ExactQuadratic::None | ExactQuadratic::All => SphereHit::None,
        ExactQuadratic::One(t) => SphereHit::Tangent(t),
        ExactQuadratic::Two(t0, t1) => SphereHit::Two(t0, t1),
    }
}
