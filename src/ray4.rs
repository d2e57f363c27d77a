//! Four rays in structure-of-arrays form, and running a slice of rays
//! through a four-lane kernel.

use crate::Ray;
use glam::Vec3;
use wide::f32x4;

/// Four rays, structure-of-arrays: lane `i` of every component is ray `i`.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4};
/// use glam::Vec3;
/// let rays = [0, 1, 2, 3].map(|i| Ray::new(Vec3::splat(i as f32), Vec3::Z));
/// let r4 = Ray4::from_rays(rays);
/// assert_eq!(r4.origin[0].to_array(), [0.0, 1.0, 2.0, 3.0]);
/// assert_eq!(r4.to_rays(), rays);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Ray4 {
    /// Origin x, y, z.
    pub origin: [f32x4; 3],
    /// Direction x, y, z.
    pub dir: [f32x4; 3],
}

/// Lane-wise gather of a 3-vector field.
pub(crate) fn gather3(v: [Vec3; 4]) -> [f32x4; 3] {
    [0, 1, 2].map(|c| f32x4::from([v[0][c], v[1][c], v[2][c], v[3][c]]))
}

/// Lane-wise scatter of a 3-vector field.
pub(crate) fn scatter3(v: [f32x4; 3]) -> [Vec3; 4] {
    let [x, y, z] = v.map(f32x4::to_array);
    [0, 1, 2, 3].map(|i| Vec3::new(x[i], y[i], z[i]))
}

impl Ray4 {
    /// Packs four rays.
    ///
    /// ```
    /// use rayoracle::{Ray, ray4::Ray4};
    /// use glam::Vec3;
    /// let r = Ray::new(Vec3::ONE, Vec3::X);
    /// assert_eq!(Ray4::from_rays([r; 4]).dir[0].to_array(), [1.0; 4]);
    /// ```
    pub fn from_rays(rays: [Ray; 4]) -> Ray4 {
        Ray4 {
            origin: gather3(rays.map(|r| r.origin)),
            dir: gather3(rays.map(|r| r.dir)),
        }
    }

    /// The same ray in all four lanes.
    ///
    /// ```
    /// use rayoracle::{Ray, ray4::Ray4};
    /// use glam::Vec3;
    /// let r = Ray::new(Vec3::ONE, Vec3::X);
    /// assert_eq!(Ray4::splat(r).to_rays(), [r; 4]);
    /// ```
    pub fn splat(ray: Ray) -> Ray4 {
        Ray4::from_rays([ray; 4])
    }

    /// Unpacks the four rays.
    ///
    /// ```
    /// use rayoracle::{Ray, ray4::Ray4};
    /// use glam::Vec3;
    /// let r = Ray::new(Vec3::ONE, Vec3::X);
    /// assert_eq!(Ray4::splat(r).to_rays()[3], r);
    /// ```
    pub fn to_rays(&self) -> [Ray; 4] {
        let (o, d) = (scatter3(self.origin), scatter3(self.dir));
        [0, 1, 2, 3].map(|i| Ray::new(o[i], d[i]))
    }
}

/// Runs `kernel` over `items` four at a time and appends one result per item
/// to `out`, in order.
///
/// The last packet of a slice whose length is not a multiple of four is
/// filled by repeating its last real item, so the kernel never sees
/// uninitialised or out-of-bounds data, and the results of the filler lanes
/// are dropped.
///
/// ```
/// use rayoracle::ray4::for_each4;
/// let mut out = Vec::new();
/// for_each4(&[1, 2, 3, 4, 5, 6], |x| x.map(|v| v * 10), &mut out);
/// assert_eq!(out, [10, 20, 30, 40, 50, 60]);
/// ```
pub fn for_each4<T: Copy, R>(
    items: &[T],
    mut kernel: impl FnMut([T; 4]) -> [R; 4],
    out: &mut Vec<R>,
) {
    let mut chunks = items.chunks_exact(4);
    for c in &mut chunks {
        out.extend(kernel([c[0], c[1], c[2], c[3]]));
    }
    let tail = chunks.remainder();
    if let Some(&last) = tail.last() {
        let packet = [0, 1, 2, 3].map(|i| *tail.get(i).unwrap_or(&last));
        out.extend(kernel(packet).into_iter().take(tail.len()));
    }
}
