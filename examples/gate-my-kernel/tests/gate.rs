//! Gating my kernels with rayoracle: a few lines per kernel.

use gate_my_kernel::{Rays4, sphere_nearest, sphere_nearest4};
use rayoracle::check::gate::{Answer, Declared, Gate, Lanes, Semantics, SphereKernel4, strategy};
use rayoracle::fuzz::gate as fuzz;
use rayoracle::{Ray, sphere::Sphere};

/// What my kernels promise: the nearest t > 0, careful f32 accuracy.
fn gate() -> Gate {
    Gate::new(Declared::f32(Semantics::NearestPositive))
}

fn scalar(ray: &Ray, s: &Sphere) -> Answer {
    Answer::Nearest(sphere_nearest(ray.origin, ray.dir, s.center, s.radius))
}

#[test]
fn my_scalar_sphere_passes_every_family() {
    let report = gate().sphere(&scalar);
    report.assert_ok();
    assert!(report.families.len() > 20);
}

/// The adapter from rayoracle's rays to my layout.
struct Mine;
impl SphereKernel4 for Mine {
    fn intersect4(&self, rays: &[Ray; 4], spheres: &[Sphere; 4]) -> [Answer; 4] {
        let r = Rays4 {
            ox: rays.map(|r| r.origin.x),
            oy: rays.map(|r| r.origin.y),
            oz: rays.map(|r| r.origin.z),
            dx: rays.map(|r| r.dir.x),
            dy: rays.map(|r| r.dir.y),
            dz: rays.map(|r| r.dir.z),
        };
        sphere_nearest4(&r, spheres.map(|s| s.center), spheres.map(|s| s.radius))
            .map(Answer::Nearest)
    }
}

#[test]
fn my_four_lane_sphere_passes_every_family_in_every_lane() {
    gate().sphere(&Lanes(Mine)).assert_ok();
}

#[test]
fn my_sphere_under_proptest() {
    let mut runner = proptest::test_runner::TestRunner::default();
    let s = strategy::sphere("sphere/random/aimed").unwrap();
    runner
        .run(&s, |(ray, sphere)| {
            gate()
                .judge_sphere(&ray, &sphere, scalar(&ray, &sphere))
                .map_err(|f| proptest::test_runner::TestCaseError::fail(f.to_string()))
        })
        .unwrap();
}

#[test]
fn the_fuzz_helper_accepts_my_kernel_on_a_few_inputs() {
    // In a cargo-fuzz target: fuzz_target!(|data: &[u8]| fuzz::sphere(data, &gate(), &scalar));
    for seed in 0u8..32 {
        let data: Vec<u8> = (0u8..64)
            .map(|i| seed.wrapping_mul(31).wrapping_add(i.wrapping_mul(7)))
            .collect();
        fuzz::sphere(&data, &gate(), &scalar);
    }
}
