//! The run-time dispatch of the batch entry points
//! (`intersect_packets` of the plane, the sphere and the quadric), written
//! once: [`packets_dispatch!`](crate::num::batch::packets_dispatch).

/// The body of a batch entry point `intersect_packets(rays, prim, out)`:
/// `$packets_in`, generic over [`Real8`](crate::num::real::Real8), on one
/// AVX-512 register where the CPU has AVX-512 F, DQ and VL (and AVX2 and
/// FMA), else on pairs of AVX registers where it has AVX2 and FMA, else
/// on pairs of the baseline lanes. Every copy gives the same bits.
macro_rules! packets_dispatch {
    ($packets_in:ident, $rays:ident, $prim:ident: $P:ty, $out:ident: $H:ty) => {{
        use $crate::ray4::Ray4;
        #[cfg(target_arch = "x86_64")]
        if let Some(avx512) = $crate::num::avx512::Avx512::detect() {
            #[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2,fma")]
            fn run(_: $crate::num::avx512::Avx512, r: &[Ray4], p: &$P, o: &mut [$H]) {
                $packets_in::<$crate::num::avx512::Avx8>(r, p, o)
            }
            // SAFETY: the token exists only where AVX-512 F, DQ and VL,
            // AVX2 and FMA were detected. Justified by the kernels bench
            // figures in `crate::num::avx512`.
            return unsafe { run(avx512, $rays, $prim, $out) };
        }
        #[cfg(target_arch = "x86_64")]
        if let Some(avx2) = $crate::num::avx::Avx2::detect() {
            #[target_feature(enable = "avx2,fma")]
            fn run(_: $crate::num::avx::Avx2, r: &[Ray4], p: &$P, o: &mut [$H]) {
                $packets_in::<$crate::num::real::Pair<$crate::num::avx::Avx4>>(r, p, o)
            }
            // SAFETY: the token exists only where AVX2 and FMA were
            // detected. Justified by the kernels bench figures in
            // `crate::num::avx`.
            return unsafe { run(avx2, $rays, $prim, $out) };
        }
        $packets_in::<$crate::num::real::Pair<$crate::num::real::F64x4>>($rays, $prim, $out)
    }};
}

pub(crate) use packets_dispatch;
