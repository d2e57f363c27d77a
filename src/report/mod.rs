//! `rayoracle report`: error against run time, for every kernel × variant ×
//! family of the stiff catalogue (`fixtures/stiff/`).
//!
//! For each family and each [`Variant`] the report gives:
//!
//! * **bits of error** against the exact oracle, `log₂(ulps + 1)` of the
//!   worst root (camera: component, in ulps of its scale `Sᵢ`, see
//!   [`case_error`]) of each case, over the cases whose class matches:
//!   the maximum, the 99th percentile and the mean;
//! * **class mismatches**: cases classified differently from the oracle
//!   (the reference and x4 have none, [`crate::check`]);
//! * **stages**: for the reference and x4, the share of the cases each
//!   [`Stage`](crate::stage::Stage) decided (the filter, f64 arithmetic
//!   proven exact, or exact arithmetic on integers);
//! * **ns per ray**: the median over repeated passes of the time per case
//!   of one pass, one `black_box`ed call per case (per packet of four for
//!   x4), a primitive's through its
//!   [`Primitive`](crate::primitive::Primitive) method, which starts with
//!   fresh registers; one core. The variants of a family are timed together, their
//!   passes interleaved, so that they meet the same load from the rest of
//!   the machine. A camera case is timed for its ray: its camera is built
//!   before the clock starts (but for the exact oracle's, which builds its
//!   own).
//!
//! Each kernel also gets a point per variant on an error-against-time plane
//! ([`Point`]): time is the mean of the family medians; error is the worst
//! maximum over *every* family, well- or ill-conditioned, a misclassified
//! case counting as 32 bits (the whole value lost). The Pareto front is the
//! set of variants no other variant beats on both. A variant that is
//! correctly rounded only where the data are well conditioned (the plain
//! f64 one) is fast but misclassifies somewhere, so it does not dominate
//! the correctly rounded kernels.

mod catalogue;
mod error;
mod variant;

pub use catalogue::{Catalogue, Family};
pub use error::{CaseError, case_error};
pub use variant::Variant;

use crate::case::Kind;
use serde::Serialize;
use variant::Batch;

/// Every kernel, in report order.
///
/// ```
/// use rayoracle::{case::Kind, report::KERNELS};
/// assert_eq!(KERNELS, [Kind::Sphere, Kind::Plane, Kind::Quadric, Kind::Camera]);
/// ```
pub const KERNELS: [Kind; 4] = [Kind::Sphere, Kind::Plane, Kind::Quadric, Kind::Camera];

/// One kernel × variant × family line of the report (also its JSON form).
///
/// ```
/// use rayoracle::{case::Kind, report::{Row, Variant}};
/// let r = Row { kernel: Kind::Sphere, variant: Variant::X4, family: "sphere/far-tiny".into(),
///     conditioning: "well".into(), cases: 4, max_bits: 1.0, p99_bits: 1.0, mean_bits: 0.25,
///     class_mismatches: 0, ns_per_ray: 20.0, stages: [("filter".into(), 0.75), ("exact".into(), 0.25)].into(),
///     front: true };
/// let json = serde_json::to_string(&r).unwrap();
/// assert!(json.starts_with(r#"{"kernel":"sphere","variant":"x4""#));
/// assert!(json.ends_with(r#""stages":{"exact":0.25,"filter":0.75},"front":true}"#));
/// ```
#[derive(Clone, Debug, PartialEq, Serialize)]
pub struct Row {
    /// The kernel (its name in JSON).
    pub kernel: Kind,
    /// The variant ([`Variant::name`] in JSON).
    pub variant: Variant,
    /// The family, `kernel/name`.
    pub family: String,
    /// `well` or `ill`, as the catalogue says of the family.
    pub conditioning: String,
    /// Cases in the family.
    pub cases: usize,
    /// Worst bits of error over the cases whose class matches.
    pub max_bits: f64,
    /// 99th percentile of the same.
    pub p99_bits: f64,
    /// Mean of the same.
    pub mean_bits: f64,
    /// Cases classified differently from the oracle.
    pub class_mismatches: usize,
    /// Median time per case, in nanoseconds.
    pub ns_per_ray: f64,
    /// For the staged variants (reference, x4): the share of the cases each
    /// stage decided, by [`Stage::name`](crate::stage::Stage::name); empty
    /// for the others.
    pub stages: std::collections::BTreeMap<String, f64>,
    /// The variant is on its kernel's Pareto front ([`points`]).
    pub front: bool,
}

/// How much to run.
///
/// ```
/// use rayoracle::report::Options;
/// assert!(Options::QUICK.cases_per_family < Options::FULL.cases_per_family);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Options {
    /// At most this many cases of each family (the first ones).
    pub cases_per_family: usize,
    /// Timed passes per family and variant; the median is reported.
    pub passes: usize,
}

impl Options {
    /// `--quick`: 64 cases per family, 7 passes.
    pub const QUICK: Options = Options {
        cases_per_family: 64,
        passes: 7,
    };
    /// The default: every case, 21 passes.
    pub const FULL: Options = Options {
        cases_per_family: usize::MAX,
        passes: 21,
    };
}

/// The accuracy half of a row: every case of `family` under `variant`,
/// against the oracle. No timing; the tests use this directly.
///
/// ```
/// use rayoracle::report::{Catalogue, Variant, accuracy};
/// let c = Catalogue::builtin().unwrap().quick(16);
/// let row = accuracy(c.family("sphere/far-tiny").unwrap(), Variant::Reference);
/// assert_eq!((row.cases, row.class_mismatches), (16, 0));
/// assert!(row.max_bits <= 1.0);
/// // The textbook formulas in plain f32 misclassify most far, tiny spheres.
/// let all = Catalogue::builtin().unwrap();
/// let row = accuracy(all.family("sphere/far-tiny").unwrap(), Variant::Textbook);
/// assert_eq!((row.cases, row.class_mismatches), (256, 154));
/// ```
pub fn accuracy(family: &Family, variant: Variant) -> Row {
    let batch = Batch::new(family.kernel, &family.cases);
    let exact = variant::outcomes(Variant::Exact, &batch);
    accuracy_against(family, variant, &batch, &exact)
}

/// The 99th percentile of ascending `bits` by nearest rank (the
/// ⌈0.99·n⌉-th value), 0 for none.
fn p99(bits: &[f64]) -> f64 {
    if bits.is_empty() {
        0.0
    } else {
        bits[(bits.len() * 99).div_ceil(100).max(1) - 1]
    }
}

/// [`accuracy`] given the family's batch and the oracle's outcomes, which
/// [`run`] computes once per family rather than once per variant.
fn accuracy_against(
    family: &Family,
    variant: Variant,
    batch: &Batch,
    exact: &[crate::eval::Outcome],
) -> Row {
    let got = variant::outcomes(variant, batch);
    let mut bits = Vec::new();
    let mut mismatches = 0;
    for ((case, e), g) in family.cases.iter().zip(exact).zip(&got) {
        match case_error(case, e, g) {
            CaseError::NotCompared => {}
            CaseError::Mismatch => mismatches += 1,
            CaseError::Bits(b) => bits.push(b),
        }
    }
    bits.sort_by(f64::total_cmp);
    let max = bits.last().copied().unwrap_or(0.0);
    let p99 = p99(&bits);
    let mean = if bits.is_empty() {
        0.0
    } else {
        bits.iter().sum::<f64>() / bits.len() as f64
    };
    Row {
        kernel: family.kernel,
        variant,
        family: family.name.clone(),
        conditioning: if family.well_conditioned {
            "well"
        } else {
            "ill"
        }
        .into(),
        cases: family.cases.len(),
        max_bits: max,
        p99_bits: p99,
        mean_bits: mean,
        class_mismatches: mismatches,
        ns_per_ray: f64::NAN,
        stages: match variant {
            Variant::Reference | Variant::X4 => stage_shares(&family.cases),
            _ => Default::default(),
        },
        front: false,
    }
}

/// The share of `cases` each stage decides (the same for the reference and
/// x4, which run the same filter); empty for cameras, which have no stages.
///
/// ```
/// use rayoracle::report::{Catalogue, stage_shares};
/// let c = Catalogue::builtin().unwrap();
/// // No exact tangent is decided by the filter: it cannot tell a tangent
/// // from a near miss. Small integers keep the tracked stage exact.
/// let s = stage_shares(&c.family("sphere/exact-tangent").unwrap().cases);
/// assert_eq!(s["filter"], 0.0);
/// assert!(s["tracked"] > 0.5);
/// assert_eq!(s.values().sum::<f64>(), 1.0);
/// ```
pub fn stage_shares(cases: &[crate::case::Case]) -> std::collections::BTreeMap<String, f64> {
    use crate::case::match_case;
    use crate::primitive::Primitive;
    use crate::stage::Stage;
    let mut counts = [0usize; Stage::ALL.len()];
    let mut n = 0;
    for case in cases {
        let stage = match_case!(case, |r, p| Primitive::staged(r, p).1, |_, _| continue);
        counts[Stage::ALL
            .iter()
            .position(|s| *s == stage)
            .expect("a stage")] += 1;
        n += 1;
    }
    if n == 0 {
        return Default::default();
    }
    Stage::ALL
        .iter()
        .zip(counts)
        .map(|(s, c)| (s.name().to_string(), c as f64 / n as f64))
        .collect()
}

/// Marks each row whose variant is on its kernel's Pareto front.
pub fn mark_front(rows: &mut [Row]) {
    for kernel in KERNELS {
        let front: Vec<String> = points(rows, kernel)
            .into_iter()
            .filter(|p| p.front)
            .map(|p| p.variant)
            .collect();
        for r in rows.iter_mut().filter(|r| r.kernel == kernel) {
            r.front = front.iter().any(|v| v == r.variant.name());
        }
    }
}

/// The median time per ray of `passes` timed passes of `variant` over
/// `family`, timed alone ([`run`] interleaves a family's variants). Each
/// pass repeats the family's cases enough times to last about 0.2 ms
/// (calibrated by one untimed pass), so that the clock's resolution and
/// the call overhead of the timer do not show.
pub fn time_per_case(family: &Family, variant: Variant, passes: usize) -> f64 {
    let batch = Batch::new(family.kernel, &family.cases);
    median_pass(passes, |reps| variant::time_pass(variant, &batch, reps))
}

/// The median nanoseconds per ray of `passes` calls of `pass(reps)`
/// (at least one), `reps` chosen from one untimed call of `pass(1)` so that
/// a pass lasts about 2·10⁵ ns (1 to 10,000 repetitions). `pass` is a
/// parameter so that a test can give it a fake clock.
fn median_pass(passes: usize, mut pass: impl FnMut(usize) -> variant::Timed) -> f64 {
    median_passes(passes, 1, |_, reps| pass(reps))[0]
}

/// [`median_pass`] for `n` timed things at once, `pass(i, reps)` timing
/// the `i`-th: each calibrated first, then their passes interleaved (pass
/// 1 of each in turn, then pass 2…), so that each meets the load of the
/// rest of the machine at the same moments as the others, and their ratios
/// do not depend on when it changed.
fn median_passes(
    passes: usize,
    n: usize,
    mut pass: impl FnMut(usize, usize) -> variant::Timed,
) -> Vec<f64> {
    let reps: Vec<usize> = (0..n)
        .map(|i| {
            let once = pass(i, 1).nanos;
            ((2e5 / once.max(1.0)).ceil() as usize).clamp(1, 10_000)
        })
        .collect();
    let mut t = vec![Vec::new(); n];
    for _ in 0..passes.max(1) {
        for (i, t) in t.iter_mut().enumerate() {
            t.push(pass(i, reps[i]).ns_per_ray());
        }
    }
    t.into_iter()
        .map(|mut t| {
            t.sort_by(f64::total_cmp);
            t[t.len() / 2]
        })
        .collect()
}

/// The whole report: for every family (in catalogue order) every variant,
/// accuracy and time. `on_step` is called after each family × variant.
pub fn run(catalogue: &Catalogue, options: Options, on_step: &mut dyn FnMut()) -> Vec<Row> {
    let catalogue = catalogue.quick(options.cases_per_family);
    let mut rows = Vec::new();
    for family in &catalogue.families {
        let batch = Batch::new(family.kernel, &family.cases);
        let exact = variant::outcomes(Variant::Exact, &batch);
        // The variants of a family timed together, their passes
        // interleaved, so that their ratios hold under a changing load.
        let ns = median_passes(options.passes, Variant::ALL.len(), |i, reps| {
            variant::time_pass(Variant::ALL[i], &batch, reps)
        });
        for (variant, ns) in Variant::ALL.into_iter().zip(ns) {
            let mut row = accuracy_against(family, variant, &batch, &exact);
            row.ns_per_ray = ns;
            rows.push(row);
            on_step();
        }
    }
    mark_front(&mut rows);
    rows
}

/// One variant of one kernel on the error-against-time plane.
///
/// ```
/// use rayoracle::report::{Point, pareto};
/// let p = |v: &str, ns, bits| Point { variant: v.into(), ns_per_ray: ns, error_bits: bits, mismatches: 0, front: false };
/// // e ties b on time and f ties it on error: b beats both.
/// let pts = pareto(vec![p("a", 1.0, 20.0), p("b", 5.0, 1.0), p("c", 6.0, 2.0), p("d", 50.0, 0.0),
///     p("e", 5.0, 3.0), p("f", 7.0, 1.0)]);
/// let front: Vec<_> = pts.iter().filter(|p| p.front).map(|p| p.variant.as_str()).collect();
/// assert_eq!(front, vec!["a", "b", "d"]);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Point {
    /// The variant.
    pub variant: String,
    /// Mean over the families of the median time per case.
    pub ns_per_ray: f64,
    /// Worst maximum over every family; a family with a misclassified
    /// case counts 32.
    pub error_bits: f64,
    /// Misclassified cases over every family.
    pub mismatches: usize,
    /// On the Pareto front: no other point is at least as good on both
    /// axes and better on one.
    pub front: bool,
}

/// Marks the Pareto front of `points`.
pub fn pareto(mut points: Vec<Point>) -> Vec<Point> {
    let all = points.clone();
    for p in &mut points {
        p.front = !all.iter().any(|q| {
            q.ns_per_ray <= p.ns_per_ray
                && q.error_bits <= p.error_bits
                && (q.ns_per_ray < p.ns_per_ray || q.error_bits < p.error_bits)
        });
    }
    points
}

/// The points of one kernel, front marked.
pub fn points(rows: &[Row], kernel: Kind) -> Vec<Point> {
    let pts = Variant::ALL
        .into_iter()
        .filter_map(|v| {
            let mine: Vec<&Row> = rows
                .iter()
                .filter(|r| r.kernel == kernel && r.variant == v)
                .collect();
            if mine.is_empty() {
                return None;
            }
            let ns = mine.iter().map(|r| r.ns_per_ray).sum::<f64>() / mine.len() as f64;
            let error_bits = mine
                .iter()
                .map(|r| {
                    if r.class_mismatches > 0 {
                        32.0
                    } else {
                        r.max_bits
                    }
                })
                .fold(0.0, f64::max);
            Some(Point {
                variant: v.name().into(),
                ns_per_ray: ns,
                error_bits,
                mismatches: mine.iter().map(|r| r.class_mismatches).sum(),
                front: false,
            })
        })
        .collect();
    pareto(pts)
}

/// The rows as a Markdown table, one section per kernel, with the Pareto
/// points of each kernel under it.
pub fn markdown(rows: &[Row], catalogue: &Catalogue) -> String {
    let mut out = String::new();
    for kernel in KERNELS {
        let mine: Vec<&Row> = rows.iter().filter(|r| r.kernel == kernel).collect();
        if mine.is_empty() {
            continue;
        }
        out += &format!("### {kernel}\n\n");
        let names: Vec<&str> = crate::stage::Stage::ALL.iter().map(|s| s.name()).collect();
        out += &format!(
            "| family | cond. | variant | cases | max bits | p99 bits | mean bits | class mismatches | {} | ns/ray |\n",
            names.join(" / ")
        );
        out += "|---|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
        for r in mine {
            let cond = match catalogue.family(&r.family) {
                Some(f) if f.well_conditioned => "well",
                Some(_) => "ill",
                None => "?",
            };
            let stages = if r.stages.is_empty() {
                "–".into()
            } else {
                let pc = |k: &str| r.stages.get(k).map_or(0.0, |x| x * 100.0);
                let shares: Vec<String> = names.iter().map(|k| format!("{:.0}%", pc(k))).collect();
                shares.join(" / ")
            };
            out += &format!(
                "| {} | {cond} | {} | {} | {:.2} | {:.2} | {:.3} | {} | {stages} | {:.1} |\n",
                r.family,
                r.variant,
                r.cases,
                r.max_bits,
                r.p99_bits,
                r.mean_bits,
                r.class_mismatches,
                r.ns_per_ray
            );
        }
        out += "\nError against time (every family; ★ = Pareto front):\n\n";
        out += "| variant | ns/ray (mean) | worst max bits | mismatches | front |\n|---|---:|---:|---:|---|\n";
        for p in points(rows, kernel) {
            out += &format!(
                "| {} | {:.1} | {:.2} | {} | {} |\n",
                p.variant,
                p.ns_per_ray,
                p.error_bits,
                p.mismatches,
                if p.front { "★" } else { "" }
            );
        }
        out += "\n";
    }
    out
}

#[cfg(test)]
mod tests {
    use super::variant::Timed;
    use super::{Catalogue, Row, Variant, markdown, median_pass, points};
    use crate::case::Kind;

    /// The calibration pass sets the repetitions (2·10⁵ ns over a pass of
    /// 10³ ns: 200; capped at 10⁴ for a pass too fast to see, at least 1
    /// for a slow one), and the median of four passes is the upper middle
    /// one.
    #[test]
    fn the_time_is_the_median_of_calibrated_passes() {
        let fake = |once: f64| {
            let (mut calls, mut reps_seen) = (0, Vec::new());
            let ns = median_pass(4, |reps| {
                calls += 1;
                reps_seen.push(reps);
                let nanos = if calls == 1 {
                    once
                } else {
                    [50.0, 10.0, 30.0, 70.0][calls - 2] * reps as f64
                };
                Timed {
                    nanos,
                    rays: reps as f64,
                }
            });
            (ns, reps_seen)
        };
        assert_eq!(fake(1e3), (50.0, vec![1, 200, 200, 200, 200]));
        assert_eq!(fake(0.0).1[1], 10_000);
        assert_eq!(fake(1e9).1[1], 1);
        assert_eq!(
            median_pass(0, |r| Timed {
                nanos: 6.0 * r as f64,
                rays: 2.0 * r as f64
            }),
            3.0
        );
    }

    /// Several timed things: each calibrated on its own, then their
    /// passes in turn, one of each per round; each its own median.
    #[test]
    fn the_passes_of_several_are_interleaved() {
        let mut calls = Vec::new();
        let ns = super::median_passes(3, 2, |i, reps| {
            calls.push((i, reps));
            // A machine slowing by 1% a call, after the calibration.
            let slow = if reps == 1 {
                1.0
            } else {
                1.0 + calls.len() as f64 / 100.0
            };
            Timed {
                nanos: [1e3, 4e4][i] * reps as f64 * slow,
                rays: reps as f64,
            }
        });
        assert_eq!(
            calls,
            [
                (0, 1),
                (1, 1),
                (0, 200),
                (1, 5),
                (0, 200),
                (1, 5),
                (0, 200),
                (1, 5)
            ]
        );
        // Calls 5 and 6 are each one's middle pass.
        assert!((ns[0] - 1050.0).abs() < 1e-9 && (ns[1] - 42_400.0).abs() < 1e-9);
    }

    fn row(kernel: &str, variant: &str, family: &str, ns: f64, mismatches: usize) -> Row {
        Row {
            kernel: kernel.parse().unwrap(),
            variant: Variant::parse(variant).unwrap(),
            family: family.into(),
            conditioning: "well".into(),
            cases: 4,
            max_bits: 1.0,
            p99_bits: 1.0,
            mean_bits: 1.0,
            class_mismatches: mismatches,
            ns_per_ray: ns,
            stages: Default::default(),
            front: false,
        }
    }

    fn rows() -> Vec<Row> {
        vec![
            row("sphere", "reference", "sphere/far-tiny", 10.0, 0),
            row("sphere", "reference", "sphere/huge-near", 20.0, 0),
            row("sphere", "x4", "sphere/far-tiny", 4.0, 1),
            row("sphere", "x4", "sphere/huge-near", 2.0, 0),
            row("plane", "reference", "plane/far", 1000.0, 0),
        ]
    }

    /// A kernel's points average its own rows only, variant by variant;
    /// a misclassified case counts 32 bits.
    #[test]
    fn points_take_only_their_kernel_and_variant() {
        let pts = points(&rows(), Kind::Sphere);
        let got: Vec<(&str, f64, f64, usize)> = pts
            .iter()
            .map(|p| (p.variant.as_str(), p.ns_per_ray, p.error_bits, p.mismatches))
            .collect();
        assert_eq!(got, [("reference", 15.0, 1.0, 0), ("x4", 3.0, 32.0, 1)]);
    }

    /// A misclassified case in an ill-conditioned family counts as well:
    /// a variant exact only on easy data does not dominate one exact on
    /// all of it, however fast.
    #[test]
    fn ill_conditioned_families_count_on_the_front() {
        let mut rs = rows();
        rs.push(row("sphere", "f64", "sphere/far-tiny", 1.0, 0));
        rs.push(row("sphere", "f64", "sphere/huge-near", 1.0, 3));
        rs[2].class_mismatches = 0;
        let pts = points(&rs, Kind::Sphere);
        let got: Vec<(&str, f64, usize, bool)> = pts
            .iter()
            .map(|p| (p.variant.as_str(), p.error_bits, p.mismatches, p.front))
            .collect();
        assert_eq!(
            got,
            [
                ("reference", 1.0, 0, false),
                ("x4", 1.0, 0, true),
                ("f64", 32.0, 3, true)
            ]
        );
    }

    /// Each row carries its variant's place on its own kernel's front:
    /// x4 is faster and the reference more accurate, so both are on the
    /// sphere's; the plane's one variant is on its own.
    #[test]
    fn rows_carry_their_front_flag() {
        let mut rs = rows();
        rs.push(row("sphere", "textbook", "sphere/far-tiny", 30.0, 1));
        super::mark_front(&mut rs);
        let front: Vec<(&str, &str, bool)> = rs
            .iter()
            .map(|r| (r.kernel.as_str(), r.variant.name(), r.front))
            .collect();
        assert_eq!(
            front,
            [
                ("sphere", "reference", true),
                ("sphere", "reference", true),
                ("sphere", "x4", true),
                ("sphere", "x4", true),
                ("plane", "reference", true),
                ("sphere", "textbook", false),
            ]
        );
    }

    /// One section per kernel, each row with its family's conditioning.
    #[test]
    fn markdown_sections_per_kernel_with_conditioning() {
        let c = Catalogue::builtin().unwrap();
        let md = markdown(&rows(), &c);
        let (sphere, plane) = md.split_once("### plane").unwrap();
        assert!(sphere.starts_with("### sphere"));
        assert!(sphere.contains("| sphere/far-tiny | well | reference | 4 |"));
        assert!(sphere.contains("| sphere/huge-near | ill | x4 | 4 |"));
        assert!(!sphere.contains("plane/far"));
        assert!(plane.contains("| plane/far | well | reference |"));
    }

    /// ⌈0.99·200⌉ = 198th of 1..=200, ⌈0.99·1⌉ = 1st of one.
    #[test]
    fn p99_is_the_nearest_rank() {
        let bits: Vec<f64> = (1..=200).map(f64::from).collect();
        assert_eq!(super::p99(&bits), 198.0);
        assert_eq!(super::p99(&[7.0]), 7.0);
        assert_eq!(super::p99(&[]), 0.0);
    }
}
