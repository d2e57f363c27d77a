//! Ray–sphere: none, tangent and two roots, origins inside, spheres behind
//! the ray, directions of any length, far tiny and huge close spheres, all
//! judged by `rayoracle::check`.
#![cfg(feature = "sphere")]

use crate::support;

use glam::Vec3;
use proptest::prelude::*;
use rayoracle::Ray;
use rayoracle::check::{CaseReport, Status, check_sphere};
use rayoracle::sphere::{Sphere, SphereHit, exact, reference};
use support::*;

fn judge(ray: &Ray, s: &Sphere) -> Result<CaseReport, TestCaseError> {
    x4_agrees(&rayoracle::case::Case::Sphere(*ray, *s))?;
    checked(check_sphere(ray, s, reference::intersect(ray, s)))
}

/// The exact roots of a case whose exact class must be `two`.
fn exact_two(ray: &Ray, s: &Sphere) -> Result<(f32, f32), TestCaseError> {
    match exact::intersect(ray, s) {
        Ok(SphereHit::Two(t0, t1)) => Ok((t0, t1)),
        other => Err(TestCaseError::fail(format!(
            "exact answer {other:?}, expected two roots"
        ))),
    }
}

proptest! {
    /// Arbitrary moderate floats: a mix of none and two.
    #[test]
    fn random_spheres(o in vec_in(20.0), d in vec_in(5.0), c in vec_in(20.0), r in 0.0f32..20.0) {
        judge(&Ray::new(o, d), &Sphere::new(c, r))?;
    }

    /// Exact tangents from Pythagorean quadruples `a² + b² + c² = r²`: the
    /// tangent point is `C + (a, b, c)`, the direction is perpendicular to
    /// `(a, b, c)` (an integer cross product), the origin `s·d` before the
    /// point, and positions and direction are scaled by powers of two. The
    /// oracle must say tangent at `t = s·2^(k−j)` exactly, and so must the
    /// reference: every quantity it forms is an integer times a power of
    /// two, and its `aΔ = (aR)² − |af − bd|²` has `af − bd = a·(a,b,c)`, so
    /// both squares are exact double-word products while `a·r < 2²⁴`
    /// (`r ≤ 64`, `|d| ≤ 4·64·√3` here, so `a·r ≤ 1.3·10⁷`).
    #[test]
    fn tangent_exact(
        (v, r) in pythagorean_quadruple(4), w in ivec(4), c in ivec(100), s in -20i32..=20,
        k in -30i32..=30, j in -20i32..=20,
    ) {
        let d = perp(v, w);
        let (sp, sd) = (2f32.powi(k), 2f32.powi(j));
        let o = add(add(c, v), mul(-s, d));
        let ray = Ray::new(scaled(o, sp), scaled(d, sd));
        let sphere = Sphere::new(scaled(c, sp), r as f32 * sp);
        let t = s as f32 * 2f32.powi(k - j);
        prop_assert_eq!(exact::intersect(&ray, &sphere), Ok(SphereHit::Tangent(t)));
        prop_assert_eq!(reference::intersect(&ray, &sphere), SphereHit::Tangent(t));
        judge(&ray, &sphere)?;
    }

    /// Origin strictly inside: two roots of opposite signs.
    #[test]
    fn origin_inside(c in vec_in(100.0), r in 0.5f32..50.0, u in vec_in(0.5), d in unitish(), sd in log_uniform(-6.0, 6.0)) {
        origin_inside_case(c, r, u, d, sd)?;
    }

    /// The sphere behind the ray: the centre is `λ|d| ≥ 3R` back along the
    /// line, which passes within `0.44 R` of it: two negative roots.
    #[test]
    fn sphere_behind(
        c in vec_in(100.0), r in 1.0f32..10.0, d in unitish(), e in vec_in(0.25),
        lambda in 3.0f32..30.0, sd in log_uniform(-6.0, 6.0),
    ) {
        let d = d * sd;
        let o = c + (lambda * r / d.length()) * d + e * r;
        let ray = Ray::new(o, d);
        let sphere = Sphere::new(c, r);
        let (_, t1) = exact_two(&ray, &sphere)?;
        prop_assert!(t1 < 0.0, "{}", t1);
        judge(&ray, &sphere)?;
    }

    /// The line passes at least `2R` from the centre: none.
    #[test]
    fn miss(
        c in vec_in(100.0), r in 0.5f32..10.0, d in unitish(), side in unitish(),
        reach in 2.0f32..10.0, lambda in -30.0f32..30.0, sd in log_uniform(-6.0, 6.0),
    ) {
        let perp = d.cross(side);
        let perp = if perp.length() > 0.25 { perp } else { d.any_orthonormal_vector() };
        let o = c + perp * (reach * r / perp.length()) + lambda * r * d;
        let ray = Ray::new(o, d * sd);
        let sphere = Sphere::new(c, r);
        prop_assert_eq!(exact::intersect(&ray, &sphere), Ok(SphereHit::None));
        judge(&ray, &sphere)?;
    }

    /// Directions of length 10⁻⁶ to 10⁶ (log-uniform) through a unit-sized
    /// scene: the roots scale as `1/|d|` and stay accurate.
    #[test]
    fn direction_length(o in vec_in(5.0), d in unitish(), c in vec_in(1.0), r in 0.5f32..3.0, sd in log_uniform(-6.0, 6.0)) {
        direction_length_case(o, d, c, r, sd)?;
    }

    /// A unit sphere `10³…10⁷` away, on the line of an integer direction,
    /// seen from an origin within ¼ of the world origin: two roots whose
    /// nearer one the textbook formula would cancel away.
    #[test]
    fn far_tiny(d in ivec_nonzero(12), dist in log_uniform(3.0, 7.0), o in vec_in(0.25), sd in pow2(-10, 10)) {
        let len = (idot(d, d) as f32).sqrt();
        let lambda = (dist / len).round().max(1.0);
        let c = scaled(d, lambda);
        let ray = Ray::new(o, scaled(d, sd));
        let sphere = Sphere::new(c, 1.0);
        let (t0, t1) = exact_two(&ray, &sphere)?;
        prop_assert!(t0 > 0.0 && t1 > t0);
        judge(&ray, &sphere)?;
    }

    /// Random directions at far tiny spheres (mostly misses; near misses
    /// exercise the band).
    #[test]
    fn far_tiny_random(o in vec_in(1.0), d in unitish(), c in unitish(), dist in log_uniform(3.0, 7.0), r in 0.1f32..2.0) {
        judge(&Ray::new(o, d), &Sphere::new(c * dist, r))?;
    }

    /// Huge spheres (`R` 10³…10⁷) with the origin within ±10 of the surface,
    /// inside or out, looking anywhere.
    #[test]
    fn huge_close(c in vec_in(1.0), u in unitish(), r in log_uniform(3.0, 7.0), gap in -10.0f32..10.0, d in unitish(), sd in log_uniform(-3.0, 3.0)) {
        huge_close_case(c, u, (r, gap), d, sd)?;
    }

    /// Origin exactly on the surface (integer quadruple), any direction:
    /// one root is exactly 0.
    #[test]
    fn origin_on_surface((v, r) in pythagorean_quadruple(4), c in ivec(100), d in ivec_nonzero(50), sp in pow2(-20, 20)) {
        let ray = Ray::new(scaled(add(c, v), sp), scaled(d, 1.0));
        let sphere = Sphere::new(scaled(c, sp), r as f32 * sp);
        let roots = exact::intersect(&ray, &sphere).map(|h| {
            use rayoracle::hit::Intersection;
            h.roots().as_slice().to_vec()
        });
        prop_assert!(roots.as_ref().is_ok_and(|rs| rs.contains(&0.0)), "{:?}", roots);
        judge(&ray, &sphere)?;
    }
}

/// Directions parallel to an axis at the extremes of the range, a subnormal
/// radius and a sphere near `f32::MAX` go through the same judge.
/// [`origin_inside`]'s check: the origin `c + u r`, inside.
fn origin_inside_case(c: Vec3, r: f32, u: Vec3, d: Vec3, sd: f32) -> Result<(), TestCaseError> {
    let ray = Ray::new(c + u * r, d * sd);
    let sphere = Sphere::new(c, r);
    let (t0, t1) = exact_two(&ray, &sphere)?;
    prop_assert!(t0 < 0.0 && t1 > 0.0, "{} {}", t0, t1);
    judge(&ray, &sphere)?;
    Ok(())
}

/// [`direction_length`]'s check: the direction `d` scaled by `sd`.
fn direction_length_case(o: Vec3, d: Vec3, c: Vec3, r: f32, sd: f32) -> Result<(), TestCaseError> {
    judge(&Ray::new(o, d * sd), &Sphere::new(c, r))?;
    Ok(())
}

/// [`huge_close`]'s check: the origin `gap` from the surface along `u`.
fn huge_close_case(
    c: Vec3,
    u: Vec3,
    (r, gap): (f32, f32),
    d: Vec3,
    sd: f32,
) -> Result<(), TestCaseError> {
    let o = c + u * ((r + gap) / u.length());
    let r = judge(&Ray::new(o, d * sd), &Sphere::new(c, r))?;
    prop_assert!(r.status != Status::NonFinite);
    Ok(())
}

/// The shrunk failures recorded in `props_sphere.proptest-regressions`,
/// each through its property's check with the values proptest reported, so
/// that they stay tests whatever the strategies come to generate from the
/// recorded seeds.
#[test]
fn recorded_failures() {
    let (v, zero) = (Vec3::new, Vec3::ZERO);
    assert_recorded([
        (
            "direction_length",
            direction_length_case(
                v(0.0, 1.9389585, 0.0),
                v(0.0, 0.6763975, 0.0),
                zero,
                0.5,
                1.0,
            ),
        ),
        (
            "huge_close",
            huge_close_case(
                zero,
                v(0.0, 0.0, -0.5759571),
                (1000.0, -1.2018872),
                v(0.0, 0.0, -0.89047),
                1.0,
            ),
        ),
        (
            "origin_inside",
            origin_inside_case(zero, 0.5, zero, v(0.0, 0.0, -0.82302976), 1.0),
        ),
    ]);
}

#[test]
fn extreme_scales() {
    let cases = [
        (
            Vec3::new(0.0, 0.0, -5.0),
            Vec3::new(0.0, 0.0, 1e-30),
            Vec3::ZERO,
            1.0,
        ),
        (
            Vec3::new(0.0, 0.0, -5.0),
            Vec3::new(0.0, 0.0, 1e30),
            Vec3::ZERO,
            1.0,
        ),
        (Vec3::new(0.0, 0.0, -5e-44), Vec3::Z, Vec3::ZERO, 1e-44),
        (Vec3::new(0.0, 0.0, -3e38), Vec3::Z, Vec3::ZERO, 1e38),
    ];
    for (o, d, c, r) in cases {
        let (ray, s) = (Ray::new(o, d), Sphere::new(c, r));
        let rep = check_sphere(&ray, &s, reference::intersect(&ray, &s))
            .unwrap_or_else(|v| panic!("{v}"));
        assert_eq!(rep.exact_class, "two", "{o} {d} {r}");
    }
}
