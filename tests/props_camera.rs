//! The camera: random valid cameras and pixels within the component bound,
//! and every construction error for the input that causes it.

use crate::support;

use glam::Vec3;
use proptest::prelude::*;
use rayoracle::camera::{CameraError, CameraParams, MAX_RESOLUTION};
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

proptest! {
    /// Every direction component within `COMPONENT_ULPS` of `Sᵢ`, origin
    /// exactly the position.
    #[test]
    fn random_pixels((p, px) in camera_and_pixel()) {
        let got = p.build().map(|cam| cam.ray(px[0], px[1]));
        let r = checked(check_camera(&p, px, got))?;
        prop_assert_eq!(r.status, Status::Checked);
        x4_agrees(&rayoracle::case::Case::Camera(p, px))?;
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
