//! The later stages: what runs after the [filter](super) leaves a line
//! undecided, before the exact oracle. Each stage's part is listed in the
//! [filter's module](super).

use super::{Classes, Dots, classes, dots, e_c};
use crate::num::certify::{SLACK, U, certify, div};
use crate::num::dd::{Acc, Approx, Dd, Dekker, Product, quotient, two_roots, two_sum};
use crate::sphere::SphereHit;

/// The tight stage, after Ray Tracing Gems ch. 7 (Haines et al.,
/// *Precision improvements for ray/sphere intersection*): the
/// discriminant as `Δ = aΔ'`, `Δ' = R² − |l|²`, where `l = f − (b/a)d` is
/// the vector from the centre to the line's closest point. Its error grows
/// with `R·|f|` where the textbook `b² − ac` grows with `|f|²a`, so a far
/// tiny sphere is decided here, in f64.
///
/// # The bound
///
/// In the notation of the [module](super), with `E_b = 8u m_b` and `E_a =
/// 4uâ` as in the filter (twice `γ₄ m_b` and `γ₂ a`); each constant below
/// is at least twice what the proof needs.
///
/// * `λ̂ = fl(b̂/â)`: `|b̂/â − b̂/a| ≤ 2.01u|b̂/â|`, `|b̂ − b|/a ≤ 1.01E_b/â`,
///   and one rounding: `E_λ = 8u|λ̂| + 2E_b/â`.
/// * `p̂ᵢ = fl(λ̂dᵢ)` and `l̂ᵢ = fl(f̂ᵢ − p̂ᵢ)`, where `f̂ᵢ` is within
///   `u|f̂ᵢ|` of `fᵢ`: `|l̂ᵢ − lᵢ| ≤ u(|l̂ᵢ| + 1.01|f̂ᵢ| + |p̂ᵢ|) + E_λ|dᵢ|`;
///   the stage uses `E_lᵢ = 2u(|l̂ᵢ| + |f̂ᵢ| + |p̂ᵢ|) + E_λ|dᵢ|`. Since
///   `E_b/â·|dᵢ| ≤ 8u m_b|dᵢ|/a ≤ 8u|f|`, this is of the order of `u|f|`.
/// * `L̂ = fl(Σl̂ᵢ²)` and `Δ̂' = fl(R² − L̂)` (`R²` exact): `|Σl̂ᵢ² −
///   Σlᵢ²| ≤ Σ(2|l̂ᵢ|E_lᵢ + E_lᵢ²)`, and four roundings, at most `γ₃L̂ +
///   u(R² + L̂)`: `E_Δ' = 4Σ|l̂ᵢ|E_lᵢ + 2ΣE_lᵢ² + 8uL̂ + 2uR² + η`, with
///   `η = 2⁻¹⁰⁰⁰` for the squares and products that may underflow (each
///   loses less than `2⁻¹⁰⁷⁴`). Near the sphere `|l| ≈ R`: `E_Δ' ≈
///   O(u R|f|)`.
/// * `Δ̂' > E_Δ'` certifies two roots, `Δ̂' < −E_Δ'` none.
/// * The roots, by [`two_roots`] from `Δ̂ = fl(âΔ̂')`, within `u|Δ̂| +
///   |Δ̂'|E_a + âE_Δ' + E_aE_Δ'` of `Δ`: `E_Δ = 2u|Δ̂| + 8uâ|Δ̂'| + 2âE_Δ'
///   + η`, with `c` and `E_c = 10u f̂f + 2u|ĉ|` as in the filter.
///
/// Every bound is widened by `1 + 2⁻³⁰` for the roundings of its own
/// evaluation and multiplied by `shrink`. `None` where the class or a root
/// is undecided.
///
/// # Range
///
/// `|f̂ᵢ| ≤ 2¹²⁹`, `â ≥ 2⁻²⁹⁸`, `|b̂| ≤ 2²⁵⁹`, so `|λ̂| ≤ 2⁵⁵⁷` and
/// `|p̂ᵢ| ≤ 2⁶⁸⁵`: no overflow. A nonzero `b̂` is at least `2⁻²⁹⁸` and `â`
/// at most `2²⁵⁸`, so `λ̂`, `p̂ᵢ` and a nonzero `l̂ᵢ` stay normal; only
/// squares and products of the bound may underflow, which `η` covers.
///
/// ```
/// use rayoracle::sphere::{SphereHit, stages::{filter, tight}};
/// // R = 1 at 10⁷ along the axis: the filter cannot certify the roots.
/// let (o, d) = ([0.5, 0.0, -1e7], [0.0, 0.0, 1.0]);
/// let f = filter::<f64>(o, d, [0.0; 3], 1.0, 1.0);
/// assert!(!(f.two && rayoracle::num::certify::certify(f.t1, f.r1, f.a1)));
/// let s = 0.75f64.sqrt();
/// let want = SphereHit::Two((1e7 - s) as f32, (1e7 + s) as f32);
/// assert_eq!(tight(o, d, [0.0; 3], 1.0, 1.0), Some(want));
/// ```
///
/// [`two_roots`]: crate::num::dd::two_roots
#[inline]
pub fn tight(o: [f64; 3], d: [f64; 3], c: [f64; 3], r: f64, shrink: f64) -> Option<SphereHit> {
    let t = tight_terms(o, d, c, r);
    // The bounds are unshrunk in `t`; the class tests and `two_roots`
    // apply `shrink`.
    if t.a.v == 0.0 || t.dp.v < -t.dp.e * shrink {
        return Some(SphereHit::None);
    }
    if !(t.dp.v > t.dp.e * shrink) {
        return None;
    }
    let (t0, t1) = two_roots(t.a, t.b, t.c, t.disc, shrink)?;
    Some(SphereHit::Two(t0, t1))
}

/// The values [`tight`] decides from, with their bounds as derived there
/// (unshrunk): `â`, `b̂`, `ĉ`, `Δ̂'` and `Δ̂ = fl(âΔ̂')`.
#[derive(Clone, Copy, Debug)]
pub(crate) struct TightTerms {
    pub(crate) a: Approx,
    pub(crate) b: Approx,
    pub(crate) c: Approx,
    pub(crate) dp: Approx,
    pub(crate) disc: Approx,
}

/// [`tight`]'s values and bounds, before any decision.
#[inline(always)]
pub(crate) fn tight_terms(o: [f64; 3], d: [f64; 3], c: [f64; 3], r: f64) -> TightTerms {
    let eta = f64::from_bits((1023 - 1000) << 52);
    let Dots {
        f,
        a,
        b,
        mb,
        ff,
        rr,
    } = dots(o, d, c, r);
    let (eb, ea) = (8.0 * U * mb, 4.0 * U * a);
    let lambda = b / a;
    let el = 8.0 * U * lambda.abs() + 2.0 * eb / a;
    let (mut ll, mut e1, mut e2) = (0.0, 0.0, 0.0);
    for i in 0..3 {
        let p = lambda * d[i];
        let l = f[i] - p;
        let e = 2.0 * U * (l.abs() + f[i].abs() + p.abs()) + el * d[i].abs();
        ll += l * l;
        e1 += l.abs() * e;
        e2 += e * e;
    }
    let dp = rr - ll;
    let edp = (4.0 * e1 + 2.0 * e2 + 8.0 * U * ll + 2.0 * U * rr) * SLACK + eta;
    let disc = a * dp;
    let ed = (2.0 * U * disc.abs() + 8.0 * U * a * dp.abs() + 2.0 * a * edp) * SLACK + eta;
    let x = |v: f64, e: f64| Approx { v, e };
    TightTerms {
        a: x(a, ea),
        b: x(b, eb),
        c: x(ff - rr, e_c(ff, ff - rr, 1.0)),
        dp: x(dp, edp),
        disc: x(disc, ed),
    }
}

/// The roots where the filter certified two but not both roots, with `c =
/// f·f − R²` recomputed compensated: the cure for an origin near a large
/// sphere, where `c ≈ 2Rh` (`h` the height above the surface) is the
/// cancellation of two terms near `R²`, so the filter's `E_c = 10u f̂f + 2u|ĉ|`
/// exceeds `|c|` itself while `a`, `b` and `Δ` stay accurate.
///
/// # The bound
///
/// * `(φᵢ, ψᵢ) = TwoSum(oᵢ, −Cᵢ)` and `(pᵢ, eᵢ) = TwoProduct(φᵢ, φᵢ)` are
///   exact ([`crate::num::dd`]): `fᵢ = φᵢ + ψᵢ`, `φᵢ² = pᵢ + eᵢ`.
/// * `mᵢ = fl(fl(2φᵢ + ψᵢ)·ψᵢ)` against the exact `fᵢ² − φᵢ² = (2φᵢ +
///   ψᵢ)ψᵢ`: two roundings, within `2.01u|mᵢ| ≤ 2.02u|m̂ᵢ|`.
/// * `h = p₀ + p₁ + p₂ − R²` by three TwoSums, exact with the errors `εⱼ`
///   (`R²` is exact).
/// * `l̂` sums the ten terms `eᵢ`, `m̂ᵢ` and `εⱼ` in f64: in any order,
///   within `γ₉M` of their exact sum (Higham §4.2), `M` the sum of their
///   magnitudes.
/// * `ĉ = fl(h + l̂)`, within `u|ĉ|` of `h + l̂`, so that `|ĉ − c|` is at
///   most `u|ĉ| + γ₉M + 2.02uΣ|m̂ᵢ| ≤ u|ĉ| + 11.1uM`. The stage uses
///   **`E_c = 2u|ĉ| + 24uM`**, twice that, widened by `1 + 2⁻³⁰`. Where
///   every term is 0 (`M = 0`) `ĉ` is exact, and an origin exactly on the
///   sphere gets its root 0.
///
/// The roots are [`two_roots`]' with `a`, `b` and `Δ` as in the filter
/// (`E_a = 4uâ`, `E_b = 8u m_b`, `E_Δ = 20u(m_b² + â m_c)`), and every
/// bound is multiplied by `shrink`. `None` where the filter's class is not
/// two or a root is undecided.
///
/// # Range
///
/// `|φᵢ| ≤ 2¹²⁹` and every value is a multiple of `2⁻¹⁴⁹` (`φ`, `ψ`) or
/// `2⁻²⁹⁸` (the rest), so TwoProduct's conditions hold and nothing
/// underflows or overflows.
///
/// ```
/// use rayoracle::num::certify::certify;
/// use rayoracle::sphere::{Sphere, exact, stages::{compensated, filter}};
/// use glam::Vec3;
/// // R ≈ 8.5e5, the origin about 0.03 above the surface, going down.
/// let (o, d) = (Vec3::new(-2.655471, -1.9088471, 5.5120096), Vec3::new(-0.22329216, 0.22213678, 0.59268516));
/// let s = Sphere::new(Vec3::new(509120.44, -279399.13, 615456.25), 846196.6);
/// let w = |v: Vec3| v.as_dvec3().to_array();
/// let (o64, d64, c64, r64) = (w(o), w(d), w(s.center), f64::from(s.radius));
/// let f = filter::<f64>(o64, d64, c64, r64, 1.0);
/// assert!(f.two && !(certify(f.t0, f.r0, f.a0) && certify(f.t1, f.r1, f.a1)));
/// let want = exact::intersect(&rayoracle::Ray::new(o, d), &s).unwrap();
/// assert_eq!(compensated(o64, d64, c64, r64, 1.0), Some(want));
/// ```
///
/// [`two_roots`]: crate::num::dd::two_roots
pub fn compensated(
    o: [f64; 3],
    d: [f64; 3],
    c: [f64; 3],
    r: f64,
    shrink: f64,
) -> Option<SphereHit> {
    compensated_from(&classes(o, d, c, r, shrink), o, c, r, shrink)
}

/// Whether [`compensated`] can help where the filter's [`classes`] are
/// `k`: the class is two and `c` cancelled by at least 8 bits (`m_c >
/// 2⁸|ĉ|`), so that its bound, not `Δ`'s, is the likelier to have left a
/// root undecided. Only an order of trial: the stages are correct either
/// way.
#[inline(always)]
pub(crate) fn c_cancels(k: &Classes<f64>) -> bool {
    k.two && k.mc > 256.0 * k.cq.abs()
}

/// [`compensated`] from the [`classes`] already computed (with `shrink`).
#[inline(always)]
pub(crate) fn compensated_from(
    k: &Classes<f64>,
    o: [f64; 3],
    c: [f64; 3],
    r: f64,
    shrink: f64,
) -> Option<SphereHit> {
    if !k.two {
        return None;
    }
    let [a, b, cq, disc] = compensated_terms(k, o, c, r);
    let (t0, t1) = two_roots(a, b, cq, disc, shrink)?;
    Some(SphereHit::Two(t0, t1))
}

/// [`compensated`]'s `a`, `b`, `c` and `Δ`, with their bounds as derived
/// there (unshrunk): the filter's values but `ĉ`, recomputed compensated.
#[inline(always)]
pub(crate) fn compensated_terms(k: &Classes<f64>, o: [f64; 3], c: [f64; 3], r: f64) -> [Approx; 4] {
    let (mut h, mut low, mut mag) = (0.0, 0.0, 0.0);
    for i in 0..3 {
        let (phi, psi) = two_sum(o[i], -c[i]);
        let (p, e) = crate::num::dd::two_prod(phi, phi);
        let m = (phi + phi + psi) * psi;
        let (s, eps) = two_sum(h, p);
        h = s;
        low += e + m + eps;
        mag += e.abs() + m.abs() + eps.abs();
    }
    let (s, eps) = two_sum(h, -(r * r));
    let cq = s + (low + eps);
    let ec = (2.0 * U * cq.abs() + 24.0 * U * (mag + eps.abs())) * SLACK;
    let x = |v: f64, e: f64| Approx { v, e };
    let ed = 20.0 * U * (k.mb * k.mb + k.a * k.mc) * SLACK;
    [
        x(k.a, 4.0 * U * k.a),
        x(k.b, 8.0 * U * k.mb),
        x(cq, ec),
        x(k.disc, ed),
    ]
}

/// The tracked stage's answer without its checks, where the data alone
/// prove the filter's f64 arithmetic exact: small integers and dyadics of
/// a narrow range, as exact tangents in the wild are.
///
/// # The proof
///
/// With `Eₚ` a bound on the span of the position data (`o`, `C`, `R`) and
/// `E_d` one on that of `d` ([`span_bound`]), every position is an
/// integer multiple of some `2ᴸᵖ` below `2ᴴᵖ` (`Hₚ − Lₚ = Eₚ`), every
/// `dᵢ` one of `2ᴸᵈ` below `2ᴴᵈ`. An f64 operation whose exact result is
/// a multiple of `2ᵏ` below `2ᵏ⁺⁵³` in magnitude is exact. Each value of
/// the filter ([`filter`](super::filter)), and each partial sum, is on
/// the grid of its products and below the sum of their magnitudes:
///
/// * `fᵢ`: grid `2ᴸᵖ`, below `2ᴴᵖ⁺¹`;
/// * `a`: grid `2²ᴸᵈ`, below `3·2²ᴴᵈ`; `b`: grid `2ᴸᵖ⁺ᴸᵈ`, below
///   `3·2ᴴᵖ⁺ᴴᵈ⁺¹`;
/// * `f·f`: grid `2²ᴸᵖ`, below `3·2²ᴴᵖ⁺²`; `R²` below `2²ᴴᵖ`; so `c` is
///   below `2²ᴴᵖ⁺⁴`;
/// * `b²` and `ac` below `2²ᴴᵖ⁺²ᴴᵈ⁺⁶`, and `Δ` below `2²ᴴᵖ⁺²ᴴᵈ⁺⁷`, all
///   on the grid `2²ᴸᵖ⁺²ᴸᵈ`.
///
/// The widest ratio is `Δ`'s, `2^(2(Eₚ + E_d) + 7)`, so `Eₚ + E_d ≤ 23`
/// makes every operation exact, and the bounds the stage asks it of carry
/// a bit of slack each. Nonzero values are at least `2⁻⁵⁹⁶`, so none is
/// subnormal. Then, as in [`tracked`], the class is the sign of `Δ̂`, a
/// tangent's root `−b/a` rounds once (certified with `2u`) and two roots
/// `q/a` and `c/q` are within `4u` (certified with `8u`). `None` where
/// the span is wider or a root sits next to an f32 rounding boundary.
///
/// ```
/// use rayoracle::sphere::{SphereHit, stages::{grid_exact, tracked}};
/// // Grazing R = 3 at (0, 3, 0) from z = −5: span bounds 5 and 1.
/// assert_eq!(grid_exact([0.0, 3.0, -5.0], [0.0, 0.0, 1.0], [0.0; 3], 3.0), Some(SphereHit::Tangent(5.0)));
/// // 0.1f32 has 24 bits: the span is too wide, as tracked finds.
/// let (o, d) = ([0.0, 3.0, 0.1f32], [0.0, 0.0, 0.1f32]);
/// assert_eq!(grid_exact(o, d, [0.0; 3], 3.0), None);
/// ```
///
/// [`span_bound`]: crate::sphere::exactness::span_bound
pub fn grid_exact(o: [f32; 3], d: [f32; 3], c: [f32; 3], r: f32) -> Option<SphereHit> {
    let w = |v: [f32; 3]| v.map(f64::from);
    let k = classes(w(o), w(d), w(c), f64::from(r), 1.0);
    grid_from(&k, o, d, c, r)
}

/// [`grid_exact`] from the [`classes`] already computed.
#[inline(always)]
pub(crate) fn grid_from(
    k: &Classes<f64>,
    o: [f32; 3],
    d: [f32; 3],
    c: [f32; 3],
    r: f32,
) -> Option<SphereHit> {
    grid_within(k, o, d, c, r, 23)
}

/// [`grid_from`] with the bound on the spans' sum given: for the test that
/// shows a wider one gives wrong answers.
#[inline(always)]
fn grid_within(
    k: &Classes<f64>,
    o: [f32; 3],
    d: [f32; 3],
    c: [f32; 3],
    r: f32,
    limit: u32,
) -> Option<SphereHit> {
    use crate::sphere::exactness::span_bound;
    if span_bound(&d) + span_bound(&[o[0], o[1], o[2], c[0], c[1], c[2], r]) > limit {
        return None;
    }
    exact_roots(k.a, k.b, k.cq, k.disc)
}

/// The answer from `a`, `b`, `c` and `Δ = b² − ac` known to be exact: the
/// class from the signs (none where `a = 0`), a tangent's root `−b/a`
/// rounded once (certified with `2u`), two roots `q/a` and `c/q` from `s =
/// √Δ`, within `2u|q|` for `q` and so `4u` for each root (certified with
/// `8u`). `None` where a root sits next to an f32 rounding boundary.
#[inline(always)]
fn exact_roots(a: f64, b: f64, cq: f64, disc: f64) -> Option<SphereHit> {
    if a == 0.0 || disc < 0.0 {
        return Some(SphereHit::None);
    }
    if disc == 0.0 {
        let t = div(-b, a);
        return certify(t, 2.0 * U, 0.0).then_some(SphereHit::Tangent(t as f32));
    }
    let q = -(b + disc.sqrt().copysign(b));
    let (t0, t1) = (q / a, div(cq, q));
    let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
    let ok = certify(t0, 8.0 * U, 0.0) && certify(t1, 8.0 * U, 0.0);
    ok.then_some(SphereHit::Two(t0 as f32, t1 as f32))
}

/// The second stage: the textbook quadratic tracked for exactness
/// ([`crate::sphere::exactness`]). Where no operation rounded, `a`, `b`, `c` and
/// `Δ` are exact, so the class follows from signs: a tangent's root `−b/a`
/// rounds once (certified with `2u`); two roots are `q/a` and `c/q` from
/// `s = √Δ`, within `2u|q|` for `q` and so `4u` for each root (certified
/// with `8u`). `None` where an operation rounded or a root sits next to an
/// f32 rounding boundary.
///
/// The values are the filter's, computed in the same order; each is proven
/// exact on its own: the squares `dᵢ²` and `R²` of f32 values always are
/// (48 bits), every other product by [`mul_exact`] and every sum by
/// TwoSum. A non-finite input fails a sum's proof.
///
/// ```
/// use rayoracle::sphere::{SphereHit, stages::tracked};
/// // Grazing the unit sphere at (0, 1, 0) from z = −5: Δ = 0 exactly.
/// assert_eq!(tracked([0.0, 1.0, -5.0], [0.0, 0.0, 1.0], [0.0; 3], 1.0), Some(SphereHit::Tangent(5.0)));
/// // 0.1f32 in f: b = f·d has more than 53 bits, so b² rounds.
/// let (o, d) = ([0.0, 3.0, 0.1f32 as f64], [0.0, 0.0, 0.1f32 as f64]);
/// assert_eq!(tracked(o, d, [0.0; 3], 3.0), None);
/// ```
///
/// [`mul_exact`]: crate::sphere::exactness::mul_exact
#[inline]
pub fn tracked(o: [f64; 3], d: [f64; 3], c: [f64; 3], r: f64) -> Option<SphereHit> {
    let x = dots(o, d, c, r);
    if !tracked_exact(o, d, c, &x) {
        return None;
    }
    let cq = x.ff - x.rr;
    exact_roots(x.a, x.b, cq, x.b * x.b - x.a * cq)
}

/// Whether every operation of [`dots`], `c = f·f − R²` and `Δ = b² − ac`
/// was exact (see [`tracked`]).
#[inline(always)]
fn tracked_exact(o: [f64; 3], d: [f64; 3], c: [f64; 3], x: &Dots<f64>) -> bool {
    use crate::sphere::exactness::{add_exact, at_most_26_bits, mul_exact};
    let Dots {
        f, a, b, ff, rr, ..
    } = *x;
    let sq = d.map(|x| x * x);
    let fd = [0, 1, 2].map(|i| f[i] * d[i]);
    let f2 = f.map(|x| x * x);
    // With every fᵢ of at most 26 bits, fᵢdᵢ (dᵢ has 24) and fᵢ² are exact.
    let products =
        || at_most_26_bits(f) || (0..3).all(|i| mul_exact(f[i], d[i]) & mul_exact(f[i], f[i]));
    // In groups, so that a near tangent, which fails early, stops early.
    (add_exact(sq[0], sq[1]) & add_exact(sq[0] + sq[1], sq[2]))
        && (add_exact(o[0], -c[0]) & add_exact(o[1], -c[1]) & add_exact(o[2], -c[2]))
        && products()
        && add_exact(fd[0], fd[1])
            & add_exact(fd[0] + fd[1], fd[2])
            & add_exact(f2[0], f2[1])
            & add_exact(f2[0] + f2[1], f2[2])
            & add_exact(ff, -rr)
            & mul_exact(b, b)
            & mul_exact(a, ff - rr)
            & add_exact(b * b, -(a * (ff - rr)))
}

/// The double-word stage ([`crate::num::dd`]): `f = o − C` split exactly
/// into two words by TwoSum, then `a = Σdᵢ²`, `b = Σfᵢdᵢ` and `c = Σfᵢ² −
/// R²` as sums of exact products, and `Δ = b² − ac` as the sum of the
/// exact products of their words. Every value is a multiple of `2⁻²⁹⁸`
/// (products of two f32 values and their sums), every product one of
/// `2⁻⁵⁹⁶`, so TwoProduct is exact ([`crate::num::dd`]); a product with
/// a zero factor is left out, and one whose factors' significant bits sum
/// to at most 53 ([`crate::sphere::exactness::sig_bits`]) is added as one word.
/// Where no low word rounded, `Δ` is exact, and so is its sign and its
/// zero; otherwise its bound (the low words' and, as in
/// [`Acc::add_dd_prod`], those of `a`,
/// `b`, `c`) decides the sign or nothing. A tangent's root `−b/a`, and two
/// roots ([`two_roots`]), are then certified from the words' leading
/// values with `|lo| + err` as their bounds. Every bound is multiplied by
/// `shrink`. `None` where the class or a root is undecided.
///
/// ```
/// use rayoracle::sphere::{SphereHit, stages::{double_word, tracked}};
/// // Grazing R = 3 at (0, 3, 0) from z = 0.1f32 along 0.1f32: Δ = 0, but
/// // b² and ac have 96 significant bits, so f64 rounds them.
/// let (o, d) = ([0.0, 3.0, 0.1f32 as f64], [0.0, 0.0, 0.1f32 as f64]);
/// assert_eq!(tracked(o, d, [0.0; 3], 3.0), None);
/// assert_eq!(double_word(o, d, [0.0; 3], 3.0, 1.0), Some(SphereHit::Tangent(-1.0)));
/// // A far tiny sphere, hit through its centre.
/// let h = double_word([0.0, 0.0, -1e6], [0.0, 0.0, 1.0], [0.0; 3], 1.0, 1.0);
/// assert_eq!(h, Some(SphereHit::Two(999_999.0, 1_000_001.0)));
/// ```
///
/// [`Acc::add_dd_prod`]: crate::num::dd::Acc::add_dd_prod
/// [`two_roots`]: crate::num::dd::two_roots
pub fn double_word(
    o: [f64; 3],
    d: [f64; 3],
    c: [f64; 3],
    r: f64,
    shrink: f64,
) -> Option<SphereHit> {
    double_word_by::<Dekker>(o, d, c, r, shrink)
}

/// [`double_word`] with the products' errors found by `P`: the same exact
/// pairs whichever `P`, so the same answers.
#[inline(always)]
pub(crate) fn double_word_by<P: Product>(
    o: [f64; 3],
    d: [f64; 3],
    c: [f64; 3],
    r: f64,
    shrink: f64,
) -> Option<SphereHit> {
    let add_prod = add_prod::<P>;
    let add_dd_prod = add_dd_prod::<P>;
    let (mut a, mut b, mut cq) = (Acc::new(), Acc::new(), Acc::new());
    for i in 0..3 {
        let (fh, fl) = two_sum(o[i], -c[i]);
        a.add(d[i] * d[i]);
        add_prod(&mut b, fh, d[i]);
        add_prod(&mut b, fl, d[i]);
        add_prod(&mut cq, fh, fh);
        add_prod(&mut cq, fh + fh, fl);
        add_prod(&mut cq, fl, fl);
    }
    cq.add(-(r * r));
    // The bounds as derived; `shrink` scales each once, where it decides:
    // the class here, the roots in `quotient` and `two_roots`.
    let (a, b, cq) = (a.finish(), b.finish(), cq.finish());
    let mut disc = Acc::wide();
    let extra = add_dd_prod(&mut disc, b, b) + add_dd_prod(&mut disc, a.scale(-1.0), cq);
    let mut disc = disc.finish();
    disc.err += extra * SLACK;
    let class = disc.shrunk(shrink);
    if a.hi == 0.0 || (class.sign_known() && disc.hi < 0.0) {
        // a = Σdᵢ² rounds to 0 only where every dᵢ is 0.
        return Some(SphereHit::None);
    }
    if class.is_zero() {
        let t = quotient(-b.approx(), a.approx(), shrink)?;
        return Some(SphereHit::Tangent(t));
    }
    if !class.sign_known() {
        return None;
    }
    let (t0, t1) = two_roots(a.approx(), b.approx(), cq.approx(), disc.approx(), shrink)?;
    Some(SphereHit::Two(t0, t1))
}

/// Adds `xy` to `acc` exactly, as [`Acc::add_prod`] does, but skips an
/// exact zero and the TwoProduct of a product [`sig_bits`] shows exact.
/// Leaving out a zero term only lowers the count of terms that
/// [`Acc::finish`]'s bound counts, which stays a bound on the terms added.
///
/// [`sig_bits`]: crate::sphere::exactness::sig_bits
#[inline(always)]
fn add_prod<P: Product>(acc: &mut Acc, x: f64, y: f64) {
    use crate::sphere::exactness::sig_bits;
    if x == 0.0 || y == 0.0 {
    } else if sig_bits(x) + sig_bits(y) <= 53 {
        acc.add(x * y);
    } else {
        acc.add_pair(P::two_prod(x, y));
    }
}

/// [`Acc::add_dd_prod`] through [`add_prod`]: the four partial products
/// of two double-word values, exactly, and the bound their errors add,
/// `2(|x.hi|E_y + E_x(|y.hi| + E_y))`, returned for the caller to add to
/// the finished sum's, as [`Acc::add_dd_prod`] adds it.
#[inline(always)]
fn add_dd_prod<P: Product>(acc: &mut Acc, x: Dd, y: Dd) -> f64 {
    add_prod::<P>(acc, x.hi, y.hi);
    add_prod::<P>(acc, x.hi, y.lo);
    add_prod::<P>(acc, x.lo, y.hi);
    add_prod::<P>(acc, x.lo, y.lo);
    2.0 * (x.hi.abs() * y.err + x.err * (y.hi.abs() + y.err))
}
#[cfg(all(test, feature = "plane", feature = "quadric"))]
mod tests {
    use super::compensated;
    use crate::Ray;
    use crate::case::Case;
    use crate::hit::same_bits;
    use crate::report::Catalogue;
    use crate::sphere::stages::tests::two_root_lines;
    use crate::sphere::{Sphere, exact};
    /// The tight stage's bounds are the derivation's ([`super::tight`]):
    /// `E_λ = 8u|λ̂| + 2E_b/â`, `E_lᵢ = 2u(|l̂ᵢ| + |f̂ᵢ| + |p̂ᵢ|) +
    /// E_λ|dᵢ|`, `E_Δ' = (4Σ|l̂ᵢ|E_lᵢ + 2ΣE_lᵢ² + 8uL̂ + 2uR²)·SLACK + η` and
    /// `E_Δ = (2u|Δ̂| + 8uâ|Δ̂'| + 2âE_Δ')·SLACK + η`, with `E_a = 4uâ`,
    /// `E_b = 8u m_b` and the filter's `E_c`, over the lines of
    /// [`two_root_lines`] and the same lines moved off their spheres (so
    /// that `Δ̂'` is negative). A line from a point sphere's centre has
    /// nothing to bound but `η = 2⁻¹⁰⁰⁰` itself.
    #[test]
    fn the_tight_bounds_are_the_derivations() {
        use super::{SLACK, U, tight_terms};
        let close = |got: f64, want: f64, what: &str| {
            let ok = got == want || ((got - want) / want).abs() < 1e-14;
            assert!(ok, "{what}: {got:e}, not {want:e}");
        };
        let eta = 2f64.powi(-1000);
        let mut misses = 0;
        for ((_, o, d, c, r), _) in two_root_lines() {
            for shift in [0.0, 3.0 * r] {
                let o = [o[0] + shift, o[1], o[2]];
                let f = [0, 1, 2].map(|i| o[i] - c[i]);
                let a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                let b = f[0] * d[0] + f[1] * d[1] + f[2] * d[2];
                let mb = (0..3).map(|i| (f[i] * d[i]).abs()).sum::<f64>();
                let lambda = b / a;
                let el = 8.0 * U * lambda.abs() + 2.0 * (8.0 * U * mb) / a;
                let (mut ll, mut e1, mut e2) = (0.0, 0.0, 0.0);
                for i in 0..3 {
                    let p = lambda * d[i];
                    let l = f[i] - p;
                    let e = 2.0 * U * (l.abs() + f[i].abs() + p.abs()) + el * d[i].abs();
                    (ll, e1, e2) = (ll + l * l, e1 + l.abs() * e, e2 + e * e);
                }
                let dp = r * r - ll;
                let edp = (4.0 * e1 + 2.0 * e2 + 8.0 * U * ll + 2.0 * U * r * r) * SLACK + eta;
                let disc = a * dp;
                let ed =
                    (2.0 * U * disc.abs() + 8.0 * U * a * dp.abs() + 2.0 * a * edp) * SLACK + eta;
                let ff = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
                let cq = ff - r * r;
                let t = tight_terms(o, d, c, r);
                let at = format!("{o:?} {d:?} R = {r}");
                for (got, want, what) in [
                    (t.a.v, a, "a"),
                    (t.a.e, 4.0 * U * a, "E_a"),
                    (t.b.v, b, "b"),
                    (t.b.e, 8.0 * U * mb, "E_b"),
                    (t.c.v, cq, "c"),
                    (t.c.e, 10.0 * U * ff + 2.0 * U * cq.abs(), "E_c"),
                    (t.dp.v, dp, "Δ'"),
                    (t.dp.e, edp, "E_Δ'"),
                    (t.disc.v, disc, "Δ"),
                    (t.disc.e, ed, "E_Δ"),
                ] {
                    close(got, want, &format!("{what}, {at}"));
                }
                misses += usize::from(dp < 0.0);
            }
        }
        assert!(misses >= 20, "{misses}");
        let t = tight_terms([1.0, 2.0, 3.0], [0.5, 0.0, 1.0], [1.0, 2.0, 3.0], 0.0);
        assert_eq!((t.dp.v, t.dp.e), (0.0, eta));
        assert_eq!(t.disc.e, 2.0 * 1.25 * eta * SLACK + eta);
    }

    /// The tight stage's class tests scale with `shrink`: lines from
    /// `2²⁰` away whose distance from a unit sphere's centre is `1 +
    /// m·2⁻⁵⁰` for small integers `m` (the direction `(0, ±m·2⁻⁷⁰, 1)`
    /// from `(0, 1, −2²⁰)`), where `Δ'` is a few times `E_Δ'`. Each side
    /// has a line the stage certifies (none, or two roots as the oracle
    /// has them), and one that it leaves at `shrink` 1 and decides at ¼.
    #[test]
    fn the_tight_class_tests_scale_with_shrink() {
        use super::tight;
        use crate::sphere::SphereHit;
        let s = Sphere::new(glam::Vec3::ZERO, 1.0);
        for side in [1.0f32, -1.0] {
            let (mut certain, mut scaled) = (0, 0);
            for m in 1..32 {
                let ray = Ray::new(
                    glam::Vec3::new(0.0, 1.0, -(2f32.powi(20))),
                    glam::Vec3::new(0.0, side * m as f32 * 2f32.powi(-70), 1.0),
                );
                let ([o, d, c], r) = wide(&ray, &s);
                let want = exact::intersect(&ray, &s).unwrap();
                assert_eq!(matches!(want, SphereHit::None), side > 0.0);
                match (tight(o, d, c, r, 1.0), tight(o, d, c, r, 0.25)) {
                    (Some(h), _) => {
                        assert!(same_bits(&h, &want), "m = {m}: {h:?}, not {want:?}");
                        certain += 1;
                    }
                    (None, Some(h)) => {
                        assert!(same_bits(&h, &want), "m = {m}, ¼: {h:?}, not {want:?}");
                        scaled += 1;
                    }
                    (None, None) => {}
                }
            }
            assert!(certain > 0 && scaled > 0, "side {side}: {certain} {scaled}");
        }
    }

    /// The catalogue's sphere cases, with their families.
    fn catalogue() -> Vec<(String, Ray, Sphere)> {
        let mut cases = Vec::new();
        for family in Catalogue::builtin().unwrap().families {
            for case in &family.cases {
                if let Case::Sphere(r, s) = case {
                    cases.push((family.name.clone(), *r, *s));
                }
            }
        }
        cases
    }

    /// A case's `o`, `d`, `C` and `R` in f64.
    fn wide(r: &Ray, s: &Sphere) -> ([[f64; 3]; 3], f64) {
        let w = |v: glam::Vec3| v.as_dvec3().to_array();
        ([w(r.origin), w(r.dir), w(s.center)], f64::from(s.radius))
    }

    /// [`compensated`] alone, on every sphere case of the catalogue: it
    /// answers only the oracle's bits, and most of the origins near a huge
    /// sphere.
    #[test]
    fn compensated_alone_matches_the_oracle() {
        let mut huge = 0;
        for (family, r, s) in catalogue() {
            let Ok(want) = exact::intersect(&r, &s) else {
                continue;
            };
            let ([o, d, c], rr) = wide(&r, &s);
            if let Some(h) = compensated(o, d, c, rr, 1.0) {
                assert!(same_bits(&h, &want), "{family} {r:?} {s:?}");
                huge += usize::from(family == "sphere/huge-near");
            }
        }
        assert!(huge >= 64, "{huge}");
    }

    /// [`compensated`]'s `ĉ` is within half its bound `E_c` of the exact
    /// `c = |o − C|² − R²` (the proof's constants are half the stage's),
    /// and its terms are the derivation's: `ĉ = h + (l̂ + ε₃)` from the
    /// TwoSums and TwoProducts, `E_c = (2u|ĉ| + 24uM)·SLACK`, and the
    /// filter's `a`, `b` and `Δ` with `E_a = 4uâ`, `E_b = 8u m_b` and `E_Δ =
    /// 20u(m_b² + â m_c)·SLACK`. On every line whose class the filter
    /// certifies two among the catalogue's sphere cases (origins near a
    /// huge sphere among them, where `c` cancels and its low words carry
    /// it), the lines of [`two_root_lines`] (where `h − R²` rounds), and
    /// lines from origins of tiny coordinates near a sphere of radius 10⁶
    /// (where `o − C` rounds, so that `ψᵢ ≠ 0`).
    #[test]
    fn the_compensated_terms_are_the_derivations() {
        use super::{SLACK, U, classes, compensated_terms};
        use crate::exact::Dyadic;
        use crate::exact::dyadic::{dot, sub3};
        use crate::num::dd::{two_prod, two_sum};
        let mut lines: Vec<_> = catalogue()
            .into_iter()
            .map(|(family, ray, s)| {
                let ([o, d, c], r) = wide(&ray, &s);
                (family, o, d, c, r)
            })
            .collect();
        for ((_, o, d, c, r), _) in two_root_lines() {
            lines.push(("two-root".into(), o, d, c, r));
        }
        for k in 0..16 {
            let t = f64::from(1e-9f32 * (k + 1) as f32);
            let o = [t, -t / 3.0, t / 7.0].map(|x| x as f32 as f64);
            let d = [-1.0, 0.25 * f64::from(k), 0.5];
            lines.push(("tiny-origin".into(), o, d, [1e6, 0.0, 0.0], 1e6));
        }
        let (mut cases, mut cancelled, mut psi_used, mut eps_used) = (0, 0, 0, 0);
        for (family, o, d, c, r) in lines {
            let k = classes(o, d, c, r, 1.0);
            if !k.two {
                continue;
            }
            let (mut h, mut low, mut mag) = (0.0, 0.0, 0.0);
            for i in 0..3 {
                let (phi, psi) = two_sum(o[i], -c[i]);
                let (p, e) = two_prod(phi, phi);
                let m = (2.0 * phi + psi) * psi;
                let (sum, eps) = two_sum(h, p);
                (h, low, mag) = (
                    sum,
                    low + (e + m + eps),
                    mag + e.abs() + m.abs() + eps.abs(),
                );
                psi_used += usize::from(psi != 0.0);
            }
            let (sum, eps) = two_sum(h, -(r * r));
            let cq = sum + (low + eps);
            let m = mag + eps.abs();
            let [a, b, got, disc] = compensated_terms(&k, o, c, r);
            let at = format!("{family} {o:?} {d:?} {c:?} R = {r}");
            assert_eq!(got.v.to_bits(), cq.to_bits(), "ĉ, {at}");
            // To the bit: `24uM` is often `u` times the size of `2u|ĉ|`.
            let ec = (2.0 * U * cq.abs() + 24.0 * U * m) * SLACK;
            assert_eq!(got.e.to_bits(), ec.to_bits(), "E_c, {at}: {:e}", got.e);
            let dy = |v: [f64; 3]| v.map(Dyadic::from_f64);
            let f = sub3(&dy(o), &dy(c));
            let rr = Dyadic::from_f64(r);
            let exact = &dot(&f, &f) - &(&rr * &rr);
            let miss = (&Dyadic::from_f64(cq) - &exact).to_f64().abs();
            assert!(miss <= got.e / 2.0, "|ĉ − c| = {miss:e} > E_c/2, {at}");
            assert_eq!((a.v, a.e), (k.a, 4.0 * U * k.a), "a, {at}");
            assert_eq!((b.v, b.e), (k.b, 8.0 * U * k.mb), "b, {at}");
            let ed = 20.0 * U * (k.mb * k.mb + k.a * k.mc) * SLACK;
            assert_eq!((disc.v, disc.e), (k.disc, ed), "Δ, {at}");
            cases += 1;
            cancelled += usize::from(k.mc > 256.0 * cq.abs() && m > 0.0);
            eps_used += usize::from(eps != 0.0);
        }
        assert!(
            cases >= 1000 && cancelled >= 64 && psi_used >= 16 && eps_used >= 16,
            "{cases} {cancelled} {psi_used} {eps_used}"
        );
    }

    /// The words stage ([`crate::sphere::words`]) alone, on every sphere
    /// case of the catalogue: it answers only the oracle's bits, the same
    /// with either product, and most of the near tangents.
    #[test]
    fn words_alone_matches_the_oracle() {
        use crate::num::dd::{Dekker, Fused};
        use crate::sphere::words::words_by;
        let mut near = 0;
        for (family, r, s) in catalogue() {
            let Ok(want) = exact::intersect(&r, &s) else {
                continue;
            };
            let ([o, d, c], rr) = wide(&r, &s);
            let k = super::classes(o, d, c, rr, 1.0);
            let dekker = words_by::<Dekker>(&k, o, d, c, rr, 1.0);
            let fused = words_by::<Fused>(&k, o, d, c, rr, 1.0);
            assert_eq!(
                dekker.map(|h| format!("{h:?}")),
                fused.map(|h| format!("{h:?}"))
            );
            if let Some(h) = dekker {
                assert!(same_bits(&h, &want), "{family} {r:?} {s:?}");
                near += usize::from(family == "sphere/near-tangent");
            }
        }
        assert!(near >= 200, "{near}");
    }

    /// The double-word stage gives the same answers with Dekker's
    /// TwoProduct and with the fused one, as the reference's copy for CPUs
    /// with FMA takes, on every sphere case of the catalogue; and answers
    /// the near tangents there.
    #[test]
    fn double_word_is_the_same_with_either_product() {
        use super::double_word_by;
        use crate::num::dd::{Dekker, Fused};
        let mut near = 0;
        for (family, r, s) in catalogue() {
            let ([o, d, c], rr) = wide(&r, &s);
            let dekker = double_word_by::<Dekker>(o, d, c, rr, 1.0);
            let fused = double_word_by::<Fused>(o, d, c, rr, 1.0);
            match (dekker, fused) {
                (Some(x), Some(y)) => {
                    assert!(same_bits(&x, &y), "{family} {r:?} {s:?}");
                    near += usize::from(family == "sphere/near-tangent");
                }
                (None, None) => {}
                _ => panic!("{family} {r:?} {s:?}: {dekker:?} {fused:?}"),
            }
        }
        assert!(near >= 128, "{near}");
    }

    /// The tracked stage answers lines whose arithmetic is exact with the
    /// oracle's bits: a miss, a tangent, and lines from just outside or
    /// inside a sphere of radius 3 (the origin `(0, y, z)` with `z` the
    /// f32 values nearest `−√(9 − y²)`), whose root near 0 is a few ulps
    /// of `z` where the other is near `2|z|`; there `q = −(b +
    /// sign(b)√Δ)` does not cancel, as `−(b − sign(b)√Δ)` would.
    #[test]
    fn tracked_answers_exact_lines_with_the_oracles_bits() {
        use super::tracked;
        use crate::sphere::SphereHit;
        let s = Sphere::new(glam::Vec3::ZERO, 3.0);
        let mut lines = vec![[0.0, 3.5, -5.0], [0.0, 3.0, -5.0]];
        for y in [0.25f32, 0.5, 1.0, 1.5, 2.0, 2.25, 2.5, 2.75] {
            let z = -(9.0 - f64::from(y * y)).sqrt() as f32;
            for k in -4i32..=4 {
                lines.push([0.0, y, f32::from_bits(z.to_bits().wrapping_add_signed(k))]);
            }
        }
        let mut near_zero = 0;
        for o in lines {
            let ray = Ray::new(o.into(), glam::Vec3::Z);
            let want = exact::intersect(&ray, &s).unwrap();
            let ([o, d, c], r) = wide(&ray, &s);
            let got = tracked(o, d, c, r);
            assert!(
                got.is_some_and(|h| same_bits(&h, &want)),
                "{ray:?}: {got:?}, not {want:?}"
            );
            near_zero += usize::from(matches!(want, SphereHit::Two(t, _) if t.abs() < 1e-5));
        }
        assert!(near_zero >= 32, "{near_zero}");
    }

    /// [`tracked_exact`](super::tracked_exact) holds exactly where every
    /// operation of `a`, `b`, `c` and `Δ` gives its exact result, each
    /// checked in [`Dyadic`](crate::exact::Dyadic) arithmetic: on seeded
    /// random lines and spheres of dyadic values over a few binades, with
    /// at most 1 to 24 significant bits a line, so that each operation is
    /// exact on some and rounds on others, and on lines built so that one
    /// operation rounds where a similar one would not.
    #[test]
    fn tracked_exact_holds_exactly_where_no_operation_rounds() {
        use super::{dots, tracked_exact};
        use crate::exact::Dyadic;
        use rand::{Rng, SeedableRng, rngs::SmallRng};
        let mut rng = SmallRng::seed_from_u64(0x7ac4);
        let value = |rng: &mut SmallRng, most: i32| {
            let bits = rng.random_range(1..=most);
            let m = rng.random_range(1u32 << (bits - 1)..1 << bits) as f32;
            let x = m * 2f32.powi(rng.random_range(-4..4) - bits);
            if rng.random() { -x } else { x }
        };
        let dy = Dyadic::from_f64;
        let add = |x: f64, y: f64, z: f64| &dy(x) + &dy(y) == dy(z);
        let mul = |x: f64, y: f64, z: f64| &dy(x) * &dy(y) == dy(z);
        // Lines built so that one operation's exactness differs from that
        // of its neighbours: `1 + 2⁻⁵³` in one `oᵢ − Cᵢ` (where `1 −
        // 2⁻⁵³` is exact); `fₓ = 2²⁶ + 1`, more than 26 bits but exact
        // products, and `2²⁷ + 1`, whose square rounds though its product
        // with `dₓ = 0` does not; `a = 1 + 1 + dz²` rounding only in the
        // second sum, and `f·f` the same.
        let p = |k: i32| 2f64.powi(k);
        let dz = f64::from(p(-20) as f32 * (1.0 + f32::EPSILON));
        let mut lines = vec![
            ([1.0, 0.0, -5.0], [0.0, 0.0, 1.0], [-p(-53), 0.0, 0.0], 1.0),
            ([0.0, 1.0, -5.0], [0.0, 0.0, 1.0], [0.0, -p(-53), 0.0], 1.0),
            ([-5.0, 0.0, 1.0], [1.0, 0.0, 0.0], [0.0, 0.0, -p(-53)], 1.0),
            ([p(26), 0.0, 0.0], [-1.0, 0.0, 0.0], [-1.0, 0.0, 0.0], p(26)),
            ([p(27), 0.0, 0.0], [0.0, 0.0, 1.0], [-1.0, 0.0, 0.0], p(27)),
            ([0.0; 3], [1.0, 1.0, dz], [0.0; 3], 1.0),
            ([1.0, 1.0, dz], [1.0, 0.0, 0.0], [0.0; 3], 1.0),
        ];
        let built = lines.len();
        for _ in 0..20_000 {
            let most = rng.random_range(1..=24);
            let mut v = || f64::from(value(&mut rng, most));
            lines.push(([v(), v(), v()], [v(), v(), v()], [v(), v(), v()], v()));
        }
        let (mut exact, mut rounded) = (0, 0);
        for (i, (o, d, c, r)) in lines.into_iter().enumerate() {
            let x = dots(o, d, c, r);
            let (f, sq) = (x.f, d.map(|x| x * x));
            let fd = [0, 1, 2].map(|i| f[i] * d[i]);
            let f2 = f.map(|x| x * x);
            let cq = x.ff - x.rr;
            let (bb, ac) = (x.b * x.b, x.a * cq);
            let every = add(sq[0], sq[1], sq[0] + sq[1])
                && add(sq[0] + sq[1], sq[2], x.a)
                && (0..3).all(|i| {
                    add(o[i], -c[i], f[i]) && mul(f[i], d[i], fd[i]) && mul(f[i], f[i], f2[i])
                })
                && add(fd[0], fd[1], fd[0] + fd[1])
                && add(fd[0] + fd[1], fd[2], x.b)
                && add(f2[0], f2[1], f2[0] + f2[1])
                && add(f2[0] + f2[1], f2[2], x.ff)
                && add(x.ff, -x.rr, cq)
                && mul(x.b, x.b, bb)
                && mul(x.a, cq, ac)
                && add(bb, -ac, bb - ac);
            assert_eq!(tracked_exact(o, d, c, &x), every, "{o:?} {d:?} {c:?} {r}");
            if i < built {
                assert_eq!(every, i == 3, "line {i}");
            }
            (exact, rounded) = (exact + usize::from(every), rounded + usize::from(!every));
        }
        assert!(exact >= 1000 && rounded >= 1000, "{exact} {rounded}");
    }

    /// The double-word stage's `add_dd_prod` adds what
    /// [`Acc::add_dd_prod`](crate::num::dd::Acc::add_dd_prod) adds, the
    /// same words (zero and exact products skipped), and returns the bound
    /// that one keeps, `2(|x.hi|E_y + E_x(|y.hi| + E_y))`, on words with
    /// and without errors, zeros among them.
    #[test]
    fn add_dd_prod_adds_the_accumulators_words_and_bound() {
        use super::add_dd_prod;
        use crate::num::dd::{Acc, Dd, Dekker};
        let dd = |hi: f64, lo: f64, err: f64| Dd { hi, lo, err };
        let words = [
            dd(1.5, 2f64.powi(-60), 2f64.powi(-110)),
            dd(-3.0 / 7.0, 2f64.powi(-57) / 3.0, 0.0),
            dd(0.0, 0.0, 2f64.powi(-200)),
            dd(1e10 / 3.0, -1e-7 / 3.0, 1e-20),
            dd(-0.1, 0.0, 0.0),
        ];
        for x in words {
            for y in words {
                let mut acc = Acc::new();
                acc.add_dd_prod(x, y);
                let mut ours = Acc::new();
                let extra = add_dd_prod::<Dekker>(&mut ours, x, y);
                let want = 2.0 * (x.hi.abs() * y.err + x.err * (y.hi.abs() + y.err));
                assert_eq!(extra, want, "{x:?} {y:?}");
                let (a, b) = (acc.finish(), ours.finish());
                assert_eq!((a.hi, a.lo), (b.hi, b.lo), "{x:?} {y:?}");
                assert!(b.err <= a.err, "{x:?} {y:?}");
            }
        }
    }

    /// The grid stage takes spans that sum to its limit, 23, and no more:
    /// grazing `R = 3` at `(0, 3, 0)` from `(0, 3, −5)` (positions of span
    /// 3) along `(0, 0, 1 + 2⁻¹⁹)` (span 20) it answers the oracle's
    /// tangent; along `1 + 2⁻²⁰` (span 21) it answers nothing.
    #[test]
    fn grid_stage_takes_spans_up_to_its_limit() {
        use super::grid_exact;
        use crate::sphere::exactness::span_bound;
        let o = [0.0, 3.0, -5.0];
        assert_eq!(span_bound(&[0.0, 3.0, -5.0, 0.0, 0.0, 0.0, 3.0]), 3);
        for (j, span, answers) in [(19, 20, true), (20, 21, false)] {
            let d = [0.0, 0.0, 1.0 + 2f32.powi(-j)];
            assert_eq!(span_bound(&d), span);
            let ray = Ray::new(o.into(), d.into());
            let want = exact::intersect(&ray, &Sphere::new(glam::Vec3::ZERO, 3.0)).unwrap();
            assert!(matches!(want, crate::sphere::SphereHit::Tangent(_)));
            let got = grid_exact(o, d, [0.0; 3], 3.0);
            match got {
                Some(h) => assert!(answers && same_bits(&h, &want), "{got:?}, not {want:?}"),
                None => assert!(!answers, "span {span}"),
            }
        }
    }

    /// The grid stage agrees with the oracle on integer and dyadic lines
    /// and spheres of every class, and answers the exact tangents of the
    /// catalogue; allowed twice the spans of its proof (a limit of 46
    /// rather than 23), it answers some of these cases wrongly.
    #[test]
    fn grid_stage_is_right_and_its_limit_matters() {
        use super::{classes, grid_exact, grid_within};
        use crate::Ray;
        use crate::sphere::Sphere;
        let (answered, wrong_wide) = (std::cell::Cell::new(0), std::cell::Cell::new(0));
        let check = |o: [f32; 3], d: [f32; 3], c: [f32; 3], r: f32| {
            let ray = Ray::new(o.into(), d.into());
            let Ok(want) = exact::intersect(&ray, &Sphere::new(c.into(), r)) else {
                return;
            };
            if let Some(h) = grid_exact(o, d, c, r) {
                assert!(same_bits(&h, &want), "{o:?} {d:?} {c:?} {r}");
                answered.set(answered.get() + 1);
            }
            let w = |v: [f32; 3]| v.map(f64::from);
            let k = classes(w(o), w(d), w(c), f64::from(r), 1.0);
            if let Some(h) = grid_within(&k, o, d, c, r, 46) {
                wrong_wide.set(wrong_wide.get() + usize::from(!same_bits(&h, &want)));
            }
        };
        for family in &Catalogue::builtin().unwrap().families {
            for case in &family.cases {
                if let Case::Sphere(r, s) = case {
                    let a = |v: glam::Vec3| v.to_array();
                    check(a(r.origin), a(r.dir), a(s.center), s.radius);
                }
            }
        }
        let catalogue = answered.get();
        // Grazing R = 3 at (0, 3, 0) along steps of 2⁻ᵏ·(1 + 2⁻ʲ) from
        // an origin on the tangent line: Δ = 0, exact in f64 only while
        // the steps have few bits.
        for k in 0..8 {
            for j in [0, 3, 9, 13, 17, 22] {
                let s = (1.0 + 2f32.powi(-j)) * 2f32.powi(-k);
                check([0.0, 3.0, s], [0.0, 0.0, s], [0.0; 3], 3.0);
                check([1.0, 3.0, -5.0 * s], [0.0, 0.0, s], [1.0, 0.0, 0.0], 3.0);
                for i in [1, 5, 8, 11, 14] {
                    let z = -(1.0 + 2f32.powi(-i)) * 2f32.powi(k - j);
                    check([0.0, 3.0, z], [0.0, 0.0, s], [0.0; 3], 3.0);
                    check([0.0, 2.5, z], [0.0, s, s], [0.0; 3], 3.0);
                }
            }
        }
        assert!(catalogue >= 200, "{catalogue}");
        assert!(answered.get() > catalogue);
        assert!(wrong_wide.get() > 0);
    }
}
