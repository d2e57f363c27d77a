//! The camera oracle: each direction component correctly rounded, by Ziv's
//! strategy over the rigorous enclosures of [`super::tan`].
//!
//! # The exact definition
//!
//! With `D = dir`, `X = D × up`, `Y = D × X` (exact dyadic vectors: products
//! and sums of `f32`), `focus = |D|`, `h = tan(angle/2)` (the real tangent
//! of half the `f32` angle, in radians) and the pixel numerators
//! `nx = 2X + 1 − resX`, `ny = 2Y + 1 − resY` (exact integers), the module
//! formulas give
//!
//! ```text
//! u·xᵢ + v·yᵢ = focus · h · Bᵢ / resY,   Bᵢ = nx·Xᵢ/|X| + ny·Yᵢ/|Y|
//! ```
//!
//! (`u·aspect = nx/resY`, and `Y/|Y|` is `ŷ` since `D × x̂ = (D × X)/|X|`).
//! Component `i` of the ray direction is the real number
//! `cᵢ = Dᵢ + focus·h·Bᵢ/resY`, rounded once to `f32`, to nearest, ties to
//! even, overflowing to ±∞. Where `Bᵢ = 0`, `cᵢ = Dᵢ` is returned as the
//! `f32` `dirᵢ` itself, the sign of a zero included.
//!
//! # Why Ziv's strategy ends
//!
//! An enclosure of `cᵢ` at `p` bits decides the rounding once it lies inside
//! the interval an `f32` owns ([`super::tan::decide`]); doubling `p` shrinks
//! it around `cᵢ`, so this happens unless `cᵢ` is a midpoint between two
//! `f32`s, the overflow threshold, or 0: dyadic rationals all. It never is
//! where `Bᵢ ≠ 0`. The half angle `a = angle/2` is a nonzero rational, so by
//! the Lindemann–Weierstrass theorem `e^{2ia}` is transcendental; were
//! `h = tan a` algebraic, `e^{2ia} = (1 + ih)/(1 − ih)` would be too. So `h`
//! is transcendental, while `focus` (a square root of a rational) and `Bᵢ`
//! (rationals and square roots of rationals) are algebraic: a nonzero
//! `focus·Bᵢ/resY` times `h` is transcendental, and so is `cᵢ`, never a
//! rational. `Bᵢ = 0` is decided exactly first: `nx·Xᵢ·|Y| = −ny·Yᵢ·|X|`
//! holds when both sides are 0, or when they have opposite-signed factors
//! `nx·Xᵢ` and `ny·Yᵢ` and equal squares `(nx·Xᵢ)²·|Y|² = (ny·Yᵢ)²·|X|²`,
//! all exact dyadics.
//!
//! The basis `x`, `y` ([`super::Camera`]) is correctly rounded the same way:
//! `xᵢ = resX·focus·h·Xᵢ/(resY·|X|)` is 0 where `Xᵢ = 0` and transcendental
//! elsewhere.
//!
//! ```
//! use rayoracle::camera::{CameraParams, exact::ray};
//! use glam::Vec3;
//! let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [3, 3]);
//! assert_eq!(ray(&p, 1, 1).unwrap().dir, -Vec3::Z);
//! // tan(1/2)·2/3 = 0.3642016598958603…, correctly rounded.
//! assert_eq!(ray(&p, 2, 1).unwrap().dir.x, 0.36420166);
//! ```

use super::tan::{Fx, Iv, decide, rsqrt, sqrt, tan_half};
use super::{CameraError, CameraParams};
use crate::Ray;
use crate::exact::memo::{Memo, remembered};
use core::cell::RefCell;
use glam::Vec3;

/// The first precision tried, in bits; each retry doubles it.
pub const FIRST_BITS: u32 = 48;

/// A component of a pixel: `(i, nx, ny)`.
type Pixel = (usize, i64, i64);

/// A camera's exact dyadic data.
#[derive(Clone, Debug)]
pub struct Exact {
    dir: [f32; 3],
    d: [Fx; 3],
    x: [Fx; 3],
    y: [Fx; 3],
    nx: Fx,
    ny: Fx,
    nd: Fx,
    angle: f32,
    res: [u32; 2],
    /// The finer enclosures Ziv's loops have asked for: `(p, approx(p))`.
    finer: core::cell::RefCell<Vec<(u32, Approx)>>,
    /// The components that took more than the first enclosure:
    /// `((i, nx, ny), cᵢ)`, the last few.
    hard: core::cell::RefCell<Vec<(Pixel, f32)>>,
}

fn cross(a: &[Fx; 3], b: &[Fx; 3]) -> [Fx; 3] {
    let c = |i: usize, j: usize| a[i].mul(&b[j]).sub(&a[j].mul(&b[i]));
    [c(1, 2), c(2, 0), c(0, 1)]
}

fn norm2(a: &[Fx; 3]) -> Fx {
    a.iter().fold(Fx::zero(), |s, c| s.add(&c.mul(c)))
}

/// The enclosures, at one precision, of what every component needs.
#[derive(Clone, Debug)]
pub struct Approx {
    /// `xᵢ/resX` and `yᵢ/resY` ([`Exact::unit_basis`]): `focus·h/resY`
    /// times `Xᵢ/|X|` and `Yᵢ/|Y|`.
    unit: [(Iv, Iv); 3],
    /// `unit` in `f64` ([`Iv64`]), where every end is zero or has its
    /// exponent within ±900 and subnormals work.
    unit64: Option<[(Iv64, Iv64); 3]>,
    p: u32,
}

/// An enclosure `[lo, hi]` in `f64`, every operation rounded outward: a
/// sum or product rounded to nearest is within half an ulp of the exact
/// one (within `2⁻¹⁰⁷⁵` where it is subnormal, and exact for a sum that
/// is), so one step of `next_down` (`next_up`) from it is a lower (upper)
/// bound. This holds where subnormals are not flushed
/// ([`crate::exact::expansion::subnormals_work`]), and for finite ends.
#[derive(Clone, Copy, Debug)]
struct Iv64 {
    lo: f64,
    hi: f64,
}

impl Iv64 {
    /// The outward `f64` enclosure of `x`, for ends that are 0 or have
    /// their exponent within ±900: [`Fx::to_f64`] truncates to 60 bits and
    /// rounds once to nearest, within 0.52 ulp of the end, so two ulps
    /// outward bound it.
    fn of(x: &Iv) -> Option<Iv64> {
        let end = |f: &Fx, out: fn(f64) -> f64| match f.signum() {
            0 => Some(0.0),
            _ if (-900..=900).contains(&f.exponent()) => Some(out(out(f.to_f64()))),
            _ => None,
        };
        Some(Iv64 {
            lo: end(&x.lo, f64::next_down)?,
            hi: end(&x.hi, f64::next_up)?,
        })
    }

    /// `self · n`, for an integer `n` exact in `f64`.
    fn scale(self, n: f64) -> Iv64 {
        let (a, b) = (self.lo * n, self.hi * n);
        let (lo, hi) = if n >= 0.0 { (a, b) } else { (b, a) };
        Iv64 {
            lo: lo.next_down(),
            hi: hi.next_up(),
        }
    }

    fn add(self, o: Iv64) -> Iv64 {
        Iv64 {
            lo: (self.lo + o.lo).next_down(),
            hi: (self.hi + o.hi).next_up(),
        }
    }

    /// The `f32` every real in the enclosure rounds to, when both ends
    /// round to it: rounding is monotone, so every real between them does
    /// too. An enclosure that holds 0 (or a NaN end) decides nothing, as
    /// [`decide`] does not; a midpoint between two `f32`s inside it does
    /// not either (the ends round apart), and one at an end is never the
    /// real number itself (module docs).
    fn decide(self) -> Option<f32> {
        if !(self.lo > 0.0 || self.hi < 0.0) || self.lo > self.hi {
            return None;
        }
        let (a, b) = (self.lo as f32, self.hi as f32);
        (a.to_bits() == b.to_bits()).then_some(a)
    }
}

impl Exact {
    /// The exact data of a camera that [`CameraParams::build`] accepts
    /// (finite `dir` and `up`, `dir × up ≠ 0`, `angle ∈ (0, π)`).
    pub fn new(p: &CameraParams) -> Exact {
        let v = |v: Vec3| v.to_array().map(|c| Fx::from_f64(c as f64));
        let (d, up) = (v(p.dir), v(p.up));
        let x = cross(&d, &up);
        let y = cross(&d, &x);
        // |Y|² = |D|²|X|² − (D·X)² (Lagrange), and D·X = 0.
        let (nx, nd) = (norm2(&x), norm2(&d));
        Exact {
            dir: p.dir.to_array(),
            ny: nd.mul(&nx),
            nx,
            nd,
            d,
            x,
            y,
            angle: p.angle,
            res: p.res,
            finer: Default::default(),
            hard: Default::default(),
        }
    }

    /// Whether `dir × up = 0` exactly.
    pub fn parallel(&self) -> bool {
        self.nx.signum() == 0
    }

    /// The enclosures at `p` bits (for a camera that is not
    /// [`Exact::parallel`]).
    pub fn approx(&self, p: u32) -> Approx {
        let q = p + 8;
        // Cameras asked for in a row often share their angle.
        thread_local! {
            static TAN: RefCell<Memo<(u32, u32), Iv>> = const { RefCell::new(Memo::new()) };
        }
        let h = remembered(&TAN, (self.angle.to_bits(), q), || tan_half(self.angle, q));
        let focus = sqrt(&self.nd, q);
        let res_y = Iv::point(Fx::new(self.res[1], 0));
        let k = focus.mul(&h, q).div_pos(&res_y, q);
        let (ix, iy) = (rsqrt(&self.nx, q), rsqrt(&self.ny, q));
        let unit = |v: &Fx, inv: &Iv| Iv::point(v.clone()).round(q).mul(inv, q).mul(&k, q);
        let unit = [0, 1, 2].map(|i| (unit(&self.x[i], &ix), unit(&self.y[i], &iy)));
        let unit64 = (|| {
            let mut u = [(Iv64 { lo: 0.0, hi: 0.0 }, Iv64 { lo: 0.0, hi: 0.0 }); 3];
            for (o, (x, y)) in u.iter_mut().zip(&unit) {
                *o = (Iv64::of(x)?, Iv64::of(y)?);
            }
            Some(u)
        })()
        .filter(|_| crate::exact::expansion::subnormals_work());
        Approx { unit, unit64, p: q }
    }

    /// The enclosures at twice `a`'s precision, computed once per camera
    /// and kept.
    pub fn refine(&self, a: &Approx) -> Approx {
        let p = a.p * 2;
        if let Some((_, f)) = self.finer.borrow().iter().find(|f| f.0 == p) {
            return f.clone();
        }
        let f = self.approx(p);
        self.finer.borrow_mut().push((p, f.clone()));
        f
    }

    /// `nx·Xᵢ` and `ny·Yᵢ`, exactly.
    fn parts(&self, i: usize, nx: i64, ny: i64) -> (Fx, Fx) {
        (
            self.x[i].mul(&Fx::new(nx, 0)),
            self.y[i].mul(&Fx::new(ny, 0)),
        )
    }

    /// Whether `Bᵢ = 0` (see the module docs), exactly.
    pub fn b_is_zero(&self, i: usize, nx: i64, ny: i64) -> bool {
        let (a, b) = self.parts(i, nx, ny);
        match (a.signum(), b.signum()) {
            (0, 0) => true,
            (sa, sb) if sa == -sb && sa != 0 => a.mul(&a).mul(&self.ny) == b.mul(&b).mul(&self.nx),
            _ => false,
        }
    }

    /// An enclosure of `cᵢ` for the pixel numerators `nx`, `ny`.
    pub fn component(&self, a: &Approx, i: usize, nx: i64, ny: i64) -> Iv {
        let q = a.p;
        let (bx, by) = &a.unit[i];
        let n = |v: i64| Iv::point(Fx::new(v, 0));
        bx.mul(&n(nx), q)
            .add(&by.mul(&n(ny), q), q)
            .add(&Iv::point(self.d[i].clone()), q)
    }

    /// [`Exact::component`] in `f64` ([`Iv64`]), decided when it can be:
    /// the same enclosure, a few `f64` ulps wider, at the cost of a few
    /// floating-point operations (`|nx|`, `|ny|` below `2³⁴`, exact).
    fn component64(&self, a: &Approx, i: usize, nx: i64, ny: i64) -> Option<f32> {
        let (bx, by) = a.unit64?[i];
        let d = f64::from(self.dir[i]);
        bx.scale(nx as f64)
            .add(by.scale(ny as f64))
            .add(Iv64 { lo: d, hi: d })
            .decide()
    }

    /// Enclosures of `xᵢ/resX` and `yᵢ/resY`: the basis per unit of `nx`
    /// and `ny`.
    pub fn unit_basis(&self, a: &Approx, i: usize) -> (Iv, Iv) {
        a.unit[i].clone()
    }

    /// Component `i` at pixel numerators `nx`, `ny`, correctly rounded
    /// (Ziv's strategy from `a`, doubling the precision). `Bᵢ = 0` is
    /// tested only once the enclosure at `a` leaves the rounding undecided:
    /// where `Bᵢ = 0` and `dirᵢ ≠ 0` the enclosure holds the `f32` `dirᵢ`,
    /// not a midpoint, so whatever it decides is `dirᵢ`. The last 64
    /// components that needed more are kept with the camera's data (the
    /// reference asks for the same ones the oracle is then asked for).
    pub fn round_component(&self, a: &Approx, i: usize, nx: i64, ny: i64) -> f32 {
        if let Some(c) = self.component64(a, i, nx, ny) {
            return c;
        }
        if let Some(c) = decide(&self.component(a, i, nx, ny)) {
            return c;
        }
        let key = (i, nx, ny);
        if let Some(&(_, c)) = self.hard.borrow().iter().find(|h| h.0 == key) {
            return c;
        }
        let c = if self.b_is_zero(i, nx, ny) {
            self.dir[i]
        } else {
            ziv(
                &self.refine(a),
                |a| self.refine(a),
                |a| self.component(a, i, nx, ny),
            )
        };
        let mut hard = self.hard.borrow_mut();
        if hard.len() == 64 {
            hard.remove(0);
        }
        hard.push((key, c));
        c
    }

    /// The basis `(xᵢ, yᵢ)`, each correctly rounded (0 where `Xᵢ`, or
    /// `Yᵢ`, is).
    pub fn round_basis(&self, a: &Approx, i: usize) -> (f32, f32) {
        let rx = Fx::new(self.res[0], 0);
        let ry = Fx::new(self.res[1], 0);
        let one = |v: &Fx, r: &Fx, pick: fn((Iv, Iv)) -> Iv| {
            if v.signum() == 0 {
                return 0.0;
            }
            ziv(
                a,
                |a| self.refine(a),
                |a| pick(self.unit_basis(a, i)).mul(&Iv::point(r.clone()), a.p),
            )
        };
        (one(&self.x[i], &rx, |b| b.0), one(&self.y[i], &ry, |b| b.1))
    }
}

/// Ziv's loop: enclose at `a`'s precision, and at twice that until decided.
fn ziv(a: &Approx, finer: impl Fn(&Approx) -> Approx, enclose: impl Fn(&Approx) -> Iv) -> f32 {
    if let Some(c) = decide(&enclose(a)) {
        return c;
    }
    let mut a = finer(a);
    loop {
        if let Some(c) = decide(&enclose(&a)) {
            return c;
        }
        a = finer(&a);
    }
}

/// `2X + 1 − res`, exact.
pub fn numerator(p: u32, res: u32) -> i64 {
    2 * p as i64 + 1 - res as i64
}

/// `f(e, a)` with the exact data of `p` and its enclosures at
/// [`FIRST_BITS`]: those of the last camera asked for on this thread are
/// kept, since a camera is usually asked for several pixels in a row.
pub fn with_approx<R>(p: &CameraParams, f: impl FnOnce(&Exact, &Approx) -> R) -> R {
    type Key = ([u32; 3], [u32; 3], u32, [u32; 2]);
    thread_local! {
        static LAST: core::cell::RefCell<Option<(Key, Exact, Approx)>> =
            const { core::cell::RefCell::new(None) };
    }
    let bits = |v: Vec3| v.to_array().map(f32::to_bits);
    let key = (bits(p.dir), bits(p.up), p.angle.to_bits(), p.res);
    LAST.with_borrow_mut(|last| {
        if last.as_ref().is_none_or(|l| l.0 != key) {
            let e = Exact::new(p);
            let a = e.approx(FIRST_BITS);
            *last = Some((key, e, a));
        }
        let (_, e, a) = last.as_ref().expect("just filled");
        f(e, a)
    })
}

/// The ray for pixel `(px, py)`, each direction component correctly
/// rounded (see the module docs). Fails exactly when the reference's
/// construction does.
pub fn ray(p: &CameraParams, px: u32, py: u32) -> Result<Ray, CameraError> {
    p.build()?;
    Ok(Ray::new(p.position, direction(p, px, py)))
}

/// The direction of [`ray`], for parameters that [`CameraParams::build`]
/// accepts (the caller has built them once; for others it may panic).
pub(crate) fn direction(p: &CameraParams, px: u32, py: u32) -> Vec3 {
    let (nx, ny) = (numerator(px, p.res[0]), numerator(py, p.res[1]));
    Vec3::from_array(with_approx(p, |e, a| {
        [0, 1, 2].map(|i| e.round_component(a, i, nx, ny))
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn b_is_zero_at_the_centre_and_where_the_terms_cancel() {
        // dir = −z, up = y: X = (1, 0, 0), Y = (0, −1, 0).
        let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [3, 3]);
        let e = Exact::new(&p);
        assert!(e.b_is_zero(2, 5, 7));
        assert!(e.b_is_zero(0, 0, 7) && !e.b_is_zero(0, 1, 0));
        // dir = −z, up = (1, 1, 0): X = (1, −1, 0)·…, Y ∥ (1, 1, 0):
        // component x cancels where nx·X₀/|X| = −ny·Y₀/|Y|.
        let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::new(1.0, 1.0, 0.0), 1.0, [3, 3]);
        let e = Exact::new(&p);
        let (s0, s1) = (e.b_is_zero(0, 1, 1), e.b_is_zero(0, 1, -1));
        assert!(s0 != s1, "exactly one of the diagonals cancels x");
        assert!(!e.b_is_zero(0, 1, 2));
    }
}
