//! The exact oracle: `d·n` and `(a − o)·n` as exact dyadics, the class from
//! their signs, and `t` as the correctly rounded quotient.

use super::{Plane, PlaneHit};
use crate::Ray;
use crate::exact::dyadic::{dot, sub3, vec3};
use crate::exact::{NonFinite, round_to_f32};

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
    use super::{Plane, PlaneHit, Ray, intersect};
    use crate::exact::round::comparisons;
    use glam::Vec3;

    /// The f64 guess only decides how long the exact search takes: a good
    /// one settles each `t` in a few comparisons, where `num·den` or a
    /// remainder would need 50 or more. Both signs of `d·n` are here.
    #[test]
    fn the_guess_makes_the_search_short() {
        let p = Plane::new(Vec3::new(0.0, 7.0, 0.0), Vec3::new(0.0, 3.0, 0.0));
        for (o, d) in [(-5.0, 3.0), (11.0, -0.1), (1e-3, 1e-7), (-9.0, 4e20)] {
            let r = Ray::new(Vec3::new(0.0, o, 0.0), Vec3::new(0.0, d, 0.0));
            let mut got = Err(crate::exact::NonFinite);
            let n = comparisons::during(|| got = intersect(&r, &p));
            let want = ((7.0 - f64::from(o)) / f64::from(d)) as f32;
            assert_eq!(got, Ok(PlaneHit::Hit(want)), "o = {o}, d = {d}");
            assert!(n <= 12, "o = {o}, d = {d}: {n} comparisons");
        }
    }
}
