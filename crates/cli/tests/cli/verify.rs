//! `dissect verify`: accepts a valid solution, rejects a tampered one with
//! exit code 1 and the reason.

use crate::support::{assert_valid, Sandbox};

/// A 2x2 square and a 1x4 bar, cut into two dominoes.
const GOOD: &str = r#"{
  "format": "dissection-solution/1",
  "lattice": "square",
  "mirror": true,
  "figures": [
    {"name": "square.txt", "pieces": [[[0,0],[1,0]], [[0,1],[1,1]]]},
    {"name": "bar.txt", "pieces": [[[0,0],[1,0]], [[2,0],[3,0]]]}
  ]
}
"#;

/// Tampered copies of [`GOOD`] and the reason `verify` must give.
const TAMPERED: &[(&str, &str, &str)] = &[
    // A cell dropped from a piece.
    (
        "[[2,0],[3,0]]",
        "[[2,0]]",
        "bar.txt: figure 1: 1 cell(s) not covered",
    ),
    // A cell listed twice.
    (
        "[[2,0],[3,0]]",
        "[[2,0],[3,0],[1,0]]",
        "bar.txt: figure 1: cell [1, 0, 0] is listed more than once",
    ),
    // A cell outside the figure.
    (
        "[[2,0],[3,0]]",
        "[[2,0],[3,0],[4,0]]",
        "bar.txt: figure 1 piece 1: cell [4, 0, 0] is not in the figure",
    ),
    // A cell moved from one piece to the other: neither matches any more.
    (
        "[[0,0],[1,0]], [[0,1],[1,1]]",
        "[[0,0],[1,0],[0,1]], [[1,1]]",
        "not congruent",
    ),
    // A piece in two parts.
    (
        "[[0,0],[1,0]], [[2,0],[3,0]]",
        "[[0,0],[3,0]], [[2,0],[1,0]]",
        "bar.txt: figure 1 piece 0 is not connected (2 components)",
    ),
    // A piece missing from one figure.
    (
        ", [[2,0],[3,0]]",
        "",
        "figures list different numbers of pieces",
    ),
];

#[test]
fn verify_accepts_a_valid_solution() {
    let sb = Sandbox::new();
    let sq = sb.write("square.txt", "##\n##\n");
    let bar = sb.write("bar.txt", "####\n");
    sb.write("good.json", GOOD);
    assert_eq!(assert_valid(&sb, "square", "good.json", &[&sq, &bar]), 2);
    // The lattice may be left to the solution.
    sb.run(&["verify", "--solution", "good.json", &sq, &bar])
        .expect_code(0)
        .stdout_has(&["valid: 2 pieces"]);
}

#[test]
fn verify_rejects_tampered_solutions_with_the_reason() {
    let sb = Sandbox::new();
    let sq = sb.write("square.txt", "##\n##\n");
    let bar = sb.write("bar.txt", "####\n");
    for (from, to, reason) in TAMPERED {
        assert!(GOOD.contains(from), "{from}");
        sb.write("bad.json", &GOOD.replacen(from, to, 1));
        let run = sb.run(&["verify", "--solution", "bad.json", &sq, &bar]);
        run.expect_code(1).stdout_has(&[reason, "invalid: "]);
    }
}

#[test]
fn verify_honours_mirror_false() {
    // An S and a Z tetromino: one piece, but only if it may be turned over.
    let sb = Sandbox::new();
    let s = sb.write("s.txt", ".##\n##.\n");
    let z = sb.write("z.txt", "##.\n.##\n");
    let sol = |mirror: bool| {
        format!(
            r#"{{"format": "dissection-solution/1", "lattice": "square", "mirror": {mirror}, "figures": [
  {{"name": "s.txt", "pieces": [[[1,0],[2,0],[0,1],[1,1]]]}},
  {{"name": "z.txt", "pieces": [[[0,0],[1,0],[1,1],[2,1]]]}}]}}"#
        )
    };
    sb.write("flip.json", &sol(true));
    assert_eq!(assert_valid(&sb, "square", "flip.json", &[&s, &z]), 1);
    sb.write("noflip.json", &sol(false));
    sb.run(&["verify", "--solution", "noflip.json", &s, &z])
        .expect_code(1)
        .stdout_has(&["z.txt: piece 0 of figure 1 is not congruent to piece 0 of figure 0"]);
}

#[test]
fn verify_rejects_a_wrong_number_of_figures() {
    let sb = Sandbox::new();
    let sq = sb.write("square.txt", "##\n##\n");
    sb.write("good.json", GOOD);
    sb.run(&["verify", "--solution", "good.json", &sq])
        .expect_code(1)
        .stdout_has(&["solution has 2 figures, 1 were given"]);
}
