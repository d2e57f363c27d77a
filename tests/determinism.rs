//! The same input gives the same bits whatever target features the build
//! enables. `.ci/run` runs the suite twice — default flags and
//! `-C target-cpu=native` — and both must reproduce the digests pinned
//! here. (Within one build, x4 = reference is checked elsewhere; this test
//! is what ties the two builds together.)
//!
//! If a deliberate change to a kernel changes its results, the digest
//! changes: check the change against the oracle first, then update the
//! constant to the value the failure prints.

use glam::Vec3;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rayoracle::camera::CameraParams;
use rayoracle::hit::Intersection;
use rayoracle::ray4::Ray4;
use rayoracle::{Ray, plane, quadric, sphere};

/// FNV-1a over 32-bit words.
struct Digest(u64);

impl Digest {
    fn add(&mut self, x: f32) {
        // NaN payloads are not part of the contract; fold every NaN to one.
        let bits = if x.is_nan() { 0x7fc0_0000 } else { x.to_bits() };
        for b in bits.to_le_bytes() {
            self.0 = (self.0 ^ b as u64).wrapping_mul(0x100_0000_01b3);
        }
    }
    fn add_hit(&mut self, h: &impl Intersection) {
        self.add(h.class().len() as f32 + if h.is_everywhere() { 0.5 } else { 0.0 });
        for &t in h.roots().as_slice() {
            self.add(t);
        }
    }
}

/// Inputs from every corner: small integers, moderate values, raw bits.
fn value(rng: &mut StdRng) -> f32 {
    match rng.random_range(0..4) {
        0 => rng.random_range(-8..8) as f32,
        1 => rng.random_range(-100.0..100.0),
        2 => f32::from_bits(rng.random()),
        _ => rng.random_range(-1.0..1.0) * 10f32.powi(rng.random_range(-30..30)),
    }
}

fn v3(rng: &mut StdRng) -> Vec3 {
    Vec3::new(value(rng), value(rng), value(rng))
}

fn digest_all() -> [u64; 4] {
    let mut rng = StdRng::seed_from_u64(2026);
    let mut out = [
        Digest(0xcbf2_9ce4_8422_2325),
        Digest(0xcbf2_9ce4_8422_2325),
        Digest(0xcbf2_9ce4_8422_2325),
        Digest(0xcbf2_9ce4_8422_2325),
    ];
    for _ in 0..2000 {
        let rays = [0; 4].map(|_| Ray::new(v3(&mut rng), v3(&mut rng)));
        let r4 = Ray4::from_rays(rays);

        let planes = [0; 4].map(|_| plane::Plane::new(v3(&mut rng), v3(&mut rng)));
        for (r, p) in rays.iter().zip(&planes) {
            out[0].add_hit(&plane::reference::intersect(r, p));
        }
        for h in plane::x4::intersect(&r4, &plane::x4::Plane4::from_planes(planes)).lanes() {
            out[0].add_hit(&h);
        }

        let spheres = [0; 4].map(|_| sphere::Sphere::new(v3(&mut rng), value(&mut rng)));
        for (r, s) in rays.iter().zip(&spheres) {
            out[1].add_hit(&sphere::reference::intersect(r, s));
        }
        for h in sphere::x4::intersect(&r4, &sphere::x4::Sphere4::from_spheres(spheres)).lanes() {
            out[1].add_hit(&h);
        }

        let quadrics = [0; 4].map(|_| quadric::Quadric::new([0; 10].map(|_| value(&mut rng))));
        for (r, q) in rays.iter().zip(&quadrics) {
            out[2].add_hit(&quadric::reference::intersect(r, q));
        }
        for h in
            quadric::x4::intersect(&r4, &quadric::x4::Quadric4::from_quadrics(quadrics)).lanes()
        {
            out[2].add_hit(&h);
        }

        let p = CameraParams::new(
            v3(&mut rng),
            v3(&mut rng),
            v3(&mut rng),
            value(&mut rng),
            [rng.random_range(1..4000), rng.random_range(1..4000)],
        );
        // Drawn whatever the camera, so that one kernel's behaviour never
        // shifts the inputs the others see.
        let px = [0; 4].map(|_| [rng.random_range(0..p.res[0]), rng.random_range(0..p.res[1])]);
        if let Ok(cam) = p.build() {
            for r in cam
                .ray4(px)
                .to_rays()
                .iter()
                .chain(px.map(|[x, y]| cam.ray(x, y)).iter())
            {
                for c in r.dir.to_array() {
                    out[3].add(c);
                }
            }
        } else {
            out[3].add(-1.0);
        }
    }
    out.map(|d| d.0)
}

#[test]
fn outputs_are_the_same_bits_on_every_build() {
    let got = digest_all();
    let want: [u64; 4] = [
        15653110373939544661,
        845456662206226893,
        12071707664359204229,
        1486946723411266596,
    ];
    assert_eq!(
        got, want,
        "kernel outputs changed: plane, sphere, quadric, camera digests (see the module docs)"
    );
}
