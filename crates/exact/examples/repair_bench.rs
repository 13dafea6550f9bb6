//! Measures the exact repair on near misses of a real instance.
//!
//! `cargo run --release -p dissect-exact --example repair_bench -- DIR [SEED] [SECONDS] [SOLUTION.json]`
//!
//! Solves the instance in `DIR` (`a.txt`, `b.txt`, ... on the square
//! lattice, or the lattice named by `DIR/lattice`) with the heuristic of
//! `dissect_core` (SEED, at most SECONDS), or reads a valid dissection from
//! SOLUTION.json, then spoils the dissection in two ways and repairs each:
//! * `swap-s`: `s` random pairs of neighbouring cells of different pieces
//!   swap labels in one figure (a near miss of matching cost about 2s);
//! * `merge`: one of the smallest pieces is merged into the neighbour it
//!   shares most edges with (in every figure): a candidate with one piece
//!   fewer, which the repair must turn into a real dissection.
//!
//! Prints one line per case: outcome, milliseconds, trouble and free cells,
//! rounds and SAT conflicts.

use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use dissect_core::io::parse_figure;
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_exact::{repair_report, RepairOptions};

struct Lcg(u64);

impl Lcg {
    fn below(&mut self, n: usize) -> usize {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 33) % n as u64) as usize
    }
}

fn main() {
    let args: Vec<String> = std::env::args().skip(1).collect();
    let dir = std::path::PathBuf::from(args.first().expect("an instance directory"));
    let seed: u64 = args.get(1).map_or(1, |s| s.parse().expect("a seed"));
    let seconds: u64 = args.get(2).map_or(60, |s| s.parse().expect("seconds"));
    let lattice = std::fs::read_to_string(dir.join("lattice"))
        .ok()
        .map_or(LatticeKind::Square, |s| {
            s.trim().parse().expect("a lattice")
        });
    let figures: Vec<Figure> = ["a.txt", "b.txt", "c.txt", "d.txt"]
        .iter()
        .filter_map(|n| std::fs::read_to_string(dir.join(n)).ok())
        .map(|t| parse_figure(&t, lattice).expect("figure parses"))
        .collect();
    let start = Instant::now();
    let pieces = match args.get(3) {
        Some(path) => {
            let text = std::fs::read_to_string(path).expect("a solution file");
            dissect_core::io::parse_solution(&text)
                .expect("a solution")
                .1
                .pieces()
                .to_vec()
        }
        None => match heuristic(&figures, seed, seconds) {
            Some(p) => p,
            None => {
                println!("heuristic found nothing in {seconds} s");
                return;
            }
        },
    };
    spoil_and_repair(&dir, &figures, lattice, pieces, seed, start);
}

/// A valid dissection by the heuristic, if it finds one in `seconds`.
fn heuristic(figures: &[Figure], seed: u64, seconds: u64) -> Option<Vec<Vec<Vec<Cell>>>> {
    let options = dissect_core::solver::Options {
        seed,
        ..Default::default()
    };
    let stop = AtomicBool::new(false);
    let start = Instant::now();
    let outcome = std::thread::scope(|s| {
        let h = s.spawn(|| dissect_core::solver::solve(figures, &options, &stop, &()));
        while !h.is_finished() && start.elapsed() < Duration::from_secs(seconds) {
            std::thread::sleep(Duration::from_millis(50));
        }
        stop.store(true, std::sync::atomic::Ordering::SeqCst);
        h.join().expect("solver thread")
    })
    .expect("solves");
    outcome.found.map(|f| f.pieces)
}

fn spoil_and_repair(
    dir: &std::path::Path,
    figures: &[Figure],
    lattice: LatticeKind,
    pieces: Vec<Vec<Vec<Cell>>>,
    seed: u64,
    start: Instant,
) {
    let k = pieces[0].len();
    println!(
        "{}: {} cells, a valid dissection of {} pieces in {:.1} s",
        dir.display(),
        figures[0].len(),
        k,
        start.elapsed().as_secs_f64()
    );
    let lat = lattice.lattice();
    let label_of =
        |f: usize, pieces: &[Vec<Vec<Cell>>]| -> std::collections::HashMap<Cell, usize> {
            pieces[f]
                .iter()
                .enumerate()
                .flat_map(|(i, p)| p.iter().map(move |c| (*c, i)))
                .collect()
        };
    let options = RepairOptions::default();
    let mut rng = Lcg(seed);
    let run = |name: String, cand: Vec<Vec<Vec<Cell>>>| {
        let stop = AtomicBool::new(false);
        let t = Instant::now();
        let r = repair_report(figures, &cand, &options, &stop).expect("valid candidate");
        println!(
            "{name:10} {:5} {:7.1} ms  trouble {:4}  free {:4}  rounds {}  conflicts {}  cuts {}",
            match &r.found {
                Some(p) => format!("{}p", p[0].len()),
                None => "none".to_string(),
            },
            t.elapsed().as_secs_f64() * 1000.0,
            r.trouble,
            r.free,
            r.rounds,
            r.conflicts,
            r.cuts
        );
        r.found.is_some()
    };
    for swaps in [1, 2, 4] {
        let mut ok = 0;
        let trials = 5;
        for trial in 0..trials {
            let f = 1 + trial % (figures.len() - 1);
            let mut cand = pieces.clone();
            for _ in 0..swaps {
                let labels = label_of(f, &cand);
                let pairs: Vec<(Cell, Cell)> = figures[f]
                    .cells()
                    .iter()
                    .flat_map(|c| lat.neighbors(*c).into_iter().map(move |d| (*c, d)))
                    .filter(|(c, d)| labels.get(d).is_some_and(|l| *l != labels[c]))
                    .collect();
                if pairs.is_empty() {
                    break;
                }
                let (c, d) = pairs[rng.below(pairs.len())];
                let (lc, ld) = (labels[&c], labels[&d]);
                cand[f][lc].retain(|x| *x != c);
                cand[f][ld].retain(|x| *x != d);
                cand[f][lc].push(d);
                cand[f][ld].push(c);
            }
            ok += usize::from(run(format!("swap-{swaps}"), cand));
        }
        println!("swap-{swaps}: {ok}/{trials} repaired");
    }
    // Merge each of the six smallest pieces into its best neighbour.
    let mut order: Vec<usize> = (0..k).collect();
    order.sort_by_key(|&i| (pieces[0][i].len(), i));
    let mut ok = 0;
    let tries = order.len().min(6);
    for &small in order.iter().take(tries) {
        let labels = label_of(0, &pieces);
        let mut shared = vec![0usize; k];
        for c in &pieces[0][small] {
            for d in lat.neighbors(*c) {
                if let Some(&l) = labels.get(&d) {
                    if l != small {
                        shared[l] += 1;
                    }
                }
            }
        }
        let Some(into) = (0..k)
            .filter(|&l| shared[l] > 0)
            .max_by_key(|&l| (shared[l], l))
        else {
            continue;
        };
        let cand: Vec<Vec<Vec<Cell>>> = pieces
            .iter()
            .map(|fp| {
                let mut fp = fp.clone();
                let moved = std::mem::take(&mut fp[small]);
                fp[into].extend(moved);
                fp.remove(small);
                fp
            })
            .collect();
        ok += usize::from(run(format!("merge-{}", pieces[0][small].len()), cand));
    }
    println!(
        "merge: {ok}/{tries} repaired into {} pieces or fewer",
        k - 1
    );
}
