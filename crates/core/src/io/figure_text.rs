//! The figure text format: `#`/`.` rows (square, tri3, hex), hex digits
//! (tri4), blocks of rows separated by one blank line (cubic).

use crate::figure::{Figure, FigureError};
use crate::lattice::{Cell, LatticeKind};

/// Occurs when a figure text cannot be read; carries the 1-based line and
/// column (0 when the problem is not at one place).
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{}{kind}", position(*line, *column))]
pub struct ParseError {
    /// 1-based line, or 0.
    pub line: usize,
    /// 1-based column (in characters), or 0.
    pub column: usize,
    /// What is wrong.
    pub kind: ParseErrorKind,
}

fn position(line: usize, column: usize) -> String {
    match (line, column) {
        (0, _) => String::new(),
        (l, 0) => format!("line {l}: "),
        (l, c) => format!("line {l}, column {c}: "),
    }
}

/// What is wrong with a figure text.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum ParseErrorKind {
    /// Occurs on a character that the lattice's format does not allow.
    #[error("unexpected character {found:?} (the {lattice} format allows {allowed})")]
    UnexpectedChar {
        /// The character found.
        found: char,
        /// The lattice being read.
        lattice: LatticeKind,
        /// What is allowed, in words.
        allowed: &'static str,
    },
    /// Occurs when a cubic figure starts with a blank line.
    #[error("blank line before the first z layer")]
    LeadingBlank,
    /// Occurs when cubic layers are separated by more than one blank line.
    #[error("more than one blank line between z layers")]
    DoubleBlank,
    /// Occurs when the figure has no cell.
    #[error("empty figure (no filled cell)")]
    Empty,
}

/// Parses a figure text of the given lattice.
pub fn parse_figure(text: &str, lattice: LatticeKind) -> Result<Figure, ParseError> {
    let mut lines: Vec<&str> = text.split('\n').collect();
    if lines.last() == Some(&"") {
        lines.pop();
    }
    let mut lines: Vec<&str> = lines
        .into_iter()
        .map(|l| l.strip_suffix('\r').unwrap_or(l).trim_end_matches(' '))
        .collect();
    while lines.last() == Some(&"") {
        lines.pop();
    }
    let mut cells: Vec<Cell> = Vec::new();
    let err = |line: usize, column: usize, kind| ParseError { line, column, kind };
    match lattice {
        LatticeKind::Cubic => {
            let (mut z, mut y) = (0, 0);
            let mut prev_blank = false;
            for (i, ln) in lines.iter().enumerate() {
                if ln.is_empty() {
                    if i == 0 {
                        return Err(err(1, 0, ParseErrorKind::LeadingBlank));
                    }
                    if prev_blank {
                        return Err(err(i + 1, 0, ParseErrorKind::DoubleBlank));
                    }
                    prev_blank = true;
                    z += 1;
                    y = 0;
                    continue;
                }
                prev_blank = false;
                for (x, ch) in ln.chars().enumerate() {
                    match ch {
                        '#' => cells.push([x as i32, y, z]),
                        '.' => {}
                        found => {
                            return Err(err(
                                i + 1,
                                x + 1,
                                ParseErrorKind::UnexpectedChar {
                                    found,
                                    lattice,
                                    allowed: "'#' and '.'",
                                },
                            ))
                        }
                    }
                }
                y += 1;
            }
        }
        LatticeKind::Square | LatticeKind::Tri4 | LatticeKind::Tri3 | LatticeKind::Hex => {
            for (y, ln) in lines.iter().enumerate() {
                for (x, ch) in ln.chars().enumerate() {
                    let (x, yy) = (x as i32, y as i32);
                    if lattice.plain_text() {
                        match ch {
                            '#' => cells.push([x, yy, 0]),
                            '.' => {}
                            found => {
                                return Err(err(
                                    y + 1,
                                    x as usize + 1,
                                    ParseErrorKind::UnexpectedChar {
                                        found,
                                        lattice,
                                        allowed: "'#' and '.'",
                                    },
                                ))
                            }
                        }
                    } else {
                        let mask = match ch {
                            '#' => 15,
                            '.' => 0,
                            c => match c.to_digit(16) {
                                Some(d) => d,
                                None => {
                                    return Err(err(
                                        y + 1,
                                        x as usize + 1,
                                        ParseErrorKind::UnexpectedChar {
                                            found: c,
                                            lattice,
                                            allowed: "hex digits, '#' and '.'",
                                        },
                                    ))
                                }
                            },
                        };
                        for t in 0..4 {
                            if mask >> t & 1 == 1 {
                                cells.push([x, yy, t]);
                            }
                        }
                    }
                }
            }
        }
    }
    Figure::new(lattice, cells).map_err(|e| match e {
        FigureError::Empty => err(0, 0, ParseErrorKind::Empty),
        // Parsing only produces well-formed cells.
        FigureError::BadCell { .. } => unreachable!("parser made a bad cell"),
    })
}

/// Writes a figure in the text format (the inverse of [`parse_figure`] up to
/// translation: the figure is placed by [`Figure::to_origin`], so its smallest
/// coordinates are 0, except a `tri3` figure's `x` that may start at 1).
pub fn format_figure(figure: &Figure) -> String {
    let l = figure.lattice().lattice();
    let figure = figure.to_origin();
    let mut min = [i32::MAX; 3];
    let mut max = [i32::MIN; 3];
    for &c in figure.cells() {
        let b = l.block(c);
        for i in 0..3 {
            min[i] = min[i].min(b[i]);
            max[i] = max[i].max(b[i]);
        }
    }
    let mut out = String::new();
    for z in min[2]..=max[2] {
        if z > min[2] {
            out.push('\n');
        }
        for y in 0..=max[1] {
            let mut row = String::new();
            for x in 0..=max[0] {
                let ch = match figure.lattice() {
                    LatticeKind::Tri4 => {
                        let mask: u32 = (0..4)
                            .filter(|&t| figure.contains([x, y, t]))
                            .map(|t| 1 << t)
                            .sum();
                        match mask {
                            0 => '.',
                            15 => '#',
                            m => char::from_digit(m, 16)
                                .expect("hex digit")
                                .to_ascii_uppercase(),
                        }
                    }
                    LatticeKind::Square | LatticeKind::Tri3 | LatticeKind::Hex => {
                        if figure.contains([x, y, 0]) {
                            '#'
                        } else {
                            '.'
                        }
                    }
                    LatticeKind::Cubic => {
                        if figure.contains([x, y, z]) {
                            '#'
                        } else {
                            '.'
                        }
                    }
                };
                row.push(ch);
            }
            if figure.lattice() == LatticeKind::Cubic {
                // A cubic row may not become blank: blank lines separate layers.
                out.push_str(&row);
            } else {
                out.push_str(row.trim_end_matches('.'));
            }
            out.push('\n');
        }
    }
    out
}
