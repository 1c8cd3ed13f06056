//! The cargo bridge's wire: one cargo command asked by a Windows program under Wine, and its
//! answer, as files in one directory that both sides see.
//!
//! Wine starts a Linux program from a Windows one, but gives back no handle to wait on or read
//! from, so a Windows program cannot run the Linux cargo itself. The stand-in
//! (`cargo_stand_in.rs`, built for Windows) writes what it was asked as `ID.ask`; the test's
//! server (`serve.rs`, on Linux) runs cargo for the Windows target and writes `ID.out`,
//! `ID.err`, then `ID.code` last, which the stand-in waits for. A file appears under its name
//! only when whole (written under another name, then renamed).
//!
//! This file is compiled twice: into the stand-in, by `rustc` alone (std only), and into the
//! test that serves it.

#![allow(dead_code)]

use std::path::{Path, PathBuf};

/// The environment variable that names the bridge's directory (as the stand-in sees it).
pub const DIR_VAR: &str = "WHITTED_CARGO_BRIDGE";

/// One cargo command: where it runs, its arguments, and the cargo variables set for it.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Ask {
    /// The working directory, as the asking side names it.
    pub cwd: String,
    /// The arguments after `cargo`.
    pub args: Vec<String>,
    /// The `CARGO_…` variables that choose what cargo builds and where.
    pub env: Vec<(String, String)>,
}

impl Ask {
    /// One line a field, `cwd`, `arg` or `env` and a tab before the value (none holds a line
    /// break: cargo's arguments and paths here do not).
    pub fn to_text(&self) -> String {
        let mut text = format!("cwd\t{}\n", self.cwd);
        for a in &self.args {
            text += &format!("arg\t{a}\n");
        }
        for (k, v) in &self.env {
            text += &format!("env\t{k}={v}\n");
        }
        text
    }

    /// The ask [`Ask::to_text`] wrote; `None` when a line is not one of its fields.
    pub fn from_text(text: &str) -> Option<Ask> {
        let mut ask = Ask {
            cwd: String::new(),
            args: Vec::new(),
            env: Vec::new(),
        };
        for line in text.lines() {
            match line.split_once('\t')? {
                ("cwd", v) => ask.cwd = v.to_string(),
                ("arg", v) => ask.args.push(v.to_string()),
                ("env", kv) => {
                    let (k, v) = kv.split_once('=')?;
                    ask.env.push((k.to_string(), v.to_string()));
                }
                _ => return None,
            }
        }
        Some(ask)
    }
}

/// Whether the variable `name` goes along with an ask: the ones that choose what cargo builds
/// and where (the loop sets the target directory and the profiles' debug information).
pub fn forwarded(name: &str) -> bool {
    name == "CARGO_TARGET_DIR" || name.starts_with("CARGO_PROFILE_")
}

/// The file `ID.EXT` in the bridge's directory `dir`.
pub fn file(dir: &Path, id: &str, ext: &str) -> PathBuf {
    dir.join(format!("{id}.{ext}"))
}

/// Writes `text` to `path` whole: under another name first, then renamed.
pub fn put(path: &Path, text: &[u8]) -> std::io::Result<()> {
    let part = path.with_extension("part");
    std::fs::write(&part, text)?;
    std::fs::rename(&part, path)
}
