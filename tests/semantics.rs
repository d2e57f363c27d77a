//! The answer forms: nearest in a range, a solid, hit points, and the
//! names the command line parses.
#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]

use glam::Vec3;
use rayoracle::Ray;
use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
use rayoracle::plane::Plane;
use rayoracle::quadric::Quadric;
use rayoracle::sphere::Sphere;

/// The unit sphere from z = −5 along z: roots 4 and 6.
fn ball() -> (Ray, Sphere) {
    (
        Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z),
        Sphere::new(Vec3::ZERO, 1.0),
    )
}

fn strict(s: &str) -> Gate {
    Gate::new(Declared::correctly_rounded(s.parse().unwrap()))
}

fn ok(g: &Gate, a: Answer) -> bool {
    let (r, s) = ball();
    g.judge_sphere(&r, &s, a).is_ok()
}

#[test]
fn a_range_answers_its_nearest_root_inside() {
    let n = |t: Option<f32>| Answer::Nearest(t);
    assert!(ok(&strict("range:0:5"), n(Some(4.0))));
    assert!(!ok(&strict("range:0:5"), n(Some(6.0))));
    assert!(ok(&strict("range:4.5:10"), n(Some(6.0))));
    assert!(!ok(&strict("range:4.5:10"), n(Some(4.0))));
    assert!(ok(&strict("range:0:3.9"), n(None)));
    assert!(!ok(&strict("range:0:3.9"), n(Some(4.0))));
    assert!(!ok(&strict("range:0:10"), n(None)));
    // Open at both ends: a root at t_max is not a hit.
    assert!(ok(&strict("range:0:4"), n(None)));
}

#[test]
fn roots_in_a_range_are_every_root_inside() {
    let r = |t: &[f32]| Answer::Roots(t.to_vec());
    assert!(ok(&strict("roots-in:0:10"), r(&[4.0, 6.0])));
    assert!(!ok(&strict("roots-in:0:10"), r(&[4.0])));
    assert!(ok(&strict("roots-in:0:5"), r(&[4.0])));
    assert!(!ok(&strict("roots-in:0:5"), r(&[4.0, 6.0])));
    assert!(!ok(&strict("roots-in:0:5"), r(&[])));
    assert!(ok(&strict("roots-in:5:10"), r(&[6.0])));
    assert!(ok(&strict("roots-in:0:4"), r(&[])));
    assert!(!ok(&strict("roots-in:0:4"), r(&[4.0])));
    assert!(!ok(&strict("roots-in:0:10"), Answer::Nearest(Some(4.0))));
    // Off by one ulp: only a declared tolerance passes it.
    let off = r(&[4.0, 6.0f32.next_up()]);
    assert!(!ok(&strict("roots-in:0:10"), off.clone()));
    let f32 = Gate::new(Declared::f32("roots-in:0:10".parse().unwrap()));
    assert!(ok(&f32, off));
}

#[test]
fn a_solid_answers_zero_inside() {
    let g = strict("solid");
    let (_, s) = ball();
    let inside = Ray::new(Vec3::new(0.0, 0.0, 0.5), Vec3::Z);
    assert!(
        g.judge_sphere(&inside, &s, Answer::Nearest(Some(0.0)))
            .is_ok()
    );
    assert!(
        g.judge_sphere(&inside, &s, Answer::Nearest(Some(0.5)))
            .is_err()
    );
    // On the surface counts as inside.
    let on = Ray::new(Vec3::new(0.0, 0.0, -1.0), Vec3::Z);
    assert!(g.judge_sphere(&on, &s, Answer::Nearest(Some(0.0))).is_ok());
    // Outside: the nearest t > 0.
    assert!(ok(&g, Answer::Nearest(Some(4.0))));
    assert!(!ok(&g, Answer::Nearest(Some(0.0))));
    // Behind a plane's front, and inside a quadric (F(o) ≤ 0).
    let ground = Plane::new(Vec3::ZERO, Vec3::Y);
    let below = Ray::new(-Vec3::Y, Vec3::X);
    assert!(
        g.judge_plane(&below, &ground, Answer::Nearest(Some(0.0)))
            .is_ok()
    );
    assert!(
        g.judge_plane(&below, &ground, Answer::Nearest(None))
            .is_err()
    );
    let above = Ray::new(Vec3::Y, -Vec3::Y);
    assert!(
        g.judge_plane(&above, &ground, Answer::Nearest(Some(1.0)))
            .is_ok()
    );
    let q = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
    assert!(
        g.judge_quadric(&inside, &q, Answer::Nearest(Some(0.0)))
            .is_ok()
    );
    assert!(
        g.judge_quadric(&inside, &q, Answer::Nearest(Some(0.5)))
            .is_err()
    );
}

#[test]
fn hit_points_are_judged_against_the_exact_point() {
    let p = |z: f32| Answer::Point(Some(Vec3::new(0.0, 0.0, z)));
    for g in [
        strict("nearest"),
        Gate::new(Declared::f32(Semantics::NearestPositive)),
    ] {
        assert!(ok(&g, p(-1.0)));
        assert!(!ok(&g, p(-1.001)));
        assert!(!ok(&g, p(1.0)));
        assert!(!ok(&g, Answer::Point(None)));
    }
    // One ulp of the point is allowed even to a correctly rounded kernel.
    assert!(ok(&strict("nearest"), p((-1f32).next_up())));
    assert!(!ok(&strict("whole-line"), p(-1.0)));
}

#[test]
fn every_name_parses_and_prints_back() {
    for s in [
        "whole-line",
        "nearest",
        "solid",
        "range:0.001:1e30",
        "roots-in:-1:1",
    ] {
        let sem: Semantics = s.parse().unwrap();
        assert_eq!(sem.to_string().parse::<Semantics>(), Ok(sem));
    }
    for bad in [
        "",
        "near",
        "range:1",
        "range:2:1",
        "range:a:b",
        "range:nan:1",
    ] {
        let e = bad.parse::<Semantics>().unwrap_err();
        assert!(e.contains(Semantics::FORMS), "{e}");
    }
    let d = Declared::f32(Semantics::WholeLine);
    assert!(d.require("magnitudes:2:1").is_err());
    assert_eq!(
        d.require("no-subnormals").map(|d| d.no_subnormals),
        Ok(true)
    );
}

/// 1/2⁻¹⁴⁹ overflows: the correctly rounded root is +∞, still a hit of an
/// unbounded ray, but not of one that stops at 10³⁰.
#[test]
fn a_root_that_overflows_is_still_a_hit() {
    let (r, p) = (
        Ray::new(Vec3::ZERO, Vec3::new(0.0, 0.0, f32::from_bits(1))),
        Plane::new(Vec3::Z, Vec3::Z),
    );
    let hit = Answer::Nearest(Some(f32::INFINITY));
    for s in ["nearest", "range:0:inf"] {
        assert!(strict(s).judge_plane(&r, &p, hit.clone()).is_ok(), "{s}");
    }
    // The origin is behind the plane's front: inside the solid.
    assert!(
        strict("solid")
            .judge_plane(&r, &p, Answer::Nearest(Some(0.0)))
            .is_ok()
    );
    assert!(
        strict("roots-in:0:inf")
            .judge_plane(&r, &p, Answer::Roots(vec![f32::INFINITY]))
            .is_ok()
    );
    assert!(strict("range:0:1e30").judge_plane(&r, &p, hit).is_err());
    assert!(
        strict("range:0:1e30")
            .judge_plane(&r, &p, Answer::Nearest(None))
            .is_ok()
    );
}
