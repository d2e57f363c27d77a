//! collision's ray casts (collision 0.20.1, on cgmath 0.17), wrapped as
//! rayoracle kernels and surveyed against the exact oracle.
//!
//! * [`sphere_cast`]: `Continuous<Ray3>::intersection` of the bounding
//!   volume `collision::Sphere { center, radius }`;
//! * [`plane_cast`]: `Continuous<Ray3>::intersection` of a `Plane` built
//!   by `Plane::from_point_normal(p, n̂)`, the documented constructor;
//! * [`plane_cast_negated`]: the same cast on `Plane::new(n̂, −p·n̂)`, the
//!   sign convention the cast itself assumes (and `Plane::from_points`
//!   builds), to measure its accuracy apart from the sign.
//!
//! The casts answer a point, not a distance; the survey recovers `t` as
//! `(p − o)·d / d·d` in f64 from the point's f32 coordinates. The ray's
//! direction must be normalised (`Ray3`'s docs), so the survey feeds unit
//! directions, and the plane normal is normalised in f32 (`n` is "a unit
//! vector").

use cgmath::{InnerSpace, Point3, Vector3};
use collision::prelude::*;
use collision::{Plane as CPlane, Ray3, Sphere as CSphere};
use rayoracle::Ray;
use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
use rayoracle::plane::Plane;
use rayoracle::sphere::Sphere;
use survey_kit::Surveyed;

fn p3(x: glam::Vec3) -> Point3<f32> {
    Point3::new(x.x, x.y, x.z)
}

fn v3(x: glam::Vec3) -> Vector3<f32> {
    Vector3::new(x.x, x.y, x.z)
}

/// The ray, if its direction is a unit vector (as `Ray3` requires); the
/// gate's normalising leaves a zero direction zero.
fn ray3(ray: &Ray) -> Option<Ray3<f32>> {
    (ray.dir != glam::Vec3::ZERO).then(|| Ray3::new(p3(ray.origin), v3(ray.dir)))
}

/// The `t` of a point answered on `ray`, in f64 from its f32 coordinates.
fn t_of(ray: &Ray, p: Point3<f32>) -> f32 {
    let (o, d) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
    let p = glam::DVec3::new(p.x.into(), p.y.into(), p.z.into());
    ((p - o).dot(d) / d.dot(d)) as f32
}

/// `collision::Sphere { center, radius }.intersection(&Ray3::new(o, d))`,
/// as a distance.
///
/// ```
/// use collision_gate::sphere_cast;
/// use glam::Vec3;
/// use rayoracle::{Ray, sphere::Sphere};
/// let s = Sphere::new(Vec3::new(0.0, 0.0, 5.0), 1.0);
/// assert_eq!(sphere_cast(&Ray::new(Vec3::ZERO, Vec3::Z), &s), Some(4.0));
/// // From inside, facing away from the center: no hit.
/// assert_eq!(sphere_cast(&Ray::new(Vec3::new(0.0, 0.0, 5.5), Vec3::Z), &s), None);
/// ```
pub fn sphere_cast(ray: &Ray, s: &Sphere) -> Option<f32> {
    let sphere = CSphere {
        center: p3(s.center),
        radius: s.radius,
    };
    sphere.intersection(&ray3(ray)?).map(|p| t_of(ray, p))
}

/// `Plane::from_point_normal(p, n̂).intersection(&Ray3::new(o, d))`, as a
/// distance.
///
/// ```
/// use collision_gate::plane_cast;
/// use glam::Vec3;
/// use rayoracle::{Ray, plane::Plane};
/// // Through the origin the sign of d does not matter:
/// let p = Plane::new(Vec3::ZERO, Vec3::Y);
/// assert_eq!(plane_cast(&Ray::new(Vec3::new(0.0, -2.0, 0.0), Vec3::Y), &p), Some(2.0));
/// // Elsewhere it does: the plane y = 2 is hit at y = −2.
/// let p = Plane::new(Vec3::new(0.0, 2.0, 0.0), Vec3::Y);
/// assert_eq!(plane_cast(&Ray::new(Vec3::new(0.0, -4.0, 0.0), Vec3::Y), &p), Some(2.0));
/// ```
pub fn plane_cast(ray: &Ray, p: &Plane) -> Option<f32> {
    let n = v3(p.normal).normalize();
    CPlane::from_point_normal(p3(p.point), n)
        .intersection(&ray3(ray)?)
        .map(|x| t_of(ray, x))
}

/// `Plane::new(n̂, −p·n̂).intersection(&Ray3::new(o, d))`: the cast with
/// the sign of `d` it assumes.
///
/// ```
/// use collision_gate::plane_cast_negated;
/// use glam::Vec3;
/// use rayoracle::{Ray, plane::Plane};
/// let p = Plane::new(Vec3::new(0.0, 2.0, 0.0), Vec3::Y);
/// assert_eq!(plane_cast_negated(&Ray::new(Vec3::new(0.0, -4.0, 0.0), Vec3::Y), &p), Some(6.0));
/// ```
pub fn plane_cast_negated(ray: &Ray, p: &Plane) -> Option<f32> {
    let n = v3(p.normal).normalize();
    let d = -cgmath::EuclideanSpace::to_vec(p3(p.point)).dot(n);
    CPlane::new(n, d)
        .intersection(&ray3(ray)?)
        .map(|x| t_of(ray, x))
}

/// What collision's casts promise, as the survey judges them: the nearest
/// `t > 0`, a careful f32 kernel's accuracy, unit directions.
pub fn gate() -> Gate {
    Gate::new(Declared::f32(Semantics::NearestPositive).unit_dirs())
}

/// The sphere cast's name in the findings.
pub const SPHERE: &str = "collision Sphere::intersection(Ray3)";
/// The plane cast's name in the findings.
pub const PLANE: &str = "collision Plane::from_point_normal + intersection(Ray3)";
/// The plane cast on the plane with `d` negated.
pub const PLANE_NEGATED: &str = "collision Plane::new(n, -p·n) + intersection(Ray3)";

/// The three casts, on every sphere and plane family the gate runs.
pub fn survey() -> Vec<Surveyed> {
    let g = gate();
    let (spheres, planes) = (g.cases("sphere"), g.cases("plane"));
    let sphere = |r: &Ray, s: &Sphere| Answer::Nearest(sphere_cast(r, s));
    let plane = |r: &Ray, p: &Plane| Answer::Nearest(plane_cast(r, p));
    let negated = |r: &Ray, p: &Plane| Answer::Nearest(plane_cast_negated(r, p));
    vec![
        Surveyed::sphere(SPHERE, &g, &sphere, &spheres),
        Surveyed::plane(PLANE, &g, &plane, &planes),
        Surveyed::plane(PLANE_NEGATED, &g, &negated, &planes),
    ]
}
