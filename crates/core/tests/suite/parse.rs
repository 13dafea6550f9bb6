//! The figure text format: cells per lattice, tolerated whitespace, every
//! error kind with its line and column, and the `format_figure` round trip.

use dissect_core::io::{format_figure, parse_figure, ParseErrorKind};
use dissect_core::{Cell, LatticeKind};

use super::util::{fig, Cubic, Square, Tri4};

/// `text` parses on `lattice` to exactly `cells` (any order).
fn check(lattice: LatticeKind, text: &str, cells: &[Cell]) {
    let f = parse_figure(text, lattice).unwrap_or_else(|e| panic!("{text:?}: {e}"));
    let mut want = cells.to_vec();
    want.sort();
    assert_eq!(f.cells(), &want[..], "cells of {text:?} on {lattice}");
    assert_eq!(f.lattice(), lattice);
}

/// `text` fails on `lattice` at `line`/`column` with `kind`, and the message
/// starts with that position.
fn check_err(lattice: LatticeKind, text: &str, line: usize, column: usize, kind: ParseErrorKind) {
    let e = parse_figure(text, lattice).expect_err(text);
    assert_eq!(
        (e.line, e.column, &e.kind),
        (line, column, &kind),
        "error of {text:?} on {lattice}"
    );
    let msg = e.to_string();
    let prefix = match (line, column) {
        (0, _) => String::new(),
        (l, 0) => format!("line {l}: "),
        (l, c) => format!("line {l}, column {c}: "),
    };
    assert!(
        msg.starts_with(&prefix),
        "{msg:?} should start with {prefix:?}"
    );
}

fn bad_char(found: char, lattice: LatticeKind) -> ParseErrorKind {
    ParseErrorKind::UnexpectedChar {
        found,
        lattice,
        allowed: if lattice == Tri4 {
            "hex digits, '#' and '.'"
        } else {
            "'#' and '.'"
        },
    }
}

#[test]
fn square_cells() {
    check(Square, "#", &[[0, 0, 0]]);
    check(Square, "##\n#.\n", &[[0, 0, 0], [1, 0, 0], [0, 1, 0]]);
    check(Square, ".#\n\n#", &[[1, 0, 0], [0, 2, 0]]);
    // Rows of different lengths: missing cells are empty.
    check(
        Square,
        "#\n###\n.#",
        &[[0, 0, 0], [0, 1, 0], [1, 1, 0], [2, 1, 0], [1, 2, 0]],
    );
}

#[test]
fn tri4_cells() {
    check(Tri4, "1", &[[0, 0, 0]]);
    check(Tri4, "2", &[[0, 0, 1]]);
    check(Tri4, "4", &[[0, 0, 2]]);
    check(Tri4, "8", &[[0, 0, 3]]);
    check(Tri4, "C", &[[0, 0, 2], [0, 0, 3]]);
    check(Tri4, "c", &[[0, 0, 2], [0, 0, 3]]);
    check(Tri4, "3", &[[0, 0, 0], [0, 0, 1]]);
    check(Tri4, ".6\n9", &[[1, 0, 1], [1, 0, 2], [0, 1, 0], [0, 1, 3]]);
    check(Tri4, "#", &[[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 0, 3]]);
    check(
        Tri4,
        "F0a",
        &[
            [0, 0, 0],
            [0, 0, 1],
            [0, 0, 2],
            [0, 0, 3],
            [2, 0, 1],
            [2, 0, 3],
        ],
    );
}

#[test]
fn cubic_cells() {
    check(Cubic, "#", &[[0, 0, 0]]);
    check(Cubic, "##\n.#\n", &[[0, 0, 0], [1, 0, 0], [1, 1, 0]]);
    check(Cubic, "#\n\n.#\n#", &[[0, 0, 0], [1, 0, 1], [0, 1, 1]]);
    check(Cubic, "#\n\n.\n\n#", &[[0, 0, 0], [0, 0, 2]]);
    // A layer of spaces only is a blank line too (trailing spaces are ignored).
    check(Cubic, "#\n  \n#", &[[0, 0, 0], [0, 0, 1]]);
}

#[test]
fn tolerated_whitespace() {
    let l_tromino = [[0, 0, 0], [1, 0, 0], [0, 1, 0]];
    for text in [
        "##\r\n#.\r\n",
        "##\r\n#.",
        "##  \n#   \n",
        "##\n#.\n\n\n",
        "##\r\n#\r\n\r\n  \r\n",
        "##\n#",
    ] {
        check(Square, text, &l_tromino);
    }
    check(Tri4, "3 \r\n\r\n", &[[0, 0, 0], [0, 0, 1]]);
    check(Cubic, "#\r\n\r\n#\r\n\r\n", &[[0, 0, 0], [0, 0, 1]]);
    check(Cubic, "# \n \n# \n\n\n", &[[0, 0, 0], [0, 0, 1]]);
}

#[test]
fn unexpected_characters() {
    check_err(Square, "#x", 1, 2, bad_char('x', Square));
    check_err(Square, "##\n#.\n.#1", 3, 3, bad_char('1', Square));
    check_err(Square, "##\r\n#.F", 2, 3, bad_char('F', Square));
    // A leading space is not trailing whitespace.
    check_err(Square, "#\n #", 2, 1, bad_char(' ', Square));
    check_err(Square, "#\t", 1, 2, bad_char('\t', Square));
    // Columns count characters, not bytes.
    check_err(Square, "é#x", 1, 1, bad_char('é', Square));
    check_err(Square, "##\n#ü", 2, 2, bad_char('ü', Square));
    check_err(Tri4, "F0g", 1, 3, bad_char('g', Tri4));
    check_err(Tri4, "#\n\n.x", 3, 2, bad_char('x', Tri4));
    check_err(Cubic, "##\n\n#F", 3, 2, bad_char('F', Cubic));
    check_err(Cubic, "#\n\n#\n.#-", 4, 3, bad_char('-', Cubic));
}

#[test]
fn empty_figures() {
    for lattice in LatticeKind::ALL {
        for text in ["", "\n", "\n\n", "   \n", "."] {
            check_err(lattice, text, 0, 0, ParseErrorKind::Empty);
        }
    }
    check_err(Square, "...\n..", 0, 0, ParseErrorKind::Empty);
    check_err(Tri4, "00\n.0", 0, 0, ParseErrorKind::Empty);
    check_err(Cubic, "..\n\n..", 0, 0, ParseErrorKind::Empty);
}

#[test]
fn cubic_blank_lines() {
    check_err(Cubic, "\n#", 1, 0, ParseErrorKind::LeadingBlank);
    check_err(Cubic, "  \n#", 1, 0, ParseErrorKind::LeadingBlank);
    check_err(Cubic, "#\n\n\n#", 3, 0, ParseErrorKind::DoubleBlank);
    check_err(
        Cubic,
        "#\n#\n\n#\n\n\n\n#",
        6,
        0,
        ParseErrorKind::DoubleBlank,
    );
    check_err(Cubic, "#\r\n\r\n\r\n#", 3, 0, ParseErrorKind::DoubleBlank);
    // Blank lines mean nothing on 2D lattices.
    check(Square, "\n#", &[[0, 1, 0]]);
    check(
        Tri4,
        "#\n\n\n1",
        &[[0, 0, 0], [0, 0, 1], [0, 0, 2], [0, 0, 3], [0, 3, 0]],
    );
}

#[test]
fn error_messages_name_the_character_and_lattice() {
    let e = parse_figure("#?", Tri4).unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 1, column 2: unexpected character '?' (the tri4 format allows hex digits, '#' and '.')"
    );
    let e = parse_figure("#\n\n\n#", Cubic).unwrap_err();
    assert_eq!(
        e.to_string(),
        "line 3: more than one blank line between z layers"
    );
    let e = parse_figure("..", Square).unwrap_err();
    assert_eq!(e.to_string(), "empty figure (no filled cell)");
}

/// `format_figure` writes `compact` (already at the origin) back exactly,
/// and parsing the output gives the same figure.
fn check_round_trip(lattice: LatticeKind, compact: &str, written: &str) {
    let f = fig(lattice, compact);
    let out = format_figure(&f);
    assert_eq!(out, written, "format of {compact:?}");
    let again = parse_figure(&out, lattice).unwrap();
    assert_eq!(again, f, "round trip of {compact:?}");
}

#[test]
fn format_round_trip() {
    check_round_trip(Square, "#", "#\n");
    check_round_trip(Square, "###|#.#|###", "###\n#.#\n###\n");
    check_round_trip(Square, "#..|.#.|..#", "#\n.#\n..#\n");
    check_round_trip(Square, "#.#", "#.#\n");
    check_round_trip(Tri4, "#9|9", "#9\n9\n");
    check_round_trip(Tri4, "6#9", "6#9\n");
    check_round_trip(Tri4, "1248|abcd", "1248\nABCD\n");
    check_round_trip(Tri4, "5.A", "5.A\n");
    check_round_trip(Cubic, "#", "#\n");
    check_round_trip(Cubic, "##|#./.#|..", "##\n#.\n\n.#\n..\n");
    check_round_trip(Cubic, "#/./#", "#\n\n.\n\n#\n");
}

#[test]
fn format_moves_the_figure_to_the_origin() {
    let f = fig(Square, "...|..#|.##");
    assert_eq!(format_figure(&f), ".#\n##\n");
    let g = fig(Cubic, "../.#/##");
    assert_eq!(format_figure(&g), ".#\n\n##\n");
    let h = fig(Tri4, "..|.4");
    assert_eq!(format_figure(&h), "4\n");
}

/// Random texts over the characters that matter never make the parser
/// panic, and every error points inside the text.
#[test]
fn random_texts_never_panic() {
    use rand::{RngExt, SeedableRng};
    let alphabet: Vec<char> = "#.#.#. 0F9c\n\n\r\t\u{e9}x".chars().collect();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(5);
    for _ in 0..3000 {
        let len = rng.random_range(0..24);
        let text: String = (0..len)
            .map(|_| alphabet[rng.random_range(0..alphabet.len())])
            .collect();
        for lattice in LatticeKind::ALL {
            match parse_figure(&text, lattice) {
                Ok(f) => assert!(!f.cells().is_empty()),
                Err(e) => {
                    let lines: Vec<&str> = text.split('\n').collect();
                    if e.line > 0 {
                        assert!(e.line <= lines.len(), "{text:?}: {e}");
                        let row = lines[e.line - 1];
                        let row = row.strip_suffix('\r').unwrap_or(row);
                        assert!(e.column <= row.chars().count(), "{text:?}: {e}");
                        if let ParseErrorKind::UnexpectedChar { found, .. } = e.kind {
                            assert_eq!(row.chars().nth(e.column - 1), Some(found), "{text:?}");
                        }
                    }
                }
            }
        }
    }
}
