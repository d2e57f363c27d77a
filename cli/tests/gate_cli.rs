//! `rayoracle cases`, `answer`, `judge` and `gate -- PROGRAM` end to end:
//! the protocol lines, the report, and every way a program can go wrong
//! (exit, hang, malformed line, wrong id, not found).

use crate::eval_cli::{Run, json, rayoracle};
use rayoracle::case::parse_line;

const BIN: &str = env!("CARGO_BIN_EXE_rayoracle");

/// `rayoracle gate ARGS -- sh -c SCRIPT`.
fn gate_sh(args: &[&str], script: &str) -> Run {
    let mut all = vec!["gate"];
    all.extend(args);
    all.extend(["--", "sh", "-c", script]);
    rayoracle(&all, "")
}

/// The last line of the text report.
fn verdict(r: &Run) -> &str {
    r.stdout.lines().last().unwrap_or("")
}

#[test]
fn cases_are_eval_lines_numbered_in_order_with_their_family() {
    let r = rayoracle(&["cases", "--kind", "sphere", "--budget", "2"], "");
    assert_eq!(r.code, 0, "{}", r.stderr);
    let lines = r.lines();
    assert!(lines.len() > 40, "{}", lines.len());
    for (i, line) in lines.iter().enumerate() {
        let c = parse_line(line).unwrap_or_else(|e| panic!("{e}: {line}"));
        assert_eq!(c.id, Some(i as u64));
        assert!(c.family.unwrap().starts_with("sphere/"));
    }
    let random = rayoracle(
        &["cases", "--kind", "sphere", "--family", "sphere/random"],
        "",
    );
    let families: Vec<String> = random
        .lines()
        .iter()
        .map(|l| parse_line(l).unwrap().family.unwrap())
        .collect();
    let mut distinct = families.clone();
    distinct.dedup();
    assert!(distinct.len() >= 2, "{distinct:?}");
    assert_eq!(families.len(), 256 * distinct.len(), "256 a random family");
    assert!(families.iter().all(|f| f.starts_with("sphere/random/")));
    let none = rayoracle(
        &["cases", "--kind", "sphere", "--family", "sphere/rand"],
        "",
    );
    assert_eq!(none.code, 2);
    assert!(
        none.stderr
            .contains("--family sphere/rand: no sphere family"),
        "{}",
        none.stderr
    );
    let kind = rayoracle(&["cases", "--kind", "cube"], "");
    assert_eq!(kind.code, 2);
    assert!(kind.stderr.contains("cube"), "{}", kind.stderr);
}

/// rayoracle's own kernels, answering through the pipe, pass every kind
/// under both semantics, at the strictest declaration.
#[test]
fn the_reference_passes_through_the_pipe() {
    for kind in ["plane", "sphere", "quadric", "camera"] {
        for sem in ["nearest", "whole-line"] {
            let r = rayoracle(
                &[
                    "gate",
                    "--kind",
                    kind,
                    "--semantics",
                    sem,
                    "--declared",
                    "correctly-rounded",
                    "--budget",
                    "32",
                    "--",
                    BIN,
                    "answer",
                    "--semantics",
                    sem,
                ],
                "",
            );
            assert_eq!(r.code, 0, "{kind} {sem}:\n{}{}", r.stdout, r.stderr);
            assert!(verdict(&r).starts_with("PASS: "), "{}", verdict(&r));
        }
    }
}

/// A program that never hits fails, with each failure shrunk to a small
/// case that still fails, and the JSON report says the same.
#[test]
fn a_wrong_program_fails_with_shrunk_cases_in_text_and_json() {
    let never = r#"while read l; do echo '{"t": null}'; done"#;
    let r = gate_sh(&["--kind", "sphere", "--budget", "16"], never);
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(verdict(&r).starts_with("FAIL: "), "{}", verdict(&r));
    assert!(r.stdout.contains("expected nearest"), "{}", r.stdout);
    let j = gate_sh(&["--kind", "sphere", "--budget", "16", "--json"], never);
    assert_eq!(j.code, 1);
    let report = json(j.stdout.trim());
    assert_eq!(
        (report["passed"].as_bool(), report["kind"].as_str()),
        (Some(false), Some("sphere"))
    );
    let failures = report["failures"].as_array().unwrap();
    assert!(failures.len() > 5);
    for f in failures {
        let line = f["eval_line"].as_str().unwrap();
        let case = parse_line(line).unwrap_or_else(|e| panic!("{e}: {line}"));
        assert_eq!(case.family.as_deref(), f["family"].as_str());
        assert_eq!(f["got"], "no hit");
    }
    let failing: usize = report["families"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["failures"].as_u64().unwrap() as usize)
        .sum();
    assert!(failing >= failures.len());
}

#[test]
fn a_program_that_exits_early_is_named_with_the_case_and_what_was_judged_stays() {
    let r = gate_sh(
        &["--kind", "sphere", "--budget", "4"],
        r#"read l; echo '{"t": 4.0}'; read l; echo '{"t": null}'; exit 3"#,
    );
    assert_eq!(r.code, 1);
    assert!(
        r.stdout.contains(
            "exited (exit status: 3) after 2 answer lines, without answering the case of id 2"
        ),
        "{}",
        r.stdout
    );
    assert!(r.stdout.contains("2 of "), "{}", r.stdout);
    assert!(verdict(&r).starts_with("FAIL: 2 cases"), "{}", verdict(&r));
}

#[test]
fn a_program_that_hangs_is_stopped_after_the_timeout() {
    let r = gate_sh(
        &["--kind", "plane", "--timeout", "0.3"],
        "read l; exec sleep 30",
    );
    assert_eq!(r.code, 1);
    assert!(
        r.stdout
            .contains("gave no answer line 1 (the case of id 0) within 300ms"),
        "{}",
        r.stdout
    );
}

/// A kernel that is a grandchild (here behind `sh -c`, as behind `npm
/// run`) is stopped with the program at the timeout, not left running.
#[cfg(target_os = "linux")]
#[test]
fn a_hanging_program_is_stopped_with_the_processes_it_started() {
    let dir = crate::cli::temp_dir("grandchild");
    let pid_file = dir.join("pid");
    let script = format!(
        "read l; sleep 600 </dev/null >/dev/null 2>&1 & echo $! > {}; wait",
        pid_file.display()
    );
    let r = gate_sh(&["--kind", "plane", "--timeout", "0.5"], &script);
    assert_eq!(r.code, 1, "{}", r.stderr);
    assert!(
        r.stdout.contains("within 500ms, so it was stopped"),
        "{}",
        r.stdout
    );
    let pid = std::fs::read_to_string(&pid_file).expect("the script wrote the pid");
    // Gone, or a zombie until init reaps it: either way not running.
    let state = std::fs::read_to_string(format!("/proc/{}/stat", pid.trim()))
        .ok()
        .and_then(|s| Some(s.rsplit_once(')')?.1.split_whitespace().next()?.to_string()));
    if matches!(state.as_deref(), Some(s) if s != "Z") {
        let _ = std::process::Command::new("kill").arg(pid.trim()).status();
        panic!("the grandchild {} still runs ({state:?})", pid.trim());
    }
}

/// A malformed line fails its own case, named by its line, and the run
/// goes on; so does an answer carrying another case's id.
#[test]
fn malformed_lines_and_wrong_ids_fail_their_case_and_the_rest_goes_on() {
    let script = format!(
        r#"read l; echo 'hit at 4'; read l; echo '{{"id": 99, "t": 3}}'; exec {BIN} answer"#
    );
    let r = gate_sh(
        &["--kind", "sphere", "--budget", "8", "--no-shrink", "--json"],
        &script,
    );
    assert_eq!(r.code, 1);
    let report = json(r.stdout.trim());
    let whys: Vec<&str> = report["failures"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f["why"].as_str().unwrap())
        .collect();
    assert_eq!(whys.len(), 2, "{whys:?}");
    assert!(
        whys[0].starts_with("answer line 1 is malformed: not a JSON object"),
        "{}",
        whys[0]
    );
    assert_eq!(
        whys[1],
        "answer line 2 has id 99, but answers the case of id 1"
    );
    assert_eq!(report["stopped"], serde_json::Value::Null);
    assert!(report["cases"].as_u64().unwrap() > 100);
}

#[test]
fn a_program_that_cannot_start_exits_2() {
    let r = rayoracle(
        &["gate", "--kind", "sphere", "--", "/nonexistent/kernel"],
        "",
    );
    assert_eq!(r.code, 2);
    assert!(
        r.stderr.contains("cannot start /nonexistent/kernel"),
        "{}",
        r.stderr
    );
    let r = rayoracle(&["gate", "--kind", "sphere"], "");
    assert_eq!(r.code, 2, "a program is required");
}

/// `cases` → `answer` → `judge` passes; a damaged answer file fails the
/// cases it no longer answers and names its bad lines.
#[test]
fn judge_matches_answers_by_id() {
    let cases = rayoracle(&["cases", "--kind", "quadric", "--budget", "8"], "");
    let answers = rayoracle(&["answer", "--semantics", "whole-line"], &cases.stdout);
    assert_eq!(answers.code, 0, "{}", answers.stderr);
    let mut lines: Vec<&str> = answers.stdout.lines().collect();
    lines.reverse(); // order does not matter, ids do
    let judge = |text: &str| {
        let args = "judge --kind quadric --budget 8 --semantics whole-line -";
        rayoracle(&args.split(' ').collect::<Vec<_>>(), text)
    };
    let r = judge(&lines.join("\n"));
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    assert!(verdict(&r).starts_with("PASS: "));
    lines[0] = "garbage";
    lines[1] = r#"{"id": 100000, "t": 1}"#;
    let r = judge(&lines.join("\n"));
    assert_eq!(r.code, 1);
    assert!(r.stderr.contains("-:1: not a JSON object"), "{}", r.stderr);
    assert!(
        r.stderr
            .contains("-:2: id 100000 is not a case of this selection"),
        "{}",
        r.stderr
    );
    assert_eq!(
        r.stdout.matches("no answer line has id").count(),
        2,
        "{}",
        r.stdout
    );
}

/// Every semantics and declaration of the Rust gate is a flag: the exact
/// answers pass each semantics; a precondition's skips are counted in
/// the report; a bad precondition or semantics is refused naming the
/// valid forms.
#[test]
fn every_semantics_and_precondition_is_a_flag() {
    for sem in ["solid", "range:0.5:100", "roots-in:-1:3"] {
        let r = rayoracle(
            &[
                "gate",
                "--kind",
                "quadric",
                "--semantics",
                sem,
                "--declared",
                "correctly-rounded",
                "--budget",
                "16",
                "--",
                BIN,
                "answer",
                "--semantics",
                sem,
            ],
            "",
        );
        assert_eq!(r.code, 0, "{sem}:\n{}{}", r.stdout, r.stderr);
    }
    // The whole line's answers under a nearest-hit semantics fail.
    let r = rayoracle(
        &[
            "gate",
            "--kind",
            "sphere",
            "--semantics",
            "solid",
            "--budget",
            "16",
            "--",
            BIN,
            "answer",
            "--semantics",
            "whole-line",
        ],
        "",
    );
    assert_eq!(r.code, 1);
    let r = rayoracle(
        &[
            "gate",
            "--kind",
            "sphere",
            "--declared",
            "careful-f32-renderer",
            "--require",
            "magnitudes:1e-3:1e3",
            "--budget",
            "16",
            "--json",
            "--",
            BIN,
            "answer",
        ],
        "",
    );
    assert_eq!(r.code, 0, "{}{}", r.stdout, r.stderr);
    let report = json(r.stdout.trim());
    let skipped = report["skipped"].as_array().unwrap();
    assert!(
        skipped
            .iter()
            .any(|s| s["precondition"] == "magnitudes" && s["cases"].as_u64() > Some(0)),
        "{skipped:?}"
    );
    let bad = rayoracle(&["cases", "--kind", "sphere", "--require", "positive"], "");
    assert_eq!(bad.code, 2);
    assert!(
        bad.stderr
            .contains("--require positive: unknown precondition"),
        "{}",
        bad.stderr
    );
    let bad = rayoracle(
        &["cases", "--kind", "sphere", "--semantics", "range:2:1"],
        "",
    );
    assert_eq!(bad.code, 2);
    assert!(bad.stderr.contains("roots-in:T0:T1"), "{}", bad.stderr);
}

/// Hit points are an answer form: the exact hit point passes, a point on
/// the far side fails.
#[test]
fn hit_points_are_an_answer_form() {
    let args = [
        "--kind",
        "sphere",
        "--family",
        "sphere/two",
        "--budget",
        "1",
        "--no-shrink",
    ];
    let case = rayoracle(&[&["cases"], &args[..6]].concat(), "");
    assert_eq!(
        case.stdout.trim(),
        r#"{"id":0,"family":"sphere/two","kind":"sphere","origin":[0.0,0.0,-5.0],"dir":[0.0,0.0,1.0],"center":[0.0,0.0,0.0],"radius":1.0}"#
    );
    let near = gate_sh(
        &args,
        r#"while read l; do echo '{"point":[0.0,0.0,-1.0]}'; done"#,
    );
    assert_eq!(near.code, 0, "{}", near.stdout);
    let far = gate_sh(
        &args,
        r#"while read l; do echo '{"point":[0.0,0.0,1.0]}'; done"#,
    );
    assert_eq!(far.code, 1, "{}", far.stdout);
}
