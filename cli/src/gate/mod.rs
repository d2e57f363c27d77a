//! `rayoracle cases`, `judge` and `gate -- PROGRAM`: the gate for kernels
//! in any language, over the line protocol of
//! `rayoracle::check::gate::protocol` (docs/protocol.md).

mod answer;
mod program;

pub use answer::answer_command;
use clap::Args;
use program::Program;
use rayoracle::case::{Case, Kind};
use rayoracle::check::gate::protocol::{answer_id, case_line, read_answer};
use rayoracle::check::gate::{CaseKernel, Declared, Gate, Reply, Report, Semantics};
use std::collections::HashMap;
use std::io::{self, BufWriter, Write};
use std::path::PathBuf;
use std::time::Duration;

/// Which cases: the kind, the families, the budget, the seed.
#[derive(Args, Debug, Clone)]
pub struct Selection {
    /// plane, sphere, quadric or camera.
    #[arg(long, value_parser = parse_kind)]
    pub kind: Kind,
    /// Only this family, or the families under it (`sphere/random` takes
    /// `sphere/random/aimed`); repeat for more. Default: every family.
    #[arg(long = "family", value_name = "NAME")]
    pub families: Vec<String>,
    /// At most this many cases a family.
    #[arg(long, default_value_t = 256)]
    pub budget: usize,
    /// The random families' seed.
    #[arg(long)]
    pub seed: Option<u64>,
}

/// What the kernel promises.
#[derive(Args, Debug, Clone)]
pub struct Declaration {
    /// What the kernel computes: nearest (the nearest t > 0), whole-line
    /// (every root), solid (t = 0 from inside), range:T0:T1 (the nearest
    /// root in the open range), roots-in:T0:T1 (every root in it). A
    /// nearest hit is answered {"t": …} or {"point": […]}, roots
    /// {"class": …, "roots": […]}; cameras answer {"dir": […]} under any.
    #[arg(long, value_parser = parse_semantics, default_value = "nearest")]
    pub semantics: Semantics,
    /// The accuracy promised: f32 (a careful f32 kernel), careful-f32-renderer
    /// (the same, with the preconditions of a careful f32 renderer),
    /// faithful (one ulp) or correctly-rounded (the oracle's bits).
    #[arg(long, value_name = "LEVEL", default_value = "f32", value_parser = ["f32", "careful-f32-renderer", "faithful", "correctly-rounded"])]
    pub declared: String,
    /// A precondition: unit-dirs, no-subnormals or magnitudes:LO:HI. A case
    /// that violates one is skipped and counted; repeat for more.
    #[arg(long = "require", value_name = "PRECONDITION")]
    pub requires: Vec<String>,
    /// Send only unit-length directions (normalised in f32): the same as
    /// --require unit-dirs.
    #[arg(long)]
    pub unit_dirs: bool,
    /// Override the bits allowed on a well-conditioned root.
    #[arg(long)]
    pub bits: Option<f64>,
    /// Override the working precision (relative, e.g. 2.4e-7).
    #[arg(long)]
    pub precision: Option<f64>,
    /// Override the class band, as a multiple of the unit band.
    #[arg(long)]
    pub band_scale: Option<f64>,
}

impl Declaration {
    /// The declaration these flags make, or what is wrong with a
    /// precondition.
    pub fn declared(&self) -> Result<Declared, String> {
        let mut d = match self.declared.as_str() {
            "faithful" => Declared::faithful(self.semantics),
            "correctly-rounded" => Declared::correctly_rounded(self.semantics),
            "careful-f32-renderer" => Declared::careful_f32_renderer(self.semantics),
            _ => Declared::f32(self.semantics),
        };
        if self.unit_dirs {
            d = d.unit_dirs();
        }
        for r in &self.requires {
            d = d.require(r).map_err(|e| format!("--require {r}: {e}"))?;
        }
        d.bits = self.bits.unwrap_or(d.bits);
        d.precision = self.precision.unwrap_or(d.precision);
        d.band_scale = self.band_scale.unwrap_or(d.band_scale);
        Ok(d)
    }
}

fn parse_kind(s: &str) -> Result<Kind, String> {
    s.parse().map_err(|e| format!("{e}"))
}

pub fn parse_semantics(s: &str) -> Result<Semantics, String> {
    s.parse()
}

/// Cases by family, in the order run.
type Families = Vec<(String, Vec<Case>)>;

/// The gate these flags make and its families, or exit code 2 after
/// naming what is wrong (a precondition, a `--family` that selects
/// nothing).
fn setup(command: &str, sel: &Selection, decl: &Declaration) -> Result<(Gate, Families), u8> {
    let fail = |e: String| {
        eprintln!("rayoracle {command}: {e}");
        2
    };
    let mut g = Gate::new(decl.declared().map_err(fail)?)
        .budget(sel.budget)
        .only(&sel.families);
    if let Some(seed) = sel.seed {
        g.seed = seed;
    }
    let all = g.cases(sel.kind.as_str());
    if all.is_empty() {
        return Err(fail(format!(
            "--family {}: no {} family has that name or sits under it; run `rayoracle cases --kind {}` to see them",
            sel.families.join(", --family "),
            sel.kind.as_str(),
            sel.kind.as_str()
        )));
    }
    Ok((g, all))
}

/// `rayoracle cases`: every selected case as a protocol line.
pub fn cases_command(sel: &Selection, decl: &Declaration) -> u8 {
    let all = match setup("cases", sel, decl) {
        Ok((_, all)) => all,
        Err(code) => return code,
    };
    let mut out = BufWriter::new(io::stdout().lock());
    let lines = all
        .iter()
        .flat_map(|(f, cases)| cases.iter().map(move |c| (f, c)))
        .enumerate();
    for (id, (family, case)) in lines {
        if writeln!(out, "{}", case_line(case, family, id as u64)).is_err() {
            return 0; // a closed pipe (`| head`) is not an error
        }
    }
    let _ = out.flush();
    0
}

/// Prints the report (text, or JSON with `--json`) and gives the exit
/// code: 0 if it passed, 1 if not.
fn finish(report: &Report, kind: Kind, json: bool) -> u8 {
    if json {
        let mut j = report.to_json();
        j["kind"] = kind.as_str().into();
        println!("{j}");
    } else {
        println!("{report}");
    }
    u8::from(!report.passed())
}

/// `rayoracle judge`: answers read from a file, matched to cases by id.
pub fn judge_command(sel: &Selection, decl: &Declaration, answers: &PathBuf, json: bool) -> u8 {
    let (g, all) = match setup("judge", sel, decl) {
        Ok((g, all)) => (Gate { shrink: false, ..g }, all),
        Err(code) => return code,
    };
    let text = if answers.as_os_str() == "-" {
        io::read_to_string(io::stdin())
    } else {
        std::fs::read_to_string(answers)
    };
    let text = match text {
        Ok(t) => t,
        Err(e) => {
            eprintln!("rayoracle judge: cannot read {}: {e}", answers.display());
            return 2;
        }
    };
    let cases: Vec<&Case> = all.iter().flat_map(|f| f.1.iter()).collect();
    let mut by_id: HashMap<u64, (usize, &str)> = HashMap::new();
    let mut errors: Vec<String> = Vec::new();
    let name = answers.display();
    for (i, line) in text.lines().enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        match answer_id(line) {
            Ok(id) if id as usize >= cases.len() => {
                errors.push(format!(
                    "{name}:{}: id {id} is not a case of this selection (ids 0..{})",
                    i + 1,
                    cases.len()
                ));
            }
            Ok(id) => {
                if let Some((first, _)) = by_id.insert(id, (i + 1, line)) {
                    errors.push(format!(
                        "{name}:{}: id {id} was already answered on line {first}; the later answer counts",
                        i + 1
                    ));
                }
            }
            Err(e) => errors.push(format!("{name}:{}: {e}", i + 1)),
        }
    }
    let replies: Vec<Reply> = cases
        .iter()
        .enumerate()
        .map(|(id, case)| match by_id.get(&(id as u64)) {
            None => Reply::Failed(format!("no answer line has id {id}")),
            Some((n, line)) => match read_answer(line, case) {
                Ok(a) => a.reply,
                Err(e) => Reply::Failed(format!("{name}:{n}: {e}")),
            },
        })
        .collect();
    for e in errors.iter().take(10) {
        eprintln!("rayoracle judge: {e}");
    }
    if errors.len() > 10 {
        eprintln!(
            "rayoracle judge: … and {} more lines that could not be matched to a case",
            errors.len() - 10
        );
    }
    let mut report = g.run(&all, &mut Recorded(Some(replies)));
    report.skipped = g.skipped(sel.kind.as_str());
    finish(&report, sel.kind, json).max(u8::from(!errors.is_empty()))
}

/// Answers read beforehand: the first batch only (no shrinking).
struct Recorded(Option<Vec<Reply>>);

impl CaseKernel for Recorded {
    fn answer(&mut self, _: &[Case], replies: &mut Vec<Reply>) -> Result<(), String> {
        replies.extend(self.0.take().ok_or("the answers were read from a file")?);
        Ok(())
    }
}

/// `rayoracle gate -- PROGRAM`.
pub fn gate_command(
    sel: &Selection,
    decl: &Declaration,
    program: &[String],
    timeout: f64,
    shrink: bool,
    json: bool,
) -> u8 {
    let (g, all) = match setup("gate", sel, decl) {
        Ok((g, all)) => (Gate { shrink, ..g }, all),
        Err(code) => return code,
    };
    let mut kernel = match Program::start(program, Duration::from_secs_f64(timeout.max(0.001))) {
        Ok(k) => k,
        Err(e) => {
            eprintln!("rayoracle gate: cannot start {}: {e}", program[0]);
            return 2;
        }
    };
    kernel.families = all
        .iter()
        .flat_map(|(f, cases)| cases.iter().map(move |_| f.clone()))
        .collect();
    kernel.bar = indicatif::ProgressBar::new(kernel.families.len() as u64).with_style(
        indicatif::ProgressStyle::with_template(
            "gate [{bar:40}] {pos}/{len} answers, {per_sec}, {eta} left",
        )
        .expect("a valid template")
        .progress_chars("=> "),
    );
    let mut report = g.run(&all, &mut kernel);
    report.skipped = g.skipped(sel.kind.as_str());
    kernel.bar.finish_and_clear();
    kernel.stop();
    finish(&report, sel.kind, json)
}
