//! `dissect solve`: maps the flags into the engine's run options, shows the
//! run's progress, and writes and prints the answer. The run itself (the
//! searches, the time limit, verification) is `dissect_engine::run`.

use std::io::IsTerminal;
use std::time::Instant;

use anyhow::Result;
use std::path::{Path, PathBuf};

use dissect_core::Figure;
use dissect_engine::{
    ConstraintError, Constraints, End, EngineError, EngineEvent, EngineObserver, KeepRegions,
    OptionsError, Report, RunOptions,
};
use dissect_exact::ExactObserver;

use crate::args::{KeepArg, SolveArgs};
use crate::progress::{self, Progress};
use crate::{input, InputError, Status};

/// Progress on stderr: the level search's lines (or bar), each
/// improvement, each rise of the lower bound, and with `--exact` or an
/// explicit `--prove` the exact search's lines.
struct Display {
    quiet: bool,
    /// `--paper`: the level lines only, as the paper's schedule always printed.
    paper: bool,
    start: Instant,
    progress: Progress,
    exact: Option<crate::prove::Lines>,
    /// Writes the certificates (`--certificate`).
    certificates: Option<dissect_certificate::Writer>,
}

impl EngineObserver for Display {
    fn on_event(&self, event: &EngineEvent<'_>) {
        if let (EngineEvent::Exact(e), Some(w)) = (event, &self.certificates) {
            w.on_event(e);
        }
        if self.quiet {
            return;
        }
        match event {
            EngineEvent::Search(e) => dissect_core::solver::Observer::on_event(&self.progress, e),
            EngineEvent::Exact(e) => {
                if let Some(lines) = &self.exact {
                    ExactObserver::on_event(lines, e);
                }
            }
            EngineEvent::Improved(_) | EngineEvent::LowerBound(_) if self.paper => {}
            EngineEvent::Improved(i) => self.progress.line(&format!(
                "{} at {:.1} s ({})",
                plural(i.pieces, "piece"),
                i.seconds,
                i.source.name()
            )),
            EngineEvent::Collected {
                pieces,
                count,
                seconds,
            } if *count > 1 => self.progress.line(&format!(
                "{} with {} at {seconds:.1} s",
                plural(*count, "different dissection"),
                plural(*pieces, "piece"),
            )),
            EngineEvent::LowerBound(b) => self.progress.line(&format!(
                "lower bound {} ({}) at {:.1} s",
                b.value,
                b.reason,
                self.start.elapsed().as_secs_f64()
            )),
            _ => {}
        }
    }
}

/// The progress display of `solve`, with the certificate writer of
/// `--certificate`.
fn display(args: &SolveArgs, names: &[String], start: Instant) -> Result<Display> {
    let explicit_prove = args.prove || args.exact;
    Ok(Display {
        quiet: args.quiet,
        paper: args.paper,
        start,
        progress: Progress::new(args.quiet),
        exact: explicit_prove.then(|| crate::prove::Lines {
            quiet: args.quiet,
            start,
            names: names.to_vec(),
            certificates: None,
        }),
        certificates: match &args.certificate {
            Some(dir) => Some(crate::certificate::writer(
                dir,
                &args.figures,
                args.lattice,
                args.no_mirror,
            )?),
            None => None,
        },
    })
}

pub fn run(args: SolveArgs) -> Result<Status> {
    let figures = input::figures(&args.figures, args.lattice)?;
    input::check_equal_areas(&args.figures, &figures)?;
    let mut config = args.run_config();
    config.constraints = constraints(&args, &figures)?;
    let options = match RunOptions::new(config) {
        Ok(o) => o,
        Err(OptionsError::Constraints(e)) if e.is_impossible() => return Ok(impossible(&e)),
        Err(e) => return Err(InputError(e.to_string()).into()),
    };
    if let Some(out) = &args.output {
        input::check_writable(out)?;
    }
    let names = crate::prove::names(&args.figures);

    // Ctrl-C: the first stops the search (the best result is kept), a
    // second one exits at once.
    let stop = crate::stop::flag();
    let start = Instant::now();
    let explicit_prove = args.prove || args.exact;
    let display = display(&args, &names, start)?;
    let report = dissect_engine::run(&figures, &names, &options, stop, &display);
    display.progress.finish();
    // The certificates' line on stderr (stdout's last line stays the verdict).
    let certificates = display.certificates.as_ref().map_or(Ok(()), |w| {
        w.summary()
            .map(|l| progress::stderr_line(&l))
            .map_err(crate::output::cli_error)
    });
    let report = match report {
        Ok(r) => r,
        Err(e @ EngineError::Figures(_)) => return Err(InputError(e.to_string()).into()),
        Err(EngineError::Constraints(e)) if e.is_impossible() => return Ok(impossible(&e)),
        Err(e @ EngineError::Constraints(_)) => return Err(InputError(e.to_string()).into()),
        Err(e) => return Err(e.into()),
    };

    let Some(best) = &report.best else {
        let why = match report.end {
            End::Interrupted => "interrupted (Ctrl-C)".to_string(),
            End::TimeLimit => format!(
                "the time limit of {} was reached",
                args.time_limit.unwrap_or_default()
            ),
            _ => match args.max_pieces {
                Some(k) => format!("--max-pieces {k} was reached"),
                None => "every piece count was tried".to_string(),
            },
        };
        progress::stderr_line(&format!(
            "no dissection found: {why} after {:.1} s; the best candidate ({}) had matching score E_M = {}; lower bound: {} ({})",
            report.seconds,
            plural(report.last_pieces.max(1), "piece"),
            report.best_mismatch.map_or("n/a".to_string(), |m| m.to_string()),
            report.lower_bound.value,
            report.lower_bound.reason,
        ));
        certificates?;
        return Ok(Status::NotFound);
    };

    // The solution file first: whatever happens next (a closed stdout, a
    // failed rendering), the run is not lost.
    let mut written = Ok(());
    if let Some(out) = &args.output {
        let text = report.solution_json().expect("a dissection was found");
        if let Err(e) = crate::output::write_atomic(out, &text) {
            // The solution goes to stdout instead.
            progress::stdout(&text);
            written = Err(InputError(format!(
                "{}: cannot write: {e} (the solution was printed on stdout instead)",
                out.display()
            )));
        }
    }
    // Several solutions: OUT-2.json, OUT-3.json, ... and a line each.
    let others = if written.is_ok() {
        write_others(&args, &report)
    } else {
        Ok(())
    };

    let verdict = verdict(&report);
    if !args.quiet {
        let colour = match args.color.as_str() {
            "always" => true,
            "never" => false,
            _ => std::io::stdout().is_terminal(),
        };
        let mut text = String::new();
        for (path, pieces) in args.figures.iter().zip(best.pieces()) {
            text += &format!(
                "{}:\n{}\n",
                path.display(),
                dissect_core::ascii::draw(args.lattice, pieces, colour)
            );
        }
        let list: Vec<String> = best
            .areas()
            .iter()
            .enumerate()
            .map(|(i, a)| format!("{}={a}", dissect_core::ascii::piece_letter(i)))
            .collect();
        if let Some(r) = &report.ranking {
            text += &format!(
                "{} with the fewest pieces ranked by {}{}\n",
                plural(report.solutions.len(), "different dissection"),
                r.rank,
                if report.solutions.len() < r.asked {
                    format!(" ({} asked for)", r.asked)
                } else {
                    String::new()
                }
            );
        }
        text += &format!(
            "{}\npiece areas: {}\narea variance: {:.2}\ntime: {:.2} s{}\n{verdict}\n",
            plural(best.piece_count(), "piece"),
            list.join(" "),
            best.variance(),
            report.seconds,
            match report.end {
                End::Interrupted => " (interrupted; best found so far)",
                End::TimeLimit => " (time limit reached; best found so far)",
                _ => "",
            }
        );
        progress::stdout(&text);
    } else if explicit_prove {
        progress::stdout(&format!("{verdict}\n"));
    }
    written?;
    others?;
    certificates?;

    #[cfg(feature = "render")]
    #[cfg(feature = "render")]
    if let Some(dir) = &args.render {
        crate::render::write_views(dir, best.dissection())?;
    }
    Ok(Status::Ok)
}

/// Reads `--keep N:REGIONS.txt`, `--min-piece`, `--max-piece`,
/// `--checkerboard` and `--symmetry-weight` (a grid that cannot be read is
/// bad input naming the file, line and column; the rest is checked by the
/// engine).
fn constraints(args: &SolveArgs, figures: &[Figure]) -> Result<Constraints> {
    let mut c = Constraints::none()
        .with_sizes(args.min_piece, args.max_piece)
        .with_checkerboard(args.checkerboard)
        .with_assembly(args.assemblable, args.min_level)
        .with_symmetry_weight(args.symmetry_weight.unwrap_or(0.0));
    for k in &args.keep {
        let KeepArg::Regions(n, path) = k else {
            continue;
        };
        let text = input::read(path, 1 << 20)?;
        let regions = KeepRegions::parse(&text, n - 1, figures)
            .map_err(|e| InputError(format!("{}: {e}", path.display())))?;
        c = c.with_keep(regions);
    }
    Ok(c)
}

/// Constraints that cannot hold: the reason, and exit 1.
fn impossible(e: &ConstraintError) -> Status {
    progress::stderr_line(&format!(
        "no dissection found: the constraints cannot all hold: {e}"
    ));
    Status::NotFound
}

/// `OUT.json`, `OUT-2.json`, ... for the `i`-th solution (0-based).
pub fn numbered(out: &Path, i: usize) -> PathBuf {
    if i == 0 {
        return out.to_path_buf();
    }
    let stem = out
        .file_stem()
        .map_or_else(String::new, |s| s.to_string_lossy().into_owned());
    let name = match out.extension() {
        Some(ext) => format!("{stem}-{}.{}", i + 1, ext.to_string_lossy()),
        None => format!("{stem}-{}", i + 1),
    };
    out.with_file_name(name)
}

/// Writes solutions 2, 3, ... of a run that collected them (each
/// atomically) and lists every solution with its scores on stderr.
fn write_others(args: &SolveArgs, report: &Report) -> Result<()> {
    let Some(ranking) = &report.ranking else {
        return Ok(());
    };
    for (i, s) in report.solutions.iter().enumerate() {
        let path = args.output.as_ref().map(|o| numbered(o, i));
        if let (Some(path), true) = (&path, i > 0) {
            let text = report.solution_json_at(i).expect("a solution");
            crate::output::write_atomic(path, &text)?;
        }
        if !args.quiet {
            let label = path.map_or_else(|| format!("#{}", i + 1), |p| p.display().to_string());
            progress::stderr_line(&format!("{label}: {} ({})", s.scores, s.source.name()));
        }
    }
    if report.solutions.len() < ranking.asked && !args.quiet {
        progress::stderr_line(&format!(
            "found {} with the fewest pieces ({} asked for)",
            plural(report.solutions.len(), "different dissection"),
            ranking.asked
        ));
    }
    Ok(())
}

/// `5 pieces — optimal (no 4-piece dissection exists; proof 38 s)`, or
/// `6 pieces — not proved optimal (lower bound 2: ...)`.
fn verdict(report: &Report) -> String {
    let count = report.best.as_ref().map_or(0, |b| b.piece_count());
    let b = &report.lower_bound;
    let count = plural(count, "piece");
    if report.optimal {
        format!("{count} — optimal ({})", b.proof)
    } else {
        format!(
            "{count} — not proved optimal (lower bound {}: {})",
            b.value, b.reason
        )
    }
}

/// `1 piece`, `2 pieces`.
fn plural(n: usize, word: &str) -> String {
    format!("{n} {word}{}", if n == 1 { "" } else { "s" })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbered_outputs() {
        let o = Path::new("dir/out.json");
        assert_eq!(numbered(o, 0), Path::new("dir/out.json"));
        assert_eq!(numbered(o, 1), Path::new("dir/out-2.json"));
        assert_eq!(numbered(Path::new("x"), 2), Path::new("x-3"));
    }
}
