//! The last few values of a pure function, remembered per thread in a fixed ring (replaced
//! oldest first; no heap allocation). A key holds the exact input (bit patterns or values
//! compared by `PartialEq`), so a remembered value is the value computed afresh; failures are
//! not remembered.

use std::cell::RefCell;
use std::thread::LocalKey;

/// `SLOTS` remembered (key, value) pairs.
pub struct Ring<K, V, const SLOTS: usize> {
    slots: [Option<(K, V)>; SLOTS],
    next: usize,
}

impl<K: PartialEq, V: Clone, const SLOTS: usize> Ring<K, V, SLOTS> {
    /// An empty ring (usable in a `thread_local!` `const` initialiser).
    pub const fn new() -> Self {
        Ring {
            slots: [const { None }; SLOTS],
            next: 0,
        }
    }

    fn get(&self, key: &K) -> Option<V> {
        self.slots
            .iter()
            .flatten()
            .find(|(k, _)| k == key)
            .map(|(_, v)| v.clone())
    }

    fn insert(&mut self, key: K, value: V) {
        self.slots[self.next] = Some((key, value));
        self.next = (self.next + 1) % SLOTS;
    }
}

impl<K: PartialEq, V: Clone, const SLOTS: usize> Default for Ring<K, V, SLOTS> {
    fn default() -> Self {
        Self::new()
    }
}

/// The value `memo` remembers for `key`, else `f()` (remembered when it succeeds). `f` runs
/// with the ring released, so it may use other memos.
pub fn remembered<K: PartialEq, V: Clone, E, const SLOTS: usize>(
    memo: &'static LocalKey<RefCell<Ring<K, V, SLOTS>>>,
    key: K,
    f: impl FnOnce() -> Result<V, E>,
) -> Result<V, E> {
    if let Some(v) = memo.with_borrow(|m| m.get(&key)) {
        return Ok(v);
    }
    let v = f()?;
    memo.with_borrow_mut(|m| m.insert(key, v.clone()));
    Ok(v)
}

#[cfg(test)]
mod tests {
    use super::*;

    thread_local! {
        static SQUARES: RefCell<Ring<u32, u64, 4>> = const { RefCell::new(Ring::new()) };
    }

    /// Hits return the remembered value without calling `f`; the fifth key pushes out the
    /// first; failures are not remembered.
    #[test]
    fn remembers_the_last_slots_and_not_failures() {
        let calls = std::cell::Cell::new(0);
        let square = |k: u32| {
            remembered(&SQUARES, k, || {
                calls.set(calls.get() + 1);
                Ok::<_, ()>(u64::from(k) * u64::from(k))
            })
        };
        for k in [1, 2, 3, 4, 1, 2] {
            assert_eq!(square(k), Ok(u64::from(k * k)));
        }
        assert_eq!(calls.get(), 4);
        square(5).unwrap();
        square(1).unwrap();
        assert_eq!(calls.get(), 6, "1 was replaced by 5 and computed again");
        assert_eq!(remembered(&SQUARES, 9, || Err::<u64, _>("bad")), Err("bad"));
        assert_eq!(remembered(&SQUARES, 9, || Ok::<_, &str>(81)), Ok(81));
    }
}
