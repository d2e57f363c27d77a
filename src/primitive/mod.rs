//! What the plane, the sphere and the quadric have in common, as one
//! trait: the harnesses (`eval`, the fuzz targets, the report) are written
//! once, generically, and each primitive's module says only what is its
//! own.
//!
//! ```
//! # #[cfg(feature = "sphere")] {
//! use rayoracle::{Ray, primitive::Primitive, sphere::{Sphere, SphereHit}};
//! use glam::Vec3;
//! fn nearest<P: Primitive>(ray: &Ray, p: &P) -> Option<f32> {
//!     use rayoracle::hit::Intersection;
//!     P::reference(ray, p).nearest(0.0, f32::INFINITY)
//! }
//! let r = Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z);
//! assert_eq!(nearest(&r, &Sphere::new(Vec3::ZERO, 1.0)), Some(4.0));
//! assert_eq!(Sphere::exact(&r, &Sphere::new(Vec3::ZERO, 1.0)), Ok(SphereHit::Two(4.0, 6.0)));
//! # }
//! ```

use crate::Ray;
use crate::case::{Case, Kind};
use crate::exact::NonFinite;
use crate::hit::Intersection;
use crate::ray4::Ray4;
use crate::stage::Stage;
use wide::f32x4;

/// A primitive a ray is intersected with: its answer type, its kernels, its
/// four-lane packet, the exact oracle, and its place in a [`Case`].
/// Implemented by [`Plane`](crate::plane::Plane),
/// [`Sphere`](crate::sphere::Sphere) and [`Quadric`](crate::quadric::Quadric),
/// each in its own module.
///
/// The kernels take `(ray, primitive)`, so `P::reference` is a
/// `fn(&Ray, &P) -> P::Hit` as the fuzz targets and gates take them.
///
/// Each kernel method is a function of its own, called through a pointer
/// or out of line, and starts as if no vector register held anything: a
/// call in a loop then never waits on the one before it. An instruction
/// such as `cvtss2sd` or `sqrtsd` writes the low lane of its destination
/// and keeps the rest, so it waits on whatever last wrote that register,
/// and a compiler breaks that false dependency only where it sees the
/// write in the same function. In `rayoracle report`, such a wait took
/// the sphere's plain-f64 variant from 7.7 to 24 ns a ray, and the
/// plane's reference from 2.7 to 3.9, in a build whose registers fell
/// that way.
pub trait Primitive: Copy + core::fmt::Debug + PartialEq + Sized + 'static {
    /// The case kind.
    const KIND: Kind;
    /// How many `f32` inputs the primitive has ([`Primitive::inputs`]).
    const INPUTS: usize;
    /// The answer over the whole line.
    type Hit: Intersection + Copy + core::fmt::Debug + PartialEq;
    /// Four primitives, one per lane.
    type Packet: Copy + core::fmt::Debug;
    /// Four answers, one per lane.
    type Hit4: Copy + core::fmt::Debug;

    /// The scalar reference: exact class, roots correctly rounded.
    fn reference(ray: &Ray, p: &Self) -> Self::Hit;
    /// [`Primitive::reference`] and the stage that decided it.
    fn staged(ray: &Ray, p: &Self) -> (Self::Hit, Stage);
    /// The textbook formulas in f32 (`*::textbook`).
    fn textbook(ray: &Ray, p: &Self) -> Self::Hit;
    /// The reference's formulation in plain f64 (`*::plain`).
    fn plain(ray: &Ray, p: &Self) -> Self::Hit;
    /// The exact oracle; an error for a non-finite input.
    fn exact(ray: &Ray, p: &Self) -> Result<Self::Hit, NonFinite>;

    /// Packs four primitives, lane `i` from `p[i]`.
    fn pack(p: [Self; 4]) -> Self::Packet;
    /// The four-lane kernel (`*::x4::intersect`).
    fn x4(ray: &Ray4, p: &Self::Packet) -> Self::Hit4;
    /// The batch entry point (`*::x4::intersect_packets`): packet `i` of
    /// `rays` against `p` into `out[i]`, eight lanes at a time where the
    /// CPU allows.
    fn batch(rays: &[Ray4], p: &Self::Packet, out: &mut [Self::Hit4]);
    /// The four answers of a packet.
    fn lanes(h: &Self::Hit4) -> [Self::Hit; 4];
    /// Per lane, whether there is a solution in `[t_min, t_max]` (a mask)
    /// and the nearest one (`+∞` where there is none).
    fn nearest4(h: &Self::Hit4, t_min: f32x4, t_max: f32x4) -> (f32x4, f32x4);

    /// Two sets of three cases for the other lanes of a packet when one
    /// case is run in each lane in turn ([`in_every_lane`]): between them
    /// every class the kind has and a NaN ray, so that a lane leaking into
    /// its neighbours shows, and so does a packet that answers every lane
    /// alike when one lane misses, is NaN or is degenerate.
    fn decoys() -> [[(Ray, Self); 3]; 2];

    /// The primitive's `f32` inputs, [`Primitive::INPUTS`] of them, in the
    /// order of its fields (the fuzz targets' byte order).
    fn inputs(&self) -> Vec<f32>;
    /// The primitive of [`Primitive::inputs`]; missing values are `0`.
    fn from_inputs(v: &[f32]) -> Self;

    /// The case of a ray and this primitive.
    fn case(ray: Ray, p: Self) -> Case;
    /// The ray and primitive of a case of this kind, `None` for another.
    fn of_case(case: &Case) -> Option<(Ray, Self)>;
}

/// Tells the compiler that every vector register is written here, with no
/// instruction, at the top of each [`Primitive`] kernel method.
///
/// An instruction such as `cvtss2sd` or `sqrtsd` writes the low lane of
/// its destination and keeps the rest, so it waits on whatever last wrote
/// that register. The compiler breaks such a false dependency (with an
/// `xorps`) only where it sees that write within the function; at a
/// function's entry it assumes every register it was not passed is old.
/// So a kernel called in a loop can wait, on its first conversion, for
/// the previous call's last division or square root. In `rayoracle
/// report`, without this, the sphere's plain-f64 variant takes 24 ns a
/// ray instead of 7.7 and the plane's reference 3.9 instead of 2.7, in a
/// build whose registers fall that way. With it, the compiler sees a write
/// just before each such instruction and breaks the dependency; the cost
/// is an `xorps`, which the CPU does not execute.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
#[inline(always)]
pub(crate) fn fresh_registers() {
    // SAFETY: the template is empty, so nothing runs; the operands only
    // declare the registers written (and so clobbered), which the compiler
    // honours by keeping nothing in them across this point.
    #[cfg(target_arch = "x86_64")]
    macro_rules! written {
        ($($r:tt),*) => {
            unsafe {
                core::arch::asm!("", $(out($r) _,)* options(nomem, nostack, preserves_flags))
            }
        };
    }
    #[cfg(target_arch = "x86_64")]
    written!(
        "xmm0", "xmm1", "xmm2", "xmm3", "xmm4", "xmm5", "xmm6", "xmm7", "xmm8", "xmm9", "xmm10",
        "xmm11", "xmm12", "xmm13", "xmm14", "xmm15"
    );
    #[cfg(all(target_arch = "x86_64", target_feature = "avx512f"))]
    written!(
        "xmm16", "xmm17", "xmm18", "xmm19", "xmm20", "xmm21", "xmm22", "xmm23", "xmm24", "xmm25",
        "xmm26", "xmm27", "xmm28", "xmm29", "xmm30", "xmm31"
    );
}

/// The kernel entry points of a [`Primitive`] impl ([`Primitive::reference`],
/// `staged`, `textbook`, `plain`, `exact`, `x4`, `batch`, `lanes`, `nearest4`), each
/// the function of the same role in the primitive's module: the modules
/// `reference`, `textbook`, `plain`, `exact` and `x4` must be in scope
/// where it is invoked.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
macro_rules! kernels {
    () => {
        fn reference(ray: &$crate::Ray, p: &Self) -> Self::Hit {
            $crate::primitive::fresh_registers();
            reference::intersect(ray, p)
        }
        fn staged(ray: &$crate::Ray, p: &Self) -> (Self::Hit, $crate::stage::Stage) {
            $crate::primitive::fresh_registers();
            reference::intersect_staged(ray, p)
        }
        fn textbook(ray: &$crate::Ray, p: &Self) -> Self::Hit {
            $crate::primitive::fresh_registers();
            textbook::intersect(ray, p)
        }
        fn plain(ray: &$crate::Ray, p: &Self) -> Self::Hit {
            $crate::primitive::fresh_registers();
            plain::intersect(ray, p)
        }
        fn exact(ray: &$crate::Ray, p: &Self) -> Result<Self::Hit, $crate::exact::NonFinite> {
            $crate::primitive::fresh_registers();
            exact::intersect(ray, p)
        }
        fn x4(ray: &$crate::ray4::Ray4, p: &Self::Packet) -> Self::Hit4 {
            $crate::primitive::fresh_registers();
            x4::intersect(ray, p)
        }
        fn batch(rays: &[$crate::ray4::Ray4], p: &Self::Packet, out: &mut [Self::Hit4]) {
            $crate::primitive::fresh_registers();
            x4::intersect_packets(rays, p, out)
        }
        fn lanes(h: &Self::Hit4) -> [Self::Hit; 4] {
            h.lanes()
        }
        fn nearest4(
            h: &Self::Hit4,
            t_min: wide::f32x4,
            t_max: wide::f32x4,
        ) -> (wide::f32x4, wide::f32x4) {
            h.nearest(t_min, t_max)
        }
    };
}
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
#[cfg(feature = "plane")]
mod plane;
#[cfg(feature = "quadric")]
mod quadric;
#[cfg(feature = "sphere")]
mod sphere;

/// `case` in lane `lane` of a packet and `decoys` in the other lanes, in
/// order.
///
/// ```
/// use rayoracle::primitive::packet;
/// assert_eq!(packet(9, [1, 2, 3], 0), [9, 1, 2, 3]);
/// assert_eq!(packet(9, [1, 2, 3], 2), [1, 2, 9, 3]);
/// assert_eq!(packet(9, [1, 2, 3], 3), [1, 2, 3, 9]);
/// ```
pub fn packet<T: Copy>(case: T, decoys: [T; 3], lane: usize) -> [T; 4] {
    let mut d = decoys.into_iter();
    core::array::from_fn(|i| {
        if i == lane {
            case
        } else {
            d.next().unwrap_or(case)
        }
    })
}

/// Runs a ray and a primitive in each lane of a packet in turn, its
/// [`Primitive::decoys`] in the other lanes (the first set when the case
/// is in lane 0 or 2, the second in lane 1 or 3, so that every class sits
/// beside the case in two placements): `run` takes the four cases and
/// answers for each lane, and the result holds the answer of the case's
/// own lane in each placement. A four-lane kernel that keeps its lanes
/// apart gives four equal answers; one that answers every lane alike when
/// any lane misses does not.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::{Ray, primitive::{in_every_lane, x4_lanes}, sphere::{Sphere, SphereHit}};
/// use glam::Vec3;
/// let (r, s) = (Ray::new(Vec3::new(0.0, 0.0, -3.0), Vec3::Z), Sphere::new(Vec3::ZERO, 1.0));
/// assert_eq!(in_every_lane(r, s, x4_lanes), [SphereHit::Two(2.0, 4.0); 4]);
/// // A kernel that answers from lane 0 only is caught.
/// let leaky = in_every_lane(r, s, |c| [x4_lanes(c)[0]; 4]);
/// assert_ne!(leaky[1], leaky[0]);
/// // So is a packet that gives up on every lane when one (non-NaN) lane
/// // misses.
/// let early_out = in_every_lane(r, s, |c| {
///     let h = x4_lanes(c);
///     let miss = (0..4).any(|i| h[i] == SphereHit::None && !c[i].0.origin.is_nan());
///     if miss { [SphereHit::None; 4] } else { h }
/// });
/// assert!(early_out.contains(&SphereHit::None) && early_out.contains(&SphereHit::Two(2.0, 4.0)));
/// # }
/// ```
pub fn in_every_lane<P: Primitive, A: Clone>(
    ray: Ray,
    p: P,
    run: impl Fn([(Ray, P); 4]) -> [A; 4],
) -> [A; 4] {
    let sets = P::decoys();
    core::array::from_fn(|lane| run(packet((ray, p), sets[lane % 2], lane))[lane].clone())
}

/// Runs the x4 kernel on four `(ray, primitive)` cases and unpacks the
/// answers.
///
/// ```
/// # #[cfg(feature = "plane")] {
/// use rayoracle::{Ray, plane::{Plane, PlaneHit}, primitive::x4_lanes};
/// use glam::Vec3;
/// let c = (Ray::new(Vec3::Y, -Vec3::Y), Plane::new(Vec3::ZERO, Vec3::Y));
/// assert_eq!(x4_lanes([c; 4]), [PlaneHit::Hit(1.0); 4]);
/// # }
/// ```
pub fn x4_lanes<P: Primitive>(cases: [(Ray, P); 4]) -> [P::Hit; 4] {
    P::lanes(&x4_packet(cases))
}

/// Runs the x4 kernel on four `(ray, primitive)` cases.
pub fn x4_packet<P: Primitive>(cases: [(Ray, P); 4]) -> P::Hit4 {
    P::x4(
        &Ray4::from_rays(cases.map(|c| c.0)),
        &P::pack(cases.map(|c| c.1)),
    )
}

/// The first `n` values of `v`, zero-padded: the fields of
/// [`Primitive::from_inputs`].
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
pub(crate) fn padded<const N: usize>(v: &[f32]) -> [f32; N] {
    core::array::from_fn(|i| v.get(i).copied().unwrap_or(0.0))
}

#[cfg(test)]
mod tests {
    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    use super::*;
    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    use crate::hit::{Class, same_bits};

    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    /// Every primitive's decoys give every class of the kind (`classes`),
    /// each set three different answers, one decoy a NaN ray; a kind's
    /// inputs read back to the same primitive; a case built from a pair
    /// gives that pair back and is of the kind.
    fn holds_for<P: Primitive>(classes: &[Class]) {
        let sets = P::decoys();
        for set in &sets {
            let h = set.map(|(r, p)| P::reference(&r, &p));
            assert!(
                !same_bits(&h[0], &h[1]) && !same_bits(&h[1], &h[2]) && !same_bits(&h[0], &h[2]),
                "{:?}: {h:?}",
                P::KIND
            );
        }
        let d: Vec<(Ray, P)> = sets.concat();
        let seen: Vec<Class> = d.iter().map(|(r, p)| P::reference(r, p).class()).collect();
        for c in classes {
            assert!(seen.contains(c), "{:?}: no {c:?} among {seen:?}", P::KIND);
        }
        assert!(d.iter().any(|(r, _)| r.origin.is_nan()));
        for (r, p) in d {
            assert_eq!(P::inputs(&p).len(), P::INPUTS);
            assert_eq!(P::from_inputs(&P::inputs(&p)), p);
            let c = P::case(r, p);
            assert_eq!(c.kind(), P::KIND);
            let (r2, p2) = P::of_case(&c).expect("a case of its own kind");
            let bits = |r: Ray| [r.origin, r.dir].map(|v| v.to_array().map(f32::to_bits));
            assert_eq!((bits(r2), p2), (bits(r), p));
            let h = x4_lanes([(r, p); 4]);
            assert!(h.iter().all(|x| same_bits(x, &P::reference(&r, &p))));
        }
        let camera = Case::Camera(
            crate::camera::CameraParams::new(
                glam::Vec3::ZERO,
                -glam::Vec3::Z,
                glam::Vec3::Y,
                1.0,
                [2, 2],
            ),
            [0, 0],
        );
        assert_eq!(P::of_case(&camera), None);
    }

    #[cfg(feature = "plane")]
    #[test]
    fn the_plane_is_a_primitive() {
        holds_for::<crate::plane::Plane>(&[Class::Hit, Class::Parallel, Class::InPlane]);
    }

    #[cfg(feature = "sphere")]
    #[test]
    fn the_sphere_is_a_primitive() {
        holds_for::<crate::sphere::Sphere>(&[Class::Two, Class::None, Class::Tangent]);
    }

    #[cfg(feature = "quadric")]
    #[test]
    fn the_quadric_is_a_primitive() {
        use crate::quadric::QuadricHit;
        holds_for::<crate::quadric::Quadric>(&[Class::None, Class::One, Class::Two, Class::All]);
        // Both kinds of one root: a linear root and a double root.
        let ones = crate::quadric::Quadric::decoys()
            .concat()
            .iter()
            .filter(|(r, q)| {
                matches!(
                    crate::quadric::reference::intersect(r, q),
                    QuadricHit::One(_)
                )
            })
            .count();
        assert_eq!(ones, 2);
    }

    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    #[test]
    fn padded_fills_missing_values_with_zero() {
        assert_eq!(padded::<3>(&[1.0]), [1.0, 0.0, 0.0]);
        assert_eq!(padded::<1>(&[1.0, 2.0]), [1.0]);
    }
}
