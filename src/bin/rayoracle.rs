//! The `rayoracle` command line.
//!
//! * `rayoracle eval [FILE|-]`: one JSON line per case on stdout, the summary
//!   table on stderr. Exit 0 if every line was evaluated, 1 if some line was
//!   not (malformed, or a camera that cannot be built), 2 if the input cannot
//!   be read.
//! * `rayoracle` with no subcommand: `eval` over every
//!   `fixtures/cases/*.jsonl` of the crate, into `out/eval.jsonl`.

use clap::{Parser, Subcommand};
use rayoracle::eval::{Summary, evaluate};
use std::fs::File;
use std::io::{self, BufRead, BufReader, BufWriter, Write};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// Reference test oracle for ray–primitive intersection.
#[derive(Parser, Debug)]
#[command(version, about)]
struct Cli {
    /// Without a subcommand: evaluate every fixtures/cases/*.jsonl into
    /// out/eval.jsonl and print the summary.
    #[command(subcommand)]
    command: Option<Command>,
}

#[derive(Subcommand, Debug)]
enum Command {
    /// Evaluate cases, one JSON object per line, against the exact oracle.
    Eval {
        /// The input file; `-` or nothing reads stdin.
        file: Option<PathBuf>,
    },
    // Room for `render` and `report`.
}

/// Exit codes.
const EXIT_OK: u8 = 0;
const EXIT_BAD_LINE: u8 = 1;
const EXIT_IO: u8 = 2;

fn main() -> ExitCode {
    let cli = Cli::parse();
    let code = match cli.command {
        Some(Command::Eval { file }) => eval_command(file.as_deref()),
        None => default_job(
            &Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/cases"),
            &Path::new(env!("CARGO_MANIFEST_DIR")).join("out/eval.jsonl"),
        ),
    };
    ExitCode::from(code)
}

/// Why a run stopped.
#[derive(Debug)]
enum IoFailure {
    /// Reading the input failed.
    Read(io::Error),
    /// Writing the output failed.
    Write(io::Error),
}

/// Evaluates every line of `input`, writing one JSON line per non-blank line
/// to `out` (with a `"file"` key when `file` is given) and tallying into
/// `summary`. Lines that are not UTF-8 are reported as malformed.
fn eval_stream(
    input: &mut dyn BufRead,
    out: &mut dyn Write,
    file: Option<&str>,
    summary: &mut Summary,
) -> Result<(), IoFailure> {
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
        summary.add(&report);
        writeln!(out, "{}", report.to_json_in(file)).map_err(IoFailure::Write)?;
    }
}

fn exit_code(summary: &Summary) -> u8 {
    if summary.all_ok() {
        EXIT_OK
    } else {
        EXIT_BAD_LINE
    }
}

fn eval_command(file: Option<&Path>) -> u8 {
    let file = file.filter(|f| f.as_os_str() != "-");
    let (name, mut input): (String, Box<dyn BufRead>) = match file {
        None => ("stdin".into(), Box::new(io::stdin().lock())),
        Some(path) => match File::open(path) {
            Ok(f) => (path.display().to_string(), Box::new(BufReader::new(f))),
            Err(e) => {
                eprintln!("rayoracle: cannot read {}: {e}", path.display());
                return EXIT_IO;
            }
        },
    };
    let mut summary = Summary::default();
    let stdout = io::stdout();
    let mut out = BufWriter::new(stdout.lock());
    let result = eval_stream(&mut input, &mut out, None, &mut summary);
    let result = result.and_then(|()| out.flush().map_err(IoFailure::Write));
    match result {
        Ok(()) => {
            eprint!("{}", summary.render());
            exit_code(&summary)
        }
        Err(IoFailure::Read(e)) => {
            eprintln!("rayoracle: cannot read {name}: {e}");
            EXIT_IO
        }
        // A closed pipe (`| head`) is the reader's choice, not an error.
        Err(IoFailure::Write(e)) if e.kind() == io::ErrorKind::BrokenPipe => exit_code(&summary),
        Err(IoFailure::Write(e)) => {
            eprintln!("rayoracle: cannot write stdout: {e}");
            EXIT_IO
        }
    }
}

/// The `*.jsonl` files in `dir`, sorted by file name; an empty list if `dir`
/// does not exist.
fn case_files(dir: &Path) -> io::Result<Vec<PathBuf>> {
    let entries = match std::fs::read_dir(dir) {
        Ok(e) => e,
        Err(e) if e.kind() == io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(e),
    };
    let mut files = Vec::new();
    for entry in entries {
        let path = entry?.path();
        if path.extension().is_some_and(|x| x == "jsonl") && path.is_file() {
            files.push(path);
        }
    }
    files.sort_by(|a, b| a.file_name().cmp(&b.file_name()));
    Ok(files)
}

/// `eval` over every `*.jsonl` in `cases_dir` into `out_path`; the summary
/// and the output path on stdout. Each output line starts with a `"file"`
/// key naming its input file, since line numbers restart per file.
fn default_job(cases_dir: &Path, out_path: &Path) -> u8 {
    let files = match case_files(cases_dir) {
        Ok(f) => f,
        Err(e) => {
            eprintln!("rayoracle: cannot read {}: {e}", cases_dir.display());
            return EXIT_IO;
        }
    };
    if files.is_empty() {
        println!(
            "rayoracle: no case files (*.jsonl) in {}; nothing to evaluate",
            cases_dir.display()
        );
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
    let mut io_failed = false;
    for path in &files {
        let name = path
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let result = File::open(path)
            .map_err(IoFailure::Read)
            .and_then(|f| eval_stream(&mut BufReader::new(f), &mut out, Some(&name), &mut summary));
        match result {
            Ok(()) => {}
            Err(IoFailure::Read(e)) => {
                eprintln!("rayoracle: cannot read {}: {e}", path.display());
                io_failed = true;
            }
            Err(IoFailure::Write(e)) => {
                eprintln!("rayoracle: cannot write {}: {e}", out_path.display());
                return EXIT_IO;
            }
        }
    }
    if let Err(e) = out.flush() {
        eprintln!("rayoracle: cannot write {}: {e}", out_path.display());
        return EXIT_IO;
    }
    println!(
        "evaluated {} file(s) from {}",
        files.len(),
        cases_dir.display()
    );
    print!("{}", summary.render());
    println!("results: {}", out_path.display());
    if io_failed {
        EXIT_IO
    } else {
        exit_code(&summary)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn temp_dir(name: &str) -> PathBuf {
        let dir = std::env::temp_dir().join(format!("rayoracle-bin-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        dir
    }

    const SPHERE: &str =
        r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#;

    #[test]
    fn default_job_merges_files_in_name_order_with_file_keys() {
        let dir = temp_dir("merge");
        let cases = dir.join("cases");
        std::fs::create_dir_all(&cases).unwrap();
        std::fs::write(cases.join("b.jsonl"), format!("{SPHERE}\n")).unwrap();
        std::fs::write(cases.join("a.jsonl"), format!("\n{SPHERE}\n")).unwrap();
        std::fs::write(cases.join("c.txt"), "not a case file\n").unwrap();
        let out = dir.join("out/eval.jsonl");
        assert_eq!(default_job(&cases, &out), EXIT_OK);
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
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn default_job_reports_bad_lines_and_empty_directories() {
        let dir = temp_dir("bad");
        let out = dir.join("out/eval.jsonl");
        assert_eq!(default_job(&dir.join("missing"), &out), EXIT_OK);
        assert!(!out.exists());
        std::fs::write(dir.join("x.jsonl"), "{}\n").unwrap();
        assert_eq!(default_job(&dir, &out), EXIT_BAD_LINE);
        assert_eq!(
            std::fs::read_to_string(&out).unwrap(),
            "{\"file\":\"x.jsonl\",\"line\":1,\"error\":\"kind: missing\"}\n"
        );
        let _ = std::fs::remove_dir_all(&dir);
    }

    #[test]
    fn non_utf8_lines_are_malformed_and_do_not_stop_the_run() {
        let mut input: &[u8] = b"\xff\xfe\n{}\n";
        let mut out = Vec::new();
        let mut summary = Summary::default();
        eval_stream(&mut input, &mut out, None, &mut summary).unwrap();
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
