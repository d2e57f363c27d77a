//! `rayoracle answer`: rayoracle's own kernels as a protocol peer.

use rayoracle::case::{Case, Kind};
use rayoracle::check::gate::protocol::answer_line;
use rayoracle::check::gate::{Answer, Reply, Semantics};
use rayoracle::eval::{Implementation, Outcome};
use rayoracle::hit::Class;
use std::io::{self, BufRead, Write};

/// `rayoracle answer`: answers case lines on stdin with rayoracle's own
/// correctly rounded reference kernels, one answer line each, flushed: a
/// peer that speaks the protocol, to compare a kernel's answers with or to
/// time the pipe.
pub fn answer_command(semantics: Semantics) -> u8 {
    let mut out = io::stdout().lock();
    let mut code = 0;
    for (i, line) in io::stdin().lock().lines().enumerate() {
        let Ok(line) = line else {
            eprintln!("rayoracle answer: stdin:{}: not UTF-8 text", i + 1);
            return 2;
        };
        if line.trim().is_empty() {
            continue;
        }
        let text = match rayoracle::case::parse_line(&line) {
            Ok(c) => {
                let a = answer_line(&reply(&c.case, semantics), c.case.kind());
                match c.id {
                    Some(id) => format!(r#"{{"id":{id},{}"#, &a[1..]),
                    None => a,
                }
            }
            Err(e) => {
                eprintln!("rayoracle answer: stdin:{}: {e}", i + 1);
                code = 1;
                answer_line(
                    &Reply::Failed(format!("stdin:{}: {e}", i + 1)),
                    Kind::Sphere,
                )
            }
        };
        if writeln!(out, "{text}").and_then(|()| out.flush()).is_err() {
            return code;
        }
    }
    code
}

/// The reference kernel's reply in the semantics.
fn reply(case: &Case, semantics: Semantics) -> Reply {
    match Implementation::Reference.run(case) {
        Outcome::Ray(r) => Reply::Camera(Some(r)),
        Outcome::Error(_) if case.kind() == Kind::Camera => Reply::Camera(None),
        Outcome::Error(e) => Reply::Failed(e),
        Outcome::Hit { class, roots } => {
            let roots = roots.as_slice();
            Reply::Answer(match (class, semantics) {
                (Class::All | Class::InPlane, _) => Answer::Everywhere,
                (_, Semantics::NearestPositive) => {
                    Answer::Nearest(roots.iter().copied().find(|&t| t > 0.0))
                }
                _ => Answer::Roots(roots.to_vec()),
            })
        }
    }
}
