//! The puzzle side of a solve: the designer's constraints as the API takes
//! them (keep-whole regions painted on a figure, piece-size bounds, the
//! checkerboard rule, the symmetry weight), read into the engine's
//! [`Constraints`] through the same types the command line uses
//! ([`KeepRegions::from_cells`] for painted cells, [`KeepRegions::parse`]
//! for a regions grid); and the several solutions of a run with their
//! scores, rank and assembly counts per figure, as the result shows them.
//!
//! Every rule on the constraints is the engine's ([`dissect_engine::RunOptions::new`],
//! [`dissect_engine::check`]); this module only turns JSON into those types
//! and their errors into API errors.

use std::collections::BTreeMap;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use dissect_core::lattice::translate_cells;
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_engine::{ConstraintError, Constraints, Count, KeepRegions, Report, Scores, Verified};
use dissect_puzzle::Motions;
use serde::Deserialize;
use serde_json::{json, Value};

use crate::error::ApiError;
use crate::figures;
use crate::limits::Limits;

/// The most solutions one solve may ask for on this server.
pub const MAX_SOLUTIONS: usize = 50;

/// How long the assemblies of one solution in one figure may be counted.
pub const COUNT_TIME: Duration = Duration::from_secs(2);

/// How long all the counts of one solve may take together; past it the
/// remaining counts stop at once (reported as cut short).
pub const COUNT_BUDGET: Duration = Duration::from_secs(12);

/// Keep-whole regions on one figure: `{"figure": 1, "regions": {"a":
/// [[x, y], ...], ...}}` (cells as in the request's figure, grouped by
/// letter: the shape of a solution file's `constraints.keep` entries), or
/// `{"figure": 1, "text": "aa..\n..b.\n"}` (a regions grid, as `--keep
/// N:REGIONS.txt` reads it, in the figure file's coordinates).
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct KeepInput {
    /// The figure, numbered from 1.
    pub figure: usize,
    /// The cells of each region, by letter.
    #[serde(default)]
    pub regions: Option<BTreeMap<String, Vec<Vec<i64>>>>,
    /// Or a regions grid.
    #[serde(default)]
    pub text: Option<String>,
}

/// The constraints part of a solve request.
#[derive(Clone, Debug, Default)]
pub struct ConstraintInput {
    /// Keep-whole regions.
    pub keep: Vec<KeepInput>,
    /// The smallest piece allowed (cells).
    pub min_piece: Option<usize>,
    /// The largest piece allowed (cells).
    pub max_piece: Option<usize>,
    /// Pieces keep the colour of each cell in a checkerboard colouring.
    pub checkerboard: bool,
    /// The weight of the symmetry term.
    pub symmetry_weight: Option<f64>,
    /// Every 3D figure comes apart by straight moves (`--assemblable`).
    pub assemblable: bool,
    /// Every figure needs at least this many moves before its first piece
    /// comes free (`--min-level`; implies `assemblable`).
    pub min_level: Option<usize>,
}

/// A constraint error as an API error: impossible ones (well formed, but
/// they cannot all hold) are 422 `impossible_constraints`, malformed ones
/// 400 `bad_constraints`; settings are named as the API spells them.
pub fn constraint_error(e: &ConstraintError) -> ApiError {
    let message = api_spelling(&e.to_string());
    if e.is_impossible() {
        ApiError::ImpossibleConstraints(format!("the constraints cannot all hold: {message}"))
    } else {
        ApiError::BadConstraints(message)
    }
}

/// `--min-piece` → `min_piece`, wherever a command-line flag appears in a
/// message.
pub fn api_spelling(message: &str) -> String {
    let mut out = String::with_capacity(message.len());
    let mut rest = message;
    while let Some(i) = rest.find("--") {
        out.push_str(&rest[..i]);
        let after = &rest[i + 2..];
        let end = after
            .find(|c: char| !(c.is_ascii_lowercase() || c == '-'))
            .unwrap_or(after.len());
        if end == 0 {
            out.push_str("--");
        } else {
            out.push_str(&after[..end].replace('-', "_"));
        }
        rest = &after[end..];
    }
    out.push_str(rest);
    out
}

/// Reads the constraints of a request. `as_given` are the figures in the
/// request's coordinates (painted cells are in those), `figures` the same
/// moved to the origin (what the engine solves); regions are read against
/// the first, so errors name the cells as the client sent them, and moved
/// with their figure.
pub fn constraints(
    input: &ConstraintInput,
    lattice: LatticeKind,
    as_given: &[Figure],
    figures: &[Figure],
    limits: &Limits,
) -> Result<Constraints, ApiError> {
    let mut c = Constraints::none()
        .with_sizes(input.min_piece, input.max_piece)
        .with_checkerboard(input.checkerboard)
        .with_assembly(input.assemblable, input.min_level)
        .with_symmetry_weight(input.symmetry_weight.unwrap_or(0.0));
    let l = lattice.lattice();
    for (n, k) in input.keep.iter().enumerate() {
        let where_ = format!("keep[{n}]");
        let Some(f) = k.figure.checked_sub(1) else {
            return Err(ApiError::BadConstraints(format!(
                "{where_}: figures are numbered from 1, got 0"
            )));
        };
        let regions = match (&k.regions, &k.text) {
            (Some(regions), None) => {
                let mut by_letter: BTreeMap<char, Vec<Cell>> = BTreeMap::new();
                for (name, cells) in regions {
                    let mut chars = name.chars();
                    let letter = match (chars.next(), chars.next()) {
                        (Some(ch), None) => ch,
                        _ => {
                            return Err(prefix(
                                &where_,
                                constraint_error(&ConstraintError::Letter(name.clone())),
                            ))
                        }
                    };
                    let cells = cells
                        .iter()
                        .map(|raw| figures::cell(raw, lattice, limits))
                        .collect::<Result<Vec<Cell>, String>>()
                        .map_err(|e| ApiError::BadConstraints(format!("{where_}: {e}")))?;
                    by_letter.entry(letter).or_default().extend(cells);
                }
                // Checked where the client painted them, then moved with
                // the figure.
                let given = KeepRegions::from_cells(f, by_letter, as_given)
                    .map_err(|e| prefix(&where_, constraint_error(&e)))?;
                let shift = l.shift_to_origin(as_given[f].cells());
                let moved: BTreeMap<char, Vec<Cell>> = given
                    .regions()
                    .map(|(letter, cells)| (letter, translate_cells(l, cells, shift)))
                    .collect();
                KeepRegions::from_cells(f, moved, figures)
                    .map_err(|e| prefix(&where_, constraint_error(&e)))?
            }
            (None, Some(text)) => KeepRegions::parse(text, f, figures)
                .map_err(|e| prefix(&where_, constraint_error(&e)))?,
            _ => {
                let want = "give either \"regions\" (cells by letter) or \"text\" (a regions grid)";
                return Err(ApiError::BadConstraints(format!("{where_}: {want}")));
            }
        };
        c = c.with_keep(regions);
    }
    Ok(c)
}

fn prefix(where_: &str, e: ApiError) -> ApiError {
    match e {
        ApiError::BadConstraints(m) => ApiError::BadConstraints(format!("{where_}: {m}")),
        ApiError::ImpossibleConstraints(m) => {
            ApiError::ImpossibleConstraints(format!("{where_}: {m}"))
        }
        other => other,
    }
}

/// The assembly counts of a run's solutions (in the order of
/// [`solutions_json`]): every solution in every figure, each count cut at
/// [`COUNT_TIME`], all of them at [`COUNT_BUDGET`] or when `halt` is
/// raised.
pub fn count_assemblies(report: &Report, figures: &[Figure], halt: &AtomicBool) -> Vec<Vec<Count>> {
    let start = Instant::now();
    listed(report)
        .into_iter()
        .map(|(v, _)| {
            let left = COUNT_BUDGET.saturating_sub(start.elapsed());
            v.assemblies(figures, COUNT_TIME.min(left), Some(halt))
                .unwrap_or_default()
        })
        .collect()
}

/// The solutions a result lists: a run that collected them (several asked
/// for, a ranking, constraints) lists [`Report::solutions`], best first;
/// a plain run its one answer.
fn listed(report: &Report) -> Vec<(&Verified, Option<usize>)> {
    if report.solutions.is_empty() {
        report.best.iter().map(|b| (b, None)).collect()
    } else {
        report
            .solutions
            .iter()
            .enumerate()
            .map(|(i, s)| (&s.dissection, Some(i)))
            .collect()
    }
}

/// One figure's count: `{"figure": name, "tilings": N, "up_to_symmetry":
/// M, "figure_symmetries": S, "complete": bool, "unique": bool, "seconds": t}`
/// (numbers are lower bounds when not `complete`; `unique` only when
/// complete with M = 1).
fn count_json(name: &str, c: &Count) -> Value {
    json!({
        "figure": name,
        "tilings": c.tilings,
        "up_to_symmetry": c.up_to_symmetry,
        "figure_symmetries": c.figure_symmetries,
        "complete": c.complete,
        "unique": c.unique(),
        "seconds": (c.elapsed.as_secs_f64() * 1000.0).round() / 1000.0,
    })
}

/// Every solution of a run, best first: `{"position", "pieces", "areas",
/// "area_variance", "scores", "found_by", "rank" ({"by", "position"} when
/// ranked), "assemblies" (one count per figure), "unique" (every figure
/// assembles in one way up to its symmetries), "solution" (the file as
/// JSON), "solution_text"}`.
pub fn solutions_json(report: &Report, counts: &[Vec<Count>]) -> Result<Vec<Value>, String> {
    let ranked = report.ranking.as_ref();
    listed(report)
        .into_iter()
        .enumerate()
        .map(|(n, (v, at))| {
            let d = v.dissection();
            let text = match at {
                Some(i) => report.solution_json_at(i),
                None => report.solution_json(),
            }
            .ok_or("a listed solution has no file")?;
            let file: Value = serde_json::from_str(&text).map_err(|e| e.to_string())?;
            let scores = match at {
                Some(i) => report.solutions[i].scores.clone(),
                None => Scores::of(
                    &Motions::new(d.lattice(), d.mirror()),
                    d.pieces().first().map_or(&[][..], Vec::as_slice),
                ),
            };
            let found_by = match at {
                Some(i) => Some(report.solutions[i].source.name()),
                None => report.source.map(|s| s.name()),
            };
            let assemblies: Vec<Value> = counts
                .get(n)
                .map(|cs| {
                    cs.iter()
                        .zip(d.names())
                        .map(|(c, name)| count_json(name, c))
                        .collect()
                })
                .unwrap_or_default();
            let unique = counts
                .get(n)
                .is_some_and(|cs| !cs.is_empty() && cs.iter().all(Count::unique));
            Ok(json!({
                "position": n + 1,
                "pieces": v.piece_count(),
                "areas": v.areas(),
                "area_variance": v.variance(),
                "scores": scores,
                "found_by": found_by,
                "rank": ranked.map(|r| json!({"by": r.rank.name(), "position": n + 1})),
                "assemblies": assemblies,
                "unique": unique,
                "solution": file,
                "solution_text": text,
            }))
        })
        .collect()
}

/// How a run that collected solutions ranked them: `{"by", "asked",
/// "found", "constraints"}`.
pub fn ranking_json(report: &Report) -> Option<Value> {
    report.ranking.as_ref().map(|r| {
        json!({
            "by": r.rank.name(),
            "asked": r.asked,
            "found": report.solutions.len(),
            "constraints": r.constraints,
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn flags_are_spelt_as_the_api_spells_them() {
        assert_eq!(
            api_spelling("impossible: --min-piece 4 is larger than --max-piece 3"),
            "impossible: min_piece 4 is larger than max_piece 3"
        );
        assert_eq!(api_spelling("a -- b --"), "a -- b --");
        assert_eq!(api_spelling("--checkerboard needs"), "checkerboard needs");
    }
}
