//! The last few answers of an oracle on this thread, by the exact bits of
//! their inputs: the kernels' last stage and a check of their answer often
//! ask the oracle the same question in a row, and it is answered once.
//! An answer depends on nothing but the input's bits, so a remembered one
//! is the one the oracle would give again.
//!
//! ```
//! # #[cfg(feature = "sphere")] {
//! use rayoracle::{Ray, sphere::{Sphere, exact::intersect}};
//! use glam::Vec3;
//! let (r, s) = (Ray::new(Vec3::new(0.0, 1.0, -5.0), Vec3::Z), Sphere::new(Vec3::ZERO, 1.0));
//! // Asked twice, the same answer (the second one remembered).
//! assert_eq!(intersect(&r, &s), intersect(&r, &s));
//! # }
//! ```

use core::cell::RefCell;

/// How many answers a [`Memo`] keeps.
const KEPT: usize = 8;

/// The last [`KEPT`] answers, oldest overwritten first, each with a hash
/// of its key ([`hash`]), compared before the key itself.
pub(crate) struct Memo<K, V> {
    kept: [Option<(u64, K, V)>; KEPT],
    next: usize,
}

/// A 64-bit hash of `key` (FxHash's multiply and rotate per word): the
/// comparison of two keys that are not equal almost always ends at their
/// hashes, without comparing the keys' bytes.
fn hash<K: core::hash::Hash>(key: &K) -> u64 {
    struct Fx(u64);
    impl core::hash::Hasher for Fx {
        fn finish(&self) -> u64 {
            self.0
        }
        fn write(&mut self, bytes: &[u8]) {
            for b in bytes {
                self.write_u64(u64::from(*b));
            }
        }
        fn write_u32(&mut self, x: u32) {
            self.write_u64(u64::from(x));
        }
        fn write_u64(&mut self, x: u64) {
            self.0 = (self.0.rotate_left(5) ^ x).wrapping_mul(0x51_7c_c1_b7_27_22_0a_95);
        }
        fn write_usize(&mut self, x: usize) {
            self.write_u64(x as u64);
        }
    }
    let mut h = Fx(0);
    key.hash(&mut h);
    core::hash::Hasher::finish(&h)
}

impl<K, V> Memo<K, V> {
    /// Empty.
    pub(crate) const fn new() -> Self {
        Memo {
            kept: [const { None }; KEPT],
            next: 0,
        }
    }
}

/// `f()`, or the answer kept for `key` in `memo`.
pub(crate) fn remembered<K: PartialEq + core::hash::Hash, V: Clone>(
    memo: &'static std::thread::LocalKey<RefCell<Memo<K, V>>>,
    key: K,
    f: impl FnOnce() -> V,
) -> V {
    let h = hash(&key);
    let found = memo.with_borrow(|m| {
        m.kept
            .iter()
            .flatten()
            .find(|e| e.0 == h && e.1 == key)
            .map(|e| e.2.clone())
    });
    if let Some(v) = found {
        return v;
    }
    let v = f();
    memo.with_borrow_mut(|m| {
        let i = m.next;
        m.kept[i] = Some((h, key, v.clone()));
        m.next = (i + 1) % KEPT;
    });
    v
}

#[cfg(test)]
mod tests {
    use super::*;

    thread_local! {
        static SQUARES: RefCell<Memo<u32, u64>> = const { RefCell::new(Memo::new()) };
    }

    /// A kept answer is returned without calling `f`; past [`KEPT`] newer
    /// keys, the oldest is computed again.
    #[test]
    fn keeps_the_last_answers() {
        let calls = core::cell::Cell::new(0);
        let sq = |x: u32| {
            remembered(&SQUARES, x, || {
                calls.set(calls.get() + 1);
                u64::from(x) * u64::from(x)
            })
        };
        assert_eq!((sq(3), sq(3), calls.get()), (9, 9, 1));
        for x in 10..10 + KEPT as u32 {
            assert_eq!(sq(x), u64::from(x * x));
        }
        assert_eq!(calls.get(), 1 + KEPT);
        for x in 10..10 + KEPT as u32 {
            assert_eq!(sq(x), u64::from(x * x));
        }
        assert_eq!(calls.get(), 1 + KEPT, "all of the last KEPT are kept");
        assert_eq!((sq(3), calls.get()), (9, 2 + KEPT));
    }

    /// Two keys of the same hash are told apart by the keys: a collision
    /// is never an answer. (The hash only spares most comparisons of keys.)
    #[test]
    fn a_hash_collision_is_not_an_answer() {
        thread_local! {
            static PAIRS: RefCell<Memo<(u64, u64), u64>> = const { RefCell::new(Memo::new()) };
        }
        // A pair hashes to ((a·C).rotl(5) ^ b)·C: the second words make up
        // for the first.
        let first = |a: u64| a.wrapping_mul(0x51_7c_c1_b7_27_22_0a_95).rotate_left(5);
        let (x, y) = ((1, 0), (2, first(1) ^ first(2)));
        assert!(x != y && hash(&x) == hash(&y));
        assert_eq!(remembered(&PAIRS, x, || 1), 1);
        assert_eq!(remembered(&PAIRS, y, || 2), 2);
    }
}
