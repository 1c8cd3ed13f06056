//! The documentation of the programs says what the programs do, because it is written from
//! the same tables: the window's keys and the ray tree's legend (`window::keys`,
//! `overlay::Stroke`, `overlay::Mark`), each binary's arguments and their values
//! (`cli::command`, from the library's `ALL` and `name()`), and the chapters (the syllabus).
//!
//! Each generated part of a document stands between two lines,
//! `<!-- BEGIN generated: NAME … -->` and `<!-- END generated: NAME -->`. A test writes the part
//! anew and compares: on a difference it names the file and the lines missing, and prints the
//! part to paste. `WHITTED_WRITE_DOCS=1 cargo test -p whitted-app --test docs` writes the
//! parts into the files instead.

mod common;

use std::collections::BTreeSet;

use whitted::render::Chapter;
use whitted_app::cli;
use whitted_app::window::keys;
use whitted_app::window::overlay::{Mark, Stroke};

/// A markdown table: a header, then a row a line.
fn table(header: [&str; 2], rows: impl IntoIterator<Item = (String, String)>) -> String {
    let mut out = format!("| {} | {} |\n|---|---|\n", header[0], header[1]);
    for (a, b) in rows {
        out += &format!("| {a} | {b} |\n");
    }
    out
}

/// The first line of a generated part, and its last.
fn markers(name: &str) -> (String, String) {
    (
        format!("<!-- BEGIN generated: {name} (crates/whitted-app/tests/docs.rs) -->"),
        format!("<!-- END generated: {name} -->"),
    )
}

/// Checks that the part `name` of the file `rel` (from the workspace's root) is `expected`,
/// or, with `WHITTED_WRITE_DOCS=1`, writes it there.
#[track_caller]
fn check_part(rel: &str, name: &str, expected: &str) {
    // one at a time: several parts share a file, and writing one must not race reading another
    static FILES: std::sync::Mutex<()> = std::sync::Mutex::new(());
    let _one = FILES
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    let path = common::root().join(rel);
    let text = std::fs::read_to_string(&path).unwrap_or_else(|e| panic!("{rel}: {e}"));
    let (begin, end) = markers(name);
    let (Some(b), Some(e)) = (text.find(&begin), text.find(&end)) else {
        panic!("{rel}: no lines `{begin}` … `{end}`; put them around this text:\n{expected}");
    };
    let start = b + begin.len() + 1;
    let found = &text[start.min(e)..e];
    if found == expected {
        return;
    }
    if std::env::var_os("WHITTED_WRITE_DOCS").is_some() {
        let written = format!("{}{expected}{}", &text[..start], &text[e..]);
        std::fs::write(&path, written).unwrap();
        return;
    }
    let have: BTreeSet<&str> = found.lines().collect();
    let missing: Vec<&str> = expected.lines().filter(|l| !have.contains(l)).collect();
    panic!(
        "{rel}: the part `{name}` is not what the code says.\nmissing or changed: {missing:#?}\n\
         paste this between its two marker lines (or run with WHITTED_WRITE_DOCS=1):\n{expected}"
    );
}

// ---- the window --------------------------------------------------------------------------

/// The course book's table of the window's keys is the keymap.
#[test]
fn the_books_key_table_is_the_keymap() {
    let rows = keys::keymap()
        .into_iter()
        .map(|r| (r.label(), r.description));
    check_part(
        "docs/src/window.md",
        "keys",
        &table(["keys", "what they do"], rows),
    );
}

/// README.md's line of keys is the keymap's summary.
#[test]
fn the_readmes_key_line_is_the_keymap() {
    check_part("README.md", "keys", &format!("{}\n", keys::summary()));
}

/// The course book's legend of the ray tree's drawing is the overlay's.
#[test]
fn the_books_legend_is_the_overlays() {
    let looks = Stroke::ALL
        .iter()
        .map(|s| s.legend())
        .chain(Mark::ALL.iter().map(|m| m.legend()))
        .map(|(look, meaning)| (look.to_string(), meaning.to_string()));
    check_part(
        "docs/src/window.md",
        "legend",
        &table(["drawn", "what it is"], looks),
    );
}

// ---- the command line -------------------------------------------------------------------

/// [`token`], its list of values cut after every [`VALUES_A_LINE`] values so that the usage
/// wraps a long list (the views) over several lines: `[--view a|b|c`, `|d|e]`.
fn tokens_of(arg: &clap::Arg) -> Vec<String> {
    let whole = token(arg);
    let Some((flag, list)) = whole.split_once(' ') else {
        return vec![whole];
    };
    let values: Vec<&str> = list.split('|').collect();
    if values.len() <= VALUES_A_LINE {
        return vec![whole];
    }
    values
        .chunks(VALUES_A_LINE)
        .enumerate()
        .map(|(k, chunk)| {
            let joined = chunk.join("|");
            if k == 0 {
                format!("{flag} {joined}")
            } else {
                format!("|{joined}")
            }
        })
        .collect()
}

/// The most values of a choice one line of the usage lists.
const VALUES_A_LINE: usize = 6;

/// How a usage line writes an argument: `[SCENE]`, `[-o OUT.png]`, `[--width W]`,
/// `[--view color|flat|…]`, `[--quiet]`.
fn token(arg: &clap::Arg) -> String {
    let values: Vec<String> = arg
        .get_possible_values()
        .iter()
        .filter(|v| !v.is_hide_set())
        .map(|v| v.get_name().to_string())
        .collect();
    let value_name = || {
        arg.get_value_names()
            .and_then(|n| n.first())
            .map_or_else(|| arg.get_id().as_str().to_uppercase(), ToString::to_string)
    };
    let Some(long) = arg.get_long() else {
        return format!("[{}]", value_name()); // a positional argument
    };
    let takes_value = arg.get_action().takes_values();
    let flag = match arg.get_short() {
        Some(short) if takes_value => format!("-{short}"),
        _ => format!("--{long}"),
    };
    match (takes_value, values.is_empty()) {
        (false, _) => format!("[{flag}]"),
        (true, false) => format!("[{flag} {}]", values.join("|")),
        (true, true) => format!("[{flag} {}]", value_name()),
    }
}

/// The arguments of `chapter`'s binary, in the order of its `--help`, without `--help`,
/// `--version` and those the help hides (for the course tools).
fn arguments(chapter: Chapter) -> Vec<clap::Arg> {
    let mut cmd = cli::command(chapter, "");
    cmd.build();
    cmd.get_arguments()
        .filter(|a| !matches!(a.get_id().as_str(), "help" | "version") && !a.is_hide_set())
        .cloned()
        .collect()
}

/// `tokens` in lines of at most `width` characters (a longer token alone on its line).
fn wrap(tokens: &[String], width: usize) -> Vec<String> {
    let mut lines: Vec<String> = Vec::new();
    for t in tokens {
        match lines.last_mut() {
            Some(line) if line.chars().count() + 1 + t.chars().count() <= width => {
                line.push(' ');
                line.push_str(t);
            }
            _ => lines.push(t.clone()),
        }
    }
    lines
}

/// The chapters from `from` to the last, in words: "every chapter", "chapters 2–5", "chapter 5".
fn from_on(from: Chapter) -> String {
    let (first, last) = (Chapter::ALL[0], Chapter::ALL[Chapter::ALL.len() - 1]);
    if from == first {
        "every chapter".into()
    } else if from == last {
        format!("chapter {}", last.number())
    } else {
        format!("chapters {}–{}", from.number(), last.number())
    }
}

/// README.md's block: every binary's arguments, grouped by the chapter that first offers
/// them, each group's lines saying which chapters have it.
fn usage_block() -> String {
    let mut offered: Vec<(Chapter, Vec<String>)> = Vec::new();
    let mut seen: BTreeSet<String> = BTreeSet::new();
    for chapter in Chapter::ALL {
        let tokens: Vec<String> = arguments(chapter).iter().flat_map(tokens_of).collect();
        for earlier in &seen {
            assert!(
                tokens.contains(earlier),
                "{earlier} is offered before chapter {} but not in it: the usage's ranges would lie",
                chapter.number()
            );
        }
        let new: Vec<String> = tokens.into_iter().filter(|t| !seen.contains(t)).collect();
        seen.extend(new.iter().cloned());
        if !new.is_empty() {
            offered.push((chapter, new));
        }
    }
    let prefix = "chNN ";
    let mut lines: Vec<(String, String)> = Vec::new();
    for (from, tokens) in &offered {
        for line in wrap(tokens, 64) {
            let start = if lines.is_empty() {
                prefix.to_string()
            } else {
                " ".repeat(prefix.len())
            };
            lines.push((start + &line, from_on(*from)));
        }
    }
    let width = lines
        .iter()
        .map(|(l, _)| l.chars().count())
        .max()
        .unwrap_or(0);
    let body: String = lines
        .iter()
        .map(|(l, chapters)| format!("{l:<width$}   {chapters}\n"))
        .collect();
    format!("```text\n{body}```\n")
}

/// A chapter README's usage: the `cargo run` line with the chapter's arguments.
fn chapter_usage(chapter: Chapter) -> String {
    let mut tokens = vec![format!(
        "cargo run --release --bin {} --",
        chapter.about().binary
    )];
    tokens.extend(arguments(chapter).iter().flat_map(tokens_of));
    let lines = wrap(&tokens, 96);
    format!("```text\n{}\n```\n", lines.join("\n      "))
}

/// README.md's block of every binary's arguments is their command lines'.
#[test]
fn the_readmes_usage_is_the_command_lines() {
    check_part("README.md", "usage", &usage_block());
}

/// Each chapter README's usage line is its binary's command line.
#[test]
fn each_chapter_readmes_usage_is_its_command_line() {
    for chapter in Chapter::ALL {
        check_part(&chapter.about().readme(), "usage", &chapter_usage(chapter));
    }
}

/// The text of `rel` between `start` and the next line starting `until` (or the end).
fn section(rel: &str, start: &str, until: &str) -> String {
    let text = std::fs::read_to_string(common::root().join(rel)).unwrap();
    let from = text
        .find(start)
        .unwrap_or_else(|| panic!("{rel}: no {start:?}"));
    let rest = &text[from + start.len()..];
    let end = rest.find(until).unwrap_or(rest.len());
    rest[..end].to_string()
}

/// The pieces of code in a markdown text: each line of a fenced block, each inline span.
fn code(text: &str) -> Vec<String> {
    let mut out = Vec::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
        } else if fenced {
            out.push(line.to_string());
        } else {
            out.extend(line.split('`').skip(1).step_by(2).map(String::from));
        }
    }
    out
}

/// Every flag a text names in code is an argument of the binary it is given to, and a value
/// written after it is one the flag takes. A piece of code is given to a binary when it is
/// `cargo run … [--bin NAME] -- …` (the flags after `--`), or when it starts with a flag, a `[`
/// or `chNN` (then to any of `chapters`); other commands (cargo's, the course tools') are
/// not the binaries'.
#[track_caller]
fn check_flags_named(rel: &str, text: &str, chapters: &[Chapter]) -> usize {
    let mut named = 0;
    for piece in code(text) {
        let (args, given): (Vec<clap::Arg>, &str) = match piece.split_once(" -- ") {
            Some((run, given)) if run.starts_with("cargo run") => {
                // without --bin, cargo runs the last chapter (its default-run, tests/cli.rs)
                let chapter = match run.split_once("--bin ") {
                    Some((_, bin)) => Chapter::ALL
                        .into_iter()
                        .find(|c| bin.split_whitespace().next() == Some(c.about().binary)),
                    None => Chapter::ALL.last().copied(),
                };
                let Some(chapter) = chapter else {
                    continue; // another program's
                };
                (arguments(chapter), given)
            }
            _ if ["--", "[", "chNN"]
                .iter()
                .any(|p| piece.trim_start().starts_with(p)) =>
            {
                (
                    chapters.iter().flat_map(|&c| arguments(c)).collect(),
                    piece.as_str(),
                )
            }
            _ => continue,
        };
        let words: Vec<&str> = given
            .split(|c: char| c.is_whitespace() || c == '[' || c == ']')
            .filter(|w| !w.is_empty())
            .collect();
        for (i, word) in words.iter().enumerate() {
            let Some(name) = word.strip_prefix("--") else {
                continue;
            };
            let name = name.trim_end_matches([',', '.', ';', ')']);
            named += 1;
            let arg = args
                .iter()
                .find(|a| {
                    a.get_long() == Some(name)
                        || a.get_all_aliases().is_some_and(|al| al.contains(&name))
                })
                .unwrap_or_else(|| {
                    panic!("{rel}: `{piece}` names --{name}, which its binary does not take")
                });
            let possible = arg.get_possible_values();
            let values: Vec<&str> = possible
                .iter()
                .map(clap::builder::PossibleValue::get_name)
                .collect();
            // a value in lower case (an upper-case word stands for any: `--view V`)
            let next = words.get(i + 1).filter(|w| {
                !values.is_empty() && !w.starts_with('-') && !w.chars().any(char::is_uppercase)
            });
            for v in next
                .iter()
                .flat_map(|w| w.split(['|', '\\']))
                .filter(|v| !v.is_empty())
            {
                assert!(
                    values.contains(&v),
                    "{rel}: `{piece}`: --{name} takes {values:?}, not {v:?}"
                );
            }
        }
    }
    named
}

/// The prose around each chapter README's usage names only its binary's flags and values.
#[test]
fn each_chapter_readme_names_only_its_flags_and_values() {
    for chapter in Chapter::ALL {
        let rel = chapter.about().readme();
        let running = section(&rel, "## Running it", "\n## ");
        let named = check_flags_named(&rel, &running, &[chapter]);
        assert!(named > 0, "{rel}: its Running it section names no flag");
    }
}

/// README.md's sections on the programs name only flags and values the binaries take.
#[test]
fn the_readme_names_only_flags_and_values_the_binaries_take() {
    let sections = [
        ("## Two commands", "\n## Watch it live"),
        ("## Watch it live", "\n## The course book"),
        ("## The chapters", "\n## Scenes"),
        ("## What happened to this pixel?", "\n## Write it yourself"),
    ];
    let named: usize = sections
        .iter()
        .map(|(start, until)| {
            let text = section("README.md", start, until);
            check_flags_named("README.md", &text, &Chapter::ALL)
        })
        .sum();
    // the usage block alone names every flag
    let every: BTreeSet<String> = Chapter::ALL
        .iter()
        .flat_map(|&c| arguments(c))
        .filter_map(|a| a.get_long().map(String::from))
        .collect();
    assert!(named >= every.len(), "README.md names {named} flags");
}

// ---- the chapters ------------------------------------------------------------------------

/// README.md's table of the chapters is the syllabus's.
#[test]
fn the_readmes_chapter_table_is_the_syllabus() {
    let mut out = String::from("| chapter | binary | adds | read |\n|---|---|---|---|\n");
    for chapter in Chapter::ALL {
        let c = chapter.about();
        out += &format!(
            "| {} | `{}` | {} | [the book]({}), [exercises]({}#exercises) |\n",
            c.number,
            c.binary,
            c.adds,
            c.page(),
            c.readme()
        );
    }
    check_part("README.md", "chapters", &out);
}
