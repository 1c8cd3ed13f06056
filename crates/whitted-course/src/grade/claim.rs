//! A claim on something two gradings on one host must never share (a block of sandbox users,
//! a build directory): a directory made for the claim, which holds the claiming process's id.
//! Making a directory is atomic, so of two gradings that try at once exactly one succeeds; a
//! claim whose process is gone was left by a grading that died, and is taken over.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::{Path, PathBuf};

/// A claim held by this process, given up when dropped.
#[derive(Debug)]
pub struct Claim {
    /// The claim's directory.
    dir: PathBuf,
}

/// The process that holds the claim `dir`, when one that is alive does.
#[must_use]
pub fn holder(dir: &Path) -> Option<u32> {
    let pid: u32 = std::fs::read_to_string(dir.join("pid"))
        .ok()?
        .trim()
        .parse()
        .ok()?;
    Path::new("/proc")
        .join(pid.to_string())
        .exists()
        .then_some(pid)
}

impl Claim {
    /// Claims `dir` for this process: `Ok(None)` when a live process holds it.
    pub fn try_take(dir: &Path) -> Result<Option<Self>, String> {
        match std::fs::create_dir(dir) {
            Ok(()) => {}
            Err(e) if e.kind() == std::io::ErrorKind::AlreadyExists => {
                // a claim being made has no id yet: it is taken, unless it stays without one
                if holder(dir).is_some() || !Self::abandoned(dir) {
                    return Ok(None);
                }
                if std::fs::remove_dir_all(dir).is_err() || std::fs::create_dir(dir).is_err() {
                    return Ok(None);
                }
            }
            Err(e) => return Err(format!("{}: {e}", dir.display())),
        }
        let pid = dir.join("pid");
        std::fs::write(&pid, std::process::id().to_string())
            .map_err(|e| format!("{}: {e}", pid.display()))?;
        Ok(Some(Self {
            dir: dir.to_path_buf(),
        }))
    }

    /// Whether the claim `dir`, held by no live process, was left by a grading that died: its
    /// id names a process that is gone, or it has had none for a second (a claim is made and
    /// given its id at once).
    fn abandoned(dir: &Path) -> bool {
        if dir.join("pid").exists() {
            return true;
        }
        std::thread::sleep(std::time::Duration::from_secs(1));
        holder(dir).is_none() && std::fs::read_to_string(dir.join("pid")).is_err()
    }
}

impl Drop for Claim {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.dir);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One claim at a time; a claim whose process is gone is taken over; a dropped claim is
    /// free again.
    #[test]
    fn a_claim_is_held_once_and_taken_over_when_its_process_is_gone() {
        let dir = tempfile::tempdir().unwrap();
        let at = dir.path().join("claim");
        let first = Claim::try_take(&at).unwrap().expect("a free claim");
        assert_eq!(holder(&at), Some(std::process::id()));
        assert!(Claim::try_take(&at).unwrap().is_none(), "claimed twice");
        drop(first);
        assert!(!at.exists(), "the dropped claim is still there");
        // a grading that died: an id no process has
        std::fs::create_dir(&at).unwrap();
        std::fs::write(at.join("pid"), u32::MAX.to_string()).unwrap();
        let taken = Claim::try_take(&at).unwrap();
        assert!(taken.is_some(), "a dead grading's claim was not taken over");
        assert_eq!(holder(&at), Some(std::process::id()));
    }
}
