//! The exact answer of a case and the scales its tolerances are measured
//! in: the condition numbers, the classification margins and their bands.

use super::judge::{in_range, root_within};
use super::{Answer, Declared, Semantics};
use crate::Ray;
#[cfg(feature = "plane")]
use crate::exact::dyadic::{dot, sub3, vec3};
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use crate::hit::Intersection;
#[cfg(feature = "plane")]
use crate::plane::{self, Plane, PlaneHit};
#[cfg(feature = "quadric")]
use crate::quadric::{self, Quadric, QuadricHit};
#[cfg(feature = "sphere")]
use crate::sphere::{self, Sphere, SphereHit};
use crate::ulp::ulp_of;
#[cfg(any(feature = "sphere", feature = "quadric"))]
use glam::Vec3;

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
    pub(super) fn may_err(&self, d: &Declared, unit: f64) -> bool {
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
    pub(super) fn near_vertex(&self, d: &Declared, t: f32, below: bool) -> bool {
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

#[cfg(all(test, any(feature = "plane", feature = "sphere", feature = "quadric")))]
mod tests {
    use super::*;
    #[cfg(feature = "quadric")]
    use crate::check::rules::tests::tiny_alpha;
    use glam::Vec3;

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
}
