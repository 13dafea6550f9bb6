//! Figures as the API sends and receives them: a name with either a list of
//! cells (`[x,y]` on `square`, `[x,y,t]` on `tri4`, `[x,y,z]` on `cubic`, as
//! in solution files) or the text of a figure file. Reading one checks the
//! server's [`Limits`].

use dissect_core::io::{format_figure, parse_figure};
use dissect_core::{Cell, Figure, LatticeKind};
use serde::{Deserialize, Serialize};
use serde_json::{json, Value};

use crate::error::ApiError;
use crate::limits::Limits;

/// A figure in a request.
#[derive(Clone, Debug, Deserialize, Serialize, PartialEq)]
#[serde(deny_unknown_fields)]
pub struct FigureInput {
    /// The name shown in errors and solutions (default `figure-N.txt`).
    #[serde(default)]
    pub name: Option<String>,
    /// The cells.
    #[serde(default)]
    pub cells: Option<Vec<Vec<i64>>>,
    /// Or the figure file's text.
    #[serde(default)]
    pub text: Option<String>,
}

/// Reads a lattice name.
pub fn lattice(name: &str) -> Result<LatticeKind, ApiError> {
    name.parse()
        .map_err(|e: dissect_core::lattice::UnknownLattice| ApiError::UnknownLattice(e.to_string()))
}

/// The name of figure `index` (0-based) of a request.
pub fn name_of(input: &FigureInput, index: usize) -> String {
    match &input.name {
        Some(n) if !n.trim().is_empty() => n.chars().take(200).collect(),
        _ => format!("figure-{}.txt", index + 1),
    }
}

/// One cell of the JSON form, checked against the lattice
/// ([`LatticeKind::cell_from_coords`]) and the limits. A 2D cell may also be
/// given with a third coordinate of 0.
pub(crate) fn cell(raw: &[i64], lattice: LatticeKind, limits: &Limits) -> Result<Cell, String> {
    let c = lattice.cell_from_coords_padded(raw).ok_or_else(|| {
        format!(
            "{raw:?} is not a cell of the {lattice} lattice (a {lattice} cell is {})",
            lattice.cell_form()
        )
    })?;
    let ext = limits.max_extent() as i64;
    if raw.iter().take(2).any(|v| v.abs() > ext)
        || (lattice == LatticeKind::Cubic && raw[2].abs() > ext)
    {
        return Err(format!(
            "cell {raw:?} is out of range (coordinates at most {ext} in size)"
        ));
    }
    Ok(c)
}

/// Reads figure `index` of a request, moved to start at block `[0, 0, 0]`
/// ([`normalized`]).
pub fn read(
    input: &FigureInput,
    index: usize,
    lattice: LatticeKind,
    limits: &Limits,
) -> Result<Figure, ApiError> {
    read_as_given(input, index, lattice, limits).map(|f| normalized(&f))
}

/// Reads figure `index` of a request in the request's own coordinates.
pub fn read_as_given(
    input: &FigureInput,
    index: usize,
    lattice: LatticeKind,
    limits: &Limits,
) -> Result<Figure, ApiError> {
    let name = name_of(input, index);
    let too_big = |n: usize| {
        ApiError::TooLarge(format!(
            "{name}: {n} cells; this server takes at most {} per figure",
            limits.max_cells()
        ))
    };
    let figure = match (&input.cells, &input.text) {
        (Some(cells), None) => {
            if cells.len() > 4 * limits.max_cells() {
                return Err(too_big(cells.len()));
            }
            let cells: Vec<Cell> = cells
                .iter()
                .map(|c| cell(c, lattice, limits))
                .collect::<Result<_, _>>()
                .map_err(|e| ApiError::BadFigure(format!("{name}: {e}")))?;
            Figure::new(lattice, cells).map_err(|e| ApiError::BadFigure(format!("{name}: {e}")))?
        }
        (None, Some(text)) => {
            let ext = limits.max_extent() as usize + 1;
            if text.len() > 4 * ext * ext * ext.min(64) {
                return Err(ApiError::TooLarge(format!(
                    "{name}: the figure text has {} bytes, too many for this server",
                    text.len()
                )));
            }
            let f = parse_figure(text, lattice)
                .map_err(|e| ApiError::BadFigure(format!("{name}: {e}")))?;
            let l = lattice.lattice();
            if let Some(c) = f
                .cells()
                .iter()
                .find(|c| l.block(**c).iter().any(|v| *v > limits.max_extent()))
            {
                return Err(ApiError::TooLarge(format!(
                    "{name}: cell {c:?} lies beyond {} rows/columns/layers",
                    limits.max_extent()
                )));
            }
            f
        }
        _ => {
            return Err(ApiError::BadValue(format!(
                "{name}: give either \"cells\" or \"text\""
            )))
        }
    };
    if figure.len() > limits.max_cells() {
        return Err(too_big(figure.len()));
    }
    Ok(figure)
}

/// The figure moved so that its bounding box starts at block `[0, 0, 0]`,
/// as the figure text format writes it: then solution cells and the
/// downloaded figure files agree.
pub fn normalized(figure: &Figure) -> Figure {
    figure.to_origin()
}

/// Reads the figures of a request and checks their number.
pub fn read_all(
    inputs: &[FigureInput],
    lattice: LatticeKind,
    limits: &Limits,
) -> Result<Vec<Figure>, ApiError> {
    Ok(read_all_as_given(inputs, lattice, limits)?
        .iter()
        .map(normalized)
        .collect())
}

/// [`read_all`] in the request's own coordinates.
pub fn read_all_as_given(
    inputs: &[FigureInput],
    lattice: LatticeKind,
    limits: &Limits,
) -> Result<Vec<Figure>, ApiError> {
    if inputs.len() > limits.max_figures() {
        return Err(ApiError::TooLarge(format!(
            "{} figures; this server takes at most {}",
            inputs.len(),
            limits.max_figures()
        )));
    }
    inputs
        .iter()
        .enumerate()
        .map(|(i, f)| read_as_given(f, i, lattice, limits))
        .collect()
}

/// Fails with every figure's count when areas differ.
pub fn check_equal_areas(inputs: &[FigureInput], figures: &[Figure]) -> Result<(), ApiError> {
    if figures.iter().all(|f| f.len() == figures[0].len()) {
        return Ok(());
    }
    Err(ApiError::UnequalAreas(
        inputs
            .iter()
            .zip(figures)
            .enumerate()
            .map(|(i, (inp, f))| (name_of(inp, i), f.len()))
            .collect(),
    ))
}

/// A cell in the JSON form of solution files.
pub fn cell_json(lattice: LatticeKind, c: &Cell) -> Value {
    json!(lattice.cell_coords(*c))
}

/// A figure as the API returns it: cells, text, count and shape facts.
pub fn describe(name: &str, figure: &Figure) -> Value {
    let lattice = figure.lattice();
    let stats = figure.stats();
    json!({
        "name": name,
        "lattice": lattice.name(),
        "cells": figure.cells().iter().map(|c| cell_json(lattice, c)).collect::<Vec<_>>(),
        "count": figure.len(),
        "components": stats.components,
        "holes": stats.holes,
        "min": stats.min,
        "max": stats.max,
        "text": format_figure(figure),
    })
}
