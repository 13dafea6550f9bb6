//! Random flood fill: grows labelled cells into unlabelled ones, one random
//! frontier cell at a time, each taking the label of a random labelled
//! neighbour. Used for level-1 clusters and for filling the holes that
//! copy-paste leaves.

use rand::RngExt;

use crate::solver::piece::UNSET;
use crate::solver::shape::Shape;

/// Where a cell that no labelled cell can reach gets its label.
pub(crate) enum Fallback<'a> {
    /// Its label in an earlier labelling.
    Previous(&'a [u16]),
    /// A random label below `k`.
    Random(usize),
}

/// Labels every `UNSET` cell of `labels`.
pub(crate) fn flood_fill<R: rand::Rng>(
    shape: &Shape,
    labels: &mut [u16],
    fallback: Fallback<'_>,
    rng: &mut R,
) {
    let n = shape.len();
    let mut queued = vec![false; n];
    let mut frontier: Vec<u32> = Vec::new();
    for c in 0..n as u32 {
        if labels[c as usize] == UNSET
            && shape
                .neighbors(c)
                .iter()
                .any(|&m| labels[m as usize] != UNSET)
        {
            queued[c as usize] = true;
            frontier.push(c);
        }
    }
    let mut scan = 0usize;
    let mut options: Vec<u16> = Vec::with_capacity(6);
    loop {
        while !frontier.is_empty() {
            let c = frontier.swap_remove(rng.random_range(0..frontier.len()));
            options.clear();
            options.extend(
                shape
                    .neighbors(c)
                    .iter()
                    .map(|&m| labels[m as usize])
                    .filter(|&l| l != UNSET),
            );
            labels[c as usize] = options[rng.random_range(0..options.len())];
            for &m in shape.neighbors(c) {
                if labels[m as usize] == UNSET && !queued[m as usize] {
                    queued[m as usize] = true;
                    frontier.push(m);
                }
            }
        }
        // Cells no labelled cell reaches: seed one and go on.
        while scan < n && labels[scan] != UNSET {
            scan += 1;
        }
        if scan == n {
            return;
        }
        labels[scan] = match fallback {
            Fallback::Previous(prev) => prev[scan],
            Fallback::Random(k) => rng.random_range(0..k) as u16,
        };
        for &m in shape.neighbors(scan as u32) {
            if labels[m as usize] == UNSET && !queued[m as usize] {
                queued[m as usize] = true;
                frontier.push(m);
            }
        }
    }
}
