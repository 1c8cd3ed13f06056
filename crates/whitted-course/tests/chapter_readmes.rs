//! The chapters' texts point at the code that runs: every function the course book's chapter
//! page names in "The path of one pixel" exists where it says, and every formula function of a
//! chapter (`chapters/formulas.toml`) appears in that chapter's README, whose exercises the
//! manifest writes. (That the pixel each page inspects is what the binary prints is checked
//! beside the binaries, in `crates/whitted-app/tests/book_pages.rs`.)

mod common;

use common::root;

use std::path::Path;

use whitted_course::{manifest, source, syllabus};

/// The README of chapter `n`.
fn readme(n: u8) -> String {
    std::fs::read_to_string(root().join(syllabus::chapter(n).unwrap().readme())).unwrap()
}

/// The course book's page of chapter `n` (`docs/src/ch0N-….md`).
fn page(n: u8) -> String {
    std::fs::read_to_string(root().join(syllabus::chapter(n).unwrap().page())).unwrap()
}

/// The text of the section `## title` (up to the next `## `).
fn section<'a>(text: &'a str, title: &str) -> Option<&'a str> {
    let start = text.find(&format!("\n## {title}\n"))? + 1;
    let body = &text[start + 3 + title.len()..];
    Some(match body.find("\n## ") {
        Some(end) => &body[..end],
        None => body,
    })
}

/// The crate paths written in backticks (`render::Tracer::pixel(x, y)` gives
/// `render::Tracer::pixel`): those whose first segment is one of the crate's modules.
fn crate_paths(text: &str, modules: &[String]) -> Vec<String> {
    let mut out = Vec::new();
    for (i, piece) in text.split('`').enumerate() {
        if i % 2 == 0 {
            continue; // outside backticks
        }
        let path: String = piece
            .chars()
            .take_while(|c| c.is_alphanumeric() || *c == '_' || *c == ':')
            .collect();
        let first = path.split("::").next().unwrap_or("");
        if path.contains("::") && modules.iter().any(|m| m == first) {
            out.push(path.trim_end_matches(':').to_string());
        }
    }
    out
}

/// The crate's top-level modules (the files and directories of `src/`).
fn modules(root: &Path) -> Vec<String> {
    std::fs::read_dir(root.join("crates/whitted/src"))
        .unwrap()
        .map(|e| {
            let name = e.unwrap().file_name().to_string_lossy().into_owned();
            name.trim_end_matches(".rs").to_string()
        })
        .filter(|m| m != "lib")
        .collect()
}

/// A path names a function when the locator finds it, or else a type or module whose name
/// the file of its parent module defines.
fn exists(root: &Path, path: &str) -> Result<(), String> {
    match source::locate(root, path) {
        Ok(_) => Ok(()),
        Err(fn_error) => {
            // not a function: a module (`render::tracer`), a type, a constant or a variant?
            let segments: Vec<String> = path.split("::").map(str::to_string).collect();
            if source::module_file(root, &segments).is_some() {
                return Ok(());
            }
            let (parent, last) = segments.split_at(segments.len() - 1);
            let names_item = |file: &Path| {
                let text = std::fs::read_to_string(root.join(file)).unwrap_or_default();
                [
                    "struct", "enum", "type", "const", "trait", "fn", "mod", "static",
                ]
                .iter()
                .any(|kind| text.contains(&format!("{kind} {}", last[0])))
                    || text.contains(&format!("    {}(", last[0]))
                    || text.contains(&format!("    {},", last[0]))
                    || text.contains(&format!("    {} {{", last[0]))
            };
            match source::module_file(root, parent) {
                Some(file) if names_item(&file) => Ok(()),
                _ => Err(fn_error),
            }
        }
    }
}

/// Every crate path in a chapter's "The path of one pixel" names something that exists.
#[test]
fn the_path_of_one_pixel_names_real_functions() {
    let root = root();
    let modules = modules(&root);
    let mut checked = 0;
    let mut missing = Vec::new();
    for n in syllabus::CHAPTERS.iter().map(|c| c.number) {
        let text = page(n);
        let path_section = section(&text, "The path of one pixel")
            .unwrap_or_else(|| panic!("chapter {n}'s book page has no \"The path of one pixel\""));
        let paths = crate_paths(path_section, &modules);
        assert!(paths.len() >= 5, "chapter {n}: only {paths:?}");
        for p in paths {
            checked += 1;
            if let Err(e) = exists(&root, &p) {
                missing.push(format!("chapter {n}: `{p}`: {e}"));
            }
        }
    }
    assert!(missing.is_empty(), "{}", missing.join("\n"));
    assert!(checked > 60, "{checked} paths checked");
}

/// Every formula function of chapter N is named in chapter N's README (by its path, or by its
/// last two segments, `Tracer::local_light` for `render::tracer::Tracer::local_light`).
#[test]
fn every_formula_function_is_in_its_chapters_readme() {
    let manifest = manifest::load(&root().join(manifest::DEFAULT_PATH)).unwrap();
    let mut absent = Vec::new();
    for entry in &manifest.entries {
        let text = readme(entry.chapter);
        let segments: Vec<&str> = entry.function.split("::").collect();
        let tail = segments[segments.len() - 2..].join("::");
        if !text.contains(&entry.function) && !text.contains(&tail) {
            absent.push(format!("chapter {}: {}", entry.chapter, entry.function));
        }
    }
    assert!(absent.is_empty(), "not in their README: {absent:?}");
}

/// Each chapter README's "## Exercises" section is the one the manifest writes (ids, names,
/// titles, functions, tasks, in order): `cargo run --bin whitted -- formulas readmes` rewrites
/// them.
#[test]
fn each_readme_lists_its_chapters_exercises_from_the_manifest() {
    let root = root();
    let m = manifest::load(&root.join(manifest::DEFAULT_PATH)).unwrap();
    for chapter in &syllabus::CHAPTERS {
        let n = chapter.number;
        let text = readme(n);
        let want = whitted_course::readme::section(&m, chapter);
        assert_eq!(
            whitted_course::readme::replace_section(&text, &want),
            text,
            "chapter {n}'s exercises differ from the manifest: run `cargo run --bin whitted -- formulas readmes`"
        );
        for e in m.entries.iter().filter(|e| e.chapter == n) {
            assert!(text.contains(&format!("### {} {}", e.exercise.id, e.exercise.title)));
            assert!(text.contains(&format!("(the exercise `{}`)", e.exercise.name)));
        }
    }
}

/// The course book's table of contents (`docs/src/SUMMARY.md`) links every chapter's page, in
/// the syllabus's order and with its title, and each page opens with its chapter's heading.
#[test]
fn the_book_lists_each_chapters_page_in_order() {
    let summary = std::fs::read_to_string(root().join("docs/src/SUMMARY.md")).unwrap();
    let mut last = 0;
    for chapter in &syllabus::CHAPTERS {
        let (n, heading) = (chapter.number, chapter.heading());
        let link = format!("[{n}. {heading}]({}.md)", chapter.book);
        let at = summary
            .find(&link)
            .unwrap_or_else(|| panic!("docs/src/SUMMARY.md does not link {link}"));
        assert!(at > last, "chapter {n} is out of order in SUMMARY.md");
        last = at;
        let first = page(n).lines().next().unwrap_or("").to_string();
        assert_eq!(
            first,
            format!("# Chapter {n} — {heading}"),
            "{}",
            chapter.page()
        );
    }
}
