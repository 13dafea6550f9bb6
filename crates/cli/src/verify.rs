//! `dissect verify`.

use std::fmt::Write;

use anyhow::Result;
use dissect_core::verify::Violation;

use crate::args::VerifyArgs;
use crate::{input, progress, Status};

pub fn run(args: VerifyArgs) -> Result<Status> {
    let (_, dissection) = input::solution(&args.solution)?;
    input::check_solution_lattice(&args.solution, dissection.lattice(), args.lattice)?;
    let lattice = dissection.lattice();
    let figures = input::figures(&args.figures, lattice)?;
    input::check_equal_areas(&args.figures, &figures)?;
    let mut out = String::new();
    let status = match dissect_core::verify::verify(&dissection, &figures) {
        Ok(n) => {
            _ = writeln!(out, "valid: {n} piece{}", if n == 1 { "" } else { "s" });
            Ok(Status::Ok)
        }
        Err(violations) => {
            for v in violations.iter().take(10) {
                match figure_of(v).and_then(|f| args.figures.get(f)) {
                    Some(path) => _ = writeln!(out, "{}: {v}", path.display()),
                    None => _ = writeln!(out, "{v}"),
                }
            }
            if violations.len() > 10 {
                _ = writeln!(out, "... {} more", violations.len() - 10);
            }
            let given: Vec<String> = args.figures.iter().map(|p| input::file_name(p)).collect();
            if dissection.names().iter().all(|n| !n.is_empty())
                && dissection.names() != given
                && dissection.names().len() == given.len()
            {
                _ = writeln!(
                    out,
                    "note: the solution lists the figures {}; they were given as {}",
                    dissection.names().join(", "),
                    given.join(", ")
                );
            }
            _ = writeln!(
                out,
                "invalid: {} problem{}",
                violations.len(),
                if violations.len() == 1 { "" } else { "s" }
            );
            Ok(Status::NotFound)
        }
    };
    progress::stdout(&out);
    status
}

/// The index of the figure a violation is about, if it is about one.
fn figure_of(v: &Violation) -> Option<usize> {
    match v {
        Violation::EmptyPiece { figure, .. }
        | Violation::Overlap { figure, .. }
        | Violation::OutsideFigure { figure, .. }
        | Violation::Uncovered { figure, .. }
        | Violation::Disconnected { figure, .. }
        | Violation::NotCongruent { figure, .. } => Some(*figure),
        _ => None,
    }
}
