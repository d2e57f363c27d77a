#![no_main]
//! The `scene` target: any bytes as a scene file. A thin wrapper; the checks
//! are `rayoracle::scene::fuzz::check` (never a panic; located errors;
//! accepted scenes render to the same bits on both paths).

use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    if let Err(failure) = rayoracle::scene::fuzz::check(data) {
        panic!("{failure}");
    }
});
