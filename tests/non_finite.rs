//! A NaN or infinite input has no exact answer, and the kernels document
//! what they return for it: the "no intersection" class of each kind
//! (`Parallel`, `None`, `None`), on the reference and on every x4 lane.
//! Each field in turn is made NaN, +∞ or −∞. Last, the other end of the
//! range: roots that round to a signed zero.
#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]

use glam::Vec3;
use rayoracle::Ray;
use rayoracle::plane::{self, Plane, PlaneHit};
use rayoracle::quadric::{self, Quadric, QuadricHit};
use rayoracle::ray4::Ray4;
use rayoracle::sphere::{self, Sphere, SphereHit};

const BAD: [f32; 3] = [f32::NAN, f32::INFINITY, f32::NEG_INFINITY];

/// Every way of putting one bad value into one of `n` fields.
fn spoiled(n: usize) -> impl Iterator<Item = (usize, f32)> {
    (0..n).flat_map(|i| BAD.map(|b| (i, b)))
}

#[test]
fn planes_with_a_non_finite_input_are_parallel() {
    for (i, bad) in spoiled(12) {
        let mut v = [0.0, 0.0, -5.0, 0.0, 0.0, 1.0, 0.0, 0.0, 2.0, 0.0, 0.0, 1.0];
        v[i] = bad;
        let at = |k: usize| Vec3::new(v[k], v[k + 1], v[k + 2]);
        let (ray, p) = (Ray::new(at(0), at(3)), Plane::new(at(6), at(9)));
        assert_eq!(
            plane::reference::intersect(&ray, &p),
            PlaneHit::Parallel,
            "field {i} = {bad}"
        );
        let h = plane::x4::intersect(&Ray4::splat(ray), &plane::x4::Plane4::splat(&p));
        assert_eq!(h.lanes(), [PlaneHit::Parallel; 4], "field {i} = {bad}");
    }
}

#[test]
fn spheres_with_a_non_finite_input_are_missed() {
    for (i, bad) in spoiled(10) {
        let mut v = [0.0, 0.0, -5.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0];
        v[i] = bad;
        let at = |k: usize| Vec3::new(v[k], v[k + 1], v[k + 2]);
        let (ray, s) = (Ray::new(at(0), at(3)), Sphere::new(at(6), v[9]));
        assert_eq!(
            sphere::reference::intersect(&ray, &s),
            SphereHit::None,
            "field {i} = {bad}"
        );
        let h = sphere::x4::intersect(&Ray4::splat(ray), &sphere::x4::Sphere4::splat(&s));
        assert_eq!(h.lanes(), [SphereHit::None; 4], "field {i} = {bad}");
    }
}

#[test]
fn quadrics_with_a_non_finite_input_are_missed() {
    for (i, bad) in spoiled(16) {
        let mut v = [0.0, 0.0, -5.0, 0.0, 0.0, 1.0];
        let mut k = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
        if i < 6 {
            v[i] = bad;
        } else {
            k[i - 6] = bad;
        }
        let ray = Ray::new(Vec3::new(v[0], v[1], v[2]), Vec3::new(v[3], v[4], v[5]));
        let q = Quadric::new(k);
        assert_eq!(
            quadric::reference::intersect(&ray, &q),
            QuadricHit::None,
            "field {i} = {bad}"
        );
        let h = quadric::x4::intersect(&Ray4::splat(ray), &quadric::x4::Quadric4::splat(&q));
        assert_eq!(h.lanes(), [QuadricHit::None; 4], "field {i} = {bad}");
    }
}

/// Roots so small that they round to zero keep their sign: `−0` where the
/// exact root is negative. Each case reached the double-word stage, which
/// negated an already rounded `+0` (the committed fuzz inputs that found
/// it replay in `fuzz-replay`).
#[test]
fn a_tiny_negative_root_rounds_to_minus_zero() {
    use rayoracle::check::{check_quadric, check_sphere};
    let v = Vec3::new;
    let spheres = [
        (
            v(1.3537992e-38, 0.0, 0.0),
            v(7.0771745e25, 0.0, 0.0),
            v(0.0, 0.0, 0.0),
        ),
        (
            v(6.162977e-33, 0.0, 0.0),
            v(1e30, 0.0, 0.0),
            v(0.0, 0.0, 0.0),
        ),
        (
            v(2.278e-41, 0.0, 0.0),
            v(-540026900.0, 0.0, 0.0),
            v(1.239779e-39, 0.0, 0.0),
        ),
        (
            v(-1.0, -1.0, 0.0),
            v(0.0, 0.0, -3.2892162e38),
            v(-1.0, -1.0, 9.1761e-41),
        ),
    ];
    for (o, d, c) in spheres {
        let (r, s) = (Ray::new(o, d), Sphere::new(c, 0.0));
        let got = sphere::reference::intersect(&r, &s);
        assert!(
            matches!(got, SphereHit::Tangent(t) if t == 0.0 && t.is_sign_negative()),
            "{got:?}"
        );
        check_sphere(&r, &s, got).unwrap_or_else(|e| panic!("{e:?}"));
        let h4 = sphere::x4::intersect(&Ray4::splat(r), &sphere::x4::Sphere4::splat(&s));
        for lane in h4.lanes() {
            check_sphere(&r, &s, lane).unwrap_or_else(|e| panic!("x4: {e:?}"));
        }
    }
    let quadrics = [
        (
            Ray::new(v(0.0, 6.8697e-41, 6.9101e-41), v(0.0, 0.0, 5.764644e17)),
            [0.0, 0.0, 8.8e-44, 8.8e-44, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        ),
        (
            Ray::new(v(8.8e-44, 2.68e-43, 4.0), v(3.6028797e16, 2.0, -0.0)),
            [5.878872e-39, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0],
        ),
    ];
    for (r, k) in quadrics {
        let q = Quadric::new(k);
        let got = quadric::reference::intersect(&r, &q);
        check_quadric(&r, &q, got).unwrap_or_else(|e| panic!("{e:?}"));
        let h4 = quadric::x4::intersect(&Ray4::splat(r), &quadric::x4::Quadric4::splat(&q));
        for lane in h4.lanes() {
            check_quadric(&r, &q, lane).unwrap_or_else(|e| panic!("x4: {e:?}"));
        }
    }
}
