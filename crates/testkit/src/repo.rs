//! What the tests find in the repository itself, and the checkers they run
//! on the solutions they produce.
//!
//! Everything a test needs is inside the repository: the benchmark figures
//! (`instances/`) and our own solution checker (`tools/check_solution.py`,
//! written from `docs/FORMAT.md`). The one thing that may live outside is
//! the external oracle `verify.py` of the project's shared folder: tests run
//! it when it is there and otherwise say once, on stderr, what they skipped.

use std::ffi::OsStr;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::Once;

/// The repository's root folder: two folders above the package being
/// tested (`crates/<name>`). Cargo names that package's folder when it
/// runs a test; the folder this crate was compiled in is the fallback
/// (a test binary run by hand). The compiled-in path alone could name
/// another checkout: one target folder serving two checkouts of the same
/// sources (CI's fresh-clone step) keeps this crate compiled for the first.
pub fn root() -> PathBuf {
    let package = std::env::var_os("CARGO_MANIFEST_DIR")
        .map_or_else(|| PathBuf::from(env!("CARGO_MANIFEST_DIR")), PathBuf::from);
    package
        .ancestors()
        .nth(2)
        .map_or_else(|| package.join("../.."), Path::to_path_buf)
}

/// The benchmark instances: `instances/` (with its `manifest.json`).
pub fn instances() -> PathBuf {
    root().join("instances")
}

/// A figure file of instance `name` under `instances/`; panics when it is
/// missing (the repository carries every instance the tests use).
#[track_caller]
pub fn instance_file(name: &str, file: &str) -> PathBuf {
    let p = instances().join(name).join(file);
    assert!(p.is_file(), "missing instance file {}", p.display());
    p
}

/// The external oracle `verify.py`: `$DISSECT_VERIFY` when set, else
/// `tools/verify.py` of the `shared` folder beside the repository. `None`
/// when it is not there (a fresh clone): then the first call of the test
/// process writes one line to stderr saying that the external check is
/// skipped (written past the test harness's capture, so `cargo test`
/// shows it).
pub fn verify_py() -> Option<PathBuf> {
    let path = match std::env::var_os("DISSECT_VERIFY") {
        Some(p) => PathBuf::from(p),
        None => root()
            .parent()
            .map_or_else(|| root().join(".."), Path::to_path_buf)
            .join("shared/tools/verify.py"),
    };
    if path.is_file() {
        return Some(path);
    }
    static SKIPPED: Once = Once::new();
    SKIPPED.call_once(|| {
        let line = format!(
            "note: {} not found: the external oracle's checks are skipped \
             (tools/check_solution.py and `dissect verify` still check every solution)\n",
            path.display()
        );
        // Past the harness's capture of `eprintln!`, so that it shows.
        let _ = std::io::stderr().write_all(line.as_bytes());
    });
    None
}

/// What a checker said about a solution file.
#[derive(Debug, Clone)]
pub struct Verdict {
    /// Whether it exited 0.
    pub ok: bool,
    /// Its standard output (`valid: N pieces` as its last line when valid).
    pub stdout: String,
    /// Its standard error.
    pub stderr: String,
}

impl Verdict {
    /// The piece count of `valid: N piece(s)`, when valid.
    pub fn pieces(&self) -> Option<usize> {
        if !self.ok {
            return None;
        }
        let last = self.stdout.lines().last()?.trim();
        let rest = last.strip_prefix("valid: ")?;
        rest.split(' ').next()?.parse().ok()
    }
}

fn run_checker(
    script: &Path,
    dir: &Path,
    lattice: &str,
    solution: &OsStr,
    figures: &[&OsStr],
) -> Verdict {
    let out = Command::new("python3")
        .arg(script)
        .args([OsStr::new("--lattice"), OsStr::new(lattice)])
        .args([OsStr::new("--solution"), solution])
        .args(figures)
        .current_dir(dir)
        .output()
        .unwrap_or_else(|e| panic!("cannot run python3 {}: {e}", script.display()));
    Verdict {
        ok: out.status.success(),
        stdout: String::from_utf8_lossy(&out.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&out.stderr).into_owned(),
    }
}

/// Runs the repository's own checker `tools/check_solution.py` on a
/// solution file (paths relative to `dir`, where it runs).
pub fn check_solution<S: AsRef<OsStr>, F: AsRef<OsStr>>(
    dir: &Path,
    lattice: &str,
    solution: S,
    figures: &[F],
) -> Verdict {
    let figures: Vec<&OsStr> = figures.iter().map(AsRef::as_ref).collect();
    run_checker(
        &root().join("tools/check_solution.py"),
        dir,
        lattice,
        solution.as_ref(),
        &figures,
    )
}

/// Runs the external oracle `verify.py` on a solution file when it is
/// present ([`verify_py`]); `None` when it is not.
pub fn run_verify_py<S: AsRef<OsStr>, F: AsRef<OsStr>>(
    dir: &Path,
    lattice: &str,
    solution: S,
    figures: &[F],
) -> Option<Verdict> {
    let script = verify_py()?;
    let figures: Vec<&OsStr> = figures.iter().map(AsRef::as_ref).collect();
    Some(run_checker(
        &script,
        dir,
        lattice,
        solution.as_ref(),
        &figures,
    ))
}

/// Asserts that the independent checkers accept a solution file: always
/// `tools/check_solution.py`, and the external `verify.py` when present.
/// Returns the piece count they agree on.
#[track_caller]
pub fn assert_checked<S: AsRef<OsStr>, F: AsRef<OsStr>>(
    dir: &Path,
    lattice: &str,
    solution: S,
    figures: &[F],
) -> usize {
    let name = Path::new(solution.as_ref()).display().to_string();
    let own = check_solution(dir, lattice, &solution, figures);
    let n = own.pieces().unwrap_or_else(|| {
        panic!(
            "tools/check_solution.py rejects {name}:\n{}{}",
            own.stdout, own.stderr
        )
    });
    if let Some(ext) = run_verify_py(dir, lattice, &solution, figures) {
        assert_eq!(
            ext.pieces(),
            Some(n),
            "verify.py on {name} (check_solution.py says {n} pieces):\n{}{}",
            ext.stdout,
            ext.stderr
        );
    }
    n
}
