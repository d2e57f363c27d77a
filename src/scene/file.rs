//! The JSON scene file: serde types, validated as they are read so that
//! every error carries serde_json's line and column and the field path.

use super::{DepthRange, Scene, ScenePlane, SceneQuadric, SceneSphere};
use crate::camera::{CameraError, CameraParams};
use glam::Vec3;
use serde::Deserialize;
use serde_json::value::RawValue;

/// Marks a validation message that names a sub-field, so the path can be
/// extended (`camera` + `up` → `camera.up`) once serde reports it.
pub(super) const SUBFIELD: char = '\u{1}';

fn at(field: &str, message: impl core::fmt::Display) -> String {
    format!("{SUBFIELD}{field}{SUBFIELD}{message}")
}

/// A number, parsed straight from its decimal text to the nearest f32 (no
/// double rounding through f64), or `"inf"`, `"nan"`, `"0x…"` bits, as in
/// `eval` lines ([`crate::case::parse_f32`]).
#[derive(Clone, Copy)]
struct F32(f32);

impl<'de> Deserialize<'de> for F32 {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<F32, D::Error> {
        let raw = <&RawValue>::deserialize(d)?;
        crate::case::parse_f32("", raw)
            .map(F32)
            .map_err(|e| serde::de::Error::custom(e.message))
    }
}

fn vec3(v: [F32; 3]) -> Vec3 {
    Vec3::new(v[0].0, v[1].0, v[2].0)
}

fn finite(field: &str, v: Vec3) -> Result<Vec3, String> {
    if v.is_finite() {
        Ok(v)
    } else {
        Err(at(field, format!("{v} has a NaN or infinite component")))
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
pub(super) struct SceneFile {
    #[serde(default)]
    name: String,
    #[serde(default)]
    description: String,
    camera: Camera,
    #[serde(default)]
    depth: Option<Depth>,
    #[serde(default)]
    planes: Vec<PlaneItem>,
    #[serde(default)]
    spheres: Vec<SphereItem>,
    #[serde(default)]
    quadrics: Vec<QuadricItem>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCamera {
    position: [F32; 3],
    dir: [F32; 3],
    up: [F32; 3],
    angle: F32,
    res: [u32; 2],
}

#[derive(Deserialize)]
#[serde(try_from = "RawCamera")]
struct Camera(CameraParams);

impl TryFrom<RawCamera> for Camera {
    type Error = String;
    fn try_from(c: RawCamera) -> Result<Camera, String> {
        let position = finite("position", vec3(c.position))?;
        let p = CameraParams::new(position, vec3(c.dir), vec3(c.up), c.angle.0, c.res);
        super::check_resolution(c.res).map_err(|(field, m)| at(field, m))?;
        match p.build() {
            Ok(_) => Ok(Camera(p)),
            Err(e @ CameraError::BasisOverflow) => Err(at(e.field(), e)),
            Err(e) => {
                // The camera's own message starts with the field name.
                let text = e.to_string();
                let msg = text
                    .strip_prefix(&format!("{}: ", e.field()))
                    .unwrap_or(&text);
                Err(at(e.field(), msg))
            }
        }
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDepth {
    near: F32,
    far: F32,
}

#[derive(Deserialize)]
#[serde(try_from = "RawDepth")]
struct Depth(DepthRange);

impl TryFrom<RawDepth> for Depth {
    type Error = String;
    fn try_from(d: RawDepth) -> Result<Depth, String> {
        let (near, far) = (d.near.0, d.far.0);
        if !(near > 0.0 && near.is_finite()) {
            return Err(at(
                "near",
                format!("{near} is not a positive finite number"),
            ));
        }
        if !(far > near && far.is_finite()) {
            return Err(at(
                "far",
                format!("{far} is not a finite number above near ({near})"),
            ));
        }
        Ok(Depth(DepthRange { near, far }))
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPlane {
    id: u32,
    point: [F32; 3],
    normal: [F32; 3],
}

#[derive(Deserialize)]
#[serde(try_from = "RawPlane")]
struct PlaneItem(ScenePlane);

impl TryFrom<RawPlane> for PlaneItem {
    type Error = String;
    fn try_from(p: RawPlane) -> Result<PlaneItem, String> {
        let normal = finite("normal", vec3(p.normal))?;
        if normal == Vec3::ZERO {
            return Err(at("normal", "is zero, so every ray would lie in the plane"));
        }
        Ok(PlaneItem(ScenePlane {
            id: id(p.id)?,
            point: finite("point", vec3(p.point))?,
            normal,
        }))
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSphere {
    id: u32,
    center: [F32; 3],
    radius: F32,
}

#[derive(Deserialize)]
#[serde(try_from = "RawSphere")]
struct SphereItem(SceneSphere);

impl TryFrom<RawSphere> for SphereItem {
    type Error = String;
    fn try_from(s: RawSphere) -> Result<SphereItem, String> {
        let radius = s.radius.0;
        if !(radius > 0.0 && radius.is_finite()) {
            return Err(at(
                "radius",
                format!("{radius} is not a positive finite number"),
            ));
        }
        Ok(SphereItem(SceneSphere {
            id: id(s.id)?,
            center: finite("center", vec3(s.center))?,
            radius,
        }))
    }
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawQuadric {
    id: u32,
    coeffs: [F32; 10],
}

#[derive(Deserialize)]
#[serde(try_from = "RawQuadric")]
struct QuadricItem(SceneQuadric);

impl TryFrom<RawQuadric> for QuadricItem {
    type Error = String;
    fn try_from(q: RawQuadric) -> Result<QuadricItem, String> {
        let coeffs = q.coeffs.map(|c| c.0);
        if let Some(i) = coeffs.iter().position(|c| !c.is_finite()) {
            return Err(at(
                &format!("coeffs[{i}]"),
                format!("{} is not finite", coeffs[i]),
            ));
        }
        if coeffs.iter().all(|&c| c == 0.0) {
            return Err(at(
                "coeffs",
                "are all zero, so every point is on the surface",
            ));
        }
        Ok(QuadricItem(SceneQuadric {
            id: id(q.id)?,
            coeffs,
        }))
    }
}

fn id(id: u32) -> Result<u32, String> {
    if id == 0 {
        Err(at("id", "0 is reserved for the background; ids start at 1"))
    } else {
        Ok(id)
    }
}

impl SceneFile {
    /// The scene, after the checks that span several objects (unique ids).
    pub(super) fn into_scene(self) -> Result<Scene, (String, String)> {
        let scene = Scene {
            name: self.name,
            description: self.description,
            camera: self.camera.0,
            depth: self.depth.map_or(DepthRange::DEFAULT, |d| d.0),
            planes: self.planes.into_iter().map(|p| p.0).collect(),
            spheres: self.spheres.into_iter().map(|s| s.0).collect(),
            quadrics: self.quadrics.into_iter().map(|q| q.0).collect(),
        };
        let mut seen = std::collections::BTreeMap::new();
        for (field, id) in scene.object_ids() {
            if let Some(first) = seen.insert(id, field.clone()) {
                return Err((
                    format!("{field}.id"),
                    format!("{id} is already the id of {first}"),
                ));
            }
        }
        Ok(scene)
    }
}
