//! The `puzzle` target: the puzzle fields and the inputs of the commands
//! built on the engine (`solve --keep/--min-piece/--max-piece/--solutions/
//! --rank`, `assemblies`, `disassemble`, `enumerate`).
//!
//! An input is sections separated by a line `--`:
//!
//! ```text
//! LATTICE key=value ...        options: rank, pieces, min, max, solutions,
//! --                           checkerboard, sym, keep (a figure, from 1), mirror
//! FIGURE A                     figure text
//! --
//! FIGURE B
//! --
//! REGIONS                      a keep-regions grid over figure `keep`
//! --
//! SOLUTION                     a solution file (puzzle fields in it too)
//! ```
//!
//! Every section goes through the parser a command uses; what parses goes
//! on to what the command does with it, on small figures and under a time
//! limit of a hundredth of a second: the constraints are validated against
//! the figures, a solution is verified, checked against the constraints,
//! scored and ranked, its assemblies counted and its figures taken apart
//! (and the plan file written); small figures are enumerated and solved
//! under the constraints.

use std::str::FromStr;
use std::sync::atomic::AtomicBool;

use dissect_core::io::{parse_figure, parse_solution};
use dissect_core::{Figure, LatticeKind};
use dissect_engine::{
    Constraints, EnumerateConfig, KeepRegions, Rank, RunConfig, RunOptions, Scores, TimeLimit,
    Verified,
};
use dissect_puzzle::Motions;

use super::Target;

/// The options line, as read.
#[derive(Default)]
struct Options {
    rank: Option<Rank>,
    pieces: Option<usize>,
    min: Option<usize>,
    max: Option<usize>,
    solutions: Option<usize>,
    checkerboard: bool,
    sym: Option<f64>,
    keep: Option<usize>,
    mirror: Option<bool>,
}

/// Reads `LATTICE key=value ...`; `None` for anything unknown.
fn options(line: &str) -> Option<(LatticeKind, Options)> {
    let mut words = line.split_whitespace();
    let lattice: LatticeKind = words.next()?.parse().ok()?;
    let mut o = Options::default();
    for w in words {
        let (k, v) = w.split_once('=')?;
        let n = || v.parse::<usize>().ok();
        match k {
            "rank" => o.rank = Some(Rank::from_str(v).ok()?),
            "pieces" => o.pieces = Some(n()?),
            "min" => o.min = Some(n()?),
            "max" => o.max = Some(n()?),
            "solutions" => o.solutions = Some(n()?),
            "checkerboard" => o.checkerboard = v == "1",
            "sym" => o.sym = Some(v.parse().ok()?),
            "keep" => o.keep = Some(n()?),
            "mirror" => o.mirror = Some(v == "1"),
            _ => return None,
        }
    }
    Some((lattice, o))
}

/// Cells of all the figures together.
fn cells(figures: &[Figure]) -> usize {
    figures.iter().map(Figure::len).sum()
}

/// The constraints the options and the regions grid ask for, as `solve`
/// builds them; `None` when they are refused.
fn constraints(o: &Options, regions: Option<&str>, figures: &[Figure]) -> Option<Constraints> {
    let mut c = Constraints::none()
        .with_sizes(o.min, o.max)
        .with_checkerboard(o.checkerboard);
    if let Some(w) = o.sym {
        c = c.with_symmetry_weight(w);
    }
    if let (Some(text), Some(f)) = (regions, o.keep) {
        c = c.with_keep(KeepRegions::parse(text, f.checked_sub(1)?, figures).ok()?);
    }
    c.validate_settings().ok()?;
    c.validate(figures).ok()?;
    Some(c)
}

/// A solution file against the figures: verified, checked, scored and
/// ranked, counted and taken apart (the plan written).
fn solution(text: &str, figures: &[Figure], c: &Constraints, rank: Rank) -> bool {
    let Ok((_, d)) = parse_solution(text) else {
        return false;
    };
    if d.lattice() != figures[0].lattice() || d.pieces().len() != figures.len() {
        return true;
    }
    let names = vec![String::new(); figures.len()];
    let Ok(v) = Verified::new(d.lattice(), d.mirror(), names, figures, d.pieces().to_vec()) else {
        return true;
    };
    let motions = Motions::new(d.lattice(), d.mirror());
    let _ = c.check(&motions, d.pieces());
    let _ = c.distance(d.pieces());
    let a = Scores::weighted(&motions, &d.pieces()[0], c.symmetry_weight());
    let b = Scores::of(&motions, &d.pieces()[0]);
    let _ = rank.compare(&a, &b);
    let limit = TimeLimit::new(0.01).expect("a time limit");
    let stop = AtomicBool::new(false);
    let _ = dissect_engine::assemblies(v.dissection(), figures, limit, &stop, &mut |_| {});
    if let Ok(outcomes) = v.disassemble(limit, Some(&stop)) {
        let named: Vec<(&str, _)> = outcomes.iter().map(|o| ("f", o)).collect();
        let _ = dissect_puzzle::disassembly::plan_json(d.lattice(), &named);
    }
    true
}

/// Enumerates and solves small figures under the options.
fn search(figures: &[Figure], o: &Options, c: Constraints) {
    let limit = TimeLimit::new(0.01).expect("a time limit");
    let stop = AtomicBool::new(false);
    let names = vec![String::new(); figures.len()];
    let mirror = o
        .mirror
        .unwrap_or(figures[0].lattice().lattice().dim() == 2);
    let config = EnumerateConfig {
        mirror,
        pieces: o.pieces,
        time_limit: limit,
        rank: o.rank,
        unique: o.rank == Some(Rank::Unique),
    };
    let _ = dissect_engine::enumerate(figures, &names, &config, &stop, &());
    let config = RunConfig {
        mirror,
        threads: 1,
        time_limit: limit,
        solutions: o.solutions.unwrap_or(1),
        rank: o.rank.unwrap_or_default(),
        constraints: c,
        ..RunConfig::default()
    };
    if let Ok(options) = RunOptions::new(config) {
        if dissect_engine::check(figures, &options).is_ok() {
            let _ = dissect_engine::run(figures, &names, &options, &stop, &());
        }
    }
}

/// The target.
pub fn target() -> Target {
    let seeds = [
        "square rank=variance min=1 max=3 keep=1\n--\n##\n##\n--\n####\n--\naa\n..\n--\n{\"format\": \"dissection-solution/1\", \"lattice\": \"square\", \"figures\": [{\"pieces\": [[[0,0],[1,0]], [[0,1],[1,1]]]}, {\"pieces\": [[[0,0],[1,0]], [[2,0],[3,0]]]}], \"constraints\": {\"min_piece\": 1}, \"ranking\": {\"by\": \"variance\"}}",
        "square rank=level pieces=2 solutions=2\n--\n###\n#..\n--\n####\n--\n\n--\n{\"format\": \"dissection-solution/1\", \"lattice\": \"square\", \"figures\": [{\"pieces\": [[[0,0],[1,0],[2,0]], [[0,1]]]}, {\"pieces\": [[[0,0],[1,0],[2,0]], [[3,0]]]}]}",
        "square checkerboard=1 rank=unique sym=0.5\n--\n##\n##\n--\n#\n#\n#\n#\n--\nab\nab\n--\n",
        "tri4 rank=shapes\n--\n#\n--\n#\n--\n\n--\n",
        "cubic rank=smallest pieces=2 keep=2\n--\n##\n--\n#\n\n#\n--\na\n\na\n--\n{\"format\": \"dissection-solution/1\", \"lattice\": \"cubic\", \"figures\": [{\"pieces\": [[[0,0,0]], [[1,0,0]]]}, {\"pieces\": [[[0,0,0]], [[0,0,1]]]}]}",
        "hex rank=symmetry mirror=0\n--\n##\n--\n#\n#\n--\n--\n",
    ];
    Target {
        name: "puzzle",
        seeds: seeds.iter().map(|s| s.as_bytes().to_vec()).collect(),
        max_len: 1 << 12,
        run: Box::new(|input| {
            let Ok(text) = std::str::from_utf8(input) else {
                return false;
            };
            let mut parts = text.split("\n--\n");
            let Some((lattice, o)) = parts.next().and_then(options) else {
                return false;
            };
            let (Some(a), Some(b)) = (parts.next(), parts.next()) else {
                return false;
            };
            let (Ok(a), Ok(b)) = (parse_figure(a, lattice), parse_figure(b, lattice)) else {
                return false;
            };
            let figures = [a, b];
            let regions = parts.next();
            let Some(c) = constraints(&o, regions, &figures) else {
                return false;
            };
            // The solver and the counts on small figures only: they run
            // under a time limit, but their setup grows with the cells.
            let small = cells(&figures) <= 24 && figures[0].len() == figures[1].len();
            let mut accepted = true;
            if let Some(s) = parts.next().filter(|s| !s.trim().is_empty()) {
                accepted = solution(s, &figures, &c, o.rank.unwrap_or_default());
            }
            if small && !figures[0].is_empty() {
                search(&figures, &o, c);
            }
            accepted
        }),
    }
}
