//! The reference's ray trees as data, and the course's known mistakes: `whitted trees
//! [--check]`.
//!
//! For each chapter, the chapter's binary renders its scene as the book's figure of it
//! (`docs/figures.toml`, the figure `chNN_name.png`: the same settings `cargo learn` renders
//! the student's picture with) and prints the ray tree of every [`STEP`]-th pixel of every
//! [`STEP`]-th row (`--inspect-grid`). Of those pixels, a few are kept, chosen greedily so
//! that together they show every [feature](features) of the scene's trees: each object and
//! each part of it hit (by any ray), each light lit, in shadow, in a translucent shadow and
//! behind the surface, each light's highlight, each kind of branch and each reason a branch
//! stops (total internal reflection among them), a miss, and each quarter of the image. Only
//! *steady* pixels are kept: pixels whose neighbours at [`STEP`] pixels all have trees of the
//! same shape ([`signature`]), so that a tree traced in f32, or with a formula written in
//! another correct way, has the reference's shape there too.
//!
//! Then the course's known mistakes ([`crate::mistakes`]) are applied to the reference one
//! at a time (one build, each behind a switch), and each one's chapter is traced `--against`
//! every steady pixel: a mistake whose trees differ at none of the pixels kept adds the
//! steadiest pixel where its trees do differ, so that every known mistake shows in the data.
//! `chapters/chNN_name/trees.json` is written (its shape: `docs/src/inspect.md`), then each
//! mistake's fingerprint, rendered with `--compare` beside the figure and `--against` the
//! file, into `chapters/mistakes.json` ([`whitted_learn::trees`]). Both ship with a handout.
//! They hold numbers at a few pixels, which the figures show already, and the mistakes' words:
//! nothing of the code.
//!
//! `whitted trees --check` keeps the pixels of the committed files: it checks that the
//! reference's trees there are still the committed ones (within the tolerances of the
//! comparison), and that the pixels chosen for the scene's features are still those a fresh
//! choice makes. It needs no build of the mistakes.
//!
//! Course book: [The ray tree of one pixel](../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

use serde_json::{Value, json};

use crate::cargo::{Build, Stderr};
use crate::figures::{self, Figure};
use crate::manifest::Manifest;
use crate::mistakes::{self, Mutant};
use crate::syllabus::{self, Chapter};
use crate::{ToolError, layout};
use whitted_learn::trees::{Against, Fingerprint, Mistake, read_output};

/// Where the known mistakes and each chapter's trees are kept, and the known mistakes' file
/// (the student's loop reads them).
pub use whitted_learn::trees::{MISTAKES, Mistakes, trees_file};

/// The distance in pixels between the pixels whose trees are traced to choose from: every
/// pixel, so that a steady pixel's neighbours are the pixels next to it.
pub const STEP: u32 = 1;

/// The specular factor ρs·max(r·v, 0)^f (its largest channel) from which a light's term at a
/// hit is a highlight, a feature the pixels kept must show: a mistake in r or in the
/// highlight then changes a number a kept tree holds, not only numbers of order 10⁻⁵ at the
/// edge of a highlight.
pub const HIGHLIGHT: f64 = 0.05;

/// The words the pixels a known mistake adds are kept for.
const MISTAKE_SHOWS: &str = "a known mistake of exercise";

/// A tree kept in a trees file, with what it is kept for.
type Kept = (Value, Vec<String>);

/// A tree chosen from a [`Grid`], by its index, with what it is chosen for.
type Pick = (usize, Vec<String>);

/// The trees traced at every [`STEP`]-th pixel of a chapter's scene: each as its line of JSON,
/// with its shape ([`signature`]) and what it shows ([`features`]).
struct Grid {
    /// The settings line `--inspect-grid` prints first.
    settings: Value,
    /// The trees' JSON, row by row.
    lines: Vec<String>,
    /// Each tree's shape.
    shapes: Vec<String>,
    /// What each tree shows.
    shows: Vec<BTreeSet<String>>,
    /// Pixels a row.
    columns: usize,
}

impl Grid {
    fn rows(&self) -> usize {
        self.lines.len() / self.columns.max(1)
    }

    /// The pixel of tree `i`.
    fn pixel(&self, i: usize) -> (u32, u32) {
        let (c, r) = ((i % self.columns) as u32, (i / self.columns) as u32);
        (STEP / 2 + c * STEP, STEP / 2 + r * STEP)
    }

    /// The index of the tree of pixel `p`, one of the grid's.
    fn index(&self, p: (u32, u32)) -> usize {
        ((p.1 - STEP / 2) / STEP) as usize * self.columns + ((p.0 - STEP / 2) / STEP) as usize
    }

    /// Tree `i` as JSON.
    fn tree(&self, i: usize) -> Value {
        serde_json::from_str(&self.lines[i]).unwrap_or(Value::Null)
    }
}

/// The chapter's figure in `docs/figures.toml`: `chNN_name.png`.
fn figure_of<'f>(figures: &'f [Figure], chapter: &Chapter) -> Result<&'f Figure, ToolError> {
    let file = format!("{}.png", chapter.binary);
    figures.iter().find(|f| f.file == file).ok_or_else(|| {
        ToolError::Usage(format!(
            "docs/figures.toml has no figure {file}: the trees are traced with the figure's settings"
        ))
    })
}

/// Runs `exe ARGS` from `root` (with `mutant` switched on, if any): its stdout, or its
/// stderr's last line as the error.
fn run(
    exe: &Path,
    args: &[String],
    root: &Path,
    mutant: Option<&str>,
) -> Result<String, ToolError> {
    let mut command = std::process::Command::new(exe);
    command
        .args(args)
        .arg("--quiet")
        .current_dir(root)
        .env_remove(mistakes::SWITCH_VAR)
        .stdin(std::process::Stdio::null());
    if let Some(m) = mutant {
        command.env(mistakes::SWITCH_VAR, m);
    }
    let out = command.output().map_err(|e| ToolError::io(exe, e))?;
    if !out.status.success() {
        let err = String::from_utf8_lossy(&out.stderr);
        return Err(ToolError::Figure(format!(
            "{} {}{}: {}",
            exe.display(),
            args.join(" "),
            mutant.map_or(String::new(), |m| format!(" (mutant {m})")),
            err.lines().last().unwrap_or("failed")
        )));
    }
    Ok(String::from_utf8_lossy(&out.stdout).into_owned())
}

/// The trees of every [`STEP`]-th pixel of `figure`'s render, by `exe`.
fn grid(exe: &Path, figure: &Figure, root: &Path) -> Result<Grid, ToolError> {
    let mut args = figure.args.clone();
    args.extend(["--inspect-grid".to_string(), STEP.to_string()]);
    let text = run(exe, &args, root, None)?;
    let mut lines_of = text.lines();
    let bad = |why: &str| ToolError::Figure(format!("{} --inspect-grid: {why}", exe.display()));
    let header: Value = lines_of
        .next()
        .and_then(|l| serde_json::from_str(l).ok())
        .ok_or_else(|| bad("no settings line"))?;
    let settings = header["settings"].clone();
    let size = |key: &str| settings[key].as_u64().unwrap_or(0) as u32;
    let size = (size("width"), size("height"));
    let (mut lines, mut shapes, mut shows) = (Vec::new(), Vec::new(), Vec::new());
    for line in lines_of {
        let tree: Value =
            serde_json::from_str(line).map_err(|e| bad(&format!("a tree is not JSON: {e}")))?;
        shapes.push(signature(&tree));
        shows.push(features(&tree, size));
        lines.push(line.to_string());
    }
    let columns = size.0.saturating_sub(STEP / 2).div_ceil(STEP) as usize;
    if columns == 0 || lines.len() % columns != 0 {
        return Err(bad("the trees do not fill the grid"));
    }
    Ok(Grid {
        settings,
        lines,
        shapes,
        shows,
        columns,
    })
}

/// The shape of a tree: which objects and parts its rays hit and from which side, which
/// lights are in front, sent a feeler and what it crossed (and whether the share is 1, 0 or
/// between), which branches leave each hit or why they stop. Two trees of one shape
/// differ only in numbers that move continuously with the pixel.
#[must_use]
pub fn signature(tree: &Value) -> String {
    fn ray(r: &Value, out: &mut String) {
        out.push_str(r["kind"].as_str().unwrap_or("?"));
        let h = &r["hit"];
        if h.is_null() {
            out.push_str(":miss;");
            return;
        }
        out.push_str(&format!(":{}/{}/{}", h["object"], h["part"], h["entering"]));
        for l in h["lights"].as_array().into_iter().flatten() {
            out.push_str(&format!("|L{}{}", l["index"], l["in_front"]));
            if let Some(f) = l["feeler"].as_object() {
                let crossed: Vec<String> = f["crossings"]
                    .as_array()
                    .into_iter()
                    .flatten()
                    .map(|c| format!("{}x{}", c["object"], c["u"].as_array().map_or(0, Vec::len)))
                    .collect();
                // the share's class: its value is a product of the materials' k_t, whose last
                // bits differ in f32
                let share = match l["share"].as_f64() {
                    Some(1.0) => "lit",
                    Some(0.0) => "dark",
                    _ => "partly",
                };
                out.push_str(&format!("f[{}]{share}", crossed.join(",")));
            }
        }
        for s in h["stopped"].as_array().into_iter().flatten() {
            out.push_str(&format!("|{}:{}", s["kind"], s["why"]));
        }
        out.push('(');
        for b in h["branches"].as_array().into_iter().flatten() {
            ray(b, out);
        }
        out.push_str(");");
    }
    let mut out = String::new();
    for s in tree["samples"].as_array().into_iter().flatten() {
        ray(&s["ray"], &mut out);
    }
    out
}

/// What a tree shows, for the choice of pixels: each object and part its rays hit (and leave),
/// each light's fate at a hit, each light's highlight (a specular factor of at least
/// [`HIGHLIGHT`] reaching the point), each kind of branch and stop, a camera ray's miss, and
/// the quarter of the image (of `size`) its pixel lies in.
#[must_use]
pub fn features(tree: &Value, size: (u32, u32)) -> BTreeSet<String> {
    fn ray(r: &Value, out: &mut BTreeSet<String>) {
        let kind = r["kind"].as_str().unwrap_or("?");
        let h = &r["hit"];
        if h.is_null() {
            out.insert(format!("a {kind} ray misses every object"));
            return;
        }
        let name = match h["name"].as_str() {
            Some(n) => format!("`{n}`"),
            None => format!("object {}", h["object"]),
        };
        let part = h["part"].as_str().unwrap_or("?");
        out.insert(format!("{name}, its {part}, hit"));
        if h["entering"] == false {
            out.insert(format!("{name} hit from inside"));
        }
        for l in h["lights"].as_array().into_iter().flatten() {
            let share = l["share"].as_f64().unwrap_or(1.0);
            let fate = if l["in_front"] == false {
                "behind the surface"
            } else if l["feeler"].is_null() {
                "lit without a feeler"
            } else if share == 1.0 {
                "lit"
            } else if share == 0.0 {
                "in shadow"
            } else {
                "in a translucent shadow"
            };
            out.insert(format!("light {}: {fate}", l["index"]));
            // ρs·max(r·v, 0)^f, the largest of its channels: a highlight that reaches the point
            let specular = l["specular"]
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(Value::as_f64)
                .fold(0.0, f64::max);
            if specular >= HIGHLIGHT && share > 0.0 {
                out.insert(format!("light {}: a highlight", l["index"]));
            }
        }
        for s in h["stopped"].as_array().into_iter().flatten() {
            let why = s["why"].as_str().unwrap_or("?").replace('_', " ");
            out.insert(format!(
                "a {} ray stopped: {why}",
                s["kind"].as_str().unwrap_or("?")
            ));
        }
        for b in h["branches"].as_array().into_iter().flatten() {
            out.insert(format!("a {} ray", b["kind"].as_str().unwrap_or("?")));
            ray(b, out);
        }
    }
    let mut out = BTreeSet::new();
    let x = tree["pixel"][0].as_u64().unwrap_or(0) as u32;
    let y = tree["pixel"][1].as_u64().unwrap_or(0) as u32;
    out.insert(format!(
        "the image's {} {} quarter",
        if y < size.1 / 2 { "top" } else { "bottom" },
        if x < size.0 / 2 { "left" } else { "right" }
    ));
    for s in tree["samples"].as_array().into_iter().flatten() {
        ray(&s["ray"], &mut out);
    }
    out
}

/// How steady a tree is: how many of the 9 trees of the 3 × 3 pixels around it (itself
/// included) have its shape, and how many of the 25 of the 5 × 5. A tree is *steady* when all
/// 9 do.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
struct Steadiness {
    near: usize,
    around: usize,
}

impl Steadiness {
    fn steady(self) -> bool {
        self.near == 9
    }
}

/// Each tree's [`Steadiness`].
fn steadiness(grid: &Grid) -> Vec<Steadiness> {
    let shapes = &grid.shapes;
    let (columns, rows) = (grid.columns as i64, grid.rows() as i64);
    let same = |i: usize, dc: i64, dr: i64| {
        let (c, r) = ((i as i64 % columns) + dc, (i as i64 / columns) + dr);
        (0..columns).contains(&c)
            && (0..rows).contains(&r)
            && shapes[(r * columns + c) as usize] == shapes[i]
    };
    let count = |i: usize, reach: i64| {
        (-reach..=reach)
            .flat_map(|dr| (-reach..=reach).map(move |dc| (dc, dr)))
            .filter(|&(dc, dr)| same(i, dc, dr))
            .count()
    };
    (0..shapes.len())
        .map(|i| Steadiness {
            near: count(i, 1),
            around: count(i, 2),
        })
        .collect()
}

/// The pixels kept for the scene's features: greedily, the steady tree that shows the most
/// features not shown yet (the steadiest first, then in row order), until every feature a
/// steady tree shows is shown. Returns each pick (tree index, the features it is kept for)
/// and the features only unsteady pixels show.
fn choose(grid: &Grid, steady: &[Steadiness]) -> (Vec<Pick>, Vec<String>) {
    let shown = &grid.shows;
    let mut wanted: BTreeSet<String> = BTreeSet::new();
    let mut everywhere: BTreeSet<String> = BTreeSet::new();
    for (i, f) in shown.iter().enumerate() {
        everywhere.extend(f.iter().cloned());
        if steady[i].steady() {
            wanted.extend(f.iter().cloned());
        }
    }
    let mut picks = Vec::new();
    while !wanted.is_empty() {
        let best = (0..shown.len())
            .filter(|&i| steady[i].steady())
            .max_by_key(|&i| {
                let new = shown[i].intersection(&wanted).count();
                (new, steady[i], std::cmp::Reverse(i))
            });
        let Some(i) = best else { break };
        let covers: Vec<String> = shown[i].intersection(&wanted).cloned().collect();
        if covers.is_empty() {
            break;
        }
        for f in &covers {
            wanted.remove(f);
        }
        picks.push((i, covers));
    }
    let unsteady: Vec<String> = everywhere
        .into_iter()
        .filter(|f| !picks.iter().any(|(_, c)| c.contains(f)))
        .collect();
    (picks, unsteady)
}

/// A trees file's text (`docs/src/inspect.md`), `pretty` for a file people read.
fn file_text(chapter: &Chapter, settings: &Value, pixels: &[Kept], pretty: bool) -> String {
    let doc = json!({
        "version": 1,
        "about": format!(
            "The reference's ray trees at {} pixels of {}, rendered as the book's figure {}.png; \
             written by `whitted trees`, compared by `{} --against` and `cargo learn`.",
            pixels.len(),
            chapter.scene(),
            chapter.binary,
            chapter.binary
        ),
        "settings": settings,
        "pixels": pixels.iter().map(|(tree, covers)| json!({
            "pixel": tree["pixel"],
            "covers": covers,
            "tree": tree,
        })).collect::<Vec<_>>(),
    });
    let text = if pretty {
        serde_json::to_string_pretty(&doc)
    } else {
        serde_json::to_string(&doc)
    };
    text.unwrap_or_default() + "\n"
}

/// The pixels' trees of a trees file, with what each is kept for.
fn read_file(path: &Path) -> Result<(Value, Vec<Kept>), ToolError> {
    let text = std::fs::read_to_string(path).map_err(|e| ToolError::io(path, e))?;
    let doc: Value = serde_json::from_str(&text)
        .map_err(|e| ToolError::Usage(format!("{}: not JSON: {e}", path.display())))?;
    let pixels = doc["pixels"]
        .as_array()
        .into_iter()
        .flatten()
        .map(|p| {
            let covers = p["covers"]
                .as_array()
                .into_iter()
                .flatten()
                .filter_map(|c| c.as_str().map(str::to_string))
                .collect();
            (p["tree"].clone(), covers)
        })
        .collect();
    Ok((doc["settings"].clone(), pixels))
}

/// The comparison `--against FILE --json` prints, one [`Against`] a pixel (with `extra`
/// arguments first, and `mutant` switched on).
fn against(
    exe: &Path,
    figure: &Figure,
    root: &Path,
    file: &Path,
    extra: &[String],
    mutant: Option<&str>,
) -> Result<(Option<String>, Vec<Against>), ToolError> {
    let mut args = figure.args.clone();
    args.extend(extra.iter().cloned());
    args.extend([
        "--against".to_string(),
        file.display().to_string(),
        "--json".to_string(),
    ]);
    Ok(read_output(&run(exe, &args, root, mutant)?))
}

/// The chapter binaries built next to this program.
fn reference_binary(chapter: &Chapter) -> Result<PathBuf, ToolError> {
    let exe = std::env::current_exe().map_err(|e| ToolError::io("whitted", e))?;
    let bin = exe.parent().unwrap_or(Path::new(".")).join(format!(
        "{}{}",
        chapter.binary,
        std::env::consts::EXE_SUFFIX
    ));
    if bin.is_file() {
        Ok(bin)
    } else {
        Err(ToolError::Usage(format!(
            "{} is not built: run `cargo build --bins` (or --release) first",
            bin.display()
        )))
    }
}

/// `whitted trees [--check]` on the project at `root` (see the module's documentation).
pub fn command(root: &Path, manifest: &Manifest, check: bool) -> Result<ExitCode, ToolError> {
    let figures = figures::read_figures(&root.join("docs/figures.toml"))?;
    if check {
        return check_all(root, &figures);
    }
    let scratch = tempfile::Builder::new()
        .prefix("whitted-trees-")
        .tempdir()
        .map_err(|e| ToolError::io(std::env::temp_dir(), e))?;
    // 1. each chapter's grid, and the pixels its features need
    let mut chosen: Vec<(Grid, Vec<Steadiness>, Vec<Pick>)> = Vec::new();
    for chapter in &syllabus::CHAPTERS {
        let figure = figure_of(&figures, chapter)?;
        let g = grid(&reference_binary(chapter)?, figure, root)?;
        let steady = steadiness(&g);
        let (picks, unsteady) = choose(&g, &steady);
        println!(
            "chapter {}: {} pixels show the {} features of its steady trees",
            chapter.number,
            picks.len(),
            picks.iter().map(|(_, c)| c.len()).sum::<usize>()
        );
        if !unsteady.is_empty() {
            println!("  only near edges, not kept: {}", unsteady.join("; "));
        }
        chosen.push((g, steady, picks));
    }
    // 2. the known mistakes, one build for all
    let mutants = mistakes::load(root)?;
    let copy = scratch.path().join("project");
    crate::files::copy_project(root, &copy)?;
    mistakes::switch(&copy, manifest, &mutants)?;
    let binaries: Vec<String> = syllabus::CHAPTERS
        .iter()
        .map(|c| c.binary.to_string())
        .collect();
    let target = root.join("target").join("mistakes");
    println!(
        "building the reference with the {} known mistakes behind a switch into {}",
        mutants.len(),
        target.display()
    );
    let built = Build {
        project: &copy,
        packages: &[layout::APP_PACKAGE],
        tests: &[],
        bins: &binaries,
        profile: None,
        features: &[],
        target_dir: Some(&target),
        debug_info: false,
        locked: true,
        stderr: Stderr::Inherit,
        wrapper: None,
    }
    .run()?;
    if !built.success {
        return Err(ToolError::Build(format!(
            "the copy with the mistakes does not build: {}",
            built.first_error()
        )));
    }
    let exe_of = |chapter: &Chapter| {
        built
            .executables
            .get(chapter.binary)
            .cloned()
            .ok_or_else(|| ToolError::Build(format!("cargo built no binary {}", chapter.binary)))
    };
    let chapter_of = |m: &Mutant| -> Result<&'static Chapter, ToolError> {
        let i = manifest.by_name(&m.exercise).ok_or_else(|| {
            ToolError::Usage(format!("mutant {}: no exercise {}", m.name, m.exercise))
        })?;
        syllabus::chapter(manifest.entries[i].chapter)
            .ok_or_else(|| ToolError::Usage(format!("mutant {}: no chapter", m.name)))
    };
    // the pixels kept, and one pixel of every 2 × 2, of a chapter, as a trees file
    let mut search_files: BTreeMap<u8, PathBuf> = BTreeMap::new();
    for m in &mutants {
        let chapter = chapter_of(m)?;
        let (g, steady, picks) = &mut chosen[usize::from(chapter.number) - 1];
        let file = match search_files.get(&chapter.number) {
            Some(f) => f.clone(),
            None => {
                let search: Vec<Kept> = (0..g.lines.len())
                    .filter(|&i| {
                        let (x, y) = g.pixel(i);
                        picks.iter().any(|(k, _)| *k == i) || x % 2 == 1 && y % 2 == 1
                    })
                    .map(|i| (g.tree(i), Vec::new()))
                    .collect();
                let f = scratch
                    .path()
                    .join(format!("{}-search.json", chapter.binary));
                crate::files::write_file(
                    &f,
                    file_text(chapter, &g.settings, &search, false).as_bytes(),
                )?;
                search_files.insert(chapter.number, f.clone());
                f
            }
        };
        let figure = figure_of(&figures, chapter)?;
        let (_, compared) = against(&exe_of(chapter)?, figure, root, &file, &[], Some(&m.name))?;
        let differ: BTreeSet<(u32, u32)> = compared
            .iter()
            .filter(|a| a.differs)
            .map(|a| a.pixel)
            .collect();
        let kept = picks.iter().any(|(i, _)| differ.contains(&g.pixel(*i)));
        // the steadiest pixel where the mistake shows
        let best = differ
            .iter()
            .map(|&p| g.index(p))
            .max_by_key(|&i| (steady[i], std::cmp::Reverse(i)));
        match (kept, best) {
            (true, _) => {}
            (false, Some(i)) => {
                let (x, y) = g.pixel(i);
                let s = steady[i];
                println!(
                    "mistake {}: its trees differ at none of chapter {}'s pixels; ({x}, {y}) is added{}",
                    m.name,
                    chapter.number,
                    if s.steady() {
                        String::new()
                    } else {
                        format!(
                            " (not steady: {} of the 9 trees around it, {} of the 25, have its shape; \
                             tests/trees.rs checks that an f32 build agrees there)",
                            s.near, s.around
                        )
                    }
                );
                picks.push((i, vec![format!("{MISTAKE_SHOWS} {}", m.exercise)]));
            }
            (false, None) => println!(
                "warning: mistake {}: no tree of chapter {}'s scene differs from the reference's",
                m.name, chapter.number
            ),
        }
    }
    // 3. the trees files
    for (chapter, (g, _, picks)) in syllabus::CHAPTERS.iter().zip(&chosen) {
        let pixels: Vec<Kept> = picks
            .iter()
            .map(|(i, covers)| (g.tree(*i), covers.clone()))
            .collect();
        let path = root.join(trees_file(chapter.number).unwrap_or_default());
        crate::files::write_file(
            &path,
            file_text(chapter, &g.settings, &pixels, true).as_bytes(),
        )?;
        println!("wrote {} ({} pixels)", rel(root, &path), pixels.len());
    }
    // 4. the mistakes' fingerprints
    let mut known = Vec::new();
    for m in &mutants {
        let chapter = chapter_of(m)?;
        let figure = figure_of(&figures, chapter)?;
        let file = root.join(trees_file(chapter.number).unwrap_or_default());
        let png = scratch.path().join(format!("{}.png", m.name));
        let extra = [
            "--compare".to_string(),
            chapter.figure(),
            "-o".to_string(),
            png.display().to_string(),
        ];
        let (compare, compared) = against(
            &exe_of(chapter)?,
            figure,
            root,
            &file,
            &extra,
            Some(&m.name),
        )?;
        let Some(fingerprint) = Fingerprint::of(&compared, compare.as_deref()) else {
            println!(
                "warning: mistake {} ({}): no tree of chapter {} differs: learn cannot tell it",
                m.name, m.exercise, chapter.number
            );
            continue;
        };
        let first = compared
            .iter()
            .find_map(|a| a.first.clone())
            .unwrap_or_default();
        let own = &manifest.entries[manifest.by_name(&m.exercise).unwrap_or(0)].function;
        println!(
            "mistake {} ({}): {}{}",
            m.name,
            m.exercise,
            first.text,
            if first.functions.contains(own) {
                String::new()
            } else {
                format!(" — warning: not computed by {own}")
            }
        );
        known.push(Mistake {
            name: m.name.clone(),
            exercise: m.exercise.clone(),
            chapter: chapter.number,
            looks_like: m.why.clone(),
            first: first.text,
            fingerprint,
        });
    }
    let doc = Mistakes {
        about: "The course's known mistakes, each made on the reference in one exercise, and how \
                its chapter's picture and ray trees then differ from the book's; written by \
                `whitted trees`, read by `cargo learn`."
            .into(),
        mistakes: known,
    };
    let path = root.join(MISTAKES);
    let text = serde_json::to_string_pretty(&doc)
        .map_err(|e| ToolError::Usage(format!("cannot write the mistakes: {e}")))?;
    crate::files::write_file(&path, (text + "\n").as_bytes())?;
    println!(
        "wrote {} ({} mistakes)",
        rel(root, &path),
        doc.mistakes.len()
    );
    Ok(ExitCode::SUCCESS)
}

/// `path` relative to `root`, for messages.
fn rel(root: &Path, path: &Path) -> String {
    path.strip_prefix(root)
        .unwrap_or(path)
        .display()
        .to_string()
}

/// `whitted trees --check`: each chapter's committed trees are still the reference's, and its
/// features' pixels still those a fresh choice makes. Status 1 when one differs.
fn check_all(root: &Path, figures: &[Figure]) -> Result<ExitCode, ToolError> {
    let mut differ = 0;
    let n = syllabus::CHAPTERS.len();
    for (k, chapter) in syllabus::CHAPTERS.iter().enumerate() {
        let started = std::time::Instant::now();
        let figure = figure_of(figures, chapter)?;
        let exe = reference_binary(chapter)?;
        let path = root.join(trees_file(chapter.number).unwrap_or_default());
        let name = rel(root, &path);
        if !path.is_file() {
            differ += 1;
            println!("[{}/{n}] {name}: missing: run `whitted trees`", k + 1);
            continue;
        }
        let (_, committed) = read_file(&path)?;
        let g = grid(&exe, figure, root)?;
        let steady = steadiness(&g);
        let (picks, _) = choose(&g, &steady);
        let mut problems: Vec<String> = Vec::new();
        let kept: Vec<Value> = committed
            .iter()
            .filter(|(_, covers)| !covers.iter().any(|c| c.starts_with(MISTAKE_SHOWS)))
            .map(|(t, _)| t["pixel"].clone())
            .collect();
        let fresh: Vec<Value> = picks
            .iter()
            .map(|(i, _)| g.tree(*i)["pixel"].clone())
            .collect();
        if kept != fresh {
            problems.push(format!(
                "the features' pixels are {} now, {} in the file",
                pixels_text(&fresh),
                pixels_text(&kept)
            ));
        }
        let (_, compared) = against(&exe, figure, root, &path, &[], None)?;
        if compared.len() != committed.len() {
            problems.push(format!(
                "{} of its {} pixels compared",
                compared.len(),
                committed.len()
            ));
        }
        problems.extend(
            compared
                .iter()
                .filter_map(|a| a.first.as_ref())
                .map(|p| p.text.clone()),
        );
        let ms = started.elapsed().as_millis();
        if problems.is_empty() {
            println!(
                "[{}/{n}] {name}: the same ({} pixels) ({ms} ms)",
                k + 1,
                committed.len()
            );
        } else {
            differ += 1;
            println!("[{}/{n}] {name}: DIFFERS ({ms} ms)", k + 1);
            for p in problems {
                println!("  {p}");
            }
        }
    }
    let unseen = mistakes_unseen(
        &mistakes::load(root)?,
        &whitted_learn::trees::load_mistakes(root),
    );
    for problem in &unseen {
        println!("{problem}");
    }
    if differ > 0 || !unseen.is_empty() {
        println!(
            "{differ} of {n} trees files differ from the reference, {} mistakes are not told: if the change is meant, run `whitted trees` and commit them (and chapters/mistakes.json)",
            unseen.len()
        );
        return Ok(ExitCode::from(1));
    }
    println!(
        "each of the {} hand-written mistakes moves a kept number or a pixel of its chapter, or says why its scene cannot show it",
        mistakes::load(root)?.len()
    );
    Ok(ExitCode::SUCCESS)
}

/// What is wrong with the known mistakes' fingerprints `known` (`chapters/mistakes.json`) for
/// the hand-written mutants `mutants`: each mutant must move some kept number or some pixel of
/// its chapter's picture (a fingerprint with a differing tree or pixel), unless it says why its
/// chapter's scene cannot show it (`unseen`), and then it must have none; every fingerprint
/// must be a mutant's. One line a problem; none when all is well.
#[must_use]
pub fn mistakes_unseen(mutants: &[Mutant], known: &[Mistake]) -> Vec<String> {
    let mut out = Vec::new();
    for m in mutants {
        let found = known.iter().find(|k| k.name == m.name);
        let moves =
            found.is_some_and(|k| !k.fingerprint.pixels.is_empty() || k.fingerprint.picture.0 > 0);
        match (&m.unseen, moves) {
            (None, false) => out.push(format!(
                "mistake {} ({}): no kept number and no pixel of its chapter moves",
                m.name, m.exercise
            )),
            (Some(why), true) => out.push(format!(
                "mistake {} ({}): its chapter shows it now, though `unseen` says \"{why}\"",
                m.name, m.exercise
            )),
            _ => {}
        }
    }
    for k in known {
        if !mutants.iter().any(|m| m.name == k.name) {
            out.push(format!(
                "mistake {} in chapters/mistakes.json is no hand-written mutant",
                k.name
            ));
        }
    }
    out
}

/// Pixels as `(x, y) (x, y) …`.
fn pixels_text(pixels: &[Value]) -> String {
    pixels
        .iter()
        .map(|p| format!("({}, {})", p[0], p[1]))
        .collect::<Vec<_>>()
        .join(" ")
}
