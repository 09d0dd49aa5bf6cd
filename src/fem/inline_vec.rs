//! [`InlineVec`]: a vector whose first `N` elements live inline, for results built once per
//! design in sweeps (a stage's load cases), so that a design with few of them allocates nothing.

use serde::{Serialize, Serializer};
use std::ops::{Deref, DerefMut};

/// A vector holding up to `N` elements inline and spilling to the heap beyond.
///
/// The elements are contiguous (a slice by [`Deref`]): inline while there are at most `N`, all
/// moved to the heap on the push that makes `N + 1`.
#[derive(Debug, Clone)]
pub struct InlineVec<T, const N: usize> {
    inline: [T; N],
    len: usize,
    /// All elements, once there were more than `N`.
    spill: Vec<T>,
}

impl<T: Default, const N: usize> Default for InlineVec<T, N> {
    fn default() -> Self {
        InlineVec {
            inline: std::array::from_fn(|_| T::default()),
            len: 0,
            spill: Vec::new(),
        }
    }
}

impl<T: Default, const N: usize> InlineVec<T, N> {
    /// An empty vector.
    pub fn new() -> Self {
        Self::default()
    }

    /// Appends `v`.
    pub fn push(&mut self, v: T) {
        if self.len < N && self.spill.is_empty() {
            self.inline[self.len] = v;
        } else {
            if self.spill.is_empty() {
                self.spill.reserve(2 * N + 1);
                self.spill.extend(self.inline.iter_mut().map(std::mem::take));
            }
            self.spill.push(v);
        }
        self.len += 1;
    }
}

impl<T, const N: usize> Deref for InlineVec<T, N> {
    type Target = [T];
    fn deref(&self) -> &[T] {
        if self.spill.is_empty() {
            &self.inline[..self.len]
        } else {
            &self.spill
        }
    }
}

impl<T, const N: usize> DerefMut for InlineVec<T, N> {
    fn deref_mut(&mut self) -> &mut [T] {
        if self.spill.is_empty() {
            &mut self.inline[..self.len]
        } else {
            &mut self.spill
        }
    }
}

impl<T: Default, const N: usize> FromIterator<T> for InlineVec<T, N> {
    fn from_iter<I: IntoIterator<Item = T>>(iter: I) -> Self {
        let mut v = Self::new();
        iter.into_iter().for_each(|x| v.push(x));
        v
    }
}

impl<'a, T, const N: usize> IntoIterator for &'a InlineVec<T, N> {
    type Item = &'a T;
    type IntoIter = std::slice::Iter<'a, T>;
    fn into_iter(self) -> Self::IntoIter {
        self.iter()
    }
}

impl<T: Serialize, const N: usize> Serialize for InlineVec<T, N> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        (**self).serialize(s)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Pushing past the inline capacity keeps every element, in order.
    #[test]
    fn spills_in_order() {
        for n in 0..9 {
            let v: InlineVec<usize, 3> = (0..n).collect();
            assert_eq!(&*v, &(0..n).collect::<Vec<_>>()[..]);
        }
    }
}
