//! The compiler under limits: every process of a graded copy's build (cargo, rustc, the linker)
//! has a CPU time and a memory limit of its own, so that a body that stalls the compiler (an
//! endless `const`, a generic blow-up, a huge expansion) costs its own exercise, in minutes.
//!
//! The grader starts cargo through its hidden command `whitted compile-watch` ([`COMMAND`]),
//! around the build sandbox when there is one: it runs the build, reads the build's processes
//! from `/proc` a few times a second (each one's CPU time, user and system, and its resident
//! memory), ends any that passes its limit with everything it started, and says so on its
//! stderr in one line that begins with [`STOPPED`]. CPU time, not the wall clock: a loaded
//! machine makes a build slower, not costlier, so it never stops an honest one. The build then
//! fails, and the grader finds the body to blame (`grade/build.rs`).
//!
//! Course book: [The instructor's guide](../../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::collections::BTreeMap;
use std::ffi::OsString;
use std::path::Path;
use std::process::{Command, ExitCode, Stdio};
use std::time::Duration;

use crate::cargo::Wrapper;

/// The hidden command of `whitted` that a graded copy's build runs inside.
pub const COMMAND: &str = "compile-watch";

/// How the line that says a build was stopped begins (on the build's stderr).
pub const STOPPED: &str = "whitted compile-watch: stopped";

/// The limits of each process of a build.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct CompileLimits {
    /// CPU time (user and system) of one process.
    pub cpu: Duration,
    /// Resident memory of one process, in bytes.
    pub memory: u64,
}

impl Default for CompileLimits {
    /// 120 s of CPU and 4 GiB: the largest compiler run of an honest submission (the renderer's
    /// crate, built from nothing) takes a fraction of each.
    fn default() -> Self {
        Self {
            cpu: Duration::from_secs(120),
            memory: 4 << 30,
        }
    }
}

/// The build's wrapper with the watch around it: `whitted compile-watch LIMITS -- WRAPPER…`
/// (the sandbox's program and arguments), or around cargo itself, with this program's
/// environment, when there is no sandbox.
#[must_use]
pub fn watched(runner: &Path, limits: CompileLimits, inner: Option<Wrapper>) -> Wrapper {
    let mut args: Vec<OsString> = vec![
        COMMAND.into(),
        "--cpu-ms".into(),
        limits.cpu.as_millis().to_string().into(),
        "--memory".into(),
        limits.memory.to_string().into(),
        "--".into(),
    ];
    let env = match inner {
        Some(w) => {
            args.push(w.program);
            args.extend(w.args);
            w.env
        }
        None => std::env::vars_os().collect(),
    };
    Wrapper {
        program: runner.as_os_str().to_owned(),
        args,
        env,
    }
}

/// The reason a build was stopped, from its stderr: the rest of the [`STOPPED`] line.
#[must_use]
pub fn stopped(stderr: &str) -> Option<String> {
    stderr
        .lines()
        .find_map(|l| l.strip_prefix(STOPPED))
        .map(|r| r.trim().to_string())
}

/// One process as `/proc/PID/stat` tells it.
pub struct Stat {
    /// Its parent's process id.
    pub parent: u32,
    /// Its name (the program's, cut at 15 bytes).
    pub name: String,
    /// Its own CPU time, user and system.
    pub cpu: Duration,
    /// The CPU time of its children that it has waited for, user and system.
    pub children_cpu: Duration,
    /// Its resident memory, in bytes.
    pub memory: u64,
}

/// Every process of the machine, by id.
#[must_use]
pub fn processes() -> BTreeMap<u32, Stat> {
    let tick = 100.0; // USER_HZ: 100 on every Linux the grader runs on
    let page = 4096; // the page size of the machines the grader runs on
    let mut out = BTreeMap::new();
    for e in std::fs::read_dir("/proc").into_iter().flatten().flatten() {
        let Some(pid) = e.file_name().to_str().and_then(|s| s.parse::<u32>().ok()) else {
            continue;
        };
        let Ok(text) = std::fs::read_to_string(e.path().join("stat")) else {
            continue;
        };
        // `PID (NAME) STATE PPID …`: the name may hold spaces and parentheses
        let (Some(open), Some(close)) = (text.find('('), text.rfind(')')) else {
            continue;
        };
        let name = text[open + 1..close].to_string();
        let fields: Vec<&str> = text[close + 1..].split_whitespace().collect();
        let field = |i: usize| {
            fields
                .get(i)
                .and_then(|f| f.parse::<u64>().ok())
                .unwrap_or(0)
        };
        // after the name: state(0) ppid(1) … utime(11) stime(12) cutime(13) cstime(14) … rss(21)
        out.insert(
            pid,
            Stat {
                parent: u32::try_from(field(1)).unwrap_or(0),
                name,
                cpu: Duration::from_secs_f64((field(11) + field(12)) as f64 / tick),
                children_cpu: Duration::from_secs_f64((field(13) + field(14)) as f64 / tick),
                memory: field(21) * page,
            },
        );
    }
    out
}

/// The processes that descend from `root`, `root` included.
#[must_use]
pub fn descendants(all: &BTreeMap<u32, Stat>, root: u32) -> Vec<u32> {
    let mut out = vec![root];
    let mut i = 0;
    while i < out.len() {
        let p = out[i];
        out.extend(all.iter().filter(|(_, s)| s.parent == p).map(|(&c, _)| c));
        i += 1;
    }
    out
}

/// `whitted compile-watch --cpu-ms N --memory BYTES -- PROGRAM ARGS…`: runs the program and
/// ends any process of it that passes a limit (see the module's documentation); exits as the
/// program did, or with 1 when it stopped one.
#[must_use]
pub fn run(args: &[OsString]) -> ExitCode {
    let fail = |why: &str| {
        eprintln!("whitted {COMMAND}: {why}");
        ExitCode::from(2)
    };
    let words: Vec<&str> = args.iter().map(|a| a.to_str().unwrap_or("")).collect();
    let Some(split) = words.iter().position(|w| *w == "--") else {
        return fail("no program to run after `--`");
    };
    let number = |flag: &str| -> Option<u64> {
        let at = words[..split].iter().position(|w| *w == flag)?;
        words.get(at + 1)?.parse().ok()
    };
    let (Some(cpu_ms), Some(memory)) = (number("--cpu-ms"), number("--memory")) else {
        return fail("--cpu-ms and --memory are required");
    };
    let Some((program, rest)) = args[split + 1..].split_first() else {
        return fail("no program to run after `--`");
    };
    let limits = CompileLimits {
        cpu: Duration::from_millis(cpu_ms),
        memory,
    };
    let mut child = match Command::new(program)
        .args(rest)
        .stdin(Stdio::null())
        .spawn()
    {
        Ok(c) => c,
        Err(e) => return fail(&format!("cannot start {}: {e}", program.to_string_lossy())),
    };
    let root = child.id();
    let mut why: Option<String> = None;
    let status = loop {
        match child.try_wait() {
            Ok(Some(status)) => break Some(status),
            Ok(None) => {}
            Err(_) => break None,
        }
        if why.is_none() {
            let all = processes();
            let over = descendants(&all, root).into_iter().find_map(|p| {
                let s = all.get(&p)?;
                if s.cpu > limits.cpu {
                    Some(format!(
                        "`{}` after {:.0} s of CPU, its limit",
                        s.name,
                        limits.cpu.as_secs_f64()
                    ))
                } else if s.memory > limits.memory {
                    Some(format!(
                        "`{}` at {:.1} GiB of memory, its limit",
                        s.name,
                        limits.memory as f64 / f64::from(1u32 << 30)
                    ))
                } else {
                    None
                }
            });
            if let Some(w) = over {
                // the whole build ends: the compiler stopped, nothing else of it is worth its time
                for p in descendants(&all, root).into_iter().rev() {
                    let _ = Command::new("kill")
                        .args(["-KILL", &p.to_string()])
                        .stderr(Stdio::null())
                        .status();
                }
                eprintln!("{STOPPED} {w}");
                why = Some(w);
            }
        }
        std::thread::sleep(Duration::from_millis(200));
    };
    if why.is_some() {
        return ExitCode::from(1);
    }
    match status.and_then(|s| s.code()) {
        Some(0) => ExitCode::SUCCESS,
        Some(c) => ExitCode::from(u8::try_from(c).unwrap_or(1)),
        None => ExitCode::from(1),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The watch reads this very process from `/proc`: its parent, its name, some memory.
    #[test]
    fn the_watch_reads_a_process_from_proc() {
        let all = processes();
        let me = all.get(&std::process::id()).expect("this process in /proc");
        assert!(me.memory > 1 << 20, "{} bytes", me.memory);
        assert_eq!(me.parent, std::os::unix::process::parent_id());
        assert!(descendants(&all, me.parent).contains(&std::process::id()));
    }

    /// A program that spins past its CPU limit is ended, and the line says why; one that ends
    /// in time keeps its own status.
    #[test]
    fn a_process_past_its_cpu_limit_is_stopped() {
        let spin = [
            "--cpu-ms",
            "300",
            "--memory",
            "4000000000",
            "--",
            "sh",
            "-c",
            "while :; do :; done",
        ]
        .map(OsString::from);
        assert_eq!(run(&spin), ExitCode::from(1));
        let quick = [
            "--cpu-ms",
            "5000",
            "--memory",
            "4000000000",
            "--",
            "sh",
            "-c",
            "exit 3",
        ]
        .map(OsString::from);
        assert_eq!(run(&quick), ExitCode::from(3));
        assert_eq!(
            stopped("x\nwhitted compile-watch: stopped `rustc` after 120 s of CPU, its limit\n")
                .as_deref(),
            Some("`rustc` after 120 s of CPU, its limit")
        );
    }
}
