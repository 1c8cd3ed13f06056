//! The minifb shell: opens the window, reads the keys and the mouse once a frame, feeds them
//! to the [`State`], carries out its [`Command`]s, and puts the [`Canvas`] on screen.
//!
//! The loop never waits on rendering: the [`Worker`] renders on its own thread, and the loop
//! only takes what has arrived since the last frame. minifb samples the keyboard once per
//! `update`, so a loop blocked for a whole render would lose the taps made meanwhile.
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use std::path::{Path, PathBuf};
use std::sync::Arc;
use std::time::{Duration, Instant, SystemTime};

use minifb::{Key, KeyRepeat, MouseButton, MouseMode, ScaleMode, Window, WindowOptions};

use super::canvas::{self, Canvas};
use super::comparison::Comparer;
use super::keys;
use super::overlay::Overlay;
use super::progressive::{Update, Worker};
use super::schedule::PASSES;
use super::state::{Command, Input, Picture, State};
use crate::cli::reference::Reference;
use whitted::accel::Accelerator;
use whitted::error::Error;
use whitted::output::{self, Encoding};
use whitted::real::Real;
use whitted::render::views::{self, Scales};
use whitted::render::{Chapter, Options, Tracer, View};
use whitted::scene::{self, Scene};

/// What the window starts from.
pub struct Setup {
    /// The scene file, if any (without one, the built-in showcase: nothing to reload).
    pub scene_path: Option<PathBuf>,
    /// The scene as loaded.
    pub scene: Scene,
    /// The options from the command line (chapter, view, size …).
    pub options: Options,
    /// The binary's own chapter (its name is the window's title).
    pub max_chapter: Chapter,
    /// How the screen and the saved PNG encode intensities.
    pub encoding: Encoding,
    /// Where `P` saves.
    pub save_to: PathBuf,
    /// No help at the start and no line per finished image.
    pub quiet: bool,
    /// The reference image of `--compare`, which the compare key shows.
    pub reference: Option<Reference>,
}

/// The scene file is polled this often for changes.
const POLL: Duration = Duration::from_millis(250);

/// Opens the window and runs it until Esc or the window is closed.
pub fn run(setup: Setup) -> Result<(), Error> {
    let (w, h) = (setup.options.width, setup.options.height);
    let binary = setup.max_chapter.about().binary;
    let mut window = open(binary, w as usize, h as usize)?;
    let worker = Worker::spawn(0)?;
    let mut state = State::new(setup.scene, setup.options, setup.max_chapter);
    let comparer = match setup.reference {
        Some(reference) => {
            state = state.with_reference(reference.image.size());
            Some(Comparer::new(reference, setup.encoding)?)
        }
        None => None,
    };
    let mut shell = Shell {
        state,
        comparer,
        canvas: Canvas::new(w, h, setup.encoding),
        overlay: None,
        accel: None,
        scales: None,
        worker,
        binary,
        scene_path: setup.scene_path,
        max_chapter: setup.max_chapter,
        save_to: setup.save_to,
        quiet: setup.quiet,
        failure: None,
        started: Instant::now(),
    };
    if !shell.quiet {
        eprintln!("{}", keys::help());
    }
    let bindings = keys::bindings();
    shell.execute(Command::Render);
    let mut stamp = shell.scene_path.as_deref().map(FileStamp::of);
    let mut polled = Instant::now();
    let mut mouse_was_down = false;
    let mut frame = Vec::new();
    let mut title = String::new();
    while window.is_open() {
        let mut inputs = Vec::new();
        let fast = window.is_key_down(Key::LeftShift) || window.is_key_down(Key::RightShift);
        for b in &bindings {
            let repeat = if b.action.repeats() {
                KeyRepeat::Yes
            } else {
                KeyRepeat::No
            };
            if window.is_key_pressed(b.key, repeat) {
                inputs.push(Input::Key {
                    action: b.action,
                    fast,
                });
            }
        }
        let down = window.get_mouse_down(MouseButton::Left);
        if down
            && !mouse_was_down
            && let Some(mouse) = window.get_unscaled_mouse_pos(MouseMode::Discard)
        {
            inputs.push(Input::Click {
                mouse,
                window: window.get_size(),
            });
        }
        mouse_was_down = down;
        if let Some(path) = &shell.scene_path
            && polled.elapsed() >= POLL
        {
            polled = Instant::now();
            let now = FileStamp::of(path);
            if stamp.as_ref() != Some(&now) {
                stamp = Some(now);
                inputs.push(Input::Loaded(Box::new(scene::load_parts(
                    path,
                    shell.max_chapter.reads(),
                ))));
            }
        }
        let mut quit = false;
        for input in inputs {
            for command in shell.state.handle(input) {
                quit |= shell.execute(command);
            }
        }
        if quit {
            break;
        }
        shell.take_updates();
        // the frame is the window's size: the image scaled, the drawing sharp on top
        let (fw, fh) = match window.get_size() {
            (0, _) | (_, 0) => (w, h),
            (fw, fh) => (fw as u32, fh as u32),
        };
        let compared = shell.comparer.as_ref().and_then(|c| {
            let screen = c.screen(shell.state.picture)?;
            Some((screen, c.size()))
        });
        if let Some((screen, size)) = compared {
            canvas::scale(screen, size, &mut frame, (fw, fh));
        } else {
            shell.canvas.blit(&mut frame, fw, fh);
            if let Some(o) = &shell.overlay {
                let scale = (fw as Real / w as Real, fh as Real / h as Real);
                o.draw(&mut frame, fw, fh, scale);
            }
            if shell.state.options.view == View::Rays {
                heat_legend(&mut frame, fw, fh, &shell.canvas);
            }
        }
        window
            .update_with_buffer(&frame, fw as usize, fh as usize)
            .map_err(|e| Error::Window(e.to_string()))?;
        let now = shell.title();
        if now != title {
            window.set_title(&now);
            title = now;
        }
    }
    Ok(())
}

/// Opens the window, or says in one line why it cannot.
fn open(binary: &str, w: usize, h: usize) -> Result<Window, Error> {
    if std::env::var_os("DISPLAY").is_none_or(|d| d.is_empty()) {
        return Err(Error::Window("DISPLAY is not set: no X display".into()));
    }
    let options = WindowOptions {
        resize: true,
        scale_mode: ScaleMode::Stretch,
        ..WindowOptions::default()
    };
    // minifb panics on a few X failures instead of returning them
    let opened = std::panic::catch_unwind(|| Window::new(binary, w, h, options));
    let mut window = match opened {
        Ok(Ok(window)) => window,
        Ok(Err(e)) => return Err(Error::Window(e.to_string())),
        Err(payload) => {
            return Err(Error::Window(
                whitted::error::panic_message(payload.as_ref()).to_string(),
            ));
        }
    };
    window.set_target_fps(60);
    Ok(window)
}

/// A file's modification time and length: a save changes one or the other.
#[derive(Debug, PartialEq)]
struct FileStamp(Option<(SystemTime, u64)>);

impl FileStamp {
    fn of(path: &Path) -> Self {
        Self(
            std::fs::metadata(path)
                .ok()
                .and_then(|m| Some((m.modified().ok()?, m.len()))),
        )
    }
}

/// The window's state and what it drives.
struct Shell {
    state: State,
    /// The comparison with the reference of `--compare`.
    comparer: Option<Comparer>,
    canvas: Canvas,
    overlay: Option<Overlay>,
    /// The acceleration structure of the current generation, once the worker has built it.
    accel: Option<(u64, Arc<Accelerator>)>,
    worker: Worker,
    /// The binary's name: the title's start.
    binary: &'static str,
    scene_path: Option<PathBuf>,
    /// The chapter of the binary, whose parts of the scene file a reload reads.
    max_chapter: Chapter,
    save_to: PathBuf,
    quiet: bool,
    /// The depth and rays views' scales of the current generation.
    scales: Option<Scales>,
    /// Why the current generation's render failed.
    failure: Option<String>,
    started: Instant,
}

impl Shell {
    /// Carries out one command; returns whether it was Quit.
    fn execute(&mut self, command: Command) -> bool {
        match command {
            Command::Render => {
                let generation = self
                    .worker
                    .submit(Arc::clone(&self.state.scene), self.state.options.clone());
                self.canvas.expect(generation);
                self.overlay = None;
                self.failure = None;
                self.scales = None;
                self.started = Instant::now();
            }
            Command::Print(text) => println!("{text}"),
            Command::Error(text) => eprintln!("error: {text}"),
            Command::Inspect { x, y } => self.inspect(x, y),
            Command::Save => self.save(),
            Command::Reload => match &self.scene_path {
                Some(path) => {
                    let loaded = Box::new(scene::load_parts(path, self.max_chapter.reads()));
                    for command in self.state.handle(Input::Loaded(loaded)) {
                        self.execute(command);
                    }
                }
                None => println!("the built-in showcase has no file to reload: name a scene file"),
            },
            Command::Compare => {
                if let (Some(c), Some(options)) = (&mut self.comparer, self.state.compare_options())
                {
                    c.ask(&self.state.scene, options);
                }
            }
            Command::Quit => return true,
        }
        false
    }

    /// Takes every update that has arrived, without waiting: the live render's, and the
    /// comparison's (its line goes to stdout, as `--compare` prints it).
    fn take_updates(&mut self) {
        match self.comparer.as_mut().and_then(Comparer::take) {
            Some(Ok(line)) => println!("{line}"),
            Some(Err(message)) => eprintln!("error: {message}"),
            None => {}
        }
        while let Some(update) = self.worker.try_update() {
            if !self.canvas.apply(&update) {
                continue; // an older generation's
            }
            match update {
                Update::Ready {
                    generation,
                    accel,
                    scales,
                } => {
                    self.accel = Some((generation, accel));
                    self.scales = Some(scales);
                }
                Update::Failed { message, .. } => {
                    eprintln!("error: {message}");
                    self.failure = Some(message);
                }
                Update::PassDone {
                    pass,
                    elapsed,
                    stats,
                    ..
                } if pass + 1 == PASSES && !self.quiet => {
                    let o = &self.state.options;
                    eprintln!(
                        "image complete: chapter {}, view {}, {}×{} in {:.3} s, {:.2} M rays/s",
                        o.chapter.number(),
                        o.view.name(),
                        o.width,
                        o.height,
                        elapsed.as_secs_f64(),
                        stats.total() as f64 / elapsed.as_secs_f64().max(1e-9) / 1e6
                    );
                }
                _ => {}
            }
        }
    }

    /// Prints the ray tree of pixel (x, y) and draws it over the image.
    fn inspect(&mut self, x: u32, y: u32) {
        let scene = Arc::clone(&self.state.scene);
        let options = self.state.options.clone();
        let accel = self
            .accel
            .as_ref()
            .filter(|(g, _)| *g == self.worker.generation())
            .map(|(_, a)| Arc::clone(a));
        let run = std::panic::AssertUnwindSafe(|| {
            let tracer = match &accel {
                Some(a) => Tracer::with_accel(&scene, &options, a),
                None => Tracer::new(&scene, &options),
            };
            let tree = tracer.inspect(x, y);
            let c = self.state.camera();
            let far = 1e3 * (c.look_at - c.eye).length().max(1.0 as Real);
            (tree.to_string(), Overlay::new(&tree, tracer.camera(), far))
        });
        match std::panic::catch_unwind(run) {
            Ok((text, overlay)) => {
                print!("{text}");
                self.overlay = Some(overlay);
            }
            Err(payload) => eprintln!(
                "error: {}",
                whitted::error::missing_exercise(payload.as_ref()).unwrap_or_else(|| format!(
                    "inspecting pixel {x},{y} panicked: {}",
                    whitted::error::panic_message(payload.as_ref())
                ))
            ),
        }
    }

    /// Saves the image as it is now (a preview if the last pass is not done).
    fn save(&self) {
        let c = &self.canvas;
        match output::save(&c.fb, &self.save_to, c.encoding) {
            Ok(()) if c.complete() => println!("wrote {}", self.save_to.display()),
            Ok(()) => println!(
                "wrote {} (a preview: {} of {PASSES} passes done)",
                self.save_to.display(),
                c.passes_done
            ),
            Err(e) => eprintln!("error: {e}"),
        }
    }

    /// chapter, view, depth, pass, time and M rays/s, and the last error if any; for the
    /// reference and the difference, which they are, the count of pixels that differ, and
    /// whether the camera has moved from the scene's (which they are for).
    fn title(&self) -> String {
        if let Some(c) = &self.comparer
            && self.state.picture != Picture::Render
        {
            return self.comparison_title(c);
        }
        let o = &self.state.options;
        let c = &self.canvas;
        let mut t = format!(
            "{} — chapter {} · {} · depth {} · pass {}/{PASSES}",
            self.binary,
            o.chapter.number(),
            o.view.name(),
            o.max_depth,
            c.passes_done
        );
        match c.last {
            Some((stats, elapsed)) => {
                let s = elapsed.as_secs_f64();
                t += &format!(
                    " · {:.0} ms · {:.1} M rays/s",
                    s * 1e3,
                    stats.total() as f64 / s.max(1e-9) / 1e6
                );
            }
            // the time since the change, running until a pass is done (not after a failure)
            None if self.failure.is_none() => {
                t += &format!(" · {:.0} ms", self.started.elapsed().as_secs_f64() * 1e3);
            }
            None => {}
        }
        match (o.view, &self.scales) {
            (View::Rays, Some(s)) => {
                t += &format!(" · rays a pixel: 1 black … {} white", s.rays_max);
            }
            (
                View::Depth,
                Some(Scales {
                    depth: Some((near, far)),
                    ..
                }),
            ) => {
                t += &format!(" · distance: {near:.3} white … {far:.3} grey");
            }
            _ => {}
        }
        if let Some(e) = self.failure.as_ref().or(self.state.error.as_ref()) {
            t += &format!(" · error: {e}");
        }
        t
    }

    /// The title while the reference or the difference is shown.
    fn comparison_title(&self, c: &Comparer) -> String {
        let o = &self.state.options;
        let (w, h) = c.size();
        let mut t = format!(
            "{} — {} ({}, {w}×{h}) · chapter {} · {} · depth {} · {}",
            self.binary,
            self.state.picture.name(),
            c.path.display(),
            o.chapter.number(),
            o.view.name(),
            o.max_depth,
            c.status()
        );
        if self.state.camera_moved() {
            t += " · for the scene's camera, not the moved one";
        }
        if let Some(e) = &self.state.error {
            t += &format!(" · error: {e}");
        }
        t
    }
}

/// The rays view's scale, bottom left: the heat colours from one ray (left) to the most a
/// pixel can cast (right); the title gives the numbers.
fn heat_legend(frame: &mut [u32], w: u32, h: u32, canvas: &Canvas) {
    let (lw, lh) = (128.min(w.saturating_sub(8)), 10);
    if w < 24 || h < lh + 8 {
        return;
    }
    let top = h - lh - 6;
    for y in top - 1..top + lh + 1 {
        for x in 5..lw + 7 {
            let inside = y >= top && y < top + lh && x >= 6 && x < lw + 6;
            let colour = if inside {
                let f = (x - 6) as Real / (lw - 1).max(1) as Real;
                canvas.screen_pixel(views::heat(f))
            } else {
                0xff_ffff
            };
            frame[(y * w + x) as usize] = colour;
        }
    }
}
