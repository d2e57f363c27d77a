//! `rayoracle render` and the no-argument default job, run as a user would.

use crate::cli::{run, run_in, temp_dir};

use std::path::Path;

fn png_size(path: &Path) -> (u32, u32) {
    let bytes = std::fs::read(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let r = png::Decoder::new(std::io::Cursor::new(bytes))
        .read_info()
        .unwrap();
    (r.info().width, r.info().height)
}

/// The compiled-in fixture scene `name`, written to `dir/name`: each test
/// reads files of its own directory, never one another test is writing.
fn fixture(dir: &Path, name: &str) -> String {
    let (_, text) = rayoracle::fixtures::SCENES
        .into_iter()
        .find(|s| s.0 == name)
        .unwrap_or_else(|| panic!("no scene {name}"));
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path.to_str().unwrap().to_string()
}

#[test]
fn render_writes_each_channel_at_the_asked_size_and_both_paths_write_the_same_bytes() {
    let dir = temp_dir("paths");
    let (x4, reference) = (dir.join("x4"), dir.join("ref"));
    for (out, path) in [(&x4, "x4"), (&reference, "reference")] {
        let (code, stdout, stderr) = run(&[
            "render",
            &fixture(&dir, "quadric-zoo.json"),
            "-o",
            out.to_str().unwrap(),
            "--path",
            path,
            "--size",
            "37x21",
        ]);
        assert_eq!(code, 0, "{stderr}");
        assert!(stdout.contains("37×21"), "{stdout}");
    }
    for channel in ["depth", "normal", "id"] {
        let file = format!("quadric-zoo.{channel}.png");
        assert_eq!(png_size(&x4.join(&file)), (37, 21));
        assert_eq!(
            std::fs::read(x4.join(&file)).unwrap(),
            std::fs::read(reference.join(&file)).unwrap(),
            "{file}"
        );
    }
}

#[test]
fn only_the_asked_channels_are_written() {
    let dir = temp_dir("channels");
    let out = dir.join("out");
    let (code, _, stderr) = run(&[
        "render",
        &fixture(&dir, "seed.json"),
        "-o",
        out.to_str().unwrap(),
        "--channel",
        "id",
        "--size",
        "16x12",
    ]);
    assert_eq!(code, 0, "{stderr}");
    let mut names: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    assert_eq!(names, vec!["seed.id.png"]);
}

#[test]
fn a_bad_scene_is_reported_with_its_place_and_the_others_are_still_rendered() {
    let dir = temp_dir("bad");
    let bad = dir.join("bad.json");
    std::fs::write(
        &bad,
        "{\"camera\": {\"position\": [0, 0, 0], \"dir\": [0, 0, -1],\n  \"up\": [0, 1, 0], \"angle\": 7, \"res\": [4, 3]}}\n",
    )
    .unwrap();
    let out = dir.join("out");
    let (code, stdout, stderr) = run(&[
        "render",
        bad.to_str().unwrap(),
        &fixture(&dir, "seed.json"),
        "-o",
        out.to_str().unwrap(),
        "--size",
        "8x6",
    ]);
    assert_eq!(code, 1);
    assert!(
        stderr.contains(&format!("{}:2:", bad.display())) && stderr.contains("camera.angle: 7"),
        "{stderr}"
    );
    assert!(stdout.contains("seed.json"), "{stdout}");
    assert_eq!(png_size(&out.join("seed.depth.png")), (8, 6));
}

#[test]
fn bad_flags_are_refused_before_any_work() {
    let dir = temp_dir("flags");
    let seed = fixture(&dir, "seed.json");
    let (code, _, stderr) = run(&["render", &seed, "-o", "x", "--size", "9"]);
    assert_eq!(code, 2, "clap's usage error");
    assert!(stderr.contains("WIDTHxHEIGHT"), "{stderr}");
    let (code, _, stderr) = run(&["render", &seed, "-o", "x", "--path", "gpu"]);
    assert_eq!(code, 2);
    assert!(stderr.contains("expected reference or x4"), "{stderr}");
    let (code, _, stderr) = run(&["render", &seed, "-o", "x", "--size", "70000x70000"]);
    assert_eq!(code, 1);
    assert!(
        stderr.contains("--size 70000x70000") && stderr.contains("limit"),
        "{stderr}"
    );
}

/// Two scenes of the same file name would write the same frames: the
/// second is refused by name and the run exits 1; `-o` naming a file is
/// refused before any work.
#[test]
fn scenes_that_would_overwrite_each_other_and_a_file_for_a_directory_are_refused() {
    let dir = temp_dir("same-stem");
    let (a, b) = (dir.join("a"), dir.join("b"));
    for d in [&a, &b] {
        std::fs::create_dir_all(d).unwrap();
        fixture(d, "seed.json");
    }
    let out = dir.join("out");
    let (sa, sb) = (a.join("seed.json"), b.join("seed.json"));
    let args = |o: &Path| {
        [
            sa.to_str(),
            sb.to_str(),
            Some("-o"),
            o.to_str(),
            Some("--size"),
            Some("8x6"),
        ]
        .map(Option::unwrap)
        .map(String::from)
    };
    let owned = args(&out);
    let argv: Vec<&str> = std::iter::once("render")
        .chain(owned.iter().map(String::as_str))
        .collect();
    let (code, stdout, stderr) = run(&argv);
    assert_eq!(code, 1, "{stderr}");
    assert!(
        stdout.contains(&format!("rendered {}", sa.display())),
        "{stdout}"
    );
    assert!(
        !stdout.contains(&format!("rendered {}", sb.display())),
        "{stdout}"
    );
    let want = format!(
        "{}: not rendered: its frames would overwrite those of {}",
        sb.display(),
        sa.display()
    );
    assert!(stderr.contains(&want), "{stderr}");

    let file = dir.join("a-file");
    std::fs::write(&file, "").unwrap();
    let owned = args(&file);
    let argv: Vec<&str> = std::iter::once("render")
        .chain(owned.iter().map(String::as_str))
        .collect();
    let (code, stdout, stderr) = run(&argv);
    assert_eq!(code, 2);
    assert_eq!(stdout, "");
    assert!(stderr.contains("is a file; name a directory"), "{stderr}");
}

/// From a directory outside the source tree: the cases, the catalogue and
/// the scene are compiled in, and the outputs land in `./out`.
#[test]
fn the_default_job_evaluates_the_fixtures_and_renders_the_default_scene() {
    let dir = temp_dir("default-job");
    let (code, stdout, stderr) = run_in(&dir, &[]);
    assert_eq!(code, 0, "{stderr}");
    assert!(stdout.contains("out/eval.jsonl"), "{stdout}");
    assert!(
        stdout.contains("camera.jsonl") && stdout.contains("sphere.jsonl"),
        "{stdout}"
    );
    let evaluated = std::fs::read_to_string(dir.join("out/eval.jsonl")).unwrap();
    assert!(evaluated.lines().count() > 100);
    for channel in ["depth", "normal", "id"] {
        let file = format!("out/seed.{channel}.png");
        assert!(stdout.contains(&file), "{stdout}");
        assert_eq!(png_size(&dir.join(file)), (160, 120));
    }
    assert!(stdout.contains("sphere/far-tiny"), "the report: {stdout}");
}
