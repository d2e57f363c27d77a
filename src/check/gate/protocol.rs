//! The gate's line protocol, for kernels outside the process (`rayoracle
//! cases`, `judge` and `gate -- PROGRAM`): cases go out as `eval` input
//! lines with an `id`, answers come back one JSON object a line.
//!
//! ```text
//! → {"id":0,"family":"sphere/unit","kind":"sphere","origin":[0.0,0.0,-5.0],"dir":[0.0,0.0,1.0],"center":[0.0,0.0,0.0],"radius":1.0}
//! ← {"t": 4.0}                              nearest t > 0, or {"t": null}
//! ← {"point": [0.0, 0.0, -1.0]}             the nearest hit as a point, or {"point": null}
//! ← {"class": "two", "roots": [4.0, 6.0]}   the whole line
//! ← {"dir": [0.1, 0.2, -0.97]}              a camera's ray, or {"dir": null}
//! ```
//!
//! * Every number of a case line is an f32 written so that parsing it as
//!   an f64 gives it exactly (`0.1f32` is `0.10000000149011612`), so a
//!   reader in any language recovers the f32 bits by a double parse and a
//!   cast. A non-finite input is the string `"nan"`, `"inf"` or `"-inf"`.
//! * An answer's numbers are JSON numbers, rounded once to the nearest
//!   f32, or the strings that `eval` accepts: `"nan"`, `"inf"`, `"-inf"`,
//!   `"0x3f800000"` (bits).
//! * `class` is one of the kind's classes (sphere: `none`, `two`,
//!   `tangent`; plane: `hit`, `parallel`, `in_plane`; quadric: `none`,
//!   `one`, `two`, `tangent`, `all`) and must agree with the number of
//!   `roots` (a tangent may give its root once or twice); `all` and
//!   `in_plane` need no roots. Without `class`, the roots alone are the
//!   answer.
//! * An answer may carry `"id"`; if it does, it must be its case's.

use super::Reply;
use crate::Ray;
use crate::case::{Case, Kind, parse_f32};
use crate::check::rules::Answer;
use glam::Vec3;
use serde_json::value::RawValue;
use std::collections::BTreeMap;

/// A case as a protocol line: its `id` and `family`, then the `eval`
/// input fields, every number exact as an f64.
///
/// ```
/// use rayoracle::check::gate::protocol::case_line;
/// use rayoracle::{Ray, case::{Case, parse_line}, sphere::Sphere};
/// use glam::Vec3;
/// let c = Case::Sphere(Ray::new(Vec3::new(0.1, f32::NAN, -5.0), Vec3::Z), Sphere::new(Vec3::ZERO, 1.0));
/// let line = case_line(&c, "mine", 7);
/// assert_eq!(line, r#"{"id":7,"family":"mine","kind":"sphere","origin":[0.10000000149011612,"nan",-5.0],"dir":[0.0,0.0,1.0],"center":[0.0,0.0,0.0],"radius":1.0}"#);
/// let back = parse_line(&line).unwrap();
/// assert_eq!((back.id, back.family.as_deref()), (Some(7), Some("mine")));
/// ```
pub fn case_line(case: &Case, family: &str, id: u64) -> String {
    format!(
        r#"{{"id":{id},"family":{},"kind":"{}",{}}}"#,
        serde_json::Value::from(family),
        case.kind().as_str(),
        fields(case, num)
    )
}

/// The `eval` input fields of a case after `kind`, each number written by
/// `num`.
pub(super) fn fields(case: &Case, num: fn(f32) -> String) -> String {
    let v = |x: Vec3| format!("[{},{},{}]", num(x.x), num(x.y), num(x.z));
    match case {
        Case::Plane(r, p) => format!(
            r#""origin":{},"dir":{},"point":{},"normal":{}"#,
            v(r.origin),
            v(r.dir),
            v(p.point),
            v(p.normal)
        ),
        Case::Sphere(r, s) => format!(
            r#""origin":{},"dir":{},"center":{},"radius":{}"#,
            v(r.origin),
            v(r.dir),
            v(s.center),
            num(s.radius)
        ),
        Case::Quadric(r, q) => format!(
            r#""origin":{},"dir":{},"coeffs":[{}]"#,
            v(r.origin),
            v(r.dir),
            q.coeffs.map(num).join(",")
        ),
        Case::Camera(p, px) => format!(
            r#""position":{},"dir":{},"up":{},"angle":{},"res":[{},{}],"pixel":[{},{}]"#,
            v(p.position),
            v(p.dir),
            v(p.up),
            num(p.angle),
            p.res[0],
            p.res[1],
            px[0],
            px[1]
        ),
    }
}

/// An f32 as the shortest JSON text that reads back as it in f32 (what
/// `rayoracle eval` does), or as a string if it is not finite.
pub(super) fn short_num(x: f32) -> String {
    if x.is_finite() {
        format!("{x:?}")
    } else {
        num(x)
    }
}

/// An f32 as JSON text that an f64 parse reads back exactly.
fn num(x: f32) -> String {
    match x {
        x if x.is_nan() => "\"nan\"".into(),
        f32::INFINITY => "\"inf\"".into(),
        f32::NEG_INFINITY => "\"-inf\"".into(),
        x => format!("{:?}", f64::from(x)),
    }
}

/// A reply as an answer line, the inverse of [`read_answer`]: `Roots` as
/// `{"roots": […]}`, `Everywhere` as the kind's class (`all`, or
/// `in_plane` for a plane), a failure as `{"error": why}`.
///
/// ```
/// use rayoracle::check::gate::{Answer, Reply, protocol::answer_line};
/// use rayoracle::case::Kind;
/// assert_eq!(answer_line(&Reply::Answer(Answer::Nearest(Some(0.1))), Kind::Sphere), r#"{"t":0.10000000149011612}"#);
/// assert_eq!(answer_line(&Reply::Answer(Answer::Roots(vec![f32::NAN])), Kind::Quadric), r#"{"roots":["nan"]}"#);
/// assert_eq!(answer_line(&Reply::Answer(Answer::Everywhere), Kind::Plane), r#"{"class":"in_plane"}"#);
/// assert_eq!(answer_line(&Reply::Camera(None), Kind::Camera), r#"{"dir":null}"#);
/// ```
pub fn answer_line(reply: &Reply, kind: Kind) -> String {
    let list = |v: &[f32]| v.iter().map(|&x| num(x)).collect::<Vec<_>>().join(",");
    match reply {
        Reply::Answer(Answer::Nearest(Some(t))) => format!(r#"{{"t":{}}}"#, num(*t)),
        Reply::Answer(Answer::Nearest(None)) => r#"{"t":null}"#.into(),
        Reply::Answer(Answer::Point(Some(p))) => {
            format!(r#"{{"point":[{}]}}"#, list(&p.to_array()))
        }
        Reply::Answer(Answer::Point(None)) => r#"{"point":null}"#.into(),
        Reply::Answer(Answer::Roots(r)) => format!(r#"{{"roots":[{}]}}"#, list(r)),
        Reply::Answer(Answer::Everywhere) if kind == Kind::Plane => {
            r#"{"class":"in_plane"}"#.into()
        }
        Reply::Answer(Answer::Everywhere) => r#"{"class":"all"}"#.into(),
        Reply::Camera(Some(r)) => format!(r#"{{"dir":[{}]}}"#, list(&r.dir.to_array())),
        Reply::Camera(None) => r#"{"dir":null}"#.into(),
        Reply::Answer(Answer::Inconsistent(why)) | Reply::Failed(why) => {
            format!(r#"{{"error":{}}}"#, serde_json::Value::from(why.as_str()))
        }
    }
}

/// An answer line read for a case: its `id` if it gave one, and the
/// reply.
#[derive(Clone, Debug, PartialEq)]
pub struct AnswerLine {
    /// The `id` field, if any.
    pub id: Option<u64>,
    /// The answer.
    pub reply: Reply,
}

/// The `id` of an answer line, for answers that come in any order
/// (`rayoracle judge`).
///
/// ```
/// use rayoracle::check::gate::protocol::answer_id;
/// assert_eq!(answer_id(r#"{"id": 12, "t": null}"#), Ok(12));
/// assert_eq!(answer_id(r#"{"t": null}"#).unwrap_err(), "no \"id\" field");
/// ```
pub fn answer_id(line: &str) -> Result<u64, String> {
    id_of(&object(line)?)?.ok_or_else(|| "no \"id\" field".into())
}

/// Reads an answer line to `case`.
///
/// ```
/// use rayoracle::check::gate::{Answer, Reply, protocol::read_answer};
/// use rayoracle::{Ray, case::Case, sphere::Sphere};
/// use glam::Vec3;
/// let c = Case::Sphere(Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), Sphere::new(Vec3::ZERO, 1.0));
/// let a = read_answer(r#"{"t": 4}"#, &c).unwrap();
/// assert_eq!(a.reply, Reply::Answer(Answer::Nearest(Some(4.0))));
/// let a = read_answer(r#"{"point": [0, 0, -1]}"#, &c).unwrap();
/// assert_eq!(a.reply, Reply::Answer(Answer::Point(Some(Vec3::new(0.0, 0.0, -1.0)))));
/// let a = read_answer(r#"{"id": 3, "class": "two", "roots": [4, "0x40c00000"]}"#, &c).unwrap();
/// assert_eq!((a.id, a.reply), (Some(3), Reply::Answer(Answer::Roots(vec![4.0, 6.0]))));
/// assert_eq!(read_answer(r#"{"class": "two", "roots": [4]}"#, &c).unwrap_err(),
///            "class \"two\" needs 2 roots, got 1");
/// assert_eq!(read_answer(r#"{"class": "hit", "roots": [4]}"#, &c).unwrap_err(),
///            "class: \"hit\" is not a sphere class (none, two, tangent)");
/// assert_eq!(read_answer("t=4", &c).unwrap_err(),
///            "not a JSON object: expected ident at line 1 column 2");
/// ```
pub fn read_answer(line: &str, case: &Case) -> Result<AnswerLine, String> {
    let mut map = object(line)?;
    let id = id_of(&map)?;
    map.remove("id");
    let reply = if case.kind() == Kind::Camera {
        let dir = take(&mut map, "dir")?;
        if dir.get() == "null" {
            Reply::Camera(None)
        } else {
            let [x, y, z] = f32s::<3>("dir", &dir)?;
            let Case::Camera(p, _) = case else {
                unreachable!("a camera kind is a camera case")
            };
            Reply::Camera(Some(Ray::new(p.position, Vec3::new(x, y, z))))
        }
    } else if let Some(p) = map.remove("point") {
        if p.get() == "null" {
            Reply::Answer(Answer::Point(None))
        } else {
            let [x, y, z] = f32s::<3>("point", &p)?;
            Reply::Answer(Answer::Point(Some(Vec3::new(x, y, z))))
        }
    } else if let Some(t) = map.remove("t") {
        if t.get() == "null" {
            Reply::Answer(Answer::Nearest(None))
        } else {
            Reply::Answer(Answer::Nearest(Some(
                parse_f32("t", &t).map_err(|e| e.to_string())?,
            )))
        }
    } else {
        Reply::Answer(whole_line(&mut map, case.kind())?)
    };
    if let Some(extra) = map.keys().next() {
        return Err(format!("unknown field \"{extra}\""));
    }
    Ok(AnswerLine { id, reply })
}

/// `class` and `roots`.
fn whole_line(map: &mut BTreeMap<String, Box<RawValue>>, kind: Kind) -> Result<Answer, String> {
    let roots = match map.remove("roots") {
        None => None,
        Some(raw) => {
            let items: Vec<Box<RawValue>> = serde_json::from_str(raw.get())
                .map_err(|_| "roots: expected an array of numbers".to_string())?;
            let roots = items
                .iter()
                .enumerate()
                .map(|(i, r)| parse_f32(&format!("roots[{i}]"), r).map_err(|e| e.to_string()))
                .collect::<Result<Vec<f32>, String>>()?;
            Some(roots)
        }
    };
    let Some(class) = map.remove("class") else {
        return roots.map(Answer::Roots).ok_or_else(|| {
            "expected \"t\" or \"point\" (nearest), \"class\" and \"roots\" (whole line) or \"dir\" (camera)"
                .to_string()
        });
    };
    let class: String = serde_json::from_str(class.get())
        .map_err(|_| format!("class: expected a string, got {}", class.get()))?;
    let classes: &[(&str, &[usize])] = match kind {
        Kind::Plane => &[("hit", &[1]), ("parallel", &[0]), ("in_plane", &[])],
        Kind::Sphere => &[("none", &[0]), ("two", &[2]), ("tangent", &[1, 2])],
        _ => &[
            ("none", &[0]),
            ("one", &[1]),
            ("two", &[2]),
            ("tangent", &[1, 2]),
            ("all", &[]),
        ],
    };
    let Some((_, counts)) = classes.iter().find(|c| c.0 == class) else {
        let names: Vec<&str> = classes.iter().map(|c| c.0).collect();
        return Err(format!(
            "class: \"{class}\" is not a {} class ({})",
            kind.as_str(),
            names.join(", ")
        ));
    };
    match (counts.is_empty(), roots) {
        (true, None) => Ok(Answer::Everywhere),
        (true, Some(r)) if r.is_empty() => Ok(Answer::Everywhere),
        (true, Some(_)) => Err(format!("class \"{class}\" takes no roots")),
        (false, None) => Err(format!("class \"{class}\" needs \"roots\"")),
        (false, Some(r)) if counts.contains(&r.len()) => Ok(Answer::Roots(r)),
        (false, Some(r)) => Err(format!(
            "class \"{class}\" needs {} roots, got {}",
            counts[0],
            r.len()
        )),
    }
}

fn object(line: &str) -> Result<BTreeMap<String, Box<RawValue>>, String> {
    serde_json::from_str(line)
        .or_else(|e| serde_json::from_str(&quote_non_finite(line)).map_err(|_| e))
        .map_err(|e| format!("not a JSON object: {e}"))
}

/// The bare `NaN`, `Infinity` and `-Infinity` that Python's `json` writes
/// (not JSON) as the strings the protocol takes.
///
/// ```
/// # use rayoracle::check::gate::{Answer, Reply, protocol::read_answer};
/// # use rayoracle::{Ray, case::Case, sphere::Sphere};
/// # let c = Case::Sphere(Ray::new(glam::Vec3::ZERO, glam::Vec3::Z), Sphere::new(glam::Vec3::ZERO, 1.0));
/// let a = read_answer(r#"{"roots": [-Infinity, NaN]}"#, &c).unwrap();
/// assert!(matches!(a.reply, Reply::Answer(Answer::Roots(r)) if r[0] == f32::NEG_INFINITY && r[1].is_nan()));
/// ```
fn quote_non_finite(line: &str) -> String {
    let mut out = String::with_capacity(line.len() + 8);
    let mut in_string = false;
    let mut escaped = false;
    let mut rest = line;
    while let Some(c) = rest.chars().next() {
        if in_string {
            in_string = escaped || c != '"';
            escaped = !escaped && c == '\\';
        } else if c == '"' {
            in_string = true;
        } else {
            let token = ["-Infinity", "Infinity", "NaN"]
                .into_iter()
                .find(|t| rest.starts_with(t));
            if let Some(t) = token {
                out.push_str(match t {
                    "NaN" => "\"nan\"",
                    "Infinity" => "\"inf\"",
                    _ => "\"-inf\"",
                });
                rest = &rest[t.len()..];
                continue;
            }
        }
        out.push(c);
        rest = &rest[c.len_utf8()..];
    }
    out
}

fn id_of(map: &BTreeMap<String, Box<RawValue>>) -> Result<Option<u64>, String> {
    map.get("id")
        .map(|raw| {
            serde_json::from_str::<u64>(raw.get())
                .map_err(|_| format!("id: expected a whole number, got {}", raw.get()))
        })
        .transpose()
}

fn take(map: &mut BTreeMap<String, Box<RawValue>>, field: &str) -> Result<Box<RawValue>, String> {
    map.remove(field)
        .ok_or_else(|| format!("expected \"{field}\" for a camera case"))
}

fn f32s<const N: usize>(field: &str, raw: &RawValue) -> Result<[f32; N], String> {
    let items: Vec<Box<RawValue>> =
        serde_json::from_str(raw.get()).map_err(|_| format!("{field}: expected {N} numbers"))?;
    if items.len() != N {
        return Err(format!(
            "{field}: expected {N} numbers, got {}",
            items.len()
        ));
    }
    let mut out = [0.0; N];
    for (i, r) in items.iter().enumerate() {
        out[i] = parse_f32(&format!("{field}[{i}]"), r).map_err(|e| e.to_string())?;
    }
    Ok(out)
}

#[cfg(all(test, feature = "plane", feature = "sphere", feature = "quadric"))]
mod tests {
    use super::*;
    use crate::plane::Plane;
    use crate::quadric::Quadric;
    use crate::sphere::Sphere;

    /// Each kind's whole-line classes with the root counts they take, and
    /// the error for any other count or class, as data.
    #[test]
    fn each_class_takes_its_root_counts() {
        let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
        let plane = Case::Plane(ray, Plane::new(Vec3::ZERO, Vec3::Z));
        let sphere = Case::Sphere(ray, Sphere::new(Vec3::ZERO, 1.0));
        let ball = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
        let quadric = Case::Quadric(ray, Quadric::new(ball));
        let roots = |r: &[f32]| Ok(Reply::Answer(Answer::Roots(r.to_vec())));
        let every = || Ok(Reply::Answer(Answer::Everywhere));
        let err = |e: &str| Err(e.to_string());
        let table: &[(&Case, &str, Result<Reply, String>)] = &[
            (&plane, r#"{"class":"hit","roots":[5]}"#, roots(&[5.0])),
            (
                &plane,
                r#"{"class":"hit","roots":[]}"#,
                err(r#"class "hit" needs 1 roots, got 0"#),
            ),
            (&plane, r#"{"class":"parallel","roots":[]}"#, roots(&[])),
            (
                &plane,
                r#"{"class":"parallel"}"#,
                err(r#"class "parallel" needs "roots""#),
            ),
            (&plane, r#"{"class":"in_plane"}"#, every()),
            (&plane, r#"{"class":"in_plane","roots":[]}"#, every()),
            (
                &plane,
                r#"{"class":"in_plane","roots":[1]}"#,
                err(r#"class "in_plane" takes no roots"#),
            ),
            (&sphere, r#"{"class":"none","roots":[]}"#, roots(&[])),
            (
                &sphere,
                r#"{"class":"none","roots":[4]}"#,
                err(r#"class "none" needs 0 roots, got 1"#),
            ),
            (&sphere, r#"{"class":"tangent","roots":[5]}"#, roots(&[5.0])),
            (
                &sphere,
                r#"{"class":"tangent","roots":[5,5]}"#,
                roots(&[5.0, 5.0]),
            ),
            (
                &sphere,
                r#"{"class":"tangent","roots":[]}"#,
                err(r#"class "tangent" needs 1 roots, got 0"#),
            ),
            (
                &sphere,
                r#"{"class":"all"}"#,
                err(r#"class: "all" is not a sphere class (none, two, tangent)"#),
            ),
            (&quadric, r#"{"class":"all"}"#, every()),
            (&quadric, r#"{"class":"one","roots":[4]}"#, roots(&[4.0])),
            (
                &quadric,
                r#"{"class":"two","roots":[4,6]}"#,
                roots(&[4.0, 6.0]),
            ),
            (
                &quadric,
                r#"{"class":"hit","roots":[4]}"#,
                err(r#"class: "hit" is not a quadric class (none, one, two, tangent, all)"#),
            ),
            (&sphere, r#"{"roots":[4,6]}"#, roots(&[4.0, 6.0])),
        ];
        for (case, line, want) in table {
            let got = read_answer(line, case).map(|a| a.reply);
            assert_eq!(&got, want, "{line}");
        }
    }

    /// Python's bare `NaN`, `Infinity` and `-Infinity` are read as numbers
    /// outside strings only: a string's escaped quote does not end it, and
    /// an escaped backslash does not escape the quote after it.
    #[test]
    fn bare_non_finite_numbers_are_read_outside_strings_only() {
        let table = [
            (r#"{"t": Infinity}"#, r#"{"t": "inf"}"#),
            (r#"{"t": -Infinity}"#, r#"{"t": "-inf"}"#),
            (r#"{"roots": [NaN, 1]}"#, r#"{"roots": ["nan", 1]}"#),
            (r#"{"class": "NaN"}"#, r#"{"class": "NaN"}"#),
            (
                r#"{"class": "not Infinity"}"#,
                r#"{"class": "not Infinity"}"#,
            ),
            (r#"{"class": "é\"NaN"}"#, r#"{"class": "é\"NaN"}"#),
            (
                r#"{"class": "a\\", "t": NaN}"#,
                r#"{"class": "a\\", "t": "nan"}"#,
            ),
        ];
        for (line, want) in table {
            assert_eq!(quote_non_finite(line), want, "{line}");
        }
        let case = Case::Sphere(
            Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z),
            Sphere::new(Vec3::ZERO, 1.0),
        );
        let t = |line: &str| match read_answer(line, &case).map(|a| a.reply) {
            Ok(Reply::Answer(Answer::Nearest(Some(t)))) => t,
            other => panic!("{line}: {other:?}"),
        };
        assert_eq!(t(r#"{"t": Infinity}"#), f32::INFINITY);
        assert_eq!(t(r#"{"t": -Infinity}"#), f32::NEG_INFINITY);
        assert!(t(r#"{"t": NaN}"#).is_nan());
    }
}
