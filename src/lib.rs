//! A reference test oracle and fuzz harness for ray–primitive intersection:
//! the perspective camera, the plane, the sphere and the general quadric.
//!
//! Every kernel here returns the **exact class** (a hit, a miss, a tangent,
//! a ray in the plane…) and **every root correctly rounded** to `f32`, on
//! every finite input. They evaluate in f64 with an error bound derived
//! beside each kernel and return only what the bound certifies; what it
//! cannot decide goes to later stages, the last of them exact arithmetic
//! on the dyadic values of the inputs ([`stage`]). Correct rounding is
//! unique, so the scalar kernels (`reference`) and the four-lane ones
//! (`x4`) give the same bits on every build.
//!
//! ```
//! # #[cfg(feature = "sphere")] {
//! use rayoracle::{Ray, sphere::{Sphere, SphereHit, reference, x4}, ray4::Ray4};
//! use glam::Vec3;
//! let s = Sphere::new(Vec3::ZERO, 1.0);
//! let r = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
//! assert_eq!(reference::intersect(&r, &s), SphereHit::Two(4.0, 6.0));
//! let h = x4::intersect(&Ray4::splat(r), &x4::Sphere4::splat(&s));
//! assert_eq!(h.lanes(), [SphereHit::Two(4.0, 6.0); 4]);
//! # }
//! ```
//!
//! # Three ways to use it
//!
//! * **Gate your own kernel** in `cargo test` ([`check::gate`]): declare
//!   what it promises, and every case family (hand-written, stiff,
//!   random) is judged against the exact oracle; failures come back
//!   shrunk, as `eval` lines.
//! * **Fuzz** with `cargo fuzz` ([`fuzz`], [`fuzz::gate`]): byte
//!   decoders and checks for fuzz targets, rayoracle's own and yours.
//! * **Review rendered frames** ([`render`], [`scene`]): depth, normal and
//!   id channels of a scene, the same bytes from either path, for
//!   snapshot tests.
//!
//! # Map
//!
//! | module | what |
//! |---|---|
//! | [`plane`], [`sphere`], [`quadric`], [`camera`] | one per primitive: types, the derivation, the filter and its bound, the kernels, the exact solution |
//! | [`primitive`] | the trait the plane, sphere and quadric share, which the harnesses are written against |
//! | [`exact`] | the exact oracle: dyadic rationals on fixed-width integers, big integers beyond |
//! | [`num`] | the lane types, certified rounding, tracked and double-word arithmetic |
//! | [`check`] | the judge: one rule set ([`check::rules`]) that holds rayoracle's kernels to the oracle's bits and outside kernels, through the gate, to what they declare |
//! | [`case`], [`eval`] | the `eval` line format (one JSON case a line) and its evaluation |
//! | [`fixtures`] | the cases, stiff catalogue and default scene, compiled in |
//! | [`report`] | error against run time, per kernel, variant and stiff family |
//!
//! # Cargo features
//!
//! `plane`, `sphere` and `quadric` (all default) each compile one
//! primitive in; a crate that never uses a kind can leave it out.

// `!(x >= 0.0)` is how these kernels say "negative or NaN"; rewriting it as
// `x < 0.0` would silently change what NaN inputs do on one path only.
#![allow(clippy::neg_cmp_op_on_partial_ord)]

pub mod camera;
pub mod case;
pub mod check;
pub mod eval;
pub mod exact;
pub mod fixtures;
pub mod fuzz;
pub mod hit;
pub mod num;
#[cfg(feature = "plane")]
pub mod plane;
pub mod primitive;
#[cfg(feature = "quadric")]
pub mod quadric;
pub mod ray;
pub mod ray4;
pub mod render;
#[cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
pub mod report;
pub mod scene;
#[cfg(feature = "sphere")]
pub mod sphere;
pub mod stage;
pub mod ulp;

pub use ray::Ray;
