//! `rayoracle eval` end to end: the binary, its output lines, its exit codes.
//! Tests that need a kind run only when its cargo feature is on; a kind that
//! is off must give an error line instead.

use std::io::Write;
use std::process::{Command, Stdio};

const SPHERE: &str =
    r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#;
const SPHERE_OUT: &str = concat!(
    r#""results":{"exact":{"class":"two","roots":[4.0,6.0],"roots_bits":["0x40800000","0x40c00000"]},"#,
    r#""reference":{"class":"two","roots":[4.0,6.0],"roots_bits":["0x40800000","0x40c00000"],"#,
    r#""class_match":true,"ulps":[0,0],"bits":[0.0,0.0]},"#,
    r#""x4":{"class":"two","roots":[4.0,6.0],"roots_bits":["0x40800000","0x40c00000"],"#,
    r#""class_match":true,"ulps":[0,0],"bits":[0.0,0.0]}}}"#
);
const PLANE: &str =
    r#"{"kind":"plane","origin":[0,0,0],"dir":[0,0,1],"point":[0,0,2],"normal":[0,0,1]}"#;
const QUADRIC: &str =
    r#"{"kind":"quadric","origin":[-5,0,0],"dir":[1,0,0],"coeffs":[1,1,0,0,0,0,0,0,0,-1]}"#;
const CAMERA: &str = r#"{"kind":"camera","position":[1,2,3],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[3,3],"pixel":[1,1]}"#;

pub(crate) struct Run {
    pub(crate) code: i32,
    pub(crate) stdout: String,
    pub(crate) stderr: String,
}

impl Run {
    pub(crate) fn lines(&self) -> Vec<&str> {
        self.stdout.lines().collect()
    }
}

pub(crate) fn rayoracle(args: &[&str], stdin: &str) -> Run {
    let mut child = Command::new(env!("CARGO_BIN_EXE_rayoracle"))
        .args(args)
        .stdin(Stdio::piped())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .expect("the binary runs");
    child
        .stdin
        .take()
        .unwrap()
        .write_all(stdin.as_bytes())
        .unwrap();
    let out = child.wait_with_output().unwrap();
    Run {
        code: out.status.code().expect("exited, not killed by a signal"),
        stdout: String::from_utf8(out.stdout).unwrap(),
        stderr: String::from_utf8(out.stderr).unwrap(),
    }
}

/// A file of `lines` in the system temp directory (never in `fixtures/`),
/// its name ending in `name`: a path that removes the file when it drops.
fn temp_file(name: &str, lines: &[&str]) -> tempfile::TempPath {
    let mut file = tempfile::Builder::new()
        .prefix("rayoracle-eval-cli-")
        .suffix(&format!("-{name}"))
        .tempfile()
        .unwrap();
    let mut text = lines.join("\n");
    text.push('\n');
    file.write_all(text.as_bytes()).unwrap();
    file.into_temp_path()
}

pub(crate) fn json(line: &str) -> serde_json::Value {
    serde_json::from_str(line).unwrap_or_else(|e| panic!("not JSON ({e}): {line}"))
}
#[test]
fn mixed_input_gives_one_line_per_case_in_order_and_exit_1() {
    let input = [
        SPHERE,                                                                  // 1
        "",                                                                      // 2 blank
        r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0]}"#, // 3
        r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1,"colour":2}"#, // 4
        r#"{"kind":"sphere","origin":[0,0,-5],"#, // 5
        r#"{"kind":"plane","origin":[0,0],"dir":[0,0,1],"point":[0,0,2],"normal":[0,0,1]}"#, // 6
        r#"{"kind":"sphere","family":"nan","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":"nan"}"#, // 7
        PLANE,   // 8
        QUADRIC, // 9
        CAMERA,  // 10
        r#"{"kind":"camera","position":[0,0,0],"dir":[0,1,0],"up":[0,2,0],"angle":1,"res":[3,3],"pixel":[1,1]}"#, // 11
        "   \t ", // 12 blank
        r#"{"kind":"quadric","origin":[0,0,0],"dir":[1,0,0],"coeffs":[1,1,0,0,0,0,0,0,0]}"#, // 13
    ];
    let path = temp_file("mixed.jsonl", &input);
    let run = rayoracle(&["eval", path.to_str().unwrap()], "");

    assert_eq!(
        run.code, 1,
        "a malformed line gives exit 1; stderr: {}",
        run.stderr
    );
    let lines = run.lines();
    let numbers: Vec<u64> = lines
        .iter()
        .map(|l| json(l)["line"].as_u64().unwrap())
        .collect();
    assert_eq!(numbers, [1, 3, 4, 5, 6, 7, 8, 9, 10, 11, 13]);

    assert_eq!(
        lines[0],
        format!(r#"{{"line":1,"kind":"sphere",{SPHERE_OUT}"#)
    );
    assert_eq!(lines[1], r#"{"line":3,"error":"radius: missing"}"#);
    assert_eq!(lines[2], r#"{"line":4,"error":"colour: unknown field"}"#);
    assert!(
        lines[3].starts_with(r#"{"line":5,"error":"json: "#),
        "{}",
        lines[3]
    );
    assert_eq!(
        lines[4],
        r#"{"line":6,"error":"origin: expected 3 numbers, got 2"}"#
    );
    assert_eq!(
        lines[5],
        concat!(
            r#"{"line":7,"kind":"sphere","family":"nan","results":{"#,
            r#""exact":{"error":"an input is NaN or infinite, so it has no exact value"},"#,
            r#""reference":{"class":"none","roots":[],"roots_bits":[]},"#,
            r#""x4":{"class":"none","roots":[],"roots_bits":[]}}}"#
        )
    );
    assert_eq!(
        lines[6],
        concat!(
            r#"{"line":8,"kind":"plane","results":{"#,
            r#""exact":{"class":"hit","roots":[2.0],"roots_bits":["0x40000000"]},"#,
            r#""reference":{"class":"hit","roots":[2.0],"roots_bits":["0x40000000"],"class_match":true,"ulps":[0],"bits":[0.0]},"#,
            r#""x4":{"class":"hit","roots":[2.0],"roots_bits":["0x40000000"],"class_match":true,"ulps":[0],"bits":[0.0]}}}"#
        )
    );
    let quadric = json(lines[7]);
    assert_eq!(quadric["kind"], "quadric");
    assert_eq!(
        quadric["results"]["exact"]["roots_bits"],
        serde_json::json!(["0x40800000", "0x40c00000"])
    );
    assert_eq!(
        quadric["results"]["reference"]["ulps"],
        serde_json::json!([0, 0])
    );
    assert_eq!(
        lines[8],
        concat!(
            r#"{"line":10,"kind":"camera","results":{"#,
            r#""exact":{"class":"ray","origin":[1.0,2.0,3.0],"dir":[0.0,0.0,-1.0],"dir_bits":["0x00000000","0x00000000","0xbf800000"]},"#,
            r#""reference":{"class":"ray","origin":[1.0,2.0,3.0],"dir":[0.0,0.0,-1.0],"dir_bits":["0x00000000","0x00000000","0xbf800000"],"#,
            r#""class_match":true,"ulps":[0,0,0],"bits":[0.0,0.0,0.0]},"#,
            r#""x4":{"class":"ray","origin":[1.0,2.0,3.0],"dir":[0.0,0.0,-1.0],"dir_bits":["0x00000000","0x00000000","0xbf800000"],"#,
            r#""class_match":true,"ulps":[0,0,0],"bits":[0.0,0.0,0.0]}}}"#
        )
    );
    assert_eq!(
        lines[9],
        r#"{"line":11,"kind":"camera","error":"up: is parallel to dir, so there is no horizontal axis"}"#
    );
    assert_eq!(
        lines[10],
        r#"{"line":13,"error":"coeffs: expected 10 numbers, got 9"}"#
    );

    // The summary goes to stderr, not into the JSON stream.
    assert!(run.stderr.contains("sphere"), "{}", run.stderr);
    assert!(run.stderr.contains("reference"), "{}", run.stderr);
    assert!(run.stderr.contains("5 malformed"), "{}", run.stderr);
    assert!(!run.stdout.contains("malformed"));
}
#[test]
fn all_good_lines_exit_0_with_a_summary_on_stderr() {
    let path = temp_file("good.jsonl", &[PLANE, SPHERE, "", QUADRIC, CAMERA]);
    let run = rayoracle(&["eval", path.to_str().unwrap()], "");
    assert_eq!(run.code, 0, "stderr: {}", run.stderr);
    let kinds: Vec<String> = run
        .lines()
        .iter()
        .map(|l| json(l)["kind"].as_str().unwrap().to_string())
        .collect();
    assert_eq!(kinds, ["plane", "sphere", "quadric", "camera"]);
    for kind in ["plane", "sphere", "quadric", "camera"] {
        assert!(
            run.stderr
                .lines()
                .any(|l| l.starts_with(kind) && l.contains("reference")),
            "no {kind} row in:\n{}",
            run.stderr
        );
    }
}
#[test]
fn nan_input_is_evaluated_not_malformed() {
    let nan =
        r#"{"kind":"plane","origin":[0,0,0],"dir":[0,0,"nan"],"point":[0,0,2],"normal":[0,0,1]}"#;
    let run = rayoracle(&["eval", "-"], &format!("{nan}\n"));
    assert_eq!(run.code, 0, "stderr: {}", run.stderr);
    let out = json(run.stdout.trim_end());
    assert_eq!(
        out["results"]["exact"]["error"],
        "an input is NaN or infinite, so it has no exact value"
    );
    let reference = out["results"]["reference"].as_object().unwrap();
    assert!(reference.contains_key("class"));
    for key in ["class_match", "ulps", "bits"] {
        assert!(!reference.contains_key(key), "{key} in {reference:?}");
    }
}

#[test]
fn a_camera_that_cannot_be_built_is_an_error_line_and_exit_1() {
    let bad = r#"{"kind":"camera","family":"fov","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":4,"res":[3,3],"pixel":[0,0]}"#;
    let run = rayoracle(&["eval"], &format!("{bad}\n"));
    assert_eq!(run.code, 1);
    assert_eq!(
        run.stdout,
        "{\"line\":1,\"kind\":\"camera\",\"family\":\"fov\",\"error\":\"angle: 4 is outside the open interval (0, π)\"}\n"
    );
}
#[test]
fn stdin_dash_and_no_file_both_read_stdin() {
    let input = format!("{SPHERE}\n\n{PLANE}\r\n");
    let dash = rayoracle(&["eval", "-"], &input);
    let none = rayoracle(&["eval"], &input);
    assert_eq!(dash.code, 0, "stderr: {}", dash.stderr);
    assert_eq!(dash.stdout, none.stdout);
    assert_eq!(none.code, 0);
    let lines = dash.lines();
    assert_eq!(lines.len(), 2);
    assert_eq!(
        lines[0],
        format!(r#"{{"line":1,"kind":"sphere",{SPHERE_OUT}"#)
    );
    assert!(
        lines[1].starts_with(r#"{"line":3,"kind":"plane","#),
        "{}",
        lines[1]
    );
}

#[test]
fn a_missing_file_exits_2_naming_the_file_and_the_os_error() {
    let path = std::env::temp_dir().join(format!(
        "rayoracle-eval-cli-{}-does-not-exist.jsonl",
        std::process::id()
    ));
    let run = rayoracle(&["eval", path.to_str().unwrap()], "");
    assert_eq!(run.code, 2);
    assert_eq!(run.stdout, "");
    assert!(
        run.stderr.starts_with(&format!(
            "rayoracle: cannot read {}: No such file or directory (os error 2)\n",
            path.display()
        )),
        "{}",
        run.stderr
    );
}

/// Several files are read in order, each output line keyed by its file; a
/// file that cannot be read is named and the others are still evaluated.
#[test]
fn several_files_are_evaluated_in_order_and_a_missing_one_does_not_stop_them() {
    let a = temp_file("several-a.jsonl", &[SPHERE]);
    let b = temp_file("several-b.jsonl", &["", SPHERE]);
    let missing = std::env::temp_dir().join("rayoracle-eval-cli-no-such.jsonl");
    let args = [
        a.to_str().unwrap(),
        missing.to_str().unwrap(),
        b.to_str().unwrap(),
    ];
    let run = rayoracle(&[&["eval"][..], &args].concat(), "");
    assert_eq!(run.code, 2, "{}", run.stderr);
    let lines = run.lines();
    assert_eq!(lines.len(), 2);
    assert_eq!(json(lines[0])["file"], args[0]);
    assert_eq!(json(lines[0])["line"], 1);
    assert_eq!(json(lines[1])["file"], args[2]);
    assert_eq!(json(lines[1])["line"], 2);
    assert!(
        run.stderr.contains(&format!("cannot read {}", args[1])),
        "{}",
        run.stderr
    );
}

/// Each line that is not evaluated is named on stderr with its file and
/// line, as well as in the JSON on stdout.
#[test]
fn a_malformed_line_is_named_on_stderr_with_its_file_and_line() {
    let run = rayoracle(&["eval"], &format!("{SPHERE}\n{{\"kind\":\"sphere\"}}\n"));
    assert_eq!(run.code, 1);
    assert!(
        run.stderr
            .starts_with("rayoracle: stdin:2: origin: missing\n"),
        "{}",
        run.stderr
    );
    let f = temp_file("named.jsonl", &[SPHERE, "", "{\"kind\":1}"]);
    let run = rayoracle(&["eval", f.to_str().unwrap()], "");
    assert!(
        run.stderr
            .starts_with(&format!("rayoracle: {}:3: kind:", f.display())),
        "{}",
        run.stderr
    );
    assert!(!run.stdout.contains("\"file\""), "one file: no file key");
}

/// A UTF-8 byte-order mark (as some Windows editors write) is skipped.
#[test]
fn a_byte_order_mark_is_skipped() {
    let run = rayoracle(&["eval"], &format!("\u{feff}{SPHERE}\n"));
    assert_eq!(run.code, 0, "{}", run.stderr);
    assert_eq!(json(run.lines()[0])["results"]["exact"]["class"], "two");
}
#[test]
fn a_bad_line_does_not_stop_the_run() {
    let mut input = String::new();
    for i in 0..200 {
        input.push_str(if i % 3 == 1 { "{not json\n" } else { SPHERE });
        if i % 3 != 1 {
            input.push('\n');
        }
    }
    let run = rayoracle(&["eval", "-"], &input);
    assert_eq!(run.code, 1);
    let lines = run.lines();
    assert_eq!(lines.len(), 200);
    for (i, line) in lines.iter().enumerate() {
        let v = json(line);
        assert_eq!(v["line"].as_u64(), Some(i as u64 + 1));
        assert_eq!(v.get("error").is_some(), i % 3 == 1, "{line}");
    }
}

/// A reader that closes the pipe early (`| head`) is not an I/O error:
/// the exit code is the run's own. A write that fails for another reason
/// (a full disk) is one, with the OS error named.
#[cfg(target_os = "linux")]
#[test]
fn a_closed_pipe_is_not_an_error_but_a_full_disk_is() {
    use std::io::Read;
    use std::process::{Command, Stdio};
    // Far more output than a pipe buffers (about 6 MB for 64 KiB).
    let line = r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#;
    let path = temp_file("many.jsonl", &vec![line; 20_000]);
    let input = path.to_str().unwrap();
    let mut child = Command::new(env!("CARGO_BIN_EXE_rayoracle"))
        .args(["eval", input])
        .stdout(Stdio::piped())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    let mut first = [0u8; 16];
    child.stdout.take().unwrap().read_exact(&mut first).unwrap();
    // The pipe is closed here, with most of the output unwritten.
    let code = child.wait().unwrap().code();
    assert!(matches!(code, Some(0 | 1)), "{code:?}");

    let full = std::fs::File::create("/dev/full").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_rayoracle"))
        .args(["eval", input])
        .stdout(full)
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot write stdout"));
}
