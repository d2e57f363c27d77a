//! A scene compiled into what its renders need, and nothing else.

use super::Channels;
use crate::camera::Camera;
use crate::scene::{DepthRange, Scene, SceneError};

#[cfg(feature = "plane")]
use crate::plane::{Plane, x4::Plane4};
#[cfg(feature = "quadric")]
use crate::quadric::{Quadric, x4::Quadric4};
#[cfg(feature = "sphere")]
use crate::sphere::{Sphere, x4::Sphere4};

/// A scene compiled for rendering: the camera built once, each primitive
/// kind the scene uses held in its own list (scalar and packed four-wide),
/// and the channels to produce.
///
/// The renderers loop over each kind's list only, so a sphere-only scene
/// runs no plane or quadric code per ray, and without the `normal` channel
/// no normal arithmetic runs at all (the unit tests count kernel calls to
/// prove both). A kind that cargo features compiled out does not exist in
/// the plan, and compiling a scene that uses it is an error.
///
/// Objects are numbered planes first, then spheres, then quadrics, each in
/// file order; on equal `t` the lower number wins.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::render::{Channels, Plan};
/// use rayoracle::scene::Scene;
/// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]},
///     "spheres": [{"id": 1, "center": [0, 0, -3], "radius": 1}]}"#).unwrap();
/// let plan = Plan::compile(&s, Channels::DEPTH).unwrap();
/// assert_eq!(plan.kinds(), vec!["sphere"]);
/// # }
/// ```
#[derive(Clone, Debug)]
pub struct Plan {
    pub(super) camera: Camera,
    pub(super) res: [u32; 2],
    pub(super) channels: Channels,
    pub(super) depth: DepthRange,
    /// Scene id of each object, by object number.
    pub(super) ids: Vec<u32>,
    /// The un-specialised path: every object through one `match` per ray
    /// packet, every channel (see [`Plan::everything`]).
    pub(super) generic: Option<Vec<Object>>,
    #[cfg(feature = "plane")]
    pub(super) planes: Vec<Plane>,
    #[cfg(feature = "plane")]
    pub(super) planes4: Vec<Plane4>,
    #[cfg(feature = "sphere")]
    pub(super) spheres: Vec<Sphere>,
    #[cfg(feature = "sphere")]
    pub(super) spheres4: Vec<Sphere4>,
    #[cfg(feature = "quadric")]
    pub(super) quadrics: Vec<Quadric>,
    #[cfg(feature = "quadric")]
    pub(super) quadrics4: Vec<Quadric4>,
}

/// One object of any kind, for the un-specialised path.
#[derive(Clone, Copy, Debug)]
pub(super) enum Object {
    #[cfg(feature = "plane")]
    Plane(Plane, Plane4),
    #[cfg(feature = "sphere")]
    Sphere(Sphere, Sphere4),
    #[cfg(feature = "quadric")]
    Quadric(Quadric, Quadric4),
}

/// The error for a scene that uses a kind this build does not have.
#[allow(dead_code)] // Unused when every kind is compiled in.
fn compiled_out(list: &str, n: usize, feature: &str) -> SceneError {
    SceneError::field(
        list,
        format!(
            "the scene has {n} {list}, but this build has no {feature} kernel \
             (cargo feature \"{feature}\" is off)"
        ),
    )
}

impl Plan {
    /// Compiles `scene` for the given channels.
    ///
    /// ```
    /// use rayoracle::render::{Channels, Plan};
    /// use rayoracle::scene::Scene;
    /// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
    ///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#).unwrap();
    /// assert!(Plan::compile(&s, Channels::ALL).unwrap().kinds().is_empty());
    /// ```
    pub fn compile(scene: &Scene, channels: Channels) -> Result<Plan, SceneError> {
        let camera = scene
            .camera
            .build()
            .map_err(|e| SceneError::field(format!("camera.{}", e.field()), e.to_string()))?;
        crate::scene::check_resolution(scene.camera.res)
            .map_err(|(f, m)| SceneError::field(format!("camera.{f}"), m))?;
        let ids = scene.object_ids().into_iter().map(|(_, id)| id).collect();
        #[cfg(not(feature = "plane"))]
        if !scene.planes.is_empty() {
            return Err(compiled_out("planes", scene.planes.len(), "plane"));
        }
        #[cfg(not(feature = "sphere"))]
        if !scene.spheres.is_empty() {
            return Err(compiled_out("spheres", scene.spheres.len(), "sphere"));
        }
        #[cfg(not(feature = "quadric"))]
        if !scene.quadrics.is_empty() {
            return Err(compiled_out("quadrics", scene.quadrics.len(), "quadric"));
        }
        #[cfg(feature = "plane")]
        let planes: Vec<Plane> = scene
            .planes
            .iter()
            .map(|p| Plane::new(p.point, p.normal))
            .collect();
        #[cfg(feature = "sphere")]
        let spheres: Vec<Sphere> = scene
            .spheres
            .iter()
            .map(|s| Sphere::new(s.center, s.radius))
            .collect();
        #[cfg(feature = "quadric")]
        let quadrics: Vec<Quadric> = scene
            .quadrics
            .iter()
            .map(|q| Quadric::new(q.coeffs))
            .collect();
        Ok(Plan {
            camera,
            res: scene.camera.res,
            channels,
            depth: scene.depth,
            ids,
            generic: None,
            #[cfg(feature = "plane")]
            planes4: planes.iter().map(Plane4::splat).collect(),
            #[cfg(feature = "plane")]
            planes,
            #[cfg(feature = "sphere")]
            spheres4: spheres.iter().map(Sphere4::splat).collect(),
            #[cfg(feature = "sphere")]
            spheres,
            #[cfg(feature = "quadric")]
            quadrics4: quadrics.iter().map(Quadric4::splat).collect(),
            #[cfg(feature = "quadric")]
            quadrics,
        })
    }

    /// The un-specialised plan, for measuring what specialising saves: every
    /// channel, and every object through one `match` on its kind per ray
    /// packet, as a renderer that handles all kinds in one list does. It
    /// renders the same frames as [`Plan::compile`] with [`Channels::ALL`].
    ///
    /// ```
    /// # #[cfg(feature = "sphere")] {
    /// use rayoracle::render::{Channels, Path, Plan, render};
    /// use rayoracle::scene::Scene;
    /// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
    ///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]},
    ///     "spheres": [{"id": 1, "center": [0, 0, -3], "radius": 1}]}"#).unwrap();
    /// let a = render(&Plan::everything(&s).unwrap(), Path::X4);
    /// let b = render(&Plan::compile(&s, Channels::ALL).unwrap(), Path::X4);
    /// assert!(a.same_bits(&b));
    /// # }
    /// ```
    pub fn everything(scene: &Scene) -> Result<Plan, SceneError> {
        let mut plan = Plan::compile(scene, Channels::ALL)?;
        let mut objects = Vec::new();
        #[cfg(feature = "plane")]
        objects.extend(
            plan.planes
                .iter()
                .zip(&plan.planes4)
                .map(|(p, p4)| Object::Plane(*p, *p4)),
        );
        #[cfg(feature = "sphere")]
        objects.extend(
            plan.spheres
                .iter()
                .zip(&plan.spheres4)
                .map(|(s, s4)| Object::Sphere(*s, *s4)),
        );
        #[cfg(feature = "quadric")]
        objects.extend(
            plan.quadrics
                .iter()
                .zip(&plan.quadrics4)
                .map(|(q, q4)| Object::Quadric(*q, *q4)),
        );
        plan.generic = Some(objects);
        Ok(plan)
    }

    /// The primitive kinds the plan runs, in object order.
    ///
    /// ```
    /// # #[cfg(feature = "plane")] {
    /// use rayoracle::render::{Channels, Plan};
    /// use rayoracle::scene::Scene;
    /// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
    ///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]},
    ///     "planes": [{"id": 1, "point": [0, -1, 0], "normal": [0, 1, 0]}]}"#).unwrap();
    /// assert_eq!(Plan::compile(&s, Channels::DEPTH).unwrap().kinds(), vec!["plane"]);
    /// # }
    /// ```
    pub fn kinds(&self) -> Vec<&'static str> {
        #[allow(unused_mut)] // Empty when every kind is compiled out.
        let mut kinds = Vec::new();
        #[cfg(feature = "plane")]
        if !self.planes.is_empty() {
            kinds.push("plane");
        }
        #[cfg(feature = "sphere")]
        if !self.spheres.is_empty() {
            kinds.push("sphere");
        }
        #[cfg(feature = "quadric")]
        if !self.quadrics.is_empty() {
            kinds.push("quadric");
        }
        kinds
    }

    /// The channels the plan produces.
    ///
    /// ```
    /// use rayoracle::render::{Channels, Plan};
    /// use rayoracle::scene::Scene;
    /// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
    ///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#).unwrap();
    /// assert_eq!(Plan::compile(&s, Channels::DEPTH).unwrap().channels(), Channels::DEPTH);
    /// ```
    pub fn channels(&self) -> Channels {
        self.channels
    }

    /// `[width, height]`.
    ///
    /// ```
    /// use rayoracle::render::{Channels, Plan};
    /// use rayoracle::scene::Scene;
    /// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
    ///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#).unwrap();
    /// assert_eq!(Plan::compile(&s, Channels::DEPTH).unwrap().size(), [4, 3]);
    /// ```
    pub fn size(&self) -> [u32; 2] {
        self.res
    }

    /// How many objects the scene has, of every kind.
    ///
    /// ```
    /// use rayoracle::render::{Channels, Plan};
    /// use rayoracle::scene::Scene;
    /// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
    ///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#).unwrap();
    /// assert_eq!(Plan::compile(&s, Channels::DEPTH).unwrap().objects(), 0);
    /// ```
    pub fn objects(&self) -> usize {
        self.ids.len()
    }

    /// The first object number of each kind: `[planes, spheres, quadrics]`.
    pub(super) fn bases(&self) -> [u32; 3] {
        #[allow(unused_mut)]
        let mut n = [0u32; 3];
        #[cfg(feature = "plane")]
        {
            n[0] = self.planes.len() as u32;
        }
        #[cfg(feature = "sphere")]
        {
            n[1] = self.spheres.len() as u32;
        }
        [0, n[0], n[0] + n[1]]
    }
}
