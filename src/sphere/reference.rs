//! The scalar reference: RTG ch. 7's discriminant and root formulas in
//! double-word arithmetic after exact prescaling (see the module docs).

use super::{Sphere, SphereHit};
use crate::Ray;
use crate::num::ff::{dot3, dot3_ff, norm2_ff};
use crate::num::scale::{exponent_of_max, ldexp3};
use crate::num::{Ff, Lane};

/// Intersects a line with a sphere: the class and both roots over `t ∈ ℝ`.
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit, reference::intersect}};
/// use glam::Vec3;
/// let s = Sphere::new(Vec3::ZERO, 1.0);
/// // |d| = 2: the seed's discriminant would be wrong here.
/// let r = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, 2.0));
/// assert_eq!(intersect(&r, &s), SphereHit::Two(2.0, 3.0));
/// // Origin inside: one root behind the origin.
/// let inside = Ray::new(Vec3::ZERO, Vec3::Z);
/// assert_eq!(intersect(&inside, &s), SphereHit::Two(-1.0, 1.0));
/// ```
pub fn intersect(ray: &Ray, sphere: &Sphere) -> SphereHit {
    let d = ray.dir.to_array();
    let (o, c) = (ray.origin.to_array(), sphere.center.to_array());

    // Prescale d into [1, 2) (roots scale by 2^-kd) and the positions so that
    // o − C cannot overflow (roots scale by 2^ks).
    let kd = exponent_of_max(&d);
    let d = ldexp3(d, -kd);
    let ks = exponent_of_max(&[o[0], o[1], o[2], c[0], c[1], c[2], sphere.radius]);
    let (o, c, r) = (ldexp3(o, -ks), ldexp3(c, -ks), sphere.radius.ldexp(-ks));

    // f = o − C exactly, then rescale f and R together into [1, 2).
    let f = [
        Ff::sum(o[0], -c[0]),
        Ff::sum(o[1], -c[1]),
        Ff::sum(o[2], -c[2]),
    ];
    let kf = exponent_of_max(&[f[0].hi, f[1].hi, f[2].hi, r]);
    let f = f.map(|x| Ff {
        hi: x.hi.ldexp(-kf),
        lo: x.lo.ldexp(-kf),
    });
    let r = r.ldexp(-kf);

    let a = dot3(d, d);
    if a.hi == 0.0 {
        return SphereHit::None;
    }
    let b = dot3_ff(f, d);
    let cq = norm2_ff(f) - Ff::square(r);

    // RTG ch. 7, division-free: aΔ = (aR)² − |a f − b d|².
    let l = [0, 1, 2].map(|i| a * f[i] - b.scale(d[i]));
    let ar = a.scale(r);
    let a_disc = ar * ar - norm2_ff(l);

    let unscale = |t: Ff<f32>| t.round().ldexp(ks + kf - kd);
    if !(a_disc.hi >= 0.0) {
        return SphereHit::None;
    }
    if a_disc.hi == 0.0 {
        return SphereHit::Tangent(unscale(-(b / a)));
    }
    let sqrt_disc = (a_disc / a).sqrt();
    // q = −(b + sign(b)·√Δ): the two terms never cancel.
    let sign_b = 1.0f32.copysign(b.hi);
    let q = -(b + Ff {
        hi: sqrt_disc.hi * sign_b,
        lo: sqrt_disc.lo * sign_b,
    });
    let (t0, t1) = (unscale(cq / q), unscale(q / a));
    if t0 > t1 {
        SphereHit::Two(t1, t0)
    } else {
        SphereHit::Two(t0, t1)
    }
}
