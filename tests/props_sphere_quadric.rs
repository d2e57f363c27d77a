//! The sphere as a quadric: for spheres with small integer
//! centre and radius `Quadric::from_sphere` is exact, the two exact oracles
//! solve the same polynomial, and the two references must agree wherever
//! neither is inside its band.
#![cfg(all(feature = "sphere", feature = "quadric"))]

use crate::support;

use proptest::prelude::*;
use rayoracle::Ray;
use rayoracle::check::sphere_as_quadric;
use rayoracle::quadric::Quadric;
use rayoracle::sphere::{self, Sphere, SphereHit};
use support::*;

fn compare(ray: &Ray, s: &Sphere) -> Result<(), TestCaseError> {
    prop_assert!(
        Quadric::from_sphere(s).1,
        "from_sphere is not exact for {:?}",
        s
    );
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
        compare(&Ray::new(o, d), &Sphere::new(scaled(c, 1.0), r as f32))?;
    }

    /// Integer spheres seen from an integer origin aimed near the centre
    /// (mostly two roots, some none).
    #[test]
    fn integer_sphere_aimed(c in ivec(8), r in 1i32..=8, o in ivec(30), aim in ivec(8)) {
        let d = add(add(c, aim), mul(-1, o));
        prop_assume!(d != [0, 0, 0]);
        compare(&Ray::new(scaled(o, 1.0), scaled(d, 1.0)), &Sphere::new(scaled(c, 1.0), r as f32))?;
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
