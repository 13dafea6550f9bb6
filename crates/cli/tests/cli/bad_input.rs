//! Bad input: a clear message naming the file (and line and column where
//! the problem is at one place), exit code 2, never a panic.

use crate::support::Sandbox;

const BAR: &str = "###\n";

/// Runs `args` and checks exit code 2 and that stderr has every part.
#[track_caller]
fn rejects(sb: &Sandbox, args: &[&str], says: &[&str]) {
    let run = sb.run(args);
    assert_eq!(
        run.code,
        Some(2),
        "{args:?} should exit 2\n--- stdout\n{}\n--- stderr\n{}",
        run.stdout,
        run.stderr
    );
    run.stderr_has(says);
    assert!(run.stderr.starts_with("dissect: error: ") || run.stderr.starts_with("error: "));
}

/// A figure text, the lattice it is read on, and what the error must say.
const FIGURE_ERRORS: &[(&str, &str, &[&str])] = &[
    // Unknown characters, with line and column.
    (
        "##\n#x#\n",
        "square",
        &["bad.txt: line 2, column 2: unexpected character 'x'"],
    ),
    (
        "###\n##\t\n",
        "square",
        &["bad.txt: line 2, column 3: unexpected character '\\t'"],
    ),
    (
        "F3\n1g\n",
        "tri4",
        &[
            "bad.txt: line 2, column 2: unexpected character 'g'",
            "hex digits",
        ],
    ),
    (
        "##\n##\n\n#o\n",
        "cubic",
        &["bad.txt: line 4, column 2: unexpected character 'o'"],
    ),
    // A tri4 figure read as square: the message points at the lattice.
    (
        "##9\n",
        "square",
        &["bad.txt: line 1, column 3", "--lattice tri4"],
    ),
    // Empty figures.
    ("", "square", &["bad.txt: empty figure"]),
    ("...\n..\n\n", "square", &["bad.txt: empty figure"]),
    ("00.\n", "tri4", &["bad.txt: empty figure"]),
    ("..\n\n..\n", "cubic", &["bad.txt: empty figure"]),
    // Cubic layer separators.
    (
        "\n##\n",
        "cubic",
        &["bad.txt: line 1: blank line before the first z layer"],
    ),
    (
        "##\n\n\n##\n",
        "cubic",
        &["bad.txt: line 3: more than one blank line"],
    ),
];

#[test]
fn figure_errors_name_file_line_and_column() {
    let sb = Sandbox::new();
    let ok = sb.write("ok.txt", BAR);
    for (text, lattice, says) in FIGURE_ERRORS {
        let bad = sb.write("bad.txt", text);
        for cmd in ["solve", "info"] {
            let mut args = vec![cmd, "--lattice", lattice, &bad];
            if cmd == "solve" {
                args.push(&ok);
            }
            rejects(&sb, &args, says);
        }
    }
}

#[test]
fn line_ends_and_trailing_blanks_are_fine() {
    let sb = Sandbox::new();
    let a = sb.write("a.txt", "##  \r\n#.\r\n\r\n\n");
    let b = sb.write("b.txt", "###\n");
    sb.run(&["solve", "-q", "-o", "out.json", &a, &b])
        .expect_code(0);
}

#[test]
fn unequal_areas_list_each_figure() {
    let sb = Sandbox::new();
    let a = sb.write("three.txt", "###\n");
    let b = sb.write("four.txt", "##\n##\n");
    let c = sb.write("also-three.txt", "#\n##\n");
    rejects(
        &sb,
        &["solve", &a, &b],
        &["different areas", "three.txt: 3 cells", "four.txt: 4 cells"],
    );
    rejects(
        &sb,
        &["solve", &a, &c, &b],
        &[
            "three.txt: 3 cells",
            "also-three.txt: 3 cells",
            "four.txt: 4 cells",
        ],
    );
    // tri4 counts triangles.
    rejects(
        &sb,
        &["solve", "--lattice", "tri4", &a, &c, &b],
        &["three.txt: 12 cells", "four.txt: 16 cells"],
    );
}

#[test]
fn unreadable_files_are_named() {
    let sb = Sandbox::new();
    let ok = sb.write("ok.txt", BAR);
    std::fs::create_dir(sb.path("folder.txt")).expect("mkdir");
    std::fs::write(sb.path("latin1.txt"), b"##\n#\xe9\n").expect("write");
    rejects(
        &sb,
        &["solve", "missing.txt", &ok],
        &["missing.txt: cannot read"],
    );
    rejects(
        &sb,
        &["solve", &ok, "missing.txt"],
        &["missing.txt: cannot read"],
    );
    rejects(&sb, &["info", "folder.txt"], &["folder.txt: cannot read"]);
    rejects(
        &sb,
        &["solve", "latin1.txt", &ok],
        &["latin1.txt: line 2, column 2: not UTF-8 text"],
    );
    rejects(
        &sb,
        &["verify", "--solution", "missing.json", &ok, &ok],
        &["missing.json: cannot read"],
    );
}

#[test]
fn unwritable_output_fails_before_the_search() {
    let sb = Sandbox::new();
    let a = sb.write("a.txt", BAR);
    let b = sb.write("b.txt", "##\n#.\n");
    rejects(
        &sb,
        &["solve", "-o", "no/such/folder/out.json", &a, &b],
        &["no/such/folder/out.json: cannot write", "does not exist"],
    );
    std::fs::create_dir(sb.path("out")).expect("mkdir");
    rejects(
        &sb,
        &["solve", "-o", "out", &a, &b],
        &["out: cannot write", "folder"],
    );
}

/// A solution text, its lattice's figures, and what the error must say.
const SOLUTION_ERRORS: &[(&str, &[&str])] = &[
    (
        "{\"lattice\": \"square\",\n \"figures\": [{\"pieces\": [[[0,0]]]}\n {\"pieces\": []}]}\n",
        &["s.json: line 3, column 2: expected `,` or `]`"],
    ),
    ("", &["s.json: line 1, column 0: EOF while parsing"]),
    ("{\"lattice\": \"square\"}", &["s.json: line 1, column 21: missing field `figures`"]),
    (
        "{\"lattice\": \"square\", \"figures\": [{\"pieces\": [[[0, \"one\"]]]}]}",
        &["s.json: line 1, column 56: invalid type: string \"one\""],
    ),
    (
        "{\"lattice\": \"hexagonal\", \"figures\": [], \"format\": \"dissection-solution/1\"}",
        &["s.json: unknown lattice \"hexagonal\""],
    ),
    (
        "{\"lattice\": \"square\", \"figures\": []}",
        &["s.json: no \"format\" key"],
    ),
    (
        "{\"format\": \"other/2\", \"lattice\": \"square\", \"figures\": []}",
        &["s.json: format is \"other/2\""],
    ),
    // Cells of the wrong shape, located in the text.
    (
        "{\"lattice\": \"square\", \"figures\": [\n  {\"pieces\": [[[0,0],[1,0],[2,0]]]},\n  {\"pieces\": [[[0,0],[1,0],[0,1,0]]]}\n], \"format\": \"dissection-solution/1\"}\n",
        &[
            "s.json: line 3, column 28: figure 1 piece 0: bad cell [0, 1, 0]",
            "a square cell is [x, y]",
        ],
    ),
    (
        "{\"lattice\": \"tri4\", \"figures\": [\n  {\"pieces\": [[[0,0,0],\n    [0,0,4]]]}], \"format\": \"dissection-solution/1\"}\n",
        &["s.json: line 3, column 5: figure 0 piece 0: bad cell [0, 0, 4]", "t in 0..=3"],
    ),
    (
        "{\"lattice\": \"cubic\", \"figures\": [{\"pieces\": [[[0,0]]]}], \"format\": \"dissection-solution/1\"}",
        &["s.json: line 1, column 47: figure 0 piece 0: bad cell [0, 0]", "[x, y, z]"],
    ),
];

#[test]
fn solution_errors_name_file_line_and_column() {
    let sb = Sandbox::new();
    let a = sb.write("a.txt", BAR);
    let b = sb.write("b.txt", "##\n#.\n");
    for (text, says) in SOLUTION_ERRORS {
        let s = sb.write("s.json", text);
        rejects(&sb, &["verify", "--solution", &s, &a, &b], says);
    }
}

#[test]
fn figures_on_another_lattice_than_the_solution() {
    let sb = Sandbox::new();
    let a = sb.write("a.txt", BAR);
    let b = sb.write("b.txt", "##\n#.\n");
    sb.run(&["solve", "-q", "-o", "s.json", &a, &b])
        .expect_code(0);
    rejects(
        &sb,
        &[
            "verify",
            "--lattice",
            "tri4",
            "--solution",
            "s.json",
            &a,
            &b,
        ],
        &["s.json: the solution is on the square lattice, but --lattice tri4 was given"],
    );
    // A tri4 figure where the lattice is square (the solution's).
    let t = sb.write("t.txt", "#C\n");
    rejects(
        &sb,
        &["verify", "--solution", "s.json", &a, &t],
        &[
            "t.txt: line 1, column 2: unexpected character 'C'",
            "--lattice tri4",
        ],
    );
}
