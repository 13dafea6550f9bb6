//! The solution JSON format: round trip, defaults, unknown keys and errors.

use dissect_core::io::{parse_solution, SolutionError, SOLUTION_FORMAT};
use dissect_core::LatticeKind;

use super::util::{dissection, Cubic, Square, Tri4};

#[test]
fn round_trip_on_every_lattice() {
    let cases: [(LatticeKind, bool, &[&str]); 4] = [
        (Square, true, &["AB|AB", "AABB"]),
        (Square, false, &["AB|AB", "AABB", "A|A|B|B"]),
        (Tri4, true, &["AABB A..A|B..B .", ".AA. ..AA|BB.. B..B"]),
        (Cubic, false, &["AA|AA/BB|BB", "AABB|AABB"]),
    ];
    for (lattice, mirror, labelled) in cases {
        let (_, d) = dissection(lattice, mirror, labelled);
        let mut extra = serde_json::Map::new();
        extra.insert("pieces".into(), serde_json::json!(2));
        let json = d.to_file(extra.clone()).to_json();
        let (file, back) = parse_solution(&json).unwrap_or_else(|e| panic!("{e}\n{json}"));
        assert_eq!(back, d, "{json}");
        assert_eq!(file.extra, extra);
        assert_eq!(file.format.as_deref(), Some(SOLUTION_FORMAT));
        assert_eq!(back.piece_count(), 2);
        // The text is plain JSON that serde_json reads the same way.
        let value: serde_json::Value = serde_json::from_str(&json).unwrap();
        assert_eq!(value["lattice"], lattice.name());
        let first_cell = &value["figures"][0]["pieces"][0][0];
        let arity = if lattice == Square { 2 } else { 3 };
        assert_eq!(first_cell.as_array().unwrap().len(), arity, "{json}");
    }
}

#[test]
fn golden_square_solution() {
    let (_, d) = dissection(Square, true, &["AB|AB", "AABB"]);
    let json = d.to_file(serde_json::Map::new()).to_json();
    assert_eq!(
        json,
        r#"{
  "format": "dissection-solution/1",
  "lattice": "square",
  "mirror": true,
  "figures": [
    {"name": "f0.txt", "pieces": [
      [[0,0],[0,1]],
      [[1,0],[1,1]]
    ]},
    {"name": "f1.txt", "pieces": [
      [[0,0],[1,0]],
      [[2,0],[3,0]]
    ]}
  ]
}
"#
    );
}

#[test]
fn defaults_and_unknown_keys() {
    let text = r#"{"format": "dissection-solution/1", "lattice": "tri4", "figures": [{"pieces": [[[0,0,1]]]}], "score": 3}"#;
    let (file, d) = parse_solution(text).unwrap();
    assert!(d.mirror(), "mirror defaults to true in 2D");
    assert_eq!(d.names(), vec![String::new()]);
    assert_eq!(d.pieces(), vec![vec![vec![[0, 0, 1]]]]);
    assert_eq!(file.extra["score"], 3);
    let (_, d) =
        parse_solution(r#"{"format": "dissection-solution/1", "lattice": "cubic", "figures": []}"#)
            .unwrap();
    assert!(!d.mirror(), "never mirror in 3D");
    let (_, d) = parse_solution(
        r#"{"format": "dissection-solution/1", "lattice": "cubic", "mirror": true, "figures": []}"#,
    )
    .unwrap();
    assert!(!d.mirror(), "never mirror in 3D, even when asked");
    let (_, d) =
        parse_solution(r#"{"format": "dissection-solution/1", "lattice": "square", "mirror": false, "figures": []}"#).unwrap();
    assert!(!d.mirror());
}

#[test]
fn the_format_key_is_required() {
    assert_eq!(
        parse_solution(r#"{"lattice": "square", "figures": []}"#),
        Err(SolutionError::MissingFormat)
    );
    let e = SolutionError::MissingFormat.to_string();
    assert!(e.contains("\"format\": \"dissection-solution/1\""), "{e}");
}

#[test]
fn errors() {
    let json_error = |text: &str| match parse_solution(text) {
        Err(SolutionError::Json { line, column, .. }) => (line, column),
        other => panic!("{text:?}: {other:?}"),
    };
    assert_eq!(
        json_error("{\n  \"lattice\": \"square\",\n  \"figures\": [}\n"),
        (3, 15)
    );
    assert_eq!(
        json_error("{\"lattice\": \"square\",\n \"figures\": [{\"pieces\": 7}]}"),
        (2, 25)
    );
    let e =
        parse_solution(r#"{"format": "dissection-solution/1", "lattice": "square"}"#).unwrap_err();
    assert!(e.to_string().contains("missing field `figures`"), "{e}");
    assert_eq!(
        parse_solution(
            r#"{"format": "dissection-solution/2", "lattice": "square", "figures": []}"#
        ),
        Err(SolutionError::WrongFormat("dissection-solution/2".into()))
    );
    assert_eq!(
        parse_solution(
            r#"{"format": "dissection-solution/1", "lattice": "hexagonal", "figures": []}"#
        ),
        Err(SolutionError::UnknownLattice("hexagonal".into()))
    );
    // Every text here is one line: the bad cell's `[` is found by its text.
    let bad_cell = |text: &str, figure, piece, cell: Vec<i64>, lattice| {
        let written = format!("{cell:?}").replace(' ', "");
        let column = text.find(&written).expect("the cell is in the text") + 1;
        assert_eq!(
            parse_solution(text),
            Err(SolutionError::BadCell {
                line: 1,
                column,
                figure,
                piece,
                cell,
                lattice
            }),
            "{text}"
        );
    };
    bad_cell(
        r#"{"format": "dissection-solution/1", "lattice": "square", "figures": [{"pieces": [[[0,0]]]}, {"pieces": [[[0,0]], [[1,0,0]]]}]}"#,
        1,
        1,
        vec![1, 0, 0],
        Square,
    );
    bad_cell(
        r#"{"format": "dissection-solution/1", "lattice": "tri4", "figures": [{"pieces": [[[0,0,4]]]}]}"#,
        0,
        0,
        vec![0, 0, 4],
        Tri4,
    );
    bad_cell(
        r#"{"format": "dissection-solution/1", "lattice": "cubic", "figures": [{"pieces": [[[0,0]]]}]}"#,
        0,
        0,
        vec![0, 0],
        Cubic,
    );
    bad_cell(
        r#"{"format": "dissection-solution/1", "lattice": "square", "figures": [{"pieces": [[[0,3000000000]]]}]}"#,
        0,
        0,
        vec![0, 3_000_000_000],
        Square,
    );
    bad_cell(
        r#"{"format": "dissection-solution/1", "lattice": "hex", "figures": [{"pieces": [[[0,0], [1,0,0]]]}]}"#,
        0,
        0,
        vec![1, 0, 0],
        LatticeKind::Hex,
    );
}

/// A bad cell's error names its line and column, and the lattice's cell form.
#[test]
fn a_bad_cell_is_located_on_its_line() {
    let text = "{\n  \"format\": \"dissection-solution/1\",\n  \"lattice\": \"tri4\",\n  \"figures\": [\n    {\"pieces\": [[[0, 0, 1],\n      [2, 0, 7]]]}\n  ]\n}\n";
    let e = parse_solution(text).expect_err("t = 7 is not a tri4 triangle");
    assert_eq!(
        e.to_string(),
        "line 6, column 7: figure 0 piece 0: bad cell [2, 0, 7] for the tri4 lattice (a tri4 cell is [x, y, t] with t in 0..=3)"
    );
}

/// Solution texts cut short or with a byte changed never make the reader
/// or the verifier panic.
#[test]
fn damaged_solutions_never_panic() {
    use rand::{RngExt, SeedableRng};
    let (figures, d) = dissection(Tri4, true, &["AABB A..A|B..B .", ".AA. ..AA|BB.. B..B"]);
    let json = d.to_file(serde_json::Map::new()).to_json();
    let bytes = json.as_bytes();
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
    let replacements = b"0123456789-,[]{}\":.ex ";
    for i in 0..2000 {
        let mut damaged = bytes.to_vec();
        if i % 4 == 0 {
            damaged.truncate(rng.random_range(0..bytes.len()));
        } else {
            let at = rng.random_range(0..bytes.len());
            damaged[at] = replacements[rng.random_range(0..replacements.len())];
        }
        let Ok(text) = String::from_utf8(damaged) else {
            continue;
        };
        if let Ok((_, d)) = parse_solution(&text) {
            // Whatever it says, the verifier answers without panicking.
            let _ = dissect_core::verify::verify(&d, &figures);
        }
    }
}
