//! The window's logic as a state machine: an [`Input`] (a key, a click, a reloaded scene)
//! changes the [`State`] and returns the [`Command`]s the shell carries out (render, print,
//! inspect, save, reload, quit). Nothing here touches a display, so every binding and rule is
//! tested without one. The keys and what each asks for are the keymap's ([`super::keys`]).
//!
//! With a reference image (`--compare REF.png`) the state also says which [`Picture`] is
//! shown: the live render, the reference, or the difference. The last two are about the
//! student's image rendered at the reference's size with the scene file's camera
//! ([`State::compare_options`]): moving the camera changes the live render, not them.
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use std::sync::Arc;

use super::camera::{FAST, MOVE_SHARE, TURN_DEGREES, camera_table, moved, turned};
use crate::cli::offers::{OBJECTS_FROM, TRACING_FROM};
use whitted::error::Error;
use whitted::render::{Chapter, Options, View};
use whitted::scene::load::MAX_DEPTH;
use whitted::scene::{CameraSettings, Scene};

/// The actions the keys ask for, which [`Input::Key`] carries.
pub use super::action::{Action, Move, Turn};

/// What the window is told.
#[derive(Debug)]
pub enum Input {
    /// A bound key was pressed (`fast`: with Shift).
    Key {
        /// What the key does.
        action: Action,
        /// Shift was held.
        fast: bool,
    },
    /// The left button was pressed at `mouse` (unscaled window coordinates) in a window
    /// whose drawing area is `window` (width, height) pixels now.
    Click {
        /// The pointer, in window pixels from the top left.
        mouse: (f32, f32),
        /// The window's current size.
        window: (usize, usize),
    },
    /// The scene file was read again.
    Loaded(Box<Result<Scene, Error>>),
}

/// What the shell must do.
#[derive(Debug, PartialEq)]
pub enum Command {
    /// Cancel the render in flight and render the state's scene and options afresh.
    Render,
    /// Print a line (or several) on standard output.
    Print(String),
    /// Print `error: …` on standard error.
    Error(String),
    /// Print the ray tree of pixel (x, y) and draw it over the image.
    Inspect {
        /// Column from the left.
        x: u32,
        /// Row from the top.
        y: u32,
    },
    /// Save the image as a PNG.
    Save,
    /// Read the scene file again (the answer comes back as [`Input::Loaded`]).
    Reload,
    /// Compare the student's image with the reference for the state's
    /// [`State::compare_options`], unless that comparison is already made or under way.
    Compare,
    /// Close the window.
    Quit,
}

/// What the window shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Picture {
    /// The live render, refined pass by pass.
    Render,
    /// The reference image of `--compare`.
    Reference,
    /// The reference in grey with the pixels that differ marked ([`crate::compare`]).
    Difference,
}

impl Picture {
    /// The pictures in the order the compare key shows them.
    pub const ALL: [Self; 3] = [Self::Render, Self::Reference, Self::Difference];

    /// How the title and the help name it.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            Self::Render => "your render",
            Self::Reference => "the reference",
            Self::Difference => "the difference",
        }
    }

    /// The one the compare key shows after this one.
    #[must_use]
    pub fn next(self) -> Self {
        let i = Self::ALL.iter().position(|&p| p == self).unwrap_or(0);
        Self::ALL[(i + 1) % Self::ALL.len()]
    }
}

/// The window's state: the last good scene and everything the keys change.
#[derive(Clone, Debug)]
pub struct State {
    /// The scene shown: the last one that loaded without error.
    pub scene: Arc<Scene>,
    /// Chapter, view, depth, size, and the camera as moved (always `Some`).
    pub options: Options,
    /// The binary's own chapter: the highest chapter the keys reach.
    pub max_chapter: Chapter,
    /// Samples per pixel from [`TRACING_FROM`] on (earlier chapters take one).
    pub samples: u32,
    /// The camera as the scene file last said it (a reload keeps the moved camera unless the
    /// file's camera changed).
    pub file_camera: CameraSettings,
    /// The last reload's error, shown in the title until a reload succeeds.
    pub error: Option<String>,
    /// The size of the reference image, (width, height), with `--compare`.
    pub reference: Option<(u32, u32)>,
    /// What the window shows: always [`Picture::Render`] without a reference.
    pub picture: Picture,
}

impl State {
    /// The state for `scene` rendered with `options` by a binary whose chapter is `max_chapter`.
    #[must_use]
    pub fn new(scene: Scene, mut options: Options, max_chapter: Chapter) -> Self {
        let file_camera = scene.camera.clone();
        options.camera.get_or_insert_with(|| file_camera.clone());
        Self {
            samples: options.samples,
            scene: Arc::new(scene),
            options,
            max_chapter,
            file_camera,
            error: None,
            reference: None,
            picture: Picture::Render,
        }
    }

    /// The state with a reference image of `size` (width, height) to compare with.
    #[must_use]
    pub fn with_reference(mut self, size: (u32, u32)) -> Self {
        self.reference = Some(size);
        self
    }

    /// What the comparison renders: the state's scene, chapter, view and depth at the
    /// reference's size with the scene file's camera (the reference cannot follow a moved
    /// camera); `None` without a reference.
    #[must_use]
    pub fn compare_options(&self) -> Option<Options> {
        let (width, height) = self.reference?;
        Some(Options {
            width,
            height,
            camera: Some(self.file_camera.clone()),
            ..self.options.clone()
        })
    }

    /// Whether the camera has moved away from the scene file's.
    #[must_use]
    pub fn camera_moved(&self) -> bool {
        self.options.camera.as_ref() != Some(&self.file_camera)
    }

    /// The camera as moved.
    #[must_use]
    pub fn camera(&self) -> &CameraSettings {
        self.options.camera.as_ref().unwrap_or(&self.scene.camera)
    }

    /// Takes one input and says what to do. While the reference or the difference is shown,
    /// every change that renders anew compares anew too.
    pub fn handle(&mut self, input: Input) -> Vec<Command> {
        let mut commands = match input {
            Input::Key { action, fast } => self.act(action, fast),
            Input::Click { .. } if self.picture != Picture::Render => {
                vec![Command::Print(format!(
                    "a click inspects your render, and {} is shown: press {} to show your render",
                    self.picture.name(),
                    super::keys::label_of(Action::NextPicture)
                ))]
            }
            Input::Click { mouse, window } => {
                match click_to_pixel(mouse, window, (self.options.width, self.options.height)) {
                    Some((x, y)) => vec![Command::Inspect { x, y }],
                    None => vec![],
                }
            }
            Input::Loaded(result) => self.loaded(*result),
        };
        if self.picture != Picture::Render
            && commands.contains(&Command::Render)
            && !commands.contains(&Command::Compare)
        {
            commands.push(Command::Compare);
        }
        commands
    }

    fn act(&mut self, action: Action, fast: bool) -> Vec<Command> {
        let speed = if fast { FAST } else { 1.0 };
        match action {
            Action::Move(m) => self.set_camera(moved(self.camera(), m, MOVE_SHARE * speed)),
            Action::Turn(t) => self.set_camera(turned(self.camera(), t, TURN_DEGREES * speed)),
            Action::Depth(step) => self.change_depth(step),
            Action::Chapter(c) => self.change_chapter(c),
            Action::NextView => self.next_view(),
            Action::PrintCamera => vec![Command::Print(camera_table(self.camera()))],
            Action::Save => vec![Command::Save],
            Action::Reload => vec![Command::Reload],
            Action::NextPicture => self.next_picture(),
            Action::Help => vec![Command::Print(super::keys::help())],
            Action::Quit => vec![Command::Quit],
        }
    }

    fn set_camera(&mut self, camera: Option<CameraSettings>) -> Vec<Command> {
        match camera {
            Some(c) => {
                self.options.camera = Some(c);
                vec![Command::Render]
            }
            None => vec![Command::Print(
                "the camera cannot look straight along its up vector: turn the other way".into(),
            )],
        }
    }

    fn change_depth(&mut self, step: i32) -> Vec<Command> {
        let old = self.options.max_depth;
        let new = old.saturating_add_signed(step).min(MAX_DEPTH);
        if new == old {
            return vec![Command::Print(format!(
                "max depth stays {old} (from 0 to {MAX_DEPTH})"
            ))];
        }
        self.options.max_depth = new;
        if self.options.chapter >= TRACING_FROM {
            vec![Command::Render]
        } else {
            vec![Command::Print(format!(
                "max depth {new}: it matters from chapter {} (mirror and transmitted rays)",
                TRACING_FROM.number()
            ))]
        }
    }

    fn change_chapter(&mut self, chapter: Chapter) -> Vec<Command> {
        if chapter > self.max_chapter {
            return vec![Command::Print(format!(
                "chapter {} is past this binary's: {} goes up to chapter {}",
                chapter.number(),
                self.max_chapter.about().binary,
                self.max_chapter.number()
            ))];
        }
        if chapter == self.options.chapter {
            return vec![];
        }
        self.options.chapter = chapter;
        // supersampling comes with the tracing controls, as on the command line
        self.options.samples = if chapter >= TRACING_FROM {
            self.samples
        } else {
            1
        };
        vec![Command::Render]
    }

    fn next_view(&mut self) -> Vec<Command> {
        if self.options.chapter < OBJECTS_FROM {
            return vec![Command::Print(format!(
                "views start at chapter {}: chapter {} traces no objects, each pixel shows its ray's direction",
                OBJECTS_FROM.number(),
                self.options.chapter.number()
            ))];
        }
        let i = View::WINDOW
            .iter()
            .position(|&v| v == self.options.view)
            .unwrap_or(0);
        self.options.view = View::WINDOW[(i + 1) % View::WINDOW.len()];
        vec![Command::Render]
    }

    fn next_picture(&mut self) -> Vec<Command> {
        if self.reference.is_none() {
            let figure = self.options.chapter.about().figure();
            return vec![Command::Print(format!(
                "no reference to compare with: start the window with --compare REF.png, such as \
                 --compare {figure} (chapter {}'s figure, of the scene {})",
                self.options.chapter.number(),
                self.options.chapter.about().scene()
            ))];
        }
        self.picture = self.picture.next();
        match self.picture {
            Picture::Render => vec![],
            Picture::Reference | Picture::Difference => vec![Command::Compare],
        }
    }

    fn loaded(&mut self, result: Result<Scene, Error>) -> Vec<Command> {
        match result {
            Ok(scene) => {
                if scene.camera != self.file_camera {
                    // the file's camera was edited: show it
                    self.file_camera = scene.camera.clone();
                    self.options.camera = Some(scene.camera.clone());
                }
                self.scene = Arc::new(scene);
                self.error = None;
                vec![Command::Print("scene reloaded".into()), Command::Render]
            }
            Err(e) => {
                let line = e.to_string();
                self.error = Some(line.clone());
                vec![Command::Error(format!(
                    "{line} (the window keeps the last scene that loaded)"
                ))]
            }
        }
    }
}

/// The image pixel under the pointer at `mouse` (unscaled window coordinates) in a window of
/// `window` pixels showing an image of `image` pixels stretched over it; `None` outside the
/// window. minifb's own scaled position is wrong once the window has been resized, so the
/// pixel comes from the window's size now.
#[must_use]
pub fn click_to_pixel(
    mouse: (f32, f32),
    window: (usize, usize),
    image: (u32, u32),
) -> Option<(u32, u32)> {
    let (mx, my) = (f64::from(mouse.0), f64::from(mouse.1));
    let (ww, wh) = (window.0 as f64, window.1 as f64);
    if !(ww > 0.0 && wh > 0.0 && (0.0..ww).contains(&mx) && (0.0..wh).contains(&my)) {
        return None;
    }
    let x = ((mx * f64::from(image.0) / ww) as u32).min(image.0 - 1);
    let y = ((my * f64::from(image.1) / wh) as u32).min(image.1 - 1);
    Some((x, y))
}
