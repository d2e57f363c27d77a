//! Reference against x4 for every kernel, over batches of 4096 primary rays
//! of a 64×64 camera (jittered, seeded), plus the plain-f64 variant as a
//! baseline and parry3d as an outside peer (`Ball` for the sphere,
//! `HalfSpace` for the plane). The sphere is also run on the same rays
//! shuffled, where neighbouring rays no longer take the same branches:
//! drawn in a fresh order before every pass, outside the timed part,
//! because a branch predictor learns one fixed order over thousands of
//! repeated passes, as incoherent rays in a renderer never repeat. Run
//! with `cargo bench --bench kernels`; the rates and ratios of the run are
//! printed at the end and written to `target/criterion/ratios.md` and
//! `target/criterion/ratios.json` (one object per kernel, Mrays/s). A
//! filter (`cargo bench --bench kernels -- sphere`) applies to every
//! measure below; a filtered run prints its kernels' rows and leaves those
//! files as the last full run wrote them.
//!
//! Two measures of each, from the same run. Criterion's median times each
//! way of running a kernel for seconds, one after another, so on a shared
//! machine two ways of one kernel can meet different loads. After it, every
//! routine runs again in interleaved rounds, one pass over the kernel's
//! rays each, a kernel's ways back to back ([`Paired`]); each keeps its
//! fastest pass (`interleaved` in the JSON) and its median one
//! (`interleaved_median`). Load from elsewhere only adds time, so the
//! fastest pass is the one least disturbed, and the ways of a kernel are
//! compared under the same conditions; the median shows which ways reach
//! their fastest only now and then.
//!
//! The ways of running a kernel, per batch:
//! * `reference/per-ray`: one `black_box`ed call per ray, so the optimiser
//!   cannot fuse calls across rays: the scalar code as written.
//! * `reference/slice`: a plain loop over the slice, which LLVM may
//!   auto-vectorise.
//! * `x4/packed`: the SIMD kernel over rays already packed four to a
//!   `Ray4`, one `intersect(&Ray4, …)` call per packet.
//! * `x4/baseline`: the per-packet call on the baseline copy of the
//!   kernel (`wide::f64x4`, two SSE2 registers in a default build), which
//!   `x4/packed` leaves for the AVX2 copy where the CPU has AVX2 and FMA.
//! * `x4/batch`: the same packets through `intersect_packets`, which runs
//!   them two at a time as eight lanes and dispatches once per batch.
//! * `x4/ftz-daz` (x86-64): `x4/packed` with flush-to-zero and
//!   denormals-are-zero on, as many renderers run; no input is subnormal,
//!   so the packets keep their fast paths.
//! * `f64/per-ray`: the plain-f64 variant (`*::plain`; `textbook` for the
//!   camera), one `black_box`ed call per ray.
//! * `parry3d/per-ray` (sphere, plane): `Ball::cast_local_ray` and
//!   `HalfSpace::cast_local_ray`, one `black_box`ed call per ray.
//!
//! The scalar and per-packet closures are `#[inline(always)]`, as a
//! kernel called directly in a renderer's loop is inlined (`intersect`
//! carries `#[inline]`): each runs inlined into the loop over the rays,
//! with the primitive's loop-invariant work hoisted out of it, and x4's
//! AVX2 copy is the one call per packet. Without that, the optimiser
//! inlines a closure by its size alone: the plain variant's, and not the
//! reference's, so the comparison would be of call overheads as much as
//! of kernels; and x4's closure stayed out of line, a second call per
//! packet with its result and the loop's sum going through memory, which
//! parry3d's cast, inlined into its loop, does not pay.

mod criterion_dir;

use criterion::{BenchmarkId, Criterion, Throughput};
use glam::Vec3;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use rayoracle::Ray;
use rayoracle::camera::{Camera, CameraParams};
use rayoracle::hit::Intersection;
use rayoracle::plane::{self, Plane};
use rayoracle::quadric::{self, Quadric};
use rayoracle::ray4::Ray4;
use rayoracle::sphere::{self, Sphere};
use std::cell::RefCell;
use std::hint::black_box;
use std::time::{Duration, Instant};
use wide::f32x4;

const N: usize = 4096;

/// The interleaved rounds: each routine's fastest and median of this many
/// passes.
const ROUNDS: usize = 1000;

fn camera() -> Camera {
    CameraParams::new(
        Vec3::new(0.0, 1.0, 6.0),
        Vec3::new(0.0, -0.15, -1.0),
        Vec3::Y,
        0.9,
        [64, 64],
    )
    .build()
    .expect("valid camera")
}

/// Primary rays of a 64×64 camera, jittered, looking at the scene.
fn rays(rng: &mut SmallRng) -> Vec<Ray> {
    let cam = camera();
    (0..N)
        .map(|i| {
            let r = cam.ray((i % 64) as u32, (i / 64) as u32);
            let j = Vec3::new(
                rng.random_range(-0.01..0.01),
                rng.random_range(-0.01..0.01),
                0.0,
            );
            Ray::new(r.origin, r.dir + j)
        })
        .collect()
}

fn pack(rays: &[Ray]) -> Vec<Ray4> {
    rays.chunks_exact(4)
        .map(|c| Ray4::from_rays([c[0], c[1], c[2], c[3]]))
        .collect()
}

/// Every routine the criterion groups time, kept to be timed again,
/// interleaved ([`Paired::run`]): one pass of each routine of a kernel in
/// turn, round after round, so that the variants of a kernel are measured
/// within microseconds of each other, under the same load from the rest
/// of the machine; each keeps its fastest pass and its median one.
#[derive(Default)]
struct Paired<'a> {
    routines: Vec<Routine<'a>>,
    /// Routines criterion's filter left out (`cargo bench --bench kernels
    /// -- sphere`, say), which the interleaved rounds leave out too.
    filtered: usize,
}

/// A kernel (the criterion group), a way of running it, one pass, and
/// the rays it reads, which may need a fresh order before the pass.
type Routine<'a> = (
    String,
    &'static str,
    Box<dyn FnMut() + 'a>,
    Option<&'a RaySet>,
);

/// A set of rays as the ways of running a kernel read it: as rays, packed
/// four to a [`Ray4`], and moved into the shape's frame for parry3d. A
/// shuffled set is drawn in a fresh order before every pass
/// ([`RaySet::prepare`], untimed): repeated passes over one fixed order
/// let a branch predictor learn it, which is not what shuffled rays are
/// there to show.
struct RaySet {
    rays: RefCell<Vec<Ray>>,
    packed: RefCell<Vec<Ray4>>,
    local: RefCell<Vec<parry3d::query::Ray>>,
    at: Vec3,
    fresh: Option<RefCell<SmallRng>>,
}

impl RaySet {
    /// The rays in the order given, moved by `-at` for parry3d; shuffled
    /// afresh before every pass, from a seeded generator, where `fresh`.
    fn new(rays: Vec<Ray>, at: Vec3, fresh: bool) -> RaySet {
        RaySet {
            packed: RefCell::new(pack(&rays)),
            local: RefCell::new(local(&rays, at)),
            rays: RefCell::new(rays),
            at,
            fresh: fresh.then(|| RefCell::new(SmallRng::seed_from_u64(0x5_4ff1e))),
        }
    }

    /// A fresh order for a shuffled set, and its packets and parry3d rays
    /// formed again from it (nothing for the others).
    fn prepare(&self) {
        use rand::seq::SliceRandom;
        let Some(rng) = &self.fresh else { return };
        let mut rays = self.rays.borrow_mut();
        rays.shuffle(&mut *rng.borrow_mut());
        *self.packed.borrow_mut() = pack(&rays);
        *self.local.borrow_mut() = local(&rays, self.at);
    }
}

/// A routine's interleaved passes, in ns: the fastest, the one least
/// disturbed by load from elsewhere, and the median, which a routine
/// whose time swings with that load (a long chain of divisions sharing a
/// core with another tenant, say) does not get credit for at its best.
#[derive(Clone, Copy)]
struct Passes {
    fastest: f64,
    median: f64,
}

impl<'a> Paired<'a> {
    /// Times `routine` under `group/id` with criterion, and keeps it, unless
    /// criterion's filter skipped it (criterion then never calls the
    /// closure that times it). Before each pass over a shuffled `set`, the
    /// set's fresh order, untimed.
    fn bench<T>(
        &mut self,
        g: &mut criterion::BenchmarkGroup<'_, criterion::measurement::WallTime>,
        group: &str,
        id: &'static str,
        set: Option<&'a RaySet>,
        mut routine: impl FnMut() -> T + 'a,
    ) {
        let (f, p) = id.split_once('/').expect("variant/way");
        let mut timed = false;
        g.bench_function(BenchmarkId::new(f, p), |b| {
            timed = true;
            match set.filter(|s| s.fresh.is_some()) {
                None => b.iter(&mut routine),
                Some(set) => b.iter_custom(|iters| {
                    let mut t = Duration::ZERO;
                    for _ in 0..iters {
                        set.prepare();
                        let start = Instant::now();
                        black_box(routine());
                        t += start.elapsed();
                    }
                    t
                }),
            }
        });
        if !timed {
            self.filtered += 1;
            return;
        }
        self.routines.push((
            group.to_string(),
            id,
            Box::new(move || {
                black_box(routine());
            }),
            set,
        ));
    }

    /// `rounds` rounds of one pass of every routine, a kernel's routines
    /// one after another; the fastest and the median pass of each, in ns,
    /// and whether every routine ran (no filter).
    fn run(mut self, rounds: usize) -> (Vec<(String, &'static str, Passes)>, bool) {
        let mut times = vec![Vec::with_capacity(rounds); self.routines.len()];
        for _ in 0..rounds {
            for (t, (_, _, r, set)) in times.iter_mut().zip(&mut self.routines) {
                if let Some(set) = set {
                    set.prepare();
                }
                let start = Instant::now();
                r();
                t.push(start.elapsed().as_nanos() as f64);
            }
        }
        let passes = times.into_iter().map(|mut t| {
            t.sort_by(f64::total_cmp);
            Passes {
                fastest: t[0],
                median: t[t.len() / 2],
            }
        });
        let complete = self.filtered == 0;
        let passes = self
            .routines
            .into_iter()
            .zip(passes)
            .map(|((g, id, _, _), t)| (g, id, t))
            .collect();
        (passes, complete)
    }
}

#[allow(clippy::too_many_arguments)]
fn bench_group<'a, P: Copy + 'a>(
    c: &mut Criterion,
    paired: &mut Paired<'a>,
    name: &str,
    set: &'a RaySet,
    prim: P,
    scalar: impl Fn(&Ray, &P) -> Option<f32> + Copy + 'a,
    baseline: impl Fn(&Ray, &P) -> Option<f32> + 'a,
    simd: impl Fn(&Ray4) -> f32x4 + Copy + 'a,
    base: impl Fn(&Ray4) -> f32x4 + 'a,
    mut batch: impl FnMut(&[Ray4]) -> f32x4 + 'a,
) {
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(set.rays.borrow().len() as u64));
    let (rays, packed) = (&set.rays, &set.packed);
    let s = Some(set);
    paired.bench(&mut g, name, "reference/per-ray", s, move || {
        let mut acc = 0.0f32;
        for r in rays.borrow().iter() {
            acc += black_box(scalar(black_box(r), &prim)).unwrap_or(0.0);
        }
        acc
    });
    paired.bench(&mut g, name, "reference/slice", s, move || {
        black_box(&rays.borrow()[..])
            .iter()
            .map(|r| scalar(r, &prim).unwrap_or(0.0))
            .sum::<f32>()
    });
    paired.bench(&mut g, name, "x4/packed", s, move || {
        let mut acc = f32x4::ZERO;
        for r in black_box(&packed.borrow()[..]) {
            acc += simd(r);
        }
        acc
    });
    #[cfg(target_arch = "x86_64")]
    paired.bench(&mut g, name, "x4/ftz-daz", s, move || {
        let _on = FtzDaz::on();
        let mut acc = f32x4::ZERO;
        for r in black_box(&packed.borrow()[..]) {
            acc += simd(r);
        }
        acc
    });
    paired.bench(&mut g, name, "x4/baseline", s, move || {
        let mut acc = f32x4::ZERO;
        for r in black_box(&packed.borrow()[..]) {
            acc += base(r);
        }
        acc
    });
    paired.bench(&mut g, name, "x4/batch", s, move || {
        batch(black_box(&packed.borrow()[..]))
    });
    paired.bench(&mut g, name, "f64/per-ray", s, move || {
        let mut acc = 0.0f32;
        for r in rays.borrow().iter() {
            acc += black_box(baseline(black_box(r), &prim)).unwrap_or(0.0);
        }
        acc
    });
    g.finish();
}

/// Flush-to-zero and denormals-are-zero on (MXCSR's bits 15 and 6) while
/// it lives, the register as it was after.
#[cfg(target_arch = "x86_64")]
struct FtzDaz(u32);

#[cfg(target_arch = "x86_64")]
impl FtzDaz {
    fn on() -> FtzDaz {
        let mut saved = 0u32;
        // SAFETY: stores the 32-bit MXCSR to `saved`, a live aligned u32;
        // there is no other way to read the register.
        unsafe { core::arch::asm!("stmxcsr [{}]", in(reg) &mut saved, options(nostack)) };
        let on = saved | 1 << 15 | 1 << 6;
        // SAFETY: loads MXCSR from `on`, a live aligned u32 holding the
        // register as it was with the FTZ and DAZ bits set: a valid value.
        unsafe { core::arch::asm!("ldmxcsr [{}]", in(reg) &on, options(nostack)) };
        FtzDaz(saved)
    }
}

#[cfg(target_arch = "x86_64")]
impl Drop for FtzDaz {
    fn drop(&mut self) {
        // SAFETY: loads MXCSR from `self.0`, the value `on` read from it: valid.
        unsafe { core::arch::asm!("ldmxcsr [{}]", in(reg) &self.0, options(nostack)) };
    }
}

/// parry3d's cast on the same rays, moved into the shape's frame
/// beforehand, one `black_box`ed call per ray.
fn bench_peer<'a, S: parry3d::query::RayCast + 'a>(
    c: &mut Criterion,
    paired: &mut Paired<'a>,
    name: &str,
    shape: &'a S,
    set: &'a RaySet,
) {
    let mut g = c.benchmark_group(name);
    let local = &set.local;
    g.throughput(Throughput::Elements(local.borrow().len() as u64));
    paired.bench(&mut g, name, "parry3d/per-ray", Some(set), move || {
        let mut acc = 0.0f32;
        for r in local.borrow().iter() {
            acc += black_box(shape.cast_local_ray(black_box(r), f32::MAX, false)).unwrap_or(0.0);
        }
        acc
    });
    g.finish();
}

/// The rays moved by `-at`, as parry3d rays.
fn local(rays: &[Ray], at: Vec3) -> Vec<parry3d::query::Ray> {
    rays.iter()
        .map(|r| {
            let o = (r.origin - at).to_array();
            parry3d::query::Ray::new(o.into(), r.dir.to_array().into())
        })
        .collect()
}

/// Runs every group with criterion, then the interleaved passes
/// ([`Paired`]); returns the fastest and the median pass of each routine
/// that ran, and whether all did.
fn benches(c: &mut Criterion) -> (Vec<(String, &'static str, Passes)>, bool) {
    let mut rng = SmallRng::seed_from_u64(0x5eed);
    let rays = rays(&mut rng);
    let (t_min, t_max) = (f32x4::ZERO, f32x4::splat(f32::INFINITY));
    let finite = |m: f32x4, t: f32x4| m.select(t, f32x4::ZERO);

    // The data every routine borrows, before the routines themselves.
    let s = Sphere::new(Vec3::new(0.3, 0.5, -1.0), 1.2);
    let s4 = sphere::x4::Sphere4::splat(&s);
    let ball = parry3d::shape::Ball::new(s.radius);
    let sets = [
        ("sphere", RaySet::new(rays.clone(), s.center, false)),
        ("sphere-shuffled", RaySet::new(rays.clone(), s.center, true)),
    ];
    let mut sphere_out =
        [(); 2].map(|_| vec![sphere::x4::intersect(&Ray4::splat(rays[0]), &s4); N / 4]);

    let p = Plane::new(Vec3::new(0.0, -1.0, 0.0), Vec3::new(0.05, 1.0, 0.02));
    let p4 = plane::x4::Plane4::splat(&p);
    let mut plane_out = vec![plane::x4::intersect(&Ray4::splat(rays[0]), &p4); N / 4];
    let n = p.normal.normalize().to_array();
    let half = parry3d::shape::HalfSpace::new(parry3d::math::Vector::new(n[0], n[1], n[2]));
    let plane_set = RaySet::new(rays.clone(), p.point, false);

    // A one-sheet hyperboloid x² + z² − y² = 0.5, tilted by the mix of terms.
    let q = Quadric::new([1.0, -1.0, 1.0, 0.1, 0.0, 0.05, 0.0, 0.2, 0.0, -0.5]);
    let q4 = quadric::x4::Quadric4::splat(&q);
    let mut quadric_out = vec![quadric::x4::intersect(&Ray4::splat(rays[0]), &q4); N / 4];
    let quadric_set = RaySet::new(rays.clone(), Vec3::ZERO, false);

    let cam = camera();
    let cam64 = rayoracle::camera::plain::Camera::new(&cam.params).expect("valid camera");

    let mut paired = Paired::default();
    for ((name, set), out) in sets.iter().zip(&mut sphere_out) {
        bench_group(
            c,
            &mut paired,
            name,
            set,
            s,
            #[inline(always)]
            |r, s| sphere::reference::intersect(r, s).nearest(0.0, f32::INFINITY),
            #[inline(always)]
            |r, s| sphere::plain::intersect(r, s).nearest(0.0, f32::INFINITY),
            #[inline(always)]
            |r| {
                let (m, t) = sphere::x4::intersect(r, &s4).nearest(t_min, t_max);
                finite(m, t)
            },
            #[inline(always)]
            |r| {
                let (m, t) = sphere::x4::intersect_baseline(r, &s4).nearest(t_min, t_max);
                finite(m, t)
            },
            |packed| {
                sphere::x4::intersect_packets(packed, &s4, out);
                let mut acc = f32x4::ZERO;
                for h in out.iter() {
                    let (m, t) = h.nearest(t_min, t_max);
                    acc += finite(m, t);
                }
                acc
            },
        );
        bench_peer(c, &mut paired, name, &ball, set);
    }

    bench_group(
        c,
        &mut paired,
        "plane",
        &plane_set,
        p,
        #[inline(always)]
        |r, p| plane::reference::intersect(r, p).nearest(0.0, f32::INFINITY),
        #[inline(always)]
        |r, p| plane::plain::intersect(r, p).nearest(0.0, f32::INFINITY),
        #[inline(always)]
        |r| {
            let (m, t) = plane::x4::intersect(r, &p4).nearest(t_min, t_max);
            finite(m, t)
        },
        #[inline(always)]
        |r| {
            let (m, t) = plane::x4::intersect_baseline(r, &p4).nearest(t_min, t_max);
            finite(m, t)
        },
        |packed| {
            plane::x4::intersect_packets(packed, &p4, &mut plane_out);
            let mut acc = f32x4::ZERO;
            for h in &plane_out {
                let (m, t) = h.nearest(t_min, t_max);
                acc += finite(m, t);
            }
            acc
        },
    );
    bench_peer(c, &mut paired, "plane", &half, &plane_set);

    bench_group(
        c,
        &mut paired,
        "quadric",
        &quadric_set,
        q,
        #[inline(always)]
        |r, q| quadric::reference::intersect(r, q).nearest(0.0, f32::INFINITY),
        #[inline(always)]
        |r, q| quadric::plain::intersect(r, q).nearest(0.0, f32::INFINITY),
        #[inline(always)]
        |r| {
            let (m, t) = quadric::x4::intersect(r, &q4).nearest(t_min, t_max);
            finite(m, t)
        },
        #[inline(always)]
        |r| {
            let (m, t) = quadric::x4::intersect_baseline(r, &q4).nearest(t_min, t_max);
            finite(m, t)
        },
        |packed| {
            quadric::x4::intersect_packets(packed, &q4, &mut quadric_out);
            let mut acc = f32x4::ZERO;
            for h in &quadric_out {
                let (m, t) = h.nearest(t_min, t_max);
                acc += finite(m, t);
            }
            acc
        },
    );

    // Camera: 4096 pixel rays; the x4 path makes four consecutive pixels.
    let (cam, cam64) = (&cam, &cam64);
    let mut g = c.benchmark_group("camera");
    g.throughput(Throughput::Elements(N as u64));
    paired.bench(&mut g, "camera", "reference/per-ray", None, move || {
        let mut acc = 0.0f32;
        for i in 0..N as u32 {
            acc += black_box(cam.ray(black_box(i % 64), i / 64)).dir.x;
        }
        acc
    });
    paired.bench(&mut g, "camera", "reference/slice", None, move || {
        (0..N as u32)
            .map(|i| cam.ray(i % 64, i / 64).dir.x)
            .sum::<f32>()
    });
    paired.bench(&mut g, "camera", "x4/packed", None, move || {
        let mut acc = f32x4::ZERO;
        for i in (0..N as u32).step_by(4) {
            acc += black_box(cam.ray4_row(black_box(i % 64), i / 64)).dir[0];
        }
        acc
    });
    paired.bench(&mut g, "camera", "f64/per-ray", None, move || {
        let mut acc = 0.0f32;
        for i in 0..N as u32 {
            acc += black_box(cam64.ray(black_box(i % 64), i / 64)).dir.x;
        }
        acc
    });
    g.finish();
    paired.run(ROUNDS)
}

/// The rates of one kernel, Mrays/s, from `ns(id)`: the time of one pass
/// over the kernel's rays by way `id`. A row of the Markdown table, and
/// the JSON object's rates.
fn rates(k: &str, ns: impl Fn(&str) -> Option<f64>) -> (String, serde_json::Value) {
    let rate = |id: &str| ns(id).map(|t| N as f64 / t * 1e3);
    let f = |x: Option<f64>| x.map_or("–".into(), |v| format!("{v:.1}"));
    let r = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => format!("{:.2}×", a / b),
        _ => "–".into(),
    };
    let (pr, sl, x4, base, batch, daz, f64r, peer) = (
        rate("reference/per-ray"),
        rate("reference/slice"),
        rate("x4/packed"),
        rate("x4/baseline"),
        rate("x4/batch"),
        rate("x4/ftz-daz"),
        rate("f64/per-ray"),
        rate("parry3d/per-ray"),
    );
    let md = format!(
        "| {k} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
        f(pr),
        f(sl),
        f(x4),
        f(base),
        f(batch),
        f(daz),
        f(f64r),
        f(peer),
        r(x4, peer),
        r(batch, peer),
        r(x4, f64r),
        r(f64r, pr),
    );
    let mut o = serde_json::json!({
        "reference_per_ray": pr,
        "reference_slice": sl,
        "x4": x4,
        "x4_baseline": base,
        "x4_batch": batch,
        "f64": f64r,
    });
    if let Some(d) = daz {
        o["x4_ftz_daz"] = serde_json::json!(d);
    }
    if let Some(p) = peer {
        o["parry3d"] = serde_json::json!(p);
    }
    (md, o)
}

/// Prints the rates and ratios of this run, and writes them to
/// `target/criterion/ratios.{md,json}`: criterion's medians (read back
/// from its estimates), and, as `interleaved` and `interleaved_median`,
/// each routine's fastest and median of the [`ROUNDS`] interleaved passes
/// ([`Paired`]). A filtered run (`complete` false) prints the rows of the
/// kernels it ran and leaves the files of the last full run alone.
fn print_ratios(passes: &[(String, &'static str, Passes)], complete: bool) {
    let base = criterion_dir::criterion_dir();
    let median = |group: &str, id: &str| -> Option<f64> {
        let path = base.join(group).join(id).join("new/estimates.json");
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
        v["median"]["point_estimate"].as_f64()
    };
    let pass = |group: &str, id: &str| {
        passes
            .iter()
            .find(|(g, i, _)| g == group && *i == id)
            .map(|b| b.2)
    };
    let head = "| kernel | reference per-ray | reference slice | x4 | x4 baseline | x4 batch | x4 FTZ+DAZ | f64 per-ray | parry3d | x4 ÷ parry3d | x4 batch ÷ parry3d | x4 ÷ f64 | f64 ÷ reference per-ray |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    let (mut md, mut fast, mut mid) = (String::from(head), String::from(head), String::from(head));
    let mut json = Vec::new();
    for k in ["camera", "plane", "sphere", "sphere-shuffled", "quadric"] {
        if !passes.iter().any(|p| p.0 == k) {
            continue;
        }
        let rays = if k == "sphere-shuffled" {
            "4096 primary rays of a 64×64 camera, shuffled"
        } else {
            "4096 primary rays of a 64×64 camera"
        };
        // Criterion's estimates of this run only: a filtered run leaves
        // those of earlier runs on disk.
        let (row, mut o) = rates(k, |id| pass(k, id).and_then(|_| median(k, id)));
        let (fast_row, interleaved) = rates(k, |id| pass(k, id).map(|p| p.fastest));
        let (mid_row, interleaved_median) = rates(k, |id| pass(k, id).map(|p| p.median));
        md += &row;
        fast += &fast_row;
        mid += &mid_row;
        o["kernel"] = serde_json::json!(k);
        o["rays"] = serde_json::json!(rays);
        o["interleaved"] = interleaved;
        o["interleaved_median"] = interleaved_median;
        json.push(o);
    }
    let md = format!(
        "Mrays/s, one run, 4096 primary rays of a 64×64 camera (sphere-shuffled: the same, shuffled).\n\n\
         Criterion's medians:\n\n{md}\n\
         The fastest of {ROUNDS} interleaved passes (one pass of each way of a kernel in turn):\n\n{fast}\n\
         The median of the same passes:\n\n{mid}"
    );
    println!("\n{md}");
    if !complete {
        println!(
            "A filtered run: target/criterion/ratios.{{md,json}} are written by full runs only."
        );
        return;
    }
    let _ = std::fs::write(base.join("ratios.md"), &md);
    let text = serde_json::to_string_pretty(&json).expect("JSON");
    let _ = std::fs::write(base.join("ratios.json"), text + "\n");
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    let (passes, complete) = benches(&mut c);
    c.final_summary();
    print_ratios(&passes, complete);
}
