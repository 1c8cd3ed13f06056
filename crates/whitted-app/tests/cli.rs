//! The command line as a user meets it: the default scene renders, malformed scenes and bad
//! flags give one line `error: file:line:col: …` with exit status 2 and no panic, and nothing
//! is written (or overwritten) when a run fails.

mod common;

use std::path::Path;
use std::process::Output;

use common::{exe, run};
use whitted::render::Chapter;

fn stderr(o: &Output) -> String {
    String::from_utf8_lossy(&o.stderr).into_owned()
}

fn png_size(path: &Path) -> (u32, u32) {
    let (width, height, _) = whitted::output::read_png(path).expect("a readable PNG");
    (width, height)
}

/// Every chapter renders the embedded showcase without arguments but a size, to its default
/// output name (its binary's), as a PNG of the requested size.
#[test]
fn every_chapter_renders_the_default_scene() {
    let dir = tempfile::tempdir().unwrap();
    for chapter in Chapter::ALL {
        let name = chapter.about().binary;
        let o = run(
            &exe(chapter),
            &["--width", "64", "--height", "48"],
            dir.path(),
        );
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let out = dir.path().join(format!("{name}.png"));
        assert_eq!(png_size(&out), (64, 48), "{name}");
    }
    // nothing but the images is left behind (no temporary files)
    let mut names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    names.sort();
    assert_eq!(names.len(), Chapter::ALL.len(), "{names:?}");
    assert!(
        names
            .iter()
            .all(|n| n.ends_with(".png") && !n.starts_with('.')),
        "{names:?}"
    );
}

/// A width alone keeps the scene's aspect ratio (the showcase is 640 × 480).
#[test]
fn width_alone_keeps_the_aspect_ratio() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(
        &exe(Chapter::GenericObjects),
        &["--width", "80", "-o", "a.png"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(png_size(&dir.path().join("a.png")), (80, 60));
}

/// Every scene in scenes/ loads, and each chapter has its own there.
#[test]
fn every_scene_file_loads() {
    for chapter in Chapter::ALL {
        let path = common::scene(chapter);
        assert!(
            path.is_file(),
            "chapter {chapter:?} has no scene {}",
            path.display()
        );
    }
    let scenes = common::root().join("scenes");
    let mut count = 0;
    for entry in std::fs::read_dir(&scenes).unwrap() {
        let path = entry.unwrap().path();
        if path.extension().is_some_and(|e| e == "toml") {
            let scene = whitted::scene::load(&path);
            assert!(scene.is_ok(), "{}: {:?}", path.display(), scene.err());
            count += 1;
        }
    }
    // the showcase and one a chapter at least
    assert!(count > Chapter::ALL.len(), "{count} scenes");
}

/// A malformed scene: exit status 2, one line `error: bad.toml:LINE:COL: …` containing what
/// was expected, no panic, and the existing output left as it was.
#[track_caller]
fn assert_scene_error(text: &str, line: usize, col: Option<usize>, needle: &str) {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("bad.toml"), text).unwrap();
    std::fs::write(dir.path().join("out.png"), b"previous image").unwrap();
    for chapter in [Chapter::GenericObjects, Chapter::ReflectionRefraction] {
        let bin = chapter.about().binary;
        let o = run(
            &exe(chapter),
            &["bad.toml", "-o", "out.png", "--width", "16"],
            dir.path(),
        );
        let err = stderr(&o);
        assert_eq!(o.status.code(), Some(2), "{bin} on {text:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
        assert_eq!(err.lines().count(), 1, "one line: {err}");
        let prefix = match col {
            Some(c) => format!("error: bad.toml:{line}:{c}: "),
            None => format!("error: bad.toml:{line}:"),
        };
        assert!(err.starts_with(&prefix), "expected {prefix:?}, got {err:?}");
        assert!(err.contains(needle), "expected {needle:?} in {err:?}");
        assert_eq!(
            std::fs::read(dir.path().join("out.png")).unwrap(),
            b"previous image"
        );
    }
}

/// An unknown key is refused at its line, listing the keys that exist.
#[test]
fn unknown_key_is_refused() {
    assert_scene_error(
        "[[objects]]\nsphere = { radius = 1 }\ncolour = 3\n",
        3,
        Some(1),
        "unknown field `colour`",
    );
    assert_scene_error(
        "[camera]\neye = [0, 0, 5]\nzoom = 2\n[[objects]]\nshape = \"cone\"\n",
        3,
        Some(1),
        "unknown field `zoom`",
    );
}

/// A value of the wrong type is refused where it stands.
#[test]
fn wrong_type_is_refused() {
    assert_scene_error(
        "[[objects]]\nsphere = { center = [0, 0, 0], radius = \"big\" }\n",
        2,
        Some(41),
        "invalid type",
    );
    assert_scene_error(
        "[[lights]]\nposition = [1, 2]\n[[objects]]\nshape = \"cone\"\n",
        2,
        None,
        "three numbers",
    );
}

/// NaN and infinity are refused.
#[test]
fn nan_and_infinity_are_refused() {
    assert_scene_error(
        "[[objects]]\nsphere = { center = [0, nan, 0] }\n",
        2,
        Some(21),
        "finite",
    );
    assert_scene_error(
        "[camera]\nnear = inf\n[[objects]]\nshape = \"cone\"\n",
        2,
        Some(8),
        "finite",
    );
}

/// Zero and negative sizes are refused.
#[test]
fn zero_or_negative_sizes_are_refused() {
    assert_scene_error(
        "[[objects]]\nsphere = { radius = -1 }\n",
        2,
        Some(21),
        "> 0",
    );
    assert_scene_error("[[objects]]\nsphere = { radius = 0 }\n", 2, Some(21), "> 0");
    assert_scene_error(
        "[image]\nwidth = 0\n[[objects]]\nshape = \"cone\"\n",
        2,
        Some(9),
        "from 1 to",
    );
    assert_scene_error(
        "[[objects]]\ncylinder = { base = [0, 0, 0], top = [0, 0, 0] }\n",
        2,
        None,
        "no height",
    );
    assert_scene_error(
        "[[objects]]\nbox = { min = [0, 0, 0], max = [1, 0, 1] }\n",
        2,
        None,
        "min < max",
    );
}

/// A zero scale is refused: M would have no inverse.
#[test]
fn zero_scale_is_refused() {
    assert_scene_error(
        "[[objects]]\nshape = \"cone\"\ntransform = [ { scale = [1, 0, 1] } ]\n",
        3,
        None,
        "non-zero scale",
    );
    assert_scene_error(
        "[[objects]]\nshape = \"cone\"\ntransform = [ { scale = 0 } ]\n",
        3,
        None,
        "non-zero scale",
    );
}

/// The viewing angle must lie strictly between 0° and 180°.
#[test]
fn fov_outside_the_open_interval_is_refused() {
    for fov in ["0", "180", "-10", "200"] {
        let text = format!("[camera]\nfov = {fov}\n[[objects]]\nshape = \"cone\"\n");
        assert_scene_error(&text, 2, Some(7), "between 0 and 180");
    }
}

/// A material that no [materials.NAME] table defines is refused at its name.
#[test]
fn undefined_material_is_refused() {
    assert_scene_error(
        "[materials.red]\ndiffuse = [0.5, 0, 0]\n[[objects]]\nshape = \"cone\"\nmaterial = \"gold\"\n",
        5,
        Some(12),
        "undefined material `gold`: expected one of red",
    );
}

/// An empty file (or one with only comments) is refused, as is a scene without objects.
#[test]
fn empty_file_is_refused() {
    assert_scene_error("", 1, Some(1), "empty");
    assert_scene_error("# nothing here\n\n", 1, Some(1), "empty");
    assert_scene_error("[camera]\neye = [0, 0, 5]\n", 3, None, "no objects");
}

/// Broken TOML syntax is reported at the place it breaks.
#[test]
fn syntax_error_is_reported_where_it_breaks() {
    assert_scene_error("[[objects]\nshape = \"cone\"\n", 1, None, "expected");
    assert_scene_error("[[objects]]\nshape = \"cone\n", 2, None, "");
}

/// Other checks: several shapes in one object, an unknown shape or step, a degenerate camera.
#[test]
fn other_scene_mistakes_are_refused() {
    assert_scene_error(
        "[[objects]]\nsphere = {}\nplane = {}\n",
        1,
        Some(1),
        "exactly one shape",
    );
    assert_scene_error(
        "[[objects]]\nshape = \"torus\"\n",
        2,
        Some(9),
        "unknown shape `torus`",
    );
    assert_scene_error(
        "[[objects]]\nshape = \"cone\"\ntransform = [ { spin = 3 } ]\n",
        3,
        None,
        "unknown variant `spin`",
    );
    assert_scene_error(
        "[camera]\neye = [0, 5, 0]\n[[objects]]\nshape = \"cone\"\n",
        1,
        None,
        "parallel",
    );
    assert_scene_error(
        "[[objects]]\npolyhedron = { preset = \"dodecahedron\" }\n",
        2,
        None,
        "cube, tetrahedron, octahedron",
    );
    assert_scene_error(
        "[[lights]]\nposition = [0, 1, 0]\nattenuation = [0, 0, 0]\n[[objects]]\nshape = \"cone\"\n",
        3,
        None,
        "cannot all be zero",
    );
}

/// Two keys in one transform step are refused with a message that says what a step is.
#[test]
fn two_keys_in_one_transform_step_are_refused() {
    assert_scene_error(
        "[[objects]]\nshape = \"cone\"\ntransform = [ { scale = 2, translate = [0, 1, 0] } ]\n",
        3,
        None,
        "a transform step has exactly one key",
    );
}

/// Bad flags and paths: one line, exit status 2, nothing written.
#[test]
fn bad_flags_and_paths_exit_with_status_2() {
    let dir = tempfile::tempdir().unwrap();
    let cases: [(&[&str], &str); 6] = [
        (&["--width", "0"], "--width"),
        (&["--bogus"], "--bogus"),
        (&["missing.toml"], "cannot read missing.toml"),
        (&["-o", "no/such/dir/x.png"], "directory does not exist"),
        (&["-o", "x.jpg"], "only PNG"),
        (&["--view", "sideways"], "sideways"),
    ];
    for (args, needle) in cases {
        let o = run(&exe(Chapter::GenericObjects), args, dir.path());
        let err = common::one_line_error(&o, &format!("{args:?}"));
        assert!(
            err.starts_with("error: ") && err.contains(needle),
            "{args:?}: {err}"
        );
    }
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        0,
        "nothing written"
    );
}

/// --help explains and exits 0.
#[test]
fn help_explains_and_exits_zero() {
    let dir = tempfile::tempdir().unwrap();
    let o = run(&exe(Chapter::ReflectionRefraction), &["--help"], dir.path());
    assert_eq!(o.status.code(), Some(0));
    let text = String::from_utf8_lossy(&o.stdout);
    for flag in [
        "--output",
        "--width",
        "--height",
        "--samples",
        "--max-depth",
        "--stats",
        "SCENE",
    ] {
        assert!(text.contains(flag), "{flag} missing from --help");
    }
}

/// A material whose ρa + ρd + ρs exceeds 1 is rendered, with a warning naming it.
#[test]
fn over_unity_material_warns_but_renders() {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(
        dir.path().join("s.toml"),
        "[materials.hot]\nambient = 0.5\ndiffuse = 0.6\nspecular = 0.2\n[[objects]]\nsphere = {}\nmaterial = \"hot\"\n",
    )
    .unwrap();
    let o = run(
        &exe(Chapter::Shading),
        &["s.toml", "-o", "s.png", "--width", "16"],
        dir.path(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("warning:") && err.contains("`hot`") && err.contains("exceeds 1"),
        "{err}"
    );
    assert!(dir.path().join("s.png").exists());
}

/// The command line takes exactly the names the library reports (`--accel octree` is
/// `Accel::Octree.name()`, and so on), each gives back its value, each has a help line, and a
/// name the library does not know is refused.
#[test]
fn command_line_names_are_the_library_names() {
    use whitted::accel::Accel;
    use whitted::offset::OffsetKind;
    use whitted::output::Encoding;
    use whitted::render::View;
    use whitted::scene::scatter::Layout;
    use whitted::shapes::Numerics;
    use whitted_app::cli::{Choice, choice};
    fn check<T: Choice + std::fmt::Debug + Clone>() {
        let command = || {
            clap::Command::new("t").arg(clap::Arg::new("v").long("v").value_parser(choice::<T>()))
        };
        for &value in T::all() {
            assert!(!value.help().is_empty(), "{value:?} has no help line");
            let matches = command()
                .try_get_matches_from(["t", "--v", value.name()])
                .unwrap_or_else(|e| panic!("--v {} is refused: {e}", value.name()));
            assert_eq!(matches.get_one::<T>("v"), Some(&value), "{}", value.name());
        }
        let refused = command().try_get_matches_from(["t", "--v", "no-such-name"]);
        assert!(refused.is_err(), "an unknown name was taken");
    }
    check::<Accel>();
    check::<Numerics>();
    check::<OffsetKind>();
    check::<View>();
    check::<Encoding>();
    check::<Layout>();
}

/// The binaries are the syllabus's chapters and nothing else: one file `src/bin/NAME.rs` a
/// chapter, named after the chapter's binary, which answers `--version` with that name (the
/// name comes from the `Chapter` the file runs); `cargo run` alone runs the last chapter.
#[test]
fn the_binaries_are_the_syllabus_chapters() {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("src/bin");
    let mut files: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().into_string().unwrap())
        .collect();
    files.sort();
    let expected: Vec<String> = Chapter::ALL
        .iter()
        .map(|c| format!("{}.rs", c.about().binary))
        .collect();
    assert_eq!(files, expected, "src/bin/ against the syllabus's binaries");
    for chapter in Chapter::ALL {
        let name = chapter.about().binary;
        let o = run(&common::exe_named(name), &["--version"], &dir);
        let said = String::from_utf8_lossy(&o.stdout);
        assert_eq!(
            said.split_whitespace().next(),
            Some(name),
            "src/bin/{name}.rs runs another chapter: its --version says {said:?}"
        );
    }
    let manifest =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("Cargo.toml")).unwrap();
    let last = Chapter::ALL[Chapter::ALL.len() - 1].about().binary;
    assert!(
        manifest.contains(&format!("default-run = \"{last}\"")),
        "crates/whitted-app/Cargo.toml: default-run should be the last chapter, {last}"
    );
}
