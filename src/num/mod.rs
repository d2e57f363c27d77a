//! Numerical building blocks.
//!
//! The plane, sphere and quadric kernels evaluate in f64 with a proven error
//! bound ([`real`], [`certify`]), then in f64 checked to be exact
//! operation by operation ([`tracked`]): the [`Real`] trait runs the same
//! expression on one lane (`f64`) or four ([`real::F64x4`]), and every
//! operation is one correctly rounded IEEE-754 operation (`+`, `−`, `×`,
//! `÷`, `√`). Nothing here calls `mul_add` (fused on one build, unfused on
//! another), `recip` or `recip_sqrt` (approximations), and rustc never
//! contracts `a * b + c` into an FMA, so every build computes the same
//! bits; and since what a kernel returns is correctly rounded, scalar and
//! SIMD agree by construction.
//!
//! The camera still evaluates in double-word f32 arithmetic, written once
//! over [`Lane`] (implemented for `f32` and `wide::f32x4`):
//!
//! * [`lane`]: the [`Lane`] trait and its two implementations.
//! * [`eft`]: error-free transformations (Knuth's TwoSum, Dekker's
//!   FastTwoSum, Veltkamp's split and Dekker's TwoProduct without FMA).
//! * [`scale`]: exact power-of-two prescaling for range.
//! * [`ff`]: double-word ("float-float") arithmetic built on them, after
//!   Joldes, Muller & Popescu, *Tight and rigorous error bounds for basic
//!   building blocks of double-word arithmetic* (ACM TOMS 44(2), 2017).

pub mod eft;
pub mod ff;
pub mod lane;
pub mod scale;

pub use ff::Ff;
pub use lane::Lane;
pub use real::Real;
pub mod certify;
pub mod dd;
pub mod real;
pub mod tracked;
