//! `dissect bound`: the exact mode of the `dissect-exact` crate, and the
//! lines that show the exact search's progress on stderr.

use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::time::Instant;

use anyhow::Result;
use dissect_core::LatticeKind;
use dissect_engine::TimeLimit;
use dissect_exact::{search, ExactEvent, ExactObserver, ExactOptions, Mode};

use crate::{input, InputError, Status};

/// Raised by Ctrl-C.
static STOP: AtomicBool = AtomicBool::new(false);

#[derive(clap::Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BoundArgs {
    /// The lattice: square, tri4, cubic, tri3 or hex.
    #[arg(long, default_value_t = LatticeKind::Square)]
    pub lattice: LatticeKind,
    /// Do not turn 2D pieces over (rotations only).
    #[arg(long)]
    pub no_mirror: bool,
    /// Stop after this many seconds and report the best bound proved so far.
    #[arg(long, value_name = "SECS")]
    pub time_limit: Option<TimeLimit>,
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
pub struct Lines {
    pub quiet: bool,
    pub start: Instant,
    pub names: Vec<String>,
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

fn catch_ctrl_c() {
    // The first Ctrl-C stops the search (what is proved is kept), a second
    // one exits at once.
    let _ = ctrlc::set_handler(|| {
        if STOP.swap(true, Ordering::SeqCst) {
            std::process::exit(130);
        }
    });
}

pub fn names(paths: &[PathBuf]) -> Vec<String> {
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
    let deadline = args.time_limit.unwrap_or_default().deadline();
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
    } else if let Some(dissect_exact::Limit::Cells { cells }) = &outcome.limit {
        println!(
            "no SAT search: a figure has {cells} cells (over {}); the bound below is the cheap one",
            dissect_exact::bound::FULL_GRAPH_MAX_CELLS
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
