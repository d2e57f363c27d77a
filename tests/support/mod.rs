//! Strategies and helpers shared by the property tests (`tests/props_*.rs`).
//! Each test binary uses a different subset.
#![allow(dead_code)]

use glam::Vec3;
use proptest::prelude::*;
use rayoracle::check::{CaseReport, Violation};

/// A check result as a proptest result, with the violation in the message.
pub fn checked(r: Result<CaseReport, Violation>) -> Result<CaseReport, TestCaseError> {
    r.map_err(|v| TestCaseError::fail(v.to_string()))
}

/// `2^k` for `k` in `lo..=hi` (exact).
pub fn pow2(lo: i32, hi: i32) -> impl Strategy<Value = f32> {
    (lo..=hi).prop_map(|k| 2f64.powi(k) as f32)
}

/// A positive factor drawn log-uniformly from `[10^lo, 10^hi]`.
pub fn log_uniform(lo: f64, hi: f64) -> impl Strategy<Value = f32> {
    (lo..=hi).prop_map(|e| 10f64.powf(e) as f32)
}

/// A vector with components uniform in `[-r, r]`.
pub fn vec_in(r: f32) -> impl Strategy<Value = Vec3> {
    [-r..=r, -r..=r, -r..=r].prop_map(Vec3::from_array)
}

/// An integer vector with components in `[-r, r]`.
pub fn ivec(r: i32) -> impl Strategy<Value = [i32; 3]> {
    [-r..=r, -r..=r, -r..=r]
}

/// An integer vector with components in `[-r, r]`, not zero.
pub fn ivec_nonzero(r: i32) -> impl Strategy<Value = [i32; 3]> {
    ivec(r).prop_filter("nonzero", |v| *v != [0, 0, 0])
}

/// A direction with components in `[-1, 1]` and length at least ½. A
/// shorter draw (one in about fifteen) has its x set to ±1 rather than be
/// rejected, so that no number of cases reaches proptest's limit on
/// rejections.
pub fn unitish() -> impl Strategy<Value = Vec3> {
    vec_in(1.0).prop_map(|v| {
        if v.length() >= 0.5 {
            v
        } else {
            Vec3::new(1f32.copysign(v.x), v.y, v.z)
        }
    })
}

/// Runs each recorded failure (a property's name, and its case function
/// on the values proptest reported) and fails naming every one that fails
/// again.
pub fn assert_recorded<'a>(cases: impl IntoIterator<Item = (&'a str, Result<(), TestCaseError>)>) {
    let failed: Vec<String> = cases
        .into_iter()
        .filter_map(|(property, r)| r.err().map(|e| format!("{property}: {e}")))
        .collect();
    assert!(
        failed.is_empty(),
        "recorded failures fail again:\n{}",
        failed.join("\n")
    );
}

pub fn cross(a: [i32; 3], b: [i32; 3]) -> [i32; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// A nonzero integer vector perpendicular to the nonzero `v`: `v × w`, or
/// `v × x̂`, `v × ŷ` when that is zero.
pub fn perp(v: [i32; 3], w: [i32; 3]) -> [i32; 3] {
    [w, [1, 0, 0], [0, 1, 0]]
        .into_iter()
        .map(|w| cross(v, w))
        .find(|p| *p != [0, 0, 0])
        .expect("v is not zero")
}

pub fn idot(a: [i32; 3], b: [i32; 3]) -> i64 {
    (0..3).map(|i| a[i] as i64 * b[i] as i64).sum()
}

/// `s · v` as an f32 vector; exact while the integers fit in 24 bits.
pub fn scaled(v: [i32; 3], s: f32) -> Vec3 {
    Vec3::new(v[0] as f32 * s, v[1] as f32 * s, v[2] as f32 * s)
}

pub fn add(a: [i32; 3], b: [i32; 3]) -> [i32; 3] {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}

pub fn mul(k: i32, v: [i32; 3]) -> [i32; 3] {
    v.map(|x| k * x)
}

/// An integer Pythagorean quadruple `(a, b, c, r)`, `a² + b² + c² = r²`,
/// `r > 0`, from the parametrisation by four integers in `[-k, k]`
/// (Euler–Lebesgue): every primitive quadruple arises this way.
pub fn pythagorean_quadruple(k: i32) -> impl Strategy<Value = ([i32; 3], i32)> {
    [-k..=k, -k..=k, -k..=k, -k..=k]
        .prop_filter("not all zero", |v| *v != [0, 0, 0, 0])
        .prop_map(|[m, n, p, q]| {
            let v = [
                m * m + n * n - p * p - q * q,
                2 * (m * q + n * p),
                2 * (n * q - m * p),
            ];
            let r = m * m + n * n + p * p + q * q;
            debug_assert_eq!(idot(v, v), (r as i64) * (r as i64));
            (v, r)
        })
}

/// An integer Pythagorean triple `(a, b, c)`, `a² + b² = c²`, `c > 0`, with
/// random signs and order of the legs.
pub fn pythagorean_triple(k: i32) -> impl Strategy<Value = [i32; 3]> {
    (1..=k)
        .prop_flat_map(|m| (Just(m), 0..m, any::<bool>(), any::<bool>(), any::<bool>()))
        .prop_map(|(m, n, sa, sb, swap)| {
            let (a, b) = (m * m - n * n, 2 * m * n);
            let (a, b) = if swap { (b, a) } else { (a, b) };
            let a = if sa { -a } else { a };
            let b = if sb { -b } else { b };
            [a, b, m * m + n * n]
        })
}

/// The x4 kernels must give the reference's bits on the same families the
/// oracle tests draw: the case is run in each lane of a packet among
/// unrelated cases (`eval`'s x4 column), and compared bit for bit.
pub fn x4_agrees(case: &rayoracle::case::Case) -> Result<(), TestCaseError> {
    use rayoracle::eval::Implementation;
    let (r, x) = (
        Implementation::Reference.run(case),
        Implementation::X4.run(case),
    );
    let bits = |o: &rayoracle::eval::Outcome| {
        o.values()
            .iter()
            .map(|v| if v.is_nan() { u32::MAX } else { v.to_bits() })
            .collect::<Vec<_>>()
    };
    if r.class() == x.class() && bits(&r) == bits(&x) {
        Ok(())
    } else {
        Err(TestCaseError::fail(format!(
            "x4 {x:?} != reference {r:?} for {case:?}"
        )))
    }
}
