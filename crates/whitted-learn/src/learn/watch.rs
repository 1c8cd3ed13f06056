//! `cargo learn watch`: a check, then another after every save of the student's sources,
//! tests, chapters or scenes (what an editor's backup files and the compiler's reads do not
//! count as).
//!
//! On a terminal each check starts on a cleared screen, as rustlings does, so the student sees
//! only the current state (the terminal's scrollback keeps the earlier ones); the progress
//! lines on stderr come after the clearing, above the report they announce, so the two
//! streams never overwrite each other. Elsewhere (a pipe, a file, CI) the reports follow one
//! another, each after a one-line divider ([`Between`]).
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::collections::BTreeMap;
use std::ffi::OsStr;
use std::io::{IsTerminal, Write};
use std::path::{Path, PathBuf};

use super::check::check;
use super::state::saved_states;
use super::style::Style;
use crate::manifest::Manifest;
use crate::{ToolError, layout};

/// Whether a changed file matters to the tests: not an editor's backup or swap file.
#[must_use]
pub fn is_source_change(path: &Path) -> bool {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_default();
    !(name.ends_with('~')
        || name.starts_with(".#")
        || name.ends_with(".swp")
        || name.ends_with(".swx")
        || name == "4913") // vim's probe file
}

/// The directories `watch` watches, relative to the project's root.
#[must_use]
pub fn watched() -> [PathBuf; 4] {
    [
        layout::core_src(),
        layout::core_tests(),
        PathBuf::from("chapters"),
        PathBuf::from("scenes"),
    ]
}

/// Each file under the watched directories with its modification time and size: what a save
/// changes. (The file watcher also reports files being read, as the compiler reads them; a
/// rerun happens only when this snapshot differs.)
#[must_use]
pub fn snapshot(root: &Path) -> BTreeMap<PathBuf, (std::time::SystemTime, u64)> {
    let mut out = BTreeMap::new();
    let mut stack: Vec<PathBuf> = watched().iter().map(|d| root.join(d)).collect();
    while let Some(dir) = stack.pop() {
        let Ok(entries) = std::fs::read_dir(&dir) else {
            continue;
        };
        for entry in entries.flatten() {
            let path = entry.path();
            let Ok(meta) = entry.metadata() else { continue };
            if meta.is_dir() {
                stack.push(path);
            } else if is_source_change(&path)
                && let Ok(modified) = meta.modified()
            {
                out.insert(path, (modified, meta.len()));
            }
        }
    }
    out
}

/// What `watch` writes on stdout before each check's report.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Between {
    /// Clears the screen (the scrollback stays) and starts at its top: on a terminal.
    Redraw,
    /// Appends, after a one-line divider: anywhere else.
    Divider,
}

/// Clears the screen and moves the cursor to its top left (ECMA-48's ED 2 and CUP), leaving
/// the terminal's scrollback as it is.
pub const CLEAR_SCREEN: &str = "\x1b[H\x1b[2J";

impl Between {
    /// [`Between::Redraw`] when stdout is a terminal that takes escape codes (not `TERM=dumb`;
    /// on Windows, once its virtual terminal processing is on), else [`Between::Divider`].
    #[must_use]
    pub fn detect() -> Self {
        let terminal = std::io::stdout().is_terminal()
            && anstyle_query::windows::enable_ansi_colors().unwrap_or(true);
        Self::choose(terminal, std::env::var_os("TERM").as_deref())
    }

    /// Redraw on a `terminal` unless `TERM` is `dumb` (a terminal that cannot move its cursor).
    /// `NO_COLOR` does not matter: clearing is not a colour.
    #[must_use]
    pub fn choose(terminal: bool, term: Option<&OsStr>) -> Self {
        if terminal && term != Some(OsStr::new("dumb")) {
            Self::Redraw
        } else {
            Self::Divider
        }
    }

    /// What goes before the report of check number `check` (0 for the first, before any
    /// save): the clearing every time, or a divider before every check but the first.
    #[must_use]
    pub fn text(self, check: usize, style: Style) -> String {
        match self {
            Self::Redraw => CLEAR_SCREEN.to_string(),
            Self::Divider if check == 0 => String::new(),
            Self::Divider => format!(
                "\n{}\n\n",
                style.strong(&format!(
                    "──────── check {}, after a save ────────",
                    check + 1
                ))
            ),
        }
    }
}

/// `whitted learn watch`: a check with its picture, then another after every save (changes
/// under [`watched`], debounced by 300 ms). Stops after `cycles` reruns when
/// given (for scripts and tests), else runs until interrupted. Each check's report comes after
/// [`Between::detect`]'s text: on a cleared screen on a terminal, after a divider elsewhere.
pub fn watch(
    root: &Path,
    manifest: &Manifest,
    style: Style,
    cycles: Option<usize>,
) -> Result<(), ToolError> {
    use notify_debouncer_mini::notify::RecursiveMode;
    let (tx, rx) = std::sync::mpsc::channel();
    let fail = |e: notify_debouncer_mini::notify::Error| {
        ToolError::Cargo(format!("cannot watch the project's files: {e}"))
    };
    let mut debouncer =
        notify_debouncer_mini::new_debouncer(std::time::Duration::from_millis(300), tx)
            .map_err(fail)?;
    for dir in watched() {
        let path = root.join(dir);
        if path.is_dir() {
            debouncer
                .watcher()
                .watch(&path, RecursiveMode::Recursive)
                .map_err(fail)?;
        }
    }
    let mut files = snapshot(root);
    let mut known = saved_states(root, manifest);
    let mut reruns = 0;
    let between = Between::detect();
    loop {
        // flushed before the check's first progress line reaches stderr, so that it lands
        // on the cleared screen, not under the clearing
        let mut out = std::io::stdout().lock();
        let _ = out.write_all(between.text(reruns, style).as_bytes());
        let _ = out.flush();
        drop(out);
        let checked = check(root, manifest, &known, style, true, true)?;
        if checked.run.build_error.is_none() {
            known = checked.states;
        }
        if cycles.is_some_and(|c| reruns >= c) {
            return Ok(());
        }
        println!(
            "\nwatching {} for changes (Ctrl-C to stop)",
            watched()
                .iter()
                .map(|d| format!("{}/", d.display()))
                .collect::<Vec<_>>()
                .join(", ")
        );
        let mut changed = false;
        while !changed {
            match rx.recv() {
                Ok(Ok(events)) if events.iter().any(|e| is_source_change(&e.path)) => {
                    while rx.try_recv().is_ok() {} // one rerun for a burst of saves
                    let now = snapshot(root);
                    changed = now != files; // a save, not a read
                    files = now;
                }
                Ok(Ok(_)) => {}
                Ok(Err(e)) => eprintln!("warning: while watching: {e}"),
                Err(_) => return Ok(()), // the watcher is gone
            }
        }
        reruns += 1;
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A terminal redraws, unless it is a dumb one; a pipe appends.
    #[test]
    fn a_terminal_redraws_and_a_pipe_appends() {
        let cases = [
            (true, None, Between::Redraw),
            (true, Some("xterm-256color"), Between::Redraw),
            (true, Some("dumb"), Between::Divider),
            (false, Some("xterm-256color"), Between::Divider),
            (false, None, Between::Divider),
        ];
        for (terminal, term, want) in cases {
            let got = Between::choose(terminal, term.map(OsStr::new));
            assert_eq!(got, want, "terminal {terminal}, TERM {term:?}");
        }
    }

    /// On a terminal every check, the first too, starts on a cleared screen; elsewhere the
    /// first check has nothing before it and each later one a one-line divider between
    /// blank lines, without colour when the style has none.
    #[test]
    fn each_check_starts_on_a_clear_screen_or_after_a_divider() {
        let plain = Style::plain();
        assert_eq!(Between::Redraw.text(0, plain), "\x1b[H\x1b[2J");
        assert_eq!(Between::Redraw.text(3, plain), "\x1b[H\x1b[2J");
        assert_eq!(Between::Divider.text(0, plain), "");
        assert_eq!(
            Between::Divider.text(1, plain),
            "\n──────── check 2, after a save ────────\n\n"
        );
        let coloured = Style::choose(true, None);
        assert_eq!(
            Between::Divider.text(2, coloured),
            "\n\x1b[1m──────── check 3, after a save ────────\x1b[0m\n\n"
        );
    }
}
