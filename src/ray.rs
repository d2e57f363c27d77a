//! A ray (or, for the whole-line results, a line) `o + t·d`.

use glam::Vec3;

/// A ray `origin + t · dir`. `dir` need not be normalised: every kernel in
/// this crate is correct for directions of any length, and `t` is in units
/// of `dir`.
///
/// ```
/// use rayoracle::Ray;
/// use glam::Vec3;
/// let r = Ray::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 2.0));
/// assert_eq!(r.at(1.5), Vec3::new(0.0, 0.0, 3.0));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Ray {
    /// The origin `o`.
    pub origin: Vec3,
    /// The direction `d`, any length.
    pub dir: Vec3,
}

impl Ray {
    /// A ray from `origin` along `dir`.
    ///
    /// ```
    /// use rayoracle::Ray;
    /// use glam::Vec3;
    /// assert_eq!(Ray::new(Vec3::X, Vec3::Y).dir, Vec3::Y);
    /// ```
    pub const fn new(origin: Vec3, dir: Vec3) -> Ray {
        Ray { origin, dir }
    }

    /// The point `origin + t · dir` (plain f32, for display and rendering).
    ///
    /// ```
    /// use rayoracle::Ray;
    /// use glam::Vec3;
    /// assert_eq!(Ray::new(Vec3::X, Vec3::Y).at(2.0), Vec3::new(1.0, 2.0, 0.0));
    /// ```
    pub fn at(&self, t: f32) -> Vec3 {
        self.origin + t * self.dir
    }
}
