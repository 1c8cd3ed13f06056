//! How fast the live window answers a camera move: for the showcase at 640 × 480, the time
//! from a key press (a 3° turn, as the arrow keys give) to the first complete coarse pass
//! and to the full image, through the same worker, channel and canvas the window uses.
//! Medians of several runs; the goals are 30 ms and 150 ms. For comparison, the same view
//! rendered in one go (`render::render`, as `-o` does: whole tiles, packets) after each move.
//!
//! ```text
//! cargo bench --bench interactive              # 21 moves
//! cargo bench --bench interactive -- 51        # 51 moves
//! ```

use std::time::{Duration, Instant};

use whitted::output::Encoding;
use whitted::render::{Chapter, Options};
use whitted_app::window::canvas::Canvas;
use whitted_app::window::progressive::{Update, Worker};
use whitted_app::window::schedule::PASSES;
use whitted_app::window::state::{Action, Command, Input, State, Turn};

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        (v[n / 2 - 1] + v[n / 2]) / 2.0
    }
}

fn main() {
    let runs: usize = std::env::args()
        .skip(1)
        .find_map(|a| a.parse().ok())
        .unwrap_or(21)
        .max(1);
    let scene = whitted::scene::showcase().expect("the showcase loads");
    let mut options = Options::for_scene(&scene, Chapter::ReflectionRefraction);
    (options.width, options.height) = (640, 480);
    let mut state = State::new(scene, options, Chapter::ReflectionRefraction);
    let worker = Worker::spawn(0).expect("the render thread starts");
    let mut canvas = Canvas::new(640, 480, Encoding::Srgb);
    let (mut coarse, mut full, mut whole) = (Vec::new(), Vec::new(), Vec::new());
    let pool = rayon::ThreadPoolBuilder::new()
        .build()
        .expect("a thread pool starts");
    // one warm-up move, then the measured ones, turning left and right in turn
    for run in 0..=runs {
        let turn = if run % 2 == 0 {
            Turn::Left
        } else {
            Turn::Right
        };
        let start = Instant::now();
        let commands = state.handle(Input::Key {
            action: Action::Turn(turn),
            fast: false,
        });
        assert_eq!(commands, [Command::Render]);
        let generation = worker.submit(std::sync::Arc::clone(&state.scene), state.options.clone());
        canvas.expect(generation);
        let mut first = None;
        loop {
            let update = worker
                .wait_update(Duration::from_secs(60))
                .expect("the worker answers");
            if let Update::Failed { message, .. } = &update {
                panic!("{message}");
            }
            canvas.apply(&update);
            if canvas.passes_done >= 1 && first.is_none() {
                first = Some(start.elapsed());
            }
            if canvas.complete() {
                break;
            }
        }
        if run > 0 {
            coarse.push(first.unwrap().as_secs_f64() * 1e3);
            full.push(start.elapsed().as_secs_f64() * 1e3);
            // the same view rendered in one go, as `-o` does (tiles, packets), for comparison
            let start = Instant::now();
            let _ = pool.install(|| whitted::render::render(&state.scene, &state.options));
            whole.push(start.elapsed().as_secs_f64() * 1e3);
        }
    }
    let threads = std::thread::available_parallelism().map_or(1, usize::from);
    println!(
        "showcase 640×480, chapter 5, {runs} camera moves, {threads} thread(s), {PASSES} passes (8, 4, 2, 1 px)"
    );
    let reference = median(&mut whole);
    for (name, v, goal) in [
        ("first coarse pass", &mut coarse, 30.0),
        ("full image", &mut full, 150.0),
    ] {
        let (lo, hi) = (
            v.iter().copied().fold(f64::INFINITY, f64::min),
            v.iter().copied().fold(0.0, f64::max),
        );
        let m = median(v);
        println!(
            "{name:>18}: median {m:7.2} ms (min {lo:.2}, max {hi:.2}); goal < {goal} ms: {}",
            if m < goal { "met" } else { "NOT met" }
        );
    }
    println!(
        "{:>18}: median {reference:7.2} ms: the progressive full image takes {:.2}× as long",
        "one-shot render",
        median(&mut full) / reference
    );
}
