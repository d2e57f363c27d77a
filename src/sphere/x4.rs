//! Four rays against four spheres at once. The filter runs on four f64
//! lanes; both paths return the exact answer, correctly rounded, so they
//! agree bit for bit with [`super::reference`](mod@super::reference) by construction.

use super::{Sphere, SphereHit, reference, stages};
#[cfg(target_arch = "x86_64")]
use crate::num::avx::{Avx2, Avx4};
use crate::num::certify::{
    any_subnormal4, certify, certify_end, certify_normal4, flush_prone4, packet_results_stand,
    results_stand, subnormals_work,
};
use crate::num::real::{F64x4, Real, Real4, Real8};
use crate::ray4::class::{NONE, ONE, TWO};
use crate::ray4::{Ray4, gather3};
use wide::bytemuck::cast;
use wide::{f32x4, i32x4};

/// Four spheres, structure-of-arrays (often the same sphere four times).
///
/// ```
/// use rayoracle::sphere::{Sphere, x4::Sphere4};
/// use glam::Vec3;
/// let s = Sphere4::splat(&Sphere::new(Vec3::ZERO, 2.0));
/// assert_eq!(s.radius.to_array(), [2.0; 4]);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Sphere4 {
    /// Centre x, y, z.
    pub center: [f32x4; 3],
    /// Radius.
    pub radius: f32x4,
}

impl Sphere4 {
    /// Packs four spheres.
    ///
    /// ```
    /// use rayoracle::sphere::{Sphere, x4::Sphere4};
    /// use glam::Vec3;
    /// let s = [1.0, 2.0, 3.0, 4.0].map(|r| Sphere::new(Vec3::ZERO, r));
    /// assert_eq!(Sphere4::from_spheres(s).radius.to_array(), [1.0, 2.0, 3.0, 4.0]);
    /// ```
    pub fn from_spheres(s: [Sphere; 4]) -> Sphere4 {
        Sphere4 {
            center: gather3(s.map(|s| s.center)),
            radius: f32x4::from(s.map(|s| s.radius)),
        }
    }
    /// The same sphere in every lane.
    ///
    /// ```
    /// use rayoracle::sphere::{Sphere, x4::Sphere4};
    /// use glam::Vec3;
    /// assert_eq!(Sphere4::splat(&Sphere::new(Vec3::X, 1.0)).center[0].to_array(), [1.0; 4]);
    /// ```
    pub fn splat(s: &Sphere) -> Sphere4 {
        Sphere4::from_spheres([*s; 4])
    }
}

/// Four results: a class per lane in the shared [codes](crate::ray4::class)
/// (`NONE`, `ONE` a tangent, `TWO`) and the roots
/// (`t0 = t1` for a tangent, NaN where there is none).
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, sphere::{Sphere, SphereHit, x4}};
/// use glam::Vec3;
/// let r = Ray4::splat(Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z));
/// let h = x4::intersect(&r, &x4::Sphere4::splat(&Sphere::new(Vec3::ZERO, 1.0)));
/// assert_eq!(h.lanes(), [SphereHit::Two(4.0, 6.0); 4]);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct SphereHit4 {
    /// [`NONE`], [`ONE`] (a tangent) or [`TWO`].
    pub class: i32x4,
    /// The smaller root (the tangent root for class 1).
    pub t0: f32x4,
    /// The larger root (the tangent root for class 1).
    pub t1: f32x4,
}

/// Intersects four lines with four spheres, lane by lane: on four f64
/// lanes, [`stages::filter_sorted`], whose roots `(−b ∓ ŝ)/â` wait on no
/// division after the square root, then [`stages::filter`]'s `c/q` for
/// any lane whose root near 0 cancelled, and the scalar stages for any
/// lane both leave undecided. A packet whose every lane certainly misses
/// returns before the roots. Every lane is the exact answer, correctly
/// rounded, so it equals [`super::reference::intersect`] bit for bit.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, sphere::{Sphere, SphereHit, reference, x4}};
/// use glam::Vec3;
/// let rays = [-5.0, 0.0, 5.0, 1.0].map(|z| Ray::new(Vec3::new(0.0, 1.0, z), Vec3::Z));
/// let s = Sphere::new(Vec3::ZERO, 1.0);
/// let h = x4::intersect(&Ray4::from_rays(rays), &x4::Sphere4::splat(&s));
/// assert_eq!(h.lanes(), rays.map(|r| reference::intersect(&r, &s)));
/// ```
#[inline]
pub fn intersect(ray: &Ray4, s: &Sphere4) -> SphereHit4 {
    #[cfg(target_arch = "x86_64")]
    if let Some(avx2) = Avx2::detect() {
        return intersect_avx2(avx2, ray, s);
    }
    intersect_baseline(ray, s)
}

/// [`intersect`] on the baseline lanes, [`F64x4`]: two SSE2 registers in a
/// default x86-64 build.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, sphere::{Sphere, SphereHit, x4}};
/// use glam::Vec3;
/// let r = Ray4::splat(Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z));
/// let h = x4::intersect_baseline(&r, &x4::Sphere4::splat(&Sphere::new(Vec3::ZERO, 1.0)));
/// assert_eq!(h.lanes(), [SphereHit::Two(4.0, 6.0); 4]);
/// ```
#[inline]
pub fn intersect_baseline(ray: &Ray4, s: &Sphere4) -> SphereHit4 {
    intersect_in::<F64x4>(ray, s, || under_daz(ray, s))
}

/// [`intersect`] on one AVX register per value, compiled for AVX2 and FMA
/// and entered with the token that proves them. The same bits as
/// [`intersect_baseline`].
///
/// ```
/// use rayoracle::{Ray, num::avx::Avx2, ray4::Ray4, sphere::{Sphere, x4}};
/// use glam::Vec3;
/// let r = Ray4::splat(Ray::new(Vec3::new(0.3, 0.1, -5.0), Vec3::Z));
/// let s = x4::Sphere4::splat(&Sphere::new(Vec3::ZERO, 1.0));
/// if let Some(avx2) = Avx2::detect() {
///     assert_eq!(x4::intersect_avx2(avx2, &r, &s).lanes(), x4::intersect_baseline(&r, &s).lanes());
/// }
/// ```
#[cfg(target_arch = "x86_64")]
#[inline]
pub fn intersect_avx2(avx2: Avx2, ray: &Ray4, s: &Sphere4) -> SphereHit4 {
    #[target_feature(enable = "avx2,fma")]
    fn run(avx2: Avx2, ray: &Ray4, s: &Sphere4) -> SphereHit4 {
        intersect_in::<Avx4>(ray, s, || under_daz_avx2(avx2, ray, s))
    }
    // SAFETY: the token exists only where AVX2 and FMA were detected.
    // Justified by the kernels bench figures in `crate::num::avx`.
    unsafe { run(avx2, ray, s) }
}

/// [`intersect`] over many packets: `out[i] = intersect(&rays[i], s)` for
/// every `i` below the shorter length, bit for bit. The packets go
/// through two at a time as eight lanes (one AVX-512 register where the
/// CPU has it, else a [`Pair`](crate::num::real::Pair) of four-lane
/// values). Which lanes may hit comes from the test in `f32`
/// ([`stages::misses`]). A pair whose every lane may hit takes the roots
/// at once. In any other, the lanes the test certifies as misses are
/// written as such, and the rest are gathered, eight at a time from any packets,
/// into dense pairs for the roots, so that rays in no order (where a
/// pair is all misses about half the time, a coin toss for the branch
/// predictor) take no branch on their classes. The floating-point
/// environment is read once.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, sphere::{Sphere, x4}};
/// use glam::Vec3;
/// let s = x4::Sphere4::splat(&Sphere::new(Vec3::ZERO, 1.0));
/// let rays: Vec<Ray4> = (0..3).map(|i| Ray4::splat(Ray::new(Vec3::new(0.0, 0.3 * i as f32, -5.0), Vec3::Z))).collect();
/// let mut out = vec![x4::intersect(&rays[0], &s); 3];
/// x4::intersect_packets(&rays, &s, &mut out);
/// for (r, h) in rays.iter().zip(&out) {
///     assert_eq!(h.lanes(), x4::intersect(r, &s).lanes());
/// }
/// ```
pub fn intersect_packets(rays: &[Ray4], s: &Sphere4, out: &mut [SphereHit4]) {
    crate::num::batch::packets_dispatch!(
        packets_in, rays, s: Sphere4, out: SphereHit4, avx512: AVX512_BATCHES
    )
}

/// Whether [`intersect_packets`] takes AVX-512 where the CPU has it. It
/// does not: with the test in `f32` deciding which lanes may hit, pairs
/// of AVX registers run the sphere's batches faster (see
/// [`crate::num::avx512`] for the figures).
const AVX512_BATCHES: bool = false;

/// [`intersect_packets`] over any eight-lane [`Real8`].
#[inline(always)]
fn packets_in<W: Real8>(rays: &[Ray4], s: &Sphere4, out: &mut [SphereHit4]) {
    if W::Half::denormals_are_zero() {
        return packets_under_daz(rays, s, out);
    }
    // Results 0 or subnormal stand only without FTZ.
    let work = subnormals_work();
    let env = |prone: bool| !prone || work;
    let w = W::Half::widen;
    let c2 = s.center.map(|x| W::twice(w(x)));
    let r2 = W::twice(w(s.radius));
    let len = rays.len().min(out.len());
    // The lanes that may hit, as `4·packet + lane`, eight at a time.
    let mut live = [0usize; 16];
    let mut n = 0usize;
    for i in 0..len / 2 {
        let pk = &rays[2 * i..2 * i + 2];
        // The lanes that may hit, from the test in `f32`.
        let m = |r: &Ray4| stages::misses::certain(r, s).to_bitmask();
        let bits = !(m(&pk[0]) | m(&pk[1]) << 4) & 0xff;
        if bits == 0xff {
            #[cfg(test)]
            note(0);
            let (o2, d2) = (
                W::widen3(&pk[0].origin, &pk[1].origin),
                W::widen3(&pk[0].dir, &pk[1].dir),
            );
            let [x, y] = decide_sorted(stages::filter_sorted(o2, d2, c2, r2, 1.0)).halves();
            out[2 * i] = finish(x.packed(), true, env, &pk[0], s);
            out[2 * i + 1] = finish(y.packed(), true, env, &pk[1], s);
            continue;
        }
        out[2 * i..2 * i + 2].fill(SphereHit4::MISS);
        let at = &COMPRESS[bits as usize];
        for (l, &j) in live[n & 7..][..8].iter_mut().zip(at) {
            *l = 8 * i + usize::from(j);
        }
        n = (n & 7) + bits.count_ones() as usize;
        if n >= 8 {
            dense::<W>(&live[..8], rays, s, env, out);
            live.copy_within(8..16, 0);
            n -= 8;
        }
    }
    if n > 0 {
        let last = live[n - 1];
        live[n..8].fill(last);
        dense::<W>(&live[..8], rays, s, env, out);
    }
    if len % 2 == 1 {
        out[len - 1] = packet::<W::Half>(&rays[len - 1], s, true, env);
    }
}

/// Four lanes `live` of `rays`, and of `s`, as one packet.
#[inline(always)]
fn gather(live: &[usize], rays: &[Ray4], s: &Sphere4) -> (Ray4, Sphere4) {
    let v = |j: usize| live[j];
    let (p, l) = (
        [v(0) >> 2, v(1) >> 2, v(2) >> 2, v(3) >> 2],
        [v(0) & 3, v(1) & 3, v(2) & 3, v(3) & 3],
    );
    let pick = |x: [&f32x4; 4]| {
        f32x4::from([
            x[0].as_array()[l[0]],
            x[1].as_array()[l[1]],
            x[2].as_array()[l[2]],
            x[3].as_array()[l[3]],
        ])
    };
    let r = [&rays[p[0]], &rays[p[1]], &rays[p[2]], &rays[p[3]]];
    let o = |k: usize| {
        pick([
            &r[0].origin[k],
            &r[1].origin[k],
            &r[2].origin[k],
            &r[3].origin[k],
        ])
    };
    let d = |k: usize| pick([&r[0].dir[k], &r[1].dir[k], &r[2].dir[k], &r[3].dir[k]]);
    let c = |x: &f32x4| pick([x; 4]);
    (
        Ray4 {
            origin: [o(0), o(1), o(2)],
            dir: [d(0), d(1), d(2)],
        },
        Sphere4 {
            center: [c(&s.center[0]), c(&s.center[1]), c(&s.center[2])],
            radius: c(&s.radius),
        },
    )
}

/// The eight lanes `live` (each `4·packet + lane`) of `rays` gathered into
/// two packets, with their spheres' lanes, decided as [`packets_in`]
/// decides a pair, and each result written to its lane of `out`.
#[inline(always)]
fn dense<W: Real8>(
    live: &[usize],
    rays: &[Ray4],
    s: &Sphere4,
    env: impl Fn(bool) -> bool + Copy,
    out: &mut [SphereHit4],
) {
    #[cfg(test)]
    note(1);
    let ((r0, s0), (r1, s1)) = (gather(&live[..4], rays, s), gather(&live[4..], rays, s));
    let (o2, d2) = (
        W::widen3(&r0.origin, &r1.origin),
        W::widen3(&r0.dir, &r1.dir),
    );
    let c2 = W::widen3(&s0.center, &s1.center);
    let [r2, ..] = W::widen3(&[s0.radius; 3], &[s1.radius; 3]);
    let [x, y] = decide_sorted(stages::filter_sorted(o2, d2, c2, r2, 1.0)).halves();
    let h = [
        finish(x.packed(), true, env, &r0, &s0),
        finish(y.packed(), true, env, &r1, &s1),
    ];
    for (j, &v) in live.iter().enumerate() {
        let (p, l) = (v >> 2, v & 3);
        let (from, to) = (&h[j / 4], &mut out[p]);
        let m = j & 3;
        to.class.as_mut_array()[l] = from.class.as_array()[m];
        to.t0.as_mut_array()[l] = from.t0.as_array()[m];
        to.t1.as_mut_array()[l] = from.t1.as_array()[m];
    }
}

/// What the lanes decide, before any conversion: the certified two-root
/// lanes, the lanes done, and, in the lanes `two`, values that round to
/// the sorted roots' `f32` values (anything elsewhere: [`Decided::packed`]
/// puts NaN there).
struct Decided<L: Real> {
    two: L::Mask,
    done: L::Mask,
    lo: L,
    hi: L,
}

impl<W: Real8> Decided<W> {
    #[inline(always)]
    fn halves(self) -> [Decided<W::Half>; 2] {
        let m = W::mask_halves;
        let ([w0, w1], [d0, d1]) = (m(self.two), m(self.done));
        let ([l0, l1], [h0, h1]) = (self.lo.halves(), self.hi.halves());
        [
            Decided {
                two: w0,
                done: d0,
                lo: l0,
                hi: h0,
            },
            Decided {
                two: w1,
                done: d1,
                lo: l1,
                hi: h1,
            },
        ]
    }
}

impl<L: Real4> Decided<L> {
    /// The decisions in `f32` lanes, as [`Packed`] holds them: a lane
    /// certified two whose root is 0 or subnormal is left, for
    /// [`finish_rest`].
    #[inline(always)]
    fn packed(&self) -> Packed {
        let (lo, hi) = (self.lo.narrow(), self.hi.narrow());
        let normal = |t: f32x4| cast::<_, i32x4>(t.abs().simd_ge(f32x4::splat(f32::MIN_POSITIVE)));
        let certified = L::mask_i32(self.two);
        let two = certified & normal(lo) & normal(hi);
        // Lanes certified but not normal, moved from done to left.
        let moved = certified ^ two;
        Packed {
            two,
            left: L::mask_i32(!self.done) | moved,
            t0: nan_but::<L>(two, lo),
            t1: nan_but::<L>(two, hi),
        }
    }
}

/// A packet's decisions in `f32` lanes, as [`finish`] takes them: the
/// masks of [`Decided`] as `i32` lanes (−1 where set), with the lanes not
/// done (`left`) in place of those done, and the roots of the lanes
/// `two`, NaN elsewhere. No root of a lane `two` is 0 or subnormal (such
/// a lane is left), so the results of a packet with no lane left stand
/// wherever denormals-are-zero is off, flush-to-zero or not.
#[derive(Clone, Copy)]
struct Packed {
    two: i32x4,
    left: i32x4,
    t0: f32x4,
    t1: f32x4,
}

/// `t` in the lanes `keep`, NaN elsewhere, as `L` blends.
#[inline(always)]
fn nan_but<L: Real4>(keep: i32x4, t: f32x4) -> f32x4 {
    L::blend_f32(keep, t, f32x4::splat(f32::NAN))
}

/// The first pass over any [`Real`]: [`certify`] on the roots of
/// [`stages::filter_sorted`], which decides every lane but those with a
/// root near 0 against the other (and those the filter leaves undecided).
/// The roots kept are the enclosures' first ends, which round to the
/// roots' `f32` values where `two`.
#[inline(always)]
fn decide_sorted<L: Real>(f: stages::Sorted<L>) -> Decided<L> {
    let (ok_lo, lo) = certify_end(f.lo, f.r, f.a);
    let (ok_hi, hi) = certify_end(f.hi, f.r, f.a);
    let two = f.two & ok_lo & ok_hi;
    Decided {
        two,
        done: f.none | two,
        lo,
        hi,
    }
}

/// [`decide_sorted`] on one packet, straight into `f32` lanes
/// ([`certify_normal4`], which leaves a root 0 or subnormal undecided, as
/// [`Packed`] needs): the masks go to `i32` lanes before the roots are
/// ready, and the certification's own conversions give the roots, so no
/// mask is widened to 64-bit lanes and narrowed back on the way from the
/// roots to the result. With it, the lanes whose class is two but whose
/// roots are not certified (the only ones the second pass can decide).
#[inline(always)]
fn decide_sorted4<L: Real4>(f: stages::Sorted<L>) -> (Packed, i32x4) {
    let (ok_lo, lo) = certify_normal4(f.lo, f.r, f.a);
    let (ok_hi, hi) = certify_normal4(f.hi, f.r, f.a);
    let certain = L::mask_i32(f.two);
    let two = certain & ok_lo & ok_hi;
    let x = Packed {
        two,
        // The lanes that may have a root (a line, not `miss`), but not
        // two certified.
        left: L::mask_i32(!f.none) & !two,
        t0: nan_but::<L>(two, lo),
        t1: nan_but::<L>(two, hi),
    };
    (x, certain & !two)
}

/// The second pass, for the lanes the first leaves: [`stages::filter`],
/// whose roots `q/a` and `c/q` do not cancel, and [`certify`].
#[inline(always)]
fn decide_quotients<L: Real>(o: [L; 3], d: [L; 3], c: [L; 3], r: L) -> Decided<L> {
    let f = stages::filter(o, d, c, r, 1.0);
    let two = f.two & certify(f.t0, f.r0, f.a0) & certify(f.t1, f.r1, f.a1);
    // Disjoint enclosures are in the exact order; overlapping ones round
    // to the same f32.
    let swap = f.t0.gt(f.t1);
    Decided {
        two,
        done: f.none | two,
        lo: L::select(swap, f.t1, f.t0),
        hi: L::select(swap, f.t0, f.t1),
    }
}

/// The results of one packet. `stands` is `env(false)`: whether results
/// with no root 0 or subnormal, as the lanes done have ([`Packed`]),
/// stand in the floating-point environment; `env(prone)` says it for
/// results with such a root ([`packet_results_stand`]). A packet with no lane
/// left is one test; any other (a lane the first pass leaves with the
/// class two, an undecided class or root), or one whose results do not
/// stand, starts again out of line, in [`finish_rest`].
#[inline(always)]
fn finish(
    x: Packed,
    stands: bool,
    env: impl Fn(bool) -> bool,
    ray: &Ray4,
    s: &Sphere4,
) -> SphereHit4 {
    if !x.left.any() && stands {
        SphereHit4 {
            class: x.two & i32x4::splat(TWO),
            t0: x.t0,
            t1: x.t1,
        }
    } else {
        finish_rest(env, ray, s)
    }
}

/// [`finish`] for a packet with a lane not done, or with denormals
/// treated as zero, from its inputs again, so that nothing of the common
/// path waits on it: the first pass on the baseline lanes (the same bits
/// on any), the second ([`decide_quotients`]) for the lanes whose class is
/// two but whose roots the first left (a root 0 or subnormal included,
/// which the environment then has to let stand), and the scalar stages
/// for what is left (an undecided class, an undecided root).
#[cold]
#[inline(never)]
fn finish_rest(env: impl FnOnce(bool) -> bool, ray: &Ray4, s: &Sphere4) -> SphereHit4 {
    let (o, d, c, r) = widened::<F64x4>(ray, s);
    let (
        Packed {
            mut two,
            left,
            mut t0,
            mut t1,
        },
        open,
    ) = decide_sorted4(stages::filter_sorted(o, d, c, r, 1.0));
    let mut done = !left;
    if open.any() {
        let y = decide_quotients(o, d, c, r);
        let two_y = F64x4::mask_i32(y.two);
        let keep = |a: f32x4, t: F64x4| -> f32x4 {
            let b = nan_but::<F64x4>(two_y, t.narrow());
            cast(done.bitselect(cast(a), cast(b)))
        };
        (t0, t1) = (keep(t0, y.lo), keep(t1, y.hi));
        two |= two_y & !done;
        done |= F64x4::mask_i32(y.done);
    }
    let class = two & i32x4::splat(TWO);
    // Where the results do not stand, no lane is done.
    let stands = env(flush_prone4(t0) || flush_prone4(t1));
    if done.all() && stands {
        SphereHit4 { class, t0, t1 }
    } else {
        let done = done & i32x4::splat(-i32::from(stands));
        SphereHit4::settle([class, cast(t0), cast(t1)], done, ray, s)
    }
}

/// The kernel over any four-lane [`Real4`]: with DAZ off, [`packet`];
/// under DAZ, `daz`, the same copy's [`under_daz_in`] out of line, so
/// that the common path holds no call for the scan of the inputs (and
/// saves no register for it).
#[inline(always)]
fn intersect_in<L: Real4>(ray: &Ray4, s: &Sphere4, daz: impl FnOnce() -> SphereHit4) -> SphereHit4 {
    if L::denormals_are_zero() {
        return daz();
    }
    packet::<L>(ray, s, true, results_stand::<L>)
}

crate::num::batch::daz_copies!(under_daz_in, Sphere4, SphereHit4);

/// A packet under DAZ: where no input it widens is subnormal (the rays'
/// components and the spheres'), DAZ changes no value of the filters
/// ([`packet_results_stand`]), and the packet takes [`packet`] (the same
/// bits on any lanes); otherwise no result stands, and [`finish_rest`]
/// settles every lane in the scalar stages.
#[inline(always)]
fn under_daz_in<L: Real4>(ray: &Ray4, s: &Sphere4) -> SphereHit4 {
    let ([o0, o1, o2], [d0, d1, d2]) = (ray.origin, ray.dir);
    let [c0, c1, c2] = s.center;
    let clean = !any_subnormal4(&[o0, o1, o2, d0, d1, d2, c0, c1, c2, s.radius]);
    packet::<L>(ray, s, clean, |prone| {
        packet_results_stand::<L>(prone, || clean)
    })
}

/// One packet on the lanes `L`: `stands` whether results with no root 0
/// or subnormal stand, `env(prone)` for any.
#[inline(always)]
fn packet<L: Real4>(
    ray: &Ray4,
    s: &Sphere4,
    stands: bool,
    env: impl Fn(bool) -> bool,
) -> SphereHit4 {
    // A packet whose every lane certainly misses needs no roots: coherent
    // rays, such as a camera's, often come so. The test in `f32` needs no
    // widening; a lane it leaves takes the roots, and is done as `none`
    // if the f64 classes certify a miss.
    if stands && stages::misses::certain(ray, s).all() {
        return SphereHit4::MISS;
    }
    let (o, d, c, r) = widened::<L>(ray, s);
    finish(
        decide_sorted4(stages::filter_sorted(o, d, c, r, 1.0)).0,
        stands,
        env,
        ray,
        s,
    )
}

#[cfg(test)]
std::thread_local!(
    /// How many pairs of a batch took the roots at once, and how many
    /// gathered pairs did, on this thread: for the tests of the batches'
    /// paths.
    static PAIRS: core::cell::Cell<[usize; 2]> = const { core::cell::Cell::new([0; 2]) }
);

/// One more pair of the kind `k` (0 whole, 1 gathered) in [`PAIRS`].
#[cfg(test)]
fn note(k: usize) {
    PAIRS.with(|c| {
        let mut n = c.get();
        n[k] += 1;
        c.set(n);
    });
}

/// For each eight-bit mask, the indices of its set bits in ascending
/// order, then zeros: the lanes a batch appends.
static COMPRESS: [[u8; 8]; 256] = {
    let mut t = [[0u8; 8]; 256];
    let mut m = 0;
    while m < 256 {
        let (mut j, mut k) = (0, 0);
        while j < 8 {
            if m >> j & 1 == 1 {
                t[m][k] = j as u8;
                k += 1;
            }
            j += 1;
        }
        m += 1;
    }
    t
};

/// A packet's inputs in f64 lanes.
#[inline(always)]
fn widened<L: Real4>(ray: &Ray4, s: &Sphere4) -> ([L; 3], [L; 3], [L; 3], L) {
    let w = L::widen;
    (
        ray.origin.map(w),
        ray.dir.map(w),
        s.center.map(w),
        w(s.radius),
    )
}

impl SphereHit4 {
    /// Every lane a miss.
    const MISS: SphereHit4 = SphereHit4 {
        class: i32x4::splat(NONE),
        t0: f32x4::splat(f32::NAN),
        t1: f32x4::splat(f32::NAN),
    };

    /// Replaces every lane not `done` with the scalar stages' answer (the
    /// caller leaves no lane done whose result does not stand).
    #[cold]
    #[inline(never)]
    fn settle(h: [i32x4; 3], done: i32x4, ray: &Ray4, s: &Sphere4) -> Self {
        #[cfg(test)]
        crate::num::paths::note_settled();
        let [class, t0, t1] = h;
        let (t0, t1): (f32x4, f32x4) = (cast(t0), cast(t1));
        let (mut class, mut t0, mut t1) = (class.to_array(), t0.to_array(), t1.to_array());
        let env = subnormals_work();
        let done = done.to_array();
        for i in (0..4).filter(|&i| done[i] == 0) {
            let (k, a, b) = match reference::escalate_lane(ray, s, i, env).0 {
                SphereHit::None => (NONE, f32::NAN, f32::NAN),
                SphereHit::Tangent(t) => (ONE, t, t),
                SphereHit::Two(a, b) => (TWO, a, b),
            };
            (class[i], t0[i], t1[i]) = (k, a, b);
        }
        SphereHit4 {
            class: i32x4::from(class),
            t0: f32x4::from(t0),
            t1: f32x4::from(t1),
        }
    }
}

impl SphereHit4 {
    /// The four results as scalar values.
    ///
    /// ```
    /// use rayoracle::sphere::{SphereHit, x4::SphereHit4};
    /// use wide::{f32x4, i32x4};
    /// let h = SphereHit4 { class: i32x4::from([0, 1, 2, 2]), t0: f32x4::from([0.0, 1.0, 2.0, 3.0]), t1: f32x4::from([0.0, 1.0, 5.0, 6.0]) };
    /// assert_eq!(h.lanes()[1], SphereHit::Tangent(1.0));
    /// ```
    pub fn lanes(&self) -> [SphereHit; 4] {
        let (c, t0, t1) = (
            self.class.to_array(),
            self.t0.to_array(),
            self.t1.to_array(),
        );
        [0, 1, 2, 3].map(|i| match c[i] {
            NONE => SphereHit::None,
            ONE => SphereHit::Tangent(t0[i]),
            _ => SphereHit::Two(t0[i], t1[i]),
        })
    }

    /// The nearest root per lane in `[t_min, t_max]`, and the mask of lanes
    /// that have one; `+∞` where none. The same rule as
    /// [`crate::hit::Intersection::nearest`].
    ///
    /// ```
    /// use rayoracle::sphere::x4::SphereHit4;
    /// use wide::{f32x4, i32x4};
    /// let h = SphereHit4 { class: i32x4::splat(2), t0: f32x4::splat(-1.0), t1: f32x4::splat(3.0) };
    /// let (hit, t) = h.nearest(f32x4::ZERO, f32x4::splat(10.0));
    /// assert_eq!(t.to_array(), [3.0; 4]);
    /// assert_eq!(hit.to_bitmask(), 0b1111);
    /// ```
    #[inline]
    pub fn nearest(&self, t_min: f32x4, t_max: f32x4) -> (f32x4, f32x4) {
        crate::ray4::nearest4::<true, false>(self.class, self.t0, self.t1, t_min, t_max)
    }
}

/// Convenience for slices: every ray against one sphere, four at a time
/// (tails handled by [`crate::ray4::for_each4`]).
///
/// ```
/// use rayoracle::{Ray, sphere::{Sphere, SphereHit, x4}};
/// use glam::Vec3;
/// let rays = vec![Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z); 5];
/// let hits = x4::intersect_slice(&rays, &Sphere::new(Vec3::ZERO, 1.0));
/// assert_eq!(hits, vec![SphereHit::Two(4.0, 6.0); 5]);
/// ```
pub fn intersect_slice(rays: &[crate::Ray], sphere: &Sphere) -> Vec<SphereHit> {
    let s4 = Sphere4::splat(sphere);
    let mut out = Vec::with_capacity(rays.len());
    crate::ray4::for_each4(
        rays,
        |r| intersect(&Ray4::from_rays(r), &s4).lanes(),
        &mut out,
    );
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::hit::same_bits;
    use crate::num::real::Pair;

    /// Every copy of the batch (pairs of [`F64x4`], pairs of AVX
    /// registers where the CPU has AVX2, one AVX-512 register where it has
    /// AVX-512, which [`intersect_packets`] takes) gives what the baseline
    /// one-packet kernel gives, odd tails included.
    #[test]
    fn every_batch_copy_equals_one_packet_at_a_time() {
        let s = Sphere4::from_spheres(
            [0.5, 1.0, 2.0, 1e-30].map(|r| Sphere::new(glam::Vec3::new(0.0, 0.5, 0.0), r)),
        );
        crate::num::batch::every_copy_agrees!(packets_in, intersect_baseline, s: Sphere4, SphereHit4);
    }

    /// A batch kernel of this module.
    type Batch = fn(&[Ray4], &Sphere4, &mut [SphereHit4]);

    /// Every copy of the batch this CPU runs, named: pairs of
    /// [`F64x4`], pairs of AVX registers where it has AVX2, one AVX-512
    /// register where it has AVX-512, and the dispatched entry point.
    fn batch_copies() -> Vec<(&'static str, Batch)> {
        let mut copies: Vec<(&str, Batch)> = vec![
            ("pairs of F64x4", packets_in::<Pair<F64x4>>),
            ("dispatched", intersect_packets),
        ];
        #[cfg(target_arch = "x86_64")]
        {
            use crate::num::{
                avx::{Avx2, Avx4},
                avx512::{Avx8, Avx512},
            };
            if Avx2::detect().is_some() {
                copies.push(("pairs of AVX", |r, s, o| {
                    #[target_feature(enable = "avx2,fma")]
                    fn run(r: &[Ray4], s: &Sphere4, o: &mut [SphereHit4]) {
                        packets_in::<Pair<Avx4>>(r, s, o)
                    }
                    // SAFETY: AVX2 and FMA were detected just above.
                    unsafe { run(r, s, o) }
                }));
            }
            if Avx512::detect().is_some() {
                copies.push(("AVX-512", |r, s, o| {
                    #[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2,fma")]
                    fn run(r: &[Ray4], s: &Sphere4, o: &mut [SphereHit4]) {
                        packets_in::<Avx8>(r, s, o)
                    }
                    // SAFETY: AVX-512 F, DQ and VL, AVX2 and FMA were
                    // detected just above.
                    unsafe { run(r, s, o) }
                }));
            }
        }
        copies
    }

    /// The baseline one-packet kernel's answers, and how many lanes have
    /// two roots.
    fn one_at_a_time(rays: &[Ray4], s: &Sphere4) -> (Vec<[SphereHit; 4]>, usize) {
        let want: Vec<_> = rays
            .iter()
            .map(|r| intersect_baseline(r, s).lanes())
            .collect();
        let two = want.iter().flatten();
        let two = two.filter(|h| matches!(h, SphereHit::Two(..))).count();
        (want, two)
    }

    /// Rays in no order against a different sphere in each lane, among
    /// them exact tangents (which the scalar stages settle): every copy of
    /// the batch, over every prefix of the packets (so that each way a
    /// group of eight gathered lanes can fall, and each tail, is met),
    /// gives each packet what the one-packet kernel gives, bit for bit.
    /// The packets mix lanes that may hit with certain misses, so most
    /// lanes reach the roots gathered from other packets, in other lanes.
    #[test]
    fn lanes_gathered_from_any_packets_are_put_back_in_place() {
        use glam::Vec3;
        let spheres = [
            Sphere::new(Vec3::ZERO, 1.0),
            Sphere::new(Vec3::new(0.5, -0.3, 0.2), 0.7),
            Sphere::new(Vec3::new(-0.4, 0.6, 0.1), 1.3),
            Sphere::new(Vec3::new(0.2, 0.1, -0.5), 0.4),
        ];
        let s4 = Sphere4::from_spheres(spheres);
        let mut x = 0x9e37_79b9u32;
        let mut next = || {
            x = x.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
            (x >> 8) as f32 / (1 << 24) as f32 - 0.5
        };
        let tangent = crate::Ray::new(Vec3::new(1.0, 0.0, -4.0), Vec3::Z);
        assert_eq!(
            reference::intersect(&tangent, &spheres[0]),
            SphereHit::Tangent(4.0)
        );
        let rays: Vec<Ray4> = (0..41)
            .map(|i| {
                let mut r = [0; 4].map(|_| {
                    let o = Vec3::new(2.0 * next(), 2.0 * next(), -4.0);
                    crate::Ray::new(o, Vec3::new(next(), next(), 1.0))
                });
                if i % 5 == 2 {
                    r[0] = tangent;
                }
                Ray4::from_rays(r)
            })
            .collect();
        let live = rays
            .iter()
            .map(|r| !stages::misses::certain(r, &s4).to_bitmask() & 0b1111);
        let live: Vec<u32> = live.collect();
        let mixed = live.iter().filter(|&&m| m != 0 && m != 0b1111).count();
        assert!(mixed >= 20, "{live:?}");
        assert!(live.contains(&0), "{live:?}");
        let (want, hits) = one_at_a_time(&rays, &s4);
        assert!(hits >= 20, "{hits}");
        for (name, batch) in batch_copies() {
            for len in 0..=rays.len() {
                let mut out = vec![SphereHit4::MISS; len];
                batch(&rays[..len], &s4, &mut out);
                for (i, h) in out.iter().enumerate() {
                    let ok = h.lanes().iter().zip(&want[i]).all(|(x, y)| same_bits(x, y));
                    assert!(
                        ok,
                        "{name}, {len} packets, packet {i}: {:?}, not {:?}",
                        h.lanes(),
                        want[i]
                    );
                }
            }
        }
    }

    /// A batch of pairs whose lanes clearly hit or clearly miss (so the
    /// classes and the test in `f32` agree): a pair whose every lane hits
    /// takes the roots whole, the hits of the others are gathered eight at
    /// a time (the last group padded), and pairs of misses take neither;
    /// on every copy, with the answers of one packet at a time.
    #[test]
    fn only_the_lanes_that_may_hit_are_gathered() {
        use glam::Vec3;
        let spheres = [0.5, 1.0, 2.0, 0.25].map(|r| Sphere::new(Vec3::new(0.0, 0.5, 0.0), r));
        let s4 = Sphere4::from_spheres(spheres);
        let ray = |hit: bool| {
            let y = if hit { 0.5 } else { 9.0 };
            crate::Ray::new(Vec3::new(0.1, y, -5.0), Vec3::Z)
        };
        // Lanes that hit, per pair: all, none, three, all, five, one; and
        // a last packet alone.
        let masks: [u32; 6] = [0xff, 0, 0b1001_0010, 0xff, 0b0111_0011, 0b0100_0000];
        let mut rays: Vec<Ray4> = masks
            .iter()
            .flat_map(|m| {
                [0, 4].map(|h| Ray4::from_rays([0, 1, 2, 3].map(|l| ray(m >> (h + l) & 1 == 1))))
            })
            .collect();
        rays.push(Ray4::from_rays([true, false, true, true].map(ray)));
        let (want, hits) = one_at_a_time(&rays, &s4);
        assert_eq!(hits, 8 + 3 + 8 + 5 + 1 + 3);
        let run = |batch: Batch| {
            let mut out = vec![SphereHit4::MISS; rays.len()];
            let before = PAIRS.with(core::cell::Cell::get);
            batch(&rays, &s4, &mut out);
            let after = PAIRS.with(core::cell::Cell::get);
            for (h, w) in out.iter().zip(&want) {
                assert!(h.lanes().iter().zip(w).all(|(x, y)| same_bits(x, y)));
            }
            [after[0] - before[0], after[1] - before[1]]
        };
        // Two whole pairs; nine lanes gathered, in two groups.
        for (name, batch) in batch_copies() {
            assert_eq!(run(batch), [2, 2], "{name}");
        }
    }

    /// Packets whose lanes all miss by the test in `f32` skip the roots,
    /// one packet at a time and in pairs; a packet with one hit among
    /// misses does not, nor one with a miss too near the silhouette for
    /// that test (which the f64 classes then certify), and every lane is
    /// the reference's either way.
    #[test]
    fn packets_that_all_miss_take_the_early_exit() {
        let s = Sphere::new(glam::Vec3::ZERO, 1.0);
        let s4 = Sphere4::splat(&s);
        let ray = |y: f32| crate::Ray::new(glam::Vec3::new(0.0, y, -5.0), glam::Vec3::Z);
        let miss = Ray4::from_rays([1.5, 2.0, -3.0, 1.001].map(ray));
        let near = Ray4::from_rays([1.5, 2.0, -3.0, 1.0 + 1e-6].map(ray));
        let mixed = Ray4::from_rays([1.5, 2.0, 0.5, -3.0].map(ray));
        assert!(stages::misses::certain(&miss, &s4).all());
        assert_eq!(stages::misses::certain(&near, &s4).to_bitmask(), 0b0111);
        let (o, d, c, r) = widened::<F64x4>(&near, &s4);
        assert!(F64x4::all(stages::classes(o, d, c, r, 1.0).none));
        let (o, d, c, r) = widened::<F64x4>(&mixed, &s4);
        assert!(!F64x4::all(stages::classes(o, d, c, r, 1.0).none));
        let packets = [miss, near, mixed, miss, near, miss];
        let mut out = vec![intersect(&miss, &s4); packets.len()];
        intersect_packets(&packets, &s4, &mut out);
        packets_in::<Pair<F64x4>>(&packets[1..], &s4, &mut out[1..]);
        for (p, h) in packets.iter().zip(&out) {
            let want = p.to_rays().map(|r| reference::intersect(&r, &s));
            for hit in [
                h.lanes(),
                intersect(p, &s4).lanes(),
                intersect_baseline(p, &s4).lanes(),
            ] {
                assert!(hit.iter().zip(&want).all(|(x, y)| same_bits(x, y)), "{p:?}");
            }
        }
        assert!(matches!(out[2].lanes()[2], SphereHit::Two(..)));
        assert_eq!(out[0].lanes(), [SphereHit::None; 4]);
    }

    /// A packet in which no lane's class is certified (four exact
    /// tangents) settles every lane in the scalar stages: the
    /// reference's bits, one packet or in pairs.
    #[test]
    fn packets_without_a_certain_hit_settle_every_lane() {
        let s = Sphere::new(glam::Vec3::ZERO, 3.0);
        let s4 = Sphere4::splat(&s);
        let ray = |z: f32, y: f32| crate::Ray::new(glam::Vec3::new(0.0, y, z), glam::Vec3::Z);
        let r4 = Ray4::from_rays([
            ray(-5.0, 3.0),
            ray(0.5, 3.0),
            ray(7.0, -3.0),
            ray(-1.0, 3.0),
        ]);
        let (o, d, c, r) = widened::<F64x4>(&r4, &s4);
        let k = stages::classes(o, d, c, r, 1.0);
        assert!(F64x4::all(!k.two) && !F64x4::all(k.none));
        let want = r4.to_rays().map(|r| reference::intersect(&r, &s));
        assert_eq!(want[0], SphereHit::Tangent(5.0));
        let mut out = vec![intersect(&r4, &s4); 3];
        packets_in::<Pair<F64x4>>(&[r4; 3], &s4, &mut out);
        for h in out
            .iter()
            .chain([&intersect(&r4, &s4), &intersect_baseline(&r4, &s4)])
        {
            assert!(h.lanes().iter().zip(&want).all(|(x, y)| same_bits(x, y)));
        }
    }

    /// Subnormal roots, which the first pass certifies, are left in the
    /// `f32` lanes ([`Packed`]) and decided out of line, as is a lane of
    /// one subnormal and one normal root (`(1 ∓ 0.1)·2⁻¹²⁶`), while a lane
    /// of normal roots is done: the reference's bits, one packet or in
    /// pairs.
    #[test]
    fn subnormal_roots_are_left_and_settled() {
        let tiny = Sphere::new(glam::Vec3::ZERO, 1e-40);
        let edge = Sphere::new(glam::Vec3::Z, 0.1);
        let unit = Sphere::new(glam::Vec3::ZERO, 1.0);
        let spheres = [tiny, edge, tiny, unit];
        let ray = |z: f32, d: f32| crate::Ray::new(glam::Vec3::new(0.0, 0.0, z), d * glam::Vec3::Z);
        let rays = [
            ray(-1e-39, 1.0),
            ray(0.0, 2f32.powi(126)),
            ray(-5.0, 1.0),
            ray(-5.0, 1.0),
        ];
        let (r4, s4) = (Ray4::from_rays(rays), Sphere4::from_spheres(spheres));
        let (o, d, c, r) = widened::<F64x4>(&r4, &s4);
        let first = decide_sorted(stages::filter_sorted(o, d, c, r, 1.0));
        assert_eq!(first.two.lanes(), [true, true, false, true]);
        let packed = first.packed();
        assert_eq!(packed.two.to_array(), [0, 0, 0, -1]);
        assert_eq!(packed.left.to_array(), [-1, -1, -1, 0]);
        let (x, open) = decide_sorted4(stages::filter_sorted(o, d, c, r, 1.0));
        assert_eq!(x.two.to_array(), [0, 0, 0, -1]);
        assert_eq!(x.left.to_array(), [-1, -1, -1, 0]);
        assert_eq!(open.to_array(), [-1, -1, 0, 0]);
        let want = [0, 1, 2, 3].map(|i| reference::intersect(&rays[i], &spheres[i]));
        assert!(matches!(want[0], SphereHit::Two(t, _) if t.is_subnormal()));
        assert!(matches!(want[1], SphereHit::Two(t, u) if t.is_subnormal() && u.is_normal()));
        assert_eq!(want[3], SphereHit::Two(4.0, 6.0));
        let mut out = vec![intersect(&r4, &s4); 3];
        packets_in::<Pair<F64x4>>(&[r4; 3], &s4, &mut out);
        intersect_packets(&[r4; 3], &s4, &mut out[1..]);
        for h in out
            .iter()
            .chain([&intersect(&r4, &s4), &intersect_baseline(&r4, &s4)])
        {
            assert!(h.lanes().iter().zip(&want).all(|(x, y)| same_bits(x, y)));
        }
    }

    /// Origins a few ulps off the sphere make the textbook root near 0
    /// mostly cancellation: the first pass leaves some of those lanes and
    /// the second (`c/q`) decides them, and every packet is the
    /// reference's.
    #[test]
    fn lanes_the_first_pass_leaves_go_to_the_quotients() {
        let s = Sphere::new(glam::Vec3::new(0.25, 0.0, 0.0), 1.0);
        let s4 = Sphere4::splat(&s);
        let (mut left, mut rescued) = (0, 0);
        for k in 0..64u32 {
            let rays = [0, 1, 2, 3].map(|i| {
                let x = f32::from_bits(1.25f32.to_bits() + 4 * k + i);
                crate::Ray::new(
                    glam::Vec3::new(x, 0.0, 0.0),
                    glam::Vec3::new(-1.0, 0.1, 0.0),
                )
            });
            let r4 = Ray4::from_rays(rays);
            let (o, d, c, r) = widened::<F64x4>(&r4, &s4);
            let first = decide_sorted(stages::filter_sorted(o, d, c, r, 1.0))
                .done
                .lanes();
            let second = decide_quotients(o, d, c, r).done.lanes();
            left += first.iter().filter(|&&x| !x).count();
            rescued += (0..4).filter(|&i| !first[i] && second[i]).count();
            let want = rays.map(|r| reference::intersect(&r, &s));
            assert_eq!(intersect_baseline(&r4, &s4).lanes(), want);
            assert_eq!(intersect(&r4, &s4).lanes(), want);
        }
        assert!(rescued > 0 && left < 256, "{left} {rescued}");
    }

    /// Under FTZ, DAZ and both, a packet with no subnormal input keeps the
    /// fast path, one packet at a time or in pairs: the same bits as
    /// without, and no packet sent to the scalar stages. A subnormal in any
    /// of a packet's input vectors, which DAZ would read as 0, sends it
    /// there under DAZ alone, with the same bits again; among them a
    /// direction whose one nonzero component is subnormal, from inside the
    /// sphere, whose roots are ±∞ once rounded, where DAZ would read no
    /// line at all.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn packets_keep_the_fast_path_unless_daz_meets_a_subnormal_input() {
        use crate::num::paths::{
            Paths, assert_packets_keep_their_paths, fan, with_lane, with_subnormal_rays,
        };
        use glam::Vec3;
        fn bits(h: SphereHit4) -> [[i32; 4]; 3] {
            [h.class, cast(h.t0), cast(h.t1)].map(|v: i32x4| v.to_array())
        }
        fn batch(rays: &[Ray4], s: &Sphere4, pairs: bool) -> Vec<[[i32; 4]; 3]> {
            let mut out = vec![SphereHit4::MISS; rays.len()];
            if pairs {
                packets_in::<Pair<F64x4>>(rays, s, &mut out);
            } else {
                intersect_packets(rays, s, &mut out);
            }
            out.into_iter().map(bits).collect()
        }
        let paths: Paths<Sphere4, [[i32; 4]; 3]> = [
            |r, s| r.iter().map(|r| bits(intersect(r, s))).collect(),
            |r, s| r.iter().map(|r| bits(intersect_baseline(r, s))).collect(),
            |r, s| batch(r, s, false),
            |r, s| batch(r, s, true),
        ];
        // From (0, 0.3, −4) at the unit sphere: hits and misses.
        let unit = Sphere::new(Vec3::ZERO, 1.0);
        let rays = fan(Vec3::new(0.0, 0.3, -4.0), |i, j| {
            Vec3::new(
                (i % 4 * 4 + j) as f32 / 16.0 - 0.5,
                (i / 4) as f32 / 4.0 - 0.5,
                1.0,
            )
        });
        let s = Sphere4::splat(&unit);
        assert!(
            rays.iter()
                .any(|r| intersect(r, &s).class.to_array().contains(&TWO))
        );
        let lone = crate::Ray::new(Vec3::new(0.0, 0.5, 0.0), Vec3::X * 1e-40);
        let want = SphereHit::Two(f32::NEG_INFINITY, f32::INFINITY);
        assert_eq!(reference::intersect(&lone, &unit), want);
        let mut dirty: Vec<_> = with_subnormal_rays(&rays, lone)
            .into_iter()
            .map(|r| (r, s))
            .collect();
        for v in 0..4 {
            let mut s = s;
            let x = if v < 3 {
                &mut s.center[v]
            } else {
                &mut s.radius
            };
            *x = with_lane(*x, v, -1e-40);
            dirty.push((rays[4..7].to_vec(), s));
        }
        // Origins a few ulps off a sphere: packets whose first pass leaves
        // a lane that the second (`c/q`) decides, with normal roots, which
        // stand under FTZ too.
        let off = Sphere4::splat(&Sphere::new(Vec3::new(0.25, 0.0, 0.0), 1.0));
        let near: Vec<Ray4> = (0..64u32)
            .map(|k| {
                Ray4::from_rays([0, 1, 2, 3].map(|i| {
                    let x = f32::from_bits(1.25f32.to_bits() + 4 * k + i);
                    crate::Ray::new(Vec3::new(x, 0.0, 0.0), Vec3::new(-1.0, 0.1, 0.0))
                }))
            })
            .filter(|r4| {
                let (o, d, c, r) = widened::<F64x4>(r4, &off);
                let first = decide_sorted(stages::filter_sorted(o, d, c, r, 1.0)).done;
                let second = decide_quotients(o, d, c, r).done;
                !F64x4::all(first) && F64x4::all(first | second)
            })
            .collect();
        assert!(near.len() >= 3, "{}", near.len());
        let clean = [(rays, s), (near, off)];
        assert_packets_keep_their_paths(paths, &clean, &dirty);
    }
}
