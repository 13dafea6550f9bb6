//! Writing output files so that they are never lost: whole or not at all
//! (`dissect_certificate::write_atomic`: a temporary file in the same
//! folder, flushed, then renamed over the target).

use std::path::Path;

use anyhow::Result;
use dissect_certificate::CertificateError;

use crate::InputError;

/// Writes `bytes` to `path` atomically. The folder must exist; it is never
/// created here (a missing folder is bad input, exit 2).
pub fn write_atomic(path: &Path, bytes: impl AsRef<[u8]>) -> Result<()> {
    dissect_certificate::write_atomic(path, bytes).map_err(cli_error)
}

/// A certificate folder's error as the CLI reports it: bad input (exit 2)
/// or an internal error.
pub fn cli_error(e: CertificateError) -> anyhow::Error {
    match e {
        CertificateError::Input(m) => InputError(m).into(),
        e => e.into(),
    }
}
