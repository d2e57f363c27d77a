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

/// The last [`KEPT`] answers, oldest overwritten first.
pub(crate) struct Memo<K, V> {
    kept: [Option<(K, V)>; KEPT],
    next: usize,
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
pub(crate) fn remembered<K: PartialEq, V: Clone>(
    memo: &'static std::thread::LocalKey<RefCell<Memo<K, V>>>,
    key: K,
    f: impl FnOnce() -> V,
) -> V {
    let found = memo.with_borrow(|m| {
        m.kept
            .iter()
            .flatten()
            .find(|e| e.0 == key)
            .map(|e| e.1.clone())
    });
    if let Some(v) = found {
        return v;
    }
    let v = f();
    memo.with_borrow_mut(|m| {
        let i = m.next;
        m.kept[i] = Some((key, v.clone()));
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
        assert_eq!((sq(3), calls.get()), (9, 2 + KEPT));
    }
}
