//! How every part of whitted says what went wrong, in one line: where in a file
//! ([`line_col`], for `file:line:col`), and a command line's problem ([`one_line`],
//! [`leave_after_args`]: the parser's error in one line, exit status 2). With the `png`
//! feature, the one PNG reader the renderer's `--compare` and the course's figure check share
//! ([`read_rgba`]).

/// The 1-based line and column (in characters) of byte `offset` in `text` (an offset past
/// the end counts as the end).
#[must_use]
pub fn line_col(text: &str, offset: usize) -> (usize, usize) {
    let offset = offset.min(text.len());
    let before = text.get(..offset).unwrap_or(text);
    let line = before.matches('\n').count() + 1;
    let line_start = before.rfind('\n').map_or(0, |i| i + 1);
    let col = before[line_start..].chars().count() + 1;
    (line, col)
}

/// clap's error text as one line: its first line, and when that ends in a colon, the list
/// that follows it (up to the usage).
#[must_use]
pub fn one_line(text: &str) -> String {
    let mut lines = text.lines().map(str::trim).filter(|l| !l.is_empty());
    let mut line = lines
        .next()
        .unwrap_or("error: invalid arguments")
        .to_string();
    if line.ends_with(':') {
        let list: Vec<&str> = lines.take_while(|l| !l.starts_with("Usage:")).collect();
        line = format!("{line} {}", list.join(", "));
    }
    line
}

/// How a program ends when its command line could not be taken, the same for every program:
/// `--help` and `--version` (`info`) print and exit 0; a bare command that needs more
/// (`bare`) prints its help and exits 2; any other problem is one line `error: …`
/// ([`one_line`] of the parser's `rendered` text) on stderr, with exit status 2. The parser's
/// own types stay with the programs (this crate needs no parser): they say which case it is.
pub fn leave_after_args(
    info: bool,
    bare: bool,
    print: impl FnOnce(),
    rendered: impl FnOnce() -> String,
) -> ! {
    if info || bare {
        print();
        std::process::exit(if info { 0 } else { 2 });
    }
    eprintln!("{} (see --help)", one_line(&rendered()));
    std::process::exit(2);
}

/// A PNG (any colour type or depth the format allows) as 8-bit RGBA, row by row from the
/// top: its width, height and bytes; `Err` is the decoder's reason.
#[cfg(feature = "png")]
pub fn read_rgba(path: &std::path::Path) -> Result<(u32, u32, Vec<u8>), String> {
    let file = std::fs::File::open(path).map_err(|e| e.to_string())?;
    decode_rgba(std::io::BufReader::new(file))
}

/// [`read_rgba`] of a PNG read from `png` (a file, or bytes in memory).
#[cfg(feature = "png")]
pub fn decode_rgba(
    png: impl std::io::BufRead + std::io::Seek,
) -> Result<(u32, u32, Vec<u8>), String> {
    let mut decoder = png::Decoder::new(png);
    // palettes and low bit depths become 8-bit channels, 16-bit channels become 8-bit
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info().map_err(|e| e.to_string())?;
    let mut buf = vec![0; reader.output_buffer_size().unwrap_or(0)];
    let info = reader.next_frame(&mut buf).map_err(|e| e.to_string())?;
    let rgba = buf[..info.buffer_size()]
        .chunks_exact(info.color_type.samples())
        .flat_map(|p| match *p {
            [g] => [g, g, g, 255],
            [g, a] => [g, g, g, a],
            [r, g, b] => [r, g, b, 255],
            [r, g, b, a, ..] => [r, g, b, a],
            [] => [0, 0, 0, 0],
        })
        .collect();
    Ok((info.width, info.height, rgba))
}

/// Whether `c` is written as its escape where a student's text is quoted (a report, a
/// terminal, XML): a control character other than a line feed or a tab, a bidirectional or
/// invisible format control, a byte-order mark, or a non-character.
#[must_use]
pub fn escaped(c: char) -> bool {
    let u = u32::from(c);
    let control = c.is_control() && c != '\n' && c != '\t';
    let bidi = matches!(u, 0x061C | 0x200E | 0x200F | 0x202A..=0x202E | 0x2066..=0x2069);
    let invisible = matches!(u, 0x200B..=0x200D | 0x2060 | 0xFEFF);
    let non_character = (0xFDD0..=0xFDEF).contains(&u) || u & 0xFFFE == 0xFFFE;
    control || bidi || invisible || non_character
}

/// `text` with every character that [`escaped`] names written as `\u{…}`, so that a reader
/// sees what was there and no report format breaks on it.
#[must_use]
pub fn clean(text: &str) -> String {
    let mut out = String::with_capacity(text.len());
    for c in text.chars() {
        if escaped(c) {
            out.push_str(&format!("\\u{{{:x}}}", u32::from(c)));
        } else {
            out.push(c);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn line_and_column_count_characters_from_one() {
        let text = "ab\nçd\n";
        assert_eq!(line_col(text, 0), (1, 1));
        assert_eq!(line_col(text, 3), (2, 1));
        // 'ç' is two bytes: the 'd' after it is the second character
        assert_eq!(line_col(text, 5), (2, 2));
        assert_eq!(line_col(text, 99), (3, 1));
    }

    #[test]
    fn a_list_after_a_colon_joins_the_line() {
        let text = "error: the following required arguments were not provided:\n  <DIR>\n  --out <OUT>\n\nUsage: x <DIR>\n";
        assert_eq!(
            one_line(text),
            "error: the following required arguments were not provided: <DIR>, --out <OUT>"
        );
        assert_eq!(one_line("error: bad\n\nUsage: x\n"), "error: bad");
        assert_eq!(one_line(""), "error: invalid arguments");
    }
}
