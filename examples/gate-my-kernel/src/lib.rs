//! "My renderer's" sphere kernels, as an outside crate would have them:
//! a scalar one and a four-lane one over its own structure-of-arrays
//! layout. Both return the nearest hit with `t > 0`.
//!
//! The arithmetic is f64 inside an f32 kernel, the variant `rayoracle
//! report` puts on the Pareto front: `b' = f·d`, `c = |f|² − R²`, the
//! discriminant as `R² − |f − (f·d̂)d̂|²` (Ray Tracing Gems ch. 7) and the
//! stable quadratic `q = −(b' + sign(b')√…)`.

use glam::Vec3;

/// The nearest `t > 0` where `o + t d` meets the sphere `(c, r)`.
pub fn sphere_nearest(o: Vec3, d: Vec3, c: Vec3, r: f32) -> Option<f32> {
    let (o, d, c, r) = (o.as_dvec3(), d.as_dvec3(), c.as_dvec3(), f64::from(r));
    let f = o - c;
    let a = d.dot(d);
    if a == 0.0 {
        return None;
    }
    let b = f.dot(d);
    let l = f - d * (b / a);
    let disc = a * (r * r - l.dot(l));
    // Negative or NaN: no real root.
    if disc.is_nan() || disc < 0.0 {
        return None;
    }
    let q = -(b + disc.sqrt().copysign(b));
    let (t0, t1) = if q == 0.0 {
        (0.0, 0.0)
    } else {
        ((f.dot(f) - r * r) / q, q / a)
    };
    let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
    [t0 as f32, t1 as f32].into_iter().find(|&t| t > 0.0)
}

/// Four rays in my renderer's layout.
pub struct Rays4 {
    pub ox: [f32; 4],
    pub oy: [f32; 4],
    pub oz: [f32; 4],
    pub dx: [f32; 4],
    pub dy: [f32; 4],
    pub dz: [f32; 4],
}

/// Four rays against four spheres, lane by lane.
pub fn sphere_nearest4(r: &Rays4, c: [Vec3; 4], rad: [f32; 4]) -> [Option<f32>; 4] {
    core::array::from_fn(|i| {
        sphere_nearest(
            Vec3::new(r.ox[i], r.oy[i], r.oz[i]),
            Vec3::new(r.dx[i], r.dy[i], r.dz[i]),
            c[i],
            rad[i],
        )
    })
}
