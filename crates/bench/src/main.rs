//! `dissect-bench`: runs the instance suite of a manifest over several seeds
//! and prints the benchmark tables (see BENCHMARKS.md).

use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::time::Duration;

use anyhow::{bail, Context, Result};
use clap::Parser;
use dissect_bench::manifest::{Instance, Manifest};
use dissect_bench::report::{self, InstanceResult, ScaleStep, Style};
use dissect_bench::run::SeedRun;
use dissect_bench::schedule::REPLAY_THREADS;
use dissect_bench::{cpu, scale, Plan};
use dissect_core::io::format_figure;
use dissect_core::solver::Options;
use dissect_core::{Dissection, Figure, LatticeKind};

/// Runs every instance of a manifest over several seeds with the dissect
/// solver, verifies every dissection, and prints a table.
#[derive(Parser, Debug)]
#[command(name = "dissect-bench", version)]
struct Args {
    /// Directory holding manifest.json and one directory per instance (the
    /// repository's `instances/` when run from its root).
    #[arg(default_value = "instances")]
    instances: PathBuf,
    /// Exactly the paper's schedule (first valid level), as `dissect solve --paper`.
    #[arg(long)]
    paper: bool,
    /// No exact lower-bound search beside the heuristic, as `dissect solve --no-prove`.
    #[arg(long)]
    no_prove: bool,
    /// Seeds, one run each.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "1,2,3",
        value_name = "N,..."
    )]
    seeds: Vec<u64>,
    /// Time limit per run in seconds (0: none) [default: 300 on 2D
    /// lattices, 600 on cubic].
    #[arg(long, value_name = "SECS")]
    time_limit: Option<f64>,
    /// Time limit per run on `cubic` instances [default: --time-limit if
    /// given, else 600].
    #[arg(long, value_name = "SECS")]
    time_limit_3d: Option<f64>,
    /// Run only these instances (manifest names).
    #[arg(long, value_delimiter = ',', value_name = "NAME,...")]
    only: Vec<String>,
    /// Run only instances on this lattice.
    #[arg(long)]
    lattice: Option<LatticeKind>,
    /// Solver worker threads (0: one per core).
    #[arg(long, default_value_t = dissect_engine::RunConfig::default().threads)]
    threads: usize,
    /// Run the scaling series instead of the suite.
    #[arg(long)]
    scaling: bool,
    /// The instance the scaling series enlarges.
    #[arg(
        long,
        default_value = "rect15x10-hole-to-square12",
        value_name = "NAME"
    )]
    scale_instance: String,
    /// The factors of the scaling series.
    #[arg(
        long,
        value_delimiter = ',',
        default_value = "1,2,4,8",
        value_name = "K,..."
    )]
    scale_factors: Vec<u32>,
    /// Print the tables as Markdown.
    #[arg(long)]
    markdown: bool,
    /// Also print one row per run.
    #[arg(long)]
    per_seed: bool,
    /// Write every dissection found (and scaled figures) to this directory.
    #[arg(long, value_name = "DIR")]
    save: Option<PathBuf>,
    /// Do not turn 2D pieces over.
    #[arg(long)]
    no_mirror: bool,
    /// Give up after levels with this many pieces.
    #[arg(long, value_name = "K")]
    max_pieces: Option<usize>,
    /// λ at level 1 (0 turns the area term off).
    #[arg(long, value_name = "X")]
    area_weight: Option<f64>,
    /// Explorations per level, N.
    #[arg(long, value_name = "N")]
    explorations: Option<usize>,
    /// Candidates kept per level, Nb.
    #[arg(long, value_name = "NB")]
    keep: Option<usize>,
    /// Refinement iterations per exploration, R.
    #[arg(long, value_name = "R")]
    iterations: Option<usize>,
    /// Objective penalty per disconnected piece.
    #[arg(long, value_name = "X")]
    split_penalty: Option<f64>,
    /// Level-1 runs tried when splitting the worst pair.
    #[arg(long, value_name = "N")]
    split_tries: Option<usize>,
    /// Run every exploration of the final level.
    #[arg(long)]
    full_level: bool,
    /// Refinement patience (0: the paper's loop).
    #[arg(long, value_name = "N")]
    patience: Option<usize>,
    /// Extra rounds of explorations for near-miss levels (0: the paper's schedule).
    #[arg(long, value_name = "N")]
    extra_rounds: Option<usize>,
    /// Record every exploration's time (thread CPU) and replay each run's
    /// levels on 1, 2, 4, 8 and 16 simulated threads, with a barrier after
    /// every batch and without: makespan, speed-up and waiting fraction.
    /// Records on one solver thread (--threads 1, the default here).
    #[arg(long)]
    replay: bool,
}

fn main() -> ExitCode {
    match run(Args::parse()) {
        Ok(true) => ExitCode::SUCCESS,
        Ok(false) => ExitCode::from(1),
        Err(e) => {
            eprintln!("dissect-bench: error: {e:#}");
            ExitCode::from(2)
        }
    }
}

/// Runs the benchmark; `Ok(false)` when a dissection failed verification.
fn run(args: Args) -> Result<bool> {
    let plan = plan(&args)?;
    let manifest = Manifest::load(&args.instances)?;
    let style = if args.markdown {
        Style::Markdown
    } else {
        Style::Text
    };
    if let Some(dir) = &args.save {
        std::fs::create_dir_all(dir)
            .with_context(|| format!("{}: cannot create directory", dir.display()))?;
    }
    println!("{}", settings(&plan, style));
    let load_before = cpu::load_average();
    if args.scaling {
        let instance = manifest.get(&args.scale_instance)?;
        let figures = instance.load_figures(manifest.root())?;
        let steps = plan.run_scaling(&figures, &args.scale_factors, |k, r| {
            eprintln!("{}", progress(&format!("{} ×{k}", instance.name), r));
        })?;
        if let Some(dir) = &args.save {
            save_scaled(dir, instance, &figures, &steps, &plan.options)?;
        }
        let what = format!(
            "Scaling series: {} ({} cells at k = 1), every cell a k×k{} block",
            instance.name,
            figures[0].len(),
            if instance.lattice() == LatticeKind::Cubic {
                "×k"
            } else {
                ""
            }
        );
        println!("{}", heading(&what, style));
        print!("{}", report::scale_table(&steps, style));
        for s in &steps {
            let name = format!("{} ×{}", instance.name, s.k);
            print_replays(&name, &s.runs, plan.options.batch, style);
        }
        println!("\n{}", load_note(load_before, cpu::load_average()));
        return Ok(!steps.iter().flat_map(|s| &s.runs).any(SeedRun::is_error));
    }

    let selected = select(&manifest, &args)?;
    let mut results: Vec<InstanceResult> = Vec::new();
    for instance in selected {
        let result = plan.run_instance(manifest.root(), instance, |r| {
            eprintln!("{}", progress(&instance.name, r));
        })?;
        if let Some(dir) = &args.save {
            save(dir, &instance.name, instance, &result.runs, &plan.options)?;
        }
        results.push(result);
    }
    println!("{}", heading("Suite", style));
    print!("{}", report::suite_table(&results, style));
    if args.per_seed {
        println!("\n{}", heading("Every run", style));
        print!("{}", report::seed_table(&results, style));
    }
    for r in &results {
        print_replays(&r.name, &r.runs, plan.options.batch, style);
    }
    println!("\n{}", load_note(load_before, cpu::load_average()));
    let errors: Vec<String> = results
        .iter()
        .flat_map(|r| r.runs.iter().map(move |s| (r, s)))
        .filter_map(|(r, s)| Some(format!("{} seed {}: {}", r.name, s.seed, s.error.as_ref()?)))
        .collect();
    for e in &errors {
        eprintln!("dissect-bench: {e}");
    }
    Ok(errors.is_empty())
}

fn plan(args: &Args) -> Result<Plan> {
    let limit = |secs: f64, flag: &str| -> Result<Option<Duration>> {
        if !(secs.is_finite() && secs >= 0.0) {
            bail!("{flag} must be a number of seconds >= 0, got {secs}");
        }
        Ok((secs > 0.0).then(|| Duration::from_secs_f64(secs)))
    };
    if args.seeds.is_empty() {
        bail!("--seeds needs at least one seed");
    }
    if let Some(w) = args.area_weight {
        if !(w.is_finite() && w >= 0.0) {
            bail!("--area-weight must be >= 0, got {w}");
        }
    }
    if args.replay && args.threads > 1 {
        bail!("--replay records exploration times on one solver thread: leave --threads out or give 1");
    }
    let d = Options::default();
    let options = Options {
        mirror: !args.no_mirror,
        threads: if args.replay { 1 } else { args.threads },
        max_pieces: args.max_pieces,
        area_weight: args.area_weight.unwrap_or(d.area_weight),
        explorations: args.explorations.unwrap_or(d.explorations),
        keep: args.keep.unwrap_or(d.keep),
        iterations: args.iterations.unwrap_or(d.iterations),
        split_penalty: args.split_penalty.unwrap_or(d.split_penalty),
        split_tries: args.split_tries.unwrap_or(d.split_tries),
        full_levels: args.full_level || d.full_levels,
        patience: args.patience.unwrap_or(d.patience),
        extra_rounds: args.extra_rounds.unwrap_or(d.extra_rounds),
        ..d
    };
    Ok(Plan {
        seeds: args.seeds.clone(),
        options,
        time_limit_2d: limit(args.time_limit.unwrap_or(300.0), "--time-limit")?,
        time_limit_3d: limit(
            args.time_limit_3d.or(args.time_limit).unwrap_or(600.0),
            "--time-limit-3d",
        )?,
        mode: dissect_bench::run::Mode {
            strategy: if args.paper {
                dissect_engine::Strategy::Paper
            } else {
                dissect_engine::Strategy::Anytime
            },
            prove: !args.no_prove,
            record: args.replay,
        },
    })
}

fn select<'m>(manifest: &'m Manifest, args: &Args) -> Result<Vec<&'m Instance>> {
    let mut out: Vec<&Instance> = if args.only.is_empty() {
        manifest.instances().iter().collect()
    } else {
        args.only
            .iter()
            .map(|n| manifest.get(n))
            .collect::<Result<_, _>>()?
    };
    if let Some(l) = args.lattice {
        out.retain(|i| i.lattice() == l);
    }
    if out.is_empty() {
        bail!("no instance selected (check --only and --lattice)");
    }
    Ok(out)
}

/// A line saying how the runs were made.
fn settings(plan: &Plan, style: Style) -> String {
    let o = &plan.options;
    let limit =
        |l: Option<Duration>| l.map_or("none".to_string(), |d| format!("{} s", report::secs(d)));
    let seeds: Vec<String> = plan.seeds.iter().map(|s| s.to_string()).collect();
    let text = format!(
        "seeds {}; time limit {} (2D), {} (3D); threads {}; N = {}, R = {}, Nb = {}, area weight {}, mirror {}, patience {}, extra rounds {}",
        seeds.join(","),
        limit(plan.time_limit_2d),
        limit(plan.time_limit_3d),
        if o.threads == 0 {
            "all cores".to_string()
        } else {
            o.threads.to_string()
        },
        o.explorations,
        o.iterations,
        o.keep,
        o.area_weight,
        o.mirror,
        o.patience,
        o.extra_rounds,
    );
    match style {
        Style::Markdown => format!("Settings: {text}.\n"),
        Style::Text => format!("dissect-bench: {text}\n"),
    }
}

/// The machine's load average before and after the runs: above the number
/// of solver threads, other jobs shared the CPU.
fn load_note(before: Option<[f64; 3]>, after: Option<[f64; 3]>) -> String {
    let show = |l: Option<[f64; 3]>| {
        l.map_or("unknown".to_string(), |l| {
            format!("{:.2} / {:.2} / {:.2}", l[0], l[1], l[2])
        })
    };
    format!(
        "Load average (1 / 5 / 15 min) before the runs: {}; after: {}; cores: {}.",
        show(before),
        show(after),
        std::thread::available_parallelism().map_or(0, |n| n.get())
    )
}

fn heading(text: &str, style: Style) -> String {
    match style {
        Style::Markdown => format!("#### {text}\n"),
        Style::Text => format!("{text}\n"),
    }
}

/// The schedule replay of every run that recorded its explorations.
fn print_replays(name: &str, runs: &[SeedRun], batch: usize, style: Style) {
    for r in runs {
        let Some(rec) = &r.recording else { continue };
        let what = format!(
            "Schedule replay: {name} seed {} (levels {}, explorations {}, exploration work {:.2} s of {}; the run's CPU {} s)",
            r.seed,
            rec.levels.len(),
            rec.explorations(),
            rec.work(),
            rec.clock,
            r.cpu.map_or("-".to_string(), report::secs),
        );
        println!("\n{}", heading(&what, style));
        print!(
            "{}",
            report::replay_table(rec, batch, &REPLAY_THREADS, style)
        );
    }
}

/// A progress line for one finished run.
fn progress(what: &str, r: &SeedRun) -> String {
    let head = format!("{what} seed {}:", r.seed);
    if let Some(e) = &r.error {
        return format!("{head} {e}");
    }
    match r.pieces {
        Some(p) => format!(
            "{head} {p} pieces{}, first valid {} s, best {} s, total {} s (CPU {} s, peak RSS {} MiB), area variance {:.1}",
            match r.lower_bound {
                Some(b) if r.optimal => format!(" (optimal: lower bound {b})"),
                Some(b) => format!(" (lower bound {b})"),
                None => String::new(),
            },
            r.first_valid.map_or("-".to_string(), report::secs),
            r.time_to_best.map_or("-".to_string(), report::secs),
            report::secs(r.total),
            r.cpu.map_or("-".to_string(), report::secs),
            report::max_rss(std::slice::from_ref(r)),
            r.variance.unwrap_or(f64::NAN),
        ),
        None => format!(
            "{head} no dissection after {} s ({}; best {}-piece E_M = {})",
            report::secs(r.total),
            if r.stopped { "time limit" } else { "gave up" },
            r.last_level.0,
            r.last_level.1.map_or("n/a".to_string(), |m| m.to_string()),
        ),
    }
}

/// Writes each run's dissection as `DIR/<stem>-seed<N>.json`.
fn save(
    dir: &Path,
    stem: &str,
    instance: &Instance,
    runs: &[SeedRun],
    options: &Options,
) -> Result<()> {
    for r in runs {
        let Some(found) = &r.found else { continue };
        let d = Dissection::new(
            instance.lattice(),
            options.mirror,
            instance.files.clone(),
            found.pieces.clone(),
        )?;
        let mut extra = serde_json::Map::new();
        extra.insert("seed".into(), r.seed.into());
        extra.insert("seconds".into(), r.total.as_secs_f64().into());
        let path = dir.join(format!("{stem}-seed{}.json", r.seed));
        std::fs::write(&path, d.to_file(extra).to_json())
            .with_context(|| format!("{}: cannot write", path.display()))?;
    }
    Ok(())
}

/// Writes the scaled figures as `DIR/<name>-x<k>/<file>` and their
/// dissections as `DIR/<name>-x<k>-seed<N>.json`.
fn save_scaled(
    dir: &Path,
    instance: &Instance,
    figures: &[Figure],
    steps: &[ScaleStep],
    options: &Options,
) -> Result<()> {
    for s in steps {
        let stem = format!("{}-x{}", instance.name, s.k);
        let fig_dir = dir.join(&stem);
        std::fs::create_dir_all(&fig_dir)
            .with_context(|| format!("{}: cannot create directory", fig_dir.display()))?;
        for (file, f) in instance.files.iter().zip(figures) {
            let path = fig_dir.join(file);
            std::fs::write(&path, format_figure(&scale::scale(f, s.k)?))
                .with_context(|| format!("{}: cannot write", path.display()))?;
        }
        save(dir, &stem, instance, &s.runs, options)?;
    }
    Ok(())
}
