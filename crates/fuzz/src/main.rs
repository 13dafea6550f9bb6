//! `dissect-fuzz [--inputs N] [--seconds S] [--seed X] [--target NAME]... [--out DIR]`:
//! feeds mutated inputs to every parser (see the library) and prints, per
//! target, the inputs tried, how many were accepted and the panics found
//! (each saved under DIR, default `fuzz-failures/`). Exit code 1 when
//! anything panicked. Without --inputs and --seconds: 10,000 inputs each.

use std::time::{Duration, Instant};

use dissect_fuzz::{Target, TARGETS};

fn main() -> std::process::ExitCode {
    let mut inputs: Option<u64> = None;
    let mut seconds: Option<f64> = None;
    let mut seed = 1u64;
    let mut names: Vec<String> = Vec::new();
    let mut out = std::path::PathBuf::from("fuzz-failures");
    let mut args = std::env::args().skip(1);
    while let Some(a) = args.next() {
        let mut value = |what: &str| {
            args.next().unwrap_or_else(|| {
                eprintln!("dissect-fuzz: {a} needs {what}");
                std::process::exit(2)
            })
        };
        let number = |s: String| -> f64 {
            s.parse().unwrap_or_else(|_| {
                eprintln!("dissect-fuzz: {s:?} is not a number");
                std::process::exit(2)
            })
        };
        match a.as_str() {
            "--inputs" => inputs = Some(number(value("a count")) as u64),
            "--seconds" => seconds = Some(number(value("seconds"))),
            "--seed" => seed = number(value("a seed")) as u64,
            "--target" => names.push(value("a target")),
            "--out" => out = value("a folder").into(),
            _ => {
                eprintln!(
                    "dissect-fuzz: unknown argument {a:?} (targets: {})",
                    TARGETS.join(", ")
                );
                return std::process::ExitCode::from(2);
            }
        }
    }
    if names.is_empty() {
        names = TARGETS.iter().map(|s| s.to_string()).collect();
    }
    let per_target = seconds.map(|s| Duration::from_secs_f64(s / names.len() as f64));
    let budget = inputs.unwrap_or(if seconds.is_some() { u64::MAX } else { 10_000 });
    let mut failed = false;
    let mut total = 0u64;
    println!("| target | inputs | accepted | panics | time |");
    println!("|---|---|---|---|---|");
    // Panics are caught and counted; their default report would flood stderr.
    std::panic::set_hook(Box::new(|_| {}));
    for name in &names {
        let Some(mut t) = Target::new(name) else {
            eprintln!(
                "dissect-fuzz: unknown target {name:?} (targets: {})",
                TARGETS.join(", ")
            );
            return std::process::ExitCode::from(2);
        };
        let deadline = per_target.map(|d| Instant::now() + d);
        let tally = t.fuzz(seed, budget, deadline);
        total += tally.inputs;
        println!(
            "| {} | {} | {} | {} | {:.1} s |",
            tally.target,
            tally.inputs,
            tally.accepted,
            tally.failures.len(),
            tally.elapsed.as_secs_f64()
        );
        for (i, (input, msg)) in tally.failures.iter().enumerate().take(20) {
            failed = true;
            let _ = std::fs::create_dir_all(&out);
            let path = out.join(format!("{name}-{i}.bin"));
            let _ = std::fs::write(&path, input);
            eprintln!(
                "dissect-fuzz: {name}: panic {msg:?}; input saved as {}",
                path.display()
            );
        }
        failed |= !tally.failures.is_empty();
    }
    println!("total: {total} inputs, seed {seed}");
    if failed {
        std::process::ExitCode::from(1)
    } else {
        std::process::ExitCode::SUCCESS
    }
}
