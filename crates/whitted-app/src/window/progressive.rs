//! The render thread of the live window: coarse-to-fine passes, cancelled the moment anything
//! changes.
//!
//! The window thread never waits on rendering. It hands a [`Job`] (a scene and the options to
//! render it with) to the [`Worker`] and goes back to reading the keyboard; the worker's own
//! thread renders the four passes of [`super::schedule`] on its own rayon pool, tile by tile,
//! and sends every finished tile back as an [`Update`]. Each job carries a *generation*: the
//! window bumps a shared counter with every change (camera, chapter, view, depth, scene), and
//! the worker compares it with its job's before each tile, so the pass in flight stops at
//! once and the window drops any tile of an older generation still on its way.
//!
//! The thread, its pool and the generations are the [`Worker`]'s; what it does with a job is
//! a [`Task`]'s: [`Passes`] for the live image, [`super::comparison::Comparing`] for the
//! comparison with a reference image, each on a worker of its own.
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::sync::mpsc::{Receiver, Sender, channel};
use std::thread::JoinHandle;
use std::time::{Duration, Instant};

use rayon::prelude::*;

use super::schedule::{self, PASSES};
use whitted::accel::Accelerator;
use whitted::error::Error;
use whitted::real::Vec3;
use whitted::render::views::Scales;
use whitted::render::{Accelerated, Finished, Options, Rect, Stats, Tracer, build_accel};
use whitted::scene::Scene;

/// A render the window asks for.
#[derive(Clone, Debug)]
pub struct Job {
    /// Which change this render answers; a newer one cancels it.
    pub generation: u64,
    /// The scene.
    pub scene: Arc<Scene>,
    /// The chapter, view, depth, camera and size.
    pub options: Options,
}

/// What the worker sends back.
#[derive(Debug)]
pub enum Update {
    /// The acceleration structure of a job is built: the window inspects clicked pixels with it.
    Ready {
        /// The job's generation.
        generation: u64,
        /// The structure its passes use.
        accel: Arc<Accelerator>,
        /// The scales of the depth and rays views, for the title.
        scales: Scales,
    },
    /// A tile of a pass is traced.
    Tile {
        /// The job's generation.
        generation: u64,
        /// The pass (0 to [`PASSES`] − 1).
        pass: usize,
        /// The tile.
        rect: Rect,
        /// The colours of the pixels the pass traces in the tile, in the order of
        /// [`schedule::pixels`].
        colours: Vec<Vec3>,
    },
    /// Every tile of a pass is traced.
    PassDone {
        /// The job's generation.
        generation: u64,
        /// The pass.
        pass: usize,
        /// Time since the worker took the job (structure build included).
        elapsed: Duration,
        /// The rays of all passes so far.
        stats: Stats,
    },
    /// The job failed: an exercise not written yet, or a panic in the renderer.
    Failed {
        /// The job's generation.
        generation: u64,
        /// One line saying why.
        message: String,
    },
}

impl Update {
    /// The generation of the job this update belongs to.
    #[must_use]
    pub fn generation(&self) -> u64 {
        match self {
            Self::Ready { generation, .. }
            | Self::Tile { generation, .. }
            | Self::PassDone { generation, .. }
            | Self::Failed { generation, .. } => *generation,
        }
    }
}

/// Traces pass `pass` over the image, tile by tile in parallel (on the current rayon pool),
/// calling `sink(tile, colours)` with each tile's colours (in the order of
/// [`schedule::pixels`]) from the thread that traced them. `cancel()` is asked before each
/// tile; once it says `true` no thread starts another tile and the result is
/// [`Finished::Cancelled`] with the rays of the tiles traced.
pub fn render_pass(
    tracer: &Tracer<'_, Accelerated<'_>>,
    pass: usize,
    cancel: &(dyn Fn() -> bool + Sync),
    sink: &(dyn Fn(Rect, Vec<Vec3>) + Sync),
) -> Finished {
    let (w, h) = (tracer.options.width, tracer.options.height);
    let stopped = AtomicBool::new(false);
    let stats = schedule::tiles(pass, w, h)
        .into_par_iter()
        .map(|tile| {
            let mut stats = Stats::default();
            if stopped.load(Ordering::Relaxed) || cancel() {
                stopped.store(true, Ordering::Relaxed);
                return stats;
            }
            let colours = schedule::pixels(pass, tile)
                .map(|(x, y)| tracer.pixel(x, y, &mut stats))
                .collect();
            sink(tile, colours);
            stats
        })
        .reduce(Stats::default, Stats::sum);
    Finished::new(stopped.into_inner(), stats)
}

/// What a [`Worker`]'s thread does with each job.
pub trait Task: Send + 'static {
    /// What it sends back to the window.
    type Update: Send + 'static;

    /// Carries out `job` on `pool`, sending what it has on `updates`; once `cancel()` says
    /// `true` (a newer job has come) it stops as soon as it can and sends nothing more.
    fn run(
        &mut self,
        pool: &rayon::ThreadPool,
        job: &Job,
        cancel: &(dyn Fn() -> bool + Sync),
        updates: &Sender<Self::Update>,
    );

    /// The update that says the job of `generation` panicked; `message` is one line. The task
    /// forgets what it kept from earlier jobs (a panic may have left it half made).
    fn failed(&mut self, generation: u64, message: String) -> Self::Update;
}

/// The live image's task: the passes of [`super::schedule`], each tile sent as it is done,
/// with the acceleration structure kept from one job to the next while it still fits.
#[derive(Default)]
pub struct Passes {
    cache: Option<(AccelKey, Arc<Accelerator>)>,
}

impl Task for Passes {
    type Update = Update;

    fn run(
        &mut self,
        pool: &rayon::ThreadPool,
        job: &Job,
        cancel: &(dyn Fn() -> bool + Sync),
        updates: &Sender<Update>,
    ) {
        run_job(pool, job, &mut self.cache, cancel, updates);
    }

    fn failed(&mut self, generation: u64, message: String) -> Update {
        self.cache = None;
        Update::Failed {
            generation,
            message,
        }
    }
}

/// A thread, its rayon pool, and the task it runs on each job.
pub struct Worker<T: Task = Passes> {
    generation: Arc<AtomicU64>,
    jobs: Option<Sender<Job>>,
    updates: Receiver<T::Update>,
    thread: Option<JoinHandle<()>>,
}

impl Worker {
    /// Starts the render thread of the live image ([`Passes`]) with a pool of `threads`
    /// threads (0: one per core).
    pub fn spawn(threads: usize) -> Result<Self, Error> {
        Self::start(threads, "whitted-render", Passes::default())
    }
}

impl<T: Task> Worker<T> {
    /// Starts a thread named `name` that runs `task` on each job, with a pool of `threads`
    /// threads (0: one per core) named after it.
    pub fn start(threads: usize, name: &str, mut task: T) -> Result<Self, Error> {
        let pool_name = name.to_string();
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .thread_name(move |i| format!("{pool_name}-{i}"))
            .build()
            .map_err(|e| Error::Usage(format!("cannot start the threads of {name}: {e}")))?;
        let generation = Arc::new(AtomicU64::new(0));
        let (jobs, job_rx) = channel::<Job>();
        let (update_tx, updates) = channel();
        let current = Arc::clone(&generation);
        let thread = std::thread::Builder::new()
            .name(name.into())
            .spawn(move || serve(&pool, &job_rx, &update_tx, &current, &mut task))
            .map_err(|e| Error::Usage(format!("cannot start the thread {name}: {e}")))?;
        Ok(Self {
            generation,
            jobs: Some(jobs),
            updates,
            thread: Some(thread),
        })
    }

    /// Cancels the render in flight and starts rendering `scene` with `options`; returns the
    /// new job's generation. Tiles of earlier jobs may still arrive: drop every update whose
    /// generation is not the latest.
    pub fn submit(&self, scene: Arc<Scene>, options: Options) -> u64 {
        let generation = self.generation.fetch_add(1, Ordering::SeqCst) + 1;
        if let Some(jobs) = &self.jobs {
            // a closed channel means the thread ended (it only ends on a dropped Worker)
            let _ = jobs.send(Job {
                generation,
                scene,
                options,
            });
        }
        generation
    }

    /// The generation of the latest job.
    #[must_use]
    pub fn generation(&self) -> u64 {
        self.generation.load(Ordering::SeqCst)
    }

    /// The next update if one is waiting, without blocking.
    #[must_use]
    pub fn try_update(&self) -> Option<T::Update> {
        self.updates.try_recv().ok()
    }

    /// The next update, waiting at most `timeout`.
    #[must_use]
    pub fn wait_update(&self, timeout: Duration) -> Option<T::Update> {
        self.updates.recv_timeout(timeout).ok()
    }
}

impl<T: Task> Drop for Worker<T> {
    fn drop(&mut self) {
        // cancel the job in flight, close the queue, and let the thread finish
        self.generation.fetch_add(1, Ordering::SeqCst);
        self.jobs = None;
        if let Some(t) = self.thread.take() {
            let _ = t.join();
        }
    }
}

/// A worker's thread: takes the newest job and runs the task on it until a newer one arrives.
fn serve<T: Task>(
    pool: &rayon::ThreadPool,
    jobs: &Receiver<Job>,
    updates: &Sender<T::Update>,
    current: &AtomicU64,
    task: &mut T,
) {
    while let Ok(mut job) = jobs.recv() {
        // only the newest job matters
        while let Ok(newer) = jobs.try_recv() {
            job = newer;
        }
        if job.generation != current.load(Ordering::SeqCst) {
            continue;
        }
        let generation = job.generation;
        let cancel = || current.load(Ordering::Relaxed) != generation;
        let run = std::panic::AssertUnwindSafe(|| task.run(pool, &job, &cancel, updates));
        if let Err(payload) = std::panic::catch_unwind(run) {
            let message = whitted::error::missing_exercise(payload.as_ref()).unwrap_or_else(|| {
                format!(
                    "the renderer panicked: {}",
                    whitted::error::panic_message(payload.as_ref())
                )
            });
            let _ = updates.send(task.failed(generation, message));
        }
    }
}

/// What an acceleration structure depends on: the scene, the structure asked for, the size
/// and, for projection extents only, the camera.
#[derive(PartialEq)]
struct AccelKey {
    scene: usize,
    options: Options,
}

impl AccelKey {
    fn new(job: &Job) -> Self {
        let mut options = job.options.clone();
        // only what build_accel reads: the chapter (chapter 1 builds none), the kind, the size,
        // and the camera when the kind looks at it
        options.view = whitted::render::View::Color;
        options.max_depth = 0;
        options.samples = 1;
        if options.accel != whitted::accel::Accel::Extents {
            options.camera = None;
        }
        Self {
            scene: Arc::as_ptr(&job.scene) as usize,
            options,
        }
    }
}

/// Renders the passes of one job, stopping as soon as its generation is no longer current.
fn run_job(
    pool: &rayon::ThreadPool,
    job: &Job,
    cache: &mut Option<(AccelKey, Arc<Accelerator>)>,
    cancel: &(dyn Fn() -> bool + Sync),
    updates: &Sender<Update>,
) {
    let start = Instant::now();
    let generation = job.generation;
    let key = AccelKey::new(job);
    let accel = match cache {
        Some((k, a)) if *k == key => Arc::clone(a),
        _ => {
            let a = Arc::new(pool.install(|| build_accel(&job.scene, &job.options)));
            *cache = Some((key, Arc::clone(&a)));
            a
        }
    };
    if cancel() {
        return;
    }
    let tracer = Tracer::with_accel(&job.scene, &job.options, &accel);
    let _ = updates.send(Update::Ready {
        generation,
        accel: Arc::clone(&accel),
        scales: *tracer.scales(),
    });
    let mut stats = Stats::default();
    for pass in 0..PASSES {
        let sink = |rect: Rect, colours: Vec<Vec3>| {
            let _ = updates.send(Update::Tile {
                generation,
                pass,
                rect,
                colours,
            });
        };
        let finished = pool.install(|| render_pass(&tracer, pass, cancel, &sink));
        stats.add(&finished.stats());
        if finished.is_cancelled() {
            return;
        }
        let _ = updates.send(Update::PassDone {
            generation,
            pass,
            elapsed: start.elapsed(),
            stats,
        });
    }
}
