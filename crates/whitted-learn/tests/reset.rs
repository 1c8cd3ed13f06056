//! `cargo learn reset`: an exercise's body back to the handout's `todo!()`, the old body kept,
//! in a small project of two exercises written in a temporary directory.

use std::path::{Path, PathBuf};
use std::process::Command;

use whitted_learn::learn::{Reset, reset};
use whitted_learn::{layout, manifest};

/// The manifest of the small project: `first` (3.1) and `second` (3.2), in `shading.rs`.
const MANIFEST: &str = r#"[prove]
test = "render_paths"
filter = "ch{chapter}_"

[[formula]]
function = "shading::a"
name = "first"
chapter = 3
section = "Shading"
formula = "x"
title = "The first"
task = "Do it."
hints = ["One.", "Two."]
points = 1

[[formula]]
function = "shading::b"
name = "second"
chapter = 3
section = "Shading"
formula = "x"
title = "The second"
task = "Do it."
hints = ["One.", "Two."]
points = 1

[handout]
tests = ["ch03_shading", "render_paths"]
"#;

/// The handout's body of `first`, as `whitted handout` writes it.
const FIRST_TODO: &str =
    "        todo!(\"exercise first (3.1): The first — see chapters/ch03_shading/README.md\")\n";

/// The source with `first`'s body `body` (its lines, newline-ended); `second` is the handout's.
fn source(body: &str) -> String {
    format!(
        "//! Shading.\n\nmod inner {{\n    pub fn a(x: f64) -> f64 {{\n        // BEGIN SOLUTION first\n{body}        // END SOLUTION\n    }}\n}}\n\n\
         pub fn b() -> f64 {{\n    // BEGIN SOLUTION second\n    todo!(\"exercise second (3.2): The second — see chapters/ch03_shading/README.md\")\n    // END SOLUTION\n}}\n"
    )
}

/// A project whose `shading.rs` is `text`; returns the directory and the file's relative path.
fn project(text: &str) -> (tempfile::TempDir, PathBuf) {
    let dir = tempfile::tempdir().unwrap();
    let chapters = dir.path().join("chapters");
    std::fs::create_dir_all(&chapters).unwrap();
    std::fs::write(chapters.join("formulas.toml"), MANIFEST).unwrap();
    let file = layout::core_src().join("shading.rs");
    std::fs::create_dir_all(dir.path().join(layout::core_src())).unwrap();
    std::fs::write(dir.path().join(&file), text).unwrap();
    (dir, file)
}

fn read(root: &Path, file: impl AsRef<Path>) -> String {
    std::fs::read_to_string(root.join(file)).unwrap()
}

fn manifest() -> manifest::Manifest {
    manifest::parse(MANIFEST, "formulas.toml").unwrap()
}

/// A written body becomes the handout's `todo!()` between the same marker lines, the rest of
/// the file unchanged; the old body is kept, under a line saying where it came from, in
/// `.whitted/reset/first-1.rs`; a second reset says the body is the handout's already and
/// changes nothing; a later reset keeps its body in `first-2.rs`, leaving `first-1.rs`.
#[test]
fn a_written_body_is_reset_and_kept_and_a_second_reset_says_so() {
    let written = "        let y = x * 2.0;\n        y + 1.0\n";
    let (dir, file) = project(&source(written));
    let root = dir.path();
    let m = manifest();

    let done = reset(root, &m, "3.1").unwrap();
    let kept1 = Path::new(".whitted").join("reset").join("first-1.rs");
    assert_eq!(
        done,
        Reset {
            index: 0,
            file: file.clone(),
            line: 6,
            kept: kept1.clone()
        }
    );
    assert_eq!(read(root, &file), source(FIRST_TODO));
    assert_eq!(
        read(root, &kept1),
        format!(
            "// exercise 3.1 (first): the body `cargo learn reset` took out of {}:6\n{written}",
            file.display()
        )
    );
    assert_eq!(
        done.said(&m),
        format!(
            "exercise 3.1 (first) is the handout's todo!() again at {}:6; your body is kept in {}",
            file.display(),
            kept1.display()
        )
    );

    let again = reset(root, &m, "first").unwrap_err().to_string();
    assert_eq!(
        again,
        format!(
            "exercise 3.1 (first) at {}:6 is the handout's todo!() already: nothing to reset",
            file.display()
        )
    );
    assert_eq!(read(root, &file), source(FIRST_TODO));
    let kept2 = Path::new(".whitted").join("reset").join("first-2.rs");
    assert!(!root.join(&kept2).exists(), "a refused reset kept a body");

    std::fs::write(root.join(&file), source("        x\n")).unwrap();
    assert_eq!(reset(root, &m, "first").unwrap().kept, kept2);
    assert_eq!(read(root, &file), source(FIRST_TODO));
    assert!(
        read(root, &kept2).ends_with(":6\n        x\n"),
        "{}",
        read(root, &kept2)
    );
    assert!(
        read(root, &kept1).ends_with(written),
        "first-1.rs was overwritten"
    );
}

/// A file saved with CRLF line endings keeps them: the handout's line ends as the BEGIN line.
#[test]
fn a_crlf_file_keeps_its_line_endings() {
    let crlf = |t: &str| t.replace('\n', "\r\n");
    let (dir, file) = project(&crlf(&source("        x\n")));
    reset(dir.path(), &manifest(), "3.1").unwrap();
    assert_eq!(read(dir.path(), &file), crlf(&source(FIRST_TODO)));
}

/// An unknown exercise, missing markers and an unclosed region are one-line errors that
/// change no file.
#[test]
fn what_cannot_be_reset_is_a_one_line_error_that_changes_nothing() {
    let m = manifest();
    let (dir, file) = project(&source("        x\n"));
    assert_eq!(
        reset(dir.path(), &m, "9.9").unwrap_err().to_string(),
        "there is no exercise 9.9: `cargo learn list` shows the ids"
    );
    let no_markers = source("        x\n").replace("        // BEGIN SOLUTION first\n", "");
    std::fs::write(dir.path().join(&file), &no_markers).unwrap();
    assert_eq!(
        reset(dir.path(), &m, "3.1").unwrap_err().to_string(),
        format!(
            "exercise 3.1 (first): no `// BEGIN SOLUTION first` … `// END SOLUTION` lines in {}: \
             put the two lines back around its body (`cargo learn` says where the exercise is)",
            layout::core_src().display()
        )
    );
    let unclosed = source("        x\n").replacen("        // END SOLUTION\n", "", 1);
    std::fs::write(dir.path().join(&file), &unclosed).unwrap();
    assert_eq!(
        reset(dir.path(), &m, "3.1").unwrap_err().to_string(),
        format!(
            "exercise 3.1 (first): {}: line 5: `// BEGIN SOLUTION first` is not closed by \
             `// END SOLUTION` before the next `// BEGIN SOLUTION`: put the marker lines back as \
             the handout had them",
            file.display()
        )
    );
    assert_eq!(read(dir.path(), &file), unclosed);
    assert!(
        !dir.path().join(".whitted").exists(),
        "an error kept a body"
    );
}

/// The command prints one line and exits 0; asked again, it prints one `error:` line on
/// stderr, nothing on stdout, and exits with status 2.
#[test]
fn the_command_says_one_line_and_exits_2_on_an_error() {
    let (dir, file) = project(&source("        x\n"));
    let run = || {
        Command::new(env!("CARGO_BIN_EXE_whitted-learn"))
            .arg("--root")
            .arg(dir.path())
            .args(["reset", "3.1"])
            .env("NO_COLOR", "1")
            .output()
            .unwrap()
    };
    let first = run();
    let kept = Path::new(".whitted").join("reset").join("first-1.rs");
    assert_eq!(first.status.code(), Some(0), "{first:?}");
    assert_eq!(
        String::from_utf8_lossy(&first.stdout),
        format!(
            "exercise 3.1 (first) is the handout's todo!() again at {}:6; your body is kept in {}\n",
            file.display(),
            kept.display()
        )
    );
    let second = run();
    assert_eq!(second.status.code(), Some(2), "{second:?}");
    assert_eq!(String::from_utf8_lossy(&second.stdout), "");
    assert_eq!(
        String::from_utf8_lossy(&second.stderr),
        format!(
            "error: exercise 3.1 (first) at {}:6 is the handout's todo!() already: nothing to reset\n",
            file.display()
        )
    );
}
