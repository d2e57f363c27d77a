//! [`Primitive`] for the plane: its kernels, packets, decoys and cases.

use super::Primitive;
use crate::Ray;
use crate::case::{Case, Kind};
use crate::plane::{Plane, PlaneHit, exact, plain, reference, textbook, x4};
use glam::Vec3;

impl Primitive for Plane {
    const KIND: Kind = Kind::Plane;
    const INPUTS: usize = 6;
    type Hit = PlaneHit;
    type Packet = x4::Plane4;
    type Hit4 = x4::PlaneHit4;

    kernels!();

    fn pack(p: [Plane; 4]) -> x4::Plane4 {
        x4::Plane4::from_planes(p)
    }
    /// A hit, a parallel ray and a ray in the plane; a hit behind the
    /// origin, a NaN ray and another ray in the plane.
    fn decoys() -> [[(Ray, Plane); 3]; 2] {
        let ground = Plane::new(Vec3::ZERO, Vec3::Y);
        [
            [
                (Ray::new(Vec3::Y, -Vec3::Y), ground),
                (Ray::new(Vec3::Y, Vec3::X), ground),
                (Ray::new(Vec3::ZERO, Vec3::X), ground),
            ],
            [
                (Ray::new(Vec3::Y, Vec3::Y), ground),
                (Ray::new(Vec3::splat(f32::NAN), Vec3::X), ground),
                (Ray::new(Vec3::X, Vec3::Z), ground),
            ],
        ]
    }
    fn inputs(&self) -> Vec<f32> {
        [self.point.to_array(), self.normal.to_array()].concat()
    }
    fn from_inputs(v: &[f32]) -> Plane {
        let [a, b, c, d, e, f] = super::padded(v);
        Plane::new(Vec3::new(a, b, c), Vec3::new(d, e, f))
    }
    fn case(ray: Ray, p: Plane) -> Case {
        Case::Plane(ray, p)
    }
    fn of_case(case: &Case) -> Option<(Ray, Plane)> {
        match case {
            Case::Plane(r, p) => Some((*r, *p)),
            _ => None,
        }
    }
}
