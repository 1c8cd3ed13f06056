//! Where the loop speaks: its report on stdout (printed as soon as each part is known), its
//! progress lines on stderr, and the one command every message names.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::io::Write;

/// The command a student types; every message that names a command names this one (a handout's
/// `.cargo/config.toml` defines it).
pub const COMMAND: &str = "cargo learn";

/// Where `learn` writes what it is doing: the report on stdout (when it is wanted), progress
/// lines on stderr.
pub(crate) struct Say {
    /// Whether the report is printed.
    pub(crate) report: bool,
}

impl Say {
    /// Writes a progress line on stderr.
    pub(crate) fn status(&self, line: &str) {
        let mut err = std::io::stderr().lock();
        let _ = writeln!(err, "{line}");
    }

    /// Writes part of the report on stdout, now.
    pub(crate) fn report(&self, text: &str) {
        if !self.report {
            return;
        }
        let mut out = std::io::stdout().lock();
        let _ = out.write_all(text.as_bytes());
        let _ = out.flush();
    }
}
