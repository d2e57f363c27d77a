//! `rayoracle report`, run as a user would: the table, the JSON rows, the
//! plots, and a broken catalogue.

use crate::cli::{run, temp_dir};

#[test]
fn quick_report_writes_the_table_the_json_rows_and_a_plot_per_kernel() {
    let dir = temp_dir("outputs");
    let (json, svg, md) = (
        dir.join("r.json"),
        dir.join("plots/r.svg"),
        dir.join("r.md"),
    );
    let (code, stdout, stderr) = run(&[
        "report",
        "--quick",
        "--json",
        json.to_str().unwrap(),
        "--svg",
        svg.to_str().unwrap(),
        "--md",
        md.to_str().unwrap(),
    ]);
    assert_eq!(code, 0, "{stderr}");
    assert!(
        stdout.contains("| family | cond. | variant | cases | max bits"),
        "{stdout}"
    );
    assert_eq!(
        std::fs::read_to_string(&md).unwrap().lines().next(),
        stdout.lines().next()
    );

    let text = std::fs::read_to_string(&json).unwrap();
    let rows: Vec<serde_json::Value> = serde_json::from_str(&text).unwrap();
    let keys = [
        "kernel",
        "variant",
        "family",
        "conditioning",
        "cases",
        "max_bits",
        "p99_bits",
        "mean_bits",
        "class_mismatches",
        "ns_per_ray",
        "stages",
        "front",
    ];
    for row in &rows {
        let obj = row.as_object().unwrap();
        let mut want = keys.to_vec();
        want.sort();
        assert_eq!(
            obj.keys().collect::<Vec<_>>(),
            want.iter().collect::<Vec<_>>(),
            "{row}"
        );
        assert!(row["ns_per_ray"].as_f64().unwrap() > 0.0, "{row}");
        assert!(
            row["cases"].as_u64().unwrap() <= 64,
            "--quick takes 64 cases a family"
        );
        assert!(
            matches!(row["conditioning"].as_str(), Some("well" | "ill")),
            "{row}"
        );
        assert!(row["front"].is_boolean(), "{row}");
        // The staged variants say which stage decided each case; the
        // others have no stages.
        let stages = row["stages"].as_object().unwrap();
        let staged = matches!(row["variant"].as_str(), Some("reference" | "x4"))
            && !row["kernel"].as_str().unwrap().starts_with("camera");
        if staged {
            let sum: f64 = stages.values().map(|v| v.as_f64().unwrap()).sum();
            assert!((sum - 1.0).abs() < 1e-9, "{row}");
            assert_eq!(
                stages.keys().collect::<Vec<_>>(),
                ["dd", "exact", "filter", "tight", "tracked"],
                "{row}"
            );
        } else {
            assert!(stages.is_empty(), "{row}");
        }
    }
    // Every kernel has a front.
    for kernel in ["sphere", "plane", "quadric", "camera"] {
        assert!(
            rows.iter()
                .any(|r| r["kernel"] == kernel && r["front"] == true),
            "{kernel}"
        );
    }
    // The keys in the issue's order, as written (the first row ends after
    // its last key, `front`).
    let end = text.find("\"front\"").unwrap();
    let first = &text[..end + text[end..].find('}').unwrap()];
    let at: Vec<usize> = keys
        .iter()
        .map(|k| first.find(&format!("\"{k}\"")).unwrap())
        .collect();
    assert!(at.windows(2).all(|w| w[0] < w[1]), "{first}");
    // Every family of the catalogue, every variant.
    let families: std::collections::BTreeSet<_> =
        rows.iter().map(|r| r["family"].as_str().unwrap()).collect();
    assert!(families.len() >= 20, "{families:?}");
    assert_eq!(rows.len(), families.len() * 5);

    for kernel in ["sphere", "plane", "quadric", "camera"] {
        let plot = std::fs::read_to_string(dir.join(format!("plots/r-{kernel}.svg"))).unwrap();
        assert!(
            plot.starts_with("<svg") && plot.contains("Pareto front"),
            "{kernel}"
        );
        for variant in ["textbook", "reference", "x4", "f64", "exact"] {
            assert!(plot.contains(variant), "{kernel} plot lacks {variant}");
        }
    }
}

#[test]
fn a_broken_catalogue_is_reported_with_its_file_and_line() {
    let dir = temp_dir("broken");
    std::fs::write(
        dir.join("families.json"),
        r#"[{"family": "sphere/x", "kernel": "sphere", "conditioning": "well", "why": "test"}]"#,
    )
    .unwrap();
    std::fs::write(
        dir.join("sphere.jsonl"),
        "{\"kind\":\"sphere\",\"family\":\"sphere/x\",\"origin\":[0,0,-5],\"dir\":[0,0,1],\"center\":[0,0,0],\"radius\":1}\n{\"kind\":\"sphere\",\"family\":\"sphere/x\",\"origin\":[0,0,-5]}\n",
    )
    .unwrap();
    let (code, _, stderr) = run(&["report", "--quick", "--stiff", dir.to_str().unwrap()]);
    assert_eq!(code, 2);
    assert!(stderr.contains("sphere.jsonl:2: dir: missing"), "{stderr}");
}
