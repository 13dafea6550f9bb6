//! Certificates from Python: `check_proof` (what `dissect check-proof`
//! does) and the built-in solver's certificate writer for `bound`, both
//! from `dissect-certificate`.

use std::sync::atomic::AtomicBool;
use std::sync::Mutex;

use dissect_certificate::{CertificateError, Checked, Outcome, Writer};
use dissect_engine::{EngineEvent, EngineObserver};
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList};

use crate::errors::{error, Kind};
use crate::run::watched_polling;

/// A certificate folder's error as a Python exception: bad input is a
/// `CertificateError`, a file that cannot be read or written an `OSError`.
pub(crate) fn certificate_error(py: Python<'_>, e: CertificateError) -> PyErr {
    match e {
        CertificateError::Input(m) => error(py, Kind::Certificate, m),
        e => pyo3::exceptions::PyOSError::new_err(e.to_string()),
    }
}

/// Hands the exact search's refutations to the certificate writer.
pub(crate) struct Certifying<'a>(pub(crate) &'a Writer);

impl EngineObserver for Certifying<'_> {
    fn on_event(&self, event: &EngineEvent<'_>) {
        if let EngineEvent::Exact(e) = event {
            self.0.on_event(e);
        }
    }
}

/// One certificate's check as a dict.
fn checked_to_py<'py>(py: Python<'py>, c: &Checked) -> PyResult<Bound<'py, PyDict>> {
    let d = PyDict::new(py);
    d.set_item("k", c.k)?;
    d.set_item("verified", c.verified())?;
    d.set_item("line", c.to_string())?;
    match &c.outcome {
        Outcome::Verified(s) => {
            d.set_item("clauses", s.clauses)?;
            d.set_item("cubes", s.cubes)?;
            d.set_item("lemmas", s.lemmas)?;
            d.set_item("rat_lemmas", s.rat_lemmas)?;
            d.set_item("deletions", s.deletions)?;
        }
        Outcome::Failed(m) => d.set_item("failure", m)?,
    }
    Ok(d)
}

/// Replays every certificate of `dir` (see `dissect.check_proof`);
/// `progress(line)` is called on this thread as each one ends. Ctrl-C
/// stops the check and is raised.
#[pyfunction]
#[pyo3(signature = (dir, progress = None))]
pub(crate) fn check_proof<'py>(
    py: Python<'py>,
    dir: std::path::PathBuf,
    progress: Option<Bound<'py, PyAny>>,
) -> PyResult<Bound<'py, PyDict>> {
    let stop = AtomicBool::new(false);
    let lines = Mutex::new(Vec::<String>::new());
    let mut deliver = |_: Python<'_>| -> PyResult<()> {
        let queued = std::mem::take(&mut *lines.lock().unwrap_or_else(|e| e.into_inner()));
        if let Some(f) = &progress {
            for line in queued {
                f.call1((line,))?;
            }
        }
        Ok(())
    };
    let run = watched_polling(py, &stop, None, &mut deliver, || {
        dissect_certificate::check_folder(&dir, &stop, &mut |c| {
            lines
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .push(c.to_string())
        })
    })?;
    if let Some(e) = run.interrupted {
        return Err(e);
    }
    let checked = run.value.map_err(|e| certificate_error(py, e))?;
    let out = PyDict::new(py);
    let list = PyList::empty(py);
    for c in &checked {
        list.append(checked_to_py(py, c)?)?;
    }
    out.set_item("certificates", list)?;
    out.set_item("verified", checked.iter().all(Checked::verified))?;
    out.set_item("verdict", dissect_certificate::verdict(&checked))?;
    Ok(out)
}
