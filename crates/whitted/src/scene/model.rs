//! The scene as the renderer reads it: [`Scene`] (the camera, image size, lights, materials and
//! placed objects) and its camera's settings ([`CameraSettings`]), which the loader fills in
//! once every value has been checked.
//!
//! Course book: [The scene file](../../../../../docs/book/scene-format.html) (`docs/src/scene-format.md`).

use crate::camera::Camera;
use crate::light::Light;
use crate::material::Material;
use crate::real::{Real, Vec3};
use crate::shapes::Object;

/// The camera as the scene describes it; [`CameraSettings::camera`] adds the image size.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct CameraSettings {
    /// The eye e.
    pub eye: Vec3,
    /// The point looked at.
    pub look_at: Vec3,
    /// The up direction.
    pub up: Vec3,
    /// θ in degrees.
    pub fov: Real,
    /// N.
    pub near: Real,
}

impl CameraSettings {
    /// The camera for an image of `width` × `height` pixels. The loader has checked that the
    /// basis is not degenerate.
    #[must_use]
    pub fn camera(&self, width: u32, height: u32) -> Camera {
        Camera::new(
            self.eye,
            self.look_at,
            self.up,
            self.fov,
            self.near,
            width,
            height,
        )
        .expect("camera basis checked when the scene was loaded")
    }
}

/// A scene ready to render.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Scene {
    /// Where the camera is and how it sees.
    pub camera: CameraSettings,
    /// Image width in pixels.
    pub width: u32,
    /// Image height in pixels.
    pub height: u32,
    /// Colour of rays that hit nothing.
    pub background: Vec3,
    /// Maximum recursion depth (chapter 5).
    pub max_depth: u32,
    /// Samples per pixel.
    pub samples: u32,
    /// I_m, the ambient light.
    pub ambient: Vec3,
    /// The point lights.
    pub lights: Vec<Light>,
    /// The materials; objects refer to them by index.
    pub materials: Vec<Material>,
    /// The material names, in the order of `materials` (index 0 is the default material).
    pub material_names: Vec<String>,
    /// The placed objects.
    pub objects: Vec<Object>,
    /// The `name` each object was given in the scene file, in the order of `objects` (the
    /// inspector shows it; an object added in code past the end has none).
    pub object_names: Vec<Option<String>>,
    /// Remarks about the scene that do not stop it from rendering (e.g. ρa + ρd + ρs > 1).
    pub warnings: Vec<String>,
}

impl Scene {
    /// The camera at the scene's own image size.
    #[must_use]
    pub fn camera(&self) -> Camera {
        self.camera.camera(self.width, self.height)
    }

    /// The name object number `i` was given in the scene file, if any.
    #[must_use]
    pub fn object_name(&self, i: usize) -> Option<&str> {
        self.object_names.get(i).and_then(|n| n.as_deref())
    }
}
