//! The bounds of each stage after the filter, and of the plane's first
//! pass, shrunk on their own. The shrunk reference of `bounds.rs` mostly
//! goes wrong in its filter, which answers first; a stage reached only
//! where the filter gives up needs its own cases, and so does the plane's
//! first pass, whose errors the search of `bounds.rs` leaves behind for
//! the larger ones of the full filter. Each stage that certifies with a
//! bound (the plane's first and second passes, tight and double-word stages; the
//! sphere's tight, compensated, words and double-word stages; the quadric's
//! words, tight and double-word stages, and the first pass of its x4 kernel,
//! `quadric::x4::first_pass_shrunk`) is called alone, every bound it uses multiplied by
//! a factor `s < 1` (the x4 first pass twice: its class bounds alone,
//! `x4-class`, and its roots' bound alone, `x4-roots`), on the cases of
//! `fixtures/bounds/stages.jsonl`. A seeded hill-climb found them by
//! maximising the largest `s` at which the stage answers wrong (its
//! *critical factor*), from seeds whose exact root lies next to an f32
//! rounding midpoint: planes and linear quadrics whose root is a midpoint
//! plus a tiny offset, spheres crossed along an axis whose near root `t =
//! x − √(R² − ρ²)` is a midpoint moved by about `ρ²/2R`, and spheres
//! grazed from just outside whose nearly double root lies next to a
//! midpoint while the double-word stage's sum for `c` rounds in its low
//! word ([`sphere_grazing_seeds`]), and spheres entered from just outside
//! whose near root lies next to a midpoint while the f64 sum for `c`
//! rounds ([`sphere_near_surface_seeds`]); exact sphere tangents whose
//! `Δ̂` rounds far from 0 ([`sphere_tangent_seeds`]); and, for the
//! compensated stage, lines that just miss a sphere with every rounding
//! of `Δ̂` pushing it up across 0
//! ([`bounds_search::sphere_rounding_up_seeds`]); for the quadric's
//! double-word stage, double planes opened by a tiny constant, whose
//! leading words of `Δ/4` each round by a full half ulp
//! ([`bounds_search::quadric_rounding_seeds`]); for the quadric's x4
//! first pass, the cases `bounds.rs` commits for the filter too
//! (`fixtures/bounds/quadric.jsonl`), and for its roots, lines whose `α̂`
//! cancels after every rounding of its sum went one way
//! ([`quadric_cancelling_seeds`]); for the quadric's tight stage, lines
//! from just off a quadric's surface whose `γ̂` cancels after every
//! rounding of its sums went one way ([`quadric_near_surface_seeds`]).
//! The stages with arithmetic proven exact (`tracked`, `grid_exact`) have
//! no bound to shrink, and the quadric's perfect-square stage
//! (`quadric::square`) none that decides: its error stays within the
//! certificate's own margin, which is not shrunk, so no factor makes it
//! wrong ([`the_square_stage_is_right_however_shrunk`], on double planes
//! whose roots lie within `8u` of a midpoint,
//! [`double_plane_midpoint_seeds`]).
//!
//! Each committed case is right at the factor 1, and for each stage some
//! case is wrong at the factor of [`CAUGHT_AT`]: a constant of that stage
//! cut to that fraction is caught here. Each stage also has the same
//! critical factor on its cases scaled by powers of two
//! ([`every_stage_decides_alike_on_scaled_cases`]): the bounds are
//! homogeneous, so a term of the wrong degree is caught too. Regenerate the cases (about two
//! minutes with `--release`) with
//!
//! ```text
//! RAYORACLE_STAGE_SEARCH=400000 cargo test --release --test all stage_bounds -- --nocapture
//! ```
//!
//! which climbs on from the committed cases and writes the best eight per
//! stage. Without the variable the test checks the committed cases and
//! runs a short search that must climb.
#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]

use crate::bounds_search::{self, Answer, answer, exact, fields, mant, to_line};
use glam::Vec3;
use rand::rngs::SmallRng;
use rand::{Rng, SeedableRng};
use rayoracle::case::{Case, parse_line};
use rayoracle::num::certify::U;
use rayoracle::num::dd::{Acc, two_prod, two_sum};
use rayoracle::plane::Plane;
use rayoracle::quadric::Quadric;
use rayoracle::sphere::Sphere;
use rayoracle::{Ray, plane, quadric, sphere};

/// A stage that certifies with a bound, called alone with every bound it
/// uses multiplied by `s`: `None` where it leaves the case undecided.
struct Staged {
    kind: &'static str,
    name: &'static str,
    run: fn(&Case, f64) -> Option<Answer>,
}

fn w(v: Vec3) -> [f64; 3] {
    v.to_array().map(f64::from)
}

fn plane_first(c: &Case, s: f64) -> Option<Answer> {
    let Case::Plane(r, p) = c else { return None };
    let (o, d, a, n) = (w(r.origin), w(r.dir), w(p.point), w(p.normal));
    let f = plane::stages::filter_relative(o, d, a, n, s);
    let certified = rayoracle::num::certify::certify_relative(f.t, f.r);
    (f.hit && certified).then(|| answer(&plane::PlaneHit::Hit(f.t as f32)))
}

fn plane_second(c: &Case, s: f64) -> Option<Answer> {
    let Case::Plane(r, p) = c else { return None };
    let (o, d, a, n) = (w(r.origin), w(r.dir), w(p.point), w(p.normal));
    let f = plane::stages::filter_compensated(o, d, a, n, s);
    let certified = rayoracle::num::certify::certify_relative(f.relative.t, f.relative.r);
    if f.relative.hit && certified {
        Some(answer(&plane::PlaneHit::Hit(f.relative.t as f32)))
    } else {
        f.parallel.then(|| answer(&plane::PlaneHit::Parallel))
    }
}

fn plane_tight(c: &Case, s: f64) -> Option<Answer> {
    let Case::Plane(r, p) = c else { return None };
    let (o, d, a, n) = (w(r.origin), w(r.dir), w(p.point), w(p.normal));
    plane::stages::tight(o, d, a, n, s).map(|h| answer(&h))
}

fn sphere_tight(c: &Case, s: f64) -> Option<Answer> {
    let Case::Sphere(r, sp) = c else { return None };
    let (o, d, m) = (w(r.origin), w(r.dir), w(sp.center));
    sphere::stages::tight(o, d, m, f64::from(sp.radius), s).map(|h| answer(&h))
}

fn sphere_compensated(c: &Case, s: f64) -> Option<Answer> {
    let Case::Sphere(r, sp) = c else { return None };
    let (o, d, m) = (w(r.origin), w(r.dir), w(sp.center));
    sphere::stages::compensated(o, d, m, f64::from(sp.radius), s).map(|h| answer(&h))
}

fn sphere_double_word(c: &Case, s: f64) -> Option<Answer> {
    let Case::Sphere(r, sp) = c else { return None };
    let (o, d, m) = (w(r.origin), w(r.dir), w(sp.center));
    sphere::stages::double_word(o, d, m, f64::from(sp.radius), s).map(|h| answer(&h))
}

fn sphere_words(c: &Case, s: f64) -> Option<Answer> {
    let Case::Sphere(r, sp) = c else { return None };
    let (o, d, m) = (w(r.origin), w(r.dir), w(sp.center));
    sphere::words::words(o, d, m, f64::from(sp.radius), s).map(|h| answer(&h))
}

fn quadric_double_word(c: &Case, s: f64) -> Option<Answer> {
    let Case::Quadric(r, q) = c else { return None };
    let k = q.coeffs.map(f64::from);
    quadric::stages::double_word(&k, w(r.origin), w(r.dir), s).map(|h| answer(&h))
}

fn quadric_tight(c: &Case, s: f64) -> Option<Answer> {
    let Case::Quadric(r, q) = c else { return None };
    let k = q.coeffs.map(f64::from);
    quadric::stages::tight(&k, w(r.origin), w(r.dir), s).map(|h| answer(&h))
}

fn quadric_words(c: &Case, s: f64) -> Option<Answer> {
    let Case::Quadric(r, q) = c else { return None };
    let k = q.coeffs.map(f64::from);
    quadric::stages::words(&k, w(r.origin), w(r.dir), s).map(|h| answer(&h))
}

fn quadric_square(c: &Case, s: f64) -> Option<Answer> {
    let Case::Quadric(r, q) = c else { return None };
    let k = q.coeffs.map(f64::from);
    quadric::square::intersect(&k, w(r.origin), w(r.dir), s).map(|h| answer(&h))
}

fn quadric_x4_class(c: &Case, s: f64) -> Option<Answer> {
    let Case::Quadric(r, q) = c else { return None };
    quadric::x4::first_pass_shrunk(r, q, s, 1.0).map(|h| answer(&h))
}

fn quadric_x4_roots(c: &Case, s: f64) -> Option<Answer> {
    let Case::Quadric(r, q) = c else { return None };
    quadric::x4::first_pass_shrunk(r, q, 1.0, s).map(|h| answer(&h))
}

const STAGES: [Staged; 12] = [
    Staged {
        kind: "plane",
        name: "first",
        run: plane_first,
    },
    Staged {
        kind: "plane",
        name: "second",
        run: plane_second,
    },
    Staged {
        kind: "plane",
        name: "tight",
        run: plane_tight,
    },
    Staged {
        kind: "sphere",
        name: "tight",
        run: sphere_tight,
    },
    Staged {
        kind: "sphere",
        name: "compensated",
        run: sphere_compensated,
    },
    Staged {
        kind: "sphere",
        name: "double-word",
        run: sphere_double_word,
    },
    Staged {
        kind: "sphere",
        name: "words",
        run: sphere_words,
    },
    Staged {
        kind: "quadric",
        name: "double-word",
        run: quadric_double_word,
    },
    Staged {
        kind: "quadric",
        name: "x4-class",
        run: quadric_x4_class,
    },
    Staged {
        kind: "quadric",
        name: "x4-roots",
        run: quadric_x4_roots,
    },
    Staged {
        kind: "quadric",
        name: "tight",
        run: quadric_tight,
    },
    Staged {
        kind: "quadric",
        name: "words",
        run: quadric_words,
    },
];

/// The quadric's perfect-square stage (`quadric::square`), which no
/// factor makes wrong (see [`the_square_stage_is_right_however_shrunk`]).
const SQUARE: Staged = Staged {
    kind: "quadric",
    name: "square",
    run: quadric_square,
};

/// The factor at which the committed cases must show each stage wrong:
/// the best factor the search reached (run with `--nocapture` to see
/// it), rounded down to a power of two. A stage is wrong only where its
/// actual error exceeds the `2⁻⁵¹|t|` that
/// [`certify`](rayoracle::num::certify::certify) adds for its own
/// roundings, so only where the stage's arithmetic cancels; the plane's
/// double-word stage, whose sums are exact or within a few `u`, is never
/// wrong that way, and is not listed. Every stage applies `s` once to each
/// bound of its derivation, where the bound decides (a double-word
/// stage's sums keep their bounds unshrunk until a class or a root is
/// decided from them), so a stage's factor is that of each of its
/// constants. The plane's passes and tight stage are caught at a quarter
/// or better by built cases (`bounds_search::plane_rounding_seeds`), and
/// so is the sphere's compensated stage, whose class is the filter's
/// (`bounds_search::sphere_rounding_up_seeds`); the sphere's double-word
/// stage, whose sums are bounded by their actual rounding errors, by the
/// grazing cases ([`sphere_grazing_seeds`]), and the quadric's
/// double-word stage by double planes built so that every leading word of
/// its `Δ/4` rounds by a full half ulp the same way
/// (`bounds_search::quadric_rounding_seeds`); the sphere's tight stage by
/// searched cases, its `E_c` that of the filter (see `docs/accuracy.md`).
/// The quadric's x4 first pass (`quadric::lanes`), its class bounds
/// alone, by searched double planes opened by a tiny constant, whose
/// class it takes on the wrong side of 0 up to about 2^-1.8 (its `E_Δ` is
/// twice the first-order proof and its sums are shorter than the
/// filter's, so fewer roundings add up, and it took a climb of several
/// million steps to pass a quarter); its roots' bound alone at a
/// quarter, by lines whose `α̂` cancels after every rounding of its sum
/// went one way ([`quadric_cancelling_seeds`]): the roots are off by
/// about 0.29 of the relative part `w = E_α/|α̂|` that leads their bound.
///
/// The sphere's words stage (`sphere::words`) at a quarter, by searched
/// far tiny spheres (`R ≈ 8` at `2·10⁶`), climbed from the generic
/// sphere seeds: its bounds are running bounds, `u` times the computed
/// results of its roundings, which a rounding near half an ulp of a value
/// just above a power of two all but reaches. The best cases go wrong up
/// to a factor of a half: there the error of `Δ̂` is its whole bound, and
/// the sign test asks `|Δ̂| > 2E`.
///
/// The quadric's words stage (`quadric::stages::words`) at a quarter,
/// by searched cases on which, as on the double-word stage's double
/// planes, the sign test of `Δ/4` from the leading words
/// (`quadric::stages::disc_near`, `|Δ̂| > 2E`) decides: with that test
/// alone left unshrunk, neither stage is wrong at any factor. Its
/// coefficients' bound, `1024u²` times the terms' magnitudes, is caught
/// only with the rest: the errors found on cancelling data reach a few
/// `u²` times them (`quadric::stages` tests).
///
/// The quadric's tight stage at an eighth, by lines from just off a
/// quadric's surface ([`quadric_near_surface_seeds`]), wrong up to about
/// 2^-2.75; a quarter is out of its reach. It decides with the filter's
/// `E_β = 24u m_β` and `E_γ = 20u m_γ`, twice the bounds of sums taken
/// left to right, and a root moves by more than the certificate's
/// `2⁻⁵¹|t|` only where `β` or `γ` cancels, at some addition `A + B`,
/// `|A| ≈ |B|`: the roundings after it are at most `u` of the small
/// result, and those before it at most `u` of each term per rounding on
/// its path. In `γ̂ = fl(fl(Q̂ + L̂) + k₉)` a quadratic term passes through at
/// most 4 roundings before `Q̂ + L̂` (its product and three sums), a
/// linear one through 2, so `γ̂` is off by at most `(4 + 2)/2 · u m_γ =
/// 3u m_γ`, 0.15 of `E_γ` (cancelling at the last sum, or inside `Q̂`,
/// leaves `2.5u m_γ`); in `β̂ = fl(fl(B̂₀ + L̂₀) + B̂₁)` a term passes
/// through at most 5 roundings before the last sum and 4 in `B̂₁`, `4.5u
/// m_β`, 0.19 of `E_β`. With `α ≠ 0`, `β`'s share of the roots' bound is
/// half as large again, through `√Δ`, and the class is taken where `|Δ̂|`
/// exceeds twice its bound. The built lines put `22.4u` or more of those
/// `24u` into `γ̂`, 0.14 of `E_γ`; the committed ones reach 0.149. Their
/// `β` does not cancel, so they catch `E_γ` cut to an eighth, not `E_β`
/// alone.
const CAUGHT_AT: [(&str, f64); 12] = [
    ("bounds/plane/first", 0.5),
    ("bounds/plane/second", 0.25),
    ("bounds/plane/tight", 0.25),
    ("bounds/sphere/tight", 0.25),
    ("bounds/sphere/compensated", 0.25),
    ("bounds/sphere/double-word", 0.25),
    ("bounds/sphere/words", 0.25),
    ("bounds/quadric/double-word", 0.25),
    ("bounds/quadric/x4-class", 0.25),
    ("bounds/quadric/x4-roots", 0.25),
    ("bounds/quadric/tight", 0.125),
    ("bounds/quadric/words", 0.25),
];

impl Staged {
    fn family(&self) -> String {
        format!("bounds/{}/{}", self.kind, self.name)
    }

    /// Whether the stage, its bounds times `2^l`, answers and is wrong.
    fn wrong(&self, c: &Case, e: &Answer, l: f64) -> bool {
        (self.run)(c, l.exp2()).is_some_and(|a| a != *e)
    }

    /// The critical factor's `log₂`, to within `2⁻¹²`: the largest power
    /// of two in `[2⁻⁴⁰, 1]` at which the stage is wrong, then bisection
    /// up to the next; `None` where it is right (or silent) at all of them.
    fn critical_log2(&self, c: &Case) -> Option<f64> {
        let e = exact(c)?;
        let first = (0..=40)
            .map(|k| -f64::from(k))
            .find(|&l| self.wrong(c, &e, l))?;
        if first == 0.0 {
            return Some(0.0);
        }
        let (mut lo, mut hi) = (first, first + 1.0);
        while hi - lo > 1.0 / 4096.0 {
            let mid = 0.5 * (lo + hi);
            if self.wrong(c, &e, mid) {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        Some(lo)
    }
}

/// Planes whose `(a − o)·n = L + sm − L` rounds once, in `fl(L + sm)`,
/// by up to `2⁻²³`, then cancels to `sm`, and `d·n = k ∈ [1, 2)`: the
/// root `sm/k` is near 10, where f32 rounding midpoints are `2⁻²⁰` apart,
/// so one seed in thirty or so has its computed root across one from the
/// exact root. (With `k` a power of two the midpoints would lie on the
/// grid `fl(L + sm)` rounds to, and no rounding would cross one.)
fn plane_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    (0..n)
        .map(|_| {
            let (l, s, m) = (mant(rng, 30), mant(rng, 2), mant(rng, 1));
            let k = mant(rng, 0);
            let ray = Ray::new(Vec3::ZERO, Vec3::new(k, 0.0, 0.0));
            Case::Plane(ray, Plane::new(Vec3::new(l, s, -l), Vec3::new(1.0, m, 1.0)))
        })
        .collect()
}

/// Planes for the second pass: [`bounds_search::plane_first_seeds`], and the same
/// numerators over `d = (1, −1, k·2⁻ʲ)`, so that `d·n = k − k + k·2⁻ʲ`
/// cancels by `2ʲ⁺¹` (`j` from 10 to 40), past the first pass, and the
/// root, scaled by `2ʲ`, is still a midpoint moved by `ε·2ʲ`.
fn plane_second_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    let mut out = bounds_search::plane_first_seeds(rng, n);
    for c in bounds_search::plane_first_seeds(rng, n) {
        let Case::Plane(r, p) = c else { continue };
        let k = p.normal.x * 2f32.powi(-rng.random_range(10..41));
        out.push(Case::Plane(Ray::new(r.origin, Vec3::new(1.0, -1.0, k)), p));
    }
    out
}

/// Spheres crossed along `−x` from `(x₀, y, z)` whose near root `x₀ −
/// √(R² − y² − z²)` is `6 − 2⁻²²`, an f32 rounding midpoint, moved by
/// about `(y² + z²)/2R` (relatively `2⁻⁴⁶` to `2⁻⁶⁰`), all scaled by a
/// power of two and shifted along `x` by an integer.
fn sphere_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    (0..n)
        .map(|_| {
            let k = 2f32.powi(rng.random_range(-6..6));
            let shift = rng.random_range(-64..64) as f32;
            let ey = rng.random_range(-27..-22);
            let y = mant(rng, ey);
            let ez = rng.random_range(-40..-26);
            let z = if rng.random() { 0.0 } else { mant(rng, ez) };
            let r = 2.0 + 2f32.powi(-22);
            let o = Vec3::new(8.0 * k + shift, y * k, z * k);
            let d = Vec3::new(-2f32.powi(rng.random_range(-3..3)), 0.0, 0.0);
            Case::Sphere(
                Ray::new(o, d),
                Sphere::new(Vec3::new(shift, 0.0, 0.0), r * k),
            )
        })
        .collect()
}

/// Spheres grazed from just outside, for the roots of the double-word
/// stage: `f = o − C = (y, R + η, z)` along `d = (d₀, 0, 0)`, so that `a
/// = d₀²`, `b = yd₀`, `c = y² + 2Rη + η² + z²` and `Δ = −a(2Rη + η² +
/// z²)`, set by the tiny `η < 0` (`f₁ = η + R` is two words). The stage
/// sums `c` in two words from `y²` (`y ≈ 2⁻¹⁵R`) and `R²`, whose f64 sum
/// rounds by up to half an ulp of `R²`: that error leads the low word,
/// which then rounds `2Rη` and `z²` (`z ≈ 2⁻⁵³R`, both a few of its ulps)
/// by up to `u` of itself each. So `Δ` is off by `ε`, up to about `2u`
/// of `a` times the low word's terms, whose bound (`Acc::finish`'s, the
/// roundings themselves) the stage shrinks once, where it decides; and
/// the roots `−y/d₀ ± √Δ/a`, nearly a double root, move
/// by `(√(Δ + ε) − √Δ)/a`, about `2⁻³⁸` of themselves, far more than the
/// roundings of the roots themselves. `d₀` is drawn until `−y/d₀` lies
/// within `τ` of an f32 rounding midpoint, `aτ` one to four times `√ε`
/// for the `ε` of one such rounding at its largest, and `η` puts an exact
/// root just inside the midpoint (for `ε > 0`, which moves the computed
/// roots outward) and, in a second case, just outside it (for `ε < 0`).
fn sphere_grazing_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    gather(rng, n, sphere_grazing)
}

/// The first `n` cases of as many draws of `one` as that takes.
fn gather(rng: &mut SmallRng, n: usize, one: fn(&mut SmallRng) -> Vec<Case>) -> Vec<Case> {
    let mut out = Vec::new();
    while out.len() < n {
        out.extend(one(rng));
    }
    out.truncate(n);
    out
}

/// One pair of [`sphere_grazing_seeds`], or none where no `d₀` was found.
fn sphere_grazing(rng: &mut SmallRng) -> Vec<Case> {
    let binade = |x: f64| 2f64.powi(((x.to_bits() >> 52) & 0x7ff) as i32 - 1023);
    let (er, ey) = (rng.random_range(-3..4), rng.random_range(-18..-11));
    let r = mant(rng, er);
    let y = mant(rng, ey) * r;
    let z = mant(rng, -53) * r;
    let (r64, y64, z64) = (f64::from(r), f64::from(y), f64::from(z));
    // ε for one rounding of half an ulp of half the largest leading term.
    let eps1 = binade(r64 * r64) * f64::EPSILON * f64::EPSILON / 8.0;
    for _ in 0..1 << 16 {
        let ed = rng.random_range(-2..3);
        let d0 = mant(rng, ed);
        let a = f64::from(d0) * f64::from(d0);
        let q = y64 / f64::from(d0);
        let half = binade(q) * 2f64.powi(-24);
        let mid = (q / (2.0 * half)).floor() * 2.0 * half + half;
        let tau = (q - mid).abs();
        let x = a * a * tau * tau / (a * eps1);
        if !(1.0..16.0).contains(&x) {
            continue;
        }
        return [1.0 - 2f64.powi(-16), 1.0 + 2f64.powi(-16)]
            .map(|gamma| {
                // −2Rη − η² − z² = Δ/a = aτ²γ: an exact root at τ√γ from −y/d₀.
                let eta = -((a * tau * tau * gamma + z64 * z64) / (2.0 * r64)) as f32;
                let ray = Ray::new(Vec3::new(y, eta, z), Vec3::new(d0, 0.0, 0.0));
                Case::Sphere(ray, Sphere::new(Vec3::new(0.0, -r, 0.0), r))
            })
            .to_vec();
    }
    Vec::new()
}

/// Spheres entered from just outside, for the near root `c/q` of the
/// tight stage, which takes `c = f·f − R²` from the filter with its bound
/// `12u(f·f + R²)`: `f₀ ≈ R cos θ` and `f₁` are each `o − C` of an f32
/// `C` and an `o` some 2⁻³⁵ of it, so that `f̂ = fl(o − C)` rounds, and
/// `f̂₀²`, `f̂₁²` and their sums round (`f₂ ≈ 2⁻²⁶R` rounds the second
/// sum), while `f₁` is solved for `c ≈ 2⁻²⁰R²`: the six roundings, near
/// half an ulp each and of one sign in the best of 64 such draws, put `ĉ`
/// off by up to about `5u·f·f`, far more than `u` of `c`, and the root by
/// as much relatively. The direction is drawn towards the sphere with a
/// small `d₀` (about `2⁻¹²`), whose ulps move `b`, and so the root, by
/// about `2⁻³⁶` of it: a bisection on `d₀` finds where the exact root
/// crosses an f32 rounding midpoint, and both cases beside it are kept.
fn sphere_near_surface_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    gather(rng, n, sphere_near_surface)
}

/// One draw of [`sphere_near_surface_seeds`]: `o`, `C`, `R` and the
/// error of the tight stage's `ĉ` as a fraction of its bound, or `None`.
fn near_surface_draw(rng: &mut SmallRng) -> Option<(f64, [f32; 3], [f32; 3], f32)> {
    let sign = |rng: &mut SmallRng| if rng.random() { 1.0 } else { -1.0 };
    let e = rng.random_range(-2..3);
    let r = mant(rng, e);
    let r64 = f64::from(r);
    let f0 = r64 * rng.random_range(0.3f64..1.2).cos() * sign(rng);
    let a0 = f0 as f32;
    let e0 = e - rng.random_range(32..40);
    let o0 = ((f0 - f64::from(a0)) + f64::from(mant(rng, e0)) * sign(rng)) as f32;
    let f2 = mant(rng, e - 26) * rng.random_range(0.5f32..1.0);
    let ct = f64::from(mant(rng, 2 * e - 20)) * sign(rng);
    let f0 = f64::from(o0) + f64::from(a0);
    let rest = r64 * r64 + ct - f0 * f0 - f64::from(f2) * f64::from(f2);
    if rest <= 0.0 {
        return None;
    }
    let f1 = rest.sqrt() * sign(rng);
    let a1 = f1 as f32;
    let o1 = (f1 - f64::from(a1)) as f32;
    if o1 == 0.0 {
        return None;
    }
    let (o, c) = ([o0, o1, f2], [-a0, -a1, 0.0]);
    // ĉ as the tight stage computes it, and the exact c − ĉ.
    let f = [0, 1, 2].map(|i| f64::from(o[i]) - f64::from(c[i]));
    let ff = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
    let (chat, mc) = (ff - r64 * r64, ff + r64 * r64);
    let mut terms = vec![-chat];
    for i in 0..3 {
        let (h, l) = two_sum(f64::from(o[i]), -f64::from(c[i]));
        for (x, y) in [(h, h), (h + h, l), (l, l)] {
            let (p, q) = two_prod(x, y);
            terms.extend([p, q]);
        }
    }
    let (p, q) = two_prod(r64, r64);
    terms.extend([-p, -q]);
    Some((exact_sum(&terms) / (12.0 * U * mc), o, c, r))
}

/// The sum of `xs`, kept exact in an expansion (Shewchuk's
/// grow-expansion, by TwoSum) and then rounded, to within a few ulps.
fn exact_sum(xs: &[f64]) -> f64 {
    let mut e: Vec<f64> = Vec::new();
    for &x in xs {
        let mut q = x;
        let mut next = Vec::with_capacity(e.len() + 1);
        for &c in &e {
            let (s, err) = two_sum(q, c);
            if err != 0.0 {
                next.push(err);
            }
            q = s;
        }
        next.push(q);
        e = next;
    }
    e.iter().sum()
}

/// One pair of [`sphere_near_surface_seeds`], or none.
fn sphere_near_surface(rng: &mut SmallRng) -> Vec<Case> {
    let best = (0..64)
        .filter_map(|_| near_surface_draw(rng))
        .max_by(|x, y| x.0.abs().total_cmp(&y.0.abs()));
    let Some((_, o, c, r)) = best else {
        return Vec::new();
    };
    let f: Vec<f64> = (0..3).map(|i| f64::from(o[i]) - f64::from(c[i])).collect();
    let mut v = [0; 3].map(|_| rng.random_range(-1.0f64..1.0));
    if v[0] * f[0] + v[1] * f[1] + v[2] * f[2] > 0.0 {
        v = v.map(|x| -x);
    }
    let d0 = (v[0] * 2f64.powi(-12)) as f32;
    if d0 == 0.0 {
        return Vec::new();
    }
    let case = |bits: u32| {
        let d = Vec3::new(f32::from_bits(bits), v[1] as f32, v[2] as f32);
        Case::Sphere(Ray::new(Vec3::from(o), d), Sphere::new(Vec3::from(c), r))
    };
    crossing(
        case,
        d0.to_bits() - (1 << 14),
        d0.to_bits() + (1 << 14),
        false,
    )
}

/// The two cases `case(b)`, `case(b + 1)` between `lo` and `hi` where
/// the exact root nearer the origin (or, `far`, the other) as an f32
/// changes, found by bisection; none where it is the same at both ends.
fn crossing(case: impl Fn(u32) -> Case, mut lo: u32, mut hi: u32, far: bool) -> Vec<Case> {
    let root = |bits: u32| match exact(&case(bits)) {
        Some(("two", t)) => {
            let nearer = t[0] & 0x7fff_ffff < t[1] & 0x7fff_ffff;
            Some(if nearer != far { t[0] } else { t[1] })
        }
        _ => None,
    };
    let Some(at_lo) = root(lo) else {
        return Vec::new();
    };
    if root(hi) == Some(at_lo) {
        return Vec::new();
    }
    while hi - lo > 1 {
        let mid = lo + (hi - lo) / 2;
        if root(mid) == Some(at_lo) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    vec![case(lo), case(hi)]
}

/// Exact tangents for the class the compensated stage takes from the
/// filter: the best of 64 [`bounds_search::sphere_tangent`]s by `Δ̂/E_Δ`
/// as the filter computes them. There `Δ = 0`, and `Δ̂` is the sum of
/// the roundings of `b`'s products and sum, `b̂²`, `f̂ᵢ²` and the sums of
/// `c`, `a` and `âĉ`, up to about `14u·b²` when all have one sign, against
/// `E_Δ ≈ 40u·b²` (the sphere is tiny beside `|f|`, so `a·m_c ≈ b²`): the
/// stage answers two roots wrongly where the factor is below `Δ̂/E_Δ`.
fn sphere_tangent_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    let score = |c: &Case| {
        let Case::Sphere(ray, sp) = c else {
            return f64::NEG_INFINITY;
        };
        let (o, d, m, r) = (
            w(ray.origin),
            w(ray.dir),
            w(sp.center),
            f64::from(sp.radius),
        );
        let f = [o[0] - m[0], o[1] - m[1], o[2] - m[2]];
        let a = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
        let fd = [f[0] * d[0], f[1] * d[1], f[2] * d[2]];
        let b = fd[0] + fd[1] + fd[2];
        let mb = fd[0].abs() + fd[1].abs() + fd[2].abs();
        let ff = f[0] * f[0] + f[1] * f[1] + f[2] * f[2];
        let disc = b * b - a * (ff - r * r);
        disc / (20.0 * U * (mb * mb + a * (ff + r * r)))
    };
    (0..n)
        .filter_map(|_| {
            (0..64)
                .map(|_| bounds_search::sphere_tangent(rng))
                .max_by(|x, y| score(x).total_cmp(&score(y)))
        })
        .collect()
}

/// Linear quadrics `x + k₇y + k₉ = 0` crossed along `x` from `(0, y₀,
/// 0)`: the root `−(k₇y₀ + k₉)` is an f32 rounding midpoint plus a tiny
/// offset; and spheres as quadrics, as in [`sphere_seeds`].
fn quadric_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    (0..n)
        .map(|i| {
            if i % 2 == 0 {
                let (x, half_ulp, eps, sign) = bounds_search::near_midpoint(rng, 30..56);
                let k7 = half_ulp + sign * eps;
                let k = [0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, k7, 0.0, -x];
                let ray = Ray::new(Vec3::new(0.0, -1.0, 0.0), Vec3::X);
                Case::Quadric(ray, Quadric::new(k))
            } else {
                let ey = rng.random_range(-27..-22);
                let y = mant(rng, ey);
                let rr = 4.0 + 2f32.powi(-20);
                let k = [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -rr];
                let ray = Ray::new(Vec3::new(8.0, y, 0.0), -Vec3::X);
                Case::Quadric(ray, Quadric::new(k))
            }
        })
        .collect()
}

/// Lines from the origin (`o = 0`) for the roots of the quadric's x4
/// first pass, whose bound is mostly `w|t| = E_α|t|/|α̂|` where `α̂`
/// cancels: `α = ((t₀ + t₁) + (t₂ + t₃)) + (t₄ + t₅)`, summed pairwise as
/// the pass sums it, each `tᵢ = kᵢ·dⱼ·dₖ` rounding up by at least 0.9 of
/// a half ulp (of draws of `kᵢ` one ulp apart, the first that does):
/// `t₀` and `t₂` just above 2 and `t₄` just beyond −4, whose roundings
/// carry `u m_α` (`m_α ≈ 8`), and `t₁`, `t₃`, `t₅` about `2⁻¹⁰`, drawn so
/// that `t₀ + t₁`, `t₂ + t₃` (just above 2) and `t₄ + t₅` (just beyond
/// −4) round up by 0.9 of a half ulp or more, `2u`, `2u` and `4u` at
/// most, and their sum `X` of the first two rounds up by a tie, `4u`
/// (a tie rounds to even, so only one level of ties adds up). The last
/// sum, `X + Y`, is exact and cancels to `2⁻¹⁶ … 2⁻¹²`. Then `α̂` is high
/// by up to `20u = 2.5u m_α`, and at least about `18.4u`, against `E_α =
/// 8u m_α`: the computed roots, `n̂/2α̂`, are off by about `0.29w` of
/// themselves. With `o = 0`, `β = k₆d₀ + k₇d₁` and `γ = k₉`: the root
/// `−β/α`, about `2¹²`, carries that error, and the other, `−γ/β` of
/// about `2⁻²`, is far from cancelling (`t₂/t₁ ≈ 2⁻¹⁴`), so that `E_Δ`'s
/// share of the bound is small. A bisection on `k₇ ≈ 2⁻¹⁸`, which moves
/// `β` finely, finds where the exact root crosses an f32 rounding
/// midpoint, and both cases beside it are kept: in one, the computed
/// root is across it.
fn quadric_cancelling_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    gather(rng, n, quadric_cancelling)
}

/// One pair of [`quadric_cancelling_seeds`], or none.
fn quadric_cancelling(rng: &mut SmallRng) -> Vec<Case> {
    let d = [0; 3].map(|_| 1.0 + rng.random_range(1..1u32 << 12) as f32 * f32::EPSILON);
    let Some(([k0, k1, k2, k3], x)) = four_terms_up(d) else {
        return Vec::new();
    };
    let [d0, d1, d2] = d.map(f64::from);
    let small = 2f64.powi(-10);
    let Some((k4, t4)) = product_up(small - x, d0, d2, &|_| true) else {
        return Vec::new();
    };
    // t₅ from 2⁻¹² short of −X − t₄ on, while X + Y stays above 2⁻¹⁶.
    let fits = |h: f64| {
        rounds_up(t4, h, 0.9) && (2f64.powi(-16)..2f64.powi(-12)).contains(&(x + (t4 + h)))
    };
    let Some((k5, t5)) = product_up(2f64.powi(-12) - x - t4, d1, d2, &fits) else {
        return Vec::new();
    };
    let alpha = x + (t4 + t5);
    // β = k₆d₀ + k₇d₁ with −β/α about 2¹², γ = k₉ with −γ/β about 2⁻².
    let t = rng.random_range(1.0..2.0) * 2f64.powi(12);
    let k6 = (-alpha * t / d0) as f32;
    let k9 = k6 * rng.random_range(0.25f32..0.5);
    let case = |bits: u32| {
        let k7 = f32::from_bits(bits);
        let k = [k0, k1, k2, k3, k4, k5, k6, k7, 0.0, k9];
        Case::Quadric(Ray::new(Vec3::ZERO, Vec3::from(d)), Quadric::new(k))
    };
    let (lo, hi) = (2f32.powi(-18).to_bits(), 2f32.powi(-17).to_bits());
    crossing(case, lo, hi, true)
}

/// Half an ulp of `x`'s binade, `u·2^⌊log₂|x|⌋`: the largest rounding
/// error of an f64 result there.
fn half_ulp(x: f64) -> f64 {
    f64::from_bits(x.abs().to_bits() & 0x7ff0_0000_0000_0000) * U
}

/// Whether `fl(a + b)` rounds up, above the exact sum, by `f` of half an
/// ulp or more (`f = 1`: a tie rounding up).
fn rounds_up(a: f64, b: f64, f: f64) -> bool {
    let (s, r) = two_sum(a, b);
    -r >= f * half_ulp(s)
}

/// `fl(fl(k·x)·y)` for an f32 `k`, its magnitude in `[|v|, |v|(1 +
/// 2⁻⁸))`, rounding up by 0.9 of a half ulp or more, with `fits`: the
/// first such `k` stepping from `v/(xy)` away from 0, and the product.
fn product_up(v: f64, x: f64, y: f64, fits: &dyn Fn(f64) -> bool) -> Option<(f32, f64)> {
    let start = ((v / (x * y)) as f32).to_bits();
    (0..1u32 << 15).find_map(|step| {
        let k = f32::from_bits(start + step);
        let (h, e) = two_prod(f64::from(k) * x, y);
        let near = h.abs() >= v.abs() && h.abs() < v.abs() * (1.0 + 2f64.powi(-8));
        (near && -e >= 0.9 * half_ulp(h) && fits(h)).then_some((k, h))
    })
}

/// The product `k·x` of an f32 `k` and `x`, exact in f64, that `fits`: the
/// first such `k` stepping from `v/x` away from 0, and the product.
fn exact_product(v: f64, x: f64, fits: &dyn Fn(f64) -> bool) -> Option<(f32, f64)> {
    let start = ((v / x) as f32).to_bits();
    (0..1u32 << 15).find_map(|step| {
        let k = f32::from_bits(start + step);
        let h = f64::from(k) * x;
        fits(h).then_some((k, h))
    })
}

/// The first four quadratic terms on the inputs `v`, `tᵢ = kᵢ·vⱼ·vₖ`
/// (`k₀v₀²`, `k₁v₁²`, `k₂v₂²`, `k₃v₀v₁`), summed as the kernels'
/// pairwise sums do, `X = (t₀ + t₁) + (t₂ + t₃)`, every rounding up:
/// `t₀` and `t₂` just above 2 and `t₁`, `t₃` about `2⁻¹⁰`, each product
/// rounding up by 0.9 of a half ulp or more (of draws of `kᵢ` one ulp
/// apart, the first that does), `t₀ + t₁` and `t₂ + t₃` (just above 2)
/// by 0.9 of a half ulp or more, `2u` at most, and `X`, just above 4, by
/// a tie, `4u` (a tie rounds to even, so only one level of ties adds
/// up). The four coefficients and `X`, or `None` where no draw fits.
fn four_terms_up(v: [f32; 3]) -> Option<([f32; 4], f64)> {
    let [v0, v1, v2] = v.map(f64::from);
    let small = 2f64.powi(-10);
    let (k0, t0) = product_up(2.0, v0, v0, &|_| true)?;
    let (k1, t1) = product_up(small, v1, v1, &|h| rounds_up(t0, h, 0.9))?;
    let (k2, t2) = product_up(2.0, v2, v2, &|_| true)?;
    let s01 = t0 + t1;
    let fits = |h: f64| rounds_up(t2, h, 0.9) && rounds_up(s01, t2 + h, 1.0);
    let (k3, t3) = product_up(small, v0, v1, &fits)?;
    Some(([k0, k1, k2, k3], s01 + (t2 + t3)))
}

/// Lines from just off a quadric's surface, for the near root `c/q` of
/// the quadric's tight stage, which takes `γ` (the quadric's value at the
/// origin) as the filter sums it, `γ̂ = fl(fl(Q̂ + L̂) + k₉)`, with its
/// bound `E_γ = 20u m_γ`. Here `Q̂`, the quadratic terms `kᵢoⱼoₖ` summed
/// pairwise, and `L̂ = fl(fl(k₆o₀ + k₇o₁) + k₈o₂)` nearly cancel, and
/// every rounding before their difference, exact, goes up. With `o`
/// drawn in `[1, 2)³`, `k₅ = k₉ = 0`:
///
/// * `Q̂ = fl(X + t₄)`, `X` from [`four_terms_up`] on `o` and `t₄ =
///   k₄o₀o₂` just over half an ulp of `X`, so that adding it rounds up
///   by nearly half an ulp: `Q̂` is high by up to `16u`, `2u` from each
///   of the products `t₀`, `t₂` and the sums `t₀ + t₁`, `t₂ + t₃` (at
///   least 0.9 of each), `4u` from the tie and `4u` from `t₄`;
/// * `L = k₆o₀ + k₇o₁ + k₈o₂`, each product exact, `k₆o₀` just beyond
///   `−4`, `k₇o₁` about `2⁻¹⁰` and `k₈o₂` about `2⁻²⁰`, drawn so that both
///   sums, just beyond −4, round up by 0.9 of a half ulp or more (`4u` at
///   most each) and `γ = Q + L` is about `2⁻ʲ` (`j` from 16 to 21).
///
/// So `γ̂` is high by about `22.4u` of the `24u` it can be at most, while
/// `m_γ ≈ 8` makes `E_γ ≈ 160u`: the near root `γ̂/q̂` is off by about
/// 0.14 of the share `E_γ/|γ|` that leads its bound (the rest, from `β`
/// and the roundings of the roots, is under `2⁻¹⁷` of it). The direction
/// `d = (d₀, d₁, d₂)`, `d₀` and `|d₂|` in `[1, 2)`, gives `β ≈ 4d₂/o₂`
/// (in `∂β/∂d₀ = 2k₀o₀ + k₆ + …` the quadratic and linear terms cancel)
/// and `α` from 1 to 16, exact; `d₁ ∈ [2⁻¹⁰, 2⁻⁹)`, with `∂β/∂d₁` from
/// `2⁻⁹` to `2⁻⁸`, moves the root by about `2⁻⁴⁴` of it an ulp: a bisection on
/// `d₁` finds where the exact root crosses an f32 rounding midpoint, and
/// both cases beside it are kept.
fn quadric_near_surface_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    gather(rng, n, |rng| quadric_near_surface(rng).unwrap_or_default())
}

/// One pair of [`quadric_near_surface_seeds`], or none.
fn quadric_near_surface(rng: &mut SmallRng) -> Option<Vec<Case>> {
    let o = [0; 3].map(|_| mant(rng, 0));
    let ([k0, k1, k2, k3], x) = four_terms_up(o)?;
    let [o0, o1, o2] = o.map(f64::from);
    let over_half = half_ulp(x) * (1.0 + 2f64.powi(-9));
    let (k4, t4) = product_up(over_half, o0, o2, &|h| rounds_up(x, h, 0.9))?;
    // L̂ = γ − Q̂, its two sums rounding up.
    let l = 2f64.powi(-rng.random_range(16..22)) - (x + t4);
    let (k6, l0) = exact_product(l - 2f64.powi(-10), o0, &|_| true)?;
    let (k7, l1) = exact_product(l - 2f64.powi(-20) - l0, o1, &|h| rounds_up(l0, h, 0.9))?;
    let (k8, _) = exact_product(l - (l0 + l1), o2, &|h| rounds_up(l0 + l1, h, 0.9))?;
    let k = [k0, k1, k2, k3, k4, 0.0, k6, k7, k8, 0.0];
    let sign = if rng.random() { 1.0 } else { -1.0 };
    let (d0, d2) = (mant(rng, 0), sign * mant(rng, 0));
    let case = |bits: u32| {
        let d = Vec3::new(d0, f32::from_bits(bits), d2);
        Case::Quadric(Ray::new(Vec3::from(o), d), Quadric::new(k))
    };
    let (lo, hi) = (2f32.powi(-10).to_bits(), 2f32.powi(-9).to_bits());
    Some(crossing(case, lo, hi, false))
}

/// Double planes `(n·p − e)² = 0`, `n = (1, n₁, n₂)` with `n₁`, `n₂` and
/// `e` of 12 significant bits (so that every coefficient, `n₁²`,
/// `2n₁n₂`, `e²` and the rest, is an f32), crossed by lines whose root
/// `−b/a` lies within `8u` of an f32 rounding midpoint, for the
/// perfect-square stage: `a = n·d` of a `d` spread over 40 binades needs
/// two words, and `o` is solved for `b = n·o − e = −τa`, `τ` the midpoint
/// moved by up to `8u` of itself, one component at a time (`o₀`, then
/// `o₁` and `o₂` from the residual each leaves, rounded to f32), to
/// within about `2⁻⁷⁰` of `b`, which then needs two words too.
fn double_plane_midpoint_seeds(rng: &mut SmallRng, n: usize) -> Vec<Case> {
    (0..n).map(|_| double_plane_near_midpoint(rng)).collect()
}

/// One of [`double_plane_midpoint_seeds`].
fn double_plane_near_midpoint(rng: &mut SmallRng) -> Case {
    let sign = |rng: &mut SmallRng| if rng.random() { 1.0 } else { -1.0 };
    let twelve = |rng: &mut SmallRng| {
        let e = rng.random_range(-15..-7);
        rng.random_range(2048..4096) as f32 * 2f32.powi(e) * sign(rng)
    };
    let (n1, n2, e) = (twelve(rng), twelve(rng), twelve(rng));
    let k = [
        1.0,
        n1 * n1,
        n2 * n2,
        2.0 * n1,
        2.0 * n2,
        2.0 * n1 * n2,
        -2.0 * e,
        -2.0 * n1 * e,
        -2.0 * n2 * e,
        e * e,
    ];
    let (e1, e2) = (rng.random_range(-30..-10), rng.random_range(-40..-20));
    let d = [mant(rng, 0), mant(rng, e1), mant(rng, e2)].map(|x| x * sign(rng));
    let [n1, n2, e] = [n1, n2, e].map(f64::from);
    let sum = |terms: &[f64]| {
        let mut acc = Acc::new();
        terms.iter().for_each(|&t| acc.add(t));
        acc.finish()
    };
    let a = sum(&[f64::from(d[0]), n1 * f64::from(d[1]), n2 * f64::from(d[2])]);
    let ey = rng.random_range(-4..4);
    let y = mant(rng, ey);
    let mid = f64::from(y) + f64::from(f32::from_bits(y.to_bits() + 1) - y) / 2.0;
    let tau = mid * (1.0 + rng.random_range(-8.0..8.0) * U);
    // b + e = −τa + e, less each component's share as it is fixed.
    let (p, q) = two_prod(tau, a.hi);
    let mut rest = vec![-p, -q, -tau * a.lo, e];
    let o0 = sum(&rest).hi as f32;
    rest.push(-f64::from(o0));
    let o1 = (sum(&rest).hi / n1) as f32;
    rest.push(-n1 * f64::from(o1));
    let o2 = (sum(&rest).hi / n2) as f32;
    let ray = Ray::new(Vec3::new(o0, o1, o2), Vec3::from(d));
    Case::Quadric(ray, Quadric::new(k))
}

/// The committed cases, as (family, case).
fn committed() -> Vec<(String, Case)> {
    let path =
        std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/bounds/stages.jsonl");
    let text = std::fs::read_to_string(&path).unwrap_or_default();
    text.lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| {
            let c = parse_line(l).unwrap_or_else(|e| panic!("{}: {e}: {l}", path.display()));
            (c.family.expect("a family naming the stage"), c.case)
        })
        .collect()
}

/// The seeds of a stage: generated, the stiff catalogue's cases of its
/// kind, and the committed cases of every stage of that kind.
fn seeds(st: &Staged, rng: &mut SmallRng, n: usize) -> Vec<Case> {
    let mut out = match (st.kind, st.name) {
        ("plane", "first") => [
            bounds_search::plane_first_seeds(rng, n),
            bounds_search::plane_rounding_seeds(rng, n),
        ]
        .concat(),
        ("plane", "second") => [
            plane_second_seeds(rng, n),
            bounds_search::plane_rounding_seeds(rng, n),
        ]
        .concat(),
        ("plane", _) => [
            plane_seeds(rng, n),
            bounds_search::plane_seeds(rng, n),
            bounds_search::plane_rounding_seeds(rng, n),
        ]
        .concat(),
        ("sphere", name) => {
            let mut out = [
                sphere_seeds(rng, n),
                bounds_search::sphere_seeds(rng, n),
                sphere_grazing_seeds(rng, n),
                sphere_near_surface_seeds(rng, n),
                sphere_tangent_seeds(rng, n),
            ]
            .concat();
            // Thousands of oracle calls each: for the long search alone
            // (`n / 256` is 0 in the short one).
            if name == "compensated" {
                out.extend(bounds_search::sphere_rounding_up_seeds(rng, n / 256, 4096));
            }
            out
        }
        (_, name) => {
            let mut out = [quadric_seeds(rng, n), bounds_search::quadric_seeds(rng, n)].concat();
            // The kernels' searched cases, on the edge of the filter's
            // class and roots, whose bounds the x4 pass shares or mirrors.
            if name.starts_with("x4") {
                out.extend(crate::bounds::found("quadric"));
            }
            if name == "x4-roots" {
                out.extend(quadric_cancelling_seeds(rng, n / 16));
            }
            if name == "tight" {
                out.extend(quadric_near_surface_seeds(rng, n / 16));
            }
            // Double planes whose double-word `Δ̂` rounds by most of its
            // bound: for the long search alone, as above.
            out.extend(bounds_search::quadric_rounding_seeds(rng, n / 256, 256));
            out
        }
    };
    let cat = rayoracle::report::Catalogue::builtin().expect("the built-in catalogue");
    for f in cat.families.iter().filter(|f| f.name.starts_with(st.kind)) {
        out.extend(f.cases.iter().cloned());
    }
    let kind = format!("bounds/{}/", st.kind);
    out.extend(
        committed()
            .into_iter()
            .filter(|(f, _)| f.starts_with(&kind))
            .map(|(_, c)| c),
    );
    out
}

/// Hill-climbs from `start` for `steps` moves
/// ([`bounds_search::climb_by`]): the best case and its factor.
fn climb(st: &Staged, rng: &mut SmallRng, start: (f64, Case), steps: usize) -> (f64, Case) {
    let mut found = bounds_search::climb_by(rng, start, steps, |c| st.critical_log2(c));
    found.pop().expect("the start at least")
}

/// The search for one stage: seeds scored, the best `starts` climbed for
/// `steps` moves each; the results, best first.
fn search(st: &Staged, seed: u64, pool: usize, starts: usize, steps: usize) -> Vec<(f64, Case)> {
    let mut rng = SmallRng::seed_from_u64(seed);
    let mut scored: Vec<(f64, Case)> = seeds(st, &mut rng, pool)
        .into_iter()
        .filter_map(|c| Some((st.critical_log2(&c)?, c)))
        .collect();
    scored.sort_by(|a, b| b.0.total_cmp(&a.0));
    // A case committed for two stages is one start, not two.
    let mut seen = std::collections::HashSet::new();
    scored.retain(|(_, c)| seen.insert(fields(c).iter().map(|x| x.to_bits()).collect::<Vec<_>>()));
    scored.truncate(starts);
    let mut out: Vec<(f64, Case)> = scored
        .into_iter()
        .map(|s| climb(st, &mut rng, s, steps))
        .collect();
    out.sort_by(|a, b| b.0.total_cmp(&a.0));
    out
}

/// Each committed case: the oracle's answer (or none) from its stage at
/// the factor 1, a wrong one at 0; and for each stage, some case wrong
/// at its factor of [`CAUGHT_AT`].
#[test]
fn each_stage_shrunk_alone_gives_wrong_answers() {
    let lines = committed();
    for st in &STAGES {
        let family = st.family();
        let of: Vec<&Case> = lines
            .iter()
            .filter(|(f, _)| *f == family)
            .map(|(_, c)| c)
            .collect();
        assert!(!of.is_empty(), "{family}: no cases");
        for c in &of {
            let e = exact(c).expect("finite");
            assert!(!st.wrong(c, &e, 0.0), "{family}: wrong at 1: {c:?}");
        }
        let best = of
            .iter()
            .filter_map(|c| st.critical_log2(c))
            .fold(f64::NEG_INFINITY, f64::max);
        println!("{family}: wrong up to the factor 2^{best:.2}");
        let s = CAUGHT_AT
            .iter()
            .find(|(f, _)| *f == family)
            .map(|&(_, s)| s)
            .expect("a factor for every stage");
        let caught = of
            .iter()
            .any(|c| exact(c).is_some_and(|e| st.wrong(c, &e, s.log2())));
        assert!(best >= s.log2(), "{family}: best 2^{best}");
        assert!(caught, "{family}: nothing wrong at {s}");
    }
}

/// A short search reaches a critical factor of at least 2⁻¹² for every
/// stage; with
/// `RAYORACLE_STAGE_SEARCH` set, a long one from the committed cases
/// rewrites them.
#[test]
fn the_stage_search_climbs_and_regenerates_on_request() {
    let budget: Option<usize> = std::env::var("RAYORACLE_STAGE_SEARCH")
        .ok()
        .and_then(|v| v.parse().ok());
    let mut lines = Vec::new();
    for (i, st) in STAGES.iter().enumerate() {
        let (pool, starts, steps) = budget.map_or((128, 1, 100), |n| (4096, 8, n));
        let found = search(st, 0x57a9e + i as u64, pool, starts, steps);
        let best = found.first().map_or(f64::NEG_INFINITY, |f| f.0);
        println!("{}: best 2^{best:.2}", st.family());
        assert!(best >= -12.0, "{}: best 2^{best}", st.family());
        for (_, c) in found.iter().take(8) {
            lines.push(to_line(c, &st.family()));
        }
    }
    if budget.is_some() {
        lines.dedup();
        let path =
            std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/bounds/stages.jsonl");
        std::fs::write(path, lines.join("\n") + "\n").expect("write the cases");
    }
}

/// The stage of `family`.
fn stage(family: &str) -> &'static Staged {
    STAGES
        .iter()
        .find(|s| s.family() == family)
        .unwrap_or_else(|| panic!("no stage {family}"))
}

/// The construction of [`quadric_cancelling_seeds`] works: from a fixed
/// seed, some of its lines make the x4 first pass's roots wrong with
/// their bound alone shrunk to a quarter, with no search at all.
#[test]
fn the_constructed_cancelling_lines_use_most_of_the_bound() {
    let st = stage("bounds/quadric/x4-roots");
    let mut rng = SmallRng::seed_from_u64(0xca9);
    let cases = quadric_cancelling_seeds(&mut rng, 8);
    bounds_search::reaches_a_quarter(&cases, |c| st.critical_log2(c));
}

/// The construction of [`quadric_near_surface_seeds`] works: from a fixed
/// seed, some of its lines make the tight stage's near root wrong with
/// every bound shrunk to an eighth, with no search at all.
#[test]
fn the_constructed_near_surface_lines_use_most_of_the_bound() {
    let st = stage("bounds/quadric/tight");
    let mut rng = SmallRng::seed_from_u64(0x9e5);
    let cases = quadric_near_surface_seeds(&mut rng, 8);
    bounds_search::reaches(&cases, |c| st.critical_log2(c), -3.0);
}

/// The perfect-square stage is right at every factor, 0 included, on
/// double planes whose roots lie within `8u` of an f32 rounding midpoint
/// ([`double_plane_midpoint_seeds`]): its root `fl(−b̂/â)` from the
/// leading words of the exact `a` and `b` is within `3u|t|` of the exact
/// one (each word within `u` of its sum, and the division), inside the
/// `2⁻⁵¹|t|` that [`certify`](rayoracle::num::certify::certify) adds
/// unshrunk, so its own bounds, `|lo|` and the quotient's `4u`, never
/// decide. Some of these lines have `fl(−b̂/â)` across the midpoint from
/// the exact root: there the stage must not answer, at any factor.
#[test]
fn the_square_stage_is_right_however_shrunk() {
    let mut rng = SmallRng::seed_from_u64(0x5a7);
    let cases = double_plane_midpoint_seeds(&mut rng, 256);
    let (mut answered, mut across) = (0, 0);
    for c in &cases {
        let e = exact(c).expect("finite");
        assert_eq!(e.0, "one", "{c:?}");
        assert_eq!(SQUARE.critical_log2(c), None, "{c:?}");
        if let Some(a) = (SQUARE.run)(c, 0.0) {
            assert_eq!(a, e, "{c:?}");
            answered += 1;
        }
        // a and b from the quadric's first row, as the stage takes them.
        let Case::Quadric(r, q) = c else {
            unreachable!()
        };
        let k = q.coeffs.map(f64::from);
        let row = [k[0], 0.5 * k[3], 0.5 * k[4], 0.5 * k[6]];
        let form = |v: [f64; 3], last: f64| {
            let mut acc = Acc::new();
            (0..3).for_each(|j| acc.add(row[j] * v[j]));
            acc.add(last);
            acc.finish().hi
        };
        let leading = (-form(w(r.origin), row[3]) / form(w(r.dir), 0.0)) as f32;
        across += usize::from(leading.to_bits() != e.1[0]);
    }
    println!(
        "{answered} of {} answered at the factor 0, {across} across",
        cases.len()
    );
    assert!(answered * 4 > cases.len(), "answered {answered}");
    assert!(across > 0, "no leading-word root across a midpoint");
}

/// The construction of [`bounds_search::sphere_rounding_up_seeds`] works:
/// from a fixed seed, some of its lines make the compensated stage answer
/// two roots where there are none or one with every bound shrunk to a
/// quarter, with no search at all.
#[test]
fn the_constructed_misses_use_most_of_the_bound() {
    let st = stage("bounds/sphere/compensated");
    let mut rng = SmallRng::seed_from_u64(0x5e1);
    let cases = bounds_search::sphere_rounding_up_seeds(&mut rng, 4, 2048);
    bounds_search::reaches_a_quarter(&cases, |c| st.critical_log2(c));
}

/// `c` scaled by powers of two where every value scales exactly (zero,
/// or normal before and after): the direction times `2^j`, and the
/// quadric's coefficients, or the plane's and sphere's lengths (origin,
/// point or centre, radius) and the plane's normal, times `2^k`. The same
/// line and surface, the roots times `2^{−j}` (and `2^k` for the lengths).
fn scaled(c: &Case, k: i32, j: i32) -> Option<Case> {
    let by = |x: f32, e: i32| {
        let y = x * 2f32.powi(e);
        (x == 0.0 || (x.is_normal() && y.is_normal())).then_some(y)
    };
    let v = |x: Vec3, e: i32| Some(Vec3::new(by(x.x, e)?, by(x.y, e)?, by(x.z, e)?));
    Some(match c {
        Case::Quadric(r, q) => {
            let mut coeffs = q.coeffs;
            for c in &mut coeffs {
                *c = by(*c, k)?;
            }
            Case::Quadric(Ray::new(r.origin, v(r.dir, j)?), Quadric::new(coeffs))
        }
        Case::Plane(r, p) => Case::Plane(
            Ray::new(v(r.origin, k)?, v(r.dir, j)?),
            Plane::new(v(p.point, k)?, v(p.normal, k)?),
        ),
        Case::Sphere(r, sp) => Case::Sphere(
            Ray::new(v(r.origin, k)?, v(r.dir, j)?),
            Sphere::new(v(sp.center, k)?, by(sp.radius, k)?),
        ),
        Case::Camera(..) => return None,
    })
}

/// Every stage's bounds are homogeneous, as their derivations make them:
/// scaling the inputs by powers of two ([`scaled`]) scales every value
/// the stage computes exactly, and so each decision with it. So each
/// stage has the same critical factor on a case and on the case scaled,
/// far up and far down; a term of a bound of the wrong degree (a
/// magnitude sum multiplied by another, or divided) moves it. On each
/// stage's committed cases, and for the quadric's x4 first pass the
/// kernels' searched quadric cases too.
#[test]
fn every_stage_decides_alike_on_scaled_cases() {
    let (committed, found) = (committed(), crate::bounds::found("quadric"));
    for st in &STAGES {
        let family = st.family();
        let mut cases: Vec<&Case> = committed
            .iter()
            .filter(|(f, _)| *f == family)
            .map(|(_, c)| c)
            .collect();
        if st.name.starts_with("x4") {
            cases.extend(&found);
        }
        let mut compared = 0;
        for c in cases {
            let base = st.critical_log2(c);
            for (k, j) in [
                (-24, 0),
                (20, 0),
                (0, -12),
                (0, 10),
                (16, -9),
                (-3, 2),
                (5, -1),
            ] {
                let Some(s) = scaled(c, k, j) else { continue };
                assert_eq!(st.critical_log2(&s), base, "{family}, 2^{k}, 2^{j}: {c:?}");
                compared += usize::from(base.is_some());
            }
        }
        println!("{family}: {compared} comparisons of a wrong case");
        assert!(
            compared >= 4,
            "{family}: {compared} comparisons of a wrong case"
        );
    }
}
