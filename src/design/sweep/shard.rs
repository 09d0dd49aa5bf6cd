//! Shards of a sweep: part `K` of `N`, the designs whose index ≡ K−1 (mod N).

use std::fmt;
use std::str::FromStr;

/// Part `k` of `n` of a sweep: the designs whose index ≡ k−1 (mod n), 1 ≤ k ≤ n.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Shard {
    k: usize,
    n: usize,
}

impl Shard {
    /// The whole sweep (`1/1`).
    pub const ALL: Shard = Shard { k: 1, n: 1 };

    /// Shard `k` of `n`; needs 1 ≤ k ≤ n.
    pub fn new(k: usize, n: usize) -> Result<Self, String> {
        if n == 0 {
            return Err("N must be at least 1".into());
        }
        if k == 0 || k > n {
            return Err(format!("K must lie in 1..={n} (1 ≤ K ≤ N)"));
        }
        Ok(Shard { k, n })
    }

    /// `K` (1-based).
    pub fn k(&self) -> usize {
        self.k
    }

    /// `N`.
    pub fn n(&self) -> usize {
        self.n
    }

    /// True when design `index` belongs to this shard.
    pub fn contains(&self, index: usize) -> bool {
        index % self.n == self.k - 1
    }

    /// How many of the designs `0..len` belong to this shard.
    pub fn count(&self, len: usize) -> usize {
        // (len − k)/n + 1 designs k−1, k−1+n, … below len; written so that no N (up to
        // usize::MAX) overflows.
        if len < self.k {
            0
        } else {
            (len - self.k) / self.n + 1
        }
    }

    /// The `j`-th design index of this shard.
    pub fn index(&self, j: usize) -> usize {
        self.k - 1 + j * self.n
    }
}

impl FromStr for Shard {
    type Err = String;

    fn from_str(s: &str) -> Result<Self, String> {
        let (k, n) = s.split_once('/').ok_or("must look like K/N, e.g. 2/3")?;
        let k: usize = k.trim().parse().map_err(|_| "K must be a whole number ≥ 1")?;
        let n: usize = n.trim().parse().map_err(|_| "N must be a whole number ≥ 1")?;
        Shard::new(k, n)
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.k, self.n)
    }
}
