#![no_main]
//! The `scene` target: any bytes as a scene file. A thin wrapper; the checks
//! are `rayoracle::fuzz::scene::check` (never a panic; located errors;
//! accepted scenes render to the same bits on both paths).

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(failure) = rayoracle::fuzz::scene::check(data) {
        panic!("{failure}");
    }
});
