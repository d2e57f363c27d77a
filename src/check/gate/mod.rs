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
pub mod protocol;
#[cfg(feature = "proptest")]
pub mod strategy;
pub mod survey;
#[cfg(test)]
mod tests;

use super::rules::{self, Exact};
pub use super::rules::{Answer, CAMERA_ULPS, Declared, Semantics};
use crate::Ray;
use crate::camera::CameraParams;
use crate::case::{Case, Kind, parse_line};
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
    /// Why the run ended before every case was judged (a kernel program
    /// that exited, hung or answered too few lines), naming the case; the
    /// cases judged before it stay in the report.
    pub stopped: Option<String>,
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

    /// Whether every case was judged and passed.
    ///
    /// ```
    /// use rayoracle::check::gate::Report;
    /// assert!(Report::default().passed());
    /// ```
    pub fn passed(&self) -> bool {
        self.failures.is_empty() && self.stopped.is_none()
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
        if let Some(why) = &self.stopped {
            panic!("rayoracle gate: the run stopped: {why}");
        }
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

impl Report {
    /// The report as JSON: `cases`, `passed`, `families` (each `family`,
    /// `cases`, `failures`), `failures` (each `family`, `eval_line`,
    /// `expected`, `got`, `why`) and `stopped` (null or why).
    ///
    /// ```
    /// use rayoracle::check::gate::Report;
    /// let j = Report::default().to_json();
    /// assert_eq!(j["passed"], true);
    /// assert_eq!(j["stopped"], serde_json::Value::Null);
    /// ```
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "cases": self.cases,
            "passed": self.passed(),
            "families": self.families.iter().map(|(family, cases, failures)| serde_json::json!({
                "family": family, "cases": cases, "failures": failures,
            })).collect::<Vec<_>>(),
            "failures": self.failures.iter().map(|f| serde_json::json!({
                "family": f.family, "eval_line": f.eval_line, "expected": f.expected,
                "got": f.got, "why": f.why,
            })).collect::<Vec<_>>(),
            "skipped": self.skipped.iter().map(|(p, n)| serde_json::json!({
                "precondition": p, "cases": n,
            })).collect::<Vec<_>>(),
            "stopped": self.stopped,
        })
    }
}

/// The per-family counts, the failures kept, and a last line that says
/// `PASS` or `FAIL`.
impl fmt::Display for Report {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let width = self.families.iter().map(|x| x.0.len()).max().unwrap_or(6);
        writeln!(f, "{:width$}  {:>6}  {:>8}", "family", "cases", "failures")?;
        for (family, cases, failures) in &self.families {
            writeln!(f, "{family:width$}  {cases:>6}  {failures:>8}")?;
        }
        for failure in &self.failures {
            writeln!(f, "\n{failure}")?;
        }
        for (precondition, n) in &self.skipped {
            writeln!(
                f,
                "\nskipped: {n} cases outside the precondition {precondition}"
            )?;
        }
        if let Some(why) = &self.stopped {
            writeln!(f, "\nstopped: {why}")?;
        }
        let failing = self.failing_families().len();
        let failed: usize = self.families.iter().map(|x| x.2).sum();
        write!(
            f,
            "\n{}: {} cases in {} families, {failed} failing in {failing} families",
            if self.passed() { "PASS" } else { "FAIL" },
            self.cases,
            self.families.len()
        )
    }
}

/// A gate run's settings: the declaration, how many cases a family, the
/// seed of the random families.
#[derive(Clone, Debug)]
pub struct Gate {
    /// What the kernel promises.
    pub declared: Declared,
    /// At most this many cases of each family.
    pub budget: usize,
    /// The random families' seed.
    pub seed: u64,
    /// Whether failing cases are shrunk (by asking the kernel again).
    pub shrink: bool,
    /// Only these families, and the families under them (`sphere/random`
    /// takes `sphere/random/aimed`); empty for every family.
    pub only: Vec<String>,
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
            shrink: true,
            only: Vec::new(),
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
        self.run_kind(
            Kind::Sphere,
            &mut Each(|c: &Case| match c {
                Case::Sphere(r, s) => Reply::Answer(k.intersect(r, s)),
                _ => Reply::Failed("not a sphere case".into()),
            }),
        )
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
        self.run_kind(
            Kind::Plane,
            &mut Each(|c: &Case| match c {
                Case::Plane(r, p) => Reply::Answer(k.intersect(r, p)),
                _ => Reply::Failed("not a plane case".into()),
            }),
        )
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
        self.run_kind(
            Kind::Quadric,
            &mut Each(|c: &Case| match c {
                Case::Quadric(r, q) => Reply::Answer(k.intersect(r, q)),
                _ => Reply::Failed("not a quadric case".into()),
            }),
        )
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
        self.run_kind(
            Kind::Camera,
            &mut Each(|c: &Case| match c {
                Case::Camera(p, px) => Reply::Camera(k.ray(p, *px)),
                _ => Reply::Failed("not a camera case".into()),
            }),
        )
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

    /// The same gate, running only the families named, and those under
    /// them.
    ///
    /// ```
    /// use rayoracle::check::gate::{Declared, Gate, Semantics};
    /// let g = Gate::new(Declared::f32(Semantics::WholeLine)).only(["sphere/random", "sphere/two"]);
    /// let names: Vec<String> = g.cases("sphere").into_iter().map(|f| f.0).collect();
    /// assert_eq!(names[..3], ["sphere/two", "sphere/random/aimed", "sphere/random/inside"]);
    /// assert!(names[1..].iter().all(|f| f.starts_with("sphere/random/")));
    /// ```
    pub fn only<S: Into<String>>(self, families: impl IntoIterator<Item = S>) -> Gate {
        Gate {
            only: families.into_iter().map(Into::into).collect(),
            ..self
        }
    }

    /// How many of a kind's cases each declared precondition skips
    /// ([`Declared::skips`]), `(precondition, cases)`; what a run's
    /// [`Report::skipped`] holds.
    ///
    /// ```
    /// use rayoracle::check::gate::{Declared, Gate, Semantics};
    /// let g = Gate::new(Declared::f32(Semantics::WholeLine).no_subnormals());
    /// assert!(g.skipped("sphere").iter().any(|(p, n)| p == "no-subnormals" && *n > 0));
    /// ```
    pub fn skipped(&self, kind: &str) -> Vec<(String, usize)> {
        let mut skipped = Vec::new();
        self.load(kind, &mut skipped);
        skipped
    }

    /// Whether `family` is run ([`Gate::only`]).
    fn selects(&self, family: &str) -> bool {
        self.only.is_empty()
            || self.only.iter().any(|w| {
                family == w
                    || family
                        .strip_prefix(w.as_str())
                        .is_some_and(|r| r.starts_with('/'))
            })
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
            if !self.selects(&family) {
                continue;
            }
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

    /// Runs every family of a kind through `kernel`, with the fixture
    /// lines that could not be loaded as failures, and the cases each
    /// declared precondition skipped.
    fn run_kind(&self, kind: Kind, kernel: &mut dyn CaseKernel) -> Report {
        let mut skipped = Vec::new();
        let (families, errors) = self.load(kind.as_str(), &mut skipped);
        let mut report = self.run(&families, kernel);
        report.skipped = skipped;
        for e in errors {
            report.failures.insert(
                0,
                Failure {
                    family: "fixtures".into(),
                    eval_line: String::new(),
                    expected: "a loadable case".into(),
                    got: "an error".into(),
                    why: e,
                },
            );
            report.families.insert(0, ("fixtures".into(), 0, 1));
        }
        report
    }

    /// Runs any families of cases through a kernel: every case is asked in
    /// one batch ([`CaseKernel::answer`]), judged by the declaration, and
    /// the first three failures of each family are shrunk, by asking the
    /// kernel one case at a time, unless [`Gate::shrink`] is off. The
    /// families keep their names, so custom families report as the built-in
    /// ones do.
    ///
    /// ```
    /// use rayoracle::check::gate::{Answer, Declared, Each, Gate, Reply, Semantics};
    /// use rayoracle::{Ray, case::Case, sphere::Sphere};
    /// use glam::Vec3;
    /// let mine = vec![("mine/behind".to_string(), vec![Case::Sphere(
    ///     Ray::new(Vec3::new(0.0, 0.0, 5.0), Vec3::Z), Sphere::new(Vec3::ZERO, 1.0))])];
    /// // A kernel that takes the line's roots as hits, behind the origin too.
    /// let mut k = Each(|_: &Case| Reply::Answer(Answer::Nearest(Some(-6.0))));
    /// let report = Gate::new(Declared::f32(Semantics::NearestPositive)).run(&mine, &mut k);
    /// assert_eq!(report.failing_families(), ["mine/behind"]);
    /// ```
    pub fn run(&self, families: &[(String, Vec<Case>)], kernel: &mut dyn CaseKernel) -> Report {
        let all: Vec<Case> = families.iter().flat_map(|f| f.1.iter().cloned()).collect();
        let mut replies = Vec::with_capacity(all.len());
        let mut report = Report::default();
        if let Err(e) = kernel.answer(&all, &mut replies) {
            replies.truncate(all.len());
            let at = replies.len();
            let family = families
                .iter()
                .scan(0, |n, f| {
                    *n += f.1.len();
                    Some((*n, &f.0))
                })
                .find(|(n, _)| *n > at)
                .map_or("", |f| f.1.as_str());
            report.stopped = Some(match all.get(at) {
                Some(c) => format!(
                    "{e}; {at} of {} cases were answered; the next case: {}",
                    all.len(),
                    eval_line(c, family)
                ),
                None => e,
            });
        }
        let mut replies = replies.into_iter();
        for (family, cases) in families {
            let mut failed = 0;
            let mut judged = 0;
            for case in cases {
                let Some(reply) = replies.next() else { break };
                judged += 1;
                let Verdict::Fail { why, .. } = self.verdict(case, &reply) else {
                    continue;
                };
                failed += 1;
                if failed > 3 {
                    continue;
                }
                let small = if self.shrink && report.stopped.is_none() {
                    kernel.shrinking(family);
                    match self.shrink_failure(case, &why, kernel) {
                        Ok(small) => small,
                        Err(e) => {
                            report.stopped = Some(format!("while shrinking a failure: {e}"));
                            case.clone()
                        }
                    }
                } else {
                    case.clone()
                };
                let reply = if &small == case {
                    reply.clone()
                } else {
                    ask(kernel, &small).unwrap_or(reply.clone())
                };
                if let Verdict::Fail { expected, got, why } = self.verdict(&small, &reply) {
                    report.failures.push(Failure {
                        family: family.clone(),
                        eval_line: eval_line(&small, family),
                        expected,
                        got,
                        why,
                    });
                }
            }
            report.cases += judged;
            report.families.push((family.clone(), judged, failed));
        }
        report
    }

    /// Shrinks a failing case while it fails for the same reason (up to
    /// its numbers) and meets the declared preconditions, so
    /// the small case shows the same bug; an error if the kernel stops
    /// answering.
    fn shrink_failure(
        &self,
        case: &Case,
        why: &str,
        kernel: &mut dyn CaseKernel,
    ) -> Result<Case, String> {
        let kind = |w: &str| {
            w.split(|c: char| c.is_ascii_digit())
                .next()
                .unwrap_or("")
                .to_string()
        };
        let want = kind(why);
        let fix = |c: &Case| self.declared.prepare(c.clone()).ok();
        let mut stop = None;
        let small = shrink(case, &mut |c| {
            let Some(c) = fix(c).filter(|_| stop.is_none()) else {
                return false;
            };
            match ask(kernel, &c) {
                Ok(reply) => {
                    matches!(self.verdict(&c, &reply), Verdict::Fail { why, .. } if kind(&why) == want)
                }
                Err(e) => {
                    stop = Some(e);
                    false
                }
            }
        });
        match stop {
            Some(e) => Err(e),
            None => Ok(fix(&small).unwrap_or(small)),
        }
    }

    /// The verdict on one reply.
    fn verdict(&self, case: &Case, reply: &Reply) -> Verdict {
        let d = &self.declared;
        match (case, reply) {
            (_, Reply::Failed(why)) => Verdict::Fail {
                expected: "an answer".into(),
                got: "no answer".into(),
                why: why.clone(),
            },
            (Case::Camera(p, px), Reply::Camera(ray)) => judge_camera(d, p, *px, *ray),
            (Case::Sphere(r, s), Reply::Answer(a)) => judge_sphere(d, r, s, a.clone()),
            (Case::Plane(r, p), Reply::Answer(a)) => judge_plane(d, r, p, a.clone()),
            (Case::Quadric(r, q), Reply::Answer(a)) => judge_quadric(d, r, q, a.clone()),
            (Case::Camera(..), Reply::Answer(a)) => Verdict::Fail {
                expected: "a camera ray".into(),
                got: a.to_string(),
                why: "an intersection answer to a camera case".into(),
            },
            (_, Reply::Camera(_)) => Verdict::Fail {
                expected: "an intersection answer".into(),
                got: "a camera ray".into(),
                why: "a camera answer to an intersection case".into(),
            },
        }
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

/// A kernel's reply to one case.
#[derive(Clone, Debug, PartialEq)]
pub enum Reply {
    /// A plane, sphere or quadric answer.
    Answer(Answer),
    /// A camera's ray, or `None` where the camera refuses its parameters.
    Camera(Option<Ray>),
    /// No answer: the kernel panicked, or its answer could not be read.
    /// Always a failure, with this reason.
    Failed(String),
}

/// A kernel over cases of any kind, asked a batch at a time: the common
/// form of a Rust closure ([`Each`]) and of a program on the other end of
/// a pipe (`rayoracle gate -- PROGRAM`).
pub trait CaseKernel {
    /// Pushes one reply per case onto `replies`, in order. An error ends
    /// the run (the kernel can no longer answer); the replies pushed before
    /// it are judged.
    fn answer(&mut self, cases: &[Case], replies: &mut Vec<Reply>) -> Result<(), String>;

    /// Called before the cases that shrink a failure of `family` are
    /// asked, one at a time; by default nothing.
    fn shrinking(&mut self, family: &str) {
        let _ = family;
    }
}

/// A case-at-a-time kernel: a panic inside it becomes a
/// [`Reply::Failed`] that names the panic's message.
///
/// ```
/// use rayoracle::check::gate::{CaseKernel, Each, Reply};
/// let mut k = Each(|_: &rayoracle::case::Case| -> Reply { panic!("no such ray") });
/// let case = rayoracle::case::parse_line(r#"{"kind":"camera","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[4,3],"pixel":[0,2]}"#).unwrap().case;
/// let mut replies = vec![];
/// k.answer(&[case], &mut replies).unwrap();
/// assert_eq!(replies, [Reply::Failed("the kernel panicked: no such ray".into())]);
/// ```
pub struct Each<F>(pub F);

impl<F: FnMut(&Case) -> Reply> CaseKernel for Each<F> {
    fn answer(&mut self, cases: &[Case], replies: &mut Vec<Reply>) -> Result<(), String> {
        for c in cases {
            let reply = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| (self.0)(c)));
            replies.push(reply.unwrap_or_else(|p| {
                let msg = p
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| p.downcast_ref::<String>().cloned())
                    .unwrap_or_else(|| "a non-string payload".into());
                Reply::Failed(format!("the kernel panicked: {msg}"))
            }));
        }
        Ok(())
    }
}

/// One case asked of a kernel.
fn ask(kernel: &mut dyn CaseKernel, case: &Case) -> Result<Reply, String> {
    let mut r = Vec::with_capacity(1);
    kernel.answer(std::slice::from_ref(case), &mut r)?;
    r.pop().ok_or_else(|| "no answer".to_string())
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
/// integer, or keeps fewer significant bits, while `fails` still holds
/// and, if it was a proper case of its kind (no zero radius, no zero
/// direction, a nonzero normal or quadric, a camera that builds), stays
/// one. At most 400 candidates are tried.
///
/// ```
/// use rayoracle::check::gate::shrink;
/// use rayoracle::{Ray, case::Case, sphere::Sphere};
/// use glam::Vec3;
/// let big = Case::Sphere(Ray::new(Vec3::new(1.3, -2.7, 3.1), Vec3::new(0.3, -0.7, 0.9)),
///                        Sphere::new(Vec3::new(4.5, 0.7, -2.2), 1.7371));
/// let small = shrink(&big, &mut |c| matches!(c, Case::Sphere(_, s) if s.radius > 1.0));
/// assert_eq!(small, Case::Sphere(Ray::new(Vec3::ZERO, Vec3::new(0.25, 0.0, 0.0)),
///                                Sphere::new(Vec3::ZERO, 2.0)));
/// ```
pub fn shrink(case: &Case, fails: &mut dyn FnMut(&Case) -> bool) -> Case {
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

/// The case as an `eval` line (a non-finite number as a string).
fn eval_line(c: &Case, family: &str) -> String {
    format!(
        r#"{{"kind":"{}","family":{},{}}}"#,
        c.kind().as_str(),
        serde_json::Value::from(family),
        protocol::fields(c, protocol::short_num)
    )
}
