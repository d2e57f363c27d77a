//! Which stage of a kernel decided an answer.
//!
//! Every kernel evaluates in stages, each certifying only what it can
//! prove and passing the rest on: a filter in f64 with a bound from
//! magnitude sums (written once for one lane or four; the plane's kernels
//! and the sphere's x4 kernels first run a variant whose longest chain of
//! dependent operations is shorter, and the full filter only for the
//! lanes it leaves: `plane::stages::filter_relative`,
//! `sphere::stages::filter_sorted`); the filter's
//! arithmetic checked to be exact, operation by operation (which settles
//! the exact zeros of small-integer and dyadic data); a tight stage in a
//! better-conditioned form (the sphere's discriminant, whose error grows
//! with `R·|f|` rather than `|f|²`; the plane's `d·n`, summed exactly;
//! the quadric's double plane as the square of a linear form, and its α
//! summed exactly where it nearly cancels);
//! double-word arithmetic, exact where no low word
//! rounded (which settles most other exact zeros); then exact arithmetic
//! on integers. The answer is the exact class and correctly
//! rounded roots whichever stage gives it; the stage only says how much
//! work it took.
//!
//! With flush-to-zero or denormals-are-zero on, the filter's bounds do not
//! hold, so every call goes to the exact stage
//! ([`crate::num::certify::subnormals_work`]): slower, still exact.
//!
//! ```
//! # #[cfg(feature = "sphere")] {
//! use rayoracle::{Ray, stage::Stage, sphere::{Sphere, reference::intersect_staged}};
//! use glam::Vec3;
//! let s = Sphere::new(Vec3::ZERO, 1.0);
//! let (_, stage) = intersect_staged(&Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), &s);
//! assert_eq!(stage, Stage::Filter);
//! // An exact tangent cannot be told from a near miss by a bound; small
//! // integers make every operation exact, which proves it.
//! let (_, stage) = intersect_staged(&Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z), &s);
//! assert_eq!(stage, Stage::Tracked);
//! // A tangent whose f64 arithmetic rounds: double words are exact.
//! let big = Sphere::new(Vec3::ZERO, 3.0);
//! let r = Ray::new(Vec3::new(0.0, 3.0, -1e30), Vec3::new(0.0, 0.0, 0.1));
//! assert_eq!(intersect_staged(&r, &big).1, Stage::DoubleWord);
//! # }
//! ```

/// A stage of evaluation, cheapest first.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Stage {
    /// f64 arithmetic with a bound from magnitude sums; SIMD in x4.
    Filter,
    /// f64 arithmetic in which no operation rounded
    /// ([`crate::num::tracked`]).
    Tracked,
    /// f64 arithmetic in a better-conditioned form with a tighter bound
    /// (the sphere's discriminant after Ray Tracing Gems ch. 7, the
    /// plane's `d·n` as an exact sum, the quadric's coefficients in
    /// double words with running bounds); scalar.
    Tight,
    /// Double-word arithmetic, exact where no low word rounded, with a
    /// bound otherwise ([`crate::num::dd`]).
    DoubleWord,
    /// Exact dyadic arithmetic ([`crate::exact`]).
    Exact,
}

impl Stage {
    /// Every stage, in order.
    pub const ALL: [Stage; 5] = [
        Stage::Filter,
        Stage::Tracked,
        Stage::Tight,
        Stage::DoubleWord,
        Stage::Exact,
    ];

    /// A short name for reports.
    ///
    /// ```
    /// assert_eq!(rayoracle::stage::Stage::Exact.name(), "exact");
    /// assert_eq!(rayoracle::stage::Stage::DoubleWord.name(), "dd");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            Stage::Filter => "filter",
            Stage::Tight => "tight",
            Stage::Tracked => "tracked",
            Stage::DoubleWord => "dd",
            Stage::Exact => "exact",
        }
    }
}
