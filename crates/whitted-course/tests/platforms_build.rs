//! A handout on the students' own systems, proven from Linux. These tests build copies of the
//! project for other targets, so they are `#[ignore]`d in a plain `cargo test`; `.ci/run`
//! runs them with `cargo test --test platforms_build -- --ignored --test-threads 1` once it has
//! installed MinGW-w64, Wine and the Rust targets.
//!
//! - **Windows, under Wine.** A handout of chapter 3, its text files turned to CRLF (as Git
//!   for Windows checks them out), is built for `x86_64-pc-windows-gnu` with MinGW-w64. Its
//!   tests (`.exe` files) run under Wine and fail exactly as `chapters/exercise-tests.toml` says;
//!   `whitted-learn`'s own tests pass under Wine; and `whitted-learn.exe` runs the loop's verdict
//!   path under Wine, with no terminal (so no ANSI colours) and with a cargo that is not on the
//!   PATH but named by `$CARGO`, as `cargo learn` finds it: a stand-in that asks this machine's
//!   cargo to build for Windows (see `platforms/wire.rs`; Wine cannot wait on a Linux program
//!   started from a Windows one). Cargo's messages reach it with Windows paths (`Z:\…\x.exe`);
//!   it runs the test executables, names the next exercise and draws the chapter's picture with
//!   the chapter's `.exe`, and a body written back (in CRLF) turns that exercise green;
//!   `cargo learn hint` gives the next exercise's hints one more at a time. The
//!   window's Windows backend (Win32) opens under Wine on an X server of its own (Xvfb) and
//!   shows exactly the picture the same binary writes with `-o`.
//! - **macOS.** A handout type-checks for `aarch64-apple-darwin` and `x86_64-apple-darwin`
//!   (`cargo check`, every target of every crate, the window's Cocoa backend included). minifb
//!   compiles its Objective-C part with Apple's compiler and SDK, which no Linux machine has:
//!   the check runs its build script with a stand-in C compiler that writes empty objects
//!   (`platforms/apple-cc`), which a check never links. So the Rust side is checked whole and
//!   the Objective-C side is not compiled here.

mod common;
#[path = "platforms/serve.rs"]
mod serve;
#[path = "platforms/wire.rs"]
mod wire;

use common::{manifest, root, text};

use std::collections::{BTreeMap, BTreeSet};
use std::path::{Path, PathBuf};
use std::process::Command;

use serve::{Server, TARGET, windows_path};
use whitted_course::manifest::Manifest;
use whitted_course::{deps, handout};

/// This machine's cargo, building in `target_dir`.
fn cargo(target_dir: &Path) -> Command {
    let mut c = Command::new(std::env::var_os("CARGO").unwrap_or_else(|| "cargo".into()));
    c.env("CARGO_TARGET_DIR", target_dir)
        .env("CARGO_PROFILE_DEV_DEBUG", "0")
        .env_remove("WHITTED_POISON");
    c
}

/// Stops the test, saying what `.ci/run` installs, when `program` is not on this machine.
fn require(program: &str, what: &str) {
    let found = Command::new(program).arg("--version").output().is_ok();
    assert!(
        found,
        "{program} is not installed: {what} (.ci/run installs it)"
    );
}

/// Stops the test when the Rust standard library of `target` is not installed.
fn require_target(target: &str) {
    let out = Command::new("rustc")
        .args(["--print", "target-libdir", "--target", target])
        .output()
        .unwrap();
    let dir = PathBuf::from(String::from_utf8_lossy(&out.stdout).trim());
    assert!(
        dir.is_dir(),
        "the Rust target {target} is not installed: `rustup target add {target}` (.ci/run does)"
    );
}

/// A handout of `selected` (manifest indices) at `dir/name`.
fn handout_of(m: &Manifest, selected: &[usize], dir: &Path, name: &str) -> PathBuf {
    let student = dir.join(name);
    handout::write(&root(), m, selected, &student).unwrap();
    student
}

/// Every text file under `dir` with CRLF line ends (Git for Windows's checkout); PNG files
/// and other binaries as they are.
fn to_crlf(dir: &Path) {
    for entry in std::fs::read_dir(dir).unwrap().flatten() {
        let path = entry.path();
        if path.is_dir() {
            to_crlf(&path);
        } else if let Ok(text) = std::fs::read_to_string(&path)
            && !text.contains('\0')
        {
            std::fs::write(&path, text.replace("\r\n", "\n").replace('\n', "\r\n")).unwrap();
        }
    }
}

/// The executables of a cargo build for the Windows target (`ARGS --target … --message-format
/// json`), by target name; panics with cargo's output when it fails.
fn windows_build(project: &Path, target_dir: &Path, args: &[&str]) -> BTreeMap<String, PathBuf> {
    let out = cargo(target_dir)
        .args(args)
        .args(["--target", TARGET, "--message-format=json"])
        .current_dir(project)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "cargo {args:?} --target {TARGET}: {}",
        text(&out)
    );
    let mut exes = BTreeMap::new();
    for line in String::from_utf8_lossy(&out.stdout).lines() {
        let Ok(msg) = serde_json::from_str::<serde_json::Value>(line) else {
            continue;
        };
        if let (Some(name), Some(exe)) =
            (msg["target"]["name"].as_str(), msg["executable"].as_str())
        {
            exes.insert(name.to_string(), PathBuf::from(exe));
        }
    }
    exes
}

/// Wine, in the prefix under `target/wine` (made on first use, with the one DLL Rust's
/// standard library needs that Debian's Wine 8 lacks).
fn wine() -> Command {
    let prefix = root().join("target").join("wine");
    let system32 = prefix.join("drive_c/windows/system32");
    if !system32.is_dir() {
        let out = Command::new("wine")
            .args(["wineboot", "--init"])
            .env("WINEPREFIX", &prefix)
            .env("WINEDEBUG", "-all")
            .output()
            .unwrap();
        assert!(system32.is_dir(), "wineboot made no prefix: {}", text(&out));
    }
    let dll = system32.join("bcryptprimitives.dll");
    if !dll.is_file() {
        let source =
            Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/platforms/bcryptprimitives.c");
        let out = Command::new("x86_64-w64-mingw32-gcc")
            .args(["-shared", "-O2", "-o"])
            .arg(&dll)
            .arg(&source)
            .args(["-ladvapi32", "-Wl,--kill-at"])
            .output()
            .unwrap();
        assert!(out.status.success(), "the DLL for Wine: {}", text(&out));
    }
    let mut c = Command::new("wine");
    c.env("WINEPREFIX", &prefix).env("WINEDEBUG", "-all");
    c
}

/// Runs the Windows test executables `exes` under Wine in `dir`: the failed and the passed
/// tests, as `target::name`.
fn run_under_wine(
    exes: &BTreeMap<String, PathBuf>,
    dir: &Path,
) -> (BTreeSet<String>, BTreeSet<String>) {
    let (mut failed, mut passed) = (BTreeSet::new(), BTreeSet::new());
    for (target, exe) in exes {
        let out = wine()
            .arg(exe)
            .args(["--test-threads", "2"])
            .current_dir(dir)
            .env_remove("WHITTED_BLESS")
            .output()
            .unwrap();
        common::sort_outcomes(target, &out, &mut failed, &mut passed);
    }
    (failed, passed)
}

/// `whitted-learn.exe` run under Wine in `student`, its cargo the stand-in `stand_in` answered
/// through `bridge`: its standard output.
fn learn_under_wine(exe: &Path, student: &Path, stand_in: &Path, bridge: &Path) -> String {
    let server = Server::start(bridge, &root().join("target").join("windows"));
    let out = wine()
        .arg(exe)
        .current_dir(student)
        .env("CARGO", windows_path(stand_in))
        .env(wire::DIR_VAR, windows_path(bridge))
        .env_remove("NO_COLOR")
        .env_remove("CARGO_TARGET_DIR")
        .env_remove("WHITTED_POISON")
        .output()
        .unwrap();
    let asked = server.stop();
    assert!(
        out.status.success(),
        "whitted-learn.exe under Wine: {}",
        text(&out)
    );
    assert!(
        asked
            .iter()
            .any(|a| a.args.starts_with(&["test".into(), "--no-run".into()])),
        "the loop asked its cargo for no test build: {asked:?}"
    );
    let report = String::from_utf8_lossy(&out.stdout).into_owned();
    eprintln!(
        "whitted-learn.exe under Wine, asked {} cargo commands:\n{report}",
        asked.len()
    );
    report
}

/// The number in `K of N exercises done`.
fn done_in(report: &str, n: usize) -> usize {
    let tail = format!(" of {n} exercises done");
    report
        .lines()
        .find_map(|l| l.split_once(&tail).map(|(k, _)| k))
        .and_then(|k| k.rsplit(' ').next()?.parse().ok())
        .unwrap_or_else(|| panic!("no `K{tail}` in:\n{report}"))
}

/// A picture's pixels as 8-bit RGB rows, and its size.
fn rgb(path: &Path) -> (u32, u32, Vec<u8>) {
    let file = std::fs::File::open(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let mut decoder = png::Decoder::new(std::io::BufReader::new(file));
    decoder.set_transformations(png::Transformations::EXPAND | png::Transformations::STRIP_16);
    let mut reader = decoder.read_info().unwrap();
    let mut buf = vec![0; reader.output_buffer_size().unwrap()];
    let frame = reader.next_frame(&mut buf).unwrap();
    let channels = frame.color_type.samples();
    let pixels = buf[..frame.buffer_size()]
        .chunks(channels)
        .flat_map(|p| [p[0], p[1], p[2]])
        .collect();
    (frame.width, frame.height, pixels)
}

/// An X server of its own (Xvfb, 24-bit): the process and its display (`:N`).
fn x_server() -> (std::process::Child, String) {
    use std::io::BufRead;
    let mut x = Command::new("Xvfb")
        .args([
            "-displayfd",
            "1",
            "-screen",
            "0",
            "1280x1024x24",
            "-nolisten",
            "tcp",
        ])
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::null())
        .spawn()
        .expect("Xvfb (.ci/run installs it)");
    let mut line = String::new();
    std::io::BufReader::new(x.stdout.take().unwrap())
        .read_line(&mut line)
        .unwrap();
    (x, format!(":{}", line.trim()))
}

/// The chapter binary `exe` (built for Windows) in a window under Wine on its own X server:
/// once the title says the last pass is done, the window's picture, as `import` captures it.
fn window_under_wine(exe: &Path, student: &Path, args: &[&str], shot: &Path) {
    let (mut x, display) = x_server();
    let mut window = wine()
        .arg(exe)
        .args(args)
        .arg("--window")
        .current_dir(student)
        .env("DISPLAY", &display)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .spawn()
        .unwrap();
    let name = exe.file_stem().unwrap().to_string_lossy().into_owned();
    let xdotool = |args: &[&str]| {
        let out = Command::new("xdotool")
            .args(args)
            .env("DISPLAY", &display)
            .output()
            .expect("xdotool (.ci/run installs it)");
        String::from_utf8_lossy(&out.stdout).trim().to_string()
    };
    let started = std::time::Instant::now();
    let mut title = String::new();
    let id = loop {
        let found = xdotool(&["search", "--name", &format!("^{name} — ")]);
        if let Some(id) = found.lines().next() {
            title = xdotool(&["getwindowname", id]);
            if title.contains("pass 4/4") {
                break id.to_string();
            }
        }
        assert!(
            started.elapsed().as_secs() < 90,
            "no finished window of {name} under Wine in 90 s; its title: {title:?}"
        );
        std::thread::sleep(std::time::Duration::from_millis(250));
    };
    let out = Command::new("import")
        .args(["-window", &id])
        .arg(shot)
        .env("DISPLAY", &display)
        .output()
        .expect("import, ImageMagick's (.ci/run installs it)");
    assert!(out.status.success(), "import: {}", text(&out));
    eprintln!("the window under Wine: {title}");
    let _ = window.kill();
    let _ = window.wait();
    // the prefix's server, and every Windows process left in it, ended
    let prefix = root().join("target").join("wine");
    let _ = Command::new("wineserver")
        .arg("-k")
        .env("WINEPREFIX", &prefix)
        .status();
    let _ = x.kill();
    let _ = x.wait();
}

#[test]
#[ignore = "builds a handout for Windows and runs it under Wine (minutes); .ci/run runs it"]
fn a_handout_builds_tests_and_learns_on_windows_under_wine() {
    require("x86_64-w64-mingw32-gcc", "MinGW-w64, the Windows linker");
    require("wine", "Wine, which runs Windows programs");
    require_target(TARGET);
    let m = manifest();
    let chapter = handout::select(&m, Some((3, 3)), &[]).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let student = handout_of(&m, &chapter, dir.path(), "ch3");
    // the handout's own manifest: its exercises (chapter 3's) and its test targets (none of a
    // later chapter)
    let own = whitted_course::manifest::load(&student.join(whitted_course::manifest::DEFAULT_PATH))
        .unwrap();
    let n = own.entries.len();
    assert_eq!(n, chapter.len(), "the chapter-3 handout's exercises");
    to_crlf(&student);
    let target_dir = root().join("target").join("windows");

    // the student's tests, as .exe files under Wine: they fail exactly as the map says
    let mut build = vec!["test", "--no-run", "-p", "whitted"];
    for t in &own.handout.tests {
        build.extend(["--test", t.as_str()]);
    }
    let exes = windows_build(&student, &target_dir, &build);
    assert_eq!(exes.len(), own.handout.tests.len(), "{exes:?}");
    assert!(
        exes.values()
            .all(|e| e.extension().is_some_and(|x| x == "exe"))
    );
    let (failed, passed) = run_under_wine(&exes, &student.join("crates/whitted"));
    let every: BTreeSet<String> = failed.union(&passed).cloned().collect();
    let map = deps::load_map(&root(), &m).unwrap();
    let expected = deps::expected(&map, &every, &chapter);
    let extra: Vec<_> = failed.difference(&expected).collect();
    let missing: Vec<_> = expected.difference(&failed).collect();
    assert!(
        extra.is_empty() && missing.is_empty() && !failed.is_empty(),
        "under Wine, failing but not expected: {extra:?}\nexpected but passing: {missing:?}"
    );

    // whitted-learn's own tests, under Wine (cargo runs each test executable through it)
    let prefix = root().join("target").join("wine");
    let _ = wine(); // makes the prefix
    let out = cargo(&target_dir)
        .args(["test", "-p", "whitted-learn", "--target", TARGET])
        .env("CARGO_TARGET_X86_64_PC_WINDOWS_GNU_RUNNER", "wine")
        .env("WINEPREFIX", &prefix)
        .env("WINEDEBUG", "-all")
        .current_dir(&student)
        .output()
        .unwrap();
    let report = text(&out);
    assert!(
        out.status.success(),
        "whitted-learn's tests under Wine: {report}"
    );
    let ran: usize = report
        .lines()
        .filter_map(|l| l.strip_prefix("test result: ok. "))
        .filter_map(|l| l.split(' ').next()?.parse::<usize>().ok())
        .sum();
    assert!(ran > 0, "no test of whitted-learn ran under Wine: {report}");

    // the loop's verdict path: whitted-learn.exe, its cargo named by $CARGO
    let learn = windows_build(
        &student,
        &target_dir,
        &[
            "build",
            "--profile",
            "test",
            "-p",
            "whitted-learn",
            "--bin",
            "whitted-learn",
        ],
    );
    let learn = &learn["whitted-learn"];
    let stand_in = dir.path().join("cargo-stand-in.exe");
    let source = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/platforms/cargo_stand_in.rs");
    let out = Command::new("rustc")
        .args(["--edition", "2024", "-O", "--target", TARGET, "-o"])
        .arg(&stand_in)
        .arg(&source)
        .output()
        .unwrap();
    assert!(out.status.success(), "the cargo stand-in: {}", text(&out));
    let bridge = dir.path().join("bridge");
    std::fs::create_dir(&bridge).unwrap();

    let report = learn_under_wine(learn, &student, &stand_in, &bridge);
    assert!(
        !report.contains('\x1b'),
        "ANSI codes with no terminal:\n{report}"
    );
    let first = &m.entries[chapter[0]].exercise;
    assert!(
        report.contains(&format!("✗ exercise {} —", first.id)),
        "exercise {} is not named next:\n{report}",
        first.id
    );
    // where to write it, as Windows writes a path: `\` between every part
    let place = report
        .lines()
        .find_map(|l| l.trim_start().strip_prefix("write it in "))
        .unwrap_or_else(|| panic!("no `write it in` in:\n{report}"));
    assert!(
        place.starts_with(r"crates\whitted\src\")
            && !place.split(';').next().unwrap().contains('/'),
        "a path with mixed separators: {place}"
    );
    let done = done_in(&report, n);
    let picture = student.join(".whitted").join("ch03-flat.png");
    assert!(
        report.contains("✓ picture: chapter 3's scene through chapter 2's road"),
        "no picture in:\n{report}"
    );
    let png = std::fs::read(&picture).unwrap_or_default();
    assert!(
        png.starts_with(b"\x89PNG"),
        "{} is not a PNG",
        picture.display()
    );

    // the first exercise's body written back, in CRLF: it turns green
    let regions = handout::regions(&root(), &m).unwrap();
    let r = &regions[chapter[0]];
    let path = student.join(&r.file);
    let now = std::fs::read_to_string(&path).unwrap();
    let todo = format!(
        "{}{}\r\n",
        r.indent,
        handout::todo_statement(&m.entries[chapter[0]])
    );
    let back = now.replacen(&todo, &r.solution.replace('\n', "\r\n"), 1);
    assert_ne!(back, now, "exercise {}'s todo!() not found", first.id);
    std::fs::write(&path, back).unwrap();
    let report = learn_under_wine(learn, &student, &stand_in, &bridge);
    assert_eq!(done_in(&report, n), done + 1, "{report}");
    let second = &m.entries[chapter[1]].exercise;
    assert!(
        report.contains(&format!("✗ exercise {} —", second.id)),
        "exercise {} is not named next:\n{report}",
        second.id
    );

    // a hint for the next exercise, twice: the second shows one more (its count kept in
    // .whitted, written whole under Windows' file rules)
    for shown in 1..=2 {
        let out = wine()
            .args([learn.as_os_str(), "hint".as_ref()])
            .current_dir(&student)
            .output()
            .unwrap();
        let said = String::from_utf8_lossy(&out.stdout);
        assert!(
            out.status.success() && said.starts_with(&format!("exercise {} —", second.id)),
            "whitted-learn.exe hint: {}",
            text(&out)
        );
        let count = said
            .lines()
            .filter(|l| l.trim_start().starts_with("hint "))
            .count();
        let hints = m.entries[chapter[1]].exercise.hints.len();
        assert_eq!(
            count,
            shown.min(hints),
            "hints shown the {shown}th time:\n{said}"
        );
    }

    // the window's Windows backend (Win32, through Wine's X11 driver): chapter 2's window shows
    // exactly the picture its `-o` writes
    let bins = windows_build(
        &student,
        &target_dir,
        &[
            "build",
            "--profile",
            "test",
            "-p",
            "whitted",
            "-p",
            "whitted-app",
            "--bin",
            "ch02_generic_objects",
        ],
    );
    let exe = &bins["ch02_generic_objects"];
    let scene = ["scenes/ch02_generic_objects.toml"];
    let written = dir.path().join("written.png");
    let out = wine()
        .arg(exe)
        .args(scene)
        .arg("-o")
        .arg(windows_path(&written))
        .current_dir(&student)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "ch02_generic_objects.exe -o: {}",
        text(&out)
    );
    let shot = dir.path().join("window.png");
    window_under_wine(exe, &student, &scene, &shot);
    let (w, h, drawn) = rgb(&shot);
    let (ow, oh, wanted) = rgb(&written);
    assert_eq!((w, h), (ow, oh), "the window's size against the picture's");
    let differ = drawn
        .chunks(3)
        .zip(wanted.chunks(3))
        .filter(|(a, b)| a != b)
        .count();
    assert_eq!(
        differ, 0,
        "pixels of the window that differ from the picture -o wrote"
    );
}

#[test]
#[ignore = "type-checks a handout for two targets (a minute or two); .ci/run runs it"]
fn a_handout_type_checks_for_both_macs() {
    let targets = ["aarch64-apple-darwin", "x86_64-apple-darwin"];
    for t in targets {
        require_target(t);
    }
    let m = manifest();
    let all: Vec<usize> = (0..m.entries.len()).collect();
    let dir = tempfile::tempdir().unwrap();
    let student = handout_of(&m, &all, dir.path(), "all");
    let cc = Path::new(env!("CARGO_MANIFEST_DIR")).join("tests/platforms/apple-cc");
    let mut check = cargo(&root().join("target").join("macos"));
    check.args(["check", "--workspace", "--all-targets"]);
    for t in targets {
        check
            .args(["--target", t])
            .env(format!("CC_{}", t.replace('-', "_")), &cc);
    }
    let out = check.current_dir(&student).output().unwrap();
    let said = text(&out);
    assert!(out.status.success(), "cargo check for macOS: {said}");
    for t in targets {
        assert!(
            root().join("target/macos").join(t).is_dir(),
            "nothing was checked for {t}: {said}"
        );
    }
}
