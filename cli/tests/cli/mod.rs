//! Running the `rayoracle` binary from the CLI tests (`tests/*_cli.rs`).
#![allow(dead_code)]

use std::path::Path;
use std::process::Command;

/// A fresh, empty directory under the system temp dir, named for `name`: a
/// [`Path`] that is removed, with all it holds, when it drops (a failing
/// test's too, as its panic unwinds).
pub struct TempDir(tempfile::TempDir);

impl std::ops::Deref for TempDir {
    type Target = Path;
    fn deref(&self) -> &Path {
        self.0.path()
    }
}

/// A [`TempDir`] whose name starts `rayoracle-cli-NAME-`.
pub fn temp_dir(name: &str) -> TempDir {
    let prefix = format!("rayoracle-cli-{name}-");
    TempDir(tempfile::Builder::new().prefix(&prefix).tempdir().unwrap())
}

/// Runs `rayoracle ARGS…`: the exit code, stdout and stderr.
pub fn run(args: &[&str]) -> (i32, String, String) {
    run_in(&std::env::current_dir().unwrap(), args)
}

/// Runs `rayoracle ARGS…` with `dir` as the working directory.
pub fn run_in(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_rayoracle"))
        .args(args)
        .current_dir(dir)
        .output()
        .unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8(out.stdout).unwrap(),
        String::from_utf8(out.stderr).unwrap(),
    )
}
