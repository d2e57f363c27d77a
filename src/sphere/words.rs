//! The words stage: the discriminant as `Δ = aR² − |f × d|²`, in two
//! words, from exact products summed in trees with running error bounds.
//! It decides the near tangents the filter leaves open in a few dozen
//! operations that mostly run side by side, where the [double-word
//! stage](super::stages::double_word) checks every addition of one long
//! chain by TwoSum, for the exact zeros.
//!
//! # The form
//!
//! Lagrange's identity, `|f|²|d|² − (f·d)² = |f × d|²`, turns `Δ = b² − ac
//! = (f·d)² − (d·d)(f·f − R²)` into
//!
//! ```text
//! Δ = a R² − |m|²,   m = f × d,   mᵢ = f_j d_k − f_k d_j.
//! ```
//!
//! `|m|` is `|d|` times the distance from the centre to the line, so near a
//! tangent both terms are about `aR²`, and `Δ`'s errors scale with `aR²`,
//! where the textbook form's scale with `(f·d)² + a(f·f + R²)`: far less
//! for a sphere seen from afar. The components of `m` cancel only where the
//! line nearly passes through the centre, far from a tangent.
//!
//! # The sums
//!
//! The inputs are f32 values, exact in f64, and every value below is a
//! multiple of `2⁻²⁹⁸` (products of two f32 values, their sums and the
//! errors of both) or, in `Δ`'s products, of `2⁻⁵⁹⁶`, so TwoProduct is
//! exact ([`crate::num::dd`]) and no product or error underflows; `|f|
//! ≤ 2¹²⁹` and `|d| ≤ 2¹²⁸` keep every product and sum below `2⁵²⁰`.
//!
//! * `(φᵢ, ψᵢ) = TwoSum(oᵢ, −Cᵢ)`, exactly `fᵢ = φᵢ + ψᵢ`.
//! * A sum of two sums in words, `(h, l) + (h′, l′)`, is `(s, e) =
//!   TwoSum(h, h′)` with the low word `fl(fl(l + l′) + e)`: the leading
//!   words' sum is exact, and each of the two roundings in the low word is
//!   at most `u` times its computed result `x̂` (`crate::num::dd`, *The
//!   sums' bounds*). Summed in any tree, the exact sum is the two words
//!   within `E = u Σ|x̂|` over the low word's additions (the running bound).
//! * `mᵢ = h_i + l_i ± E_i`: the exact products `φ_j d_k` and `−φ_k d_j`
//!   (and, where `f` is not exact in one word, `ψ_j d_k` and `−ψ_k d_j`)
//!   by TwoProduct, summed so.
//! * `Δ` sums the exact products `dᵢ²·R²` (`dᵢ²` and `R²` are exact: 48
//!   bits each) and `−h_i²` by TwoProduct, then takes
//!   `Ĝ = fl(fl(ĝ₀ + ĝ₁) + ĝ₂)` from its low word, where
//!   `ĝᵢ = fl(2h_i l_i)` is off by at most `u|ĝᵢ|`: two more roundings
//!   for the running bound, and one in the low word. It leaves out
//!   `−l_i²`. With `|mᵢ² − (h_i + l_i)²| ≤ E_i(2|h_i| + 2|l_i| + E_i)`,
//!   the words of `Δ` miss it by at most their running bound plus
//!
//!   ```text
//!   Σᵢ u|ĝᵢ| + l_i² + E_i(2|h_i| + 2|l_i| + E_i).
//!   ```
//!
//! TwoSum renormalises `Δ`'s words exactly. The bound is widened by
//! [`SLACK`], which covers its own roundings (a few dozen non-negative
//! terms, within `γ₃₀` of their exact sum) and the products by `u`
//! (exact: an addition of multiples of `2⁻⁵⁹⁶` rounds only at a result of
//! at least `2⁵³·2⁻⁵⁹⁶`, so `u Σ|x̂|` is normal, and where none rounds the
//! bound is not needed).
//!
//! Where nothing rounds the bound is 0 and `Δ` exact, its zero too;
//! elsewhere the bound is a few `u²aR²`. Since `Δ = a(R² − ρ²)` for a
//! line at a distance `ρ` from the centre, the stage decides a line with
//! `|ρ − R|` down to about `2⁻¹⁰⁰R`, where the filter, whose bound is
//! `20u(m_b² + a m_c) ≥ 20u·a(f·f + R²)`, stops near `2⁻⁴⁷R` from an origin
//! near the sphere and sooner from afar. A nearer tangent goes on to the
//! double-word stage, whose third word reaches further.
//!
//! # The answer
//!
//! `Δ`'s sign where its bound decides it (`|Δ̂| > 2E`); a tangent where
//! `Δ` is exactly 0 (its words 0 and its bound 0 as derived, unshrunk:
//! exactness is proven, not bounded), its root `−b/a`; two roots by
//! [`two_roots`] from the filter's `a`, `b` and `c` with its bounds
//! ([`super::stages`]), which certify wherever `√Δ` is known well enough
//! and `b` does not cancel. Every bound is multiplied by `shrink`, once,
//! where it decides.
//!
//! [`SLACK`]: crate::num::certify::SLACK
//! [`two_roots`]: crate::num::dd::two_roots

use super::SphereHit;
use super::stages::{Classes, classes};
use crate::num::certify::{SLACK, U};
use crate::num::dd::{Dd, Dekker, Product, quotient, two_roots, two_sum};

/// The words stage on a line `o + t d` and a sphere `(c, r)` (f32 values
/// widened), every bound multiplied by `shrink`: the class and the roots,
/// or `None` where a bound leaves either undecided.
///
/// ```
/// use rayoracle::sphere::{SphereHit, stages::filter, words::words};
/// // Grazing R = 3 at (0, 3, 0) along z, tilted by ε = 2⁻⁴⁰ in x: with
/// // δ = 0.1f32, Δ = −ε²δ², about 2⁻⁷³ of b² = δ⁴, which f64 loses and
/// // two words keep: the line misses.
/// let (o, d) = ([0.0, 3.0, -0.1f32 as f64], [2f64.powi(-40), 0.0, 0.1f32 as f64]);
/// let f = filter::<f64>(o, d, [0.0; 3], 3.0, 1.0);
/// assert!(!f.two && !f.none);
/// assert_eq!(words(o, d, [0.0; 3], 3.0, 1.0), Some(SphereHit::None));
/// ```
pub fn words(o: [f64; 3], d: [f64; 3], c: [f64; 3], r: f64, shrink: f64) -> Option<SphereHit> {
    words_by::<Dekker>(&classes(o, d, c, r, 1.0), o, d, c, r, shrink)
}

/// [`words`] from the filter's [`classes`] `k`, with the products' errors
/// found by `P`: the same exact pairs whichever `P`, so the same answers.
#[inline(always)]
pub(crate) fn words_by<P: Product>(
    k: &Classes<f64>,
    o: [f64; 3],
    d: [f64; 3],
    c: [f64; 3],
    r: f64,
    shrink: f64,
) -> Option<SphereHit> {
    if !k.line() {
        return Some(SphereHit::None);
    }
    let disc = discriminant::<P>(o, d, c, r);
    let class = disc.shrunk(shrink);
    if class.sign_known() && disc.hi < 0.0 {
        return Some(SphereHit::None);
    }
    let [a, b, c] = k.quadratic();
    if disc.is_zero() {
        return quotient(-b, a, shrink).map(SphereHit::Tangent);
    }
    if !class.sign_known() {
        return None;
    }
    let (t0, t1) = two_roots(a, b, c, disc.approx(), shrink)?;
    Some(SphereHit::Two(t0, t1))
}

/// `Δ = aR² − |m|²` in two words, with its bound as derived in the
/// [module](self), widened by [`SLACK`] and not shrunk.
#[inline(always)]
fn discriminant<P: Product>(o: [f64; 3], d: [f64; 3], c: [f64; 3], r: f64) -> Dd {
    let f = [
        two_sum(o[0], -c[0]),
        two_sum(o[1], -c[1]),
        two_sum(o[2], -c[2]),
    ];
    let split = (f[0].1.to_bits() | f[1].1.to_bits() | f[2].1.to_bits()) << 1 != 0;
    let pair = |x: f64, y: f64| Words::pair(P::two_prod(x, y));
    // mᵢ = f_j d_k − f_k d_j.
    let moment = |j: usize, k: usize| {
        let m = pair(f[j].0, d[k]).add(pair(-f[k].0, d[j]));
        if split {
            m.add(pair(f[j].1, d[k]).add(pair(-f[k].1, d[j])))
        } else {
            m
        }
    };
    let m = [moment(1, 2), moment(2, 0), moment(0, 1)];
    let rr = r * r;
    let ar = pair(d[0] * d[0], rr)
        .add(pair(d[1] * d[1], rr))
        .add(pair(d[2] * d[2], rr));
    let g = m.map(|m| (m.hi + m.hi) * m.lo);
    let squares =
        (pair(-m[0].hi, m[0].hi).add(pair(-m[1].hi, m[1].hi))).add(pair(-m[2].hi, m[2].hi));
    let g01 = g[0] + g[1];
    let gs = g01 + g[2];
    let mut disc = ar.add(squares).sub_low(gs, g01.abs() + gs.abs()).finish();
    let lost = |m: &Words, g: f64| {
        let e = U * m.run;
        U * g.abs() + m.lo * m.lo + e * (2.0 * (m.hi.abs() + m.lo.abs()) + e)
    };
    disc.err = (disc.err + (lost(&m[0], g[0]) + lost(&m[1], g[1]) + lost(&m[2], g[2]))) * SLACK;
    disc
}

/// A sum in two words, `hi + lo`, within `u·run` of the exact sum of its
/// terms: `run` sums the magnitudes of the low word's computed partial
/// sums.
#[derive(Clone, Copy)]
struct Words {
    hi: f64,
    lo: f64,
    run: f64,
}

impl Words {
    /// An exact pair, `hi + lo`.
    #[inline(always)]
    fn pair((hi, lo): (f64, f64)) -> Words {
        Words { hi, lo, run: 0.0 }
    }
    /// The sum of two sums: TwoSum of the leading words, the low words and
    /// its error added plainly, their two results' magnitudes to `run`.
    #[inline(always)]
    fn add(self, y: Words) -> Words {
        let (hi, e) = two_sum(self.hi, y.hi);
        let l = self.lo + y.lo;
        let lo = l + e;
        Words {
            hi,
            lo,
            run: (self.run + y.run) + (l.abs() + lo.abs()),
        }
    }
    /// The sum minus `x` in the low word, `mag` the magnitudes of the
    /// computed partial sums that made `x` (summed single words), added
    /// to `run` with that of the new low word.
    #[inline(always)]
    fn sub_low(self, x: f64, mag: f64) -> Words {
        let lo = self.lo - x;
        Words {
            lo,
            run: self.run + (mag + lo.abs()),
            ..self
        }
    }
    /// The sum renormalised, with its running bound (not yet widened).
    #[inline(always)]
    fn finish(self) -> Dd {
        let (hi, lo) = two_sum(self.hi, self.lo);
        Dd {
            hi,
            lo,
            err: U * self.run,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Ray;
    use crate::hit::same_bits;
    use crate::sphere::{Sphere, exact, stages::filter};
    use glam::Vec3;

    /// The words stage's bound on `Δ` is the derivation's
    /// ([module](super)): `SLACK·(u Σ|x̂| + Σᵢ (u|ĝᵢ| + lᵢ² + Eᵢ(2|hᵢ| +
    /// 2|lᵢ| + Eᵢ)))`, `Σ|x̂|` over the computed partial sums of `Δ`'s low
    /// word (those of `ĝ₀ + ĝ₁` and `ĝ` among them) and `Eᵢ = u Σ|x̂|`
    /// over those of `mᵢ`'s, recomputed from the derivation with either
    /// product and compared bit for bit (the magnitudes are summed in the
    /// stage's order). No committed case is led by these terms, so this is
    /// what holds them to the derivation.
    #[test]
    fn the_words_bound_is_the_derivations() {
        use crate::num::dd::{Fused, Product, two_sum};
        use rand::{Rng, SeedableRng, rngs::SmallRng};
        /// A sum in words with `Σ|x̂|` over its low word's partial sums,
        /// added in the stage's order, so that the bits must agree.
        struct Kept {
            hi: f64,
            lo: f64,
            run: f64,
        }
        fn plus(x: Kept, y: Kept) -> Kept {
            let (hi, e) = two_sum(x.hi, y.hi);
            let l = x.lo + y.lo;
            let lo = l + e;
            let run = (x.run + y.run) + (l.abs() + lo.abs());
            Kept { hi, lo, run }
        }
        /// The words and bound of `Δ`, and whether a moment's low word is
        /// above `2⁻³⁰` of its leading one (its leading products cancel).
        fn want<P: Product>(o: [f64; 3], d: [f64; 3], c: [f64; 3], r: f64) -> (Dd, bool) {
            let exact = |x: f64, y: f64| {
                let (hi, lo) = P::two_prod(x, y);
                Kept { hi, lo, run: 0.0 }
            };
            let f = [0, 1, 2].map(|i| two_sum(o[i], -c[i]));
            let split = f.iter().any(|f| f.1 != 0.0);
            let m = [(1, 2), (2, 0), (0, 1)].map(|(j, k)| {
                let m = plus(exact(f[j].0, d[k]), exact(-f[k].0, d[j]));
                match split {
                    true => plus(m, plus(exact(f[j].1, d[k]), exact(-f[k].1, d[j]))),
                    false => m,
                }
            });
            let rr = r * r;
            let ar = plus(
                plus(exact(d[0] * d[0], rr), exact(d[1] * d[1], rr)),
                exact(d[2] * d[2], rr),
            );
            let sq = |i: usize| exact(-m[i].hi, m[i].hi);
            let mut disc = plus(ar, plus(plus(sq(0), sq(1)), sq(2)));
            let g = m.each_ref().map(|m| 2.0 * m.hi * m.lo);
            let (g01, gs) = (g[0] + g[1], g[0] + g[1] + g[2]);
            disc.lo -= gs;
            disc.run += (g01.abs() + gs.abs()) + disc.lo.abs();
            let lost: f64 = (0..3)
                .map(|i| {
                    let (h, l, e) = (m[i].hi, m[i].lo, U * m[i].run);
                    U * g[i].abs() + l * l + e * (2.0 * h.abs() + 2.0 * l.abs() + e)
                })
                .sum();
            let (hi, lo) = two_sum(disc.hi, disc.lo);
            let err = SLACK * (U * disc.run + lost);
            let cancels = m.iter().any(|m| m.lo.abs() > 2f64.powi(-30) * m.hi.abs());
            (Dd { hi, lo, err }, cancels)
        }
        let mut rng = SmallRng::seed_from_u64(0x30d5);
        let mut x = |scale: i32| {
            let v: f32 = rng.random_range(-1.0..1.0);
            (v * 2f32.powi(rng.random_range(-scale..=scale))) as f64
        };
        // Three kinds of line: centres from far wider binades than the
        // origins, so that `f` often takes two words; origins and centres
        // near integers, so that it takes one; and directions along `f`
        // rounded to f32, past a small sphere, so that the moments cancel
        // and their own bounds lead.
        let mut count = [0; 3];
        for i in 0..6000 {
            let (o, c) = ([x(8), x(8), x(8)], [x(40), x(40), x(40)]);
            let (o, c, d, r) = match i % 3 {
                0 => (o, c, [x(20), x(20), x(20)], x(8).abs()),
                1 => (
                    o.map(|v| v.round() + 0.5),
                    o.map(f64::round),
                    [x(20), x(20), x(20)],
                    x(8).abs(),
                ),
                _ => (
                    o,
                    c,
                    [0, 1, 2].map(|i| (o[i] - c[i]) as f32 as f64),
                    x(8).abs() * 2f64.powi(-30),
                ),
            };
            let split = (0..3).any(|i| two_sum(o[i], -c[i]).1 != 0.0);
            for (got, (want, cancels)) in [
                (
                    discriminant::<Dekker>(o, d, c, r),
                    want::<Dekker>(o, d, c, r),
                ),
                (discriminant::<Fused>(o, d, c, r), want::<Fused>(o, d, c, r)),
            ] {
                let at = format!("{o:?} {d:?} {c:?} {r}");
                assert_eq!((got.hi, got.lo), (want.hi, want.lo), "{at}");
                assert_eq!(got.err, want.err, "{at}");
                count[0] += usize::from(split && got.err > 0.0);
                count[1] += usize::from(!split && got.err > 0.0);
                count[2] += usize::from(cancels);
            }
        }
        assert!(count.iter().all(|&n| n >= 1000), "{count:?}");
    }

    /// Lines along z past the sphere of radius 5 whose centre is `−ε` in x
    /// and `∓ε` in y from the origin's `(3, 4)`, `ε = 2⁻⁶⁰`: `f = o − C`
    /// is `3 + ε` and `4 ± ε`, two words each, with low words equal or
    /// opposite. Their leading words alone make an exact tangent; the low
    /// words make `Δ = 25 − |f|²` a miss (`−14ε − 2ε²`), which the stage
    /// decides, or two roots (`2ε − 2ε²`, the roots `±√Δ`, which it
    /// leaves: the filter's `c` has lost them), `2⁻⁵⁶` from 0 where the
    /// filter cannot see either. The same with the axes turned.
    #[test]
    fn the_low_words_of_every_component_count() {
        let e = 2f32.powi(-60);
        for (k, (cy, decided)) in (0..3).flat_map(|k| [(k, (-e, true)), (k, (e, false))]) {
            // The same turned by k axes, so that each pair of components
            // carries the low words once.
            let turn = |mut v: [f32; 3]| {
                v.rotate_right(k);
                v
            };
            let (o, d, c) = (
                turn([3.0, 4.0, 0.0]),
                turn([0.0, 0.0, 1.0]),
                turn([-e, cy, 0.0]),
            );
            let w = |v: [f32; 3]| v.map(f64::from);
            let f = filter::<f64>(w(o), w(d), w(c), 5.0, 1.0);
            assert!(!f.two && !f.none);
            let (ray, s) = (
                Ray::new(Vec3::from(o), Vec3::from(d)),
                Sphere::new(Vec3::from(c), 5.0),
            );
            let exact = exact::intersect(&ray, &s).unwrap();
            assert_eq!(decided, exact == SphereHit::None, "{exact:?}");
            match words(w(o), w(d), w(c), 5.0, 1.0) {
                Some(got) => assert!(same_bits(&got, &exact), "{got:?} {exact:?}"),
                None => assert!(!decided, "{exact:?} left"),
            }
        }
    }
}
