//! The smallest use of the library: read figures, solve, verify, print.
//!
//! `cargo run --release -p dissect-core --example solve -- [--lattice L]
//! [--seed N] [--threads N] [--explorations N] [--iterations R]
//! [--max-pieces K] FIGURE FIGURE...`

use std::sync::atomic::AtomicBool;
use std::time::Instant;

use dissect_core::io::parse_figure;
use dissect_core::solver::{solve, Options};
use dissect_core::LatticeKind;

fn main() {
    let mut args = std::env::args().skip(1);
    let mut lattice = LatticeKind::Square;
    let mut options = Options::default();
    let mut paths = Vec::new();
    while let Some(a) = args.next() {
        let mut value = || args.next().expect("flag needs a value");
        match a.as_str() {
            "--lattice" => lattice = value().parse().expect("lattice"),
            "--seed" => options.seed = value().parse().expect("seed"),
            "--threads" => options.threads = value().parse().expect("threads"),
            "--explorations" => options.explorations = value().parse().expect("explorations"),
            "--iterations" => options.iterations = value().parse().expect("iterations"),
            "--max-pieces" => options.max_pieces = Some(value().parse().expect("max pieces")),
            "--patience" => options.patience = value().parse().expect("patience"),
            "--extra-rounds" => options.extra_rounds = value().parse().expect("extra rounds"),
            _ => paths.push(a),
        }
    }
    let figures: Vec<_> = paths
        .iter()
        .map(|p| {
            let text = std::fs::read_to_string(p).expect("readable figure");
            parse_figure(&text, lattice).unwrap_or_else(|e| panic!("{p}: {e}"))
        })
        .collect();
    let start = Instant::now();
    let outcome = solve(&figures, &options, &AtomicBool::new(false), &()).expect("solvable input");
    let secs = start.elapsed().as_secs_f64();
    match outcome.found {
        Some(found) => {
            let pieces = dissect_core::verify::verify_pieces(
                lattice,
                options.mirror,
                &figures,
                &found.pieces,
            )
            .expect("the solver's answer verifies");
            println!(
                "{pieces} pieces in {secs:.2} s ({} explorations)",
                outcome.explorations
            );
        }
        None => println!(
            "none within {} pieces in {secs:.2} s (best E_M {:?})",
            outcome.last_pieces, outcome.best_mismatch
        ),
    }
}
