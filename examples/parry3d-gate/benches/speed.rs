//! Rays per second of parry3d's casts against rayoracle's reference and x4
//! paths, on the very rays the survey judged: every sphere family (and,
//! separately, the far-1e4 family), every plane family. One run measures
//! them all, and the ratios of that run are printed at the end.
//!
//! `cargo bench` here. Each scalar kernel is called once per ray through
//! `black_box`, so the optimiser cannot fuse calls across rays (parry3d's
//! and rayoracle's scalar code as written); `reference/slice` is the plain
//! loop LLVM may auto-vectorise; `x4` runs rays already packed four to a
//! `Ray4` against four primitives packed the same way.

use criterion::{BenchmarkId, Criterion, Throughput};
use parry3d_gate::{ball_local, ball_posed, careful_ball, far_1e4, halfspace_local};
use rayoracle::Ray;
use rayoracle::case::Case;
use rayoracle::hit::Intersection;
use rayoracle::plane::{self, Plane, x4::Plane4};
use rayoracle::ray4::Ray4;
use rayoracle::sphere::{self, Sphere, x4::Sphere4};
use std::hint::black_box;
use std::time::Duration;
use wide::f32x4;

fn spheres(cases: &[Case]) -> Vec<(Ray, Sphere)> {
    cases
        .iter()
        .filter_map(|c| match c {
            Case::Sphere(r, s) if sphere::exact::intersect(r, s).is_ok() => Some((*r, *s)),
            _ => None,
        })
        .collect()
}

fn planes(cases: &[Case]) -> Vec<(Ray, Plane)> {
    cases
        .iter()
        .filter_map(|c| match c {
            Case::Plane(r, p) if plane::exact::intersect(r, p).is_ok() => Some((*r, *p)),
            _ => None,
        })
        .collect()
}

/// Rays and primitives packed four to a packet (the tail repeats the last).
fn packed<P: Copy, P4>(items: &[(Ray, P)], pack: impl Fn([P; 4]) -> P4) -> Vec<(Ray4, P4)> {
    items
        .chunks(4)
        .map(|c| {
            let at = |i: usize| c[i.min(c.len() - 1)];
            let four = [at(0), at(1), at(2), at(3)];
            (Ray4::from_rays(four.map(|x| x.0)), pack(four.map(|x| x.1)))
        })
        .collect()
}

/// A scalar kernel: the nearest hit `t > 0`.
type Kernel<P> = fn(&Ray, &P) -> Option<f32>;

fn sum(t: Option<f32>) -> f32 {
    t.filter(|t| t.is_finite()).unwrap_or(0.0)
}

/// One group: each scalar kernel per ray, the reference's slice loop, and
/// the x4 kernel over packets.
fn group<P: Copy, P4>(
    c: &mut Criterion,
    name: &str,
    items: &[(Ray, P)],
    scalar: &[(&str, Kernel<P>)],
    reference: impl Fn(&Ray, &P) -> Option<f32>,
    pack: impl Fn([P; 4]) -> P4,
    x4: impl Fn(&Ray4, &P4) -> (f32x4, f32x4),
) {
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(items.len() as u64));
    for &(id, k) in scalar {
        g.bench_function(BenchmarkId::new(id, "per-ray"), |b| {
            b.iter(|| {
                let mut acc = 0.0f32;
                for (r, p) in items {
                    acc += sum(black_box(k(black_box(r), black_box(p))));
                }
                acc
            })
        });
    }
    // The reference again, as a plain loop the optimiser sees through.
    g.bench_function(BenchmarkId::new("reference", "slice"), |b| {
        b.iter(|| items.iter().map(|(r, p)| sum(reference(r, p))).sum::<f32>())
    });
    let packs = packed(items, pack);
    g.bench_function(BenchmarkId::new("x4", "packed"), |b| {
        b.iter(|| {
            let mut acc = f32x4::ZERO;
            for (r, p) in &packs {
                let (m, t) = x4(black_box(r), black_box(p));
                acc += m.select(t, f32x4::ZERO);
            }
            acc
        })
    });
    g.finish();
}

fn sphere_ref(r: &Ray, s: &Sphere) -> Option<f32> {
    sphere::reference::intersect(r, s).nearest(0.0, f32::INFINITY)
}

fn plane_ref(r: &Ray, p: &Plane) -> Option<f32> {
    plane::reference::intersect(r, p).nearest(0.0, f32::INFINITY)
}

fn sphere_group(c: &mut Criterion, name: &str, items: &[(Ray, Sphere)]) {
    let (lo, hi) = (f32x4::ZERO, f32x4::splat(f32::INFINITY));
    group(
        c,
        name,
        items,
        &[
            ("parry3d-local", ball_local),
            ("parry3d-posed", ball_posed),
            ("careful-f32", careful_ball),
            ("reference", sphere_ref),
        ],
        sphere_ref,
        Sphere4::from_spheres,
        |r, s| sphere::x4::intersect(r, s).nearest(lo, hi),
    );
}

fn plane_group(c: &mut Criterion, items: &[(Ray, Plane)]) {
    let (lo, hi) = (f32x4::ZERO, f32x4::splat(f32::INFINITY));
    group(
        c,
        "planes",
        items,
        &[("parry3d-local", halfspace_local), ("reference", plane_ref)],
        plane_ref,
        Plane4::from_planes,
        |r, p| plane::x4::intersect(r, p).nearest(lo, hi),
    );
}

/// Reads this run's estimates back: Mrays/s per kernel and the ratios to
/// parry3d.
fn print_table(sizes: &[(&str, usize)]) {
    // Where criterion writes: $CRITERION_HOME, else $CARGO_TARGET_DIR/criterion,
    // else the workspace's target directory (examples/survey-kit/target), which
    // criterion too asks `cargo metadata` for.
    let base = std::env::var_os("CRITERION_HOME")
        .map(std::path::PathBuf::from)
        .or_else(|| {
            std::env::var_os("CARGO_TARGET_DIR")
                .map(|t| std::path::PathBuf::from(t).join("criterion"))
        })
        .or_else(|| {
            let out = std::process::Command::new(std::env::var_os("CARGO")?)
                .args(["metadata", "--format-version", "1", "--no-deps"])
                .output()
                .ok()?;
            let text = String::from_utf8(out.stdout).ok()?;
            let key = "\"target_directory\":\"";
            let at = text.find(key)? + key.len();
            let end = text[at..].find('"')?;
            Some(std::path::PathBuf::from(&text[at..at + end]).join("criterion"))
        })
        .unwrap_or_else(|| std::path::PathBuf::from("target/criterion"));
    let ns = |group: &str, id: &str| -> Option<f64> {
        let path = base.join(group).join(id).join("new/estimates.json");
        let text = std::fs::read_to_string(path).ok()?;
        let at = text.find("\"median\"")?;
        let rest = &text[at..];
        let p = rest.find("\"point_estimate\":")? + "\"point_estimate\":".len();
        rest[p..].split([',', '}']).next()?.trim().parse().ok()
    };
    let mut out =
        String::from("| rays | kernel | Mrays/s | ÷ parry3d (local) |\n|---|---|---|---|\n");
    for &(group, n) in sizes {
        let rate = |id: &str| ns(group, id).map(|t| n as f64 / t * 1e3);
        let peer = rate("parry3d-local/per-ray");
        for id in [
            "parry3d-local/per-ray",
            "parry3d-posed/per-ray",
            "careful-f32/per-ray",
            "reference/per-ray",
            "reference/slice",
            "x4/packed",
        ] {
            let Some(r) = rate(id) else { continue };
            let ratio = peer.map_or("–".into(), |p| format!("{:.3}×", r / p));
            out += &format!("| {group} ({n}) | {id} | {r:.1} | {ratio} |\n");
        }
    }
    println!("\n{out}");
    let _ = std::fs::write(base.join("parry3d-speed.md"), out);
}

fn main() {
    let mut c = Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(30)
        .configure_from_args();
    let all: Vec<Case> = parry3d_gate::parry_gate()
        .cases("sphere")
        .into_iter()
        .flat_map(|f| f.1)
        .collect();
    let all = spheres(&all);
    let far = spheres(&far_1e4(4096, 0x1e4));
    let flat: Vec<Case> = parry3d_gate::plane_families()
        .into_iter()
        .flat_map(|f| f.1)
        .collect();
    let pl = planes(&flat);
    sphere_group(&mut c, "spheres-all-families", &all);
    sphere_group(&mut c, "spheres-far-1e4", &far);
    plane_group(&mut c, &pl);
    c.final_summary();
    print_table(&[
        ("spheres-all-families", all.len()),
        ("spheres-far-1e4", far.len()),
        ("planes", pl.len()),
    ]);
}
