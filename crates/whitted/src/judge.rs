//! The grader's wire (no chapter adds it; `whitted grade` writes the code that uses it): an
//! exercise judged from outside the process that runs the student's body.
//!
//! The grader builds a project twice. The **judge** is the instructor's crate with its tests,
//! public and hidden: the expected values, the comparisons, the verdict. The **server** is the
//! student's crate: the student's bodies and no reference body. In both, the grader puts a stub
//! first in each exercise's function, on the line of its `{`, and a table in `lib.rs`:
//!
//! ```text
//! pub fn discriminant(ray: &Ray, a: Real, b: Real) -> Real {if crate::judged::remote(12) { return crate::judged::call(12, &(ray, a, b)); }
//! ```
//!
//! In the judge, the exercise a test is named after (`ex_NAME_…`, in [`TEST_VAR`] or on
//! libtest's command line) is remote: its arguments cross to the server, which runs the
//! student's body and sends back the value it returned; any other test, and every test with
//! [`WHOLE_ROAD_VAR`], runs every exercise on the server (the student's whole road). In
//! the server, every exercise that the judge did not name is remote: the student's body asks
//! the judge for the reference's value. Each side answers the other's calls while it waits for
//! its own answer, so calls nest as deeply as the functions do.
//!
//! What this guarantees: the judge runs no student code, and the server holds no reference
//! body, so it can neither call the reference's code for its exercise nor read it. Whatever the
//! server does to its own process — print libtest's lines, exit with 0, write files — the judge
//! sees only frames on a pipe: a value of the function's type is judged by the test's own
//! assertions, and anything else (no frame, a frame that is no such value, the process ended)
//! fails the test that asked.
//!
//! The wire is the server's standard input and output. A frame is a line: [`MAGIC`], then a
//! bincode payload (exact for every float, NaN and ∞ included) in base64, which holds no line
//! break, so the server's standard output writes a frame at once; what else the
//! server writes to its standard output is the student's own output, passed to the judge's
//! standard error beside the test's failure. A panic on either side crosses as a panic of the
//! call that caused it, with its message.
//!
//! Course book: [The instructor's guide](../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::io::{BufRead, BufReader, Write};
use std::panic::{AssertUnwindSafe, catch_unwind};
use std::process::{Child, Command, ExitCode, Stdio};
use std::sync::{Condvar, Mutex, MutexGuard, OnceLock, PoisonError};
use std::thread::ThreadId;

use serde::Serialize;
use serde::de::DeserializeOwned;

mod frame;

pub use frame::MAGIC;
use frame::{Capped, Frame, read_frame, write_frame};

/// The environment variable that gives the judge the server's command line, its words
/// separated by the unit separator `\x1f`. Without it the judge runs every exercise itself.
pub const SERVER_VAR: &str = "WHITTED_JUDGE_SERVER";

/// The environment variable in which the test runner names the test a process runs; without
/// it, the judge reads the name from libtest's command line (`NAME --exact`), as nextest and
/// `cargo test NAME -- --exact` give it.
pub const TEST_VAR: &str = "WHITTED_GRADED_TEST";

/// The environment variable that makes the judge send every exercise to the server, whichever
/// test runs: the student's whole road judged (`whitted grade --whole-road`).
pub const WHOLE_ROAD_VAR: &str = "WHITTED_JUDGE_WHOLE_ROAD";

/// How much of the server's own output the judge passes on.
const MAX_SPILL: usize = 64 << 10;

/// What a graded copy tells the wire: its exercises and how to run one here.
pub struct Table {
    /// Each exercise's test prefix (`ex_NAME_`), by the number its stubs call it.
    pub prefixes: &'static [&'static str],
    /// Runs exercise `n` in this process on its encoded arguments, and encodes its value.
    pub dispatch: fn(u16, &[u8]) -> Result<Vec<u8>, String>,
}

/// Which end of the wire this process is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Side {
    Judge,
    Server,
}

/// The pipe to the other side, and the server process when this side is the judge.
struct Link {
    to: Box<dyn Write + Send>,
    from: Box<dyn BufRead + Send>,
    child: Option<Child>,
    spilled: usize,
}

/// The process's end of the wire.
struct Wire {
    side: Side,
    /// By exercise number: whether its calls cross the wire.
    remote: Vec<bool>,
    link: Mutex<Option<Link>>,
    /// The thread holding the conversation, and how deeply its calls nest: a call from another
    /// thread waits for the conversation to end (the renderer's tiles call from many).
    owner: Mutex<Option<(ThreadId, usize)>>,
    free: Condvar,
}

static WIRE: OnceLock<Wire> = OnceLock::new();

fn lock<T>(m: &Mutex<T>) -> MutexGuard<'_, T> {
    m.lock().unwrap_or_else(PoisonError::into_inner)
}

/// Whether exercise `n`'s call crosses the wire in this process: the stub's question.
#[must_use]
pub fn remote(table: &'static Table, n: u16) -> bool {
    let wire = WIRE.get_or_init(|| judge_side(table));
    wire.remote.get(usize::from(n)).copied().unwrap_or(false)
}

/// The judge's end: which exercises cross, from the test's name; none without a server.
fn judge_side(table: &Table) -> Wire {
    let count = table.prefixes.len();
    let alone = std::env::var_os(WHOLE_ROAD_VAR).is_none();
    let remote = if std::env::var_os(SERVER_VAR).is_none() {
        vec![false; count]
    } else {
        let test = std::env::var(TEST_VAR)
            .ok()
            .or_else(|| test_of(std::env::args().skip(1)));
        match test.filter(|_| alone).and_then(|t| judged(table, &t)) {
            Some(x) => (0..count).map(|n| n == x).collect(),
            None => vec![true; count], // a test of no exercise: the student's whole road
        }
    };
    Wire {
        side: Side::Judge,
        remote,
        link: Mutex::new(None),
        owner: Mutex::new(None),
        free: Condvar::new(),
    }
}

/// The single test a libtest command line runs (`NAME --exact`, in any order), or `None`.
fn test_of(args: impl Iterator<Item = String>) -> Option<String> {
    let args: Vec<String> = args.collect();
    if !args.iter().any(|a| a == "--exact") || args.iter().any(|a| a == "--list") {
        return None;
    }
    // libtest's options that take the next word as their value
    const VALUED: [&str; 6] = [
        "--test-threads",
        "--skip",
        "--format",
        "--color",
        "--logfile",
        "-Z",
    ];
    let mut names = Vec::new();
    let mut words = args.into_iter();
    while let Some(w) = words.next() {
        if VALUED.contains(&w.as_str()) {
            words.next();
        } else if !w.starts_with('-') {
            names.push(w);
        }
    }
    let name = names.pop()?;
    names.is_empty().then_some(name)
}

/// The exercise a libtest name (`target::module::ex_NAME_sentence`) is named after.
fn judged(table: &Table, test: &str) -> Option<usize> {
    let own = test.rsplit("::").next().unwrap_or(test);
    table.prefixes.iter().position(|p| own.starts_with(p))
}

/// Exercise `n`'s value for `args`, computed on the other side of the wire: the stub's call.
/// A panic there is a panic here, with its message.
pub fn call<A: Serialize + ?Sized, R: DeserializeOwned>(
    table: &'static Table,
    n: u16,
    args: &A,
) -> R {
    call_pulling::<A, R, ()>(table, n, args, None)
}

/// [`call`] for a function that also takes an iterator, `items`: the other side pulls its
/// items one at a time, as the function asks for them ([`Pulled`]), so that an item it never
/// asks for is never made (`transmittance` stops at the first 0).
pub fn call_pulling<A, R, T>(
    table: &'static Table,
    n: u16,
    args: &A,
    items: Option<&mut dyn Iterator<Item = T>>,
) -> R
where
    A: Serialize + ?Sized,
    R: DeserializeOwned,
    T: Serialize,
{
    let wire = WIRE.get_or_init(|| judge_side(table));
    let turn = wire.turn();
    let args = once(args)
        .unwrap_or_else(|e| wire.broken(&format!("exercise {n}'s arguments cannot be sent: {e}")));
    let mut pull = items.map(|it| move || bincode::serialize(&it.next()).unwrap_or_default());
    let pull = pull.as_mut().map(|p| p as &mut dyn FnMut() -> Vec<u8>);
    match wire.exchange(table, Frame::Call { exercise: n, args }, pull) {
        Ok(value) => {
            let r = bincode::deserialize(&value).unwrap_or_else(|e| {
                wire.broken(&format!(
                    "the answer for exercise {} is no value of its function's type ({e})",
                    name(table, n)
                ))
            });
            drop(turn);
            r
        }
        Err(message) => {
            drop(turn);
            // the other side's words, escaped where they would break a report
            panic!("{}", whitted_syllabus::words::clean(&message))
        }
    }
}

/// The name an exercise's number stands for, in messages.
fn name(table: &Table, n: u16) -> String {
    table.prefixes.get(usize::from(n)).map_or_else(
        || format!("#{n}"),
        |p| {
            p.trim_start_matches("ex_")
                .trim_end_matches('_')
                .to_string()
        },
    )
}

/// `value` encoded in one pass: what it writes is decided as it is written
/// (`render::crossing::RoadRef`), and `bincode::serialize` writes twice (once to count).
fn once<T: Serialize + ?Sized>(value: &T) -> bincode::Result<Vec<u8>> {
    let mut bytes = Vec::new();
    bincode::serialize_into(&mut bytes, value)?;
    Ok(bytes)
}

/// Decodes an exercise's arguments (the grader's generated dispatch).
pub fn decode<A: DeserializeOwned>(args: &[u8]) -> Result<A, String> {
    bincode::deserialize(args).map_err(|e| format!("arguments that are no such values: {e}"))
}

/// Encodes an exercise's value (the grader's generated dispatch).
pub fn encode<R: Serialize + ?Sized>(value: &R) -> Result<Vec<u8>, String> {
    once(value).map_err(|e| format!("a value that cannot be sent: {e}"))
}

/// The iterator a function that crosses takes, on the side that runs it: each item is pulled
/// from the side that called, when the function asks for it ([`call_pulling`]).
pub struct Pulled<T> {
    table: &'static Table,
    ended: bool,
    item: std::marker::PhantomData<T>,
}

impl<T> Pulled<T> {
    /// The items of the iterator that the call being answered took.
    #[must_use]
    pub fn new(table: &'static Table) -> Self {
        Self {
            table,
            ended: false,
            item: std::marker::PhantomData,
        }
    }
}

impl<T: DeserializeOwned> Iterator for Pulled<T> {
    type Item = T;

    fn next(&mut self) -> Option<T> {
        if self.ended {
            return None;
        }
        let wire = WIRE.get_or_init(|| judge_side(self.table));
        let _turn = wire.turn();
        let item: Option<T> = bincode::deserialize(&wire.pull(self.table))
            .unwrap_or_else(|e| wire.broken(&format!("an item that is no such value ({e})")));
        self.ended = item.is_none();
        item
    }
}

/// The server's `main`: reads the judge's first frame, then answers its calls until the judge
/// closes the pipe.
pub fn serve(table: &'static Table) -> ExitCode {
    let mut from: Box<dyn BufRead + Send> = Box::new(BufReader::new(std::io::stdin()));
    let local = match read_frame(&mut from, &mut std::io::sink()) {
        Ok(Frame::Start { local }) => local,
        _ => return ExitCode::FAILURE,
    };
    let count = table.prefixes.len();
    let wire = Wire {
        side: Side::Server,
        remote: (0..count)
            .map(|n| !local.iter().any(|&l| usize::from(l) == n))
            .collect(),
        link: Mutex::new(Some(Link {
            to: Box::new(std::io::stdout()),
            from,
            child: None,
            spilled: 0,
        })),
        owner: Mutex::new(None),
        free: Condvar::new(),
    };
    if WIRE.set(wire).is_err() {
        return ExitCode::FAILURE;
    }
    let Some(wire) = WIRE.get() else {
        return ExitCode::FAILURE;
    };
    let _turn = wire.turn();
    loop {
        let frame = wire.receive();
        match frame {
            Some(Frame::Call { exercise, args }) => wire.answer(table, exercise, &args),
            _ => return ExitCode::SUCCESS, // the judge is done, or is no judge
        }
    }
}

/// Ends on this side when the wire breaks: the judge fails the test with the reason; a server
/// whose judge is gone just ends.
impl Wire {
    fn broken(&self, why: &str) -> ! {
        if self.side == Side::Judge {
            // the server's end, when it ended: waited for a moment, since its pipe closes
            // just before it is reaped
            let ended = lock(&self.link)
                .as_mut()
                .and_then(|l| l.child.as_mut())
                .and_then(|c| {
                    (0..100).find_map(|_| {
                        let s = c.try_wait().ok().flatten();
                        if s.is_none() {
                            std::thread::sleep(std::time::Duration::from_millis(10));
                        }
                        s
                    })
                });
            match ended {
                Some(s) if s.code().is_none() => {
                    eprintln!("whitted judge: the student's process died ({s}): the test fails");
                }
                Some(s) => {
                    eprintln!("whitted judge: {why} (the student's process: {s}): the test fails")
                }
                None => eprintln!("whitted judge: {why}: the test fails"),
            }
            std::process::exit(101);
        }
        std::process::exit(0);
    }

    /// Waits for this thread's turn in the conversation; nested calls of the thread that has
    /// it go on at once.
    fn turn(&self) -> Turn<'_> {
        let me = std::thread::current().id();
        let mut owner = lock(&self.owner);
        loop {
            match *owner {
                None => *owner = Some((me, 1)),
                Some((t, depth)) if t == me => *owner = Some((t, depth + 1)),
                Some(_) => {
                    owner = self
                        .free
                        .wait(owner)
                        .unwrap_or_else(PoisonError::into_inner);
                    continue;
                }
            }
            return Turn(self);
        }
    }

    /// Sends `frame`, then answers the other side's calls until the value (or the panic) of
    /// this one arrives; the other side's pulls are answered from `pull` (the items of the
    /// iterator this call took).
    fn exchange(
        &self,
        table: &Table,
        frame: Frame,
        mut pull: Option<&mut dyn FnMut() -> Vec<u8>>,
    ) -> Result<Vec<u8>, String> {
        self.send(&frame);
        loop {
            match self.receive() {
                Some(Frame::Value(v)) => return Ok(v),
                Some(Frame::Panicked(m)) => return Err(m),
                Some(Frame::Call { exercise, args }) => self.answer(table, exercise, &args),
                Some(Frame::Pull) => match pull.as_mut() {
                    Some(next) => {
                        let item = next();
                        self.send(&Frame::Item(item));
                    }
                    None => self.broken("the student's process pulled an item no call gave"),
                },
                Some(Frame::Start { .. } | Frame::Item(_)) => {
                    self.broken("the student's process sent a frame out of turn")
                }
                None => self.broken("the student's process ended or sent what is no frame"),
            }
        }
    }

    /// The next item of the iterator the innermost waiting call took, pulled from the other
    /// side; the other side's calls meanwhile are answered.
    fn pull(&self, table: &Table) -> Vec<u8> {
        self.send(&Frame::Pull);
        loop {
            match self.receive() {
                Some(Frame::Item(item)) => return item,
                Some(Frame::Call { exercise, args }) => self.answer(table, exercise, &args),
                _ => self.broken("the judge sent no item when one was pulled"),
            }
        }
    }

    /// Runs exercise `n` here for the other side and sends its value, or its panic.
    fn answer(&self, table: &Table, n: u16, args: &[u8]) {
        // what the judge sends to the server it never computes for it: the server asking for
        // the value it is judged on gets nothing (and asking back and forth would never end)
        if self.side == Side::Judge && self.remote.get(usize::from(n)).copied().unwrap_or(true) {
            self.broken(&format!(
                "the student's process asked the judge for exercise {}, which it is judged on",
                name(table, n)
            ));
        }
        let ran = catch_unwind(AssertUnwindSafe(|| (table.dispatch)(n, args)));
        let frame = match ran {
            Ok(Ok(value)) => Frame::Value(value),
            Ok(Err(why)) => Frame::Panicked(format!("exercise {}: {why}", name(table, n))),
            Err(payload) => Frame::Panicked(panic_message(payload.as_ref())),
        };
        self.send(&frame);
    }

    fn send(&self, frame: &Frame) {
        let mut guard = lock(&self.link);
        let link = match guard.as_mut() {
            Some(link) => link,
            None => match self.connect() {
                Ok(link) => guard.insert(link),
                Err(why) => {
                    drop(guard);
                    self.broken(&why)
                }
            },
        };
        let sent = write_frame(&mut link.to, frame);
        drop(guard);
        if let Err(e) = sent {
            self.broken(&format!("the student's process stopped reading ({e})"));
        }
    }

    fn receive(&self) -> Option<Frame> {
        let mut guard = lock(&self.link);
        let link = guard.as_mut()?;
        // what the other side writes between frames is kept up to what is left to pass on,
        // and the rest dropped as it comes: the judge's memory never holds more
        let room = match self.side {
            Side::Judge => MAX_SPILL.saturating_sub(link.spilled),
            Side::Server => 0,
        };
        let mut spill = Capped {
            kept: Vec::new(),
            room,
        };
        let frame = read_frame(&mut link.from, &mut spill).ok();
        if !spill.kept.is_empty() {
            link.spilled += spill.kept.len();
            let said = String::from_utf8_lossy(&spill.kept);
            eprint!("{}", whitted_syllabus::words::clean(&said));
        }
        frame
    }

    /// The judge's link: the server started from [`SERVER_VAR`], told what it runs itself.
    fn connect(&self) -> Result<Link, String> {
        let line = std::env::var(SERVER_VAR).map_err(|_| format!("{SERVER_VAR} is not set"))?;
        let mut words = line.split('\x1f');
        let program = words.next().unwrap_or_default();
        let mut child = Command::new(program)
            .args(words)
            .stdin(Stdio::piped())
            .stdout(Stdio::piped())
            .spawn()
            .map_err(|e| format!("the student's process cannot start ({program}: {e})"))?;
        let (Some(to), Some(from)) = (child.stdin.take(), child.stdout.take()) else {
            return Err("the student's process has no pipes".into());
        };
        let mut link = Link {
            to: Box::new(to),
            from: Box::new(BufReader::new(from)),
            child: Some(child),
            spilled: 0,
        };
        let local = (0..self.remote.len())
            .filter(|&n| self.remote[n])
            .filter_map(|n| u16::try_from(n).ok())
            .collect();
        write_frame(&mut link.to, &Frame::Start { local })
            .map_err(|e| format!("the student's process does not read ({e})"))?;
        Ok(link)
    }
}

/// A thread's turn in the conversation, given back when dropped (a panic included).
struct Turn<'w>(&'w Wire);

impl Drop for Turn<'_> {
    fn drop(&mut self) {
        let mut owner = lock(&self.0.owner);
        if let Some((t, depth)) = *owner {
            *owner = (depth > 1).then_some((t, depth - 1));
        }
        if owner.is_none() {
            self.0.free.notify_all();
        }
    }
}

/// A panic's message, as `panic!` was given it.
fn panic_message(payload: &(dyn std::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "a panic with no message".to_string())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A test is judged on the exercise its name starts with after the module path: a name
    /// that is a prefix of another's does not take its tests.
    #[test]
    fn a_test_is_judged_on_the_exercise_its_name_begins_with() {
        fn none(_: u16, _: &[u8]) -> Result<Vec<u8>, String> {
            Err(String::new())
        }
        let table = Table {
            prefixes: &["ex_hit_sphere_", "ex_hit_", "ex_sphere_normal_"],
            dispatch: none,
        };
        assert_eq!(judged(&table, "ch02::ex_hit_sphere_misses"), Some(0));
        assert_eq!(judged(&table, "ch02::ex_hit_plane_misses"), Some(1));
        assert_eq!(judged(&table, "render_paths::ch2_sphere"), None);
        assert_eq!(name(&table, 2), "sphere_normal");
    }

    /// Without the runner's variable, the judged test is the one libtest's command line runs
    /// alone; a listing, a filter that is no exact name, or two names judge none.
    #[test]
    fn the_judged_test_is_read_from_libtests_command_line() {
        let of = |a: &[&str]| test_of(a.iter().map(|w| (*w).to_string()));
        assert_eq!(
            of(&["--exact", "ch01::ex_ray_direction_x", "--nocapture"]),
            Some("ch01::ex_ray_direction_x".into())
        );
        assert_eq!(
            of(&["ch01::ex_ray_direction_x", "--exact", "--test-threads", "1"]),
            Some("ch01::ex_ray_direction_x".into())
        );
        assert_eq!(of(&["ex_ray_direction"]), None);
        assert_eq!(of(&["--list", "--exact", "a"]), None);
        assert_eq!(of(&["--exact", "a", "b"]), None);
    }
}
