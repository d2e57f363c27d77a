//! Numerical building blocks shared, operation for operation, by the scalar
//! reference kernels and the four-lane SIMD kernels.
//!
//! Bit-identity between the two paths is by construction: every helper here is
//! generic over [`Lane`] (implemented for `f32` and `wide::f32x4`) and uses only
//! IEEE-754 operations that are correctly rounded on both paths: `+`, `−`, `×`,
//! `÷` and `√`. Nothing here calls `mul_add` (fused on one build, unfused on
//! another), `recip` or `recip_sqrt` (approximations), and rustc never contracts
//! `a * b + c` into an FMA, so a scalar and a SIMD evaluation of the same
//! expression tree give the same bits whatever target features are enabled.
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
pub mod certify;
pub mod real;
