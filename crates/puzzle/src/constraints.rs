//! The designer's constraints on a dissection: regions of a figure kept
//! whole (`--keep N:REGIONS.txt`), piece-size bounds (`--min-piece`,
//! `--max-piece`), the checkerboard rule (`--checkerboard`: every piece
//! keeps the colour of each of its cells) and the weight of the symmetry
//! term (`--symmetry-weight`). Parsed from text, validated against the
//! figures, and checked on a dissection.
//!
//! The checkerboard colour of a cell is the parity of its block
//! coordinates; it is offered on the lattices where that colours every two
//! neighbouring cells differently (`square`, `cubic`), found through the
//! [`dissect_core::Lattice`] trait alone.

use std::collections::{BTreeMap, HashMap};
use std::fmt;

use dissect_core::{Cell, Figure, LatticeKind};
use serde_json::{json, Value};

use crate::disassembly::{disassemble, Limits};
use crate::geometry::Motions;

/// Cells of one figure that must end in the same piece, one region per
/// letter.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct KeepRegions {
    figure: usize,
    regions: BTreeMap<char, Vec<Cell>>,
}

/// Occurs when constraints cannot be read or cannot hold.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ConstraintError {
    /// Occurs on a character other than a-z, `.` and `#` in a regions grid.
    #[error("line {line}, column {column}: unexpected character {found:?} (a regions grid allows the letters a-z, '.' and '#')")]
    Character {
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The character.
        found: char,
    },
    /// Occurs on a bad layer separator in a cubic regions grid.
    #[error("line {line}: {problem}")]
    Layers {
        /// 1-based line.
        line: usize,
        /// What is wrong.
        problem: &'static str,
    },
    /// Occurs when a letter marks a place where the figure has no cell.
    #[error(
        "line {line}, column {column}: {letter:?} marks a place where figure {figure} has no cell"
    )]
    OutsideFigure {
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// The letter.
        letter: char,
        /// The figure (1-based).
        figure: usize,
    },
    /// Occurs when a region given by its cells is not named by a letter a-z.
    #[error("a region is named by one letter a-z, not {0:?}")]
    Letter(String),
    /// Occurs when a region given by its cells has a cell the figure lacks.
    #[error("region {letter:?}: cell {cell:?} is not a cell of figure {figure}")]
    CellOutside {
        /// The letter.
        letter: char,
        /// The cell's coordinates (as in the solution format).
        cell: Vec<i64>,
        /// The figure (1-based).
        figure: usize,
    },
    /// Occurs when a regions grid marks nothing.
    #[error("no region is marked (mark the cells to keep together with the letters a-z)")]
    NoRegion,
    /// Occurs when a keep constraint names a figure that is not given.
    #[error("figure {figure} does not exist (there are {figures} figures, numbered from 1)")]
    FigureNumber {
        /// The figure asked for (1-based).
        figure: usize,
        /// How many there are.
        figures: usize,
    },
    /// Occurs when a size bound is 0.
    #[error("--{0} must be at least 1")]
    ZeroSize(&'static str),
    /// Occurs when the smallest allowed piece is larger than the largest.
    #[error("impossible: --min-piece {min} is larger than --max-piece {max}")]
    SizeBounds {
        /// The lower bound.
        min: usize,
        /// The upper bound.
        max: usize,
    },
    /// Occurs when no piece can be as large as the lower bound.
    #[error("impossible: --min-piece {min} is larger than the figures ({area} cells)")]
    MinTooLarge {
        /// The lower bound.
        min: usize,
        /// The figures' area.
        area: usize,
    },
    /// Occurs when a keep region has more cells than a piece may have.
    #[error("impossible: region {letter:?} of figure {figure} has {cells} cells, more than --max-piece {max}")]
    RegionTooLarge {
        /// The figure (1-based).
        figure: usize,
        /// The letter.
        letter: char,
        /// The region's cells.
        cells: usize,
        /// The upper bound.
        max: usize,
    },
    /// Occurs when the lattice has no checkerboard colouring.
    #[error("--checkerboard needs a lattice whose cells can be coloured like a checkerboard (square or cubic), not {0}")]
    NoCheckerboard(LatticeKind),
    /// Occurs when figures have different numbers of black cells.
    #[error("impossible with --checkerboard: the figures have different numbers of black cells ({0}); pieces that keep their colours cannot make them all")]
    ColourCounts(String),
    /// Occurs when a level of 2 or more is asked of flat figures (every
    /// flat piece lifts off: level 1).
    #[error("impossible: --min-level {0} on a flat lattice (every piece of a flat figure lifts off: level 1)")]
    FlatLevel(usize),
    /// Occurs when a level of 2 or more is asked and a figure meets every
    /// line along a lattice axis in one run of cells at most
    /// ([`crate::disassembly::axis_convex`]: a box, a cube, a slab): there
    /// the first group that can move at all can go away at once, so its
    /// level is 1.
    #[error("impossible: --min-level {level}: figure {figure} meets every line along an axis in one run of cells (a box, a cube, a slab...), so the first group that can move in it comes free at once: level 1")]
    ConvexLevel {
        /// The figure (1-based).
        figure: usize,
        /// The level asked.
        level: usize,
    },
    /// Occurs when the symmetry weight is negative or not a number.
    #[error("--symmetry-weight must be a number >= 0, not {0}")]
    SymmetryWeight(String),
}

impl ConstraintError {
    /// Whether the constraints are well formed but cannot all hold (a run
    /// under them finds nothing: exit 1 on the command line), rather than
    /// malformed (bad input: exit 2).
    pub fn is_impossible(&self) -> bool {
        matches!(
            self,
            ConstraintError::SizeBounds { .. }
                | ConstraintError::MinTooLarge { .. }
                | ConstraintError::RegionTooLarge { .. }
                | ConstraintError::ColourCounts(_)
                | ConstraintError::FlatLevel(_)
                | ConstraintError::ConvexLevel { .. }
        )
    }
}

impl KeepRegions {
    /// Reads a regions grid over figure `figure` (0-based; `figures[figure]`
    /// is that figure): a text in the figure's own coordinates where a
    /// letter a-z marks the cells (on `tri4` every triangle of the square,
    /// on `cubic` one z layer per block of rows) that must end in one piece,
    /// and `.` or `#` leave a place free.
    pub fn parse(
        text: &str,
        figure: usize,
        figures: &[Figure],
    ) -> Result<KeepRegions, ConstraintError> {
        let Some(fig) = figures.get(figure) else {
            return Err(ConstraintError::FigureNumber {
                figure: figure + 1,
                figures: figures.len(),
            });
        };
        let lattice = fig.lattice();
        let l = lattice.lattice();
        let layered = l.dim() == 3;
        let mut lines: Vec<&str> = text
            .split('\n')
            .map(|s| s.strip_suffix('\r').unwrap_or(s).trim_end_matches(' '))
            .collect();
        while lines.last() == Some(&"") {
            lines.pop();
        }
        let mut regions: BTreeMap<char, Vec<Cell>> = BTreeMap::new();
        let (mut y, mut z) = (0i32, 0i32);
        let mut prev_blank = false;
        for (i, line) in lines.iter().enumerate() {
            if layered && line.is_empty() {
                let problem = if i == 0 {
                    Some("blank line before the first z layer")
                } else if prev_blank {
                    Some("more than one blank line between z layers")
                } else {
                    None
                };
                if let Some(problem) = problem {
                    return Err(ConstraintError::Layers {
                        line: i + 1,
                        problem,
                    });
                }
                prev_blank = true;
                z += 1;
                y = 0;
                continue;
            }
            prev_blank = false;
            for (x, ch) in line.chars().enumerate() {
                match ch {
                    '.' | '#' => {}
                    'a'..='z' => {
                        let block = [x as i32, y, z];
                        let cells: Vec<Cell> = l
                            .cells_in_box(block, block)
                            .into_iter()
                            .filter(|c| fig.contains(*c))
                            .collect();
                        if cells.is_empty() {
                            return Err(ConstraintError::OutsideFigure {
                                line: i + 1,
                                column: x + 1,
                                letter: ch,
                                figure: figure + 1,
                            });
                        }
                        regions.entry(ch).or_default().extend(cells);
                    }
                    found => {
                        return Err(ConstraintError::Character {
                            line: i + 1,
                            column: x + 1,
                            found,
                        })
                    }
                }
            }
            y += 1;
        }
        if regions.is_empty() {
            return Err(ConstraintError::NoRegion);
        }
        for cells in regions.values_mut() {
            cells.sort_unstable();
            cells.dedup();
        }
        Ok(KeepRegions { figure, regions })
    }

    /// Regions from cells directly (figure 0-based), e.g. painted in the
    /// studio; the cells must lie in the figure.
    pub fn from_cells(
        figure: usize,
        regions: BTreeMap<char, Vec<Cell>>,
        figures: &[Figure],
    ) -> Result<KeepRegions, ConstraintError> {
        let Some(fig) = figures.get(figure) else {
            return Err(ConstraintError::FigureNumber {
                figure: figure + 1,
                figures: figures.len(),
            });
        };
        let mut out = BTreeMap::new();
        for (letter, mut cells) in regions {
            if !letter.is_ascii_lowercase() {
                return Err(ConstraintError::Letter(letter.to_string()));
            }
            if let Some(c) = cells.iter().find(|c| !fig.contains(**c)) {
                return Err(ConstraintError::CellOutside {
                    letter,
                    cell: fig.lattice().cell_coords(*c),
                    figure: figure + 1,
                });
            }
            cells.sort_unstable();
            cells.dedup();
            if !cells.is_empty() {
                out.insert(letter, cells);
            }
        }
        if out.is_empty() {
            return Err(ConstraintError::NoRegion);
        }
        Ok(KeepRegions {
            figure,
            regions: out,
        })
    }

    /// The figure (0-based).
    pub fn figure(&self) -> usize {
        self.figure
    }

    /// The regions: letter and cells (sorted).
    pub fn regions(&self) -> impl Iterator<Item = (char, &[Cell])> {
        self.regions.iter().map(|(k, v)| (*k, v.as_slice()))
    }
}

/// Every constraint of one solve.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Constraints {
    keep: Vec<KeepRegions>,
    min_piece: Option<usize>,
    max_piece: Option<usize>,
    checkerboard: bool,
    symmetry_weight: f64,
    assemblable: bool,
    min_level: Option<usize>,
}

/// The positions a constraint check may explore to take one figure apart
/// ([`crate::disassembly::Limits::max_states`]): a count of work, not a
/// time, so a check gives the same verdict on every machine; a figure not
/// decided within it counts as not assemblable.
pub const CHECK_STATES: usize = 20_000;

/// One way a dissection breaks its constraints.
#[derive(Debug, Clone, PartialEq, Eq)]
#[non_exhaustive]
pub enum Violation {
    /// A keep region is split between pieces.
    RegionSplit {
        /// The figure (0-based).
        figure: usize,
        /// The letter.
        letter: char,
        /// The pieces it touches.
        pieces: Vec<usize>,
    },
    /// A piece is smaller than `--min-piece`.
    TooSmall {
        /// The piece.
        piece: usize,
        /// Its cells.
        cells: usize,
    },
    /// A piece is larger than `--max-piece`.
    TooLarge {
        /// The piece.
        piece: usize,
        /// Its cells.
        cells: usize,
    },
    /// A piece reaches another figure only by a motion that changes colours.
    Colour {
        /// The piece.
        piece: usize,
        /// The figure (0-based).
        figure: usize,
    },
    /// A 3D figure cannot be taken apart by straight moves (or was not
    /// decided within [`CHECK_STATES`] positions).
    NotAssemblable {
        /// The figure (0-based).
        figure: usize,
    },
    /// A figure comes apart with fewer moves before its first removal than
    /// `--min-level`.
    LevelTooLow {
        /// The figure (0-based).
        figure: usize,
        /// Its level.
        level: usize,
    },
}

impl fmt::Display for Violation {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Violation::RegionSplit {
                figure,
                letter,
                pieces,
            } => write!(
                f,
                "region {letter:?} of figure {} is split between pieces {pieces:?}",
                figure + 1
            ),
            Violation::TooSmall { piece, cells } => {
                write!(f, "piece {piece} has {cells} cells, fewer than --min-piece")
            }
            Violation::TooLarge { piece, cells } => {
                write!(f, "piece {piece} has {cells} cells, more than --max-piece")
            }
            Violation::Colour { piece, figure } => write!(
                f,
                "piece {piece} changes the colour of its cells to fit figure {}",
                figure + 1
            ),
            Violation::NotAssemblable { figure } => write!(
                f,
                "figure {} cannot be taken apart by straight moves",
                figure + 1
            ),
            Violation::LevelTooLow { figure, level } => write!(
                f,
                "figure {} comes apart at level {level}, below --min-level",
                figure + 1
            ),
        }
    }
}

/// The checkerboard colour of a cell: the parity of its block coordinates.
pub fn colour(lattice: LatticeKind, cell: Cell) -> bool {
    let b = lattice.lattice().block(cell);
    (b[0] + b[1] + b[2]).rem_euclid(2) == 1
}

/// Whether the block parity colours every two neighbouring cells of the
/// lattice differently (checked on the cells of a small box).
pub fn has_checkerboard(lattice: LatticeKind) -> bool {
    let l = lattice.lattice();
    l.cells_in_box([0, 0, 0], [2, 2, 2]).into_iter().all(|c| {
        l.neighbors(c)
            .into_iter()
            .all(|n| colour(lattice, n) != colour(lattice, c))
    })
}

impl Constraints {
    /// No constraint.
    pub fn none() -> Constraints {
        Constraints::default()
    }

    /// Whether nothing is constrained (the symmetry weight aside).
    pub fn is_empty(&self) -> bool {
        self.keep.is_empty()
            && self.min_piece.is_none()
            && self.max_piece.is_none()
            && !self.checkerboard
            && !self.assemblable
            && self.min_level.is_none()
    }

    /// The same constraints for the figures in another order: the figure
    /// numbered `f` here is numbered `new_of_old[f]` in the result.
    pub fn renumbered(&self, new_of_old: &[usize]) -> Constraints {
        let mut c = self.clone();
        for k in &mut c.keep {
            k.figure = new_of_old.get(k.figure).copied().unwrap_or(k.figure);
        }
        c
    }

    /// Adds keep regions.
    pub fn with_keep(mut self, keep: KeepRegions) -> Constraints {
        self.keep.push(keep);
        self
    }

    /// Sets the piece-size bounds.
    pub fn with_sizes(mut self, min: Option<usize>, max: Option<usize>) -> Constraints {
        self.min_piece = min;
        self.max_piece = max;
        self
    }

    /// Sets the checkerboard rule.
    pub fn with_checkerboard(mut self, on: bool) -> Constraints {
        self.checkerboard = on;
        self
    }

    /// Sets the assembly rules: every 3D figure comes apart by straight
    /// moves (`assemblable`), with at least `min_level` moves before its
    /// first removal (which implies `assemblable`).
    pub fn with_assembly(mut self, assemblable: bool, min_level: Option<usize>) -> Constraints {
        self.assemblable = assemblable || min_level.is_some();
        self.min_level = min_level;
        self
    }

    /// Whether every 3D figure must come apart by straight moves.
    pub fn assemblable(&self) -> bool {
        self.assemblable
    }

    /// The least level every figure must have.
    pub fn min_level(&self) -> Option<usize> {
        self.min_level
    }

    /// Sets the symmetry weight.
    pub fn with_symmetry_weight(mut self, weight: f64) -> Constraints {
        self.symmetry_weight = weight;
        self
    }

    /// The keep regions.
    pub fn keep(&self) -> &[KeepRegions] {
        &self.keep
    }

    /// The smallest piece allowed.
    pub fn min_piece(&self) -> Option<usize> {
        self.min_piece
    }

    /// The largest piece allowed.
    pub fn max_piece(&self) -> Option<usize> {
        self.max_piece
    }

    /// Whether pieces must keep their cells' colours.
    pub fn checkerboard(&self) -> bool {
        self.checkerboard
    }

    /// The weight of the symmetry term.
    pub fn symmetry_weight(&self) -> f64 {
        self.symmetry_weight
    }

    /// Checks what can be checked without the figures: size bounds of at
    /// least 1, the smallest not above the largest, a symmetry weight that
    /// is a number >= 0.
    pub fn validate_settings(&self) -> Result<(), ConstraintError> {
        if self.min_piece == Some(0) {
            return Err(ConstraintError::ZeroSize("min-piece"));
        }
        if self.max_piece == Some(0) {
            return Err(ConstraintError::ZeroSize("max-piece"));
        }
        if self.min_level == Some(0) {
            return Err(ConstraintError::ZeroSize("min-level"));
        }
        if let (Some(min), Some(max)) = (self.min_piece, self.max_piece) {
            if min > max {
                return Err(ConstraintError::SizeBounds { min, max });
            }
        }
        if !(self.symmetry_weight.is_finite() && self.symmetry_weight >= 0.0) {
            return Err(ConstraintError::SymmetryWeight(
                self.symmetry_weight.to_string(),
            ));
        }
        Ok(())
    }

    /// For every keep region of every figure: the figure, the region's
    /// letter and the pieces (sorted, distinct) that hold its cells.
    fn region_owners<'a>(
        &'a self,
        pieces: &'a [Vec<Vec<Cell>>],
    ) -> impl Iterator<Item = (usize, char, Vec<usize>)> + 'a {
        self.keep.iter().flat_map(move |k| {
            let owner: HashMap<Cell, usize> = pieces
                .get(k.figure)
                .into_iter()
                .flat_map(|fig| {
                    fig.iter()
                        .enumerate()
                        .flat_map(|(i, p)| p.iter().map(move |c| (*c, i)))
                })
                .collect();
            k.regions()
                .map(move |(letter, cells)| {
                    let mut ps: Vec<usize> =
                        cells.iter().filter_map(|c| owner.get(c).copied()).collect();
                    ps.sort_unstable();
                    ps.dedup();
                    (k.figure, letter, ps)
                })
                .collect::<Vec<_>>()
        })
    }

    /// How far a candidate (`pieces[f][i]`, maybe not yet a dissection) is
    /// from honouring the keep regions and the size bounds, cheaply: for
    /// every region, the pieces it touches beyond one; for every piece of
    /// the first figure, the cells above `--max-piece` or below
    /// `--min-piece`. 0 for a candidate that honours them. The level
    /// search adds it to its objective, so it keeps candidates closer to
    /// the constraints (the checkerboard rule needs congruent pieces and is
    /// checked on dissections only).
    pub fn distance(&self, pieces: &[Vec<Vec<Cell>>]) -> usize {
        let mut d: usize = self
            .region_owners(pieces)
            .map(|(_, _, ps)| ps.len().saturating_sub(1))
            .sum();
        if let Some(first) = pieces.first() {
            for p in first.iter().filter(|p| !p.is_empty()) {
                if let Some(m) = self.min_piece {
                    d += m.saturating_sub(p.len());
                }
                if let Some(m) = self.max_piece {
                    d += p.len().saturating_sub(m);
                }
            }
        }
        d
    }

    /// Checks that the constraints make sense for these figures and are not
    /// impossible on their face.
    pub fn validate(&self, figures: &[Figure]) -> Result<(), ConstraintError> {
        let area = figures.first().map_or(0, Figure::len);
        if self.min_piece == Some(0) {
            return Err(ConstraintError::ZeroSize("min-piece"));
        }
        if self.max_piece == Some(0) {
            return Err(ConstraintError::ZeroSize("max-piece"));
        }
        if let (Some(min), Some(max)) = (self.min_piece, self.max_piece) {
            if min > max {
                return Err(ConstraintError::SizeBounds { min, max });
            }
        }
        if let Some(min) = self.min_piece {
            if min > area {
                return Err(ConstraintError::MinTooLarge { min, area });
            }
        }
        if self.min_level == Some(0) {
            return Err(ConstraintError::ZeroSize("min-level"));
        }
        if let (Some(level), Some(f)) = (self.min_level, figures.first()) {
            if level >= 2 && f.lattice().lattice().dim() < 3 {
                return Err(ConstraintError::FlatLevel(level));
            }
            let lattice = f.lattice().lattice();
            if level >= 2 {
                if let Some(i) = figures
                    .iter()
                    .position(|g| crate::disassembly::axis_convex(lattice, g.cells()))
                {
                    return Err(ConstraintError::ConvexLevel {
                        figure: i + 1,
                        level,
                    });
                }
            }
        }
        if !(self.symmetry_weight.is_finite() && self.symmetry_weight >= 0.0) {
            return Err(ConstraintError::SymmetryWeight(
                self.symmetry_weight.to_string(),
            ));
        }
        for k in &self.keep {
            if k.figure >= figures.len() {
                return Err(ConstraintError::FigureNumber {
                    figure: k.figure + 1,
                    figures: figures.len(),
                });
            }
            if let Some(max) = self.max_piece {
                if let Some((letter, cells)) = k.regions().find(|(_, c)| c.len() > max) {
                    return Err(ConstraintError::RegionTooLarge {
                        figure: k.figure + 1,
                        letter,
                        cells: cells.len(),
                        max,
                    });
                }
            }
        }
        if self.checkerboard {
            if let Some(f) = figures.first() {
                let lattice = f.lattice();
                if !has_checkerboard(lattice) {
                    return Err(ConstraintError::NoCheckerboard(lattice));
                }
                let black: Vec<usize> = figures
                    .iter()
                    .map(|f| f.cells().iter().filter(|c| colour(lattice, **c)).count())
                    .collect();
                if black.iter().any(|b| *b != black[0]) {
                    let list: Vec<String> = black
                        .iter()
                        .enumerate()
                        .map(|(i, b)| format!("figure {}: {b}", i + 1))
                        .collect();
                    return Err(ConstraintError::ColourCounts(list.join(", ")));
                }
            }
        }
        Ok(())
    }

    /// Whether a motion keeps the colour of every cell of `cells`.
    pub fn keeps_colours(
        motions: &Motions,
        motion: &dissect_core::transform::Transform,
        cells: &[Cell],
    ) -> bool {
        let lattice = motions.lattice();
        cells.iter().all(|c| {
            motions
                .move_cell(motion, *c)
                .is_some_and(|d| colour(lattice, d) == colour(lattice, *c))
        })
    }

    /// For the assembly rules: every figure that does not come apart
    /// (within [`CHECK_STATES`] positions) or comes apart below
    /// `--min-level`.
    fn check_assembly(&self, motions: &Motions, pieces: &[Vec<Vec<Cell>>]) -> Vec<Violation> {
        if !self.assemblable {
            return Vec::new();
        }
        let lattice = motions.lattice().lattice();
        let limits = Limits {
            max_states: CHECK_STATES,
            ..Limits::default()
        };
        let mut out = Vec::new();
        for (figure, fig) in pieces.iter().enumerate() {
            match disassemble(lattice, fig, limits)
                .ok()
                .and_then(|d| d.level())
            {
                None => out.push(Violation::NotAssemblable { figure }),
                Some(level) if self.min_level.is_some_and(|m| level < m) => {
                    out.push(Violation::LevelTooLow { figure, level })
                }
                Some(_) => {}
            }
        }
        out
    }

    /// Every way the dissection `pieces[f][i]` (a valid dissection: piece
    /// `i` congruent in every figure) breaks these constraints. The
    /// assembly rules are checked last and only when all else holds (they
    /// cost a disassembly search per figure).
    pub fn check(&self, motions: &Motions, pieces: &[Vec<Vec<Cell>>]) -> Vec<Violation> {
        let mut out: Vec<Violation> = self
            .region_owners(pieces)
            .filter(|(_, _, ps)| ps.len() > 1)
            .map(|(figure, letter, pieces)| Violation::RegionSplit {
                figure,
                letter,
                pieces,
            })
            .collect();
        if let Some(first) = pieces.first() {
            for (i, p) in first.iter().enumerate() {
                if self.min_piece.is_some_and(|m| p.len() < m) {
                    out.push(Violation::TooSmall {
                        piece: i,
                        cells: p.len(),
                    });
                }
                if self.max_piece.is_some_and(|m| p.len() > m) {
                    out.push(Violation::TooLarge {
                        piece: i,
                        cells: p.len(),
                    });
                }
            }
            if self.checkerboard {
                for (f, fig) in pieces.iter().enumerate().skip(1) {
                    for (i, p) in first.iter().enumerate() {
                        let Some(q) = fig.get(i) else { continue };
                        let ok = motions
                            .motion_between(p, q, |m| Self::keeps_colours(motions, m, p))
                            .is_some();
                        if !ok {
                            out.push(Violation::Colour {
                                piece: i,
                                figure: f,
                            });
                        }
                    }
                }
            }
        }
        if out.is_empty() {
            out = self.check_assembly(motions, pieces);
        }
        out
    }

    /// The constraints as JSON, for the solution file's `constraints` key
    /// (cells as in the solution format).
    pub fn to_json(&self, lattice: LatticeKind) -> Value {
        let cell = |c: &Cell| -> Value { json!(lattice.cell_coords(*c)) };
        let mut m = serde_json::Map::new();
        if !self.keep.is_empty() {
            let keep: Vec<Value> = self
                .keep
                .iter()
                .map(|k| {
                    let regions: serde_json::Map<String, Value> = k
                        .regions()
                        .map(|(l, cells)| {
                            (
                                l.to_string(),
                                Value::Array(cells.iter().map(cell).collect()),
                            )
                        })
                        .collect();
                    json!({"figure": k.figure + 1, "regions": regions})
                })
                .collect();
            m.insert("keep".into(), Value::Array(keep));
        }
        if let Some(v) = self.min_piece {
            m.insert("min_piece".into(), json!(v));
        }
        if let Some(v) = self.max_piece {
            m.insert("max_piece".into(), json!(v));
        }
        if self.checkerboard {
            m.insert("checkerboard".into(), json!(true));
        }
        if self.symmetry_weight != 0.0 {
            m.insert("symmetry_weight".into(), json!(self.symmetry_weight));
        }
        if self.assemblable {
            m.insert("assemblable".into(), json!(true));
        }
        if let Some(v) = self.min_level {
            m.insert("min_level".into(), json!(v));
        }
        Value::Object(m)
    }
}
