//! Measures `dissect_exact::enumerate` with and without its symmetry
//! breaking (BENCHMARKS.md, "Enumeration"): the model without it is the
//! enumeration as it was before the lex-leader constraints.
//!
//! ```sh
//! cargo run --release -p dissect-exact --example enumerate_count -- \
//!     [--no-mirror] [--no-symmetry-breaking] [--time-limit S] FIG.txt FIG.txt...
//! ```
//!
//! Square-lattice figures only (the benchmark's). Prints the count so far
//! every 10 s and the final count, classes, completeness and time.

use std::sync::atomic::AtomicBool;
use std::sync::Mutex;
use std::time::{Duration, Instant};

use dissect_core::io::parse_figure;
use dissect_core::LatticeKind;
use dissect_exact::{enumerate, EnumerateEvent, EnumerateObserver, EnumerateOptions};

struct Progress(Mutex<f64>);

impl EnumerateObserver for Progress {
    fn on_event(&self, event: &EnumerateEvent) {
        if let EnumerateEvent::Found {
            count,
            classes,
            seconds,
        } = event
        {
            let mut last = self.0.lock().unwrap_or_else(|e| e.into_inner());
            if *seconds >= *last + 10.0 {
                *last = *seconds;
                eprintln!("{count} so far ({classes} classes), {seconds:.1} s");
            }
        }
    }
}

fn main() -> Result<(), Box<dyn std::error::Error>> {
    let mut options = EnumerateOptions::default();
    let mut figures = Vec::new();
    let mut args = std::env::args().skip(1);
    let start = Instant::now();
    while let Some(a) = args.next() {
        match a.as_str() {
            "--no-mirror" => options.mirror = false,
            "--no-symmetry-breaking" => options.symmetry_breaking = false,
            "--time-limit" => {
                let s: f64 = args.next().ok_or("--time-limit needs seconds")?.parse()?;
                options.deadline = Some(start + Duration::from_secs_f64(s));
            }
            path => figures.push(parse_figure(
                &std::fs::read_to_string(path)?,
                LatticeKind::Square,
            )?),
        }
    }
    let stop = AtomicBool::new(false);
    let got = enumerate(&figures, &options, &stop, &Progress(Mutex::new(0.0)))?;
    println!(
        "{} dissections with {} pieces ({} classes), {}, {:.1} s, {} conflicts",
        got.dissections.len(),
        got.pieces,
        got.classes,
        if got.complete { "complete" } else { "stopped" },
        start.elapsed().as_secs_f64(),
        got.conflicts
    );
    Ok(())
}
