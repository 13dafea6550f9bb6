//! Certificate folders: what `--certificate DIR` writes and `check-proof
//! DIR` reads.
//!
//! The exact search (`dissect-exact`) proves "no dissection into K pieces"
//! and hands each refutation over as a [`dissect_exact::Certificate`]: the
//! formula and the SAT solver's DRAT proof, or the cubes of a
//! cube-and-conquer run. [`Writer`] turns those into files
//! (`DIR/k{K}.cnf`, `DIR/k{K}.drat` or `DIR/k{K}.cubes` with one formula and
//! proof per cube, and `DIR/README.txt`); the cubes of an unfinished run
//! are kept in `DIR/k{K}.work/` so that the same question run again
//! resumes from them. [`check_folder`] replays every certificate of a
//! folder with the independent checker `dissect-proof`, a proof a line at a
//! time (a proof may be a named pipe that a solver is writing).
//!
//! This is front-end support, like `dissect-solver-process`: it reads and
//! writes files, so it is not in the engine; the CLI and the Python
//! extension share it, and only display what it returns. Every file is
//! written whole or not at all ([`write_atomic`]).

mod check;
mod kept_cubes;
mod writer;

pub use check::{check_folder, verdict, Checked, Outcome, Summary};
pub use writer::{Writer, Written};

use std::io::Write;
use std::path::Path;

/// What can go wrong with a certificate folder.
#[derive(Debug, thiserror::Error)]
pub enum CertificateError {
    /// Bad input: a path that is not a folder, a folder with no
    /// certificate, a formula without its proof, a file that is not text or
    /// not DIMACS/DRAT (the message names the file and, where it can, the
    /// line).
    #[error("{0}")]
    Input(String),
    /// A file that could not be read or written.
    #[error("{context}: {error}")]
    Io {
        /// What was being done, naming the file.
        context: String,
        /// The operating system's error.
        error: std::io::Error,
    },
    /// Errors met while the run wrote its certificates, reported at its end.
    #[error("{0}")]
    Writing(String),
    /// The check was stopped (its stop flag raised) before it was done.
    #[error("stopped before every certificate was checked")]
    Stopped,
}

impl CertificateError {
    fn io(context: impl Into<String>, error: std::io::Error) -> CertificateError {
        CertificateError::Io {
            context: context.into(),
            error,
        }
    }
}

/// The K of a certificate folder's file name `k{K}{suffix}` (`k4.cnf`,
/// `k4.work`), or `None` for any other name.
fn k_of(name: &str, suffix: &str) -> Option<usize> {
    name.strip_prefix('k')?.strip_suffix(suffix)?.parse().ok()
}

/// Writes `bytes` to `path` whole or not at all: the bytes go to a
/// temporary file in the same folder, flushed to disk, then renamed over
/// `path`. A kill or a full disk during the write leaves the old file (or
/// none), never a truncated one. The folder must exist; it is never made
/// here. A `path` that is a folder, or whose folder is missing, is
/// [`CertificateError::Input`].
pub fn write_atomic(path: &Path, bytes: impl AsRef<[u8]>) -> Result<(), CertificateError> {
    let bytes = bytes.as_ref();
    let dir = match path.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if path.is_dir() {
        return Err(CertificateError::Input(format!(
            "{}: cannot write: it is a folder",
            path.display()
        )));
    }
    if !dir.is_dir() {
        return Err(CertificateError::Input(format!(
            "{}: cannot write: folder {} does not exist",
            path.display(),
            dir.display()
        )));
    }
    let name = path
        .file_name()
        .map_or_else(|| "output".into(), |n| n.to_string_lossy().into_owned());
    let cannot = |e| CertificateError::io(format!("cannot write {}", path.display()), e);
    let mut tmp = tempfile::Builder::new()
        .prefix(&format!(".{name}."))
        .suffix(".tmp")
        .tempfile_in(dir)
        .map_err(cannot)?;
    tmp.write_all(bytes)
        .and_then(|()| tmp.as_file().sync_all())
        .map_err(cannot)?;
    tmp.persist(path).map_err(|e| cannot(e.error))?;
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::write_atomic;

    #[test]
    fn replaces_the_file_and_leaves_no_temporary_file() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("out.json");
        std::fs::write(&p, "old").unwrap();
        write_atomic(&p, b"new").unwrap();
        assert_eq!(std::fs::read_to_string(&p).unwrap(), "new");
        let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(names.len(), 1);
    }

    #[test]
    fn a_missing_folder_is_an_error_and_not_created() {
        let dir = tempfile::tempdir().unwrap();
        let p = dir.path().join("nope/out.json");
        let e = write_atomic(&p, b"x").unwrap_err().to_string();
        assert!(e.contains("does not exist"), "{e}");
        assert!(!dir.path().join("nope").exists());
        let e = write_atomic(dir.path(), b"x").unwrap_err().to_string();
        assert!(e.contains("it is a folder"), "{e}");
    }
}
