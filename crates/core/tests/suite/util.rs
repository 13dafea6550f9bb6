//! Helpers shared by the topics: figures and labelled figures from compact
//! ASCII strings.
//!
//! Notation: `|` ends a row, `/` ends a cubic z layer (it becomes the blank
//! line of the file format). Plain figures use the file format's characters.
//! Labelled figures write a piece letter (`A` is piece 0, `B` piece 1, ...)
//! instead of a filled cell: one letter per cell on `square` and `cubic`;
//! on `tri4` one whitespace-separated token of four letters per square, for
//! the triangles top, right, bottom, left (`.` for an empty triangle, a lone
//! `.` for an empty square).

use dissect_core::io::parse_figure;
use dissect_core::Dissection;
use dissect_core::{Cell, Figure, LatticeKind};

pub use LatticeKind::{Cubic, Hex, Square, Tri3, Tri4};

/// The file text of a compact figure string.
pub fn text(compact: &str) -> String {
    let mut out = compact.replace('/', "\n\n").replace('|', "\n");
    out.push('\n');
    out
}

/// Parses a compact figure string; panics with the parse error.
pub fn fig(lattice: LatticeKind, compact: &str) -> Figure {
    parse_figure(&text(compact), lattice)
        .unwrap_or_else(|e| panic!("test figure {compact:?} ({lattice}): {e}"))
}

/// The pieces of a labelled compact string: `pieces[i]` holds the cells
/// written with letter `'A' + i` (sorted; letters not used give empty pieces).
pub fn pieces(lattice: LatticeKind, compact: &str) -> Vec<Vec<Cell>> {
    let mut out: Vec<Vec<Cell>> = Vec::new();
    let mut put = |letter: char, cell: Cell| {
        assert!(
            letter.is_ascii_uppercase(),
            "bad piece letter {letter:?} in {compact:?}"
        );
        let i = (letter as u8 - b'A') as usize;
        if out.len() <= i {
            out.resize(i + 1, Vec::new());
        }
        out[i].push(cell);
    };
    for (z, layer) in compact.split('/').enumerate() {
        assert!(
            z == 0 || lattice == Cubic,
            "layers only on cubic: {compact:?}"
        );
        for (y, row) in layer.split('|').enumerate() {
            let (y, z) = (y as i32, z as i32);
            if lattice == Tri4 {
                for (x, token) in row.split_whitespace().enumerate() {
                    if token == "." {
                        continue;
                    }
                    assert_eq!(token.len(), 4, "tri4 token {token:?} in {compact:?}");
                    for (t, ch) in token.chars().enumerate() {
                        if ch != '.' {
                            put(ch, [x as i32, y, t as i32]);
                        }
                    }
                }
            } else {
                for (x, ch) in row.chars().enumerate() {
                    if ch != '.' {
                        let x = x as i32;
                        put(
                            ch,
                            if lattice == Cubic {
                                [x, y, z]
                            } else {
                                [x, y, 0]
                            },
                        );
                    }
                }
            }
        }
    }
    for p in &mut out {
        p.sort();
    }
    out
}

/// The figure made of every cell of a labelled compact string.
pub fn labelled_figure(lattice: LatticeKind, compact: &str) -> Figure {
    let cells = pieces(lattice, compact).into_iter().flatten();
    Figure::new(lattice, cells).unwrap_or_else(|e| panic!("test figure {compact:?}: {e}"))
}

/// The figures and the dissection written by labelled compact strings.
pub fn dissection(
    lattice: LatticeKind,
    mirror: bool,
    labelled: &[&str],
) -> (Vec<Figure>, Dissection) {
    let figures = labelled
        .iter()
        .map(|s| labelled_figure(lattice, s))
        .collect();
    let d = Dissection::new(
        lattice,
        mirror,
        (0..labelled.len()).map(|i| format!("f{i}.txt")).collect(),
        labelled.iter().map(|s| pieces(lattice, s)).collect(),
    )
    .expect("cells of the lattice");
    (figures, d)
}

/// Every cell whose block lies in `-r..=r` (z too on `cubic`).
pub fn cells_around(lattice: LatticeKind, r: i32) -> Vec<Cell> {
    let zr = if lattice == Cubic { r } else { 0 };
    lattice.lattice().cells_in_box([-r, -r, -zr], [r, r, zr])
}
