//! `dissect.Figure`: a set of cells on one lattice, with an optional name.

use dissect_core::io::{format_figure, parse_figure};
use dissect_core::{Cell, Figure, LatticeKind};
use pyo3::prelude::*;
use pyo3::types::{PyList, PyTuple};

use crate::errors::{error, Kind};

/// A figure: a non-empty set of cells on one lattice (`square`, `tri4`,
/// `cubic`, ...). Build one with `Figure.from_text`, `Figure.from_cells` or
/// `Figure.from_array`.
#[pyclass(module = "dissect._dissect", name = "Figure", frozen)]
pub(crate) struct PyFigure {
    pub(crate) figure: Figure,
    pub(crate) name: Option<String>,
}

/// A lattice from its name, or an error naming the known ones.
pub(crate) fn lattice(py: Python<'_>, name: &str) -> PyResult<LatticeKind> {
    name.parse::<LatticeKind>()
        .map_err(|e| error(py, Kind::Figure, e.to_string()))
}

/// Cells as written in solution files: `[x, y]` or `[x, y, t|z]`, the
/// form `dissect_core::io` gives each lattice.
pub(crate) fn cells_as_json(lattice: LatticeKind, cells: &[Cell]) -> Vec<Vec<i64>> {
    cells.iter().map(|c| lattice.cell_coords(*c)).collect()
}

/// Cells as a Python list of tuples.
pub(crate) fn cells_to_py<'py>(
    py: Python<'py>,
    lattice: LatticeKind,
    cells: &[Cell],
) -> PyResult<Bound<'py, PyList>> {
    let tuples = cells_as_json(lattice, cells)
        .into_iter()
        .map(|c| PyTuple::new(py, c))
        .collect::<PyResult<Vec<_>>>()?;
    PyList::new(py, tuples)
}

/// A cell as solution files write it (a 2D cell may also be `[x, y, 0]`):
/// the core's one rule, [`LatticeKind::cell_from_coords_padded`].
pub(crate) fn cell_from_coords(
    py: Python<'_>,
    lattice: LatticeKind,
    coords: &[i64],
) -> PyResult<Cell> {
    lattice.cell_from_coords_padded(coords).ok_or_else(|| {
        error(
            py,
            Kind::Figure,
            format!(
                "{coords:?} is not a cell of the {lattice} lattice (a {lattice} cell is {})",
                lattice.cell_form()
            ),
        )
    })
}

#[pymethods]
impl PyFigure {
    /// A figure from its text (FORMAT.md): `#`/`.` rows, hex digits on
    /// `tri4`, blank-line separated layers on `cubic`.
    #[staticmethod]
    #[pyo3(signature = (text, lattice = "square", name = None))]
    fn from_text(
        py: Python<'_>,
        text: &str,
        lattice: &str,
        name: Option<String>,
    ) -> PyResult<PyFigure> {
        let kind = self::lattice(py, lattice)?;
        let figure = parse_figure(text, kind).map_err(|e| {
            let what = name.as_deref().unwrap_or("figure text");
            error(py, Kind::Figure, format!("{what}: {e}"))
        })?;
        Ok(PyFigure { figure, name })
    }

    /// A figure from its cells: tuples `(x, y)` on 2D lattices with one
    /// coordinate pair per cell, `(x, y, t)` on `tri4`, `(x, y, z)` on `cubic`.
    #[staticmethod]
    #[pyo3(signature = (cells, lattice = "square", name = None))]
    fn from_cells(
        py: Python<'_>,
        cells: Vec<Vec<i64>>,
        lattice: &str,
        name: Option<String>,
    ) -> PyResult<PyFigure> {
        let kind = self::lattice(py, lattice)?;
        let cells = cells
            .iter()
            .map(|c| cell_from_coords(py, kind, c))
            .collect::<PyResult<Vec<_>>>()?;
        let figure = Figure::new(kind, cells).map_err(|e| {
            let what = name.as_deref().unwrap_or("figure");
            error(py, Kind::Figure, format!("{what}: {e}"))
        })?;
        Ok(PyFigure { figure, name })
    }

    /// A figure from a boolean numpy array (or anything `numpy.asarray`
    /// takes; 0/1 integers too). A 2D array is a `square` figure (or another
    /// 2D lattice's) indexed `[y, x]`, a row per text line; a 3D array is a
    /// `cubic` figure indexed `[z, y, x]`, or with `lattice="tri4"` a
    /// `tri4` figure indexed `[y, x, t]` (shape `(rows, columns, 4)`).
    #[staticmethod]
    #[pyo3(signature = (array, lattice = None, name = None))]
    fn from_array(
        py: Python<'_>,
        array: &Bound<'_, PyAny>,
        lattice: Option<&str>,
        name: Option<String>,
    ) -> PyResult<PyFigure> {
        let np = py.import("numpy")?;
        let what = name.clone().unwrap_or_else(|| "array".to_string());
        let bad = |m: String| error(py, Kind::Figure, format!("{what}: {m}"));
        let a = np.call_method1("asarray", (array,))?;
        let ndim: usize = a.getattr("ndim")?.extract()?;
        let kind = match (lattice, ndim) {
            (Some(l), _) => self::lattice(py, l)?,
            (None, 2) => LatticeKind::Square,
            (None, 3) => LatticeKind::Cubic,
            (None, n) => {
                return Err(bad(format!(
                    "expected a 2D or 3D array, got {n} dimensions"
                )))
            }
        };
        let want = match kind {
            LatticeKind::Cubic | LatticeKind::Tri4 => 3,
            _ => 2,
        };
        if ndim != want {
            return Err(bad(format!(
                "a {kind} figure needs a {want}D array, got {ndim} dimensions"
            )));
        }
        let shape: Vec<usize> = a.getattr("shape")?.extract()?;
        if kind == LatticeKind::Tri4 && shape[2] != 4 {
            return Err(bad(format!(
                "a tri4 array has shape (rows, columns, 4), got {shape:?}"
            )));
        }
        let dtype = a.getattr("dtype")?.getattr("kind")?.extract::<String>()?;
        if dtype != "b" {
            // 0/1 numbers are fine; anything else is a mistake.
            let ok: bool = np
                .call_method1("isin", (&a, (0, 1)))?
                .call_method0("all")?
                .extract()?;
            if !ok {
                return Err(bad(format!(
                    "expected booleans or 0/1 values, got dtype {}",
                    a.getattr("dtype")?.str()?
                )));
            }
        }
        let idx: Vec<Vec<i64>> = np
            .call_method1("argwhere", (&a,))?
            .call_method0("tolist")?
            .extract()?;
        let cells = idx
            .iter()
            .map(|i| match kind {
                LatticeKind::Cubic => [i[2] as i32, i[1] as i32, i[0] as i32],
                LatticeKind::Tri4 => [i[1] as i32, i[0] as i32, i[2] as i32],
                _ => [i[1] as i32, i[0] as i32, 0],
            })
            .collect::<Vec<Cell>>();
        if cells.is_empty() {
            return Err(bad("the array has no filled cell (empty figure)".into()));
        }
        let figure = Figure::new(kind, cells).map_err(|e| bad(e.to_string()))?;
        Ok(PyFigure { figure, name })
    }

    /// The lattice's name.
    #[getter]
    fn lattice(&self) -> &'static str {
        self.figure.lattice().name()
    }

    /// The name given at construction (used in solution files), or None.
    #[getter]
    fn name(&self) -> Option<String> {
        self.name.clone()
    }

    /// The cells, sorted, as tuples (see `from_cells`).
    #[getter]
    fn cells<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyList>> {
        cells_to_py(py, self.figure.lattice(), self.figure.cells())
    }

    /// The number of cells.
    #[getter]
    fn area(&self) -> usize {
        self.figure.len()
    }

    /// The number of connected components.
    #[getter]
    fn components(&self) -> usize {
        self.figure.stats().components
    }

    /// The figure with another name.
    fn with_name(&self, name: Option<String>) -> PyFigure {
        PyFigure {
            figure: self.figure.clone(),
            name,
        }
    }

    /// The figure as text (FORMAT.md).
    fn to_text(&self) -> String {
        format_figure(&self.figure)
    }

    fn __len__(&self) -> usize {
        self.figure.len()
    }

    fn __eq__(&self, other: &Bound<'_, PyAny>) -> bool {
        other
            .cast::<PyFigure>()
            .is_ok_and(|o| o.get().figure == self.figure)
    }

    fn __hash__(&self) -> u64 {
        use std::hash::{Hash, Hasher};
        let mut h = std::collections::hash_map::DefaultHasher::new();
        self.figure.lattice().hash(&mut h);
        self.figure.cells().hash(&mut h);
        h.finish()
    }

    fn __repr__(&self) -> String {
        format!(
            "Figure({}lattice={:?}, area={})",
            self.name
                .as_ref()
                .map_or(String::new(), |n| format!("name={n:?}, ")),
            self.figure.lattice().name(),
            self.figure.len()
        )
    }

    /// Pickling (Ray sends figures to its workers): rebuilt from its cells.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let this = slf.get();
        let rebuild = slf.get_type().getattr("from_cells")?;
        let args = (
            this.cells(py)?,
            this.figure.lattice().name(),
            this.name.clone(),
        );
        PyTuple::new(py, [rebuild, args.into_pyobject(py)?.into_any()])
    }
}
