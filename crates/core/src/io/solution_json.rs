//! The solution JSON format `dissection-solution/1`.

use serde::{Deserialize, Serialize};

use crate::dissection::{Dissection, DissectionError};
use crate::lattice::{Cell, LatticeKind};

/// The value of the `format` key.
pub const SOLUTION_FORMAT: &str = "dissection-solution/1";

/// A solution file as it is on disk. Unknown keys are kept in `extra`.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SolutionFile {
    /// Always [`SOLUTION_FORMAT`] when written by us.
    #[serde(default)]
    pub format: Option<String>,
    /// `square`, `tri4` or `cubic`.
    pub lattice: String,
    /// Whether pieces may be flipped; defaults to true in 2D, false in 3D.
    #[serde(default)]
    pub mirror: Option<bool>,
    /// The figures in input order.
    pub figures: Vec<SolutionFigure>,
    /// Other keys (scores, timings, seeds ...).
    #[serde(flatten)]
    pub extra: serde_json::Map<String, serde_json::Value>,
}

/// One figure of a solution file.
#[derive(Clone, Debug, Serialize, Deserialize, PartialEq)]
pub struct SolutionFigure {
    /// The input file's name.
    #[serde(default)]
    pub name: String,
    /// `pieces[i]` is the list of cells of piece `i`.
    pub pieces: Vec<Vec<Vec<i64>>>,
}

/// Occurs when a solution text cannot be read.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum SolutionError {
    /// Occurs when the text is not valid JSON of the solution's shape.
    #[error("line {line}, column {column}: {message}")]
    Json {
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// serde_json's message.
        message: String,
    },
    /// Occurs when the `format` key is missing (FORMAT.md: every solution
    /// file says `"format": "dissection-solution/1"`).
    #[error("no \"format\" key: a solution file says \"format\": \"dissection-solution/1\"")]
    MissingFormat,
    /// Occurs when `format` names another format.
    #[error("format is {0:?}, expected \"dissection-solution/1\"")]
    WrongFormat(String),
    /// Occurs when `lattice` is not a known lattice.
    #[error("unknown lattice {0:?} (expected square, tri4, cubic, tri3 or hex)")]
    UnknownLattice(String),
    /// Occurs when a cell does not have the lattice's form
    /// ([`LatticeKind::cell_from_coords`]).
    #[error(
        "line {line}, column {column}: figure {figure} piece {piece}: bad cell {cell:?} for the {lattice} lattice (a {lattice} cell is {form})",
        form = lattice.cell_form()
    )]
    BadCell {
        /// 1-based line of the cell's `[`.
        line: usize,
        /// 1-based column of the cell's `[`.
        column: usize,
        /// Figure index.
        figure: usize,
        /// Piece index.
        piece: usize,
        /// The cell as written.
        cell: Vec<i64>,
        /// The lattice.
        lattice: LatticeKind,
    },
    /// Occurs when the parts do not make a dissection.
    #[error("{0}")]
    Dissection(#[from] DissectionError),
}

/// Parses a solution text into its typed form.
pub fn parse_solution(text: &str) -> Result<(SolutionFile, Dissection), SolutionError> {
    let file: SolutionFile = serde_json::from_str(text).map_err(|e| SolutionError::Json {
        line: e.line(),
        column: e.column(),
        message: e
            .to_string()
            .split(" at line ")
            .next()
            .unwrap_or_default()
            .to_string(),
    })?;
    match &file.format {
        None => return Err(SolutionError::MissingFormat),
        Some(f) if f != SOLUTION_FORMAT => return Err(SolutionError::WrongFormat(f.clone())),
        Some(_) => {}
    }
    let lattice: LatticeKind = file
        .lattice
        .parse()
        .map_err(|_| SolutionError::UnknownLattice(file.lattice.clone()))?;
    let mirror = file.mirror.unwrap_or(lattice.lattice().supports_mirror());
    let mut pieces = Vec::with_capacity(file.figures.len());
    for (fi, fig) in file.figures.iter().enumerate() {
        let mut fp = Vec::with_capacity(fig.pieces.len());
        for (pi, piece) in fig.pieces.iter().enumerate() {
            let mut cells = Vec::with_capacity(piece.len());
            for cell in piece {
                let Some(c) = lattice.cell_from_coords(cell) else {
                    let (line, column) = bad_cell::locate(text, lattice).unwrap_or((0, 0));
                    return Err(SolutionError::BadCell {
                        line,
                        column,
                        figure: fi,
                        piece: pi,
                        cell: cell.clone(),
                        lattice,
                    });
                };
                cells.push(c);
            }
            fp.push(cells);
        }
        pieces.push(fp);
    }
    let names = file.figures.iter().map(|f| f.name.clone()).collect();
    let d = Dissection::new(lattice, mirror, names, pieces)?;
    Ok((file, d))
}

impl Dissection {
    /// The file form, with `extra` keys added after the contract's keys.
    pub fn to_file(&self, extra: serde_json::Map<String, serde_json::Value>) -> SolutionFile {
        let lattice = self.lattice();
        let cell_json = |c: &Cell| -> Vec<i64> { lattice.cell_coords(*c) };
        SolutionFile {
            format: Some(SOLUTION_FORMAT.to_string()),
            lattice: lattice.name().to_string(),
            mirror: Some(self.mirror()),
            figures: self
                .pieces()
                .iter()
                .enumerate()
                .map(|(f, pieces)| SolutionFigure {
                    name: self.names().get(f).cloned().unwrap_or_default(),
                    pieces: pieces
                        .iter()
                        .map(|p| p.iter().map(cell_json).collect())
                        .collect(),
                })
                .collect(),
            extra,
        }
    }
}

impl SolutionFile {
    /// JSON with one piece per line: readable, diffable and still compact.
    pub fn to_json(&self) -> String {
        let j = |v: &dyn erased::Json| v.json();
        let mut out = String::from("{\n");
        if let Some(f) = &self.format {
            out += &format!("  \"format\": {},\n", j(f));
        }
        out += &format!("  \"lattice\": {},\n", j(&self.lattice));
        if let Some(m) = self.mirror {
            out += &format!("  \"mirror\": {m},\n");
        }
        out += "  \"figures\": [\n";
        for (fi, fig) in self.figures.iter().enumerate() {
            out += &format!("    {{\"name\": {}, \"pieces\": [\n", j(&fig.name));
            for (pi, piece) in fig.pieces.iter().enumerate() {
                let sep = if pi + 1 < fig.pieces.len() { "," } else { "" };
                out += &format!("      {}{sep}\n", j(piece));
            }
            let sep = if fi + 1 < self.figures.len() { "," } else { "" };
            out += &format!("    ]}}{sep}\n");
        }
        out += "  ]";
        for (k, v) in &self.extra {
            out += &format!(",\n  {}: {}", j(k), j(v));
        }
        out += "\n}\n";
        out
    }
}

mod erased {
    /// Anything serde can write as one line of JSON.
    pub(super) trait Json {
        fn json(&self) -> String;
    }
    impl<T: serde::Serialize> Json for T {
        fn json(&self) -> String {
            serde_json::to_string(self).expect("serialisable")
        }
    }
}

/// Finds where the first bad cell is in a solution text: a second reading of
/// `figures[*].pieces[*][*]` that fails at the first cell
/// [`LatticeKind::cell_from_coords`] refuses, so that serde_json reports its
/// line and column.
mod bad_cell {
    use std::cell::Cell;

    use serde::de::{Deserialize, Deserializer, Error};

    use crate::lattice::LatticeKind;

    thread_local! {
        /// The lattice whose cells are expected (serde has no other way to
        /// pass it to a derived reader).
        static LATTICE: Cell<LatticeKind> = const { Cell::new(LatticeKind::Square) };
    }

    #[derive(serde::Deserialize)]
    struct Document {
        #[allow(dead_code)] // read only for its checks
        figures: Vec<Figure>,
    }

    #[derive(serde::Deserialize)]
    struct Figure {
        #[allow(dead_code)] // read only for its checks
        pieces: Vec<Vec<CheckedCell>>,
    }

    struct CheckedCell;

    impl<'de> Deserialize<'de> for CheckedCell {
        fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
            let v = Vec::<i64>::deserialize(d)?;
            match LATTICE.with(Cell::get).cell_from_coords(&v) {
                Some(_) => Ok(CheckedCell),
                None => Err(D::Error::custom("bad cell")),
            }
        }
    }

    /// The 1-based line and column of the `[` that opens the first bad cell.
    pub(super) fn locate(text: &str, lattice: LatticeKind) -> Option<(usize, usize)> {
        LATTICE.with(|l| l.set(lattice));
        let e = serde_json::from_str::<Document>(text).err()?;
        if e.line() == 0 {
            return None;
        }
        // serde_json stops just after the cell's `]`; a cell holds only
        // numbers, so its `[` is the last one before that.
        let line_start: usize = text
            .split_inclusive('\n')
            .take(e.line() - 1)
            .map(str::len)
            .sum();
        let end = text[line_start..]
            .char_indices()
            .nth(e.column().saturating_sub(1))
            .map_or(text.len(), |(i, _)| line_start + i);
        let open = text[..end].rfind('[')?;
        let line = text[..open].matches('\n').count() + 1;
        let from = text[..open].rfind('\n').map_or(0, |i| i + 1);
        Some((line, text[from..open].chars().count() + 1))
    }
}
