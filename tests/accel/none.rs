//! `--accel none` is the road's own loop: a render that asks for no structure asks the notes'
//! [`EveryObject`], not a structure that happens to test every object.

use super::STRAIN;
use whitted::accel::Accel;
use whitted::real::Real;
use whitted::render::{self, Chapter, EveryObject, Options, Recorder, Tracer};
use whitted::scene::parse;
use whitted::shapes::Hits;

/// What only [`EveryObject`] tells a recorder: each object a feeler crosses, in scene order
/// (an acceleration structure answers a feeler's share without naming them, and may stop at
/// the first opaque one).
#[derive(Default, Debug, PartialEq)]
struct Crossings(Vec<(usize, u64)>);

impl Recorder for Crossings {
    #[allow(clippy::useless_conversion)] // Real is f64, or f32 with the `f32` feature
    fn crossing(&mut self, object: usize, _: &Hits, k_t: Real) {
        self.0.push((object, u64::from(k_t.to_bits())));
    }
}

/// Every pixel of the strain scene (translucent spheres in a row, two lights, chapter 5)
/// rendered as the chapter binaries render it — the structure `--accel` names, built by
/// `build_accel` for a tracer made `with_accel` — tells its recorder the objects its feelers
/// cross with `--accel none`, exactly as the road asking [`EveryObject`] itself does, crossing
/// by crossing; with any structure it tells none.
#[test]
fn accel_none_renders_through_every_object() {
    let scene = parse(STRAIN, "strain.toml").expect("the strain scene parses");
    let mut o = Options::for_scene(&scene, Chapter::ReflectionRefraction);
    (o.width, o.height) = (48, 36);
    for accel in Accel::ALL {
        o.accel = accel;
        let structure = render::build_accel(&scene, &o);
        let tracer = Tracer::with_accel(&scene, &o, &structure);
        let every = tracer.asking(EveryObject {
            scene: &scene,
            numerics: o.numerics,
        });
        let (mut rendered, mut plain) = (Crossings::default(), Crossings::default());
        for y in 0..o.height {
            for x in 0..o.width {
                let _ = tracer.pixel(x, y, &mut rendered);
                let _ = every.pixel(x, y, &mut plain);
            }
        }
        assert!(
            plain.0.len() > 100,
            "the objects the feelers of the notes' loop cross: {}",
            plain.0.len()
        );
        if accel == Accel::None {
            assert!(
                rendered == plain,
                "--accel none: the crossings its render told ({}) are not those of EveryObject ({})",
                rendered.0.len(),
                plain.0.len()
            );
        } else {
            assert!(
                rendered.0.is_empty(),
                "--accel {}: a structure named {} crossings",
                accel.name(),
                rendered.0.len()
            );
        }
    }
}
