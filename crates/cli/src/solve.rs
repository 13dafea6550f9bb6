//! `dissect solve`: maps the flags into the engine's run options, shows the
//! run's progress, and writes and prints the answer. The run itself (the
//! searches, the time limit, verification) is `dissect_engine::run`.

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Instant;

use anyhow::Result;
use dissect_engine::{End, EngineError, EngineEvent, EngineObserver, Report, RunOptions};
use dissect_exact::ExactObserver;

use crate::args::SolveArgs;
use crate::progress::{self, Progress};
use crate::{input, InputError, Status};

/// Raised by Ctrl-C (SIGINT, or SIGTERM).
static STOP: AtomicBool = AtomicBool::new(false);

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
}

impl EngineObserver for Display {
    fn on_event(&self, event: &EngineEvent<'_>) {
        if self.quiet {
            return;
        }
        match event {
            EngineEvent::Search(e) => dissect_core::solver::Observer::on_event(&self.progress, e),
            EngineEvent::Exact(e) => {
                if let Some(lines) = &self.exact {
                    lines.on_event(e);
                }
            }
            EngineEvent::Improved(_) | EngineEvent::LowerBound(_) if self.paper => {}
            EngineEvent::Improved(i) => self.progress.line(&format!(
                "{} at {:.1} s ({})",
                plural(i.pieces, "piece"),
                i.seconds,
                i.source.name()
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

pub fn run(args: SolveArgs) -> Result<Status> {
    let figures = input::figures(&args.figures, args.lattice)?;
    input::check_equal_areas(&args.figures, &figures)?;
    let options = RunOptions::new(args.run_config()).map_err(|e| InputError(e.to_string()))?;
    if let Some(out) = &args.output {
        input::check_writable(out)?;
    }
    let names = crate::prove::names(&args.figures);

    // Ctrl-C: the first stops the search (the best result is kept), a
    // second one exits at once.
    let _ = ctrlc::set_handler(|| {
        if STOP.swap(true, Ordering::SeqCst) {
            std::process::exit(130);
        }
    });
    let start = Instant::now();
    let explicit_prove = args.prove || args.exact;
    let display = Display {
        quiet: args.quiet,
        paper: args.paper,
        start,
        progress: Progress::new(args.quiet),
        exact: explicit_prove.then(|| crate::prove::Lines {
            quiet: args.quiet,
            start,
            names: names.clone(),
        }),
    };
    let report = dissect_engine::run(&figures, &names, &options, &STOP, &display);
    display.progress.finish();
    let report = match report {
        Ok(r) => r,
        Err(e @ EngineError::Figures(_)) => return Err(InputError(e.to_string()).into()),
        Err(e) => return Err(e.into()),
    };

    let Some(best) = &report.best else {
        let why = match report.end {
            End::Interrupted => "interrupted (Ctrl-C)".to_string(),
            End::TimeLimit => format!(
                "the time limit of {} s was reached",
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

    #[cfg(feature = "render")]
    #[cfg(feature = "render")]
    if let Some(dir) = &args.render {
        crate::render::write_views(dir, best.dissection())?;
    }
    Ok(Status::Ok)
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
