//! The one error measure used everywhere: ULP distance to the correctly
//! rounded value, and bits of error `log₂(ulps + 1)` as Herbie defines it.

/// The position of `x` on the ordered line of floats: consecutive floats
/// differ by one, `+0` and `−0` share position 0, `±∞` sit one step past
/// `±f32::MAX`.
///
/// ```
/// use rayoracle::ulp::ordinal;
/// assert_eq!(ordinal(1.0) - ordinal(1.0 - f32::EPSILON / 2.0), 1);
/// assert_eq!(ordinal(-0.0), ordinal(0.0));
/// // Negative floats sit below zero, mirrored (cargo-mutants found these
/// // lines untested: a sign-blind ordinal passed every other test).
/// assert_eq!(ordinal(-1.0), -ordinal(1.0));
/// assert_eq!(ordinal(-f32::from_bits(1)), -1);
/// assert!(ordinal(-2.0) < ordinal(-1.0));
/// ```
pub fn ordinal(x: f32) -> i64 {
    let b = x.to_bits();
    let mag = (b & 0x7fff_ffff) as i64;
    if b >> 31 == 1 { -mag } else { mag }
}

/// The float `n` positions from `x` on the [`ordinal`] line (`+0` at
/// position 0), saturating at `±∞`; NaN stays NaN.
///
/// ```
/// use rayoracle::ulp::step;
/// assert_eq!(step(1.0, 1), 1.0 + f32::EPSILON);
/// assert_eq!(step(1.0, -1), 1.0 - f32::EPSILON / 2.0);
/// assert_eq!(step(f32::from_bits(1), -2), -f32::from_bits(1));
/// assert_eq!(step(-0.0, 0).to_bits(), 0.0f32.to_bits());
/// assert_eq!(step(f32::MAX, 5), f32::INFINITY);
/// assert_eq!(step(-f32::MAX, i64::MIN), f32::NEG_INFINITY);
/// ```
pub fn step(x: f32, n: i64) -> f32 {
    if x.is_nan() {
        return x;
    }
    let inf = ordinal(f32::INFINITY);
    let k = ordinal(x).saturating_add(n).clamp(-inf, inf);
    let mag = f32::from_bits(k.unsigned_abs() as u32);
    if k < 0 { -mag } else { mag }
}

/// The number of floats between `a` and `b` (0 if equal, `±0` equal), or
/// `u64::MAX` if exactly one of them is NaN. Two NaNs are at distance 0.
///
/// ```
/// use rayoracle::ulp::ulps;
/// assert_eq!(ulps(1.0, 1.0 + f32::EPSILON), 1);
/// assert_eq!(ulps(f32::NAN, f32::NAN), 0);
/// assert_eq!(ulps(f32::NAN, 0.0), u64::MAX);
/// assert_eq!(ulps(f32::MAX, f32::INFINITY), 1);
/// // Across zero: the two smallest subnormals of opposite sign are 2 apart.
/// assert_eq!(ulps(-f32::from_bits(1), f32::from_bits(1)), 2);
/// ```
pub fn ulps(a: f32, b: f32) -> u64 {
    match (a.is_nan(), b.is_nan()) {
        (true, true) => 0,
        (false, false) => (ordinal(a) - ordinal(b)).unsigned_abs(),
        _ => u64::MAX,
    }
}

/// Bits of error: `log₂(ulps + 1)`. 0 for exact, 1 for one ulp, 32 at most.
///
/// ```
/// use rayoracle::ulp::bits;
/// assert_eq!(bits(0), 0.0);
/// assert_eq!(bits(1), 1.0);
/// assert_eq!(bits(3), 2.0);
/// ```
pub fn bits(ulps: u64) -> f64 {
    ((ulps as f64) + 1.0).log2().min(64.0)
}

/// The size of one ulp at `x` (the gap to the next float away from zero), in
/// f64: `2^(e−23)` for normal `x`, `2^−149` for subnormal.
///
/// ```
/// use rayoracle::ulp::ulp_of;
/// assert_eq!(ulp_of(1.0), f32::EPSILON as f64);
/// assert_eq!(ulp_of(0.0), 2f64.powi(-149));
/// ```
pub fn ulp_of(x: f64) -> f64 {
    let a = x.abs();
    if !(a >= f32::MIN_POSITIVE as f64) {
        return 2f64.powi(-149);
    }
    let e = ((a.to_bits() >> 52) & 0x7ff) as i32 - 1023;
    2f64.powi(e - 23)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `step` walks the ordinal line: `n` steps from `x` land at
    /// `ordinal(x) + n`, across zero and the subnormals, and stop at the
    /// infinities; position 0 is `+0`, and NaN stays NaN.
    #[test]
    fn step_walks_the_ordinal_line() {
        let inf = ordinal(f32::INFINITY);
        let tiny = f32::from_bits(1);
        for x in [0.0, -0.0, tiny, -tiny, 1.0, -2.0, f32::MAX, -f32::MAX] {
            for n in -3..=3 {
                let want = (ordinal(x) + n).clamp(-inf, inf);
                assert_eq!(ordinal(step(x, n)), want, "{x} {n}");
            }
        }
        assert_eq!(step(-0.0, 0).to_bits(), 0);
        assert_eq!(step(tiny, -1).to_bits(), 0);
        assert_eq!(step(-tiny, 1).to_bits(), 0);
        assert!(step(f32::NAN, 1).is_nan());
        assert_eq!(step(1.0, i64::MAX), f32::INFINITY);
        assert_eq!(step(-1.0, i64::MIN), f32::NEG_INFINITY);
    }
}
