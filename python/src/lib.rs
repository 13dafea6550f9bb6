//! `dissect._dissect`: the Rust half of the Python package `dissect`.
//!
//! Figures, the solver, lower bounds and the verifier of `dissect-core` and
//! `dissect-exact`, with the GIL released while they run and Ctrl-C turned
//! into the solver's stop flag. The Python half (`dissect/__init__.py`)
//! wraps the results in friendly classes (`Dissection`, plotting, Ray).
//!
//! Errors are raised as the exception classes of `dissect._errors` (Python),
//! each message naming the problem.

use pyo3::prelude::*;

mod assemblies;
mod disassemble;
mod enumerate;
mod errors;
mod figure;
mod picture;
mod proof;
mod puzzle;
mod run;
mod solve;

#[pymodule]
fn _dissect(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<figure::PyFigure>()?;
    m.add_class::<solve::PyExplorer>()?;
    m.add_function(wrap_pyfunction!(solve::solve, m)?)?;
    m.add_function(wrap_pyfunction!(solve::bound, m)?)?;
    m.add_function(wrap_pyfunction!(solve::verify, m)?)?;
    m.add_function(wrap_pyfunction!(proof::check_proof, m)?)?;
    m.add_function(wrap_pyfunction!(solve::solution_json, m)?)?;
    m.add_function(wrap_pyfunction!(solve::option_names, m)?)?;
    m.add_function(wrap_pyfunction!(assemblies::assemblies, m)?)?;
    m.add_function(wrap_pyfunction!(disassemble::disassemble, m)?)?;
    m.add_function(wrap_pyfunction!(picture::piece_colour, m)?)?;
    m.add_function(wrap_pyfunction!(picture::render_svg, m)?)?;
    m.add_function(wrap_pyfunction!(picture::render_html, m)?)?;
    m.add_function(wrap_pyfunction!(picture::drawing, m)?)?;
    m.add("PALETTE", picture::palette())?;
    m.add(
        "RANKS",
        dissect_engine::Rank::ALL.map(|r| r.name()).to_vec(),
    )?;
    m.add_function(wrap_pyfunction!(enumerate::enumerate, m)?)?;
    m.add("LATTICES", lattice_names())?;
    Ok(())
}

/// The lattice names the core knows.
fn lattice_names() -> Vec<&'static str> {
    dissect_core::LatticeKind::ALL
        .iter()
        .map(|k| k.name())
        .collect()
}
