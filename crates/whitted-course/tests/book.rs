//! The course book's checks (`whitted figures --check`, `whitted book`): each check is shown
//! to catch what it is for, and the repository's book is held to them where no mdBook is
//! needed (the figures' manifest against the figures, and every include of the pages).

mod common;

use common::root;

use std::path::{Path, PathBuf};

use whitted_course::book::{
    self, check_html, check_includes, include_links, log_problems, resolve_include,
};
use whitted_course::figures::{self, Difference, Figure, compare, parse_figures};

fn write(dir: &Path, name: &str, text: &str) -> PathBuf {
    let path = dir.join(name);
    std::fs::create_dir_all(path.parent().unwrap()).unwrap();
    std::fs::write(&path, text).unwrap();
    path
}

const GOOD: &str = r#"# the book's renders
[[figure]]
file = "a.png"
binary = "ch02_generic_objects"
args = ["scenes/ch02_generic_objects.toml", "--view", "normals"]

[[figure]]
file = "b.png"
binary = "ch05_reflection_refraction"
args = []
"#;

#[test]
fn the_figures_manifest_is_read_with_each_tables_line() {
    let figures = parse_figures(GOOD, "figures.toml").unwrap();
    assert_eq!(
        figures,
        vec![
            Figure {
                file: "a.png".into(),
                binary: "ch02_generic_objects".into(),
                args: vec![
                    "scenes/ch02_generic_objects.toml".into(),
                    "--view".into(),
                    "normals".into()
                ],
                line: 2,
            },
            Figure {
                file: "b.png".into(),
                binary: "ch05_reflection_refraction".into(),
                args: vec![],
                line: 7,
            },
        ]
    );
}

#[test]
fn a_wrong_figures_manifest_is_one_line_with_file_line_and_column() {
    let cases = [
        (
            GOOD.replace("ch02_generic_objects\"", "ch09\""),
            "figures.toml:4:10: binary `ch09` is not a chapter binary",
        ),
        (
            GOOD.replace("\"b.png\"", "\"a.png\""),
            "figures.toml:8:8: file `a.png` is listed twice (first on line 2)",
        ),
        (
            GOOD.replace("\"a.png\"", "\"figures/a.png\""),
            "figures.toml:3:8: file `figures/a.png` must be a name ending in .png",
        ),
        (
            GOOD.replace("args = []", "args = [\"-o\", \"x.png\"]"),
            "figures.toml:7:1: args must not contain `-o`",
        ),
        (
            GOOD.replace("args = []", "args = []\nsize = 3"),
            "figures.toml:11:1: unknown field `size`",
        ),
    ];
    for (text, expected) in cases {
        let message = parse_figures(&text, "figures.toml")
            .unwrap_err()
            .to_string();
        assert!(
            message.starts_with(expected),
            "{message:?} should start with {expected:?}"
        );
        assert!(!message.contains('\n'), "{message:?}");
    }
}

#[test]
fn include_links_are_found_unless_escaped() {
    let text = "text\n```rust\n{{#include ../src/a.rs:road}} and {{#rustdoc_include b.rs:2:4}}\n```\n\\{{#include not/this.rs}}\n{{#title x}}\n";
    assert_eq!(
        include_links(text),
        vec![
            (3, "../src/a.rs:road".to_string()),
            (3, "b.rs:2:4".to_string())
        ]
    );
}

#[test]
fn an_include_resolves_by_anchor_or_line_range_or_says_why_not() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "a.rs",
        "fn a() {}\n// ANCHOR: road\nfn road() {}\n// ANCHOR: inner\nlet x = 1;\n// ANCHOR_END: inner\n// ANCHOR_END: road\n// ANCHOR: roads\n// ANCHOR_END: roads\n// ANCHOR: open\n",
    );
    let d = dir.path();
    assert_eq!(
        resolve_include(d, "a.rs:road").unwrap(),
        "fn road() {}\nlet x = 1;"
    );
    assert_eq!(resolve_include(d, "a.rs:inner").unwrap(), "let x = 1;");
    assert_eq!(
        resolve_include(d, "a.rs:2:3").unwrap(),
        "// ANCHOR: road\nfn road() {}"
    );
    assert_eq!(resolve_include(d, "a.rs:1").unwrap(), "fn a() {}");
    assert!(
        resolve_include(d, "a.rs")
            .unwrap()
            .starts_with("fn a() {}\n")
    );
    let errors = [
        ("a.rs:ro", "no line `ANCHOR: ro`"),
        ("a.rs:roads", "holds nothing"),
        ("a.rs:open", "has no `ANCHOR_END: open` after it"),
        (
            "a.rs:9:12",
            "lines 9 to 12 are not inside the file's 10 lines",
        ),
        ("a.rs:0", "lines 0 to 0"),
        ("b.rs:road", "cannot read"),
    ];
    for (target, expected) in errors {
        let message = resolve_include(d, target).unwrap_err();
        assert!(message.contains(expected), "{target}: {message}");
    }
}

#[test]
fn check_includes_reports_each_broken_include_with_its_page_and_line() {
    let dir = tempfile::tempdir().unwrap();
    write(
        dir.path(),
        "code.rs",
        "// ANCHOR: x\nlet x = 1;\n// ANCHOR_END: x\n",
    );
    write(
        dir.path(),
        "src/page.md",
        "# P\n\n{{#include ../code.rs:x}}\n{{#include ../code.rs:y}}\n",
    );
    write(dir.path(), "src/sub/q.md", "{{#include ../../gone.rs}}\n");
    let problems = check_includes(&dir.path().join("src")).unwrap();
    let shown: Vec<String> = problems
        .iter()
        .map(|p| {
            format!(
                "{}:{}",
                p.file.strip_prefix(dir.path()).unwrap().display(),
                p.line
            )
        })
        .collect();
    assert_eq!(shown, ["src/page.md:4", "src/sub/q.md:1"]);
}

#[test]
fn the_repositorys_book_has_no_include_that_gives_nothing() {
    let problems = check_includes(&root().join("docs/src")).unwrap();
    assert!(
        problems.is_empty(),
        "{}",
        problems
            .iter()
            .map(ToString::to_string)
            .collect::<Vec<_>>()
            .join("\n")
    );
}

#[test]
fn mdbooks_log_problems_are_its_warnings_and_errors_but_the_version_notice() {
    let log = "\
 INFO Book building has started
\u{1b}[2m2026-11-29T13:27:40Z\u{1b}[0m \u{1b}[33m WARN\u{1b}[0m mdbook_katex: This mdbook-katex was built against mdbook v0.5.3, but we are being called from mdbook v0.5.4.
2026-11-29T13:27:40Z  WARN render{item=\"\\frac{a}\"}: mdbook_katex::render: Rendering failed, keeping the original content
ERROR ToolError updating \"{{#include x.rs}}\"
 INFO HTML book written to `book`
";
    let problems = log_problems(log);
    assert_eq!(problems.len(), 2, "{problems:?}");
    assert!(problems[0].contains("Rendering failed"));
    assert!(problems[1].starts_with("ERROR ToolError updating"));
}

const PAGE: &str = r##"<html><head>
<link rel="stylesheet" href="katex/katex.min.css">
<script src="book.js"></script>
</head><body><main>
<h1 id="top">T</h1><p><span class="katex">x</span></p>
<img src="figures/a.png" alt="a">
<a href="#top">up</a> <a href="other.html#there">there</a> <a href="https://example.org/x">out</a>
<a href="mailto:x@y.z">mail</a>
</main></body></html>
"##;

fn book_dir() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    write(dir.path(), "ch.html", PAGE);
    write(
        dir.path(),
        "other.html",
        "<main><h2 id=\"there\">x</h2></main>",
    );
    write(dir.path(), "book.js", "");
    write(dir.path(), "katex/katex.min.css", "");
    write(dir.path(), "figures/a.png", "");
    dir
}

fn problems_of(dir: &Path, page: &str, chapters: &[&str]) -> Vec<String> {
    write(dir, "ch.html", page);
    check_html(dir, chapters)
        .unwrap()
        .iter()
        .map(|p| p.message.clone())
        .collect()
}

#[test]
fn a_clean_built_book_has_no_problems() {
    let dir = book_dir();
    assert_eq!(
        problems_of(dir.path(), PAGE, &["ch.html"]),
        Vec::<String>::new()
    );
}

#[test]
fn check_html_catches_each_kind_of_problem() {
    let dir = book_dir();
    let cases = [
        (
            PAGE.replace("other.html#there", "gone.html"),
            "`href=\"gone.html\"`: no such file in the book",
        ),
        (
            PAGE.replace("other.html#there", "other.html#nowhere"),
            "`href=\"other.html#nowhere\"`: the page has no `id=\"nowhere\"`",
        ),
        (
            PAGE.replace("href=\"#top\"", "href=\"#bottom\""),
            "`href=\"#bottom\"`: the page has no `id=\"bottom\"`",
        ),
        (
            PAGE.replace("figures/a.png", "figures/b.png"),
            "`src=\"figures/b.png\"`: no such file in the book",
        ),
        (
            PAGE.replace("src=\"book.js\"", "src=\"https://cdn.example/katex.js\""),
            "loads `https://cdn.example/katex.js` from the network",
        ),
        (
            PAGE.replace(
                "href=\"katex/katex.min.css\"",
                "href=\"https://cdn.example/katex.css\"",
            ),
            "loads `https://cdn.example/katex.css` from the network",
        ),
        (
            PAGE.replace("class=\"katex\">x", "class=\"katex-error\">x"),
            "a formula failed to render",
        ),
        (
            PAGE.replace("<p>", "<p>$$ a^2 $$"),
            "`$$` left in the text: a formula was not typeset",
        ),
    ];
    for (page, expected) in cases {
        let problems = problems_of(dir.path(), &page, &[]);
        assert!(
            problems.iter().any(|p| p == expected),
            "{expected:?} not in {problems:?}"
        );
    }
    let bare = PAGE
        .replace("<span class=\"katex\">x</span>", "x")
        .replace("<img src=\"figures/a.png\" alt=\"a\">", "");
    assert_eq!(
        problems_of(dir.path(), &bare, &["ch.html"]),
        [
            "a chapter page without typeset math",
            "a chapter page without a figure"
        ]
    );
    // the same page is fine when it is not a chapter
    assert_eq!(problems_of(dir.path(), &bare, &[]), Vec::<String>::new());
}

fn png(dir: &Path, name: &str, pixels: &[[u8; 3]], width: u32) -> PathBuf {
    let path = dir.join(name);
    let height = pixels.len() as u32 / width;
    let file = std::io::BufWriter::new(std::fs::File::create(&path).unwrap());
    let mut encoder = png::Encoder::new(file, width, height);
    encoder.set_color(png::ColorType::Rgb);
    encoder.set_depth(png::BitDepth::Eight);
    let mut writer = encoder.write_header().unwrap();
    writer.write_image_data(pixels.as_flattened()).unwrap();
    writer.finish().unwrap();
    path
}

#[test]
fn figures_compare_within_one_level_and_report_what_differs() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let base = [[10, 20, 30], [40, 50, 60], [70, 80, 90], [0, 0, 255]];
    let a = png(d, "a.png", &base, 2);
    let near = png(
        d,
        "near.png",
        &[[11, 19, 30], [40, 50, 61], [70, 80, 90], [0, 1, 254]],
        2,
    );
    let far = png(
        d,
        "far.png",
        &[[10, 20, 30], [40, 52, 60], [70, 80, 90], [9, 0, 255]],
        2,
    );
    let tall = png(d, "tall.png", &base, 1);
    assert_eq!(
        compare(&a, &a, figures::TOLERANCE).unwrap(),
        Difference::Same
    );
    assert_eq!(
        compare(&a, &near, figures::TOLERANCE).unwrap(),
        Difference::Same
    );
    assert_eq!(
        compare(&a, &near, 0).unwrap(),
        Difference::Pixels {
            pixels: 3,
            largest: 1,
            first: (0, 0)
        }
    );
    assert_eq!(
        compare(&a, &far, figures::TOLERANCE).unwrap(),
        Difference::Pixels {
            pixels: 2,
            largest: 9,
            first: (1, 0)
        }
    );
    assert_eq!(
        compare(&a, &tall, figures::TOLERANCE).unwrap(),
        Difference::Size((2, 2), (1, 4))
    );
}

/// Every render of the book is in the manifest, and the manifest names only figures that are
/// there: `whitted figures --check` (in CI) then re-renders all of them.
#[test]
fn every_figure_of_the_book_is_in_the_manifest_and_every_entry_is_committed() {
    let root = root();
    let figures = figures::read_figures(&root.join("docs/figures.toml")).unwrap();
    let listed: Vec<&str> = figures.iter().map(|f| f.file.as_str()).collect();
    let dir = root.join("docs/src/figures");
    let mut on_disk: Vec<String> = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".png"))
        .collect();
    on_disk.sort();
    let mut sorted = listed.clone();
    sorted.sort_unstable();
    assert_eq!(
        on_disk, sorted,
        "docs/src/figures/ against docs/figures.toml"
    );
    // every figure a page shows is one of them
    for page in book::pages(&root.join("docs/src"), "md").unwrap() {
        let text = std::fs::read_to_string(&page).unwrap();
        for (i, _) in text.match_indices("](figures/") {
            let name = &text[i + 10..];
            let name = &name[..name.find(')').unwrap()];
            assert!(
                listed.contains(&name),
                "{}: figures/{name} is not in docs/figures.toml",
                page.display()
            );
        }
    }
}

/// Each module of the workspace's libraries (the renderer, the programs, the course tools)
/// names the course book's page that teaches it, with a link that works from the module's
/// rustdoc page (`target/doc/CRATE/…/index.html`, so one `../` per module level, plus three up
/// to the project) to the built book, and the page exists.
/// Each chapter's figure is its binary's render of its own scene at the figure's width and
/// nothing else, which is how `cargo learn` renders the student's picture to compare with it
/// (`whitted_syllabus::Chapter::figure`; the width read from the PNG).
#[test]
fn each_chapters_figure_is_its_scene_at_a_width_as_learn_renders_it() {
    let root = root();
    let figures = figures::read_figures(&root.join("docs/figures.toml")).unwrap();
    for c in whitted_course::syllabus::CHAPTERS {
        let path = c.figure();
        let file = path.strip_prefix("docs/src/figures/").unwrap();
        let f = figures
            .iter()
            .find(|f| f.file == file)
            .unwrap_or_else(|| panic!("docs/figures.toml has no figure {file}"));
        assert_eq!(f.binary, c.binary, "docs/figures.toml:{}", f.line);
        let width_ok = f.args.len() == 3
            && f.args[0] == c.scene()
            && f.args[1] == "--width"
            && f.args[2].parse::<u32>().is_ok();
        assert!(
            width_ok,
            "docs/figures.toml:{}: {file} must be `{} --width W` for cargo learn to render the student's picture the same way, found {:?}",
            f.line,
            c.scene(),
            f.args
        );
        assert!(root.join(&path).is_file(), "{path} is not committed");
    }
}

#[test]
fn every_module_links_the_book_page_that_teaches_it() {
    let root = root();
    let mut bad = Vec::new();
    let mut files = Vec::new();
    for krate in ["whitted", "whitted-app", "whitted-course"] {
        let src = root.join("crates").join(krate).join("src");
        for file in book::pages(&src, "rs").unwrap() {
            // a binary's page is its own crate's root, not a module of the library
            if !file.strip_prefix(&src).unwrap().starts_with("bin") && !file.ends_with("main.rs") {
                files.push((src.clone(), file));
            }
        }
    }
    assert!(files.len() > 60, "{} modules", files.len());
    for (src, file) in files {
        let rel = file.strip_prefix(&src).unwrap();
        let mut parts: Vec<String> = rel
            .with_extension("")
            .iter()
            .map(|p| p.to_string_lossy().into_owned())
            .collect();
        if matches!(parts.last().map(String::as_str), Some("mod" | "lib")) {
            parts.pop();
        }
        let ups = "../".repeat(3 + parts.len());
        let text = std::fs::read_to_string(&file).unwrap();
        let docs: Vec<&str> = text.lines().take_while(|l| l.starts_with("//!")).collect();
        let lines: Vec<&str> = docs
            .iter()
            .filter_map(|l| l.find("Course book: [").map(|i| &l[i..]))
            .collect();
        let [line] = lines.as_slice() else {
            bad.push(format!(
                "{}: {} `Course book:` lines",
                rel.display(),
                lines.len()
            ));
            continue;
        };
        let link = line
            .split("](")
            .nth(1)
            .and_then(|r| r.split(')').next())
            .unwrap_or("");
        let page = link
            .strip_prefix(&format!("{ups}docs/book/"))
            .and_then(|p| p.strip_suffix(".html"));
        match page {
            Some(page) if root.join(format!("docs/src/{page}.md")).is_file() => {
                assert!(
                    line.ends_with(&format!("(`docs/src/{page}.md`).")),
                    "{}: {line}",
                    rel.display()
                );
            }
            _ => bad.push(format!("{}: link `{link}`", rel.display())),
        }
    }
    assert!(bad.is_empty(), "{}", bad.join("\n"));
}

/// Without the manifest, or without mdBook, the book's commands stop with one line on stderr
/// and exit status 2; `--check` on a figure that differs exits 1 and names it.
#[test]
fn the_book_commands_fail_in_one_line_with_status_2_or_name_what_differs() {
    let whitted = env!("CARGO_BIN_EXE_whitted");
    let empty = tempfile::tempdir().unwrap();
    let run = |args: &[&str], dir: &Path| {
        let out = std::process::Command::new(whitted)
            .args(args)
            .current_dir(dir)
            .output()
            .unwrap();
        (
            out.status.code(),
            String::from_utf8_lossy(&out.stdout).into_owned(),
            String::from_utf8_lossy(&out.stderr).into_owned(),
        )
    };
    let root = empty.path().to_str().unwrap();
    let (code, _, err) = run(&["figures", "--root", root], empty.path());
    assert_eq!(code, Some(2));
    assert!(
        err.starts_with("error: ") && err.contains("figures.toml"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    std::fs::create_dir_all(empty.path().join("docs/src")).unwrap();
    let (code, _, err) = run(
        &["book", "--root", root, "--mdbook", "/nonexistent/mdbook"],
        empty.path(),
    );
    assert_eq!(code, Some(2));
    assert!(err.contains("cannot run `/nonexistent/mdbook`"), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    // a project whose one figure is not what its binary renders
    write(
        empty.path(),
        "docs/figures.toml",
        "[[figure]]\nfile = \"x.png\"\nbinary = \"ch01_camera_rays\"\nargs = [\"--width\", \"8\", \"--height\", \"6\"]\n",
    );
    std::fs::create_dir_all(empty.path().join("docs/src/figures")).unwrap();
    png(
        &empty.path().join("docs/src/figures"),
        "x.png",
        &[[0, 0, 0]; 48],
        8,
    );
    let (code, out, _) = run(&["figures", "--check", "--root", root], empty.path());
    assert_eq!(code, Some(1), "{out}");
    assert!(
        out.contains("docs/src/figures/x.png (docs/figures.toml:1): DIFFERS: 48 pixels"),
        "{out}"
    );
    // rendered again, it is the same
    let (code, _, err) = run(&["figures", "--root", root], empty.path());
    assert_eq!(code, Some(0), "{err}");
    let (code, out, _) = run(&["figures", "--check", "--root", root], empty.path());
    assert_eq!(code, Some(0), "{out}");
    assert!(
        out.contains("x.png (docs/figures.toml:1): the same"),
        "{out}"
    );
}
