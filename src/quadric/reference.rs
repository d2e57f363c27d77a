//! The scalar reference: α, β, γ in double-word arithmetic, then pbrt-v4's
//! `Quadratic` (with its α = 0 branch) in double-word, rounded once.

use super::{Quadric, QuadricHit};
use crate::Ray;
use crate::num::scale::{exponent_of_max, ldexp3};
use crate::num::{Ff, Lane};

/// `k · x · y` to double-word accuracy: the exact `x·y`, scaled by `k`.
#[inline(always)]
fn term<L: Lane>(k: L, x: L, y: L) -> Ff<L> {
    Ff::product(x, y).scale(k)
}

/// α, β, γ of the ray against the (prescaled) coefficients `k`, in
/// double-word arithmetic. Shared by the scalar and the SIMD path.
#[inline(always)]
pub(crate) fn coefficients<L: Lane>(k: &[L; 10], o: [L; 3], d: [L; 3]) -> (Ff<L>, Ff<L>, Ff<L>) {
    let two = L::splat(2.0);
    let alpha = term(k[0], d[0], d[0])
        + term(k[1], d[1], d[1])
        + term(k[2], d[2], d[2])
        + term(k[3], d[0], d[1])
        + term(k[4], d[0], d[2])
        + term(k[5], d[1], d[2]);
    let beta = (term(k[0], o[0], d[0]) + term(k[1], o[1], d[1]) + term(k[2], o[2], d[2]))
        .scale(two)
        + term(k[3], o[0], d[1])
        + term(k[3], d[0], o[1])
        + term(k[4], o[0], d[2])
        + term(k[4], d[0], o[2])
        + term(k[5], o[1], d[2])
        + term(k[5], d[1], o[2])
        + Ff::product(k[6], d[0])
        + Ff::product(k[7], d[1])
        + Ff::product(k[8], d[2]);
    let gamma = term(k[0], o[0], o[0])
        + term(k[1], o[1], o[1])
        + term(k[2], o[2], o[2])
        + term(k[3], o[0], o[1])
        + term(k[4], o[0], o[2])
        + term(k[5], o[1], o[2])
        + Ff::product(k[6], o[0])
        + Ff::product(k[7], o[1])
        + Ff::product(k[8], o[2])
        + Ff::from(k[9]);
    (alpha, beta, gamma)
}

/// Intersects a line with a quadric: class and roots over `t ∈ ℝ`.
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit, reference::intersect}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let across = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X);
/// assert_eq!(intersect(&across, &cyl), QuadricHit::Two(4.0, 6.0));
/// // Parallel to the axis, on the surface: α = β = γ = 0.
/// let along = Ray::new(Vec3::new(1.0, 0.0, 0.0), Vec3::Z);
/// assert_eq!(intersect(&along, &cyl), QuadricHit::All);
/// ```
pub fn intersect(ray: &Ray, quadric: &Quadric) -> QuadricHit {
    let kq = exponent_of_max(&quadric.coeffs);
    let k = quadric.coeffs.map(|x| x.ldexp(-kq));
    let d = ray.dir.to_array();
    let kd = exponent_of_max(&d);
    let d = ldexp3(d, -kd);
    let (alpha, beta, gamma) = coefficients(&k, ray.origin.to_array(), d);
    let unscale = |t: Ff<f32>| t.round().ldexp(-kd);

    if alpha.hi == 0.0 {
        if beta.hi == 0.0 {
            return if gamma.hi == 0.0 {
                QuadricHit::All
            } else {
                QuadricHit::None
            };
        }
        return QuadricHit::One(unscale(-(gamma / beta)));
    }
    let disc = beta * beta - (alpha * gamma).scale(4.0);
    if !(disc.hi >= 0.0) {
        return QuadricHit::None;
    }
    if disc.hi == 0.0 {
        return QuadricHit::One(unscale(-(beta / alpha.scale(2.0))));
    }
    let root = disc.sqrt();
    let sign_b = 1.0f32.copysign(beta.hi);
    let q = -(beta
        + Ff {
            hi: root.hi * sign_b,
            lo: root.lo * sign_b,
        })
    .scale(0.5);
    let (t0, t1) = (unscale(q / alpha), unscale(gamma / q));
    if t0 > t1 {
        QuadricHit::Two(t1, t0)
    } else {
        QuadricHit::Two(t0, t1)
    }
}
