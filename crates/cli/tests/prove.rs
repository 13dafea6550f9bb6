//! End-to-end tests of the exact mode: `dissect bound`, `dissect solve
//! --exact` and `dissect solve --prove`. Every solution written is checked by
//! `dissect verify`, by `tools/check_solution.py` and, when present, by the
//! external `verify.py`.

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

const SQUARES_3_4: &str = "####..###\n####..###\n####..###\n####.....\n";
const SQUARE_5: &str = "#####\n#####\n#####\n#####\n#####\n";
/// A rectangle with a hole: no 2-piece dissection into the 4x4 square.
const HOLE: &str = "#####\n#..##\n#..##\n#####\n";
const SQUARE_4: &str = "####\n####\n####\n####\n";

fn dissect(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dissect"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("dissect runs")
}

fn stdout(o: &Output) -> String {
    String::from_utf8_lossy(&o.stdout).into_owned()
}

fn files(dir: &Path, figures: &[(&str, &str)]) {
    for (name, text) in figures {
        std::fs::write(dir.join(name), text).unwrap();
    }
}

fn golden(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/golden")
        .join(name)
}

/// Compares with a golden file; `UPDATE_GOLDEN=1` rewrites it.
fn check_golden(name: &str, actual: &str) {
    let path = golden(name);
    if std::env::var_os("UPDATE_GOLDEN").is_some() {
        std::fs::write(&path, actual).unwrap();
    }
    let expected = std::fs::read_to_string(&path).expect("golden file exists");
    assert_eq!(actual, expected, "differs from {}", path.display());
}

/// The independent checkers: `tools/check_solution.py` always, the
/// external `verify.py` when present.
fn python_verify(dir: &Path, lattice: &str, solution: &str, figures: &[&str]) {
    dissect_testkit::repo::assert_checked(dir, lattice, solution, figures);
}

#[test]
fn bound_prints_the_corner_argument_last() {
    let dir = tempfile::tempdir().unwrap();
    files(dir.path(), &[("a.txt", SQUARES_3_4), ("b.txt", SQUARE_5)]);
    let out = dissect(dir.path(), &["bound", "--quiet", "a.txt", "b.txt"]);
    assert!(out.status.success());
    check_golden("bound-squares-3-4.txt", &stdout(&out));
}

#[test]
fn bound_refutes_two_pieces_by_sat() {
    let dir = tempfile::tempdir().unwrap();
    files(dir.path(), &[("a.txt", HOLE), ("b.txt", SQUARE_4)]);
    let out = dissect(
        dir.path(),
        &["bound", "--max-pieces", "2", "a.txt", "b.txt"],
    );
    assert!(out.status.success());
    let text = stdout(&out);
    let last = text.lines().last().unwrap();
    assert!(
        last.starts_with("lower bound: 3 (SAT: no 2-piece dissection, "),
        "{text}"
    );
    // The progress went to stderr.
    assert!(String::from_utf8_lossy(&out.stderr).contains("cheap bound: 2"));
}

#[test]
fn bound_writes_the_dimacs_of_k_pieces() {
    let dir = tempfile::tempdir().unwrap();
    files(dir.path(), &[("a.txt", HOLE), ("b.txt", SQUARE_4)]);
    // `bound --max-pieces 2 --dimacs FILE` with `more` flags.
    let write = |file: &str, more: &[&str]| {
        let mut args = vec!["bound", "--max-pieces", "2", "--dimacs", file];
        args.extend(more);
        args.extend(["a.txt", "b.txt"]);
        dissect(dir.path(), &args)
    };
    let out = write("k2.cnf", &[]);
    assert!(out.status.success());
    assert!(stdout(&out).starts_with("wrote k2.cnf: at most 2 pieces, "));
    let cnf = std::fs::read_to_string(dir.path().join("k2.cnf")).unwrap();
    let header: Vec<&str> = cnf.lines().next().unwrap().split_whitespace().collect();
    assert_eq!(header[..2], ["p", "cnf"]);
    let clauses: usize = header[3].parse().unwrap();
    assert_eq!(cnf.lines().count(), clauses + 1);
    // --dimacs needs the K of --max-pieces.
    let out = dissect(
        dir.path(),
        &["bound", "--dimacs", "k.cnf", "a.txt", "b.txt"],
    );
    assert!(!out.status.success());
    // --connected adds the connectivity encoding: the same clauses first,
    // then more; it needs --dimacs.
    let out = write("k2c.cnf", &["--connected"]);
    assert!(out.status.success());
    assert!(stdout(&out).starts_with("wrote k2c.cnf: at most 2 connected pieces, "));
    let connected = std::fs::read_to_string(dir.path().join("k2c.cnf")).unwrap();
    let body = |t: &str| t.lines().skip(1).map(String::from).collect::<Vec<_>>();
    let (relaxed, full) = (body(&cnf), body(&connected));
    assert!(full.len() > relaxed.len());
    assert_eq!(full[..relaxed.len()], relaxed[..]);
    let out = dissect(
        dir.path(),
        &[
            "bound",
            "--max-pieces",
            "2",
            "--connected",
            "a.txt",
            "b.txt",
        ],
    );
    assert!(!out.status.success());
    // A formula estimated past --max-encoding-mib is refused before it is
    // built, naming the cap; the default (512 MiB) builds it.
    files(dir.path(), &[("c.txt", SQUARES_3_4), ("d.txt", SQUARE_5)]);
    let large = |more: &[&str]| {
        let mut args = vec!["bound", "--max-pieces", "25", "--dimacs", "k25.cnf"];
        args.extend_from_slice(more);
        args.extend_from_slice(&["c.txt", "d.txt"]);
        dissect(dir.path(), &args)
    };
    let out = large(&["--max-encoding-mib", "1"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("over the cap of 1 MiB"), "{err}");
    assert!(!dir.path().join("k25.cnf").exists());
    assert!(large(&[]).status.success());
}

#[test]
fn exact_solve_writes_an_optimal_verified_solution() {
    let dir = tempfile::tempdir().unwrap();
    files(dir.path(), &[("a.txt", SQUARES_3_4), ("b.txt", SQUARE_5)]);
    let out = dissect(
        dir.path(),
        &[
            "solve", "--exact", "--color", "never", "a.txt", "b.txt", "-o", "s.json",
        ],
    );
    assert!(out.status.success());
    let text = stdout(&out);
    assert!(
        text.lines()
            .last()
            .unwrap()
            .starts_with("4 pieces — optimal (4 cells of b.txt"),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("s.json")).unwrap()).unwrap();
    assert_eq!(json["lower_bound"], 4);
    assert_eq!(json["optimal"], true);
    let v = dissect(
        dir.path(),
        &["verify", "--solution", "s.json", "a.txt", "b.txt"],
    );
    assert!(v.status.success(), "{}", stdout(&v));
    python_verify(dir.path(), "square", "s.json", &["a.txt", "b.txt"]);
}

#[test]
fn exact_solve_on_tri4_and_cubic() {
    let dir = tempfile::tempdir().unwrap();
    files(
        dir.path(),
        &[
            ("t.txt", "FF\n"),
            ("d.txt", "6C\n39\n"),
            ("c.txt", "##\n##\n\n##\n##\n"),
            ("r.txt", "####\n####\n"),
        ],
    );
    for (lattice, a, b) in [("tri4", "t.txt", "d.txt"), ("cubic", "c.txt", "r.txt")] {
        let out = dissect(
            dir.path(),
            &[
                "solve",
                "--exact",
                "--quiet",
                "--lattice",
                lattice,
                a,
                b,
                "-o",
                "s.json",
            ],
        );
        assert!(out.status.success(), "{lattice}");
        assert!(stdout(&out).contains("optimal"), "{}", stdout(&out));
        python_verify(dir.path(), lattice, "s.json", &[a, b]);
    }
}

#[test]
fn prove_runs_the_heuristic_beside_the_proof() {
    let dir = tempfile::tempdir().unwrap();
    files(dir.path(), &[("a.txt", HOLE), ("b.txt", SQUARE_4)]);
    let out = dissect(
        dir.path(),
        &[
            "solve",
            "--prove",
            "--quiet",
            "--time-limit",
            "60",
            "a.txt",
            "b.txt",
            "-o",
            "s.json",
        ],
    );
    assert!(out.status.success());
    let text = stdout(&out);
    assert!(
        text.starts_with("3 pieces — optimal (no 2-piece dissection exists; proof "),
        "{text}"
    );
    let json: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(dir.path().join("s.json")).unwrap()).unwrap();
    assert_eq!(json["optimal"], true);
    assert_eq!(json["lower_bound"], 3);
    python_verify(dir.path(), "square", "s.json", &["a.txt", "b.txt"]);
}

#[test]
fn bound_names_the_file_on_bad_input() {
    let dir = tempfile::tempdir().unwrap();
    files(dir.path(), &[("a.txt", "###\n"), ("b.txt", "#x\n")]);
    let out = dissect(dir.path(), &["bound", "a.txt", "b.txt"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("b.txt") && err.contains("column"), "{err}");
    files(dir.path(), &[("b.txt", "##\n")]);
    let out = dissect(dir.path(), &["bound", "a.txt", "b.txt"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("different areas"));
}

/// `bound --model FILE`: another solver's model of the `--dimacs
/// --connected` formula becomes the dissection it stands for, verified and
/// written; a malformed or wrong model is bad input naming the file. The
/// round trip needs a solver on the PATH (CI installs cadical).
#[test]
fn bound_turns_another_solvers_model_into_a_verified_dissection() {
    let dir = tempfile::tempdir().unwrap();
    files(dir.path(), &[("a.txt", SQUARES_3_4), ("b.txt", SQUARE_5)]);
    let decode = |model: &str| {
        dissect(
            dir.path(),
            &[
                "bound",
                "--max-pieces",
                "4",
                "--model",
                model,
                "-o",
                "s.json",
                "a.txt",
                "b.txt",
            ],
        )
    };
    std::fs::write(dir.path().join("bad.txt"), "s SATISFIABLE\nv 1 -2 x 0\n").unwrap();
    let out = decode("bad.txt");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("bad.txt line 2: `x` is not a literal"),
        "{err}"
    );
    std::fs::write(dir.path().join("none.txt"), "v 0\n").unwrap();
    let out = decode("none.txt");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("none.txt: the model is no dissection"),
        "{err}"
    );
    std::fs::write(dir.path().join("unsat.txt"), "c cadical\ns UNSATISFIABLE\n").unwrap();
    let out = decode("unsat.txt");
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("unsat.txt line 2: the solver answered UNSATISFIABLE"),
        "{err}"
    );
    assert!(!dir.path().join("s.json").exists());

    let Ok(solver) = Command::new("cadical").arg("--version").output() else {
        eprintln!("no cadical on the PATH: the round trip is not run");
        return;
    };
    assert!(solver.status.success());
    let out = dissect(
        dir.path(),
        &[
            "bound",
            "--max-pieces",
            "4",
            "--dimacs",
            "k4.cnf",
            "--connected",
            "a.txt",
            "b.txt",
        ],
    );
    assert!(out.status.success());
    let answer = Command::new("cadical")
        .current_dir(dir.path())
        .args(["-q", "k4.cnf"])
        .output()
        .unwrap();
    assert_eq!(
        answer.status.code(),
        Some(10),
        "satisfiable: 4 pieces exist"
    );
    std::fs::write(dir.path().join("model.txt"), &answer.stdout).unwrap();
    let out = decode("model.txt");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        stdout(&out).contains("is a verified dissection into 4 pieces"),
        "{}",
        stdout(&out)
    );
    assert_eq!(
        dissect_testkit::repo::assert_checked(dir.path(), "square", "s.json", &["a.txt", "b.txt"]),
        4
    );
}

/// `bound --solver CMD`: another solver answers each K from the cheap
/// bound up. Its refutation and proof stay in --certificate DIR, which
/// `check-proof` verifies; its model becomes the -o dissection, verified.
/// The solver here is CaDiCaL when on the PATH (CI installs it); the
/// answers of stand-in scripts run everywhere: a solver that cannot run, a
/// claimed UNSAT without a proof, a bogus proof that check-proof rejects,
/// and one that never answers, stopped by the time limit with nothing left
/// behind.
#[test]
fn bound_asks_another_solver_and_keeps_its_certificates() {
    let dir = tempfile::tempdir().unwrap();
    files(dir.path(), &[("a.txt", HOLE), ("b.txt", SQUARE_4)]);
    let bound = |solver: &str, more: &[&str]| {
        let mut args = vec!["bound", "--solver", solver];
        args.extend_from_slice(more);
        args.extend_from_slice(&["a.txt", "b.txt"]);
        dissect(dir.path(), &args)
    };
    let out = bound("no-such-solver-anywhere", &[]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("cannot run `no-such-solver-anywhere`"),
        "{err}"
    );

    std::fs::write(dir.path().join("liar.sh"), "echo 's UNSATISFIABLE'\n").unwrap();
    let out = bound("sh liar.sh", &["--certificate", "liar"]);
    assert_eq!(out.status.code(), Some(2));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("answered UNSATISFIABLE but wrote no proof"),
        "{err}"
    );
    assert!(!dir.path().join("liar/k2.cnf").exists());

    // A proof that proves nothing: kept, but check-proof says so.
    std::fs::write(
        dir.path().join("empty.sh"),
        "echo 's UNSATISFIABLE'\n: > \"$2\"\n",
    )
    .unwrap();
    let out = bound(
        "sh empty.sh",
        &["--certificate", "empty", "--max-pieces", "2"],
    );
    assert!(out.status.success());
    assert!(stdout(&out).contains("lower bound: 3 (sh: no 2-piece dissection"));
    let check = dissect(dir.path(), &["check-proof", "empty"]);
    assert_eq!(check.status.code(), Some(1), "{}", stdout(&check));

    std::fs::write(dir.path().join("slow.sh"), "sleep 30\n").unwrap();
    let started = std::time::Instant::now();
    let out = bound(
        "sh slow.sh",
        &["--certificate", "slow", "--time-limit", "1"],
    );
    assert!(out.status.success());
    assert!(started.elapsed().as_secs_f64() < 10.0);
    assert!(stdout(&out).contains("stopped (time limit or Ctrl-C)"));
    let left: Vec<_> = std::fs::read_dir(dir.path().join("slow"))
        .unwrap()
        .collect();
    assert!(left.is_empty(), "{left:?}");

    if Command::new("cadical").arg("--version").output().is_err() {
        eprintln!("no cadical on the PATH: the real solver is not run");
        return;
    }
    let out = bound(
        "cadical --no-binary",
        &["--certificate", "cert", "-o", "s.json"],
    );
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let text = stdout(&out);
    assert!(text.contains("certificates: k2 in cert"), "{text}");
    assert!(text.contains("a 3-piece dissection exists"), "{text}");
    assert!(
        text.contains("lower bound: 3 (cadical: no 2-piece dissection, "),
        "{text}"
    );
    let readme = std::fs::read_to_string(dir.path().join("cert/README.txt")).unwrap();
    assert!(readme.contains("k2.drat  cadical's DRAT proof"), "{readme}");
    assert!(!dir.path().join("cert/k3.cnf").exists());
    let check = dissect(dir.path(), &["check-proof", "cert"]);
    assert!(check.status.success(), "{}", stdout(&check));
    assert!(stdout(&check).contains("k2: verified"));
    python_verify(dir.path(), "square", "s.json", &["a.txt", "b.txt"]);
}
