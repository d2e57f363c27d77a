//! The judge's edges: each place where a rule forgives an answer, or
//! refuses one, tested on both sides, with the fault it names.
#![cfg(all(feature = "plane", feature = "sphere"))]

use glam::Vec3;
use rayoracle::Ray;
use rayoracle::check::rules::{self, Answer, Declared, Fault, Semantics};
use rayoracle::plane::Plane;
use rayoracle::sphere::Sphere;

/// The fault `d` finds in `got` on a plane case, `None` if it passes.
fn plane(d: &Declared, ray: &Ray, p: &Plane, got: Answer) -> Option<Fault> {
    let (_, e) = rules::plane(ray, p).expect("finite");
    rules::judge(d, &e, &got).fault
}

/// The fault `d` finds in `got` on a sphere case, `None` if it passes.
fn sphere(d: &Declared, ray: &Ray, s: &Sphere, got: Answer) -> Option<Fault> {
    let (_, e) = rules::sphere(ray, s).expect("finite");
    rules::judge(d, &e, &got).fault
}

fn strict(s: Semantics) -> Declared {
    Declared::correctly_rounded(s)
}

/// Where every `t` is a hit, a nearest hit needs no comparison, but a NaN
/// is still a NaN, as a `t` or in a point.
#[test]
fn a_nan_fails_even_where_every_t_is_a_hit() {
    let ground = Plane::new(Vec3::ZERO, Vec3::Y);
    let along = Ray::new(Vec3::new(0.5, 0.0, 0.0), Vec3::X);
    let d = strict(Semantics::NearestPositive);
    assert_eq!(plane(&d, &along, &ground, Answer::Nearest(Some(2.0))), None);
    let nan = [
        Answer::Nearest(Some(f32::NAN)),
        Answer::Point(Some(Vec3::new(f32::NAN, 0.0, 0.0))),
    ];
    for got in nan {
        assert_eq!(plane(&d, &along, &ground, got), Some(Fault::NanRoot));
    }
}

/// A ray exactly in a plane whose offset's terms are not 0 (`0.1 − 0.1`):
/// a kernel that declares a band may compute the offset as not 0 and miss,
/// or hit once; one that declares none may not.
#[test]
fn a_ray_in_the_plane_may_miss_within_a_band() {
    let p = Plane::new(Vec3::new(0.0, 0.1, 0.0), Vec3::Y);
    let along = Ray::new(Vec3::new(0.5, 0.1, 0.0), Vec3::X);
    for s in [Semantics::WholeLine, "roots-in:0:10".parse().unwrap()] {
        for got in [Answer::Roots(vec![]), Answer::Roots(vec![1.0])] {
            assert_eq!(plane(&Declared::f32(s), &along, &p, got.clone()), None);
            let strict = plane(&strict(s), &along, &p, got);
            assert_eq!(strict, Some(Fault::NotEverywhere));
        }
    }
    // Along the ground every term of `d·n` and of the offset is 0: any
    // kernel computes them exactly, so no band excuses a miss.
    let (ground, along) = (
        Plane::new(Vec3::ZERO, Vec3::Y),
        Ray::new(Vec3::new(0.5, 0.0, 0.0), Vec3::X),
    );
    let miss = plane(
        &Declared::f32(Semantics::WholeLine),
        &along,
        &ground,
        Answer::Roots(vec![]),
    );
    assert_eq!(miss, Some(Fault::NotEverywhere));
}

/// A solid whose origin is clearly outside: `t = 0` (inside) is wrong
/// whatever band is declared; the nearest root is right.
#[test]
fn an_origin_far_outside_a_solid_is_outside_in_any_band() {
    let (ray, s) = (
        Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z),
        Sphere::new(Vec3::ZERO, 1.5),
    );
    for d in [
        Declared::f32(Semantics::Solid),
        Declared::faithful(Semantics::Solid),
        strict(Semantics::Solid),
    ] {
        assert_eq!(sphere(&d, &ray, &s, Answer::Nearest(Some(3.5))), None);
        assert!(sphere(&d, &ray, &s, Answer::Nearest(Some(0.0))).is_some());
        let origin = Answer::Point(Some(ray.origin));
        assert!(sphere(&d, &ray, &s, origin).is_some());
    }
}

/// An origin an ulp outside a solid's surface, whose sign a kernel with a
/// band may get wrong: there `t = 0` and the nearest root both pass, as a
/// `t` or as a point; without a band only the root does.
#[test]
fn an_origin_on_a_solids_surface_may_be_either_within_a_band() {
    let z = -(1.5f32.next_up());
    let (ray, s) = (
        Ray::new(Vec3::new(0.0, 0.0, z), Vec3::Z),
        Sphere::new(Vec3::ZERO, 1.5),
    );
    let (_, e) = rules::sphere(&ray, &s).unwrap();
    let root = e.roots.as_ref().unwrap()[0];
    assert!(root > 0.0 && root < 1e-6, "{root}");
    let f32 = Declared::f32(Semantics::Solid);
    for got in [
        Answer::Nearest(Some(0.0)),
        Answer::Point(Some(ray.origin)),
        Answer::Nearest(Some(root)),
    ] {
        assert_eq!(sphere(&f32, &ray, &s, got), None);
    }
    let d = strict(Semantics::Solid);
    assert_eq!(sphere(&d, &ray, &s, Answer::Nearest(Some(root))), None);
    assert!(sphere(&d, &ray, &s, Answer::Nearest(Some(0.0))).is_some());
}

/// An origin inside a solid: `t = 0`, as a `t` or as the origin's point,
/// is the answer; a root ahead is [`Fault::Inside`].
#[test]
fn inside_a_solid_the_origin_is_the_hit_point() {
    let (ray, s) = (
        Ray::new(Vec3::new(0.0, 0.0, 0.5), Vec3::Z),
        Sphere::new(Vec3::ZERO, 1.5),
    );
    for d in [Declared::f32(Semantics::Solid), strict(Semantics::Solid)] {
        assert_eq!(sphere(&d, &ray, &s, Answer::Nearest(Some(0.0))), None);
        assert_eq!(sphere(&d, &ray, &s, Answer::Point(Some(ray.origin))), None);
        let ahead = Answer::Point(Some(Vec3::new(0.0, 0.0, 1.5)));
        assert_eq!(sphere(&d, &ray, &s, ahead), Some(Fault::Inside));
        let ahead = Answer::Nearest(Some(1.0));
        assert_eq!(sphere(&d, &ray, &s, ahead), Some(Fault::Inside));
    }
}

/// A plane `10⁻³⁵` ahead of the origin, and one `10⁻³⁵` behind it (inputs
/// not small integers): a root that near 0 may fall on either side, so a
/// miss for the first and `t = 0` for the second pass even a correctly
/// rounded declaration. Planes a whole root ahead and behind give no such
/// excuse.
#[test]
fn a_root_within_1e_30_of_0_may_fall_either_side() {
    let d = strict(Semantics::NearestPositive);
    let ray = Ray::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 0.5));
    let at = |z: f32| Plane::new(Vec3::new(0.0, 0.0, z), Vec3::Z);
    let (ahead, back) = (at(1e-35), at(-1e-35));
    let (_, e) = rules::plane(&ray, &ahead).unwrap();
    assert_eq!(e.roots, Some(vec![2e-35]));
    assert_eq!(plane(&d, &ray, &ahead, Answer::Nearest(None)), None);
    assert_eq!(plane(&d, &ray, &ahead, Answer::Nearest(Some(2e-35))), None);
    assert_eq!(plane(&d, &ray, &back, Answer::Nearest(Some(0.0))), None);
    assert_eq!(plane(&d, &ray, &back, Answer::Nearest(None)), None);
    let zero = plane(&d, &ray, &at(-0.5), Answer::Nearest(Some(0.0)));
    assert_eq!(zero, Some(Fault::NotPositive));
    // A root 1 ahead is no excuse for a miss.
    let missed = plane(&d, &ray, &at(0.5), Answer::Nearest(None));
    assert_eq!(missed, Some(Fault::Missed));
}

/// The ends of a root's reach `r ± w` (`w` the allowed ulps times
/// `ulp(r)`) against the open ends of a range: a root whose reach starts
/// exactly at `t_min`, or ends exactly at `t_max`, is not surely inside,
/// so a miss passes; a hair further in, it is, and a miss is
/// [`Fault::Missed`].
#[test]
fn a_root_whose_reach_touches_an_end_may_be_missed() {
    let d = Declared::f32(Semantics::NearestPositive);
    let (ray, p) = (Ray::new(Vec3::ZERO, Vec3::Z), Plane::new(Vec3::Z, Vec3::Z));
    let (_, e) = rules::plane(&ray, &p).unwrap();
    let w = e.reach(&d, 1.0, e.kappa[0]);
    assert!(w > 0.0 && w < 1e-5, "{w}");
    let (lo, hi) = ((1.0 - w) as f32, (1.0 + w) as f32);
    assert_eq!(
        (f64::from(lo), f64::from(hi)),
        (1.0 - w, 1.0 + w),
        "exact ends"
    );
    let within = |lo: f32, hi: f32| {
        let d = Declared {
            semantics: Semantics::Range {
                t_min: lo,
                t_max: hi,
            },
            ..d
        };
        let (_, e) = rules::plane(&ray, &p).unwrap();
        let judge = |got| rules::judge(&d, &e, &got).fault;
        assert_eq!(judge(Answer::Nearest(Some(1.0))), None, "({lo}, {hi})");
        judge(Answer::Nearest(None))
    };
    assert_eq!(within(lo, 10.0), None);
    assert_eq!(within(0.0, hi), None);
    assert_eq!(within(lo.next_down(), 10.0), Some(Fault::Missed));
    assert_eq!(within(0.0, hi.next_up()), Some(Fault::Missed));
}

/// A root that overflows to `−∞` is outside any range with a finite
/// `t_min`, and the fault says so.
#[test]
fn minus_infinity_is_below_a_finite_range() {
    let (ray, s) = (
        Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z),
        Sphere::new(Vec3::ZERO, 1.0),
    );
    let d = strict("roots-in:0:10".parse().unwrap());
    let got = Answer::Roots(vec![f32::NEG_INFINITY, 4.0, 6.0]);
    let fault = sphere(&d, &ray, &s, got);
    assert_eq!(fault, Some(Fault::OutOfRange(f32::NEG_INFINITY)));
}

/// `εt² + t − 1` (ε = 2⁻²⁴) with both roots, about 1 and −2²⁴, in the
/// range: a kernel whose band covers α may take it for 0 and answer the
/// one root of `t − 1`; without a band, or answering a root near neither,
/// it fails.
#[cfg(feature = "quadric")]
#[test]
fn roots_in_a_range_may_drop_one_where_alpha_is_in_the_band() {
    use rayoracle::quadric::Quadric;
    let e = 1.0 - 2f32.powi(-24);
    let q = Quadric::new([1.0, -e, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -1.0]);
    let ray = Ray::new(Vec3::ZERO, Vec3::ONE);
    let (_, exact) = rules::quadric(&ray, &q).unwrap();
    assert_eq!(exact.roots.as_ref().map(Vec::len), Some(2));
    let s: Semantics = "roots-in:-1e9:10".parse().unwrap();
    let judge = |d: Declared, t: f32| rules::judge(&d, &exact, &Answer::Roots(vec![t])).fault;
    assert_eq!(judge(Declared::f32(s), 1.0), None);
    assert!(judge(Declared::f32(s), 2.0).is_some());
    assert!(judge(strict(s), 1.0).is_some());
}

/// A ray from `(0, 1 + 2⁻²³, −5.5)` along `(0, 0, 2)` misses the unit
/// sphere by a margin within an f32 kernel's band: a hit point at the
/// double root `t* = 2.75`, `(0, 1, 0)`, passes, because the point's `t`
/// is `(p − o)·d / d·d` (with `|d| = 2`, not 1); a point past it, and any
/// point without a band, is [`Fault::Spurious`].
#[test]
fn a_hit_point_near_a_tangent_is_judged_by_its_t() {
    let (ray, s) = (
        Ray::new(
            Vec3::new(0.0, 1f32.next_up(), -5.5),
            Vec3::new(0.0, 0.0, 2.0),
        ),
        Sphere::new(Vec3::ZERO, 1.0),
    );
    let (_, e) = rules::sphere(&ray, &s).unwrap();
    assert_eq!(e.roots, Some(vec![]));
    let f32 = Declared::f32(Semantics::NearestPositive);
    assert!(e.in_band(&f32));
    let at = |z: f32| Answer::Point(Some(Vec3::new(0.0, 1.0, z)));
    assert_eq!(sphere(&f32, &ray, &s, at(0.0)), None);
    assert_eq!(sphere(&f32, &ray, &s, at(0.5)), Some(Fault::Spurious));
    let d = strict(Semantics::NearestPositive);
    assert_eq!(sphere(&d, &ray, &s, at(0.0)), Some(Fault::Spurious));
}

/// A root `r = 2 − 2⁻²³` just below a power of two, and a range whose
/// `t_min` is where its absolute reach `r + w` ends (`w` the allowed ulps
/// times `ulp(r)`). The floats just above `t_min` are still within the
/// allowed ulps of `r`, because ulps above 2 are twice as wide: answered
/// as the nearest hit, they match `r`, and pass; one ulp further does not.
#[test]
fn a_root_below_a_power_of_two_reaches_as_far_as_its_ulps() {
    use rayoracle::ulp::step;
    let d = Declared::f32(Semantics::NearestPositive);
    let r = 2.0 - 2f32.powi(-23);
    let (ray, p) = (
        Ray::new(Vec3::ZERO, Vec3::Z),
        Plane::new(Vec3::new(0.0, 0.0, r), Vec3::Z),
    );
    let (_, e) = rules::plane(&ray, &p).unwrap();
    assert_eq!(e.roots, Some(vec![r]));
    let allowed = d.allowed_ulps(e.kappa[0]);
    let w = e.reach(&d, r, e.kappa[0]);
    assert_eq!(w, allowed * 2f64.powi(-23));
    let n = allowed.floor() as i64;
    let lo = (f64::from(r) + w) as f32;
    assert!(f64::from(lo) <= f64::from(r) + w && lo > 2.0, "{lo}");
    let d = Declared {
        semantics: Semantics::Range {
            t_min: lo,
            t_max: 10.0,
        },
        ..d
    };
    let judge = |t: Option<f32>| rules::judge(&d, &e, &Answer::Nearest(t)).fault;
    let last = step(r, n);
    assert!(last > lo.next_up(), "{last} {lo}");
    assert_eq!(judge(Some(lo.next_up())), None);
    assert_eq!(judge(Some(last)), None);
    assert_eq!(judge(Some(last.next_up())), Some(Fault::Spurious));
    assert_eq!(judge(None), None);
}

/// A hit point's own rounding is allowed at the scale of its terms,
/// `|oᵢ| + |t dᵢ|`, even to a correctly rounded kernel: from `z = −5` to the unit
/// sphere (`t = 4`, the terms 5 and 4, so an ulp of 9) and from `z = 0`
/// along `0.5` to a sphere at `z = 6` (`t = 10`, the terms 0 and 5), each
/// point may be off by its terms' ulp, plus half an ulp of `t` along `d`,
/// and no more.
#[test]
fn a_hit_points_rounding_is_allowed_at_its_terms_scale() {
    let d = strict(Semantics::NearestPositive);
    let at = |z: f32| Answer::Point(Some(Vec3::new(0.0, 0.0, z)));
    let (ray, s) = (
        Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z),
        Sphere::new(Vec3::ZERO, 1.0),
    );
    // 2⁻²¹ is within ulp(9) = 2⁻²⁰, and beyond ulp(5 − 4).
    assert_eq!(sphere(&d, &ray, &s, at(-1.0 + 2f32.powi(-21))), None);
    let (ray, s) = (
        Ray::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 0.5)),
        Sphere::new(Vec3::new(0.0, 0.0, 6.0), 1.0),
    );
    // ulp(5) + ½ ulp(10) · 0.5 = 3 · 2⁻²².
    assert_eq!(sphere(&d, &ray, &s, at(5.0 + 2f32.powi(-21))), None);
    assert_eq!(
        sphere(&d, &ray, &s, at(5.0 + 2f32.powi(-20))),
        Some(Fault::Point(10.0))
    );
}

/// A hit point is matched to a root in space, not by its `t`, so which
/// roots may be in the range decides it: the point of a root surely
/// outside the range, or of one whose interval `[a, b]` only touches an
/// open end (`b = t_min`, `a = t_max`), fails.
#[test]
fn a_hit_point_of_a_root_outside_the_range_fails() {
    let f32 = Declared::f32(Semantics::NearestPositive);
    let within = |lo: f32, hi: f32| Declared {
        semantics: Semantics::Range {
            t_min: lo,
            t_max: hi,
        },
        ..f32
    };
    let point = |z: f32| Answer::Point(Some(Vec3::new(0.0, 0.0, z)));
    // Roots 4 and 6 in (5, 10): the point of 4 is not the hit.
    let (ray, s) = (
        Ray::new(Vec3::new(0.0, 0.0, -5.0), Vec3::Z),
        Sphere::new(Vec3::ZERO, 1.0),
    );
    let d = within(5.0, 10.0);
    assert_eq!(sphere(&d, &ray, &s, point(1.0)), None);
    assert_eq!(sphere(&d, &ray, &s, point(-1.0)), Some(Fault::Point(6.0)));
    // The root 1 with its interval ending exactly at either end.
    let (ray, p) = (Ray::new(Vec3::ZERO, Vec3::Z), Plane::new(Vec3::Z, Vec3::Z));
    let (_, e) = rules::plane(&ray, &p).unwrap();
    let w = e.reach(&f32, 1.0, e.kappa[0]);
    let (a, b) = ((1.0 - w) as f32, (1.0 + w) as f32);
    assert_eq!(
        (f64::from(a), f64::from(b)),
        (1.0 - w, 1.0 + w),
        "exact ends"
    );
    let judge = |d: Declared, got| rules::judge(&d, &e, &got).fault;
    for d in [within(b, 10.0), within(0.0, a)] {
        assert_eq!(judge(d, point(1.0)), Some(Fault::Spurious));
        assert_eq!(judge(d, Answer::Point(None)), None);
    }
    assert_eq!(judge(within(b.next_down(), 10.0), point(1.0)), None);
    assert_eq!(judge(within(0.0, a.next_up()), point(1.0)), None);
}

/// The answer the gate expects of a solid: `t = 0` with the origin
/// inside or on the surface, else the nearest root ahead; a range with
/// the origin inside still expects its nearest root.
#[test]
fn a_solid_expects_zero_inside_and_the_nearest_root_outside() {
    let s = Sphere::new(Vec3::ZERO, 1.5);
    let expected = |o: Vec3, sem: Semantics| {
        let (_, e) = rules::sphere(&Ray::new(o, Vec3::Z), &s).unwrap();
        e.expected(&strict(sem))
    };
    let (inside, on, outside) = (
        Vec3::new(0.0, 0.0, 0.5),
        Vec3::new(0.0, 0.0, -1.5),
        Vec3::new(0.0, 0.0, -5.0),
    );
    assert_eq!(
        expected(inside, Semantics::Solid),
        Answer::Nearest(Some(0.0))
    );
    assert_eq!(expected(on, Semantics::Solid), Answer::Nearest(Some(0.0)));
    assert_eq!(
        expected(outside, Semantics::Solid),
        Answer::Nearest(Some(3.5))
    );
    let range = "range:0:10".parse().unwrap();
    assert_eq!(expected(inside, range), Answer::Nearest(Some(1.0)));
    assert_eq!(
        expected(inside, Semantics::NearestPositive),
        Answer::Nearest(Some(1.0))
    );
}

/// A root's interval reaches `allowed · ulp(r)` even where the allowance
/// is not a whole number of ulps: with the faithful allowance of `1 + ε`
/// ulps, the root 1 reaches past `t_min = 1 + ulp`, so its hit point
/// passes.
#[test]
fn a_roots_interval_reaches_its_whole_allowance() {
    let d = Declared::faithful(Semantics::NearestPositive);
    let (ray, p) = (Ray::new(Vec3::ZERO, Vec3::Z), Plane::new(Vec3::Z, Vec3::Z));
    let (_, e) = rules::plane(&ray, &p).unwrap();
    let allowed = d.allowed_ulps(e.kappa[0]);
    assert!(allowed > 1.0 && allowed < 2.0, "{allowed}");
    let d = Declared {
        semantics: Semantics::Range {
            t_min: 1f32.next_up(),
            t_max: 10.0,
        },
        ..d
    };
    let point = Answer::Point(Some(Vec3::Z));
    assert_eq!(rules::judge(&d, &e, &point).fault, None);
}

/// A root exactly at 0 has an infinite κ, so an f32 kernel is allowed any
/// ulps on it, but no absolute reach: from a sphere's surface (roots 0
/// and 2), the nearest hit is 2, and 1 is wrong, not a rounding of 0.
#[test]
fn a_root_at_zero_reaches_nowhere() {
    let d = Declared::f32(Semantics::NearestPositive);
    let (ray, s) = (
        Ray::new(Vec3::new(0.0, 0.0, -1.0), Vec3::Z),
        Sphere::new(Vec3::ZERO, 1.0),
    );
    let (_, e) = rules::sphere(&ray, &s).unwrap();
    assert_eq!(e.roots, Some(vec![0.0, 2.0]));
    assert_eq!(d.allowed_ulps(e.kappa[0]), f64::INFINITY);
    assert_eq!(e.reach(&d, 0.0, e.kappa[0]), 0.0);
    assert_eq!(
        rules::judge(&d, &e, &Answer::Nearest(Some(2.0))).fault,
        None
    );
    assert!(
        rules::judge(&d, &e, &Answer::Nearest(Some(1.0)))
            .fault
            .is_some()
    );
}

/// The mirror of [`a_root_below_a_power_of_two_reaches_as_far_as_its_ulps`]
/// below 0: the root `−(2 − 2⁻²³)` reaches down past `r − w` by its
/// ulps, which below −2 are twice as wide, so a hit just below a `t_max`
/// at `r − w` matches it.
#[test]
fn a_negative_root_reaches_down_as_far_as_its_ulps() {
    use rayoracle::ulp::step;
    let d = Declared::f32(Semantics::NearestPositive);
    let r = -(2.0 - 2f32.powi(-23));
    let (ray, p) = (
        Ray::new(Vec3::ZERO, Vec3::Z),
        Plane::new(Vec3::new(0.0, 0.0, r), Vec3::Z),
    );
    let (_, e) = rules::plane(&ray, &p).unwrap();
    assert_eq!(e.roots, Some(vec![r]));
    let w = e.reach(&d, r, e.kappa[0]);
    let hi = (f64::from(r) - w) as f32;
    assert_eq!(f64::from(hi), f64::from(r) - w, "exact end");
    let d = Declared {
        semantics: Semantics::Range {
            t_min: -10.0,
            t_max: hi,
        },
        ..d
    };
    let n = d.allowed_ulps(e.kappa[0]).floor() as i64;
    let judge = |t: f32| rules::judge(&d, &e, &Answer::Nearest(Some(t))).fault;
    assert_eq!(judge(hi.next_down()), None);
    assert_eq!(judge(step(r, -n)), None);
    assert_eq!(judge(step(r, -n).next_down()), Some(Fault::Spurious));
}

/// Where a root's error is absolute it reaches `allowed · ulp(r)`: a
/// linear root of a quadric (α = 0) whose β is computed well; but not a
/// root next to a double root, whose error is not linear in the margin's.
#[cfg(feature = "quadric")]
#[test]
fn a_root_reaches_where_its_error_is_absolute() {
    use rayoracle::quadric::Quadric;
    let d = Declared::f32(Semantics::WholeLine);
    // x² + z − 1.5 along (0, 0, 1) from (0, 0, −1): α = 0, β = 1.
    let q = Quadric::new([1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, -1.5]);
    let ray = Ray::new(Vec3::new(0.0, 0.0, -1.0), Vec3::Z);
    let (_, e) = rules::quadric(&ray, &q).unwrap();
    assert_eq!(e.roots, Some(vec![2.5]));
    let reach = e.reach(&d, 2.5, e.kappa[0]);
    assert_eq!(reach, d.allowed_ulps(e.kappa[0]) * 2f64.powi(-22));
    // Roots about 5 ± 3·10⁻⁷, one ulp either side of the double root 5:
    // a faithful kernel's allowance there already covers the double root.
    let r = 2f32.powi(-10);
    let (ray, s) = (
        Ray::new(Vec3::new(0.0, r * (1.0 - 2f32.powi(-24)), -5.0), Vec3::Z),
        Sphere::new(Vec3::ZERO, r),
    );
    let (_, e) = rules::sphere(&ray, &s).unwrap();
    let roots = e.roots.clone().unwrap();
    assert_eq!(roots.len(), 2);
    let d = Declared::faithful(Semantics::WholeLine);
    for (i, &x) in roots.iter().enumerate() {
        assert!((x - 5.0).abs() <= 5e-7, "{x}");
        assert_eq!(e.reach(&d, x, e.kappa[i]), 0.0, "{x}");
    }
}

/// Near a tangent, within a band, each root of the other class must lie
/// within `√(2(|margin| + band·scale))·a^(−3/2)` of the double root. From
/// `(0, 1 − 2⁻²⁴, −5)` along `(0, 0, 2)` to the unit sphere, the exact
/// roots are two near the double root 2.5, the margin is about `2⁻¹⁹`
/// and the band about `5.5·10⁻¹²`, so under `f32` (scale `2²⁰`) the reach
/// is about `4.9·10⁻⁴`: one root at 2.5 or `4·10⁻⁴` past it passes,
/// `6·10⁻⁴` past it is [`Fault::Stray`].
#[test]
fn a_tangents_roots_reach_as_far_as_its_band() {
    let (ray, s) = (
        Ray::new(
            Vec3::new(0.0, 1.0 - 2f32.powi(-24), -5.0),
            Vec3::new(0.0, 0.0, 2.0),
        ),
        Sphere::new(Vec3::ZERO, 1.0),
    );
    let (_, e) = rules::sphere(&ray, &s).unwrap();
    assert_eq!(e.roots.as_ref().map(Vec::len), Some(2));
    let f32 = Declared::f32(Semantics::WholeLine);
    for t in [2.5, 2.5004, 2.4996] {
        assert_eq!(sphere(&f32, &ray, &s, Answer::Roots(vec![t])), None, "{t}");
    }
    for t in [2.5006, 2.4994] {
        let far = sphere(&f32, &ray, &s, Answer::Roots(vec![t]));
        assert_eq!(far, Some(Fault::Stray(t)));
    }
}

/// A ray parallel to a plane (`d·n = 0.5 − 0.5`) and `2⁻²⁴` off it (an
/// offset `0.5 − (0.5 + 2⁻²⁴)`): with no vertex, a root answered within a
/// band must make `(|d·n| band · |t| + offset band) · scale` reach the
/// offset. Both bands are about `2⁻⁴⁴`, so at a scale of `2¹⁹` that holds
/// from `|t| = 1 − 2⁻²⁴` on: `t = ±1` passes, `t = 0.5` is
/// [`Fault::Stray`].
#[test]
fn a_root_of_a_parallel_ray_must_reach_the_offset() {
    let (ray, p) = (
        Ray::new(
            Vec3::new(0.5, 0.5 + 2f32.powi(-24), 0.0),
            Vec3::new(0.5, 0.5, 0.0),
        ),
        Plane::new(Vec3::ZERO, Vec3::new(1.0, -1.0, 0.0)),
    );
    let (_, e) = rules::plane(&ray, &p).unwrap();
    assert_eq!((e.roots.clone(), e.margin), (Some(vec![]), 0.0));
    let d = Declared {
        band_scale: 2f64.powi(19),
        ..Declared::f32(Semantics::WholeLine)
    };
    for t in [1.0, -1.0, 4.0] {
        assert_eq!(plane(&d, &ray, &p, Answer::Roots(vec![t])), None, "{t}");
    }
    let near = plane(&d, &ray, &p, Answer::Roots(vec![0.5]));
    assert_eq!(near, Some(Fault::Stray(0.5)));
}

/// A quadric whose α and β are exactly 0 from terms that are not
/// (`x² − y² + 2⁻³⁰` from `(1, 1, 0)` along `(1, 1, 0)`: α = 1 − 1,
/// β = 2 − 2, γ = 2⁻³⁰): no vertex, so a root answered within a band must
/// make `(|α| band · t² + |β| band · |t| + γ band) · scale` reach γ. With
/// bands `2⁻⁴³`, `2⁻⁴²` and about `2⁻⁴³` and a scale of `2¹⁰`, that is
/// `(t + 1)² ≥ 8`: `t = 2` passes, `t = 1.75` is [`Fault::Stray`].
#[cfg(feature = "quadric")]
#[test]
fn a_root_where_alpha_and_beta_vanish_must_reach_gamma() {
    use rayoracle::quadric::Quadric;
    let q = Quadric::new([1.0, -1.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 2f32.powi(-30)]);
    let ray = Ray::new(Vec3::new(1.0, 1.0, 0.0), Vec3::new(1.0, 1.0, 0.0));
    let (_, e) = rules::quadric(&ray, &q).unwrap();
    assert_eq!(e.roots, Some(vec![]));
    let d = Declared {
        band_scale: 2f64.powi(10),
        ..Declared::f32(Semantics::WholeLine)
    };
    let judge = |t: f32| rules::judge(&d, &e, &Answer::Roots(vec![t])).fault;
    for t in [2.0, -2.0, 100.0] {
        assert_eq!(judge(t), None, "{t}");
    }
    assert_eq!(judge(1.75), Some(Fault::Stray(1.75)));
}

/// A double root at `t* = −0` (`f·d = +0`, so `−f·d/a = −0`) and a nearest
/// hit at `+0`: the same value, so within any reach, even under a
/// declaration that allows no ulps (exact roots, a band on the class
/// only). From `(0.75, 1, 0)` along z, the sphere of radius 1.25 about
/// `(0, −2⁻³⁰, 0)` is missed by about `2⁻³⁰`, well within the band.
#[test]
fn a_hit_at_plus_zero_is_at_a_double_root_of_minus_zero() {
    let (ray, s) = (
        Ray::new(Vec3::new(0.75, 1.0, 0.0), Vec3::Z),
        Sphere::new(Vec3::new(0.0, -(2f32.powi(-30)), 0.0), 1.25),
    );
    let d = Declared {
        band_scale: 2f64.powi(20),
        ..strict("range:-1:1".parse().unwrap())
    };
    let (_, e) = rules::sphere(&ray, &s).unwrap();
    assert_eq!(e.roots, Some(vec![]));
    assert!(e.in_band(&d) && d.allowed_ulps(1.0) == 0.0);
    assert_eq!(sphere(&d, &ray, &s, Answer::Nearest(Some(0.0))), None);
    let far = sphere(&d, &ray, &s, Answer::Nearest(Some(1e-3)));
    assert_eq!(far, Some(Fault::Spurious));
}
