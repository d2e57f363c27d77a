//! Reference against x4 for every kernel, over batches of 4096 primary rays
//! of a 64×64 camera (jittered, seeded), plus the plain-f64 variant as a
//! baseline and parry3d as an outside peer (`Ball` for the sphere,
//! `HalfSpace` for the plane). The sphere is also run on the same rays
//! shuffled, where neighbouring rays no longer take the same branches. Run
//! with `cargo bench --bench kernels`; the rates and ratios of the run are
//! printed at the end and written to `target/criterion/ratios.md` and
//! `target/criterion/ratios.json` (one object per kernel, Mrays/s).
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
//! * `f64/per-ray`: the plain-f64 variant (`*::plain`; `textbook` for the
//!   camera), one `black_box`ed call per ray.
//! * `parry3d/per-ray` (sphere, plane): `Ball::cast_local_ray` and
//!   `HalfSpace::cast_local_ray`, one `black_box`ed call per ray.

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
use std::hint::black_box;
use wide::f32x4;

const N: usize = 4096;

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

#[allow(clippy::too_many_arguments)]
fn bench_group<P: Copy>(
    c: &mut Criterion,
    name: &str,
    rays: &[Ray],
    prim: P,
    scalar: impl Fn(&Ray, &P) -> Option<f32>,
    baseline: impl Fn(&Ray, &P) -> Option<f32>,
    simd: impl Fn(&Ray4) -> f32x4,
    base: impl Fn(&Ray4) -> f32x4,
    mut batch: impl FnMut(&[Ray4]) -> f32x4,
) {
    let packed = pack(rays);
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(rays.len() as u64));
    g.bench_function(BenchmarkId::new("reference", "per-ray"), |b| {
        b.iter(|| {
            let mut acc = 0.0f32;
            for r in rays {
                acc += black_box(scalar(black_box(r), &prim)).unwrap_or(0.0);
            }
            acc
        })
    });
    g.bench_function(BenchmarkId::new("reference", "slice"), |b| {
        b.iter(|| {
            black_box(rays)
                .iter()
                .map(|r| scalar(r, &prim).unwrap_or(0.0))
                .sum::<f32>()
        })
    });
    g.bench_function(BenchmarkId::new("x4", "packed"), |b| {
        b.iter(|| {
            let mut acc = f32x4::ZERO;
            for r in black_box(&packed) {
                acc += simd(r);
            }
            acc
        })
    });
    g.bench_function(BenchmarkId::new("x4", "baseline"), |b| {
        b.iter(|| {
            let mut acc = f32x4::ZERO;
            for r in black_box(&packed) {
                acc += base(r);
            }
            acc
        })
    });
    g.bench_function(BenchmarkId::new("x4", "batch"), |b| {
        b.iter(|| batch(black_box(&packed)))
    });
    g.bench_function(BenchmarkId::new("f64", "per-ray"), |b| {
        b.iter(|| {
            let mut acc = 0.0f32;
            for r in rays {
                acc += black_box(baseline(black_box(r), &prim)).unwrap_or(0.0);
            }
            acc
        })
    });
    g.finish();
}

/// parry3d's cast on the same rays, moved into the shape's frame
/// beforehand, one `black_box`ed call per ray.
fn bench_peer<S: parry3d::query::RayCast>(
    c: &mut Criterion,
    name: &str,
    shape: &S,
    local: &[parry3d::query::Ray],
) {
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(local.len() as u64));
    g.bench_function(BenchmarkId::new("parry3d", "per-ray"), |b| {
        b.iter(|| {
            let mut acc = 0.0f32;
            for r in local {
                acc +=
                    black_box(shape.cast_local_ray(black_box(r), f32::MAX, false)).unwrap_or(0.0);
            }
            acc
        })
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

/// The same rays in a seeded random order.
fn shuffled(rays: &[Ray]) -> Vec<Ray> {
    use rand::seq::SliceRandom;
    let mut v = rays.to_vec();
    v.shuffle(&mut SmallRng::seed_from_u64(0x5_4ff1e));
    v
}

fn benches(c: &mut Criterion) {
    let mut rng = SmallRng::seed_from_u64(0x5eed);
    let rays = rays(&mut rng);
    let (t_min, t_max) = (f32x4::ZERO, f32x4::splat(f32::INFINITY));
    let finite = |m: f32x4, t: f32x4| m.select(t, f32x4::ZERO);

    let s = Sphere::new(Vec3::new(0.3, 0.5, -1.0), 1.2);
    let s4 = sphere::x4::Sphere4::splat(&s);
    let ball = parry3d::shape::Ball::new(s.radius);
    let mut sphere_out = vec![sphere::x4::intersect(&Ray4::splat(rays[0]), &s4); N / 4];
    for (name, rays) in [
        ("sphere", rays.clone()),
        ("sphere-shuffled", shuffled(&rays)),
    ] {
        bench_group(
            c,
            name,
            &rays,
            s,
            |r, s| sphere::reference::intersect(r, s).nearest(0.0, f32::INFINITY),
            |r, s| sphere::plain::intersect(r, s).nearest(0.0, f32::INFINITY),
            |r| {
                let (m, t) = sphere::x4::intersect(r, &s4).nearest(t_min, t_max);
                finite(m, t)
            },
            |r| {
                let (m, t) = sphere::x4::intersect_baseline(r, &s4).nearest(t_min, t_max);
                finite(m, t)
            },
            |packed| {
                sphere::x4::intersect_packets(packed, &s4, &mut sphere_out);
                let mut acc = f32x4::ZERO;
                for h in &sphere_out {
                    let (m, t) = h.nearest(t_min, t_max);
                    acc += finite(m, t);
                }
                acc
            },
        );
        bench_peer(c, name, &ball, &local(&rays, s.center));
    }

    let p = Plane::new(Vec3::new(0.0, -1.0, 0.0), Vec3::new(0.05, 1.0, 0.02));
    let p4 = plane::x4::Plane4::splat(&p);
    let mut plane_out = vec![plane::x4::intersect(&Ray4::splat(rays[0]), &p4); N / 4];
    bench_group(
        c,
        "plane",
        &rays,
        p,
        |r, p| plane::reference::intersect(r, p).nearest(0.0, f32::INFINITY),
        |r, p| plane::plain::intersect(r, p).nearest(0.0, f32::INFINITY),
        |r| {
            let (m, t) = plane::x4::intersect(r, &p4).nearest(t_min, t_max);
            finite(m, t)
        },
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
    let n = p.normal.normalize().to_array();
    let half = parry3d::shape::HalfSpace::new(parry3d::math::Vector::new(n[0], n[1], n[2]));
    bench_peer(c, "plane", &half, &local(&rays, p.point));

    // A one-sheet hyperboloid x² + z² − y² = 0.5, tilted by the mix of terms.
    let q = Quadric::new([1.0, -1.0, 1.0, 0.1, 0.0, 0.05, 0.0, 0.2, 0.0, -0.5]);
    let q4 = quadric::x4::Quadric4::splat(&q);
    let mut quadric_out = vec![quadric::x4::intersect(&Ray4::splat(rays[0]), &q4); N / 4];
    bench_group(
        c,
        "quadric",
        &rays,
        q,
        |r, q| quadric::reference::intersect(r, q).nearest(0.0, f32::INFINITY),
        |r, q| quadric::plain::intersect(r, q).nearest(0.0, f32::INFINITY),
        |r| {
            let (m, t) = quadric::x4::intersect(r, &q4).nearest(t_min, t_max);
            finite(m, t)
        },
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
    let cam = camera();
    let mut g = c.benchmark_group("camera");
    g.throughput(Throughput::Elements(N as u64));
    g.bench_function(BenchmarkId::new("reference", "per-ray"), |b| {
        b.iter(|| {
            let mut acc = 0.0f32;
            for i in 0..N as u32 {
                acc += black_box(cam.ray(black_box(i % 64), i / 64)).dir.x;
            }
            acc
        })
    });
    g.bench_function(BenchmarkId::new("reference", "slice"), |b| {
        b.iter(|| {
            (0..N as u32)
                .map(|i| cam.ray(i % 64, i / 64).dir.x)
                .sum::<f32>()
        })
    });
    g.bench_function(BenchmarkId::new("x4", "packed"), |b| {
        b.iter(|| {
            let mut acc = f32x4::ZERO;
            for i in (0..N as u32).step_by(4) {
                acc += black_box(cam.ray4_row(black_box(i % 64), i / 64)).dir[0];
            }
            acc
        })
    });
    let cam64 = rayoracle::camera::plain::Camera::new(&cam.params).expect("valid camera");
    g.bench_function(BenchmarkId::new("f64", "per-ray"), |b| {
        b.iter(|| {
            let mut acc = 0.0f32;
            for i in 0..N as u32 {
                acc += black_box(cam64.ray(black_box(i % 64), i / 64)).dir.x;
            }
            acc
        })
    });
    g.finish();
}

/// Reads criterion's point estimates back, prints the rates and ratios of
/// this run, and writes them to `target/criterion/ratios.{md,json}`.
fn print_ratios() {
    let base = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("target/criterion");
    let ns = |group: &str, id: &str| -> Option<f64> {
        let path = base.join(group).join(id).join("new/estimates.json");
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
        v["median"]["point_estimate"].as_f64()
    };
    let f = |x: Option<f64>| x.map_or("–".into(), |v| format!("{v:.1}"));
    let r = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => format!("{:.2}×", a / b),
        _ => "–".into(),
    };
    let mut md = String::from(
        "| kernel | rays | reference per-ray | reference slice | x4 | x4 baseline | x4 batch | f64 per-ray | parry3d | x4 ÷ parry3d | x4 batch ÷ parry3d | x4 ÷ f64 | f64 ÷ reference per-ray |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n",
    );
    let mut json = Vec::new();
    for k in ["camera", "plane", "sphere", "sphere-shuffled", "quadric"] {
        let rate = |id: &str| ns(k, id).map(|t| N as f64 / t * 1e3);
        let (pr, sl, x4, base, batch, f64r, peer) = (
            rate("reference/per-ray"),
            rate("reference/slice"),
            rate("x4/packed"),
            rate("x4/baseline"),
            rate("x4/batch"),
            rate("f64/per-ray"),
            rate("parry3d/per-ray"),
        );
        let rays = if k == "sphere-shuffled" {
            "4096 primary rays of a 64×64 camera, shuffled"
        } else {
            "4096 primary rays of a 64×64 camera"
        };
        md += &format!(
            "| {k} | {rays} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} | {} |\n",
            f(pr),
            f(sl),
            f(x4),
            f(base),
            f(batch),
            f(f64r),
            f(peer),
            r(x4, peer),
            r(batch, peer),
            r(x4, f64r),
            r(f64r, pr),
        );
        let mut o = serde_json::json!({
            "kernel": k,
            "rays": rays,
            "reference_per_ray": pr,
            "reference_slice": sl,
            "x4": x4,
            "x4_baseline": base,
            "x4_batch": batch,
            "f64": f64r,
        });
        if let Some(p) = peer {
            o["parry3d"] = serde_json::json!(p);
        }
        json.push(o);
    }
    println!("\nMrays/s, one run:\n\n{md}");
    let _ = std::fs::write(base.join("ratios.md"), md);
    let text = serde_json::to_string_pretty(&json).expect("JSON");
    let _ = std::fs::write(base.join("ratios.json"), text + "\n");
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    benches(&mut c);
    c.final_summary();
    print_ratios();
}
