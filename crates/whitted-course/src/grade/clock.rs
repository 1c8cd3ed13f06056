//! A test's time limit counted in CPU time, so that a busy machine fails no correct test.
//!
//! nextest starts each of the judge's tests through `whitted test-clock` ([`COMMAND`], its
//! target runner). The clock runs the test and reads the test's processes from `/proc` ten
//! times a second: the judge's test and everything it started, the student's server in its
//! sandbox included, each counted with the children it has waited for. The test is stopped
//! when that CPU time (user and system) passes its limit, and the line it leaves says so
//! ([`STOPPED`]: "stopped after 20 s of CPU"). A machine shared with other work makes a test
//! slower, not costlier, so the limit is the same on a loaded machine as on an idle one.
//!
//! A test that waits without computing (a body that sleeps, or blocks on a pipe) spends no
//! CPU time; it is stopped on the wall clock after [`WAIT_TIMES`] its CPU limit, stretched
//! by how busy the machine was while it ran (the mean number of running processes a core,
//! from `/proc/stat`), so that waiting for a turn on a busy machine is never taken for
//! waiting on purpose.
//!
//! A test whose process, or the student's, was killed by `SIGKILL` without the clock's doing
//! (the machine's out-of-memory killer, an administrator, another program's clean-up) runs
//! once more; its output says so. What the first run printed is dropped.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ffi::OsString;
use std::io::{Read, Write};
use std::path::Path;
use std::process::{Command, ExitCode, ExitStatus, Stdio};
use std::sync::mpsc;
use std::time::{Duration, Instant};

use super::sandbox::watch::{descendants, processes};

/// The hidden command of `whitted` that nextest starts each test through.
pub const COMMAND: &str = "test-clock";

/// How the line that says a test was stopped at its limit begins (on the test's stderr).
pub const STOPPED: &str = "whitted test-clock: stopped after ";

/// How the line that says a test ran again begins.
pub const RAN_AGAIN: &str = "whitted test-clock: ran again";

/// How many times its CPU limit a test may run on the wall clock on an idle machine.
pub const WAIT_TIMES: u32 = 2;

/// How often the clock reads the test's processes.
const TICK: Duration = Duration::from_millis(100);

/// The most of each of a test's outputs the clock keeps, in bytes (the judge prints a few
/// lines; the student's output is cut by the sandbox's runner).
const OUTPUT_CAP: u64 = 1 << 20;

/// What the judge's line or the exit status says of a process killed by `SIGKILL`.
const KILLED: &str = "signal: 9 (SIGKILL)";

/// The environment that makes nextest start every test binary through the clock: the
/// runner setting of the host's target `triple`, with the CPU limit of a test of an exercise
/// (`cpu`) and how many times that a test of no exercise gets (`road_times`). `Err` when
/// `whitted`'s path has a space, which cargo's runner setting cannot hold.
pub fn runner_env(
    whitted: &Path,
    triple: &str,
    cpu: Duration,
    road_times: u32,
) -> Result<Vec<(OsString, OsString)>, String> {
    let path = whitted.to_string_lossy();
    if path.contains(char::is_whitespace) {
        return Err(format!(
            "{path} has a space in its path, which cargo's runner setting cannot hold"
        ));
    }
    let var = format!(
        "CARGO_TARGET_{}_RUNNER",
        triple.to_uppercase().replace(['-', '.'], "_")
    );
    let line = format!(
        "{path} {COMMAND} --cpu-ms {} --road-times {road_times}",
        cpu.as_millis()
    );
    Ok(vec![(var.into(), line.into())])
}

/// The CPU limit of the test that libtest's arguments `args` run: `cpu` for a test of an
/// exercise (its name has an `ex_` segment), `road_times` that for the others, which judge
/// the student's whole road.
fn limit_of(args: &[OsString], cpu: Duration, road_times: u32) -> Duration {
    let of_exercise = super::runner::test_of(args)
        .is_some_and(|name| name.split("::").any(|part| part.starts_with("ex_")));
    if of_exercise { cpu } else { cpu * road_times }
}

/// The CPU time of `root` and everything it started that is still running, each with the
/// children it has waited for.
fn tree_cpu(root: u32) -> Duration {
    let all = processes();
    descendants(&all, root)
        .iter()
        .filter_map(|p| all.get(p))
        .map(|s| s.cpu + s.children_cpu)
        .sum()
}

/// How many processes are running on the machine now (`procs_running` of `/proc/stat`).
fn running_now() -> Option<f64> {
    let stat = std::fs::read_to_string("/proc/stat").ok()?;
    stat.lines()
        .find_map(|l| l.strip_prefix("procs_running "))
        .and_then(|n| n.trim().parse::<f64>().ok())
}

/// Ends `root` and everything it started.
fn kill_tree(root: u32) {
    let all = processes();
    let pids: Vec<String> = descendants(&all, root)
        .into_iter()
        .map(|p| p.to_string())
        .collect();
    let _ = Command::new("kill")
        .arg("-KILL")
        .args(&pids)
        .stdin(Stdio::null())
        .stderr(Stdio::null())
        .status();
}

/// How one run of a test ended.
enum End {
    /// On its own, with this status.
    Exited(ExitStatus),
    /// Stopped: the line that says why.
    Stopped(String),
}

/// One run of a test: how it ended and what it printed.
struct Run {
    end: End,
    stdout: Vec<u8>,
    stderr: Vec<u8>,
}

impl Run {
    /// Whether the test or the student's process died by `SIGKILL` without the clock's doing.
    fn killed_from_outside(&self) -> bool {
        use std::os::unix::process::ExitStatusExt;
        match &self.end {
            End::Exited(status) => {
                status.signal() == Some(9)
                    || String::from_utf8_lossy(&self.stderr).contains(KILLED)
                    || String::from_utf8_lossy(&self.stdout).contains(KILLED)
            }
            End::Stopped(_) => false,
        }
    }
}

/// Reads `from` to its end (at most [`OUTPUT_CAP`] bytes kept) on a thread of its own.
fn collect(from: Option<impl Read + Send + 'static>) -> mpsc::Receiver<Vec<u8>> {
    let (send, receive) = mpsc::channel();
    if let Some(from) = from {
        std::thread::spawn(move || {
            let mut kept = Vec::new();
            let mut from = from;
            let _ = from.by_ref().take(OUTPUT_CAP).read_to_end(&mut kept);
            // the rest is read and dropped, so that the test never blocks on a full pipe
            let _ = std::io::copy(&mut from, &mut std::io::sink());
            let _ = send.send(kept);
        });
    }
    receive
}

/// Runs `program` with `args` once under `cpu`, the wall clock's limit stretched by the load.
fn run_once(program: &OsString, args: &[OsString], cpu: Duration) -> Result<Run, String> {
    let mut child = Command::new(program)
        .args(args)
        .stdin(Stdio::null())
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
        .map_err(|e| format!("cannot start {}: {e}", program.to_string_lossy()))?;
    let root = child.id();
    let stdout = collect(child.stdout.take());
    let stderr = collect(child.stderr.take());
    let (done, ended) = mpsc::channel();
    std::thread::spawn(move || {
        let _ = done.send(child.wait());
    });
    let started = Instant::now();
    let cores = std::thread::available_parallelism().map_or(1.0, |n| n.get() as f64);
    let (mut load_sum, mut looks) = (0.0, 0u32);
    let mut stopped = None;
    let status = loop {
        match ended.recv_timeout(TICK) {
            Ok(waited) => break waited.map_err(|e| format!("waiting for the test: {e}"))?,
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                return Err("the test's waiter ended without a word".into());
            }
            Err(mpsc::RecvTimeoutError::Timeout) => {}
        }
        if stopped.is_some() {
            continue;
        }
        let used = tree_cpu(root);
        if let Some(n) = running_now() {
            load_sum += n / cores;
            looks += 1;
        }
        let busy = if looks == 0 {
            1.0
        } else {
            (load_sum / f64::from(looks)).max(1.0)
        };
        let waited = started.elapsed();
        let wall = cpu.mul_f64(f64::from(WAIT_TIMES) * busy);
        let why = if used > cpu {
            Some(format!(
                "{STOPPED}{:.0} s of CPU, its limit ({:.0} s on the clock): an endless loop, or far too slow",
                cpu.as_secs_f64(),
                waited.as_secs_f64()
            ))
        } else if waited > wall {
            Some(format!(
                "{STOPPED}{:.0} s on the clock with {:.1} s of CPU: the test waits without computing (its limit on the clock is {WAIT_TIMES} times its {:.0} s of CPU, {busy:.1} times longer on this machine's load)",
                waited.as_secs_f64(),
                used.as_secs_f64(),
                cpu.as_secs_f64()
            ))
        } else {
            None
        };
        if let Some(why) = why {
            kill_tree(root);
            stopped = Some(why);
        }
    };
    // a process the test left may hold its output open: what arrived within a moment is kept
    let take =
        |r: mpsc::Receiver<Vec<u8>>| r.recv_timeout(Duration::from_secs(2)).unwrap_or_default();
    Ok(Run {
        end: stopped.map_or(End::Exited(status), End::Stopped),
        stdout: take(stdout),
        stderr: take(stderr),
    })
}

/// Ends this process as the test's did: by the same signal when a signal ended it.
fn end_as(status: ExitStatus) -> ExitCode {
    use std::os::unix::process::ExitStatusExt;
    if let Some(signal) = status.signal() {
        super::runner::die_by(signal);
    }
    ExitCode::from(u8::try_from(status.code().unwrap_or(1)).unwrap_or(1))
}

/// `whitted test-clock --cpu-ms N --road-times K PROGRAM ARGS…`: runs the test binary
/// `PROGRAM` with libtest's `ARGS` under its CPU limit (see the module's documentation);
/// ends as the test did, or with 1 when the clock stopped it.
#[must_use]
pub fn run(args: &[OsString]) -> ExitCode {
    let fail = |why: &str| {
        eprintln!("whitted {COMMAND}: {why}");
        ExitCode::from(2)
    };
    let words: Vec<&str> = args.iter().map(|a| a.to_str().unwrap_or("")).collect();
    // the grader writes the flags first, in this order; the test's own arguments follow
    let number = |at: usize, flag: &str| -> Option<u64> {
        (words.get(at) == Some(&flag))
            .then(|| words.get(at + 1)?.parse().ok())
            .flatten()
    };
    let (Some(cpu_ms), Some(road_times)) = (number(0, "--cpu-ms"), number(2, "--road-times"))
    else {
        return fail("`--cpu-ms N --road-times K` come first");
    };
    let Some((program, rest)) = args.get(4..).and_then(<[OsString]>::split_first) else {
        return fail("no test binary to run");
    };
    let cpu = limit_of(
        rest,
        Duration::from_millis(cpu_ms),
        u32::try_from(road_times).unwrap_or(1),
    );
    let mut first = match run_once(program, rest, cpu) {
        Ok(r) => r,
        Err(e) => return fail(&e),
    };
    let mut again = false;
    if first.killed_from_outside() {
        again = true;
        first = match run_once(program, rest, cpu) {
            Ok(r) => r,
            Err(e) => return fail(&e),
        };
    }
    let _ = std::io::stdout().write_all(&first.stdout);
    let _ = std::io::stderr().write_all(&first.stderr);
    if again {
        eprintln!(
            "{RAN_AGAIN}: its first run was killed by SIGKILL from outside it, not at its limit"
        );
    }
    match first.end {
        End::Exited(status) => end_as(status),
        End::Stopped(why) => {
            eprintln!("{why}");
            ExitCode::from(1)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(w: &[&str]) -> Vec<OsString> {
        w.iter().map(OsString::from).collect()
    }

    /// A test of an exercise gets the limit, any other the road's multiple of it.
    #[test]
    fn a_test_of_no_exercise_gets_the_roads_limit() {
        let cpu = Duration::from_secs(20);
        let ex = words(&["sphere::ex_sphere_discriminant_x", "--exact", "--nocapture"]);
        let road = words(&["render_paths::chapter_3_matches", "--exact"]);
        assert_eq!(limit_of(&ex, cpu, 3), cpu);
        assert_eq!(limit_of(&road, cpu, 3), Duration::from_secs(60));
    }

    /// A program that spins is stopped at its CPU limit, and the line says so; one that ends
    /// in time keeps its own status.
    #[test]
    fn a_spinning_test_is_stopped_at_its_cpu_limit() {
        let spin = run_once(
            &"sh".into(),
            &words(&["-c", "while :; do :; done"]),
            Duration::from_millis(400),
        )
        .unwrap();
        match &spin.end {
            End::Stopped(why) => assert!(
                why.starts_with(STOPPED) && why.contains("s of CPU, its limit"),
                "{why}"
            ),
            End::Exited(s) => panic!("the spinning program ended on its own: {s}"),
        }
        let quick = run_once(
            &"sh".into(),
            &words(&["-c", "echo out; echo err >&2; exit 3"]),
            Duration::from_secs(5),
        )
        .unwrap();
        match quick.end {
            End::Exited(s) => assert_eq!(s.code(), Some(3)),
            End::Stopped(why) => panic!("stopped: {why}"),
        }
        assert_eq!(quick.stdout, b"out\n");
        assert_eq!(quick.stderr, b"err\n");
    }

    /// A program that sleeps spends no CPU time: the wall clock stops it, and says that it
    /// waited.
    #[test]
    fn a_waiting_test_is_stopped_on_the_clock() {
        let sleeper = run_once(
            &"sh".into(),
            &words(&["-c", "sleep 30"]),
            Duration::from_millis(300),
        )
        .unwrap();
        match &sleeper.end {
            End::Stopped(why) => assert!(why.contains("waits without computing"), "{why}"),
            End::Exited(s) => panic!("the sleeper ended on its own: {s}"),
        }
    }

    /// A test killed by SIGKILL, or whose student's process the judge says was, is one
    /// killed from outside; one stopped by the clock or failing on its own is not.
    #[test]
    fn a_kill_from_outside_is_told_from_a_failure() {
        let killed = run_once(
            &"sh".into(),
            &words(&["-c", "kill -KILL $$"]),
            Duration::from_secs(5),
        )
        .unwrap();
        assert!(killed.killed_from_outside());
        let said = run_once(
            &"sh".into(),
            &words(&[
                "-c",
                "echo 'whitted judge: the student'\\''s process died (signal: 9 (SIGKILL)): the test fails' >&2; exit 101",
            ]),
            Duration::from_secs(5),
        )
        .unwrap();
        assert!(said.killed_from_outside());
        let failed = run_once(
            &"sh".into(),
            &words(&["-c", "echo 'assertion failed' >&2; exit 101"]),
            Duration::from_secs(5),
        )
        .unwrap();
        assert!(!failed.killed_from_outside());
    }
}
