//! Rendering scenes: the nearest hit per pixel, through the reference or
//! the x4 kernels, into depth, normal and object-id channels.
//!
//! # What a frame holds
//!
//! For pixel `(X, Y)` the camera's ray ([`crate::camera`]) is intersected
//! with every object of the [`Plan`]; the hit is the smallest root `t ≥ 0`
//! (a closed interval, as [`crate::hit::Intersection::nearest`]; a ray lying
//! in a plane or on a quadric hits at `t = 0`). Objects are tried planes,
//! spheres, quadrics, each in file order, and a later object wins only when
//! strictly nearer. `t` is in units of the ray direction, which the camera
//! does not normalise (`|dir|` is the focal distance).
//!
//! Both paths run the same arithmetic lane by lane, so [`Path::Reference`]
//! and [`Path::X4`] give frames with the same bits; the tests check every
//! fixture scene.
//!
//! # Channels
//!
//! With the `png` feature, `Frame::depth_png`, `normal_png` and `id_png`
//! encode them:
//!
//! * **depth**, 16-bit grey: 0 where nothing is hit. A hit at `t` maps by
//!   the bits of `t` read as an integer, which is a piecewise-linear
//!   `log₂ t` (exponent + significand; exact integer arithmetic, so the same
//!   on every machine): with `L(x)` the bit pattern of `x`,
//!   `grey = 65535 − round(65534 · clamp((L(t) − L(near)) / (L(far) − L(near)), 0, 1))`.
//!   Near is white (65535), `far` and beyond the darkest grey (1). `near`
//!   and `far` come from the scene ([`crate::scene::DepthRange`]); each
//!   octave of depth gets the same number of grey levels, so a tiny sphere
//!   at 10⁷ and the ground at 10⁻³ are both visible.
//! * **normal**, RGB 8-bit: the unit normal facing the ray
//!   ([`normal`](mod@normal)), `round(127.5 · (n + 1))` per component; black
//!   where nothing is hit, mid-grey `(128, 128, 128)` where the normal is
//!   undefined (zero gradient).
//! * **id**, RGB 8-bit: black where nothing is hit; object id `k` gets
//!   [`PALETTE`]`[(k − 1) mod 12]`.
//!
//! With the `png` feature, `Frame::pngs` and `write_pngs` encode the
//! channels with the `png` crate at fixed settings (the same frame gives
//! the same bytes), and `diff` draws review images of two frames.

mod channels;
#[cfg(feature = "png")]
pub mod diff;
mod encode;
pub mod normal;
// A camera-only build (no kind compiled in) renders empty frames.
#[cfg_attr(
    not(any(feature = "plane", feature = "sphere", feature = "quadric")),
    allow(unused, dead_code)
)]
mod plan;
// A camera-only build (no kind compiled in) renders empty frames.
#[cfg_attr(
    not(any(feature = "plane", feature = "sphere", feature = "quadric")),
    allow(unused, dead_code)
)]
mod reference;
// A camera-only build (no kind compiled in) renders empty frames.
#[cfg_attr(
    not(any(feature = "plane", feature = "sphere", feature = "quadric")),
    allow(unused, dead_code)
)]
mod x4;

pub use channels::Channels;
#[cfg(feature = "png")]
pub use encode::write_pngs;
pub use encode::{PALETTE, depth_grey};
pub use plan::Plan;

/// Which implementation renders.
///
/// ```
/// use rayoracle::render::Path;
/// assert_eq!(Path::parse("x4"), Ok(Path::X4));
/// assert!(Path::parse("gpu").is_err());
/// ```
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Path {
    /// One pixel at a time through the scalar reference kernels.
    Reference,
    /// Four pixels at a time through the x4 kernels.
    X4,
}

impl Path {
    /// Parses `reference` or `x4`.
    ///
    /// ```
    /// use rayoracle::render::Path;
    /// assert_eq!(Path::parse("reference"), Ok(Path::Reference));
    /// ```
    pub fn parse(text: &str) -> Result<Path, String> {
        match text {
            "reference" => Ok(Path::Reference),
            "x4" => Ok(Path::X4),
            other => Err(format!(
                "unknown path \"{other}\"; expected reference or x4"
            )),
        }
    }

    /// The name `parse` accepts.
    ///
    /// ```
    /// use rayoracle::render::Path;
    /// assert_eq!(Path::X4.name(), "x4");
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            Path::Reference => "reference",
            Path::X4 => "x4",
        }
    }
}

/// A rendered frame: per pixel (row-major, row 0 at the top) the nearest
/// hit's `t` (`+∞` for none), and, when the plan asked for them, the hit
/// object's id (0 for none) and its unit normal.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::render::{Channels, Path, Plan, render};
/// use rayoracle::scene::Scene;
/// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
///     "up": [0, 1, 0], "angle": 0.5, "res": [5, 3]},
///     "spheres": [{"id": 4, "center": [0, 0, -3], "radius": 1}]}"#).unwrap();
/// let f = render(&Plan::compile(&s, Channels::ALL).unwrap(), Path::Reference);
/// assert_eq!(f.depth[7], 2.0); // the centre pixel looks straight at the sphere
/// assert_eq!(f.id[7], 4);
/// assert_eq!(f.normal[7], [0.0, 0.0, 1.0]);
/// # }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Width in pixels.
    pub width: u32,
    /// Height in pixels.
    pub height: u32,
    /// The depth range the depth channel maps.
    pub range: crate::scene::DepthRange,
    /// `t` of the nearest hit, `+∞` for none.
    pub depth: Vec<f32>,
    /// Object id of the nearest hit, 0 for none; empty without the id channel.
    pub id: Vec<u32>,
    /// Unit normal facing the ray; empty without the normal channel.
    pub normal: Vec<[f32; 3]>,
}

impl Frame {
    /// Whether two frames hold the same bits (`+0 ≠ −0`; any NaN equals any
    /// NaN, though renders produce none).
    ///
    /// ```
    /// use rayoracle::render::Frame;
    /// use rayoracle::scene::DepthRange;
    /// let a = Frame { width: 1, height: 1, range: DepthRange::DEFAULT, depth: vec![0.0], id: vec![], normal: vec![] };
    /// let mut b = a.clone();
    /// assert!(a.same_bits(&b));
    /// b.depth[0] = -0.0;
    /// assert!(!a.same_bits(&b));
    /// ```
    pub fn same_bits(&self, other: &Frame) -> bool {
        let bits = |x: &f32| if x.is_nan() { u32::MAX } else { x.to_bits() };
        let same = |a: &[f32], b: &[f32]| a.iter().map(bits).eq(b.iter().map(bits));
        (self.width, self.height, self.range) == (other.width, other.height, other.range)
            && same(&self.depth, &other.depth)
            && self.id == other.id
            && self.normal.len() == other.normal.len()
            && self
                .normal
                .iter()
                .zip(&other.normal)
                .all(|(a, b)| same(a, b))
    }

    /// The first pixel `(X, Y)` where two frames differ, if any.
    ///
    /// ```
    /// use rayoracle::render::Frame;
    /// use rayoracle::scene::DepthRange;
    /// let a = Frame { width: 2, height: 1, range: DepthRange::DEFAULT, depth: vec![0.0, 1.0], id: vec![], normal: vec![] };
    /// let mut b = a.clone();
    /// b.depth[1] = 2.0;
    /// assert_eq!(a.first_difference(&b), Some((1, 0)));
    /// assert_eq!(a.first_difference(&a), None);
    /// // Row-major: index 5 of a 3×3 frame is (2, 1), and 8 is (2, 2).
    /// let c = Frame { width: 3, height: 3, depth: vec![0.0; 9], ..a };
    /// let mut d = c.clone();
    /// d.depth[8] = -0.0;
    /// assert_eq!(c.first_difference(&d), Some((2, 2)));
    /// d.depth[5] = 1.0;
    /// assert_eq!(c.first_difference(&d), Some((2, 1)));
    /// ```
    pub fn first_difference(&self, other: &Frame) -> Option<(u32, u32)> {
        let n = (self.width * self.height) as usize;
        let at = |f: &Frame, i: usize| {
            let d = f.depth.get(i).map(|x| x.to_bits());
            let id = f.id.get(i).copied();
            let nm = f.normal.get(i).map(|v| v.map(f32::to_bits));
            (d, id, nm)
        };
        (0..n)
            .find(|&i| at(self, i) != at(other, i))
            .map(|i| (i as u32 % self.width, i as u32 / self.width))
    }
}

/// Renders a plan through one path.
///
/// ```
/// # #[cfg(feature = "plane")] {
/// use rayoracle::render::{Channels, Path, Plan, render};
/// use rayoracle::scene::Scene;
/// let s = Scene::parse(r#"{"camera": {"position": [0, 1, 0], "dir": [0, 0, -1],
///     "up": [0, 1, 0], "angle": 1, "res": [7, 5]},
///     "planes": [{"id": 1, "point": [0, 0, 0], "normal": [0, 1, 0]}]}"#).unwrap();
/// let plan = Plan::compile(&s, Channels::ALL).unwrap();
/// assert!(render(&plan, Path::Reference).same_bits(&render(&plan, Path::X4)));
/// # }
/// ```
pub fn render(plan: &Plan, path: Path) -> Frame {
    render_with_progress(plan, path, &mut || {})
}

/// [`render`], calling `on_row` after each row (for a progress bar).
///
/// ```
/// use rayoracle::render::{Channels, Path, Plan, render_with_progress};
/// use rayoracle::scene::Scene;
/// let s = Scene::parse(r#"{"camera": {"position": [0, 0, 0], "dir": [0, 0, -1],
///     "up": [0, 1, 0], "angle": 1, "res": [4, 3]}}"#).unwrap();
/// let mut rows = 0;
/// render_with_progress(&Plan::compile(&s, Channels::DEPTH).unwrap(), Path::X4, &mut || rows += 1);
/// assert_eq!(rows, 3);
/// ```
pub fn render_with_progress(plan: &Plan, path: Path, on_row: &mut dyn FnMut()) -> Frame {
    let [w, h] = plan.res;
    let n = w as usize * h as usize;
    let ch = plan.channels;
    let mut frame = Frame {
        width: w,
        height: h,
        range: plan.depth,
        depth: vec![f32::INFINITY; n],
        id: if ch.id { vec![0; n] } else { Vec::new() },
        normal: if ch.normal {
            vec![[0.0; 3]; n]
        } else {
            Vec::new()
        },
    };
    match path {
        Path::Reference => reference::render_rows(plan, &mut frame, 0..h, on_row),
        Path::X4 => x4::render_rows(plan, &mut frame, 0..h, on_row),
    }
    frame
}

/// Kernel-call counters, compiled only into the crate's own unit tests, so
/// they can prove what a plan leaves out. Elsewhere `bump` is empty.
pub(crate) mod counters {
    // Which kinds count depends on the cargo features.
    #![allow(dead_code)]

    pub const PLANE: usize = 0;
    pub const SPHERE: usize = 1;
    pub const QUADRIC: usize = 2;
    pub const NORMAL: usize = 3;

    #[cfg(test)]
    thread_local! {
        static CALLS: core::cell::Cell<[u64; 4]> = const { core::cell::Cell::new([0; 4]) };
    }

    /// Counts one call of kind `k` (a no-op outside unit tests).
    #[inline(always)]
    pub fn bump(_k: usize) {
        #[cfg(test)]
        CALLS.with(|c| {
            let mut v = c.get();
            v[_k] += 1;
            c.set(v);
        });
    }

    /// The counts so far on this thread, and resets them.
    #[cfg(test)]
    pub fn take() -> [u64; 4] {
        CALLS.with(|c| c.replace([0; 4]))
    }
}

#[cfg(test)]
mod tests;
