//! What each fuzz target's checks cost per input, without the fuzzer's
//! coverage instrumentation: every committed corpus input of every target,
//! repeated for a second. `cargo run --release --example fuzz_check_cost`.
//! (The fuzzer's own exec/s, instrumentation included, is what
//! `fuzz/campaign` and the README report.)

use std::time::Instant;
fn main() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fuzz/corpus");
    for (t, check) in rayoracle::fuzz::TARGETS {
        let inputs: Vec<Vec<u8>> = std::fs::read_dir(dir.join(t))
            .unwrap()
            .flatten()
            .map(|e| std::fs::read(e.path()).unwrap())
            .collect();
        let start = Instant::now();
        let mut n = 0;
        while start.elapsed().as_secs_f64() < 1.0 {
            for i in &inputs {
                let _ = check(i);
                n += 1;
            }
        }
        println!(
            "{t}: {:.1} µs/input over {} inputs",
            start.elapsed().as_secs_f64() * 1e6 / n as f64,
            inputs.len()
        );
    }
}
