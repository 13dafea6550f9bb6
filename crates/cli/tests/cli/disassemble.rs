//! `dissect disassemble`: one line per figure, exit codes, and plan files
//! replayed by the independent checker of `dissect-testkit`.

use dissect_testkit::disassembly::{replay, voxel_pieces, PlanMove, Voxel};

use crate::support::{json, Sandbox};

/// A Soma cube, one letter per piece.
const SOMA: &str = "AFB\nFFB\nGGC\n\nAFB\nAGC\nEGC\n\nDDB\nEDD\nEEC\n";

/// Ring A in the layer z = 1, ring B through its hole and around its side.
const RINGS: &str =
    "...\n...\n.B.\n.B.\n.B.\n\n...\nAAA\nABA\nAAA\n.B.\n\n...\n...\n.B.\n.B.\n.B.\n";

/// Writes a lettered voxel figure as a figure file (`#` per cube) and a
/// one-figure solution placing its pieces there; returns both names.
fn puzzle(sb: &Sandbox, name: &str, lettered: &str) -> (String, String) {
    let figure: String = lettered
        .chars()
        .map(|c| if c.is_ascii_uppercase() { '#' } else { c })
        .collect();
    let fig = sb.write(&format!("{name}.txt"), &figure);
    let pieces = voxel_pieces(lettered);
    let solution = serde_json::json!({
        "format": "dissection-solution/1",
        "lattice": "cubic",
        "mirror": false,
        "figures": [{"name": format!("{name}.txt"), "pieces": pieces}],
    });
    let s = sb.write(&format!("{name}.json"), &solution.to_string());
    (fig, s)
}

/// Replays every figure's plan in `plan` (a `dissection-disassembly/1`
/// file) on the solution's pieces; returns each figure's level.
fn replay_all(plan: &serde_json::Value, solution: &serde_json::Value) -> Vec<Option<usize>> {
    assert_eq!(plan["format"], "dissection-disassembly/1");
    assert_eq!(plan["lattice"], solution["lattice"]);
    let figures = plan["figures"].as_array().unwrap();
    assert_eq!(figures.len(), solution["figures"].as_array().unwrap().len());
    figures
        .iter()
        .zip(solution["figures"].as_array().unwrap())
        .map(|(f, s)| {
            assert_eq!(f["name"], s["name"]);
            let pieces: Vec<Vec<Voxel>> = serde_json::from_value(s["pieces"].clone()).unwrap();
            let moves: Vec<PlanMove> = f["moves"]
                .as_array()
                .unwrap()
                .iter()
                .map(|m| PlanMove {
                    pieces: serde_json::from_value(m["pieces"].clone()).unwrap(),
                    by: serde_json::from_value(m["by"].clone()).unwrap(),
                    removed: m["removed"].as_bool().unwrap(),
                })
                .collect();
            let level = f["level"].as_u64().map(|l| l as usize);
            if level.is_some() {
                assert_eq!(replay(&pieces, &moves).map(Some), Ok(level), "{f}");
            }
            level
        })
        .collect()
}

#[test]
fn a_soma_cube_comes_apart_and_its_plan_replays() {
    let sb = Sandbox::new();
    let (fig, s) = puzzle(&sb, "soma", SOMA);
    let run = sb.run(&["disassemble", "--solution", &s, "-o", "plan.json", &fig]);
    run.expect_code(0);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines.len(), 1, "{}", run.stdout);
    assert!(lines[0].starts_with("soma.txt: apart in "), "{}", lines[0]);
    assert!(lines[0].ends_with(" moves (level 1)"), "{}", lines[0]);
    let levels = replay_all(&json(&sb.read("plan.json")), &json(&sb.read("soma.json")));
    assert_eq!(levels, vec![Some(1)]);
}

#[test]
fn linked_rings_cannot_be_taken_apart() {
    let sb = Sandbox::new();
    let (fig, s) = puzzle(&sb, "rings", RINGS);
    let run = sb.run(&["disassemble", "--solution", &s, "-o", "plan.json", &fig]);
    run.expect_code(1);
    assert_eq!(
        run.stdout,
        "rings.txt: cannot be taken apart by straight moves (pieces A, B locked)\n"
    );
    let plan = json(&sb.read("plan.json"));
    assert_eq!(plan["figures"][0]["level"], serde_json::Value::Null);
    assert_eq!(plan["figures"][0]["locked"], serde_json::json!([0, 1]));
}

#[test]
fn a_two_figure_solution_gets_a_plan_per_figure() {
    let sb = Sandbox::new();
    let a = sb.copy_instance("cubes-3-4-5-joined-to-6", "a.txt", "a.txt");
    let b = sb.copy_instance("cubes-3-4-5-joined-to-6", "b.txt", "b.txt");
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../../docs/solutions/cubes-3-4-5-joined-to-6.json"),
    )
    .unwrap();
    let s = sb.write("s.json", &text);
    let run = sb.run(&["disassemble", "--solution", &s, "-o", "plan.json", &a, &b]);
    let lines: Vec<&str> = run.stdout.lines().collect();
    assert_eq!(lines.len(), 2, "{}", run.stdout);
    assert!(lines[0].starts_with("a.txt: ") && lines[1].starts_with("b.txt: "));
    let levels = replay_all(&json(&sb.read("plan.json")), &json(&text));
    let code = if levels.iter().all(Option::is_some) {
        0
    } else {
        1
    };
    run.expect_code(code);
}

#[test]
fn a_time_limit_of_zero_leaves_it_undecided() {
    let sb = Sandbox::new();
    let (fig, s) = puzzle(&sb, "rings", RINGS);
    sb.run(&["disassemble", "--time-limit", "0", "--solution", &s, &fig])
        .expect_code(1)
        .stdout_has(&["rings.txt: not decided (stopped)\n"]);
}

#[test]
fn flat_figures_lift_off() {
    let sb = Sandbox::new();
    sb.write(
        "dominoes.json",
        r#"{"format": "dissection-solution/1", "lattice": "square", "mirror": true,
  "figures": [{"name": "rect.txt", "pieces": [[[0,0],[0,1]], [[1,0],[1,1]], [[2,0],[2,1]], [[3,0],[3,1]]]}]}"#,
    );
    sb.write("rect.txt", "####\n####\n");
    let run = sb.run(&[
        "disassemble",
        "--solution",
        "dominoes.json",
        "-o",
        "p.json",
        "rect.txt",
    ]);
    run.expect_code(0).stderr_has(&["every piece lifts off"]);
    assert_eq!(run.stdout, "rect.txt: apart in 3 moves (level 1)\n");
    let plan = json(&sb.read("p.json"));
    assert_eq!(plan["lattice"], "square");
    assert_eq!(
        plan["figures"][0]["moves"][0]["by"],
        serde_json::json!([0, 0, 1])
    );
}

#[test]
fn bad_input_exits_2() {
    let sb = Sandbox::new();
    let (fig, s) = puzzle(&sb, "soma", SOMA);
    sb.write(
        "other.txt",
        "###\n###\n###\n\n###\n###\n###\n\n###\n###\n##.\n",
    );
    sb.run(&["disassemble", "--solution", &s, "other.txt"])
        .expect_code(2)
        .stderr_has(&["soma.json: not a dissection of the figures given"]);
    sb.run(&["disassemble", "--time-limit", "-1", "--solution", &s, &fig])
        .expect_code(2)
        .stderr_has(&["--time-limit must be a number of seconds >= 0"]);
    sb.run(&["disassemble", "--lattice", "square", "--solution", &s, &fig])
        .expect_code(2)
        .stderr_has(&["the solution is on the cubic lattice, but --lattice square was given"]);
    sb.run(&[
        "disassemble",
        "--solution",
        &s,
        "-o",
        "nope/plan.json",
        &fig,
    ])
    .expect_code(2)
    .stderr_has(&["does not exist"]);
    sb.run(&["disassemble", "--solution", "missing.json", &fig])
        .expect_code(2);
}

/// Two pairs hooked along x: the slab A + B leaves the rings C, D as one group.
const TWO_PAIRS: &str =
    "CCCD\nCDCD\nCDCD\nCDCD\n\nCDCD\nBAAB\nBBBB\nCDCD\n\nCDCD\nCDDD\nCDCD\nCDCD\n";

#[test]
fn a_group_move_is_written_and_replays() {
    let sb = Sandbox::new();
    let (fig, s) = puzzle(&sb, "pairs", TWO_PAIRS);
    let run = sb.run(&[
        "disassemble",
        "--solution",
        &s,
        "-o",
        "plan.json",
        "--quiet",
        &fig,
    ]);
    run.expect_code(0);
    assert_eq!(run.stdout, "pairs.txt: apart in 3 moves (level 1)\n");
    let plan = json(&sb.read("plan.json"));
    assert_eq!(
        plan["figures"][0]["moves"][0]["pieces"],
        serde_json::json!([0, 1])
    );
    let levels = replay_all(&plan, &json(&sb.read("pairs.json")));
    assert_eq!(levels, vec![Some(1)]);
}

#[test]
fn solve_assemblable_records_levels_and_its_plans_replay() {
    let sb = Sandbox::new();
    sb.write("cube.txt", "##\n##\n\n##\n##\n");
    sb.write("slab.txt", "####\n####\n");
    for extra in [
        &["--assemblable"][..],
        &["--rank", "level", "--solutions", "2"],
    ] {
        let mut args = vec![
            "solve",
            "--lattice",
            "cubic",
            "--seed",
            "1",
            "--quiet",
            "-o",
            "s.json",
        ];
        args.extend_from_slice(extra);
        args.extend(["cube.txt", "slab.txt"]);
        sb.run(&args).expect_code(0);
        crate::support::assert_valid(&sb, "cubic", "s.json", &["cube.txt", "slab.txt"]);
        let solution = json(&sb.read("s.json"));
        let levels = solution["levels"].as_array().expect("levels").clone();
        assert_eq!(levels.len(), 2, "{solution}");
        let run = sb.run(&[
            "disassemble",
            "--solution",
            "s.json",
            "-o",
            "p.json",
            "cube.txt",
            "slab.txt",
        ]);
        run.expect_code(0);
        let replayed = replay_all(&json(&sb.read("p.json")), &solution);
        let want: Vec<Option<usize>> = levels
            .iter()
            .map(|l| l.as_u64().map(|l| l as usize))
            .collect();
        assert_eq!(replayed, want);
    }
    let solution = json(&sb.read("s.json"));
    assert_eq!(solution["rank"]["by"], "level");
}

#[test]
fn min_level_on_flat_figures_is_impossible() {
    let sb = Sandbox::new();
    sb.write("a.txt", "####\n");
    sb.write("b.txt", "##\n##\n");
    sb.run(&["solve", "--min-level", "2", "a.txt", "b.txt"])
        .expect_code(1)
        .stderr_has(&["--min-level 2 on a flat lattice"]);
    sb.run(&["solve", "--min-level", "0", "a.txt", "b.txt"])
        .expect_code(2)
        .stderr_has(&["--min-level must be at least 1"]);
}

/// A 4×4×4 cube with a 2×2×2 cavity: no line along an axis through the
/// cavity meets it in one run, so a group can slide into the cavity.
const CAVITY_CUBE: &str =
    "####\n####\n####\n####\n\n####\n#..#\n#..#\n####\n\n####\n#..#\n#..#\n####\n\n####\n####\n####\n####\n";

#[test]
fn solve_min_level_2_interlocks_and_its_plans_replay() {
    // The figures are congruent: one piece is the plain answer (level 0),
    // so --min-level 2 needs a cut into pieces that interlock.
    let sb = Sandbox::new();
    sb.write("a.txt", CAVITY_CUBE);
    sb.write("b.txt", CAVITY_CUBE);
    let args = [
        "solve",
        "--lattice",
        "cubic",
        "--seed",
        "1",
        "--time-limit",
        "60",
        "--min-level",
        "2",
        "--quiet",
        "-o",
        "s.json",
        "a.txt",
        "b.txt",
    ];
    sb.run(&args).expect_code(0);
    crate::support::assert_valid(&sb, "cubic", "s.json", &["a.txt", "b.txt"]);
    let solution = json(&sb.read("s.json"));
    let pieces = solution["figures"][0]["pieces"].as_array().unwrap().len();
    assert!((2..=3).contains(&pieces), "{solution}");
    let run = sb.run(&[
        "disassemble",
        "--lattice",
        "cubic",
        "--solution",
        "s.json",
        "-o",
        "p.json",
        "a.txt",
        "b.txt",
    ]);
    run.expect_code(0);
    let replayed = replay_all(&json(&sb.read("p.json")), &solution);
    assert_eq!(replayed.len(), 2);
    for level in &replayed {
        assert!(level.is_some_and(|l| l >= 2), "{replayed:?}");
    }
    let recorded: Vec<Option<usize>> = solution["levels"]
        .as_array()
        .expect("levels")
        .iter()
        .map(|l| l.as_u64().map(|l| l as usize))
        .collect();
    assert_eq!(recorded, replayed);
}

#[test]
fn min_level_2_on_a_box_is_impossible_at_once() {
    let sb = Sandbox::new();
    sb.write("a.txt", CAVITY_CUBE);
    sb.write(
        "b.txt",
        "#######\n#######\n#######\n#######\n\n#######\n#######\n#######\n#######\n",
    );
    let run = sb.run(&[
        "solve",
        "--lattice",
        "cubic",
        "--time-limit",
        "60",
        "--min-level",
        "2",
        "a.txt",
        "b.txt",
    ]);
    run.expect_code(1)
        .stderr_has(&["figure 2 meets every line along an axis in one run"]);
}
