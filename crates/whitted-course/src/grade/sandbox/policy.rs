//! The policy of a test run: how much of the machine the student's code is kept from
//! ([`Level`]), the limits it runs under, and the command that starts a test binary in the
//! sandbox. The grader writes it into [`POLICY_VAR`]; the runner reads it back.
//!
//! Course book: [The instructor's guide](../../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use serde::{Deserialize, Serialize};

use super::bwrap::{ancestors, push, push_path, system, unshare};

/// The environment variable that carries the run sandbox's policy from the grader to
/// [`crate::grade::runner::run_test`] (through nextest, which passes its environment to the
/// runner).
pub const POLICY_VAR: &str = "WHITTED_SANDBOX_POLICY";

/// The hidden subcommand of `whitted` that nextest starts each test binary with.
pub const RUNNER_COMMAND: &str = "sandbox-run";

/// The first user id the tests run as when the grader is root; worker `N` owns the
/// [`SLOTS`] ids from this plus `N × SLOTS`.
pub const FIRST_UID: u32 = 61_000;

/// User ids each worker owns: one for each test nextest runs at once (its slot, from
/// `NEXTEST_TEST_GLOBAL_SLOT`), so that a test's limit on processes counts only its own and a
/// fork bomb cannot starve the test beside it. A render run outside nextest uses the first.
pub const SLOTS: u32 = 64;

/// The environment variable in which nextest tells a test (and its runner) its slot.
pub(crate) const SLOT_VAR: &str = "NEXTEST_TEST_GLOBAL_SLOT";

/// What a test may use.
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Limits {
    /// Address space of each process, in bytes (`RLIMIT_AS`).
    pub memory: u64,
    /// Processes of the sandbox's user (`RLIMIT_NPROC`).
    pub processes: u64,
    /// The largest file it may write, in bytes (`RLIMIT_FSIZE`).
    pub file_size: u64,
    /// Its `/tmp` and `/dev/shm`, each a memory file system of this many bytes.
    pub tmp: u64,
    /// What is kept of its stdout and of its stderr, in bytes each; the rest is dropped.
    pub output: u64,
    /// Open files (`RLIMIT_NOFILE`).
    pub open_files: u64,
}

impl Default for Limits {
    fn default() -> Self {
        Self {
            memory: 2 << 30,
            processes: 64,
            file_size: 16 << 20,
            tmp: 32 << 20,
            output: 64 << 10,
            open_files: 256,
        }
    }
}

/// How much of the machine the student's code is kept from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize, clap::ValueEnum)]
pub enum Level {
    /// bubblewrap's namespaces: the build and the tests see only what they are shown, and the
    /// tests have no network.
    Namespaces,
    /// Where no namespace can be made (a platform's container), as root: the tests run as a
    /// user of their own with the limits, and what they must not read is closed to other
    /// users; the build is not sandboxed, so a body that would read files at compile time
    /// is not compiled. The tests keep the network; each test has a temporary directory of
    /// its own, and what its user left in the machine's shared ones is removed when it ends.
    User,
    /// No sandbox (`--unsandboxed`): the tests run with the grader's rights. The runner still
    /// passes a test only when libtest reported it `ok`, cleans its output and gives it a
    /// temporary directory of its own.
    #[value(skip)]
    Off,
}

/// How the tests of one grading are sandboxed: what [`crate::grade::runner::run_test`] reads
/// from [`POLICY_VAR`].
#[derive(Clone, Debug, PartialEq, Eq, Serialize, Deserialize)]
pub struct Policy {
    /// Namespaces, or a user of its own only.
    pub level: Level,
    /// The bubblewrap program.
    pub bwrap: PathBuf,
    /// The user id to drop to inside the sandbox (when the grader is root), also the group
    /// of every slot's user; `None` runs as the grader's own user, in a user namespace.
    pub uid: Option<u32>,
    /// The test's slot: it runs as `uid + slot` (below [`SLOTS`]), in the group `uid`.
    #[serde(default)]
    pub slot: u32,
    /// The limits.
    pub limits: Limits,
    /// Directories and files the tests read at run time, shown read-only at their own paths.
    pub read: Vec<PathBuf>,
    /// Directories the program may write in, shown at their own paths (a render's output:
    /// the grader makes each one empty, for this run only, and owned by the policy's user).
    pub write: Vec<PathBuf>,
    /// The test's time limit, in milliseconds: the runner ends the test and everything it
    /// started a moment before nextest's limit, so that nothing outlives a test that ran too
    /// long. `None` for a program run outside nextest.
    #[serde(default)]
    pub timeout_ms: Option<u64>,
}

impl Policy {
    /// Makes `dir` a fresh empty directory the sandboxed program may write in: owned by the
    /// policy's user when it has one (the grader is root), listed in [`Policy::write`].
    pub fn writable(&mut self, dir: &Path) -> std::io::Result<()> {
        std::fs::create_dir_all(dir)?;
        if let Some(uid) = self.uid {
            std::os::unix::fs::chown(dir, Some(uid), Some(uid))?;
        }
        self.write.push(dir.to_path_buf());
        Ok(())
    }

    /// The user and group the test runs as (when the grader is root): the slot's user, in
    /// the worker's group.
    pub(super) fn user(&self) -> Option<(u32, u32)> {
        self.uid.map(|uid| (uid + self.slot % SLOTS, uid))
    }

    /// The command that runs `bin` in `cwd` under this policy, the test's own arguments to
    /// follow: with an empty environment but for what a test needs, reading no input.
    #[must_use]
    pub fn command(&self, bin: &Path, cwd: &Path) -> Command {
        let inner = self.inner(bin);
        let mut command = match self.level {
            Level::Namespaces => {
                let mut c = Command::new(&self.bwrap);
                c.args(self.namespaces(bin, cwd)).args(&inner);
                c
            }
            Level::User | Level::Off => {
                let mut c = Command::new(&inner[0]);
                c.args(&inner[1..]);
                c
            }
        };
        command
            .env_clear()
            .envs([
                ("PATH", "/usr/bin:/bin"),
                ("HOME", "/tmp"),
                ("TMPDIR", "/tmp"),
                ("RUST_BACKTRACE", "0"),
                ("NO_COLOR", "1"),
            ])
            .stdin(Stdio::null());
        command
    }

    /// bubblewrap's arguments, up to its `--`: the new root and namespaces.
    fn namespaces(&self, bin: &Path, cwd: &Path) -> Vec<OsString> {
        let mut args = Vec::new();
        unshare(&mut args, self.uid.is_some());
        system(&mut args);
        push(&mut args, ["--proc", "/proc", "--dev", "/dev"]);
        let size = self.limits.tmp.to_string();
        for tmp in ["/tmp", "/dev/shm"] {
            push(
                &mut args,
                ["--size", &size, "--perms", "1777", "--tmpfs", tmp],
            );
        }
        let mut made = Vec::new();
        for p in self.read.iter().filter(|p| p.exists()) {
            ancestors(&mut args, &mut made, p);
            push_path(&mut args, "--ro-bind", p);
            args.push(p.as_os_str().to_owned());
        }
        for p in self.write.iter().filter(|p| p.is_dir()) {
            ancestors(&mut args, &mut made, p);
            push_path(&mut args, "--bind", p);
            args.push(p.as_os_str().to_owned());
        }
        ancestors(&mut args, &mut made, bin);
        push_path(&mut args, "--ro-bind", bin);
        args.push(bin.as_os_str().to_owned());
        if !self.read.iter().any(|r| cwd.starts_with(r)) {
            ancestors(&mut args, &mut made, &cwd.join("x"));
        }
        push_path(&mut args, "--chdir", cwd);
        args.push("--".into());
        args
    }

    /// The user and the limits, then `bin`: `setpriv` to the policy's user (when there is
    /// one) without capabilities, `prlimit` with the limits.
    fn inner(&self, bin: &Path) -> Vec<OsString> {
        let mut args: Vec<OsString> = Vec::new();
        if let Some((uid, gid)) = self.user() {
            args.push("setpriv".into());
            for a in [
                format!("--reuid={uid}"),
                format!("--regid={gid}"),
                "--clear-groups".into(),
                "--inh-caps=-all".into(),
                "--bounding-set=-all".into(),
                "--".into(),
            ] {
                args.push(a.into());
            }
        }
        let l = &self.limits;
        args.push("prlimit".into());
        for a in [
            format!("--as={}", l.memory),
            format!("--nproc={}", l.processes),
            format!("--fsize={}", l.file_size),
            format!("--nofile={}", l.open_files),
            "--core=0".into(),
            "--".into(),
        ] {
            args.push(a.into());
        }
        args.push(bin.as_os_str().to_owned());
        args
    }
}
