#![no_main]
//! The `plane` target: a thin wrapper; the checks are
//! `rayoracle::fuzz::primitive`, generic over the primitive.

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(failure) = rayoracle::fuzz::primitive::<rayoracle::plane::Plane>(data) {
        panic!("{failure}");
    }
});
