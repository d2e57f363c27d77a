//! The `x4` column of `eval`: each case is run in every lane of a packet
//! whose other lanes hold unrelated cases, and the four placements must
//! agree bit for bit.

use crate::case::{Case, match_case};
use crate::eval::Outcome;
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use crate::{
    Ray,
    primitive::{Primitive, x4_lanes},
};

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
/// use rayoracle::hit::{Class, Roots};
/// let c = parse_line(r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#).unwrap();
/// assert_eq!(rayoracle::eval::x4::run(&c.case), Outcome::Hit { class: Class::Two, roots: Roots::two(4.0, 6.0) });
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
    match_case!(
        case,
        |r, p| primitive_in_lane(*r, *p, lane),
        |p, px| match p.build() {
            Ok(cam) => {
                let pk = packet(*px, camera_decoys(p.res), lane);
                Outcome::Ray(cam.ray4(pk).to_rays()[lane])
            }
            Err(e) => Outcome::Error(e.to_string()),
        },
    )
}

/// A ray and a primitive in lane `lane` of a packet, its
/// [`Primitive::decoys`] in the others.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn primitive_in_lane<P: Primitive>(ray: Ray, p: P, lane: usize) -> Outcome {
    let pk = packet((ray, p), P::decoys(), lane);
    Outcome::hit(&x4_lanes(pk)[lane])
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_camera_decoys_are_corners_and_the_top_middle() {
        assert_eq!(super::camera_decoys([5, 3]), [[0, 0], [4, 2], [2, 0]]);
    }

    /// The case is in its lane and the decoys fill the others in order.
    #[test]
    fn a_packet_holds_the_case_in_its_lane() {
        assert_eq!(super::packet(9, [1, 2, 3], 0), [9, 1, 2, 3]);
        assert_eq!(super::packet(9, [1, 2, 3], 2), [1, 2, 9, 3]);
        assert_eq!(super::packet(9, [1, 2, 3], 3), [1, 2, 3, 9]);
    }
}
