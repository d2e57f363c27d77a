#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
//! Known-wrong cameras: orientation and field-of-view slips on top of the
//! reference camera's basis, and validations that are missing or too
//! strict, each caught by a whole family.

use super::known_wrong::{assert_family_catches, assert_passes, camera_correct, camera_with, gate};
use rayoracle::Ray;
use rayoracle::camera::{CameraError, CameraParams, filter};
use rayoracle::check::gate::Semantics;

/// The pixel offsets `(u, v)` of the reference, then bent by `bend`
/// (given the parameters).
fn bent(
    p: &CameraParams,
    px: [u32; 2],
    bend: impl Fn(&CameraParams, f32, f32) -> (f32, f32),
) -> Option<Ray> {
    camera_with(p, px, |res, px| {
        bend(
            p,
            filter::offset(px[0], res[0]),
            filter::offset(px[1], res[1]),
        )
    })
}

/// The control: the reference offsets through the same code path.
fn camera_unbent(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    bent(p, px, |_, u, v| (u, v))
}

/// Row 0 at the bottom: `v` negated.
fn camera_flipped_y(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    bent(p, px, |_, u, v| (u, -v))
}

/// The horizontal axis reversed (`up × dir` for `dir × up`): `u` negated.
fn camera_mirrored_x(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    bent(p, px, |_, u, v| (-u, v))
}

/// The pixel's `X` and `Y` swapped (`ray(y, x)`).
fn camera_swapped_pixel(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    camera_with(p, px, |res, px| {
        (filter::offset(px[1], res[1]), filter::offset(px[0], res[0]))
    })
}

/// The aspect ratio inverted: `resY/resX` where `resX/resY` belongs.
fn camera_aspect_inverted(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    bent(p, px, |p, u, v| {
        let inv = f64::from(p.res[1]) / f64::from(p.res[0]);
        ((f64::from(u) * inv * inv) as f32, v)
    })
}

/// The field of view taken as the half angle: `tan(angle)` where
/// `tan(angle/2)` belongs.
fn camera_fov_full_angle(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    bent(p, px, |p, u, v| {
        let a = f64::from(p.angle);
        let s = a.tan() / (a / 2.0).tan();
        ((f64::from(u) * s) as f32, (f64::from(v) * s) as f32)
    })
}

/// The field of view read in degrees.
fn camera_fov_degrees(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    bent(p, px, |p, u, v| {
        let a = f64::from(p.angle);
        let s = (a.to_radians() / 2.0).tan() / (a / 2.0).tan();
        ((f64::from(u) * s) as f32, (f64::from(v) * s) as f32)
    })
}

/// The reference camera, except where `accept` lets refused parameters
/// through (the ray along `dir`) or `refuse` turns valid ones down.
fn validated(
    p: &CameraParams,
    px: [u32; 2],
    accept: impl Fn(&CameraError) -> bool,
    refuse: impl Fn(&CameraParams) -> bool,
) -> Option<Ray> {
    match p.build() {
        Ok(_) if refuse(p) => None,
        Ok(c) => Some(c.ray(px[0], px[1])),
        Err(e) if accept(&e) => Some(Ray::new(p.position, p.dir)),
        Err(_) => None,
    }
}

fn camera_accepts_parallel_up(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    validated(
        p,
        px,
        |e| matches!(e, CameraError::DirParallelToUp),
        |_| false,
    )
}

fn camera_accepts_wide_angle(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    validated(
        p,
        px,
        |e| matches!(e, CameraError::AngleOutOfRange(a) if *a >= std::f32::consts::PI),
        |_| false,
    )
}

/// A field of view under 10⁻³ refused as "degenerate".
fn camera_refuses_narrow(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    validated(p, px, |_| false, |p| p.angle < 1e-3)
}

/// An `up` that is not of unit length refused.
fn camera_refuses_non_unit_up(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    validated(
        p,
        px,
        |_| false,
        |p| (p.up.length_squared() - 1.0).abs() > 1e-3,
    )
}

#[test]
fn the_unbent_camera_passes() {
    let report = gate(Semantics::WholeLine).camera(&camera_unbent);
    assert_passes("camera through camera_with", &report, 500);
    let report = gate(Semantics::WholeLine).camera(&camera_correct);
    assert_passes("the reference camera", &report, 500);
}

#[test]
fn flipped_y_is_caught_by_random_cameras() {
    let report = gate(Semantics::WholeLine).camera(&camera_flipped_y);
    assert_family_catches("camera y flipped", &report, "camera/random/any", 100);
}

#[test]
fn mirrored_x_is_caught_by_random_cameras() {
    let report = gate(Semantics::WholeLine).camera(&camera_mirrored_x);
    assert_family_catches("camera x mirrored", &report, "camera/random/any", 100);
}

#[test]
fn swapped_pixel_is_caught_by_random_cameras() {
    let report = gate(Semantics::WholeLine).camera(&camera_swapped_pixel);
    assert_family_catches("camera pixel x ↔ y", &report, "camera/random/any", 100);
}

#[test]
fn inverted_aspect_is_caught_by_random_cameras() {
    let report = gate(Semantics::WholeLine).camera(&camera_aspect_inverted);
    assert_family_catches("camera aspect inverted", &report, "camera/random/any", 100);
}

#[test]
fn full_angle_fov_is_caught_by_random_cameras() {
    let report = gate(Semantics::WholeLine).camera(&camera_fov_full_angle);
    assert_family_catches("camera tan(angle)", &report, "camera/random/any", 100);
}

#[test]
fn fov_in_degrees_is_caught_by_random_cameras() {
    let report = gate(Semantics::WholeLine).camera(&camera_fov_degrees);
    assert_family_catches("camera angle in degrees", &report, "camera/random/any", 100);
}

#[test]
fn accepting_parallel_up_is_caught() {
    let report = gate(Semantics::WholeLine).camera(&camera_accepts_parallel_up);
    assert_family_catches(
        "camera accepts dir ∥ up",
        &report,
        "camera/random/parallel-up",
        200,
    );
}

#[test]
fn accepting_wide_angles_is_caught() {
    let report = gate(Semantics::WholeLine).camera(&camera_accepts_wide_angle);
    assert_family_catches(
        "camera accepts angle ≥ π",
        &report,
        "camera/random/bad-angle",
        100,
    );
}

#[test]
fn refusing_narrow_angles_is_caught() {
    let report = gate(Semantics::WholeLine).camera(&camera_refuses_narrow);
    assert_family_catches(
        "camera refuses angle < 1e-3",
        &report,
        "camera/random/narrow",
        100,
    );
}

#[test]
fn refusing_non_unit_up_is_caught() {
    let report = gate(Semantics::WholeLine).camera(&camera_refuses_non_unit_up);
    assert_family_catches("camera refuses |up| ≠ 1", &report, "camera/random/any", 100);
}
