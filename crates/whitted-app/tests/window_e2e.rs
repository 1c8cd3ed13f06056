//! The live window end to end, under Xvfb (a virtual X server with a 24-bit screen; a 16-bit
//! one crashes minifb), driven by `xdotool` and captured with ImageMagick's `import`, as a
//! student would use it: the window opens on the showcase and refines to the image `-o`
//! writes, a click prints the ray tree and draws it, saving the scene file reloads it, and
//! every key does what the help says; Esc closes it with exit status 0. With `--compare
//! REF.png`, Tab shows the reference and then the difference, which marks the pixels changed.
//!
//! Ignored by default (it needs those programs); `.ci/run` installs them and runs
//! `cargo test --test window_e2e -- --ignored`. Keys are held 100 ms, as fingers do: minifb
//! reads the keyboard once a frame, so a press and release within one frame would be lost.

mod common;

use std::path::{Path, PathBuf};
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

use whitted::render::Chapter;

/// The chapter whose binary the window runs: the last, which reaches every chapter.
const LAST: Chapter = Chapter::ReflectionRefraction;

/// A virtual X server on a display of its own, stopped on drop.
struct Xvfb {
    child: Child,
    display: String,
}

impl Xvfb {
    /// Starts Xvfb on a display of its own: Xvfb itself picks a free one (`-displayfd`) and
    /// writes its number once it takes connections, so tests running at once (these, or
    /// another checkout's) never share a screen.
    fn start() -> Self {
        use std::io::BufRead;
        let Ok(mut child) = Command::new("Xvfb")
            .args([
                "-displayfd",
                "1",
                "-screen",
                "0",
                "1280x1024x24",
                "-nolisten",
                "tcp",
            ])
            .stdout(Stdio::piped())
            .stderr(Stdio::null())
            .spawn()
        else {
            panic!("Xvfb is not installed (Debian: apt-get install xvfb)");
        };
        let mut number = String::new();
        if let Some(out) = child.stdout.take() {
            let _ = std::io::BufReader::new(out).read_line(&mut number);
        }
        let number = number.trim().to_string();
        let mut x = Self {
            child,
            display: format!(":{number}"),
        };
        assert!(
            number.parse::<u32>().is_ok(),
            "Xvfb started no display (it wrote {number:?})"
        );
        let start = Instant::now();
        while !xdotool_ok(&x.display) {
            assert!(
                start.elapsed() < Duration::from_secs(10),
                "Xvfb's display {} does not answer",
                x.display
            );
            assert!(
                matches!(x.child.try_wait(), Ok(None)),
                "Xvfb ended on {}",
                x.display
            );
            std::thread::sleep(Duration::from_millis(100));
        }
        x
    }
}

/// Asks a process to end (SIGTERM, so that Xvfb removes its lock file), then reaps it.
fn stop(child: &mut Child) {
    if let Ok(None) = child.try_wait() {
        let _ = Command::new("kill").arg(child.id().to_string()).status();
        let start = Instant::now();
        while start.elapsed() < Duration::from_secs(5) {
            if let Ok(Some(_)) = child.try_wait() {
                return;
            }
            std::thread::sleep(Duration::from_millis(50));
        }
        let _ = child.kill();
    }
    let _ = child.wait();
}

impl Drop for Xvfb {
    fn drop(&mut self) {
        stop(&mut self.child);
    }
}

/// Whether the X server answers (`xdotool getmouselocation` needs a connection).
fn xdotool_ok(display: &str) -> bool {
    Command::new("xdotool")
        .arg("getmouselocation")
        .env("DISPLAY", display)
        .output()
        .is_ok_and(|o| o.status.success())
}

/// Runs `xdotool` with `args` on `display`; returns its stdout.
fn xdotool(display: &str, args: &[&str]) -> String {
    let out = Command::new("xdotool")
        .args(args)
        .env("DISPLAY", display)
        .output()
        .expect("xdotool is installed (Debian: apt-get install xdotool)");
    assert!(
        out.status.success(),
        "xdotool {args:?}: {}",
        String::from_utf8_lossy(&out.stderr)
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

/// The window under test: its process, its X id and geometry, and its output files.
struct Session {
    x: Xvfb,
    child: Child,
    window: String,
    geometry: (u32, u32, u32, u32),
    stdout: PathBuf,
    stderr: PathBuf,
    dir: tempfile::TempDir,
    /// One window at a time: two renders at once slow each other's frames, and a key held
    /// 100 ms could then repeat.
    _alone: std::sync::MutexGuard<'static, ()>,
}

/// Held by the window open now.
static ONE_WINDOW: std::sync::Mutex<()> = std::sync::Mutex::new(());

impl Session {
    fn text(path: &Path) -> String {
        std::fs::read_to_string(path).unwrap_or_default()
    }

    /// Waits until `pattern` occurs more than `seen` times in the file; returns the count.
    fn wait_for(&mut self, stderr: bool, pattern: &str, seen: usize) -> usize {
        let path = if stderr { &self.stderr } else { &self.stdout };
        let start = Instant::now();
        loop {
            let n = Self::text(path).matches(pattern).count();
            if n > seen {
                return n;
            }
            if let Ok(Some(status)) = self.child.try_wait() {
                panic!(
                    "the window exited ({status}) waiting for {pattern:?}; stderr: {}",
                    Self::text(&self.stderr)
                );
            }
            assert!(
                start.elapsed() < Duration::from_secs(60),
                "no {pattern:?} within 60 s; stderr: {}",
                Self::text(&self.stderr)
            );
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    fn count(&self, stderr: bool, pattern: &str) -> usize {
        Self::text(if stderr { &self.stderr } else { &self.stdout })
            .matches(pattern)
            .count()
    }

    /// Presses `key` (an xdotool key name) for 100 ms, the pointer over the window (with no
    /// window manager, the keyboard goes to the window under the pointer).
    fn key(&self, key: &str) {
        xdotool(
            &self.x.display,
            &["mousemove", "--window", &self.window, "4", "4"],
        );
        xdotool(&self.x.display, &["keydown", key]);
        std::thread::sleep(Duration::from_millis(100));
        xdotool(&self.x.display, &["keyup", key]);
    }

    /// Presses a key and waits for the image it asks for to be complete.
    fn key_and_render(&mut self, key: &str) {
        let n = self.count(true, "image complete");
        self.key(key);
        self.wait_for(true, "image complete", n);
        // one more frame on screen
        std::thread::sleep(Duration::from_millis(150));
    }

    /// Clicks the window's pixel (x, y), holding the button 100 ms.
    fn click(&self, x: u32, y: u32) {
        let (xs, ys) = (x.to_string(), y.to_string());
        xdotool(
            &self.x.display,
            &["mousemove", "--window", &self.window, &xs, &ys],
        );
        xdotool(&self.x.display, &["mousedown", "1"]);
        std::thread::sleep(Duration::from_millis(100));
        xdotool(&self.x.display, &["mouseup", "1"]);
    }

    /// The window's pixels now, as the screen shows them.
    fn shot(&self, name: &str) -> image::RgbImage {
        let (x, y, w, h) = self.geometry;
        let path = self.dir.path().join(format!("{name}.png"));
        let out = Command::new("import")
            .args(["-window", "root", "-crop", &format!("{w}x{h}+{x}+{y}")])
            .arg(&path)
            .env("DISPLAY", &self.x.display)
            .output()
            .expect("ImageMagick's import is installed (Debian: apt-get install imagemagick)");
        assert!(
            out.status.success(),
            "{}",
            String::from_utf8_lossy(&out.stderr)
        );
        if let Ok(keep) = std::env::var("WHITTED_E2E_SHOTS") {
            let _ = std::fs::copy(&path, Path::new(&keep).join(format!("{name}.png")));
        }
        image::open(&path).unwrap().to_rgb8()
    }
}

impl Drop for Session {
    fn drop(&mut self) {
        // a failed test leaves no window behind (the X server goes after it, field order)
        stop(&mut self.child);
    }
}

/// Renders the scene file to a PNG with the chapter binary's `-o`, with extra arguments.
fn reference(bin: &Path, scene: &Path, dir: &Path, name: &str, args: &[&str]) -> image::RgbImage {
    let png = dir.join(format!("{name}.png"));
    let out = Command::new(bin)
        .arg(scene)
        .args(["-q", "-o"])
        .arg(&png)
        .args(args)
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    image::open(&png).unwrap().to_rgb8()
}

/// The share of pixels that differ by more than 2 in some channel.
fn differing(a: &image::RgbImage, b: &image::RgbImage) -> f64 {
    assert_eq!(a.dimensions(), b.dimensions());
    let n = a
        .pixels()
        .zip(b.pixels())
        .filter(|(p, q)| p.0.iter().zip(q.0).any(|(x, y)| x.abs_diff(y) > 2))
        .count();
    n as f64 / f64::from(a.width() * a.height())
}

/// Writes `text` over `path` as editors do: a new file renamed into place.
fn save_by_rename(path: &Path, text: &str) {
    let tmp = path.with_extension("toml.swp");
    std::fs::write(&tmp, text).unwrap();
    std::fs::rename(&tmp, path).unwrap();
}

impl Session {
    /// Starts an X server and `chapter`'s binary on it with `args` and `--window`, its
    /// stdout and stderr going to files in `dir`; waits for its window.
    fn open(chapter: Chapter, args: &[&std::ffi::OsStr], dir: tempfile::TempDir) -> Self {
        let alone = ONE_WINDOW
            .lock()
            .unwrap_or_else(std::sync::PoisonError::into_inner);
        let x = Xvfb::start();
        let (stdout, stderr) = (dir.path().join("out.txt"), dir.path().join("err.txt"));
        let child = Command::new(common::exe(chapter))
            .args(args)
            .arg("--window")
            .env("DISPLAY", &x.display)
            .stdout(std::fs::File::create(&stdout).unwrap())
            .stderr(std::fs::File::create(&stderr).unwrap())
            .spawn()
            .unwrap();
        let window = xdotool(
            &x.display,
            &["search", "--sync", "--name", chapter.about().binary],
        )
        .lines()
        .next()
        .unwrap()
        .to_string();
        let geo = xdotool(&x.display, &["getwindowgeometry", "--shell", &window]);
        let field = |k: &str| -> u32 {
            geo.lines()
                .find_map(|l| l.strip_prefix(&format!("{k}=")))
                .unwrap()
                .parse()
                .unwrap()
        };
        let geometry = (field("X"), field("Y"), field("WIDTH"), field("HEIGHT"));
        Self {
            x,
            child,
            window,
            geometry,
            stdout,
            stderr,
            dir,
            _alone: alone,
        }
    }

    /// The window's title now.
    fn title(&self) -> String {
        xdotool(&self.x.display, &["getwindowname", &self.window])
    }
}

#[test]
#[ignore = "needs Xvfb, xdotool and ImageMagick: .ci/run installs them and runs it"]
fn the_window_refines_inspects_reloads_and_obeys_every_key() {
    let bin = &common::exe(LAST);
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("scene.toml");
    std::fs::write(&scene, whitted_app::cli::SHOWCASE).unwrap();
    let saved = dir.path().join("saved.png");
    let mut s = Session::open(
        LAST,
        &[scene.as_os_str(), "-o".as_ref(), saved.as_os_str()],
        dir,
    );
    assert_eq!(
        (s.geometry.2, s.geometry.3),
        (640, 480),
        "the showcase's size"
    );
    let refs = tempfile::tempdir().unwrap();

    // 1. it refines to the image -o writes
    s.wait_for(true, "image complete: chapter 5, view color", 0);
    std::thread::sleep(Duration::from_millis(200));
    let first = s.shot("01-refined");
    let want = reference(bin, &scene, refs.path(), "color", &[]);
    assert!(
        differing(&first, &want) < 0.001,
        "{}",
        differing(&first, &want)
    );

    // 2. a click prints the ray tree and draws it; the image under it is unchanged elsewhere
    s.click(365, 255);
    s.wait_for(false, "pixel (365, 255), chapter 5", 0);
    std::thread::sleep(Duration::from_millis(200));
    let tree = s.shot("02-ray-tree");
    let drawn = differing(&tree, &first);
    assert!(drawn > 0.002 && drawn < 0.2, "overlay covers {drawn}");
    assert_eq!(
        tree.get_pixel(365 + 6, 255).0,
        [255, 255, 255],
        "the ring round the pixel"
    );
    let text = std::fs::read_to_string(&s.stdout).unwrap();
    assert!(text.contains("camera ray r(t) = e + d·t") && text.contains("transmitted ray"));

    // 2b. made twice as large, the window maps a click to the same pixel, and draws sharp
    xdotool(&s.x.display, &["windowsize", &s.window, "1280", "960"]);
    std::thread::sleep(Duration::from_millis(300));
    s.click(730, 510);
    s.wait_for(false, "pixel (365, 255), chapter 5", 1);
    std::thread::sleep(Duration::from_millis(200));
    let (x0, y0, w0, h0) = s.geometry;
    s.geometry = (x0, y0, 1280, 960);
    let large = s.shot("02b-resized");
    // the ring round the pixel's centre (731, 511), 6 window pixels to its right, 1 pixel wide
    assert_eq!(large.get_pixel(737, 511).0, [255, 255, 255]);
    assert_ne!(large.get_pixel(739, 511).0, [255, 255, 255]);
    xdotool(&s.x.display, &["windowsize", &s.window, "640", "480"]);
    s.geometry = (x0, y0, w0, h0);
    std::thread::sleep(Duration::from_millis(300));

    // 3. V: the next view, flat
    s.key_and_render("v");
    s.wait_for(true, "view flat", 0);
    let flat = reference(bin, &scene, refs.path(), "flat", &["--view", "flat"]);
    assert!(differing(&s.shot("03-flat"), &flat) < 0.001);
    for (i, view) in ["normals", "depth", "shadows", "rays", "color"]
        .iter()
        .enumerate()
    {
        s.key_and_render("v");
        s.wait_for(true, &format!("view {view}"), 0);
        let want = reference(bin, &scene, refs.path(), view, &["--view", view]);
        let mut got = s.shot(&format!("04-{i}-{view}"));
        if *view == "rays" {
            // the heat scale's legend, bottom left: white frame, black (1 ray) to white
            let (l, r) = (*got.get_pixel(6, 470), *got.get_pixel(133, 470));
            assert_eq!((l.0, r.0), ([0, 0, 0], [255, 255, 255]), "the legend");
            assert_eq!(got.get_pixel(5, 470).0, [255, 255, 255], "its frame");
            // compare the rest of the image
            for y in 460..480 {
                for x in 0..140 {
                    got.put_pixel(x, y, *want.get_pixel(x, y));
                }
            }
        }
        assert!(
            differing(&got, &want) < 0.001,
            "view {view}: {}",
            differing(&got, &want)
        );
    }

    // 4. the digits: the chapters; 3 is chapter 3's image, as its binary renders it
    s.key_and_render("3");
    s.wait_for(true, "chapter 3, view color", 0);
    let ch3 = reference(
        &common::exe(Chapter::Shading),
        &scene,
        refs.path(),
        "ch03",
        &[],
    );
    assert!(differing(&s.shot("05-chapter3"), &ch3) < 0.001);
    for chapter in Chapter::ALL.into_iter().filter(|&c| c != Chapter::Shading) {
        let digit = chapter.number().to_string();
        s.key_and_render(&digit);
        s.wait_for(true, &format!("chapter {digit}, "), 0);
    }

    // 5. -/+: depth 4 differs from depth 5 in the mirror, then back
    s.key_and_render("minus");
    s.key_and_render("minus");
    let shallow = s.shot("06-depth3");
    let want = reference(bin, &scene, refs.path(), "depth3", &["--max-depth", "3"]);
    assert!(differing(&shallow, &want) < 0.001);
    s.key_and_render("plus");
    s.key_and_render("equal");
    assert!(differing(&s.shot("07-depth5"), &first) < 0.001);

    // 6. C prints the camera; W moves it forward, arrows turn it, Q/E/A/S/D move it
    let n = s.count(false, "[camera]");
    s.key("c");
    s.wait_for(false, "[camera]", n);
    assert!(
        std::fs::read_to_string(&s.stdout)
            .unwrap()
            .contains("eye = [0, 2.4, 8.5]")
    );
    let mut before = first.clone();
    for key in ["w", "s", "a", "d", "q", "e", "Left", "Right", "Up", "Down"] {
        s.key_and_render(key);
        let moved = s.shot(&format!("08-{key}"));
        assert!(differing(&moved, &before) > 0.01, "{key} moved nothing");
        before = moved;
    }
    // each key above undid the one before it: one more step forward, and the camera moved
    s.key_and_render("w");
    let n = s.count(false, "[camera]");
    s.key("c");
    s.wait_for(false, "[camera]", n);
    let last_camera = std::fs::read_to_string(&s.stdout).unwrap();
    let last_camera = last_camera.rsplit("[camera]").next().unwrap();
    // 5% of the distance to the point looked at, |(0, 1.5, 8.5)| = 8.631, along its direction
    assert!(
        last_camera.contains("eye = [0, 2.325, 8.075]"),
        "{last_camera}"
    );

    // 7. P saves what is on screen
    let n = s.count(false, "wrote");
    s.key("p");
    s.wait_for(false, "wrote", n);
    let png = image::open(&saved).unwrap().to_rgb8();
    assert!(differing(&png, &s.shot("09-saved")) < 0.001);

    // 8. saving the scene file (by rename, as editors do) reloads it: a red background
    let red = whitted_app::cli::SHOWCASE.replace(
        "background = [0.05, 0.06, 0.10]",
        "background = [1.0, 0.0, 0.0]",
    );
    assert_ne!(red, whitted_app::cli::SHOWCASE);
    let n = s.count(false, "scene reloaded");
    save_by_rename(&scene, &red);
    s.wait_for(false, "scene reloaded", n);
    s.wait_for(true, "image complete", s.count(true, "image complete"));
    std::thread::sleep(Duration::from_millis(200));
    assert_eq!(s.shot("10-reloaded").get_pixel(2, 2).0, [255, 0, 0]);
    // a broken file: one error line, the last good image stays
    let n = s.count(true, "error: ");
    save_by_rename(&scene, "[camera]\neye = [0, 0\n");
    s.wait_for(true, "error: ", n);
    std::thread::sleep(Duration::from_millis(400));
    let err = std::fs::read_to_string(&s.stderr).unwrap();
    assert!(err.contains("scene.toml:"), "{err}");
    assert_eq!(s.shot("11-kept").get_pixel(2, 2).0, [255, 0, 0]);
    let title = s.title();
    assert!(title.contains("error: "), "{title}");
    // R reloads by hand: the file fixed again
    std::fs::write(&scene, whitted_app::cli::SHOWCASE).unwrap();
    let n = s.count(false, "scene reloaded");
    s.key("r");
    s.wait_for(false, "scene reloaded", n);

    // 9. H prints the keys, as the keymap writes them; Tab, with no reference, says how to
    // give one; Esc quits with status 0
    let help = whitted_app::window::keys::help();
    let n = s.count(false, &help);
    s.key("h");
    s.wait_for(false, &help, n);
    let n = s.count(false, "no reference to compare with");
    s.key("Tab");
    s.wait_for(false, "no reference to compare with", n);
    quit(&mut s);
}

/// Esc closes the window, and the program ends with status 0.
fn quit(s: &mut Session) {
    s.key("Escape");
    let start = Instant::now();
    let status = loop {
        if let Some(status) = s.child.try_wait().unwrap() {
            break status;
        }
        assert!(
            start.elapsed() < Duration::from_secs(10),
            "Esc did not close the window"
        );
        std::thread::sleep(Duration::from_millis(50));
    };
    assert!(status.success(), "{status}");
}

/// `image` scaled to `w` × `h` by the nearest pixel, as the window scales what it shows.
fn scaled(image: &image::RgbImage, w: u32, h: u32) -> image::RgbImage {
    let (iw, ih) = image.dimensions();
    image::RgbImage::from_fn(w, h, |x, y| *image.get_pixel(x * iw / w, y * ih / h))
}

/// With `--compare REF.png`, Tab shows the reference, then the difference, then the render
/// again; the reference here is chapter 3's figure with a blue square painted in, so the
/// difference marks exactly that square, red. The title counts it, and says when the camera
/// has moved from the scene's.
#[test]
#[ignore = "needs Xvfb, xdotool and ImageMagick: .ci/run installs them and runs it"]
fn the_compare_key_shows_the_reference_and_the_difference() {
    const CHAPTER: Chapter = Chapter::Shading;
    let dir = tempfile::tempdir().unwrap();
    let figure = common::root().join(CHAPTER.about().figure());
    let mut reference = image::open(&figure).unwrap().to_rgb8();
    assert_eq!(reference.dimensions(), (240, 120), "the chapter's figure");
    // a 20 × 20 square on the dark background, top left
    for y in 8..28 {
        for x in 8..28 {
            reference.put_pixel(x, y, image::Rgb([0, 0, 255]));
        }
    }
    let ref_png = dir.path().join("ref.png");
    reference.save(&ref_png).unwrap();
    let scene = common::scene(CHAPTER);
    let mut s = Session::open(
        CHAPTER,
        &[scene.as_os_str(), "--compare".as_ref(), ref_png.as_os_str()],
        dir,
    );
    // the scene's own size, 480 × 240: the reference shows twice as large
    let (w, h) = (s.geometry.2, s.geometry.3);
    assert_eq!((w, h), (480, 240), "chapter 3's scene's size");
    s.wait_for(true, "image complete: chapter 3", 0);
    std::thread::sleep(Duration::from_millis(200));
    let render = s.shot("20-render");

    // Tab: the reference, scaled to the window; the comparison is made on the side
    s.key("Tab");
    s.wait_for(false, "compare: ", 0);
    std::thread::sleep(Duration::from_millis(200));
    let shown = s.shot("21-reference");
    let want = scaled(&reference, w, h);
    assert!(
        differing(&shown, &want) < 0.001,
        "{}",
        differing(&shown, &want)
    );
    assert_eq!(shown.get_pixel(36, 36).0, [0, 0, 255], "the square, scaled");
    let line = std::fs::read_to_string(&s.stdout).unwrap();
    assert!(
        line.contains("compare: 400 of 28800 pixels differ by more than 2/255 (1.39%), by up to ")
            && line.contains("; the first at (8, 8)"),
        "{line}"
    );
    let title = s.title();
    assert!(
        title.contains("the reference") && title.contains("400 of 28800 pixels differ"),
        "{title}"
    );

    // Tab: the difference: the square red, the rest the reference in grey
    s.key("Tab");
    std::thread::sleep(Duration::from_millis(300));
    let difference = s.shot("22-difference");
    assert_eq!(
        difference.get_pixel(36, 36).0,
        [255, 0, 0],
        "the square, marked"
    );
    let grey = difference.get_pixel(240, 200).0;
    assert!(grey[0] == grey[1] && grey[1] == grey[2], "{grey:?}");
    assert!(
        differing(&difference, &shown) > 0.1,
        "the difference is not the reference"
    );
    let marked = difference.pixels().filter(|p| p.0 == [255, 0, 0]).count();
    assert_eq!(
        marked,
        40 * 40,
        "the square, twice as large, and nothing else red"
    );
    assert!(s.title().contains("the difference"), "{}", s.title());

    // W moves the camera: the comparison stays (it is for the scene's camera), and says so
    s.key("w");
    std::thread::sleep(Duration::from_millis(300));
    let title = s.title();
    assert!(
        title.contains("for the scene's camera") && title.contains("400 of 28800"),
        "{title}"
    );
    assert_eq!(s.count(false, "compare: "), 1, "no new comparison");
    assert!(differing(&s.shot("23-moved"), &difference) < 0.001);

    // Tab: the live render again, from the moved camera
    s.wait_for(true, "image complete: chapter 3", 1);
    s.key("Tab");
    std::thread::sleep(Duration::from_millis(300));
    let moved = s.shot("24-render-again");
    assert!(differing(&moved, &difference) > 0.1, "back to the render");
    assert!(
        differing(&moved, &render) > 0.01,
        "the moved camera's render"
    );
    assert!(!s.title().contains("pixels differ"), "{}", s.title());
    quit(&mut s);
}
