//! Pictures of a dissection for Python: the one palette
//! (`dissect_core::palette`), the SVG view and the shareable HTML page of
//! `dissect-render`, and the plane geometry `Dissection.plot` draws with
//! matplotlib (cell polygons from [`Tiling`], piece outlines from
//! [`Outline`]), so that Python keeps no colour and no lattice geometry of
//! its own.

use std::collections::BTreeMap;

use dissect_core::palette::{piece_hex, PIECE_COLOURS};
use dissect_core::{Cell, LatticeKind};
use dissect_render::outline::Outline;
use dissect_render::scene::deepest_cell;
use dissect_render::tiling::Tiling;
use dissect_render::{html, svg, Scene};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::errors::{error, Kind};
use crate::solve::dissection_from_py;

/// The piece colours `#rrggbb`: piece `i` has colour `PALETTE[i]` in every
/// picture (terminal, SVG, PNG, studio, page, matplotlib).
pub(crate) fn palette() -> Vec<String> {
    (0..PIECE_COLOURS.len()).map(piece_hex).collect()
}

/// The colour of piece `i` (past the palette: the engine's golden-angle hues).
#[pyfunction]
pub(crate) fn piece_colour(i: usize) -> String {
    piece_hex(i)
}

/// The scene of a dissection given by its parts.
fn scene(
    py: Python<'_>,
    lattice: &str,
    mirror: bool,
    names: Vec<String>,
    pieces: &[Vec<Vec<Vec<i64>>>],
) -> PyResult<Scene> {
    let d = dissection_from_py(py, lattice, mirror, names, pieces)?;
    Scene::new(&d).map_err(|e| error(py, Kind::InvalidSolution, e.to_string()))
}

/// `dissect render`'s SVG view of a dissection (pieces, labels, legend).
#[pyfunction]
pub(crate) fn render_svg(
    py: Python<'_>,
    lattice: &str,
    mirror: bool,
    names: Vec<String>,
    pieces: Vec<Vec<Vec<Vec<i64>>>>,
) -> PyResult<String> {
    Ok(svg::render(&scene(py, lattice, mirror, names, &pieces)?))
}

/// The shareable page of a dissection (`dissect render --html`: one
/// self-contained HTML file with the motion player).
#[pyfunction]
pub(crate) fn render_html(
    py: Python<'_>,
    lattice: &str,
    mirror: bool,
    names: Vec<String>,
    pieces: Vec<Vec<Vec<Vec<i64>>>>,
) -> PyResult<String> {
    let scene = scene(py, lattice, mirror, names, &pieces)?;
    html::page(&scene).map_err(|e| error(py, Kind::InvalidSolution, e.to_string()))
}

/// Points as a list of `(x, y)` tuples.
fn points<'py>(py: Python<'py>, ps: &[[f64; 2]]) -> PyResult<Bound<'py, PyList>> {
    PyList::new(
        py,
        ps.iter()
            .map(|p| PyTuple::new(py, p))
            .collect::<PyResult<Vec<_>>>()?,
    )
}

/// What `Dissection.plot` draws, in the plane of the lattice (lattice
/// units, y downward): `[figure][piece]` dicts with the piece's `label`,
/// `colour` and `layers` (one on 2D lattices, one per z on 3D ones), each
/// with its `layer`, the `cells` as polygons, the piece's `outline` loops
/// and the `label_at` point.
#[pyfunction]
pub(crate) fn drawing<'py>(
    py: Python<'py>,
    lattice: &str,
    pieces: Vec<Vec<Vec<Vec<i64>>>>,
) -> PyResult<Bound<'py, PyList>> {
    let kind = crate::figure::lattice(py, lattice)?;
    let tiling = Tiling::of(kind);
    let figures = PyList::empty(py);
    for fig in &pieces {
        let list = PyList::empty(py);
        for (i, piece) in fig.iter().enumerate() {
            let cells = piece
                .iter()
                .map(|c| crate::figure::cell_from_coords(py, kind, c))
                .collect::<PyResult<Vec<Cell>>>()?;
            let p = PyDict::new(py);
            p.set_item("label", dissect_core::ascii::piece_letter(i).to_string())?;
            p.set_item("colour", piece_hex(i))?;
            p.set_item("layers", layers(py, kind, &tiling, &cells)?)?;
            list.append(p)?;
        }
        figures.append(list)?;
    }
    Ok(figures)
}

/// The layers of one piece (see [`drawing`]).
fn layers<'py>(
    py: Python<'py>,
    kind: LatticeKind,
    tiling: &Tiling,
    cells: &[Cell],
) -> PyResult<Bound<'py, PyList>> {
    let layered = kind.lattice().dim() == 3;
    let mut by_layer: BTreeMap<i32, Vec<Cell>> = BTreeMap::new();
    for &c in cells {
        by_layer
            .entry(if layered { c[2] } else { 0 })
            .or_default()
            .push(c);
    }
    let out = PyList::empty(py);
    for (z, cells) in by_layer {
        let layer = PyDict::new(py);
        layer.set_item("layer", z)?;
        let polygons = PyList::empty(py);
        for &c in &cells {
            polygons.append(points(py, &tiling.polygon(c))?)?;
        }
        layer.set_item("cells", polygons)?;
        let loops = PyList::empty(py);
        for l in Outline::of_cells(kind, &cells).loops() {
            loops.append(points(py, &l.points_f64())?)?;
        }
        layer.set_item("outline", loops)?;
        let deepest = tiling.polygon(deepest_cell(kind, &cells));
        let n = deepest.len() as f64;
        let at = deepest
            .iter()
            .fold([0.0, 0.0], |m, p| [m[0] + p[0] / n, m[1] + p[1] / n]);
        layer.set_item("label_at", PyTuple::new(py, at)?)?;
        out.append(layer)?;
    }
    Ok(out)
}
