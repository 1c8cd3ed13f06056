//! The road's own exercises across the grader's wire ([`crate::judge`]; no chapter adds it):
//! `Tracer::local_light` (3.7), `Tracer::feeler` (4.4) and `Tracer::reflect_and_refract` (5.5).
//!
//! A method of the road reads its tracer (the scene, the options, the camera, the views'
//! scales) and tells a [`Recorder`] what it computed. To run one in another process, the
//! grader's stub sends the tracer's parts ([`RoadRef`]: once, then their number while they
//! stay the same) and the shading point by value; the
//! other side builds a tracer over the same scene asking [`EveryObject`] (every query gives the
//! same answers: `tests/render_paths.rs`), runs the method with a [`Log`] for its recorder, and
//! sends back its value with the events it recorded, which the stub then tells its own
//! recorder in their order ([`replay`]): the caller's recorder hears what it would have heard.
//!
//! Course book: [The instructor's guide](../../../../../docs/book/instructor-guide.html) (`docs/src/instructor-guide.md`).

use std::sync::{Arc, Mutex, PoisonError};

use serde::{Deserialize, Serialize};

use super::options::Options;
use super::query::ShadingPoint;
use super::recorder::{RayKind, Recorder, Stop};
use super::scales::Scales;
use super::tracer::{EveryObject, Tracer};
use crate::camera::Camera;
use crate::judge::{decode, encode};
use crate::light::Light;
use crate::material::Material;
use crate::offset::SpawnPoint;
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shading::Phong;
use crate::shadow::Feeler;
use crate::shapes::{Hit, Hits, Nearest};

/// One call a road's method made of its recorder, with its values.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub enum Event {
    /// [`Recorder::sample`].
    Sample(u32, Real, Real),
    /// [`Recorder::ray`].
    Ray(RayKind, Ray, Real, u32, Real, Real),
    /// [`Recorder::hit`].
    Hit(Option<Nearest>),
    /// [`Recorder::ambient`].
    Ambient(Vec3),
    /// [`Recorder::crossing`].
    Crossing(usize, Hits, Real),
    /// [`Recorder::light`].
    Light(usize, bool, Phong, Option<Feeler>, Real, Vec3),
    /// [`Recorder::local`].
    Local(Vec3),
    /// [`Recorder::stopped`].
    Stopped(RayKind, Stop),
    /// [`Recorder::done`].
    Done(Vec3),
}

/// A recorder that keeps every event, in order.
#[derive(Debug, Default)]
pub struct Log(pub Vec<Event>);

impl Recorder for Log {
    fn sample(&mut self, index: u32, dx: Real, dy: Real) {
        self.0.push(Event::Sample(index, dx, dy));
    }
    fn ray(&mut self, kind: RayKind, ray: &Ray, t_min: Real, depth: u32, weight: Real, k: Real) {
        self.0.push(Event::Ray(kind, *ray, t_min, depth, weight, k));
    }
    fn hit(&mut self, nearest: Option<&Nearest>) {
        self.0.push(Event::Hit(nearest.copied()));
    }
    fn ambient(&mut self, i_a: Vec3) {
        self.0.push(Event::Ambient(i_a));
    }
    fn crossing(&mut self, object: usize, hits: &Hits, k_t: Real) {
        self.0.push(Event::Crossing(object, *hits, k_t));
    }
    fn light(
        &mut self,
        light: usize,
        in_front: bool,
        phong: &Phong,
        feeler: Option<&Feeler>,
        share: Real,
        arriving: Vec3,
    ) {
        let e = Event::Light(light, in_front, *phong, feeler.copied(), share, arriving);
        self.0.push(e);
    }
    fn local(&mut self, colour: Vec3) {
        self.0.push(Event::Local(colour));
    }
    fn stopped(&mut self, kind: RayKind, why: Stop) {
        self.0.push(Event::Stopped(kind, why));
    }
    fn done(&mut self, colour: Vec3) {
        self.0.push(Event::Done(colour));
    }
}

/// Tells `rec` the `events`, in their order.
pub fn replay(events: &[Event], rec: &mut impl Recorder) {
    for e in events {
        match e {
            Event::Sample(i, dx, dy) => rec.sample(*i, *dx, *dy),
            Event::Ray(kind, ray, t_min, depth, weight, k) => {
                rec.ray(*kind, ray, *t_min, *depth, *weight, *k);
            }
            Event::Hit(nearest) => rec.hit(nearest.as_ref()),
            Event::Ambient(i_a) => rec.ambient(*i_a),
            Event::Crossing(object, hits, k_t) => rec.crossing(*object, hits, *k_t),
            Event::Light(l, in_front, phong, feeler, share, arriving) => {
                rec.light(*l, *in_front, phong, feeler.as_ref(), *share, *arriving);
            }
            Event::Local(c) => rec.local(*c),
            Event::Stopped(kind, why) => rec.stopped(*kind, *why),
            Event::Done(c) => rec.done(*c),
        }
    }
}

/// What a road's method reads of its tracer, as the stub sends it: the parts themselves the
/// first time, then only their number while they stay the same (a render asks thousands of
/// times with one scene). Which of the two is decided as it is written, so it must be written
/// once, inside the wire's turn, as [`crate::judge`] writes a call's arguments: decided
/// before, a render's threads could send a number before the parts it stands for.
pub struct RoadRef<'a> {
    parts: Parts<'a>,
}

/// [`RoadRef`] as it is written.
#[derive(Serialize)]
enum RoadOut<'p, 'a> {
    /// New parts, and the number they go by.
    Parts(u64, &'p Parts<'a>),
    /// The parts sent last, under this number.
    Same(u64),
}

/// The parts of a tracer its road's methods read, borrowed.
#[derive(Serialize)]
struct Parts<'a> {
    scene: &'a Scene,
    options: &'a Options,
    camera: &'a Camera,
    scales: &'a Scales,
}

/// The parts this side sent last, owned, and their number.
struct Sent {
    number: u64,
    road: Road,
}

/// What this side sent last.
static SENT: Mutex<Option<Sent>> = Mutex::new(None);

/// What the other side sent last, and its number.
static RECEIVED: Mutex<Option<(u64, Arc<Road>)>> = Mutex::new(None);

impl<'a> RoadRef<'a> {
    /// What to send for the parts of `tracer` its road's methods read.
    #[must_use]
    pub fn of<Q>(tracer: &'a Tracer<'a, Q>) -> Self {
        Self {
            parts: Parts {
                scene: tracer.scene,
                options: tracer.options,
                camera: &tracer.camera,
                scales: &tracer.scales,
            },
        }
    }
}

impl Serialize for RoadRef<'_> {
    fn serialize<S: serde::Serializer>(&self, serializer: S) -> Result<S::Ok, S::Error> {
        let p = &self.parts;
        let mut sent = SENT.lock().unwrap_or_else(PoisonError::into_inner);
        let same = sent.as_ref().filter(|s| {
            s.road.scene == *p.scene
                && s.road.options == *p.options
                && s.road.camera == *p.camera
                && s.road.scales == *p.scales
        });
        if let Some(s) = same {
            return RoadOut::Same(s.number).serialize(serializer);
        }
        let number = sent.as_ref().map_or(0, |s| s.number + 1);
        *sent = Some(Sent {
            number,
            road: Road {
                scene: p.scene.clone(),
                options: p.options.clone(),
                camera: p.camera.clone(),
                scales: *p.scales,
            },
        });
        drop(sent);
        RoadOut::Parts(number, p).serialize(serializer)
    }
}

/// [`RoadRef`] as the other side receives it (the same variants in the same order).
#[derive(Deserialize)]
enum RoadMsg {
    Parts(u64, Box<Road>),
    Same(u64),
}

impl RoadMsg {
    /// The parts this message stands for: new ones, kept for the next, or those kept.
    fn road(self) -> Result<Arc<Road>, String> {
        let mut received = RECEIVED.lock().unwrap_or_else(PoisonError::into_inner);
        match self {
            Self::Parts(number, road) => {
                let road = Arc::new(*road);
                *received = Some((number, Arc::clone(&road)));
                Ok(road)
            }
            Self::Same(number) => match received.as_ref() {
                Some((n, road)) if *n == number => Ok(Arc::clone(road)),
                _ => Err(format!("a tracer's parts never sent (number {number})")),
            },
        }
    }
}

/// The parts of a tracer, owned (the fields of [`Parts`] in the same order).
#[derive(Deserialize)]
struct Road {
    scene: Scene,
    options: Options,
    camera: Camera,
    scales: Scales,
}

/// A [`ShadingPoint`] received, its material owned (the same fields in the same order).
#[derive(Deserialize)]
struct Point {
    hit: Hit,
    material: Material,
    p: Vec3,
    d: Vec3,
    n: Vec3,
    spawn: SpawnPoint,
}

impl Road {
    /// A tracer over these parts, asking every object.
    fn tracer(&self) -> Tracer<'_, EveryObject<'_>> {
        Tracer {
            scene: &self.scene,
            options: &self.options,
            camera: self.camera.clone(),
            query: EveryObject {
                scene: &self.scene,
                numerics: self.options.numerics,
            },
            scales: self.scales,
        }
    }
}

impl Point {
    fn shading_point(&self) -> ShadingPoint<'_> {
        ShadingPoint {
            hit: self.hit,
            material: &self.material,
            p: self.p,
            d: self.d,
            n: self.n,
            spawn: self.spawn,
        }
    }
}

/// `Tracer::local_light` run here for the other end of the wire: its value and its events.
pub fn answer_local_light(args: &[u8]) -> Result<Vec<u8>, String> {
    let (road, point): (RoadMsg, Point) = decode(args)?;
    let road = road.road()?;
    let mut log = Log::default();
    let value = road.tracer().local_light(&point.shading_point(), &mut log);
    encode(&(value, log.0))
}

/// `Tracer::feeler` run here for the other end of the wire: its value.
pub fn answer_feeler(args: &[u8]) -> Result<Vec<u8>, String> {
    let (road, point, light): (RoadMsg, Point, Light) = decode(args)?;
    let road = road.road()?;
    encode(&road.tracer().feeler(&point.shading_point(), &light))
}

/// `Tracer::reflect_and_refract` run here for the other end of the wire: its value and its
/// events.
pub fn answer_reflect_and_refract(args: &[u8]) -> Result<Vec<u8>, String> {
    let (road, point, color, depth, weight): (RoadMsg, Point, Vec3, u32, Real) = decode(args)?;
    let road = road.road()?;
    let mut log = Log::default();
    let s = point.shading_point();
    let value = road
        .tracer()
        .reflect_and_refract(&s, color, depth, weight, &mut log);
    encode(&(value, log.0))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::render::Chapter;

    /// A tracer's parts cross whole the first time, then as their number, and the other side
    /// finds the same parts under it; other parts cross whole again. Each is decided as it is
    /// written: written twice (a count, then the bytes), the first write of new parts would
    /// carry only their number.
    #[test]
    fn a_tracers_parts_cross_once_then_as_their_number() {
        let text = "[camera]\neye = [0.0, 0.0, 5.0]\n[[objects]]\nsphere = {}\n";
        let road = |text: &str| {
            let scene = crate::scene::parse(text, "crossing.toml").unwrap();
            let options = Options::for_scene(&scene, Chapter::Shading);
            Road {
                camera: options.camera(&scene),
                scene,
                options,
                scales: Scales::default(),
            }
        };
        let (one, other) = (road(text), road(&text.replace("5.0", "6.0")));
        let send = |road: &Road| -> RoadMsg {
            decode(&encode(&RoadRef::of(&road.tracer())).unwrap()).unwrap()
        };
        let RoadMsg::Parts(n, _) = send(&one) else {
            panic!("new parts crossed as a number only");
        };
        let first = RoadMsg::Parts(n, Box::new(road(text))).road().unwrap();
        let RoadMsg::Same(m) = send(&one) else {
            panic!("the same parts crossed whole again");
        };
        assert_eq!(m, n, "the number of the parts sent last");
        let found = RoadMsg::Same(m).road().unwrap();
        assert!(Arc::ptr_eq(&first, &found), "the parts under that number");
        assert!(found.scene == one.scene && found.camera == one.camera);
        let RoadMsg::Parts(k, sent) = send(&other) else {
            panic!("other parts crossed as a number only");
        };
        assert_eq!(k, n + 1, "other parts' number");
        assert!(sent.scene == other.scene, "the other parts, whole");
        assert!(RoadMsg::Same(n + 7).road().is_err(), "a number never sent");
    }
}
