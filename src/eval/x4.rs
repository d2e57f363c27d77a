//! The `x4` column of `eval`: each case is run in every lane of a packet
//! whose other lanes hold unrelated cases, and the four placements must
//! agree bit for bit.

use crate::case::{Case, match_case};
use crate::eval::Outcome;
use crate::primitive::packet;
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use crate::primitive::{in_every_lane, x4_lanes};

/// Neighbours for a camera pixel: two corners and the middle of the top
/// row, all inside the image.
fn camera_decoys([w, h]: [u32; 2]) -> [[u32; 2]; 3] {
    [[0, 0], [w - 1, h - 1], [w / 2, 0]]
}

/// Runs `case` through the x4 kernels in each of the four lanes
/// ([`in_every_lane`] for a primitive).
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
    let per_lane: [Outcome; 4] = match_case!(
        case,
        |r, p| in_every_lane(*r, *p, |c| x4_lanes(c).map(|h| Outcome::hit(&h))),
        |p, px| match p.build() {
            Ok(cam) => core::array::from_fn(|lane| {
                let pk = packet(*px, camera_decoys(p.res), lane);
                Outcome::Ray(cam.ray4(pk).to_rays()[lane])
            }),
            Err(e) => core::array::from_fn(|_| Outcome::Error(e.to_string())),
        },
    );
    if per_lane.iter().all(|o| o.same_bits(&per_lane[0])) {
        per_lane[0].clone()
    } else {
        Outcome::Error(format!("x4 lanes disagree: {per_lane:?}"))
    }
}

#[cfg(test)]
mod tests {
    #[test]
    fn the_camera_decoys_are_corners_and_the_top_middle() {
        assert_eq!(super::camera_decoys([5, 3]), [[0, 0], [4, 2], [2, 0]]);
    }
}
