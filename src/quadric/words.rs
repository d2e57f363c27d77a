//! α, β and γ in double words, on the four lanes of one AVX register:
//! the later stages' sums of the 28 exact terms, for CPUs with AVX2 and
//! FMA. Exact under a grid test ([`exact`]), for the stages that settle
//! exact zeros; within a bound of about `u²` times the terms' magnitudes
//! on any data ([`bounded`]), for the words stage
//! ([`words`](super::stages::words)).
//!
//! # The lanes
//!
//! Each quadratic coefficient `c` with inputs `i`, `j` ([`QUADRATIC`])
//! gives one term to each of α, β (two) and γ: with `X = c·(d_i, o_i,
//! d_i, o_i)` (products of two f32 values, exact) and `Y = (d_j, d_j,
//! o_j, o_j)`, the lanes of `XY` are `c d_i d_j` (α's term), `c o_i d_j`
//! and `c d_i o_j` (β's two, the square term's two halves where `i = j`)
//! and `c o_i o_j` (γ's). TwoProduct by one fused multiply-add splits
//! each lane exactly (`H = fl(XY)`, `L = XY − H`, as [`Fused`]); the
//! linear terms `c d_i` and `c o_i`, and `J`, are exact single words in
//! lanes 1 and 3.
//!
//! # The sums
//!
//! Each lane is a [`GridAcc`] of its own: the leading words through
//! TwoSum, every error into the low word by plain additions, and the sum
//! of those errors' magnitudes `m` for the grid test. Lanes 1 and 2 are
//! then joined by one more TwoSum. Every value entering a low word is a
//! multiple of the data's [`grid`](super::stages::grid()) `g` (products,
//! their errors and TwoSum's errors of multiples of `g` are), and each
//! low word's partial sums, lane 1's and 2's joined included, are sums of
//! subsets of those values: where their magnitudes sum below `2⁵²g`
//! (`m(1 + 2⁻³⁰) < 2⁵²g`, the slack covering the rounding of `m`), each
//! is a multiple of `g` below `2⁵³g` and exact. So each sum is exact as
//! its two words, renormalised by TwoSum, or the test fails and the
//! caller sums again with running bounds. The same words and test as
//! [`GridAcc::finish_exact`] on the same values, in another order of
//! addition, which exact sums do not see.
//!
//! [`Fused`]: crate::num::dd::Fused
//! [`GridAcc`]: crate::num::dd::GridAcc
//! [`GridAcc::finish_exact`]: crate::num::dd::GridAcc::finish_exact

use super::stages::{QUADRATIC, bounded_lanes, tree_sum};
use crate::num::avx::Avx4;
use crate::num::certify::SLACK;
use crate::num::dd::{Dd, two_sum};
use crate::num::real::Real;

/// α, β and γ of the line `o + t d` on the quadric `k` as exact double
/// words (`err = 0`), or `None` where a grid test fails on the grid `g`
/// (the [module](self)'s sums). The inputs are f32 values widened.
///
/// Only inside a function compiled for AVX2 and FMA and entered with an
/// [`Avx2`](crate::num::avx::Avx2) token, as every use of [`Avx4`].
/// Written without closures, which are not always inlined into that
/// function, and outside it would call each AVX instruction.
#[inline(always)]
pub(crate) fn exact(k: &[f64; 10], o: [f64; 3], d: [f64; 3], g: f64) -> Option<[Dd; 3]> {
    let ([ah, bh, ch], [al, bl, cl], [am, bm, cm]) = sums(k, o, d);
    let limit = g * 4_503_599_627_370_496.0;
    Some([
        word(ah, al, am, limit)?,
        word(bh, bl, bm, limit)?,
        word(ch, cl, cm, limit)?,
    ])
}

/// α, β and γ of the line `o + t d` on the quadric `k` in double words
/// with their bounds, from the filter's magnitude sums `m`: the
/// [module](self)'s sums, without the grid, as the scalar
/// `bounded_words` of the later stages computes them one lane at a time
/// (the same operations in the same order, so the same words), with its
/// bound.
///
/// Under the same conditions as [`exact`].
#[inline(always)]
pub(crate) fn bounded(k: &[f64; 10], o: [f64; 3], d: [f64; 3], m: [f64; 3]) -> [Dd; 3] {
    let lin = |i: usize| Avx4::new(0.0, k[6 + i] * d[i], 0.0, k[6 + i] * o[i]);
    let (h, l) = tree_sum(
        [
            term(k, o, d, QUADRATIC[0]),
            term(k, o, d, QUADRATIC[1]),
            term(k, o, d, QUADRATIC[2]),
            term(k, o, d, QUADRATIC[3]),
            term(k, o, d, QUADRATIC[4]),
            term(k, o, d, QUADRATIC[5]),
        ],
        [lin(0), lin(1), lin(2)],
        Avx4::new(0.0, 0.0, 0.0, k[9]),
    );
    bounded_lanes(h.to_array(), l.to_array(), m)
}

/// The leading words, the low words and the sums of the low values'
/// magnitudes of α, β and γ, β's two lanes joined by one more TwoSum
/// (its error to the low word).
#[inline(always)]
#[allow(clippy::type_complexity)]
fn sums(k: &[f64; 10], o: [f64; 3], d: [f64; 3]) -> ([f64; 3], [f64; 3], [f64; 3]) {
    let mut acc = Sums::start(term(k, o, d, QUADRATIC[0]));
    for &q in &QUADRATIC[1..] {
        acc.add_pair(term(k, o, d, q));
    }
    for i in 0..3 {
        acc.add(Avx4::new(0.0, k[6 + i] * d[i], 0.0, k[6 + i] * o[i]));
    }
    acc.add(Avx4::new(0.0, 0.0, 0.0, k[9]));
    let (h, l, m) = (acc.hi.to_array(), acc.lo.to_array(), acc.mag.to_array());
    let (bh, e) = two_sum(h[1], h[2]);
    let (bl, bm) = ((l[1] + l[2]) + e, (m[1] + m[2]) + e.abs());
    ([h[0], bh, h[3]], [l[0], bl, l[3]], [m[0], bm, m[3]])
}

/// The quadratic coefficient `c`'s terms `k_c x y` on the four lanes, as
/// TwoProduct's words.
#[inline(always)]
fn term(k: &[f64; 10], o: [f64; 3], d: [f64; 3], (c, i, j): (usize, usize, usize)) -> (Avx4, Avx4) {
    let x = Avx4::splat(k[c]) * Avx4::new(d[i], o[i], d[i], o[i]);
    let y = Avx4::new(d[j], d[j], o[j], o[j]);
    let h = x * y;
    (h, x.mul_sub(y, h))
}

/// Four [`GridAcc`](crate::num::dd::GridAcc)s at once, without running
/// bounds.
struct Sums {
    hi: Avx4,
    lo: Avx4,
    mag: Avx4,
}

impl Sums {
    /// The sums of one pair of words each.
    #[inline(always)]
    fn start((hi, lo): (Avx4, Avx4)) -> Sums {
        Sums {
            hi,
            lo,
            mag: lo.abs(),
        }
    }
    /// Adds a pair of words in each lane.
    #[inline(always)]
    fn add_pair(&mut self, (p, e): (Avx4, Avx4)) {
        let (s, e1) = two_sum(self.hi, p);
        self.hi = s;
        self.lo = self.lo + (e + e1);
        self.mag = self.mag + (e.abs() + e1.abs());
    }
    /// Adds one exact word in each lane.
    #[inline(always)]
    fn add(&mut self, p: Avx4) {
        let (s, e1) = two_sum(self.hi, p);
        self.hi = s;
        self.lo = self.lo + e1;
        self.mag = self.mag + e1.abs();
    }
}

/// A sum's two words, renormalised, where the grid test proves them
/// exact.
#[inline(always)]
fn word(hi: f64, lo: f64, m: f64, limit: f64) -> Option<Dd> {
    let (hi, lo) = two_sum(hi, lo);
    (m * SLACK < limit).then_some(Dd { hi, lo, err: 0.0 })
}
