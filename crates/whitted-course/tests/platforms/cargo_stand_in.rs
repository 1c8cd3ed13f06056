//! A stand-in for cargo, built for Windows and run under Wine by `whitted-learn.exe` (found as
//! `$CARGO`, the way `cargo learn` finds the cargo that started it): it asks the test's server
//! on Linux to run the command (see `wire.rs`), waits for the answer, prints what cargo printed
//! and exits with cargo's status.
//!
//! Built by the test with `rustc --target x86_64-pc-windows-gnu`, std only.

#[path = "wire.rs"]
mod wire;

use std::io::Write;
use std::time::{Duration, Instant, SystemTime, UNIX_EPOCH};

/// How long one cargo command may take (a first build compiles every dependency).
const PATIENCE: Duration = Duration::from_secs(1200);

fn main() {
    let Some(dir) = std::env::var_os(wire::DIR_VAR) else {
        eprintln!("error: the cargo stand-in needs {} (the bridge's directory)", wire::DIR_VAR);
        std::process::exit(2);
    };
    let dir = std::path::PathBuf::from(dir);
    let nanos = SystemTime::now()
        .duration_since(UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    let id = format!("{}-{nanos}", std::process::id());
    let ask = wire::Ask {
        cwd: std::env::current_dir()
            .map(|d| d.display().to_string())
            .unwrap_or_default(),
        args: std::env::args().skip(1).collect(),
        env: std::env::vars().filter(|(k, _)| wire::forwarded(k)).collect(),
    };
    if let Err(e) = wire::put(&wire::file(&dir, &id, "ask"), ask.to_text().as_bytes()) {
        eprintln!("error: the cargo stand-in cannot ask in {}: {e}", dir.display());
        std::process::exit(2);
    }
    let started = Instant::now();
    let code = loop {
        if let Ok(code) = std::fs::read_to_string(wire::file(&dir, &id, "code")) {
            break code.trim().parse::<i32>().unwrap_or(101);
        }
        if started.elapsed() > PATIENCE {
            eprintln!("error: no answer from the cargo bridge in {} s", PATIENCE.as_secs());
            std::process::exit(101);
        }
        std::thread::sleep(Duration::from_millis(20));
    };
    let out = std::fs::read(wire::file(&dir, &id, "out")).unwrap_or_default();
    let err = std::fs::read(wire::file(&dir, &id, "err")).unwrap_or_default();
    let _ = std::io::stdout().write_all(&out);
    let _ = std::io::stderr().write_all(&err);
    std::process::exit(code);
}
