//! Scaling a figure by an integer factor `k`: every cell becomes the `k×k`
//! block of cells (`k×k×k` on `cubic`) that fills the cell enlarged `k`
//! times about the origin, so a dissection of the original figures scales to
//! a dissection of the scaled ones with the same piece count.
//!
//! On `tri4` the enlarged triangle of square `(x, y)` is the union of the
//! `k²` small triangles of the squares `k·x..k·x+k`, `k·y..k·y+k` whose
//! centroids lie in it (the big square's diagonals run along the small
//! squares' diagonals, so no small triangle is cut).
//!
//! On `tri3` the triangle is enlarged about a vertex of the lattice (the
//! origin of its skew points) into `k²` small triangles. Hexagons do not
//! tile an enlarged hexagon, so `hex` has no scaling series.

use dissect_core::lattice::Point;
use dissect_core::{Cell, Figure, LatticeKind};

use crate::BenchError;

/// Centroids of the four triangles of square `(0, 0)`, times 6 (top, right,
/// bottom, left), as in `FORMAT.md`.
const TRI_CENTROID6: [[i32; 2]; 4] = [[3, 1], [5, 3], [3, 5], [1, 3]];

/// The figure enlarged `k` times: `k²` cells per cell in 2D, `k³` in 3D.
pub fn scale(figure: &Figure, k: u32) -> Result<Figure, BenchError> {
    let too_large = || BenchError::ScaleTooLarge {
        cells: figure.len(),
        k,
    };
    let ki = i32::try_from(k).map_err(|_| too_large())?;
    if ki == 0 {
        return Err(BenchError::ScaleFactor);
    }
    let lattice = figure.lattice();
    let per_cell = match lattice {
        LatticeKind::Cubic => (ki as usize).pow(3),
        _ => (ki as usize).pow(2),
    };
    let total = figure
        .len()
        .checked_mul(per_cell)
        .filter(|n| *n <= 50_000_000)
        .ok_or_else(too_large)?;
    let mut cells: Vec<Cell> = Vec::with_capacity(total);
    if lattice == LatticeKind::Hex {
        return Err(BenchError::Scale(
            "hexagons do not tile an enlarged hexagon: the hex lattice has no scaling series"
                .into(),
        ));
    }
    if lattice == LatticeKind::Tri3 {
        for &c in figure.cells() {
            scale_tri3(c, ki, &mut cells).ok_or_else(too_large)?;
        }
        return Figure::new(lattice, cells).map_err(|e| BenchError::Scale(e.to_string()));
    }
    for &[x, y, z] in figure.cells() {
        let (x, y) = (
            x.checked_mul(ki).ok_or_else(too_large)?,
            y.checked_mul(ki).ok_or_else(too_large)?,
        );
        match lattice {
            LatticeKind::Square => {
                for j in 0..ki {
                    for i in 0..ki {
                        cells.push([x + i, y + j, 0]);
                    }
                }
            }
            LatticeKind::Cubic => {
                let z = z.checked_mul(ki).ok_or_else(too_large)?;
                for l in 0..ki {
                    for j in 0..ki {
                        for i in 0..ki {
                            cells.push([x + i, y + j, z + l]);
                        }
                    }
                }
            }
            LatticeKind::Tri3 | LatticeKind::Hex => unreachable!("handled above"),
            LatticeKind::Tri4 => {
                let s = 6 * ki;
                for j in 0..ki {
                    for i in 0..ki {
                        for (t, r) in TRI_CENTROID6.iter().enumerate() {
                            // The small centroid relative to the big square, in
                            // sixths of a small square: a, b in (0, 6k).
                            let a = 6 * i + r[0];
                            let b = 6 * j + r[1];
                            if big_triangle(a, b, s) == z {
                                cells.push([x + i, y + j, t as i32]);
                            }
                        }
                    }
                }
            }
        }
    }
    Figure::new(lattice, cells).map_err(|e| BenchError::Scale(e.to_string()))
}

/// Which triangle (0 top, 1 right, 2 bottom, 3 left) of the square
/// `(0, 0)-(s, s)` holds the point `(a, b)` (y down). Points on a diagonal
/// never occur here: centroids are never on one.
fn big_triangle(a: i32, b: i32, s: i32) -> i32 {
    match (b < a, a + b < s) {
        (true, true) => 0,
        (true, false) => 1,
        (false, false) => 2,
        (false, true) => 3,
    }
}

/// The `k²` small `tri3` triangles of `cell` enlarged `k` times about the
/// origin vertex, pushed onto `out`; `None` on overflow.
///
/// In the skew basis `a`, `b` of the vertices, an up triangle with apex `A`
/// has the vertices `A`, `A + b − a`, `A + b` (point `3A + (−1, 2)`), a down
/// triangle with top left vertex `T` has `T`, `T + a`, `T + b` (point
/// `3T + (1, 1)`). Enlarged, an up triangle holds the small up triangles
/// with apex `kA + m(b − a) + n·a` (`0 ≤ n ≤ m < k`) and the small down ones
/// with top left vertex `kA + m(b − a) + n·a` (`0 ≤ n < m < k`); a down
/// triangle holds the small down triangles with top left `kT + m·b + n·a`
/// (`m + n < k`) and the small up ones with apex `kT + m·b + n·a`
/// (`n ≥ 1`, `m + n < k`).
fn scale_tri3(cell: Cell, k: i32, out: &mut Vec<Cell>) -> Option<()> {
    let l = LatticeKind::Tri3.lattice();
    let p = l.to_point(cell);
    let up = p[0].rem_euclid(3) == 2;
    let corner = if up { [-1, 2] } else { [1, 1] };
    let v = [(p[0] - corner[0]) / 3, (p[1] - corner[1]) / 3];
    let base = [v[0].checked_mul(k)?, v[1].checked_mul(k)?];
    let mut push = |vertex: [i32; 2], small_up: bool| -> Option<()> {
        let c = if small_up { [-1, 2] } else { [1, 1] };
        let q = Point::new(
            vertex[0].checked_mul(3)?.checked_add(c[0])?,
            vertex[1].checked_mul(3)?.checked_add(c[1])?,
            0,
        );
        out.push(l.from_point(q)?);
        Some(())
    };
    for m in 0..k {
        for n in 0..k {
            if up {
                // kA + m(b − a) + n·a = kA + (n − m, m)
                let vertex = [base[0] + n - m, base[1] + m];
                if n <= m {
                    push(vertex, true)?;
                }
                if n < m {
                    push(vertex, false)?;
                }
            } else {
                // kT + m·b + n·a = kT + (n, m)
                let vertex = [base[0] + n, base[1] + m];
                if m + n < k {
                    push(vertex, false)?;
                    if n >= 1 {
                        push(vertex, true)?;
                    }
                }
            }
        }
    }
    Some(())
}
