//! Regrouping: a local search on the incumbent dissection. A few of its
//! pieces that touch one another in every figure (a *group*, grown from
//! the smallest pieces) are set aside together: in each figure their union
//! is a small figure of its own, all of equal size, and the exact
//! dissector (the [`Repair::regroup`] hook) cuts those unions again with
//! fewer pieces than the group had. The rest of the dissection stays as
//! it is, so the result is a dissection with fewer pieces.
//!
//! This is where large figures lose the small pieces a constructive
//! dissection leaves behind: the greedy's leftovers (single cells, short
//! rods) are regrouped with their neighbours into pieces the exact search
//! finds, a problem of a few dozen or hundred cells whatever the size of
//! the figures.

use std::sync::atomic::{AtomicBool, Ordering};

use crate::figure::Figure;
use crate::lattice::Cell;
use crate::solver::candidate::Problem;
use crate::solver::Repair;

/// Group sizes tried, smallest first.
const GROUP_SIZES: [usize; 5] = [2, 3, 4, 5, 6];

/// The most cells a group's union may have (per figure): the exact search
/// stays quick below it.
pub(crate) const MAX_GROUP_CELLS: usize = 90;

/// `pieces[f][i]`: the cells of piece `i` in figure `f`.
pub(crate) type Pieces = Vec<Vec<Vec<Cell>>>;

/// Which pieces touch which, and in how many figures.
struct Touching {
    /// `adjacent[i][j]`: in how many figures pieces `i` and `j` share a
    /// face.
    adjacent: Vec<Vec<u8>>,
    /// The cells of each piece.
    size: Vec<usize>,
}

impl Touching {
    fn of(problem: &Problem, labels: &[Vec<u16>], k: usize) -> Touching {
        let mut adjacent = vec![vec![0u8; k]; k];
        for (shape, l) in problem.shapes.iter().zip(labels) {
            let mut here = vec![vec![false; k]; k];
            for c in 0..shape.len() as u32 {
                let a = l[c as usize] as usize;
                for &n in shape.neighbors(c) {
                    let b = l[n as usize] as usize;
                    if a != b {
                        here[a][b] = true;
                    }
                }
            }
            for (row, h) in adjacent.iter_mut().zip(&here) {
                for (x, y) in row.iter_mut().zip(h) {
                    *x += u8::from(*y);
                }
            }
        }
        let mut size = vec![0usize; k];
        for &a in &labels[0] {
            size[a as usize] += 1;
        }
        Touching { adjacent, size }
    }

    /// The group grown from `seed` to `t` pieces, each new one a piece that
    /// touches a piece of the group in the most figures, the smallest of
    /// those (ties: the lower index); sorted. `None` when it cannot grow
    /// that far within the cell cap. (A union split in some figure is still
    /// a problem the exact search takes: its pieces then number at least
    /// the components.)
    fn group(&self, seed: usize, t: usize) -> Option<Vec<usize>> {
        let mut group = vec![seed];
        let mut cells = self.size[seed];
        while group.len() < t {
            let touch = |j: usize| {
                group
                    .iter()
                    .map(|&i| self.adjacent[i][j])
                    .max()
                    .unwrap_or(0)
            };
            let next = (0..self.size.len())
                .filter(|j| !group.contains(j))
                .filter(|&j| touch(j) > 0)
                .min_by_key(|&j| (std::cmp::Reverse(touch(j)), self.size[j], j))?;
            cells += self.size[next];
            if cells > MAX_GROUP_CELLS {
                return None;
            }
            group.push(next);
        }
        group.sort_unstable();
        Some(group)
    }
}

/// Regroups the dissection given by `labels` (`k` pieces, labels `0..k`
/// per figure) once: the first group (by size, then by its smallest
/// piece) whose union the repairer dissects with fewer pieces. Returns the
/// new dissection's pieces, or `None` when no group gives fewer pieces or
/// `stop` is raised. `tried` holds the groups (as sorted cell lists of
/// figure 0) already tried without success, so a later call skips them.
pub(crate) fn regroup_once(
    figures: &[Figure],
    problem: &Problem,
    labels: &[Vec<u16>],
    k: usize,
    repairer: &dyn Repair,
    stop: &AtomicBool,
    tried: &mut Vec<Vec<Cell>>,
) -> Option<Pieces> {
    let touching = Touching::of(problem, labels, k);
    let mut seeds: Vec<usize> = (0..k).collect();
    seeds.sort_by_key(|&i| (touching.size[i], i));
    let pieces = pieces_of(figures, labels, k);
    for t in GROUP_SIZES.into_iter().filter(|&t| t <= k) {
        for &seed in &seeds {
            if stop.load(Ordering::Relaxed) {
                return None;
            }
            let Some(group) = touching.group(seed, t) else {
                continue;
            };
            let mut key: Vec<Cell> = group.iter().flat_map(|&i| pieces[0][i].clone()).collect();
            key.sort_unstable();
            if tried.contains(&key) {
                continue;
            }
            tried.push(key);
            let unions: Vec<Vec<Cell>> = pieces
                .iter()
                .map(|fp| group.iter().flat_map(|&i| fp[i].iter().copied()).collect())
                .collect();
            let Some(found) = repairer.regroup(&unions, t - 1, stop) else {
                continue;
            };
            if found.len() != figures.len() || found[0].is_empty() || found[0].len() >= t {
                continue;
            }
            let mut out: Pieces = pieces
                .iter()
                .map(|fp| {
                    (0..k)
                        .filter(|i| !group.contains(i))
                        .map(|i| fp[i].clone())
                        .collect()
                })
                .collect();
            for (f, fp) in found.into_iter().enumerate() {
                out[f].extend(fp);
            }
            return Some(out);
        }
    }
    None
}

/// The cells of every piece in every figure.
fn pieces_of(figures: &[Figure], labels: &[Vec<u16>], k: usize) -> Pieces {
    figures
        .iter()
        .zip(labels)
        .map(|(fig, l)| {
            let mut fp = vec![Vec::new(); k];
            for (c, &a) in fig.cells().iter().zip(l) {
                fp[a as usize].push(*c);
            }
            fp
        })
        .collect()
}
