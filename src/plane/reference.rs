//! The scalar reference: the seed's formula `t = ((a − o)·n)/(d·n)` with
//! exact differences, double-word dot products and one final rounding.

use super::{Plane, PlaneHit};
use crate::Ray;
use crate::num::ff::{dot3, dot3_ff};
use crate::num::scale::{exponent_of_max, ldexp3};
use crate::num::{Ff, Lane};

/// Intersects a ray (as a whole line) with a plane.
///
/// ```
/// use rayoracle::{Ray, plane::{Plane, PlaneHit, reference::intersect}};
/// use glam::Vec3;
/// let ground = Plane::new(Vec3::ZERO, Vec3::Y);
/// let ray = Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, -4.0, 0.0));
/// assert_eq!(intersect(&ray, &ground), PlaneHit::Hit(0.5));
/// let flat = Ray::new(Vec3::Y, Vec3::X);
/// assert_eq!(intersect(&flat, &ground), PlaneHit::Parallel);
/// ```
pub fn intersect(ray: &Ray, plane: &Plane) -> PlaneHit {
    let n = plane.normal.to_array();
    let d = ray.dir.to_array();
    let (a, o) = (plane.point.to_array(), ray.origin.to_array());

    // Exact prescaling: t does not depend on |n|; t ∝ 1/|d|; t ∝ |a − o|.
    let n = ldexp3(n, -exponent_of_max(&n));
    let kd = exponent_of_max(&d);
    let d = ldexp3(d, -kd);
    let ka = exponent_of_max(&[a[0], a[1], a[2], o[0], o[1], o[2]]);
    let (a, o) = (ldexp3(a, -ka), ldexp3(o, -ka));

    // a − o exactly, then (a − o)·n and d·n in double-word arithmetic.
    let w = [
        Ff::sum(a[0], -o[0]),
        Ff::sum(a[1], -o[1]),
        Ff::sum(a[2], -o[2]),
    ];
    let num = dot3_ff(w, n);
    let den = dot3(d, n);

    if den.hi == 0.0 {
        return if num.hi == 0.0 {
            PlaneHit::InPlane
        } else {
            PlaneHit::Parallel
        };
    }
    let t = (num / den).round();
    PlaneHit::Hit(t.ldexp(ka - kd))
}
