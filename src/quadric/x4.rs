//! Four rays against four quadrics at once (`wide::f32x4`), bit-identical
//! to [`super::reference`](mod@super::reference): both run [`super::kernel::solve`], this one at
//! `f32x4`, classified with masks and selects.

use super::{Quadric, QuadricHit, kernel};
use crate::ray4::Ray4;
use wide::{f32x4, i32x4};

/// Four quadrics, structure-of-arrays: one `f32x4` per coefficient.
///
/// ```
/// use rayoracle::quadric::{Quadric, x4::Quadric4};
/// let q = Quadric4::splat(&Quadric::new([1.0; 10]));
/// assert_eq!(q.coeffs[9].to_array(), [1.0; 4]);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Quadric4 {
    /// `[A … J]`, lane `i` from quadric `i`.
    pub coeffs: [f32x4; 10],
}

impl Quadric4 {
    /// Packs four quadrics.
    ///
    /// ```
    /// use rayoracle::quadric::{Quadric, x4::Quadric4};
    /// let q = [0.0, 1.0, 2.0, 3.0].map(|j| Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, j]));
    /// assert_eq!(Quadric4::from_quadrics(q).coeffs[9].to_array(), [0.0, 1.0, 2.0, 3.0]);
    /// ```
    pub fn from_quadrics(q: [Quadric; 4]) -> Quadric4 {
        Quadric4 {
            coeffs: core::array::from_fn(|k| f32x4::from(q.map(|q| q.coeffs[k]))),
        }
    }
    /// The same quadric in every lane.
    ///
    /// ```
    /// use rayoracle::quadric::{Quadric, x4::Quadric4};
    /// assert_eq!(Quadric4::splat(&Quadric::new([2.0; 10])).coeffs[0].to_array(), [2.0; 4]);
    /// ```
    pub fn splat(q: &Quadric) -> Quadric4 {
        Quadric4::from_quadrics([*q; 4])
    }
}

/// Four results: a class per lane (0 none, 1 one, 2 two, 3 all) and the
/// roots (`t0 = t1` for class 1, NaN where there is none).
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, quadric::{Quadric, QuadricHit, x4}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let r = Ray4::splat(Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X));
/// assert_eq!(x4::intersect(&r, &x4::Quadric4::splat(&cyl)).lanes(), [QuadricHit::Two(4.0, 6.0); 4]);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct QuadricHit4 {
    /// 0 none, 1 one, 2 two, 3 all.
    pub class: i32x4,
    /// The smaller (or only) root.
    pub t0: f32x4,
    /// The larger (or only) root.
    pub t1: f32x4,
}

/// Intersects four lines with four quadrics, lane by lane.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, quadric::{Quadric, reference, x4}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let rays = [Vec3::X, Vec3::Z, Vec3::new(1.0, 1.0, 0.0), Vec3::Y]
///     .map(|d| Ray::new(Vec3::new(1.0, 0.0, 0.0), d));
/// let h = x4::intersect(&Ray4::from_rays(rays), &x4::Quadric4::splat(&cyl));
/// assert_eq!(h.lanes(), rays.map(|r| reference::intersect(&r, &cyl)));
/// ```
#[inline]
pub fn intersect(ray: &Ray4, q: &Quadric4) -> QuadricHit4 {
    let p = kernel::solve(&q.coeffs, ray.origin, ray.dir);
    let zero = f32x4::ZERO;
    let linear = p.alpha.simd_eq(zero);
    let lin_one = linear & p.beta.simd_ne(zero);
    let all = linear & !lin_one & p.gamma.simd_eq(zero);
    let quad = !linear & p.disc.simd_ge(zero);
    let double = quad & p.disc.simd_eq(zero);
    let two = quad & !double;
    let one = lin_one | double;
    let nan = f32x4::splat(f32::NAN);
    let single = lin_one.select(p.linear, p.double);
    let t0 = two.select(p.t0, one.select(single, nan));
    let t1 = two.select(p.t1, one.select(single, nan));
    let as_int = |m: f32x4| wide::bytemuck::cast::<f32x4, i32x4>(m) & i32x4::splat(1);
    let class = as_int(one) + (as_int(two) << 1) + as_int(all) * i32x4::splat(3);
    QuadricHit4 { class, t0, t1 }
}

impl QuadricHit4 {
    /// The four results as scalar values.
    ///
    /// ```
    /// use rayoracle::quadric::{QuadricHit, x4::QuadricHit4};
    /// use wide::{f32x4, i32x4};
    /// let h = QuadricHit4 { class: i32x4::from([0, 1, 2, 3]), t0: f32x4::splat(1.0), t1: f32x4::splat(2.0) };
    /// assert_eq!(h.lanes(), [QuadricHit::None, QuadricHit::One(1.0), QuadricHit::Two(1.0, 2.0), QuadricHit::All]);
    /// ```
    pub fn lanes(&self) -> [QuadricHit; 4] {
        let (c, t0, t1) = (
            self.class.to_array(),
            self.t0.to_array(),
            self.t1.to_array(),
        );
        [0, 1, 2, 3].map(|i| match c[i] {
            0 => QuadricHit::None,
            1 => QuadricHit::One(t0[i]),
            2 => QuadricHit::Two(t0[i], t1[i]),
            _ => QuadricHit::All,
        })
    }

    /// The nearest solution per lane in `[t_min, t_max]` and the mask of
    /// lanes that have one (`+∞` elsewhere); a line on the surface gives
    /// `t_min`. The rule of [`crate::hit::Intersection::nearest`].
    ///
    /// ```
    /// use rayoracle::quadric::x4::QuadricHit4;
    /// use wide::{f32x4, i32x4};
    /// let h = QuadricHit4 { class: i32x4::from([0, 1, 2, 3]), t0: f32x4::splat(-1.0), t1: f32x4::splat(2.0) };
    /// let (hit, t) = h.nearest(f32x4::ZERO, f32x4::splat(5.0));
    /// assert_eq!(hit.to_bitmask(), 0b1100);
    /// assert_eq!(t.to_array(), [f32::INFINITY, f32::INFINITY, 2.0, 0.0]);
    /// ```
    #[inline]
    pub fn nearest(&self, t_min: f32x4, t_max: f32x4) -> (f32x4, f32x4) {
        let is = |k: i32| -> f32x4 { wide::bytemuck::cast(self.class.simd_eq(i32x4::splat(k))) };
        let (one, two, all) = (is(1), is(2), is(3));
        let within = |t: f32x4| t.simd_ge(t_min) & t.simd_le(t_max);
        let ok0 = (one | two) & within(self.t0);
        let ok1 = two & within(self.t1);
        let ok_all = all & t_min.simd_le(t_max);
        let inf = f32x4::splat(f32::INFINITY);
        let t = ok0.select(self.t0, ok1.select(self.t1, ok_all.select(t_min, inf)));
        (ok0 | ok1 | ok_all, t)
    }
}
