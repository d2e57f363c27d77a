//! Bad scenes get errors that say where (line, column, field) and what; the
//! cases are a table, run by one loop.

use rayoracle::scene::Scene;

const CAMERA: &str = r#""camera": {"position": [0, 0, 0], "dir": [0, 0, -1], "up": [0, 1, 0], "angle": 1, "res": [4, 3]}"#;

/// `(scene text, field, line, words the message must contain)`.
fn cases() -> Vec<(String, &'static str, Option<usize>, &'static str)> {
    let with = |rest: &str| format!("{{{CAMERA},\n{rest}}}");
    vec![
        ("{\n  \"camera\": {\"position\": [0, 0, 0],,\n}".into(), "camera", Some(2), "key must be a string"),
        ("".into(), "", Some(1), "EOF"),
        ("[1, 2]".into(), "", Some(1), "a scene is a JSON object"),
        ("\n  7".into(), "", Some(2), "a scene is a JSON object"),
        ("{}".into(), "", Some(1), "missing field `camera`"),
        (with(r#""sphere": []"#), "sphere", Some(2), "unknown field `sphere`"),
        (format!("{{{CAMERA}}} trailing"), "", Some(1), "trailing characters"),
        (
            r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1], "up": [0, 1, 0], "angle": 1}}"#.into(),
            "camera",
            Some(1),
            "missing field `res`",
        ),
        (
            "{\"camera\": {\"position\": [0, 0, 0], \"dir\": [0, 0, -1],\n \"up\": [0, 1, 0], \"angle\": 4, \"res\": [4, 3]}}".into(),
            "camera.angle",
            Some(2),
            "outside the open interval (0, π)",
        ),
        (
            r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, 0], "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#.into(),
            "camera.dir",
            Some(1),
            "is zero",
        ),
        (
            r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1], "up": [0, 0, 2], "angle": 1, "res": [4, 3]}}"#.into(),
            "camera.up",
            Some(1),
            "parallel to dir",
        ),
        (
            r#"{"camera": {"position": ["nan", 0, 0], "dir": [0, 0, -1], "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#.into(),
            "camera.position",
            Some(1),
            "NaN or infinite",
        ),
        (
            r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1], "up": [0, 1, 0], "angle": 1, "res": [100000, 100000]}}"#.into(),
            "camera.res",
            Some(1),
            "limit",
        ),
        (
            r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1], "up": [0, 1, 0], "angle": 1, "res": [0, 3]}}"#.into(),
            "camera.res",
            Some(1),
            "no pixels",
        ),
        (
            r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1], "up": [0, 1, 0], "angle": 1, "res": [4, -3]}}"#.into(),
            "camera.res[1]",
            Some(1),
            "invalid value",
        ),
        (
            r#"{"camera": {"position": [0, 0], "dir": [0, 0, -1], "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#.into(),
            "camera.position",
            Some(1),
            "invalid length 2",
        ),
        (
            r#"{"camera": {"position": [0, "x", 0], "dir": [0, 0, -1], "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#.into(),
            "camera.position[1]",
            Some(1),
            "expected a number",
        ),
        (with(r#""spheres": [{"id": 1, "center": [0, 0, -3], "radius": -1}]"#), "spheres[0].radius", Some(2), "not a positive finite"),
        (with(r#""spheres": [{"id": 0, "center": [0, 0, -3], "radius": 1}]"#), "spheres[0].id", Some(2), "reserved"),
        (with(r#""spheres": [{"center": [0, 0, -3], "radius": 1}]"#), "spheres[0]", Some(2), "missing field `id`"),
        (
            with("\"spheres\": [{\"id\": 1, \"center\": [0, 0, -3], \"radius\": 1},\n{\"id\": 2, \"center\": [0, 0, -3], \"radius\": \"inf\"}]"),
            "spheres[1].radius",
            Some(3),
            "inf is not a positive finite",
        ),
        (with(r#""planes": [{"id": 1, "point": [0, 0, 0], "normal": [0, 0, 0]}]"#), "planes[0].normal", Some(2), "is zero"),
        (with(r#""quadrics": [{"id": 1, "coeffs": [0, 0, 0, 0, 0, 0, 0, 0, 0, 0]}]"#), "quadrics[0].coeffs", Some(2), "all zero"),
        (with(r#""quadrics": [{"id": 1, "coeffs": [1, 1, 1]}]"#), "quadrics[0].coeffs", Some(2), "invalid length 3"),
        (with(r#""quadrics": [{"id": 1, "coeffs": [1, 1, 1, 0, 0, 0, 0, 0, 0, "-inf"]}]"#), "quadrics[0].coeffs[9]", Some(2), "not finite"),
        (
            with(r#""planes": [{"id": 3, "point": [0, 0, 0], "normal": [0, 1, 0]}], "spheres": [{"id": 3, "center": [0, 0, -3], "radius": 1}]"#),
            "spheres[0].id",
            None,
            "already the id of planes[0]",
        ),
        (with(r#""depth": {"near": 5, "far": 1}"#), "depth.far", Some(2), "above near"),
        (with(r#""depth": {"near": 0, "far": 1}"#), "depth.near", Some(2), "positive"),
    ]
}

#[test]
fn every_bad_scene_gets_a_located_error_naming_the_field() {
    for (text, field, line, words) in cases() {
        let e = Scene::parse(&text).expect_err(&text);
        let shown = e.to_string();
        assert_eq!(e.field, field, "{text}\n→ {shown}");
        assert_eq!(e.line, line, "{text}\n→ {shown}");
        assert!(e.message.contains(words), "{text}\n→ {shown}");
        assert!(line.is_none() || e.column.is_some(), "{shown}");
        assert!(
            !e.message.contains('\u{1}'),
            "internal marker leaked: {shown:?}"
        );
    }
}

#[test]
fn a_file_error_names_the_file_line_and_column() {
    // Removed on drop, a failing run's too.
    let file = tempfile::Builder::new().suffix(".json").tempfile().unwrap();
    let path = file.path();
    std::fs::write(path, "{\n  \"camera\": 7\n}\n").unwrap();
    let e = Scene::load(path).unwrap_err();
    let shown = e.to_string();
    let want = format!("{}:2:", path.display());
    assert!(shown.starts_with(&want), "{shown}");
    assert!(
        shown.contains(": camera: invalid type: integer `7`"),
        "{shown}"
    );
}

/// A byte-order mark before the object is skipped; errors after it keep
/// their line and column.
#[test]
fn a_byte_order_mark_is_not_content() {
    let s = Scene::parse(&format!("\u{feff}{}", rayoracle::fixtures::DEFAULT_SCENE)).unwrap();
    assert_eq!(s, Scene::parse(rayoracle::fixtures::DEFAULT_SCENE).unwrap());
    let e = Scene::parse("\u{feff}{\n  \"camera\": 7\n}").unwrap_err();
    assert_eq!((e.line, e.column), (Some(2), Some(13)), "{e}");
}

/// Every scene file loads, and every one is compiled into the library.
#[test]
fn every_fixture_scene_loads() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/scenes");
    let mut names = Vec::new();
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        let s = Scene::load(&path).unwrap_or_else(|e| panic!("{e}"));
        assert!(
            !s.name.is_empty() && !s.description.is_empty(),
            "{}",
            path.display()
        );
        let name = path.file_name().unwrap().to_str().unwrap().to_string();
        let compiled = rayoracle::fixtures::SCENES.iter().find(|c| c.0 == name);
        assert_eq!(
            compiled.map(|c| c.1),
            Some(std::fs::read_to_string(&path).unwrap().as_str()),
            "{name}"
        );
        names.push(name);
    }
    assert_eq!(names.len(), rayoracle::fixtures::SCENES.len());
}
