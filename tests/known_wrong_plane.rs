#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
//! Known-wrong plane kernels, each a plausible slip on top of a correct
//! kernel (`plane::plain`, or the f64 kernel below), each caught by a
//! whole family.

use super::known_wrong::{assert_family_catches, assert_passes, gate};
use rayoracle::Ray;
use rayoracle::check::gate::{Answer, Semantics};
use rayoracle::plane::{self, Plane, PlaneHit};

/// The nearest root of `plane::plain` (correct) that `keep` accepts.
fn nearest_where(ray: &Ray, p: &Plane, keep: impl Fn(f32) -> bool) -> Answer {
    match plane::plain::intersect(ray, p) {
        PlaneHit::Hit(t) => Answer::Nearest(keep(t).then_some(t)),
        h => Answer::nearest(h, 0.0),
    }
}

/// Which sub-expression of [`plane_f64`] is computed in f32.
#[derive(Clone, Copy, PartialEq)]
enum InF32 {
    Nothing,
    Numerator,
    Denominator,
}

/// `t = ((a − o)·n)/(d·n)` in f64, rounded once, with one sub-expression
/// in f32 (or none: a correct kernel, the control).
fn plane_f64(ray: &Ray, p: &Plane, f32_part: InF32) -> Answer {
    let (o, d, a, n) = (ray.origin, ray.dir, p.point, p.normal);
    let num = if f32_part == InF32::Numerator {
        f64::from((a - o).dot(n))
    } else {
        (a.as_dvec3() - o.as_dvec3()).dot(n.as_dvec3())
    };
    let den = if f32_part == InF32::Denominator {
        f64::from(d.dot(n))
    } else {
        d.as_dvec3().dot(n.as_dvec3())
    };
    Answer::roots(if den != 0.0 {
        PlaneHit::Hit((num / den) as f32)
    } else if num == 0.0 {
        PlaneHit::InPlane
    } else {
        PlaneHit::Parallel
    })
}

fn plane_correct_f64(ray: &Ray, p: &Plane) -> Answer {
    plane_f64(ray, p, InF32::Nothing)
}

fn plane_denominator_f32(ray: &Ray, p: &Plane) -> Answer {
    plane_f64(ray, p, InF32::Denominator)
}

fn plane_numerator_f32(ray: &Ray, p: &Plane) -> Answer {
    plane_f64(ray, p, InF32::Numerator)
}

/// A self-intersection guard `t > 1e-4`.
fn plane_epsilon_1e4(ray: &Ray, p: &Plane) -> Answer {
    nearest_where(ray, p, |t| t > 1e-4)
}

/// The guard `t > f32::EPSILON`.
fn plane_epsilon_machine(ray: &Ray, p: &Plane) -> Answer {
    nearest_where(ray, p, |t| t > f32::EPSILON)
}

/// `|d·n| < 10⁻⁶` taken as parallel: a far hit at a grazing angle is lost.
fn plane_parallel_epsilon(ray: &Ray, p: &Plane) -> Answer {
    if f64::from(ray.dir.dot(p.normal)).abs() < 1e-6 {
        return Answer::Roots(vec![]);
    }
    Answer::roots(plane::plain::intersect(ray, p))
}

/// One-sided: only front faces (`d·n < 0`) are hit, as a culling
/// rasteriser does, for a plane that has two sides.
fn plane_front_only(ray: &Ray, p: &Plane) -> Answer {
    if ray.dir.dot(p.normal) >= 0.0 {
        return Answer::Nearest(None);
    }
    Answer::nearest(plane::plain::intersect(ray, p), 0.0)
}

/// The numerator's sign flipped: `(o − a)·n` for `(a − o)·n`.
fn plane_sign_flipped(ray: &Ray, p: &Plane) -> Answer {
    match plane::plain::intersect(ray, p) {
        PlaneHit::Hit(t) => Answer::Roots(vec![-t]),
        h => Answer::roots(h),
    }
}

#[test]
fn the_f64_plane_passes() {
    let report = gate(Semantics::WholeLine).plane(&plane_correct_f64);
    assert_passes("plane in f64", &report, 500);
}

#[test]
fn epsilon_1e4_is_caught_by_small_roots() {
    let report = gate(Semantics::NearestPositive).plane(&plane_epsilon_1e4);
    assert_family_catches("plane t > 1e-4", &report, "plane/random/small-root", 200);
}

#[test]
fn epsilon_machine_is_caught_by_small_roots() {
    let report = gate(Semantics::NearestPositive).plane(&plane_epsilon_machine);
    assert_family_catches(
        "plane t > f32::EPSILON",
        &report,
        "plane/random/small-root",
        150,
    );
}

#[test]
fn parallel_epsilon_is_caught_by_short_normals() {
    let report = gate(Semantics::WholeLine).plane(&plane_parallel_epsilon);
    assert_family_catches(
        "plane |d·n| < 1e-6",
        &report,
        "plane/random/short-normal",
        200,
    );
}

#[test]
fn front_faces_only_is_caught_by_random_planes() {
    let report = gate(Semantics::NearestPositive).plane(&plane_front_only);
    assert_family_catches("plane front faces only", &report, "plane/random/any", 32);
}

#[test]
fn sign_flip_is_caught_by_random_planes() {
    let report = gate(Semantics::WholeLine).plane(&plane_sign_flipped);
    assert_family_catches("plane (o − a)·n", &report, "plane/random/any", 200);
}

#[test]
fn denominator_in_f32_is_caught_by_grazing_rays() {
    let report = gate(Semantics::WholeLine).plane(&plane_denominator_f32);
    assert_family_catches("plane d·n in f32", &report, "plane/random/grazing", 8);
}

#[test]
fn numerator_in_f32_is_caught_by_subnormal_normals() {
    let report = gate(Semantics::WholeLine).plane(&plane_numerator_f32);
    assert_family_catches(
        "plane (a − o)·n in f32",
        &report,
        "plane/subnormal-normal",
        8,
    );
}

/// `t ≥ 0` for `t > 0`: a ray that starts on the plane hits it at 0.
fn plane_t_ge_0(ray: &Ray, p: &Plane) -> Answer {
    nearest_where(ray, p, |t| t >= 0.0)
}

#[test]
fn t_ge_0_is_caught_by_origins_on_the_plane() {
    let report = gate(Semantics::NearestPositive).plane(&plane_t_ge_0);
    assert_family_catches("plane t ≥ 0", &report, "plane/random/on-plane", 250);
    // The control: the same kernel with `t > 0`.
    let control = gate(Semantics::NearestPositive)
        .plane(&|r: &Ray, p: &Plane| nearest_where(r, p, |t| t > 0.0));
    assert_passes("plane t > 0", &control, 500);
}
