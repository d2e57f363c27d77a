#![no_main]
//! The `sphere` target: a thin wrapper; the checks are `rayoracle::fuzz::sphere`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(failure) = rayoracle::fuzz::sphere(data) {
        panic!("{failure}");
    }
});
