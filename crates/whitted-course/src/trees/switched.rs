//! The course's known mistakes in the trees: the reference built once with every hand-written
//! mutant behind its switch ([`crate::mistakes`]), each mutant's chapter traced `--against`
//! the reference's trees, so that every mistake changes a tree kept ([`Switched::add_pixels`]),
//! and each mistake's fingerprint written for `cargo learn` ([`Switched::fingerprints`]).
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};

use super::choose::Chosen;
use super::file::{MISTAKE_SHOWS, rel, tree_file, write_file};
use super::run::{against, figure_of};
use crate::ToolError;
use crate::cargo::Built;
use crate::figures::Figure;
use crate::manifest::Manifest;
use crate::mistakes::{self, Mutant};
use crate::syllabus::{self, Chapter};
use whitted_learn::trees::{Fingerprint, MISTAKES, Mistake, Mistakes, trees_file};

/// The reference's chapter binaries with every known mistake behind its switch, and what
/// tracing them needs.
pub(super) struct Switched<'a> {
    /// The project.
    root: &'a Path,
    /// A temporary directory for the files traced against and the pictures.
    scratch: &'a Path,
    /// The book's figures, whose settings each chapter is traced with.
    figures: &'a [Figure],
    /// The manifest, which names each mutant's exercise and chapter.
    manifest: &'a Manifest,
    /// The hand-written mutants.
    mutants: &'a [Mutant],
    /// The build of the copy with the switches.
    built: Built,
    /// Each mistake's failing tests of its own exercise, with their values.
    tests: BTreeMap<String, BTreeMap<String, String>>,
}

impl<'a> Switched<'a> {
    /// Copies the project into `scratch` with every one of `mutants` behind its switch and
    /// builds the chapter binaries of the copy, once for all of them, into
    /// `target/mistakes`.
    pub(super) fn build(
        root: &'a Path,
        scratch: &'a Path,
        figures: &'a [Figure],
        manifest: &'a Manifest,
        mutants: &'a [Mutant],
    ) -> Result<Self, ToolError> {
        let copy = scratch.join("project");
        crate::files::copy_project(root, &copy)?;
        mistakes::switch(&copy, manifest, mutants)?;
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
        let built = super::values::build_copy(
            &copy,
            &target,
            &[],
            &binaries,
            "the copy with the mistakes",
        )?;
        let tests = super::values::record(root, &copy, &target, manifest, mutants)?;
        Ok(Self {
            root,
            scratch,
            figures,
            manifest,
            mutants,
            built,
            tests,
        })
    }

    /// The chapter binary of the copy with the switches.
    fn exe_of(&self, chapter: &Chapter) -> Result<PathBuf, ToolError> {
        self.built
            .executables
            .get(chapter.binary)
            .cloned()
            .ok_or_else(|| ToolError::Build(format!("cargo built no binary {}", chapter.binary)))
    }

    /// The chapter of the exercise `m` changes.
    fn chapter_of(&self, m: &Mutant) -> Result<&'static Chapter, ToolError> {
        let i = self.manifest.by_name(&m.exercise).ok_or_else(|| {
            ToolError::Usage(format!("mutant {}: no exercise {}", m.name, m.exercise))
        })?;
        syllabus::chapter(self.manifest.entries[i].chapter)
            .ok_or_else(|| ToolError::Usage(format!("mutant {}: no chapter", m.name)))
    }

    /// For each mutant whose trees differ at none of its chapter's pixels kept, keeps the
    /// steadiest pixel where they do differ (`chosen` holds the chapters in order). Each
    /// chapter is searched at its pixels kept and at one pixel of every 2 × 2.
    pub(super) fn add_pixels(&self, chosen: &mut [Chosen]) -> Result<(), ToolError> {
        let mut search_files: BTreeMap<u8, PathBuf> = BTreeMap::new();
        for m in self.mutants {
            let chapter = self.chapter_of(m)?;
            let c = &mut chosen[usize::from(chapter.number) - 1];
            let file = match search_files.get(&chapter.number) {
                Some(f) => f.clone(),
                None => {
                    let f = self.search_file(chapter, c)?;
                    search_files.insert(chapter.number, f.clone());
                    f
                }
            };
            let figure = figure_of(self.figures, chapter)?;
            let (_, compared) = against(
                &self.exe_of(chapter)?,
                figure,
                self.root,
                &file,
                None,
                Some(&m.name),
            )?;
            let differ: BTreeSet<(u32, u32)> = compared
                .iter()
                .filter(|a| a.differs)
                .map(|a| a.pixel)
                .collect();
            let g = &c.grid;
            let kept = c.picks.iter().any(|(i, _)| differ.contains(&g.pixel(*i)));
            // the steadiest pixel where the mistake shows
            let best = differ
                .iter()
                .map(|&p| g.index(p))
                .max_by_key(|&i| (c.steady[i], std::cmp::Reverse(i)));
            match (kept, best) {
                (true, _) => {}
                (false, Some(i)) => {
                    let (x, y) = g.pixel(i);
                    let s = c.steady[i];
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
                    c.picks
                        .push((i, vec![format!("{MISTAKE_SHOWS} {}", m.exercise)]));
                }
                (false, None) => println!(
                    "warning: mistake {}: no tree of chapter {}'s scene differs from the reference's",
                    m.name, chapter.number
                ),
            }
        }
        Ok(())
    }

    /// A trees file of the pixels kept of `chapter`, and one pixel of every 2 × 2, for the
    /// search of [`Switched::add_pixels`].
    fn search_file(&self, chapter: &Chapter, c: &Chosen) -> Result<PathBuf, ToolError> {
        let g = &c.grid;
        let search = (0..g.trees.len())
            .filter(|&i| {
                let (x, y) = g.pixel(i);
                c.picks.iter().any(|(k, _)| *k == i) || x % 2 == 1 && y % 2 == 1
            })
            .map(|i| (g.trees[i].clone(), Vec::new()))
            .collect();
        let f = self.scratch.join(format!("{}-search.json", chapter.binary));
        write_file(&f, &tree_file(chapter, &g.settings, search), false)?;
        Ok(f)
    }

    /// Each mistake's fingerprint, traced `--against` its chapter's trees file as written and
    /// with `--compare` beside the book's figure, written into `chapters/mistakes.json`.
    pub(super) fn fingerprints(&self) -> Result<(), ToolError> {
        let (root, manifest) = (self.root, self.manifest);
        let mut known = Vec::new();
        for m in self.mutants {
            let chapter = self.chapter_of(m)?;
            let figure = figure_of(self.figures, chapter)?;
            let file = root.join(trees_file(chapter.number).unwrap_or_default());
            let png = self.scratch.join(format!("{}.png", m.name));
            let book = PathBuf::from(chapter.figure());
            let (compare, compared) = against(
                &self.exe_of(chapter)?,
                figure,
                root,
                &file,
                Some((&book, &png)),
                Some(&m.name),
            )?;
            let tests = self.tests.get(&m.name).cloned().unwrap_or_default();
            if tests.is_empty() {
                println!(
                    "warning: mistake {} ({}): no test of its exercise fails: learn cannot tell it at the save",
                    m.name, m.exercise
                );
            }
            let fingerprint = Fingerprint::of(&compared, compare.as_deref());
            let first = compared
                .iter()
                .find_map(|a| a.first.clone())
                .unwrap_or_default();
            let own = &manifest.entries[manifest.by_name(&m.exercise).unwrap_or(0)].function;
            match &fingerprint {
                None => println!(
                    "mistake {} ({}): no tree of chapter {} differs; its tests alone tell it",
                    m.name, m.exercise, chapter.number
                ),
                Some(_) => println!(
                    "mistake {} ({}): {}{}",
                    m.name,
                    m.exercise,
                    first.text,
                    if first.functions.contains(own) {
                        String::new()
                    } else {
                        format!(" — warning: not computed by {own}")
                    }
                ),
            }
            known.push(Mistake {
                name: m.name.clone(),
                exercise: m.exercise.clone(),
                chapter: chapter.number,
                looks_like: m.why.clone(),
                first: first.text,
                fingerprint,
                tests,
            });
        }
        let doc = Mistakes {
            about:
                "The course's known mistakes, each made on the reference in one exercise: how its \
                    chapter's picture and ray trees then differ from the book's, and what its \
                    exercise's failing tests print; written by `whitted trees`, read by `cargo learn`."
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
        Ok(())
    }
}
