//! Rendering a rectangle of the image, cancellable between tiles: the render the live window
//! drives. A rectangle's pixels must be the whole render's bit for bit, the pixels outside it
//! untouched; a cancelled render must stop starting tiles and say which it finished.
//!
//! Every framebuffer here starts filled with a sentinel colour no render produces (negative),
//! so an untouched pixel is told from a rendered one.

use std::collections::HashMap;
use std::sync::Mutex;
use std::sync::atomic::{AtomicUsize, Ordering};

use whitted::error::Error;
use whitted::real::Vec3;
use whitted::render::{
    Accelerated, Chapter, Finished, Framebuffer, Options, Rect, Stats, TILE, Tracer, render,
    render_rect,
};
use whitted::scene::Scene;

/// The test image: 64 × 48 is 4 × 3 tiles of 16.
const W: u32 = 64;
const H: u32 = 48;

/// A colour no render gives: a pixel holding it was not written.
const SENTINEL: Vec3 = Vec3::new(-1.0, -2.0, -3.0);

fn showcase() -> Scene {
    whitted::scene::showcase().expect("the showcase parses")
}

/// The showcase's options for chapter 5 at `w` × `h`.
fn options(scene: &Scene, w: u32, h: u32) -> Options {
    let mut o = Options::for_scene(scene, Chapter::ReflectionRefraction);
    (o.width, o.height) = (w, h);
    o
}

fn sentinel_fb(w: u32, h: u32) -> Framebuffer {
    let mut fb = Framebuffer::new(w, h);
    fb.pixels.fill(SENTINEL);
    fb
}

/// Every pixel's components as bits: equal vectors are the same image bit for bit.
fn bits(fb: &Framebuffer) -> impl PartialEq {
    let bits = fb
        .pixels
        .iter()
        .flat_map(|p| p.to_array().map(|x| x.to_bits()));
    bits.collect::<Vec<_>>()
}

/// Renders `rect` never cancelled, returning the tiles reported and the rays cast.
fn render_part(
    tracer: &Tracer<'_, Accelerated<'_>>,
    rect: Rect,
    fb: &mut Framebuffer,
) -> (Vec<Rect>, Stats) {
    let tiles = Mutex::new(Vec::new());
    let finished = render_rect(tracer, rect, fb, &|| false, &|t| {
        tiles.lock().unwrap().push(t);
    })
    .expect("the framebuffer is the image's size");
    let Finished::Done(stats) = finished else {
        panic!("a render never cancelled ended {finished:?}");
    };
    (tiles.into_inner().unwrap(), stats)
}

/// The number of tiles of the image's grid that `rect` (inside the image, not empty) touches.
fn tiles_touched(rect: Rect) -> usize {
    let cols = rect.x1.div_ceil(TILE) - rect.x0 / TILE;
    let rows = rect.y1.div_ceil(TILE) - rect.y0 / TILE;
    (cols * rows) as usize
}

/// Asserts every pixel of `fb` is `full`'s inside one of `done` and the sentinel elsewhere.
#[track_caller]
fn assert_only(fb: &Framebuffer, full: &Framebuffer, done: &[Rect]) {
    for y in 0..fb.height {
        for x in 0..fb.width {
            let (got, want) = if done.iter().any(|r| r.contains(x, y)) {
                (fb.get(x, y), full.get(x, y))
            } else {
                (fb.get(x, y), SENTINEL)
            };
            assert!(
                got.to_array().map(|c| c.to_bits()) == want.to_array().map(|c| c.to_bits()),
                "pixel ({x}, {y}): expected {want:?}, got {got:?}"
            );
        }
    }
}

/// Four quadrants split off the tile grid (at column 23 and row 29), and a 1 × 1 rectangle
/// painted over again, make up exactly the whole render; each rectangle writes only itself.
#[test]
fn rectangles_make_up_the_whole_render_bit_for_bit() {
    let scene = showcase();
    let o = options(&scene, W, H);
    let (full, full_stats) = render(&scene, &o);
    assert!(
        full.pixels.iter().any(|p| *p != full.pixels[0]),
        "a blank image proves nothing"
    );
    let tracer = Tracer::new(&scene, &o);
    let (sx, sy) = (23, 29);
    let quadrants = [
        Rect::new(0, 0, sx, sy),
        Rect::new(sx, 0, W, sy),
        Rect::new(0, sy, sx, H),
        Rect::new(sx, sy, W, H),
    ];
    let mut fb = sentinel_fb(W, H);
    let mut primary = 0;
    for (i, &q) in quadrants.iter().enumerate() {
        let (_, stats) = render_part(&tracer, q, &mut fb);
        primary += stats.primary;
        // the quadrants so far are rendered, the others untouched
        assert_only(&fb, &full, &quadrants[..=i]);
    }
    assert!(
        bits(&fb) == bits(&full),
        "the quadrants differ from the whole render"
    );
    assert_eq!(primary, full_stats.primary, "camera rays of the quadrants");

    // a single pixel, into a fresh framebuffer and over the finished image
    let one = Rect::new(37, 11, 38, 12);
    let mut alone = sentinel_fb(W, H);
    let (tiles, stats) = render_part(&tracer, one, &mut alone);
    assert_eq!(tiles, vec![one]);
    assert_eq!(stats.primary, u64::from(o.samples_per_pixel()));
    assert_only(&alone, &full, &[one]);
    render_part(&tracer, one, &mut fb);
    assert!(
        bits(&fb) == bits(&full),
        "rendering a pixel again changed it"
    );
}

/// The whole image as one rectangle is [`render`] itself.
#[test]
fn the_whole_rectangle_is_the_render() {
    let scene = showcase();
    let o = options(&scene, W, H);
    let mut fb = sentinel_fb(W, H);
    let (tiles, stats) = render_part(&Tracer::new(&scene, &o), Rect::new(0, 0, W, H), &mut fb);
    let (full, full_stats) = render(&scene, &o);
    assert!(bits(&fb) == bits(&full));
    assert_eq!(stats, full_stats);
    assert_eq!(tiles.len(), 12, "4 × 3 tiles");
}

/// In every view, a rectangle rendered alone is that part of the whole image bit for bit: the
/// depth view's scale (and the rays view's) is fixed before the first tile, not taken from the
/// finished image.
#[test]
fn a_rectangle_alone_matches_the_whole_image_in_every_view() {
    let scene = showcase();
    for view in whitted::render::View::ALL {
        let mut o = options(&scene, W, H);
        o.view = view;
        let (full, _) = render(&scene, &o);
        let part = Rect::new(37, 21, 50, 40); // a corner of the image, off the tile grid
        let mut fb = sentinel_fb(W, H);
        render_part(&Tracer::new(&scene, &o), part, &mut fb);
        for y in part.y0..part.y1 {
            for x in part.x0..part.x1 {
                assert_eq!(
                    fb.get(x, y).to_array().map(|c| c.to_bits()),
                    full.get(x, y).to_array().map(|c| c.to_bits()),
                    "{view:?} pixel ({x}, {y})"
                );
            }
        }
    }
}

/// Each tile is reported once, lies on the image's tile grid, and together the tiles cover the
/// rectangle and nothing else.
#[test]
fn progress_reports_every_tile_once_and_they_cover_the_rectangle() {
    let scene = showcase();
    let o = options(&scene, W, H);
    let tracer = Tracer::new(&scene, &o);
    for rect in [
        Rect::new(5, 3, 61, 45),
        Rect::new(0, 0, W, H),
        Rect::new(16, 16, 32, 32),
        Rect::new(15, 0, 17, H),
    ] {
        let mut fb = sentinel_fb(W, H);
        let (tiles, stats) = render_part(&tracer, rect, &mut fb);
        assert_eq!(tiles.len(), tiles_touched(rect), "{rect:?}");
        let mut seen = HashMap::new();
        for t in &tiles {
            assert!(!t.is_empty(), "{t:?}");
            // inside one cell of the grid
            assert_eq!(
                (t.x0 / TILE, t.y0 / TILE),
                ((t.x1 - 1) / TILE, (t.y1 - 1) / TILE),
                "{t:?} crosses the tile grid"
            );
            for y in t.y0..t.y1 {
                for x in t.x0..t.x1 {
                    *seen.entry((x, y)).or_insert(0) += 1;
                }
            }
        }
        assert_eq!(seen.len() as u64, rect.pixels(), "{rect:?}");
        assert!(
            seen.iter()
                .all(|(&(x, y), &n)| n == 1 && rect.contains(x, y))
        );
        assert_eq!(
            stats.primary,
            rect.pixels() * u64::from(o.samples_per_pixel())
        );
    }
}

/// A render in a pool of `threads` threads whose `cancel()`, asked for the n-th time (from 0),
/// says `stop(n)`: returns how it ended, the tiles finished, and the framebuffer.
fn cancel_when(
    tracer: &Tracer<'_, Accelerated<'_>>,
    rect: Rect,
    threads: usize,
    stop: &(dyn Fn(usize) -> bool + Sync),
) -> (Finished, Vec<Rect>, Framebuffer) {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    let asked = AtomicUsize::new(0);
    let tiles = Mutex::new(Vec::new());
    let mut fb = sentinel_fb(W, H);
    let finished = pool.install(|| {
        render_rect(
            tracer,
            rect,
            &mut fb,
            &|| stop(asked.fetch_add(1, Ordering::SeqCst)),
            &|t| tiles.lock().unwrap().push(t),
        )
    });
    let finished = finished.expect("the framebuffer is the image's size");
    (finished, tiles.into_inner().unwrap(), fb)
}

/// A render whose `cancel()` says stop from its (k+1)-th question on, in a pool of `threads`
/// threads.
fn cancel_after(
    tracer: &Tracer<'_, Accelerated<'_>>,
    rect: Rect,
    k: usize,
    threads: usize,
) -> (Finished, Vec<Rect>, Framebuffer) {
    cancel_when(tracer, rect, threads, &|n| n >= k)
}

/// Cancelled after k tiles on one thread: exactly k tiles are done, they hold the whole
/// render's pixels, every other pixel keeps the sentinel, and the stats are theirs.
#[test]
fn a_cancelled_render_stops_after_the_tiles_it_started() {
    let scene = showcase();
    let o = options(&scene, W, H);
    let (full, _) = render(&scene, &o);
    let tracer = Tracer::new(&scene, &o);
    let rect = Rect::new(3, 5, 60, 47);
    let total = tiles_touched(rect);
    assert_eq!(total, 12);
    for k in [1, 5, total - 1] {
        let (finished, done, fb) = cancel_after(&tracer, rect, k, 1);
        assert!(finished.is_cancelled(), "k = {k}: {finished:?}");
        assert_eq!(done.len(), k);
        assert_only(&fb, &full, &done);
        let pixels: u64 = done.iter().map(Rect::pixels).sum();
        assert_eq!(
            finished.stats().primary,
            pixels * u64::from(o.samples_per_pixel())
        );
    }
    // asked before each of the 12 tiles, never saying stop: done
    let (finished, done, fb) = cancel_after(&tracer, rect, total, 1);
    assert!(matches!(finished, Finished::Done(_)), "{finished:?}");
    assert_eq!(done.len(), total);
    assert_only(&fb, &full, &[rect]);
}

/// With several threads a tile starts only after `cancel()` said go, so a `cancel()` that says
/// go k times lets exactly k tiles be done, however the threads interleave.
#[test]
fn a_cancelled_render_on_several_threads_finishes_only_tiles_it_was_let_start() {
    let scene = showcase();
    let o = options(&scene, W, H);
    let (full, _) = render(&scene, &o);
    let tracer = Tracer::new(&scene, &o);
    let rect = Rect::new(0, 0, W, H);
    for k in [0, 3, 7] {
        let (finished, done, fb) = cancel_after(&tracer, rect, k, 4);
        assert!(finished.is_cancelled(), "k = {k}: {finished:?}");
        assert_eq!(done.len(), k);
        assert!(done.len() < tiles_touched(rect));
        assert_only(&fb, &full, &done);
    }
}

/// `cancel()` is a request, not a state: once it has said stop, no tile starts even if it
/// would say go again (a window's "stop" that is reset as soon as it has been read). On one
/// thread exactly the tiles before the stop are done; on several, other threads may ask (and be
/// told go) before the stop is seen, but the tile that was told stop is never done.
#[test]
fn one_stop_is_enough_to_cancel() {
    let scene = showcase();
    let o = options(&scene, W, H);
    let (full, _) = render(&scene, &o);
    let tracer = Tracer::new(&scene, &o);
    for threads in [1, 3] {
        // stop on the fifth question only
        let (finished, done, fb) =
            cancel_when(&tracer, Rect::new(0, 0, W, H), threads, &|n| n == 4);
        assert!(finished.is_cancelled(), "{finished:?}");
        let wanted = if threads == 1 { 4..5 } else { 4..12 };
        assert!(
            wanted.contains(&done.len()),
            "{threads} thread(s): {} tiles done",
            done.len()
        );
        assert_only(&fb, &full, &done);
    }
}

/// A render cancelled before its first tile does nothing: no tile, no ray, not a pixel written.
#[test]
fn a_render_cancelled_at_once_leaves_the_framebuffer_untouched() {
    let scene = showcase();
    let o = options(&scene, W, H);
    let tracer = Tracer::new(&scene, &o);
    let mut fb = sentinel_fb(W, H);
    let reported = AtomicUsize::new(0);
    let finished = render_rect(&tracer, Rect::new(0, 0, W, H), &mut fb, &|| true, &|_| {
        reported.fetch_add(1, Ordering::SeqCst);
    });
    assert!(matches!(finished, Ok(Finished::Cancelled(s)) if s == Stats::default()));
    assert_eq!(reported.into_inner(), 0);
    assert!(fb.pixels.iter().all(|p| *p == SENTINEL));
}

/// A rectangle reaching past the image renders its part inside; an empty one, an upside-down
/// one or one wholly outside renders nothing and is done, without asking `cancel()`.
#[test]
fn rectangles_past_the_image_are_clipped_and_empty_ones_render_nothing() {
    let scene = showcase();
    let o = options(&scene, W, H);
    let (full, _) = render(&scene, &o);
    let tracer = Tracer::new(&scene, &o);

    let mut fb = sentinel_fb(W, H);
    let (tiles, _) = render_part(&tracer, Rect::new(50, 40, u32::MAX, 1000), &mut fb);
    let inside = Rect::new(50, 40, W, H);
    assert_eq!(tiles.len(), tiles_touched(inside));
    assert!(tiles.iter().all(|t| t.x1 <= W && t.y1 <= H));
    assert_only(&fb, &full, &[inside]);

    for rect in [
        Rect::new(10, 10, 10, 30),
        Rect::new(10, 10, 30, 10),
        Rect::new(30, 30, 10, 10),
        Rect::new(W, 0, W + 16, H),
        Rect::new(0, H, W, u32::MAX),
        Rect::new(u32::MAX, u32::MAX, u32::MAX, u32::MAX),
        Rect::default(),
    ] {
        let mut fb = sentinel_fb(W, H);
        let asked = AtomicUsize::new(0);
        let finished = render_rect(
            &tracer,
            rect,
            &mut fb,
            &|| asked.fetch_add(1, Ordering::SeqCst) > 0,
            &|t| panic!("{rect:?} reported the tile {t:?}"),
        );
        assert!(
            matches!(finished, Ok(Finished::Done(s)) if s == Stats::default()),
            "{rect:?}: {finished:?}"
        );
        assert_eq!(asked.into_inner(), 0, "{rect:?}");
        assert!(fb.pixels.iter().all(|p| *p == SENTINEL), "{rect:?}");
    }
}

/// A framebuffer of another size than the tracer's image is refused, and left as it was.
#[test]
fn a_framebuffer_of_the_wrong_size_is_refused() {
    let scene = showcase();
    let o = options(&scene, W, H);
    let tracer = Tracer::new(&scene, &o);
    let mut wrong = [
        sentinel_fb(W + 1, H),
        sentinel_fb(W, H - 1),
        sentinel_fb(0, 0),
    ];
    // a framebuffer whose pixels were truncated by hand
    let mut short = sentinel_fb(W, H);
    short.pixels.truncate(10);
    for fb in wrong.iter_mut().chain([&mut short]) {
        let before = fb.clone();
        let result = render_rect(&tracer, Rect::new(0, 0, W, H), fb, &|| false, &|_| {});
        assert!(
            matches!(&result, Err(Error::Usage(m)) if m.contains("cannot hold a render of 64×48")),
            "{}×{}: {result:?}",
            fb.width,
            fb.height
        );
        assert_eq!(*fb, before);
    }
}

/// [`Rect`]'s sizes and clipping, including rectangles with no pixel.
#[test]
fn a_rect_counts_its_pixels_and_clips_to_the_image() {
    let r = Rect::new(3, 4, 10, 6);
    assert_eq!((r.width(), r.height(), r.pixels()), (7, 2, 14));
    assert!(r.contains(3, 4) && r.contains(9, 5));
    assert!(!r.contains(10, 5) && !r.contains(9, 6) && !r.contains(2, 4));
    assert_eq!(r.clip(8, 5), Rect::new(3, 4, 8, 5));
    assert_eq!(r.clip(2, 2), Rect::new(2, 2, 2, 2));
    assert!(r.clip(2, 2).is_empty());
    let upside_down = Rect::new(10, 10, 5, 5);
    assert!(upside_down.is_empty());
    assert_eq!(upside_down.pixels(), 0);
    assert!(!upside_down.contains(7, 7));
    let huge = Rect::new(0, 0, u32::MAX, u32::MAX);
    assert_eq!(huge.pixels(), u64::from(u32::MAX) * u64::from(u32::MAX));
}
