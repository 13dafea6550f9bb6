//! The exact local repair on near misses drawn as labelled ASCII figures:
//! each letter is a label (a piece of the candidate), '.' no cell. Every
//! dissection it returns is checked by `dissect_core::verify`, and one by
//! the independent checkers (`tools/check_solution.py`, and the external
//! `verify.py` when present).

use std::collections::BTreeMap;
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use dissect_core::io::parse_figure;
use dissect_core::Dissection;
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_exact::{repair, repair_report, ExactError, RepairOptions};

/// Figures and the candidate drawn by `texts` (letters: labels; on `cubic`
/// layers are separated by blank lines).
fn labelled(lattice: LatticeKind, texts: &[&str]) -> (Vec<Figure>, Vec<Vec<Vec<Cell>>>) {
    let letters: std::collections::BTreeSet<char> = texts
        .iter()
        .flat_map(|t| t.chars())
        .filter(|c| c.is_ascii_lowercase())
        .collect();
    let mut figs = Vec::new();
    let mut pieces = Vec::new();
    for t in texts {
        let plain: String = t
            .chars()
            .map(|c| if c.is_ascii_lowercase() { '#' } else { c })
            .collect();
        figs.push(parse_figure(&plain, lattice).expect("test figure parses"));
        let mut by_label: BTreeMap<char, Vec<Cell>> =
            letters.iter().map(|&l| (l, Vec::new())).collect();
        let (mut x, mut y, mut z) = (0, 0, 0);
        for line in t.lines() {
            if line.is_empty() {
                z += 1;
                y = 0;
                continue;
            }
            for ch in line.chars() {
                if ch.is_ascii_lowercase() {
                    by_label.get_mut(&ch).unwrap().push([x, y, z]);
                }
                x += 1;
            }
            x = 0;
            y += 1;
        }
        pieces.push(by_label.into_values().collect());
    }
    (figs, pieces)
}

fn verified(figs: &[Figure], pieces: &[Vec<Vec<Cell>>], mirror: bool) -> usize {
    let lattice = figs[0].lattice();
    dissect_core::verify::verify_pieces(lattice, mirror, figs, pieces)
        .unwrap_or_else(|v| panic!("not a dissection: {v:?}"))
}

/// The label of `cell` in figure `f` of a dissection, as its piece index.
fn piece_of(pieces: &[Vec<Vec<Cell>>], f: usize, cell: Cell) -> usize {
    pieces[f]
        .iter()
        .position(|p| p.contains(&cell))
        .expect("cell covered")
}

fn no_stop() -> AtomicBool {
    AtomicBool::new(false)
}

/// A 4×4 square to a 2×8 bar, two halves; in the bar one cell pair is
/// swapped (the cell of `a` at (4,0) is cut off from the rest).
const SWAPPED: [&str; 2] = ["aaaa\naaaa\nbbbb\nbbbb\n", "aaababbb\naaaabbbb\n"];

#[test]
fn a_swapped_pair_is_repaired_into_two_pieces() {
    let (figs, cand) = labelled(LatticeKind::Square, &SWAPPED);
    assert!(dissect_core::verify::verify_pieces(LatticeKind::Square, true, &figs, &cand).is_err());
    let report = repair_report(&figs, &cand, &RepairOptions::default(), &no_stop()).unwrap();
    let found = report.found.expect("repaired");
    assert_eq!(verified(&figs, &found, true), 2);
    assert!(report.trouble > 0 && report.free >= report.trouble);
    // Far from the swap the labels stay.
    let a = piece_of(&found, 0, [0, 0, 0]);
    assert_eq!(piece_of(&found, 1, [0, 1, 0]), a);
    assert_ne!(piece_of(&found, 1, [7, 1, 0]), a);
}

#[test]
fn a_two_cell_sliver_is_absorbed() {
    // In the bar, `a` took two cells of `b`: a column of two too many.
    let (figs, cand) = labelled(
        LatticeKind::Square,
        &["aaaa\naaaa\nbbbb\nbbbb\n", "aaaaabbb\naaaaabbb\n"],
    );
    let found = repair(&figs, &cand, &RepairOptions::default(), &no_stop())
        .unwrap()
        .expect("repaired");
    assert_eq!(verified(&figs, &found, true), 2);
}

#[test]
fn a_repair_may_need_a_turn_and_keeps_at_most_k_pieces() {
    // Three strips of a 6×6 square into a 2×18 bar: the strips turn; two
    // cells of the bar are swapped between `b` and `c`, and `a` holds a
    // stray cell inside `c`.
    let bar = "aa\n".repeat(6) + &"bb\n".repeat(5) + "bc\ncb\n" + "cc\ncc\nac\ncc\ncc\n";
    let (figs, cand) = labelled(
        LatticeKind::Square,
        &["aaaaaa\naaaaaa\nbbbbbb\nbbbbbb\ncccccc\ncccccc\n", &bar],
    );
    let found = repair(&figs, &cand, &RepairOptions::default(), &no_stop())
        .unwrap()
        .expect("repaired");
    assert!(verified(&figs, &found, true) <= 3);
}

#[test]
fn a_one_cell_piece_moved_by_a_swap_goes_home() {
    // `c` is one cell; in the bar it swapped places with a cell of `b`, so
    // its best motion is wrong and its cells are all freed.
    let (figs, cand) = labelled(
        LatticeKind::Square,
        &[
            "aaaaaa\naaaaaa\nbbbbbb\nbbbbbc\n",
            "aaaaaabbbbbb\naaaaaabbbbcb\n",
        ],
    );
    let report = repair_report(&figs, &cand, &RepairOptions::default(), &no_stop()).unwrap();
    let found = report.found.expect("repaired");
    // At most the candidate's 3 pieces (here the floating piece may even
    // vanish: two 6×2 halves).
    assert!(verified(&figs, &found, true) <= 3);
    assert_eq!(report.rounds, 1);
}

#[test]
fn cubic_near_miss_is_repaired() {
    // A 2×2×2 cube into a 4×2×1 slab: two 2×2×1 slabs; one pair swapped.
    let (figs, cand) = labelled(LatticeKind::Cubic, &["aa\naa\n\nbb\nbb\n", "abab\naabb\n"]);
    let found = repair(&figs, &cand, &RepairOptions::default(), &no_stop())
        .unwrap()
        .expect("repaired");
    assert_eq!(verified(&figs, &found, true), 2);
}

#[test]
fn three_figures_are_repaired_together() {
    let (figs, cand) = labelled(
        LatticeKind::Square,
        &[
            "aaaa\naaaa\nbbbb\nbbbb\n",
            "aaababbb\naaaabbbb\n",
            "aa\naa\naa\nab\nba\nbb\nbb\nbb\n",
        ],
    );
    let found = repair(&figs, &cand, &RepairOptions::default(), &no_stop())
        .unwrap()
        .expect("repaired");
    assert_eq!(verified(&figs, &found, true), 2);
}

#[test]
fn a_candidate_already_valid_comes_back() {
    let (figs, mut cand) = labelled(
        LatticeKind::Square,
        &["aaaa\naaaa\nbbbb\nbbbb\n", "aaaabbbb\naaaabbbb\n"],
    );
    cand.iter_mut().flatten().for_each(|p| p.sort());
    let report = repair_report(&figs, &cand, &RepairOptions::default(), &no_stop()).unwrap();
    assert_eq!(report.trouble, 0);
    assert_eq!(report.found.as_deref(), Some(&cand[..]));
}

#[test]
fn an_impossible_candidate_gives_none() {
    // One piece cannot be both a 2×2 square and a 1×4 bar.
    let (figs, cand) = labelled(LatticeKind::Square, &["aa\naa\n", "aaaa\n"]);
    let report = repair_report(&figs, &cand, &RepairOptions::default(), &no_stop()).unwrap();
    assert!(report.found.is_none());
    assert!(!report.stopped);
    assert!(report.rounds >= 1);
    // Without turning over, an S-tetromino is no Z-tetromino.
    let (figs, cand) = labelled(LatticeKind::Square, &["aa.\n.aa\n", ".aa\naa.\n"]);
    assert!(repair(&figs, &cand, &RepairOptions::default(), &no_stop())
        .unwrap()
        .is_some());
    let no_flip = RepairOptions {
        mirror: false,
        ..RepairOptions::default()
    };
    // (Rotations still map an S onto itself, not onto a Z.)
    assert!(repair(&figs, &cand, &no_flip, &no_stop())
        .unwrap()
        .is_none());
}

#[test]
fn the_free_region_cap_is_honoured() {
    let (figs, cand) = labelled(LatticeKind::Square, &SWAPPED);
    let tight = RepairOptions {
        max_free_cells: 3,
        ..RepairOptions::default()
    };
    let report = repair_report(&figs, &cand, &tight, &no_stop()).unwrap();
    assert!(report.found.is_none());
    assert_eq!(report.rounds, 0);
}

#[test]
fn bad_candidates_are_typed_errors() {
    let (figs, mut cand) = labelled(LatticeKind::Square, &SWAPPED);
    cand[1][0].push([9, 9, 0]);
    let err = repair(&figs, &cand, &RepairOptions::default(), &no_stop()).unwrap_err();
    assert!(matches!(err, ExactError::Candidate(ref m) if m.contains("not in the figure")));
    let (figs, mut cand) = labelled(LatticeKind::Square, &SWAPPED);
    cand[1][0].pop();
    let err = repair(&figs, &cand, &RepairOptions::default(), &no_stop()).unwrap_err();
    assert!(matches!(err, ExactError::Candidate(ref m) if m.contains("no label")));
    let (figs, mut cand) = labelled(LatticeKind::Square, &SWAPPED);
    cand[1].pop();
    assert!(matches!(
        repair(&figs, &cand, &RepairOptions::default(), &no_stop()),
        Err(ExactError::Candidate(_))
    ));
    assert!(matches!(
        repair(
            &figs[..1],
            &cand[..1],
            &RepairOptions::default(),
            &no_stop()
        ),
        Err(ExactError::Figures(_))
    ));
}

/// Two halves of a `2n × 2n` square into a `4n × n` bar, with `swaps` cell
/// pairs swapped along the seam of the bar.
fn big_near_miss(n: i32, swaps: i32) -> (Vec<Figure>, Vec<Vec<Vec<Cell>>>) {
    let square: String = (0..2 * n)
        .map(|y| {
            let ch = if y < n { 'a' } else { 'b' };
            ch.to_string().repeat(2 * n as usize) + "\n"
        })
        .collect();
    let bar: String = (0..n)
        .map(|y| {
            let mut row: Vec<char> = (0..4 * n)
                .map(|x| if x < 2 * n { 'a' } else { 'b' })
                .collect();
            if y % 3 == 0 && y / 3 < swaps {
                row.swap((2 * n - 1) as usize, (2 * n) as usize);
            }
            let mut row: String = row.into_iter().collect();
            row.push('\n');
            row
        })
        .collect();
    labelled(LatticeKind::Square, &[&square, &bar])
}

#[test]
fn a_larger_near_miss_is_repaired_deterministically() {
    let (figs, cand) = big_near_miss(15, 4);
    let options = RepairOptions::default();
    let first = repair_report(&figs, &cand, &options, &no_stop()).unwrap();
    let found = first.found.clone().expect("repaired");
    assert_eq!(verified(&figs, &found, true), 2);
    let again = repair_report(&figs, &cand, &options, &no_stop()).unwrap();
    assert_eq!(first, again);
}

#[test]
fn the_budget_is_honoured() {
    let (figs, cand) = labelled(LatticeKind::Square, &SWAPPED);
    let none = RepairOptions {
        budget: 0,
        ..RepairOptions::default()
    };
    let report = repair_report(&figs, &cand, &none, &no_stop()).unwrap();
    assert!(report.found.is_none());
    assert_eq!(report.conflicts, 0);
    // A budget caps the conflicts spent, whatever the outcome.
    let (figs, cand) = big_near_miss(12, 4);
    for budget in [1, 5, 50] {
        let options = RepairOptions {
            budget,
            ..RepairOptions::default()
        };
        let report = repair_report(&figs, &cand, &options, &no_stop()).unwrap();
        assert!(
            report.conflicts <= budget,
            "{} > {budget}",
            report.conflicts
        );
        if let Some(found) = &report.found {
            verified(&figs, found, true);
        }
    }
}

#[test]
fn stop_and_deadline_are_honoured() {
    let (figs, cand) = big_near_miss(15, 4);
    let stop = AtomicBool::new(true);
    let report = repair_report(&figs, &cand, &RepairOptions::default(), &stop).unwrap();
    assert!(report.stopped && report.found.is_none());
    let past = RepairOptions {
        deadline: Some(Instant::now() - Duration::from_millis(1)),
        ..RepairOptions::default()
    };
    let report = repair_report(&figs, &cand, &past, &no_stop()).unwrap();
    assert!(report.stopped && report.found.is_none());
}

#[test]
fn the_independent_checkers_accept_a_repair() {
    let texts = SWAPPED;
    let (figs, cand) = labelled(LatticeKind::Square, &texts);
    let pieces = repair(&figs, &cand, &RepairOptions::default(), &no_stop())
        .unwrap()
        .expect("repaired");
    let dir = tempfile::tempdir().unwrap();
    let mut paths = Vec::new();
    for (i, t) in texts.iter().enumerate() {
        let plain: String = t
            .chars()
            .map(|c| if c.is_ascii_lowercase() { '#' } else { c })
            .collect();
        let p = dir.path().join(format!("f{i}.txt"));
        std::fs::write(&p, plain).unwrap();
        paths.push(p);
    }
    let d = Dissection::new(
        LatticeKind::Square,
        true,
        vec!["f0.txt".into(), "f1.txt".into()],
        pieces,
    )
    .unwrap();
    let sol = dir.path().join("s.json");
    std::fs::write(&sol, d.to_file(Default::default()).to_json()).unwrap();
    assert_eq!(
        dissect_testkit::repo::assert_checked(dir.path(), "square", &sol, &paths),
        2
    );
}
