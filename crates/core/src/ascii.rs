//! ASCII art of figures and their pieces, as strings (one letter, and
//! optionally one ANSI colour, per piece). Printing is the caller's business.

use std::collections::HashMap;

use crate::lattice::{Cell, LatticeKind};

const LETTERS: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";

/// The letter of piece `i`.
pub fn piece_letter(i: usize) -> char {
    LETTERS.get(i).map_or('*', |b| *b as char)
}

/// The ANSI 256-colour background of piece `i` (derived from the one
/// palette, [`crate::palette`]).
fn colour(i: usize) -> u8 {
    crate::palette::piece_ansi256(i)
}

/// Draws one figure whose cells are split into `pieces` (`pieces[i]` gets
/// letter `i`; `.` is a cell of no piece). Square: one character per cell.
/// `tri4`: a 3×3 block per square whose side middles show the four
/// triangles and whose corners and centre draw the diagonals where pieces
/// meet (see `tri4_block_row`). `cubic`: the z layers side by side, left to
/// right, each under a `z=N` header. `tri3`: one line per row, two columns
/// per triangle, its edge to the left (`/` or `\\`, slanting as the edge
/// does, so an up triangle sits between `/` and `\\`) then its letter. `hex`:
/// one line per row, two columns per hexagon, odd rows indented by one
/// column as the hexagons are.
pub fn draw(lattice: LatticeKind, pieces: &[Vec<Cell>], colour_on: bool) -> String {
    let owner: HashMap<Cell, usize> = pieces
        .iter()
        .enumerate()
        .flat_map(|(i, p)| p.iter().map(move |c| (*c, i)))
        .collect();
    if owner.is_empty() {
        return String::new();
    }
    let l = lattice.lattice();
    let mut min = [i32::MAX; 3];
    let mut max = [i32::MIN; 3];
    for c in owner.keys() {
        let b = l.block(*c);
        for d in 0..3 {
            min[d] = min[d].min(b[d]);
            max[d] = max[d].max(b[d]);
        }
    }
    let paint = |who: Option<usize>| -> String {
        match who {
            None => ".".to_string(),
            Some(i) if colour_on => {
                format!("\x1b[48;5;{}m\x1b[30m{}\x1b[0m", colour(i), piece_letter(i))
            }
            Some(i) => piece_letter(i).to_string(),
        }
    };
    let mut out = String::new();
    match lattice {
        LatticeKind::Square => {
            for y in min[1]..=max[1] {
                for x in min[0]..=max[0] {
                    out += &paint(owner.get(&[x, y, 0]).copied());
                }
                out.push('\n');
            }
        }
        LatticeKind::Tri4 => {
            for y in min[1]..=max[1] {
                for row in 0..3 {
                    for x in min[0]..=max[0] {
                        let t = |t: i32| owner.get(&[x, y, t]).copied();
                        for glyph in tri4_block_row([t(0), t(1), t(2), t(3)], row) {
                            out += &match glyph {
                                Glyph::Owner(who) => paint(who),
                                Glyph::Mark(ch) => ch.to_string(),
                            };
                        }
                    }
                    out.push('\n');
                }
            }
        }
        LatticeKind::Tri3 => {
            for y in min[1]..=max[1] {
                let mut line = String::new();
                for x in min[0]..=max[0] + 1 {
                    let left = owner.get(&[x - 1, y, 0]).copied();
                    let here = owner.get(&[x, y, 0]).copied();
                    // The edge between x - 1 and x rises to the right ('/')
                    // when x points up.
                    line += match (left, here) {
                        (None, None) => " ",
                        _ if (x + y).rem_euclid(2) == 0 => "/",
                        _ => "\\",
                    };
                    if x <= max[0] {
                        line += &paint(here);
                    }
                }
                out += line.trim_end();
                out.push('\n');
            }
        }
        LatticeKind::Hex => {
            for y in min[1]..=max[1] {
                let mut line = String::new();
                if y.rem_euclid(2) == 1 {
                    line.push(' ');
                }
                for x in min[0]..=max[0] {
                    line += &paint(owner.get(&[x, y, 0]).copied());
                    line.push(' ');
                }
                out += line.trim_end();
                out.push('\n');
            }
        }
        LatticeKind::Cubic => {
            // Each layer is a column as wide as the figure (or its header).
            let w = ((max[0] - min[0] + 1) as usize).max(format!("z={}", max[2]).len());
            let header: Vec<String> = (min[2]..=max[2])
                .map(|z| format!("{:<w$}", format!("z={z}")))
                .collect();
            out += header.join("  ").trim_end();
            out.push('\n');
            for y in min[1]..=max[1] {
                let mut parts = Vec::new();
                for z in min[2]..=max[2] {
                    let mut s = String::new();
                    for x in min[0]..=max[0] {
                        s += &paint(owner.get(&[x, y, z]).copied());
                    }
                    let pad = w - (max[0] - min[0] + 1) as usize;
                    s += &" ".repeat(pad);
                    parts.push(s);
                }
                out += parts.join("  ").trim_end();
                out.push('\n');
            }
        }
    }
    out
}

/// One character of a `tri4` block: a piece's letter (or `.` for no piece),
/// or a line drawn where two triangles of different owners meet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Glyph {
    Owner(Option<usize>),
    Mark(char),
}

/// Row `row` (0..3) of the 3×3 block of one `tri4` square whose triangles
/// (top, right, bottom, left) belong to `own`.
///
/// The middle of each side shows the triangle on that side. A corner lies on
/// a diagonal between two triangles: it shows their owner when they agree,
/// otherwise the diagonal (`\` at the top-left and bottom-right corners, `/`
/// at the other two). The centre shows the owner when all four agree, the
/// diagonal when the square is cut along one diagonal, the apex of a lone
/// triangle (`v`, `<`, `^`, `>` for top, right, bottom, left) when three
/// agree, and `x` otherwise. So a half square `9` reads
///
/// ```text
/// AA/
/// A/.
/// /..
/// ```
fn tri4_block_row(own: [Option<usize>; 4], row: usize) -> [Glyph; 3] {
    let [top, right, bottom, left] = own;
    let corner = |a: Option<usize>, b: Option<usize>, diagonal: char| {
        if a == b {
            Glyph::Owner(a)
        } else {
            Glyph::Mark(diagonal)
        }
    };
    match row {
        0 => [
            corner(top, left, '\\'),
            Glyph::Owner(top),
            corner(top, right, '/'),
        ],
        1 => [Glyph::Owner(left), centre(own), Glyph::Owner(right)],
        _ => [
            corner(bottom, left, '/'),
            Glyph::Owner(bottom),
            corner(bottom, right, '\\'),
        ],
    }
}

/// The centre glyph of a `tri4` block (see [`tri4_block_row`]).
fn centre(own: [Option<usize>; 4]) -> Glyph {
    let [top, right, bottom, left] = own;
    if top == right && right == bottom && bottom == left {
        return Glyph::Owner(top);
    }
    if top == left && right == bottom {
        return Glyph::Mark('/');
    }
    if top == right && left == bottom {
        return Glyph::Mark('\\');
    }
    // A lone triangle: the other three agree.
    const APEX: [char; 4] = ['v', '<', '^', '>'];
    for (i, apex) in APEX.iter().enumerate() {
        let others: Vec<Option<usize>> = (1..4).map(|k| own[(i + k) % 4]).collect();
        if others.iter().all(|o| *o == others[0]) {
            return Glyph::Mark(*apex);
        }
    }
    Glyph::Mark('x')
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::io::parse_figure;

    /// Draws a figure given as text, with the cells split into pieces by a
    /// list of rows whose letters name the pieces (`tri4`: four letters per
    /// square, for triangles 0..4; `cubic`: the rows of every layer in turn).
    fn pieces_of(lattice: LatticeKind, figure: &str, labels: &[&str]) -> Vec<Vec<Cell>> {
        let fig = parse_figure(figure, lattice).expect("test figure parses");
        let layers = fig
            .cells()
            .iter()
            .map(|c| c[2] as usize + 1)
            .max()
            .unwrap_or(1);
        let layer_rows = labels.len() / layers;
        let mut pieces: Vec<Vec<Cell>> = Vec::new();
        for &c in fig.cells() {
            // Cubic labels list the layers' rows one after the other.
            let row = match lattice {
                LatticeKind::Cubic => c[1] as usize + c[2] as usize * layer_rows,
                _ => c[1] as usize,
            };
            let label = labels[row].as_bytes()[if lattice == LatticeKind::Tri4 {
                c[0] as usize * 4 + c[2] as usize
            } else {
                c[0] as usize
            }];
            let i = (label - b'A') as usize;
            if pieces.len() <= i {
                pieces.resize(i + 1, Vec::new());
            }
            pieces[i].push(c);
        }
        pieces
    }

    #[test]
    fn square_one_letter_per_cell() {
        let p = pieces_of(LatticeKind::Square, "##.\n.##\n", &["AA.", ".BB"]);
        assert_eq!(draw(LatticeKind::Square, &p, false), "AA.\n.BB\n");
    }

    #[test]
    fn tri4_half_squares_draw_their_diagonal() {
        // `9` = top + left (above the `/` diagonal), `6` = its complement,
        // `3` = top + right (above `\\`), `C` = its complement.
        let p = pieces_of(
            LatticeKind::Tri4,
            "9..6\n3..C\n",
            &["A..A.........AA.", "AA............AA"],
        );
        let expected = "\
AA/......../
A/......../A
/......../AA
\\AA......\\..
.\\A......A\\.
..\\......AA\\
";
        assert_eq!(draw(LatticeKind::Tri4, &p, false), expected);
    }

    #[test]
    fn tri4_pieces_meeting_inside_a_square() {
        // Square 0 cut along `\\` (A above, B below), square 1 with a lone
        // top triangle (C) over three triangles of D, square 2 whole (E).
        let p = pieces_of(LatticeKind::Tri4, "###\n", &["AABBCDDDEEEE"]);
        let expected = "\
\\AA\\C/EEE
B\\ADvDEEE
BB\\DDDEEE
";
        assert_eq!(draw(LatticeKind::Tri4, &p, false), expected);
    }

    #[test]
    fn tri4_four_owners_meet_at_an_x() {
        let p = pieces_of(LatticeKind::Tri4, "#\n", &["ABCD"]);
        assert_eq!(draw(LatticeKind::Tri4, &p, false), "\\A/\nDxB\n/C\\\n");
    }

    #[test]
    fn cubic_layers_side_by_side_under_aligned_headers() {
        let p = pieces_of(
            LatticeKind::Cubic,
            "##\n#.\n\n#.\n..\n",
            &["AB", "A.", "B.", ".."],
        );
        assert_eq!(
            draw(LatticeKind::Cubic, &p, false),
            "z=0  z=1\nAB   B.\nA.   ..\n"
        );
    }

    #[test]
    fn colour_wraps_letters_only() {
        let p = pieces_of(LatticeKind::Square, "#\n", &["A"]);
        assert_eq!(
            draw(LatticeKind::Square, &p, true),
            "\x1b[48;5;167m\x1b[30mA\x1b[0m\n"
        );
    }
}
