//! `dissect verify`.

use anyhow::Result;

use crate::args::VerifyArgs;
use crate::{input, Status};

pub fn run(args: VerifyArgs) -> Result<Status> {
    let (_, dissection) = input::solution(&args.solution)?;
    let lattice = args.lattice.unwrap_or(dissection.lattice);
    let figures = input::figures(&args.figures, lattice)?;
    input::check_equal_areas(&args.figures, &figures)?;
    match dissect_core::verify::verify(&dissection, &figures) {
        Ok(n) => {
            println!("valid: {n} pieces");
            Ok(Status::Ok)
        }
        Err(violations) => {
            for v in violations.iter().take(10) {
                println!("{v}");
            }
            if violations.len() > 10 {
                println!("... {} more", violations.len() - 10);
            }
            println!("invalid: {} problem(s)", violations.len());
            Ok(Status::NotFound)
        }
    }
}
