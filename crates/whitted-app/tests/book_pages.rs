//! The pixel each chapter page of the course book inspects ("One pixel, inspected") is what the
//! chapter binary prints for it today, so the book cannot drift from the code.

use std::path::{Path, PathBuf};

/// The workspace's root: this crate sits in `crates/whitted-app`.
fn root() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .ancestors()
        .nth(2)
        .expect("the crate sits two levels below the workspace's root")
        .to_path_buf()
}

/// The course book's page of chapter `n` (`docs/src/ch0N-….md`).
fn page(n: u8) -> String {
    let dir = root().join("docs/src");
    let path = std::fs::read_dir(&dir)
        .unwrap()
        .map(|e| e.unwrap().path())
        .find(|p| {
            p.file_name()
                .unwrap()
                .to_string_lossy()
                .starts_with(&format!("ch0{n}-"))
        })
        .unwrap_or_else(|| panic!("no page docs/src/ch0{n}-*"));
    std::fs::read_to_string(path).unwrap()
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

/// The chapter binaries, by name.
const BINARIES: [(&str, &str); 4] = [
    (
        "ch02_generic_objects",
        env!("CARGO_BIN_EXE_ch02_generic_objects"),
    ),
    ("ch03_shading", env!("CARGO_BIN_EXE_ch03_shading")),
    ("ch04_shadows", env!("CARGO_BIN_EXE_ch04_shadows")),
    (
        "ch05_reflection_refraction",
        env!("CARGO_BIN_EXE_ch05_reflection_refraction"),
    ),
];

/// The text with every digit replaced by `#` (f32 prints other last digits than f64).
fn digits_masked(text: &str) -> String {
    text.chars()
        .map(|c| if c.is_ascii_digit() { '#' } else { c })
        .collect()
}

/// Chapters 2–5 show one inspected pixel of their scene: the command on the book's page, run
/// now, prints exactly the tree the page shows (in an f32 build, the same lines with other
/// digits), so the book cannot drift from the code.
#[test]
fn the_inspected_pixel_on_each_chapter_page_is_what_the_binary_prints() {
    for n in 2..=5u8 {
        let text = page(n);
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
        let exe = BINARIES
            .iter()
            .find(|(name, _)| *name == bin)
            .unwrap_or_else(|| panic!("chapter {n}: no binary {bin}"))
            .1;
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
