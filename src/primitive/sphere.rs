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
    /// A two-hit, a NaN ray and a tangent.
    fn decoys() -> [(Ray, Sphere); 3] {
        let unit = Sphere::new(Vec3::ZERO, 1.0);
        [
            (Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), unit),
            (Ray::new(Vec3::splat(f32::NAN), Vec3::Z), unit),
            (Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z), unit),
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
