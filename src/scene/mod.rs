//! Scene files: a camera and lists of planes, spheres and quadrics.
//!
//! Scenes live in `fixtures/scenes/*.json`:
//!
//! ```json
//! {
//!   "name": "seed",
//!   "description": "what the scene is for",
//!   "camera": {"position": [0, 1, 6], "dir": [0, 0, -1], "up": [0, 1, 0],
//!              "angle": 0.9, "res": [160, 120]},
//!   "depth": {"near": 0.5, "far": 100},
//!   "planes":   [{"id": 1, "point": [0, 0, 0], "normal": [0, 1, 0]}],
//!   "spheres":  [{"id": 2, "center": [0, 1, 0], "radius": 1}],
//!   "quadrics": [{"id": 3, "coeffs": [1, 0, 1, 0, 0, 0, 0, 0, 0, -0.25]}]
//! }
//! ```
//!
//! * The camera takes the usual parameters (see
//!   [`crate::camera`]): `angle` is the vertical field of view in radians,
//!   `res` is `[width, height]`; `dir` need not be unit length and `up` need
//!   not be orthogonal to it.
//! * Quadric coefficients are `[A … J]` of `Ax² + By² + Cz² + Dxy + Exz +
//!   Fyz + Gx + Hy + Iz + J = 0`, as in [`crate::quadric::Quadric`].
//! * `depth` is optional ([`DepthRange::DEFAULT`]); it sets the range the
//!   depth channel maps to grey ([`crate::render`]).
//! * Every object has an `id` from 1 up, unique in the scene; the id channel
//!   colours by it. The lists may be empty or left out.
//! * Numbers are read from their decimal text straight to the nearest f32,
//!   and may be `"inf"`, `"nan"` or `"0x…"` bits as in `eval` lines (which
//!   the checks then reject where a value must be finite).
//!
//! Everything is checked while it is read. An error names the file, the line
//! and column, the field, and the problem ([`SceneError`]); loading never
//! panics, whatever the bytes (the `scene` fuzz target holds it to that).
//! The resolution is checked against [`MAX_PIXELS`] before anything is
//! allocated for it.

mod error;
mod file;

pub use error::SceneError;

use crate::camera::CameraParams;
use glam::Vec3;
use std::path::Path;

/// The most pixels a scene may ask for (`2²⁶`, 8192 × 8192): a frame with
/// every channel takes 20 bytes a pixel, so this caps a render at 1.3 GiB.
/// [`crate::camera::MAX_RESOLUTION`] also bounds each side.
pub const MAX_PIXELS: u64 = 1 << 26;

/// Checks a resolution against the limits, naming the field at fault.
///
/// ```
/// use rayoracle::scene::check_resolution;
/// assert!(check_resolution([1920, 1080]).is_ok());
/// assert_eq!(check_resolution([0, 5]).unwrap_err().0, "res");
/// assert!(check_resolution([100_000, 100_000]).unwrap_err().1.contains("67108864"));
/// // Each side up to the limit, in either orientation.
/// let max = rayoracle::camera::MAX_RESOLUTION;
/// assert!(check_resolution([max, 1]).is_ok() && check_resolution([1, max]).is_ok());
/// for res in [[max + 1, 1], [1, max + 1]] {
///     assert!(check_resolution(res).unwrap_err().1.contains("a side exceeds"));
/// }
/// // Up to 2²⁶ pixels.
/// assert!(check_resolution([8192, 8192]).is_ok());
/// assert!(check_resolution([8192, 8193]).unwrap_err().1.contains("pixels"));
/// ```
pub fn check_resolution(res: [u32; 2]) -> Result<(), (&'static str, String)> {
    let [w, h] = res;
    if w == 0 || h == 0 {
        return Err(("res", format!("{w}×{h} has no pixels")));
    }
    let max = crate::camera::MAX_RESOLUTION;
    if w > max || h > max {
        return Err(("res", format!("{w}×{h}: a side exceeds the limit {max}")));
    }
    if u64::from(w) * u64::from(h) > MAX_PIXELS {
        return Err((
            "res",
            format!("{w}×{h} is more than the limit of {MAX_PIXELS} pixels"),
        ));
    }
    Ok(())
}

/// The depths the depth channel spreads over its 16 bits: `near` maps to
/// white, `far` to the darkest grey (see [`crate::render`] for the mapping).
///
/// ```
/// use rayoracle::scene::DepthRange;
/// assert!(DepthRange::DEFAULT.near < DepthRange::DEFAULT.far);
/// assert_eq!((DepthRange::DEFAULT.near, DepthRange::DEFAULT.far), (0.00390625, 16777216.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DepthRange {
    /// The nearest depth told apart; anything nearer is white.
    pub near: f32,
    /// The farthest depth told apart; anything farther is the darkest grey.
    pub far: f32,
}

impl DepthRange {
    /// `2⁻⁸` to `2²⁴`: 32 octaves, 2048 grey levels each.
    pub const DEFAULT: DepthRange = DepthRange {
        near: 1.0 / 256.0,
        far: 16_777_216.0,
    };
}

/// A plane in a scene.
///
/// ```
/// use rayoracle::scene::ScenePlane;
/// use glam::Vec3;
/// let p = ScenePlane { id: 1, point: Vec3::ZERO, normal: Vec3::Y };
/// assert_eq!(p.id, 1);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ScenePlane {
    /// The object's id, from 1 up.
    pub id: u32,
    /// A point on the plane.
    pub point: Vec3,
    /// Its normal (any length, not zero).
    pub normal: Vec3,
}

/// A sphere in a scene.
///
/// ```
/// use rayoracle::scene::SceneSphere;
/// use glam::Vec3;
/// let s = SceneSphere { id: 2, center: Vec3::ZERO, radius: 1.0 };
/// assert_eq!(s.radius, 1.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneSphere {
    /// The object's id, from 1 up.
    pub id: u32,
    /// The centre.
    pub center: Vec3,
    /// The radius, positive and finite.
    pub radius: f32,
}

/// A quadric in a scene.
///
/// ```
/// use rayoracle::scene::SceneQuadric;
/// let q = SceneQuadric { id: 3, coeffs: [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0] };
/// assert_eq!(q.coeffs[9], -1.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SceneQuadric {
    /// The object's id, from 1 up.
    pub id: u32,
    /// `[A … J]`, finite and not all zero.
    pub coeffs: [f32; 10],
}

/// A loaded, checked scene. The objects are plain data whatever cargo
/// features are on; compiling it into a [`crate::render::Plan`] is where a
/// kind that is compiled out is refused.
///
/// ```
/// use rayoracle::scene::Scene;
/// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]},
///     "spheres": [{"id": 1, "center": [0, 0, -3], "radius": 1}]}"#).unwrap();
/// assert_eq!((s.spheres.len(), s.camera.res), (1, [4, 3]));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Scene {
    /// A short name.
    pub name: String,
    /// What the scene is for.
    pub description: String,
    /// The camera (already checked to build).
    pub camera: CameraParams,
    /// The depth channel's range.
    pub depth: DepthRange,
    /// The planes, in file order.
    pub planes: Vec<ScenePlane>,
    /// The spheres, in file order.
    pub spheres: Vec<SceneSphere>,
    /// The quadrics, in file order.
    pub quadrics: Vec<SceneQuadric>,
}

impl Scene {
    /// Parses and checks a scene from JSON text.
    ///
    /// ```
    /// use rayoracle::scene::Scene;
    /// let text = "{\"camera\": {\"position\": [0, 0, 0], \"dir\": [0, 0, -1],\n\
    ///             \"up\": [0, 0, -2], \"angle\": 1, \"res\": [4, 3]}}";
    /// let e = Scene::parse(text).unwrap_err();
    /// assert_eq!((e.field.as_str(), e.line), ("camera.up", Some(2)));
    /// assert!(e.message.contains("parallel"), "{e}");
    /// ```
    pub fn parse(text: &str) -> Result<Scene, SceneError> {
        // A UTF-8 byte-order mark, as some editors write, is not content.
        let text = text.strip_prefix('\u{feff}').unwrap_or(text);
        // serde would read a struct from an array too (`[name, description,
        // …]`); a scene is only ever an object.
        let body = text.trim_start();
        if let Some(first) = body.chars().next()
            && first != '{'
        {
            let before = &text[..text.len() - body.len()];
            let line = before.matches('\n').count() + 1;
            let column = before.len() - before.rfind('\n').map_or(0, |i| i + 1) + 1;
            return Err(SceneError {
                line: Some(line),
                column: Some(column),
                ..SceneError::field("", "a scene is a JSON object, {\"camera\": …}")
            });
        }
        let mut de = serde_json::Deserializer::from_str(text);
        let parsed: Result<file::SceneFile, _> = serde_path_to_error::deserialize(&mut de);
        let parsed = match parsed {
            Ok(f) => f,
            Err(e) => {
                let path = e.path().to_string();
                return Err(located(path, e.into_inner()));
            }
        };
        // Trailing characters after the object.
        de.end().map_err(|e| located(String::new(), e))?;
        parsed
            .into_scene()
            .map_err(|(field, message)| SceneError::field(field, message))
    }

    /// Reads and parses a scene file; errors carry the file name.
    ///
    /// ```
    /// use rayoracle::scene::Scene;
    /// let e = Scene::load("no/such/scene.json").unwrap_err();
    /// assert!(e.to_string().starts_with("no/such/scene.json: "));
    /// ```
    pub fn load(path: impl AsRef<Path>) -> Result<Scene, SceneError> {
        let path = path.as_ref();
        let text = std::fs::read_to_string(path)
            .map_err(|e| SceneError::field("", format!("cannot read: {e}")).in_file(path))?;
        Scene::parse(&text).map_err(|e| e.in_file(path))
    }

    /// The same scene at another resolution, checked like the file's.
    ///
    /// ```
    /// use rayoracle::scene::Scene;
    /// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
    ///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#).unwrap();
    /// assert_eq!(s.with_size([8, 6]).unwrap().camera.res, [8, 6]);
    /// assert!(s.with_size([1 << 20, 1 << 20]).is_err());
    /// ```
    pub fn with_size(&self, res: [u32; 2]) -> Result<Scene, SceneError> {
        check_resolution(res).map_err(|(f, m)| SceneError::field(f, m))?;
        let mut s = self.clone();
        s.camera.res = res;
        s.camera
            .build()
            .map_err(|e| SceneError::field(format!("camera.{}", e.field()), e.to_string()))?;
        Ok(s)
    }

    /// Every object's field path and id, in plan order (planes, spheres,
    /// quadrics, each in file order).
    ///
    /// ```
    /// use rayoracle::scene::Scene;
    /// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
    ///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]},
    ///     "spheres": [{"id": 7, "center": [0, 0, -3], "radius": 1}]}"#).unwrap();
    /// assert_eq!(s.object_ids(), vec![("spheres[0]".to_string(), 7)]);
    /// ```
    pub fn object_ids(&self) -> Vec<(String, u32)> {
        let planes = self.planes.iter().map(|p| p.id);
        let spheres = self.spheres.iter().map(|s| s.id);
        let quadrics = self.quadrics.iter().map(|q| q.id);
        let tag = |kind: &'static str| move |(i, id)| (format!("{kind}[{i}]"), id);
        planes
            .enumerate()
            .map(tag("planes"))
            .chain(spheres.enumerate().map(tag("spheres")))
            .chain(quadrics.enumerate().map(tag("quadrics")))
            .collect()
    }
}

/// A serde error with its place and path, as a [`SceneError`].
fn located(path: String, inner: serde_json::Error) -> SceneError {
    // serde_path_to_error writes `.` for the root and `?` for a key it
    // could not read; neither is a field name.
    let path = path.trim_end_matches('?').trim_end_matches('.');
    let mut field = path.to_string();
    let (line, column) = (inner.line(), inner.column());
    let full = inner.to_string();
    let suffix = format!(" at line {line} column {column}");
    let mut message = full.strip_suffix(&suffix).unwrap_or(&full).to_string();
    // A check that names a sub-field (`camera` → `camera.up`).
    if let Some(rest) = message.strip_prefix(file::SUBFIELD)
        && let Some((sub, msg)) = rest.split_once(file::SUBFIELD)
    {
        field = if field.is_empty() {
            sub.to_string()
        } else {
            format!("{field}.{sub}")
        };
        message = msg.to_string();
    }
    SceneError {
        file: None,
        line: (line > 0).then_some(line),
        // serde_json says column 0 for an error before the first character
        // of a line (an empty file); columns here count from 1.
        column: (line > 0).then_some(column.max(1)),
        field,
        message,
    }
}

#[cfg(test)]
mod tests {
    use super::{Scene, located};

    /// A scene that is not an object is refused where its first character
    /// is: here line 2, column 3.
    #[test]
    fn a_non_object_is_refused_at_its_first_character() {
        let e = Scene::parse("\n  [1, 2]").unwrap_err();
        assert_eq!((e.line, e.column), (Some(2), Some(3)));
        let e = Scene::parse("7").unwrap_err();
        assert_eq!((e.line, e.column), (Some(1), Some(1)));
    }

    /// The bounds are strict: a depth range of no width and a sphere of
    /// radius 0 are refused, by field.
    #[test]
    fn the_bounds_are_strict() {
        let cam = r#""camera": {"position": [0, 0, 0], "dir": [0, 0, -1], "up": [0, 1, 0], "angle": 1, "res": [4, 3]}"#;
        let e =
            Scene::parse(&format!(r#"{{{cam}, "depth": {{"near": 2, "far": 2}}}}"#)).unwrap_err();
        assert_eq!(e.field, "depth.far", "{e}");
        let e = Scene::parse(&format!(
            r#"{{{cam}, "spheres": [{{"id": 1, "center": [0, 0, -3], "radius": 0}}]}}"#
        ))
        .unwrap_err();
        assert_eq!(e.field, "spheres[0].radius", "{e}");
    }

    /// An error serde_json could not place (line 0) has no line or column.
    #[test]
    fn an_unplaced_error_has_no_line_or_column() {
        let inner = serde_json::from_value::<u32>(serde_json::json!("x")).unwrap_err();
        assert_eq!(inner.line(), 0);
        let e = located("camera".into(), inner);
        assert_eq!((e.line, e.column, e.field.as_str()), (None, None, "camera"));
    }
}
