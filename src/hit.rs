//! What every primitive's result has in common: a class name, its roots, and
//! the nearest root in an interval.

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
/// assert_eq!(h.class(), "two");
/// # }
/// ```
pub trait Intersection {
    /// The class name used in `eval` output (`hit`, `two`, `none`, …).
    fn class(&self) -> &'static str;
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
