#![cfg(feature = "png")]
//! Every fixture scene (`fixtures/scenes/*.json`), rendered through both
//! paths: the frames must be the same bits, and each channel's PNG is an
//! insta snapshot (`tests/snapshots/render_snapshots__SCENE_CHANNEL.snap.png`).
//!
//! When a channel's PNG differs from its accepted snapshot, this test writes
//! `…SCENE_CHANNEL.diff.png` next to it: old | new | heat map of the
//! difference, so `cargo insta review` can be done by looking, not by
//! reading numbers. The file is removed again once the snapshot matches.
#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]

use rayoracle::render::diff::{Comparison, diff_png};
use rayoracle::render::{Channels, Path, Plan, render};
use rayoracle::scene::Scene;
use std::path::{Path as FsPath, PathBuf};

const ROOT: &str = env!("CARGO_MANIFEST_DIR");

fn scene_files() -> Vec<PathBuf> {
    let mut files: Vec<PathBuf> = std::fs::read_dir(FsPath::new(ROOT).join("fixtures/scenes"))
        .unwrap()
        .map(|e| e.unwrap().path())
        .filter(|p| p.extension().is_some_and(|e| e == "json"))
        .collect();
    files.sort();
    files
}

/// Writes (or removes) the review diff for a snapshot: `snap_png` is the
/// accepted image, `new` the one just rendered. Returns the comparison when
/// they differ.
fn review_aid(snap_png: &FsPath, new: &[u8]) -> Option<Comparison> {
    let diff_path = snap_png.with_extension("").with_extension("diff.png");
    let old = std::fs::read(snap_png).ok();
    match old {
        Some(old) if old != new => {
            let (png, cmp) = diff_png(&old, new).expect("both are PNGs");
            std::fs::write(&diff_path, png).unwrap();
            eprintln!("{}: {cmp}; see {}", snap_png.display(), diff_path.display());
            Some(cmp)
        }
        _ => {
            let _ = std::fs::remove_file(&diff_path);
            None
        }
    }
}

#[test]
fn every_fixture_scene_is_the_same_bits_on_both_paths_and_matches_its_snapshots() {
    let files = scene_files();
    assert!(
        files.len() >= 9,
        "expected the fixture scenes, found {files:?}"
    );
    // Render everything and write every review diff first, so one run
    // shows every changed frame, not just the first failing assertion.
    let mut snapshots = Vec::new();
    for file in files {
        let scene = Scene::load(&file).unwrap_or_else(|e| panic!("{e}"));
        let plan = Plan::compile(&scene, Channels::ALL).unwrap();
        let reference = render(&plan, Path::Reference);
        let x4 = render(&plan, Path::X4);
        assert!(
            reference.same_bits(&x4),
            "{}: reference and x4 frames differ first at pixel {:?}",
            file.display(),
            reference.first_difference(&x4)
        );
        // Something is in view: a snapshot of an empty frame proves little.
        assert!(
            reference.depth.iter().any(|t| t.is_finite()),
            "{}: nothing hit",
            file.display()
        );
        let stem = file.file_stem().unwrap().to_str().unwrap().to_string();
        let ref_pngs = reference.pngs();
        assert_eq!(
            ref_pngs,
            x4.pngs(),
            "{stem}: PNG bytes differ between paths"
        );
        for (channel, bytes) in ref_pngs {
            let name = format!("{stem}_{channel}");
            let snap = FsPath::new(ROOT)
                .join("tests/snapshots")
                .join(format!("render_snapshots__{name}.snap.png"));
            review_aid(&snap, &bytes);
            snapshots.push((name, bytes));
        }
    }
    // Named as when this file was its own test binary (the module path
    // now starts with the harness, `all::`), so the snapshots keep their
    // names.
    insta::with_settings!({ prepend_module_to_snapshot => false }, {
        for (name, bytes) in snapshots {
            insta::assert_binary_snapshot!(&format!("render_snapshots__{name}.png"), bytes);
        }
    });
}

#[test]
fn the_review_aid_writes_a_diff_for_a_changed_frame_and_removes_it_when_it_matches() {
    // Removed on drop, a failing run's too.
    let dir = tempfile::tempdir().unwrap();
    let snap = dir.path().join("t__seed_depth.snap.png");
    let diff = dir.path().join("t__seed_depth.diff.png");
    let scene = Scene::load(FsPath::new(ROOT).join("fixtures/scenes/seed.json")).unwrap();
    let old = render(&Plan::compile(&scene, Channels::DEPTH).unwrap(), Path::X4).depth_png();
    let mut moved = scene.clone();
    moved.spheres[0].center.x += 0.25;
    let new = render(&Plan::compile(&moved, Channels::DEPTH).unwrap(), Path::X4).depth_png();
    std::fs::write(&snap, &old).unwrap();

    let cmp = review_aid(&snap, &new).expect("a moved sphere changes the frame");
    assert!(cmp.differing > 0 && cmp.differing < cmp.pixels, "{cmp}");
    let png = std::fs::read(&diff).unwrap();
    // old | new | heat: three 160-pixel panels and two 4-pixel gutters.
    let header = png::Decoder::new(std::io::Cursor::new(&png))
        .read_info()
        .unwrap()
        .info()
        .clone();
    assert_eq!((header.width, header.height), (3 * 160 + 8, 120));

    assert_eq!(review_aid(&snap, &old), None);
    assert!(
        !diff.exists(),
        "a stale diff is removed once the frame matches"
    );
}
