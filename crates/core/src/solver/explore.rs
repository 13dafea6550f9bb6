//! Explorations as self-contained tasks, so that a search's explorations
//! can run elsewhere (other processes or machines: `dissect.ray`).
//!
//! An exploration is a pure function of the problem, the options, its
//! `(round, level, index)` and the kept candidates of the level below (its
//! possible parents): [`Explorer::explore`]. The search hands each batch of
//! explorations to an [`Executor`]; the default one runs them on the
//! solver's thread pool, and any other gives the same answer as long as it
//! returns, in index order, what [`Explorer::explore`] returns.
//! [`Exploration`]s travel as bytes ([`Exploration::to_bytes`]).

use std::ops::Range;
use std::sync::atomic::AtomicBool;

use crate::figure::Figure;
use crate::solver::candidate::{Candidate, Problem, Score};
use crate::solver::{levels, problem_of, stream, Options, SolveError, DESCENT};

/// One exploration's result (or a kept candidate handed to the next level
/// as a parent): a labelling of every figure and its score.
#[derive(Clone, Debug, PartialEq)]
pub struct Exploration {
    pub(crate) candidate: Candidate,
    pub(crate) score: Score,
}

/// Occurs when bytes or explorations do not fit the problem.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ExplorationError {
    /// Occurs when bytes are not an exploration written by
    /// [`Exploration::to_bytes`] (truncated, wrong header, trailing bytes).
    #[error("not an exploration: {0}")]
    Bytes(String),
    /// Occurs when an exploration's labelling does not fit the problem
    /// (another problem's, or corrupted): figure count, cell counts, labels.
    #[error("an exploration does not fit this problem: {0}")]
    Mismatch(String),
    /// Occurs when an executor returns the wrong number of explorations.
    #[error("the executor returned {got} explorations for a batch of {want}")]
    Count {
        /// Returned.
        got: usize,
        /// Asked for.
        want: usize,
    },
    /// Occurs when an executor fails (its message).
    #[error("the executor failed: {0}")]
    Executor(String),
}

const MAGIC: &[u8; 4] = b"DXP1";

impl Exploration {
    /// The matching cost `E_M` (0 with connected pieces: a dissection).
    pub fn mismatch(&self) -> u64 {
        self.score.mismatch
    }

    /// Whether it is a valid dissection.
    pub fn is_valid(&self) -> bool {
        self.score.valid
    }

    /// Its number of pieces.
    pub fn pieces(&self) -> usize {
        self.candidate.k
    }

    /// A compact little-endian encoding (header, labels, score).
    pub fn to_bytes(&self) -> Vec<u8> {
        let c = &self.candidate;
        let cells: usize = c.labels.iter().map(|l| l.len()).sum();
        let mut out = Vec::with_capacity(40 + 4 * c.labels.len() + 2 * cells);
        out.extend_from_slice(MAGIC);
        out.extend_from_slice(&(c.k as u32).to_le_bytes());
        out.extend_from_slice(&(c.labels.len() as u32).to_le_bytes());
        for l in &c.labels {
            out.extend_from_slice(&(l.len() as u32).to_le_bytes());
            for v in l {
                out.extend_from_slice(&v.to_le_bytes());
            }
        }
        let s = &self.score;
        out.extend_from_slice(&s.value.to_le_bytes());
        out.extend_from_slice(&s.mismatch.to_le_bytes());
        out.extend_from_slice(&s.split.to_le_bytes());
        out.push(u8::from(s.valid));
        out.extend_from_slice(&s.variance.to_le_bytes());
        out
    }

    /// Reads [`Exploration::to_bytes`]'s encoding. Whether it fits a
    /// problem is checked where it is used.
    pub fn from_bytes(bytes: &[u8]) -> Result<Exploration, ExplorationError> {
        let mut r = Reader { bytes, at: 0 };
        if r.take(4)? != MAGIC {
            return Err(ExplorationError::Bytes("wrong header".into()));
        }
        let k = r.u32()? as usize;
        let figures = r.u32()? as usize;
        let mut labels = Vec::with_capacity(figures.min(64));
        for _ in 0..figures {
            let n = r.u32()? as usize;
            let raw = r.take(n.checked_mul(2).ok_or_else(|| r.short())?)?;
            labels.push(
                raw.chunks_exact(2)
                    .map(|b| u16::from_le_bytes([b[0], b[1]]))
                    .collect(),
            );
        }
        let value = f64::from_le_bytes(r.array()?);
        let mismatch = u64::from_le_bytes(r.array()?);
        let split = u32::from_le_bytes(r.array()?);
        let valid = match r.take(1)?[0] {
            0 => false,
            1 => true,
            v => return Err(ExplorationError::Bytes(format!("bad flag {v}"))),
        };
        let variance = f64::from_le_bytes(r.array()?);
        if r.at != bytes.len() {
            return Err(ExplorationError::Bytes(format!(
                "{} trailing bytes",
                bytes.len() - r.at
            )));
        }
        Ok(Exploration {
            candidate: Candidate { labels, k },
            score: Score {
                value,
                mismatch,
                split,
                valid,
                variance,
            },
        })
    }

    /// Checks the labelling's validity invariant against `problem`.
    pub(crate) fn check(&self, problem: &Problem) -> Result<(), ExplorationError> {
        let c = &self.candidate;
        let bad = |m: String| Err(ExplorationError::Mismatch(m));
        if c.labels.len() != problem.shapes.len() {
            return bad(format!(
                "{} figures, the problem has {}",
                c.labels.len(),
                problem.shapes.len()
            ));
        }
        if c.k == 0 || c.k > u16::MAX as usize {
            return bad(format!("{} pieces", c.k));
        }
        for (f, (l, s)) in c.labels.iter().zip(&problem.shapes).enumerate() {
            if l.len() != s.len() {
                return bad(format!(
                    "figure {f} has {} cells, the problem's has {}",
                    l.len(),
                    s.len()
                ));
            }
            if let Some(v) = l.iter().find(|v| **v as usize >= c.k) {
                return bad(format!("label {v} in figure {f} with {} pieces", c.k));
            }
        }
        Ok(())
    }
}

struct Reader<'a> {
    bytes: &'a [u8],
    at: usize,
}

impl<'a> Reader<'a> {
    fn short(&self) -> ExplorationError {
        ExplorationError::Bytes(format!("truncated at byte {}", self.at))
    }

    fn take(&mut self, n: usize) -> Result<&'a [u8], ExplorationError> {
        let end = self
            .at
            .checked_add(n)
            .filter(|e| *e <= self.bytes.len())
            .ok_or_else(|| self.short())?;
        let s = &self.bytes[self.at..end];
        self.at = end;
        Ok(s)
    }

    fn u32(&mut self) -> Result<u32, ExplorationError> {
        Ok(u32::from_le_bytes(self.array()?))
    }

    fn array<const N: usize>(&mut self) -> Result<[u8; N], ExplorationError> {
        let s = self.take(N)?;
        let mut a = [0u8; N];
        a.copy_from_slice(s);
        Ok(a)
    }
}

/// A batch of explorations the search asks an [`Executor`] for.
#[derive(Clone, Debug)]
pub struct Batch<'a> {
    /// The round of the schedule (0: the paper's).
    pub round: usize,
    /// The level (`level + 1` pieces).
    pub level: usize,
    /// Whether these are steps of the descent (one piece fewer than the
    /// only parent, a dissection) rather than the ladder's explorations.
    pub descent: bool,
    /// The explorations' indices.
    pub indices: Range<usize>,
    /// The kept candidates of the level below (empty at level 1).
    pub parents: &'a [Exploration],
}

/// Runs batches of explorations somewhere.
pub trait Executor: Sync {
    /// The explorations `batch.indices`, in index order: for the search to
    /// give the same answer as a local one, each must be what
    /// [`Explorer::explore`] returns for it. An `Err` ends the search with
    /// [`SolveError::Executor`].
    fn run(&self, batch: &Batch<'_>) -> Result<Vec<Exploration>, String>;
}

/// Runs single explorations of one problem (what an executor's workers
/// call).
pub struct Explorer {
    problem: Problem,
    options: Options,
}

impl Explorer {
    /// The explorer of `figures` under `options` (as given to the search).
    pub fn new(figures: &[Figure], options: &Options) -> Result<Explorer, SolveError> {
        Ok(Explorer {
            problem: problem_of(figures, options)?,
            options: options.clone(),
        })
    }

    /// Exploration `index` of `level` in `round` from `parents` (of the
    /// descent when `descent`, see [`Batch::descent`]). Raising `stop` cuts
    /// its refinement short (the result then differs from an unstopped one).
    pub fn explore(
        &self,
        round: usize,
        level: usize,
        descent: bool,
        index: usize,
        parents: &[Exploration],
        stop: &AtomicBool,
    ) -> Result<Exploration, ExplorationError> {
        for p in parents {
            p.check(&self.problem)?;
        }
        if descent && parents.len() != 1 {
            return Err(ExplorationError::Mismatch(format!(
                "a descent step has one parent, got {}",
                parents.len()
            )));
        }
        let (candidate, score) = explore_one(
            &self.problem,
            &self.options,
            round,
            level,
            index,
            descent,
            parents.len(),
            |i| &parents[i].candidate,
            stop,
        );
        Ok(Exploration { candidate, score })
    }
}

/// Exploration `index` of `level` in `round`: level 1 from scratch, above
/// it grown from one of `parent_count` parents drawn from its stream; in
/// the descent, the only parent (a dissection) with two pieces merged. The
/// one definition every executor's result must equal.
#[allow(clippy::too_many_arguments)] // one exploration's whole identity
pub(crate) fn explore_one<'p>(
    problem: &Problem,
    options: &Options,
    round: usize,
    level: usize,
    index: usize,
    descent: bool,
    parent_count: usize,
    parent: impl Fn(usize) -> &'p Candidate,
    stop: &AtomicBool,
) -> (Candidate, Score) {
    if descent {
        let mut rng = stream(options.seed, round, DESCENT + level, index);
        return levels::merge(problem, parent(0), level, options, &mut rng, stop);
    }
    let mut rng = stream(options.seed, round, level, index);
    if level == 1 || parent_count == 0 {
        levels::level_one(problem, options, &mut rng, stop)
    } else {
        use rand::RngExt;
        let p = parent(rng.random_range(0..parent_count));
        levels::grow(problem, p, level, options, &mut rng, stop)
    }
}
