//! The independent verifier: it accepts valid dissections on every lattice
//! and names every kind of violation.

use dissect_core::verify::{verify, verify_pieces, Violation};
use dissect_core::{Cell, Dissection, Figure, LatticeKind};

use super::util::{dissection, Cubic, Square, Tri4};

/// The labelled figures are a valid dissection into `n` pieces.
fn check_valid(lattice: LatticeKind, mirror: bool, labelled: &[&str], n: usize) {
    let (figures, d) = dissection(lattice, mirror, labelled);
    assert_eq!(verify(&d, &figures), Ok(n), "{labelled:?} on {lattice}");
}

/// The labelled figures, after `edit`, give exactly `violations`.
fn check_invalid(
    lattice: LatticeKind,
    mirror: bool,
    labelled: &[&str],
    edit: impl FnOnce(&mut Parts, &mut Vec<Figure>),
    violations: &[Violation],
) {
    let (mut figures, d) = dissection(lattice, mirror, labelled);
    let (lattice, mirror, names, pieces) = d.into_parts();
    let mut parts = Parts {
        lattice,
        mirror,
        names,
        pieces,
    };
    edit(&mut parts, &mut figures);
    let d = Dissection::new(parts.lattice, parts.mirror, parts.names, parts.pieces)
        .expect("edits keep cells of the lattice");
    assert_eq!(
        verify(&d, &figures),
        Err(violations.to_vec()),
        "{labelled:?} on {lattice}"
    );
}

fn no_edit(_: &mut Parts, _: &mut Vec<Figure>) {}

/// A dissection taken apart, to be edited into an invalid one.
struct Parts {
    lattice: LatticeKind,
    mirror: bool,
    names: Vec<String>,
    pieces: Vec<Vec<Vec<Cell>>>,
}

/// Two vertical dominoes and two horizontal ones.
const DOMINOES: [&str; 2] = ["AB|AB", "AABB"];

#[test]
fn accepts_valid_dissections() {
    check_valid(Square, true, &DOMINOES, 2);
    check_valid(Square, false, &DOMINOES, 2);
    check_valid(Square, true, &["AB|AB", "AABB", "A|A|B|B"], 2);
    check_valid(Square, true, &["AAB|ACB|CCB", "AABBB|.ACC.|..C.."], 3);
    // One piece: the figures themselves are congruent.
    check_valid(Square, false, &[".A|.A|AA", "AAA|..A"], 1);
    // Mirror images with mirror allowed (L and J tetrominoes, S and Z).
    check_valid(Square, true, &[".A|.A|AA", "A.|A.|AA"], 1);
    check_valid(Square, true, &[".AA|AA.", "AA.|.AA"], 1);
    // tri4: two right triangles of 4 cells make a big triangle and a diamond.
    check_valid(Tri4, true, &["AABB A..A|B..B .", ".AA. ..AA|BB.. B..B"], 2);
    check_valid(Tri4, false, &["AABB A..A|B..B .", ".AA. ..AA|BB.. B..B"], 2);
    check_valid(Tri4, true, &["AAAA A..A", "AA.. AAAA"], 1);
    // cubic: a 2x2x2 cube as two slabs, and a 4x2x1 box.
    check_valid(Cubic, false, &["AA|AA/BB|BB", "AABB|AABB"], 2);
    check_valid(Cubic, true, &["AA|AA/BB|BB", "AABB|AABB", "AA|AA|BB|BB"], 2);
    // A chiral tetracube turned by a rotation.
    check_valid(Cubic, false, &["AA|.A/..|.A", "A.|A./..|AA"], 1);
}

#[test]
fn rejects_overlap() {
    check_invalid(
        Square,
        true,
        &DOMINOES,
        |d, _| d.pieces[0][1].push([0, 0, 0]),
        &[
            Violation::Overlap {
                figure: 0,
                cell: [0, 0, 0],
            },
            Violation::NotCongruent {
                figure: 1,
                piece: 1,
            },
        ],
    );
    // A cell listed twice inside one piece is an overlap too.
    check_invalid(
        Square,
        true,
        &DOMINOES,
        |d, _| d.pieces[1][0].push([0, 0, 0]),
        &[
            Violation::Overlap {
                figure: 1,
                cell: [0, 0, 0],
            },
            Violation::NotCongruent {
                figure: 1,
                piece: 0,
            },
        ],
    );
}

#[test]
fn rejects_uncovered_cells() {
    check_invalid(
        Square,
        true,
        &DOMINOES,
        |d, _| {
            d.pieces[0][1].retain(|c| *c != [1, 1, 0]);
        },
        &[
            Violation::Uncovered {
                figure: 0,
                count: 1,
                example: [1, 1, 0],
            },
            Violation::NotCongruent {
                figure: 1,
                piece: 1,
            },
        ],
    );
    // The figure grew a cell that no piece lists.
    check_invalid(
        Cubic,
        false,
        &["AA|AA/BB|BB", "AABB|AABB"],
        |_, figs| {
            let cells = figs[1]
                .cells()
                .iter()
                .copied()
                .chain([[9, 9, 9], [9, 9, 8]]);
            figs[1] = Figure::new(Cubic, cells).unwrap();
        },
        &[Violation::Uncovered {
            figure: 1,
            count: 2,
            example: [9, 9, 8],
        }],
    );
}

#[test]
fn rejects_cells_outside_the_figure() {
    check_invalid(
        Square,
        true,
        &DOMINOES,
        |d, _| d.pieces[1][0].push([5, 5, 0]),
        &[
            Violation::OutsideFigure {
                figure: 1,
                piece: 0,
                cell: [5, 5, 0],
            },
            Violation::Disconnected {
                figure: 1,
                piece: 0,
                components: 2,
            },
            Violation::NotCongruent {
                figure: 1,
                piece: 0,
            },
        ],
    );
    check_invalid(
        Tri4,
        true,
        &["AAAA A..A", "AA.. AAAA"],
        |d, _| d.pieces[1][0].push([0, 0, 2]),
        &[
            Violation::OutsideFigure {
                figure: 1,
                piece: 0,
                cell: [0, 0, 2],
            },
            Violation::NotCongruent {
                figure: 1,
                piece: 0,
            },
        ],
    );
}

#[test]
fn rejects_disconnected_pieces() {
    check_invalid(
        Square,
        true,
        &["ABA", "ABA"],
        no_edit,
        &[
            Violation::Disconnected {
                figure: 0,
                piece: 0,
                components: 2,
            },
            Violation::Disconnected {
                figure: 1,
                piece: 0,
                components: 2,
            },
        ],
    );
    // Top and bottom triangles of one square touch only at a point.
    check_invalid(
        Tri4,
        true,
        &["ABAB", "ABAB"],
        no_edit,
        &[
            Violation::Disconnected {
                figure: 0,
                piece: 0,
                components: 2,
            },
            Violation::Disconnected {
                figure: 0,
                piece: 1,
                components: 2,
            },
            Violation::Disconnected {
                figure: 1,
                piece: 0,
                components: 2,
            },
            Violation::Disconnected {
                figure: 1,
                piece: 1,
                components: 2,
            },
        ],
    );
    // Cubes sharing only an edge.
    check_invalid(
        Cubic,
        false,
        &["A./.A", "A./.A"],
        no_edit,
        &[
            Violation::Disconnected {
                figure: 0,
                piece: 0,
                components: 2,
            },
            Violation::Disconnected {
                figure: 1,
                piece: 0,
                components: 2,
            },
        ],
    );
}

#[test]
fn rejects_pieces_that_are_not_congruent() {
    let not = |figure, piece| Violation::NotCongruent { figure, piece };
    check_invalid(Square, true, &["AAAB", "AA|AB"], no_edit, &[not(1, 0)]);
    // The right shapes in the wrong order.
    check_invalid(
        Square,
        true,
        &["AAAB", "ABBB"],
        no_edit,
        &[not(1, 0), not(1, 1)],
    );
    check_invalid(
        Square,
        true,
        &["AB|AB", "AABB", "AAA|.BB"],
        no_edit,
        &[not(2, 0)],
    );
    check_invalid(Tri4, true, &["AAAA", "AA.."], no_edit, &[not(1, 0)]);
    check_invalid(Cubic, false, &["AAA", "A|A/A."], no_edit, &[not(1, 0)]);
}

#[test]
fn rejects_mirror_images_without_mirror() {
    let not = [Violation::NotCongruent {
        figure: 1,
        piece: 0,
    }];
    check_invalid(Square, false, &[".A|.A|AA", "A.|A.|AA"], no_edit, &not);
    check_invalid(Square, false, &[".AA|AA.", "AA.|.AA"], no_edit, &not);
    check_invalid(Tri4, false, &["AAAA A..A", "AA.. AAAA"], no_edit, &not);
    // cubic never allows mirror images, whatever `mirror` says.
    for mirror in [true, false] {
        check_invalid(
            Cubic,
            mirror,
            &["AA|.A/..|.A", "AA|A./..|A."],
            no_edit,
            &not,
        );
    }
}

#[test]
fn rejects_mismatched_shapes_of_the_solution() {
    check_invalid(
        Square,
        true,
        &DOMINOES,
        |d, _| {
            d.pieces[1].pop();
        },
        &[Violation::PieceCount(vec![2, 1])],
    );
    check_invalid(
        Square,
        true,
        &DOMINOES,
        |d, _| {
            d.pieces[0].pop();
        },
        &[Violation::PieceCount(vec![1, 2])],
    );
    check_invalid(
        Square,
        true,
        &DOMINOES,
        |_, figs| figs.push(figs[0].clone()),
        &[Violation::FigureCount {
            found: 2,
            expected: 3,
        }],
    );
    check_invalid(
        Square,
        true,
        &DOMINOES,
        |d, _| d.lattice = Tri4,
        &[Violation::LatticeMismatch {
            found: Tri4,
            expected: Square,
        }],
    );
    check_invalid(
        Square,
        true,
        &DOMINOES,
        |d, _| d.pieces = vec![vec![], vec![]],
        &[Violation::NoPieces],
    );
    check_invalid(
        Square,
        true,
        &DOMINOES,
        |d, _| {
            for p in &mut d.pieces {
                p.push(vec![]);
            }
        },
        &[
            Violation::EmptyPiece {
                figure: 0,
                piece: 2,
            },
            Violation::EmptyPiece {
                figure: 1,
                piece: 2,
            },
        ],
    );
}

#[test]
fn verify_pieces_is_verify() {
    let (figures, d) = dissection(Tri4, false, &["AAAA A..A", "AA.. AAAA"]);
    assert_eq!(
        verify_pieces(Tri4, false, &figures, d.pieces()),
        verify(&d, &figures)
    );
    assert!(verify_pieces(Tri4, true, &figures, d.pieces()).is_ok());
}

#[test]
fn violation_messages() {
    let msg = |v: Violation| v.to_string();
    assert_eq!(
        msg(Violation::NotCongruent {
            figure: 2,
            piece: 1
        }),
        "piece 1 of figure 2 is not congruent to piece 1 of figure 0"
    );
    assert_eq!(
        msg(Violation::PieceCount(vec![2, 3])),
        "figures list different numbers of pieces: [2, 3]"
    );
    assert_eq!(
        msg(Violation::Disconnected {
            figure: 0,
            piece: 4,
            components: 3
        }),
        "figure 0 piece 4 is not connected (3 components)"
    );
}

#[test]
fn a_dissection_of_no_figure_is_refused_not_a_panic() {
    let d = Dissection::unnamed(dissect_core::LatticeKind::Square, true, vec![]).unwrap();
    assert_eq!(
        dissect_core::verify::verify(&d, &[]),
        Err(vec![Violation::NoPieces])
    );
}
