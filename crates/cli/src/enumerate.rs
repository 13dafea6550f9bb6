//! `dissect enumerate`: every dissection with the fewest pieces (or with
//! `--pieces K`), counted by `dissect_engine::enumerate`. The last line is
//! `N dissections with K pieces (M up to the first figure's symmetries),
//! complete` (or `at least N ..., stopped`); with `-o DIR` one verified
//! solution file per class, `DIR/1.json`, `DIR/2.json`, ...

use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::Mutex;
use std::time::{Duration, Instant};

use anyhow::Result;
use clap::Args;
use dissect_core::LatticeKind;
use dissect_engine::{
    EngineError, EnumerateConfig, EnumerateEvent, EnumerateObserver, EnumerationReport, Rank,
    TimeLimit,
};
use serde_json::{json, Map};

use crate::args::whole_usize;
use crate::progress;
use crate::{input, InputError, Status};

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct EnumerateArgs {
    /// The lattice: square, tri4, cubic, tri3 or hex.
    #[arg(long, default_value_t = LatticeKind::Square)]
    pub lattice: LatticeKind,
    /// Do not turn 2D pieces over (and count reflections of the first figure as different).
    #[arg(long)]
    pub no_mirror: bool,
    /// Count the dissections with exactly K pieces (default: the minimum, proved first).
    #[arg(long, value_name = "K", value_parser = whole_usize::<1>)]
    pub pieces: Option<usize>,
    /// Stop after this many seconds and report the dissections found so far.
    #[arg(long, value_name = "SECS")]
    pub time_limit: Option<TimeLimit>,
    /// Write one solution file per class up to symmetry: DIR/1.json, DIR/2.json, ... (DIR is created if missing).
    #[arg(short = 'o', long = "output", value_name = "DIR")]
    pub output: Option<PathBuf>,
    /// Order the classes by: variance, smallest, shapes, symmetry, unique (default: the order found).
    #[arg(long, value_name = "CRITERION", value_parser = rank)]
    pub rank: Option<Rank>,
    /// Keep only dissections whose pieces tile every figure in a single way up to its symmetries.
    #[arg(long)]
    pub unique: bool,
    /// Print nothing but errors and the last line.
    #[arg(long, short)]
    pub quiet: bool,
    /// The figures (text files, see FORMAT.md); classes are up to the first one's symmetries.
    #[arg(required = true, num_args = 2.., value_name = "FIGURE")]
    pub figures: Vec<PathBuf>,
}

fn rank(s: &str) -> Result<Rank, String> {
    s.parse()
        .map_err(|e: dissect_puzzle::scores::UnknownRank| e.to_string())
}

/// Progress on stderr: a line rewritten in place on a terminal, a line
/// every ten seconds otherwise, nothing with `--quiet`.
struct Display {
    quiet: bool,
    terminal: bool,
    start: Instant,
    /// When the last plain line was written, and whether a terminal line
    /// is showing.
    state: Mutex<(Instant, bool)>,
}

impl Display {
    fn clear(&self) {
        let mut state = self.state.lock().expect("display lock");
        if state.1 {
            eprint!("\r\x1b[2K");
            state.1 = false;
        }
    }

    fn line(&self, text: &str) {
        self.clear();
        progress::stderr_line(text);
    }
}

impl EnumerateObserver for Display {
    fn on_event(&self, event: &EnumerateEvent) {
        if self.quiet {
            return;
        }
        match event {
            EnumerateEvent::Minimum { pieces, seconds } => self.line(&format!(
                "minimum: {pieces} pieces (proved at {seconds:.1} s); counting every dissection with {pieces} pieces"
            )),
            EnumerateEvent::Search(dissect_exact::ExactEvent::Refuted(b)) => self.line(&format!(
                "no dissection with {} pieces ({:.1} s)",
                b.value - 1,
                self.start.elapsed().as_secs_f64()
            )),
            EnumerateEvent::Found {
                count,
                classes,
                seconds,
            } => {
                let text = format!(
                    "{count} dissections so far ({classes} up to symmetry), {seconds:.1} s"
                );
                let mut state = self.state.lock().expect("display lock");
                if self.terminal {
                    eprint!("\r\x1b[2K{text}");
                    state.1 = true;
                } else if state.0.elapsed() >= Duration::from_secs(10) {
                    progress::stderr_line(&text);
                    state.0 = Instant::now();
                }
            }
            _ => {}
        }
    }
}

pub fn run(args: EnumerateArgs) -> Result<Status> {
    let figures = input::figures(&args.figures, args.lattice)?;
    input::check_equal_areas(&args.figures, &figures)?;
    if let Some(dir) = &args.output {
        prepare_folder(dir)?;
    }
    let names = crate::prove::names(&args.figures);
    let display = Display {
        quiet: args.quiet,
        terminal: std::io::stderr().is_terminal(),
        start: Instant::now(),
        state: Mutex::new((Instant::now(), false)),
    };
    let config = EnumerateConfig {
        mirror: !args.no_mirror,
        pieces: args.pieces,
        time_limit: args.time_limit.unwrap_or_default(),
        rank: args.rank,
        unique: args.unique,
    };
    let report =
        dissect_engine::enumerate(&figures, &names, &config, crate::stop::flag(), &display);
    display.clear();
    let report = match report {
        Ok(r) => r,
        Err(e @ EngineError::Figures(_)) => return Err(InputError(e.to_string()).into()),
        Err(e) => return Err(e.into()),
    };
    if let Some(dir) = &args.output {
        write_classes(dir, &report)?;
    }
    if !args.quiet {
        print_classes(&args, &report);
    }
    let n = report.dissections.len();
    let m = report.classes.len();
    let k = report.pieces;
    progress::stdout(&format!(
        "{}{n} dissection{} with {k} pieces ({m} up to the first figure's symmetries), {}\n",
        if report.complete { "" } else { "at least " },
        if n == 1 { "" } else { "s" },
        if report.complete {
            "complete"
        } else {
            "stopped"
        }
    ));
    Ok(if report.complete && n > 0 {
        Status::Ok
    } else {
        Status::NotFound
    })
}

/// The output folder: created when missing (its parent must exist); a
/// file in its place is bad input.
fn prepare_folder(dir: &Path) -> Result<()> {
    if dir.is_dir() {
        return Ok(());
    }
    if dir.exists() {
        return Err(InputError(format!("{}: not a folder", dir.display())).into());
    }
    std::fs::create_dir(dir)
        .map_err(|e| InputError(format!("{}: cannot create the folder: {e}", dir.display())))?;
    Ok(())
}

/// `DIR/1.json`, `DIR/2.json`, ...: one verified dissection per class, in
/// the order listed, each written atomically.
fn write_classes(dir: &Path, report: &EnumerationReport) -> Result<()> {
    for (i, class) in report.classes.iter().enumerate() {
        let d = &class.dissection;
        let mut extra = Map::new();
        extra.insert("pieces".into(), json!(d.piece_count()));
        extra.insert("areas".into(), json!(d.areas()));
        extra.insert(
            "enumeration".into(),
            json!({
                "class": i + 1,
                "classes": report.classes.len(),
                "dissections_in_class": class.size,
                "dissections": report.dissections.len(),
                "complete": report.complete,
                "minimum": report.minimum,
            }),
        );
        extra.insert(
            "scores".into(),
            serde_json::to_value(&class.scores).unwrap_or_default(),
        );
        let text = d.dissection().to_file(extra).to_json();
        crate::output::write_atomic(&dir.join(format!("{}.json", i + 1)), text)?;
    }
    Ok(())
}

/// One line per class on stderr, then the `--unique` tally.
fn print_classes(args: &EnumerateArgs, report: &EnumerationReport) {
    for (i, class) in report.classes.iter().enumerate() {
        let label = match &args.output {
            Some(dir) => dir.join(format!("{}.json", i + 1)).display().to_string(),
            None => format!("#{}", i + 1),
        };
        progress::stderr_line(&format!(
            "{label}: {} dissection{} in the class; {}",
            class.size,
            if class.size == 1 { "" } else { "s" },
            class.scores
        ));
    }
    if let Some((n, m)) = report.before_unique {
        progress::stderr_line(&format!(
            "unique: {} of {n} dissections ({} of {m} classes) tile every figure in a single way",
            report.dissections.len(),
            report.classes.len()
        ));
    }
    if !report.minimum && args.pieces.is_none() {
        progress::stderr_line(&format!(
            "stopped before the minimum piece count was proved (lower bound {})",
            report.lower_bound.value
        ));
    }
}
