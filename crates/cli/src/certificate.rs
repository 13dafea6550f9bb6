//! `dissect check-proof DIR`: the certificates of `--certificate DIR`
//! (written by `dissect_certificate::Writer`) replayed by the independent
//! checker, through `dissect_certificate::check_folder`.

use std::path::{Path, PathBuf};

use anyhow::Result;

use crate::output::cli_error;
use crate::Status;

/// The writer of `--certificate DIR` for a run on `figures`.
pub fn writer(
    dir: &Path,
    figures: &[PathBuf],
    lattice: dissect_core::LatticeKind,
    no_mirror: bool,
) -> Result<dissect_certificate::Writer> {
    let names: Vec<String> = figures.iter().map(|p| p.display().to_string()).collect();
    let mirror = !no_mirror && lattice.lattice().supports_mirror();
    dissect_certificate::Writer::new(dir, &names, &lattice.to_string(), mirror).map_err(cli_error)
}

/// `dissect check-proof DIR`.
#[derive(clap::Args, Debug)]
pub struct CheckProofArgs {
    /// A folder written by `--certificate`: every kK.cnf there is checked
    /// against its kK.drat (a file, or a named pipe a solver writes into).
    #[arg(value_name = "DIR")]
    pub dir: PathBuf,
}

/// Checks every certificate of the folder, a line as each ends; the last
/// line is `verified: ...` or `failed: ...` (exit 1); a malformed file is
/// bad input (exit 2).
pub fn check(args: CheckProofArgs) -> Result<Status> {
    // Ctrl-C ends the process (no handler is installed for check-proof).
    let never = std::sync::atomic::AtomicBool::new(false);
    let checked = dissect_certificate::check_folder(&args.dir, &never, &mut |c| println!("{c}"))
        .map_err(cli_error)?;
    println!("{}", dissect_certificate::verdict(&checked));
    Ok(if checked.iter().all(|c| c.verified()) {
        Status::Ok
    } else {
        Status::NotFound
    })
}
