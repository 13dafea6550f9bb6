//! The corner bound at any size: a cheap relaxation of
//! [`incompatible_clique`](crate::incompatible_clique) for figures too large
//! for the full incompatibility graph (its cost is quadratic in the cells
//! and linear in the motions).
//!
//! Two cells `a`, `b` of one shape can share a connected piece only if,
//! for every other shape `h`, some motion puts both inside one component of
//! `h`: the moved difference `g(b) - g(a)` is then the difference `q2 - q1`
//! of two cells of one component of `h`, and the translation carrying
//! `g(a)` onto `q1` is a lattice translation (`q1` has the residue of
//! `g(a)`). The set of such differences of `h` (its *difference set*, keyed
//! by the residue of `q1`) is built once per shape; a pair whose moved
//! differences miss it under every symmetry is incompatible. This drops the
//! path condition of the full graph, so it proves less, never more: a clique
//! of it is still a lower bound.
//!
//! Only a few *extreme* cells are candidates (per direction of a small set,
//! the cells furthest along it, and the cells with the fewest neighbours):
//! the corners of a cube against smaller pieces are what such a bound needs,
//! and the clique search stays tiny.

use rustc_hash::FxHashMap;

use dissect_core::lattice::Point;

use crate::incompatible_clique::Incompatibility;
use crate::instance::{Instance, Shape};

/// Cells kept per direction (ties beyond it are dropped).
const PER_DIRECTION: usize = 2;

/// Cells with the fewest neighbours kept as candidates, at most.
const FEWEST_NEIGHBOURS: usize = 48;

/// The largest difference set built (flags, one byte each); a shape whose
/// box of differences is larger gets no such bound.
const MAX_FLAGS: usize = 1 << 26;

/// The difference set of one shape: which `q2 - q1` occur for two cells of
/// one component, per residue of `q1`.
struct Differences {
    /// The residue classes of the shape's points, numbered.
    residues: FxHashMap<Point, usize>,
    /// The smallest difference on each axis.
    lo: [i32; 3],
    /// The box of differences on each axis.
    size: [usize; 3],
    /// One flag per (residue, difference in the box).
    seen: Vec<bool>,
}

impl Differences {
    /// The difference set of `shape`; `None` when `interrupted` or when it
    /// would be larger than `MAX_FLAGS`.
    fn of(inst: &Instance, shape: &Shape, interrupted: &dyn Fn() -> bool) -> Option<Differences> {
        let mut residues: FxHashMap<Point, usize> = FxHashMap::default();
        let class: Vec<usize> = shape
            .points
            .iter()
            .map(|p| {
                let n = residues.len();
                *residues.entry(inst.residue(*p)).or_insert(n)
            })
            .collect();
        let (mut pmin, mut pmax) = ([i32::MAX; 3], [i32::MIN; 3]);
        for p in &shape.points {
            for d in 0..3 {
                pmin[d] = pmin[d].min(p[d]);
                pmax[d] = pmax[d].max(p[d]);
            }
        }
        let mut lo = [0i32; 3];
        let mut size = [1usize; 3];
        for d in 0..3 {
            let span = pmax[d] - pmin[d];
            lo[d] = -span;
            size[d] = (2 * span + 1) as usize;
        }
        let cells = size[0] * size[1] * size[2];
        if cells.saturating_mul(residues.len()) > MAX_FLAGS {
            return None;
        }
        let mut seen = vec![false; cells * residues.len()];
        let mut by_component: Vec<Vec<usize>> = vec![Vec::new(); shape.components];
        for (i, &c) in shape.component.iter().enumerate() {
            by_component[c].push(i);
        }
        for members in &by_component {
            for (n, &i) in members.iter().enumerate() {
                if n % 256 == 0 && interrupted() {
                    return None;
                }
                let q1 = shape.points[i];
                let base = class[i] * cells;
                for &j in members {
                    let q2 = shape.points[j];
                    let mut idx = 0usize;
                    for d in (0..3).rev() {
                        idx = idx * size[d] + (q2[d] - q1[d] - lo[d]) as usize;
                    }
                    seen[base + idx] = true;
                }
            }
        }
        Some(Differences {
            residues,
            lo,
            size,
            seen,
        })
    }

    /// Whether some `q1` of residue `residue` and `q2 = q1 + diff` lie in one
    /// component.
    fn contains(&self, residue: Point, diff: Point) -> bool {
        let Some(&class) = self.residues.get(&residue) else {
            return false;
        };
        let mut idx = 0usize;
        for d in (0..3).rev() {
            let v = diff[d] - self.lo[d];
            if v < 0 || v as usize >= self.size[d] {
                return false;
            }
            idx = idx * self.size[d] + v as usize;
        }
        self.seen[class * self.size[0] * self.size[1] * self.size[2] + idx]
    }
}

/// The extreme cells of a shape: per direction of `{-1, 0, 1}^dim \ 0`, the
/// cells furthest along it, and the cells with the fewest neighbours; sorted
/// and without repeats.
fn extremes(inst: &Instance, shape: &Shape) -> Vec<usize> {
    let dim = inst.dim;
    let mut out = Vec::new();
    let mut dirs: Vec<[i64; 3]> = Vec::new();
    for code in 0..3i64.pow(dim as u32) {
        let mut v = [0i64; 3];
        let mut rest = code;
        for x in v.iter_mut().take(dim) {
            *x = rest % 3 - 1;
            rest /= 3;
        }
        if v != [0, 0, 0] {
            dirs.push(v);
        }
    }
    let n = shape.len();
    let mut order: Vec<usize> = (0..n).collect();
    for dir in &dirs {
        let key =
            |i: usize| -> i64 { (0..3).map(|d| dir[d] * i64::from(shape.points[i][d])).sum() };
        order.sort_unstable_by_key(|&i| (std::cmp::Reverse(key(i)), i));
        out.extend(order.iter().take(PER_DIRECTION));
    }
    order.sort_unstable_by_key(|&i| (shape.adj[i].len(), i));
    out.extend(order.iter().take(FEWEST_NEIGHBOURS));
    out.sort_unstable();
    out.dedup();
    out
}

/// A clique of incompatible extreme cells of shape `k` (indices into its
/// cells), by the difference sets of every other shape; `None` when
/// `interrupted` or when a difference set would be too large.
pub(crate) fn extent_clique(
    inst: &Instance,
    k: usize,
    node_limit: usize,
    interrupted: &dyn Fn() -> bool,
) -> Option<Vec<usize>> {
    let shape = &inst.shapes[k];
    let cand = extremes(inst, shape);
    let mut others = Vec::new();
    for (h, s) in inst.shapes.iter().enumerate() {
        if h != k {
            others.push(Differences::of(inst, s, interrupted)?);
        }
    }
    let m = cand.len();
    let mut apart = vec![vec![false; m]; m];
    for a in 0..m {
        if interrupted() {
            return None;
        }
        for b in a + 1..m {
            let split = never_together(inst, shape, &others, cand[a], cand[b]);
            apart[a][b] = split;
            apart[b][a] = split;
        }
    }
    let graph = Incompatibility::from_pairs(m, |a, b| apart[a][b]);
    let clique = graph.clique(node_limit, interrupted);
    Some(clique.into_iter().map(|i| cand[i]).collect())
}

/// Whether cells `a` and `b` of `shape` lie in different components, or some
/// other shape (its difference set in `others`) takes their moved
/// difference under no symmetry.
fn never_together(
    inst: &Instance,
    shape: &Shape,
    others: &[Differences],
    a: usize,
    b: usize,
) -> bool {
    let (pa, pb) = (shape.points[a], shape.points[b]);
    shape.component[a] != shape.component[b]
        || others.iter().any(|diffs| {
            inst.syms.iter().all(|g| {
                let (ga, gb) = (g.apply(pa), g.apply(pb));
                !diffs.contains(inst.residue(ga), gb - ga)
            })
        })
}

#[cfg(test)]
mod tests {
    use super::*;
    use dissect_core::io::parse_figure;
    use dissect_core::{Figure, LatticeKind};

    /// The relaxation proves less than the full graph, never more: every
    /// pair it calls apart, the full graph (paths kept inside) calls apart
    /// too; on every lattice, with and without mirror images.
    #[test]
    fn every_pair_apart_by_differences_is_apart_in_the_full_graph() {
        let cases: [(LatticeKind, &[&str]); 4] = [
            (
                LatticeKind::Square,
                &["###.#\n###..\n###..\n", "#####\n#####\n"],
            ),
            (
                LatticeKind::Square,
                &["#.#.#\n#####\n", "#######\n...#...\n"],
            ),
            (LatticeKind::Tri4, &["4444\n4444\n", "########\n"]),
            (
                LatticeKind::Cubic,
                &["##.#\n##..\n\n##..\n##..\n", "###\n###\n\n###\n...\n"],
            ),
        ];
        for (lattice, texts) in cases {
            let figs: Vec<Figure> = texts
                .iter()
                .map(|t| parse_figure(t, lattice).expect("test figure"))
                .collect();
            for mirror in [false, true] {
                let inst = Instance::new(&figs, mirror, 0);
                for k in 0..inst.shapes.len() {
                    let shape = &inst.shapes[k];
                    let others: Vec<Differences> = (0..inst.shapes.len())
                        .filter(|&h| h != k)
                        .map(|h| Differences::of(&inst, &inst.shapes[h], &|| false).expect("small"))
                        .collect();
                    let full = Incompatibility::of_shape(&inst, k, &|| false).expect("built");
                    let mut apart_pairs = 0;
                    for a in 0..shape.len() {
                        for b in a + 1..shape.len() {
                            if never_together(&inst, shape, &others, a, b) {
                                apart_pairs += 1;
                                assert!(
                                    full.apart(a, b),
                                    "{lattice:?} mirror {mirror}: {a} {b} apart by differences only"
                                );
                            }
                        }
                    }
                    // The test figures are chosen so that it proves something.
                    assert!(apart_pairs > 0, "{lattice:?}: no pair apart in shape {k}");
                }
            }
        }
    }

    /// A 9x9x9 cube against a 27x9x3 slab (729 cells, over the full
    /// graph's size): two cubes can share a piece only if their difference
    /// fits the slab, so only cells more than 2 apart on every axis are
    /// apart; opposite corners are, and the clique holds only such pairs.
    #[test]
    fn a_cube_against_a_thin_slab_keeps_far_corners_apart() {
        let layer = |w: usize, h: usize| -> String { format!("{}\n", "#".repeat(w)).repeat(h) };
        let cube = vec![layer(9, 9); 9].join("\n");
        let slab = vec![layer(27, 9); 3].join("\n");
        let figs: Vec<Figure> = [cube, slab]
            .iter()
            .map(|t| parse_figure(t, LatticeKind::Cubic).expect("figure"))
            .collect();
        let inst = Instance::new(&figs, true, 0);
        let clique = extent_clique(&inst, 0, 10_000, &|| false).expect("small");
        // Opposite corners (differing on all three axes) pair up: 2 at least.
        assert!(clique.len() >= 2, "{clique:?}");
        for (i, &a) in clique.iter().enumerate() {
            for &b in &clique[i + 1..] {
                let d = inst.shapes[0].points[b] - inst.shapes[0].points[a];
                let spread = (0..3).filter(|&k| d[k].abs() > 2).count();
                assert_eq!(spread, 3, "{a} and {b} could share a piece in the slab");
            }
        }
    }
}
