//! The generated families: the seeded `random/*` families of every kind
//! and `camera/invalid`, run beside the compiled-in fixtures.
//!
//! Besides the plain random draws (`*/random/any`, `aimed`, `inside`),
//! each family below aims at a class of bugs that no fixture family
//! reaches with many cases, and draws from a stream of its own (seeded by
//! its full name, [`kind_seed`]), so that adding one leaves the others'
//! cases unchanged:
//!
//! * `*/random/small-root`: a nearest positive root in `(1e-30, 1e-4]`
//!   (plane) or `(0, 2⁻²³]` (sphere, quadric), so that a cutoff such as
//!   `t > 1e-4` or `t > f32::EPSILON` misses it;
//! * `*/random/on-surface`, `plane/random/on-plane`: the origin exactly on
//!   the surface (a root exactly 0), every input a small integer (where
//!   the judge forgives no rounding), so that a nearest `t ≥ 0` answers 0
//!   where `t > 0` wants the other root or none;
//! * `quadric/random/line-on-surface`, `plane/random/in-plane`: lines on
//!   the surface (every `t`) in small integers;
//! * `sphere/random/tangent`: exact tangents in small integers, which a
//!   kernel that takes `b² − ac = 0` for a miss gets wrong;
//! * `plane/random/grazing`: `|d·n|` from about `2⁻³⁵` to `2⁻²⁰` of
//!   `|d||n|`, a hit far away; `plane/random/short-normal`: a normal
//!   `2⁻⁴⁰` to `2⁻²⁰` long met at an angle, which an absolute `|d·n| <
//!   1e-6` parallel test drops;
//! * `sphere/random/far`, `sphere/random/far-graze`: `|f|/R` from about 10⁵
//!   to 10¹² at distances up to 10¹² (radii down to 10⁻⁹), through the
//!   centre or off it, and rays grazing the silhouette, where even the
//!   textbook `b² − ac` in f64 loses the class;
//!   `quadric/random/far-sphere` is the first of them as a quadric
//!   `x² + y² + z² − R²` seen from `o − C`;
//! * `camera/random/narrow` (valid fields of view down to 2⁻²⁰),
//!   `camera/random/parallel-up` and `camera/random/bad-angle`
//!   (parameters the oracle refuses).

use super::Sourced;
use crate::Ray;
use crate::camera::CameraParams;
use crate::case::Case;
use crate::hit::Intersection;
use crate::plane::Plane;
use crate::quadric::Quadric;
use crate::sphere::Sphere;
use glam::{DVec3, Vec3};
use rand::{Rng, SeedableRng, rngs::SmallRng};

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
    let mut out = plain_random(kind, seed, n);
    let aimed: &[(&str, Draw)] = match kind {
        "sphere" => &[
            ("small-root", sphere_small_root),
            ("on-surface", sphere_on_surface),
            ("tangent", sphere_tangent),
            ("far", |r| far_sphere(r, false).map(sphere_case)),
            ("far-graze", |r| far_sphere(r, true).map(sphere_case)),
        ],
        "plane" => &[
            ("small-root", plane_small_root),
            ("on-plane", plane_on_plane),
            ("in-plane", plane_in_plane),
            ("grazing", plane_grazing),
            ("short-normal", plane_short_normal),
        ],
        "quadric" => &[
            ("small-root", quadric_small_root),
            ("on-surface", quadric_on_surface),
            ("line-on-surface", quadric_line_on_surface),
            ("far-sphere", far_sphere_quadric),
        ],
        "camera" => &[
            ("narrow", camera_narrow),
            ("parallel-up", camera_parallel_up),
            ("bad-angle", camera_bad_angle),
        ],
        _ => &[],
    };
    for (name, draw) in aimed {
        let family = format!("{kind}/random/{name}");
        let mut rng = SmallRng::seed_from_u64(kind_seed(&family, seed));
        // A draw may be rejected (the exact answer outside the family's
        // range); a bounded number of tries keeps the cost fixed.
        let cases = (0..n * 4).filter_map(|_| draw(&mut rng)).take(n);
        out.extend(cases.map(|c| (family.clone(), c)));
    }
    out
}

/// One draw of a generated family: a case, or `None` if rejected.
type Draw = fn(&mut SmallRng) -> Option<Case>;

/// `2^e` for an `e` of the normal range, exactly (no `libm`).
fn pow2(e: i32) -> f64 {
    f64::from_bits(((1023 + i64::from(e)) as u64) << 52)
}

/// A log-uniform value in `[2^lo, 2^hi)`.
fn log2_uniform(rng: &mut SmallRng, lo: i32, hi: i32) -> f64 {
    rng.random_range(1.0..2.0) * pow2(rng.random_range(lo..hi))
}

fn v3(rng: &mut SmallRng, s: f32) -> Vec3 {
    Vec3::new(
        rng.random_range(-s..s),
        rng.random_range(-s..s),
        rng.random_range(-s..s),
    )
}

/// A vector of small integers in `-m..=m`.
fn int3(rng: &mut SmallRng, m: i32) -> Vec3 {
    Vec3::new(
        rng.random_range(-m..=m) as f32,
        rng.random_range(-m..=m) as f32,
        rng.random_range(-m..=m) as f32,
    )
}

/// The smallest root above 0 of an answer's roots.
fn first_positive(roots: &[f32]) -> Option<f32> {
    roots.iter().copied().find(|&t| t > 0.0)
}

/// The plane with a root in `(1e-30, 1e-4]`: the plane's point is the
/// origin plus `t d`, everything at the scale of `t` (or, for `t` above
/// 2⁻²⁰, the origin at the scale of 1).
fn plane_small_root(rng: &mut SmallRng) -> Option<Case> {
    use crate::plane::{PlaneHit, exact};
    let t = log2_uniform(rng, -99, -14);
    let n = v3(rng, 1.0);
    let d = v3(rng, 1.0);
    if d.dot(n).abs() < 0.2 * d.length() * n.length() {
        return None;
    }
    let scale = if t > pow2(-20) && rng.random() {
        1.0
    } else {
        t * 4.0
    };
    let o = v3(rng, 1.0) * scale as f32;
    let point = o + d * t as f32;
    let (ray, p) = (Ray::new(o, d), Plane::new(point, n));
    match exact::intersect(&ray, &p) {
        Ok(PlaneHit::Hit(t)) if t > 1e-30 && t <= 1e-4 => Some(Case::Plane(ray, p)),
        _ => None,
    }
}

/// A sphere whose near root is in `(0, 2⁻²³]`: the origin just outside
/// the surface, going in; radii from 2⁻⁴⁰ up, so that `R²` stays normal.
fn sphere_small_root(rng: &mut SmallRng) -> Option<Case> {
    use crate::sphere::exact;
    let t = log2_uniform(rng, -60, -23);
    let r = t * pow2(rng.random_range(2..18));
    if r < pow2(-40) {
        return None;
    }
    let u = v3(rng, 1.0).normalize_or_zero();
    let mut d = v3(rng, 1.0);
    if d.dot(u) > 0.0 {
        d = -d;
    }
    if d.dot(u) > -0.2 * d.length() {
        return None;
    }
    let c = v3(rng, 4.0 * r as f32);
    let o = (c + u * r as f32) - d * t as f32;
    let (ray, s) = (Ray::new(o, d), Sphere::new(c, r as f32));
    let near = first_positive(exact::intersect(&ray, &s).ok()?.roots().as_slice())?;
    (near <= f32::EPSILON).then_some(Case::Sphere(ray, s))
}

/// A quadric whose nearest positive root is in `(0, 2⁻²³]`: `J` chosen so
/// that `γ ≈ −β t` at an origin near 0, at the scale of `t`.
fn quadric_small_root(rng: &mut SmallRng) -> Option<Case> {
    use crate::quadric::exact;
    let t = log2_uniform(rng, -60, -23);
    let mut k = random_coeffs(rng);
    let d = v3(rng, 1.0);
    let o = v3(rng, 1.0) * (t / 16.0) as f32;
    let (od, dd) = (o.as_dvec3(), d.as_dvec3());
    let lin = DVec3::new(k[6].into(), k[7].into(), k[8].into());
    let beta = lin.dot(dd);
    if beta.abs() < 0.1 {
        return None;
    }
    k[9] = (-(beta * t + lin.dot(od))) as f32;
    let (ray, q) = (Ray::new(o, d), Quadric::new(k));
    let near = first_positive(exact::intersect(&ray, &q).ok()?.roots().as_slice())?;
    (near <= f32::EPSILON).then_some(Case::Quadric(ray, q))
}

/// The coefficients of `quadric/random/any`: `A, B, C` in `±2`, the rest
/// in `±1`.
fn random_coeffs(rng: &mut SmallRng) -> [f32; 10] {
    core::array::from_fn(|i| {
        let s = if i < 3 { 2.0 } else { 1.0 };
        rng.random_range(-s..s)
    })
}

/// Pythagorean quadruples `(a, b, c, R)`: `a² + b² + c² = R²`.
const QUADS: [[f32; 4]; 5] = [
    [3.0, 4.0, 0.0, 5.0],
    [2.0, 3.0, 6.0, 7.0],
    [1.0, 2.0, 2.0, 3.0],
    [2.0, 6.0, 9.0, 11.0],
    [0.0, 0.0, 1.0, 1.0],
];

/// A vector of length `R` in integers, and `R`: a quadruple, signed and
/// rotated.
fn int_radius(rng: &mut SmallRng) -> (Vec3, f32) {
    let [a, b, c, r] = QUADS[rng.random_range(0..QUADS.len())];
    let mut w = [a, b, c].map(|x| if rng.random() { -x } else { x });
    w.rotate_left(rng.random_range(0..3));
    (Vec3::from_array(w), r)
}

/// Whether every component is at most 16 in magnitude (with integer
/// inputs: the judge's small integers, where it forgives no rounding).
fn small(v: &[Vec3]) -> bool {
    v.iter().all(|x| x.abs().max_element() <= 16.0)
}

/// The origin exactly on a sphere, in small integers: `C` plus a vector
/// of length `R`; any integer direction.
fn sphere_on_surface(rng: &mut SmallRng) -> Option<Case> {
    let (w, r) = int_radius(rng);
    let centre = int3(rng, 4);
    let (o, d) = (centre + w, int3(rng, 3));
    (d != Vec3::ZERO && small(&[o])).then_some(Case::Sphere(Ray::new(o, d), Sphere::new(centre, r)))
}

/// A line tangent to a sphere, in small integers: the direction is
/// perpendicular to the radius `w` at the touching point, the origin `k`
/// steps from it, so the double root is `−k`.
fn sphere_tangent(rng: &mut SmallRng) -> Option<Case> {
    let (w, r) = int_radius(rng);
    let centre = int3(rng, 2);
    let d = w.cross(int3(rng, 1));
    let o = centre + w + d * rng.random_range(-1..=1) as f32;
    (d != Vec3::ZERO && small(&[o, d]))
        .then_some(Case::Sphere(Ray::new(o, d), Sphere::new(centre, r)))
}

/// The origin exactly on a plane, in small integers: the plane's point
/// plus `n × v`; an integer direction off the plane.
fn plane_on_plane(rng: &mut SmallRng) -> Option<Case> {
    let (p, n) = (int3(rng, 8), int3(rng, 2));
    let o = p + n.cross(int3(rng, 2));
    let d = int3(rng, 3);
    (d.dot(n) != 0.0 && small(&[o])).then_some(Case::Plane(Ray::new(o, d), Plane::new(p, n)))
}

/// A line exactly in a plane, in small integers: the origin and the
/// direction both `n × v` away from the plane's point, so that a kernel
/// without the in-plane case (every `t`) answers "parallel".
fn plane_in_plane(rng: &mut SmallRng) -> Option<Case> {
    let (p, n) = (int3(rng, 4), int3(rng, 2));
    let o = p + n.cross(int3(rng, 2));
    let d = n.cross(int3(rng, 2));
    (d != Vec3::ZERO && small(&[o, d])).then_some(Case::Plane(Ray::new(o, d), Plane::new(p, n)))
}

/// The origin exactly on a quadric, in small integers: `J` makes `γ = 0`.
fn quadric_on_surface(rng: &mut SmallRng) -> Option<Case> {
    let mut k: [f32; 10] = core::array::from_fn(|_| rng.random_range(-2..=2) as f32);
    let o = int3(rng, 2);
    let [x, y, z] = o.to_array();
    let terms = [x * x, y * y, z * z, x * y, x * z, y * z, x, y, z];
    k[9] = -terms.iter().zip(&k).map(|(t, c)| t * c).sum::<f32>();
    let d = int3(rng, 3);
    (d != Vec3::ZERO && k[9].abs() <= 16.0)
        .then_some(Case::Quadric(Ray::new(o, d), Quadric::new(k)))
}

/// A plane whose normal is short, `2⁻⁴⁰` to `2⁻²⁰` long (as an
/// unnormalised normal may be), met at an angle: `d·n` is small in
/// absolute terms only.
fn plane_short_normal(rng: &mut SmallRng) -> Option<Case> {
    let n = v3(rng, 1.0);
    let d = v3(rng, 1.0);
    let len = log2_uniform(rng, -40, -20) as f32;
    let n = n.normalize_or_zero() * len;
    let (o, p) = (v3(rng, 10.0), v3(rng, 10.0));
    (d.dot(n).abs() > 0.2 * d.length() * n.length())
        .then_some(Case::Plane(Ray::new(o, d), Plane::new(p, n)))
}

/// A line on a quadric, in small integers: random coefficients and a
/// direction with a unit component, then `A` (or `B`, `C`) makes `α = 0`,
/// `G` (or `H`, `I`) makes `β = 0` and `J` makes `γ = 0`.
fn quadric_line_on_surface(rng: &mut SmallRng) -> Option<Case> {
    let mut k: [f32; 10] = core::array::from_fn(|_| rng.random_range(-2..=2) as f32);
    let axis = rng.random_range(0..3);
    let mut d = int3(rng, 1);
    d[axis] = if rng.random() { 1.0 } else { -1.0 };
    let o = int3(rng, 2);
    // Small integers: every term and sum is exact in f64.
    let eq = |k: &[f32; 10]| {
        let (a, b, g) = crate::quadric::terms(&Ray::new(o, d), &Quadric::new(*k));
        let sum = |x: &[f64]| x.iter().sum::<f64>() as f32;
        (sum(&a), sum(&b), sum(&g))
    };
    // d[axis] = ±1: each step is exact in small integers and zeroes its
    // equation without touching the ones before it.
    k[axis] -= eq(&k).0;
    k[6 + axis] -= eq(&k).1 * d[axis];
    k[9] -= eq(&k).2;
    (eq(&k) == (0.0, 0.0, 0.0) && k.iter().all(|x| x.abs() <= 16.0))
        .then_some(Case::Quadric(Ray::new(o, d), Quadric::new(k)))
}

/// A ray nearly in the plane, so the hit is far but real: a unit vector
/// along the plane, rounded to f32, plus `2⁻⁴⁰` to `2⁻²⁰` of the unit
/// normal. Below about `2⁻²⁴` the first's rounding sets `|d·n|`, which
/// ends between about `2⁻³⁵` and `2⁻²⁰` of `|d||n|`, mostly above `2⁻²⁸`.
fn plane_grazing(rng: &mut SmallRng) -> Option<Case> {
    let n = v3(rng, 1.0).normalize_or_zero();
    let along = n.cross(v3(rng, 1.0)).normalize_or_zero();
    let eps = log2_uniform(rng, -40, -20) as f32;
    let d = along + n * if rng.random() { eps } else { -eps };
    let (o, p) = (v3(rng, 10.0), v3(rng, 10.0));
    (n != Vec3::ZERO && along != Vec3::ZERO && d.dot(n) != 0.0)
        .then_some(Case::Plane(Ray::new(o, d), Plane::new(p, n)))
}

/// A sphere far from the origin: `|f|` from 2³ to 2⁴⁰ (about 10¹²),
/// `|f|/R` from 2²⁰ to 2⁴⁰ (10⁶ to 10¹²), `R` at least 2⁻³⁰. Half the
/// origins are 0, the centre exactly `2^k d` (through the centre, at any
/// ratio); the others are off the line by rounding, and `R` grows to hit
/// when the ray passes outside. With `graze`, `R` is the distance from
/// the centre to the line within 2⁻²³ to 2⁻⁸ (relative) either way.
fn far_sphere(rng: &mut SmallRng, graze: bool) -> Option<(Ray, Sphere)> {
    let e = rng.random_range(3..40);
    let q = rng.random_range(20..41);
    let d = v3(rng, 1.0);
    let o = if rng.random() {
        Vec3::ZERO
    } else {
        v3(rng, 4.0)
    };
    let mut c = o + d * pow2(e) as f32;
    if graze && o == Vec3::ZERO {
        for _ in 0..rng.random_range(1..4) {
            c.x = c.x.next_up();
        }
    }
    let (f, dd) = ((o.as_dvec3() - c.as_dvec3()), d.as_dvec3());
    let p = f.cross(dd).length() / dd.length();
    let r = if graze {
        let rel = log2_uniform(rng, -23, -8);
        p * if rng.random() { 1.0 + rel } else { 1.0 - rel }
    } else {
        let r = rng.random_range(1.0..2.0) * pow2(e - q);
        if p >= r {
            p * rng.random_range(1.2..4.0)
        } else {
            r
        }
    };
    let r = r as f32;
    (d != Vec3::ZERO && r >= pow2(-30) as f32 && r.is_finite())
        .then_some((Ray::new(o, d), Sphere::new(c, r)))
}

fn sphere_case((ray, s): (Ray, Sphere)) -> Case {
    Case::Sphere(ray, s)
}

/// [`far_sphere`] as the quadric `x² + y² + z² − R² = 0` seen from
/// `o − C`.
fn far_sphere_quadric(rng: &mut SmallRng) -> Option<Case> {
    let (ray, s) = far_sphere(rng, false)?;
    let r2 = (f64::from(s.radius) * f64::from(s.radius)) as f32;
    let k = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -r2];
    (r2 > 0.0).then(|| Case::Quadric(Ray::new(ray.origin - s.center, ray.dir), Quadric::new(k)))
}

/// A valid camera with a narrow field of view, `2⁻²⁰` to `2⁻³` radians.
fn camera_narrow(rng: &mut SmallRng) -> Option<Case> {
    let angle = log2_uniform(rng, -20, -3) as f32;
    camera_with_angle(rng, angle).filter(|c| match c {
        Case::Camera(p, _) => p.build().is_ok(),
        _ => false,
    })
}

/// A camera whose `up` is `±2^k dir`, exactly parallel to it.
fn camera_parallel_up(rng: &mut SmallRng) -> Option<Case> {
    let Some(Case::Camera(mut p, px)) = camera_with_angle(rng, 1.0) else {
        return None;
    };
    let s = pow2(rng.random_range(-8..9)) as f32;
    p.up = p.dir * if rng.random() { s } else { -s };
    (p.dir != Vec3::ZERO).then_some(Case::Camera(p, px))
}

/// A camera with a field of view outside `(0, π)`: from `π` (as an f32,
/// above the real π) to 8, 0, or negative.
fn camera_bad_angle(rng: &mut SmallRng) -> Option<Case> {
    let angle = match rng.random_range(0..4) {
        0 => std::f32::consts::PI,
        1 => rng.random_range(std::f32::consts::PI..8.0),
        2 => 0.0,
        _ => -rng.random_range(0.0..4.0f32),
    };
    camera_with_angle(rng, angle)
}

/// A random camera (as `camera/random/any`) with the given angle.
fn camera_with_angle(rng: &mut SmallRng, angle: f32) -> Option<Case> {
    let res = [rng.random_range(1..2000u32), rng.random_range(1..2000u32)];
    let p = CameraParams::new(v3(rng, 10.0), v3(rng, 1.0), v3(rng, 1.0), angle, res);
    let px = [rng.random_range(0..res[0]), rng.random_range(0..res[1])];
    Some(Case::Camera(p, px))
}

/// The plain random families (`aimed`, `inside`, `any`), one stream a kind.
fn plain_random(kind: &str, seed: u64, n: usize) -> Vec<Sourced> {
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
