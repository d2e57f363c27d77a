//! Four rays in structure-of-arrays form, running a slice of rays
//! through a four-lane kernel, and what the four-lane results of every
//! kind share: the [`class`] codes and [`nearest4`].

use crate::Ray;
use glam::Vec3;
use wide::{f32x4, i32x4};

/// The class codes of the x4 results (`PlaneHit4`, `SphereHit4`,
/// `QuadricHit4`), one meaning for every kind: which of the lane's `t0`,
/// `t1` are points of the line on the surface. Lanes without a root hold
/// NaN there.
pub mod class {
    /// No point: a miss, no real root, a line parallel to a plane and off
    /// it.
    pub const NONE: i32 = 0;
    /// One root, in `t0` (and `t1`): a plane's hit, a sphere's tangent, a
    /// quadric's single or double root.
    pub const ONE: i32 = 1;
    /// Two roots, `t0 ≤ t1`.
    pub const TWO: i32 = 2;
    /// Every `t`: a line in a plane or on a quadric.
    pub const ALL: i32 = 3;
}

/// The nearest solution per lane in `[t_min, t_max]`, for results in the
/// [`class`] codes, and the mask of lanes that have one: `t0` before `t1`,
/// and `t_min` for a lane of [`class::ALL`]; `+∞` where there is none. The
/// rule of [`crate::hit::Intersection::nearest`]. `TWO` and `ALL` say
/// whether the kind has those classes at all (the sphere has no `ALL`, the
/// plane no `TWO`), which spares the others' tests.
///
/// ```
/// use rayoracle::ray4::nearest4;
/// use wide::{f32x4, i32x4};
/// let (t0, t1) = (f32x4::splat(-1.0), f32x4::splat(2.0));
/// let (lo, hi) = (f32x4::ZERO, f32x4::splat(5.0));
/// let (hit, t) = nearest4::<true, true>(i32x4::from([0, 1, 2, 3]), t0, t1, lo, hi);
/// assert_eq!(hit.to_bitmask(), 0b1100);
/// assert_eq!(t.to_array(), [f32::INFINITY, f32::INFINITY, 2.0, 0.0]);
/// // Without ALL, class 3 is not looked for.
/// let (hit, _) = nearest4::<true, false>(i32x4::from([0, 1, 2, 3]), t0, t1, lo, hi);
/// assert_eq!(hit.to_bitmask(), 0b0100);
/// ```
#[inline(always)]
pub fn nearest4<const TWO: bool, const ALL: bool>(
    class: i32x4,
    t0: f32x4,
    t1: f32x4,
    t_min: f32x4,
    t_max: f32x4,
) -> (f32x4, f32x4) {
    let m = |x: i32x4| -> f32x4 { wide::bytemuck::cast(x) };
    let is = |k: i32| m(class.simd_eq(i32x4::splat(k)));
    let within = |t: f32x4| t.simd_ge(t_min) & t.simd_le(t_max);
    let (two, all) = (
        if TWO { is(class::TWO) } else { f32x4::ZERO },
        is(class::ALL),
    );
    let any = match (TWO, ALL) {
        (false, _) => is(class::ONE),
        // No ALL: ONE and TWO are every class above NONE.
        (true, false) => m(class.simd_gt(i32x4::splat(class::NONE))),
        (true, true) => is(class::ONE) | two,
    };
    let ok0 = any & within(t0);
    let inf = f32x4::splat(f32::INFINITY);
    let (ok1, t) = if TWO {
        let ok1 = two & within(t1);
        (ok1, ok1.select(t1, inf))
    } else {
        (f32x4::ZERO, inf)
    };
    let (ok_all, t) = if ALL {
        let ok_all = all & t_min.simd_le(t_max);
        (ok_all, ok_all.select(t_min, t))
    } else {
        (f32x4::ZERO, t)
    };
    (ok0 | ok1 | ok_all, ok0.select(t0, t))
}

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

    /// The origins' components, then the directions'.
    #[cfg(any(feature = "plane", feature = "quadric"))]
    #[inline(always)]
    pub(crate) fn components(&self) -> [f32x4; 6] {
        let ([o0, o1, o2], [d0, d1, d2]) = (self.origin, self.dir);
        [o0, o1, o2, d0, d1, d2]
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
