//! What each `cargo fuzz` target checks, as library functions: a target in
//! `fuzz/fuzz_targets/` is one line around [`primitive`] (the `plane`,
//! `sphere` and `quadric` targets, one generic check), [`camera()`] or
//! [`eval_line`], and `cargo test` replays every committed corpus and
//! regression input through the same functions ([`TARGETS`]).
//!
//! A kernel input is four cases, one per lane, decoded with `arbitrary`
//! from the fuzzer's bytes, so the fuzzer chooses what goes in which lane.
//! For every input:
//!
//! 1. each x4 lane equals the reference bit for bit (class, roots, and
//!    `nearest` over a fuzzer-chosen interval), and the batch entry point
//!    (`intersect_packets`) equals x4 on the input's packet and on its rays
//!    turned by one lane;
//! 2. each reference answer is the exact oracle's ([`crate::check`]: the
//!    exact class and every root's bits; the camera's direction bits);
//! 3. for spheres, when the quadric is compiled in too, the same sphere
//!    written as a quadric agrees ([`crate::check::sphere_as_quadric`]);
//! 4. nothing panics.
//!
//! Checks 2 and 3 run on the oracle alone first ([`accepts`]): the answer's
//! bits against the oracle's, without the margins and condition numbers
//! that [`crate::check`] adds to its reports, each exact polynomial solved
//! once. Only an answer that this does not accept goes to [`crate::check`],
//! whose verdict is final; so the targets pass and fail exactly as the full
//! check does, at the cost of the oracle.
//!
//! Every float is a [`FuzzF32`]: a mode byte picks raw bits (so NaN, ±∞,
//! subnormals and values near `f32::MAX` are all reachable), a table of
//! special values, exact wide-range values `m·2^e`, a fine grid, or small
//! integers (which make exact tangents, parallels and surfaces reachable).
//! [`encode_f32`] writes any float back as raw bits, which is how corpora are
//! built from the fixtures ([`encode_case`]).

use crate::camera::{Camera, CameraParams};
use crate::case::{Case, match_case};
use crate::check::{self, Violation};
use crate::num::Lane;
#[cfg(feature = "plane")]
use crate::plane::Plane;
#[cfg(feature = "quadric")]
use crate::quadric::Quadric;
#[cfg(feature = "sphere")]
use crate::sphere::{self, Sphere};
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use crate::{Ray, hit::Intersection, primitive::Primitive, ray4::Ray4};
use arbitrary::{Arbitrary, Unstructured};
use glam::Vec3;
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
use wide::f32x4;

/// Special values the fuzzer can pick by index.
const SPECIALS: [f32; 16] = [
    0.0,
    -0.0,
    f32::INFINITY,
    f32::NEG_INFINITY,
    f32::NAN,
    f32::MAX,
    -f32::MAX,
    f32::MIN_POSITIVE,
    f32::from_bits(1),
    -f32::from_bits(1),
    f32::EPSILON,
    1.0,
    -1.0,
    1e30,
    1e-30,
    3.0e38,
];

/// A fuzzed `f32`. Mode byte (mod 8): 0 raw bits (4 bytes), 1 a special
/// value, 2 `i16 · 2^i8` (exact, any magnitude), 3 `i16/256`, 4–7 an `i8`.
///
/// ```
/// use arbitrary::{Arbitrary, Unstructured};
/// use rayoracle::fuzz::FuzzF32;
/// let x = FuzzF32::arbitrary(&mut Unstructured::new(&[4, 0xfd])).unwrap();
/// assert_eq!(x.0, -3.0);
/// let n = FuzzF32::arbitrary(&mut Unstructured::new(&[0, 0, 0, 0xc0, 0x7f])).unwrap();
/// assert!(n.0.is_nan());
/// ```
#[derive(Clone, Copy, Debug)]
pub struct FuzzF32(pub f32);

impl<'a> Arbitrary<'a> for FuzzF32 {
    fn arbitrary(u: &mut Unstructured<'a>) -> arbitrary::Result<Self> {
        let x = match u8::arbitrary(u)? % 8 {
            0 => f32::from_bits(u32::arbitrary(u)?),
            1 => SPECIALS[usize::from(u8::arbitrary(u)?) % SPECIALS.len()],
            2 => {
                let m = i16::arbitrary(u)? as f32;
                let e = i8::arbitrary(u)? as i32;
                // An i8 exponent needs no clamp: ldexp is exact from 2⁻¹²⁸.
                m.ldexp(e)
            }
            3 => i16::arbitrary(u)? as f32 / 256.0,
            _ => i8::arbitrary(u)? as f32,
        };
        Ok(FuzzF32(x))
    }
}

/// Appends the bytes that decode to exactly `x` (mode 0, raw bits).
///
/// ```
/// use arbitrary::{Arbitrary, Unstructured};
/// use rayoracle::fuzz::{FuzzF32, encode_f32};
/// let mut b = Vec::new();
/// encode_f32(-1.5e-40, &mut b);
/// assert_eq!(FuzzF32::arbitrary(&mut Unstructured::new(&b)).unwrap().0, -1.5e-40);
/// ```
pub fn encode_f32(x: f32, out: &mut Vec<u8>) {
    out.push(0);
    out.extend(x.to_bits().to_le_bytes());
}

fn vec3(u: &mut Unstructured<'_>) -> arbitrary::Result<Vec3> {
    Ok(Vec3::new(
        FuzzF32::arbitrary(u)?.0,
        FuzzF32::arbitrary(u)?.0,
        FuzzF32::arbitrary(u)?.0,
    ))
}

fn f(u: &mut Unstructured<'_>) -> arbitrary::Result<f32> {
    Ok(FuzzF32::arbitrary(u)?.0)
}

fn encode3(v: Vec3, out: &mut Vec<u8>) {
    v.to_array().iter().for_each(|&x| encode_f32(x, out));
}

/// Why a fuzz input failed: which check, which lane, and the case.
///
/// ```
/// use rayoracle::fuzz::Failure;
/// assert_eq!(Failure("x".into()).to_string(), "x");
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct Failure(pub String);

impl core::fmt::Display for Failure {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for Failure {}

fn judged(
    lane: usize,
    case: &dyn core::fmt::Debug,
    r: Result<impl Sized, Violation>,
) -> Result<(), Failure> {
    r.map(|_| ())
        .map_err(|v| Failure(format!("lane {lane}: {v}\n  case: {case:?}")))
}

/// Compares x4's lanes and `nearest` with the reference's.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn x4_matches<H: Intersection + core::fmt::Debug>(
    lanes: [H; 4],
    reference: &[H; 4],
    nearest: (f32x4, f32x4),
    interval: (f32, f32),
) -> Result<(), Failure> {
    let (mask, t) = (nearest.0.to_bitmask(), nearest.1.to_array());
    for i in 0..4 {
        if !crate::hit::same_bits(&lanes[i], &reference[i]) {
            return Err(Failure(format!(
                "lane {i}: x4 {:?} but reference {:?}",
                lanes[i], reference[i]
            )));
        }
        let want = reference[i].nearest(interval.0, interval.1);
        let got = (mask >> i & 1 == 1).then_some(t[i]);
        let agree = match (want, got) {
            (Some(a), Some(b)) => a.to_bits() == b.to_bits(),
            (None, None) => t[i] == f32::INFINITY,
            _ => false,
        };
        if !agree {
            return Err(Failure(format!(
                "lane {i}: x4 nearest{:?} = {got:?}, reference {want:?}",
                interval
            )));
        }
    }
    Ok(())
}

/// Decodes four cases and an interval `[t_min, t_max]` for `nearest`.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn decode<'a, T>(
    data: &'a [u8],
    one: impl Fn(&mut Unstructured<'a>) -> arbitrary::Result<T>,
) -> Option<([T; 4], (f32, f32))> {
    let mut u = Unstructured::new(data);
    let cases = [
        one(&mut u).ok()?,
        one(&mut u).ok()?,
        one(&mut u).ok()?,
        one(&mut u).ok()?,
    ];
    let interval = (f(&mut u).ok()?, f(&mut u).ok()?);
    Some((cases, interval))
}

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn ray(u: &mut Unstructured<'_>) -> arbitrary::Result<Ray> {
    Ok(Ray::new(vec3(u)?, vec3(u)?))
}

#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn interval4(i: (f32, f32)) -> (f32x4, f32x4) {
    (f32x4::splat(i.0), f32x4::splat(i.1))
}

/// Whether the full check ([`check::check_plane`], [`check::check_quadric`]
/// or [`check::check_sphere`]) surely passes `got`, given the oracle's
/// answer: the check passes a non-finite input, and otherwise exactly the
/// oracle's class and root bits, which is what [`crate::hit::same_bits`]
/// compares (the oracle's roots are never NaN). `false` sends the answer
/// to the full check, which decides.
///
/// ```
/// # #[cfg(feature = "plane")] {
/// use rayoracle::{Ray, plane::{Plane, PlaneHit, exact}};
/// use rayoracle::fuzz::accepts;
/// use glam::Vec3;
/// let (r, p) = (Ray::new(Vec3::ZERO, Vec3::Z), Plane::new(Vec3::Z, Vec3::Z));
/// assert!(accepts(&PlaneHit::Hit(1.0), exact::intersect(&r, &p)));
/// assert!(!accepts(&PlaneHit::Hit(-0.0), exact::intersect(&Ray::new(Vec3::Z, Vec3::Z), &p)));
/// # }
/// ```
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
pub fn accepts<H: Intersection>(got: &H, oracle: Result<H, crate::exact::NonFinite>) -> bool {
    match oracle {
        Ok(e) => crate::hit::same_bits(got, &e),
        Err(_) => true,
    }
}

/// A primitive with a fuzz target: how the target judges the reference's
/// answer against the exact oracle. [`primitive`] is the target.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
pub trait Target: Primitive {
    /// Whether the oracle alone accepts `got` ([`accepts`]); `false` sends
    /// it to [`Target::check`], which decides.
    fn accepts(ray: &Ray, p: &Self, got: &Self::Hit) -> bool {
        accepts(got, Self::exact(ray, p))
    }
    /// The full check ([`crate::check`]).
    fn check(ray: &Ray, p: &Self, got: Self::Hit) -> Result<check::CaseReport, Violation>;
}

#[cfg(feature = "plane")]
impl Target for Plane {
    fn check(ray: &Ray, p: &Plane, got: Self::Hit) -> Result<check::CaseReport, Violation> {
        check::check_plane(ray, p, got)
    }
}

/// The `sphere` target checks, with the quadric compiled in, the same
/// sphere written as a quadric too.
#[cfg(feature = "sphere")]
impl Target for Sphere {
    fn accepts(ray: &Ray, s: &Sphere, got: &Self::Hit) -> bool {
        sphere_accepts(ray, s, got)
    }
    fn check(ray: &Ray, s: &Sphere, got: Self::Hit) -> Result<check::CaseReport, Violation> {
        #[cfg(feature = "quadric")]
        return check::check_sphere_and_quadric(ray, s, got);
        #[cfg(not(feature = "quadric"))]
        return check::check_sphere(ray, s, got);
    }
}

#[cfg(feature = "quadric")]
impl Target for Quadric {
    fn check(ray: &Ray, q: &Quadric, got: Self::Hit) -> Result<check::CaseReport, Violation> {
        check::check_quadric(ray, q, got)
    }
}

/// [`accepts`] for what the `sphere` target checks: the sphere reference's
/// answer is the oracle's and, with the quadric compiled in, the sphere
/// written as a quadric passes [`check::sphere_as_quadric`]: where
/// [`Quadric::from_sphere`] is exact and the direction nonzero, the quadric
/// oracle's exact polynomial is the sphere oracle's, and the quadric
/// reference gives the sphere oracle's answer (so the two references agree,
/// the sphere's being the oracle's). Without the quadric, the sphere's
/// answer is [`sphere::exact::intersect`]'s, which keeps the last few (an
/// answer the reference's last stage asked for is not solved again); with
/// it, the oracle's coefficients are formed once, for its answer and for
/// the comparison. The two polynomials are compared exactly on expansions,
/// and where either does not fit there, `false` leaves it to the full
/// check.
#[cfg(feature = "sphere")]
fn sphere_accepts(ray: &Ray, s: &Sphere, got: &sphere::SphereHit) -> bool {
    #[cfg(not(feature = "quadric"))]
    {
        let Ok(es) = sphere::exact::intersect(ray, s) else {
            return true;
        };
        crate::hit::same_bits(got, &es)
    }
    #[cfg(feature = "quadric")]
    {
        // The sphere oracle's coefficients, formed once for its answer and
        // for the comparison with the quadric's below.
        let Ok((es, sphere_poly)) = sphere::exact::intersect_and_expansions(ray, s) else {
            return true;
        };
        if !crate::hit::same_bits(got, &es) {
            return false;
        }
        // Spheres recur from one input to the next (the fuzzer mutates one
        // lane at a time): the last few conversions are kept.
        use crate::exact::memo::{Memo, remembered};
        thread_local! {
            static QUADRICS: core::cell::RefCell<Memo<[u32; 4], (Quadric, bool)>> =
                const { core::cell::RefCell::new(Memo::new()) };
        }
        let key = [s.center.x, s.center.y, s.center.z, s.radius].map(f32::to_bits);
        let (q, exact) = remembered(&QUADRICS, key, || Quadric::from_sphere(s));
        if !exact || ray.dir == Vec3::ZERO {
            return true;
        }
        use crate::quadric;
        let Ok(eq) = quadric::exact::expansions(ray, &q) else {
            return true;
        };
        let same = match (sphere_poly, eq) {
            (Some(es), Some(eq)) => es
                .iter()
                .zip(&eq)
                .all(|(x, y)| x.compare(y) == Some(core::cmp::Ordering::Equal)),
            _ => false,
        };
        let as_quadric = match es {
            sphere::SphereHit::None => quadric::QuadricHit::None,
            sphere::SphereHit::Tangent(t) => quadric::QuadricHit::One(t),
            sphere::SphereHit::Two(t0, t1) => quadric::QuadricHit::Two(t0, t1),
        };
        same && crate::hit::same_bits(&quadric::reference::intersect(ray, &q), &as_quadric)
    }
}

/// The implementations a target compares: the scalar one, the four-lane
/// one and, for a primitive, the batch entry point. Each target is a
/// one-line call of its `*_with` function with the shipped kernels; the
/// tests (`fuzz/wrong_kernels.rs`) pass in wrong ones, to show that every
/// check a target makes fires on a wrong kernel.
#[derive(Clone, Copy)]
pub(crate) struct Kernels<R, X, B = ()> {
    /// The scalar kernel, judged against the exact oracle.
    pub(crate) reference: R,
    /// The four-lane kernel, compared bit for bit with `reference`.
    pub(crate) x4: X,
    /// The batch kernel, compared bit for bit with `x4`, packet by packet
    /// (`()` for the camera, which has none).
    #[cfg_attr(
        not(any(feature = "plane", feature = "sphere", feature = "quadric")),
        allow(dead_code)
    )]
    pub(crate) batch: B,
}

/// The kernels of a primitive's target.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
pub(crate) type PrimitiveKernels<P> = Kernels<
    fn(&Ray, &P) -> <P as Primitive>::Hit,
    fn(&Ray4, &<P as Primitive>::Packet) -> <P as Primitive>::Hit4,
    fn(&[Ray4], &<P as Primitive>::Packet, &mut [<P as Primitive>::Hit4]),
>;
/// The camera kernels a target can be given: one pixel's ray, four pixels'.
pub(crate) type CameraKernels =
    Kernels<fn(&Camera, u32, u32) -> crate::Ray, fn(&Camera, [[u32; 2]; 4]) -> crate::ray4::Ray4>;

/// The `plane`, `sphere` and `quadric` targets: four cases of `P`, one per
/// lane, and an interval for `nearest`. The sphere's target also checks
/// the sphere written as a quadric when the quadric is compiled in
/// ([`Target`]).
///
/// ```
/// use rayoracle::{case::parse_line, fuzz::{encode_case, primitive}};
/// let mut b = Vec::new();
/// # #[cfg(feature = "plane")] {
/// encode_case(&parse_line(
///     r#"{"kind":"plane","origin":[0,1,0],"dir":[0,-1,0],"point":[0,0,0],"normal":[0,1,0]}"#).unwrap().case, &mut b);
/// assert_eq!(primitive::<rayoracle::plane::Plane>(&b), Ok(()));
/// # }
/// # #[cfg(feature = "sphere")] {
/// b.clear();
/// encode_case(&parse_line(
///     r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#).unwrap().case, &mut b);
/// assert_eq!(primitive::<rayoracle::sphere::Sphere>(&b), Ok(()));
/// # }
/// # #[cfg(feature = "quadric")] {
/// b.clear();
/// encode_case(&parse_line(
///     r#"{"kind":"quadric","origin":[-5,0,0],"dir":[1,0,0],"coeffs":[1,1,0,0,0,0,0,0,0,-1]}"#).unwrap().case, &mut b);
/// assert_eq!(primitive::<rayoracle::quadric::Quadric>(&b), Ok(()));
/// # }
/// ```
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
pub fn primitive<P: Target>(data: &[u8]) -> Result<(), Failure> {
    primitive_with::<P>(
        data,
        Kernels {
            reference: P::reference,
            x4: P::x4,
            batch: P::batch,
        },
    )
}

/// One case of `P`: the ray, then the primitive's [`Primitive::inputs`].
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn one<P: Primitive>(u: &mut Unstructured<'_>) -> arbitrary::Result<(Ray, P)> {
    let r = ray(u)?;
    let mut v = [0.0; 16];
    let v = &mut v[..P::INPUTS];
    for x in v.iter_mut() {
        *x = f(u)?;
    }
    Ok((r, P::from_inputs(v)))
}

/// [`primitive()`] with the kernels given.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
pub(crate) fn primitive_with<P: Target>(
    data: &[u8],
    k: PrimitiveKernels<P>,
) -> Result<(), Failure> {
    let Some((cases, interval)) = decode(data, one::<P>) else {
        return Ok(());
    };
    let reference = cases.map(|(r, p)| (k.reference)(&r, &p));
    let (rays, packet) = (
        Ray4::from_rays(cases.map(|c| c.0)),
        P::pack(cases.map(|c| c.1)),
    );
    let h4 = (k.x4)(&rays, &packet);
    let (lo, hi) = interval4(interval);
    x4_matches(
        P::lanes(&h4),
        &reference,
        P::nearest4(&h4, lo, hi),
        interval,
    )?;
    for (i, (r, p)) in cases.iter().enumerate() {
        if !P::accepts(r, p, &reference[i]) {
            judged(i, &(r, p), P::check(r, p, reference[i]))?;
        }
    }
    batch_matches::<P>(&k, cases.map(|c| c.0), &packet, h4)
}

/// Compares the batch kernel with x4, packet by packet, on two packets:
/// the rays of the input, and the same rays turned by one lane (against the
/// same primitives, so new cases), which makes a batch of eight lanes.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn batch_matches<P: Target>(
    k: &PrimitiveKernels<P>,
    r: [Ray; 4],
    packet: &P::Packet,
    h4: P::Hit4,
) -> Result<(), Failure> {
    let (rays, turned) = (
        Ray4::from_rays(r),
        Ray4::from_rays([r[1], r[2], r[3], r[0]]),
    );
    let want = [P::lanes(&h4), P::lanes(&(k.x4)(&turned, packet))];
    let mut out = [h4; 2];
    (k.batch)(&[rays, turned], packet, &mut out);
    for (j, (got, want)) in out.iter().zip(&want).enumerate() {
        let got = P::lanes(got);
        for i in 0..4 {
            if !crate::hit::same_bits(&got[i], &want[i]) {
                return Err(Failure(format!(
                    "packet {j} lane {i}: batch {:?} but x4 {:?}",
                    got[i], want[i]
                )));
            }
        }
    }
    Ok(())
}

/// The `camera` target: one camera, four pixels (any resolution up to
/// 65535, 0 included to reach the construction errors).
///
/// ```
/// let mut b = Vec::new();
/// rayoracle::fuzz::encode_case(&rayoracle::case::parse_line(
///     r#"{"kind":"camera","position":[0,0,0],"dir":[0,0,-1],"up":[0,1,0],"angle":1,"res":[64,48],"pixel":[3,4]}"#).unwrap().case, &mut b);
/// assert_eq!(rayoracle::fuzz::camera(&b), Ok(()));
/// ```
pub fn camera(data: &[u8]) -> Result<(), Failure> {
    camera_with(
        data,
        Kernels {
            reference: Camera::ray,
            x4: Camera::ray4,
            batch: (),
        },
    )
}

/// [`camera()`] with the kernels given.
pub(crate) fn camera_with(data: &[u8], k: CameraKernels) -> Result<(), Failure> {
    let mut u = Unstructured::new(data);
    let decoded = (|| -> arbitrary::Result<_> {
        let (position, dir, up, angle) = (vec3(&mut u)?, vec3(&mut u)?, vec3(&mut u)?, f(&mut u)?);
        let res = [
            u16::arbitrary(&mut u)? as u32,
            u16::arbitrary(&mut u)? as u32,
        ];
        let mut px = [[0u32; 2]; 4];
        for p in &mut px {
            *p = [
                u16::arbitrary(&mut u)? as u32,
                u16::arbitrary(&mut u)? as u32,
            ];
        }
        Ok((CameraParams::new(position, dir, up, angle, res), px))
    })();
    let Ok((p, px)) = decoded else { return Ok(()) };
    let built = p.build();
    let px = px.map(|[x, y]| [x % p.res[0].max(1), y % p.res[1].max(1)]);
    if let Ok(cam) = &built {
        let got = (k.x4)(cam, px).to_rays();
        for i in 0..4 {
            let want = (k.reference)(cam, px[i][0], px[i][1]);
            let same = |a: f32, b: f32| a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan());
            let all_same = (0..3).all(|c| {
                same(got[i].origin[c], want.origin[c]) && same(got[i].dir[c], want.dir[c])
            });
            if !all_same {
                return Err(Failure(format!(
                    "lane {i}: x4 {:?} but reference {want:?}\n  camera {p:?} pixel {:?}",
                    got[i], px[i]
                )));
            }
        }
    }
    for (i, pixel) in px.iter().enumerate() {
        let got = built.map(|cam| (k.reference)(&cam, pixel[0], pixel[1]));
        if !camera_accepts(&p, *pixel, &got) {
            judged(i, &(p, pixel), check::check_camera(&p, *pixel, got))?;
        }
    }
    Ok(())
}

/// Whether [`check::check_camera`] surely passes `got`, the reference's
/// answer for camera parameters `p` as built once: a construction error is
/// the oracle's own ([`crate::camera::exact::ray`] fails exactly when the
/// construction does), and a ray passes when its origin and direction have
/// the oracle's bits. `false` sends the answer to the full check, which
/// decides; so, as for the primitives ([`accepts`]), the target passes and
/// fails exactly as the full check does, building the camera once and
/// asking the oracle once per pixel.
fn camera_accepts(
    p: &CameraParams,
    pixel: [u32; 2],
    got: &Result<crate::Ray, crate::camera::CameraError>,
) -> bool {
    let Ok(got) = got else { return true };
    let bits = |v: Vec3| v.to_array().map(f32::to_bits);
    let want = crate::camera::exact::direction(p, pixel[0], pixel[1]);
    bits(got.origin) == bits(p.position) && bits(got.dir) == bits(want)
}

/// The `eval_line` target: any bytes as one `eval` line. It must give one
/// JSON object that names the line, never an internal error (a panic that
/// `eval` caught).
///
/// ```
/// assert_eq!(rayoracle::fuzz::eval_line(br#"{"kind":"sphere","radius":[1]}"#), Ok(()));
/// assert_eq!(rayoracle::fuzz::eval_line(b"\xff\xfe"), Ok(()));
/// ```
pub fn eval_line(data: &[u8]) -> Result<(), Failure> {
    eval_line_with(data, crate::eval::eval_line)
}

/// [`eval_line()`] with the `eval` of one line given.
pub(crate) fn eval_line_with(data: &[u8], eval: fn(usize, &str) -> String) -> Result<(), Failure> {
    let line = String::from_utf8_lossy(data);
    let line = line.lines().next().unwrap_or("");
    let out = eval(7, line);
    if line.trim().is_empty() {
        return if out.is_empty() {
            Ok(())
        } else {
            Err(Failure(format!("blank line gave output {out}")))
        };
    }
    let v: serde_json::Value =
        serde_json::from_str(&out).map_err(|e| Failure(format!("not JSON ({e}): {out}")))?;
    if v["line"] != 7 {
        return Err(Failure(format!("wrong line number: {out}")));
    }
    if v["error"]
        .as_str()
        .is_some_and(|e| e.starts_with("internal error"))
    {
        return Err(Failure(format!("eval panicked on {line:?}: {out}")));
    }
    Ok(())
}

/// Appends the bytes of one case in its target's format, with raw-bit
/// floats, so the case decodes exactly. A kernel case fills all four lanes
/// (the case itself in lane 0 and, in lanes 1–3, the same case, so x4 is
/// exercised with it everywhere), then the interval `[0, ∞]`.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::case::parse_line;
/// let c = parse_line(r#"{"kind":"sphere","origin":[0,0,-5],"dir":[0,0,1],"center":[0,0,0],"radius":1}"#).unwrap();
/// let mut b = Vec::new();
/// rayoracle::fuzz::encode_case(&c.case, &mut b);
/// assert_eq!(b.len(), 4 * 10 * 5 + 2 * 5);
/// # }
/// ```
pub fn encode_case(case: &Case, out: &mut Vec<u8>) {
    match_case!(
        case,
        |r, p| {
            for _ in 0..4 {
                encode3(r.origin, out);
                encode3(r.dir, out);
                Primitive::inputs(p)
                    .iter()
                    .for_each(|&x| encode_f32(x, out));
            }
            encode_interval(out);
        },
        |p, px| {
            encode3(p.position, out);
            encode3(p.dir, out);
            encode3(p.up, out);
            encode_f32(p.angle, out);
            for r in p.res {
                out.extend((r.min(65535) as u16).to_le_bytes());
            }
            for _ in 0..4 {
                for c in px {
                    out.extend((*c as u16).to_le_bytes());
                }
            }
        },
    )
}

/// The interval `[0, ∞]` that ends a kernel input.
#[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
fn encode_interval(out: &mut Vec<u8>) {
    encode_f32(0.0, out);
    encode_f32(f32::INFINITY, out);
}

/// A target's check: the fuzzer's bytes in, a [`Failure`] out.
pub type Check = fn(&[u8]) -> Result<(), Failure>;

/// The checks by target name, for the replay test and the campaign.
///
/// ```
/// assert!(rayoracle::fuzz::TARGETS.iter().any(|(n, _)| *n == "eval_line"));
/// ```
pub const TARGETS: &[(&str, Check)] = &[
    ("camera", camera),
    #[cfg(feature = "plane")]
    ("plane", primitive::<Plane>),
    #[cfg(feature = "sphere")]
    ("sphere", primitive::<Sphere>),
    #[cfg(feature = "quadric")]
    ("quadric", primitive::<Quadric>),
    ("eval_line", eval_line),
    #[cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
    ("scene", scene::check),
];

#[cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
pub mod gate;
#[cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]
pub mod scene;
#[cfg(test)]
mod wrong_kernels;

#[cfg(test)]
mod tests {
    use super::{FuzzF32, SPECIALS};
    use arbitrary::{Arbitrary, Unstructured};

    /// What `encode_case` writes, the targets' decoder reads back: the
    /// same four cases (bit for bit, −0 and NaN included) and the interval,
    /// for every primitive (each decoy, and the ray below with the decoy's
    /// primitive, its inputs negated).
    #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
    fn encoded_cases_decode_to_themselves<P: crate::primitive::Primitive>() {
        use super::{decode, encode_case, one};
        use crate::Ray;
        use glam::Vec3;
        let odd = Ray::new(Vec3::new(-0.0, 1.5, f32::NAN), Vec3::new(3.0, -2.0, 1e-40));
        let negated = |p: &P| P::from_inputs(&P::inputs(p).iter().map(|x| -x).collect::<Vec<_>>());
        let mut all: Vec<(Ray, P)> = P::decoys().concat();
        all.extend(P::decoys().concat().iter().map(|(_, p)| (odd, negated(p))));
        let bits = |r: Ray, p: P| {
            let mut v: Vec<f32> = [r.origin.to_array(), r.dir.to_array()].concat();
            v.extend(P::inputs(&p));
            v.into_iter().map(f32::to_bits).collect::<Vec<u32>>()
        };
        for (r, p) in all {
            let mut b = Vec::new();
            encode_case(&P::case(r, p), &mut b);
            let (cases, interval) = decode(&b, one::<P>).unwrap();
            for (rd, pd) in cases {
                assert_eq!(bits(rd, pd), bits(r, p), "{:?}", P::KIND);
            }
            assert_eq!((interval.0, interval.1), (0.0, f32::INFINITY));
        }
    }

    #[cfg(feature = "plane")]
    #[test]
    fn an_encoded_plane_case_decodes_to_itself() {
        encoded_cases_decode_to_themselves::<crate::plane::Plane>();
    }

    #[cfg(feature = "sphere")]
    #[test]
    fn an_encoded_sphere_case_decodes_to_itself() {
        encoded_cases_decode_to_themselves::<crate::sphere::Sphere>();
    }

    #[cfg(feature = "quadric")]
    #[test]
    fn an_encoded_quadric_case_decodes_to_itself() {
        encoded_cases_decode_to_themselves::<crate::quadric::Quadric>();
    }

    /// A violation becomes a failure naming its lane and case; an
    /// acceptable answer passes.
    #[test]
    fn a_violation_is_a_failure_naming_lane_and_case() {
        use super::judged;
        use crate::check::Violation;
        let bad: Result<(), Violation> = Err(Violation::SphereAsQuadric("x".into()));
        let f = judged(2, &"the case", bad).unwrap_err();
        assert!(
            f.0.starts_with("lane 2: ") && f.0.contains("\"the case\""),
            "{}",
            f.0
        );
        assert_eq!(judged(0, &"ok", Ok::<(), Violation>(())), Ok(()));
    }

    /// The x4-against-reference check the targets run fails on each way x4
    /// can differ: a lane's bits (−0 against +0 included), a nearest hit
    /// that should not be there, one that is missing, and a different `t`;
    /// and passes when x4 agrees (a miss reads as `+∞`).
    #[cfg(feature = "plane")]
    #[test]
    fn x4_matches_fails_on_each_kind_of_difference() {
        use super::x4_matches;
        use crate::plane::PlaneHit::{self, Hit, InPlane, Parallel};
        use wide::f32x4;
        let reference: [PlaneHit; 4] = [Hit(1.0), Parallel, Hit(-2.0), InPlane];
        let interval = (0.0, 10.0);
        let inf = f32::INFINITY;
        let nearest = |mask: [bool; 4], t: [f32; 4]| {
            let m = f32x4::from(mask.map(|b| if b { f32::from_bits(!0) } else { 0.0 }));
            (m, f32x4::from(t))
        };
        let good = nearest([true, false, false, true], [1.0, inf, inf, 0.0]);
        assert_eq!(x4_matches(reference, &reference, good, interval), Ok(()));

        let mut lanes = reference;
        lanes[2] = Hit(-2.5);
        let e = x4_matches(lanes, &reference, good, interval).unwrap_err();
        assert!(e.0.starts_with("lane 2: x4 Hit(-2.5)"), "{}", e.0);
        let zeros = [Hit(0.0), Parallel, Parallel, Parallel];
        let e = x4_matches(
            [Hit(-0.0), Parallel, Parallel, Parallel],
            &zeros,
            good,
            interval,
        );
        assert!(e.unwrap_err().0.starts_with("lane 0: x4 Hit(-0.0)"));

        for (bad, lane) in [
            (nearest([true, true, false, true], [1.0, 5.0, inf, 0.0]), 1),
            (
                nearest([true, false, false, false], [1.0, inf, inf, inf]),
                3,
            ),
            (nearest([true, false, false, true], [1.5, inf, inf, 0.0]), 0),
            (nearest([true, false, false, true], [1.0, 0.0, inf, 0.0]), 1),
        ] {
            let e = x4_matches(reference, &reference, bad, interval).unwrap_err();
            assert!(
                e.0.starts_with(&format!("lane {lane}: x4 nearest")),
                "{}",
                e.0
            );
        }
    }

    /// Every mode decodes as documented (i16 and u32 are little-endian).
    #[test]
    fn each_mode_decodes_as_documented() {
        let f = |b: &[u8]| FuzzF32::arbitrary(&mut Unstructured::new(b)).unwrap().0;
        // Index 33 is 1 modulo 16 (and would be 2 divided by 16).
        assert_eq!(f(&[1, 33]).to_bits(), (-0.0f32).to_bits());
        assert_eq!(f(&[9, 2]), f32::INFINITY);
        // 3 · 2⁻¹²⁸ (i16 = 3, i8 = −128), exact in the subnormal range.
        assert_eq!(f(&[2, 3, 0, 0x80]), f32::from_bits(3 << 21));
        assert_eq!(f(&[10, 0x00, 0xff, 0]), -256.0);
        // −512 / 256.
        assert_eq!(f(&[3, 0x00, 0xfe]), -2.0);
        assert_eq!(f(&[7, 0x7f]), 127.0);
    }

    /// The specials are 16 different bit patterns (−0 and +0 both there):
    /// a duplicate would be a value the fuzzer can no longer pick by index.
    #[test]
    fn the_specials_are_distinct_bit_patterns() {
        let mut bits: Vec<u32> = SPECIALS.iter().map(|x| x.to_bits()).collect();
        bits.sort_unstable();
        bits.dedup();
        assert_eq!(bits.len(), SPECIALS.len());
        assert!(bits.contains(&(-0.0f32).to_bits()));
    }
}
