//! The command line.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand};
use dissect_core::LatticeKind;
use dissect_engine::TimeLimit;

#[derive(Parser, Debug)]
#[command(
    name = "dissect",
    version,
    about = "Find the fewest connected pieces that cut one lattice figure into another."
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand, Debug)]
pub enum Command {
    /// Find a dissection of two or more figures of equal area.
    Solve(SolveArgs),
    /// Check a solution file against its figures.
    Verify(VerifyArgs),
    /// Print each figure's cell count, components, holes and bounding box.
    Info(InfoArgs),
    /// Prove a lower bound on the number of pieces (last line: "lower bound: K (reason)").
    Bound(crate::prove::BoundArgs),
    /// Serve the browser studio (figure editor, solver, downloads) on 127.0.0.1.
    #[cfg(feature = "serve")]
    Serve(crate::serve::ServeArgs),
    /// Draw a solution (svg, png), or make it (stl meshes, ldraw LEGO models, --cut-sheet).
    #[cfg(feature = "render")]
    Render(crate::render::RenderArgs),
    /// Turn a picture (PNG, JPEG, SVG; slices for cubic) into a figure with an exact cell count.
    #[cfg(feature = "render")]
    Rasterize(crate::render::RasterizeArgs),
    /// Turn a closed STL mesh into a cubic figure with an exact cube count.
    #[cfg(feature = "render")]
    Voxelize(crate::render::VoxelizeArgs),
    /// Count the ways a solution's pieces tile each figure (and say when it is unique).
    Assemblies(crate::assemblies::AssembliesArgs),
    /// Take each 3D figure of a solution apart by straight moves: the plan and its level, or the locked pieces.
    Disassemble(crate::disassemble::DisassembleArgs),
    /// Count every dissection with the fewest pieces (or --pieces K), complete, up to the first figure's symmetries.
    Enumerate(crate::enumerate::EnumerateArgs),
    /// Check the certificates of a --certificate folder (every kK.cnf against its kK.drat) with the independent checker.
    CheckProof(crate::certificate::CheckProofArgs),
}

/// A thread count from 0 (one per core) to the engine's
/// [`dissect_engine::MAX_THREADS`] ([`dissect_engine::check_threads`]).
pub fn thread_count(s: &str) -> Result<usize, String> {
    let n = whole_usize::<0>(s)?;
    dissect_engine::check_threads(n).map_err(|e| e.to_string())
}

/// A whole number of at least `MIN`. Negative numbers reach this parser
/// (every command allows them as values) so that `-1` is told what range
/// it is out of, not to be written `-- -1`.
pub fn whole<const MIN: u64>(s: &str) -> Result<u64, String> {
    match s.trim().parse::<i128>() {
        Ok(n) if n < MIN as i128 => Err(format!("must be a whole number >= {MIN}, got {s}")),
        Ok(n) => u64::try_from(n).map_err(|_| format!("must be at most {}, got {s}", u64::MAX)),
        Err(_) => Err(format!("{s:?} is not a whole number (>= {MIN})")),
    }
}

/// [`whole`] as a `usize`.
pub fn whole_usize<const MIN: u64>(s: &str) -> Result<usize, String> {
    whole::<MIN>(s).and_then(|n| {
        usize::try_from(n).map_err(|_| format!("must be at most {}, got {s}", usize::MAX))
    })
}

/// A finite number.
#[cfg_attr(not(any(feature = "render", feature = "serve")), allow(dead_code))]
pub fn finite(s: &str) -> Result<f64, String> {
    match s.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(format!("must be a finite number, got {s}")),
        Err(_) => Err(format!("{s:?} is not a number")),
    }
}

/// A finite number above 0.
#[cfg_attr(not(any(feature = "render", feature = "serve")), allow(dead_code))]
pub fn positive(s: &str) -> Result<f64, String> {
    finite(s).and_then(|v| {
        if v > 0.0 {
            Ok(v)
        } else {
            Err(format!("must be more than 0, got {s}"))
        }
    })
}

/// A finite number of at least 0.
#[cfg_attr(not(any(feature = "render", feature = "serve")), allow(dead_code))]
pub fn non_negative(s: &str) -> Result<f64, String> {
    finite(s).and_then(|v| {
        if v >= 0.0 {
            Ok(v)
        } else {
            Err(format!("must be >= 0, got {s}"))
        }
    })
}

/// What `dissect solve` does without flags: the engine's defaults (the
/// paper's constants, from `dissect_core::Options::default()`), never a copy.
fn defaults() -> dissect_engine::RunConfig {
    dissect_engine::RunConfig::default()
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct SolveArgs {
    /// The lattice: square, tri4, cubic, tri3 or hex.
    #[arg(long, default_value_t = LatticeKind::Square)]
    pub lattice: LatticeKind,
    /// Do not turn 2D pieces over (rotations only).
    #[arg(long)]
    pub no_mirror: bool,
    /// Seed of every random choice; the same seed gives the same result for any --threads.
    #[arg(long, default_value_t = defaults().seed, value_parser = whole::<0>)]
    pub seed: u64,
    /// Worker threads (default: one per core; at most 256).
    #[arg(long, default_value_t = defaults().threads, value_parser = thread_count)]
    pub threads: usize,
    /// Stop after this many seconds and report the best dissection found so far.
    #[arg(long, value_name = "SECS")]
    pub time_limit: Option<TimeLimit>,
    /// Give up after trying this many pieces.
    #[arg(long, value_name = "K", value_parser = whole_usize::<0>)]
    pub max_pieces: Option<usize>,
    /// For every "no K-piece dissection" the exact search proves, write
    /// DIR/kK.cnf, DIR/kK.drat (its DRAT proof) and DIR/README.txt; check
    /// them with `dissect check-proof DIR`.
    #[arg(long, value_name = "DIR", conflicts_with = "no_prove")]
    pub certificate: Option<std::path::PathBuf>,
    /// Weight of the area-balance term at level 1 (paper: 0.5; 0 turns it off).
    #[arg(long, default_value_t = defaults().area_weight, value_name = "X")]
    pub area_weight: f64,
    /// Random explorations per level (paper: N = 400).
    #[arg(long, default_value_t = defaults().explorations, value_name = "N", value_parser = whole_usize::<0>)]
    pub explorations: usize,
    /// A number NB: best candidates kept per level (paper: Nb = 30). N:REGIONS.txt: cells of figure N
    /// marked with the same letter a-z in that grid end in the same piece (repeatable).
    #[arg(long, value_name = "NB|N:REGIONS.txt", value_parser = keep_arg)]
    pub keep: Vec<KeepArg>,
    /// Refinement iterations per exploration (paper: R = 100).
    #[arg(long, default_value_t = defaults().iterations, value_name = "R", value_parser = whole_usize::<0>)]
    pub iterations: usize,
    /// Objective penalty per disconnected piece during the search.
    #[arg(long, default_value_t = defaults().split_penalty, value_name = "X")]
    pub split_penalty: f64,
    /// Level-1 runs tried when splitting the worst pair of pieces.
    #[arg(long, default_value_t = defaults().split_tries, value_name = "N", value_parser = whole_usize::<0>)]
    pub split_tries: usize,
    /// Run the whole final level to pick the least area variance among more solutions.
    #[arg(long)]
    pub full_level: bool,
    /// Extra rounds of explorations for a level whose best candidate is a near miss (0: the paper's schedule).
    #[arg(long, default_value_t = defaults().extra_rounds, value_name = "N", value_parser = whole_usize::<0>)]
    pub extra_rounds: usize,
    /// Stop refining an exploration after this many iterations without fewer conflicts (0: the paper's loop).
    #[arg(long, default_value_t = defaults().patience, value_name = "N", value_parser = whole_usize::<0>)]
    pub patience: usize,
    /// Prove a lower bound by SAT beside the search and say whether the result is optimal (the default).
    #[arg(long, conflicts_with = "no_prove")]
    pub prove: bool,
    /// Do not run the SAT lower-bound search beside the heuristic.
    #[arg(long)]
    pub no_prove: bool,
    /// Find a minimum dissection by SAT alone (small figures).
    #[arg(long, conflicts_with = "paper")]
    pub exact: bool,
    /// Exactly the paper's schedule: levels of 2, 3, ... pieces, stopping at the first level with a valid dissection.
    #[arg(long)]
    pub paper: bool,
    /// Without --time-limit, end after this many rounds in a row that found no fewer pieces (with --solutions: more of them, and a round that found a new solution counts as progress).
    #[arg(long, default_value_t = defaults().idle_rounds, value_name = "N")]
    pub rounds: usize,
    /// Write up to N different dissections with the fewest pieces: OUT.json (the best), OUT-2.json, ...
    #[arg(long, default_value_t = defaults().solutions, value_name = "N", value_parser = whole_usize::<0>)]
    pub solutions: usize,
    /// How several solutions are ranked: variance (default), smallest, shapes, symmetry, unique, level.
    #[arg(long, value_name = "CRITERION", value_parser = rank)]
    pub rank: Option<dissect_engine::Rank>,
    /// Every piece has at least C cells.
    #[arg(long, value_name = "C", value_parser = whole_usize::<0>)]
    pub min_piece: Option<usize>,
    /// Every piece has at most C cells.
    #[arg(long, value_name = "C", value_parser = whole_usize::<0>)]
    pub max_piece: Option<usize>,
    /// Accept only dissections whose every 3D figure comes apart by straight moves (dissect disassemble).
    #[arg(long)]
    pub assemblable: bool,
    /// Every figure needs at least L moves before its first piece comes free (interlocking; implies --assemblable).
    #[arg(long, value_name = "L", value_parser = whole_usize::<0>)]
    pub min_level: Option<usize>,
    /// Every piece keeps the colour of each of its cells in a checkerboard colouring (square, cubic).
    #[arg(long)]
    pub checkerboard: bool,
    /// Favour pieces with more self-symmetries when choosing among dissections (0: off).
    #[arg(long, value_name = "X")]
    pub symmetry_weight: Option<f64>,
    /// Write the solution JSON here.
    #[arg(short = 'o', long = "output", value_name = "OUT.json")]
    pub output: Option<PathBuf>,
    /// Also write SVG views (dissection.svg, cut-sheet.svg) into this directory.
    #[cfg(feature = "render")]
    #[arg(long, value_name = "DIR")]
    pub render: Option<PathBuf>,
    /// Print nothing but errors.
    #[arg(long, short)]
    pub quiet: bool,
    /// Colour the pieces: auto (when stdout is a terminal), always, never.
    #[arg(long, default_value = "auto", value_parser = ["auto", "always", "never"])]
    pub color: String,
    /// The figures (text files, see FORMAT.md).
    #[arg(required = true, num_args = 2.., value_name = "FIGURE")]
    pub figures: Vec<PathBuf>,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct VerifyArgs {
    /// The lattice (default: the solution's).
    #[arg(long)]
    pub lattice: Option<LatticeKind>,
    /// The solution JSON.
    #[arg(long, value_name = "S.json")]
    pub solution: PathBuf,
    /// The figures, in the solution's order.
    #[arg(required = true, num_args = 1.., value_name = "FIGURE")]
    pub figures: Vec<PathBuf>,
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct InfoArgs {
    /// The lattice: square, tri4, cubic, tri3 or hex.
    #[arg(long, default_value_t = LatticeKind::Square)]
    pub lattice: LatticeKind,
    /// The figures.
    #[arg(required = true, num_args = 1.., value_name = "FIGURE")]
    pub figures: Vec<PathBuf>,
}

/// A `--keep` value: a number of candidates, or a regions grid over a figure.
#[derive(Clone, Debug, PartialEq)]
pub enum KeepArg {
    /// Best candidates kept per level.
    Candidates(usize),
    /// Figure (1-based) and the regions grid file.
    Regions(usize, PathBuf),
}

fn keep_arg(s: &str) -> Result<KeepArg, String> {
    match s.split_once(':') {
        Some((n, file)) => match n.trim().parse::<usize>() {
            Ok(n) if n >= 1 && !file.is_empty() => Ok(KeepArg::Regions(n, PathBuf::from(file))),
            _ => Err(format!(
                "{s:?}: expected N:REGIONS.txt with N a figure number from 1"
            )),
        },
        None => whole_usize::<0>(s).map(KeepArg::Candidates),
    }
}

fn rank(s: &str) -> Result<dissect_engine::Rank, String> {
    s.parse()
        .map_err(|e: dissect_puzzle::scores::UnknownRank| e.to_string())
}

impl SolveArgs {
    /// The best candidates kept per level (`--keep NB`, default 30).
    pub fn kept_candidates(&self) -> usize {
        self.keep
            .iter()
            .rev()
            .find_map(|k| match k {
                KeepArg::Candidates(n) => Some(*n),
                KeepArg::Regions(..) => None,
            })
            .unwrap_or(defaults().keep)
    }

    /// The run these flags ask for (checked by the engine).
    pub fn run_config(&self) -> dissect_engine::RunConfig {
        dissect_engine::RunConfig {
            strategy: if self.exact {
                dissect_engine::Strategy::Exact
            } else if self.paper {
                dissect_engine::Strategy::Paper
            } else {
                dissect_engine::Strategy::Anytime
            },
            prove: !self.no_prove,
            mirror: !self.no_mirror,
            seed: self.seed,
            threads: self.threads,
            time_limit: self.time_limit.unwrap_or_default(),
            max_pieces: self.max_pieces,
            area_weight: self.area_weight,
            explorations: self.explorations,
            keep: self.kept_candidates(),
            iterations: self.iterations,
            split_penalty: self.split_penalty,
            split_tries: self.split_tries,
            full_level: self.full_level,
            extra_rounds: self.extra_rounds,
            patience: self.patience,
            idle_rounds: self.rounds,
            solutions: self.solutions,
            rank: self.rank.unwrap_or_default(),
            certify: self.certificate.is_some(),
            ..dissect_engine::RunConfig::default()
        }
    }
}

#[cfg(test)]
mod tests {
    use clap::Parser;

    use super::{Cli, Command};

    /// The flags' defaults are the engine's, so `dissect solve` with no
    /// flag runs exactly `RunConfig::default()`.
    #[test]
    fn solve_without_flags_runs_the_engine_defaults() {
        let cli = Cli::try_parse_from(["dissect", "solve", "a.txt", "b.txt"]).expect("parses");
        let Command::Solve(args) = cli.command else {
            panic!("not solve: {:?}", cli.command);
        };
        assert_eq!(args.run_config(), dissect_engine::RunConfig::default());
    }

    /// Every command reads `--lattice` with the core's one parser.
    #[test]
    fn lattice_names_are_the_cores() {
        for kind in dissect_core::LatticeKind::ALL {
            let cli = Cli::try_parse_from(["dissect", "info", "--lattice", kind.name(), "a.txt"])
                .expect("parses");
            let Command::Info(args) = cli.command else {
                panic!("not info");
            };
            assert_eq!(args.lattice, kind);
        }
        let e = Cli::try_parse_from(["dissect", "info", "--lattice", "hexagon", "a.txt"])
            .unwrap_err()
            .to_string();
        assert!(
            e.contains("unknown lattice \"hexagon\" (expected square, tri4, cubic, tri3 or hex)"),
            "{e}"
        );
    }
}
