//! Numerical building blocks.
//!
//! The plane, sphere, quadric and camera kernels evaluate in f64 with a proven error
//! bound ([`real`], [`certify`]), then in f64 checked to be exact
//! operation by operation ([`tracked`]): the [`Real`] trait runs the same
//! expression on one lane (`f64`) or four ([`real::F64x4`]; on x86-64 also
//! one AVX register, chosen at run time, see `avx`), and every
//! operation is one correctly rounded IEEE-754 operation (`+`, `−`, `×`,
//! `÷`, `√`). Nothing here calls `recip` or `recip_sqrt` (approximations),
//! and rustc never contracts `a * b + c` into an FMA, so every build
//! computes the same bits; and since what a kernel returns is correctly
//! rounded, scalar and SIMD agree by construction. The one `mul_add`,
//! [`dd::Fused`], computes a TwoProduct error that is exact (so the same
//! bits as [`dd::Dekker`]'s plain arithmetic), and runs only in code
//! compiled for FMA.
//!
//! The render normals are plain `f32` (and `wide::f32x4`), written once
//! over [`Lane`]:
//!
//! * [`lane`]: the [`Lane`] trait and its two implementations.
//! * [`scale`]: exact power-of-two prescaling for range.

pub mod lane;
pub mod scale;

pub use lane::Lane;
pub use real::Real;
#[cfg(target_arch = "x86_64")]
pub mod avx;
#[cfg(all(
    target_arch = "x86_64",
    any(feature = "plane", feature = "sphere", feature = "quadric")
))]
pub mod avx512;
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
pub(crate) mod batch;
pub mod certify;
#[cfg(feature = "plane")]
pub(crate) mod cold;
pub mod dd;
#[cfg(all(test, any(feature = "plane", feature = "sphere", feature = "quadric")))]
pub(crate) mod paths;
pub mod real;
pub mod tracked;

/// Marsaglia's xorshift64 from `seed`: the unit tests' values, the same on
/// every run.
#[cfg(test)]
pub(crate) fn xorshift(mut seed: u64) -> impl FnMut() -> u64 {
    move || {
        seed ^= seed << 13;
        seed ^= seed >> 7;
        seed ^= seed << 17;
        seed
    }
}
