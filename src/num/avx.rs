//! Four `f64` lanes in one AVX register, for the x4 kernels' run-time
//! dispatch on x86-64.
//!
//! A default build targets baseline x86-64 (SSE2), where
//! [`F64x4`](super::real::F64x4) is two 128-bit registers. The x4 kernels
//! also compile a second copy of themselves over `Avx4` inside a
//! `#[target_feature(enable = "avx2,fma")]` function, and take it when
//! [`Avx2::detect`] finds the features at run time. Every operation of
//! [`Real`] is still one correctly rounded IEEE-754 operation per lane
//! (no FMA contraction: a product and a sum stay two roundings), so both
//! copies give the same bits.
//!
//! In the kernels bench (`cargo bench --bench kernels`, default build,
//! 4,096 jittered primary rays of a 64×64 camera, AMD EPYC with AVX2, one
//! run on a shared machine), one packet per call gave, in Mrays/s, for
//! this copy (`x4/packed`) against the SSE2 one (`x4/baseline`): plane
//! 200.7 against 144.0, sphere 79.4 against 57.7, quadric 65.2 against
//! 48.2; and two packets per step (`x4/batch`): plane 317.4, sphere 121.0,
//! quadric 81.4. That is what the `unsafe` blocks of this module and of
//! the x4 entry points buy.
//!
//! `Avx4` is crate-private: its [`Real`] methods run AVX instructions
//! without a target feature of their own, so they may only run inside a
//! function that was entered with an [`Avx2`] token. The crate names the
//! type only in such functions (the `x4::intersect_avx2` entry points).
//!
//! ```
//! use rayoracle::num::avx::Avx2;
//! // Some on any x86-64 CPU since Haswell (2013) or Excavator (2015).
//! let _: Option<Avx2> = Avx2::detect();
//! ```

use super::real::{Real, Real4};
use core::arch::x86_64::*;
use core::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};
use core::sync::atomic::{AtomicU8, Ordering};
use wide::bytemuck::cast;
use wide::{f32x4, i32x4};

/// Proof that the running CPU has AVX2 and FMA: only [`Avx2::detect`]
/// makes one.
#[derive(Clone, Copy, Debug)]
pub struct Avx2(());

impl Avx2 {
    /// The token, where the CPU has AVX2 and FMA (and the OS saves the
    /// AVX registers). The answer is cached in one byte: a load and a
    /// comparison per call, where the standard library's cache, asked for
    /// two features, takes two loads and four tests.
    ///
    /// ```
    /// let on = rayoracle::num::avx::Avx2::detect().is_some();
    /// assert_eq!(on, is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma"));
    /// ```
    #[inline(always)]
    pub fn detect() -> Option<Avx2> {
        match DETECTED.load(Ordering::Relaxed) {
            YES => Some(Avx2(())),
            NO => None,
            _ => Avx2::detect_first(),
        }
    }

    /// [`Avx2::detect`]'s first call: asks the standard library, and keeps
    /// the answer.
    #[cold]
    #[inline(never)]
    fn detect_first() -> Option<Avx2> {
        let on = is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma");
        DETECTED.store(if on { YES } else { NO }, Ordering::Relaxed);
        on.then_some(Avx2(()))
    }
}

/// [`Avx2::detect`]'s answer once known: [`YES`], [`NO`], or 0 before the
/// first call. A race stores the same answer twice.
static DETECTED: AtomicU8 = AtomicU8::new(0);
const YES: u8 = 2;
const NO: u8 = 1;

/// Four `f64` lanes in one `__m256d`. Crate-private: see the module
/// documentation for the rule that makes its `unsafe` blocks sound.
/// (Only the primitive kinds' x4 kernels use it: a camera-only build has
/// none.)
#[derive(Clone, Copy, Debug)]
#[cfg_attr(
    not(any(feature = "plane", feature = "sphere", feature = "quadric")),
    allow(dead_code)
)]
pub(crate) struct Avx4(__m256d);

/// Four lane masks of `Avx4`, all ones or all zeros per lane.
#[derive(Clone, Copy, Debug)]
#[cfg_attr(
    not(any(feature = "plane", feature = "sphere", feature = "quadric")),
    allow(dead_code)
)]
pub(crate) struct AvxMask(__m256d);

impl Avx4 {
    /// The register, for the AVX-512 lanes' halves.
    #[inline(always)]
    #[cfg_attr(not(feature = "quadric"), allow(dead_code))]
    pub(super) fn raw(self) -> __m256d {
        self.0
    }
    /// Four lanes from a register.
    #[inline(always)]
    #[cfg_attr(not(feature = "quadric"), allow(dead_code))]
    pub(super) fn from_raw(x: __m256d) -> Avx4 {
        Avx4(x)
    }
}

impl AvxMask {
    /// Four masks from a register of all-ones or all-zeros lanes.
    #[inline(always)]
    #[cfg_attr(not(feature = "quadric"), allow(dead_code))]
    pub(super) fn from_raw(x: __m256d) -> AvxMask {
        AvxMask(x)
    }
}

/// Runs AVX intrinsics from a method of `Avx4`.
///
/// `unsafe` is needed because trait methods cannot carry
/// `#[target_feature]`; they are `#[inline(always)]` and the crate calls
/// them only inside `#[target_feature(enable = "avx2,fma")]` functions
/// entered with an [`Avx2`] token, so the instructions exist on the CPU
/// that runs them.
macro_rules! avx {
    ($e:expr) => {
        // SAFETY: AVX2 and FMA were detected (an `Avx2` token exists, see
        // the macro's documentation). Justified by the kernels bench
        // figures in the module documentation (x4/packed against
        // x4/baseline, e.g. plane 200.7 against 144.0 Mrays/s).
        unsafe { $e }
    };
}

macro_rules! lanewise {
    ($tr:ident, $f:ident, $op:ident) => {
        impl $tr for Avx4 {
            type Output = Avx4;
            #[inline(always)]
            fn $f(self, o: Avx4) -> Avx4 {
                Avx4(avx!($op(self.0, o.0)))
            }
        }
    };
}
lanewise!(Add, add, _mm256_add_pd);
lanewise!(Sub, sub, _mm256_sub_pd);
lanewise!(Mul, mul, _mm256_mul_pd);
lanewise!(Div, div, _mm256_div_pd);

impl Avx4 {
    /// Four lanes from values in registers, lowest first: built there,
    /// not stored and loaded back, which would stall store forwarding.
    #[inline(always)]
    #[cfg_attr(not(feature = "quadric"), allow(dead_code))]
    pub(crate) fn new(a: f64, b: f64, c: f64, d: f64) -> Avx4 {
        Avx4(avx!(_mm256_set_pd(d, c, b, a)))
    }
    /// The lanes, lowest first.
    #[inline(always)]
    #[cfg_attr(not(feature = "quadric"), allow(dead_code))]
    pub(crate) fn to_array(self) -> [f64; 4] {
        cast::<__m256d, [f64; 4]>(self.0)
    }
    /// `self·b − c`, rounded once (a fused multiply-subtract).
    #[inline(always)]
    #[cfg_attr(not(feature = "quadric"), allow(dead_code))]
    pub(crate) fn mul_sub(self, b: Avx4, c: Avx4) -> Avx4 {
        Avx4(avx!(_mm256_fmsub_pd(self.0, b.0, c.0)))
    }
}

impl Neg for Avx4 {
    type Output = Avx4;
    #[inline(always)]
    fn neg(self) -> Avx4 {
        Avx4(avx!(_mm256_xor_pd(self.0, _mm256_set1_pd(-0.0))))
    }
}

impl BitAnd for AvxMask {
    type Output = AvxMask;
    #[inline(always)]
    fn bitand(self, o: AvxMask) -> AvxMask {
        AvxMask(avx!(_mm256_and_pd(self.0, o.0)))
    }
}

impl BitOr for AvxMask {
    type Output = AvxMask;
    #[inline(always)]
    fn bitor(self, o: AvxMask) -> AvxMask {
        AvxMask(avx!(_mm256_or_pd(self.0, o.0)))
    }
}

impl Not for AvxMask {
    type Output = AvxMask;
    #[inline(always)]
    fn not(self) -> AvxMask {
        let ones = avx!(_mm256_castsi256_pd(_mm256_set1_epi64x(-1)));
        AvxMask(avx!(_mm256_xor_pd(self.0, ones)))
    }
}

impl Real for Avx4 {
    const FEW_DIVISIONS: bool = true;
    #[inline(always)]
    fn denormals_are_zero() -> bool {
        crate::num::certify::daz_probe::<true>()
    }
    #[inline(always)]
    fn least_subnormal() -> Avx4 {
        Self::splat(crate::num::certify::least_subnormal::<true>())
    }
    type Mask = AvxMask;
    #[inline(always)]
    fn splat(x: f64) -> Avx4 {
        Avx4(avx!(_mm256_set1_pd(x)))
    }
    #[inline(always)]
    fn sqrt(self) -> Avx4 {
        Avx4(avx!(_mm256_sqrt_pd(self.0)))
    }
    #[inline(always)]
    fn abs(self) -> Avx4 {
        Avx4(avx!(_mm256_andnot_pd(_mm256_set1_pd(-0.0), self.0)))
    }
    #[inline(always)]
    fn copysign(self, sign: Avx4) -> Avx4 {
        let s = avx!(_mm256_set1_pd(-0.0));
        let mag = avx!(_mm256_andnot_pd(s, self.0));
        Avx4(avx!(_mm256_or_pd(mag, _mm256_and_pd(sign.0, s))))
    }
    #[inline(always)]
    fn gt(self, other: Avx4) -> AvxMask {
        AvxMask(avx!(_mm256_cmp_pd::<_CMP_GT_OQ>(self.0, other.0)))
    }
    #[inline(always)]
    fn eq(self, other: Avx4) -> AvxMask {
        AvxMask(avx!(_mm256_cmp_pd::<_CMP_EQ_OQ>(self.0, other.0)))
    }
    #[inline(always)]
    fn select(m: AvxMask, a: Avx4, b: Avx4) -> Avx4 {
        Avx4(avx!(_mm256_blendv_pd(b.0, a.0, m.0)))
    }
    #[inline(always)]
    fn same_f32(lo: Avx4, hi: Avx4) -> AvxMask {
        // Equal as floats (so no NaN) and as bits (so not −0 against +0),
        // compared as four f32 lanes; the mask is then widened by sign
        // extension.
        let (a, b) = avx!((_mm256_cvtpd_ps(lo.0), _mm256_cvtpd_ps(hi.0)));
        let bits = avx!(_mm_cmpeq_epi32(_mm_castps_si128(a), _mm_castps_si128(b)));
        let m = avx!(_mm_and_si128(bits, _mm_castps_si128(_mm_cmpeq_ps(a, b))));
        AvxMask(avx!(_mm256_castsi256_pd(_mm256_cvtepi32_epi64(m))))
    }
    #[inline(always)]
    fn off_midpoint(self, m: i64) -> AvxMask {
        avx!({
            let b = _mm256_sub_epi64(
                _mm256_castpd_si256(self.0),
                _mm256_set1_epi64x((1 << 28) - m),
            );
            let x = _mm256_and_si256(b, _mm256_set1_epi64x((1 << 29) - 1));
            AvxMask(_mm256_castsi256_pd(_mm256_cmpgt_epi64(
                x,
                _mm256_set1_epi64x(2 * m),
            )))
        })
    }
    #[inline(always)]
    fn equal_f32(lo: Avx4, hi: Avx4) -> AvxMask {
        let (a, b) = avx!((_mm256_cvtpd_ps(lo.0), _mm256_cvtpd_ps(hi.0)));
        let m = avx!(_mm_castps_si128(_mm_cmpeq_ps(a, b)));
        AvxMask(avx!(_mm256_castsi256_pd(_mm256_cvtepi32_epi64(m))))
    }
}

impl Real4 for Avx4 {
    #[inline(always)]
    fn load(x: &[f64; 4]) -> Avx4 {
        Avx4(avx!(_mm256_loadu_pd(x.as_ptr())))
    }
    #[inline(always)]
    fn widen(x: f32x4) -> Avx4 {
        Avx4(avx!(_mm256_cvtps_pd(cast::<f32x4, __m128>(x))))
    }
    #[inline(always)]
    fn narrow(self) -> f32x4 {
        cast::<__m128, f32x4>(avx!(_mm256_cvtpd_ps(self.0)))
    }
    #[inline(always)]
    fn mask_i32(m: AvxMask) -> i32x4 {
        // The low half of each 64-bit lane (all ones or all zeros).
        let (lo, hi) = avx!((
            _mm256_castps256_ps128(_mm256_castpd_ps(m.0)),
            _mm256_extractf128_ps::<1>(_mm256_castpd_ps(m.0))
        ));
        cast::<__m128, i32x4>(avx!(_mm_shuffle_ps::<0b10_00_10_00>(lo, hi)))
    }
    #[inline(always)]
    fn all(m: AvxMask) -> bool {
        avx!(_mm256_movemask_pd(m.0)) == 0b1111
    }
    #[inline(always)]
    fn blend_f32(m: i32x4, a: f32x4, b: f32x4) -> f32x4 {
        // One `blendvps`, which reads each lane's sign bit: the lanes of
        // `m` are all ones or all zeros.
        let (m, a, b) = (
            cast::<i32x4, __m128>(m),
            cast::<f32x4, __m128>(a),
            cast::<f32x4, __m128>(b),
        );
        cast::<__m128, f32x4>(avx!(_mm_blendv_ps(b, a, m)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::real::F64x4;

    #[target_feature(enable = "avx2,fma")]
    fn check_lanes() {
        let xs = [
            0.0,
            -0.0,
            1.0,
            -1.0,
            f64::NAN,
            1e-40,
            -1e-40,
            3.0,
            0.1,
            1e300,
        ];
        for &a in &xs {
            for &b in &xs {
                let (va, vb) = (Avx4::splat(a), Avx4::splat(b));
                let (wa, wb) = (F64x4::splat(a), F64x4::splat(b));
                let same = |x: Avx4, y: F64x4| {
                    x.narrow().to_array().map(f32::to_bits)
                        == y.narrow().to_array().map(f32::to_bits)
                        && cast::<__m256d, [u64; 4]>(x.0) == y.to_array().map(f64::to_bits)
                };
                let mask = |m: AvxMask| Avx4::mask_i32(m).to_array();
                let wmask = |m| F64x4::mask_i32(m).to_array();
                assert_eq!(mask(Avx4::same_f32(va, vb)), wmask(F64x4::same_f32(wa, wb)));
                assert_eq!(
                    mask(Avx4::equal_f32(va, vb)),
                    wmask(F64x4::equal_f32(wa, wb))
                );
                assert_eq!(mask(va.gt(vb)), wmask(wa.gt(wb)));
                assert_eq!(mask(!va.eq(vb)), wmask(!wa.eq(wb)));
                let m = (b.abs() * 1e3).min(1e8) as i64;
                assert_eq!(mask(va.off_midpoint(m)), wmask(wa.off_midpoint(m)));
                assert_eq!(mask(va.off_midpoint(m)), [-i32::from(a.off_midpoint(m)); 4]);
                assert_eq!(Avx4::all(va.eq(vb)), F64x4::all(wa.eq(wb)));
                for (x, y) in [
                    (va + vb, wa + wb),
                    (va - vb, wa - wb),
                    (va * vb, wa * wb),
                    (va / vb, wa / wb),
                    (-va, -wa),
                    (va.sqrt(), wa.sqrt()),
                    (va.abs(), wa.abs()),
                    (va.copysign(vb), wa.copysign(wb)),
                    (
                        Avx4::select(va.gt(vb), va, vb),
                        F64x4::select(wa.gt(wb), wa, wb),
                    ),
                ] {
                    assert!(same(x, y), "{a} {b}");
                }
            }
        }
        let s = Avx4::least_subnormal();
        assert_eq!(cast::<__m256d, [f64; 4]>(s.0), [2f64.powi(-149); 4]);
        let x = f32x4::from([0.1, -3.0, f32::from_bits(1), f32::MAX]);
        let y = Avx4::widen(x);
        let w = [1.0, 2.5, -7.0, 1e-30];
        assert_eq!(cast::<__m256d, [f64; 4]>(Avx4::load(&w).0), w);
        assert_eq!(cast::<__m256d, [f64; 4]>(y.0), x.to_array().map(f64::from));
        assert_eq!(y.narrow().to_array(), x.to_array());
        let (m, b) = (i32x4::from([-1, 0, 0, -1]), f32x4::splat(f32::NAN));
        let bits = |v: f32x4| v.to_array().map(f32::to_bits);
        assert_eq!(
            bits(Avx4::blend_f32(m, x, b)),
            bits(F64x4::blend_f32(m, x, b))
        );
        assert_eq!(
            bits(Avx4::blend_f32(m, x, b))[..2],
            [0.1f32.to_bits(), f32::NAN.to_bits()]
        );
    }

    /// The token exists exactly where the standard library sees AVX2 and
    /// FMA: on the first call, which asks it, and on every later one, from
    /// the cache, which holds the answer. (The test below runs only where
    /// it exists.)
    #[test]
    fn detect_agrees_with_the_standard_library() {
        let want = is_x86_feature_detected!("avx2") && is_x86_feature_detected!("fma");
        assert_eq!(Avx2::detect_first().is_some(), want);
        assert_eq!(
            DETECTED.load(Ordering::Relaxed),
            if want { YES } else { NO }
        );
        for _ in 0..3 {
            assert_eq!(Avx2::detect().is_some(), want);
        }
    }

    /// The AVX lanes' probe for denormals-are-zero sees the flag, as the
    /// baseline lanes' does, and is false without it.
    #[test]
    fn the_avx_probe_sees_denormals_are_zero() {
        if Avx2::detect().is_none() {
            return;
        }
        crate::num::certify::assert_probe_sees_daz::<Avx4>();
    }

    /// Every operation gives, lane by lane, the bits of the SSE2 lanes.
    #[test]
    fn avx_lanes_agree_with_the_baseline() {
        if Avx2::detect().is_some() {
            // SAFETY: AVX2 and FMA were just detected.
            unsafe { check_lanes() }
        }
    }
}
