//! An answer and its [`Stage`] as two integers, for the way out of a
//! kernel's later stages.
//!
//! A hit and its stage, returned as they are from a function that is not
//! inlined, go through memory: written field by field (a tag, one or two
//! `f32` roots, the stage) and read back eight bytes at a time, which
//! stalls store forwarding on every call that reaches the later stages.
//! Two `u64`s come back in two registers instead.

use super::Stage;

/// A hit and its stage: the hit's tag and the stage in the first word,
/// the roots' bits in the second.
#[derive(Clone, Copy)]
pub(crate) struct Packed(u64, u64);

/// A hit as a tag below 256 and at most two roots, for [`Packed`].
pub(crate) trait Tagged: Copy {
    /// The tag and the roots (0 where there are fewer than two).
    fn tag(self) -> (u64, [f32; 2]);
    /// The hit of a tag and roots that [`Tagged::tag`] gave.
    fn untag(tag: u64, roots: [f32; 2]) -> Self;
}

impl Packed {
    /// `(h, s)` packed.
    #[inline(always)]
    pub(crate) fn of<H: Tagged>((h, s): (H, Stage)) -> Packed {
        let (tag, [a, b]) = h.tag();
        Packed(
            tag | (s as u64) << 8,
            u64::from(a.to_bits()) | u64::from(b.to_bits()) << 32,
        )
    }

    /// The hit and the stage that [`Packed::of`] was given.
    #[inline(always)]
    pub(crate) fn unpack<H: Tagged>(self) -> (H, Stage) {
        let roots = [
            f32::from_bits(self.1 as u32),
            f32::from_bits((self.1 >> 32) as u32),
        ];
        let stage = Stage::ALL[(self.0 >> 8) as usize % Stage::ALL.len()];
        (H::untag(self.0 & 0xff, roots), stage)
    }
}
