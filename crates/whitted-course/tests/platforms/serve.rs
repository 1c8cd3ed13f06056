//! The Linux side of the cargo bridge (see `wire.rs`): answers each ask by running this
//! machine's cargo for `x86_64-pc-windows-gnu`, with the paths in cargo's messages written as
//! Windows names them under Wine (`Z:\…`, with `\`), so that the asking program reads what a
//! Windows cargo would have printed.

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::thread::JoinHandle;
use std::time::Duration;

use super::wire::{self, Ask};

/// The Windows target the bridge builds for.
pub const TARGET: &str = "x86_64-pc-windows-gnu";

/// A Linux path as a Windows program under Wine names it: `/a/b` is `Z:\a\b`.
pub fn windows_path(path: &Path) -> String {
    format!("Z:{}", path.display()).replace('/', "\\")
}

/// A path a Windows program under Wine gave, on Linux: `Z:\a\b` is `/a/b`.
pub fn unix_path(path: &str) -> PathBuf {
    let path = path.strip_prefix(r"\\?\").unwrap_or(path);
    let path = path
        .strip_prefix("Z:")
        .or_else(|| path.strip_prefix("z:"))
        .unwrap_or(path);
    PathBuf::from(path.replace('\\', "/"))
}

/// A path in cargo's messages as a Windows cargo prints it: absolute ones on drive Z:, and `\`
/// between the parts of relative ones.
fn message_path(path: &str) -> String {
    if path.starts_with('/') {
        windows_path(Path::new(path))
    } else {
        path.replace('/', "\\")
    }
}

/// The keys of cargo's JSON messages whose values are paths.
const PATH_KEYS: [&str; 6] = [
    "executable",
    "filenames",
    "src_path",
    "manifest_path",
    "out_dir",
    "file_name",
];

/// Rewrites the paths of one JSON value in place, at any depth.
fn rewrite(value: &mut serde_json::Value, is_path: bool) {
    match value {
        serde_json::Value::String(s) if is_path => *s = message_path(s),
        serde_json::Value::Array(items) => items.iter_mut().for_each(|v| rewrite(v, is_path)),
        serde_json::Value::Object(map) => {
            for (k, v) in map.iter_mut() {
                rewrite(v, PATH_KEYS.contains(&k.as_str()));
            }
        }
        _ => {}
    }
}

/// cargo's standard output with the paths of its JSON messages rewritten (other lines as
/// they are).
pub fn windows_messages(stdout: &str) -> String {
    let mut out = String::new();
    for line in stdout.lines() {
        match serde_json::from_str::<serde_json::Value>(line) {
            Ok(mut v) if v.is_object() => {
                rewrite(&mut v, false);
                out += &v.to_string();
            }
            _ => out += line,
        }
        out.push('\n');
    }
    out
}

/// A server answering asks in a directory until it is stopped.
pub struct Server {
    stop: Arc<AtomicBool>,
    handle: Option<JoinHandle<Vec<Ask>>>,
}

impl Server {
    /// Serves the asks that appear in `dir`; cargo builds in `target_dir` unless an ask names
    /// its own.
    pub fn start(dir: &Path, target_dir: &Path) -> Server {
        let stop = Arc::new(AtomicBool::new(false));
        let (dir, target_dir, stopped) =
            (dir.to_path_buf(), target_dir.to_path_buf(), stop.clone());
        let handle = std::thread::spawn(move || {
            let mut served = Vec::new();
            while !stopped.load(Ordering::Relaxed) {
                for (id, ask) in waiting(&dir) {
                    answer(&dir, &id, &ask, &target_dir);
                    served.push(ask);
                }
                std::thread::sleep(Duration::from_millis(20));
            }
            served
        });
        Server {
            stop,
            handle: Some(handle),
        }
    }

    /// Stops serving; the asks it answered, in order.
    pub fn stop(mut self) -> Vec<Ask> {
        self.stop.store(true, Ordering::Relaxed);
        self.handle
            .take()
            .map(|h| h.join().expect("the bridge's server panicked"))
            .unwrap_or_default()
    }
}

/// The asks waiting in `dir`, each taken (its file removed), by id.
fn waiting(dir: &Path) -> Vec<(String, Ask)> {
    let mut found = Vec::new();
    for entry in std::fs::read_dir(dir).into_iter().flatten().flatten() {
        let path = entry.path();
        if path.extension().is_some_and(|e| e == "ask") {
            let id = path.file_stem().unwrap().to_string_lossy().into_owned();
            let text = std::fs::read_to_string(&path).unwrap();
            std::fs::remove_file(&path).unwrap();
            let ask = Ask::from_text(&text)
                .unwrap_or_else(|| panic!("the stand-in asked what the wire does not say: {text}"));
            found.push((id, ask));
        }
    }
    found
}

/// Runs cargo as `ask` says, for the Windows target, and writes its answer.
fn answer(dir: &Path, id: &str, ask: &Ask, target_dir: &Path) {
    let cargo = std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into());
    let mut command = Command::new(cargo);
    // `--target` right after the subcommand: the loop's commands have no `--` of their own
    let (sub, rest) = ask
        .args
        .split_first()
        .expect("the stand-in asked for no command");
    command
        .arg(sub)
        .args(["--target", TARGET])
        .args(rest)
        .current_dir(unix_path(&ask.cwd))
        .env("CARGO_TARGET_DIR", target_dir);
    for (k, v) in &ask.env {
        if k == "CARGO_TARGET_DIR" {
            command.env(k, unix_path(v));
        } else {
            command.env(k, v);
        }
    }
    // an answer always comes, so that the stand-in never waits for one that cannot
    let (stdout, stderr, code) = match command.output() {
        Ok(out) => (
            windows_messages(&String::from_utf8_lossy(&out.stdout)),
            out.stderr,
            out.status.code().unwrap_or(101),
        ),
        Err(e) => (
            String::new(),
            format!("error: the bridge cannot run cargo: {e}\n").into_bytes(),
            101,
        ),
    };
    wire::put(&wire::file(dir, id, "out"), stdout.as_bytes()).unwrap();
    wire::put(&wire::file(dir, id, "err"), &stderr).unwrap();
    wire::put(&wire::file(dir, id, "code"), code.to_string().as_bytes()).unwrap();
}

#[test]
fn paths_cross_between_the_two_systems() {
    assert_eq!(windows_path(Path::new("/tmp/h/a.exe")), r"Z:\tmp\h\a.exe");
    assert_eq!(unix_path(r"Z:\tmp\h"), PathBuf::from("/tmp/h"));
    assert_eq!(unix_path(r"\\?\Z:\tmp\h"), PathBuf::from("/tmp/h"));
    let line = r#"{"reason":"compiler-artifact","target":{"name":"t","src_path":"/p/tests/t.rs"},"executable":"/p/target/t.exe","filenames":["/p/target/t.exe"],"fresh":true}"#;
    let v: serde_json::Value = serde_json::from_str(windows_messages(line).trim()).unwrap();
    assert_eq!(v["executable"], r"Z:\p\target\t.exe");
    assert_eq!(v["filenames"][0], r"Z:\p\target\t.exe");
    assert_eq!(v["target"]["src_path"], r"Z:\p\tests\t.rs");
    assert_eq!(v["target"]["name"], "t");
    let message = r#"{"reason":"compiler-message","message":{"level":"error","spans":[{"file_name":"crates/whitted/src/a.rs","line_start":3}]}}"#;
    let v: serde_json::Value = serde_json::from_str(windows_messages(message).trim()).unwrap();
    assert_eq!(
        v["message"]["spans"][0]["file_name"],
        r"crates\whitted\src\a.rs"
    );
    assert_eq!(windows_messages("not json\n"), "not json\n");
    let ask = Ask {
        cwd: r"Z:\tmp\h".into(),
        args: vec!["test".into(), "--no-run".into()],
        env: vec![("CARGO_PROFILE_DEV_DEBUG".into(), "0".into())],
    };
    assert_eq!(Ask::from_text(&ask.to_text()), Some(ask));
}
