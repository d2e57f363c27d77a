#![no_main]
//! The `quadric` target: a thin wrapper; the checks are `rayoracle::fuzz::quadric`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(failure) = rayoracle::fuzz::quadric(data) {
        panic!("{failure}");
    }
});
