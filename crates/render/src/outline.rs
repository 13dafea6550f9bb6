//! Outlines: the boundary of a set of lattice cells as closed polygons, one
//! per connected boundary curve (the outer boundary and each hole), found by
//! cancelling shared edges and tracing the rest.
//!
//! Corners are stored as integer *grid units* so that shared edges cancel
//! exactly: on `square`, `tri4` (and `cubic` faces) half units, the point
//! `(x, y)` of the plane stored as `[2x, 2y]`, so the centre of a `tri4`
//! square is an integer point too; on `tri3` `[2x, y/h]` and on `hex`
//! `[2x, 3y/h]` (`h = √3/2`: triangle corners lie on the rows' lines, hexagon
//! corners a third of a row from their centres). [`Loop::points_f64`] gives
//! the plane. The plane is in image orientation (y grows downward).

use std::collections::HashMap;

use dissect_core::{Cell, LatticeKind};

/// A point in grid units (half units `[2x, 2y]` on `square` and `tri4`;
/// see the module documentation for `tri3` and `hex`).
pub type HalfPoint = [i64; 2];

/// The plane length of one grid unit along x and along y.
pub fn grid_unit(lattice: LatticeKind) -> [f64; 2] {
    let h = 3f64.sqrt() / 2.0;
    match lattice {
        LatticeKind::Tri3 => [0.5, h],
        LatticeKind::Hex => [0.5, h / 3.0],
        LatticeKind::Square | LatticeKind::Tri4 | LatticeKind::Cubic => [0.5, 0.5],
    }
}

/// One closed boundary curve.
///
/// # Validity
/// At least 3 points, no two consecutive points equal and no three
/// consecutive points collinear (edges are merged). Edges run along cell
/// edges of `lattice` (horizontal, vertical or at 45° on `square` and
/// `tri4`; at multiples of 60° on `tri3`, of 60° plus 30° on `hex`). The material is always on the same side
/// ([`Loop::is_hole`] tells which way round the curve goes). A curve may
/// touch itself at a vertex where two corners of the material meet; it is
/// then traced so that each corner is turned round on its own.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Loop {
    points: Vec<HalfPoint>,
    lattice: LatticeKind,
}

impl Loop {
    /// The corners in grid units.
    pub fn points(&self) -> &[HalfPoint] {
        &self.points
    }

    /// The corners in the plane, in lattice units (the side of a square or
    /// triangle, the distance between hexagon centres).
    pub fn points_f64(&self) -> Vec<[f64; 2]> {
        let u = grid_unit(self.lattice);
        self.points
            .iter()
            .map(|p| [p[0] as f64 * u[0], p[1] as f64 * u[1]])
            .collect()
    }

    /// Twice the signed area in grid units squared (shoelace, image
    /// orientation): positive for an outer boundary, negative for a hole.
    pub fn doubled_area(&self) -> i64 {
        let n = self.points.len();
        (0..n)
            .map(|i| {
                let a = self.points[i];
                let b = self.points[(i + 1) % n];
                a[0] * b[1] - b[0] * a[1]
            })
            .sum()
    }

    /// Whether this curve bounds a hole (it runs the other way round).
    pub fn is_hole(&self) -> bool {
        self.doubled_area() < 0
    }
}

/// The outline of a set of cells: its boundary curves.
#[derive(Clone, Debug, PartialEq, Eq, Default)]
pub struct Outline {
    loops: Vec<Loop>,
}

impl Outline {
    /// The outline of `cells` (any 2D lattice; `cubic` cells are read as
    /// squares `(x, y)` and their `z` ignored).
    pub fn of_cells(lattice: LatticeKind, cells: &[Cell]) -> Outline {
        let unit = grid_unit(lattice);
        let dir_index = |a: HalfPoint, b: HalfPoint| direction(unit, a, b);
        // A cell listed twice would leave edges that close no curve.
        let mut cells = cells.to_vec();
        cells.sort_unstable();
        cells.dedup();
        let mut edges: HashMap<(HalfPoint, HalfPoint), i32> = HashMap::new();
        for &c in &cells {
            let poly = cell_polygon(lattice, c);
            for i in 0..poly.len() {
                let a = poly[i];
                let b = poly[(i + 1) % poly.len()];
                if let Some(n) = edges.get_mut(&(b, a)) {
                    *n -= 1;
                    if *n == 0 {
                        edges.remove(&(b, a));
                    }
                } else {
                    *edges.entry((a, b)).or_insert(0) += 1;
                }
            }
        }
        let mut out_edges: HashMap<HalfPoint, Vec<HalfPoint>> = HashMap::new();
        let mut sorted: Vec<(HalfPoint, HalfPoint)> = edges.keys().copied().collect();
        sorted.sort();
        for &(a, b) in &sorted {
            out_edges.entry(a).or_default().push(b);
        }
        let mut loops = Vec::new();
        for &(a0, b0) in &sorted {
            // Take this edge if it is still unused.
            let Some(list) = out_edges.get_mut(&a0) else {
                continue;
            };
            let Some(pos) = list.iter().position(|b| *b == b0) else {
                continue;
            };
            list.swap_remove(pos);
            let mut pts = vec![a0];
            let (mut prev, mut cur) = (a0, b0);
            loop {
                let d_in = dir_index(prev, cur);
                let list = out_edges
                    .get_mut(&cur)
                    .expect("boundary edges form closed curves");
                let best = list
                    .iter()
                    .enumerate()
                    .max_by_key(|(_, b)| turn(d_in, dir_index(cur, **b)));
                // Back at the start: close unless the curve hugs another
                // corner of the material here first.
                if cur == a0
                    && !matches!(best, Some((_, b))
                        if turn(d_in, dir_index(cur, *b)) >= turn(d_in, dir_index(cur, b0)))
                {
                    break;
                }
                let (k, _) = best.expect("boundary edges form closed curves");
                let next = list.swap_remove(k);
                pts.push(cur);
                prev = cur;
                cur = next;
            }
            loops.push(Loop {
                points: merge_collinear(pts),
                lattice,
            });
        }
        loops.sort_by_key(|l| std::cmp::Reverse(l.doubled_area()));
        Outline { loops }
    }

    /// The boundary curves, outer boundaries first (largest first).
    pub fn loops(&self) -> &[Loop] {
        &self.loops
    }

    /// The bounding box `[min, max]` in the plane, in lattice units.
    pub fn bounds_f64(&self) -> Option<[[f64; 2]; 2]> {
        let mut it = self.loops.iter().flat_map(|l| l.points_f64());
        let first = it.next()?;
        Some(it.fold([first, first], |[lo, hi], p| {
            [
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            ]
        }))
    }

    /// The bounding box `[min, max]` in grid units.
    pub fn bounds(&self) -> Option<[HalfPoint; 2]> {
        let mut it = self.loops.iter().flat_map(|l| l.points.iter());
        let first = *it.next()?;
        Some(it.fold([first, first], |[lo, hi], p| {
            [
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            ]
        }))
    }
}

/// The polygon of one cell in grid units, in the orientation that gives a
/// positive shoelace area.
pub fn cell_polygon(lattice: LatticeKind, [x, y, t]: Cell) -> Vec<HalfPoint> {
    let (xi, yi) = (x as i64, y as i64);
    match lattice {
        // Row y between the lines y and y + 1; triangle x spans 2x..2x + 2.
        LatticeKind::Tri3 if (x + y).rem_euclid(2) == 0 => {
            return vec![[xi + 1, yi], [xi + 2, yi + 1], [xi, yi + 1]];
        }
        LatticeKind::Tri3 => return vec![[xi, yi], [xi + 2, yi], [xi + 1, yi + 1]],
        // Centre (x + (y mod 2)/2, y·h): [2x + y mod 2, 3y] in grid units.
        LatticeKind::Hex => {
            let c = [2 * xi + yi.rem_euclid(2), 3 * yi];
            return [[0, -2], [1, -1], [1, 1], [0, 2], [-1, 1], [-1, -1]]
                .iter()
                .map(|d| [c[0] + d[0], c[1] + d[1]])
                .collect();
        }
        _ => {}
    }
    let (x, y) = (2 * xi, 2 * yi);
    let (tl, tr, br, bl, c) = (
        [x, y],
        [x + 2, y],
        [x + 2, y + 2],
        [x, y + 2],
        [x + 1, y + 1],
    );
    match (lattice, t) {
        (LatticeKind::Tri4, 0) => vec![tl, tr, c],
        (LatticeKind::Tri4, 1) => vec![tr, br, c],
        (LatticeKind::Tri4, 2) => vec![br, bl, c],
        (LatticeKind::Tri4, _) => vec![bl, tl, c],
        _ => vec![tl, tr, br, bl],
    }
}

/// The direction of `a -> b` in the plane (whose grid unit is `unit`), in
/// thousandths of a degree from +x toward +y (edge directions are multiples
/// of 15°, so rounding never merges two of them).
fn direction(unit: [f64; 2], a: HalfPoint, b: HalfPoint) -> i64 {
    let dx = (b[0] - a[0]) as f64 * unit[0];
    let dy = (b[1] - a[1]) as f64 * unit[1];
    (dy.atan2(dx).to_degrees() * 1000.0).round() as i64
}

/// The turn from direction `a` to `b` (thousandths of a degree), in
/// `(-180°, 180°]`; positive turns toward the material (which lies on the
/// `+90°` side of every edge).
fn turn(a: i64, b: i64) -> i64 {
    let t = (b - a).rem_euclid(360_000);
    if t > 180_000 {
        t - 360_000
    } else {
        t
    }
}

/// Drops the points where the curve goes straight on.
fn merge_collinear(pts: Vec<HalfPoint>) -> Vec<HalfPoint> {
    let n = pts.len();
    let keep: Vec<HalfPoint> = (0..n)
        .filter(|&i| {
            let a = pts[(i + n - 1) % n];
            let b = pts[i];
            let c = pts[(i + 1) % n];
            let (u, v) = ([b[0] - a[0], b[1] - a[1]], [c[0] - b[0], c[1] - b[1]]);
            // Straight on: parallel and the same way.
            !(u[0] * v[1] - u[1] * v[0] == 0 && u[0] * v[0] + u[1] * v[1] > 0)
        })
        .map(|i| pts[i])
        .collect();
    keep
}

#[cfg(test)]
mod tests {
    use super::*;
    use dissect_core::io::parse_figure;

    fn outline(text: &str, lattice: LatticeKind) -> Outline {
        let f = parse_figure(text, lattice).unwrap();
        Outline::of_cells(lattice, f.cells())
    }

    #[test]
    fn rectangle_is_one_quadrilateral() {
        let o = outline("###\n###\n", LatticeKind::Square);
        assert_eq!(o.loops().len(), 1);
        assert_eq!(o.loops()[0].points(), &[[0, 0], [6, 0], [6, 4], [0, 4]]);
        assert_eq!(o.loops()[0].doubled_area(), 2 * 24);
    }

    #[test]
    fn ring_has_an_outer_curve_and_a_hole() {
        let o = outline("###\n#.#\n###\n", LatticeKind::Square);
        assert_eq!(o.loops().len(), 2);
        assert!(!o.loops()[0].is_hole());
        assert!(o.loops()[1].is_hole());
        assert_eq!(o.loops()[1].points().len(), 4);
    }

    #[test]
    fn pinched_hole_joins_the_outer_curve() {
        // The hole at (1,1) touches the outside at the corner (1,1).
        let o = outline(".##\n#.#\n###\n", LatticeKind::Square);
        assert_eq!(o.loops().len(), 1);
        // 7 cells; the curve visits the pinch point twice.
        assert_eq!(o.loops()[0].doubled_area(), 2 * 7 * 4);
        let pinch = o.loops()[0]
            .points()
            .iter()
            .filter(|p| **p == [2, 2])
            .count();
        assert_eq!(pinch, 2);
    }

    #[test]
    fn tri4_half_square_is_a_triangle() {
        // C = bottom + left: the half square below the \ diagonal.
        let o = outline("C\n", LatticeKind::Tri4);
        assert_eq!(o.loops().len(), 1);
        assert_eq!(o.loops()[0].points().len(), 3);
        assert_eq!(o.loops()[0].doubled_area(), 2 * 2);
    }

    #[test]
    fn tri4_staircase_of_half_squares_is_smooth() {
        // A right triangle of legs 2 made of two half squares and one square.
        let o = outline(".6\n6#\n", LatticeKind::Tri4);
        assert_eq!(o.loops().len(), 1);
        assert_eq!(o.loops()[0].points().len(), 3);
    }
}
