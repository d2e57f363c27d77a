//! What a plan leaves out, proved by counting kernel calls. The counters
//! exist only in this crate's unit tests ([`super::counters`]).

#[allow(unused_imports)] // Which are used depends on the cargo features.
use super::counters::{self, NORMAL, PLANE, QUADRIC, SPHERE};
use super::{Channels, Path, Plan, render};
use crate::scene::Scene;

const W: u32 = 10; // not a multiple of 4: the x4 path has a tail packet
const H: u32 = 6;

fn scene(objects: &str) -> Scene {
    Scene::parse(&format!(
        r#"{{"camera": {{"position": [0, 0, 0], "dir": [0, 0, -1], "up": [0, 1, 0],
            "angle": 1.2, "res": [{W}, {H}]}}, {objects}}}"#
    ))
    .unwrap()
}

#[cfg(feature = "sphere")]
fn spheres_only() -> Scene {
    scene(
        r#""spheres": [{"id": 1, "center": [0, 0, -4], "radius": 1},
                       {"id": 2, "center": [1.5, 0, -6], "radius": 1}]"#,
    )
}

/// The calls one render makes: `[plane, sphere, quadric, normal]`.
#[allow(dead_code)] // Unused when every kind is compiled out.
fn calls(plan: &Plan, path: Path) -> [u64; 4] {
    counters::take();
    render(plan, path);
    counters::take()
}

/// A one-kind scene with `n` objects, rendered depth-only, runs that kind's
/// kernel once per object per ray (per packet on x4) and nothing else.
#[allow(dead_code)] // Unused when every kind is compiled out.
fn only(kind: usize, n: u64, scene: &Scene) {
    let plan = Plan::compile(scene, Channels::DEPTH).unwrap();
    let pixels = u64::from(W * H);
    let packets = u64::from(W.div_ceil(4) * H);
    let mut want = [0; 4];
    want[kind] = n * pixels;
    assert_eq!(calls(&plan, Path::Reference), want);
    want[kind] = n * packets;
    assert_eq!(calls(&plan, Path::X4), want);
}

#[cfg(feature = "sphere")]
#[test]
fn a_sphere_only_depth_plan_runs_only_sphere_kernels_and_no_normals() {
    only(SPHERE, 2, &spheres_only());
}

#[cfg(feature = "plane")]
#[test]
fn a_plane_only_depth_plan_runs_only_plane_kernels_and_no_normals() {
    let s = scene(r#""planes": [{"id": 1, "point": [0, -1, 0], "normal": [0, 1, 0]}]"#);
    only(PLANE, 1, &s);
}

#[cfg(feature = "quadric")]
#[test]
fn a_quadric_only_depth_plan_runs_only_quadric_kernels_and_no_normals() {
    let s = scene(
        r#""quadrics": [{"id": 1, "coeffs": [1, 0, 1, 0, 0, 0, 0, 0, 0, -0.25]},
                        {"id": 2, "coeffs": [1, 1, 0, 0, 0, 0, 0, 0, 0, -9]},
                        {"id": 3, "coeffs": [0, 1, 0, 0, 0, 0, 0, 0, 0, -4]}]"#,
    );
    only(QUADRIC, 3, &s);
}

#[cfg(feature = "sphere")]
#[test]
fn normals_run_only_when_the_normal_channel_is_asked_for() {
    let s = spheres_only();
    let id_only = Channels::parse("id").unwrap();
    assert_eq!(
        calls(&Plan::compile(&s, id_only).unwrap(), Path::X4)[NORMAL],
        0
    );
    let with_normals = Channels::parse("normal").unwrap();
    // Some pixels hit, so the counter can see normal work when it happens.
    assert!(calls(&Plan::compile(&s, with_normals).unwrap(), Path::Reference)[NORMAL] > 0);
    assert!(calls(&Plan::compile(&s, with_normals).unwrap(), Path::X4)[NORMAL] > 0);
}

#[cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
#[test]
fn a_mixed_scene_runs_each_kind_once_per_object_per_ray() {
    let s = scene(
        r#""planes": [{"id": 1, "point": [0, -1, 0], "normal": [0, 1, 0]}],
           "spheres": [{"id": 2, "center": [0, 0, -4], "radius": 1}],
           "quadrics": [{"id": 3, "coeffs": [1, 0, 1, 0, 0, 0, 0, 0, 0, -0.25]},
                        {"id": 4, "coeffs": [1, 1, 0, 0, 0, 0, 0, 0, 0, -9]}]"#,
    );
    let pixels = u64::from(W * H);
    let got = calls(
        &Plan::compile(&s, Channels::DEPTH).unwrap(),
        Path::Reference,
    );
    assert_eq!(got, [pixels, pixels, 2 * pixels, 0]);
    // The un-specialised path runs the same kernels, and normals too.
    let got = calls(&Plan::everything(&s).unwrap(), Path::Reference);
    assert_eq!(&got[..3], &[pixels, pixels, 2 * pixels]);
    assert!(got[NORMAL] > 0);
}

#[cfg(feature = "sphere")]
#[test]
fn the_everything_plan_renders_the_same_frames() {
    let s = spheres_only();
    for path in [Path::Reference, Path::X4] {
        let a = render(&Plan::everything(&s).unwrap(), path);
        let b = render(&Plan::compile(&s, Channels::ALL).unwrap(), path);
        assert!(a.same_bits(&b), "{path:?}");
    }
}

#[cfg(not(feature = "quadric"))]
#[test]
fn a_scene_with_a_compiled_out_kind_is_refused_by_name() {
    let s = scene(r#""quadrics": [{"id": 1, "coeffs": [1, 1, 1, 0, 0, 0, 0, 0, 0, -1]}]"#);
    let e = Plan::compile(&s, Channels::ALL).unwrap_err();
    assert_eq!(e.field, "quadrics");
    assert!(e.message.contains("feature \"quadric\" is off"), "{e}");
}

#[cfg(not(feature = "sphere"))]
#[test]
fn a_scene_with_compiled_out_spheres_is_refused_by_name() {
    let s = scene(r#""spheres": [{"id": 1, "center": [0, 0, -4], "radius": 1}]"#);
    let e = Plan::compile(&s, Channels::ALL).unwrap_err();
    assert_eq!(e.field, "spheres");
    assert!(e.message.contains("feature \"sphere\" is off"), "{e}");
}

#[cfg(not(feature = "plane"))]
#[test]
fn a_scene_with_compiled_out_planes_is_refused_by_name() {
    let s = scene(r#""planes": [{"id": 1, "point": [0, -1, 0], "normal": [0, 1, 0]}]"#);
    let e = Plan::compile(&s, Channels::ALL).unwrap_err();
    assert_eq!(e.field, "planes");
    assert!(e.message.contains("feature \"plane\" is off"), "{e}");
}

/// Two objects of every kind, each seen somewhere (a floor and a ceiling,
/// two spheres, and two balls written as quadrics, of radius 1 at
/// (0, 0, −4) and 1.2 at (−4, 0, −4)): the object numbers are each kind's
/// base plus its index on both paths, so every id shows up, and the paths
/// agree bit for bit.
#[cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
#[test]
fn two_objects_of_each_kind_keep_their_ids_on_both_paths() {
    let s = scene(
        r#""planes": [{"id": 11, "point": [0, -1, 0], "normal": [0, 1, 0]},
                      {"id": 12, "point": [0, 1.5, 0], "normal": [0, -1, 0]}],
           "spheres": [{"id": 21, "center": [-1.5, 0, -4], "radius": 0.7},
                       {"id": 22, "center": [1.5, 0, -4], "radius": 0.7}],
           "quadrics": [{"id": 31, "coeffs": [1, 1, 1, 0, 0, 0, 0, 0, 8, 15]},
                        {"id": 32, "coeffs": [1, 1, 1, 0, 0, 0, 8, 0, 8, 30.56]}]"#,
    );
    let plan = Plan::compile(&s, Channels::ALL).unwrap();
    let (r, x) = (render(&plan, Path::Reference), render(&plan, Path::X4));
    assert!(r.same_bits(&x));
    let mut ids = r.id.clone();
    ids.sort_unstable();
    ids.dedup();
    assert_eq!(ids, [11, 12, 21, 22, 31, 32]);
}
