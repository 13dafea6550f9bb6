//! Exact cover by dancing links (Knuth's Algorithm X), with *groups*: every
//! row belongs to one group, and a group may be used at most `capacity`
//! times. Items (the cells) must each be covered exactly once; groups are
//! never branched on. This is what counting tilings with several identical
//! pieces needs: the placements of one piece shape form a group whose
//! capacity is the number of copies, so tilings that only swap identical
//! pieces are found once.
//!
//! The search visits every solution, checks a stop flag and a deadline
//! after every [`CHECK_WORK`] link updates (a measure of work, not of
//! nodes: one node of a large board can update millions of links), and
//! reports progress (an estimate of the fraction of
//! the search tree done) through a callback.

use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

/// Link updates between two checks of the stop flag and the deadline
/// (well under a millisecond of work).
const CHECK_WORK: u64 = 1 << 16;

/// An exact cover problem under construction.
#[derive(Clone, Debug)]
pub struct ExactCover {
    items: usize,
    capacity: Vec<usize>,
    rows: Vec<(Vec<usize>, usize)>,
}

/// Occurs when a row names an item or group that does not exist.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("row names item {item} or group {group}, but there are {items} items and {groups} groups")]
pub struct BadRow {
    item: usize,
    group: usize,
    items: usize,
    groups: usize,
}

/// How a search ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum End {
    /// Every solution was visited.
    Complete,
    /// The visitor asked to stop.
    Visitor,
    /// The stop flag was raised.
    Stopped,
    /// The deadline passed.
    Deadline,
}

/// Progress of a running search.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Progress {
    /// Search nodes visited.
    pub nodes: u64,
    /// Solutions found.
    pub solutions: u64,
    /// Estimated fraction of the search tree done (0 to 1).
    pub done: f64,
}

/// When a search must stop early, and where progress goes.
pub struct Limits<'a> {
    /// Raised by someone else to stop the search.
    pub stop: Option<&'a AtomicBool>,
    /// Stop when this instant passes.
    pub deadline: Option<Instant>,
    /// Called every `progress_every` (checked every 4096 nodes).
    pub progress: Option<&'a mut dyn FnMut(Progress)>,
    /// Time between progress calls.
    pub progress_every: Duration,
}

impl Default for Limits<'_> {
    fn default() -> Self {
        Limits {
            stop: None,
            deadline: None,
            progress: None,
            progress_every: Duration::from_secs(1),
        }
    }
}

impl ExactCover {
    /// A problem with `items` items to cover exactly once and groups of the
    /// given capacities.
    pub fn new(items: usize, capacity: Vec<usize>) -> ExactCover {
        ExactCover {
            items,
            capacity,
            rows: Vec::new(),
        }
    }

    /// Adds a row covering `items` (distinct) in `group`; returns its index.
    pub fn add_row(&mut self, mut items: Vec<usize>, group: usize) -> Result<usize, BadRow> {
        items.sort_unstable();
        items.dedup();
        if group >= self.capacity.len() || items.iter().any(|&i| i >= self.items) {
            return Err(BadRow {
                item: items.last().copied().unwrap_or(0),
                group,
                items: self.items,
                groups: self.capacity.len(),
            });
        }
        self.rows.push((items, group));
        Ok(self.rows.len() - 1)
    }

    /// The number of rows.
    pub fn rows(&self) -> usize {
        self.rows.len()
    }

    /// Visits every solution (the indices of its rows, in the order chosen);
    /// the visitor returns `false` to stop. Returns how the search ended and
    /// the final progress.
    pub fn search(
        &self,
        mut visit: impl FnMut(&[usize]) -> bool,
        mut limits: Limits<'_>,
    ) -> (End, Progress) {
        let mut links = Links::new(self);
        let mut state = State {
            chosen: Vec::new(),
            remaining: self.capacity.clone(),
            progress: Progress {
                nodes: 0,
                solutions: 0,
                done: 0.0,
            },
            branch: Vec::new(),
            end: None,
            last_report: Instant::now(),
            next_check: 0,
        };
        links.solve(&mut state, &mut visit, &mut limits);
        let end = state.end.unwrap_or(End::Complete);
        if end == End::Complete {
            state.progress.done = 1.0;
        }
        (end, state.progress)
    }
}

struct State {
    chosen: Vec<usize>,
    remaining: Vec<usize>,
    progress: Progress,
    /// (index, count) of the branch taken at each depth, for the estimate.
    branch: Vec<(usize, usize)>,
    end: Option<End>,
    last_report: Instant,
    /// The work count at which the limits are checked next.
    next_check: u64,
}

/// The dancing links: node 0 is the root, nodes `1..=items` the item
/// headers, then one header per group, then the row nodes.
struct Links {
    left: Vec<usize>,
    right: Vec<usize>,
    up: Vec<usize>,
    down: Vec<usize>,
    /// The header of a node's column.
    col: Vec<usize>,
    /// The row of a row node.
    row: Vec<usize>,
    /// The number of nodes in a column (by header).
    size: Vec<usize>,
    items: usize,
    /// The group of each row, and its node in the group's column.
    group: Vec<usize>,
    /// Link updates so far (the search's measure of work).
    work: u64,
}

impl Links {
    fn new(p: &ExactCover) -> Links {
        let headers = 1 + p.items + p.capacity.len();
        let mut l = Links {
            left: Vec::new(),
            right: Vec::new(),
            up: Vec::new(),
            down: Vec::new(),
            col: Vec::new(),
            row: Vec::new(),
            size: vec![0; headers],
            items: p.items,
            group: Vec::with_capacity(p.rows.len()),
            work: 0,
        };
        for h in 0..headers {
            l.up.push(h);
            l.down.push(h);
            l.col.push(h);
            l.row.push(usize::MAX);
            // Items form the root's ring; group headers link to themselves.
            if h <= p.items {
                l.left.push(if h == 0 { p.items } else { h - 1 });
                l.right.push(if h == p.items { 0 } else { h + 1 });
            } else {
                l.left.push(h);
                l.right.push(h);
            }
        }
        for (r, (items, g)) in p.rows.iter().enumerate() {
            l.group.push(*g);
            let first = l.col.len();
            let cols = items.iter().map(|i| i + 1).chain([1 + p.items + g]);
            let n = items.len() + 1;
            for (k, c) in cols.enumerate() {
                let x = l.col.len();
                l.col.push(c);
                l.row.push(r);
                l.left.push(if k == 0 { first + n - 1 } else { x - 1 });
                l.right.push(if k == n - 1 { first } else { x + 1 });
                let last = l.up[c];
                l.up.push(last);
                l.down.push(c);
                l.down[last] = x;
                l.up[c] = x;
                l.size[c] += 1;
            }
        }
        l
    }

    fn hide_rows(&mut self, c: usize) {
        let mut i = self.down[c];
        while i != c {
            let mut j = self.right[i];
            while j != i {
                let (u, d) = (self.up[j], self.down[j]);
                self.down[u] = d;
                self.up[d] = u;
                self.size[self.col[j]] -= 1;
                self.work += 1;
                j = self.right[j];
            }
            i = self.down[i];
        }
    }

    fn unhide_rows(&mut self, c: usize) {
        let mut i = self.up[c];
        while i != c {
            let mut j = self.left[i];
            while j != i {
                let (u, d) = (self.up[j], self.down[j]);
                self.down[u] = j;
                self.up[d] = j;
                self.size[self.col[j]] += 1;
                self.work += 1;
                j = self.left[j];
            }
            i = self.up[i];
        }
    }

    fn cover(&mut self, c: usize) {
        let (l, r) = (self.left[c], self.right[c]);
        self.right[l] = r;
        self.left[r] = l;
        self.hide_rows(c);
    }

    fn uncover(&mut self, c: usize) {
        self.unhide_rows(c);
        let (l, r) = (self.left[c], self.right[c]);
        self.right[l] = c;
        self.left[r] = c;
    }

    /// Chooses row node `x`'s other columns: covers items, counts the group
    /// down and hides its remaining rows when it is used up.
    fn select(&mut self, x: usize, state: &mut State) {
        let mut j = self.right[x];
        while j != x {
            let c = self.col[j];
            if c <= self.items {
                self.cover(c);
            } else {
                let g = c - 1 - self.items;
                state.remaining[g] -= 1;
                if state.remaining[g] == 0 {
                    self.hide_rows(c);
                }
            }
            j = self.right[j];
        }
    }

    fn deselect(&mut self, x: usize, state: &mut State) {
        let mut j = self.left[x];
        while j != x {
            let c = self.col[j];
            if c <= self.items {
                self.uncover(c);
            } else {
                let g = c - 1 - self.items;
                if state.remaining[g] == 0 {
                    self.unhide_rows(c);
                }
                state.remaining[g] += 1;
            }
            j = self.left[j];
        }
    }

    fn estimate(state: &State) -> f64 {
        let mut done = 0.0;
        let mut scale = 1.0;
        for &(i, n) in &state.branch {
            done += scale * i as f64 / n as f64;
            scale /= n as f64;
        }
        done
    }

    fn solve(
        &mut self,
        state: &mut State,
        visit: &mut impl FnMut(&[usize]) -> bool,
        limits: &mut Limits<'_>,
    ) {
        state.progress.nodes += 1;
        if self.work >= state.next_check {
            state.next_check = self.work + CHECK_WORK;
            if limits.stop.is_some_and(|s| s.load(Ordering::Relaxed)) {
                state.end = Some(End::Stopped);
                return;
            }
            let now = Instant::now();
            if limits.deadline.is_some_and(|d| now >= d) {
                state.end = Some(End::Deadline);
                return;
            }
            if now.duration_since(state.last_report) >= limits.progress_every {
                state.last_report = now;
                state.progress.done = Self::estimate(state);
                if let Some(f) = limits.progress.as_mut() {
                    f(state.progress);
                }
            }
        }
        if self.right[0] == 0 {
            state.progress.solutions += 1;
            if !visit(&state.chosen) {
                state.end = Some(End::Visitor);
            }
            return;
        }
        // The item with the fewest rows left (Knuth's MRV rule).
        let mut c = self.right[0];
        let mut best = self.size[c];
        let mut j = self.right[c];
        while j != 0 && best > 0 {
            if self.size[j] < best {
                best = self.size[j];
                c = j;
            }
            j = self.right[j];
        }
        if best == 0 {
            return;
        }
        self.cover(c);
        let mut x = self.down[c];
        let mut k = 0;
        state.branch.push((0, best));
        while x != c {
            if let Some(b) = state.branch.last_mut() {
                b.0 = k;
            }
            state.chosen.push(self.row[x]);
            self.select(x, state);
            self.solve(state, visit, limits);
            self.deselect(x, state);
            state.chosen.pop();
            if state.end.is_some() {
                break;
            }
            x = self.down[x];
            k += 1;
        }
        state.branch.pop();
        self.uncover(c);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn all(p: &ExactCover) -> Vec<Vec<usize>> {
        let mut out = Vec::new();
        let (end, _) = p.search(
            |rows| {
                let mut r = rows.to_vec();
                r.sort();
                out.push(r);
                true
            },
            Limits::default(),
        );
        assert_eq!(end, End::Complete);
        out.sort();
        out
    }

    #[test]
    fn knuths_example_has_its_one_solution() {
        // Knuth, "Dancing links", the 7-item example (items A..G = 0..6).
        let rows = [
            vec![2, 4, 5],
            vec![0, 3, 6],
            vec![1, 2, 5],
            vec![0, 3],
            vec![1, 6],
            vec![3, 4, 6],
        ];
        let mut p = ExactCover::new(7, vec![rows.len()]);
        for r in rows {
            p.add_row(r, 0).unwrap();
        }
        assert_eq!(all(&p), vec![vec![0, 3, 4]]);
    }

    #[test]
    fn group_capacity_limits_the_uses_of_a_group() {
        // Two items, each coverable by a row of group 0 or of group 1.
        let mut p = ExactCover::new(2, vec![1, 2]);
        p.add_row(vec![0], 0).unwrap();
        p.add_row(vec![1], 0).unwrap();
        p.add_row(vec![0], 1).unwrap();
        p.add_row(vec![1], 1).unwrap();
        // Group 0 at most once: {0,3}, {1,2}, {2,3}; not {0,1}.
        assert_eq!(all(&p), vec![vec![0, 3], vec![1, 2], vec![2, 3]]);
    }

    #[test]
    fn a_bad_row_is_refused() {
        let mut p = ExactCover::new(2, vec![1]);
        assert!(p.add_row(vec![2], 0).is_err());
        assert!(p.add_row(vec![0], 1).is_err());
    }

    #[test]
    fn the_visitor_and_the_stop_flag_end_the_search() {
        let mut p = ExactCover::new(1, vec![5]);
        for _ in 0..5 {
            p.add_row(vec![0], 0).unwrap();
        }
        let (end, prog) = p.search(|_| false, Limits::default());
        assert_eq!((end, prog.solutions), (End::Visitor, 1));
        let stop = AtomicBool::new(true);
        // 20 items with 2 rows each: 2^20 solutions, so the check at node
        // 4096 sees the flag.
        let mut q = ExactCover::new(20, vec![40]);
        for i in 0..20 {
            q.add_row(vec![i], 0).unwrap();
            q.add_row(vec![i], 0).unwrap();
        }
        let limits = Limits {
            stop: Some(&stop),
            ..Limits::default()
        };
        let (end, prog) = q.search(|_| true, limits);
        assert_eq!(end, End::Stopped);
        assert!(prog.solutions < 1 << 20);
    }
}
