//! What a submission prints, made safe to carry: every report quotes a test's output, and
//! every byte of it is the student's.
//!
//! A test's output goes to nextest's XML report, then into JSON, JUnit, Markdown and the
//! terminal. Some characters break one of those or mislead a reader of another: bytes that
//! are not UTF-8, control characters (a terminal's escapes, XML 1.0 forbids most of them),
//! non-characters (U+FFFE made nextest's report unreadable, and the grade with it), and the
//! bidirectional controls (U+202E turns the rest of a line around). [`clean`] keeps a line
//! feed and a tab, replaces bytes that are not UTF-8 with U+FFFD, and writes each of the others
//! as its escape, `\u{202e}`, so a reader sees what was there.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

pub use whitted_syllabus::words::{clean, escaped};

fn push(out: &mut String, c: char) {
    if escaped(c) {
        out.push_str(&format!("\\u{{{:x}}}", u32::from(c)));
    } else {
        out.push(c);
    }
}

/// [`clean`] over a stream of bytes that arrive in pieces: a character cut between two
/// pieces is kept until its last byte comes, and bytes that are not UTF-8 become U+FFFD.
#[derive(Debug, Default)]
pub struct Cleaner {
    /// The start of a character whose other bytes have not come yet (at most 3 bytes).
    pending: Vec<u8>,
}

impl Cleaner {
    /// The clean text of `bytes`, after what was pending.
    pub fn feed(&mut self, bytes: &[u8]) -> String {
        let mut all = std::mem::take(&mut self.pending);
        all.extend_from_slice(bytes);
        // an unfinished character at the end waits for the next piece
        let keep = unfinished_tail(&all);
        self.pending = all.split_off(all.len() - keep);
        decode(&all)
    }

    /// The clean text of what is still pending, once the stream has ended.
    pub fn finish(&mut self) -> String {
        let rest = std::mem::take(&mut self.pending);
        decode(&rest)
    }
}

/// `bytes` as clean text: what is not UTF-8 as U+FFFD.
fn decode(bytes: &[u8]) -> String {
    let mut out = String::with_capacity(bytes.len());
    for chunk in bytes.utf8_chunks() {
        for c in chunk.valid().chars() {
            push(&mut out, c);
        }
        if !chunk.invalid().is_empty() {
            out.push(char::REPLACEMENT_CHARACTER);
        }
    }
    out
}

/// How many bytes at the end of `bytes` begin a character that is not finished: a lead byte
/// among the last three whose sequence runs past the end, with only continuation bytes after
/// it.
fn unfinished_tail(bytes: &[u8]) -> usize {
    for back in 1..=3.min(bytes.len()) {
        let b = bytes[bytes.len() - back];
        if b & 0xC0 == 0x80 {
            continue; // a continuation byte: look further back for its lead
        }
        let needs = match b {
            0xC2..=0xDF => 2,
            0xE0..=0xEF => 3,
            0xF0..=0xF4 => 4,
            _ => return 0,
        };
        return if needs > back { back } else { 0 };
    }
    0
}

/// `text` with every character that XML 1.0 forbids (most controls, U+FFFE, U+FFFF) replaced
/// by U+FFFD: a report written by a tool that did not clean its input can still be read.
#[must_use]
pub fn xml_safe(text: &str) -> String {
    text.chars()
        .map(|c| {
            let u = u32::from(c);
            let allowed =
                matches!(u, 0x9 | 0xA | 0xD | 0x20..=0xD7FF | 0xE000..=0xFFFD) || u >= 0x10000;
            if allowed {
                c
            } else {
                char::REPLACEMENT_CHARACTER
            }
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A non-character, a bidi override, an escape and a bell are written out; a line feed, a
    /// tab and ordinary letters are kept.
    #[test]
    fn what_misleads_or_breaks_a_report_is_escaped() {
        let text = "a\u{fffe}b\u{202e}c\u{1b}[31m\u{7}\td\n";
        assert_eq!(clean(text), "a\\u{fffe}b\\u{202e}c\\u{1b}[31m\\u{7}\td\n");
        assert_eq!(clean("η = 1.5, ρd ≥ 0"), "η = 1.5, ρd ≥ 0");
        assert_eq!(clean("\u{10ffff}"), "\\u{10ffff}");
    }

    /// A character cut between two pieces is decoded whole; a byte that is not UTF-8 becomes
    /// U+FFFD, and so does a character the stream ends in the middle of.
    #[test]
    fn a_stream_cut_anywhere_decodes_as_a_whole() {
        let text = "θ = 30°, \u{202e}!".as_bytes();
        for cut in 0..=text.len() {
            let mut c = Cleaner::default();
            let got = c.feed(&text[..cut]) + &c.feed(&text[cut..]) + &c.finish();
            assert_eq!(got, "θ = 30°, \\u{202e}!", "cut at byte {cut}");
        }
        let mut c = Cleaner::default();
        assert_eq!(c.feed(b"a\xffb\xe2\x80"), "a\u{fffd}b");
        assert_eq!(c.finish(), "\u{fffd}");
    }

    /// What XML 1.0 forbids is replaced, the rest is kept.
    #[test]
    fn xml_safe_replaces_what_xml_forbids() {
        assert_eq!(
            xml_safe("a\u{fffe}\u{1}b\n\u{1F600}"),
            "a\u{fffd}\u{fffd}b\n\u{1F600}"
        );
    }
}
