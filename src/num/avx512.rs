//! Eight `f64` lanes in one AVX-512 register, for the quadric's batch
//! path (`intersect_packets`), chosen at run time on x86-64.
//!
//! The batch paths run two packets at a time as eight lanes
//! ([`Real8`]): on CPUs with AVX2 as a [`Pair`](super::real::Pair) of
//! `Avx4`, two 256-bit registers per value. Where [`Avx512::detect`]
//! finds AVX-512 (F, DQ and VL), they run on one 512-bit register,
//! `Avx8`, with their comparisons in mask registers, and finish each
//! packet on a 256-bit half. Every operation of [`Real`] is one correctly
//! rounded IEEE-754 operation per lane, as in [`super::avx`] (no FMA
//! contraction), so every copy gives the same bits.
//!
//! The `unsafe` blocks of this module and of the batch dispatch
//! (`num::batch`) are justified by the kernels bench (`cargo bench
//! --bench kernels`, default build, 4,096 jittered primary rays of a
//! 64×64 camera, shared machines). `x4/batch` took, its fastest
//! interleaved pass, on AVX-512 against pairs of AVX2 registers:
//!
//! * Intel Xeon with AVX-512, three runs each: the quadric 188.2, 188.3
//!   and 188.2 Mrays/s against 161.1, 160.8 and 141.6.
//! * AMD EPYC with AVX-512, where a 512-bit operation is two 256-bit
//!   ones, two runs each, alternated: the quadric 37.9 against 50.1 µs;
//!   the plane 10.0 against 9.5, the sphere 8.1 against 8.4 and,
//!   shuffled, 14.4 against 14.0, so within a few percent either way.
//!
//! The sphere's and the plane's batches skip AVX-512. The sphere's take
//! their lanes from the test for certain misses in `f32`: on the same
//! Xeon, two runs each, alternated, the medians of the interleaved
//! passes read 437 and 442 Mrays/s on AVX-512 against 525 and 528 on
//! pairs of AVX2 registers, and 359 and 367 against 451 and 458 on the
//! shuffled rays. The plane's, two runs each, alternated, read 673.6 and
//! 672.7 Mrays/s on AVX-512 against 695.9 and 692.1 on pairs (medians
//! 667.9 and 666.3 against 675.7 and 673.7); parry3d's `HalfSpace`,
//! timed after them, read 546.8 and 545.8 after the AVX-512 passes and
//! 588.6 and 588.5 after the pairs, as the CPU slows down for a while
//! after 512-bit work.
//!
//! `Avx8` is crate-private for the reason `Avx4` is: its methods run
//! AVX-512 instructions without a target feature of their own, so the
//! crate names it only inside functions compiled for
//! `avx512f,avx512dq,avx512vl,avx2,fma` and entered with an [`Avx512`]
//! token.
//!
//! ```
//! use rayoracle::num::avx512::Avx512;
//! let on = Avx512::detect().is_some();
//! assert!(!on || rayoracle::num::avx::Avx2::detect().is_some());
//! ```

use super::avx::{Avx2, Avx4, AvxMask};
use super::real::{Real, Real8};
use core::arch::x86_64::*;
use core::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};
use wide::bytemuck::cast;
use wide::f32x4;

/// Proof that the running CPU has AVX-512 F, DQ and VL, and AVX2 and
/// FMA: only [`Avx512::detect`] makes one.
#[derive(Clone, Copy, Debug)]
pub struct Avx512(());

impl Avx512 {
    /// The token, where the CPU has the features (and the OS saves the
    /// AVX-512 state). Cached by the standard library: a few loads and
    /// tests per call.
    ///
    /// ```
    /// let on = rayoracle::num::avx512::Avx512::detect().is_some();
    /// assert_eq!(on, is_x86_feature_detected!("avx512f") && is_x86_feature_detected!("avx512dq")
    ///     && is_x86_feature_detected!("avx512vl") && is_x86_feature_detected!("avx2")
    ///     && is_x86_feature_detected!("fma"));
    /// ```
    #[inline(always)]
    pub fn detect() -> Option<Avx512> {
        let on = is_x86_feature_detected!("avx512f")
            && is_x86_feature_detected!("avx512dq")
            && is_x86_feature_detected!("avx512vl");
        (on && Avx2::detect().is_some()).then_some(Avx512(()))
    }
}

/// Eight `f64` lanes in one `__m512d`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx8(__m512d);

/// Eight lane masks in one mask register.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Avx8Mask(__mmask8);

/// Runs AVX-512 intrinsics from a method of `Avx8`.
///
/// `unsafe` is needed because trait methods cannot carry
/// `#[target_feature]`; they are `#[inline(always)]` and the crate calls
/// them only inside `#[target_feature(enable =
/// "avx512f,avx512dq,avx512vl,avx2,fma")]` functions entered with an
/// [`Avx512`] token, so the instructions exist on the CPU that runs them.
macro_rules! avx512 {
    ($e:expr) => {
        // SAFETY: AVX-512 F, DQ and VL were detected (an `Avx512` token
        // exists, see the macro's documentation). Justified by the kernels
        // bench figures in the module documentation.
        unsafe { $e }
    };
}

macro_rules! lanewise {
    ($tr:ident, $f:ident, $op:ident) => {
        impl $tr for Avx8 {
            type Output = Avx8;
            #[inline(always)]
            fn $f(self, o: Avx8) -> Avx8 {
                Avx8(avx512!($op(self.0, o.0)))
            }
        }
    };
}
lanewise!(Add, add, _mm512_add_pd);
lanewise!(Sub, sub, _mm512_sub_pd);
lanewise!(Mul, mul, _mm512_mul_pd);
lanewise!(Div, div, _mm512_div_pd);

impl Neg for Avx8 {
    type Output = Avx8;
    #[inline(always)]
    fn neg(self) -> Avx8 {
        Avx8(avx512!(_mm512_xor_pd(self.0, _mm512_set1_pd(-0.0))))
    }
}

impl BitAnd for Avx8Mask {
    type Output = Avx8Mask;
    #[inline(always)]
    fn bitand(self, o: Avx8Mask) -> Avx8Mask {
        Avx8Mask(self.0 & o.0)
    }
}

impl BitOr for Avx8Mask {
    type Output = Avx8Mask;
    #[inline(always)]
    fn bitor(self, o: Avx8Mask) -> Avx8Mask {
        Avx8Mask(self.0 | o.0)
    }
}

impl Not for Avx8Mask {
    type Output = Avx8Mask;
    #[inline(always)]
    fn not(self) -> Avx8Mask {
        Avx8Mask(!self.0)
    }
}

impl Real for Avx8 {
    const FEW_DIVISIONS: bool = true;
    #[inline(always)]
    fn denormals_are_zero() -> bool {
        crate::num::certify::daz_probe::<true>()
    }
    #[inline(always)]
    fn least_subnormal() -> Avx8 {
        Self::splat(crate::num::certify::least_subnormal::<true>())
    }
    type Mask = Avx8Mask;
    #[inline(always)]
    fn splat(x: f64) -> Avx8 {
        Avx8(avx512!(_mm512_set1_pd(x)))
    }
    #[inline(always)]
    fn sqrt(self) -> Avx8 {
        Avx8(avx512!(_mm512_sqrt_pd(self.0)))
    }
    #[inline(always)]
    fn abs(self) -> Avx8 {
        Avx8(avx512!(_mm512_abs_pd(self.0)))
    }
    #[inline(always)]
    fn copysign(self, sign: Avx8) -> Avx8 {
        let s = avx512!(_mm512_set1_pd(-0.0));
        let mag = avx512!(_mm512_andnot_pd(s, self.0));
        Avx8(avx512!(_mm512_or_pd(mag, _mm512_and_pd(sign.0, s))))
    }
    #[inline(always)]
    fn gt(self, other: Avx8) -> Avx8Mask {
        Avx8Mask(avx512!(_mm512_cmp_pd_mask::<_CMP_GT_OQ>(self.0, other.0)))
    }
    #[inline(always)]
    fn eq(self, other: Avx8) -> Avx8Mask {
        Avx8Mask(avx512!(_mm512_cmp_pd_mask::<_CMP_EQ_OQ>(self.0, other.0)))
    }
    #[inline(always)]
    fn select(m: Avx8Mask, a: Avx8, b: Avx8) -> Avx8 {
        Avx8(avx512!(_mm512_mask_blend_pd(m.0, b.0, a.0)))
    }
    #[inline(always)]
    fn same_f32(lo: Avx8, hi: Avx8) -> Avx8Mask {
        // Equal as floats (so no NaN) and as bits (so not −0 against +0),
        // compared as eight f32 lanes.
        let (a, b) = avx512!((_mm512_cvtpd_ps(lo.0), _mm512_cvtpd_ps(hi.0)));
        let bits = avx512!(_mm256_cmpeq_epi32_mask(
            _mm256_castps_si256(a),
            _mm256_castps_si256(b)
        ));
        Avx8Mask(bits & avx512!(_mm256_cmp_ps_mask::<_CMP_EQ_OQ>(a, b)))
    }
    #[inline(always)]
    fn off_midpoint(self, m: i64) -> Avx8Mask {
        avx512!({
            let b = _mm512_sub_epi64(
                _mm512_castpd_si512(self.0),
                _mm512_set1_epi64((1 << 28) - m),
            );
            let x = _mm512_and_si512(b, _mm512_set1_epi64((1 << 29) - 1));
            Avx8Mask(_mm512_cmpgt_epi64_mask(x, _mm512_set1_epi64(2 * m)))
        })
    }
    #[inline(always)]
    fn equal_f32(lo: Avx8, hi: Avx8) -> Avx8Mask {
        let (a, b) = avx512!((_mm512_cvtpd_ps(lo.0), _mm512_cvtpd_ps(hi.0)));
        Avx8Mask(avx512!(_mm256_cmp_ps_mask::<_CMP_EQ_OQ>(a, b)))
    }
}

impl Real8 for Avx8 {
    type Half = Avx4;
    #[inline(always)]
    fn widen3(a: &[f32x4; 3], b: &[f32x4; 3]) -> [Avx8; 3] {
        let w = |x: f32x4, y: f32x4| {
            let (x, y) = (cast::<f32x4, __m128>(x), cast::<f32x4, __m128>(y));
            Avx8(avx512!(_mm512_cvtps_pd(_mm256_set_m128(y, x))))
        };
        [w(a[0], b[0]), w(a[1], b[1]), w(a[2], b[2])]
    }
    #[inline(always)]
    fn twice(x: Avx4) -> Avx8 {
        let x = x.raw();
        Avx8(avx512!(_mm512_insertf64x4::<1>(
            _mm512_castpd256_pd512(x),
            x
        )))
    }
    #[inline(always)]
    fn halves(self) -> [Avx4; 2] {
        let (lo, hi) = avx512!((
            _mm512_castpd512_pd256(self.0),
            _mm512_extractf64x4_pd::<1>(self.0)
        ));
        [Avx4::from_raw(lo), Avx4::from_raw(hi)]
    }
    #[inline(always)]
    fn mask_halves(m: Avx8Mask) -> [AvxMask; 2] {
        // Each mask bit as a lane of all ones or all zeros.
        let lanes = avx512!(_mm512_castsi512_pd(_mm512_movm_epi64(m.0)));
        let (lo, hi) = avx512!((
            _mm512_castpd512_pd256(lanes),
            _mm512_extractf64x4_pd::<1>(lanes)
        ));
        [AvxMask::from_raw(lo), AvxMask::from_raw(hi)]
    }
    #[inline(always)]
    fn all(m: Avx8Mask) -> bool {
        m.0 == 0xff
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::real::{F64x4, Pair, Real4};

    /// Every operation on AVX-512 lanes, halves and masks included, gives
    /// the bits of the same operation on a pair of baseline lanes.
    #[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2,fma")]
    fn check_lanes() {
        let xs = [0.1f32, -2.5, 1e-40, 3.0, 0.0, -0.0, 7.25, 1e30];
        let ys = [1.0f32, 2.5, -1e-40, 3.0, -0.0, 0.0, f32::NAN, 1e-30];
        let (x4, y4) = (
            f32x4::from([xs[0], xs[1], xs[2], xs[3]]),
            f32x4::from([xs[4], xs[5], xs[6], xs[7]]),
        );
        let (u4, v4) = (
            f32x4::from([ys[0], ys[1], ys[2], ys[3]]),
            f32x4::from([ys[4], ys[5], ys[6], ys[7]]),
        );
        let [a, b, _] = Avx8::widen3(&[x4, u4, x4], &[y4, v4, y4]);
        let [p, q, _] = Pair::<F64x4>::widen3(&[x4, u4, x4], &[y4, v4, y4]);
        // Bits, with every NaN alike (IEEE leaves a NaN's sign open).
        let key = |x: f32| if x.is_nan() { u32::MAX } else { x.to_bits() };
        let bits = |v: [Avx4; 2]| v.map(|h| h.narrow().to_array().map(key));
        let want = |v: Pair<F64x4>| [v.0, v.1].map(|h| h.narrow().to_array().map(key));
        let masks = |m: Avx8Mask| Avx8::mask_halves(m).map(|h| Avx4::mask_i32(h).to_array());
        let want_m =
            |m: Pair<crate::num::real::M4>| [m.0, m.1].map(|h| F64x4::mask_i32(h).to_array());
        assert_eq!(bits((a + b).halves()), want(p + q));
        assert_eq!(bits((a - b).halves()), want(p - q));
        assert_eq!(bits((a * b).halves()), want(p * q));
        assert_eq!(bits((a / b).halves()), want(p / q));
        assert_eq!(bits((-a).halves()), want(-p));
        assert_eq!(bits(a.abs().sqrt().halves()), want(p.abs().sqrt()));
        assert_eq!(bits(a.copysign(b).halves()), want(p.copysign(q)));
        assert_eq!(
            bits(Avx8::twice(a.halves()[1]).halves()),
            want(Pair::twice(p.1))
        );
        assert_eq!(masks(a.gt(b)), want_m(p.gt(q)));
        assert_eq!(masks(a.eq(b)), want_m(p.eq(q)));
        assert_eq!(
            masks(!a.gt(b) & a.eq(a) | b.gt(a)),
            want_m(!p.gt(q) & p.eq(p) | q.gt(p))
        );
        assert_eq!(masks(Avx8::same_f32(a, b)), want_m(Pair::same_f32(p, q)));
        assert_eq!(masks(Avx8::same_f32(a, a)), want_m(Pair::same_f32(p, p)));
        assert_eq!(masks(Avx8::equal_f32(a, b)), want_m(Pair::equal_f32(p, q)));
        let m = a.gt(b);
        assert_eq!(
            bits(Avx8::select(m, a, b).halves()),
            want(Pair::select(p.gt(q), p, q))
        );
        // At, near and far from f32 midpoints.
        let mid = 1.0 + 2f64.powi(-24);
        let w = [mid, mid + 2f64.powi(-46), 0.1, -(3.0 + 2f64.powi(-23))];
        let (c, r) = (Avx8::twice(Avx4::load(&w)), Pair::twice(F64x4::load(&w)));
        for m in [0, 63, 64, 1 << 20, 1 << 27] {
            assert_eq!(masks(c.off_midpoint(m)), want_m(r.off_midpoint(m)), "{m}");
        }
        assert_eq!(masks(c.off_midpoint(63))[0], [0, -1, -1, 0]);
        assert_eq!(masks(c.off_midpoint(64))[0], [0, 0, -1, 0]);
        assert_eq!(bits(Avx8::least_subnormal().halves()), [[1; 4]; 2]);
        // A mask of every lane, and one of some.
        assert!(Avx8::all(a.eq(a) | !a.eq(a)) && Pair::<F64x4>::all(p.eq(p) | !p.eq(p)));
        assert!(!Avx8::all(a.gt(b)) && !Pair::<F64x4>::all(p.gt(q)));
    }

    /// The token exists exactly where the standard library sees the
    /// features, AVX2 and FMA among them.
    #[test]
    fn detect_agrees_with_the_standard_library() {
        let want = is_x86_feature_detected!("avx512f")
            && is_x86_feature_detected!("avx512dq")
            && is_x86_feature_detected!("avx512vl")
            && is_x86_feature_detected!("avx2")
            && is_x86_feature_detected!("fma");
        assert_eq!(Avx512::detect().is_some(), want);
    }

    /// The AVX-512 lanes' probe for denormals-are-zero sees the flag, as
    /// the baseline lanes' does, and is false without it.
    #[test]
    fn the_avx512_probe_sees_denormals_are_zero() {
        if Avx512::detect().is_none() {
            return;
        }
        crate::num::certify::assert_probe_sees_daz::<Avx8>();
    }

    #[test]
    fn avx512_lanes_match_the_baseline() {
        if Avx512::detect().is_some() {
            // SAFETY: the features were detected just above.
            unsafe { check_lanes() }
        }
    }
}
