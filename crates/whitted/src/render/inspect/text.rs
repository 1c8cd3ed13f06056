//! The ray tree as indented text: what `--inspect X,Y` prints and the live window shows.
//!
//! One line per stop of the road, nested as the rays are; each number printed with at most
//! four decimals (the JSON of [`super::tree`] carries them in full). The lines are described
//! in `docs/src/inspect.md`.
//!
//! Course book: [The ray tree of one pixel](../../../../../../docs/book/inspect.html) (`docs/src/inspect.md`).

use std::fmt;

use super::super::framebuffer::Encoding;
use super::super::recorder::{RayKind, Stop};
use super::super::{Chapter, View};
use super::tree::{LightNode, RayNode, RayTree, part_name};
use crate::real::{Real, Vec3};

/// A vector as (x, y, z), each as [`N`] writes it.
struct V(Vec3);

impl fmt::Display for V {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "({}, {}, {})", N(self.0.x), N(self.0.y), N(self.0.z))
    }
}

/// A number with at most four decimals, trailing zeros dropped, without a sign on zero.
struct N(Real);

impl fmt::Display for N {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let x = self.0;
        if x.is_infinite() {
            return f.write_str(if x > 0.0 { "∞" } else { "−∞" });
        }
        let text = format!("{x:.4}");
        let text = text.trim_end_matches('0').trim_end_matches('.');
        f.write_str(if text == "-0" { "0" } else { text })
    }
}

/// `name` (object i), or object i.
fn object_label(name: Option<&str>, object: usize) -> String {
    match name {
        Some(n) => format!("`{n}` (object {object})"),
        None => format!("object {object}"),
    }
}

fn stop_reason(why: Stop) -> &'static str {
    match why {
        Stop::MaxDepth => "not traced: the maximum depth is reached",
        Stop::Weight => "not traced: its weight would fall below the minimum weight",
        Stop::TotalInternalReflection => {
            "none: total internal reflection (sin θ₂ > 1), k_t goes to the mirror ray"
        }
    }
}

impl fmt::Display for RayTree {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (x, y) = self.pixel;
        let n = self.samples.len();
        let png = match self.encoding {
            Encoding::Srgb => "sRGB",
            Encoding::Linear => "linear",
        };
        writeln!(
            f,
            "pixel ({x}, {y}), chapter {}, view {}: colour I = {} (linear RGB; {:?} in the {png} PNG), {} ray{}, {n} sample{}",
            self.chapter as u8,
            self.view.name(),
            V(self.colour),
            self.bytes(),
            self.rays,
            if self.rays == 1 { "" } else { "s" },
            if n == 1 { "" } else { "s" },
        )?;
        let shows = match (self.chapter, self.view) {
            (Chapter::CameraRays, _) => Some("the ray direction as a colour, (d̂ + 1)/2"),
            (Chapter::GenericObjects, View::Color) | (_, View::Flat) => {
                Some("the diffuse colour ρd of the material hit, unlit (background for a miss)")
            }
            (_, View::Normals) => Some("the normal facing the camera as a colour, (n + 1)/2"),
            (_, View::Depth) => {
                Some("the distance |t·d| of the hit on the depth view's grey scale")
            }
            (_, View::Shadows) => {
                Some("which lights reach the hit: light 0 red, 1 green, 2 blue, × share")
            }
            (_, View::Rays) => Some("the number of rays the pixel cast, on the heat scale"),
            (_, view) if crate::render::stages::is_stage(view) => {
                Some("one exercise's quantity at the hit (see `--help`'s list of views)")
            }
            _ => None,
        };
        if let Some(what) = shows {
            writeln!(f, "the colour shows {what}")?;
        }
        if n > 1 {
            writeln!(f, "I is the mean of the samples' colours")?;
        }
        for s in &self.samples {
            if n > 1 {
                writeln!(
                    f,
                    "sample {} at ({}, {}) in the pixel",
                    s.index,
                    N(s.position.0),
                    N(s.position.1)
                )?;
            }
            write_ray(f, &s.ray, 1)?;
        }
        Ok(())
    }
}

fn write_ray(f: &mut fmt::Formatter<'_>, r: &RayNode, level: usize) -> fmt::Result {
    let pad = "  ".repeat(level);
    match r.kind {
        RayKind::Camera => writeln!(
            f,
            "{pad}camera ray r(t) = e + d·t: e = {}, d = {} → colour {}",
            V(r.origin),
            V(r.direction),
            V(r.colour)
        )?,
        kind => {
            // the mirror ray brings back I_l (counted k_r times), the transmitted ray I_r (k_t)
            let (k, along, light) = match kind {
                RayKind::Mirror => ("k_r", "along l = ", "I_l"),
                _ => ("k_t", "along ", "I_r"),
            };
            writeln!(
                f,
                "{pad}{} ray (depth {}, {k} = {}, weight {}) from {} {along}{} → {light} = {}",
                kind.name(),
                r.depth,
                N(r.k),
                N(r.weight),
                V(r.origin),
                V(r.direction),
                V(r.colour)
            )?;
        }
    }
    let pad = "  ".repeat(level + 1);
    let Some(h) = &r.hit else {
        return writeln!(f, "{pad}hits nothing: the background colour");
    };
    writeln!(
        f,
        "{pad}hits {}: {}, material `{}`, on its {} at t = {}{}",
        object_label(h.name.as_deref(), h.object),
        h.shape,
        h.material,
        part_name(h.part),
        N(h.t),
        if h.entering {
            ", entering"
        } else {
            ", leaving"
        }
    )?;
    writeln!(f, "{pad}  P = {}, n = {}", V(h.point), V(h.normal))?;
    if let Some(i_a) = h.ambient {
        writeln!(f, "{pad}I_a = ρa·I_m = {}", V(i_a))?;
    }
    for l in &h.lights {
        write_light(f, l, &pad)?;
    }
    if let Some(local) = h.local {
        writeln!(
            f,
            "{pad}local light I_a + Σ (I_d + I_s)·share = {}",
            V(local)
        )?;
    }
    for b in &h.branches {
        write_ray(f, b, level + 1)?;
    }
    for (kind, why) in &h.stopped {
        writeln!(f, "{pad}{} ray: {}", kind.name(), stop_reason(*why))?;
    }
    if let (Some(_), false) = (h.local, h.branches.is_empty()) {
        let mut sum = String::from("I = local light");
        for b in &h.branches {
            sum += match b.kind {
                RayKind::Transmitted => " + k_t·I_r",
                _ => " + k_r·I_l",
            };
        }
        writeln!(f, "{pad}{sum} = {}", V(r.colour))?;
    }
    Ok(())
}

fn write_light(f: &mut fmt::Formatter<'_>, l: &LightNode, pad: &str) -> fmt::Result {
    writeln!(
        f,
        "{pad}light {} at {}: I_p·att = {} (attenuation {}), ρd·max(n·s, 0) = {}, ρs·max(r·v, 0)^f = {}",
        l.index,
        V(l.position),
        V(l.intensity),
        N(l.attenuation),
        V(l.diffuse),
        V(l.specular)
    )?;
    writeln!(
        f,
        "{pad}  I_d + I_s = I_p·att·(ρd·max(n·s, 0) + ρs·max(r·v, 0)^f) = {}",
        V(l.unshadowed)
    )?;
    match &l.feeler {
        None if !l.in_front => {
            return writeln!(f, "{pad}  behind the surface, n·(L − P) ≤ 0: adds nothing");
        }
        None if l.unshadowed == Vec3::ZERO => {
            return writeln!(f, "{pad}  adds nothing (no diffuse or specular colour)");
        }
        None => writeln!(
            f,
            "{pad}  no feeler (before chapter 4, or shadows = false): all of it arrives"
        )?,
        Some(feeler) => {
            writeln!(
                f,
                "{pad}  feeler S(u) = P′ + (L − P′)·u from P′ = {}, counting u ∈ ]{}, 1]",
                V(feeler.origin),
                N(feeler.u_min)
            )?;
            if feeler.crossings.is_empty() {
                writeln!(f, "{pad}    crosses nothing")?;
            }
            for c in &feeler.crossings {
                let us: Vec<String> = c.u.iter().map(|u| N(*u).to_string()).collect();
                writeln!(
                    f,
                    "{pad}    crosses {} at u = {} (k_t = {}{})",
                    object_label(c.name.as_deref(), c.object),
                    us.join(", "),
                    N(c.transmission),
                    if c.transmission == 0.0 {
                        ": opaque"
                    } else {
                        ""
                    }
                )?;
            }
        }
    }
    writeln!(
        f,
        "{pad}  share arriving {} → (I_d + I_s)·share = {}",
        N(l.share),
        V(l.arriving)
    )
}
