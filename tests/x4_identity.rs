//! x4 against the reference, bit for bit, on packets that mix unrelated
//! cases: a miss beside a two-hit beside a NaN beside a tangent, with
//! ±0, ±∞, subnormals and values near f32::MAX in any lane.

use glam::Vec3;
use proptest::prelude::*;
use rayoracle::camera::CameraParams;
#[cfg(feature = "plane")]
use rayoracle::plane::{self, Plane, PlaneHit};
#[cfg(feature = "quadric")]
use rayoracle::quadric::{self, Quadric, QuadricHit};
use rayoracle::ray4::for_each4;
#[cfg(feature = "sphere")]
use rayoracle::sphere::{self, Sphere, SphereHit};
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use rayoracle::{
    Ray,
    hit::{Intersection, same_bits},
    ray4::Ray4,
};
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use wide::f32x4;

/// Any f32: every bit pattern, with the interesting ones over-represented.
fn any_f32() -> impl Strategy<Value = f32> {
    prop_oneof![
        3 => (-8i32..8).prop_map(|i| i as f32),
        3 => -1e3f32..1e3,
        2 => any::<u32>().prop_map(f32::from_bits),
        1 => prop::sample::select(vec![
            0.0, -0.0, f32::INFINITY, f32::NEG_INFINITY, f32::NAN, f32::MAX, -f32::MAX,
            f32::MIN_POSITIVE, f32::from_bits(1), -f32::from_bits(1), f32::EPSILON, 1e30, -1e-30,
            3.4e38, 1.7e38, 1e-40,
        ]),
    ]
}

fn vec3() -> impl Strategy<Value = Vec3> {
    (any_f32(), any_f32(), any_f32()).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn ray() -> impl Strategy<Value = Ray> {
    (vec3(), vec3()).prop_map(|(o, d)| Ray::new(o, d))
}

/// Sensible geometry, so packets also hold real hits, tangents and misses.
#[cfg(feature = "sphere")]
fn tame_sphere_case() -> impl Strategy<Value = (Ray, Sphere)> {
    (-4i32..4, -4i32..4, -4i32..4, 1i32..4, -3i32..3, -3i32..3).prop_map(
        |(ox, oy, cz, r, dx, dy)| {
            let ray = Ray::new(
                Vec3::new(ox as f32, oy as f32, -10.0),
                Vec3::new(dx as f32, dy as f32, 4.0),
            );
            (ray, Sphere::new(Vec3::new(0.0, 0.0, cz as f32), r as f32))
        },
    )
}

#[cfg(feature = "sphere")]
fn sphere_case() -> impl Strategy<Value = (Ray, Sphere)> {
    prop_oneof![
        tame_sphere_case(),
        (ray(), vec3(), any_f32()).prop_map(|(r, c, rad)| (r, Sphere::new(c, rad))),
    ]
}

#[cfg(feature = "plane")]
fn plane_case() -> impl Strategy<Value = (Ray, Plane)> {
    prop_oneof![
        (-4i32..4, -4i32..4, 0i32..3).prop_map(|(y, dy, axis)| {
            let mut n = Vec3::ZERO;
            n[axis as usize] = 1.0;
            (
                Ray::new(
                    Vec3::new(1.0, y as f32, 2.0),
                    Vec3::new(1.0, dy as f32, 0.0),
                ),
                Plane::new(Vec3::ZERO, n),
            )
        }),
        (ray(), vec3(), vec3()).prop_map(|(r, a, n)| (r, Plane::new(a, n))),
    ]
}

#[cfg(feature = "quadric")]
fn quadric_case() -> impl Strategy<Value = (Ray, Quadric)> {
    let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
    prop_oneof![
        (-3i32..3, -3i32..3, -1i32..2, -1i32..2).prop_map(move |(ox, oy, dx, dz)| {
            (
                Ray::new(
                    Vec3::new(ox as f32, oy as f32, 0.0),
                    Vec3::new(dx as f32, 0.0, dz as f32),
                ),
                cyl,
            )
        }),
        (ray(), prop::array::uniform10(any_f32())).prop_map(|(r, k)| (r, Quadric::new(k))),
    ]
}

/// Bit equality, with any NaN equal to any NaN.
fn same(a: f32, b: f32) -> bool {
    a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
}

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn same_opt(a: Option<f32>, hit: bool, t: f32) -> bool {
    match a {
        Some(x) => hit && same(x, t),
        None => !hit && t == f32::INFINITY,
    }
}

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
const T_MIN: f32 = 0.0;
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
const T_MAX: f32 = 1e30;

proptest! {
    #![proptest_config(ProptestConfig { cases: 2048, ..ProptestConfig::default() })]

    #[cfg(feature = "sphere")]
    #[test]
    fn sphere_lanes_equal_the_reference(cases in prop::array::uniform4(sphere_case())) {
        let r4 = Ray4::from_rays(cases.map(|c| c.0));
        let s4 = sphere::x4::Sphere4::from_spheres(cases.map(|c| c.1));
        let h4 = sphere::x4::intersect(&r4, &s4);
        let (mask, t) = h4.nearest(f32x4::splat(T_MIN), f32x4::splat(T_MAX));
        let (mask, t) = (mask.to_bitmask(), t.to_array());
        for (i, (r, s)) in cases.iter().enumerate() {
            let want: SphereHit = sphere::reference::intersect(r, s);
            prop_assert!(same_bits(&h4.lanes()[i], &want), "lane {i}: {:?} vs {:?} for {r:?} {s:?}", h4.lanes()[i], want);
            prop_assert!(same_opt(want.nearest(T_MIN, T_MAX), mask >> i & 1 == 1, t[i]), "nearest lane {i}");
        }
    }

    #[cfg(feature = "plane")]
    #[test]
    fn plane_lanes_equal_the_reference(cases in prop::array::uniform4(plane_case())) {
        let r4 = Ray4::from_rays(cases.map(|c| c.0));
        let p4 = plane::x4::Plane4::from_planes(cases.map(|c| c.1));
        let h4 = plane::x4::intersect(&r4, &p4);
        let (mask, t) = h4.nearest(f32x4::splat(T_MIN), f32x4::splat(T_MAX));
        let (mask, t) = (mask.to_bitmask(), t.to_array());
        for (i, (r, p)) in cases.iter().enumerate() {
            let want: PlaneHit = plane::reference::intersect(r, p);
            prop_assert!(same_bits(&h4.lanes()[i], &want), "lane {i}: {:?} vs {:?} for {r:?} {p:?}", h4.lanes()[i], want);
            prop_assert!(same_opt(want.nearest(T_MIN, T_MAX), mask >> i & 1 == 1, t[i]), "nearest lane {i}");
        }
    }

    #[cfg(feature = "quadric")]
    #[test]
    fn quadric_lanes_equal_the_reference(cases in prop::array::uniform4(quadric_case())) {
        let r4 = Ray4::from_rays(cases.map(|c| c.0));
        let q4 = quadric::x4::Quadric4::from_quadrics(cases.map(|c| c.1));
        let h4 = quadric::x4::intersect(&r4, &q4);
        let (mask, t) = h4.nearest(f32x4::splat(T_MIN), f32x4::splat(T_MAX));
        let (mask, t) = (mask.to_bitmask(), t.to_array());
        for (i, (r, q)) in cases.iter().enumerate() {
            let want: QuadricHit = quadric::reference::intersect(r, q);
            prop_assert!(same_bits(&h4.lanes()[i], &want), "lane {i}: {:?} vs {:?} for {r:?} {q:?}", h4.lanes()[i], want);
            prop_assert!(same_opt(want.nearest(T_MIN, T_MAX), mask >> i & 1 == 1, t[i]), "nearest lane {i}");
        }
    }

    #[test]
    fn camera_packets_equal_the_reference(
        dir in vec3(), up in vec3(), angle in any_f32(),
        w in 1u32..5000, h in 1u32..5000, px in prop::array::uniform4((0u32..5000, 0u32..5000)),
    ) {
        let p = CameraParams::new(Vec3::new(1.0, -2.0, 3.0), dir, up, angle, [w, h]);
        if let Ok(cam) = p.build() {
            let px = px.map(|(x, y)| [x % w, y % h]);
            let got = cam.ray4(px).to_rays();
            for i in 0..4 {
                let want = cam.ray(px[i][0], px[i][1]);
                for c in 0..3 {
                    prop_assert!(same(got[i].dir[c], want.dir[c]), "pixel {:?} component {c}", px[i]);
                }
                prop_assert_eq!(got[i].origin, want.origin);
            }
        }
    }

    /// A row and a tile, whose numerators are built in vector registers,
    /// give what `Camera::ray4` gives for the same four pixels, inside
    /// the image or straddling its edge.
    #[test]
    fn rows_and_tiles_equal_their_pixels(
        dir in vec3(), up in vec3(), angle in any_f32(),
        w in 1u32..64, h in 1u32..64, x in 0u32..70, y in 0u32..70,
    ) {
        let p = CameraParams::new(Vec3::new(1.0, -2.0, 3.0), dir, up, angle, [w, h]);
        if let Ok(cam) = p.build() {
            let row = [[x, y], [x + 1, y], [x + 2, y], [x + 3, y]];
            let tile = [[x, y], [x + 1, y], [x, y + 1], [x + 1, y + 1]];
            let bits = |r: [rayoracle::Ray; 4]| r.map(|r| r.dir.to_array().map(f32::to_bits));
            prop_assert_eq!(bits(cam.ray4_row(x, y).to_rays()), bits(cam.ray4(row).to_rays()));
            prop_assert_eq!(bits(cam.ray4_tile(x, y).to_rays()), bits(cam.ray4(tile).to_rays()));
        }
    }

    /// The batch entry points give, packet by packet, what `intersect`
    /// gives, for any number of packets (odd ones included) and an output
    /// slice of any length.
    #[cfg(all(feature = "sphere", feature = "plane", feature = "quadric"))]
    #[test]
    fn packets_equal_one_packet_at_a_time(
        spheres in prop::collection::vec(prop::array::uniform4(sphere_case()), 0..6),
        planes in prop::collection::vec(prop::array::uniform4(plane_case()), 0..6),
        quadrics in prop::collection::vec(prop::array::uniform4(quadric_case()), 0..6),
        short in 0usize..2,
    ) {
        let r4 = |c: &[(Ray, Sphere); 4]| Ray4::from_rays(c.map(|c| c.0));
        let rays: Vec<Ray4> = spheres.iter().map(r4).collect();
        let s4 = sphere::x4::Sphere4::from_spheres(spheres.first().map_or([Sphere::new(Vec3::ZERO, 1.0); 4], |c| c.map(|c| c.1)));
        let n = rays.len().saturating_sub(short);
        let mut out = vec![sphere::x4::intersect(&Ray4::splat(Ray::new(Vec3::ZERO, Vec3::Z)), &s4); n];
        sphere::x4::intersect_packets(&rays, &s4, &mut out);
        for (r, h) in rays.iter().zip(&out) {
            let want = sphere::x4::intersect(r, &s4);
            prop_assert!(h.lanes().iter().zip(want.lanes().iter()).all(|(a, b)| same_bits(a, b)));
        }

        let rays: Vec<Ray4> = planes.iter().map(|c| Ray4::from_rays(c.map(|c| c.0))).collect();
        let p4 = plane::x4::Plane4::from_planes(planes.first().map_or([Plane::new(Vec3::ZERO, Vec3::Y); 4], |c| c.map(|c| c.1)));
        let mut out = vec![plane::x4::intersect(&Ray4::splat(Ray::new(Vec3::ZERO, Vec3::Z)), &p4); rays.len()];
        plane::x4::intersect_packets(&rays, &p4, &mut out);
        for (r, h) in rays.iter().zip(&out) {
            let want = plane::x4::intersect(r, &p4);
            prop_assert!(h.lanes().iter().zip(want.lanes().iter()).all(|(a, b)| same_bits(a, b)));
        }

        let rays: Vec<Ray4> = quadrics.iter().map(|c| Ray4::from_rays(c.map(|c| c.0))).collect();
        let unit = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let q4 = quadric::x4::Quadric4::from_quadrics(quadrics.first().map_or([unit; 4], |c| c.map(|c| c.1)));
        let mut out = vec![quadric::x4::intersect(&Ray4::splat(Ray::new(Vec3::ZERO, Vec3::Z)), &q4); rays.len()];
        quadric::x4::intersect_packets(&rays, &q4, &mut out);
        for (r, h) in rays.iter().zip(&out) {
            let want = quadric::x4::intersect(r, &q4);
            prop_assert!(h.lanes().iter().zip(want.lanes().iter()).all(|(a, b)| same_bits(a, b)));
        }
    }

    /// Tails of 1 to 3 rays: the helper must give exactly one result per ray,
    /// equal to the reference, whatever the length.
    #[cfg(feature = "sphere")]
    #[test]
    fn slices_of_any_length_match_ray_by_ray(cases in prop::collection::vec(sphere_case(), 1..12)) {
        let sphere = cases[0].1;
        let rays: Vec<Ray> = cases.iter().map(|c| c.0).collect();
        let got = sphere::x4::intersect_slice(&rays, &sphere);
        prop_assert_eq!(got.len(), rays.len());
        for (r, g) in rays.iter().zip(&got) {
            prop_assert!(same_bits(g, &sphere::reference::intersect(r, &sphere)));
        }
    }
}

#[test]
fn tail_lanes_never_read_past_the_slice() {
    // Each kernel call records the packet it saw: the filler lanes of the
    // last packet repeat the last real element instead of anything else.
    let items: Vec<u32> = (1..=7).collect();
    let mut seen = Vec::new();
    let mut out = Vec::new();
    for_each4(
        &items,
        |p| {
            seen.push(p);
            p.map(|x| x * 2)
        },
        &mut out,
    );
    assert_eq!(out, vec![2, 4, 6, 8, 10, 12, 14]);
    assert_eq!(seen, vec![[1, 2, 3, 4], [5, 6, 7, 7]]);
    for n in 1..=3 {
        let mut out = Vec::new();
        for_each4(&items[..n], |p| p, &mut out);
        assert_eq!(out, items[..n].to_vec());
    }
}

/// The two compiled copies of each x4 kernel, the AVX2 one (one 256-bit
/// register per value) and the baseline one (`wide::f64x4`, two SSE2
/// registers in a default build), give the same bits on the stiff
/// catalogue (`fixtures/stiff/`) and on random packets. Where the CPU lacks
/// AVX2, the dispatching `intersect` must be the baseline copy.
#[cfg(all(
    target_arch = "x86_64",
    feature = "plane",
    feature = "sphere",
    feature = "quadric"
))]
mod avx2_against_baseline {
    use super::*;
    use rayoracle::case::{Case, parse_line};
    use rayoracle::num::avx::Avx2;
    use wide::i32x4;

    /// The raw bits of each field, NaNs included.
    fn bits(class: i32x4, ts: &[f32x4]) -> Vec<u32> {
        let mut v: Vec<u32> = class.to_array().map(|c| c as u32).to_vec();
        for t in ts {
            v.extend(t.to_array().map(f32::to_bits));
        }
        v
    }

    fn sphere_bits(r: &Ray4, s: &sphere::x4::Sphere4, avx2: Option<Avx2>) -> Vec<u32> {
        let h = match avx2 {
            Some(t) => sphere::x4::intersect_avx2(t, r, s),
            None => sphere::x4::intersect(r, s),
        };
        bits(h.class, &[h.t0, h.t1])
    }

    fn plane_bits(r: &Ray4, p: &plane::x4::Plane4, avx2: Option<Avx2>) -> Vec<u32> {
        let h = match avx2 {
            Some(t) => plane::x4::intersect_avx2(t, r, p),
            None => plane::x4::intersect(r, p),
        };
        bits(h.class, &[h.t])
    }

    fn quadric_bits(r: &Ray4, q: &quadric::x4::Quadric4, avx2: Option<Avx2>) -> Vec<u32> {
        let h = match avx2 {
            Some(t) => quadric::x4::intersect_avx2(t, r, q),
            None => quadric::x4::intersect(r, q),
        };
        bits(h.class, &[h.t0, h.t1])
    }

    fn sphere_same(cases: [(Ray, Sphere); 4]) -> bool {
        let (r, s) = (
            Ray4::from_rays(cases.map(|c| c.0)),
            sphere::x4::Sphere4::from_spheres(cases.map(|c| c.1)),
        );
        let base = sphere::x4::intersect_baseline(&r, &s);
        sphere_bits(&r, &s, Avx2::detect()) == bits(base.class, &[base.t0, base.t1])
    }

    fn plane_same(cases: [(Ray, Plane); 4]) -> bool {
        let (r, p) = (
            Ray4::from_rays(cases.map(|c| c.0)),
            plane::x4::Plane4::from_planes(cases.map(|c| c.1)),
        );
        let base = plane::x4::intersect_baseline(&r, &p);
        plane_bits(&r, &p, Avx2::detect()) == bits(base.class, &[base.t])
    }

    fn quadric_same(cases: [(Ray, Quadric); 4]) -> bool {
        let (r, q) = (
            Ray4::from_rays(cases.map(|c| c.0)),
            quadric::x4::Quadric4::from_quadrics(cases.map(|c| c.1)),
        );
        let base = quadric::x4::intersect_baseline(&r, &q);
        quadric_bits(&r, &q, Avx2::detect()) == bits(base.class, &[base.t0, base.t1])
    }

    /// The cases of one file of the catalogue.
    fn catalogue(kernel: &str) -> Vec<Case> {
        let path = format!(
            "{}/fixtures/stiff/{kernel}.jsonl",
            env!("CARGO_MANIFEST_DIR")
        );
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        text.lines()
            .map(|l| parse_line(l).unwrap_or_else(|e| panic!("{path}: {e}")).case)
            .collect()
    }

    /// Packets of four consecutive cases, and of each case beside the ones
    /// a quarter and a half of the file away (other families).
    fn packets<T: Copy>(v: &[T]) -> Vec<[T; 4]> {
        let n = v.len();
        let mut out: Vec<[T; 4]> = v
            .chunks_exact(4)
            .map(|c| [c[0], c[1], c[2], c[3]])
            .collect();
        out.extend((0..n).map(|i| [0, n / 4, n / 2, 3 * n / 4].map(|k| v[(i + k) % n])));
        out
    }

    #[test]
    fn stiff_catalogue_gives_the_same_bits() {
        let spheres: Vec<(Ray, Sphere)> = catalogue("sphere")
            .into_iter()
            .filter_map(|c| match c {
                Case::Sphere(r, s) => Some((r, s)),
                _ => None,
            })
            .collect();
        let planes: Vec<(Ray, Plane)> = catalogue("plane")
            .into_iter()
            .filter_map(|c| match c {
                Case::Plane(r, p) => Some((r, p)),
                _ => None,
            })
            .collect();
        let quadrics: Vec<(Ray, Quadric)> = catalogue("quadric")
            .into_iter()
            .filter_map(|c| match c {
                Case::Quadric(r, q) => Some((r, q)),
                _ => None,
            })
            .collect();
        assert!(spheres.len() >= 1000 && planes.len() >= 1000 && quadrics.len() >= 1000);
        for p in packets(&spheres) {
            assert!(sphere_same(p), "{p:?}");
        }
        for p in packets(&planes) {
            assert!(plane_same(p), "{p:?}");
        }
        for p in packets(&quadrics) {
            assert!(quadric_same(p), "{p:?}");
        }
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 1024, ..ProptestConfig::default() })]

        #[test]
        fn random_sphere_packets_give_the_same_bits(cases in prop::array::uniform4(sphere_case())) {
            prop_assert!(sphere_same(cases));
        }

        #[test]
        fn random_plane_packets_give_the_same_bits(cases in prop::array::uniform4(plane_case())) {
            prop_assert!(plane_same(cases));
        }

        #[test]
        fn random_quadric_packets_give_the_same_bits(cases in prop::array::uniform4(quadric_case())) {
            prop_assert!(quadric_same(cases));
        }
    }
}
