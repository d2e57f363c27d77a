//! The certain misses of a packet, in `f32`: the filter's test `Δ̂ <
//! −E_Δ` on the inputs as given, with no widening, for the x4 kernels'
//! early exit (a packet whose four lanes all miss, as most of a camera's
//! do around a small sphere) and for the batches' choice of the lanes to
//! gather. On every copy of the lanes it is cheaper than the f64 classes:
//! no conversions, and four `f32` lanes fill one SSE register.
//!
//! # The bound
//!
//! Write `u = 2⁻²⁴` and `η₀ = 2⁻¹²⁵`. Every operation here (`+`, `−`,
//! `×`) gives `x(1 + δ) + η` for its exact result `x`, `|δ| ≤ u`, with
//! `η ≠ 0` only where `|x| < 2⁻¹²⁶`: the subnormal range, where gradual
//! underflow loses up to `2⁻¹⁵⁰`, flush-to-zero up to `2⁻¹²⁶`, and
//! denormals-are-zero reading the result as 0 up to `2⁻¹²⁶` more; so
//! `|η| ≤ η₀` in every floating-point environment. (An input that DAZ
//! reads as 0 is not covered: the kernel tests only packets without one.)
//! With `F = o − C` exact, `A = |d|²`, `B = F·d`, `M_b = Σ|Fᵢdᵢ|`, `G =
//! |F|²`, `N = G + R²` and `Δ = B² − A(G − R²)`, to first order in `u`:
//!
//! * `f̂ᵢ`, `p̂ᵢ = fl(f̂ᵢdᵢ)` and two additions: `|b̂ − B| ≤ 4u M_b`, as in
//!   the [filter](super), but in `f32`. `fl(b̂²)` is within `9u M_b²` of
//!   `B²`.
//! * `â`: three products and two additions, `3u A`. `ĝ`: `f̂ᵢ²` carries
//!   three roundings, the additions two, `5u G`; `R²` one; and `ĉ =
//!   fl(ĝ − R̂²)` one more, relative to `|ĉ| ≤ N`: `|ĉ − (G − R²)| ≤ 6u
//!   N`. `fl(âĉ)` is within `(3 + 6 + 1)u A N = 10u AN` of `A(G − R²)`.
//! * The difference rounds once more, `u(M_b² + AN)`: `|Δ̂ − Δ| ≤ 10u
//!   M_b² + 11u AN`. And `M_b ≤ |F||d|` (Cauchy–Schwarz), so `M_b² ≤ AG ≤
//!   AN`: **`|Δ̂ − Δ| ≤ 21u AN`**. (The f64 filter keeps `m_b²` for its
//!   roots; this test needs no `m_b`.)
//!
//! The `η` terms, carried through the same steps: `b̂` gains up to
//! `η₀(Σ|dᵢ| + 5)` (each `f̂ᵢ`'s times `|dᵢ|`, the three products', the two
//! additions'), `ĉ` up to `η₀(2Σ|Fᵢ| + 7)`, `â` up to `5η₀`, and `Δ̂` in
//! all at most `η₀(2M_b(Σ|dᵢ| + 5) + 5N + A(2Σ|Fᵢ| + 7) + 3)`. With
//! `Σ|dᵢ| ≤ √(3A)`, `Σ|Fᵢ| ≤ √(3N)`, `2xy ≤ x² + y²` and `2√N ≤ 1 + N`,
//! that is at most `6.8η₀(M_b² + AN) + 10.5η₀(1 + A + N)`. The first part
//! is below `2⁻¹²¹AN`, which the relative bound's slack covers; the
//! second is an absolute term the relative bound does not.
//!
//! The test takes twice each constant, on the computed magnitudes (`â`
//! and `n̂ = fl(ĝ + R̂²)`, each within a few `u` and `η₀` of its own), as
//! the filter does: **`E_Δ = 42u ân̂ + 2⁻¹²⁰(1 + â + n̂)`**, `2⁻¹²⁰ = 32η₀`
//! (twice the `10.5η₀`, and the losses of `E_Δ`'s own operations to
//! underflow, a few `η₀` against the `1` in `1 + â + n̂`).
//! `Δ̂ < −E_Δ` then gives `Δ < 0`: no root. A tangent, an exact root, a
//! lane without a line (`Δ̂ = 0`) never pass.
//!
//! # Range
//!
//! An `f32` overflows where the f64 filter's values do not, so each
//! overflow must leave the test false. An infinite `f̂ᵢ`, `ĝ` or `R̂²`
//! makes `n̂` infinite, and an infinite `â` makes `1 + â` so; then `E_Δ`
//! is `+∞` or NaN (`0·∞`), and no `Δ̂` is below `−E_Δ`. Otherwise an
//! infinite `p̂ᵢ`, `b̂` or `b̂²` makes `Δ̂` `+∞` or NaN, which certify
//! nothing. Rounding is monotone, so `|ĉ| ≤ n̂`: an infinite `âĉ` makes
//! `ân̂` and `E_Δ` infinite. With `fl(b̂²) ≥ 0` and `fl(âĉ)` finite, `Δ̂`
//! overflows only upwards, to `+∞`. NaN certifies nothing.
//!
//! ```
//! use rayoracle::{Ray, ray4::Ray4, sphere::{Sphere, stages::misses, x4::Sphere4}};
//! use glam::Vec3;
//! let s = Sphere4::splat(&Sphere::new(Vec3::ZERO, 1.0));
//! let ray = |y: f32| Ray::new(Vec3::new(0.0, y, -5.0), Vec3::Z);
//! let m = misses::certain(&Ray4::from_rays([2.0, 1.0, 0.5, -1.5].map(ray)), &s);
//! assert_eq!(m.to_bitmask(), 0b1001);
//! ```

use crate::ray4::Ray4;
use crate::sphere::x4::Sphere4;
use wide::f32x4;

/// `u` in `f32`, `2⁻²⁴`.
const U32: f32 = f32::EPSILON / 2.0;

/// The relative part of `E_Δ`, `42u`.
pub const RELATIVE: f32 = 42.0 * U32;

/// The absolute part of `E_Δ`, `2⁻¹²⁰`.
pub const ABSOLUTE: f32 = 1.0 / (1u128 << 120) as f32;

/// The lanes whose line certainly misses its sphere (all bits set), by
/// the [module](self)'s test.
#[inline(always)]
pub fn certain(ray: &Ray4, s: &Sphere4) -> f32x4 {
    certain_by(ray, s, RELATIVE, ABSOLUTE)
}

/// [`certain`] with `E_Δ`'s two constants given: [`RELATIVE`] and
/// [`ABSOLUTE`] in the kernels, smaller ones only in the tests that show
/// the bound is needed.
#[inline(always)]
pub fn certain_by(ray: &Ray4, s: &Sphere4, relative: f32, absolute: f32) -> f32x4 {
    let (disc, e) = disc_and_bound(ray, s, relative, absolute);
    (-e).simd_gt(disc)
}

/// `Δ̂` and `E_Δ` of [`certain_by`].
#[inline(always)]
fn disc_and_bound(ray: &Ray4, s: &Sphere4, relative: f32, absolute: f32) -> (f32x4, f32x4) {
    let ([o0, o1, o2], [d0, d1, d2]) = (ray.origin, ray.dir);
    let [c0, c1, c2] = s.center;
    let f = [o0 - c0, o1 - c1, o2 - c2];
    let a = d0 * d0 + d1 * d1 + d2 * d2;
    let p = [f[0] * d0, f[1] * d1, f[2] * d2];
    let b = p[0] + p[1] + p[2];
    let g = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
    let rr = s.radius * s.radius;
    let (c, n) = (g - rr, g + rr);
    let one = f32x4::splat(1.0);
    let e = f32x4::splat(relative) * (a * n) + f32x4::splat(absolute) * (one + a + n);
    (b * b - a * c, e)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Ray;
    use crate::sphere::{Sphere, SphereHit, reference};
    use glam::{DVec3, Vec3};
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    /// Lines from outside a sphere aimed at its silhouette, each direction
    /// rounded to `f32` and nudged by a few ulps, so that `Δ` is a tiny
    /// fraction of its terms, of either sign; with the spheres.
    fn grazing(n: usize, seed: u64, scale: f64) -> Vec<(Ray, Sphere)> {
        grazing_from(n, seed, scale, 3.0)
    }

    /// [`grazing`] from origins `near` radii or more from the centre
    /// (`near` above 1).
    fn grazing_from(n: usize, seed: u64, scale: f64, near: f64) -> Vec<(Ray, Sphere)> {
        let mut rng = SmallRng::seed_from_u64(seed);
        let mut v = |k: f64| k * (rng.random::<f64>() * 2.0 - 1.0);
        (0..n)
            .map(|_| {
                let c = DVec3::new(v(2.0), v(2.0), v(2.0)) * scale;
                let r = (1.25 + v(0.75)) * scale;
                let out = DVec3::new(v(1.0), v(1.0), v(1.0)).normalize();
                let l = r * (near + v(1.0).abs() * 4.0 * (near - 1.0));
                let o = (c + out * l).as_vec3();
                let f = o.as_dvec3() - c;
                let w = f.normalize().any_orthonormal_vector();
                let (l, r32) = (f.length(), r as f32);
                let h = r32 as f64 * l / (l * l - (r32 as f64).powi(2)).sqrt();
                let mut d = (w * h - f).as_vec3();
                for k in 0..3 {
                    let steps = (v(1.49)).round() as i32;
                    d[k] = f32::from_bits((d[k].to_bits() as i32 + steps) as u32);
                }
                (Ray::new(o, d), Sphere::new(c.as_vec3(), r32))
            })
            .collect()
    }

    /// How many lines the test calls misses where the reference finds a
    /// root, with `E_Δ`'s constants `relative` and `absolute`; how many it
    /// calls misses; how many have a root.
    fn wrong(cases: &[(Ray, Sphere)], relative: f32, absolute: f32) -> [usize; 3] {
        let [mut wrong, mut misses, mut hits] = [0; 3];
        for chunk in cases.chunks_exact(4) {
            let rays = Ray4::from_rays([0, 1, 2, 3].map(|i| chunk[i].0));
            let s = Sphere4::from_spheres([0, 1, 2, 3].map(|i| chunk[i].1));
            let m = certain_by(&rays, &s, relative, absolute).to_bitmask();
            for (i, (r, s)) in chunk.iter().enumerate() {
                let hit = reference::intersect(r, s) != SphereHit::None;
                let miss = m >> i & 1 == 1;
                hits += usize::from(hit);
                misses += usize::from(miss);
                wrong += usize::from(hit && miss);
            }
        }
        [wrong, misses, hits]
    }

    /// `wrong` in each floating-point environment: neither flag, FTZ,
    /// DAZ, both.
    fn in_every_environment(
        cases: &[(Ray, Sphere)],
        relative: f32,
        absolute: f32,
    ) -> [[usize; 3]; 4] {
        use crate::num::certify::in_environment;
        [(false, false), (true, false), (false, true), (true, true)].map(|(ftz, daz)| {
            let cases = cases.to_vec();
            in_environment(ftz, daz, move || wrong(&cases, relative, absolute))
        })
    }

    /// Grazing lines, about half of them hits whose `Δ` is a few `u` of
    /// its terms: with `E_Δ` as derived, no hit is called a miss, in any
    /// floating-point environment, at sizes from `2⁻¹⁰` to `2¹⁰` and from
    /// origins just off the sphere, where `ĉ` cancels; with the relative
    /// part cut to an eighth, some hits are. (The worst error seen in two
    /// million such lines is about `8u ân̂`, a fifth of the constant, so a
    /// quarter of it is not caught here.)
    #[test]
    fn grazing_hits_need_the_relative_bound() {
        let cases = grazing(40_000, 1, 1.0);
        let sets = [
            cases.clone(),
            grazing(8_000, 4, 2f64.powi(-10)),
            grazing(8_000, 5, 2f64.powi(10)),
            grazing_from(8_000, 6, 1.0, 1.0 + 2f64.powi(-8)),
        ];
        for set in &sets {
            for [wrong, _, hits] in in_every_environment(set, RELATIVE, ABSOLUTE) {
                assert_eq!(wrong, 0);
                assert!(hits > set.len() / 3, "{hits}");
            }
        }
        let [wrong, ..] = super::tests::wrong(&cases, RELATIVE / 8.0, ABSOLUTE);
        assert!(wrong > 0);
    }

    /// Grazing lines `2⁻³⁵` the size: their `Δ̂`'s terms are subnormal, and
    /// gradual underflow rounds them by up to `2⁻¹⁵⁰` where the relative
    /// part of `E_Δ` has underflowed to 0. Without the absolute part some
    /// hits are called misses; with it none are, in any environment. Lines
    /// `2⁶⁰` the size overflow: no lane is certified at all.
    #[test]
    fn tiny_lines_need_the_absolute_term_and_huge_ones_certify_nothing() {
        let tiny = grazing(40_000, 2, 2f64.powi(-35));
        let [unguarded, ..] = wrong(&tiny, RELATIVE, 0.0);
        assert!(unguarded > 0);
        for [wrong, _, hits] in in_every_environment(&tiny, RELATIVE, ABSOLUTE) {
            assert_eq!(wrong, 0);
            assert!(hits > 15_000, "{hits}");
        }
        let huge = grazing(4_000, 3, 2f64.powi(60));
        for [_, misses, hits] in in_every_environment(&huge, RELATIVE, ABSOLUTE) {
            assert_eq!(misses, 0);
            assert!(hits > 1_500, "{hits}");
        }
    }

    /// `E_Δ` is the derivation's, `42u ân̂ + 2⁻¹²⁰(1 + â + n̂)` with `â` and
    /// `n̂` summed in f32 as written, on lines whose `â` and `n̂` range
    /// from `2⁻⁴⁰` to `2⁴⁰`, where a wrong degree or operation in either
    /// part shows (the absolute part shows wherever `â` or `n̂` is not
    /// small).
    #[test]
    fn the_bound_is_the_derivations() {
        for e in (-20..=20).step_by(5) {
            let k = 2f32.powi(e);
            let rays = Ray4::from_rays([0.5, 1.0, 3.0, 7.0].map(|x| {
                Ray::new(
                    Vec3::new(x * k, -2.0 * k, 0.25 * k),
                    Vec3::new(k, 0.5, -3.0 * k),
                )
            }));
            let s = Sphere4::from_spheres(
                [1.0, 0.5, 2.0, 0.125]
                    .map(|r| Sphere::new(Vec3::new(0.1 * k, 0.0, 0.3 * k), r * k)),
            );
            let (_, got) = disc_and_bound(&rays, &s, RELATIVE, ABSOLUTE);
            let abs = disc_and_bound(&rays, &s, 0.0, ABSOLUTE).1;
            for l in 0..4 {
                let (r, sp) = (rays.to_rays()[l], s.radius.as_array()[l]);
                let d = r.dir;
                let f = r.origin - Vec3::new(0.1 * k, 0.0, 0.3 * k);
                let a = d.x * d.x + d.y * d.y + d.z * d.z;
                let n = (f.x * f.x + f.y * f.y + f.z * f.z) + sp * sp;
                let want = RELATIVE * (a * n) + ABSOLUTE * (1.0 + a + n);
                assert_eq!(got.as_array()[l], want, "scale 2^{e}, lane {l}");
                assert_eq!(
                    abs.as_array()[l],
                    ABSOLUTE * (1.0 + a + n),
                    "scale 2^{e}, lane {l}"
                );
            }
        }
    }

    /// The constants are the derivation's: twice `21u`, and `32η₀`.
    #[test]
    fn the_constants_are_the_derivations() {
        assert_eq!(RELATIVE, 42.0 * 2f32.powi(-24));
        assert_eq!(ABSOLUTE, 32.0 * 2f32.powi(-125));
        let rays = Ray4::splat(Ray::new(Vec3::new(0.0, 2.0, -5.0), Vec3::Z));
        let s = Sphere4::splat(&Sphere::new(Vec3::ZERO, 1.0));
        let by = certain_by(&rays, &s, RELATIVE, ABSOLUTE).to_bitmask();
        assert_eq!((certain(&rays, &s).to_bitmask(), by), (0b1111, 0b1111));
    }
}
