//! `dissect assemblies`: in how many ways the pieces of a solution tile
//! each figure (crate `dissect-puzzle`).

use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::{Duration, Instant};

use anyhow::Result;
use clap::Args;
use dissect_core::LatticeKind;
use dissect_engine::TimeLimit;
use dissect_puzzle::assemblies::{count, report_line, AssemblyError, CountLimits, PieceSet};
use dissect_puzzle::dlx::Progress;
use dissect_puzzle::Motions;

use crate::{input, InputError, Status};

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct AssembliesArgs {
    /// The lattice (default: the solution's).
    #[arg(long)]
    pub lattice: Option<LatticeKind>,
    /// The solution JSON whose pieces are counted (as cut from its first figure).
    #[arg(long, value_name = "S.json")]
    pub solution: PathBuf,
    /// Stop counting after this many seconds in all and report what was found.
    #[arg(long, value_name = "SECS")]
    pub time_limit: Option<TimeLimit>,
    /// No progress on stderr.
    #[arg(long, short)]
    pub quiet: bool,
    /// The figures to tile (any figures of the pieces' total area).
    #[arg(required = true, num_args = 1.., value_name = "FIGURE")]
    pub figures: Vec<PathBuf>,
}

static STOP: AtomicBool = AtomicBool::new(false);

pub fn run(args: AssembliesArgs) -> Result<Status> {
    let (_, dissection) = input::solution(&args.solution)?;
    input::check_solution_lattice(&args.solution, dissection.lattice(), args.lattice)?;
    let lattice = dissection.lattice();
    let deadline = args.time_limit.unwrap_or_default().deadline();
    let figures = input::figures(&args.figures, lattice)?;
    let pieces = dissection.pieces().first().cloned().unwrap_or_default();
    let set = PieceSet::new(Motions::new(lattice, dissection.mirror()), &pieces)
        .map_err(|e| InputError(format!("{}: {e}", args.solution.display())))?;
    let _ = ctrlc::set_handler(|| STOP.store(true, Ordering::SeqCst));
    let terminal = std::io::stderr().is_terminal();
    let mut complete = true;
    for (path, figure) in args.figures.iter().zip(&figures) {
        let name = input::file_name(path);
        let mut last_line = Instant::now();
        let mut shown = false;
        let mut progress = |p: Progress| {
            if args.quiet {
                return;
            }
            let text = format!(
                "{name}: {} tilings so far, about {:.0}% searched",
                p.solutions,
                100.0 * p.done
            );
            if terminal {
                eprint!("\r\x1b[2K{text}");
                shown = true;
            } else if last_line.elapsed() >= Duration::from_secs(10) {
                eprintln!("{text}");
                last_line = Instant::now();
            }
        };
        let result = count(
            &set,
            figure,
            CountLimits {
                stop: Some(&STOP),
                deadline,
                progress: Some(&mut progress),
            },
        );
        if shown {
            eprint!("\r\x1b[2K");
        }
        let c = result.map_err(|e| match e {
            AssemblyError::Area { .. } | AssemblyError::Lattice { .. } => {
                anyhow::Error::from(InputError(format!("{}: {e}", path.display())))
            }
            other => other.into(),
        })?;
        complete &= c.complete;
        let mut out = std::io::stdout().lock();
        writeln!(out, "{}", report_line(&name, &c))?;
        out.flush()?;
    }
    // A count cut short is still a result: say so, but do not fail.
    if !complete && !args.quiet {
        eprintln!(
            "note: the count stopped early (time limit or Ctrl-C); the numbers are lower bounds"
        );
    }
    Ok(Status::Ok)
}
