//! What a key asks for: an [`Action`], with the directions the camera [`Move`]s and [`Turn`]s
//! in. The keymap ([`super::keys`]) binds keys to actions, and the state ([`super::state`])
//! carries them out.
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use whitted::render::Chapter;

/// Directions the camera moves in.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Move {
    /// Along the viewing direction.
    Forward,
    /// Against the viewing direction.
    Back,
    /// To the left on the image (−u).
    Left,
    /// To the right on the image (+u).
    Right,
    /// Against the scene's up vector.
    Down,
    /// Along the scene's up vector.
    Up,
}

/// Directions the camera turns in (the eye stays put, the point looked at moves).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Turn {
    /// About the up vector, to the left.
    Left,
    /// About the up vector, to the right.
    Right,
    /// About the image's horizontal, upwards.
    Up,
    /// About the image's horizontal, downwards.
    Down,
}

/// What a key asks for.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Action {
    /// Move the camera.
    Move(Move),
    /// Turn the camera.
    Turn(Turn),
    /// Change the maximum depth by this much.
    Depth(i32),
    /// Switch to this chapter.
    Chapter(Chapter),
    /// Cycle the views.
    NextView,
    /// Print the camera as a `[camera]` table.
    PrintCamera,
    /// Save the image.
    Save,
    /// Reload the scene file.
    Reload,
    /// Show the next picture: the render, the reference, the difference.
    NextPicture,
    /// Print the keys.
    Help,
    /// Quit.
    Quit,
}

impl Action {
    /// Whether holding its key repeats it: moving and turning do, the rest act once a press.
    #[must_use]
    pub fn repeats(self) -> bool {
        matches!(self, Action::Move(_) | Action::Turn(_))
    }
}
