//! parry3d's ray casts, wrapped as rayoracle kernels and surveyed against
//! the exact oracle.
//!
//! * [`ball_local`]: `Ball::cast_local_ray` on the ray moved into the
//!   ball's frame (`o − C` in f32, as a caller must do).
//! * [`ball_posed`]: `Ball::cast_ray` with the pose translated to `C`
//!   (parry3d forms `o − C` itself).
//! * [`halfspace_local`]: `HalfSpace::cast_local_ray` on the ray moved to
//!   the plane's point, with the normal normalised in f32 (the constructor
//!   asks for a unit normal).
//!
//! All three are called with `solid = false` and `max_time_of_impact =
//! f32::MAX`, and answer the nearest `t > 0`, as parry3d documents:
//! from an origin inside the ball it returns the exit point (the far
//! root), not 0 (which `solid = true` would give).
//!
//! [`careful_ball`] is parry3d's ball code with one change, the
//! discriminant formed as `R² − |f − (f·d)d/|d|²|²` (Ray Tracing Gems
//! ch. 7, eq. 7.5) instead of `b² − ac`, still plain f32: the patch the
//! survey suggests.

use glam::Vec3;
use parry3d::math::{Pose, Vector};
use parry3d::query::{Ray as PRay, RayCast};
use parry3d::shape::{Ball, HalfSpace};
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use rayoracle::Ray;
use rayoracle::case::Case;
use rayoracle::check::gate::survey::FamilyStats;
use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
use rayoracle::hit::Intersection;
use rayoracle::plane::{self, Plane};
use rayoracle::sphere::{self, Sphere};

/// parry3d keeps a hit only if `t ≤ max_time_of_impact`. `f32::MAX`, not
/// infinity: with infinity, a ray parallel to a half-space (`t = ±∞`)
/// would come back as a hit at `t = ∞`.
pub const MAX_TOI: f32 = f32::MAX;

fn v(x: Vec3) -> Vector {
    Vector::new(x.x, x.y, x.z)
}

/// `Ball::cast_local_ray` on the ray in the ball's frame.
///
/// ```
/// use parry3d_gate::ball_local;
/// use glam::Vec3;
/// use rayoracle::{Ray, sphere::Sphere};
/// let s = Sphere::new(Vec3::new(0.0, 0.0, 5.0), 1.0);
/// assert_eq!(ball_local(&Ray::new(Vec3::ZERO, Vec3::Z), &s), Some(4.0));
/// // From inside: the exit point, not 0.
/// assert_eq!(ball_local(&Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::Z), &s), Some(1.0));
/// ```
pub fn ball_local(ray: &Ray, s: &Sphere) -> Option<f32> {
    let local = PRay::new(v(ray.origin - s.center), v(ray.dir));
    Ball::new(s.radius).cast_local_ray(&local, MAX_TOI, false)
}

/// `Ball::cast_ray` with a pose translated to the sphere's center.
///
/// ```
/// use parry3d_gate::ball_posed;
/// use glam::Vec3;
/// use rayoracle::{Ray, sphere::Sphere};
/// let s = Sphere::new(Vec3::new(0.0, 0.0, 5.0), 1.0);
/// assert_eq!(ball_posed(&Ray::new(Vec3::ZERO, Vec3::Z), &s), Some(4.0));
/// ```
pub fn ball_posed(ray: &Ray, s: &Sphere) -> Option<f32> {
    let pose = Pose::from_translation(v(s.center));
    let world = PRay::new(v(ray.origin), v(ray.dir));
    Ball::new(s.radius).cast_ray(&pose, &world, MAX_TOI, false)
}

/// `HalfSpace::cast_local_ray` on the ray moved to the plane's point,
/// the normal normalised.
///
/// ```
/// use parry3d_gate::halfspace_local;
/// use glam::Vec3;
/// use rayoracle::{Ray, plane::Plane};
/// let p = Plane::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, 3.0, 0.0));
/// assert_eq!(halfspace_local(&Ray::new(Vec3::ZERO, Vec3::Y), &p), Some(2.0));
/// ```
pub fn halfspace_local(ray: &Ray, p: &Plane) -> Option<f32> {
    let local = PRay::new(v(ray.origin - p.point), v(ray.dir));
    HalfSpace::new(v(p.normal).normalize()).cast_local_ray(&local, MAX_TOI, false)
}

/// parry3d's `ray_toi_with_ball` with the discriminant of Ray Tracing Gems
/// ch. 7 (eq. 7.5): `a(R² − |f − (b/a)d|²)` instead of `b² − ac`, which
/// keeps the digits `b² − ac` cancels away when `|f| ≫ R`. Everything else
/// (plain f32, the early out, the root formulas) is parry3d's.
///
/// ```
/// use parry3d_gate::careful_ball;
/// use glam::Vec3;
/// use rayoracle::{Ray, sphere::Sphere};
/// let s = Sphere::new(Vec3::new(0.0, 0.0, 5.0), 1.0);
/// assert_eq!(careful_ball(&Ray::new(Vec3::ZERO, Vec3::Z), &s), Some(4.0));
/// ```
pub fn careful_ball(ray: &Ray, s: &Sphere) -> Option<f32> {
    let f = ray.origin - s.center;
    let d = ray.dir;
    let a = d.length_squared();
    let b = f.dot(d);
    let c = f.length_squared() - s.radius * s.radius;
    if a == 0.0 {
        return (c <= 0.0).then_some(0.0);
    }
    if c > 0.0 && b > 0.0 {
        return None;
    }
    // RTG ch. 7, eq. 7.5: the distance from C to the line, squared, is
    // |f − (f·d/d·d) d|²; the discriminant keeps its digits.
    let l = f - d * (b / a);
    let delta = a * (s.radius * s.radius - l.length_squared());
    // Negative or NaN: no real root.
    if delta.is_nan() || delta < 0.0 {
        return None;
    }
    let t = (-b - delta.sqrt()) / a;
    if t <= 0.0 {
        Some((-b + delta.sqrt()) / a)
    } else {
        Some(t)
    }
}

/// What parry3d's casts promise, as the gate should judge them: the
/// nearest `t > 0`, the accuracy of a careful f32 kernel.
pub fn parry_gate() -> Gate {
    Gate::new(Declared::f32(Semantics::NearestPositive))
}

/// What rayoracle's reference promises: correctly rounded, its own band.
pub fn reference_gate() -> Gate {
    Gate::new(Declared::faithful(Semantics::NearestPositive))
}

/// The claim under test: a sphere of radius 1 at distance 1e4 from the
/// ray origin (a random direction), unit rays aimed at a random point of
/// the disc of radius 2 through its center and facing the origin. A ray
/// hits when its aim is within about 1 of the center: a quarter of them.
///
/// ```
/// let cases = parry3d_gate::far_1e4(64, 1);
/// assert_eq!(cases.len(), 64);
/// ```
pub fn far_1e4(n: usize, seed: u64) -> Vec<Case> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let unit = |rng: &mut SmallRng| loop {
        let p = Vec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let l = p.length();
        if l > 0.1 && l <= 1.0 {
            return p / l;
        }
    };
    (0..n)
        .map(|_| {
            let axis = unit(&mut rng);
            let center = axis * 1e4;
            let o = Vec3::new(
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
                rng.random_range(-1.0..1.0),
            );
            // A point of the disc ⟂ axis of radius 2, uniform in area.
            let side = axis.any_orthonormal_pair();
            let (r, phi) = (
                2.0 * rng.random_range(0.0f32..1.0).sqrt(),
                rng.random_range(0.0..std::f32::consts::TAU),
            );
            let aim = center + side.0 * (r * phi.cos()) + side.1 * (r * phi.sin());
            Case::Sphere(Ray::new(o, (aim - o).normalize()), Sphere::new(center, 1.0))
        })
        .collect()
}

/// The name of the claim's family in the survey.
pub const FAR_1E4: &str = "parry3d/far-1e4";

/// Every sphere family the gate runs (fixtures, stiff catalogue, random),
/// then [`far_1e4`] with 4096 rays.
pub fn sphere_families() -> Vec<(String, Vec<Case>)> {
    let mut f = parry_gate().cases("sphere");
    f.push((FAR_1E4.to_string(), far_1e4(4096, 0x1e4)));
    f
}

/// Every plane family the gate runs.
pub fn plane_families() -> Vec<(String, Vec<Case>)> {
    parry_gate().cases("plane")
}

/// One surveyed kernel: its name and its families' numbers.
pub struct Surveyed {
    /// What was surveyed.
    pub kernel: &'static str,
    /// Per family.
    pub stats: Vec<FamilyStats>,
}

/// Surveys parry3d's two ball casts, the careful formula and rayoracle's
/// reference (and x4 path, which gives the same bits) on every sphere
/// family, and the half-space cast and the reference on every plane family.
pub fn survey() -> (Vec<Surveyed>, Vec<Surveyed>) {
    let (spheres, planes) = (sphere_families(), plane_families());
    let (g, ours) = (parry_gate(), reference_gate());
    let sphere_ref = |r: &Ray, s: &Sphere| Answer::nearest(sphere::reference::intersect(r, s), 0.0);
    let plane_ref = |r: &Ray, p: &Plane| Answer::nearest(plane::reference::intersect(r, p), 0.0);
    let s = vec![
        Surveyed {
            kernel: "parry3d Ball::cast_local_ray",
            stats: g.survey_sphere(
                &|r: &Ray, s: &Sphere| Answer::Nearest(ball_local(r, s)),
                &spheres,
            ),
        },
        Surveyed {
            kernel: "parry3d Ball::cast_ray (posed)",
            stats: g.survey_sphere(
                &|r: &Ray, s: &Sphere| Answer::Nearest(ball_posed(r, s)),
                &spheres,
            ),
        },
        Surveyed {
            kernel: "parry3d + RTG ch. 7 discriminant",
            stats: g.survey_sphere(
                &|r: &Ray, s: &Sphere| Answer::Nearest(careful_ball(r, s)),
                &spheres,
            ),
        },
        Surveyed {
            kernel: "rayoracle reference",
            stats: ours.survey_sphere(&sphere_ref, &spheres),
        },
    ];
    let p = vec![
        Surveyed {
            kernel: "parry3d HalfSpace::cast_local_ray",
            stats: g.survey_plane(
                &|r: &Ray, p: &Plane| Answer::Nearest(halfspace_local(r, p)),
                &planes,
            ),
        },
        Surveyed {
            kernel: "rayoracle reference",
            stats: ours.survey_plane(&plane_ref, &planes),
        },
    ];
    (s, p)
}

/// The survey side by side: parry3d's first kernel against the others,
/// one row a family, as `wrong hits / wrong misses`, `max / median ulps`
/// and gate failures.
pub fn side_by_side(kernels: &[&Surveyed]) -> String {
    let mut out = String::from("| family | cases |");
    let mut rule = String::from("|---|---|");
    for k in kernels {
        out += &format!(
            " {}: wrong hits / misses | max / median ulps | gate failures |",
            k.kernel
        );
        rule += "---|---|---|";
    }
    out += "\n";
    out += &rule;
    out += "\n";
    for (i, fam) in kernels[0].stats.iter().enumerate() {
        out += &format!("| {} | {} |", fam.family, fam.cases);
        for k in kernels {
            let s = &k.stats[i];
            let ulps = if s.hits == 0 {
                "–".to_string()
            } else {
                format!("{} / {}", s.max_ulps, s.median_ulps)
            };
            let other = if s.other > 0 {
                format!(" (+{} other)", s.other)
            } else {
                String::new()
            };
            out += &format!(
                " {} / {}{} | {} | {} |",
                s.wrong_hits, s.wrong_misses, other, ulps, s.failures
            );
        }
        out += "\n";
    }
    out
}

/// The families where a surveyed kernel fails the gate.
pub fn failing(s: &Surveyed) -> Vec<&str> {
    s.stats
        .iter()
        .filter(|f| f.failures > 0)
        .map(|f| f.family.as_str())
        .collect()
}

/// On the claim's rays: how many should miss, and how many of those each
/// kernel reports as a hit.
pub fn should_miss(stats: &[FamilyStats]) -> Option<&FamilyStats> {
    stats.iter().find(|f| f.family == FAR_1E4)
}

/// The exact nearest hit of a sphere case, for tests.
pub fn exact_nearest(c: &Case) -> Option<f32> {
    match c {
        Case::Sphere(r, s) => sphere::exact::intersect(r, s)
            .ok()
            .and_then(|h| h.roots().as_slice().iter().copied().find(|&t| t > 0.0)),
        _ => None,
    }
}
