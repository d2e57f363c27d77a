//! Whole-frame rendering on one core. Run with `cargo bench --bench render`;
//! the figures of the run are printed at the end (and written to
//! `target/criterion/render.md`).
//!
//! * `frame-1920x1080/{x4,reference}`: the default scene
//!   (`fixtures/scenes/seed.json`: a plane, four spheres, a quadric) at
//!   1920×1080, every channel, through each path.
//! * `leave-out/*`: a sphere-only scene (`rtg7-stress.json`, four spheres)
//!   at 640×480 through x4: the compiled plan with the depth channel only,
//!   the compiled plan with every channel, and the un-specialised
//!   [`Plan::everything`] (every object through a `match` on its kind,
//!   every channel), which is what a renderer that does not compile its
//!   scene pays; and, for scale, the same spheres written as general
//!   quadrics (seed 1.4b), which is what one general kernel for every kind
//!   would run.

mod criterion_dir;

use criterion::{Criterion, Throughput};
use rayoracle::quadric::Quadric;
use rayoracle::render::{Channels, Path, Plan, render};
use rayoracle::scene::{Scene, SceneQuadric};
use rayoracle::sphere::Sphere;
use std::hint::black_box;
use std::time::Duration;

fn scene(name: &str, size: [u32; 2]) -> Scene {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../fixtures/scenes")
        .join(name);
    Scene::load(path)
        .and_then(|s| s.with_size(size))
        .unwrap_or_else(|e| panic!("{e}"))
}

const FRAME: [u32; 2] = [1920, 1080];
const LEAVE_OUT: [u32; 2] = [640, 480];

fn benches(c: &mut Criterion) {
    let seed = scene("seed.json", FRAME);
    let plan = Plan::compile(&seed, Channels::ALL).unwrap();
    let mut g = c.benchmark_group("frame-1920x1080");
    g.throughput(Throughput::Elements(u64::from(FRAME[0] * FRAME[1])));
    g.sample_size(10).measurement_time(Duration::from_secs(15));
    for path in [Path::X4, Path::Reference] {
        g.bench_function(path.name(), |b| b.iter(|| render(black_box(&plan), path)));
    }
    g.finish();

    let spheres = scene("rtg7-stress.json", LEAVE_OUT);
    let plans = [
        (
            "plan-depth",
            Plan::compile(&spheres, Channels::DEPTH).unwrap(),
        ),
        ("plan-all", Plan::compile(&spheres, Channels::ALL).unwrap()),
        ("everything", Plan::everything(&spheres).unwrap()),
    ];
    // The same spheres as general quadrics (seed 1.4b), for a renderer that
    // has one general kernel for every kind.
    let mut as_quadrics = spheres.clone();
    as_quadrics.quadrics = spheres
        .spheres
        .iter()
        .map(|s| SceneQuadric {
            id: s.id,
            coeffs: Quadric::from_sphere(&Sphere::new(s.center, s.radius))
                .0
                .coeffs,
        })
        .collect();
    as_quadrics.spheres.clear();
    let mut plans = plans.to_vec();
    plans.push((
        "all-as-quadrics",
        Plan::compile(&as_quadrics, Channels::ALL).unwrap(),
    ));
    let mut g = c.benchmark_group("leave-out");
    g.throughput(Throughput::Elements(u64::from(LEAVE_OUT[0] * LEAVE_OUT[1])));
    g.sample_size(20);
    for (name, plan) in &plans {
        g.bench_function(*name, |b| b.iter(|| render(black_box(plan), Path::X4)));
    }
    g.finish();
}

/// Reads criterion's median estimates back and prints the figures.
fn print_figures() {
    let base = criterion_dir::criterion_dir();
    let ns = |group: &str, id: &str| -> Option<f64> {
        let path = base.join(group).join(id).join("new/estimates.json");
        let v: serde_json::Value =
            serde_json::from_str(&std::fs::read_to_string(path).ok()?).ok()?;
        v["median"]["point_estimate"].as_f64()
    };
    let mrays =
        |group: &str, id: &str, [w, h]: [u32; 2]| ns(group, id).map(|t| f64::from(w * h) / t * 1e3);
    let f = |x: Option<f64>| x.map_or("–".into(), |v| format!("{v:.2}"));
    let r = |a: Option<f64>, b: Option<f64>| match (a, b) {
        (Some(a), Some(b)) => format!("{:.2}×", a / b),
        _ => "–".into(),
    };
    let (x4, rf) = (
        mrays("frame-1920x1080", "x4", FRAME),
        mrays("frame-1920x1080", "reference", FRAME),
    );
    let mut out =
        String::from("| default scene, 1920×1080, all channels, one core | Mrays/s |\n|---|---|\n");
    out += &format!(
        "| x4 | {} |\n| reference | {} |\n| x4 ÷ reference | {} |\n\n",
        f(x4),
        f(rf),
        r(x4, rf)
    );
    let lo = |id: &str| mrays("leave-out", id, LEAVE_OUT);
    let (depth, all, every) = (lo("plan-depth"), lo("plan-all"), lo("everything"));
    out += "| sphere-only scene, 640×480, x4 | Mrays/s | speed-up over `everything` |\n|---|---|---|\n";
    out += &format!(
        "| plan, depth only | {} | {} |\n",
        f(depth),
        r(depth, every)
    );
    out += &format!("| plan, all channels | {} | {} |\n", f(all), r(all, every));
    out += &format!("| everything (un-specialised) | {} | 1.00× |\n", f(every));
    let quad = lo("all-as-quadrics");
    out += &format!(
        "| the spheres as general quadrics, all channels | {} | {} |\n",
        f(quad),
        r(quad, every)
    );
    println!("\n{out}");
    let _ = std::fs::write(base.join("render.md"), out);
}

fn main() {
    let mut c = Criterion::default().configure_from_args();
    benches(&mut c);
    c.final_summary();
    print_figures();
}
