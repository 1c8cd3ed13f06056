//! The student's tests themselves, read as text (the files a handout carries under
//! `crates/whitted/tests/`, by `handout::part_of`): each failure must say what was computed
//! and what was expected, and each exercise's `first_check` in `chapters/formulas.toml` must
//! name one of its tests.
//!
//! A student sees a failing test through its message only (`cargo learn` shows it). An
//! `assert!(close(at(8.0, 0.0), (2.0, -1.5)))` fails with `assertion failed: close(…)`: no
//! value, no name. So every assertion of these files must carry a message that shows a value,
//! and the check below finds those that do not, at their file:line:col.

mod common;

use common::root;

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use proc_macro2::{Delimiter, Spacing, TokenStream, TokenTree};
use whitted_course::handout::{self, Part};
use whitted_course::manifest::{self, Manifest};
use whitted_learn::layout;

fn manifest() -> Manifest {
    manifest::load(&root().join(manifest::DEFAULT_PATH))
        .unwrap_or_else(|e| panic!("chapters/formulas.toml: {e}"))
}

/// The `.rs` files under `crates/whitted/tests/` that a handout carries (the manifest's
/// `[handout] tests` targets and their helpers, such as `common/`), relative to the root, in
/// name order.
fn student_test_files(root: &Path, m: &Manifest) -> Vec<PathBuf> {
    let mut out = Vec::new();
    let mut stack = vec![layout::core_tests()];
    while let Some(dir) = stack.pop() {
        let entries = std::fs::read_dir(root.join(&dir))
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()));
        for entry in entries {
            let entry = entry.unwrap_or_else(|e| panic!("cannot read {}: {e}", dir.display()));
            let path = dir.join(entry.file_name());
            if root.join(&path).is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|x| x == "rs")
                && handout::part_of(&path, &m.handout.tests, root) == Part::Copied
            {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

// ── the check ───────────────────────────────────────────────────────────────────────────────

/// The macros whose message is a format string that must show a value: an `assert!` fails
/// with `assertion failed: EXPR` and nothing else, a `panic!` with its text alone.
const FORMAT_MESSAGE: [&str; 6] = [
    "assert",
    "debug_assert",
    "panic",
    "unreachable",
    "todo",
    "unimplemented",
];

/// The macros that print both values (`left`, `right`) but not what they are: they need a
/// message, which names the quantity.
const NAMED_PAIR: [&str; 4] = [
    "assert_eq",
    "assert_ne",
    "debug_assert_eq",
    "debug_assert_ne",
];

/// approx's macros print both values and the expressions, but neither the notes' name of the
/// quantity nor the tolerance's value: `common::assert_near` and `assert_vec_eq` do.
const APPROX: [&str; 6] = [
    "assert_abs_diff_eq",
    "assert_abs_diff_ne",
    "assert_relative_eq",
    "assert_relative_ne",
    "assert_ulps_eq",
    "assert_ulps_ne",
];

/// Whether the string literal `lit` (as written, quotes and all) holds a format placeholder:
/// a `{` that does not open `{{`.
fn has_placeholder(lit: &str) -> bool {
    let mut chars = lit.chars().peekable();
    while let Some(c) = chars.next() {
        if c == '{' {
            if chars.peek() == Some(&'{') {
                chars.next();
            } else {
                return true;
            }
        }
    }
    false
}

/// The arguments of a macro call, split at the commas of its top level (a comma inside `(…)`,
/// `[…]` or `{…}` belongs to a nested group; generic arguments `<A, B>` written at the top
/// level of an assertion would split wrongly: the files hold none).
fn arguments(stream: TokenStream) -> Vec<Vec<TokenTree>> {
    let mut args = vec![Vec::new()];
    for t in stream {
        match &t {
            TokenTree::Punct(p) if p.as_char() == ',' => args.push(Vec::new()),
            _ => args.last_mut().expect("one argument at least").push(t),
        }
    }
    if args.last().is_some_and(Vec::is_empty) {
        args.pop(); // a trailing comma, or no argument at all
    }
    args
}

/// Whether `arg` is a single string literal with a placeholder.
fn shows_a_value(arg: &[TokenTree]) -> bool {
    matches!(arg, [TokenTree::Literal(l)] if {
        let text = l.to_string();
        (text.starts_with('"') || text.starts_with('r')) && has_placeholder(&text)
    })
}

/// What is wrong with the call of the macro `name` with these arguments, if anything.
fn macro_problem(name: &str, args: &[Vec<TokenTree>]) -> Option<String> {
    if FORMAT_MESSAGE.contains(&name) {
        // assert!(cond, "format", …): the message is the second argument; panic!("format", …)
        // and its kin: the first
        let message = if name.contains("assert") {
            args.get(1)
        } else {
            args.first()
        };
        return match message {
            None if name.contains("assert") => Some(format!(
                "a bare {name}!(…) fails with `assertion failed` and no value: add a message \
                 that shows what was computed and what was expected (a {{…}} in it)"
            )),
            None => Some(format!("{name}!() without a message shows no value")),
            Some(m) if !shows_a_value(m) => Some(format!(
                "the message of this {name}! shows no value: put what was computed in it (a \
                 {{…}} in its format string)"
            )),
            Some(_) => None,
        };
    }
    if NAMED_PAIR.contains(&name) && args.len() < 3 {
        return Some(format!(
            "{name}! without a message shows left and right but not what they are: name it"
        ));
    }
    if APPROX.contains(&name) {
        return Some(format!(
            "{name}! names neither the quantity nor the tolerance: use common::assert_near (or \
             assert_vec_eq), which say both"
        ));
    }
    None
}

/// The problems of the Rust source `text`, each as `file:line:col: what`.
///
/// What it accepts, and why:
/// - `assert!(cond, "… {x} …", …)`, `panic!("… {} …", x)` and their kin: the message is a
///   string literal with a placeholder, so the failure shows a value. A message without one
///   (`assert!(ok, "too small")`) is refused: it says what went wrong but not with what value;
/// - `assert_eq!(a, b, "what a is")`: the macro prints both values, the message names them;
/// - `.expect("what was expected")` and `.unwrap_or_else(|| panic!("… {v} …"))`: the failure
///   says what was missing (an `expect` has no format string; its text names the quantity).
///
/// Refused: a bare `assert!(…)` (`assertion failed` and nothing else, as
/// `assert!(close(at(8.0, 0.0), (2.0, -1.5)))`, `assert!(hits.as_slice()[0].entering)` or
/// `assert!(!nearer(2.0, 1, 2.0, 0))` would fail), an
/// `assert_eq!` without a message, approx's macros, a `panic!` without a value, and every
/// `.unwrap()` or `.unwrap_err()`: nearly every value in these files comes through an exercise
/// (a scene's parse builds the camera and the placements), and `called Option::unwrap() on a
/// None value` names neither the exercise nor the quantity.
fn problems(text: &str, file: &str) -> Vec<String> {
    let stream: TokenStream = text
        .parse()
        .unwrap_or_else(|e| panic!("{file}: not Rust tokens: {e:?}"));
    let mut out = Vec::new();
    walk(stream, file, &mut out);
    out
}

fn walk(stream: TokenStream, file: &str, out: &mut Vec<String>) {
    let tokens: Vec<TokenTree> = stream.into_iter().collect();
    let at = |t: &TokenTree| {
        let start = t.span().start();
        format!("{file}:{}:{}", start.line, start.column + 1)
    };
    for (i, t) in tokens.iter().enumerate() {
        match t {
            TokenTree::Ident(name) => {
                // NAME ! ( … ): a macro call
                if let (Some(TokenTree::Punct(bang)), Some(TokenTree::Group(g))) =
                    (tokens.get(i + 1), tokens.get(i + 2))
                    && bang.as_char() == '!'
                    && g.delimiter() != Delimiter::None
                    && let Some(why) = macro_problem(&name.to_string(), &arguments(g.stream()))
                {
                    out.push(format!("{}: {why}", at(t)));
                }
            }
            TokenTree::Punct(dot) if dot.as_char() == '.' && dot.spacing() == Spacing::Alone => {
                // . unwrap ( ): a bare unwrap
                if let (Some(TokenTree::Ident(method)), Some(TokenTree::Group(g))) =
                    (tokens.get(i + 1), tokens.get(i + 2))
                    && matches!(method.to_string().as_str(), "unwrap" | "unwrap_err")
                    && g.delimiter() == Delimiter::Parenthesis
                    && g.stream().is_empty()
                {
                    out.push(format!(
                        "{}: .{method}() fails with no name and no value: use .expect(\"what was \
                         expected\"), or unwrap_or_else with a panic! that shows the value",
                        at(&tokens[i + 1])
                    ));
                }
            }
            TokenTree::Group(g) => walk(g.stream(), file, out),
            _ => {}
        }
    }
}

/// Every assertion of the student's tests fails with a message that shows a value: see
/// [`problems`] for what passes and why.
#[test]
fn every_failure_of_the_students_tests_shows_a_value() {
    let root = root();
    let m = manifest();
    let files = student_test_files(&root, &m);
    assert!(
        files.len() >= m.handout.tests.len(),
        "the student's test files found: {files:?}, expected one at least per target of {:?}",
        m.handout.tests
    );
    let mut found = Vec::new();
    for f in &files {
        let text = std::fs::read_to_string(root.join(f))
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", f.display()));
        found.extend(problems(&text, &f.display().to_string()));
    }
    assert!(
        found.is_empty(),
        "{} failure(s) of the student's tests would show no value:\n{}",
        found.len(),
        found.join("\n")
    );
}

/// The check finds the three bare assertions above (a pixel's place, a hit's entering flag, the
/// tie rule of the nearest hit) should they be written again, each at its line, and
/// the other kinds it refuses; it lets pass what shows a value.
#[test]
fn the_check_finds_assertions_without_a_value_and_lets_the_others_pass() {
    let refused = r#"fn t() {
    assert!(close(at(8.0, 0.0), (2.0, -1.5)));
    assert!(hits.as_slice()[0].entering);
    assert!(!nearer(2.0, 1, 2.0, 0));
    assert!(x > 1.0, "x is too small");
    assert!(ok, "{{not a value}}");
    assert_eq!(a, b);
    assert_abs_diff_eq!(h, 1.0, epsilon = TOL);
    let y = f(x).unwrap();
    panic!("no value here");
    let e = check().unwrap_err();
    if bad { panic!() }
}
"#;
    let found = problems(refused, "t.rs");
    let lines: Vec<&str> = found
        .iter()
        .map(|p| p.split(':').nth(1).unwrap_or(""))
        .collect();
    assert_eq!(
        lines,
        ["2", "3", "4", "5", "6", "7", "8", "9", "10", "11", "12"],
        "the lines the check finds in:\n{refused}\nits findings:\n{}",
        found.join("\n")
    );
    assert!(
        found[0].starts_with("t.rs:2:5: a bare assert!"),
        "the first finding: {}",
        found[0]
    );
    let accepted = r#"fn t() {
    assert!(x > 1.0, "x = {x}");
    assert!(x > 1.0, "x = {}, expected more than 1", x);
    assert!(ok, r"raw {v:?}",);
    assert!(ok, "{{braces}} and a value {v:?}");
    assert_eq!(a, b, "the entering flag of the first hit");
    assert_ne!(a, b, "{what}");
    let y = f(x).expect("f gives a y for x = 1");
    let z = g().unwrap_or_else(|| panic!("g of {a}: none"));
    let w = h().unwrap_or(0.0);
    debug_assert!(ok, "{ok}");
    macro_rules! m { ($a:expr) => { check($a) }; }
}
"#;
    let found = problems(accepted, "t.rs");
    assert!(
        found.is_empty(),
        "the check refuses what shows a value:\n{}",
        found.join("\n")
    );
}

// ── first_check ─────────────────────────────────────────────────────────────────────────────

/// The names of the functions declared in the Rust source `text`.
fn function_names(text: &str) -> Vec<String> {
    fn walk(stream: TokenStream, out: &mut Vec<String>) {
        let tokens: Vec<TokenTree> = stream.into_iter().collect();
        for (i, t) in tokens.iter().enumerate() {
            match t {
                TokenTree::Ident(kw) if *kw == "fn" => {
                    if let Some(TokenTree::Ident(name)) = tokens.get(i + 1) {
                        out.push(name.to_string());
                    }
                }
                TokenTree::Group(g) => walk(g.stream(), out),
                _ => {}
            }
        }
    }
    let mut out = Vec::new();
    walk(text.parse().unwrap_or_default(), &mut out);
    out
}

/// The functions of each handout test target, by target (its files: `NAME.rs`, or `NAME/`).
fn functions_by_target(root: &Path, m: &Manifest) -> BTreeMap<String, Vec<String>> {
    let mut out: BTreeMap<String, Vec<String>> = BTreeMap::new();
    for f in student_test_files(root, m) {
        let relative = f.strip_prefix(layout::core_tests()).unwrap_or(&f);
        let target = relative
            .components()
            .next()
            .map(|c| {
                c.as_os_str()
                    .to_string_lossy()
                    .trim_end_matches(".rs")
                    .to_string()
            })
            .unwrap_or_default();
        let text = std::fs::read_to_string(root.join(&f))
            .unwrap_or_else(|e| panic!("cannot read {}: {e}", f.display()));
        out.entry(target).or_default().extend(function_names(&text));
    }
    out
}

/// Each `first_check` of `m` that names no test of its exercise in its chapter's test target:
/// `MANIFEST:LINE: …`, with the exercise's tests. `manifest_text` is the manifest as written
/// (for the line of the key).
fn first_check_problems(
    m: &Manifest,
    manifest_text: &str,
    functions: &BTreeMap<String, Vec<String>>,
) -> Vec<String> {
    let lines: Vec<&str> = manifest_text.lines().collect();
    let mut out = Vec::new();
    for e in &m.entries {
        let x = &e.exercise;
        let Some(check) = &x.first_check else {
            continue;
        };
        let target = whitted_learn::syllabus::chapter(e.chapter).map_or("?", |c| c.binary);
        let own: Vec<&String> = functions
            .get(target)
            .into_iter()
            .flatten()
            .filter(|f| f.starts_with(&x.test_prefix()))
            .collect();
        let wanted = format!("{}{check}", x.test_prefix());
        if own.iter().any(|f| **f == wanted) {
            continue;
        }
        // the key's line: the first `first_check` from the entry's `function` on
        let line = (e.line.saturating_sub(1)..lines.len())
            .find(|&i| lines[i].trim_start().starts_with("first_check"))
            .map_or(e.line, |i| i + 1);
        out.push(format!(
            "{}:{line}: exercise {} ({}): first_check = {check:?} names no test: there is no \
             `fn {wanted}` in {}; its tests are {own:?}",
            m.file,
            x.name,
            x.id,
            layout::core_test_target(&root(), target).display()
        ));
    }
    out
}

/// Every `first_check` of the manifest is the rest of the name of one of its exercise's tests.
#[test]
fn every_first_check_names_a_test_of_its_exercise() {
    let root = root();
    let m = manifest();
    let text = std::fs::read_to_string(root.join(manifest::DEFAULT_PATH))
        .unwrap_or_else(|e| panic!("cannot read the manifest: {e}"));
    let found = first_check_problems(&m, &text, &functions_by_target(&root, &m));
    assert!(found.is_empty(), "{}", found.join("\n"));
}

/// A typo in a `first_check` fails at the manifest's line, naming the test it looked for.
#[test]
fn a_first_check_with_a_typo_is_found_at_its_line() {
    let root = root();
    let text = std::fs::read_to_string(root.join(manifest::DEFAULT_PATH))
        .unwrap_or_else(|e| panic!("cannot read the manifest: {e}"));
    let right = "first_check = \"viewing_angle_is_converted_from_degrees\"";
    let line = text
        .lines()
        .position(|l| l.trim() == right)
        .map(|i| i + 1)
        .unwrap_or_else(|| panic!("the manifest holds no line {right}"));
    let typo = text.replace(
        right,
        "first_check = \"viewing_angle_is_converted_from_degree\"",
    );
    let m = manifest::parse(&typo, "formulas.toml")
        .unwrap_or_else(|e| panic!("the manifest with a typo in a first_check: {e}"));
    let found = first_check_problems(&m, &typo, &functions_by_target(&root, &m));
    assert_eq!(
        found.len(),
        1,
        "the problems found with a typo on line {line}: {found:?}"
    );
    assert!(
        found[0].starts_with(&format!(
            "formulas.toml:{line}: exercise near_plane_half_height"
        )) && found[0]
            .contains("fn ex_near_plane_half_height_viewing_angle_is_converted_from_degree`")
            && found[0].contains("ch01_camera_rays.rs"),
        "the problem found with a typo on line {line}: {}",
        found[0]
    );
}
