//! The library's closed sets of values (views, acceleration structures, offsets, encodings …)
//! as command-line choices: [`Choice`] says how a type is offered, [`choice`] is clap's parser
//! for it, and each type's lines of `--help` are written here, one per value.
//!
//! Course book: [Introduction](../../../../../docs/book/introduction.html) (`docs/src/introduction.md`).

use clap::builder::PossibleValue;

use whitted::accel::Accel;
use whitted::offset::OffsetKind;
use whitted::output::Encoding;
use whitted::render::View;
use whitted::scene::scatter::Layout;
use whitted::shapes::Numerics;

/// A library type offered on the command line. Its values and their names are the library's
/// own (`ALL` and `name()`), so the two cannot disagree; only the line each value gets in
/// `--help` is the command line's.
pub trait Choice: Copy + PartialEq + Send + Sync + 'static {
    /// Every value, in the order `--help` lists them.
    fn all() -> &'static [Self];
    /// The value's name, as the library reports it and the command line takes it.
    fn name(self) -> &'static str;
    /// The value's line in `--help`.
    fn help(self) -> &'static str;
}

/// clap's parser for a [`Choice`]: the names it accepts, each with its help, and the value a
/// name stands for.
#[must_use]
pub fn choice<T: Choice>() -> impl clap::builder::TypedValueParser<Value = T> {
    use clap::builder::TypedValueParser;
    let names = T::all()
        .iter()
        .map(|&v| PossibleValue::new(v.name()).help(v.help()));
    clap::builder::PossibleValuesParser::new(names).try_map(|name: String| {
        T::all()
            .iter()
            .copied()
            .find(|v| v.name() == name)
            .ok_or_else(|| format!("no value is named `{name}`"))
    })
}

/// Implements [`Choice`] for a library type from its `ALL`, its `name()` and one help line
/// per value.
macro_rules! choice {
    ($ty:ty { $($variant:path => $help:literal),+ $(,)? }) => {
        impl Choice for $ty {
            fn all() -> &'static [Self] {
                &<$ty>::ALL
            }

            fn name(self) -> &'static str {
                <$ty>::name(self)
            }

            fn help(self) -> &'static str {
                match self {
                    $($variant => $help),+
                }
            }
        }
    };
}

choice!(Numerics {
    Numerics::Textbook => "the notes' formulas as printed",
    Numerics::Robust => "cancellation-free roots and discriminants",
});

choice!(View {
    View::Color => "the chapter's colour",
    View::Flat => "the material's diffuse colour, unlit",
    View::Normals => "the normal facing the camera, (n + 1)/2",
    View::Depth => "the distance to the nearest hit, near = white, far = grey (scale 1/d)",
    View::Shadows => "which lights reach each point: light 0 red, 1 green, 2 blue",
    View::Rays => "the rays each pixel casts, black (1) to white (the most possible)",
    View::Ambient => "exercise 3.1: the ambient term I_a = ρa·I_m alone",
    View::Attenuation => "exercise 3.2: each light's attenuation, in its colour (light 0 red, 1 green, 2 blue)",
    View::Diffuse => "exercise 3.3: each light's max(n·s, 0), in its colour; magenta: outside [0, 1]",
    View::Mirror => "exercise 3.4: the first light's mirror direction r, (r + 1)/2",
    View::Highlight => "exercise 3.5: each light's max(r·v, 0)^f, in its colour; magenta: outside [0, 1]",
    View::Direct => "exercise 3.6: I_d + I_s of every light, no ambient term, no shadows",
    View::Refracted => "exercise 5.3: the transmitted direction t of a translucent hit, (t + 1)/2",
    View::Mirrored => "exercise 5.4: the mirror ray's direction of a reflective hit, (l + 1)/2",
});

choice!(Accel {
    Accel::None => "every object for every ray (the notes' step 4)",
    Accel::Boxes => "a bounding box per object",
    Accel::Extents => "boxes, and projection extents for camera rays",
    Accel::Octree => "cubes subdivided until each holds at most 8 objects",
    Accel::Bvh => "a bounding volume hierarchy, binned SAH",
});

choice!(OffsetKind {
    OffsetKind::Fixed => "accept hits only for t > 1e-4 (world units): the classic",
    OffsetKind::Scaled => "move the origin by 1e-4·max(1, |P|) along the normal",
    OffsetKind::ErrorBound => "move the origin by a bound on the hit point's rounding error",
});

choice!(Encoding {
    Encoding::Srgb => "encode for screens and image viewers",
    Encoding::Linear => "the linear intensities as bytes, 0.5 → 128",
});

choice!(Layout {
    Layout::Field => "constant size and density over a square of side 2√N",
    Layout::Fog => "a fixed square; the radius shrinks as 1/√N",
});
