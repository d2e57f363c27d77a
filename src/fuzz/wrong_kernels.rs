//! Every check a fuzz target makes fires on a wrong kernel.
//!
//! The shipped kernels never fail a target, so `cargo test` replaying the
//! corpora shows only that they pass. Here each target's `*_with` function
//! is handed kernels that are wrong in one way, on an input where that way
//! shows, and the failure is checked to name the check and the lane. The
//! wrong kernels are `fn` items, as the targets take them: a lane swap, a
//! shifted root (with an x4 shifted the same way, so that the bit-identity
//! check passes and the exact oracle has to catch it), the textbook
//! sphere, a batch that leaves its last packet out, a camera ray wrong at
//! one pixel, and broken `eval` outputs.

use super::{Failure, camera, camera_with, encode_f32, eval_line, eval_line_with};
use crate::Ray;
use crate::camera::Camera;
use crate::ray4::Ray4;
use glam::Vec3;
use wide::f32x4;
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use wide::i32x4;

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
/// Four lanes in order 1, 0, 2, 3.
fn swap01<T: Copy>(a: [T; 4]) -> [T; 4] {
    [a[1], a[0], a[2], a[3]]
}

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn swap_f(v: f32x4) -> f32x4 {
    f32x4::from(swap01(v.to_array()))
}

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn swap_i(v: i32x4) -> i32x4 {
    i32x4::from(swap01(v.to_array()))
}

/// A kernel input of four lanes written by `lane`, then `[0, ∞]`.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn kernel_input(lane: impl Fn(f32, &mut Vec<u8>)) -> Vec<u8> {
    let mut b = Vec::new();
    for i in 0..4 {
        lane(i as f32, &mut b);
    }
    super::encode_interval(&mut b);
    b
}

/// The start of a failure, to compare with (the rest is the case).
fn head(r: Result<(), Failure>) -> String {
    let e = r.expect_err("a wrong kernel passed");
    e.0.lines().next().unwrap_or("").to_string()
}

#[cfg(feature = "plane")]
mod plane {
    use super::*;
    use crate::fuzz::{Kernels, PrimitiveKernels, encode3, primitive_with};
    use crate::plane::{Plane, PlaneHit, reference, x4};

    /// Lane `i` is the line from `(0, 1 + i, 0)` straight down onto `y = 0`:
    /// a hit at `t = 1 + i`, different in each lane.
    fn input() -> Vec<u8> {
        kernel_input(|i, b| {
            encode3(Vec3::new(0.0, 1.0 + i, 0.0), b);
            encode3(-Vec3::Y, b);
            encode3(Vec3::ZERO, b);
            encode3(Vec3::Y, b);
        })
    }

    fn swapped(r: &Ray4, p: &x4::Plane4) -> x4::PlaneHit4 {
        let h = x4::intersect(r, p);
        x4::PlaneHit4 {
            class: swap_i(h.class),
            t: swap_f(h.t),
        }
    }

    fn shifted(r: &Ray, p: &Plane) -> PlaneHit {
        match reference::intersect(r, p) {
            PlaneHit::Hit(t) => PlaneHit::Hit(t + 1.0),
            h => h,
        }
    }

    fn shifted4(r: &Ray4, p: &x4::Plane4) -> x4::PlaneHit4 {
        let h = x4::intersect(r, p);
        x4::PlaneHit4 {
            t: h.t + f32x4::ONE,
            ..h
        }
    }

    /// A batch that leaves its last packet out.
    fn first_only(r: &[Ray4], p: &x4::Plane4, out: &mut [x4::PlaneHit4]) {
        x4::intersect_packets(&r[..1], p, &mut out[..1])
    }

    #[test]
    fn the_plane_target_catches_swapped_lanes_a_wrong_root_and_a_short_batch() {
        let short: PrimitiveKernels<Plane> = Kernels {
            reference: reference::intersect,
            x4: x4::intersect,
            batch: first_only,
        };
        assert_eq!(
            head(primitive_with::<Plane>(&input(), short)),
            "packet 1 lane 0: batch Hit(1.0) but x4 Hit(2.0)"
        );
        assert_eq!(crate::fuzz::primitive::<Plane>(&input()), Ok(()));
        let swap: PrimitiveKernels<Plane> = Kernels {
            reference: reference::intersect,
            x4: swapped,
            batch: x4::intersect_packets,
        };
        assert_eq!(
            head(primitive_with::<Plane>(&input(), swap)),
            "lane 0: x4 Hit(2.0) but reference Hit(1.0)"
        );
        let shift: PrimitiveKernels<Plane> = Kernels {
            reference: shifted,
            x4: shifted4,
            batch: x4::intersect_packets,
        };
        let e = head(primitive_with::<Plane>(&input(), shift));
        assert!(
            e.starts_with("lane 0: plane: root 0 is 2e0 (0x40000000), exact 1e0 (0x3f800000)"),
            "{e}"
        );
    }
}

#[cfg(feature = "sphere")]
mod sphere {
    use super::*;
    use crate::fuzz::{Kernels, PrimitiveKernels, encode3, primitive_with};
    use crate::ray4::scatter3;
    use crate::sphere::{Sphere, SphereHit, reference, textbook, x4};

    /// Lane `i` looks along +z at the unit sphere from `z = −(5 + i)`,
    /// except lane 0, which is `10⁴` away, where the textbook formula
    /// turns the two roots 9999 and 10001 into a tangent.
    fn input() -> Vec<u8> {
        kernel_input(|i, b| {
            let z = if i == 0.0 { -1e4 } else { -5.0 - i };
            encode3(Vec3::new(0.0, 0.0, z), b);
            encode3(Vec3::Z, b);
            encode3(Vec3::ZERO, b);
            encode_f32(1.0, b);
        })
    }

    fn swapped(r: &Ray4, s: &x4::Sphere4) -> x4::SphereHit4 {
        let h = x4::intersect(r, s);
        x4::SphereHit4 {
            class: swap_i(h.class),
            t0: swap_f(h.t0),
            t1: swap_f(h.t1),
        }
    }

    /// The textbook kernel lane by lane, so x4 agrees with it bit for bit.
    fn textbook4(r: &Ray4, s: &x4::Sphere4) -> x4::SphereHit4 {
        let (rays, centers, radii) = (r.to_rays(), scatter3(s.center), s.radius.to_array());
        let hits =
            [0, 1, 2, 3].map(|i| textbook::intersect(&rays[i], &Sphere::new(centers[i], radii[i])));
        let (class, t0, t1) = (
            hits.map(|h| match h {
                SphereHit::None => 0,
                SphereHit::Tangent(_) => 1,
                SphereHit::Two(..) => 2,
            }),
            hits.map(|h| match h {
                SphereHit::None => f32::NAN,
                SphereHit::Tangent(t) | SphereHit::Two(t, _) => t,
            }),
            hits.map(|h| match h {
                SphereHit::None => f32::NAN,
                SphereHit::Tangent(t) | SphereHit::Two(_, t) => t,
            }),
        );
        x4::SphereHit4 {
            class: i32x4::from(class),
            t0: f32x4::from(t0),
            t1: f32x4::from(t1),
        }
    }

    /// A batch that leaves its last packet out.
    fn first_only(r: &[Ray4], p: &x4::Sphere4, out: &mut [x4::SphereHit4]) {
        x4::intersect_packets(&r[..1], p, &mut out[..1])
    }

    #[test]
    fn the_sphere_target_catches_swapped_lanes_the_textbook_formula_and_a_short_batch() {
        let short: PrimitiveKernels<Sphere> = Kernels {
            reference: reference::intersect,
            x4: x4::intersect,
            batch: first_only,
        };
        assert_eq!(
            head(primitive_with::<Sphere>(&input(), short)),
            "packet 1 lane 0: batch Two(9999.0, 10001.0) but x4 Two(5.0, 7.0)"
        );
        assert_eq!(crate::fuzz::primitive::<Sphere>(&input()), Ok(()));
        let swap: PrimitiveKernels<Sphere> = Kernels {
            reference: reference::intersect,
            x4: swapped,
            batch: x4::intersect_packets,
        };
        assert_eq!(
            head(primitive_with::<Sphere>(&input(), swap)),
            "lane 0: x4 Two(5.0, 7.0) but reference Two(9999.0, 10001.0)"
        );
        let seed: PrimitiveKernels<Sphere> = Kernels {
            reference: textbook::intersect,
            x4: textbook4,
            batch: x4::intersect_packets,
        };
        let e = head(primitive_with::<Sphere>(&input(), seed));
        assert!(
            e.starts_with("lane 0: sphere: class tangent, exact two"),
            "{e}"
        );
    }
}

#[cfg(feature = "quadric")]
mod quadric {
    use super::*;
    use crate::fuzz::{Kernels, PrimitiveKernels, encode3, primitive_with};
    use crate::quadric::{Quadric, QuadricHit, reference, x4};

    /// Lane `i` runs along +x from `x = −(5 + i)` through the cylinder
    /// `x² + y² = 1`: two roots, different in each lane.
    fn input() -> Vec<u8> {
        kernel_input(|i, b| {
            encode3(Vec3::new(-5.0 - i, 0.0, 0.0), b);
            encode3(Vec3::X, b);
            [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]
                .iter()
                .for_each(|&c| encode_f32(c, b));
        })
    }

    fn swapped(r: &Ray4, q: &x4::Quadric4) -> x4::QuadricHit4 {
        let h = x4::intersect(r, q);
        x4::QuadricHit4 {
            class: swap_i(h.class),
            t0: swap_f(h.t0),
            t1: swap_f(h.t1),
        }
    }

    fn shifted(r: &Ray, q: &Quadric) -> QuadricHit {
        match reference::intersect(r, q) {
            QuadricHit::One(t) => QuadricHit::One(t + 1.0),
            QuadricHit::Two(a, b) => QuadricHit::Two(a + 1.0, b + 1.0),
            h => h,
        }
    }

    fn shifted4(r: &Ray4, q: &x4::Quadric4) -> x4::QuadricHit4 {
        let h = x4::intersect(r, q);
        x4::QuadricHit4 {
            t0: h.t0 + f32x4::ONE,
            t1: h.t1 + f32x4::ONE,
            ..h
        }
    }

    /// A batch that leaves its last packet out.
    fn first_only(r: &[Ray4], p: &x4::Quadric4, out: &mut [x4::QuadricHit4]) {
        x4::intersect_packets(&r[..1], p, &mut out[..1])
    }

    #[test]
    fn the_quadric_target_catches_swapped_lanes_wrong_roots_and_a_short_batch() {
        let short: PrimitiveKernels<Quadric> = Kernels {
            reference: reference::intersect,
            x4: x4::intersect,
            batch: first_only,
        };
        assert_eq!(
            head(primitive_with::<Quadric>(&input(), short)),
            "packet 1 lane 0: batch Two(4.0, 6.0) but x4 Two(5.0, 7.0)"
        );
        assert_eq!(crate::fuzz::primitive::<Quadric>(&input()), Ok(()));
        let swap: PrimitiveKernels<Quadric> = Kernels {
            reference: reference::intersect,
            x4: swapped,
            batch: x4::intersect_packets,
        };
        assert_eq!(
            head(primitive_with::<Quadric>(&input(), swap)),
            "lane 0: x4 Two(5.0, 7.0) but reference Two(4.0, 6.0)"
        );
        let shift: PrimitiveKernels<Quadric> = Kernels {
            reference: shifted,
            x4: shifted4,
            batch: x4::intersect_packets,
        };
        let e = head(primitive_with::<Quadric>(&input(), shift));
        assert!(
            e.starts_with("lane 0: quadric: root 0 is 5e0 (0x40a00000), exact 4e0 (0x40800000)"),
            "{e}"
        );
    }
}

/// A camera input: a 64 × 48 camera looking down −z and four pixels.
fn camera_input(px: [[u16; 2]; 4]) -> Vec<u8> {
    let mut b = Vec::new();
    for v in [Vec3::ZERO, -Vec3::Z, Vec3::Y] {
        super::encode3(v, &mut b);
    }
    encode_f32(1.0, &mut b);
    for r in [64u16, 48] {
        b.extend(r.to_le_bytes());
    }
    for [x, y] in px {
        b.extend(x.to_le_bytes());
        b.extend(y.to_le_bytes());
    }
    b
}

/// The shipped ray, with its direction's x off by 1 at column 2 or row 3.
fn wrong_at_2_3(cam: &Camera, x: u32, y: u32) -> Ray {
    let r = cam.ray(x, y);
    if x == 2 || y == 3 {
        Ray::new(r.origin, r.dir + Vec3::X)
    } else {
        r
    }
}

/// [`wrong_at_2_3`] four pixels at a time, so x4 agrees with it.
fn wrong_at_2_3_x4(cam: &Camera, px: [[u32; 2]; 4]) -> Ray4 {
    Ray4::from_rays(px.map(|[x, y]| wrong_at_2_3(cam, x, y)))
}

/// The shipped x4 with one lane's value changed by `f`.
fn lane_changed(r: Ray4, lane: usize, f: fn(f32) -> f32) -> Ray4 {
    let mut d = r.dir[0].to_array();
    d[lane] = f(d[lane]);
    Ray4 {
        dir: [f32x4::from(d), r.dir[1], r.dir[2]],
        ..r
    }
}

#[test]
fn the_camera_target_catches_a_wrong_lane_and_checks_the_wrapped_pixel() {
    use super::{CameraKernels, Kernels};
    let px = [[1, 1], [5, 6], [7, 8], [9, 10]];
    assert_eq!(camera(&camera_input(px)), Ok(()));
    // The direction of lane 2 off (its origin right), and lane 1 NaN.
    let dir_off: CameraKernels = Kernels {
        reference: Camera::ray,
        x4: |c: &Camera, p| lane_changed(c.ray4(p), 2, |x| x + 1.0),
        batch: (),
    };
    assert!(head(camera_with(&camera_input(px), dir_off)).starts_with("lane 2: x4 Ray"));
    let nan: CameraKernels = Kernels {
        reference: Camera::ray,
        x4: |c: &Camera, p| lane_changed(c.ray4(p), 1, |_| f32::NAN),
        batch: (),
    };
    assert!(head(camera_with(&camera_input(px), nan)).starts_with("lane 1: x4 Ray"));
    // A kernel wrong only at column 2 and row 3, bit-identical in x4: the
    // oracle catches it at pixel (66, 1) and (1, 51), which wrap to (2, 1)
    // and (1, 3), and not at (1, 1) or at pixels that wrap elsewhere.
    let wrong: CameraKernels = Kernels {
        reference: wrong_at_2_3,
        x4: wrong_at_2_3_x4,
        batch: (),
    };
    assert_eq!(camera_with(&camera_input([[1, 1]; 4]), wrong), Ok(()));
    assert_eq!(camera_with(&camera_input([[3, 4]; 4]), wrong), Ok(()));
    for (p, lane) in [([66, 1], 0), ([1, 51], 3), ([2, 0], 1)] {
        let mut px = [[1, 1]; 4];
        px[lane] = p;
        let e = head(camera_with(&camera_input(px), wrong));
        assert!(e.starts_with(&format!("lane {lane}: ")), "{p:?}: {e}");
    }
}

#[test]
fn the_eval_line_target_catches_each_broken_output() {
    let line: &[u8] = br#"{"kind":"sphere","radius":[1]}"#;
    assert_eq!(eval_line(line), Ok(()));
    type Eval = fn(usize, &str) -> String;
    let cases: [(Eval, &[u8], &str); 4] = [
        (|_, _| "{".into(), line, "not JSON"),
        (|_, _| r#"{"line": 8}"#.into(), line, "wrong line number"),
        (
            |n, _| format!(r#"{{"line": {n}, "error": "internal error: boom"}}"#),
            line,
            "eval panicked",
        ),
        (|_, _| "{}".into(), b"  ", "blank line gave output"),
    ];
    for (eval, input, why) in cases {
        let e = eval_line_with(input, eval).unwrap_err().0;
        assert!(e.starts_with(why), "{e}");
    }
    let fine = |n: usize, _: &str| format!(r#"{{"line": {n}, "error": "no camera"}}"#);
    assert_eq!(eval_line_with(line, fine), Ok(()));
    assert_eq!(eval_line_with(b"", |_, _| String::new()), Ok(()));
}
