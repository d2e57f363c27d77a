//! Replays every committed fuzz input through the same library checks the
//! fuzz targets run: the seed corpora in `fuzz/corpus/<target>/` (built
//! from the fixtures, stiff and extreme cases included) and every crash or
//! regression input kept in `fuzz/regressions/<target>/`.

use std::fs;
use std::path::Path;

#[test]
fn every_committed_fuzz_input_passes_its_target_checks() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../fuzz");
    let mut failures = Vec::new();
    for (target, check) in rayoracle::fuzz::TARGETS {
        let mut seen = 0;
        for kind in ["corpus", "regressions"] {
            let dir = root.join(kind).join(target);
            let Ok(entries) = fs::read_dir(&dir) else {
                continue;
            };
            for entry in entries.flatten() {
                let path = entry.path();
                let bytes = fs::read(&path).expect("readable fuzz input");
                seen += 1;
                match std::panic::catch_unwind(|| check(&bytes)) {
                    Ok(Ok(())) => {}
                    Ok(Err(f)) => failures.push(format!("{}: {f}", path.display())),
                    Err(_) => failures.push(format!("{}: panicked", path.display())),
                }
            }
        }
        assert!(seen > 0, "no committed inputs for the {target} target");
    }
    assert!(
        failures.is_empty(),
        "{} fuzz inputs fail:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

/// The seed corpora are the fixtures as `fuzz_seeds` writes them: every
/// line of `fixtures/cases/*.jsonl` is the `eval_line` input
/// `fixture-<file>-<line>` byte for byte, and, where it parses, the input
/// of that name in its kind's target is its encoding. A fixture added or
/// changed without `cargo run --example fuzz_seeds` fails here.
#[test]
fn the_seed_corpora_are_the_fixtures() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("..");
    let corpus = root.join("fuzz/corpus");
    let mut files: Vec<_> = fs::read_dir(root.join("fixtures/cases"))
        .expect("fixtures/cases")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|e| e == "jsonl"))
        .collect();
    files.sort();
    let (mut stale, mut lines) = (Vec::new(), 0);
    for path in files {
        let stem = path.file_stem().unwrap_or_default().to_string_lossy();
        let text = fs::read_to_string(&path).expect("readable fixture file");
        for (i, line) in text.lines().enumerate() {
            lines += 1;
            let name = format!("fixture-{stem}-{:03}", i + 1);
            let mut want = vec![("eval_line", line.as_bytes().to_vec())];
            if let Ok(parsed) = rayoracle::case::parse_line(line) {
                let mut bytes = Vec::new();
                rayoracle::fuzz::encode_case(&parsed.case, &mut bytes);
                want.push((parsed.case.kind().as_str(), bytes));
            }
            for (target, bytes) in want {
                if fs::read(corpus.join(target).join(&name)).ok() != Some(bytes) {
                    stale.push(format!("{target}/{name}"));
                }
            }
        }
    }
    assert!(lines > 100, "only {lines} fixture lines");
    assert!(
        stale.is_empty(),
        "{} seed inputs missing or stale (run `cargo run --example fuzz_seeds`): {}",
        stale.len(),
        stale.join(", ")
    );
}
