//! The live window without a display: the coarse-to-fine schedule, the progressive render
//! against the whole-image render, cancelling, the key bindings and what each key changes, the
//! click-to-pixel mapping after a resize, reloading, and the ray-tree overlay's projection.

mod common;

use std::collections::HashSet;
use std::sync::Arc;
use std::sync::atomic::{AtomicUsize, Ordering};
use std::time::Duration;

use approx::assert_relative_eq;

/// Asserts two vectors agree component by component within `epsilon` (absolute, or relative to
/// the larger of the two for large components), showing both.
#[track_caller]
fn assert_vec_close(actual: Vec3, expected: Vec3, epsilon: Real) {
    for (a, e) in actual.to_array().into_iter().zip(expected.to_array()) {
        assert!(
            approx::relative_eq!(a, e, epsilon = epsilon),
            "expected {expected:?}, got {actual:?} (epsilon {epsilon})"
        );
    }
}
use minifb::Key;
use whitted::error::Error;
use whitted::real::{Real, Vec3};
use whitted::render::{self, Chapter, Finished, Options, Rect, Tracer, View};
use whitted::scene::{CameraSettings, Scene};
use whitted_app::window::canvas::Canvas;
use whitted_app::window::keys::{self, Trigger, action_of};
use whitted_app::window::overlay::{self, Mark, Overlay, Stroke};
use whitted_app::window::progressive::{Update, Worker, render_pass};
use whitted_app::window::schedule::{self, PASSES, STEPS};
use whitted_app::window::state::{
    Action, Command, Input, Move, Picture, State, Turn, click_to_pixel,
};

/// Tolerance for positions computed in `Real`.
const EPS: Real = if cfg!(feature = "f32") { 1e-4 } else { 1e-10 };

fn showcase() -> Scene {
    whitted::scene::showcase().unwrap()
}

fn options(scene: &Scene, chapter: Chapter, w: u32, h: u32) -> Options {
    let mut o = Options::for_scene(scene, chapter);
    (o.width, o.height) = (w, h);
    o
}

/// Every pixel of an image is traced by exactly one pass, whatever the size.
#[test]
fn every_pixel_is_traced_in_exactly_one_pass() {
    for (w, h) in [(1, 1), (8, 8), (17, 9), (37, 23), (640, 480)] {
        let mut seen = vec![0u8; (w * h) as usize];
        for pass in 0..PASSES {
            for tile in schedule::tiles(pass, w, h) {
                for (x, y) in schedule::pixels(pass, tile) {
                    assert!(tile.contains(x, y));
                    assert!(schedule::traced_in(pass, x, y));
                    seen[(y * w + x) as usize] += 1;
                }
            }
        }
        assert!(
            seen.iter().all(|&n| n == 1),
            "{w}×{h}: some pixel traced 0 or 2 times"
        );
    }
}

/// The passes trace 1/64, then 3/64, 12/64 and 48/64 of a 64 × 64 image: the grid of step 8,
/// then the new points of each finer grid.
#[test]
fn each_pass_traces_the_new_points_of_its_grid() {
    let counts: Vec<usize> = (0..PASSES)
        .map(|p| schedule::pixels(p, Rect::new(0, 0, 64, 64)).count())
        .collect();
    assert_eq!(counts, [64, 3 * 64, 12 * 64, 48 * 64]);
    assert_eq!(STEPS, [8, 4, 2, 1]);
    // pass 2 (step 4) traces (4, 0), (0, 4), (4, 4) but not (0, 0) or (8, 8)
    assert!(schedule::traced_in(1, 4, 0) && schedule::traced_in(1, 0, 4));
    assert!(!schedule::traced_in(1, 0, 0) && !schedule::traced_in(1, 8, 8));
    assert!(schedule::traced_in(3, 3, 2) && !schedule::traced_in(3, 2, 2));
}

/// Each pass's tiles cover the image once, 32 × its step on a side, cut at the edges.
#[test]
fn tiles_cover_the_image_once() {
    let tiles = schedule::tiles(3, 70, 40);
    assert_eq!(tiles.len(), 3 * 2);
    assert_eq!(tiles.last(), Some(&Rect::new(64, 32, 70, 40)));
    for (pass, step) in STEPS.into_iter().enumerate() {
        let tiles = schedule::tiles(pass, 700, 300);
        let total: u64 = tiles.iter().map(Rect::pixels).sum();
        assert_eq!(total, 700 * 300);
        assert_eq!(tiles[0], Rect::new(0, 0, 32 * step, 32 * step));
    }
    // a full tile of every pass holds about the same work
    let work: Vec<usize> = (0..PASSES)
        .map(|p| schedule::pixels(p, schedule::tiles(p, 1024, 1024)[0]).count())
        .collect();
    assert_eq!(work, [1024, 768, 768, 768]);
}

/// The canvas after all four passes holds every pixel's own colour; after the first pass,
/// each pixel shows the colour of the corner of its 8 × 8 block.
#[test]
fn passes_paint_blocks_and_the_last_pass_leaves_each_pixel_its_own_colour() {
    let (w, h) = (21, 13);
    let colour = |x: u32, y: u32| Vec3::new(x as Real, y as Real, 1.0);
    let mut canvas = Canvas::new(w, h, whitted::output::Encoding::Linear);
    canvas.expect(7);
    for pass in 0..PASSES {
        for rect in schedule::tiles(pass, w, h) {
            let colours = schedule::pixels(pass, rect)
                .map(|(x, y)| colour(x, y))
                .collect();
            let tile = Update::Tile {
                generation: 7,
                pass,
                rect,
                colours,
            };
            assert!(canvas.apply(&tile));
        }
        if pass == 0 {
            for y in 0..h {
                for x in 0..w {
                    assert_eq!(canvas.fb.get(x, y), colour(x - x % 8, y - y % 8));
                }
            }
        }
    }
    for y in 0..h {
        for x in 0..w {
            assert_eq!(canvas.fb.get(x, y), colour(x, y));
        }
    }
}

/// A tile of an older generation is dropped and leaves the canvas as it was.
#[test]
fn stale_tiles_are_dropped() {
    let mut canvas = Canvas::new(16, 16, whitted::output::Encoding::Linear);
    canvas.expect(3);
    let stale = Update::Tile {
        generation: 2,
        pass: 0,
        rect: Rect::new(0, 0, 16, 16),
        colours: vec![Vec3::ONE; 4],
    };
    assert!(!canvas.apply(&stale));
    assert!(canvas.fb.pixels.iter().all(|&p| p == Vec3::ZERO));
    assert!(canvas.screen.iter().all(|&p| p == 0));
}

/// The four passes, painted, give the whole-image render bit for bit, in every view and
/// chapter (a coarse-to-fine render traces the same road).
#[test]
fn the_progressive_render_equals_the_whole_image_render() {
    let scene = showcase();
    for (chapter, view) in [
        (Chapter::CameraRays, View::Color),
        (Chapter::Shading, View::Normals),
        (Chapter::Shadows, View::Shadows),
        (Chapter::ReflectionRefraction, View::Color),
        (Chapter::ReflectionRefraction, View::Depth),
        (Chapter::ReflectionRefraction, View::Rays),
    ] {
        let mut o = options(&scene, chapter, 70, 45);
        o.view = view;
        let tracer = Tracer::new(&scene, &o);
        let mut canvas = Canvas::new(70, 45, whitted::output::Encoding::Srgb);
        canvas.expect(1);
        let mut rays = 0;
        for pass in 0..PASSES {
            let updates = std::sync::Mutex::new(Vec::new());
            let finished = render_pass(&tracer, pass, &|| false, &|rect, colours| {
                updates.lock().unwrap().push(Update::Tile {
                    generation: 1,
                    pass,
                    rect,
                    colours,
                });
            });
            assert!(!finished.is_cancelled());
            rays += finished.stats().primary;
            for u in updates.into_inner().unwrap() {
                canvas.apply(&u);
            }
        }
        let (whole, stats) = render::render(&scene, &o);
        assert_eq!(canvas.fb, whole, "chapter {chapter:?}, view {view:?}");
        assert_eq!(rays, stats.primary, "each pixel's camera rays once");
    }
}

/// Once `cancel()` says stop, no tile starts: exactly the tiles it let start are traced.
#[test]
fn a_cancelled_pass_traces_only_the_tiles_started_before_the_stop() {
    let scene = showcase();
    let o = options(&scene, Chapter::Shading, 160, 128); // 5 × 4 tiles of 32 in pass 4
    let tracer = Tracer::new(&scene, &o);
    for allowed in [0, 1, 5, 13] {
        let asked = AtomicUsize::new(0);
        let traced = AtomicUsize::new(0);
        let finished = render_pass(
            &tracer,
            3,
            &|| asked.fetch_add(1, Ordering::SeqCst) >= allowed,
            &|_, _| {
                traced.fetch_add(1, Ordering::SeqCst);
            },
        );
        assert!(matches!(finished, Finished::Cancelled(_)));
        assert_eq!(traced.load(Ordering::SeqCst), allowed);
        // pass 4 traces 3/4 of each full 32 × 32 tile's pixels
        assert_eq!(finished.stats().primary, allowed as u64 * 768);
    }
}

/// A new job cancels the one in flight: the old one never finishes its last pass, the new
/// one does, and the worker reports passes in order.
#[test]
fn a_new_job_cancels_the_render_in_flight() {
    let scene = Arc::new(showcase());
    let worker = Worker::spawn(2).unwrap();
    let big = options(&scene, Chapter::ReflectionRefraction, 1280, 960);
    let small = options(&scene, Chapter::Shading, 64, 48);
    let first = worker.submit(Arc::clone(&scene), big);
    let second = worker.submit(Arc::clone(&scene), small);
    assert_eq!(second, first + 1);
    assert_eq!(worker.generation(), second);
    let mut passes = Vec::new();
    while let Some(u) = worker.wait_update(Duration::from_secs(60)) {
        match u {
            Update::PassDone {
                generation, pass, ..
            } => {
                assert_eq!(generation, second, "the cancelled job finished a pass");
                passes.push(pass);
                if pass + 1 == PASSES {
                    break;
                }
            }
            Update::Failed { message, .. } => panic!("{message}"),
            _ => {}
        }
    }
    assert_eq!(passes, [0, 1, 2, 3]);
}

/// No key is bound twice, and every kind of action has a key.
#[test]
fn every_action_has_a_key_and_no_key_two_actions() {
    let bindings = keys::bindings();
    let distinct: HashSet<_> = bindings.iter().map(|b| b.key as usize).collect();
    assert_eq!(distinct.len(), bindings.len(), "a key is bound twice");
    let mut wanted = vec![
        Action::Depth(1),
        Action::Depth(-1),
        Action::NextView,
        Action::NextPicture,
        Action::PrintCamera,
        Action::Save,
        Action::Reload,
        Action::Help,
        Action::Quit,
    ];
    wanted.extend(
        [
            Move::Forward,
            Move::Back,
            Move::Left,
            Move::Right,
            Move::Down,
            Move::Up,
        ]
        .map(Action::Move),
    );
    wanted.extend([Turn::Left, Turn::Right, Turn::Up, Turn::Down].map(Action::Turn));
    wanted.extend(Chapter::ALL.map(Action::Chapter));
    for a in wanted {
        assert!(bindings.iter().any(|b| b.action == a), "{a:?} has no key");
    }
}

/// The bindings the issue and the help promise.
#[test]
fn keys_are_bound_as_the_help_says() {
    let expect = [
        (Key::W, Action::Move(Move::Forward)),
        (Key::S, Action::Move(Move::Back)),
        (Key::A, Action::Move(Move::Left)),
        (Key::D, Action::Move(Move::Right)),
        (Key::Q, Action::Move(Move::Down)),
        (Key::E, Action::Move(Move::Up)),
        (Key::Left, Action::Turn(Turn::Left)),
        (Key::Right, Action::Turn(Turn::Right)),
        (Key::Up, Action::Turn(Turn::Up)),
        (Key::Down, Action::Turn(Turn::Down)),
        (Key::Equal, Action::Depth(1)),
        (Key::NumPadPlus, Action::Depth(1)),
        (Key::Minus, Action::Depth(-1)),
        (Key::Key1, Action::Chapter(Chapter::CameraRays)),
        (Key::NumPad2, Action::Chapter(Chapter::GenericObjects)),
        (Key::Key5, Action::Chapter(Chapter::ReflectionRefraction)),
        (Key::V, Action::NextView),
        (Key::Tab, Action::NextPicture),
        (Key::C, Action::PrintCamera),
        (Key::P, Action::Save),
        (Key::R, Action::Reload),
        (Key::H, Action::Help),
        (Key::Escape, Action::Quit),
    ];
    for (key, action) in expect {
        assert_eq!(action_of(key), Some(action), "{key:?}");
    }
    assert_eq!(action_of(Key::Z), None);
    assert_eq!(action_of(Key::Key6), None, "a digit past the last chapter");
    // moving and turning repeat while held; the rest act once per press
    let repeats = |key| action_of(key).map(Action::repeats);
    assert_eq!(repeats(Key::W), Some(true));
    assert_eq!(repeats(Key::Left), Some(true));
    assert_eq!(repeats(Key::V), Some(false));
    assert_eq!(repeats(Key::Minus), Some(false));
}

/// Chapter n's key is the digit n, on the main keyboard and the keypad, for every chapter.
#[test]
fn each_chapter_has_its_digit() {
    let digits = [Key::Key1, Key::Key2, Key::Key3, Key::Key4, Key::Key5];
    let keypad = [
        Key::NumPad1,
        Key::NumPad2,
        Key::NumPad3,
        Key::NumPad4,
        Key::NumPad5,
    ];
    assert_eq!(Chapter::ALL.len(), digits.len());
    for (i, chapter) in Chapter::ALL.into_iter().enumerate() {
        assert_eq!(usize::from(chapter.number()), i + 1);
        for key in [digits[i], keypad[i]] {
            assert_eq!(action_of(key), Some(Action::Chapter(chapter)), "{key:?}");
        }
    }
}

/// The keymap's rows as the help writes them: each key under its label, named as it is
/// printed on the keyboard.
#[test]
fn the_keymap_labels_name_the_keys() {
    let labels: Vec<String> = keys::keymap().iter().map(keys::Row::label).collect();
    assert_eq!(
        labels,
        [
            "W A S D",
            "Q E",
            "← → ↑ ↓",
            "+ −",
            "1 … 5",
            "V",
            "Tab",
            "C",
            "P",
            "R",
            "H",
            "Esc",
            "left click"
        ]
    );
    let views: Vec<&str> = View::WINDOW.iter().map(|v| v.name()).collect();
    let keymap = keys::keymap();
    let v = keymap
        .iter()
        .find(|r| matches!(&r.trigger, Trigger::Keys(b) if b.iter().any(|b| b.action == Action::NextView)))
        .expect("a row for V");
    assert!(
        v.description.ends_with(&views.join(", ")),
        "V lists the views: {}",
        v.description
    );
    assert_eq!(
        keys::keymap()
            .iter()
            .filter(|r| r.trigger == Trigger::LeftClick)
            .count(),
        1
    );
}

/// `H`, `--window --help` and `--window -h` show every row of the keymap: its keys, and what
/// they do (a sentence in the help and `--help`, a word or two in `-h`).
#[test]
fn the_help_texts_show_every_row_of_the_keymap() {
    let help = keys::help();
    let long = whitted_app::cli::window_help(true);
    let short = whitted_app::cli::window_help(false);
    for row in keys::keymap() {
        let label = row.label();
        for (name, text) in [("H", &help), ("--help", &long)] {
            let line = text
                .lines()
                .find(|l| l.trim_start().starts_with(&label))
                .unwrap_or_else(|| panic!("{name}: no line for {label}:\n{text}"));
            assert!(
                line.ends_with(&row.description),
                "{name}: {label} should say {:?}, says {line:?}",
                row.description
            );
        }
        let entry = format!("{label} {}", row.short);
        assert!(short.contains(&entry), "-h lacks {entry:?}: {short}");
    }
    assert!(help.starts_with("keys:\n"), "{help}");
}

/// What `H` prints after the keys: every stroke and mark of the ray tree's drawing, its look
/// and its meaning; a dotted stroke is called dotted.
#[test]
fn the_help_explains_every_stroke_and_mark() {
    let help = keys::help();
    let legend: Vec<(&str, &str)> = Stroke::ALL
        .iter()
        .map(|s| s.legend())
        .chain(Mark::ALL.iter().map(|m| m.legend()))
        .collect();
    for (look, meaning) in &legend {
        assert!(
            help.lines()
                .any(|l| l.trim_start().starts_with(look) && l.ends_with(meaning)),
            "H does not explain {look}: {help}"
        );
    }
    for s in Stroke::ALL {
        assert_eq!(s.legend().0.starts_with("dotted"), s.dotted(), "{s:?}");
    }
    let looks: HashSet<&str> = legend.iter().map(|l| l.0).collect();
    assert_eq!(looks.len(), legend.len(), "two strokes or marks look alike");
}

fn state(chapter: Chapter) -> State {
    let scene = showcase();
    let o = options(&scene, chapter, 64, 48);
    State::new(scene, o, chapter)
}

fn key(action: Action) -> Input {
    Input::Key {
        action,
        fast: false,
    }
}

/// W moves eye and point looked at by 5% of their distance along the viewing direction;
/// Shift moves 4 times as far; then a render.
#[test]
fn moving_translates_eye_and_look_at_together() {
    let mut s = state(Chapter::Shadows);
    let before = s.camera().clone();
    let f = (before.look_at - before.eye).normalize();
    let dist = (before.look_at - before.eye).length();
    assert_eq!(
        s.handle(key(Action::Move(Move::Forward))),
        [Command::Render]
    );
    let after = s.camera().clone();
    assert_vec_close(after.eye, before.eye + f * 0.05 * dist, EPS);
    assert_vec_close(after.look_at, before.look_at + f * 0.05 * dist, EPS);
    let cmds = s.handle(Input::Key {
        action: Action::Move(Move::Up),
        fast: true,
    });
    assert_eq!(cmds, [Command::Render]);
    assert_vec_close(s.camera().eye, after.eye + Vec3::Y * 0.2 * dist, EPS);
    // D moves right: along u of the camera
    let c = s.camera().clone();
    s.handle(key(Action::Move(Move::Right)));
    let u = c.camera(64, 48).u();
    assert_vec_close(s.camera().eye, c.eye + u * 0.05 * dist, EPS);
}

/// Turning keeps the eye and the distance; left then right comes back; turning up stops
/// short of the up vector with a message and no render.
#[test]
fn turning_keeps_the_eye_and_stops_before_looking_straight_up() {
    let mut s = state(Chapter::Shadows);
    let start = s.camera().clone();
    assert_eq!(s.handle(key(Action::Turn(Turn::Left))), [Command::Render]);
    let turned = s.camera().clone();
    assert_eq!(turned.eye, start.eye);
    assert_relative_eq!(
        (turned.look_at - turned.eye).length(),
        (start.look_at - start.eye).length(),
        epsilon = EPS * 10.0
    );
    // the point looked at went left: along −u
    let u = start.camera(64, 48).u();
    assert!((turned.look_at - start.look_at).dot(u) < 0.0);
    s.handle(key(Action::Turn(Turn::Right)));
    assert_vec_close(s.camera().look_at, start.look_at, EPS * 10.0);
    let mut refused = 0;
    for _ in 0..100 {
        let before = s.camera().clone();
        match s.handle(key(Action::Turn(Turn::Up))).as_slice() {
            [Command::Render] => {}
            [Command::Print(m)] => {
                assert!(m.contains("up vector"), "{m}");
                assert_eq!(*s.camera(), before);
                refused += 1;
            }
            other => panic!("{other:?}"),
        }
    }
    assert!(refused > 0, "turning up never stopped");
    let c = s.camera();
    let angle = (c.look_at - c.eye)
        .normalize()
        .dot(Vec3::Y)
        .acos()
        .to_degrees();
    assert!(angle >= 2.0 - 1e-3, "{angle}° from up");
}

/// The chapter keys switch the chapter up to the binary's own, never past it; chapter 5
/// brings back the samples, earlier chapters take one.
#[test]
fn chapter_keys_stop_at_the_binarys_chapter() {
    let mut s = state(Chapter::Shadows);
    let cmds = s.handle(key(Action::Chapter(Chapter::ReflectionRefraction)));
    assert!(
        matches!(cmds.as_slice(), [Command::Print(m)] if m.contains("ch04_shadows goes up to chapter 4")),
        "{cmds:?}"
    );
    assert_eq!(s.options.chapter, Chapter::Shadows);
    let ch2 = key(Action::Chapter(Chapter::GenericObjects));
    assert_eq!(s.handle(ch2), [Command::Render]);
    assert_eq!(s.options.chapter, Chapter::GenericObjects);
    assert_eq!(s.handle(key(Action::Chapter(Chapter::GenericObjects))), []);
    let mut s5 = state(Chapter::ReflectionRefraction);
    s5.samples = 4;
    s5.handle(key(Action::Chapter(Chapter::Shading)));
    assert_eq!(s5.options.samples, 1);
    s5.handle(key(Action::Chapter(Chapter::ReflectionRefraction)));
    assert_eq!(s5.options.samples, 4);
}

/// V cycles the six views and comes back; at chapter 1 it says why it does nothing.
#[test]
fn v_cycles_the_views() {
    let mut s = state(Chapter::ReflectionRefraction);
    let mut seen = vec![s.options.view];
    for _ in 0..6 {
        assert_eq!(s.handle(key(Action::NextView)), [Command::Render]);
        seen.push(s.options.view);
    }
    assert_eq!(&seen[..6], &View::WINDOW);
    assert_eq!(seen[6], View::Color);
    let mut s1 = state(Chapter::CameraRays);
    assert!(matches!(
        s1.handle(key(Action::NextView)).as_slice(),
        [Command::Print(_)]
    ));
    assert_eq!(s1.options.view, View::Color);
}

/// +/- change the depth within 0 … MAX_DEPTH; only chapter 5 renders again.
#[test]
fn depth_keys_change_max_depth_within_its_range() {
    let mut s = state(Chapter::ReflectionRefraction);
    let d = s.options.max_depth;
    assert_eq!(s.handle(key(Action::Depth(1))), [Command::Render]);
    assert_eq!(s.options.max_depth, d + 1);
    for _ in 0..(d + 5) {
        s.handle(key(Action::Depth(-1)));
    }
    assert_eq!(s.options.max_depth, 0);
    assert!(matches!(
        s.handle(key(Action::Depth(-1))).as_slice(),
        [Command::Print(_)]
    ));
    let mut s3 = state(Chapter::Shading);
    assert!(
        matches!(s3.handle(key(Action::Depth(1))).as_slice(), [Command::Print(m)] if m.contains("chapter 5"))
    );
    assert_eq!(s3.options.max_depth, d + 1);
}

/// C prints a `[camera]` table that reads back as the camera moved.
#[test]
fn the_printed_camera_reads_back_as_the_same_camera() {
    let mut s = state(Chapter::Shading);
    s.handle(key(Action::Turn(Turn::Left)));
    s.handle(key(Action::Move(Move::Forward)));
    let cmds = s.handle(key(Action::PrintCamera));
    let [Command::Print(table)] = cmds.as_slice() else {
        panic!("C prints one table: {cmds:?}")
    };
    assert!(table.starts_with("[camera]\n"));
    // paste it over the showcase's own [camera] table
    let text = whitted_app::cli::SHOWCASE;
    let start = text.find("[camera]").unwrap();
    let end = start + text[start..].find("\n\n").unwrap();
    let pasted = format!("{}{table}{}", &text[..start], &text[end..]);
    let back = whitted::scene::parse(&pasted, "pasted.toml")
        .unwrap()
        .camera;
    let c = s.camera();
    for (a, b) in [
        (back.eye, c.eye),
        (back.look_at, c.look_at),
        (back.up, c.up),
    ] {
        assert_vec_close(a, b, 1e-5);
    }
    assert_eq!((back.fov, back.near), (c.fov, c.near));
}

/// The other keys ask the shell for what they name.
#[test]
fn save_reload_help_and_quit_become_commands() {
    let mut s = state(Chapter::Shading);
    assert_eq!(s.handle(key(Action::Save)), [Command::Save]);
    assert_eq!(s.handle(key(Action::Reload)), [Command::Reload]);
    assert_eq!(s.handle(key(Action::Quit)), [Command::Quit]);
    assert!(
        matches!(s.handle(key(Action::Help)).as_slice(), [Command::Print(h)] if h.contains("Esc"))
    );
}

/// A click maps to the image pixel from the window's size now: after the window is resized
/// to twice the image, the window's centre is still the image's centre.
#[test]
fn a_click_maps_to_the_pixel_under_it_after_a_resize() {
    let image = (640, 480);
    assert_eq!(click_to_pixel((0.0, 0.0), (640, 480), image), Some((0, 0)));
    assert_eq!(
        click_to_pixel((639.9, 479.9), (640, 480), image),
        Some((639, 479))
    );
    assert_eq!(
        click_to_pixel((640.0, 480.0), (1280, 960), image),
        Some((320, 240))
    );
    assert_eq!(
        click_to_pixel((1279.5, 959.5), (1280, 960), image),
        Some((639, 479))
    );
    assert_eq!(
        click_to_pixel((10.0, 10.0), (320, 240), image),
        Some((20, 20))
    );
    assert_eq!(click_to_pixel((-1.0, 10.0), (640, 480), image), None);
    assert_eq!(click_to_pixel((10.0, 480.0), (640, 480), image), None);
    assert_eq!(click_to_pixel((10.0, 10.0), (0, 0), image), None);
    let mut s = state(Chapter::Shading); // a 64 × 48 image
    let cmds = s.handle(Input::Click {
        mouse: (200.0, 50.0),
        window: (256, 192),
    });
    assert_eq!(cmds, [Command::Inspect { x: 50, y: 12 }]);
}

/// A scene with an error keeps the last good one and says why; a good one replaces it, and
/// keeps the moved camera unless the file's camera changed.
#[test]
fn reloading_keeps_the_last_good_scene() {
    let mut s = state(Chapter::Shading);
    s.handle(key(Action::Move(Move::Back)));
    let moved = s.camera().clone();
    let before = Arc::clone(&s.scene);
    let bad = Error::Scene {
        file: "scene.toml".into(),
        line: 3,
        col: 7,
        message: "expected a number".into(),
    };
    let cmds = s.handle(Input::Loaded(Box::new(Err(bad))));
    assert!(
        matches!(cmds.as_slice(), [Command::Error(m)] if m.starts_with("scene.toml:3:7: expected a number"))
    );
    assert!(Arc::ptr_eq(&s.scene, &before));
    assert_eq!(
        s.error.as_deref(),
        Some("scene.toml:3:7: expected a number")
    );
    // the same scene file fixed: the moved camera stays
    let mut edited = showcase();
    edited.background = Vec3::new(1.0, 0.0, 0.0);
    let cmds = s.handle(Input::Loaded(Box::new(Ok(edited))));
    assert_eq!(cmds.last(), Some(&Command::Render));
    assert_eq!(s.scene.background, Vec3::new(1.0, 0.0, 0.0));
    assert_eq!(s.error, None);
    assert_eq!(*s.camera(), moved);
    // the file's camera edited: it wins
    let mut recamera = showcase();
    recamera.camera = CameraSettings {
        eye: Vec3::new(0.0, 1.0, 9.0),
        ..recamera.camera
    };
    s.handle(Input::Loaded(Box::new(Ok(recamera))));
    assert_eq!(s.camera().eye, Vec3::new(0.0, 1.0, 9.0));
}

/// Without `--compare` the compare key shows nothing new: it says, in one line, how to start
/// with a reference (the chapter's figure, of the chapter's scene).
#[test]
fn the_compare_key_without_a_reference_says_how_to_give_one() {
    let mut s = state(Chapter::Shading);
    let cmds = s.handle(key(Action::NextPicture));
    match cmds.as_slice() {
        [Command::Print(line)] => {
            assert!(!line.contains('\n'), "one line: {line}");
            assert!(
                line.contains("--compare REF.png")
                    && line.contains("docs/src/figures/ch03_shading.png")
                    && line.contains("scenes/ch03_shading.toml"),
                "{line}"
            );
        }
        other => panic!("expected one printed line, got {other:?}"),
    }
    assert_eq!(s.picture, Picture::Render);
    assert_eq!(s.compare_options(), None);
}

/// With a reference the compare key shows the render, the reference, the difference in turn;
/// the two last ask for the comparison, the render asks for nothing.
#[test]
fn the_compare_key_cycles_render_reference_difference() {
    let mut s = state(Chapter::Shading).with_reference((24, 12));
    assert_eq!(s.picture, Picture::Render);
    assert_eq!(s.handle(key(Action::NextPicture)), [Command::Compare]);
    assert_eq!(s.picture, Picture::Reference);
    assert_eq!(s.handle(key(Action::NextPicture)), [Command::Compare]);
    assert_eq!(s.picture, Picture::Difference);
    assert_eq!(s.handle(key(Action::NextPicture)), []);
    assert_eq!(s.picture, Picture::Render);
    // on the render, a change renders and does not compare
    assert_eq!(s.handle(key(Action::NextView)), [Command::Render]);
}

/// The comparison is for the scene file's camera at the reference's size, with the chapter,
/// view and depth the keys chose: moving the camera leaves it as it was (and the state says
/// the camera moved); a new view renders and compares anew.
#[test]
fn the_comparison_follows_the_keys_but_not_the_camera() {
    let mut s = state(Chapter::ReflectionRefraction).with_reference((24, 12));
    s.handle(key(Action::NextPicture));
    let before = s.compare_options().unwrap();
    assert_eq!((before.width, before.height), (24, 12));
    assert_eq!(before.camera.as_ref(), Some(&s.file_camera));
    assert!(!s.camera_moved());

    let cmds = s.handle(key(Action::Move(Move::Forward)));
    assert_eq!(cmds, [Command::Render, Command::Compare]);
    assert!(s.camera_moved());
    assert_ne!(s.camera(), &s.file_camera);
    assert_eq!(
        s.compare_options(),
        Some(before.clone()),
        "the camera moved"
    );

    assert_eq!(
        s.handle(key(Action::NextView)),
        [Command::Render, Command::Compare]
    );
    let flat = s.compare_options().unwrap();
    assert_eq!(flat.view, View::Flat);
    assert_eq!(flat.camera.as_ref(), Some(&s.file_camera));
    s.handle(key(Action::Depth(-1)));
    assert_eq!(s.compare_options().unwrap().max_depth, s.options.max_depth);
    s.handle(key(Action::Chapter(Chapter::Shading)));
    assert_eq!(s.compare_options().unwrap().chapter, Chapter::Shading);
    // the live image keeps its own size
    assert_eq!((s.options.width, s.options.height), (64, 48));
}

/// While the reference or the difference is shown a click inspects nothing: the line says
/// how to get back to the render.
#[test]
fn a_click_on_the_reference_says_to_show_the_render() {
    let mut s = state(Chapter::Shading).with_reference((24, 12));
    s.handle(key(Action::NextPicture));
    let cmds = s.handle(Input::Click {
        mouse: (10.0, 10.0),
        window: (64, 48),
    });
    assert!(
        matches!(cmds.as_slice(), [Command::Print(m)] if m.contains("press Tab")),
        "{cmds:?}"
    );
}

/// The window's comparison renders on its own thread, for the options it is given, and finds
/// the pixels changed in the reference: here a reference rendered by the chapter binaries'
/// render with two pixels changed, one by 3 steps (it differs) and one by 2 (it does not).
#[test]
fn the_windows_comparison_finds_the_changed_pixels() {
    use whitted::output::{Encoding, to_rgb8};
    use whitted_app::cli::Reference;
    use whitted_app::compare::Image;
    use whitted_app::window::comparison::Comparer;

    let s = state(Chapter::Shading).with_reference((32, 24));
    let options = s.compare_options().unwrap();
    let (fb, _) = render::render(&s.scene, &options);
    let mut rgb = to_rgb8(&fb, Encoding::Srgb);
    let rendered = rgb.clone();
    let at = |x: usize, y: usize| 3 * (y * 32 + x);
    let shift = |v: u8, by: u8| if v >= 128 { v - by } else { v + by };
    rgb[at(20, 9) + 1] = shift(rgb[at(20, 9) + 1], 3);
    rgb[at(4, 2)] = shift(rgb[at(4, 2)], 2);
    let reference = Reference {
        path: "ref.png".into(),
        image: Image::new(32, 24, rgb).unwrap(),
    };
    let mut comparer = Comparer::new(reference.clone(), Encoding::Srgb).unwrap();
    assert_eq!(comparer.status(), "comparing at 32×24…");
    assert_eq!(
        comparer.screen(Picture::Difference),
        Some(reference.image.to_screen().as_slice()),
        "the reference until the difference is made"
    );
    assert_eq!(comparer.screen(Picture::Render), None);

    comparer.ask(&s.scene, options.clone());
    let said = comparer.wait(Duration::from_secs(60));
    assert_eq!(
        said,
        Some(Ok(format!(
            "compare: 1 of 768 pixels differ by more than 2/255 (0.13%), by up to 3/255; the first at (20, 9), where the render has ({}, {}, {}) and the reference ({}, {}, {})",
            rendered[at(20, 9)],
            rendered[at(20, 9) + 1],
            rendered[at(20, 9) + 2],
            reference.image.rgb[at(20, 9)],
            reference.image.rgb[at(20, 9) + 1],
            reference.image.rgb[at(20, 9) + 2],
        )))
    );
    assert_eq!(
        comparer.status(),
        "1 of 768 pixels differ by more than 2/255"
    );
    let difference = comparer.screen(Picture::Difference).unwrap();
    assert_eq!(difference[9 * 32 + 20], 0x00ff_ff00, "3 steps off: yellow");
    let grey = difference[2 * 32 + 4];
    assert_eq!(grey >> 16, grey & 0xff, "2 steps off: grey, {grey:06x}");
    assert_eq!(
        comparer.screen(Picture::Reference),
        Some(reference.image.to_screen().as_slice())
    );

    // the same options again: nothing new is asked, the result stays
    comparer.ask(&s.scene, options.clone());
    assert!(comparer.comparison().is_some());
    assert_eq!(comparer.wait(Duration::from_millis(200)), None);
    // other options: a new comparison, for the whole image again (flat view differs a lot)
    let flat = Options {
        view: View::Flat,
        ..options
    };
    comparer.ask(&s.scene, flat);
    assert!(comparer.comparison().is_none());
    let said = comparer.wait(Duration::from_secs(60)).unwrap().unwrap();
    assert!(
        said.starts_with("compare: ") && !said.contains(" 1 of 768"),
        "{said}"
    );
}

/// The overlay's projection inverts the camera ray: any point on the ray through a pixel's
/// centre lands on that centre; a point behind the eye does not land.
#[test]
fn projection_inverts_the_camera_ray() {
    let scene = showcase();
    let camera = scene.camera.camera(640, 480);
    for (x, y) in [(0, 0), (320, 240), (639, 479), (17, 400)] {
        let ray = camera.pixel_ray(x, y, 0.5, 0.5);
        for t in [0.5, 1.0, 7.0, 300.0] {
            let (px, py) = overlay::project(&camera, ray.at(t)).unwrap();
            assert_relative_eq!(px, x as Real + 0.5, epsilon = 1e3 * EPS);
            assert_relative_eq!(py, y as Real + 0.5, epsilon = 1e3 * EPS);
        }
        assert_eq!(overlay::project(&camera, ray.at(-1.0)), None);
    }
}

/// The overlay of a pixel in a shadow holds a blocked feeler ending at its blocker, marked;
/// drawn, it changes pixels along the lines and leaves the far corner alone.
#[test]
fn the_overlay_of_a_shadowed_pixel_shows_the_blocked_feeler() {
    let scene = showcase();
    let o = options(&scene, Chapter::Shadows, 640, 480);
    let tracer = Tracer::new(&scene, &o);
    // find a pixel whose first hit has a blocked feeler
    let tree = (0..480)
        .step_by(7)
        .flat_map(|y| (0..640).step_by(7).map(move |x| (x, y)))
        .map(|(x, y)| tracer.inspect(x, y))
        .find(|t| {
            t.samples[0].ray.hit.as_ref().is_some_and(|h| {
                h.lights
                    .iter()
                    .any(|l| l.feeler.is_some() && l.share == 0.0)
            })
        })
        .expect("the showcase has shadows");
    let ov = Overlay::new(&tree, tracer.camera(), 100.0);
    assert!(ov.lines.iter().any(|l| l.2 == Stroke::FeelerBlocked));
    assert!(ov.lines.iter().any(|l| l.2 == Stroke::FeelerBeyond));
    assert!(ov.marks.iter().any(|m| m.1 == Mark::Blocker));
    let (x, y) = tree.pixel;
    // the hit point lands on the clicked pixel
    let hit = ov.marks.iter().find(|m| m.1 == Mark::Hit).unwrap().0;
    assert!((hit.0 - (x as Real + 0.5)).abs() < 0.01 && (hit.1 - (y as Real + 0.5)).abs() < 0.01);
    let mut screen = vec![0x12_3456u32; 640 * 480];
    ov.draw(&mut screen, 640, 480, (1.0, 1.0));
    assert_eq!(
        screen[(y * 640 + x + 6) as usize] & 0xff_ffff,
        0xff_ffff,
        "the ring"
    );
    let changed = screen.iter().filter(|&&p| p != 0x12_3456).count();
    assert!(changed > 200, "{changed} pixels drawn");
    let blocked = ov
        .lines
        .iter()
        .find(|l| l.2 == Stroke::FeelerBlocked)
        .unwrap();
    let mid = (
        (blocked.0.0 + blocked.1.0) / 2.0,
        (blocked.0.1 + blocked.1.1) / 2.0,
    );
    if (0.0..640.0).contains(&mid.0) && (0.0..480.0).contains(&mid.1) {
        let p = screen[(mid.1 as usize) * 640 + mid.0 as usize];
        assert!(p == Stroke::FeelerBlocked.colour() || p == 0, "{p:06x}");
    }
}

/// Runs a chapter binary with `args` and the environment changed by `env`.
fn run_binary(
    bin: &std::path::Path,
    args: &[&str],
    env: &[(&str, Option<&str>)],
) -> std::process::Output {
    let mut cmd = std::process::Command::new(bin);
    cmd.args(args).current_dir(std::env::temp_dir());
    for (k, v) in env {
        match v {
            Some(v) => cmd.env(k, v),
            None => cmd.env_remove(k),
        };
    }
    cmd.output().unwrap()
}

/// Without a display every chapter binary says so in one line, points to -o, and exits 2.
#[test]
fn without_a_display_the_window_is_one_line_of_error() {
    for chapter in Chapter::ALL {
        let bin = chapter.about().binary;
        for display in [None, Some(""), Some(":4093")] {
            let out = run_binary(
                &common::exe(chapter),
                &["--window"],
                &[("DISPLAY", display), ("WAYLAND_DISPLAY", None)],
            );
            let err = String::from_utf8_lossy(&out.stderr);
            assert_eq!(
                out.status.code(),
                Some(2),
                "{bin} DISPLAY={display:?}: {err}"
            );
            assert_eq!(err.lines().count(), 1, "{err}");
            assert!(
                err.starts_with("error: cannot open a window (")
                    && err
                        .trim_end()
                        .ends_with("): render to a file with -o FILE instead"),
                "{err}"
            );
            assert!(!err.contains("panicked"), "{err}");
        }
    }
}

/// --window with --inspect is refused: the window inspects by clicking.
#[test]
fn window_and_inspect_do_not_go_together() {
    let out = run_binary(
        &common::exe(Chapter::ReflectionRefraction),
        &["--window", "--inspect", "1,1"],
        &[],
    );
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(2));
    assert_eq!(err.lines().count(), 1);
    assert!(err.contains("--window and --inspect"), "{err}");
}

/// Each chapter binary offers --window in its help.
#[test]
fn every_chapter_binary_has_a_window() {
    for chapter in Chapter::ALL {
        let out = run_binary(&common::exe(chapter), &["--help"], &[]);
        assert!(
            String::from_utf8_lossy(&out.stdout).contains("--window"),
            "{chapter:?}"
        );
    }
}

/// The window's default size is the scene's, shrunk to fit 1280 × 960 with its aspect.
#[test]
fn the_window_fits_large_scenes_on_screen() {
    use whitted_app::cli::{WINDOW_FIT, fit};
    assert_eq!(fit(640, 480, WINDOW_FIT), (640, 480));
    assert_eq!(fit(1920, 1080, WINDOW_FIT), (1280, 720));
    assert_eq!(fit(1000, 4000, WINDOW_FIT), (240, 960));
    assert_eq!(fit(20000, 1, WINDOW_FIT), (1280, 1));
}

/// The screen scaled to the window: one to one at the image's size, each pixel twice across
/// and down at twice the size, the nearest pixel at any other.
#[test]
fn the_screen_scales_to_the_window_by_the_nearest_pixel() {
    let mut canvas = Canvas::new(3, 2, whitted::output::Encoding::Linear);
    canvas.screen = vec![1, 2, 3, 4, 5, 6];
    let mut frame = Vec::new();
    canvas.blit(&mut frame, 3, 2);
    assert_eq!(frame, [1, 2, 3, 4, 5, 6]);
    canvas.blit(&mut frame, 6, 4);
    assert_eq!(
        frame,
        [
            1, 1, 2, 2, 3, 3, 1, 1, 2, 2, 3, 3, 4, 4, 5, 5, 6, 6, 4, 4, 5, 5, 6, 6
        ]
    );
    canvas.blit(&mut frame, 2, 1);
    assert_eq!(frame, [1, 2]);
}
