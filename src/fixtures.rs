//! The data rayoracle ships, compiled into the library: the hand-written
//! cases of every kind (`fixtures/cases/`), the stiff catalogue
//! (`fixtures/stiff/`) and the default scene. Nothing reads the source tree
//! at run time, so an installed binary and a crate that depends on
//! rayoracle see the same data as a checkout.
//!
//! ```
//! use rayoracle::{case::Kind, fixtures};
//! assert!(fixtures::cases(Kind::Sphere).lines().count() > 10);
//! assert!(fixtures::stiff(Kind::Quadric).contains("\"family\""));
//! // A kind is named by a `Kind`, so an unknown one is a parse error:
//! assert!("torus".parse::<Kind>().is_err());
//! ```

use crate::case::Kind;

/// `fixtures/stiff/families.json`: the stiff families, their kernels,
/// conditioning and reasons.
pub const STIFF_FAMILIES: &str = include_str!("../fixtures/stiff/families.json");

/// `fixtures/scenes/seed.json`, the scene `rayoracle` renders by default.
pub const DEFAULT_SCENE: &str = include_str!("../fixtures/scenes/seed.json");

/// Every scene of `fixtures/scenes/`, as `(file name, text)`: the default
/// scene and the stress scenes (a far ground sphere, a quadric zoo, a
/// grazing plane, extreme cameras).
///
/// ```
/// let (name, text) = rayoracle::fixtures::SCENES[0];
/// assert!(name.ends_with(".json") && rayoracle::scene::Scene::parse(text).is_ok());
/// ```
pub const SCENES: [(&str, &str); 9] = [
    ("seed.json", DEFAULT_SCENE),
    (
        "rtg7-stress.json",
        include_str!("../fixtures/scenes/rtg7-stress.json"),
    ),
    (
        "quadric-zoo.json",
        include_str!("../fixtures/scenes/quadric-zoo.json"),
    ),
    (
        "grazing-plane.json",
        include_str!("../fixtures/scenes/grazing-plane.json"),
    ),
    (
        "camera-narrow.json",
        include_str!("../fixtures/scenes/camera-narrow.json"),
    ),
    (
        "camera-wide.json",
        include_str!("../fixtures/scenes/camera-wide.json"),
    ),
    (
        "camera-nonsquare.json",
        include_str!("../fixtures/scenes/camera-nonsquare.json"),
    ),
    (
        "camera-long-dir.json",
        include_str!("../fixtures/scenes/camera-long-dir.json"),
    ),
    (
        "camera-tilted-up.json",
        include_str!("../fixtures/scenes/camera-tilted-up.json"),
    ),
];

/// `fixtures/cases/KIND.jsonl`: hand-written cases of a kind, one `eval`
/// line each, with their families and expectations. Every kind has the
/// file, whether or not it is compiled in.
pub fn cases(kind: Kind) -> &'static str {
    match kind {
        Kind::Plane => include_str!("../fixtures/cases/plane.jsonl"),
        Kind::Sphere => include_str!("../fixtures/cases/sphere.jsonl"),
        Kind::Quadric => include_str!("../fixtures/cases/quadric.jsonl"),
        Kind::Camera => include_str!("../fixtures/cases/camera.jsonl"),
    }
}

/// `fixtures/stiff/KIND.jsonl`: the stiff catalogue's cases of a kind.
pub fn stiff(kind: Kind) -> &'static str {
    match kind {
        Kind::Plane => include_str!("../fixtures/stiff/plane.jsonl"),
        Kind::Sphere => include_str!("../fixtures/stiff/sphere.jsonl"),
        Kind::Quadric => include_str!("../fixtures/stiff/quadric.jsonl"),
        Kind::Camera => include_str!("../fixtures/stiff/camera.jsonl"),
    }
}

#[cfg(test)]
mod tests {
    /// Every kind has both files, and every line of them parses.
    #[test]
    fn every_compiled_in_line_parses() {
        for kind in crate::case::Kind::ALL
            .into_iter()
            .filter(|k| k.compiled_in())
        {
            for (what, text) in [("cases", super::cases(kind)), ("stiff", super::stiff(kind))] {
                assert!(!text.trim().is_empty(), "{what} of {kind}");
                for (i, line) in text.lines().enumerate() {
                    if !line.trim().is_empty() {
                        let c = crate::case::parse_line(line)
                            .unwrap_or_else(|e| panic!("{what}/{kind}.jsonl:{}: {e}", i + 1));
                        assert_eq!(c.case.kind(), kind, "{what}/{kind}.jsonl:{}", i + 1);
                    }
                }
            }
        }
    }
}
