//! One judge for every answer: the faults an answer can have, and how
//! each root is compared with the exact one.

use super::{Answer, Declared, Exact, Semantics};
use crate::Ray;
use crate::ulp::{step, ulp_of, ulps};
use glam::Vec3;
use std::fmt;

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
/// the rules in the [module docs](super).
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
pub(super) fn in_range(t: f32, lo: f32, hi: f32) -> bool {
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

#[cfg(all(test, feature = "sphere"))]
mod tests {
    use super::*;
    use crate::check::rules::sphere;
    use crate::sphere::Sphere;
    use glam::Vec3;

    /// Two equal roots are a tangent only where there is a band: without
    /// one they are the other class.
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
}
