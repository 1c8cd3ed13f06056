//! The sandbox a submission is built and run in (Linux, bubblewrap): the student's code never
//! runs, nor is compiled, with the grader's view of the machine.
//!
//! - **Build.** cargo runs in a bubblewrap sandbox that sees the system (`/usr`, and of `/etc`
//!   what the linker needs), the toolchain and the registry read-only, the graded copy
//!   read-only, the build directory writable, and nothing else: not the instructor's project,
//!   not the hidden tests, not the results, not the machine's own files. A body's
//!   `include_str!`, `include_bytes!` or `#[path]` can read only what the sandbox shows, which
//!   holds nothing secret (the graded copy carries no reference body of a graded exercise and
//!   no hidden test while the student's crate compiles).
//! - **Run.** nextest stays outside and writes its report; each test binary it starts goes
//!   through [`super::runner::run_test`] (nextest's target runner, `CARGO_TARGET_<TRIPLE>_RUNNER`): a new
//!   root that holds only the system's libraries, the test binary read-only, the files the
//!   tests read and a small private `/tmp`; namespaces of its own (network, processes, IPC,
//!   host name, and users when the grader is not root); an empty environment; an
//!   unprivileged user (as root, a user id of its own per worker, so that its limit on
//!   processes counts only its own); limits on memory,
//!   processes, file size and open files (`prlimit`). The runner cuts its output at a size
//!   (a test that prints megabytes costs the grader nothing), cleans it, passes a test only
//!   when libtest reported it `ok`, and ends it a moment before nextest's time limit: the
//!   sandbox ends with it (`--die-with-parent`, and the PID namespace ends with its first
//!   process).
//!
//! When bubblewrap is missing or cannot make namespaces, [`Sandbox::probe`] says why in one
//! line; the grader then refuses unless told to grade at [`Level::User`] (as root, in a
//! container that makes no namespace: the same user, limits and environment without the new
//! root, the secrets closed by their permissions, what the test's user leaves swept) or
//! unsandboxed ([`Level::Off`]: the runner's verdict, limits and cleaning only).
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use serde::{Deserialize, Serialize};

use crate::ToolError;
use crate::cargo::Wrapper;

/// The environment variable that carries the run sandbox's policy from the grader to
/// [`super::runner::run_test`] (through nextest, which passes its environment to the runner).
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
pub(super) const SLOT_VAR: &str = "NEXTEST_TEST_GLOBAL_SLOT";

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

/// How the tests of one grading are sandboxed: what [`super::runner::run_test`] reads from [`POLICY_VAR`].
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

/// The sandbox of one worker: found and tried by [`Sandbox::probe`].
#[derive(Clone, Debug)]
pub struct Sandbox {
    /// The policy of its test runs.
    pub policy: Policy,
    /// The program nextest starts each test binary with (`whitted`, given
    /// [`RUNNER_COMMAND`]).
    pub runner: PathBuf,
    /// The host's target triple (the `CARGO_TARGET_<TRIPLE>_RUNNER` variable's name).
    pub triple: String,
}

/// Whether this process runs as root.
fn is_root() -> bool {
    // the owner of /proc/self is the process's effective user
    std::fs::metadata("/proc/self").is_ok_and(|m| {
        use std::os::unix::fs::MetadataExt;
        m.uid() == 0
    })
}

/// `name` found on the `PATH`.
fn on_path(name: &str) -> Option<PathBuf> {
    let path = std::env::var_os("PATH")?;
    std::env::split_paths(&path)
        .map(|d| d.join(name))
        .find(|p| p.is_file())
}

/// The arguments that give a new root with the system's programs and libraries read-only:
/// `/usr` and the top-level links into it (or the directories, where they are not links).
fn system(args: &mut Vec<OsString>) {
    push(args, ["--ro-bind", "/usr", "/usr"]);
    for top in ["/bin", "/sbin", "/lib", "/lib32", "/lib64", "/libx32"] {
        let p = Path::new(top);
        match std::fs::read_link(p) {
            Ok(to) => {
                args.push("--symlink".into());
                args.push(to.into_os_string());
                args.push(top.into());
            }
            Err(_) if p.is_dir() => push(args, ["--ro-bind", top, top]),
            Err(_) => {}
        }
    }
}

fn push<const N: usize>(args: &mut Vec<OsString>, items: [&str; N]) {
    args.extend(items.iter().map(OsString::from));
}

fn push_path(args: &mut Vec<OsString>, flag: &str, path: &Path) {
    args.push(flag.into());
    args.push(path.as_os_str().to_owned());
}

/// `--perms 0755 --dir D` for each ancestor of `path` not made yet, so that an unprivileged
/// user can reach what is bound below them (bubblewrap makes missing parents private).
fn ancestors(args: &mut Vec<OsString>, made: &mut Vec<PathBuf>, path: &Path) {
    let mut chain: Vec<&Path> = path.ancestors().skip(1).collect();
    chain.reverse();
    for dir in chain {
        if dir.parent().is_none() || made.iter().any(|m| m == dir) {
            continue;
        }
        push(args, ["--perms", "0755"]);
        push_path(args, "--dir", dir);
        made.push(dir.to_path_buf());
    }
}

/// The namespaces to leave: all of them; as root, all but the user namespace (the test drops
/// to its own user instead, with `setpriv`).
fn unshare(args: &mut Vec<OsString>, root: bool) {
    if root {
        push(
            args,
            [
                "--unshare-ipc",
                "--unshare-pid",
                "--unshare-net",
                "--unshare-uts",
                "--unshare-cgroup-try",
            ],
        );
    } else {
        push(args, ["--unshare-all"]);
    }
    push(args, ["--die-with-parent", "--new-session"]);
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
    fn user(&self) -> Option<(u32, u32)> {
        self.uid.map(|uid| (uid + self.slot % SLOTS, uid))
    }

    /// Ends every process the test's user (its slot's) still has once the test has ended, and
    /// removes what that user left in the machine's shared temporary directories, at the user
    /// level (as root): a child left running would count against the next test's limit on
    /// processes in this slot and could hold its output open, and a file left in `/tmp` could
    /// carry answers to the next submission. `kill -1` is sent again while a process of the
    /// user is alive (one that forks as it is killed can slip past one round). In namespaces
    /// nothing is left: the PID namespace ends with the test, and its `/tmp` is its own.
    pub fn sweep(&self) {
        let (Level::User, Some((uid, gid))) = (self.level, self.user()) else {
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
        remove_left_files(&(uid..uid + 1));
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

/// Whether a user other than the owner can reach `path`: every directory from the root to it
/// searchable by others (and the path itself readable, when it is a file).
fn open_to_others(path: &Path) -> bool {
    use std::os::unix::fs::PermissionsExt;
    let Ok(path) = path.canonicalize() else {
        return false;
    };
    path.ancestors().all(|a| {
        std::fs::metadata(a).is_ok_and(|m| {
            let mode = m.permissions().mode();
            if m.is_dir() {
                mode & 0o001 != 0
            } else {
                mode & 0o004 != 0
            }
        })
    })
}

impl Sandbox {
    /// Finds bubblewrap and tries a sandbox like the tests' with `true` in it; `Err` says in
    /// one line why there can be none. `runner` is the `whitted` program, `worker` the
    /// worker's number (its user id when the grader is root), `read` what the tests read.
    pub fn probe(
        runner: &Path,
        worker: usize,
        read: Vec<PathBuf>,
        level: Level,
    ) -> Result<Self, String> {
        let bwrap = match level {
            Level::Namespaces => on_path("bwrap").ok_or(
                "bubblewrap (bwrap) is not installed: apt-get install bubblewrap".to_string(),
            )?,
            Level::User if !is_root() => {
                return Err(
                    "--sandbox user runs the tests as a user of their own, which only root can"
                        .into(),
                );
            }
            Level::User | Level::Off => PathBuf::new(),
        };
        for tool in ["setpriv", "prlimit"] {
            if on_path(tool).is_none() {
                return Err(format!("{tool} (util-linux) is not installed"));
            }
        }
        let uid = (is_root() && level != Level::Off)
            .then(|| FIRST_UID + SLOTS * u32::try_from(worker).unwrap_or(0));
        let policy = Policy {
            level,
            bwrap,
            uid,
            slot: 0,
            limits: Limits::default(),
            read,
            write: Vec::new(),
            timeout_ms: None,
        };
        let truth = on_path("true").ok_or("no `true` program on the PATH".to_string())?;
        let out = policy
            .command(&truth, Path::new("/tmp"))
            .output()
            .map_err(|e| format!("cannot start the sandbox: {e}"))?;
        if !out.status.success() {
            let why = String::from_utf8_lossy(&out.stderr);
            return Err(format!(
                "{} cannot make a sandbox here{}: {}",
                if level == Level::User {
                    "setpriv"
                } else {
                    "bubblewrap"
                },
                if level == Level::User {
                    ""
                } else {
                    " (user namespaces off?)"
                },
                why.lines().next().unwrap_or("it failed").trim()
            ));
        }
        let triple = host_triple().ok_or("`rustc -vV` names no host triple".to_string())?;
        Ok(Self {
            policy,
            runner: runner.to_path_buf(),
            triple,
        })
    }

    /// The wrapper cargo builds in: the system (`/usr`, of `/etc` what the linker needs), the
    /// toolchain and the registry (never cargo's credentials) read-only, the graded copy `project` read-only, the build directory `target_dir` writable, a private
    /// `/tmp`, no network; its environment only what cargo needs.
    /// `None` at [`Level::User`] and [`Level::Off`], whose build is not sandboxed.
    #[must_use]
    pub fn build_wrapper(&self, project: &Path, target_dir: &Path) -> Option<Wrapper> {
        if self.policy.level != Level::Namespaces {
            return None;
        }
        let mut args = Vec::new();
        unshare(&mut args, self.policy.uid.is_some());
        system(&mut args);
        // of /etc only what the linker needs (`cc` is a link through the alternatives; the
        // dynamic linker's cache): the build runs as the grader's user, and a body's
        // include_bytes! must find nothing of the machine's own there
        for etc in [
            "/etc/alternatives",
            "/etc/ld.so.cache",
            "/etc/ld.so.conf",
            "/etc/ld.so.conf.d",
        ] {
            if Path::new(etc).exists() {
                push(&mut args, ["--ro-bind", etc, etc]);
            }
        }
        push(
            &mut args,
            ["--proc", "/proc", "--dev", "/dev", "--tmpfs", "/tmp"],
        );
        let home = std::env::var_os("HOME").map(PathBuf::from);
        let cargo_home = std::env::var_os("CARGO_HOME")
            .map(PathBuf::from)
            .or_else(|| home.as_ref().map(|h| h.join(".cargo")));
        let rustup_home = std::env::var_os("RUSTUP_HOME")
            .map(PathBuf::from)
            .or_else(|| home.as_ref().map(|h| h.join(".rustup")));
        let mut read: Vec<PathBuf> = Vec::new();
        if let Some(c) = &cargo_home {
            // the programs, the crates and the settings: never the credentials
            for part in ["bin", "registry", "git", "config.toml", "config"] {
                read.push(c.join(part));
            }
        }
        read.extend(rustup_home.iter().cloned());
        // a toolchain outside both homes ($CARGO set by a cargo that started us)
        if let Some(cargo) = std::env::var_os("CARGO").map(PathBuf::from)
            && let Some(toolchain) = cargo.parent().and_then(Path::parent)
            && !read.iter().any(|r| toolchain.starts_with(r))
            && !toolchain.starts_with("/usr")
        {
            read.push(toolchain.to_path_buf());
        }
        for p in read.iter().filter(|p| p.exists()) {
            push_path(&mut args, "--ro-bind", p);
            args.push(p.as_os_str().to_owned());
        }
        push_path(&mut args, "--bind", target_dir);
        args.push(target_dir.as_os_str().to_owned());
        // the copy after the build directory: it may lie inside it, and stays read-only
        push_path(&mut args, "--ro-bind", project);
        args.push(project.as_os_str().to_owned());
        push_path(&mut args, "--chdir", project);
        args.push("--".into());
        let mut env: Vec<(OsString, OsString)> = vec![
            ("CARGO_NET_OFFLINE".into(), "true".into()),
            ("TMPDIR".into(), "/tmp".into()),
            ("HOME".into(), "/tmp".into()),
        ];
        if let Some(c) = cargo_home {
            env.push(("CARGO_HOME".into(), c.into_os_string()));
        }
        if let Some(r) = rustup_home {
            env.push(("RUSTUP_HOME".into(), r.into_os_string()));
        }
        for (k, v) in std::env::vars_os() {
            let name = k.to_string_lossy();
            let keep = name == "PATH"
                || name == "RUSTUP_TOOLCHAIN"
                || name == "RUSTFLAGS"
                || name == "CARGO_INCREMENTAL"
                || name == "CARGO"
                || name.starts_with("CARGO_PROFILE_")
                || name.starts_with("CARGO_BUILD_");
            if keep {
                env.push((k, v));
            }
        }
        Some(Wrapper {
            program: self.policy.bwrap.clone().into_os_string(),
            args,
            env,
        })
    }

    /// At [`Level::User`], before the tests run: refuses when one of `secrets` (the
    /// instructor's project, the hidden tests) is open to other users, or when the build
    /// directory is not (the tests' user must reach its binaries), and closes the graded copy
    /// (which holds the hidden tests while they run) to other users until [`Sandbox::reopen`].
    /// Nothing at
    /// [`Level::Namespaces`], whose tests see none of these.
    pub fn protect(
        &self,
        secrets: &[&Path],
        target_dir: &Path,
        project: &Path,
    ) -> Result<(), ToolError> {
        use std::os::unix::fs::PermissionsExt;
        if self.policy.level != Level::User {
            return Ok(());
        }
        for s in secrets {
            if open_to_others(s) {
                return Err(ToolError::Usage(format!(
                    "--sandbox user: {} is open to other users, and the tests would read it: close it (chmod o-rwx)",
                    s.display()
                )));
            }
        }
        if !open_to_others(target_dir) {
            return Err(ToolError::Usage(format!(
                "--sandbox user: the build directory {} is closed to other users, and the tests run as one: every directory above it must be searchable (o+x)",
                target_dir.display()
            )));
        }
        // what the submission before left running ends before this one's tests start
        self.policy.sweep_all();
        std::fs::set_permissions(project, std::fs::Permissions::from_mode(0o700))
            .map_err(|e| ToolError::io(project, e))
    }

    /// Opens the graded copy again once the hidden tests have left it (the leaderboard's
    /// render reads its scenes and figures as the tests' user).
    pub fn reopen(&self, project: &Path) -> Result<(), ToolError> {
        use std::os::unix::fs::PermissionsExt;
        if self.policy.level != Level::User {
            return Ok(());
        }
        self.policy.sweep_all();
        std::fs::set_permissions(project, std::fs::Permissions::from_mode(0o755))
            .map_err(|e| ToolError::io(project, e))
    }

    /// The environment nextest runs with: its target runner is [`RUNNER_COMMAND`], which
    /// reads the policy from [`POLICY_VAR`].
    pub fn runner_env(&self) -> Result<Vec<(OsString, OsString)>, ToolError> {
        let runner = self.runner.to_string_lossy();
        if runner.contains(char::is_whitespace) {
            return Err(ToolError::Usage(format!(
                "the sandbox's runner {runner} has a space in its path, which cargo's runner setting cannot hold"
            )));
        }
        let var = format!(
            "CARGO_TARGET_{}_RUNNER",
            self.triple.to_uppercase().replace(['-', '.'], "_")
        );
        let policy = serde_json::to_string(&self.policy)
            .map_err(|e| ToolError::Usage(format!("the sandbox's policy: {e}")))?;
        Ok(vec![
            (var.into(), format!("{runner} {RUNNER_COMMAND}").into()),
            (POLICY_VAR.into(), policy.into()),
        ])
    }
}

/// The host's target triple, from `rustc -vV`.
fn host_triple() -> Option<String> {
    let rustc = std::env::var_os("RUSTC").unwrap_or_else(|| "rustc".into());
    let out = Command::new(rustc).arg("-vV").output().ok()?;
    String::from_utf8_lossy(&out.stdout)
        .lines()
        .find_map(|l| l.strip_prefix("host: "))
        .map(|t| t.trim().to_string())
}
