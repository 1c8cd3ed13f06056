//! A class's gradebook, `class.csv` in `whitted grade --class`'s `--out`: one row a
//! submission, a row of the points possible under the header, and a regrade that keeps what
//! it does not grade.
//!
//! ```text
//! student,id,email,total,max,chapter 1,…,ex 1.1,…,note
//! Points Possible,,,119,119,13,…,3,…,
//! ada,s001,ada@uni.example,118,119,13,…,3,…,
//! bob,s002,bob@uni.example,,119,,…,,…,"not graded: … is not a copy of the handout"
//! ```
//!
//! - The `id` and `email` columns come from a roster (`--roster FILE`: lines
//!   `folder,id,email`, the folder being the submission's directory name; a first line that
//!   starts with `folder` is a header); empty without one.
//! - A submission that could not be graded has empty cells, not zeros (an LMS imports a 0 as
//!   a grade), and the reason in `note`.
//! - A regrade into an `--out` that holds a gradebook updates the rows of the submissions it
//!   graded and keeps the others, in their order; a gradebook of other columns (other
//!   chapters) is refused unless `--new-gradebook` asks to write it anew.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::path::Path;

use crate::ToolError;
use crate::grade::Grade;
use crate::manifest::Manifest;

/// The gradebook's file name in `--out`.
pub const FILE: &str = "class.csv";

/// The first cell of the row of the points possible (the words Canvas's gradebook uses).
pub const POSSIBLE: &str = "Points Possible";

/// A roster: each submission's folder name → (student id, e-mail).
pub type Roster = BTreeMap<String, (String, String)>;

/// A CSV cell: quoted when it holds a comma, a quote or a line break.
#[must_use]
pub fn cell(text: &str) -> String {
    if text.contains([',', '"', '\n', '\r']) {
        format!("\"{}\"", text.replace('"', "\"\""))
    } else {
        text.to_string()
    }
}

/// The first cell of a CSV line, unquoted.
fn first_cell(line: &str) -> String {
    match line.strip_prefix('"') {
        Some(rest) => {
            let mut out = String::new();
            let mut chars = rest.chars().peekable();
            while let Some(c) = chars.next() {
                match (c, chars.peek()) {
                    ('"', Some('"')) => {
                        out.push('"');
                        chars.next();
                    }
                    ('"', _) => break,
                    (c, _) => out.push(c),
                }
            }
            out
        }
        None => line.split(',').next().unwrap_or("").to_string(),
    }
}

/// The header of the gradebook of `chapters`.
#[must_use]
pub fn header(manifest: &Manifest, chapters: &[u8]) -> String {
    let mut cols = vec!["student".to_string(), "id".into(), "email".into()];
    cols.extend(crate::report::score_columns(manifest, chapters));
    cols.push("note".into());
    cols.join(",")
}

/// The row of the points possible, in the columns of [`header`].
#[must_use]
pub fn possible(manifest: &Manifest, chapters: &[u8]) -> String {
    let of = |c: u8| -> u32 {
        manifest
            .entries
            .iter()
            .filter(|e| e.chapter == c)
            .map(|e| e.exercise.points)
            .sum()
    };
    let total: u32 = chapters.iter().map(|&c| of(c)).sum();
    let mut cols = vec![POSSIBLE.to_string(), String::new(), String::new()];
    cols.extend([total.to_string(), total.to_string()]);
    cols.extend(chapters.iter().map(|&c| of(c).to_string()));
    cols.extend(
        manifest
            .entries
            .iter()
            .filter(|e| chapters.contains(&e.chapter))
            .map(|e| e.exercise.points.to_string()),
    );
    cols.push(String::new());
    cols.join(",")
}

/// The first cells of a row: the submission's folder, its id and e-mail by the roster.
fn who(student: &str, roster: &Roster) -> Vec<String> {
    let (id, email) = roster.get(student).cloned().unwrap_or_default();
    vec![cell(student), cell(&id), cell(&email)]
}

/// The row of the graded submission `student` (its folder's name).
#[must_use]
pub fn graded(student: &str, grade: &Grade, manifest: &Manifest, roster: &Roster) -> String {
    let mut cols = who(student, roster);
    cols.extend(crate::report::score_cells(grade, manifest));
    cols.push(String::new());
    cols.join(",")
}

/// The row of a submission that could not be graded, and why: empty cells, not zeros, but
/// the maximum.
#[must_use]
pub fn ungraded(
    student: &str,
    why: &str,
    manifest: &Manifest,
    chapters: &[u8],
    roster: &Roster,
) -> String {
    let max: u32 = manifest
        .entries
        .iter()
        .filter(|e| chapters.contains(&e.chapter))
        .map(|e| e.exercise.points)
        .sum();
    let exercises = manifest
        .entries
        .iter()
        .filter(|e| chapters.contains(&e.chapter))
        .count();
    let mut cols = who(student, roster);
    cols.extend([String::new(), max.to_string()]);
    cols.extend(std::iter::repeat_n(
        String::new(),
        chapters.len() + exercises,
    ));
    cols.push(cell(&format!("not graded: {why}")));
    cols.join(",")
}

/// The gradebook `header` with the rows `fresh` (by student), over what `existing` (the
/// text of the gradebook already in `--out`, if any) holds: its rows of other students are
/// kept in their order, those of `fresh` replace theirs or follow. An `existing` of another
/// header is an error, unless `anew`.
pub fn merged(
    existing: Option<&str>,
    header: &str,
    possible: &str,
    fresh: &[(String, String)],
    anew: bool,
) -> Result<String, String> {
    let mut rows: Vec<(String, String)> = Vec::new();
    if let Some(text) = existing.filter(|_| !anew) {
        let mut lines = text.lines();
        let old = lines.next().unwrap_or("");
        if old != header {
            return Err(format!(
                "it holds other columns (another --chapter?): grade into another --out, or pass \
                 --new-gradebook to write it anew (its header: {old})"
            ));
        }
        for line in lines.filter(|l| !l.trim().is_empty()) {
            let student = first_cell(line);
            if student != POSSIBLE {
                rows.push((student, line.to_string()));
            }
        }
    }
    for (student, line) in fresh {
        match rows.iter_mut().find(|(s, _)| s == student) {
            Some(row) => row.1.clone_from(line),
            None => rows.push((student.clone(), line.clone())),
        }
    }
    let mut out = format!("{header}\n{possible}\n");
    for (_, line) in rows {
        out += &line;
        out.push('\n');
    }
    Ok(out)
}

/// Reads the roster at `path`: lines `folder,id,email` (a first line starting with
/// `folder` is a header, blank lines are skipped); a line of another shape is an error at its
/// line.
pub fn read_roster(path: &Path) -> Result<Roster, ToolError> {
    let text = std::fs::read_to_string(path).map_err(|e| ToolError::io(path, e))?;
    let mut out = Roster::new();
    for (n, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.is_empty() || (n == 0 && line.to_ascii_lowercase().starts_with("folder")) {
            continue;
        }
        let cells: Vec<&str> = line.split(',').map(str::trim).collect();
        match cells.as_slice() {
            [folder, id, email] if !folder.is_empty() => {
                out.insert(
                    (*folder).to_string(),
                    ((*id).to_string(), (*email).to_string()),
                );
            }
            _ => {
                return Err(ToolError::Usage(format!(
                    "{}:{}:1: expected folder,id,email (three cells, the folder not empty), found `{line}`",
                    path.display(),
                    n + 1
                )));
            }
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_regrade_keeps_the_rows_it_does_not_grade() {
        let header = "student,id,email,total,note";
        let possible = "Points Possible,,,10,";
        let first = merged(
            None,
            header,
            possible,
            &[
                ("ada".into(), "ada,,,9,".into()),
                ("b,c".into(), "\"b,c\",,,,not graded".into()),
                ("eve".into(), "eve,,,3,".into()),
            ],
            false,
        )
        .unwrap();
        // the key of a quoted name is the name
        let fresh = [("b,c".to_string(), "\"b,c\",,,7,".to_string())];
        let again = merged(Some(&first), header, possible, &fresh, false).unwrap();
        assert_eq!(
            again,
            "student,id,email,total,note\nPoints Possible,,,10,\nada,,,9,\n\"b,c\",,,7,\neve,,,3,\n"
        );
        let other = merged(Some(&first), "student,total", possible, &fresh, false).unwrap_err();
        assert!(other.contains("--new-gradebook"), "{other}");
        let anew = merged(Some(&first), "student,total", "P,10", &fresh, true).unwrap();
        assert_eq!(anew, "student,total\nP,10\n\"b,c\",,,7,\n");
    }

    #[test]
    fn an_ungraded_row_has_empty_cells_and_its_reason() {
        let m = crate::manifest::load(
            &Path::new(env!("CARGO_MANIFEST_DIR")).join("../../chapters/formulas.toml"),
        )
        .unwrap();
        let roster = Roster::from([("bob".to_string(), ("s2".to_string(), "b@x".to_string()))]);
        let head = header(&m, &[1]);
        let max = possible(&m, &[1]);
        let row = ungraded(
            "bob",
            "no crates/whitted/src, \"really\"",
            &m,
            &[1],
            &roster,
        );
        let cells = |line: &str| line.split(',').count();
        // the reason holds one comma, inside its quotes
        assert_eq!(
            (cells(&head), cells(&max)),
            (cells(&row) - 1, cells(&row) - 1)
        );
        assert!(
            row.starts_with(
                "bob,s2,b@x,,13,,,,,,,,,\"not graded: no crates/whitted/src, \"\"really\"\"\""
            ),
            "computed {row:?}"
        );
        assert!(
            max.starts_with("Points Possible,,,13,13,13,3,"),
            "computed {max:?}"
        );
        assert!(head.ends_with(",ex 1.7,note"), "computed {head:?}");
    }

    #[test]
    fn a_roster_is_read_and_a_bad_line_is_placed() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("roster.csv");
        std::fs::write(&path, "folder,id,email\nada, s1 ,ada@x\n\nbob,s2,\n").unwrap();
        let r = read_roster(&path).unwrap();
        assert_eq!(r.get("ada"), Some(&("s1".into(), "ada@x".into())));
        assert_eq!(r.get("bob"), Some(&("s2".into(), String::new())));
        std::fs::write(&path, "ada,s1\n").unwrap();
        let err = read_roster(&path).unwrap_err().to_string();
        assert!(
            err.starts_with(&format!("{}:1:1: expected folder,id,email", path.display())),
            "{err}"
        );
    }
}
