//! Several solutions: dissections gathered from several runs, kept when they
//! honour the constraints, have the fewest pieces seen and differ from every
//! one kept before (canonical form, see [`crate::scores::canonical`]), then
//! ranked.

use std::collections::HashSet;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use dissect_core::lattice::Point;
use dissect_core::{Cell, Figure};

use crate::assemblies::{count, CountLimits, PieceSet};
use crate::constraints::{Constraints, Violation, CHECK_STATES};
use crate::disassembly::{disassemble, Limits};
use crate::geometry::Motions;
use crate::scores::{canonical, Rank, Scores};

/// One dissection kept, with its scores.
#[derive(Clone, Debug, PartialEq)]
pub struct Entry {
    /// `pieces[f][i]`: cells of piece `i` in figure `f`.
    pub pieces: Vec<Vec<Vec<Cell>>>,
    /// Its scores.
    pub scores: Scores,
}

/// What [`Collection::add`] did with a dissection.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Added {
    /// Kept: a new puzzle with the fewest pieces so far.
    New,
    /// Kept, and it has fewer pieces than every earlier one (those were dropped).
    Fewer,
    /// The same pieces as one kept before.
    Duplicate,
    /// More pieces than the fewest kept.
    MorePieces,
    /// It breaks the constraints.
    Broken(Vec<Violation>),
}

/// Distinct dissections with the fewest pieces, honouring constraints.
#[derive(Clone, Debug)]
pub struct Collection {
    motions: Motions,
    constraints: Constraints,
    entries: Vec<Entry>,
    seen: HashSet<Vec<Vec<Point>>>,
}

impl Collection {
    /// An empty collection.
    pub fn new(motions: Motions, constraints: Constraints) -> Collection {
        Collection {
            motions,
            constraints,
            entries: Vec::new(),
            seen: HashSet::new(),
        }
    }

    /// Offers a valid dissection (checked by the verifier beforehand).
    pub fn add(&mut self, pieces: Vec<Vec<Vec<Cell>>>) -> Added {
        let broken = self.constraints.check(&self.motions, &pieces);
        if !broken.is_empty() {
            return Added::Broken(broken);
        }
        let first = pieces.first().cloned().unwrap_or_default();
        let n = first.len();
        let mut fewer = false;
        match self.fewest() {
            Some(k) if n > k => return Added::MorePieces,
            Some(k) if n < k => {
                self.entries.clear();
                self.seen.clear();
                fewer = true;
            }
            _ => {}
        }
        if !self.seen.insert(canonical(&self.motions, &first)) {
            return Added::Duplicate;
        }
        let scores = Scores::weighted(&self.motions, &first, self.constraints.symmetry_weight());
        self.entries.push(Entry { pieces, scores });
        if fewer || self.entries.len() == 1 {
            Added::Fewer
        } else {
            Added::New
        }
    }

    /// The fewest pieces kept.
    pub fn fewest(&self) -> Option<usize> {
        self.entries.first().map(|e| e.scores.pieces)
    }

    /// The number of dissections kept.
    pub fn len(&self) -> usize {
        self.entries.len()
    }

    /// Whether nothing is kept.
    pub fn is_empty(&self) -> bool {
        self.entries.is_empty()
    }

    /// The dissections kept, in the order they came.
    pub fn entries(&self) -> &[Entry] {
        &self.entries
    }

    /// The best `limit` by `rank`, best first. With [`Rank::Unique`] the
    /// assemblies are counted first, in every figure (each count within
    /// `count_time`; a count cut short ranks last, and once its stop is
    /// raised or its deadline has passed no more are counted).
    pub fn ranked(
        mut self,
        rank: Rank,
        limit: usize,
        figures: &[Figure],
        count_time: CountTime<'_>,
    ) -> Vec<Entry> {
        if rank.needs_assemblies() {
            for e in &mut self.entries {
                e.scores.assemblies = assemblies(&self.motions, &e.pieces, figures, count_time);
            }
        }
        if rank.needs_levels() || self.constraints.assemblable() {
            for e in &mut self.entries {
                e.scores.levels = Some(levels(&self.motions, &e.pieces));
            }
        }
        let mut items: Vec<(Scores, Entry)> = self
            .entries
            .into_iter()
            .map(|e| (e.scores.clone(), e))
            .collect();
        rank.sort(&mut items);
        items.into_iter().take(limit).map(|(_, e)| e).collect()
    }
}

/// Each figure's disassembly level (`None`: it does not come apart within
/// [`CHECK_STATES`] positions).
pub fn levels(motions: &Motions, pieces: &[Vec<Vec<Cell>>]) -> Vec<Option<usize>> {
    let limits = Limits {
        max_states: CHECK_STATES,
        ..Limits::default()
    };
    let lattice = motions.lattice().lattice();
    pieces
        .iter()
        .map(|fig| {
            disassemble(lattice, fig, limits)
                .ok()
                .and_then(|d| d.level())
        })
        .collect()
}

/// How long the counts of assemblies may take.
#[derive(Clone, Copy, Debug, Default)]
pub struct CountTime<'a> {
    /// Each count (one figure of one dissection).
    pub each: Duration,
    /// No count goes past this instant.
    pub until: Option<Instant>,
    /// Raised to stop every count at once.
    pub stop: Option<&'a AtomicBool>,
}

impl CountTime<'_> {
    /// The deadline of a count that starts now.
    fn deadline(&self) -> Option<Instant> {
        let each = Instant::now().checked_add(self.each);
        match (each, self.until) {
            (Some(a), Some(b)) => Some(a.min(b)),
            (a, b) => a.or(b),
        }
    }

    /// Whether the counts are to stop.
    fn over(&self) -> bool {
        self.stop.is_some_and(|s| s.load(Ordering::SeqCst))
            || self.until.is_some_and(|u| Instant::now() >= u)
    }
}

/// The tilings up to symmetry of every figure by a dissection's pieces,
/// summed; `None` when a count did not finish in its time (or was stopped).
pub fn assemblies(
    motions: &Motions,
    pieces: &[Vec<Vec<Cell>>],
    figures: &[Figure],
    time: CountTime<'_>,
) -> Option<u64> {
    if time.over() {
        return None;
    }
    let set = PieceSet::new(motions.clone(), pieces.first()?).ok()?;
    let mut total = 0;
    for f in figures {
        let c = count(
            &set,
            f,
            CountLimits {
                deadline: time.deadline(),
                stop: time.stop,
                ..CountLimits::default()
            },
        )
        .ok()?;
        if !c.complete {
            return None;
        }
        total += c.up_to_symmetry;
    }
    Some(total)
}
