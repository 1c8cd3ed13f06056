//! The course tools: the manifest of formula functions (`chapters/formulas.toml`), the locator
//! that finds a function's body in the source, and the poison guards the proof puts there.
//! The proof itself (`whitted formulas prove`) builds the project and runs in CI.

use std::path::{Path, PathBuf};

use whitted_course::ToolError;
use whitted_course::cargo::TestOutcome;
use whitted_course::cargo::parse_libtest;
use whitted_course::manifest::{self, Entry, Exercise, Prove};
use whitted_course::poison::{guard, poisoned_sources};
use whitted_course::source::{self, Edit, edit_bodies, locate};

// ── the manifest ────────────────────────────────────────────────────────────────────────────

const GOOD: &str = r#"# two entries
[prove]
test = "render_paths"
filter = "ch{chapter}_"

[[formula]]
function = "camera::near_plane_half_height"
name = "half_height"
chapter = 1
section = "Principles of Ray Tracing"
formula = "H = N·tan(θ/2)"
title = "The near plane's half height"
task = "Return H."
hints = ["Half the angle.", "Degrees to radians."]
points = 2
[[formula]]
function = "shading::ambient"
name = "ambient"
chapter = 3
section = "Shading"
formula = "I_a = ρ_a·I_m"
title = "Ambient light"
task = "Return ρ_a·I_m."
hints = ["Per channel.", "A product of two vectors."]
points = 1
first_check = "is_per_channel"
picture = "ch03-ambient.png"

[handout]
tests = ["ch03_shading", "render_paths"]
"#;

/// The (line, column, message) of a manifest error; panics on success or another error.
#[track_caller]
fn manifest_error(text: &str) -> (usize, usize, String) {
    match manifest::parse(text, "m.toml") {
        Err(ToolError::Manifest {
            file,
            line,
            col,
            message,
        }) => {
            assert_eq!(file, "m.toml");
            (line, col, message)
        }
        other => panic!("expected a manifest error, got {other:?}"),
    }
}

/// A manifest with every key right reads into its entries, in order, with their lines.
#[test]
fn a_good_manifest_reads_every_entry_in_order() {
    let m = manifest::parse(GOOD, "m.toml").unwrap();
    assert_eq!(m.file, "m.toml");
    assert_eq!(
        m.prove,
        Prove {
            test: "render_paths".into(),
            filter: "ch{chapter}_".into()
        }
    );
    assert_eq!(m.prove.filter_for(3), "ch3_");
    assert_eq!(
        m.entries,
        vec![
            Entry {
                function: "camera::near_plane_half_height".into(),
                chapter: 1,
                section: "Principles of Ray Tracing".into(),
                formula: "H = N·tan(θ/2)".into(),
                line: 7,
                exercise: Exercise {
                    name: "half_height".into(),
                    id: "1.1".into(),
                    title: "The near plane's half height".into(),
                    task: "Return H.".into(),
                    hints: vec!["Half the angle.".into(), "Degrees to radians.".into()],
                    points: 2,
                    first_check: None,
                    picture: None,
                },
            },
            Entry {
                function: "shading::ambient".into(),
                chapter: 3,
                section: "Shading".into(),
                formula: "I_a = ρ_a·I_m".into(),
                line: 17,
                exercise: Exercise {
                    name: "ambient".into(),
                    id: "3.1".into(),
                    title: "Ambient light".into(),
                    task: "Return ρ_a·I_m.".into(),
                    hints: vec!["Per channel.".into(), "A product of two vectors.".into()],
                    points: 1,
                    first_check: Some("is_per_channel".into()),
                    picture: Some("ch03-ambient.png".into()),
                },
            },
        ]
    );
}

/// A first check that cannot end a test's name is refused at its value.
#[test]
fn a_first_check_that_is_no_test_name_is_an_error_at_its_value() {
    let bad = GOOD.replace(
        "first_check = \"is_per_channel\"",
        "first_check = \"Is per channel\"",
    );
    let (line, col, message) = manifest_error(&bad);
    assert_eq!((line, col), (26, 15), "{message}");
    assert!(
        message.starts_with("first_check: expected the rest of a test's name after `ex_ambient_`"),
        "{message}"
    );
}

/// A picture that is not a figure's plain file name is refused at its value.
#[test]
fn a_picture_that_is_no_figure_file_is_an_error_at_its_value() {
    for wrong in ["figures/ch03-ambient.png", "ch03-ambient", ".png"] {
        let bad = GOOD.replace(
            "picture = \"ch03-ambient.png\"",
            &format!("picture = \"{wrong}\""),
        );
        let (line, col, message) = manifest_error(&bad);
        assert_eq!((line, col), (27, 11), "{wrong}: {message}");
        assert!(
            message.starts_with("picture: expected a figure's file name ending in .png"),
            "{wrong}: {message}"
        );
    }
}

/// A key the format does not have is refused where it stands, in an entry or in [prove].
#[test]
fn an_unknown_key_is_an_error_at_its_line_and_column() {
    let text = GOOD.replace("chapter = 3\n", "chapter = 3\ncolour = \"red\"\n");
    let (line, col, message) = manifest_error(&text);
    assert_eq!((line, col), (20, 1));
    assert!(message.starts_with("unknown field `colour`"), "{message}");

    let text = GOOD.replace("filter =", "jobs = 2\nfilter =");
    let (line, col, message) = manifest_error(&text);
    assert_eq!((line, col), (4, 1));
    assert!(message.starts_with("unknown field `jobs`"), "{message}");
}

/// The same function twice is refused at the second one, naming the line of the first.
#[test]
fn a_function_listed_twice_is_an_error_at_the_second() {
    let text = GOOD.replace("\"shading::ambient\"", "\"camera::near_plane_half_height\"");
    let (line, col, message) = manifest_error(&text);
    assert_eq!((line, col), (17, 12));
    assert_eq!(
        message,
        "function camera::near_plane_half_height is listed twice (first on line 7)"
    );
}

/// Chapters are 1 to 5: 0, 6 and −1 are refused at the number.
#[test]
fn a_chapter_outside_one_to_five_is_an_error() {
    for bad in ["0", "6", "-1"] {
        let text = GOOD.replace("chapter = 3", &format!("chapter = {bad}"));
        let (line, col, message) = manifest_error(&text);
        assert_eq!((line, col), (19, 11), "chapter = {bad}");
        assert_eq!(message, format!("chapter: expected 1 to 5, found {bad}"));
    }
    let text = GOOD.replace("chapter = 3", "chapter = \"three\"");
    let (line, col, _) = manifest_error(&text);
    assert_eq!((line, col), (19, 11));
}

/// A section must be one of the notes' titles, and a function a path of at least two names.
#[test]
fn an_unknown_section_or_a_malformed_path_is_an_error() {
    let text = GOOD.replace("section = \"Shading\"", "section = \"Shadows\"");
    let (line, col, message) = manifest_error(&text);
    assert_eq!((line, col), (20, 11));
    assert!(
        message.starts_with("section: \"Shadows\" is not a section of the course notes"),
        "{message}"
    );

    for bad in [
        "ambient",
        "shading::",
        "shading::ambient()",
        "shading:: ambient",
    ] {
        let text = GOOD.replace("shading::ambient", bad);
        let (line, col, message) = manifest_error(&text);
        assert_eq!((line, col), (17, 12), "{bad}");
        assert!(
            message.starts_with("function: expected a path"),
            "{message}"
        );
    }
}

/// A manifest without any [[formula]], or without [prove], has nothing to prove.
#[test]
fn a_manifest_without_entries_or_prove_is_an_error() {
    let cut = GOOD.find("[[formula]]").unwrap();
    let no_entries = format!("{}[handout]\ntests = [\"render_paths\"]\n", &GOOD[..cut]);
    let (line, _, message) = manifest_error(&no_entries);
    assert_eq!(line, 2);
    assert!(
        message.starts_with("the manifest lists no function"),
        "{message}"
    );

    let (line, col, message) = manifest_error(&GOOD[GOOD.find("[[formula]]").unwrap()..]);
    assert_eq!((line, col), (1, 1));
    assert!(message.contains("missing field `prove`"), "{message}");
}

/// The project's own manifest reads, and each of its functions is found in `src/`.
#[test]
fn the_projects_manifest_names_functions_that_exist() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .unwrap();
    let m = manifest::load(&root.join(manifest::DEFAULT_PATH)).unwrap();
    assert!(m.entries.len() >= 30, "{} entries", m.entries.len());
    let found = whitted_course::source::locate_all(root, &m).unwrap();
    let ambient = m
        .entries
        .iter()
        .position(|e| e.function == "shading::ambient")
        .unwrap();
    assert_eq!(
        found[ambient].file,
        PathBuf::from("crates/whitted/src/shading.rs")
    );
    let text = std::fs::read_to_string(root.join("crates/whitted/src/shading.rs")).unwrap();
    let head = &text[..found[ambient].body.start];
    assert!(head.trim_end().ends_with("-> Vec3"), "{head}");
}

// ── the source locator ──────────────────────────────────────────────────────────────────────

const GEO: &str = "//! A module.

pub struct Rect {
    pub w: f64,
    pub h: f64,
}

/// Area of a w × h rectangle.
pub fn area(w: f64, h: f64) -> f64 {
    w * h
}

impl Rect {
    pub fn area(&self) -> f64 {
        area(self.w, self.h)
    }
}

impl std::fmt::Display for Rect {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, \"{}×{}\", self.w, self.h)
    }
}

#[cfg(feature = \"a\")]
pub fn twice() {}
#[cfg(not(feature = \"a\"))]
pub fn twice() {}

pub const fn fixed() -> u32 {
    7
}
";

/// A small crate in a temporary directory: `geo` (a file), `shapes` (a directory whose
/// `mod.rs` re-exports `inner::Thing`).
fn sample_crate() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    let write = |path: &str, text: &str| {
        let path = dir.path().join(path);
        std::fs::create_dir_all(path.parent().unwrap()).unwrap();
        std::fs::write(path, text).unwrap();
    };
    write(
        "crates/whitted/src/lib.rs",
        "pub mod geo;\npub mod shapes;\n",
    );
    write("crates/whitted/src/geo.rs", GEO);
    write(
        "crates/whitted/src/shapes/mod.rs",
        "mod inner;\npub use inner::{Thing, helper as assist};\n",
    );
    write(
        "crates/whitted/src/shapes/inner.rs",
        "pub struct Thing;\n\nimpl Thing {\n    pub fn size(&self) -> u8 { 3 }\n}\n\npub fn helper() {}\n",
    );
    dir
}

/// The text of a located body.
fn body_text(root: &Path, found: &source::Location) -> String {
    let text = std::fs::read_to_string(root.join(&found.file)).unwrap();
    text[found.body.clone()].to_string()
}

/// A free function is found in its module's file, body braces included.
#[test]
fn the_locator_finds_a_free_function() {
    let dir = sample_crate();
    let found = locate(dir.path(), "geo::area").unwrap();
    assert_eq!(found.file, PathBuf::from("crates/whitted/src/geo.rs"));
    assert_eq!(found.line, 9);
    assert!(!found.is_const);
    assert_eq!(body_text(dir.path(), &found), "{\n    w * h\n}");
    assert_eq!(&GEO[found.body.start - 7..found.body.start], "-> f64 ");
}

/// A method is found in an `impl Type` block, and in an `impl Trait for Type` block.
#[test]
fn the_locator_finds_a_method_in_an_impl_block() {
    let dir = sample_crate();
    let found = locate(dir.path(), "geo::Rect::area").unwrap();
    assert_eq!(
        (found.file.to_str(), found.line),
        (Some("crates/whitted/src/geo.rs"), 14)
    );
    assert_eq!(
        body_text(dir.path(), &found),
        "{\n        area(self.w, self.h)\n    }"
    );

    let found = locate(dir.path(), "geo::Rect::fmt").unwrap();
    assert_eq!(found.line, 20);
    assert_eq!(
        body_text(dir.path(), &found),
        "{\n        write!(f, \"{}×{}\", self.w, self.h)\n    }"
    );
}

/// `shapes::Thing::size` is found through `pub use inner::{Thing, …}`, and a renamed
/// re-export (`helper as assist`) is followed too.
#[test]
fn the_locator_follows_a_re_export() {
    let dir = sample_crate();
    let found = locate(dir.path(), "shapes::Thing::size").unwrap();
    assert_eq!(
        found.file,
        PathBuf::from("crates/whitted/src/shapes/inner.rs")
    );
    assert_eq!(
        (found.line, body_text(dir.path(), &found)),
        (4, "{ 3 }".into())
    );

    let found = locate(dir.path(), "shapes::assist").unwrap();
    assert_eq!(
        found.file,
        PathBuf::from("crates/whitted/src/shapes/inner.rs")
    );
    assert_eq!(
        (found.line, body_text(dir.path(), &found)),
        (7, "{}".into())
    );
}

/// A missing function, a missing method and a name defined twice are reported with the file.
#[test]
fn the_locator_reports_missing_and_ambiguous_functions() {
    let dir = sample_crate();
    assert_eq!(
        locate(dir.path(), "geo::perimeter").unwrap_err(),
        "no fn perimeter in crates/whitted/src/geo.rs"
    );
    assert_eq!(
        locate(dir.path(), "geo::Rect::volume").unwrap_err(),
        "no method volume in an `impl Rect` block in crates/whitted/src/geo.rs (nor a module `geo::Rect` with a file of its own)"
    );
    assert_eq!(
        locate(dir.path(), "geo::twice").unwrap_err(),
        "fn twice is defined 2 times in crates/whitted/src/geo.rs (lines 26, 28): the path must name exactly one"
    );
    assert_eq!(
        locate(dir.path(), "shapes::Thing::weight").unwrap_err(),
        "no method weight in an `impl Thing` block in crates/whitted/src/shapes/inner.rs (nor a module `shapes::inner::Thing` with a file of its own)"
    );
    assert!(locate(dir.path(), "geo::fixed").unwrap().is_const);
}

/// The proof refuses a const fn, whose body cannot read the poison switch, naming the entry.
#[test]
fn the_proof_refuses_a_const_fn() {
    let dir = sample_crate();
    let text = GOOD
        .replace("camera::near_plane_half_height", "geo::area")
        .replace("shading::ambient", "geo::fixed");
    let m = manifest::parse(&text, "m.toml").unwrap();
    let err = whitted_course::source::locate_all(dir.path(), &m)
        .unwrap_err()
        .to_string();
    assert_eq!(
        err,
        "m.toml:17: geo::fixed: is a const fn (crates/whitted/src/geo.rs:30): its body cannot test the poison switch"
    );
}

// ── editing bodies: the guards ──────────────────────────────────────────────────────────────

/// The guard goes right after the opening brace of the chosen body; every other byte of the
/// file stays as it was.
#[test]
fn the_guard_opens_the_right_body_and_nothing_else_changes() {
    let dir = sample_crate();
    let found = locate(dir.path(), "geo::Rect::area").unwrap();
    let statement = guard(4, "geo::Rect::area");
    assert_eq!(
        statement,
        " if crate::__poison::on(4) { todo!(\"poisoned: geo::Rect::area\") }"
    );
    let edited = edit_bodies(
        GEO,
        &[(found.body.clone(), Edit::Prepend(statement.clone()))],
    )
    .unwrap();
    let expected = GEO.replace(
        "    pub fn area(&self) -> f64 {\n",
        "    pub fn area(&self) -> f64 { if crate::__poison::on(4) { todo!(\"poisoned: geo::Rect::area\") }\n",
    );
    assert_eq!(edited, expected);
    // nothing before the body moved, and removing the guard gives the file back
    assert_eq!(&edited[..=found.body.start], &GEO[..=found.body.start]);
    assert_eq!(edited.replacen(&statement, "", 1), GEO);
    assert_eq!(edited.matches("__poison").count(), 1);
}

/// The proof's edit of a crate: each manifest function of a file gets its own numbered guard.
#[test]
fn poisoned_sources_number_each_function_by_its_entry() {
    let dir = sample_crate();
    let text = GOOD
        .replace("camera::near_plane_half_height", "geo::Rect::fmt")
        .replace("shading::ambient", "geo::area");
    let m = manifest::parse(&text, "m.toml").unwrap();
    let found = whitted_course::source::locate_all(dir.path(), &m).unwrap();
    let files = poisoned_sources(dir.path(), &m, &found).unwrap();
    assert_eq!(files.len(), 1);
    let edited = &files[Path::new("crates/whitted/src/geo.rs")];
    let expected = GEO
        .replace(
            "-> f64 {\n    w * h",
            "-> f64 { if crate::__poison::on(1) { todo!(\"poisoned: geo::area\") }\n    w * h",
        )
        .replace(
            "std::fmt::Result {\n",
            "std::fmt::Result { if crate::__poison::on(0) { todo!(\"poisoned: geo::Rect::fmt\") }\n",
        );
    assert_eq!(edited, &expected);
}

/// A body can be replaced (a handout's `todo!()`); overlapping or non-body ranges are refused.
#[test]
fn a_body_can_be_replaced_and_bad_ranges_are_refused() {
    let text = "fn a() -> u8 { 1 }\nfn b() -> u8 { 2 }\n";
    let a = 13..18;
    let b = 32..37;
    assert_eq!(&text[a.clone()], "{ 1 }");
    let edited = edit_bodies(
        text,
        &[
            (b.clone(), Edit::Replace(" todo!(\"exercise\") ".into())),
            (a.clone(), Edit::Prepend(" let x = 0;".into())),
        ],
    )
    .unwrap();
    assert_eq!(
        edited,
        "fn a() -> u8 { let x = 0; 1 }\nfn b() -> u8 { todo!(\"exercise\") }\n"
    );
    assert_eq!(
        edit_bodies(text, &[(13..20, Edit::Prepend(String::new()))]).unwrap_err(),
        "bytes 13..20 are not a body block { … } of the text"
    );
    assert_eq!(
        edit_bodies(
            text,
            &[
                (a.clone(), Edit::Prepend(String::new())),
                (14..18, Edit::Prepend(String::new()))
            ]
        )
        .unwrap_err(),
        "the bodies at bytes 13..18 and 14..18 overlap"
    );
}

/// libtest's lines `test NAME ... ok|FAILED|ignored` are read; other lines are not results.
#[test]
fn libtest_results_are_read_line_by_line() {
    let out = "\nrunning 4 tests\ntest ch2_none ... ok\ntest ch2_bvh ... FAILED\n\
               test ch2_slow ... ignored, takes a minute\ntest ch2_x has been running for over 60 seconds\n\
               \nfailures:\n    ch2_bvh\n\ntest result: FAILED. 1 passed; 1 failed; 1 ignored\n";
    assert_eq!(
        parse_libtest(out),
        vec![
            ("ch2_none".to_string(), TestOutcome::Passed),
            ("ch2_bvh".to_string(), TestOutcome::Failed),
            ("ch2_slow".to_string(), TestOutcome::Ignored),
        ]
    );
}

// ── the exercises ───────────────────────────────────────────────────────────────────────────

/// Every exercise key is required, the name a snake_case word; two or three hints; points 1
/// to 100. Each mistake is reported at its line and column.
#[test]
fn the_exercise_keys_are_checked_where_they_stand() {
    let text = GOOD.replace("points = 1\n", "");
    let (line, _, message) = manifest_error(&text);
    assert_eq!(line, 16, "{message}");
    assert!(message.contains("`points` is missing"), "{message}");

    let text = GOOD.replace("name = \"ambient\"\n", "");
    let (line, _, message) = manifest_error(&text);
    assert_eq!(line, 16, "{message}");
    assert!(message.contains("`name` is missing"), "{message}");

    for bad in [
        "Ambient",
        "ambient_",
        "_ambient",
        "amb__ient",
        "3ambient",
        "am-bient",
        "",
    ] {
        let text = GOOD.replace("name = \"ambient\"", &format!("name = {bad:?}"));
        let (line, col, message) = manifest_error(&text);
        assert_eq!((line, col), (18, 8), "{bad:?}");
        assert!(
            message.starts_with("name: expected a snake_case name"),
            "{message}"
        );
    }

    let text = GOOD.replace(
        "hints = [\"Per channel.\", \"A product of two vectors.\"]",
        "hints = [\"Per channel.\"]",
    );
    let (line, _, message) = manifest_error(&text);
    assert_eq!(line, 24);
    assert!(
        message.starts_with("hints: expected two or three"),
        "{message}"
    );

    let text = GOOD.replace("points = 2", "points = 0");
    let (line, col, message) = manifest_error(&text);
    assert_eq!((line, col), (15, 10));
    assert_eq!(message, "points: expected 1 to 100, found 0");
}

/// Two exercises cannot share a name, and no name followed by `_` may begin another (a test
/// `ex_half_height_of_x_…` would then be both exercises'): both are refused at the second
/// name, naming the line of the first.
#[test]
fn names_are_unique_and_none_begins_another() {
    for (second, says) in [
        (
            "half_height",
            "name \"half_height\" is taken (by the exercise on line 7)",
        ),
        (
            "half_height_of_x",
            "name \"half_height_of_x\": `half_height_` begins `half_height_of_x` (line 7 has the other)",
        ),
        (
            "half",
            "name \"half\": `half_` begins `half_height` (line 7 has the other)",
        ),
    ] {
        let text = GOOD.replace("name = \"ambient\"", &format!("name = {second:?}"));
        let (line, col, message) = manifest_error(&text);
        assert_eq!((line, col), (18, 8), "{second}");
        assert!(message.starts_with(says), "{second}: {message}");
    }
    // a name that only shares a first word is fine: `half_` does not begin `halves`
    let text = GOOD
        .replace("name = \"half_height\"", "name = \"half\"")
        .replace("name = \"ambient\"", "name = \"halves\"");
    assert!(manifest::parse(&text, "m.toml").is_ok());
}

/// An exercise's own tests are those named `ex_NAME_…`; a test is found by its name or its
/// displayed id, and a test belongs to the exercise whose prefix it has, or to none.
#[test]
fn an_exercises_tests_are_named_after_its_name() {
    let m = manifest::parse(GOOD, "m.toml").unwrap();
    assert_eq!(m.entries[1].exercise.test_prefix(), "ex_ambient_");
    assert_eq!(m.entries[0].exercise.test_prefix(), "ex_half_height_");
    assert_eq!(m.find("ambient"), Some(1));
    assert_eq!(m.find(" 3.1 "), Some(1));
    assert_eq!(m.find("1.1"), Some(0));
    assert_eq!(m.find("3.2"), None);
    assert_eq!(m.display("ambient"), "3.1");
    assert_eq!(m.display("gone"), "gone");
    assert_eq!(m.exercise_of_test("ex_ambient_is_a_product"), Some(1));
    assert_eq!(m.exercise_of_test("ex_half_height_at_90"), Some(0));
    assert_eq!(m.exercise_of_test("ex_ambient"), None);
    assert_eq!(m.exercise_of_test("ambient_is_a_product"), None);
}

/// The map of tests to exercises (chapters/exercise-tests.toml) names tests by prefix and
/// the exercises they need by name; a handout of some exercises is expected to fail the tests
/// that need one of them; a name that names nothing (an old id among them) is an error.
#[test]
fn the_test_map_names_tests_and_the_exercises_they_need() {
    use whitted_course::deps;
    let m = manifest::parse(GOOD, "m.toml").unwrap();
    let map = deps::parse_map(
        "[[tests]]\ntests = [\"render_paths::ch3_\"]\nneeds = [\"half_height\", \"ambient\"]\n\n[[tests]]\ntests = [\"ch03_shading::ex_ambient_\"]\nneeds = [\"ambient\"]\n",
        "map.toml",
        &m,
    )
    .unwrap();
    assert_eq!(map[0].needs, vec![0, 1]);
    assert!(map[0].matches("render_paths::ch3_road") && !map[0].matches("render_paths::ch4_road"));
    let tests = [
        "render_paths::ch3_road",
        "ch03_shading::ex_ambient_works",
        "render_paths::ch4_road",
    ]
    .map(String::from)
    .into_iter()
    .collect();
    assert_eq!(deps::expected(&map, &tests, &[0]).len(), 1);
    assert_eq!(deps::expected(&map, &tests, &[1]).len(), 2);
    assert_eq!(manifest::compress_ids(&m.entries, &[1, 0]), ["1.*", "3.*"]);
    let bad = deps::parse_map(
        "[[tests]]\ntests = [\"x::y\"]\nneeds = [\"3.1\"]\n",
        "map.toml",
        &m,
    );
    let message = bad.unwrap_err().to_string();
    assert!(
        message.starts_with("map.toml:3:9: needs: \"3.1\" names no exercise"),
        "{message}"
    );
}
