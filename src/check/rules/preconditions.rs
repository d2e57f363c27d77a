//! Declared preconditions: the inputs a kernel is meant for. A case that
//! violates one is skipped, not judged, and the gate counts the skips of
//! each precondition by its name.
//!
//! | name | the case is skipped when |
//! |---|---|
//! | `unit-dirs` | the direction's `f32` normalisation is zero or not finite (the other cases are fed normalised) |
//! | `no-subnormals` | an input is subnormal |
//! | `magnitudes:LO:HI` | the largest magnitude of a finite nonzero input (a vector's largest component, the radius, the quadric's largest coefficient) is below `LO` or above `HI` |
//! | `off-surface` | the ray starts exactly on the surface (the surface's function is exactly 0 at the origin): a renderer offsets such origins or asks for `t > t_min`, since no f32 kernel resolves the sign of roots that close to 0 |
//! | `spread:K` | the largest of those magnitudes, the direction's left out, is more than `K` times the least nonzero one: a scene whose extent and smallest feature are that far apart (a sphere `10⁹` radii away) is beyond an `f32` kernel's resolution |

use super::Declared;
use crate::Ray;
use crate::case::Case;
use glam::Vec3;

impl Declared {
    /// Every precondition's form, for error messages and help texts.
    pub const PRECONDITIONS: &'static str =
        "unit-dirs, no-subnormals, magnitudes:LO:HI (0 ≤ LO ≤ HI), spread:K (K ≥ 1), off-surface";

    /// The same, skipping cases with a subnormal input.
    pub fn no_subnormals(self) -> Declared {
        Declared {
            no_subnormals: true,
            ..self
        }
    }

    /// The same, skipping cases with a finite nonzero input whose largest
    /// magnitude is outside `[lo, hi]`: a vector's largest component (so
    /// that a tiny component of a unit vector is no reason to skip), the
    /// radius, the quadric's largest coefficient, the camera's angle.
    pub fn magnitudes(self, lo: f32, hi: f32) -> Declared {
        Declared {
            magnitudes: Some((lo, hi)),
            ..self
        }
    }

    /// The same, skipping cases whose largest input magnitude (the
    /// direction's left out) is more than `k` times the least nonzero one.
    ///
    /// ```
    /// # #[cfg(feature = "sphere")] {
    /// use rayoracle::check::rules::{Declared, Semantics};
    /// use rayoracle::{Ray, case::Case, sphere::Sphere};
    /// use glam::Vec3;
    /// let d = Declared::f32(Semantics::NearestPositive).spread(1e6);
    /// let far = Case::Sphere(Ray::new(Vec3::ZERO, Vec3::Z), Sphere::new(Vec3::new(0.0, 0.0, 1e9), 4.0));
    /// assert_eq!(d.skips(&far), Some("spread"));
    /// let near = Case::Sphere(Ray::new(Vec3::ZERO, Vec3::Z), Sphere::new(Vec3::new(0.0, 0.0, 1e3), 4.0));
    /// assert_eq!(d.skips(&near), None);
    /// # }
    /// ```
    pub fn spread(self, k: f32) -> Declared {
        Declared {
            spread: Some(k),
            ..self
        }
    }

    /// The same, skipping rays that start exactly on the surface.
    ///
    /// ```
    /// # #[cfg(feature = "sphere")] {
    /// use rayoracle::check::rules::{Declared, Semantics};
    /// use rayoracle::{Ray, case::Case, sphere::Sphere};
    /// use glam::Vec3;
    /// let d = Declared::f32(Semantics::NearestPositive).off_surface();
    /// let s = Sphere::new(Vec3::ZERO, 1.0);
    /// assert_eq!(d.skips(&Case::Sphere(Ray::new(Vec3::X, Vec3::Y), s)), Some("off-surface"));
    /// assert_eq!(d.skips(&Case::Sphere(Ray::new(Vec3::new(1.5, 0.0, 0.0), Vec3::Y), s)), None);
    /// # }
    /// ```
    pub fn off_surface(self) -> Declared {
        Declared {
            off_surface: true,
            ..self
        }
    }

    /// The same with the precondition named `spec`, or an error listing
    /// the valid forms ([`Declared::PRECONDITIONS`]):
    ///
    /// | name | the case is skipped when |
    /// |---|---|
    /// | `unit-dirs` | the direction's `f32` normalisation is zero or not finite (the other cases are fed normalised) |
    /// | `no-subnormals` | an input is subnormal |
    /// | `magnitudes:LO:HI` | the largest magnitude of a finite nonzero input (a vector's largest component, the radius, the quadric's largest coefficient) is below `LO` or above `HI` |
    /// | `off-surface` | the ray starts exactly on the surface (the surface's function is exactly 0 at the origin): a renderer offsets such origins or asks for `t > t_min`, since no f32 kernel resolves the sign of roots that close to 0 |
    /// | `spread:K` | the largest of those magnitudes, the direction's left out, is more than `K` times the least nonzero one: a scene whose extent and smallest feature are that far apart (a sphere `10⁹` radii away) is beyond an `f32` kernel's resolution |
    ///
    /// ```
    /// use rayoracle::check::rules::{Declared, Semantics};
    /// let d = Declared::f32(Semantics::NearestPositive);
    /// let d = d.require("unit-dirs").unwrap().require("magnitudes:1e-9:1e9").unwrap();
    /// assert!(d.unit_dirs_only && d.magnitudes == Some((1e-9, 1e9)));
    /// assert!(d.require("positive").unwrap_err().contains("no-subnormals"));
    /// ```
    pub fn require(self, spec: &str) -> Result<Declared, String> {
        let bad = || {
            format!(
                "unknown precondition {spec:?}: valid forms are {}",
                Self::PRECONDITIONS
            )
        };
        match spec {
            "unit-dirs" => Ok(self.unit_dirs()),
            "no-subnormals" => Ok(self.no_subnormals()),
            "off-surface" => Ok(self.off_surface()),
            _ if spec.starts_with("spread:") => match spec["spread:".len()..].parse::<f32>() {
                Ok(k) if k >= 1.0 => Ok(self.spread(k)),
                _ => Err(bad()),
            },
            _ => {
                let rest = spec.strip_prefix("magnitudes:").ok_or_else(bad)?;
                let (a, b) = rest.split_once(':').ok_or_else(bad)?;
                let (lo, hi) = (
                    a.parse::<f32>().map_err(|_| bad())?,
                    b.parse::<f32>().map_err(|_| bad())?,
                );
                if 0.0 <= lo && lo <= hi {
                    Ok(self.magnitudes(lo, hi))
                } else {
                    Err(bad())
                }
            }
        }
    }

    /// The name of the first declared precondition `case` violates, or
    /// `None` if it meets them all. With `unit-dirs`, `case` is taken as
    /// the gate feeds it: normalised first ([`Declared::prepare`]).
    ///
    /// ```
    /// # #[cfg(feature = "sphere")] {
    /// use rayoracle::check::rules::{Declared, Semantics};
    /// use rayoracle::{Ray, case::Case, sphere::Sphere};
    /// use glam::Vec3;
    /// let d = Declared::f32(Semantics::NearestPositive).unit_dirs().no_subnormals();
    /// let s = Sphere::new(Vec3::ZERO, 1.0);
    /// let zero = Case::Sphere(Ray::new(Vec3::Z, Vec3::ZERO), s);
    /// assert_eq!(d.skips(&zero), Some("unit-dirs"));
    /// let tiny = Case::Sphere(Ray::new(Vec3::new(0.0, 0.0, 1e-40), Vec3::Z), s);
    /// assert_eq!(d.skips(&tiny), Some("no-subnormals"));
    /// let huge = Case::Sphere(Ray::new(Vec3::new(0.0, 0.0, -1e30), Vec3::Z), s);
    /// assert_eq!(d.skips(&huge), None);
    /// assert_eq!(d.magnitudes(0.0, 1e12).skips(&huge), Some("magnitudes"));
    /// # }
    /// ```
    pub fn skips(&self, case: &Case) -> Option<&'static str> {
        let (ray, inputs) = inputs(case);
        if self.unit_dirs_only && ray.is_some_and(|r| normalised(r.dir).is_none()) {
            return Some("unit-dirs");
        }
        if self.no_subnormals && inputs.iter().flatten().any(|x| x.is_subnormal()) {
            return Some("no-subnormals");
        }
        let largest = |v: &Vec<f32>| v.iter().fold(0f32, |m, x| m.max(x.abs()));
        if let Some((lo, hi)) = self.magnitudes
            && inputs
                .iter()
                .map(largest)
                .any(|x| x != 0.0 && x.is_finite() && !(lo <= x && x <= hi))
        {
            return Some("magnitudes");
        }
        if self.off_surface && on_surface(case) {
            return Some("off-surface");
        }
        if let Some(k) = self.spread {
            let sizes = inputs
                .iter()
                .enumerate()
                .filter(|(i, _)| ray.is_none() || *i != 1)
                .map(|(_, v)| largest(v))
                .filter(|x| *x != 0.0 && x.is_finite());
            let (lo, hi) = sizes.fold((f32::INFINITY, 0f32), |(lo, hi), x| (lo.min(x), hi.max(x)));
            if hi > k * lo {
                return Some("spread");
            }
        }
        None
    }

    /// The case as the gate feeds it, or the name of the precondition it
    /// violates: with `unit-dirs` the direction normalised in `f32` (the
    /// exact answer is then the normalised ray's own), and every
    /// precondition met ([`Declared::skips`]).
    ///
    /// ```
    /// # #[cfg(feature = "sphere")] {
    /// use rayoracle::check::rules::{Declared, Semantics};
    /// use rayoracle::{Ray, case::Case, sphere::Sphere};
    /// use glam::Vec3;
    /// let d = Declared::f32(Semantics::NearestPositive).unit_dirs();
    /// let s = Sphere::new(Vec3::ZERO, 1.0);
    /// let c = d.prepare(Case::Sphere(Ray::new(Vec3::Z, Vec3::new(0.0, 0.0, 4.0)), s));
    /// assert_eq!(c, Ok(Case::Sphere(Ray::new(Vec3::Z, Vec3::Z), s)));
    /// // 1e-30² underflows: f32 normalisation fails, and the case is skipped.
    /// let tiny = Case::Sphere(Ray::new(Vec3::Z, Vec3::splat(1e-30)), s);
    /// assert_eq!(d.prepare(tiny), Err("unit-dirs"));
    /// # }
    /// ```
    pub fn prepare(&self, case: Case) -> Result<Case, &'static str> {
        let case = if self.unit_dirs_only {
            #[cfg(any(feature = "plane", feature = "sphere", feature = "quadric"))]
            let n = |r: Ray| Ray::new(r.origin, normalised(r.dir).unwrap_or(r.dir));
            match case {
                #[cfg(feature = "plane")]
                Case::Plane(r, p) => Case::Plane(n(r), p),
                #[cfg(feature = "sphere")]
                Case::Sphere(r, s) => Case::Sphere(n(r), s),
                #[cfg(feature = "quadric")]
                Case::Quadric(r, q) => Case::Quadric(n(r), q),
                c => c,
            }
        } else {
            case
        };
        match self.skips(&case) {
            Some(name) => Err(name),
            None => Ok(case),
        }
    }
}

/// Whether the case's ray starts exactly on its surface (the exact value
/// of the surface's function at the origin is 0).
fn on_surface(case: &Case) -> bool {
    let at_origin = match case {
        #[cfg(feature = "plane")]
        Case::Plane(r, p) => super::plane(r, p).map(|e| e.1.inside.0),
        #[cfg(feature = "sphere")]
        Case::Sphere(r, s) => super::sphere(r, s).map(|e| e.1.inside.0),
        #[cfg(feature = "quadric")]
        Case::Quadric(r, q) => super::quadric(r, q).map(|e| e.1.inside.0),
        Case::Camera(..) => None,
    };
    at_origin == Some(0.0)
}

/// `d / |d|` in `f32`, or `None` where that is zero or not finite.
fn normalised(d: Vec3) -> Option<Vec3> {
    let n = d.normalize_or_zero();
    (n != Vec3::ZERO && n.is_finite()).then_some(n)
}

/// The case's ray, if it has one, and its inputs: each vector, scalar or
/// the quadric's coefficients as one group.
fn inputs(case: &Case) -> (Option<Ray>, Vec<Vec<f32>>) {
    let v = |x: Vec3| x.to_array().to_vec();
    match case {
        #[cfg(feature = "plane")]
        Case::Plane(r, p) => (
            Some(*r),
            vec![v(r.origin), v(r.dir), v(p.point), v(p.normal)],
        ),
        #[cfg(feature = "sphere")]
        Case::Sphere(r, s) => (
            Some(*r),
            vec![v(r.origin), v(r.dir), v(s.center), vec![s.radius]],
        ),
        #[cfg(feature = "quadric")]
        Case::Quadric(r, q) => (Some(*r), vec![v(r.origin), v(r.dir), q.coeffs.to_vec()]),
        Case::Camera(p, _) => (None, vec![v(p.position), v(p.dir), v(p.up), vec![p.angle]]),
    }
}

#[cfg(test)]
mod tests {
    use super::super::{Declared, Semantics};

    /// Each form of [`Declared::PRECONDITIONS`] parses to its setting,
    /// `spread:K` from `K = 1` and `magnitudes:LO:HI` from `LO = HI = 0`;
    /// every refusal names the input and the valid forms.
    #[test]
    fn every_precondition_parses_from_its_least_bound() {
        let d = Declared::f32(Semantics::NearestPositive);
        let require = |s: &str| d.require(s);
        assert_eq!(require("unit-dirs"), Ok(d.unit_dirs()));
        assert_eq!(require("no-subnormals"), Ok(d.no_subnormals()));
        assert_eq!(require("off-surface"), Ok(d.off_surface()));
        assert_eq!(require("spread:1"), Ok(d.spread(1.0)));
        assert_eq!(require("spread:1e6"), Ok(d.spread(1e6)));
        assert_eq!(require("magnitudes:0:0"), Ok(d.magnitudes(0.0, 0.0)));
        assert_eq!(require("magnitudes:1e-9:1e9"), Ok(d.magnitudes(1e-9, 1e9)));
        for bad in [
            "spread:0.99",
            "spread:NaN",
            "spread:",
            "magnitudes:2:1",
            "magnitudes:-1:1",
            "magnitudes:1",
            "off_surface",
            "",
        ] {
            let e = require(bad).unwrap_err();
            assert!(
                e.contains(&format!("{bad:?}")) && e.contains(Declared::PRECONDITIONS),
                "{e}"
            );
        }
    }

    /// `spread:K` skips a case whose largest magnitude is more than `K`
    /// times its least, not one at exactly `K` times: here a centre 4
    /// from the origin and a radius of 1 (the direction left out).
    #[cfg(feature = "sphere")]
    #[test]
    fn spread_skips_beyond_its_ratio_not_at_it() {
        use crate::{Ray, case::Case, sphere::Sphere};
        use glam::Vec3;
        let d = Declared::f32(Semantics::NearestPositive);
        let c = Case::Sphere(
            Ray::new(Vec3::ZERO, Vec3::new(0.0, 0.0, 1e9)),
            Sphere::new(Vec3::new(0.0, 0.0, -4.0), 1.0),
        );
        assert_eq!(d.spread(4.0).skips(&c), None);
        assert_eq!(d.spread(3.9).skips(&c), Some("spread"));
    }
}
