//! The exact oracle: `a`, `b`, `c` exactly, the class from the exact sign
//! of `b² − ac`, and the correctly rounded roots.
//!
//! The coefficients are formed on expansions ([`crate::exact::expansion`]):
//! `f = o − c` is a two-term sum of `f32`s, and `|d|²`, `2 f·d`,
//! `|f|² − r²` are sums of products of two such terms. Every factor's
//! lowest bit is at `2⁻¹⁴⁹` or above and its magnitude below `2¹²⁹`, so
//! every product is exact (lowest bits from `2⁻²⁹⁸`, magnitudes below
//! `2²⁵⁸`), and so are the coefficients. Where subnormals are flushed
//! ([`subnormals_work`]), they are formed on dyadics instead.

use super::{Sphere, SphereHit};
use crate::Ray;
use crate::exact::dyadic::{dot, sub3};
use crate::exact::expansion::{Expansion, subnormals_work, two_sum};
use crate::exact::memo::{Memo, remembered};
use crate::exact::quadratic::solve_expansions;
use crate::exact::{Dyadic, ExactQuadratic, NonFinite, Quadratic};
use core::cell::RefCell;

/// The exact quadratic `a t² + 2b t + c` of a ray and a sphere.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, exact::quadratic}};
/// use glam::Vec3;
/// let q = quadratic(&Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z), &Sphere::new(Vec3::ZERO, 1.0)).unwrap();
/// assert!(q.discriminant().is_zero()); // grazing the top of the sphere
/// ```
pub fn quadratic(ray: &Ray, sphere: &Sphere) -> Result<Quadratic, NonFinite> {
    Ok(match expansions(ray, sphere)? {
        Some([a, b2, cc]) => Quadratic::from_expansions(a, b2, cc),
        None => on_dyadics(ray, sphere),
    })
}

/// `a`, `2b`, `c` as [`quadratic`] forms them on expansions (not
/// normalised), or `None` where it forms them on dyadics.
pub(crate) fn expansions(ray: &Ray, sphere: &Sphere) -> Result<Option<[Expansion; 3]>, NonFinite> {
    let (o, d, c) = (ray.origin, ray.dir, sphere.center);
    let r = sphere.radius;
    if !(o.is_finite() && d.is_finite() && c.is_finite() && r.is_finite()) {
        return Err(NonFinite);
    }
    Ok(on_expansions(ray, sphere).filter(|_| subnormals_work()))
}

/// `a`, `2b`, `c` on expansions, unless one outgrows its capacity.
fn on_expansions(ray: &Ray, sphere: &Sphere) -> Option<[Expansion; 3]> {
    let (o, d, c) = (
        ray.origin.as_dvec3(),
        ray.dir.as_dvec3(),
        sphere.center.as_dvec3(),
    );
    let (mut a, mut b, mut cc) = (Expansion::ZERO, Expansion::ZERO, Expansion::ZERO);
    for i in 0..3 {
        // fᵢ = oᵢ − cᵢ as its exact pair; a zero part adds nothing.
        let (hi, lo) = two_sum(o[i], -c[i]);
        let f = [lo, hi];
        a.add_product(d[i], d[i])?;
        for x in f {
            b.add_product(x, d[i])?;
            for y in f {
                cc.add_product(x, y)?;
            }
        }
    }
    let r = f64::from(sphere.radius);
    cc.add_product(-r, r)?;
    Some([a, b.mul_pow2(1), cc])
}

/// `a`, `2b`, `c` on dyadics, for finite inputs.
fn on_dyadics(ray: &Ray, sphere: &Sphere) -> Quadratic {
    let v = |v: glam::Vec3| v.to_array().map(Dyadic::from_f32);
    let (o, d, c) = (v(ray.origin), v(ray.dir), v(sphere.center));
    let r = Dyadic::from_f32(sphere.radius);
    let f = sub3(&o, &c);
    let a = dot(&d, &d);
    let b2 = dot(&f, &d).mul_pow2(1);
    let cc = &dot(&f, &f) - &(&r * &r);
    Quadratic::new(a, b2, cc)
}

/// The exact answer, or [`NonFinite`] when an input is NaN or infinite
/// (the last few kept per thread, by the inputs' bits).
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit, exact::intersect}};
/// use glam::Vec3;
/// let s = Sphere::new(Vec3::ZERO, 1.0);
/// let r = Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z);
/// assert_eq!(intersect(&r, &s), Ok(SphereHit::Tangent(5.0)));
/// ```
pub fn intersect(ray: &Ray, sphere: &Sphere) -> Result<SphereHit, NonFinite> {
    type Key = [u32; 10];
    thread_local! {
        static LAST: RefCell<Memo<Key, Result<SphereHit, NonFinite>>> =
            const { RefCell::new(Memo::new()) };
    }
    let (o, d, c) = (ray.origin, ray.dir, sphere.center);
    let key = [o.x, o.y, o.z, d.x, d.y, d.z, c.x, c.y, c.z, sphere.radius].map(f32::to_bits);
    remembered(&LAST, key, || Ok(intersect_and_expansions(ray, sphere)?.0))
}

/// [`intersect`] without its memo, and with the coefficients it solved,
/// where it formed them on expansions: the `sphere` fuzz target compares
/// them with the quadric oracle's, and so forms them once.
pub(crate) fn intersect_and_expansions(
    ray: &Ray,
    sphere: &Sphere,
) -> Result<(SphereHit, Option<[Expansion; 3]>), NonFinite> {
    let e = expansions(ray, sphere)?;
    let h = match e {
        Some([a, b2, cc]) => hit(solve_expansions(a, b2, cc)),
        None => classify(&on_dyadics(ray, sphere)),
    };
    Ok((h, e))
}

/// The sphere result of an exact [`quadratic`] (so a caller that needs both
/// computes the quadratic once).
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit, exact}};
/// use glam::Vec3;
/// let q = exact::quadratic(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), &Sphere::new(Vec3::ZERO, 1.0)).unwrap();
/// assert_eq!(exact::classify(&q), SphereHit::Two(4.0, 6.0));
/// ```
pub fn classify(q: &Quadratic) -> SphereHit {
    hit(q.solve())
}

/// The sphere result of a solved quadratic.
pub(crate) fn hit(q: ExactQuadratic) -> SphereHit {
    match q {
        // α = 0 only for d = 0, which is not a line.
        ExactQuadratic::None | ExactQuadratic::All => SphereHit::None,
        ExactQuadratic::One(t) => SphereHit::Tangent(t),
        ExactQuadratic::Two(t0, t1) => SphereHit::Two(t0, t1),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::dyadic::tests::{big_only, fuzz_like_f32};
    use crate::exact::dyadic::vec3;
    use glam::Vec3;
    use rand::SeedableRng;
    use rand::rngs::SmallRng;

    /// The coefficients formed on expansions are the dyadic formulas'
    /// `|d|²`, `2 f·d`, `|f|² − r²` (normalised), and the answer is the one
    /// solving on big integers alone gives, at every scale.
    #[test]
    fn expansions_match_the_dyadic_formulas() {
        let mut r = SmallRng::seed_from_u64(0x5fe7e);
        let mut two = 0;
        for _ in 0..4_000 {
            let mut v = || {
                Vec3::new(
                    fuzz_like_f32(&mut r),
                    fuzz_like_f32(&mut r),
                    fuzz_like_f32(&mut r),
                )
            };
            let (o, d, c) = (v(), v(), v());
            let rad = fuzz_like_f32(&mut r);
            let (ray, s) = (Ray::new(o, d), Sphere::new(c, rad));
            let q = quadratic(&ray, &s).unwrap();
            let want = big_only(|| {
                let [o, d, c] = [o, d, c].map(|x| vec3(x.to_array()).unwrap());
                let f = sub3(&o, &c);
                let rr = Dyadic::from_f32(rad);
                Quadratic::new(
                    dot(&d, &d),
                    dot(&f, &d).mul_pow2(1),
                    &dot(&f, &f) - &(&rr * &rr),
                )
            });
            assert!(
                big_only(|| (&q.alpha, &q.beta, &q.gamma) == (&want.alpha, &want.beta, &want.gamma)),
                "{ray:?} {s:?}"
            );
            let (got, slow) = (classify(&q), big_only(|| classify(&want)));
            assert!(
                crate::hit::same_bits(&got, &slow),
                "{ray:?} {s:?}: {got:?} {slow:?}"
            );
            two += usize::from(matches!(got, SphereHit::Two(..)));
        }
        assert!(two > 200, "{two}");
    }

    /// The oracle decides on expansions where the environment keeps
    /// subnormals: of 4,000 cases of the previous test's kind, about one in
    /// nine forms a dyadic product (452: those whose coefficients, of dense
    /// mantissas, stay longer than the solver's short expansions).
    #[test]
    fn expansions_decide_without_dyadics() {
        use crate::exact::dyadic::tests::products_during;
        let mut r = SmallRng::seed_from_u64(0x5fe7e);
        let mut on_dyadics = 0;
        for _ in 0..4_000 {
            let mut v = || Vec3::from_array([(); 3].map(|_| fuzz_like_f32(&mut r)));
            let (o, d, c) = (v(), v(), v());
            let (ray, s) = (Ray::new(o, d), Sphere::new(c, fuzz_like_f32(&mut r)));
            let (_, n) = products_during(|| intersect(&ray, &s));
            on_dyadics += usize::from(n > 0);
        }
        assert!(on_dyadics < 700, "{on_dyadics} cases on dyadics");
    }
}
