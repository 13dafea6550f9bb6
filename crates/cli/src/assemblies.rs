//! `dissect assemblies`: in how many ways the pieces of a solution tile
//! each figure (the engine's [`dissect_engine::assemblies`]).

use std::io::{IsTerminal, Write};
use std::path::PathBuf;
use std::time::{Duration, Instant};

use anyhow::Result;
use clap::Args;
use dissect_core::LatticeKind;
use dissect_engine::{AssemblyError, AssemblyEvent, TimeLimit};
use dissect_puzzle::assemblies::report_line;

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

pub fn run(args: AssembliesArgs) -> Result<Status> {
    let (_, dissection) = input::solution(&args.solution)?;
    input::check_solution_lattice(&args.solution, dissection.lattice(), args.lattice)?;
    let figures = input::figures(&args.figures, dissection.lattice())?;
    let names: Vec<String> = args.figures.iter().map(|p| input::file_name(p)).collect();
    let terminal = std::io::stderr().is_terminal();
    let mut last_line = Instant::now();
    let mut shown = false;
    let mut written: std::io::Result<()> = Ok(());
    let mut on_event = |event: AssemblyEvent<'_>| match event {
        AssemblyEvent::Progress { figure, progress } if !args.quiet => {
            let text = format!(
                "{}: {} tilings so far, about {:.0}% searched",
                names[figure],
                progress.solutions,
                100.0 * progress.done
            );
            if terminal {
                eprint!("\r\x1b[2K{text}");
                shown = true;
            } else if last_line.elapsed() >= Duration::from_secs(10) {
                eprintln!("{text}");
                last_line = Instant::now();
            }
        }
        AssemblyEvent::Counted { figure, count } => {
            if shown {
                eprint!("\r\x1b[2K");
                shown = false;
            }
            let mut out = std::io::stdout().lock();
            if written.is_ok() {
                written = writeln!(out, "{}", report_line(&names[figure], count))
                    .and_then(|()| out.flush());
            }
        }
        _ => {}
    };
    let counts = dissect_engine::assemblies(
        &dissection,
        &figures,
        args.time_limit.unwrap_or_default(),
        crate::stop::flag(),
        &mut on_event,
    );
    if shown {
        eprint!("\r\x1b[2K");
    }
    let counts = counts.map_err(|e| match (e.figure, &e.error) {
        (None, _) => anyhow::Error::from(InputError(format!("{}: {e}", args.solution.display()))),
        (Some(i), AssemblyError::Area { .. } | AssemblyError::Lattice { .. }) => {
            anyhow::Error::from(InputError(format!("{}: {e}", args.figures[i].display())))
        }
        (Some(_), _) => e.error.clone().into(),
    })?;
    written?;
    // A count cut short is still a result: say so, but do not fail.
    if counts.iter().any(|c| !c.complete) && !args.quiet {
        eprintln!(
            "note: the count stopped early (time limit or Ctrl-C); the numbers are lower bounds"
        );
    }
    Ok(Status::Ok)
}
