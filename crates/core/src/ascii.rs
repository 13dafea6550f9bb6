//! ASCII art of figures and their pieces, as strings (one letter, and
//! optionally one ANSI colour, per piece). Printing is the caller's business.

use std::collections::HashMap;

use crate::lattice::{Cell, LatticeKind};

const LETTERS: &[u8] = b"ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789";

/// The letter of piece `i`.
pub fn piece_letter(i: usize) -> char {
    LETTERS.get(i).map_or('*', |b| *b as char)
}

/// A distinct ANSI 256-colour background for piece `i`.
fn colour(i: usize) -> u8 {
    const PALETTE: [u8; 16] = [
        196, 46, 33, 226, 201, 51, 208, 129, 118, 39, 214, 165, 84, 27, 220, 160,
    ];
    PALETTE[i % PALETTE.len()]
}

/// Draws one figure whose cells are split into `pieces` (`pieces[i]` gets
/// letter `i`). Square: one character per cell. `tri4`: a 3×3 block per
/// square (top row = top triangle, bottom row = bottom triangle, the middle
/// row shows left, centre and right). `cubic`: the z layers side by side.
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
                        let (top, right, bottom, left) = (t(0), t(1), t(2), t(3));
                        let centre = if top == right && right == bottom && bottom == left {
                            top
                        } else {
                            None
                        };
                        let cells = match row {
                            0 => [top, top, top],
                            1 => [left, centre, right],
                            _ => [bottom, bottom, bottom],
                        };
                        for (i, c) in cells.into_iter().enumerate() {
                            if row == 1 && i == 1 && c.is_none() {
                                out.push(
                                    if [top, right, bottom, left].iter().all(|v| v.is_none()) {
                                        '.'
                                    } else {
                                        ' '
                                    },
                                );
                            } else {
                                out += &paint(c);
                            }
                        }
                    }
                    out.push('\n');
                }
            }
        }
        LatticeKind::Cubic => {
            let header: Vec<String> = (min[2]..=max[2])
                .map(|z| {
                    let w = (max[0] - min[0] + 1) as usize;
                    format!("{:<w$}", format!("z={z}"), w = w)
                })
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
                    parts.push(s);
                }
                out += &parts.join("  ");
                out.push('\n');
            }
        }
    }
    out
}
