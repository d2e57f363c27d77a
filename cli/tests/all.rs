//! The command line's tests, as one test binary: each file of `tests/` is
//! a module here, run against the built `rayoracle` binary.

mod cli;
mod eval_cli;
mod gate_cli;
mod render_cli;
mod report_cli;
