//! `--certificate DIR` of `bound` and `solve`, and `dissect check-proof
//! DIR`: the certificates written verify; a formula or proof with a clause
//! removed fails; a corrupted file is bad input naming its file and line.

use std::path::Path;
use std::process::{Command, Output};

/// A 5×4 rectangle with a 2×2 hole: no 2-piece dissection into the 4×4
/// square (SAT refutes it).
const HOLE: &str = "#####\n#..##\n#..##\n#####\n";
const SQUARE_4: &str = "####\n####\n####\n####\n";

fn dissect(dir: &Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dissect"))
        .current_dir(dir)
        .args(args)
        .output()
        .expect("dissect runs")
}

fn text(o: &Output) -> String {
    format!(
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    )
}

fn setup() -> tempfile::TempDir {
    let dir = tempfile::tempdir().unwrap();
    std::fs::write(dir.path().join("a.txt"), HOLE).unwrap();
    std::fs::write(dir.path().join("b.txt"), SQUARE_4).unwrap();
    dir
}

/// `bound -q --max-pieces 2 --certificate cert a.txt b.txt` in `dir`.
fn certify_k2(dir: &Path) -> Output {
    dissect(
        dir,
        &[
            "bound",
            "-q",
            "--max-pieces",
            "2",
            "--certificate",
            "cert",
            "a.txt",
            "b.txt",
        ],
    )
}

#[test]
fn bound_writes_certificates_that_check_proof_verifies() {
    let dir = setup();
    let out = certify_k2(dir.path());
    assert!(out.status.success(), "{}", text(&out));
    assert!(
        text(&out).contains("certificates: k1, k2 in cert"),
        "{}",
        text(&out)
    );
    let cert = dir.path().join("cert");
    let readme = std::fs::read_to_string(cert.join("README.txt")).unwrap();
    assert!(
        readme.contains("k2.cnf, k2.drat: no dissection into at most 2 pieces"),
        "{readme}"
    );
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert!(out.status.success(), "{}", text(&out));
    let last = String::from_utf8_lossy(&out.stdout)
        .lines()
        .last()
        .unwrap_or("")
        .to_string();
    assert_eq!(last, "verified: 2 certificates (k1, k2)");

    // The proof of k2 without its lemmas (the empty clause alone) fails.
    std::fs::write(cert.join("k2.drat"), "0\n").unwrap();
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(text(&out).contains("k2: FAILED"), "{}", text(&out));
    assert!(
        text(&out).contains("k2.drat: proof line 1"),
        "{}",
        text(&out)
    );
}

/// A proof read from a named pipe as it is written (the way to check a
/// proof too large to store: the solver writes into the pipe): verified as
/// the same proof from a file is.
#[cfg(unix)]
#[test]
fn check_proof_reads_a_proof_from_a_named_pipe() {
    let dir = setup();
    let out = certify_k2(dir.path());
    assert!(out.status.success(), "{}", text(&out));
    let cert = dir.path().join("cert");
    let piped = dir.path().join("piped");
    std::fs::create_dir(&piped).unwrap();
    std::fs::copy(cert.join("k2.cnf"), piped.join("k2.cnf")).unwrap();
    let fifo = piped.join("k2.drat");
    let made = Command::new("mkfifo")
        .arg(&fifo)
        .status()
        .expect("mkfifo runs");
    assert!(made.success());
    let proof = std::fs::read(cert.join("k2.drat")).unwrap();
    // The writer blocks until check-proof opens the pipe for reading.
    let writer = std::thread::spawn(move || std::fs::write(fifo, proof).unwrap());
    let out = dissect(dir.path(), &["check-proof", "piped"]);
    // Asserted before the join: a check that never opened the pipe leaves
    // the writer blocked, and the failing test must not wait for it.
    assert!(out.status.success(), "{}", text(&out));
    writer.join().unwrap();
    assert!(
        String::from_utf8_lossy(&out.stdout).ends_with("verified: 1 certificate (k2)\n"),
        "{}",
        text(&out)
    );
}

#[test]
fn a_formula_with_clauses_removed_fails_and_corruption_names_file_and_line() {
    let dir = setup();
    let out = dissect(
        dir.path(),
        &[
            "solve",
            "--exact",
            "-q",
            "--certificate",
            "cert",
            "a.txt",
            "b.txt",
        ],
    );
    assert!(out.status.success(), "{}", text(&out));
    let cert = dir.path().join("cert");
    let cnf = std::fs::read_to_string(cert.join("k2.cnf")).expect("k2 certified");
    let proof = std::fs::read_to_string(cert.join("k2.drat")).expect("k2's proof");
    assert!(dissect(dir.path(), &["check-proof", "cert"])
        .status
        .success());

    // Keep the header true but drop the clauses that place each cell in
    // some piece: the formula is satisfiable and no proof can refute it.
    let mut lines: Vec<String> = cnf.lines().map(String::from).collect();
    let keep: Vec<String> = lines[1..]
        .iter()
        .filter(|l| l.split_whitespace().any(|t| t.starts_with('-')))
        .cloned()
        .collect();
    let header: Vec<&str> = lines[0].split_whitespace().collect();
    lines = vec![format!("p cnf {} {}", header[2], keep.len())];
    lines.extend(keep);
    std::fs::write(cert.join("k2.cnf"), lines.join("\n") + "\n").unwrap();
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(text(&out).contains("k2: FAILED"), "{}", text(&out));

    // A corrupted proof: bad input, the file and line named.
    std::fs::write(cert.join("k2.cnf"), &cnf).unwrap();
    std::fs::write(cert.join("k2.drat"), "1 2 0\n3 x 0\n0\n").unwrap();
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(
        text(&out).contains("k2.drat: proof line 2: `x` is not a literal"),
        "{}",
        text(&out)
    );
    // The proof is read a line at a time: a malformed line after the
    // refutation is still bad input, and a binary (not text) proof too.
    std::fs::write(cert.join("k2.drat"), format!("{proof}1 2\n")).unwrap();
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(text(&out).contains("not ended by 0"), "{}", text(&out));
    std::fs::write(cert.join("k2.drat"), b"a\x82\x01\x00").unwrap();
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(text(&out).contains("k2.drat: not text"), "{}", text(&out));
    // A missing proof, and a folder without certificates.
    std::fs::remove_file(cert.join("k2.drat")).unwrap();
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(
        text(&out).contains("no proof beside k2.cnf"),
        "{}",
        text(&out)
    );
    let out = dissect(dir.path(), &["check-proof", "."]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
}

/// `bound --threads 2`: cube-and-conquer writes kK.cnf (the base), kK.cubes
/// (the cover) and one formula and proof per cube; `check-proof` verifies
/// them, and fails (exit 1) when a cube is missing, when the base loses a
/// clause, or when a cube's proof is emptied.
#[test]
fn cubed_certificates_verify_and_fail_without_a_cube_or_a_clause() {
    let dir = setup();
    let out = dissect(
        dir.path(),
        &[
            "bound",
            "-q",
            "--threads",
            "2",
            "--max-pieces",
            "2",
            "--certificate",
            "cert",
            "a.txt",
            "b.txt",
        ],
    );
    assert!(out.status.success(), "{}", text(&out));
    let cert = dir.path().join("cert");
    let cover = std::fs::read_to_string(cert.join("k2.cubes")).expect("k2 cubed");
    let cubes = cover
        .lines()
        .find(|l| !l.starts_with('c'))
        .expect("the cover")
        .split_whitespace()
        .count()
        - 1;
    assert!(cubes >= 2, "{cover}");
    assert!(cert.join(format!("k2.cube{}.drat", cubes - 1)).is_file());
    assert!(!cert.join("k2.drat").exists());
    // The cubes' proofs went to files in k2.work as the solvers wrote
    // them, and came out of it with the certificate.
    let left: Vec<String> = std::fs::read_dir(&cert)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.ends_with(".part") || n.ends_with(".work"))
        .collect();
    assert!(left.is_empty(), "{left:?}");
    let readme = std::fs::read_to_string(cert.join("README.txt")).unwrap();
    assert!(readme.contains("by cube-and-conquer"), "{readme}");
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(
        text(&out).contains("k2: verified: no dissection into at most 2 pieces"),
        "{}",
        text(&out)
    );
    assert!(
        text(&out).contains(&format!("{cubes} cubes")),
        "{}",
        text(&out)
    );

    // A cube missing.
    let last = cert.join(format!("k2.cube{}.cnf", cubes - 1));
    let kept = std::fs::read(&last).unwrap();
    std::fs::remove_file(&last).unwrap();
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(text(&out).contains("k2: FAILED"), "{}", text(&out));
    assert!(
        text(&out).contains(&format!("{} cubes for the {cubes} literals", cubes - 1)),
        "{}",
        text(&out)
    );
    std::fs::write(&last, kept).unwrap();

    // The base without the cover's clause.
    let cnf = std::fs::read_to_string(cert.join("k2.cnf")).unwrap();
    let mut wanted: Vec<i32> = cover
        .lines()
        .find(|l| !l.starts_with('c'))
        .unwrap()
        .split_whitespace()
        .map(|t| t.parse().unwrap())
        .filter(|&l| l != 0)
        .collect();
    wanted.sort_unstable();
    let mut lines: Vec<String> = cnf.lines().map(String::from).collect();
    let header: Vec<String> = lines[0].split_whitespace().map(String::from).collect();
    lines.retain(|l| {
        let mut c: Vec<i32> = l
            .split_whitespace()
            .filter_map(|t| t.parse().ok())
            .filter(|&x| x != 0)
            .collect();
        c.sort_unstable();
        c != wanted
    });
    let count: usize = header[3].parse::<usize>().unwrap() - 1;
    lines[0] = format!("p cnf {} {count}", header[2]);
    std::fs::write(cert.join("k2.cnf"), lines.join("\n") + "\n").unwrap();
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        text(&out).contains("are not a clause of the base formula"),
        "{}",
        text(&out)
    );
    std::fs::write(cert.join("k2.cnf"), &cnf).unwrap();

    // A cube without its unit (its first clause): it may not stand for
    // its literal.
    let first = cert.join("k2.cube0.cnf");
    let kept = std::fs::read_to_string(&first).unwrap();
    let mut lines: Vec<&str> = kept.lines().collect();
    let header: Vec<&str> = lines[0].split_whitespace().collect();
    let count: usize = header[3].parse::<usize>().unwrap() - 1;
    let new_header = format!("p cnf {} {count}", header[2]);
    lines.remove(1);
    lines[0] = &new_header;
    std::fs::write(&first, lines.join("\n") + "\n").unwrap();
    let out = dissect(dir.path(), &["check-proof", "cert"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        text(&out).contains("k2.cube0.cnf: the cube of literal"),
        "{}",
        text(&out)
    );
}
