//! Levels: `λ`, level-1 explorations, growing a candidate by one piece, and
//! the objective of a candidate.

use std::sync::atomic::AtomicBool;

use crate::lattice::LatticeKind;
use crate::solver::levels::{grow, isolated, lambda, level_one, merge};
use crate::solver::Options;

use super::util::{candidate, rng, verified, Cubic, Square, Tri4};

fn small() -> Options {
    Options {
        iterations: 10,
        split_tries: 2,
        ..Options::default()
    }
}

#[test]
fn lambda_decays_by_level() {
    let o = Options::default();
    for (level, want) in [(1, 0.5), (2, 0.4), (3, 0.32), (4, 0.256)] {
        assert!((lambda(&o, level) - want).abs() < 1e-12, "level {level}");
    }
    let off = Options {
        area_weight: 0.0,
        ..Options::default()
    };
    assert_eq!(lambda(&off, 3), 0.0);
}

/// Level-1 explorations on the figures give two labels everywhere, and a
/// result scored valid passes the verifier.
fn check_level_one(lattice: LatticeKind, compact: &[&str]) {
    let (figures, problem, _) = candidate(lattice, true, compact);
    let mut valid = 0;
    for seed in 0..6 {
        let (cand, score) = level_one(&problem, &small(), &mut rng(seed), &AtomicBool::new(false));
        assert_eq!(cand.k, 2);
        for (f, labels) in cand.labels.iter().enumerate() {
            assert_eq!(labels.len(), figures[f].len());
            assert!(labels.iter().all(|l| *l < 2), "{labels:?}");
        }
        if score.valid {
            valid += 1;
            assert_eq!(score.mismatch, 0);
            assert!(
                verified(lattice, true, &figures, &cand),
                "{:?}",
                cand.labels
            );
        }
    }
    assert!(valid > 0, "no level-1 exploration solved {compact:?}");
}

#[test]
fn level_one_explorations() {
    check_level_one(Square, &["??|??|??", "??????"]);
    check_level_one(Square, &["??|??|??", "??????", "???|???"]);
    check_level_one(Tri4, &["???? ????", "????|????"]);
    check_level_one(Tri4, &["???? ?..?", ".??. ????"]);
    check_level_one(Cubic, &["??|??/??|??", "????|????"]);
}

/// Growing a candidate adds exactly one label and keeps every label in
/// range; a result scored valid passes the verifier.
fn check_grow(lattice: LatticeKind, labelled: &[&str]) {
    let (figures, problem, parent) = candidate(lattice, true, labelled);
    let mut valid = 0;
    for seed in 0..40 {
        let (cand, score) = grow(
            &problem,
            &parent,
            parent.k,
            &small(),
            &mut rng(seed),
            &AtomicBool::new(false),
        );
        assert_eq!(cand.k, parent.k + 1);
        for labels in &cand.labels {
            assert!(labels.iter().all(|l| (*l as usize) < cand.k), "{labels:?}");
        }
        if score.valid {
            valid += 1;
            assert!(
                verified(lattice, true, &figures, &cand),
                "{:?}",
                cand.labels
            );
        }
    }
    assert!(
        valid > 0,
        "growing {labelled:?} never gave a valid dissection"
    );
}

#[test]
fn growing_by_one_piece() {
    // A 3x3 square against a 1x9 bar: three bars of three.
    check_grow(Square, &["AAA|AAA|BBB", "AAAAAABBB"]);
    check_grow(Square, &["AAA|AAA|BBB", "AAAAAABBB", "AAAAAA|BBB"]);
    check_grow(Cubic, &["AA|AA/BB|BB", "AAAA|AAAA"]);
}

#[test]
fn objective() {
    // Valid: no mismatch, no split; areas 2 and 2.
    let (_, problem, mut cand) = candidate(Square, true, &["AB|AB", "AABB"]);
    let s = cand.evaluate(&problem, 0.5, 1000.0);
    assert!(s.valid);
    assert_eq!((s.mismatch, s.split, s.value, s.variance), (0, 0, 0.0, 0.0));
    // I3 + single against L3 + single: E_M = D(I3, L3) = 2; no area term.
    let (_, problem, mut cand) = candidate(Square, true, &["AAAB", "AA|AB"]);
    let s = cand.evaluate(&problem, 0.5, 1000.0);
    assert!(!s.valid);
    assert_eq!((s.mismatch, s.split), (2, 0));
    assert_eq!(s.value, 2.0);
    assert_eq!(s.variance, 1.0);
    // Areas 4 and 1 (mean 2.5): the small piece costs 2.5/1 - 1 per figure.
    let (_, problem, mut cand) = candidate(Square, true, &["AAAAB", "AAAAB"]);
    let s = cand.evaluate(&problem, 0.5, 1000.0);
    assert!(s.valid);
    assert_eq!(s.value, 0.5 * 3.0);
    assert_eq!(s.variance, 2.25);
    // A split piece is penalised and never valid.
    let (_, problem, mut cand) = candidate(Square, true, &["ABA", "ABA"]);
    let s = cand.evaluate(&problem, 0.0, 1000.0);
    assert!(!s.valid);
    assert_eq!((s.mismatch, s.split), (0, 2));
    assert_eq!(s.value, 2000.0);
}

/// Piece A is a whole component of the first figure (a lone cell): it
/// touches no other piece there, so it is isolated; B and C touch in
/// both figures.
const LONE: [&str; 2] = ["A.BBC|..BBC", "BBA|BBC|..C"];

#[test]
fn isolated_pieces_are_whole_components_somewhere() {
    let (_, problem, cand) = candidate(Square, true, &LONE);
    assert_eq!(isolated(&problem, &cand), vec![true, false, false]);
    // Every piece touches another in both figures: none is isolated.
    let (_, problem, cand) = candidate(Square, true, &["AB|CC", "AB|CC"]);
    assert_eq!(isolated(&problem, &cand), vec![false, false, false]);
}

/// The descent's merge never merges a piece that is a whole component of
/// a figure (the result would be split there): the lone cell keeps a
/// label of its own in every exploration.
#[test]
fn merge_keeps_whole_components_apart() {
    let (figures, problem, cand) = candidate(Square, true, &LONE);
    let no_refining = Options {
        iterations: 0,
        ..small()
    };
    let lone = figures[0]
        .cells()
        .iter()
        .position(|c| *c == [0, 0, 0])
        .expect("the lone cell");
    for seed in 0..40 {
        let stop = AtomicBool::new(false);
        let (merged, _) = merge(&problem, &cand, 1, &no_refining, &mut rng(seed), &stop);
        assert_eq!(merged.k, 2);
        let labels = &merged.labels[0];
        let shared = labels.iter().filter(|&&l| l == labels[lone]).count();
        assert_eq!(shared, 1, "seed {seed}: {labels:?}");
    }
}
