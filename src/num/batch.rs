//! The run-time dispatch of the batch entry points
//! (`intersect_packets` of the plane, the sphere and the quadric), written
//! once: [`packets_dispatch!`](crate::num::batch::packets_dispatch); and
//! the out-of-line copies of their packets' path under denormals-are-zero
//! ([`daz_copies!`](crate::num::batch::daz_copies)).

/// The body of a batch entry point `intersect_packets(rays, prim, out)`:
/// `$packets_in`, generic over [`Real8`](crate::num::real::Real8), on one
/// AVX-512 register where the CPU has AVX-512 F, DQ and VL (and AVX2 and
/// FMA), else on pairs of AVX registers where it has AVX2 and FMA, else
/// on pairs of the baseline lanes. Every copy gives the same bits. A
/// kernel whose batches run faster on pairs of AVX registers passes
/// `avx512: false` last, and skips the AVX-512 copy.
macro_rules! packets_dispatch {
    ($packets_in:ident, $rays:ident, $prim:ident: $P:ty, $out:ident: $H:ty) => {
        $crate::num::batch::packets_dispatch!(
            $packets_in, $rays, $prim: $P, $out: $H, avx512: true
        )
    };
    ($packets_in:ident, $rays:ident, $prim:ident: $P:ty, $out:ident: $H:ty, avx512: $wide:expr) => {{
        use $crate::ray4::Ray4;
        #[cfg(target_arch = "x86_64")]
        if let Some(avx512) = $crate::num::avx512::Avx512::detect().filter(|_| $wide) {
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

/// A kernel's path under denormals-are-zero, `$under_daz_in`, generic over
/// [`Real4`](crate::num::real::Real4), as two cold functions: `under_daz`
/// on the baseline lanes, and `under_daz_avx2` on the AVX lanes, compiled
/// for AVX2 and FMA and entered with the token that proves them, as the
/// AVX copy of the kernel that calls it. Each kernel asks DAZ first and
/// calls the one of its own copy, so the common path holds neither call's
/// registers. A third, `packets_under_daz`, takes a batch under DAZ
/// through the kernel's `intersect`, one packet at a time.
macro_rules! daz_copies {
    ($under_daz_in:ident, $P:ty, $H:ty) => {
        /// The path under DAZ on the baseline lanes, out of line.
        #[cold]
        #[inline(never)]
        fn under_daz(ray: &$crate::ray4::Ray4, p: &$P) -> $H {
            $under_daz_in::<$crate::num::real::F64x4>(ray, p)
        }

        /// The path under DAZ on the AVX lanes, out of line.
        #[cfg(target_arch = "x86_64")]
        #[cold]
        #[inline(never)]
        #[target_feature(enable = "avx2,fma")]
        fn under_daz_avx2(_: $crate::num::avx::Avx2, ray: &$crate::ray4::Ray4, p: &$P) -> $H {
            $under_daz_in::<$crate::num::avx::Avx4>(ray, p)
        }

        /// `intersect_packets` under DAZ, out of line: one packet at a
        /// time, as `intersect` takes it there (on the AVX lanes where the
        /// CPU has them).
        #[cold]
        #[inline(never)]
        fn packets_under_daz(rays: &[$crate::ray4::Ray4], p: &$P, out: &mut [$H]) {
            for (r, o) in rays.iter().zip(out) {
                *o = intersect(r, p);
            }
        }
    };
}

pub(crate) use daz_copies;

/// The rays of [`every_copy_agrees!`]: seven packets from one point below
/// the origin, fanning out, so that each primitive's test meets more than
/// one class and an odd tail.
#[cfg(test)]
pub(crate) fn test_rays() -> Vec<crate::ray4::Ray4> {
    let origin = glam::Vec3::new(0.1, -3.0, 0.0);
    (0..7)
        .map(|i| {
            let d = [0, 1, 2, 3]
                .map(|k| glam::Vec3::new(0.1 * (i + k) as f32 - 0.3, 1.0 - 0.2 * k as f32, 0.05));
            crate::ray4::Ray4::from_rays(d.map(|d| crate::Ray::new(origin, d)))
        })
        .collect()
}

/// A test body: every copy of the batch `$packets_in` this CPU can run
/// (pairs of [`F64x4`](crate::num::real::F64x4), pairs of AVX registers
/// where it has AVX2, one AVX-512 register where it has AVX-512) gives, on
/// [`test_rays`] against `$prim`, what the one-packet kernel `$one` gives,
/// bit for bit, and the answers span at least two classes.
#[cfg(test)]
macro_rules! every_copy_agrees {
    ($packets_in:ident, $one:ident, $prim:ident: $P:ty, $H:ty) => {{
        use $crate::num::real::{F64x4, Pair};
        use $crate::ray4::Ray4;
        let rays = $crate::num::batch::test_rays();
        let mut outs = vec![vec![$one(&rays[0], &$prim); rays.len()]];
        $packets_in::<Pair<F64x4>>(&rays, &$prim, &mut outs[0]);
        #[cfg(target_arch = "x86_64")]
        {
            use $crate::num::{
                avx::{Avx2, Avx4},
                avx512::{Avx8, Avx512},
            };
            #[target_feature(enable = "avx2,fma")]
            fn pairs(_: Avx2, r: &[Ray4], x: &$P, o: &mut [$H]) {
                $packets_in::<Pair<Avx4>>(r, x, o)
            }
            #[target_feature(enable = "avx512f,avx512dq,avx512vl,avx2,fma")]
            fn wide(_: Avx512, r: &[Ray4], x: &$P, o: &mut [$H]) {
                $packets_in::<Avx8>(r, x, o)
            }
            if let Some(t) = Avx2::detect() {
                let mut o = outs[0].clone();
                // SAFETY: the token proves the features `pairs` needs.
                unsafe { pairs(t, &rays, &$prim, &mut o) };
                outs.push(o);
            }
            if let Some(t) = Avx512::detect() {
                let mut o = outs[0].clone();
                // SAFETY: the token proves the features `wide` needs.
                unsafe { wide(t, &rays, &$prim, &mut o) };
                outs.push(o);
            }
        }
        let mut classes = std::collections::BTreeSet::new();
        for (r, h) in outs.iter().flat_map(|out| rays.iter().zip(out)) {
            let want = $one(r, &$prim).lanes();
            assert!(
                h.lanes()
                    .iter()
                    .zip(&want)
                    .all(|(x, y)| $crate::hit::same_bits(x, y)),
                "{r:?}"
            );
            classes.extend(want.map(|w| format!("{w:?}").chars().take(3).collect::<String>()));
        }
        assert!(classes.len() >= 2, "{classes:?}");
    }};
}

#[cfg(test)]
pub(crate) use every_copy_agrees;
