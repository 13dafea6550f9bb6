//! Certificates (`ExactOptions::certify`): every refutation of the search
//! comes with its formula and a DRAT proof that the independent checker
//! `dissect-proof` verifies, and no certificate ever claims a piece count
//! that brute force can reach.

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, AtomicUsize};
use std::sync::{Arc, Mutex};

use dissect_core::io::parse_figure;
use dissect_core::{Figure, LatticeKind};
use dissect_exact::{
    search, Certificate, CubeProofWriters, ExactEvent, ExactObserver, ExactOptions, Mode,
    MotionEncoding, ProofSink, Reason,
};

struct Collect(Mutex<Vec<Certificate>>, Mutex<Vec<usize>>);

impl ExactObserver for Collect {
    fn on_event(&self, event: &ExactEvent) {
        match event {
            ExactEvent::Certified(c) => self.0.lock().unwrap().push(c.clone()),
            ExactEvent::Refuted(b) => {
                if let Reason::Sat { refuted, .. } = b.reason {
                    self.1.lock().unwrap().push(refuted);
                }
            }
            _ => {}
        }
    }
}

fn figures(lattice: LatticeKind, texts: &[&str]) -> Vec<Figure> {
    texts
        .iter()
        .map(|t| parse_figure(t, lattice).expect("test figure parses"))
        .collect()
}

/// Certificates of a bound search up to `minimum - 1` pieces, each checked.
fn certified(figs: &[Figure], mirror: bool, minimum: usize, eager: bool) -> Vec<Certificate> {
    certified_with(
        figs,
        mirror,
        minimum,
        eager,
        ExactOptions::default().max_encoding_bytes,
    )
}

fn certified_with(
    figs: &[Figure],
    mirror: bool,
    minimum: usize,
    eager: bool,
    max_encoding_bytes: u64,
) -> Vec<Certificate> {
    certified_encoded(
        figs,
        (mirror, minimum, eager),
        max_encoding_bytes,
        MotionEncoding::Auto,
    )
}

fn certified_encoded(
    figs: &[Figure],
    (mirror, minimum, eager): (bool, usize, bool),
    max_encoding_bytes: u64,
    motion_encoding: MotionEncoding,
) -> Vec<Certificate> {
    let options = ExactOptions {
        mirror,
        mode: Mode::LowerBound,
        max_pieces: Some(minimum - 1),
        eager_connectivity: eager,
        certify: true,
        max_encoding_bytes,
        motion_encoding,
        ..ExactOptions::default()
    };
    let collect = Collect(Mutex::new(Vec::new()), Mutex::new(Vec::new()));
    let out = search(
        figs,
        &options,
        &AtomicBool::new(false),
        &AtomicUsize::new(usize::MAX),
        &collect,
    )
    .expect("search runs");
    assert_eq!(out.lower_bound.value, minimum, "{figs:?} eager {eager}");
    let certs = collect.0.into_inner().unwrap();
    for refuted in collect.1.into_inner().unwrap() {
        assert!(
            certs.iter().any(|c| c.pieces == refuted),
            "the refutation of {refuted} pieces has a certificate"
        );
    }
    for c in &certs {
        assert!(
            c.pieces < minimum,
            "a certificate claims {} < the minimum {minimum}",
            c.pieces
        );
        let cnf = dissect_proof::Cnf::parse(&c.formula).expect("the formula parses");
        assert_eq!((cnf.vars(), cnf.clauses().len()), (c.vars, c.clauses));
        let proof = dissect_proof::Proof::parse(&c.proof).expect("the proof parses");
        dissect_proof::check(&cnf, &proof)
            .unwrap_or_else(|e| panic!("k{}: the checker rejects the proof: {e}", c.pieces));
    }
    certs
}

#[test]
fn every_refutation_has_a_certificate_the_checker_verifies() {
    let s = LatticeKind::Square;
    // Minimum piece counts from the brute force of tests/exact.rs.
    let cases: [(&[&str], usize); 5] = [
        (&["###\n#..", "##\n##"], 2),
        (&["#.#\n###", "#####"], 3),
        (&["###\n###", "######"], 2),
        (&["##..\n.##.\n..##", "###\n###"], 2),
        (&["###\n#.#\n###", "####\n####"], 2),
    ];
    for (texts, minimum) in cases {
        for eager in [true, false] {
            let certs = certified(&figures(s, texts), true, minimum, eager);
            assert!(
                certs.iter().any(|c| c.pieces == minimum - 1),
                "{texts:?}: the bound {minimum} is certified"
            );
        }
    }
    let tri = figures(LatticeKind::Tri4, &["FF", "6C\n39"]);
    certified(&tri, true, 3, false);
}

#[test]
fn a_refutation_with_lemmas_is_certified() {
    // A 15×10 rectangle with a 3×2 hole into a 12×12 square: SAT refutes 2
    // pieces after conflicts, so the proof has lemmas to check.
    let figs = figures(
        LatticeKind::Square,
        &[
            "###############\n###############\n###############\n####...########\n####...########\n\
             ###############\n###############\n###############\n###############\n###############",
            &"############\n".repeat(12),
        ],
    );
    let certs = certified(&figs, true, 3, true);
    let k2 = certs.iter().find(|c| c.pieces == 2).expect("k2 certified");
    assert!(k2.lemmas() > 1, "{} lemmas", k2.lemmas());
}

#[test]
fn a_clique_bound_too_large_to_encode_is_certified_by_its_clique() {
    // Squares 3 and 4 into 5: the 4 corners of the 5×5 square are pairwise
    // incompatible. With no room for the encoding, the certificate of 3
    // pieces holds the clique's clauses only.
    let figs = figures(
        LatticeKind::Square,
        &[
            "####..###\n####..###\n####..###\n####.....\n",
            &"#####\n".repeat(5),
        ],
    );
    let certs = certified_with(&figs, true, 4, true, 1);
    assert_eq!(certs.len(), 1);
    assert!(certs[0].clique_only && certs[0].pieces == 3);
    assert_eq!(certs[0].vars, 4 * 3);
    let full = certified(&figs, true, 4, true);
    assert!(full.iter().all(|c| !c.clique_only && c.vars > 12));
}

/// The formula `text` without its clause number `drop` (0-based, the header
/// count lowered).
fn without_clause(text: &str, drop: usize) -> String {
    let mut lines = text.lines();
    let header: Vec<&str> = lines.next().expect("header").split_whitespace().collect();
    let clauses: usize = header[3].parse().expect("count");
    let mut out = format!("p cnf {} {}\n", header[2], clauses - 1);
    for (i, line) in lines.enumerate() {
        if i != drop {
            out.push_str(line);
            out.push('\n');
        }
    }
    out
}

/// With the shift chain ([`MotionEncoding::Shifts`]) every refutation is
/// certified and checked as with the direct encoding (the chain's clauses
/// and the connectivity added after a model are in the formula written),
/// and the proof depends on them: some clause removed makes the checker
/// fail.
#[test]
fn shift_chain_refutations_are_certified_and_need_their_clauses() {
    let s = LatticeKind::Square;
    let shifts = MotionEncoding::Shifts;
    let cap = ExactOptions::default().max_encoding_bytes;
    for (texts, minimum) in [
        (&["#.#\n###", "#####"][..], 3),
        (&["##..\n.##.\n..##", "###\n###"][..], 2),
    ] {
        for eager in [true, false] {
            let certs = certified_encoded(&figures(s, texts), (true, minimum, eager), cap, shifts);
            assert!(certs.iter().any(|c| c.pieces == minimum - 1), "{texts:?}");
        }
    }
    let figs = figures(
        LatticeKind::Square,
        &[
            "###############\n###############\n###############\n####...########\n####...########\n\
             ###############\n###############\n###############\n###############\n###############",
            &"############\n".repeat(12),
        ],
    );
    let certs = certified_encoded(&figs, (true, 3, true), cap, shifts);
    let k2 = certs.iter().find(|c| c.pieces == 2).expect("k2 certified");
    let proof = dissect_proof::Proof::parse(&k2.proof).expect("the proof parses");
    let step = (k2.clauses / 300).max(1);
    let failed = (0..k2.clauses).step_by(step).any(|drop| {
        let cnf = dissect_proof::Cnf::parse(&without_clause(&k2.formula, drop)).expect("parses");
        dissect_proof::check(&cnf, &proof).is_err()
    });
    assert!(failed, "no clause of {} was needed", k2.clauses);
}

/// The certificate of "no 2-piece dissection" of a U into a bar (3 pieces
/// by brute force, tests/exact.rs) by cube-and-conquer on two threads,
/// the cubes' proofs going to `sink` when there is one.
fn cubed_u_to_bar(sink: Option<ProofSink>) -> Certificate {
    let figs = figures(LatticeKind::Square, &["#.#\n###", "#####"]);
    let options = ExactOptions {
        mode: Mode::LowerBound,
        max_pieces: Some(2),
        certify: true,
        cube_threads: 2,
        cube_proofs: sink,
        ..ExactOptions::default()
    };
    let collect = Collect(Mutex::new(Vec::new()), Mutex::new(Vec::new()));
    let out = search(
        &figs,
        &options,
        &AtomicBool::new(false),
        &AtomicUsize::new(usize::MAX),
        &collect,
    )
    .expect("search runs");
    assert_eq!(out.lower_bound.value, 3);
    let certs = collect.0.into_inner().unwrap();
    let k2 = certs
        .into_iter()
        .find(|c| c.pieces == 2)
        .expect("k2 certified");
    assert!(k2.cubes.len() >= 2, "{} cubes", k2.cubes.len());
    k2
}

/// Cube-and-conquer (two threads): the certificate is the base formula and
/// one proof per cube; the checker verifies it, and fails when a clause of
/// the base is removed (some clause), when a cube is missing, or when the
/// cover is no clause of the base.
#[test]
fn cube_and_conquer_certificates_verify_and_need_every_part() {
    let k2 = cubed_u_to_bar(None);
    assert!(k2.proof.is_empty());
    let base = dissect_proof::Cnf::parse(&k2.formula).expect("the base parses");
    assert_eq!(base.clauses().len(), k2.clauses);
    let cover: Vec<i32> = k2.cubes.iter().map(|c| c.literal).collect();
    let parts: Vec<(dissect_proof::Cnf, dissect_proof::Proof)> = k2
        .cubes
        .iter()
        .map(|c| {
            let cnf = dissect_proof::Cnf::parse(&c.formula).expect("a cube parses");
            assert_eq!(cnf.clauses()[0], vec![c.literal], "the unit first");
            let text = c.proof.as_deref().expect("kept in memory without a sink");
            assert_eq!(
                text.lines().filter(|l| !l.starts_with('d')).count(),
                c.lemmas
            );
            let proof = dissect_proof::Proof::parse(text).expect("a proof parses");
            (cnf, proof)
        })
        .collect();
    let verified = dissect_proof::check_cubes(&base, &cover, &parts).expect("verified");
    assert_eq!(verified.len(), cover.len());
    // A missing cube.
    assert!(matches!(
        dissect_proof::check_cubes(&base, &cover, &parts[1..]),
        Err((None, dissect_proof::ProofError::MissingCube { .. }))
    ));
    // A cover that is not a clause of the base.
    assert!(matches!(
        dissect_proof::check_cubes(&base, &cover[1..], &parts[1..]),
        Err((None, dissect_proof::ProofError::NotCovered { .. }))
    ));
    // A clause of the base removed: some removal breaks a cube's proof or
    // the cover.
    let failed = (0..k2.clauses).any(|drop| {
        let cnf = dissect_proof::Cnf::parse(&without_clause(&k2.formula, drop)).expect("parses");
        dissect_proof::check_cubes(&cnf, &cover, &parts).is_err()
    });
    assert!(failed, "no clause of {} was needed", k2.clauses);
    // The cover's own clause removed.
    let wanted = {
        let mut c = cover.clone();
        c.sort_unstable();
        c
    };
    let at = base
        .clauses()
        .iter()
        .position(|c| {
            let mut c = c.clone();
            c.sort_unstable();
            c == wanted
        })
        .expect("the cover is a clause");
    let cnf = dissect_proof::Cnf::parse(&without_clause(&k2.formula, at)).expect("parses");
    assert!(dissect_proof::check_cubes(&cnf, &cover, &parts).is_err());
}

/// The bytes written per (pieces, cube).
type Written = Arc<Mutex<BTreeMap<(usize, usize), Vec<u8>>>>;

/// Proof writers into shared buffers, by (pieces, cube).
#[derive(Default)]
struct Buffers(Written);

struct Into(Written, (usize, usize));

impl std::io::Write for Into {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        let mut all = self.0.lock().unwrap();
        all.get_mut(&self.1).expect("opened").extend_from_slice(buf);
        Ok(buf.len())
    }
    fn flush(&mut self) -> std::io::Result<()> {
        Ok(())
    }
}

impl CubeProofWriters for Buffers {
    fn open(&self, pieces: usize, cube: usize) -> Option<Box<dyn std::io::Write + Send>> {
        // A cube opened again starts afresh.
        self.0.lock().unwrap().insert((pieces, cube), Vec::new());
        Some(Box::new(Into(self.0.clone(), (pieces, cube))))
    }
}

/// Cube-and-conquer with a proof sink: no cube's proof is held in the
/// certificate, each went whole to its writer, and the streamed proofs
/// verify against the base and the cubes' clauses.
#[test]
fn cube_proofs_stream_to_their_writers_and_verify() {
    let buffers = Arc::new(Buffers::default());
    let k2 = cubed_u_to_bar(Some(ProofSink::new(buffers.clone())));
    let written = buffers.0.lock().unwrap();
    let base = dissect_proof::Cnf::parse(&k2.formula).expect("the base parses");
    let cover: Vec<i32> = k2.cubes.iter().map(|c| c.literal).collect();
    let parts: Vec<(dissect_proof::Cnf, dissect_proof::Proof)> = k2
        .cubes
        .iter()
        .enumerate()
        .map(|(j, c)| {
            assert!(c.proof.is_none(), "cube {j}: its proof went to the writer");
            let text = String::from_utf8(written[&(2, j)].clone()).expect("text DRAT");
            assert!(text.ends_with("0\n"), "cube {j}: ended by the empty clause");
            assert_eq!(
                text.lines().filter(|l| !l.starts_with('d')).count(),
                c.lemmas
            );
            let cnf = dissect_proof::Cnf::parse(&c.formula).expect("a cube parses");
            assert_eq!(cnf.clauses()[0], vec![c.literal], "the unit first");
            (
                cnf,
                dissect_proof::Proof::parse(&text).expect("a proof parses"),
            )
        })
        .collect();
    let verified = dissect_proof::check_cubes(&base, &cover, &parts).expect("verified");
    assert_eq!(verified.len(), cover.len());
    assert_eq!(
        k2.lemmas(),
        k2.cubes.iter().map(|c| c.lemmas).sum::<usize>()
    );
}
