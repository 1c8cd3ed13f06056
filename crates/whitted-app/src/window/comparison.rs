//! The comparison with a reference image in the live window (`--window --compare REF.png`).
//!
//! The compare key shows the student's render, the reference and the difference in turn
//! ([`Picture`]). A reference is a picture of the scene file's camera at the reference's own
//! size, so the window cannot compare it with what it shows after the camera has moved or at
//! another size: [`Comparing`] renders the student's image anew, at the reference's size with
//! the scene's camera ([`super::state::State::compare_options`]), on a [`Worker`] of its own
//! (the window's loop never waits for it, and the live render goes on beside it), compares it
//! ([`crate::compare`]) and sends the result back. The [`Comparer`] keeps the latest result
//! and gives the window the pixels to show and the words for its title.
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use std::path::PathBuf;
use std::sync::Arc;
use std::sync::mpsc::Sender;
use std::time::Duration;

use super::progressive::{Job, Task, Worker};
use super::state::Picture;
use crate::cli::reference::Reference;
use crate::compare::{self, Comparison, Image};
use whitted::error::Error;
use whitted::output::Encoding;
use whitted::render::{Framebuffer, Options, Rect, Tracer, build_accel, render_rect};
use whitted::scene::Scene;

/// What the comparison's worker sends back.
#[derive(Debug)]
pub enum Compared {
    /// The job's image is rendered and compared.
    Done {
        /// The job's generation.
        generation: u64,
        /// How it differs from the reference.
        comparison: Box<Comparison>,
    },
    /// The job failed: an exercise not written yet, or a panic in the renderer.
    Failed {
        /// The job's generation.
        generation: u64,
        /// One line saying why.
        message: String,
    },
}

/// The comparison's task: renders a job's image whole (the tiles of the chapter binaries'
/// render, so the bytes are those `-o` writes) and compares it with the reference.
pub struct Comparing {
    reference: Arc<Image>,
    encoding: Encoding,
}

impl Comparing {
    /// The task for `reference`, comparing renders in `encoding`.
    #[must_use]
    pub fn new(reference: Arc<Image>, encoding: Encoding) -> Self {
        Self {
            reference,
            encoding,
        }
    }

    /// The job's image in the task's encoding, or `None` if it was cancelled first.
    fn render(
        &self,
        pool: &rayon::ThreadPool,
        job: &Job,
        cancel: &(dyn Fn() -> bool + Sync),
    ) -> Result<Option<Image>, Error> {
        let accel = pool.install(|| build_accel(&job.scene, &job.options));
        if cancel() {
            return Ok(None);
        }
        let tracer = Tracer::with_accel(&job.scene, &job.options, &accel);
        let (w, h) = (job.options.width, job.options.height);
        let mut fb = Framebuffer::new(w, h);
        let whole = Rect::new(0, 0, w, h);
        let finished = pool.install(|| render_rect(&tracer, whole, &mut fb, cancel, &|_| {}))?;
        Ok((!finished.is_cancelled()).then(|| Image::from_framebuffer(&fb, self.encoding)))
    }
}

impl Task for Comparing {
    type Update = Compared;

    fn run(
        &mut self,
        pool: &rayon::ThreadPool,
        job: &Job,
        cancel: &(dyn Fn() -> bool + Sync),
        updates: &Sender<Compared>,
    ) {
        let generation = job.generation;
        let compared = self.render(pool, job, cancel).and_then(|image| {
            image
                .map(|image| {
                    compare::compare(&image, &self.reference).map_err(|sizes| {
                        Error::Usage(format!(
                            "the comparison rendered {}×{}, the reference is {}×{}",
                            sizes.render.0, sizes.render.1, sizes.reference.0, sizes.reference.1
                        ))
                    })
                })
                .transpose()
        });
        let update = match compared {
            Ok(None) => return, // cancelled
            Ok(Some(comparison)) => Compared::Done {
                generation,
                comparison: Box::new(comparison),
            },
            Err(e) => Compared::Failed {
                generation,
                message: e.to_string(),
            },
        };
        let _ = updates.send(update);
    }

    fn failed(&mut self, generation: u64, message: String) -> Compared {
        Compared::Failed {
            generation,
            message,
        }
    }
}

/// The latest comparison's result: the comparison and its difference as screen pixels, or
/// why it failed.
type Outcome = Result<(Box<Comparison>, Vec<u32>), String>;

/// The window's side of the comparison: the reference, the worker that compares, and the
/// latest result.
pub struct Comparer {
    /// The reference's file, as the command line named it.
    pub path: PathBuf,
    reference: Arc<Image>,
    /// The reference as screen pixels.
    reference_screen: Vec<u32>,
    worker: Worker<Comparing>,
    /// The scene and options of the latest job.
    asked: Option<(Arc<Scene>, Options)>,
    /// The latest job's result, once it has come.
    outcome: Option<Outcome>,
}

impl Comparer {
    /// Starts the comparison's worker for `reference`, comparing in `encoding`.
    pub fn new(reference: Reference, encoding: Encoding) -> Result<Self, Error> {
        let image = Arc::new(reference.image);
        let task = Comparing::new(Arc::clone(&image), encoding);
        Ok(Self {
            path: reference.path,
            reference_screen: image.to_screen(),
            reference: image,
            worker: Worker::start(0, "whitted-compare", task)?,
            asked: None,
            outcome: None,
        })
    }

    /// The reference's size, (width, height).
    #[must_use]
    pub fn size(&self) -> (u32, u32) {
        self.reference.size()
    }

    /// Compares the render of `scene` with `options` (see
    /// [`super::state::State::compare_options`]) with the reference, unless the latest job
    /// is that one already; a new job cancels the one in flight.
    pub fn ask(&mut self, scene: &Arc<Scene>, options: Options) {
        if let Some((s, o)) = &self.asked
            && Arc::ptr_eq(s, scene)
            && *o == options
        {
            return;
        }
        self.worker.submit(Arc::clone(scene), options.clone());
        self.asked = Some((Arc::clone(scene), options));
        self.outcome = None;
    }

    /// Takes the latest job's result if it has come (the results of older jobs are dropped):
    /// the line [`Comparison::line`] says, or the error, in one line.
    pub fn take(&mut self) -> Option<Result<String, String>> {
        let mut said = None;
        while let Some(update) = self.worker.try_update() {
            said = self.keep(update).or(said);
        }
        said
    }

    /// Waits at most `timeout` for the latest job's result; what [`Self::take`] gives.
    pub fn wait(&mut self, timeout: Duration) -> Option<Result<String, String>> {
        let end = std::time::Instant::now() + timeout;
        while let Some(left) = end.checked_duration_since(std::time::Instant::now()) {
            let update = self.worker.wait_update(left)?;
            if let Some(said) = self.keep(update) {
                return Some(said);
            }
        }
        None
    }

    /// Keeps `update` if it is the latest job's; returns what it says.
    fn keep(&mut self, update: Compared) -> Option<Result<String, String>> {
        let latest = self.worker.generation();
        match update {
            Compared::Done {
                generation,
                comparison,
            } if generation == latest => {
                let line = comparison.line();
                let screen = comparison.difference.to_screen();
                self.outcome = Some(Ok((comparison, screen)));
                Some(Ok(line))
            }
            Compared::Failed {
                generation,
                message,
            } if generation == latest => {
                self.outcome = Some(Err(message.clone()));
                Some(Err(message))
            }
            _ => None,
        }
    }

    /// The latest comparison, once made.
    #[must_use]
    pub fn comparison(&self) -> Option<&Comparison> {
        match &self.outcome {
            Some(Ok((c, _))) => Some(c),
            _ => None,
        }
    }

    /// The screen pixels of `picture` at the reference's size: the reference, or the
    /// difference (the reference until the comparison is made); `None` for the render, which
    /// is the canvas's.
    #[must_use]
    pub fn screen(&self, picture: Picture) -> Option<&[u32]> {
        match (picture, &self.outcome) {
            (Picture::Render, _) => None,
            (Picture::Difference, Some(Ok((_, difference)))) => Some(difference),
            (Picture::Reference | Picture::Difference, _) => Some(&self.reference_screen),
        }
    }

    /// What the title says of the comparison: the count of differing pixels, that it is under
    /// way, or why it failed.
    #[must_use]
    pub fn status(&self) -> String {
        match &self.outcome {
            Some(Ok((c, _))) => c.count(),
            Some(Err(message)) => format!("error: {message}"),
            None => {
                let (w, h) = self.size();
                format!("comparing at {w}×{h}…")
            }
        }
    }
}
