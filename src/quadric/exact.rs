//! The exact oracle: α, β, γ exactly, then the exact quadratic.
//!
//! Each coefficient is a sum of products of up to three `f32`s, formed on
//! expansions ([`crate::exact::expansion`]): the product of the first two
//! factors is exact in an `f64` (48 bits), and its product with the third
//! is exact as two terms (lowest bits from `2⁻⁴⁴⁷`, magnitudes below
//! `2³⁸⁴`). A sum that outgrows an expansion (spans no quadric reaches in
//! practice) is formed on dyadics instead, and so is every coefficient
//! where subnormals are flushed ([`subnormals_work`]).

use super::{Quadric, QuadricHit};
use crate::Ray;
use crate::exact::dyadic::{sum, vec3};
use crate::exact::expansion::{Expansion, subnormals_work};
use crate::exact::memo::{Memo, remembered};
use crate::exact::quadratic::solve_expansions;
use crate::exact::{Dyadic, ExactQuadratic, NonFinite, Quadratic};
use core::cell::RefCell;

/// The exact quadratic `α t² + β t + γ` of a ray and a quadric.
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, exact::quadratic}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let q = quadratic(&Ray::new(Vec3::ZERO, Vec3::Z), &cyl).unwrap();
/// // Along the axis from inside: 0t² + 0t − 1 (a sign the normalisation
/// // of Quadratic::new leaves alone when α = β = 0).
/// assert!(q.alpha.is_zero() && q.beta.is_zero() && q.gamma.to_f64() == -1.0);
/// // Across it from x = −5: t² − 10t + 24.
/// let q = quadratic(&Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X), &cyl).unwrap();
/// assert_eq!([q.alpha, q.beta, q.gamma].map(|x| x.to_f64()), [1.0, -10.0, 24.0]);
/// ```
pub fn quadratic(ray: &Ray, quadric: &Quadric) -> Result<Quadratic, NonFinite> {
    match expansions(ray, quadric)? {
        Some([a, b, c]) => Ok(Quadratic::from_expansions(a, b, c)),
        None => on_dyadics(ray, quadric),
    }
}

/// α, β, γ as [`quadratic`] forms them on expansions (not normalised), or
/// `None` where it forms them on dyadics.
pub(crate) fn expansions(
    ray: &Ray,
    quadric: &Quadric,
) -> Result<Option<[Expansion; 3]>, NonFinite> {
    let finite = ray.origin.is_finite() && ray.dir.is_finite();
    if !(finite && quadric.coeffs.iter().all(|c| c.is_finite())) {
        return Err(NonFinite);
    }
    Ok(on_expansions(ray, quadric).filter(|_| subnormals_work()))
}

/// α, β, γ on expansions, unless one outgrows its capacity.
fn on_expansions(ray: &Ray, quadric: &Quadric) -> Option<[Expansion; 3]> {
    let (o, d) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
    let k = quadric.coeffs.map(f64::from);
    // Each term: (the exact f64 product of two factors, the third).
    let alpha = [
        (k[0] * d[0], d[0]),
        (k[1] * d[1], d[1]),
        (k[2] * d[2], d[2]),
        (k[3] * d[0], d[1]),
        (k[4] * d[0], d[2]),
        (k[5] * d[1], d[2]),
    ];
    let beta = [
        (2.0 * k[0] * o[0], d[0]),
        (2.0 * k[1] * o[1], d[1]),
        (2.0 * k[2] * o[2], d[2]),
        (k[3] * o[0], d[1]),
        (k[3] * d[0], o[1]),
        (k[4] * o[0], d[2]),
        (k[4] * d[0], o[2]),
        (k[5] * o[1], d[2]),
        (k[5] * d[1], o[2]),
        (k[6], d[0]),
        (k[7], d[1]),
        (k[8], d[2]),
    ];
    let gamma = [
        (k[0] * o[0], o[0]),
        (k[1] * o[1], o[1]),
        (k[2] * o[2], o[2]),
        (k[3] * o[0], o[1]),
        (k[4] * o[0], o[2]),
        (k[5] * o[1], o[2]),
        (k[6], o[0]),
        (k[7], o[1]),
        (k[8], o[2]),
        (k[9], 1.0),
    ];
    let sum = |terms: &[(f64, f64)]| {
        let mut e = Expansion::ZERO;
        for &(x, y) in terms {
            e.add_product(x, y)?;
        }
        Some(e)
    };
    Some([sum(&alpha)?, sum(&beta)?, sum(&gamma)?])
}

/// α, β, γ on dyadics.
fn on_dyadics(ray: &Ray, quadric: &Quadric) -> Result<Quadratic, NonFinite> {
    let o = vec3(ray.origin.to_array())?;
    let d = vec3(ray.dir.to_array())?;
    let mut k = Vec::with_capacity(10);
    for &c in &quadric.coeffs {
        k.push(Dyadic::try_from_f32(c)?);
    }
    let t = |c: &Dyadic, x: &Dyadic, y: &Dyadic| &(c * x) * y;
    let alpha = [
        t(&k[0], &d[0], &d[0]),
        t(&k[1], &d[1], &d[1]),
        t(&k[2], &d[2], &d[2]),
        t(&k[3], &d[0], &d[1]),
        t(&k[4], &d[0], &d[2]),
        t(&k[5], &d[1], &d[2]),
    ];
    let beta = [
        t(&k[0], &o[0], &d[0]).mul_pow2(1),
        t(&k[1], &o[1], &d[1]).mul_pow2(1),
        t(&k[2], &o[2], &d[2]).mul_pow2(1),
        t(&k[3], &o[0], &d[1]),
        t(&k[3], &d[0], &o[1]),
        t(&k[4], &o[0], &d[2]),
        t(&k[4], &d[0], &o[2]),
        t(&k[5], &o[1], &d[2]),
        t(&k[5], &d[1], &o[2]),
        &k[6] * &d[0],
        &k[7] * &d[1],
        &k[8] * &d[2],
    ];
    let gamma = [
        t(&k[0], &o[0], &o[0]),
        t(&k[1], &o[1], &o[1]),
        t(&k[2], &o[2], &o[2]),
        t(&k[3], &o[0], &o[1]),
        t(&k[4], &o[0], &o[2]),
        t(&k[5], &o[1], &o[2]),
        &k[6] * &o[0],
        &k[7] * &o[1],
        &k[8] * &o[2],
        k[9].clone(),
    ];
    Ok(Quadratic::new(sum(&alpha), sum(&beta), sum(&gamma)))
}

/// The exact answer, or [`NonFinite`] when an input is NaN or infinite
/// (the last few kept per thread, by the inputs' bits).
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit, exact::intersect}};
/// use glam::Vec3;
/// // The paraboloid z = x² + y², hit along its axis: α = 0, one root.
/// let p = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0]);
/// let r = Ray::new(Vec3::new(0.0, 0.0, -2.0), Vec3::Z);
/// assert_eq!(intersect(&r, &p), Ok(QuadricHit::One(2.0)));
/// ```
pub fn intersect(ray: &Ray, quadric: &Quadric) -> Result<QuadricHit, NonFinite> {
    type Key = ([u32; 6], [u32; 10]);
    thread_local! {
        static LAST: RefCell<Memo<Key, Result<QuadricHit, NonFinite>>> =
            const { RefCell::new(Memo::new()) };
    }
    let (o, d) = (ray.origin, ray.dir);
    let key = (
        [o.x, o.y, o.z, d.x, d.y, d.z].map(f32::to_bits),
        quadric.coeffs.map(f32::to_bits),
    );
    remembered(&LAST, key, || {
        Ok(match expansions(ray, quadric)? {
            Some([a, b, c]) => hit(solve_expansions(a, b, c)),
            None => classify(&on_dyadics(ray, quadric)?),
        })
    })
}

/// The quadric result of an exact [`quadratic`] (so a caller that needs
/// both computes the quadratic once).
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit, exact}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let q = exact::quadratic(&Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X), &cyl).unwrap();
/// assert_eq!(exact::classify(&q), QuadricHit::Two(4.0, 6.0));
/// ```
pub fn classify(q: &Quadratic) -> QuadricHit {
    hit(q.solve())
}

/// The quadric result of a solved quadratic.
fn hit(q: ExactQuadratic) -> QuadricHit {
    match q {
        ExactQuadratic::None => QuadricHit::None,
        ExactQuadratic::One(t) => QuadricHit::One(t),
        ExactQuadratic::Two(t0, t1) => QuadricHit::Two(t0, t1),
        ExactQuadratic::All => QuadricHit::All,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::dyadic::tests::{big_only, fuzz_like_f32};
    use glam::Vec3;
    use rand::SeedableRng;
    use rand::rngs::SmallRng;

    /// The coefficients formed on expansions are those formed on dyadics,
    /// and the answer is the one solving on big integers alone gives.
    #[test]
    fn expansions_match_the_dyadic_formulas() {
        let mut r = SmallRng::seed_from_u64(0x9ad);
        let mut roots = 0;
        for _ in 0..3_000 {
            let mut v = || {
                Vec3::new(
                    fuzz_like_f32(&mut r),
                    fuzz_like_f32(&mut r),
                    fuzz_like_f32(&mut r),
                )
            };
            let ray = Ray::new(v(), v());
            let q = Quadric::new(core::array::from_fn(|_| fuzz_like_f32(&mut r)));
            let got = quadratic(&ray, &q).unwrap();
            let want = big_only(|| on_dyadics(&ray, &q)).unwrap();
            assert!(
                big_only(|| (&got.alpha, &got.beta, &got.gamma)
                    == (&want.alpha, &want.beta, &want.gamma)),
                "{ray:?} {q:?}"
            );
            let (a, b) = (classify(&got), big_only(|| classify(&want)));
            assert!(crate::hit::same_bits(&a, &b), "{ray:?} {q:?}: {a:?} {b:?}");
            roots += usize::from(matches!(a, QuadricHit::Two(..) | QuadricHit::One(_)));
        }
        assert!(roots > 300, "{roots}");
    }

    /// The oracle decides on expansions where the environment keeps
    /// subnormals: of 3,000 cases of the previous test's kind, about one in
    /// ten forms a dyadic product (305: those whose coefficients, of dense
    /// mantissas, stay longer than the solver's short expansions).
    #[test]
    fn expansions_decide_without_dyadics() {
        use crate::exact::dyadic::tests::products_during;
        let mut r = SmallRng::seed_from_u64(0x9ad);
        let mut on_dyadics = 0;
        for _ in 0..3_000 {
            let mut v = || Vec3::from_array([(); 3].map(|_| fuzz_like_f32(&mut r)));
            let ray = Ray::new(v(), v());
            let q = Quadric::new(core::array::from_fn(|_| fuzz_like_f32(&mut r)));
            let (_, n) = products_during(|| intersect(&ray, &q));
            on_dyadics += usize::from(n > 0);
        }
        assert!(on_dyadics < 450, "{on_dyadics} cases on dyadics");
    }
}
