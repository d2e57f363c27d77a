//! fyrox-math's ray solvers (fyrox-math 1.0.1, the math of the Fyrox
//! engine), wrapped as rayoracle kernels and surveyed against the exact
//! oracle. Each answers every root on the whole line, so the survey
//! declares [`Semantics::WholeLine`] with a careful f32 kernel's accuracy.
//!
//! * [`sphere_roots`]: `Ray::sphere_intersection`, the textbook
//!   `b² − 4ac` through `fyrox_math::solve_quadratic`;
//! * [`plane_root`]: `Ray::plane_intersection` on
//!   `Plane::from_normal_and_point`;
//! * [`cylinder_roots`]: `Ray::cylinder_intersection` with
//!   `CylinderKind::Infinite`, on the axis-aligned cylinders among
//!   rayoracle's quadrics ([`as_cylinder`]) and on [`cylinder_families`].
//!
//! `IntersectionResult { min, max }` becomes the roots `[min, max]`.

use fyrox_math::plane::Plane as FPlane;
use fyrox_math::ray::{CylinderKind, Ray as FRay};
use nalgebra::Vector3;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use rayoracle::Ray;
use rayoracle::case::Case;
use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
use rayoracle::plane::Plane;
use rayoracle::quadric::Quadric;
use rayoracle::sphere::Sphere;
use survey_kit::Surveyed;

fn v3(x: glam::Vec3) -> Vector3<f32> {
    Vector3::new(x.x, x.y, x.z)
}

fn fray(ray: &Ray) -> FRay {
    FRay::new(v3(ray.origin), v3(ray.dir))
}

/// `Ray::sphere_intersection`, as `[min, max]`.
///
/// ```
/// use fyrox_math_gate::sphere_roots;
/// use glam::Vec3;
/// use rayoracle::{Ray, sphere::Sphere};
/// let s = Sphere::new(Vec3::new(0.0, 0.0, 5.0), 1.0);
/// assert_eq!(sphere_roots(&Ray::new(Vec3::ZERO, Vec3::Z), &s), Some([4.0, 6.0]));
/// ```
pub fn sphere_roots(ray: &Ray, s: &Sphere) -> Option<[f32; 2]> {
    let r = fray(ray).sphere_intersection(&v3(s.center), s.radius)?;
    Some([r.min, r.max])
}

/// `Ray::plane_intersection` on `Plane::from_normal_and_point(n, p)`:
/// `None` where the constructor refuses the normal (`|n| ≤ f32::EPSILON`).
///
/// ```
/// use fyrox_math_gate::plane_root;
/// use glam::Vec3;
/// use rayoracle::{Ray, plane::Plane};
/// let p = Plane::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.0, 3.0, 0.0));
/// assert_eq!(plane_root(&Ray::new(Vec3::ZERO, Vec3::Y), &p), Some(2.0));
/// ```
pub fn plane_root(ray: &Ray, p: &Plane) -> Option<f32> {
    let plane = FPlane::from_normal_and_point(&v3(p.normal), &v3(p.point))?;
    Some(fray(ray).plane_intersection(&plane))
}

/// An infinite cylinder: a point of its axis, the axis (0, 1 or 2 for x,
/// y, z) and the radius.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylinder {
    /// The axis passes through this point.
    pub point: glam::Vec3,
    /// The coordinate axis it is parallel to.
    pub axis: usize,
    /// The radius.
    pub radius: f32,
}

/// `Ray::cylinder_intersection(pa, pb, r, CylinderKind::Infinite)` with
/// `pa` the axis point and `pb` one unit along the axis, as `[min, max]`.
///
/// ```
/// use fyrox_math_gate::{Cylinder, cylinder_roots};
/// use glam::Vec3;
/// use rayoracle::Ray;
/// let c = Cylinder { point: Vec3::ZERO, axis: 2, radius: 1.0 };
/// let r = Ray::new(Vec3::new(-3.0, 0.0, 7.0), Vec3::X);
/// assert_eq!(cylinder_roots(&r, &c), Some([2.0, 4.0]));
/// ```
pub fn cylinder_roots(ray: &Ray, c: &Cylinder) -> Option<[f32; 2]> {
    let pa = v3(c.point);
    let mut pb = pa;
    pb[c.axis] += 1.0;
    let r = fray(ray).cylinder_intersection(&pa, &pb, c.radius, CylinderKind::Infinite)?;
    Some([r.min, r.max])
}

/// The quadric `Σ_{i≠axis} (xᵢ − pᵢ)² − r² = 0` of a cylinder, if every
/// coefficient is exact in f32.
///
/// ```
/// use fyrox_math_gate::{Cylinder, as_cylinder, to_quadric};
/// use glam::Vec3;
/// let c = Cylinder { point: Vec3::new(1.0, 2.0, 0.0), axis: 2, radius: 1.5 };
/// let q = to_quadric(&c).unwrap();
/// assert_eq!(q.coeffs, [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, -2.0, -4.0, 0.0, 2.75]);
/// assert_eq!(as_cylinder(&q), Some(c));
/// ```
pub fn to_quadric(c: &Cylinder) -> Option<Quadric> {
    let mut k = [0f32; 10];
    let mut j = -f64::from(c.radius).powi(2);
    for i in (0..3).filter(|&i| i != c.axis) {
        let p = f64::from(c.point[i]);
        k[i] = 1.0;
        k[6 + i] = (-2.0 * p) as f32;
        j += p * p;
        if f64::from(k[6 + i]) != -2.0 * p {
            return None;
        }
    }
    k[9] = j as f32;
    (f64::from(k[9]) == j).then_some(Quadric::new(k))
}

/// The cylinder a quadric is, if it is an axis-aligned circular cylinder
/// with unit square terms whose axis point and radius are exact in f32.
pub fn as_cylinder(q: &Quadric) -> Option<Cylinder> {
    let k = q.coeffs;
    let axis = (0..3).find(|&i| k[i] == 0.0)?;
    let others = (0..3).filter(|&i| i != axis);
    if others.clone().any(|i| k[i] != 1.0) || k[3..6] != [0.0; 3] || k[6 + axis] != 0.0 {
        return None;
    }
    let mut point = glam::Vec3::ZERO;
    let mut r2 = -f64::from(k[9]);
    for i in others {
        point[i] = -k[6 + i] / 2.0;
        r2 += f64::from(point[i]).powi(2);
    }
    let c = Cylinder {
        point,
        axis,
        radius: r2.sqrt() as f32,
    };
    (r2 > 0.0 && to_quadric(&c) == Some(*q)).then_some(c)
}

/// The cylinder families: seeded random z-axis cylinders (axis points and
/// radii multiples of 1/64, so the quadric is exact) with
///
/// * `fyrox/cylinder-aimed`: rays aimed near the axis (about half hit);
/// * `fyrox/cylinder-parallel`: rays exactly parallel to the axis (no
///   root, or every `t` on the surface);
/// * `fyrox/cylinder-near-parallel`: rays from inside, within 1e-3 of
///   the axis direction (two roots, hundreds of radii away);
/// * `fyrox/cylinder-far`: a unit cylinder 8192 to 16376 away, rays from
///   within 1 of the origin aimed within 2 of its axis (about half hit).
///
/// ```
/// let f = fyrox_math_gate::cylinder_families(8, 1);
/// assert_eq!(f.len(), 4);
/// assert!(f.iter().all(|(_, cases)| cases.len() == 8));
/// ```
pub fn cylinder_families(n: usize, seed: u64) -> Vec<(String, Vec<Case>)> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let grid = |rng: &mut SmallRng, lo: i32, hi: i32| rng.random_range(lo..=hi) as f32 / 64.0;
    let mut fams: Vec<(String, Vec<Case>)> = [
        "fyrox/cylinder-aimed",
        "fyrox/cylinder-parallel",
        "fyrox/cylinder-near-parallel",
        "fyrox/cylinder-far",
    ]
    .iter()
    .map(|f| (f.to_string(), Vec::new()))
    .collect();
    while fams[0].1.len() < n {
        let c = Cylinder {
            point: glam::Vec3::new(grid(&mut rng, -512, 512), grid(&mut rng, -512, 512), 0.0),
            axis: 2,
            radius: grid(&mut rng, 16, 256),
        };
        let q = to_quadric(&c).expect("exact by construction");
        let v = |rng: &mut SmallRng, s: f32| {
            glam::Vec3::new(
                rng.random_range(-s..s),
                rng.random_range(-s..s),
                rng.random_range(-s..s),
            )
        };
        let o = c.point + v(&mut rng, 30.0);
        let aim = c.point + v(&mut rng, 1.5 * c.radius) - o;
        fams[0].1.push(Case::Quadric(Ray::new(o, aim), q));
        let z = if rng.random_bool(0.5) { 1.0 } else { -1.0 };
        let parallel = glam::Vec3::new(0.0, 0.0, z * rng.random_range(0.1..10.0));
        fams[1].1.push(Case::Quadric(Ray::new(o, parallel), q));
        let tilt = v(&mut rng, 1e-3);
        let near = glam::Vec3::new(tilt.x, tilt.y, z);
        let inside = c.point + v(&mut rng, 0.5 * c.radius) * glam::Vec3::new(1.0, 1.0, 0.0);
        fams[2].1.push(Case::Quadric(Ray::new(inside, near), q));
        // The axis at (8a, 1): J = 64a² + 1 − 1 is exact for a < 2¹².
        let a = rng.random_range(1024..2048) as f32;
        let far = Cylinder {
            point: glam::Vec3::new(8.0 * a, 1.0, 0.0),
            axis: 2,
            radius: 1.0,
        };
        let q = to_quadric(&far).expect("exact by construction");
        let o = v(&mut rng, 1.0);
        let aim = far.point + glam::Vec3::new(0.0, rng.random_range(-2.0..2.0), 0.0) - o;
        fams[3].1.push(Case::Quadric(Ray::new(o, aim), q));
    }
    fams
}

/// What fyrox-math's solvers promise, as the survey judges them: every
/// root on the line, a careful f32 kernel's accuracy.
pub fn gate() -> Gate {
    Gate::new(Declared::f32(Semantics::WholeLine))
}

/// The sphere solver's name in the findings.
pub const SPHERE: &str = "fyrox-math Ray::sphere_intersection";
/// The plane solver's name in the findings.
pub const PLANE: &str = "fyrox-math Ray::plane_intersection";
/// The cylinder solver's name in the findings.
pub const CYLINDER: &str = "fyrox-math Ray::cylinder_intersection (Infinite)";

/// The quadric families the cylinder is surveyed on: the gate's quadric
/// cases that are cylinders ([`as_cylinder`]), then
/// [`cylinder_families`] with 256 cases each.
pub fn quadric_families() -> Vec<(String, Vec<Case>)> {
    let mut fams: Vec<(String, Vec<Case>)> = gate()
        .cases("quadric")
        .into_iter()
        .map(|(f, cases)| {
            let cyl = |c: &Case| matches!(c, Case::Quadric(_, q) if as_cylinder(q).is_some());
            (f, cases.into_iter().filter(cyl).collect::<Vec<_>>())
        })
        .filter(|(_, cases)| !cases.is_empty())
        .collect();
    fams.extend(cylinder_families(256, 0xf1));
    fams
}

/// A pair of roots as the whole-line answer, as given (an infinite or
/// NaN root too).
fn roots(r: Option<[f32; 2]>) -> Answer {
    Answer::Roots(r.map_or(Vec::new(), |r| r.to_vec()))
}

/// The three solvers, on every sphere and plane family the gate runs and
/// on [`quadric_families`].
pub fn survey() -> Vec<Surveyed> {
    let g = gate();
    let sphere = |r: &Ray, s: &Sphere| roots(sphere_roots(r, s));
    let plane = |r: &Ray, p: &Plane| Answer::Roots(plane_root(r, p).into_iter().collect());
    let cylinder = |r: &Ray, q: &Quadric| match as_cylinder(q) {
        Some(c) => roots(cylinder_roots(r, &c)),
        None => Answer::Inconsistent("not a cylinder".into()),
    };
    vec![
        Surveyed::sphere(SPHERE, &g, &sphere, &g.cases("sphere")),
        Surveyed::plane(PLANE, &g, &plane, &g.cases("plane")),
        Surveyed::quadric(CYLINDER, &g, &cylinder, &quadric_families()),
    ]
}
