//! `scatter`, the scene generator: N spheres over a plane, for the renderer or for POV-Ray,
//! and one-line errors for a bad count or destination.

use std::process::Command;

use whitted::render::{Chapter, Options, render};

const SCATTER: &str = env!("CARGO_BIN_EXE_scatter");

fn run(bin: &str, args: &[&str]) -> (i32, String, String) {
    let out = Command::new(bin)
        .args(args)
        .output()
        .expect("the binary runs");
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// `scatter N` writes a scene of N spheres over a plane that the chapters can render.
#[test]
fn scatter_writes_a_scene_of_n_spheres() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.toml");
    let (code, _, err) = run(
        SCATTER,
        &["25", "--seed", "3", "-o", scene.to_str().unwrap()],
    );
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&scene).unwrap();
    assert_eq!(text.matches("sphere = {").count(), 25);
    assert_eq!(text.matches("plane = {").count(), 1);
    // the chapters render it: it parses, and every pixel of a small render is traced
    let parsed = whitted::scene::parse(&text, "s.toml").unwrap();
    let mut options = Options::for_scene(&parsed, Chapter::ReflectionRefraction);
    (options.width, options.height) = (64, 48);
    let (fb, stats) = render(&parsed, &options);
    assert_eq!((fb.width, fb.height, stats.primary), (64, 48, 64 * 48));
    let (code, _, _) = run(SCATTER, &["0"]);
    assert_eq!(code, 2);
}

/// `scatter --pov` writes the scene for POV-Ray; a bad destination or count is one line with
/// status 2, and leaves an existing file as it was.
#[test]
fn scatter_writes_povray_scenes_and_refuses_bad_destinations_in_one_line() {
    let dir = tempfile::tempdir().unwrap();
    let pov = dir.path().join("s.pov");
    let (code, _, err) = run(SCATTER, &["12", "--pov", "-o", pov.to_str().unwrap()]);
    assert_eq!(code, 0, "{err}");
    let text = std::fs::read_to_string(&pov).unwrap();
    assert_eq!(
        text.lines().filter(|l| l.starts_with("sphere {")).count(),
        12
    );
    assert_eq!(text.matches("plane { y, 0").count(), 1);

    let missing = dir.path().join("no-such-dir").join("s.toml");
    for (args, what) in [
        (
            vec!["5", "-o", missing.to_str().unwrap()],
            "directory does not exist",
        ),
        (
            vec!["5", "-o", dir.path().to_str().unwrap()],
            "it is a directory",
        ),
        (vec!["0", "-o", pov.to_str().unwrap()], "0 is not in"),
        (vec!["5", "--layout", "grid"], "invalid value"),
    ] {
        let (code, _, err) = run(SCATTER, &args);
        assert_eq!(code, 2, "{args:?}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.starts_with("error:") && err.contains(what), "{err}");
    }
    // the earlier file is untouched by a failed run, and nothing is left behind
    assert_eq!(std::fs::read_to_string(&pov).unwrap(), text);
    let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
    assert_eq!(names.len(), 1, "{names:?}");
}
