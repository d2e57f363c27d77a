//! bevy_math's ray casts, wrapped as rayoracle kernels and surveyed
//! against the exact oracle (bevy_math 0.19.1, the last release with
//! `bounding` and `Ray3d`).
//!
//! * [`sphere_cast`]: `RayCast3d::sphere_intersection_at` against a
//!   `BoundingSphere`, with `max = f32::MAX`;
//! * [`plane_cast`]: `Ray3d::intersect_plane` against an
//!   `InfinitePlane3d` through the plane's point.
//!
//! Both take a `Dir3A`/`Dir3`, a unit direction built by `Dir3::new`
//! (which normalises, and refuses a zero or non-finite vector), so the
//! survey feeds unit directions ([`Declared::unit_dirs`]). Where a
//! constructor refuses the inputs (a zero direction or normal, a negative
//! radius, which `BoundingSphere::new` debug-asserts), no ray can be cast,
//! and the answer is "no hit".

use bevy_math::bounding::{BoundingSphere, RayCast3d};
use bevy_math::primitives::InfinitePlane3d;
use bevy_math::{Dir3, Dir3A, Ray3d, Vec3, Vec3A};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use rayoracle::Ray;
use rayoracle::case::Case;
use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
use rayoracle::plane::Plane;
use rayoracle::sphere::Sphere;
use survey_kit::Surveyed;
use survey_kit::random_unit;

fn v3(x: glam::Vec3) -> Vec3 {
    Vec3::from_array(x.to_array())
}

fn v3a(x: glam::Vec3) -> Vec3A {
    Vec3A::from_array(x.to_array())
}

/// `RayCast3d::new(o, Dir3A::new(d), f32::MAX).sphere_intersection_at`.
/// From an origin inside the sphere it answers 0 (a solid sphere), not
/// the exit point.
///
/// ```
/// use bevy_math_gate::sphere_cast;
/// use glam::Vec3;
/// use rayoracle::{Ray, sphere::Sphere};
/// let s = Sphere::new(Vec3::new(0.0, 0.0, 5.0), 1.0);
/// assert_eq!(sphere_cast(&Ray::new(Vec3::ZERO, Vec3::Z), &s), Some(4.0));
/// assert_eq!(sphere_cast(&Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::Z), &s), Some(0.0));
/// ```
pub fn sphere_cast(ray: &Ray, s: &Sphere) -> Option<f32> {
    let dir = Dir3A::new(v3a(ray.dir)).ok()?;
    let cast = RayCast3d::new(v3a(ray.origin), dir, f32::MAX);
    // `BoundingSphere::new` debug-asserts `radius ≥ 0`; the fields are
    // public, and the cast uses only `radius²`.
    let sphere = BoundingSphere {
        center: v3a(s.center),
        sphere: bevy_math::primitives::Sphere { radius: s.radius },
    };
    cast.sphere_intersection_at(&sphere)
}

/// `Ray3d::new(o, Dir3::new(d)).intersect_plane(point, InfinitePlane3d::new(n))`.
///
/// ```
/// use bevy_math_gate::plane_cast;
/// use glam::Vec3;
/// use rayoracle::{Ray, plane::Plane};
/// let p = Plane::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, 3.0, 0.0));
/// assert_eq!(plane_cast(&Ray::new(Vec3::ZERO, Vec3::Y), &p), Some(2.0));
/// ```
pub fn plane_cast(ray: &Ray, p: &Plane) -> Option<f32> {
    let dir = Dir3::new(v3(ray.dir)).ok()?;
    let normal = Dir3::new(v3(p.normal)).ok()?;
    Ray3d::new(v3(ray.origin), dir).intersect_plane(v3(p.point), InfinitePlane3d { normal })
}

/// What bevy_math's casts promise, as the survey judges them: the nearest
/// `t > 0`, a careful f32 kernel's accuracy, unit directions.
pub fn gate() -> Gate {
    Gate::new(Declared::f32(Semantics::NearestPositive).unit_dirs())
}

/// The sphere cast's name in the findings.
pub const SPHERE: &str = "bevy_math RayCast3d::sphere_intersection_at";
/// The plane cast's name in the findings.
pub const PLANE: &str = "bevy_math Ray3d::intersect_plane";

/// The family of [`small_t`].
pub const SMALL_T: &str = "bevy/plane-small-t";

/// Planes just ahead of the ray: unit rays from the origin to a plane
/// through `t·d`, `t` log-uniform in `[1e-20, 1e-7]`, its normal random
/// within 60° of `d`. Every case hits at about `t` (the oracle gives the
/// exact root), below `f32::EPSILON`.
///
/// ```
/// let f = bevy_math_gate::small_t(16, 1);
/// assert_eq!(f.len(), 16);
/// ```
pub fn small_t(n: usize, seed: u64) -> Vec<Case> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let mut out = Vec::new();
    while out.len() < n {
        let d = random_unit(&mut rng);
        let normal = random_unit(&mut rng);
        if normal.dot(d) < 0.5 {
            continue;
        }
        let t = 10f32.powf(rng.random_range(-20.0..-7.0));
        out.push(Case::Plane(
            Ray::new(glam::Vec3::ZERO, d),
            Plane::new(d * t, normal),
        ));
    }
    out
}

/// Both casts, on every sphere and plane family the gate runs, the plane
/// also on [`small_t`] (256 cases).
pub fn survey() -> Vec<Surveyed> {
    let g = gate();
    let sphere = |r: &Ray, s: &Sphere| Answer::Nearest(sphere_cast(r, s));
    let plane = |r: &Ray, p: &Plane| Answer::Nearest(plane_cast(r, p));
    let mut planes = g.cases("plane");
    planes.push((SMALL_T.to_string(), small_t(256, 0xb1)));
    vec![
        Surveyed::sphere(SPHERE, &g, &sphere, &g.cases("sphere")),
        Surveyed::plane(PLANE, &g, &plane, &planes),
    ]
}
