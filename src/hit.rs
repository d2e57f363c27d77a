//! What every primitive's result has in common: a class, its roots, and
//! the nearest root in an interval.

/// The class of an answer: what kind of solution set the line has. Each
/// primitive uses its own few ([`Intersection::class`]); the camera's
/// answer is a [`Class::Ray`].
///
/// ```
/// use rayoracle::hit::Class;
/// assert_eq!(Class::InPlane.as_str(), "in_plane");
/// assert_eq!(Class::Two.to_string(), "two");
/// assert_eq!("tangent".parse(), Ok(Class::Tangent));
/// assert!("cube".parse::<Class>().is_err());
/// ```
#[derive(Clone, Copy, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Class {
    /// No point of the line is on the surface (sphere, quadric).
    None,
    /// One simple root (quadric).
    One,
    /// Two roots (sphere, quadric).
    Two,
    /// A double root: the line touches the sphere.
    Tangent,
    /// Every point of the line is on the quadric.
    All,
    /// The line crosses the plane once.
    Hit,
    /// The line is parallel to the plane and off it.
    Parallel,
    /// The line lies in the plane.
    InPlane,
    /// A camera's ray.
    Ray,
}

impl Class {
    /// Every class.
    pub const ALL: [Class; 9] = [
        Class::None,
        Class::One,
        Class::Two,
        Class::Tangent,
        Class::All,
        Class::Hit,
        Class::Parallel,
        Class::InPlane,
        Class::Ray,
    ];

    /// The name used in `eval` output and reports.
    ///
    /// ```
    /// assert_eq!(rayoracle::hit::Class::None.as_str(), "none");
    /// ```
    pub const fn as_str(self) -> &'static str {
        match self {
            Class::None => "none",
            Class::One => "one",
            Class::Two => "two",
            Class::Tangent => "tangent",
            Class::All => "all",
            Class::Hit => "hit",
            Class::Parallel => "parallel",
            Class::InPlane => "in_plane",
            Class::Ray => "ray",
        }
    }
}

/// As its name, quoted (`"two"`): the form results and messages have
/// always shown.
impl core::fmt::Debug for Class {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(f, "{:?}", self.as_str())
    }
}

impl core::fmt::Display for Class {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.write_str(self.as_str())
    }
}

/// A class name that is not one of [`Class::ALL`].
///
/// ```
/// let e = "cube".parse::<rayoracle::hit::Class>().unwrap_err();
/// assert!(e.to_string().starts_with(r#"unknown class "cube"; expected none, one,"#));
/// ```
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownClass(pub String);

impl core::fmt::Display for UnknownClass {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let names: Vec<&str> = Class::ALL.iter().map(|c| c.as_str()).collect();
        write!(
            f,
            "unknown class \"{}\"; expected {}",
            self.0,
            names.join(", ")
        )
    }
}

impl std::error::Error for UnknownClass {}

impl core::str::FromStr for Class {
    type Err = UnknownClass;
    fn from_str(s: &str) -> Result<Class, UnknownClass> {
        Class::ALL
            .into_iter()
            .find(|c| c.as_str() == s)
            .ok_or_else(|| UnknownClass(s.to_string()))
    }
}

/// A class compares equal to its name, so that tests and fixtures can
/// write `h.class() == "two"`.
impl PartialEq<&str> for Class {
    fn eq(&self, other: &&str) -> bool {
        self.as_str() == *other
    }
}

impl serde::Serialize for Class {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(self.as_str())
    }
}

/// Up to two roots, ascending.
///
/// ```
/// use rayoracle::hit::Roots;
/// assert_eq!(Roots::two(1.0, 2.0).as_slice(), &[1.0, 2.0]);
/// assert!(Roots::none().as_slice().is_empty());
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Roots {
    vals: [f32; 2],
    len: u8,
}

impl Roots {
    /// No root.
    ///
    /// ```
    /// assert_eq!(rayoracle::hit::Roots::none().as_slice().len(), 0);
    /// ```
    pub const fn none() -> Roots {
        Roots {
            vals: [0.0; 2],
            len: 0,
        }
    }
    /// One root.
    ///
    /// ```
    /// assert_eq!(rayoracle::hit::Roots::one(3.0).as_slice(), &[3.0]);
    /// ```
    pub const fn one(t: f32) -> Roots {
        Roots {
            vals: [t, 0.0],
            len: 1,
        }
    }
    /// Two roots, in the order given.
    ///
    /// ```
    /// assert_eq!(rayoracle::hit::Roots::two(1.0, 2.0).as_slice()[1], 2.0);
    /// ```
    pub const fn two(t0: f32, t1: f32) -> Roots {
        Roots {
            vals: [t0, t1],
            len: 2,
        }
    }
    /// The roots as a slice.
    ///
    /// ```
    /// assert_eq!(rayoracle::hit::Roots::one(3.0).as_slice(), &[3.0]);
    /// ```
    #[inline]
    pub fn as_slice(&self) -> &[f32] {
        &self.vals[..self.len as usize]
    }
}

/// A classified intersection result.
///
/// `nearest(t_min, t_max)` is the ray-tracing view of the whole-line result:
/// the smallest root `t` with `t_min ≤ t ≤ t_max` (a closed interval; NaN
/// roots never qualify), and for results that hold for every `t` (a ray in
/// the plane, a line on the quadric) `t_min` itself when `t_min ≤ t_max`.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::hit::Intersection;
/// use rayoracle::sphere::SphereHit;
/// let h = SphereHit::Two(-1.0, 3.0);
/// assert_eq!(h.nearest(0.0, f32::INFINITY), Some(3.0));
/// assert_eq!(h.nearest(0.0, 2.0), None);
/// assert_eq!(h.class(), rayoracle::hit::Class::Two);
/// # }
/// ```
pub trait Intersection {
    /// The class ([`Class::Hit`], [`Class::Two`], [`Class::None`], …).
    fn class(&self) -> Class;
    /// The roots, ascending.
    fn roots(&self) -> Roots;
    /// Whether every `t` is a solution.
    fn is_everywhere(&self) -> bool {
        false
    }
    /// The nearest solution in `[t_min, t_max]`.
    fn nearest(&self, t_min: f32, t_max: f32) -> Option<f32> {
        if self.is_everywhere() {
            return (t_min <= t_max).then_some(t_min);
        }
        self.roots()
            .as_slice()
            .iter()
            .copied()
            .find(|&t| t >= t_min && t <= t_max)
    }
}

/// Whether two results are the same class with the same root bits (any
/// NaN equal to any NaN, `+0` and `−0` different): the bit-identity x4 owes
/// the reference.
///
/// ```
/// # #[cfg(feature = "sphere")] {
/// use rayoracle::hit::same_bits;
/// use rayoracle::sphere::SphereHit;
/// assert!(same_bits(&SphereHit::Tangent(f32::NAN), &SphereHit::Tangent(-f32::NAN)));
/// assert!(!same_bits(&SphereHit::Tangent(0.0), &SphereHit::Tangent(-0.0)));
/// assert!(!same_bits(&SphereHit::Tangent(f32::NAN), &SphereHit::Tangent(1.0)));
/// # }
/// ```
pub fn same_bits<H: Intersection>(a: &H, b: &H) -> bool {
    let (ra, rb) = (a.roots(), b.roots());
    let same = |x: f32, y: f32| x.to_bits() == y.to_bits() || (x.is_nan() && y.is_nan());
    a.class() == b.class()
        && ra.as_slice().len() == rb.as_slice().len()
        && ra
            .as_slice()
            .iter()
            .zip(rb.as_slice())
            .all(|(&x, &y)| same(x, y))
}

#[cfg(test)]
mod tests {
    use super::Class;

    /// Every class has its own name, which reads back to it, and compares
    /// equal to it as a string.
    #[test]
    fn every_class_name_is_distinct_and_reads_back() {
        let mut names: Vec<&str> = Class::ALL.iter().map(|c| c.as_str()).collect();
        for c in Class::ALL {
            assert_eq!(c.as_str().parse(), Ok(c));
            assert!(c == c.as_str());
            assert_eq!(format!("{c:?}"), format!("{:?}", c.as_str()));
            assert_eq!(serde_json::to_string(&c).unwrap(), format!("\"{c}\""));
        }
        names.sort_unstable();
        names.dedup();
        assert_eq!(names.len(), Class::ALL.len());
        assert!(Class::Hit != "hit ");
    }
}
