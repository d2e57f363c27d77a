//! One case per JSON line: the input format of `rayoracle eval` and of the
//! fixtures in `fixtures/cases/*.jsonl`.
//!
//! ```text
//! {"kind":"plane","origin":[x,y,z],"dir":[x,y,z],"point":[x,y,z],"normal":[x,y,z]}
//! {"kind":"sphere","origin":[..],"dir":[..],"center":[..],"radius":r}
//! {"kind":"quadric","origin":[..],"dir":[..],"coeffs":[a,b,c,d,e,f,g,h,i,j]}
//! {"kind":"camera","position":[..],"dir":[..],"up":[..],"angle":rad,"res":[w,h],"pixel":[X,Y]}
//! ```
//!
//! * A JSON number is parsed from its decimal text straight to the nearest
//!   `f32` (ties to even), not through f64, so no double rounding. A number
//!   beyond the f32 range becomes ±∞, as IEEE rounding says.
//! * A number may also be a string: `"inf"`, `"-inf"`, `"nan"`, or the exact
//!   bits as `"0x3f800000"`.
//! * `res` and `pixel` are whole numbers.
//! * Three optional fields are carried along but do not change the case:
//!   `"family"` (a string naming the case family), `"id"` (a whole number,
//!   as `rayoracle cases` numbers its lines) and `"expect"` (any JSON,
//!   used by the fixture harness).
//! * Anything else is an error naming the field: a missing or unknown field,
//!   a wrong type, a wrong length.

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use crate::Ray;
use crate::camera::CameraParams;
#[cfg(feature = "plane")]
use crate::plane::Plane;
#[cfg(feature = "quadric")]
use crate::quadric::Quadric;
#[cfg(feature = "sphere")]
use crate::sphere::Sphere;
use glam::Vec3;
use serde_json::value::RawValue;
use std::collections::BTreeMap;

/// A parsed case. The plane, sphere and quadric variants exist only when
/// their cargo feature is on; the camera is always there.
///
/// ```
/// use rayoracle::case::{Case, parse_line};
/// let c = parse_line(r#"{"kind":"camera","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[4,3],"pixel":[0,2]}"#).unwrap();
/// assert!(matches!(c.case, Case::Camera(..)));
/// # #[cfg(feature = "sphere")] {
/// let c = parse_line(r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#).unwrap();
/// assert!(matches!(c.case, Case::Sphere(..)));
/// # }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Case {
    /// A ray against a plane.
    #[cfg(feature = "plane")]
    Plane(Ray, Plane),
    /// A ray against a sphere.
    #[cfg(feature = "sphere")]
    Sphere(Ray, Sphere),
    /// A ray against a quadric.
    #[cfg(feature = "quadric")]
    Quadric(Ray, Quadric),
    /// A camera and a pixel.
    Camera(CameraParams, [u32; 2]),
}

impl Case {
    /// The case's kind.
    ///
    /// ```
    /// use rayoracle::case::{Kind, parse_line};
    /// let c = parse_line(r#"{"kind":"camera","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[4,3],"pixel":[0,2]}"#).unwrap();
    /// assert_eq!(c.case.kind(), Kind::Camera);
    /// ```
    pub fn kind(&self) -> Kind {
        match self {
            #[cfg(feature = "plane")]
            Case::Plane(..) => Kind::Plane,
            #[cfg(feature = "sphere")]
            Case::Sphere(..) => Kind::Sphere,
            #[cfg(feature = "quadric")]
            Case::Quadric(..) => Kind::Quadric,
            Case::Camera(..) => Kind::Camera,
        }
    }
}

/// One expression per case, written once for every primitive: `$prim`
/// with `$r` and `$p` bound to the ray and the primitive (of whichever
/// type the case holds, so `$prim` is usually a generic call over
/// [`crate::primitive::Primitive`]), `$camera` with `$c` and `$px` bound to
/// the camera parameters and the pixel. The arms of kinds that are not
/// compiled in are left out, as in [`Case`].
macro_rules! match_case {
    ($case:expr, |$r:pat_param, $p:pat_param| $prim:expr, |$c:pat_param, $px:pat_param| $camera:expr $(,)?) => {
        match $case {
            #[cfg(feature = "plane")]
            $crate::case::Case::Plane($r, $p) => $prim,
            #[cfg(feature = "sphere")]
            $crate::case::Case::Sphere($r, $p) => $prim,
            #[cfg(feature = "quadric")]
            $crate::case::Case::Quadric($r, $p) => $prim,
            $crate::case::Case::Camera($c, $px) => $camera,
        }
    };
}
pub(crate) use match_case;

/// A case with the optional fields that travel with it.
///
/// ```
/// use rayoracle::case::parse_line;
/// let c = parse_line(r#"{"kind":"camera","family":"demo","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[4,3],"pixel":[0,2]}"#).unwrap();
/// assert_eq!(c.family.as_deref(), Some("demo"));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct CaseLine {
    /// The case.
    pub case: Case,
    /// The `family` field, if any.
    pub family: Option<String>,
    /// The `id` field, if any.
    pub id: Option<u64>,
    /// The `expect` field, if any, as JSON.
    pub expect: Option<serde_json::Value>,
}

/// What is wrong with a line, and where.
///
/// ```
/// use rayoracle::case::parse_line;
/// let e = parse_line(r#"{"kind":"camera","position":[0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[4,3],"pixel":[0,2]}"#).unwrap_err();
/// assert_eq!(e.field, "position");
/// assert_eq!(e.to_string(), "position: expected 3 numbers, got 2");
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CaseError {
    /// The field (`origin`, `coeffs[3]`, …), or `json` for a syntax error.
    pub field: String,
    /// The problem.
    pub message: String,
}

impl core::fmt::Display for CaseError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "{}: {}", self.field, self.message)
    }
}

impl std::error::Error for CaseError {}

fn err(field: impl Into<String>, message: impl Into<String>) -> CaseError {
    CaseError {
        field: field.into(),
        message: message.into(),
    }
}

/// Up to 40 characters of a raw JSON value, for messages.
fn show(raw: &RawValue) -> String {
    let s = raw.get();
    if s.chars().count() > 40 {
        format!("{}…", s.chars().take(40).collect::<String>())
    } else {
        s.to_string()
    }
}

/// A number field: decimal text straight to the nearest f32, or a string
/// `inf`, `-inf`, `nan`, `0x…` (bits).
///
/// ```
/// use rayoracle::case::parse_f32;
/// use serde_json::value::RawValue;
/// let raw: Box<RawValue> = serde_json::from_str("\"0x3f800000\"").unwrap();
/// assert_eq!(parse_f32("radius", &raw), Ok(1.0));
/// // Decimal text rounds once, straight to f32 (no double rounding via f64):
/// let raw: Box<RawValue> = serde_json::from_str("1.00000005960464477539062500000001").unwrap();
/// assert_eq!(parse_f32("radius", &raw), Ok(1.0000001));
/// ```
pub fn parse_f32(field: &str, raw: &RawValue) -> Result<f32, CaseError> {
    let text = raw.get();
    if text.starts_with('"') {
        let s: String = serde_json::from_str(text).map_err(|e| err(field, e.to_string()))?;
        return match s.as_str() {
            "inf" | "+inf" | "infinity" => Ok(f32::INFINITY),
            "-inf" | "-infinity" => Ok(f32::NEG_INFINITY),
            "nan" | "NaN" => Ok(f32::NAN),
            hex if hex.starts_with("0x") => u32::from_str_radix(&hex[2..], 16)
                .map(f32::from_bits)
                .map_err(|_| err(field, format!("\"{hex}\" is not 8 hex digits of f32 bits"))),
            other => Err(err(
                field,
                format!(
                    "expected a number, or \"inf\", \"-inf\", \"nan\" or \"0x…\" bits; got \"{other}\""
                ),
            )),
        };
    }
    // A RawValue is valid JSON, so text that Rust parses as an f32 is a JSON
    // number: "inf", "nan", "+1" and ".5" are not JSON and never get here.
    text.parse::<f32>()
        .map_err(|_| err(field, format!("expected a number, got {}", show(raw))))
}

fn parse_array<'a>(
    field: &str,
    raw: &'a RawValue,
    n: usize,
    what: &str,
) -> Result<Vec<&'a RawValue>, CaseError> {
    let items: Vec<&RawValue> = serde_json::from_str(raw.get()).map_err(|_| {
        err(
            field,
            format!("expected an array of {n} {what}, got {}", show(raw)),
        )
    })?;
    if items.len() != n {
        return Err(err(
            field,
            format!("expected {n} {what}, got {}", items.len()),
        ));
    }
    Ok(items)
}

fn parse_f32s<const N: usize>(field: &str, raw: &RawValue) -> Result<[f32; N], CaseError> {
    let items = parse_array(field, raw, N, "numbers")?;
    let mut out = [0.0; N];
    for (i, item) in items.iter().enumerate() {
        out[i] = parse_f32(&format!("{field}[{i}]"), item)?;
    }
    Ok(out)
}

fn parse_u32s(field: &str, raw: &RawValue) -> Result<[u32; 2], CaseError> {
    let items = parse_array(field, raw, 2, "whole numbers")?;
    let mut out = [0; 2];
    for (i, item) in items.iter().enumerate() {
        out[i] = item.get().parse::<u32>().map_err(|_| {
            err(
                format!("{field}[{i}]"),
                format!(
                    "expected a whole number from 0 to {}, got {}",
                    u32::MAX,
                    show(item)
                ),
            )
        })?;
    }
    Ok(out)
}

/// The fields of one line, consumed as they are read so that what is left
/// over can be reported as unknown.
struct Fields(BTreeMap<String, Box<RawValue>>);

impl Fields {
    fn take(&mut self, name: &str) -> Result<Box<RawValue>, CaseError> {
        self.0.remove(name).ok_or_else(|| err(name, "missing"))
    }
    fn vec3(&mut self, name: &str) -> Result<Vec3, CaseError> {
        Ok(Vec3::from_array(parse_f32s::<3>(name, &self.take(name)?)?))
    }
    fn f32(&mut self, name: &str) -> Result<f32, CaseError> {
        parse_f32(name, &self.take(name)?)
    }
    fn finish(self) -> Result<(), CaseError> {
        match self.0.keys().next() {
            Some(k) => Err(err(k.as_str(), "unknown field")),
            None => Ok(()),
        }
    }
}

/// The kind of a case: which primitive, or the camera. Every kind exists
/// whatever the build; [`Kind::compiled_in`] says whether its cases can be
/// run. It reads and writes as the lowercase names of the `kind` field.
///
/// ```
/// use rayoracle::case::Kind;
/// assert_eq!(Kind::ALL.map(Kind::as_str), ["plane", "sphere", "quadric", "camera"]);
/// assert_eq!("quadric".parse(), Ok(Kind::Quadric));
/// assert_eq!(
///     "cube".parse::<Kind>().unwrap_err().to_string(),
///     r#"unknown kind "cube"; expected plane, sphere, quadric or camera"#
/// );
/// assert_eq!(serde_json::to_string(&Kind::Camera).unwrap(), r#""camera""#);
/// assert_eq!(serde_json::from_str::<Kind>(r#""plane""#).unwrap(), Kind::Plane);
/// assert!(serde_json::from_str::<Kind>(r#""cube""#).unwrap_err().to_string().contains("unknown kind"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Kind {
    /// A ray against a plane.
    Plane,
    /// A ray against a sphere.
    Sphere,
    /// A ray against a quadric.
    Quadric,
    /// A camera and a pixel.
    Camera,
}

impl Kind {
    /// Every kind, in the order rayoracle lists them.
    pub const ALL: [Kind; 4] = [Kind::Plane, Kind::Sphere, Kind::Quadric, Kind::Camera];

    /// The name, as in the `kind` field.
    ///
    /// ```
    /// assert_eq!(rayoracle::case::Kind::Plane.as_str(), "plane");
    /// ```
    pub const fn as_str(self) -> &'static str {
        match self {
            Kind::Plane => "plane",
            Kind::Sphere => "sphere",
            Kind::Quadric => "quadric",
            Kind::Camera => "camera",
        }
    }

    /// Whether cases of this kind exist in this build: the camera always,
    /// the plane, sphere and quadric when the cargo feature of the same
    /// name is on. [`parse_line`] reports a line of a kind that is not
    /// compiled in as an error in its `kind` field.
    ///
    /// ```
    /// use rayoracle::case::Kind;
    /// assert!(Kind::Camera.compiled_in());
    /// assert_eq!(Kind::Quadric.compiled_in(), cfg!(feature = "quadric"));
    /// ```
    pub const fn compiled_in(self) -> bool {
        match self {
            Kind::Plane => cfg!(feature = "plane"),
            Kind::Sphere => cfg!(feature = "sphere"),
            Kind::Quadric => cfg!(feature = "quadric"),
            Kind::Camera => true,
        }
    }
}

impl core::fmt::Display for Kind {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A kind name that is not one of [`Kind::ALL`]; the message lists them.
///
/// ```
/// let e = "torus".parse::<rayoracle::case::Kind>().unwrap_err();
/// assert_eq!(e.0, "torus");
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownKind(pub String);

impl core::fmt::Display for UnknownKind {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "unknown kind \"{}\"; expected plane, sphere, quadric or camera",
            self.0
        )
    }
}

impl std::error::Error for UnknownKind {}

impl core::str::FromStr for Kind {
    type Err = UnknownKind;
    fn from_str(s: &str) -> Result<Kind, UnknownKind> {
        Kind::ALL
            .into_iter()
            .find(|k| k.as_str() == s)
            .ok_or_else(|| UnknownKind(s.to_string()))
    }
}

impl serde::Serialize for Kind {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

impl<'de> serde::Deserialize<'de> for Kind {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Kind, D::Error> {
        let s = <std::borrow::Cow<'de, str>>::deserialize(d)?;
        s.parse().map_err(serde::de::Error::custom)
    }
}

/// Parses one line.
///
/// ```
/// use rayoracle::case::{Case, parse_line};
/// let c = parse_line(r#"{"kind":"camera","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[4,3],"pixel":[0,2]}"#).unwrap();
/// assert!(matches!(c.case, Case::Camera(_, [0, 2])));
/// let e = parse_line(r#"{"kind":"cube"}"#).unwrap_err();
/// assert_eq!(e.field, "kind");
/// ```
pub fn parse_line(line: &str) -> Result<CaseLine, CaseError> {
    let map: BTreeMap<String, Box<RawValue>> = serde_json::from_str(line).map_err(|e| {
        let msg = e.to_string();
        if e.is_data() {
            err("json", "expected an object, one case per line")
        } else {
            err("json", msg)
        }
    })?;
    let mut fields = Fields(map);
    let kind_raw = fields.take("kind")?;
    let kind: String = serde_json::from_str(kind_raw.get()).map_err(|_| {
        err(
            "kind",
            format!("expected a string, got {}", show(&kind_raw)),
        )
    })?;
    let kind: Kind = kind
        .parse()
        .map_err(|e: UnknownKind| err("kind", e.to_string()))?;
    let family = match fields.0.remove("family") {
        None => None,
        Some(raw) => Some(
            serde_json::from_str::<String>(raw.get())
                .map_err(|_| err("family", format!("expected a string, got {}", show(&raw))))?,
        ),
    };
    let id = match fields.0.remove("id") {
        None => None,
        Some(raw) => Some(
            serde_json::from_str::<u64>(raw.get())
                .map_err(|_| err("id", format!("expected a whole number, got {}", show(&raw))))?,
        ),
    };
    let expect = match fields.0.remove("expect") {
        None => None,
        Some(raw) => {
            Some(serde_json::from_str(raw.get()).map_err(|e| err("expect", e.to_string()))?)
        }
    };
    let case = match kind {
        #[cfg(feature = "plane")]
        Kind::Plane => {
            let ray = Ray::new(fields.vec3("origin")?, fields.vec3("dir")?);
            Case::Plane(
                ray,
                Plane::new(fields.vec3("point")?, fields.vec3("normal")?),
            )
        }
        #[cfg(feature = "sphere")]
        Kind::Sphere => {
            let ray = Ray::new(fields.vec3("origin")?, fields.vec3("dir")?);
            Case::Sphere(
                ray,
                Sphere::new(fields.vec3("center")?, fields.f32("radius")?),
            )
        }
        #[cfg(feature = "quadric")]
        Kind::Quadric => {
            let ray = Ray::new(fields.vec3("origin")?, fields.vec3("dir")?);
            let coeffs = parse_f32s::<10>("coeffs", &fields.take("coeffs")?)?;
            Case::Quadric(ray, Quadric::new(coeffs))
        }
        Kind::Camera => {
            let position = fields.vec3("position")?;
            let dir = fields.vec3("dir")?;
            let up = fields.vec3("up")?;
            let angle = fields.f32("angle")?;
            let res = parse_u32s("res", &fields.take("res")?)?;
            let pixel = parse_u32s("pixel", &fields.take("pixel")?)?;
            for i in 0..2 {
                if res[i] > 0 && pixel[i] >= res[i] {
                    return Err(err(
                        format!("pixel[{i}]"),
                        format!("{} is outside 0..{}", pixel[i], res[i]),
                    ));
                }
            }
            Case::Camera(CameraParams::new(position, dir, up, angle, res), pixel)
        }
        // A kind the earlier arms do not take is one whose feature is off.
        #[allow(unreachable_patterns)]
        _ => {
            return Err(err(
                "kind",
                format!(
                    "\"{kind}\" is not compiled into this build (cargo feature \"{kind}\" is off)"
                ),
            ));
        }
    };
    fields.finish()?;
    Ok(CaseLine {
        case,
        family,
        id,
        expect,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn e(line: &str) -> String {
        parse_line(line).unwrap_err().to_string()
    }

    /// `parse_f32` trusts that a `RawValue` is JSON: the texts Rust would
    /// parse as an f32 but JSON has no number for cannot be one.
    #[test]
    fn a_raw_value_cannot_hold_a_non_json_number() {
        use serde_json::value::RawValue;
        for t in ["inf", "-inf", "nan", "NaN", "+1", ".5", "1.", "infinity"] {
            assert!(t.parse::<f32>().is_ok(), "{t}");
            assert!(RawValue::from_string(t.to_string()).is_err(), "{t}");
        }
        let raw = RawValue::from_string("-0".to_string()).unwrap();
        assert_eq!(
            parse_f32("x", &raw).map(f32::to_bits),
            Ok((-0.0f32).to_bits())
        );
    }

    /// A raw value in a message is cut to 40 characters and an ellipsis;
    /// 40 or fewer are shown whole.
    #[test]
    fn show_cuts_long_values_at_40_characters() {
        let raw = |s: &str| serde_json::value::RawValue::from_string(s.to_string()).unwrap();
        let forty = format!("\"{}\"", "é".repeat(38));
        assert_eq!(show(&raw(&forty)), forty);
        let long = format!("\"{}\"", "é".repeat(45));
        assert_eq!(show(&raw(&long)), format!("\"{}…", "é".repeat(39)));
    }

    #[cfg(feature = "sphere")]
    #[test]
    fn errors_name_the_field_and_the_problem() {
        let ok = r#""origin":[0,0,0],"dir":[0,0,1],"center":[0,0,0]"#;
        assert_eq!(
            e(&format!(r#"{{"kind":"sphere",{ok}}}"#)),
            "radius: missing"
        );
        assert_eq!(
            e(&format!(r#"{{"kind":"sphere",{ok},"radius":"big"}}"#)),
            r#"radius: expected a number, or "inf", "-inf", "nan" or "0x…" bits; got "big""#
        );
        assert_eq!(
            e(&format!(
                r#"{{"kind":"sphere",{ok},"radius":1,"colour":2}}"#
            )),
            "colour: unknown field"
        );
        assert_eq!(
            e(&format!(r#"{{"kind":"sphere",{ok},"radius":[1]}}"#)),
            "radius: expected a number, got [1]"
        );
        assert_eq!(
            e(r#"{"kind":"sphere","origin":[0,"x",0]}"#),
            r#"origin[1]: expected a number, or "inf", "-inf", "nan" or "0x…" bits; got "x""#
        );
    }

    #[test]
    fn errors_name_the_field_and_the_problem_in_every_build() {
        assert_eq!(e(r#"[1,2]"#), "json: expected an object, one case per line");
        assert_eq!(
            e(r#"{"kind":"cube"}"#),
            r#"kind: unknown kind "cube"; expected plane, sphere, quadric or camera"#
        );
        assert!(e(r#"{"kind":"#).starts_with("json: "));
        assert_eq!(
            e(
                r#"{"kind":"camera","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[4,3],"pixel":[4,0]}"#
            ),
            "pixel[0]: 4 is outside 0..4"
        );
        assert_eq!(
            e(
                r#"{"kind":"camera","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[4,-3],"pixel":[0,0]}"#
            ),
            "res[1]: expected a whole number from 0 to 4294967295, got -3"
        );
    }

    #[cfg(not(all(feature = "plane", feature = "sphere", feature = "quadric")))]
    #[test]
    fn a_line_of_a_kind_that_is_compiled_out_is_an_error_in_its_kind_field() {
        let lines = [
            (
                "plane",
                cfg!(feature = "plane"),
                r#"{"kind":"plane","origin":[0,0,0],"dir":[0,0,1],"point":[0,0,1],"normal":[0,0,1]}"#,
            ),
            (
                "sphere",
                cfg!(feature = "sphere"),
                r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#,
            ),
            (
                "quadric",
                cfg!(feature = "quadric"),
                r#"{"kind":"quadric","origin":[-5,0,0],"dir":[1,0,0],"coeffs":[1,1,0,0,0,0,0,0,0,-1]}"#,
            ),
        ];
        let mut compiled_out = 0;
        for (kind, _, line) in lines.iter().filter(|l| !l.1) {
            compiled_out += 1;
            assert_eq!(
                e(line),
                format!(
                    r#"kind: "{kind}" is not compiled into this build (cargo feature "{kind}" is off)"#
                )
            );
        }
        assert!(compiled_out > 0);
    }

    /// `Kind::ALL` is in declaration order (tallies index by `kind as
    /// usize`), every name reads back to its kind, and a name differing
    /// only in case is unknown.
    #[test]
    fn kinds_are_listed_in_order_and_read_back() {
        for (i, k) in Kind::ALL.into_iter().enumerate() {
            assert_eq!(k as usize, i);
            assert_eq!(k.as_str().parse(), Ok(k));
            assert_eq!(k.to_string(), k.as_str());
        }
        assert_eq!("Plane".parse::<Kind>(), Err(UnknownKind("Plane".into())));
    }

    #[test]
    fn numbers_round_once_to_f32_and_accept_special_spellings() {
        let raw = |s: &str| -> Box<RawValue> { serde_json::from_str(s).unwrap() };
        assert_eq!(parse_f32("x", &raw("0.1")), Ok(0.1f32));
        assert_eq!(parse_f32("x", &raw("1e39")), Ok(f32::INFINITY));
        assert_eq!(
            parse_f32("x", &raw("-1e-50")).map(f32::to_bits),
            Ok((-0.0f32).to_bits())
        );
        assert!(parse_f32("x", &raw("\"nan\"")).unwrap().is_nan());
        assert_eq!(
            parse_f32("x", &raw("\"0x00000001\"")),
            Ok(f32::from_bits(1))
        );
        assert!(parse_f32("x", &raw("true")).is_err());
        assert!(parse_f32("x", &raw("null")).is_err());
    }
}
