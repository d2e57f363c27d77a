#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
//! Known-wrong kernels, driven through [`rayoracle::check::gate`] at its
//! default budget (`Gate::new`, what `cargo test` runs): the gate must catch
//! every one of them, and each test says which family catches what.
//!
//! Each bug is modelled on top of a correct kernel, so that the bug is the
//! only thing wrong: the formula slips of common hand derivations are evaluated in `f64`
//! (stably, rounded once), the classic bugs wrap `sphere::plain`,
//! `plane::plain`, the four-lane `sphere::x4` or the reference camera. The
//! correct counterparts run through the same gate with the same declaration
//! and must pass, so the gate is not simply failing everything.
//!
//! Every kernel declares what a careful f32 kernel would
//! ([`Declared::f32`]).
//!
//! More known-wrong kernels, one file a kind, share the helpers here:
//! `known_wrong_sphere.rs`, `known_wrong_plane.rs`,
//! `known_wrong_quadric.rs`, `known_wrong_camera.rs` and
//! `known_wrong_lanes.rs`. Each of their bugs is caught by a whole family
//! ([`assert_family_catches`]), not by one fixture line.

use glam::DVec3;
use rayoracle::camera::{CameraParams, filter};
use rayoracle::case::{Case, parse_line};
use rayoracle::check::gate::{Answer, Declared, Gate, Lanes, Report, Semantics, SphereKernel4};
use rayoracle::plane::{self, Plane, PlaneHit};
use rayoracle::quadric::{self, Quadric, QuadricHit};
use rayoracle::ray4::Ray4;
use rayoracle::sphere::{self, Sphere, SphereHit, x4};
use rayoracle::{Ray, hit::Intersection};

/// The gate every kernel here goes through: the default budget, a careful
/// f32 declaration.
pub(crate) fn gate(semantics: Semantics) -> Gate {
    Gate::new(Declared::f32(semantics))
}

/// Asserts that the gate caught a known-wrong kernel, and that one of
/// `expected` caught it on at least 8 of its cases. Prints the catchers
/// and the first failure, so that `cargo test -- --nocapture` documents
/// which family catches what.
pub(crate) fn assert_caught(kernel: &str, report: &Report, expected: &[&str]) {
    let caught = report.failing_families();
    eprintln!(
        "{kernel}: caught by {} of {} families: {caught:?}",
        caught.len(),
        report.families.len()
    );
    if let Some(f) = report.failures.first() {
        eprintln!("{kernel}: first failure {f}");
    }
    assert!(
        !caught.is_empty(),
        "the gate missed the known-wrong kernel {kernel}; families run: {:?}",
        report.families
    );
    assert!(
        expected.iter().any(|e| caught.contains(e)),
        "{kernel}: none of {expected:?} caught it; the catchers are {caught:?}"
    );
    // Caught by a whole family, not by a line or two: one of the expected
    // families fails on at least 8 of its cases.
    let most = report
        .families
        .iter()
        .filter(|f| expected.contains(&f.0.as_str()))
        .map(|f| f.2)
        .max()
        .unwrap_or(0);
    assert!(
        most >= 8,
        "{kernel}: the expected families {expected:?} fail on at most {most} cases each; families: {:?}",
        report
            .families
            .iter()
            .filter(|f| f.2 > 0)
            .collect::<Vec<_>>()
    );
    // Failures must be reproducible: every one is a parseable eval line.
    for f in &report.failures {
        parse_line(&f.eval_line).unwrap_or_else(|e| panic!("{kernel}: {}: {e}", f.eval_line));
    }
}

/// Asserts that a correct kernel passes, after running at least `min_cases`.
pub(crate) fn assert_passes(kernel: &str, report: &Report, min_cases: usize) {
    eprintln!(
        "{kernel}: {} cases in {} families, no failure",
        report.cases,
        report.families.len()
    );
    report.assert_ok();
    assert!(
        report.cases >= min_cases,
        "{kernel}: only {} cases",
        report.cases
    );
}

/// Asserts that the gate caught a known-wrong kernel with a whole family:
/// `family` ran and failed on at least `min` of its cases (and every kept
/// failure is a parseable eval line).
pub(crate) fn assert_family_catches(kernel: &str, report: &Report, family: &str, min: usize) {
    assert_caught(kernel, report, &[family]);
    let (_, cases, failed) = report
        .families
        .iter()
        .find(|f| f.0 == family)
        .unwrap_or_else(|| panic!("{kernel}: no family {family} in {:?}", report.families));
    eprintln!("{kernel}: {family} fails {failed} of {cases} cases");
    assert!(
        *failed >= min,
        "{kernel}: {family} fails only {failed} of {cases} cases, fewer than {min}"
    );
}

// ---------------------------------------------------------------------------
// The sphere in f64: the helper the derivation slips are built on.

/// The sphere's inputs in `f64`: `f = o − C`, `d`, `R`, `a = d·d`,
/// `b = f·d` (half the linear coefficient) and `|a f − b d|²`, which is
/// `a(f·f) − b²` without the cancellation (Lagrange's identity).
pub(crate) struct Terms {
    pub(crate) a: f64,
    pub(crate) b: f64,
    pub(crate) ff: f64,
    pub(crate) r2: f64,
    pub(crate) perp2: f64,
}

pub(crate) fn terms(ray: &Ray, s: &Sphere) -> Terms {
    let f: DVec3 = ray.origin.as_dvec3() - s.center.as_dvec3();
    let d: DVec3 = ray.dir.as_dvec3();
    let (a, b) = (d.dot(d), f.dot(d));
    let r = f64::from(s.radius);
    Terms {
        a,
        b,
        ff: f.dot(f),
        r2: r * r,
        perp2: (a * f - b * d).length_squared(),
    }
}

/// Solves `a t² + 2b t + c = 0` as `sphere::plain` does (RTG ch. 7):
/// `disc` is `a(b² − ac)`, `q = −(b + sign(b)·√(disc/a))`, `t₀ = c/q`,
/// `t₁ = q/a`, sorted, each rounded once. `sqrt` is the square root the
/// kernel uses.
pub(crate) fn solve(a: f64, b: f64, c: f64, disc: f64, sqrt: impl Fn(f64) -> f64) -> SphereHit {
    if a == 0.0 || disc.is_nan() || disc < 0.0 {
        SphereHit::None
    } else if disc == 0.0 {
        SphereHit::Tangent((-b / a) as f32)
    } else {
        let q = -(b + sqrt(disc / a).copysign(b));
        let (t0, t1) = (c / q, q / a);
        let (t0, t1) = if t0 > t1 { (t1, t0) } else { (t0, t1) };
        SphereHit::Two(t0 as f32, t1 as f32)
    }
}

/// The correct sphere through [`solve`]: `c = f·f − R²`,
/// `disc = (aR)² − |af − bd|²`. A control: the helper the derivation slips are
/// built on is not itself what the gate catches.
pub(crate) fn helper_sphere(ray: &Ray, s: &Sphere) -> Answer {
    let t = terms(ray, s);
    let disc = t.a * t.a * t.r2 - t.perp2;
    Answer::roots(solve(t.a, t.b, t.ff - t.r2, disc, f64::sqrt))
}

/// The sphere's discriminant without `d·d` on `R²`: `t = (−d·f ± √M)/d²` with
/// `M = (d·f)² − d²(f·f) + R²`, where `R²` should have been multiplied by
/// `d²` too (`M = (d·f)² − d²(f·f − R²)`). Evaluated stably in `f64`
/// (`M = R² − |af − bd|²/a`, product of the roots `(a(f·f) − R²)/a²`), so
/// only the slip is wrong. Exact for `|d| = 1`: only cases with non-unit
/// directions can catch it.
fn seed_sphere_r2_unscaled(ray: &Ray, s: &Sphere) -> Answer {
    let t = terms(ray, s);
    // a·M and c with a·c = a(f·f) − R²: the slip in the normalised form.
    let disc = t.a * t.r2 - t.perp2;
    Answer::roots(solve(t.a, t.b, t.ff - t.r2 / t.a, disc, f64::sqrt))
}

/// The sphere as a quadric, solved by hand: `t = ((o − C)·d ± √…)/d²`, the sign of the
/// linear term flipped (the other common slip there, `− R²` under the root,
/// is left out so this one is seen alone). The roots come out mirrored,
/// `−t₁` and `−t₀`: the renderer hits spheres behind it and misses those in
/// front.
fn seed_sphere_sign_flipped(ray: &Ray, s: &Sphere) -> Answer {
    let mirrored = match sphere::plain::intersect(ray, s) {
        SphereHit::None => SphereHit::None,
        SphereHit::Tangent(t) => SphereHit::Tangent(-t),
        SphereHit::Two(t0, t1) => SphereHit::Two(-t1, -t0),
    };
    Answer::nearest(mirrored, 0.0)
}

/// A case analysis by the roots' signs: a hit only when both roots are positive
/// ("`M > 0 ∧ t₁ > 0 ∧ t₂ > 0`"), so an origin inside the sphere (one root
/// behind, one ahead) sees nothing.
fn seed_sphere_ignores_inside(ray: &Ray, s: &Sphere) -> Answer {
    Answer::Nearest(match sphere::plain::intersect(ray, s) {
        SphereHit::None => None,
        SphereHit::Tangent(t) => (t > 0.0).then_some(t),
        SphereHit::Two(t0, t1) => (t0 > 0.0 && t1 > 0.0).then_some(t0),
    })
}

/// The classic "t < 0 accepted": the nearest root of the line, not of the
/// ray, so the renderer sees spheres behind the camera, and the back face
/// of a sphere it is inside.
fn sphere_accepts_negative_t(ray: &Ray, s: &Sphere) -> Answer {
    let roots = sphere::plain::intersect(ray, s).roots();
    Answer::Nearest(roots.as_slice().first().copied())
}

/// Roots returned unsorted: the far root first (the `+√` branch computed
/// first and never swapped).
fn sphere_unsorted(ray: &Ray, s: &Sphere) -> Answer {
    match sphere::plain::intersect(ray, s) {
        SphereHit::Two(t0, t1) => Answer::Roots(vec![t1, t0]),
        h => Answer::roots(h),
    }
}

/// `√x` as `x · rsqrt(x)`, with a fast inverse square root: the magic
/// constant and `steps` Newton steps (relative error up to about
/// `1.75·10⁻³`, 9 bits, after one; about `5·10⁻⁶`, 17 bits, after two).
fn approx_sqrt(x: f64, steps: u32) -> f64 {
    let xf = x as f32;
    let mut y = f32::from_bits(0x5f37_59df - (xf.to_bits() >> 1));
    for _ in 0..steps {
        y *= 1.5 - 0.5 * xf * y * y;
    }
    x * f64::from(y)
}

/// The correct f64 sphere except that `√disc` is an approximate rsqrt with
/// `STEPS` Newton steps: the class is right and the roots are off by
/// hundreds of ulps (one step) or tens (two), which only the bit budget can
/// see.
fn sphere_approx_rsqrt<const STEPS: u32>(ray: &Ray, s: &Sphere) -> Answer {
    let t = terms(ray, s);
    let disc = t.a * t.a * t.r2 - t.perp2;
    Answer::roots(solve(t.a, t.b, t.ff - t.r2, disc, |x| {
        approx_sqrt(x, STEPS)
    }))
}

// ---------------------------------------------------------------------------
// Four lanes.

/// rayoracle's own four-lane sphere (bit-identical to the reference), with
/// the lanes' inputs gathered through `gather`: lane `i` computes the case
/// in lane `gather[i]`. Output lane `j` is then computed lane `scatter[j]`.
struct Packet {
    gather: [usize; 4],
    scatter: [usize; 4],
}

impl SphereKernel4 for Packet {
    fn intersect4(&self, rays: &[Ray; 4], spheres: &[Sphere; 4]) -> [Answer; 4] {
        let r = Ray4::from_rays(self.gather.map(|i| rays[i]));
        let s = x4::Sphere4::from_spheres(self.gather.map(|i| spheres[i]));
        let lanes = x4::intersect(&r, &s).lanes();
        self.scatter.map(|i| Answer::roots(lanes[i]))
    }
}

/// The correct four-lane kernel: identity gather and scatter.
const X4_CORRECT: Packet = Packet {
    gather: [0, 1, 2, 3],
    scatter: [0, 1, 2, 3],
};

/// Swapped lanes: the results of lanes 1 and 2 are stored to each other's
/// slots (a wrong shuffle in the epilogue).
const X4_SWAPPED: Packet = Packet {
    gather: [0, 1, 2, 3],
    scatter: [0, 2, 1, 3],
};

/// A garbage tail lane: the gather clamps its index to 2 (an off-by-one in
/// the tail handling), so lane 3 computes lane 2's case and returns that
/// result, stale for lane 3's own ray.
const X4_GARBAGE_TAIL: Packet = Packet {
    gather: [0, 1, 2, 2],
    scatter: [0, 1, 2, 3],
};

// ---------------------------------------------------------------------------
// Plane and quadric.

/// A plane kernel without the in-plane case: `d·n = 0` is always
/// "parallel, no hit", even when the ray lies in the plane (the usual derivation's
/// first case dropped). Whole-line semantics, so the gate expects every `t`.
fn plane_no_in_plane(ray: &Ray, p: &Plane) -> Answer {
    match plane::plain::intersect(ray, p) {
        PlaneHit::InPlane => Answer::roots(PlaneHit::Parallel),
        h => Answer::roots(h),
    }
}

/// The textbook quadric root formula `t = −β/2α ± √(β²/4α² − γ/α)`, applied even
/// when `α = 0` (a ray parallel to a cylinder's axis, along a paraboloid's),
/// where it divides by zero and gives NaN or ∞ instead of the linear root
/// `−γ/β`. α, β and γ are exact (rayoracle's exact expansion) rounded to
/// `f64`, so the missing guard is what is wrong.
fn seed_quadric_no_alpha_guard(ray: &Ray, q: &Quadric) -> Answer {
    let Ok(eq) = quadric::exact::quadratic(ray, q) else {
        return Answer::Roots(vec![]);
    };
    let (alpha, beta, gamma) = (eq.alpha.to_f64(), eq.beta.to_f64(), eq.gamma.to_f64());
    let h = -beta / (2.0 * alpha);
    let disc = beta * beta / (4.0 * alpha * alpha) - gamma / alpha;
    Answer::roots(if disc < 0.0 {
        QuadricHit::None
    } else if disc == 0.0 {
        QuadricHit::One(h as f32)
    } else {
        let s = disc.sqrt();
        QuadricHit::Two((h - s) as f32, (h + s) as f32)
    })
}

// ---------------------------------------------------------------------------
// Camera.

/// The reference camera's basis with the pixel offsets `(u, v)` computed by
/// `offsets` (from `res` and the pixel), then `(dir + u·x) + v·y` as the
/// reference does it.
pub(crate) fn camera_with(
    p: &CameraParams,
    px: [u32; 2],
    offsets: impl Fn([u32; 2], [u32; 2]) -> (f32, f32),
) -> Option<Ray> {
    let cam = p.build().ok()?;
    let (u, v) = offsets(p.res, px);
    let (f, x, y) = (p.dir, cam.x, cam.y);
    let d = [0, 1, 2].map(|i| (f[i] + u * x[i]) + v * y[i]);
    Some(Ray::new(p.position, glam::Vec3::from_array(d)))
}

/// The correct camera, as the brief's control.
pub(crate) fn camera_correct(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    p.build().ok().map(|c| c.ray(px[0], px[1]))
}

/// An x-for-y mix-up: `v = 2((Y + ½)/resX − ½)`, `resX` where `resY`
/// belongs. Invisible for square images.
fn camera_res_x_for_y(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    camera_with(p, px, |res, px| {
        (filter::offset(px[0], res[0]), filter::offset(px[1], res[0]))
    })
}

/// The half-pixel offset dropped: `2(X/res − ½)` instead of
/// `2((X + ½)/res − ½)`, every ray through a pixel's corner.
fn camera_no_half_pixel(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    let corner = |x: u32, r: u32| (2 * i64::from(x) - i64::from(r)) as f32 / r as f32;
    camera_with(p, px, |res, px| {
        (corner(px[0], res[0]), corner(px[1], res[1]))
    })
}

/// A camera that checks only for zero vectors: an up vector parallel to
/// the view direction, or a field of view outside `(0, π)`, goes through
/// (here as the ray along `dir`) where it must be refused.
fn camera_unchecked(p: &CameraParams, px: [u32; 2]) -> Option<Ray> {
    use rayoracle::camera::CameraError::{AngleOutOfRange, DirParallelToUp};
    match p.build() {
        Ok(c) => Some(c.ray(px[0], px[1])),
        Err(DirParallelToUp | AngleOutOfRange(_)) => Some(Ray::new(p.position, p.dir)),
        Err(_) => None,
    }
}

// ---------------------------------------------------------------------------
// The controls: the correct counterparts pass the same gate.

#[test]
fn controls_pass() {
    use Semantics::{NearestPositive, WholeLine};
    let nearest = |ray: &Ray, s: &Sphere| Answer::nearest(sphere::plain::intersect(ray, s), 0.0);
    let whole = |ray: &Ray, s: &Sphere| Answer::roots(sphere::plain::intersect(ray, s));
    let plane = |ray: &Ray, p: &Plane| Answer::roots(plane::plain::intersect(ray, p));
    let quadric = |ray: &Ray, q: &Quadric| Answer::roots(quadric::plain::intersect(ray, q));
    // Floors well below today's counts (about 2800, 1300, 2800, 1300): the
    // point is that the gate ran its families, not their exact sizes.
    let runs = [
        (
            "sphere::plain, nearest",
            gate(NearestPositive).sphere(&nearest),
            1000,
        ),
        (
            "sphere::plain, whole line",
            gate(WholeLine).sphere(&whole),
            1000,
        ),
        (
            "the f64 helper",
            gate(WholeLine).sphere(&helper_sphere),
            1000,
        ),
        (
            "sphere::x4 through Lanes",
            gate(WholeLine).sphere(&Lanes(X4_CORRECT)),
            1000,
        ),
        ("plane::plain", gate(WholeLine).plane(&plane), 500),
        ("quadric::plain", gate(WholeLine).quadric(&quadric), 1000),
        (
            "the reference camera",
            gate(WholeLine).camera(&camera_correct),
            500,
        ),
    ];
    for (kernel, report, min_cases) in &runs {
        assert_passes(kernel, report, *min_cases);
    }
}

// ---------------------------------------------------------------------------
// Hand derivations, literally.

#[test]
fn seed_sphere_r2_unscaled_is_caught_by_non_unit_directions() {
    let report = gate(Semantics::WholeLine).sphere(&seed_sphere_r2_unscaled);
    assert_caught(
        "sphere: R² not times d·d",
        &report,
        &["sphere/dir-scale", "sphere/dir-tiny", "sphere/dir-huge"],
    );
    // Every failure, shrunk, still has |d| ≠ 1.
    for f in &report.failures {
        let Case::Sphere(ray, _) = parse_line(&f.eval_line).unwrap().case else {
            panic!("not a sphere case: {}", f.eval_line);
        };
        let dd = ray.dir.as_dvec3().length_squared();
        assert_ne!(dd, 1.0, "{f}");
    }
}

#[test]
fn seed_sphere_sign_flipped_is_caught() {
    let report = gate(Semantics::NearestPositive).sphere(&seed_sphere_sign_flipped);
    assert_caught(
        "sphere as quadric: sign of (o−C)·d flipped",
        &report,
        &["sphere/two", "sphere/sphere-behind", "sphere/random/aimed"],
    );
}

#[test]
fn seed_quadric_formula_is_caught_near_alpha_zero() {
    let report = gate(Semantics::WholeLine).quadric(&seed_quadric_no_alpha_guard);
    // −β/2α + √… cancels for a tiny α, even in f64.
    assert_caught(
        "quadric formula, α ≈ 0",
        &report,
        &[
            "quadric/alpha-near-zero-paraboloid",
            "quadric/alpha-near-zero",
        ],
    );
}

/// The missing guard itself: at `α = 0` the kernel answers two NaN roots
/// where there is one root, none, or every `t`. The gate catches it on the
/// small-integer cases, where it requires exact degenerate classes.
#[test]
fn seed_quadric_no_alpha_guard_is_caught_by_alpha_zero() {
    let report = gate(Semantics::WholeLine).quadric(&seed_quadric_no_alpha_guard);
    assert_caught(
        "quadric formula, no α = 0 guard",
        &report,
        &[
            "quadric/alpha-zero-cylinder",
            "quadric/alpha-zero-paraboloid",
            "quadric/alpha-zero-linear",
        ],
    );
}

/// The same kernel answers two NaN roots on every case of
/// `quadric/alpha-zero-paraboloid` (exactly one finite root each). α = 0 is
/// inside the gate's α band, which excuses a root count, but never a NaN:
/// every case of the family fails. (This was a gap in the gate, found by
/// this test; the gate now rejects NaN roots everywhere.)
#[test]
fn nan_roots_fail_on_every_alpha_zero_case() {
    let report = gate(Semantics::WholeLine).quadric(&seed_quadric_no_alpha_guard);
    let (_, cases, failed) = report
        .families
        .iter()
        .find(|f| f.0 == "quadric/alpha-zero-paraboloid")
        .expect("the family runs")
        .clone();
    assert_eq!(failed, cases, "{:?}", report.families);
}

#[test]
fn seed_sphere_ignores_inside_is_caught_by_origin_inside() {
    let report = gate(Semantics::NearestPositive).sphere(&seed_sphere_ignores_inside);
    assert_caught(
        "sphere case analysis, hit iff both roots > 0",
        &report,
        &["sphere/origin-inside", "sphere/random/inside"],
    );
}

/// Caught on the in-plane lines in small integers (`plane/random/in-plane`),
/// where the gate requires the exact degenerate class.
#[test]
fn plane_no_in_plane_is_caught_by_in_plane() {
    let report = gate(Semantics::WholeLine).plane(&plane_no_in_plane);
    assert_caught(
        "plane without the in-plane case",
        &report,
        &["plane/in-plane", "plane/random/in-plane"],
    );
}

// ---------------------------------------------------------------------------
// Classic bugs.

#[test]
fn negative_t_is_caught_by_origin_inside_and_behind() {
    let report = gate(Semantics::NearestPositive).sphere(&sphere_accepts_negative_t);
    assert_caught(
        "t < 0 accepted",
        &report,
        &[
            "sphere/origin-inside",
            "sphere/sphere-behind",
            "sphere/random/inside",
        ],
    );
}

#[test]
fn unsorted_roots_are_caught() {
    let report = gate(Semantics::WholeLine).sphere(&sphere_unsorted);
    assert_caught(
        "roots unsorted",
        &report,
        &["sphere/two", "sphere/random/aimed", "sphere/origin-inside"],
    );
}

#[test]
fn swapped_lanes_are_caught_through_lanes() {
    let report = gate(Semantics::WholeLine).sphere(&Lanes(X4_SWAPPED));
    assert_caught(
        "lanes 1 and 2 swapped",
        &report,
        &["sphere/two", "sphere/random/aimed", "sphere/origin-inside"],
    );
}

#[test]
fn garbage_tail_lane_is_caught_through_lanes() {
    let report = gate(Semantics::WholeLine).sphere(&Lanes(X4_GARBAGE_TAIL));
    assert_caught(
        "garbage lane 3",
        &report,
        &["sphere/two", "sphere/random/aimed", "sphere/origin-inside"],
    );
}

#[test]
fn camera_res_x_for_y_is_caught_by_non_square_images() {
    let report = gate(Semantics::WholeLine).camera(&camera_res_x_for_y);
    assert_caught(
        "camera resX for resY",
        &report,
        &["camera/random/any", "camera/fov-range", "camera/res-65535"],
    );
}

#[test]
fn camera_no_half_pixel_is_caught() {
    let report = gate(Semantics::WholeLine).camera(&camera_no_half_pixel);
    assert_caught(
        "camera half-pixel offset dropped",
        &report,
        &["camera/basic", "camera/centre", "camera/random/any"],
    );
}

#[test]
fn camera_unchecked_is_caught_by_invalid_parameters() {
    let report = gate(Semantics::WholeLine).camera(&camera_unchecked);
    assert_caught(
        "camera accepting dir ∥ up and any angle",
        &report,
        &["camera/invalid"],
    );
    let why = |f: &str| report.failures.iter().any(|x| x.family == f);
    assert!(why("camera/error-parallel-up") && why("camera/error-angle"));
    for f in &report.failures {
        assert_eq!(f.why, "the camera must refuse these parameters", "{f}");
    }
}

#[test]
fn approx_rsqrt_is_caught_by_the_bit_budget() {
    let one_step = gate(Semantics::WholeLine).sphere(&sphere_approx_rsqrt::<1>);
    assert_caught(
        "approximate rsqrt, one Newton step",
        &one_step,
        &["sphere/two", "sphere/random/aimed", "sphere/random/inside"],
    );
    // Two steps leave about 17 bits: still caught, by the families whose
    // roots are well conditioned enough for a tight bound.
    let two_steps = gate(Semantics::WholeLine).sphere(&sphere_approx_rsqrt::<2>);
    assert_caught(
        "approximate rsqrt, two Newton steps",
        &two_steps,
        &[
            "sphere/origin-inside",
            "sphere/random/inside",
            "sphere/dir-scale",
        ],
    );
    // Caught on the roots' ulps, never on the class.
    for f in one_step.failures.iter().chain(&two_steps.failures) {
        assert!(f.why.contains("ulps"), "{f}");
    }
}

// ---------------------------------------------------------------------------
// Failures are reproducible.

#[test]
fn assert_ok_panics_with_a_parseable_eval_line() {
    let report = gate(Semantics::WholeLine)
        .budget(16)
        .sphere(&sphere_unsorted);
    let panic = std::panic::catch_unwind(|| report.assert_ok()).expect_err("a failing kernel");
    let msg = panic
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| panic.downcast_ref::<&str>().map(|s| s.to_string()))
        .expect("a text panic");
    let line = msg
        .lines()
        .find_map(|l| l.trim_start().strip_prefix("eval: "))
        .unwrap_or_else(|| panic!("no eval line in {msg}"));
    let parsed = parse_line(line).unwrap_or_else(|e| panic!("{line}: {e}"));
    // The eval line reproduces the failure: the kernel still answers it
    // unsorted.
    let Case::Sphere(ray, s) = parsed.case else {
        panic!("not a sphere case: {line}");
    };
    let Answer::Roots(r) = sphere_unsorted(&ray, &s) else {
        panic!("whole-line kernel");
    };
    assert!(r.len() == 2 && r[0] > r[1], "{line}: {r:?}");
}
