//! Assembly counts: in how many ways do a dissection's pieces tile a figure?
//!
//! Every placement the lattice allows is tried (translations and the
//! allowed point symmetries, mirror images only when the dissection allows
//! them); identical pieces are interchangeable, so a tiling is a set of
//! (piece shape, cells) pairs and tilings that only swap identical pieces
//! count once. The tilings are counted by exact cover ([`crate::dlx`]), and
//! the count up to the figure's own symmetries by Burnside's lemma: each
//! tiling found adds the number of the figure's symmetries that fix it, and
//! the sum divided by the number of symmetries is the number of orbits. So
//! nothing but the current tiling is kept in memory.

use std::collections::{HashMap, HashSet};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use dissect_core::lattice::Point;
use dissect_core::transform::Transform;
use dissect_core::{Cell, Figure};

use crate::dlx::{End, ExactCover, Limits, Progress};
use crate::geometry::Motions;

/// The pieces of a dissection grouped into shapes: congruent pieces (under
/// the allowed motions) are one shape with a multiplicity.
#[derive(Clone, Debug)]
pub struct PieceSet {
    motions: Motions,
    /// One representative per shape, with its number of copies and the
    /// indices of the pieces of that shape.
    shapes: Vec<(Vec<Cell>, Vec<usize>)>,
    area: usize,
}

/// Occurs when assemblies cannot be counted.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum AssemblyError {
    /// Occurs when there is no piece or a piece has no cell.
    #[error("the solution has an empty piece or no piece")]
    EmptyPiece,
    /// Occurs when the pieces' total area is not the figure's.
    #[error("the pieces have {pieces} cells in all, the figure has {figure}")]
    Area {
        /// Cells of all pieces.
        pieces: usize,
        /// Cells of the figure.
        figure: usize,
    },
    /// Occurs when the figure is on another lattice than the pieces.
    #[error("the figure is on the {figure} lattice, the pieces on {pieces}")]
    Lattice {
        /// The figure's lattice.
        figure: dissect_core::LatticeKind,
        /// The pieces' lattice.
        pieces: dissect_core::LatticeKind,
    },
}

impl PieceSet {
    /// Groups `pieces` (cells of each piece, in any figure's coordinates)
    /// into shapes.
    pub fn new(motions: Motions, pieces: &[Vec<Cell>]) -> Result<PieceSet, AssemblyError> {
        if pieces.is_empty() || pieces.iter().any(|p| p.is_empty()) {
            return Err(AssemblyError::EmptyPiece);
        }
        let mut by_form: HashMap<Vec<Point>, usize> = HashMap::new();
        let mut shapes: Vec<(Vec<Cell>, Vec<usize>)> = Vec::new();
        for (i, p) in pieces.iter().enumerate() {
            let mut cells = p.clone();
            cells.sort_unstable();
            cells.dedup();
            let form = motions.canonical(&cells);
            match by_form.get(&form) {
                Some(&s) => shapes[s].1.push(i),
                None => {
                    by_form.insert(form, shapes.len());
                    shapes.push((cells, vec![i]));
                }
            }
        }
        let area = shapes.iter().map(|(c, n)| c.len() * n.len()).sum();
        Ok(PieceSet {
            motions,
            shapes,
            area,
        })
    }

    /// The motions pieces may make.
    pub fn motions(&self) -> &Motions {
        &self.motions
    }

    /// The number of distinct shapes.
    pub fn shape_count(&self) -> usize {
        self.shapes.len()
    }

    /// The number of pieces.
    pub fn piece_count(&self) -> usize {
        self.shapes.iter().map(|s| s.1.len()).sum()
    }

    /// The pieces' total number of cells.
    pub fn area(&self) -> usize {
        self.area
    }
}

/// The result of counting the tilings of one figure.
#[derive(Clone, Debug, PartialEq)]
pub struct Count {
    /// Distinct tilings found (all of them when `complete`).
    pub tilings: u64,
    /// Tilings up to the figure's symmetries (a lower bound unless `complete`).
    pub up_to_symmetry: u64,
    /// The number of the figure's symmetries (allowed motions mapping it onto itself).
    pub figure_symmetries: usize,
    /// Whether the search finished (not stopped by the time limit or the flag).
    pub complete: bool,
    /// Search nodes visited.
    pub nodes: u64,
    /// Time spent.
    pub elapsed: Duration,
}

impl Count {
    /// Whether the figure has exactly one tiling up to its symmetries.
    pub fn unique(&self) -> bool {
        self.complete && self.up_to_symmetry == 1
    }
}

/// When to stop counting, and where progress goes.
#[derive(Default)]
pub struct CountLimits<'a> {
    /// Raised to stop.
    pub stop: Option<&'a AtomicBool>,
    /// Stop at this instant.
    pub deadline: Option<Instant>,
    /// Called now and then with the progress so far.
    pub progress: Option<&'a mut dyn FnMut(Progress)>,
}

/// The placements of every shape in a figure, as an exact cover problem.
struct Board {
    cover: ExactCover,
    /// `rows[r]`: (shape, sorted cells).
    rows: Vec<(usize, Vec<Cell>)>,
}

/// The board of `figure` (`Ok(None)` when `interrupted` says so: it is
/// asked before each orientation of each shape).
fn board(
    pieces: &PieceSet,
    figure: &Figure,
    interrupted: &dyn Fn() -> bool,
) -> Result<Option<Board>, AssemblyError> {
    let m = &pieces.motions;
    if figure.lattice() != m.lattice() {
        return Err(AssemblyError::Lattice {
            figure: figure.lattice(),
            pieces: m.lattice(),
        });
    }
    if pieces.area != figure.len() {
        return Err(AssemblyError::Area {
            pieces: pieces.area,
            figure: figure.len(),
        });
    }
    let index: HashMap<Cell, usize> = figure
        .cells()
        .iter()
        .enumerate()
        .map(|(i, c)| (*c, i))
        .collect();
    let region: HashSet<Cell> = figure.cells().iter().copied().collect();
    let mut cover = ExactCover::new(
        figure.len(),
        pieces.shapes.iter().map(|s| s.1.len()).collect(),
    );
    let mut rows = Vec::new();
    for (s, (rep, _)) in pieces.shapes.iter().enumerate() {
        let Some(placements) = m.placements_until(rep, &region, interrupted) else {
            return Ok(None);
        };
        for cells in placements {
            let items = cells.iter().map(|c| index[c]).collect();
            cover
                .add_row(items, s)
                .expect("placements lie in the figure");
            rows.push((s, cells));
        }
    }
    Ok(Some(Board { cover, rows }))
}

/// The figure's symmetries (but the identity) as permutations of the
/// board's rows; `None` when `interrupted` says so (it is asked every
/// 1024 rows).
fn row_permutations(
    m: &Motions,
    b: &Board,
    syms: &[Transform],
    interrupted: &dyn Fn() -> bool,
) -> Option<Vec<Vec<usize>>> {
    let row_of: HashMap<(usize, &[Cell]), usize> = b
        .rows
        .iter()
        .enumerate()
        .map(|(r, (s, c))| ((*s, c.as_slice()), r))
        .collect();
    let mut perms = Vec::with_capacity(syms.len().saturating_sub(1));
    for g in syms.iter().skip(1) {
        let mut perm = Vec::with_capacity(b.rows.len());
        for (r, (s, cells)) in b.rows.iter().enumerate() {
            if r.is_multiple_of(1024) && interrupted() {
                return None;
            }
            let mut img: Vec<Cell> = cells
                .iter()
                .map(|c| m.move_cell(g, *c).expect("a symmetry maps cells to cells"))
                .collect();
            img.sort_unstable();
            perm.push(row_of[&(*s, img.as_slice())]);
        }
        perms.push(perm);
    }
    Some(perms)
}

/// Counts the tilings of `figure` by `pieces`, and the tilings up to the
/// figure's symmetries. The stop flag and the deadline of `limits` are
/// looked at while the board is built and all through the search.
pub fn count(
    pieces: &PieceSet,
    figure: &Figure,
    limits: CountLimits<'_>,
) -> Result<Count, AssemblyError> {
    let start = Instant::now();
    let interrupted = || {
        limits.stop.is_some_and(|s| s.load(Ordering::Relaxed))
            || limits.deadline.is_some_and(|d| Instant::now() >= d)
    };
    let cut_short = |figure_symmetries: usize| Count {
        tilings: 0,
        up_to_symmetry: 0,
        figure_symmetries,
        complete: false,
        nodes: 0,
        elapsed: start.elapsed(),
    };
    let m = &pieces.motions;
    let syms = m.symmetries_of(figure.cells());
    let Some(b) = board(pieces, figure, &interrupted)? else {
        return Ok(cut_short(syms.len()));
    };
    let Some(perms) = row_permutations(m, &b, &syms, &interrupted) else {
        return Ok(cut_short(syms.len()));
    };
    let mut tilings = 0u64;
    let mut fixed_sum = 0u64;
    let mut a: Vec<usize> = Vec::new();
    let mut img: Vec<usize> = Vec::new();
    let (end, progress) = b.cover.search(
        |rows| {
            tilings += 1;
            a.clear();
            a.extend_from_slice(rows);
            a.sort_unstable();
            let mut fixed = 1;
            for p in &perms {
                img.clear();
                img.extend(a.iter().map(|&r| p[r]));
                img.sort_unstable();
                if img == a {
                    fixed += 1;
                }
            }
            fixed_sum += fixed;
            true
        },
        Limits {
            stop: limits.stop,
            deadline: limits.deadline,
            progress: limits.progress,
            progress_every: Duration::from_millis(250),
        },
    );
    let g = syms.len().max(1) as u64;
    Ok(Count {
        tilings,
        up_to_symmetry: fixed_sum.div_ceil(g),
        figure_symmetries: syms.len(),
        complete: end == End::Complete,
        nodes: progress.nodes,
        elapsed: start.elapsed(),
    })
}

/// One line of `dissect assemblies` for a figure called `name`:
/// `NAME: N tilings (M up to the figure's symmetries)`, then ` unique`
/// when M is 1; a count cut short says so.
pub fn report_line(name: &str, c: &Count) -> String {
    if c.complete {
        let unique = if c.unique() { " unique" } else { "" };
        format!(
            "{name}: {} tilings ({} up to the figure's symmetries){unique}",
            c.tilings, c.up_to_symmetry
        )
    } else {
        format!(
            "{name}: at least {} tilings (at least {} up to the figure's symmetries; stopped after {:.1} s)",
            c.tilings,
            c.up_to_symmetry,
            c.elapsed.as_secs_f64()
        )
    }
}
