//! The solution JSON format `dissection-solution/1`.

use serde::{Deserialize, Serialize};

use crate::lattice::{Cell, LatticeKind};

/// The largest coordinate a solution cell may have (so that lattice points,
/// up to 6 times larger, stay far from overflow).
pub const MAX_COORDINATE: i64 = 1 << 24;

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

/// A dissection in typed form: `pieces[f][i]` are the cells of piece `i` in
/// figure `f`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Dissection {
    /// The lattice.
    pub lattice: LatticeKind,
    /// Whether flips are allowed.
    pub mirror: bool,
    /// The figures' names.
    pub names: Vec<String>,
    /// `pieces[f][i]`: cells of piece `i` in figure `f`.
    pub pieces: Vec<Vec<Vec<Cell>>>,
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
    /// Occurs when a cell does not have the lattice's form.
    #[error("figure {figure} piece {piece}: bad cell {cell:?} for the {lattice} lattice")]
    BadCell {
        /// Figure index.
        figure: usize,
        /// Piece index.
        piece: usize,
        /// The cell as written.
        cell: Vec<i64>,
        /// The lattice.
        lattice: LatticeKind,
    },
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
    let l = lattice.lattice();
    let mirror = file.mirror.unwrap_or(l.supports_mirror()) && l.supports_mirror();
    let mut pieces = Vec::with_capacity(file.figures.len());
    for (fi, fig) in file.figures.iter().enumerate() {
        let mut fp = Vec::with_capacity(fig.pieces.len());
        for (pi, piece) in fig.pieces.iter().enumerate() {
            let mut cells = Vec::with_capacity(piece.len());
            for cell in piece {
                let bad = || SolutionError::BadCell {
                    figure: fi,
                    piece: pi,
                    cell: cell.clone(),
                    lattice,
                };
                let want = lattice.cell_arity();
                if cell.len() != want || cell.iter().any(|v| v.abs() > MAX_COORDINATE) {
                    return Err(bad());
                }
                let c = [
                    cell[0] as i32,
                    cell[1] as i32,
                    if want == 3 { cell[2] as i32 } else { 0 },
                ];
                if !l.is_cell(c) {
                    return Err(bad());
                }
                cells.push(c);
            }
            fp.push(cells);
        }
        pieces.push(fp);
    }
    let names = file.figures.iter().map(|f| f.name.clone()).collect();
    Ok((
        file,
        Dissection {
            lattice,
            mirror,
            names,
            pieces,
        },
    ))
}

impl Dissection {
    /// The file form, with `extra` keys added after the contract's keys.
    pub fn to_file(&self, extra: serde_json::Map<String, serde_json::Value>) -> SolutionFile {
        let cell_json = |c: &Cell| -> Vec<i64> {
            if self.lattice.cell_arity() == 2 {
                vec![c[0] as i64, c[1] as i64]
            } else {
                c.iter().map(|v| *v as i64).collect()
            }
        };
        SolutionFile {
            format: Some(SOLUTION_FORMAT.to_string()),
            lattice: self.lattice.name().to_string(),
            mirror: Some(self.mirror),
            figures: self
                .pieces
                .iter()
                .enumerate()
                .map(|(f, pieces)| SolutionFigure {
                    name: self.names.get(f).cloned().unwrap_or_default(),
                    pieces: pieces
                        .iter()
                        .map(|p| p.iter().map(cell_json).collect())
                        .collect(),
                })
                .collect(),
            extra,
        }
    }

    /// The number of pieces (of the first figure).
    pub fn piece_count(&self) -> usize {
        self.pieces.first().map_or(0, |p| p.len())
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
