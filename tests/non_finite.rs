//! A NaN or infinite input has no exact answer, and the kernels document
//! what they return for it: the "no intersection" class of each kind
//! (`Parallel`, `None`, `None`), on the reference and on every x4 lane.
//! Each field in turn is made NaN, +∞ or −∞.
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
