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
pub mod x4_column;

pub use ray::Ray;
