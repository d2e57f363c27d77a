//! The `scene` fuzz target's check: any bytes, read as a scene file.

use super::Scene;
use crate::fuzz::Failure;
use crate::render::{Channels, Path, Plan, render};

fn fail(what: String) -> Result<(), Failure> {
    Err(Failure(what))
}

/// The largest frame the fuzz check renders; bigger scenes are checked at
/// this size (`Scene::with_size`) so one input stays fast.
pub const FUZZ_MAX_PIXELS: u32 = 24 * 16;

/// A rejection must say what is wrong, and any line and column it gives
/// must be inside `text` (lines from 1, columns from 1).
fn well_placed(text: &str, e: &super::SceneError) -> Result<(), Failure> {
    if e.message.is_empty() {
        return fail(format!("an error without a message: {e:?}"));
    }
    if let (Some(line), Some(column)) = (e.line, e.column) {
        let lines = text.split('\n').count().max(1);
        if !(1..=lines).contains(&line) || column == 0 {
            return fail(format!(
                "line {line}, column {column} of {lines} lines: {e}"
            ));
        }
    }
    let _ = e.to_string();
    Ok(())
}

/// Parses `data` as a scene. Loading must never panic; a rejected scene must
/// have an error that names a place inside the text; an accepted one must
/// compile and render to the same bits through the reference and x4 paths,
/// and through the un-specialised plan, and encode to PNG.
///
/// ```
/// use rayoracle::scene::fuzz::check;
/// assert!(check(br#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1], "up": [0, 1, 0],
///     "angle": 1, "res": [4, 3]}, "spheres": [{"id": 1, "center": [0, 0, -3], "radius": 1}]}"#).is_ok());
/// assert!(check(b"\xff{").is_ok());
/// assert!(check(b"{\"camera\": ").is_ok());
/// ```
pub fn check(data: &[u8]) -> Result<(), Failure> {
    let Ok(text) = std::str::from_utf8(data) else {
        return Ok(());
    };
    let scene = match Scene::parse(text) {
        Ok(s) => s,
        Err(e) => return well_placed(text, &e),
    };
    let [w, h] = scene.camera.res;
    let scene = if w.saturating_mul(h) > FUZZ_MAX_PIXELS {
        match scene.with_size([w.clamp(1, 24), h.clamp(1, 16)]) {
            Ok(s) => s,
            // A camera valid at one resolution can fail at another (the
            // basis scales with the aspect ratio): an error, not a panic.
            Err(_) => return Ok(()),
        }
    } else {
        scene
    };
    let compile = |everything: bool| {
        let plan = if everything {
            Plan::everything(&scene)
        } else {
            Plan::compile(&scene, Channels::ALL)
        };
        plan.map_err(|e| Failure(format!("a parsed scene does not compile: {e}")))
    };
    let plan = compile(false)?;
    let reference = render(&plan, Path::Reference);
    let x4 = render(&plan, Path::X4);
    if !reference.same_bits(&x4) {
        return fail(format!(
            "reference and x4 frames differ first at pixel {:?}",
            reference.first_difference(&x4)
        ));
    }
    let everything = render(&compile(true)?, Path::X4);
    if !everything.same_bits(&x4) {
        return fail(format!(
            "the un-specialised plan's frame differs first at pixel {:?}",
            everything.first_difference(&x4)
        ));
    }
    if x4.pngs().len() != 3 {
        return fail("not every channel encoded".into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::super::SceneError;
    use super::well_placed;

    fn at(line: usize, column: usize, message: &str) -> SceneError {
        SceneError {
            line: Some(line),
            column: Some(column),
            ..SceneError::field("camera", message)
        }
    }

    /// Each way a rejection can be badly placed fails the check, and a
    /// well placed one passes, on a two-line text.
    #[test]
    fn a_rejection_must_be_placed_inside_the_text() {
        let text = "{\n}";
        assert!(well_placed(text, &at(2, 1, "no camera")).is_ok());
        assert!(well_placed(text, &SceneError::field("camera", "no line")).is_ok());
        for bad in [at(2, 1, ""), at(0, 1, "x"), at(3, 1, "x"), at(1, 0, "x")] {
            assert!(well_placed(text, &bad).is_err(), "{bad:?}");
        }
    }
}
