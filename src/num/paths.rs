//! Test support for the x4 kernels' paths under flush-to-zero and
//! denormals-are-zero: a per-thread count of the packets a kernel sends to
//! its scalar stages lane by lane, and the checks built on it.

use core::cell::Cell;
#[cfg(target_arch = "x86_64")]
use {crate::Ray, crate::ray4::Ray4, wide::f32x4};

std::thread_local!(static SETTLED: Cell<usize> = const { Cell::new(0) });

/// One more packet sent to the scalar stages (each kernel's `settle`).
pub(crate) fn note_settled() {
    SETTLED.with(|c| c.set(c.get() + 1));
}

/// Runs `run` on a thread of its own in the plain environment and under
/// FTZ, DAZ and both, checks that it answers the same in each, and
/// returns how many packets each environment sent to the scalar stages,
/// in that order.
#[cfg(target_arch = "x86_64")]
fn settled_in_each_environment<R>(run: impl Fn() -> R + Clone + Send + 'static) -> [usize; 4]
where
    R: PartialEq + core::fmt::Debug + Send + 'static,
{
    let modes = [(false, false), (true, false), (false, true), (true, true)];
    let got = modes.map(|(ftz, daz)| {
        let run = run.clone();
        crate::num::certify::in_environment(ftz, daz, move || {
            let before = SETTLED.with(Cell::get);
            let answers = run();
            (answers, SETTLED.with(Cell::get) - before)
        })
    });
    for ((answers, _), (ftz, daz)) in got.iter().zip(modes) {
        assert_eq!(*answers, got[0].0, "FTZ {ftz}, DAZ {daz}");
    }
    got.map(|(_, n)| n)
}

/// A kernel's four ways of answering packets (one packet, the baseline
/// copy, the batch, the batch on pairs of baseline lanes), each giving
/// the answers' bits.
#[cfg(target_arch = "x86_64")]
pub(crate) type Paths<P, B> = [fn(&[Ray4], &P) -> Vec<B>; 4];

/// Under FTZ, DAZ and both, every path answers as without them. On the
/// `clean` sets, whose packets have no subnormal input that the kernel
/// widens as it runs, no path sends a packet to the scalar stages. On the
/// `dirty` ones, each with such an input that DAZ would read as 0, every
/// path does under DAZ, and none in the plain environment or under FTZ
/// alone, which meets no input.
#[cfg(target_arch = "x86_64")]
pub(crate) fn assert_packets_keep_their_paths<P, B>(
    paths: Paths<P, B>,
    clean: &[(Vec<Ray4>, P)],
    dirty: &[(Vec<Ray4>, P)],
) where
    P: Copy + Send + 'static,
    B: PartialEq + core::fmt::Debug + Send + 'static,
{
    for (i, (rays, p)) in clean.iter().enumerate() {
        for path in paths {
            let (r, p) = (rays.clone(), *p);
            assert_eq!(
                settled_in_each_environment(move || path(&r, &p)),
                [0; 4],
                "clean set {i}"
            );
        }
    }
    for (i, (rays, p)) in dirty.iter().enumerate() {
        for path in paths {
            let (r, p) = (rays.clone(), *p);
            let n = settled_in_each_environment(move || path(&r, &p));
            assert!(
                n[..2] == [0; 2] && n[2] > 0 && n[3] > 0,
                "dirty set {i}: {n:?}"
            );
        }
    }
}

/// Rays from `origin` fanned over `dirs`: sixteen packets, packet `i`'s
/// lane `j` along `dir(i, j)`.
#[cfg(target_arch = "x86_64")]
pub(crate) fn fan(origin: glam::Vec3, dir: impl Fn(usize, usize) -> glam::Vec3) -> Vec<Ray4> {
    (0..16)
        .map(|i| Ray4::from_rays([0, 1, 2, 3].map(|j| Ray::new(origin, dir(i, j)))))
        .collect()
}

/// Three packets of `rays` (the fifth to the seventh: a pair and one
/// alone) with a subnormal, −10⁻⁴⁰, in the second, once per ray vector
/// (in lane `v % 4` of vector `v`, the origin's then the direction's),
/// and once with `lone` in its middle lanes: seven sets.
#[cfg(target_arch = "x86_64")]
pub(crate) fn with_subnormal_rays(rays: &[Ray4], lone: Ray) -> Vec<Vec<Ray4>> {
    (0..7)
        .map(|v| {
            let mut r = rays[4..7].to_vec();
            if v < 6 {
                let x = if v < 3 {
                    &mut r[1].origin[v]
                } else {
                    &mut r[1].dir[v - 3]
                };
                *x = with_lane(*x, v % 4, -1e-40);
            } else {
                let keep = r[1].to_rays();
                r[1] = Ray4::from_rays([keep[0], lone, lone, keep[3]]);
            }
            r
        })
        .collect()
}

/// `x` with lane `i` set to `v`.
#[cfg(target_arch = "x86_64")]
pub(crate) fn with_lane(x: f32x4, i: usize, v: f32) -> f32x4 {
    let mut lanes = x.to_array();
    lanes[i] = v;
    f32x4::from(lanes)
}

#[cfg(all(test, target_arch = "x86_64"))]
mod tests {
    use super::*;
    use glam::Vec3;

    /// Seven sets of the three packets after the fourth, each differing
    /// from them in the second packet alone: sets 0 to 5 in one value, the
    /// origin's components and then the direction's, in lane `v % 4`, set
    /// to −10⁻⁴⁰; set 6 in its middle lanes, which are `lone`.
    #[test]
    fn with_subnormal_rays_puts_each_subnormal_where_it_says() {
        let rays = fan(Vec3::new(0.5, 1.5, -3.0), |i, j| {
            Vec3::new(i as f32 + 1.0, j as f32 + 2.0, 1.0)
        });
        let lone = Ray::new(Vec3::splat(7.0), Vec3::Z);
        let sets = with_subnormal_rays(&rays, lone);
        assert_eq!(sets.len(), 7);
        let values = |p: &Ray4| [p.origin, p.dir].map(|v| v.map(|x| x.to_array()));
        for (v, set) in sets.iter().enumerate() {
            assert_eq!(set.len(), 3);
            assert_eq!(values(&set[0]), values(&rays[4]), "set {v}");
            assert_eq!(values(&set[2]), values(&rays[6]), "set {v}");
            let (got, was) = (values(&set[1]), values(&rays[5]));
            if v < 6 {
                let (which, axis, lane) = (v / 3, v % 3, v % 4);
                for (w, (g, x)) in got.iter().zip(&was).enumerate() {
                    for (a, (g, x)) in g.iter().zip(x).enumerate() {
                        for (l, (g, x)) in g.iter().zip(x).enumerate() {
                            let here = (w, a, l) == (which, axis, lane);
                            let want = if here { -1e-40 } else { *x };
                            assert_eq!(g.to_bits(), want.to_bits(), "set {v}: {w} {a} {l}");
                        }
                    }
                }
            } else {
                let lanes = set[1].to_rays();
                let kept = rays[5].to_rays();
                assert_eq!([lanes[0], lanes[3]], [kept[0], kept[3]]);
                assert_eq!([lanes[1], lanes[2]], [lone, lone]);
            }
        }
    }

    /// Whether a packet has a subnormal input.
    fn subnormal(p: &Ray4) -> bool {
        [p.origin, p.dir]
            .iter()
            .flatten()
            .any(|v| v.to_array().iter().any(|x| x.is_subnormal()))
    }

    /// A path that sends every packet to the scalar stages.
    fn always(r: &[Ray4], _: &()) -> Vec<u8> {
        r.iter().for_each(|_| note_settled());
        vec![0; r.len()]
    }

    /// A path that never does.
    fn never(r: &[Ray4], _: &()) -> Vec<u8> {
        vec![0; r.len()]
    }

    /// A path that does as the kernels must: only under DAZ, for a packet
    /// with a subnormal input.
    fn as_kernels(r: &[Ray4], _: &()) -> Vec<u8> {
        let daz = crate::num::certify::denormals_are_zero();
        r.iter()
            .filter(|p| daz && subnormal(p))
            .for_each(|_| note_settled());
        vec![0; r.len()]
    }

    /// A path whose answers depend on the environment.
    fn moody(r: &[Ray4], _: &()) -> Vec<u8> {
        vec![u8::from(crate::num::certify::denormals_are_zero()); r.len()]
    }

    /// The check passes the kernels' behaviour and fails each way of
    /// leaving it: a clean packet sent to the scalar stages, a dirty one
    /// that is not under DAZ, answers that change with the environment.
    #[test]
    fn the_check_fails_a_path_that_strays() {
        let rays = fan(Vec3::new(0.0, 0.0, -3.0), |i, j| {
            Vec3::new(i as f32 * 0.1, j as f32 * 0.1, 1.0)
        });
        let dirty: Vec<_> = with_subnormal_rays(&rays, Ray::new(Vec3::ZERO, Vec3::X * 1e-40))
            .into_iter()
            .map(|r| (r, ()))
            .collect();
        let clean = [(rays, ())];
        let check = |path: fn(&[Ray4], &()) -> Vec<u8>, clean: &[_], dirty: &[_]| {
            let (clean, dirty): (Vec<_>, Vec<_>) = (clean.to_vec(), dirty.to_vec());
            std::panic::catch_unwind(move || {
                assert_packets_keep_their_paths([path; 4], &clean, &dirty)
            })
            .is_ok()
        };
        assert!(check(as_kernels, &clean, &dirty));
        assert!(!check(always, &clean, &[]));
        assert!(!check(never, &[], &dirty));
        assert!(!check(moody, &clean, &[]));
    }
}
