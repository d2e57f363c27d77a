//! The `scene` fuzz target's check: any bytes, read as a scene file.

use super::Failure;
use crate::render::{Channels, Frame, Path, Plan, render};
use crate::scene::Scene;

fn fail(what: String) -> Result<(), Failure> {
    Err(Failure(what))
}

/// The largest frame the fuzz check renders; bigger scenes are checked at
/// this size (`Scene::with_size`) so one input stays fast.
pub const FUZZ_MAX_PIXELS: u32 = 24 * 16;

/// The size the fuzz check renders a scene of resolution `res` at: `res`
/// itself up to [`FUZZ_MAX_PIXELS`] pixels, and beyond that each side
/// clamped to 24 × 16.
///
/// ```
/// use rayoracle::fuzz::scene::fuzz_size;
/// assert_eq!(fuzz_size([24, 16]), [24, 16]);
/// assert_eq!(fuzz_size([1920, 1080]), [24, 16]);
/// assert_eq!(fuzz_size([100, 1]), [100, 1]);
/// assert_eq!(fuzz_size([1000, 1]), [24, 1]);
/// ```
pub fn fuzz_size([w, h]: [u32; 2]) -> [u32; 2] {
    if w.saturating_mul(h) > FUZZ_MAX_PIXELS {
        [w.clamp(1, 24), h.clamp(1, 16)]
    } else {
        [w, h]
    }
}

/// A rejection must say what is wrong, and any line and column it gives
/// must be inside `text` (lines from 1, columns from 1).
fn well_placed(text: &str, e: &crate::scene::SceneError) -> Result<(), Failure> {
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
/// use rayoracle::fuzz::scene::check;
/// assert!(check(br#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1], "up": [0, 1, 0],
///     "angle": 1, "res": [4, 3]}, "spheres": [{"id": 1, "center": [0, 0, -3], "radius": 1}]}"#).is_ok());
/// assert!(check(b"\xff{").is_ok());
/// assert!(check(b"{\"camera\": ").is_ok());
/// ```
pub fn check(data: &[u8]) -> Result<(), Failure> {
    check_with(data, render)
}

/// [`check`] with the renderer given, so a test can pass in a wrong one.
pub(crate) fn check_with(data: &[u8], render: fn(&Plan, Path) -> Frame) -> Result<(), Failure> {
    let Ok(text) = std::str::from_utf8(data) else {
        return Ok(());
    };
    let scene = match Scene::parse(text) {
        Ok(s) => s,
        Err(e) => return well_placed(text, &e),
    };
    // A camera valid at one resolution can fail at another (the basis
    // scales with the aspect ratio): an error, not a panic. At its own
    // resolution it stays valid.
    let Ok(scene) = scene.with_size(fuzz_size(scene.camera.res)) else {
        return Ok(());
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
    if x4.normal.is_empty() || x4.id.is_empty() {
        return fail("not every channel rendered".into());
    }
    // Encoding must not fail either, where the build has it.
    #[cfg(feature = "png")]
    if x4.pngs().len() != 3 {
        return fail("not every channel encoded".into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::{check_with, fuzz_size, well_placed};
    use crate::render::{Frame, Path, Plan, render};
    use crate::scene::SceneError;
    use std::cell::Cell;

    const SCENE: &[u8] = br#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
        "up": [0, 1, 0], "angle": 1, "res": [4, 3]},
        "spheres": [{"id": 1, "center": [0, 0, -3], "radius": 1}]}"#;

    thread_local! {
        /// How many frames the wrong renderers below have been asked for.
        static CALLS: Cell<u32> = const { Cell::new(0) };
    }

    /// The shipped renderer, with frame number `n` (from 1: reference,
    /// x4, un-specialised) given a wrong depth at pixel (1, 0).
    fn wrong_frame(plan: &Plan, path: Path, n: u32) -> Frame {
        let mut f = render(plan, path);
        if CALLS.with(|c| c.replace(c.get() + 1)) + 1 == n {
            f.depth[1] = 0.5;
        }
        f
    }

    /// Each check of the scene target fires on a renderer wrong in its way,
    /// naming what differs, and the shipped renderer passes.
    #[test]
    fn the_scene_check_fails_on_each_wrong_renderer() {
        assert_eq!(check_with(SCENE, render), Ok(()));
        type Render = fn(&Plan, Path) -> Frame;
        let wrong: [(Render, &str); 4] = [
            (
                |p, path| wrong_frame(p, path, 1),
                "reference and x4 frames differ first at pixel Some((1, 0))",
            ),
            (
                |p, path| wrong_frame(p, path, 2),
                "reference and x4 frames differ first at pixel Some((1, 0))",
            ),
            (
                |p, path| wrong_frame(p, path, 3),
                "the un-specialised plan's frame differs first at pixel Some((1, 0))",
            ),
            (
                |p, path| Frame {
                    normal: vec![],
                    ..render(p, path)
                },
                "not every channel rendered",
            ),
        ];
        for (r, why) in wrong {
            CALLS.with(|c| c.set(0));
            assert_eq!(check_with(SCENE, r).unwrap_err().0, why);
        }
    }

    /// The fuzz size keeps a frame of up to 384 pixels and clamps a larger
    /// one's sides to 24 × 16, at the edges of both rules.
    #[test]
    fn a_fuzzed_scene_is_rendered_at_most_24_by_16() {
        for (res, size) in [
            ([24, 16], [24, 16]),
            ([32, 12], [32, 12]),
            ([30, 2], [30, 2]),
            ([384, 1], [384, 1]),
            ([385, 1], [24, 1]),
            ([25, 16], [24, 16]),
            ([65535, 65535], [24, 16]),
            ([0, 7], [0, 7]),
        ] {
            assert_eq!(fuzz_size(res), size, "{res:?}");
        }
    }

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
