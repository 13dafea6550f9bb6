//! `dissect bound`: the engine's bound ([`dissect_engine::bound`]), and the
//! lines that show the exact search's progress on stderr.

use std::path::PathBuf;
use std::time::Instant;

use anyhow::Result;
use dissect_core::LatticeKind;
use dissect_engine::{BoundConfig, EngineError, EngineEvent, EngineObserver, TimeLimit};
use dissect_exact::{ExactEvent, ExactObserver};

use crate::{input, InputError, Status};

#[derive(clap::Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct BoundArgs {
    /// The lattice: square, tri4, cubic, tri3 or hex.
    #[arg(long, default_value_t = LatticeKind::Square)]
    pub lattice: LatticeKind,
    /// Do not turn 2D pieces over (rotations only).
    #[arg(long)]
    pub no_mirror: bool,
    /// Stop after this many seconds and report the best bound proved so far.
    #[arg(long, value_name = "SECS")]
    pub time_limit: Option<TimeLimit>,
    /// Try to refute no more than this many pieces.
    #[arg(long, value_name = "K", value_parser = crate::args::whole_usize::<1>)]
    pub max_pieces: Option<usize>,
    /// Print only the last line.
    #[arg(long, short)]
    pub quiet: bool,
    /// Solve nothing: write to FILE, as DIMACS CNF, the formula the search
    /// would solve for "at most K pieces" with K given by --max-pieces (the
    /// relaxation without connectivity: UNSAT proves that no K-piece
    /// dissection exists). For timing other SAT solvers.
    #[arg(long, value_name = "FILE", requires = "max_pieces")]
    pub dimacs: Option<PathBuf>,
    /// With --dimacs: add the full connectivity encoding (every piece
    /// reached from its root), so that UNSAT proves that no dissection
    /// into K connected pieces exists in one solve, and SAT gives one.
    #[arg(long, requires = "dimacs")]
    pub connected: bool,
    /// With --dimacs or --model: the most memory (MiB) the formula may
    /// take while it is built; a larger one is refused before building.
    #[arg(long, value_name = "MIB", default_value_t = 512, value_parser = clap::value_parser!(u64).range(1..=1 << 20))]
    pub max_encoding_mib: u64,
    /// Solve nothing: read FILE, another SAT solver's model of the
    /// formula of --dimacs (with or without --connected) for the K of
    /// --max-pieces (its `v` lines, or bare literals), and turn it into
    /// the dissection it stands for, verified; written with --output.
    #[arg(long, value_name = "FILE", requires = "max_pieces", conflicts_with_all = ["dimacs", "certificate"])]
    pub model: Option<PathBuf>,
    /// With --model: write the dissection to FILE (solution JSON).
    #[arg(long, short, value_name = "FILE")]
    pub output: Option<PathBuf>,
    /// For every "no K-piece dissection" proved by SAT, write DIR/kK.cnf
    /// (the formula), DIR/kK.drat (its DRAT proof of unsatisfiability) and
    /// DIR/README.txt; check them with `dissect check-proof DIR`.
    #[arg(long, value_name = "DIR", conflicts_with = "dimacs")]
    pub certificate: Option<PathBuf>,
    /// Ask another SAT solver instead of the built-in one: for K from the
    /// cheap bound up, run `CMD kK.cnf kK.drat` on the formula of "at most K
    /// connected pieces" (e.g. "cadical --no-binary"); with --certificate
    /// DIR its refutations and proofs are kept there for check-proof.
    #[arg(long, value_name = "CMD", conflicts_with_all = ["dimacs", "model"])]
    pub solver: Option<String>,
    /// Cube-and-conquer on this many threads: each "at most K pieces?" is
    /// split into cubes (the literals of one of its clauses) solved in
    /// parallel; certificates then hold one proof per cube (1: no cubes).
    #[arg(long, default_value_t = 1, value_parser = crate::args::thread_count)]
    pub threads: usize,
    /// The figures (text files, see FORMAT.md).
    #[arg(required = true, num_args = 2.., value_name = "FIGURE")]
    pub figures: Vec<PathBuf>,
}

/// Prints the exact search's progress on stderr.
pub struct Lines {
    pub quiet: bool,
    pub start: Instant,
    pub names: Vec<String>,
    /// Writes the certificates (`--certificate`).
    pub certificates: Option<dissect_certificate::Writer>,
}

impl ExactObserver for Lines {
    fn on_event(&self, event: &ExactEvent) {
        if let Some(w) = &self.certificates {
            w.on_event(event);
        }
        if self.quiet {
            return;
        }
        let t = self.start.elapsed().as_secs_f64();
        match event {
            ExactEvent::Certified(c) => eprintln!(
                "[exact {t:6.1} s] certificate k{}: {} clauses, {} lemmas",
                c.pieces,
                c.clauses,
                c.lemmas()
            ),
            ExactEvent::CheapBound(b) => eprintln!(
                "[exact {t:6.1} s] cheap bound: {} ({})",
                b.value,
                b.describe(&self.names)
            ),
            ExactEvent::Encoded {
                pieces,
                motions,
                size,
            } => eprintln!(
                "[exact {t:6.1} s] {pieces} pieces, {motions}: {} variables, {} clauses, {} placements",
                size.vars, size.clauses, size.motions
            ),
            ExactEvent::Cuts {
                pieces,
                added,
                total,
            } if total.is_power_of_two() || *total == *added => eprintln!(
                "[exact {t:6.1} s] {pieces} pieces: a model had split pieces, {total} connectivity cuts so far"
            ),
            ExactEvent::ConnectivityEncoded { pieces } => eprintln!(
                "[exact {t:6.1} s] {pieces} pieces: a model had split pieces, connectivity encoded"
            ),
            ExactEvent::Refuted(b) => eprintln!(
                "[exact {t:6.1} s] lower bound {} ({})",
                b.value,
                b.describe(&self.names)
            ),
            ExactEvent::Inconclusive {
                pieces,
                motions,
                timed_out,
            } => eprintln!(
                "[exact {t:6.1} s] {pieces} pieces, {motions}: {}",
                if *timed_out {
                    "out of time"
                } else {
                    "none (this proves nothing)"
                }
            ),
            ExactEvent::Cube {
                pieces,
                index,
                of,
                refuted,
                seconds,
            } => eprintln!(
                "[exact {t:6.1} s] {pieces} pieces: cube {}/{of} {} in {seconds:.1} s",
                index + 1,
                if *refuted { "refuted" } else { "not refuted" }
            ),
            ExactEvent::CubeKept { pieces, index, of } => eprintln!(
                "[exact {t:6.1} s] {pieces} pieces: cube {}/{of} refuted by an earlier run (kept in the certificate folder)",
                index + 1
            ),
            ExactEvent::Found { pieces, .. } => {
                eprintln!("[exact {t:6.1} s] SAT found a connected {pieces}-piece dissection")
            }
            _ => {}
        }
    }
}

pub fn names(paths: &[PathBuf]) -> Vec<String> {
    paths.iter().map(|p| input::file_name(p)).collect()
}

/// `dissect bound`: the last line printed is `lower bound: K (reason)`.
pub fn bound(args: BoundArgs) -> Result<Status> {
    let figures = input::figures(&args.figures, args.lattice)?;
    input::check_equal_areas(&args.figures, &figures)?;
    if let (Some(path), Some(k)) = (&args.dimacs, args.max_pieces) {
        let cnf = if args.connected {
            dissect_exact::dimacs_connected(
                &figures,
                !args.no_mirror,
                k,
                args.max_encoding_mib << 20,
            )
        } else {
            dissect_exact::dimacs_within(&figures, !args.no_mirror, k, args.max_encoding_mib << 20)
        }
        .map_err(|e| InputError(e.to_string()))?;
        crate::output::write_atomic(path, cnf.text.as_bytes())?;
        println!(
            "wrote {}: at most {k} {}pieces, {} variables, {} clauses",
            path.display(),
            if args.connected { "connected " } else { "" },
            cnf.vars,
            cnf.clauses
        );
        return Ok(Status::Ok);
    }
    if let (Some(path), Some(k)) = (&args.model, args.max_pieces) {
        return from_model(&args, &figures, path, k);
    }
    let names = names(&args.figures);
    if let Some(command) = &args.solver {
        return with_solver(&args, &figures, &names, command);
    }
    if args.output.is_some() {
        return Err(InputError("-o/--output needs --model or --solver".to_string()).into());
    }
    let certificates = match &args.certificate {
        Some(dir) => Some(crate::certificate::writer(
            dir,
            &args.figures,
            args.lattice,
            args.no_mirror,
        )?),
        None => None,
    };
    let config = BoundConfig {
        mirror: !args.no_mirror,
        max_pieces: args.max_pieces,
        time_limit: args.time_limit.unwrap_or_default(),
        certify: args.certificate.is_some(),
        cube_proofs: certificates.as_ref().map(|w| w.cube_proofs()),
        threads: args.threads,
    };
    let observer = Lines {
        quiet: args.quiet,
        start: Instant::now(),
        names: names.clone(),
        certificates,
    };
    let report = dissect_engine::bound(&figures, &names, &config, crate::stop::flag(), &observer)
        .map_err(engine_error)?;
    print_report(&report, &observer)
}

/// Bad figures and exact-search refusals are the user's input; the rest
/// is an internal error.
fn engine_error(e: EngineError) -> anyhow::Error {
    match e {
        e @ (EngineError::Figures(_) | EngineError::Exact(_) | EngineError::External(..)) => {
            anyhow::Error::from(InputError(e.to_string()))
        }
        e => e.into(),
    }
}

/// `bound --solver CMD`: the engine's `bound_external` with the solver run
/// as a process; its files in --certificate DIR or a temporary folder.
fn with_solver(
    args: &BoundArgs,
    figures: &[dissect_core::Figure],
    names: &[String],
    command: &str,
) -> Result<Status> {
    let mut solver =
        dissect_solver_process::SolverProcess::new(command, args.certificate.as_deref())
            .map_err(|e| InputError(format!("--solver: {e}")))?;
    if !args.quiet {
        let program = solver_name(command);
        solver = solver.with_progress(Box::new(move |k, path, cnf| {
            eprintln!(
                "[solver] {program} on {}: at most {k} connected pieces, {} variables, {} clauses",
                path.display(),
                cnf.vars,
                cnf.clauses
            );
        }));
    }
    let keep = args.certificate.is_some();
    let dir = solver.dir().to_path_buf();
    let config = BoundConfig {
        mirror: !args.no_mirror,
        max_pieces: args.max_pieces,
        time_limit: args.time_limit.unwrap_or_default(),
        ..BoundConfig::default()
    };
    let observer = Lines {
        quiet: args.quiet,
        start: Instant::now(),
        names: names.to_vec(),
        certificates: None,
    };
    let report = dissect_engine::bound_external(
        figures,
        names,
        (&config, args.max_encoding_mib << 20),
        &solver,
        crate::stop::flag(),
        &observer,
    )
    .map_err(engine_error)?;
    if let (Some(found), Some(out)) = (&report.found, &args.output) {
        let file = found.dissection().to_file(Default::default());
        crate::output::write_atomic(out, file.to_json())?;
        println!("wrote {}", out.display());
    }
    let refuted = solver
        .finish()
        .map_err(|e| InputError(format!("--solver: {e}")))?;
    if keep && !refuted.is_empty() {
        println!(
            "certificates: {} in {} (check with: dissect check-proof {})",
            refuted
                .iter()
                .map(|k| format!("k{k}"))
                .collect::<Vec<_>>()
                .join(", "),
            dir.display(),
            dir.display()
        );
    }
    print_report(&report, &observer)
}

/// The solver's program name (the first word of its command).
fn solver_name(command: &str) -> String {
    command
        .split_whitespace()
        .next()
        .unwrap_or(command)
        .to_string()
}

/// The bound's closing lines: why it stopped, the certificates, and last
/// `lower bound: K (reason)`.
fn print_report(report: &dissect_engine::BoundReport, observer: &Lines) -> Result<Status> {
    if let Some(found) = &report.found {
        println!(
            "a {}-piece dissection exists (found by SAT): the bound is optimal",
            found.piece_count()
        );
    } else if let Some((pieces, bytes, cap)) = report.too_large {
        println!(
            "stopped: the SAT encoding for {pieces} pieces would need about {} MiB \
             (over the cap of {} MiB); the bound below is the best proved",
            bytes >> 20,
            cap >> 20
        );
    } else if let Some(cells) = report.too_many_cells {
        println!(
            "no SAT search: a figure has {cells} cells (over {}); the bound below is the cheap one",
            dissect_exact::bound::SAT_MAX_CELLS
        );
    } else if report.stopped() {
        println!("stopped (time limit or Ctrl-C); the bound below is the best proved");
    }
    if let Some(w) = &observer.certificates {
        println!("{}", w.summary().map_err(crate::output::cli_error)?);
    }
    println!(
        "lower bound: {} ({})",
        report.lower_bound.value, report.lower_bound.reason
    );
    Ok(Status::Ok)
}

impl EngineObserver for Lines {
    fn on_event(&self, event: &EngineEvent<'_>) {
        if let EngineEvent::Exact(e) = event {
            ExactObserver::on_event(self, e);
        }
    }
}

/// `bound --model FILE`: the dissection a SAT solver's model stands for.
fn from_model(
    args: &BoundArgs,
    figures: &[dissect_core::Figure],
    path: &std::path::Path,
    k: usize,
) -> Result<Status> {
    let text = std::fs::read_to_string(path)
        .map_err(|e| InputError(format!("{}: cannot read: {e}", path.display())))?;
    let mut model = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if line.starts_with('s') && line.contains("UNSAT") {
            return Err(InputError(format!(
                "{} line {}: the solver answered UNSATISFIABLE: no model, so no dissection into {k} pieces \
                 (to certify it, have the solver write a DRAT proof and run `dissect check-proof`)",
                path.display(),
                i + 1
            ))
            .into());
        }
        // A solver's answer line and comments; `v` lines or bare literals.
        if line.is_empty() || line.starts_with('c') || line.starts_with('s') {
            continue;
        }
        for token in line.strip_prefix('v').unwrap_or(line).split_whitespace() {
            let lit: i32 = token.parse().map_err(|_| {
                InputError(format!(
                    "{} line {}: `{token}` is not a literal",
                    path.display(),
                    i + 1
                ))
            })?;
            model.push(lit);
        }
    }
    let mirror = !args.no_mirror && args.lattice.lattice().supports_mirror();
    let pieces =
        dissect_exact::decode_model_within(figures, mirror, k, &model, args.max_encoding_mib << 20)
            .map_err(|e| InputError(format!("{}: {e}", path.display())))?;
    let count = pieces[0].len();
    println!(
        "the model of {} is a verified dissection into {count} pieces",
        path.display()
    );
    if let Some(out) = &args.output {
        let d = dissect_core::Dissection::new(args.lattice, mirror, names(&args.figures), pieces)
            .map_err(|e| InputError(e.to_string()))?;
        crate::output::write_atomic(out, d.to_file(Default::default()).to_json())?;
        println!("wrote {}", out.display());
    }
    Ok(Status::Ok)
}
