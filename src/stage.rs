//! Which stage of a kernel decided an answer.
//!
//! Every kernel evaluates in stages, each certifying only what its error
//! bound decides and passing the rest on: a filter in f64 with a bound from
//! magnitude sums (the same arithmetic on one lane or four), then exact
//! arithmetic. The answer is the exact class and correctly rounded roots
//! whichever stage gives it; the stage only says how much work it took.
//!
//! With flush-to-zero or denormals-are-zero on, the filter's bounds do not
//! hold, so every call goes to the exact stage
//! ([`crate::num::certify::subnormals_work`]): slower, still exact.
//!
//! ```
//! use rayoracle::{Ray, stage::Stage, sphere::{Sphere, reference::intersect_staged}};
//! use glam::Vec3;
//! let s = Sphere::new(Vec3::ZERO, 1.0);
//! let (_, stage) = intersect_staged(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), &s);
//! assert_eq!(stage, Stage::Filter);
//! // An exact tangent cannot be told from a near miss in rounded arithmetic.
//! let (_, stage) = intersect_staged(&Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z), &s);
//! assert_eq!(stage, Stage::Exact);
//! ```

/// A stage of evaluation, cheapest first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Stage {
    /// f64 arithmetic with a bound from magnitude sums; SIMD in x4.
    Filter,
    /// Exact dyadic arithmetic ([`crate::exact`]).
    Exact,
}

impl Stage {
    /// Every stage, in order.
    pub const ALL: [Stage; 2] = [Stage::Filter, Stage::Exact];

    /// A short name for reports.
    ///
    /// ```
    /// assert_eq!(rayoracle::stage::Stage::Exact.name(), "exact");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Stage::Filter => "filter",
            Stage::Exact => "exact",
        }
    }
}
