//! `rayoracle answer`: the exact oracle as a protocol peer.

use rayoracle::camera;
use rayoracle::case::{Case, Kind};
use rayoracle::check::gate::protocol::answer_line;
use rayoracle::check::gate::{Answer, Declared, Reply, Semantics};
use rayoracle::check::rules;
use rayoracle::eval::{Implementation, Outcome};
use rayoracle::hit::Class;
use std::io::{self, BufRead, Write};

/// `rayoracle answer`: answers case lines on stdin with the exact
/// oracle's answer in the semantics (what the gate expects), one answer
/// line each, flushed: a peer that speaks the protocol, to compare a
/// kernel's answers with or to time the pipe.
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

/// The exact answer in the semantics: the oracle's roots, read as the
/// semantics reads them (the answer the gate expects), or the camera's
/// correctly rounded ray; for a non-finite input, which the oracle does
/// not take, the reference kernel's.
fn reply(case: &Case, semantics: Semantics) -> Reply {
    let d = Declared::correctly_rounded(semantics);
    let exact = match case {
        Case::Plane(r, p) => rules::plane(r, p).map(|e| e.1),
        Case::Sphere(r, s) => rules::sphere(r, s).map(|e| e.1),
        Case::Quadric(r, q) => rules::quadric(r, q).map(|e| e.1),
        Case::Camera(p, [x, y]) => return Reply::Camera(camera::exact::ray(p, *x, *y).ok()),
    };
    if let Some(e) = exact {
        return Reply::Answer(e.expected(&d));
    }
    match Implementation::Reference.run(case) {
        Outcome::Hit { class, roots } => {
            let roots = roots.as_slice();
            Reply::Answer(match (class, semantics.range()) {
                (Class::All | Class::InPlane, _) => Answer::Everywhere,
                (_, None) => Answer::Roots(roots.to_vec()),
                (_, Some((lo, hi))) => {
                    Answer::Nearest(roots.iter().copied().find(|&t| lo < t && t < hi))
                }
            })
        }
        Outcome::Ray(r) => Reply::Camera(Some(r)),
        Outcome::Error(e) => Reply::Failed(e),
    }
}
