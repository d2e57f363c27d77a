//! What the crate surveys (`examples/*-gate`) share: a kernel run over
//! families of cases through rayoracle's gate, with the survey's numbers
//! per family and the first failing case of each as an `eval` line, and
//! the findings as Markdown.
//!
//! ```
//! use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
//! use rayoracle::{Ray, sphere::Sphere};
//! use survey_kit::Surveyed;
//! let gate = Gate::new(Declared::f32(Semantics::NearestPositive)).budget(8);
//! let never = |_: &Ray, _: &Sphere| Answer::Nearest(None);
//! let s = Surveyed::sphere("never", &gate, &never, &gate.cases("sphere"));
//! // On far-tiny, every case it fails is a hit it misses.
//! let (_, n) = *s.failing().iter().find(|f| f.0 == "sphere/far-tiny").unwrap();
//! let far = s.stats.iter().find(|f| f.family == "sphere/far-tiny").unwrap();
//! assert!(n > 0 && n == far.wrong_misses);
//! assert!(s.findings().contains(&format!("| sphere/far-tiny | 8 | {n} | 0 / {n} |")));
//! assert!(s.example("sphere/far-tiny").unwrap().eval_line.contains(r#""family":"sphere/far-tiny""#));
//! ```

use rayoracle::case::Case;
use rayoracle::check::gate::survey::FamilyStats;
use rayoracle::check::gate::{Failure, Gate, PlaneKernel, QuadricKernel, SphereKernel};

/// Families of cases, as [`Gate::cases`] gives them.
pub type Families = [(String, Vec<Case>)];

/// One kernel, surveyed.
#[derive(Clone, Debug)]
pub struct Surveyed {
    /// The function surveyed, as the findings name it.
    pub kernel: String,
    /// The survey's numbers, one entry a family.
    pub stats: Vec<FamilyStats>,
    /// The first failing case of each failing family, judged (not shrunk).
    pub examples: Vec<Failure>,
}

impl Surveyed {
    fn new(
        kernel: &str,
        stats: Vec<FamilyStats>,
        families: &Families,
        judge: impl Fn(&Case) -> Option<Failure>,
    ) -> Surveyed {
        let examples = families
            .iter()
            .filter_map(|(family, cases)| {
                let mut f = cases.iter().find_map(&judge)?;
                let named = format!("\"family\":{family:?}");
                f.eval_line = f.eval_line.replace("\"family\":\"single case\"", &named);
                f.family = family.clone();
                Some(f)
            })
            .collect();
        Surveyed {
            kernel: kernel.to_string(),
            stats,
            examples,
        }
    }

    /// Surveys a sphere kernel on `families`.
    pub fn sphere(
        kernel: &str,
        gate: &Gate,
        k: &impl SphereKernel,
        families: &Families,
    ) -> Surveyed {
        let stats = gate.survey_sphere(k, families);
        Surveyed::new(kernel, stats, families, |c| match c {
            Case::Sphere(r, s) => gate.judge_sphere(r, s, k.intersect(r, s)).err(),
            _ => None,
        })
    }

    /// Surveys a plane kernel on `families`.
    pub fn plane(kernel: &str, gate: &Gate, k: &impl PlaneKernel, families: &Families) -> Surveyed {
        let stats = gate.survey_plane(k, families);
        Surveyed::new(kernel, stats, families, |c| match c {
            Case::Plane(r, p) => gate.judge_plane(r, p, k.intersect(r, p)).err(),
            _ => None,
        })
    }

    /// Surveys a quadric kernel on `families`.
    pub fn quadric(
        kernel: &str,
        gate: &Gate,
        k: &impl QuadricKernel,
        families: &Families,
    ) -> Surveyed {
        let stats = gate.survey_quadric(k, families);
        Surveyed::new(kernel, stats, families, |c| match c {
            Case::Quadric(r, q) => gate.judge_quadric(r, q, k.intersect(r, q)).err(),
            _ => None,
        })
    }

    /// The families that fail the gate, with their failure counts.
    pub fn failing(&self) -> Vec<(&str, usize)> {
        self.stats
            .iter()
            .filter(|f| f.failures > 0)
            .map(|f| (f.family.as_str(), f.failures))
            .collect()
    }

    /// The numbers of `family`.
    ///
    /// # Panics
    ///
    /// If `family` was not surveyed.
    pub fn family(&self, family: &str) -> &FamilyStats {
        let f = self.stats.iter().find(|f| f.family == family);
        f.unwrap_or_else(|| panic!("{family} not surveyed"))
    }

    /// The first failure of `family`, if it fails.
    pub fn example(&self, family: &str) -> Option<&Failure> {
        self.examples.iter().find(|f| f.family == family)
    }

    /// The findings as Markdown: a heading, then one row a failing family
    /// (cases, gate failures, wrong hits and misses, max ulps, and the
    /// first failure's `eval` line with the expected and actual answers).
    pub fn findings(&self) -> String {
        let mut out = format!(
            "### {}\n\n{} of {} families fail.\n\n",
            self.kernel,
            self.failing().len(),
            self.stats.len()
        );
        if self.failing().is_empty() {
            return out;
        }
        out += "| family | cases | gate failures | wrong hits / misses | max ulps | first failure |\n|---|---|---|---|---|---|\n";
        for s in self.stats.iter().filter(|s| s.failures > 0) {
            let ex = self.example(&s.family).map_or(String::new(), |f| {
                format!("`{}` expected {}, got {}", f.eval_line, f.expected, f.got)
            });
            out += &format!(
                "| {} | {} | {} | {} / {} | {} | {} |\n",
                s.family,
                s.cases,
                s.failures,
                s.wrong_hits,
                s.wrong_misses,
                if s.hits == 0 {
                    "–".to_string()
                } else {
                    s.max_ulps.to_string()
                },
                ex
            );
        }
        out
    }
}

/// The surveyed kernel named `kernel` in `list`.
///
/// # Panics
///
/// If there is none.
pub fn named<'a>(list: &'a [Surveyed], kernel: &str) -> &'a Surveyed {
    let k = list.iter().find(|s| s.kernel == kernel);
    k.unwrap_or_else(|| panic!("{kernel} not surveyed"))
}

/// The surveyed kernels whose [`Surveyed::findings`] are not in `doc`
/// word for word (for a test that the published tables are current).
///
/// ```
/// use survey_kit::{Surveyed, missing_from};
/// let s = Surveyed { kernel: "k".into(), stats: vec![], examples: vec![] };
/// assert_eq!(missing_from(std::slice::from_ref(&s), &s.findings()), Vec::<&str>::new());
/// assert_eq!(missing_from(&[s], "nothing"), ["k"]);
/// ```
pub fn missing_from<'a>(list: &'a [Surveyed], doc: &str) -> Vec<&'a str> {
    list.iter()
        .filter(|s| !doc.contains(s.findings().trim()))
        .map(|s| s.kernel.as_str())
        .collect()
}

/// In a survey's tests: `all()`, the survey run once; `surveyed(kernel)`,
/// one kernel of it; and the test that docs/crate-surveys.md shows its
/// findings word for word.
#[macro_export]
macro_rules! survey_tests {
    ($survey:path) => {
        fn all() -> &'static [$crate::Surveyed] {
            static S: std::sync::OnceLock<Vec<$crate::Surveyed>> = std::sync::OnceLock::new();
            S.get_or_init($survey)
        }

        fn surveyed(kernel: &str) -> &'static $crate::Surveyed {
            $crate::named(all(), kernel)
        }

        #[test]
        fn the_published_tables_are_current() {
            let doc = include_str!(concat!(
                env!("CARGO_MANIFEST_DIR"),
                "/../../docs/crate-surveys.md"
            ));
            assert_eq!($crate::missing_from(all(), doc), Vec::<&str>::new());
        }
    };
}

/// A random unit vector, uniform on the sphere (by rejection from the
/// cube), for a survey's own families.
///
/// ```
/// use rand::SeedableRng;
/// let d = survey_kit::random_unit(&mut rand::rngs::SmallRng::seed_from_u64(1));
/// assert!((d.length() - 1.0).abs() < 1e-6);
/// ```
pub fn random_unit(rng: &mut impl rand::Rng) -> glam::Vec3 {
    loop {
        let p = glam::Vec3::new(
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
            rng.random_range(-1.0..1.0),
        );
        let l = p.length();
        if l > 0.1 && l <= 1.0 {
            return p / l;
        }
    }
}
