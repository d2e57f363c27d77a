#![no_main]
//! The `camera` target: a thin wrapper; the checks are `rayoracle::fuzz::camera`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(failure) = rayoracle::fuzz::camera(data) {
        panic!("{failure}");
    }
});
