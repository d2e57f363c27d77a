//! The rules every answer is judged by, in one place: what the exact answer
//! of a case is ([`Exact`]), what a kernel declares it promises
//! ([`Declared`]), and one [`judge`] that compares the two. rayoracle's own
//! kernels are held by [`check`](super) to the strictest declaration,
//! [`Declared::correctly_rounded`]; the gate (`check::gate`) holds an
//! outside kernel to the declaration its author chooses. Both call the same
//! [`judge`] (and [`judge_camera`]), so a rule changed here changes for
//! both.
//!
//! # The exact answer
//!
//! For a plane, sphere or quadric case, [`Exact`] holds the exact roots
//! correctly rounded to `f32` (ascending; or every `t`), each root's
//! condition number κ, the exact classification margin (`d·n`, `aΔ` or
//! `β² − 4αγ`) and the unit band it is measured against (`2⁻⁴⁴` of the
//! terms it is made of), the quadric's exact α against its own unit band,
//! and whether every input is an integer of magnitude at most 16. Where an
//! input is NaN or infinite there is no exact answer, and nothing is
//! judged.
//!
//! # The rules
//!
//! * **Roots.** A root of condition κ may be off by
//!   [`Declared::allowed_ulps`]`(κ) = 2^bits − 1 + κ · precision · 2²⁴`
//!   ulps from the correctly rounded exact root (an infinite κ allows
//!   anything, unless the precision is 0). Where nothing is allowed the
//!   root must be the exact root's bits: `−0` is not `+0`. A NaN root
//!   always fails, and whole-line roots must be ascending, whatever the
//!   class.
//! * **Double roots.** A tangent's root `t* = −β/2α` is a quotient, so its
//!   κ is finite: the relative condition of β plus that of α (for a sphere
//!   `Σ(|oᵢdᵢ| + |Cᵢdᵢ| + |dᵢ(fᵢ + 2t*dᵢ)|)/(a|t*|)`, for a quadric
//!   `3(Σ|β terms|/|β| + Σ|α terms|/|α|)`); only `t* = 0` has an infinite
//!   one.
//! * **Class.** The number of roots must be the exact one, unless the
//!   exact margin is within the declared band (`band_scale` times the unit
//!   band). A band of 0 forgives nothing, and neither does a margin whose
//!   terms are all 0 (every kernel computes it exactly). When every input
//!   is an integer of magnitude at most 16, an exactly zero margin (a ray
//!   in the plane, an exact tangent) is never in the band, since any
//!   kernel computes its margin exactly there. Where the class differs
//!   within the band, each root given must lie within `√(2(|margin| +
//!   band))·s` of the nearest double root `t*` (or within its allowed
//!   ulps), `s` being how far a margin error of 1 moves the roots
//!   (`a^(−3/2)` for a sphere, `1/(2|α|)` for a quadric). A quadric with
//!   α = β = 0 has no double root: there each root `t` must solve some α,
//!   β and γ within their bands (`(|α band| t² + |β band| |t| + γ band) ≥
//!   |γ|`), and so must a root of a plane with `d·n = 0` (`(d·n band |t|
//!   + offset band) ≥ |offset|`).
//! * **Every `t`.** "Every t" against another class is judged by what must
//!   vanish for every `t` to solve it, not by the margin: `d·n` and the
//!   offset `(a − o)·n` of a plane (unit band `2⁻⁴⁴Σ(|aᵢ| + |oᵢ|)|nᵢ|`),
//!   α, β and γ of a quadric (each `2⁻⁴⁴` of its terms). It is forgiven
//!   only where each of them may be computed as 0 (is 0, or within its
//!   band, off small integers), or, against an exact "every t", where one
//!   of them may be computed as nonzero. A sphere is never every `t`.
//! * **Tangents and small α.** With a band, a single exact root may come
//!   as the same root twice. A quadric whose exact α is within the band
//!   of its terms (and not on small integers) may be answered as linear
//!   (one of the exact two roots) or, where α = 0, as a quadratic (one of
//!   the two roots the exact one).
//! * **Roots in absolute terms.** A root's allowance is also taken in
//!   absolute terms, `allowed · ulp(root)` ([`Exact::reach`]), where the
//!   error is absolute: where that interval stays clear of the double root
//!   (or, for a linear root, where its denominator is computed to better
//!   than ½). A root near 0 from a cancelling `γ` (an origin near a huge
//!   sphere's surface) is then judged by its terms' scale, and may cross 0,
//!   instead of by counting the fine floats near 0.
//! * **Nearest hit.** In [`Semantics::NearestPositive`] the answer is the
//!   nearest exact root `t > 0`; in [`Semantics::Range`] the nearest with
//!   `t_min < t < t_max`. It is judged by that root's κ. A root whose
//!   absolute reach crosses `t_min` or `t_max` may be taken as a hit or
//!   not, so the answer may be any root up to the first one surely in the
//!   range (each by its own κ), or none where every root may be outside.
//!   A hit outside the range fails. A ray lying on the surface has no
//!   nearest hit, so any answer passes; a hit or a miss at `|t| ≤ 10⁻³⁰`,
//!   or within the band, may go either way (a hit: the nearer of two roots
//!   within the band's reach of the double root, `t ≤ t*`). A hit at `|t|
//!   ≤ 10⁻³⁰` is forgiven only where some exact root may be there (within
//!   its reach), and not where every input is a small integer
//!   ([`Exact::small_integers`]): every root is then 0 exactly or far from
//!   it, so a hit at 0 is `t ≥ 0`.
//! * **Solid.** In [`Semantics::Solid`] the answer is `t = 0` where the
//!   surface's function at the origin ([`Exact::inside`]) is `≤ 0`, else
//!   the nearest hit `t > 0`. Where that value is within its band, both
//!   pass.
//! * **Hit points.** [`Answer::Point`] is judged as the nearest hit, each
//!   component against the exact root's point within the root's absolute
//!   allowance times `|dᵢ|`, plus `½ ulp(t)·|dᵢ|` (the exact root rounded to
//!   f32), plus `2^bits` ulps of `|oᵢ| + |t dᵢ|`.
//! * **Preconditions** ([`Declared::skips`]). A case that violates one is
//!   not judged; the gate counts it by the precondition's name.
//! * **The quadric's band and κ** are measured about the ray's double root
//!   `p* = o + t*d` as well as at the origin, and the lesser counts: the
//!   terms of `F(p*)`, of `∇F(p*)·d` and the way from `o` to `p*`, as a
//!   careful kernel sees them. A far sphere written as a quadric is then
//!   judged about as strictly as the sphere.
//! * **Camera** ([`judge_camera`]). Construction must fail exactly when the
//!   oracle's does (with the same error, where the kernel names one). The
//!   origin must be the camera position, bit for bit, and each direction
//!   component within [`Declared::camera_ulps`] ulps of `Sᵢ`
//!   ([`component_scale`](crate::camera::component_scale)) of the oracle's.
//!
//! ```
//! # #[cfg(feature = "sphere")] {
//! use rayoracle::check::rules::{self, Answer, Declared, Semantics};
//! use rayoracle::{Ray, sphere::Sphere};
//! use glam::Vec3;
//! let (ray, s) = (Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), Sphere::new(Vec3::ZERO, 1.0));
//! let (_, exact) = rules::sphere(&ray, &s).unwrap();
//! let one_off = Answer::Roots(vec![4.0, 6.0 + 4.0 * f32::EPSILON]);
//! assert!(rules::judge(&Declared::f32(Semantics::WholeLine), &exact, &one_off).passed());
//! assert!(!rules::judge(&Declared::correctly_rounded(Semantics::WholeLine), &exact, &one_off).passed());
//! # }
//! ```

use crate::hit::Intersection;
use glam::Vec3;
use std::fmt;

mod camera;
mod exact;
mod judge;
mod preconditions;
mod semantics;

pub use camera::{CameraFault, CameraJudgement, ComponentCheck, judge_camera};
pub use exact::Exact;
#[cfg(feature = "quadric")]
pub use exact::quadric;
#[cfg(feature = "quadric")]
pub(crate) use exact::quadric_given;
#[cfg(feature = "sphere")]
pub use exact::sphere;
#[cfg(feature = "sphere")]
pub(crate) use exact::sphere_given;
#[cfg(feature = "plane")]
pub use exact::{plane, plane_condition};
pub use judge::{Fault, Judgement, RootJudged, judge, root_within};
pub use semantics::Semantics;

/// The least allowance for a gated camera's direction components, in ulps
/// of `Sᵢ = |fᵢ| + |u xᵢ| + |v yᵢ|` ([`component_scale`](crate::camera::component_scale)): what a plain
/// `f32` camera `(f + u·x) + v·y` reaches from a correctly rounded basis
/// (½ ulp for the basis, ½ for the offset, ½ for each of the two products
/// and two sums, rounded up, plus ½ for the oracle's own rounding).
pub const CAMERA_ULPS: f64 = 4.0;

/// A kernel's answer for one ray and primitive.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::check::rules::Answer;
/// use rayoracle::sphere::SphereHit;
/// assert_eq!(Answer::nearest(SphereHit::Two(-1.0, 3.0), 0.0), Answer::Nearest(Some(3.0)));
/// assert_eq!(Answer::roots(SphereHit::Tangent(2.0)), Answer::Roots(vec![2.0]));
/// # }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub enum Answer {
    /// Every root on the whole line, ascending (a tangent once, or twice).
    Roots(Vec<f32>),
    /// The nearest root `t > t_min` only, or none.
    Nearest(Option<f32>),
    /// The nearest hit's point `o + t·d`, or none, in any nearest-hit
    /// semantics: judged against the exact root's point, each component
    /// within the root's tolerance times `|dᵢ|`, plus half an ulp of the
    /// root times `|dᵢ|`, plus `2^bits` ulps of `|oᵢ| + |t dᵢ|` (the
    /// point's own rounding).
    Point(Option<Vec3>),
    /// Every `t` is a solution (a ray in the plane, a line on the quadric).
    Everywhere,
    /// The gate's `Lanes` adapter saw the lanes disagree; always a
    /// failure.
    Inconsistent(String),
}

impl Answer {
    /// The whole-line answer of any of rayoracle's result types.
    pub fn roots(h: impl Intersection) -> Answer {
        if h.is_everywhere() {
            Answer::Everywhere
        } else {
            Answer::Roots(h.roots().as_slice().to_vec())
        }
    }

    /// The nearest root strictly above `t_min` of any result type.
    pub fn nearest(h: impl Intersection, t_min: f32) -> Answer {
        if h.is_everywhere() {
            return Answer::Everywhere;
        }
        Answer::Nearest(h.roots().as_slice().iter().copied().find(|&t| t > t_min))
    }
}

impl fmt::Display for Answer {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Answer::Roots(r) if r.is_empty() => write!(f, "no roots"),
            Answer::Roots(r) => write!(f, "roots {r:?}"),
            Answer::Nearest(Some(t)) => write!(f, "nearest {t:?}"),
            Answer::Nearest(None) | Answer::Point(None) => write!(f, "no hit"),
            Answer::Point(Some(p)) => write!(f, "point {:?}", p.to_array()),
            Answer::Everywhere => write!(f, "every t"),
            Answer::Inconsistent(why) => write!(f, "inconsistent lanes: {why}"),
        }
    }
}

/// What the kernel promises: its semantics, its accuracy, and its inputs
/// (the rules are in the [module docs](self)).
///
/// ```
/// use rayoracle::check::rules::{Declared, Semantics};
/// let d = Declared::f32(Semantics::WholeLine);
/// assert_eq!(d.bits, 2.0);
/// assert!(Declared::faithful(Semantics::WholeLine).band_scale == 1.0);
/// assert_eq!(Declared::correctly_rounded(Semantics::WholeLine).allowed_ulps(f64::INFINITY), 0.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Declared {
    /// Whole line or nearest positive.
    pub semantics: Semantics,
    /// Bits of error allowed on a well-conditioned root.
    pub bits: f64,
    /// The kernel's relative working precision.
    pub precision: f64,
    /// Class tolerance, as a multiple of the unit band (0: none).
    pub band_scale: f64,
    /// Feed only unit-length directions (normalised in f32 first); skip
    /// cases whose normalisation fails (`unit-dirs`).
    pub unit_dirs_only: bool,
    /// Skip cases with a subnormal input (`no-subnormals`).
    pub no_subnormals: bool,
    /// Skip cases with a nonzero input of magnitude outside `[lo, hi]`
    /// (`magnitudes:LO:HI`).
    pub magnitudes: Option<(f32, f32)>,
    /// Skip cases whose largest input magnitude is more than `k` times the
    /// least (`spread:K`).
    pub spread: Option<f32>,
    /// Skip rays that start exactly on the surface (`off-surface`).
    pub off_surface: bool,
}

impl Declared {
    /// A careful f32 kernel: 2 bits, a few f32 roundings of working
    /// precision (`2⁻²²`), a band of `2²⁰` units (a plain f32 kernel needs
    /// about that much).
    pub fn f32(semantics: Semantics) -> Declared {
        Declared {
            semantics,
            bits: 2.0,
            precision: 2f64.powi(-22),
            band_scale: 2f64.powi(20),
            unit_dirs_only: false,
            no_subnormals: false,
            magnitudes: None,
            spread: None,
            off_surface: false,
        }
    }

    /// A faithfully rounded kernel: every root within one ulp of the exact
    /// one, with about `2⁻⁴²` of working precision and the unit band.
    pub fn faithful(semantics: Semantics) -> Declared {
        Declared {
            semantics,
            bits: 1.0,
            precision: 2f64.powi(-42),
            band_scale: 1.0,
            unit_dirs_only: false,
            no_subnormals: false,
            magnitudes: None,
            spread: None,
            off_surface: false,
        }
    }

    /// A correctly rounded kernel, what rayoracle's own kernels promise:
    /// every root the exact root's bits, whatever its κ, the exact class
    /// (no band), and every camera component the oracle's bits.
    /// [`check`](super) holds rayoracle's kernels to this.
    ///
    /// ```
    /// use rayoracle::check::rules::{Declared, Semantics};
    /// let d = Declared::correctly_rounded(Semantics::WholeLine);
    /// assert_eq!((d.allowed_ulps(1e30), d.band_scale, d.camera_ulps()), (0.0, 0.0, 0.0));
    /// ```
    pub fn correctly_rounded(semantics: Semantics) -> Declared {
        Declared {
            semantics,
            bits: 0.0,
            precision: 0.0,
            band_scale: 0.0,
            unit_dirs_only: false,
            no_subnormals: false,
            magnitudes: None,
            spread: None,
            off_surface: false,
        }
    }

    /// A careful pure-f32 renderer, declared honestly: [`Declared::f32`]'s
    /// roots, a class band of `2²⁴` units (a discriminant formed as `R² −
    /// |f − (f·d̂)d̂|²` in f32 errs by a few `2⁻²⁴ R|f|`), fed unit
    /// directions, no subnormal input, and every nonzero input between
    /// `2⁻³²` and `2⁴⁰` (so that squares and their sums neither underflow
    /// nor overflow).
    ///
    /// ```
    /// use rayoracle::check::rules::{Declared, Semantics};
    /// let d = Declared::careful_f32_renderer(Semantics::NearestPositive);
    /// assert!(d.unit_dirs_only && d.no_subnormals);
    /// assert_eq!(d.magnitudes, Some((2f32.powi(-32), 2f32.powi(40))));
    /// ```
    pub fn careful_f32_renderer(semantics: Semantics) -> Declared {
        Declared {
            band_scale: 2f64.powi(24),
            ..Declared::f32(semantics)
        }
        .unit_dirs()
        .no_subnormals()
        .magnitudes(2f32.powi(-32), 2f32.powi(40))
        .spread(2f32.powi(24))
        .off_surface()
    }

    /// The same, fed only unit-length directions.
    pub fn unit_dirs(self) -> Declared {
        Declared {
            unit_dirs_only: true,
            ..self
        }
    }

    /// The ulps allowed on a root of condition `kappa`:
    /// `2^bits − 1 + κ · precision · 2²⁴`; a NaN κ counts as infinite, and
    /// a precision of 0 allows nothing for κ.
    ///
    /// ```
    /// use rayoracle::check::rules::{Declared, Semantics};
    /// let d = Declared::f32(Semantics::WholeLine);
    /// assert_eq!(d.allowed_ulps(3.0), 3.0 + 12.0);
    /// assert_eq!(d.allowed_ulps(f64::NAN), f64::INFINITY);
    /// ```
    pub fn allowed_ulps(&self, kappa: f64) -> f64 {
        let k = if kappa.is_finite() {
            kappa
        } else {
            f64::INFINITY
        };
        let spread = if self.precision == 0.0 {
            0.0
        } else {
            k * self.precision * 2f64.powi(24)
        };
        (2f64.powf(self.bits) - 1.0) + spread
    }

    /// The ulps of `Sᵢ` allowed on a camera direction component: none
    /// where nothing is allowed on a root of κ = 4 (the oracle's bits),
    /// else at least [`CAMERA_ULPS`].
    ///
    /// ```
    /// use rayoracle::check::rules::{CAMERA_ULPS, Declared, Semantics};
    /// assert_eq!(Declared::faithful(Semantics::WholeLine).camera_ulps(), CAMERA_ULPS);
    /// ```
    pub fn camera_ulps(&self) -> f64 {
        match self.allowed_ulps(4.0) {
            0.0 => 0.0,
            a => a.max(CAMERA_ULPS),
        }
    }
}

#[cfg(test)]
pub(crate) mod tests {
    use super::*;

    /// `2^bits − 1 + κ · precision · 2²⁴`, term by term; a precision of 0
    /// allows nothing even for an infinite κ.
    #[test]
    fn allowed_ulps_term_by_term() {
        let faithful = Declared::faithful(Semantics::WholeLine);
        // 2¹ − 1 + 4 · 2⁻⁴² · 2²⁴.
        assert_eq!(faithful.allowed_ulps(4.0), 1.0 + 4.0 * 2f64.powi(-18));
        let f32 = Declared::f32(Semantics::WholeLine);
        // 2² − 1 + 3 · 2⁻²² · 2²⁴.
        assert_eq!(f32.allowed_ulps(3.0), 3.0 + 12.0);
        assert_eq!(f32.allowed_ulps(f64::NAN), f64::INFINITY);
        let cr = Declared::correctly_rounded(Semantics::WholeLine);
        assert_eq!(cr.allowed_ulps(f64::INFINITY), 0.0);
        assert_eq!(cr.allowed_ulps(f64::NAN), 0.0);
        // A camera gets at least CAMERA_ULPS unless nothing is allowed.
        assert_eq!(f32.camera_ulps(), 3.0 + 16.0);
        assert_eq!(cr.camera_ulps(), 0.0);
        assert_eq!(Declared { bits: 0.5, ..cr }.camera_ulps(), CAMERA_ULPS);
    }

    #[test]
    fn unit_dirs_changes_only_that() {
        let d = Declared::faithful(Semantics::NearestPositive);
        let u = d.unit_dirs();
        assert!(!d.unit_dirs_only && u.unit_dirs_only);
        assert_eq!(
            Declared {
                unit_dirs_only: false,
                ..u
            },
            d
        );
    }

    /// `x² − (1 − 2⁻²⁴)y² + z − 1`, crossed along `(1, 1, 1)` from 0 with
    /// α = 2⁻²⁴.
    #[cfg(feature = "quadric")]
    pub(crate) fn tiny_alpha() -> crate::quadric::Quadric {
        crate::quadric::Quadric::new([
            1.0,
            -(1.0 - 2f32.powi(-24)),
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            0.0,
            1.0,
            -1.0,
        ])
    }
}
