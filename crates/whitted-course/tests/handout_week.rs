//! A handout of its own week: `whitted handout --chapters 3-4` holds nothing of chapter 5's
//! answers (no body, no test, no golden image), lists its own exercises in its manifest, and
//! its loop counts those alone; a full handout is what it was. Nothing here builds a handout
//! (`tests/handout_build.rs` does, ignored in a plain `cargo test`).

mod common;

use common::{manifest, root};

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use whitted_course::handout::{self, later};
use whitted_course::learn::{self, State, Style};
use whitted_course::manifest::{self as manifests, Manifest};

/// Every file under `dir`, relative, with its bytes.
fn files(dir: &Path) -> BTreeMap<PathBuf, Vec<u8>> {
    let mut out = BTreeMap::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for e in std::fs::read_dir(&d).unwrap() {
            let p = e.unwrap().path();
            if p.is_dir() {
                stack.push(p);
            } else {
                out.insert(
                    p.strip_prefix(dir).unwrap().to_path_buf(),
                    std::fs::read(&p).unwrap(),
                );
            }
        }
    }
    out
}

/// The handout of chapters `lo` to `hi`, written into a new directory (kept alive by the
/// returned guard), with the selection.
fn week(m: &Manifest, lo: u8, hi: u8) -> (tempfile::TempDir, PathBuf, Vec<usize>) {
    let selected = handout::select(m, Some((lo, hi)), &[]).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("week");
    handout::write(&root(), m, &selected, &out).unwrap();
    (dir, out, selected)
}

/// The handout's own manifest, as its loop reads it.
fn own_manifest(handout: &Path) -> Manifest {
    manifests::load(&handout.join(manifests::DEFAULT_PATH)).unwrap()
}

/// The notes' "Reflection and Refraction": in a handout of chapters 3 and 4, not one line of
/// a chapter-5 body is anywhere (each body's lines of a dozen characters or more, searched in
/// every file, the book's pages included), and each chapter-5 body is the panic that says
/// chapter 5 is not part of the handout.
#[test]
fn a_handout_of_chapters_3_and_4_holds_no_chapter_5_answer() {
    let m = manifest();
    let (_guard, out, _) = week(&m, 3, 4);
    let texts: BTreeMap<PathBuf, String> = files(&out)
        .into_iter()
        .filter_map(|(p, b)| Some((p, String::from_utf8(b).ok()?)))
        .collect();
    let regions = handout::regions(&root(), &m).unwrap();
    let mut searched = 0;
    for r in regions.iter().filter(|r| m.entries[r.entry].chapter == 5) {
        let e = &m.entries[r.entry];
        let lines: Vec<&str> = r
            .solution
            .lines()
            .map(str::trim)
            .filter(|l| l.len() >= 12 && !l.starts_with("//"))
            .collect();
        assert!(
            !lines.is_empty(),
            "exercise {}: no line to search for",
            e.exercise.id
        );
        for line in lines {
            searched += 1;
            let found: Vec<&PathBuf> = texts
                .iter()
                .filter(|(_, t)| t.lines().any(|l| l.trim() == line))
                .map(|(p, _)| p)
                .collect();
            assert!(
                found.is_empty(),
                "exercise {} (chapter 5): its body's line `{line}` is in {found:?}",
                e.exercise.id
            );
        }
        let file = &texts[&r.file];
        let stub = later::later_statement(e);
        assert_eq!(
            file.matches(&stub).count(),
            1,
            "exercise {}: {stub} in {}",
            e.exercise.id,
            r.file.display()
        );
    }
    assert!(
        searched >= 5,
        "only {searched} lines of chapter 5's bodies searched"
    );
}

/// Of tests/, a handout of chapters 3 and 4 keeps the targets of chapters 1 to 4 and the
/// render paths' tests of those chapters only: every test the map says needs a chapter-5
/// exercise is gone (so every test left can pass once the handout's exercises are written), and
/// so are chapter 5's and the showcase's golden images.
#[test]
fn a_handout_of_chapters_3_and_4_keeps_no_test_of_chapter_5() {
    let m = manifest();
    let (_guard, out, _) = week(&m, 3, 4);
    let tests = out.join("crates/whitted/tests");
    let own = own_manifest(&out);
    assert_eq!(
        own.handout.tests,
        [
            "ch01_camera_rays",
            "ch02_generic_objects",
            "ch03_shading",
            "ch04_shadows",
            "render_paths"
        ],
        "the handout's test targets"
    );
    assert!(!tests.join("ch05_reflection_refraction.rs").exists());
    let golden: Vec<String> = std::fs::read_dir(tests.join("golden"))
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect::<std::collections::BTreeSet<_>>()
        .into_iter()
        .collect();
    assert_eq!(
        golden,
        [
            "ch01_camera_rays.png",
            "ch02_generic_objects.png",
            "ch03_shading.png",
            "ch04_shadows.png"
        ]
    );
    let paths = std::fs::read_to_string(tests.join("render_paths.rs")).unwrap();
    let map = whitted_course::deps::load_map(&root(), &m).unwrap();
    let mut gone = 0;
    for g in &map {
        let latest = g.needs.iter().map(|&i| m.entries[i].chapter).max();
        for t in g
            .tests
            .iter()
            .filter_map(|t| t.strip_prefix("render_paths::"))
        {
            let present = paths.contains(t);
            assert_eq!(
                present,
                latest.is_none_or(|c| c <= 4),
                "render_paths::{t} (needs chapters up to {latest:?}): present in the handout = {present}"
            );
            gone += usize::from(!present);
        }
    }
    assert_eq!(
        gone, 2,
        "render_paths::ch5_ and ::showcase_ should be the ones gone"
    );
    // the project's own render paths keep every section
    let project =
        std::fs::read_to_string(root().join("crates/whitted/tests/render_paths.rs")).unwrap();
    assert!(project.contains("ch5_road") && project.contains("showcase_road"));
}

/// The handout's manifest lists chapters 3 and 4's exercises as its own, and the loop reads
/// only those: `cargo learn`'s progress on an untouched handout says 0 of 11 (the manifest's
/// chapter-3 and chapter-4 exercises), with a bar for chapters 3 and 4 alone; its list names
/// none of the others; once they are all done the check says all 11 pass, and the picture is
/// never of chapter 5.
#[test]
fn the_loop_of_a_handout_of_chapters_3_and_4_counts_its_11_exercises() {
    let m = manifest();
    let (_guard, out, selected) = week(&m, 3, 4);
    let own = own_manifest(&out);
    let want: Vec<&str> = m
        .entries
        .iter()
        .filter(|e| (3..=4).contains(&e.chapter))
        .map(|e| e.exercise.name.as_str())
        .collect();
    assert_eq!(
        want.len(),
        11,
        "chapters 3 and 4 have {} exercises",
        want.len()
    );
    let names: Vec<&str> = own
        .entries
        .iter()
        .map(|e| e.exercise.name.as_str())
        .collect();
    assert_eq!(names, want);
    assert_eq!(selected.len(), 11);
    assert_eq!(
        own.handout.exercises.as_deref().map(<[String]>::len),
        Some(11)
    );
    assert_eq!(own.handout.others.len(), m.entries.len() - 11);
    // the displayed ids are the course's
    let ids: Vec<&str> = own.entries.iter().map(|e| e.exercise.id.as_str()).collect();
    assert_eq!(ids.first().copied(), Some("3.1"));
    assert_eq!(ids.last().copied(), Some("4.4"));
    assert_eq!(own.last_chapter(), 4);

    let todo = vec![State::ToDo; own.entries.len()];
    let progress = learn::progress(&own, &todo, Style::plain());
    assert_eq!(
        progress.lines().next(),
        Some("progress — 0 of 11 exercises done"),
        "{progress}"
    );
    let chapters: Vec<&str> = progress
        .lines()
        .skip(1)
        .filter_map(|l| l.trim_start().strip_prefix("chapter "))
        .map(|l| &l[..1])
        .collect();
    assert_eq!(chapters, ["3", "4"], "{progress}");
    let list = learn::list(&own, &todo, Style::plain());
    for e in m.entries.iter().filter(|e| !(3..=4).contains(&e.chapter)) {
        assert!(
            !list.contains(&format!(" {} ", e.function)),
            "the list names {} (chapter {}):\n{list}",
            e.function,
            e.chapter
        );
    }
    let done = vec![State::Done; own.entries.len()];
    assert_eq!(
        learn::progress(&own, &done, Style::plain()).lines().next(),
        Some("progress — 11 of 11 exercises done")
    );
    assert_eq!(
        learn::written_road(&own),
        "the road of one pixel is written up to chapter 4, the last of this handout"
    );
    assert_eq!(
        whitted_course::picture::drawable_chapter(&own, &done),
        Some(4)
    );
    assert_eq!(
        whitted_course::picture::picture_chapter(&own, &done, &done),
        4
    );
    // the map of tests reads past the exercises the handout leaves out
    let map = whitted_course::map::load_map(&out, &own).unwrap();
    assert!(
        map.iter()
            .flat_map(|g| &g.needs)
            .all(|&i| i < own.entries.len())
    );
}

/// A handout of every exercise is what it was: the project's manifest and render paths byte
/// for byte, every golden image, every test target, and no list of its own exercises.
#[test]
fn a_full_handout_keeps_the_manifest_and_every_test() {
    let m = manifest();
    let all: Vec<usize> = (0..m.entries.len()).collect();
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("all");
    handout::write(&root(), &m, &all, &out).unwrap();
    let got = files(&out);
    for file in [
        manifests::DEFAULT_PATH,
        "crates/whitted/tests/render_paths.rs",
        "crates/whitted/tests/ch05_reflection_refraction.rs",
        "crates/whitted/tests/golden/ch05_reflection_refraction.png",
        "crates/whitted/tests/golden/showcase.png",
    ] {
        let want = std::fs::read(root().join(file)).unwrap();
        assert!(
            got.get(Path::new(file)) == Some(&want),
            "{file} differs from the project's"
        );
    }
    assert_eq!(own_manifest(&out).handout.exercises, None);
    assert_eq!(own_manifest(&out).entries.len(), m.entries.len());
}

/// `[handout] exercises` names exercises of the manifest: an unknown name or an empty list is
/// an error at its line and column.
#[test]
fn a_handouts_list_of_exercises_names_known_exercises() {
    let text = std::fs::read_to_string(root().join(manifests::DEFAULT_PATH)).unwrap();
    let at = text.find("\ntests = [").unwrap();
    let line = text[..at].lines().count() + 1;
    for (list, says) in [
        (
            "[\"ambient\", \"no_such\"]",
            "\"no_such\" names no exercise",
        ),
        ("[]", "found none"),
    ] {
        let bad = text.replacen(
            "\ntests = [",
            &format!("\nexercises = {list}\ntests = ["),
            1,
        );
        let err = manifests::parse(&bad, "f.toml").unwrap_err().to_string();
        assert!(
            err.starts_with(&format!("f.toml:{line}:13: handout.exercises: "))
                && err.contains(says),
            "{err}"
        );
    }
    let one = text.replacen("\ntests = [", "\nexercises = [\"ambient\"]\ntests = [", 1);
    let m = manifests::parse(&one, "f.toml").unwrap();
    assert_eq!(m.entries.len(), 1);
    assert_eq!(m.entries[0].exercise.id, "3.1");
    // an exercise it leaves out, by name or by an id of a chapter it has none of, is named as
    // such; a key that is no exercise's is not
    for key in ["attenuation", "2.1", "5.3"] {
        let said = m.not_found(key);
        assert!(
            said.contains("is not one of this handout's"),
            "{key}: {said}"
        );
    }
    for key in ["9.9", "no_such", "3.9"] {
        let said = m.not_found(key);
        assert!(said.starts_with("there is no exercise"), "{key}: {said}");
    }
}

/// A handout of chapter 1's exercise `viewing_basis` alone ends at chapter 1: chapters 2 to 5
/// are later, and their render paths' sections are cut; a chapter section's marker without
/// its end is an error that names its line.
#[test]
fn the_sections_of_later_chapters_are_cut_and_a_broken_one_is_an_error() {
    let text = "a\n// BEGIN CHAPTER 2\nb\n// END CHAPTER\n// BEGIN CHAPTER 3 (why)\nc\n// END CHAPTER\nd\n";
    let f = Path::new("t.rs");
    assert_eq!(later::cut_later_sections(text, f, 5).unwrap(), text);
    assert_eq!(
        later::cut_later_sections(text, f, 2).unwrap(),
        "a\n// BEGIN CHAPTER 2\nb\n// END CHAPTER\nd\n"
    );
    assert_eq!(later::cut_later_sections(text, f, 1).unwrap(), "a\nd\n");
    let open = "a\n// BEGIN CHAPTER 4\nb\n";
    assert_eq!(
        later::cut_later_sections(open, f, 3)
            .unwrap_err()
            .to_string(),
        "t.rs:2: this chapter's section has no `// END CHAPTER` line"
    );
    let m = manifest();
    let one = handout::select(&m, None, &["viewing_basis".into()]).unwrap();
    assert_eq!(later::last_chapter(&m, &one), Some(1));
    assert_eq!(
        later::last_chapter(&m, &(0..m.entries.len()).collect::<Vec<_>>()),
        None
    );
}
