#![no_main]
//! The `plane` target: a thin wrapper; the checks are `rayoracle::fuzz::plane`.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(failure) = rayoracle::fuzz::plane(data) {
        panic!("{failure}");
    }
});
