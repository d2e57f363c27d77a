#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
//! Known-wrong four-lane kernels of every kind, through `Lanes`: packet
//! early-outs that answer every lane alike when one lane misses or is
//! NaN. rayoracle's own four-lane kernels, unchanged, are the controls.

use super::known_wrong::{assert_family_catches, assert_passes, gate};
use rayoracle::Ray;
use rayoracle::check::gate::{
    Answer, Lanes, PlaneKernel4, QuadricKernel4, Report, Semantics, SphereKernel4,
};
use rayoracle::hit::{Class, Intersection};
use rayoracle::plane::Plane;
use rayoracle::primitive::{Primitive, x4_lanes};
use rayoracle::quadric::Quadric;
use rayoracle::sphere::Sphere;

/// What a packet does to its four correct answers.
type Slip<H> = fn(&[Ray; 4], [H; 4]) -> [H; 4];

/// rayoracle's own four-lane kernel of a kind, its answers passed through
/// a slip.
struct Packet<P: Primitive>(Slip<P::Hit>);

impl<P: Primitive> Packet<P> {
    fn run(&self, rays: &[Ray; 4], prims: &[P; 4]) -> [Answer; 4] {
        let hits = x4_lanes(core::array::from_fn(|i| (rays[i], prims[i])));
        (self.0)(rays, hits).map(Answer::roots)
    }
}

impl SphereKernel4 for Packet<Sphere> {
    fn intersect4(&self, r: &[Ray; 4], s: &[Sphere; 4]) -> [Answer; 4] {
        self.run(r, s)
    }
}
impl PlaneKernel4 for Packet<Plane> {
    fn intersect4(&self, r: &[Ray; 4], p: &[Plane; 4]) -> [Answer; 4] {
        self.run(r, p)
    }
}
impl QuadricKernel4 for Packet<Quadric> {
    fn intersect4(&self, r: &[Ray; 4], q: &[Quadric; 4]) -> [Answer; 4] {
        self.run(r, q)
    }
}

fn unchanged<H>(_: &[Ray; 4], h: [H; 4]) -> [H; 4] {
    h
}

/// "No lane hits" tested as "some lane misses" (a `movemask != 0` for
/// `== 0xf`): every lane answers the missing lane's miss. A NaN lane's
/// miss does not count (its comparisons are false), so only a decoy that
/// truly misses shows it.
fn early_out<H: Intersection + Copy>(r: &[Ray; 4], h: [H; 4]) -> [H; 4] {
    let nan = |x: &Ray| x.origin.is_nan() || x.dir.is_nan();
    let miss =
        (0..4).find(|&i| !nan(&r[i]) && matches!(h[i].class(), Class::None | Class::Parallel));
    match miss {
        Some(i) => [h[i]; 4],
        None => h,
    }
}

/// A packet with a NaN lane given up whole: every lane answers the NaN
/// lane's answer.
fn nan_drops_packet<H: Intersection + Copy>(r: &[Ray; 4], h: [H; 4]) -> [H; 4] {
    let nan = |x: &Ray| x.origin.is_nan() || x.dir.is_nan();
    match r.iter().position(nan) {
        Some(i) => [h[i]; 4],
        None => h,
    }
}

/// The catching family fails on `min` cases, all for disagreeing lanes.
fn caught_inconsistent(kernel: &str, report: &Report, family: &str, min: usize) {
    assert_family_catches(kernel, report, family, min);
    for f in &report.failures {
        assert!(f.got.contains("inconsistent lanes"), "{kernel}: {f}");
    }
}

#[test]
fn unchanged_packets_pass() {
    let g = gate(Semantics::WholeLine);
    assert_passes(
        "plane::x4",
        &g.plane(&Lanes(Packet::<Plane>(unchanged))),
        500,
    );
    assert_passes(
        "quadric::x4",
        &g.quadric(&Lanes(Packet::<Quadric>(unchanged))),
        1000,
    );
    assert_passes(
        "sphere::x4",
        &g.sphere(&Lanes(Packet::<Sphere>(unchanged))),
        1000,
    );
}

#[test]
fn sphere_early_out_is_caught_by_aimed_rays() {
    let report = gate(Semantics::WholeLine).sphere(&Lanes(Packet::<Sphere>(early_out)));
    caught_inconsistent(
        "sphere packet early-out",
        &report,
        "sphere/random/aimed",
        32,
    );
}

#[test]
fn plane_early_out_is_caught_by_random_planes() {
    let report = gate(Semantics::WholeLine).plane(&Lanes(Packet::<Plane>(early_out)));
    caught_inconsistent("plane packet early-out", &report, "plane/random/any", 200);
}

#[test]
fn quadric_early_out_is_caught_by_random_quadrics() {
    let report = gate(Semantics::WholeLine).quadric(&Lanes(Packet::<Quadric>(early_out)));
    caught_inconsistent(
        "quadric packet early-out",
        &report,
        "quadric/random/any",
        32,
    );
}

#[test]
fn sphere_nan_lane_is_caught_by_aimed_rays() {
    let report = gate(Semantics::WholeLine).sphere(&Lanes(Packet::<Sphere>(nan_drops_packet)));
    caught_inconsistent(
        "sphere NaN lane drops the packet",
        &report,
        "sphere/random/aimed",
        32,
    );
}

#[test]
fn plane_nan_lane_is_caught_by_random_planes() {
    let report = gate(Semantics::WholeLine).plane(&Lanes(Packet::<Plane>(nan_drops_packet)));
    caught_inconsistent(
        "plane NaN lane drops the packet",
        &report,
        "plane/random/any",
        200,
    );
}

#[test]
fn quadric_nan_lane_is_caught_by_random_quadrics() {
    let report = gate(Semantics::WholeLine).quadric(&Lanes(Packet::<Quadric>(nan_drops_packet)));
    caught_inconsistent(
        "quadric NaN lane drops the packet",
        &report,
        "quadric/random/any",
        32,
    );
}
