#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
//! Known-wrong quadric kernels, each a plausible slip on top of a correct
//! kernel (`quadric::plain`, or the f64 expansion below), each caught by a
//! whole family.

use super::known_wrong::{assert_family_catches, gate};
use rayoracle::check::gate::{Answer, Semantics};
use rayoracle::quadric::{self, Quadric, QuadricHit};
use rayoracle::{Ray, hit::Intersection};

/// `quadric::plain` (correct) on the coefficients `edit` makes of the
/// quadric's: a slip in reading them.
fn plain_on(ray: &Ray, q: &Quadric, edit: impl Fn([f32; 10]) -> [f32; 10]) -> Answer {
    Answer::roots(quadric::plain::intersect(
        ray,
        &Quadric::new(edit(q.coeffs)),
    ))
}

/// The `xy` and `yz` coefficients read in each other's place.
fn quadric_xy_yz_swapped(ray: &Ray, q: &Quadric) -> Answer {
    plain_on(ray, q, |mut k| {
        k.swap(3, 5);
        k
    })
}

/// The cross terms halved: `D, E, F` taken as the symmetric matrix's
/// off-diagonal entries, whose sum `2Q₀₁ xy` then lacks its factor 2.
fn quadric_cross_halved(ray: &Ray, q: &Quadric) -> Answer {
    plain_on(ray, q, |mut k| {
        for c in &mut k[3..6] {
            *c *= 0.5;
        }
        k
    })
}

/// α, β, γ in f64 by the expansion of `quadric`'s docs, the factor 2 of
/// β's square terms written `two` (2 is right, 1 the slip), solved with
/// an `|α| < alpha_eps` test for the linear case (0 is right).
fn quadric_f64(ray: &Ray, q: &Quadric, two: f64, alpha_eps: f64) -> QuadricHit {
    let [a, b, c, d, e, f, g, h, i, j] = q.coeffs.map(f64::from);
    let (o, v) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
    let alpha = a * v.x * v.x
        + b * v.y * v.y
        + c * v.z * v.z
        + d * v.x * v.y
        + e * v.x * v.z
        + f * v.y * v.z;
    let beta = two * (a * o.x * v.x + b * o.y * v.y + c * o.z * v.z)
        + d * (o.x * v.y + v.x * o.y)
        + e * (o.x * v.z + v.x * o.z)
        + f * (o.y * v.z + v.y * o.z)
        + g * v.x
        + h * v.y
        + i * v.z;
    let gamma = a * o.x * o.x
        + b * o.y * o.y
        + c * o.z * o.z
        + d * o.x * o.y
        + e * o.x * o.z
        + f * o.y * o.z
        + g * o.x
        + h * o.y
        + i * o.z
        + j;
    if alpha.abs() <= alpha_eps {
        return match (beta == 0.0, gamma == 0.0) {
            (false, _) => QuadricHit::One((-gamma / beta) as f32),
            (true, true) => QuadricHit::All,
            (true, false) => QuadricHit::None,
        };
    }
    let disc = beta * beta - 4.0 * alpha * gamma;
    if disc < 0.0 || disc.is_nan() {
        QuadricHit::None
    } else if disc == 0.0 {
        QuadricHit::One((-beta / (2.0 * alpha)) as f32)
    } else {
        let qq = -0.5 * (beta + disc.sqrt().copysign(beta));
        let (t0, t1) = ((qq / alpha) as f32, (gamma / qq) as f32);
        QuadricHit::Two(t0.min(t1), t0.max(t1))
    }
}

/// β's square terms without their factor 2.
fn quadric_beta_missing_two(ray: &Ray, q: &Quadric) -> Answer {
    Answer::roots(quadric_f64(ray, q, 1.0, 0.0))
}

/// `|α| < 10⁻⁶` taken as a linear equation: the near-α-zero root `−γ/β`
/// is kept and the far root (about `−β/α`) dropped.
fn quadric_alpha_epsilon(ray: &Ray, q: &Quadric) -> Answer {
    Answer::roots(quadric_f64(ray, q, 2.0, 1e-6))
}

/// A line on the surface answered as a miss (`α = β = 0` means none,
/// whatever `γ`).
fn quadric_all_as_none(ray: &Ray, q: &Quadric) -> Answer {
    match quadric::plain::intersect(ray, q) {
        QuadricHit::All => Answer::Roots(vec![]),
        h => Answer::roots(h),
    }
}

/// The nearest `t` of `quadric::plain` that `keep` accepts.
fn nearest_where(ray: &Ray, q: &Quadric, keep: impl Fn(f32) -> bool) -> Answer {
    let h = quadric::plain::intersect(ray, q);
    if h.is_everywhere() {
        return Answer::Everywhere;
    }
    Answer::Nearest(h.roots().as_slice().iter().copied().find(|&t| keep(t)))
}

fn quadric_epsilon_1e4(ray: &Ray, q: &Quadric) -> Answer {
    nearest_where(ray, q, |t| t > 1e-4)
}

fn quadric_epsilon_machine(ray: &Ray, q: &Quadric) -> Answer {
    nearest_where(ray, q, |t| t > f32::EPSILON)
}

fn quadric_t_nonnegative(ray: &Ray, q: &Quadric) -> Answer {
    nearest_where(ray, q, |t| t >= 0.0)
}

#[test]
fn xy_yz_swap_is_caught_by_random_quadrics() {
    let report = gate(Semantics::WholeLine).quadric(&quadric_xy_yz_swapped);
    assert_family_catches("quadric xy ↔ yz", &report, "quadric/random/any", 100);
}

#[test]
fn halved_cross_terms_are_caught_by_random_quadrics() {
    let report = gate(Semantics::WholeLine).quadric(&quadric_cross_halved);
    assert_family_catches(
        "quadric cross terms / 2",
        &report,
        "quadric/random/any",
        100,
    );
}

#[test]
fn beta_missing_two_is_caught_by_random_quadrics() {
    let report = gate(Semantics::WholeLine).quadric(&quadric_beta_missing_two);
    assert_family_catches("quadric β without 2", &report, "quadric/random/any", 100);
}

#[test]
fn alpha_epsilon_is_caught_near_alpha_zero() {
    let report = gate(Semantics::WholeLine).quadric(&quadric_alpha_epsilon);
    assert_family_catches(
        "quadric |α| < 1e-6 linear",
        &report,
        "quadric/alpha-near-zero",
        8,
    );
}

#[test]
fn all_as_none_is_caught_by_lines_on_the_surface() {
    let report = gate(Semantics::WholeLine).quadric(&quadric_all_as_none);
    assert_family_catches(
        "quadric line on surface as none",
        &report,
        "quadric/random/line-on-surface",
        200,
    );
}

#[test]
fn epsilon_1e4_is_caught_by_small_roots() {
    let report = gate(Semantics::NearestPositive).quadric(&quadric_epsilon_1e4);
    assert_family_catches(
        "quadric t > 1e-4",
        &report,
        "quadric/random/small-root",
        200,
    );
}

#[test]
fn epsilon_machine_is_caught_by_small_roots() {
    let report = gate(Semantics::NearestPositive).quadric(&quadric_epsilon_machine);
    assert_family_catches(
        "quadric t > f32::EPSILON",
        &report,
        "quadric/random/small-root",
        200,
    );
}

#[test]
fn t_nonnegative_is_caught_by_origins_on_the_surface() {
    let report = gate(Semantics::NearestPositive).quadric(&quadric_t_nonnegative);
    assert_family_catches("quadric t ≥ 0", &report, "quadric/random/on-surface", 100);
}
