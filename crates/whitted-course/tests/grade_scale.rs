//! A class at scale: 100 generated submissions graded one after the other in the sandbox,
//! the way a platform's container or `whitted grade --class` grades them, and the figures the
//! instructor's guide quotes: the per-submission median after the first, and where the time
//! goes (splice, build, test run).
//!
//! The submissions mix what a class hands in: the reference with one hand-written mutant,
//! a handout of one chapter, a handout of two exercises, and a chapter's handout with a
//! mutant elsewhere. Each is checked for what it must get: the reference's points but in the
//! exercises it left out or got wrong.
//!
//! Not part of `.ci/run` (about ten minutes on the 2-core machine):
//!
//! ```sh
//! cargo test -p whitted-course --test grade_scale -- --ignored --nocapture
//! ```
//!
//! `WHITTED_CLASS_SIZE=N` grades the first N submissions of the same class instead (a
//! quicker median).

mod common;

use std::path::PathBuf;
use std::time::Duration;

use common::{copy, index, manifest, mutant_body, mutants, root, set_body};
use whitted_course::grade::sandbox::Level;
use whitted_course::grade::{self, Grade};
use whitted_course::handout;

/// How many submissions: 100, or `WHITTED_CLASS_SIZE`.
fn class_size() -> usize {
    std::env::var("WHITTED_CLASS_SIZE")
        .ok()
        .and_then(|n| n.parse().ok())
        .filter(|&n| n >= 2)
        .unwrap_or(100)
}

/// The median of `values`.
fn median(mut values: Vec<f64>) -> f64 {
    values.sort_by(f64::total_cmp);
    values.get(values.len() / 2).copied().unwrap_or(0.0)
}

#[test]
#[ignore = "grades a class of 100 (ten minutes): run it by hand for the guide's figures"]
fn a_class_of_a_hundred_is_graded_and_timed() {
    let class_size = class_size();
    let m = manifest();
    let mutants = mutants();
    let chapter = |c: u8| -> Vec<usize> {
        (0..m.entries.len())
            .filter(|&i| m.entries[i].chapter == c)
            .collect()
    };
    let work = tempfile::tempdir().unwrap();
    let class = work.path().join("class");
    // what each submission leaves out or gets wrong, to check its points against
    let mut wrong: Vec<(String, Vec<usize>)> = Vec::new();
    for k in 0..class_size {
        let name = format!("s{k:03}");
        let dir = class.join(&name);
        let mu = &mutants[(k / 4) % mutants.len()];
        let c = u8::try_from((k / 4) % 5 + 1).unwrap();
        let lost = match k % 4 {
            0 => {
                copy(&dir);
                set_body(&dir, &m, &mu.exercise, &mutant_body(&m, mu));
                vec![index(&m, &mu.exercise)]
            }
            1 => {
                handout::write(&root(), &m, &chapter(c), &dir).unwrap();
                chapter(c)
            }
            2 => {
                let two = vec![(k * 7) % m.entries.len(), (k * 13 + 5) % m.entries.len()];
                handout::write(&root(), &m, &two, &dir).unwrap();
                two
            }
            _ => {
                let stripped = chapter(c);
                handout::write(&root(), &m, &stripped, &dir).unwrap();
                let i = index(&m, &mu.exercise);
                let mut lost = stripped;
                if !lost.contains(&i) {
                    set_body(&dir, &m, &mu.exercise, &mutant_body(&m, mu));
                    lost.push(i);
                }
                lost
            }
        };
        wrong.push((name, lost));
    }
    let options = grade::GradeSetup {
        chapter: None,
        hidden: None,
        timeout: Duration::from_secs(5),
        target_dir: Some(root().join("target").join("grade-tests")),
        keep: false,
        sandbox: Some(grade::SandboxSetup {
            runner: PathBuf::from(env!("CARGO_BIN_EXE_whitted")),
            worker: 0,
            level: Level::Namespaces,
        }),
        render: false,
        feedback: true,
        screen: true,
        judging: grade::Judging::Alone,
        judge: None,
        compile: grade::sandbox::watch::CompileLimits::default(),
    };
    let start = std::time::Instant::now();
    let entries = grade::grade_class(&root(), &m, &class, &options, 1, &|e| {
        if let Ok(g) = &e.grade {
            eprintln!(
                "graded {}: {:.2} / {} in {:.1} s (splice {:.1}, build {:.1}, run {:.1})",
                e.student,
                g.score(),
                g.max(),
                g.elapsed.as_secs_f64(),
                g.timings.splice.as_secs_f64(),
                g.timings.build.as_secs_f64(),
                g.timings.run.as_secs_f64()
            );
        }
    })
    .unwrap();
    let total = start.elapsed().as_secs_f64();
    let graded: Vec<&Grade> = entries
        .iter()
        .map(|e| {
            e.grade
                .as_ref()
                .unwrap_or_else(|why| panic!("{} not graded: {why}", e.student))
        })
        .collect();
    assert_eq!(graded.len(), class_size);
    for (g, (name, lost)) in graded.iter().zip(&wrong) {
        for e in &g.exercises {
            if lost.contains(&e.entry) {
                assert!(
                    e.score < e.max,
                    "{name} keeps the points of exercise {}",
                    m.entries[e.entry].exercise.id
                );
            }
        }
    }
    let later = &graded[1..];
    let of = |f: &dyn Fn(&Grade) -> Duration| -> f64 {
        median(later.iter().map(|g| f(g).as_secs_f64()).collect())
    };
    let mut all: Vec<f64> = later.iter().map(|g| g.elapsed.as_secs_f64()).collect();
    all.sort_by(f64::total_cmp);
    eprintln!(
        "a class of {class_size} in {total:.0} s, one at a time; the first in {:.0} s; after it the median submission {:.1} s (splice {:.1} s, build {:.1} s, test run {:.1} s), the slowest {:.1} s, 90% within {:.1} s",
        graded[0].elapsed.as_secs_f64(),
        of(&|g| g.elapsed),
        of(&|g| g.timings.splice),
        of(&|g| g.timings.build),
        of(&|g| g.timings.run),
        all.last().copied().unwrap_or(0.0),
        all[all.len() * 9 / 10],
    );
}
