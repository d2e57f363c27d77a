//! Located scene errors.

use std::path::PathBuf;

/// Why a scene could not be loaded, and where: the file, the line and column
/// (from serde_json, when the problem is in the text), and the field path
/// (`camera.up`, `spheres[2].radius`).
///
/// ```
/// use rayoracle::scene::Scene;
/// let e = Scene::parse("{\"camera\": 3}").unwrap_err();
/// assert_eq!((e.line, e.field.as_str()), (Some(1), "camera"));
/// assert!(e.to_string().starts_with("<scene>:1:"));
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct SceneError {
    /// The scene file, when there is one.
    pub file: Option<PathBuf>,
    /// 1-based line, when the error is tied to a place in the text.
    pub line: Option<usize>,
    /// 1-based column, with `line`.
    pub column: Option<usize>,
    /// The field path, `""` for the whole scene.
    pub field: String,
    /// What is wrong.
    pub message: String,
}

impl SceneError {
    /// An error about a field, not tied to a place in the text.
    ///
    /// ```
    /// use rayoracle::scene::SceneError;
    /// let e = SceneError::field("camera.res", "too large");
    /// assert_eq!(e.to_string(), "<scene>: camera.res: too large");
    /// ```
    pub fn field(field: impl Into<String>, message: impl Into<String>) -> SceneError {
        SceneError {
            file: None,
            line: None,
            column: None,
            field: field.into(),
            message: message.into(),
        }
    }

    /// The same error, attributed to `file`.
    ///
    /// ```
    /// use rayoracle::scene::SceneError;
    /// let e = SceneError::field("camera", "bad").in_file("a.json");
    /// assert_eq!(e.to_string(), "a.json: camera: bad");
    /// ```
    pub fn in_file(mut self, file: impl Into<PathBuf>) -> SceneError {
        self.file = Some(file.into());
        self
    }
}

impl core::fmt::Display for SceneError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        match &self.file {
            Some(p) => write!(f, "{}", p.display())?,
            None => write!(f, "<scene>")?,
        }
        if let (Some(l), Some(c)) = (self.line, self.column) {
            write!(f, ":{l}:{c}")?;
        }
        if !self.field.is_empty() {
            write!(f, ": {}", self.field)?;
        }
        write!(f, ": {}", self.message)
    }
}

impl std::error::Error for SceneError {}
