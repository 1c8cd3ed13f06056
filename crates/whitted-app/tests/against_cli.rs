//! `--against TREES.json` on every chapter binary, as `cargo learn` runs it: the chapter's own
//! trees file agrees with the reference, in text and in JSON; a tree that differs is one line
//! naming the pixel, the node, the quantity with both values and the functions; with
//! `--compare` the picture comes too; a file of another chapter, or none, is one line of error.
//! And `--inspect-grid STEP`, which `whitted trees` reads.

mod common;

use common::{exe, root, run};
use whitted::render::Chapter;

/// The chapter's trees file, as a path from the workspace's root.
fn trees(chapter: Chapter) -> String {
    root()
        .join("chapters")
        .join(chapter.about().binary)
        .join("trees.json")
        .display()
        .to_string()
}

fn stdout(o: &std::process::Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

/// A run that succeeded, its stdout read as one JSON value a line.
fn json_lines(o: &std::process::Output) -> Vec<serde_json::Value> {
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    stdout(o)
        .lines()
        .map(|l| serde_json::from_str(l).unwrap())
        .collect()
}

/// Each chapter binary traces its chapter's trees file and finds every tree the reference's:
/// one summary line in text, one JSON line a pixel with `"differs": false`, and no image.
#[test]
fn each_chapter_agrees_with_its_trees_and_writes_no_image() {
    let dir = tempfile::tempdir().unwrap();
    for chapter in Chapter::ALL {
        let scene = common::scene(chapter).display().to_string();
        let file = trees(chapter);
        let o = run(&exe(chapter), &[&scene, "--against", &file], dir.path());
        assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
        let text = stdout(&o);
        assert_eq!(text.lines().count(), 1, "{text}");
        assert!(
            text.starts_with("against: the ") && text.contains("pixels' trees are the reference's"),
            "{text}"
        );
        let o = run(
            &exe(chapter),
            &[&scene, "--against", &file, "--json"],
            dir.path(),
        );
        let lines = json_lines(&o);
        assert!(lines.len() >= 3, "{lines:?}");
        for l in &lines {
            assert_eq!(l["differs"], false, "{l}");
            assert!(l["pixel"].is_array(), "{l}");
        }
    }
    assert!(std::fs::read_dir(dir.path()).unwrap().next().is_none());
}

/// A trees file whose reference says another t: the pixel's line names the node, t with both
/// values and the plane's intersection; in JSON the same, with the quantity's key and the
/// nodes' kinds. With --compare, the picture's line comes first and the image is written.
#[test]
fn a_tree_that_differs_is_one_line_with_the_node_the_quantity_and_the_functions() {
    let dir = tempfile::tempdir().unwrap();
    let chapter = Chapter::Shadows;
    let mut doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(trees(chapter)).unwrap()).unwrap();
    let pixels = doc["pixels"].as_array_mut().unwrap();
    let floor = pixels
        .iter_mut()
        .find(|p| p["tree"]["samples"][0]["ray"]["hit"]["name"] == "floor")
        .expect("a pixel of the floor");
    let (x, y) = (floor["pixel"][0].clone(), floor["pixel"][1].clone());
    let hit = &mut floor["tree"]["samples"][0]["ray"]["hit"];
    let t = hit["t"].as_f64().unwrap();
    hit["t"] = (t + 1.0).into();
    let file = dir.path().join("doctored.json");
    std::fs::write(&file, doc.to_string()).unwrap();
    let file = file.display().to_string();
    let scene = common::scene(chapter).display().to_string();

    let o = run(&exe(chapter), &[&scene, "--against", &file], dir.path());
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = stdout(&o);
    let line = text.lines().next().unwrap();
    assert!(
        line.starts_with(&format!(
            "against: pixel ({x}, {y}), camera ray → hit `floor`: t: "
        )) && line.contains("(the reference: ")
            && line.contains("computed by shapes::plane::intersect"),
        "{text}"
    );
    assert!(text.contains("against: 1 of "), "{text}");

    let png = dir.path().join("picture.png").display().to_string();
    let figure = root().join(chapter.about().figure()).display().to_string();
    let o = run(
        &exe(chapter),
        &[
            &scene,
            "--width",
            "240",
            "--compare",
            &figure,
            "-o",
            &png,
            "--against",
            &file,
            "--json",
            "-q",
        ],
        dir.path(),
    );
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    let text = stdout(&o);
    let mut lines = text.lines();
    assert!(
        lines
            .next()
            .unwrap()
            .starts_with("compare: the same as the reference"),
        "{text}"
    );
    let differs: Vec<serde_json::Value> = lines
        .map(|l| serde_json::from_str::<serde_json::Value>(l).unwrap())
        .filter(|l| l["differs"] == true)
        .collect();
    assert_eq!(differs.len(), 1, "{text}");
    let d = &differs[0];
    assert_eq!(d["quantity"], "t");
    assert_eq!(d["nodes"], serde_json::json!(["camera ray", "hit"]));
    assert_eq!(
        d["reference"],
        whitted::render::inspect::provenance::number(t + 1.0)
    );
    assert!(
        d["text"]
            .as_str()
            .unwrap()
            .starts_with(&format!("pixel ({x}, {y}), "))
    );
    assert!(std::path::Path::new(&png).is_file());
}

/// Another chapter's trees, a file that is not one, and --against with --inspect are each one
/// line `error: …` with exit status 2.
#[test]
fn wrong_trees_files_exit_with_status_2() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("not.json"), "{ \"version\": 7 }").unwrap();
    let ch4 = exe(Chapter::Shadows);
    let five = trees(Chapter::ReflectionRefraction);
    let cases: [(&[&str], &str); 4] = [
        (&["--against", &five], "run `ch05_reflection_refraction`"),
        (&["--against", "not.json"], "version 1 is expected"),
        (&["--against", "missing.json"], "cannot read missing.json"),
        (
            &["--against", &five, "--inspect", "1,1"],
            "cannot be used with",
        ),
    ];
    let scene = common::scene(Chapter::Shadows).display().to_string();
    for (args, needle) in cases {
        let mut all = vec![scene.as_str()];
        all.extend(args);
        let o = run(&ch4, &all, dir.path());
        let err = common::one_line_error(&o, &format!("{args:?}"));
        assert!(
            err.starts_with("error: ") && err.contains(needle),
            "{args:?}: {err}"
        );
    }
}

/// `--inspect-grid STEP` prints the settings, then the tree of every STEP-th pixel of every
/// STEP-th row, from STEP/2, row by row.
#[test]
fn the_grid_is_the_settings_then_every_steps_tree() {
    let dir = tempfile::tempdir().unwrap();
    let scene = common::scene(Chapter::Shading).display().to_string();
    let o = run(
        &exe(Chapter::Shading),
        &[
            &scene,
            "--width",
            "48",
            "--height",
            "24",
            "--inspect-grid",
            "8",
        ],
        dir.path(),
    );
    let lines = json_lines(&o);
    assert_eq!(lines[0]["settings"]["width"], 48);
    assert_eq!(lines[0]["settings"]["chapter"], 3);
    let pixels: Vec<(u64, u64)> = lines[1..]
        .iter()
        .map(|t| {
            (
                t["pixel"][0].as_u64().unwrap(),
                t["pixel"][1].as_u64().unwrap(),
            )
        })
        .collect();
    let expected: Vec<(u64, u64)> = [4, 12, 20]
        .into_iter()
        .flat_map(|y| [4, 12, 20, 28, 36, 44].into_iter().map(move |x| (x, y)))
        .collect();
    assert_eq!(pixels, expected);
}
