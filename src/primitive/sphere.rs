//! [`Primitive`] for the sphere: its kernels, packets, decoys and cases.

use super::Primitive;
use crate::Ray;
use crate::case::{Case, Kind};
use crate::sphere::{Sphere, SphereHit, exact, plain, reference, textbook, x4};
use glam::Vec3;

impl Primitive for Sphere {
    const KIND: Kind = Kind::Sphere;
    const INPUTS: usize = 4;
    type Hit = SphereHit;
    type Packet = x4::Sphere4;
    type Hit4 = x4::SphereHit4;

    kernels!();

    fn pack(s: [Sphere; 4]) -> x4::Sphere4 {
        x4::Sphere4::from_spheres(s)
    }
    /// A two-hit, a miss and a tangent; a two-hit from inside (one root
    /// behind), a NaN ray and a two-hit nearer by.
    fn decoys() -> [[(Ray, Sphere); 3]; 2] {
        let unit = Sphere::new(Vec3::ZERO, 1.0);
        let ray = |o: [f32; 3]| Ray::new(Vec3::from_array(o), Vec3::Z);
        [
            [
                (ray([0.0, 0.0, -5.0]), unit),
                (ray([0.0, 3.0, -5.0]), unit),
                (ray([0.0, 1.0, -5.0]), unit),
            ],
            [
                (ray([0.0, 0.0, 0.0]), unit),
                (ray([f32::NAN; 3]), unit),
                (ray([0.0, 0.0, -3.0]), unit),
            ],
        ]
    }
    fn inputs(&self) -> Vec<f32> {
        [self.center.to_array().as_slice(), &[self.radius]].concat()
    }
    fn from_inputs(v: &[f32]) -> Sphere {
        let [x, y, z, r] = super::padded(v);
        Sphere::new(Vec3::new(x, y, z), r)
    }
    fn case(ray: Ray, s: Sphere) -> Case {
        Case::Sphere(ray, s)
    }
    fn of_case(case: &Case) -> Option<(Ray, Sphere)> {
        match case {
            Case::Sphere(r, s) => Some((*r, *s)),
            _ => None,
        }
    }
}
