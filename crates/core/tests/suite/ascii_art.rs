//! ASCII art of pieces: a golden output on the square lattice, and the
//! layout rules of the other lattices (one letter per piece, three text rows
//! per row of `tri4` squares, one `z=N` header per cubic layer).

use dissect_core::ascii::{draw, piece_letter};
use dissect_core::LatticeKind;

use super::util::{pieces, Cubic, Square, Tri4};

/// Drawing the labelled compact string gives exactly `golden`.
fn check(lattice: LatticeKind, labelled: &str, golden: &str) {
    let p = pieces(lattice, labelled);
    assert_eq!(
        draw(lattice, &p, false),
        golden,
        "{labelled:?} on {lattice}"
    );
}

#[test]
fn square_art() {
    check(Square, "AB|AB", "AB\nAB\n");
    check(Square, ".AB|CC.", ".AB\nCC.\n");
    check(Square, "..|.A", "A\n");
    check(Square, "A.A", "A.A\n");
}

/// The art of a labelled string has `lines` lines and shows every piece's
/// letter, and no other letter.
fn check_layout(lattice: LatticeKind, labelled: &str, lines: usize) -> String {
    let p = pieces(lattice, labelled);
    let art = draw(lattice, &p, false);
    assert_eq!(art.lines().count(), lines, "{labelled:?}:\n{art}");
    assert!(art.ends_with('\n'));
    for (i, piece) in p.iter().enumerate() {
        let letter = piece_letter(i);
        assert_eq!(
            art.contains(letter),
            !piece.is_empty(),
            "letter {letter} in {labelled:?}:\n{art}"
        );
    }
    let letters = art.chars().filter(|c| c.is_ascii_uppercase()).count();
    assert!(letters > 0);
    art
}

#[test]
fn tri4_layout() {
    check_layout(Tri4, "AABB", 3);
    check_layout(Tri4, "AAAA . .B..", 3);
    check_layout(Tri4, "A...|..B.", 6);
    check_layout(Tri4, "AABB A..A|B..B .", 6);
}

#[test]
fn cubic_layout() {
    let art = check_layout(Cubic, "AB/.A", 2);
    assert!(art.starts_with("z=0"), "{art}");
    assert!(art.lines().next().unwrap().contains("z=1"), "{art}");
    let art = check_layout(Cubic, "AAAA|B.../BBBB|..../C", 3);
    let header = art.lines().next().unwrap();
    for z in ["z=0", "z=1", "z=2"] {
        assert!(header.contains(z), "{art}");
    }
}

#[test]
fn colour_and_letters() {
    let p = pieces(Square, "AB");
    let art = draw(Square, &p, true);
    assert!(art.contains("\x1b[30mA\x1b[0m"), "{art:?}");
    assert!(art.contains("\x1b[30mB\x1b[0m"), "{art:?}");
    assert!(art.ends_with('\n'));
    assert_eq!(draw(Square, &[], false), "");
    let letters: String = [0, 1, 25, 26, 51, 52, 61, 62, 100]
        .into_iter()
        .map(piece_letter)
        .collect();
    assert_eq!(letters, "ABZaz09**");
}
