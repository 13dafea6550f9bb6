//! Summaries over seeds and the tables printed from them, as aligned text
//! or as Markdown.
//!
//! Medians over an even number of seeds take the upper middle value (the
//! worse of the two), and a run that found nothing counts as worse than any
//! run that found something.

use std::time::Duration;

use dissect_core::LatticeKind;

use crate::paper::PaperResult;
use crate::run::SeedRun;

/// All seeds of one instance.
#[derive(Clone, Debug, PartialEq)]
pub struct InstanceResult {
    /// The instance's name.
    pub name: String,
    /// Its lattice.
    pub lattice: LatticeKind,
    /// Cells per figure.
    pub cells: usize,
    /// Number of figures.
    pub figures: usize,
    /// The reference piece count (best known for this layout).
    pub reference: Option<usize>,
    /// What the paper reports for the figures this instance reconstructs.
    pub paper: Option<PaperResult>,
    /// The time limit of each run.
    pub time_limit: Option<Duration>,
    /// Our target for the median time to the first valid dissection at the
    /// reference piece count, in seconds.
    pub target: Option<f64>,
    /// One run per seed.
    pub runs: Vec<SeedRun>,
}

/// One step of a scaling series.
#[derive(Clone, Debug, PartialEq)]
pub struct ScaleStep {
    /// The factor: every cell became `k×k` (or `k×k×k`) cells.
    pub k: u32,
    /// Cells per figure.
    pub cells: usize,
    /// One run per seed.
    pub runs: Vec<SeedRun>,
}

/// How tables are printed.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Style {
    /// Space-aligned columns for a terminal.
    Text,
    /// A Markdown table.
    Markdown,
}

/// The upper median and the maximum, with `None` greater than any value.
pub fn median_worst<T: Ord + Copy>(values: &[Option<T>]) -> Option<(Option<T>, Option<T>)> {
    if values.is_empty() {
        return None;
    }
    let mut v = values.to_vec();
    // `None` last: a run that found nothing is the worst.
    v.sort_by(|a, b| match (a, b) {
        (Some(x), Some(y)) => x.cmp(y),
        (Some(_), None) => std::cmp::Ordering::Less,
        (None, Some(_)) => std::cmp::Ordering::Greater,
        (None, None) => std::cmp::Ordering::Equal,
    });
    Some((v[v.len() / 2], v[v.len() - 1]))
}

/// The upper median of the finite values, if any.
pub fn median_f64(values: impl IntoIterator<Item = f64>) -> Option<f64> {
    let mut v: Vec<f64> = values.into_iter().filter(|x| x.is_finite()).collect();
    if v.is_empty() {
        return None;
    }
    v.sort_by(f64::total_cmp);
    Some(v[v.len() / 2])
}

/// A duration in seconds, with fewer decimals as it grows.
pub fn secs(d: Duration) -> String {
    let s = d.as_secs_f64();
    if s < 10.0 {
        format!("{s:.2}")
    } else if s < 100.0 {
        format!("{s:.1}")
    } else {
        format!("{s:.0}")
    }
}

fn pair<T: Copy>(mw: Option<(Option<T>, Option<T>)>, show: impl Fn(T) -> String) -> String {
    let one = |v: Option<T>| v.map_or("none".to_string(), &show);
    match mw {
        None => "-".to_string(),
        Some((m, w)) => format!("{} / {}", one(m), one(w)),
    }
}

impl InstanceResult {
    /// Median and worst piece count.
    pub fn pieces(&self) -> Option<(Option<usize>, Option<usize>)> {
        median_worst(&self.runs.iter().map(|r| r.pieces).collect::<Vec<_>>())
    }

    /// The fewest pieces any seed found.
    pub fn best_pieces(&self) -> Option<usize> {
        self.runs.iter().filter_map(|r| r.pieces).min()
    }

    /// Median and worst time to the first valid dissection.
    pub fn first_valid(&self) -> Option<(Option<Duration>, Option<Duration>)> {
        median_worst(&self.runs.iter().map(|r| r.first_valid).collect::<Vec<_>>())
    }

    /// Median and worst total time.
    pub fn total(&self) -> Option<(Option<Duration>, Option<Duration>)> {
        median_worst(&self.runs.iter().map(|r| Some(r.total)).collect::<Vec<_>>())
    }

    /// How many seeds reached the reference piece count (or fewer).
    pub fn reached(&self) -> Option<usize> {
        let r = self.reference?;
        Some(
            self.runs
                .iter()
                .filter(|s| s.pieces.is_some_and(|p| p <= r))
                .count(),
        )
    }

    /// Whether the target is met: the median run reaches the reference
    /// piece count and its time to the first valid dissection is under the
    /// target. `"< 10 s: met"`, `"< 10 s: missed"` or `"-"`.
    pub fn target_verdict(&self) -> String {
        let Some(target) = self.target else {
            return "-".to_string();
        };
        let pieces_ok = match (self.reference, self.pieces()) {
            (Some(r), Some((Some(p), _))) => p <= r,
            _ => false,
        };
        let time_ok = matches!(
            self.first_valid(),
            Some((Some(t), _)) if t.as_secs_f64() < target
        );
        let verdict = if pieces_ok && time_ok && !self.has_error() {
            "met"
        } else {
            "missed"
        };
        format!("< {target} s: {verdict}")
    }

    /// Whether any run failed verification or could not run.
    pub fn has_error(&self) -> bool {
        self.runs.iter().any(SeedRun::is_error)
    }
}

/// The summary table: one row per instance.
pub fn suite_table(results: &[InstanceResult], style: Style) -> String {
    let headers = [
        "instance",
        "lattice",
        "cells",
        "ref",
        "paper pieces",
        "paper time",
        "pieces best / med / worst",
        "first valid s med / worst",
        "total s med / worst",
        "CPU s (med)",
        "peak RSS MiB (max)",
        "area var (med)",
        "reached ref",
        "target",
    ];
    let rows: Vec<Vec<String>> = results
        .iter()
        .map(|r| {
            let reached = match (r.has_error(), r.reached()) {
                (true, _) => "ERROR".to_string(),
                (false, Some(n)) => format!("{n}/{}", r.runs.len()),
                (false, None) => "n/a".to_string(),
            };
            let cells = if r.figures > 2 {
                format!("{}×{}", r.figures, r.cells)
            } else {
                r.cells.to_string()
            };
            vec![
                r.name.clone(),
                r.lattice.to_string(),
                cells,
                r.reference.map_or("-".to_string(), |v| v.to_string()),
                r.paper
                    .map_or("-".to_string(), |p| format!("{} ({})", p.pieces, p.figure)),
                r.paper.map_or("-".to_string(), |p| p.time.to_string()),
                format!(
                    "{} / {}",
                    r.best_pieces()
                        .map_or("none".to_string(), |v| v.to_string()),
                    pair(r.pieces(), |v| v.to_string())
                ),
                pair(r.first_valid(), secs),
                pair(r.total(), secs),
                median_cpu(&r.runs),
                max_rss(&r.runs),
                median_f64(r.runs.iter().filter_map(|s| s.variance))
                    .map_or("-".to_string(), |v| format!("{v:.1}")),
                reached,
                r.target_verdict(),
            ]
        })
        .collect();
    table(&headers, &rows, style)
}

/// Every run: one row per instance and seed.
pub fn seed_table(results: &[InstanceResult], style: Style) -> String {
    let headers = [
        "instance",
        "seed",
        "pieces",
        "first valid s",
        "best s",
        "lower bound",
        "total s",
        "CPU s",
        "peak RSS MiB",
        "area var",
        "explorations",
        "note",
    ];
    let mut rows = Vec::new();
    for r in results {
        for s in &r.runs {
            rows.push(vec![
                r.name.clone(),
                s.seed.to_string(),
                s.pieces.map_or("none".to_string(), |v| v.to_string()),
                s.first_valid.map_or("-".to_string(), secs),
                s.time_to_best.map_or("-".to_string(), secs),
                match s.lower_bound {
                    Some(b) if s.optimal => format!("{b} (optimal)"),
                    Some(b) => b.to_string(),
                    None => "-".to_string(),
                },
                secs(s.total),
                s.cpu.map_or("-".to_string(), secs),
                max_rss(std::slice::from_ref(s)),
                s.variance.map_or("-".to_string(), |v| format!("{v:.1}")),
                s.explorations.to_string(),
                note(s),
            ]);
        }
    }
    table(&headers, &rows, style)
}

/// The largest peak resident set size of some runs in MiB (`-` when
/// unknown for any of them).
pub fn max_rss(runs: &[SeedRun]) -> String {
    let peaks: Option<Vec<u64>> = runs.iter().map(|r| r.peak_rss).collect();
    match peaks.and_then(|p| p.into_iter().max()) {
        Some(bytes) => format!("{:.0}", bytes as f64 / (1024.0 * 1024.0)),
        None => "-".to_string(),
    }
}

/// The median CPU time of the runs that report one.
fn median_cpu(runs: &[SeedRun]) -> String {
    median_f64(runs.iter().filter_map(|r| r.cpu).map(|d| d.as_secs_f64()))
        .map_or("-".to_string(), |c| secs(Duration::from_secs_f64(c)))
}

/// What a run's table row says beyond its numbers.
fn note(s: &SeedRun) -> String {
    if let Some(e) = &s.error {
        return e.clone();
    }
    if s.pieces.is_none() {
        let (k, em) = s.last_level;
        return format!(
            "{}; best {k}-piece E_M = {}",
            if s.stopped { "time limit" } else { "gave up" },
            em.map_or("n/a".to_string(), |m| m.to_string())
        );
    }
    String::new()
}

/// The growth exponent between two steps: `ln(t2/t1) / ln(c2/c1)`.
pub fn growth_exponent(c1: usize, t1: Duration, c2: usize, t2: Duration) -> Option<f64> {
    let (t1, t2) = (t1.as_secs_f64(), t2.as_secs_f64());
    if c2 == c1 || t1 <= 0.0 || t2 <= 0.0 {
        return None;
    }
    Some((t2 / t1).ln() / (c2 as f64 / c1 as f64).ln())
}

/// The scaling table: one row per factor, with the growth exponents
/// against the previous row of the median wall time to the first valid
/// dissection and of the median CPU time (when every run found one).
pub fn scale_table(steps: &[ScaleStep], style: Style) -> String {
    let headers = [
        "k",
        "cells",
        "pieces med / worst",
        "first valid s med / worst",
        "total s med / worst",
        "CPU s (med)",
        "peak RSS MiB (max)",
        "growth exponent vs previous k (wall / CPU)",
    ];
    let median_first = |s: &ScaleStep| {
        median_worst(&s.runs.iter().map(|r| r.first_valid).collect::<Vec<_>>()).and_then(|(m, _)| m)
    };
    // The CPU time of a run that found nothing says nothing about growth.
    let median_cpu_found = |s: &ScaleStep| {
        if s.runs.iter().any(|r| r.pieces.is_none()) {
            return None;
        }
        median_f64(s.runs.iter().filter_map(|r| r.cpu).map(|d| d.as_secs_f64()))
            .map(Duration::from_secs_f64)
    };
    let rows: Vec<Vec<String>> = steps
        .iter()
        .enumerate()
        .map(|(i, s)| {
            let exponent = |time: &dyn Fn(&ScaleStep) -> Option<Duration>| {
                i.checked_sub(1)
                    .and_then(|p| {
                        let prev = &steps[p];
                        growth_exponent(prev.cells, time(prev)?, s.cells, time(s)?)
                    })
                    .map_or("-".to_string(), |e| format!("{e:.2}"))
            };
            let exponent = format!(
                "{} / {}",
                exponent(&median_first),
                exponent(&median_cpu_found)
            );
            let errors = s.runs.iter().filter(|r| r.is_error()).count();
            let pieces = pair(
                median_worst(&s.runs.iter().map(|r| r.pieces).collect::<Vec<_>>()),
                |v| v.to_string(),
            );
            vec![
                s.k.to_string(),
                s.cells.to_string(),
                if errors > 0 {
                    format!("{pieces} ({errors} ERROR)")
                } else {
                    pieces
                },
                pair(
                    median_worst(&s.runs.iter().map(|r| r.first_valid).collect::<Vec<_>>()),
                    secs,
                ),
                pair(
                    median_worst(&s.runs.iter().map(|r| Some(r.total)).collect::<Vec<_>>()),
                    secs,
                ),
                median_cpu(&s.runs),
                max_rss(&s.runs),
                exponent,
            ]
        })
        .collect();
    table(&headers, &rows, style)
}

/// The replay of a recorded run on each of `threads` simulated threads:
/// makespan, speed-up over one thread and waiting fraction, with a barrier
/// after every `batch` explorations, without barriers, and the solver's way
/// (no barriers, a sliding window; levels keep their barriers in all).
pub fn replay_table(
    recording: &crate::schedule::Recording,
    batch: usize,
    threads: &[usize],
    style: Style,
) -> String {
    use crate::schedule::replay_levels;
    let batched = format!("makespan s (batches of {batch})");
    let headers = [
        "threads",
        batched.as_str(),
        "speed-up",
        "waiting",
        "makespan s (no barriers)",
        "speed-up",
        "waiting",
        "barriers cost",
        "solver's window",
        "makespan s (window)",
        "waiting (window)",
    ];
    let levels = recording.durations();
    let one = |b| replay_levels(&levels, b, 1).makespan;
    let (one_batched, one_free) = (one(batch), one(0));
    let speedup = |one: f64, t: f64| {
        if t > 0.0 {
            format!("{:.2}", one / t)
        } else {
            "-".to_string()
        }
    };
    let share = |x: f64| format!("{:.1} %", 100.0 * x);
    let rows: Vec<Vec<String>> = threads
        .iter()
        .map(|&t| {
            let b = replay_levels(&levels, batch, t);
            let f = replay_levels(&levels, 0, t);
            let w = crate::schedule::window(batch, t);
            let wr = crate::schedule::replay_levels_window(&levels, w, t);
            vec![
                t.to_string(),
                format!("{:.3}", b.makespan),
                speedup(one_batched, b.makespan),
                share(b.waiting()),
                format!("{:.3}", f.makespan),
                speedup(one_free, f.makespan),
                share(f.waiting()),
                if f.makespan > 0.0 {
                    format!("{:+.1} %", 100.0 * (b.makespan / f.makespan - 1.0))
                } else {
                    "-".to_string()
                },
                w.to_string(),
                format!("{:.3}", wr.makespan),
                share(wr.waiting()),
            ]
        })
        .collect();
    table(&headers, &rows, style)
}

/// Lays out a table.
pub fn table(headers: &[&str], rows: &[Vec<String>], style: Style) -> String {
    let mut out = String::new();
    match style {
        Style::Markdown => {
            let line = |cells: Vec<&str>| format!("| {} |\n", cells.join(" | "));
            out += &line(headers.to_vec());
            out += &line(headers.iter().map(|_| "---").collect());
            for r in rows {
                out += &line(r.iter().map(|c| c.as_str()).collect());
            }
        }
        Style::Text => {
            let mut width: Vec<usize> = headers.iter().map(|h| h.chars().count()).collect();
            for r in rows {
                for (w, c) in width.iter_mut().zip(r) {
                    *w = (*w).max(c.chars().count());
                }
            }
            let line = |cells: Vec<&str>| {
                let padded: Vec<String> = cells
                    .iter()
                    .zip(&width)
                    .map(|(c, w)| format!("{c}{}", " ".repeat(w - c.chars().count())))
                    .collect();
                format!("{}\n", padded.join("  ").trim_end())
            };
            out += &line(headers.to_vec());
            let rule: Vec<String> = width.iter().map(|w| "-".repeat(*w)).collect();
            out += &line(rule.iter().map(String::as_str).collect());
            for r in rows {
                out += &line(r.iter().map(|c| c.as_str()).collect());
            }
        }
    }
    out
}
