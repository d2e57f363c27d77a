//! What a kernel computes, and the short stable names a command line gives
//! each semantics.

use std::fmt;
use std::str::FromStr;

/// What the kernel computes. Each has a short stable name, parsed by
/// [`FromStr`] and printed by [`Display`](fmt::Display):
///
/// | name | semantics | answer |
/// |---|---|---|
/// | `whole-line` | every root, `t ∈ ℝ` | [`Answer::Roots`](super::Answer::Roots) |
/// | `nearest` | the nearest root `t > 0` | [`Answer::Nearest`](super::Answer::Nearest) or [`Answer::Point`](super::Answer::Point) |
/// | `range:T0:T1` | the nearest root `T0 < t < T1` | the same |
/// | `solid` | `t = 0` when the origin is inside, else the nearest `t > 0` | the same |
/// | `roots-in:T0:T1` | every root `T0 < t < T1`, ascending | [`Answer::Roots`](super::Answer::Roots) |
///
/// ```
/// use rayoracle::check::rules::Semantics;
/// assert_eq!("nearest".parse(), Ok(Semantics::NearestPositive));
/// let seg: Semantics = "range:0.001:1e30".parse().unwrap();
/// assert_eq!(seg, Semantics::Range { t_min: 0.001, t_max: 1e30 });
/// assert_eq!(seg.to_string().parse(), Ok(seg));
/// let e = "range:2:1".parse::<Semantics>().unwrap_err();
/// assert!(e.contains("whole-line") && e.contains("range:T0:T1"));
/// ```
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Semantics {
    /// Every root on the whole line, `t ∈ ℝ` ([`Answer::Roots`](super::Answer::Roots)).
    WholeLine,
    /// The nearest root `t > 0`, as a ray caster.
    NearestPositive,
    /// The nearest root with `t_min < t < t_max`, or none: a segment, or a
    /// ray with a least and a greatest distance.
    Range {
        /// Roots at or below this are not hits.
        t_min: f32,
        /// Roots at or above this are not hits.
        t_max: f32,
    },
    /// A solid: `t = 0` when the origin is inside or on the surface (the
    /// surface's function at the origin is `≤ 0`: `|o − C| ≤ R` for a
    /// sphere, `F(o) ≤ 0` for a quadric, `(o − a)·n ≤ 0` for a plane,
    /// the half-space behind its normal), else the nearest root `t > 0`.
    Solid,
    /// Every root with `t_min < t < t_max`, ascending
    /// ([`Answer::Roots`](super::Answer::Roots)): both hits of a segment.
    RootsIn {
        /// Roots at or below this are left out.
        t_min: f32,
        /// Roots at or above this are left out.
        t_max: f32,
    },
}

impl Semantics {
    /// Every valid form, for error messages and help texts.
    pub const FORMS: &'static str =
        "whole-line, nearest, solid, range:T0:T1, roots-in:T0:T1 (T0 < T1)";

    /// The open interval of `t` a semantics looks in (`Solid` outside the
    /// solid); `None` for the whole line.
    ///
    /// ```
    /// use rayoracle::check::rules::Semantics;
    /// assert_eq!(Semantics::NearestPositive.range(), Some((0.0, f32::INFINITY)));
    /// assert_eq!(Semantics::WholeLine.range(), None);
    /// ```
    pub fn range(&self) -> Option<(f32, f32)> {
        match *self {
            Semantics::WholeLine => None,
            Semantics::NearestPositive | Semantics::Solid => Some((0.0, f32::INFINITY)),
            Semantics::Range { t_min, t_max } | Semantics::RootsIn { t_min, t_max } => {
                Some((t_min, t_max))
            }
        }
    }
}

impl fmt::Display for Semantics {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Semantics::WholeLine => write!(f, "whole-line"),
            Semantics::NearestPositive => write!(f, "nearest"),
            Semantics::Solid => write!(f, "solid"),
            Semantics::Range { t_min, t_max } => write!(f, "range:{t_min:?}:{t_max:?}"),
            Semantics::RootsIn { t_min, t_max } => write!(f, "roots-in:{t_min:?}:{t_max:?}"),
        }
    }
}

impl FromStr for Semantics {
    type Err = String;

    fn from_str(s: &str) -> Result<Semantics, String> {
        let bad = || format!("unknown semantics {s:?}: valid forms are {}", Self::FORMS);
        match s {
            "whole-line" => Ok(Semantics::WholeLine),
            "nearest" => Ok(Semantics::NearestPositive),
            "solid" => Ok(Semantics::Solid),
            _ => {
                let (nearest, rest) = match (s.strip_prefix("range:"), s.strip_prefix("roots-in:"))
                {
                    (Some(rest), _) => (true, rest),
                    (_, Some(rest)) => (false, rest),
                    _ => return Err(bad()),
                };
                let (a, b) = rest.split_once(':').ok_or_else(bad)?;
                let (t_min, t_max) = (
                    a.parse::<f32>().map_err(|_| bad())?,
                    b.parse::<f32>().map_err(|_| bad())?,
                );
                match () {
                    _ if !(t_min < t_max) => Err(bad()),
                    _ if nearest => Ok(Semantics::Range { t_min, t_max }),
                    _ => Ok(Semantics::RootsIn { t_min, t_max }),
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::Semantics;

    /// Each name parses to its semantics; an interval must be nonempty
    /// (`T0 < T1`, so NaN is refused), and every refusal names the input
    /// and the valid forms.
    #[test]
    fn every_form_parses_and_an_empty_interval_is_refused() {
        let parse = |s: &str| s.parse::<Semantics>();
        assert_eq!(parse("whole-line"), Ok(Semantics::WholeLine));
        assert_eq!(parse("nearest"), Ok(Semantics::NearestPositive));
        assert_eq!(parse("solid"), Ok(Semantics::Solid));
        let (t_min, t_max) = (-1.0, 2.0);
        assert_eq!(parse("range:-1:2"), Ok(Semantics::Range { t_min, t_max }));
        assert_eq!(
            parse("roots-in:-1:2"),
            Ok(Semantics::RootsIn { t_min, t_max })
        );
        for bad in [
            "range:1:1",
            "roots-in:2:1",
            "range:0:NaN",
            "range:1",
            "range:a:1",
            "near",
            "",
        ] {
            let e = parse(bad).unwrap_err();
            assert!(
                e.contains(&format!("{bad:?}")) && e.contains(Semantics::FORMS),
                "{e}"
            );
        }
    }
}
