//! A lattice's cells as a periodic tiling of the plane: the description a
//! drawer that works cell by cell (the studio's editor and result views)
//! needs, made from [`cell_polygon`], [`cell_centre`] and the lattice's
//! neighbours, so that no drawer keeps geometry of its own.
//!
//! The cells of a 2D lattice repeat with a *period* `[px, py]` in cell
//! coordinates: cell `(x + px, y, t)` is cell `(x, y, t)` moved by the plane
//! vector `steps[0]`, and `(x, y + py, t)` moved by `steps[1]` (`square`,
//! `tri4`: `[1, 1]`; `tri3`: `[2, 2]`, up and down triangles alternate; `hex`:
//! `[1, 2]`, odd rows are shifted). One [`Tile`] per cell of the block
//! `0..px × 0..py` gives its polygon, centre and, for each polygon edge, the
//! neighbour across it as an offset in cell coordinates. `cubic` is drawn
//! layer by layer: its tiling is the square one of a layer, and the third
//! cell coordinate is the layer.
//!
//! Plane coordinates are lattice units (side of a square or triangle,
//! distance between hexagon centres), image orientation (y grows downward),
//! the plane of [`crate::outline::Loop::points_f64`].

use std::collections::HashMap;

use dissect_core::{Cell, LatticeKind};
use serde_json::{json, Value};

use crate::outline::{cell_polygon, grid_unit, HalfPoint};
use crate::scene::cell_centre;

/// One cell of the periodic block.
#[derive(Clone, Debug, PartialEq)]
pub struct Tile {
    /// The cell, in `0..px × 0..py` (and its `t` on `tri4`).
    pub cell: Cell,
    /// Its corners in the plane, positive (shoelace) orientation.
    pub polygon: Vec<[f64; 2]>,
    /// Its centre (the centroid for triangles).
    pub centre: [f64; 2],
    /// `across[i]`: the neighbour across the edge from corner `i` to corner
    /// `i + 1`, as the offset `[dx, dy, dt]` from this cell.
    pub across: Vec<[i32; 3]>,
}

/// The periodic description of a lattice's cells (of one layer for `cubic`).
#[derive(Clone, Debug, PartialEq)]
pub struct Tiling {
    lattice: LatticeKind,
    period: [i32; 2],
    steps: [[f64; 2]; 2],
    tiles: Vec<Tile>,
}

/// The cell drawn for `c`: a `cubic` layer is drawn as squares.
fn flat(lattice: LatticeKind) -> LatticeKind {
    if lattice == LatticeKind::Cubic {
        LatticeKind::Square
    } else {
        lattice
    }
}

/// The polygon of `c` in grid units.
fn poly(lattice: LatticeKind, c: Cell) -> Vec<HalfPoint> {
    cell_polygon(flat(lattice), c)
}

/// The plane offset (grid units) that moves every cell of `cells` onto the
/// cell moved by `d` in cell coordinates, if one offset does that for all.
fn common_shift(lattice: LatticeKind, cells: &[Cell], d: [i32; 2]) -> Option<HalfPoint> {
    let mut shift = None;
    for &c in cells {
        let a = poly(lattice, c);
        let b = poly(lattice, [c[0] + d[0], c[1] + d[1], c[2]]);
        if a.len() != b.len() {
            return None;
        }
        let s = [b[0][0] - a[0][0], b[0][1] - a[0][1]];
        if a.iter()
            .zip(&b)
            .any(|(p, q)| [q[0] - p[0], q[1] - p[1]] != s)
        {
            return None;
        }
        match shift {
            None => shift = Some(s),
            Some(t) if t != s => return None,
            Some(_) => {}
        }
    }
    shift
}

impl Tiling {
    /// The tiling of `lattice`.
    pub fn of(lattice: LatticeKind) -> Tiling {
        let l = lattice.lattice();
        let unit = grid_unit(flat(lattice));
        let plane = |p: HalfPoint| [p[0] as f64 * unit[0], p[1] as f64 * unit[1]];
        // The smallest period along each axis: every lattice here repeats
        // within 6 cells (a sample window of 6 × 6 blocks checks it).
        let sample = l.cells_in_box([-3, -3, 0], [3, 3, 0]);
        let find = |axis: usize| -> (i32, HalfPoint) {
            (1..=6)
                .find_map(|p| {
                    let d = if axis == 0 { [p, 0] } else { [0, p] };
                    common_shift(lattice, &sample, d).map(|s| (p, s))
                })
                .expect("a lattice's cells repeat within 6 cells")
        };
        let (px, sx) = find(0);
        let (py, sy) = find(1);
        let cells = l.cells_in_box([0, 0, 0], [px - 1, py - 1, 0]);
        let tiles = cells
            .iter()
            .map(|&c| {
                let p = poly(lattice, c);
                let across = (0..p.len())
                    .map(|i| {
                        let (a, b) = (p[i], p[(i + 1) % p.len()]);
                        l.neighbors(c)
                            .into_iter()
                            .filter(|n| n[2] == c[2] || lattice != LatticeKind::Cubic)
                            .find(|n| {
                                let q = poly(lattice, *n);
                                (0..q.len()).any(|j| q[j] == b && q[(j + 1) % q.len()] == a)
                            })
                            .map(|n| [n[0] - c[0], n[1] - c[1], n[2] - c[2]])
                            .expect("every cell edge is shared with a neighbour")
                    })
                    .collect();
                Tile {
                    cell: c,
                    polygon: p.iter().map(|q| plane(*q)).collect(),
                    centre: cell_centre(flat(lattice), c),
                    across,
                }
            })
            .collect();
        Tiling {
            lattice,
            period: [px, py],
            steps: [plane(sx), plane(sy)],
            tiles,
        }
    }

    /// The lattice.
    pub fn lattice(&self) -> LatticeKind {
        self.lattice
    }

    /// The period `[px, py]` in cell coordinates.
    pub fn period(&self) -> [i32; 2] {
        self.period
    }

    /// The plane vectors of one period along x and along y.
    pub fn steps(&self) -> [[f64; 2]; 2] {
        self.steps
    }

    /// The cells of the periodic block.
    pub fn tiles(&self) -> &[Tile] {
        &self.tiles
    }

    /// The polygon of any cell in the plane (for a `cubic` cell, its square).
    pub fn polygon(&self, c: Cell) -> Vec<[f64; 2]> {
        let [px, py] = self.period;
        let (bx, by) = (c[0].div_euclid(px), c[1].div_euclid(py));
        let t = if self.lattice == LatticeKind::Cubic {
            0
        } else {
            c[2]
        };
        let rest = [c[0].rem_euclid(px), c[1].rem_euclid(py), t];
        let tile = self
            .tiles
            .iter()
            .find(|tile| tile.cell == rest)
            .expect("a cell of the lattice");
        let off = [
            bx as f64 * self.steps[0][0] + by as f64 * self.steps[1][0],
            bx as f64 * self.steps[0][1] + by as f64 * self.steps[1][1],
        ];
        tile.polygon
            .iter()
            .map(|p| [p[0] + off[0], p[1] + off[1]])
            .collect()
    }

    /// The description as JSON (the studio's `GET /api/lattices`).
    pub fn to_json(&self) -> Value {
        json!({
            "lattice": self.lattice.name(),
            "dim": self.lattice.lattice().dim(),
            "arity": self.lattice.cell_arity(),
            "layers": self.lattice == LatticeKind::Cubic,
            "mirror": self.lattice.lattice().supports_mirror(),
            "period": self.period,
            "steps": self.steps,
            "tiles": self.tiles.iter().map(|t| json!({
                "cell": t.cell,
                "polygon": t.polygon,
                "centre": t.centre,
                "across": t.across,
            })).collect::<Vec<_>>(),
        })
    }
}

/// The tilings of every lattice, by name.
pub fn all() -> HashMap<&'static str, Tiling> {
    LatticeKind::ALL
        .iter()
        .map(|k| (k.name(), Tiling::of(*k)))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::collections::HashSet;

    fn close(a: [f64; 2], b: [f64; 2]) -> bool {
        (a[0] - b[0]).abs() < 1e-9 && (a[1] - b[1]).abs() < 1e-9
    }

    #[test]
    fn periods_and_steps_follow_format_md() {
        let h = 3f64.sqrt() / 2.0;
        type Want = (LatticeKind, [i32; 2], [[f64; 2]; 2], usize);
        let want: [Want; 5] = [
            (LatticeKind::Square, [1, 1], [[1.0, 0.0], [0.0, 1.0]], 1),
            (LatticeKind::Tri4, [1, 1], [[1.0, 0.0], [0.0, 1.0]], 4),
            (LatticeKind::Cubic, [1, 1], [[1.0, 0.0], [0.0, 1.0]], 1),
            (LatticeKind::Tri3, [2, 2], [[1.0, 0.0], [0.0, 2.0 * h]], 4),
            (LatticeKind::Hex, [1, 2], [[1.0, 0.0], [0.0, 2.0 * h]], 2),
        ];
        for (k, period, steps, n) in want {
            let t = Tiling::of(k);
            assert_eq!(t.period(), period, "{k}");
            assert!(
                close(t.steps()[0], steps[0]) && close(t.steps()[1], steps[1]),
                "{k}: {:?}",
                t.steps()
            );
            assert_eq!(t.tiles().len(), n, "{k}");
        }
    }

    /// FORMAT.md: tri3 (x, y) points up when x + y is even, spans
    /// x/2..x/2 + 1 in row y; hex (x, y) is centred at (x + (y mod 2)/2, y·h).
    #[test]
    fn polygons_are_the_cells_of_format_md() {
        let h = 3f64.sqrt() / 2.0;
        let tri = Tiling::of(LatticeKind::Tri3);
        for y in -3..4 {
            for x in -4..5 {
                let p = tri.polygon([x, y, 0]);
                assert_eq!(p.len(), 3);
                let (xf, yf) = (x as f64, y as f64);
                let apex = if (x + y).rem_euclid(2) == 0 {
                    [(xf + 1.0) / 2.0, yf * h]
                } else {
                    [(xf + 1.0) / 2.0, (yf + 1.0) * h]
                };
                assert!(p.iter().any(|q| close(*q, apex)), "tri3 {x},{y}: {p:?}");
                let minx = p.iter().map(|q| q[0]).fold(f64::INFINITY, f64::min);
                assert!((minx - xf / 2.0).abs() < 1e-9);
            }
        }
        let hex = Tiling::of(LatticeKind::Hex);
        for y in -3..4 {
            for x in -3..4 {
                let p = hex.polygon([x, y, 0]);
                assert_eq!(p.len(), 6);
                let c = [x as f64 + y.rem_euclid(2) as f64 / 2.0, y as f64 * h];
                for q in &p {
                    let r = ((q[0] - c[0]).powi(2) + (q[1] - c[1]).powi(2)).sqrt();
                    assert!((r - 1.0 / 3f64.sqrt()).abs() < 1e-9, "hex {x},{y}");
                }
            }
        }
    }

    /// The neighbour across every edge is a lattice neighbour, its polygon
    /// has that edge, and every neighbour (in the layer) is across one edge.
    #[test]
    fn the_cell_across_each_edge_is_the_lattice_neighbour_there() {
        for k in LatticeKind::ALL {
            let t = Tiling::of(k);
            let l = k.lattice();
            for c in l.cells_in_box([-2, -2, 0], [3, 3, 0]) {
                let p = t.polygon(c);
                let [px, py] = t.period();
                let rest = [c[0].rem_euclid(px), c[1].rem_euclid(py), c[2]];
                let tile = t.tiles().iter().find(|x| x.cell == rest).unwrap();
                let mut seen = HashSet::new();
                for (i, d) in tile.across.iter().enumerate() {
                    let n = [c[0] + d[0], c[1] + d[1], c[2] + d[2]];
                    assert!(l.neighbors(c).contains(&n), "{k}: {c:?} -> {n:?}");
                    let q = t.polygon(n);
                    let (a, b) = (p[i], p[(i + 1) % p.len()]);
                    assert!(
                        (0..q.len()).any(|j| close(q[j], b) && close(q[(j + 1) % q.len()], a)),
                        "{k}: {c:?} edge {i}"
                    );
                    seen.insert(n);
                }
                let in_layer = l
                    .neighbors(c)
                    .into_iter()
                    .filter(|n| n[2] == c[2] || k != LatticeKind::Cubic)
                    .count();
                assert_eq!(seen.len(), in_layer, "{k}: {c:?}");
                // The centre lies inside.
                let cen = cell_centre(flat(k), c);
                let n = p.len();
                let inside = (0..n).all(|i| {
                    let (a, b) = (p[i], p[(i + 1) % n]);
                    (b[0] - a[0]) * (cen[1] - a[1]) - (b[1] - a[1]) * (cen[0] - a[0]) > 0.0
                });
                assert!(inside, "{k}: centre of {c:?}");
            }
        }
    }

    #[test]
    fn the_json_lists_every_tile() {
        let v = Tiling::of(LatticeKind::Hex).to_json();
        assert_eq!(v["lattice"], "hex");
        assert_eq!(v["period"], json!([1, 2]));
        assert_eq!(v["tiles"].as_array().unwrap().len(), 2);
        assert_eq!(v["tiles"][1]["across"].as_array().unwrap().len(), 6);
        assert_eq!(Tiling::of(LatticeKind::Cubic).to_json()["layers"], true);
        assert_eq!(all().len(), 5);
    }
}
