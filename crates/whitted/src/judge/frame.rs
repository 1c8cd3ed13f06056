//! The frames of the grader's wire: the messages the judge and the server send each other,
//! and how a frame is found among the student's own output.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::io::{BufRead, Write};

use base64::Engine;
use base64::engine::general_purpose::STANDARD as BASE64;
use serde::{Deserialize, Serialize};

/// What every frame begins with: a byte no Rust `print!` of text begins a line with, then a
/// name. Its first byte appears nowhere else in it, so a scan can restart at any byte.
pub const MAGIC: &[u8; 6] = b"\x1bWHJDG";

/// The longest line a frame may be (a scene's arguments are a few kilobytes).
const MAX_LINE: u64 = 64 << 20;

/// One message on the wire.
#[derive(Debug, Serialize, Deserialize, PartialEq)]
pub(super) enum Frame {
    /// The judge's first word to a new server: the exercises the server runs itself.
    Start { local: Vec<u16> },
    /// Run exercise `exercise` on these arguments and send its value.
    Call {
        exercise: u16,
        #[serde(with = "serde_bytes")]
        args: Vec<u8>,
    },
    /// The value of the innermost call that is waiting.
    Value(#[serde(with = "serde_bytes")] Vec<u8>),
    /// The innermost call that is waiting panicked, with this message.
    Panicked(String),
    /// The next item of the iterator the innermost waiting call took, please.
    Pull,
    /// That item (`Option<T>`, `None` at its end).
    Item(#[serde(with = "serde_bytes")] Vec<u8>),
}

/// Writes `frame` as one line, in one write: the server's standard output writes a line at
/// once, and each write is a system call that wakes the other side.
pub(super) fn write_frame(to: &mut dyn Write, frame: &Frame) -> std::io::Result<()> {
    let payload = bincode::serialize(frame).map_err(std::io::Error::other)?;
    let mut line = Vec::with_capacity(MAGIC.len() + payload.len() * 4 / 3 + 8);
    line.extend_from_slice(MAGIC);
    line.extend_from_slice(BASE64.encode(payload).as_bytes());
    line.push(b'\n');
    to.write_all(&line)?;
    to.flush()
}

/// A sink that keeps the first `room` bytes written to it and drops the rest: what the
/// other side writes between frames, held by the judge up to what it passes on.
pub(super) struct Capped {
    /// What was kept.
    pub(super) kept: Vec<u8>,
    /// How much may be kept.
    pub(super) room: usize,
}

impl Write for Capped {
    fn write(&mut self, bytes: &[u8]) -> std::io::Result<usize> {
        let take = bytes.len().min(self.room - self.kept.len().min(self.room));
        self.kept.extend_from_slice(&bytes[..take]);
        Ok(bytes.len())
    }

    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

/// The next frame on `from`; the bytes before it go to `spill`. An error at the end of the
/// input, or for a frame that is too long or no frame.
pub(super) fn read_frame(from: &mut dyn BufRead, spill: &mut dyn Write) -> std::io::Result<Frame> {
    let mut matched = 0;
    while matched < MAGIC.len() {
        let buf = from.fill_buf()?;
        if buf.is_empty() {
            return Err(std::io::ErrorKind::UnexpectedEof.into());
        }
        let mut used = 0;
        for &b in buf {
            used += 1;
            if b == MAGIC[matched] {
                matched += 1;
                if matched == MAGIC.len() {
                    break;
                }
            } else {
                spill.write_all(&MAGIC[..matched])?;
                matched = usize::from(b == MAGIC[0]);
                if matched == 0 {
                    spill.write_all(&[b])?;
                }
            }
        }
        from.consume(used);
    }
    let mut line = Vec::new();
    std::io::Read::take(&mut *from, MAX_LINE).read_until(b'\n', &mut line)?;
    if line.pop() != Some(b'\n') {
        return Err(std::io::Error::other(
            "a frame longer than the wire allows, or cut",
        ));
    }
    let payload = BASE64
        .decode(&line)
        .map_err(|e| std::io::Error::other(e.to_string()))?;
    bincode::deserialize(&payload).map_err(std::io::Error::other)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::real::Real;

    /// What the student's process writes between frames is kept up to the room left and
    /// dropped beyond it, however much comes.
    #[test]
    fn the_spill_is_kept_up_to_its_room() {
        let mut c = Capped {
            kept: Vec::new(),
            room: 5,
        };
        assert_eq!(c.write(b"abc").unwrap(), 3);
        assert_eq!(c.write(b"defgh").unwrap(), 5);
        assert_eq!(c.write(&[b'x'; 1 << 20]).unwrap(), 1 << 20);
        assert_eq!(c.kept, b"abcde");
    }

    /// Frames cross whole among the student's own output, which is kept in order, even when
    /// it holds the magic's first bytes; floats cross exactly, NaN and ∞ included.
    #[test]
    fn frames_cross_among_the_students_output_and_floats_cross_exactly() {
        let values: Vec<Real> = vec![
            0.1,
            -0.0,
            Real::NAN,
            Real::INFINITY,
            Real::MIN_POSITIVE / 2.0,
        ];
        let mut wire = Vec::new();
        wire.extend_from_slice(b"debug: t = 3\n\x1bW not a frame\n");
        write_frame(
            &mut wire,
            &Frame::Value(bincode::serialize(&values).unwrap()),
        )
        .unwrap();
        wire.extend_from_slice(b"\x1b\x1bWHJ");
        write_frame(&mut wire, &Frame::Panicked("not yet implemented".into())).unwrap();
        let mut from = std::io::Cursor::new(wire);
        let mut spill = Vec::new();
        let Frame::Value(v) = read_frame(&mut from, &mut spill).unwrap() else {
            panic!("no value frame first");
        };
        let back: Vec<Real> = bincode::deserialize(&v).unwrap();
        let bits = |v: &[Real]| v.iter().map(|x| x.to_bits()).collect::<Vec<_>>();
        assert_eq!(bits(&back), bits(&values), "the floats after crossing");
        assert_eq!(
            read_frame(&mut from, &mut spill).unwrap(),
            Frame::Panicked("not yet implemented".into())
        );
        assert_eq!(
            String::from_utf8_lossy(&spill),
            "debug: t = 3\n\x1bW not a frame\n\x1b\x1bWHJ",
            "the student's own output, in order"
        );
        assert_eq!(
            read_frame(&mut from, &mut spill).unwrap_err().kind(),
            std::io::ErrorKind::UnexpectedEof
        );
    }

    /// A frame cut before its end, or whose payload is no frame, is an error, not a panic.
    #[test]
    fn a_frame_cut_or_garbled_is_an_error() {
        let mut cut = MAGIC.to_vec();
        cut.extend_from_slice(b"AAAA");
        assert!(read_frame(&mut std::io::Cursor::new(cut), &mut std::io::sink()).is_err());
        let mut garbled = MAGIC.to_vec();
        garbled.extend_from_slice(b"////\n");
        assert!(read_frame(&mut std::io::Cursor::new(garbled), &mut std::io::sink()).is_err());
        let mut not_base64 = MAGIC.to_vec();
        not_base64.extend_from_slice(b"\x00\x01!\n");
        assert!(read_frame(&mut std::io::Cursor::new(not_base64), &mut std::io::sink()).is_err());
    }
}
