//! The runner (`whitted sandbox-run`): a program of the student's run in the grader's sandbox.
//! `whitted grade` starts each submission's server through it ([`SERVE`], below): the judge,
//! outside the sandbox, decides every test. Given a test binary instead, as nextest's target
//! runner (a test suite that runs the student's code in its own process), it decides whether a
//! test's end was earned, as well as a process that runs the student's code can.
//!
//! nextest counts a test process that exits with status 0 as a pass. A body that ends its
//! process early (`exit(0)`, `exec`, a signal handler) would pass every test that calls it, so
//! the runner asks more of a pass:
//!
//! - **libtest's word.** The test runs with its output captured by libtest (the runner drops
//!   nextest's `--nocapture`), so that `print!` from the student's code never reaches the
//!   process's standard output while the test passes; what does reach it is libtest's own
//!   report. The runner passes the test only when the process exited with status 0 *and*
//!   libtest reported `test NAME ... ok` for that very test, which it does after the test
//!   function returned: after every assertion ran. Anything else with status 0 is a failure
//!   that says so ([`verdict`]). Writing that line without `print!` takes `std::io`, a file
//!   descriptor or `unsafe`, which the screen refuses ([`mod@super::screen`]).
//! - **Nothing outlives the test.** The runner ends the test itself a moment before nextest's
//!   time limit, and at the user level ends every process of the test's user and removes what
//!   that user left in the shared temporary directories when the test ends, however it ends.
//! - **A room of its own.** Each run gets an empty temporary directory (`TMPDIR`, `HOME`),
//!   removed afterwards; in namespaces its `/tmp` is a private file system.
//! - **Output that is safe to quote.** Its standard output and error reach nextest cleaned
//!   ([`super::clean`]) and cut at the policy's size.
//!
//! With [`SERVE`] first (`whitted sandbox-run --serve SERVER`) it runs instead the server of
//! the judge outside the student's process (the renderer's `judge` module) in the same
//! sandbox, its standard input and output the judge's pipes.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::ffi::{OsStr, OsString};
use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Command, ExitCode, Stdio};
use std::time::{Duration, Instant};

use super::clean::Cleaner;
use super::sandbox::{Level, POLICY_VAR, Policy, RUNNER_COMMAND, SLOT_VAR};

/// How each line the runner adds to a test's output begins: the reports quote it as the
/// test's message.
pub const RUNNER_MARK: &str = "whitted sandbox-run:";

/// How long before nextest's time limit the runner stops a test itself, so that it ends the
/// test's processes before nextest ends the runner.
const STOP_BEFORE: Duration = Duration::from_millis(300);

/// The test that a libtest command line runs (`NAME --exact`), or `None` for a listing
/// (`--list`) or a line that names no single test.
#[must_use]
pub fn test_of(args: &[OsString]) -> Option<String> {
    let words: Vec<&str> = args.iter().filter_map(|a| a.to_str()).collect();
    if words.contains(&"--list") || !words.contains(&"--exact") {
        return None;
    }
    words
        .iter()
        .find(|w| !w.starts_with('-'))
        .map(|w| (*w).to_string())
}

/// libtest's arguments with the options that turn its capture off removed: the student's
/// `print!` then goes to libtest's buffer, shown only with a failure.
fn captured(args: &[OsString]) -> Vec<OsString> {
    args.iter()
        .filter(|a| !matches!(a.to_str(), Some("--nocapture" | "--no-capture")))
        .cloned()
        .collect()
}

/// Whether a test's end is a pass: `Ok` when its process exited with `status` 0 and libtest
/// reported it `ok` (`reported_ok`), or when it failed (its status stands, non-zero);
/// `Err` with the reason when it exited with 0 but libtest never said so: the process was
/// ended before its assertions finished.
pub fn verdict(status: i32, test: Option<&str>, reported_ok: bool) -> Result<(), String> {
    match test {
        Some(name) if status == 0 && !reported_ok => Err(format!(
            "{RUNNER_MARK} the test's process ended with status 0, but libtest never reported `test {name} ... ok`: the process was ended before the test's assertions finished (a body that exits, execs or kills its own process passes nothing)"
        )),
        _ => Ok(()),
    }
}

/// Watches a test's standard output for libtest's line `test NAME ... ok`.
struct Watch {
    /// The line that reports the test passed.
    wanted: String,
    /// The line read so far.
    line: String,
    /// Whether the line came.
    seen: bool,
}

impl Watch {
    fn new(name: &str) -> Self {
        Self {
            wanted: format!("test {name} ... ok"),
            line: String::new(),
            seen: false,
        }
    }

    fn feed(&mut self, text: &str) {
        for c in text.chars() {
            if c == '\n' {
                self.seen |= self.line.trim_end() == self.wanted;
                self.line.clear();
            } else if self.line.len() <= self.wanted.len() + 2 {
                self.line.push(c);
            }
        }
    }

    fn finish(&mut self) -> bool {
        self.seen |= self.line.trim_end() == self.wanted;
        self.seen
    }
}

/// Copies what `from` gives to `to`, cleaned ([`super::clean`]) and at most `cap` bytes: its
/// first half as it comes, then, when there was more, a line saying how much was cut and the
/// last half (where a panic's message is). Reads to the end either way, so the writer is
/// never blocked, and holds at most `cap / 2` bytes. `watch` sees all of it.
fn relay(mut from: impl Read, mut to: impl Write, cap: u64, mut watch: Option<&mut Watch>) {
    let half = usize::try_from(cap / 2).unwrap_or(usize::MAX);
    let mut head = 0usize;
    let mut tail: std::collections::VecDeque<u8> = std::collections::VecDeque::new();
    let mut dropped = 0u64;
    let mut buf = [0u8; 16 * 1024];
    let mut cleaner = Cleaner::default();
    loop {
        let (text, done) = match from.read(&mut buf) {
            Ok(0) | Err(_) => (cleaner.finish(), true),
            Ok(n) => (cleaner.feed(&buf[..n]), false),
        };
        if let Some(w) = watch.as_deref_mut() {
            w.feed(&text);
        }
        let bytes = text.as_bytes();
        let take = bytes.len().min(half - head);
        if take > 0 {
            let _ = to.write_all(&bytes[..take]);
            let _ = to.flush();
            head += take;
        }
        tail.extend(&bytes[take..]);
        if tail.len() > half {
            let extra = tail.len() - half;
            tail.drain(..extra);
            dropped += extra as u64;
        }
        if done {
            break;
        }
    }
    if dropped > 0 {
        let _ = writeln!(to, "\n[whitted: {dropped} bytes of output cut here]");
    }
    let (a, b) = tail.as_slices();
    let _ = to.write_all(a);
    let _ = to.write_all(b);
    let _ = to.flush();
}

/// The run's own temporary directory, owned by the test's user at the user level; `None` in
/// namespaces, where `/tmp` is already the run's own.
fn private_tmp(policy: &Policy) -> Result<Option<tempfile::TempDir>, String> {
    if policy.level == Level::Namespaces {
        return Ok(None);
    }
    let dir = tempfile::Builder::new()
        .prefix("whitted-test-")
        .tempdir()
        .map_err(|e| format!("cannot make the test's temporary directory: {e}"))?;
    if let (Level::User, Some(uid)) = (policy.level, policy.uid) {
        use std::os::unix::fs::PermissionsExt;
        let user = uid + policy.slot % super::sandbox::SLOTS;
        std::os::unix::fs::chown(dir.path(), Some(user), Some(uid))
            .and_then(|()| {
                std::fs::set_permissions(dir.path(), std::fs::Permissions::from_mode(0o700))
            })
            .map_err(|e| format!("{}: {e}", dir.path().display()))?;
    }
    Ok(Some(dir))
}

/// The runner's first word that makes it run the server of the grader's wire instead of a
/// test, in the same sandbox, its standard input and output the judge's pipes.
pub const SERVE: &str = "--serve";

/// The sandbox's policy from [`POLICY_VAR`], its slot set from nextest's: a test has a slot
/// no other running test has; a listing of the tests (`--list`) has none, and runs beside the
/// other listings.
fn policy_of_env() -> Result<(Policy, Option<u32>), String> {
    let mut policy: Policy = std::env::var(POLICY_VAR)
        .map_err(|e| e.to_string())
        .and_then(|t| serde_json::from_str(&t).map_err(|e| e.to_string()))
        .map_err(|e| format!("no sandbox policy in {POLICY_VAR}: {e}"))?;
    let slot: Option<u32> = std::env::var(SLOT_VAR).ok().and_then(|s| s.parse().ok());
    policy.slot = slot.unwrap_or(0);
    Ok((policy, slot))
}

/// Runs the student's server of the grader's wire (`sandbox-run --serve SERVER ARGS…`,
/// started by the judge's test process, whose slot it inherits) in the sandbox of
/// [`POLICY_VAR`]: its standard input and output are the judge's pipes, passed through
/// untouched; its standard error arrives cleaned and cut at the policy's size. Nothing it
/// prints is a verdict: the judge decides on the values that cross. When it ends, every
/// process of its user ends too and its temporary directory is removed; it ends as the
/// server ended, by the same signal when it died by one (the judge then reports a crash). Its time is the judge's test's: when that test is stopped, so is this.
fn serve(command: &[OsString]) -> ExitCode {
    let fail = |why: String| {
        eprintln!("whitted {RUNNER_COMMAND} {SERVE}: {why}");
        ExitCode::from(2)
    };
    let Some((bin, args)) = command.split_first() else {
        return fail("no server to run".into());
    };
    let (policy, slot) = match policy_of_env() {
        Ok(p) => p,
        Err(e) => return fail(e),
    };
    let tmp = match private_tmp(&policy) {
        Ok(t) => t,
        Err(e) => return fail(e),
    };
    // the judge's working directory is inside its copy, closed to the sandbox's user: the
    // server starts in its temporary directory instead
    let cwd = PathBuf::from("/tmp");
    let mut command = policy.command(Path::new(bin), &cwd);
    command.current_dir(&cwd);
    if let Some(t) = &tmp {
        command.env("TMPDIR", t.path()).env("HOME", t.path());
    }
    let mut child = match command
        .args(args)
        .stdin(Stdio::inherit())
        .stdout(Stdio::inherit())
        .stderr(Stdio::piped())
        .spawn()
    {
        Ok(c) => c,
        Err(e) => return fail(format!("cannot start the sandbox: {e}")),
    };
    // a process the server left behind may hold its standard error open: the server is
    // waited for first, what it left is ended, and only then is its error read to the end
    let err = child.stderr.take();
    let waited = std::thread::scope(|s| {
        let reader =
            err.map(|err| s.spawn(|| relay(err, std::io::stderr(), policy.limits.output, None)));
        let waited = child.wait();
        wind_up(&policy, slot, reader);
        waited
    });
    drop(tmp);
    match waited {
        Ok(status) => {
            if let Some(signal) = signal_of(status) {
                die_by(signal);
            }
            ExitCode::from(u8::try_from(status.code().unwrap_or(1)).unwrap_or(1))
        }
        Err(e) => fail(format!("waiting for the sandbox: {e}")),
    }
}

/// The signal that ended a sandboxed process of `status`, when one did (bubblewrap ends with
/// 128 + N when its child was killed by signal N).
fn signal_of(status: std::process::ExitStatus) -> Option<i32> {
    use std::os::unix::process::ExitStatusExt;
    status.signal().or_else(|| {
        status
            .code()
            .filter(|c| (129..=128 + 31).contains(c))
            .map(|c| c - 128)
    })
}

/// Ends this process by `signal`, as the sandboxed process ended, so that whoever waits for
/// it sees a crash (when the signal does not end it, the caller goes on).
pub(super) fn die_by(signal: i32) {
    let signal = signal.to_string();
    let _ = Command::new("kill")
        .args([OsStr::new("-s"), OsStr::new(&signal)])
        .arg(std::process::id().to_string())
        .status();
    std::thread::sleep(Duration::from_millis(200));
}

/// What follows the end of a sandboxed process: with a slot, every process its user left is
/// ended, which closes the output such a process may hold open; then that output is read to
/// its end (`reader`).
fn wind_up(
    policy: &Policy,
    slot: Option<u32>,
    reader: Option<std::thread::ScopedJoinHandle<'_, ()>>,
) {
    if slot.is_some() {
        policy.sweep();
    }
    if let Some(r) = reader {
        let _ = r.join();
    }
}

/// The target runner: runs the test binary `command[0]` with its arguments in the sandbox
/// that [`POLICY_VAR`] describes, passes its output on (cleaned, cut at the policy's size),
/// and ends as it ended (by the same signal when it was killed, so that nextest sees a
/// crash), except that a test whose process exited with 0 before libtest reported it `ok`
/// fails ([`verdict`]).
#[must_use]
pub fn run_test(command: &[OsString]) -> ExitCode {
    let fail = |why: String| {
        eprintln!("whitted {RUNNER_COMMAND}: {why}");
        ExitCode::from(2)
    };
    let Some((bin, args)) = command.split_first() else {
        return fail("no test binary to run".into());
    };
    if bin == SERVE {
        return serve(args);
    }
    let (policy, slot) = match policy_of_env() {
        Ok(p) => p,
        Err(e) => return fail(e),
    };
    let test = test_of(args);
    let args = if test.is_some() {
        captured(args)
    } else {
        args.to_vec()
    };
    let tmp = match private_tmp(&policy) {
        Ok(t) => t,
        Err(e) => return fail(e),
    };
    let bin = Path::new(bin);
    let cwd = std::env::current_dir().unwrap_or_else(|_| PathBuf::from("/tmp"));
    let mut command = policy.command(bin, &cwd);
    if let Some(t) = &tmp {
        command.env("TMPDIR", t.path()).env("HOME", t.path());
    }
    // the test's name, which the judge reads to know which exercise it judges
    if let Some(name) = &test {
        command.env(super::alone::GRADED_TEST_VAR, name);
    }
    let mut child = match command
        .args(&args)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped())
        .spawn()
    {
        Ok(c) => c,
        Err(e) => return fail(format!("cannot start the sandbox: {e}")),
    };
    let cap = policy.limits.output;
    let (out, err) = (child.stdout.take(), child.stderr.take());
    let deadline = policy
        .timeout_ms
        .filter(|_| test.is_some())
        .map(|ms| Instant::now() + Duration::from_millis(ms).saturating_sub(STOP_BEFORE));
    let mut watch = test.as_deref().map(Watch::new);
    let mut stopped = false;
    // the output is read while the test runs; once it ends (or its time is up), what it left
    // behind is ended too, which closes the output a left-over child may hold open
    let waited = std::thread::scope(|s| {
        if let Some(err) = err {
            s.spawn(move || relay(err, std::io::stderr(), cap, None));
        }
        let watching = watch.as_mut();
        let reader = out.map(|out| s.spawn(move || relay(out, std::io::stdout(), cap, watching)));
        // the test is waited for by a thread of its own, so that its end is seen at once (a
        // poll would add its period to every test) and its time limit by this one
        let pid = child.id();
        let (done, ended) = std::sync::mpsc::channel();
        s.spawn(move || {
            let _ = done.send(child.wait());
        });
        let waited = match deadline {
            None => ended
                .recv()
                .unwrap_or_else(|e| Err(std::io::Error::other(e))),
            Some(d) => match ended.recv_timeout(d.saturating_duration_since(Instant::now())) {
                Ok(w) => w,
                Err(_) => {
                    stopped = true;
                    // not yet collected by the waiter, so the process id is still the test's
                    let _ = Command::new("kill")
                        .args(["-KILL", &pid.to_string()])
                        .stdin(Stdio::null())
                        .stderr(Stdio::null())
                        .status();
                    policy.sweep();
                    ended
                        .recv()
                        .unwrap_or_else(|e| Err(std::io::Error::other(e)))
                }
            },
        };
        wind_up(&policy, slot, reader);
        waited
    });
    drop(tmp);
    if stopped {
        eprintln!(
            "{RUNNER_MARK} stopped at the time limit; the test and every process it started were ended"
        );
        // nextest's own limit comes within a moment and records the time-out
        std::thread::sleep(STOP_BEFORE * 20);
        return ExitCode::from(1);
    }
    let status = match waited {
        Ok(s) => s,
        Err(e) => return fail(format!("waiting for the sandbox: {e}")),
    };
    let code = status.code().unwrap_or(1);
    if let Some(signal) = signal_of(status) {
        die_by(signal);
    }
    let reported_ok = watch.as_mut().is_some_and(Watch::finish);
    if let Err(why) = verdict(code, test.as_deref(), reported_ok) {
        eprintln!("{why}");
        return ExitCode::from(1);
    }
    ExitCode::from(u8::try_from(code).unwrap_or(1))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn words(w: &[&str]) -> Vec<OsString> {
        w.iter().map(OsString::from).collect()
    }

    /// nextest's command line for one test names it; a listing names none.
    #[test]
    fn the_test_is_read_from_libtests_command_line() {
        let one = words(&["sphere::ex_hit_sphere_misses", "--exact", "--nocapture"]);
        assert_eq!(
            test_of(&one).as_deref(),
            Some("sphere::ex_hit_sphere_misses")
        );
        assert_eq!(test_of(&words(&["--list", "--format", "terse"])), None);
        assert_eq!(
            captured(&one),
            words(&["sphere::ex_hit_sphere_misses", "--exact"])
        );
    }

    /// Status 0 is a pass only with libtest's `ok`; a failure stays a failure.
    #[test]
    fn status_zero_without_libtests_ok_fails() {
        let why = verdict(0, Some("t"), false).unwrap_err();
        assert!(
            why.starts_with(RUNNER_MARK) && why.contains("`test t ... ok`"),
            "{why}"
        );
        assert_eq!(verdict(0, Some("t"), true), Ok(()));
        assert_eq!(verdict(101, Some("t"), false), Ok(()));
        assert_eq!(verdict(0, None, false), Ok(()));
    }

    /// The line must be libtest's for this test, whole, at a line's start; the output is
    /// cleaned on its way, and a forged line of another test does not count.
    #[test]
    fn only_libtests_line_for_this_test_counts() {
        let cases = [
            ("running 1 test\ntest a::b ... ok\n\ntest result: ok.", true),
            ("test a::b ... ok", true),
            ("test a::bc ... ok\n", false),
            ("xtest a::b ... ok\n", false),
            ("test a::b ... FAILED\n", false),
            ("test a::b ... ok but not\n", false),
        ];
        for (text, seen) in cases {
            let mut w = Watch::new("a::b");
            let mut out = Vec::new();
            relay(text.as_bytes(), &mut out, 1 << 16, Some(&mut w));
            assert_eq!(w.finish(), seen, "{text:?}");
            assert_eq!(String::from_utf8(out).unwrap(), text);
        }
    }

    /// Output past the cap keeps its head and its tail, with a line that says what was cut;
    /// bytes that would break a report arrive escaped.
    #[test]
    fn output_is_cleaned_and_capped() {
        let text = format!("{}\u{202e}end", "x".repeat(100));
        let mut out = Vec::new();
        relay(text.as_bytes(), &mut out, 40, None);
        let out = String::from_utf8(out).unwrap();
        assert!(out.starts_with(&"x".repeat(20)), "{out}");
        assert!(out.ends_with("\\u{202e}end"), "{out}");
        assert!(out.contains("bytes of output cut here"), "{out}");
    }
}
