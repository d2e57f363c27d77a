//! Every minimal case in docs/crate-surveys.md is an `eval` line that
//! rayoracle reads, and the oracle's answer is the one the write-up
//! expects.

use rayoracle::case::{Case, parse_line};
use rayoracle::hit::Intersection;
use rayoracle::plane;
use rayoracle::quadric;
use rayoracle::sphere;

/// The lines of every ```jsonl block.
fn doc_cases() -> Vec<String> {
    let doc = include_str!("../../../docs/crate-surveys.md");
    let mut inside = false;
    let mut out = Vec::new();
    for line in doc.lines().map(str::trim) {
        if line.starts_with("```") {
            inside = line == "```jsonl";
        } else if inside {
            out.push(line.to_string());
        }
    }
    out
}

/// The exact roots on the whole line, `None` for every `t`.
fn whole(h: impl Intersection) -> Option<Vec<f32>> {
    (!h.is_everywhere()).then(|| h.roots().as_slice().to_vec())
}

fn exact(c: &Case) -> Option<Vec<f32>> {
    match c {
        Case::Plane(r, p) => whole(plane::exact::intersect(r, p).ok()?),
        Case::Sphere(r, s) => whole(sphere::exact::intersect(r, s).ok()?),
        Case::Quadric(r, q) => whole(quadric::exact::intersect(r, q).ok()?),
        Case::Camera(..) => None,
    }
}

#[test]
fn every_minimal_case_parses_and_has_the_expected_exact_answer() {
    let expected: [&[f32]; 11] = [
        &[1e-8],
        &[1e4],
        &[8.507059e37, 2.5521178e38],
        &[6.0],
        &[-1.0, 1.0],
        &[-1.5, 0.5],
        &[],
        &[122286.305, 122288.164],
        &[],
        &[],
        &[85171.64, 85172.94],
    ];
    let lines = doc_cases();
    assert_eq!(lines.len(), expected.len(), "{lines:#?}");
    for (line, want) in lines.iter().zip(expected) {
        let c = parse_line(line)
            .unwrap_or_else(|e| panic!("{line}: {e}"))
            .case;
        assert_eq!(exact(&c).as_deref(), Some(want), "{line}");
    }
}
