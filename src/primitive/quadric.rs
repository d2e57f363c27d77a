//! [`Primitive`] for the quadric: its kernels, packets, decoys and cases.

use super::Primitive;
use crate::Ray;
use crate::case::{Case, Kind};
use crate::quadric::{Quadric, QuadricHit, exact, plain, reference, textbook, x4};
use glam::Vec3;

impl Primitive for Quadric {
    const KIND: Kind = Kind::Quadric;
    const INPUTS: usize = 10;
    type Hit = QuadricHit;
    type Packet = x4::Quadric4;
    type Hit4 = x4::QuadricHit4;

    kernels!();

    fn pack(q: [Quadric; 4]) -> x4::Quadric4 {
        x4::Quadric4::from_quadrics(q)
    }
    /// A two-hit, a miss (parallel to the cylinder's axis, outside) and a
    /// line on the cylinder; the linear root of a ray along a paraboloid's
    /// axis, a NaN ray and a tangent (a double root).
    fn decoys() -> [[(Ray, Quadric); 3]; 2] {
        let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let bowl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0]);
        let ray = |o: [f32; 3], d: Vec3| Ray::new(Vec3::from_array(o), d);
        [
            [
                (ray([-5.0, 0.0, 0.0], Vec3::X), cyl),
                (ray([5.0, 5.0, 0.0], Vec3::Z), cyl),
                (ray([1.0, 0.0, 0.0], Vec3::Z), cyl),
            ],
            [
                (ray([0.0, 0.0, -2.0], Vec3::Z), bowl),
                (ray([f32::NAN; 3], Vec3::X), cyl),
                (ray([-5.0, 1.0, 0.0], Vec3::X), cyl),
            ],
        ]
    }
    fn inputs(&self) -> Vec<f32> {
        self.coeffs.to_vec()
    }
    fn from_inputs(v: &[f32]) -> Quadric {
        Quadric::new(super::padded(v))
    }
    fn case(ray: Ray, q: Quadric) -> Case {
        Case::Quadric(ray, q)
    }
    fn of_case(case: &Case) -> Option<(Ray, Quadric)> {
        match case {
            Case::Quadric(r, q) => Some((*r, *q)),
            _ => None,
        }
    }
}
