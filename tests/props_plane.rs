//! Ray–plane: the three cases (hit, parallel, in-plane), judged by
//! `rayoracle::check`, with the exact class asserted where the construction
//! fixes it.
#![cfg(feature = "plane")]

use crate::support;

use glam::Vec3;
use proptest::prelude::*;
use rayoracle::Ray;
use rayoracle::check::{Status, check_plane};
use rayoracle::plane::{Plane, PlaneHit, exact, reference};
use support::*;

fn judge(ray: &Ray, p: &Plane) -> Result<rayoracle::check::CaseReport, TestCaseError> {
    x4_agrees(&rayoracle::case::Case::Plane(*ray, *p))?;
    checked(check_plane(ray, p, reference::intersect(ray, p)))
}

proptest! {
    /// Arbitrary floats of moderate size: almost always a hit.
    #[test]
    fn random_planes(o in vec_in(100.0), d in vec_in(10.0), a in vec_in(100.0), n in vec_in(10.0)) {
        judge(&Ray::new(o, d), &Plane::new(a, n))?;
    }

    /// `d·n ≠ 0` by construction (integers times powers of two): a hit,
    /// wherever the plane is and however the vectors are scaled, from
    /// subnormal normals to planes at 10³⁰.
    #[test]
    fn hit(
        n in ivec_nonzero(50), d in ivec_nonzero(50),
        sn in pow2(-149 + 6, 100), sd in pow2(-100, 100),
        o in vec_in(1.0), a in vec_in(1.0), so in log_uniform(-30.0, 30.0), sa in log_uniform(-30.0, 30.0),
    ) {
        hit_case(n, d, (sn, sd), (o, a), (so, sa))?;
    }

    /// `d ⟂ n` exactly and the origin off the plane (integer data times
    /// powers of two): parallel, and the reference must see the exact zero.
    #[test]
    fn parallel(
        n in ivec_nonzero(40), w in ivec(40), pa in ivec(1000), po in ivec(1000),
        sn in pow2(-120, 100), sd in pow2(-100, 100), sp in pow2(-60, 60),
    ) {
        let d = perp(n, w);
        prop_assume!(idot(add(pa, mul(-1, po)), n) != 0);
        let ray = Ray::new(scaled(po, sp), scaled(d, sd));
        let plane = Plane::new(scaled(pa, sp), scaled(n, sn));
        prop_assert_eq!(exact::intersect(&ray, &plane), Ok(PlaneHit::Parallel));
        prop_assert_eq!(reference::intersect(&ray, &plane), PlaneHit::Parallel);
        judge(&ray, &plane)?;
    }

    /// `d ⟂ n` and the origin exactly on the plane: every `t`.
    #[test]
    fn in_plane(
        n in ivec_nonzero(40), w in ivec(40), e1 in ivec(40), e2 in ivec(40), pa in ivec(1000),
        u in -20i32..=20, v in -20i32..=20,
        sn in pow2(-120, 100), sd in pow2(-100, 100), sp in pow2(-60, 60),
    ) {
        let d = perp(n, w);
        // o = a + u (n × e1) + v (n × e2) lies on the plane.
        let po = add(pa, add(mul(u, cross(n, e1)), mul(v, cross(n, e2))));
        let ray = Ray::new(scaled(po, sp), scaled(d, sd));
        let plane = Plane::new(scaled(pa, sp), scaled(n, sn));
        prop_assert_eq!(exact::intersect(&ray, &plane), Ok(PlaneHit::InPlane));
        prop_assert_eq!(reference::intersect(&ray, &plane), PlaneHit::InPlane);
        judge(&ray, &plane)?;
    }

    /// The origin exactly on the plane but the ray crossing it: `t = 0`.
    #[test]
    fn origin_on_plane(
        n in ivec_nonzero(40), d in ivec_nonzero(40), e1 in ivec(40), pa in ivec(1000), u in -20i32..=20,
        sn in pow2(-120, 100), sd in pow2(-100, 100), sp in pow2(-60, 60),
    ) {
        prop_assume!(idot(n, d) != 0);
        let po = add(pa, mul(u, cross(n, e1)));
        let ray = Ray::new(scaled(po, sp), scaled(d, sd));
        let plane = Plane::new(scaled(pa, sp), scaled(n, sn));
        let Ok(PlaneHit::Hit(t)) = exact::intersect(&ray, &plane) else {
            return Err(TestCaseError::fail("the exact class is not hit"));
        };
        prop_assert_eq!(t, 0.0);
        let PlaneHit::Hit(t) = reference::intersect(&ray, &plane) else {
            return Err(TestCaseError::fail("the reference class is not hit"));
        };
        prop_assert_eq!(t, 0.0);
        judge(&ray, &plane)?;
    }

    /// Nearly parallel rays (`d = d⟂ + ε n`): the class may flip only inside
    /// the band, and a hit must still be accurate for its condition number.
    #[test]
    fn nearly_parallel(
        n in unitish(), w in unitish(), o in vec_in(10.0), a in vec_in(10.0), eps in log_uniform(-12.0, -1.0),
    ) {
        nearly_parallel_case(n, w, o, a, eps)?;
    }

    /// A line parallel to the plane term by term but for one tiny product:
    /// `d = n × eᵢ` (scaled) with its zero component set to `ε`, so `d·n =
    /// εnᵢ` exactly while the other two products cancel, as in the stiff
    /// catalogue's near-parallel family, for `ε` from about 1 down to
    /// subnormal. The plane's second pass decides most of these; the
    /// answers of the reference and x4 are the oracle's.
    #[test]
    fn parallel_but_for_one_tiny_term(
        n in unitish(), i in 0usize..3, m in 1u32..(1 << 24), e in -160i32..0,
        o in vec_in(100.0), a in vec_in(100.0), s in log_uniform(-20.0, 20.0),
    ) {
        one_tiny_term_case(n, i, (m, e), (o, a), s)?;
    }
}

/// [`hit`]'s check: `n` and `d` scaled by `sn`, `sd`; `o` and `a` by `so`,
/// `sa`.
fn hit_case(
    n: [i32; 3],
    d: [i32; 3],
    (sn, sd): (f32, f32),
    (o, a): (Vec3, Vec3),
    (so, sa): (f32, f32),
) -> Result<(), TestCaseError> {
    prop_assume!(idot(n, d) != 0);
    let ray = Ray::new(o * so, scaled(d, sd));
    let plane = Plane::new(a * sa, scaled(n, sn));
    let r = judge(&ray, &plane)?;
    prop_assert_eq!(r.exact_class, "hit");
    prop_assert_eq!(r.status, Status::Checked);
    Ok(())
}

/// [`nearly_parallel`]'s check.
fn nearly_parallel_case(n: Vec3, w: Vec3, o: Vec3, a: Vec3, eps: f32) -> Result<(), TestCaseError> {
    let d = n.cross(w) + eps * n;
    prop_assume!(d != Vec3::ZERO);
    judge(&Ray::new(o, d), &Plane::new(a, n))?;
    Ok(())
}

/// [`parallel_but_for_one_tiny_term`]'s check: component `i` of `d` set to
/// `m·2^(e − 24)`.
fn one_tiny_term_case(
    n: Vec3,
    i: usize,
    (m, e): (u32, i32),
    (o, a): (Vec3, Vec3),
    s: f32,
) -> Result<(), TestCaseError> {
    let mut d = n.cross(Vec3::AXES[i]) * s;
    d[i] = (f64::from(m) * 2f64.powi(e - 24)) as f32;
    judge(&Ray::new(o, d), &Plane::new(a, n))?;
    Ok(())
}

/// The shrunk failures recorded in `props_plane.proptest-regressions`, each
/// through its property's check with the values proptest reported, so that
/// they stay tests whatever the strategies come to generate from the
/// recorded seeds.
#[test]
fn recorded_failures() {
    let v = Vec3::new;
    let cases: [(&str, Result<(), TestCaseError>); 3] = [
        (
            "hit",
            hit_case(
                [0, 0, 1],
                [0, 0, 1],
                (1.0, 1.0),
                (v(0.0, 0.0, 0.18864065), v(0.0, 0.0, 0.028765123)),
                (3.5373272e-29, 1.5924287e20),
            ),
        ),
        (
            "parallel_but_for_one_tiny_term",
            one_tiny_term_case(
                v(-0.13230738, 0.41377276, 0.39880395),
                0,
                (14312467, -91),
                (
                    v(36.71322, 0.0, 14.040102),
                    v(-65.51939, 35.416805, -24.536283),
                ),
                1.0,
            ),
        ),
        (
            "nearly_parallel",
            nearly_parallel_case(
                v(-0.5419659, -0.5195481, 0.4414962),
                v(-0.37756896, 0.9356014, -0.8069887),
                v(0.0, 0.0, 0.0),
                v(0.0, 0.0, 8.763067),
                5.069713e-10,
            ),
        ),
    ];
    assert_recorded(cases);
}
