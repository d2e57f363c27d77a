//! An answer and its [`Stage`] as two integers, for the way out of the
//! quadric's later stages.
//!
//! A hit and its stage, returned as they are from a function that is not
//! inlined, go through memory: written field by field (a tag, one or two
//! `f32` roots, the stage) and read back eight bytes at a time, which
//! stalls store forwarding on every call that reaches the later stages.
//! Two `u64`s come back in two registers instead.

use super::QuadricHit;
use crate::stage::Stage;

/// A hit and its stage: the hit's tag and the stage in the first word,
/// the roots' bits in the second.
#[derive(Clone, Copy)]
pub(crate) struct Packed(u64, u64);

impl Packed {
    /// `(h, s)` packed.
    #[inline(always)]
    pub(crate) fn of((h, s): (QuadricHit, Stage)) -> Packed {
        // The class as a tag below 256, and the roots (0 where there are
        // fewer than two).
        let (tag, [a, b]) = match h {
            QuadricHit::None => (0, [0.0; 2]),
            QuadricHit::One(t) => (1, [t, 0.0]),
            QuadricHit::Two(a, b) => (2, [a, b]),
            QuadricHit::All => (3, [0.0; 2]),
        };
        Packed(
            tag | (s as u64) << 8,
            u64::from(a.to_bits()) | u64::from(b.to_bits()) << 32,
        )
    }

    /// The hit and the stage that [`Packed::of`] was given.
    #[inline(always)]
    pub(crate) fn unpack(self) -> (QuadricHit, Stage) {
        let (a, b) = (
            f32::from_bits(self.1 as u32),
            f32::from_bits((self.1 >> 32) as u32),
        );
        let stage = Stage::ALL[(self.0 >> 8) as usize % Stage::ALL.len()];
        let hit = match self.0 & 0xff {
            0 => QuadricHit::None,
            1 => QuadricHit::One(a),
            2 => QuadricHit::Two(a, b),
            _ => QuadricHit::All,
        };
        (hit, stage)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// [`Packed`] gives back every class, root bits and stage it was
    /// given: ±0, subnormal and infinite roots, roots in either order.
    #[test]
    fn packed_answers_unpack_to_themselves() {
        let t = [0.0, -0.0, 2f32.powi(-149), -1.5, f32::INFINITY, f32::MAX];
        let mut hits = vec![QuadricHit::None, QuadricHit::All];
        for &a in &t {
            hits.push(QuadricHit::One(a));
            for &b in &t {
                hits.push(QuadricHit::Two(a, b));
            }
        }
        let bits = |h: QuadricHit| match h {
            QuadricHit::One(a) => [1, a.to_bits(), 0],
            QuadricHit::Two(a, b) => [2, a.to_bits(), b.to_bits()],
            QuadricHit::None => [0; 3],
            QuadricHit::All => [3, 0, 0],
        };
        for h in hits {
            for s in Stage::ALL {
                let (g, gs) = Packed::of((h, s)).unpack();
                assert_eq!((bits(g), gs), (bits(h), s), "{h:?} {s:?}");
            }
        }
    }
}
