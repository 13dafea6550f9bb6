//! Constraints: reading regions grids, validating, checking dissections.

use dissect_core::io::parse_figure;
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_puzzle::constraints::{ConstraintError, Violation};
use dissect_puzzle::{Constraints, KeepRegions, Motions};

fn fig(text: &str, lattice: LatticeKind) -> Figure {
    parse_figure(text, lattice).unwrap()
}

#[test]
fn regions_grid_on_each_lattice() {
    let square = fig("###\n###\n", LatticeKind::Square);
    let k = KeepRegions::parse("a.b\n#a.\n", 0, std::slice::from_ref(&square)).unwrap();
    let r: Vec<(char, Vec<Cell>)> = k.regions().map(|(l, c)| (l, c.to_vec())).collect();
    assert_eq!(
        r,
        vec![('a', vec![[0, 0, 0], [1, 1, 0]]), ('b', vec![[2, 0, 0]])]
    );
    // tri4: a letter takes every triangle of its square in the figure.
    let tri = fig("#C\n", LatticeKind::Tri4);
    let k = KeepRegions::parse(".a\n", 0, &[tri]).unwrap();
    assert_eq!(k.regions().next().unwrap().1, &[[1, 0, 2], [1, 0, 3]]);
    // cubic: one block of rows per z layer.
    let cube = fig("##\n\n##\n", LatticeKind::Cubic);
    let k = KeepRegions::parse("a.\n\n.a\n", 0, &[cube]).unwrap();
    assert_eq!(k.regions().next().unwrap().1, &[[0, 0, 0], [1, 0, 1]]);
}

#[test]
fn regions_grid_errors_name_line_and_column() {
    let square = fig("###\n###\n", LatticeKind::Square);
    let e = KeepRegions::parse("a..\n.A.\n", 0, std::slice::from_ref(&square)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 2, column 2: unexpected character 'A' (a regions grid allows the letters a-z, '.' and '#')"
    );
    let e = KeepRegions::parse("a..\n...\n..b\n", 0, std::slice::from_ref(&square)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 3, column 3: 'b' marks a place where figure 1 has no cell"
    );
    assert_eq!(
        KeepRegions::parse("...\n", 0, std::slice::from_ref(&square)).unwrap_err(),
        ConstraintError::NoRegion
    );
    assert_eq!(
        KeepRegions::parse("a\n", 2, &[square])
            .unwrap_err()
            .to_string(),
        "figure 3 does not exist (there are 1 figures, numbered from 1)"
    );
    let cube = fig("##\n\n##\n", LatticeKind::Cubic);
    assert_eq!(
        KeepRegions::parse("a.\n\n\n.a\n", 0, &[cube])
            .unwrap_err()
            .to_string(),
        "line 3: more than one blank line between z layers"
    );
}

#[test]
fn validation_finds_impossible_constraints() {
    let a = fig("####\n####\n", LatticeKind::Square);
    let b = fig("########\n", LatticeKind::Square);
    let figs = [a, b];
    let v = |c: Constraints| c.validate(&figs).map_err(|e| e.to_string());
    assert_eq!(v(Constraints::none().with_sizes(Some(2), Some(6))), Ok(()));
    assert!(v(Constraints::none().with_sizes(Some(5), Some(4)))
        .unwrap_err()
        .contains("impossible: --min-piece 5 is larger than --max-piece 4"));
    assert!(v(Constraints::none().with_sizes(Some(9), None))
        .unwrap_err()
        .contains("larger than the figures (8 cells)"));
    assert!(v(Constraints::none().with_sizes(None, Some(0)))
        .unwrap_err()
        .contains("--max-piece must be at least 1"));
    let keep = KeepRegions::parse("aaa\n", 0, &figs).unwrap();
    assert!(v(Constraints::none()
        .with_keep(keep)
        .with_sizes(None, Some(2)))
    .unwrap_err()
    .contains("region 'a' of figure 1 has 3 cells, more than --max-piece 2"));
    assert!(v(Constraints::none().with_symmetry_weight(-1.0))
        .unwrap_err()
        .contains("--symmetry-weight"));
    // Checkerboard: 4 black cells in each figure is fine; a 3x3 square
    // against a 1x9 bar has 4 against 5... both colourings count from (0,0).
    assert_eq!(v(Constraints::none().with_checkerboard(true)), Ok(()));
    let c = fig("###\n###\n###\n", LatticeKind::Square);
    let d = fig("#########\n", LatticeKind::Square);
    let e = fig("#.#.#\n.#.#.\n#.#.#\n.#.#.\n#.#.#\n", LatticeKind::Square);
    assert!(Constraints::none()
        .with_checkerboard(true)
        .validate(&[c.clone(), d])
        .is_ok());
    assert!(Constraints::none()
        .with_checkerboard(true)
        .validate(&[c, e])
        .unwrap_err()
        .to_string()
        .contains("different numbers of black cells (figure 1: 4, figure 2: 0)"));
    let t = fig("#\n", LatticeKind::Tri4);
    assert!(Constraints::none()
        .with_checkerboard(true)
        .validate(&[t.clone(), t])
        .unwrap_err()
        .to_string()
        .contains("not tri4"));
}

#[test]
fn check_reports_each_broken_constraint() {
    let lattice = LatticeKind::Square;
    let a = fig("####\n", lattice);
    let b = fig("##\n##\n", lattice);
    let figs = [a, b];
    // Piece 0: the left domino of the bar, to the top row of the square
    // (a translation); piece 1: the right domino, to the bottom row.
    let good = vec![
        vec![vec![[0, 0, 0], [1, 0, 0]], vec![[2, 0, 0], [3, 0, 0]]],
        vec![vec![[0, 0, 0], [1, 0, 0]], vec![[0, 1, 0], [1, 1, 0]]],
    ];
    let m = Motions::new(lattice, true);
    let keep = KeepRegions::parse(".aa.\n", 0, &figs).unwrap();
    let c = Constraints::none().with_keep(keep.clone());
    assert_eq!(
        c.check(&m, &good),
        vec![Violation::RegionSplit {
            figure: 0,
            letter: 'a',
            pieces: vec![0, 1]
        }]
    );
    let ok = KeepRegions::parse("aa..\n", 0, &figs).unwrap();
    assert!(Constraints::none()
        .with_keep(ok)
        .check(&m, &good)
        .is_empty());
    let c = Constraints::none().with_sizes(Some(3), Some(1));
    assert_eq!(c.check(&m, &good).len(), 4);
    // Checkerboard: piece 1 moves by (-2, 1), which keeps colours.
    let c = Constraints::none().with_checkerboard(true);
    assert!(c.check(&m, &good).is_empty());
    // Piece 0 moved by (0, 1) alone would swap them, but a domino also
    // reaches there by a half turn, (0,0),(1,0) -> (1,1),(0,1), which keeps
    // them.
    let swapped = vec![
        vec![vec![[0, 0, 0], [1, 0, 0]], vec![[2, 0, 0], [3, 0, 0]]],
        vec![vec![[0, 1, 0], [1, 1, 0]], vec![[0, 0, 0], [1, 0, 0]]],
    ];
    assert!(c.check(&m, &swapped).is_empty());
    // A single cell moved by one step cannot keep its colour.
    let moved = vec![vec![vec![[0, 0, 0]]], vec![vec![[1, 0, 0]]]];
    assert_eq!(
        c.check(&m, &moved),
        vec![Violation::Colour {
            piece: 0,
            figure: 1
        }]
    );
}

#[test]
fn constraints_are_recorded_as_json() {
    let a = fig("##\n", LatticeKind::Square);
    let keep = KeepRegions::parse("aa\n", 0, &[a]).unwrap();
    let c = Constraints::none()
        .with_keep(keep)
        .with_sizes(Some(1), Some(2))
        .with_checkerboard(true)
        .with_symmetry_weight(0.5);
    assert_eq!(
        c.to_json(LatticeKind::Square).to_string(),
        r#"{"checkerboard":true,"keep":[{"figure":1,"regions":{"a":[[0,0],[1,0]]}}],"max_piece":2,"min_piece":1,"symmetry_weight":0.5}"#
    );
}

#[test]
fn distance_counts_split_regions_and_cells_out_of_bounds() {
    let square = fig("####\n", LatticeKind::Square);
    let k = KeepRegions::parse("aa.b\n", 0, std::slice::from_ref(&square)).unwrap();
    let c = Constraints::none()
        .with_keep(k)
        .with_sizes(Some(2), Some(3));
    let sq = |xs: &[i32]| xs.iter().map(|&x| [x, 0, 0]).collect::<Vec<Cell>>();
    // a split between two pieces: 1; pieces of 1 and 3 cells: 1 below the least.
    assert_eq!(c.distance(&[vec![sq(&[0]), sq(&[1, 2, 3])]]), 2);
    assert_eq!(c.distance(&[vec![sq(&[0, 1]), sq(&[2, 3])]]), 0);
    assert_eq!(c.distance(&[vec![sq(&[0, 1, 2, 3])]]), 1);
}

#[test]
fn impossible_and_malformed_constraints_are_told_apart() {
    let s = |min, max| Constraints::none().with_sizes(min, max).validate_settings();
    assert!(s(Some(3), Some(2)).unwrap_err().is_impossible());
    assert!(!s(Some(0), None).unwrap_err().is_impossible());
    assert_eq!(s(Some(2), Some(3)), Ok(()));
    let w = Constraints::none().with_symmetry_weight(f64::NAN);
    assert!(!w.validate_settings().unwrap_err().is_impossible());
}

#[test]
fn regions_from_cells_name_a_bad_letter_or_cell() {
    use std::collections::BTreeMap;
    let square = fig("###\n###\n", LatticeKind::Square);
    let figs = std::slice::from_ref(&square);
    let k = KeepRegions::from_cells(
        0,
        BTreeMap::from([('b', vec![[2, 1, 0], [0, 0, 0], [2, 1, 0]]), ('c', vec![])]),
        figs,
    )
    .unwrap();
    let r: Vec<(char, Vec<Cell>)> = k.regions().map(|(l, c)| (l, c.to_vec())).collect();
    assert_eq!(r, vec![('b', vec![[0, 0, 0], [2, 1, 0]])]);
    let e = KeepRegions::from_cells(0, BTreeMap::from([('A', vec![[0, 0, 0]])]), figs).unwrap_err();
    assert_eq!(
        e.to_string(),
        "a region is named by one letter a-z, not \"A\""
    );
    assert!(!e.is_impossible());
    let e = KeepRegions::from_cells(0, BTreeMap::from([('a', vec![[3, 0, 0]])]), figs).unwrap_err();
    assert_eq!(
        e.to_string(),
        "region 'a': cell [3, 0] is not a cell of figure 1"
    );
    let e = KeepRegions::from_cells(0, BTreeMap::from([('a', vec![])]), figs).unwrap_err();
    assert_eq!(e, ConstraintError::NoRegion);
    let e = KeepRegions::from_cells(1, BTreeMap::new(), figs).unwrap_err();
    assert_eq!(
        e.to_string(),
        "figure 2 does not exist (there are 1 figures, numbered from 1)"
    );
}
