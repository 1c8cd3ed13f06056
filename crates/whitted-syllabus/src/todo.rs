//! The message of an exercise not written yet, written and read here only.
//!
//! A handout replaces an exercise's body by `todo!("MESSAGE")`, with the message [`message`]
//! writes:
//!
//! ```text
//! exercise sphere_coefficients (2.6): The sphere's quadratic — see chapters/ch02_generic_objects/README.md
//! ```
//!
//! The exercise's name comes first: it is what stays when an exercise is inserted before it
//! (the displayed id in parentheses follows from the manifest's order, and is what the student
//! reads). When the body runs, the panic's text is `not yet implemented: ` and the message;
//! [`find`] reads it back out of a panic or a test's output, so that the renderer's binaries
//! print one line for it, `cargo learn` tells "not written yet" from "wrong", and the grader
//! says "not written".
//!
//! ```
//! use whitted_syllabus::todo;
//! let m = todo::message("sphere_coefficients", "2.6", "The sphere's quadratic", "chapters/ch02_generic_objects/README.md");
//! let panic = format!("thread 'main' panicked at src/a.rs:1:1:\nnot yet implemented: {m}");
//! let found = todo::find(&panic).unwrap();
//! assert_eq!((found.name, found.id), ("sphere_coefficients", "2.6"));
//! assert_eq!(
//!     found.not_written(),
//!     "exercise 2.6 (sphere_coefficients) is not written yet: The sphere's quadratic — see chapters/ch02_generic_objects/README.md"
//! );
//! ```

/// How the panic of a handout's `todo!()` begins: `todo!`'s own words, then the message's.
pub const PANIC_START: &str = "not yet implemented: exercise ";

/// The word that opens every message.
const LEAD: &str = "exercise ";

/// The message of exercise `name`, displayed as `id`, titled `title`, whose chapter's README is
/// `readme`.
#[must_use]
pub fn message(name: &str, id: &str, title: &str, readme: &str) -> String {
    format!("{LEAD}{name} ({id}): {title} — see {readme}")
}

/// How the panic of a later chapter's body begins in a handout that ends before that chapter
/// (see [`later_message`]).
pub const LATER_START: &str = "not yet implemented: chapter ";

/// The message of the body of exercise `name` (displayed as `id`) of chapter `chapter` in a
/// handout whose chapters end before it: the body is not the student's to write (it comes with
/// that chapter's handout), so the message opens with the chapter, never with `exercise `, and
/// [`find`] does not read it as an exercise not written yet.
///
/// ```
/// use whitted_syllabus::todo;
/// let m = todo::later_message("refract", "5.3", 5);
/// assert_eq!(
///     m,
///     "chapter 5 (reflection and refraction) is not part of this handout: exercise 5.3 (refract) comes with chapter 5's handout"
/// );
/// let panic = format!("not yet implemented: {m}");
/// assert_eq!(todo::find(&panic), None);
/// assert_eq!(todo::find_later(&panic), Some(m.as_str()));
/// ```
#[must_use]
pub fn later_message(name: &str, id: &str, chapter: u8) -> String {
    let title = crate::chapter(chapter).map_or_else(String::new, |c| format!(" ({})", c.title));
    format!(
        "chapter {chapter}{title} is not part of this handout: {LEAD}{id} ({name}) comes with chapter {chapter}'s handout"
    )
}

/// The message of the first panic of a later chapter's body ([`later_message`]) in `text` (a
/// panic's text, or a test's whole output): its first line, from `chapter …` on.
#[must_use]
pub fn find_later(text: &str) -> Option<&str> {
    let at = text.find(LATER_START)?;
    let message = text[at + "not yet implemented: ".len()..].lines().next()?;
    message
        .contains(" is not part of this handout: ")
        .then_some(message.trim_end())
}

/// An exercise's message, read back.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Todo<'a> {
    /// The exercise's name (`sphere_coefficients`).
    pub name: &'a str,
    /// Its displayed id when the handout was written (`2.6`).
    pub id: &'a str,
    /// The rest: its title and where to read about it.
    pub what: &'a str,
}

impl Todo<'_> {
    /// The one line a program prints for it: `exercise 2.6 (sphere_coefficients) is not
    /// written yet: The sphere's quadratic — see …`.
    #[must_use]
    pub fn not_written(&self) -> String {
        format!(
            "exercise {} ({}) is not written yet: {}",
            self.id, self.name, self.what
        )
    }
}

/// The message of the first `todo!()` panic of an exercise in `text` (a panic's text, or a
/// test's whole output), or `None` when there is none.
#[must_use]
pub fn find(text: &str) -> Option<Todo<'_>> {
    let at = text.find(PANIC_START)?;
    parse(&text[at + PANIC_START.len() - LEAD.len()..])
}

/// Reads a message as [`message`] writes it (its first line; anything after it is ignored).
#[must_use]
pub fn parse(message: &str) -> Option<Todo<'_>> {
    let line = message.lines().next()?.strip_prefix(LEAD)?;
    let (head, what) = line.split_once(": ")?;
    let (name, id) = head.split_once(" (")?;
    let id = id.strip_suffix(')')?;
    let is_name = !name.is_empty()
        && name
            .chars()
            .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '_');
    (is_name && !id.is_empty()).then_some(Todo {
        name,
        id,
        what: what.trim_end(),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What `message` writes, `parse` and `find` read back, wherever it sits in a test's output.
    #[test]
    fn a_message_is_read_back_by_name_and_id() {
        let m = message(
            "local_light",
            "3.7",
            "The local light: a hit",
            "chapters/x/README.md",
        );
        assert_eq!(
            m,
            "exercise local_light (3.7): The local light: a hit — see chapters/x/README.md"
        );
        let want = Todo {
            name: "local_light",
            id: "3.7",
            what: "The local light: a hit — see chapters/x/README.md",
        };
        assert_eq!(parse(&m), Some(want));
        let output = format!(
            "thread 'ex_local_light_x' (77) panicked at crates/whitted/src/a.rs:3:9:\n\
             not yet implemented: {m}\nnote: run with `RUST_BACKTRACE=1`\n"
        );
        assert_eq!(find(&output), Some(want));
    }

    /// Another panic, or a message of another shape, is not an exercise's.
    #[test]
    fn other_panics_are_not_an_exercises() {
        for text in [
            "index out of bounds: the len is 3 but the index is 7",
            "not yet implemented",
            "not yet implemented: exercise 2.3: The sphere",
            "not yet implemented: exercise Sphere (2.3): x",
            "not yet implemented: exercise sphere (2.3) x",
        ] {
            assert_eq!(find(text), None, "{text}");
        }
    }
}
