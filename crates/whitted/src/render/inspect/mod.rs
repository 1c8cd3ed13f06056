//! The ray tree of one pixel: what `--inspect X,Y` prints, and what the live window draws.
//!
//! [`Tracer::inspect`](super::Tracer::inspect) runs the road of one pixel ([`super::tracer`])
//! with a [`TreeRecorder`], which keeps every event of the road ([`super::Recorder`]) as a
//! tree:
//!
//! ```text
//! RayTree ── samples ─► Sample ── ray ─► RayNode (camera ray: e, d, colour)
//!                                          └─ hit ─► HitNode (object, part, t, P, n, entering,
//!                                                     I_a, lights, local light, stopped branches)
//!                                                       ├─ lights ─► LightNode (Phong's factors
//!                                                       │             I_p·att, ρd·max(n·s, 0),
//!                                                       │             ρs·max(r·v, 0)^f, their sum,
//!                                                       │             feeler ─► crossings (u, k_t), share)
//!                                                       └─ branches ─► RayNode (mirror: k_r, I_l;
//!                                                                      transmitted: k_t, I_r) …
//! ```
//!
//! The tree records, and never recomputes: every number in it is a value the road computed
//! and handed to the recorder, from the function that computed it — the Phong terms from
//! [`crate::shading::phong`], each k from `Tracer::reflect_and_refract`, each object a feeler
//! crosses from [`super::tracer::EveryObject`], which the inspector asks (it tests every
//! object, where an acceleration structure may stop at the first opaque one, and gives the
//! same answers). So the tree's colour is the pixel's colour bit for bit, and its sums hold in
//! its own numbers.
//!
//! Three files, one job each: [`tree`] fills the tree's types (`whitted_syllabus::tree`, with
//! their JSON both ways) with the renderer's kinds,
//! [`record`] the recorder that builds it, [`text`] its indented text (`Display`). Two more
//! compare trees: [`provenance`] says which functions of the road computed each quantity of a
//! tree, and [`against`] walks a tree beside the reference's and finds the first quantity
//! that differs (`--against TREES.json`, `cargo learn`).
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

pub mod against;
pub mod difference;
pub mod provenance;
pub mod record;
pub mod text;
pub mod tree;
pub mod walk;

pub use record::{TreeRecorder, ray_tree};
pub use tree::{
    Crossing, FeelerNode, HitNode, JSON_VERSION, LightNode, RayNode, RayTree, Sample, Traced,
    part_name,
};
