//! `dissect-fuzz [--inputs N] [--seconds S] [--seed X] [--target NAME]... [--out DIR] [--jobs J]`:
//! feeds mutated inputs to every parser (see the library) and prints, per
//! target, the inputs tried, how many were accepted and the panics found
//! (each saved under DIR, default `fuzz-failures/`). Exit code 1 when
//! anything panicked. Without --inputs and --seconds: 10,000 inputs each.
//! `--jobs J` fuzzes J targets at once (one thread each); the seconds are
//! shared out so that the run still takes about S.

use std::sync::Mutex;
use std::time::{Duration, Instant};

use dissect_fuzz::{Tally, Target, TARGETS};

/// Fuzzes `names` on `jobs` threads: each target's tally, in `names` order.
fn fuzz_all(
    names: &[String],
    jobs: usize,
    seed: u64,
    budget: u64,
    per_target: Option<Duration>,
) -> Vec<Tally> {
    let next = Mutex::new(0usize);
    let tallies = Mutex::new(vec![Tally::default(); names.len()]);
    std::thread::scope(|scope| {
        for _ in 0..jobs.clamp(1, names.len().max(1)) {
            scope.spawn(|| loop {
                let i = {
                    let mut n = next.lock().unwrap_or_else(|e| e.into_inner());
                    *n += 1;
                    *n - 1
                };
                let Some(name) = names.get(i) else { break };
                let Some(mut t) = Target::new(name) else {
                    break;
                };
                let deadline = per_target.map(|d| Instant::now() + d);
                let tally = t.fuzz(seed, budget, deadline);
                tallies.lock().unwrap_or_else(|e| e.into_inner())[i] = tally;
            });
        }
    });
    tallies.into_inner().unwrap_or_else(|e| e.into_inner())
}

fn main() -> std::process::ExitCode {
    let mut inputs: Option<u64> = None;
    let mut seconds: Option<f64> = None;
    let mut seed = 1u64;
    let mut names: Vec<String> = Vec::new();
    let mut out = std::path::PathBuf::from("fuzz-failures");
    let mut jobs = 1usize;
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
            "--jobs" => jobs = (number(value("a count")) as usize).max(1),
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
    if let Some(name) = names.iter().find(|n| !TARGETS.contains(&n.as_str())) {
        eprintln!(
            "dissect-fuzz: unknown target {name:?} (targets: {})",
            TARGETS.join(", ")
        );
        return std::process::ExitCode::from(2);
    }
    // The targets run `jobs` at a time: each gets its share of the seconds.
    let rounds = names.len().div_ceil(jobs.min(names.len()).max(1));
    let per_target = seconds.map(|s| Duration::from_secs_f64(s / rounds as f64));
    let budget = inputs.unwrap_or(if seconds.is_some() { u64::MAX } else { 10_000 });
    let mut failed = false;
    let mut total = 0u64;
    println!("| target | inputs | accepted | panics | time |");
    println!("|---|---|---|---|---|");
    // Panics are caught and counted; their default report would flood stderr.
    std::panic::set_hook(Box::new(|_| {}));
    let tallies = fuzz_all(&names, jobs, seed, budget, per_target);
    for (name, tally) in names.iter().zip(tallies) {
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
