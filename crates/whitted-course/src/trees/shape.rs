//! What one ray tree is made of, in words: its *shape* ([`signature`]), which two pixels
//! share when their trees differ only in numbers that move continuously with the pixel, and
//! its *features* ([`features`]), which the pixels kept must show between them.
//!
//! Course book: [The ray tree of one pixel](../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::collections::BTreeSet;

use whitted_syllabus::tree::{Number, Plain, RayNode, RayTree};

/// The specular factor ρs·max(r·v, 0)^f (its largest channel) from which a light's term at a
/// hit is a highlight, a feature the pixels kept must show: a mistake in r or in the
/// highlight then changes a number a kept tree holds, not only numbers of order 10⁻⁵ at the
/// edge of a highlight.
pub const HIGHLIGHT: f64 = 0.05;

/// The shape of a tree: which objects and parts its rays hit and from which side, which
/// lights are in front, sent a feeler and what it crossed (and whether the share is 1, 0 or
/// between), which branches leave each hit or why they stop. Two trees of one shape
/// differ only in numbers that move continuously with the pixel.
#[must_use]
pub fn signature(tree: &RayTree<Plain>) -> String {
    fn ray(r: &RayNode<Plain>, out: &mut String) {
        out.push_str(r.kind.name());
        let Some(h) = &r.hit else {
            out.push_str(":miss;");
            return;
        };
        out.push_str(&format!(":{}/{:?}/{}", h.object, h.part, h.entering));
        for l in &h.lights {
            out.push_str(&format!("|L{}{}", l.index, l.in_front));
            if let Some(f) = &l.feeler {
                let crossed: Vec<String> = f
                    .crossings
                    .iter()
                    .map(|c| format!("{}x{}", c.object, c.u.len()))
                    .collect();
                // the share's class: its value is a product of the materials' k_t, whose last
                // bits differ in f32 (a share that is not a number is "partly")
                let share = if l.share.0 == 1.0 {
                    "lit"
                } else if l.share.0 == 0.0 {
                    "dark"
                } else {
                    "partly"
                };
                out.push_str(&format!("f[{}]{share}", crossed.join(",")));
            }
        }
        for (kind, why) in &h.stopped {
            out.push_str(&format!("|{}:{}", kind.name(), why.name()));
        }
        out.push('(');
        for b in &h.branches {
            ray(b, out);
        }
        out.push_str(");");
    }
    let mut out = String::new();
    for s in &tree.samples {
        ray(&s.ray, &mut out);
    }
    out
}

/// What a tree shows, for the choice of pixels: each object and part its rays hit (and leave),
/// each light's fate at a hit, each light's highlight (a specular factor of at least
/// [`HIGHLIGHT`] reaching the point), each kind of branch and stop, a camera ray's miss, and
/// the quarter of the image (of `size`) its pixel lies in.
#[must_use]
pub fn features(tree: &RayTree<Plain>, size: (u32, u32)) -> BTreeSet<String> {
    fn ray(r: &RayNode<Plain>, out: &mut BTreeSet<String>) {
        let kind = r.kind.name();
        let Some(h) = &r.hit else {
            out.insert(format!("a {kind} ray misses every object"));
            return;
        };
        let name = match &h.name {
            Some(n) => format!("`{n}`"),
            None => format!("object {}", h.object),
        };
        out.insert(format!("{name}, its {}, hit", h.part));
        if !h.entering {
            out.insert(format!("{name} hit from inside"));
        }
        for l in &h.lights {
            let share = arriving_share(l.share);
            let fate = if !l.in_front {
                "behind the surface"
            } else if l.feeler.is_none() {
                "lit without a feeler"
            } else if share == 1.0 {
                "lit"
            } else if share == 0.0 {
                "in shadow"
            } else {
                "in a translucent shadow"
            };
            out.insert(format!("light {}: {fate}", l.index));
            // ρs·max(r·v, 0)^f, the largest of its channels (a channel that is not a number
            // counts for none): a highlight that reaches the point
            let specular = l.specular.iter().map(|s| s.0).fold(0.0, f64::max);
            if specular >= HIGHLIGHT && share > 0.0 {
                out.insert(format!("light {}: a highlight", l.index));
            }
        }
        for (kind, why) in &h.stopped {
            out.insert(format!(
                "a {} ray stopped: {}",
                kind.name(),
                why.name().replace('_', " ")
            ));
        }
        for b in &h.branches {
            out.insert(format!("a {} ray", b.kind.name()));
            ray(b, out);
        }
    }
    let mut out = BTreeSet::new();
    let (x, y) = tree.pixel;
    out.insert(format!(
        "the image's {} {} quarter",
        if y < size.1 / 2 { "top" } else { "bottom" },
        if x < size.0 / 2 { "left" } else { "right" }
    ));
    for s in &tree.samples {
        ray(&s.ray, &mut out);
    }
    out
}

/// A light's share as [`features`] weighs it: a share that is not a number (`null` in the
/// JSON) counts as the whole light.
fn arriving_share(share: Number) -> f64 {
    if share.0.is_nan() { 1.0 } else { share.0 }
}
