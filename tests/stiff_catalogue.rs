//! The catalogue of stiff cases, `fixtures/stiff/`, as committed (nothing is
//! regenerated here; `cargo run --example stiff_catalogue -- --check` does
//! that):
//!
//! * every line of `<kernel>.jsonl` parses, is of its file's kind and names
//!   a family; the families of the data and of `families.json` are the same
//!   set, each with at least 64 cases, and `README.md` lists each one;
//! * every case of a well-conditioned family is inside its kernel's stated
//!   domain, and each of its roots has a bound of at most 2 ulps (κ small),
//!   unless it is an exact construction with an `expect` (a tangent);
//! * the exact constructions are what they claim: the exact oracle gives
//!   the `expect`ed class and root bits, α (and β) are exactly zero where
//!   the family says so.
#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]

use rayoracle::case::{Case, CaseLine, parse_line};
use rayoracle::check::{self, CaseReport, Status};
use rayoracle::hit::Intersection;
use rayoracle::{camera, plane, quadric, sphere};
use serde_json::Value;
use std::collections::{BTreeMap, BTreeSet};

const DIR: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/fixtures/stiff");
const KERNELS: [&str; 4] = ["sphere", "plane", "quadric", "camera"];
const MIN_CASES: usize = 64;

/// The exact constructions: each line must carry an `expect` with one of
/// these classes.
const EXACT: &[(&str, &[&str])] = &[
    ("sphere/exact-tangent", &["tangent"]),
    ("plane/in-plane", &["in_plane"]),
    ("quadric/alpha-zero-cylinder", &["none", "all"]),
    ("quadric/alpha-zero-paraboloid", &["one"]),
    ("quadric/line-on-surface", &["all"]),
    ("quadric/cone-apex", &["one"]),
    ("quadric/double-plane", &["one"]),
];

struct Family {
    kernel: String,
    well: bool,
}

/// `families.json`, in its order.
fn families() -> Vec<(String, Family)> {
    let path = format!("{DIR}/families.json");
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
    let v: Value = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{path}: {e}"));
    let mut out: Vec<(String, Family)> = Vec::new();
    for f in v.as_array().expect("an array") {
        let obj = f.as_object().expect("objects");
        let keys: Vec<&str> = obj.keys().map(String::as_str).collect();
        let mut want = vec!["conditioning", "family", "kernel", "why"];
        want.sort();
        let mut got = keys.clone();
        got.sort();
        assert_eq!(got, want, "{f}");
        let s = |k: &str| {
            obj[k]
                .as_str()
                .unwrap_or_else(|| panic!("{k}: {f}"))
                .to_string()
        };
        let (name, kernel, cond) = (s("family"), s("kernel"), s("conditioning"));
        assert!(KERNELS.contains(&kernel.as_str()), "{f}");
        assert_eq!(name.split('/').next(), Some(kernel.as_str()), "{f}");
        assert!(cond == "well" || cond == "ill", "{f}");
        assert!(s("why").len() > 40, "{name}: say why");
        assert!(out.iter().all(|(n, _)| *n != name), "{name} twice");
        let well = cond == "well";
        out.push((name, Family { kernel, well }));
    }
    out
}

/// Every line of the data, as `(file:line, parsed)`.
fn lines() -> Vec<(String, CaseLine)> {
    let mut out = Vec::new();
    for kernel in KERNELS {
        let path = format!("{DIR}/{kernel}.jsonl");
        let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{path}: {e}"));
        for (i, line) in text.lines().enumerate() {
            let at = format!("{kernel}.jsonl:{}", i + 1);
            let c = parse_line(line).unwrap_or_else(|e| panic!("{at}: {e}"));
            assert_eq!(c.case.kind().as_str(), kernel, "{at}");
            assert!(c.family.is_some(), "{at}: no family");
            out.push((at, c));
        }
    }
    out
}

/// The exact oracle's answer judged by `check` against itself: the domain,
/// the margin and band, and each root's κ and bound.
fn self_report(case: &Case) -> CaseReport {
    let r = match case {
        Case::Sphere(ray, s) => {
            check::check_sphere(ray, s, sphere::exact::intersect(ray, s).unwrap())
        }
        Case::Plane(ray, p) => check::check_plane(ray, p, plane::exact::intersect(ray, p).unwrap()),
        Case::Quadric(ray, q) => {
            check::check_quadric(ray, q, quadric::exact::intersect(ray, q).unwrap())
        }
        Case::Camera(p, [x, y]) => check::check_camera(p, [*x, *y], camera::exact::ray(p, *x, *y)),
    };
    r.expect("the exact answer passes its own check")
}

/// Every kernel is correctly rounded on every finite input: a case is in
/// the domain when the camera, if it is one, builds.
fn in_domain(case: &Case) -> bool {
    match case {
        Case::Camera(p, _) => p.build().is_ok(),
        _ => true,
    }
}

#[test]
fn every_line_parses_and_every_family_is_documented() {
    let fams = families();
    let lines = lines();
    let mut counts: BTreeMap<&str, usize> = BTreeMap::new();
    for (at, c) in &lines {
        let name = c.family.as_deref().unwrap();
        let (_, f) = fams
            .iter()
            .find(|(n, _)| n == name)
            .unwrap_or_else(|| panic!("{at}: family {name} is not in families.json"));
        assert_eq!(c.case.kind().as_str(), f.kernel, "{at}");
        *counts.entry(name).or_default() += 1;
    }
    let readme = std::fs::read_to_string(format!("{DIR}/README.md")).expect("README.md");
    for (name, _) in &fams {
        let n = counts.get(name.as_str()).copied().unwrap_or(0);
        assert!(
            n >= MIN_CASES,
            "{name}: {n} cases, want at least {MIN_CASES}"
        );
        assert!(readme.contains(&format!("`{name}`")), "README.md: {name}");
    }
    assert_eq!(counts.len(), fams.len());
}

#[test]
fn well_conditioned_families_have_kappa_at_most_2_to_the_18() {
    let fams: BTreeMap<String, Family> = families().into_iter().collect();
    let mut checked = 0;
    for (at, c) in lines() {
        let name = c.family.as_deref().unwrap();
        if !fams[name].well {
            continue;
        }
        assert!(in_domain(&c.case), "{at} [{name}]: outside the domain");
        if let Case::Camera(p, _) = &c.case {
            assert!(p.build().is_ok(), "{at}: the camera cannot be built");
        }
        let r = self_report(&c.case);
        assert_eq!(r.status, Status::Checked, "{at} [{name}]");
        if c.expect.is_none() {
            for root in &r.roots {
                assert!(
                    root.kappa <= 2f64.powi(18),
                    "{at} [{name}]: root {} has κ = {:e}",
                    root.exact,
                    root.kappa
                );
            }
        }
        checked += 1;
    }
    assert!(checked > 0);
}

#[test]
fn exact_constructions_are_what_they_claim() {
    let mut seen: BTreeSet<&str> = BTreeSet::new();
    for (at, c) in lines() {
        let name = c.family.as_deref().unwrap();
        let claimed = EXACT.iter().find(|(n, _)| *n == name).map(|(_, cl)| *cl);
        let Some(expect) = &c.expect else {
            assert!(claimed.is_none(), "{at} [{name}]: no expect");
            continue;
        };
        let classes = claimed.unwrap_or_else(|| panic!("{at} [{name}]: unexpected expect"));
        if let Some((n, _)) = EXACT.iter().find(|(n, _)| *n == name) {
            seen.insert(n);
        }
        let class = expect["class"].as_str().expect("expect.class");
        assert!(classes.contains(&class), "{at} [{name}]: claims {class}");
        let (got, roots) = match &c.case {
            Case::Sphere(ray, s) => {
                let h = sphere::exact::intersect(ray, s).unwrap();
                (h.class(), h.roots().as_slice().to_vec())
            }
            Case::Plane(ray, p) => {
                let h = plane::exact::intersect(ray, p).unwrap();
                (h.class(), h.roots().as_slice().to_vec())
            }
            Case::Quadric(ray, q) => {
                let e = quadric::exact::quadratic(ray, q).unwrap();
                if name.starts_with("quadric/alpha-zero") {
                    assert!(e.alpha.is_zero(), "{at} [{name}]: α ≠ 0");
                }
                if name == "quadric/alpha-zero-cylinder" {
                    assert!(e.beta.is_zero(), "{at} [{name}]: β ≠ 0");
                }
                let h = quadric::exact::classify(&e);
                (h.class(), h.roots().as_slice().to_vec())
            }
            Case::Camera(..) => unreachable!("no camera family is an exact construction"),
        };
        assert_eq!(got, class, "{at} [{name}]: the exact class");
        if let Some(bits) = expect.get("roots_bits") {
            let want: Vec<&str> = bits
                .as_array()
                .expect("roots_bits")
                .iter()
                .map(|b| b.as_str().unwrap())
                .collect();
            let got: Vec<String> = roots
                .iter()
                .map(|t| format!("{:#010x}", t.to_bits()))
                .collect();
            assert_eq!(got, want, "{at} [{name}]: the exact roots");
        }
    }
    assert_eq!(seen.len(), EXACT.len(), "every exact family has cases");
}
