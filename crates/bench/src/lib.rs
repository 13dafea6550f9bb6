//! The benchmark harness of `dissect`: runs the instances of a manifest (and
//! scaled copies of one) through `dissect_core::solver::solve` over several
//! seeds, verifies every dissection with `dissect_core::verify`, and lays
//! the results out as tables.
//!
//! Architecture invariant: this crate prints nothing; the binary does.

#![forbid(unsafe_code)]

pub mod cpu;
pub mod manifest;
pub mod paper;
pub mod report;
pub mod run;
pub mod scale;
pub mod schedule;

use std::path::PathBuf;
use std::time::Duration;

use dissect_core::solver::Options;
use dissect_core::Figure;

use manifest::Instance;
use report::{InstanceResult, ScaleStep};
use run::{run_mode, SeedRun};

/// Occurs when the harness cannot read or prepare an instance.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum BenchError {
    /// Occurs when a file cannot be read.
    #[error("{}: cannot read: {source}", path.display())]
    Read {
        /// The file.
        path: PathBuf,
        /// Why.
        source: std::io::Error,
    },
    /// Occurs when the manifest is not JSON of the expected shape.
    #[error("{}: line {line}, column {column}: {message}", path.display())]
    ManifestJson {
        /// The manifest file.
        path: PathBuf,
        /// 1-based line.
        line: usize,
        /// 1-based column.
        column: usize,
        /// What serde_json says.
        message: String,
    },
    /// Occurs when a manifest entry is not usable.
    #[error("{}: instance {name:?} {what}", path.display())]
    ManifestEntry {
        /// The manifest file.
        path: PathBuf,
        /// The instance.
        name: String,
        /// What is wrong.
        what: String,
    },
    /// Occurs when an instance named on the command line is not in the manifest.
    #[error("{}: no instance {name:?}; known: {}", path.display(), known.join(", "))]
    UnknownInstance {
        /// The manifest file.
        path: PathBuf,
        /// The name asked for.
        name: String,
        /// The names in the manifest.
        known: Vec<String>,
    },
    /// Occurs when a figure file does not parse.
    #[error("{}: {source}", path.display())]
    Figure {
        /// The figure file.
        path: PathBuf,
        /// The parse error (with line and column).
        source: dissect_core::io::ParseError,
    },
    /// Occurs when a figure's cell count differs from the manifest's `area`.
    #[error("{}: {cells} cells, the manifest says {expected}", path.display())]
    Area {
        /// The figure file.
        path: PathBuf,
        /// Its cells.
        cells: usize,
        /// The manifest's area.
        expected: usize,
    },
    /// Occurs when asked to scale by 0.
    #[error("the scale factor must be at least 1")]
    ScaleFactor,
    /// Occurs when a scaled figure would be absurdly large.
    #[error("scaling {cells} cells by {k} gives too many cells")]
    ScaleTooLarge {
        /// Cells before scaling.
        cells: usize,
        /// The factor.
        k: u32,
    },
    /// Occurs when the scaled cells do not make a figure (a bug).
    #[error("scaled figure is invalid: {0}")]
    Scale(String),
}

/// How every run of a benchmark is made.
#[derive(Clone, Debug, PartialEq)]
pub struct Plan {
    /// The seeds, one run each.
    pub seeds: Vec<u64>,
    /// Solver settings; each run sets its own `seed`.
    pub options: Options,
    /// The time limit of each run on 2D lattices.
    pub time_limit_2d: Option<Duration>,
    /// The time limit of each run on `cubic`.
    pub time_limit_3d: Option<Duration>,
    /// How each run searches (default: `dissect solve` with no flag).
    pub mode: run::Mode,
}

impl Plan {
    /// The time limit of a run on `figures`' lattice.
    pub fn time_limit(&self, figures: &[Figure]) -> Option<Duration> {
        match figures.first().map(|f| f.lattice().lattice().dim()) {
            Some(3) => self.time_limit_3d,
            _ => self.time_limit_2d,
        }
    }

    /// Runs every seed on `figures`, calling `each` after each run.
    pub fn run_seeds(&self, figures: &[Figure], mut each: impl FnMut(&SeedRun)) -> Vec<SeedRun> {
        let limit = self.time_limit(figures);
        self.seeds
            .iter()
            .map(|&seed| {
                let options = Options {
                    seed,
                    ..self.options.clone()
                };
                let run = run_mode(figures, &options, self.mode, limit);
                each(&run);
                run
            })
            .collect()
    }

    /// Runs one instance of a manifest rooted at `root` over every seed.
    pub fn run_instance(
        &self,
        root: &std::path::Path,
        instance: &Instance,
        each: impl FnMut(&SeedRun),
    ) -> Result<InstanceResult, BenchError> {
        let figures = instance.load_figures(root)?;
        let runs = self.run_seeds(&figures, each);
        let paper = paper::paper_result(&instance.name).map(|mut p| {
            if let Some(n) = instance.paper_pieces {
                p.pieces = n;
            }
            p
        });
        Ok(InstanceResult {
            name: instance.name.clone(),
            lattice: instance.lattice(),
            cells: figures[0].len(),
            figures: figures.len(),
            reference: instance.reference,
            paper,
            time_limit: self.time_limit(&figures),
            target: paper::target_seconds(&instance.name),
            runs,
        })
    }

    /// Runs `figures` scaled by each factor of `factors` over every seed;
    /// `each` gets the factor and the run.
    pub fn run_scaling(
        &self,
        figures: &[Figure],
        factors: &[u32],
        mut each: impl FnMut(u32, &SeedRun),
    ) -> Result<Vec<ScaleStep>, BenchError> {
        let mut steps = Vec::new();
        for &k in factors {
            let scaled = figures
                .iter()
                .map(|f| scale::scale(f, k))
                .collect::<Result<Vec<Figure>, BenchError>>()?;
            let runs = self.run_seeds(&scaled, |r| each(k, r));
            steps.push(ScaleStep {
                k,
                cells: scaled[0].len(),
                runs,
            });
        }
        Ok(steps)
    }
}
