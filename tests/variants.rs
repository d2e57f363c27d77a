//! The `textbook` and `plain` variants of each kernel (the baselines that
//! `rayoracle report` sets against the reference) are implemented correctly,
//! not broken on purpose: on seeded random well-conditioned cases, `plain`
//! classifies as the exact oracle does and its roots are within 1 ulp, and
//! `textbook` is within a few ulps on easy cases. `textbook`'s documented
//! failures (a far, small sphere; a quadric with α ≈ 0) are checked too, so
//! that the baseline stays the naive one.
//!
//! Run with `--nocapture` to see the largest errors measured.

use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};

/// Cases per property.
const N: usize = 4000;

/// A vector with components uniform in `[-r, r]`.
fn vec_in(rng: &mut SmallRng, r: f32) -> glam::Vec3 {
    glam::Vec3::new(
        rng.random_range(-r..=r),
        rng.random_range(-r..=r),
        rng.random_range(-r..=r),
    )
}

/// A direction with components in `[-1, 1]` and length at least ½.
fn unitish(rng: &mut SmallRng) -> glam::Vec3 {
    loop {
        let v = vec_in(rng, 1.0);
        if v.length() >= 0.5 {
            return v;
        }
    }
}

/// The roots of a result.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn roots<H: rayoracle::hit::Intersection>(h: &H) -> Vec<f32> {
    h.roots().as_slice().to_vec()
}

/// Draws cases until [`N`] of them pass `keep` (given the case and its exact
/// answer), and runs `got` on each: its class must be the exact one. Returns
/// the largest ulp distance between its roots and the exact ones, and prints
/// it under `what`.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn worst_ulps<C, H>(
    what: &str,
    rng: &mut SmallRng,
    case: impl Fn(&mut SmallRng) -> C,
    exact: impl Fn(&C) -> H,
    keep: impl Fn(&C, &H) -> bool,
    got: impl Fn(&C) -> H,
) -> u64
where
    C: std::fmt::Debug,
    H: rayoracle::hit::Intersection + std::fmt::Debug,
{
    let (mut worst, mut compared, mut count) = (0, 0, 0);
    while compared < N {
        let c = case(rng);
        let e = exact(&c);
        if !keep(&c, &e) {
            continue;
        }
        compared += 1;
        let g = got(&c);
        assert_eq!(g.class(), e.class(), "{what}: {c:?}: {g:?}, exact {e:?}");
        for (e, g) in roots(&e).into_iter().zip(roots(&g)) {
            worst = worst.max(rayoracle::ulp::ulps(e, g));
            count += 1;
        }
    }
    eprintln!("{what}: max {worst} ulps over {count} roots");
    worst
}

#[cfg(feature = "plane")]
mod plane {
    use super::*;
    use rayoracle::Ray;
    use rayoracle::check::plane_condition;
    use rayoracle::plane::{Plane, PlaneHit, exact, plain, textbook};

    /// Moderate random planes.
    fn random(rng: &mut SmallRng) -> (Ray, Plane) {
        let ray = Ray::new(vec_in(rng, 20.0), vec_in(rng, 5.0));
        (ray, Plane::new(vec_in(rng, 20.0), vec_in(rng, 3.0)))
    }

    fn exact_of(c: &(Ray, Plane)) -> PlaneHit {
        exact::intersect(&c.0, &c.1).unwrap()
    }

    /// The largest error of `got` on [`N`] random planes whose root has
    /// condition number below `kappa`.
    fn measure(what: &str, seed: u64, kappa: f64, got: fn(&Ray, &Plane) -> PlaneHit) -> u64 {
        let mut rng = SmallRng::seed_from_u64(seed);
        let below = |c: &(Ray, Plane), _: &_| plane_condition(&c.0, &c.1) < kappa;
        worst_ulps(what, &mut rng, random, exact_of, below, |c| got(&c.0, &c.1))
    }

    #[test]
    fn double_matches_the_oracle() {
        assert!(measure("plane plain, κ < 10⁴", 0x91a7e, 1e4, plain::intersect) <= 1);
    }

    /// Integer inputs with `d ⟂ n` exactly, the origin on the plane or off
    /// it: both variants must see the exact zeros.
    #[test]
    fn both_classify_exact_parallels() {
        let mut rng = SmallRng::seed_from_u64(0x9a7a11e1);
        let int = |rng: &mut SmallRng| vec_in(rng, 30.0).round();
        for _ in 0..N {
            let (n, w) = (int(&mut rng), int(&mut rng));
            let d = n.cross(w);
            let o = int(&mut rng);
            let on = rng.random_bool(0.5);
            let a = if on { o + d.cross(n) } else { o + n };
            let (ray, p) = (Ray::new(o, d), Plane::new(a, n));
            let e = exact::intersect(&ray, &p).unwrap();
            assert_eq!(plain::intersect(&ray, &p), e, "{ray:?} {p:?}");
            assert_eq!(textbook::intersect(&ray, &p), e, "{ray:?} {p:?}");
        }
    }

    #[test]
    fn textbook_is_close_on_easy_cases() {
        assert!(measure("plane textbook, κ < 4", 0x7e47, 4.0, textbook::intersect) <= 4);
    }
}

#[cfg(feature = "sphere")]
mod sphere {
    use super::*;
    use glam::Vec3;
    use rayoracle::Ray;
    use rayoracle::sphere::{Sphere, SphereHit, condition_at, exact, plain, textbook};

    fn exact_of(c: &(Ray, Sphere)) -> SphereHit {
        exact::intersect(&c.0, &c.1).unwrap()
    }

    /// The exact discriminant clear of its terms (`|b² − ac| > 2⁻³⁰(b² +
    /// |ac|)`, so any careful kernel gets the class), and each exact root
    /// with `κ < 10⁴`.
    fn well_conditioned((ray, s): &(Ray, Sphere), e: &SphereHit) -> bool {
        let q = exact::quadratic(ray, s).unwrap();
        let (a, b2, c) = (q.alpha.to_f64(), q.beta.to_f64(), q.gamma.to_f64());
        q.discriminant().to_f64().abs() > 2f64.powi(-30) * (b2 * b2 + 4.0 * (a * c).abs())
            && roots(e)
                .iter()
                .all(|&t| condition_at(ray, s, t as f64) < 1e4)
    }

    fn double_of(c: &(Ray, Sphere)) -> SphereHit {
        plain::intersect(&c.0, &c.1)
    }

    #[test]
    fn double_matches_the_oracle() {
        let mut rng = SmallRng::seed_from_u64(0x59e7e);
        let random = |rng: &mut SmallRng| {
            let ray = Ray::new(vec_in(rng, 20.0), vec_in(rng, 5.0));
            let r = rng.random_range(0.5..20.0);
            (ray, Sphere::new(vec_in(rng, 20.0), r))
        };
        let what = "sphere plain, random, κ < 10⁴";
        let worst = worst_ulps(
            what,
            &mut rng,
            random,
            exact_of,
            well_conditioned,
            double_of,
        );
        assert!(worst <= 1);
        // A unit sphere 10³ to 10⁷ away, aimed at: the textbook's failure.
        let far_tiny = |rng: &mut SmallRng| {
            let dist = 10f32.powf(rng.random_range(3.0..7.0));
            let c = unitish(rng).normalize() * dist;
            let o = vec_in(rng, 0.25);
            (Ray::new(o, c + vec_in(rng, 0.5) - o), Sphere::new(c, 1.0))
        };
        let what = "sphere plain, R = 1 at 10³…10⁷";
        let worst = worst_ulps(
            what,
            &mut rng,
            far_tiny,
            exact_of,
            well_conditioned,
            double_of,
        );
        assert!(worst <= 1);
    }

    /// Lines touching a sphere at `C ± R ŷ` along an integer direction in
    /// the x–z plane: exact tangents, which `plain` must see exactly.
    #[test]
    fn double_sees_integer_tangents() {
        let mut rng = SmallRng::seed_from_u64(0x7a9);
        for _ in 0..N {
            let c = vec_in(&mut rng, 50.0).round();
            let r = rng.random_range(1..=20) as f32;
            let side = if rng.random_bool(0.5) { r } else { -r };
            let d = Vec3::new(
                rng.random_range(-9..=9) as f32,
                0.0,
                rng.random_range(1..=9) as f32,
            );
            let s = rng.random_range(-20..=20) as f32;
            let ray = Ray::new(c + Vec3::new(0.0, side, 0.0) - s * d, d);
            let sphere = Sphere::new(c, r);
            assert_eq!(exact::intersect(&ray, &sphere), Ok(SphereHit::Tangent(s)));
            assert_eq!(plain::intersect(&ray, &sphere), SphereHit::Tangent(s));
        }
    }

    /// A unit sphere at distance 5, hit near its middle from near the
    /// origin, with directions of length ½ to 2. Even here `b² − 4ac`
    /// cancels by about `|f|²/R² = 25`, and half of that reaches `√disc`:
    /// the worst root is 15 ulps off, not the 1 of the reference.
    #[test]
    fn textbook_is_close_on_easy_cases() {
        let mut rng = SmallRng::seed_from_u64(0xea5);
        let at_five = |rng: &mut SmallRng| {
            let c = unitish(rng).normalize() * 5.0;
            let o = vec_in(rng, 0.25);
            let aim = c + vec_in(rng, 0.3) - o;
            let d = aim.normalize() * rng.random_range(0.5..2.0);
            (Ray::new(o, d), Sphere::new(c, 1.0))
        };
        let two = |_: &_, e: &SphereHit| matches!(e, SphereHit::Two(..));
        let worst = worst_ulps(
            "sphere textbook, R = 1 at 5",
            &mut rng,
            at_five,
            exact_of,
            two,
            |c| textbook::intersect(&c.0, &c.1),
        );
        assert!(worst <= 16);
    }

    /// The baseline stays naive: a unit sphere 10⁴ to 10⁵ away, aimed at
    /// its centre, is lost or badly wrong, far more often than not.
    #[test]
    fn textbook_fails_far_tiny_spheres() {
        let mut rng = SmallRng::seed_from_u64(0xfa7);
        let mut bad = 0;
        for _ in 0..N {
            let dist = 10f32.powf(rng.random_range(4.0..5.0));
            let c = unitish(&mut rng).normalize() * dist;
            let o = vec_in(&mut rng, 0.25);
            let (ray, s) = (Ray::new(o, c - o), Sphere::new(c, 1.0));
            let e = exact::intersect(&ray, &s).unwrap();
            let g = textbook::intersect(&ray, &s);
            let off = std::mem::discriminant(&e) != std::mem::discriminant(&g)
                || roots(&e)
                    .iter()
                    .zip(roots(&g))
                    .any(|(&e, g)| rayoracle::ulp::ulps(e, g) > 1000);
            bad += off as usize;
        }
        eprintln!("sphere textbook, R = 1 at 10⁴…10⁵: {bad} of {N} off");
        assert!(bad > N / 2, "{bad}");
    }
}

#[cfg(feature = "quadric")]
mod quadric {
    use super::*;
    use glam::Vec3;
    use rayoracle::Ray;
    use rayoracle::quadric::{Quadric, QuadricHit, condition, exact, plain, textbook};

    fn exact_of(c: &(Ray, Quadric)) -> QuadricHit {
        exact::intersect(&c.0, &c.1).unwrap()
    }

    /// The discriminant clear of its terms (the exact α, β, γ, with
    /// `|β² − 4αγ| > 2⁻³⁰(β² + 4|αγ|)` in f64), and every root with `κ < 10⁴`
    /// (which also keeps α away from 0 unless it is 0: the far root's κ
    /// grows as `Σ|α terms| / |α|`).
    fn well_conditioned((ray, q): &(Ray, Quadric), _: &QuadricHit) -> bool {
        let e = exact::quadratic(ray, q).unwrap();
        let (a, b, c) = (e.alpha.to_f64(), e.beta.to_f64(), e.gamma.to_f64());
        (b * b - 4.0 * a * c).abs() > 2f64.powi(-30) * (b * b + 4.0 * (a * c).abs())
            && condition(ray, q).iter().all(|&k| k < 1e4)
    }

    /// Random coefficients without the `z²`, `xz` and `yz` terms, and a
    /// direction along z: α = 0 exactly, so the linear root `−γ/β`.
    fn alpha_zero(rng: &mut SmallRng) -> (Ray, Quadric) {
        let mut k: [f32; 10] = std::array::from_fn(|_| rng.random_range(-2.0..2.0));
        (k[2], k[4], k[5]) = (0.0, 0.0, 0.0);
        let d = Vec3::new(0.0, 0.0, rng.random_range(0.5..2.0));
        (Ray::new(vec_in(rng, 5.0), d), Quadric::new(k))
    }

    fn double_of(c: &(Ray, Quadric)) -> QuadricHit {
        plain::intersect(&c.0, &c.1)
    }

    fn textbook_of(c: &(Ray, Quadric)) -> QuadricHit {
        textbook::intersect(&c.0, &c.1)
    }

    #[test]
    fn double_matches_the_oracle() {
        let mut rng = SmallRng::seed_from_u64(0x90ad);
        let random = |rng: &mut SmallRng| {
            let k = std::array::from_fn(|_| rng.random_range(-2.0..2.0));
            (
                Ray::new(vec_in(rng, 5.0), vec_in(rng, 2.0)),
                Quadric::new(k),
            )
        };
        let what = "quadric plain, random, κ < 10⁴";
        let worst = worst_ulps(
            what,
            &mut rng,
            random,
            exact_of,
            well_conditioned,
            double_of,
        );
        assert!(worst <= 1);
        let what = "quadric plain, α = 0";
        let worst = worst_ulps(
            what,
            &mut rng,
            alpha_zero,
            exact_of,
            well_conditioned,
            double_of,
        );
        assert!(worst <= 1);
    }

    /// A unit sphere as a quadric (exact integer coefficients) about 5
    /// away, hit near its middle from near the origin. `β²/4α² − γ/α`
    /// cancels by about 25 here, as the textbook sphere's discriminant does.
    #[test]
    fn textbook_is_close_on_easy_cases() {
        let mut rng = SmallRng::seed_from_u64(0xea590);
        let at_five = |rng: &mut SmallRng| {
            let c = (unitish(rng).normalize() * 5.0).round();
            let (g, h, i) = (-2.0 * c.x, -2.0 * c.y, -2.0 * c.z);
            let j = c.length_squared() - 1.0;
            let q = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, g, h, i, j]);
            let o = vec_in(rng, 0.25);
            let d = (c + vec_in(rng, 0.3) - o).normalize() * rng.random_range(0.5..2.0);
            (Ray::new(o, d), q)
        };
        let two = |_: &_, e: &QuadricHit| matches!(e, QuadricHit::Two(..));
        let what = "quadric textbook, unit sphere at 5";
        let worst = worst_ulps(what, &mut rng, at_five, exact_of, two, textbook_of);
        assert!(worst <= 16);
    }

    /// The textbook's one guard, α = 0 exactly, works: the same class and
    /// a root within a few ulps where `κ < 30` (κ counts 3 roundings per
    /// term, so it is at least 6 here).
    #[test]
    fn textbook_handles_alpha_zero() {
        let mut rng = SmallRng::seed_from_u64(0xa1fa0);
        let below_30 = |(ray, q): &(Ray, Quadric), _: &_| condition(ray, q)[0] < 30.0;
        let what = "quadric textbook, α = 0, κ < 30";
        let worst = worst_ulps(what, &mut rng, alpha_zero, exact_of, below_30, textbook_of);
        assert!(worst <= 8);
    }

    /// The baseline stays naive: `εx² + x + γ = 0` along x with ε from
    /// 10⁻⁷ to 10⁻⁵ (α ≈ 0), whose root near −γ the seed's formula cancels
    /// away, while `plain` is within 1 ulp.
    #[test]
    fn textbook_fails_alpha_near_zero() {
        let mut rng = SmallRng::seed_from_u64(0xa1fa);
        let near_zero = |rng: &mut SmallRng| {
            let eps = 10f32.powf(rng.random_range(-7.0..-5.0));
            let j = rng.random_range(0.5..2.0);
            let q = Quadric::new([eps, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, j]);
            (Ray::new(Vec3::ZERO, Vec3::X), q)
        };
        let mut bad = 0;
        for _ in 0..N {
            let c = near_zero(&mut rng);
            let (QuadricHit::Two(_, near), QuadricHit::Two(_, got)) =
                (exact_of(&c), textbook_of(&c))
            else {
                panic!("{c:?}: not two roots");
            };
            bad += (rayoracle::ulp::ulps(near, got) > 1000) as usize;
        }
        eprintln!("quadric textbook, α ≈ 0: {bad} of {N} roots more than 1000 ulps off");
        assert!(bad > N / 2, "{bad}");
        let what = "quadric plain, α ≈ 0";
        let worst = worst_ulps(what, &mut rng, near_zero, exact_of, |_, _| true, double_of);
        assert!(worst <= 1);
    }
}

mod camera {
    use super::*;
    use glam::Vec3;
    use rayoracle::camera::{CameraError, CameraParams, component_scale, exact, plain, textbook};
    use rayoracle::ulp::ulp_of;

    /// A random valid camera (`up` at least 0.1 rad from `dir`) and a pixel
    /// inside it. `easy` keeps the field of view within `[0.2, 2]` rad and
    /// the aspect ratio within `[½, 2]`; otherwise the angle goes up to 3
    /// rad (`tan` of 14) and each side from 1 to 4000 pixels.
    fn camera(rng: &mut SmallRng, easy: bool) -> (CameraParams, [u32; 2]) {
        loop {
            let dir = unitish(rng) * rng.random_range(0.1..10.0);
            let up = unitish(rng);
            let res = [rng.random_range(1..4000), rng.random_range(1..4000)];
            let aspect = res[0] as f32 / res[1] as f32;
            let angle = rng.random_range(0.05..3.0);
            let easy_enough = (0.5..=2.0).contains(&aspect) && (0.2..=2.0).contains(&angle);
            if dir.angle_between(up).sin() < 0.1 || (easy && !easy_enough) {
                continue;
            }
            let p = CameraParams::new(vec_in(rng, 10.0), dir, up, angle, res);
            let px = [rng.random_range(0..res[0]), rng.random_range(0..res[1])];
            return (p, px);
        }
    }

    /// The largest error of a variant's direction, in ulps of the component
    /// scale `Sᵢ` (what the gate's `CAMERA_ULPS` allowance is in), and
    /// in plain ulps where the component is at least `Sᵢ/2` (no
    /// cancellation).
    fn worst_errors(
        rng: &mut SmallRng,
        easy: bool,
        ray: impl Fn(&CameraParams, u32, u32) -> Vec3,
    ) -> (f64, u64) {
        let (mut of_scale, mut plain) = (0f64, 0u64);
        for _ in 0..N {
            let (p, [px, py]) = camera(rng, easy);
            let e = exact::ray(&p, px, py).unwrap().dir;
            let g = ray(&p, px, py);
            let s = component_scale(&p.build().unwrap(), px, py);
            for i in 0..3 {
                of_scale = of_scale.max((g[i] as f64 - e[i] as f64).abs() / ulp_of(s[i]));
                if (e[i] as f64).abs() >= s[i] / 2.0 {
                    plain = plain.max(rayoracle::ulp::ulps(e[i], g[i]));
                }
            }
        }
        (of_scale, plain)
    }

    #[test]
    fn double_matches_the_oracle() {
        let mut rng = SmallRng::seed_from_u64(0xca3e7a);
        let (of_scale, plain) = worst_errors(&mut rng, false, |p, x, y| {
            plain::Camera::new(p).unwrap().ray(x, y).dir
        });
        eprintln!("camera double: max {of_scale} ulps of Sᵢ, {plain} ulps");
        assert!(of_scale <= 1.0 && plain <= 1);
    }

    #[test]
    fn textbook_is_close_on_easy_cases() {
        let mut rng = SmallRng::seed_from_u64(0xca3e7b);
        let (of_scale, plain) = worst_errors(&mut rng, true, |p, x, y| {
            textbook::Camera::new(p).unwrap().ray(x, y).dir
        });
        eprintln!("camera textbook, easy: max {of_scale} ulps of Sᵢ, {plain} ulps");
        assert!(of_scale <= 8.0);
        // Wide angles and extreme aspect ratios, for the record: the naive
        // pixel offset rounds `(X + ½)/res` before subtracting ½, an error
        // of up to 2⁻²⁴ in `u` that |x| ≫ |f| turns into many ulps of Sᵢ.
        let (of_scale, plain) = worst_errors(&mut rng, false, |p, x, y| {
            textbook::Camera::new(p).unwrap().ray(x, y).dir
        });
        eprintln!("camera textbook, any: max {of_scale} ulps of Sᵢ, {plain} ulps");
    }

    /// Both variants refuse exactly what the reference refuses.
    #[test]
    fn construction_errors_are_the_reference_ones() {
        let ok = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [4, 4]);
        let cases = [
            (
                CameraParams {
                    dir: Vec3::ZERO,
                    ..ok
                },
                CameraError::DirZero,
            ),
            (
                CameraParams {
                    up: Vec3::NAN,
                    ..ok
                },
                CameraError::UpNonFinite,
            ),
            (
                CameraParams { up: Vec3::Z, ..ok },
                CameraError::DirParallelToUp,
            ),
            (
                CameraParams { angle: 3.5, ..ok },
                CameraError::AngleOutOfRange(3.5),
            ),
            (
                CameraParams { res: [0, 4], ..ok },
                CameraError::ZeroResolution,
            ),
        ];
        for (p, err) in cases {
            assert_eq!(p.build().unwrap_err(), err);
            assert_eq!(textbook::Camera::new(&p).unwrap_err(), err);
            assert_eq!(plain::Camera::new(&p).unwrap_err(), err);
        }
        assert!(textbook::Camera::new(&ok).is_ok() && plain::Camera::new(&ok).is_ok());
    }
}
