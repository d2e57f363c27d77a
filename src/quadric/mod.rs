//! Ray–quadric intersection, and the sphere as a quadric.
//!
//! # The derivation, as corrected
//!
//! The quadric is `A x² + B y² + C z² + D xy + E xz + F yz + G x + H y + I z +
//! J = 0`, coefficients in that order, `a…j` (stored as
//! [`Quadric::coeffs`]`[0..10]`). With `p = o + t d`:
//!
//! ```text
//! α = A dx² + B dy² + C dz² + D dx dy + E dx dz + F dy dz
//! β = 2(A ox dx + B oy dy + C oz dz) + D(ox dy + dx oy) + E(ox dz + dx oz)
//!     + F(oy dz + dy oz) + G dx + H dy + I dz
//! γ = A ox² + B oy² + C oz² + D ox oy + E ox oz + F oy oz + G ox + H oy + I oz + J
//! α t² + β t + γ = 0
//! ```
//!
//! Departures from the usual hand expansion:
//!
//! * it is easily written with `o t d_z` for `i t d_z`, and with β split
//!   across two braces; the β above is the correct one;
//! * `t = −β/2α ± √(β²/4α² − γ/α)` divides by α, which is 0 for a ray
//!   parallel to a cylinder's axis or along a paraboloid's axis, and cancels
//!   catastrophically when α ≈ 0. Here, after pbrt-v4's `Quadratic`:
//!   - `α = 0, β ≠ 0`: the linear root `−γ/β`, [`QuadricHit::One`];
//!   - `α = β = 0`: `γ = 0` means the line lies on the surface,
//!     [`QuadricHit::All`]; otherwise [`QuadricHit::None`];
//!   - otherwise the discriminant `β² − 4αγ` (with a proven bound on its
//!     error, [`stages`]), `q = −½(β + sign(β)√Δ)`, `t₀ = q/α`,
//!     `t₁ = γ/q`;
//! * the sphere written as a quadric is often solved as `((o−C)·d ±
//!   √…)/d²`; the sign of `(o−C)·d`
//!   is wrong (it must be `−(o−C)·d`), and `R²` is again missing its `d·d`
//!   factor. [`Quadric::from_sphere`] builds the sphere's coefficients, and
//!   the tests check that the quadric path classifies it like the sphere.
//!
//! # Accuracy
//!
//! [`reference::intersect`](mod@reference) and [`x4`] return the exact class
//! and every root correctly rounded to `f32`, for every finite input. The
//! [filter](stages) evaluates α, β, γ and the discriminant in f64 with the
//! error bound derived there and certifies what it decides (x4's first
//! pass, [`lanes`], does the same with its own bound); a double root, an
//! α that is 0 in exact arithmetic but not term by term, a line on the
//! surface or a root too close to a rounding boundary goes to the later
//! stages ([`stages::later`]), and what they leave to the exact oracle
//! ([`exact`]). In order:
//!
//! * where nothing looks exactly 0, α, β and γ in double words within
//!   about `u²` of their terms' magnitudes, without a grid, and the roots
//!   from them ([`stages::words`]): lines nearly parallel to a rotated
//!   cylinder's axis, whose α and β cancel;
//! * a perfect square, the double plane, whose `Δ` is 0 on every line,
//!   proved by exact products of its coefficients ([`square`]);
//! * the filter's own α̂, β̂ and γ̂ where a grid test proves them exact,
//!   with `Δ` checked for exactness (f64 arithmetic that proves itself
//!   exact), then summed exactly from them;
//! * α alone exact, with β and γ under the filter's bounds (or exact
//!   where the grid proves them so): lines nearly parallel to an axis
//!   ([`stages::tight`]);
//! * α, β and γ summed exactly in double words, on four AVX lanes where
//!   the CPU has AVX2 and FMA, then the same checks, and `Δ` in double
//!   words ([`stages::double_word`]).

pub mod exact;
pub mod lanes;
mod packed;
pub mod plain;
pub mod reference;
pub mod square;
pub mod stages;
pub mod textbook;
#[cfg(target_arch = "x86_64")]
mod words;
pub mod x4;

use crate::Ray;
use crate::hit::{Class, Intersection, Roots};
#[cfg(feature = "sphere")]
use crate::sphere::Sphere;

/// A quadric surface by its ten coefficients `[A, B, C, D, E, F, G, H, I,
/// J]` of `Ax² + By² + Cz² + Dxy + Exz + Fyz + Gx + Hy + Iz + J = 0`.
///
/// ```
/// use rayoracle::quadric::Quadric;
/// // The unit cylinder around the z axis: x² + y² − 1 = 0.
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// assert_eq!(cyl.coeffs[9], -1.0);
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Quadric {
    /// `[A, B, C, D, E, F, G, H, I, J]`, in the order of the equation.
    pub coeffs: [f32; 10],
}

impl Quadric {
    /// The quadric with these coefficients.
    ///
    /// ```
    /// use rayoracle::quadric::Quadric;
    /// assert_eq!(Quadric::new([0.0; 10]).coeffs, [0.0; 10]);
    /// ```
    pub const fn new(coeffs: [f32; 10]) -> Quadric {
        Quadric { coeffs }
    }

    /// The sphere as a quadric: `A = B = C = 1`, `G, H, I =
    /// −2C`, `J = |C|² − R²`, with `J` rounded once from its exact value.
    /// Returns the quadric and whether it is *exactly* the sphere (true when
    /// `J` is representable, e.g. for small integer centres and radii; a
    /// representable `J` whose f64 evaluation rounds is reported inexact).
    ///
    /// ```
    /// use rayoracle::{quadric::Quadric, sphere::Sphere};
    /// use glam::Vec3;
    /// let (q, exact) = Quadric::from_sphere(&Sphere::new(Vec3::new(1.0, 2.0, 3.0), 2.0));
    /// assert!(exact);
    /// assert_eq!(q.coeffs, [1.0, 1.0, 1.0, 0.0, 0.0, 0.0, -2.0, -4.0, -6.0, 10.0]);
    /// // |C|² = 4097² needs 25 bits, but J = 4097² − 4096² = 8193 is exact.
    /// let (q, exact) = Quadric::from_sphere(&Sphere::new(Vec3::new(4097.0, 0.0, 0.0), 4096.0));
    /// assert!(exact && q.coeffs[9] == 8193.0);
    /// // Neither |C|² nor R² is an f32 here, but J = 2·32772 is.
    /// let (q, exact) = Quadric::from_sphere(&Sphere::new(Vec3::new(16387.0, 0.0, 0.0), 16385.0));
    /// assert!(exact && q.coeffs[9] == 65544.0);
    /// // J = 2²⁴ + 1 − 0.25 is not an f32, and a non-finite radius has no J.
    /// assert!(!Quadric::from_sphere(&Sphere::new(Vec3::new(4097.0, 0.0, 0.0), 0.5)).1);
    /// assert!(!Quadric::from_sphere(&Sphere::new(Vec3::ONE, f32::INFINITY)).1);
    /// assert!(!Quadric::from_sphere(&Sphere::new(Vec3::ONE, f32::NAN)).1);
    /// ```
    #[cfg(feature = "sphere")]
    pub fn from_sphere(s: &Sphere) -> (Quadric, bool) {
        use crate::exact::{Dyadic, dyadic::dot, round_to_f32};
        let c = s.center.to_array();
        let neg2c = c.map(|x| -2.0 * x);
        let exact_ok = c.iter().all(|x| x.is_finite()) && s.radius.is_finite();
        // Fast rejection: the squares are exact in f64; unless their f64 sum
        // is an f32 the exact J is (almost always) not one either. The rare
        // J that is representable although its f64 sum rounded is reported
        // inexact, which only skips the checks that need exactness.
        let j64 =
            c.iter().map(|&x| x as f64 * x as f64).sum::<f64>() - s.radius as f64 * s.radius as f64;
        let exact_ok = exact_ok && (j64 as f32) as f64 == j64;
        let (j, j_exact) = if exact_ok {
            let cd = c.map(Dyadic::from_f32);
            let r = Dyadic::from_f32(s.radius);
            let jd = &dot(&cd, &cd) - &(&r * &r);
            let j = round_to_f32(|m| jd.cmp(m), jd.to_f64());
            (j, j.is_finite() && Dyadic::from_f32(j) == jd)
        } else {
            (f32::NAN, false)
        };
        let exact = j_exact && neg2c.iter().all(|x| x.is_finite());
        let q = [
            1.0, 1.0, 1.0, 0.0, 0.0, 0.0, neg2c[0], neg2c[1], neg2c[2], j,
        ];
        (Quadric::new(q), exact)
    }
}

/// The result over the whole line (`t ∈ ℝ`).
///
/// ```
/// use rayoracle::quadric::QuadricHit;
/// use rayoracle::hit::Intersection;
/// assert_eq!(QuadricHit::All.nearest(1.0, 2.0), Some(1.0));
/// assert_eq!(QuadricHit::One(3.0).class(), "one");
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum QuadricHit {
    /// No real solution.
    None,
    /// A double root, or the linear root when α = 0.
    One(f32),
    /// Two roots `t0 ≤ t1`.
    Two(f32, f32),
    /// The line lies on the surface: every `t`.
    All,
}

impl Intersection for QuadricHit {
    fn class(&self) -> Class {
        match self {
            QuadricHit::None => Class::None,
            QuadricHit::One(_) => Class::One,
            QuadricHit::Two(..) => Class::Two,
            QuadricHit::All => Class::All,
        }
    }
    fn roots(&self) -> Roots {
        match *self {
            QuadricHit::One(t) => Roots::one(t),
            QuadricHit::Two(t0, t1) => Roots::two(t0, t1),
            _ => Roots::none(),
        }
    }
    fn is_everywhere(&self) -> bool {
        matches!(self, QuadricHit::All)
    }
}

/// The terms of α, β, γ in f64 (each product of f32 inputs is exact in f64
/// only approximately; these are for bounds, not decisions).
pub(crate) fn terms(ray: &Ray, q: &Quadric) -> ([f64; 6], [f64; 12], [f64; 10]) {
    let k = q.coeffs.map(|x| x as f64);
    let o = ray.origin.to_array().map(|x| x as f64);
    let d = ray.dir.to_array().map(|x| x as f64);
    terms64(&k, &o, &d)
}

/// [`terms`] on f64 inputs.
fn terms64(k: &[f64; 10], o: &[f64; 3], d: &[f64; 3]) -> ([f64; 6], [f64; 12], [f64; 10]) {
    let alpha = [
        k[0] * d[0] * d[0],
        k[1] * d[1] * d[1],
        k[2] * d[2] * d[2],
        k[3] * d[0] * d[1],
        k[4] * d[0] * d[2],
        k[5] * d[1] * d[2],
    ];
    let beta = [
        2.0 * k[0] * o[0] * d[0],
        2.0 * k[1] * o[1] * d[1],
        2.0 * k[2] * o[2] * d[2],
        k[3] * o[0] * d[1],
        k[3] * d[0] * o[1],
        k[4] * o[0] * d[2],
        k[4] * d[0] * o[2],
        k[5] * o[1] * d[2],
        k[5] * d[1] * o[2],
        k[6] * d[0],
        k[7] * d[1],
        k[8] * d[2],
    ];
    let gamma = [
        k[0] * o[0] * o[0],
        k[1] * o[1] * o[1],
        k[2] * o[2] * o[2],
        k[3] * o[0] * o[1],
        k[4] * o[0] * o[2],
        k[5] * o[1] * o[2],
        k[6] * o[0],
        k[7] * o[1],
        k[8] * o[2],
        k[9],
    ];
    (alpha, beta, gamma)
}

/// The condition number of each root with respect to the *terms* of α, β
/// and γ: `Σ|∂t/∂termᵢ · termᵢ| / |t|`, each term weighted by its 3 rounded
/// factors. It is larger than the condition number with respect to the
/// inputs where terms cancel (γ = 25 − 1 for a unit cylinder seen from 5),
/// and it is the one that bounds an evaluation that is accurate relative to
/// each term, as the reference is. Infinite at a double root.
///
/// ```
/// use rayoracle::{Ray, quadric::{Quadric, condition}};
/// use glam::Vec3;
/// let cyl = Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]);
/// let k = condition(&Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::X), &cyl);
/// assert!(k[0] > 1.0 && k[0] < 100.0);
/// ```
pub fn condition(ray: &Ray, q: &Quadric) -> [f64; 2] {
    let (at, bt, gt) = terms(ray, q);
    let (a, b, g): (f64, f64, f64) = (at.iter().sum(), bt.iter().sum(), gt.iter().sum());
    let (sa, sb, sg): (f64, f64, f64) = (
        at.iter().map(|x| x.abs()).sum(),
        bt.iter().map(|x| x.abs()).sum(),
        gt.iter().map(|x| x.abs()).sum(),
    );
    let roots: Vec<f64> = if a == 0.0 {
        vec![-g / b]
    } else {
        let disc = b * b - 4.0 * a * g;
        if !(disc > 0.0) {
            return [f64::INFINITY; 2];
        }
        let qq = -0.5 * (b + disc.sqrt().copysign(b));
        let (r0, r1) = (qq / a, g / qq);
        vec![r0.min(r1), r0.max(r1)]
    };
    let k = |t: f64| {
        if t == 0.0 {
            return 0.0;
        }
        // p(t) = αt² + βt + γ; ∂t/∂α = −t²/p', ∂t/∂β = −t/p', ∂t/∂γ = −1/p'.
        // Each term of α carries 3 rounded factors, hence the weights.
        let dp = (2.0 * a * t + b).abs();
        (3.0 * sa * t * t + 3.0 * sb * t.abs() + 3.0 * sg) / (dp * t.abs())
    };
    let mut out = [f64::INFINITY; 2];
    for (i, t) in roots.iter().enumerate() {
        out[i] = k(*t);
    }
    if roots.len() == 1 {
        out[1] = out[0];
    }
    out
}

#[cfg(test)]
mod tests {
    use super::{Quadric, condition, terms};
    use crate::Ray;
    use glam::Vec3;

    /// `α t² + β t + γ` is the quadric at `o + t d`: on integer inputs (all
    /// exact in f64) with no 0, ±1 or 2, a misplaced factor in any of the 28
    /// terms changes the polynomial at one of these `t`.
    #[test]
    fn the_terms_are_the_quadric_along_the_ray() {
        let k = [3.0, 5.0, 7.0, 11.0, 13.0, 17.0, 19.0, 23.0, 29.0, 31.0];
        let (o, d) = ([11.0, -13.0, 3.0], [5.0, -3.0, 7.0]);
        let (a, b, g) = terms(
            &Ray::new(Vec3::from_array(o), Vec3::from_array(d)),
            &Quadric::new(k),
        );
        let (a, b, g): (f64, f64, f64) = (a.iter().sum(), b.iter().sum(), g.iter().sum());
        let k = k.map(f64::from);
        for t in [0.0, 1.0, -1.0, 3.0, -7.0] {
            let p = [0, 1, 2].map(|i| f64::from(o[i]) + t * f64::from(d[i]));
            let q = k[0] * p[0] * p[0]
                + k[1] * p[1] * p[1]
                + k[2] * p[2] * p[2]
                + k[3] * p[0] * p[1]
                + k[4] * p[0] * p[2]
                + k[5] * p[1] * p[2]
                + k[6] * p[0]
                + k[7] * p[1]
                + k[8] * p[2]
                + k[9];
            assert_eq!(a * t * t + b * t + g, q, "t = {t}");
        }
    }

    /// A unit cylinder seen from x = −5 along 3x: α = 9, β = −30, γ = 25 − 1
    /// (Σ|γ terms| = 26), so the roots are 4/3 and 2.
    fn cylinder() -> (Ray, Quadric) {
        (
            Ray::new(Vec3::new(-5.0, 0.0, 0.0), Vec3::new(3.0, 0.0, 0.0)),
            Quadric::new([1.0, 1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1.0]),
        )
    }

    /// κ(t) = 3(Σ|α|t² + Σ|β||t| + Σ|γ|) / (|2αt + β| |t|): at t = 4/3,
    /// (48 + 120 + 78) / (6 · 4/3) = 30.75; at t = 2, 366 / 12 = 30.5. The
    /// smaller root comes first.
    #[test]
    fn the_condition_numbers_by_hand() {
        let (r, q) = cylinder();
        let k = condition(&r, &q);
        assert!((k[0] - 30.75).abs() < 1e-12, "{k:?}");
        assert_eq!(k[1], 30.5);
        // Grazing: β² = 4αγ exactly, a double root with no finite number.
        let graze = Ray::new(Vec3::new(-5.0, 1.0, 0.0), Vec3::X);
        assert_eq!(condition(&graze, &q), [f64::INFINITY; 2]);
        // Also where β² = 4αγ in f64 (110² = 4·25·121) but the double root
        // −β/2α = 2.2 rounds, so p' there is not quite 0.
        let graze = Ray::new(Vec3::new(-11.0, 1.0, 0.0), Vec3::new(5.0, 0.0, 0.0));
        assert_eq!(condition(&graze, &q), [f64::INFINITY; 2]);
    }

    /// Roots 10⁻⁸ and 10⁸ (t² − 10⁸t + 1): the stable form keeps the small
    /// one, where `−β − √Δ` would cancel to almost nothing; κ ≈ 6 for both.
    #[test]
    fn the_small_root_of_a_stiff_quadratic_is_not_cancelled_away() {
        let q = Quadric::new([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, -1e8, 0.0, 0.0, 1.0]);
        let k = condition(&Ray::new(Vec3::ZERO, Vec3::X), &q);
        assert!(k.iter().all(|k| (k - 6.0).abs() < 1e-6), "{k:?}");
    }

    /// α = 0: the one root −γ/β, reported twice. For x = 2 from x = −1
    /// along 4x: β = 4, γ = −3, t = 3/4, κ = 3(4 · 3/4 + 3) / (4 · 3/4) = 6.
    #[test]
    fn a_linear_quadric_has_one_root_and_its_number_twice() {
        let plane = Quadric::new([0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, -2.0]);
        let r = Ray::new(Vec3::new(-1.0, 0.0, 0.0), Vec3::new(4.0, 0.0, 0.0));
        assert_eq!(condition(&r, &plane), [6.0, 6.0]);
        // At t = 0 (the origin on the surface) the relative number is 0.
        let on = Ray::new(Vec3::new(2.0, 0.0, 0.0), Vec3::X);
        assert_eq!(condition(&on, &plane), [0.0, 0.0]);
    }
}
