//! Ray–quadric: random general quadrics, `α = 0` (one root, or all/none),
//! lines lying on the surface (`All`), judged by `rayoracle::check`.
#![cfg(feature = "quadric")]

use crate::support;

use glam::Vec3;
use proptest::prelude::*;
use rayoracle::Ray;
use rayoracle::check::{CaseReport, Status, check_quadric};
use rayoracle::quadric::{Quadric, QuadricHit, exact, reference};
use support::*;

fn judge(ray: &Ray, q: &Quadric) -> Result<CaseReport, TestCaseError> {
    x4_agrees(&rayoracle::case::Case::Quadric(*ray, *q))?;
    checked(check_quadric(ray, q, reference::intersect(ray, q)))
}

/// Asserts that both the oracle and the reference find the line on the
/// surface, then judges.
fn assert_all(ray: &Ray, q: &Quadric) -> Result<(), TestCaseError> {
    prop_assert_eq!(exact::intersect(ray, q), Ok(QuadricHit::All));
    prop_assert_eq!(reference::intersect(ray, q), QuadricHit::All);
    judge(ray, q)?;
    Ok(())
}

fn coeffs(k: [i32; 10], s: f32) -> Quadric {
    Quadric::new(k.map(|x| x as f32 * s))
}

/// Ten random coefficients, about a third of them zero.
fn random_coeffs() -> impl Strategy<Value = [f32; 10]> {
    proptest::array::uniform10(prop_oneof![1 => Just(0.0f32), 2 => -10.0f32..10.0])
}

proptest! {
    /// Random general quadrics and rays.
    #[test]
    fn random_quadrics(k in random_coeffs(), o in vec_in(10.0), d in vec_in(5.0)) {
        random_case(k, o, d)?;
    }

    /// Random quadrics scaled by a power of two and rays with directions of
    /// any length: the surface and the roots transform exactly.
    #[test]
    fn random_quadrics_scaled(k in random_coeffs(), s in pow2(-60, 60), o in vec_in(10.0), d in unitish(), sd in log_uniform(-6.0, 6.0)) {
        judge(&Ray::new(o, d * sd), &Quadric::new(k.map(|x| x * s)))?;
    }

    /// The paraboloid `A x² + B y² + G x + H y + I z + J = 0` (any `A`, `B`,
    /// `I ≠ 0`) hit along its axis: `α = 0`, `β = I d_z`, one root.
    #[test]
    fn alpha_zero_paraboloid(
        a in -10.0f32..10.0, b in -10.0f32..10.0, g in -10.0f32..10.0, h in -10.0f32..10.0,
        i in prop_oneof![-10.0f32..-0.1, 0.1f32..10.0], j in -10.0f32..10.0,
        o in vec_in(10.0), dz in prop_oneof![-1e3f32..-1e-3, 1e-3f32..1e3],
    ) {
        let q = Quadric::new([a, b, 0.0, 0.0, 0.0, 0.0, g, h, i, j]);
        let ray = Ray::new(o, Vec3::new(0.0, 0.0, dz));
        let e = exact::intersect(&ray, &q);
        prop_assert!(matches!(e, Ok(QuadricHit::One(_))), "{:?}", e);
        prop_assert!(matches!(reference::intersect(&ray, &q), QuadricHit::One(_)));
        judge(&ray, &q)?;
    }

    /// The cylinder around an integer axis `w` through an integer point `p`,
    /// `|w|²|x − p|² − ((x − p)·w)² = |e|²|w|²` with `e ⟂ w`, and a ray along
    /// the axis: `α = β = 0`. From `p + e + λw` the ray is a ruling (all);
    /// from `p + 2e` it is off the surface (none).
    #[test]
    fn alpha_zero_cylinder(
        w in ivec_nonzero(3), x in ivec(3), p in ivec(5), lambda in -3i32..=3, sd in pow2(-20, 20), on in any::<bool>(),
    ) {
        let e = perp(w, x);
        let q = cylinder(w, p, e);
        let o = add(p, add(mul(if on { 1 } else { 2 }, e), mul(lambda, w)));
        let ray = Ray::new(scaled(o, 1.0), scaled(w, sd));
        if on {
            assert_all(&ray, &q)?;
        } else {
            prop_assert_eq!(exact::intersect(&ray, &q), Ok(QuadricHit::None));
            prop_assert_eq!(reference::intersect(&ray, &q), QuadricHit::None);
            judge(&ray, &q)?;
        }
    }

    /// A cone `(x−Px)² + (y−Py)² − (z−Pz)² = 0` times an integer and a power
    /// of two, and a line through the apex along a ruling `(a, b, c)` with
    /// `a² + b² = c²`: all.
    #[test]
    fn all_cone_ruling(t in pythagorean_triple(6), p in ivec(20), lambda in -5i32..=5, mult in 1i32..=5, s in pow2(-30, 30), sd in pow2(-10, 10)) {
        let k = [1, 1, -1, 0, 0, 0, -2 * p[0], -2 * p[1], 2 * p[2], p[0] * p[0] + p[1] * p[1] - p[2] * p[2]];
        let q = coeffs(k.map(|x| x * mult), s);
        let o = add(p, mul(lambda, t));
        assert_all(&Ray::new(scaled(o, 1.0), scaled(t, sd)), &q)?;
    }

    /// The pair of planes `(n₁·x + c₁)(n₂·x + c₂) = 0` with integer data,
    /// and a line in the first plane: all.
    #[test]
    fn all_plane_pair(n1 in ivec_nonzero(6), n2 in ivec_nonzero(6), o in ivec(20), c2 in -20i32..=20, w in ivec(6), sd in pow2(-10, 10)) {
        let d = perp(n1, w);
        let c1 = -(idot(n1, o) as i32);
        let k = [
            n1[0] * n2[0], n1[1] * n2[1], n1[2] * n2[2],
            n1[0] * n2[1] + n1[1] * n2[0], n1[0] * n2[2] + n1[2] * n2[0], n1[1] * n2[2] + n1[2] * n2[1],
            c1 * n2[0] + c2 * n1[0], c1 * n2[1] + c2 * n1[1], c1 * n2[2] + c2 * n1[2],
            c1 * c2,
        ];
        assert_all(&Ray::new(scaled(o, 1.0), scaled(d, sd)), &coeffs(k, 1.0))?;
    }

    /// `xy = 0` with any line in the plane `x = 0`: all, for any floats.
    #[test]
    fn all_xy_pair(o in vec_in(100.0), d in vec_in(100.0), s in log_uniform(-10.0, 10.0)) {
        let q = Quadric::new([0.0, 0.0, 0.0, s, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        assert_all(&Ray::new(Vec3::new(0.0, o.y, o.z), Vec3::new(0.0, d.y, d.z)), &q)?;
    }

    /// The hyperboloid of one sheet `x² + y² − z² = c²` and its rulings
    /// through `(a, b, 0)` along `(−b, a, ±c)`, `a² + b² = c²`: all.
    #[test]
    fn all_hyperboloid_ruling(t in pythagorean_triple(6), plus in any::<bool>(), lambda in -5i32..=5, s in pow2(-30, 30), sd in pow2(-10, 10)) {
        let [a, b, c] = t;
        let q = coeffs([1, 1, -1, 0, 0, 0, 0, 0, 0, -c * c], s);
        let d = [-b, a, if plus { c } else { -c }];
        let o = add([a, b, 0], mul(lambda, d));
        assert_all(&Ray::new(scaled(o, 1.0), scaled(d, sd)), &q)?;
    }

    /// Origins beyond `2⁴⁰` are no exception: the exact answer, checked.
    #[test]
    fn far_origin_is_exact(k in random_coeffs(), o in unitish(), d in unitish()) {
        far_origin_case(k, o, d)?;
    }
}

/// [`random_quadrics`]'s check.
fn random_case(k: [f32; 10], o: Vec3, d: Vec3) -> Result<(), TestCaseError> {
    judge(&Ray::new(o, d), &Quadric::new(k))?;
    Ok(())
}

/// [`far_origin_is_exact`]'s check: the origin `o` moved out by `10¹³`.
fn far_origin_case(k: [f32; 10], o: Vec3, d: Vec3) -> Result<(), TestCaseError> {
    let r = judge(&Ray::new(o * 1e13, d), &Quadric::new(k))?;
    prop_assert!(matches!(r.status, Status::Checked | Status::NonFinite));
    Ok(())
}

/// The shrunk failure recorded in `props_quadric.proptest-regressions`,
/// with the values proptest reported, through both properties that draw
/// `(k, o, d)` (the record does not name its property), so that it stays a
/// test whatever the strategies come to generate from the recorded seed.
#[test]
fn recorded_failures() {
    let (o, d) = (
        Vec3::new(0.0, -0.9844189, 0.0),
        Vec3::new(0.0, 0.0, -0.58496946),
    );
    assert_recorded([
        ("random_quadrics", random_case([0.0; 10], o, d)),
        ("far_origin_is_exact", far_origin_case([0.0; 10], o, d)),
    ]);
}

/// `|w|²|x − p|² − ((x − p)·w)² − |e|²|w|² = 0`, expanded.
fn cylinder(w: [i32; 3], p: [i32; 3], e: [i32; 3]) -> Quadric {
    let ww = idot(w, w) as i32;
    let ee = idot(e, e) as i32;
    // M = |w|² I − w wᵀ; the quadric is (x−p)ᵀ M (x−p) − |e|²|w|².
    let m = |i: usize, j: usize| {
        if i == j {
            ww - w[i] * w[i]
        } else {
            -w[i] * w[j]
        }
    };
    let mp = [0, 1, 2].map(|i| (0..3).map(|j| m(i, j) * p[j]).sum::<i32>());
    let pmp: i32 = (0..3).map(|i| p[i] * mp[i]).sum();
    coeffs(
        [
            m(0, 0),
            m(1, 1),
            m(2, 2),
            2 * m(0, 1),
            2 * m(0, 2),
            2 * m(1, 2),
            -2 * mp[0],
            -2 * mp[1],
            -2 * mp[2],
            pmp - ee * ww,
        ],
        1.0,
    )
}
