//! Chapter 1 — camera rays (notes: "Principles of Ray Tracing").
//!
//! The synthetic camera is the viewing coordinate system: the eye e and three unit vectors
//! u (right), v (up) and n (backwards, away from what the camera looks at). The near plane
//! sits at distance N in front of the eye, along −n, and spans 2W × 2H where
//!
//! ```text
//! H = N·tan(θ/2)        θ: vertical viewing angle, converted from degrees to radians
//! W = H·A               A = width / height, the aspect ratio
//! (u_c, v_r) = (−W + W·2c/n,  −H + H·2r/m)        column c of n, row r of m (r from the bottom)
//! d = −N·n + u_c·u + v_r·v
//! r(t) = e + d·t
//! ```
//!
//! The notes' (c, r) name a pixel's lower-left *corner*: c = 0 lands on the left edge −W and
//! c = n on the right edge +W. The renderer shoots through pixel *centres*, (c + ½, r + ½), so
//! that the image is symmetric; see `chapters/ch01_camera_rays/README.md`.
//!
//! ```toml
//! [camera]
//! eye = [0.0, 2.0, 8.0]
//! look_at = [0.0, 0.5, 0.0]
//! up = [0.0, 1.0, 0.0]
//! fov = 60.0
//! near = 1.0
//! ```
//!
//! Course book: [Chapter 1, camera rays](../../../../docs/book/ch01-camera-rays.html) (`docs/src/ch01-camera-rays.md`).

use crate::ray::Ray;
use crate::real::{Real, Vec3};

/// H = N·tan(θ/2): half the height of the near plane, for a vertical viewing angle θ in degrees.
#[must_use]
pub fn near_plane_half_height(near: Real, fov_degrees: Real) -> Real {
    // BEGIN SOLUTION near_plane_half_height
    near * (fov_degrees.to_radians() / 2.0).tan() // H = N tan(π/180 · θ/2)
    // END SOLUTION
}

/// W = H·A: half the width of the near plane for the aspect ratio A = width / height.
#[must_use]
pub fn near_plane_half_width(half_height: Real, aspect: Real) -> Real {
    // BEGIN SOLUTION near_plane_half_width
    half_height * aspect // W = H A
    // END SOLUTION
}

/// The notes' (u_c, v_r) = (−W + W·2c/n, −H + H·2r/m): where pixel (c, r) of an n × m window
/// lands on the near plane. Integer c, r give the pixel's lower-left corner; add ½ for its centre.
#[must_use]
pub fn pixel_on_near_plane(
    c: Real,
    r: Real,
    columns: Real,
    rows: Real,
    half_width: Real,
    half_height: Real,
) -> (Real, Real) {
    // BEGIN SOLUTION pixel_on_near_plane
    // −W + W·2c/n written as W·(2c/n − 1): the centre column c = n/2 lands exactly on 0, so
    // the middle ray of an odd-sized image is exactly d = −N·n
    let u_c = half_width * (2.0 * c / columns - 1.0);
    let v_r = half_height * (2.0 * r / rows - 1.0);
    (u_c, v_r)
    // END SOLUTION
}

/// Chapter 1's colour of a ray: its unit direction d̂ mapped from [−1, 1] to [0, 1] on each
/// channel, (d̂ + 1)/2 (red = x, green = y, blue = z). The normals view of later chapters
/// shows unit normals the same way.
#[must_use]
pub fn direction_colour(d: Vec3) -> Vec3 {
    // BEGIN SOLUTION direction_colour
    (crate::numeric::normalize(d) + Vec3::ONE) * 0.5
    // END SOLUTION
}

/// The viewing coordinate system (u, v, n) of an eye looking at a point, with `up` as the
/// approximate up direction. Returns `None` when the view direction is zero or parallel to `up`.
#[must_use]
pub fn viewing_basis(eye: Vec3, look_at: Vec3, up: Vec3) -> Option<(Vec3, Vec3, Vec3)> {
    // BEGIN SOLUTION viewing_basis
    let n = (eye - look_at).try_normalize()?; // n points from the scene back to the eye
    let u = up.cross(n).try_normalize()?; // u = up × n, to the right
    let v = n.cross(u); // v = n × u, already unit
    Some((u, v, n))
    // END SOLUTION
}

/// A pinhole camera with the notes' parameters, and the derived near-plane size. Built once
/// by [`Camera::new`]; its parts are read with the accessors of the same names.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Camera {
    eye: Vec3,
    u: Vec3,
    v: Vec3,
    n: Vec3,
    near: Real,
    fov: Real,
    columns: u32,
    rows: u32,
    half_height: Real,
    half_width: Real,
}

impl Camera {
    // ANCHOR: ch1_camera_new
    /// Builds the camera. Returns `None` when the basis is degenerate (see [`viewing_basis`]).
    #[must_use]
    pub fn new(
        eye: Vec3,
        look_at: Vec3,
        up: Vec3,
        fov: Real,
        near: Real,
        columns: u32,
        rows: u32,
    ) -> Option<Self> {
        let (u, v, n) = viewing_basis(eye, look_at, up)?;
        let aspect = columns as Real / rows as Real; // A
        let half_height = near_plane_half_height(near, fov);
        let half_width = near_plane_half_width(half_height, aspect);
        Some(Self {
            eye,
            u,
            v,
            n,
            near,
            fov,
            columns,
            rows,
            half_height,
            half_width,
        })
    }
    // ANCHOR_END: ch1_camera_new

    /// The eye e, origin of the viewing coordinates.
    #[must_use]
    pub fn eye(&self) -> Vec3 {
        self.eye
    }

    /// Unit vector to the right on the near plane.
    #[must_use]
    pub fn u(&self) -> Vec3 {
        self.u
    }

    /// Unit vector up on the near plane.
    #[must_use]
    pub fn v(&self) -> Vec3 {
        self.v
    }

    /// Unit vector pointing backwards (the camera looks along −n).
    #[must_use]
    pub fn n(&self) -> Vec3 {
        self.n
    }

    /// Distance N from the eye to the near plane.
    #[must_use]
    pub fn near(&self) -> Real {
        self.near
    }

    /// Vertical viewing angle θ in degrees.
    #[must_use]
    pub fn fov(&self) -> Real {
        self.fov
    }

    /// Number of pixel columns (the notes' n).
    #[must_use]
    pub fn columns(&self) -> u32 {
        self.columns
    }

    /// Number of pixel rows (the notes' m).
    #[must_use]
    pub fn rows(&self) -> u32 {
        self.rows
    }

    /// H, half the near plane's height.
    #[must_use]
    pub fn half_height(&self) -> Real {
        self.half_height
    }

    /// W, half the near plane's width.
    #[must_use]
    pub fn half_width(&self) -> Real {
        self.half_width
    }

    // ANCHOR: ch1_direction_sig
    /// The notes' direction d = −N·n + u_c·u + v_r·v towards the point (u_c, v_r) where the
    /// (possibly fractional) column c and row r counted from the bottom land on the near plane
    /// ([`pixel_on_near_plane`]). d reaches the near plane at t = 1.
    #[must_use]
    pub fn direction(&self, c: Real, r: Real) -> Vec3 {
        // ANCHOR_END: ch1_direction_sig
        // BEGIN SOLUTION ray_direction
        let (u_c, v_r) = pixel_on_near_plane(
            c,
            r,
            self.columns as Real,
            self.rows as Real,
            self.half_width,
            self.half_height,
        );
        -self.near * self.n + u_c * self.u + v_r * self.v
        // END SOLUTION
    }

    // ANCHOR: ch1_ray
    /// The ray r(t) = e + d·t through the notes' pixel corner (c, r).
    #[must_use]
    pub fn ray(&self, c: Real, r: Real) -> Ray {
        Ray::new(self.eye, self.direction(c, r))
    }
    // ANCHOR_END: ch1_ray

    // ANCHOR: ch1_pixel_ray_sig
    /// The ray through a point of an image pixel, addressed as images are stored: column `x`
    /// from the left, row `y` from the *top*; (`dx`, `dy`) ∈ [0, 1)² is the position inside the
    /// pixel, (½, ½) being its centre.
    #[must_use]
    pub fn pixel_ray(&self, x: u32, y: u32, dx: Real, dy: Real) -> Ray {
        // ANCHOR_END: ch1_pixel_ray_sig
        // BEGIN SOLUTION pixel_ray
        let c = x as Real + dx;
        // row r counts from the bottom: the image row y (from the top) covers r ∈ [m−1−y, m−y]
        let r = (self.rows - 1 - y) as Real + (1.0 - dy);
        self.ray(c, r)
        // END SOLUTION
    }
}
