//! The search that finds the cases of `fixtures/bounds/`: inputs on which a
//! kernel, with its filter's bounds multiplied by a factor `s < 1`, gives a
//! wrong answer for `s` as large as it can be made. For a case and a
//! certified quantity (the class, or one root), the *critical factor* is the
//! largest `s` at which that quantity comes out wrong: the case's actual
//! error, measured in units of the bound, where it crosses a decision (a
//! sign, or an f32 rounding boundary). A seeded hill-climb maximises it,
//! from seeds that sit on the edge of a decision by construction (roots by
//! an f32 rounding midpoint, numerators that round next to one, margins
//! `d·n`, `Δ`, `β² − 4αγ` near 0, a sphere's `c` and `Δ` and a quadric's
//! double-word `Δ` with every rounding of their bounds near its maximum
//! and in one direction), by moving single inputs by a few ulps or by
//! powers of two, keeping every move that does not lower the factor;
//! exact sphere tangents, which no one-input move keeps tangent, are
//! sampled instead. The committed cases are seeds too, so each run goes on
//! from the best found so far.
//!
//! Regenerate the cases (about a minute with `--release`) with
//!
//! ```text
//! RAYORACLE_BOUNDS_SEARCH=300000 cargo test --release --test all bounds_search -- --nocapture
//! ```
//!
//! which writes `fixtures/bounds/{plane,sphere,quadric}.jsonl`: the best
//! case found per kernel and quantity, and up to seven more whose factor
//! is at least 1/8. Without the variable the test runs a short search and
//! checks that it climbs.
#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]

use glam::Vec3;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use rayoracle::Ray;
use rayoracle::case::Case;
use rayoracle::hit::Intersection;
use rayoracle::plane::{self, Plane};
use rayoracle::quadric::{self, Quadric};
use rayoracle::sphere::{self, Sphere};

/// What a wrong answer got wrong first: the class, or root `i` (ascending).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantity {
    /// The class.
    Class,
    /// A root, the class being right.
    Root(usize),
}

impl Quantity {
    /// `class`, `root0` or `root1`.
    pub fn name(self) -> String {
        match self {
            Quantity::Class => "class".into(),
            Quantity::Root(i) => format!("root{i}"),
        }
    }
}

/// A class and root bits.
pub type Answer = (&'static str, Vec<u32>);

/// The class and root bits of `h`.
pub fn answer(h: &impl Intersection) -> Answer {
    let r = h.roots();
    (
        h.class().as_str(),
        r.as_slice().iter().map(|t| t.to_bits()).collect(),
    )
}

/// The oracle's answer (`None` for a non-finite case).
pub fn exact(case: &Case) -> Option<Answer> {
    match case {
        Case::Plane(r, p) => plane::exact::intersect(r, p).ok().map(|h| answer(&h)),
        Case::Sphere(r, s) => sphere::exact::intersect(r, s).ok().map(|h| answer(&h)),
        Case::Quadric(r, q) => quadric::exact::intersect(r, q).ok().map(|h| answer(&h)),
        Case::Camera(..) => None,
    }
}

/// The reference's answer with its filter's bounds multiplied by `s`.
fn shrunk(case: &Case, s: f64) -> Answer {
    match case {
        Case::Plane(r, p) => answer(&plane::reference::intersect_shrunk(r, p, s).0),
        Case::Sphere(r, sp) => answer(&sphere::reference::intersect_shrunk(r, sp, s).0),
        Case::Quadric(r, q) => answer(&quadric::reference::intersect_shrunk(r, q, s).0),
        Case::Camera(..) => unreachable!("no camera filter"),
    }
}

/// What the kernel with bounds times `s` gets wrong, if anything.
pub fn wrong_in(case: &Case, exact: &Answer, s: f64) -> Option<Quantity> {
    let got = shrunk(case, s);
    if got.0 != exact.0 {
        return Some(Quantity::Class);
    }
    (0..exact.1.len())
        .find(|&i| got.1[i] != exact.1[i])
        .map(Quantity::Root)
}

/// The critical factor's `log₂` for quantity `q`, to within 2⁻¹²: the
/// largest `s` in `[2⁻⁴⁰, 1]` at which `q` comes out wrong (by bisection,
/// as wrong answers grow with the shrinking); `None` if it is right at
/// `2⁻⁴⁰`.
pub fn critical_log2(case: &Case, exact: &Answer, q: Quantity) -> Option<f64> {
    let wrong = |l: f64| wrong_in(case, exact, l.exp2()) == Some(q);
    let (mut lo, mut hi) = (-40.0, 0.0);
    if !wrong(lo) {
        return None;
    }
    if wrong(hi) {
        return Some(0.0);
    }
    while hi - lo > 1.0 / 4096.0 {
        let mid = 0.5 * (lo + hi);
        if wrong(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Some(lo)
}

/// A case's inputs, in the order of the `eval` fields.
pub fn fields(case: &Case) -> Vec<f32> {
    let flat = |vs: &[Vec3]| vs.iter().flat_map(|x| x.to_array()).collect::<Vec<f32>>();
    match case {
        Case::Plane(r, p) => flat(&[r.origin, r.dir, p.point, p.normal]),
        Case::Sphere(r, s) => [flat(&[r.origin, r.dir, s.center]), vec![s.radius]].concat(),
        Case::Quadric(r, q) => [flat(&[r.origin, r.dir]), q.coeffs.to_vec()].concat(),
        Case::Camera(..) => Vec::new(),
    }
}

/// The case of `kind` with these inputs.
pub fn from_fields(kind: &str, v: &[f32]) -> Case {
    let at = |i: usize| Vec3::new(v[i], v[i + 1], v[i + 2]);
    let ray = Ray::new(at(0), at(3));
    match kind {
        "plane" => Case::Plane(ray, Plane::new(at(6), at(9))),
        "sphere" => Case::Sphere(ray, Sphere::new(at(6), v[9])),
        _ => Case::Quadric(ray, Quadric::new(v[6..16].try_into().expect("ten"))),
    }
}

/// The case as one `eval` line, every input as its bits.
pub fn to_line(case: &Case, family: &str) -> String {
    let v = fields(case);
    let hex = |xs: &[f32]| {
        let s: Vec<String> = xs
            .iter()
            .map(|x| format!("\"{:#010x}\"", x.to_bits()))
            .collect();
        format!("[{}]", s.join(","))
    };
    let head = format!(
        r#"{{"kind":"{}","family":"{family}","origin":{},"dir":{}"#,
        case.kind(),
        hex(&v[0..3]),
        hex(&v[3..6])
    );
    match case {
        Case::Plane(..) => format!(
            r#"{head},"point":{},"normal":{}}}"#,
            hex(&v[6..9]),
            hex(&v[9..12])
        ),
        Case::Sphere(..) => format!(
            r#"{head},"center":{},"radius":"{:#010x}"}}"#,
            hex(&v[6..9]),
            v[9].to_bits()
        ),
        _ => format!(r#"{head},"coeffs":{}}}"#, hex(&v[6..16])),
    }
}

/// An f32 with a random 24-bit significand in `[2^e, 2^(e+1))`.
pub fn mant(rng: &mut SmallRng, e: i32) -> f32 {
    (1.0 + rng.random_range(0..1u32 << 23) as f32 / 8388608.0) * 2f32.powi(e)
}

/// [`mant`] with `e` drawn from `lo..hi`.
fn mant_in(rng: &mut SmallRng, lo: i32, hi: i32) -> f32 {
    let e = rng.random_range(lo..hi);
    mant(rng, e)
}

/// An f32 `x` of a random exponent `e` in `−20..20`, half its ulp,
/// `2^(e − k)·m` with `k` in `ks` and `m ∈ [1, 2)`, and a random sign:
/// the makings of a value `x + ulp(x)/2 ± ε` next to a rounding midpoint.
pub fn near_midpoint(rng: &mut SmallRng, ks: std::ops::Range<i32>) -> (f32, f32, f32, f32) {
    let e = rng.random_range(-20..20);
    let x = mant(rng, e);
    let k = rng.random_range(ks);
    let eps = mant(rng, e - k);
    let sign = if rng.random() { 1.0 } else { -1.0 };
    (x, 2f32.powi(e - 24), eps, sign)
}

/// Planes whose root is an f32 rounding midpoint plus a tiny offset: `d =
/// x̂`, `n = (1, ulp/2, ε)`, `a = (x, 1, ±1)`, so `t = x + ulp(x)/2 ± ε`;
/// and near-parallel planes, `d·n` a few roundings of its terms from 0.
pub fn plane_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    (0..n)
        .map(|i| {
            if i % 2 == 0 {
                let (x, half_ulp, eps, sign) = near_midpoint(rng, 40..56);
                let o = Vec3::new(rng.random_range(-4.0..4.0), 0.0, 0.0);
                let ray = Ray::new(o, Vec3::X);
                let p = Plane::new(Vec3::new(x + o.x, 1.0, sign), Vec3::new(1.0, half_ulp, eps));
                Case::Plane(ray, p)
            } else {
                // d·n = x·y − x·y' + z·w with y − y' one ulp and z·w tiny.
                let (x, y) = (mant(rng, 0), mant(rng, 0));
                let y2 = f32::from_bits(y.to_bits() + 1);
                let e = rng.random_range(-60..-40);
                let w = mant(rng, e);
                let d = Vec3::new(x, x, 1.0);
                let n = Vec3::new(y, -y2, w);
                let o = Vec3::new(mant(rng, 2), mant(rng, 2), mant(rng, 2));
                Case::Plane(Ray::new(o, d), Plane::new(Vec3::ZERO, n))
            }
        })
        .collect()
}

/// Planes for the first pass, whose sums cancel by less than `2¹⁰`:
/// with `o = (−x, ε, 0)`, `d = (0, 1, 0)`, `a = (C, 2⁻²⁴, −Ck)` and `n =
/// (k, k, 1)`, `d·n = k` (odd, so that the root's f32 rounding midpoints
/// do not lie on the grid of its numerator's roundings) and `(a − o)·n =
/// (C + x)k + (2⁻²⁴ − ε)k − Ck`: the root is `x + 2⁻²⁴ − ε`, a midpoint
/// moved by `ε` (`2⁻⁵⁵` to `2⁻⁴⁵`), while `(C + x)k` rounds by up to
/// `2ᵉ⁻⁵²` for `C = 2ᵉ` (`e` from 4 to 9), enough to cross it.
pub fn plane_first_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    (0..n)
        .map(|_| {
            let x = mant(rng, 0);
            let k = f32::from_bits(mant(rng, 0).to_bits() | 1);
            let c = 2f32.powi(rng.random_range(4..10));
            let (e, sign) = (rng.random_range(-55..-45), rng.random::<bool>());
            let eps = if sign { mant(rng, e) } else { -mant(rng, e) };
            let ray = Ray::new(Vec3::new(-x, eps, 0.0), Vec3::Y);
            let plane = Plane::new(Vec3::new(c, 2f32.powi(-24), -c * k), Vec3::new(k, k, 1.0));
            Case::Plane(ray, plane)
        })
        .collect()
}

/// Planes on which the first pass's bound is nearly all used: every
/// rounding it covers is close to half an ulp and moves `t̂` the same way,
/// below the exact root, and `t̂` lies just below an f32 rounding midpoint,
/// so the exact root lies above it. With `n = (n₀, 2⁻³⁰, n₂)`, `d = (1,
/// d₁, d₂)`, `o = (o₀, o₁, o₂)` and `a = (a₀, a₁, a₂)`:
///
/// * `p̂₀ = fl(fl(a₀ − o₀)n₀) ∈ [1, 2)`, `o₀` too small for the difference to
///   be exact, and `p̂₂ = fl(fl(a₂ − o₂)n₂) ≈ −p̂₀(1 − 2/1025)`: the
///   first the best of sixty-four draws with both roundings down, the
///   third the first draw whose roundings leave it below its exact value;
/// * `p₁ = (k + ½ − 2⁻²¹)·2⁻⁵²`, exact, so that `fl(p̂₀ + p₁)` drops just
///   under half an ulp, and the integer `k` places `t̂`;
/// * `num = p̂₀ + p₁ + p̂₂` cancels by just under `K/2`, the most the pass
///   accepts (`m_num ≈ 2p̂₀ < K|num|`), so the three terms' roundings come
///   to about `2.5Ku|t|`;
/// * `d·n = n₀ + d₁2⁻³⁰ + d₂n₂`, with `d₁2⁻³⁰` just under half an ulp of
///   `n₀` and lost, and `n₀ + d₂n₂` just over `n₀/1023`, the most
///   cancellation the pass accepts: another `Ku|t|` in the same direction.
///
/// The root is near 2, at the top of its binade, where the certificate's
/// margin in bit patterns is widest for its error; `t̂` is put a random
/// fraction of the error below the midpoint. The second pass and the tight
/// stage, whose `d·n` is exact or nearly, see the numerator's share alone.
pub fn plane_rounding_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    let mut out = Vec::with_capacity(n);
    while out.len() < n {
        out.extend(plane_rounding(rng));
    }
    out
}

/// One of [`plane_rounding_seeds`], if the draws allow it.
fn plane_rounding(rng: &mut SmallRng) -> Option<Case> {
    // The exact error of fl(fl(a − o)n), positive where both round down.
    let err = |a: f32, o: f32, n: f32| {
        let (a, o, n) = (f64::from(a), f64::from(o), f64::from(n));
        let w = a - o;
        let e_w = (a - w) - o;
        let p = w * n;
        (p, e_w * n + w.mul_add(n, -p))
    };
    let grid = |rng: &mut SmallRng, base: f32, bits: u32| {
        base + rng.random_range(0..1u32 << bits) as f32 * f32::EPSILON
    };
    let tiny = |rng: &mut SmallRng| {
        let e = rng.random_range(-45..-30);
        mant(rng, e)
    };
    let (mut best, mut e0) = (None, 0.0);
    for _ in 0..64 {
        let (n0, a0, o0) = (grid(rng, 1.002, 14), grid(rng, 1.0, 14), tiny(rng));
        let (p0, e) = err(a0, o0, n0);
        if e > e0 && p0 < 1.002 * f64::from(n0) {
            (best, e0) = (Some((n0, a0, o0, p0)), e);
        }
    }
    let (n0, a0, o0, p0) = best?;
    let (n2, o2) = (grid(rng, 1.0, 12), tiny(rng));
    let want = p0 * (1.0 - 2.0 / 1025.0 * (1.0 + 2f64.powi(-12)));
    let a2_bits = ((want / f64::from(n2)) as f32).to_bits();
    let (a2, p2, e2) = (0..16).find_map(|i| {
        let a2 = -f32::from_bits(a2_bits - i);
        let (p2, e2) = err(a2, o2, n2);
        (e2 > 0.0).then_some((a2, p2, e2))
    })?;
    let d2 = -((f64::from(n0) * (1.0 - (1.0 + 2f64.powi(-12)) / 1023.0) / f64::from(n2)) as f32);
    let den = f64::from(n0) + f64::from(d2) * f64::from(n2);
    let num0 = p0 + p2;
    let t0 = num0 / den;
    let f = t0 as f32;
    let ulp = f32::from_bits(f.to_bits() + 1) - f;
    let mid = f64::from(f) + f64::from(ulp) / 2.0;
    // The error in f64 ulps of t near 2: the numerator's and d·n's shares.
    let u52 = 2f64.powi(-52);
    let e_num = e0 + e2 + u52 / 2.0;
    let patterns = (e_num / num0.abs() + u52 / 2.0 / den) * mid / u52;
    let below = patterns * rng.random_range(0.3..0.95);
    let k = ((mid - below * u52) * den - num0) / u52;
    let k = k.round();
    if k.abs() >= f64::from(1u32 << 23) {
        return None;
    }
    let (a1, o1) = (
        k as f32 * 2f32.powi(-22),
        -(2f32.powi(-23) - 2f32.powi(-43)),
    );
    let d1 = -(2f32.powi(-23) - 2f32.powi(-43));
    let ray = Ray::new(Vec3::new(o0, o1, o2), Vec3::new(1.0, d1, d2));
    let plane = Plane::new(Vec3::new(a0, a1, a2), Vec3::new(n0, 2f32.powi(-30), n2));
    Some(Case::Plane(ray, plane))
}

/// Spheres grazed at a relative miss distance of 10⁻² to 10⁻⁹, from
/// distances of 1 to 10⁶ radii; and exact tangents: `f = o − C = (R, 0,
/// z)` along `d = (0, 0, d_z)`, where `Δ = 0` but `|f|²` rounds, and
/// `f = (R, 3k, 4k)` along `(0, 3, 4)`, where `f̂` rounds too.
pub fn sphere_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    (0..n)
        .map(|i| {
            if i % 4 == 3 {
                return sphere_tangent(rng);
            }
            if i % 2 == 1 {
                let e = rng.random_range(-10..10);
                let r = mant(rng, e);
                let cx = mant_in(rng, e - 3, e + 3);
                let c = Vec3::new(cx, mant(rng, e), 0.0);
                let oz = mant_in(rng, e + 5, e + 25);
                let o = Vec3::new(c.x + r, c.y, -oz);
                let r = o.x - c.x;
                let d = Vec3::new(0.0, 0.0, mant_in(rng, -5, 5));
                return Case::Sphere(Ray::new(o, d), Sphere::new(c, r));
            }
            let r = 10f32.powf(rng.random_range(-3.0..3.0));
            let dist = r * 10f32.powf(rng.random_range(0.3..6.0));
            let miss = 1.0 + rng.random_range(-1.0..1.0) * 10f32.powf(rng.random_range(-9.0..-2.0));
            let c = Vec3::new(rng.random_range(-10.0..10.0), 0.0, 0.0);
            let o = c + Vec3::new(0.0, r * miss, -dist);
            let d = Vec3::new(rng.random_range(-1e-3..1e-3), 0.0, 1.0);
            Case::Sphere(Ray::new(o, d), Sphere::new(c, r))
        })
        .collect()
}

/// An exact tangent whose `f̂` rounds: `f = (R, 3k, 4k)` and `d = (0, 3s,
/// 4s)` give `f × d = (0, −4Rs, 3Rs)`, so `|f × d| = R|d|` and `Δ = 0`;
/// `k = w − m` with `w` and `m` 2²⁰ to 2⁶⁰ apart, so that `f̂ = fl(o − C)`
/// rounds, and differently in `y` and `z`.
pub fn sphere_tangent(rng: &mut SmallRng) -> Case {
    let small = |rng: &mut SmallRng, e: i32| {
        (rng.random_range(1u32 << 20..1 << 21) as f32) * 2f32.powi(e - 20)
    };
    let (eo, ec) = (rng.random_range(-30..-10), rng.random_range(10..30));
    let (w, m, sd) = (small(rng, eo), small(rng, ec), small(rng, 0));
    let (er, ex) = (rng.random_range(-5..5), rng.random_range(-5..5));
    let (r, cx) = (small(rng, er), small(rng, ex));
    let o = Vec3::new(cx + r, 3.0 * w, 4.0 * w);
    let c = Vec3::new(cx, 3.0 * m, 4.0 * m);
    let d = Vec3::new(0.0, 3.0 * sd, 4.0 * sd);
    Case::Sphere(Ray::new(o, d), Sphere::new(c, o.x - cx))
}

/// The best of `n` [`sphere_tangent`]s for the sphere's class: moving one
/// input by an ulp would leave the tangent, so this family is sampled,
/// not climbed.
pub fn sphere_tangent_search(seed: u64, n: usize) -> Vec<Found> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let q = Quantity::Class;
    let mut out: Vec<Found> = (0..n)
        .filter_map(|_| {
            let c = sphere_tangent(&mut rng);
            let log2 = critical_log2(&c, &exact(&c)?, q)?;
            Some(Found {
                case: c,
                quantity: q,
                log2,
            })
        })
        .collect();
    out.sort_by(|a, b| b.log2.total_cmp(&a.log2));
    out.truncate(8);
    out
}

/// Lines from a point on a sphere's surface, where the root near 0 is
/// `c/q` with `c = f·f − R²` nearly 0 and its bound is mostly `E_c/|q|`,
/// built so that `ĉ` carries nearly all the error it can: `o` tiny and the
/// centre `C` at `2ᵏ` to within `2⁸` of its ulps per component, so that
/// `f̂ᵢ = fl(oᵢ − Cᵢ)`, just above a power of two, rounds by nearly half an
/// ulp (the bits `oᵢ` has below `ulp(fᵢ)` make a half ulp plus or minus
/// `2⁻ᵍ` of one), and of `tries` such components the one whose square and
/// whose running sum `f·f` round the most in that same direction; `R`
/// within two ulps of `|f|`, so that `f·f − R²` cancels exactly and `c/q`
/// is tiny, and `d` random, which moves the root against the f32 grid
/// without touching `ĉ`. Every rounding then adds up: twice `u f·f` from
/// `f̂`, and up to `u f·f` from the squares and from each sum, near `5u
/// f·f` in all, against `E_c = 10u f̂f + 2u|ĉ|`, about `10u f·f` here.
pub fn sphere_surface_seeds(rng: &mut SmallRng, n: usize, tries: usize) -> Vec<Case> {
    use rayoracle::num::dd::{two_prod, two_sum};
    (0..n)
        .map(|_| {
            let k0 = rng.random_range(0..=20);
            let ks = [
                k0,
                k0 - [0, 0, 3, 6, 9][rng.random_range(0..5)],
                k0 - [3, 6, 9, 12][rng.random_range(0..4)],
            ];
            let up: bool = rng.random();
            let (dir, g): (f32, i32) = (if up { 1.0 } else { -1.0 }, rng.random_range(6..=12));
            let (mut o, mut c) = ([0f32; 3], [0f32; 3]);
            let mut sum: Option<f64> = None;
            for i in 0..3 {
                let s = if rng.random() { 1.0 } else { -1.0 };
                let mut best = (f64::NEG_INFINITY, 0f32, 0f32, 0f64);
                for _ in 0..tries {
                    let k = ks[i];
                    let j = rng.random_range(0..=256) as f32;
                    let ci = -s * 2f32.powi(k) * (1.0 + j * 2f32.powi(-23));
                    let m = rng.random_range(0..1u32 << (23 - g));
                    let frac = (1u32 << (g - 1)) as f32 + dir;
                    let oi = s * ((m << g) as f32 + frac) * 2f32.powi(k - 52 - g);
                    let f = f64::from(oi) - f64::from(ci);
                    // The roundings of f̂², and of the sum it joins, as
                    // computed minus exact.
                    let (sq, e) = two_prod(f, f);
                    let (next, rounded) = match sum {
                        None => (sq, -e),
                        Some(acc) => {
                            let (t, r) = two_sum(acc, sq);
                            (t, -e - r)
                        }
                    };
                    if f64::from(dir) * rounded > best.0 {
                        best = (f64::from(dir) * rounded, ci, oi, next);
                    }
                }
                (c[i], o[i], sum) = (best.1, best.2, Some(best.3));
            }
            let ff: f64 = (0..3)
                .map(|i| (f64::from(o[i]) - f64::from(c[i])).powi(2))
                .sum();
            let r = (ff.sqrt() as f32).to_bits() as i64 + rng.random_range(-2..=2);
            let d = [0; 3].map(|_| {
                let s = if rng.random() { 1.0 } else { -1.0 };
                s * (1.0 + rng.random_range(0.0..1.0f32)) * 2f32.powi(rng.random_range(-2..=2))
            });
            Case::Sphere(
                Ray::new(Vec3::from(o), Vec3::from(d)),
                Sphere::new(Vec3::from(c), f32::from_bits(r as u32)),
            )
        })
        .collect()
}

/// Lines that just touch a sphere or just cross it, built so that `Δ̂`
/// carries nearly all the error its bound allows, and in one direction:
/// down, across 0, while the exact `Δ` is 0 or just above, so that the
/// filter certifies no root. `f = o − C` is nearly `−λd`, where (to first
/// order) the rounding of `f̂` cancels out of `Δ`, so `f̂` is left exact:
/// `C ≈ d` to within `2⁸` of its ulps per component, and `o` small (`2⁻²⁷`
/// to `2⁻²⁵`), which fills in the low bits of `f`. With `d = (dx, dy,
/// dz)`, `dx` and `dy` just above 1, and `dz = fz` just above `2⁻²⁶`
/// (`o_z = dz`, `C_z = 0`, so that `fz dz` has the sign opposite to `b`),
/// every quantity of the filter lies just above a power of two, where a
/// rounding error of half an ulp is a relative `u`, and:
///
/// * `f̂ᵢdᵢ` (`i` = x, y) rounds down in magnitude and `f̂ᵢ²` up, each by
///   at least 0.35 ulp (of `tries` draws of each component, the ones that
///   do);
/// * `f̂ₓdₓ + f̂ᵧdᵧ` rounds down by exactly half an ulp (a tie, the two
///   terms being in one binade) and `f̂ₓ² + f̂ᵧ²` up (the pairs of
///   components whose ties go that way);
/// * `fz dz` and `fz²` are just above half an ulp of `b` and of `f·f`, so
///   that adding them rounds `b` down and `f·f` up by nearly half an ulp,
///   and `dz²` likewise rounds `a` up (`dx² + dy²` is exact);
/// * `R` is the smallest f32 for which the line is not a miss (`Δ =
///   aR² − |f × d|² ≥ 0`, found by the oracle's class), tiny against
///   `|f|`, so that `ĉ = f·f − R²` and `âĉ` round as they may.
///
/// Then `b̂` is low by up to `3u b`, `b̂²` by up to `7u b²`, and `âĉ` high
/// by up to `6u b²` (`u` from `â`, `3u` from `f·f`, `u` from `c`, `u` from
/// the product), against `E_Δ = 20u(m_b² + â m_c) ≈ 40u b²`: a factor of
/// up to `13/40`. Of the pairs, the one whose `Δ̂` is lowest in units of
/// `E_Δ` (computed as the filter does) is kept.
pub fn sphere_rounding_seeds(rng: &mut SmallRng, n: usize, tries: usize) -> Vec<Case> {
    (0..n)
        .filter_map(|_| sphere_rounding(rng, tries, false))
        .collect()
}

/// The mirror of [`sphere_rounding_seeds`]: lines that just miss or just
/// touch a sphere, with every rounding of `Δ̂` near half an ulp and
/// pushing it up, across 0, while the exact `Δ` is 0 or just below, so
/// that the filter certifies two roots where there are none or one. The
/// same lines, with each direction turned over:
///
/// * `f̂ᵢdᵢ` rounds up in magnitude and `f̂ᵢ²` down, the tie of `f̂ₓdₓ +
///   f̂ᵧdᵧ` up in magnitude and that of `f̂ₓ² + f̂ᵧ²` down;
/// * `dz = fz` is just below `2⁻²⁶`, so that `fz dz` (of the sign opposite
///   to `b`), `fz²` and `dz²` are just below half an ulp of `b`, `f·f`
///   and `a`, and are lost: `b̂` high in magnitude, `f·f` and `â` low,
///   each by nearly half an ulp;
/// * `R` is the largest f32 for which the line does not cross the sphere
///   (`Δ ≤ 0`, by the oracle's class).
///
/// `b̂² ≈ 4` and `âĉ ≈ 4`, so `Δ̂` is a multiple of `2⁻⁵⁰`, about `E_Δ/20`,
/// and the roundings come to at most 6.5 of those: the factor is at most
/// `6/20`, `2^-1.74`. A class of two is only answered with both roots
/// certified, and at the factor `s` the roots `−b̂/â ∓ ŝ/â` (`ŝ = √Δ̂`)
/// are known to within about `sE_Δ/(âŝ)`, nearly `ŝ/â` itself where `s`
/// approaches `Δ̂/E_Δ`: with `ŝ/â` about 0.3 of the f32 ulp of the
/// root, `C` is drawn on the far side of `d` (`Cᵢ − dᵢ` from 1 to 256 of
/// its ulps), so that the roots `t ≈ 1 + (C − d − o)·d/a` lie just above 1,
/// where that ulp is `2⁻²³`, and each enclosure fits in a rounding cell
/// only where a rounding midpoint lies between the roots, away from both.
/// Of the pairs of components, the one kept has the largest `s` at which
/// both enclosures fit and `Δ̂ > sE_Δ` (computed as the filter does, with
/// `R` first estimated as `|f × d|/√a`, then found by the oracle for the
/// best eight).
pub fn sphere_rounding_up_seeds(rng: &mut SmallRng, n: usize, tries: usize) -> Vec<Case> {
    (0..n)
        .filter_map(|_| sphere_rounding(rng, tries, true))
        .collect()
}

/// The distance from `x` to the nearest f32 rounding midpoint.
fn to_midpoint(x: f64) -> f64 {
    let y = x as f32;
    let (lo, hi) = (y.next_down(), y.next_up());
    let below = 0.5 * (f64::from(y) + f64::from(lo));
    let above = 0.5 * (f64::from(y) + f64::from(hi));
    (x - below).min(above - x)
}

/// One of [`sphere_rounding_seeds`] (or, `up`, of
/// [`sphere_rounding_up_seeds`]), if the draws allow it.
fn sphere_rounding(rng: &mut SmallRng, tries: usize, up: bool) -> Option<Case> {
    use rayoracle::num::dd::{two_prod, two_sum};
    let ulp = |x: f64| f64::from_bits(x.abs().to_bits() & 0x7ff0_0000_0000_0000) * f64::EPSILON;
    // +1 where a rounding is to push Δ̂ down, −1 where up.
    let dir = if up { -1.0 } else { 1.0 };
    let step = 2f32.powi(-23);
    let dv = [0; 2].map(|_| 1.0 + rng.random_range(1..1 << 12) as f32 * step);
    // Components (o, C, f) whose product with d rounds down in magnitude
    // and whose square rounds up (or, `up`, the reverse), both by at least
    // 0.35 ulp.
    let components = |rng: &mut SmallRng, d: f32| {
        let mut out = Vec::new();
        for _ in 0..tries {
            let k = if up {
                rng.random_range(1..=256)
            } else {
                rng.random_range(-256..=256)
            };
            let c = d + k as f32 * step;
            let s = if rng.random() { 1.0 } else { -1.0 };
            let o = s * rng.random_range(2f32.powi(-27)..2f32.powi(-25));
            let f = f64::from(o) - f64::from(c);
            let (p, e) = two_prod(f, f64::from(d));
            let (q, g) = two_prod(f, f);
            if dir * e * p.signum() >= 0.35 * ulp(p) && -dir * g >= 0.35 * ulp(q) {
                out.push((o, c, f, p, q));
            }
        }
        out
    };
    let (xs, ys) = (components(rng, dv[0]), components(rng, dv[1]));
    let dz = if up {
        f32::from_bits(2f32.powi(-26).to_bits() - 1)
    } else {
        f32::from_bits(2f32.powi(-26).to_bits() + 1)
    };
    let d = Vec3::new(dv[0], dv[1], dz);
    let dd = [dv[0], dv[1], dz].map(f64::from);
    let a = dd[0] * dd[0] + dd[1] * dd[1] + dd[2] * dd[2];
    // The factor each direction aims at, from Δ̂ and E_Δ as the filter
    // computes them for the radius `r`.
    let score = |(sb, sf, mb, fz): (f64, f64, f64, f64), r: f32| {
        let (bb, ff, rr) = (sb + fz * dd[2], sf + fz * fz, f64::from(r) * f64::from(r));
        let disc = bb * bb - a * (ff - rr);
        let ed = 20.0 * f64::EPSILON / 2.0 * (mb * mb + a * (ff + rr));
        if !up {
            return -disc / ed;
        }
        if disc <= 0.0 {
            return f64::NEG_INFINITY;
        }
        let (s, t) = (disc.sqrt(), -bb / a);
        let room = to_midpoint(t - s / a).min(to_midpoint(t + s / a));
        disc.min(a * s * room) / ed
    };
    let mut pairs = Vec::new();
    for &(ox, cx, fx, px, qx) in &xs {
        for &(oy, cy, fy, py, qy) in &ys {
            // The ties: b's partial sum down in magnitude, f·f's up (or,
            // `up`, the reverse).
            let (sb, rb) = two_sum(px, py);
            let (sf, rf) = two_sum(qx, qy);
            if dir * rb * sb.signum() <= 0.0 || dir * rf >= 0.0 {
                continue;
            }
            let o = Vec3::new(ox, oy, dz);
            let c = Vec3::new(cx, cy, 0.0);
            let f = [fx, fy, f64::from(dz)];
            let cross = [
                f[1] * dd[2] - f[2] * dd[1],
                f[2] * dd[0] - f[0] * dd[2],
                f[0] * dd[1] - f[1] * dd[0],
            ];
            let cross2: f64 = cross.iter().map(|x| x * x).sum();
            let r = (cross2 / a).sqrt() as f32;
            let mb = px.abs() + py.abs() + (f[2] * dd[2]).abs();
            let sums = (sb, sf, mb, f[2]);
            pairs.push((score(sums, r), r, o, c, sums));
        }
    }
    // Down, every pair has its radius found; up, the best eight by the
    // estimate.
    if up {
        pairs.sort_by(|x, y| y.0.total_cmp(&x.0));
        pairs.truncate(8);
    }
    let mut best: Option<(f64, Case)> = None;
    for (_, mut r, o, c, sums) in pairs {
        let case = |r: f32| Case::Sphere(Ray::new(o, d), Sphere::new(c, r));
        let next = |r: f32, k: i32| f32::from_bits((r.to_bits() as i32 + k) as u32);
        if up {
            // The largest R with no two roots.
            let two = |r: f32| exact(&case(r)).is_some_and(|e| e.0 == "two");
            while !two(r) {
                r = next(r, 1);
            }
            while two(r) {
                r = next(r, -1);
            }
        } else {
            // The smallest R with a root.
            let miss = |r: f32| exact(&case(r)).is_none_or(|e| e.0 == "none");
            while miss(r) {
                r = next(r, 1);
            }
            while !miss(next(r, -1)) {
                r = next(r, -1);
            }
        }
        let factor = score(sums, r);
        if best.as_ref().is_none_or(|b| factor > b.0) {
            best = Some((factor, case(r)));
        }
    }
    best.map(|b| b.1)
}

/// Lines crossing two parallel planes `(x + νy)² = ε` (`ν = 2⁻²⁴`, `ε` a
/// tiny power of two), a double plane opened just enough for two roots,
/// on which the double-word stage's `Δ̂` carries more than half the error
/// its bound allows, and upwards. That stage takes `Δ/4 = b² − ac` (`b =
/// β/2`) from the leading words `â`, `b̂`, `ĉ` of the exact coefficients
/// (`quadric::stages::disc_near`): its bound `E` counts each word's
/// distance from the exact value, `2|b̂||lo_b| + |â||lo_c| + |ĉ||lo_a|`,
/// and `3u(b̂² + |âĉ|)` for the roundings; it takes the sign where `Δ̂ >
/// 2sE` at the factor `s`, and the roots `(−b̂ ± √Δ̂)/â` to within
/// `sE/(â√Δ̂)`. With `o = (o₀, o₁, 0)`, `d = (d₀, d₁, 0)`, `P = o₀ + νo₁`
/// and `D = d₀ + νd₁`: `a = D²`, `b = PD`, `c = P² − ε`, and `Δ/4 = D²ε`,
/// the roots `−P/D ± √ε/D`, nearly a double root.
///
/// * `P` and `D` are odd 27-bit integers `K_P`, `K_D` above `2^26.5` times
///   powers of two, so that `D²`, `PD` and `P²` have 54 bits: each lies
///   halfway between two f64 values and its word is off by half an ulp,
///   the most there is. An odd square is 1 modulo 8, so `D²` rounds down
///   (to even), `P² − ε`, just below its tie, rounds down, and `K_P K_D ≡
///   3 (mod 4)` makes `PD` round up. `Δ̂/4` then gains `2|b̂|h_b + |â|h_c +
///   |ĉ|h_a` (`h` half an ulp): with `b̂² ∈ [2^2m, 2^(2m+1))`, `a` just
///   above 2 and `c` 10 to 20 % above a power of two (`P/D` 1.05 to 1.1
///   times `2ᵖ`), at least `4U`, `U = u·2^2m`.
/// * `b̂²` and `âĉ` round to multiples of `2U`, so `Δ̂/4` is `6U` where
///   their roundings, up and down, add the rest: of `tries` draws of
///   `K_D` and of an f32 rounding midpoint near `P/D`, the best, by `Δ̂`
///   and `E` computed as the stage computes them. Against `E ≈ 11U`, the
///   sign is taken up to a factor of about 0.27.
/// * `K_P` puts `P/D` a quarter of the expected `√Δ̂/a` from the midpoint,
///   below it for the lesser root (`upper` false) to cross it, above it
///   for the greater, so that wherever the sign is taken that root is
///   certified on the wrong side; `ε = 2^(2p − 80)` parts the exact
///   roots by about `2^-39.5` of `|t|`, far less.
///
/// The filter, whose `E_Δ` (of `Δ = 4(b² − ac)`) is `700u b²` here, leaves
/// these lines to the later stages, and the tracked stage, their sums not
/// fitting one f64, to the double-word stage.
pub fn quadric_rounding_seeds(rng: &mut SmallRng, n: usize, tries: usize) -> Vec<Case> {
    (0..n)
        .filter_map(|i| quadric_rounding(rng, tries, i % 2 == 1))
        .collect()
}

/// One of [`quadric_rounding_seeds`], its greater root the one to cross a
/// midpoint if `upper`, if the draws allow it.
fn quadric_rounding(rng: &mut SmallRng, tries: usize, upper: bool) -> Option<Case> {
    use rayoracle::num::dd::two_prod;
    let u = f64::EPSILON / 2.0;
    let nu = 2f32.powi(-24);
    let p = rng.random_range(0..8);
    let eps = 2f32.powi(2 * p - 80);
    let mut best: Option<(f64, u64, u64)> = None;
    for _ in 0..tries {
        // D = K_D·2⁻²⁶ just above √2, so that a = D² is just above 2.
        let kd = (94_906_267 + 2 * rng.random_range(0..1u64 << 16)) as f64;
        let dd = kd * 2f64.powi(-26);
        // The midpoint above the f32 y, P/D a quarter of √Δ̂/a beside it.
        let y = (1.05 + rng.random_range(0.0..0.05f32)) * 2f32.powi(p);
        let mid = f64::from(y) + f64::from(f32::from_bits(y.to_bits() + 1) - y) / 2.0;
        let off = 0.25 * (6.0 * u).sqrt() * mid;
        let target = dd * if upper { mid + off } else { mid - off };
        // K_P odd, with K_P·K_D ≡ 3 (mod 4).
        let kp = (target * 2f64.powi(26 - p)).round() as u64;
        let kp = kp - kp % 4 + if kd as u64 % 4 == 1 { 3 } else { 1 };
        let pp = kp as f64 * 2f64.powi(p - 26);
        let (ah, al) = two_prod(dd, dd);
        let (bh, bl) = two_prod(pp, dd);
        let (ch, cl) = two_prod(pp, pp);
        let cl = cl - f64::from(eps);
        let (b2, ac) = (bh * bh, ah * ch);
        let disc = b2 - ac;
        let (eb, ea, ec) = (bl.abs(), al.abs(), cl.abs());
        let e = eb * (2.0 * bh.abs() + eb) + ah * ec + ea * (ch + ec) + 3.0 * u * (b2 + ac);
        if disc <= 0.0 {
            continue;
        }
        let s = disc.sqrt();
        let dist = (mid - pp / dd) * if upper { -1.0 } else { 1.0 };
        let score = (disc / (2.0 * e)).min((disc - ah * dist * s) / e);
        if dist > 0.0 && best.is_none_or(|b| score > b.0) {
            best = Some((score, kd as u64, kp));
        }
    }
    let (_, kd, kp) = best?;
    let split = |k: u64, e: i32| {
        let hi = (k - k % 8) as f32 * 2f32.powi(e - 26);
        let lo = (k % 8) as f32 * 2f32.powi(e - 2);
        (hi, lo)
    };
    let (d0, d1) = split(kd, 0);
    let (o0, o1) = split(kp, p);
    let mut k = [0.0; 10];
    (k[0], k[1], k[3], k[9]) = (1.0, nu * nu, 2.0 * nu, -eps);
    let ray = Ray::new(Vec3::new(o0, o1, 0.0), Vec3::new(d0, d1, 0.0));
    Some(Case::Quadric(ray, Quadric::new(k)))
}

/// Cylinders `x² + y² = 1` grazed at a relative miss of 10⁻² to 10⁻⁹, and
/// rays nearly along their axis.
pub fn quadric_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
    (0..n)
        .map(|i| {
            let miss = 1.0 + rng.random_range(-1.0..1.0) * 10f32.powf(rng.random_range(-9.0..-2.0));
            let ray = if i % 2 == 0 {
                let o = Vec3::new(-10f32.powf(rng.random_range(0.5..5.0)), miss, 0.0);
                Ray::new(o, Vec3::new(1.0, 0.0, rng.random_range(-1.0..1.0)))
            } else {
                let tilt = 10f32.powf(rng.random_range(-8.0..-1.0));
                Ray::new(Vec3::new(0.0, miss * 0.5, 0.0), Vec3::new(tilt, 0.0, 1.0))
            };
            Case::Quadric(ray, cyl)
        })
        .collect()
}

/// The seeds of a kind: its generated cases, the stiff catalogue's, and
/// (if `go_on`, for a long search) the committed ones and the planes,
/// sphere tangents and opened double planes built to the bound's limit
/// ([`plane_rounding_seeds`], [`sphere_rounding_seeds`],
/// [`quadric_rounding_seeds`]). Those start at the top, so the short
/// search, which must climb, starts without them; their own tests are
/// [`the_constructed_planes_use_most_of_the_bound`],
/// [`the_constructed_tangents_use_most_of_the_bound`] and
/// [`the_constructed_double_planes_use_most_of_the_bound`].
pub fn seeds(kind: &str, rng: &mut SmallRng, n: usize, go_on: bool) -> Vec<Case> {
    let mut out = match kind {
        "plane" => [plane_seeds(rng, n), plane_first_seeds(rng, n)].concat(),
        "sphere" => [sphere_seeds(rng, n), sphere_surface_seeds(rng, n / 8, 32)].concat(),
        _ => quadric_seeds(rng, n),
    };
    let cat = rayoracle::report::Catalogue::builtin().expect("the built-in catalogue");
    for f in cat.families.iter().filter(|f| f.name.starts_with(kind)) {
        out.extend(f.cases.iter().cloned());
    }
    if go_on {
        out.extend(committed(kind));
        if kind == "plane" {
            out.extend(plane_rounding_seeds(rng, n));
        }
        if kind == "sphere" {
            out.extend(sphere_rounding_seeds(rng, 16, 4096));
        }
        if kind == "quadric" {
            out.extend(quadric_rounding_seeds(rng, 16, 256));
        }
    }
    out
}

/// The cases of `fixtures/bounds/{kind}.jsonl`, so that a new search goes
/// on from the best found so far.
pub fn committed(kind: &str) -> Vec<Case> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(format!("fixtures/bounds/{kind}.jsonl"));
    let text = std::fs::read_to_string(path).unwrap_or_default();
    text.lines()
        .filter_map(|l| rayoracle::case::parse_line(l).ok())
        .map(|c| c.case)
        .collect()
}

/// One move: a random input nudged by a few ulps (up to 2²⁴), scaled by
/// a power of two, or given fresh low bits.
fn mutate(rng: &mut SmallRng, v: &mut [f32]) {
    let i = rng.random_range(0..v.len());
    let x = v[i];
    v[i] = match rng.random_range(0..8) {
        0 => x * 2f32.powi(rng.random_range(-2..=2)),
        1 => {
            let bits = rng.random_range(1..12);
            f32::from_bits(x.to_bits() ^ rng.random_range(0..1u32 << bits))
        }
        _ => {
            let top = rng.random_range(0..24);
            let width = rng.random_range(0..=top);
            let k = 1i64 << width;
            let step = rng.random_range(1..=k) * if rng.random() { 1 } else { -1 };
            f32::from_bits((x.to_bits() as i64 + step).clamp(0, u32::MAX as i64) as u32)
        }
    };
}

/// A case found for a quantity, with its critical factor's `log₂`.
#[derive(Clone, Debug)]
pub struct Found {
    /// The case.
    pub case: Case,
    /// The quantity it gets wrong.
    pub quantity: Quantity,
    /// `log₂` of the largest factor at which it is wrong.
    pub log2: f64,
}

/// Hill-climbs from `start` for `steps` moves, maximising the critical
/// factor of `q`; returns every improvement (the last is the best).
pub fn climb(rng: &mut SmallRng, start: &Case, q: Quantity, steps: usize) -> Vec<Found> {
    let score = |c: &Case| exact(c).and_then(|e| critical_log2(c, &e, q));
    let Some(best) = score(start) else {
        return Vec::new();
    };
    climb_by(rng, (best, start.clone()), steps, score)
        .into_iter()
        .map(|(log2, case)| Found {
            case,
            quantity: q,
            log2,
        })
        .collect()
}

/// The climb of [`climb`] for any score (a critical factor's `log₂`,
/// `None` where there is none), from a case and its score: moves that do
/// not lower the score are kept; returns the start and every
/// improvement, the best last.
pub fn climb_by(
    rng: &mut SmallRng,
    start: (f64, Case),
    steps: usize,
    score: impl Fn(&Case) -> Option<f64>,
) -> Vec<(f64, Case)> {
    let kind = start.1.kind();
    let (mut best, mut cur) = (start.0, fields(&start.1));
    let mut out = vec![start];
    for _ in 0..steps {
        let mut next = cur.clone();
        for _ in 0..rng.random_range(1..=2) {
            mutate(rng, &mut next);
        }
        if next.iter().any(|x| !x.is_finite()) {
            continue;
        }
        let c = from_fields(kind.as_str(), &next);
        if let Some(s) = score(&c).filter(|&s| s >= best) {
            if s > best {
                out.push((s, c));
            }
            best = s;
            cur = next;
        }
    }
    out
}

/// The quantities each kernel certifies with a bound that can be too
/// small. The plane's class is not among them: its products `dᵢnᵢ` are
/// exact in f64, so only the two additions of `d·n` round, and a computed
/// `d·n` never has the wrong sign. (For the sum `fl(fl(p₀ + p₁) + p₂)` to
/// cross 0, `p₂` must nearly cancel `F = fl(p₀ + p₁)`; a product of two
/// f32 values has 48 significant bits, so then `F + p₂` is a multiple of
/// `ulp(F)`, and either it is 0, computed exactly as 0, or it outweighs
/// the rounding of `F`, at most `ulp(F)/2`.)
pub fn quantities(kind: &str) -> &'static [Quantity] {
    match kind {
        "plane" => &[Quantity::Root(0)],
        _ => &[Quantity::Class, Quantity::Root(0), Quantity::Root(1)],
    }
}

/// The search for one kind: seeds (the committed cases among them if
/// `go_on`) scored per quantity, the best `starts` of each climbed for
/// `steps` moves; every improvement found, best first per quantity.
pub fn search(
    kind: &str,
    seed: u64,
    (pool, starts, steps): (usize, usize, usize),
    go_on: bool,
) -> Vec<Found> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let seeds = seeds(kind, &mut rng, pool, go_on);
    let mut out = Vec::new();
    for &q in quantities(kind) {
        let mut scored: Vec<(f64, &Case)> = seeds
            .iter()
            .filter_map(|c| Some((critical_log2(c, &exact(c)?, q)?, c)))
            .collect();
        scored.sort_by(|a, b| b.0.total_cmp(&a.0));
        let mut found: Vec<Found> = scored
            .iter()
            .take(starts)
            .flat_map(|(_, c)| climb(&mut rng, c, q, steps))
            .collect();
        found.sort_by(|a, b| b.log2.total_cmp(&a.log2));
        out.extend(found);
    }
    out
}

/// A short search climbs: from the seeds' best, each root reaches a
/// higher critical factor, at least 1/128.
#[test]
fn the_search_climbs_and_regenerates_the_fixtures_on_request() {
    let budget: Option<usize> = std::env::var("RAYORACLE_BOUNDS_SEARCH")
        .ok()
        .and_then(|v| v.parse().ok());
    for (i, kind) in ["plane", "sphere", "quadric"].into_iter().enumerate() {
        let (pool, starts, steps) = match budget {
            Some(n) => (8192, 8, n),
            None => (256, 1, 150),
        };
        let mut found = search(
            kind,
            0x5eed + i as u64,
            (pool, starts, steps),
            budget.is_some(),
        );
        if kind == "sphere" {
            found.extend(sphere_tangent_search(
                0x7a9,
                budget.map_or(2_000, |n| n * 2),
            ));
            found.sort_by(|a, b| b.log2.total_cmp(&a.log2));
        }
        for &q in quantities(kind) {
            let of_q: Vec<&Found> = found.iter().filter(|f| f.quantity == q).collect();
            let best = of_q.first().map_or(f64::NEG_INFINITY, |f| f.log2);
            let first = of_q.iter().map(|f| f.log2).fold(f64::INFINITY, f64::min);
            println!("{kind} {}: from 2^{first:.2} to 2^{best:.2}", q.name());
            if q != Quantity::Class {
                assert!(best >= -7.0, "{kind} {}: best 2^{best}", q.name());
                // A long search from the committed cases may find none
                // better; the short one from fresh seeds must climb.
                assert!(
                    budget.is_some() || best > first,
                    "{kind} {}: no climb",
                    q.name()
                );
            }
        }
        if budget.is_some() {
            let mut lines = Vec::new();
            for &q in quantities(kind) {
                let of_q = found.iter().filter(|f| f.quantity == q);
                for (j, f) in of_q.enumerate() {
                    if j == 0 || (j < 8 && f.log2 >= -3.0) {
                        lines.push(to_line(&f.case, &format!("bounds/{kind}/{}", q.name())));
                    }
                }
            }
            lines.dedup();
            let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/bounds");
            std::fs::create_dir_all(&dir).expect("fixtures/bounds");
            std::fs::write(dir.join(format!("{kind}.jsonl")), lines.join("\n") + "\n")
                .expect("write the cases");
        }
    }
}

/// The construction of [`plane_rounding_seeds`] works: from a fixed seed,
/// some of its planes make the reference's root wrong with every bound
/// shrunk to a quarter, with no search at all.
#[test]
fn the_constructed_planes_use_most_of_the_bound() {
    let mut rng = SmallRng::seed_from_u64(0x91a);
    let cases = plane_rounding_seeds(&mut rng, 32);
    reaches_a_quarter(&cases, |c| critical_log2(c, &exact(c)?, Quantity::Root(0)));
}

/// The construction of [`sphere_rounding_seeds`] works: from a fixed seed,
/// some of its lines make the reference's class wrong with every bound
/// shrunk to a quarter, with no search at all.
#[test]
fn the_constructed_tangents_use_most_of_the_bound() {
    let mut rng = SmallRng::seed_from_u64(0x7a3);
    let cases = sphere_rounding_seeds(&mut rng, 4, 512);
    reaches_a_quarter(&cases, |c| critical_log2(c, &exact(c)?, Quantity::Class));
}

/// The construction of [`quadric_rounding_seeds`] works: from a fixed
/// seed, some of its lines make the reference's lesser root wrong, and
/// some its greater, with every bound shrunk to a quarter, with no search
/// at all.
#[test]
fn the_constructed_double_planes_use_most_of_the_bound() {
    let mut rng = SmallRng::seed_from_u64(0x9ad);
    let cases = quadric_rounding_seeds(&mut rng, 4, 64);
    for q in [Quantity::Root(0), Quantity::Root(1)] {
        reaches_a_quarter(&cases, |c| critical_log2(c, &exact(c)?, q));
    }
}

/// Asserts that some case of a construction is wrong at a quarter of its
/// bound: `log2` gives a case's critical factor (`None` where it is right
/// at every factor).
pub fn reaches_a_quarter(cases: &[Case], log2: impl Fn(&Case) -> Option<f64>) {
    reaches(cases, log2, -2.0);
}

/// Asserts that some case of a construction is wrong at the factor
/// `2^at` of its bound, as [`reaches_a_quarter`] does at a quarter.
pub fn reaches(cases: &[Case], log2: impl Fn(&Case) -> Option<f64>, at: f64) {
    let factors: Vec<f64> = cases.iter().filter_map(log2).collect();
    let best = factors.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    println!(
        "{} of {} wrong somewhere, the best up to 2^{best:.2}",
        factors.len(),
        cases.len()
    );
    assert!(best >= at, "best 2^{best}");
}
