//! The generated families: the seeded `random/*` families of every kind
//! and `camera/invalid`, run beside the compiled-in fixtures.

use super::Sourced;
use crate::Ray;
use crate::camera::CameraParams;
use crate::case::Case;
use crate::plane::Plane;
use crate::quadric::Quadric;
use crate::sphere::Sphere;
use glam::Vec3;

/// The random families' seed for a kind: `seed` xor the 64-bit FNV-1a
/// hash of the kind's name, so each kind draws a stream of its own, the
/// same on every platform.
pub(super) fn kind_seed(kind: &str, seed: u64) -> u64 {
    let fnv = kind.bytes().fold(0xcbf2_9ce4_8422_2325u64, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0000_0100_0000_01b3)
    });
    seed ^ fnv
}

/// The `camera/invalid` family: parameters the oracle refuses, each a
/// plausible slip a camera might let through (an up vector exactly
/// parallel to the view direction, longer, shorter, reversed or tiny; a
/// field of view of π or more, of 0 or less, or NaN), so that a camera
/// accepting any of them fails. The fixtures' `camera/error-*` families
/// run too.
pub(super) fn invalid_cameras() -> Vec<Sourced> {
    let (o, f, up) = (
        Vec3::new(1.5, -2.0, 3.0),
        Vec3::new(0.6, -0.8, 0.5),
        Vec3::Y,
    );
    let params = [
        (f, f * 4.0, 1.0),
        (f, -f * 0.25, 1.0),
        (Vec3::new(0.0, 0.0, -1.0), Vec3::new(0.0, 0.0, 1e-30), 1.2),
        (f, up, 3.3),
        (f, up, std::f32::consts::PI),
        (f, up, 4.0),
        (f, up, 0.0),
        (f, up, -0.5),
        (f, up, f32::NAN),
    ];
    params
        .into_iter()
        .map(|(dir, up, angle)| {
            let p = CameraParams::new(o, dir, up, angle, [64, 48]);
            ("camera/invalid".to_string(), Case::Camera(p, [5, 7]))
        })
        .collect()
}

/// Seeded random cases (`random/*` families), `n` per family.
pub(super) fn random_cases(kind: &str, seed: u64, n: usize) -> Vec<Sourced> {
    use rand::{Rng, SeedableRng, rngs::SmallRng};
    let mut rng = SmallRng::seed_from_u64(kind_seed(kind, seed));
    let v3 = |rng: &mut SmallRng, s: f32| {
        Vec3::new(
            rng.random_range(-s..s),
            rng.random_range(-s..s),
            rng.random_range(-s..s),
        )
    };
    let mut out = Vec::new();
    let fam = |name: &str| format!("{kind}/random/{name}");
    for _ in 0..n {
        match kind {
            "sphere" => {
                let c = v3(&mut rng, 10.0);
                let r = rng.random_range(0.1..5.0f32);
                let o = c + v3(&mut rng, 30.0);
                let aim = c + v3(&mut rng, r) - o;
                out.push((
                    fam("aimed"),
                    Case::Sphere(Ray::new(o, aim), Sphere::new(c, r)),
                ));
                let inside = c + v3(&mut rng, r * 0.5);
                out.push((
                    fam("inside"),
                    Case::Sphere(Ray::new(inside, v3(&mut rng, 1.0)), Sphere::new(c, r)),
                ));
            }
            "plane" => {
                let p = Plane::new(v3(&mut rng, 10.0), v3(&mut rng, 1.0));
                out.push((
                    fam("any"),
                    Case::Plane(Ray::new(v3(&mut rng, 20.0), v3(&mut rng, 1.0)), p),
                ));
            }
            "quadric" => {
                let mut k = [0f32; 10];
                for (i, x) in k.iter_mut().enumerate() {
                    *x = if i < 3 {
                        rng.random_range(-2.0..2.0)
                    } else {
                        rng.random_range(-1.0..1.0)
                    };
                }
                let ray = Ray::new(v3(&mut rng, 6.0), v3(&mut rng, 1.0));
                out.push((fam("any"), Case::Quadric(ray, Quadric::new(k))));
            }
            "camera" => {
                let res = [rng.random_range(1..2000u32), rng.random_range(1..2000u32)];
                let p = CameraParams::new(
                    v3(&mut rng, 10.0),
                    v3(&mut rng, 1.0),
                    v3(&mut rng, 1.0),
                    rng.random_range(0.1..3.0f32),
                    res,
                );
                let px = [rng.random_range(0..res[0]), rng.random_range(0..res[1])];
                if p.build().is_ok() {
                    out.push((fam("any"), Case::Camera(p, px)));
                }
            }
            _ => {}
        }
    }
    out
}
