//! `dissect disassemble`: a plan of straight moves that takes each figure
//! of a solution apart, or why there is none (the engine's
//! [`dissect_engine::disassemble()`]).

use std::io::Write;
use std::path::PathBuf;

use anyhow::Result;
use clap::Args;
use dissect_core::LatticeKind;
use dissect_engine::{Disassembly, DisassemblyError, TimeLimit};
use dissect_puzzle::disassembly::{outcome_line, plan_json};

use crate::{input, output, InputError, Status};

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct DisassembleArgs {
    /// The lattice (default: the solution's).
    #[arg(long)]
    pub lattice: Option<LatticeKind>,
    /// The solution JSON whose figures are taken apart (pieces start where it places them).
    #[arg(long, value_name = "S.json")]
    pub solution: PathBuf,
    /// Write the plans here (format dissection-disassembly/1).
    #[arg(short = 'o', long = "output", value_name = "PLAN.json")]
    pub output: Option<PathBuf>,
    /// Stop after this many seconds in all; figures not decided by then say so.
    #[arg(long, value_name = "SECS")]
    pub time_limit: Option<TimeLimit>,
    /// Print nothing but the result lines and errors.
    #[arg(long, short)]
    pub quiet: bool,
    /// The figures, in the solution's order.
    #[arg(required = true, num_args = 1.., value_name = "FIGURE")]
    pub figures: Vec<PathBuf>,
}

pub fn run(args: DisassembleArgs) -> Result<Status> {
    let (_, dissection) = input::solution(&args.solution)?;
    input::check_solution_lattice(&args.solution, dissection.lattice(), args.lattice)?;
    let lattice = dissection.lattice();
    let time_limit = args.time_limit.unwrap_or_default();
    if let Some(path) = &args.output {
        input::check_writable(path)?;
    }
    let figures = input::figures(&args.figures, lattice)?;
    if let Err(violations) = dissect_core::verify::verify(&dissection, &figures) {
        let first = violations
            .first()
            .map_or_else(|| "rejected".to_string(), |v| v.to_string());
        return Err(InputError(format!(
            "{}: not a dissection of the figures given: {first}",
            args.solution.display()
        ))
        .into());
    }
    let names: Vec<String> = args.figures.iter().map(|p| input::file_name(p)).collect();
    let flat = lattice.lattice().dim() < 3;
    let outcomes = dissect_engine::disassemble(
        &dissection,
        time_limit,
        Some(crate::stop::flag()),
        |f, outcome| {
            let mut out = std::io::stdout().lock();
            _ = writeln!(out, "{}", outcome_line(&names[f], outcome));
            _ = out.flush();
        },
    )
    .map_err(|e| match e {
        DisassemblyError::TooManyPieces { .. } => {
            anyhow::Error::from(InputError(format!("{}: {e}", args.solution.display())))
        }
        other => other.into(),
    })?;
    if flat && !args.quiet {
        eprintln!("note: {lattice} figures are flat: every piece lifts off the table (level 1)");
    }
    if let Some(path) = &args.output {
        let figures: Vec<(&str, &Disassembly)> =
            names.iter().map(String::as_str).zip(&outcomes).collect();
        output::write_atomic(path, plan_json(lattice, &figures))?;
    }
    let all_apart = outcomes.iter().all(|o| matches!(o, Disassembly::Apart(_)));
    Ok(if all_apart {
        Status::Ok
    } else {
        Status::NotFound
    })
}
