//! `bound --solver CMD`: another SAT solver run as a process, for the
//! engine's `bound_external` (which decides what to ask and what the
//! answers prove); the front ends (`dissect bound --solver`, Python's
//! `dissect.bound(solver=...)`) share it. For each K the formula goes to
//! `DIR/kK.cnf` and the solver runs as `CMD DIR/kK.cnf DIR/kK.drat` (the
//! DIMACS input and the proof output, as CaDiCaL, Kissat and most solvers
//! take them), its standard output read for the `s` line and the model's
//! `v` lines. A refuted K keeps its formula and proof in DIR (a
//! certificate `dissect check-proof DIR` checks) when DIR is the caller's;
//! anything else is removed. Stopped (time limit, Ctrl-C), the solver is
//! killed and its files removed.

use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use dissect_engine::{ExternalAnswer, ExternalSolver};
use dissect_exact::Dimacs;

/// How often a running solver is looked at.
const POLL: Duration = Duration::from_millis(20);

/// The README.txt of a folder of another solver's certificates.
fn readme(program: &str, refuted: &[usize]) -> String {
    let mut s = format!(
        "Certificates written by `dissect bound --solver`: another SAT solver ({program})\n\
         refuted the formula of \"at most K connected pieces\" for each K below.\n\n"
    );
    for k in refuted {
        s.push_str(&format!(
            "k{k}.cnf   the formula (`dissect bound --max-pieces {k} --dimacs F --connected` writes it too)\n\
             k{k}.drat  {program}'s DRAT proof that it is unsatisfiable: no dissection into {k} pieces\n"
        ));
    }
    s.push_str(
        "\nCheck them: `dissect check-proof DIR` (an independent checker, crate dissect-proof;\n\
         it reads text DRAT, so give the solver its text-proof option, e.g. cadical --no-binary),\n\
         or any DRAT checker (drat-trim kK.cnf kK.drat).\n",
    );
    s
}

/// Told when a formula goes to the solver: K, the formula's file and the
/// formula.
pub type OnSolve = Box<dyn Fn(usize, &Path, &Dimacs) + Sync>;

/// A solver command and the folder its files go to.
pub struct SolverProcess {
    program: String,
    args: Vec<String>,
    dir: PathBuf,
    /// Whether the proofs are kept (the caller's folder) or the folder is
    /// a temporary one (`temp`, removed with the value).
    keep: bool,
    temp: Option<tempfile::TempDir>,
    on_solve: Option<OnSolve>,
    /// The K it refuted, in order.
    refuted: std::sync::Mutex<Vec<usize>>,
}

impl SolverProcess {
    /// `command` split at white space (the program, then its arguments);
    /// files in `dir` (made if missing), kept as certificates, or in a
    /// temporary folder when `None`. An error for an empty command or a
    /// folder that cannot be made.
    pub fn new(command: &str, dir: Option<&Path>) -> Result<SolverProcess, String> {
        let mut words = command.split_whitespace().map(String::from);
        let program = words.next().ok_or("an empty solver command")?;
        let (dir, temp) = match dir {
            Some(d) => {
                std::fs::create_dir_all(d)
                    .map_err(|e| format!("{}: cannot create: {e}", d.display()))?;
                (d.to_path_buf(), None)
            }
            None => {
                let t = tempfile::tempdir().map_err(|e| format!("a temporary folder: {e}"))?;
                (t.path().to_path_buf(), Some(t))
            }
        };
        Ok(SolverProcess {
            program,
            args: words.collect(),
            dir,
            keep: temp.is_none(),
            temp,
            on_solve: None,
            refuted: std::sync::Mutex::new(Vec::new()),
        })
    }

    /// The same, telling `on_solve` of each formula before the solver runs.
    pub fn with_progress(mut self, on_solve: OnSolve) -> SolverProcess {
        self.on_solve = Some(on_solve);
        self
    }

    /// The folder of its files (a temporary one unless given).
    pub fn dir(&self) -> &Path {
        self.temp.as_ref().map_or(&self.dir, |t| t.path())
    }

    /// The K this solver refuted (their certificates are kept when the
    /// folder is).
    pub fn refuted(&self) -> Vec<usize> {
        self.refuted
            .lock()
            .unwrap_or_else(|e| e.into_inner())
            .clone()
    }

    /// Once the bound is over: writes `README.txt` (what each file claims) into a kept
    /// folder where some K was refuted; the refuted K.
    pub fn finish(&self) -> Result<Vec<usize>, String> {
        let refuted = self.refuted();
        if self.keep && !refuted.is_empty() {
            let text = readme(&self.program, &refuted);
            write_atomic(&self.dir.join("README.txt"), text.as_bytes())?;
        }
        Ok(refuted)
    }

    fn paths(&self, k: usize) -> [PathBuf; 3] {
        ["cnf", "drat", "out"].map(|ext| self.dir.join(format!("k{k}.{ext}")))
    }

    /// Removes K's files (all of them, or the solver's output only).
    fn remove(&self, k: usize, all: bool) {
        let [cnf, drat, out] = self.paths(k);
        let _ = std::fs::remove_file(out);
        if all || !self.keep {
            let _ = std::fs::remove_file(cnf);
            let _ = std::fs::remove_file(drat);
        }
    }
}

impl ExternalSolver for SolverProcess {
    fn name(&self) -> String {
        self.program.clone()
    }

    fn solve(&self, k: usize, cnf: &Dimacs, stop: &AtomicBool) -> Result<ExternalAnswer, String> {
        let [cnf_path, drat, out_path] = self.paths(k);
        write_atomic(&cnf_path, cnf.text.as_bytes())?;
        if let Some(tell) = &self.on_solve {
            tell(k, &cnf_path, cnf);
        }
        let out = std::fs::File::create(&out_path)
            .map_err(|e| format!("{}: cannot write: {e}", out_path.display()))?;
        let mut command = Command::new(&self.program);
        command.args(&self.args).arg(&cnf_path);
        if self.keep {
            command.arg(&drat);
        }
        let mut child = command
            .stdin(Stdio::null())
            .stdout(out)
            .stderr(Stdio::null())
            .spawn()
            .map_err(|e| {
                self.remove(k, true);
                format!("cannot run `{}`: {e}", self.program)
            })?;
        loop {
            if stop.load(Ordering::SeqCst) {
                let _ = child.kill();
                let _ = child.wait();
                self.remove(k, true);
                return Ok(ExternalAnswer::Unknown);
            }
            match child.try_wait() {
                Ok(Some(_)) => break,
                Ok(None) => std::thread::sleep(POLL),
                Err(e) => return Err(e.to_string()),
            }
        }
        let text = std::fs::read_to_string(&out_path)
            .map_err(|e| format!("{}: cannot read: {e}", out_path.display()));
        let answer = text.and_then(|t| parse_answer(&t, &out_path));
        let refuted = matches!(answer, Ok(ExternalAnswer::Unsat));
        if refuted && self.keep && !drat.exists() {
            self.remove(k, true);
            return Err(format!(
                "answered UNSATISFIABLE but wrote no proof to {}",
                drat.display()
            ));
        }
        self.remove(k, !refuted);
        if refuted {
            self.refuted
                .lock()
                .unwrap_or_else(|e| e.into_inner())
                .push(k);
        }
        answer
    }
}

/// Writes `bytes` to `path` whole or not at all (a temporary file in the
/// same folder, renamed over it).
fn write_atomic(path: &Path, bytes: &[u8]) -> Result<(), String> {
    use std::io::Write;
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut tmp = tempfile::NamedTempFile::new_in(dir)
        .map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
    tmp.write_all(bytes)
        .and_then(|()| tmp.as_file().sync_all())
        .map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
    tmp.persist(path)
        .map_err(|e| format!("{}: cannot write: {}", path.display(), e.error))?;
    Ok(())
}

/// The answer in a solver's standard output (`s SATISFIABLE` with `v`
/// lines, `s UNSATISFIABLE`, or neither: no answer).
fn parse_answer(text: &str, path: &Path) -> Result<ExternalAnswer, String> {
    let mut status = None;
    let mut model = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let line = line.trim();
        if let Some(s) = line.strip_prefix("s ") {
            status = Some(s.trim().to_string());
        } else if let Some(v) = line.strip_prefix('v') {
            for token in v.split_whitespace() {
                let lit: i32 = token.parse().map_err(|_| {
                    format!(
                        "{} line {}: `{token}` is not a literal",
                        path.display(),
                        i + 1
                    )
                })?;
                if lit > 0 {
                    model.push(lit);
                }
            }
        }
    }
    Ok(match status.as_deref() {
        Some("UNSATISFIABLE") => ExternalAnswer::Unsat,
        Some("SATISFIABLE") => ExternalAnswer::Sat(model),
        _ => ExternalAnswer::Unknown,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_solvers_output_is_read_by_its_status_line() {
        let p = Path::new("k3.out");
        assert_eq!(
            parse_answer("c x\ns UNSATISFIABLE\n", p),
            Ok(ExternalAnswer::Unsat)
        );
        assert_eq!(
            parse_answer("s SATISFIABLE\nv 1 -2 3\nv -4 5 0\n", p),
            Ok(ExternalAnswer::Sat(vec![1, 3, 5]))
        );
        assert_eq!(
            parse_answer("c interrupted\n", p),
            Ok(ExternalAnswer::Unknown)
        );
        assert_eq!(parse_answer("s UNKNOWN\n", p), Ok(ExternalAnswer::Unknown));
        let err = parse_answer("s SATISFIABLE\nv 1 x 0\n", p).unwrap_err();
        assert!(err.contains("k3.out line 2: `x` is not a literal"), "{err}");
    }
}
