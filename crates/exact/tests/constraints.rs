//! The designer's constraints in the exact search: on small ASCII figures
//! each changes the minimum dissection, and every dissection found honours
//! them (checked by `Constraints::check` and `dissect_core::verify`).

use std::sync::atomic::{AtomicBool, AtomicUsize};

use dissect_core::io::parse_figure;
use dissect_core::verify::verify_pieces;
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_exact::{search, ExactOptions, Mode};
use dissect_puzzle::{Constraints, KeepRegions, Motions};

fn figures(lattice: LatticeKind, texts: &[&str]) -> Vec<Figure> {
    texts
        .iter()
        .map(|t| parse_figure(t, lattice).unwrap())
        .collect()
}

/// The minimum piece count under `c` (None when there is no dissection),
/// after checking that the dissection is valid and honours `c`.
fn minimum(figs: &[Figure], mirror: bool, c: Constraints) -> Option<usize> {
    c.validate(figs).expect("valid constraints");
    let options = ExactOptions {
        mirror,
        mode: Mode::Minimum,
        constraints: Some(c.clone()),
        ..ExactOptions::default()
    };
    let out = search(
        figs,
        &options,
        &AtomicBool::new(false),
        &AtomicUsize::new(usize::MAX),
        &(),
    )
    .expect("search runs");
    assert!(!out.stopped);
    let found: Vec<Vec<Vec<Cell>>> = out.found?;
    let lattice = figs[0].lattice();
    verify_pieces(lattice, mirror, figs, &found).expect("valid dissection");
    let broken = c.check(&Motions::new(lattice, mirror), &found);
    assert!(broken.is_empty(), "{broken:?}");
    Some(found[0].len())
}

#[test]
fn keep_regions_change_the_minimum() {
    let figs = figures(LatticeKind::Square, &["###\n###\n", "######\n"]);
    assert_eq!(minimum(&figs, true, Constraints::none()), Some(2));
    // A vertical pair kept whole cannot lie in a 1x6 bar unless it is a
    // piece of its own: three vertical dominoes.
    let keep = KeepRegions::parse("a..\na..\n", 0, &figs).unwrap();
    assert_eq!(
        minimum(&figs, true, Constraints::none().with_keep(keep)),
        Some(3)
    );
    // A region on the second figure: the bar's two ends in one piece means
    // one piece of 6 cells, which the rectangle is not.
    let keep = KeepRegions::parse("a....a\n", 1, &figs).unwrap();
    assert_eq!(
        minimum(&figs, true, Constraints::none().with_keep(keep)),
        None
    );
}

#[test]
fn piece_sizes_change_the_minimum() {
    let figs = figures(LatticeKind::Square, &["##\n##\n", "####\n"]);
    assert_eq!(minimum(&figs, true, Constraints::none()), Some(2));
    let c = Constraints::none().with_sizes(None, Some(1));
    assert_eq!(minimum(&figs, true, c), Some(4));
    // Pieces of at least 3 cells: one piece of 4, which does not fit.
    let c = Constraints::none().with_sizes(Some(3), None);
    assert_eq!(minimum(&figs, true, c), None);
    // 3x3 square to 1x9 bar: 3 bars of 3; at most 2 cells: 5 pieces.
    let figs = figures(LatticeKind::Square, &["###\n###\n###\n", "#########\n"]);
    assert_eq!(minimum(&figs, true, Constraints::none()), Some(3));
    let c = Constraints::none().with_sizes(None, Some(2));
    assert_eq!(minimum(&figs, true, c), Some(5));
}

#[test]
fn piece_sizes_beyond_the_figure_are_answered_without_counting_to_them() {
    // The fuzzer's input: a maximum of usize::MAX once asked the size
    // counter for that many variables (an allocation of 128 GB).
    let figs = figures(LatticeKind::Square, &["##\n##\n", "####\n"]);
    let c = Constraints::none().with_sizes(None, Some(usize::MAX));
    assert_eq!(minimum(&figs, true, c), Some(2));
    let c = Constraints::none().with_sizes(Some(1), Some(4));
    assert_eq!(minimum(&figs, true, c), Some(2));
    // A minimum of the whole area: the square in one piece, not a bar.
    let c = Constraints::none().with_sizes(Some(4), Some(usize::MAX));
    assert_eq!(minimum(&figs, false, c), None);
}

#[test]
fn the_checkerboard_changes_the_minimum() {
    // An L tetromino and the same L one column to the right: one piece by a
    // translation that swaps colours, so two pieces with --checkerboard.
    let figs = figures(LatticeKind::Square, &["#.\n#.\n##\n", ".#.\n.#.\n.##\n"]);
    assert_eq!(minimum(&figs, true, Constraints::none()), Some(1));
    let c = Constraints::none().with_checkerboard(true);
    assert_eq!(minimum(&figs, true, c), Some(2));
    // Cubic: the same L as a layer of cubes.
    let figs = figures(LatticeKind::Cubic, &["#.\n#.\n##\n", ".#.\n.#.\n.##\n"]);
    assert_eq!(minimum(&figs, false, Constraints::none()), Some(1));
    let c = Constraints::none().with_checkerboard(true);
    assert_eq!(minimum(&figs, false, c), Some(2));
}
