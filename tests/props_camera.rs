//! The camera: random valid cameras and pixels, each direction component
//! the oracle's bits (ordinary cameras, and edges: near-axis-aligned,
//! tiny and huge focus, angles near 0 and π, resolutions up to
//! `MAX_RESOLUTION`, centre pixels); the `tan` enclosure against known
//! values; the filter's bound shown to be needed; and every construction
//! error for the input that causes it.

use crate::support;

use dashu_int::IBig;
use glam::Vec3;
use proptest::prelude::*;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use rayoracle::camera::tan::{Fx, tan_half};
use rayoracle::camera::{CameraError, CameraParams, MAX_RESOLUTION, exact};
use rayoracle::check::{Status, check_camera};
use support::*;

/// A valid camera: `|dir|` from 10⁻⁴ to 10⁴, `up` at least ~6° away from
/// `dir` (and generally not orthogonal to it), field of view in
/// `[10⁻³, π − 10⁻³]`, resolutions `1…4096`.
fn valid_camera() -> impl Strategy<Value = CameraParams> {
    (
        vec_in(1e3),
        unitish(),
        log_uniform(-4.0, 4.0),
        unitish(),
        log_uniform(-3.0, 3.0),
        1e-3f32..(std::f32::consts::PI - 1e-3),
        1u32..=4096,
        1u32..=4096,
    )
        .prop_filter("up not within ~6° of ±dir", |(_, d, _, u, ..)| {
            d.normalize().cross(u.normalize()).length() > 0.1
        })
        .prop_map(|(pos, d, sd, u, su, angle, w, h)| {
            CameraParams::new(pos, d * sd, u * su, angle, [w, h])
        })
}

/// A camera with a pixel inside its image.
fn camera_and_pixel() -> impl Strategy<Value = (CameraParams, [u32; 2])> {
    valid_camera().prop_flat_map(|p| (Just(p), [0..p.res[0], 0..p.res[1]]))
}

/// The error `p` must be rejected with, checked against both the oracle and
/// the reference through the judge.
fn rejects(p: CameraParams, want: CameraError) -> Result<(), TestCaseError> {
    let got = p.build().map(|cam| cam.ray(0, 0));
    prop_assert_eq!(got, Err(want));
    let r = checked(check_camera(&p, [0, 0], got))?;
    prop_assert_eq!(r.status, Status::Rejected);
    Ok(())
}

/// A component of `dir` or `up`: 0, a power of two, or any value, with a
/// sign, scaled by `2^k` (the scale is shared by the vector).
fn edge_component() -> impl Strategy<Value = f32> {
    prop_oneof![
        Just(0.0f32),
        pow2(-30, 0),
        -1.0f32..1.0,
        Just(1.0f32),
        Just(-1.0f32),
    ]
}

fn edge_vec(lo: i32, hi: i32) -> impl Strategy<Value = Vec3> {
    (
        [edge_component(), edge_component(), edge_component()],
        pow2(lo, hi),
    )
        .prop_map(|(v, s)| Vec3::from_array(v) * s)
        .prop_filter("nonzero", |v| *v != Vec3::ZERO)
}

/// Angles near 0 (down to the smallest subnormal), near π (up to the
/// largest `f32` below it), and anywhere between.
fn edge_angle() -> impl Strategy<Value = f32> {
    let below_pi = std::f32::consts::PI.next_down();
    prop_oneof![
        log_uniform(-44.0, -2.0),
        Just(f32::from_bits(1)),
        (0u32..64).prop_map(move |k| f32::from_bits(below_pi.to_bits() - k)),
        1e-3f32..3.1,
    ]
}

/// A resolution: small, up to `MAX_RESOLUTION`, or exactly it.
fn edge_res() -> impl Strategy<Value = u32> {
    prop_oneof![1u32..=16, 1u32..=MAX_RESOLUTION, Just(MAX_RESOLUTION)]
}

/// A buildable edge camera and a pixel: a corner, the centre row or column
/// (`u = 0` or `v = 0` where the resolution is odd), or anywhere.
fn edge_camera_and_pixel() -> impl Strategy<Value = (CameraParams, [u32; 2])> {
    (
        edge_vec(-60, 60),
        edge_vec(-60, 60),
        edge_angle(),
        edge_res(),
        edge_res(),
    )
        .prop_map(|(d, u, angle, w, h)| CameraParams::new(Vec3::ONE, d, u, angle, [w, h]))
        .prop_filter("builds", |p| p.build().is_ok())
        .prop_flat_map(|p| {
            let pick = |r: u32| prop_oneof![Just(0), Just(r - 1), Just(r / 2), 0..r];
            (Just(p), [pick(p.res[0]), pick(p.res[1])])
        })
}

/// Reference, x4 and oracle agree bit for bit (through the judge).
fn agrees(p: CameraParams, px: [u32; 2]) -> Result<(), TestCaseError> {
    let got = p.build().map(|cam| cam.ray(px[0], px[1]));
    let r = checked(check_camera(&p, px, got))?;
    prop_assert_eq!(r.status, Status::Checked);
    x4_agrees(&rayoracle::case::Case::Camera(p, px))
}

proptest! {
    /// Edge cameras: every component the oracle's bits, and where `u = 0`
    /// and `v = 0` the direction is `dir` itself.
    #[test]
    fn edge_pixels((p, px) in edge_camera_and_pixel()) {
        agrees(p, px)?;
        let centre = p.res.map(|r| r % 2 == 1);
        if centre == [true, true] && px == [p.res[0] / 2, p.res[1] / 2] {
            let d = p.build().unwrap().ray(px[0], px[1]).dir;
            prop_assert_eq!(d.to_array().map(f32::to_bits), p.dir.to_array().map(f32::to_bits));
        }
    }

    /// Mirror pixels `X` and `resX − 1 − X` have `u` and `−u`: with
    /// `dir = −z` and `up = y`, the x component is exactly `u·xₓ`, and
    /// correct rounding is symmetric, so the two are negatives bit for bit.
    #[test]
    fn mirror_pixels_negate_exactly(angle in 1e-3f32..3.1, f in log_uniform(-20.0, 20.0), w in 1u32..=MAX_RESOLUTION, h in 1u32..5000, x in 0u32..MAX_RESOLUTION, y in 0u32..5000) {
        let p = CameraParams::new(Vec3::ZERO, -Vec3::Z * f, Vec3::Y, angle, [w, h]);
        let cam = p.build().unwrap();
        let (x, y) = (x % w, y % h);
        prop_assume!(2 * x + 1 != w, "the centre column is dir's own −0");
        let (a, b) = (cam.ray(x, y).dir, cam.ray(w - 1 - x, y).dir);
        prop_assert_eq!((-a.x).to_bits(), b.x.to_bits());
        prop_assert_eq!(a.y.to_bits(), b.y.to_bits());
    }

    /// Every direction component the oracle's bits, origin exactly the
    /// position.
    #[test]
    fn random_pixels((p, px) in camera_and_pixel()) {
        let got = p.build().map(|cam| cam.ray(px[0], px[1]));
        let r = checked(check_camera(&p, px, got))?;
        prop_assert_eq!(r.status, Status::Checked);
        x4_agrees(&rayoracle::case::Case::Camera(p, px))?;
    }

    /// Pixels outside the image extrapolate the same formula, with the
    /// filter's bound computed per pixel rather than the image's.
    #[test]
    fn pixels_outside_the_image((p, x, y) in valid_camera().prop_flat_map(|p| (
        Just(p),
        prop_oneof![Just(p.res[0]), p.res[0]..=u32::MAX, 0..=p.res[0] - 1],
        prop_oneof![Just(p.res[1]), p.res[1]..=u32::MAX, u32::MAX..=u32::MAX],
    ))) {
        agrees(p, [x, y])?;
    }

    /// The enclosure of `tan(a/2)` is monotone in `a`: at 120 bits the
    /// enclosures of two neighbouring `f32` angles are disjoint and in order.
    #[test]
    fn tan_is_monotone(a in 1e-30f32..3.1) {
        let (h, g) = (tan_half(a, 120), tan_half(a.next_up(), 120));
        prop_assert!(h.lo <= h.hi && h.hi < g.lo);
    }

    /// The corners and the centre of every image.
    #[test]
    fn corners(p in valid_camera()) {
        let [w, h] = p.res;
        for px in [[0, 0], [w - 1, 0], [0, h - 1], [w - 1, h - 1], [w / 2, h / 2]] {
            checked(check_camera(&p, px, p.build().map(|cam| cam.ray(px[0], px[1]))))?;
        }
    }

    #[test]
    fn zero_dir(p in valid_camera()) {
        rejects(CameraParams { dir: Vec3::ZERO, ..p }, CameraError::DirZero)?;
    }

    #[test]
    fn non_finite_dir(p in valid_camera(), i in 0usize..3, bad in prop_oneof![Just(f32::NAN), Just(f32::INFINITY), Just(f32::NEG_INFINITY)]) {
        let mut dir = p.dir;
        dir[i] = bad;
        rejects(CameraParams { dir, ..p }, CameraError::DirNonFinite)?;
    }

    #[test]
    fn zero_up(p in valid_camera()) {
        rejects(CameraParams { up: Vec3::ZERO, ..p }, CameraError::UpZero)?;
    }

    #[test]
    fn non_finite_up(p in valid_camera(), i in 0usize..3, bad in prop_oneof![Just(f32::NAN), Just(f32::INFINITY)]) {
        let mut up = p.up;
        up[i] = bad;
        rejects(CameraParams { up, ..p }, CameraError::UpNonFinite)?;
    }

    /// `up = ±2^k dir`: exactly parallel.
    #[test]
    fn parallel_up(p in valid_camera(), s in pow2(-20, 20), neg in any::<bool>()) {
        let up = p.dir * if neg { -s } else { s };
        rejects(CameraParams { up, ..p }, CameraError::DirParallelToUp)?;
    }

    /// Angles 0, ±π (f32's π is above the real π), negative, beyond π, NaN.
    #[test]
    fn angle_out_of_range(p in valid_camera(), angle in prop_oneof![
        Just(0.0f32), Just(-0.0), Just(std::f32::consts::PI), Just(-std::f32::consts::PI),
        -10.0f32..0.0, std::f32::consts::PI..10.0, Just(f32::INFINITY),
    ]) {
        rejects(CameraParams { angle, ..p }, CameraError::AngleOutOfRange(angle))?;
    }

    #[test]
    fn nan_angle(p in valid_camera()) {
        let p = CameraParams { angle: f32::NAN, ..p };
        let got = p.build().map(|cam| cam.ray(0, 0));
        prop_assert!(matches!(got, Err(CameraError::AngleOutOfRange(a)) if a.is_nan()));
        prop_assert_eq!(checked(check_camera(&p, [0, 0], got))?.status, Status::Rejected);
    }

    #[test]
    fn zero_resolution(p in valid_camera(), which in 0usize..3) {
        let res = match which { 0 => [0, p.res[1]], 1 => [p.res[0], 0], _ => [0, 0] };
        rejects(CameraParams { res, ..p }, CameraError::ZeroResolution)?;
    }

    #[test]
    fn resolution_too_large(p in valid_camera(), r in (MAX_RESOLUTION + 1)..=u32::MAX) {
        rejects(CameraParams { res: [r, p.res[1]], ..p }, CameraError::ResolutionTooLarge(r))?;
    }
}

/// `tan(a/2)` for `f32` angles, to 55 significant digits: computed with
/// mpmath at 60 digits (`mpmath.tan(mpmath.mpf(a)/2)` of the exact `f32`
/// value), and, for `a = 1`, the published `tan(1/2) = 0.5463024898…`.
/// `0x4049_0fda` is the largest `f32` below π, `from_bits(1)` the least
/// subnormal.
const TAN_HALF: [(f32, &str); 6] = [
    (
        1.0,
        "0.5463024898437905132551794657802853832975517201797912461",
    ),
    (
        std::f32::consts::FRAC_PI_2,
        "1.000000043711390957205264095395048370500530232089130310",
    ),
    (
        3.0,
        "14.10141994717171938764608365198775644565954357723586186",
    ),
    (
        f32::from_bits(0x4049_0fda),
        "13245401.60686256788617171124487363295366120005398125151",
    ),
    (
        1e-30,
        "5.000000015855384254855256735676323769073757378230554726e-31",
    ),
    (
        f32::from_bits(1),
        "7.006492321624085354618647916449580656401309709382578858e-46",
    ),
];

/// `digits` (a decimal, optionally with an exponent `e−N`) as the integer
/// `N` and power of ten `k` with `value ∈ [N, N + 1]·10^−k`.
fn decimal(digits: &str) -> (IBig, i64) {
    let (m, e) = digits.split_once('e').unwrap_or((digits, "0"));
    let (int, frac) = m.split_once('.').unwrap_or((m, ""));
    let n: IBig = format!("{int}{frac}").parse().unwrap();
    (n, frac.len() as i64 - e.parse::<i64>().unwrap())
}

/// The enclosure at 180 bits holds each known value to its 55 digits (it
/// overlaps `[N, N + 1]·10^−k`), and is far narrower than that.
#[test]
fn tan_half_against_known_values() {
    for (a, digits) in TAN_HALF {
        let h = tan_half(a, 180);
        let (n, k) = decimal(digits);
        let ten_k = Fx::new(IBig::from(10u8).pow(k as usize), 0);
        let (lo, hi) = (h.lo.mul(&ten_k), h.hi.mul(&ten_k));
        let (nl, nh) = (Fx::new(n.clone(), 0), Fx::new(n + IBig::ONE, 0));
        assert!(lo <= nh && nl <= hi, "tan({a}/2): {:e}", h.lo.to_f64());
        assert!(h.width_bits() < -170, "tan({a}/2) too wide");
    }
}

/// The filter's bound is needed: shrunk by `shrink`, it certifies wrong
/// components on near-diagonal cameras (`dir ≈ −z` tilted by a tiny
/// amount, `up ≈ (1, 1, 0)`, square images, diagonal pixels), where the
/// terms `u·xₓ` and `v·yₓ` nearly cancel and the component is about the
/// tiny `dirₓ`. At full size it never does. `outside` takes the pixels
/// beyond the image (still on its diagonal), whose bound is computed per
/// pixel rather than once for the image.
fn wrong_with_shrink(shrink: f64, outside: bool) -> usize {
    let mut rng = SmallRng::seed_from_u64(0x5a1c);
    let mut wrong = 0;
    for _ in 0..200 {
        let tilt = |rng: &mut SmallRng| {
            rng.random_range(-1.0f32..1.0) * 2f32.powi(rng.random_range(-50..-20))
        };
        let dir = Vec3::new(tilt(&mut rng), tilt(&mut rng), -1.0);
        let up = Vec3::new(1.0, 1.0 + tilt(&mut rng), 0.0);
        let res = rng.random_range(2..5000);
        let p = CameraParams::new(Vec3::ZERO, dir, up, rng.random_range(0.1f32..3.0), [res; 2]);
        let cam = p.build().unwrap();
        let x = rng.random_range(0..res) + if outside { res } else { 0 };
        let got = cam.ray_shrunk(x, x, shrink).dir;
        let want = exact::ray(&p, x, x).unwrap().dir;
        if got.to_array().map(f32::to_bits) != want.to_array().map(f32::to_bits) {
            wrong += 1;
        }
    }
    wrong
}

#[test]
fn a_shrunk_filter_bound_gives_wrong_components() {
    for outside in [false, true] {
        assert_eq!(wrong_with_shrink(1.0, outside), 0);
        assert!(wrong_with_shrink(1e-6, outside) > 0);
    }
}

/// Rounding defines overflow: a component whose real value is beyond
/// `f32::MAX` (plus half an ulp) is `+∞`, in the reference, x4 and the
/// oracle alike; a basis that rounds to ∞ is a construction error.
#[test]
fn a_component_beyond_f32_max_is_infinite_and_an_infinite_basis_is_refused() {
    // x = (−1.5, 0, 1.5)·10³⁸ and y = (0, −2.1, 0)·10³⁸, roughly; pixel
    // (1, 0) has u = ½, so z = 3·10³⁸ + ½·1.5·10³⁸ > f32::MAX.
    let p = CameraParams::new(
        Vec3::ZERO,
        Vec3::new(3e38, 0.0, 3e38),
        Vec3::Y,
        0.9273,
        [2, 2],
    );
    let cam = p.build().unwrap();
    assert!(cam.x.is_finite() && cam.y.is_finite());
    let d = cam.ray(1, 0).dir;
    assert_eq!(d.z, f32::INFINITY);
    assert!(d.x.is_finite() && d.x > 2e38);
    let r = check_camera(&p, [1, 0], Ok(cam.ray(1, 0))).unwrap();
    assert_eq!(r.status, Status::Checked);
    assert_eq!(cam.ray4([[1, 0]; 4]).to_rays()[3], cam.ray(1, 0));
    // 64 times as wide: x overflows.
    let wide = CameraParams { res: [128, 2], ..p };
    assert_eq!(wide.build().unwrap_err(), CameraError::BasisOverflow);
    assert_eq!(
        exact::ray(&wide, 0, 0).unwrap_err(),
        CameraError::BasisOverflow
    );
}
