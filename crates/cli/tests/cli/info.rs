//! `dissect info`: cell count, components, holes and bounding box of each
//! figure, and a clear message when the areas differ.

use crate::support::{golden, Sandbox};

/// Runs `info` and compares its stdout with a golden file.
#[track_caller]
fn info_golden(sb: &Sandbox, lattice: &str, files: &[&str], golden_name: &str) {
    let mut args = vec!["info", "--lattice", lattice];
    args.extend_from_slice(files);
    let run = sb.run(&args);
    run.expect_code(0);
    assert_eq!(run.stderr, "");
    golden(golden_name, &run.stdout);
}

#[test]
fn info_square() {
    let sb = Sandbox::new();
    // A ring around a 2-cell hole, and a 2x2 block apart: 14 cells.
    sb.write("ring.txt", "####..##\n#..#..##\n####\n");
    sb.write("bar.txt", ".\n..##############\n");
    info_golden(&sb, "square", &["ring.txt", "bar.txt"], "info-square.txt");
}

#[test]
fn info_tri4() {
    let sb = Sandbox::new();
    // A 4x4 square with a diamond hole (56 triangles), a 7x2 rectangle
    // (56), then the diamond itself (8) beside the big triangle (128).
    sb.write("ring.txt", "####\n#93#\n#C6#\n####\n");
    sb.write("rect.txt", "#######\n#######\n");
    sb.write("diamond.txt", "6C\n39\n");
    sb.copy_instance("tri-triangle8-to-rect4x8", "a.txt", "triangle.txt");
    info_golden(&sb, "tri4", &["ring.txt", "rect.txt"], "info-tri4.txt");
    info_golden(
        &sb,
        "tri4",
        &["diamond.txt", "triangle.txt"],
        "info-tri4-areas-differ.txt",
    );
}

#[test]
fn info_cubic() {
    let sb = Sandbox::new();
    sb.copy_instance("cube4-cavity-to-7x4x2", "a.txt", "cube.txt");
    sb.copy_instance("cube4-cavity-to-7x4x2", "b.txt", "box.txt");
    // Two cubes apart, in different layers.
    sb.write("two.txt", "#.\n..\n\n..\n.#\n");
    info_golden(&sb, "cubic", &["cube.txt", "box.txt"], "info-cubic.txt");
    info_golden(&sb, "cubic", &["two.txt"], "info-cubic-apart.txt");
}

#[test]
fn info_says_clearly_when_areas_differ() {
    let sb = Sandbox::new();
    sb.write("three.txt", "###\n");
    sb.write("four.txt", "##\n##\n");
    sb.write("six.txt", "###\n###\n");
    info_golden(
        &sb,
        "square",
        &["three.txt", "four.txt", "six.txt"],
        "info-areas-differ.txt",
    );
    let run = sb.run(&["info", "three.txt", "four.txt"]);
    run.stdout_has(&["AREAS DIFFER", "three.txt: 3 cells", "four.txt: 4 cells"]);
}
