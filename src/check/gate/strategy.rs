//! The gate's families as proptest strategies, for a user's own property
//! tests: the fixture and stiff families sample their cases; the random
//! families generate new ones.
//!
//! ```
//! use proptest::prelude::*;
//! use rayoracle::check::gate::{Declared, Gate, Semantics, strategy};
//! use rayoracle::sphere;
//!
//! let gate = Gate::new(Declared::f32(Semantics::WholeLine));
//! let mut runner = proptest::test_runner::TestRunner::default();
//! for family in strategy::families("sphere") {
//!     let cases = strategy::sphere(&family).unwrap();
//!     runner.run(&cases, |(ray, s)| {
//!         let answer = rayoracle::check::gate::Answer::roots(sphere::plain::intersect(&ray, &s));
//!         gate.judge_sphere(&ray, &s, answer).map_err(|f| TestCaseError::fail(f.to_string()))
//!     }).unwrap();
//! }
//! ```

use super::Gate;
use crate::Ray;
use crate::camera::CameraParams;
use crate::case::Case;
use crate::plane::Plane;
use crate::quadric::Quadric;
use crate::sphere::Sphere;
use glam::Vec3;
use proptest::prelude::*;

/// Every family name of a kind (`sphere`, `plane`, `quadric`, `camera`):
/// the fixture families, the stiff families and the random ones.
///
/// ```
/// let f = rayoracle::check::gate::strategy::families("sphere");
/// assert!(f.contains(&"sphere/far-tiny".to_string()));
/// assert!(f.contains(&"sphere/random/aimed".to_string()));
/// ```
pub fn families(kind: &str) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    for (f, _) in Gate::new(super::Declared::f32(super::Semantics::WholeLine))
        .sources(kind, 1)
        .0
    {
        if !names.contains(&f) {
            names.push(f);
        }
    }
    names
}

/// A family's cases: the compiled-in ones, or 256 drawn cases of a
/// generated family that has no strategy of its own.
fn cases_of(family: &str) -> Vec<Case> {
    let kind = family.split('/').next().unwrap_or("");
    let drawn = if family.contains("/random/") { 256 } else { 0 };
    Gate::new(super::Declared::f32(super::Semantics::WholeLine))
        .sources(kind, drawn)
        .0
        .into_iter()
        .filter(|(f, _)| f == family)
        .map(|(_, c)| c)
        .collect()
}

/// A vector with components in `(−s, s)`.
fn v3(s: f32) -> impl Strategy<Value = Vec3> {
    (-s..s, -s..s, -s..s).prop_map(|(x, y, z)| Vec3::new(x, y, z))
}

macro_rules! kind_strategy {
    ($(#[$doc:meta])* $name:ident, $variant:ident, $prim:ty, $random:expr) => {
        $(#[$doc])*
        pub fn $name(family: &str) -> Option<BoxedStrategy<(Ray, $prim)>> {
            if let Some(s) = ($random)(family) {
                return Some(s);
            }
            let cases: Vec<(Ray, $prim)> = cases_of(family)
                .into_iter()
                .filter_map(|c| match c {
                    Case::$variant(r, p) => Some((r, p)),
                    _ => None,
                })
                .collect();
            (!cases.is_empty()).then(|| proptest::sample::select(cases).boxed())
        }
    };
}

kind_strategy!(
    /// The cases of a sphere family as a strategy (`None` for an unknown
    /// family). `sphere/random/aimed` and `sphere/random/inside` generate;
    /// the other generated families sample 256 drawn cases.
    sphere, Sphere, Sphere, |family: &str| match family {
        "sphere/random/aimed" => Some(
            (v3(10.0), 0.1f32..5.0, v3(30.0), v3(1.0))
                .prop_map(|(c, r, off, aim)| (Ray::new(c + off, c + aim * r - (c + off)), Sphere::new(c, r)))
                .boxed(),
        ),
        "sphere/random/inside" => Some(
            (v3(10.0), 0.1f32..5.0, v3(0.5), v3(1.0))
                .prop_map(|(c, r, off, d)| (Ray::new(c + off * r, d), Sphere::new(c, r)))
                .boxed(),
        ),
        _ => None,
    }
);

kind_strategy!(
    /// The cases of a plane family as a strategy. `plane/random/any`
    /// generates.
    plane, Plane, Plane, |family: &str| match family {
        "plane/random/any" => Some(
            (v3(20.0), v3(1.0), v3(10.0), v3(1.0))
                .prop_map(|(o, d, a, n)| (Ray::new(o, d), Plane::new(a, n)))
                .boxed(),
        ),
        _ => None,
    }
);

kind_strategy!(
    /// The cases of a quadric family as a strategy. `quadric/random/any`
    /// generates.
    quadric, Quadric, Quadric, |family: &str| match family {
        "quadric/random/any" => Some(
            (v3(6.0), v3(1.0), prop::array::uniform10(-2.0f32..2.0))
                .prop_map(|(o, d, k)| (Ray::new(o, d), Quadric::new(k)))
                .boxed(),
        ),
        _ => None,
    }
);

/// The cases of a camera family as a strategy: the parameters and a pixel.
/// `camera/random/any` generates (valid cameras only).
///
/// ```
/// assert!(rayoracle::check::gate::strategy::camera("camera/fov-range").is_some());
/// assert!(rayoracle::check::gate::strategy::camera("camera/nope").is_none());
/// ```
pub fn camera(family: &str) -> Option<BoxedStrategy<(CameraParams, [u32; 2])>> {
    if family == "camera/random/any" {
        return Some(
            (
                v3(10.0),
                v3(1.0),
                v3(1.0),
                0.1f32..3.0,
                1u32..2000,
                1u32..2000,
            )
                .prop_flat_map(|(pos, dir, up, angle, w, h)| {
                    let p = CameraParams::new(pos, dir, up, angle, [w, h]);
                    (Just(p), 0..w, 0..h)
                })
                .prop_filter("a camera that builds", |(p, _, _)| p.build().is_ok())
                .prop_map(|(p, x, y)| (p, [x, y]))
                .boxed(),
        );
    }
    let cases: Vec<(CameraParams, [u32; 2])> = cases_of(family)
        .into_iter()
        .filter_map(|c| match c {
            Case::Camera(p, px) => Some((p, px)),
            _ => None,
        })
        .collect();
    (!cases.is_empty()).then(|| proptest::sample::select(cases).boxed())
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::strategy::ValueTree;
    use proptest::test_runner::TestRunner;

    /// `n` values of `s`.
    fn draw<T: std::fmt::Debug>(s: BoxedStrategy<T>, runner: &mut TestRunner, n: usize) -> Vec<T> {
        (0..n)
            .map(|_| s.new_tree(runner).expect("a value").current())
            .collect()
    }

    /// Every family of every kind, named once, has a strategy: a fixture
    /// family's draws are its own compiled-in cases, which together are
    /// every compiled-in case of the kind; a random family's are finite.
    /// An unknown family has none.
    #[test]
    fn every_family_draws_its_own_cases() {
        let mut runner = TestRunner::deterministic();
        for kind in ["plane", "sphere", "quadric", "camera"] {
            let names = families(kind);
            let mut once = names.clone();
            once.sort();
            once.dedup();
            assert_eq!(once.len(), names.len(), "{kind}: {names:?}");
            assert!(names.iter().all(|n| n.starts_with(&format!("{kind}/"))));
            assert!(names.iter().any(|n| n.contains("/random/")), "{kind}");
            let fixed: Vec<&String> = names.iter().filter(|n| !n.contains("/random/")).collect();
            assert!(fixed.len() >= 2, "{kind}");
            let all = Gate::new(super::super::Declared::f32(
                super::super::Semantics::WholeLine,
            ))
            .sources(kind, 0)
            .0;
            let total: usize = fixed.iter().map(|f| cases_of(f).len()).sum();
            assert_eq!(total, all.len(), "{kind}");
            for family in &names {
                let own = cases_of(family);
                let drawn: Vec<Case> = match kind {
                    "plane" => draw(plane(family).unwrap(), &mut runner, 8)
                        .into_iter()
                        .map(|(r, p)| Case::Plane(r, p))
                        .collect(),
                    "sphere" => draw(sphere(family).unwrap(), &mut runner, 8)
                        .into_iter()
                        .map(|(r, s)| Case::Sphere(r, s))
                        .collect(),
                    "quadric" => draw(quadric(family).unwrap(), &mut runner, 8)
                        .into_iter()
                        .map(|(r, q)| Case::Quadric(r, q))
                        .collect(),
                    _ => draw(camera(family).unwrap(), &mut runner, 8)
                        .into_iter()
                        .map(|(p, px)| Case::Camera(p, px))
                        .collect(),
                };
                for c in &drawn {
                    if family.contains("/random/") {
                        assert!(!format!("{c:?}").contains("NaN"), "{family}: {c:?}");
                    } else {
                        // By their printed values, so that a NaN input
                        // matches itself.
                        let same = |o: &Case| format!("{o:?}") == format!("{c:?}");
                        assert!(own.iter().any(same), "{family}: {c:?}");
                    }
                }
            }
        }
        assert!(sphere("sphere/no-such-family").is_none());
        assert!(plane("sphere/far-tiny").is_none());
    }
}
