//! The camera's judge: construction, origin and each direction component
//! against the oracle's.

use super::Declared;
use crate::Ray;
use crate::camera::{CameraError, CameraParams, component_scale};
use crate::ulp::ulp_of;

/// One camera direction component compared with the oracle's.
///
/// ```
/// use rayoracle::check::ComponentCheck;
/// let c = ComponentCheck { axis: 0, exact: 1.0, got: 1.0, scale: 1.0, err_ulps: 0.0, bound: 4.0 };
/// assert!(c.ok());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ComponentCheck {
    /// 0, 1 or 2 for x, y, z.
    pub axis: usize,
    /// The oracle's component (rounded to f32).
    pub exact: f32,
    /// The candidate's component.
    pub got: f32,
    /// `Sᵢ`, the size of the terms the component is made of.
    pub scale: f64,
    /// `|got − exact| / ulp_of(Sᵢ)`; where the bits differ but the values
    /// do not (`−0` against `+0`), the least positive f64; NaN for a NaN.
    pub err_ulps: f64,
    /// The allowance in ulps of `Sᵢ` ([`Declared::camera_ulps`]).
    pub bound: f64,
}

impl ComponentCheck {
    /// Whether the component is within its bound (NaN error is not).
    ///
    /// ```
    /// use rayoracle::check::ComponentCheck;
    /// let c = ComponentCheck { axis: 2, exact: 1.0, got: f32::NAN, scale: 1.0, err_ulps: f64::NAN, bound: 4.0 };
    /// assert!(!c.ok());
    /// ```
    pub fn ok(&self) -> bool {
        self.err_ulps <= self.bound
    }
}

/// Why a camera's answer fails.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum CameraFault {
    /// The oracle refuses the parameters and the camera does not.
    NotRefused,
    /// The camera refuses valid parameters.
    Refused,
    /// Both refuse, with different errors.
    OtherError,
    /// The ray's origin is not the camera position.
    Origin,
    /// A direction component is outside its bound.
    Component(ComponentCheck),
}

/// What [`judge_camera`] found: the components compared (up to the first
/// failing one) and the fault, if any.
#[derive(Clone, Debug, PartialEq)]
pub struct CameraJudgement {
    /// The direction components compared.
    pub components: Vec<ComponentCheck>,
    /// Why the answer fails; `None` if it passes.
    pub fault: Option<CameraFault>,
}

/// Whether two camera errors are the same (NaN angles compare by bits).
fn same_error(a: &CameraError, b: &CameraError) -> bool {
    match (a, b) {
        (CameraError::AngleOutOfRange(x), CameraError::AngleOutOfRange(y)) => {
            x.to_bits() == y.to_bits()
        }
        _ => a == b,
    }
}

/// Judges a camera's answer for `pixel` (a ray, or a refusal with the
/// error if the camera names one) against the oracle's, `exact`
/// ([`camera::exact::ray`](crate::camera::exact::ray)).
///
/// ```
/// use rayoracle::check::rules::{CameraFault, Declared, Semantics, judge_camera};
/// use rayoracle::camera::{CameraParams, exact};
/// use glam::Vec3;
/// let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [64, 48]);
/// let d = Declared::correctly_rounded(Semantics::WholeLine);
/// let exact = exact::ray(&p, 5, 7);
/// let mut ray = p.build().unwrap().ray(5, 7);
/// assert_eq!(judge_camera(&d, &p, [5, 7], &exact, &Ok(ray)).fault, None);
/// ray.dir.x = f32::from_bits(ray.dir.x.to_bits() + 1);
/// let j = judge_camera(&d, &p, [5, 7], &exact, &Ok(ray));
/// assert!(matches!(j.fault, Some(CameraFault::Component(c)) if c.axis == 0));
/// ```
pub fn judge_camera(
    d: &Declared,
    p: &CameraParams,
    pixel: [u32; 2],
    exact: &Result<Ray, CameraError>,
    got: &Result<Ray, Option<CameraError>>,
) -> CameraJudgement {
    let mut components = Vec::new();
    let fault = match (exact, got) {
        (Err(_), Err(None)) => None,
        (Err(e), Err(Some(g))) if same_error(e, g) => None,
        (Err(_), Err(Some(_))) => Some(CameraFault::OtherError),
        (Err(_), Ok(_)) => Some(CameraFault::NotRefused),
        (Ok(_), Err(_)) => Some(CameraFault::Refused),
        (Ok(x), Ok(g)) => {
            let bits = |v: glam::Vec3| v.to_array().map(f32::to_bits);
            // The oracle builds exactly when the reference does.
            match p.build() {
                _ if bits(g.origin) != bits(x.origin) => Some(CameraFault::Origin),
                Err(_) => None,
                Ok(cam) => {
                    let scale = component_scale(&cam, pixel[0], pixel[1]);
                    (0..3).find_map(|axis| {
                        let (e, g) = (x.dir[axis], g.dir[axis]);
                        let err_ulps = if e.to_bits() == g.to_bits() {
                            0.0
                        } else {
                            let err = (f64::from(g) - f64::from(e)).abs() / ulp_of(scale[axis]);
                            if err.is_nan() {
                                err
                            } else {
                                err.max(f64::MIN_POSITIVE)
                            }
                        };
                        let c = ComponentCheck {
                            axis,
                            exact: e,
                            got: g,
                            scale: scale[axis],
                            err_ulps,
                            bound: d.camera_ulps(),
                        };
                        components.push(c);
                        (!c.ok()).then_some(CameraFault::Component(c))
                    })
                }
            }
        }
    };
    CameraJudgement { components, fault }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::rules::Semantics;
    use glam::Vec3;

    /// A NaN camera component is out of any bound, and a +0 for the
    /// centre pixel's −0 only out of a zero one.
    #[test]
    fn a_nan_camera_component_fails_any_bound() {
        let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [3, 3]);
        let exact = crate::camera::exact::ray(&p, 1, 1);
        assert_eq!(exact.unwrap().dir.x.to_bits(), (-0f32).to_bits());
        let with_x = |x: f32| {
            let mut r = exact.unwrap();
            r.dir.x = x;
            Ok(r)
        };
        let f32 = Declared::f32(Semantics::WholeLine);
        let cr = Declared::correctly_rounded(Semantics::WholeLine);
        let fault = |d: &Declared, x: f32| judge_camera(d, &p, [1, 1], &exact, &with_x(x)).fault;
        assert!(
            matches!(fault(&f32, f32::NAN), Some(CameraFault::Component(c)) if c.err_ulps.is_nan())
        );
        assert_eq!(fault(&f32, 0.0), None);
        assert!(
            matches!(fault(&cr, 0.0), Some(CameraFault::Component(c)) if c.err_ulps == f64::MIN_POSITIVE)
        );
        let moved = Ok(Ray::new(Vec3::X, exact.unwrap().dir));
        assert_eq!(
            judge_camera(&f32, &p, [1, 1], &exact, &moved).fault,
            Some(CameraFault::Origin)
        );
    }
}
