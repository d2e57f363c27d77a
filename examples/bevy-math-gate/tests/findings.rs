//! What rayoracle finds in bevy_math, asserted: the families each cast
//! fails and how many cases, and each finding on a minimal case. A
//! bevy_math release (or a gate change) that changes any of it fails here.

use bevy_math_gate::*;
use glam::Vec3;
use rayoracle::Ray;
use rayoracle::plane::Plane;
use rayoracle::sphere::Sphere;

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
            ("sphere/far-tiny", 7),
            ("sphere/huge-near", 34),
            ("sphere/near-surface-inside", 256),
            ("sphere/random/inside", 256),
            ("sphere/random/on-surface", 117),
            ("sphere/random/tangent", 24),
            ("sphere/random/far", 17),
            ("sphere/random/far-graze", 9),
        ]
    );
}

#[test]
fn the_plane_cast_fails_exactly_these_families() {
    assert_eq!(
        surveyed(PLANE).failing(),
        [
            ("plane/subnormal-normal", 128),
            ("plane/near-parallel", 3),
            ("plane/random/small-root", 232),
            ("plane/random/grazing", 30),
            (SMALL_T, 256),
        ]
    );
}

/// The origin-inside families fail only by the semantics: every answer
/// there is 0, the "solid" answer, where the nearest `t > 0` is the exit.
#[test]
fn from_inside_the_sphere_cast_answers_zero() {
    let inside = [
        "sphere/origin-inside",
        "sphere/near-surface-inside",
        "sphere/random/inside",
    ];
    let mut n = 0;
    for (family, cases) in gate().cases("sphere") {
        if !inside.contains(&family.as_str()) {
            continue;
        }
        for c in cases {
            let rayoracle::case::Case::Sphere(r, s) = c else {
                continue;
            };
            assert_eq!(sphere_cast(&r, &s), Some(0.0), "{family}: {r:?} {s:?}");
            n += 1;
        }
    }
    assert_eq!(n, 3 * 256);
    let c = Vec3::new(1.0, 2.0, 3.0);
    let inside = Ray::new(c, Vec3::X);
    assert_eq!(sphere_cast(&inside, &Sphere::new(c, 2.0)), Some(0.0));
}

/// `R² = ∞` for a radius above 1.8e19: the cast answers 0 (inside) for an
/// origin twice the radius away.
#[test]
fn a_huge_sphere_is_hit_at_zero_from_outside() {
    let s = Sphere::new(Vec3::ZERO, 8.507059e37);
    let r = Ray::new(Vec3::new(0.0, 0.0, -1.7014118e38), Vec3::Z);
    assert_eq!(sphere_cast(&r, &s), Some(0.0));
}

/// A plane `t ≤ f32::EPSILON` ahead is never hit (`distance > EPSILON`),
/// whatever the scale of the scene.
#[test]
fn a_plane_closer_than_epsilon_is_missed() {
    let p = Plane::new(Vec3::new(0.0, 0.0, 1e-8), Vec3::Z);
    assert_eq!(plane_cast(&Ray::new(Vec3::ZERO, Vec3::Z), &p), None);
    let p = Plane::new(Vec3::new(0.0, 0.0, 1e-6), Vec3::Z);
    assert_eq!(plane_cast(&Ray::new(Vec3::ZERO, Vec3::Z), &p), Some(1e-6));
    let f = surveyed(PLANE).family(SMALL_T);
    assert_eq!((f.wrong_misses, f.cases), (256, 256));
}

/// A ray within `f32::EPSILON` of parallel (`|d·n| ≤ 2⁻²³`) misses, however
/// near the hit: here `t = 1e-3 / 1e-7 = 1e4`.
#[test]
fn a_nearly_parallel_plane_is_missed() {
    let d = Vec3::new(1.0, 0.0, 1e-7).normalize();
    let p = Plane::new(Vec3::new(0.0, 0.0, 1e-3), Vec3::Z);
    assert_eq!(plane_cast(&Ray::new(Vec3::ZERO, d), &p), None);
    let f = surveyed(PLANE).family("plane/near-parallel");
    assert_eq!((f.wrong_hits, f.wrong_misses, f.failures), (0, 113, 3));
}

/// bevy_math's closest-point discriminant keeps the far sphere: 7 of 256
/// `far-tiny` cases fail (parry3d's `b² − ac` fails 212).
#[test]
fn the_far_sphere_is_mostly_right() {
    let f = surveyed(SPHERE).family("sphere/far-tiny");
    assert_eq!((f.wrong_hits, f.wrong_misses, f.failures), (0, 9, 7));
    assert!(f.max_ulps <= 3, "{f:?}");
}
