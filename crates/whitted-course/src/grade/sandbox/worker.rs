//! The sandbox of one grading worker ([`Sandbox`]): bubblewrap found and tried, the policy
//! of its test runs, and the environment that makes nextest run each test binary through it.
//!
//! Course book: [The instructor's guide](../../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::process::Command;

use super::policy::{FIRST_UID, Level, Limits, POLICY_VAR, Policy, RUNNER_COMMAND, SLOTS};
use crate::ToolError;
use crate::grade::claim::Claim;

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
    /// The block of user ids its tests run as, leased for as long as any copy of it lives
    /// (when the grader is root).
    pub lease: Option<std::sync::Arc<Lease>>,
}

/// How many blocks of [`SLOTS`] user ids there are from [`FIRST_UID`]: as many gradings at
/// once on one host, whatever their levels and their `--jobs`.
pub const BLOCKS: u32 = 64;

/// Where the leases are taken: a directory of root's alone, which no test's user can open.
const LEASES: &str = "/tmp/whitted-sandbox-leases";

/// A block of user ids leased by one grading: the claim `block-N` in `/tmp/whitted-sandbox-leases`
/// ([`crate::grade::claim`]), given up when the lease is dropped; a claim left by a grading that
/// died is taken over. Two gradings on one host never run tests as the same user, so a
/// clean-up, which ends every process of its users, reaches only its own grading's.
#[derive(Debug)]
pub struct Lease {
    /// The block: user ids from `FIRST_UID + block × SLOTS`.
    pub block: u32,
    /// Its claim.
    _claim: Claim,
}

impl Lease {
    /// The first free block, tried from `preferred` on (a worker's number, so that a class's
    /// workers take one each).
    pub fn take(preferred: u32) -> Result<Self, String> {
        use std::os::unix::fs::{DirBuilderExt, PermissionsExt};
        let leases = Path::new(LEASES);
        std::fs::DirBuilder::new()
            .recursive(true)
            .mode(0o700)
            .create(leases)
            .map_err(|e| format!("{LEASES}: {e}"))?;
        std::fs::set_permissions(leases, std::fs::Permissions::from_mode(0o700))
            .map_err(|e| format!("{LEASES}: {e}"))?;
        for k in 0..BLOCKS {
            let block = (preferred + k) % BLOCKS;
            if let Some(claim) = Claim::try_take(&leases.join(format!("block-{block}")))? {
                return Ok(Self {
                    block,
                    _claim: claim,
                });
            }
        }
        Err(format!(
            "all {BLOCKS} blocks of sandbox users are taken by other gradings on this host"
        ))
    }
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
        // a block of users of this grading's own: no other grading's clean-up reaches them
        let lease = if is_root() && level != Level::Off {
            let preferred = u32::try_from(worker).unwrap_or(0) % BLOCKS;
            Some(std::sync::Arc::new(Lease::take(preferred)?))
        } else {
            None
        };
        let uid = lease.as_ref().map(|l| FIRST_UID + SLOTS * l.block);
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
            lease,
        })
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
