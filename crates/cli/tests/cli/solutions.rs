//! `dissect solve` with the puzzle options: several solutions, their
//! ranking, and the designer's constraints. Every solution written is
//! checked by `dissect verify` and the independent checkers (`assert_valid`).

use std::collections::HashSet;

use crate::support::{assert_valid, json, Sandbox};

/// The piece areas of figure 0, sorted: a cheap fingerprint.
fn areas(v: &serde_json::Value) -> Vec<usize> {
    let mut a: Vec<usize> = v["figures"][0]["pieces"]
        .as_array()
        .unwrap()
        .iter()
        .map(|p| p.as_array().unwrap().len())
        .collect();
    a.sort();
    a
}

#[test]
fn several_solutions_are_written_ranked_and_different() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("squares-3-4-split-to-5", "a.txt", "a.txt");
    let b = sb.copy_instance("squares-3-4-split-to-5", "b.txt", "b.txt");
    let run = sb.run(&[
        "solve",
        "--solutions",
        "3",
        "--rank",
        "smallest",
        "--threads",
        "2",
        "--seed",
        "1",
        &a,
        &b,
        "-o",
        "out.json",
    ]);
    run.expect_code(0).stderr_has(&[
        "out.json: 4 pieces, variance",
        "out-2.json: 4 pieces",
        "out-3.json: 4 pieces",
    ]);
    let mut forms = HashSet::new();
    let mut smallest = Vec::new();
    for f in ["out.json", "out-2.json", "out-3.json"] {
        assert_eq!(assert_valid(&sb, "square", f, &[&a, &b]), 4);
        let v = json(&sb.read(f));
        assert_eq!(v["rank"]["by"], "smallest");
        smallest.push(v["scores"]["smallest"].as_u64().unwrap());
        forms.insert(v["figures"][0]["pieces"].to_string());
    }
    assert_eq!(forms.len(), 3);
    // Ranked: the largest smallest piece first.
    assert!(smallest.windows(2).all(|w| w[0] >= w[1]), "{smallest:?}");
    assert!(!sb.path("out-4.json").exists());
}

#[test]
fn keep_regions_change_the_answer_and_are_honoured() {
    let sb = Sandbox::new();
    sb.write("r.txt", "###\n###\n");
    sb.write("bar.txt", "######\n");
    sb.run(&["solve", "r.txt", "bar.txt", "-o", "free.json", "-q"])
        .expect_code(0);
    assert_eq!(areas(&json(&sb.read("free.json"))), vec![3, 3]);
    // The left column kept whole: three vertical dominoes.
    sb.write("k.txt", "a..\na..\n");
    sb.run(&[
        "solve", "--keep", "1:k.txt", "r.txt", "bar.txt", "-o", "k.json", "-q",
    ])
    .expect_code(0);
    assert_eq!(
        assert_valid(&sb, "square", "k.json", &["r.txt", "bar.txt"]),
        3
    );
    let v = json(&sb.read("k.json"));
    let region = &v["constraints"]["keep"][0]["regions"]["a"];
    assert_eq!(region.to_string(), "[[0,0],[0,1]]");
    let holder = v["figures"][0]["pieces"]
        .as_array()
        .unwrap()
        .iter()
        .filter(|p| {
            let s = p.to_string();
            s.contains("[0,0]") || s.contains("[0,1]")
        })
        .count();
    assert_eq!(holder, 1, "both cells in one piece");
}

#[test]
fn piece_sizes_change_the_answer_and_are_honoured() {
    let sb = Sandbox::new();
    sb.write("sq.txt", "###\n###\n###\n");
    sb.write("bar.txt", "#########\n");
    sb.run(&[
        "solve",
        "--max-piece",
        "2",
        "sq.txt",
        "bar.txt",
        "-o",
        "s.json",
        "-q",
    ])
    .expect_code(0);
    assert_eq!(
        assert_valid(&sb, "square", "s.json", &["sq.txt", "bar.txt"]),
        5
    );
    let v = json(&sb.read("s.json"));
    assert!(areas(&v).iter().all(|&a| a <= 2));
    assert_eq!(v["constraints"]["max_piece"], 2);
    sb.run(&[
        "solve",
        "--min-piece",
        "2",
        "--max-piece",
        "3",
        "sq.txt",
        "bar.txt",
        "-o",
        "m.json",
        "-q",
    ])
    .expect_code(0);
    assert!(areas(&json(&sb.read("m.json")))
        .iter()
        .all(|&a| (2..=3).contains(&a)));
}

#[test]
fn the_checkerboard_changes_the_answer_and_is_honoured() {
    let sb = Sandbox::new();
    sb.write("l.txt", "#.\n#.\n##\n");
    sb.write("m.txt", ".#.\n.#.\n.##\n");
    sb.run(&["solve", "l.txt", "m.txt", "-o", "free.json", "-q"])
        .expect_code(0);
    assert_eq!(areas(&json(&sb.read("free.json"))), vec![4]);
    sb.run(&[
        "solve",
        "--checkerboard",
        "l.txt",
        "m.txt",
        "-o",
        "c.json",
        "-q",
    ])
    .expect_code(0);
    assert_eq!(
        assert_valid(&sb, "square", "c.json", &["l.txt", "m.txt"]),
        2
    );
    assert_eq!(
        json(&sb.read("c.json"))["constraints"]["checkerboard"],
        true
    );
}

#[test]
fn impossible_constraints_exit_1_with_a_clear_message() {
    let sb = Sandbox::new();
    sb.write("r.txt", "###\n###\n");
    sb.write("bar.txt", "######\n");
    sb.run(&[
        "solve",
        "--min-piece",
        "4",
        "--max-piece",
        "3",
        "r.txt",
        "bar.txt",
    ])
    .expect_code(1)
    .stderr_has(&["impossible: --min-piece 4 is larger than --max-piece 3"]);
    sb.write("ends.txt", "a....a\n");
    sb.run(&[
        "solve",
        "--keep",
        "2:ends.txt",
        "r.txt",
        "bar.txt",
        "-o",
        "x.json",
    ])
    .expect_code(1)
    .stderr_has(&["no dissection found"]);
    assert!(!sb.path("x.json").exists());
    sb.write("odd.txt", "#.#\n.#.\n");
    sb.write("line.txt", "###\n");
    sb.run(&["solve", "--checkerboard", "odd.txt", "line.txt"])
        .expect_code(1)
        .stderr_has(&["different numbers of black cells"]);
    // Malformed input is exit 2, naming the file, line and column.
    sb.write("bad.txt", "a..\n.A.\n");
    sb.run(&["solve", "--keep", "1:bad.txt", "r.txt", "bar.txt"])
        .expect_code(2)
        .stderr_has(&["bad.txt: line 2, column 2: unexpected character 'A'"]);
    sb.run(&["solve", "--keep", "3:bad.txt", "r.txt", "bar.txt"])
        .expect_code(2)
        .stderr_has(&["figure 3 does not exist"]);
    sb.run(&[
        "solve",
        "--checkerboard",
        "--lattice",
        "tri4",
        "r.txt",
        "bar.txt",
    ])
    .expect_code(2)
    .stderr_has(&["--checkerboard needs"]);
}

#[test]
fn rank_unique_orders_by_assembly_count() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("squares-3-4-split-to-5", "a.txt", "a.txt");
    let b = sb.copy_instance("squares-3-4-split-to-5", "b.txt", "b.txt");
    sb.run(&[
        "solve",
        "--solutions",
        "3",
        "--rank",
        "unique",
        "--threads",
        "2",
        &a,
        &b,
        "-o",
        "u.json",
    ])
    .expect_code(0)
    .stderr_has(&["u.json: 4 pieces", "assemblies"]);
    let mut counts = Vec::new();
    for f in ["u.json", "u-2.json", "u-3.json"] {
        assert_eq!(assert_valid(&sb, "square", f, &[&a, &b]), 4);
        let v = json(&sb.read(f));
        assert_eq!(v["rank"]["by"], "unique");
        counts.push(v["scores"]["assemblies"].as_u64().expect("counted"));
    }
    assert!(counts.windows(2).all(|w| w[0] <= w[1]), "{counts:?}");
}

#[test]
fn a_plain_keep_number_still_sets_the_candidates_kept() {
    let sb = Sandbox::new();
    sb.write("r.txt", "###\n###\n");
    sb.write("bar.txt", "######\n");
    sb.run(&[
        "solve", "--keep", "5", "r.txt", "bar.txt", "-o", "k.json", "-q",
    ])
    .expect_code(0);
    let v = json(&sb.read("k.json"));
    assert!(v.get("constraints").is_none(), "no constraint: {v}");
    assert_eq!(
        assert_valid(&sb, "square", "k.json", &["r.txt", "bar.txt"]),
        2
    );
}
