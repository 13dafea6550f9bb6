//! LDraw models (`.ldr`) of the figures, built from real LEGO parts: every
//! piece's cells are merged greedily into the largest plates (2D) or bricks
//! (`cubic`, one brick layer per z layer) that fit inside that piece, one
//! part per merged brick. One model per figure.
//!
//! A cell is one stud (20 LDU). LDraw's axes: x right, y down, z away from
//! the viewer; parts hang down from their origin at the top centre.

use std::collections::HashSet;

use dissect_core::{Cell, LatticeKind};

use crate::{RenderError, Scene};

/// Which part family 2D figures are built from.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum PartKind {
    /// Plates (8 LDU high).
    #[default]
    Plate,
    /// Bricks (24 LDU high).
    Brick,
}

/// The parts used: (studs along x, studs along z, plate, brick), largest first.
pub const PARTS: [(i32, i32, &str, &str); 11] = [
    (8, 2, "3034", "3007"),
    (6, 2, "3795", "2456"),
    (8, 1, "3460", "3008"),
    (4, 2, "3020", "3001"),
    (6, 1, "3666", "3009"),
    (3, 2, "3021", "3002"),
    (4, 1, "3710", "3010"),
    (2, 2, "3022", "3003"),
    (3, 1, "3623", "3622"),
    (2, 1, "3023", "3004"),
    (1, 1, "3024", "3005"),
];

/// LDraw colour codes for pieces.
const COLOURS: [u32; 16] = [4, 1, 14, 2, 25, 22, 3, 13, 27, 73, 15, 6, 19, 11, 71, 5];

/// One part placed in a model.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Brick {
    /// The piece it belongs to.
    pub piece: usize,
    /// Its cells, `[x, y, z]` (z = 0 for 2D).
    pub cells: Vec<Cell>,
    /// The part number (`3001` ...).
    pub part: &'static str,
}

/// Cells of one piece merged into parts (largest first, greedy, scanning
/// rows from the top left).
pub fn merge_cells(piece: usize, cells: &[Cell], kind: PartKind) -> Vec<Brick> {
    let mut free: HashSet<Cell> = cells.iter().copied().collect();
    let mut order: Vec<Cell> = cells.to_vec();
    order.sort_by_key(|c| (c[2], c[1], c[0]));
    let mut out = Vec::new();
    for start in order {
        if !free.contains(&start) {
            continue;
        }
        'parts: for &(long, short, plate, brick) in &PARTS {
            for (w, d) in [(long, short), (short, long)] {
                let cells: Vec<Cell> = (0..d)
                    .flat_map(|dy| (0..w).map(move |dx| [start[0] + dx, start[1] + dy, start[2]]))
                    .collect();
                if cells.iter().all(|c| free.contains(c)) {
                    for c in &cells {
                        free.remove(c);
                    }
                    out.push(Brick {
                        piece,
                        cells,
                        part: match kind {
                            PartKind::Plate => plate,
                            PartKind::Brick => brick,
                        },
                    });
                    break 'parts;
                }
            }
        }
    }
    out
}

/// Whether LDraw models are made for `lattice` (square and cubic: `tri4`,
/// `tri3` and `hex` triangles and hexagons have no LEGO part).
pub fn supports(lattice: LatticeKind) -> bool {
    matches!(lattice, LatticeKind::Square | LatticeKind::Cubic)
}

/// One `.ldr` model per figure (named after the figure), or an error for
/// the lattices it does not [`supports`].
pub fn render(scene: &Scene, kind: PartKind) -> Result<Vec<(String, String)>, RenderError> {
    match scene.lattice() {
        LatticeKind::Tri4 => {
            return Err(RenderError::BadOption(
                "LDraw models are made for the square and cubic lattices (LEGO has no quarter-square triangles)".into(),
            ));
        }
        LatticeKind::Tri3 | LatticeKind::Hex => {
            return Err(RenderError::BadOption(format!(
                "LDraw models are made for the square and cubic lattices (LEGO has no {} bricks); use --format stl to print the pieces",
                if scene.lattice() == LatticeKind::Tri3 { "equilateral-triangle" } else { "hexagonal" }
            )));
        }
        LatticeKind::Square | LatticeKind::Cubic => {}
    }
    let cubic = scene.lattice() == LatticeKind::Cubic;
    let kind = if cubic { PartKind::Brick } else { kind };
    let height = match kind {
        PartKind::Plate => 8,
        PartKind::Brick => 24,
    };
    let mut files = Vec::new();
    for f in 0..scene.figure_count() {
        let name = model_name(scene.name(f));
        let mut s = format!(
            "0 {}\n0 Name: {name}\n0 Author: dissect\n0 {} pieces, {} lattice\n",
            scene.name(f),
            scene.piece_count(),
            scene.lattice()
        );
        let mut bricks: Vec<Brick> = (0..scene.piece_count())
            .flat_map(|i| merge_cells(i, scene.cells(f, i), kind))
            .collect();
        bricks.sort_by_key(|b| (b.cells[0][2], b.piece, b.cells[0][1], b.cells[0][0]));
        let mut layer = bricks.first().map_or(0, |b| b.cells[0][2]);
        for b in &bricks {
            let z = b.cells[0][2];
            if cubic && z != layer {
                s += "0 STEP\n";
                layer = z;
            }
            let (x0, x1) = (
                b.cells.iter().map(|c| c[0]).min().unwrap_or(0),
                b.cells.iter().map(|c| c[0]).max().unwrap_or(0),
            );
            let (y0, y1) = (
                b.cells.iter().map(|c| c[1]).min().unwrap_or(0),
                b.cells.iter().map(|c| c[1]).max().unwrap_or(0),
            );
            let (w, d) = (x1 - x0 + 1, y1 - y0 + 1);
            // Centre in LDU; rows run toward the viewer, i.e. -z in LDraw.
            let cx = 10 * (x0 + x1 + 1);
            let cz = -10 * (y0 + y1 + 1);
            let top = -height * (z + 1);
            let rot = if w >= d {
                "1 0 0 0 1 0 0 0 1"
            } else {
                "0 0 1 0 1 0 -1 0 0"
            };
            s += &format!(
                "1 {} {cx} {top} {cz} {rot} {}.dat\n",
                COLOURS[b.piece % COLOURS.len()],
                b.part
            );
        }
        s += "0 STEP\n";
        files.push((name, s));
    }
    Ok(files)
}

fn model_name(figure: &str) -> String {
    let stem = figure.rsplit_once('.').map_or(figure, |(a, _)| a);
    let clean: String = stem
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || c == '-' || c == '_' {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("{clean}.ldr")
}

/// The studs covered by a part line of a model written by [`render`]:
/// `(colour, cells)` with cells `[x, y, layer]`, or `None` when the line
/// is not a part line of a known part.
pub fn part_cells(line: &str, kind: PartKind) -> Option<(u32, Vec<Cell>)> {
    let w: Vec<&str> = line.split_whitespace().collect();
    if w.len() != 15 || w[0] != "1" {
        return None;
    }
    let num = |i: usize| w[i].parse::<i32>().ok();
    let colour = w[1].parse::<u32>().ok()?;
    let (cx, top, cz) = (num(2)?, num(3)?, num(4)?);
    let part = w[14].strip_suffix(".dat")?;
    let &(long, short, _, _) = PARTS.iter().find(|p| p.2 == part || p.3 == part)?;
    let rotated = num(5)? == 0;
    let (wd, dd) = if rotated {
        (short, long)
    } else {
        (long, short)
    };
    let height = match kind {
        PartKind::Plate => 8,
        PartKind::Brick => 24,
    };
    let z = -top / height - 1;
    let x0 = (cx - 10 * wd) / 20;
    let y0 = (-cz - 10 * dd) / 20;
    let cells = (0..dd)
        .flat_map(|dy| (0..wd).map(move |dx| [x0 + dx, y0 + dy, z]))
        .collect();
    Some((colour, cells))
}
