//! What a test's user leaves behind at the user level (as root, without namespaces): its
//! processes, ended, and its files in the machine's shared temporary directories, removed.
//!
//! Course book: [The instructor's guide](../../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::path::Path;
use std::process::{Command, Stdio};

use super::policy::{Level, Policy, SLOTS};

impl Policy {
    /// Ends every process the test's user (its slot's) still has once the test has ended, and
    /// removes what that user left in the machine's shared temporary directories, at the user
    /// level (as root): a child left running would count against the next test's limit on
    /// processes in this slot and could hold its output open, and a file left in `/tmp` could
    /// carry answers to the next submission. `kill -1` is sent again while a process of the
    /// user is alive (one that forks as it is killed can slip past one round). In namespaces
    /// the kernel ends what is left when the PID namespace's first process ends, but not at
    /// once: the same rounds make sure that it has ended before the runner returns (the
    /// namespace's `/tmp` is its own, so no file is left there).
    pub fn sweep(&self) {
        let (Level::User | Level::Namespaces, Some((uid, gid))) = (self.level, self.user()) else {
            return;
        };
        for round in 0..50 {
            // kill(-1) as that user reaches that user's processes and no other's
            let _ = Command::new("setpriv")
                .args([
                    format!("--reuid={uid}"),
                    format!("--regid={gid}"),
                    "--clear-groups".into(),
                    "--".into(),
                    "kill".into(),
                    "-KILL".into(),
                    "-1".into(),
                ])
                .stdin(Stdio::null())
                .stdout(Stdio::null())
                .stderr(Stdio::null())
                .status();
            if processes_of(&(uid..uid + 1)).is_empty() {
                break;
            }
            std::thread::sleep(std::time::Duration::from_millis(5 * (round + 1)));
        }
        if self.level == Level::User {
            remove_left_files(&(uid..uid + 1));
        }
    }

    /// [`Policy::sweep`] for every slot of this worker: before a submission's tests, what the
    /// one before left; after them, what a test killed at its time limit left.
    pub fn sweep_all(&self) {
        let (Level::User, Some(first)) = (self.level, self.uid) else {
            return;
        };
        let left: std::collections::BTreeSet<u32> = processes_of(&(first..first + SLOTS))
            .into_iter()
            .map(|(_, uid)| uid - first)
            .collect();
        for slot in left {
            Self {
                slot,
                ..self.clone()
            }
            .sweep();
        }
        remove_left_files(&(first..first + SLOTS));
    }
}

/// The live processes (process id, real user id) whose real user is in `users`, read from
/// `/proc` (none when it cannot be read). A zombie is not one: it has ended, and waits only
/// for the machine's first process to collect it.
#[must_use]
pub fn processes_of(users: &std::ops::Range<u32>) -> Vec<(u32, u32)> {
    let Ok(entries) = std::fs::read_dir("/proc") else {
        return Vec::new();
    };
    entries
        .filter_map(Result::ok)
        .filter_map(|entry| {
            let pid = entry.file_name().to_str()?.parse::<u32>().ok()?;
            let status = std::fs::read_to_string(entry.path().join("status")).ok()?;
            let zombie = status
                .lines()
                .find_map(|l| l.strip_prefix("State:"))
                .is_some_and(|state| state.trim_start().starts_with('Z'));
            if zombie {
                return None;
            }
            let uid = status
                .lines()
                .find_map(|l| l.strip_prefix("Uid:"))?
                .split_whitespace()
                .next()?
                .parse::<u32>()
                .ok()?;
            users.contains(&uid).then_some((pid, uid))
        })
        .collect()
}

/// The directories every user may write in, where a test at the user level could leave a
/// file for a later one.
pub const SHARED_TEMPORARY: [&str; 4] = ["/tmp", "/var/tmp", "/dev/shm", "/run/lock"];

/// Removes every file and directory owned by one of `users` in [`SHARED_TEMPORARY`], and in
/// the directories there that every user may write in (two levels down): what a test at the
/// user level left behind.
pub fn remove_left_files(users: &std::ops::Range<u32>) {
    use std::os::unix::fs::{MetadataExt, PermissionsExt};
    fn walk(dir: &Path, users: &std::ops::Range<u32>, depth: u32) {
        let Ok(entries) = std::fs::read_dir(dir) else {
            return;
        };
        for e in entries.flatten() {
            let path = e.path();
            let Ok(meta) = std::fs::symlink_metadata(&path) else {
                continue;
            };
            if users.contains(&meta.uid()) {
                let _ = if meta.is_dir() {
                    std::fs::remove_dir_all(&path)
                } else {
                    std::fs::remove_file(&path)
                };
            } else if meta.is_dir() && meta.permissions().mode() & 0o002 != 0 && depth > 0 {
                walk(&path, users, depth - 1);
            }
        }
    }
    for dir in SHARED_TEMPORARY {
        walk(Path::new(dir), users, 2);
    }
}
