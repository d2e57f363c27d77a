//! `rayoracle eval`: one case per input line in, one JSON line out, with
//! every implementation's result and its error against the exact oracle.
//!
//! ```text
//! {"line":N,"kind":K[,"family":F][,"id":I],"results":{"exact":{…},"reference":{…},…}}
//! {"line":N,"kind":"camera"[,"family":F],"error":"<field>: …"}   camera cannot be built
//! {"line":N,"error":"<field>: …"}                                 malformed line
//! ```
//!
//! * `exact` comes first, then every [`Implementation`] in
//!   [`Implementation::ALL`] order.
//! * A plane, sphere or quadric result is
//!   `{"class":C,"roots":[..],"roots_bits":["0x…",..]}`; a camera result is
//!   `{"class":"ray","origin":[..],"dir":[..],"dir_bits":[..]}`. Numbers are
//!   the shortest text that reads back as the same `f32` (`null` for NaN and
//!   ±∞); the `*_bits` strings are the exact bits.
//! * Each implementation then gets `"class_match"`: `true` with `"ulps"` and
//!   `"bits"` per root (per direction component for a camera) against the
//!   exact result, or `false` with `"ulps":null,"bits":null`.
//! * If the exact oracle cannot judge the input (NaN or ∞), `exact` is
//!   `{"error":…}` and the implementations carry no comparison.
//!
//! [`evaluate`] gives the typed [`LineReport`], [`eval_line`] its JSON, and
//! [`Summary`] tallies reports into a table.

pub mod x4;

use crate::Ray;
use crate::case::{Case, CaseError, Kind, match_case, parse_line};
use crate::hit::{Class, Intersection, Roots};
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use crate::primitive::Primitive;
use crate::{camera, ulp};
use serde::Serialize;
use serde::ser::{SerializeMap, Serializer};
use std::fmt::Write as _;

/// An implementation under test: one column of `eval` output. Adding an
/// implementation is adding a variant, its [`name`](Implementation::name),
/// its [`run`](Implementation::run) and an entry in [`ALL`](Implementation::ALL).
///
/// ```
/// use rayoracle::eval::Implementation;
/// assert_eq!(Implementation::ALL[0].name(), "reference");
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Implementation {
    /// The scalar references: `plane::reference`, `sphere::reference`,
    /// `quadric::reference` and `camera::Camera`.
    Reference,
    /// The four-lane SIMD kernels (`*::x4`). The case is run four times,
    /// once in each lane, with unrelated cases (a hit, a NaN, a miss or a
    /// tangent) in the other three lanes; all four placements must agree
    /// bit for bit, or the column reports an error.
    X4,
}

impl Implementation {
    /// Every implementation, in output order (after `exact`).
    ///
    /// ```
    /// use rayoracle::eval::Implementation;
    /// assert!(Implementation::ALL.contains(&Implementation::Reference));
    /// ```
    pub const ALL: &'static [Implementation] = &[Implementation::Reference, Implementation::X4];

    /// The key in `eval` output.
    ///
    /// ```
    /// use rayoracle::eval::Implementation;
    /// assert_eq!(Implementation::Reference.name(), "reference");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Implementation::Reference => "reference",
            Implementation::X4 => "x4",
        }
    }

    /// Runs this implementation on a case.
    ///
    /// ```
    /// # #[cfg(feature = "sphere")] {
    /// use rayoracle::case::parse_line;
    /// use rayoracle::eval::{Implementation, Outcome};
    /// use rayoracle::hit::{Class, Roots};
    /// let c = parse_line(r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#).unwrap();
    /// assert_eq!(
    ///     Implementation::Reference.run(&c.case),
    ///     Outcome::Hit { class: Class::Two, roots: Roots::two(4.0, 6.0) }
    /// );
    /// # }
    /// ```
    pub fn run(self, case: &Case) -> Outcome {
        match self {
            Implementation::Reference => match_case!(
                case,
                |r, p| Outcome::hit(&Primitive::reference(r, p)),
                |p, [px, py]| match p.build() {
                    Ok(cam) => Outcome::Ray(cam.ray(*px, *py)),
                    Err(e) => Outcome::Error(e.to_string()),
                },
            ),
            Implementation::X4 => x4::run(case),
        }
    }
}

/// The exact oracle's answer for a case: correctly rounded roots for the
/// primitives, the f64 camera oracle's ray for a camera.
///
/// ```
/// # #[cfg(feature = "plane")] {
/// use rayoracle::case::parse_line;
/// use rayoracle::eval::{exact, Outcome};
/// let c = parse_line(r#"{"kind":"plane","origin":[0,0,0],"dir":[0,0,1],"point":[0,0,2],"normal":[0,0,1]}"#).unwrap();
/// assert_eq!(exact(&c.case).class(), Some(rayoracle::hit::Class::Hit));
/// let nan = parse_line(r#"{"kind":"plane","origin":["nan",0,0],"dir":[0,0,1],"point":[0,0,2],"normal":[0,0,1]}"#).unwrap();
/// assert!(matches!(exact(&nan.case), Outcome::Error(_)));
/// # }
/// ```
pub fn exact(case: &Case) -> Outcome {
    match_case!(case, |r, p| exact_of(r, p), |p, [px, py]| {
        camera::exact::ray(p, *px, *py).map_or_else(|e| Outcome::Error(e.to_string()), Outcome::Ray)
    },)
}

/// [`exact`] for a ray and a primitive.
///
/// ```
/// # #[cfg(feature = "plane")] {
/// use rayoracle::{Ray, eval::{exact_of, Outcome}, hit::{Class, Roots}, plane::Plane};
/// use glam::Vec3;
/// let p = Plane::new(Vec3::new(0.0, 0.0, 2.0), Vec3::Z);
/// let o = exact_of(&Ray::new(Vec3::ZERO, Vec3::Z), &p);
/// assert_eq!(o, Outcome::Hit { class: Class::Hit, roots: Roots::one(2.0) });
/// # }
/// ```
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
pub fn exact_of<P: Primitive>(ray: &Ray, p: &P) -> Outcome {
    P::exact(ray, p).map_or_else(|e| Outcome::Error(e.to_string()), |h| Outcome::hit(&h))
}

/// What one implementation (or the exact oracle) produced for one case.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::eval::Outcome;
/// use rayoracle::hit::{Class, Roots};
/// use rayoracle::sphere::SphereHit;
/// let o = Outcome::hit(&SphereHit::Tangent(5.0));
/// assert_eq!(o, Outcome::Hit { class: Class::Tangent, roots: Roots::one(5.0) });
/// assert_eq!(o.class(), Some(Class::Tangent));
/// # }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Outcome {
    /// A classified plane, sphere or quadric result.
    Hit {
        /// The class ([`Intersection::class`]).
        class: Class,
        /// The roots, ascending.
        roots: Roots,
    },
    /// A camera ray.
    Ray(Ray),
    /// No result; the message says why.
    Error(String),
}

impl Outcome {
    /// The outcome of an [`Intersection`].
    ///
    /// ```
    /// # #[cfg(feature = "plane")] {
    /// use rayoracle::eval::Outcome;
    /// use rayoracle::plane::PlaneHit;
    /// assert_eq!(Outcome::hit(&PlaneHit::Parallel).class(), Some(rayoracle::hit::Class::Parallel));
    /// # }
    /// ```
    pub fn hit(h: &impl Intersection) -> Outcome {
        Outcome::Hit {
            class: h.class(),
            roots: h.roots(),
        }
    }

    /// The class ([`Class::Ray`] for a camera ray), or `None` for an error.
    ///
    /// ```
    /// use rayoracle::eval::Outcome;
    /// assert_eq!(Outcome::Error("no".into()).class(), None);
    /// ```
    pub fn class(&self) -> Option<Class> {
        match self {
            Outcome::Hit { class, .. } => Some(*class),
            Outcome::Ray(_) => Some(Class::Ray),
            Outcome::Error(_) => None,
        }
    }

    /// The values compared against the exact result: the roots, or a camera
    /// ray's direction components; empty for an error.
    ///
    /// ```
    /// use rayoracle::eval::Outcome;
    /// use rayoracle::Ray;
    /// use glam::Vec3;
    /// let o = Outcome::Ray(Ray::new(Vec3::ZERO, Vec3::new(1.0, 2.0, 3.0)));
    /// assert_eq!(o.values(), vec![1.0, 2.0, 3.0]);
    /// ```
    pub fn values(&self) -> Vec<f32> {
        match self {
            Outcome::Hit { roots, .. } => roots.as_slice().to_vec(),
            Outcome::Ray(r) => r.dir.to_array().to_vec(),
            Outcome::Error(_) => Vec::new(),
        }
    }

    /// Whether two outcomes are the same class with the same bits (any NaN
    /// equal to any NaN; `+0` and `−0` differ): the bit-identity that x4
    /// owes the reference.
    ///
    /// ```
    /// use rayoracle::eval::Outcome;
    /// use rayoracle::hit::{Class, Roots};
    /// let a = Outcome::Hit { class: Class::Hit, roots: Roots::one(0.0) };
    /// let b = Outcome::Hit { class: Class::Hit, roots: Roots::one(-0.0) };
    /// assert!(a.same_bits(&a) && !a.same_bits(&b));
    /// let n = Outcome::Hit { class: Class::Hit, roots: Roots::one(f32::NAN) };
    /// assert!(n.same_bits(&Outcome::Hit { class: Class::Hit, roots: Roots::one(-f32::NAN) }));
    /// ```
    pub fn same_bits(&self, other: &Outcome) -> bool {
        let bits = |o: &Outcome| -> Vec<u32> {
            o.values()
                .iter()
                .map(|v| if v.is_nan() { u32::MAX } else { v.to_bits() })
                .collect()
        };
        self.class() == other.class() && bits(self) == bits(other)
    }
}

/// How an implementation's outcome compares with the exact one.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::eval::{compare, Comparison, Outcome};
/// use rayoracle::sphere::SphereHit;
/// let exact = Outcome::hit(&SphereHit::Two(4.0, 6.0));
/// let near = Outcome::hit(&SphereHit::Two(4.0, 6.0000005));
/// assert_eq!(compare(&exact, &near), Comparison::Ulps(vec![0, 1]));
/// # }
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Comparison {
    /// The exact oracle has no answer, so nothing is compared.
    NotCompared,
    /// The classes differ (or the implementation failed).
    ClassMismatch,
    /// The classes agree; ULP distance per root or component.
    Ulps(Vec<u64>),
}

/// Compares an implementation's outcome with the exact one: the class
/// first, then [`ulp::ulps`] value by value.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::eval::{compare, Comparison, Outcome};
/// use rayoracle::sphere::SphereHit;
/// let exact = Outcome::hit(&SphereHit::Tangent(5.0));
/// assert_eq!(compare(&exact, &Outcome::hit(&SphereHit::None)), Comparison::ClassMismatch);
/// assert_eq!(compare(&Outcome::Error("x".into()), &exact), Comparison::NotCompared);
/// # }
/// ```
pub fn compare(exact: &Outcome, other: &Outcome) -> Comparison {
    match (exact.class(), other.class()) {
        (None, _) => Comparison::NotCompared,
        (Some(a), Some(b)) if a == b => Comparison::Ulps(
            exact
                .values()
                .iter()
                .zip(other.values())
                .map(|(&e, o)| ulp::ulps(e, o))
                .collect(),
        ),
        _ => Comparison::ClassMismatch,
    }
}

/// One implementation's column: its outcome and how it compares.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::case::parse_line;
/// use rayoracle::eval::{evaluate, Comparison, LineReport};
/// let line = r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#;
/// let Some(LineReport::Evaluated(e)) = evaluate(1, line) else { panic!() };
/// assert_eq!(e.columns[0].comparison, Comparison::Ulps(vec![0, 0]));
/// # }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Column {
    /// Which implementation.
    pub implementation: Implementation,
    /// What it produced.
    pub outcome: Outcome,
    /// Against the exact outcome.
    pub comparison: Comparison,
}

/// A case that was evaluated: the exact outcome and one column per
/// implementation, in [`Implementation::ALL`] order.
///
/// ```
/// # #[cfg(feature = "quadric")] {
/// use rayoracle::{case::Kind, eval::{evaluate, LineReport}};
/// let line = r#"{"kind":"quadric","family":"cyl","origin":[-5,0,0],"dir":[1,0,0],"coeffs":[1,1,0,0,0,0,0,0,0,-1]}"#;
/// let Some(LineReport::Evaluated(e)) = evaluate(7, line) else { panic!() };
/// assert_eq!((e.line, e.kind, e.family.as_deref()), (7, Kind::Quadric, Some("cyl")));
/// assert_eq!(e.exact.values(), vec![4.0, 6.0]);
/// # }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Evaluation {
    /// 1-based input line number.
    pub line: usize,
    /// The case's kind.
    pub kind: Kind,
    /// The case's `family`, if given.
    pub family: Option<String>,
    /// The case's `id`, if given.
    pub id: Option<u64>,
    /// The exact oracle's outcome.
    pub exact: Outcome,
    /// One column per implementation.
    pub columns: Vec<Column>,
}

/// The typed result of one non-blank input line.
///
/// ```
/// use rayoracle::eval::{evaluate, LineReport};
/// let r = evaluate(3, r#"{"kind":"sphere","origin":[0,0,0],"dir":[0,0,1],"center":[0,0,0]}"#).unwrap();
/// assert!(r.is_error());
/// assert_eq!(r.line(), 3);
/// assert!(evaluate(4, "   ").is_none());
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum LineReport {
    /// The line is not a valid case.
    Malformed {
        /// 1-based line number.
        line: usize,
        /// What is wrong, naming the field.
        error: CaseError,
    },
    /// The line is a well-formed case that has no meaning (a camera that
    /// cannot be built).
    Invalid {
        /// 1-based line number.
        line: usize,
        /// The case's kind.
        kind: Kind,
        /// The case's `family`, if given.
        family: Option<String>,
        /// Why, starting with the field name.
        error: String,
    },
    /// The evaluation itself failed (a panic in an implementation, caught).
    Internal {
        /// 1-based line number.
        line: usize,
        /// The panic message.
        error: String,
    },
    /// The case was evaluated.
    Evaluated(Evaluation),
}

impl LineReport {
    /// The 1-based input line number.
    ///
    /// ```
    /// use rayoracle::eval::evaluate;
    /// assert_eq!(evaluate(12, "{").unwrap().line(), 12);
    /// ```
    pub fn line(&self) -> usize {
        match self {
            LineReport::Malformed { line, .. }
            | LineReport::Invalid { line, .. }
            | LineReport::Internal { line, .. } => *line,
            LineReport::Evaluated(e) => e.line,
        }
    }

    /// Whether the line could not be evaluated (the output line has a
    /// top-level `"error"`). An input the exact oracle cannot judge (NaN, ∞)
    /// is still evaluated: its error is inside `results.exact`.
    ///
    /// ```
    /// # #[cfg(feature = "sphere")] {
    /// use rayoracle::eval::evaluate;
    /// let nan = r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":"nan"}"#;
    /// assert!(!evaluate(1, nan).unwrap().is_error());
    /// assert!(evaluate(1, "[]").unwrap().is_error());
    /// # }
    /// ```
    pub fn is_error(&self) -> bool {
        !matches!(self, LineReport::Evaluated(_))
    }

    /// The JSON line (no newline).
    ///
    /// ```
    /// use rayoracle::eval::evaluate;
    /// assert_eq!(evaluate(2, "{}").unwrap().to_json(), r#"{"line":2,"error":"kind: missing"}"#);
    /// ```
    pub fn to_json(&self) -> String {
        self.to_json_in(None)
    }

    /// The JSON line with a leading `"file"` key when `file` is given, for
    /// output that merges several input files.
    ///
    /// ```
    /// use rayoracle::eval::evaluate;
    /// assert_eq!(
    ///     evaluate(2, "{}").unwrap().to_json_in(Some("a.jsonl")),
    ///     r#"{"file":"a.jsonl","line":2,"error":"kind: missing"}"#
    /// );
    /// ```
    pub fn to_json_in(&self, file: Option<&str>) -> String {
        let json = match self {
            LineReport::Malformed { line, error } => serde_json::to_string(&ErrorJson {
                file,
                line: *line,
                kind: None,
                family: None,
                error: &error.to_string(),
            }),
            LineReport::Invalid {
                line,
                kind,
                family,
                error,
            } => serde_json::to_string(&ErrorJson {
                file,
                line: *line,
                kind: Some(kind.as_str()),
                family: family.as_deref(),
                error,
            }),
            LineReport::Internal { line, error } => serde_json::to_string(&ErrorJson {
                file,
                line: *line,
                kind: None,
                family: None,
                error,
            }),
            LineReport::Evaluated(e) => serde_json::to_string(&EvaluationJson {
                file,
                line: e.line,
                kind: e.kind.as_str(),
                family: e.family.as_deref(),
                id: e.id,
                results: ResultsJson(e),
            }),
        };
        // Every value above is a string, number, bool, null or a sequence or
        // map of them with string keys: serialisation cannot fail.
        json.unwrap_or_else(|e| format!(r#"{{"error":"internal: {e}"}}"#))
    }
}

/// Evaluates one input line: `None` for a blank line (only whitespace),
/// otherwise the [`LineReport`]. Never panics: a panic inside an
/// implementation becomes [`LineReport::Internal`].
///
/// ```
/// use rayoracle::eval::{evaluate, LineReport, Outcome};
/// let line = r#"{"kind":"camera","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[3,3],"pixel":[1,1]}"#;
/// let Some(LineReport::Evaluated(e)) = evaluate(1, line) else { panic!() };
/// assert!(matches!(e.exact, Outcome::Ray(r) if r.dir.z == -1.0));
/// ```
pub fn evaluate(line_no: usize, line: &str) -> Option<LineReport> {
    if line.trim().is_empty() {
        return None;
    }
    let parsed = match parse_line(line) {
        Ok(c) => c,
        Err(error) => {
            return Some(LineReport::Malformed {
                line: line_no,
                error,
            });
        }
    };
    let run = || {
        let case = &parsed.case;
        if let Case::Camera(p, _) = case
            && let Err(e) = p.build()
        {
            return LineReport::Invalid {
                line: line_no,
                kind: case.kind(),
                family: parsed.family.clone(),
                error: e.to_string(),
            };
        }
        let exact = exact(case);
        let columns = Implementation::ALL
            .iter()
            .map(|&implementation| {
                let outcome = implementation.run(case);
                let comparison = compare(&exact, &outcome);
                Column {
                    implementation,
                    outcome,
                    comparison,
                }
            })
            .collect();
        LineReport::Evaluated(Evaluation {
            line: line_no,
            kind: case.kind(),
            family: parsed.family.clone(),
            id: parsed.id,
            exact,
            columns,
        })
    };
    Some(std::panic::catch_unwind(run).unwrap_or_else(|payload| {
        let msg = payload
            .downcast_ref::<&str>()
            .map(|s| s.to_string())
            .or_else(|| payload.downcast_ref::<String>().cloned())
            .unwrap_or_else(|| "unknown panic".to_string());
        LineReport::Internal {
            line: line_no,
            error: format!("internal error: {msg}"),
        }
    }))
}

/// Evaluates one input line and returns its JSON line (no newline); the
/// empty string for a blank line, which produces no output.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::eval::eval_line;
/// let out = eval_line(1, r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#);
/// assert_eq!(out, concat!(
///     r#"{"line":1,"kind":"sphere","results":{"#,
///     r#""exact":{"class":"two","roots":[4.0,6.0],"roots_bits":["0x40800000","0x40c00000"]},"#,
///     r#""reference":{"class":"two","roots":[4.0,6.0],"roots_bits":["0x40800000","0x40c00000"],"#,
///     r#""class_match":true,"ulps":[0,0],"bits":[0.0,0.0]},"#,
///     r#""x4":{"class":"two","roots":[4.0,6.0],"roots_bits":["0x40800000","0x40c00000"],"#,
///     r#""class_match":true,"ulps":[0,0],"bits":[0.0,0.0]}}}"#,
/// ));
/// assert_eq!(eval_line(3, r#"{"kind":"sphere"}"#), r#"{"line":3,"error":"origin: missing"}"#);
/// assert_eq!(eval_line(4, "  "), "");
/// # }
/// ```
pub fn eval_line(line_no: usize, line: &str) -> String {
    evaluate(line_no, line)
        .map(|r| r.to_json())
        .unwrap_or_default()
}

// ---------------------------------------------------------------------------
// JSON shapes. Field order here is the output's key order.

#[derive(Serialize)]
struct ErrorJson<'a> {
    #[serde(skip_serializing_if = "Option::is_none")]
    file: Option<&'a str>,
    line: usize,
    #[serde(skip_serializing_if = "Option::is_none")]
    kind: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    family: Option<&'a str>,
    error: &'a str,
}

#[derive(Serialize)]
struct EvaluationJson<'a> {
    #[serde(skip_serializing_if = "Option::is_none")]
    file: Option<&'a str>,
    line: usize,
    kind: &'a str,
    #[serde(skip_serializing_if = "Option::is_none")]
    family: Option<&'a str>,
    #[serde(skip_serializing_if = "Option::is_none")]
    id: Option<u64>,
    results: ResultsJson<'a>,
}

/// `{"exact":…, <implementation>:…, …}` in that order.
struct ResultsJson<'a>(&'a Evaluation);

impl Serialize for ResultsJson<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let e = self.0;
        let mut map = s.serialize_map(Some(1 + e.columns.len()))?;
        map.serialize_entry("exact", &OutcomeJson::new(&e.exact, None))?;
        for c in &e.columns {
            map.serialize_entry(
                c.implementation.name(),
                &OutcomeJson::new(&c.outcome, Some(&c.comparison)),
            )?;
        }
        map.end()
    }
}

fn bits_str(x: f32) -> String {
    format!("{:#010x}", x.to_bits())
}

/// The comparison keys: absent (`None`), or `class_match` with `ulps` and
/// `bits` that are `null` on a mismatch.
#[derive(Serialize)]
struct ComparisonJson {
    class_match: bool,
    ulps: Option<Vec<u64>>,
    bits: Option<Vec<f64>>,
}

impl ComparisonJson {
    fn new(c: &Comparison) -> Option<ComparisonJson> {
        match c {
            Comparison::NotCompared => None,
            Comparison::ClassMismatch => Some(ComparisonJson {
                class_match: false,
                ulps: None,
                bits: None,
            }),
            Comparison::Ulps(u) => Some(ComparisonJson {
                class_match: true,
                ulps: Some(u.clone()),
                bits: Some(u.iter().map(|&u| ulp::bits(u)).collect()),
            }),
        }
    }
}

#[derive(Serialize)]
#[serde(untagged)]
enum OutcomeJson {
    Hit {
        class: &'static str,
        roots: Vec<f32>,
        roots_bits: Vec<String>,
        #[serde(flatten)]
        cmp: Option<ComparisonJson>,
    },
    Ray {
        class: &'static str,
        origin: [f32; 3],
        dir: [f32; 3],
        dir_bits: [String; 3],
        #[serde(flatten)]
        cmp: Option<ComparisonJson>,
    },
    Error {
        error: String,
        #[serde(flatten)]
        cmp: Option<ComparisonJson>,
    },
}

impl OutcomeJson {
    fn new(o: &Outcome, c: Option<&Comparison>) -> OutcomeJson {
        let cmp = c.and_then(ComparisonJson::new);
        match o {
            Outcome::Hit { class, roots } => OutcomeJson::Hit {
                class: class.as_str(),
                roots: roots.as_slice().to_vec(),
                roots_bits: roots.as_slice().iter().map(|&t| bits_str(t)).collect(),
                cmp,
            },
            Outcome::Ray(r) => OutcomeJson::Ray {
                class: Class::Ray.as_str(),
                origin: r.origin.to_array(),
                dir: r.dir.to_array(),
                dir_bits: r.dir.to_array().map(bits_str),
                cmp,
            },
            Outcome::Error(e) => OutcomeJson::Error {
                error: e.clone(),
                cmp,
            },
        }
    }
}

// ---------------------------------------------------------------------------
// Summary.

/// Per kind and implementation: how its results compare with the exact ones.
///
/// ```
/// use rayoracle::eval::ImplTally;
/// let t = ImplTally::default();
/// assert_eq!((t.compared, t.class_mismatches, t.values, t.zero_ulp, t.max_ulps), (0, 0, 0, 0, 0));
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ImplTally {
    /// Cases compared (the exact oracle had an answer).
    pub compared: usize,
    /// Compared cases whose class differs from the exact one.
    pub class_mismatches: usize,
    /// Roots (or camera components) compared, in cases whose class matched.
    pub values: usize,
    /// Of those, how many are at 0 ulps.
    pub zero_ulp: usize,
    /// The largest ULP distance seen (`u64::MAX`: a NaN against a number).
    pub max_ulps: u64,
}

/// Per kind: cases, errors, and one [`ImplTally`] per implementation.
///
/// ```
/// use rayoracle::eval::KindTally;
/// assert_eq!(KindTally::default().cases, 0);
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct KindTally {
    /// Well-formed lines of this kind.
    pub cases: usize,
    /// Of those, how many have no exact answer (NaN/∞ input) or no meaning
    /// (a camera that cannot be built).
    pub errors: usize,
    /// Per implementation, in [`Implementation::ALL`] order.
    pub impls: Vec<ImplTally>,
}

/// Tallies [`LineReport`]s and renders a plain-text table.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::{case::Kind, eval::{evaluate, Summary}};
/// let mut s = Summary::default();
/// s.add(&evaluate(1, r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#).unwrap());
/// s.add(&evaluate(2, r#"{"kind":"sphere"}"#).unwrap());
/// assert_eq!(s.kind(Kind::Sphere).cases, 1);
/// let t = &s.kind(Kind::Sphere).impls[0];
/// assert_eq!((t.compared, t.values, t.zero_ulp), (1, 2, 2));
/// assert_eq!(s.malformed, 1);
/// assert!(!s.all_ok());
/// assert!(s.render().contains("sphere"));
/// # }
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Summary {
    /// Non-blank lines seen.
    pub lines: usize,
    /// Lines that are not valid cases.
    pub malformed: usize,
    /// Well-formed cases that have no meaning (a camera that cannot be
    /// built); also counted in their kind's `cases` and `errors`.
    pub invalid: usize,
    /// Lines whose evaluation panicked (caught).
    pub internal: usize,
    /// Per kind, in [`Kind::ALL`] order.
    pub kinds: [KindTally; 4],
}

impl Summary {
    /// The tally for `kind`.
    ///
    /// ```
    /// use rayoracle::{case::Kind, eval::Summary};
    /// assert_eq!(Summary::default().kind(Kind::Plane).cases, 0);
    /// ```
    pub fn kind(&self, kind: Kind) -> &KindTally {
        &self.kinds[kind as usize]
    }

    fn kind_mut(&mut self, kind: Kind) -> &mut KindTally {
        let t = &mut self.kinds[kind as usize];
        if t.impls.len() < Implementation::ALL.len() {
            t.impls
                .resize(Implementation::ALL.len(), ImplTally::default());
        }
        t
    }

    /// Adds one line's report.
    ///
    /// ```
    /// # #[cfg(feature = "plane")] {
    /// use rayoracle::{case::Kind, eval::{evaluate, Summary}};
    /// let mut s = Summary::default();
    /// s.add(&evaluate(1, r#"{"kind":"plane","origin":[0,0,0],"dir":[0,0,1],"point":[0,0,3],"normal":["inf",0,1]}"#).unwrap());
    /// assert_eq!(s.kind(Kind::Plane).errors, 1);
    /// s.add(&evaluate(2, r#"{"kind":"plane","origin":[0,0,0],"dir":[0,0,1],"point":[0,0,3],"normal":[0,0,1]}"#).unwrap());
    /// assert_eq!((s.lines, s.kind(Kind::Plane).cases), (2, 2));
    /// assert!(s.all_ok());
    /// # }
    /// ```
    pub fn add(&mut self, report: &LineReport) {
        self.lines += 1;
        match report {
            LineReport::Malformed { .. } => self.malformed += 1,
            LineReport::Internal { .. } => self.internal += 1,
            LineReport::Invalid { kind, .. } => {
                self.invalid += 1;
                let t = self.kind_mut(*kind);
                t.cases += 1;
                t.errors += 1;
            }
            LineReport::Evaluated(e) => {
                let t = self.kind_mut(e.kind);
                t.cases += 1;
                if matches!(e.exact, Outcome::Error(_)) {
                    t.errors += 1;
                }
                for c in &e.columns {
                    let Some(i) = Implementation::ALL
                        .iter()
                        .position(|&x| x == c.implementation)
                    else {
                        continue;
                    };
                    let it = &mut t.impls[i];
                    match &c.comparison {
                        Comparison::NotCompared => {}
                        Comparison::ClassMismatch => {
                            it.compared += 1;
                            it.class_mismatches += 1;
                        }
                        Comparison::Ulps(u) => {
                            it.compared += 1;
                            it.values += u.len();
                            it.zero_ulp += u.iter().filter(|&&x| x == 0).count();
                            it.max_ulps = it.max_ulps.max(u.iter().copied().max().unwrap_or(0));
                        }
                    }
                }
            }
        }
    }

    /// Whether every line was evaluated (no malformed line, no camera that
    /// cannot be built, no internal error). NaN/∞ inputs do not count
    /// against this: they are evaluated, and only the exact oracle declines.
    ///
    /// ```
    /// use rayoracle::eval::{evaluate, Summary};
    /// let mut s = Summary::default();
    /// assert!(s.all_ok());
    /// s.add(&evaluate(1, "not json").unwrap());
    /// assert!(!s.all_ok());
    /// ```
    pub fn all_ok(&self) -> bool {
        self.malformed == 0 && self.invalid == 0 && self.internal == 0
    }

    /// A short plain-text table, one row per kind and implementation, and a
    /// line for malformed input.
    ///
    /// ```
    /// # #[cfg(feature = "plane")] {
    /// use rayoracle::eval::{evaluate, Summary};
    /// let mut s = Summary::default();
    /// s.add(&evaluate(1, r#"{"kind":"plane","origin":[0,0,0],"dir":[0,0,1],"point":[0,0,3],"normal":[0,0,1]}"#).unwrap());
    /// let table = s.render();
    /// assert!(table.lines().next().unwrap().starts_with("kind"));
    /// assert!(table.contains("plane"));
    /// assert!(table.contains("reference"));
    /// # }
    /// ```
    pub fn render(&self) -> String {
        let mut out = String::new();
        let _ = writeln!(
            out,
            "{:<8} {:>6} {:>6}  {:<10} {:>8} {:>7} {:>7} {:>9}",
            "kind", "cases", "errors", "impl", "mismatch", "values", "0-ulp", "max-ulps"
        );
        for (kind, t) in Kind::ALL.iter().zip(&self.kinds) {
            if t.cases == 0 {
                continue;
            }
            for (i, imp) in Implementation::ALL.iter().enumerate() {
                let it = t.impls.get(i).cloned().unwrap_or_default();
                let (k, c, e) = if i == 0 {
                    (kind.to_string(), t.cases.to_string(), t.errors.to_string())
                } else {
                    (String::new(), String::new(), String::new())
                };
                let max = if it.max_ulps == u64::MAX {
                    "nan".to_string()
                } else {
                    it.max_ulps.to_string()
                };
                let _ = writeln!(
                    out,
                    "{:<8} {:>6} {:>6}  {:<10} {:>8} {:>7} {:>7} {:>9}",
                    k,
                    c,
                    e,
                    imp.name(),
                    it.class_mismatches,
                    it.values,
                    it.zero_ulp,
                    max
                );
            }
        }
        let _ = write!(
            out,
            "{} non-blank lines, {} malformed",
            self.lines, self.malformed
        );
        if self.invalid > 0 {
            let _ = write!(out, ", {} invalid", self.invalid);
        }
        if self.internal > 0 {
            let _ = write!(out, ", {} internal errors", self.internal);
        }
        out.push('\n');
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    /// Every kind of line lands in its own counter, once per line.
    #[test]
    fn summary_counts_each_kind_of_line() {
        let mut s = Summary::default();
        let internal = || LineReport::Internal {
            line: 1,
            error: "boom".into(),
        };
        let invalid = || LineReport::Invalid {
            line: 2,
            kind: Kind::Camera,
            family: None,
            error: "angle".into(),
        };
        for _ in 0..2 {
            s.add(&internal());
            s.add(&invalid());
        }
        s.add(&evaluate(3, "{").unwrap());
        let cam = s.kind(Kind::Camera);
        assert_eq!(
            (
                s.lines,
                s.internal,
                s.invalid,
                s.malformed,
                cam.cases,
                cam.errors
            ),
            (5, 2, 2, 1, 2, 2)
        );
        assert!(!s.all_ok());
    }

    /// The table shows a NaN-against-number maximum as `nan`, and the
    /// invalid and internal counts only when there are some.
    #[test]
    fn summary_render_shows_nan_and_only_nonzero_problem_counts() {
        let mut s = Summary {
            lines: 3,
            ..Summary::default()
        };
        s.kinds[0].cases = 3;
        s.kinds[0].impls = vec![
            ImplTally {
                max_ulps: u64::MAX,
                ..ImplTally::default()
            },
            ImplTally {
                max_ulps: 7,
                ..ImplTally::default()
            },
        ];
        let t = s.render();
        assert!(t.contains(" nan\n") && t.contains(" 7\n"), "{t}");
        assert!(t.ends_with("3 non-blank lines, 0 malformed\n"), "{t}");
        s.invalid = 1;
        s.internal = 2;
        let t = s.render();
        assert!(t.ends_with(", 1 invalid, 2 internal errors\n"), "{t}");
    }

    /// A class mismatch is tallied as compared and mismatched, for each
    /// implementation, twice over two lines: an exact tangent answered with
    /// two roots by both columns.
    #[cfg(feature = "sphere")]
    #[test]
    fn summary_tallies_class_mismatches() {
        let column = |implementation| Column {
            implementation,
            outcome: Outcome::Hit {
                class: Class::Two,
                roots: Roots::two(4.0, 6.0),
            },
            comparison: Comparison::ClassMismatch,
        };
        let r = LineReport::Evaluated(Evaluation {
            line: 1,
            kind: Kind::Sphere,
            family: None,
            id: None,
            exact: Outcome::Hit {
                class: Class::Tangent,
                roots: Roots::one(5.0),
            },
            columns: vec![
                column(Implementation::Reference),
                column(Implementation::X4),
            ],
        });
        let mut s = Summary::default();
        s.add(&r);
        s.add(&r);
        let impls = &s.kind(Kind::Sphere).impls;
        assert_eq!(impls.len(), 2);
        for t in impls {
            assert_eq!((t.compared, t.class_mismatches, t.values), (2, 2, 0));
        }
    }

    fn num(bits: u32) -> String {
        format!("\"{:#010x}\"", bits)
    }

    fn nums(bits: &[u32]) -> String {
        bits.iter().map(|&b| num(b)).collect::<Vec<_>>().join(",")
    }

    /// Interesting floats more often than uniform bits would give them.
    fn any_bits() -> impl Strategy<Value = u32> {
        prop_oneof![
            any::<u32>(),
            prop::sample::select(vec![
                0u32,
                0x8000_0000,
                1,
                0x7f7f_ffff,
                0xff7f_ffff,
                0x7f80_0000,
                0x7fc0_0000,
                0x3f80_0000,
                0xbf80_0000,
                0x0080_0000,
            ]),
            (-4i32..4).prop_map(|i| (i as f32).to_bits()),
        ]
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 300, .. ProptestConfig::default() })]

        #[test]
        fn arbitrary_inputs_are_evaluated_without_panics(
            v in prop::collection::vec(any_bits(), 16),
            kind in 0usize..4,
            px in 0u32..4,
        ) {
            let line = match kind {
                0 => format!(r#"{{"kind":"plane","origin":[{}],"dir":[{}],"point":[{}],"normal":[{}]}}"#,
                    nums(&v[0..3]), nums(&v[3..6]), nums(&v[6..9]), nums(&v[9..12])),
                1 => format!(r#"{{"kind":"sphere","origin":[{}],"dir":[{}],"center":[{}],"radius":{}}}"#,
                    nums(&v[0..3]), nums(&v[3..6]), nums(&v[6..9]), num(v[9])),
                2 => format!(r#"{{"kind":"quadric","origin":[{}],"dir":[{}],"coeffs":[{}]}}"#,
                    nums(&v[0..3]), nums(&v[3..6]), nums(&v[6..16])),
                _ => format!(r#"{{"kind":"camera","position":[{}],"dir":[{}],"up":[{}],"angle":{},"res":[4,4],"pixel":[{px},3]}}"#,
                    nums(&v[0..3]), nums(&v[3..6]), nums(&v[6..9]), num(v[9])),
            };
            // Whatever the implementations do (even panic), evaluation gives
            // one well-formed JSON line for this line; a kind that is
            // compiled out is a malformed `kind`.
            let report = evaluate(1, &line).unwrap();
            match &report {
                LineReport::Malformed { error, .. } => {
                    prop_assert!(error.field == "kind" && !Kind::ALL[kind].compiled_in(), "{line}: {report:?}");
                }
                _ => prop_assert!(Kind::ALL[kind].compiled_in(), "{line}: {report:?}"),
            }
            let json: serde_json::Value = serde_json::from_str(&report.to_json()).unwrap();
            prop_assert_eq!(json["line"].as_u64(), Some(1));
            match &report {
                LineReport::Evaluated(e) => {
                    let keys: Vec<&String> = json["results"].as_object().unwrap().keys().collect();
                    prop_assert_eq!(keys.len(), 1 + Implementation::ALL.len());
                    prop_assert_eq!(e.columns.len(), Implementation::ALL.len());
                    prop_assert_eq!(json["kind"].as_str(), Some(e.kind.as_str()));
                }
                LineReport::Internal { error, .. } => {
                    prop_assert!(json["error"].as_str().unwrap().starts_with("internal error: "), "{error}");
                }
                _ => {}
            }
        }
    }

    /// Regression: the exact oracle's `round_to_f32` used to gallop downward
    /// forever when the root lies in `(−MAX − ulp/2, −MAX)` (it must round
    /// to `−MAX`): "attempt to multiply with overflow" in debug builds, an
    /// endless loop in release builds. Found by the random-input property
    /// above; here `t = −MAX − p/3` for a tiny `p`.
    #[cfg(feature = "plane")]
    #[test]
    fn a_root_just_below_minus_max_rounds_to_minus_max() {
        let line = r#"{"kind":"plane","origin":[0,"0x7f7fffff",0],"dir":[-1,0,-2],"point":["0x3498c525",0,0],"normal":[-1,3,-1]}"#;
        let Some(LineReport::Evaluated(e)) = evaluate(1, line) else {
            panic!("not evaluated: {}", eval_line(1, line));
        };
        assert_eq!(
            e.exact,
            Outcome::Hit {
                class: Class::Hit,
                roots: Roots::one(-f32::MAX)
            }
        );
    }

    #[test]
    fn a_class_mismatch_has_null_ulps_and_bits() {
        let e = Evaluation {
            line: 5,
            kind: Kind::Plane,
            family: None,
            id: None,
            exact: Outcome::Hit {
                class: Class::Hit,
                roots: Roots::one(1.0),
            },
            columns: vec![Column {
                implementation: Implementation::Reference,
                outcome: Outcome::Hit {
                    class: Class::Parallel,
                    roots: Roots::none(),
                },
                comparison: Comparison::ClassMismatch,
            }],
        };
        let r = LineReport::Evaluated(e);
        assert_eq!(
            r.to_json(),
            r#"{"line":5,"kind":"plane","results":{"exact":{"class":"hit","roots":[1.0],"roots_bits":["0x3f800000"]},"reference":{"class":"parallel","roots":[],"roots_bits":[],"class_match":false,"ulps":null,"bits":null}}}"#
        );
        let mut s = Summary::default();
        s.add(&r);
        let t = &s.kind(Kind::Plane).impls[0];
        assert_eq!((t.compared, t.class_mismatches, t.values), (1, 1, 0));
    }

    #[test]
    fn non_finite_roots_are_null_with_exact_bits_and_nan_ulps_render_as_nan() {
        let e = Evaluation {
            line: 1,
            kind: Kind::Sphere,
            family: None,
            id: None,
            exact: Outcome::Hit {
                class: Class::Two,
                roots: Roots::two(1.0, f32::INFINITY),
            },
            columns: vec![Column {
                implementation: Implementation::Reference,
                outcome: Outcome::Hit {
                    class: Class::Two,
                    roots: Roots::two(f32::NAN, f32::INFINITY),
                },
                comparison: compare(
                    &Outcome::Hit {
                        class: Class::Two,
                        roots: Roots::two(1.0, f32::INFINITY),
                    },
                    &Outcome::Hit {
                        class: Class::Two,
                        roots: Roots::two(f32::NAN, f32::INFINITY),
                    },
                ),
            }],
        };
        let r = LineReport::Evaluated(e);
        let json = r.to_json();
        assert!(json.contains(r#""exact":{"class":"two","roots":[1.0,null],"roots_bits":["0x3f800000","0x7f800000"]}"#), "{json}");
        assert!(
            json.contains(r#""ulps":[18446744073709551615,0],"bits":[64.0,0.0]"#),
            "{json}"
        );
        let mut s = Summary::default();
        s.add(&r);
        assert_eq!(s.kind(Kind::Sphere).impls[0].max_ulps, u64::MAX);
        assert!(s.render().contains(" nan\n"), "{}", s.render());
    }
}
