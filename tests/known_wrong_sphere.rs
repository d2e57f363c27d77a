#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
//! Known-wrong sphere kernels, each a plausible slip on top of a correct
//! kernel (`sphere::plain`, or the stable f64 helper of
//! `known_wrong.rs`), each caught by a whole family.

use super::known_wrong::{assert_family_catches, gate, solve, terms};
use glam::DVec3;
use rayoracle::check::gate::{Answer, Semantics};
use rayoracle::sphere::{self, Sphere, SphereHit};
use rayoracle::{Ray, hit::Intersection};

/// The roots of `sphere::plain` (correct), the nearest one kept by `keep`.
fn nearest_where(ray: &Ray, s: &Sphere, keep: impl Fn(f32) -> bool) -> Answer {
    let h = sphere::plain::intersect(ray, s);
    Answer::Nearest(h.roots().as_slice().iter().copied().find(|&t| keep(t)))
}

/// A self-intersection guard `t > 1e-4`, the usual shadow-acne epsilon.
fn sphere_epsilon_1e4(ray: &Ray, s: &Sphere) -> Answer {
    nearest_where(ray, s, |t| t > 1e-4)
}

/// The guard `t > f32::EPSILON`: an absolute 2⁻²³ taken for a relative one.
fn sphere_epsilon_machine(ray: &Ray, s: &Sphere) -> Answer {
    nearest_where(ray, s, |t| t > f32::EPSILON)
}

/// The nearest `t ≥ 0` instead of `t > 0`: from the surface it answers the
/// origin's own 0.
fn sphere_t_nonnegative(ray: &Ray, s: &Sphere) -> Answer {
    nearest_where(ray, s, |t| t >= 0.0)
}

/// The far root taken for the near one (`q/a` and `c/q` confused): the
/// exit point wherever it is ahead.
fn sphere_far_root(ray: &Ray, s: &Sphere) -> Answer {
    Answer::Nearest(match sphere::plain::intersect(ray, s) {
        SphereHit::None => None,
        SphereHit::Tangent(t) => (t > 0.0).then_some(t),
        SphereHit::Two(t0, t1) => [t1, t0].into_iter().find(|&t| t > 0.0),
    })
}

/// The textbook discriminant `b² − ac` in f64 (`f·d` and `f·f − R²`
/// rounded in f64, then subtracted), roots by the stable quadratic: the
/// discriminant is rounding noise once `|f|/R` passes about 10⁸.
fn sphere_textbook_f64(ray: &Ray, s: &Sphere) -> Answer {
    let t = terms(ray, s);
    let c = t.ff - t.r2;
    let disc = t.a * (t.b * t.b - t.a * c);
    Answer::roots(solve(t.a, t.b, c, disc, f64::sqrt))
}

/// The stable f64 kernel except that `c = f·f − R²` is computed in f32
/// (`f` rounded to f32 first): `c` cancels for an origin near the surface.
fn sphere_c_in_f32(ray: &Ray, s: &Sphere) -> Answer {
    let t = terms(ray, s);
    let f = ray.origin - s.center;
    let c = f64::from(f.dot(f) - s.radius * s.radius);
    let disc = t.a * t.a * t.r2 - t.perp2;
    Answer::roots(solve(t.a, t.b, c, disc, f64::sqrt))
}

/// The stable f64 kernel except that the discriminant `b² − ac` is one
/// f32 expression: noise for a far sphere.
fn sphere_disc_in_f32(ray: &Ray, s: &Sphere) -> Answer {
    let t = terms(ray, s);
    let (a, b, c) = (t.a as f32, t.b as f32, (t.ff - t.r2) as f32);
    let disc = t.a * f64::from(b * b - a * c);
    Answer::roots(solve(t.a, t.b, t.ff - t.r2, disc, f64::sqrt))
}

/// A tangent taken for a miss: `disc ≤ 0` means no hit.
fn sphere_tangent_misses(ray: &Ray, s: &Sphere) -> Answer {
    match sphere::plain::intersect(ray, s) {
        SphereHit::Tangent(_) => Answer::Roots(vec![]),
        h => Answer::roots(h),
    }
}

/// A unit direction assumed: `a = d·d` taken as 1.
fn sphere_assumes_unit_dir(ray: &Ray, s: &Sphere) -> Answer {
    let f: DVec3 = ray.origin.as_dvec3() - s.center.as_dvec3();
    let d: DVec3 = ray.dir.as_dvec3();
    let r = f64::from(s.radius);
    let (b, c) = (f.dot(d), f.dot(f) - r * r);
    let perp2 = (f - b * d).length_squared();
    Answer::roots(solve(1.0, b, c, r * r - perp2, f64::sqrt))
}

/// An absolute epsilon on the discriminant: `b² − ac < 10⁻⁶` (per `a²`)
/// is a miss, which loses every small sphere.
fn sphere_disc_epsilon(ray: &Ray, s: &Sphere) -> Answer {
    let t = terms(ray, s);
    let disc = t.a * t.a * t.r2 - t.perp2;
    if disc / (t.a * t.a) < 1e-6 {
        return Answer::Roots(vec![]);
    }
    Answer::roots(solve(t.a, t.b, t.ff - t.r2, disc, f64::sqrt))
}

#[test]
fn epsilon_1e4_is_caught_by_small_roots() {
    let report = gate(Semantics::NearestPositive).sphere(&sphere_epsilon_1e4);
    assert_family_catches("sphere t > 1e-4", &report, "sphere/random/small-root", 200);
}

#[test]
fn epsilon_machine_is_caught_by_small_roots() {
    let report = gate(Semantics::NearestPositive).sphere(&sphere_epsilon_machine);
    assert_family_catches(
        "sphere t > f32::EPSILON",
        &report,
        "sphere/random/small-root",
        200,
    );
}

#[test]
fn t_nonnegative_is_caught_by_origins_on_the_surface() {
    let report = gate(Semantics::NearestPositive).sphere(&sphere_t_nonnegative);
    assert_family_catches("sphere t ≥ 0", &report, "sphere/random/on-surface", 100);
}

#[test]
fn far_root_is_caught_by_aimed_rays() {
    let report = gate(Semantics::NearestPositive).sphere(&sphere_far_root);
    assert_family_catches("sphere far root", &report, "sphere/random/aimed", 8);
}

/// `sphere::textbook`, all in f32: caught by the far spheres.
#[test]
fn textbook_f32_is_caught_by_far_spheres() {
    let k = |r: &Ray, s: &Sphere| Answer::roots(sphere::textbook::intersect(r, s));
    let report = gate(Semantics::WholeLine).sphere(&k);
    assert_family_catches("sphere::textbook", &report, "sphere/random/far", 8);
    assert_family_catches("sphere::textbook", &report, "sphere/random/far-graze", 8);
}

/// The textbook discriminant in f64 answers within what a careful f32
/// kernel may (its noise is within the f32 band), so it is caught under
/// the faithful declaration, which a kernel working in f64 can make.
#[test]
fn textbook_f64_is_caught_by_far_spheres() {
    let g = rayoracle::check::gate::Gate::new(rayoracle::check::gate::Declared::faithful(
        Semantics::WholeLine,
    ));
    let report = g.sphere(&sphere_textbook_f64);
    assert_family_catches("sphere textbook f64", &report, "sphere/random/far", 8);
    assert_family_catches("sphere textbook f64", &report, "sphere/random/far-graze", 8);
}

/// `c = |f|² − R²` in f32 moves a root near 0 by about `ulp(|f|²)/|b|`:
/// within what a careful f32 kernel may do (roots near 0 are judged by
/// their terms' scale), so it is caught under the faithful declaration of
/// the f64 kernel it sits in.
#[test]
fn c_in_f32_is_caught_near_huge_surfaces() {
    let g = rayoracle::check::gate::Gate::new(rayoracle::check::gate::Declared::faithful(
        Semantics::WholeLine,
    ));
    let report = g.sphere(&sphere_c_in_f32);
    assert_family_catches("sphere c in f32", &report, "sphere/huge-near", 8);
}

#[test]
fn disc_in_f32_is_caught_by_far_spheres() {
    let report = gate(Semantics::WholeLine).sphere(&sphere_disc_in_f32);
    assert_family_catches("sphere b² − ac in f32", &report, "sphere/random/far", 8);
}

#[test]
fn tangent_as_miss_is_caught_by_integer_tangents() {
    let report = gate(Semantics::WholeLine).sphere(&sphere_tangent_misses);
    assert_family_catches(
        "sphere tangent as miss",
        &report,
        "sphere/random/tangent",
        100,
    );
}

#[test]
fn unit_dir_assumed_is_caught_by_scaled_directions() {
    let report = gate(Semantics::WholeLine).sphere(&sphere_assumes_unit_dir);
    assert_family_catches("sphere d·d = 1 assumed", &report, "sphere/dir-scale", 8);
}

#[test]
fn disc_epsilon_is_caught_by_small_spheres() {
    let report = gate(Semantics::WholeLine).sphere(&sphere_disc_epsilon);
    assert_family_catches(
        "sphere b² − ac < 1e-6 a miss",
        &report,
        "sphere/random/small-root",
        8,
    );
    assert_family_catches(
        "sphere b² − ac < 1e-6 a miss",
        &report,
        "sphere/random/far",
        8,
    );
}

/// A miss answered as a hit at `t = 0` (an API where 0 means "no hit",
/// wrapped as a distance).
fn sphere_miss_as_zero(ray: &Ray, s: &Sphere) -> Answer {
    Answer::Nearest(Some(
        sphere::plain::intersect(ray, s)
            .nearest(0.0, f32::INFINITY)
            .unwrap_or(0.0),
    ))
}

#[test]
fn a_miss_answered_as_zero_is_caught_by_rays_behind() {
    let report = gate(Semantics::NearestPositive).sphere(&sphere_miss_as_zero);
    assert_family_catches("sphere miss as t = 0", &report, "sphere/sphere-behind", 250);
}
