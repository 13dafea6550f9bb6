//! `--certificate DIR` of `bound` and `solve`: every refutation the exact
//! search proves is written as `DIR/k{K}.cnf` (the formula) and
//! `DIR/k{K}.drat` (the solver's proof that it is unsatisfiable), with
//! `DIR/README.txt` saying what each claims. And `dissect check-proof DIR`,
//! which replays them with the independent checker `dissect-proof`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::Mutex;

use anyhow::{Context, Result};
use dissect_exact::{Certificate, ExactEvent};

use crate::output::write_atomic;
use crate::{InputError, Status};

/// What one certificate claims, for README.txt.
struct Entry {
    vars: usize,
    clauses: usize,
    lemmas: usize,
    cuts: usize,
    connectivity: bool,
    clique_only: bool,
}

/// Writes the certificates of a run as they come.
pub struct Writer {
    dir: PathBuf,
    /// The figures and settings, for README.txt.
    about: String,
    written: Mutex<(BTreeMap<usize, Entry>, Option<String>)>,
}

impl Writer {
    /// A writer into `dir` (made if missing) for a run on `figures`.
    pub fn new(dir: &Path, figures: &[PathBuf], lattice: &str, mirror: bool) -> Result<Writer> {
        if dir.exists() && !dir.is_dir() {
            return Err(InputError(format!("{}: not a folder", dir.display())).into());
        }
        std::fs::create_dir_all(dir).with_context(|| format!("cannot make {}", dir.display()))?;
        let names: Vec<String> = figures.iter().map(|p| p.display().to_string()).collect();
        let about = format!(
            "figures: {} (lattice {lattice}; pieces may be turned over: {})",
            names.join(", "),
            if mirror { "yes" } else { "no" }
        );
        Ok(Writer {
            dir: dir.to_path_buf(),
            about,
            written: Mutex::new((BTreeMap::new(), None)),
        })
    }

    /// Writes the certificate an event carries (errors are kept for
    /// [`Writer::finish`]).
    pub fn on_event(&self, event: &ExactEvent) {
        if let ExactEvent::Certified(c) = event {
            let mut state = self.written.lock().unwrap_or_else(|e| e.into_inner());
            if state.1.is_some() {
                return;
            }
            match self.write(c, &mut state.0) {
                Ok(()) => {}
                Err(e) => state.1 = Some(format!("{e:#}")),
            }
        }
    }

    fn write(&self, c: &Certificate, written: &mut BTreeMap<usize, Entry>) -> Result<()> {
        let k = c.pieces;
        write_atomic(&self.dir.join(format!("k{k}.cnf")), c.formula.as_bytes())?;
        write_atomic(&self.dir.join(format!("k{k}.drat")), c.proof.as_bytes())?;
        written.insert(
            k,
            Entry {
                vars: c.vars,
                clauses: c.clauses,
                lemmas: c.lemmas(),
                cuts: c.cuts,
                connectivity: c.connectivity,
                clique_only: c.clique_only,
            },
        );
        write_atomic(&self.dir.join("README.txt"), self.readme(written))
    }

    fn readme(&self, written: &BTreeMap<usize, Entry>) -> String {
        let mut s = String::from(
            "Certificates written by `dissect` (see docs/FORMAT.md, \"Certificates\").\n\n",
        );
        s.push_str(&self.about);
        s.push_str(
            "\n\nkK.cnf (DIMACS CNF) is the formula \"these figures have a dissection into at most K\n\
             pieces\" as dissect encodes it: the placement relaxation (pieces need not be\n\
             connected) with the clauses the search added before the solver answered (the\n\
             connectivity encoding, connectivity cuts; both only remove splits). Every real\n\
             dissection into at most K connected pieces satisfies it.\n\
             kK.drat (text DRAT) is the SAT solver's proof that kK.cnf is unsatisfiable.\n\
             Together they claim: no dissection of these figures into K or fewer pieces exists.\n\n",
        );
        for (k, e) in written {
            if e.clique_only {
                s.push_str(&format!(
                    "k{k}.cnf, k{k}.drat: no dissection into at most {k} pieces, from the encoding's \
                     clauses over {} pairwise incompatible cells only (each in some piece, the \
                     first {k} in pieces 1..{k}, no two in one piece; the whole encoding would \
                     not fit) ({} clauses, {} lemmas)\n",
                    e.vars / k.max(&1),
                    e.clauses,
                    e.lemmas
                ));
                continue;
            }
            s.push_str(&format!(
                "k{k}.cnf, k{k}.drat: no dissection into at most {k} pieces ({} variables, {} clauses, \
                 {} lemmas; connectivity encoding: {}; connectivity cuts: {})\n",
                e.vars,
                e.clauses,
                e.lemmas,
                if e.connectivity { "yes" } else { "no" },
                e.cuts
            ));
        }
        s.push_str(
            "\nCheck them: `dissect check-proof DIR` (an independent checker, crate dissect-proof),\n\
             or any DRAT checker (drat-trim kK.cnf kK.drat); any SAT solver must answer UNSAT on kK.cnf.\n",
        );
        s
    }

    /// The certificates written, or the first error met writing one.
    pub fn finish(&self) -> Result<Vec<usize>> {
        let state = self.written.lock().unwrap_or_else(|e| e.into_inner());
        match &state.1 {
            Some(e) => Err(anyhow::anyhow!("{e}")),
            None => Ok(state.0.keys().copied().collect()),
        }
    }

    /// The line to print once the run is over.
    pub fn summary(&self) -> Result<String> {
        let ks = self.finish()?;
        Ok(if ks.is_empty() {
            format!(
                "certificates: none written to {} (no SAT refutation)",
                self.dir.display()
            )
        } else {
            let list: Vec<String> = ks.iter().map(|k| format!("k{k}")).collect();
            format!(
                "certificates: {} in {} (check with: dissect check-proof {})",
                list.join(", "),
                self.dir.display(),
                self.dir.display()
            )
        })
    }
}

/// `dissect check-proof DIR`.
#[derive(clap::Args, Debug)]
pub struct CheckProofArgs {
    /// A folder written by `--certificate`: every kK.cnf there is checked
    /// against its kK.drat.
    #[arg(value_name = "DIR")]
    pub dir: PathBuf,
}

/// The certificates in `dir`: `(K, formula, proof)`, by K.
fn certificates(dir: &Path) -> Result<Vec<(usize, PathBuf, PathBuf)>> {
    let entries = std::fs::read_dir(dir)
        .map_err(|e| InputError(format!("{}: cannot read the folder: {e}", dir.display())))?;
    let mut found = Vec::new();
    for entry in entries {
        let name = entry?.file_name().to_string_lossy().into_owned();
        let Some(k) = name
            .strip_prefix('k')
            .and_then(|r| r.strip_suffix(".cnf"))
            .and_then(|k| k.parse::<usize>().ok())
        else {
            continue;
        };
        let proof = dir.join(format!("k{k}.drat"));
        if !proof.is_file() {
            return Err(InputError(format!(
                "{}: no proof beside {name} (k{k}.drat)",
                dir.display()
            ))
            .into());
        }
        found.push((k, dir.join(name), proof));
    }
    found.sort();
    if found.is_empty() {
        return Err(InputError(format!("{}: no certificate (kK.cnf) in it", dir.display())).into());
    }
    Ok(found)
}

fn read(path: &Path) -> Result<String> {
    let bytes = std::fs::read(path).with_context(|| format!("cannot read {}", path.display()))?;
    String::from_utf8(bytes).map_err(|_| {
        InputError(format!(
            "{}: not text (binary DRAT is not read; write text DRAT)",
            path.display()
        ))
        .into()
    })
}

/// Checks every certificate of the folder; the last line is `verified: ...`
/// or `failed: ...` (exit 1); a malformed file is bad input (exit 2).
pub fn check(args: CheckProofArgs) -> Result<Status> {
    let mut failed = 0;
    let found = certificates(&args.dir)?;
    for (k, cnf_path, proof_path) in &found {
        let cnf = dissect_proof::Cnf::parse(&read(cnf_path)?)
            .map_err(|e| located(e, cnf_path, proof_path))?;
        let proof = dissect_proof::Proof::parse(&read(proof_path)?)
            .map_err(|e| located(e, cnf_path, proof_path))?;
        match dissect_proof::check(&cnf, &proof) {
            Ok(v) => println!(
                "k{k}: verified: no dissection into at most {k} pieces ({} clauses, {} lemmas, {} RAT, {} deletions)",
                cnf.clauses().len(),
                v.lemmas,
                v.rat_lemmas,
                v.deletions
            ),
            Err(e) => {
                failed += 1;
                println!("k{k}: FAILED: {}", located(e, cnf_path, proof_path));
            }
        }
    }
    if failed > 0 {
        println!(
            "failed: {failed} of {} certificates do not verify",
            found.len()
        );
        return Ok(Status::NotFound);
    }
    let ks: Vec<String> = found.iter().map(|(k, ..)| format!("k{k}")).collect();
    println!("verified: {} ({})", plural(found.len()), ks.join(", "));
    Ok(Status::Ok)
}

fn plural(n: usize) -> String {
    if n == 1 {
        "1 certificate".into()
    } else {
        format!("{n} certificates")
    }
}

/// The checker's error with the file it is in.
fn located(e: dissect_proof::ProofError, cnf: &Path, proof: &Path) -> InputError {
    let (source, _) = e.location();
    let path = match source {
        dissect_proof::Source::Formula => cnf,
        dissect_proof::Source::Proof => proof,
    };
    InputError(format!("{}: {e}", path.display()))
}
