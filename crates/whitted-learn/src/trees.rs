//! The first wrong number, and known mistakes: what `cargo learn` adds to a chapter's picture.
//!
//! Each chapter of a handout holds the reference's ray trees at a few pixels of its scene,
//! `chapters/chNN_name/trees.json` ([`trees_file`], written by `whitted trees`). When `learn`
//! draws a chapter, its chapter binary traces the same pixels with the student's code and
//! compares the trees (`--against … --json`, one JSON line a pixel: [`Against`]). Of the first
//! pixel whose tree differs, [`first_wrong`] says the node and the quantity, the value
//! computed and the reference's, and maps the functions that computed it to the exercise the
//! student should look at — the first of them whose tests fail, by the manifest — with the
//! notes' formula:
//!
//! ```text
//!   first wrong number: pixel (98, 75), camera ray → hit `cone`: t: 4.0213 (the reference: 3.8702)
//!     computed in exercise 2.17 (cone_coefficients), the notes: a = …, b = …, c = …
//! ```
//!
//! `chapters/mistakes.json` ([`MISTAKES`]) holds the [`Fingerprint`] of each of the course's
//! known mistakes (the hand-written mutants, applied to the reference one at a time by
//! `whitted trees`): the first quantity that differs, the pixels whose trees differ, and how
//! many pixels of the picture do. When the student's difference [resembles](Fingerprint::resembles)
//! a known mistake of the exercise they are on, and only once they have asked for that
//! exercise's first hint, [`known_mistake`] names it in words ("this looks like normals
//! transformed by M instead of (M⁻¹)ᵀ"); the file holds those words and numbers, never code.
//!
//! Course book: [The student's guide](../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};

use serde::{Deserialize, Serialize};

use crate::learn::State;
use crate::manifest::Manifest;

/// The known mistakes' fingerprints, relative to the project's root.
pub const MISTAKES: &str = "chapters/mistakes.json";

/// The reference's ray trees of chapter `chapter`'s scene: `chapters/chNN_name/trees.json`
/// (relative to the project's root).
#[must_use]
pub fn trees_file(chapter: u8) -> Option<PathBuf> {
    let about = whitted_syllabus::chapter(chapter)?;
    Some(Path::new("chapters").join(about.binary).join("trees.json"))
}

/// One pixel of a trees file as the chapter binary compared it (`--against … --json`), and
/// where its tree first parts from the reference's.
pub use whitted_syllabus::tree::{Against, Parting};

/// The chapter binary's output with `--compare` and `--against … --json`: its `compare:` line
/// and the trees' lines, in order.
#[must_use]
pub fn read_output(stdout: &str) -> (Option<String>, Vec<Against>) {
    let compare = stdout
        .lines()
        .find(|l| l.starts_with("compare: "))
        .map(str::to_string);
    let against = stdout
        .lines()
        .filter(|l| l.starts_with('{'))
        .filter_map(|l| serde_json::from_str(l).ok())
        .collect();
    (compare, against)
}

/// How many pixels of the picture differ, and of how many, from a `compare:` line
/// ("compare: 312 of 28800 pixels differ …"; "compare: the same as the reference …" is 0 of an
/// unknown number, given as 0).
#[must_use]
pub fn picture_counts(compare: &str) -> Option<(usize, usize)> {
    let rest = compare.strip_prefix("compare: ")?;
    if rest.starts_with("the same") {
        return Some((0, 0));
    }
    let mut words = rest.split_whitespace();
    let differing = words.next()?.parse().ok()?;
    (words.next()? == "of").then_some(())?;
    let of = words.next()?.parse().ok()?;
    Some((differing, of))
}

/// The exercises (manifest indices) whose functions computed a quantity, in manifest order.
fn exercises_of(manifest: &Manifest, functions: &[String]) -> Vec<usize> {
    (0..manifest.entries.len())
        .filter(|&i| functions.contains(&manifest.entries[i].function))
        .collect()
}

/// The first pixel whose tree differs from the reference's, and the exercise to look at: the
/// first of those whose functions computed the quantity whose own tests do not pass in
/// `states` (`None` when they all pass, or when no manifest function computed it).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct FirstWrong<'a> {
    /// Where the first differing pixel's tree parts from the reference's.
    pub at: &'a Parting,
    /// The exercise (manifest index) to look at, when one of those that computed the
    /// quantity fails its tests.
    pub exercise: Option<usize>,
    /// Every exercise whose function computed the quantity, in manifest order.
    pub computed: Vec<usize>,
    /// How many of the pixels compared have a tree that differs.
    pub differing: usize,
}

/// The first wrong number of `against`, attributed by the manifest ([`FirstWrong`]). `None`
/// when no tree differs, and when the picture is the book's (`picture_differs` false) and
/// every exercise that computed the quantity passes its tests: a difference that changes no
/// pixel and breaks no test is the last bits of another correct way to compute it.
#[must_use]
pub fn attribute<'a>(
    manifest: &Manifest,
    states: &[State],
    against: &'a [Against],
    picture_differs: bool,
) -> Option<FirstWrong<'a>> {
    let at = against.iter().find_map(|a| a.first.as_ref())?;
    let computed = exercises_of(manifest, &at.functions);
    let exercise = computed
        .iter()
        .copied()
        .find(|&i| states.get(i).is_some_and(|s| *s != State::Done));
    if exercise.is_none() && !picture_differs {
        return None;
    }
    Some(FirstWrong {
        at,
        exercise,
        computed,
        differing: against.iter().filter(|a| a.differs).count(),
    })
}

impl FirstWrong<'_> {
    /// The lines learn and the grader print: where, which quantity, both values, and the
    /// exercise to look at with the notes' formula (or the exercises whose tests pass, when
    /// none fails).
    #[must_use]
    pub fn lines(&self, manifest: &Manifest, total: usize) -> String {
        let mut out = format!("  first wrong number: {}\n", self.at.text);
        match (self.exercise, self.computed.is_empty()) {
            (Some(i), _) => {
                let e = &manifest.entries[i];
                out += &format!(
                    "    computed in exercise {} ({}), the notes: {}\n",
                    e.exercise.id, e.exercise.name, e.formula
                );
            }
            (None, false) => {
                let ids: Vec<String> = self
                    .computed
                    .iter()
                    .map(|&i| {
                        let x = &manifest.entries[i].exercise;
                        format!("{} ({})", x.id, x.name)
                    })
                    .collect();
                out += &format!(
                    "    computed by exercises whose tests pass: {}\n",
                    ids.join(", ")
                );
            }
            (None, true) => {}
        }
        if self.differing > 1 {
            out += &format!(
                "    (the ray trees differ at {} of the {total} pixels compared)\n",
                self.differing
            );
        }
        out
    }
}

/// The lines on the first pixel whose tree differs from the reference's ([`attribute`], then
/// [`FirstWrong::lines`]).
#[must_use]
pub fn first_wrong(
    manifest: &Manifest,
    states: &[State],
    against: &[Against],
    picture_differs: bool,
) -> Option<String> {
    attribute(manifest, states, against, picture_differs).map(|f| f.lines(manifest, against.len()))
}

/// What a difference from the reference looks like, coarsely: enough to tell one known mistake
/// from another, and from other mistakes in the same exercise.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Fingerprint {
    /// The quantity that differs first (its key in the tree), at the first pixel that differs.
    pub quantity: String,
    /// The kinds of the nodes on the path to it.
    pub nodes: Vec<String>,
    /// The pixels of the trees file whose trees differ.
    pub pixels: Vec<(u32, u32)>,
    /// The picture's differing pixels, and all its pixels (0 of 0 when none differs).
    pub picture: (usize, usize),
}

impl Fingerprint {
    /// The fingerprint of a comparison: `None` when no tree differs.
    #[must_use]
    pub fn of(against: &[Against], compare: Option<&str>) -> Option<Self> {
        let first = against.iter().find_map(|a| a.first.as_ref())?;
        Some(Self {
            quantity: first.quantity.clone(),
            nodes: first.nodes.clone(),
            pixels: against
                .iter()
                .filter(|a| a.differs)
                .map(|a| a.pixel)
                .collect(),
            picture: compare.and_then(picture_counts).unwrap_or((0, 0)),
        })
    }

    /// Whether a difference with this fingerprint looks like one with `known`'s: the same
    /// quantity differs first, on the same kind of node; the pixels whose trees differ are
    /// mostly the same (they share at least half of those of either); and the picture differs
    /// in none of its pixels for both, or for both in counts within a factor of two.
    #[must_use]
    pub fn resembles(&self, known: &Fingerprint) -> bool {
        let shared = self
            .pixels
            .iter()
            .filter(|p| known.pixels.contains(p))
            .count();
        let union = self.pixels.len() + known.pixels.len() - shared;
        let (a, b) = (self.picture.0, known.picture.0);
        let picture = match (a, b) {
            (0, 0) => true,
            (0, _) | (_, 0) => false,
            _ => a.max(b) <= 2 * a.min(b),
        };
        self.quantity == known.quantity
            && self.nodes == known.nodes
            && 2 * shared >= union
            && picture
    }
}

/// A known mistake: which exercise it is made in, what it is in words, and its fingerprint.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Mistake {
    /// A short name for it (the mutant's).
    pub name: String,
    /// The exercise it is made in (its name).
    pub exercise: String,
    /// The chapter whose picture shows it.
    pub chapter: u8,
    /// What the mistake is, in words: "normals transformed by M instead of (M⁻¹)ᵀ".
    pub looks_like: String,
    /// Its first wrong number, as `learn` shows it.
    pub first: String,
    /// Its fingerprint in the trees; `None` for a mistake its chapter's scene cannot show,
    /// which its tests alone tell.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fingerprint: Option<Fingerprint>,
    /// What its exercise's own tests print with it: each failing test by name (without its
    /// target) with its message's values ([`crate::known`]); empty when none fails.
    #[serde(default, skip_serializing_if = "BTreeMap::is_empty")]
    pub tests: BTreeMap<String, String>,
}

/// The file of known mistakes ([`MISTAKES`]).
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Mistakes {
    /// What the file is.
    pub about: String,
    /// The mistakes, in the order of the course's list.
    pub mistakes: Vec<Mistake>,
}

/// The known mistakes of the project at `root` (none when the file is missing or unreadable).
#[must_use]
pub fn load_mistakes(root: &Path) -> Vec<Mistake> {
    std::fs::read_to_string(root.join(MISTAKES))
        .ok()
        .and_then(|t| serde_json::from_str::<Mistakes>(&t).ok())
        .map(|m| m.mistakes)
        .unwrap_or_default()
}

/// The line naming the known mistake of exercise `exercise` (a name) that the difference
/// `fingerprint` resembles, once the student has seen `hints` ≥ 1 of its hints; `None`
/// otherwise.
#[must_use]
pub fn known_mistake(
    mistakes: &[Mistake],
    exercise: &str,
    hints: usize,
    fingerprint: &Fingerprint,
) -> Option<String> {
    if hints == 0 {
        return None;
    }
    let m = mistakes.iter().find(|m| {
        m.exercise == exercise
            && m.fingerprint
                .as_ref()
                .is_some_and(|known| fingerprint.resembles(known))
    })?;
    Some(format!(
        "  a known mistake? this looks like {}\n",
        m.looks_like
    ))
}

/// What the trees add to a chapter's picture in the project at `root`: the first wrong number
/// ([`first_wrong`]), and the known mistake of the next exercise it looks like, if the
/// student has seen that exercise's first hint ([`known_mistake`]). Empty when every tree is
/// the reference's.
#[must_use]
pub fn feedback(
    root: &Path,
    manifest: &Manifest,
    states: &[State],
    against: &[Against],
    compare: Option<&str>,
) -> String {
    let picture_differs = compare
        .and_then(picture_counts)
        .is_some_and(|(differing, _)| differing > 0);
    let Some(mut out) = first_wrong(manifest, states, against, picture_differs) else {
        return String::new();
    };
    let next = states.iter().position(|s| *s != State::Done);
    if let (Some(next), Some(fingerprint)) = (next, Fingerprint::of(against, compare)) {
        let name = &manifest.entries[next].exercise.name;
        let hints = crate::learn::hints_shown(root)
            .get(name)
            .copied()
            .unwrap_or(0);
        if let Some(line) = known_mistake(&load_mistakes(root), name, hints, &fingerprint) {
            out += &line;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn against(pixel: (u32, u32), quantity: &str) -> Against {
        Against {
            pixel,
            differs: !quantity.is_empty(),
            first: (!quantity.is_empty()).then(|| Parting {
                nodes: vec!["camera ray".into(), "hit".into()],
                quantity: quantity.into(),
                ..Parting::default()
            }),
        }
    }

    fn normals_by_m() -> Mistake {
        Mistake {
            name: "normals-by-m".into(),
            exercise: "normal_to_world".into(),
            chapter: 2,
            looks_like: "normals transformed by M instead of (M⁻¹)ᵀ".into(),
            first: String::new(),
            fingerprint: Some(Fingerprint {
                quantity: "normal".into(),
                nodes: vec!["camera ray".into(), "hit".into()],
                pixels: vec![(10, 10), (20, 20)],
                picture: (0, 0),
            }),
            tests: BTreeMap::new(),
        }
    }

    /// Every exercise of the manifest, in a week's handout too (whose list is left out).
    fn manifest() -> Manifest {
        crate::week::every_exercise()
    }

    /// The first wrong number names the first exercise that computed it and fails, with the
    /// notes' formula; when all of them pass, it names them all, and says nothing unless the
    /// picture differs.
    #[test]
    fn the_first_wrong_number_names_the_exercise_that_computed_it_and_fails() {
        let m = manifest();
        let i = m.by_name("cone_coefficients").unwrap();
        let mut states = vec![State::Done; m.entries.len()];
        states[i] = State::Failing(vec!["x".into()]);
        let text = "pixel (128, 67), camera ray → hit `cone`: t: 9.4089 (the reference: 9.4929)";
        let mut t = against((128, 67), "t");
        t.first = t.first.map(|p| Parting {
            text: text.into(),
            functions: vec![
                "shapes::cone::coefficients".into(),
                "shapes::cone::intersect".into(),
                "ray::Ray::transformed".into(),
            ],
            ..p
        });
        let same = [t.clone(), against((3, 3), "")];
        let said = first_wrong(&m, &states, &same, false).unwrap();
        let x = &m.entries[i];
        assert!(
            said.contains(&format!("first wrong number: {text}")),
            "{said}"
        );
        assert!(
            said.contains(&format!(
                "computed in exercise {} (cone_coefficients), the notes: {}",
                x.exercise.id, x.formula
            )),
            "{said}"
        );
        assert!(
            !said.contains("pixels compared"),
            "one pixel differs: {said}"
        );
        // every exercise that computed it passes: only a picture that differs makes it worth saying
        let done = vec![State::Done; m.entries.len()];
        assert_eq!(first_wrong(&m, &done, &same, false), None);
        let said = first_wrong(&m, &done, &same, true).unwrap();
        assert!(
            said.contains("computed by exercises whose tests pass: "),
            "{said}"
        );
        assert!(
            said.contains(&format!("{} (cone_coefficients)", x.exercise.id)),
            "{said}"
        );
        // no tree differs
        assert_eq!(first_wrong(&m, &states, &[against((3, 3), "")], true), None);
    }

    #[test]
    fn the_compare_line_gives_its_counts() {
        let line = "compare: 312 of 28800 pixels differ by more than 2/255 (1.08%), by up to 87/255; the first at (17, 40)";
        assert_eq!(picture_counts(line), Some((312, 28800)));
        let same = "compare: the same as the reference (no pixel differs by more than 2/255)";
        assert_eq!(picture_counts(same), Some((0, 0)));
        assert_eq!(picture_counts("wrote x.png"), None);
    }

    #[test]
    fn a_known_mistake_is_named_only_after_the_first_hint() {
        let mine = Fingerprint::of(
            &[
                against((10, 10), "normal"),
                against((20, 20), "normal"),
                against((30, 30), ""),
            ],
            Some("compare: the same as the reference (no pixel differs by more than 2/255)"),
        )
        .unwrap();
        let known = [normals_by_m()];
        assert_eq!(known_mistake(&known, "normal_to_world", 0, &mine), None);
        let said = known_mistake(&known, "normal_to_world", 1, &mine).unwrap();
        assert!(
            said.contains("normals transformed by M instead of (M⁻¹)ᵀ"),
            "{said}"
        );
        // another exercise's mistake is not this one's
        assert_eq!(known_mistake(&known, "ray_in_object_space", 2, &mine), None);
    }

    #[test]
    fn another_mistake_in_the_same_exercise_is_not_taken_for_the_known_one() {
        let known = normals_by_m().fingerprint.unwrap();
        // other pixels differ: normals wrong on every object, not only the ellipsoid
        let everywhere = Fingerprint {
            pixels: vec![(10, 10), (20, 20), (30, 30), (40, 40), (50, 50)],
            ..known.clone()
        };
        assert!(!everywhere.resembles(&known));
        // another quantity differs first
        let t = Fingerprint {
            quantity: "t".into(),
            ..known.clone()
        };
        assert!(!t.resembles(&known));
        // the picture differs where the known mistake leaves it alone
        let seen = Fingerprint {
            picture: (500, 38400),
            ..known.clone()
        };
        assert!(!seen.resembles(&known));
        assert!(known.resembles(&known));
    }
}
