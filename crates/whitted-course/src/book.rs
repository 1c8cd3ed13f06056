//! The course book (`docs/`, an mdBook): its figures, and the checks that keep it honest.
//!
//! Every render in the book is made by a chapter binary from a scene of the repository; the
//! manifest `docs/figures.toml` lists them, one `[[figure]]` table each:
//!
//! ```toml
//! [[figure]]
//! file = "ch02-normals.png"          # under docs/src/figures/
//! binary = "ch02_generic_objects"     # one of the five chapter binaries
//! args = ["scenes/ch02_generic_objects.toml", "--view", "normals", "--width", "320"]
//! ```
//!
//! `whitted figures` renders them all (`BINARY ARGS -o docs/src/figures/FILE`, from the
//! project's root); `whitted figures --check` renders them to a temporary directory and
//! compares each with the committed PNG, pixel by pixel, within [`TOLERANCE`].
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
use std::ops::Range;
use std::path::{Path, PathBuf};

use serde::Deserialize;

use super::ToolError;
use super::manifest::{error_at, from_toml};
use crate::files::line_col;

/// The largest difference, in 8-bit levels, between a committed figure and a fresh render of
/// it that `whitted figures --check` accepts: floating point may round the last bit
/// differently on another machine, and one level is 1/255.
pub const TOLERANCE: u8 = 1;

/// The chapter binaries a figure may name.
pub const BINARIES: [&str; 5] = [
    "ch01_camera_rays",
    "ch02_generic_objects",
    "ch03_shading",
    "ch04_shadows",
    "ch05_reflection_refraction",
];

/// One render of the book, as the manifest lists it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Figure {
    /// The PNG's name under `docs/src/figures/`.
    pub file: String,
    /// The chapter binary that renders it.
    pub binary: String,
    /// Its arguments, all but `-o`; paths are relative to the project's root.
    pub args: Vec<String>,
    /// The line of the manifest where its table starts.
    pub line: usize,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFigures {
    #[serde(default)]
    figure: Vec<toml::Spanned<RawFigure>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawFigure {
    file: toml::Spanned<String>,
    binary: toml::Spanned<String>,
    args: Vec<String>,
}

/// Reads the figures' manifest; a mistake is reported as `file:line:col: …`.
pub fn read_figures(path: &Path) -> Result<Vec<Figure>, ToolError> {
    let text = std::fs::read_to_string(path).map_err(|e| ToolError::io(path, e))?;
    parse_figures(&text, &path.display().to_string())
}

/// Checks the manifest text `text`; `file` names it in messages. Each `file` must be a plain
/// `NAME.png` (no directory) named once, each `binary` one of [`BINARIES`], and `args` must
/// not say where to write (`-o`/`--output`): the manifest's `file` does.
pub fn parse_figures(text: &str, file: &str) -> Result<Vec<Figure>, ToolError> {
    let err = |span: Range<usize>, message: String| error_at(text, file, span, message);
    let raw: RawFigures = from_toml(text, file)?;
    let mut seen: HashMap<String, usize> = HashMap::new();
    let mut figures = Vec::new();
    for spanned in &raw.figure {
        let raw = spanned.get_ref();
        let name = raw.file.get_ref();
        let plain = !name.contains(['/', '\\']) && name.len() > 4 && name.ends_with(".png");
        if !plain {
            return Err(err(
                raw.file.span(),
                format!("file `{name}` must be a name ending in .png, without a directory"),
            ));
        }
        let (line, _) = line_col(text, spanned.span().start);
        if let Some(first) = seen.insert(name.clone(), line) {
            return Err(err(
                raw.file.span(),
                format!("file `{name}` is listed twice (first on line {first})"),
            ));
        }
        if !BINARIES.contains(&raw.binary.get_ref().as_str()) {
            return Err(err(
                raw.binary.span(),
                format!(
                    "binary `{}` is not a chapter binary (one of {})",
                    raw.binary.get_ref(),
                    BINARIES.join(", ")
                ),
            ));
        }
        if let Some(o) = raw
            .args
            .iter()
            .find(|a| *a == "-o" || a.starts_with("--output"))
        {
            return Err(err(
                spanned.span(),
                format!("args must not contain `{o}`: the figure's `file` says where it goes"),
            ));
        }
        figures.push(Figure {
            file: name.clone(),
            binary: raw.binary.get_ref().clone(),
            args: raw.args.clone(),
            line,
        });
    }
    Ok(figures)
}

/// Renders `figure` to `out` with the binary of that name in `bin_dir`, from `root` (so that
/// the scene paths of its arguments resolve). The binary's own message is the error.
pub fn render(figure: &Figure, bin_dir: &Path, root: &Path, out: &Path) -> Result<(), ToolError> {
    let binary = bin_dir.join(format!("{}{}", figure.binary, std::env::consts::EXE_SUFFIX));
    if !binary.is_file() {
        return Err(ToolError::Usage(format!(
            "{} is not built: run `cargo build --bins` (or --release) first",
            binary.display()
        )));
    }
    let result = std::process::Command::new(&binary)
        .args(&figure.args)
        .arg("-o")
        .arg(out)
        .arg("--quiet")
        .current_dir(root)
        .output()
        .map_err(|e| ToolError::io(&binary, e))?;
    if result.status.success() {
        Ok(())
    } else {
        let stderr = String::from_utf8_lossy(&result.stderr);
        Err(ToolError::Figure(format!(
            "{} {}: {}",
            figure.binary,
            figure.args.join(" "),
            stderr.trim()
        )))
    }
}

/// How a fresh render differs from the committed figure.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Difference {
    /// Every channel of every pixel is within [`TOLERANCE`].
    Same,
    /// The two images do not have the same size: (committed, fresh), as (width, height).
    Size((u32, u32), (u32, u32)),
    /// `pixels` pixels have a channel off by more than the tolerance, at most by `largest`
    /// levels; `first` is the first such pixel, (x, y) from the top left.
    Pixels {
        /// How many pixels differ.
        pixels: usize,
        /// The largest difference of a channel, in 8-bit levels.
        largest: u8,
        /// The first pixel that differs.
        first: (u32, u32),
    },
}

/// Compares two PNGs channel by channel; a difference of at most `tolerance` levels counts as
/// the same.
pub fn compare(committed: &Path, fresh: &Path, tolerance: u8) -> Result<Difference, ToolError> {
    let (a, b) = (read_rgba(committed)?, read_rgba(fresh)?);
    if a.0 != b.0 {
        return Ok(Difference::Size(a.0, b.0));
    }
    let mut pixels = 0;
    let mut largest = 0;
    let mut first = None;
    let width = a.0.0 as usize;
    for (i, (p, q)) in a.1.chunks_exact(4).zip(b.1.chunks_exact(4)).enumerate() {
        let (x, y) = ((i % width) as u32, (i / width) as u32);
        let off = p
            .iter()
            .zip(q)
            .map(|(u, v)| u.abs_diff(*v))
            .max()
            .unwrap_or(0);
        if off > tolerance {
            pixels += 1;
            largest = largest.max(off);
            first.get_or_insert((x, y));
        }
    }
    Ok(match first {
        None => Difference::Same,
        Some(first) => Difference::Pixels {
            pixels,
            largest,
            first,
        },
    })
}

/// A PNG's size and its pixels as 8-bit RGBA, row by row from the top.
fn read_rgba(path: &Path) -> Result<((u32, u32), Vec<u8>), ToolError> {
    let fail =
        |e: String| ToolError::Usage(format!("{}: cannot read the PNG: {e}", path.display()));
    let file = std::fs::File::open(path).map_err(|e| fail(e.to_string()))?;
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info().map_err(|e| fail(e.to_string()))?;
    let mut buf = vec![0; reader.output_buffer_size().unwrap_or(0)];
    let info = reader
        .next_frame(&mut buf)
        .map_err(|e| fail(e.to_string()))?;
    let samples = info.color_type.samples();
    let rgba = buf[..info.buffer_size()]
        .chunks_exact(samples)
        .flat_map(|p| match *p {
            [g] => [g, g, g, 255],
            [g, a] => [g, g, g, a],
            [r, g, b] => [r, g, b, 255],
            [r, g, b, a, ..] => [r, g, b, a],
            [] => [0, 0, 0, 0],
        })
        .collect();
    Ok(((info.width, info.height), rgba))
}

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

/// The values of the attribute `name` in the tags of `html`, each with its line.
fn attributes(html: &str, name: &str) -> Vec<(usize, String)> {
    let mut found = Vec::new();
    let needle = format!(" {name}=");
    let mut from = 0;
    while let Some(i) = html[from..].find(&needle) {
        let start = from + i + needle.len();
        let quote = html[start..].chars().next();
        let value = match quote {
            Some(q @ ('"' | '\'')) => html[start + 1..]
                .find(q)
                .map(|end| &html[start + 1..start + 1 + end]),
            _ => html[start..]
                .find(|c: char| c.is_whitespace() || c == '>')
                .map(|end| &html[start..start + end]),
        };
        if let Some(v) = value {
            found.push((line_col(html, start).0, v.replace("&amp;", "&")));
        }
        from = start;
    }
    found
}

/// The `id`s of the elements of `html`.
fn ids(html: &str) -> Vec<String> {
    attributes(html, "id").into_iter().map(|(_, v)| v).collect()
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
        for (attribute, loads) in [("src", true), ("href", false)] {
            for (line, value) in attributes(html, attribute) {
                let remote = value.starts_with("http://")
                    || value.starts_with("https://")
                    || value.starts_with("//");
                if remote {
                    let stylesheet = !loads && is_stylesheet_link(html, &value);
                    if loads || stylesheet {
                        problem(line, format!("loads `{value}` from the network"));
                    }
                    continue;
                }
                if value.contains(':') && !value.starts_with('#') {
                    continue; // mailto:, javascript:, data: …
                }
                let (path, fragment) = match value.split_once('#') {
                    Some((p, f)) => (p, Some(f)),
                    None => (value.as_str(), None),
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
                            format!(
                                "`{attribute}=\"{value}\"`: the page has no `id=\"{fragment}\"`"
                            ),
                        );
                    }
                }
            }
        }
        if let Some(i) = html.find("katex-error") {
            problem(
                line_col(html, i).0,
                "a formula failed to render".to_string(),
            );
        }
        let start = html.find("<main>").unwrap_or(0);
        let end = html[start..]
            .find("</main>")
            .map_or(html.len(), |j| start + j);
        let main = &html[start..end];
        if let Some(i) = main.find("$$") {
            problem(
                line_col(html, start + i).0,
                "`$$` left in the text: a formula was not typeset".to_string(),
            );
        }
        let name = page.file_name().and_then(|n| n.to_str()).unwrap_or("");
        if chapters.contains(&name) {
            if !main.contains("class=\"katex\"") {
                problem(0, "a chapter page without typeset math".to_string());
            }
            if !main.contains("<img src=\"figures/") {
                problem(0, "a chapter page without a figure".to_string());
            }
        }
    }
    Ok(problems)
}

/// Whether `html` links `url` as a stylesheet (`<link rel="stylesheet" href="url">`).
fn is_stylesheet_link(html: &str, url: &str) -> bool {
    html.match_indices("<link").any(|(i, _)| {
        let tag = &html[i..html[i..].find('>').map_or(html.len(), |j| i + j)];
        tag.contains(url) && tag.contains("stylesheet")
    })
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
