//! The speed flags on the command line: `--accel`, `--quiet`, the summary line and the
//! framebuffer limit (issue 5).

use std::process::Command;

mod common;

use whitted::render::Chapter;

fn run(chapter: Chapter, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(common::exe(chapter))
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// An image whose framebuffer would pass the limit is refused, in one line, with status 2,
/// before any work: nothing is written.
#[test]
fn an_oversized_image_is_refused_in_one_line_before_any_work() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("big.png");
    let (code, _, err) = run(
        Chapter::ReflectionRefraction,
        &[
            "-o",
            out.to_str().unwrap(),
            "--width",
            "65535",
            "--height",
            "65535",
        ],
    );
    assert_eq!(code, 2);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.starts_with("error: image 65535×65535 is too large"),
        "{err}"
    );
    assert!(!out.exists());
}

/// Every `--accel`, with packets and with `--no-packets`, writes the same PNG, byte for byte.
#[test]
fn every_accel_writes_the_same_png() {
    let dir = tempfile::tempdir().unwrap();
    let mut images = Vec::new();
    for accel in ["none", "boxes", "extents", "octree", "bvh"] {
        for packets in [None, Some("--no-packets")] {
            let out = dir.path().join(format!("{accel}-{packets:?}.png"));
            let mut args = vec![
                "-o",
                out.to_str().unwrap(),
                "--width",
                "64",
                "--accel",
                accel,
            ];
            args.extend(packets);
            args.push("-q");
            let (code, _, err) = run(Chapter::ReflectionRefraction, &args);
            assert_eq!(code, 0, "{err}");
            images.push(std::fs::read(&out).unwrap());
        }
    }
    assert_eq!(images.len(), 10);
    assert!(images.iter().all(|i| *i == images[0]));
    let (code, _, err) = run(
        Chapter::GenericObjects,
        &["-o", "/dev/null.png", "--accel", "kd-tree"],
    );
    assert_eq!(code, 2, "{err}");
}

/// `--quiet` prints nothing; otherwise the last line gives size, rays by kind, time, M rays/s.
#[test]
fn the_last_line_sums_up_the_render_unless_quiet() {
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("s.png");
    let (code, _, err) = run(
        Chapter::ReflectionRefraction,
        &["-o", out.to_str().unwrap(), "--width", "48", "-q"],
    );
    assert_eq!((code, err.as_str()), (0, ""));
    let (code, _, err) = run(
        Chapter::ReflectionRefraction,
        &["-o", out.to_str().unwrap(), "--width", "48"],
    );
    assert_eq!(code, 0);
    let last = err.lines().last().unwrap();
    assert!(last.starts_with("48×36: rays 1728 primary, "), "{last}");
    for word in [
        "shadow",
        "reflected",
        "refracted",
        "total",
        " s, ",
        "M rays/s",
    ] {
        assert!(last.contains(word), "{last}");
    }
    // stderr is a pipe here, not a terminal: no progress bar is drawn
    assert!(!err.contains('%'), "{err}");
}
