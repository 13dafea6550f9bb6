//! The ASCII display, checked against golden files (`UPDATE_GOLDEN=1`
//! regenerates them): `tri4` squares as 3x3 blocks that draw the diagonals,
//! `cubic` layers side by side.

use std::path::Path;

use dissect_core::io::parse_solution;

use crate::support::{assert_valid, golden, Sandbox};

/// `solve`'s stdout without its one varying line (the time taken).
fn without_time(stdout: &str) -> String {
    stdout
        .lines()
        .map(|l| {
            if l.starts_with("time: ") {
                "time: (varies)"
            } else {
                l
            }
        })
        .map(|l| format!("{l}\n"))
        .collect()
}

/// Draws every figure of a solution fixture (checked by both verifiers
/// first) as `solve` does, each under its name.
fn draw_fixture(sb: &Sandbox, fixture: &str, lattice: &str, figures: &[&str]) -> String {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/fixtures")
        .join(fixture);
    let text = std::fs::read_to_string(&path).expect("fixture");
    sb.write("solution.json", &text);
    assert_valid(sb, lattice, "solution.json", figures);
    let (_, d) = parse_solution(&text).expect("fixture parses");
    let mut out = String::new();
    for (name, pieces) in d.names().iter().zip(d.pieces()) {
        out += &format!(
            "{name}:\n{}\n",
            dissect_core::ascii::draw(d.lattice(), pieces, false)
        );
    }
    out
}

#[test]
fn tri4_squares_are_3x3_blocks_with_their_diagonals() {
    let sb = Sandbox::new();
    let t = sb.copy_instance("tri-triangle8-to-rect4x8", "a.txt", "triangle.txt");
    let r = sb.copy_instance("tri-triangle8-to-rect4x8", "b.txt", "rect.txt");
    let drawn = draw_fixture(&sb, "tri4-triangle-rect.solution.json", "tri4", &[&t, &r]);
    golden("tri4-triangle-rect.txt", &drawn);
}

#[test]
fn cubic_layers_are_side_by_side() {
    let sb = Sandbox::new();
    let a = sb.write("rings.txt", "###\n#.#\n###\n\n###\n#.#\n###\n");
    let b = sb.write("square.txt", "####\n####\n####\n####\n");
    let drawn = draw_fixture(&sb, "cubic-rings-square.solution.json", "cubic", &[&a, &b]);
    golden("cubic-rings-square.txt", &drawn);
}

#[test]
fn solve_output_tri4() {
    // A pentagon with two 45° edges, and its mirror image across the main
    // diagonal: one piece (turned over), drawn with its diagonals.
    let sb = Sandbox::new();
    let a = sb.write("a.txt", "#9\n#.\n9.\n");
    let b = sb.write("b.txt", "##9\n9.\n");
    let run = sb.run(&["solve", "--lattice", "tri4", "-o", "out.json", &a, &b]);
    run.expect_code(0);
    assert_valid(&sb, "tri4", "out.json", &[&a, &b]);
    golden("solve-tri4.txt", &without_time(&run.stdout));
}

#[test]
fn solve_output_cubic() {
    // A tripod of four cubes and the same tripod turned about the z axis.
    let sb = Sandbox::new();
    let a = sb.write("a.txt", "##\n#.\n\n#.\n..\n");
    let b = sb.write("b.txt", "##\n.#\n\n.#\n..\n");
    let run = sb.run(&["solve", "--lattice", "cubic", "-o", "out.json", &a, &b]);
    run.expect_code(0);
    assert_eq!(assert_valid(&sb, "cubic", "out.json", &[&a, &b]), 1);
    golden("solve-cubic.txt", &without_time(&run.stdout));
}

#[test]
fn cubic_never_mirrors() {
    // The two screw tetracubes are mirror images, not turns of each other:
    // more than one piece on the cubic lattice.
    let sb = Sandbox::new();
    let a = sb.write("a.txt", "##\n.#\n\n..\n.#\n");
    let m = sb.write("m.txt", "..\n.#\n\n##\n.#\n");
    let run = sb.run(&[
        "solve",
        "--lattice",
        "cubic",
        "-q",
        "-o",
        "out.json",
        &a,
        &m,
    ]);
    run.expect_code(0);
    let sol = crate::support::json(&sb.read("out.json"));
    assert_eq!(sol["mirror"], false);
    assert!(assert_valid(&sb, "cubic", "out.json", &[&a, &m]) >= 2);
}
