//! Gate your own kernel: implement a small trait for your plane, sphere,
//! quadric or camera code, declare what it promises, and run every case
//! family against the exact oracle from one `#[test]`.
//!
//! ```
//! use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
//! use rayoracle::{Ray, sphere::Sphere};
//!
//! // A careful f32 kernel: nearest t > 0, as a renderer wants it.
//! fn my_sphere(ray: &Ray, s: &Sphere) -> Answer {
//!     Answer::nearest(rayoracle::sphere::plain::intersect(ray, s), 0.0)
//! }
//! let gate = Gate::new(Declared::f32(Semantics::NearestPositive)).budget(64);
//! let report = gate.sphere(&my_sphere);
//! report.assert_ok();
//! assert!(report.cases > 500);
//! ```
//!
//! # What is run
//!
//! For the kernel's kind, up to `budget` cases of every family of
//! `fixtures/cases/KIND.jsonl`, of the stiff catalogue (`fixtures/stiff/`),
//! and of seeded random families (`random/*`). Every case is judged against
//! the exact oracle by the declared [`Semantics`] and tolerance
//! ([`Declared`]), by the rules of [`rules`], which
//! rayoracle's own [`check`](super) shares. A failing case is shrunk (fewer significant bits, small
//! integers, zeros, while it still fails) and reported with its inputs as
//! an `eval` line, the expected and computed answers, the ulps and the
//! family ([`Failure`]).
//!
//! # Four lanes at a time
//!
//! A SIMD kernel implements [`SphereKernel4`] (and the others) over four
//! rays in whatever layout it likes, converting inside; [`Lanes`] turns it
//! into a scalar kernel that runs each case in every lane of a packet among
//! unrelated cases. If the lanes disagree (swapped lanes, a garbage lane)
//! the case fails with [`Answer::Inconsistent`].

mod families;
#[cfg(feature = "proptest")]
pub mod strategy;
pub mod survey;
#[cfg(test)]
mod tests;

use super::rules::{self, Exact};
pub use super::rules::{Answer, CAMERA_ULPS, Declared, Semantics};
use crate::Ray;
use crate::camera::CameraParams;
use crate::case::{Case, parse_line};
use crate::plane::Plane;
use crate::primitive::{self, Primitive};
use crate::quadric::Quadric;
use crate::sphere::Sphere;
use families::{invalid_cameras, random_cases};
use glam::Vec3;
use std::fmt;

/// A scalar plane kernel. Any `Fn(&Ray, &Plane) -> Answer` is one.
pub trait PlaneKernel {
    /// The kernel's answer.
    fn intersect(&self, ray: &Ray, plane: &Plane) -> Answer;
}
/// A scalar sphere kernel. Any `Fn(&Ray, &Sphere) -> Answer` is one.
pub trait SphereKernel {
    /// The kernel's answer.
    fn intersect(&self, ray: &Ray, sphere: &Sphere) -> Answer;
}
/// A scalar quadric kernel. Any `Fn(&Ray, &Quadric) -> Answer` is one.
pub trait QuadricKernel {
    /// The kernel's answer.
    fn intersect(&self, ray: &Ray, quadric: &Quadric) -> Answer;
}
/// A camera: the ray through pixel `[X, Y]`, or `None` if the camera
/// refuses the parameters. Any `Fn(&CameraParams, [u32; 2]) -> Option<Ray>`
/// is one.
pub trait CameraKernel {
    /// The kernel's ray.
    fn ray(&self, params: &CameraParams, pixel: [u32; 2]) -> Option<Ray>;
}

impl<F: Fn(&Ray, &Plane) -> Answer> PlaneKernel for F {
    fn intersect(&self, ray: &Ray, plane: &Plane) -> Answer {
        self(ray, plane)
    }
}
impl<F: Fn(&Ray, &Sphere) -> Answer> SphereKernel for F {
    fn intersect(&self, ray: &Ray, sphere: &Sphere) -> Answer {
        self(ray, sphere)
    }
}
impl<F: Fn(&Ray, &Quadric) -> Answer> QuadricKernel for F {
    fn intersect(&self, ray: &Ray, quadric: &Quadric) -> Answer {
        self(ray, quadric)
    }
}
impl<F: Fn(&CameraParams, [u32; 2]) -> Option<Ray>> CameraKernel for F {
    fn ray(&self, params: &CameraParams, pixel: [u32; 2]) -> Option<Ray> {
        self(params, pixel)
    }
}

/// A four-lane sphere kernel, in the user's own layout (convert inside).
pub trait SphereKernel4 {
    /// Four answers, lane by lane.
    fn intersect4(&self, rays: &[Ray; 4], spheres: &[Sphere; 4]) -> [Answer; 4];
}
/// A four-lane plane kernel.
pub trait PlaneKernel4 {
    /// Four answers, lane by lane.
    fn intersect4(&self, rays: &[Ray; 4], planes: &[Plane; 4]) -> [Answer; 4];
}
/// A four-lane quadric kernel.
pub trait QuadricKernel4 {
    /// Four answers, lane by lane.
    fn intersect4(&self, rays: &[Ray; 4], quadrics: &[Quadric; 4]) -> [Answer; 4];
}

/// Adapts a four-lane kernel to the scalar traits: each case runs in every
/// lane, the other lanes holding unrelated cases, and all four placements
/// must give the same answer.
///
/// ```
/// use rayoracle::check::gate::{Answer, Declared, Gate, Lanes, Semantics, SphereKernel4};
/// use rayoracle::{Ray, sphere::{Sphere, reference}};
/// struct Swapped; // lanes 1 and 2 exchanged on the way out
/// impl SphereKernel4 for Swapped {
///     fn intersect4(&self, r: &[Ray; 4], s: &[Sphere; 4]) -> [Answer; 4] {
///         let a: [Answer; 4] = core::array::from_fn(|i| Answer::roots(reference::intersect(&r[i], &s[i])));
///         [a[0].clone(), a[2].clone(), a[1].clone(), a[3].clone()]
///     }
/// }
/// let report = Gate::new(Declared::f32(Semantics::WholeLine)).budget(4).sphere(&Lanes(Swapped));
/// assert!(report.failures[0].got.contains("inconsistent lanes"));
/// ```
pub struct Lanes<K>(pub K);

/// Runs the case in each lane in turn, the primitive's
/// [`Primitive::decoys`] in the others ([`primitive::in_every_lane`]), and
/// checks that the placements agree.
fn in_every_lane<P: Primitive>(
    ray: &Ray,
    p: &P,
    run: impl Fn(&[Ray; 4], &[P; 4]) -> [Answer; 4],
) -> Answer {
    let seen = primitive::in_every_lane(*ray, *p, |c| run(&c.map(|x| x.0), &c.map(|x| x.1)));
    if seen.iter().all(|a| a == &seen[0]) {
        seen[0].clone()
    } else {
        Answer::Inconsistent(format!(
            "the case gives {} in lanes 0..3",
            seen.iter()
                .map(|a| a.to_string())
                .collect::<Vec<_>>()
                .join(" / ")
        ))
    }
}

impl<K: SphereKernel4> SphereKernel for Lanes<K> {
    fn intersect(&self, ray: &Ray, s: &Sphere) -> Answer {
        in_every_lane(ray, s, |r, p| self.0.intersect4(r, p))
    }
}
impl<K: PlaneKernel4> PlaneKernel for Lanes<K> {
    fn intersect(&self, ray: &Ray, p: &Plane) -> Answer {
        in_every_lane(ray, p, |r, q| self.0.intersect4(r, q))
    }
}
impl<K: QuadricKernel4> QuadricKernel for Lanes<K> {
    fn intersect(&self, ray: &Ray, q: &Quadric) -> Answer {
        in_every_lane(ray, q, |r, p| self.0.intersect4(r, p))
    }
}

/// One failing case, shrunk.
#[derive(Clone, Debug, PartialEq)]
pub struct Failure {
    /// The family it came from.
    pub family: String,
    /// The case as an `eval` line (run it with `rayoracle eval`).
    pub eval_line: String,
    /// What the exact oracle says, in the declared semantics.
    pub expected: String,
    /// What the kernel said.
    pub got: String,
    /// Why it fails (class, ulps against the allowed bound).
    pub why: String,
}

impl fmt::Display for Failure {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "[{}] {}\n    expected {}, got {}\n    eval: {}",
            self.family, self.why, self.expected, self.got, self.eval_line
        )
    }
}

/// The result of a gate run.
#[derive(Clone, Debug, Default)]
pub struct Report {
    /// Cases run.
    pub cases: usize,
    /// `(family, cases run, failures)` in the order run.
    pub families: Vec<(String, usize, usize)>,
    /// Every failure, shrunk (at most 3 a family are kept).
    pub failures: Vec<Failure>,
    /// `(precondition, cases skipped)`: cases not run because they violate
    /// a declared precondition ([`Declared::skips`]).
    pub skipped: Vec<(String, usize)>,
}

impl Report {
    /// The families that caught at least one failure.
    ///
    /// ```
    /// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
    /// use rayoracle::{Ray, sphere::Sphere};
    /// let never = |_: &Ray, _: &Sphere| Answer::Nearest(None);
    /// let r = Gate::new(Declared::f32(Semantics::NearestPositive)).budget(8).sphere(&never);
    /// assert!(r.failing_families().contains(&"sphere/far-tiny"));
    /// ```
    pub fn failing_families(&self) -> Vec<&str> {
        self.families
            .iter()
            .filter(|f| f.2 > 0)
            .map(|f| f.0.as_str())
            .collect()
    }

    /// Panics with every failure if there is one.
    ///
    /// ```should_panic
    /// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
    /// use rayoracle::{Ray, sphere::Sphere};
    /// let never = |_: &Ray, _: &Sphere| Answer::Nearest(None);
    /// Gate::new(Declared::f32(Semantics::NearestPositive)).budget(8).sphere(&never).assert_ok();
    /// ```
    pub fn assert_ok(&self) {
        if !self.failures.is_empty() {
            let shown: Vec<String> = self.failures.iter().map(|f| f.to_string()).collect();
            panic!(
                "rayoracle gate: {} failing cases in families {:?}\n{}",
                self.families.iter().map(|f| f.2).sum::<usize>(),
                self.failing_families(),
                shown.join("\n")
            );
        }
    }
}

/// A gate run's settings: the declaration, how many cases a family, the
/// seed of the random families.
#[derive(Clone, Copy, Debug)]
pub struct Gate {
    /// What the kernel promises.
    pub declared: Declared,
    /// At most this many cases of each family.
    pub budget: usize,
    /// The random families' seed.
    pub seed: u64,
}

/// A case to judge: the family and the inputs.
pub(super) type Sourced = (String, Case);

impl Gate {
    /// A gate with 256 cases a family and a fixed seed.
    ///
    /// ```
    /// use rayoracle::check::gate::{Declared, Gate, Semantics};
    /// assert_eq!(Gate::new(Declared::f32(Semantics::WholeLine)).budget, 256);
    /// ```
    pub fn new(declared: Declared) -> Gate {
        Gate {
            declared,
            budget: 256,
            seed: 0x7261_796f,
        }
    }

    /// The same gate with another budget.
    ///
    /// ```
    /// use rayoracle::check::gate::{Declared, Gate, Semantics};
    /// assert_eq!(Gate::new(Declared::f32(Semantics::WholeLine)).budget(8).budget, 8);
    /// ```
    pub fn budget(self, budget: usize) -> Gate {
        Gate { budget, ..self }
    }

    /// Runs every sphere family.
    pub fn sphere(&self, k: &impl SphereKernel) -> Report {
        self.run("sphere", |c| match c {
            Case::Sphere(r, s) => Some(judge_sphere(&self.declared, r, s, k.intersect(r, s))),
            _ => None,
        })
    }

    /// Runs every plane family.
    ///
    /// ```
    /// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
    /// use rayoracle::{Ray, plane::{Plane, reference}};
    /// let k = |r: &Ray, p: &Plane| Answer::roots(reference::intersect(r, p));
    /// Gate::new(Declared::faithful(Semantics::WholeLine)).budget(32).plane(&k).assert_ok();
    /// ```
    pub fn plane(&self, k: &impl PlaneKernel) -> Report {
        self.run("plane", |c| match c {
            Case::Plane(r, p) => Some(judge_plane(&self.declared, r, p, k.intersect(r, p))),
            _ => None,
        })
    }

    /// Runs every quadric family.
    ///
    /// ```
    /// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
    /// use rayoracle::{Ray, quadric::{Quadric, textbook}};
    /// // The textbook quadric formula, α = 0 guarded but not α ≈ 0: caught.
    /// let k = |r: &Ray, q: &Quadric| Answer::roots(textbook::intersect(r, q));
    /// let report = Gate::new(Declared::f32(Semantics::WholeLine)).budget(32).quadric(&k);
    /// assert!(report.failing_families().contains(&"quadric/alpha-near-zero-paraboloid"));
    /// ```
    pub fn quadric(&self, k: &impl QuadricKernel) -> Report {
        self.run("quadric", |c| match c {
            Case::Quadric(r, q) => Some(judge_quadric(&self.declared, r, q, k.intersect(r, q))),
            _ => None,
        })
    }

    /// Runs every camera family.
    ///
    /// ```
    /// use rayoracle::check::gate::{Declared, Gate, Semantics};
    /// use rayoracle::camera::CameraParams;
    /// let k = |p: &CameraParams, [x, y]: [u32; 2]| p.build().ok().map(|c| c.ray(x, y));
    /// Gate::new(Declared::f32(Semantics::WholeLine)).budget(32).camera(&k).assert_ok();
    /// ```
    pub fn camera(&self, k: &impl CameraKernel) -> Report {
        self.run("camera", |c| match c {
            Case::Camera(p, px) => Some(judge_camera(&self.declared, p, *px, k.ray(p, *px))),
            _ => None,
        })
    }

    /// The cases the gate runs for a kind (`"plane"`, `"sphere"`,
    /// `"quadric"` or `"camera"`), by family in the order run: at most
    /// `budget` a family, directions already normalised if the declaration
    /// asks for unit directions. The same inputs serve to benchmark a
    /// kernel on exactly the rays it was judged on.
    ///
    /// ```
    /// use rayoracle::check::gate::{Declared, Gate, Semantics};
    /// let families = Gate::new(Declared::f32(Semantics::WholeLine)).budget(4).cases("sphere");
    /// let far = families.iter().find(|f| f.0 == "sphere/far-tiny").unwrap();
    /// assert_eq!(far.1.len(), 4);
    /// assert!(families.iter().all(|f| f.1.len() <= 4));
    /// ```
    pub fn cases(&self, kind: &str) -> Vec<(String, Vec<Case>)> {
        self.load(kind, &mut Vec::new()).0
    }

    /// [`Gate::cases`], and the fixture lines that could not be loaded;
    /// counts the cases each precondition skips into `skipped`.
    fn load(
        &self,
        kind: &str,
        skipped: &mut Vec<(String, usize)>,
    ) -> (Vec<(String, Vec<Case>)>, Vec<String>) {
        let mut by_family: Vec<(String, Vec<Case>)> = Vec::new();
        let (sources, errors) = self.sources(kind, self.budget);
        for (family, case) in sources {
            let case = match self.declared.prepare(case) {
                Ok(c) => c,
                Err(name) => {
                    match skipped.iter_mut().find(|s| s.0 == name) {
                        Some(s) => s.1 += 1,
                        None => skipped.push((name.to_string(), 1)),
                    }
                    continue;
                }
            };
            match by_family.iter_mut().find(|f| f.0 == family) {
                Some(f) if f.1.len() < self.budget => f.1.push(case),
                Some(_) => {}
                None => by_family.push((family, vec![case])),
            }
        }
        (by_family, errors)
    }

    fn run(&self, kind: &str, judge: impl Fn(&Case) -> Option<Verdict>) -> Report {
        let mut report = Report::default();
        let judge = |c: &Case| guarded(|| judge(c));
        let (families, errors) = self.load(kind, &mut report.skipped);
        for e in errors {
            report.failures.push(Failure {
                family: "fixtures".into(),
                eval_line: String::new(),
                expected: "a loadable case".into(),
                got: "an error".into(),
                why: e,
            });
            report.families.push(("fixtures".into(), 0, 1));
        }
        for (family, cases) in families {
            let mut failed = 0;
            for case in &cases {
                let Some(Verdict::Fail { why, .. }) = judge(case) else {
                    continue;
                };
                failed += 1;
                if failed <= 3 {
                    // A shrink step must keep the kind of failure (the reason
                    // up to its numbers) and the declared inputs (unit
                    // directions), so the small case shows the same bug.
                    let kind = |w: &str| {
                        w.split(|c: char| c.is_ascii_digit())
                            .next()
                            .unwrap_or("")
                            .to_string()
                    };
                    let want = kind(&why);
                    let fix = |c: &Case| self.declared.prepare(c.clone()).ok();
                    let small = shrink(case, &|c| {
                        fix(c).is_some_and(|c| matches!(judge(&c), Some(Verdict::Fail { why, .. }) if kind(&why) == want))
                    });
                    let small = fix(&small).unwrap_or(small);
                    if let Some(Verdict::Fail { expected, got, why }) = judge(&small) {
                        report.failures.push(Failure {
                            family: family.clone(),
                            eval_line: eval_line(&small, &family),
                            expected,
                            got,
                            why,
                        });
                    }
                }
            }
            report.cases += cases.len();
            report.families.push((family, cases.len(), failed));
        }
        report
    }

    /// One sphere case, judged: for a user's own property tests and
    /// fuzzers (`strategy`, with the `proptest` feature, and [`crate::fuzz::gate`]). The failure is not shrunk.
    ///
    /// ```
    /// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
    /// use rayoracle::{Ray, sphere::Sphere};
    /// use glam::Vec3;
    /// let g = Gate::new(Declared::f32(Semantics::WholeLine));
    /// let (r, s) = (Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), Sphere::new(Vec3::ZERO, 1.0));
    /// assert!(g.judge_sphere(&r, &s, Answer::Roots(vec![4.0, 6.0])).is_ok());
    /// let f = g.judge_sphere(&r, &s, Answer::Roots(vec![6.0, 4.0])).unwrap_err();
    /// assert!(f.why.contains("ascending") && f.eval_line.contains("\"kind\":\"sphere\""));
    /// ```
    pub fn judge_sphere(&self, ray: &Ray, s: &Sphere, answer: Answer) -> Result<(), Failure> {
        one(
            Case::Sphere(*ray, *s),
            judge_sphere(&self.declared, ray, s, answer),
        )
    }

    /// One plane case, judged (see [`Gate::judge_sphere`]).
    ///
    /// ```
    /// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
    /// use rayoracle::{Ray, plane::Plane};
    /// use glam::Vec3;
    /// let g = Gate::new(Declared::f32(Semantics::WholeLine));
    /// let in_plane = (Ray::new(Vec3::ZERO, Vec3::X), Plane::new(Vec3::ZERO, Vec3::Y));
    /// assert!(g.judge_plane(&in_plane.0, &in_plane.1, Answer::Everywhere).is_ok());
    /// assert!(g.judge_plane(&in_plane.0, &in_plane.1, Answer::Roots(vec![])).is_err());
    /// ```
    pub fn judge_plane(&self, ray: &Ray, p: &Plane, answer: Answer) -> Result<(), Failure> {
        one(
            Case::Plane(*ray, *p),
            judge_plane(&self.declared, ray, p, answer),
        )
    }

    /// One quadric case, judged (see [`Gate::judge_sphere`]).
    ///
    /// ```
    /// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
    /// use rayoracle::{Ray, quadric::Quadric};
    /// use glam::Vec3;
    /// let g = Gate::new(Declared::f32(Semantics::NearestPositive));
    /// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
    /// let r = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X);
    /// assert!(g.judge_quadric(&r, &cyl, Answer::Nearest(Some(4.0))).is_ok());
    /// assert!(g.judge_quadric(&r, &cyl, Answer::Nearest(Some(-6.0))).is_err());
    /// ```
    pub fn judge_quadric(&self, ray: &Ray, q: &Quadric, answer: Answer) -> Result<(), Failure> {
        one(
            Case::Quadric(*ray, *q),
            judge_quadric(&self.declared, ray, q, answer),
        )
    }

    /// One camera case, judged (see [`Gate::judge_sphere`]).
    ///
    /// ```
    /// use rayoracle::check::gate::{Declared, Gate, Semantics};
    /// use rayoracle::camera::CameraParams;
    /// use glam::Vec3;
    /// let g = Gate::new(Declared::f32(Semantics::WholeLine));
    /// let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [4, 4]);
    /// let good = p.build().unwrap().ray(1, 2);
    /// assert!(g.judge_camera(&p, [1, 2], Some(good)).is_ok());
    /// assert!(g.judge_camera(&p, [1, 2], Some(p.build().unwrap().ray(2, 1))).is_err());
    /// ```
    pub fn judge_camera(
        &self,
        p: &CameraParams,
        pixel: [u32; 2],
        ray: Option<Ray>,
    ) -> Result<(), Failure> {
        one(
            Case::Camera(*p, pixel),
            judge_camera(&self.declared, p, pixel, ray),
        )
    }

    /// The fixture families, the stiff families and the random families of
    /// a kind, all compiled in ([`crate::fixtures`]); and the lines that
    /// could not be loaded, each `FILE:LINE: problem`, which fail the run
    /// rather than shrink it.
    fn sources(&self, kind: &str, random: usize) -> (Vec<Sourced>, Vec<String>) {
        let mut out = Vec::new();
        let mut errors = Vec::new();
        let known = kind.parse::<crate::case::Kind>().ok();
        let files = [
            ("cases", known.map(crate::fixtures::cases)),
            ("stiff", known.map(crate::fixtures::stiff)),
        ];
        for (dir, text) in files {
            let Some(text) = text else {
                errors.push(format!("fixtures/{dir}: no cases of the kind \"{kind}\""));
                continue;
            };
            for (i, line) in text.lines().enumerate() {
                if line.trim().is_empty() {
                    continue;
                }
                match parse_line(line) {
                    Ok(c) => out.push((
                        c.family.unwrap_or_else(|| format!("{kind}/unnamed")),
                        c.case,
                    )),
                    Err(e) => errors.push(format!("fixtures/{dir}/{kind}.jsonl:{}: {e}", i + 1)),
                }
            }
        }
        if kind == "camera" {
            out.extend(invalid_cameras());
        }
        out.extend(random_cases(kind, self.seed, random));
        (out, errors)
    }
}

/// Runs `judge`, turning a panic inside it (the user's kernel) into a
/// failure that names the panic's message.
fn guarded(judge: impl FnOnce() -> Option<Verdict>) -> Option<Verdict> {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(judge)).unwrap_or_else(|p| {
        let msg = p
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| p.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "a non-string payload".into());
        Some(Verdict::Fail {
            expected: "an answer".into(),
            got: "a panic".into(),
            why: format!("the kernel panicked: {msg}"),
        })
    })
}

/// A single judged case as a result.
fn one(case: Case, v: Verdict) -> Result<(), Failure> {
    match v {
        Verdict::Pass => Ok(()),
        Verdict::Fail { expected, got, why } => Err(Failure {
            family: "single case".into(),
            eval_line: eval_line(&case, "single case"),
            expected,
            got,
            why,
        }),
    }
}

/// How one case was judged.
enum Verdict {
    Pass,
    Fail {
        expected: String,
        got: String,
        why: String,
    },
}

/// The verdict of the shared rules ([`rules::judge`]) on `got`, with what
/// was expected, or a pass where the oracle has no answer (non-finite
/// inputs).
fn verdict(d: &Declared, e: Option<&Exact>, got: &Answer) -> Verdict {
    let Some(e) = e else {
        return Verdict::Pass;
    };
    let Some(fault) = rules::judge(d, e, got).fault else {
        return Verdict::Pass;
    };
    let expected = match fault {
        rules::Fault::Inconsistent(_) => "the same answer in every lane".into(),
        _ => e.expected(d).to_string(),
    };
    Verdict::Fail {
        expected,
        got: got.to_string(),
        why: fault.to_string(),
    }
}

fn judge_sphere(d: &Declared, ray: &Ray, s: &Sphere, got: Answer) -> Verdict {
    verdict(d, rules::sphere(ray, s).map(|e| e.1).as_ref(), &got)
}

fn judge_plane(d: &Declared, ray: &Ray, p: &Plane, got: Answer) -> Verdict {
    verdict(d, rules::plane(ray, p).map(|e| e.1).as_ref(), &got)
}

fn judge_quadric(d: &Declared, ray: &Ray, q: &Quadric, got: Answer) -> Verdict {
    verdict(d, rules::quadric(ray, q).map(|e| e.1).as_ref(), &got)
}

fn judge_camera(d: &Declared, p: &CameraParams, px: [u32; 2], got: Option<Ray>) -> Verdict {
    use rules::CameraFault::*;
    let exact = crate::camera::exact::ray(p, px[0], px[1]);
    let j = rules::judge_camera(d, p, px, &exact, &got.ok_or(None));
    let Some(fault) = j.fault else {
        return Verdict::Pass;
    };
    let show = |r: Option<Ray>| r.map_or("no camera".to_string(), |r| format!("{r:?}"));
    let why = match fault {
        NotRefused | OtherError => "the camera must refuse these parameters".into(),
        Refused => "valid parameters were refused".into(),
        Origin => "the origin is not the camera position".into(),
        Component(c) => format!(
            "direction component {} is {:.1} ulps of its scale Sᵢ away, allowed {:.1}",
            c.axis, c.err_ulps, c.bound
        ),
    };
    Verdict::Fail {
        expected: match &exact {
            Err(e) => format!("no camera ({e})"),
            Ok(x) => format!("{x:?}"),
        },
        got: show(got),
        why,
    }
}

/// The case's f32 inputs, in a fixed order, and back.
fn fields(c: &Case) -> Vec<f32> {
    let v = |x: Vec3| x.to_array().to_vec();
    match c {
        Case::Plane(r, p) => [v(r.origin), v(r.dir), v(p.point), v(p.normal)].concat(),
        Case::Sphere(r, s) => [v(r.origin), v(r.dir), v(s.center), vec![s.radius]].concat(),
        Case::Quadric(r, q) => [v(r.origin), v(r.dir), q.coeffs.to_vec()].concat(),
        Case::Camera(p, _) => [v(p.position), v(p.dir), v(p.up), vec![p.angle]].concat(),
    }
}

fn with_fields(c: &Case, f: &[f32]) -> Case {
    let v = |i: usize| Vec3::new(f[i], f[i + 1], f[i + 2]);
    match c {
        Case::Plane(..) => Case::Plane(Ray::new(v(0), v(3)), Plane::new(v(6), v(9))),
        Case::Sphere(..) => Case::Sphere(Ray::new(v(0), v(3)), Sphere::new(v(6), f[9])),
        Case::Quadric(..) => Case::Quadric(
            Ray::new(v(0), v(3)),
            Quadric::new(core::array::from_fn(|i| f[6 + i])),
        ),
        Case::Camera(p, px) => Case::Camera(CameraParams::new(v(0), v(3), v(6), f[9], p.res), *px),
    }
}

/// Whether a case is a proper one of its kind: a nonzero direction, and a
/// nonzero radius, a nonzero normal, a quadric with a nonzero coefficient,
/// or a camera that builds.
fn proper(c: &Case) -> bool {
    match c {
        Case::Sphere(r, s) => r.dir != Vec3::ZERO && s.radius != 0.0,
        Case::Plane(r, p) => r.dir != Vec3::ZERO && p.normal != Vec3::ZERO,
        Case::Quadric(r, q) => r.dir != Vec3::ZERO && q.coeffs.iter().any(|&k| k != 0.0),
        Case::Camera(p, _) => p.build().is_ok(),
    }
}

/// Shrinks a failing case: each input in turn becomes 0, its nearest
/// integer, or keeps fewer significant bits, while the case still fails
/// and, if it was a proper case of its kind ([`proper`]: no zero radius,
/// no zero direction, a camera that builds), stays one.
fn shrink(case: &Case, fails: &dyn Fn(&Case) -> bool) -> Case {
    let keep_proper = proper(case);
    let mut best = case.clone();
    let mut tries = 0;
    loop {
        let mut improved = false;
        let f = fields(&best);
        for i in 0..f.len() {
            let x = f[i];
            let mut candidates = vec![0.0, x.round()];
            for keep in [1u32, 4, 8, 12] {
                let mask = !((1u32 << (23 - keep)) - 1);
                candidates.push(f32::from_bits(x.to_bits() & mask));
            }
            for cand in candidates {
                if cand == x || !cand.is_finite() || tries > 400 {
                    continue;
                }
                tries += 1;
                let mut g = f.clone();
                g[i] = cand;
                let c = with_fields(&best, &g);
                if (!keep_proper || proper(&c)) && fails(&c) {
                    best = c;
                    improved = true;
                    break;
                }
            }
        }
        // Past 400 tries every candidate is skipped, so that pass ends
        // with no improvement: the cap needs no test here.
        if !improved {
            return best;
        }
    }
}

/// The case as an `eval` line.
fn eval_line(c: &Case, family: &str) -> String {
    let v = |x: Vec3| format!("[{:?},{:?},{:?}]", x.x, x.y, x.z);
    match c {
        Case::Plane(r, p) => format!(
            r#"{{"kind":"plane","family":"{family}","origin":{},"dir":{},"point":{},"normal":{}}}"#,
            v(r.origin),
            v(r.dir),
            v(p.point),
            v(p.normal)
        ),
        Case::Sphere(r, s) => format!(
            r#"{{"kind":"sphere","family":"{family}","origin":{},"dir":{},"center":{},"radius":{:?}}}"#,
            v(r.origin),
            v(r.dir),
            v(s.center),
            s.radius
        ),
        Case::Quadric(r, q) => format!(
            r#"{{"kind":"quadric","family":"{family}","origin":{},"dir":{},"coeffs":{:?}}}"#,
            v(r.origin),
            v(r.dir),
            q.coeffs
        ),
        Case::Camera(p, px) => format!(
            r#"{{"kind":"camera","family":"{family}","position":{},"dir":{},"up":{},"angle":{:?},"res":[{},{}],"pixel":[{},{}]}}"#,
            v(p.position),
            v(p.dir),
            v(p.up),
            p.angle,
            p.res[0],
            p.res[1],
            px[0],
            px[1]
        ),
    }
}
