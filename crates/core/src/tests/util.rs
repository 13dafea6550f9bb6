//! Test helpers: shapes and labellings from compact ASCII strings.
//!
//! Notation: `|` ends a row and `/` ends a cubic z layer. A labelled string
//! writes a piece letter (`A` is label 0, `B` label 1, ...) for each cell:
//! one letter per cell on `square` and `cubic`; on `tri4` one
//! whitespace-separated token of four letters per square, for the triangles
//! top, right, bottom, left (`.` for an empty triangle, a lone `.` for an
//! empty square). A `?` marks a cell of the figure left unlabelled.

use std::collections::BTreeSet;

use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

use crate::figure::Figure;
use crate::lattice::{Cell, LatticeKind, Point};
use crate::solver::candidate::{Candidate, Problem};
use crate::solver::distance::Geometry;
use crate::solver::matching::PairMatching;
use crate::solver::piece::{Pieces, UNSET};
use crate::solver::shape::Shape;

pub(crate) use LatticeKind::{Cubic, Hex, Square, Tri3, Tri4};

/// The cells of a labelled string with their labels (`UNSET` for `?`).
pub(crate) fn labelled_cells(lattice: LatticeKind, compact: &str) -> Vec<(Cell, u16)> {
    let mut out = Vec::new();
    let label = |ch: char| -> u16 {
        match ch {
            '?' => UNSET,
            'A'..='Z' => ch as u16 - 'A' as u16,
            _ => panic!("bad label {ch:?} in {compact:?}"),
        }
    };
    for (z, layer) in compact.split('/').enumerate() {
        assert!(
            z == 0 || lattice == Cubic,
            "layers only on cubic: {compact:?}"
        );
        for (y, row) in layer.split('|').enumerate() {
            let (y, z) = (y as i32, z as i32);
            if lattice == Tri4 {
                for (x, token) in row.split_whitespace().enumerate() {
                    if token == "." {
                        continue;
                    }
                    assert_eq!(token.len(), 4, "tri4 token {token:?} in {compact:?}");
                    for (t, ch) in token.chars().enumerate() {
                        if ch != '.' {
                            out.push(([x as i32, y, t as i32], label(ch)));
                        }
                    }
                }
            } else {
                for (x, ch) in row.chars().enumerate() {
                    if ch != '.' {
                        let x = x as i32;
                        let cell = if lattice == Cubic {
                            [x, y, z]
                        } else {
                            [x, y, 0]
                        };
                        out.push((cell, label(ch)));
                    }
                }
            }
        }
    }
    out
}

/// A figure and its labels in the figure's cell order (labels of a shape).
pub(crate) fn labelled(lattice: LatticeKind, compact: &str) -> (Figure, Vec<u16>) {
    let cells = labelled_cells(lattice, compact);
    let figure = Figure::new(lattice, cells.iter().map(|(c, _)| *c))
        .unwrap_or_else(|e| panic!("{compact:?}: {e}"));
    let labels = figure
        .cells()
        .iter()
        .map(|c| cells.iter().find(|(d, _)| d == c).expect("cell").1)
        .collect();
    (figure, labels)
}

/// The solver's geometry of a lattice.
pub(crate) fn geometry(lattice: LatticeKind, mirror: bool) -> Geometry {
    let l = lattice.lattice();
    Geometry {
        syms: l.symmetries(mirror && l.supports_mirror()),
        dim: l.dim(),
        modulus: l.modulus(),
    }
}

/// A problem and a candidate from labelled strings, one per figure.
pub(crate) fn candidate(
    lattice: LatticeKind,
    mirror: bool,
    compact: &[&str],
) -> (Vec<Figure>, Problem, Candidate) {
    let parts: Vec<(Figure, Vec<u16>)> = compact.iter().map(|s| labelled(lattice, s)).collect();
    candidate_of(lattice, mirror, parts)
}

/// A problem and a candidate from labelled figures.
pub(crate) fn candidate_of(
    lattice: LatticeKind,
    mirror: bool,
    parts: Vec<(Figure, Vec<u16>)>,
) -> (Vec<Figure>, Problem, Candidate) {
    let k = parts
        .iter()
        .flat_map(|(_, l)| l.iter())
        .filter(|l| **l != UNSET)
        .map(|l| *l as usize + 1)
        .max()
        .unwrap_or(1);
    let problem = Problem::new(
        parts.iter().map(|(f, _)| Shape::of_figure(f)).collect(),
        geometry(lattice, mirror),
    );
    let figures = parts.iter().map(|(f, _)| f.clone()).collect();
    let cand = Candidate {
        labels: parts.into_iter().map(|(_, l)| l).collect(),
        k,
    };
    (figures, problem, cand)
}

/// The pieces of figure `f` of a candidate.
pub(crate) fn pieces_of(problem: &Problem, cand: &Candidate, f: usize) -> Pieces {
    Pieces::of(&problem.shapes[f], &cand.labels[f], cand.k)
}

/// The cells of each label of each figure (`[f][label]`), for the verifier.
/// Labels that no figure uses are dropped, as the solver drops them.
pub(crate) fn cells_by_label(figures: &[Figure], cand: &Candidate) -> Vec<Vec<Vec<Cell>>> {
    cand.cells_by_label(figures)
}

/// Whether the candidate is a valid dissection by the independent verifier.
pub(crate) fn verified(
    lattice: LatticeKind,
    mirror: bool,
    figures: &[Figure],
    cand: &Candidate,
) -> bool {
    crate::verify::verify_pieces(lattice, mirror, figures, &cells_by_label(figures, cand)).is_ok()
}

/// A seeded random stream for tests.
pub(crate) fn rng(seed: u64) -> ChaCha8Rng {
    ChaCha8Rng::seed_from_u64(seed)
}

/// The labels of a figure written back in the labelled notation of
/// `square` (`.` for cells not in the figure), for readable assertions.
pub(crate) fn draw_square(figure: &Figure, labels: &[u16]) -> String {
    let stats = figure.stats();
    let mut rows = Vec::new();
    for y in stats.min[1]..=stats.max[1] {
        let mut row = String::new();
        for x in stats.min[0]..=stats.max[0] {
            row.push(match figure.cells().iter().position(|c| *c == [x, y, 0]) {
                Some(i) if labels[i] == UNSET => '?',
                Some(i) => (b'A' + labels[i] as u8) as char,
                None => '.',
            });
        }
        rows.push(row);
    }
    rows.join("|")
}

/// The matching from the pieces of figure `from` to those of figure `to`,
/// as the solver computes it (through [`Candidate::align`], which builds
/// the distance's inputs itself), and the labels of `to` before alignment.
pub(crate) fn matching(
    problem: &Problem,
    cand: &Candidate,
    from: usize,
    to: usize,
) -> PairMatching {
    let mut c = cand.clone();
    let mut aligned = c.align(problem, from);
    aligned.matchings[to]
        .take()
        .expect("a matching to another figure")
}

/// The points of piece `label` of figure `f`.
pub(crate) fn piece_points(
    problem: &Problem,
    cand: &Candidate,
    f: usize,
    label: usize,
) -> BTreeSet<Point> {
    let p = pieces_of(problem, cand, f);
    p.members(label)
        .iter()
        .map(|&c| problem.shapes[f].point(c))
        .collect()
}
