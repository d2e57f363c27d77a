//! Certified rounding: the `f32` a real number rounds to, from an f64
//! approximation `t` and a proven bound `e ≥ |t − x|` on its error.
//!
//! Rounding to `f32` is monotone, so if both ends of `[t − e, t + e]` round
//! to the same `f32`, so does every real in between, the exact `x`
//! included. That one test covers subnormal results, ±0 (the two zeros have
//! different bits, so an enclosure that straddles 0 is never certified) and
//! overflow to ±∞ without special cases; a NaN anywhere fails it.
//!
//! The bound comes in two parts, `e = |t|·r + a`: a relative part `r`,
//! which the kernels can often work out before `t` itself, and an absolute
//! part `a`. `certify` adds `2⁻⁵¹` to `r`, `w = r + 2⁻⁵¹`, and computes
//! the ends in f64, rounded to nearest, as `t(1 − w) − a'` and `t(1 + w) +
//! a'` with `a' = a` carrying the sign of `t`: for `t > 0` the lower and
//! upper ends, for `t < 0` the upper and lower, and neither waits on a sum
//! `|t|w + a`, which would lengthen the chain of dependent operations
//! after `t` by two. Where the test can pass, `|t|w + a < 2⁻²²|t|`: a
//! wider enclosure holds 0 or an f32 midpoint far inside it, and so do the
//! computed ends. There each end is within `3.02·2⁻⁵³|t|` of `t(1 ∓ w) ∓
//! a'`, so on the outer side of `t(1 ∓ r) ∓ a'`: the roundings of `1 ∓ w`,
//! the product and the sum are covered by the `2⁻⁵¹ = 4·2⁻⁵³`. The kernels
//! widen `r` and `a` by `1 + 2⁻³⁰`, which covers the roundings of the few
//! dozen operations that evaluate them.
//!
//! A bound relative alone, `e = |t|·r` with `|t|` in `f32`'s normal range,
//! is certified from `t`'s bits instead ([`certify_relative`]): the
//! midpoints between neighbouring `f32` values are the f64 values whose 29
//! dropped bits are `0x1000_0000`, and the enclosure spans at most
//! about `r·2⁵³` bit patterns on either side of `t`'s. Three integer operations,
//! exact, replace two products, two conversions and a comparison.

use super::real::{Real, Real4};

/// The unit roundoff of f64, `u = 2⁻⁵³`.
pub const U: f64 = f64::EPSILON / 2.0;

/// The relative slack every bound is widened by, `1 + 2⁻³⁰`.
pub const SLACK: f64 = 1.0 + 1.0 / (1u64 << 30) as f64;

/// Whether every real within `|t|·r + a` of `t` rounds to one `f32`, lane
/// by lane; where it does, that `f32` is `t as f32`. `r` and `a` must be
/// non-negative (or NaN, which certifies nothing).
///
/// ```
/// use rayoracle::num::certify::certify;
/// // 1/3 to within 1e-12: every such real rounds to 1/3f32.
/// assert!(certify(1.0 / 3.0, 0.0, 1e-12));
/// // Within 2⁻⁴⁰ relatively: the same.
/// assert!(certify(1.0 / 3.0, 2f64.powi(-40), 0.0));
/// // Straddling the midpoint between 1 and the next f32: undecided.
/// let mid = 1.0 + f32::EPSILON as f64 / 2.0;
/// assert!(!certify(mid, 0.0, 1e-12));
/// // Straddling 0: +0 and −0 differ.
/// assert!(!certify(0.0, 0.0, 1e-300));
/// assert!(certify(0.0, 0.0, 0.0));
/// assert!(!certify(f64::NAN, 0.0, 0.0) && !certify(1.0, f64::NAN, 0.0));
/// ```
#[inline(always)]
pub fn certify<L: Real>(t: L, r: L, a: L) -> L::Mask {
    certify_end(t, r, a).0
}

/// [`certify`], and the first end of the enclosure, which rounds to
/// `t`'s `f32` wherever the mask is set: a caller that narrows it, rather
/// than `t`, shares the conversion [`certify`] makes anyway.
///
/// ```
/// use rayoracle::num::certify::{certify, certify_end};
/// let (ok, end) = certify_end(-1.0 / 3.0, 2f64.powi(-40), 1e-15);
/// assert!(ok && ok == certify(-1.0 / 3.0, 2f64.powi(-40), 1e-15));
/// assert_eq!(end as f32, -1.0f32 / 3.0);
/// ```
#[inline(always)]
pub fn certify_end<L: Real>(t: L, r: L, a: L) -> (L::Mask, L) {
    let (one, w) = (L::splat(1.0), r + L::splat(2f64.powi(-51)));
    let a = a.copysign(t);
    let lo = t * (one - w) - a;
    (L::same_f32(lo, t * (one + w) + a), lo)
}

/// [`certify_end`] on four lanes, with the answer in `f32` lanes, for
/// results that must also be normal: the mask as `i32` lanes (−1 where
/// both ends of the enclosure round to one `f32` that is normal or
/// infinite) and the first end rounded to `f32`, which is `t`'s correctly
/// rounded value wherever the mask is set. The ends are [`certify_end`]'s;
/// their `f32` values are compared as bits (so not −0 against +0), and
/// the first must be at least `f32::MIN_POSITIVE` in magnitude, an
/// ordered comparison that also fails for NaN. A lane whose result would
/// be 0 or subnormal ([`flush_prone4`]) is left undecided, so a caller
/// whose results must be checked against flush-to-zero has nothing left
/// to check in the lanes set. The mask stays in the `f32` lanes the test
/// compares: a caller that wants `f32` results neither widens it to
/// 64-bit lanes nor narrows it back.
///
/// ```
/// use rayoracle::num::certify::{certify, certify_normal4};
/// use rayoracle::num::real::{F64x4, Real};
/// let t = F64x4::from([1.0 / 3.0, 1.0 + f32::EPSILON as f64 / 2.0, -0.1, f64::NAN]);
/// let (r, a) = (F64x4::splat(2f64.powi(-40)), F64x4::splat(1e-15));
/// let (ok, end) = certify_normal4(t, r, a);
/// assert_eq!(ok.to_array(), [-1, 0, -1, 0]);
/// assert_eq!(ok.to_array().map(|m| m != 0), certify(t, r, a).lanes());
/// assert_eq!(end.to_array()[0], 1.0f32 / 3.0);
/// assert_eq!(end.to_array()[2], -0.1f32);
/// // Certified by `certify`, but 0 and subnormal: left undecided here.
/// let t = F64x4::from([0.0, 1e-40, -1e-39, f32::MAX as f64 * 4.0]);
/// let (z, a) = (F64x4::splat(0.0), F64x4::splat(0.0));
/// assert_eq!(certify(t, z, a).lanes(), [true; 4]);
/// assert_eq!(certify_normal4(t, z, a).0.to_array(), [0, 0, 0, -1]);
/// ```
#[inline(always)]
pub fn certify_normal4<L: Real4>(t: L, r: L, a: L) -> (wide::i32x4, wide::f32x4) {
    use wide::bytemuck::cast;
    let (one, w) = (L::splat(1.0), r + L::splat(2f64.powi(-51)));
    let a = a.copysign(t);
    let (lo, hi) = ((t * (one - w) - a).narrow(), (t * (one + w) + a).narrow());
    let bits = cast::<_, wide::i32x4>(lo).simd_eq(cast::<_, wide::i32x4>(hi));
    let normal = lo.abs().simd_ge(wide::f32x4::splat(f32::MIN_POSITIVE));
    (bits & cast::<_, wide::i32x4>(normal), lo)
}

/// [`certify`] with a relative bound alone, `e = |t|·r`, read from `t`'s
/// bits: whether every value within `e` of `t` rounds to `t`'s `f32`.
/// `t` must be 0, or finite with `|t| ≥ 2⁻¹²⁶`, where the caller uses
/// the mask, and `r < 2⁻³⁰`.
///
/// Rounding to the nearest `f32` is monotone, and changes value only at
/// the midpoints between neighbouring `f32` values. From `2⁻¹²⁶` up, an
/// f64 is a midpoint exactly where the 29 bits that rounding drops are
/// `0x1000_0000`, half an `f32` ulp (past `f32::MAX` every value rounds
/// to ∞, and the midpoints there change nothing). Positive f64 values
/// are ordered as their bit patterns. With `2ᵏ ≤ |t| < 2ᵏ⁺¹`, an f64 ulp
/// is `2ᵏ⁻⁵²` in `t`'s binade, so `[|t|, |t| + e]` spans fewer than
/// `e/2ᵏ⁻⁵² < r·2⁵³` patterns (fewer still past `2ᵏ⁺¹`, where ulps
/// double), and so does `[|t| − e, |t|]` while it stays above `2ᵏ`. One
/// that crosses below, where ulps are half as large, spans at most
/// `2e/2ᵏ⁻⁵²` patterns, and crossing needs `|t| − 2ᵏ < e`, so `|t| <
/// 2ᵏ(1 + 2r)`: at most `r·2⁵³(1 + 2r)`, below `r·2⁵³ + 1`. So where `t`'s
/// last 29 bits are more than `m = ⌊r·2⁵³⌋ + 3` (at least `⌈r·2⁵³⌉ + 2`;
/// a truncating conversion, where `ceil` is a library call in a baseline
/// x86-64 build) from `0x1000_0000` (modulo `2²⁹`), no midpoint lies in
/// the enclosure, and every value in it rounds as `t` does. The test is
/// three exact integer operations ([`Real::off_midpoint`]), with no
/// rounding of its own, and waits on nothing but `t`. An exact 0
/// certifies (`e = 0`).
///
/// ```
/// use rayoracle::num::certify::{certify, certify_relative};
/// assert!(certify_relative(1.0 / 3.0, 2f64.powi(-40)));
/// assert_eq!(certify_relative(0.1, 2f64.powi(-30)), certify(0.1, 2f64.powi(-30), 0.0));
/// assert!(certify_relative(0.0, 2f64.powi(-30)) && certify_relative(-2.0, 2f64.powi(-30)));
/// let mid = 1.0 + f32::EPSILON as f64 / 2.0;
/// assert!(!certify_relative(mid, 2f64.powi(-50)) && !certify_relative(-mid, 2f64.powi(-50)));
/// // Just below a midpoint: certified while the enclosure stays below it.
/// let below = mid - 2f64.powi(-40);
/// assert!(certify_relative(below, 2f64.powi(-44)) && !certify_relative(below, 2f64.powi(-39)));
/// ```
#[inline(always)]
pub fn certify_relative<L: Real>(t: L, r: f64) -> L::Mask {
    t.off_midpoint((r * 2f64.powi(53)) as i64 + 3)
}

/// The bound on a quotient, in the two parts [`certify`] takes. For `t̂ =
/// x̂·(1/ŷ)`, with `|x̂ − x| ≤ ex`, `|ŷ − y| ≤ ey` and `iy` within a few `u`
/// of `1/ŷ`: `|x̂/ŷ − x/y| ≤ (|x̂/ŷ| w + ex/|ŷ|) / (1 − w)` with `w =
/// ey/|ŷ|`. Certified only where `w < 1/4`, with `1/(1 − w)` bounded by
/// `1 + 2w`; `round` is the relative part for the roundings of `t̂` itself.
/// Every part is widened by [`SLACK`]. Returns `(r, a)`, `r` infinite where
/// `w ≥ 1/4` (or NaN).
///
/// ```
/// use rayoracle::num::certify::{U, certify, quotient_bound};
/// // 1/3 from x = 1 ± 0 and y = 3 ± 1e-300.
/// let (r, a) = quotient_bound(1e-300, 0.0, 1.0 / 3.0, 2.0 * U);
/// assert!(certify(1.0 / 3.0, r, a));
/// // y known only to within a third of itself: nothing certified.
/// let (r, _) = quotient_bound(1.0, 0.0, 1.0 / 3.0, 2.0 * U);
/// assert_eq!(r, f64::INFINITY);
/// ```
#[inline(always)]
pub fn quotient_bound<L: Real>(ey: L, ex: L, iy: L, round: f64) -> (L, L) {
    let (one, slack) = (L::splat(1.0), L::splat(SLACK));
    let iya = iy.abs();
    let w = ey * iya * slack;
    let g = (one + w + w) * slack;
    let r = L::select(
        L::splat(0.25).gt(w),
        w * g + L::splat(round),
        L::splat(f64::INFINITY),
    );
    (r, ex * iya * g)
}

/// `x / y` for a quotient that is certified next: `+0` where `x` is 0,
/// since an exact zero rounds to `+0` whatever the signs, and IEEE's own
/// sign elsewhere, which a quotient keeps even where it underflows to 0
/// (the tiny negative quotient's correctly rounded `f32` is `−0`, which
/// `x / y + 0.0` would turn into `+0`).
///
/// ```
/// use rayoracle::num::certify::div;
/// assert_eq!(div(0.0, -3.0).to_bits(), 0.0f64.to_bits());
/// assert_eq!(div(-0.0, 3.0).to_bits(), 0.0f64.to_bits());
/// assert_eq!(div(-1e-300, 1e300).to_bits(), (-0.0f64).to_bits());
/// assert_eq!(div(1.0, 4.0), 0.25);
/// ```
#[inline(always)]
pub fn div(x: f64, y: f64) -> f64 {
    if x == 0.0 { 0.0 } else { x / y }
}

/// Whether the floating-point environment keeps subnormals: false when
/// flush-to-zero (FTZ) or denormals-are-zero (DAZ) is on, as some renderers
/// and audio engines set it. The filters' bounds assume IEEE-754 gradual
/// underflow (an f32 subnormal input, an f64 → f32 subnormal result), so
/// the kernels check this wherever [`needs_probe`] says it matters and,
/// when it fails, take the exact path, whose arithmetic is on integers and
/// unaffected.
///
/// On x86-64 this reads the two flags from the SSE control register
/// (MXCSR): a few cycles. Elsewhere it is [`subnormals_survive`], which
/// computes with a subnormal and costs far more.
///
/// ```
/// // A default Rust program runs with both off.
/// assert!(rayoracle::num::certify::subnormals_work());
/// ```
#[inline(always)]
pub fn subnormals_work() -> bool {
    #[cfg(target_arch = "x86_64")]
    {
        /// MXCSR's flush-to-zero and denormals-are-zero bits.
        const FTZ_DAZ: u32 = 1 << 15 | 1 << 6;
        let mut csr: u32 = 0;
        // SAFETY: `stmxcsr` stores the 32-bit MXCSR register, which every
        // x86-64 CPU has, to the address given: `csr`, a live, aligned,
        // writable u32. It writes nothing else and changes no flags. The
        // arithmetic probe it replaces computes with a subnormal, which
        // costs a microcode assist on every call: with it, the kernels
        // bench (4,096 primary rays; two runs minutes apart) gave 38.3 Mrays/s for the
        // sphere reference, 23.3 for the plane's and 64.8 for x4's sphere,
        // against 83.1, 69.9 and 88.5 with this.
        unsafe {
            core::arch::asm!(
                "stmxcsr [{}]",
                in(reg) &mut csr,
                options(nostack, preserves_flags)
            );
        }
        csr & FTZ_DAZ == 0
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        subnormals_survive()
    }
}

/// Whether denormals-are-zero (DAZ) is on: the one way the environment
/// reaches an input. A subnormal `f32` input is exact in f64, and every
/// intermediate of the filters stays far above f64's subnormals
/// ([`needs_probe`]), so flush-to-zero alone changes no value before the
/// result's rounding to `f32`; DAZ alone reads a subnormal input as 0. The
/// scalar kernels test this, and only where it is on scan their inputs
/// for a subnormal, rather than scanning every input of every call.
///
/// On x86-64 this converts the least subnormal `f32` to f64, in inline
/// assembly so that the conversion runs under the current MXCSR whatever
/// the optimiser knows; DAZ makes it 0. Elsewhere it is
/// [`subnormals_survive`].
///
/// ```
/// // A default Rust program runs with DAZ off.
/// assert!(!rayoracle::num::certify::denormals_are_zero());
/// ```
#[inline(always)]
pub fn denormals_are_zero() -> bool {
    daz_probe::<{ cfg!(target_feature = "avx") }>()
}

/// [`denormals_are_zero`], its conversion VEX-encoded where `VEX` (for
/// code compiled with AVX, where a legacy SSE instruction that meets the
/// dirty upper halves of the vector registers costs a state transition or
/// a false dependency on some Intel cores).
#[inline(always)]
pub(crate) fn daz_probe<const VEX: bool>() -> bool {
    least_subnormal::<VEX>().to_bits() == 0
}

/// The least subnormal `f32`, `2⁻¹⁴⁹`, converted to f64 at run time,
/// VEX-encoded where `VEX`: 0 under denormals-are-zero. A kernel that
/// multiplies a comparison's side by it certifies nothing there, with no
/// branch of its own ([`crate::plane::stages::filter_relative`]).
///
/// ```
/// assert_eq!(rayoracle::num::certify::least_subnormal::<false>(), 2f64.powi(-149));
/// ```
#[inline(always)]
pub fn least_subnormal<const VEX: bool>() -> f64 {
    #[cfg(target_arch = "x86_64")]
    {
        let (x, mut y) = (f32::from_bits(1), 0.0f64);
        // SAFETY: one conversion between two XMM registers, SSE2 (which
        // every x86-64 CPU has) or, where `VEX`, AVX, which only code
        // compiled for AVX asks for; it reads and writes no memory,
        // touches no flags but MXCSR's sticky exception bits, and needs no
        // stack. Not `pure`: its result depends on MXCSR, so it must run
        // where it is written. It replaces a scan of every input for a
        // subnormal on every call of the scalar kernels: in the kernels
        // bench (`reference/per-ray`, 4,096 primary rays, default build,
        // two runs within the hour), the sphere's reference went from
        // 100.3 to 122.3 Mrays/s and the plane's from 83.0 to 100.4.
        unsafe {
            if VEX {
                core::arch::asm!(
                    "vcvtss2sd {y}, {y}, {x}",
                    x = in(xmm_reg) x,
                    y = inout(xmm_reg) y,
                    options(nomem, nostack, preserves_flags)
                );
            } else {
                core::arch::asm!(
                    "cvtss2sd {y}, {x}",
                    x = in(xmm_reg) x,
                    y = inout(xmm_reg) y,
                    options(nomem, nostack, preserves_flags)
                );
            }
        }
        y
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        if subnormals_survive() {
            2f64.powi(-149)
        } else {
            0.0
        }
    }
}

/// [`least_subnormal`] in both lanes of an `f64x2`, VEX-encoded where the
/// build has AVX: `2⁻¹⁴⁹`, or 0 under denormals-are-zero. One conversion
/// of two `f32` lanes (`cvtps2pd`), which writes the whole register and so
/// needs none zeroed first, where `cvtss2sd` keeps the upper lane and
/// waits on it. The plane's first pass multiplies its constants by it
/// ([`crate::plane::stages::filter_relative`]).
///
/// ```
/// assert_eq!(rayoracle::num::certify::least_subnormal_pair().to_array(), [2f64.powi(-149); 2]);
/// ```
#[inline(always)]
pub fn least_subnormal_pair() -> wide::f64x2 {
    #[cfg(target_arch = "x86_64")]
    {
        use core::arch::x86_64::{__m128, __m128d};
        use wide::bytemuck::cast;
        let x: __m128 = cast([1u32, 1, 0, 0]);
        let y: __m128d;
        // SAFETY: one conversion between two XMM registers, SSE2 (which
        // every x86-64 CPU has) or, in a build with AVX, its VEX form; it
        // reads and writes no memory, touches no flags but MXCSR's sticky
        // exception bits, and needs no stack. Not `pure`, as for
        // `least_subnormal`: its result depends on MXCSR. It replaces
        // `least_subnormal`'s `cvtss2sd` and the zeroing and lane shuffle
        // around it in the plane's first pass: in the kernels bench
        // (4,096 primary rays, one interleaved run each), the plane
        // reference took 1.40 times plain f64's time with `cvtss2sd` and
        // 1.35 times with this.
        unsafe {
            if cfg!(target_feature = "avx") {
                core::arch::asm!(
                    "vcvtps2pd {y}, {x}",
                    x = in(xmm_reg) x,
                    y = lateout(xmm_reg) y,
                    options(nomem, nostack, preserves_flags)
                );
            } else {
                core::arch::asm!(
                    "cvtps2pd {y}, {x}",
                    x = in(xmm_reg) x,
                    y = lateout(xmm_reg) y,
                    options(nomem, nostack, preserves_flags)
                );
            }
        }
        cast(y)
    }
    #[cfg(not(target_arch = "x86_64"))]
    {
        wide::f64x2::splat(least_subnormal::<false>())
    }
}

/// The value of the finite `f32` with bits `b`, exactly, in f64: what
/// `f64::from(f32::from_bits(b))` gives in the default environment, found
/// with integer arithmetic and products of normal f64 values, so that
/// neither denormals-are-zero (which reads a subnormal operand as 0) nor
/// the optimiser (which may turn a test on a float's bits into a float
/// comparison, valid only in the default environment) meets a subnormal
/// `f32`. For the exact paths, which must not depend on the environment.
///
/// ```
/// use rayoracle::num::certify::widen_bits;
/// assert_eq!(widen_bits(1e-40f32.to_bits()), f64::from(1e-40f32));
/// assert_eq!(widen_bits((-0.1f32).to_bits()), f64::from(-0.1f32));
/// assert_eq!(widen_bits(f32::MAX.to_bits()), f64::from(f32::MAX));
/// ```
#[inline]
pub fn widen_bits(b: u32) -> f64 {
    let (exp, man) = ((b >> 23) & 0xff, b & 0x007f_ffff);
    // m·2^(e − 150) for a normal value, m·2⁻¹⁴⁹ for 0 and subnormals: an
    // integer below 2²⁴ times a power of two from 2⁻¹⁴⁹ to 2¹⁰⁴, all
    // normal f64 values, exact.
    let (m, e) = if exp == 0 {
        (man, -149)
    } else {
        (man | 0x0080_0000, exp as i32 - 150)
    };
    let v = f64::from(m) * f64::from_bits(((1023 + e) as u64) << 52);
    if b >> 31 == 0 { v } else { -v }
}

/// Four `f32` lanes widened to f64 as the default environment does,
/// whatever the environment: [`widen_bits`] for a finite lane. For a
/// packet's primitives, widened once when packed.
///
/// ```
/// use rayoracle::num::certify::widen_lanes;
/// let x = wide::f32x4::from([1e-40, -0.1, f32::INFINITY, 2.0]);
/// assert_eq!(widen_lanes(x), x.to_array().map(f64::from));
/// ```
pub fn widen_lanes(x: wide::f32x4) -> [f64; 4] {
    x.to_array().map(|v| {
        if v.is_finite() {
            widen_bits(v.to_bits())
        } else {
            f64::from(v)
        }
    })
}

/// `x` rounded to the nearest `f32`, ties to even: what `x as f32` gives
/// in the default environment, which flush-to-zero would make 0 for a
/// subnormal result. For the exact paths.
///
/// ```
/// use rayoracle::num::certify::narrow_exact;
/// assert_eq!(narrow_exact(1e-40).to_bits(), (1e-40f64 as f32).to_bits());
/// assert_eq!(narrow_exact(-2f64.powi(-150)).to_bits(), (-0.0f32).to_bits());
/// assert_eq!(narrow_exact(0.1), 0.1f32);
/// ```
#[inline]
pub fn narrow_exact(x: f64) -> f32 {
    if !(x.abs() < f64::from(f32::MIN_POSITIVE)) || x == 0.0 {
        // A normal result, ±0, ±∞ or NaN: nothing to flush.
        return x as f32;
    }
    // The subnormal range: the nearest multiple of 2⁻¹⁴⁹, as an integer
    // (the scaling is exact; a value below 2⁻¹⁵⁰ gives 0, and one that
    // rounds up to 2⁻¹²⁶ gives the least normal's bits).
    let n = (x.abs() * 2f64.powi(149)).round_ties_even() as u32;
    f32::from_bits(n | (u32::from(x.is_sign_negative()) << 31))
}

/// Whether FTZ or DAZ could change what a kernel returns on these inputs,
/// or on a result `t` it certified, so that [`subnormals_work`] must be
/// asked; the scalar kernels skip that register read (the dearest single
/// step of their fast path) when this is false.
///
/// FTZ and DAZ act only on subnormal values: DAZ reads a subnormal operand
/// as 0, FTZ writes 0 for a subnormal result. Three places can meet one:
///
/// * **an f32 input that is subnormal**: DAZ reads it as 0 when widening
///   to f64. Tested here on the bits (integer arithmetic, which DAZ does
///   not touch; a float comparison would see 0).
/// * **an f64 intermediate**: with no subnormal input, every input is 0
///   or at least `2⁻¹²⁶` in magnitude, and below `2¹²⁸`. The scalar
///   stages compute products of at most six inputs (at least `2⁻⁷⁵⁶`),
///   rounded sums and differences of them (a nonzero one at least `2⁻⁵²`
///   of its terms), TwoSum and TwoProduct errors of values on the grid
///   of their inputs' products, and bounds and quotients whose factors the
///   kernels' range sections pair (a large divisor comes with a large
///   dividend: `E_Δ/ŝ ≥ 75uŝ`, `E_q/â ≥ 2u|q̂|/â`): all of them stay above
///   `2⁻⁹⁰⁰`, far from `2⁻¹⁰²²`. A discriminant may come within a few
///   ulps of 0 and below that, where a flush to 0 certifies nothing, as
///   the unflushed value would not. The tight stage's squares may
///   underflow; its `η = 2⁻¹⁰⁰⁰` covers a flush to 0 as it covers
///   gradual underflow (each loses less than `2⁻¹⁰²²`).
/// * **the result's rounding to f32**: FTZ flushes a subnormal f32. Both
///   ends of a certified enclosure round to one f32; if that f32 is
///   subnormal, `|t| < 2⁻¹²⁶`. An end flushed alone makes the ends differ,
///   which certifies nothing; `t = 0` certifies only with `e = 0`, where
///   no rounding happens.
///
/// So the environment matters only where an input is subnormal or a
/// certified `t` is nonzero with `|t| < 2⁻¹²⁶`.
///
/// ```
/// use rayoracle::num::certify::needs_probe;
/// assert!(!needs_probe(&[1.0, 0.0, -3.5], &[4.0, 0.0]));
/// assert!(needs_probe(&[1.0, 1e-40], &[4.0]));
/// assert!(needs_probe(&[1.0], &[1e-39]));
/// // The least normal f32 is not subnormal, as an input or as a result.
/// let least = f32::MIN_POSITIVE;
/// assert!(!needs_probe(&[least, -least], &[f64::from(least), -f64::from(least)]));
/// assert!(needs_probe(&[f32::from_bits(least.to_bits() - 1)], &[]));
/// ```
#[inline(always)]
pub fn needs_probe(inputs: &[f32], t: &[f64]) -> bool {
    let mut any = false;
    for x in inputs {
        any |= (x.to_bits() & 0x7fff_ffff).wrapping_sub(1) < 0x007f_ffff;
    }
    for t in t {
        any |= *t != 0.0 && t.abs() < f64::from(f32::MIN_POSITIVE);
    }
    any
}

/// Whether the results of a four-lane packet stand as its filter left
/// them: denormals-are-zero is off ([`denormals_are_zero`]), so no input
/// was read as 0, and, where some lane's result is 0 or subnormal
/// ([`flush_prone4`]), flush-to-zero is off too ([`subnormals_work`]),
/// the only place FTZ meets the filters, whose f64 arithmetic never
/// underflows. MXCSR is read only for such a packet: `stmxcsr` and the load
/// after it cost more than the conversion that probes DAZ.
///
/// `L` picks the probe's encoding ([`Real::denormals_are_zero`]).
///
/// ```
/// use rayoracle::num::certify::results_stand;
/// // A default Rust program runs with FTZ and DAZ off.
/// assert!(results_stand::<f64>(false) && results_stand::<f64>(true));
/// ```
#[inline(always)]
pub fn results_stand<L: Real>(prone: bool) -> bool {
    !L::denormals_are_zero() && (!prone || subnormals_work())
}

/// [`results_stand`] for a packet whose inputs, the `f32` lanes the kernel
/// widens as it runs, have no subnormal where `clean()` says so. Under
/// denormals-are-zero, results with no root 0 or subnormal stand too for
/// such a packet: DAZ reaches the filters only through a subnormal input,
/// and their f64 arithmetic makes no subnormal ([`needs_probe`]).
/// `clean` runs only under DAZ (a kernel passes a scan out of line,
/// [`any_subnormal4`]), so a renderer that runs with FTZ and DAZ on keeps
/// the packet's fast path, and one that does not pays nothing for it.
///
/// ```
/// use rayoracle::num::certify::{any_subnormal4, packet_results_stand};
/// use wide::f32x4;
/// let inputs = [f32x4::splat(1.0), f32x4::from([0.0, 1e-40, 2.0, 3.0])];
/// // DAZ is off here: the subnormal input is read as it is.
/// let clean = || !any_subnormal4(&inputs);
/// assert!(packet_results_stand::<f64>(false, clean) && packet_results_stand::<f64>(true, clean));
/// ```
#[inline(always)]
pub fn packet_results_stand<L: Real>(prone: bool, clean: impl FnOnce() -> bool) -> bool {
    if L::denormals_are_zero() {
        !prone && clean()
    } else {
        !prone || subnormals_work()
    }
}

/// Whether any lane of `inputs` is subnormal: the values that
/// denormals-are-zero reads as 0.
///
/// ```
/// use rayoracle::num::certify::any_subnormal4;
/// use wide::f32x4;
/// let least = f32::MIN_POSITIVE;
/// assert!(!any_subnormal4(&[f32x4::from([0.0, -0.0, least, f32::NAN]), f32x4::splat(-least)]));
/// assert!(any_subnormal4(&[f32x4::splat(1.0), f32x4::from([1.0, 2.0, -1e-40, 3.0])]));
/// assert!(any_subnormal4(&[f32x4::from([f32::from_bits(1), 1.0, 1.0, 1.0])]));
/// ```
#[inline(always)]
pub fn any_subnormal4(inputs: &[wide::f32x4]) -> bool {
    use wide::i32x4;
    let mut any = i32x4::ZERO;
    for x in inputs {
        // The magnitude's bits: 1 to 2²³ − 1 for a subnormal.
        let m = wide::bytemuck::cast::<_, i32x4>(*x) & i32x4::splat(0x7fff_ffff);
        any |= m.simd_gt(i32x4::ZERO) & m.simd_lt(i32x4::splat(0x80_0000));
    }
    any.any()
}

/// [`flush_prone`] over the lanes of an `f32x4`: whether any is 0 or
/// subnormal. A NaN lane (no root) is not.
///
/// ```
/// use rayoracle::num::certify::flush_prone4;
/// use wide::f32x4;
/// assert!(!flush_prone4(f32x4::from([1.0, -2.0, f32::NAN, 3.0])));
/// assert!(flush_prone4(f32x4::from([1.0, -0.0, 2.0, 3.0])));
/// assert!(flush_prone4(f32x4::from([1.0, 2.0, 1e-40, 3.0])));
/// ```
#[inline(always)]
pub fn flush_prone4(t: wide::f32x4) -> bool {
    let bits: wide::i32x4 = wide::bytemuck::cast(t);
    (bits & wide::i32x4::splat(0x7f80_0000))
        .simd_eq(wide::i32x4::ZERO)
        .any()
}

/// Whether any of these certified f32 results is 0 or subnormal (by its
/// bits): the results of the later stages, which return f32 values, need
/// [`subnormals_work`] only there. A result FTZ flushed is 0; one that
/// certified only because FTZ flushed both ends of its enclosure is 0 too
/// ([`needs_probe`]).
///
/// ```
/// use rayoracle::num::certify::flush_prone;
/// assert!(!flush_prone(&[1.0, -2.0]));
/// assert!(flush_prone(&[1.0, 0.0]) && flush_prone(&[-1e-40]));
/// ```
#[inline(always)]
pub fn flush_prone(roots: &[f32]) -> bool {
    roots.iter().any(|t| t.to_bits() & 0x7f80_0000 == 0)
}

/// [`subnormals_work`] by arithmetic, on any target: halves the smallest
/// normal f64 and doubles it back.
///
/// ```
/// assert!(rayoracle::num::certify::subnormals_survive());
/// ```
#[inline(always)]
pub fn subnormals_survive() -> bool {
    subnormals_survive_with(|a, b| core::hint::black_box(a) * core::hint::black_box(b))
}

/// [`subnormals_survive`] with the multiplication given, so that a test can
/// pass one that flushes.
#[inline(always)]
fn subnormals_survive_with(mul: impl Fn(f64, f64) -> f64) -> bool {
    // FTZ makes `half` 0; DAZ reads the subnormal `half` as 0 when doubling.
    let half = mul(f64::MIN_POSITIVE, 0.5);
    half != 0.0 && mul(half, 2.0) == f64::MIN_POSITIVE
}

/// Runs `f` on a thread of its own with MXCSR's flush-to-zero and
/// denormals-are-zero bits as given, and returns what it returns: for the
/// unit tests of the paths those environments take.
#[cfg(all(test, target_arch = "x86_64"))]
pub(crate) fn in_environment<R: Send + 'static>(
    ftz: bool,
    daz: bool,
    f: impl FnOnce() -> R + Send + 'static,
) -> R {
    std::thread::spawn(move || {
        let mut csr = 0u32;
        // SAFETY: stores MXCSR to `csr`, a live aligned u32. Test code
        // only: there is no other way to read the register.
        unsafe { core::arch::asm!("stmxcsr [{}]", in(reg) &mut csr, options(nostack)) };
        let csr = csr & !(1 << 15 | 1 << 6) | u32::from(ftz) << 15 | u32::from(daz) << 6;
        // SAFETY: loads MXCSR from `csr`, a live aligned u32 holding the
        // thread's own register with at most the FTZ and DAZ bits changed:
        // a valid value, on a thread that ends with `f`.
        unsafe { core::arch::asm!("ldmxcsr [{}]", in(reg) &csr, options(nostack)) };
        f()
    })
    .join()
    .unwrap()
}

/// Asserts that `L`'s probe for denormals-are-zero sees the flag, as the
/// baseline lanes' does, and is false without it: for the tests of each
/// lane type, on a CPU that runs `L`.
#[cfg(all(test, target_arch = "x86_64"))]
pub(crate) fn assert_probe_sees_daz<L: crate::num::real::Real + 'static>() {
    use crate::num::real::F64x4;
    for daz in [false, true] {
        let seen = in_environment(false, daz, || {
            (L::denormals_are_zero(), F64x4::denormals_are_zero())
        });
        assert_eq!(seen, (daz, daz));
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::exact::Dyadic;

    /// Whether `v` rounds to `f` (ties to even); f32 midpoints are f64s.
    fn rounds_to(v: &Dyadic, f: f32) -> bool {
        let mid = |g: f32| Dyadic::from_f64((f as f64 + g as f64) / 2.0);
        let (lo, hi) = (mid(f.next_down()), mid(f.next_up()));
        let even = f.to_bits().is_multiple_of(2);
        (lo < *v || (lo == *v && even)) && (*v < hi || (*v == hi && even))
    }

    /// `certify` against exact arithmetic: wherever it passes, both ends
    /// of `[t − |t|r − a, t + |t|r + a]`, computed exactly ([`Dyadic`]),
    /// round to `t as f32`. The cases put `t` at and around f32 midpoints,
    /// a few f64 ulps either side, with the bound just inside and just
    /// outside the distance to the midpoint.
    ///
    /// [`Dyadic`]: crate::exact::Dyadic
    #[test]
    fn certified_enclosures_round_to_one_f32_exactly() {
        use rand::{Rng, SeedableRng};
        let d = Dyadic::from_f64;
        let mut rng = rand::rngs::SmallRng::seed_from_u64(51);
        let (mut certified, mut near) = (0, 0);
        for _ in 0..200_000 {
            let f = rng.random_range(0.001f32..1000.0) * if rng.random() { 1.0 } else { -1.0 };
            let mid = (f as f64 + f.next_up() as f64) / 2.0;
            let t = mid + (rng.random_range(-40i64..=40) as f64) * mid.abs() * 2f64.powi(-52);
            let dist = (t - mid).abs();
            let r = match rng.random_range(0..3) {
                0 => 0.0,
                1 => rng.random_range(0.0..2f64.powi(-50)),
                _ => rng.random::<f64>() * dist / t.abs(),
            };
            let a = match rng.random_range(0..3) {
                0 => 0.0,
                1 => dist * rng.random_range(0.5..1.5),
                _ => (dist - r * t.abs()).max(0.0) * rng.random_range(0.9..1.1),
            };
            if !certify(t, r, a) {
                continue;
            }
            certified += 1;
            near += usize::from(r * t.abs() + a > dist / 2.0);
            let e = d(t.abs()) * d(r) + d(a);
            let want = t as f32;
            for end in [d(t) - &e, d(t) + &e] {
                assert!(
                    rounds_to(&end, want),
                    "t {t:e}, r {r:e}, a {a:e}: not {want:e}"
                );
            }
        }
        assert!(
            certified > 20_000 && near > 5_000,
            "{certified} certified, {near} near"
        );
    }

    /// [`certify_relative`] against exact arithmetic: wherever it passes,
    /// both ends of `t(1 ∓ r)`, computed exactly, round to `t as f32`.
    /// The cases put `t` within a few hundred thousand f64 ulps of an f32
    /// midpoint, in the middle of a binade and next to a power of two
    /// (where the binade below has ulps half as large), either sign, with
    /// `r` up to and past the distance to the midpoint; and each lane type
    /// gives the scalar answer.
    #[test]
    fn relative_certificates_round_to_one_f32_exactly() {
        use crate::num::real::{F64x4, Pair};
        use rand::{Rng, SeedableRng};
        let d = Dyadic::from_f64;
        let mut rng = rand::rngs::SmallRng::seed_from_u64(52);
        let (mut certified, mut near, mut refused) = (0, 0, 0);
        for i in 0..200_000 {
            let e = rng.random_range(-120..120);
            let f = if i % 2 == 0 {
                rng.random_range(1.0f32..2.0) * 2f32.powi(e)
            } else {
                2f32.powi(e)
            };
            let f = if rng.random() { f } else { -f };
            let g = if rng.random() {
                f.next_up()
            } else {
                f.next_down()
            };
            let mid = (f as f64 + g as f64) / 2.0;
            let k = rng.random_range(-300_000i64..=300_000);
            let t = f64::from_bits((mid.to_bits() as i64 + k) as u64);
            let dist = (t - mid).abs() / t.abs();
            let r = match rng.random_range(0..3) {
                0 => rng.random_range(0.0..2f64.powi(-40)),
                1 => dist * rng.random_range(0.25..0.75),
                _ => dist * rng.random_range(0.9..1.1),
            };
            let ok = certify_relative(t, r);
            let lanes = certify_relative(F64x4::splat(t), r).lanes();
            assert_eq!(lanes, [ok; 4], "t {t:e}, r {r:e}");
            let pair = certify_relative(Pair(t, t), r);
            assert_eq!((pair.0, pair.1), (ok, ok));
            if !ok {
                refused += 1;
                continue;
            }
            certified += 1;
            near += usize::from(r > dist / 2.0);
            let e = d(t.abs()) * d(r);
            let want = t as f32;
            for end in [d(t) - &e, d(t) + &e] {
                assert!(rounds_to(&end, want), "t {t:e}, r {r:e}: not {want:e}");
            }
        }
        assert!(
            certified > 50_000 && near > 10_000 && refused > 20_000,
            "{certified} certified, {near} near, {refused} refused"
        );
    }

    /// Every probe of the environment sees the flags it is for: both
    /// encodings of the DAZ probe see DAZ (the VEX one where the CPU has
    /// AVX), and the register read and the arithmetic probe see FTZ and DAZ
    /// alike.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn the_environment_probes_see_the_flags() {
        let avx = std::arch::is_x86_feature_detected!("avx");
        for (ftz, daz) in [(false, false), (true, false), (false, true), (true, true)] {
            let (sse, vex, work, survive) = in_environment(ftz, daz, move || {
                let vex = avx.then(daz_probe::<true>);
                (
                    daz_probe::<false>(),
                    vex,
                    subnormals_work(),
                    subnormals_survive(),
                )
            });
            assert_eq!(sse, daz, "ftz {ftz}, daz {daz}");
            assert!(vex.is_none_or(|v| v == daz), "{vex:?}");
            assert_eq!(work, !(ftz || daz), "ftz {ftz}, daz {daz}");
            assert_eq!(survive, !(ftz || daz), "ftz {ftz}, daz {daz}");
        }
    }

    /// The conversions from bits agree with the hardware's in the default
    /// environment, bit for bit, over the subnormal and low normal ranges
    /// and random others.
    #[test]
    fn exact_conversions_match_the_default_environment() {
        let mut next = crate::num::xorshift(0x2545_f491_4f6c_dd1d);
        for _ in 0..200_000 {
            let r = next();
            let f = f32::from_bits(if r & 1 == 0 {
                (r >> 32) as u32 & 0x80ff_ffff
            } else {
                (r >> 32) as u32
            });
            if f.is_finite() {
                assert_eq!(
                    widen_bits(f.to_bits()).to_bits(),
                    f64::from(f).to_bits(),
                    "{f:e}"
                );
            }
            let e = (r >> 8) as i32 % 60 - 180;
            let x = f64::from_bits(0x3ff0_0000_0000_0000 | (r >> 12)) * 2f64.powi(e);
            let x = if r & 2 == 0 { x } else { -x };
            for x in [x, f64::from(f), f64::from(f) * 1.5] {
                assert_eq!(narrow_exact(x).to_bits(), (x as f32).to_bits(), "{x:e}");
            }
        }
    }

    /// A multiplication that flushes subnormal results (FTZ), and one that
    /// reads subnormal inputs as 0 (DAZ), are both detected.
    #[test]
    fn flushing_is_detected() {
        let sub = |x: f64| x != 0.0 && x.abs() < f64::MIN_POSITIVE;
        let ftz = |a: f64, b: f64| if sub(a * b) { 0.0 } else { a * b };
        let daz = |a: f64, b: f64| {
            let z = |x: f64| if sub(x) { 0.0 } else { x };
            z(a) * z(b)
        };
        assert!(subnormals_survive_with(|a, b| a * b));
        assert!(!subnormals_survive_with(ftz));
        assert!(!subnormals_survive_with(daz));
        // The register and the arithmetic agree in this environment.
        assert_eq!(subnormals_work(), subnormals_survive());
    }
}
