//! Pieces of a labelled figure: the cells carrying each label, with the sums
//! the centroid alignment needs.

use crate::solver::shape::Shape;

/// The label of a cell not yet given to any piece.
pub(crate) const UNSET: u16 = u16::MAX;

/// The pieces of one labelled figure.
///
/// # Validity
/// `members[i]` lists, in increasing order, the cells labelled `i`; `sums[i]`
/// is the sum of their points. Built only by [`Pieces::of`].
#[derive(Clone, Debug)]
pub(crate) struct Pieces {
    members: Vec<Vec<u32>>,
    sums: Vec<[i64; 3]>,
}

impl Pieces {
    /// The pieces `0..k` of `shape` under `labels` (every label `< k`).
    pub(crate) fn of(shape: &Shape, labels: &[u16], k: usize) -> Pieces {
        // Sizes first, so every member list is allocated once.
        let mut sizes = vec![0usize; k];
        for &l in labels {
            sizes[l as usize] += 1;
        }
        let mut members: Vec<Vec<u32>> = sizes.iter().map(|&n| Vec::with_capacity(n)).collect();
        let mut sums = vec![[0i64; 3]; k];
        for (c, &l) in labels.iter().enumerate() {
            let l = l as usize;
            members[l].push(c as u32);
            let p = shape.point(c as u32);
            for d in 0..3 {
                sums[l][d] += p[d] as i64;
            }
        }
        Pieces { members, sums }
    }

    /// The number of labels.
    pub(crate) fn count(&self) -> usize {
        self.members.len()
    }

    /// Cells of piece `i`.
    pub(crate) fn members(&self, i: usize) -> &[u32] {
        &self.members[i]
    }

    /// Size of piece `i`.
    pub(crate) fn size(&self, i: usize) -> usize {
        self.members[i].len()
    }

    /// Sum of the points of piece `i`.
    pub(crate) fn sum(&self, i: usize) -> [i64; 3] {
        self.sums[i]
    }
}

impl Pieces {
    /// The pieces renumbered so that new piece `a` is old piece `partner[a]`.
    pub(crate) fn permuted(&self, partner: &[usize]) -> Pieces {
        Pieces {
            members: partner.iter().map(|&b| self.members[b].clone()).collect(),
            sums: partner.iter().map(|&b| self.sums[b]).collect(),
        }
    }

    /// The number of connected components of piece `i` in `shape`
    /// (`scratch` must hold `shape.len()` entries, all `false`; it is left so).
    pub(crate) fn components(&self, shape: &Shape, i: usize, scratch: &mut [bool]) -> usize {
        let cells = &self.members[i];
        for &c in cells {
            scratch[c as usize] = true;
        }
        shape.count_marked(cells.iter().copied(), scratch)
    }
}
