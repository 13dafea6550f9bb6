//! STL models of the pieces, in millimetres: one closed, manifold mesh per
//! piece with coplanar faces merged (one polygon per flat face, triangulated
//! without T-junctions). 2D pieces are their merged outline extruded to a
//! thickness; `cubic` pieces are the surface of their cubes. A clearance
//! shrinks every piece by that much on every side (a mitred offset of the
//! outline in 2D; an erosion by a small cube in 3D) so printed pieces fit.
//!
//! Axes: `x` to the right, `y` away from the viewer (the figure text's rows
//! run toward the viewer), `z` up (the figure's z layers).

use std::collections::{BTreeMap, HashMap, HashSet};

use dissect_core::{Cell, LatticeKind};

use crate::ear_clipping::triangulate;
use crate::mesh::{normal, Mesh};
use crate::outline::Outline;
use crate::{RenderError, Scene};

/// Sizes for physical output.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PhysicalOptions {
    /// The edge of one cell, mm.
    pub cell_mm: f64,
    /// The height of an extruded 2D piece, mm.
    pub thickness_mm: f64,
    /// How much every piece shrinks on each side, mm.
    pub clearance_mm: f64,
}

impl Default for PhysicalOptions {
    fn default() -> Self {
        PhysicalOptions {
            cell_mm: 10.0,
            thickness_mm: 4.0,
            clearance_mm: 0.1,
        }
    }
}

impl PhysicalOptions {
    /// Checks the ranges: sizes positive and finite, the clearance below a
    /// tenth of a cell (a larger one would eat thin parts of pieces).
    pub fn check(&self) -> Result<(), RenderError> {
        let ok = |v: f64| v.is_finite() && v > 0.0;
        if !ok(self.cell_mm) {
            return Err(RenderError::BadOption(format!(
                "--cell-mm must be > 0, got {}",
                self.cell_mm
            )));
        }
        if !ok(self.thickness_mm) {
            return Err(RenderError::BadOption(format!(
                "--thickness must be > 0, got {}",
                self.thickness_mm
            )));
        }
        if !(self.clearance_mm.is_finite()
            && self.clearance_mm >= 0.0
            && self.clearance_mm < self.cell_mm / 10.0)
        {
            return Err(RenderError::BadOption(format!(
                "--clearance must be >= 0 and below a tenth of --cell-mm ({} mm), got {}",
                self.cell_mm / 10.0,
                self.clearance_mm
            )));
        }
        Ok(())
    }
}

/// One binary STL per piece (named `piece-A.stl`, ...), made from the
/// pieces as they lie in the first figure. Fails rather than write a mesh
/// that is not closed and manifold (a piece touching itself at a corner
/// needs a clearance).
pub fn render(
    scene: &Scene,
    opts: &PhysicalOptions,
) -> Result<Vec<(String, Vec<u8>)>, RenderError> {
    (0..scene.piece_count())
        .map(|i| {
            let name = piece_file_stem(scene, i);
            let mesh = piece_mesh(scene, i, opts)?;
            if mesh.bad_edges() > 0 {
                return Err(RenderError::BadOption(format!(
                    "piece {} touches itself along an edge or at a corner, so its mesh cannot be manifold without a clearance: give --clearance > 0",
                    scene.label(i)
                )));
            }
            Ok((format!("{name}.stl"), mesh.to_binary_stl(&name)))
        })
        .collect()
}

/// The file name (without `.stl`) of piece `i`: `piece-01-A`, its number
/// padded to the width of the piece count (at least 2 digits), then its
/// label when it has one (pieces past the 62nd share the label `*`). The
/// number makes every name unique for any piece count, also where file
/// names are not case-sensitive (`piece-01-A`, `piece-27-a`).
pub fn piece_file_stem(scene: &Scene, i: usize) -> String {
    let width = scene.piece_count().to_string().len().max(2);
    let label = scene.label(i);
    if label.chars().all(|c| c.is_ascii_alphanumeric()) {
        format!("piece-{:0width$}-{label}", i + 1)
    } else {
        format!("piece-{:0width$}", i + 1)
    }
}

/// The mesh of piece `i` (as it lies in the first figure).
pub fn piece_mesh(scene: &Scene, i: usize, opts: &PhysicalOptions) -> Result<Mesh, RenderError> {
    opts.check()?;
    let cells = scene.cells(0, i);
    match scene.lattice() {
        LatticeKind::Cubic => voxel_mesh(cells, opts),
        lattice => extrude(&Outline::of_cells(lattice, cells), opts),
    }
}

/// The loops of an outline in lattice units shrunk by `c` (mitred offset;
/// the material is on the same side of every loop).
pub fn offset_loops(outline: &Outline, c: f64) -> Vec<Vec<[f64; 2]>> {
    outline
        .loops()
        .iter()
        .map(|l| {
            let p = l.points_f64();
            let n = p.len();
            (0..n)
                .map(|k| {
                    let (a, b, d) = (p[(k + n - 1) % n], p[k], p[(k + 1) % n]);
                    if c == 0.0 {
                        return b;
                    }
                    // Material lies on the +90° side (image orientation) of each edge.
                    let unit_normal = |u: [f64; 2], v: [f64; 2]| {
                        let (dx, dy) = (v[0] - u[0], v[1] - u[1]);
                        let len = (dx * dx + dy * dy).sqrt();
                        [-dy / len, dx / len]
                    };
                    let n1 = unit_normal(a, b);
                    let n2 = unit_normal(b, d);
                    let k = c / (1.0 + n1[0] * n2[0] + n1[1] * n2[1]);
                    [b[0] + k * (n1[0] + n2[0]), b[1] + k * (n1[1] + n2[1])]
                })
                .collect()
        })
        .collect()
}

/// Signed area in image orientation (positive for outer loops).
fn loop_area(l: &[[f64; 2]]) -> f64 {
    let n = l.len();
    (0..n)
        .map(|i| l[i][0] * l[(i + 1) % n][1] - l[(i + 1) % n][0] * l[i][1])
        .sum::<f64>()
        / 2.0
}

fn point_in(l: &[[f64; 2]], p: [f64; 2]) -> bool {
    let mut inside = false;
    let n = l.len();
    for i in 0..n {
        let (a, b) = (l[i], l[(i + 1) % n]);
        if (a[1] > p[1]) != (b[1] > p[1]) {
            let x = a[0] + (p[1] - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
            if p[0] < x {
                inside = !inside;
            }
        }
    }
    inside
}

/// Triangles filling loops given in image orientation (outer loops positive,
/// holes negative), as index triples into the concatenated loop points;
/// the triangles have positive shoelace area like the outer loops.
fn fill_loops(loops: &[Vec<[f64; 2]>]) -> Result<Vec<[usize; 3]>, RenderError> {
    let mut pts = Vec::new();
    let mut ids = Vec::new();
    for l in loops {
        let start = pts.len();
        pts.extend(l.iter().copied());
        ids.push((start..start + l.len()).collect::<Vec<usize>>());
    }
    let outers: Vec<usize> = (0..loops.len())
        .filter(|&k| loop_area(&loops[k]) > 0.0)
        .collect();
    let mut holes_of: HashMap<usize, Vec<Vec<usize>>> = HashMap::new();
    for k in (0..loops.len()).filter(|&k| loop_area(&loops[k]) <= 0.0) {
        let l = &loops[k];
        let probe = [(l[0][0] + l[1][0]) / 2.0, (l[0][1] + l[1][1]) / 2.0];
        let owner = outers
            .iter()
            .copied()
            .filter(|&o| point_in(&loops[o], probe))
            .min_by(|a, b| loop_area(&loops[*a]).total_cmp(&loop_area(&loops[*b])))
            .ok_or_else(|| RenderError::Draw("a hole outside every outline".into()))?;
        holes_of.entry(owner).or_default().push(ids[k].clone());
    }
    let mut tris = Vec::new();
    for o in outers {
        let holes = holes_of.remove(&o).unwrap_or_default();
        tris.extend(
            triangulate(&pts, &ids[o], &holes)
                .ok_or_else(|| RenderError::Draw("cannot triangulate a piece outline".into()))?,
        );
    }
    Ok(tris)
}

fn extrude(outline: &Outline, opts: &PhysicalOptions) -> Result<Mesh, RenderError> {
    let s = opts.cell_mm;
    let loops = offset_loops(outline, opts.clearance_mm / s);
    let tris = fill_loops(&loops)?;
    let flat: Vec<[f64; 2]> = loops.iter().flatten().copied().collect();
    // Physical: x right, y away from the viewer (= up the page).
    let at = |p: [f64; 2], z: f64| [p[0] * s, -p[1] * s, z];
    let h = opts.thickness_mm;
    let mut out = Vec::new();
    for t in &tris {
        let (a, b, c) = (flat[t[0]], flat[t[1]], flat[t[2]]);
        // Flipping y turns the triangles over: the top runs a, c, b.
        out.push([at(a, h), at(c, h), at(b, h)]);
        out.push([at(a, 0.0), at(b, 0.0), at(c, 0.0)]);
    }
    for l in &loops {
        let n = l.len();
        for k in 0..n {
            let (a, b) = (l[k], l[(k + 1) % n]);
            // Image-orientation loops have the material on the +90° side;
            // after flipping y, walls face outward when wound b→a at the bottom.
            out.push([at(b, 0.0), at(a, 0.0), at(a, h)]);
            out.push([at(b, 0.0), at(a, h), at(b, h)]);
        }
    }
    Ok(Mesh::new(out))
}

/// The corner loops of one flat face: axis, direction, loops of grid points.
type FaceLoops = (usize, i32, Vec<Vec<[i32; 3]>>);

/// The surface of a set of cubes shrunk by `clearance`, with one polygon per
/// flat face.
fn voxel_mesh(cells: &[Cell], opts: &PhysicalOptions) -> Result<Mesh, RenderError> {
    let c = opts.clearance_mm / opts.cell_mm;
    let (solid, split) = shrunk_solid(cells, c);
    let coord = |line: i32| -> f64 {
        if split == 1 {
            return line as f64;
        }
        let (k, r) = (line.div_euclid(3) as f64, line.rem_euclid(3));
        match r {
            0 => k,
            1 => k + c,
            _ => k + 1.0 - c,
        }
    };
    let faces = face_loops(&solid);
    let on_line = corners_on_lines(&faces);
    let s = opts.cell_mm;
    let phys = |q: [i32; 3]| [coord(q[0]) * s, -coord(q[1]) * s, coord(q[2]) * s];
    let mut out = Vec::new();
    for (axis, dir, loops) in faces {
        let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
        let mut pts2: Vec<[f64; 2]> = Vec::new();
        let mut pts3: Vec<[i32; 3]> = Vec::new();
        let mut rings: Vec<Vec<[f64; 2]>> = Vec::new();
        for l in &loops {
            let mut ring = Vec::new();
            for k in 0..l.len() {
                let (a, b) = (l[k], l[(k + 1) % l.len()]);
                ring.push(a);
                // The axis along which this edge runs.
                let e = (0..3).find(|&d| a[d] != b[d]).expect("edges have length");
                let (eu, ew) = ((e + 1) % 3, (e + 2) % 3);
                if let Some(list) = on_line.get(&(e, a[eu], a[ew])) {
                    let (lo, hi) = (a[e].min(b[e]), a[e].max(b[e]));
                    let mut mid: Vec<i32> =
                        list.iter().copied().filter(|&t| t > lo && t < hi).collect();
                    if a[e] > b[e] {
                        mid.reverse();
                    }
                    for t in mid {
                        let mut q = a;
                        q[e] = t;
                        ring.push(q);
                    }
                }
            }
            pts3.extend(&ring);
            let ring2: Vec<[f64; 2]> = ring.iter().map(|q| [q[u] as f64, q[w] as f64]).collect();
            pts2.extend(&ring2);
            rings.push(ring2);
        }
        let tris = fill_loops(&rings)?;
        let mut expected = [0.0; 3];
        expected[axis] = dir as f64;
        expected[1] = -expected[1];
        for t in tris {
            let tri = [phys(pts3[t[0]]), phys(pts3[t[1]]), phys(pts3[t[2]])];
            let n = normal(&tri);
            let facing = n[0] * expected[0] + n[1] * expected[1] + n[2] * expected[2];
            out.push(if facing < 0.0 {
                [tri[0], tri[2], tri[1]]
            } else {
                tri
            });
        }
        let _ = pts2;
    }
    Ok(Mesh::new(out))
}

/// The solid on a grid of "lines" and the lines per unit: with a
/// clearance `c` (in cells) every unit is split into three slabs
/// [k, k+c], [k+c, k+1-c], [k+1-c, k+1].
fn shrunk_solid(cells: &[Cell], c: f64) -> (HashSet<Cell>, i32) {
    let set: HashSet<Cell> = cells.iter().copied().collect();
    if c == 0.0 {
        (set.clone(), 1)
    } else {
        let mut solid = HashSet::new();
        for &[x, y, z] in cells {
            for s in 0..27 {
                let sub = [s % 3, s / 3 % 3, s / 9];
                let needs = |k: i32, s: i32| match s {
                    0 => vec![k - 1, k],
                    1 => vec![k],
                    _ => vec![k, k + 1],
                };
                let (nx, ny, nz) = (needs(x, sub[0]), needs(y, sub[1]), needs(z, sub[2]));
                let inside = nx.iter().all(|&a| {
                    ny.iter()
                        .all(|&b| nz.iter().all(|&cc| set.contains(&[a, b, cc])))
                });
                if inside {
                    solid.insert([3 * x + sub[0], 3 * y + sub[1], 3 * z + sub[2]]);
                }
            }
        }
        (solid, 3)
    }
}

/// The exposed faces of `solid` grouped by (axis, direction, plane line),
/// each as loops of grid points.
fn face_loops(solid: &HashSet<Cell>) -> Vec<FaceLoops> {
    // Exposed faces grouped by (axis, direction, plane line).
    let mut groups: BTreeMap<(usize, i32, i32), Vec<Cell>> = BTreeMap::new();
    let mut sorted: Vec<Cell> = solid.iter().copied().collect();
    sorted.sort();
    for &v in &sorted {
        for axis in 0..3 {
            for dir in [-1, 1] {
                let mut n = v;
                n[axis] += dir;
                if solid.contains(&n) {
                    continue;
                }
                let plane = if dir > 0 { v[axis] + 1 } else { v[axis] };
                let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
                groups
                    .entry((axis, dir, plane))
                    .or_default()
                    .push([v[u], v[w], 0]);
            }
        }
    }
    // Face loops in grid lines (3D integer points).
    let mut faces: Vec<FaceLoops> = Vec::new();
    for (&(axis, dir, plane), squares) in &groups {
        let outline = Outline::of_cells(LatticeKind::Square, squares);
        let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
        let loops = outline
            .loops()
            .iter()
            .map(|l| {
                l.points()
                    .iter()
                    .map(|p| {
                        let mut q = [0; 3];
                        q[axis] = plane;
                        q[u] = (p[0] / 2) as i32;
                        q[w] = (p[1] / 2) as i32;
                        q
                    })
                    .collect()
            })
            .collect();
        faces.push((axis, dir, loops));
    }
    faces
}

/// Every corner of every face, by the line it lies on (axis and the two
/// other coordinates), sorted along it: to split edges at T-junctions.
fn corners_on_lines(faces: &[FaceLoops]) -> HashMap<(usize, i32, i32), Vec<i32>> {
    // Every corner of every face, by the line it lies on, to split edges at
    // T-junctions.
    let mut on_line: HashMap<(usize, i32, i32), Vec<i32>> = HashMap::new();
    let mut corners: HashSet<[i32; 3]> = HashSet::new();
    for (_, _, loops) in faces {
        for p in loops.iter().flatten() {
            corners.insert(*p);
        }
    }
    for p in &corners {
        for axis in 0..3 {
            let (u, w) = ((axis + 1) % 3, (axis + 2) % 3);
            on_line.entry((axis, p[u], p[w])).or_default().push(p[axis]);
        }
    }
    for v in on_line.values_mut() {
        v.sort_unstable();
    }
    on_line
}

#[cfg(test)]
mod tests {
    use super::*;
    use dissect_core::io::parse_figure;

    fn cubic_mesh(text: &str, clearance: f64) -> Mesh {
        let f = parse_figure(text, LatticeKind::Cubic).unwrap();
        let opts = PhysicalOptions {
            cell_mm: 10.0,
            thickness_mm: 3.0,
            clearance_mm: clearance,
        };
        voxel_mesh(f.cells(), &opts).unwrap()
    }

    #[test]
    fn one_cube_is_twelve_triangles() {
        let m = cubic_mesh("#\n", 0.0);
        assert_eq!(m.triangles().len(), 12);
        assert_eq!(m.bad_edges(), 0);
        assert!((m.volume() - 1000.0).abs() < 1e-9);
    }

    #[test]
    fn a_step_needs_its_t_junction_split() {
        // Two cubes side by side plus one on top of the left one, and one
        // more in front: faces meet with T-junctions.
        let m = cubic_mesh("##\n#.\n\n#.\n", 0.0);
        assert_eq!(m.bad_edges(), 0);
        assert!((m.volume() - 4000.0).abs() < 1e-6);
    }

    #[test]
    fn clearance_erodes_by_the_clearance() {
        let m = cubic_mesh("##\n", 1.0);
        assert_eq!(m.bad_edges(), 0);
        assert!(
            (m.volume() - 18.0 * 8.0 * 8.0).abs() < 1e-6,
            "{}",
            m.volume()
        );
    }
}
