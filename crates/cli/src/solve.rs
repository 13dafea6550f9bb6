//! `dissect solve`.

use std::io::IsTerminal;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Condvar, Mutex};
use std::time::{Duration, Instant};

use anyhow::Result;
use dissect_core::io::Dissection;
use dissect_core::solver::solve;
use serde_json::{json, Map, Value};

use crate::args::SolveArgs;
use crate::progress::{self, Progress};
use crate::{input, InputError, Status};

/// Raised by the time limit and by Ctrl-C.
static STOP: AtomicBool = AtomicBool::new(false);
/// Raised by Ctrl-C (SIGINT, or SIGTERM) only.
static INTERRUPTED: AtomicBool = AtomicBool::new(false);

pub fn run(args: SolveArgs) -> Result<Status> {
    if args.prove || args.exact {
        return crate::prove::solve_exact(args);
    }
    let figures = input::figures(&args.figures, args.lattice)?;
    input::check_equal_areas(&args.figures, &figures)?;
    if let Some(t) = args.time_limit {
        // `inf` is allowed: no limit.
        if t.is_nan() || t < 0.0 {
            return Err(InputError(format!(
                "--time-limit must be a number of seconds >= 0, got {t}"
            ))
            .into());
        }
    }
    if !(args.area_weight.is_finite() && args.area_weight >= 0.0) {
        return Err(InputError(format!(
            "--area-weight must be >= 0, got {}",
            args.area_weight
        ))
        .into());
    }
    if let Some(out) = &args.output {
        input::check_writable(out)?;
    }
    let lattice = args.lattice.lattice();
    let mirror = !args.no_mirror && lattice.supports_mirror();
    let options = args.solver_options(args.threads);

    // Ctrl-C: the first stops the search (the best result is kept), a
    // second one exits at once.
    let _ = ctrlc::set_handler(|| {
        INTERRUPTED.store(true, Ordering::SeqCst);
        if STOP.swap(true, Ordering::SeqCst) {
            std::process::exit(130);
        }
    });
    let start = Instant::now();
    if args.time_limit == Some(0.0) {
        // No time at all: stop before the timer thread would have started.
        STOP.store(true, Ordering::SeqCst);
    }
    let finished = Arc::new((Mutex::new(false), Condvar::new()));
    // A limit too far away to be a point in time is no limit.
    let deadline = args.time_limit.and_then(|secs| {
        Duration::try_from_secs_f64(secs)
            .ok()
            .and_then(|d| start.checked_add(d))
    });
    let timer = deadline.map(|deadline| {
        let finished = Arc::clone(&finished);
        std::thread::spawn(move || {
            let (lock, cv) = &*finished;
            let mut done = lock.lock().expect("timer lock");
            while !*done {
                let now = Instant::now();
                if now >= deadline {
                    STOP.store(true, Ordering::SeqCst);
                    return;
                }
                done = cv.wait_timeout(done, deadline - now).expect("timer lock").0;
            }
        })
    });

    let progress = Progress::new(args.quiet);
    let outcome = solve(&figures, &options, &STOP, &progress);
    progress.finish();
    {
        let (lock, cv) = &*finished;
        *lock.lock().expect("timer lock") = true;
        cv.notify_all();
    }
    if let Some(t) = timer {
        let _ = t.join();
    }
    let outcome = outcome.map_err(|e| InputError(e.to_string()))?;
    let elapsed = start.elapsed().as_secs_f64();

    let Some(found) = outcome.found else {
        let why = if INTERRUPTED.load(Ordering::SeqCst) {
            "interrupted (Ctrl-C)".to_string()
        } else if outcome.stopped {
            format!(
                "the time limit of {} s was reached",
                args.time_limit.unwrap_or_default()
            )
        } else {
            match args.max_pieces {
                Some(k) => format!("--max-pieces {k} was reached"),
                None => "every piece count was tried".to_string(),
            }
        };
        progress::stderr_line(&format!(
            "no dissection found: {why} after {elapsed:.1} s; the best candidate ({}) had matching score E_M = {}",
            plural(outcome.last_pieces, "piece"),
            outcome.best_mismatch.map_or("n/a".to_string(), |m| m.to_string()),
        ));
        return Ok(Status::NotFound);
    };

    let dissection = Dissection {
        lattice: args.lattice,
        mirror,
        names: args.figures.iter().map(|p| input::file_name(p)).collect(),
        pieces: found.pieces.clone(),
    };
    // Never hand out an answer that the independent verifier rejects.
    if let Err(v) = dissect_core::verify::verify(&dissection, &figures) {
        anyhow::bail!(
            "internal error: the solver's dissection failed verification: {}",
            v[0]
        );
    }

    // The solution file first: whatever happens next (a closed stdout, a
    // failed rendering), the run is not lost.
    let mut written = Ok(());
    if let Some(out) = &args.output {
        let mut extra = Map::new();
        extra.insert("pieces".into(), json!(found.piece_count()));
        extra.insert("areas".into(), json!(found.areas()));
        extra.insert("area_variance".into(), json!(found.variance));
        extra.insert("seed".into(), json!(args.seed));
        extra.insert("seconds".into(), json!((elapsed * 1000.0).round() / 1000.0));
        extra.insert("level".into(), json!(found.level));
        extra.insert("explorations".into(), json!(outcome.explorations));
        extra.insert("stopped_early".into(), Value::Bool(outcome.stopped));
        let text = dissection.to_file(extra).to_json();
        if let Err(e) = std::fs::write(out, &text) {
            // The solution goes to stdout instead.
            progress::stdout(&text);
            written = Err(InputError(format!(
                "{}: cannot write: {e} (the solution was printed on stdout instead)",
                out.display()
            )));
        }
    }

    if !args.quiet {
        let colour = match args.color.as_str() {
            "always" => true,
            "never" => false,
            _ => std::io::stdout().is_terminal(),
        };
        let mut text = String::new();
        for (path, pieces) in args.figures.iter().zip(&found.pieces) {
            text += &format!(
                "{}:\n{}\n",
                path.display(),
                dissect_core::ascii::draw(args.lattice, pieces, colour)
            );
        }
        let list: Vec<String> = found
            .areas()
            .iter()
            .enumerate()
            .map(|(i, a)| format!("{}={a}", dissect_core::ascii::piece_letter(i)))
            .collect();
        text += &format!(
            "{}\npiece areas: {}\narea variance: {:.2}\ntime: {elapsed:.2} s{}\n",
            plural(found.piece_count(), "piece"),
            list.join(" "),
            found.variance,
            if INTERRUPTED.load(Ordering::SeqCst) {
                " (interrupted; best found so far)"
            } else if outcome.stopped {
                " (time limit reached; best found so far)"
            } else {
                ""
            }
        );
        progress::stdout(&text);
    }
    written?;

    #[cfg(feature = "render")]
    if let Some(dir) = &args.render {
        crate::render::write_views(dir, &dissection)?;
    }
    Ok(Status::Ok)
}

/// `1 piece`, `2 pieces`.
fn plural(n: usize, word: &str) -> String {
    format!("{n} {word}{}", if n == 1 { "" } else { "s" })
}
