//! What the modes print on stdout (trees, the comparison's line) goes through [`print_out`].
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::path::PathBuf;

use whitted::error::Error;

/// Writes `text` on stdout; a reader that stops early (`| head`) is not an error.
pub fn print_out(text: &str) -> Result<(), Error> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(Error::Write {
            path: PathBuf::from("standard output"),
            message: e.to_string(),
        }),
        _ => Ok(()),
    }
}
