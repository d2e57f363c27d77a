//! Writes the seed corpora `fuzz/corpus/<target>/` from the case fixtures:
//! every line of `fixtures/cases/*.jsonl` (the stiff and extreme families
//! included) becomes one input of its kernel's target, with raw-bit floats
//! so it decodes exactly, and every raw line (plus a few malformed ones)
//! becomes an `eval_line` input. Run `cargo run --example fuzz_seeds` after
//! changing the fixtures; the files are committed, and `cargo test` replays
//! them (`fuzz-replay/tests/replay.rs`), which also checks that they
//! match the fixtures.

use rayoracle::case::parse_line;
use std::fs;
use std::path::Path;

fn main() -> std::io::Result<()> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let mut files: Vec<_> = fs::read_dir(root.join("fixtures/cases"))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "jsonl"))
        .collect();
    files.sort();
    let mut written = 0;
    for path in files {
        let stem = path
            .file_stem()
            .unwrap_or_default()
            .to_string_lossy()
            .to_string();
        for (i, line) in fs::read_to_string(&path)?.lines().enumerate() {
            let name = format!("fixture-{stem}-{:03}", i + 1);
            write(root, "eval_line", &name, line.as_bytes())?;
            written += 1;
            let Ok(parsed) = parse_line(line) else {
                continue;
            };
            // The fuzz targets are named after the kinds.
            let target = parsed.case.kind().as_str();
            let mut bytes = Vec::new();
            rayoracle::fuzz::encode_case(&parsed.case, &mut bytes);
            write(root, target, &name, &bytes)?;
            written += 1;
        }
    }
    for (i, bad) in [
        r#"{"kind":"sphere","origin":[0,0],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#,
        r#"{"kind":"quadric","origin":[0,0,0],"dir":[0,0,1],"coeffs":[1,1,1]}"#,
        r#"{"kind":"camera","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[4,4],"pixel":[9,0]}"#,
        r#"{"kind":"plane","origin":["0x7f800000",0,0],"dir":[1e39,0,-1e-50],"point":[0,0,0],"normal":["nan",1,0]}"#,
        r#"{"kind":"#,
        "[1,2,3]",
    ]
    .iter()
    .enumerate()
    {
        write(root, "eval_line", &format!("malformed-{i}"), bad.as_bytes())?;
        written += 1;
    }
    println!("wrote {written} seed inputs under fuzz/corpus/");
    Ok(())
}

fn write(root: &Path, target: &str, name: &str, bytes: &[u8]) -> std::io::Result<()> {
    let dir = root.join("fuzz/corpus").join(target);
    fs::create_dir_all(&dir)?;
    fs::write(dir.join(name), bytes)
}
