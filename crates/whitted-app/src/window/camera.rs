//! The camera as the window's keys move and turn it, and as `C` prints it: how far a key
//! press goes ([`MOVE_SHARE`], [`TURN_DEGREES`], [`FAST`] with Shift), the camera [`moved`] or
//! [`turned`] (never straight along its up vector), and the `[camera]` table of the scene
//! format ([`camera_table`]).
//!
//! Course book: [The live window](../../../../../docs/book/window.html) (`docs/src/window.md`).

use whitted::camera::Camera;
use whitted::real::{Real, Vec3};
use whitted::scene::CameraSettings;

use super::action::{Move, Turn};

/// The camera moves by this share of the eye's distance to the point looked at per key press.
pub const MOVE_SHARE: Real = 0.05;
/// The camera turns by this many degrees per key press.
pub const TURN_DEGREES: Real = 3.0;
/// Shift multiplies moves and turns by this.
pub const FAST: Real = 4.0;
/// The viewing direction stays at least this many degrees away from the up vector.
pub const MIN_PITCH_GAP: Real = 2.0;

/// The camera moved by `share` of its distance to the point looked at, in direction `m`;
/// `None` if the result cannot be a camera.
#[must_use]
pub fn moved(c: &CameraSettings, m: Move, share: Real) -> Option<CameraSettings> {
    let (f, right, up) = frame(c)?;
    let step = share * (c.look_at - c.eye).length();
    let delta = step
        * match m {
            Move::Forward => f,
            Move::Back => -f,
            Move::Right => right,
            Move::Left => -right,
            Move::Up => up,
            Move::Down => -up,
        };
    checked(CameraSettings {
        eye: c.eye + delta,
        look_at: c.look_at + delta,
        ..c.clone()
    })
}

/// The camera turned by `degrees` in direction `t` about its eye; `None` if the viewing
/// direction would come within [`MIN_PITCH_GAP`] degrees of the up vector.
#[must_use]
pub fn turned(c: &CameraSettings, t: Turn, degrees: Real) -> Option<CameraSettings> {
    let (f, right, up) = frame(c)?;
    let a = degrees.to_radians();
    let (axis, angle) = match t {
        Turn::Left => (up, a),
        Turn::Right => (up, -a),
        Turn::Up => (right, a),
        Turn::Down => (right, -a),
    };
    let g = rotate(f, axis, angle);
    if g.dot(up).abs() > MIN_PITCH_GAP.to_radians().cos() {
        return None;
    }
    let distance = (c.look_at - c.eye).length();
    checked(CameraSettings {
        look_at: c.eye + g * distance,
        ..c.clone()
    })
}

/// The unit viewing direction, the unit right vector and the unit up vector of a camera.
fn frame(c: &CameraSettings) -> Option<(Vec3, Vec3, Vec3)> {
    let f = (c.look_at - c.eye).try_normalize()?;
    let up = c.up.try_normalize()?;
    let right = f.cross(up).try_normalize()?;
    Some((f, right, up))
}

/// v turned by `angle` radians about the unit `axis` (Rodrigues' formula).
fn rotate(v: Vec3, axis: Vec3, angle: Real) -> Vec3 {
    let (s, c) = angle.sin_cos();
    v * c + axis.cross(v) * s + axis * axis.dot(v) * (1.0 - c)
}

/// The camera if its basis is not degenerate (see [`whitted::camera::viewing_basis`]).
fn checked(c: CameraSettings) -> Option<CameraSettings> {
    Camera::new(c.eye, c.look_at, c.up, c.fov, c.near, 1, 1).map(|_| c)
}

/// The camera as a `[camera]` table of the scene format.
#[must_use]
pub fn camera_table(c: &CameraSettings) -> String {
    let v = |p: Vec3| format!("[{}, {}, {}]", number(p.x), number(p.y), number(p.z));
    format!(
        "[camera]\neye = {}\nlook_at = {}\nup = {}\nfov = {}\nnear = {}",
        v(c.eye),
        v(c.look_at),
        v(c.up),
        number(c.fov),
        number(c.near)
    )
}

/// A number with at most 6 decimals and no trailing zeros, always with a decimal point or
/// as an integer TOML reads as a float field.
fn number(x: Real) -> String {
    let s = format!("{x:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" { "0".into() } else { s.into() }
}
