//! The data-driven fixtures: every line of `fixtures/cases/*.jsonl` is
//! parsed, the scalar reference is judged by `rayoracle::check`, and an
//! `"expect"` field (worked out by hand, not by the oracle) must be
//! reproduced by the exact oracle bit for bit. All failures are collected
//! and reported together as `file:line [family]: what`.
//!
//! `expect` keys: `class` (the oracle's class: `hit`, `parallel`,
//! `in_plane`, `none`, `tangent`, `two`, `one`, `all`, `non_finite`, and for
//! cameras `ray` or `error`), `roots_bits` (the roots' f32 bits, ascending),
//! `dir_bits` (a camera ray's direction bits), `error` (a camera
//! construction error's variant name, e.g. `DirZero`) and `stage` (for a
//! plane, sphere or quadric: the stage of the scalar reference that
//! decides it, by [`Stage::name`](rayoracle::stage::Stage::name), as
//! recorded when the line was added; a case sent to a later stage than it
//! needs still gets the right answer, so only this key shows it, and a
//! change of stage must be a deliberate one).
//!
//! Lines of a kind that is compiled out of this build (cargo features) are
//! skipped and counted; every kind that is compiled in must run at least one
//! line, and its required families.
//!
//! Run with `--nocapture` for a per-family summary of the worst errors.

use rayoracle::camera;
use rayoracle::case::{Case, CaseLine, Kind, parse_line};
use rayoracle::check::{CaseReport, Status, reference_case};
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use rayoracle::hit::Intersection;
#[cfg(feature = "plane")]
use rayoracle::plane;
#[cfg(feature = "quadric")]
use rayoracle::quadric;
#[cfg(feature = "sphere")]
use rayoracle::sphere;
use serde_json::Value;
use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

/// Families every fixture set must cover (more are welcome).
const REQUIRED_FAMILIES: &[&str] = &[
    "plane/hit",
    "plane/parallel",
    "plane/in-plane",
    "plane/origin-on-plane",
    "plane/far-1e30",
    "plane/subnormal-normal",
    "plane/nearly-parallel",
    "plane/non-finite",
    "sphere/two",
    "sphere/none",
    "sphere/origin-inside",
    "sphere/behind",
    "sphere/tangent-exact",
    "sphere/dir-tiny",
    "sphere/dir-huge",
    "sphere/far-tiny-1e7",
    "sphere/huge-close",
    "sphere/subnormal",
    "sphere/non-finite",
    "quadric/general",
    "quadric/alpha-zero-cylinder",
    "quadric/alpha-zero-paraboloid",
    "quadric/all-cone-ruling",
    "quadric/all-plane-pair",
    "quadric/all-hyperboloid-ruling",
    "quadric/sphere-as-quadric",
    "quadric/non-finite",
    "camera/centre",
    "camera/wide-fov",
    "camera/narrow-fov",
    "camera/error-zero-dir",
    "camera/error-parallel-up",
    "camera/error-angle",
    "camera/error-resolution",
];

/// The line's `kind` if it names a kind that is compiled out of this build.
fn compiled_out_kind(line: &str) -> Option<&'static str> {
    let v: Value = serde_json::from_str(line).ok()?;
    let kind = v.get("kind")?.as_str()?;
    kind.parse::<Kind>()
        .ok()
        .filter(|k| !k.compiled_in())
        .map(Kind::as_str)
}

fn fixture_files() -> Vec<PathBuf> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/cases");
    let mut files: Vec<PathBuf> = std::fs::read_dir(&dir)
        .unwrap_or_else(|e| panic!("{}: {e}", dir.display()))
        .map(|e| e.expect("directory entry").path())
        .filter(|p| p.extension().is_some_and(|x| x == "jsonl"))
        .collect();
    files.sort();
    files
}

/// The oracle's answer in the vocabulary of `expect`.
struct Oracle {
    class: &'static str,
    bits: Vec<u32>,
    error: Option<String>,
}

fn oracle(case: &Case) -> Oracle {
    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    fn hit(r: Result<impl Intersection, rayoracle::exact::NonFinite>) -> Oracle {
        match r {
            Ok(h) => Oracle {
                class: h.class().as_str(),
                bits: h.roots().as_slice().iter().map(|t| t.to_bits()).collect(),
                error: None,
            },
            Err(_) => Oracle {
                class: "non_finite",
                bits: vec![],
                error: None,
            },
        }
    }
    match case {
        #[cfg(feature = "plane")]
        Case::Plane(ray, p) => hit(plane::exact::intersect(ray, p)),
        #[cfg(feature = "sphere")]
        Case::Sphere(ray, s) => hit(sphere::exact::intersect(ray, s)),
        #[cfg(feature = "quadric")]
        Case::Quadric(ray, q) => hit(quadric::exact::intersect(ray, q)),
        Case::Camera(p, [px, py]) => match camera::exact::ray(p, *px, *py) {
            Ok(ray) => Oracle {
                class: "ray",
                bits: ray.dir.to_array().map(f32::to_bits).to_vec(),
                error: None,
            },
            Err(e) => {
                let name = format!("{e:?}");
                let name = name.split('(').next().unwrap_or_default().to_string();
                Oracle {
                    class: "error",
                    bits: vec![],
                    error: Some(name),
                }
            }
        },
    }
}

/// The stage of the scalar reference that decides `case` (`None` for a
/// camera, which has none).
fn reference_stage(case: &Case) -> Option<&'static str> {
    match case {
        #[cfg(feature = "plane")]
        Case::Plane(ray, p) => Some(plane::reference::intersect_staged(ray, p).1.name()),
        #[cfg(feature = "sphere")]
        Case::Sphere(ray, s) => Some(sphere::reference::intersect_staged(ray, s).1.name()),
        #[cfg(feature = "quadric")]
        Case::Quadric(ray, q) => Some(quadric::reference::intersect_staged(ray, q).1.name()),
        Case::Camera(..) => None,
    }
}

fn parse_bits(v: &Value) -> Result<Vec<u32>, String> {
    let items = v.as_array().ok_or("expected an array of \"0x…\" strings")?;
    items
        .iter()
        .map(|x| {
            x.as_str()
                .and_then(|s| s.strip_prefix("0x"))
                .and_then(|h| u32::from_str_radix(h, 16).ok())
                .ok_or_else(|| format!("{x} is not a \"0x…\" bit pattern"))
        })
        .collect()
}

fn show_bits(bits: &[u32]) -> String {
    let parts: Vec<String> = bits
        .iter()
        .map(|b| format!("{b:#010x} ({:e})", f32::from_bits(*b)))
        .collect();
    format!("[{}]", parts.join(", "))
}

/// Compares `expect` with the oracle; every mismatch is one message.
fn check_expect(case: &Case, expect: &Value) -> Vec<String> {
    let Some(obj) = expect.as_object() else {
        return vec!["expect: not an object".into()];
    };
    let got = oracle(case);
    let mut errs = Vec::new();
    for (key, want) in obj {
        match key.as_str() {
            "class" => match want.as_str() {
                Some(w) if w == got.class => {}
                Some(w) => errs.push(format!(
                    "expect.class: oracle says {}, expected {w}",
                    got.class
                )),
                None => errs.push("expect.class: not a string".into()),
            },
            "roots_bits" | "dir_bits" => {
                let is_camera = matches!(case, Case::Camera(..));
                if is_camera != (key == "dir_bits") {
                    errs.push(format!("expect.{key}: not for a {} case", case.kind()));
                    continue;
                }
                match parse_bits(want) {
                    Ok(w) if w == got.bits => {}
                    Ok(w) => errs.push(format!(
                        "expect.{key}: oracle gives {}, expected {}",
                        show_bits(&got.bits),
                        show_bits(&w)
                    )),
                    Err(e) => errs.push(format!("expect.{key}: {e}")),
                }
            }
            "error" => match (want.as_str(), &got.error) {
                (Some(w), Some(g)) if w == g => {}
                (Some(w), g) => {
                    errs.push(format!("expect.error: oracle gives {g:?}, expected {w}"))
                }
                (None, _) => errs.push("expect.error: not a string".into()),
            },
            "stage" => match (want.as_str(), reference_stage(case)) {
                (Some(w), Some(g)) if w == g => {}
                (Some(w), Some(g)) => errs.push(format!(
                    "expect.stage: the reference decides in stage {g}, expected {w}"
                )),
                (Some(_), None) => {
                    errs.push(format!("expect.stage: not for a {} case", case.kind()))
                }
                (None, _) => errs.push("expect.stage: not a string".into()),
            },
            other => errs.push(format!("expect.{other}: unknown key")),
        }
    }
    errs
}

/// Worst results seen in one family, for the summary.
#[derive(Default)]
struct Worst {
    lines: usize,
    root_ulps: Option<u64>,
    component_ulps: Option<f64>,
    statuses: BTreeMap<String, usize>,
}

impl Worst {
    fn add(&mut self, r: &CaseReport) {
        self.lines += 1;
        if let Some(u) = r.max_root_ulps() {
            self.root_ulps = Some(self.root_ulps.map_or(u, |w| w.max(u)));
        }
        if let Some(u) = r.max_component_ulps() {
            self.component_ulps = Some(self.component_ulps.map_or(u, |w| w.max(u)));
        }
        let key = if r.status == Status::Checked {
            r.exact_class.to_string()
        } else {
            format!("{:?}", r.status)
        };
        *self.statuses.entry(key).or_default() += 1;
    }
}

/// Runs one line; `Err` lists what failed.
fn run_line(parsed: &CaseLine, kind_prefix: &str) -> Result<CaseReport, Vec<String>> {
    let mut errs = Vec::new();
    match &parsed.family {
        None => errs.push("no \"family\" field".to_string()),
        Some(f) if !f.starts_with(kind_prefix) => errs.push(format!(
            "family \"{f}\" does not start with \"{kind_prefix}\""
        )),
        Some(_) => {}
    }
    let judged = std::panic::catch_unwind(|| reference_case(&parsed.case));
    let report = match judged {
        Ok(Ok(r)) => Some(r),
        Ok(Err(v)) => {
            errs.push(v.to_string());
            None
        }
        Err(_) => {
            errs.push("panicked while judging".to_string());
            None
        }
    };
    // x4 must give the reference's bits on every fixture line, placed in
    // each lane among unrelated cases.
    {
        use rayoracle::eval::Implementation;
        let (r, x) = (
            Implementation::Reference.run(&parsed.case),
            Implementation::X4.run(&parsed.case),
        );
        let bits = |o: &rayoracle::eval::Outcome| {
            o.values()
                .iter()
                .map(|v| if v.is_nan() { u32::MAX } else { v.to_bits() })
                .collect::<Vec<_>>()
        };
        if r.class() != x.class() || bits(&r) != bits(&x) {
            errs.push(format!("x4 {x:?} differs from the reference {r:?}"));
        }
    }
    if let Some(expect) = &parsed.expect {
        match std::panic::catch_unwind(|| check_expect(&parsed.case, expect)) {
            Ok(e) => errs.extend(e),
            Err(_) => errs.push("the oracle panicked".to_string()),
        }
    }
    match report {
        Some(r) if errs.is_empty() => Ok(r),
        _ => Err(errs),
    }
}

#[test]
fn every_fixture_line_passes() {
    let files = fixture_files();
    assert!(!files.is_empty(), "no fixtures/cases/*.jsonl files");
    let mut failures = Vec::new();
    let mut worst: BTreeMap<String, Worst> = BTreeMap::new();
    let mut total = 0;
    // Lines run and lines skipped (compiled out), per kind.
    let mut ran: BTreeMap<&str, usize> = BTreeMap::new();
    let mut skipped: BTreeMap<&str, usize> = BTreeMap::new();
    for file in &files {
        let name = file.file_name().unwrap().to_string_lossy().to_string();
        let text = std::fs::read_to_string(file).unwrap_or_else(|e| panic!("{name}: {e}"));
        for (i, line) in text.lines().enumerate() {
            if line.trim().is_empty() {
                continue;
            }
            if let Some(kind) = compiled_out_kind(line) {
                *skipped.entry(kind).or_default() += 1;
                continue;
            }
            total += 1;
            let loc = format!("{name}:{}", i + 1);
            let parsed = match parse_line(line) {
                Ok(p) => p,
                Err(e) => {
                    failures.push(format!("{loc}: malformed fixture line: {e}"));
                    continue;
                }
            };
            *ran.entry(parsed.case.kind().as_str()).or_default() += 1;
            let family = parsed.family.clone().unwrap_or_else(|| "?".into());
            let prefix = format!("{}/", parsed.case.kind());
            match run_line(&parsed, &prefix) {
                Ok(r) => worst.entry(family).or_default().add(&r),
                Err(errs) => {
                    for e in errs {
                        failures.push(format!("{loc} [{family}]: {e}"));
                    }
                }
            }
        }
    }
    for kind in Kind::ALL.into_iter().filter(|k| k.compiled_in()) {
        if !ran.contains_key(kind.as_str()) {
            failures.push(format!("no fixture line of kind {kind} ran"));
        }
    }
    let families = REQUIRED_FAMILIES.iter().filter(|f| {
        let kind = f.split('/').next().unwrap_or_default();
        kind.parse::<Kind>().is_ok_and(Kind::compiled_in)
    });
    for f in families {
        if !worst.contains_key(*f) && !failures.iter().any(|x| x.contains(&format!("[{f}]"))) {
            failures.push(format!("no fixture line of family {f}"));
        }
    }
    println!(
        "{total} fixture lines in {} files; run per kind {ran:?}; skipped (compiled out) {skipped:?}",
        files.len()
    );
    for (family, w) in &worst {
        println!(
            "{family:32} {:3} lines  worst root ulps {:>4}  worst component ulps {:>6}  {:?}",
            w.lines,
            w.root_ulps.map_or("-".into(), |u| u.to_string()),
            w.component_ulps.map_or("-".into(), |u| format!("{u:.3}")),
            w.statuses
        );
    }
    assert!(
        failures.is_empty(),
        "{} fixture failure(s) in {total} lines:\n{}",
        failures.len(),
        failures.join("\n")
    );
}
