//! Four rays against four planes at once. The filter runs on four f64
//! lanes; both paths return the exact answer, correctly rounded, so they
//! agree bit for bit with [`super::reference`](mod@super::reference) by construction.

use super::{Plane, PlaneHit, reference, stages};
#[cfg(target_arch = "x86_64")]
use crate::num::avx::{Avx2, Avx4};
use crate::num::certify::{
    any_subnormal4, certify_end, certify_relative, flush_prone4, packet_results_stand,
    results_stand, subnormals_work, widen_lanes,
};
use crate::num::real::{F64x4, Real, Real4, Real8};
use crate::ray4::class::{ALL, NONE, ONE};
use crate::ray4::{Ray4, gather3, scatter3};
use wide::bytemuck::cast;
use wide::{f32x4, i32x4};

/// Four planes, structure-of-arrays, held as given and as f64 lanes:
/// widened once when packed (exactly, with integer arithmetic, so that
/// denormals-are-zero at that moment changes nothing), so that each
/// packet's call loads them as they are.
///
/// ```
/// use rayoracle::plane::{Plane, x4::Plane4};
/// use glam::Vec3;
/// assert_eq!(Plane4::splat(&Plane::new(Vec3::ZERO, Vec3::Y)).normal()[1].to_array(), [1.0; 4]);
/// ```
#[derive(Clone, Copy, Debug)]
#[repr(align(32))]
pub struct Plane4 {
    /// A point on each plane, per axis, in f64.
    point: [[f64; 4]; 3],
    /// Each plane's normal, per axis, in f64.
    normal: [[f64; 4]; 3],
    /// The same as given.
    given: [[f32x4; 3]; 2],
}

impl Plane4 {
    /// Packs four planes.
    ///
    /// ```
    /// use rayoracle::plane::{Plane, x4::Plane4};
    /// use glam::Vec3;
    /// let p = [0.0, 1.0, 2.0, 3.0].map(|y| Plane::new(Vec3::new(0.0, y, 0.0), Vec3::Y));
    /// assert_eq!(Plane4::from_planes(p).point()[1].to_array(), [0.0, 1.0, 2.0, 3.0]);
    /// ```
    pub fn from_planes(p: [Plane; 4]) -> Plane4 {
        let (point, normal) = (gather3(p.map(|p| p.point)), gather3(p.map(|p| p.normal)));
        Plane4 {
            point: point.map(widen_lanes),
            normal: normal.map(widen_lanes),
            given: [point, normal],
        }
    }
    /// A point on each plane, per axis.
    ///
    /// ```
    /// use rayoracle::plane::{Plane, x4::Plane4};
    /// use glam::Vec3;
    /// assert_eq!(Plane4::splat(&Plane::new(Vec3::Z, Vec3::Y)).point()[2].to_array(), [1.0; 4]);
    /// ```
    pub fn point(&self) -> [f32x4; 3] {
        self.given[0]
    }
    /// Each plane's normal, per axis.
    ///
    /// ```
    /// use rayoracle::plane::{Plane, x4::Plane4};
    /// use glam::Vec3;
    /// assert_eq!(Plane4::splat(&Plane::new(Vec3::Z, Vec3::X)).normal()[0].to_array(), [1.0; 4]);
    /// ```
    pub fn normal(&self) -> [f32x4; 3] {
        self.given[1]
    }
    /// The same plane in every lane.
    ///
    /// ```
    /// use rayoracle::plane::{Plane, x4::Plane4};
    /// use glam::Vec3;
    /// assert_eq!(Plane4::splat(&Plane::new(Vec3::X, Vec3::Y)).point()[0].to_array(), [1.0; 4]);
    /// ```
    pub fn splat(p: &Plane) -> Plane4 {
        Plane4::from_planes([*p; 4])
    }
}

/// Four results: a class per lane in the shared
/// [codes](crate::ray4::class) (`ONE` a hit, `NONE` parallel, `ALL` in the
/// plane) and the root (NaN where there is none).
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, plane::{Plane, PlaneHit, x4}};
/// use glam::Vec3;
/// let r = Ray4::splat(Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, -4.0, 0.0)));
/// let h = x4::intersect(&r, &x4::Plane4::splat(&Plane::new(Vec3::ZERO, Vec3::Y)));
/// assert_eq!(h.lanes(), [PlaneHit::Hit(0.5); 4]);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct PlaneHit4 {
    /// [`ONE`] hit, [`NONE`] parallel, [`ALL`] in the plane.
    pub class: i32x4,
    /// The root where the class is [`ONE`].
    pub t: f32x4,
}

/// Intersects four lines with four planes, lane by lane: the filter on
/// four f64 lanes, first with the root's bound of
/// [`stages::filter_relative`], then, for a packet with a lane it leaves,
/// with [`stages::filter_compensated`]'s and [`stages::filter`]'s, and
/// the scalar stages for any lane left undecided, so every lane equals
/// [`super::reference::intersect`] bit for bit.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, plane::{Plane, PlaneHit, reference, x4}};
/// use glam::Vec3;
/// let p = Plane::new(Vec3::new(0.0, 0.0, 3.0), Vec3::Z);
/// let rays = [Vec3::Z, Vec3::X, -Vec3::Z, Vec3::new(0.0, 1.0, 1e-30)].map(|d| Ray::new(Vec3::ZERO, d));
/// let h = x4::intersect(&Ray4::from_rays(rays), &x4::Plane4::splat(&p));
/// assert_eq!(h.lanes(), rays.map(|r| reference::intersect(&r, &p)));
/// assert_eq!(h.lanes()[1], PlaneHit::Parallel);
/// ```
#[inline]
pub fn intersect(ray: &Ray4, p: &Plane4) -> PlaneHit4 {
    #[cfg(target_arch = "x86_64")]
    if let Some(avx2) = Avx2::detect() {
        return intersect_avx2(avx2, ray, p);
    }
    intersect_baseline(ray, p)
}

/// [`intersect`] on the baseline lanes, [`F64x4`]: two SSE2 registers in a
/// default x86-64 build.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, plane::{Plane, PlaneHit, x4}};
/// use glam::Vec3;
/// let r = Ray4::splat(Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, -4.0, 0.0)));
/// let h = x4::intersect_baseline(&r, &x4::Plane4::splat(&Plane::new(Vec3::ZERO, Vec3::Y)));
/// assert_eq!(h.lanes(), [PlaneHit::Hit(0.5); 4]);
/// ```
#[inline]
pub fn intersect_baseline(ray: &Ray4, p: &Plane4) -> PlaneHit4 {
    intersect_in::<F64x4>(ray, p, || under_daz(ray, p))
}

/// [`intersect`] on one AVX register per value, compiled for AVX2 and FMA
/// and entered with the token that proves them. The same bits as
/// [`intersect_baseline`].
///
/// ```
/// use rayoracle::{Ray, num::avx::Avx2, ray4::Ray4, plane::{Plane, x4}};
/// use glam::Vec3;
/// let r = Ray4::splat(Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(0.1, -3.0, 0.0)));
/// let p = x4::Plane4::splat(&Plane::new(Vec3::ZERO, Vec3::Y));
/// if let Some(avx2) = Avx2::detect() {
///     assert_eq!(x4::intersect_avx2(avx2, &r, &p).lanes(), x4::intersect_baseline(&r, &p).lanes());
/// }
/// ```
#[cfg(target_arch = "x86_64")]
#[inline]
pub fn intersect_avx2(avx2: Avx2, ray: &Ray4, p: &Plane4) -> PlaneHit4 {
    #[target_feature(enable = "avx2,fma")]
    fn run(avx2: Avx2, ray: &Ray4, p: &Plane4) -> PlaneHit4 {
        intersect_in::<Avx4>(ray, p, || under_daz_avx2(avx2, ray, p))
    }
    // SAFETY: the token exists only where AVX2 and FMA were detected.
    // Justified by the kernels bench figures in `crate::num::avx`.
    unsafe { run(avx2, ray, p) }
}

/// [`intersect`] over many packets: `out[i] = intersect(&rays[i], p)` for
/// every `i` below the shorter length, two packets at a time as eight
/// lanes (a [`Pair`](crate::num::real::Pair) of four-lane values, AVX
/// registers where the CPU has AVX2), with the floating-point environment
/// read once.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, plane::{Plane, x4}};
/// use glam::Vec3;
/// let p = x4::Plane4::splat(&Plane::new(Vec3::ZERO, Vec3::Y));
/// let rays: Vec<Ray4> = (0..3).map(|i| Ray4::splat(Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::new(1.0, i as f32 - 1.0, 0.0)))).collect();
/// let mut out = vec![x4::intersect(&rays[0], &p); 3];
/// x4::intersect_packets(&rays, &p, &mut out);
/// for (r, h) in rays.iter().zip(&out) {
///     assert_eq!(h.lanes(), x4::intersect(r, &p).lanes());
/// }
/// ```
pub fn intersect_packets(rays: &[Ray4], p: &Plane4, out: &mut [PlaneHit4]) {
    crate::num::batch::packets_dispatch!(
        packets_in, rays, p: Plane4, out: PlaneHit4, avx512: AVX512_BATCHES
    )
}

/// Whether [`intersect_packets`] takes AVX-512 where the CPU has it. It
/// does not: pairs of AVX registers run the plane's batches a little
/// faster, and leave the code timed after them at full speed (see
/// [`crate::num::avx512`] for the figures).
const AVX512_BATCHES: bool = false;

/// [`intersect_packets`] over any eight-lane [`Real8`].
#[inline(always)]
fn packets_in<W: Real8>(rays: &[Ray4], p: &Plane4, out: &mut [PlaneHit4]) {
    if W::Half::denormals_are_zero() {
        return packets_under_daz(rays, p, out);
    }
    // Results 0 or subnormal stand only without FTZ; only a packet the
    // first pass leaves asks.
    let work = subnormals_work();
    let env = |prone: bool| !prone || work;
    let (a, n) = (
        p.point.each_ref().map(W::Half::load),
        p.normal.each_ref().map(W::Half::load),
    );
    let (a2, n2) = (a.map(W::twice), n.map(W::twice));
    let len = rays.len().min(out.len());
    let mut pairs = rays[..len].chunks_exact(2);
    let mut outs = out[..len].chunks_exact_mut(2);
    for (pk, o) in (&mut pairs).zip(&mut outs) {
        let (o2, d2) = (
            W::widen3(&pk[0].origin, &pk[1].origin),
            W::widen3(&pk[0].dir, &pk[1].dir),
        );
        let [x, y] = decide(o2, d2, a2, n2, LEAST).halves();
        o[0] = finish(x, env, &pk[0], p);
        o[1] = finish(y, env, &pk[1], p);
    }
    if let ([one], [o]) = (pairs.remainder(), outs.into_remainder()) {
        let (o1, d1) = (one.origin.map(W::Half::widen), one.dir.map(W::Half::widen));
        *o = finish(decide(o1, d1, a, n, LEAST), env, one, p);
    }
}

/// What the first pass decides, before any conversion: the hits it
/// certified, and where it did, a value that rounds to the root's `f32`.
struct Decided<L: Real> {
    hit: L::Mask,
    t: L,
}

impl<W: Real8> Decided<W> {
    #[inline(always)]
    fn halves(self) -> [Decided<W::Half>; 2] {
        let ([h0, h1], [t0, t1]) = (W::mask_halves(self.hit), self.t.halves());
        [Decided { hit: h0, t: t0 }, Decided { hit: h1, t: t1 }]
    }
}

/// The first pass ([`stages::filter_relative`]) and its certificate
/// over any [`Real`], with `least` for its probe of DAZ: the least
/// subnormal itself where the caller has found DAZ off or no input
/// subnormal, else 0, and the pass certifies nothing.
#[inline(always)]
fn decide<L: Real>(o: [L; 3], d: [L; 3], a: [L; 3], n: [L; 3], least: f64) -> Decided<L> {
    let f = stages::relative_terms_with(&stages::first_terms(o, d, a, n), L::splat(least), 1.0);
    Decided {
        hit: f.hit & certify_relative(f.t, f.r),
        t: f.t,
    }
}

/// The least subnormal `f32`, `2⁻¹⁴⁹`, as [`decide`] takes it.
const LEAST: f64 = f32::from_bits(1) as f64;

/// The results of one packet; `env(prone)` says whether they stand in the
/// floating-point environment, `prone` where a root is 0 or subnormal
/// ([`results_stand`], or [`packet_results_stand`] under DAZ; asked only
/// where the first pass leaves a lane).
#[inline(always)]
fn finish<L: Real4>(
    x: Decided<L>,
    env: impl Fn(bool) -> bool,
    ray: &Ray4,
    p: &Plane4,
) -> PlaneHit4 {
    let t = x.t.narrow();
    // A root the first pass certifies is normal as an f32: not flush-prone.
    if L::all(x.hit) {
        return PlaneHit4 {
            class: i32x4::splat(ONE),
            t,
        };
    }
    // The lanes the first pass decided, as bits, and their roots as two
    // words, stored on the way to the cold call only: passed as vectors,
    // which go through memory, they were stored before the branch above,
    // on the path of every packet it returns.
    let [t01, t23]: [u64; 2] = cast(t);
    finish_full(L::mask_i32(x.hit).to_bitmask(), [t01, t23], env, ray, p)
}

/// [`finish`] for a packet with a lane the first pass left (`hit` the
/// lanes it certified, bit `i` for lane `i`, with their roots' `f32` bits
/// in the two words): the second pass
/// ([`stages::filter_compensated`], with [`stages::exact_num`] where `d·n`
/// is exactly 0) on the packet, the full filter ([`stages::filter`]) where
/// a lane is still open, on the baseline lanes (the same bits on any),
/// then the scalar stages for what they leave.
#[cold]
#[inline(never)]
fn finish_full(
    hit: u32,
    t: [u64; 2],
    env: impl Fn(bool) -> bool,
    ray: &Ray4,
    p: &Plane4,
) -> PlaneHit4 {
    // The second pass's `least`: the least subnormal itself wherever the
    // inputs stand (DAZ off, or no input subnormal), else 0, as the probe
    // gives it under DAZ.
    let least = F64x4::splat(if env(false) { LEAST } else { 0.0 });
    let (class, t, done) = decide_full(hit, t, least, ray, p);
    // Where the results do not stand, no lane is done.
    let stands = env(flush_prone4(t));
    if done.all() && stands {
        PlaneHit4 { class, t }
    } else {
        let done = done & i32x4::splat(-i32::from(stands));
        PlaneHit4::settle([class, cast(t)], done, ray, p)
    }
}

/// The packet's passes of [`finish_full`] before the scalar stages: the
/// classes and roots, and the lanes they decide (−1), as `i32` lanes;
/// `least` for the second pass ([`stages::compensated_terms`]).
#[inline(always)]
fn decide_full(
    hit: u32,
    [t01, t23]: [u64; 2],
    least: F64x4,
    ray: &Ray4,
    p: &Plane4,
) -> (i32x4, f32x4, i32x4) {
    let bits = i32x4::from([1, 2, 4, 8]);
    let hit = (i32x4::splat(hit as i32) & bits).simd_eq(bits);
    let t: f32x4 = cast([t01, t23]);
    let (o, d, a, n) = widened::<F64x4>(ray, p);
    let first = stages::first_terms(o, d, a, n);
    let x = first.terms();
    // The second pass: d·n summed once compensated.
    let c = stages::compensated_terms(x.num, x.m_num, first.dn, least, 1.0);
    let second = certify_relative(c.relative.t, c.relative.r);
    let m = F64x4::mask_i32;
    // Where passes certify a hit, each gives the one correctly rounded
    // root; a hit is never parallel (its d·n is certainly not 0).
    let h2 = m(c.relative.hit & second);
    // Where d·n is exactly 0, (a − o)·n summed exactly, where it can be,
    // tells a line in the plane from one off it.
    let (exact, num) = stages::exact_num(o, a, n);
    let zero = F64x4::splat(0.0);
    let settled = c.den_zero & exact;
    let (par, in_plane) = (
        c.parallel | (settled & !num.eq(zero)),
        settled & num.eq(zero),
    );
    // The full filter only for a packet these leave a lane of: lines
    // near parallel and in the plane come whole.
    let (h, t, par, done) = if (hit | h2 | m(par | in_plane)).all() {
        let t = hit.bitselect(cast(t), cast(c.relative.t.narrow()));
        (hit | h2, t, m(par), hit | h2 | m(par | in_plane))
    } else {
        let f = stages::filter_terms(x, 1.0);
        let (certified, end) = certify_end(f.t, f.r, f.a);
        let h = hit | h2 | m(f.hit & certified);
        let t = hit.bitselect(
            cast(t),
            cast(h2.bitselect(cast(c.relative.t.narrow()), cast(end.narrow()))),
        );
        let par = m(f.parallel | par);
        (h, t, par, h | par | m(f.in_plane | in_plane))
    };
    let t: f32x4 = cast(h.bitselect(cast(t), cast(f32x4::splat(f32::NAN))));
    // ONE where hit, NONE where parallel (never both), else ALL.
    let k = i32x4::splat;
    let class = k(ALL) + (h & k(ONE - ALL)) + (par & k(NONE - ALL));
    (class, t, done)
}

/// The kernel over any four-lane [`Real4`]: with DAZ off, the first pass
/// and [`finish`]; under DAZ, `daz`, the same copy's [`under_daz_in`] out
/// of line, so that the common path holds no call for the scan of the
/// inputs.
#[inline(always)]
fn intersect_in<L: Real4>(ray: &Ray4, p: &Plane4, daz: impl FnOnce() -> PlaneHit4) -> PlaneHit4 {
    if L::denormals_are_zero() {
        return daz();
    }
    let (o, d, a, n) = widened::<L>(ray, p);
    finish(decide(o, d, a, n, LEAST), results_stand::<L>, ray, p)
}

/// A packet under DAZ. The planes' lanes were widened exactly when
/// packed, so DAZ meets only the rays' components. Where none is
/// subnormal, DAZ changes no value of the passes, and the first pass runs
/// (the same bits on any lanes) with `least` the least subnormal itself
/// ([`stages::relative_terms_with`]), as without DAZ, where its probe
/// reads 0; [`finish_full`] then takes what it leaves. Otherwise no result
/// stands, and every lane goes to the scalar stages.
#[inline(always)]
fn under_daz_in<L: Real4>(ray: &Ray4, p: &Plane4) -> PlaneHit4 {
    let clean = !any_subnormal4(&ray.components());
    let (o, d, a, n) = widened::<L>(ray, p);
    let x = decide(o, d, a, n, if clean { LEAST } else { 0.0 });
    finish(
        x,
        |prone| packet_results_stand::<L>(prone, || clean),
        ray,
        p,
    )
}

crate::num::batch::daz_copies!(under_daz_in, Plane4, PlaneHit4);

/// A packet's inputs in f64 lanes.
#[inline(always)]
fn widened<L: Real4>(ray: &Ray4, p: &Plane4) -> ([L; 3], [L; 3], [L; 3], [L; 3]) {
    let (w, l) = (L::widen, L::load);
    (
        ray.origin.map(w),
        ray.dir.map(w),
        p.point.each_ref().map(l),
        p.normal.each_ref().map(l),
    )
}

impl PlaneHit4 {
    /// Replaces every lane not `done` with the scalar stages' answer (the
    /// caller leaves no lane done whose result does not stand).
    #[cold]
    #[inline(never)]
    fn settle(h: [i32x4; 2], done: i32x4, ray: &Ray4, p: &Plane4) -> Self {
        #[cfg(test)]
        crate::num::paths::note_settled();
        let (class, t): (i32x4, f32x4) = (h[0], cast(h[1]));
        let rays = ray.to_rays();
        let (a, n) = (scatter3(p.point()), scatter3(p.normal()));
        let (mut class, mut t) = (class.to_array(), t.to_array());
        let done = done.to_array();
        for i in (0..4).filter(|&i| done[i] == 0) {
            (class[i], t[i]) = match reference::escalate(&rays[i], &Plane::new(a[i], n[i])).0 {
                PlaneHit::Hit(x) => (ONE, x),
                PlaneHit::Parallel => (NONE, f32::NAN),
                PlaneHit::InPlane => (ALL, f32::NAN),
            };
        }
        PlaneHit4 {
            class: i32x4::from(class),
            t: f32x4::from(t),
        }
    }

    /// The four results as scalar values.
    ///
    /// ```
    /// use rayoracle::plane::{PlaneHit, x4::PlaneHit4};
    /// use wide::{f32x4, i32x4};
    /// let h = PlaneHit4 { class: i32x4::from([1, 0, 3, 1]), t: f32x4::splat(2.0) };
    /// assert_eq!(h.lanes(), [PlaneHit::Hit(2.0), PlaneHit::Parallel, PlaneHit::InPlane, PlaneHit::Hit(2.0)]);
    /// ```
    pub fn lanes(&self) -> [PlaneHit; 4] {
        let (c, t) = (self.class.to_array(), self.t.to_array());
        [0, 1, 2, 3].map(|i| match c[i] {
            ONE => PlaneHit::Hit(t[i]),
            NONE => PlaneHit::Parallel,
            _ => PlaneHit::InPlane,
        })
    }

    /// The nearest solution per lane in `[t_min, t_max]` and the mask of
    /// lanes that have one (`+∞` elsewhere); a ray in the plane gives
    /// `t_min`. The rule of [`crate::hit::Intersection::nearest`].
    ///
    /// ```
    /// use rayoracle::plane::x4::PlaneHit4;
    /// use wide::{f32x4, i32x4};
    /// let h = PlaneHit4 { class: i32x4::from([1, 0, 3, 1]), t: f32x4::from([1.0, 0.0, 0.0, -1.0]) };
    /// let (hit, t) = h.nearest(f32x4::ZERO, f32x4::splat(5.0));
    /// assert_eq!(hit.to_bitmask(), 0b0101);
    /// assert_eq!(t.to_array(), [1.0, f32::INFINITY, 0.0, f32::INFINITY]);
    /// ```
    #[inline]
    pub fn nearest(&self, t_min: f32x4, t_max: f32x4) -> (f32x4, f32x4) {
        crate::ray4::nearest4::<false, true>(self.class, self.t, self.t, t_min, t_max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// What the packet's own passes decide, from the first pass through
    /// [`decide_full`], before the scalar stages: the answers, and the
    /// lanes decided.
    fn packet_passes(r4: &Ray4, p4: &Plane4) -> ([PlaneHit; 4], [bool; 4]) {
        let (o, d, a, n) = widened::<F64x4>(r4, p4);
        let first = decide(o, d, a, n, LEAST);
        let hit = F64x4::mask_i32(first.hit).to_bitmask();
        let least = F64x4::least_subnormal();
        let (class, t, done) = decide_full(hit, cast(first.t.narrow()), least, r4, p4);
        (
            PlaneHit4 { class, t }.lanes(),
            done.to_array().map(|x| x != 0),
        )
    }

    /// Every copy of the batch (pairs of [`F64x4`], pairs of AVX
    /// registers where the CPU has AVX2, one AVX-512 register where it has
    /// AVX-512, which [`intersect_packets`] takes) gives what the baseline
    /// one-packet kernel gives, odd tails included.
    #[test]
    fn every_batch_copy_equals_one_packet_at_a_time() {
        let p = Plane4::from_planes(
            [
                glam::Vec3::Y,
                glam::Vec3::X,
                glam::Vec3::new(1.0, 1.0, 0.0),
                glam::Vec3::ZERO,
            ]
            .map(|n| Plane::new(glam::Vec3::new(0.0, 0.5, 0.0), n)),
        );
        crate::num::batch::every_copy_agrees!(packets_in, intersect_baseline, p: Plane4, PlaneHit4);
    }

    /// A line whose `d·n = 1 + 2⁻⁶⁰ − (1 − 2⁻²⁰)` has a partial sum that
    /// rounds, and one whose `d·n = (1 + 2⁻²³)(1 − 2⁻²³) − 1` has an exact
    /// one: the first pass leaves the first and certifies the second, the
    /// full filter certifies both, and the packet gives the reference's
    /// answers.
    #[test]
    fn nearly_parallel_lanes_go_to_the_full_filter() {
        use glam::Vec3;
        let (s, e) = (2f32.powi(-30), f32::EPSILON);
        let p = Plane::new(Vec3::Z, Vec3::new(1.0 - e, s, 2f32.powi(-20) - 1.0));
        let rays = [
            Vec3::new(1.0 - e, s, 1.0),
            Vec3::new(1.0 + e, -1.0 / s, 0.0),
            Vec3::X,
            -Vec3::Z,
        ]
        .map(|d| crate::Ray::new(Vec3::new(0.3, 0.1, 0.7), d));
        let (r4, p4) = (Ray4::from_rays(rays), Plane4::splat(&p));
        let (o, d, a, n) = widened::<F64x4>(&r4, &p4);
        let (first, full) = (decide(o, d, a, n, LEAST), stages::filter(o, d, a, n, 1.0));
        assert_eq!(first.hit.lanes(), [false, true, true, true]);
        assert_eq!(full.hit.lanes(), [true; 4]);
        let want = rays.map(|r| reference::intersect(&r, &p));
        assert!(matches!(want[0], PlaneHit::Hit(_)), "{want:?}");
        assert_eq!(packet_passes(&r4, &p4), (want, [true; 4]));
        assert_eq!(intersect_baseline(&r4, &p4).lanes(), want);
        assert_eq!(intersect(&r4, &p4).lanes(), want);
    }

    /// Lines whose `d·n` cancels term by term: near parallel (`2⁻⁶⁰`,
    /// past the full filter), in the plane, and off it. The packet's
    /// second pass decides all three on its lanes, and the packet gives
    /// the reference's answers.
    #[test]
    fn the_second_pass_decides_cancelling_lanes_on_the_packet() {
        use glam::Vec3;
        let p = Plane::new(Vec3::new(1.0, 2.0, 3.0), Vec3::ONE);
        let rays = [
            crate::Ray::new(Vec3::ZERO, Vec3::new(1.0, -1.0, 2f32.powi(-60))),
            crate::Ray::new(Vec3::new(2.0, 1.0, 3.0), Vec3::new(1.0, -1.0, 0.0)),
            crate::Ray::new(Vec3::ZERO, Vec3::new(1.0, -1.0, 0.0)),
            crate::Ray::new(Vec3::ZERO, Vec3::Z),
        ];
        let (r4, p4) = (Ray4::from_rays(rays), Plane4::splat(&p));
        let (o, d, a, n) = widened::<F64x4>(&r4, &p4);
        let full = stages::filter(o, d, a, n, 1.0);
        assert_eq!(full.hit.lanes(), [false, false, false, true]);
        let c = stages::filter_compensated(o, d, a, n, 1.0);
        assert_eq!(c.relative.hit.lanes(), [true, false, false, true]);
        assert_eq!(c.den_zero.lanes(), [false, true, true, false]);
        assert_eq!(c.parallel.lanes(), [false, false, true, false]);
        let (exact, num) = stages::exact_num(o, a, n);
        assert_eq!(exact.lanes(), [true; 4]);
        assert_eq!(num.to_array(), [6.0, 0.0, 6.0, 6.0]);
        let want = [
            PlaneHit::Hit(6.0 * 2f32.powi(60)),
            PlaneHit::InPlane,
            PlaneHit::Parallel,
            PlaneHit::Hit(6.0),
        ];
        assert_eq!(rays.map(|r| reference::intersect(&r, &p)), want);
        assert_eq!(packet_passes(&r4, &p4), (want, [true; 4]));
        assert_eq!(intersect_baseline(&r4, &p4).lanes(), want);
        assert_eq!(intersect(&r4, &p4).lanes(), want);
    }

    /// Lines parallel to the plane `(a − o)·n = 0`, `a = (2⁶⁰, 0, 1)`,
    /// `n = (1, 1, 1)`: one whose offset `2⁶⁰ − 2⁶⁰ + 1` cancels below the
    /// passes' bounds (settled by the exact offset), one in the plane
    /// (likewise), and one whose offset `2⁶⁰ + 1` is certain but not exact
    /// in f64 (settled by the second pass alone); and a hit. The packet's
    /// own passes decide every lane, as the reference does, and none goes
    /// to the scalar stages; so they do without the hit (the first pass
    /// certifying no lane), with a line from a point of the plane in its
    /// place, whose root 0 only the full filter certifies, and in a packet
    /// of hits each certified by a different set of passes.
    #[test]
    fn the_packet_decides_parallel_lanes_whichever_pass_settles_them() {
        use glam::Vec3;
        let big = 2f32.powi(60);
        let p = Plane::new(Vec3::new(big, 0.0, 1.0), Vec3::ONE);
        let across = Vec3::new(1.0, -1.0, 0.0);
        let rays = [
            crate::Ray::new(Vec3::new(0.0, big, 0.0), across),
            crate::Ray::new(Vec3::new(0.0, big, 1.0), across),
            crate::Ray::new(Vec3::ZERO, across),
            crate::Ray::new(Vec3::ZERO, Vec3::Z),
        ];
        let (r4, p4) = (Ray4::from_rays(rays), Plane4::splat(&p));
        let (o, d, a, n) = widened::<F64x4>(&r4, &p4);
        let c = stages::filter_compensated(o, d, a, n, 1.0);
        assert_eq!(c.den_zero.lanes(), [true, true, true, false]);
        assert_eq!(c.parallel.lanes(), [false, false, true, false]);
        assert_eq!(
            stages::exact_num(o, a, n).0.lanes(),
            [true, true, false, false]
        );
        let want = [
            PlaneHit::Parallel,
            PlaneHit::InPlane,
            PlaneHit::Parallel,
            PlaneHit::Hit(big),
        ];
        assert_eq!(rays.map(|r| reference::intersect(&r, &p)), want);
        assert_eq!(packet_passes(&r4, &p4), (want, [true; 4]));
        assert_eq!(intersect_baseline(&r4, &p4).lanes(), want);
        assert_eq!(intersect(&r4, &p4).lanes(), want);
        // Without the hit, a packet the first pass certifies no lane of.
        let r4 = Ray4::from_rays([rays[0], rays[1], rays[2], rays[2]]);
        let want = [want[0], want[1], want[2], want[2]];
        assert_eq!(packet_passes(&r4, &p4), (want, [true; 4]));
        // With a line from a point of the plane, whose root 0 only the
        // full filter certifies: it runs on the packet, and keeps the
        // other lanes.
        let from = crate::Ray::new(Vec3::new(big, 0.0, 1.0), Vec3::Z);
        let r4 = Ray4::from_rays([from, rays[0], rays[1], rays[2]]);
        let want = [PlaneHit::Hit(0.0), want[0], want[1], want[2]];
        assert_eq!(reference::intersect(&from, &p), want[0]);
        let (o, d, a, n) = widened::<F64x4>(&r4, &p4);
        let c = stages::filter_compensated(o, d, a, n, 1.0);
        let second = c.relative.hit & certify_relative(c.relative.t, c.relative.r);
        assert_eq!(second.lanes(), [false; 4]);
        assert_eq!(decide(o, d, a, n, LEAST).hit.lanes(), [false; 4]);
        assert_eq!(packet_passes(&r4, &p4), (want, [true; 4]));
        assert_eq!(intersect(&r4, &p4).lanes(), want);
        // Hits each certified by a different set of passes, with the full
        // filter running: the first and second pass (`d·n = 1 − 1 + 2⁻⁶⁰`,
        // exact in f64, below the full filter's bound), the second alone
        // (`d·n = 1 + 2⁻⁶⁰ − 1`, whose first sum rounds), the second and
        // the full filter (as in `nearly_parallel_lanes_go_to_the_full_filter`),
        // and the full filter alone (the root 0 above).
        let (s, e) = (2f32.powi(-30), f32::EPSILON);
        let tilted = Plane::new(Vec3::Z, Vec3::new(1.0 - e, s, 2f32.powi(-20) - 1.0));
        let ones = Plane::new(Vec3::new(1.0, 2.0, 3.0), Vec3::ONE);
        let tiny = 2f32.powi(-60);
        let rays = [
            crate::Ray::new(Vec3::ZERO, Vec3::new(1.0, -1.0, tiny)),
            crate::Ray::new(Vec3::ZERO, Vec3::new(1.0, tiny, -1.0)),
            crate::Ray::new(Vec3::new(0.3, 0.1, 0.7), Vec3::new(1.0 - e, s, 1.0)),
            from,
        ];
        let planes = [ones, ones, tilted, p];
        let (r4, p4) = (Ray4::from_rays(rays), Plane4::from_planes(planes));
        let (o, d, a, n) = widened::<F64x4>(&r4, &p4);
        let c = stages::filter_compensated(o, d, a, n, 1.0);
        let second = c.relative.hit & certify_relative(c.relative.t, c.relative.r);
        let f = stages::filter(o, d, a, n, 1.0);
        let full = f.hit & certify_end(f.t, f.r, f.a).0;
        assert_eq!(
            decide(o, d, a, n, LEAST).hit.lanes(),
            [true, false, false, false]
        );
        assert_eq!(second.lanes(), [true, true, true, false]);
        assert_eq!(full.lanes(), [false, false, true, true]);
        let want = [0, 1, 2, 3].map(|i| reference::intersect(&rays[i], &planes[i]));
        assert!(
            want.iter().all(|h| matches!(h, PlaneHit::Hit(_))),
            "{want:?}"
        );
        assert_eq!(packet_passes(&r4, &p4), (want, [true; 4]));
        assert_eq!(intersect(&r4, &p4).lanes(), want);
    }

    /// Under FTZ, DAZ and both, a packet with no subnormal ray component
    /// keeps the packet's passes, one packet at a time or in pairs: the
    /// same bits as without, and no packet sent to the scalar stages. The
    /// planes' lanes, widened exactly when packed, meet DAZ nowhere, so a
    /// subnormal there changes nothing either. A subnormal in any of the
    /// rays' vectors sends its packet to the scalar stages under DAZ alone,
    /// with the same bits again; among them a direction whose one nonzero
    /// component is subnormal, whose root is ∞ once rounded, where DAZ
    /// would read no direction at all.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn packets_keep_their_passes_unless_daz_meets_a_subnormal_input() {
        use crate::num::paths::{Paths, assert_packets_keep_their_paths, fan, with_subnormal_rays};
        use crate::num::real::Pair;
        use glam::Vec3;
        fn bits(h: PlaneHit4) -> [[i32; 4]; 2] {
            [h.class, cast(h.t)].map(|v: i32x4| v.to_array())
        }
        fn batch(rays: &[Ray4], p: &Plane4, pairs: bool) -> Vec<[[i32; 4]; 2]> {
            let mut out = vec![intersect_baseline(&rays[0], p); rays.len()];
            if pairs {
                packets_in::<Pair<F64x4>>(rays, p, &mut out);
            } else {
                intersect_packets(rays, p, &mut out);
            }
            out.into_iter().map(bits).collect()
        }
        let paths: Paths<Plane4, [[i32; 4]; 2]> = [
            |r, p| r.iter().map(|r| bits(intersect(r, p))).collect(),
            |r, p| r.iter().map(|r| bits(intersect_baseline(r, p))).collect(),
            |r, p| batch(r, p, false),
            |r, p| batch(r, p, true),
        ];
        // From (0.1, 2, 0.3) at a tilted plane: hits both ways along the
        // rays, and one ray parallel to it.
        let plane = Plane::new(Vec3::new(0.0, -1.0, 0.0), Vec3::new(0.1, 1.0, -0.2));
        let rays = fan(Vec3::new(0.1, 2.0, 0.3), |i, j| match (i, j) {
            (5, 2) => Vec3::new(2.0, 0.0, 1.0),
            _ => Vec3::new(
                (i % 4 * 4 + j) as f32 / 8.0 - 1.0,
                (i / 4) as f32 / 2.0 - 1.0,
                1.0,
            ),
        });
        assert_eq!(
            reference::intersect(&rays[5].to_rays()[2], &plane),
            PlaneHit::Parallel
        );
        let tiny = Plane::new(Vec3::new(0.0, -1.0, -1e-40), Vec3::new(1e-40, 1.0, -0.2));
        let clean = [
            (rays.clone(), Plane4::splat(&plane)),
            (
                rays.clone(),
                Plane4::from_planes([plane, tiny, plane, tiny]),
            ),
        ];
        let floor = Plane::new(-Vec3::Y, Vec3::Y);
        let lone = crate::Ray::new(Vec3::new(0.0, 2.0, 0.0), Vec3::Y * -1e-40);
        assert_eq!(
            reference::intersect(&lone, &floor),
            PlaneHit::Hit(f32::INFINITY)
        );
        let p = Plane4::splat(&floor);
        let dirty: Vec<_> = with_subnormal_rays(&rays, lone)
            .into_iter()
            .map(|r| (r, p))
            .collect();
        assert_packets_keep_their_paths(paths, &clean, &dirty);
    }
}
