//! The recorder that builds the ray tree from the road's events.
//!
//! It writes down the values the road hands it and computes no formula of its own: the names
//! it adds (of objects, shapes, materials) are labels for the reader. What it reads off those
//! values, it reads with the road's own functions: the hit point P = r(t) ([`Ray::at`]), and
//! which of a crossing object's hits lie in ]u_min, 1] ([`shadow::between`]). Whether a light
//! lies in front of the surface is the road's decision, handed to it.
//!
//! Course book: [The ray tree of one pixel](../../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use super::super::framebuffer::Encoding;
use super::super::query::Query;
use super::super::recorder::{RayKind, Recorder, Stop};
use super::super::tracer::{EveryObject, Tracer};
use super::super::{Options, Stats};
use super::tree::{Crossing, FeelerNode, HitNode, LightNode, RayNode, RayTree, Sample};
use crate::ray::Ray;
use crate::real::{Real, Vec3};
use crate::scene::Scene;
use crate::shading::Phong;
use crate::shadow::{self, Feeler};
use crate::shapes::{Hits, Nearest};

/// The ray tree of pixel (x, y): the road of [`Tracer::pixel`] with a [`TreeRecorder`], each
/// ray asked of [`EveryObject`] (which tells the recorder every object a feeler crosses, where
/// an acceleration structure may stop at the first opaque one). Its colour is the pixel's
/// colour bit for bit, whatever query `tracer` asks: every query gives the same answers.
#[must_use]
pub fn ray_tree(tracer: &Tracer<impl Query>, x: u32, y: u32) -> RayTree {
    let every = EveryObject {
        scene: tracer.scene,
        numerics: tracer.options.numerics,
    };
    let mut tree = TreeRecorder::new(tracer.scene);
    let mut count = Stats::default();
    let colour = tracer
        .asking(every)
        .pixel(x, y, &mut (&mut tree, &mut count));
    tree.into_tree((x, y), tracer.options, colour, count.total())
}

/// The recorder that keeps the tree ([`ray_tree`] uses it).
pub struct TreeRecorder<'s> {
    scene: &'s Scene,
    /// The rays under way, the camera ray first.
    stack: Vec<RayNode>,
    /// The sample under way: its index and position.
    sample: (u32, (Real, Real)),
    samples: Vec<Sample>,
    /// The objects the feeler under way crosses, as the query names them, until its light's
    /// event.
    crossed: Vec<(usize, Hits, Real)>,
}

impl<'s> TreeRecorder<'s> {
    /// An empty recorder for rays through `scene`.
    #[must_use]
    pub fn new(scene: &'s Scene) -> Self {
        Self {
            scene,
            stack: Vec::new(),
            sample: (0, (0.5, 0.5)),
            samples: Vec::new(),
            crossed: Vec::new(),
        }
    }

    /// The tree of pixel `pixel` rendered with `options`: the samples recorded, the colour the
    /// road returned for the pixel and the rays it cast.
    #[must_use]
    pub fn into_tree(
        self,
        pixel: (u32, u32),
        options: &Options,
        colour: Vec3,
        rays: u64,
    ) -> RayTree {
        RayTree(whitted_syllabus::tree::RayTree {
            pixel,
            chapter: options.chapter,
            view: options.view,
            colour,
            encoding: Encoding::default(),
            rays,
            samples: self.samples,
        })
    }

    fn top_hit(&mut self) -> Option<&mut HitNode> {
        self.stack.last_mut().and_then(|r| r.hit.as_mut())
    }

    fn object_name(&self, object: usize) -> Option<String> {
        self.scene.object_name(object).map(str::to_string)
    }
}

impl Recorder for TreeRecorder<'_> {
    fn sample(&mut self, index: u32, dx: Real, dy: Real) {
        self.sample = (index, (dx, dy));
    }

    fn ray(&mut self, kind: RayKind, ray: &Ray, t_min: Real, depth: u32, weight: Real, k: Real) {
        self.stack.push(RayNode {
            kind,
            origin: ray.origin,
            direction: ray.dir,
            t_min,
            depth,
            weight,
            k,
            colour: Vec3::ZERO,
            hit: None,
        });
    }

    fn hit(&mut self, nearest: Option<&Nearest>) {
        let Some(n) = nearest else {
            return;
        };
        let scene = self.scene;
        let object = &scene.objects[n.object];
        let name = self.object_name(n.object);
        let Some(top) = self.stack.last_mut() else {
            return;
        };
        top.hit = Some(HitNode {
            object: n.object,
            name,
            shape: object.shape.name().to_string(),
            material: scene
                .material_names
                .get(object.material)
                .cloned()
                .unwrap_or_else(|| format!("#{}", object.material)),
            part: n.hit.part,
            t: n.hit.t,
            point: Ray::new(top.origin, top.direction).at(n.hit.t),
            normal: n.hit.normal,
            entering: n.hit.entering,
            ambient: None,
            lights: Vec::new(),
            local: None,
            branches: Vec::new(),
            stopped: Vec::new(),
        });
    }

    fn ambient(&mut self, i_a: Vec3) {
        if let Some(hit) = self.top_hit() {
            hit.ambient = Some(i_a);
        }
    }

    fn crossing(&mut self, object: usize, hits: &Hits, k_t: Real) {
        self.crossed.push((object, *hits, k_t));
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
        let crossed = std::mem::take(&mut self.crossed);
        let feeler = feeler.map(|f| FeelerNode {
            origin: f.ray.origin,
            u_min: f.u_min,
            crossings: crossed
                .into_iter()
                .map(|(object, hits, transmission)| Crossing {
                    object,
                    name: self.object_name(object),
                    u: hits
                        .as_slice()
                        .iter()
                        .map(|h| h.t)
                        .filter(|&u| shadow::between(u, f.u_min))
                        .collect(),
                    transmission,
                })
                .collect(),
        });
        let position = self.scene.lights[light].position;
        let node = LightNode {
            index: light,
            position,
            attenuation: phong.attenuation,
            intensity: phong.intensity,
            diffuse: phong.diffuse,
            specular: phong.specular,
            unshadowed: phong.sum,
            in_front,
            feeler,
            share,
            arriving,
        };
        if let Some(hit) = self.top_hit() {
            hit.lights.push(node);
        }
    }

    fn local(&mut self, colour: Vec3) {
        if let Some(hit) = self.top_hit() {
            hit.local = Some(colour);
        }
    }

    fn stopped(&mut self, kind: RayKind, why: Stop) {
        if let Some(hit) = self.top_hit() {
            hit.stopped.push((kind, why));
        }
    }

    fn done(&mut self, colour: Vec3) {
        let Some(mut node) = self.stack.pop() else {
            return;
        };
        node.colour = colour;
        match self.top_hit() {
            Some(parent) => parent.branches.push(node),
            None => {
                let (index, position) = self.sample;
                self.samples.push(Sample {
                    index,
                    position,
                    ray: node,
                });
            }
        }
    }
}
