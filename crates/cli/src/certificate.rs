//! `--certificate DIR` of `bound` and `solve`: every refutation the exact
//! search proves is written as `DIR/k{K}.cnf` (the formula) and
//! `DIR/k{K}.drat` (the solver's proof that it is unsatisfiable), with
//! `DIR/README.txt` saying what each claims. And `dissect check-proof DIR`,
//! which replays them with the independent checker `dissect-proof`.

use std::collections::BTreeMap;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use anyhow::{Context, Result};
use dissect_exact::{Certificate, ExactEvent, ProofSink};

use crate::kept_cubes;
use crate::output::write_atomic;
use crate::{InputError, Status};

/// `(K, refuted cubes)` of a K whose refuted cubes are kept for a later run.
type KeptCubes = (usize, usize);

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
            streamed: Arc::new(Mutex::new(None)),
        })
    }

    /// Writers that take the cubes' proofs to files as the solvers go, so
    /// that no proof is held in memory (for
    /// `BoundConfig::cube_proofs`).
    pub fn cube_proofs(&self) -> ProofSink {
        ProofSink::new(Arc::new(crate::kept_cubes::CubeFiles {
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
                Err(e) => state.1 = Some(format!("{e:#}")),
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
                return Err(e).with_context(|| format!("cannot remove {stale}"))
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
                None => std::fs::rename(kept_cubes::proof(&work, j), &drat)
                    .with_context(|| format!("cannot write {}", drat.display()))?,
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
                        return Err(e).with_context(|| format!("cannot remove {}", stale.display()))
                    }
                    _ => {}
                }
            }
        }
        write_atomic(&self.dir.join(format!("k{k}.cubes")), cover.as_bytes())?;
        // The cubes kept for a later run are in the certificate now.
        match std::fs::remove_dir_all(&work) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => {
                Err(e).with_context(|| format!("cannot remove {}", work.display()))
            }
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

    /// The certificates written (their K) and the refuted cubes kept for
    /// a later run (`(K, cubes)`), or the first error met writing one. The
    /// proofs of cubes that were not refuted (`*.drat.part`) are removed;
    /// the refuted cubes of an unfinished K stay for a later run.
    fn finish(&self) -> Result<(Vec<usize>, Vec<KeptCubes>)> {
        let state = self.written.lock().unwrap_or_else(|e| e.into_inner());
        let kept = kept_cubes::tidy(&self.dir);
        let streamed = self.streamed.lock().unwrap_or_else(|e| e.into_inner());
        match state.1.as_ref().or(streamed.as_ref()) {
            Some(e) => Err(anyhow::anyhow!("{e}")),
            None => Ok((state.0.keys().copied().collect(), kept)),
        }
    }

    /// The line to print once the run is over (and one per K whose
    /// refuted cubes are kept for a later run).
    pub fn summary(&self) -> Result<String> {
        let (ks, kept) = self.finish()?;
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

/// `dissect check-proof DIR`.
#[derive(clap::Args, Debug)]
pub struct CheckProofArgs {
    /// A folder written by `--certificate`: every kK.cnf there is checked
    /// against its kK.drat.
    #[arg(value_name = "DIR")]
    pub dir: PathBuf,
}

/// The certificates in `dir`: `(K, formula, proof or cover)`, by K; the
/// third path ends in `.cubes` for a cube-and-conquer certificate.
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
        let cover = dir.join(format!("k{k}.cubes"));
        let proof = if cover.is_file() {
            cover
        } else {
            dir.join(format!("k{k}.drat"))
        };
        // A proof need not be a plain file: a named pipe (`mkfifo`) lets a
        // proof be checked as the solver writes it, never stored.
        if !proof.exists() || proof.is_dir() {
            return Err(InputError(format!(
                "{}: no proof beside {name} (k{k}.drat or k{k}.cubes)",
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

fn not_text(path: &Path) -> anyhow::Error {
    InputError(format!(
        "{}: not text (binary DRAT is not read; write text DRAT)",
        path.display()
    ))
    .into()
}

/// Checks the text DRAT proof in the file `proof` against `cnf` (read from
/// `cnf_path`), a line at a time: the proof is never held whole, whatever
/// its size. `Err`: the file cannot be read, is not text or is malformed
/// (bad input, the whole file parsed as before); `Ok(Err)`: the proof
/// fails.
fn check_streamed(
    cnf: &dissect_proof::Cnf,
    cnf_path: &Path,
    proof: &Path,
) -> Result<std::result::Result<dissect_proof::Verified, dissect_proof::ProofError>> {
    use std::io::BufRead;
    let file =
        std::fs::File::open(proof).with_context(|| format!("cannot read {}", proof.display()))?;
    let mut reader = std::io::BufReader::with_capacity(1 << 20, file);
    let mut checker = dissect_proof::Checker::new(cnf);
    let mut stream = dissect_proof::ProofStream::new();
    let (mut done, mut failed) = (false, None);
    let mut buf = Vec::new();
    loop {
        buf.clear();
        let n = reader
            .read_until(b'\n', &mut buf)
            .with_context(|| format!("cannot read {}", proof.display()))?;
        if n == 0 {
            break;
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
    let bytes = std::fs::read(path).with_context(|| format!("cannot read {}", path.display()))?;
    String::from_utf8(bytes).map_err(|_| not_text(path))
}

/// Checks every certificate of the folder; the last line is `verified: ...`
/// or `failed: ...` (exit 1); a malformed file is bad input (exit 2).
pub fn check(args: CheckProofArgs) -> Result<Status> {
    let mut failed = 0;
    let found = certificates(&args.dir)?;
    for (k, cnf_path, proof_path) in &found {
        if proof_path.extension().is_some_and(|e| e == "cubes") {
            if !check_cubed(*k, cnf_path, proof_path)? {
                failed += 1;
            }
            continue;
        }
        let cnf = dissect_proof::Cnf::parse(&read(cnf_path)?)
            .map_err(|e| located(e, cnf_path, proof_path))?;
        match check_streamed(&cnf, cnf_path, proof_path)? {
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

/// Checks a cube-and-conquer certificate `kK.cnf`, `kK.cubes`,
/// `kK.cube{j}.cnf`/`.drat` (the cubes counted until the first missing one;
/// the checker then says how many are missing), one cube at a time so that
/// only one cube's proof is held. `Ok(false)`: it failed (printed).
fn check_cubed(k: usize, cnf_path: &Path, cover_path: &Path) -> Result<bool> {
    let dir = cnf_path.parent().unwrap_or(Path::new("."));
    let base = dissect_proof::Cnf::parse(&read(cnf_path)?)
        .map_err(|e| located(e, cnf_path, cover_path))?;
    let cover = dissect_proof::parse_cover(&read(cover_path)?)
        .map_err(|e| InputError(format!("{}: {e}", cover_path.display())))?;
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
        println!("k{k}: FAILED: {}: {e}", cover_path.display());
        return Ok(false);
    }
    let (mut lemmas, mut rat, mut deletions) = (0, 0, 0);
    for (j, &literal) in cover.iter().enumerate() {
        let (c, p) = files(j);
        let cnf = dissect_proof::Cnf::parse(&read(&c)?).map_err(|e| located(e, &c, &p))?;
        let checked = match dissect_proof::cube_formula(&base, literal, &cnf) {
            Ok(whole) => check_streamed(&whole, &c, &p)?,
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
                    dissect_proof::Source::Proof => p,
                    _ => c,
                };
                println!("k{k}: FAILED: {}: {e}", place.display());
                return Ok(false);
            }
        }
    }
    println!(
        "k{k}: verified: no dissection into at most {k} pieces ({} clauses, {} cubes, {lemmas} lemmas, {rat} RAT, {deletions} deletions)",
        base.clauses().len(),
        cover.len(),
    );
    Ok(true)
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
        dissect_proof::Source::Proof | dissect_proof::Source::Cubes => proof,
    };
    InputError(format!("{}: {e}", path.display()))
}
