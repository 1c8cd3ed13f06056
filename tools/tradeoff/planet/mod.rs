//! A huge object seen from close by: a planet-sized sphere as the ground, the camera about
//! one unit above it.
//!
//! whitted intersects every object by the generic-object method: the world ray is carried
//! into the object's own space by M⁻¹ and meets the unit sphere there. For a sphere of radius
//! R the camera, one unit above the surface, lands at distance 1 + 1/R from the unit sphere's
//! centre, so the hit is known only to about R·u world units (u the unit roundoff). Each
//! worker measures, at its build's precision, for R = 1e3 … 1e7 and rays from the camera at
//! a few angles below the horizon:
//!
//! - how far the hit found lies from the true surface, and how far along the ray from the
//!   true hit (against an f64 reference computed in world space, see [`truth`]), for the
//!   generic-object method alone, for the library's nearest hit (refined in the f32 build)
//!   and for the fixes of [`fixes`];
//! - the share of the library's lit hit points whose feeler ray meets the planet again
//!   (shadow acne) under each offset strategy, and how far the error-bound offset pushes
//!   feelers out;
//! - the time per ray of each method.
//!
//! The sphere is placed as the scene file places `sphere = { center = [0, −R, 0], radius = R }`
//! (scale R, then translate): its top is the world origin, so every world coordinate the rays
//! and hits have is small, and the error measured is the method's, not the scene's.
//!
//! | module | what it holds |
//! |---|---|
//! | [`setup`] | the radii, angles and light measured, the planet, the camera rays |
//! | [`truth`] | the nearest hit and the height above the surface, to f64's accuracy |
//! | [`fixes`] | the ways of finding the nearest hit: the library's and the fixes |
//! | [`errors`] | hit errors, shadow acne and cost per ray, measured on one planet |
//! | [`tsv`] | `planet.tsv`: the worker's measurements written, and read back |
//! | [`report`] | the report's section, from both workers' measurements |

pub mod errors;
pub mod fixes;
pub mod report;
pub mod setup;
pub mod truth;
pub mod tsv;

pub use tsv::{Measured, measure_all};
