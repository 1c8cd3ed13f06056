//! The loop's colours on a terminal ([`Style`]), and none elsewhere.
//!
//! Course book: [The student's guide](../../../../../docs/book/student-guide.html) (`docs/src/student-guide.md`).

use std::io::IsTerminal;

/// Colours for a terminal: none when stdout is not one, or `NO_COLOR` is set.
#[derive(Clone, Copy, Debug)]
pub struct Style {
    on: bool,
}

impl Style {
    /// Colour when stdout is a terminal that shows it and `NO_COLOR` is unset or empty.
    /// Windows' console shows ANSI colours only once its virtual terminal processing is on
    /// (Windows 10 and later): it is switched on here, and where it cannot be, no colour.
    #[must_use]
    pub fn detect() -> Self {
        let terminal = std::io::stdout().is_terminal();
        // `None` off Windows, where every terminal shows them
        let shows = terminal && anstyle_query::windows::enable_ansi_colors().unwrap_or(true);
        Self::choose(shows, std::env::var_os("NO_COLOR").as_deref())
    }

    /// Colour on a terminal, unless `NO_COLOR` holds something (<https://no-color.org>).
    #[must_use]
    pub fn choose(terminal: bool, no_color: Option<&std::ffi::OsStr>) -> Self {
        Self {
            on: terminal && no_color.is_none_or(|v| v.is_empty()),
        }
    }

    /// No colour at all.
    #[must_use]
    pub fn plain() -> Self {
        Self { on: false }
    }

    fn paint(self, code: &str, text: &str) -> String {
        if self.on {
            // the line's end after the colour's: a terminal that keeps the colour past it
            // would paint the next line's start
            let body = text.trim_end_matches('\n');
            let end = &text[body.len()..];
            format!("\x1b[{code}m{body}\x1b[0m{end}")
        } else {
            text.to_string()
        }
    }

    /// Green.
    #[must_use]
    pub fn good(self, text: &str) -> String {
        self.paint("32", text)
    }

    /// Red.
    #[must_use]
    pub fn bad(self, text: &str) -> String {
        self.paint("31", text)
    }

    /// Bold.
    #[must_use]
    pub fn strong(self, text: &str) -> String {
        self.paint("1", text)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_line_end_comes_after_the_colour() {
        let on = Style { on: true };
        assert_eq!(on.good("✓ done\n"), "\x1b[32m✓ done\x1b[0m\n");
        assert_eq!(on.bad("✗"), "\x1b[31m✗\x1b[0m");
        assert_eq!(Style { on: false }.good("✓ done\n"), "✓ done\n");
    }
}
