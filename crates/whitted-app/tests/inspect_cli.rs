//! `--inspect X,Y [--json]` on the chapters that trace objects, as a student runs it: the tree printed for a
//! pixel of each chapter's scene has the colour and the bytes of that pixel in the `-o` render
//! (in either `--encoding`), no image is written, and a pixel outside the image is one line
//! of error with exit status 2.

mod common;

use common::{exe, run};
use whitted::output::Encoding;
use whitted::real::Real;
use whitted::render::Chapter;
use whitted_app::cli::OBJECTS_FROM;

/// The chapters that offer `--inspect`.
fn inspecting() -> impl Iterator<Item = Chapter> {
    Chapter::ALL.into_iter().filter(|&c| c >= OBJECTS_FROM)
}

/// For a few pixels of each chapter's scene, in the default sRGB encoding and with
/// `--encoding linear`: the bytes `--inspect X,Y --json` prints, and its colour encoded as
/// the PNG encodes it, are that pixel of the `-o` render; the text form names the same pixel,
/// chapter and bytes; neither writes a file.
#[test]
fn the_inspected_colour_is_the_rendered_pixel_in_every_chapter() {
    let dir = tempfile::tempdir().unwrap();
    for encoding in [Encoding::Srgb, Encoding::Linear] {
        // the default is sRGB: no flag for it
        let flag: &[&str] = match encoding {
            Encoding::Srgb => &[],
            Encoding::Linear => &["--encoding", "linear"],
        };
        for chapter in inspecting() {
            let (bin, exe) = (chapter.about().binary, exe(chapter));
            let scene = common::scene(chapter).display().to_string();
            let png = dir.path().join("out.png");
            let size = ["--width", "80"];
            let mut args = vec![
                scene.as_str(),
                "-o",
                png.to_str().unwrap(),
                size[0],
                size[1],
            ];
            args.extend(flag);
            args.push("-q");
            let o = run(&exe, &args, dir.path());
            assert!(
                o.status.success(),
                "{bin}: {}",
                String::from_utf8_lossy(&o.stderr)
            );
            let (w, h, rgb) = whitted::output::read_png(&png).unwrap();
            std::fs::remove_file(&png).unwrap();
            for (x, y) in [(w / 2, h / 2), (3, h - 2), (w - 5, 4), (w / 3, 2 * h / 3)] {
                let pixel = format!("{x},{y}");
                let inspect = |json: bool| {
                    let mut args = vec![scene.as_str(), size[0], size[1], "--inspect", &pixel];
                    args.extend(flag);
                    if json {
                        args.push("--json");
                    }
                    let o = run(&exe, &args, dir.path());
                    assert!(
                        o.status.success(),
                        "{bin}: {}",
                        String::from_utf8_lossy(&o.stderr)
                    );
                    o.stdout
                };
                let at = 3 * (y * w + x) as usize;
                let png_bytes = [rgb[at], rgb[at + 1], rgb[at + 2]];
                let v: serde_json::Value = serde_json::from_slice(&inspect(true)).expect("JSON");
                assert_eq!(v["chapter"], chapter.number());
                assert_eq!(v["pixel"], serde_json::json!([x, y]));
                assert_eq!(v["encoding"], encoding.name());
                let rgb: Vec<u8> = v["colour"]
                    .as_array()
                    .unwrap()
                    .iter()
                    .map(|c| encoding.byte(c.as_f64().unwrap() as Real))
                    .collect();
                let what = format!("{bin} pixel ({x}, {y}), {}", encoding.name());
                assert_eq!(rgb, png_bytes, "{what}");
                assert_eq!(v["bytes"], serde_json::json!(png_bytes), "{what}");

                let text = String::from_utf8(inspect(false)).unwrap();
                let head = format!("pixel ({x}, {y}), chapter {}", chapter.number());
                assert!(text.starts_with(&head), "{text}");
                let shown = format!("{png_bytes:?} in the {} PNG", shown_name(encoding));
                assert!(text.lines().next().unwrap().contains(&shown), "{text}");
                assert!(text.contains("camera ray r(t) = e + d·t"), "{text}");
            }
            let left: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
            assert!(left.is_empty(), "--inspect wrote {left:?}");
        }
    }
}

/// How the text of `--inspect` names the encoding of the PNG.
fn shown_name(encoding: Encoding) -> &'static str {
    match encoding {
        Encoding::Srgb => "sRGB",
        Encoding::Linear => "linear",
    }
}

/// A pixel outside the image, a malformed X,Y, --json alone and --inspect with -o are each one
/// line `error: …` with exit status 2; the chapters before objects have no --inspect.
#[test]
fn bad_inspect_requests_exit_with_status_2() {
    let dir = tempfile::tempdir().unwrap();
    let ch05 = &exe(Chapter::ReflectionRefraction);
    let cases: [(&std::path::Path, &[&str], &str); 6] = [
        (ch05, &["--inspect", "640,0"], "outside the 640×480 image"),
        (ch05, &["--inspect", "0,480"], "outside the 640×480 image"),
        (ch05, &["--inspect", "3x4"], "expected X,Y"),
        (ch05, &["--inspect", "-1,2"], "expected X,Y"),
        (ch05, &["--json"], "--inspect"),
        (
            ch05,
            &["--inspect", "1,1", "-o", "x.png"],
            "cannot be used with",
        ),
    ];
    for (bin, args, needle) in cases {
        let o = run(bin, args, dir.path());
        let err = common::one_line_error(&o, &format!("{args:?}"));
        assert!(
            err.starts_with("error: ") && err.contains(needle),
            "{args:?}: {err}"
        );
        assert!(!err.contains("panicked"));
    }
    for chapter in Chapter::ALL.into_iter().filter(|&c| c < OBJECTS_FROM) {
        let o = run(&exe(chapter), &["--inspect", "1,1"], dir.path());
        assert_eq!(o.status.code(), Some(2), "{chapter:?} took --inspect");
    }
    assert!(std::fs::read_dir(dir.path()).unwrap().next().is_none());
}
