//! The `rayoracle` command line.
//!
//! * `rayoracle eval [FILE|-]`: one JSON line per case on stdout, the summary
//!   table on stderr. Exit 0 if every line was evaluated, 1 if some line was
//!   not (malformed, or a camera that cannot be built), 2 if the input cannot
//!   be read.
//! * `rayoracle render SCENE... -o DIR [--path reference|x4] [--channel
//!   depth|normal|id|all] [--size WxH]`: each scene's channels as
//!   `DIR/STEM.CHANNEL.png`. A scene that cannot be loaded is reported with
//!   its file, line, column and field, and the others are still rendered;
//!   exit 1 if any scene failed, 2 if an output cannot be written.
//! * `rayoracle cases --kind KIND`, `rayoracle judge --kind KIND ANSWERS`
//!   and `rayoracle gate --kind KIND -- PROGRAM`: the gate for kernels in
//!   any language, over standard streams (`gate.rs`, docs/protocol.md).
//!   Exit 0 if every case passed, 1 if not, 2 for bad usage or a program
//!   that cannot start.
//! * `rayoracle` with no subcommand: `eval` over the compiled-in
//!   `fixtures/cases/*.jsonl` into `./out/eval.jsonl`, then the built-in
//!   default scene (`fixtures/scenes/seed.json`) rendered into `./out/`,
//!   then `report --quick`. Nothing is read from the source tree.

mod gate;
mod plot;

use clap::{Parser, Subcommand};
use rayoracle::case::Kind;
use rayoracle::eval::{Summary, evaluate};
use rayoracle::render::{Channels, Path as RenderPath, Plan, render_with_progress, write_pngs};
use rayoracle::scene::{Scene, SceneError};
use std::fs::File;
use std::io::{self, BufRead, BufReader, BufWriter, IsTerminal, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Reference test oracle for ray–primitive intersection.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Cli {
    /// Without a subcommand: evaluate the built-in cases into
    /// ./out/eval.jsonl, render the default scene into ./out/, and run
    /// report --quick.
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Evaluate cases, one JSON object per line, against the exact oracle.
    Eval {
        /// Input files, read in order; `-` or nothing reads stdin. With
        /// more than one, each output line starts with a "file" key.
        files: Vec<PathBuf>,
    },
    /// Render scenes to PNG: depth (16-bit grey), normal and id channels.
    Render {
        /// Scene files (JSON, see fixtures/scenes/).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// The directory for the PNGs (created if missing).
        #[arg(short = 'o', long = "out")]
        out: PathBuf,
        /// Which implementation renders: reference or x4.
        #[arg(long, default_value = "x4", value_parser = RenderPath::parse)]
        path: RenderPath,
        /// Channels: depth, normal, id, all, or a comma-separated list.
        #[arg(long, default_value = "all", value_parser = Channels::parse)]
        channel: Channels,
        /// Override the scene's resolution, as WIDTHxHEIGHT.
        #[arg(long, value_parser = parse_size)]
        size: Option<[u32; 2]>,
    },
    /// Error against run time on the stiff catalogue (fixtures/stiff/): a
    /// Markdown table on stdout, optionally JSON rows, SVG plots, Markdown file.
    Report {
        /// 64 cases per family and 5 timed passes (under 30 s).
        #[arg(long)]
        quick: bool,
        /// Also write the rows as a JSON array to FILE.
        #[arg(long, value_name = "FILE")]
        json: Option<PathBuf>,
        /// Also write one SVG plot per kernel: FILE with -KERNEL before its
        /// extension (report.svg → report-sphere.svg, …).
        #[arg(long, value_name = "FILE")]
        svg: Option<PathBuf>,
        /// Also write the Markdown table to FILE.
        #[arg(long, value_name = "FILE")]
        md: Option<PathBuf>,
        /// A catalogue directory to use instead of the compiled-in one.
        #[arg(long, value_name = "DIR")]
        stiff: Option<PathBuf>,
    },
    /// Write the gate's cases as eval input lines, each with its family
    /// and id, for a kernel in another language.
    Cases {
        #[command(flatten)]
        selection: gate::Selection,
        #[command(flatten)]
        declaration: gate::Declaration,
    },
    /// Judge answer lines (each with the id of its case, as `cases` wrote
    /// it) by the gate's rules, and print the gate's report.
    Judge {
        #[command(flatten)]
        selection: gate::Selection,
        #[command(flatten)]
        declaration: gate::Declaration,
        /// The report as one JSON object.
        #[arg(long)]
        json: bool,
        /// The answer lines; `-` reads stdin.
        answers: PathBuf,
    },
    /// Answer case lines on stdin with rayoracle's own reference kernels,
    /// one answer line each: a peer that speaks the gate's protocol.
    Answer {
        /// nearest or whole-line.
        #[arg(long, value_parser = gate::parse_semantics, default_value = "nearest")]
        semantics: rayoracle::check::gate::Semantics,
    },
    /// Gate a kernel program: case lines to its stdin, one answer line per
    /// case from its stdout; failures are shrunk by sending new cases.
    Gate {
        #[command(flatten)]
        selection: gate::Selection,
        #[command(flatten)]
        declaration: gate::Declaration,
        /// The report as one JSON object.
        #[arg(long)]
        json: bool,
        /// Seconds to wait for each answer line before stopping the program.
        #[arg(long, default_value_t = 10.0, value_name = "SECS")]
        timeout: f64,
        /// Report failures as found, without shrinking them.
        #[arg(long)]
        no_shrink: bool,
        /// The program and its arguments, after `--`.
        #[arg(last = true, required = true, value_name = "PROGRAM")]
        program: Vec<String>,
    },
}

/// `--size WxH`.
fn parse_size(text: &str) -> Result<[u32; 2], String> {
    let bad = || format!("expected WIDTHxHEIGHT such as 1920x1080, got \"{text}\"");
    let (w, h) = text.split_once(['x', 'X', '×']).ok_or_else(bad)?;
    Ok([
        w.trim().parse().map_err(|_| bad())?,
        h.trim().parse().map_err(|_| bad())?,
    ])
}

/// Exit codes.
const EXIT_OK: u8 = 0;
const EXIT_BAD_LINE: u8 = 1;
const EXIT_IO: u8 = 2;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let code = match cli.command {
        Some(Command::Eval { files }) => eval_command(&files),
        Some(Command::Render {
            scenes,
            out,
            path,
            channel,
            size,
        }) => {
            let jobs = scenes.iter().map(|f| RenderJob {
                name: f.display().to_string(),
                stem: f
                    .file_stem()
                    .map_or("scene".into(), |s| s.to_string_lossy().into_owned()),
                scene: Scene::load(f),
            });
            render_command(jobs, &out, path, channel, size)
        }
        Some(Command::Report {
            quick,
            json,
            svg,
            md,
            stiff,
        }) => report_command(&ReportArgs {
            quick,
            json,
            svg,
            md,
            stiff,
        }),
        Some(Command::Cases {
            selection,
            declaration,
        }) => gate::cases_command(&selection, &declaration),
        Some(Command::Judge {
            selection,
            declaration,
            json,
            answers,
        }) => gate::judge_command(&selection, &declaration, &answers, json),
        Some(Command::Gate {
            selection,
            declaration,
            json,
            timeout,
            no_shrink,
            program,
        }) => gate::gate_command(
            &selection,
            &declaration,
            &program,
            timeout,
            !no_shrink,
            json,
        ),
        Some(Command::Answer { semantics }) => gate::answer_command(semantics),
        None => {
            let out = Path::new("out");
            let eval = default_job(&builtin_cases(), &out.join("eval.jsonl"));
            println!();
            let scene = RenderJob {
                name: "the built-in default scene (fixtures/scenes/seed.json)".into(),
                stem: "seed".into(),
                scene: Scene::parse(DEFAULT_SCENE),
            };
            let render = render_command(
                [scene].into_iter(),
                out,
                RenderPath::X4,
                Channels::ALL,
                None,
            );
            let render = {
                println!(
                    "\nrayoracle report --quick (error against run time on the stiff catalogue):\n"
                );
                let report = report_command(&ReportArgs {
                    quick: true,
                    json: None,
                    svg: None,
                    md: None,
                    stiff: None,
                });
                render.max(report)
            };
            eval.max(render)
        }
    };
    ExitCode::from(code)
}

/// `rayoracle report`'s arguments.
struct ReportArgs {
    quick: bool,
    json: Option<PathBuf>,
    svg: Option<PathBuf>,
    md: Option<PathBuf>,
    stiff: Option<PathBuf>,
}

/// Runs the report; exit 2 if the catalogue cannot be read or an output
/// cannot be written.
fn report_command(args: &ReportArgs) -> u8 {
    use rayoracle::report::{self, Catalogue, KERNELS, Options, Variant};
    let catalogue = match &args.stiff {
        Some(dir) => Catalogue::load(dir),
        None => Catalogue::builtin(),
    };
    let catalogue = match catalogue {
        Ok(c) => c,
        Err(e) => {
            eprintln!("rayoracle: {e}");
            return EXIT_IO;
        }
    };
    let options = if args.quick {
        Options::QUICK
    } else {
        Options::FULL
    };
    let steps = report_steps(&catalogue);
    let bar = indicatif::ProgressBar::new(steps);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "report [{bar:40}] {pos}/{len} family × variant, {eta} left",
        )
        .expect("a valid template")
        .progress_chars("=> "),
    );
    let start = std::time::Instant::now();
    let rows = report::run(&catalogue, options, &mut || bar.inc(1));
    bar.finish_and_clear();
    let table = report::markdown(&rows, &catalogue);
    print!("{table}");
    println!(
        "{} families × {} variants in {:.1} s{}",
        catalogue.families.len(),
        Variant::ALL.len(),
        start.elapsed().as_secs_f64(),
        if args.quick { " (--quick)" } else { "" }
    );
    let write = |path: &Path, text: &str| -> Result<(), u8> {
        if let Some(parent) = path.parent().filter(|p| !p.as_os_str().is_empty()) {
            let _ = std::fs::create_dir_all(parent);
        }
        std::fs::write(path, text).map_err(|e| {
            eprintln!("rayoracle: cannot write {}: {e}", path.display());
            EXIT_IO
        })?;
        println!("wrote {}", path.display());
        Ok(())
    };
    let mut outputs: Vec<(PathBuf, String)> = Vec::new();
    if let Some(p) = &args.json {
        let json = serde_json::to_string_pretty(&rows).expect("rows serialise");
        outputs.push((p.clone(), json + "\n"));
    }
    if let Some(p) = &args.md {
        outputs.push((p.clone(), table.clone()));
    }
    if let Some(p) = &args.svg {
        for kernel in KERNELS {
            let stem = p
                .file_stem()
                .map_or("report".into(), |s| s.to_string_lossy().into_owned());
            let ext = p
                .extension()
                .map_or("svg".into(), |e| e.to_string_lossy().into_owned());
            let file = p.with_file_name(format!("{stem}-{kernel}.{ext}"));
            let points = report::points(&rows, kernel);
            outputs.push((file, plot::svg(kernel.as_str(), &points)));
        }
    }
    for (path, text) in outputs {
        if let Err(code) = write(&path, &text) {
            return code;
        }
    }
    EXIT_OK
}

/// The default scene, compiled in so `rayoracle` runs from anywhere.
const DEFAULT_SCENE: &str = rayoracle::fixtures::DEFAULT_SCENE;

/// One scene to render.
struct RenderJob {
    /// How messages name it.
    name: String,
    /// The output file stem.
    stem: String,
    scene: Result<Scene, SceneError>,
}

/// Renders each scene into `out`; a scene that fails to load or compile is
/// reported and skipped. Exit 0, 1 if a scene failed, 2 if writing failed.
fn render_command(
    jobs: impl Iterator<Item = RenderJob>,
    out: &Path,
    path: RenderPath,
    channels: Channels,
    size: Option<[u32; 2]>,
) -> u8 {
    if out.exists() && !out.is_dir() {
        eprintln!(
            "rayoracle: -o {}: is a file; name a directory (it is created if missing)",
            out.display()
        );
        return EXIT_IO;
    }
    let mut code = EXIT_OK;
    // Output stem → the scene that took it: a second scene of the same file
    // name would silently overwrite the first one's frames.
    let mut taken: Vec<(String, String)> = Vec::new();
    for job in jobs {
        if let Some((_, first)) = taken.iter().find(|t| t.0 == job.stem) {
            eprintln!(
                "rayoracle: {}: not rendered: its frames would overwrite those of {first} \
                 (both {}.*.png in {}); rename one, or render them into separate -o directories",
                job.name,
                job.stem,
                out.display()
            );
            code = code.max(EXIT_BAD_LINE);
            continue;
        }
        taken.push((job.stem.clone(), job.name.clone()));
        let plan = job
            .scene
            .and_then(|s| match size {
                Some([w, h]) => s.with_size([w, h]).map_err(|e| {
                    SceneError::field(format!("--size {w}x{h}"), e.message).in_file(&job.name)
                }),
                None => Ok(s),
            })
            .and_then(|s| Plan::compile(&s, channels).map_err(|e| e.in_file(&job.name)));
        let plan = match plan {
            Ok(p) => p,
            Err(e) => {
                eprintln!("rayoracle: {e}");
                code = code.max(EXIT_BAD_LINE);
                continue;
            }
        };
        let [w, h] = plan.size();
        // Only long renders get a bar (and indicatif draws nothing when
        // stderr is not a terminal, so tests see no bar either way: the
        // choice is `long_render`, tested on its own).
        let target = if long_render(w, h, plan.objects()) {
            indicatif::ProgressDrawTarget::stderr()
        } else {
            indicatif::ProgressDrawTarget::hidden()
        };
        let bar = indicatif::ProgressBar::with_draw_target(Some(u64::from(h)), target);
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{msg} [{bar:40}] {pos}/{len} rows, {eta} left",
            )
            .expect("a valid template")
            .progress_chars("=> "),
        );
        bar.set_message(job.stem.clone());
        let start = std::time::Instant::now();
        let frame = render_with_progress(&plan, path, &mut || bar.inc(1));
        let seconds = start.elapsed().as_secs_f64();
        bar.finish_and_clear();
        match write_pngs(&frame, channels, out, &job.stem) {
            Ok(files) => {
                println!(
                    "rendered {} ({w}×{h}, {} path, kinds: {}) in {seconds:.2} s",
                    job.name,
                    path.name(),
                    plan.kinds().join(", ")
                );
                for f in files {
                    println!("  {}", f.display());
                }
            }
            Err(e) => {
                eprintln!("rayoracle: {e}");
                return EXIT_IO;
            }
        }
    }
    code
}

/// Why a run stopped.
#[derive(Debug)]
enum IoFailure {
    /// Reading the input failed.
    Read(io::Error),
    /// Writing the output failed.
    Write(io::Error),
}

/// Where `eval_stream`'s lines come from.
struct Source<'a> {
    /// How messages name it (a path, or `stdin`).
    name: &'a str,
    /// Each output line starts with a `"file"` key of `name`.
    keyed: bool,
    /// Each line that is not evaluated is also named on stderr.
    tell: bool,
}

/// Evaluates every line of `input`, writing one JSON line per non-blank
/// line to `out` and tallying into `summary`. Lines that are not UTF-8 are
/// reported as malformed; with `source.tell`, every line that is not
/// evaluated is also named on stderr as `NAME:LINE: problem`. A UTF-8
/// byte-order mark before the first line is skipped.
fn eval_stream(
    input: &mut dyn BufRead,
    out: &mut dyn Write,
    source: &Source,
    summary: &mut Summary,
) -> Result<(), IoFailure> {
    let file = source.keyed.then_some(source.name);
    let mut buf = Vec::new();
    let mut line_no = 0;
    loop {
        buf.clear();
        if input.read_until(b'\n', &mut buf).map_err(IoFailure::Read)? == 0 {
            return Ok(());
        }
        line_no += 1;
        let line = buf.strip_suffix(b"\n").unwrap_or(&buf);
        let line = line.strip_suffix(b"\r").unwrap_or(line);
        let line = match line_no {
            1 => line.strip_prefix(b"\xef\xbb\xbf").unwrap_or(line),
            _ => line,
        };
        let report = match std::str::from_utf8(line) {
            Ok(text) => match evaluate(line_no, text) {
                Some(r) => r,
                None => continue,
            },
            Err(e) => rayoracle::eval::LineReport::Malformed {
                line: line_no,
                error: rayoracle::case::CaseError {
                    field: "json".into(),
                    message: format!("the line is not valid UTF-8 ({e})"),
                },
            },
        };
        if let Some(problem) = not_evaluated(&report).filter(|_| source.tell) {
            eprintln!("rayoracle: {}:{line_no}: {problem}", source.name);
        }
        summary.add(&report);
        writeln!(out, "{}", report.to_json_in(file)).map_err(IoFailure::Write)?;
    }
}

/// Why a line was not evaluated, or `None` if it was.
fn not_evaluated(report: &rayoracle::eval::LineReport) -> Option<String> {
    use rayoracle::eval::LineReport;
    match report {
        LineReport::Malformed { error, .. } => Some(error.to_string()),
        LineReport::Invalid { kind, error, .. } => Some(format!("invalid {kind}: {error}")),
        LineReport::Internal { error, .. } => Some(format!("internal error: {error}")),
        LineReport::Evaluated(_) => None,
    }
}

fn exit_code(summary: &Summary) -> u8 {
    if summary.all_ok() {
        EXIT_OK
    } else {
        EXIT_BAD_LINE
    }
}

/// `rayoracle eval FILE...`: every file in order (stdin for none or `-`),
/// one summary. A file that cannot be read is reported and the others are
/// still evaluated (exit 2).
fn eval_command(files: &[PathBuf]) -> u8 {
    let stdin_only = [PathBuf::from("-")];
    let files = if files.is_empty() {
        &stdin_only[..]
    } else {
        files
    };
    let keyed = files.len() > 1;
    let mut summary = Summary::default();
    let stdout = io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    let mut code = EXIT_OK;
    for path in files {
        let (name, mut input): (String, Box<dyn BufRead>) = if path.as_os_str() == "-" {
            if io::stdin().is_terminal() {
                eprintln!(
                    "rayoracle: reading cases from the terminal, one JSON object a line; end with Ctrl-D (see rayoracle eval --help)"
                );
            }
            ("stdin".into(), Box::new(io::stdin().lock()))
        } else {
            match File::open(path) {
                Ok(f) => (path.display().to_string(), Box::new(BufReader::new(f))),
                Err(e) => {
                    eprintln!("rayoracle: cannot read {}: {e}", path.display());
                    code = EXIT_IO;
                    continue;
                }
            }
        };
        let source = Source {
            name: &name,
            keyed,
            tell: true,
        };
        let result = eval_stream(&mut input, &mut out, &source, &mut summary);
        match result {
            Ok(()) => {}
            Err(IoFailure::Read(e)) => {
                eprintln!("rayoracle: cannot read {name}: {e}");
                code = EXIT_IO;
            }
            // A closed pipe (`| head`) is the reader's choice, not an error.
            Err(IoFailure::Write(e)) if e.kind() == io::ErrorKind::BrokenPipe => {
                return exit_code(&summary).max(code);
            }
            Err(IoFailure::Write(e)) => {
                eprintln!("rayoracle: cannot write stdout: {e}");
                return EXIT_IO;
            }
        }
    }
    match out.flush() {
        Err(e) if e.kind() != io::ErrorKind::BrokenPipe => {
            eprintln!("rayoracle: cannot write stdout: {e}");
            return EXIT_IO;
        }
        _ => {}
    }
    eprint!("{}", summary.render());
    exit_code(&summary).max(code)
}

/// Whether a render is long enough for a progress bar: 2²⁴ ray–object
/// tests or more (about a second on one core), counting a scene with no
/// objects as one.
fn long_render(w: u32, h: u32, objects: usize) -> bool {
    u64::from(w) * u64::from(h) * (objects.max(1) as u64) >= 1 << 24
}

/// The report's progress steps: one per family per variant.
fn report_steps(catalogue: &rayoracle::report::Catalogue) -> u64 {
    (catalogue.families.len() * rayoracle::report::Variant::ALL.len()) as u64
}

/// `eval` over the compiled-in `fixtures/cases/*.jsonl` (name, text) into
/// `out_path`; the summary and the output path on stdout. Each output line
/// starts with a `"file"` key naming its input file, since line numbers
/// restart per file.
fn default_job(files: &[(String, &str)], out_path: &Path) -> u8 {
    if files.is_empty() {
        println!("rayoracle: no case files; nothing to evaluate");
        return EXIT_OK;
    }
    if let Some(parent) = out_path.parent()
        && let Err(e) = std::fs::create_dir_all(parent)
    {
        eprintln!("rayoracle: cannot create {}: {e}", parent.display());
        return EXIT_IO;
    }
    let mut out = match File::create(out_path) {
        Ok(f) => BufWriter::new(f),
        Err(e) => {
            eprintln!("rayoracle: cannot write {}: {e}", out_path.display());
            return EXIT_IO;
        }
    };
    let mut summary = Summary::default();
    for (name, text) in files {
        // The fixtures' invalid lines are on purpose: the summary counts them.
        let source = Source {
            name,
            keyed: true,
            tell: false,
        };
        let result = eval_stream(&mut text.as_bytes(), &mut out, &source, &mut summary);
        if result.is_err() {
            eprintln!("rayoracle: cannot write {}", out_path.display());
            return EXIT_IO;
        }
    }
    if let Err(e) = out.flush() {
        eprintln!("rayoracle: cannot write {}: {e}", out_path.display());
        return EXIT_IO;
    }
    let names: Vec<&str> = files.iter().map(|f| f.0.as_str()).collect();
    println!("evaluated the built-in cases ({})", names.join(", "));
    print!("{}", summary.render());
    println!("results: {}", out_path.display());
    // The fixtures hold error cases on purpose (`"expect": {"class":
    // "error"}`, e.g. a zero camera dir); the run is clean when exactly
    // those lines are the invalid ones.
    let expected_errors: usize = files.iter().map(|f| expected_error_lines(f.1)).sum();
    if summary.malformed == 0 && summary.internal == 0 && summary.invalid == expected_errors {
        println!("({expected_errors} invalid lines are the fixtures' expected error cases)");
        EXIT_OK
    } else {
        EXIT_BAD_LINE
    }
}

/// How many lines of `text` say they expect an error.
fn expected_error_lines(text: &str) -> usize {
    text.lines()
        .filter_map(|l| serde_json::from_str::<serde_json::Value>(l).ok())
        .filter(|v| v["expect"]["class"] == "error")
        .count()
}

/// The compiled-in case files of every kind this build has, as
/// `(KIND.jsonl, text)`.
fn builtin_cases() -> Vec<(String, &'static str)> {
    Kind::ALL
        .into_iter()
        .filter(|k| k.compiled_in())
        .map(|k| (format!("{k}.jsonl"), rayoracle::fixtures::cases(k)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A bar from 2²⁴ ray–object tests on: many objects at a small size
    /// count as much as a large frame of one object.
    #[test]
    fn a_render_is_long_from_its_ray_object_tests() {
        assert!(long_render(4096, 4096, 0) && long_render(4096, 4096, 1));
        assert!(long_render(160, 120, 100_000) && long_render(1 << 20, 1, 16));
        assert!(!long_render(4096, 4095, 1) && !long_render(160, 120, 873));
        assert!(long_render(160, 120, 874));
    }

    /// 27 stiff families, 5 variants each.
    #[test]
    fn the_report_counts_a_step_per_family_and_variant() {
        let c = rayoracle::report::Catalogue::builtin().unwrap();
        assert_eq!(report_steps(&c), 27 * 5);
    }

    /// A fresh directory, removed with all it holds when it drops.
    fn temp_dir(name: &str) -> tempfile::TempDir {
        let prefix = format!("rayoracle-bin-{name}-");
        tempfile::Builder::new().prefix(&prefix).tempdir().unwrap()
    }
    const SPHERE: &str =
        r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#;
    #[test]
    fn default_job_merges_files_in_order_with_file_keys() {
        let dir = temp_dir("merge");
        let out = dir.path().join("out/eval.jsonl");
        let a = format!("\n{SPHERE}\n");
        let files = [
            ("a.jsonl".to_string(), a.as_str()),
            ("b.jsonl".into(), SPHERE),
        ];
        assert_eq!(default_job(&files, &out), EXIT_OK);
        let text = std::fs::read_to_string(&out).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 2);
        assert!(
            lines[0].starts_with(r#"{"file":"a.jsonl","line":2,"kind":"sphere""#),
            "{}",
            lines[0]
        );
        assert!(
            lines[1].starts_with(r#"{"file":"b.jsonl","line":1,"kind":"sphere""#),
            "{}",
            lines[1]
        );
    }

    #[test]
    fn default_job_reports_bad_lines_and_empty_inputs() {
        let dir = temp_dir("bad");
        let out = dir.path().join("out/eval.jsonl");
        assert_eq!(default_job(&[], &out), EXIT_OK);
        assert!(!out.exists());
        assert_eq!(
            default_job(&[("x.jsonl".into(), "{}\n")], &out),
            EXIT_BAD_LINE
        );
        assert_eq!(
            std::fs::read_to_string(&out).unwrap(),
            "{\"file\":\"x.jsonl\",\"line\":1,\"error\":\"kind: missing\"}\n"
        );
    }

    /// Every kind this build has, from the data compiled in: the run needs
    /// no source tree.
    #[test]
    fn the_builtin_cases_are_compiled_in() {
        let files = builtin_cases();
        let want = Kind::ALL.into_iter().filter(|k| k.compiled_in()).count();
        assert_eq!(files.len(), want);
        assert!(files.iter().all(|f| f.1.lines().count() > 10), "{files:?}");
    }

    #[test]
    fn non_utf8_lines_are_malformed_and_do_not_stop_the_run() {
        let mut input: &[u8] = b"\xff\xfe\n{}\n";
        let mut out = Vec::new();
        let mut summary = Summary::default();
        let source = Source {
            name: "stdin",
            keyed: false,
            tell: false,
        };
        eval_stream(&mut input, &mut out, &source, &mut summary).unwrap();
        let text = String::from_utf8(out).unwrap();
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 2);
        assert!(
            lines[0].starts_with(r#"{"line":1,"error":"json: the line is not valid UTF-8"#),
            "{}",
            lines[0]
        );
        assert_eq!(lines[1], r#"{"line":2,"error":"kind: missing"}"#);
        assert_eq!(summary.malformed, 2);
    }
}
