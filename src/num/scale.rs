//! Exact power-of-two prescaling, so that the double-word arithmetic never
//! overflows, never sinks into the subnormal range, and never splits a number
//! above `2^115` (see [`super::eft::split`]).
//!
//! Scaling by `2^k` is exact (barring underflow of components that are
//! negligible anyway next to the largest one), and every kernel knows how its
//! roots transform: a plane's `t` is unchanged by scaling `n`, every root
//! scales by `2^−k` when `d` is scaled by `2^k`, and by `2^k` when all
//! positions and lengths are.
//!
//! The scale is read off the largest magnitude's exponent bits and applied
//! as one multiplication by a power of two; the only integer work is one
//! subtraction, which matters for the SIMD path on baseline x86-64 (SSE2
//! has no packed 32-bit min/max). The roots are put back into the caller's
//! units once, at the end, with [`Lane::ldexp`].

use super::Lane;

/// The power of two that brings a set of values into range.
///
/// ```
/// use rayoracle::num::scale::Scale;
/// let s = Scale::of_max(&[3.0f32, -1e3, 0.5]);
/// assert_eq!(s.k, 9);
/// assert_eq!(s.apply(-1e3), -1e3 / 512.0);
/// ```
#[derive(Clone, Copy, Debug)]
pub struct Scale<L: Lane> {
    /// `2^−k`: multiplying by it brings the largest magnitude into `[1, 2)`
    /// (into `[2⁻²³, 1)` if it is subnormal, `[2, 4)` if it is `≥ 2¹²⁷`).
    pub down: L,
    /// `k`.
    pub k: L::Int,
}

impl<L: Lane> Scale<L> {
    /// The scale of `max |xᵢ|`.
    ///
    /// ```
    /// use rayoracle::num::scale::Scale;
    /// assert_eq!(Scale::of_max(&[0.0f32, 0.0]).k, -126);
    /// ```
    #[inline(always)]
    pub fn of_max(xs: &[L]) -> Self {
        let mut m = xs[0].abs();
        for &x in &xs[1..] {
            m = x.abs().max(m);
        }
        let p = m.pow2_floor();
        Scale {
            down: p.recip_pow2(),
            k: p.pow2_exponent(),
        }
    }

    /// `x · 2^−k`, exact.
    ///
    /// ```
    /// use rayoracle::num::scale::Scale;
    /// assert_eq!(Scale::of_max(&[8.0f32]).apply(12.0), 1.5);
    /// ```
    #[inline(always)]
    pub fn apply(&self, x: L) -> L {
        x * self.down
    }

    /// `v · 2^−k`, component-wise.
    ///
    /// ```
    /// use rayoracle::num::scale::Scale;
    /// assert_eq!(Scale::of_max(&[4.0f32]).apply3([4.0, 2.0, 1.0]), [1.0, 0.5, 0.25]);
    /// ```
    #[inline(always)]
    pub fn apply3(&self, v: [L; 3]) -> [L; 3] {
        [v[0] * self.down, v[1] * self.down, v[2] * self.down]
    }
}

/// The scale of a vector and the vector scaled by it.
///
/// ```
/// use rayoracle::num::scale::normalized3;
/// let (v, s) = normalized3([0.0f32, 6.0, -3.0]);
/// assert_eq!((v, s.k), ([0.0, 1.5, -0.75], 2));
/// ```
#[inline(always)]
pub fn normalized3<L: Lane>(v: [L; 3]) -> ([L; 3], Scale<L>) {
    let s = Scale::of_max(&v);
    (s.apply3(v), s)
}

/// Whether a magnitude is zero or within `[2^lo, 2^hi]`: the camera's
/// domain ([`crate::camera::in_domain`]) is stated with it.
/// A product of f32 values is formed exactly by Dekker's TwoProduct only
/// while it is above about `2⁻¹⁰³` (its error term must not underflow).
///
/// ```
/// use rayoracle::num::scale::in_range;
/// assert!(in_range(0.0, -50, 50) && in_range(1e-15, -50, 50));
/// assert!(!in_range(1e-16, -50, 50) && !in_range(1e16, -50, 50));
/// ```
pub fn in_range(s: f64, lo: i32, hi: i32) -> bool {
    s == 0.0 || (2f64.powi(lo)..=2f64.powi(hi)).contains(&s)
}

/// What scaling `x` by `s` in f32 loses: `|x·2^−k − fl(x·2^−k)|`, zero
/// unless a value far below the largest one of its group is pushed into the
/// subnormal range and rounded. The kernels' domains require the total loss
/// to be negligible (`≤ 2⁻⁶⁰`) against the sums it feeds.
///
/// ```
/// use rayoracle::num::scale::{Scale, crush_loss};
/// let s = Scale::of_max(&[1.7e38f32, 4.9e-39]);
/// assert_eq!(crush_loss(1.7e38, s), 0.0);
/// assert!(crush_loss(4.9e-39, s) > 0.0);
/// ```
pub fn crush_loss(x: f32, s: Scale<f32>) -> f64 {
    if !x.is_finite() {
        return 0.0;
    }
    (x as f64 * 2f64.powi(-s.k) - s.apply(x) as f64).abs()
}

/// `loss ≤ 2⁻⁶⁰ · scale`: a prescaling loss that cannot matter.
///
/// ```
/// assert!(rayoracle::num::scale::negligible(1e-30, 1.0));
/// assert!(!rayoracle::num::scale::negligible(1e-10, 1.0));
/// ```
pub fn negligible(loss: f64, scale: f64) -> bool {
    loss <= scale * 2f64.powi(-60)
}
