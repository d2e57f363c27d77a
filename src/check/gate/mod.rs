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
//! ([`Declared`]). A failing case is shrunk (fewer significant bits, small
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

pub mod fuzz;
#[cfg(feature = "proptest")]
pub mod strategy;
pub mod survey;
#[cfg(test)]
mod tests;

use crate::Ray;
use crate::camera::{CameraParams, component_scale};

/// The least allowance for a gated camera's direction components, in ulps
/// of `Sᵢ = |fᵢ| + |u xᵢ| + |v yᵢ|` ([`component_scale`]): what a plain
/// `f32` camera `(f + u·x) + v·y` reaches from a correctly rounded basis
/// (½ ulp for the basis, ½ for the offset, ½ for each of the two products
/// and two sums, rounded up, plus ½ for the oracle's own rounding).
pub const CAMERA_ULPS: f64 = 4.0;
use crate::case::{Case, parse_line};
use crate::exact::dyadic::{dot, vec3};
use crate::hit::Intersection;
use crate::plane::{self, Plane, PlaneHit};
use crate::quadric::{self, Quadric, QuadricHit};
use crate::sphere::{self, Sphere, SphereHit};
use crate::ulp::{ulp_of, ulps};
use glam::Vec3;
use std::fmt;

/// A kernel's answer for one ray and primitive.
///
/// ```
/// use rayoracle::check::gate::Answer;
/// use rayoracle::sphere::SphereHit;
/// assert_eq!(Answer::nearest(SphereHit::Two(-1.0, 3.0), 0.0), Answer::Nearest(Some(3.0)));
/// assert_eq!(Answer::roots(SphereHit::Tangent(2.0)), Answer::Roots(vec![2.0]));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Answer {
    /// Every root on the whole line, ascending (a tangent once, or twice).
    Roots(Vec<f32>),
    /// The nearest root `t > t_min` only, or none.
    Nearest(Option<f32>),
    /// Every `t` is a solution (a ray in the plane, a line on the quadric).
    Everywhere,
    /// The [`Lanes`] adapter saw the lanes disagree; always a failure.
    Inconsistent(String),
}

impl Answer {
    /// The whole-line answer of any of rayoracle's result types.
    pub fn roots(h: impl Intersection) -> Answer {
        if h.is_everywhere() {
            Answer::Everywhere
        } else {
            Answer::Roots(h.roots().as_slice().to_vec())
        }
    }

    /// The nearest root strictly above `t_min` of any result type.
    pub fn nearest(h: impl Intersection, t_min: f32) -> Answer {
        if h.is_everywhere() {
            return Answer::Everywhere;
        }
        Answer::Nearest(h.roots().as_slice().iter().copied().find(|&t| t > t_min))
    }
}

impl fmt::Display for Answer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Answer::Roots(r) if r.is_empty() => write!(f, "no roots"),
            Answer::Roots(r) => write!(f, "roots {r:?}"),
            Answer::Nearest(Some(t)) => write!(f, "nearest {t:?}"),
            Answer::Nearest(None) => write!(f, "no hit"),
            Answer::Everywhere => write!(f, "every t"),
            Answer::Inconsistent(why) => write!(f, "inconsistent lanes: {why}"),
        }
    }
}

/// What the kernel computes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Semantics {
    /// Every root on the whole line, `t ∈ ℝ` ([`Answer::Roots`]).
    WholeLine,
    /// The nearest root `t > 0` ([`Answer::Nearest`]), as a ray caster.
    NearestPositive,
}

/// What the kernel promises: its semantics, its accuracy, and its inputs.
///
/// A root of condition number κ may be off by
/// `2^bits − 1 + κ · precision · 2²⁴` ulps: `bits` for a well-conditioned
/// root, plus what the kernel's working precision (relative, `2⁻²⁴` for
/// one f32 rounding) makes unavoidable. A class may differ from the exact
/// one when the exact classification margin is within `band_scale` times
/// the unit band, `2⁻⁴⁴` of the terms the margin is made of (a plain f32
/// kernel needs about `2²⁰` of it), with one exception: when
/// every input is an integer of magnitude at most 16, an exactly degenerate
/// case (a ray in the plane, an exact tangent, α = 0) must be classified
/// exactly, since any kernel computes its margin exactly there.
///
/// ```
/// use rayoracle::check::gate::{Declared, Semantics};
/// let d = Declared::f32(Semantics::WholeLine);
/// assert_eq!(d.bits, 2.0);
/// assert!(Declared::faithful(Semantics::WholeLine).band_scale == 1.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Declared {
    /// Whole line or nearest positive.
    pub semantics: Semantics,
    /// Bits of error allowed on a well-conditioned root.
    pub bits: f64,
    /// The kernel's relative working precision.
    pub precision: f64,
    /// Class tolerance, as a multiple of the unit band.
    pub band_scale: f64,
    /// Feed only unit-length directions (normalised in f32 first).
    pub unit_dirs_only: bool,
}

impl Declared {
    /// A careful f32 kernel: 2 bits, a few f32 roundings of working
    /// precision (`2⁻²²`), a band of `2²⁰` units.
    pub fn f32(semantics: Semantics) -> Declared {
        Declared {
            semantics,
            bits: 2.0,
            precision: 2f64.powi(-22),
            band_scale: 2f64.powi(20),
            unit_dirs_only: false,
        }
    }

    /// A faithfully rounded kernel: every root within one ulp of the exact
    /// one, with about `2⁻⁴²` of working precision and the unit band.
    pub fn faithful(semantics: Semantics) -> Declared {
        Declared {
            semantics,
            bits: 1.0,
            precision: 2f64.powi(-42),
            band_scale: 1.0,
            unit_dirs_only: false,
        }
    }

    /// The same, fed only unit-length directions.
    pub fn unit_dirs(self) -> Declared {
        Declared {
            unit_dirs_only: true,
            ..self
        }
    }

    fn allowed_ulps(&self, kappa: f64) -> f64 {
        let k = if kappa.is_finite() {
            kappa
        } else {
            f64::INFINITY
        };
        (2f64.powf(self.bits) - 1.0) + k * self.precision * 2f64.powi(24)
    }
}

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

/// Runs `case` in each lane among `decoys` and checks the placements agree.
fn in_every_lane<P: Copy>(
    case: (Ray, P),
    decoys: [(Ray, P); 3],
    run: impl Fn(&[Ray; 4], &[P; 4]) -> [Answer; 4],
) -> Answer {
    let mut seen: Vec<Answer> = Vec::new();
    for lane in 0..4 {
        let mut items = [decoys[0], decoys[1], decoys[2], decoys[0]];
        let mut d = 0;
        for (i, item) in items.iter_mut().enumerate() {
            if i == lane {
                *item = case;
            } else {
                *item = decoys[d % 3];
                d += 1;
            }
        }
        let answers = run(&items.map(|x| x.0), &items.map(|x| x.1));
        seen.push(answers[lane].clone());
    }
    if seen.iter().all(|a| a == &seen[0]) {
        seen.swap_remove(0)
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

// The decoys that fill the other three lanes: for each kind, answers of
// different classes and at different t (pinned in the tests), so a kernel
// that leaks one lane's data into another shows as a wrong or inconsistent
// answer.
fn sphere_decoys() -> [(Ray, Sphere); 3] {
    let unit = Sphere::new(Vec3::ZERO, 1.0);
    [
        (Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), unit),
        (
            Ray::new(Vec3::new(3.0, 7.0, 1.0), Vec3::X),
            Sphere::new(Vec3::new(9.0, 7.0, 1.0), 2.0),
        ),
        (Ray::new(Vec3::new(0.0, 4.0, 0.0), Vec3::Y), unit),
    ]
}
fn plane_decoys() -> [(Ray, Plane); 3] {
    let ground = Plane::new(Vec3::ZERO, Vec3::Y);
    [
        (Ray::new(Vec3::Y, -Vec3::Y), ground),
        (
            Ray::new(Vec3::new(1.0, 2.0, 3.0), Vec3::X),
            Plane::new(Vec3::new(7.0, 0.0, 0.0), Vec3::X),
        ),
        (Ray::new(Vec3::Y, Vec3::Z), ground),
    ]
}
fn quadric_decoys() -> [(Ray, Quadric); 3] {
    let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
    let ball = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -4.0]);
    [
        (Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X), cyl),
        (Ray::new(Vec3::new(0.0, 0.0, -9.0), Vec3::Z), ball),
        (Ray::new(Vec3::new(0.5, 0.0, 0.0), Vec3::Z), cyl),
    ]
}

impl<K: SphereKernel4> SphereKernel for Lanes<K> {
    fn intersect(&self, ray: &Ray, s: &Sphere) -> Answer {
        in_every_lane((*ray, *s), sphere_decoys(), |r, p| self.0.intersect4(r, p))
    }
}
impl<K: PlaneKernel4> PlaneKernel for Lanes<K> {
    fn intersect(&self, ray: &Ray, p: &Plane) -> Answer {
        in_every_lane((*ray, *p), plane_decoys(), |r, q| self.0.intersect4(r, q))
    }
}
impl<K: QuadricKernel4> QuadricKernel for Lanes<K> {
    fn intersect(&self, ray: &Ray, q: &Quadric) -> Answer {
        in_every_lane((*ray, *q), quadric_decoys(), |r, p| self.0.intersect4(r, p))
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
type Sourced = (String, Case);

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
        self.load(kind).0
    }

    /// [`Gate::cases`], and the fixture lines that could not be loaded.
    fn load(&self, kind: &str) -> (Vec<(String, Vec<Case>)>, Vec<String>) {
        let mut by_family: Vec<(String, Vec<Case>)> = Vec::new();
        let (sources, errors) = self.sources(kind, self.budget);
        for (family, case) in sources {
            let case = if self.declared.unit_dirs_only {
                unit_dir(case)
            } else {
                case
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
        let (families, errors) = self.load(kind);
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
                    let unit = self.declared.unit_dirs_only;
                    let fix = |c: Case| if unit { unit_dir(c) } else { c };
                    let small = shrink(
                        case,
                        &|c| matches!(judge(&fix(c.clone())), Some(Verdict::Fail { why, .. }) if kind(&why) == want),
                    );
                    let small = fix(small);
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
    /// fuzzers (`strategy`, with the `proptest` feature, and [`fuzz`]). The failure is not shrunk.
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
                    Ok(c) if c.expect.as_ref().is_some_and(|e| e["class"] == "error") => {}
                    Ok(c) => out.push((
                        c.family.unwrap_or_else(|| format!("{kind}/unnamed")),
                        c.case,
                    )),
                    Err(e) => errors.push(format!("fixtures/{dir}/{kind}.jsonl:{}: {e}", i + 1)),
                }
            }
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

/// Unit-length direction (f32 normalisation); the oracle then sees exactly
/// these inputs.
fn unit_dir(case: Case) -> Case {
    let n = |r: Ray| Ray::new(r.origin, r.dir.normalize_or_zero());
    match case {
        Case::Plane(r, p) => Case::Plane(n(r), p),
        Case::Sphere(r, s) => Case::Sphere(n(r), s),
        Case::Quadric(r, q) => Case::Quadric(n(r), q),
        c => c,
    }
}

/// Seeded random cases (`random/*` families), `n` per family.
fn random_cases(kind: &str, seed: u64, n: usize) -> Vec<Sourced> {
    use rand::{Rng, SeedableRng, rngs::SmallRng};
    let mut rng = SmallRng::seed_from_u64(seed ^ kind.len() as u64);
    let v3 = |rng: &mut SmallRng, s: f32| {
        Vec3::new(
            rng.random_range(-s..s),
            rng.random_range(-s..s),
            rng.random_range(-s..s),
        )
    };
    let mut out = Vec::new();
    let fam = |name: &str| format!("{kind}/random/{name}");
    for _ in 0..n {
        match kind {
            "sphere" => {
                let c = v3(&mut rng, 10.0);
                let r = rng.random_range(0.1..5.0f32);
                let o = c + v3(&mut rng, 30.0);
                let aim = c + v3(&mut rng, r) - o;
                out.push((
                    fam("aimed"),
                    Case::Sphere(Ray::new(o, aim), Sphere::new(c, r)),
                ));
                let inside = c + v3(&mut rng, r * 0.5);
                out.push((
                    fam("inside"),
                    Case::Sphere(Ray::new(inside, v3(&mut rng, 1.0)), Sphere::new(c, r)),
                ));
            }
            "plane" => {
                let p = Plane::new(v3(&mut rng, 10.0), v3(&mut rng, 1.0));
                out.push((
                    fam("any"),
                    Case::Plane(Ray::new(v3(&mut rng, 20.0), v3(&mut rng, 1.0)), p),
                ));
            }
            "quadric" => {
                let mut k = [0f32; 10];
                for (i, x) in k.iter_mut().enumerate() {
                    *x = if i < 3 {
                        rng.random_range(-2.0..2.0)
                    } else {
                        rng.random_range(-1.0..1.0)
                    };
                }
                let ray = Ray::new(v3(&mut rng, 6.0), v3(&mut rng, 1.0));
                out.push((fam("any"), Case::Quadric(ray, Quadric::new(k))));
            }
            "camera" => {
                let res = [rng.random_range(1..2000u32), rng.random_range(1..2000u32)];
                let p = CameraParams::new(
                    v3(&mut rng, 10.0),
                    v3(&mut rng, 1.0),
                    v3(&mut rng, 1.0),
                    rng.random_range(0.1..3.0f32),
                    res,
                );
                let px = [rng.random_range(0..res[0]), rng.random_range(0..res[1])];
                if p.build().is_ok() {
                    out.push((fam("any"), Case::Camera(p, px)));
                }
            }
            _ => {}
        }
    }
    out
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

fn fail(expected: impl fmt::Display, got: &Answer, why: String) -> Verdict {
    Verdict::Fail {
        expected: expected.to_string(),
        got: got.to_string(),
        why,
    }
}

/// The exact answer of a primitive case, its classification margin against
/// the (scaled) band, and each exact root's κ.
struct Exact {
    /// Whole-line roots, correctly rounded; empty for none; `None` for
    /// every `t`.
    roots: Option<Vec<f32>>,
    in_band: bool,
    /// The quadric's α is within its band: the kernel may take it for 0
    /// (one root where there are two) or not (two where α = 0 gives one);
    /// the root they share must still be right.
    alpha_small: bool,
    kappa: Vec<f64>,
}

fn judge(d: &Declared, e: &Exact, got: Answer) -> Verdict {
    if let Answer::Inconsistent(why) = &got {
        return fail("the same answer in every lane", &got, why.clone());
    }
    let expected = match &e.roots {
        None => Answer::Everywhere,
        Some(r) => match d.semantics {
            Semantics::WholeLine => Answer::Roots(r.clone()),
            Semantics::NearestPositive => Answer::Nearest(r.iter().copied().find(|&t| t > 0.0)),
        },
    };
    let close = |exact: f32, got: f32, kappa: f64| -> Result<(), String> {
        let u = ulps(exact, got);
        let allowed = d.allowed_ulps(kappa);
        if (u as f64) <= allowed {
            Ok(())
        } else {
            Err(format!(
                "{u} ulps from the correctly rounded root, allowed {allowed:.1} (κ = {kappa:.3e})"
            ))
        }
    };
    let class_msg =
        || "a different class, and the exact margin is outside the declared band".to_string();
    // No NaN is ever a right root, whatever the band.
    let nan = match &got {
        Answer::Roots(g) => g.iter().any(|t| t.is_nan()),
        Answer::Nearest(Some(t)) => t.is_nan(),
        _ => false,
    };
    // Each finite root the kernel gives must be close to some exact root:
    // what a band excuses is the count, not the values.
    let each_close = |x: &[f32], g: &[f32]| -> Result<(), String> {
        for &t in g {
            let best = x
                .iter()
                .zip(&e.kappa)
                .map(|(&xe, &k)| close(xe, t, k))
                .find(Result::is_ok);
            if best.is_none() && !x.is_empty() {
                return Err(format!("the root {t:?} is near none of the exact roots"));
            }
        }
        Ok(())
    };
    let verdict = match (&expected, &got) {
        _ if nan => Err("a NaN root".into()),
        (Answer::Everywhere, Answer::Everywhere) => Ok(()),
        // A ray lying on the surface has no nearest hit to compare.
        (Answer::Everywhere, _) if d.semantics == Semantics::NearestPositive => Ok(()),
        (Answer::Roots(x), Answer::Roots(g)) => {
            // A tangent may come once or twice.
            let g: Vec<f32> = if x.len() == 1 && g.len() == 2 && g[0] == g[1] {
                vec![g[0]]
            } else {
                g.clone()
            };
            if x.len() != g.len() {
                let one_or_two = x.len().min(g.len()) == 1 && x.len().max(g.len()) == 2;
                if e.in_band {
                    // Near a double root (infinite κ) any nearby value passes.
                    Ok(())
                } else if e.alpha_small && one_or_two {
                    if g.len() == 1 {
                        // The kernel took a tiny α for 0: its one root must
                        // be one of the exact two.
                        each_close(x, &g)
                    } else {
                        // α = 0 exactly, and the kernel kept a tiny α: one
                        // of its two roots must be the exact one.
                        let k = e.kappa.first().copied().unwrap_or(f64::INFINITY);
                        if g.iter().any(|&t| close(x[0], t, k).is_ok()) {
                            Ok(())
                        } else {
                            Err(format!("neither root is near the exact root {:?}", x[0]))
                        }
                    }
                } else {
                    Err(class_msg())
                }
            } else if g.windows(2).any(|w| !(w[0] <= w[1])) {
                Err("the roots are not ascending".into())
            } else {
                x.iter()
                    .zip(&g)
                    .zip(&e.kappa)
                    .try_for_each(|((&x, &g), &k)| close(x, g, k))
            }
        }
        (Answer::Nearest(x), Answer::Nearest(g)) => match (x, g) {
            (None, None) => Ok(()),
            (Some(x), Some(g)) => {
                let i = e
                    .roots
                    .as_ref()
                    .and_then(|r| r.iter().position(|t| t == x))
                    .unwrap_or(0);
                close(*x, *g, e.kappa.get(i).copied().unwrap_or(f64::INFINITY))
            }
            // A root at t ≈ 0, or a class in the band, may go either way.
            (Some(x), None) | (None, Some(x)) if e.in_band || x.abs() <= 1e-30 => Ok(()),
            (Some(_), None) => Err("a hit was missed".into()),
            (None, Some(g)) if *g <= 0.0 => Err("a hit at t ≤ 0 was returned".into()),
            (None, Some(_)) => Err("a hit where there is none".into()),
        },
        (_, _) if e.in_band => Ok(()),
        (_, Answer::Nearest(_) | Answer::Roots(_)) if matches!(expected, Answer::Everywhere) => {
            Err(
                "every t solves it (the ray lies on the surface), and the kernel says otherwise"
                    .into(),
            )
        }
        _ => Err(format!(
            "the kernel answers in the wrong semantics for {:?}",
            d.semantics
        )),
    };
    match verdict {
        Ok(()) => Verdict::Pass,
        Err(why) => fail(expected, &got, why),
    }
}

/// Whether every input is an integer of magnitude at most 16: then every
/// classification margin (a polynomial of degree at most 4 in them) is
/// computed exactly even in plain f32, so an exactly degenerate case (a ray
/// in the plane, a tangent, α = 0) must be classified exactly.
fn small_integers(c: &Case) -> bool {
    fields(c)
        .iter()
        .all(|&x| x.fract() == 0.0 && x.abs() <= 16.0)
}

/// Whether a class mismatch is forgiven: the exact margin within the band,
/// except an exactly zero margin on small-integer inputs.
fn in_band(margin: f64, band: f64, c: &Case) -> bool {
    if margin == 0.0 && small_integers(c) {
        return false;
    }
    margin.abs() <= band
}

/// The sphere's class band for outside kernels, in units of the margin
/// `aΔ = (aR)² − |af − bd|²`: `a²(R² + R|f|)·2⁻⁴⁴` before `band_scale`.
/// Near a tangent `|af − bd| ≈ aR`, and a careful kernel forms it with an
/// error of about `a|f|` times its precision, so its square errs by about
/// `2a²R|f|` times that. A band from `(a|f|)²` instead would forgive a
/// plain f32 kernel every class of a far sphere.
fn sphere_band(ray: &Ray, s: &Sphere) -> f64 {
    let d = ray.dir.as_dvec3();
    let f = ray.origin.as_dvec3() - s.center.as_dvec3();
    let (a, r) = (d.length_squared(), f64::from(s.radius).abs());
    a * a * (r * r + r * f.length()) * 2f64.powi(-44)
}

/// The plane's unit band on the margin `d·n`: `2⁻⁴⁴ Σ|dᵢnᵢ|`.
fn plane_band(ray: &Ray, p: &Plane) -> f64 {
    let s: f64 = (0..3)
        .map(|i| (f64::from(ray.dir[i]) * f64::from(p.normal[i])).abs())
        .sum();
    s * 2f64.powi(-44)
}

/// The quadric's unit band on the discriminant `β² − 4αγ`: `2⁻⁴⁰((Σ|β
/// terms|)² + 4 Σ|α terms| Σ|γ terms|)`.
fn quadric_band(ray: &Ray, q: &Quadric) -> f64 {
    let (a, b, g) = quadric::terms(ray, q);
    let sum = |x: &[f64]| x.iter().map(|x| x.abs()).sum::<f64>();
    let (sa, sb, sg) = (sum(&a), sum(&b), sum(&g));
    (sb * sb + 4.0 * sa * sg) * 2f64.powi(-40)
}

/// `Σ |kᵢ dⱼ dₖ|` over α's six terms: the scale α's rounding error is
/// relative to.
fn alpha_terms(ray: &Ray, q: &Quadric) -> f64 {
    let k = q.coeffs.map(f64::from);
    let dd = ray.dir.to_array().map(f64::from);
    (k[0] * dd[0] * dd[0]).abs()
        + (k[1] * dd[1] * dd[1]).abs()
        + (k[2] * dd[2] * dd[2]).abs()
        + (k[3] * dd[0] * dd[1]).abs()
        + (k[4] * dd[0] * dd[2]).abs()
        + (k[5] * dd[1] * dd[2]).abs()
}

fn judge_sphere(d: &Declared, ray: &Ray, s: &Sphere, got: Answer) -> Verdict {
    exact_sphere(d, ray, s).map_or(Verdict::Pass, |e| judge(d, &e, got))
}

fn judge_plane(d: &Declared, ray: &Ray, p: &Plane, got: Answer) -> Verdict {
    exact_plane(d, ray, p).map_or(Verdict::Pass, |e| judge(d, &e, got))
}

fn judge_quadric(d: &Declared, ray: &Ray, q: &Quadric, got: Answer) -> Verdict {
    exact_quadric(d, ray, q).map_or(Verdict::Pass, |e| judge(d, &e, got))
}

/// The exact answer a sphere case is judged against, or `None` where the
/// oracle has none (non-finite inputs): then any answer passes.
fn exact_sphere(d: &Declared, ray: &Ray, s: &Sphere) -> Option<Exact> {
    let Ok(q) = sphere::exact::quadratic(ray, s) else {
        return None;
    };
    let exact = sphere::exact::classify(&q);
    let margin = (&q.alpha * &q.discriminant()).mul_pow2(-2).to_f64();
    let kappa = match exact {
        SphereHit::Two(t0, t1) => vec![
            sphere::condition_at(ray, s, t0 as f64),
            sphere::condition_at(ray, s, t1 as f64),
        ],
        _ => vec![f64::INFINITY; 2],
    };
    let e = Exact {
        roots: Some(exact.roots().as_slice().to_vec()),
        in_band: in_band(
            margin,
            sphere_band(ray, s) * d.band_scale,
            &Case::Sphere(*ray, *s),
        ),
        alpha_small: false,
        kappa,
    };
    Some(e)
}

/// The exact answer a plane case is judged against, or `None` where the
/// oracle has none (non-finite inputs): then any answer passes.
fn exact_plane(d: &Declared, ray: &Ray, p: &Plane) -> Option<Exact> {
    let Ok(exact) = plane::exact::intersect(ray, p) else {
        return None;
    };
    let (Ok(dir), Ok(n)) = (vec3(ray.dir.to_array()), vec3(p.normal.to_array())) else {
        return None;
    };
    let margin = dot(&dir, &n).to_f64();
    let e = Exact {
        roots: (!matches!(exact, PlaneHit::InPlane)).then(|| exact.roots().as_slice().to_vec()),
        in_band: in_band(
            margin,
            plane_band(ray, p) * d.band_scale,
            &Case::Plane(*ray, *p),
        ),
        alpha_small: false,
        kappa: vec![super::plane_condition(ray, p)],
    };
    Some(e)
}

/// The exact answer a quadric case is judged against, or `None` where the
/// oracle has none (non-finite inputs): then any answer passes.
fn exact_quadric(d: &Declared, ray: &Ray, q: &Quadric) -> Option<Exact> {
    let Ok(eq) = quadric::exact::quadratic(ray, q) else {
        return None;
    };
    let exact = quadric::exact::classify(&eq);
    let margin = eq.discriminant().to_f64();
    // α within the band of its terms may be taken for 0 (a linear answer).
    let alpha_small =
        eq.alpha.to_f64().abs() <= alpha_terms(ray, q) * 2f64.powi(-44) * d.band_scale;
    let kappa = match exact {
        QuadricHit::Two(..) | QuadricHit::One(..) => quadric::condition(ray, q).to_vec(),
        _ => vec![f64::INFINITY; 2],
    };
    let e = Exact {
        roots: (!matches!(exact, QuadricHit::All)).then(|| exact.roots().as_slice().to_vec()),
        in_band: in_band(
            margin,
            quadric_band(ray, q) * d.band_scale,
            &Case::Quadric(*ray, *q),
        ),
        alpha_small: alpha_small && !small_integers(&Case::Quadric(*ray, *q)),
        kappa,
    };
    Some(e)
}

fn judge_camera(d: &Declared, p: &CameraParams, px: [u32; 2], got: Option<Ray>) -> Verdict {
    let exact = crate::camera::exact::ray(p, px[0], px[1]);
    match (exact, got) {
        (Err(_), None) => Verdict::Pass,
        (Err(e), Some(g)) => Verdict::Fail {
            expected: format!("no camera ({e})"),
            got: format!("{g:?}"),
            why: "the camera must refuse these parameters".into(),
        },
        (Ok(x), None) => Verdict::Fail {
            expected: format!("{x:?}"),
            got: "no camera".into(),
            why: "valid parameters were refused".into(),
        },
        (Ok(x), Some(g)) => {
            let Ok(cam) = p.build() else {
                return Verdict::Pass;
            };
            let scale = component_scale(&cam, px[0], px[1]);
            // The camera's components are judged like rayoracle's own (in
            // ulps of Sᵢ), with at least its reference's bound.
            let allowed = d.allowed_ulps(4.0).max(CAMERA_ULPS);
            let same_origin =
                g.origin.to_array().map(f32::to_bits) == x.origin.to_array().map(f32::to_bits);
            for (i, s) in scale.iter().enumerate() {
                let err = (f64::from(g.dir[i]) - f64::from(x.dir[i])).abs() / ulp_of(*s);
                if !(err <= allowed) || !same_origin {
                    return Verdict::Fail {
                        expected: format!("{x:?}"),
                        got: format!("{g:?}"),
                        why: format!(
                            "direction component {i} is {err:.1} ulps of its scale Sᵢ away, allowed {allowed:.1} (or the origin moved)"
                        ),
                    };
                }
            }
            Verdict::Pass
        }
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

/// Shrinks a failing case: each input in turn becomes 0, its nearest
/// integer, or keeps fewer significant bits, while the case still fails.
fn shrink(case: &Case, fails: &dyn Fn(&Case) -> bool) -> Case {
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
                if fails(&c) {
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
