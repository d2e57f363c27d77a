//! What rayoracle finds in collision, asserted: the families each cast
//! fails and how many cases, and each bug on a minimal case, called on
//! collision directly. A collision release (or a gate change) that changes
//! any of it fails here.

use cgmath::{Point3, Vector3};
use collision::prelude::*;
use collision::{Plane as CPlane, Ray3, Sphere as CSphere};
use collision_gate::*;

survey_kit::survey_tests!(survey);

#[test]
fn the_sphere_cast_fails_exactly_these_families() {
    assert_eq!(
        surveyed(SPHERE).failing(),
        [
            ("sphere/origin-inside", 256),
            ("sphere/origin-on-surface", 1),
            ("sphere/tangent-exact-large", 1),
            ("sphere/huge-close", 1),
            ("sphere/subnormal", 1),
            ("sphere/huge", 1),
            ("sphere/far-tiny", 196),
            ("sphere/huge-near", 32),
            ("sphere/near-surface-inside", 256),
            ("sphere/near-tangent", 6),
            ("sphere/exact-tangent", 12),
            ("sphere/dir-scale", 39),
            ("sphere/random/aimed", 76),
            ("sphere/random/inside", 256),
            ("sphere/random/on-surface", 115),
            ("sphere/random/tangent", 30),
            ("sphere/random/far", 138),
            ("sphere/random/far-graze", 115),
        ]
    );
}

#[test]
fn the_plane_cast_fails_exactly_these_families() {
    assert_eq!(
        surveyed(PLANE).failing(),
        [
            ("plane/hit", 3),
            ("plane/parallel", 1),
            ("plane/in-plane", 52),
            ("plane/zero-normal", 1),
            ("plane/far-1e30", 4),
            ("plane/subnormal-normal", 256),
            ("plane/nearly-parallel", 2),
            ("plane/near-parallel", 36),
            ("plane/far", 256),
            ("plane/random/any", 164),
            ("plane/random/small-root", 256),
            ("plane/random/on-plane", 23),
            ("plane/random/in-plane", 65),
            ("plane/random/grazing", 62),
            ("plane/random/short-normal", 191),
        ]
    );
    assert_eq!(
        surveyed(PLANE_NEGATED).failing(),
        [
            ("plane/parallel", 1),
            ("plane/in-plane", 136),
            ("plane/zero-normal", 1),
            ("plane/subnormal-normal", 256),
            ("plane/nearly-parallel", 2),
            ("plane/random/small-root", 8),
            ("plane/random/on-plane", 7),
            ("plane/random/in-plane", 172),
        ]
    );
}

/// `Plane` documents `n·x − d = 0`, and `from_point_normal` builds
/// `d = p·n`; the ray cast solves `n·x + d = 0`, and so does
/// `from_points` (`d = −a·n`). A ray up the y axis from y = −4 meets the
/// plane y = 2 at y = −2.
#[test]
fn the_plane_cast_solves_the_plane_with_d_negated() {
    let up = Vector3::new(0.0f32, 1.0, 0.0);
    let ray = Ray3::new(Point3::new(0.0f32, -4.0, 0.0), up);
    let plane = CPlane::from_point_normal(Point3::new(0.0, 2.0, 0.0), up);
    assert_eq!(plane.d, 2.0);
    assert_eq!(plane.intersection(&ray), Some(Point3::new(0.0, -2.0, 0.0)));
    // The same plane through three of its points: the other sign.
    let three = CPlane::from_points(
        Point3::new(0.0, 2.0, 0.0),
        Point3::new(0.0, 2.0, 1.0),
        Point3::new(1.0, 2.0, 0.0),
    )
    .unwrap();
    assert_eq!((three.n, three.d), (up, -2.0));
    assert_eq!(three.intersection(&ray), Some(Point3::new(0.0, 2.0, 0.0)));
}

/// From inside the sphere the cast answers the entry point behind the
/// origin (`tca − thc < 0`), or nothing once the center is behind
/// (`tca < 0`); the exit point is ahead in both cases.
#[test]
fn from_inside_the_sphere_the_cast_answers_behind_or_nothing() {
    let s = CSphere {
        center: Point3::new(0.0f32, 0.0, 0.0),
        radius: 1.0,
    };
    let z = Vector3::new(0.0, 0.0, 1.0);
    let at_center = Ray3::new(Point3::new(0.0, 0.0, 0.0), z);
    assert_eq!(
        s.intersection(&at_center),
        Some(Point3::new(0.0, 0.0, -1.0))
    );
    let past_center = Ray3::new(Point3::new(0.0, 0.0, 0.5), z);
    assert_eq!(s.intersection(&past_center), None);
    let f = surveyed(SPHERE).family("sphere/origin-inside");
    assert_eq!((f.wrong_misses, f.hits, f.failures), (120, 136, 256));
}

/// A ray parallel to the plane gets `t = ±∞` or NaN, which passes the
/// `t < 0` test, and a point with infinite or NaN coordinates.
#[test]
fn a_parallel_ray_hits_at_infinity() {
    let x = Vector3::new(1.0f32, 0.0, 0.0);
    let plane = CPlane::new(Vector3::new(0.0, 1.0, 0.0), 0.0);
    // 1 below the plane y = 0: t = −(0 − 1)/0 = +∞.
    let below = Ray3::new(Point3::new(0.0f32, -1.0, 0.0), x);
    let p = plane.intersection(&below).expect("a hit");
    assert!(
        p.x == f32::INFINITY && p.y.is_nan() && p.z.is_nan(),
        "{p:?}"
    );
    // In the plane: t = −0/0 = NaN.
    let on = Ray3::new(Point3::new(0.0f32, 0.0, 0.0), x);
    assert!(plane.intersection(&on).is_some_and(|p| p.x.is_nan()));
}

/// The discriminant `R² − (l·l − tca²)` cancels when `|l| ≫ R`, as
/// parry3d's `b² − ac` does: 196 of 256 far-tiny cases fail, with wrong
/// hits and misses.
#[test]
fn the_far_sphere_loses_its_class() {
    let f = surveyed(SPHERE).family("sphere/far-tiny");
    assert_eq!((f.wrong_hits, f.wrong_misses, f.failures), (28, 63, 196));
    assert!(f.max_ulps > 4096, "{f:?}");
}
