//! The command line every chapter binary shares: [`main`] builds a chapter's command line from
//! the chapter alone ([`command`]), reads it, and renders.
//!
//! Every binary takes [`Common`]; the other groups come with the chapter that first needs
//! them: [`Objects`] from [`OBJECTS_FROM`] (objects to view, find and inspect), [`Accuracy`]
//! from [`ACCURACY_FROM`] (secondary rays leave surfaces), [`Tracing`] from [`TRACING_FROM`]
//! (recursion and supersampling). Each binary's arguments, as README.md and each chapter's
//! README list them, are written from [`command`] (`tests/docs.rs` compares them).
//!
//! Without SCENE the embedded default scene `scenes/showcase.toml` is rendered. The PNG is
//! sRGB-encoded, as viewers expect; `--encoding linear` writes the linear intensities as bytes
//! (see [`output`]). Every failure
//! is one line on stderr, `error: …`, and exit status 2; nothing is written unless the whole
//! image was rendered. An image whose framebuffer would pass
//! [`render::MAX_FRAMEBUFFER_BYTES`] is refused before any work starts.
//!
//! With `--compare REF.png` the PNG holds three images side by side, the render, REF.png and
//! their difference ([`crate::compare`]), and stdout gets one line saying how many pixels
//! differ and where the first is; the exit status is 0 whether they differ or not. REF.png
//! must have the render's size (checked before any work starts).
//!
//! A render that lasts more than a second shows a progress bar on stderr (only when stderr
//! is a terminal, and not with `--quiet`). Unless `--quiet`, the last line on stderr gives the
//! resolution, the rays cast by kind, the time and the millions of rays per second.
//!
//! Course book: [Introduction](../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use clap::builder::PossibleValue;
use clap::{Args, FromArgMatches};

use whitted::accel::Accel;
/// The one line of an exercise not written yet (it lives in [`whitted::error`], where the live
/// window finds it too).
pub use whitted::error::missing_exercise;
use whitted::error::{Error, MISSING, panic_text};
use whitted::offset::OffsetKind;
use whitted::output::{self, Encoding};
use whitted::real::Real;
use whitted::render::inspect::against::{self, TreeFile};
use whitted::render::inspect::tree::GridHeader;
use whitted::render::{self, Chapter, Options, View};
use whitted::scene::load::{MAX_DEPTH, MAX_SAMPLES, MAX_SIDE};
use whitted::scene::scatter::Layout;
use whitted::scene::{self, Scene};
use whitted::shapes::Numerics;

use crate::compare::{self, Image};

/// The default scene, compiled into every binary (it lives in the library).
pub use whitted::scene::{SHOWCASE, SHOWCASE_NAME};

/// A library type offered on the command line. Its values and their names are the library's
/// own (`ALL` and `name()`), so the two cannot disagree; only the line each value gets in
/// `--help` is the command line's.
pub trait Choice: Copy + PartialEq + Send + Sync + 'static {
    /// Every value, in the order `--help` lists them.
    fn all() -> &'static [Self];
    /// The value's name, as the library reports it and the command line takes it.
    fn name(self) -> &'static str;
    /// The value's line in `--help`.
    fn help(self) -> &'static str;
}

/// clap's parser for a [`Choice`]: the names it accepts, each with its help, and the value a
/// name stands for.
#[must_use]
pub fn choice<T: Choice>() -> impl clap::builder::TypedValueParser<Value = T> {
    use clap::builder::TypedValueParser;
    let names = T::all()
        .iter()
        .map(|&v| PossibleValue::new(v.name()).help(v.help()));
    clap::builder::PossibleValuesParser::new(names).try_map(|name: String| {
        T::all()
            .iter()
            .copied()
            .find(|v| v.name() == name)
            .ok_or_else(|| format!("no value is named `{name}`"))
    })
}

/// Implements [`Choice`] for a library type from its `ALL`, its `name()` and one help line
/// per value.
macro_rules! choice {
    ($ty:ty { $($variant:path => $help:literal),+ $(,)? }) => {
        impl Choice for $ty {
            fn all() -> &'static [Self] {
                &<$ty>::ALL
            }

            fn name(self) -> &'static str {
                <$ty>::name(self)
            }

            fn help(self) -> &'static str {
                match self {
                    $($variant => $help),+
                }
            }
        }
    };
}

choice!(Numerics {
    Numerics::Textbook => "the notes' formulas as printed",
    Numerics::Robust => "cancellation-free roots and discriminants",
});

choice!(View {
    View::Color => "the chapter's colour",
    View::Flat => "the material's diffuse colour, unlit",
    View::Normals => "the normal facing the camera, (n + 1)/2",
    View::Depth => "the distance to the nearest hit, near = white, far = grey (scale 1/d)",
    View::Shadows => "which lights reach each point: light 0 red, 1 green, 2 blue",
    View::Rays => "the rays each pixel casts, black (1) to white (the most possible)",
    View::Ambient => "exercise 3.1: the ambient term I_a = ρa·I_m alone",
    View::Attenuation => "exercise 3.2: each light's attenuation, in its colour (light 0 red, 1 green, 2 blue)",
    View::Diffuse => "exercise 3.3: each light's max(n·s, 0), in its colour; magenta: outside [0, 1]",
    View::Mirror => "exercise 3.4: the first light's mirror direction r, (r + 1)/2",
    View::Highlight => "exercise 3.5: each light's max(r·v, 0)^f, in its colour; magenta: outside [0, 1]",
    View::Direct => "exercise 3.6: I_d + I_s of every light, no ambient term, no shadows",
    View::Refracted => "exercise 5.3: the transmitted direction t of a translucent hit, (t + 1)/2",
    View::Mirrored => "exercise 5.4: the mirror ray's direction of a reflective hit, (l + 1)/2",
});

choice!(Accel {
    Accel::None => "every object for every ray (the notes' step 4)",
    Accel::Boxes => "a bounding box per object",
    Accel::Extents => "boxes, and projection extents for camera rays",
    Accel::Octree => "cubes subdivided until each holds at most 8 objects",
    Accel::Bvh => "a bounding volume hierarchy, binned SAH",
});

choice!(OffsetKind {
    OffsetKind::Fixed => "accept hits only for t > 1e-4 (world units): the classic",
    OffsetKind::Scaled => "move the origin by 1e-4·max(1, |P|) along the normal",
    OffsetKind::ErrorBound => "move the origin by a bound on the hit point's rounding error",
});

choice!(Encoding {
    Encoding::Srgb => "encode for screens and image viewers",
    Encoding::Linear => "the linear intensities as bytes, 0.5 → 128",
});

choice!(Layout {
    Layout::Field => "constant size and density over a square of side 2√N",
    Layout::Fog => "a fixed square; the radius shrinks as 1/√N",
});

/// Arguments shared by every chapter.
#[derive(Args, Debug, Clone)]
pub struct Common {
    /// Scene file (TOML). Without it, the built-in showcase scene (scenes/showcase.toml) is rendered.
    pub scene: Option<PathBuf>,
    /// Where to write the PNG image [default: BINARY_NAME.png in the current directory].
    #[arg(short, long, value_name = "OUT.png")]
    pub output: Option<PathBuf>,
    /// Image width in pixels; alone, the height follows the scene's aspect ratio.
    #[arg(long, value_name = "W", value_parser = clap::value_parser!(u32).range(1..=MAX_SIDE as i64))]
    pub width: Option<u32>,
    /// Image height in pixels; alone, the width follows the scene's aspect ratio.
    #[arg(long, value_name = "H", value_parser = clap::value_parser!(u32).range(1..=MAX_SIDE as i64))]
    pub height: Option<u32>,
    /// How the PNG's bytes encode the linear intensities (`--inspect` prints the same bytes).
    #[arg(long, value_parser = choice::<Encoding>(), default_value = Encoding::default().name())]
    pub encoding: Encoding,
    /// No progress bar and no statistics line (errors and warnings are still printed).
    #[arg(short, long)]
    pub quiet: bool,
    /// Open a live window instead of writing a file; its help, with the keys, is
    /// [`window_help`].
    #[arg(long, help = window_help(false), long_help = window_help(true))]
    pub window: bool,
    /// Compare the render with REF.png (of the same size): write your render, the reference and
    /// the differing pixels side by side, and print on stdout how many differ. With --window,
    /// Tab shows the reference and the difference.
    #[arg(long, value_name = "REF.png")]
    pub compare: Option<PathBuf>,
    /// Trace the pixels of TREES.json (the reference's ray trees, chapters/chNN_name/trees.json)
    /// with this code and the settings the file records, and print, for each pixel whose tree
    /// differs, the first quantity that does and the functions that computed it. No image is
    /// written unless -o or --compare asks for one.
    #[arg(long, value_name = "TREES.json", conflicts_with = "window")]
    pub against: Option<PathBuf>,
    /// Print the ray tree of every STEP-th pixel of every STEP-th row as JSON lines, after a
    /// line with the settings they were traced with, and exit (`whitted trees` reads them).
    #[arg(long, value_name = "STEP", hide = true,
          value_parser = clap::value_parser!(u32).range(1..=MAX_SIDE as i64),
          conflicts_with_all = ["output", "compare", "against", "window"])]
    pub inspect_grid: Option<u32>,
    /// With --inspect or --against: print JSON (its shapes: docs/src/inspect.md).
    #[arg(long)]
    pub json: bool,
}

/// The help of `--window`, with the keys from the window's keymap
/// ([`crate::window::keys`]): in one line (`-h`), or a key a line (`--help`).
#[must_use]
pub fn window_help(long: bool) -> String {
    let what = "Open a live window instead of writing a file: the image refines coarse to fine";
    if long {
        format!(
            "{what}. Without --width/--height the image is the scene's size, shrunk to fit {}×{}. \
             Its keys (H in the window prints them too):\n{}",
            WINDOW_FIT.0,
            WINDOW_FIT.1,
            crate::window::keys::lines()
        )
    } else {
        format!("{what}; keys: {}", crate::window::keys::summary())
    }
}

/// The switches of the chapters that trace objects: what a pixel shows, how the
/// nearest hit is searched for, and one pixel's ray tree.
#[derive(Args, Debug, Clone)]
pub struct Objects {
    /// What each pixel shows.
    #[arg(long, value_parser = choice::<View>(), default_value = View::default().name())]
    pub view: View,
    /// How ray queries are accelerated (notes: "Computational Aspects"); the image is the same
    /// with every choice, only the time changes.
    #[arg(long, value_parser = choice::<Accel>(), default_value = Accel::default().name())]
    pub accel: Accel,
    /// Trace every pixel alone by the plain road, instead of the camera rays and feelers of
    /// 8×8 blocks as packets (a BVH or an octree, one sample a pixel); the same image either way.
    #[arg(long)]
    pub no_packets: bool,
    /// Print the ray tree of pixel X,Y (column X, row Y from the top, from 0) — hits, each
    /// light's I_a, I_d, I_s and feeler, mirror and transmitted rays — and exit, writing no image.
    #[arg(long, value_name = "X,Y", value_parser = parse_pixel, conflicts_with_all = ["output", "compare", "against", "inspect_grid"], allow_hyphen_values = true)]
    pub inspect: Option<(u32, u32)>,
}

/// Reads `X,Y` as a pixel's column and row.
fn parse_pixel(text: &str) -> Result<(u32, u32), String> {
    let bad = || format!("expected X,Y: a pixel's column and row, such as 320,240 (got `{text}`)");
    let (x, y) = text.split_once(',').ok_or_else(bad)?;
    let x = x.trim().parse().map_err(|_| bad())?;
    let y = y.trim().parse().map_err(|_| bad())?;
    Ok((x, y))
}

/// The tracing controls of the chapter with recursion: samples a pixel and depth.
#[derive(Args, Debug, Clone)]
pub struct Tracing {
    /// Samples per pixel (jittered from a fixed seed: the same image every run) [default: the scene's, else 1].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=MAX_SAMPLES as i64))]
    pub samples: Option<u32>,
    /// Maximum recursion depth of mirror and transmitted rays [default: the scene's, else 5].
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(0..=MAX_DEPTH as i64))]
    pub max_depth: Option<u32>,
    /// Also print the samples, depth, threads and the acceleration structure built (and, in a
    /// build with `--features counters`, the node visits, box tests and object tests).
    #[arg(long)]
    pub stats: bool,
}

/// The accuracy switches of the chapters with secondary rays: which intersection formulas, and
/// how secondary rays leave a surface (see [`whitted::shapes::quadratic`] and [`whitted::offset`]).
#[derive(Args, Debug, Clone)]
pub struct Accuracy {
    /// Which intersection formulas.
    #[arg(long, alias = "formula", value_parser = choice::<Numerics>(), default_value = Numerics::default().name())]
    pub numerics: Numerics,
    /// How feeler, mirror and transmitted rays leave a surface.
    #[arg(long, value_parser = choice::<OffsetKind>(), default_value = OffsetKind::default().name())]
    pub offset: OffsetKind,
}

/// The chapter from which the binaries offer [`Objects`]: the first that traces objects.
pub const OBJECTS_FROM: Chapter = Chapter::GenericObjects;
/// The chapter from which the binaries offer [`Accuracy`]: the first with secondary rays.
pub const ACCURACY_FROM: Chapter = Chapter::Shadows;
/// The chapter from which the binaries offer [`Tracing`]: the first with recursion.
pub const TRACING_FROM: Chapter = Chapter::ReflectionRefraction;

/// What a chapter's binary was given: [`Common`], and each other group if the chapter offers
/// it.
#[derive(Debug, Clone)]
pub struct ChapterArgs {
    /// Every chapter's arguments.
    pub common: Common,
    /// From [`OBJECTS_FROM`] on.
    pub objects: Option<Objects>,
    /// From [`ACCURACY_FROM`] on.
    pub accuracy: Option<Accuracy>,
    /// From [`TRACING_FROM`] on.
    pub tracing: Option<Tracing>,
}

impl ChapterArgs {
    /// Reads the groups `chapter` offers from what [`command`] parsed.
    pub fn from_matches(chapter: Chapter, m: &clap::ArgMatches) -> Result<Self, clap::Error> {
        Ok(Self {
            common: Common::from_arg_matches(m)?,
            objects: group(chapter, OBJECTS_FROM, m)?,
            accuracy: group(chapter, ACCURACY_FROM, m)?,
            tracing: group(chapter, TRACING_FROM, m)?,
        })
    }
}

/// Group `G`, offered from chapter `from`, as `chapter`'s binary was given it.
fn group<G: clap::FromArgMatches>(
    chapter: Chapter,
    from: Chapter,
    m: &clap::ArgMatches,
) -> Result<Option<G>, clap::Error> {
    (chapter >= from)
        .then(|| G::from_arg_matches(m))
        .transpose()
}

/// The command line of `chapter`'s binary: named after the chapter's binary, described as
/// "Chapter N of whitted, TITLE: `about`", with the argument groups the chapter offers.
#[must_use]
pub fn command(chapter: Chapter, about: &str) -> clap::Command {
    let offer = |cmd, from, add: fn(clap::Command) -> clap::Command| {
        if chapter >= from { add(cmd) } else { cmd }
    };
    let entry = chapter.about();
    let cmd = clap::Command::new(entry.binary).version(env!("CARGO_PKG_VERSION"));
    let cmd = Common::augment_args(cmd);
    let cmd = offer(cmd, OBJECTS_FROM, Objects::augment_args);
    let cmd = offer(cmd, ACCURACY_FROM, Accuracy::augment_args);
    // after the groups: each sets the command's description to its own
    offer(cmd, TRACING_FROM, Tracing::augment_args)
        .about(format!(
            "Chapter {} of whitted, {}: {about}",
            entry.number, entry.title
        ))
        .long_about(None)
}

/// A chapter binary's whole program: reads its command line ([`command`]) and runs it
/// ([`run`]); returns the exit status.
#[must_use]
pub fn main(chapter: Chapter, about: &str) -> ExitCode {
    let parsed = command(chapter, about)
        .try_get_matches()
        .and_then(|m| ChapterArgs::from_matches(chapter, &m));
    run(chapter, &parsed_or_exit(parsed))
}

/// Parses the command line of a program built with clap's derive (the chapter binaries use
/// [`main`]). `--help`, `--version` and errors as [`parsed_or_exit`] says.
#[must_use]
pub fn parse_args<T: clap::Parser>() -> T {
    parsed_or_exit(T::try_parse())
}

/// The parsed command line, or the exit every whitted program makes
/// ([`leave_after_args`](whitted_syllabus::words::leave_after_args)): `--help` and
/// `--version` exit 0, any other problem is one line `error: …` with exit status 2.
#[must_use]
pub fn parsed_or_exit<T>(parsed: Result<T, clap::Error>) -> T {
    parsed.unwrap_or_else(|e| {
        whitted_syllabus::words::leave_after_args(
            !e.use_stderr(),
            e.kind() == clap::error::ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand,
            || drop(e.print()),
            || e.render().to_string(),
        )
    })
}

/// Reads the scene named on the command line, or the embedded showcase: the parts the chapter
/// `chapter` uses ([`Chapter::reads`]).
pub fn read_scene(path: Option<&Path>, chapter: Chapter) -> Result<Scene, Error> {
    match path {
        Some(p) => scene::load_parts(p, chapter.reads()),
        None => scene::showcase_parts(chapter.reads()),
    }
}

/// The image size after the command line's overrides, keeping the scene's aspect ratio when
/// only one side is given.
#[must_use]
pub fn image_size(scene: &Scene, width: Option<u32>, height: Option<u32>) -> (u32, u32) {
    let aspect = scene.width as Real / scene.height as Real;
    let clampside = |x: Real| (x.round() as u32).clamp(1, MAX_SIDE);
    match (width, height) {
        (Some(w), Some(h)) => (w, h),
        (Some(w), None) => (w, clampside(w as Real / aspect)),
        (None, Some(h)) => (clampside(h as Real * aspect), h),
        (None, None) => (scene.width, scene.height),
    }
}

/// The largest image `--window` opens without `--width` or `--height`.
pub const WINDOW_FIT: (u32, u32) = (1280, 960);

/// `width` × `height` shrunk, keeping its aspect ratio, to fit in `bound` (unchanged if it
/// fits already).
#[must_use]
pub fn fit(width: u32, height: u32, bound: (u32, u32)) -> (u32, u32) {
    let scale = (f64::from(bound.0) / f64::from(width))
        .min(f64::from(bound.1) / f64::from(height))
        .min(1.0);
    let side = |x: u32| ((f64::from(x) * scale).round() as u32).max(1);
    (side(width), side(height))
}

/// Runs a chapter: read, render, write (or inspect, or open the window). Returns the exit
/// status (0, or 2 after printing the error).
pub fn run(chapter: Chapter, args: &ChapterArgs) -> ExitCode {
    guard(|| run_inner(chapter, args))
}

/// Runs `work` and returns the exit status: 0 when it succeeds; 2 after one line on stderr,
/// `error: …`, when it fails or panics on an exercise not written yet (from any thread: the
/// line names the exercise, as [`missing_exercise`] writes it). Any other panic goes on as a
/// panic.
pub fn guard(work: impl FnOnce() -> Result<(), Error>) -> ExitCode {
    quiet_missing_exercises();
    match std::panic::catch_unwind(std::panic::AssertUnwindSafe(work)) {
        Ok(Ok(())) => ExitCode::SUCCESS,
        Ok(Err(e)) => {
            eprintln!("error: {e}");
            ExitCode::from(2)
        }
        Err(payload) => match missing_exercise(payload.as_ref()) {
            Some(line) => {
                eprintln!("error: {line}");
                ExitCode::from(2)
            }
            None => std::panic::resume_unwind(payload),
        },
    }
}

/// Keeps the panics of exercises not written yet quiet (no message, no backtrace, on any
/// thread): [`run`] turns the first into one line. Other panics are reported as usual.
fn quiet_missing_exercises() {
    let default = std::panic::take_hook();
    std::panic::set_hook(Box::new(move |info| {
        if !panic_text(info.payload()).is_some_and(|t| t.starts_with(MISSING)) {
            default(info);
        }
    }));
}

fn run_inner(chapter: Chapter, args: &ChapterArgs) -> Result<(), Error> {
    let ChapterArgs {
        common,
        objects,
        accuracy,
        tracing,
    } = args;
    let inspect = objects.as_ref().and_then(|o| o.inspect);
    if common.window && inspect.is_some() {
        return Err(Error::Usage(
            "--window and --inspect do not go together: click a pixel in the window to inspect it"
                .into(),
        ));
    }
    if common.json && inspect.is_none() && common.against.is_none() {
        return Err(Error::Usage(
            "--json goes with --inspect X,Y or --against TREES.json: it says how they print".into(),
        ));
    }
    let against = match &common.against {
        Some(path) => Some(TreeFile::read(path)?),
        None => None,
    };
    let out = common
        .output
        .clone()
        .unwrap_or_else(|| PathBuf::from(format!("{}.png", chapter.about().binary)));
    // an image is written unless the run only prints trees
    let image = inspect.is_none()
        && common.inspect_grid.is_none()
        && (against.is_none() || common.output.is_some() || common.compare.is_some());
    if image {
        output::check_destination(&out)?;
    }
    let scene = read_scene(common.scene.as_deref(), chapter)?;
    for w in &scene.warnings {
        eprintln!("warning: {w}");
    }
    let mut options = Options::for_scene(&scene, chapter);
    (options.width, options.height) = image_size(&scene, common.width, common.height);
    if let Some(o) = objects {
        options.view = o.view;
        options.accel = o.accel;
        options.packets = !o.no_packets;
    }
    if let Some(t) = tracing {
        options.samples = t.samples.unwrap_or(options.samples);
        options.max_depth = t.max_depth.unwrap_or(options.max_depth);
    }
    if let Some(a) = accuracy {
        options.numerics = a.numerics;
        options.offset = a.offset.offset();
    }
    if let Some(pixel) = inspect {
        return print_tree(&scene, &options, pixel, common.encoding, common.json);
    }
    if let Some(step) = common.inspect_grid {
        return print_grid(&scene, &options, step);
    }
    if let (Some(trees), false) = (&against, image) {
        return print_against(&scene, &options, trees, common).map(|_| ());
    }
    let reference = match &common.compare {
        Some(path) => Some(Reference {
            image: Image::read_reference(path)?,
            path: path.clone(),
        }),
        None => None,
    };
    if common.window {
        if common.width.is_none() && common.height.is_none() {
            (options.width, options.height) = fit(options.width, options.height, WINDOW_FIT);
        }
        render::check_size(options.width, options.height)?;
        if let Some(r) = &reference {
            // the comparison renders at the reference's size
            render::check_size(r.image.width, r.image.height)?;
        }
        return crate::window::run(crate::window::Setup {
            scene_path: common.scene.clone(),
            scene,
            options,
            max_chapter: chapter,
            encoding: common.encoding,
            save_to: out,
            quiet: common.quiet,
            reference,
        });
    }
    render::check_size(options.width, options.height)?;
    if let Some(r) = &reference {
        r.check(&out, (options.width, options.height))?;
    }
    let start = Instant::now();
    let accel = render::build_accel(&scene, &options);
    let progress = Progress::new(
        u64::from(options.width) * u64::from(options.height),
        !common.quiet && std::io::stderr().is_terminal(),
    );
    let (fb, stats) = render::render_with(&scene, &options, &accel, &|n| progress.advance(n));
    progress.finish();
    let seconds = start.elapsed().as_secs_f64();
    match &reference {
        None => output::save(&fb, &out, common.encoding)?,
        Some(r) => {
            let line = r.write_comparison(&fb, common.encoding, &out)?;
            print_out(&format!("{line}\n"))?;
        }
    }
    let traced = match &against {
        Some(trees) => Some(print_against(&scene, &options, trees, common)?),
        None => None,
    };
    if !common.quiet {
        match &reference {
            None => eprintln!("wrote {} ({}×{})", out.display(), fb.width, fb.height),
            Some(r) => eprintln!(
                "wrote {}: your render, {} and the difference, {}×{} each",
                out.display(),
                r.path.display(),
                fb.width,
                fb.height
            ),
        }
        if tracing.as_ref().is_some_and(|t| t.stats) {
            eprintln!(
                "{} sample(s)/px, depth {}, {} thread(s), {} mirror rays by total internal reflection; {}",
                options.samples,
                options.max_depth,
                rayon::current_num_threads(),
                stats.total_internal,
                accel.describe()
            );
            if whitted::accel::counters::ENABLED {
                eprintln!("{}", work_line(&stats.work));
            }
        }
        eprintln!("{}", summary(fb.width, fb.height, &stats, seconds));
        if let Some((pixels, seconds)) = traced {
            eprintln!("traced {pixels} pixels' trees against the reference's in {seconds:.3} s");
        }
    }
    Ok(())
}

/// The reference image of `--compare`, and the path it was read from.
#[derive(Clone, Debug)]
pub struct Reference {
    /// The file, as the command line named it.
    pub path: PathBuf,
    /// Its pixels.
    pub image: Image,
}

impl Reference {
    /// Checks, before any rendering, that a render of `size` can be compared with the
    /// reference and written to `out`: the sizes agree, and `out` is not the reference itself.
    pub fn check(&self, out: &Path, size: (u32, u32)) -> Result<(), Error> {
        if self.image.size() != size {
            let sizes = compare::SizeMismatch {
                render: size,
                reference: self.image.size(),
            };
            return Err(compare::size_error(&self.path, sizes));
        }
        let same = |a: &Path, b: &Path| matches!((a.canonicalize(), b.canonicalize()), (Ok(x), Ok(y)) if x == y);
        if same(out, &self.path) {
            return Err(Error::Usage(format!(
                "-o {} is the reference itself: the comparison would replace it; write it elsewhere",
                out.display()
            )));
        }
        Ok(())
    }

    /// Compares the render `fb`, in `encoding`, with the reference, writes the three images
    /// side by side to `out` ([`compare::side_by_side`]: the render, the reference, the
    /// difference) and returns the line that says how they differ ([`compare::Comparison::line`]).
    pub fn write_comparison(
        &self,
        fb: &render::Framebuffer,
        encoding: Encoding,
        out: &Path,
    ) -> Result<String, Error> {
        let render = Image::from_framebuffer(fb, encoding);
        let c = compare::compare(&render, &self.image)
            .map_err(|sizes| compare::size_error(&self.path, sizes))?;
        let composite = compare::side_by_side(&[&render, &self.image, &c.difference]);
        output::write_png(out, composite.width, composite.height, &composite.rgb)?;
        Ok(c.line())
    }
}

/// `--inspect X,Y [--json]`: prints the ray tree of one pixel on stdout, its bytes in
/// `encoding` (those the PNG would hold).
fn print_tree(
    scene: &Scene,
    options: &Options,
    (x, y): (u32, u32),
    encoding: Encoding,
    json: bool,
) -> Result<(), Error> {
    let (w, h) = (options.width, options.height);
    if x >= w || y >= h {
        return Err(Error::Usage(format!(
            "--inspect {x},{y}: the pixel is outside the {w}×{h} image (X from 0 to {}, Y from 0 to {})",
            w - 1,
            h - 1
        )));
    }
    let mut tree = render::Tracer::new(scene, options).inspect(x, y);
    tree.encoding = encoding;
    let text = if json {
        let json = serde_json::to_string_pretty(&tree.to_json())
            .map_err(|e| Error::Usage(format!("cannot write the tree as JSON: {e}")))?;
        json + "\n"
    } else {
        tree.to_string()
    };
    print_out(&text)
}

/// `--inspect-grid STEP`: the settings as one JSON line, then the ray tree of every STEP-th
/// pixel of every STEP-th row (from STEP/2), one JSON line each.
fn print_grid(scene: &Scene, options: &Options, step: u32) -> Result<(), Error> {
    let tracer = render::Tracer::new(scene, options);
    let header = GridHeader {
        version: against::FILE_VERSION,
        settings: against::settings_of(options),
    };
    let header = serde_json::to_string(&header)
        .map_err(|e| Error::Usage(format!("cannot write the settings as JSON: {e}")))?;
    let mut text = format!("{header}\n");
    for y in (step / 2..options.height).step_by(step as usize) {
        for x in (step / 2..options.width).step_by(step as usize) {
            text += &tracer.inspect(x, y).to_json().to_string();
            text.push('\n');
        }
    }
    print_out(&text)
}

/// `--against TREES.json`: each pixel of the file traced with this code and compared with the
/// reference's tree. In text, a line for each pixel that differs and one that sums up; in JSON
/// (`--json`), a line for every pixel. Returns how many pixels were traced, and in how many
/// seconds.
fn print_against(
    scene: &Scene,
    options: &Options,
    trees: &TreeFile,
    common: &Common,
) -> Result<(usize, f64), Error> {
    let start = Instant::now();
    let compared = trees.against(scene, options)?;
    let seconds = start.elapsed().as_secs_f64();
    let mut text = String::new();
    for c in &compared {
        if common.json {
            text += &c.to_json().to_string();
            text.push('\n');
        } else if c.difference.is_some() {
            text += &c.line();
            text.push('\n');
        }
    }
    if !common.json {
        let differ = compared.iter().filter(|c| c.difference.is_some()).count();
        let file = common.against.as_deref().unwrap_or(Path::new("")).display();
        text += &match differ {
            0 => format!(
                "against: the {} pixels' trees are the reference's ({file})\n",
                compared.len()
            ),
            n => format!(
                "against: {n} of {} pixels' trees differ from the reference's ({file})\n",
                compared.len()
            ),
        };
    }
    print_out(&text)?;
    Ok((compared.len(), seconds))
}

/// Writes `text` on stdout; a reader that stops early (`| head`) is not an error.
fn print_out(text: &str) -> Result<(), Error> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Err(e) if e.kind() != std::io::ErrorKind::BrokenPipe => Err(Error::Write {
            path: PathBuf::from("standard output"),
            message: e.to_string(),
        }),
        _ => Ok(()),
    }
}

/// The line `--stats` adds in a build with the `counters` feature: what the queries tested, in
/// all and per query.
#[must_use]
pub fn work_line(w: &whitted::accel::counters::Counts) -> String {
    let per = |n: u64| n as f64 / w.queries.max(1) as f64;
    format!(
        "work: {} queries; {} node visits ({:.2} a query), {} box tests ({:.2}), {} object tests ({:.2})",
        w.queries,
        w.nodes,
        per(w.nodes),
        w.boxes,
        per(w.boxes),
        w.objects,
        per(w.objects)
    )
}

/// The final line: resolution, rays by kind, time (structure build and render) and M rays/s.
#[must_use]
pub fn summary(width: u32, height: u32, stats: &render::Stats, seconds: f64) -> String {
    format!(
        "{width}×{height}: rays {} primary, {} shadow, {} reflected, {} refracted ({} total); {:.3} s, {:.2} M rays/s",
        stats.primary,
        stats.shadow,
        stats.reflected,
        stats.refracted,
        stats.total(),
        seconds,
        stats.total() as f64 / seconds.max(1e-9) / 1e6
    )
}

/// A progress bar on stderr that appears only once a render has lasted a second.
struct Progress {
    bar: indicatif::ProgressBar,
    enabled: bool,
    shown: AtomicBool,
    start: Instant,
}

impl Progress {
    fn new(total: u64, enabled: bool) -> Self {
        let bar = indicatif::ProgressBar::with_draw_target(
            Some(total),
            indicatif::ProgressDrawTarget::hidden(),
        );
        if let Ok(style) = indicatif::ProgressStyle::with_template(
            "{elapsed_precise} [{bar:40}] {percent:>3}% ({eta} left)",
        ) {
            bar.set_style(style.progress_chars("=> "));
        }
        Self {
            bar,
            enabled,
            shown: AtomicBool::new(false),
            start: Instant::now(),
        }
    }

    fn advance(&self, pixels: u64) {
        if !self.enabled {
            return;
        }
        self.bar.inc(pixels);
        if !self.shown.load(Ordering::Relaxed)
            && self.start.elapsed() > Duration::from_secs(1)
            && !self.shown.swap(true, Ordering::Relaxed)
        {
            self.bar
                .set_draw_target(indicatif::ProgressDrawTarget::stderr());
        }
    }

    fn finish(&self) {
        if self.shown.load(Ordering::Relaxed) {
            self.bar.finish_and_clear();
        }
    }
}
