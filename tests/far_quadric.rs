//! A far sphere written as a quadric is judged as strictly as the sphere:
//! the quadric's band and κ are measured about the ray's double root, not
//! against the terms at the origin (which are `|o|²` where the
//! discriminant is `4aR²`).
#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]

use glam::Vec3;
use rayoracle::Ray;
use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
use rayoracle::quadric::{self, Quadric};
use rayoracle::sphere::{self, Sphere};

/// 4,096 rays from 10⁴ to 10⁷ radii away, aimed within 1.2 radii of the
/// unit sphere's centre (a fixed linear congruential stream).
fn far_rays() -> Vec<Ray> {
    let mut x: u64 = 0x5eed;
    let mut next = move || {
        x = x
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((x >> 40) as f32 / (1u64 << 24) as f32) * 2.0 - 1.0
    };
    (0..4096i32)
        .map(|i| {
            let far = 10f32.powi(4 + i % 4);
            let o = Vec3::new(next(), next(), next()).normalize() * far;
            let aim = Vec3::new(next(), next(), next()) * 1.2;
            Ray::new(o, aim - o)
        })
        .collect()
}

fn unit() -> (Sphere, Quadric) {
    (
        Sphere::new(Vec3::ZERO, 1.0),
        Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]),
    )
}

/// Failures of the textbook f32 formulas under `Declared::f32`, as a
/// sphere and as a quadric.
fn textbook_failures() -> (usize, usize) {
    let (s, q) = unit();
    let g = Gate::new(Declared::f32(Semantics::WholeLine));
    let rays = far_rays();
    let as_sphere = rays
        .iter()
        .filter(|r| {
            g.judge_sphere(r, &s, Answer::roots(sphere::textbook::intersect(r, &s)))
                .is_err()
        })
        .count();
    let as_quadric = rays
        .iter()
        .filter(|r| {
            g.judge_quadric(r, &q, Answer::roots(quadric::textbook::intersect(r, &q)))
                .is_err()
        })
        .count();
    (as_sphere, as_quadric)
}

#[test]
fn a_far_sphere_as_a_quadric_fails_as_the_sphere_does() {
    let (as_sphere, as_quadric) = textbook_failures();
    assert!(as_sphere > 1000, "{as_sphere}");
    assert!(
        2 * as_quadric >= as_sphere,
        "{as_sphere} as a sphere, {as_quadric} as a quadric"
    );
}

#[test]
fn correct_kernels_pass_the_far_quadric() {
    let (_, q) = unit();
    let g = Gate::new(Declared::f32(Semantics::WholeLine));
    let strict = Gate::new(Declared::correctly_rounded(Semantics::WholeLine));
    for r in far_rays() {
        g.judge_quadric(&r, &q, Answer::roots(quadric::plain::intersect(&r, &q)))
            .unwrap();
        strict
            .judge_quadric(&r, &q, Answer::roots(quadric::reference::intersect(&r, &q)))
            .unwrap();
    }
}
