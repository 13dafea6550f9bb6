//! The cubes of cube-and-conquer kept on disk (`bound --threads N
//! --certificate DIR`): each cube's solver writes its DRAT proof to a file
//! as it goes, and every refuted cube is kept in `DIR/kK.work/` so that a
//! later run of the same question (the same base formula and cover) does
//! not solve it again.
//!
//! `DIR/kK.work/` holds `base.cnf` (the base formula), `cover` (the cubes'
//! literals), and per refuted cube `cube{j}.cnf` (its clauses),
//! `cube{j}.drat` (its proof) and `cube{j}.meta` (written last: the cube
//! is kept once it is there); a cube being solved writes
//! `cube{j}.drat.part`. When every cube of K is refuted the certificate
//! takes the files to `DIR/kK.cube{j}.*` and the folder goes.

use std::io::Write;
use std::path::{Path, PathBuf};
use std::sync::{Arc, Mutex};

use dissect_exact::{CubeProof, CubeProofWriters};

use crate::{write_atomic, CertificateError};

/// The work folder of K in `dir`.
pub fn work(dir: &Path, k: usize) -> PathBuf {
    dir.join(format!("k{k}.work"))
}

/// The kept proof of cube `j` in the work folder `work`.
pub fn proof(work: &Path, j: usize) -> PathBuf {
    work.join(format!("cube{j}.drat"))
}

fn part(work: &Path, j: usize) -> PathBuf {
    work.join(format!("cube{j}.drat.part"))
}

fn meta(work: &Path, j: usize) -> PathBuf {
    work.join(format!("cube{j}.meta"))
}

/// Keeps the first error in `slot`.
pub fn note(slot: &Mutex<Option<String>>, message: String) {
    slot.lock()
        .unwrap_or_else(|e| e.into_inner())
        .get_or_insert(message);
}

/// The proof writers of a certificate folder.
pub struct CubeFiles {
    pub dir: PathBuf,
    /// The first error met (reported when the run ends).
    pub error: Arc<Mutex<Option<String>>>,
}

impl CubeFiles {
    fn noted(&self, r: Result<(), CertificateError>) {
        if let Err(e) = r {
            note(&self.error, e.to_string());
        }
    }

    /// Starts the work folder of K afresh with `base` and `cover`.
    fn start(&self, k: usize, base: &str, cover: &[i32]) -> Result<(), CertificateError> {
        let work = work(&self.dir, k);
        let cannot = |e| CertificateError::io(format!("cannot make {}", work.display()), e);
        if work.exists() {
            std::fs::remove_dir_all(&work).map_err(cannot)?;
        }
        std::fs::create_dir_all(&work).map_err(cannot)?;
        write_atomic(&work.join("base.cnf"), base)?;
        write_atomic(&work.join("cover"), cover_text(cover))
    }
}

fn cover_text(cover: &[i32]) -> String {
    let mut s: String = cover.iter().map(|l| format!("{l} ")).collect();
    s.push_str("0\n");
    s
}

/// The kept cube `j` of `work` for literal `literal`, when whole.
fn kept(work: &Path, j: usize, literal: i32) -> Option<CubeProof> {
    let fields: Vec<i64> = std::fs::read_to_string(meta(work, j))
        .ok()?
        .split_whitespace()
        .map(str::parse)
        .collect::<Result<_, _>>()
        .ok()?;
    let [lit, clauses, lemmas, vars, cuts, connectivity] = fields[..] else {
        return None;
    };
    if lit != i64::from(literal) || !proof(work, j).is_file() {
        return None;
    }
    let formula = std::fs::read_to_string(work.join(format!("cube{j}.cnf"))).ok()?;
    let count = |v: i64| usize::try_from(v).ok();
    Some(CubeProof {
        literal,
        formula,
        clauses: count(clauses)?,
        proof: None,
        lemmas: count(lemmas)?,
        vars: count(vars)?,
        cuts: count(cuts)?,
        connectivity: connectivity != 0,
    })
}

impl CubeProofWriters for CubeFiles {
    fn open(&self, pieces: usize, cube: usize) -> Option<Box<dyn Write + Send>> {
        let path = part(&work(&self.dir, pieces), cube);
        match std::fs::File::create(&path) {
            Ok(file) => Some(Box::new(Noted {
                file,
                path,
                error: self.error.clone(),
            })),
            Err(e) => {
                // The proof is then kept in memory and written at the end.
                note(&self.error, format!("cannot write {}: {e}", path.display()));
                None
            }
        }
    }

    fn begin(&self, pieces: usize, base: &str, cover: &[i32]) -> Vec<Option<CubeProof>> {
        let work = work(&self.dir, pieces);
        let same = std::fs::read_to_string(work.join("base.cnf")).is_ok_and(|b| b == base)
            && std::fs::read_to_string(work.join("cover")).is_ok_and(|c| c == cover_text(cover));
        if same {
            return (0..cover.len()).map(|j| kept(&work, j, cover[j])).collect();
        }
        self.noted(self.start(pieces, base, cover));
        vec![None; cover.len()]
    }

    fn refuted(&self, pieces: usize, cube: usize, p: &CubeProof) {
        let work = work(&self.dir, pieces);
        let keep = || -> Result<(), CertificateError> {
            write_atomic(&work.join(format!("cube{cube}.cnf")), &p.formula)?;
            match &p.proof {
                Some(text) => write_atomic(&proof(&work, cube), text)?,
                None => std::fs::rename(part(&work, cube), proof(&work, cube)).map_err(|e| {
                    CertificateError::io(
                        format!("cannot write {}", proof(&work, cube).display()),
                        e,
                    )
                })?,
            }
            let fields = format!(
                "{} {} {} {} {} {}\n",
                p.literal,
                p.clauses,
                p.lemmas,
                p.vars,
                p.cuts,
                u8::from(p.connectivity)
            );
            write_atomic(&meta(&work, cube), fields)
        };
        self.noted(keep());
    }
}

/// The cubes kept in each work folder of `dir` (K, cubes), after removing
/// the proofs of cubes that were not refuted (`*.drat.part`).
pub fn tidy(dir: &Path) -> Vec<(usize, usize)> {
    let mut kept = Vec::new();
    let Ok(entries) = std::fs::read_dir(dir) else {
        return kept;
    };
    for entry in entries.flatten() {
        let name = entry.file_name().to_string_lossy().into_owned();
        let Some(k) = crate::k_of(&name, ".work") else {
            continue;
        };
        let mut metas = 0;
        for file in std::fs::read_dir(entry.path())
            .into_iter()
            .flatten()
            .flatten()
        {
            let file_name = file.file_name().to_string_lossy().into_owned();
            if file_name.ends_with(".drat.part") {
                let _ = std::fs::remove_file(file.path());
            } else if file_name.ends_with(".meta") {
                metas += 1;
            }
        }
        kept.push((k, metas));
    }
    kept.sort_unstable();
    kept
}

/// A proof file whose first write error is kept for the run's end.
struct Noted {
    file: std::fs::File,
    path: PathBuf,
    error: Arc<Mutex<Option<String>>>,
}

impl Noted {
    fn noted<T>(&self, r: std::io::Result<T>) -> std::io::Result<T> {
        if let Err(e) = &r {
            note(
                &self.error,
                format!("cannot write {}: {e}", self.path.display()),
            );
        }
        r
    }
}

impl Write for Noted {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let r = self.file.write(buf);
        self.noted(r)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        let r = self.file.sync_all();
        self.noted(r)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::atomic::{AtomicBool, AtomicUsize};

    use dissect_core::io::parse_figure;
    use dissect_core::LatticeKind;
    use dissect_exact::{
        search, Certificate, ExactEvent, ExactObserver, ExactOptions, Mode, ProofSink,
    };

    /// The certificate of k2 and the cubes announced as kept.
    #[derive(Default)]
    struct Seen(Mutex<(Option<Certificate>, Vec<usize>)>);

    impl ExactObserver for Seen {
        fn on_event(&self, event: &ExactEvent) {
            let mut seen = self.0.lock().unwrap();
            match event {
                ExactEvent::Certified(c) if c.pieces == 2 => seen.0 = Some(c.clone()),
                ExactEvent::CubeKept { index, .. } => seen.1.push(*index),
                _ => {}
            }
        }
    }

    /// "No 2-piece dissection" of a U into a bar by cube-and-conquer on
    /// two threads, the cubes' proofs going to files in `dir`.
    fn certify(dir: &Path) -> (Certificate, Vec<usize>) {
        let figs: Vec<_> = ["#.#\n###", "#####"]
            .iter()
            .map(|t| parse_figure(t, LatticeKind::Square).unwrap())
            .collect();
        let sink = CubeFiles {
            dir: dir.to_path_buf(),
            error: Arc::new(Mutex::new(None)),
        };
        let error = sink.error.clone();
        let options = ExactOptions {
            mode: Mode::LowerBound,
            max_pieces: Some(2),
            certify: true,
            cube_threads: 2,
            cube_proofs: Some(ProofSink::new(Arc::new(sink))),
            ..ExactOptions::default()
        };
        let seen = Seen::default();
        let out = search(
            &figs,
            &options,
            &AtomicBool::new(false),
            &AtomicUsize::new(usize::MAX),
            &seen,
        )
        .unwrap();
        assert_eq!(out.lower_bound.value, 3);
        assert_eq!(*error.lock().unwrap(), None);
        let (cert, kept) = seen.0.into_inner().unwrap();
        (cert.expect("k2 certified"), kept)
    }

    /// The kept cubes of `work` checked against its base and cover.
    fn check(work: &Path, cert: &Certificate) {
        let base =
            dissect_proof::Cnf::parse(&std::fs::read_to_string(work.join("base.cnf")).unwrap())
                .unwrap();
        let cover: Vec<i32> = cert.cubes.iter().map(|c| c.literal).collect();
        for (j, cube) in cert.cubes.iter().enumerate() {
            let cnf = dissect_proof::Cnf::parse(&cube.formula).unwrap();
            let text = std::fs::read_to_string(proof(work, j)).unwrap();
            let drat = dissect_proof::Proof::parse(&text).unwrap();
            dissect_proof::check_cube(&base, cover[j], &cnf, &drat).expect("the kept proof");
        }
    }

    #[test]
    fn refuted_cubes_are_kept_and_the_same_question_resumes_from_them() {
        let dir = tempfile::tempdir().unwrap();
        let (first, kept) = certify(dir.path());
        assert!(kept.is_empty());
        let n = first.cubes.len();
        assert!(n >= 2, "{n} cubes");
        let work = work(dir.path(), 2);
        // Every cube refuted is kept whole (its meta written last), and no
        // proof is left half written.
        for j in 0..n {
            assert!(
                meta(&work, j).is_file() && proof(&work, j).is_file(),
                "cube {j}"
            );
            assert!(!part(&work, j).exists(), "cube {j}");
        }
        check(&work, &first);

        // The same question again: every cube is taken from the folder.
        let (again, kept) = certify(dir.path());
        assert_eq!(kept, (0..n).collect::<Vec<_>>());
        assert_eq!(again.cubes, first.cubes);
        assert_eq!(again.formula, first.formula);

        // A cube whose meta is missing is solved again; the others kept.
        std::fs::remove_file(meta(&work, 1)).unwrap();
        let (_, kept) = certify(dir.path());
        assert_eq!(kept.len(), n - 1);
        assert!(!kept.contains(&1));
        assert!(meta(&work, 1).is_file(), "kept again once refuted");

        // A different base formula: nothing is kept, the folder starts
        // afresh with the real base.
        let base = work.join("base.cnf");
        let real = std::fs::read_to_string(&base).unwrap();
        std::fs::write(&base, format!("{real}1 0\n")).unwrap();
        std::fs::write(work.join("stale"), "").unwrap();
        let (fresh, kept) = certify(dir.path());
        assert!(kept.is_empty());
        assert_eq!(std::fs::read_to_string(&base).unwrap(), real);
        assert!(!work.join("stale").exists());
        check(&work, &fresh);

        // The run's end removes half-written proofs and counts the kept.
        std::fs::write(part(&work, 0), "1 2 ").unwrap();
        assert_eq!(tidy(dir.path()), vec![(2, n)]);
        assert!(!part(&work, 0).exists());
    }
}
