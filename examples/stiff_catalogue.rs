//! Writes the catalogue of stiff and extreme cases, `fixtures/stiff/`: one
//! `<kernel>.jsonl` per kernel (N cases per family, `eval` case lines with
//! `"family":"<kernel>/<name>"`), `families.json` (each family's kernel,
//! conditioning and why it is stiff) and `README.md` (the same as a table,
//! with what the exact oracle says about each family).
//!
//! ```text
//! cargo run --example stiff_catalogue              # rewrite fixtures/stiff/
//! cargo run --example stiff_catalogue -- --check   # compare, write nothing
//! ```
//!
//! Every family draws from its own `SmallRng::seed_from_u64(seed)`, so adding
//! or changing one family leaves the others' cases alone. The random numbers
//! are turned into floats here with `+ − × ÷ √` only (no `exp`, `sin`, …,
//! whose last bit may differ between platforms' libms), and every number is
//! written as an integer (when it is one, below 2²⁴) or as its f32 bits, so
//! the files are reproduced byte for byte. Each line is parsed back and
//! must give the same bits.
//!
//! Candidates are reject-sampled: a case is kept only if the exact oracle
//! gives the class the family wants, a camera is inside its stated domain
//! (`camera::in_domain`), and, for a well-conditioned family, every root's
//! condition number κ (as `rayoracle::check` evaluates it) is at most `2¹⁸`
//! (plane, sphere) or `2¹⁶` (quadric). The rejections are counted per
//! reason and printed.

use glam::Vec3;
use rand::rngs::SmallRng;
use rand::{RngCore, SeedableRng};
use rayoracle::Ray;
use rayoracle::camera::{self, CameraParams};
use rayoracle::case::{Case, parse_line};
use rayoracle::check::{self, CaseReport};
use rayoracle::exact::Quadratic;
use rayoracle::hit::Intersection;
use rayoracle::plane::{self, Plane};
use rayoracle::quadric::{self, Quadric};
use rayoracle::sphere::{self, Sphere};
use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

/// Cases per family.
const N: usize = 256;

/// The largest κ a well-conditioned plane or sphere root may have: the root
/// bound `1 + κ·2⁻¹⁸` is then at most 2 ulps.
const KAPPA_WELL: f64 = (1u64 << 18) as f64;
/// The same for the quadric, whose bound is `1 + κ·2⁻¹⁶`.
const KAPPA_WELL_QUADRIC: f64 = (1u64 << 16) as f64;

const PI: f64 = std::f64::consts::PI;

// ---------------------------------------------------------------------------
// Vectors in f64 (exact for the small integers and dyadics of the exact
// families; the random families round to f32 once, where it says so).

type V = [f64; 3];

fn add(a: V, b: V) -> V {
    [a[0] + b[0], a[1] + b[1], a[2] + b[2]]
}
fn sub(a: V, b: V) -> V {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}
fn mul(a: V, k: f64) -> V {
    [a[0] * k, a[1] * k, a[2] * k]
}
fn dot(a: V, b: V) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}
fn cross(a: V, b: V) -> V {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}
fn norm(a: V) -> f64 {
    dot(a, a).sqrt()
}
fn unit(a: V) -> V {
    mul(a, 1.0 / norm(a))
}
fn axis(i: usize) -> V {
    let mut v = [0.0; 3];
    v[i] = 1.0;
    v
}
/// Each component rounded to f32 (and back).
fn rv(a: V) -> V {
    a.map(|x| x as f32 as f64)
}
fn r1(x: f64) -> f64 {
    x as f32 as f64
}
/// Rounded to f32, with −0 written as +0 (a sign flip of a zero component
/// is not what any family is about).
fn f32v(a: V) -> Vec3 {
    Vec3::new(a[0] as f32 + 0.0, a[1] as f32 + 0.0, a[2] as f32 + 0.0)
}
/// Whether `x` is exactly an f32.
fn is_f32(x: f64) -> bool {
    x.is_finite() && x as f32 as f64 == x
}
/// `2^k` for `k` in the normal range of f64.
fn pow2(k: i32) -> f64 {
    assert!((-1022..=1023).contains(&k));
    f64::from_bits(((k + 1023) as u64) << 52)
}
/// The binary exponent of a positive normal f64.
fn exponent(x: f64) -> i32 {
    ((x.to_bits() >> 52) & 0x7ff) as i32 - 1023
}
/// An integer vector divided by the gcd of its components.
fn reduce(v: V) -> V {
    fn gcd(a: i64, b: i64) -> i64 {
        if b == 0 { a } else { gcd(b, a % b) }
    }
    let g = v.iter().fold(0, |g, &x| gcd(g, (x as i64).abs()));
    if g <= 1 { v } else { v.map(|x| x / g as f64) }
}
fn is_zero(v: V) -> bool {
    v == [0.0; 3]
}

// ---------------------------------------------------------------------------
// Random numbers: only `next_u64` of the seeded SmallRng, turned into
// floats here so the values do not depend on rand's float conversions.

struct Rng(SmallRng);

impl Rng {
    fn new(seed: u64) -> Rng {
        Rng(SmallRng::seed_from_u64(seed))
    }
    fn u64(&mut self) -> u64 {
        self.0.next_u64()
    }
    /// Uniform in [0, 1).
    fn unit(&mut self) -> f64 {
        (self.u64() >> 11) as f64 * pow2(-53)
    }
    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.unit()
    }
    /// Uniform integer in `lo..=hi`.
    fn int(&mut self, lo: i64, hi: i64) -> i64 {
        lo + (self.u64() % (hi - lo + 1) as u64) as i64
    }
    fn nonzero_int(&mut self, lo: i64, hi: i64) -> i64 {
        loop {
            let k = self.int(lo, hi);
            if k != 0 {
                return k;
            }
        }
    }
    fn chance(&mut self, p: f64) -> bool {
        self.unit() < p
    }
    fn sign(&mut self) -> f64 {
        if self.u64() >> 63 == 0 { 1.0 } else { -1.0 }
    }
    fn pick<T: Copy>(&mut self, xs: &[T]) -> T {
        xs[self.int(0, xs.len() as i64 - 1) as usize]
    }
    /// Log-spread in `[lo, hi]` (both positive): a uniform binary exponent
    /// and a uniform mantissa, so every octave is equally likely.
    fn log_uniform(&mut self, lo: f64, hi: f64) -> f64 {
        let (klo, khi) = (exponent(lo), exponent(hi));
        loop {
            let k = self.int(klo as i64, khi as i64) as i32;
            let x = pow2(k) * (1.0 + self.unit());
            if (lo..=hi).contains(&x) {
                return x;
            }
        }
    }
    /// A uniformly distributed unit vector (rejection from the cube).
    fn unit_vec(&mut self) -> V {
        loop {
            let v = [0; 3].map(|_| self.range(-1.0, 1.0));
            let r2 = dot(v, v);
            if r2 > 0.01 && r2 <= 1.0 {
                return mul(v, 1.0 / r2.sqrt());
            }
        }
    }
    /// A unit vector perpendicular to the unit vector `u`.
    fn perp(&mut self, u: V) -> V {
        loop {
            let w = cross(u, self.unit_vec());
            if norm(w) > 0.1 {
                return unit(w);
            }
        }
    }
    /// An integer vector with components in `lo..=hi`.
    fn ivec(&mut self, lo: i64, hi: i64) -> V {
        [0; 3].map(|_| self.int(lo, hi) as f64)
    }
    fn nonzero_ivec(&mut self, lo: i64, hi: i64) -> V {
        loop {
            let v = self.ivec(lo, hi);
            if !is_zero(v) {
                return v;
            }
        }
    }
    /// A random vector in the cube `[-h, h]³`, rounded to f32.
    fn cube(&mut self, h: f64) -> V {
        rv([0; 3].map(|_| self.range(-h, h)))
    }
    /// A nonzero dyadic `k / 2^j`, `k` in `±1..=m`, `j` in `0..=jmax`.
    fn dyadic(&mut self, m: i64, jmax: i64) -> f64 {
        self.nonzero_int(-m, m) as f64 * pow2(-self.int(0, jmax) as i32)
    }
}

// ---------------------------------------------------------------------------
// Families.

#[derive(Clone, Copy, PartialEq, Eq)]
enum Cond {
    Well,
    Ill,
}

impl Cond {
    fn name(self) -> &'static str {
        match self {
            Cond::Well => "well",
            Cond::Ill => "ill",
        }
    }
}

/// Why a candidate was thrown away.
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Debug)]
enum Reject {
    /// The exact oracle's class (or a geometric property checked with it)
    /// is not what the family wants.
    Class,
    /// Outside the kernel's stated domain.
    Domain,
    /// A root of a well-conditioned family has κ above the limit.
    Kappa,
    /// Not representable as wanted (a coefficient that is not exactly an
    /// f32, a root that overflows, a camera that cannot be built).
    Range,
}

const REJECTS: [Reject; 4] = [Reject::Class, Reject::Domain, Reject::Kappa, Reject::Range];

/// What the exact oracle must answer, known by construction (written to
/// the line as `"expect"`).
struct Expect {
    class: &'static str,
    /// The roots by construction, when they are known exactly.
    roots: Vec<f32>,
}

struct Cand {
    case: Case,
    expect: Option<Expect>,
    /// For the α ≈ 0 families: the angle between the ray and the axis.
    tilt: Option<f64>,
}

impl Cand {
    fn new(case: Case) -> Cand {
        Cand {
            case,
            expect: None,
            tilt: None,
        }
    }
    fn expect(case: Case, class: &'static str, roots: Vec<f32>) -> Cand {
        Cand {
            expect: Some(Expect { class, roots }),
            ..Cand::new(case)
        }
    }
    fn tilted(self, tilt: f64) -> Cand {
        Cand {
            tilt: Some(tilt),
            ..self
        }
    }
}

type Gen = fn(&mut Rng) -> Result<Cand, Reject>;

struct Family {
    name: &'static str,
    seed: u64,
    cond: Cond,
    make: Gen,
    why: &'static str,
}

impl Family {
    fn kernel(&self) -> &'static str {
        self.name.split('/').next().expect("kernel/name")
    }
}

const FAMILIES: &[Family] = &[
    // ----------------------------------------------------------------- sphere
    Family {
        name: "sphere/far-tiny",
        seed: 0x5f1f_0001,
        cond: Cond::Well,
        make: sphere_far_tiny,
        why: "R = 1 at 1e3 to 1e7, aimed to hit (80%) or to miss by at least 0.1 R: b² ≈ ac ≈ 1e14 while Δ ≈ 1, so the textbook f32 discriminant b² − ac is rounding noise and (−b − √Δ)/a loses every digit of the near root, although the roots are well-conditioned (κ < 5). From a distance of 4e5 to 1e6 on (depending on the aim) even the f64 textbook discriminant can lose the class.",
    },
    Family {
        name: "sphere/huge-near",
        seed: 0x5f1f_0002,
        cond: Cond::Ill,
        make: sphere_huge_near,
        why: "R = 1e4 to 1e7 with the origin 1e-3 to 10 above the surface, going down into it or grazing away (the line dips into the sphere behind): c = |f|² − R² cancels (both ≈ 1e14), so a naive c has no correct digit. The near root is ill-conditioned in the inputs (κ ≈ R/h, up to 1e10: one ulp of R or C moves the surface by R·2⁻²⁴ ≫ h), so it is judged by the κ-aware bound; the far root is well-conditioned.",
    },
    Family {
        name: "sphere/near-surface-outside",
        seed: 0x5f1f_0003,
        cond: Cond::Well,
        make: sphere_near_surface_outside,
        why: "The origin 1.5e-5 to 1e-4 (relative) outside the surface, rays that cross the sphere: c = |f|² − R² ≈ 2δR² cancels, so an uncompensated c makes the near root wrong by about 2⁻²⁴/δ relative (thousands of ulps), while its κ ≈ 1/δ < 2¹⁸ still promises 2 ulps.",
    },
    Family {
        name: "sphere/near-surface-inside",
        seed: 0x5f1f_0004,
        cond: Cond::Well,
        make: sphere_near_surface_inside,
        why: "As near-surface-outside with the origin just inside (c < 0 and tiny): a naive kernel gives the root near t = 0 the wrong sign or no correct digits, and picking the stable root formula by the sign of b matters on both sides of 0.",
    },
    Family {
        name: "sphere/near-tangent",
        seed: 0x5f1f_0005,
        cond: Cond::Ill,
        make: sphere_near_tangent,
        why: "Exact integer tangents perturbed by a tilt of 1e-30 to 1e-3 (relative) in a zero component of d, or by 1 to 1024 ulps of R or of the origin: the exact discriminant is tiny against its terms (down to 1e-46 of its terms), so the class is ill-conditioned and the two roots nearly coincide (κ → ∞). A naive kernel flips hit and miss at random.",
    },
    Family {
        name: "sphere/exact-tangent",
        seed: 0x5f1f_0006,
        cond: Cond::Well,
        make: sphere_exact_tangent,
        why: "Exactly tangent lines in small integers and dyadics (Pythagorean quadruples for the tangent point, d ⊥ T − C, o = T − s·d, scaled by powers of two; some axis-aligned, like centre 0 and a ray along an axis offset by R): Δ = 0 exactly with a·R within 24 bits, which the kernel documents it reproduces exactly (class tangent, root exact). A naive Δ rounds to a tiny ± value: two roots or a miss.",
    },
    Family {
        name: "sphere/origin-inside",
        seed: 0x5f1f_0007,
        cond: Cond::Well,
        make: sphere_origin_inside,
        why: "The origin strictly inside (up to 0.95 R from the centre), so t₀ < 0 < t₁: the seed's case analysis dropped this case, and a kernel that returns only positive roots, or picks the root by the sign of b, returns the wrong one.",
    },
    Family {
        name: "sphere/sphere-behind",
        seed: 0x5f1f_0008,
        cond: Cond::Well,
        make: sphere_behind,
        why: "The sphere entirely behind the origin (1.5 R to 1e3 R away, both roots negative): the line meets the sphere, so the exact class is two; a kernel that clips to t ≥ 0 inside the solver, or takes the class from the roots' signs, reports a miss.",
    },
    Family {
        name: "sphere/dir-scale",
        seed: 0x5f1f_0009,
        cond: Cond::Well,
        make: sphere_dir_scale,
        why: "Ordinary hits with |d| from 1e-10 to 1e10, so a = d·d spans 1e-20 to 1e20 and the roots 1e-10 to 1e13: the seed's discriminant is right only for |d| = 1, and the division-free form (aR)² − |af − bd|² reaches 1e40 and overflows f32 unless d is prescaled. The roots are well-conditioned.",
    },
    // ------------------------------------------------------------------ plane
    Family {
        name: "plane/near-parallel",
        seed: 0x91a0_0001,
        cond: Cond::Ill,
        make: plane_near_parallel,
        why: "d = n × e_i with its zero component set to ε, so d·n = ε·n_i exactly and |d·n| / Σ|dᵢnᵢ| runs from 1e-30 to 1e-3 (roots up to 1e34): κ ≈ 1/ε, for the class and the root alike. In a naive f32 dot product the ε term is absorbed before the other two cancel, so it returns 0 (parallel) or a residue of the wrong size.",
    },
    Family {
        name: "plane/in-plane",
        seed: 0x91a0_0002,
        cond: Cond::Well,
        make: plane_in_plane,
        why: "Origin and direction exactly in the plane (small integers, in-plane vectors n × w, powers of two; 30% axis-aligned): d·n = (a − o)·n = 0 exactly, class in_plane. The zeros come from exact products, which the kernel promises to keep; a rounding residue turns into a hit at a random t or a parallel miss.",
    },
    Family {
        name: "plane/far",
        seed: 0x91a0_0003,
        cond: Cond::Well,
        make: plane_far,
        why: "Planes 1e29 to 1e31 away, origins of size 1e-3 to 1e30, directions at least 0.1 from parallel: the roots (≈ 1e30) are well-conditioned, but |a − o|² or |n|²·|a − o|² (1e60) overflows f32, so a kernel that normalises or measures distances through squares fails, and the origin is lost next to the point unless a − o is formed exactly.",
    },
    Family {
        name: "plane/subnormal-normal",
        seed: 0x91a0_0004,
        cond: Cond::Well,
        make: plane_subnormal_normal,
        why: "Every component of the normal is subnormal (1 to 23 significant bits) or zero, so each dᵢnᵢ underflows to 0 or keeps a few bits in f32: a naive kernel calls the ray parallel or returns a root with few correct bits. The kernel prescales n by a power of two; the root is well-conditioned.",
    },
    // ---------------------------------------------------------------- quadric
    Family {
        name: "quadric/alpha-zero-cylinder",
        seed: 0x9ad0_0001,
        cond: Cond::Well,
        make: quadric_alpha_zero_cylinder,
        why: "A ray exactly parallel to the axis of an elliptic, hyperbolic or parabolic cylinder (integer axis, mostly off the coordinate axes, so α = 0 comes from nonzero terms that cancel exactly): α = β = 0, class none, or all when the origin is on the surface (25%). The textbook −β/2α ± √(β²/4α² − γ/α) computes 0/0.",
    },
    Family {
        name: "quadric/alpha-zero-paraboloid",
        seed: 0x9ad0_0002,
        cond: Cond::Well,
        make: quadric_alpha_zero_paraboloid,
        why: "A ray exactly along the axis of an elliptic or hyperbolic paraboloid (integer axis): α = 0 exactly and β ≠ 0, so the equation is linear with the one well-conditioned root −γ/β. The textbook formula divides by α = 0 and returns NaN or ±∞.",
    },
    Family {
        name: "quadric/alpha-near-zero",
        seed: 0x9ad0_0003,
        cond: Cond::Well,
        make: quadric_alpha_near_zero,
        why: "A ray 1e-7 to 1e-3 rad off the axis of an axis-aligned elliptic cylinder: α ≈ θ² is tiny but has no cancelling terms, and both roots (≈ ρ/θ, up to 5e7) keep κ ≤ 3.5e4 at every tilt (set by the off-centre γ terms, not by θ). The textbook form divides by α and squares β/2α, so it loses digits where pbrt's q = −½(β + sign(β)√Δ) does not.",
    },
    Family {
        name: "quadric/alpha-near-zero-rotated",
        seed: 0x9ad0_0004,
        cond: Cond::Ill,
        make: quadric_alpha_near_zero_rotated,
        why: "As alpha-near-zero, but the cylinder's axis is an integer vector off the coordinate axes, so α ≈ θ² is the difference of O(1) terms: one ulp of one coefficient moves α by far more than θ², and κ (over the terms) grows roughly like 1/θ², from 1e9 at 1e-3 to 1e15 at 1e-7. A naive f32 α is pure rounding noise below θ ≈ 2⁻¹².",
    },
    Family {
        name: "quadric/alpha-near-zero-paraboloid",
        seed: 0x9ad0_0005,
        cond: Cond::Well,
        make: quadric_alpha_near_zero_paraboloid,
        why: "A ray 1e-7 to 1e-3 rad off an axis-aligned paraboloid's axis: one near root ≈ −γ/β and one far root ≈ −β/α up to 6e14, both well-conditioned. The textbook −β/2α ± √(β²/4α² − γ/α) forms the near root as the difference of two numbers of size 1/θ² and loses every digit: the classic case for pbrt's stable form.",
    },
    Family {
        name: "quadric/coefficient-spread",
        seed: 0x9ad0_0006,
        cond: Cond::Well,
        make: quadric_coefficient_spread,
        why: "Ellipsoids and hyperboloids of one and two sheets with axis scales from 1e-4 to 1e4, so the coefficients span 1e-8 to 1e8 (after pbrt-v4's quadric tests), half of them off-centre, rays aimed through the body: the terms of α, β and γ differ by up to 16 orders of magnitude, and f32 sums and the discriminant drop the small ones. The roots are well-conditioned.",
    },
    Family {
        name: "quadric/cone-apex",
        seed: 0x9ad0_0007,
        cond: Cond::Ill,
        make: quadric_cone_apex,
        why: "Rays exactly through the apex of elliptic cones (integer axes and apex, dyadic t₀): p(t) = (t − t₀)²·dᵀMd, a double root at the apex, class one with t₀ known exactly. A double root is infinitely ill-conditioned: only exact arithmetic finds it, and a naive kernel reports two roots or none.",
    },
    Family {
        name: "quadric/line-on-surface",
        seed: 0x9ad0_0008,
        cond: Cond::Well,
        make: quadric_line_on_surface,
        why: "Lines on the surface, in integers: rulings of elliptic hyperboloids of one sheet (through Pythagorean points of the throat), generators of elliptic cylinders, rulings of elliptic cones and of the saddle 2xy = 2mz. α = β = γ = 0 exactly, class all; a naive kernel sees 0/0 and reports none or NaN.",
    },
    Family {
        name: "quadric/degenerate-plane-pair",
        seed: 0x9ad0_0009,
        cond: Cond::Well,
        make: quadric_plane_pair,
        why: "Products of two integer linear factors, crossing (x² − k²y²) or parallel (x² − e² = (x − e)(x + e)), rotated and shifted: the quadric's matrix is singular and β² − 4αγ is a perfect square, cases that a kernel which first classifies the surface type has no branch for. A ray crossing both planes has two well-conditioned roots.",
    },
    Family {
        name: "quadric/double-plane",
        seed: 0x9ad0_000a,
        cond: Cond::Ill,
        make: quadric_double_plane,
        why: "(n·p − e)² = 0 with integer n, e (x² = 0 and its rotations), random rays: β² − 4αγ = 0 exactly, a double root where the ray crosses the plane, class one. Infinitely ill-conditioned: plain floating point answers two or none on most of these, as it must for inexact t.",
    },
    // ----------------------------------------------------------------- camera
    Family {
        name: "camera/fov-range",
        seed: 0xca3e_0001,
        cond: Cond::Well,
        make: camera_fov_range,
        why: "Vertical fields of view from 1e-3 to π − 1e-3 rad, log-spread toward both ends: h = tan(angle/2) spans 5e-4 to 2e3 and near π amplifies any error in angle/2 by about 3e3, so a tanf a few ulps off near π/2, or a round trip through degrees, breaks the 4-ulp bound there.",
    },
    Family {
        name: "camera/res-65535",
        seed: 0xca3e_0002,
        cond: Cond::Well,
        make: camera_res_65535,
        why: "resX and/or resY = 65535 (aspect ratios up to 65535:1), pixels at the edges, next to them and at the exact centre: the offset 2((X + ½)/res − ½) must be exactly 0 at the centre and is rounded once from the exact integer 2X + 1 − res; computing it in steps rounds twice, and 16-bit pixel arithmetic overflows.",
    },
    Family {
        name: "camera/dir-near-up",
        seed: 0xca3e_0003,
        cond: Cond::Ill,
        make: camera_dir_near_up,
        why: "dir within 1e-6 to 1e-3 rad of up or of −up: dir × up is a difference of nearly equal products, so the horizontal axis is ill-conditioned in the inputs (κ ≈ 1/angle, up to 1e6). The check's bound stays 4 ulps of the oracle's components for the given inputs; a naive f32 cross product turns the axis by up to about 2⁻²⁴/angle rad and fails it.",
    },
    Family {
        name: "camera/dir-scale",
        seed: 0xca3e_0004,
        cond: Cond::Well,
        make: camera_dir_scale,
        why: "|dir| (the focal distance) from 1e-20 to 1e20 and |up| from 1e-3 to 1e3: normalising dir or dir × up through squared lengths underflows (1e-40) or overflows (1e40) in f32. The ray direction is well-conditioned and scales with |dir|.",
    },
];

// ---------------------------------------------------------------------------
// Case constructors.

fn sphere_case(o: V, d: V, c: V, r: f64) -> Case {
    Case::Sphere(Ray::new(f32v(o), f32v(d)), Sphere::new(f32v(c), r as f32))
}

fn plane_case(o: V, d: V, a: V, n: V) -> Case {
    Case::Plane(Ray::new(f32v(o), f32v(d)), Plane::new(f32v(a), f32v(n)))
}

fn quadric_case(o: V, d: V, k: [f32; 10]) -> Case {
    Case::Quadric(Ray::new(f32v(o), f32v(d)), Quadric::new(k))
}

/// A sphere case whose inputs are all exactly f32 (the exact families).
fn exact_sphere_case(o: V, d: V, c: V, r: f64) -> Result<Case, Reject> {
    let all = [o, d, c, [r; 3]];
    if all.iter().flatten().all(|&x| is_f32(x)) {
        Ok(sphere_case(o, d, c, r))
    } else {
        Err(Reject::Range)
    }
}

/// The sphere's exact quadratic `a t² + 2b t + c` (`a > 0`).
fn sphere_quadratic(case: &Case) -> Quadratic {
    let Case::Sphere(ray, s) = case else {
        unreachable!()
    };
    sphere::exact::quadratic(ray, s).expect("finite")
}

/// `Δ/a = R² − |l|²` (`l` the closest-approach vector) over `R²`: positive
/// for a hit, negative for a miss, −0.21 for a miss by 0.1 R.
fn sphere_rel_margin(case: &Case) -> f64 {
    let Case::Sphere(_, s) = case else {
        unreachable!()
    };
    let q = sphere_quadratic(case);
    let r2 = s.radius as f64 * s.radius as f64;
    q.discriminant().to_f64() / (4.0 * q.alpha.to_f64()) / r2
}

fn exact_class(case: &Case) -> (&'static str, Vec<f32>) {
    fn of(h: impl Intersection) -> (&'static str, Vec<f32>) {
        (h.class().as_str(), h.roots().as_slice().to_vec())
    }
    match case {
        Case::Sphere(r, s) => of(sphere::exact::intersect(r, s).expect("finite")),
        Case::Plane(r, p) => of(plane::exact::intersect(r, p).expect("finite")),
        Case::Quadric(r, q) => of(quadric::exact::intersect(r, q).expect("finite")),
        Case::Camera(..) => ("ray", vec![]),
    }
}

/// Keeps the candidate only if the exact class is one of `classes`.
fn want(case: Case, classes: &[&str]) -> Result<Cand, Reject> {
    if classes.contains(&exact_class(&case).0) {
        Ok(Cand::new(case))
    } else {
        Err(Reject::Class)
    }
}

// ---------------------------------------------------------------------------
// Sphere families.

fn sphere_far_tiny(g: &mut Rng) -> Result<Cand, Reject> {
    let c = rv(mul(g.unit_vec(), g.range(0.0, 1e3)));
    let u = g.unit_vec();
    let o = rv(add(c, mul(u, g.log_uniform(1e3, 1e7))));
    let hit = g.chance(0.8);
    let h = if hit {
        g.range(0.0, 0.9)
    } else {
        g.range(1.2, 3.0)
    };
    let target = add(c, mul(g.perp(u), h));
    let dir = sub(target, o);
    let d = rv(mul(dir, g.log_uniform(0.5, 2.0) / norm(dir)));
    let case = sphere_case(o, d, c, 1.0);
    // The aim is only as good as f32 positions at 1e7 (about 1 unit), so the
    // exact class decides, and a miss must clear the sphere by 0.1 R.
    if hit {
        want(case, &["two"])
    } else if sphere_rel_margin(&case) <= -0.21 {
        want(case, &["none"])
    } else {
        Err(Reject::Class)
    }
}

fn sphere_huge_near(g: &mut Rng) -> Result<Cand, Reject> {
    let r = r1(g.log_uniform(1e4, 1e7));
    let h = g.log_uniform(1e-3, 10.0);
    let u = g.unit_vec();
    // The origin stays near the coordinate origin (fine f32 spacing); the
    // centre is far, rounded first, and the origin placed from it.
    let near = mul(g.unit_vec(), g.range(0.0, 10.0));
    let c = rv(sub(near, mul(u, r + h)));
    let o = rv(add(c, mul(u, r + h)));
    let w = g.perp(u);
    let dir = if g.chance(0.75) {
        // Down into the sphere, up to about 80° from the vertical.
        add(mul(u, -1.0), mul(w, g.range(0.0, 6.0)))
    } else {
        // Grazing away: above the horizon by 1.5 to 20 times the angle at
        // which the line behind the origin starts to dip into the sphere.
        add(w, mul(u, g.range(1.5, 20.0) * (2.0 * h / r).sqrt()))
    };
    let d = rv(mul(unit(dir), g.log_uniform(0.5, 2.0)));
    let case = sphere_case(o, d, c, r);
    // The height above the surface, c/(|f| + R) ≈ c/2R, from the exact c.
    let height = sphere_quadratic(&case).gamma.to_f64() / (2.0 * r);
    if !(5e-4..=20.0).contains(&height) {
        return Err(Reject::Class);
    }
    want(case, &["two"])
}

fn sphere_near_surface(g: &mut Rng, outside: bool) -> Result<Cand, Reject> {
    let r = r1(g.log_uniform(pow2(-4), pow2(10)));
    let c = rv(mul(g.unit_vec(), r * g.range(0.0, 1.0)));
    let delta = g.log_uniform(pow2(-16), 1e-4);
    let rho = if outside {
        r * (1.0 + delta)
    } else {
        r * (1.0 - delta)
    };
    let o = rv(add(c, mul(g.unit_vec(), rho)));
    let d = rv(mul(g.unit_vec(), g.log_uniform(0.5, 2.0)));
    let case = sphere_case(o, d, c, r);
    // c = |f|² − R² ≈ ±2δR²: on the intended side and within 1e-4.
    let rel = sphere_quadratic(&case).gamma.to_f64() / (r * r);
    let side_ok = if outside { rel > 0.0 } else { rel < 0.0 };
    if !side_ok || rel.abs() > 2.1e-4 {
        return Err(Reject::Class);
    }
    want(case, &["two"])
}

fn sphere_near_surface_outside(g: &mut Rng) -> Result<Cand, Reject> {
    sphere_near_surface(g, true)
}

fn sphere_near_surface_inside(g: &mut Rng) -> Result<Cand, Reject> {
    sphere_near_surface(g, false)
}

/// Pythagorean quadruples `(x, y, z, n)`, `x² + y² + z² = n²`.
const QUADRUPLES: [[f64; 4]; 14] = [
    [1.0, 0.0, 0.0, 1.0],
    [0.0, 3.0, 4.0, 5.0],
    [1.0, 2.0, 2.0, 3.0],
    [2.0, 3.0, 6.0, 7.0],
    [1.0, 4.0, 8.0, 9.0],
    [4.0, 4.0, 7.0, 9.0],
    [2.0, 6.0, 9.0, 11.0],
    [6.0, 6.0, 7.0, 11.0],
    [3.0, 4.0, 12.0, 13.0],
    [0.0, 5.0, 12.0, 13.0],
    [2.0, 10.0, 11.0, 15.0],
    [2.0, 5.0, 14.0, 15.0],
    [1.0, 12.0, 12.0, 17.0],
    [8.0, 9.0, 12.0, 17.0],
];

/// A signed permutation of the coordinates: `(S p)ᵢ = sᵢ p_{π(i)}`.
#[derive(Clone, Copy)]
struct Perm {
    pi: [usize; 3],
    s: [f64; 3],
}

impl Perm {
    fn random(g: &mut Rng) -> Perm {
        let pi = g.pick(&[
            [0, 1, 2],
            [0, 2, 1],
            [1, 0, 2],
            [1, 2, 0],
            [2, 0, 1],
            [2, 1, 0],
        ]);
        Perm {
            pi,
            s: [g.sign(), g.sign(), g.sign()],
        }
    }
    fn v(&self, p: V) -> V {
        [0, 1, 2].map(|i| self.s[i] * p[self.pi[i]])
    }
}

/// An exactly tangent configuration in small integers and dyadics: centre
/// `c`, radius `r`, origin `o`, direction `d`, tangent at `t` (`o + t d`).
struct Tangent {
    c: V,
    r: f64,
    o: V,
    d: V,
    t: f64,
}

/// `zero_in`: make `d` have a zero component there (`d = w × e_i`).
fn tangent_setup(g: &mut Rng, zero_in: Option<usize>) -> Tangent {
    loop {
        let axis_mode = zero_in.is_none() && g.chance(0.2);
        let q = if axis_mode {
            QUADRUPLES[0]
        } else {
            g.pick(&QUADRUPLES)
        };
        let w = Perm::random(g).v([q[0], q[1], q[2]]);
        let k = g.int(1, 6) as f64;
        let c = if axis_mode && g.chance(0.5) {
            [0.0; 3]
        } else {
            g.ivec(-20, 20)
        };
        let e = match zero_in {
            Some(i) => axis(i),
            None if axis_mode => axis(g.int(0, 2) as usize),
            None => g.ivec(-3, 3),
        };
        let d = mul(reduce(cross(w, e)), g.int(1, 3) as f64 * g.sign());
        let r = k * q[3];
        if is_zero(d) || dot(d, d) * r >= pow2(24) {
            continue;
        }
        let t = g.dyadic(16, 3);
        let o = sub(add(c, mul(w, k)), mul(d, t));
        return Tangent { c, r, o, d, t };
    }
}

fn sphere_exact_tangent(g: &mut Rng) -> Result<Cand, Reject> {
    let tg = tangent_setup(g, None);
    // Scale positions by 2^p and the direction by 2^q: t scales by 2^(p−q).
    let (p, q) = (g.int(-12, 12) as i32, g.int(-12, 12) as i32);
    let (sp, sq) = (pow2(p), pow2(q));
    let t = tg.t * sp / sq;
    let case = exact_sphere_case(mul(tg.o, sp), mul(tg.d, sq), mul(tg.c, sp), tg.r * sp)?;
    Ok(Cand::expect(case, "tangent", vec![t as f32]))
}

/// `x` moved by `k` ulps (`k` may be negative); `x` nonzero and normal.
fn ulps_away(x: f32, k: i64) -> f32 {
    let bits = x.to_bits() as i64;
    let k = if x < 0.0 { -k } else { k };
    f32::from_bits((bits + k) as u32)
}

fn sphere_near_tangent(g: &mut Rng) -> Result<Cand, Reject> {
    let mode = g.int(0, 3);
    let zero_in = (mode < 2).then(|| g.int(0, 2) as usize);
    let tg = tangent_setup(g, zero_in);
    let (sp, sq) = (pow2(g.int(-8, 8) as i32), pow2(g.int(-8, 8) as i32));
    let (mut o, mut d, c, mut r) = (mul(tg.o, sp), mul(tg.d, sq), mul(tg.c, sp), tg.r * sp);
    let k = g.log_uniform(1.0, 1024.0) as i64 * g.sign() as i64;
    match zero_in {
        // Tilt d in its zero component, relative 1e-30 to 1e-3.
        Some(i) => {
            let m = d.iter().fold(0.0f64, |m, x| m.max(x.abs()));
            d[i] = r1(g.sign() * g.log_uniform(1e-30, 1e-3) * m);
        }
        None if mode == 2 => r = ulps_away(r as f32, k) as f64,
        None => {
            let i = g.int(0, 2) as usize;
            o[i] = if o[i] == 0.0 {
                r1(g.sign() * g.log_uniform(1e-30, 1e-3) * r)
            } else {
                ulps_away(o[i] as f32, k) as f64
            };
        }
    }
    let case = exact_sphere_case(o, d, c, r)?;
    want(case, &["two", "none"])
}

fn sphere_origin_inside(g: &mut Rng) -> Result<Cand, Reject> {
    let r = r1(g.log_uniform(1e-3, 1e4));
    let c = rv(mul(g.unit_vec(), r * g.log_uniform(1e-3, 100.0)));
    let o = rv(add(c, mul(g.unit_vec(), r * g.range(0.0, 0.95))));
    let d = rv(mul(g.unit_vec(), g.log_uniform(0.25, 4.0)));
    let case = sphere_case(o, d, c, r);
    if sphere_quadratic(&case).gamma.signum() >= 0 {
        return Err(Reject::Class);
    }
    want(case, &["two"])
}

/// A sphere (`c`, `r`) and an origin `dist · r` from its centre, with the
/// unit direction from the origin to a point within 0.9 r of the centre.
fn aimed(g: &mut Rng, dist: f64) -> (V, f64, V, V) {
    let r = r1(g.log_uniform(1e-2, 1e3));
    let c = rv(mul(g.unit_vec(), r * g.log_uniform(1e-3, 100.0)));
    let u = g.unit_vec();
    let o = rv(add(c, mul(u, r * dist)));
    let target = add(c, mul(g.perp(u), r * g.range(0.0, 0.9)));
    (c, r, o, unit(sub(target, o)))
}

fn sphere_behind(g: &mut Rng) -> Result<Cand, Reject> {
    let dist = g.log_uniform(1.5, 1e3);
    let (c, r, o, toward) = aimed(g, dist);
    let d = rv(mul(toward, -g.log_uniform(0.25, 4.0)));
    let case = sphere_case(o, d, c, r);
    match exact_class(&case) {
        ("two", roots) if roots[1] < 0.0 => Ok(Cand::new(case)),
        _ => Err(Reject::Class),
    }
}

fn sphere_dir_scale(g: &mut Rng) -> Result<Cand, Reject> {
    let dist = g.range(1.5, 20.0);
    let (c, r, o, toward) = aimed(g, dist);
    let d = rv(mul(toward, g.log_uniform(1e-10, 1e10)));
    want(sphere_case(o, d, c, r), &["two"])
}

// ---------------------------------------------------------------------------
// Plane families.

fn plane_near_parallel(g: &mut Rng) -> Result<Cand, Reject> {
    let n = rv(mul(g.unit_vec(), g.log_uniform(0.1, 10.0)));
    let i = g.int(0, 2) as usize;
    // d = 2^q (n × e_i) copies two components of n, so d·n = 0 exactly;
    // then its zero component i becomes ε.
    let mut d = mul(cross(n, axis(i)), pow2(g.int(-4, 4) as i32));
    let sum: f64 = (0..3).map(|j| (d[j] * n[j]).abs()).sum();
    d[i] = r1(g.sign() * g.log_uniform(1e-30, 1e-3) * sum / n[i].abs());
    let case = plane_case(g.cube(100.0), d, g.cube(100.0), n);
    want(case, &["hit"])
}

fn plane_in_plane(g: &mut Rng) -> Result<Cand, Reject> {
    let n = if g.chance(0.3) {
        mul(axis(g.int(0, 2) as usize), g.dyadic(5, 0))
    } else {
        reduce(g.nonzero_ivec(-6, 6))
    };
    let (e1, e2) = (cross(n, g.ivec(-3, 3)), cross(n, g.ivec(-3, 3)));
    let d = add(mul(e1, g.int(-3, 3) as f64), mul(e2, g.int(-3, 3) as f64));
    if is_zero(d) {
        return Err(Reject::Class);
    }
    let a = g.ivec(-50, 50);
    let o = add(
        a,
        add(mul(e1, g.int(-5, 5) as f64), mul(e2, g.int(-5, 5) as f64)),
    );
    let sp = pow2(g.int(-20, 20) as i32);
    let (sn, sd) = (pow2(g.int(-20, 20) as i32), pow2(g.int(-20, 20) as i32));
    let (o, d, a, n) = (mul(o, sp), mul(d, sd), mul(a, sp), mul(n, sn));
    if ![o, d, a, n].iter().flatten().all(|&x| is_f32(x)) {
        return Err(Reject::Range);
    }
    Ok(Cand::expect(plane_case(o, d, a, n), "in_plane", vec![]))
}

fn plane_far(g: &mut Rng) -> Result<Cand, Reject> {
    let o = rv(mul(g.unit_vec(), g.log_uniform(1e-3, 1e30)));
    let nh = g.unit_vec();
    let n = rv(mul(nh, g.log_uniform(0.1, 10.0)));
    let dist = g.sign() * g.log_uniform(1e29, 1e31);
    let a = rv(add(
        o,
        add(
            mul(nh, dist),
            mul(g.perp(nh), dist.abs() * g.range(0.0, 2.0)),
        ),
    ));
    let dh = loop {
        let v = g.unit_vec();
        if dot(v, nh).abs() >= 0.1 {
            break v;
        }
    };
    let d = rv(mul(dh, g.log_uniform(0.5, 2.0)));
    want(plane_case(o, d, a, n), &["hit"])
}

fn plane_subnormal_normal(g: &mut Rng) -> Result<Cand, Reject> {
    let n = [0; 3].map(|_| {
        if g.chance(0.15) {
            0.0
        } else {
            let bits = g.int(1, 23);
            let m = g.int(1, (1 << bits) - 1);
            g.sign() * m as f64 * pow2(-149)
        }
    });
    if is_zero(n) {
        return Err(Reject::Class);
    }
    let d = rv(mul(g.unit_vec(), g.log_uniform(0.5, 2.0)));
    want(plane_case(g.cube(100.0), d, g.cube(100.0), n), &["hit"])
}

// ---------------------------------------------------------------------------
// Quadric families. A quadric is kept as `Q(p) = pᵀMp + l·p + j` in f64,
// exact for the integer and dyadic families.

#[derive(Clone, Copy)]
struct Quad {
    m: [[f64; 3]; 3],
    l: V,
    j: f64,
}

impl Quad {
    fn form(m: [[f64; 3]; 3]) -> Quad {
        Quad {
            m,
            l: [0.0; 3],
            j: 0.0,
        }
    }
    /// `Σ λ u uᵀ`.
    fn sum_of_squares(terms: &[(f64, V)]) -> Quad {
        let mut m = [[0.0; 3]; 3];
        for &(lam, u) in terms {
            for (i, row) in m.iter_mut().enumerate() {
                for (j, x) in row.iter_mut().enumerate() {
                    *x += lam * u[i] * u[j];
                }
            }
        }
        Quad::form(m)
    }
    fn mv(&self, v: V) -> V {
        [0, 1, 2].map(|i| dot(self.m[i], v))
    }
    fn eval(&self, p: V) -> f64 {
        dot(p, self.mv(p)) + dot(self.l, p) + self.j
    }
    /// `Q(p − c)`: the same surface moved by `c`.
    fn translate(&self, c: V) -> Quad {
        Quad {
            m: self.m,
            l: sub(self.l, mul(self.mv(c), 2.0)),
            j: dot(c, self.mv(c)) - dot(self.l, c) + self.j,
        }
    }
    /// The surface under the signed permutation `p ↦ S p`.
    fn permute(&self, s: &Perm) -> Quad {
        let mut m = [[0.0; 3]; 3];
        for (a, row) in m.iter_mut().enumerate() {
            for (b, x) in row.iter_mut().enumerate() {
                *x = s.s[a] * s.s[b] * self.m[s.pi[a]][s.pi[b]];
            }
        }
        Quad {
            m,
            l: s.v(self.l),
            j: self.j,
        }
    }
    /// The surface scaled by `2^k` about the origin: `Q(p · 2^−k)`.
    fn scale_space(&self, k: i32) -> Quad {
        Quad {
            m: self.m.map(|row| row.map(|x| x * pow2(-2 * k))),
            l: mul(self.l, pow2(-k)),
            j: self.j,
        }
    }
    /// Every coefficient times `2^r` (the same surface).
    fn scale_coeffs(&self, r: i32) -> Quad {
        let s = pow2(r);
        Quad {
            m: self.m.map(|row| row.map(|x| x * s)),
            l: mul(self.l, s),
            j: self.j * s,
        }
    }
    fn coeffs64(&self) -> [f64; 10] {
        let m = &self.m;
        [
            m[0][0],
            m[1][1],
            m[2][2],
            2.0 * m[0][1],
            2.0 * m[0][2],
            2.0 * m[1][2],
            self.l[0],
            self.l[1],
            self.l[2],
            self.j,
        ]
    }
    /// The coefficients, if each is exactly an f32.
    fn exact(&self) -> Result<[f32; 10], Reject> {
        let k = self.coeffs64();
        if k.iter().all(|&x| is_f32(x)) {
            Ok(k.map(|x| x as f32 + 0.0))
        } else {
            Err(Reject::Range)
        }
    }
    fn rounded(&self) -> [f32; 10] {
        self.coeffs64().map(|x| x as f32 + 0.0)
    }
}

/// Signed permutation, scaling of space by `2^p`, of the direction by
/// `2^k` and of the coefficients by `2^r`, drawn once and applied to a
/// quadric and its ray (all exact).
struct Frame {
    perm: Perm,
    p: i32,
    k: i32,
    r: i32,
}

impl Frame {
    fn random(g: &mut Rng, max: i64) -> Frame {
        Frame {
            perm: Perm::random(g),
            p: g.int(-max, max) as i32,
            k: g.int(-max, max) as i32,
            r: g.int(-max, max) as i32,
        }
    }
    fn quad(&self, q: &Quad) -> Quad {
        q.permute(&self.perm)
            .scale_space(self.p)
            .scale_coeffs(self.r)
    }
    fn point(&self, o: V) -> V {
        mul(self.perm.v(o), pow2(self.p))
    }
    fn dir(&self, d: V) -> V {
        mul(self.perm.v(d), pow2(self.k))
    }
    fn t(&self, t: f64) -> f64 {
        t * pow2(self.p - self.k)
    }
}

/// An exact quadric case: coefficients, origin and direction must all be
/// exactly f32.
fn exact_quadric_case(q: &Quad, o: V, d: V) -> Result<Case, Reject> {
    let k = q.exact()?;
    if [o, d].iter().flatten().all(|&x| is_f32(x)) {
        Ok(quadric_case(o, d, k))
    } else {
        Err(Reject::Range)
    }
}

/// Mutually orthogonal integer vectors `(v, u1, u2)`, `v` the axis: axis
/// aligned with probability `p_axis`, otherwise with `v` having at least
/// two nonzero components.
fn orth_basis(g: &mut Rng, p_axis: f64) -> (V, V, V) {
    if g.chance(p_axis) {
        let k = g.int(0, 2) as usize;
        return (axis(k), axis((k + 1) % 3), axis((k + 2) % 3));
    }
    loop {
        let v = reduce(g.nonzero_ivec(-2, 2));
        if v.iter().filter(|x| **x != 0.0).count() < 2 {
            continue;
        }
        let u1 = reduce(cross(v, g.ivec(-2, 2)));
        if is_zero(u1) {
            continue;
        }
        return (v, u1, reduce(cross(v, u1)));
    }
}

fn quadric_alpha_zero_cylinder(g: &mut Rng) -> Result<Cand, Reject> {
    let (v, u1, u2) = orth_basis(g, 0.3);
    let kind = g.int(0, 2);
    let l1 = g.int(1, 3) as f64;
    let mut q = match kind {
        0 => Quad::sum_of_squares(&[(l1, u1), (g.int(1, 3) as f64, u2)]),
        1 => Quad::sum_of_squares(&[(l1, u1), (-g.int(1, 3) as f64, u2)]),
        _ => {
            // Parabolic cylinder λ(u1·p)² + μ(u2·p).
            let mut q = Quad::sum_of_squares(&[(l1, u1)]);
            q.l = mul(u2, g.nonzero_int(-3, 3) as f64);
            q
        }
    };
    let c = g.ivec(-5, 5);
    let on_surface = g.chance(0.25);
    let q0 = g.ivec(-3, 3);
    q.j = if on_surface {
        -q.eval(q0)
    } else {
        g.nonzero_int(-200, 200) as f64
    };
    let f = Frame::random(g, 6);
    let qf = f.quad(&q.translate(c));
    let d = f.dir(mul(v, g.dyadic(3, 2)));
    if on_surface {
        let o = f.point(add(c, add(q0, mul(v, g.dyadic(16, 2)))));
        let case = exact_quadric_case(&qf, o, d)?;
        Ok(Cand::expect(case, "all", vec![]))
    } else {
        let o = g.cube(30.0);
        let case = exact_quadric_case(&qf, o, d)?;
        if exact_class(&case).0 != "none" {
            return Err(Reject::Class);
        }
        Ok(Cand::expect(case, "none", vec![]))
    }
}

fn quadric_alpha_zero_paraboloid(g: &mut Rng) -> Result<Cand, Reject> {
    let (v, u1, u2) = orth_basis(g, 0.3);
    let l2 = g.int(1, 3) as f64 * if g.chance(0.3) { -1.0 } else { 1.0 };
    let mut q = Quad::sum_of_squares(&[(g.int(1, 3) as f64, u1), (l2, u2)]);
    q.l = mul(v, g.nonzero_int(-4, 4) as f64);
    let f = Frame::random(g, 6);
    let qf = f.quad(&q.translate(g.ivec(-5, 5)));
    let d = f.dir(mul(v, g.dyadic(3, 2)));
    let o = g.cube(30.0);
    let case = exact_quadric_case(&qf, o, d)?;
    Ok(Cand::expect(case, "one", vec![]))
}

/// A random 2-D unit vector `(x, y)`.
fn unit2(g: &mut Rng) -> (f64, f64) {
    loop {
        let (x, y) = (g.range(-1.0, 1.0), g.range(-1.0, 1.0));
        let r2 = x * x + y * y;
        if r2 > 0.01 && r2 <= 1.0 {
            let r = r2.sqrt();
            return (x / r, y / r);
        }
    }
}

/// An axis-aligned (z) elliptic conic form `A x² + B y² + D xy`.
fn elliptic_xy(g: &mut Rng) -> Quad {
    let (a, b) = (g.log_uniform(0.25, 4.0), g.log_uniform(0.25, 4.0));
    let dxy = g.range(-0.9, 0.9) * (a * b).sqrt();
    Quad::form([[a, dxy, 0.0], [dxy, b, 0.0], [0.0, 0.0, 0.0]])
}

/// A direction tilted by `θ` (1e-7 to 1e-3) from the z axis, any length,
/// rounded to f32, and its tilt after rounding.
fn tilted_z(g: &mut Rng) -> (V, f64) {
    let theta = g.log_uniform(1e-7, 1e-3);
    let (x, y) = unit2(g);
    let d = rv(mul(
        [theta * x, theta * y, g.sign()],
        g.log_uniform(0.5, 2.0),
    ));
    (d, (d[0] * d[0] + d[1] * d[1]).sqrt() / d[2].abs())
}

fn quadric_alpha_near_zero(g: &mut Rng) -> Result<Cand, Reject> {
    let mut q = elliptic_xy(g);
    let r = g.log_uniform(0.5, 5.0);
    q.j = -r * r;
    let c = [g.range(-10.0, 10.0), g.range(-10.0, 10.0), 0.0];
    let q = q.translate(c);
    let (x, y) = unit2(g);
    let rho = r * g.range(0.0, 2.0);
    let o = add(c, [rho * x, rho * y, g.range(-100.0, 100.0)]);
    let perm = Perm::random(g);
    let (d, tilt) = tilted_z(g);
    let case = quadric_case(rv(perm.v(o)), perm.v(d), q.permute(&perm).rounded());
    Ok(want(case, &["two"])?.tilted(tilt))
}

fn quadric_alpha_near_zero_rotated(g: &mut Rng) -> Result<Cand, Reject> {
    let (v, u1, u2) = orth_basis(g, 0.0);
    let mut q = Quad::sum_of_squares(&[(g.int(1, 3) as f64, u1), (g.int(1, 3) as f64, u2)]);
    let rad = g.log_uniform(0.5, 5.0);
    q.j = -(q.eval(mul(unit(u1), rad))).round().max(1.0);
    let c = g.ivec(-5, 5);
    let q = q.translate(c);
    let vh = unit(v);
    let o = add(
        c,
        add(
            mul(g.perp(vh), rad * g.range(0.0, 2.0)),
            mul(vh, g.range(-50.0, 50.0)),
        ),
    );
    let theta = g.log_uniform(1e-7, 1e-3);
    let d = rv(mul(
        add(vh, mul(g.perp(vh), theta)),
        g.sign() * g.log_uniform(0.5, 2.0),
    ));
    // The tilt that survived rounding d to f32.
    let tilt = norm(cross(d, vh)) / norm(d);
    if !(5e-8..=2e-3).contains(&tilt) {
        return Err(Reject::Class);
    }
    let case = exact_quadric_case(&q, rv(o), d)?;
    Ok(want(case, &["two"])?.tilted(tilt))
}

fn quadric_alpha_near_zero_paraboloid(g: &mut Rng) -> Result<Cand, Reject> {
    let mut q = elliptic_xy(g);
    q.l = [0.0, 0.0, -g.sign() * g.log_uniform(0.25, 4.0)];
    let c = [0; 3].map(|_| g.range(-10.0, 10.0));
    let q = q.translate(c);
    let o = add(
        c,
        [g.range(-3.0, 3.0), g.range(-3.0, 3.0), g.range(-50.0, 50.0)],
    );
    let perm = Perm::random(g);
    let (d, tilt) = tilted_z(g);
    let case = quadric_case(rv(perm.v(o)), perm.v(d), q.permute(&perm).rounded());
    Ok(want(case, &["two"])?.tilted(tilt))
}

fn quadric_coefficient_spread(g: &mut Rng) -> Result<Cand, Reject> {
    let s = [0; 3].map(|_| g.log_uniform(1e-4, 1e4));
    // Ellipsoid, hyperboloid of one sheet, of two sheets: 0, 1 or 2
    // negative coefficients, on randomly chosen axes.
    let negatives = g.int(0, 2) as usize;
    let mut sorted = [1.0; 3];
    for x in sorted.iter_mut().take(negatives) {
        *x = -1.0;
    }
    let pi = Perm::random(g).pi;
    let signs = [0, 1, 2].map(|i| sorted[pi[i]]);
    let a = [0, 1, 2].map(|i| signs[i] / (s[i] * s[i]));
    let q = Quad::form([[a[0], 0.0, 0.0], [0.0, a[1], 0.0], [0.0, 0.0, a[2]]]);
    let q = Quad { j: -1.0, ..q };
    let c = if g.chance(0.5) {
        [0, 1, 2].map(|i| s[i] * g.range(-2.0, 2.0))
    } else {
        [0.0; 3]
    };
    let q = q.translate(c);
    // Aim in the coordinates where the surface has unit scale.
    let yo = mul(g.unit_vec(), g.range(1.2, 5.0));
    let yt = mul(g.unit_vec(), g.range(0.0, 0.8));
    let o = [0, 1, 2].map(|i| c[i] + s[i] * yo[i]);
    let dv = [0, 1, 2].map(|i| s[i] * (yt[i] - yo[i]));
    let m = dv.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    let d = mul(dv, g.log_uniform(0.5, 2.0) / m);
    want(quadric_case(rv(o), rv(d), q.rounded()), &["two"])
}

fn quadric_cone_apex(g: &mut Rng) -> Result<Cand, Reject> {
    let (v, u1, u2) = orth_basis(g, 0.4);
    let lam = [0; 3].map(|_| g.int(1, 3) as f64);
    let q = Quad::sum_of_squares(&[(lam[0], u1), (lam[1], u2), (-lam[2], v)]);
    let d = g.nonzero_ivec(-4, 4);
    if q.eval(d) == 0.0 {
        return Err(Reject::Class);
    }
    let apex = g.ivec(-8, 8);
    let t = g.dyadic(12, 2);
    let f = Frame::random(g, 6);
    let qf = f.quad(&q.translate(apex));
    let o = f.point(sub(apex, mul(d, t)));
    let case = exact_quadric_case(&qf, o, f.dir(d))?;
    Ok(Cand::expect(case, "one", vec![f.t(t) as f32]))
}

/// Pythagorean triples `(a, b, h)`, `a² + b² = h²`.
const TRIPLES: [[f64; 3]; 5] = [
    [1.0, 0.0, 1.0],
    [3.0, 4.0, 5.0],
    [5.0, 12.0, 13.0],
    [8.0, 15.0, 17.0],
    [7.0, 24.0, 25.0],
];

fn quadric_line_on_surface(g: &mut Rng) -> Result<Cand, Reject> {
    let tri = {
        let t = g.pick(&TRIPLES);
        let (a, b) = if g.chance(0.5) {
            (t[0], t[1])
        } else {
            (t[1], t[0])
        };
        [a * g.sign(), b * g.sign(), t[2]]
    };
    // (quadric, a point on the line, its direction)
    let (q, p, d) = match g.int(0, 3) {
        0 => {
            // Ruling of h²sy²x² + h²sx²y² − R²w²sx²sy²z² = R²w²h²sx²sy²
            // through the throat point (sx R p, sy R q, 0).
            let (r0, h) = (g.int(1, 3) as f64, g.int(1, 6) as f64);
            let (sx, sy) = (g.int(1, 2) as f64, g.int(1, 2) as f64);
            let w2 = tri[2] * tri[2];
            let mut q = Quad::form([
                [h * h * sy * sy, 0.0, 0.0],
                [0.0, h * h * sx * sx, 0.0],
                [0.0, 0.0, -r0 * r0 * w2 * sx * sx * sy * sy],
            ]);
            q.j = -r0 * r0 * w2 * h * h * sx * sx * sy * sy;
            let p = [sx * r0 * tri[0], sy * r0 * tri[1], 0.0];
            let d = [-sx * r0 * tri[1], sy * r0 * tri[0], h * g.sign()];
            (q, p, d)
        }
        1 => {
            // Generator of an elliptic cylinder with an integer axis.
            let (v, u1, u2) = orth_basis(g, 0.3);
            let mut q = Quad::sum_of_squares(&[(g.int(1, 3) as f64, u1), (g.int(1, 3) as f64, u2)]);
            let p = g.ivec(-3, 3);
            q.j = -q.eval(p);
            if q.j == 0.0 {
                return Err(Reject::Class);
            }
            (q, p, v)
        }
        2 => {
            // Ruling of the cone k1²x² + k2²y² = k3²z² through its apex.
            let k = [0; 3].map(|_| g.int(1, 3) as f64);
            let q = Quad::form([
                [k[0] * k[0], 0.0, 0.0],
                [0.0, k[1] * k[1], 0.0],
                [0.0, 0.0, -k[2] * k[2]],
            ]);
            let d = [
                tri[0] * k[1] * k[2],
                tri[1] * k[0] * k[2],
                tri[2] * k[0] * k[1],
            ];
            (q, [0.0; 3], d)
        }
        _ => {
            // Ruling x = mk of the saddle 2xy − 2mz = 0: (mk, y0 + t, k(y0 + t)).
            let (m, k, y0) = (
                g.nonzero_int(1, 4) as f64,
                g.int(-4, 4) as f64,
                g.int(-8, 8) as f64,
            );
            let mut q = Quad::form([[0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 0.0]]);
            q.l = [0.0, 0.0, -2.0 * m];
            (q, [m * k, y0, k * y0], [0.0, 1.0, k])
        }
    };
    debug_assert_eq!(q.eval(p), 0.0);
    let c = g.ivec(-6, 6);
    let f = Frame::random(g, 5);
    let qf = f.quad(&q.translate(c));
    let o = f.point(add(c, add(p, mul(d, g.int(-4, 4) as f64))));
    let case = exact_quadric_case(&qf, o, f.dir(mul(d, g.dyadic(3, 1))))?;
    Ok(Cand::expect(case, "all", vec![]))
}

/// `(n1·p − e1)(n2·p − e2)` as a quadric.
fn plane_product(n1: V, e1: f64, n2: V, e2: f64) -> Quad {
    let mut m = [[0.0; 3]; 3];
    for (i, row) in m.iter_mut().enumerate() {
        for (j, x) in row.iter_mut().enumerate() {
            *x = (n1[i] * n2[j] + n2[i] * n1[j]) / 2.0;
        }
    }
    Quad {
        m,
        l: sub(mul(n1, -e2), mul(n2, e1)),
        j: e1 * e2,
    }
}

fn quadric_plane_pair(g: &mut Rng) -> Result<Cand, Reject> {
    let q = match g.int(0, 3) {
        // x² − k²y² = (x − ky)(x + ky)
        0 => {
            let k = g.int(1, 4) as f64;
            plane_product([1.0, -k, 0.0], 0.0, [1.0, k, 0.0], 0.0)
        }
        // x² − e² = (x − e)(x + e)
        1 => {
            let e = g.int(1, 8) as f64;
            plane_product(axis(0), e, axis(0), -e)
        }
        // Two crossing integer planes.
        2 => {
            let n1 = reduce(g.nonzero_ivec(-4, 4));
            let n2 = reduce(g.nonzero_ivec(-4, 4));
            if is_zero(cross(n1, n2)) {
                return Err(Reject::Class);
            }
            plane_product(n1, g.int(-20, 20) as f64, n2, g.int(-20, 20) as f64)
        }
        // Two parallel integer planes.
        _ => {
            let n = reduce(g.nonzero_ivec(-4, 4));
            let (e1, e2) = (g.int(-20, 20) as f64, g.int(-20, 20) as f64);
            if e1 == e2 {
                return Err(Reject::Class);
            }
            plane_product(n, e1, n, e2)
        }
    };
    let f = Frame::random(g, 6);
    let qf = f.quad(&q.translate(g.ivec(-5, 5)));
    let o = g.cube(50.0);
    let d = rv(mul(g.unit_vec(), g.log_uniform(0.5, 2.0)));
    let case = exact_quadric_case(&qf, o, d)?;
    want(case, &["two"])
}

fn quadric_double_plane(g: &mut Rng) -> Result<Cand, Reject> {
    let n = reduce(g.nonzero_ivec(-4, 4));
    let e = g.int(-20, 20) as f64;
    let f = Frame::random(g, 6);
    let qf = f.quad(&plane_product(n, e, n, e));
    let o = g.cube(50.0);
    let d = rv(mul(g.unit_vec(), g.log_uniform(0.5, 2.0)));
    let case = exact_quadric_case(&qf, o, d)?;
    if exact_class(&case).0 != "one" {
        return Err(Reject::Class);
    }
    Ok(Cand::expect(case, "one", vec![]))
}

// ---------------------------------------------------------------------------
// Camera families.

fn camera_case(pos: V, dir: V, up: V, angle: f32, res: [u32; 2], pixel: [u32; 2]) -> Case {
    Case::Camera(
        CameraParams::new(f32v(pos), f32v(dir), f32v(up), angle, res),
        pixel,
    )
}

/// An up vector at least 0.1 rad away from `dir` (and from −dir).
fn random_up(g: &mut Rng, dir: V, lo: f64, hi: f64) -> V {
    let dh = unit(dir);
    loop {
        let u = g.unit_vec();
        if norm(cross(u, dh)) >= 0.1 {
            return rv(mul(u, g.log_uniform(lo, hi)));
        }
    }
}

/// A pixel coordinate in `0..res`: an edge, next to one, the centre, or
/// anywhere.
fn pixel(g: &mut Rng, res: u32) -> u32 {
    let p = match g.int(0, 6) {
        0 => 0,
        1 => 1,
        2 => res / 2,
        3 => (res - 1) / 2,
        4 => res.saturating_sub(2),
        5 => res - 1,
        _ => g.int(0, res as i64 - 1) as u32,
    };
    p.min(res - 1)
}

fn ordinary_camera(g: &mut Rng, dir: V, up: V, angle: f32, res: [u32; 2]) -> Case {
    let pos = rv(mul(g.unit_vec(), g.log_uniform(1e-3, 1e3)));
    let px = [pixel(g, res[0]), pixel(g, res[1])];
    camera_case(pos, dir, up, angle, res, px)
}

fn random_res(g: &mut Rng) -> [u32; 2] {
    [g.int(1, 4096) as u32, g.int(1, 4096) as u32]
}

fn camera_fov_range(g: &mut Rng) -> Result<Cand, Reject> {
    let angle = match g.int(0, 2) {
        0 => g.log_uniform(1e-3, 1.0),
        1 => PI - g.log_uniform(1e-3, 1.0),
        _ => g.range(1.0, PI - 1.0),
    } as f32;
    let dir = rv(mul(g.unit_vec(), g.log_uniform(0.1, 10.0)));
    let up = random_up(g, dir, 0.1, 10.0);
    let res = random_res(g);
    Ok(Cand::new(ordinary_camera(g, dir, up, angle, res)))
}

fn camera_res_65535(g: &mut Rng) -> Result<Cand, Reject> {
    let other = g.int(1, 65535) as u32;
    let res = match g.int(0, 2) {
        0 => [65535, other],
        1 => [other, 65535],
        _ => [65535, 65535],
    };
    let dir = rv(mul(g.unit_vec(), g.log_uniform(0.1, 10.0)));
    let up = random_up(g, dir, 0.1, 10.0);
    let angle = g.range(0.1, 3.0) as f32;
    Ok(Cand::new(ordinary_camera(g, dir, up, angle, res)))
}

fn camera_dir_near_up(g: &mut Rng) -> Result<Cand, Reject> {
    let uh = g.unit_vec();
    let up = rv(mul(uh, g.log_uniform(0.1, 10.0)));
    let theta = g.log_uniform(1e-6, 1e-3);
    let dh = add(uh, mul(g.perp(uh), theta));
    let dir = rv(mul(dh, g.sign() * g.log_uniform(0.1, 10.0)));
    // The angle between the lines of dir and up after rounding.
    let sin = norm(cross(dir, up)) / (norm(dir) * norm(up));
    if !(5e-7..=2e-3).contains(&sin) {
        return Err(Reject::Class);
    }
    let angle = g.range(0.1, 3.0) as f32;
    let res = random_res(g);
    Ok(Cand::new(ordinary_camera(g, dir, up, angle, res)))
}

fn camera_dir_scale(g: &mut Rng) -> Result<Cand, Reject> {
    let dir = rv(mul(g.unit_vec(), g.log_uniform(1e-20, 1e20)));
    let up = random_up(g, dir, 1e-3, 1e3);
    let angle = g.range(0.1, 3.0) as f32;
    let res = random_res(g);
    Ok(Cand::new(ordinary_camera(g, dir, up, angle, res)))
}

// ---------------------------------------------------------------------------
// Judging a candidate.

/// What the exact oracle says about a kept case.
struct Kept {
    line: String,
    class: &'static str,
    /// The largest root κ (infinite at a double root; 0 with no roots).
    kappa: f64,
    /// The scalar reference against the exact oracle.
    reference: Result<CaseReport, String>,
    tilt: Option<f64>,
    /// The largest of `quadric::condition` (roots found again in f64).
    kappa_f64: f64,
}

/// The exact oracle's own answer, judged by `check` (which computes the
/// margin and each root's κ).
fn self_report(case: &Case) -> CaseReport {
    let r = match case {
        Case::Sphere(ray, s) => {
            check::check_sphere(ray, s, sphere::exact::intersect(ray, s).expect("finite"))
        }
        Case::Plane(ray, p) => {
            check::check_plane(ray, p, plane::exact::intersect(ray, p).expect("finite"))
        }
        Case::Quadric(ray, q) => {
            check::check_quadric(ray, q, quadric::exact::intersect(ray, q).expect("finite"))
        }
        Case::Camera(p, [x, y]) => check::check_camera(p, [*x, *y], camera::exact::ray(p, *x, *y)),
    };
    r.expect("the exact answer passes its own check")
}

fn judge(fam: &Family, cand: &Cand) -> Result<Kept, Reject> {
    let case = &cand.case;
    if let Case::Camera(p, _) = case
        && p.build().is_err()
    {
        return Err(Reject::Range);
    }
    let (class, roots) = exact_class(case);
    if let Some(e) = &cand.expect {
        let bits = |r: &[f32]| r.iter().map(|t| t.to_bits()).collect::<Vec<_>>();
        assert_eq!(class, e.class, "{}: the construction is wrong", fam.name);
        if !e.roots.is_empty() {
            assert_eq!(bits(&roots), bits(&e.roots), "{}: roots", fam.name);
        }
    }
    if roots.iter().any(|t| !t.is_finite()) {
        return Err(Reject::Range);
    }
    let report = self_report(case);
    let kappa = report.roots.iter().map(|r| r.kappa).fold(0.0, f64::max);
    let exact_roots = cand.expect.as_ref().is_some_and(|e| !e.roots.is_empty());
    if fam.cond == Cond::Well && !exact_roots {
        let limit = if fam.kernel() == "quadric" {
            KAPPA_WELL_QUADRIC
        } else {
            KAPPA_WELL
        };
        if kappa.is_nan() || kappa > limit {
            return Err(Reject::Kappa);
        }
    }
    Ok(Kept {
        line: line(fam.name, case, cand.expect.as_ref()),
        class,
        kappa,
        reference: check::reference_case(case).map_err(|v| v.to_string()),
        tilt: cand.tilt,
        kappa_f64: match case {
            Case::Quadric(ray, q) => quadric::condition(ray, q).into_iter().fold(0.0, f64::max),
            _ => f64::NAN,
        },
    })
}

// ---------------------------------------------------------------------------
// Writing.

/// The exact decimal value of `x`, worked out from its bits, if it takes
/// at most 10 characters (small integers and short dyadic fractions such
/// as `-0.375`); it parses back to the same f32 exactly.
fn short_decimal(x: f32) -> Option<String> {
    let bits = x.to_bits();
    if bits == 0 {
        return Some("0".into());
    }
    if bits == 0x8000_0000 {
        return None; // −0 keeps its sign bit
    }
    let (e, f) = (((bits >> 23) & 0xff) as i32, (bits & 0x7f_ffff) as u128);
    if e == 0xff {
        return None;
    }
    // |x| = m · 2^exp, m odd.
    let (mut m, mut exp) = if e == 0 {
        (f, -149)
    } else {
        (f | 0x80_0000, e - 150)
    };
    while m & 1 == 0 {
        m >>= 1;
        exp += 1;
    }
    let digits = if exp >= 0 {
        if exp > 100 {
            return None;
        }
        (m << exp).to_string()
    } else {
        // m / 2^k = m·5^k / 10^k.
        let k = (-exp) as usize;
        if k > 20 {
            return None;
        }
        let d = format!("{:0>width$}", m * 5u128.pow(k as u32), width = k + 1);
        format!("{}.{}", &d[..d.len() - k], &d[d.len() - k..])
    };
    let s = if bits >> 31 == 1 {
        format!("-{digits}")
    } else {
        digits
    };
    (s.len() <= 10).then_some(s)
}

/// A number: its exact short decimal, or else its bits as `"0x…"`.
fn num(x: f32) -> String {
    short_decimal(x).unwrap_or_else(|| format!("\"{:#010x}\"", x.to_bits()))
}

fn nums(xs: &[f32]) -> String {
    let parts: Vec<String> = xs.iter().map(|&x| num(x)).collect();
    format!("[{}]", parts.join(","))
}

fn v3(v: Vec3) -> String {
    nums(&v.to_array())
}

/// The fields after `kind` and `family`.
fn body(case: &Case) -> String {
    match case {
        Case::Sphere(r, s) => format!(
            r#""origin":{},"dir":{},"center":{},"radius":{}"#,
            v3(r.origin),
            v3(r.dir),
            v3(s.center),
            num(s.radius)
        ),
        Case::Plane(r, p) => format!(
            r#""origin":{},"dir":{},"point":{},"normal":{}"#,
            v3(r.origin),
            v3(r.dir),
            v3(p.point),
            v3(p.normal)
        ),
        Case::Quadric(r, q) => format!(
            r#""origin":{},"dir":{},"coeffs":{}"#,
            v3(r.origin),
            v3(r.dir),
            nums(&q.coeffs)
        ),
        Case::Camera(p, px) => format!(
            r#""position":{},"dir":{},"up":{},"angle":{},"res":[{},{}],"pixel":[{},{}]"#,
            v3(p.position),
            v3(p.dir),
            v3(p.up),
            num(p.angle),
            p.res[0],
            p.res[1],
            px[0],
            px[1]
        ),
    }
}

fn line(family: &str, case: &Case, expect: Option<&Expect>) -> String {
    let mut s = format!(
        r#"{{"kind":"{}","family":"{family}",{}"#,
        case.kind(),
        body(case)
    );
    if let Some(e) = expect {
        write!(s, r#","expect":{{"class":"{}""#, e.class).unwrap();
        if !e.roots.is_empty() {
            let bits: Vec<String> = e
                .roots
                .iter()
                .map(|t| format!("\"{:#010x}\"", t.to_bits()))
                .collect();
            write!(s, r#","roots_bits":[{}]"#, bits.join(",")).unwrap();
        }
        s.push('}');
    }
    s.push('}');
    // Parsed back, the line must give the same bits.
    let parsed = parse_line(&s).unwrap_or_else(|e| panic!("{s}: {e}"));
    assert_eq!(body(&parsed.case), body(case), "{s}");
    assert_eq!(parsed.family.as_deref(), Some(family));
    s
}

struct Stats {
    rejected: BTreeMap<Reject, usize>,
    classes: BTreeMap<&'static str, usize>,
    kappa_max: f64,
    ref_worst_ulps: u64,
    ref_violations: Vec<String>,
    by_tilt: BTreeMap<usize, TiltRow>,
}

/// The α ≈ 0 cases of one decade of tilt.
#[derive(Default)]
struct TiltRow {
    n: usize,
    kappa: f64,
    kappa_f64: f64,
    ref_ulps: u64,
}

const TILT_DECADES: [&str; 4] = [
    "1e-7 to 1e-6",
    "1e-6 to 1e-5",
    "1e-5 to 1e-4",
    "1e-4 to 1e-3",
];

fn decade(t: f64) -> usize {
    [1e-6, 1e-5, 1e-4].iter().filter(|&&x| t >= x).count()
}

fn generate(fam: &Family, n: usize) -> (Vec<String>, Stats) {
    let mut g = Rng::new(fam.seed);
    let mut lines = Vec::with_capacity(n);
    let mut st = Stats {
        rejected: REJECTS.iter().map(|r| (*r, 0)).collect(),
        classes: BTreeMap::new(),
        kappa_max: 0.0,
        ref_worst_ulps: 0,
        ref_violations: Vec::new(),
        by_tilt: BTreeMap::new(),
    };
    let mut tries = 0;
    while lines.len() < n {
        tries += 1;
        assert!(tries < 2000 * n, "{}: cannot find {n} cases", fam.name);
        let kept = (fam.make)(&mut g).and_then(|c| judge(fam, &c));
        let k = match kept {
            Ok(k) => k,
            Err(r) => {
                *st.rejected.get_mut(&r).expect("every reason") += 1;
                continue;
            }
        };
        *st.classes.entry(k.class).or_default() += 1;
        st.kappa_max = st.kappa_max.max(k.kappa);
        let ref_ulps = k
            .reference
            .as_ref()
            .map_or(0, |r| r.max_root_ulps().unwrap_or(0));
        if let Some(t) = k.tilt {
            let row = st.by_tilt.entry(decade(t)).or_default();
            row.n += 1;
            row.kappa = row.kappa.max(k.kappa);
            row.kappa_f64 = row.kappa_f64.max(k.kappa_f64);
            row.ref_ulps = row.ref_ulps.max(ref_ulps);
        }
        match &k.reference {
            Ok(_) => st.ref_worst_ulps = st.ref_worst_ulps.max(ref_ulps),
            Err(v) => st.ref_violations.push(format!("{}: {v}", k.line)),
        }
        lines.push(k.line);
    }
    (lines, st)
}

fn families_json() -> String {
    let mut s = String::from("[\n");
    for (i, f) in FAMILIES.iter().enumerate() {
        let q = |x: &str| serde_json::to_string(x).expect("a string");
        write!(
            s,
            "  {{\"family\": {}, \"kernel\": {}, \"conditioning\": {}, \"why\": {}}}",
            q(f.name),
            q(f.kernel()),
            q(f.cond.name()),
            q(f.why)
        )
        .unwrap();
        s.push_str(if i + 1 < FAMILIES.len() { ",\n" } else { "\n" });
    }
    s.push_str("]\n");
    s
}

fn sci(x: f64) -> String {
    if x.is_infinite() {
        "∞".into()
    } else if x == 0.0 {
        "0".into()
    } else {
        format!("{x:.1e}")
    }
}

const README_HEAD: &str = "# Stiff and extreme cases

The catalogue of stiff and extreme inputs for every kernel: 256 cases per
family, one `rayoracle eval` case line each, in `sphere.jsonl`,
`plane.jsonl`, `quadric.jsonl` and `camera.jsonl`, every line with
`\"family\":\"<kernel>/<name>\"`. `families.json` lists the families in a
fixed order with their kernel, conditioning and why each is stiff.

Everything here is written by `examples/stiff_catalogue.rs`; do not edit by
hand. Regenerate, byte for byte, with

```text
cargo run --example stiff_catalogue
```

and check that the committed files are what the generator writes with
`cargo run --example stiff_catalogue -- --check`. `tests/stiff_catalogue.rs`
checks the committed data without regenerating it. To evaluate a family:

```text
grep '\"sphere/far-tiny\"' fixtures/stiff/sphere.jsonl | rayoracle eval -
```

## How the cases are made

Each family draws from its own `SmallRng::seed_from_u64(seed)` (rand 0.9),
turned into floats with `+ − × ÷ √` only, so no platform's `libm` can change
a bit. Numbers are written as their exact decimal value when that is short
(small integers, dyadics such as `-0.375`) and otherwise as their f32 bits
(`\"0x3f800000\"`); every line is parsed back and must give the same bits.
The exact constructions (tangents, in-plane rays, α = 0, lines on the
surface, apexes, double planes) are built in small integers and dyadics,
scaled by powers of two and permuted, so they stay exact, and carry an
`\"expect\"` with the class (and the root bits where they are known by
construction, not from the oracle).

Candidates are reject-sampled: a case is kept only if

* the exact oracle gives the class the family wants (and, where it says so,
  a geometric condition holds: a miss by at least 0.1 R, the origin on the
  intended side of the surface, the tilt surviving rounding);
* a camera is inside its stated domain (`camera::in_domain`) and builds;
* for a **well**-conditioned family, every root's condition number κ, as
  `rayoracle::check` evaluates it at the exact roots, is at most 2¹⁸
  (plane, sphere) or 2¹⁶ (quadric); or the case is an exact construction
  with an `expect` (an exact tangent is a double root, with κ = ∞).

The plane, sphere and quadric kernels are correctly rounded, so every case
of every family, well or **ill**, is judged the same way: the exact class
and the oracle's bits. *ill* says that the roots, the class or (camera) the
basis move a lot when an input moves by one ulp: a kernel in plain
floating point gets these wrong. The camera has no κ: every camera case is
judged by the 4-ulp component bound.

## What the data showed

* `sphere/huge-near` is ill-conditioned, not well: one ulp of R or of the
  centre moves the surface by R·2⁻²⁴, far more than the origin's height h,
  so the near root has κ ≈ R/h, up to 1.2e10 here. Its far root is fine.
* `sphere/far-tiny`: the roots have κ < 5, but from a distance of 4e5 to
  1e6 on the textbook discriminant `b² − ac` loses the margin `aΔ` to
  cancellation (its rounding error scales with |f|², not R²).
* `sphere/near-surface-*`: the near root's κ is at least 1/δ (δ the
  relative height), whatever the kernel does, so δ starts at 2⁻¹⁶ for the
  family to stay within 2 ulps.
* The α ≈ 0 cylinder of the issue splits in two (below): axis-aligned, κ
  does not depend on the tilt; off the coordinate axes, κ grows like 1/θ²
  and the family is ill.
* `quadric/alpha-zero-paraboloid` loses a third of its candidates to κ: for a
  rotated paraboloid, β's terms `2·M o·d` cancel exactly (M d = 0), and the
  term-wise κ that `check` uses counts them.
* The scalar reference reproduces every exact tangent, every cone apex
  (class one, exact root), every in-plane ray and every line on a surface,
  and every root of `quadric/double-plane` (random rays, inexact t).
";

const README_ALPHA: &str = "
## α ≈ 0: condition numbers by tilt

`quadric::condition` finds the roots again in f64; `check` evaluates the
same κ at the exact roots. For the axis-aligned cylinder and paraboloid κ
does not depend on the tilt θ: α ≈ θ² has no cancelling terms, and what κ
there is comes from the off-centre γ terms. For the cylinder off the
coordinate axes α is a difference of O(1) terms, and κ grows roughly like
1/θ²; below θ ≈ 1e-6, `quadric::condition`'s own f64 α has lost digits and
it overstates κ. The reference is correctly rounded whatever κ is.

";

fn readme(stats: &[(&Family, Stats)]) -> String {
    let mut s = String::from(README_HEAD);
    s.push_str("\n## The families\n\n");
    s.push_str("| family | kernel | conditioning | why |\n|---|---|---|---|\n");
    for (f, _) in stats {
        writeln!(
            s,
            "| `{}` | {} | {} | {} |",
            f.name,
            f.kernel(),
            f.cond.name(),
            f.why.replace('|', "\\|")
        )
        .unwrap();
    }
    s.push_str(
        "\n## What the exact oracle says\n\n\
         Written by the generator from the kept cases. *Rejected* counts the \
         candidates thrown away, by reason: the exact class was not the one \
         wanted (or a geometric condition checked with the exact oracle \
         failed), outside the kernel's domain, a root κ above the limit of a \
         well-conditioned family, not representable. *κ max* is the largest \
         root condition number as `rayoracle::check` evaluates it (∞ at a \
         double root).\n\n",
    );
    s.push_str(
        "| family | cases | exact classes | rejected: class / domain / κ / range | κ max |\n|---|---|---|---|---|\n",
    );
    for (f, st) in stats {
        let classes: Vec<String> = st.classes.iter().map(|(c, n)| format!("{c} {n}")).collect();
        let rej: Vec<String> = REJECTS.iter().map(|r| st.rejected[r].to_string()).collect();
        let kappa = if f.kernel() == "camera" {
            "–".to_string()
        } else {
            sci(st.kappa_max)
        };
        writeln!(
            s,
            "| `{}` | {} | {} | {} | {} |",
            f.name,
            st.classes.values().sum::<usize>(),
            classes.join(", "),
            rej.join(" / "),
            kappa
        )
        .unwrap();
    }
    s.push_str(README_ALPHA);
    s.push_str(
        "| family | tilt (rad) | cases | κ max (check, exact roots) | κ max (`quadric::condition`) | reference worst ulps |\n|---|---|---|---|---|---|\n",
    );
    for (f, st) in stats {
        for (dec, row) in &st.by_tilt {
            writeln!(
                s,
                "| `{}` | {} | {} | {} | {} | {} |",
                f.name,
                TILT_DECADES[*dec],
                row.n,
                sci(row.kappa),
                sci(row.kappa_f64),
                row.ref_ulps
            )
            .unwrap();
        }
    }
    s
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let check_only = args.iter().any(|a| a == "--check");
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("fixtures/stiff");
    let mut files: BTreeMap<&str, String> = BTreeMap::new();
    let mut stats = Vec::new();
    println!(
        "{:<38} {:>5} {:>22} {:>9} {:>9}",
        "family", "cases", "rejected c/d/k/r", "kappa max", "ref ulps"
    );
    for f in FAMILIES {
        let (lines, st) = generate(f, N);
        let file = files.entry(f.kernel()).or_default();
        for l in &lines {
            file.push_str(l);
            file.push('\n');
        }
        let rej: Vec<String> = REJECTS.iter().map(|r| st.rejected[r].to_string()).collect();
        println!(
            "{:<38} {:>5} {:>22} {:>9} {:>9}",
            f.name,
            lines.len(),
            rej.join("/"),
            sci(st.kappa_max),
            st.ref_worst_ulps
        );
        for v in &st.ref_violations {
            println!("  reference violation: {v}");
        }
        stats.push((f, st));
    }
    let mut out: Vec<(String, String)> = files
        .into_iter()
        .map(|(k, v)| (format!("{k}.jsonl"), v))
        .collect();
    out.push(("families.json".into(), families_json()));
    out.push(("README.md".into(), readme(&stats)));
    let mut differ = 0;
    for (name, text) in &out {
        let path = dir.join(name);
        if check_only {
            let old = std::fs::read_to_string(&path).unwrap_or_default();
            if old != *text {
                println!("{} differs from what the generator writes", path.display());
                differ += 1;
            }
        } else {
            std::fs::create_dir_all(&dir).expect("fixtures/stiff");
            std::fs::write(&path, text).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
        }
    }
    let total: usize = out.iter().map(|(_, t)| t.len()).sum();
    println!("{} files, {total} bytes", out.len());
    if differ > 0 {
        std::process::exit(1);
    }
}
