//! Four rays against four quadrics at once. A first pass
//! ([`lanes`]: the filter's classes, and the roots as
//! `(−β ∓ √Δ)/2α`) runs on four f64 lanes, then the filter's quotients
//! for a packet it leaves a lane of; both paths return the exact answer,
//! correctly rounded, so they agree bit for bit with
//! [`super::reference`](mod@super::reference) by construction.

use super::{Quadric, QuadricHit, lanes, reference, stages};
#[cfg(target_arch = "x86_64")]
use crate::num::avx::{Avx2, Avx4};
use crate::num::certify::{
    any_subnormal4, certify, certify_end, flush_prone4, narrow_exact, packet_results_stand,
    results_stand, subnormals_work, widen_lanes,
};
use crate::num::real::{F64x4, Real, Real4, Real8};
use crate::ray4::Ray4;
use crate::ray4::class::{ALL, NONE, ONE, TWO};
use wide::bytemuck::cast;
use wide::{f32x4, i32x4};

/// Four quadrics, structure-of-arrays, one lane per quadric for each
/// coefficient, held as f64 lanes: widened once when packed (exactly, with
/// integer arithmetic, so that denormals-are-zero at that moment changes
/// nothing), so that each packet's call loads them as they are.
///
/// ```
/// use rayoracle::quadric::{Quadric, x4::Quadric4};
/// let q = Quadric4::splat(&Quadric::new([1.0; 10]));
/// assert_eq!(q.coeffs()[9].to_array(), [1.0; 4]);
/// ```
#[derive(Clone, Copy, Debug)]
#[repr(align(32))]
pub struct Quadric4 {
    /// `[A … J]` in f64, lane `i` from quadric `i`.
    wide: [[f64; 4]; 10],
}

impl Quadric4 {
    /// Packs four quadrics.
    ///
    /// ```
    /// use rayoracle::quadric::{Quadric, x4::Quadric4};
    /// let q = [0.0, 1.0, 2.0, 3.0].map(|j| Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, j]));
    /// assert_eq!(Quadric4::from_quadrics(q).coeffs()[9].to_array(), [0.0, 1.0, 2.0, 3.0]);
    /// ```
    pub fn from_quadrics(q: [Quadric; 4]) -> Quadric4 {
        Quadric4 {
            wide: core::array::from_fn(|k| widen_lanes(f32x4::from(q.map(|q| q.coeffs[k])))),
        }
    }
    /// `[A … J]` as given, lane `i` from quadric `i` (narrowed exactly,
    /// whatever the environment; a signalling NaN comes back quiet).
    ///
    /// ```
    /// use rayoracle::quadric::{Quadric, x4::Quadric4};
    /// let k = [1e-40, -0.0, 2.5, 0.1, 0.0, 0.0, 0.0, 0.0, 0.0, f32::INFINITY];
    /// let got = Quadric4::splat(&Quadric::new(k)).coeffs().map(|c| c.to_array()[3].to_bits());
    /// assert_eq!(got, k.map(f32::to_bits));
    /// ```
    pub fn coeffs(&self) -> [f32x4; 10] {
        self.wide.map(|c| f32x4::from(c.map(narrow_exact)))
    }
    /// `[A … J]` widened, lane `i` from quadric `i`: what the kernels and
    /// the scalar stages read.
    #[inline(always)]
    pub(crate) fn f64_lanes(&self) -> &[[f64; 4]; 10] {
        &self.wide
    }
    /// The same quadric in every lane.
    ///
    /// ```
    /// use rayoracle::quadric::{Quadric, x4::Quadric4};
    /// assert_eq!(Quadric4::splat(&Quadric::new([2.0; 10])).coeffs()[0].to_array(), [2.0; 4]);
    /// ```
    pub fn splat(q: &Quadric) -> Quadric4 {
        Quadric4::from_quadrics([*q; 4])
    }
    /// The coefficients in lanes of `L`, written out: `map` over ten lanes
    /// is not always inlined.
    #[inline(always)]
    fn lanes<L: Real4>(&self) -> [L; 10] {
        let (w, l) = (&self.wide, L::load);
        [
            l(&w[0]),
            l(&w[1]),
            l(&w[2]),
            l(&w[3]),
            l(&w[4]),
            l(&w[5]),
            l(&w[6]),
            l(&w[7]),
            l(&w[8]),
            l(&w[9]),
        ]
    }
}

/// Four results: a class per lane in the shared
/// [codes](crate::ray4::class) (`NONE`, `ONE`, `TWO`, `ALL`) and the
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
    /// [`NONE`], [`ONE`], [`TWO`] or [`ALL`].
    pub class: i32x4,
    /// The smaller (or only) root.
    pub t0: f32x4,
    /// The larger (or only) root.
    pub t1: f32x4,
}

/// Intersects four lines with four quadrics, lane by lane: a first pass
/// on four f64 lanes (the [filter](super::stages)'s classes, and the roots
/// in a form whose divisions do not wait on the square root), the
/// filter's quotients for a packet with a lane it leaves, and the scalar
/// stages for any lane still undecided, so every lane equals
/// [`super::reference::intersect`] bit for bit. A packet whose every lane
/// certainly misses returns before the roots.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, quadric::{Quadric, QuadricHit, reference, x4}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let rays = [
///     Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X),
///     Ray::new(Vec3::X, Vec3::Z),
///     Ray::new(Vec3::new(-5.0, 1.0, 0.0), Vec3::X),
///     Ray::new(Vec3::new(-5.0, 2.0, 0.0), Vec3::X),
/// ];
/// let h = x4::intersect(&Ray4::from_rays(rays), &x4::Quadric4::splat(&cyl));
/// assert_eq!(h.lanes(), rays.map(|r| reference::intersect(&r, &cyl)));
/// assert_eq!(h.lanes()[2], QuadricHit::One(5.0));
/// ```
#[inline]
pub fn intersect(ray: &Ray4, q: &Quadric4) -> QuadricHit4 {
    #[cfg(target_arch = "x86_64")]
    if let Some(avx2) = Avx2::detect() {
        return intersect_avx2(avx2, ray, q);
    }
    intersect_baseline(ray, q)
}

/// [`intersect`] on the baseline lanes, [`F64x4`]: two SSE2 registers in a
/// default x86-64 build.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, quadric::{Quadric, QuadricHit, x4}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let r = Ray4::splat(Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X));
/// assert_eq!(x4::intersect_baseline(&r, &x4::Quadric4::splat(&cyl)).lanes(), [QuadricHit::Two(4.0, 6.0); 4]);
/// ```
#[inline]
pub fn intersect_baseline(ray: &Ray4, q: &Quadric4) -> QuadricHit4 {
    intersect_in::<F64x4>(ray, q, || under_daz(ray, q))
}

/// [`intersect`] on one AVX register per value, compiled for AVX2 and FMA
/// and entered with the token that proves them. The same bits as
/// [`intersect_baseline`].
///
/// ```
/// use rayoracle::{Ray, num::avx::Avx2, ray4::Ray4, quadric::{Quadric, x4}};
/// use glam::Vec3;
/// let cyl = x4::Quadric4::splat(&Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]));
/// let r = Ray4::splat(Ray::new(Vec3::new(-5.0, 0.3, 0.0), Vec3::new(1.0, 0.1, 0.0)));
/// if let Some(avx2) = Avx2::detect() {
///     assert_eq!(x4::intersect_avx2(avx2, &r, &cyl).lanes(), x4::intersect_baseline(&r, &cyl).lanes());
/// }
/// ```
#[cfg(target_arch = "x86_64")]
#[inline]
pub fn intersect_avx2(avx2: Avx2, ray: &Ray4, q: &Quadric4) -> QuadricHit4 {
    #[target_feature(enable = "avx2,fma")]
    fn run(avx2: Avx2, ray: &Ray4, q: &Quadric4) -> QuadricHit4 {
        intersect_in::<Avx4>(ray, q, || under_daz_avx2(avx2, ray, q))
    }
    // SAFETY: the token exists only where AVX2 and FMA were detected.
    // Justified by the kernels bench figures in `crate::num::avx`.
    unsafe { run(avx2, ray, q) }
}

/// [`intersect`] over many packets: `out[i] = intersect(&rays[i], q)` for
/// every `i` below the shorter length, two packets at a time as eight
/// lanes (one AVX-512 register where the CPU has it, else a
/// [`Pair`](crate::num::real::Pair) of four-lane values), with the
/// floating-point environment read once.
///
/// ```
/// use rayoracle::{Ray, ray4::Ray4, quadric::{Quadric, x4}};
/// use glam::Vec3;
/// let cyl = x4::Quadric4::splat(&Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]));
/// let rays: Vec<Ray4> = (0..3).map(|i| Ray4::splat(Ray::new(Vec3::new(-5.0, 0.5 * i as f32, 0.0), Vec3::X))).collect();
/// let mut out = vec![x4::intersect(&rays[0], &cyl); 3];
/// x4::intersect_packets(&rays, &cyl, &mut out);
/// for (r, h) in rays.iter().zip(&out) {
///     assert_eq!(h.lanes(), x4::intersect(r, &cyl).lanes());
/// }
/// ```
pub fn intersect_packets(rays: &[Ray4], q: &Quadric4, out: &mut [QuadricHit4]) {
    crate::num::batch::packets_dispatch!(packets_in, rays, q: Quadric4, out: QuadricHit4)
}

/// [`intersect_packets`] over any eight-lane [`Real8`].
#[inline(always)]
fn packets_in<W: Real8>(rays: &[Ray4], q: &Quadric4, out: &mut [QuadricHit4]) {
    if W::Half::denormals_are_zero() {
        return packets_under_daz(rays, q, out);
    }
    // Results 0 or subnormal stand only without FTZ.
    let work = subnormals_work();
    let env = |prone: bool| !prone || work;
    let k = q.lanes::<W::Half>();
    let t = W::twice;
    let k2 = [
        t(k[0]),
        t(k[1]),
        t(k[2]),
        t(k[3]),
        t(k[4]),
        t(k[5]),
        t(k[6]),
        t(k[7]),
        t(k[8]),
        t(k[9]),
    ];
    let len = rays.len().min(out.len());
    let mut pairs = rays[..len].chunks_exact(2);
    let mut outs = out[..len].chunks_exact_mut(2);
    for (pk, o) in (&mut pairs).zip(&mut outs) {
        let (o2, d2) = (
            W::widen3(&pk[0].origin, &pk[1].origin),
            W::widen3(&pk[0].dir, &pk[1].dir),
        );
        let c = lanes::classes(&k2, o2, d2, 1.0, 1.0);
        if W::all(c.none) {
            o.fill(QuadricHit4::MISS);
            continue;
        }
        let (x, open) = decide_sorted(&c, lanes::sorted(&c, 1.0));
        if !W::all(!open) {
            o[0] = quotients(&pk[0], q, env);
            o[1] = quotients(&pk[1], q, env);
            continue;
        }
        let [x, y] = x.halves();
        o[0] = finish(x, env, &pk[0], q);
        o[1] = finish(y, env, &pk[1], q);
    }
    if let ([one], [o]) = (pairs.remainder(), outs.into_remainder()) {
        *o = packet::<W::Half>(one, q, env);
    }
}

/// What the lanes decide, before any conversion.
struct Decided<L: Real> {
    two: L::Mask,
    one: L::Mask,
    all: L::Mask,
    done: L::Mask,
    /// The smaller (or only) root, NaN where there is none.
    lo: L,
    /// The larger (or only) root, NaN where there is none.
    hi: L,
}

impl<W: Real8> Decided<W> {
    #[inline(always)]
    fn halves(self) -> [Decided<W::Half>; 2] {
        let m = W::mask_halves;
        let ([w0, w1], [n0, n1], [a0, a1]) = (m(self.two), m(self.one), m(self.all));
        let ([d0, d1], [l0, l1], [h0, h1]) = (m(self.done), self.lo.halves(), self.hi.halves());
        [
            Decided {
                two: w0,
                one: n0,
                all: a0,
                done: d0,
                lo: l0,
                hi: h0,
            },
            Decided {
                two: w1,
                one: n1,
                all: a1,
                done: d1,
                lo: l1,
                hi: h1,
            },
        ]
    }
}

/// The filter's roots certified ([`certify`]) over any [`Real`]: the
/// quotients `q/α` and `γ/q`, which do not cancel, and the linear root.
#[inline(always)]
fn decide<L: Real>(f: stages::Filtered<L>) -> Decided<L> {
    let ok1 = certify(f.t1, f.r1, f.a1);
    let two = f.two & certify(f.t0, f.r0, f.a0) & ok1;
    let one = f.linear & ok1;
    // Disjoint enclosures are in the exact order; overlapping ones round
    // to the same f32. The linear root is t1.
    let swap = (two & f.t0.gt(f.t1)) | one;
    let nan = L::splat(f64::NAN);
    let lo = L::select(two | one, L::select(swap, f.t1, f.t0), nan);
    Decided {
        two,
        one,
        all: f.all,
        done: two | one | f.none | f.all,
        lo,
        hi: L::select(two, L::select(swap, f.t0, f.t1), lo),
    }
}

/// The results of one packet; `env(prone)` says whether they stand in the
/// floating-point environment, `prone` where a root is 0 or subnormal
/// ([`packet_results_stand`]).
#[inline(always)]
fn finish<L: Real4>(
    x: Decided<L>,
    env: impl Fn(bool) -> bool,
    ray: &Ray4,
    q: &Quadric4,
) -> QuadricHit4 {
    let (t, o, a) = (L::mask_i32(x.two), L::mask_i32(x.one), L::mask_i32(x.all));
    let k = i32x4::splat;
    let class = t.select(k(TWO), o.select(k(ONE), a & k(ALL)));
    let (t0, t1) = (x.lo.narrow(), x.hi.narrow());
    let prone = flush_prone4(t0) || flush_prone4(t1);
    if L::all(x.done) && env(prone) {
        QuadricHit4 { class, t0, t1 }
    } else {
        // Where the results do not stand, no lane is done.
        let done = L::mask_i32(x.done) & i32x4::splat(-i32::from(env(prone)));
        QuadricHit4::settle([class, cast(t0), cast(t1)], done, ray, q)
    }
}

/// The kernel over any four-lane [`Real4`]: with DAZ off, [`packet`];
/// under DAZ, `daz`, the same copy's [`under_daz_in`] out of line, so
/// that the common path holds no call for the scan of the inputs (and
/// saves no register for it).
#[inline(always)]
fn intersect_in<L: Real4>(
    ray: &Ray4,
    q: &Quadric4,
    daz: impl FnOnce() -> QuadricHit4,
) -> QuadricHit4 {
    if L::denormals_are_zero() {
        return daz();
    }
    packet::<L>(ray, q, results_stand::<L>)
}

crate::num::batch::daz_copies!(under_daz_in, Quadric4, QuadricHit4);

/// A packet under DAZ: the coefficients were widened exactly when packed,
/// so where no ray component is subnormal, DAZ changes no value of the
/// filters ([`packet_results_stand`]), and the packet takes [`packet`]
/// (the same bits on any lanes); otherwise no result stands, and every
/// lane goes to the scalar stages.
#[inline(always)]
fn under_daz_in<L: Real4>(ray: &Ray4, q: &Quadric4) -> QuadricHit4 {
    let clean = !any_subnormal4(&ray.components());
    packet::<L>(ray, q, |prone| packet_results_stand::<L>(prone, || clean))
}

/// One packet on the lanes `L`, `env(prone)` saying whether its results
/// stand. A packet whose every lane certainly misses needs no roots
/// (their square root, division and bounds): a camera's coherent rays
/// often come so. A packet with a lane the first pass leaves (α = 0, a
/// root near 0 against the other, an `α̂` that cancels or a product out
/// of range) takes [`quotients`] whole.
#[inline(always)]
fn packet<L: Real4>(ray: &Ray4, q: &Quadric4, env: impl Fn(bool) -> bool) -> QuadricHit4 {
    let k = q.lanes::<L>();
    let c = lanes::classes(
        &k,
        ray.origin.map(L::widen),
        ray.dir.map(L::widen),
        1.0,
        1.0,
    );
    if L::all(c.none) && env(false) {
        return QuadricHit4::MISS;
    }
    let (x, open) = decide_sorted(&c, lanes::sorted(&c, 1.0));
    if L::all(!open) {
        finish(x, env, ray, q)
    } else {
        quotients(ray, q, env)
    }
}

/// The first pass's decisions from its classes and sorted roots, and the
/// lanes it leaves to the quotients: those of the class two whose roots
/// it did not certify, and those with α = 0.
#[inline(always)]
fn decide_sorted<L: Real>(c: &lanes::Classes<L>, f: lanes::Sorted<L>) -> (Decided<L>, L::Mask) {
    let (ok_lo, lo) = certify_end(f.lo, f.r, f.a);
    let (ok_hi, hi) = certify_end(f.hi, f.r, f.a);
    let two = c.two & ok_lo & ok_hi;
    let nan = L::splat(f64::NAN);
    let no = nan.gt(nan);
    let x = Decided {
        two,
        one: no,
        all: no,
        done: two | c.none,
        lo: L::select(two, lo, nan),
        hi: L::select(two, hi, nan),
    };
    (x, (c.two & !two) | c.linear())
}

/// The whole packet by the filter's quotients ([`decide`]), on the
/// baseline lanes (the same bits on any): for a packet with a lane the
/// first pass leaves. Where no lane is of the filter's class two or
/// linear, the filter's classes alone: no root, or the line on the
/// surface; the scalar stages take the rest.
#[cold]
#[inline(never)]
fn quotients(ray: &Ray4, q: &Quadric4, env: impl Fn(bool) -> bool) -> QuadricHit4 {
    finish(decide_quotients(ray, q), env, ray, q)
}

/// What [`quotients`] decides, before the scalar stages.
#[inline(always)]
fn decide_quotients(ray: &Ray4, q: &Quadric4) -> Decided<F64x4> {
    let k = q.lanes::<F64x4>();
    let w = F64x4::widen;
    let c = stages::classes(&k, ray.origin.map(w), ray.dir.map(w), 1.0);
    if F64x4::all(!(c.two | c.linear())) {
        let (none, all) = (c.none(), c.all());
        let (no_lane, nan) = (none & !none, F64x4::splat(f64::NAN));
        Decided {
            two: no_lane,
            one: no_lane,
            all,
            done: none | all,
            lo: nan,
            hi: nan,
        }
    } else {
        decide(stages::roots(&c, 1.0))
    }
}

/// The first pass of [`intersect`] alone on one line, the bounds of
/// [`lanes`] multiplied by `shrink` where they decide the class and by
/// `roots` where they certify the roots: the answer where it certifies one
/// (two roots or none), `None` where it leaves the line to the quotients
/// or the scalar stages. Each lane of the kernel
/// computes the same bits, every operation being one IEEE-754 operation
/// per lane. For the tests that show a bound too small gives wrong
/// answers.
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, QuadricHit, x4}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let r = Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X);
/// assert_eq!(x4::first_pass_shrunk(&r, &cyl, 1.0, 1.0), Some(QuadricHit::Two(4.0, 6.0)));
/// ```
#[doc(hidden)]
pub fn first_pass_shrunk(
    ray: &crate::Ray,
    q: &Quadric,
    shrink: f64,
    roots: f64,
) -> Option<QuadricHit> {
    let w = |v: glam::Vec3| v.to_array().map(f64::from);
    let k = q.coeffs.map(f64::from);
    let c = lanes::classes(&k, w(ray.origin), w(ray.dir), shrink, roots);
    let (x, _) = decide_sorted(&c, lanes::sorted(&c, roots));
    if x.two {
        Some(QuadricHit::Two(x.lo as f32, x.hi as f32))
    } else {
        c.none.then_some(QuadricHit::None)
    }
}

impl QuadricHit4 {
    /// Every lane a miss.
    const MISS: QuadricHit4 = QuadricHit4 {
        class: i32x4::splat(NONE),
        t0: f32x4::splat(f32::NAN),
        t1: f32x4::splat(f32::NAN),
    };

    /// Replaces every lane not `done` with the scalar stages' answer (the
    /// caller leaves no lane done whose result does not stand).
    #[cold]
    #[inline(never)]
    fn settle(h: [i32x4; 3], done: i32x4, ray: &Ray4, q: &Quadric4) -> Self {
        #[cfg(test)]
        crate::num::paths::note_settled();
        let [class, t0, t1] = h;
        let (t0, t1): (f32x4, f32x4) = (cast(t0), cast(t1));
        let (mut class, mut t0, mut t1) = (class.to_array(), t0.to_array(), t1.to_array());
        let done = done.to_array();
        for i in (0..4).filter(|&i| done[i] == 0) {
            (class[i], t0[i], t1[i]) =
                match reference::escalate_lane(ray, q.f64_lanes(), i).unpack().0 {
                    QuadricHit::None => (NONE, f32::NAN, f32::NAN),
                    QuadricHit::One(t) => (ONE, t, t),
                    QuadricHit::Two(a, b) => (TWO, a, b),
                    QuadricHit::All => (ALL, f32::NAN, f32::NAN),
                };
        }
        QuadricHit4 {
            class: i32x4::from(class),
            t0: f32x4::from(t0),
            t1: f32x4::from(t1),
        }
    }

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
            NONE => QuadricHit::None,
            ONE => QuadricHit::One(t0[i]),
            TWO => QuadricHit::Two(t0[i], t1[i]),
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
        crate::ray4::nearest4::<true, true>(self.class, self.t0, self.t1, t_min, t_max)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every copy of the batch (pairs of [`F64x4`], and where the CPU has
    /// them pairs of AVX2 registers and AVX-512 registers, of which
    /// [`intersect_packets`] takes only the widest) gives what the baseline
    /// one-packet kernel gives, odd tails included.
    #[test]
    fn every_batch_copy_equals_one_packet_at_a_time() {
        let q = Quadric4::from_quadrics(
            [-1.0, 0.0, 1.0, 1e-30]
                .map(|j| Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, j])),
        );
        crate::num::batch::every_copy_agrees!(packets_in, intersect_baseline, q: Quadric4, QuadricHit4);
    }

    /// A packet whose every lane certainly misses returns before the
    /// roots, with what the reference gives lane by lane; so does a pair
    /// of such packets in a batch, and a packet with one hit among misses
    /// takes the whole path.
    #[test]
    fn packets_that_miss_return_the_reference_answers() {
        use crate::{Ray, ray4::Ray4};
        use glam::Vec3;
        let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let q = Quadric4::splat(&cyl);
        let along = |y: f32| Ray::new(Vec3::new(-5.0, y, 0.0), Vec3::X);
        for ys in [[2.0, 3.0, -2.0, 1.5], [2.0, 0.5, -2.0, 1.5]] {
            let rays = ys.map(along);
            let r4 = Ray4::from_rays(rays);
            let want = rays.map(|r| reference::intersect(&r, &cyl));
            assert_eq!(intersect(&r4, &q).lanes(), want, "{ys:?}");
            assert_eq!(intersect_baseline(&r4, &q).lanes(), want, "{ys:?}");
            let mut out = [QuadricHit4::MISS; 2];
            intersect_packets(&[r4, r4], &q, &mut out);
            assert_eq!(out.map(|h| h.lanes()), [want; 2], "{ys:?}");
        }
        let misses = [2.0, 3.0, -2.0, 1.5].map(along);
        assert!(
            misses
                .iter()
                .all(|r| reference::intersect(r, &cyl) == QuadricHit::None)
        );
    }

    /// A lane with α = 0 goes to the quotients only where `|β̂|` passes the
    /// filter's test for the linear root, `|β̂| > 2E_β`: the plane `x − y +
    /// 2⁻⁶⁰z = 2⁻⁶⁰` met along `(1, 1, 1)` from the origin has `β̂ = 2⁻⁶⁰`
    /// (exact), far below `2E_β = 48u` (with `m_β = 2`), which the
    /// quotients cannot take further than the first pass; so the first
    /// pass leaves it to the scalar stages alone, and one with `β = 1`
    /// (the plane `x = 1`) to the quotients. The answers are the
    /// reference's either way.
    #[test]
    fn only_alpha_zero_lanes_the_quotients_can_decide_go_to_them() {
        use crate::{Ray, ray4::Ray4};
        use glam::Vec3;
        let tiny = 2f32.powi(-60);
        let steep = Quadric::new([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -1.0, tiny, -tiny]);
        let wall = Quadric::new([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -1.0]);
        let (slant, along) = (
            Ray::new(Vec3::ZERO, Vec3::ONE),
            Ray::new(Vec3::ZERO, Vec3::X),
        );
        let (rays, qs) = ([slant, along, slant, along], [steep, wall, steep, wall]);
        let want = [QuadricHit::One(1.0); 4];
        assert_eq!(
            [0, 1, 2, 3].map(|i| reference::intersect(&rays[i], &qs[i])),
            want
        );
        let (r4, q4) = (Ray4::from_rays(rays), Quadric4::from_quadrics(qs));
        let w = F64x4::widen;
        let first = lanes::classes(
            &q4.lanes::<F64x4>(),
            r4.origin.map(w),
            r4.dir.map(w),
            1.0,
            1.0,
        );
        let (_, open) = decide_sorted(&first, lanes::sorted(&first, 1.0));
        assert_eq!(open.lanes(), [false, true, false, true]);
        assert_eq!(intersect_baseline(&r4, &q4).lanes(), want);
        assert_eq!(intersect(&r4, &q4).lanes(), want);
    }

    /// The quotients ([`decide_quotients`]) settle a lane of each class on the
    /// packet: two roots, the paraboloid `z = x² + y²` along its axis (α
    /// = 0, every term 0: one root), no root, and a line in the double
    /// plane `x² = 0` (every term of α, β and γ 0). A lane with α = 0
    /// sends the packet to them from the first pass, which settles the two
    /// roots and the miss itself; no lane goes on to the scalar stages, nor
    /// in a packet of misses and lines on the surface alone.
    #[test]
    fn the_quotients_settle_a_lane_of_each_class() {
        use crate::{Ray, ray4::Ray4};
        use glam::Vec3;
        let bowl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0, 0.0]);
        let plane = Quadric::new([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0]);
        let qs = [bowl, bowl, bowl, plane];
        let rays = [
            Ray::new(Vec3::new(-5.0, 0.0, 1.0), Vec3::X),
            Ray::new(Vec3::new(0.0, 0.0, -2.0), Vec3::Z),
            Ray::new(Vec3::new(-5.0, 0.0, -1.0), Vec3::X),
            Ray::new(Vec3::ZERO, Vec3::Y),
        ];
        let want = [
            QuadricHit::Two(4.0, 6.0),
            QuadricHit::One(2.0),
            QuadricHit::None,
            QuadricHit::All,
        ];
        assert_eq!(
            [0, 1, 2, 3].map(|i| reference::intersect(&rays[i], &qs[i])),
            want
        );
        let (r4, q4) = (Ray4::from_rays(rays), Quadric4::from_quadrics(qs));
        let w = F64x4::widen;
        let (o, d) = (r4.origin.map(w), r4.dir.map(w));
        let first = lanes::classes(&q4.lanes::<F64x4>(), o, d, 1.0, 1.0);
        let (sorted, open) = decide_sorted(&first, lanes::sorted(&first, 1.0));
        assert_eq!(sorted.done.lanes(), [true, false, true, false]);
        assert_eq!(open.lanes(), [false, true, false, false]);
        let x = decide_quotients(&r4, &q4);
        assert_eq!(x.two.lanes(), [true, false, false, false]);
        assert_eq!(x.one.lanes(), [false, true, false, false]);
        assert_eq!(x.all.lanes(), [false, false, false, true]);
        assert_eq!(x.done.lanes(), [true; 4]);
        assert_eq!(intersect_baseline(&r4, &q4).lanes(), want);
        assert_eq!(intersect(&r4, &q4).lanes(), want);
        // With no lane of two roots or one, the filter's classes alone.
        let (r4, q4) = (
            Ray4::from_rays([rays[2], rays[3], rays[3], rays[2]]),
            Quadric4::from_quadrics([bowl, plane, plane, bowl]),
        );
        let x = decide_quotients(&r4, &q4);
        assert_eq!(x.all.lanes(), [false, true, true, false]);
        assert_eq!(x.done.lanes(), [true; 4]);
        let want = [want[2], want[3], want[3], want[2]];
        assert_eq!(intersect_baseline(&r4, &q4).lanes(), want);
    }

    /// Under FTZ, DAZ and both, a packet with no subnormal ray component
    /// keeps the fast path, one packet at a time or in pairs: the same bits
    /// as without, and no packet sent to the scalar stages. The
    /// coefficients, widened exactly when packed, meet DAZ nowhere, so a
    /// subnormal there changes nothing either. A subnormal in any of the
    /// rays' vectors sends its packet to the scalar stages under DAZ alone,
    /// with the same bits again; among them a direction whose one nonzero
    /// component is subnormal, from inside, whose roots are ±∞ once
    /// rounded, where DAZ would read no line at all.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn packets_keep_the_fast_path_unless_daz_meets_a_subnormal_input() {
        use crate::num::paths::{Paths, assert_packets_keep_their_paths, fan, with_subnormal_rays};
        use crate::num::real::Pair;
        use glam::Vec3;
        fn bits(h: QuadricHit4) -> [[i32; 4]; 3] {
            [h.class, cast(h.t0), cast(h.t1)].map(|v: i32x4| v.to_array())
        }
        fn batch(rays: &[Ray4], q: &Quadric4, pairs: bool) -> Vec<[[i32; 4]; 3]> {
            let mut out = vec![QuadricHit4::MISS; rays.len()];
            if pairs {
                packets_in::<Pair<F64x4>>(rays, q, &mut out);
            } else {
                intersect_packets(rays, q, &mut out);
            }
            out.into_iter().map(bits).collect()
        }
        let paths: Paths<Quadric4, [[i32; 4]; 3]> = [
            |r, q| r.iter().map(|r| bits(intersect(r, q))).collect(),
            |r, q| r.iter().map(|r| bits(intersect_baseline(r, q))).collect(),
            |r, q| batch(r, q, false),
            |r, q| batch(r, q, true),
        ];
        // From (0, 0.3, −4) at the unit sphere: hits and misses.
        let ball = Quadric::new([1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
        let rays = fan(Vec3::new(0.0, 0.3, -4.0), |i, j| {
            Vec3::new(
                (i % 4 * 4 + j) as f32 / 16.0 - 0.5,
                (i / 4) as f32 / 4.0 - 0.5,
                1.0,
            )
        });
        let q = Quadric4::splat(&ball);
        assert!(
            rays.iter()
                .any(|r| intersect(r, &q).class.to_array().contains(&TWO))
        );
        let mut k = ball.coeffs;
        (k[3], k[6], k[8]) = (1e-40, -1e-40, 3e-39);
        let odd = Quadric4::from_quadrics([ball, Quadric::new(k), ball, Quadric::new(k)]);
        let lone = crate::Ray::new(Vec3::new(0.0, 0.5, 0.0), Vec3::X * 1e-40);
        let want = QuadricHit::Two(f32::NEG_INFINITY, f32::INFINITY);
        assert_eq!(reference::intersect(&lone, &ball), want);
        let dirty: Vec<_> = with_subnormal_rays(&rays, lone)
            .into_iter()
            .map(|r| (r, q))
            .collect();
        assert_packets_keep_their_paths(paths, &[(rays.clone(), q), (rays, odd)], &dirty);
    }
}
