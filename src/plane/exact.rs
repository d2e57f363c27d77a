//! The exact oracle: `d·n` and `(a − o)·n` exactly, the class from their
//! signs, and `t` as the correctly rounded quotient.
//!
//! Both are formed on expansions ([`crate::exact::expansion`]): `a − o` is
//! a two-term sum of `f32`s, and each dot product a sum of products of an
//! `f32` and such a term. Every factor's lowest bit is at `2⁻¹⁴⁹` or above
//! and its magnitude below `2¹²⁹`, so every product is exact (lowest bits
//! from `2⁻²⁹⁸`, magnitudes below `2²⁵⁸`), and the root of the linear
//! equation `(d·n) t − (a − o)·n = 0` is rounded by the quadratics'
//! solver ([`crate::exact::quadratic`]), with `α = 0`. Where subnormals
//! are flushed ([`subnormals_work`]), both are formed on dyadics instead.

use super::{Plane, PlaneHit};
use crate::Ray;
use crate::exact::dyadic::{dot, sub3, vec3};
use crate::exact::expansion::{Expansion, subnormals_work, two_sum};
use crate::exact::quadratic::solve_expansions;
use crate::exact::{ExactQuadratic, NonFinite, round_to_f32};

/// The exact answer, or [`NonFinite`] when an input is NaN or infinite.
///
/// ```
/// use rayoracle::{Ray, plane::{Plane, PlaneHit, exact::intersect}};
/// use glam::Vec3;
/// let p = Plane::new(Vec3::ZERO, Vec3::new(0.0, 3.0, 0.0));
/// let r = Ray::new(Vec3::new(0.0, 1.0, 0.0), Vec3::new(0.0, -3.0, 0.0));
/// assert_eq!(intersect(&r, &p), Ok(PlaneHit::Hit(1.0 / 3.0)));
/// ```
pub fn intersect(ray: &Ray, plane: &Plane) -> Result<PlaneHit, NonFinite> {
    let finite = [ray.origin, ray.dir, plane.point, plane.normal]
        .iter()
        .all(|v| v.is_finite());
    if !finite {
        return Err(NonFinite);
    }
    if let Some((neg_num, den)) = on_expansions(ray, plane).filter(|_| subnormals_work()) {
        // d·n t − (a − o)·n = 0, with α = 0: never two roots.
        return Ok(match solve_expansions(Expansion::ZERO, den, neg_num) {
            ExactQuadratic::One(t) => PlaneHit::Hit(t),
            ExactQuadratic::All => PlaneHit::InPlane,
            ExactQuadratic::None | ExactQuadratic::Two(..) => PlaneHit::Parallel,
        });
    }
    on_dyadics(ray, plane)
}

/// `−(a − o)·n` and `d·n` on expansions (at most 12 and 6 components, so
/// never `None`). `aᵢ − oᵢ` is the exact pair of [`two_sum`], whose zero
/// low part adds nothing.
fn on_expansions(ray: &Ray, plane: &Plane) -> Option<(Expansion, Expansion)> {
    let (o, d) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
    let (a, n) = (plane.point.as_dvec3(), plane.normal.as_dvec3());
    let (mut neg_num, mut den) = (Expansion::ZERO, Expansion::ZERO);
    for i in 0..3 {
        let (hi, lo) = two_sum(a[i], -o[i]);
        neg_num.add_product(lo, -n[i])?;
        neg_num.add_product(hi, -n[i])?;
        den.add_product(d[i], n[i])?;
    }
    Some((neg_num, den))
}

/// The exact answer on dyadics, for finite inputs.
fn on_dyadics(ray: &Ray, plane: &Plane) -> Result<PlaneHit, NonFinite> {
    let o = vec3(ray.origin.to_array())?;
    let d = vec3(ray.dir.to_array())?;
    let a = vec3(plane.point.to_array())?;
    let n = vec3(plane.normal.to_array())?;
    let num = dot(&sub3(&a, &o), &n);
    let den = dot(&d, &n);
    if den.is_zero() {
        return Ok(if num.is_zero() {
            PlaneHit::InPlane
        } else {
            PlaneHit::Parallel
        });
    }
    // t ≷ m ⇔ num ≷ den·m for den > 0; flip both for den < 0.
    let (num, den) = if den.signum() < 0 {
        (-num, -den)
    } else {
        (num, den)
    };
    let guess = num.to_f64() / den.to_f64();
    Ok(PlaneHit::Hit(round_to_f32(|m| num.cmp(&(&den * m)), guess)))
}

#[cfg(test)]
mod tests {
    use super::{Plane, PlaneHit, Ray, intersect, on_dyadics};
    use crate::exact::dyadic::tests::{big_only, fuzz_like_f32, products_during};
    use crate::exact::round::comparisons;
    use glam::Vec3;
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    /// The answer on expansions is the one on big integers alone, bit for
    /// bit, at every scale: any bits, subnormals, `f32::MAX`, and in a
    /// quarter of the cases an axis normal with `d` or `a − o` exactly
    /// across it, so that `d·n = 0` and `(a − o)·n = 0` come up.
    #[test]
    fn expansions_match_big_integers() {
        let mut r = SmallRng::seed_from_u64(0x91a9e);
        let mut seen = [0; 3];
        for _ in 0..20_000 {
            let mut v = || Vec3::from_array([(); 3].map(|_| fuzz_like_f32(&mut r)));
            let (mut o, mut d, a, mut n) = (v(), v(), v(), v());
            if r.random_bool(0.25) {
                (n.y, n.z, d.x) = (0.0, 0.0, 0.0);
                if r.random_bool(0.5) {
                    o.x = a.x;
                }
            }
            let (ray, p) = (Ray::new(o, d), Plane::new(a, n));
            let got = intersect(&ray, &p).unwrap();
            let want = big_only(|| on_dyadics(&ray, &p)).unwrap();
            assert!(
                crate::hit::same_bits(&got, &want),
                "{ray:?} {p:?}: {got:?} {want:?}"
            );
            seen[match got {
                PlaneHit::Hit(_) => 0,
                PlaneHit::Parallel => 1,
                PlaneHit::InPlane => 2,
            }] += 1;
        }
        assert!(seen.iter().all(|&k| k > 500), "{seen:?}");
    }

    /// The oracle decides on expansions, where the environment keeps
    /// subnormals: of 20,000 cases of the previous test's kind, fewer than
    /// one in a thousand forms a dyadic product (8 do, with a numerator
    /// too long for the exact comparisons on expansions).
    #[test]
    fn expansions_decide_without_dyadics() {
        let mut r = SmallRng::seed_from_u64(0xe4a);
        let mut on_dyadics = 0;
        for _ in 0..20_000 {
            let mut v = || Vec3::from_array([(); 3].map(|_| fuzz_like_f32(&mut r)));
            let (ray, p) = (Ray::new(v(), v()), Plane::new(v(), v()));
            let (_, n) = products_during(|| intersect(&ray, &p));
            on_dyadics += usize::from(n > 0);
        }
        assert!(on_dyadics < 20, "{on_dyadics} cases on dyadics");
    }

    /// The f64 guess only decides how long the exact search takes: a good
    /// one settles each `t` in a few comparisons, where `num·den` or a
    /// remainder would need 50 or more. Both signs of `d·n` are here.
    #[test]
    fn the_guess_makes_the_search_short() {
        let p = Plane::new(Vec3::new(0.0, 7.0, 0.0), Vec3::new(0.0, 3.0, 0.0));
        for (o, d) in [(-5.0, 3.0), (11.0, -0.1), (1e-3, 1e-7), (-9.0, 4e20)] {
            let r = Ray::new(Vec3::new(0.0, o, 0.0), Vec3::new(0.0, d, 0.0));
            let want = ((7.0 - f64::from(o)) / f64::from(d)) as f32;
            // On expansions, and on the dyadics of a flushing environment.
            for solve in [intersect, on_dyadics] {
                let mut got = Err(crate::exact::NonFinite);
                let n = comparisons::during(|| got = solve(&r, &p));
                assert_eq!(got, Ok(PlaneHit::Hit(want)), "o = {o}, d = {d}");
                assert!(n <= 12, "o = {o}, d = {d}: {n} comparisons");
            }
        }
    }
}
