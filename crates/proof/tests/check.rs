//! The checker against formulas small enough to decide by brute force:
//! every proof it accepts is of an unsatisfiable formula, a complete proof
//! of any unsatisfiable formula is accepted, and a proof or formula with a
//! clause removed, or a corrupted text, is rejected with its line.

use dissect_proof::{Checker, Cnf, Proof, ProofError, ProofStream, Source, Verified};

fn cnf(text: &str) -> Cnf {
    Cnf::parse(text).expect("a formula")
}

/// A proof, parsed whole, and its text.
struct Text(Proof, String);

fn proof(text: &str) -> Text {
    Text(Proof::parse(text).expect("a proof"), text.to_string())
}

/// `dissect_proof::check` on the whole proof, asserting that the proof
/// read a line at a time (`ProofStream` into a `Checker`) gives the same
/// answer.
fn check(f: &Cnf, p: &Text) -> Result<Verified, ProofError> {
    let whole = dissect_proof::check(f, &p.0);
    assert_eq!(streamed(f, &p.1), whole, "streamed: {:?}", p.1);
    whole
}

/// The proof `text` checked against `f` a line at a time.
fn streamed(f: &Cnf, text: &str) -> Result<Verified, ProofError> {
    let mut checker = Checker::new(f);
    let mut stream = ProofStream::new();
    let mut done = false;
    for line in text.lines() {
        stream.line(line, &mut |at, step| {
            if !done {
                done = checker.step(at, &step)?;
            }
            Ok(())
        })?;
    }
    let last = stream.end()?;
    checker.finish(last)
}

/// The four clauses over two variables: unsatisfiable.
const FOUR: &str = "p cnf 2 4\n1 2 0\n1 -2 0\n-1 2 0\n-1 -2 0\n";

#[test]
fn a_valid_rup_proof_verifies() {
    let v = check(&cnf(FOUR), &proof("1 0\n0\n")).expect("verified");
    assert_eq!(
        v.lemmas, 1,
        "the unit 1 makes the formula propagate to a conflict"
    );
    assert_eq!(v.refuted_at_line, 1);
}

#[test]
fn a_formula_with_a_clause_removed_fails_at_the_lemma_that_needed_it() {
    let weaker = "p cnf 2 3\n1 2 0\n1 -2 0\n-1 2 0\n";
    let e = check(&cnf(weaker), &proof("1 0\n0\n")).unwrap_err();
    assert!(
        matches!(
            e,
            ProofError::NotImplied {
                line: 2,
                step: 2,
                ..
            }
        ),
        "{e}"
    );
    assert_eq!(e.location(), (Source::Proof, 2));
}

#[test]
fn a_proof_with_a_lemma_removed_fails() {
    // 1 ∨ 2, both imply 3, and 3 implies 4 and ¬4: unsatisfiable, but
    // nothing propagates until 3 is known.
    let f = cnf("p cnf 4 5\n1 2 0\n-1 3 0\n-2 3 0\n-3 4 0\n-3 -4 0\n");
    let v = check(&f, &proof("3 0\n0\n")).expect("the full proof verifies");
    assert_eq!((v.lemmas, v.rat_lemmas), (1, 0));
    let e = check(&f, &proof("0\n")).unwrap_err();
    assert!(matches!(e, ProofError::NotImplied { line: 1, .. }), "{e}");
    let e = check(&f, &proof("")).unwrap_err();
    assert!(matches!(e, ProofError::Incomplete { .. }), "{e}");
}

#[test]
fn rat_lemmas_on_a_fresh_variable_are_accepted_and_others_refused() {
    // 3 ∨ 1 is RAT on 3 (nothing holds ¬3); 3 is then no RUP.
    let f = cnf("p cnf 3 2\n1 2 0\n-1 2 0\n");
    let v = check(&f, &proof("3 1 0\n-2 0\n0\n"));
    // -2 is neither RUP nor RAT (2 is implied): rejected.
    assert!(
        matches!(v, Err(ProofError::NotImplied { line: 2, .. })),
        "{v:?}"
    );
    let f = cnf("p cnf 3 3\n1 2 0\n-1 2 0\n-2 0\n");
    let v = check(&f, &proof("3 1 0\n0\n")).expect("verified");
    assert_eq!(v.lemmas, 0, "the formula alone propagates to a conflict");
    // A RAT lemma whose resolvent is no RUP: 1 ∨ 3 against ¬1 ∨ 2 gives 3 ∨ 2.
    let f = cnf("p cnf 3 2\n-1 2 0\n-2 -3 0\n");
    let e = check(&f, &proof("1 3 0\n0\n")).unwrap_err();
    assert!(matches!(e, ProofError::NotImplied { line: 1, .. }), "{e}");
    let v = check(&cnf("p cnf 2 1\n1 0\n"), &proof("2 0\n")).unwrap_err();
    assert!(matches!(v, ProofError::Incomplete { .. }), "{v}");
    let f = cnf("p cnf 2 2\n1 2 0\n-1 2 0\n");
    let v = check(&f, &proof("-2 1 0\n")).unwrap_err();
    assert!(matches!(v, ProofError::NotImplied { line: 1, .. }), "{v}");
}

#[test]
fn deletions_are_honoured_and_deleted_units_propagate_no_more() {
    let f = cnf(FOUR);
    // Deleting a clause the next lemma needs makes it fail.
    let e = check(&f, &proof("d -1 -2 0\n1 0\n0\n")).unwrap_err();
    assert!(matches!(e, ProofError::NotImplied { line: 3, .. }), "{e}");
    // A derived unit, deleted: its consequences are gone.
    let f = cnf("p cnf 3 4\n1 2 0\n1 -2 0\n-1 3 0\n-1 -3 2 0\n");
    let e = check(&f, &proof("1 0\nd 1 0\n-2 0\n0\n")).unwrap_err();
    assert!(matches!(e, ProofError::NotImplied { line: 3, .. }), "{e}");
    // A binary clause that implied its second literal, deleted: that
    // literal is free again, so its negation (a RAT: no clause present
    // holds the literal) refutes nothing, and the empty clause fails.
    let f = cnf("p cnf 2 2\n-1 2 0\n1 0\n");
    let e = check(&f, &proof("d -1 2 0\n-2 0\n0\n")).unwrap_err();
    assert!(matches!(e, ProofError::NotImplied { line: 3, .. }), "{e}");
    // Deleting a clause that is not there is ignored and counted.
    let v = check(&cnf(FOUR), &proof("d 1 2 3 0\n1 0\n0\n")).expect("verified");
    assert_eq!(v.missing_deletions, 1);
}

#[test]
fn corrupted_texts_are_errors_that_name_the_line() {
    let cases: [(&str, &str, Source, usize); 6] = [
        (
            "p cnf 2 4\n1 2 0\n1 x 0\n-1 2 0\n-1 -2 0\n",
            "1 0\n",
            Source::Formula,
            3,
        ),
        ("p cnf 2 5\n1 2 0\n", "0\n", Source::Formula, 1),
        ("1 2 0\np cnf 2 1\n", "0\n", Source::Formula, 1),
        ("p cnf 2 1\n1 3 0\n", "0\n", Source::Formula, 2),
        (FOUR, "1 0\n0\n1 2\n", Source::Proof, 3),
        (FOUR, "c a comment\n1 0\n-1 d 2 0\n", Source::Proof, 3),
    ];
    for (formula, text, source, line) in cases {
        let e = Cnf::parse(formula)
            .and_then(|f| Proof::parse(text).map(|p| (f, p)))
            .and_then(|(f, p)| dissect_proof::check(&f, &p).map(|_| ()))
            .unwrap_err();
        if let Ok(f) = Cnf::parse(formula) {
            assert_eq!(streamed(&f, text).map(|_| ()), Err(e.clone()), "streamed");
        }
        assert!(matches!(e, ProofError::Parse { .. }), "{e}");
        assert_eq!(e.location(), (source, line), "{formula:?} / {text:?}: {e}");
        assert!(e.to_string().contains(&format!("line {line}")), "{e}");
    }
}

/// A small random generator (xorshift), so the test needs no crate.
struct Rng(u64);

impl Rng {
    fn below(&mut self, n: u64) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0 % n
    }
}

fn satisfiable(vars: u32, clauses: &[Vec<i32>]) -> bool {
    (0..1u32 << vars).any(|m| {
        clauses.iter().all(|c| {
            c.iter()
                .any(|&l| (m >> (l.unsigned_abs() - 1) & 1 == 1) == (l > 0))
        })
    })
}

fn text(vars: u32, clauses: &[Vec<i32>]) -> String {
    let mut s = format!("p cnf {vars} {}\n", clauses.len());
    for c in clauses {
        for l in c {
            s.push_str(&format!("{l} "));
        }
        s.push_str("0\n");
    }
    s
}

/// Every clause over all `vars` variables, then every clause over the
/// first `vars - 1`, ..., then the empty clause: a proof of any
/// unsatisfiable formula over `vars` variables.
fn exhaustive_proof(vars: u32) -> String {
    let mut s = String::new();
    for n in (0..=vars).rev() {
        for m in 0..1u32 << n {
            for v in 1..=n as i32 {
                let l = if m >> (v - 1) & 1 == 1 { -v } else { v };
                s.push_str(&format!("{l} "));
            }
            s.push_str("0\n");
        }
    }
    s
}

#[test]
fn accepted_proofs_are_of_unsatisfiable_formulas_only() {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let (mut accepted, mut unsat) = (0, 0);
    for _ in 0..400 {
        let vars = 2 + rng.below(4) as u32;
        let count = 2 + rng.below(14) as usize;
        let random_clause = |rng: &mut Rng| -> Vec<i32> {
            (0..1 + rng.below(3))
                .map(|_| {
                    let v = 1 + rng.below(u64::from(vars)) as i32;
                    if rng.below(2) == 0 {
                        v
                    } else {
                        -v
                    }
                })
                .collect()
        };
        let clauses: Vec<Vec<i32>> = (0..count).map(|_| random_clause(&mut rng)).collect();
        let f = cnf(&text(vars, &clauses));
        let sat = satisfiable(vars, &clauses);
        // A random proof: accepted only when the formula is unsatisfiable.
        let mut p = String::new();
        for _ in 0..rng.below(6) {
            let c = random_clause(&mut rng);
            if rng.below(4) == 0 {
                p.push_str("d ");
            }
            for l in c {
                p.push_str(&format!("{l} "));
            }
            p.push_str("0\n");
        }
        p.push_str("0\n");
        if check(&f, &proof(&p)).is_ok() {
            accepted += 1;
            assert!(
                !sat,
                "accepted a proof of a satisfiable formula:\n{}\n{p}",
                text(vars, &clauses)
            );
        }
        // The exhaustive proof: accepted exactly when unsatisfiable.
        let full = check(&f, &proof(&exhaustive_proof(vars)));
        assert_eq!(full.is_ok(), !sat, "{}: {full:?}", text(vars, &clauses));
        unsat += usize::from(!sat);
    }
    assert!(
        accepted > 10 && unsat > 50,
        "{accepted} accepted, {unsat} unsatisfiable"
    );
}

/// Cube-and-conquer: `(1 ∨ 2)` is a clause of the base, each literal's
/// cube is refuted; the checker accepts it and refuses a missing cube, a
/// cover that is no clause of the base, a cube without its unit, a cube
/// whose proof fails, and a malformed cover.
#[test]
fn cubes_cover_the_base_and_each_is_refuted() {
    use dissect_proof::{check_cubes, parse_cover, Cnf, Proof, ProofError};
    let base = Cnf::parse("p cnf 3 4\n1 2 0\n-1 3 0\n-2 3 0\n-3 1 2 0\n").unwrap();
    let cover = parse_cover("c the cubes\n1 2 0\n").unwrap();
    assert_eq!(cover, vec![1, 2]);
    // Cube 1 needs `-3` to conflict: its formula adds it with the unit.
    let cube = |text: &str| Cnf::parse(text).unwrap();
    let empty = Proof::parse("0\n").unwrap();
    let ok = vec![
        (cube("p cnf 3 2\n1 0\n-3 0\n"), empty.clone()),
        (cube("p cnf 3 2\n2 0\n-3 0\n"), empty.clone()),
    ];
    assert_eq!(check_cubes(&base, &cover, &ok).unwrap().len(), 2);
    assert!(matches!(
        check_cubes(&base, &cover, &ok[..1]),
        Err((
            None,
            ProofError::MissingCube {
                cubes: 1,
                literals: 2
            }
        ))
    ));
    assert!(matches!(
        check_cubes(&base, &[1, 3], &ok),
        Err((None, ProofError::NotCovered { .. }))
    ));
    let no_unit = vec![ok[0].clone(), (cube("p cnf 3 1\n-3 0\n"), empty.clone())];
    assert!(matches!(
        check_cubes(&base, &cover, &no_unit),
        Err((Some(1), ProofError::NoUnit { literal: 2 }))
    ));
    // Without `-3` cube 1 is satisfiable (2, 3): no proof refutes it.
    let satisfiable = vec![ok[0].clone(), (cube("p cnf 3 1\n2 0\n"), empty)];
    assert!(matches!(
        check_cubes(&base, &cover, &satisfiable),
        Err((Some(1), ProofError::NotImplied { .. }))
    ));
    assert!(parse_cover("1 2\n").is_err(), "not ended by 0");
    assert!(parse_cover("1 0\n2 0\n").is_err(), "two clauses");
    assert!(parse_cover("0\n").is_err(), "empty");
    assert!(parse_cover("1 x 0\n").is_err(), "not a literal");
}
