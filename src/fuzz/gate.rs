//! The gate inside a user's `fuzz_target!`: bytes in, a case out, judged.
//!
//! ```no_run
//! // fuzz/fuzz_targets/my_sphere.rs
//! # fn my_kernel(r: &rayoracle::Ray, s: &rayoracle::sphere::Sphere) -> rayoracle::check::gate::Answer { unimplemented!() }
//! use rayoracle::check::gate::{Declared, Gate, Semantics};
//! use rayoracle::fuzz::gate as fuzz;
//! // libfuzzer_sys::fuzz_target!(|data: &[u8]| {
//! let data: &[u8] = &[];
//! fuzz::sphere(data, &Gate::new(Declared::f32(Semantics::NearestPositive)), &my_kernel);
//! // });
//! ```
//!
//! Floats are decoded as rayoracle's own fuzz targets decode them
//! ([`FuzzF32`]: raw bits, special values, exact `m·2^e` of
//! any magnitude, small integers), so NaN, subnormals and exact tangents are
//! all reachable. A case a declared precondition skips is not run (with
//! `unit-dirs`, the kernel gets the direction normalised). A failure
//! panics with the case as an `eval` line.

use super::FuzzF32;
use crate::Ray;
use crate::case::Case;
use crate::check::gate::{Gate, PlaneKernel, QuadricKernel, SphereKernel};
use crate::plane::Plane;
use crate::quadric::Quadric;
use crate::sphere::Sphere;
use arbitrary::{Arbitrary, Unstructured};
use glam::Vec3;

fn f(u: &mut Unstructured<'_>) -> Option<f32> {
    FuzzF32::arbitrary(u).ok().map(|x| x.0)
}
fn v(u: &mut Unstructured<'_>) -> Option<Vec3> {
    Some(Vec3::new(f(u)?, f(u)?, f(u)?))
}

/// Decodes a sphere case from `data` and judges `kernel` on it; panics
/// with the failure (and its `eval` line) if the answer is not acceptable.
///
/// ```
/// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
/// use rayoracle::fuzz::gate as fuzz;
/// let good = |r: &rayoracle::Ray, s: &rayoracle::sphere::Sphere| Answer::roots(rayoracle::sphere::reference::intersect(r, s));
/// fuzz::sphere(&[7; 64], &Gate::new(Declared::faithful(Semantics::WholeLine)), &good);
/// ```
pub fn sphere(data: &[u8], gate: &Gate, kernel: &impl SphereKernel) {
    let mut u = Unstructured::new(data);
    let (Some(o), Some(d), Some(c), Some(r)) = (v(&mut u), v(&mut u), v(&mut u), f(&mut u)) else {
        return;
    };
    let Ok(Case::Sphere(ray, s)) = gate
        .declared
        .prepare(Case::Sphere(Ray::new(o, d), Sphere::new(c, r)))
    else {
        return; // a declared precondition skips it
    };
    if let Err(e) = gate.judge_sphere(&ray, &s, kernel.intersect(&ray, &s)) {
        panic!("{e}");
    }
}

/// As [`sphere`], for a plane kernel.
///
/// ```
/// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
/// use rayoracle::fuzz::gate as fuzz;
/// let good = |r: &rayoracle::Ray, p: &rayoracle::plane::Plane| Answer::roots(rayoracle::plane::reference::intersect(r, p));
/// fuzz::plane(&[3; 64], &Gate::new(Declared::faithful(Semantics::WholeLine)), &good);
/// ```
pub fn plane(data: &[u8], gate: &Gate, kernel: &impl PlaneKernel) {
    let mut u = Unstructured::new(data);
    let (Some(o), Some(d), Some(a), Some(n)) = (v(&mut u), v(&mut u), v(&mut u), v(&mut u)) else {
        return;
    };
    let Ok(Case::Plane(ray, p)) = gate
        .declared
        .prepare(Case::Plane(Ray::new(o, d), Plane::new(a, n)))
    else {
        return;
    };
    if let Err(e) = gate.judge_plane(&ray, &p, kernel.intersect(&ray, &p)) {
        panic!("{e}");
    }
}

/// As [`sphere`], for a quadric kernel.
///
/// ```
/// use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
/// use rayoracle::fuzz::gate as fuzz;
/// let good = |r: &rayoracle::Ray, q: &rayoracle::quadric::Quadric| Answer::roots(rayoracle::quadric::reference::intersect(r, q));
/// fuzz::quadric(&[5; 80], &Gate::new(Declared::faithful(Semantics::WholeLine)), &good);
/// ```
pub fn quadric(data: &[u8], gate: &Gate, kernel: &impl QuadricKernel) {
    let mut u = Unstructured::new(data);
    let (Some(o), Some(d)) = (v(&mut u), v(&mut u)) else {
        return;
    };
    let mut k = [0f32; 10];
    for x in &mut k {
        let Some(c) = f(&mut u) else { return };
        *x = c;
    }
    let Ok(Case::Quadric(ray, q)) = gate
        .declared
        .prepare(Case::Quadric(Ray::new(o, d), Quadric::new(k)))
    else {
        return;
    };
    if let Err(e) = gate.judge_quadric(&ray, &q, kernel.intersect(&ray, &q)) {
        panic!("{e}");
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::check::gate::{Answer, Declared, Semantics};
    use crate::fuzz::encode_f32;
    use std::cell::RefCell;

    /// The fuzz helpers decode the case the way rayoracle's own targets encode
    /// it, hand it to the kernel, and panic when the gate fails the answer.
    #[test]
    fn the_fuzz_helpers_judge_the_decoded_case() {
        let whole_line = Gate::new(Declared::f32(Semantics::WholeLine));
        let mut bytes = Vec::new();
        for x in [0.0, 0.0, -5.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0] {
            encode_f32(x, &mut bytes);
        }
        let seen = RefCell::new(None);
        let right = |r: &Ray, s: &Sphere| {
            *seen.borrow_mut() = Some((*r, *s));
            Answer::Roots(vec![4.0, 6.0])
        };
        super::sphere(&bytes, &whole_line, &right);
        assert_eq!(
            seen.into_inner().unwrap(),
            (
                Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z),
                Sphere::new(Vec3::ZERO, 1.0)
            )
        );
        let wrong = |_: &Ray, _: &Sphere| Answer::Roots(vec![4.0, 7.0]);
        assert!(std::panic::catch_unwind(|| super::sphere(&bytes, &whole_line, &wrong)).is_err());

        // A plane: origin (0, 1, 0) down onto y = 0 at t = 1.
        let mut bytes = Vec::new();
        for x in [0.0, 1.0, 0.0, 0.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0] {
            encode_f32(x, &mut bytes);
        }
        let right = |_: &Ray, _: &Plane| Answer::Roots(vec![1.0]);
        super::plane(&bytes, &whole_line, &right);
        let wrong = |_: &Ray, _: &Plane| Answer::Roots(vec![2.0]);
        assert!(std::panic::catch_unwind(|| super::plane(&bytes, &whole_line, &wrong)).is_err());

        // A quadric: the unit sphere from z = −5 along z.
        let mut bytes = Vec::new();
        for x in [
            0.0, 0.0, -5.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0,
        ] {
            encode_f32(x, &mut bytes);
        }
        let right = |_: &Ray, _: &Quadric| Answer::Roots(vec![4.0, 6.0]);
        super::quadric(&bytes, &whole_line, &right);
        let wrong = |_: &Ray, _: &Quadric| Answer::Roots(vec![4.0]);
        assert!(std::panic::catch_unwind(|| super::quadric(&bytes, &whole_line, &wrong)).is_err());
    }

    /// A declared precondition applies here as in the gate: with unit
    /// directions the kernel sees the direction normalised, and a subnormal
    /// input is skipped, not judged.
    #[test]
    fn the_fuzz_helpers_keep_the_preconditions() {
        let careful = Gate::new(
            Declared::f32(Semantics::WholeLine)
                .unit_dirs()
                .no_subnormals(),
        );
        let mut bytes = Vec::new();
        for x in [0.0, 0.0, -5.0, 0.0, 0.0, 4.0, 0.0, 0.0, 0.0, 1.0] {
            encode_f32(x, &mut bytes);
        }
        let seen = RefCell::new(None);
        let right = |r: &Ray, _: &Sphere| {
            *seen.borrow_mut() = Some(r.dir);
            Answer::Roots(vec![4.0, 6.0])
        };
        super::sphere(&bytes, &careful, &right);
        assert_eq!(seen.into_inner(), Some(Vec3::Z));
        let mut bytes = Vec::new();
        for x in [0.0, 0.0, -5.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1e-40] {
            encode_f32(x, &mut bytes);
        }
        let never = |_: &Ray, _: &Sphere| -> Answer { panic!("skipped cases are not run") };
        super::sphere(&bytes, &careful, &never);
    }
}
