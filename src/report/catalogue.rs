//! The catalogue of stiff and extreme cases (`fixtures/stiff/`): named
//! families of `eval` case lines, each documented with why it is stiff.

use crate::case::{Case, Kind, parse_line};
use serde::Deserialize;
use std::path::Path;

/// One family of the catalogue.
///
/// ```
/// use rayoracle::{case::Kind, report::Catalogue};
/// let c = Catalogue::builtin().unwrap();
/// let far = c.family("sphere/far-tiny").unwrap();
/// assert_eq!(far.kernel, Kind::Sphere);
/// assert!(far.well_conditioned && !far.cases.is_empty());
/// ```
#[derive(Clone, Debug)]
pub struct Family {
    /// `kernel/name`, as in the cases' `family` field.
    pub name: String,
    /// The kernel it exercises.
    pub kernel: Kind,
    /// Whether its roots are well-conditioned (judged by a fixed bit
    /// budget) or ill-conditioned (judged by a condition-aware bound).
    pub well_conditioned: bool,
    /// Why it is stiff.
    pub why: String,
    /// Its cases, in file order.
    pub cases: Vec<Case>,
}

/// The stiff catalogue: families in the order of `families.json`.
///
/// ```
/// use rayoracle::report::Catalogue;
/// let c = Catalogue::builtin().unwrap();
/// assert!(c.families.len() >= 20);
/// assert!(c.quick(8).families.iter().all(|f| f.cases.len() <= 8));
/// ```
#[derive(Clone, Debug)]
pub struct Catalogue {
    /// The families.
    pub families: Vec<Family>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct FamilyEntry {
    family: String,
    kernel: String,
    conditioning: String,
    why: String,
}

impl Catalogue {
    /// The crate's own catalogue, `fixtures/stiff/`, compiled in
    /// ([`crate::fixtures`]).
    pub fn builtin() -> Result<Catalogue, String> {
        let files = [Kind::Camera, Kind::Plane, Kind::Quadric, Kind::Sphere].map(|k| {
            let text = crate::fixtures::stiff(k);
            (format!("fixtures/stiff/{k}.jsonl"), text.to_string())
        });
        Catalogue::parse(
            "fixtures/stiff/families.json",
            crate::fixtures::STIFF_FAMILIES,
            &files,
        )
    }

    /// Loads `DIR/families.json` and every `DIR/*.jsonl` ([`Catalogue::parse`]).
    pub fn load(dir: &Path) -> Result<Catalogue, String> {
        let index = dir.join("families.json");
        let text = std::fs::read_to_string(&index)
            .map_err(|e| format!("{}: cannot read: {e}", index.display()))?;
        let mut paths: Vec<_> = std::fs::read_dir(dir)
            .map_err(|e| format!("{}: {e}", dir.display()))?
            .filter_map(|e| e.ok().map(|e| e.path()))
            .filter(|p| p.extension().is_some_and(|x| x == "jsonl"))
            .collect();
        paths.sort();
        let mut files = Vec::new();
        for file in paths {
            let text = std::fs::read_to_string(&file)
                .map_err(|e| format!("{}: cannot read: {e}", file.display()))?;
            files.push((file.display().to_string(), text));
        }
        Catalogue::parse(&index.display().to_string(), &text, &files)
    }

    /// A catalogue from the text of its index (named `index` in errors) and
    /// of its case files (name, text). Every case must parse and name a
    /// listed family of its own kind; every family must have cases. Errors
    /// name the file and line.
    ///
    /// ```
    /// use rayoracle::report::Catalogue;
    /// let index = r#"[{"family":"sphere/one","kernel":"sphere","conditioning":"well","why":"demo"}]"#;
    /// let case = r#"{"kind":"sphere","family":"sphere/one","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#;
    /// let c = Catalogue::parse("families.json", index, &[("s.jsonl".into(), case.into())]).unwrap();
    /// assert_eq!(c.families[0].cases.len(), 1);
    /// let e = Catalogue::parse("families.json", index, &[]).unwrap_err();
    /// assert_eq!(e, "families.json: family sphere/one has no cases");
    /// ```
    pub fn parse(
        index: &str,
        index_text: &str,
        files: &[(String, String)],
    ) -> Result<Catalogue, String> {
        let entries: Vec<FamilyEntry> =
            serde_json::from_str(index_text).map_err(|e| format!("{index}: {e}"))?;
        let mut families = Vec::new();
        for e in entries {
            let kernel: Kind = e.kernel.parse().map_err(|_| {
                format!("{index}: family {}: unknown kernel {}", e.family, e.kernel)
            })?;
            let well_conditioned = match e.conditioning.as_str() {
                "well" => true,
                "ill" => false,
                other => {
                    return Err(format!(
                        "{index}: family {}: conditioning \"{other}\" is neither \"well\" nor \"ill\"",
                        e.family
                    ));
                }
            };
            families.push(Family {
                name: e.family,
                kernel,
                well_conditioned,
                why: e.why,
                cases: Vec::new(),
            });
        }
        for (file, text) in files {
            for (i, line) in text.lines().enumerate() {
                if line.trim().is_empty() {
                    continue;
                }
                let at = || format!("{file}:{}", i + 1);
                let parsed = parse_line(line).map_err(|e| format!("{}: {e}", at()))?;
                let name = parsed
                    .family
                    .ok_or_else(|| format!("{}: no family", at()))?;
                let family = families
                    .iter_mut()
                    .find(|f| f.name == name)
                    .ok_or_else(|| format!("{}: family {name} is not in {index}", at()))?;
                if parsed.case.kind() != family.kernel {
                    return Err(format!(
                        "{}: a {} case in the {} family {name}",
                        at(),
                        parsed.case.kind(),
                        family.kernel
                    ));
                }
                family.cases.push(parsed.case);
            }
        }
        if let Some(f) = families.iter().find(|f| f.cases.is_empty()) {
            return Err(format!("{index}: family {} has no cases", f.name));
        }
        Ok(Catalogue { families })
    }

    /// The family of a name.
    pub fn family(&self, name: &str) -> Option<&Family> {
        self.families.iter().find(|f| f.name == name)
    }

    /// The same catalogue with at most `n` cases per family (the first
    /// ones), for `--quick`.
    pub fn quick(&self, n: usize) -> Catalogue {
        Catalogue {
            families: self
                .families
                .iter()
                .map(|f| Family {
                    cases: f.cases.iter().take(n).cloned().collect(),
                    ..f.clone()
                })
                .collect(),
        }
    }
}
