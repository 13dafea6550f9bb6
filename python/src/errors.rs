//! Python exceptions, defined in `dissect/_errors.py` so that they can
//! inherit from both `DissectError` and `ValueError`.

use pyo3::prelude::*;

/// The exception classes of `dissect._errors`.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Kind {
    /// A figure text or cell list that is not a figure.
    Figure,
    /// Figures that cannot be dissected together (areas, lattices, count).
    Problem,
    /// An unknown option or a bad option value.
    Option,
    /// A solution that is not a valid dissection of its figures.
    InvalidSolution,
    /// The search ended without a dissection.
    NotFound,
    /// A certificate folder or file that is not what it should be.
    Certificate,
}

impl Kind {
    fn class_name(self) -> &'static str {
        match self {
            Kind::Figure => "FigureError",
            Kind::Problem => "ProblemError",
            Kind::Option => "OptionError",
            Kind::InvalidSolution => "InvalidSolution",
            Kind::NotFound => "NoDissectionFound",
            Kind::Certificate => "CertificateError",
        }
    }
}

/// An exception of `kind` with `message`.
pub(crate) fn error(py: Python<'_>, kind: Kind, message: impl Into<String>) -> PyErr {
    let message = message.into();
    match py
        .import("dissect._errors")
        .and_then(|m| m.getattr(kind.class_name()))
    {
        Ok(class) => PyErr::from_type(class.cast_into().expect("an exception class"), message),
        Err(e) => e,
    }
}
