//! `enumerate`: every dissection with K pieces (the minimum unless K is
//! given), counted and verified, grouped into classes up to the first
//! figure's symmetries, filtered (`unique`) and ranked. The time limit and
//! the stop flag end it with what was found, marked incomplete.

use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use dissect_core::Figure;
use dissect_exact::{Bound, EnumerateObserver, EnumerateOptions, Limit};
use dissect_puzzle::{Motions, Rank, Scores};

use crate::{EngineError, TimeLimit, Verified};

/// What a front end asks of [`enumerate`].
#[derive(Clone, Debug, Default, PartialEq)]
pub struct EnumerateConfig {
    /// Whether 2D pieces may be turned over; also whether the first
    /// figure's reflections count as its symmetries.
    pub mirror: bool,
    /// Count the dissections with exactly this many pieces (`None`: the
    /// minimum, proved first).
    pub pieces: Option<usize>,
    /// How long before the enumeration stops with what it found.
    pub time_limit: TimeLimit,
    /// The order of the classes (`None`: the order they were found).
    pub rank: Option<Rank>,
    /// Keep only the dissections whose pieces tile every figure in a
    /// single way up to that figure's symmetries.
    pub unique: bool,
}

/// One class of dissections up to the first figure's symmetries.
#[derive(Clone, Debug, PartialEq)]
pub struct EnumeratedClass {
    /// Its first dissection found, verified.
    pub dissection: Verified,
    /// How many dissections it holds.
    pub size: usize,
    /// The representative's scores (with assemblies when counted).
    pub scores: Scores,
}

/// What [`enumerate`] found.
#[derive(Clone, Debug, PartialEq)]
pub struct EnumerationReport {
    /// K, the piece count counted (the lower bound proved when stopped
    /// before the minimum was known).
    pub pieces: usize,
    /// Whether K is the proved minimum piece count.
    pub minimum: bool,
    /// The lower bound proved.
    pub lower_bound: Bound,
    /// Every dissection kept, verified, in the order found.
    pub dissections: Vec<Verified>,
    /// The classes kept, ranked (or in the order found).
    pub classes: Vec<EnumeratedClass>,
    /// Whether no dissection with K pieces (that `unique` would keep) is
    /// missing.
    pub complete: bool,
    /// With `unique`: the dissections and classes before the filter.
    pub before_unique: Option<(usize, usize)>,
    /// The limit that ended the SAT search, if one did.
    pub limit: Option<Limit>,
    /// Seconds spent.
    pub seconds: f64,
}

/// Counts every dissection of `figures` with K pieces ([`EnumerateConfig`]),
/// each verified into a [`Verified`] named by `names`; `observer` sees the
/// count so far. The time limit and `stop` end it early with what was
/// found (`complete` false).
pub fn enumerate(
    figures: &[Figure],
    names: &[String],
    config: &EnumerateConfig,
    stop: &AtomicBool,
    observer: &dyn EnumerateObserver,
) -> Result<EnumerationReport, EngineError> {
    let start = Instant::now();
    let deadline = config.time_limit.deadline_from(start);
    dissect_core::solver::check_figures(figures)?;
    let found = dissect_exact::enumerate(
        figures,
        &EnumerateOptions {
            mirror: config.mirror,
            pieces: config.pieces,
            deadline,
            ..EnumerateOptions::default()
        },
        stop,
        observer,
    )?;
    let lattice = figures[0].lattice();
    let motions = Motions::new(lattice, config.mirror);
    let mirror = motions.mirror();
    let verified = |pieces: Vec<Vec<Vec<dissect_core::Cell>>>| {
        Verified::new(lattice, mirror, names.to_vec(), figures, pieces)
            .map_err(|e| EngineError::Unverified("enumerated", e))
    };
    let dissections = found
        .dissections
        .into_iter()
        .map(verified)
        .collect::<Result<Vec<Verified>, EngineError>>()?;
    let mut classes: Vec<Option<EnumeratedClass>> = vec![None; found.classes];
    for (d, &c) in dissections.iter().zip(&found.class_of) {
        match &mut classes[c] {
            Some(class) => class.size += 1,
            slot @ None => {
                *slot = Some(EnumeratedClass {
                    scores: Scores::of(&motions, &d.pieces()[0]),
                    dissection: d.clone(),
                    size: 1,
                })
            }
        }
    }
    let mut classes: Vec<EnumeratedClass> = classes.into_iter().flatten().collect();
    let mut keep_class: Vec<bool> = vec![true; classes.len()];
    let mut complete = found.complete;
    let needs_counts = config.unique || config.rank.is_some_and(Rank::needs_assemblies);
    if needs_counts {
        for (class, keep) in classes.iter_mut().zip(&mut keep_class) {
            let time = deadline.map_or(Duration::from_secs(u32::MAX as u64), |d| {
                d.saturating_duration_since(Instant::now())
            });
            let counts = class
                .dissection
                .assemblies(figures, time, Some(stop))
                .map_err(|e| EngineError::Unverified("enumerated", e.to_string()))?;
            let counted = counts.iter().all(|c| c.complete);
            class.scores.assemblies =
                counted.then(|| counts.iter().map(|c| c.up_to_symmetry).sum());
            if config.unique {
                // A count cut short decides nothing: the class is left out
                // and the list is no longer complete.
                complete &= counted;
                *keep = counted && counts.iter().all(|c| c.unique());
            }
        }
    }
    let before_unique = config.unique.then_some((dissections.len(), classes.len()));
    // Classes are numbered in the order of their first dissection.
    let dissections: Vec<Verified> = dissections
        .into_iter()
        .zip(&found.class_of)
        .filter(|(_, c)| keep_class[**c])
        .map(|(d, _)| d)
        .collect();
    let mut classes: Vec<EnumeratedClass> = classes
        .into_iter()
        .zip(keep_class)
        .filter_map(|(c, keep)| keep.then_some(c))
        .collect();
    if let Some(rank) = config.rank {
        let mut items: Vec<(Scores, EnumeratedClass)> =
            classes.into_iter().map(|c| (c.scores.clone(), c)).collect();
        rank.sort(&mut items);
        classes = items.into_iter().map(|(_, c)| c).collect();
    }
    Ok(EnumerationReport {
        pieces: found.pieces,
        minimum: found.minimum,
        lower_bound: found.lower_bound,
        dissections,
        classes,
        complete,
        before_unique,
        limit: found.limit,
        seconds: start.elapsed().as_secs_f64(),
    })
}
