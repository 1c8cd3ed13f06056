//! What a render is asked to do besides the scene: the chapter, the view, the image size and
//! the accuracy and speed settings.
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use crate::accel::Accel;
use crate::camera::Camera;
use crate::offset::Offset;
use crate::real::Real;
use crate::scene::{CameraSettings, Parts, Scene};
use crate::shapes::Numerics;

/// Which chapter's renderer runs: how far along the road of one pixel a render goes. Its
/// number, title, binary, scene and book page are the course outline's
/// ([`Chapter::about`], from `whitted_syllabus::CHAPTERS`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Chapter {
    /// Chapter 1: rays only.
    CameraRays = 1,
    /// Chapter 2: nearest hit.
    GenericObjects = 2,
    /// Chapter 3: Phong shading.
    Shading = 3,
    /// Chapter 4: shadows.
    Shadows = 4,
    /// Chapter 5: reflection and refraction.
    ReflectionRefraction = 5,
}

impl Chapter {
    /// Every chapter, in order.
    pub const ALL: [Chapter; 5] = [
        Chapter::CameraRays,
        Chapter::GenericObjects,
        Chapter::Shading,
        Chapter::Shadows,
        Chapter::ReflectionRefraction,
    ];

    /// Chapter `n` (1 to 5), or `None`.
    #[must_use]
    pub fn from_number(n: u8) -> Option<Chapter> {
        Self::ALL.get(usize::from(n).checked_sub(1)?).copied()
    }

    /// Its number, 1 to 5.
    #[must_use]
    pub fn number(self) -> u8 {
        self as u8
    }

    /// The course outline's entry for it: title, binary, scene, book page.
    #[must_use]
    pub fn about(self) -> &'static whitted_syllabus::Chapter {
        &whitted_syllabus::CHAPTERS[usize::from(self.number()) - 1]
    }

    /// What of a scene file this chapter reads: chapter 1 only the camera and the image (it
    /// places no object, so it runs before chapter 2's functions are written), the others all.
    #[must_use]
    pub fn reads(self) -> Parts {
        match self {
            Chapter::CameraRays => Parts::CameraAndImage,
            _ => Parts::All,
        }
    }
}

const _: () = assert!(Chapter::ALL.len() == whitted_syllabus::CHAPTERS.len());
const _: () = assert!(View::ALL.len() == View::WINDOW.len() + View::STAGES.len());

/// What a chapter-2 (or later) render shows at each pixel.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Hash)]
pub enum View {
    /// The chapter's own colour (for chapter 2: the flat colour).
    #[default]
    Color,
    /// The material's diffuse colour ρd, unlit.
    Flat,
    /// The world normal n mapped to a colour, (n + 1)/2.
    Normals,
    /// Distance to the nearest hit on an inverse scale, near = white, far = grey, a miss
    /// black (see [`super::views`]).
    Depth,
    /// Which lights reach each point: light 0 red, 1 green, 2 blue … times the share that
    /// arrives (see [`super::views`]).
    Shadows,
    /// The rays each pixel casts, on a heat scale from 1 (black) to the most possible
    /// (white) (see [`super::views`]).
    Rays,
    /// Exercise 3.1's picture: the ambient term I_a = ρa·I_m alone (see [`super::stages`]).
    Ambient,
    /// Exercise 3.2's picture: each light's attenuation at the hit, in the light's colour.
    Attenuation,
    /// Exercise 3.3's picture: each light's max(n·s, 0), in the light's colour.
    Diffuse,
    /// Exercise 3.4's picture: the first light's mirror direction r as a colour, (r + 1)/2.
    Mirror,
    /// Exercise 3.5's picture: each light's max(r·v, 0)^f, in the light's colour.
    Highlight,
    /// Exercise 3.6's picture: Σ I_d + I_s of every light, without the ambient term.
    Direct,
    /// Exercise 5.3's picture: the transmitted direction of a translucent hit as a colour.
    Refracted,
    /// Exercise 5.4's picture: the mirror ray's direction of a reflective hit as a colour.
    Mirrored,
}

impl View {
    /// The views of a whole road, in the order the live window cycles through them.
    pub const WINDOW: [View; 6] = [
        View::Color,
        View::Flat,
        View::Normals,
        View::Depth,
        View::Shadows,
        View::Rays,
    ];

    /// The pictures of single exercises ([`super::stages`]), in the chapters' order.
    pub const STAGES: [View; 8] = [
        View::Ambient,
        View::Attenuation,
        View::Diffuse,
        View::Mirror,
        View::Highlight,
        View::Direct,
        View::Refracted,
        View::Mirrored,
    ];

    /// Every view: [`View::WINDOW`]'s, then [`View::STAGES`].
    pub const ALL: [View; 14] = {
        let mut all = [View::Color; 14];
        let mut i = 0;
        while i < all.len() {
            all[i] = if i < Self::WINDOW.len() {
                Self::WINDOW[i]
            } else {
                Self::STAGES[i - Self::WINDOW.len()]
            };
            i += 1;
        }
        all
    };

    /// The view's name on the command line and in reports.
    #[must_use]
    pub fn name(self) -> &'static str {
        match self {
            View::Color => "color",
            View::Flat => "flat",
            View::Normals => "normals",
            View::Depth => "depth",
            View::Shadows => "shadows",
            View::Rays => "rays",
            View::Ambient => "ambient",
            View::Attenuation => "attenuation",
            View::Diffuse => "diffuse",
            View::Mirror => "mirror",
            View::Highlight => "highlight",
            View::Direct => "direct",
            View::Refracted => "refracted",
            View::Mirrored => "mirrored",
        }
    }
}

/// Everything about a render that is not in the scene.
#[derive(Clone, Debug, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct Options {
    /// The chapter.
    pub chapter: Chapter,
    /// What to show.
    pub view: View,
    /// Image width (pixels).
    pub width: u32,
    /// Image height (pixels).
    pub height: u32,
    /// Samples per pixel (1 = the pixel centre).
    pub samples: u32,
    /// Maximum recursion depth: a primary ray has depth 0, its mirror ray depth 1 …
    pub max_depth: u32,
    /// A secondary ray whose weight (product of reflection/transmission shares) falls below
    /// this is not traced.
    pub min_weight: Real,
    /// Textbook or robust intersection formulas.
    pub numerics: Numerics,
    /// How secondary rays leave a surface.
    pub offset: Offset,
    /// Seed of the supersampling positions.
    pub seed: u64,
    /// Which acceleration structure answers ray queries (the image does not depend on it).
    pub accel: Accel,
    /// Trace the camera rays of 8 × 8 pixels, and their feelers, as packets where that pays
    /// (one sample a pixel, a BVH or an octree; see [`super::packets`]). The image is the
    /// same bit for bit either way; `false` renders every pixel by the plain road alone.
    pub packets: bool,
    /// The camera, when it is not the scene's own `[camera]`: the live window moves it.
    pub camera: Option<CameraSettings>,
}

impl Options {
    /// The scene's own settings for `chapter`: its size, samples and depth, robust formulas, the
    /// default offset and accelerator, packets on.
    #[must_use]
    pub fn for_scene(scene: &Scene, chapter: Chapter) -> Self {
        Self {
            chapter,
            view: View::Color,
            width: scene.width,
            height: scene.height,
            // supersampling belongs to chapter 5; earlier chapters shoot one ray per pixel centre
            samples: if chapter == Chapter::ReflectionRefraction {
                scene.samples
            } else {
                1
            },
            max_depth: scene.max_depth,
            min_weight: Self::MIN_WEIGHT,
            numerics: Numerics::default(),
            offset: Offset::default(),
            seed: 0x5eed,
            accel: Accel::default(),
            packets: true,
            camera: None,
        }
    }

    /// The camera of this render: [`Options::camera`] if set, else the scene's, at the
    /// options' image size.
    #[must_use]
    pub fn camera(&self, scene: &Scene) -> Camera {
        self.camera
            .as_ref()
            .unwrap_or(&scene.camera)
            .camera(self.width, self.height)
    }

    /// The default weight threshold: a contribution below 1/1000 (a quarter of one 8-bit step)
    /// cannot change a pixel.
    pub const MIN_WEIGHT: Real = 1e-3;

    /// The samples a pixel takes: the depth view shows one distance a pixel.
    #[must_use]
    pub fn samples_per_pixel(&self) -> u32 {
        if self.view == View::Depth {
            1
        } else {
            self.samples.max(1)
        }
    }
}
