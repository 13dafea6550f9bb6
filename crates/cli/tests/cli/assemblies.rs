//! `dissect assemblies`: tilings of each figure by a solution's pieces.

use crate::support::{golden, Sandbox};

const DOMINOES: &str = r#"{"format": "dissection-solution/1", "lattice": "square", "mirror": true,
  "figures": [{"name": "rect.txt", "pieces": [[[0,0],[0,1]], [[1,0],[1,1]], [[2,0],[2,1]], [[3,0],[3,1]]]}]}"#;

#[test]
fn assemblies_golden_on_every_lattice() {
    let sb = Sandbox::new();
    let mut out = String::new();
    // Square: four dominoes in a 2x4 rectangle (5 tilings, 4 up to its
    // symmetries) and in a 1x8 bar (1, unique).
    sb.write("dominoes.json", DOMINOES);
    sb.write("rect.txt", "####\n####\n");
    sb.write("bar.txt", "########\n");
    let run = sb.run(&[
        "assemblies",
        "--solution",
        "dominoes.json",
        "rect.txt",
        "bar.txt",
    ]);
    run.expect_code(0);
    out += &run.stdout;
    // tri4 and cubic: the fixtures' solutions in their own figures.
    let t = sb.copy_instance("tri-triangle8-to-rect4x8", "a.txt", "triangle.txt");
    let r = sb.copy_instance("tri-triangle8-to-rect4x8", "b.txt", "rect4x8.txt");
    let fixture = |name: &str| {
        let text = std::fs::read_to_string(
            std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
                .join("tests/fixtures")
                .join(name),
        )
        .unwrap();
        sb.write(name, &text)
    };
    let s = fixture("tri4-triangle-rect.solution.json");
    let run = sb.run(&["assemblies", "--lattice", "tri4", "--solution", &s, &t, &r]);
    run.expect_code(0);
    out += &run.stdout;
    let a = sb.write("rings.txt", "###\n#.#\n###\n\n###\n#.#\n###\n");
    let b = sb.write("square.txt", "####\n####\n####\n####\n");
    let s = fixture("cubic-rings-square.solution.json");
    let run = sb.run(&["assemblies", "--solution", &s, &a, &b]);
    run.expect_code(0);
    out += &run.stdout;
    golden("assemblies.txt", &out);
}

#[test]
fn assemblies_bad_input() {
    let sb = Sandbox::new();
    sb.write("dominoes.json", DOMINOES);
    sb.write("small.txt", "###\n");
    sb.run(&["assemblies", "--solution", "dominoes.json", "small.txt"])
        .expect_code(2)
        .stderr_has(&["small.txt: the pieces have 8 cells in all, the figure has 3"]);
    sb.run(&[
        "assemblies",
        "--lattice",
        "tri4",
        "--solution",
        "dominoes.json",
        "small.txt",
    ])
    .expect_code(2)
    .stderr_has(&["the solution is on the square lattice, but --lattice tri4 was given"]);
    sb.write("rect.txt", "####\n####\n");
    sb.run(&[
        "assemblies",
        "--solution",
        "dominoes.json",
        "--time-limit",
        "nan",
        "rect.txt",
    ])
    .expect_code(2)
    .stderr_has(&["--time-limit"]);
}

#[test]
fn assemblies_time_limit_reports_a_lower_bound() {
    // Dominoes of a 10x10 square: about 2.6e11 tilings, far too many.
    let sb = Sandbox::new();
    let pieces: Vec<String> = (0..50)
        .map(|i| {
            format!(
                "[[{},{}],[{},{}]]",
                i % 10,
                2 * (i / 10),
                i % 10,
                2 * (i / 10) + 1
            )
        })
        .collect();
    sb.write(
        "d.json",
        &format!(
            r#"{{"format": "dissection-solution/1", "lattice": "square", "figures": [{{"name": "sq.txt", "pieces": [{}]}}]}}"#,
            pieces.join(",")
        ),
    );
    sb.write("sq.txt", &"##########\n".repeat(10));
    let run = sb.run(&[
        "assemblies",
        "--solution",
        "d.json",
        "--time-limit",
        "0.5",
        "sq.txt",
    ]);
    run.expect_code(0)
        .stdout_has(&["sq.txt: at least "])
        .stderr_has(&["lower bounds"]);
    assert!(run.elapsed.as_secs_f64() < 10.0);
}
