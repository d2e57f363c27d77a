//! The implementations `rayoracle report` compares, run over a family's
//! cases for their results and for their time.

use crate::Ray;
use crate::camera::{self, CameraParams};
use crate::case::{Case, Kind};
use crate::eval::Outcome;
use crate::plane::Plane;
use crate::primitive::{Primitive, x4_lanes};
use crate::quadric::Quadric;
use crate::ray4::Ray4;
use crate::sphere::Sphere;
use std::hint::black_box;
use std::time::Instant;

/// One implementation of every kernel.
///
/// ```
/// use rayoracle::report::Variant;
/// assert_eq!(Variant::parse("f64"), Some(Variant::F64));
/// assert_eq!(Variant::ALL.map(|v| v.name()), ["textbook", "reference", "x4", "f64", "exact"]);
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Variant {
    /// The textbook formulas, algebra corrected, no numerical care, in f32
    /// (`*::textbook`).
    Textbook,
    /// The scalar reference (`*::reference`).
    Reference,
    /// The four-lane kernels (`*::x4`), four cases per packet.
    X4,
    /// The reference's formulation in plain f64, rounded to f32 once
    /// (`*::plain`).
    F64,
    /// The exact oracle itself (`*::exact`; f64 for the camera).
    Exact,
}

impl Variant {
    /// Every variant, in report order.
    pub const ALL: [Variant; 5] = [
        Variant::Textbook,
        Variant::Reference,
        Variant::X4,
        Variant::F64,
        Variant::Exact,
    ];

    /// The name used in tables and JSON.
    pub fn name(self) -> &'static str {
        match self {
            Variant::Textbook => "textbook",
            Variant::Reference => "reference",
            Variant::X4 => "x4",
            Variant::F64 => "f64",
            Variant::Exact => "exact",
        }
    }

    /// The variant of a name.
    pub fn parse(name: &str) -> Option<Variant> {
        Variant::ALL.into_iter().find(|v| v.name() == name)
    }
}

impl core::fmt::Display for Variant {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.name())
    }
}

/// A variant serialises as its [`name`](Variant::name).
impl serde::Serialize for Variant {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.name())
    }
}

/// A family's cases, unpacked by kind (and packed four-wide for x4), so
/// that timing measures the kernels and not a dispatch per case.
pub(super) enum Batch {
    Plane(Vec<(Ray, Plane)>),
    Sphere(Vec<(Ray, Sphere)>),
    Quadric(Vec<(Ray, Quadric)>),
    Camera(Vec<(CameraParams, [u32; 2])>),
}

/// `$body` with `$v` bound to the batch's cases, for each kind: the same
/// tokens for the three primitives (a generic call), `$camera` for the
/// camera.
macro_rules! per_batch {
    ($batch:expr, |$v:ident| $prim:expr, $camera:expr) => {
        match $batch {
            Batch::Plane($v) => $prim,
            Batch::Sphere($v) => $prim,
            Batch::Quadric($v) => $prim,
            Batch::Camera($v) => $camera,
        }
    };
}

impl Batch {
    pub(super) fn new(kernel: Kind, cases: &[Case]) -> Batch {
        fn pick<P: Primitive>(cases: &[Case]) -> Vec<(Ray, P)> {
            cases.iter().filter_map(P::of_case).collect()
        }
        match kernel {
            Kind::Plane => Batch::Plane(pick(cases)),
            Kind::Sphere => Batch::Sphere(pick(cases)),
            Kind::Quadric => Batch::Quadric(pick(cases)),
            Kind::Camera => Batch::Camera(
                cases
                    .iter()
                    .filter_map(|c| match c {
                        Case::Camera(p, px) => Some((*p, *px)),
                        _ => None,
                    })
                    .collect(),
            ),
        }
    }

    #[cfg(test)]
    pub(super) fn len(&self) -> usize {
        per_batch!(self, |v| v.len(), v.len())
    }
}

/// Groups of four, the last padded with its own last element.
fn fours<T: Copy>(v: &[T]) -> Vec<[T; 4]> {
    v.chunks(4)
        .map(|c| core::array::from_fn(|i| c[i.min(c.len() - 1)]))
        .collect()
}

fn camera_outcome(r: Result<Ray, camera::CameraError>) -> Outcome {
    r.map_or_else(|e| Outcome::Error(e.to_string()), Outcome::Ray)
}

/// The x4 camera: the reference construction, then one `ray4` per pixel
/// (the four lanes are four pixels of the same camera, as a renderer runs
/// it; lane 0 is the case's pixel).
fn camera_x4(p: &CameraParams, [x, y]: [u32; 2]) -> Result<Ray, camera::CameraError> {
    let cam = p.build()?;
    let [w, h] = p.res;
    let px = [0, 1, 2, 3].map(|i| [(x + i).min(w - 1), y.min(h - 1)]);
    Ok(cam.ray4(px).to_rays()[0])
}

/// Every case's outcome under `variant`, in order.
pub(super) fn outcomes(variant: Variant, batch: &Batch) -> Vec<Outcome> {
    per_batch!(
        batch,
        |v| primitive_outcomes(variant, v),
        camera_outcomes(variant, v)
    )
}

fn primitive_outcomes<P: Primitive>(variant: Variant, v: &[(Ray, P)]) -> Vec<Outcome> {
    let each = |f: fn(&Ray, &P) -> P::Hit| v.iter().map(|(r, p)| Outcome::hit(&f(r, p))).collect();
    match variant {
        Variant::Textbook => each(P::textbook),
        Variant::Reference => each(P::reference),
        Variant::F64 => each(P::plain),
        Variant::Exact => v.iter().map(|(r, p)| crate::eval::exact_of(r, p)).collect(),
        Variant::X4 => {
            let mut out: Vec<Outcome> = fours(v)
                .into_iter()
                .flat_map(x4_lanes)
                .map(|h| Outcome::hit(&h))
                .collect();
            out.truncate(v.len());
            out
        }
    }
}

fn camera_outcomes(variant: Variant, v: &[(CameraParams, [u32; 2])]) -> Vec<Outcome> {
    v.iter()
        .map(|&(p, px)| match variant {
            Variant::Textbook => {
                camera_outcome(camera::textbook::Camera::new(&p).map(|c| c.ray(px[0], px[1])))
            }
            Variant::Reference => camera_outcome(p.build().map(|c| c.ray(px[0], px[1]))),
            Variant::F64 => {
                camera_outcome(camera::plain::Camera::new(&p).map(|c| c.ray(px[0], px[1])))
            }
            Variant::Exact => crate::eval::exact(&Case::Camera(p, px)),
            Variant::X4 => camera_outcome(camera_x4(&p, px)),
        })
        .collect()
}

/// One call per item, its inputs passed by `black_box`ed references, so
/// that the optimiser can neither fuse calls across items nor see the
/// inputs. Not copies: a copy through `black_box` goes to memory in
/// pieces, which a kernel's wider loads then cannot take from the store
/// buffer, a store-forwarding stall of about 10 ns a call on the x86-64
/// machines measured, on every variant that loads its inputs as vectors.
fn each<A, B, R>(v: &[(A, B)], f: impl Fn(&A, &B) -> R) {
    for (a, b) in v {
        black_box(f(black_box(a), black_box(b)));
    }
}

/// Packets of four cases, packed before the clock starts.
fn packed<P: Copy, P4>(v: &[(Ray, P)], pack: impl Fn([P; 4]) -> P4) -> Vec<(Ray4, P4)> {
    fours(v)
        .into_iter()
        .map(|g| (Ray4::from_rays(g.map(|c| c.0)), pack(g.map(|c| c.1))))
        .collect()
}

/// Cameras built before the clock starts (cases whose camera fails are
/// left out), with their pixels.
fn built<C>(
    v: &[(CameraParams, [u32; 2])],
    build: impl Fn(&CameraParams) -> Option<C>,
) -> Vec<(C, [u32; 2])> {
    v.iter()
        .filter_map(|(p, px)| build(p).map(|c| (c, *px)))
        .collect()
}

/// What one timed pass measured: its wall time and the rays it computed
/// in that time. The count is kept apart from the clock so that a test can
/// check it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Timed {
    /// Wall time of the whole pass.
    pub(super) nanos: f64,
    /// Rays computed.
    pub(super) rays: f64,
}

impl Timed {
    /// Nanoseconds per ray.
    pub(super) fn ns_per_ray(self) -> f64 {
        self.nanos / self.rays
    }
}

/// `reps` runs of `body`, which computes `rays` rays, timed. `rays` is
/// what one repetition computes over the cases actually run (a camera
/// that fails to build is left out of the pass, and so of the count).
fn timed(reps: usize, rays: usize, mut body: impl FnMut()) -> Timed {
    let start = Instant::now();
    for _ in 0..reps {
        body();
    }
    Timed {
        nanos: start.elapsed().as_nanos() as f64,
        rays: (reps * rays.max(1)) as f64,
    }
}

/// `reps` passes of `variant` over `batch`, timed: one `black_box`ed call
/// per case (per packet of four for x4), so the optimiser cannot vectorise
/// the scalar variants across cases. Packing into packets and building
/// cameras happen before the clock starts; a camera case is timed for its
/// ray only (the construction is once per frame), the camera passed by
/// reference, except for the exact oracle, whose f64 basis is rebuilt per
/// call.
pub(super) fn time_pass(variant: Variant, batch: &Batch, reps: usize) -> Timed {
    per_batch!(
        batch,
        |v| time_primitive(variant, v, reps),
        time_camera(variant, v, reps)
    )
}

fn time_primitive<P: Primitive>(variant: Variant, v: &[(Ray, P)], reps: usize) -> Timed {
    let n = v.len();
    match variant {
        Variant::X4 => {
            let v = packed(v, P::pack);
            timed(reps, n, || each(&v, P::x4))
        }
        Variant::Textbook => timed(reps, n, || each(v, P::textbook)),
        Variant::Reference => timed(reps, n, || each(v, P::reference)),
        Variant::F64 => timed(reps, n, || each(v, P::plain)),
        Variant::Exact => timed(reps, n, || each(v, |r, p| P::exact(r, p).ok())),
    }
}

fn time_camera(variant: Variant, v: &[(CameraParams, [u32; 2])], reps: usize) -> Timed {
    match variant {
        Variant::X4 => {
            // Four pixels of a row per call: four rays per case.
            let v = built(v, |p| p.build().ok());
            timed(reps, 4 * v.len(), || {
                for (c, [x, y]) in &v {
                    let [w, _] = c.params.res;
                    black_box(black_box(c).ray4_row((*x).min(w.saturating_sub(4)), *y));
                }
            })
        }
        // The built camera by reference, as x4 takes it: one camera serves
        // a frame, so a copy of it per ray is no part of a ray's cost.
        Variant::Textbook => {
            let v = built(v, |p| camera::textbook::Camera::new(p).ok());
            timed(reps, v.len(), || each(&v, |c, px| c.ray(px[0], px[1])))
        }
        Variant::Reference => {
            let v = built(v, |p| p.build().ok());
            timed(reps, v.len(), || each(&v, |c, px| c.ray(px[0], px[1])))
        }
        Variant::F64 => {
            let v = built(v, |p| camera::plain::Camera::new(p).ok());
            timed(reps, v.len(), || each(&v, |c, px| c.ray(px[0], px[1])))
        }
        Variant::Exact => timed(reps, v.len(), || {
            each(v, |p, px| camera::exact::ray(p, px[0], px[1]).ok())
        }),
    }
}

#[cfg(test)]
mod tests {
    use super::{Batch, Timed, Variant, outcomes, time_pass};
    use crate::report::Catalogue;

    /// A pass counts `reps` rays per case, four per case for the x4
    /// camera (one `ray4_row` call makes four), over the cases it ran: the
    /// textbook and f64 cameras leave out a case whose camera they cannot
    /// build, and nothing else is left out.
    #[test]
    fn a_timed_pass_counts_its_rays() {
        use crate::case::Kind;
        let c = Catalogue::builtin().unwrap().quick(3);
        for f in &c.families {
            let batch = Batch::new(f.kernel, &f.cases);
            for v in Variant::ALL {
                let t = time_pass(v, &batch, 5);
                let per_case = if (v, f.kernel) == (Variant::X4, Kind::Camera) {
                    4.0
                } else {
                    1.0
                };
                let all = 5.0 * f.cases.len() as f64 * per_case;
                let may_drop =
                    f.kernel == Kind::Camera && matches!(v, Variant::Textbook | Variant::F64);
                if may_drop {
                    assert!((5.0..=all).contains(&t.rays), "{} {v:?}", f.name);
                } else {
                    assert_eq!(t.rays, all, "{} {v:?}", f.name);
                }
                assert!(t.nanos >= 0.0);
            }
        }
        let t = Timed {
            nanos: 60.0,
            rays: 4.0,
        };
        assert_eq!(t.ns_per_ray(), 15.0);
    }

    /// Five cases make two packets, the second padded with the last case;
    /// `built` keeps the cases whose camera builds, with their pixels.
    #[test]
    fn packets_and_cameras_are_prepared_case_for_case() {
        use super::{built, packed};
        use crate::{Ray, camera::CameraParams};
        use glam::Vec3;
        let v: Vec<(Ray, u32)> = (0..5)
            .map(|i| (Ray::new(Vec3::splat(i as f32), Vec3::X), i))
            .collect();
        let p = packed(&v, |k: [u32; 4]| k);
        assert_eq!(p.len(), 2);
        assert_eq!((p[0].1, p[1].1), ([0, 1, 2, 3], [4, 4, 4, 4]));
        assert_eq!(p[1].0.origin[0].to_array(), [4.0; 4]);
        let cams: Vec<(CameraParams, [u32; 2])> = [0.5, 2.0, 1.5]
            .iter()
            .enumerate()
            .map(|(i, &a)| {
                let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, a, [4, 3]);
                (p, [i as u32, 0])
            })
            .collect();
        let kept = built(&cams, |p| (p.angle > 1.0).then_some(p.angle));
        assert_eq!(kept, vec![(2.0, [1, 0]), (1.5, [2, 0])]);
    }

    /// On every family of every kernel (6 cases each, so the last packet
    /// is padded), x4 gives one outcome per case, with the reference's
    /// bits, and so does every other variant's count.
    #[test]
    fn x4_matches_the_reference_case_for_case() {
        let c = Catalogue::builtin().unwrap().quick(6);
        for f in &c.families {
            let batch = Batch::new(f.kernel, &f.cases);
            assert_eq!(batch.len(), f.cases.len(), "{}", f.name);
            let reference = outcomes(Variant::Reference, &batch);
            let x4 = outcomes(Variant::X4, &batch);
            assert_eq!(x4.len(), f.cases.len(), "{}", f.name);
            for (i, (r, x)) in reference.iter().zip(&x4).enumerate() {
                assert!(r.same_bits(x), "{} case {i}: {r:?} against {x:?}", f.name);
            }
        }
    }
}
