//! The sphere as a quadric: for spheres with small integer
//! centre and radius `Quadric::from_sphere` is exact, the two exact oracles
//! solve the same polynomial, and the two references must agree wherever
//! neither is inside its band.
#![cfg(all(feature = "sphere", feature = "quadric"))]

use crate::support;

use glam::Vec3;
use proptest::prelude::*;
use rayoracle::Ray;
use rayoracle::check::sphere_as_quadric;
use rayoracle::quadric::{self, Quadric, QuadricHit};
use rayoracle::sphere::{self, Sphere, SphereHit};
use support::*;

fn compare(ray: &Ray, s: &Sphere) -> Result<(), TestCaseError> {
    prop_assert!(
        Quadric::from_sphere(s).1,
        "from_sphere is not exact for {:?}",
        s
    );
    if ray.dir == Vec3::ZERO {
        // Not a line, so no sphere check: the sphere's answer is none, and
        // the quadric's is its constant's, all where the origin is on the
        // surface and none elsewhere.
        let q = Quadric::from_sphere(s).0;
        prop_assert_eq!(sphere::reference::intersect(ray, s), SphereHit::None);
        let want = quadric::exact::intersect(ray, &q)
            .map_err(|e| TestCaseError::fail(format!("{e:?}")))?;
        prop_assert!(matches!(want, QuadricHit::None | QuadricHit::All));
        prop_assert_eq!(quadric::reference::intersect(ray, &q), want);
        return Ok(());
    }
    prop_assert!(
        sphere_as_quadric(ray, s).map_err(|v| TestCaseError::fail(v.to_string()))?,
        "the check did not run"
    );
    Ok(())
}

proptest! {
    /// Integer spheres, arbitrary float rays.
    #[test]
    fn integer_sphere_float_ray(c in ivec(8), r in 1i32..=8, o in vec_in(20.0), d in vec_in(4.0)) {
        float_ray_case(c, r, o, d)?;
    }

    /// Integer spheres seen from an integer origin aimed near the centre
    /// (mostly two roots, some none).
    #[test]
    fn integer_sphere_aimed(c in ivec(8), r in 1i32..=8, o in ivec(30), aim in ivec(8)) {
        aimed_case(c, r, o, aim)?;
    }

    /// Exact tangents (Pythagorean quadruples): sphere tangent ↔ quadric one.
    #[test]
    fn integer_tangent((v, r) in pythagorean_quadruple(2), c in ivec(8), w in ivec(3), s in -8i32..=8) {
        let d = perp(v, w);
        let o = add(add(c, v), mul(-s, d));
        let ray = Ray::new(scaled(o, 1.0), scaled(d, 1.0));
        let sphere = Sphere::new(scaled(c, 1.0), r as f32);
        prop_assert_eq!(sphere::exact::intersect(&ray, &sphere), Ok(SphereHit::Tangent(s as f32)));
        compare(&ray, &sphere)?;
    }
}

/// [`integer_sphere_float_ray`]'s check.
fn float_ray_case(c: [i32; 3], r: i32, o: Vec3, d: Vec3) -> Result<(), TestCaseError> {
    compare(&Ray::new(o, d), &Sphere::new(scaled(c, 1.0), r as f32))
}

/// [`integer_sphere_aimed`]'s check: the ray from `o` towards `c + aim`.
fn aimed_case(c: [i32; 3], r: i32, o: [i32; 3], aim: [i32; 3]) -> Result<(), TestCaseError> {
    let d = add(add(c, aim), mul(-1, o));
    prop_assume!(d != [0, 0, 0]);
    compare(
        &Ray::new(scaled(o, 1.0), scaled(d, 1.0)),
        &Sphere::new(scaled(c, 1.0), r as f32),
    )
}

/// The shrunk failures recorded in
/// `props_sphere_quadric.proptest-regressions`, each through its property's
/// check with the values proptest reported, so that they stay tests
/// whatever the strategies come to generate from the recorded seeds.
#[test]
fn recorded_failures() {
    assert_recorded([
        (
            "integer_sphere_aimed",
            aimed_case([0, 0, 1], 4, [0, 0, 1], [0, 0, 1]),
        ),
        (
            "integer_sphere_float_ray",
            float_ray_case([-3, 0, 0], 8, Vec3::new(0.0, 0.0, -5.4953475), Vec3::ZERO),
        ),
    ]);
}
