//! The window's keys, in one table: [`keymap`]. Each row names its keys and what each asks
//! for, a word or two for the one-line summaries, and a sentence for the help. Everything
//! else about keys is read from it: the keys the shell polls ([`bindings`]), what `H` prints
//! ([`help`]), the help of `--window` ([`summary`], [`lines`]), and the key tables of the
//! course book (`docs/src/window.md`) and of README.md, which a test writes from these rows and
//! compares with the committed text.
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use minifb::Key;

use whitted::real::Real;
use whitted::render::{Chapter, View};

use super::action::{Action, Move, Turn};
use super::camera::{FAST, MOVE_SHARE, TURN_DEGREES};
use super::overlay::{Mark, Stroke};

/// A key and what it asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Binding {
    /// The key.
    pub key: Key,
    /// What it does.
    pub action: Action,
}

/// What sets a row off: keys, or a click.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Trigger {
    /// These keys, each with what it asks for.
    Keys(Vec<Binding>),
    /// The left mouse button (the pixel under it: [`super::state::Input::Click`]).
    LeftClick,
}

/// One row of the keymap: keys that do one kind of thing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Row {
    /// The keys (or the click).
    pub trigger: Trigger,
    /// What they do in a word or two, for the one-line summaries: "turn".
    pub short: &'static str,
    /// What they do in a sentence, for the help and the course book.
    pub description: String,
}

impl Row {
    fn keys(keys: Vec<(Key, Action)>, short: &'static str, description: impl Into<String>) -> Self {
        let bindings = keys
            .into_iter()
            .map(|(key, action)| Binding { key, action })
            .collect();
        Self {
            trigger: Trigger::Keys(bindings),
            short,
            description: description.into(),
        }
    }

    /// How the help and the book write the row's keys: "W A S D", "← → ↑ ↓", "1 … 5", "left
    /// click". A key on the keypad that types the same as one on the main keyboard is named
    /// once; a run of three or more digits is written first … last.
    #[must_use]
    pub fn label(&self) -> String {
        let Trigger::Keys(bindings) = &self.trigger else {
            return "left click".into();
        };
        let mut names: Vec<String> = Vec::new();
        for b in bindings {
            let name = key_name(b.key);
            if !names.contains(&name) {
                names.push(name);
            }
        }
        let digits: Vec<u32> = names.iter().filter_map(|n| n.parse().ok()).collect();
        let consecutive = digits.windows(2).all(|w| w[1] == w[0] + 1);
        match (digits.first(), digits.last()) {
            (Some(first), Some(last))
                if digits.len() == names.len() && digits.len() >= 3 && consecutive =>
            {
                format!("{first} … {last}")
            }
            _ => names.join(" "),
        }
    }
}

/// The keys that type the digits 1 to 9, on the main keyboard and on the keypad:
/// `DIGITS[n - 1]` types n.
const DIGITS: [[Key; 2]; 9] = [
    [Key::Key1, Key::NumPad1],
    [Key::Key2, Key::NumPad2],
    [Key::Key3, Key::NumPad3],
    [Key::Key4, Key::NumPad4],
    [Key::Key5, Key::NumPad5],
    [Key::Key6, Key::NumPad6],
    [Key::Key7, Key::NumPad7],
    [Key::Key8, Key::NumPad8],
    [Key::Key9, Key::NumPad9],
];

// every chapter has a digit
const _: () = assert!(Chapter::ALL.len() <= DIGITS.len());

/// How the help writes a key: what is printed on it.
#[must_use]
pub fn key_name(key: Key) -> String {
    if let Some(n) = DIGITS.iter().position(|keys| keys.contains(&key)) {
        return (n + 1).to_string();
    }
    match key {
        Key::Left => "←".into(),
        Key::Right => "→".into(),
        Key::Up => "↑".into(),
        Key::Down => "↓".into(),
        Key::Equal | Key::NumPadPlus => "+".into(),
        Key::Minus | Key::NumPadMinus => "−".into(),
        Key::Escape => "Esc".into(),
        // the letters: minifb names them by their letter
        other => format!("{other:?}"),
    }
}

/// `x` as the help prints it: no decimals when it has none.
fn number(x: Real) -> String {
    let rounded = (x * 1000.0).round() / 1000.0;
    format!("{rounded}")
}

/// Each key with its action, in order.
fn pairs<const N: usize>(keys: [Key; N], actions: [Action; N]) -> Vec<(Key, Action)> {
    keys.into_iter().zip(actions).collect()
}

/// The window's keys, in the order the help lists them.
#[must_use]
pub fn keymap() -> Vec<Row> {
    use Key::{Down, Left, Right, Up};
    let chapters: Vec<(Key, Action)> = Chapter::ALL
        .iter()
        .zip(DIGITS)
        .flat_map(|(&c, keys)| keys.map(|k| (k, Action::Chapter(c))))
        .collect();
    let views: Vec<&str> = View::WINDOW.iter().map(|v| v.name()).collect();
    let (more, less) = (Action::Depth(1), Action::Depth(-1));
    let one =
        |key, action, short, description: &str| Row::keys(vec![(key, action)], short, description);
    vec![
        Row::keys(
            pairs(
                [Key::W, Key::A, Key::S, Key::D],
                [Move::Forward, Move::Left, Move::Back, Move::Right].map(Action::Move),
            ),
            "move",
            format!(
                "move forward, left, back, right ({}% of the distance to the point looked at; Shift: {}×)",
                number(MOVE_SHARE * 100.0),
                number(FAST)
            ),
        ),
        Row::keys(
            pairs([Key::Q, Key::E], [Move::Down, Move::Up].map(Action::Move)),
            "down, up",
            "move down, up (along the scene's `up`)",
        ),
        Row::keys(
            pairs(
                [Left, Right, Up, Down],
                [Turn::Left, Turn::Right, Turn::Up, Turn::Down].map(Action::Turn),
            ),
            "turn",
            format!(
                "turn left, right, up, down by {}° (Shift: {}°); never straight along `up`",
                number(TURN_DEGREES),
                number(TURN_DEGREES * FAST)
            ),
        ),
        Row::keys(
            pairs(
                [Key::Equal, Key::NumPadPlus, Key::Minus, Key::NumPadMinus],
                [more, more, less, less],
            ),
            "depth",
            format!(
                "one more, one less level of mirror and transmitted rays (`max_depth`, chapter {})",
                crate::cli::offers::TRACING_FROM.number()
            ),
        ),
        Row::keys(
            chapters,
            "chapter",
            "the chapter whose renderer runs, up to the binary's own",
        ),
        Row::keys(
            vec![(Key::V, Action::NextView)],
            "view",
            format!("the next view: {}", views.join(", ")),
        ),
        one(
            Key::Tab,
            Action::NextPicture,
            "compare",
            &format!(
                "with `--compare REF.png`: show your render, the reference, the difference (pixels \
                 off by more than {}/255 marked) in turn; the title counts the pixels that differ",
                crate::compare::TOLERANCE
            ),
        ),
        one(
            Key::C,
            Action::PrintCamera,
            "camera",
            "print the camera as a `[camera]` table, ready to paste into the scene",
        ),
        one(
            Key::P,
            Action::Save,
            "save",
            "save the image as a PNG, to `-o` (atomically; a preview if the last pass is not done)",
        ),
        one(
            Key::R,
            Action::Reload,
            "reload",
            "reload the scene file; saving the file does the same",
        ),
        one(Key::H, Action::Help, "keys", "print these keys"),
        one(
            Key::Escape,
            Action::Quit,
            "quit",
            "quit (closing the window does too)",
        ),
        Row {
            trigger: Trigger::LeftClick,
            short: "ray tree",
            description: "print the pixel's ray tree and draw it over the image".into(),
        },
    ]
}

/// Every key the window reads, with what it asks for: the shell polls each once a frame.
#[must_use]
pub fn bindings() -> Vec<Binding> {
    keymap()
        .into_iter()
        .flat_map(|row| match row.trigger {
            Trigger::Keys(b) => b,
            Trigger::LeftClick => Vec::new(),
        })
        .collect()
}

/// The action bound to `key`, if any.
#[must_use]
pub fn action_of(key: Key) -> Option<Action> {
    bindings()
        .into_iter()
        .find(|b| b.key == key)
        .map(|b| b.action)
}

/// How the help writes the key bound to `action` ("Tab"), or "its key" if none is.
#[must_use]
pub fn label_of(action: Action) -> String {
    bindings()
        .into_iter()
        .find(|b| b.action == action)
        .map_or_else(|| "its key".into(), |b| key_name(b.key))
}

/// The keymap in one line: "W A S D move; Q E down, up; …".
#[must_use]
pub fn summary() -> String {
    let rows: Vec<String> = keymap()
        .iter()
        .map(|r| format!("{} {}", r.label(), r.short))
        .collect();
    rows.join("; ")
}

/// Two columns, each line indented by two spaces: the first padded to its widest entry.
fn columns(rows: &[(String, String)]) -> String {
    let width = rows
        .iter()
        .map(|(a, _)| a.chars().count())
        .max()
        .unwrap_or(0);
    let lines: Vec<String> = rows
        .iter()
        .map(|(a, b)| format!("  {a:<width$}  {b}"))
        .collect();
    lines.join("\n")
}

/// The keymap a row a line: each row's keys, then what they do.
#[must_use]
pub fn lines() -> String {
    let rows: Vec<(String, String)> = keymap()
        .iter()
        .map(|r| (r.label(), r.description.clone()))
        .collect();
    columns(&rows)
}

/// What the drawing of a ray tree shows, a stroke or mark a line: its look, then its meaning.
#[must_use]
pub fn legend() -> String {
    let rows: Vec<(String, String)> = Stroke::ALL
        .iter()
        .map(|s| s.legend())
        .chain(Mark::ALL.iter().map(|m| m.legend()))
        .map(|(look, meaning)| (look.to_string(), meaning.to_string()))
        .collect();
    columns(&rows)
}

/// What `H` prints (and the window at its start): the keys, then what a click draws.
#[must_use]
pub fn help() -> String {
    format!(
        "keys:\n{}\na click's ray tree, drawn:\n{}",
        lines(),
        legend()
    )
}
