//! # whitted-syllabus — the outline of the course
//!
//! The five chapters of the course notes, as every part of whitted names them: the renderer's
//! `Chapter` (how far along the road of one pixel a render goes), the chapter binaries, the
//! student's tests, the scenes, the chapter READMEs, the course book's pages, the window's
//! chapter keys and the course tools all read [`CHAPTERS`], and nothing else lists them.
//! Beside them, the section titles of the notes ([`SECTIONS`]) that the exercises cite, and
//! the message of an exercise not written yet ([`todo`](mod@todo)): a handout writes it into each
//! exercise's `todo!()`, and the renderer's error lines, `cargo learn` and the grader read it
//! back. And how every layer words a problem in one line ([`words`](mod@words): `line:col` in
//! a file, a command line's error, the PNG reader behind `--compare` and the figure check).
//!
//! Without features it depends on nothing (`png` adds the PNG decoder, `tree` the ray tree's
//! types and their JSON: [`tree`](mod@tree)), so the renderer and the course tools (which must not depend on the
//! renderer) can both use it, and a student's edit never rebuilds it.
//!
//! ```
//! let ch2 = whitted_syllabus::chapter(2).unwrap();
//! assert_eq!(ch2.binary, "ch02_generic_objects");
//! assert_eq!(ch2.scene(), "scenes/ch02_generic_objects.toml");
//! assert_eq!(ch2.page(), "docs/src/ch02-generic-objects.md");
//! assert_eq!(ch2.figure(), "docs/src/figures/ch02_generic_objects.png");
//! ```

#![deny(missing_docs)]

pub mod todo;
#[cfg(feature = "tree")]
pub mod tree;
pub mod words;

/// One chapter of the course.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Chapter {
    /// Its number, 1 to 5.
    pub number: u8,
    /// Its title in a sentence's lower case: "camera rays".
    pub title: &'static str,
    /// The name of its binary, which also names its test target (`tests/{binary}.rs`), its
    /// scene (`scenes/{binary}.toml`) and its README's directory (`chapters/{binary}/`).
    pub binary: &'static str,
    /// The stem of its page in the course book: `docs/src/{book}.md`.
    pub book: &'static str,
    /// What it adds to the renderer, in a line.
    pub adds: &'static str,
}

impl Chapter {
    /// The chapter's own scene: `scenes/chNN_name.toml`.
    #[must_use]
    pub fn scene(&self) -> String {
        format!("scenes/{}.toml", self.binary)
    }

    /// The chapter's README: `chapters/chNN_name/README.md`.
    #[must_use]
    pub fn readme(&self) -> String {
        format!("chapters/{}/README.md", self.binary)
    }

    /// The chapter's page in the course book's sources: `docs/src/chNN-name.md`.
    #[must_use]
    pub fn page(&self) -> String {
        format!("docs/src/{}.md", self.book)
    }

    /// The chapter's figure in the course book, its scene as the reference renders it:
    /// `docs/src/figures/chNN_name.png` (rendered by the chapter's binary from its scene, at
    /// the figure's width, as `docs/figures.toml` says; `cargo learn` compares the student's
    /// render with it).
    #[must_use]
    pub fn figure(&self) -> String {
        format!("docs/src/figures/{}.png", self.binary)
    }

    /// The chapter's title with a capital: "Camera rays".
    #[must_use]
    pub fn heading(&self) -> String {
        let mut chars = self.title.chars();
        chars.next().map_or_else(String::new, |first| {
            first.to_uppercase().chain(chars).collect()
        })
    }
}

/// The chapters, in order: `CHAPTERS[n - 1]` is chapter n.
pub const CHAPTERS: [Chapter; 5] = [
    Chapter {
        number: 1,
        title: "camera rays",
        binary: "ch01_camera_rays",
        book: "ch01-camera-rays",
        adds: "viewing coordinates, near plane, one ray per pixel",
    },
    Chapter {
        number: 2,
        title: "generic objects",
        binary: "ch02_generic_objects",
        book: "ch02-generic-objects",
        adds: "sphere, plane, cylinder, cone, polyhedra placed by M; rays by M⁻¹; normals by (M⁻¹)ᵀ",
    },
    Chapter {
        number: 3,
        title: "shading",
        binary: "ch03_shading",
        book: "ch03-shading",
        adds: "ambient + diffuse + specular (Phong), attenuation, several lights, RGB",
    },
    Chapter {
        number: 4,
        title: "shadows",
        binary: "ch04_shadows",
        book: "ch04-shadows",
        adds: "feeler rays towards each light, translucent shadows",
    },
    Chapter {
        number: 5,
        title: "reflection and refraction",
        binary: "ch05_reflection_refraction",
        book: "ch05-reflection-refraction",
        adds: "mirror and transmitted rays, Snell, total internal reflection, recursion",
    },
];

/// The first chapter's number and the last's: `FIRST..=LAST` are all of them.
pub const FIRST: u8 = 1;
/// The last chapter's number.
pub const LAST: u8 = CHAPTERS.len() as u8;

/// Chapter `number`, or `None` outside 1 to 5.
#[must_use]
pub fn chapter(number: u8) -> Option<&'static Chapter> {
    CHAPTERS.get(usize::from(number).checked_sub(1)?)
}

/// The chapter whose binary (and test target, scene, README directory) is `name`.
#[must_use]
pub fn by_binary(name: &str) -> Option<&'static Chapter> {
    CHAPTERS.iter().find(|c| c.binary == name)
}

/// The section titles of the course notes, the only values an exercise's `section` may take.
pub const SECTIONS: [&str; 14] = [
    "Principles of Ray Tracing",
    "Ray Tracing Process",
    "Generic Objects",
    "Generic Sphere",
    "Generic Plane",
    "Generic Cylinder",
    "Generic Cone",
    "Convex Polyhedra",
    "Computational Aspects",
    "Shading",
    "Surface Normals at Intersections",
    "Shadowing",
    "Reflection and Refraction",
    "Lighting Equations",
];

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chapters_are_numbered_in_order_and_named_after_their_number() {
        for (i, c) in CHAPTERS.iter().enumerate() {
            assert_eq!(usize::from(c.number), i + 1, "{c:?}");
            let prefix = format!("ch{:02}_", c.number);
            assert!(
                c.binary.starts_with(&prefix),
                "{} should start {prefix}",
                c.binary
            );
            assert_eq!(
                c.book,
                c.binary.replace('_', "-"),
                "the book page of {} should be its binary with dashes",
                c.number
            );
        }
        assert_eq!((FIRST, LAST), (1, 5));
    }

    #[test]
    fn a_chapter_is_found_by_number_and_by_binary() {
        assert_eq!(chapter(0), None);
        assert_eq!(chapter(6), None);
        assert_eq!(chapter(3).map(|c| c.title), Some("shading"));
        assert_eq!(by_binary("ch04_shadows").map(|c| c.number), Some(4));
        assert_eq!(by_binary("ch04"), None);
        assert_eq!(CHAPTERS[4].heading(), "Reflection and refraction");
    }
}
