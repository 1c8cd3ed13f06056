//! Checking a scene file and building the [`Scene`].
//!
//! Reading is two steps: serde reads the TOML into [`format`] structures, checking every number
//! on the way; then [`parse`] checks what needs more than one value (an object has exactly one
//! shape, a material name is defined, a cylinder has a height …) and builds each object's
//! placement. Any error names the file, line and column of the offending value.
//!
//! Placement forms and the matrix M each one builds (steps applied left to right):
//!
//! | form | steps |
//! |---|---|
//! | `sphere = { center = c, radius = r }` | scale r, translate c |
//! | `plane = { point = p, normal = n }` | rotate +z onto n, translate p |
//! | `cylinder = { base = b, top = t, radius = r }` | scale (r, r, h/2), rotate +z onto (t − b)/h, translate (b + t)/2, with h = ‖t − b‖ |
//! | `cone = { base = b, apex = a, radius = r }` | scale (r/2, r/2, h/2), then as the cylinder with t = a: the generic base (radius 2 at z = −1) lands on b with radius r, the apex (0, 0, 1) on a |
//! | `box = { min = p, max = q }` | the cube [−1, 1]³, scale (q − p)/2, translate (p + q)/2 |
//!
//! Any object may add `transform = [ … ]` steps, applied after its placement form.
//!
//! Course book: [The scene file](../../../../../docs/book/scene-format.html) (`docs/src/scene-format.md`).

use std::collections::HashMap;
use std::ops::Range;
use std::path::Path;

use toml::Spanned;

use super::format::{AxialDesc, BoxDesc, ObjectDesc, PolyhedronDesc, SceneFile, StepDesc};
use super::model::{CameraSettings, Scene};
use crate::camera::viewing_basis;
use crate::error::{Error, line_col};
use crate::light::Light;
use crate::material::Material;
use crate::real::{Vec3, real, vec3_from};
use crate::shapes::{Facet, Object, Polyhedron, Shape};
use crate::transform::{Placement, Step, rotation_from_z};

/// The largest image side accepted, in pixels.
pub const MAX_SIDE: u32 = 65_535;
/// The most samples per pixel accepted.
pub const MAX_SAMPLES: u32 = 4096;
/// The deepest recursion accepted.
pub const MAX_DEPTH: u32 = 64;

/// What of a scene file a chapter reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Parts {
    /// The camera, the image and the render settings: chapter 1 shoots rays and places no
    /// object, so it needs none of chapter 2's functions. The lights, materials and objects are
    /// read as TOML (a syntax error is still an error) but not built: `objects` is empty.
    CameraAndImage,
    /// Everything, every object placed: chapters 2 to 5.
    All,
}

/// Reads and checks the scene file at `path`.
pub fn load(path: &Path) -> Result<Scene, Error> {
    load_parts(path, Parts::All)
}

/// Reads and checks the `parts` of the scene file at `path` that a chapter uses.
pub fn load_parts(path: &Path, parts: Parts) -> Result<Scene, Error> {
    let bytes = std::fs::read(path).map_err(|source| Error::Read {
        path: path.to_path_buf(),
        source,
    })?;
    let name = path.display().to_string();
    let text = String::from_utf8(bytes).map_err(|e| {
        let offset = e.utf8_error().valid_up_to();
        let text = String::from_utf8_lossy(e.as_bytes());
        at(
            &name,
            &text,
            offset..offset,
            "the file is not valid UTF-8 text".into(),
        )
    })?;
    parse_parts(&text, &name, parts)
}

fn at(file: &str, text: &str, span: Range<usize>, message: String) -> Error {
    let (line, col) = line_col(text, span.start);
    Error::Scene {
        file: file.to_string(),
        line,
        col,
        message,
    }
}

/// Checks the scene text `text`; `file` names it in error messages.
pub fn parse(text: &str, file: &str) -> Result<Scene, Error> {
    parse_parts(text, file, Parts::All)
}

/// Checks the `parts` of the scene text `text` that a chapter uses; `file` names it in error
/// messages.
pub fn parse_parts(text: &str, file: &str, parts: Parts) -> Result<Scene, Error> {
    let err = |span: Range<usize>, message: String| at(file, text, span, message);

    let has_content = text
        .lines()
        .any(|l| !l.trim().is_empty() && !l.trim_start().starts_with('#'));
    if !has_content {
        return Err(err(
            0..0,
            "the scene file is empty: expected at least one [[objects]] table".into(),
        ));
    }

    let raw: SceneFile = toml::from_str(text).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        let message = e.message().trim().replace('\n', " ");
        // serde's words for a one-key table (a `transform` step) with several keys
        let message = if message.starts_with("wanted exactly 1 element") {
            "a transform step has exactly one key: scale, rotate_x, rotate_y, rotate_z, rotate or translate (write one { … } per step)".to_string()
        } else {
            message
        };
        err(span, message)
    })?;

    // camera
    let cam = raw.camera.as_ref().map(|c| c.get_ref());
    let default_cam = super::format::CameraDesc::default();
    let cd = cam.unwrap_or(&default_cam);
    let camera = CameraSettings {
        eye: vec3_from(cd.eye.0),
        look_at: vec3_from(cd.look_at.0),
        up: vec3_from(cd.up.0),
        fov: real(cd.fov.0),
        near: real(cd.near.0),
    };
    let cam_span = raw.camera.as_ref().map_or(0..0, |c| c.span());
    if camera.eye == camera.look_at {
        return Err(err(
            cam_span,
            "camera: eye and look_at are the same point, so there is no view direction".into(),
        ));
    }
    if viewing_basis(camera.eye, camera.look_at, camera.up).is_none() {
        return Err(err(cam_span, "camera: up is zero or parallel to the view direction (look_at − eye); choose another up".into()));
    }

    // image and render settings
    for (what, v) in [("width", &raw.image.width), ("height", &raw.image.height)] {
        if *v.get_ref() == 0 || *v.get_ref() > MAX_SIDE {
            return Err(err(
                v.span(),
                format!(
                    "image {what}: expected a whole number from 1 to {MAX_SIDE}, found {}",
                    v.get_ref()
                ),
            ));
        }
    }
    let samples = &raw.render.samples;
    if !(1..=MAX_SAMPLES).contains(samples.get_ref()) {
        return Err(err(
            samples.span(),
            format!(
                "render samples: expected from 1 to {MAX_SAMPLES} samples per pixel, found {}",
                samples.get_ref()
            ),
        ));
    }
    let depth = &raw.render.max_depth;
    if *depth.get_ref() > MAX_DEPTH {
        return Err(err(
            depth.span(),
            format!(
                "render max_depth: expected at most {MAX_DEPTH}, found {}",
                depth.get_ref()
            ),
        ));
    }

    // lights
    let mut lights = Vec::with_capacity(raw.lights.len());
    for l in &raw.lights {
        let attenuation = match &l.attenuation {
            None => [1.0, 0.0, 0.0],
            Some(a) => {
                let v = a.get_ref().map(|x| real(x.0));
                if v.iter().all(|&x| x == 0.0) {
                    return Err(err(a.span(), "light attenuation: a0, a1, a2 cannot all be zero (the light would be infinitely bright)".into()));
                }
                v
            }
        };
        lights.push(Light {
            position: vec3_from(l.position.0),
            intensity: vec3_from(l.intensity.0),
            attenuation,
            shadows: l.shadows,
        });
    }

    // materials: index 0 is the default
    let mut materials = vec![Material::default()];
    let mut material_names = vec!["(default)".to_string()];
    let mut warnings = Vec::new();
    let mut by_name = HashMap::new();
    for (name, spanned) in &raw.materials {
        let m = spanned.get_ref();
        let d = Material::default();
        let material = Material {
            ambient: m.ambient.map_or(d.ambient, |c| vec3_from(c.0)),
            diffuse: m.diffuse.map_or(d.diffuse, |c| vec3_from(c.0)),
            specular: m.specular.map_or(d.specular, |c| vec3_from(c.0)),
            shininess: m.shininess.map_or(d.shininess, |x| real(x.0)),
            reflection: m.reflection.map_or(d.reflection, |x| real(x.0)),
            transmission: m.transmission.map_or(d.transmission, |x| real(x.0)),
            ior: m.ior.map_or(d.ior, |x| real(x.0)),
        };
        let over = material.over_unity_channels();
        if !over.is_empty() {
            let (line, col) = line_col(text, spanned.span().start);
            warnings.push(format!(
                "{file}:{line}:{col}: material `{name}`: ρa + ρd + ρs exceeds 1 in {} (the notes want it to be 1); rendering anyway",
                over.join(", ")
            ));
        }
        by_name.insert(name.clone(), materials.len());
        materials.push(material);
        material_names.push(name.clone());
    }

    // objects
    if raw.objects.is_empty() {
        return Err(err(
            text.len()..text.len(),
            "the scene has no objects: expected at least one [[objects]] table".into(),
        ));
    }
    let mut objects = Vec::with_capacity(raw.objects.len());
    let object_names = match parts {
        Parts::All => raw
            .objects
            .iter()
            .map(|o| o.get_ref().name.clone())
            .collect(),
        Parts::CameraAndImage => Vec::new(),
    };
    let placed = match parts {
        Parts::All => raw.objects.as_slice(),
        Parts::CameraAndImage => &[],
    };
    for o in placed {
        let mut object = build_object(o, &err)?;
        if let Some(name) = &o.get_ref().material {
            object.material = *by_name.get(name.get_ref()).ok_or_else(|| {
                let known: Vec<&str> = raw.materials.keys().map(String::as_str).collect();
                err(
                    name.span(),
                    if known.is_empty() {
                        format!(
                            "undefined material `{}`: the scene defines no [materials.NAME] tables",
                            name.get_ref()
                        )
                    } else {
                        format!(
                            "undefined material `{}`: expected one of {}",
                            name.get_ref(),
                            known.join(", ")
                        )
                    },
                )
            })?;
        }
        objects.push(object);
    }

    Ok(Scene {
        camera,
        width: *raw.image.width.get_ref(),
        height: *raw.image.height.get_ref(),
        background: vec3_from(raw.image.background.0),
        max_depth: *depth.get_ref(),
        samples: *samples.get_ref(),
        ambient: vec3_from(raw.ambient.intensity.0),
        lights,
        materials,
        material_names,
        objects,
        object_names,
        warnings,
    })
}

/// The steps that turn a generic shape whose base disc at z = −1 has radius `generic_radius`
/// (1 for the cylinder, 2 for the cone) into the object with the given base, top and radius.
fn axial_steps(base: Vec3, top: Vec3, radius: f64, generic_radius: f64) -> Option<Vec<Step>> {
    let axis = top - base;
    let h = axis.length();
    let dir = axis.try_normalize()?;
    let r = real(radius / generic_radius);
    Some(vec![
        Step::Scale(Vec3::new(r, r, h / 2.0)),
        rotation_from_z(dir),
        Step::Translate((base + top) / 2.0),
    ])
}

fn build_object(
    spanned: &Spanned<ObjectDesc>,
    err: &impl Fn(Range<usize>, String) -> Error,
) -> Result<Object, Error> {
    let o = spanned.get_ref();
    let span = spanned.span();
    let forms = [
        o.sphere.is_some(),
        o.plane.is_some(),
        o.cylinder.is_some(),
        o.cone.is_some(),
        o.box_.is_some(),
        o.polyhedron.is_some(),
        o.shape.is_some(),
    ];
    match forms.iter().filter(|&&f| f).count() {
        1 => {}
        0 => return Err(err(span, "object: expected one shape: sphere, plane, cylinder, cone, box, polyhedron = { … } or shape = \"…\"".into())),
        _ => return Err(err(span, "object: expected exactly one shape, found several (sphere, plane, cylinder, cone, box, polyhedron, shape)".into())),
    }

    let (shape, mut steps): (Shape, Vec<Step>) = if let Some(s) = &o.sphere {
        let r = real(s.radius.0);
        (
            Shape::Sphere,
            vec![
                Step::Scale(Vec3::splat(r)),
                Step::Translate(vec3_from(s.center.0)),
            ],
        )
    } else if let Some(p) = &o.plane {
        let n = vec3_from(p.normal.get_ref().0)
            .try_normalize()
            .ok_or_else(|| {
                err(
                    p.normal.span(),
                    "plane normal: expected a non-zero vector".into(),
                )
            })?;
        (
            Shape::Plane,
            vec![rotation_from_z(n), Step::Translate(vec3_from(p.point.0))],
        )
    } else if let Some(c) = &o.cylinder {
        (
            Shape::Cylinder,
            axial(c, "cylinder", "top", |a: &AxialDesc| a.top, err)?,
        )
    } else if let Some(c) = &o.cone {
        (
            Shape::Cone,
            axial(c, "cone", "apex", |a: &AxialDesc| a.apex, err)?,
        )
    } else if let Some(b) = &o.box_ {
        (Shape::Polyhedron(Polyhedron::cube()), box_steps(b, err)?)
    } else if let Some(p) = &o.polyhedron {
        (Shape::Polyhedron(polyhedron(p, err)?), vec![])
    } else if let Some(name) = &o.shape {
        let shape = match name.get_ref().as_str() {
            "sphere" => Shape::Sphere,
            "plane" => Shape::Plane,
            "cylinder" => Shape::Cylinder,
            "cone" => Shape::Cone,
            other => Shape::Polyhedron(Polyhedron::preset(other).ok_or_else(|| {
                err(name.span(), format!("unknown shape `{other}`: expected sphere, plane, cylinder, cone, cube, tetrahedron or octahedron"))
            })?),
        };
        (shape, vec![])
    } else {
        unreachable!("exactly one form was counted above")
    };

    for step in &o.transform {
        let s = match step.get_ref() {
            StepDesc::Scale(f) => Step::Scale(vec3_from(f.0)),
            StepDesc::RotateX(a) => Step::RotateX(real(a.0)),
            StepDesc::RotateY(a) => Step::RotateY(real(a.0)),
            StepDesc::RotateZ(a) => Step::RotateZ(real(a.0)),
            StepDesc::Rotate { axis, angle } => {
                let v = vec3_from(axis.get_ref().0);
                if v.try_normalize().is_none() {
                    return Err(err(
                        axis.span(),
                        "rotate axis: expected a non-zero vector".into(),
                    ));
                }
                Step::RotateAxis(v, real(angle.0))
            }
            StepDesc::Translate(t) => Step::Translate(vec3_from(t.0)),
        };
        if !s.is_invertible() {
            return Err(err(
                step.span(),
                format!(
                    "transform step cannot be inverted at {} precision (a scale of zero, or too small or too large to represent)",
                    crate::real::PRECISION
                ),
            ));
        }
        steps.push(s);
    }

    let placement = Placement::from_steps(&steps)
        .filter(|p| p.m().is_finite() && p.inv().is_finite())
        .ok_or_else(|| {
            err(
                span.clone(),
                format!(
                    "object placement is not invertible at {} precision",
                    crate::real::PRECISION
                ),
            )
        })?;
    Ok(Object::new(shape, placement))
}

fn axial(
    c: &Spanned<AxialDesc>,
    what: &str,
    end_key: &str,
    end: impl Fn(&AxialDesc) -> Option<super::format::Xyz>,
    err: &impl Fn(Range<usize>, String) -> Error,
) -> Result<Vec<Step>, Error> {
    let a = c.get_ref();
    let other = if end_key == "top" {
        a.apex.is_some()
    } else {
        a.top.is_some()
    };
    if other {
        let wrong = if end_key == "top" { "apex" } else { "top" };
        return Err(err(
            c.span(),
            format!(
                "{what}: unexpected key `{wrong}`, a {what} has `base`, `{end_key}` and `radius`"
            ),
        ));
    }
    let top = end(a).ok_or_else(|| err(c.span(), format!("{what}: missing `{end_key}`")))?;
    // the generic cone x² + y² = (1 − z)² is 2 wide at its base z = −1; the cylinder 1
    let generic_radius = if end_key == "apex" { 2.0 } else { 1.0 };
    axial_steps(
        vec3_from(a.base.0),
        vec3_from(top.0),
        a.radius.0,
        generic_radius,
    )
    .ok_or_else(|| {
        err(
            c.span(),
            format!("{what}: `base` and `{end_key}` are the same point, so it has no height"),
        )
    })
}

fn box_steps(
    b: &Spanned<BoxDesc>,
    err: &impl Fn(Range<usize>, String) -> Error,
) -> Result<Vec<Step>, Error> {
    let (lo, hi) = (vec3_from(b.get_ref().min.0), vec3_from(b.get_ref().max.0));
    if !lo.cmplt(hi).all() {
        return Err(err(
            b.span(),
            "box: expected min < max in x, y and z".into(),
        ));
    }
    Ok(vec![
        Step::Scale((hi - lo) / 2.0),
        Step::Translate((lo + hi) / 2.0),
    ])
}

fn polyhedron(
    p: &Spanned<PolyhedronDesc>,
    err: &impl Fn(Range<usize>, String) -> Error,
) -> Result<Polyhedron, Error> {
    let d = p.get_ref();
    match (&d.preset, &d.facets) {
        (Some(name), None) => Polyhedron::preset(name.get_ref()).ok_or_else(|| {
            err(
                name.span(),
                format!(
                    "unknown polyhedron preset `{}`: expected {}",
                    name.get_ref(),
                    Polyhedron::PRESETS.join(", ")
                ),
            )
        }),
        (None, Some(facets)) => {
            let count = facets.get_ref().len();
            if count > Polyhedron::MAX_FACETS {
                return Err(err(
                    facets.span(),
                    format!(
                        "polyhedron facets: at most {} facets, found {count}",
                        Polyhedron::MAX_FACETS
                    ),
                ));
            }
            if count < 4 {
                return Err(err(
                    facets.span(),
                    format!(
                        "polyhedron facets: a closed convex polyhedron needs at least 4 facets, found {}",
                        facets.get_ref().len()
                    ),
                ));
            }
            let list = facets
                .get_ref()
                .iter()
                .map(|f| {
                    let [nx, ny, nz, dd] = f.get_ref().map(|x| x.0);
                    Facet::new(vec3_from([nx, ny, nz]), real(dd)).ok_or_else(|| {
                        err(
                            f.span(),
                            "polyhedron facet: expected [nx, ny, nz, d] with a non-zero normal"
                                .into(),
                        )
                    })
                })
                .collect::<Result<Vec<_>, _>>()?;
            let poly = Polyhedron::new(list);
            poly.check()
                .map_err(|why| err(facets.span(), format!("polyhedron facets: {why}")))?;
            Ok(poly)
        }
        _ => Err(err(
            p.span(),
            "polyhedron: expected either `preset` or `facets`, not both or neither".into(),
        )),
    }
}
