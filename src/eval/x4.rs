//! The `x4` column of `eval`: each case is run in every lane of a packet
//! whose other lanes hold unrelated cases, and the four placements must
//! agree bit for bit.

use crate::case::Case;
use crate::eval::Outcome;
#[cfg(feature = "plane")]
use crate::plane::{self, Plane};
#[cfg(feature = "quadric")]
use crate::quadric::{self, Quadric};
#[cfg(feature = "sphere")]
use crate::sphere::{self, Sphere};
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use crate::{Ray, ray4::Ray4};
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use glam::Vec3;

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
const NAN3: Vec3 = Vec3::splat(f32::NAN);

/// Neighbours for a sphere case: a two-hit, a NaN, a tangent.
#[cfg(feature = "sphere")]
fn sphere_decoys() -> [(Ray, Sphere); 3] {
    let unit = Sphere::new(Vec3::ZERO, 1.0);
    [
        (Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z), unit),
        (Ray::new(NAN3, Vec3::Z), unit),
        (Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z), unit),
    ]
}

#[cfg(feature = "plane")]
fn plane_decoys() -> [(Ray, Plane); 3] {
    let ground = Plane::new(Vec3::ZERO, Vec3::Y);
    [
        (Ray::new(Vec3::Y, -Vec3::Y), ground),
        (Ray::new(NAN3, Vec3::X), ground),
        (Ray::new(Vec3::Y, Vec3::X), ground),
    ]
}

#[cfg(feature = "quadric")]
fn quadric_decoys() -> [(Ray, Quadric); 3] {
    let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
    [
        (Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X), cyl),
        (Ray::new(NAN3, Vec3::X), cyl),
        (Ray::new(Vec3::new(1.0, 0.0, 0.0), Vec3::Z), cyl),
    ]
}

/// Neighbours for a camera pixel: two corners and the middle of the top
/// row, all inside the image.
fn camera_decoys([w, h]: [u32; 2]) -> [[u32; 2]; 3] {
    [[0, 0], [w - 1, h - 1], [w / 2, 0]]
}

/// The case placed in lane `lane` and the decoys in the others.
fn packet<T: Copy>(case: T, decoys: [T; 3], lane: usize) -> [T; 4] {
    let mut d = decoys.into_iter();
    core::array::from_fn(|i| {
        if i == lane {
            case
        } else {
            d.next().unwrap_or(case)
        }
    })
}

/// Runs `case` through the x4 kernels in each of the four lanes.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::case::parse_line;
/// use rayoracle::eval::Outcome;
/// use rayoracle::hit::Roots;
/// let c = parse_line(r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#).unwrap();
/// assert_eq!(rayoracle::eval::x4::run(&c.case), Outcome::Hit { class: "two", roots: Roots::two(4.0, 6.0) });
/// # }
/// ```
pub fn run(case: &Case) -> Outcome {
    let per_lane: Vec<Outcome> = (0..4).map(|lane| in_lane(case, lane)).collect();
    if per_lane.iter().all(|o| o.same_bits(&per_lane[0])) {
        per_lane[0].clone()
    } else {
        Outcome::Error(format!("x4 lanes disagree: {per_lane:?}"))
    }
}

fn in_lane(case: &Case, lane: usize) -> Outcome {
    match case {
        #[cfg(feature = "plane")]
        Case::Plane(r, p) => {
            let pk = packet((*r, *p), plane_decoys(), lane);
            let h = plane::x4::intersect(
                &Ray4::from_rays(pk.map(|c| c.0)),
                &plane::x4::Plane4::from_planes(pk.map(|c| c.1)),
            );
            Outcome::hit(&h.lanes()[lane])
        }
        #[cfg(feature = "sphere")]
        Case::Sphere(r, s) => {
            let pk = packet((*r, *s), sphere_decoys(), lane);
            let h = sphere::x4::intersect(
                &Ray4::from_rays(pk.map(|c| c.0)),
                &sphere::x4::Sphere4::from_spheres(pk.map(|c| c.1)),
            );
            Outcome::hit(&h.lanes()[lane])
        }
        #[cfg(feature = "quadric")]
        Case::Quadric(r, q) => {
            let pk = packet((*r, *q), quadric_decoys(), lane);
            let h = quadric::x4::intersect(
                &Ray4::from_rays(pk.map(|c| c.0)),
                &quadric::x4::Quadric4::from_quadrics(pk.map(|c| c.1)),
            );
            Outcome::hit(&h.lanes()[lane])
        }
        Case::Camera(p, px) => match p.build() {
            Ok(cam) => {
                let pk = packet(*px, camera_decoys(p.res), lane);
                Outcome::Ray(cam.ray4(pk).to_rays()[lane])
            }
            Err(e) => Outcome::Error(e.to_string()),
        },
    }
}

#[cfg(test)]
mod tests {
    /// The decoys are what their docs say: an ordinary hit, a NaN ray and
    /// a boundary class, so a lane that leaks into its neighbours meets
    /// answers of every kind. (Any change to them weakens the column
    /// without failing a correct kernel, so it is pinned here.)
    #[cfg(feature = "sphere")]
    #[test]
    fn the_sphere_decoys_are_a_two_hit_a_nan_and_a_tangent() {
        use crate::sphere::{SphereHit, reference::intersect};
        let [two, nan, tangent] = super::sphere_decoys();
        assert_eq!(intersect(&two.0, &two.1), SphereHit::Two(4.0, 6.0));
        assert!(nan.0.origin.is_nan());
        assert_eq!(intersect(&tangent.0, &tangent.1), SphereHit::Tangent(5.0));
    }

    #[cfg(feature = "plane")]
    #[test]
    fn the_plane_decoys_are_a_hit_a_nan_and_a_parallel() {
        use crate::plane::{PlaneHit, reference::intersect};
        let [hit, nan, parallel] = super::plane_decoys();
        assert_eq!(intersect(&hit.0, &hit.1), PlaneHit::Hit(1.0));
        assert!(nan.0.origin.is_nan());
        assert_eq!(intersect(&parallel.0, &parallel.1), PlaneHit::Parallel);
    }

    #[test]
    fn the_camera_decoys_are_corners_and_the_top_middle() {
        assert_eq!(super::camera_decoys([5, 3]), [[0, 0], [4, 2], [2, 0]]);
    }

    #[cfg(feature = "quadric")]
    #[test]
    fn the_quadric_decoys_are_a_two_hit_a_nan_and_an_all() {
        use crate::quadric::{QuadricHit, reference::intersect};
        let [two, nan, all] = super::quadric_decoys();
        assert_eq!(intersect(&two.0, &two.1), QuadricHit::Two(4.0, 6.0));
        assert!(nan.0.origin.is_nan());
        assert_eq!(intersect(&all.0, &all.1), QuadricHit::All);
    }
}
