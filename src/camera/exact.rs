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
use crate::num::certify::{narrow_exact, widen_bits};
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
    /// their exponent within ±900: an end that is an `f64` exactly is
    /// kept; otherwise [`Fx::to_f64`] truncates to 60 bits and rounds once
    /// to nearest, within 0.52 ulp of the end, so two ulps outward bound
    /// it.
    fn of(x: &Iv) -> Option<Iv64> {
        let end = |f: &Fx, out: fn(f64) -> f64| match f.signum() {
            0 => Some(0.0),
            _ if (-900..=900).contains(&f.exponent()) => {
                Some(f.to_f64_exact().unwrap_or_else(|| out(out(f.to_f64()))))
            }
            _ => None,
        };
        Some(Iv64 {
            lo: end(&x.lo, f64::next_down)?,
            hi: end(&x.hi, f64::next_up)?,
        })
    }

    /// `self · o`: the least and greatest of the four rounded products of
    /// ends, one ulp outward (the rounded products keep the exact ones'
    /// order, so the least rounded one is within an ulp of the least); NaN
    /// ends where a product is NaN.
    fn mul(self, o: Iv64) -> Iv64 {
        let p = [
            self.lo * o.lo,
            self.lo * o.hi,
            self.hi * o.lo,
            self.hi * o.hi,
        ];
        if p.iter().any(|x| x.is_nan()) {
            return Iv64 {
                lo: f64::NAN,
                hi: f64::NAN,
            };
        }
        Iv64 {
            lo: p.iter().fold(f64::INFINITY, |m, &x| m.min(x)).next_down(),
            hi: p.iter().fold(f64::NEG_INFINITY, |m, &x| m.max(x)).next_up(),
        }
    }

    /// `self / d` for `d > 0`.
    fn div(self, d: f64) -> Iv64 {
        Iv64 {
            lo: (self.lo / d).next_down(),
            hi: (self.hi / d).next_up(),
        }
    }

    /// `1/self`, for `self > 0`.
    fn inv(self) -> Iv64 {
        Iv64 {
            lo: (1.0 / self.hi).next_down(),
            hi: (1.0 / self.lo).next_up(),
        }
    }

    /// `√self`, for `self ≥ 0` (a negative end gives NaN, which no
    /// caller lets through).
    fn sqrt(self) -> Iv64 {
        Iv64 {
            lo: self.lo.sqrt().next_down(),
            hi: self.hi.sqrt().next_up(),
        }
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
        let (a, b) = (narrow_exact(self.lo), narrow_exact(self.hi));
        (a.to_bits() == b.to_bits()).then_some(a)
    }
}

impl Exact {
    /// The exact data of a camera that [`CameraParams::build`] accepts
    /// (finite `dir` and `up`, `dir × up ≠ 0`, `angle ∈ (0, π)`).
    pub fn new(p: &CameraParams) -> Exact {
        let v = |v: Vec3| v.to_array().map(|c| Fx::from_f64(widen_bits(c.to_bits())));
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
    fn component64(&self, unit: &[(Iv64, Iv64); 3], i: usize, nx: i64, ny: i64) -> Option<f32> {
        let (bx, by) = unit[i];
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
        if let Some(c) = a.unit64.and_then(|u| self.component64(&u, i, nx, ny)) {
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
    with_kept(p, |k| f(&k.exact, k.approx()))
}

/// What is kept of the last camera asked for on this thread: its exact
/// data, its `f64` enclosures ([`unit64`]), and its enclosures at
/// [`FIRST_BITS`], formed when first asked for.
struct Kept {
    exact: Exact,
    unit64: Option<[(Iv64, Iv64); 3]>,
    approx: core::cell::OnceCell<Approx>,
}

impl Kept {
    fn approx(&self) -> &Approx {
        self.approx.get_or_init(|| self.exact.approx(FIRST_BITS))
    }
}

/// `f` with what is kept of camera `p` (formed if it is not the last one).
fn with_kept<R>(p: &CameraParams, f: impl FnOnce(&Kept) -> R) -> R {
    type Key = ([u32; 3], [u32; 3], u32, [u32; 2]);
    thread_local! {
        static LAST: RefCell<Option<(Key, Kept)>> = const { RefCell::new(None) };
    }
    let bits = |v: Vec3| v.to_array().map(f32::to_bits);
    let key = (bits(p.dir), bits(p.up), p.angle.to_bits(), p.res);
    LAST.with_borrow_mut(|last| {
        if last.as_ref().is_none_or(|l| l.0 != key) {
            let exact = Exact::new(p);
            let unit64 = unit64(&exact);
            let approx = Default::default();
            *last = Some((
                key,
                Kept {
                    exact,
                    unit64,
                    approx,
                },
            ));
        }
        let (_, kept) = last.as_ref().expect("just filled");
        f(kept)
    })
}

/// [`Approx`]'s `unit`, `xᵢ/resX` and `yᵢ/resY`, enclosed in `f64`
/// ([`Iv64`]) from the exact data, [`tan_half64`], and IEEE 754's
/// correctly rounded `√` and `/` (each result one ulp outward encloses
/// the exact one); `None` where an end is not finite (or an exact datum
/// is out of [`Iv64::of`]'s range), or subnormals are flushed.
fn unit64(e: &Exact) -> Option<[(Iv64, Iv64); 3]> {
    if !crate::exact::expansion::subnormals_work() || e.parallel() {
        return None;
    }
    let point = |x: &Fx| Iv64::of(&Iv::point(x.clone()));
    let h = tan_half64(e.angle)?;
    let focus = point(&e.nd)?.sqrt();
    let k = focus.mul(h).div(f64::from(e.res[1]));
    let (ix, iy) = (point(&e.nx)?.sqrt().inv(), point(&e.ny)?.sqrt().inv());
    let mut u = [(Iv64 { lo: 0.0, hi: 0.0 }, Iv64 { lo: 0.0, hi: 0.0 }); 3];
    for (i, o) in u.iter_mut().enumerate() {
        *o = (
            point(&e.x[i])?.mul(ix).mul(k),
            point(&e.y[i])?.mul(iy).mul(k),
        );
    }
    let finite = |v: &Iv64| v.lo.is_finite() && v.hi.is_finite();
    u.iter().all(|(x, y)| finite(x) && finite(y)).then_some(u)
}

/// `tan(angle/2)` enclosed in `f64`, for an angle in `(0, π)`, by the
/// series of [`super::tan`]'s module docs summed to 13 terms in `f64`.
///
/// With `t = angle/2` (exact) and `u = 2⁻⁵³`: `t²` is rounded once, and
/// each term is formed from the previous one by a product and a division
/// (the denominators exact), so the `k`-th is within `γ₃ₖ ≤ 39u` of its
/// exact value, relatively; the 13 additions err by at most `u` of the
/// sum of the terms' magnitudes each. Those magnitudes sum to at most
/// `cosh t < 2.51` (`sinh t / t` for `S`), so each sum is within
/// `52u·2.51·1.01 < 2⁻⁴⁵·⁹` of the 13-term partial sum, and the tail past
/// it (alternating, decreasing) is below its first term,
/// `t²⁸/28! < 2⁻⁷⁰`. So `S` and `C` are within `2⁻⁴⁵` of the sums
/// formed, and `t·S/C` is enclosed by rounding outward (`C > 2⁻²⁵`
/// for every such angle).
fn tan_half64(angle: f32) -> Option<Iv64> {
    let t = f64::from(angle) * 0.5;
    let t2 = t * t;
    let (mut s, mut c) = (1.0, 1.0);
    let (mut a, mut b) = (1.0f64, 1.0f64);
    for k in 1..=13u32 {
        a = a * t2 / f64::from((2 * k) * (2 * k + 1));
        b = b * t2 / f64::from((2 * k - 1) * (2 * k));
        if k % 2 == 1 {
            (s, c) = (s - a, c - b);
        } else {
            (s, c) = (s + a, c + b);
        }
    }
    let e = 1.0 / (1u64 << 45) as f64;
    let widen = |x: f64| Iv64 {
        lo: (x - e).next_down(),
        hi: (x + e).next_up(),
    };
    let (s, c) = (widen(s), widen(c));
    (c.lo > 0.0 && t > 0.0).then(|| Iv64 { lo: t, hi: t }.mul(s).mul(c.inv()))
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
    Vec3::from_array(with_kept(p, |k| {
        [0, 1, 2].map(|i| {
            let e = &k.exact;
            match k.unit64.and_then(|u| e.component64(&u, i, nx, ny)) {
                Some(c) => c,
                // What [`Exact::round_component`] gives where `Bᵢ = 0` (a
                // zero component, say), without the enclosures it needs
                // otherwise.
                None if e.b_is_zero(i, nx, ny) => e.dir[i],
                None => e.round_component(k.approx(), i, nx, ny),
            }
        })
    }))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The `f64` enclosures decide only what Ziv's loop on the big-integer
    /// ones gives, and most components: over random cameras (small
    /// integers and random mantissas over wide exponents, angles from tiny
    /// to nearly π) and pixels. `tan_half64` encloses the 120-bit
    /// enclosure of `tan(angle/2)`.
    #[test]
    fn the_f64_enclosures_decide_as_the_big_integer_ones() {
        use rand::{Rng, SeedableRng, rngs::SmallRng};
        let mut r = SmallRng::seed_from_u64(0xca3);
        let mut f = |r: &mut SmallRng| match r.random_range(0..3) {
            0 => r.random_range(-4..=4) as f32,
            1 => r.random_range(-1.0..1.0f32) * 2f32.powi(r.random_range(-60..60)),
            _ => r.random_range(-1.0..1.0f32),
        };
        let (mut decided, mut all) = (0, 0);
        for _ in 0..300 {
            let v = |r: &mut SmallRng, f: &mut dyn FnMut(&mut SmallRng) -> f32| {
                Vec3::new(f(r), f(r), f(r))
            };
            let (dir, up) = (v(&mut r, &mut f), v(&mut r, &mut f));
            let angle = match r.random_range(0..3) {
                0 => core::f32::consts::PI.next_down(),
                1 => r.random_range(0.0..1.0f32) * 2f32.powi(r.random_range(-40..0)),
                _ => r.random_range(0.0..core::f32::consts::PI),
            };
            let res = [r.random_range(1..2000), r.random_range(1..2000)];
            let p = CameraParams::new(Vec3::ZERO, dir, up, angle, res);
            if p.build().is_err() {
                continue;
            }
            let h = tan_half(angle, 120);
            let h64 = tan_half64(angle).unwrap();
            assert!(
                Fx::from_f64(h64.lo) <= h.lo && h.hi <= Fx::from_f64(h64.hi),
                "{angle}"
            );
            let e = Exact::new(&p);
            let (u, a) = (unit64(&e), e.approx(FIRST_BITS));
            for _ in 0..8 {
                let px = [r.random_range(0..res[0]), r.random_range(0..res[1])];
                let (nx, ny) = (numerator(px[0], res[0]), numerator(px[1], res[1]));
                for i in 0..3 {
                    all += 1;
                    let Some(c) = u.and_then(|u| e.component64(&u, i, nx, ny)) else {
                        continue;
                    };
                    decided += 1;
                    let want = if e.b_is_zero(i, nx, ny) {
                        p.dir[i]
                    } else {
                        ziv(&a, |a| e.refine(a), |a| e.component(a, i, nx, ny))
                    };
                    assert_eq!(c.to_bits(), want.to_bits(), "{p:?} {px:?} {i}");
                }
            }
        }
        // A third of the angles are next to π, where C is near 2⁻²⁴ and the
        // f64 tangent too wide to decide.
        assert!(decided * 10 > all * 6, "{decided} of {all}");
    }

    /// An axis-aligned camera, whose basis has zero components, keeps its
    /// `f64` enclosures (a zero end is 0, whatever its exponent), and they
    /// decide its components at the corners.
    #[test]
    fn zero_components_keep_the_f64_enclosures() {
        let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [4, 4]);
        let e = Exact::new(&p);
        let u = unit64(&e).expect("f64 enclosures for an axis-aligned camera");
        let (nx, ny) = (numerator(0, 4), numerator(3, 4));
        for i in 0..3 {
            assert!(e.component64(&u, i, nx, ny).is_some(), "component {i}");
        }
    }

    /// Where flush-to-zero is on, no `f64` enclosure is formed: their
    /// outward rounding assumes subnormals. Without it, the same camera
    /// has them.
    #[cfg(target_arch = "x86_64")]
    #[test]
    fn no_f64_enclosures_where_subnormals_flush() {
        let p = CameraParams::new(Vec3::ZERO, -Vec3::Z, Vec3::Y, 1.0, [4, 4]);
        let formed = move || unit64(&Exact::new(&p)).is_some();
        assert!(!crate::num::certify::in_environment(true, false, formed));
        assert!(crate::num::certify::in_environment(false, false, formed));
    }

    /// The components that the enclosures given do not decide are kept
    /// per camera and each found again by its own key: from enclosures of
    /// 2 bits, which decide none, every component of several pixels goes
    /// through the kept ones, asked for twice in turn, and is the one a
    /// fresh camera gives.
    #[test]
    fn kept_components_are_found_by_their_own_pixel() {
        let p = CameraParams::new(Vec3::ZERO, Vec3::new(0.3, -1.0, 0.7), Vec3::Y, 0.9, [8, 8]);
        let (e, fresh) = (Exact::new(&p), Exact::new(&p));
        let coarse = e.approx(2);
        let pixels = [(0, 0), (3, 5), (7, 7), (5, 2)];
        for _ in 0..2 {
            for (px, py) in pixels {
                let (nx, ny) = (numerator(px, 8), numerator(py, 8));
                for i in 0..3 {
                    let want = fresh.round_component(&fresh.approx(FIRST_BITS), i, nx, ny);
                    let got = e.round_component(&coarse, i, nx, ny);
                    assert_eq!(got.to_bits(), want.to_bits(), "({px}, {py}) component {i}");
                }
            }
        }
        assert!(e.hard.borrow().len() >= 6, "{} kept", e.hard.borrow().len());
    }

    /// An `f64` enclosure decides only where both ends are on one side of
    /// 0 and round to one `f32`: not where an end is 0, nor where an end is
    /// NaN or the ends are inverted; a point decides.
    #[test]
    fn an_f64_enclosure_decides_only_off_zero() {
        let iv = |lo: f64, hi: f64| Iv64 { lo, hi }.decide();
        assert_eq!(iv(1.0, 1.0), Some(1.0));
        assert_eq!(iv(-3.0, -3.0), Some(-3.0));
        assert_eq!(iv(1.0, 1.0 + 2f64.powi(-40)), Some(1.0));
        assert_eq!(iv(0.0, 1e-50), None);
        assert_eq!(iv(-1e-50, 0.0), None);
        assert_eq!(iv(-1e-50, 1e-50), None);
        assert_eq!(iv(0.0, 0.0), None);
        assert_eq!(iv(-0.0, -0.0), None);
        assert_eq!(iv(f64::NAN, f64::NAN), None);
        assert_eq!(iv(2.0, 1.0), None);
        assert_eq!(iv(1.0, 1.0 + 2f64.powi(-20)), None);
    }

    /// The enclosures are taken at the precision asked for plus 8 guard
    /// bits, and each refinement asks for twice the last, so that Ziv's
    /// loop grows geometrically from a first precision just above what
    /// most components need.
    #[test]
    fn the_enclosures_precision_doubles_from_the_first() {
        let p = CameraParams::new(Vec3::ZERO, Vec3::new(0.3, -1.0, 0.7), Vec3::Y, 0.9, [8, 8]);
        let e = Exact::new(&p);
        let a = e.approx(FIRST_BITS);
        assert_eq!(a.p, FIRST_BITS + 8);
        let b = e.refine(&a);
        assert_eq!(b.p, 2 * a.p + 8);
        assert_eq!(e.refine(&b).p, 2 * b.p + 8);
    }

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
