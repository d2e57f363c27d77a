#![no_main]
//! The `eval_line` target: a thin wrapper; the checks are `rayoracle::fuzz::eval_line`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(failure) = rayoracle::fuzz::eval_line(data) {
        panic!("{failure}");
    }
});
