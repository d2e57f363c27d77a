//! The exact oracle's arithmetic: every finite `f32` is a dyadic rational
//! `m·2^e`, and sums, differences and products of dyadics are dyadic, so the
//! polynomial quantities of every primitive (`d·n`, the discriminant, α, β,
//! γ, …) are computed here *exactly*: on `i128` or 256-bit mantissas on
//! the stack while they fit, on big integers (`dashu-int`) beyond that.
//! The plane's linear equation and the quadratics of the sphere and the
//! quadric are also solved on floating-point [`expansion`]s, exact sums of
//! a few `f64`s, which hold values of widely spread exponents in a few
//! words.
//!
//! A root of a quadratic is in general irrational, so it is never formed.
//! Instead [`round`] finds its correctly rounded `f32` (ties to even) by
//! asking, for a handful of dyadic points `m` (neighbouring floats and the
//! midpoints between them), on which side of `m` the root lies; for a root of
//! a polynomial that is one exact sign evaluation ([`quadratic`]).

pub mod dyadic;
pub mod expansion;
pub(crate) mod memo;
pub mod quadratic;
pub mod round;
mod wide;

pub use dyadic::Dyadic;

pub use quadratic::{ExactQuadratic, Quadratic};
pub use round::round_to_f32;

/// The oracle cannot judge an input that is not a real number.
///
/// ```
/// use rayoracle::exact::{Dyadic, NonFinite};
/// assert_eq!(Dyadic::try_from_f32(f32::NAN), Err(NonFinite));
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct NonFinite;

impl core::fmt::Display for NonFinite {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str("an input is NaN or infinite, so it has no exact value")
    }
}

impl std::error::Error for NonFinite {}
