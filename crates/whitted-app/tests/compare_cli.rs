//! `--compare REF.png` as `cargo learn` runs it: each chapter binary renders its chapter's
//! scene at the book's figure size and compares it with the figure (`docs/src/figures/`,
//! rendered so by `whitted figures`); the reference build is the same. A reference with a few
//! pixels changed is reported pixel for pixel; a reference of another size, or no PNG at
//! all, is one line of error with exit status 2 and nothing written; and a render that meets
//! an exercise not written yet still ends in the one line that names it.

mod common;

use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Output};

use common::{exe, run};
use whitted::output::{read_png, write_png};
use whitted::render::Chapter;
use whitted_app::compare::{GAP, Image, TOLERANCE};

/// What `cargo learn` runs: the chapter's scene at the figures' width, compared with the
/// chapter's figure.
fn figure(chapter: Chapter) -> PathBuf {
    common::root().join(chapter.about().figure())
}

/// The figures' width (docs/figures.toml renders the chapters' figures with `--width 240`).
const WIDTH: &str = "240";

fn text(bytes: &[u8]) -> String {
    String::from_utf8_lossy(bytes).into_owned()
}

/// Runs chapter `chapter`'s binary on its scene at the figures' width with `--compare
/// reference -o out.png` and `extra`, in `dir`.
fn compare(chapter: Chapter, reference: &Path, dir: &Path, extra: &[&str]) -> Output {
    let scene = common::scene(chapter);
    let mut args = vec![
        scene.to_str().unwrap(),
        "--width",
        WIDTH,
        "--compare",
        reference.to_str().unwrap(),
        "-o",
        "out.png",
    ];
    args.extend_from_slice(extra);
    run(&exe(chapter), &args, dir)
}

fn read(path: &Path) -> Image {
    let (w, h, rgb) = read_png(path).unwrap_or_else(|e| panic!("{e}"));
    Image::new(w, h, rgb).unwrap()
}

/// The part of `composite` from column `left`, `width` × `height` pixels.
fn crop(composite: &Image, left: u32, width: u32, height: u32) -> Image {
    let mut rgb = Vec::new();
    for y in 0..height {
        for x in left..left + width {
            rgb.extend_from_slice(&composite.pixel(x, y));
        }
    }
    Image::new(width, height, rgb).unwrap()
}

/// The share of pixels a render may have off the figures by more than [`TOLERANCE`]: none in
/// double precision, in which the figures are rendered; in single precision, as many as the
/// golden tests allow (0.5%: a grazing ray may hit or miss, a refracted one bend another way;
/// chapter 5's figure has 2 such pixels of 38400).
const SHARE: f64 = if cfg!(feature = "f32") { 0.005 } else { 0.0 };

/// The count of differing pixels a compare line gives (0 for "the same").
fn count(line: &str) -> usize {
    if line.starts_with("compare: the same as the reference") {
        return 0;
    }
    let rest = line
        .strip_prefix("compare: ")
        .unwrap_or_else(|| panic!("{line:?}"));
    let n = rest.split(' ').next().unwrap_or_default();
    n.parse().unwrap_or_else(|_| panic!("no count in {line:?}"))
}

/// Every chapter's binary, run as `cargo learn` runs it, finds its render the same as its
/// figure (within [`SHARE`]), says so in one line on stdout, exits 0, and writes the three
/// images side by side: the render, the figure itself, and their difference, grey wherever
/// nothing differs.
#[test]
fn every_chapter_is_the_same_as_its_figure() {
    let dir = tempfile::tempdir().unwrap();
    let same = format!(
        "compare: the same as the reference (no pixel differs by more than {TOLERANCE}/255)\n"
    );
    for chapter in Chapter::ALL {
        let name = chapter.about().binary;
        let reference = figure(chapter);
        let o = compare(chapter, &reference, dir.path(), &[]);
        assert_eq!(o.status.code(), Some(0), "{name}: {}", text(&o.stderr));
        let line = text(&o.stdout);
        let fig = read(&reference);
        let (w, h) = fig.size();
        let allowed = (SHARE * f64::from(w * h)) as usize;
        assert!(
            line == same || (line.lines().count() == 1 && count(&line) <= allowed),
            "{name}: {line:?}, expected {same:?} (or at most {allowed} pixels differing)"
        );
        let out = read(&dir.path().join("out.png"));
        assert_eq!(
            out.size(),
            (3 * w + 2 * GAP, h),
            "{name}: the composite's size"
        );
        assert_eq!(
            crop(&out, w + GAP, w, h),
            fig,
            "{name}: the middle is the figure"
        );
        let render = crop(&out, 0, w, h);
        let c = whitted_app::compare::compare(&render, &fig).unwrap();
        assert_eq!(c.line() + "\n", line, "{name}: the left is the render");
        let diff = crop(&out, 2 * (w + GAP), w, h);
        assert_eq!(diff, c.difference, "{name}: the right is the difference");
        let grey = diff
            .rgb
            .chunks_exact(3)
            .filter(|p| p[0] == p[1] && p[1] == p[2])
            .count();
        assert_eq!(
            grey,
            c.pixels - c.differing,
            "{name}: grey wherever nothing differs"
        );
    }
}

/// A reference with four pixels changed: the three changed by more than the tolerance are
/// counted, the first in row order is named, and they are marked in the difference image
/// (red for a large change, yellow at 16 steps' change to orange); the one changed by one
/// step is not. `--quiet` still prints the line, and only it.
#[test]
fn a_changed_reference_is_reported_pixel_by_pixel() {
    let dir = tempfile::tempdir().unwrap();
    let chapter = Chapter::GenericObjects;
    let mut fig = read(&figure(chapter));
    let (w, h) = fig.size();
    let mut set = |x: u32, y: u32, f: &dyn Fn([u8; 3]) -> [u8; 3]| {
        let i = 3 * (y * w + x) as usize;
        let p = f([fig.rgb[i], fig.rgb[i + 1], fig.rgb[i + 2]]);
        fig.rgb[i..i + 3].copy_from_slice(&p);
    };
    // far off: each channel moved by half the range
    let far = |p: [u8; 3]| p.map(|c| c.wrapping_add(128));
    set(200, 100, &far);
    set(17, 40, &far);
    set(3, 90, &|p| {
        [p[0], p[1], if p[2] >= 16 { p[2] - 16 } else { p[2] + 16 }]
    });
    set(5, 5, &|p| [p[0] ^ 1, p[1], p[2]]);
    let reference = dir.path().join("ref.png");
    write_png(&reference, w, h, &fig.rgb).unwrap();

    let o = compare(chapter, &reference, dir.path(), &["--quiet"]);
    assert_eq!(o.status.code(), Some(0), "{}", text(&o.stderr));
    assert_eq!(text(&o.stderr), "", "--quiet: nothing on stderr");
    let line = text(&o.stdout);
    assert!(
        line.starts_with("compare: 3 of 32400 pixels differ by more than 2/255 (0.01%), by up to ")
            && line.contains("; the first at (17, 40), where the render has "),
        "{line}"
    );
    // the first pixel's bytes: the render's are the figure's, the reference's moved by 128
    let rendered = read(&figure(chapter));
    let i = 3 * (40 * w + 17) as usize;
    let bytes = |p: &[u8]| format!("({}, {}, {})", p[0], p[1], p[2]);
    let said = format!(
        "where the render has {} and the reference {}\n",
        bytes(&rendered.rgb[i..i + 3]),
        bytes(&fig.rgb[i..i + 3])
    );
    assert!(
        line.ends_with(&said),
        "computed {line:?}, expected it to end {said:?}"
    );
    let out = read(&dir.path().join("out.png"));
    assert_eq!(
        crop(&out, w + GAP, w, h),
        fig,
        "the middle is the reference"
    );
    let diff = crop(&out, 2 * (w + GAP), w, h);
    assert_eq!(diff.pixel(17, 40), [255, 0, 0], "far off: red");
    assert_eq!(diff.pixel(200, 100), [255, 0, 0], "far off: red");
    let mark = diff.pixel(3, 90);
    assert!(
        mark[0] == 255 && mark[1] > 0 && mark[2] == 0,
        "16 steps: orange, {mark:?}"
    );
    let grey = diff.pixel(5, 5);
    assert!(
        grey[0] == grey[1] && grey[1] == grey[2] && grey[0] <= 127,
        "{grey:?}"
    );
}

/// A reference of another size than the render: one line naming both sizes and the flags
/// that render at the reference's, exit status 2, nothing written and nothing on stdout.
#[test]
fn a_reference_of_another_size_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    // chapter 3's scene at width 240 is 240×120; chapter 2's figure is 240×135
    let reference = figure(Chapter::GenericObjects);
    let o = compare(Chapter::Shading, &reference, dir.path(), &[]);
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(
        err,
        format!(
            "error: the reference {} is 240×135 but the render is 240×120: render with the reference's size (--width 240 --height 135)\n",
            reference.display()
        )
    );
    assert_eq!(text(&o.stdout), "");
    assert!(!dir.path().join("out.png").exists());
}

/// A reference that is no PNG, or no file: one line, exit status 2, nothing written; the
/// reference is not overwritten by `-o` naming it.
#[test]
fn an_unreadable_reference_is_one_line_of_error() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("not.png"), b"not a picture").unwrap();
    for (name, needle) in [
        ("not.png", "cannot read the reference "),
        ("missing.png", "cannot read the reference "),
    ] {
        let o = compare(Chapter::Shading, &dir.path().join(name), dir.path(), &[]);
        let err = common::one_line_error(&o, name);
        assert!(
            err.starts_with("error: ") && err.contains(needle) && err.contains(name),
            "{err}"
        );
        assert!(!dir.path().join("out.png").exists(), "{name}");
    }
    let reference = dir.path().join("out.png");
    std::fs::copy(figure(Chapter::Shading), &reference).unwrap();
    let before = std::fs::read(&reference).unwrap();
    let o = compare(Chapter::Shading, &reference, dir.path(), &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        text(&o.stderr).contains("is the reference itself"),
        "{}",
        text(&o.stderr)
    );
    assert_eq!(
        std::fs::read(&reference).unwrap(),
        before,
        "the reference is untouched"
    );
}

/// `--compare` and `--inspect` do not go together (one prints a tree and writes nothing).
#[test]
fn compare_and_inspect_do_not_go_together() {
    let dir = tempfile::tempdir().unwrap();
    let reference = figure(Chapter::GenericObjects);
    let o = compare(
        Chapter::GenericObjects,
        &reference,
        dir.path(),
        &["--inspect", "1,1"],
    );
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--compare") && err.contains("--inspect"),
        "{err}"
    );
}

/// Set in the child process of [`a_render_that_meets_a_missing_exercise_ends_in_one_line`].
const CHILD: &str = "WHITTED_TEST_MISSING_EXERCISE";

/// The panic of a handout's `todo!()` met on the render's worker threads, as a chapter
/// binary runs its render (and its comparison) under [`whitted_app::cli::guard`]: exit status
/// 2 and exactly one line on stderr naming the exercise, no backtrace, nothing on stdout.
/// The panic needs a process of its own, so the test runs itself again as the child.
#[test]
fn a_render_that_meets_a_missing_exercise_ends_in_one_line() {
    if std::env::var_os(CHILD).is_some() {
        let status = whitted_app::cli::guard(|| {
            use rayon::prelude::*;
            (0..4096u32).into_par_iter().for_each(|pixel| {
                if pixel == 2048 {
                    todo!(
                        "{}",
                        whitted_syllabus::todo::message(
                            "sphere_discriminant",
                            "2.7",
                            "The sphere's discriminant",
                            "chapters/ch02_generic_objects/README.md"
                        )
                    );
                }
            });
            println!("compare: never reached");
            Ok(())
        });
        std::process::exit(if status == ExitCode::SUCCESS { 0 } else { 2 });
    }
    let test = std::env::current_exe().unwrap();
    let o = Command::new(test)
        .args([
            "--exact",
            "a_render_that_meets_a_missing_exercise_ends_in_one_line",
            "--nocapture",
        ])
        .env(CHILD, "1")
        .env("RUST_BACKTRACE", "1")
        .output()
        .unwrap();
    let err = text(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert_eq!(
        err,
        "error: exercise 2.7 (sphere_discriminant) is not written yet: The sphere's discriminant — see chapters/ch02_generic_objects/README.md\n"
    );
    assert!(!text(&o.stdout).contains("compare:"), "{}", text(&o.stdout));
}
