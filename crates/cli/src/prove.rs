//! `dissect bound`, and `dissect solve --prove` / `--exact`: the exact mode
//! of the `dissect-exact` crate, alone or beside the heuristic solver.

use std::io::IsTerminal;
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::{Duration, Instant};

use anyhow::{Context, Result};
use dissect_core::io::Dissection;
use dissect_core::solver::solve;
use dissect_core::{Cell, LatticeKind};
use dissect_exact::{search, Bound, ExactEvent, ExactObserver, ExactOptions, Mode, Reason};
use serde_json::{json, Map, Value};

use crate::args::SolveArgs;
use crate::{input, InputError, Status};

/// Raised by Ctrl-C.
static STOP: AtomicBool = AtomicBool::new(false);

fn lattice(s: &str) -> Result<LatticeKind, String> {
    s.parse()
        .map_err(|e: dissect_core::lattice::UnknownLattice| e.to_string())
}

#[derive(clap::Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BoundArgs {
    /// The lattice: square, tri4, cubic, tri3 or hex.
    #[arg(long, default_value = "square", value_parser = lattice)]
    pub lattice: LatticeKind,
    /// Do not turn 2D pieces over (rotations only).
    #[arg(long)]
    pub no_mirror: bool,
    /// Stop after this many seconds and report the best bound proved so far.
    #[arg(long, value_name = "SECS")]
    pub time_limit: Option<f64>,
    /// Try to refute no more than this many pieces.
    #[arg(long, value_name = "K", value_parser = crate::args::whole_usize::<1>)]
    pub max_pieces: Option<usize>,
    /// Print only the last line.
    #[arg(long, short)]
    pub quiet: bool,
    /// Solve nothing: write to FILE, as DIMACS CNF, the formula the search
    /// would solve for "at most K pieces" with K given by --max-pieces (the
    /// relaxation without connectivity: UNSAT proves that no K-piece
    /// dissection exists). For timing other SAT solvers.
    #[arg(long, value_name = "FILE", requires = "max_pieces")]
    pub dimacs: Option<PathBuf>,
    /// The figures (text files, see FORMAT.md).
    #[arg(required = true, num_args = 2.., value_name = "FIGURE")]
    pub figures: Vec<PathBuf>,
}

/// Prints the exact search's progress on stderr.
struct Lines {
    quiet: bool,
    start: Instant,
    names: Vec<String>,
}

impl ExactObserver for Lines {
    fn on_event(&self, event: &ExactEvent) {
        if self.quiet {
            return;
        }
        let t = self.start.elapsed().as_secs_f64();
        match event {
            ExactEvent::CheapBound(b) => eprintln!(
                "[exact {t:6.1} s] cheap bound: {} ({})",
                b.value,
                b.describe(&self.names)
            ),
            ExactEvent::Encoded {
                pieces,
                motions,
                size,
            } => eprintln!(
                "[exact {t:6.1} s] {pieces} pieces, {motions}: {} variables, {} clauses, {} placements",
                size.vars, size.clauses, size.motions
            ),
            ExactEvent::Cuts {
                pieces,
                added,
                total,
            } if total.is_power_of_two() || *total == *added => eprintln!(
                "[exact {t:6.1} s] {pieces} pieces: a model had split pieces, {total} connectivity cuts so far"
            ),
            ExactEvent::ConnectivityEncoded { pieces } => eprintln!(
                "[exact {t:6.1} s] {pieces} pieces: a model had split pieces, connectivity encoded"
            ),
            ExactEvent::Refuted(b) => eprintln!(
                "[exact {t:6.1} s] lower bound {} ({})",
                b.value,
                b.describe(&self.names)
            ),
            ExactEvent::Inconclusive {
                pieces,
                motions,
                timed_out,
            } => eprintln!(
                "[exact {t:6.1} s] {pieces} pieces, {motions}: {}",
                if *timed_out {
                    "out of time"
                } else {
                    "none (this proves nothing)"
                }
            ),
            ExactEvent::Found { pieces, .. } => {
                eprintln!("[exact {t:6.1} s] SAT found a connected {pieces}-piece dissection")
            }
            _ => {}
        }
    }
}

fn check_time_limit(t: Option<f64>) -> Result<Option<Instant>> {
    match t {
        None => Ok(None),
        Some(t) if t.is_finite() && t >= 0.0 => {
            Ok(Some(Instant::now() + Duration::from_secs_f64(t)))
        }
        Some(t) => Err(InputError(format!(
            "--time-limit must be a number of seconds >= 0, got {t}"
        ))
        .into()),
    }
}

fn catch_ctrl_c() {
    // The first Ctrl-C stops the search (what is proved is kept), a second
    // one exits at once.
    let _ = ctrlc::set_handler(|| {
        if STOP.swap(true, Ordering::SeqCst) {
            std::process::exit(130);
        }
    });
}

fn names(paths: &[PathBuf]) -> Vec<String> {
    paths.iter().map(|p| input::file_name(p)).collect()
}

/// `dissect bound`: the last line printed is `lower bound: K (reason)`.
pub fn bound(args: BoundArgs) -> Result<Status> {
    let figures = input::figures(&args.figures, args.lattice)?;
    input::check_equal_areas(&args.figures, &figures)?;
    if let (Some(path), Some(k)) = (&args.dimacs, args.max_pieces) {
        let cnf = dissect_exact::dimacs(&figures, !args.no_mirror, k)
            .map_err(|e| InputError(e.to_string()))?;
        crate::output::write_atomic(path, cnf.text.as_bytes())?;
        println!(
            "wrote {}: at most {k} pieces, {} variables, {} clauses",
            path.display(),
            cnf.vars,
            cnf.clauses
        );
        return Ok(Status::Ok);
    }
    let deadline = check_time_limit(args.time_limit)?;
    catch_ctrl_c();
    let options = ExactOptions {
        mirror: !args.no_mirror,
        mode: Mode::LowerBound,
        deadline,
        max_pieces: args.max_pieces,
        ..ExactOptions::default()
    };
    let observer = Lines {
        quiet: args.quiet,
        start: Instant::now(),
        names: names(&args.figures),
    };
    let upper = AtomicUsize::new(usize::MAX);
    let outcome = search(&figures, &options, &STOP, &upper, &observer)
        .map_err(|e| InputError(e.to_string()))?;
    let names = names(&args.figures);
    if let Some(p) = &outcome.found {
        println!(
            "a {}-piece dissection exists (found by SAT): the bound is optimal",
            p[0].len()
        );
    } else if let Some(dissect_exact::Limit::TooLarge { pieces, bytes }) = &outcome.limit {
        println!(
            "stopped: the SAT encoding for {pieces} pieces would need about {} MiB \
             (over the cap of {} MiB); the bound below is the best proved",
            bytes >> 20,
            options.max_encoding_bytes >> 20
        );
    } else if outcome.stopped {
        println!("stopped (time limit or Ctrl-C); the bound below is the best proved");
    }
    println!(
        "lower bound: {} ({})",
        outcome.lower_bound.value,
        outcome.lower_bound.describe(&names)
    );
    Ok(Status::Ok)
}

/// Where the reported dissection came from.
#[derive(Clone, Copy, PartialEq, Eq)]
enum Source {
    Heuristic,
    Sat,
}

/// `dissect solve --exact` (SAT alone) and `dissect solve --prove` (the
/// heuristic and the exact search side by side, sharing bounds).
pub fn solve_exact(args: SolveArgs) -> Result<Status> {
    let figures = input::figures(&args.figures, args.lattice)?;
    input::check_equal_areas(&args.figures, &figures)?;
    let deadline = check_time_limit(args.time_limit)?;
    catch_ctrl_c();
    let start = Instant::now();
    let mirror = !args.no_mirror && args.lattice.lattice().supports_mirror();
    let exact_options = ExactOptions {
        mirror,
        mode: if args.exact {
            Mode::Minimum
        } else {
            Mode::LowerBound
        },
        deadline,
        max_pieces: args.max_pieces,
        ..ExactOptions::default()
    };
    let observer = Lines {
        quiet: args.quiet,
        start,
        names: names(&args.figures),
    };
    let upper = AtomicUsize::new(usize::MAX);
    let exact_stop = AtomicBool::new(false);
    let heuristic_stop = AtomicBool::new(false);
    let exact_done = AtomicBool::new(false);
    let heuristic_done = AtomicBool::new(!args.prove || args.exact);

    let (exact, heuristic) = std::thread::scope(|s| {
        let exact = s.spawn(|| {
            let r = search(&figures, &exact_options, &exact_stop, &upper, &observer);
            exact_done.store(true, Ordering::SeqCst);
            r
        });
        let heuristic = (args.prove && !args.exact).then(|| {
            s.spawn(|| {
                // One core for the SAT solver, the rest for the heuristic.
                let threads = if args.threads == 0 {
                    std::thread::available_parallelism()
                        .map_or(1, |n| n.get().saturating_sub(1))
                        .max(1)
                } else {
                    args.threads
                };
                let options = args.solver_options(threads);
                let r = solve(&figures, &options, &heuristic_stop, &());
                if let Ok(Some(found)) = r.as_ref().map(|o| o.found.as_ref()) {
                    upper.fetch_min(found.piece_count(), Ordering::SeqCst);
                    if !args.quiet {
                        eprintln!(
                            "[heuristic {:6.1} s] {} pieces",
                            start.elapsed().as_secs_f64(),
                            found.piece_count()
                        );
                    }
                }
                heuristic_done.store(true, Ordering::SeqCst);
                r
            })
        });
        // Share bounds and stop both sides on time, Ctrl-C, or when the
        // exact side has nothing left to prove.
        loop {
            let interrupted =
                STOP.load(Ordering::SeqCst) || deadline.is_some_and(|d| Instant::now() >= d);
            if interrupted {
                exact_stop.store(true, Ordering::SeqCst);
                heuristic_stop.store(true, Ordering::SeqCst);
            }
            if exact_done.load(Ordering::SeqCst) {
                // The exact side ends once its bound meets an upper bound
                // (its own or the heuristic's), so the heuristic can stop.
                if upper.load(Ordering::SeqCst) != usize::MAX {
                    heuristic_stop.store(true, Ordering::SeqCst);
                }
                if heuristic_done.load(Ordering::SeqCst) {
                    break;
                }
            }
            std::thread::sleep(Duration::from_millis(20));
        }
        (
            exact.join().expect("exact search thread"),
            heuristic.map(|h| h.join().expect("heuristic thread")),
        )
    });
    let exact = exact.map_err(|e| InputError(e.to_string()))?;
    let heuristic = heuristic
        .transpose()
        .map_err(|e| InputError(e.to_string()))?;
    let elapsed = start.elapsed().as_secs_f64();

    let from_heuristic = heuristic
        .as_ref()
        .and_then(|o| o.found.as_ref())
        .map(|f| (f.pieces.clone(), Source::Heuristic));
    let from_sat = exact.found.clone().map(|p| (p, Source::Sat));
    let best = [from_heuristic, from_sat]
        .into_iter()
        .flatten()
        .min_by_key(|(p, _)| p[0].len());
    let names = names(&args.figures);
    let bound = &exact.lower_bound;
    let Some((pieces, source)) = best else {
        eprintln!(
            "no dissection found after {elapsed:.1} s ({}); lower bound: {} ({})",
            if exact.stopped || STOP.load(Ordering::SeqCst) {
                "stopped by the time limit or Ctrl-C"
            } else {
                "--max-pieces was reached"
            },
            bound.value,
            bound.describe(&names)
        );
        return Ok(Status::NotFound);
    };
    let dissection = Dissection {
        lattice: args.lattice,
        mirror,
        names: names.clone(),
        pieces,
    };
    if let Err(v) = dissect_core::verify::verify(&dissection, &figures) {
        anyhow::bail!(
            "internal error: the dissection failed verification: {}",
            v[0]
        );
    }
    let count = dissection.piece_count();
    let optimal = count <= bound.value;
    let verdict = verdict(count, bound, optimal, &names);
    if !args.quiet {
        let colour = match args.color.as_str() {
            "always" => true,
            "never" => false,
            _ => std::io::stdout().is_terminal(),
        };
        for (path, p) in args.figures.iter().zip(&dissection.pieces) {
            println!("{}:", path.display());
            print!("{}", dissect_core::ascii::draw(args.lattice, p, colour));
            println!();
        }
        println!(
            "found by: {}",
            match source {
                Source::Heuristic => "the heuristic solver",
                Source::Sat => "the SAT search",
            }
        );
        println!("time: {elapsed:.2} s");
    }
    println!("{verdict}");
    if let Some(out) = &args.output {
        let mut extra = Map::new();
        extra.insert("pieces".into(), json!(count));
        extra.insert("areas".into(), json!(areas(&dissection.pieces[0])));
        extra.insert("lower_bound".into(), json!(bound.value));
        extra.insert("lower_bound_reason".into(), json!(bound.describe(&names)));
        extra.insert("optimal".into(), Value::Bool(optimal));
        extra.insert(
            "found_by".into(),
            json!(match source {
                Source::Heuristic => "heuristic",
                Source::Sat => "sat",
            }),
        );
        extra.insert("seed".into(), json!(args.seed));
        extra.insert("seconds".into(), json!((elapsed * 1000.0).round() / 1000.0));
        let text = dissection.to_file(extra).to_json();
        std::fs::write(out, text).with_context(|| format!("cannot write {}", out.display()))?;
    }
    Ok(Status::Ok)
}

fn areas(pieces: &[Vec<Cell>]) -> Vec<usize> {
    pieces.iter().map(|p| p.len()).collect()
}

/// `5 pieces — optimal (no 4-piece dissection exists; proof 38 s)`.
fn verdict(count: usize, bound: &Bound, optimal: bool, names: &[String]) -> String {
    if !optimal {
        return format!(
            "{count} pieces — not proved optimal (lower bound {}: {})",
            bound.value,
            bound.describe(names)
        );
    }
    match &bound.reason {
        Reason::Sat {
            refuted, seconds, ..
        } => format!(
            "{count} pieces — optimal (no {refuted}-piece dissection exists; proof {})",
            seconds_text(*seconds)
        ),
        _ => format!("{count} pieces — optimal ({})", bound.describe(names)),
    }
}

fn seconds_text(s: f64) -> String {
    if s < 10.0 {
        format!("{s:.1} s")
    } else {
        format!("{s:.0} s")
    }
}
