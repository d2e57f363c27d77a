//! The grids: powers of two that divide every term of α, β and γ, from
//! the lowest set bits of the data. A sum whose terms' magnitudes add up
//! below `2⁵²g`, `g` a grid of its terms, is exact in f64 in any order,
//! which is how the [later stages](super::after) prove sums exact without
//! checking each addition.

/// The exponent of the lowest set bit of a nonzero `x` widened from f32
/// (`x = m·2ᵉ` with `m` odd), less `−1022`, so that 0 (which lies on
/// every grid) wraps to `u32::MAX` and an unsigned minimum passes over
/// it: f32 data widens to normal f64 values of biased exponent at least
/// `874`, so the exponent field plus the trailing zeros of the
/// significand (with its implicit bit) is at least 874 for those, and 52
/// for 0. Meaningless, but harmless, for a non-finite `x`, whose terms
/// make every sum NaN.
#[inline(always)]
fn low_key(x: f64) -> u32 {
    // No branch on 0, which the data's zero coefficients would
    // mispredict; the implicit bit bounds the trailing zeros, and the
    // sign and exponent above it leave them alone.
    let b = x.to_bits();
    let e = ((b << 1) >> 53) as u32;
    (e + (b | 1 << 52).trailing_zeros()).wrapping_sub(53)
}

/// [`low_key`] as the exponent itself, 2000 for 0.
#[cfg(test)]
fn low_bit(x: f64) -> i32 {
    match low_key(x) {
        u32::MAX => 2000,
        k => k as i32 - 1022,
    }
}

/// A power of two `g` that divides every term `k·x·y` of α, β and γ: with
/// `2^κ` the least lowest set bit of the coefficients and `2^ν` that of
/// the origin, the direction and 1, every term is a multiple of `2^(κ +
/// 2ν)` (`ν ≤ 0`, and a term has at most two factors besides its
/// coefficient; a zero factor makes the term 0, on every grid). The
/// exponent is at least `−149·3` for f32 data; it is capped at 400, which
/// only applies where every coefficient is 0 (then every term is, and any
/// grid holds them) or not finite (then every sum is NaN), so that `g²`
/// is a normal f64 too.
///
/// ```
/// # use rayoracle::quadric::stages::grid;
/// // Coefficients 3 and 0.5 (2⁻¹), data 0.75 (lowest bit 2⁻²): 2⁻⁵.
/// let k = [3.0, 0.5, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0];
/// assert_eq!(grid(&k, [0.75, 2.0, 0.0], [1.0, 0.0, 0.0]), 2f64.powi(-5));
/// ```
#[doc(hidden)]
#[inline(always)]
pub fn grid(k: &[f64; 10], o: [f64; 3], d: [f64; 3]) -> f64 {
    // Minima by pairs, not one chain: their latency is on the way to
    // every later test.
    let m = |a: f64, b: f64| low_key(a).min(low_key(b));
    let kappa = (m(k[0], k[1]).min(m(k[2], k[3])))
        .min(m(k[4], k[5]).min(m(k[6], k[7])))
        .min(m(k[8], k[9]));
    // 1 (key 1022) among the data: ν ≤ 0.
    let nu = (m(o[0], o[1]).min(m(o[2], d[0]))).min(m(d[1], d[2]).min(1022));
    let e = (i64::from(kappa) + 2 * i64::from(nu) - 3066).clamp(-1000, 400);
    f64::from_bits(((1023 + e) as u64) << 52)
}

/// A power of two for each of α, β and γ that divides its terms, and so
/// is at least [`grid()`]: with `2^κ_q`, `2^κ_l` and `2^κ_c` the least lowest
/// set bits of the quadratic, the linear and the constant coefficients,
/// and `2^ν_o`, `2^ν_d` those of the origin and the direction, α's terms
/// `k·dᵢ·dⱼ` are multiples of `2^(κ_q + 2ν_d)`; β's, `k·oᵢ·dⱼ` (some
/// doubled) and `k·dᵢ`, of `2^min(κ_q + ν_o + ν_d, κ_l + ν_d)`; γ's,
/// `k·oᵢ·oⱼ`, `k·oᵢ` and the constant, of `2^min(κ_q + 2ν_o, κ_l + ν_o,
/// κ_c)`. Each exponent is capped as [`grid()`]'s: a group of factors all 0
/// makes its terms 0. An origin of many bits next to a direction of few,
/// as on a line along a cylinder's integer axis, leaves α's and β's grids
/// far coarser than the data's, so that they prove those sums exact where
/// γ's terms round.
///
/// ```
/// # use rayoracle::quadric::stages::{grid, grids};
/// // The cylinder x² + y² = 1 along its axis from an origin of 24 bits.
/// let k = [1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0];
/// let (o, d) = ([0.1f32 as f64, 0.0, 0.0], [0.0, 0.0, 2.0]);
/// let lo = 2f64.powi(-27);
/// assert_eq!(grids(&k, o, d), [4.0, 2.0 * lo, lo * lo]);
/// assert_eq!(grid(&k, o, d), lo * lo);
/// ```
#[doc(hidden)]
#[inline(always)]
pub fn grids(k: &[f64; 10], o: [f64; 3], d: [f64; 3]) -> [f64; 3] {
    let m = |a: f64, b: f64| low_key(a).min(low_key(b));
    let e = |k: u32| i64::from(k) - 1022;
    let (kq, kl, kc) = (
        e(m(k[0], k[1]).min(m(k[2], k[3])).min(m(k[4], k[5]))),
        e(m(k[6], k[7]).min(low_key(k[8]))),
        e(low_key(k[9])),
    );
    let (no, nd) = (
        e(m(o[0], o[1]).min(low_key(o[2]))),
        e(m(d[0], d[1]).min(low_key(d[2]))),
    );
    let pow2 = |e: i64| f64::from_bits(((1023 + e.clamp(-1000, 400)) as u64) << 52);
    [
        pow2(kq + 2 * nd),
        pow2((kq + no + nd).min(kl + nd)),
        pow2((kq + 2 * no).min(kl + no).min(kc)),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::num::dd::Dekker;
    use crate::quadric::stages::after::{ExactTerms, Pair};
    use rand::rngs::SmallRng;
    use rand::{Rng, SeedableRng};

    /// The exponent of the lowest set bit by a bit scan, for comparison:
    /// `|x| = m·2ᵉ`, `m` odd.
    fn low_exponent(x: f32) -> i32 {
        let b = x.to_bits() & !(1 << 31);
        let (e, f) = ((b >> 23) as i32, b & ((1 << 23) - 1));
        // A subnormal's fraction is read with the exponent of 2⁻¹²⁶.
        let m = if e == 0 { f } else { f | 1 << 23 };
        e.max(1) - 150 + m.trailing_zeros() as i32
    }

    /// `2ᵉ` for `e` from −1074 to 1023, subnormals included.
    fn pow2(e: i32) -> f64 {
        if e < -1022 {
            f64::from_bits(1 << (e + 1074))
        } else {
            f64::from_bits(((e + 1023) as u64) << 52)
        }
    }

    /// The lowest set bit of the values f32 data widens to: both zeros,
    /// the extremes of the range, and every other kind of f32 value at
    /// random, against a bit scan of the f32 encoding.
    #[test]
    fn low_bit_finds_the_lowest_set_bit() {
        let cases = [
            (1.0, 0),
            (-1.0, 0),
            (0.75, -2),
            (-3.0 * 2f32.powi(-5), -5),
            (1.0 + f32::EPSILON, -23),
            (f32::MAX, 104),
            (f32::from_bits(1), -149),
            (-f32::from_bits(6), -148),
            (f32::MIN_POSITIVE, -126),
            (0.0, 2000),
            (-0.0, 2000),
        ];
        for (x, want) in cases {
            assert_eq!(low_bit(f64::from(x)), want, "{x:e}");
        }
        let mut rng = SmallRng::seed_from_u64(0x10_b17);
        for _ in 0..100_000 {
            let x = f32::from_bits(
                rng.random::<u32>() & !(0xff << 23) | rng.random_range(0..0xff) << 23,
            );
            if x != 0.0 {
                assert_eq!(low_bit(f64::from(x)), low_exponent(x), "{x:e}");
            }
        }
    }

    /// The grid is `2^(κ + 2ν)` with the exponents found by bit scans, on
    /// f32 data of every magnitude, zeros, subnormals and values just above
    /// the least normal f32 among it (whose lowest bits are subnormal f32
    /// weights); the same under flush-to-zero, in which the later stages
    /// run, and under denormals-are-zero too where no input is subnormal
    /// (a subnormal input sends the reference to the oracle there).
    #[test]
    fn grid_is_the_least_lowest_bits() {
        type Case = ([f64; 10], [f64; 3], [f64; 3]);
        let mut rng = SmallRng::seed_from_u64(0x6_21d);
        let f = |rng: &mut SmallRng| match rng.random_range(0..9) {
            0 => 0.0,
            1 => f64::from(f32::from_bits(rng.random_range(1..1 << 23))),
            2 => f64::from(f32::from_bits(rng.random_range(1 << 23..27 << 23))),
            3 => 2f64.powi(rng.random_range(-149..128)),
            4 => f64::from(rng.random_range(-64i32..64)),
            _ => {
                let x = f32::from_bits(
                    rng.random::<u32>() & !(0xff << 23) | rng.random_range(0..0xff) << 23,
                );
                f64::from(x)
            }
        };
        let cases: Vec<Case> = (0..20_000)
            .map(|_| {
                let k: [f64; 10] = core::array::from_fn(|_| f(&mut rng));
                (k, [0; 3].map(|_| f(&mut rng)), [0; 3].map(|_| f(&mut rng)))
            })
            .collect();
        let want: Vec<f64> = cases
            .iter()
            .map(|(k, o, d)| {
                let scan = |x: f64| {
                    if x == 0.0 {
                        2000
                    } else {
                        low_exponent(x as f32)
                    }
                };
                let kappa = k.iter().map(|&c| scan(c)).min().unwrap();
                let nu = o.iter().chain(d).map(|&x| scan(x)).min().unwrap().min(0);
                pow2((kappa + 2 * nu).clamp(-1000, 400))
            })
            .collect();
        let grids = |c: &[Case]| {
            c.iter()
                .map(|(k, o, d)| grid(k, *o, *d))
                .collect::<Vec<_>>()
        };
        let check = |got: Vec<f64>, daz: bool, mode: &str| {
            for ((c, g), w) in cases.iter().zip(got).zip(&want) {
                let subnormal = |x: &f64| *x != 0.0 && x.abs() < f64::from(f32::MIN_POSITIVE);
                if daz && c.0.iter().chain(&c.1).chain(&c.2).any(subnormal) {
                    continue;
                }
                assert_eq!(g, *w, "{mode}: {c:?}");
            }
        };
        check(grids(&cases), false, "default");
        #[cfg(target_arch = "x86_64")]
        for (ftz, daz) in [(true, false), (true, true)] {
            let c = cases.clone();
            let got = crate::num::certify::in_environment(ftz, daz, move || grids(&c));
            check(got, daz, &format!("FTZ {ftz}, DAZ {daz}"));
        }
    }

    /// Each coefficient's grid ([`grids()`]) is the least lowest set bit of
    /// its own factors' groups, divides every exact term of its
    /// coefficient (both words of each TwoProduct pair), and is at least
    /// the data's [`grid()`], on data of every kind where whole groups (the
    /// direction, the origin, the quadratic, linear or constant
    /// coefficients) are often 0.
    #[test]
    fn each_coefficient_s_grid_divides_its_terms() {
        let mut rng = SmallRng::seed_from_u64(0x6_21d5);
        let f = |rng: &mut SmallRng| match rng.random_range(0..8) {
            0 => 0.0,
            1 => f64::from(f32::from_bits(rng.random_range(1..1 << 23))),
            2 => 2f64.powi(rng.random_range(-149..128)),
            3 => f64::from(rng.random_range(-64i32..64)),
            _ => f64::from(f32::from_bits(
                rng.random::<u32>() & !(0xff << 23) | rng.random_range(1..0xff) << 23,
            )),
        };
        let scan = |x: &[f64]| {
            x.iter()
                .map(|&x| {
                    if x == 0.0 {
                        2000
                    } else {
                        low_exponent(x as f32)
                    }
                })
                .min()
                .unwrap()
        };
        let mut coarser = 0;
        for n in 0..20_000 {
            let mut k: [f64; 10] = core::array::from_fn(|_| f(&mut rng));
            let (mut o, mut d) = ([0; 3].map(|_| f(&mut rng)), [0; 3].map(|_| f(&mut rng)));
            // One group zeroed in each of five cases.
            match n % 8 {
                0 => d = [0.0; 3],
                1 => o = [0.0; 3],
                2 => k[..6].fill(0.0),
                3 => k[6..9].fill(0.0),
                4 => k[9] = 0.0,
                _ => {}
            }
            let (kq, kl, kc, no, nd) = (
                scan(&k[..6]),
                scan(&k[6..9]),
                scan(&k[9..]),
                scan(&o),
                scan(&d),
            );
            let want = [
                kq + 2 * nd,
                (kq + no + nd).min(kl + nd),
                (kq + 2 * no).min(kl + no).min(kc),
            ]
            .map(|e| pow2(e.clamp(-1000, 400)));
            let got = grids(&k, o, d);
            assert_eq!(got, want, "{k:?} {o:?} {d:?}");
            let g = grid(&k, o, d);
            assert!(got.iter().all(|&x| x >= g), "{k:?} {o:?} {d:?}");
            coarser += usize::from(got.iter().any(|&x| x > g));
            let t = ExactTerms::new::<Dekker>(&k, o, d);
            let terms: [&[Pair]; 3] = [&t.0, &t.1, &t.2];
            for (terms, g) in terms.iter().zip(got) {
                for p in terms.iter() {
                    for x in [p.0, p.1].into_iter().filter(|x| x.is_finite()) {
                        assert_eq!((x / g).fract(), 0.0, "{x:e} on {g:e}: {k:?} {o:?} {d:?}");
                    }
                }
            }
        }
        // The point of them: most data has some coefficient's grid above
        // the data's.
        assert!(coarser > 10_000, "{coarser}");
    }
}
