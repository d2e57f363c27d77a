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
