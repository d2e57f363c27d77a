//! Measure a kernel, family by family, against the exact oracle: what a
//! gate run passes or fails, and the raw numbers behind it.
//!
//! A [`Report`](super::Report) answers "does my kernel keep its
//! declaration?". A survey answers "how wrong is it, and where?", which is
//! what you publish about someone else's kernel: for each family, the wrong
//! hits and wrong misses (whatever the band would forgive), the max and
//! median ulps of the hits both sides agree on, and the gate's own
//! failures under the declaration.
//!
//! Every count is in ray-caster terms, the nearest `t > 0`, whatever the
//! declared semantics (a whole-line answer is reduced to its first root
//! above 0), so kernels of either kind compare in one table.
//!
//! ```
//! use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
//! use rayoracle::{Ray, sphere::{Sphere, reference}};
//! let gate = Gate::new(Declared::faithful(Semantics::NearestPositive)).budget(16);
//! let k = |r: &Ray, s: &Sphere| Answer::nearest(reference::intersect(r, s), 0.0);
//! let survey = gate.survey_sphere(&k, &gate.cases("sphere"));
//! let far = survey.iter().find(|f| f.family == "sphere/far-tiny").unwrap();
//! assert_eq!((far.wrong_hits, far.wrong_misses, far.max_ulps), (0, 0, 0));
//! ```

use super::{Answer, Gate, PlaneKernel, QuadricKernel, SphereKernel, Verdict, verdict};
use crate::case::Case;
use crate::check::rules::{self, Exact};
use crate::ulp::ulps;
use std::fmt::Write;

/// One family's numbers.
///
/// ```
/// use rayoracle::check::gate::survey::FamilyStats;
/// let s = FamilyStats { family: "sphere/x".into(), cases: 4, hits: 2, ..Default::default() };
/// assert_eq!(s.wrong(), 0);
/// ```
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct FamilyStats {
    /// The family.
    pub family: String,
    /// Cases the oracle answered (non-finite inputs are not counted).
    pub cases: usize,
    /// Cases that fail the gate under the declaration (band and κ aware).
    pub failures: usize,
    /// The kernel reports a hit `t` where the exact nearest `t > 0` does
    /// not exist.
    pub wrong_hits: usize,
    /// The kernel reports no hit where the exact nearest `t > 0` exists.
    pub wrong_misses: usize,
    /// Other wrong answers: a NaN, lanes that disagree, "every `t`" where
    /// the exact answer is a point. (Where every `t` solves it there is no
    /// nearest hit, and any answer is counted right.)
    pub other: usize,
    /// Cases where both report a hit; the ulps are over these.
    pub hits: usize,
    /// The largest ulps between the kernel's hit and the correctly rounded
    /// exact one.
    pub max_ulps: u64,
    /// The median (the lower one of an even count) of the same.
    pub median_ulps: u64,
}

impl FamilyStats {
    /// Wrong hits, wrong misses and other wrong answers together.
    ///
    /// ```
    /// use rayoracle::check::gate::survey::FamilyStats;
    /// let s = FamilyStats { wrong_hits: 2, wrong_misses: 1, other: 1, ..Default::default() };
    /// assert_eq!(s.wrong(), 4);
    /// ```
    pub fn wrong(&self) -> usize {
        self.wrong_hits + self.wrong_misses + self.other
    }
}

/// What the oracle says for one case, reduced to a ray caster's answer.
enum Truth {
    /// The inputs are not finite: nothing to compare.
    Refused,
    /// Every `t` solves it.
    Everywhere,
    /// The nearest exact root above 0, correctly rounded.
    Nearest(Option<f32>),
}

/// The oracle's answer as the gate judged it (solved once for both).
fn truth(e: Option<&Exact>) -> Truth {
    match e {
        None => Truth::Refused,
        Some(Exact { roots: None, .. }) => Truth::Everywhere,
        Some(Exact { roots: Some(r), .. }) => Truth::Nearest(r.iter().copied().find(|&t| t > 0.0)),
    }
}

/// One case's contribution.
fn tally(stats: &mut FamilyStats, ulps_seen: &mut Vec<u64>, truth: Truth, got: &Answer) {
    let got = match got {
        Answer::Nearest(t) => Ok(*t),
        Answer::Roots(r) => Ok(r.iter().copied().find(|&t| t > 0.0 || t.is_nan())),
        Answer::Everywhere => Err(true),
        Answer::Inconsistent(_) | Answer::Point(_) => Err(false),
    };
    match (truth, got) {
        (Truth::Refused, _) => return,
        (_, Err(false)) => stats.other += 1,
        (_, Ok(Some(t))) if t.is_nan() => stats.other += 1,
        (Truth::Everywhere, _) => {}
        (Truth::Nearest(_), Err(_)) => stats.other += 1,
        (Truth::Nearest(None), Ok(None)) => {}
        (Truth::Nearest(None), Ok(Some(_))) => stats.wrong_hits += 1,
        (Truth::Nearest(Some(_)), Ok(None)) => stats.wrong_misses += 1,
        (Truth::Nearest(Some(x)), Ok(Some(g))) => {
            stats.hits += 1;
            ulps_seen.push(ulps(x, g));
        }
    }
    stats.cases += 1;
}

impl Gate {
    fn survey(
        &self,
        families: &[(String, Vec<Case>)],
        one: impl Fn(&Case) -> Option<(Truth, Answer, Verdict)>,
    ) -> Vec<FamilyStats> {
        families
            .iter()
            .map(|(family, cases)| {
                let mut s = FamilyStats {
                    family: family.clone(),
                    ..FamilyStats::default()
                };
                let mut seen = Vec::new();
                for c in cases {
                    let Some((truth, got, verdict)) = one(c) else {
                        continue;
                    };
                    let refused = matches!(truth, Truth::Refused);
                    tally(&mut s, &mut seen, truth, &got);
                    if !refused && matches!(verdict, Verdict::Fail { .. }) {
                        s.failures += 1;
                    }
                }
                seen.sort_unstable();
                s.max_ulps = seen.last().copied().unwrap_or(0);
                s.median_ulps = seen
                    .get(seen.len().saturating_sub(1) / 2)
                    .copied()
                    .unwrap_or(0);
                s
            })
            .collect()
    }

    /// Surveys a sphere kernel over `families` (usually
    /// [`Gate::cases`]`("sphere")`, perhaps with families of your own).
    pub fn survey_sphere(
        &self,
        k: &impl SphereKernel,
        families: &[(String, Vec<Case>)],
    ) -> Vec<FamilyStats> {
        self.survey(families, |c| match c {
            Case::Sphere(r, s) => {
                let got = k.intersect(r, s);
                let e = rules::sphere(r, s).map(|e| e.1);
                let v = verdict(&self.declared, e.as_ref(), &got);
                Some((truth(e.as_ref()), got, v))
            }
            _ => None,
        })
    }

    /// Surveys a plane kernel (see [`Gate::survey_sphere`]).
    ///
    /// ```
    /// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
    /// use rayoracle::{Ray, plane::Plane};
    /// let gate = Gate::new(Declared::f32(Semantics::NearestPositive)).budget(8);
    /// let never = |_: &Ray, _: &Plane| Answer::Nearest(None);
    /// let survey = gate.survey_plane(&never, &gate.cases("plane"));
    /// assert!(survey.iter().any(|f| f.wrong_misses > 0));
    /// assert!(survey.iter().all(|f| f.wrong_hits == 0 && f.hits == 0));
    /// ```
    pub fn survey_plane(
        &self,
        k: &impl PlaneKernel,
        families: &[(String, Vec<Case>)],
    ) -> Vec<FamilyStats> {
        self.survey(families, |c| match c {
            Case::Plane(r, p) => {
                let got = k.intersect(r, p);
                let e = rules::plane(r, p).map(|e| e.1);
                let v = verdict(&self.declared, e.as_ref(), &got);
                Some((truth(e.as_ref()), got, v))
            }
            _ => None,
        })
    }

    /// Surveys a quadric kernel (see [`Gate::survey_sphere`]).
    ///
    /// ```
    /// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
    /// use rayoracle::{Ray, quadric::Quadric};
    /// let gate = Gate::new(Declared::f32(Semantics::NearestPositive)).budget(8);
    /// let never = |_: &Ray, _: &Quadric| Answer::Nearest(None);
    /// let families = gate.cases("quadric");
    /// let survey = gate.survey_quadric(&never, &families);
    /// assert_eq!(survey.len(), families.len());
    /// assert!(survey.iter().any(|f| f.wrong_misses > 0));
    /// assert!(survey.iter().all(|f| f.wrong_hits == 0 && f.hits == 0));
    /// ```
    pub fn survey_quadric(
        &self,
        k: &impl QuadricKernel,
        families: &[(String, Vec<Case>)],
    ) -> Vec<FamilyStats> {
        self.survey(families, |c| match c {
            Case::Quadric(r, q) => {
                let got = k.intersect(r, q);
                let e = rules::quadric(r, q).map(|e| e.1);
                let v = verdict(&self.declared, e.as_ref(), &got);
                Some((truth(e.as_ref()), got, v))
            }
            _ => None,
        })
    }
}

/// A survey as a Markdown table, one row a family.
///
/// ```
/// use rayoracle::check::gate::survey::{FamilyStats, markdown};
/// let t = markdown(&[FamilyStats { family: "sphere/x".into(), cases: 3, wrong_hits: 1, ..Default::default() }]);
/// assert!(t.contains("| sphere/x | 3 | 0 | 1 | 0 | 0 | 0 | – | – |"));
/// ```
pub fn markdown(stats: &[FamilyStats]) -> String {
    let mut out = String::from(
        "| family | cases | gate failures | wrong hits | wrong misses | other wrong | hits compared | max ulps | median ulps |\n|---|---|---|---|---|---|---|---|---|\n",
    );
    for s in stats {
        let (max, med) = if s.hits == 0 {
            ("–".to_string(), "–".to_string())
        } else {
            (s.max_ulps.to_string(), s.median_ulps.to_string())
        };
        let _ = writeln!(
            out,
            "| {} | {} | {} | {} | {} | {} | {} | {} | {} |",
            s.family, s.cases, s.failures, s.wrong_hits, s.wrong_misses, s.other, s.hits, max, med
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Ray;
    use crate::plane::Plane;
    use crate::sphere::Sphere;
    use glam::Vec3;

    /// The truth is the nearest root strictly above 0 (a root at 0 is the
    /// origin on the surface, not a hit).
    #[test]
    fn the_truth_is_the_nearest_root_above_zero() {
        let e = Exact {
            roots: Some(vec![-1.0, 0.0, 2.0]),
            kappa: vec![1.0; 3],
            margin: 1.0,
            band: 0.0,
            alpha: None,
            small_integers: true,
            vertex: None,
            lies_on: Vec::new(),
            ray: Ray::new(Vec3::ZERO, Vec3::Z),
            inside: (1.0, 0.0),
        };
        assert!(matches!(truth(Some(&e)), Truth::Nearest(Some(2.0))));
    }

    fn counted(truth: Truth, got: Answer) -> FamilyStats {
        let mut s = FamilyStats::default();
        tally(&mut s, &mut Vec::new(), truth, &got);
        s
    }

    #[test]
    fn each_answer_lands_in_one_column() {
        let n = |t| Truth::Nearest(t);
        let s = counted(n(None), Answer::Nearest(Some(1.0)));
        assert_eq!((s.cases, s.wrong_hits, s.wrong()), (1, 1, 1));
        let s = counted(n(Some(1.0)), Answer::Nearest(None));
        assert_eq!((s.wrong_misses, s.wrong()), (1, 1));
        let s = counted(n(Some(1.0)), Answer::Nearest(Some(f32::NAN)));
        assert_eq!((s.other, s.hits), (1, 0));
        let s = counted(n(None), Answer::Roots(vec![f32::NAN]));
        assert_eq!(s.other, 1);
        let s = counted(n(Some(1.0)), Answer::Everywhere);
        assert_eq!(s.other, 1);
        let s = counted(n(None), Answer::Inconsistent("lanes".into()));
        assert_eq!(s.other, 1);
        // A whole-line answer is reduced to its first root above 0.
        let mut seen = Vec::new();
        let mut s = FamilyStats::default();
        tally(
            &mut s,
            &mut seen,
            n(Some(2.0)),
            &Answer::Roots(vec![-1.0, 0.0, 2.0]),
        );
        assert_eq!((s.hits, s.wrong(), seen), (1, 0, vec![0]));
        // Every t: any answer is right; refused inputs are not counted.
        let s = counted(Truth::Everywhere, Answer::Nearest(Some(3.0)));
        assert_eq!((s.cases, s.wrong()), (1, 0));
        let s = counted(Truth::Refused, Answer::Nearest(Some(f32::NAN)));
        assert_eq!(s, FamilyStats::default());
    }

    #[test]
    fn max_median_and_failures_per_family() {
        let gate = Gate::new(super::super::Declared::f32(
            super::super::Semantics::NearestPositive,
        ));
        let s = Sphere::new(Vec3::ZERO, 1.0);
        let rays =
            [-6.0, -5.0, -4.0, -3.0, -2.0].map(|z| Ray::new(Vec3::new(0.0, 0.0, z), Vec3::Z));
        let cases = vec![(
            "f".to_string(),
            rays.iter().map(|r| Case::Sphere(*r, s)).collect(),
        )];
        // Off by 0 to 4 ulps of the exact near root z − 1: an odd count,
        // so the median is the middle one, 2.
        let k = |r: &Ray, _: &Sphere| {
            let t: f32 = -r.origin.z - 1.0;
            let off = (-r.origin.z) as u32 - 2;
            Answer::Nearest(Some(f32::from_bits(t.to_bits() + off)))
        };
        let out = gate.survey_sphere(&k, &cases);
        assert_eq!(out.len(), 1);
        let f = &out[0];
        assert_eq!(f.family, "f");
        assert_eq!((f.cases, f.hits, f.max_ulps, f.median_ulps), (5, 5, 4, 2));
        // 2 bits allow 3 ulps, and κ ≥ 1 adds 4 more: none fails.
        assert_eq!(f.failures, 0);
        let far = |r: &Ray, _: &Sphere| Answer::Nearest(Some(-r.origin.z + 1.0));
        assert_eq!(gate.survey_sphere(&far, &cases)[0].failures, 5);
        // Other kinds are skipped, not counted.
        let plane = vec![(
            "p".to_string(),
            vec![Case::Plane(rays[0], Plane::new(Vec3::ZERO, Vec3::Z))],
        )];
        assert_eq!(gate.survey_sphere(&k, &plane)[0].cases, 0);
        let q = |_: &Ray, _: &crate::quadric::Quadric| Answer::Nearest(None);
        assert_eq!(gate.survey_quadric(&q, &cases)[0].cases, 0);
    }

    /// A kernel that never hits, surveyed over every plane and quadric
    /// family: a row per family, in order, with every case counted, wrong
    /// misses, and no hit; `wrong` sums its three columns.
    #[test]
    fn a_kernel_that_never_hits_misses_in_every_kind() {
        let gate = Gate::new(super::super::Declared::f32(
            super::super::Semantics::NearestPositive,
        ))
        .budget(8);
        let never = |_: &Ray, _: &Plane| Answer::Nearest(None);
        let never_q = |_: &Ray, _: &crate::quadric::Quadric| Answer::Nearest(None);
        let (planes, quadrics) = (gate.cases("plane"), gate.cases("quadric"));
        for (out, families) in [
            (gate.survey_plane(&never, &planes), &planes),
            (gate.survey_quadric(&never_q, &quadrics), &quadrics),
        ] {
            assert_eq!(out.len(), families.len());
            assert!(out.iter().zip(families).all(|(s, f)| s.family == f.0));
            assert!(out.iter().any(|s| s.wrong_misses > 0));
            assert!(out.iter().all(|s| s.hits == 0 && s.wrong_hits == 0));
            assert!(out.iter().map(|s| s.cases).sum::<usize>() > 0);
        }
        let s = FamilyStats {
            wrong_hits: 2,
            wrong_misses: 1,
            other: 1,
            ..Default::default()
        };
        assert_eq!(s.wrong(), 4);
    }

    /// The Markdown table: a header, and a row per family, with "–" for
    /// the ulps of a family with no hit compared.
    #[test]
    fn the_markdown_table_has_a_row_per_family() {
        let row = |hits| FamilyStats {
            family: "sphere/x".into(),
            cases: 3,
            wrong_hits: 1,
            hits,
            max_ulps: 7,
            median_ulps: 2,
            ..Default::default()
        };
        let t = markdown(&[row(0), row(2)]);
        let lines: Vec<&str> = t.lines().collect();
        assert_eq!(lines.len(), 4, "{t}");
        assert!(lines[0].starts_with("| family | cases |"));
        assert_eq!(lines[2], "| sphere/x | 3 | 0 | 1 | 0 | 0 | 0 | – | – |");
        assert_eq!(lines[3], "| sphere/x | 3 | 0 | 1 | 0 | 0 | 2 | 7 | 2 |");
    }
}
