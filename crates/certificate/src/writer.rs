//! [`Writer`]: every refutation the exact search proves, written as
//! `DIR/k{K}.cnf` (the formula) and `DIR/k{K}.drat` (the solver's proof
//! that it is unsatisfiable) or the cubes of a cube-and-conquer run, with
//! `DIR/README.txt` saying what each claims.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use dissect_exact::{Certificate, ExactEvent, ProofSink};

use crate::kept_cubes;
use crate::{write_atomic, CertificateError};

type Result<T> = std::result::Result<T, CertificateError>;

/// What a run's certificates came to ([`Writer::finish`]).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Written {
    /// The K of every certificate written: "no dissection into at most K
    /// pieces", ascending.
    pub certified: Vec<usize>,
    /// `(K, cubes)` of every K whose refuted cubes are kept in
    /// `DIR/k{K}.work/` for a later run (its question unfinished).
    pub kept: Vec<(usize, usize)>,
}

/// What one certificate claims, for README.txt.
struct Entry {
    vars: usize,
    clauses: usize,
    lemmas: usize,
    cuts: usize,
    connectivity: bool,
    clique_only: bool,
    /// Cube-and-conquer: the number of cubes (0: one proof).
    cubes: usize,
}

/// Writes the certificates of a run as they come.
pub struct Writer {
    dir: PathBuf,
    /// The figures and settings, for README.txt.
    about: String,
    written: Mutex<(BTreeMap<usize, Entry>, Option<String>)>,
    /// The first error met writing a cube's proof as it went.
    streamed: Arc<Mutex<Option<String>>>,
}

impl Writer {
    /// A writer into `dir` (made if missing) for a run on `figures`.
    /// `figures` names the figures (their files) for README.txt.
    pub fn new(dir: &Path, figures: &[String], lattice: &str, mirror: bool) -> Result<Writer> {
        if dir.exists() && !dir.is_dir() {
            return Err(CertificateError::Input(format!(
                "{}: not a folder",
                dir.display()
            )));
        }
        std::fs::create_dir_all(dir)
            .map_err(|e| CertificateError::io(format!("cannot make {}", dir.display()), e))?;
        let names = figures;
        let about = format!(
            "figures: {} (lattice {lattice}; pieces may be turned over: {})",
            names.join(", "),
            if mirror { "yes" } else { "no" }
        );
        Ok(Writer {
            dir: dir.to_path_buf(),
            about,
            written: Mutex::new((BTreeMap::new(), None)),
            streamed: Arc::new(Mutex::new(None)),
        })
    }

    /// Writers that take the cubes' proofs to files as the solvers go, so
    /// that no proof is held in memory (for
    /// `BoundConfig::cube_proofs`).
    pub fn cube_proofs(&self) -> ProofSink {
        ProofSink::new(Arc::new(kept_cubes::CubeFiles {
            dir: self.dir.clone(),
            error: self.streamed.clone(),
        }))
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
                Err(e) => state.1 = Some(e.to_string()),
            }
        }
    }

    fn write(&self, c: &Certificate, written: &mut BTreeMap<usize, Entry>) -> Result<()> {
        let k = c.pieces;
        write_atomic(&self.dir.join(format!("k{k}.cnf")), c.formula.as_bytes())?;
        // A stale file of the other kind would be read beside this one.
        let stale = if c.cubes.is_empty() {
            format!("k{k}.cubes")
        } else {
            format!("k{k}.drat")
        };
        match std::fs::remove_file(self.dir.join(&stale)) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                return Err(CertificateError::io(format!("cannot remove {stale}"), e))
            }
            _ => {}
        }
        if c.cubes.is_empty() {
            write_atomic(&self.dir.join(format!("k{k}.drat")), c.proof.as_bytes())?;
        } else {
            self.write_cubes(c)?;
        }
        written.insert(
            k,
            Entry {
                vars: c.vars,
                clauses: c.clauses,
                lemmas: c.lemmas(),
                cuts: c.cuts,
                connectivity: c.connectivity,
                clique_only: c.clique_only,
                cubes: c.cubes.len(),
            },
        );
        write_atomic(&self.dir.join("README.txt"), self.readme(written))
    }

    /// A cubed certificate's cover `kK.cubes` and its cubes
    /// `kK.cube{j}.cnf`, `kK.cube{j}.drat`.
    fn write_cubes(&self, c: &Certificate) -> Result<()> {
        let k = c.pieces;
        let work = kept_cubes::work(&self.dir, k);
        let mut cover = format!(
            "c the cubes of k{k}.cnf: their literals, in order, are a clause of it;\n\
             c cube j (from 0) is k{k}.cube{{j}}.cnf (clauses added to k{k}.cnf, its unit first)\n\
             c refuted by k{k}.cube{{j}}.drat\n"
        );
        for cube in &c.cubes {
            cover.push_str(&format!("{} ", cube.literal));
        }
        cover.push_str("0\n");
        for (j, cube) in c.cubes.iter().enumerate() {
            write_atomic(
                &self.dir.join(format!("k{k}.cube{j}.cnf")),
                cube.formula.as_bytes(),
            )?;
            let drat = self.dir.join(format!("k{k}.cube{j}.drat"));
            match &cube.proof {
                Some(proof) => write_atomic(&drat, proof.as_bytes())?,
                None => std::fs::rename(kept_cubes::proof(&work, j), &drat).map_err(|e| {
                    CertificateError::io(format!("cannot write {}", drat.display()), e)
                })?,
            }
        }
        // The cubes of an earlier certificate for K with more of them.
        for j in c.cubes.len().. {
            let (cnf, drat) = (
                self.dir.join(format!("k{k}.cube{j}.cnf")),
                self.dir.join(format!("k{k}.cube{j}.drat")),
            );
            if !cnf.exists() && !drat.exists() {
                break;
            }
            for stale in [cnf, drat] {
                match std::fs::remove_file(&stale) {
                    Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                        return Err(CertificateError::io(
                            format!("cannot remove {}", stale.display()),
                            e,
                        ))
                    }
                    _ => {}
                }
            }
        }
        write_atomic(&self.dir.join(format!("k{k}.cubes")), cover.as_bytes())?;
        // The cubes kept for a later run are in the certificate now.
        match std::fs::remove_dir_all(&work) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => Err(CertificateError::io(
                format!("cannot remove {}", work.display()),
                e,
            )),
            _ => Ok(()),
        }
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
            if e.cubes > 0 {
                s.push_str(&format!(
                    "k{k}.cnf, k{k}.cubes, k{k}.cube0..{}.cnf/.drat: no dissection into at most {k} \
                     pieces by cube-and-conquer: k{k}.cubes is one clause of k{k}.cnf, each of its \
                     {} literals a cube; k{k}.cube{{j}}.cnf adds to k{k}.cnf the unit of literal j (and the \
                     connectivity encoding and cuts that cube met), k{k}.cube{{j}}.drat refutes the two \
                     together. Every model of k{k}.cnf satisfies one literal, so no model exists \
                     ({} clauses in k{k}.cnf, {} lemmas in all, {} cuts in all)\n",
                    e.cubes - 1,
                    e.cubes,
                    e.clauses,
                    e.lemmas,
                    e.cuts
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
             or any DRAT checker (drat-trim kK.cnf kK.drat); any SAT solver must answer UNSAT on kK.cnf.\n\
             For a cubed kK, the formula of cube j is kK.cnf's clauses with kK.cube{j}.cnf's (kK.cnf\n\
             alone is the relaxation without connectivity); any SAT solver must answer UNSAT on each.\n",
        );
        s
    }

    /// The folder written into.
    pub fn dir(&self) -> &Path {
        &self.dir
    }

    /// Once the run is over: the certificates written and the refuted
    /// cubes kept for a later run, or the first error met writing one. The
    /// proofs of cubes that were not refuted (`*.drat.part`) are removed;
    /// the refuted cubes of an unfinished K stay for a later run.
    pub fn finish(&self) -> Result<Written> {
        let state = self.written.lock().unwrap_or_else(|e| e.into_inner());
        let kept = kept_cubes::tidy(&self.dir);
        let streamed = self.streamed.lock().unwrap_or_else(|e| e.into_inner());
        match state.1.as_ref().or(streamed.as_ref()) {
            Some(e) => Err(CertificateError::Writing(e.clone())),
            None => Ok(Written {
                certified: state.0.keys().copied().collect(),
                kept,
            }),
        }
    }

    /// The line to print once the run is over (and one per K whose
    /// refuted cubes are kept for a later run).
    pub fn summary(&self) -> Result<String> {
        let Written {
            certified: ks,
            kept,
        } = self.finish()?;
        let kept: String = kept
            .into_iter()
            .map(|(k, cubes)| {
                format!(
                    "k{k}: {cubes} refuted cube(s) kept in {} (the same command resumes from them)\n",
                    kept_cubes::work(&self.dir, k).display()
                )
            })
            .collect();
        let line = if ks.is_empty() {
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
        };
        Ok(format!("{kept}{line}"))
    }
}
