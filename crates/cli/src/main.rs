//! `dissect`: designs geometric dissection puzzles on lattices.

mod args;
mod assemblies;
mod certificate;
mod disassemble;
mod enumerate;
mod info;
mod input;
mod output;
mod progress;
mod prove;
#[cfg(feature = "render")]
mod render;
#[cfg(feature = "serve")]
mod serve;
mod solve;
mod stop;
mod verify;

use std::process::ExitCode;

use clap::Parser;

/// Exit status: 0 success, 1 no dissection / invalid solution, 2 bad input.
pub(crate) enum Status {
    Ok,
    NotFound,
}

/// An error caused by the user's input (exit code 2).
#[derive(Debug)]
pub(crate) struct InputError(pub String);

impl std::fmt::Display for InputError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.0)
    }
}

impl std::error::Error for InputError {}

fn main() -> ExitCode {
    let cli = args::Cli::parse();
    let result = match cli.command {
        args::Command::Solve(a) => solve::run(a),
        args::Command::Verify(a) => verify::run(a),
        args::Command::Info(a) => info::run(a),
        args::Command::Bound(a) => prove::bound(a),
        #[cfg(feature = "serve")]
        args::Command::Serve(a) => serve::run(a),
        #[cfg(feature = "render")]
        args::Command::Render(a) => render::run(a),
        #[cfg(feature = "render")]
        args::Command::Rasterize(a) => render::rasterize(a),
        #[cfg(feature = "render")]
        args::Command::Voxelize(a) => render::voxelize(a),
        args::Command::Assemblies(a) => assemblies::run(a),
        args::Command::Disassemble(a) => disassemble::run(a),
        args::Command::Enumerate(a) => enumerate::run(a),
        args::Command::CheckProof(a) => certificate::check(a),
    };
    match result {
        Ok(Status::Ok) => ExitCode::SUCCESS,
        Ok(Status::NotFound) => ExitCode::from(1),
        Err(e) => {
            eprintln!("dissect: error: {e:#}");
            if e.downcast_ref::<InputError>().is_some() {
                ExitCode::from(2)
            } else {
                ExitCode::from(3)
            }
        }
    }
}
