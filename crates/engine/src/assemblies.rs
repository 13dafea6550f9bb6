//! `assemblies`: in how many ways the pieces of a dissection tile each of
//! some figures, under the engine's time limit and stop flag (the
//! operation behind `dissect assemblies` and the studio's puzzle
//! answers). The counter ([`dissect_puzzle::assemblies::count`]) checks
//! the flag and the deadline itself, by its work.

use std::sync::atomic::AtomicBool;

use dissect_core::{Dissection, Figure};
use dissect_puzzle::assemblies::{count, AssemblyError, Count, CountLimits, PieceSet};
use dissect_puzzle::dlx::Progress;
use dissect_puzzle::Motions;

use crate::limits::TimeLimit;

/// News of a count.
#[derive(Debug)]
#[non_exhaustive]
pub enum AssemblyEvent<'a> {
    /// Progress of the count of figure `figure`.
    Progress {
        /// The figure's index.
        figure: usize,
        /// How far its count is.
        progress: Progress,
    },
    /// Figure `figure` is counted.
    Counted {
        /// The figure's index.
        figure: usize,
        /// Its count.
        count: &'a Count,
    },
}

/// Occurs when a count cannot be done: the pieces do not make a piece set
/// (`figure: None`), or a figure is on another lattice or of another area.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{error}")]
pub struct CountError {
    /// The figure the error is about (`None`: the pieces).
    pub figure: Option<usize>,
    /// What is wrong.
    #[source]
    pub error: AssemblyError,
}

/// Counts the ways the pieces of `dissection` (as cut from its first
/// figure; every placement the lattice allows, mirror images as the
/// dissection allows them, identical pieces interchangeable) tile each of
/// `figures`, one [`Count`] per figure, all within `limit` and until `stop`
/// is raised; a count cut short says so ([`Count::complete`]) and its
/// numbers are lower bounds (the figures after it get no time and are
/// counted as cut short too).
pub fn assemblies(
    dissection: &Dissection,
    figures: &[Figure],
    limit: TimeLimit,
    stop: &AtomicBool,
    on_event: &mut dyn FnMut(AssemblyEvent<'_>),
) -> Result<Vec<Count>, CountError> {
    let deadline = limit.deadline();
    let pieces = dissection.pieces().first().cloned().unwrap_or_default();
    let set = PieceSet::new(
        Motions::new(dissection.lattice(), dissection.mirror()),
        &pieces,
    )
    .map_err(|error| CountError {
        figure: None,
        error,
    })?;
    let mut counts = Vec::with_capacity(figures.len());
    for (i, figure) in figures.iter().enumerate() {
        let mut progress = |progress: Progress| {
            on_event(AssemblyEvent::Progress {
                figure: i,
                progress,
            })
        };
        let c = count(
            &set,
            figure,
            CountLimits {
                stop: Some(stop),
                deadline,
                progress: Some(&mut progress),
            },
        )
        .map_err(|error| CountError {
            figure: Some(i),
            error,
        })?;
        on_event(AssemblyEvent::Counted {
            figure: i,
            count: &c,
        });
        counts.push(c);
    }
    Ok(counts)
}
