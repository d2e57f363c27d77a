//! Ray–plane intersection.
//!
//! # The derivation, as corrected
//!
//! The plane through `a` with normal `n` is `(p − a)·n = 0`. Putting the ray
//! `p = o + t d` in gives `(o − a)·n + t (d·n) = 0`, so
//!
//! * `d·n ≠ 0`: one hit, `t = ((a − o)·n) / (d·n)`;
//! * `d·n = 0` and `(a − o)·n ≠ 0`: the ray is parallel and off the plane;
//! * `d·n = 0` and `(a − o)·n = 0`: the ray lies in the plane, every `t`.
//!
//! The usual derivation has these three cases right. One thing it does
//! not say, which the code handles: **a zero normal** makes every ray satisfy `0 = 0`; it
//! is classified [`PlaneHit::InPlane`] by the same rule (both dot products
//! are 0). `eval` reports it as such; scenes reject it.
//!
//! # Accuracy
//!
//! [`reference::intersect`](mod@reference) and [`x4`] return the exact class
//! and the root correctly rounded to `f32`, for every finite input: the
//! [filter](stages) evaluates both dot products in f64 with a proven error
//! bound and certifies what the bound decides. Its first pass
//! ([`stages::filter_relative`]) bounds the root relatively by a constant
//! wherever neither sum cancels by `2¹⁰` or more, so that nothing but the
//! certificate waits on the division; the second
//! ([`stages::filter_compensated`]) keeps that bound for a line near
//! parallel to the plane, and sees a `d·n` of exactly 0; the full bound
//! takes the rest. A root too close to a rounding boundary, or a line
//! whose sums defeat all three, goes on to the later [stages] and, last,
//! to the exact oracle ([`exact`]).

pub mod exact;
pub mod plain;
pub mod reference;
pub mod stages;
pub mod textbook;
pub mod x4;

use crate::hit::{Class, Intersection, Roots};
use glam::Vec3;

/// A plane through `point` with normal `normal` (any length).
///
/// ```
/// use rayoracle::plane::Plane;
/// use glam::Vec3;
/// let ground = Plane::new(Vec3::ZERO, Vec3::Y);
/// assert_eq!(ground.normal, Vec3::Y);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// A point `a` on the plane.
    pub point: Vec3,
    /// The normal `n`; need not be unit length.
    pub normal: Vec3,
}

impl Plane {
    /// The plane through `point` with normal `normal`.
    ///
    /// ```
    /// use rayoracle::plane::Plane;
    /// use glam::Vec3;
    /// assert_eq!(Plane::new(Vec3::ONE, Vec3::Z).point, Vec3::ONE);
    /// ```
    pub const fn new(point: Vec3, normal: Vec3) -> Plane {
        Plane { point, normal }
    }
}

/// The result over the whole line (`t ∈ ℝ`).
///
/// ```
/// use rayoracle::plane::PlaneHit;
/// use rayoracle::hit::Intersection;
/// assert_eq!(PlaneHit::Hit(-2.0).nearest(0.0, f32::INFINITY), None);
/// assert_eq!(PlaneHit::InPlane.nearest(0.5, 1.0), Some(0.5));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum PlaneHit {
    /// One intersection at `t`.
    Hit(f32),
    /// `d·n = 0`, the ray is off the plane: no intersection.
    Parallel,
    /// `d·n = 0` and the origin is on the plane: every `t`.
    InPlane,
}

impl Intersection for PlaneHit {
    fn class(&self) -> Class {
        match self {
            PlaneHit::Hit(_) => Class::Hit,
            PlaneHit::Parallel => Class::Parallel,
            PlaneHit::InPlane => Class::InPlane,
        }
    }
    fn roots(&self) -> Roots {
        match *self {
            PlaneHit::Hit(t) => Roots::one(t),
            _ => Roots::none(),
        }
    }
    fn is_everywhere(&self) -> bool {
        matches!(self, PlaneHit::InPlane)
    }
}
