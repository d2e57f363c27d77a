//! The same input gives the same bits whatever target features the build
//! enables. `.ci/run` runs the suite twice — default flags and
//! `-C target-cpu=native` — and both must reproduce the digests pinned
//! here. (Within one build, x4 = reference is checked elsewhere; this test
//! is what ties the two builds together.)
//!
//! If a deliberate change to a kernel changes its results, the digest
//! changes: check the change against the oracle first, then update the
//! constant to the value the failure prints.
//!
//! The inputs are drawn whichever kinds are compiled in, so a build without
//! some kind (cargo features) still reproduces the others' digests.

use glam::Vec3;
use rand::rngs::StdRng;
use rand::{Rng, SeedableRng};
use rayoracle::Ray;
use rayoracle::camera::CameraParams;
#[cfg(feature = "plane")]
use rayoracle::plane;
#[cfg(feature = "quadric")]
use rayoracle::quadric;
#[cfg(feature = "sphere")]
use rayoracle::sphere;
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use rayoracle::{hit::Intersection, ray4::Ray4};

/// The digest of nothing: FNV-1a's offset basis.
const EMPTY: u64 = 0xcbf2_9ce4_8422_2325;

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
    /// Each hit's class (and whether it is everywhere), then its roots.
    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    fn add_hits<H: Intersection>(&mut self, hits: impl IntoIterator<Item = H>) {
        for h in hits {
            self.add(h.class().as_str().len() as f32 + if h.is_everywhere() { 0.5 } else { 0.0 });
            for &t in h.roots().as_slice() {
                self.add(t);
            }
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
    let mut out = [Digest(EMPTY), Digest(EMPTY), Digest(EMPTY), Digest(EMPTY)];
    for _ in 0..2000 {
        let rays = [0; 4].map(|_| Ray::new(v3(&mut rng), v3(&mut rng)));

        // Every kind's inputs are drawn whether or not it is compiled in,
        // so that the random stream is the same in every build.
        let planes = [0; 4].map(|_| (v3(&mut rng), v3(&mut rng)));
        let spheres = [0; 4].map(|_| (v3(&mut rng), value(&mut rng)));
        let quadrics = [0; 4].map(|_| [0; 10].map(|_| value(&mut rng)));
        #[cfg(feature = "plane")]
        digest_planes(
            &mut out[0],
            &rays,
            planes.map(|(a, n)| plane::Plane::new(a, n)),
        );
        #[cfg(feature = "sphere")]
        digest_spheres(
            &mut out[1],
            &rays,
            spheres.map(|(c, r)| sphere::Sphere::new(c, r)),
        );
        #[cfg(feature = "quadric")]
        digest_quadrics(&mut out[2], &rays, quadrics.map(quadric::Quadric::new));
        #[cfg(not(all(feature = "plane", feature = "sphere", feature = "quadric")))]
        let _ = (rays, planes, spheres, quadrics); // a compiled-out kind's are dropped

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

#[cfg(feature = "plane")]
fn digest_planes(d: &mut Digest, rays: &[Ray; 4], planes: [plane::Plane; 4]) {
    let reference = rays
        .iter()
        .zip(&planes)
        .map(|(r, p)| plane::reference::intersect(r, p));
    d.add_hits(reference);
    let p4 = plane::x4::Plane4::from_planes(planes);
    d.add_hits(plane::x4::intersect(&Ray4::from_rays(*rays), &p4).lanes());
}

#[cfg(feature = "sphere")]
fn digest_spheres(d: &mut Digest, rays: &[Ray; 4], spheres: [sphere::Sphere; 4]) {
    let reference = rays
        .iter()
        .zip(&spheres)
        .map(|(r, s)| sphere::reference::intersect(r, s));
    d.add_hits(reference);
    let s4 = sphere::x4::Sphere4::from_spheres(spheres);
    d.add_hits(sphere::x4::intersect(&Ray4::from_rays(*rays), &s4).lanes());
}

#[cfg(feature = "quadric")]
fn digest_quadrics(d: &mut Digest, rays: &[Ray; 4], quadrics: [quadric::Quadric; 4]) {
    let reference = rays
        .iter()
        .zip(&quadrics)
        .map(|(r, q)| quadric::reference::intersect(r, q));
    d.add_hits(reference);
    let q4 = quadric::x4::Quadric4::from_quadrics(quadrics);
    d.add_hits(quadric::x4::intersect(&Ray4::from_rays(*rays), &q4).lanes());
}

#[test]
fn outputs_are_the_same_bits_on_every_build() {
    let got = digest_all();
    let pinned: [u64; 4] = [
        10553959330667295637,
        13667940467011394293,
        2537997569441458989,
        3126374901972296524,
    ];
    // A kind that is compiled out digests nothing.
    let compiled_in = rayoracle::case::Kind::ALL.map(rayoracle::case::Kind::compiled_in);
    let want: [u64; 4] = core::array::from_fn(|i| if compiled_in[i] { pinned[i] } else { EMPTY });
    assert_eq!(
        got, want,
        "kernel outputs changed: plane, sphere, quadric, camera digests (see the module docs)"
    );
}
