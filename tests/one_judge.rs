//! One judge: `check_*` and the gate under the strictest declaration
//! (`Declared::correctly_rounded`) give the same pass or fail, on every
//! compiled-in fixture and stiff case, for the exact answer and for answers
//! perturbed from it (a root one ulp off either way, the other sign of
//! zero, a NaN, roots swapped, another class). Both must pass exactly the
//! answers with the exact answer's class and bits.
#![cfg(all(feature = "plane", feature = "sphere", feature = "quadric"))]

use glam::Vec3;
use rayoracle::Ray;
use rayoracle::camera::{self, CameraError};
use rayoracle::case::{Case, parse_line};
use rayoracle::check::gate::{Answer, Declared, Gate, Semantics};
use rayoracle::check::{check_camera, check_plane, check_quadric, check_sphere};
use rayoracle::hit::{Intersection, same_bits};
use rayoracle::plane::{self, PlaneHit};
use rayoracle::quadric::{self, QuadricHit};
use rayoracle::sphere::{self, SphereHit};

fn strict() -> Gate {
    Gate::new(Declared::correctly_rounded(Semantics::WholeLine))
}

/// Every case of a kind, from the fixtures and the stiff catalogue.
fn cases(kind: &str) -> Vec<(String, Case)> {
    let k: rayoracle::case::Kind = kind.parse().expect("a kind");
    let text = [rayoracle::fixtures::cases(k), rayoracle::fixtures::stiff(k)];
    let mut out = Vec::new();
    for (i, line) in text.iter().flat_map(|t| t.lines()).enumerate() {
        if line.trim().is_empty() {
            continue;
        }
        let c = parse_line(line).unwrap_or_else(|e| panic!("{kind} line {i}: {e}"));
        out.push((line.to_string(), c.case));
    }
    out
}

/// The floats next to `t`, its other zero, and a NaN.
fn near(t: f32) -> Vec<f32> {
    let mut v = vec![t.next_up(), t.next_down(), f32::NAN];
    if t == 0.0 {
        v.push(-t);
    }
    v
}

/// Answers perturbed from the exact roots `r`: each root moved to each of
/// its neighbours, the roots swapped, and the counts of 0, 1 and 2 roots.
fn perturbed<H>(r: &[f32], make: impl Fn(&[f32]) -> Option<H>) -> Vec<H> {
    let mut out = Vec::new();
    for i in 0..r.len() {
        for t in near(r[i]) {
            let mut g = r.to_vec();
            g[i] = t;
            out.extend(make(&g));
        }
    }
    if let [a, b] = r {
        out.extend(make(&[*b, *a]));
    }
    let t = r.first().copied().unwrap_or(1.0);
    for g in [vec![], vec![t], vec![t, t], vec![t, t.next_up()]] {
        out.extend(make(&g));
    }
    out
}

/// For each answer: check's pass is the gate's, and both pass exactly the
/// exact answer's bits. Returns how many answers passed and failed.
fn agree<H: Intersection + Copy + std::fmt::Debug>(
    line: &str,
    exact: Option<H>,
    answers: impl IntoIterator<Item = H>,
    check: impl Fn(H) -> bool,
    gate: impl Fn(Answer) -> bool,
) -> [usize; 2] {
    let mut seen = [0, 0];
    for h in answers {
        let (c, g) = (check(h), gate(Answer::roots(h)));
        assert_eq!(c, g, "{line}\n  {h:?}: check {c}, gate {g}");
        let right = exact.is_none_or(|e| same_bits(&e, &h));
        assert_eq!(c, right, "{line}\n  {h:?} against {exact:?}");
        seen[usize::from(c)] += 1;
    }
    seen
}

#[test]
fn check_and_the_strict_gate_agree_on_spheres() {
    let mut seen = [0, 0];
    for (line, case) in cases("sphere") {
        let Case::Sphere(ray, s) = case else { continue };
        let exact = sphere::exact::intersect(&ray, &s).ok();
        let r = exact.map_or(vec![4.0, 6.0], |e| e.roots().as_slice().to_vec());
        let mut answers = perturbed(&r, |g| match g {
            [] => Some(SphereHit::None),
            [t] => Some(SphereHit::Tangent(*t)),
            [a, b] => Some(SphereHit::Two(*a, *b)),
            _ => None,
        });
        answers.extend(exact);
        answers.push(sphere::reference::intersect(&ray, &s));
        let n = agree(
            &line,
            exact,
            answers,
            |h| check_sphere(&ray, &s, h).is_ok(),
            |a| strict().judge_sphere(&ray, &s, a).is_ok(),
        );
        seen = [seen[0] + n[0], seen[1] + n[1]];
    }
    assert!(seen[0] > 20_000 && seen[1] > 5000, "{seen:?}");
}

#[test]
fn check_and_the_strict_gate_agree_on_quadrics() {
    let mut seen = [0, 0];
    for (line, case) in cases("quadric") {
        let Case::Quadric(ray, q) = case else {
            continue;
        };
        let exact = quadric::exact::intersect(&ray, &q).ok();
        let r = exact.map_or(vec![4.0, 6.0], |e| e.roots().as_slice().to_vec());
        let mut answers = perturbed(&r, |g| match g {
            [] => Some(QuadricHit::None),
            [t] => Some(QuadricHit::One(*t)),
            [a, b] => Some(QuadricHit::Two(*a, *b)),
            _ => None,
        });
        answers.extend(exact);
        answers.extend([QuadricHit::All, quadric::reference::intersect(&ray, &q)]);
        let n = agree(
            &line,
            exact,
            answers,
            |h| check_quadric(&ray, &q, h).is_ok(),
            |a| strict().judge_quadric(&ray, &q, a).is_ok(),
        );
        seen = [seen[0] + n[0], seen[1] + n[1]];
    }
    assert!(seen[0] > 20_000 && seen[1] > 6000, "{seen:?}");
}

#[test]
fn check_and_the_strict_gate_agree_on_planes() {
    let mut seen = [0, 0];
    for (line, case) in cases("plane") {
        let Case::Plane(ray, p) = case else { continue };
        let exact = plane::exact::intersect(&ray, &p).ok();
        let r = exact.map_or(vec![1.0], |e| e.roots().as_slice().to_vec());
        let mut answers = perturbed(&r, |g| match g {
            [] => Some(PlaneHit::Parallel),
            [t] => Some(PlaneHit::Hit(*t)),
            _ => None,
        });
        answers.extend(exact);
        answers.extend([PlaneHit::InPlane, plane::reference::intersect(&ray, &p)]);
        let n = agree(
            &line,
            exact,
            answers,
            |h| check_plane(&ray, &p, h).is_ok(),
            |a| strict().judge_plane(&ray, &p, a).is_ok(),
        );
        seen = [seen[0] + n[0], seen[1] + n[1]];
    }
    assert!(seen[0] > 4000 && seen[1] > 3000, "{seen:?}");
}

/// A camera's ray with one direction component moved to `t`.
fn moved(r: Ray, axis: usize, t: f32) -> Ray {
    let mut d = r.dir.to_array();
    d[axis] = t;
    Ray::new(r.origin, Vec3::from_array(d))
}

#[test]
fn check_and_the_strict_gate_agree_on_cameras() {
    let mut seen = [0, 0];
    for (line, case) in cases("camera") {
        let Case::Camera(p, px) = case else { continue };
        let exact = camera::exact::ray(&p, px[0], px[1]);
        let mut answers: Vec<Result<Ray, CameraError>> = vec![exact, Err(CameraError::DirZero)];
        let somewhere = Ray::new(Vec3::ZERO, Vec3::Z);
        match exact {
            Ok(x) => {
                for axis in 0..3 {
                    answers.extend(near(x.dir[axis]).into_iter().map(|t| Ok(moved(x, axis, t))));
                }
                answers.push(Ok(Ray::new(x.origin + Vec3::X, x.dir)));
            }
            Err(_) => answers.push(Ok(somewhere)),
        }
        for got in answers {
            let c = check_camera(&p, px, got).is_ok();
            let g = strict().judge_camera(&p, px, got.ok()).is_ok();
            // The gate's kernels refuse without naming an error, so only
            // check can tell one error from another.
            let named_wrong = matches!((exact, got), (Err(e), Err(g)) if e != g);
            assert_eq!(
                c || named_wrong,
                g,
                "{line}\n  {got:?}: check {c}, gate {g}"
            );
            let right = match (exact, got) {
                (Ok(x), Ok(g)) => same_ray(x, g),
                (Err(e), Err(g)) => format!("{e:?}") == format!("{g:?}"),
                _ => false,
            };
            assert_eq!(c, right, "{line}\n  {got:?} against {exact:?}");
            seen[usize::from(c)] += 1;
        }
    }
    assert!(seen[0] > 10_000 && seen[1] > 1000, "{seen:?}");
}

fn same_ray(a: Ray, b: Ray) -> bool {
    let bits = |v: Vec3| v.to_array().map(f32::to_bits);
    (bits(a.origin), bits(a.dir)) == (bits(b.origin), bits(b.dir))
}

/// The one place the strict gate and check part: two equal roots are not
/// a tangent for either, while a declaration with a band takes them for
/// one.
#[test]
fn a_tangent_twice_is_a_tangent_only_with_a_band() {
    let (ray, s) = (
        Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z),
        sphere::Sphere::new(Vec3::ZERO, 1.0),
    );
    let twice = SphereHit::Two(5.0, 5.0);
    assert!(check_sphere(&ray, &s, twice).is_err());
    assert!(
        strict()
            .judge_sphere(&ray, &s, Answer::roots(twice))
            .is_err()
    );
    let f32 = Gate::new(Declared::f32(Semantics::WholeLine));
    assert!(f32.judge_sphere(&ray, &s, Answer::roots(twice)).is_ok());
}
