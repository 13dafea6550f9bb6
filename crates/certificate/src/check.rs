//! [`check_folder`]: every certificate of a folder replayed by the
//! independent checker `dissect-proof`, a proof a line at a time (never
//! held whole, whatever its size; it may be a named pipe a solver is
//! writing into).

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

use dissect_proof::{Cnf, ProofError, Source};

use crate::CertificateError;

type Result<T> = std::result::Result<T, CertificateError>;

/// One certificate checked: "no dissection into at most `k` pieces".
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Checked {
    /// The K the certificate refutes.
    pub k: usize,
    /// Verified, or where the replay failed.
    pub outcome: Outcome,
}

/// How a certificate's check ended.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Outcome {
    /// Every lemma checked and the empty clause reached.
    Verified(Summary),
    /// The proof does not refute the formula: the message names the file
    /// (and the line) where the replay failed.
    Failed(String),
}

/// What a verified certificate held.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Summary {
    /// Clauses of the formula `kK.cnf`.
    pub clauses: usize,
    /// Cube-and-conquer: the cubes (0: one proof).
    pub cubes: usize,
    /// Lemmas checked (over every cube).
    pub lemmas: usize,
    /// Of them, RAT (not RUP) lemmas.
    pub rat_lemmas: usize,
    /// Clauses deleted.
    pub deletions: usize,
}

impl Checked {
    /// Whether the certificate verified.
    pub fn verified(&self) -> bool {
        matches!(self.outcome, Outcome::Verified(_))
    }
}

/// The line `check-proof` prints for it.
impl fmt::Display for Checked {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let k = self.k;
        match &self.outcome {
            Outcome::Failed(m) => write!(f, "k{k}: FAILED: {m}"),
            Outcome::Verified(s) if s.cubes > 0 => write!(
                f,
                "k{k}: verified: no dissection into at most {k} pieces ({} clauses, {} cubes, {} lemmas, {} RAT, {} deletions)",
                s.clauses, s.cubes, s.lemmas, s.rat_lemmas, s.deletions
            ),
            Outcome::Verified(s) => write!(
                f,
                "k{k}: verified: no dissection into at most {k} pieces ({} clauses, {} lemmas, {} RAT, {} deletions)",
                s.clauses, s.lemmas, s.rat_lemmas, s.deletions
            ),
        }
    }
}

/// The last line of a check: `verified: 2 certificates (k3, k4)`, or
/// `failed: 1 of 2 certificates do not verify`.
pub fn verdict(checked: &[Checked]) -> String {
    let failed = checked.iter().filter(|c| !c.verified()).count();
    if failed > 0 {
        return format!(
            "failed: {failed} of {} certificates do not verify",
            checked.len()
        );
    }
    let ks: Vec<String> = checked.iter().map(|c| format!("k{}", c.k)).collect();
    let n = checked.len();
    let count = if n == 1 {
        "1 certificate".to_string()
    } else {
        format!("{n} certificates")
    };
    format!("verified: {count} ({})", ks.join(", "))
}

/// Checks every certificate in `dir` (`kK.cnf` with `kK.drat`, or with
/// `kK.cubes` and its cubes), by K, calling `each` as each one ends (a
/// large proof takes as long as its solve). A proof that fails is an
/// [`Outcome::Failed`]; a folder without certificates, a formula without
/// its proof, a file that cannot be read or is malformed is an error, and
/// so is `stop` raised ([`CertificateError::Stopped`], within a proof line).
pub fn check_folder(
    dir: &Path,
    stop: &AtomicBool,
    each: &mut dyn FnMut(&Checked),
) -> Result<Vec<Checked>> {
    let mut all = Vec::new();
    for (k, cnf_path, proof_path) in certificates(dir)? {
        let outcome = if proof_path.extension().is_some_and(|e| e == "cubes") {
            check_cubed(k, &cnf_path, &proof_path, stop)?
        } else {
            let cnf =
                Cnf::parse(&read(&cnf_path)?).map_err(|e| located(e, &cnf_path, &proof_path))?;
            let clauses = cnf.clauses().len();
            match check_streamed(cnf, &cnf_path, &proof_path, stop)? {
                Ok(v) => Outcome::Verified(Summary {
                    clauses,
                    cubes: 0,
                    lemmas: v.lemmas,
                    rat_lemmas: v.rat_lemmas,
                    deletions: v.deletions,
                }),
                Err(e) => Outcome::Failed(located(e, &cnf_path, &proof_path).to_string()),
            }
        };
        let checked = Checked { k, outcome };
        each(&checked);
        all.push(checked);
    }
    Ok(all)
}

/// The certificates in `dir`: `(K, formula, proof or cover)`, by K; the
/// third path ends in `.cubes` for a cube-and-conquer certificate.
fn certificates(dir: &Path) -> Result<Vec<(usize, PathBuf, PathBuf)>> {
    let input = |m: String| CertificateError::Input(m);
    let entries = std::fs::read_dir(dir)
        .map_err(|e| input(format!("{}: cannot read the folder: {e}", dir.display())))?;
    let mut found = Vec::new();
    for entry in entries {
        let entry =
            entry.map_err(|e| input(format!("{}: cannot read the folder: {e}", dir.display())))?;
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some(k) = crate::k_of(&name, ".cnf") else {
            continue;
        };
        let cover = dir.join(format!("k{k}.cubes"));
        let proof = if cover.is_file() {
            cover
        } else {
            dir.join(format!("k{k}.drat"))
        };
        // A proof need not be a plain file: a named pipe (`mkfifo`) lets a
        // proof be checked as the solver writes it, never stored.
        if !proof.exists() || proof.is_dir() {
            return Err(input(format!(
                "{}: no proof beside {name} (k{k}.drat or k{k}.cubes)",
                dir.display()
            )));
        }
        found.push((k, dir.join(name), proof));
    }
    found.sort();
    if found.is_empty() {
        return Err(input(format!(
            "{}: no certificate (kK.cnf) in it",
            dir.display()
        )));
    }
    Ok(found)
}

fn not_text(path: &Path) -> CertificateError {
    CertificateError::Input(format!(
        "{}: not text (binary DRAT is not read; write text DRAT)",
        path.display()
    ))
}

fn cannot_read(path: &Path, e: std::io::Error) -> CertificateError {
    CertificateError::io(format!("cannot read {}", path.display()), e)
}

/// Checks the text DRAT proof in the file `proof` against `cnf` (read from
/// `cnf_path`), a line at a time: the proof is never held whole, whatever
/// its size. `Err`: the file cannot be read, is not text or is malformed
/// (bad input, the whole file parsed as before); `Ok(Err)`: the proof
/// fails.
fn check_streamed(
    cnf: Cnf,
    cnf_path: &Path,
    proof: &Path,
    stop: &AtomicBool,
) -> Result<std::result::Result<dissect_proof::Verified, ProofError>> {
    use std::io::BufRead;
    let file = std::fs::File::open(proof).map_err(|e| cannot_read(proof, e))?;
    let mut reader = std::io::BufReader::with_capacity(1 << 20, file);
    let mut checker = dissect_proof::Checker::new(&cnf);
    // The checker holds the clauses now: the parsed copy goes (on a
    // formula of millions of clauses, hundreds of MB).
    drop(cnf);
    let mut stream = dissect_proof::ProofStream::new();
    let (mut done, mut failed) = (false, None);
    let mut buf = Vec::new();
    loop {
        buf.clear();
        let n = reader
            .read_until(b'\n', &mut buf)
            .map_err(|e| cannot_read(proof, e))?;
        if n == 0 {
            break;
        }
        if stop.load(Ordering::Relaxed) {
            return Err(CertificateError::Stopped);
        }
        let line = std::str::from_utf8(&buf).map_err(|_| not_text(proof))?;
        let line = line.strip_suffix('\n').unwrap_or(line);
        let line = line.strip_suffix('\r').unwrap_or(line);
        stream
            .line(line, &mut |at, step| {
                // Past a refutation or a failure the rest is only parsed.
                if !done && failed.is_none() {
                    match checker.step(at, &step) {
                        Ok(refuted) => done = refuted,
                        Err(e) => failed = Some(e),
                    }
                }
                Ok(())
            })
            .map_err(|e| located(e, cnf_path, proof))?;
    }
    let last = stream.end().map_err(|e| located(e, cnf_path, proof))?;
    Ok(match failed {
        Some(e) => Err(e),
        None => checker.finish(last),
    })
}

fn read(path: &Path) -> Result<String> {
    let bytes = std::fs::read(path).map_err(|e| cannot_read(path, e))?;
    String::from_utf8(bytes).map_err(|_| not_text(path))
}

/// Checks a cube-and-conquer certificate `kK.cnf`, `kK.cubes`,
/// `kK.cube{j}.cnf`/`.drat` (the cubes counted until the first missing one;
/// the checker then says how many are missing), one cube at a time so that
/// only one cube's proof is held.
fn check_cubed(k: usize, cnf_path: &Path, cover_path: &Path, stop: &AtomicBool) -> Result<Outcome> {
    let dir = cnf_path.parent().unwrap_or(Path::new("."));
    let base = Cnf::parse(&read(cnf_path)?).map_err(|e| located(e, cnf_path, cover_path))?;
    let cover = dissect_proof::parse_cover(&read(cover_path)?)
        .map_err(|e| CertificateError::Input(format!("{}: {e}", cover_path.display())))?;
    let files = |j: usize| {
        (
            dir.join(format!("k{k}.cube{j}.cnf")),
            dir.join(format!("k{k}.cube{j}.drat")),
        )
    };
    let present = (0..)
        .take_while(|&j| {
            let (c, p) = files(j);
            c.is_file() && p.is_file()
        })
        .count();
    if let Err(e) = dissect_proof::check_cover(&base, &cover, present) {
        return Ok(Outcome::Failed(format!("{}: {e}", cover_path.display())));
    }
    let (mut lemmas, mut rat, mut deletions) = (0, 0, 0);
    for (j, &literal) in cover.iter().enumerate() {
        let (c, p) = files(j);
        let cnf = Cnf::parse(&read(&c)?).map_err(|e| located(e, &c, &p))?;
        let checked = match dissect_proof::cube_formula(&base, literal, &cnf) {
            Ok(whole) => check_streamed(whole, &c, &p, stop)?,
            Err(e) => Err(e),
        };
        match checked {
            Ok(v) => {
                lemmas += v.lemmas;
                rat += v.rat_lemmas;
                deletions += v.deletions;
            }
            Err(e) => {
                let place = match e.location().0 {
                    Source::Proof => p,
                    _ => c,
                };
                return Ok(Outcome::Failed(format!("{}: {e}", place.display())));
            }
        }
    }
    Ok(Outcome::Verified(Summary {
        clauses: base.clauses().len(),
        cubes: cover.len(),
        lemmas,
        rat_lemmas: rat,
        deletions,
    }))
}

/// The checker's error with the file it is in (bad input).
fn located(e: ProofError, cnf: &Path, proof: &Path) -> CertificateError {
    let (source, _) = e.location();
    let path = match source {
        Source::Formula => cnf,
        Source::Proof | Source::Cubes => proof,
    };
    CertificateError::Input(format!("{}: {e}", path.display()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `(x1 ∨ x2) (¬x1 ∨ x2) (x1 ∨ ¬x2) (¬x1 ∨ ¬x2)`: unsatisfiable,
    /// refuted by the lemma `x2` and the empty clause.
    const CNF: &str = "p cnf 2 4\n1 2 0\n-1 2 0\n1 -2 0\n-1 -2 0\n";

    fn folder(cnf: &str, proof: &str) -> tempfile::TempDir {
        let dir = tempfile::tempdir().unwrap();
        std::fs::write(dir.path().join("k3.cnf"), cnf).unwrap();
        std::fs::write(dir.path().join("k3.drat"), proof).unwrap();
        dir
    }

    #[test]
    fn verifies_fails_and_stops() {
        let never = AtomicBool::new(false);
        let dir = folder(CNF, "2 0\n0\n");
        let mut seen = Vec::new();
        let checked = check_folder(dir.path(), &never, &mut |c| seen.push(c.to_string())).unwrap();
        assert_eq!(checked.len(), 1);
        assert!(checked[0].verified(), "{}", checked[0]);
        assert_eq!(
            seen,
            ["k3: verified: no dissection into at most 3 pieces (4 clauses, 1 lemmas, 0 RAT, 0 deletions)"]
        );
        assert_eq!(verdict(&checked), "verified: 1 certificate (k3)");

        // A clause removed from the formula: the lemma no longer follows.
        let dir = folder("p cnf 2 3\n1 2 0\n-1 2 0\n1 -2 0\n", "2 0\n0\n");
        let checked = check_folder(dir.path(), &never, &mut |_| {}).unwrap();
        assert!(!checked[0].verified());
        assert!(checked[0].to_string().contains("k3.drat"), "{}", checked[0]);
        assert_eq!(
            verdict(&checked),
            "failed: 1 of 1 certificates do not verify"
        );

        // Stopped: an error, not a verdict.
        let dir = folder(CNF, "2 0\n0\n");
        let e = check_folder(dir.path(), &AtomicBool::new(true), &mut |_| {}).unwrap_err();
        assert!(matches!(e, CertificateError::Stopped), "{e}");

        // No proof beside the formula: bad input naming the folder.
        std::fs::remove_file(dir.path().join("k3.drat")).unwrap();
        let e = check_folder(dir.path(), &never, &mut |_| {}).unwrap_err();
        assert!(e.to_string().contains("no proof beside k3.cnf"), "{e}");
    }
}
