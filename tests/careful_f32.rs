//! A careful pure-f32 sphere kernel passes the declaration that describes
//! it honestly, `Declared::careful_f32_renderer`, in every nearest-hit
//! semantics and answer form, and fails where it should: without the
//! preconditions it is meant for, and the textbook formula fails even with
//! them.
#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]

use glam::Vec3;
use rayoracle::Ray;
use rayoracle::check::gate::{Answer, Declared, Gate, Report, Semantics};
use rayoracle::sphere::Sphere;

/// Every root of the careful f32 sphere, all in f32 (Ray Tracing Gems ch.
/// 7): the discriminant `R² − |f − (f·d̂)d̂|²`, the stable quadratic `q =
/// −b − sign(b)√(aΔ)`, `t₀ = c/q`, `t₁ = q/a`.
fn careful_roots(ray: &Ray, s: &Sphere) -> Vec<f32> {
    let (d, r) = (ray.dir, s.radius);
    let f = ray.origin - s.center;
    let (a, b, c) = (d.dot(d), f.dot(d), f.dot(f) - r * r);
    let dn = d / a.sqrt();
    let l = f - f.dot(dn) * dn;
    let disc = r * r - l.dot(l);
    if !(disc >= 0.0 && a > 0.0) {
        return vec![];
    }
    let q = -b - (a * disc).sqrt().copysign(b);
    if q == 0.0 {
        // b = 0 and Δ = 0: a tangent at t = 0.
        return vec![-b / a];
    }
    let (t0, t1) = (c / q, q / a);
    if t0 <= t1 { vec![t0, t1] } else { vec![t1, t0] }
}

/// The textbook `b² − ac` in f32, for contrast.
fn textbook_roots(ray: &Ray, s: &Sphere) -> Vec<f32> {
    let (d, f) = (ray.dir, ray.origin - s.center);
    let (a, b, c) = (d.dot(d), f.dot(d), f.dot(f) - s.radius * s.radius);
    let disc = b * b - a * c;
    if !(disc >= 0.0 && a > 0.0) {
        return vec![];
    }
    let r = disc.sqrt();
    vec![(-b - r) / a, (-b + r) / a]
}

fn in_range(roots: Vec<f32>, lo: f32, hi: f32) -> Option<f32> {
    roots.into_iter().find(|&t| lo < t && t < hi)
}

fn nearest(ray: &Ray, s: &Sphere) -> Answer {
    Answer::Nearest(in_range(careful_roots(ray, s), 0.0, f32::INFINITY))
}

fn segment(ray: &Ray, s: &Sphere) -> Answer {
    Answer::Nearest(in_range(careful_roots(ray, s), 1e-3, 1e30))
}

fn whole_line(ray: &Ray, s: &Sphere) -> Answer {
    Answer::Roots(careful_roots(ray, s))
}

/// `t = 0` where `|f|² − R² ≤ 0` in f32, else the nearest `t > 0`.
fn solid(ray: &Ray, s: &Sphere) -> Answer {
    let f = ray.origin - s.center;
    if f.dot(f) - s.radius * s.radius <= 0.0 {
        return Answer::Nearest(Some(0.0));
    }
    nearest(ray, s)
}

/// The nearest hit's point, `o + t·d` in f32.
fn point(ray: &Ray, s: &Sphere) -> Answer {
    Answer::Point(
        in_range(careful_roots(ray, s), 0.0, f32::INFINITY).map(|t| ray.origin + t * ray.dir),
    )
}

fn textbook(ray: &Ray, s: &Sphere) -> Answer {
    Answer::Nearest(in_range(textbook_roots(ray, s), 0.0, f32::INFINITY))
}

fn careful(semantics: Semantics) -> Gate {
    Gate::new(Declared::careful_f32_renderer(semantics))
}

fn fails(r: &Report, family: &str) -> bool {
    r.failing_families().contains(&family)
}

#[test]
fn the_careful_sphere_passes_its_honest_declaration() {
    let runs = [
        careful(Semantics::NearestPositive).sphere(&nearest),
        careful(Semantics::NearestPositive).sphere(&point),
        careful(Semantics::WholeLine).sphere(&whole_line),
        careful(Semantics::Solid).sphere(&solid),
        careful("range:0.001:1e30".parse().unwrap()).sphere(&segment),
    ];
    for r in &runs {
        r.assert_ok();
        let skipped: usize = r.skipped.iter().map(|s| s.1).sum();
        assert!(
            r.cases > 2000 && skipped < r.cases / 10,
            "{} {:?}",
            r.cases,
            r.skipped
        );
        let names: Vec<&str> = r.skipped.iter().map(|s| s.0.as_str()).collect();
        assert_eq!(names, ["unit-dirs", "no-subnormals", "magnitudes"]);
    }
}

#[test]
fn without_its_preconditions_the_careful_sphere_fails() {
    let any = Gate::new(Declared::f32(Semantics::NearestPositive)).sphere(&nearest);
    for family in [
        "sphere/dir-tiny",
        "sphere/subnormal",
        "sphere/huge",
        "sphere/far-tiny",
    ] {
        assert!(
            fails(&any, family),
            "{family}: {:?}",
            any.failing_families()
        );
    }
    let preset = Declared::careful_f32_renderer(Semantics::NearestPositive);
    let without = |d: Declared| Gate::new(d).sphere(&nearest);
    // A tiny direction is normalised (or skipped) with unit directions,
    // and fails without them, where no magnitude range skips it.
    let r = without(Declared {
        magnitudes: None,
        ..preset
    });
    assert!(!fails(&r, "sphere/dir-tiny"), "{:?}", r.failing_families());
    let r = without(Declared {
        magnitudes: None,
        unit_dirs_only: false,
        ..preset
    });
    assert!(fails(&r, "sphere/dir-tiny"), "{:?}", r.failing_families());
    assert!(!fails(&r, "sphere/subnormal"), "{:?}", r.failing_families());
    assert!(fails(&r, "sphere/huge"), "{:?}", r.failing_families());
    let r = without(Declared {
        magnitudes: None,
        no_subnormals: false,
        ..preset
    });
    assert!(fails(&r, "sphere/subnormal"), "{:?}", r.failing_families());
}

#[test]
fn the_textbook_sphere_fails_the_careful_declaration() {
    let r = careful(Semantics::NearestPositive).sphere(&textbook);
    assert!(fails(&r, "sphere/far-tiny"), "{:?}", r.failing_families());
}

#[test]
fn a_solid_kernel_must_answer_zero_inside() {
    // The nearest-positive kernel answers the far root from inside.
    let r = careful(Semantics::Solid).sphere(&nearest);
    assert!(
        fails(&r, "sphere/origin-inside"),
        "{:?}",
        r.failing_families()
    );
    let inside = (Ray::new(Vec3::ZERO, Vec3::Z), Sphere::new(Vec3::ZERO, 2.0));
    let g = careful(Semantics::Solid);
    assert!(
        g.judge_sphere(&inside.0, &inside.1, Answer::Nearest(Some(0.0)))
            .is_ok()
    );
    let f = g
        .judge_sphere(&inside.0, &inside.1, Answer::Nearest(Some(2.0)))
        .unwrap_err();
    assert!(f.why.contains("inside"), "{}", f.why);
}

#[test]
fn a_segment_kernel_must_keep_to_its_range() {
    // A kernel that ignores t_max answers hits beyond it.
    let r = careful("range:0.001:5".parse().unwrap()).sphere(&segment);
    assert!(!r.failures.is_empty());
    let short = careful("range:0.001:5".parse().unwrap());
    let k = |ray: &Ray, s: &Sphere| Answer::Nearest(in_range(careful_roots(ray, s), 1e-3, 5.0));
    short.sphere(&k).assert_ok();
}
