//! The puzzle options of `solve` (`dissect solve`'s `--solutions`,
//! `--rank`, `--keep N:REGIONS.txt`, `--min-piece`, `--max-piece`,
//! `--checkerboard`, `--symmetry-weight`, `--assemblable`, `--min-level`)
//! read from Python values into the
//! engine's [`RunConfig`]; every rule on them is the engine's
//! ([`dissect_engine::RunOptions::new`], [`dissect_engine::check`],
//! [`KeepRegions`]), none is repeated here.

use std::collections::BTreeMap;

use dissect_core::{Cell, Figure};
use dissect_engine::{ConstraintError, KeepRegions, Rank, RunConfig};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyString};

use crate::errors::{error, Kind};
use crate::figure::cell_from_coords;

/// The puzzle options' names, as `solve` takes them.
pub(crate) const NAMES: [&str; 8] = [
    "solutions",
    "rank",
    "min_piece",
    "max_piece",
    "checkerboard",
    "symmetry_weight",
    "assemblable",
    "min_level",
];

/// Sets the puzzle option `key` of `config` from `value`; `Ok(false)` when
/// `key` is not one (nor `keep` given as regions). `figures` are the
/// problem's, for keep regions (none: regions are refused).
pub(crate) fn apply(
    py: Python<'_>,
    config: &mut RunConfig,
    key: &str,
    value: &Bound<'_, PyAny>,
    figures: &[Figure],
) -> PyResult<bool> {
    let bad = |m: String| error(py, Kind::Option, m);
    let whole = |v: &Bound<'_, PyAny>| -> PyResult<usize> {
        if v.is_instance_of::<PyBool>() {
            return Err(bad(format!("{key} must be a whole number, got {v}")));
        }
        v.extract::<usize>()
            .map_err(|_| bad(format!("{key} must be a whole number, got {v}")))
    };
    let optional = |v: &Bound<'_, PyAny>| -> PyResult<Option<usize>> {
        if v.is_none() {
            Ok(None)
        } else {
            whole(v).map(Some)
        }
    };
    match key {
        "solutions" => config.solutions = whole(value)?,
        "rank" => {
            let name: String = value
                .extract()
                .map_err(|_| bad(format!("rank must be a string, got {value}")))?;
            config.rank = name
                .parse::<Rank>()
                .map_err(|e| bad(format!("rank: {e}")))?;
        }
        "min_piece" | "max_piece" => {
            let (min, max) = (
                config.constraints.min_piece(),
                config.constraints.max_piece(),
            );
            let v = optional(value)?;
            let (min, max) = if key == "min_piece" {
                (v, max)
            } else {
                (min, v)
            };
            config.constraints = config.constraints.clone().with_sizes(min, max);
        }
        "checkerboard" => {
            if !value.is_instance_of::<PyBool>() {
                return Err(bad(format!(
                    "checkerboard must be True or False, got {value}"
                )));
            }
            config.constraints = config
                .constraints
                .clone()
                .with_checkerboard(value.extract()?);
        }
        "assemblable" => {
            if !value.is_instance_of::<PyBool>() {
                return Err(bad(format!(
                    "assemblable must be True or False, got {value}"
                )));
            }
            let level = config.constraints.min_level();
            config.constraints = config
                .constraints
                .clone()
                .with_assembly(value.extract()?, level);
        }
        "min_level" => {
            let level = optional(value)?;
            let assemblable = config.constraints.assemblable();
            config.constraints = config.constraints.clone().with_assembly(assemblable, level);
        }
        "symmetry_weight" => {
            let w = if value.is_none() {
                0.0
            } else {
                value
                    .extract::<f64>()
                    .map_err(|_| bad(format!("symmetry_weight must be a number, got {value}")))?
            };
            config.constraints = config.constraints.clone().with_symmetry_weight(w);
        }
        "keep" if value.is_instance_of::<PyDict>() => {
            let dict = value.cast::<PyDict>()?;
            for (figure, regions) in dict.iter() {
                let keep = keep_regions(py, &figure, &regions, figures)?;
                config.constraints = config.constraints.clone().with_keep(keep);
            }
        }
        _ => return Ok(false),
    }
    Ok(true)
}

/// One entry of `keep={figure: regions}`: `figure` is an index into the
/// figures (0-based); `regions` is a regions grid (the text of
/// `--keep N:REGIONS.txt`), a list of cell groups (lettered a, b, ...), or
/// a dict of letter to cells.
fn keep_regions(
    py: Python<'_>,
    figure: &Bound<'_, PyAny>,
    regions: &Bound<'_, PyAny>,
    figures: &[Figure],
) -> PyResult<KeepRegions> {
    let bad = |m: String| error(py, Kind::Option, m);
    let index = figure
        .extract::<usize>()
        .ok()
        .filter(|_| !figure.is_instance_of::<PyBool>())
        .ok_or_else(|| {
            bad(format!(
                "keep's keys are figure indices (0 for the first figure), got {figure}"
            ))
        })?;
    let what = format!("keep[{index}]");
    let engine = |e: ConstraintError| {
        bad(format!(
            "{what}: {}",
            crate::solve::python_words(&e.to_string())
        ))
    };
    if regions.is_instance_of::<PyString>() {
        let text: String = regions.extract()?;
        return KeepRegions::parse(&text, index, figures).map_err(engine);
    }
    let lattice = figures.get(index).map(Figure::lattice);
    let cells = |v: &Bound<'_, PyAny>| -> PyResult<Vec<Cell>> {
        let coords: Vec<Vec<i64>> = v.extract().map_err(|_| {
            bad(format!(
                "{what}: a region is a list of cells (tuples of coordinates), got {v}"
            ))
        })?;
        match lattice {
            Some(l) => coords.iter().map(|c| cell_from_coords(py, l, c)).collect(),
            // The engine names the missing figure.
            None => Ok(Vec::new()),
        }
    };
    let mut groups: BTreeMap<char, Vec<Cell>> = BTreeMap::new();
    if let Ok(dict) = regions.cast::<PyDict>() {
        for (letter, group) in dict.iter() {
            let name: String = letter.extract().map_err(|_| {
                bad(format!(
                    "{what}: a region is named by a letter a-z, got {letter}"
                ))
            })?;
            let mut chars = name.chars();
            let (Some(c), None) = (chars.next(), chars.next()) else {
                return Err(engine(ConstraintError::Letter(name)));
            };
            groups.insert(c, cells(&group)?);
        }
    } else {
        let kind = regions.get_type().name()?;
        let list: Vec<Bound<'_, PyAny>> = regions.extract().map_err(|_| {
            bad(format!(
                "{what} must be a regions grid (str), a list of cell groups or a dict of letter to cells, got {kind}"
            ))
        })?;
        for (k, group) in list.iter().enumerate() {
            // Letters a, b, ... in order; past z the engine names the problem.
            let letter = char::from_u32('a' as u32 + k as u32).unwrap_or('?');
            groups.insert(letter, cells(group)?);
        }
    }
    KeepRegions::from_cells(index, groups, figures).map_err(engine)
}
