pub mod camera;
pub mod case;
pub mod check;
pub mod eval;
pub mod exact;
pub mod hit;
pub mod num;
pub mod plane;
pub mod quadric;
pub mod ray;
pub mod sphere;
pub mod ulp;

pub use ray::Ray;
