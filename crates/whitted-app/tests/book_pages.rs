//! The pixel each chapter page of the course book inspects ("One pixel, inspected") is what the
//! chapter binary prints for it today, so the book cannot drift from the code.

mod common;

use common::root;
use whitted::render::Chapter;
use whitted_app::cli::OBJECTS_FROM;

/// The course book's page of `chapter`.
fn page(chapter: Chapter) -> String {
    let path = root().join(chapter.about().page());
    std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{}: {e}", path.display()))
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

/// The text with every digit replaced by `#` (f32 prints other last digits than f64).
fn digits_masked(text: &str) -> String {
    text.chars()
        .map(|c| if c.is_ascii_digit() { '#' } else { c })
        .collect()
}

/// The chapters that trace objects show one inspected pixel of their scene: the command on the book's page, run
/// now, prints exactly the tree the page shows (in an f32 build, the same lines with other
/// digits), so the book cannot drift from the code.
#[test]
fn the_inspected_pixel_on_each_chapter_page_is_what_the_binary_prints() {
    for chapter in Chapter::ALL.into_iter().filter(|&c| c >= OBJECTS_FROM) {
        let n = chapter.number();
        let text = page(chapter);
        let body = section(&text, "One pixel, inspected")
            .unwrap_or_else(|| panic!("chapter {n}'s book page has no \"One pixel, inspected\""));
        let block = body
            .split("```text\n")
            .nth(1)
            .and_then(|b| b.split("```").next())
            .unwrap_or_else(|| panic!("chapter {n}: no ```text block"));
        let (command, shown) = block.split_once('\n').unwrap();
        let (bin, args) = command
            .strip_prefix("$ cargo run --release --bin ")
            .and_then(|c| c.split_once(" -- "))
            .unwrap_or_else(|| panic!("chapter {n}: `{command}` is not a cargo run line"));
        assert!(
            Chapter::ALL.iter().any(|c| c.about().binary == bin),
            "chapter {n}: no chapter's binary is named {bin}"
        );
        let exe = common::exe_named(bin);
        assert!(args.contains("--inspect"), "{command}");
        let out = std::process::Command::new(exe)
            .args(args.split_whitespace())
            .current_dir(root())
            .output()
            .unwrap();
        assert!(
            out.status.success(),
            "{command}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let printed = String::from_utf8(out.stdout).unwrap();
        if cfg!(feature = "f32") {
            assert_eq!(digits_masked(&printed), digits_masked(shown), "chapter {n}");
        } else {
            assert_eq!(
                printed, shown,
                "chapter {n}: rerun `{command}` and paste its output"
            );
        }
    }
}
