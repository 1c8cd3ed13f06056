//! The course book (`docs/`, an mdBook): the checks that keep it honest. (Its figures are
//! [`crate::figures`].)
//!
//! `whitted book` builds the book and fails on what mdBook and its preprocessors only log:
//!
//! - an `{{#include file:anchor}}` whose file, anchor or line range gives nothing
//!   ([`check_includes`]; mdBook logs it and builds the page without it);
//! - a warning or error of mdBook or mdbook-katex (a formula KaTeX cannot parse is logged,
//!   and the page keeps the raw TeX) ([`log_problems`]);
//! - in the built HTML, a link or image to a file that is not there, a `#fragment` that no
//!   element carries, anything loaded from the network (`src=` or a stylesheet over
//!   `http(s)://`), and a chapter page without typeset math or without a figure
//!   ([`check_html`]).
//!
//! Course book: [Introduction](../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::collections::{BTreeMap, HashMap};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use super::ToolError;
use crate::files::line_col;

/// A problem found in the book, where it is.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Problem {
    /// The file, as given to the check (a page of `src/`, or a page of the built book).
    pub file: PathBuf,
    /// The line, from 1 (0 when the problem has no line).
    pub line: usize,
    /// What is wrong.
    pub message: String,
}

impl std::fmt::Display for Problem {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.line == 0 {
            write!(f, "{}: {}", self.file.display(), self.message)
        } else {
            write!(f, "{}:{}: {}", self.file.display(), self.line, self.message)
        }
    }
}

/// The files under `dir` (and its subdirectories) whose extension is `extension`, sorted.
pub fn pages(dir: &Path, extension: &str) -> Result<Vec<PathBuf>, ToolError> {
    let mut found = Vec::new();
    let mut stack = vec![dir.to_path_buf()];
    while let Some(d) = stack.pop() {
        for entry in std::fs::read_dir(&d).map_err(|e| ToolError::io(&d, e))? {
            let path = entry.map_err(|e| ToolError::io(&d, e))?.path();
            if path.is_dir() {
                stack.push(path);
            } else if path.extension().is_some_and(|e| e == extension) {
                found.push(path);
            }
        }
    }
    found.sort();
    Ok(found)
}

/// Checks every `{{#include …}}` and `{{#rustdoc_include …}}` of the pages under `src_dir`:
/// the file must exist, a named anchor must have its `ANCHOR: name` and `ANCHOR_END: name`
/// lines with something between them, and a line range must lie inside the file. Escaped
/// links (`\{{#include …}}`) are text, not links.
pub fn check_includes(src_dir: &Path) -> Result<Vec<Problem>, ToolError> {
    let mut problems = Vec::new();
    for page in pages(src_dir, "md")? {
        let text = std::fs::read_to_string(&page).map_err(|e| ToolError::io(&page, e))?;
        let dir = page.parent().unwrap_or(src_dir);
        for (line, target) in include_links(&text) {
            if let Err(message) = resolve_include(dir, &target) {
                problems.push(Problem {
                    file: page.clone(),
                    line,
                    message,
                });
            }
        }
    }
    Ok(problems)
}

/// The include links of a page: (line, the text after the command), e.g.
/// `(12, "../../src/camera.rs:basis")`.
#[must_use]
pub fn include_links(text: &str) -> Vec<(usize, String)> {
    let mut links = Vec::new();
    for (number, line) in text.lines().enumerate() {
        let mut rest = line;
        let mut offset = 0;
        while let Some(i) = rest.find("{{#") {
            let at = offset + i;
            let escaped = at > 0 && line.as_bytes()[at - 1] == b'\\';
            let after = &rest[i + 3..];
            let Some(end) = after.find("}}") else { break };
            let body = after[..end].trim();
            if !escaped
                && let Some((command, target)) = body.split_once(char::is_whitespace)
                && matches!(command, "include" | "rustdoc_include")
            {
                links.push((number + 1, target.trim().to_string()));
            }
            offset = at + 3 + end + 2;
            rest = &line[offset..];
        }
    }
    links
}

/// `text` with every `{{#include …}}` replaced by what it includes (relative to `dir`), for
/// pages read without mdBook; an include that gives nothing is an error.
pub fn expand_includes(text: &str, dir: &Path) -> Result<String, String> {
    let mut out = String::with_capacity(text.len());
    let mut rest = text;
    while let Some(i) = rest.find("{{#") {
        let escaped = i > 0 && rest.as_bytes()[i - 1] == b'\\';
        let after = &rest[i + 3..];
        let Some(end) = after.find("}}") else { break };
        let body = after[..end].trim();
        out.push_str(&rest[..i]);
        match body.split_once(char::is_whitespace) {
            Some((command, target))
                if !escaped && matches!(command, "include" | "rustdoc_include") =>
            {
                out.push_str(&resolve_include(dir, target.trim())?);
            }
            _ => out.push_str(&rest[i..i + 3 + end + 2]),
        }
        rest = &after[end + 2..];
    }
    out.push_str(rest);
    Ok(out)
}

/// What `target` (`path`, `path:anchor`, `path:N`, `path:N:M`, `path:N:`, `path::M`)
/// includes, relative to `dir`; an error says why it would include nothing.
pub fn resolve_include(dir: &Path, target: &str) -> Result<String, String> {
    let (path, selector) = match target.split_once(':') {
        Some((p, s)) => (p, Some(s)),
        None => (target, None),
    };
    let file = dir.join(path);
    let text = std::fs::read_to_string(&file)
        .map_err(|e| format!("include `{target}`: cannot read {}: {e}", file.display()))?;
    let lines: Vec<&str> = text.lines().collect();
    let Some(selector) = selector else {
        return if text.trim().is_empty() {
            Err(format!("include `{target}`: the file is empty"))
        } else {
            Ok(text)
        };
    };
    let number = |s: &str| -> Result<Option<usize>, String> {
        if s.is_empty() {
            Ok(None)
        } else {
            s.parse()
                .map(Some)
                .map_err(|_| format!("include `{target}`: `{s}` is not a line number"))
        }
    };
    let is_range = selector.chars().all(|c| c.is_ascii_digit() || c == ':') && !selector.is_empty();
    if is_range {
        let (from, to) = match selector.split_once(':') {
            Some((a, b)) => (number(a)?, number(b)?),
            None => {
                let n = number(selector)?;
                (n, n)
            }
        };
        let from = from.unwrap_or(1);
        let to = to.unwrap_or(lines.len());
        if from == 0 || from > to || to > lines.len() {
            return Err(format!(
                "include `{target}`: lines {from} to {to} are not inside the file's {} lines",
                lines.len()
            ));
        }
        return Ok(lines[from - 1..to].join("\n"));
    }
    let start = format!("ANCHOR: {selector}");
    let end = format!("ANCHOR_END: {selector}");
    let is = |line: &str, marker: &str| {
        line.find(marker).is_some_and(|i| {
            line[i + marker.len()..]
                .chars()
                .next()
                .is_none_or(|c| !(c.is_alphanumeric() || c == '_'))
        })
    };
    let Some(open) = lines.iter().position(|l| is(l, &start)) else {
        return Err(format!(
            "include `{target}`: no line `ANCHOR: {selector}` in {}",
            file.display()
        ));
    };
    let Some(close) = lines[open + 1..].iter().position(|l| is(l, &end)) else {
        return Err(format!(
            "include `{target}`: `ANCHOR: {selector}` on line {} of {} has no `ANCHOR_END: {selector}` after it",
            open + 1,
            file.display()
        ));
    };
    let body: Vec<&str> = lines[open + 1..open + 1 + close]
        .iter()
        .filter(|l| !l.contains("ANCHOR: ") && !l.contains("ANCHOR_END: "))
        .copied()
        .collect();
    if body.iter().all(|l| l.trim().is_empty()) {
        return Err(format!(
            "include `{target}`: the anchor `{selector}` in {} holds nothing",
            file.display()
        ));
    }
    Ok(body.join("\n"))
}

/// The lines of mdBook's log that are problems: every warning and error, except the notice
/// of mdbook-katex that it was built against another 0.5 release of mdBook than the one
/// running it (their interface is the same within 0.5; the registries have no pair of
/// matching prebuilt releases).
#[must_use]
pub fn log_problems(log: &str) -> Vec<String> {
    log.lines()
        .map(strip_ansi)
        .filter(|l| l.contains(" WARN ") || l.contains("ERROR ") || l.starts_with("WARN "))
        .filter(|l| !(l.contains("mdbook_katex") && l.contains("was built against mdbook")))
        .map(|l| l.trim().to_string())
        .collect()
}

/// `text` without terminal colour escapes (`ESC [ … m`).
fn strip_ansi(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    let mut chars = text.chars();
    while let Some(c) = chars.next() {
        if c == '\u{1b}' {
            for d in chars.by_ref() {
                if d.is_ascii_alphabetic() {
                    break;
                }
            }
        } else {
            out.push(c);
        }
    }
    out
}

/// What the checks read of one page of the built book, parsed as HTML (with `tl`).
#[derive(Debug, Default)]
struct Page {
    /// Every `src` and `href` value, with its attribute's name, its line and whether its tag
    /// links a stylesheet (`<link rel="stylesheet">`).
    links: Vec<Link>,
    /// The `id`s of its elements.
    ids: Vec<String>,
    /// The line of the first element of class `katex-error`, if any.
    katex_error: Option<usize>,
    /// The inner HTML of its `<main>` (the whole page without one), and where it starts.
    main: (String, usize),
    /// Whether `<main>` holds typeset math (an element of class `katex`).
    math: bool,
    /// Whether `<main>` holds an image of `figures/`.
    figure: bool,
}

/// A `src` or `href` of a page.
#[derive(Debug)]
struct Link {
    attribute: &'static str,
    value: String,
    line: usize,
    stylesheet: bool,
}

impl Page {
    /// Reads `html`; a page that does not parse reads as empty.
    fn read(html: &str) -> Page {
        let Ok(dom) = tl::parse(html, tl::ParserOptions::default()) else {
            return Page::default();
        };
        let parser = dom.parser();
        let text = |b: &tl::Bytes| b.as_utf8_str().replace("&amp;", "&");
        let mut page = Page {
            main: (html.to_string(), 0),
            ..Page::default()
        };
        let mut main_range = None;
        let mut tags = Vec::new();
        for tag in dom.nodes().iter().filter_map(tl::Node::as_tag) {
            let (start, end) = tag.boundaries(parser);
            let name = tag.name().as_utf8_str().to_ascii_lowercase();
            let attributes = tag.attributes();
            let line = line_col(html, start).0;
            let stylesheet = name == "link"
                && attributes
                    .get("rel")
                    .flatten()
                    .is_some_and(|r| text(r).split_whitespace().any(|w| w == "stylesheet"));
            for attribute in ["src", "href"] {
                if let Some(Some(value)) = attributes.get(attribute) {
                    page.links.push(Link {
                        attribute,
                        value: text(value),
                        line,
                        stylesheet,
                    });
                }
            }
            if let Some(id) = attributes.id() {
                page.ids.push(text(id));
            }
            if attributes.is_class_member("katex-error") && page.katex_error.is_none() {
                page.katex_error = Some(line);
            }
            if name == "main" && main_range.is_none() {
                main_range = Some(start..=end);
                page.main = (tag.inner_html(parser), start);
            }
            let figure = name == "img"
                && attributes
                    .get("src")
                    .flatten()
                    .is_some_and(|v| text(v).starts_with("figures/"));
            tags.push((start, attributes.is_class_member("katex"), figure));
        }
        let inside = |at: usize| main_range.as_ref().is_none_or(|r| r.contains(&at));
        for (start, katex, figure) in tags {
            if inside(start) {
                page.math |= katex;
                page.figure |= figure;
            }
        }
        page
    }
}

/// The `id`s of the elements of `html`.
fn ids(html: &str) -> Vec<String> {
    Page::read(html).ids
}

/// Checks the built book under `book_dir`: every relative `href` and `src` must name a file
/// of the book, and a `#fragment` an `id` of its page; nothing may be loaded from the network
/// (`src=` or a stylesheet over http(s) or `//`); no formula may have failed to render
/// (KaTeX's `katex-error`, or a `$$` left in the text); and each page named in `chapters`
/// (e.g. `ch01-camera-rays.html`) must show typeset math and at least one figure.
pub fn check_html(book_dir: &Path, chapters: &[&str]) -> Result<Vec<Problem>, ToolError> {
    let files = pages(book_dir, "html")?;
    let mut texts: BTreeMap<PathBuf, String> = BTreeMap::new();
    for f in &files {
        let text = std::fs::read_to_string(f).map_err(|e| ToolError::io(f, e))?;
        texts.insert(f.clone(), text);
    }
    let mut id_cache: HashMap<PathBuf, Vec<String>> = HashMap::new();
    let mut problems = Vec::new();
    for (page, html) in &texts {
        let read = Page::read(html);
        // mdBook's 404 page sets `<base href="/">` (the site's root): its links start there
        let dir = if html.contains("<base href=\"/\"") {
            book_dir
        } else {
            page.parent().unwrap_or(book_dir)
        };
        let mut problem = |line: usize, message: String| {
            problems.push(Problem {
                file: page.clone(),
                line,
                message,
            });
        };
        for link in &read.links {
            let (attribute, value, line) = (link.attribute, link.value.as_str(), link.line);
            let loads = attribute == "src";
            let remote = value.starts_with("http://")
                || value.starts_with("https://")
                || value.starts_with("//");
            if remote {
                if loads || link.stylesheet {
                    problem(line, format!("loads `{value}` from the network"));
                }
                continue;
            }
            if value.contains(':') && !value.starts_with('#') {
                continue; // mailto:, javascript:, data: …
            }
            let (path, fragment) = match value.split_once('#') {
                Some((p, f)) => (p, Some(f)),
                None => (value, None),
            };
            let path = path.split('?').next().unwrap_or(path);
            let target = if path.is_empty() {
                page.clone()
            } else {
                let t = match path.strip_prefix('/') {
                    Some(from_root) => book_dir.join(percent_decode(from_root)),
                    None => dir.join(percent_decode(path)),
                };
                if t.is_dir() { t.join("index.html") } else { t }
            };
            if !target.is_file() {
                problem(
                    line,
                    format!("`{attribute}=\"{value}\"`: no such file in the book"),
                );
                continue;
            }
            if let Some(fragment) = fragment.filter(|f| !f.is_empty())
                && target.extension().is_some_and(|e| e == "html")
            {
                let known = id_cache.entry(target.clone()).or_insert_with(|| {
                    texts
                        .get(&target)
                        .map(|t| ids(t))
                        .or_else(|| std::fs::read_to_string(&target).ok().map(|t| ids(&t)))
                        .unwrap_or_default()
                });
                let fragment = percent_decode(fragment);
                if !known.contains(&fragment) {
                    problem(
                        line,
                        format!("`{attribute}=\"{value}\"`: the page has no `id=\"{fragment}\"`"),
                    );
                }
            }
        }
        if let Some(line) = read.katex_error {
            problem(line, "a formula failed to render".to_string());
        }
        let (main, start) = &read.main;
        if let Some(i) = main.find("$$") {
            let at = html
                .get(*start..)
                .and_then(|h| h.find("$$"))
                .map_or(i, |j| start + j);
            problem(
                line_col(html, at).0,
                "`$$` left in the text: a formula was not typeset".to_string(),
            );
        }
        let name = page.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if chapters.contains(&name) {
            if !read.math {
                problem(0, "a chapter page without typeset math".to_string());
            }
            if !read.figure {
                problem(0, "a chapter page without a figure".to_string());
            }
        }
    }
    Ok(problems)
}

/// `%XX` escapes of a URL path decoded (as UTF-8; an invalid escape is kept as it is).
fn percent_decode(text: &str) -> String {
    let bytes = text.as_bytes();
    let mut out = Vec::with_capacity(bytes.len());
    let mut i = 0;
    while i < bytes.len() {
        let hex = |b: u8| (b as char).to_digit(16);
        if bytes[i] == b'%'
            && i + 2 < bytes.len()
            && let (Some(h), Some(l)) = (hex(bytes[i + 1]), hex(bytes[i + 2]))
        {
            out.push((h * 16 + l) as u8);
            i += 3;
        } else {
            out.push(bytes[i]);
            i += 1;
        }
    }
    String::from_utf8_lossy(&out).into_owned()
}

/// `whitted book`: checks the includes, builds the book with `mdbook`, checks its log and the
/// HTML; status 1 when a problem is found (each printed as file:line: …).
pub fn command(root: &Path, mdbook: &Path) -> Result<ExitCode, ToolError> {
    let docs = root.join("docs");
    let mut problems: Vec<String> = check_includes(&docs.join("src"))?
        .iter()
        .map(ToString::to_string)
        .collect();
    let out = std::process::Command::new(mdbook)
        .arg("build")
        .arg(&docs)
        .env("NO_COLOR", "1")
        .output()
        .map_err(|e| {
            ToolError::Usage(format!(
                "cannot run `{}`: {e}: install the book's tools as docs/README.md says (`.ci/run` does)",
                mdbook.display()
            ))
        })?;
    let log = format!(
        "{}{}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    problems.extend(
        log_problems(&log)
            .into_iter()
            .map(|l| format!("mdbook: {l}")),
    );
    if !out.status.success() {
        problems.push(format!("mdbook build failed ({})", out.status));
    } else {
        let chapters: Vec<String> = crate::syllabus::CHAPTERS
            .iter()
            .map(|c| format!("{}.html", c.book))
            .collect();
        let chapters: Vec<&str> = chapters.iter().map(String::as_str).collect();
        let built = docs.join("book");
        for chapter in &chapters {
            if !built.join(chapter).is_file() {
                problems.push(format!(
                    "docs/book/{chapter}: the chapter page was not built"
                ));
            }
        }
        problems.extend(
            check_html(&built, &chapters)?
                .iter()
                .map(ToString::to_string),
        );
    }
    for p in &problems {
        println!("{p}");
    }
    if problems.is_empty() {
        println!(
            "the book is built and clean: {}",
            docs.join("book/index.html").display()
        );
        Ok(ExitCode::SUCCESS)
    } else {
        println!("{} problems in the book", problems.len());
        Ok(ExitCode::from(1))
    }
}

/// The arguments of `whitted book`.
#[derive(clap::Args)]
pub struct BookArgs {
    /// The mdbook program to run.
    #[arg(long, value_name = "PATH", default_value = "mdbook")]
    mdbook: PathBuf,
    /// The project [default: the nearest Cargo.toml at or above the current directory].
    #[arg(long, value_name = "DIR")]
    root: Option<PathBuf>,
}

impl BookArgs {
    /// Runs `whitted book` on the project the arguments name.
    pub fn run(&self) -> Result<ExitCode, ToolError> {
        let root = crate::project::root(self.root.as_ref())?;
        command(&root, &self.mdbook)
    }
}
