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
//!   ([`component_scale`]) of the oracle's.
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

use crate::Ray;
use crate::camera::{CameraError, CameraParams, component_scale};
#[cfg(feature = "plane")]
use crate::exact::dyadic::{dot, sub3, vec3};
use crate::hit::Intersection;
#[cfg(feature = "plane")]
use crate::plane::{self, Plane, PlaneHit};
#[cfg(feature = "quadric")]
use crate::quadric::{self, Quadric, QuadricHit};
#[cfg(feature = "sphere")]
use crate::sphere::{self, Sphere, SphereHit};
use crate::ulp::{step, ulp_of, ulps};
use glam::Vec3;
use std::fmt;

mod preconditions;
mod semantics;
pub use semantics::Semantics;

/// The least allowance for a gated camera's direction components, in ulps
/// of `Sᵢ = |fᵢ| + |u xᵢ| + |v yᵢ|` ([`component_scale`]): what a plain
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

/// The exact answer of a plane, sphere or quadric case, and the scales its
/// tolerances are measured in.
#[derive(Clone, Debug, PartialEq)]
pub struct Exact {
    /// Whole-line roots, ascending, correctly rounded; empty for none;
    /// `None` for every `t`.
    pub roots: Option<Vec<f32>>,
    /// Each root's condition number (infinite at a double root): one a
    /// root.
    pub kappa: Vec<f64>,
    /// The exact classification margin (`d·n`, `aΔ` or `β² − 4αγ`)
    /// rounded to f64.
    pub margin: f64,
    /// The margin's unit band, which `band_scale` multiplies.
    pub band: f64,
    /// A quadric's exact α and its unit band (`2⁻⁴⁴ Σ|α terms|`).
    pub alpha: Option<(f64, f64)>,
    /// Every input is an integer of magnitude at most 16: every margin is
    /// then computed exactly even in plain f32.
    pub small_integers: bool,
    /// The nearest double root `t* = −β/2α`, its κ, and the factor `s`
    /// by which a margin error `m` moves a root from it (`√m · s`); `None`
    /// for a plane or α = 0.
    pub vertex: Option<(f64, f64, f64)>,
    /// What must all vanish for every `t` to solve it, each with its unit
    /// band: `d·n` and the offset `(a − o)·n` of a plane, α, β and γ of a
    /// quadric; empty for a sphere, which is never every `t`.
    pub lies_on: Vec<(f64, f64)>,
    /// The ray, as judged (for [`Answer::Point`]).
    pub ray: Ray,
    /// The surface's function at the origin, exact and rounded to f64
    /// (`|o − C|² − R²`, `F(o)`, or `(o − a)·n`; `≤ 0` is inside a
    /// [`Semantics::Solid`]), and its unit band.
    pub inside: (f64, f64),
}

impl Exact {
    /// Whether a class other than the exact one is forgiven under `d`.
    ///
    /// ```
    /// # #[cfg(feature = "plane")] {
    /// use rayoracle::check::rules::{self, Declared, Semantics};
    /// use rayoracle::{Ray, plane::Plane};
    /// use glam::Vec3;
    /// // d·n = 2⁻²⁴ from terms 1 and 1 − 2⁻²⁴: within 2²⁰ units of 2⁻⁴⁴.
    /// let grazing = Ray::new(Vec3::Y, Vec3::new(1.0, 1.0 - 2f32.powi(-24), 0.0));
    /// let (_, e) = rules::plane(&grazing, &Plane::new(Vec3::ZERO, Vec3::new(1.0, -1.0, 0.0))).unwrap();
    /// assert!(e.in_band(&Declared::f32(Semantics::WholeLine)));
    /// assert!(!e.in_band(&Declared::correctly_rounded(Semantics::WholeLine)));
    /// // Along the ground, d·n = 0 from terms that are all 0: computed
    /// // exactly by any kernel, so in no band.
    /// let (_, e) = rules::plane(&Ray::new(Vec3::splat(0.5), Vec3::X), &Plane::new(Vec3::ZERO, Vec3::Y)).unwrap();
    /// assert!(!e.in_band(&Declared::f32(Semantics::WholeLine)));
    /// # }
    /// ```
    pub fn in_band(&self, d: &Declared) -> bool {
        !(self.margin == 0.0 && self.small_integers)
            && d.band_scale != 0.0
            && self.band > 0.0
            && self.margin.abs() <= self.band * d.band_scale
    }

    /// Whether a kernel under `d` may compute a value of unit band `unit`
    /// with an error at all: not without a band, nor on small integers,
    /// nor where every term is 0 (`unit = 0`).
    fn may_err(&self, d: &Declared, unit: f64) -> bool {
        d.band_scale != 0.0 && !self.small_integers && unit > 0.0
    }

    /// Whether "every t" against the exact answer's other class (or the
    /// other way round) is forgiven under `d`: each of
    /// [`lies_on`](Exact::lies_on) may be computed as 0 where some is not
    /// exactly 0, and some may be computed as nonzero where all are.
    ///
    /// ```
    /// # #[cfg(feature = "plane")] {
    /// use rayoracle::check::rules::{self, Declared, Semantics};
    /// use rayoracle::{Ray, plane::Plane};
    /// use glam::Vec3;
    /// let (ground, f32) = (Plane::new(Vec3::ZERO, Vec3::Y), Declared::f32(Semantics::WholeLine));
    /// let (_, off) = rules::plane(&Ray::new(Vec3::splat(0.5), Vec3::X), &ground).unwrap();
    /// assert!(!off.everywhere_in_band(&f32));
    /// // 2⁻²³ above y = 1, an ulp of the terms 1 and 1 + 2⁻²³ of the offset.
    /// let lifted = Plane::new(Vec3::Y, Vec3::Y);
    /// let (_, near) = rules::plane(&Ray::new(Vec3::new(0.0, 1.0 + 2f32.powi(-23), 0.0), Vec3::X), &lifted).unwrap();
    /// assert!(near.everywhere_in_band(&f32));
    /// assert!(!near.everywhere_in_band(&Declared::faithful(Semantics::WholeLine)));
    /// # }
    /// ```
    pub fn everywhere_in_band(&self, d: &Declared) -> bool {
        let on = &self.lies_on;
        if on.iter().all(|&(v, _)| v == 0.0) {
            on.iter().any(|&(_, u)| self.may_err(d, u))
        } else {
            !on.is_empty()
                && on
                    .iter()
                    .all(|&(v, u)| v == 0.0 || self.may_err(d, u) && v.abs() <= u * d.band_scale)
        }
    }

    /// Whether `t`, answered where the class differs within the band, is
    /// near the double root the band stands for: within `√(2(|margin| +
    /// band))·s` of `t*`, or within the ulps allowed at `t*`'s κ.
    ///
    /// A quadric with α = β = 0 has no vertex: there `t` must be a root of
    /// some α, β and γ within their bands, `|α|t² + |β||t| ≥ |γ| − γ band`;
    /// likewise a plane with `d·n = 0`, `|d·n| |t| ≥ |offset| − its band`.
    /// With `below`, only the lower of two roots: `t ≤ t*` or within its
    /// allowed ulps (a nearest hit is the lower root).
    fn near_vertex(&self, d: &Declared, t: f32, below: bool) -> bool {
        let Some((c, k, s)) = self.vertex else {
            return match self.lies_on[..] {
                [(0.0, au), (0.0, bu), (g, gu)] => {
                    let (t, k) = (f64::from(t).abs(), d.band_scale);
                    (au * t * t + bu * t + gu) * k >= g.abs()
                }
                [(0.0, du), (off, ou)] => {
                    let (t, k) = (f64::from(t).abs(), d.band_scale);
                    (du * t + ou) * k >= off.abs()
                }
                _ => true,
            };
        };
        let reach = (2.0 * (self.margin.abs() + self.band * d.band_scale)).sqrt() * s;
        let off = f64::from(t) - c;
        off.abs() <= reach && !(below && off > 0.0) || root_within(c as f32, t, d.allowed_ulps(k))
    }

    /// The allowance on a root `x` of condition `kappa` in absolute terms,
    /// `allowed · ulp(x)`, where the root's error is absolute: where that
    /// interval stays clear of the double root `t*` (the linear model of
    /// the error holds: a root near 0 from a cancelling `γ` may then cross
    /// 0), or for a linear root, where its denominator (`d·n`, or β at
    /// α = 0) is computed to a relative error below ½. Elsewhere 0, and
    /// roots are judged in ulps only.
    pub fn reach(&self, d: &Declared, x: f32, kappa: f64) -> f64 {
        let tol = match d.allowed_ulps(kappa) {
            0.0 => return 0.0,
            a => a * ulp_of(f64::from(x)),
        };
        let den = |(v, u): (f64, f64)| u * 2f64.powi(44) * d.precision < 0.5 * v.abs();
        let clear = match (self.vertex, &self.lies_on[..]) {
            (Some((c, _, _)), _) => tol < (f64::from(x) - c).abs(),
            (None, [dn, _]) => den(*dn),
            (None, [_, beta, _]) => den(*beta),
            _ => false,
        };
        if clear { tol } else { 0.0 }
    }

    /// Whether a quadric's α is within the band of its terms under `d`, so
    /// that the kernel may take it for 0 or not.
    pub fn alpha_small(&self, d: &Declared) -> bool {
        d.band_scale != 0.0
            && !self.small_integers
            && self
                .alpha
                .is_some_and(|(a, unit)| a.abs() <= unit * d.band_scale)
    }

    /// The answer a kernel of the declared semantics should give.
    pub fn expected(&self, d: &Declared) -> Answer {
        match &self.roots {
            None => Answer::Everywhere,
            Some(r) => match d.semantics.range() {
                None => Answer::Roots(r.clone()),
                Some((lo, hi)) if matches!(d.semantics, Semantics::RootsIn { .. }) => {
                    Answer::Roots(r.iter().copied().filter(|&t| in_range(t, lo, hi)).collect())
                }
                Some(_) if d.semantics == Semantics::Solid && self.inside.0 <= 0.0 => {
                    Answer::Nearest(Some(0.0))
                }
                Some((lo, hi)) => Answer::Nearest(r.iter().copied().find(|&t| in_range(t, lo, hi))),
            },
        }
    }
}

/// Whether every input is an integer of magnitude at most 16.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn small_integers(inputs: &[&[f32]]) -> bool {
    inputs
        .iter()
        .flat_map(|x| x.iter())
        .all(|&x| x.fract() == 0.0 && x.abs() <= 16.0)
}

/// A plane case's exact answer, or `None` for a non-finite input.
///
/// ```
/// use rayoracle::check::rules;
/// use rayoracle::{Ray, plane::{Plane, PlaneHit}};
/// use glam::Vec3;
/// let (h, e) = rules::plane(&Ray::new(Vec3::ZERO, Vec3::Z), &Plane::new(Vec3::Z, Vec3::Z)).unwrap();
/// assert_eq!((h, e.roots, e.kappa, e.margin), (PlaneHit::Hit(1.0), Some(vec![1.0]), vec![2.0], 1.0));
/// ```
#[cfg(feature = "plane")]
pub fn plane(ray: &Ray, p: &Plane) -> Option<(PlaneHit, Exact)> {
    let exact = plane::exact::intersect(ray, p).ok()?;
    let (o, d, a, n) = (
        vec3(ray.origin.to_array()).ok()?,
        vec3(ray.dir.to_array()).ok()?,
        vec3(p.point.to_array()).ok()?,
        vec3(p.normal.to_array()).ok()?,
    );
    let roots = (!exact.is_everywhere()).then(|| exact.roots().as_slice().to_vec());
    let k = plane_condition(ray, p);
    let e = Exact {
        kappa: vec![k; roots.as_ref().map_or(0, Vec::len)],
        roots,
        margin: dot(&d, &n).to_f64(),
        band: plane_band(ray, p),
        alpha: None,
        small_integers: small_integers(&[
            &ray.origin.to_array(),
            &ray.dir.to_array(),
            &p.point.to_array(),
            &p.normal.to_array(),
        ]),
        vertex: None,
        lies_on: vec![
            (dot(&d, &n).to_f64(), plane_band(ray, p)),
            (dot(&sub3(&a, &o), &n).to_f64(), offset_band(ray, p)),
        ],
        ray: *ray,
        inside: (dot(&sub3(&o, &a), &n).to_f64(), offset_band(ray, p)),
    };
    Some((exact, e))
}

/// A sphere case's exact answer, or `None` for a non-finite input.
#[cfg(feature = "sphere")]
pub fn sphere(ray: &Ray, s: &Sphere) -> Option<(SphereHit, Exact)> {
    let q = sphere::exact::quadratic(ray, s).ok()?;
    let exact = sphere::exact::classify(&q);
    Some((exact, sphere_given(ray, s, &q, exact)))
}

/// [`sphere`], given the exact quadratic and its solution.
#[cfg(feature = "sphere")]
pub(crate) fn sphere_given(
    ray: &Ray,
    s: &Sphere,
    q: &crate::exact::Quadratic,
    exact: SphereHit,
) -> Exact {
    let roots = exact.roots().as_slice().to_vec();
    let kappa = roots
        .iter()
        .map(|&t| match exact {
            SphereHit::Two(..) => sphere::condition_at(ray, s, t as f64),
            _ => sphere_vertex(ray, s, t as f64).1,
        })
        .collect();
    Exact {
        roots: Some(roots),
        kappa,
        margin: (&q.alpha * &q.discriminant()).mul_pow2(-2).to_f64(),
        band: sphere_band(ray, s),
        alpha: None,
        small_integers: small_integers(&[
            &ray.origin.to_array(),
            &ray.dir.to_array(),
            &s.center.to_array(),
            &[s.radius],
        ]),
        vertex: Some(sphere_vertex(ray, s, f64::NAN)),
        lies_on: Vec::new(),
        ray: *ray,
        inside: sphere_inside(ray, s),
    }
}

/// The sphere's double root `t* = −b/a` (`a = d·d`, `b = f·d`, `f = o −
/// C`), its κ, and `s = a^(−3/2)`, by which a margin error `m` moves the
/// roots `t* ± √(aΔ)/a^(3/2)`. `t*` is a quotient, so its condition is
/// finite: `∂t*/∂oᵢ = −dᵢ/a`, `∂t*/∂Cᵢ = dᵢ/a`, `∂t*/∂dᵢ = −(fᵢ + 2t*dᵢ)/a`
/// and R does not enter, so `κ = Σ(|oᵢdᵢ| + |Cᵢdᵢ| + |dᵢ(fᵢ + 2t*dᵢ)|) /
/// (a|t*|)`, infinite at `t* = 0`. κ is taken at `at` where given (a
/// tangent's rounded root), else at `t*`.
#[cfg(feature = "sphere")]
fn sphere_vertex(ray: &Ray, s: &Sphere, at: f64) -> (f64, f64, f64) {
    let (o, c, d) = (
        ray.origin.as_dvec3(),
        s.center.as_dvec3(),
        ray.dir.as_dvec3(),
    );
    let f = o - c;
    let a = d.length_squared();
    let vertex = -f.dot(d) / a;
    let t = if at.is_nan() { vertex } else { at };
    let kappa = if t == 0.0 || !t.is_finite() {
        f64::INFINITY
    } else {
        (0..3)
            .map(|i| {
                (o[i] * d[i]).abs() + (c[i] * d[i]).abs() + (d[i] * (f[i] + 2.0 * t * d[i])).abs()
            })
            .sum::<f64>()
            / (a * t.abs())
    };
    (vertex, kappa, a.powf(-1.5))
}

/// The sphere's `|o − C|² − R²`, exact (from the quadratic of the ray with
/// `d = 0`, where α = β = 0 and γ keeps its sign), and its unit band
/// `2⁻⁴⁴(2Σ(|oᵢ| + |Cᵢ|)|fᵢ| + R²)`, since `fᵢ = oᵢ − Cᵢ` rounds relative
/// to its operands.
#[cfg(feature = "sphere")]
fn sphere_inside(ray: &Ray, s: &Sphere) -> (f64, f64) {
    let value = sphere::exact::quadratic(&Ray::new(ray.origin, Vec3::ZERO), s)
        .map_or(f64::NAN, |z| z.gamma.to_f64());
    let (o, c) = (ray.origin.as_dvec3(), s.center.as_dvec3());
    let f = o - c;
    let terms: f64 = (0..3)
        .map(|i| 2.0 * (o[i].abs() + c[i].abs()) * f[i].abs())
        .sum();
    let r = f64::from(s.radius);
    (value, (terms + r * r) * 2f64.powi(-44))
}

/// A quadric case's exact answer, or `None` for a non-finite input.
#[cfg(feature = "quadric")]
pub fn quadric(ray: &Ray, q: &Quadric) -> Option<(QuadricHit, Exact)> {
    let eq = quadric::exact::quadratic(ray, q).ok()?;
    let exact = quadric::exact::classify(&eq);
    Some((exact, quadric_given(ray, q, &eq, exact)))
}

/// [`quadric`], given the exact quadratic and its solution.
#[cfg(feature = "quadric")]
pub(crate) fn quadric_given(
    ray: &Ray,
    q: &Quadric,
    eq: &crate::exact::Quadratic,
    exact: QuadricHit,
) -> Exact {
    let roots = (!exact.is_everywhere()).then(|| exact.roots().as_slice().to_vec());
    let double = matches!(exact, QuadricHit::One(_)) && !eq.alpha.is_zero();
    let kappa = roots
        .iter()
        .flatten()
        .map(|&t| {
            if double {
                quadric_vertex(ray, q, eq).1
            } else {
                quadric_kappa_at(ray, q, eq, t as f64)
            }
        })
        .collect();
    let (at, bt, gt) = quadric::terms(ray, q);
    let unit = |x: &[f64]| x.iter().map(|x| x.abs()).sum::<f64>() * 2f64.powi(-44);
    Exact {
        roots,
        kappa,
        margin: eq.discriminant().to_f64(),
        band: match vertex_frame(ray, q, eq) {
            Some(v) => quadric_band(ray, q).min(v.band()),
            None => quadric_band(ray, q),
        },
        alpha: Some((eq.alpha.to_f64(), alpha_terms(ray, q) * 2f64.powi(-44))),
        small_integers: small_integers(&[&ray.origin.to_array(), &ray.dir.to_array(), &q.coeffs]),
        vertex: (!eq.alpha.is_zero()).then(|| quadric_vertex(ray, q, eq)),
        lies_on: vec![
            (eq.alpha.to_f64(), unit(&at)),
            (eq.beta.to_f64(), unit(&bt)),
            (eq.gamma.to_f64(), unit(&gt)),
        ],
        ray: *ray,
        inside: (
            // With d = 0, α = β = 0 and γ = F(o) keeps its sign.
            quadric::exact::quadratic(&Ray::new(ray.origin, Vec3::ZERO), q)
                .map_or(f64::NAN, |z| z.gamma.to_f64()),
            unit(&gt),
        ),
    }
}

/// The quadric's double root `t* = −β/2α`, its κ, and `s = 1/(2|α|)`, by
/// which a discriminant error `m` moves the roots `t* ± √D/(2|α|)`. `t*`
/// is a quotient: its relative error is β's plus α's, each term a product
/// of at most three inputs, so `κ = 3(Σ|β terms|/|β| + Σ|α terms|/|α|)`,
/// infinite at `t* = 0` (β = 0). α must not be 0.
#[cfg(feature = "quadric")]
fn quadric_vertex(ray: &Ray, q: &Quadric, eq: &crate::exact::Quadratic) -> (f64, f64, f64) {
    let (at, bt, _) = quadric::terms(ray, q);
    let sum = |x: &[f64]| x.iter().map(|x| x.abs()).sum::<f64>();
    let (a, b) = (eq.alpha.to_f64(), eq.beta.to_f64());
    let kappa = if b == 0.0 {
        f64::INFINITY
    } else {
        3.0 * (sum(&bt) / b.abs() + sum(&at) / a.abs())
    };
    (-b / (2.0 * a), kappa, 0.5 / a.abs())
}

/// The plane root's condition number, as the plane module documents it:
/// `κ = Σ|dᵢnᵢ| / |d·n| + Σ|(aᵢ−oᵢ)nᵢ| / |(a−o)·n|`, with the two dot
/// products exact (a `0/0` term counts as 0, `x/0` as ∞). NaN for a
/// non-finite input.
///
/// ```
/// use rayoracle::check::plane_condition;
/// use rayoracle::{Ray, plane::Plane};
/// use glam::Vec3;
/// let k = plane_condition(&Ray::new(Vec3::ZERO, Vec3::Z), &Plane::new(Vec3::Z, Vec3::Z));
/// assert_eq!(k, 2.0);
/// ```
#[cfg(feature = "plane")]
pub fn plane_condition(ray: &Ray, p: &Plane) -> f64 {
    let (Ok(o), Ok(d), Ok(a), Ok(n)) = (
        vec3(ray.origin.to_array()),
        vec3(ray.dir.to_array()),
        vec3(p.point.to_array()),
        vec3(p.normal.to_array()),
    ) else {
        return f64::NAN;
    };
    let den = dot(&d, &n).to_f64().abs();
    let num = dot(&sub3(&a, &o), &n).to_f64().abs();
    let sd: f64 = (0..3)
        .map(|i| (ray.dir[i] as f64 * p.normal[i] as f64).abs())
        .sum();
    let sn: f64 = (0..3)
        .map(|i| ((p.point[i] as f64 - ray.origin[i] as f64) * p.normal[i] as f64).abs())
        .sum();
    let ratio = |s: f64, x: f64| if s == 0.0 { 0.0 } else { s / x };
    ratio(sd, den) + ratio(sn, num)
}

/// [`quadric::condition`]'s κ, `(3Σ|α terms| t² + 3Σ|β terms| |t| +
/// 3Σ|γ terms|) / (|2αt + β| |t|)`, at a given root `t`, with the exact α
/// and β in `p'(t) = 2αt + β`.
#[cfg(feature = "quadric")]
fn quadric_kappa_at(ray: &Ray, q: &Quadric, eq: &crate::exact::Quadratic, t: f64) -> f64 {
    let (at, bt, gt) = quadric::terms(ray, q);
    let abs_sum = |xs: &[f64]| xs.iter().map(|x| x.abs()).sum::<f64>();
    let (sa, sb, sg) = (abs_sum(&at), abs_sum(&bt), abs_sum(&gt));
    if t == 0.0 || !t.is_finite() {
        // A zero root is exact when γ has no terms at all.
        return if t == 0.0 && sg == 0.0 {
            0.0
        } else {
            f64::INFINITY
        };
    }
    let dp = (2.0 * eq.alpha.to_f64() * t + eq.beta.to_f64()).abs();
    let at_origin = (3.0 * sa * t * t + 3.0 * sb * t.abs() + 3.0 * sg) / (dp * t.abs());
    match vertex_frame(ray, q, eq) {
        Some(v) => {
            let s = (t - v.t).abs();
            let at_vertex = (3.0 * sa * s * s + 3.0 * v.beta * s + 3.0 * v.gamma) / (dp * t.abs());
            at_origin.min(at_vertex)
        }
        None => at_origin,
    }
}

/// The quadric re-expanded about the ray's double root `p* = o + t*d`
/// (`t* = −β/2α`), where its α, β, γ are those of `s = t − t*`: what a
/// careful kernel's error depends on, whatever frame the coefficients are
/// written in. Measured from the terms at the origin instead, a far sphere
/// written as a quadric (terms `|o|²` against a discriminant `4aR²`) would
/// forgive every class and every root.
#[cfg(feature = "quadric")]
struct VertexFrame {
    /// `t*`.
    t: f64,
    /// `Σ|α terms|`.
    alpha: f64,
    /// `Σ|gᵢdᵢ|`, `g = ∇F(p*)`: the terms of β at `p*` (which sum to 0).
    beta: f64,
    /// `Σ|F terms at p*| + G·|t*d|`: the terms of γ at `p*` (what a kernel
    /// that evaluates `F(p*)` errs by), and what an error of `2⁻⁴⁴` of the
    /// way from `o` to `p*` changes it by, `G = |g| + |Hd|·√(Σ|F terms|/Σ|α
    /// terms|)` bounding the gradient between `p*` and the roots (`2R` for
    /// a sphere, whose gradient vanishes at the centre).
    gamma: f64,
}

#[cfg(feature = "quadric")]
impl VertexFrame {
    /// The discriminant's unit band in this frame: `2⁻⁴⁰(Σβ)² + 2⁻⁴²
    /// Σα·γ`, the sphere's `a²(R² + R|f|)·2⁻⁴⁴` (times the 4 of `β² − 4αγ`)
    /// for a sphere written as a quadric.
    fn band(&self) -> f64 {
        self.beta * self.beta * 2f64.powi(-40) + self.alpha * self.gamma * 2f64.powi(-42)
    }
}

/// [`VertexFrame`] of a ray and quadric with α ≠ 0, in f64 (a scale, not
/// an exact value).
#[cfg(feature = "quadric")]
fn vertex_frame(ray: &Ray, q: &Quadric, eq: &crate::exact::Quadratic) -> Option<VertexFrame> {
    if eq.alpha.is_zero() {
        return None;
    }
    let t = -eq.beta.to_f64() / (2.0 * eq.alpha.to_f64());
    let k = q.coeffs.map(f64::from);
    let d = ray.dir.as_dvec3();
    let p = ray.origin.as_dvec3() + t * d;
    let g = glam::DVec3::new(
        2.0 * k[0] * p.x + k[3] * p.y + k[4] * p.z + k[6],
        2.0 * k[1] * p.y + k[3] * p.x + k[5] * p.z + k[7],
        2.0 * k[2] * p.z + k[4] * p.x + k[5] * p.y + k[8],
    );
    let terms = [
        k[0] * p.x * p.x,
        k[1] * p.y * p.y,
        k[2] * p.z * p.z,
        k[3] * p.x * p.y,
        k[4] * p.x * p.z,
        k[5] * p.y * p.z,
        k[6] * p.x,
        k[7] * p.y,
        k[8] * p.z,
        k[9],
    ];
    let f = terms.iter().map(|x| x.abs()).sum::<f64>();
    let hd = glam::DVec3::new(
        2.0 * k[0] * d.x + k[3] * d.y + k[4] * d.z,
        k[3] * d.x + 2.0 * k[1] * d.y + k[5] * d.z,
        k[4] * d.x + k[5] * d.y + 2.0 * k[2] * d.z,
    );
    let alpha = alpha_terms(ray, q);
    let grad = g.length() + hd.length() * (f / alpha).sqrt();
    let v = VertexFrame {
        t,
        alpha,
        beta: (g * d).abs().element_sum(),
        gamma: f + grad * (t * d).length(),
    };
    [v.t, v.beta, v.gamma]
        .iter()
        .all(|x| x.is_finite())
        .then_some(v)
}

/// The sphere's unit band, in units of the margin `aΔ = (aR)² − |af −
/// bd|²`: `a²(R² + R|f|)·2⁻⁴⁴`. Near a tangent `|af − bd| ≈ aR`, and a
/// careful kernel forms it with an error of about `a|f|` times its
/// precision, so its square errs by about `2a²R|f|` times that. A band
/// from `(a|f|)²` instead would forgive a plain f32 kernel every class of
/// a far sphere.
#[cfg(feature = "sphere")]
fn sphere_band(ray: &Ray, s: &Sphere) -> f64 {
    let d = ray.dir.as_dvec3();
    let f = ray.origin.as_dvec3() - s.center.as_dvec3();
    let (a, r) = (d.length_squared(), f64::from(s.radius).abs());
    a * a * (r * r + r * f.length()) * 2f64.powi(-44)
}

/// The plane's unit band on the offset `(a − o)·n`: `2⁻⁴⁴ Σ(|aᵢ| +
/// |oᵢ|)|nᵢ|`, since `aᵢ − oᵢ` rounds relative to its operands.
#[cfg(feature = "plane")]
fn offset_band(ray: &Ray, p: &Plane) -> f64 {
    let s: f64 = (0..3)
        .map(|i| {
            (f64::from(p.point[i]).abs() + f64::from(ray.origin[i]).abs())
                * f64::from(p.normal[i]).abs()
        })
        .sum();
    s * 2f64.powi(-44)
}

/// The plane's unit band on the margin `d·n`: `2⁻⁴⁴ Σ|dᵢnᵢ|`.
#[cfg(feature = "plane")]
fn plane_band(ray: &Ray, p: &Plane) -> f64 {
    let s: f64 = (0..3)
        .map(|i| (f64::from(ray.dir[i]) * f64::from(p.normal[i])).abs())
        .sum();
    s * 2f64.powi(-44)
}

/// The quadric's unit band on the discriminant `β² − 4αγ`: `2⁻⁴⁰((Σ|β
/// terms|)² + 4 Σ|α terms| Σ|γ terms|)`.
#[cfg(feature = "quadric")]
fn quadric_band(ray: &Ray, q: &Quadric) -> f64 {
    let (a, b, g) = quadric::terms(ray, q);
    let sum = |x: &[f64]| x.iter().map(|x| x.abs()).sum::<f64>();
    let (sa, sb, sg) = (sum(&a), sum(&b), sum(&g));
    (sb * sb + 4.0 * sa * sg) * 2f64.powi(-40)
}

/// `Σ |kᵢ dⱼ dₖ|` over α's six terms: the scale α's rounding error is
/// relative to.
#[cfg(feature = "quadric")]
fn alpha_terms(ray: &Ray, q: &Quadric) -> f64 {
    let k = q.coeffs.map(f64::from);
    let dd = ray.dir.to_array().map(f64::from);
    (k[0] * dd[0] * dd[0]).abs()
        + (k[1] * dd[1] * dd[1]).abs()
        + (k[2] * dd[2] * dd[2]).abs()
        + (k[3] * dd[0] * dd[1]).abs()
        + (k[4] * dd[0] * dd[2]).abs()
        + (k[5] * dd[1] * dd[2]).abs()
}

/// One root compared with the exact one, and what was allowed.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RootJudged {
    /// Which exact root (ascending).
    pub index: usize,
    /// The exact, correctly rounded root.
    pub exact: f32,
    /// The kernel's root.
    pub got: f32,
    /// The distance between them in ulps.
    pub ulps: u64,
    /// The ulps allowed ([`Declared::allowed_ulps`] at κ).
    pub allowed: f64,
    /// The root's condition number.
    pub kappa: f64,
    /// The same allowance in absolute terms, `allowed · ulp(exact)`, where
    /// the root's error is absolute ([`Exact::reach`]), else 0.
    pub reach: f64,
}

impl RootJudged {
    fn new(d: &Declared, e: &Exact, index: usize, exact: f32, got: f32, kappa: f64) -> RootJudged {
        RootJudged {
            index,
            exact,
            got,
            ulps: ulps(exact, got),
            allowed: d.allowed_ulps(kappa),
            kappa,
            reach: e.reach(d, exact, kappa),
        }
    }

    /// Whether the root is within what is allowed, in ulps or within its
    /// absolute reach: the exact root's bits where nothing is.
    ///
    /// ```
    /// use rayoracle::check::rules::RootJudged;
    /// let r = RootJudged { index: 0, exact: 0.0, got: -0.0, ulps: 0, allowed: 0.0, kappa: 1.0, reach: 0.0 };
    /// assert!(!r.ok() && RootJudged { allowed: 1.0, ..r }.ok());
    /// // Across zero: 2⁻²⁰ − 2⁻³⁰ is 2²⁰ floats away, but within a reach of 2⁻¹⁹.
    /// let r = RootJudged { exact: 2f32.powi(-20), got: -2f32.powi(-30), ulps: 1 << 30, allowed: 8.0, reach: 2f64.powi(-19), ..r };
    /// assert!(r.ok() && !RootJudged { reach: 0.0, ..r }.ok());
    /// ```
    pub fn ok(&self) -> bool {
        root_within(self.exact, self.got, self.allowed)
            || self.reach > 0.0 && (f64::from(self.got) - f64::from(self.exact)).abs() <= self.reach
    }
}

/// Whether `got` is within `allowed` ulps of `exact`; where nothing is
/// allowed, whether it is `exact`'s bits (`−0` is not `+0`).
///
/// ```
/// use rayoracle::check::rules::root_within;
/// assert!(root_within(1.0, 1.0, 0.0) && !root_within(0.0, -0.0, 0.0));
/// assert!(root_within(1.0, 1.0 + f32::EPSILON, 1.0) && !root_within(1.0, f32::NAN, 1e9));
/// ```
pub fn root_within(exact: f32, got: f32, allowed: f64) -> bool {
    if allowed == 0.0 {
        got.to_bits() == exact.to_bits()
    } else {
        ulps(exact, got) as f64 <= allowed
    }
}

/// Why an answer fails; its `Display` is the reason the gate prints.
#[derive(Clone, Debug, PartialEq)]
pub enum Fault {
    /// The lanes of a four-lane kernel disagree (the message).
    Inconsistent(String),
    /// A root is NaN.
    NanRoot,
    /// A different class, outside the band.
    Class,
    /// Every `t` solves it and the kernel says otherwise.
    NotEverywhere,
    /// The answer is of the other semantics.
    Semantics(Semantics),
    /// Whole-line roots out of order.
    NotAscending,
    /// A root farther from the exact one than allowed.
    Root(RootJudged),
    /// With a small α, a root near none of the exact ones.
    Stray(f32),
    /// With α = 0, neither of two roots is the exact one.
    Neither(f32),
    /// A nearest hit that exists was missed.
    Missed,
    /// A nearest hit at `t ≤ t_min` (0 unless declared) or `t ≥ t_max`
    /// was returned.
    NotPositive,
    /// A nearest hit where there is none.
    Spurious,
    /// The origin is inside the solid, and the answer is not `t = 0`.
    Inside,
    /// A root outside the declared range of `t`.
    OutOfRange(f32),
    /// A hit point off the exact root's point (the exact root) by more than
    /// allowed.
    Point(f32),
}

impl fmt::Display for Fault {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Fault::Inconsistent(why) => write!(f, "{why}"),
            Fault::NanRoot => write!(f, "a NaN root"),
            Fault::Class => write!(
                f,
                "a different class, and the exact margin is outside the declared band"
            ),
            Fault::NotEverywhere => write!(
                f,
                "every t solves it (the ray lies on the surface), and the kernel says otherwise"
            ),
            Fault::Semantics(s) => write!(f, "the kernel answers in the wrong semantics for {s:?}"),
            Fault::NotAscending => write!(f, "the roots are not ascending"),
            Fault::Root(r) if r.ulps == 0 => write!(
                f,
                "the sign of zero is not the correctly rounded root's (κ = {:.3e})",
                r.kappa
            ),
            Fault::Root(r) => write!(
                f,
                "{} ulps from the correctly rounded root, allowed {:.1} (κ = {:.3e})",
                r.ulps, r.allowed, r.kappa
            ),
            Fault::Stray(t) => write!(f, "the root {t:?} is near none of the exact roots"),
            Fault::Neither(x) => write!(f, "neither root is near the exact root {x:?}"),
            Fault::Missed => write!(f, "a hit was missed"),
            Fault::NotPositive => write!(f, "a hit at t ≤ 0 was returned"),
            Fault::Spurious => write!(f, "a hit where there is none"),
            Fault::Inside => write!(f, "the origin is inside the solid, and t is not 0"),
            Fault::OutOfRange(t) => write!(f, "the root {t:?} is outside the declared range"),
            Fault::Point(t) => write!(
                f,
                "the point is farther than allowed from the exact point at t = {t:?}"
            ),
        }
    }
}

/// What [`judge`] found: the roots it compared one to one, and the fault,
/// if any.
#[derive(Clone, Debug, PartialEq)]
pub struct Judgement {
    /// The roots compared with their exact counterparts (all of them when
    /// the counts match, the nearest one in `NearestPositive`).
    pub roots: Vec<RootJudged>,
    /// Why the answer fails; `None` if it passes.
    pub fault: Option<Fault>,
}

impl Judgement {
    /// Whether the answer passes.
    pub fn passed(&self) -> bool {
        self.fault.is_none()
    }
}

/// Judges `got` against the exact answer `e` under the declaration `d`, by
/// the rules in the [module docs](self).
///
/// ```
/// # #[cfg(feature = "quadric")] {
/// use rayoracle::check::rules::{self, Answer, Declared, Fault, Semantics};
/// use rayoracle::{Ray, quadric::Quadric};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let (_, e) = rules::quadric(&Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X), &cyl).unwrap();
/// let d = Declared::correctly_rounded(Semantics::WholeLine);
/// assert!(rules::judge(&d, &e, &Answer::Roots(vec![4.0, 6.0])).passed());
/// assert_eq!(rules::judge(&d, &e, &Answer::Roots(vec![4.0])).fault, Some(Fault::Class));
/// # }
/// ```
pub fn judge(d: &Declared, e: &Exact, got: &Answer) -> Judgement {
    let mut roots = Vec::new();
    let fault = fault(d, e, got, &mut roots);
    Judgement { roots, fault }
}

fn fault(d: &Declared, e: &Exact, got: &Answer, seen: &mut Vec<RootJudged>) -> Option<Fault> {
    if let Answer::Inconsistent(why) = got {
        return Some(Fault::Inconsistent(why.clone()));
    }
    let (in_band, alpha_small) = (e.in_band(d), e.alpha_small(d));
    let kappa = |i: usize| e.kappa.get(i).copied().unwrap_or(f64::INFINITY);
    let close = |i: usize, x: f32, g: f32| RootJudged::new(d, e, i, x, g, kappa(i)).ok();
    let nan = match got {
        Answer::Roots(g) => g.iter().any(|t| t.is_nan()),
        Answer::Nearest(Some(t)) => t.is_nan(),
        Answer::Point(Some(p)) => p.is_nan(),
        _ => false,
    };
    let expected = e.expected(d);
    if let (Answer::Roots(x), Answer::Roots(g), Semantics::WholeLine) =
        (&expected, got, d.semantics)
    {
        // With a band, a single root may come twice.
        let g = match g.as_slice() {
            [a, b] if x.len() == 1 && a == b && d.band_scale != 0.0 => &g[..1],
            g => g,
        };
        if x.len() == g.len() {
            seen.extend((0..x.len()).map(|i| RootJudged::new(d, e, i, x[i], g[i], kappa(i))));
        }
    }
    if nan {
        return Some(Fault::NanRoot);
    }
    if let Answer::Roots(g) = got
        && g.windows(2).any(|w| !(w[0] <= w[1]))
    {
        return Some(Fault::NotAscending);
    }
    let fault = match (&expected, got) {
        (Answer::Everywhere, Answer::Everywhere) => return None,
        // A ray lying on the surface has no nearest hit to compare.
        (Answer::Everywhere, _)
            if !matches!(
                d.semantics,
                Semantics::WholeLine | Semantics::RootsIn { .. }
            ) =>
        {
            return None;
        }
        (Answer::Everywhere, Answer::Nearest(_) | Answer::Roots(_) | Answer::Point(_))
            if e.everywhere_in_band(d) =>
        {
            return None;
        }
        (Answer::Everywhere, Answer::Nearest(_) | Answer::Roots(_) | Answer::Point(_)) => {
            Fault::NotEverywhere
        }
        (_, Answer::Everywhere) if e.everywhere_in_band(d) => return None,
        (_, Answer::Everywhere) => Fault::Class,
        (Answer::Roots(_), Answer::Roots(g)) if d.semantics != Semantics::WholeLine => {
            return roots_in_fault(d, e, g, in_band, seen);
        }
        (Answer::Roots(x), Answer::Roots(g)) => {
            let one_or_two = x.len().min(g.len()) == 1 && x.len().max(g.len()) == 2;
            if !seen.is_empty() || x.is_empty() && g.is_empty() {
                Fault::Root(*seen.iter().find(|r| !r.ok())?)
            } else if in_band {
                // Near a double root the class may differ, but each root
                // must be as near the double root as the band reaches.
                match g.iter().find(|&&t| !e.near_vertex(d, t, false)) {
                    None => return None,
                    Some(&t) => Fault::Stray(t),
                }
            } else if alpha_small && one_or_two && g.len() == 1 {
                // The kernel took a tiny α for 0: its one root must be one
                // of the exact two; what a band excuses is the count, not
                // the values.
                if (0..x.len()).any(|i| close(i, x[i], g[0])) {
                    return None;
                }
                Fault::Stray(g[0])
            } else if alpha_small && one_or_two {
                // α = 0 exactly, and the kernel kept a tiny α: one of its
                // two roots must be the exact one.
                if g.iter().any(|&t| close(0, x[0], t)) {
                    return None;
                }
                Fault::Neither(x[0])
            } else {
                Fault::Class
            }
        }
        (Answer::Nearest(_), Answer::Nearest(_) | Answer::Point(_)) => {
            return nearest_fault(d, e, got, in_band, seen);
        }
        _ => Fault::Semantics(d.semantics),
    };
    Some(fault)
}

/// A nearest-hit answer ([`Answer::Nearest`] or [`Answer::Point`]) under a
/// nearest-hit semantics, judged root by root in absolute terms: each exact
/// root `rᵢ` stands for the interval `rᵢ ± tolᵢ`, `tolᵢ` its allowed ulps
/// times `ulp(rᵢ)`. A root whose interval crosses `t_min` or `t_max` may
/// be taken as a hit or not, so the answer may be any root up to the first
/// one surely inside the range, or none where every root may be outside.
fn nearest_fault(
    d: &Declared,
    e: &Exact,
    got: &Answer,
    in_band: bool,
    seen: &mut Vec<RootJudged>,
) -> Option<Fault> {
    let roots = e.roots.as_deref().unwrap_or(&[]);
    let kappa = |i: usize| e.kappa.get(i).copied().unwrap_or(f64::INFINITY);
    let tol = |i: usize| e.reach(d, roots[i], kappa(i));
    let (t, p) = match got {
        Answer::Nearest(t) => (*t, None),
        Answer::Point(p) => (p.map(|p| t_of_point(&e.ray, p)), *p),
        _ => (None, None),
    };
    // The hit matches the exact root `x` within `tol` (in t, or in space).
    let near = |x: f32, i: usize| match (t, p) {
        (_, Some(p)) => point_near(d, &e.ray, f64::from(x), tol(i), p),
        (Some(t), None) => RootJudged::new(d, e, i, x, t, kappa(i)).ok(),
        _ => false,
    };
    if d.semantics == Semantics::Solid {
        let (v, u) = e.inside;
        let either = e.may_err(d, u) && v.abs() <= u * d.band_scale;
        let zero = match (t, p) {
            (_, Some(p)) => point_near(d, &e.ray, 0.0, 0.0, p),
            (Some(t), None) => t == 0.0,
            _ => false,
        };
        match () {
            _ if zero && (v <= 0.0 || either) => return None,
            _ if v <= 0.0 && !either => return Some(Fault::Inside),
            _ => {}
        }
    }
    let (lo, hi) = d.semantics.range().unwrap_or((0.0, f32::INFINITY));
    let span = Span { d, e, lo, hi };
    let mut candidates = Vec::new();
    let mut none_ok = true;
    for i in 0..roots.len() {
        if span.may(i) {
            candidates.push(i);
        }
        if span.sure(i) {
            none_ok = false;
            break;
        }
    }
    let expected = roots.iter().position(|&r| in_range(r, lo, hi));
    let Some(t) = t else {
        // A root at t ≈ 0, or a class in the band, may go either way.
        return match expected.map(|i| roots[i]) {
            _ if none_ok || in_band => None,
            Some(x) if x.abs() <= 1e-30 => None,
            _ => Some(Fault::Missed),
        };
    };
    if let (Some(i), None) = (expected, p) {
        seen.push(RootJudged::new(d, e, i, roots[i], t, kappa(i)));
    }
    // A root this close to 0 may round to either side: forgiven where some
    // exact root may be there (within its reach), but not where every input
    // is a small integer: there every root is 0 or far from it, and
    // rounding errors are far above 10⁻³⁰, so a 0 answered for `t > 0` is
    // `t ≥ 0`. A miss answered as 0 is not forgiven.
    let root_near_zero = e.roots.is_none()
        || (0..roots.len()).any(|i| {
            let (a, b) = span.ends(i);
            a <= 1e-30 && b >= -1e-30
        });
    if expected.is_none() && t.abs() <= 1e-30 && root_near_zero && !e.small_integers {
        return None;
    }
    if p.is_none() && !in_range(t, lo, hi) {
        return Some(Fault::NotPositive);
    }
    // In the band, the nearer of two roots near the double root.
    if candidates.iter().any(|&i| near(roots[i], i)) || in_band && e.near_vertex(d, t, true) {
        return None;
    }
    Some(match (expected, p) {
        (None, _) => Fault::Spurious,
        (Some(i), Some(_)) => Fault::Point(roots[i]),
        (Some(_), None) => Fault::Root(*seen.last()?),
    })
}

/// Every root in `(t_min, t_max)` ([`Semantics::RootsIn`]): the answer
/// must be the exact roots in order, each by its own κ, leaving out only
/// roots whose absolute reach crosses an end of the range and keeping every
/// root surely inside; with a band, a single root may come twice, and a
/// class forgiven near a tangent wants roots near it.
fn roots_in_fault(
    d: &Declared,
    e: &Exact,
    g: &[f32],
    in_band: bool,
    seen: &mut Vec<RootJudged>,
) -> Option<Fault> {
    let roots = e.roots.as_deref().unwrap_or(&[]);
    let kappa = |i: usize| e.kappa.get(i).copied().unwrap_or(f64::INFINITY);
    let (lo, hi) = d
        .semantics
        .range()
        .unwrap_or((f32::NEG_INFINITY, f32::INFINITY));
    if let Some(&t) = g.iter().find(|&&t| !in_range(t, lo, hi)) {
        return Some(Fault::OutOfRange(t));
    }
    let g = match g {
        [a, b] if a == b && d.band_scale != 0.0 => &g[..1],
        g => g,
    };
    let span = Span { d, e, lo, hi };
    let (may, sure) = (|i| span.may(i), |i| span.sure(i));
    // Each subsequence of the exact roots the answer may stand for.
    let n = roots.len();
    let mut first_bad = None;
    for mask in 0u32..(1 << n) {
        let pick: Vec<usize> = (0..n).filter(|i| mask >> i & 1 == 1).collect();
        let picked = |i: usize| mask >> i & 1 == 1;
        if pick.len() != g.len() || (0..n).any(|i| if picked(i) { !may(i) } else { sure(i) }) {
            continue;
        }
        let judged: Vec<RootJudged> = pick
            .iter()
            .zip(g)
            .map(|(&i, &t)| RootJudged::new(d, e, i, roots[i], t, kappa(i)))
            .collect();
        match judged.iter().find(|r| !r.ok()) {
            None => {
                seen.extend(judged);
                return None;
            }
            Some(r) => {
                first_bad.get_or_insert(*r);
            }
        }
    }
    if in_band && g.iter().all(|&t| e.near_vertex(d, t, false)) {
        return None;
    }
    if e.alpha_small(d)
        && g.len() == 1
        && (0..n).any(|i| RootJudged::new(d, e, i, roots[i], g[0], kappa(i)).ok())
    {
        return None;
    }
    Some(match first_bad {
        Some(r) => {
            seen.push(r);
            Fault::Root(r)
        }
        None => Fault::Class,
    })
}

/// Whether `t` is in the open range `(lo, hi)`, or is an infinite end of
/// an unbounded one (a root that overflows is still a hit of a ray).
fn in_range(t: f32, lo: f32, hi: f32) -> bool {
    (lo < t || t == lo && t == f32::NEG_INFINITY) && (t < hi || t == hi && t == f32::INFINITY)
}

/// Exact roots as intervals `r ± reach` against a range of `t`.
struct Span<'a> {
    d: &'a Declared,
    e: &'a Exact,
    lo: f32,
    hi: f32,
}

impl Span<'_> {
    /// Root `i`'s interval (its reach 0 where it is infinite). Where the
    /// reach `w` is not 0, the interval also holds every float within the
    /// allowed ulps of `r`, which [`RootJudged::ok`] takes as well: above
    /// a power of two those reach past `r + w`. So an answer that matches
    /// root `i` always lies in its interval.
    fn ends(&self, i: usize) -> (f64, f64) {
        let r = self.e.roots.as_deref().unwrap_or(&[])[i];
        let k = self.e.kappa.get(i).copied().unwrap_or(f64::INFINITY);
        let w = if r.is_finite() {
            self.e.reach(self.d, r, k)
        } else {
            0.0
        };
        let (a, b) = (f64::from(r) - w, f64::from(r) + w);
        if w > 0.0 {
            // Saturates where the allowance is infinite, and so is `w`.
            let n = self.d.allowed_ulps(k).floor() as i64;
            (a.min(f64::from(step(r, -n))), b.max(f64::from(step(r, n))))
        } else {
            (a, b)
        }
    }

    /// Whether root `i` may be inside the range.
    fn may(&self, i: usize) -> bool {
        let (a, b) = self.ends(i);
        let within = |x: f64| in_range(x as f32, self.lo, self.hi);
        if a == b {
            within(a)
        } else {
            b > f64::from(self.lo) && a < f64::from(self.hi)
        }
    }

    /// Whether root `i` is surely inside the range.
    fn sure(&self, i: usize) -> bool {
        let (a, b) = self.ends(i);
        let within = |x: f64| x > f64::from(self.lo) && x < f64::from(self.hi);
        if a == b {
            in_range(a as f32, self.lo, self.hi)
        } else {
            within(a) && within(b)
        }
    }
}

/// The `t` nearest a point on the ray, `(p − o)·d / d·d`, for the band's
/// reach of a double root.
fn t_of_point(ray: &Ray, p: Vec3) -> f32 {
    let (o, d) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
    ((p.as_dvec3() - o).dot(d) / d.length_squared()) as f32
}

/// Whether `p` is the point `o + t·d` within `tol` of `t`: each component
/// within `(tol + ½ ulp(t))·|dᵢ| + 2^bits · ulp(|oᵢ| + |t dᵢ|)`.
fn point_near(d: &Declared, ray: &Ray, t: f64, tol: f64, p: Vec3) -> bool {
    let (o, dir) = (ray.origin.as_dvec3(), ray.dir.as_dvec3());
    let half = 0.5 * ulp_of(t);
    (0..3).all(|j| {
        let x = o[j] + t * dir[j];
        let scale = o[j].abs() + (t * dir[j]).abs();
        let allow = (tol + half) * dir[j].abs() + 2f64.powf(d.bits) * ulp_of(scale);
        (f64::from(p[j]) - x).abs() <= allow
    })
}

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
pub(crate) mod tests {
    use super::*;
    use glam::Vec3;

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

    /// `a² (r² + r|f|) 2⁻⁴⁴` with `a = d·d = 4`, `r = 3`, `f = o − c =
    /// (3, 4, 0)`: `16 · (9 + 15) · 2⁻⁴⁴`. (With `r = 2`, `r·r` and `r + r`
    /// agree.)
    #[cfg(feature = "sphere")]
    #[test]
    fn sphere_band_term_by_term() {
        let ray = Ray::new(Vec3::new(4.0, 4.0, 0.0), Vec3::new(0.0, 0.0, 2.0));
        let s = Sphere::new(Vec3::X, 3.0);
        assert_eq!(sphere_band(&ray, &s), 384.0 * 2f64.powi(-44));
    }

    /// The sphere's double root, its κ and `a^(−3/2)` by hand: from
    /// `o = (1, 2, 3)` along `d = (2, 0, 2)` to a sphere about `(0, 0, −1)`,
    /// `f = (1, 2, 4)`, `a = 8` and `f·d = 10`, so `t* = −1.25`, and the
    /// terms are `2 + 0 + 2|1 − 5|` (x) and `6 + 2 + 2|4 − 5|` (z):
    /// `κ = 20 / (8 · 1.25)`. At `t = 1` they are `2 + 0 + 2|1 + 4|` and
    /// `6 + 2 + 2|4 + 4|`: `κ = 36 / 8`. A tangent root at 0 (the origin
    /// at the tangent point) has an infinite κ.
    #[cfg(feature = "sphere")]
    #[test]
    fn sphere_vertex_by_hand() {
        let ray = Ray::new(Vec3::new(1.0, 2.0, 3.0), Vec3::new(2.0, 0.0, 2.0));
        let s = Sphere::new(Vec3::new(0.0, 0.0, -1.0), 1.0);
        let v = sphere_vertex(&ray, &s, f64::NAN);
        assert_eq!(v, (-1.25, 2.0, 8f64.powf(-1.5)));
        assert_eq!(sphere_vertex(&ray, &s, 1.0).1, 4.5);
        let (ray, s) = (Ray::new(Vec3::X, Vec3::Z), Sphere::new(Vec3::ZERO, 1.0));
        let (_, e) = sphere(&ray, &s).unwrap();
        assert_eq!((e.roots, e.kappa), (Some(vec![0.0]), vec![f64::INFINITY]));
    }

    /// `|o − C|² − R²` and its band `2⁻⁴⁴(2Σ(|oᵢ| + |Cᵢ|)|fᵢ| + R²)` by
    /// hand: `o = (1, 2, 0)`, `C = (3, 0, 0)`, `R = 3`, `f = (−2, 2, 0)`:
    /// `8 − 9`, and `2·4·2 + 2·2·2 + 9 = 33`.
    #[cfg(feature = "sphere")]
    #[test]
    fn sphere_inside_by_hand() {
        let ray = Ray::new(Vec3::new(1.0, 2.0, 0.0), Vec3::Z);
        let s = Sphere::new(Vec3::new(3.0, 0.0, 0.0), 3.0);
        assert_eq!(sphere_inside(&ray, &s), (-1.0, 33.0 * 2f64.powi(-44)));
    }

    /// The plane's κ and bands by hand: from `o = (1, 2, 3)` along `d =
    /// (2, −1, 2)` to the plane through `a = (2, 0, 1)` with `n = (1, 2,
    /// −1)`, `d·n = 2 − 2 − 2` and `(a − o)·n = 1 − 4 + 2`, so `κ = 6/2 +
    /// 7/1`; the offset's band is `2⁻⁴⁴((2 + 1)·1 + (0 + 2)·2 + (1 + 3)·1)`
    /// and the margin's `2⁻⁴⁴ · 6`. From `a` itself the offset's ratio is
    /// `0/0`, which counts as 0; along the plane `d·n = 0` from terms that
    /// are not, an infinite κ.
    #[cfg(feature = "plane")]
    #[test]
    fn the_plane_condition_and_bands_by_hand() {
        let (o, d) = (Vec3::new(1.0, 2.0, 3.0), Vec3::new(2.0, -1.0, 2.0));
        let p = Plane::new(Vec3::new(2.0, 0.0, 1.0), Vec3::new(1.0, 2.0, -1.0));
        let ray = Ray::new(o, d);
        assert_eq!(plane_condition(&ray, &p), 10.0);
        assert_eq!(offset_band(&ray, &p), 11.0 * 2f64.powi(-44));
        assert_eq!(plane_band(&ray, &p), 6.0 * 2f64.powi(-44));
        assert_eq!(plane_condition(&Ray::new(p.point, d), &p), 3.0);
        let along = Ray::new(o, Vec3::new(2.0, -1.0, 0.0));
        assert_eq!(plane_condition(&along, &p), f64::INFINITY);
        assert!(plane_condition(&Ray::new(o, Vec3::new(f32::NAN, 0.0, 0.0)), &p).is_nan());
    }

    /// `Σ |kᵢ dⱼ dₖ|` for `k = 1..6` and `d = (2, 3, 5)`:
    /// 4 + 18 + 75 + 4·6 + 5·10 + 6·15 = 261.
    #[cfg(feature = "quadric")]
    #[test]
    fn alpha_terms_term_by_term() {
        let q = Quadric::new([1.0, 2.0, -3.0, 4.0, 5.0, -6.0, 7.0, 8.0, 9.0, 10.0]);
        let ray = Ray::new(Vec3::ONE, Vec3::new(2.0, 3.0, -5.0));
        assert_eq!(alpha_terms(&ray, &q), 261.0);
    }

    /// The sphere's margin is `α · (β² − 4αγ) / 4`: from z = −5 along
    /// (0, 0, 2) to the unit sphere, α = 4, β = −20, γ = 24, so
    /// 4 · 16 / 4 = 16. A band of 32 holds it and a band of 8 does not;
    /// no band holds nothing.
    #[cfg(feature = "sphere")]
    #[test]
    fn the_sphere_margin_against_its_band() {
        let (ray, s) = (
            Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, 2.0)),
            Sphere::new(Vec3::ZERO, 1.0),
        );
        let (_, e) = sphere(&ray, &s).unwrap();
        assert_eq!(e.margin, 16.0);
        // sphere_band = 4² · (1 + 5) · 2⁻⁴⁴ = 96 · 2⁻⁴⁴.
        let with_band = |band: f64| Declared {
            band_scale: band / (96.0 * 2f64.powi(-44)),
            ..Declared::f32(Semantics::WholeLine)
        };
        assert!(e.in_band(&with_band(32.0)));
        assert!(!e.in_band(&with_band(8.0)));
        assert!(!e.in_band(&Declared::correctly_rounded(Semantics::WholeLine)));
    }

    /// A zero margin is in any band but none where its terms can err; on
    /// small integers, or from terms that are all 0, in none.
    #[cfg(feature = "plane")]
    #[test]
    fn a_zero_margin_is_in_every_band_but_none() {
        let p = Plane::new(Vec3::ZERO, Vec3::Y);
        let (_, on) = plane(&Ray::new(Vec3::ZERO, Vec3::X), &p).unwrap();
        let (_, off) = plane(&Ray::new(Vec3::splat(0.5), Vec3::X), &p).unwrap();
        let f32 = Declared::f32(Semantics::WholeLine);
        assert_eq!((on.margin, on.small_integers), (0.0, true));
        assert!(!on.in_band(&f32));
        assert_eq!(
            (off.margin, off.band, off.small_integers),
            (0.0, 0.0, false)
        );
        assert!(!off.in_band(&f32));
        // d·n = 0.5 − 0.5: terms that can err.
        let slant = Plane::new(Vec3::ZERO, Vec3::new(1.0, -1.0, 0.0));
        let (_, cancel) = plane(&Ray::new(Vec3::splat(0.5), Vec3::splat(0.5)), &slant).unwrap();
        assert_eq!((cancel.margin, cancel.band), (0.0, 2f64.powi(-44)));
        assert!(cancel.in_band(&f32));
        assert!(!cancel.in_band(&Declared::correctly_rounded(Semantics::WholeLine)));
    }

    /// A plane's band is scaled by the declared factor, not offset by it:
    /// a ray at 30° to the plane is far outside rayoracle's own band.
    #[cfg(feature = "plane")]
    #[test]
    fn a_steep_ray_is_outside_the_plane_band() {
        let (ray, p) = (
            Ray::new(Vec3::Y, Vec3::new(1.0, -0.5, 0.0)),
            Plane::new(Vec3::ZERO, Vec3::Y),
        );
        let (_, e) = plane(&ray, &p).unwrap();
        assert!(!e.in_band(&Declared::faithful(Semantics::WholeLine)));
    }

    /// The quadric margin (here β² − 4αγ = 100 − 99.0625 = 0.9375) is
    /// judged against the band times the declared scale.
    #[cfg(feature = "quadric")]
    #[test]
    fn the_quadric_margin_against_its_band() {
        let ball = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let r = Ray::new(Vec3::new(0.0, 0.875, -5.0), Vec3::Z);
        let (_, e) = quadric(&r, &ball).unwrap();
        // Measured about the double root, the band is narrower than the
        // terms at the origin make it.
        assert_eq!(e.margin, 0.9375);
        assert!(0.0 < e.band && e.band < quadric_band(&r, &ball));
        let with_band = |band: f64| Declared {
            band_scale: band / e.band,
            ..Declared::f32(Semantics::WholeLine)
        };
        assert!(e.in_band(&with_band(2.0 * 0.9375)));
        assert!(!e.in_band(&with_band(0.5 * 0.9375)));
    }

    /// `x² − (1 − 2⁻²⁴)y² + z − 1` along `(1, 1, 1)`: α = 2⁻²⁴ against
    /// terms 2 − 2⁻²⁴, so α is small for a band scale of 2²⁰ (bound 2⁻²³ −
    /// 2⁻⁴⁸) and not for 2¹⁹ (bound 2⁻²⁴ − 2⁻⁴⁹) nor without a band; and
    /// small-integer inputs never are.
    #[cfg(feature = "quadric")]
    #[test]
    fn alpha_small_at_its_bound() {
        let q = tiny_alpha();
        let scaled = |e: i32| Declared {
            band_scale: 2f64.powi(e),
            ..Declared::f32(Semantics::WholeLine)
        };
        let (_, e) = quadric(&Ray::new(Vec3::ZERO, Vec3::ONE), &q).unwrap();
        assert!(e.alpha_small(&scaled(20)));
        assert!(!e.alpha_small(&scaled(19)));
        assert!(!e.alpha_small(&Declared::correctly_rounded(Semantics::WholeLine)));
        // The unit sphere as a quadric, from (0, 0.875, −5): α = 1.
        let ball = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let r = Ray::new(Vec3::new(0.0, 0.875, -5.0), Vec3::Z);
        assert!(!quadric(&r, &ball).unwrap().1.alpha_small(&scaled(20)));
        // x² − y² + z − 1 along (1, 1, 1): α = 0 exactly, on small integers.
        let q = Quadric::new([1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -1.0]);
        let (_, e) = quadric(&Ray::new(Vec3::ZERO, Vec3::ONE), &q).unwrap();
        assert_eq!(e.alpha, Some((0.0, 2f64.powi(-43))));
        assert!(!e.alpha_small(&scaled(20)));
    }

    /// κ at a root by hand: the unit sphere as a quadric, o = (0, 0, −5),
    /// d = z. At the origin the term sums are 1 (α), 10 (β) and 25 + 1
    /// (γ), and p'(t) = 2t − 10, so κ(4) = (48 + 120 + 78) / (2·4) = 30.75.
    /// About the double root t* = 5, p* = 0, they are 1 (α), 0 (β, g = 0)
    /// and 1 + G·5 (γ) with G = |Hd|·√1 = 2, so with s = |t − 5| = 1,
    /// κ(4) = (3 + 33) / (2·4) and κ(6) = (3 + 33) / (2·6): the lesser
    /// counts. A zero root is exact only without γ terms.
    #[cfg(feature = "quadric")]
    #[test]
    fn quadric_kappa_at_a_root_by_hand() {
        let q = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let ray = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
        let eq = quadric::exact::quadratic(&ray, &q).unwrap();
        assert_eq!(quadric_kappa_at(&ray, &q, &eq, 4.0), 4.5);
        assert_eq!(quadric_kappa_at(&ray, &q, &eq, 6.0), 3.0);
        assert_eq!(quadric(&ray, &q).unwrap().1.kappa, [4.5, 3.0]);
        assert_eq!(
            quadric_kappa_at(&ray, &q, &eq, f64::INFINITY),
            f64::INFINITY
        );
        assert_eq!(quadric_kappa_at(&ray, &q, &eq, 0.0), f64::INFINITY);
        // A cone x² + y² − z² = 0 from its apex: no γ term at all.
        let cone = Quadric::new([1.0, 1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        let apex = Ray::new(Vec3::ZERO, Vec3::new(1.0, 0.0, 2.0));
        let eq = quadric::exact::quadratic(&apex, &cone).unwrap();
        assert_eq!(quadric_kappa_at(&apex, &cone, &eq, 0.0), 0.0);
    }

    /// A quadric with every coefficient in play, by hand: `k = (3/2, −3,
    /// −3, 3/2, −3/2, −3/2, −3/2, 3/2, −5/2, 3)` from `o = (−3/2, −3, 3/2)`
    /// along `d = (5, −3, 3)` has α = −48, β = −123, γ = −16.5, whose terms
    /// sum to 150, 190.5 and 67.5. The double root is `t* = −41/32`, at
    /// `p* = (−253/32, 27/32, −75/32)`, where `g = ∇F = (−327/16, −381/32,
    /// 709/32)`, `Hd = (6, 21, −21)` and F's terms sum to `89667/512`. So
    /// the frame's β is `Σ|gᵢdᵢ| = 1635/8` and its γ is `89667/512 + (|g| +
    /// |Hd|·√(89667/512/150))·|t*d|`, with `|g|² = 537779/512` and `|t*d|²
    /// = 72283/1024`. κ at `t = 1` is the one at the origin, `(3·150 +
    /// 3·190.5 + 3·67.5) / (|2α + β|·1)`; at `t = −2` the one about the
    /// vertex, with `s = 23/32`, is less. No two factors of these sums are
    /// equal or opposite, so an operator changed in any of them changes a
    /// result.
    #[cfg(feature = "quadric")]
    #[test]
    fn the_quadric_frames_by_hand() {
        let q = Quadric::new([1.5, -3.0, -3.0, 1.5, -1.5, -1.5, -1.5, 1.5, -2.5, 3.0]);
        let ray = Ray::new(Vec3::new(-1.5, -3.0, 1.5), Vec3::new(5.0, -3.0, 3.0));
        let eq = quadric::exact::quadratic(&ray, &q).unwrap();
        let close = |x: f64, y: f64| (x - y).abs() <= 1e-14 * y.abs();
        assert_eq!(alpha_terms(&ray, &q), 150.0);
        let sums = 190.5 * 190.5 + 4.0 * 150.0 * 67.5;
        assert_eq!(quadric_band(&ray, &q), sums * 2f64.powi(-40));
        let kappa = 3.0 * (190.5 / 123.0 + 150.0 / 48.0);
        assert_eq!(quadric_vertex(&ray, &q, &eq), (-1.28125, kappa, 0.5 / 48.0));
        let v = vertex_frame(&ray, &q, &eq).unwrap();
        let f = 89667.0f64 / 512.0;
        let grad = (537779.0f64 / 512.0).sqrt() + 918f64.sqrt() * (f / 150.0).sqrt();
        let gamma = f + grad * (72283.0f64 / 1024.0).sqrt();
        assert_eq!((v.t, v.alpha, v.beta), (-1.28125, 150.0, 204.375));
        assert!(close(v.gamma, gamma), "{} {gamma}", v.gamma);
        let band = 204.375 * 204.375 * 2f64.powi(-40) + 150.0 * gamma * 2f64.powi(-42);
        assert!(close(v.band(), band), "{} {band}", v.band());
        let (_, e) = quadric(&ray, &q).unwrap();
        assert!(close(e.band, band));
        assert!(close(quadric_kappa_at(&ray, &q, &eq, 1.0), 1224.0 / 219.0));
        // About the vertex, s = |−2 − t*|, over |2α(−2) + β|·2.
        let s = 23.0 / 32.0;
        let at_vertex = (3.0 * 150.0 * s * s + 3.0 * 204.375 * s + 3.0 * gamma) / 138.0;
        let k = quadric_kappa_at(&ray, &q, &eq, -2.0);
        assert!(close(k, at_vertex), "{k} {at_vertex}");
    }

    /// Two equal roots are a tangent only where there is a band: without
    /// one they are the other class.
    #[cfg(feature = "sphere")]
    #[test]
    fn a_tangent_twice_needs_a_band() {
        let (ray, s) = (
            Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z),
            Sphere::new(Vec3::ZERO, 1.0),
        );
        let (_, e) = sphere(&ray, &s).unwrap();
        let twice = Answer::Roots(vec![5.0, 5.0]);
        assert!(judge(&Declared::faithful(Semantics::WholeLine), &e, &twice).passed());
        let cr = Declared::correctly_rounded(Semantics::WholeLine);
        assert_eq!(judge(&cr, &e, &twice).fault, Some(Fault::Class));
        assert!(!judge(&cr, &e, &twice).passed());
        assert!(judge(&cr, &e, &Answer::Roots(vec![5.0])).passed());
    }

    /// The roots compared are recorded whatever the fault: a NaN root and
    /// unsorted roots still list each pair.
    #[cfg(feature = "sphere")]
    #[test]
    fn the_roots_compared_are_recorded() {
        let (ray, s) = (
            Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z),
            Sphere::new(Vec3::ZERO, 1.0),
        );
        let (_, e) = sphere(&ray, &s).unwrap();
        let d = Declared::correctly_rounded(Semantics::WholeLine);
        let j = judge(&d, &e, &Answer::Roots(vec![6.0, 4.0]));
        assert_eq!(j.fault, Some(Fault::NotAscending));
        assert_eq!(
            j.roots.iter().map(|r| r.ulps).collect::<Vec<_>>(),
            [1 << 22, 1 << 22]
        );
        let j = judge(&d, &e, &Answer::Roots(vec![4.0, f32::NAN]));
        assert_eq!((j.fault, j.roots[1].ulps), (Some(Fault::NanRoot), u64::MAX));
        let j = judge(&d, &e, &Answer::Roots(vec![-0.0, 6.0]));
        assert!(matches!(j.fault, Some(Fault::Root(r)) if r.index == 0));
        assert_eq!(
            j.fault.unwrap().to_string(),
            format!(
                "{} ulps from the correctly rounded root, allowed 0.0 (κ = {:.3e})",
                ulps(4.0, -0.0),
                e.kappa[0]
            )
        );
        // From the surface the first root is +0: −0 is 0 ulps from it, and
        // the message says what differs.
        let (_, e) = sphere(&Ray::new(-Vec3::Z, Vec3::Z), &s).unwrap();
        let j = judge(&d, &e, &Answer::Roots(vec![-0.0, 2.0]));
        let fault = j.fault.unwrap().to_string();
        assert!(fault.starts_with("the sign of zero is not"), "{fault}");
    }

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

    /// `x² − (1 − 2⁻²⁴)y² + z − 1`, crossed along `(1, 1, 1)` from 0 with
    /// α = 2⁻²⁴.
    #[cfg(feature = "quadric")]
    pub(crate) fn tiny_alpha() -> Quadric {
        Quadric::new([
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
