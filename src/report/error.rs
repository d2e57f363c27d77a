//! One case's error against the exact oracle, in bits.

use crate::case::Case;
use crate::eval::{Comparison, Outcome, compare};
use crate::ulp::{bits, ulp_of};

/// How one case came out.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CaseError {
    /// The oracle has no answer (a non-finite intermediate), or neither
    /// has: nothing to compare.
    NotCompared,
    /// The classes differ.
    Mismatch,
    /// Bits of error `log₂(ulps + 1)` of the worst root or component.
    Bits(f64),
}

/// The error of `got` against `exact` for `case`.
///
/// Roots are measured in ulps of the correctly rounded root. A camera ray
/// is measured per component in ulps of `Sᵢ = |fᵢ| + |u xᵢ| + |v yᵢ|`
/// ([`crate::camera::component_scale`]), the scale the gate's allowance
/// for other cameras is stated in: the terms of a component may cancel,
/// and an error relative to the cancelled result would blame the kernel
/// for the cancellation.
///
/// ```
/// use rayoracle::case::parse_line;
/// use rayoracle::eval::{exact, Outcome};
/// use rayoracle::report::{CaseError, case_error};
/// use rayoracle::sphere::SphereHit;
/// let c = parse_line(r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#).unwrap().case;
/// let e = exact(&c);
/// assert_eq!(case_error(&c, &e, &Outcome::hit(&SphereHit::Two(4.0, 6.0))), CaseError::Bits(0.0));
/// assert_eq!(case_error(&c, &e, &Outcome::hit(&SphereHit::Two(4.0, 6.0000005))), CaseError::Bits(1.0));
/// assert_eq!(case_error(&c, &e, &Outcome::hit(&SphereHit::None)), CaseError::Mismatch);
/// ```
pub fn case_error(case: &Case, exact: &Outcome, got: &Outcome) -> CaseError {
    if let (Case::Camera(p, [px, py]), Outcome::Ray(e), Outcome::Ray(g)) = (case, exact, got) {
        let Ok(cam) = p.build() else {
            return CaseError::NotCompared;
        };
        let scale = crate::camera::component_scale(&cam, *px, *py);
        let worst = (0..3)
            .map(|i| {
                let diff = (f64::from(g.dir[i]) - f64::from(e.dir[i])).abs();
                let u = diff / ulp_of(scale[i]);
                if u.is_nan() {
                    u64::MAX
                } else {
                    u.ceil().min(u64::MAX as f64) as u64
                }
            })
            .max()
            .unwrap_or(0);
        return CaseError::Bits(bits(worst));
    }
    match compare(exact, got) {
        Comparison::NotCompared => CaseError::NotCompared,
        Comparison::ClassMismatch => CaseError::Mismatch,
        Comparison::Ulps(u) => CaseError::Bits(bits(u.into_iter().max().unwrap_or(0))),
    }
}
