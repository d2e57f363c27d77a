//! The judge of rayoracle's own kernels: whether an answer (the scalar
//! reference's, x4's, or any other implementation's) is the exact answer,
//! against the exact oracle. Property tests, the fixture harness and fuzzers
//! all decide here.
//!
//! The rules are [`rules`], shared with [`gate`], which judges outside
//! kernels by the tolerance they declare. Here every answer is held to the
//! strictest declaration, [`rules::Declared::correctly_rounded`]: the exact
//! class, every root the exact root correctly rounded to `f32` bit for bit
//! (`−0` is not `+0`), and every camera direction component the oracle's
//! bits, since the reference and x4 are correctly rounded on every finite
//! input. A camera must fail to build exactly when the oracle's does, with
//! the same [`CameraError`]. Where an input is NaN or ±∞ the oracle has no
//! answer and nothing is checked ([`Status::NonFinite`]).
//!
//! What this module adds is the report: a [`CaseReport`] for an acceptable
//! answer, with the exact classification margin and each root's κ for the
//! reports that show how hard a case is, and a [`Violation`] with the
//! numbers for one that is not.

#[cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
pub mod gate;
pub mod rules;

pub use rules::ComponentCheck;
#[cfg(feature = "plane")]
pub use rules::plane_condition;

use crate::Ray;
use crate::camera::{self, CameraError, CameraParams};
use crate::case::Case;
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use crate::hit::Intersection;
#[cfg(feature = "plane")]
use crate::plane::{self, Plane, PlaneHit};
#[cfg(feature = "quadric")]
use crate::quadric::{self, Quadric, QuadricHit};
#[cfg(feature = "sphere")]
use crate::sphere::{self, Sphere, SphereHit};
use core::fmt;
use rules::{Declared, Semantics};

/// How a case was judged. Every status except [`Status::Checked`] means
/// that part of the answer was, by the rules, not checked.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::check::{Status, reference_case};
/// use rayoracle::case::parse_line;
/// let c = parse_line(r#"{"kind":"sphere","origin":[0,0,"nan"],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#).unwrap();
/// assert_eq!(reference_case(&c.case).unwrap().status, Status::NonFinite);
/// # }
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Status {
    /// Class and every root (or component) were checked: the oracle's bits.
    Checked,
    /// An input is NaN or infinite: no exact answer, nothing checked.
    NonFinite,
    /// The camera could not be built, and the candidate failed with the same
    /// error.
    Rejected,
}

/// One root compared with the exact one.
///
/// ```
/// use rayoracle::check::RootCheck;
/// let r = RootCheck { exact: 1.0, got: 1.0, ulps: 0, kappa: 2.0 };
/// assert!(r.ok());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RootCheck {
    /// The exact, correctly rounded root.
    pub exact: f32,
    /// The candidate's root.
    pub got: f32,
    /// The distance between them in ulps.
    pub ulps: u64,
    /// The root's condition number (may be infinite): how hard the root
    /// is, for reports; it allows nothing.
    pub kappa: f64,
}

impl RootCheck {
    /// Whether the root is the exact one's bits (`−0` is not `+0`).
    ///
    /// ```
    /// use rayoracle::check::RootCheck;
    /// let r = RootCheck { exact: 0.0, got: -0.0, ulps: 0, kappa: f64::INFINITY };
    /// assert!(!r.ok());
    /// let r = RootCheck { exact: 1.0, got: 1.0 + f32::EPSILON, ulps: 1, kappa: 1.0 };
    /// assert!(!r.ok());
    /// ```
    pub fn ok(&self) -> bool {
        rules::root_within(self.exact, self.got, 0.0)
    }
}

/// What was checked and what was found, for an acceptable answer.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::check::{Status, reference_case};
/// use rayoracle::case::parse_line;
/// let c = parse_line(r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#).unwrap();
/// let r = reference_case(&c.case).unwrap();
/// assert_eq!((r.kind, r.exact_class, r.got_class, r.status), ("sphere", "two", "two", Status::Checked));
/// assert_eq!(r.roots.iter().map(|x| x.exact).collect::<Vec<_>>(), [4.0, 6.0]);
/// assert_eq!(r.max_root_ulps(), Some(0));
/// # }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CaseReport {
    /// `plane`, `sphere`, `quadric` or `camera`.
    pub kind: &'static str,
    /// How the case was judged.
    pub status: Status,
    /// The exact class (`hit`, `two`, …); `non_finite` when the oracle has
    /// no answer; for a camera `ray`, or `error` when construction fails.
    pub exact_class: &'static str,
    /// The candidate's class, in the same vocabulary.
    pub got_class: &'static str,
    /// The exact classification margin (`d·n`, `aΔ` or `β² − 4αγ`) rounded
    /// to f64; NaN where there is none (camera, non-finite input).
    pub margin: f64,
    /// The roots compared (empty unless the classes match and have roots).
    pub roots: Vec<RootCheck>,
    /// The camera direction components compared (empty for the others).
    pub components: Vec<ComponentCheck>,
}

impl CaseReport {
    /// The largest root error in ulps, if any root was compared.
    ///
    /// ```
    /// # #[cfg(feature = "plane")] {
    /// use rayoracle::check::reference_case;
    /// use rayoracle::case::parse_line;
    /// let c = parse_line(r#"{"kind":"plane","origin":[0,0,0],"dir":[0,0,1],"point":[0,0,1],"normal":[0,0,1]}"#).unwrap();
    /// assert_eq!(reference_case(&c.case).unwrap().max_root_ulps(), Some(0));
    /// # }
    /// ```
    pub fn max_root_ulps(&self) -> Option<u64> {
        self.roots.iter().map(|r| r.ulps).max()
    }

    /// The largest camera component error in ulps of `Sᵢ`, if any.
    ///
    /// ```
    /// use rayoracle::check::reference_case;
    /// use rayoracle::case::parse_line;
    /// let c = parse_line(r#"{"kind":"camera","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[3,3],"pixel":[1,1]}"#).unwrap();
    /// assert_eq!(reference_case(&c.case).unwrap().max_component_ulps(), Some(0.0));
    /// ```
    pub fn max_component_ulps(&self) -> Option<f64> {
        self.components.iter().map(|c| c.err_ulps).reduce(f64::max)
    }
}

/// Why an answer is not acceptable, with the numbers.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::check::{Violation, check_sphere};
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit}};
/// use glam::Vec3;
/// let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
/// let v = check_sphere(&ray, &Sphere::new(Vec3::ZERO, 1.0), SphereHit::None).unwrap_err();
/// assert!(matches!(v, Violation::Class { exact: "two", got: "none", .. }));
/// assert!(v.to_string().starts_with("sphere: class none, exact two"));
/// # }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Violation {
    /// The classes differ.
    Class {
        /// The primitive.
        kind: &'static str,
        /// The exact class.
        exact: &'static str,
        /// The candidate's class.
        got: &'static str,
        /// The exact margin (see [`CaseReport::margin`]).
        margin: f64,
    },
    /// A root is not the exact one's bits.
    Root {
        /// The primitive.
        kind: &'static str,
        /// Which root (0 or 1, ascending).
        index: usize,
        /// The numbers.
        check: RootCheck,
    },
    /// A camera direction component is not the oracle's.
    Component(ComponentCheck),
    /// The camera ray's origin is not the position.
    Origin {
        /// The position.
        exact: [f32; 3],
        /// The candidate's origin.
        got: [f32; 3],
    },
    /// The sphere and the same sphere written as a quadric disagree.
    SphereAsQuadric(String),
    /// The camera was built where the oracle's failed, or the other way
    /// round, or both failed differently.
    Construction {
        /// The oracle's error, if any.
        exact: Option<CameraError>,
        /// The candidate's error, if any.
        got: Option<CameraError>,
    },
}

impl fmt::Display for Violation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Violation::Class {
                kind,
                exact,
                got,
                margin,
            } => write!(
                f,
                "{kind}: class {got}, exact {exact} (exact margin {margin:e})"
            ),
            Violation::Root { kind, index, check } => write!(
                f,
                "{kind}: root {index} is {got:e} ({gb:#010x}), exact {ex:e} ({eb:#010x}): {u} ulps (kappa {k:e})",
                got = check.got,
                gb = check.got.to_bits(),
                ex = check.exact,
                eb = check.exact.to_bits(),
                u = check.ulps,
                k = check.kappa,
            ),
            Violation::Component(c) => write!(
                f,
                "camera: dir[{}] is {:e}, oracle {:e}: {:.3} ulps of S = {:e} > bound {}",
                c.axis, c.got, c.exact, c.err_ulps, c.scale, c.bound
            ),
            Violation::SphereAsQuadric(what) => write!(f, "sphere as quadric: {what}"),
            Violation::Origin { exact, got } => {
                write!(f, "camera: origin {got:?} is not the position {exact:?}")
            }
            Violation::Construction { exact, got } => {
                let show = |e: &Option<CameraError>| match e {
                    Some(e) => format!("error \"{e}\""),
                    None => "a camera".to_string(),
                };
                write!(
                    f,
                    "camera: construction gave {}, oracle {}",
                    show(got),
                    show(exact)
                )
            }
        }
    }
}

impl std::error::Error for Violation {}

/// Judges the scalar reference's answer to a case: runs the reference for
/// its kind and hands the answer to [`check_plane`], [`check_sphere`],
/// [`check_quadric`] or [`check_camera`].
///
/// ```
/// # #[cfg(feature = "quadric")] {
/// use rayoracle::check::{Status, reference_case};
/// use rayoracle::case::parse_line;
/// let c = parse_line(r#"{"kind":"quadric","origin":[1,0,0],"dir":[0,0,1],"coeffs":[1,1,0,0,0,0,0,0,0,-1]}"#).unwrap();
/// let r = reference_case(&c.case).unwrap();
/// assert_eq!((r.exact_class, r.status), ("all", Status::Checked));
/// # }
/// ```
pub fn reference_case(case: &Case) -> Result<CaseReport, Violation> {
    match case {
        #[cfg(feature = "plane")]
        Case::Plane(ray, p) => check_plane(ray, p, plane::reference::intersect(ray, p)),
        #[cfg(feature = "sphere")]
        Case::Sphere(ray, s) => check_sphere(ray, s, sphere::reference::intersect(ray, s)),
        #[cfg(feature = "quadric")]
        Case::Quadric(ray, q) => check_quadric(ray, q, quadric::reference::intersect(ray, q)),
        Case::Camera(p, [px, py]) => {
            let got = p.build().map(|cam| cam.ray(*px, *py));
            check_camera(p, [*px, *py], got)
        }
    }
}

/// A report with nothing compared yet.
fn report(kind: &'static str, exact_class: &'static str, got_class: &'static str) -> CaseReport {
    CaseReport {
        kind,
        status: Status::Checked,
        exact_class,
        got_class,
        margin: f64::NAN,
        roots: Vec::new(),
        components: Vec::new(),
    }
}

/// The strictest declaration, which rayoracle's own kernels keep.
fn strict() -> Declared {
    Declared::correctly_rounded(Semantics::WholeLine)
}

/// The report of `got` against the exact answer by the shared rules under
/// [`strict`]: a root violation where a root is not the exact one's bits
/// (a NaN, or out of order), a class violation otherwise.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn judged(
    mut r: CaseReport,
    exact: &rules::Exact,
    got: impl Intersection,
) -> Result<CaseReport, Violation> {
    use rules::Fault;
    r.margin = exact.margin;
    let j = rules::judge(&strict(), exact, &rules::Answer::roots(got));
    let check = |x: &rules::RootJudged| RootCheck {
        exact: x.exact,
        got: x.got,
        ulps: x.ulps,
        kappa: x.kappa,
    };
    let wrong_root = j.roots.iter().find(|x| !x.ok());
    match (j.fault, wrong_root) {
        (None, _) => {
            r.roots = j.roots.iter().map(check).collect();
            Ok(r)
        }
        (Some(Fault::Root(_) | Fault::NanRoot | Fault::NotAscending), Some(x)) => {
            Err(Violation::Root {
                kind: r.kind,
                index: x.index,
                check: check(x),
            })
        }
        (Some(_), _) => Err(Violation::Class {
            kind: r.kind,
            exact: r.exact_class,
            got: r.got_class,
            margin: r.margin,
        }),
    }
}

/// Judges an answer to a ray–plane case: it must be the exact answer, bit
/// for bit. Margin `d·n`, κ [`plane_condition`].
///
/// ```
/// use rayoracle::check::check_plane;
/// use rayoracle::{Ray, plane::{Plane, PlaneHit}};
/// use glam::Vec3;
/// let (ray, p) = (Ray::new(Vec3::ZERO, Vec3::Z), Plane::new(Vec3::new(0.0, 0.0, 0.5), Vec3::Z));
/// assert_eq!(check_plane(&ray, &p, PlaneHit::Hit(0.5)).unwrap().max_root_ulps(), Some(0));
/// assert!(check_plane(&ray, &p, PlaneHit::Hit(0.5 + f32::EPSILON / 2.0)).is_err());
/// assert!(check_plane(&ray, &p, PlaneHit::Parallel).is_err());
/// ```
#[cfg(feature = "plane")]
pub fn check_plane(ray: &Ray, p: &Plane, got: PlaneHit) -> Result<CaseReport, Violation> {
    let Some((exact, e)) = rules::plane(ray, p) else {
        let mut r = report("plane", "non_finite", got.class().as_str());
        r.status = Status::NonFinite;
        return Ok(r);
    };
    judged(
        report("plane", exact.class().as_str(), got.class().as_str()),
        &e,
        got,
    )
}

/// Judges an answer to a ray–sphere case: it must be the exact answer, bit
/// for bit. Margin `aΔ = a(b² − ac)`, exact (`a` times a quarter of the
/// discriminant of the exact `a t² + 2b t + c`); κ [`sphere::condition_at`]
/// at each exact root (infinite for a tangent).
///
/// ```
/// use rayoracle::check::{Status, check_sphere};
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit}};
/// use glam::Vec3;
/// let s = Sphere::new(Vec3::ZERO, 1.0);
/// // Exactly tangent: aΔ = 0, and only a tangent is right.
/// let graze = Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z);
/// assert!(check_sphere(&graze, &s, SphereHit::None).is_err());
/// assert_eq!(check_sphere(&graze, &s, SphereHit::Tangent(5.0)).unwrap().status, Status::Checked);
/// ```
#[cfg(feature = "sphere")]
pub fn check_sphere(ray: &Ray, s: &Sphere, got: SphereHit) -> Result<CaseReport, Violation> {
    let Ok(q) = sphere::exact::quadratic(ray, s) else {
        let mut r = report("sphere", "non_finite", got.class().as_str());
        r.status = Status::NonFinite;
        return Ok(r);
    };
    let exact = sphere::exact::classify(&q);
    check_sphere_against(ray, s, got, &q, exact)
}

/// [`check_sphere`] given the exact quadratic and its solution.
#[cfg(feature = "sphere")]
fn check_sphere_against(
    ray: &Ray,
    s: &Sphere,
    got: SphereHit,
    q: &crate::exact::Quadratic,
    exact: SphereHit,
) -> Result<CaseReport, Violation> {
    let e = rules::sphere_given(ray, s, q, exact);
    judged(
        report("sphere", exact.class().as_str(), got.class().as_str()),
        &e,
        got,
    )
}

/// Judges an answer to a ray–quadric case: it must be the exact answer, bit
/// for bit. Margin `β² − 4αγ` (exact); κ at each exact root (infinite for
/// a double root).
///
/// ```
/// use rayoracle::check::check_quadric;
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let ray = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X);
/// assert!(check_quadric(&ray, &cyl, QuadricHit::Two(4.0, 6.0)).is_ok());
/// assert!(check_quadric(&ray, &cyl, QuadricHit::Two(4.0, 6.0000005)).is_err());
/// ```
#[cfg(feature = "quadric")]
pub fn check_quadric(ray: &Ray, q: &Quadric, got: QuadricHit) -> Result<CaseReport, Violation> {
    let Ok(eq) = quadric::exact::quadratic(ray, q) else {
        let mut r = report("quadric", "non_finite", got.class().as_str());
        r.status = Status::NonFinite;
        return Ok(r);
    };
    let exact = quadric::exact::classify(&eq);
    check_quadric_against(ray, q, got, &eq, exact)
}

/// [`check_quadric`] given the exact quadratic and its solution.
#[cfg(feature = "quadric")]
fn check_quadric_against(
    ray: &Ray,
    q: &Quadric,
    got: QuadricHit,
    eq: &crate::exact::Quadratic,
    exact: QuadricHit,
) -> Result<CaseReport, Violation> {
    let e = rules::quadric_given(ray, q, eq, exact);
    judged(
        report("quadric", exact.class().as_str(), got.class().as_str()),
        &e,
        got,
    )
}

/// Judges an answer (`got`, the ray for `pixel` or a construction error) to
/// a camera case against [`camera::exact::ray`].
///
/// ```
/// use rayoracle::check::{Status, check_camera};
/// use rayoracle::camera::CameraParams;
/// use glam::Vec3;
/// let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [64, 48]);
/// let got = p.build().map(|cam| cam.ray(5, 7));
/// assert_eq!(check_camera(&p, [5, 7], got).unwrap().status, Status::Checked);
/// let bad = CameraParams::new(Vec3::ZERO, Vec3::Y, Vec3::Y, 1.0, [64, 48]);
/// let r = check_camera(&bad, [0, 0], bad.build().map(|cam| cam.ray(0, 0))).unwrap();
/// assert_eq!((r.status, r.exact_class), (Status::Rejected, "error"));
/// ```
pub fn check_camera(
    p: &CameraParams,
    pixel: [u32; 2],
    got: Result<Ray, CameraError>,
) -> Result<CaseReport, Violation> {
    use rules::CameraFault::*;
    let exact = camera::exact::ray(p, pixel[0], pixel[1]);
    let class = |x: &Result<Ray, CameraError>| if x.is_ok() { "ray" } else { "error" };
    let mut r = report("camera", class(&exact), class(&got));
    let j = rules::judge_camera(&strict(), p, pixel, &exact, &got.map_err(Some));
    match (j.fault, got) {
        (None, _) => {
            if exact.is_err() {
                r.status = Status::Rejected;
            }
            r.components = j.components;
            Ok(r)
        }
        (Some(Origin), Ok(g)) => Err(Violation::Origin {
            exact: p.position.to_array(),
            got: g.origin.to_array(),
        }),
        (Some(Component(c)), _) => Err(Violation::Component(c)),
        (Some(_), got) => Err(Violation::Construction {
            exact: exact.err(),
            got: got.err(),
        }),
    }
}

/// The quadric class that corresponds to a sphere class (tangent ↔ one).
#[cfg(all(feature = "sphere", feature = "quadric"))]
fn sphere_as_quadric_hit(h: SphereHit) -> QuadricHit {
    match h {
        SphereHit::None => QuadricHit::None,
        SphereHit::Tangent(t) => QuadricHit::One(t),
        SphereHit::Two(t0, t1) => QuadricHit::Two(t0, t1),
    }
}

/// The sphere and the same sphere written as a quadric agree:
///
/// * when [`Quadric::from_sphere`] is exact (e.g. small integer centre and
///   radius), the quadric's exact `(α, β, γ)` is the sphere's exact
///   `(a, 2b, c)` coefficient for coefficient, so the two oracles cannot
///   differ (a zero direction is the one exception: no line for the sphere);
/// * the quadric reference is the quadric oracle's answer (the sphere
///   reference's own check is [`check_sphere`]);
/// * so the sphere reference and the quadric reference give the same
///   answer, bit for bit (a tangent is the quadric's one double root).
///
/// Returns `Ok(false)` when the check does not apply (inexact coefficients
/// or non-finite inputs), `Ok(true)` when it ran and passed.
///
/// ```
/// use rayoracle::check::sphere_as_quadric;
/// use rayoracle::{Ray, sphere::Sphere};
/// use glam::Vec3;
/// let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
/// assert_eq!(sphere_as_quadric(&ray, &Sphere::new(Vec3::new(1.0, 0.0, 0.0), 2.0)), Ok(true));
/// ```
#[cfg(all(feature = "sphere", feature = "quadric"))]
pub fn sphere_as_quadric(ray: &Ray, s: &Sphere) -> Result<bool, Violation> {
    let Ok(qs) = sphere::exact::quadratic(ray, s) else {
        return Ok(false);
    };
    let es = sphere::exact::classify(&qs);
    sphere_as_quadric_given(ray, s, &qs, es)
}

/// [`check_sphere`] and [`sphere_as_quadric`] together, solving the exact
/// polynomial once: what the `sphere` fuzz target runs.
///
/// ```
/// use rayoracle::check::check_sphere_and_quadric;
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit}};
/// use glam::Vec3;
/// let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
/// assert!(check_sphere_and_quadric(&ray, &Sphere::new(Vec3::ZERO, 1.0), SphereHit::Two(4.0, 6.0)).is_ok());
/// ```
#[cfg(all(feature = "sphere", feature = "quadric"))]
pub fn check_sphere_and_quadric(
    ray: &Ray,
    s: &Sphere,
    got: SphereHit,
) -> Result<CaseReport, Violation> {
    let Ok(qs) = sphere::exact::quadratic(ray, s) else {
        return check_sphere(ray, s, got);
    };
    let es = sphere::exact::classify(&qs);
    let report = check_sphere_against(ray, s, got, &qs, es)?;
    sphere_as_quadric_given(ray, s, &qs, es)?;
    Ok(report)
}

#[cfg(all(feature = "sphere", feature = "quadric"))]
fn sphere_as_quadric_given(
    ray: &Ray,
    s: &Sphere,
    qs: &crate::exact::Quadratic,
    es: SphereHit,
) -> Result<bool, Violation> {
    sphere_as_quadric_with(ray, s, qs, es, sphere::reference::intersect)
}

/// The same, with the sphere kernel given: the cross-check only fires when
/// a kernel is wrong, so a test passes in a wrong one to see it fire.
#[cfg(all(feature = "sphere", feature = "quadric"))]
fn sphere_as_quadric_with(
    ray: &Ray,
    s: &Sphere,
    qs: &crate::exact::Quadratic,
    es: SphereHit,
    sphere_kernel: fn(&Ray, &Sphere) -> SphereHit,
) -> Result<bool, Violation> {
    let (q, exact) = Quadric::from_sphere(s);
    if !exact || ray.dir == glam::Vec3::ZERO {
        return Ok(false);
    }
    let Ok(eq) = quadric::exact::quadratic(ray, &q) else {
        return Ok(false);
    };
    if (&eq.alpha, &eq.beta, &eq.gamma) != (&qs.alpha, &qs.beta, &qs.gamma) {
        return Err(Violation::SphereAsQuadric(format!(
            "exact sphere polynomial ({}, {}, {}) but exact quadric ({}, {}, {})",
            qs.alpha.to_f64(),
            qs.beta.to_f64(),
            qs.gamma.to_f64(),
            eq.alpha.to_f64(),
            eq.beta.to_f64(),
            eq.gamma.to_f64()
        )));
    }
    let hs = sphere_as_quadric_hit(sphere_kernel(ray, s));
    let hq = quadric::reference::intersect(ray, &q);
    check_quadric_against(ray, &q, hq, &eq, sphere_as_quadric_hit(es))?;
    if !crate::hit::same_bits(&hs, &hq) {
        return Err(Violation::SphereAsQuadric(format!(
            "reference sphere {hs:?} but reference quadric {hq:?}"
        )));
    }
    Ok(true)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A root passes the strict check only with the exact root's bits.
    #[test]
    fn a_root_check_wants_the_bits() {
        let r = |exact: f32, got: f32| RootCheck {
            exact,
            got,
            ulps: crate::ulp::ulps(exact, got),
            kappa: 1.0,
        };
        assert!(r(1.0, 1.0).ok());
        assert!(!r(1.0, 1f32.next_up()).ok());
        assert!(!r(0.0, -0.0).ok());
    }

    /// The plane x = 2⁻¹⁰⁰ as a linear quadric (α = 0), from the origin
    /// along x: the root 2⁻¹⁰⁰ is checked, and a wrong class is a
    /// violation.
    #[cfg(feature = "quadric")]
    #[test]
    fn a_linear_quadric_with_a_tiny_root_is_checked_and_its_class_enforced() {
        let edge = 2f32.powi(-100);
        let q = Quadric::new([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -edge]);
        let ray = Ray::new(Vec3::ZERO, Vec3::X);
        let r = check_quadric(&ray, &q, QuadricHit::One(edge)).unwrap();
        assert_eq!((r.status, r.exact_class), (Status::Checked, "one"));
        assert!(check_quadric(&ray, &q, QuadricHit::None).is_err());
    }

    /// The sphere-as-quadric cross-check fires when a sphere kernel's
    /// answer differs from the quadric reference's, near a tangent or far
    /// from one: two stiff cases, one clear of the tangent and one near it,
    /// and a sphere kernel that always answers the other class. The right
    /// kernel passes both.
    #[cfg(all(feature = "sphere", feature = "quadric"))]
    #[test]
    fn the_sphere_as_quadric_cross_check_fires_on_any_disagreement() {
        let other = |r: &Ray, s: &Sphere| match sphere::reference::intersect(r, s) {
            SphereHit::None => SphereHit::Two(1.0, 2.0),
            _ => SphereHit::None,
        };
        let run = |line: &str, kernel: fn(&Ray, &Sphere) -> SphereHit| {
            let Case::Sphere(ray, s) = crate::case::parse_line(line).unwrap().case else {
                unreachable!("a sphere line")
            };
            let qs = sphere::exact::quadratic(&ray, &s).unwrap();
            let es = sphere::exact::classify(&qs);
            sphere_as_quadric_with(&ray, &s, &qs, es, kernel)
        };
        let clear = r#"{"kind":"sphere","origin":[0.83984375,1.125,-0.234375],"dir":[-20,48,"0xb98df1f5"],"center":[0.15625,0.125,-0.234375],"radius":1.015625}"#;
        let near = r#"{"kind":"sphere","origin":[-1536,-2944,-8512],"dir":[-16,"0xafb1fc07",-88],"center":[-1792,-1664,-1920],"radius":1920}"#;
        for line in [clear, near] {
            assert!(
                matches!(run(line, other), Err(Violation::SphereAsQuadric(_))),
                "{:?}",
                run(line, other)
            );
            assert_eq!(run(line, sphere::reference::intersect), Ok(true));
        }
    }

    /// Construction errors must be the same error (NaN angles by bits).
    #[test]
    fn camera_errors_must_match_to_be_rejected_alike() {
        let nan = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, f32::NAN, [8, 8]);
        let err = nan.build().map(|c| c.ray(0, 0));
        assert!(matches!(err, Err(CameraError::AngleOutOfRange(_))));
        let r = check_camera(&nan, [0, 0], err).unwrap();
        assert_eq!(r.status, Status::Rejected);
        let other_nan = Err(CameraError::AngleOutOfRange(-f32::NAN));
        assert!(check_camera(&nan, [0, 0], other_nan).is_err());
        let bad = CameraParams::new(Vec3::ZERO, Vec3::Y, Vec3::Y, 1.0, [8, 8]);
        assert!(matches!(
            check_camera(&bad, [0, 0], Err(CameraError::UpZero)),
            Err(Violation::Construction { .. })
        ));
    }

    /// A direction component moved by many ulps is reported as such.
    #[test]
    fn a_wrong_camera_component_is_a_violation() {
        let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [64, 48]);
        let mut ray = p.build().unwrap().ray(5, 7);
        ray.dir.x = f32::from_bits(ray.dir.x.to_bits() + 64);
        let v = check_camera(&p, [5, 7], Ok(ray)).unwrap_err();
        assert!(
            matches!(v, Violation::Component(c) if c.axis == 0 && c.err_ulps > 4.0),
            "{v}"
        );
    }

    /// The sphere-as-quadric check declines where it does not apply.
    #[cfg(all(feature = "sphere", feature = "quadric"))]
    #[test]
    fn sphere_as_quadric_declines_a_zero_direction_and_an_inexact_quadric() {
        let s = Sphere::new(Vec3::new(1.0, 0.0, 0.0), 2.0);
        assert_eq!(
            sphere_as_quadric(&Ray::new(Vec3::Z, Vec3::ZERO), &s),
            Ok(false)
        );
        // |C|² − R² = 9 − 1e-6 is not an f32.
        let inexact = Sphere::new(Vec3::new(3.0, 0.0, 0.0), 1e-3);
        assert_eq!(
            sphere_as_quadric(&Ray::new(Vec3::ZERO, Vec3::X), &inexact),
            Ok(false)
        );
        assert_eq!(
            sphere_as_quadric(&Ray::new(Vec3::ZERO, Vec3::X), &s),
            Ok(true)
        );
    }

    /// The maxima are over every root and component, and None without any
    /// (cargo-mutants: both passed as constant `Some(0)`).
    #[test]
    fn case_report_maxima_are_over_all_entries() {
        let root = |ulps| RootCheck {
            exact: 1.0,
            got: 1.0,
            ulps,
            kappa: 1.0,
        };
        let comp = |err_ulps| ComponentCheck {
            axis: 0,
            exact: 1.0,
            got: 1.0,
            scale: 1.0,
            err_ulps,
            bound: 4.0,
        };
        let mut r = CaseReport {
            kind: "sphere",
            status: Status::Checked,
            exact_class: "two",
            got_class: "two",
            margin: 1.0,
            roots: vec![],
            components: vec![],
        };
        assert_eq!((r.max_root_ulps(), r.max_component_ulps()), (None, None));
        r.roots = vec![root(3), root(7), root(2)];
        r.components = vec![comp(0.5), comp(2.5), comp(1.0)];
        assert_eq!(
            (r.max_root_ulps(), r.max_component_ulps()),
            (Some(7), Some(2.5))
        );
    }
    use glam::Vec3;

    #[cfg(feature = "sphere")]
    #[test]
    fn sphere_margin_is_a_times_quarter_discriminant() {
        // d = (0,0,2), o = (0,0,-5), unit sphere: a = 4, b = -10, c = 24,
        // Δ = b² − ac = 100 − 96 = 4, aΔ = 16.
        let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, 2.0));
        let r = check_sphere(
            &ray,
            &Sphere::new(Vec3::ZERO, 1.0),
            SphereHit::Two(2.0, 3.0),
        )
        .unwrap();
        assert_eq!(r.margin, 16.0);
    }

    #[cfg(feature = "quadric")]
    #[test]
    fn quadric_small_but_clear_alpha_is_not_tolerated_as_linear() {
        // z = x² + y² along a direction tilted by ε = 2^-30 from the axis:
        // α = ε² is all of Σ|α terms|, and β² − 4αγ = 1 − 8ε²: the exact
        // answer is two roots (≈ 2 and ≈ 2^60), and "one" is wrong.
        let p = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0]);
        let ray = Ray::new(
            Vec3::new(0.0, 0.0, -2.0),
            Vec3::new(2f32.powi(-30), 0.0, 1.0),
        );
        let r = check_quadric(&ray, &p, QuadricHit::One(2.0));
        assert!(matches!(
            r,
            Err(Violation::Class {
                exact: "two",
                got: "one",
                ..
            })
        ));
    }

    #[cfg(feature = "quadric")]
    #[test]
    fn a_tiny_alpha_is_not_zero() {
        // (x − y)² = 1 along d = (1, 1 + 2⁻²³, 0): α = 2⁻⁴⁶, about 2⁻⁴⁸ of
        // Σ|α terms|; the roots are ±2²³, and nothing else is accepted.
        let q = Quadric::new([1.0, 1.0, 0.0, -2.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let ray = Ray::new(Vec3::ZERO, Vec3::new(1.0, 1.0 + f32::EPSILON, 0.0));
        let two = QuadricHit::Two(-8388608.0, 8388608.0);
        assert_eq!(quadric::exact::intersect(&ray, &q), Ok(two));
        assert_eq!(quadric::reference::intersect(&ray, &q), two);
        assert!(check_quadric(&ray, &q, QuadricHit::None).is_err());
        let r = check_quadric(&ray, &q, two).unwrap();
        assert_eq!(r.max_root_ulps(), Some(0));
        // Both roots are as ill-conditioned as α itself (κ ≈ 6·2⁴⁶).
        assert!(
            r.roots
                .iter()
                .all(|x| x.kappa > 2f64.powi(46) && x.kappa.is_finite())
        );
    }

    #[test]
    fn camera_construction_disagreement_is_a_violation() {
        let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [4, 4]);
        let v = check_camera(&p, [0, 0], Err(CameraError::DirZero)).unwrap_err();
        assert_eq!(
            v,
            Violation::Construction {
                exact: None,
                got: Some(CameraError::DirZero)
            }
        );
        let moved = Ray::new(Vec3::X, p.build().unwrap().ray(0, 0).dir);
        assert!(matches!(
            check_camera(&p, [0, 0], Ok(moved)),
            Err(Violation::Origin { .. })
        ));
    }
}
