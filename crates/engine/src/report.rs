//! What a run produced.

use dissect_puzzle::{Rank, Scores};
use serde_json::{json, Map, Value};

use crate::verified::Verified;

/// Which search found a dissection.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum Source {
    /// The constructive dissection.
    Greedy,
    /// The level search.
    Search,
    /// A near miss of the level search, finished by the exact repair.
    Repair,
    /// The SAT search.
    Sat,
    /// The level search on the figures at half resolution, lifted.
    Coarse,
    /// One large common piece, the rest dissected exactly sector by sector.
    Sectors,
    /// Touching pieces of the best dissection cut again exactly, fewer.
    Regroup,
    /// The tail of the best dissection cut again by a randomized greedy.
    Rebuild,
    /// Figures of a few boxes cut into boxes by guillotine cuts.
    Boxes,
    /// The interlocking search (`--min-level`, `--assemblable`): touching
    /// pieces of a refused dissection cut again until it holds together.
    Interlock,
}

impl Source {
    /// `greedy`, `search`, `repair`, `sat`, `coarse`, `sectors`,
    /// `regroup`, `rebuild` or `interlock`.
    pub fn name(self) -> &'static str {
        match self {
            Source::Greedy => "greedy",
            Source::Search => "search",
            Source::Repair => "repair",
            Source::Sat => "sat",
            Source::Coarse => "coarse",
            Source::Sectors => "sectors",
            Source::Regroup => "regroup",
            Source::Rebuild => "rebuild",
            Source::Boxes => "boxes",
            Source::Interlock => "interlock",
        }
    }
}

/// A dissection with fewer pieces than any before it in the run.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Improvement {
    /// Its piece count.
    pub pieces: usize,
    /// Seconds from the start of the run.
    pub seconds: f64,
    /// Who found it.
    pub source: Source,
}

/// A proved lower bound on the piece count.
#[derive(Clone, Debug, PartialEq)]
pub struct LowerBound {
    /// No dissection has fewer pieces.
    pub value: usize,
    /// Why, in words.
    pub reason: String,
    /// Why a dissection with this many pieces is optimal, in words
    /// (`no 4-piece dissection exists; proof 1.2 s` for a SAT proof, else
    /// the reason).
    pub proof: String,
}

/// Why a run ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum End {
    /// The best dissection meets the lower bound.
    Optimal,
    /// The work rule ended it (no time limit): the paper's first valid
    /// level in [`Strategy::Paper`](crate::Strategy::Paper), rounds without
    /// improvement in the anytime schedule, the exact search's end.
    Finished,
    /// The time limit.
    TimeLimit,
    /// The caller's stop flag (Stop, Ctrl-C).
    Interrupted,
}

impl End {
    /// Whether the run was cut short (by time or by the caller).
    pub fn stopped(self) -> bool {
        matches!(self, End::TimeLimit | End::Interrupted)
    }
}

/// One of the different dissections with the fewest pieces a run
/// collected (verified, honouring the constraints), with its scores.
#[derive(Clone, Debug, PartialEq)]
pub struct Solution {
    /// The dissection.
    pub dissection: Verified,
    /// Its scores (the ranking criteria).
    pub scores: Scores,
    /// Who found it.
    pub source: Source,
}

/// How a run that collects solutions ranked them, and under what.
#[derive(Clone, Debug, PartialEq)]
pub struct Ranking {
    /// The criterion.
    pub rank: Rank,
    /// How many were asked for.
    pub asked: usize,
    /// The constraints, as the solution files record them.
    pub constraints: Value,
}

/// What a run produced.
#[derive(Clone, Debug, PartialEq)]
pub struct Report {
    /// The seed.
    pub seed: u64,
    /// The best dissection (verified); `None` only when none was found.
    pub best: Option<Verified>,
    /// Who found it.
    pub source: Option<Source>,
    /// The level it was found at (heuristic answers).
    pub level: Option<usize>,
    /// Seconds the run took.
    pub seconds: f64,
    /// Seconds to the first valid dissection.
    pub time_to_first: Option<f64>,
    /// Seconds to the first dissection with the final piece count.
    pub time_to_best: Option<f64>,
    /// The best lower bound proved.
    pub lower_bound: LowerBound,
    /// Whether the best dissection meets the lower bound.
    pub optimal: bool,
    /// Every improvement, in order.
    pub history: Vec<Improvement>,
    /// Why the run ended.
    pub end: End,
    /// Explorations of the level search.
    pub explorations: usize,
    /// Rounds of the level schedule.
    pub rounds: usize,
    /// The largest piece count the level search tried.
    pub last_pieces: usize,
    /// The best matching cost at the last level searched.
    pub best_mismatch: Option<u64>,
    /// When the run collected solutions (several asked for, a ranking,
    /// constraints): the different dissections with the fewest pieces,
    /// best first by the ranking (at most as many as asked; the first is
    /// `best`). Empty otherwise.
    pub solutions: Vec<Solution>,
    /// The ranking and constraints of a run that collected solutions.
    pub ranking: Option<Ranking>,
}

fn rounded(s: f64) -> f64 {
    (s * 1000.0).round() / 1000.0
}

impl Report {
    /// The keys a solution file gets beside the dissection (FORMAT.md
    /// allows extra keys): pieces, areas, area_variance, seed, seconds,
    /// level, explorations, stopped_early, lower_bound, lower_bound_reason,
    /// optimal, found_by, time_to_first, time_to_best, history.
    pub fn extra(&self) -> Map<String, Value> {
        let mut extra = Map::new();
        if let Some(best) = &self.best {
            extra.insert("pieces".into(), json!(best.piece_count()));
            extra.insert("areas".into(), json!(best.areas()));
            extra.insert("area_variance".into(), json!(best.variance()));
        }
        extra.insert("seed".into(), json!(self.seed));
        extra.insert("seconds".into(), json!(rounded(self.seconds)));
        if let Some(level) = self.level {
            extra.insert("level".into(), json!(level));
        }
        extra.insert("explorations".into(), json!(self.explorations));
        extra.insert("stopped_early".into(), Value::Bool(self.end.stopped()));
        extra.insert("lower_bound".into(), json!(self.lower_bound.value));
        extra.insert(
            "lower_bound_reason".into(),
            json!(self.lower_bound.reason.clone()),
        );
        extra.insert("optimal".into(), Value::Bool(self.optimal));
        if let Some(s) = self.source {
            extra.insert("found_by".into(), json!(s.name()));
        }
        if let Some(t) = self.time_to_first {
            extra.insert("time_to_first".into(), json!(rounded(t)));
        }
        if let Some(t) = self.time_to_best {
            extra.insert("time_to_best".into(), json!(rounded(t)));
        }
        extra.insert(
            "history".into(),
            Value::Array(
                self.history
                    .iter()
                    .map(|h| {
                        json!({
                            "pieces": h.pieces,
                            "seconds": rounded(h.seconds),
                            "by": h.source.name(),
                        })
                    })
                    .collect(),
            ),
        );
        extra
    }

    /// The solution file text (`dissection-solution/1` with [`Report::extra`]),
    /// when a dissection was found.
    pub fn solution_json(&self) -> Option<String> {
        if !self.solutions.is_empty() {
            return self.solution_json_at(0);
        }
        let best = self.best.as_ref()?;
        Some(best.dissection().to_file(self.extra()).to_json())
    }

    /// The file text of solution `i` (0-based, ranked) of a run that
    /// collected solutions: the first has every key of [`Report::extra`];
    /// each has its own `pieces`, `areas`, `area_variance`, `found_by`, and
    /// `scores`, `rank` (`{"by": criterion, "position": i + 1}`) and
    /// `constraints` (what it was solved under).
    pub fn solution_json_at(&self, i: usize) -> Option<String> {
        let s = self.solutions.get(i)?;
        let mut extra = if i == 0 {
            self.extra()
        } else {
            let mut m = Map::new();
            m.insert("seed".into(), json!(self.seed));
            m.insert("seconds".into(), json!(rounded(self.seconds)));
            m.insert("lower_bound".into(), json!(self.lower_bound.value));
            m.insert(
                "optimal".into(),
                Value::Bool(s.dissection.piece_count() <= self.lower_bound.value),
            );
            m
        };
        extra.insert("pieces".into(), json!(s.dissection.piece_count()));
        extra.insert("areas".into(), json!(s.dissection.areas()));
        extra.insert("area_variance".into(), json!(s.dissection.variance()));
        extra.insert("found_by".into(), json!(s.source.name()));
        extra.insert(
            "scores".into(),
            serde_json::to_value(&s.scores).unwrap_or(Value::Null),
        );
        if let Some(levels) = &s.scores.levels {
            extra.insert("levels".into(), json!(levels));
        }
        if let Some(r) = &self.ranking {
            extra.insert(
                "rank".into(),
                json!({"by": r.rank.name(), "position": i + 1}),
            );
            extra.insert("constraints".into(), r.constraints.clone());
        }
        Some(s.dissection.dissection().to_file(extra).to_json())
    }
}
