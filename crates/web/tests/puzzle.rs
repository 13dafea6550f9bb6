//! The puzzle options of `POST /api/solve` (issue 14): several solutions
//! ranked, keep-whole regions painted as cells or given as a grid, piece-size
//! bounds, the checkerboard rule and the symmetry weight; each solution's
//! assembly count per figure with its `unique` mark; bad or impossible
//! constraints refused with a clear 4xx. Every solution a test gets goes
//! through `dissect_core::verify`, and the constraints are checked on it
//! with the puzzle crate's `Constraints::check`.

use std::collections::HashSet;
use std::time::Duration;

use axum::http::StatusCode;
use axum::Router;
use dissect_core::io::{parse_figure, parse_solution};
use dissect_core::{Figure, LatticeKind};
use dissect_puzzle::scores::canonical;
use dissect_puzzle::{Constraints, KeepRegions, Motions};
use serde_json::{json, Value};

mod common;
use common::{app, call, wait_done};

/// Starts a solve and waits for its end; the final snapshot.
async fn solve(app: &Router, body: Value) -> Value {
    let (s, v) = call(app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{body}: {v}");
    let v = wait_done(app, v["id"].as_u64().unwrap(), Duration::from_secs(60)).await;
    assert_eq!(v["state"], "done", "{v}");
    assert_eq!(v["counting"], false, "{v}");
    v
}

fn square(text: &str) -> Figure {
    parse_figure(text, LatticeKind::Square).unwrap()
}

/// Every solution of a result: verified against `figures` by the core
/// verifier, checked against `constraints`, its assembly counts shaped
/// right; returns each solution's pieces (first figure).
fn solutions(
    result: &Value,
    figures: &[Figure],
    constraints: &Constraints,
) -> Vec<Vec<Vec<[i32; 3]>>> {
    assert_eq!(result["found"], true, "{result}");
    let list = result["solutions"].as_array().expect("a solutions list");
    assert!(!list.is_empty());
    // The best is the first.
    assert_eq!(result["solution_text"], list[0]["solution_text"]);
    let motions = Motions::new(LatticeKind::Square, true);
    list.iter()
        .enumerate()
        .map(|(i, s)| {
            assert_eq!(s["position"], i + 1);
            let (_, d) = parse_solution(s["solution_text"].as_str().unwrap()).unwrap();
            let n = dissect_core::verify::verify(&d, figures).expect("a valid dissection");
            assert_eq!(s["pieces"], n);
            assert_eq!(s["scores"]["pieces"], n);
            assert_eq!(constraints.check(&motions, d.pieces()), vec![], "{s}");
            let counts = s["assemblies"].as_array().unwrap();
            assert_eq!(counts.len(), figures.len(), "{s}");
            for c in counts {
                let unique = c["complete"] == true && c["up_to_symmetry"] == 1;
                assert_eq!(c["unique"], unique, "{c}");
                assert!(
                    c["tilings"].as_u64().unwrap() >= 1,
                    "the solution itself: {c}"
                );
            }
            assert_eq!(
                s["unique"],
                counts.iter().all(|c| c["unique"] == true),
                "{s}"
            );
            d.pieces()[0].clone()
        })
        .collect()
}

const SQUARES_3_4: &str = "###.....\n###.....\n###.####\n....####\n....####\n....####\n";
const SQUARE_5: &str = "#####\n#####\n#####\n#####\n#####\n";

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn several_solutions_come_ranked_with_their_assembly_counts() {
    let app = app();
    let figures = [square(SQUARES_3_4), square(SQUARE_5)];
    let motions = Motions::new(LatticeKind::Square, true);
    for rank in ["smallest", "variance"] {
        let done = solve(
            &app,
            json!({"lattice": "square", "seed": 1, "time_limit": 40, "explorations": 24,
                "solutions": 3, "rank": rank,
                "figures": [{"name": "a.txt", "text": SQUARES_3_4}, {"name": "b.txt", "text": SQUARE_5}]}),
        )
        .await;
        let r = &done["result"];
        let all = solutions(r, &figures, &Constraints::none());
        assert_eq!(all.len(), 3, "{rank}: {r}");
        let forms: HashSet<_> = all.iter().map(|p| canonical(&motions, p)).collect();
        assert_eq!(forms.len(), 3, "different up to the motions");
        let list = r["solutions"].as_array().unwrap();
        for (i, s) in list.iter().enumerate() {
            assert_eq!(s["pieces"], 4, "{s}");
            assert_eq!(s["rank"], json!({"by": rank, "position": i + 1}));
            // The file records the same rank.
            let file: Value = serde_json::from_str(s["solution_text"].as_str().unwrap()).unwrap();
            assert_eq!(file["rank"]["position"], i + 1);
            assert_eq!(s["assemblies"][0]["figure"], "a.txt");
        }
        // Ranked: the smallest piece never grows down the list; the
        // objective (the variance here) never falls.
        for w in list.windows(2) {
            let (a, b) = (&w[0]["scores"], &w[1]["scores"]);
            if rank == "smallest" {
                assert!(a["smallest"].as_u64() >= b["smallest"].as_u64(), "{a} {b}");
            } else {
                assert!(
                    a["objective"].as_f64() <= b["objective"].as_f64(),
                    "{a} {b}"
                );
            }
        }
        assert_eq!(r["ranking"]["by"], rank);
        assert_eq!(r["ranking"]["asked"], 3);
        assert_eq!(r["ranking"]["found"], 3);
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_plain_solve_lists_its_one_answer_with_counts_and_the_unique_mark() {
    // 2×3 into 1×6: two bars, one way into each figure: unique.
    let app = app();
    let figures = [square("###\n###\n"), square("######\n")];
    let done = solve(
        &app,
        json!({"lattice": "square", "time_limit": 20,
            "figures": [{"name": "r.txt", "text": "###\n###\n"}, {"name": "b.txt", "text": "######\n"}]}),
    )
    .await;
    let r = &done["result"];
    assert!(r.get("ranking").is_none(), "a plain run ranks nothing: {r}");
    let all = solutions(r, &figures, &Constraints::none());
    assert_eq!(all.len(), 1);
    let s = &r["solutions"][0];
    assert_eq!(s["rank"], Value::Null);
    assert_eq!(s["unique"], true, "{s}");
    for c in s["assemblies"].as_array().unwrap() {
        assert_eq!(
            (c["tilings"].as_u64(), c["up_to_symmetry"].as_u64()),
            (Some(1), Some(1)),
            "{c}"
        );
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn painted_keep_regions_are_honoured_where_the_client_painted_them() {
    let app = app();
    let rect = square("###\n###\n");
    let figures = [rect.clone(), square("######\n")];
    // The left column kept whole: three vertical dominoes (two bars without it).
    let c = Constraints::none()
        .with_keep(KeepRegions::parse("a..\na..\n", 0, std::slice::from_ref(&rect)).unwrap());
    // As cells, with the figure drawn away from the origin (the editor's
    // coordinates): the regions move with it.
    let rect_cells: Vec<Value> = (0..2)
        .flat_map(|y| (0..3).map(move |x| json!([x + 4, y + 2])))
        .collect();
    let painted = json!({"lattice": "square", "time_limit": 20,
        "figures": [{"name": "r.txt", "cells": rect_cells}, {"name": "b.txt", "text": "######\n"}],
        "keep": [{"figure": 1, "regions": {"a": [[4, 2], [4, 3]]}}]});
    // As a regions grid, in the figure file's coordinates.
    let grid = json!({"lattice": "square", "time_limit": 20,
        "figures": [{"name": "r.txt", "text": "###\n###\n"}, {"name": "b.txt", "text": "######\n"}],
        "keep": [{"figure": 1, "text": "a..\na..\n"}]});
    for body in [painted, grid] {
        let done = solve(&app, body.clone()).await;
        let r = &done["result"];
        let all = solutions(r, &figures, &c);
        let mut areas: Vec<usize> = all[0].iter().map(Vec::len).collect();
        areas.sort();
        assert_eq!(areas, vec![2, 2, 2], "{body}: {r}");
        // The result records the constraint as the solution file does.
        assert_eq!(
            r["ranking"]["constraints"]["keep"],
            json!([{"figure": 1, "regions": {"a": [[0, 0], [0, 1]]}}])
        );
        assert_eq!(r["solution"]["constraints"], r["ranking"]["constraints"]);
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn size_bounds_checkerboard_and_symmetry_weight_are_honoured() {
    let app = app();
    let figures = [square("###\n###\n"), square("######\n")];
    let texts = json!([{"text": "###\n###\n"}, {"text": "######\n"}]);
    // At most 2 cells a piece: three dominoes.
    let done = solve(
        &app,
        json!({"lattice": "square", "time_limit": 20, "figures": texts, "max_piece": 2}),
    )
    .await;
    let c = Constraints::none().with_sizes(None, Some(2));
    let all = solutions(&done["result"], &figures, &c);
    assert_eq!(all[0].len(), 3);
    // At least 3 cells a piece (and a symmetry weight): honoured, recorded.
    let done = solve(
        &app,
        json!({"lattice": "square", "time_limit": 20, "figures": texts, "min_piece": 3,
            "symmetry_weight": 0.5}),
    )
    .await;
    let c = Constraints::none().with_sizes(Some(3), None);
    let all = solutions(&done["result"], &figures, &c);
    assert!(all[0].iter().all(|p| p.len() >= 3));
    assert_eq!(
        done["result"]["ranking"]["constraints"],
        json!({"min_piece": 3, "symmetry_weight": 0.5})
    );
    let s = &done["result"]["solutions"][0]["scores"];
    let objective = s["variance"].as_f64().unwrap() - 0.5 * s["symmetry"].as_f64().unwrap();
    assert!(
        (s["objective"].as_f64().unwrap() - objective).abs() < 1e-9,
        "{s}"
    );
    // The checkerboard: the L turned half a turn (the only motion between
    // them) changes colours, so it takes 2 pieces instead of 1.
    let (l, m) = ("#.\n#.\n##\n", "##\n.#\n.#\n");
    let figures = [square(l), square(m)];
    let body = |on: bool| {
        json!({"lattice": "square", "time_limit": 20, "checkerboard": on,
            "figures": [{"text": l}, {"text": m}]})
    };
    let free = solve(&app, body(false)).await;
    assert_eq!(
        solutions(&free["result"], &figures, &Constraints::none())[0].len(),
        1
    );
    let c = Constraints::none().with_checkerboard(true);
    let kept = solve(&app, body(true)).await;
    assert_eq!(solutions(&kept["result"], &figures, &c)[0].len(), 2);
    assert_eq!(
        kept["result"]["ranking"]["constraints"]["checkerboard"],
        true
    );
}

#[tokio::test]
async fn bad_and_impossible_constraints_get_clear_4xx() {
    let app = app();
    let base = || {
        json!({"lattice": "square", "time_limit": 5,
            "figures": [{"name": "r.txt", "text": "###\n###\n"}, {"name": "b.txt", "text": "######\n"}]})
    };
    let with = |extra: Value| {
        let mut b = base();
        for (k, v) in extra.as_object().unwrap() {
            b[k] = v.clone();
        }
        b
    };
    let cases = [
        // Malformed: 400 bad_constraints / bad_value.
        (
            json!({"min_piece": 0}),
            400,
            "bad_constraints",
            "min_piece must be at least 1",
        ),
        (
            json!({"symmetry_weight": -1.0}),
            400,
            "bad_constraints",
            "symmetry_weight must be a number >= 0",
        ),
        (
            json!({"keep": [{"figure": 1, "regions": {"A": [[0, 0]]}}]}),
            400,
            "bad_constraints",
            "keep[0]: a region is named by one letter a-z, not \"A\"",
        ),
        (
            json!({"keep": [{"figure": 1, "regions": {"ab": [[0, 0]]}}]}),
            400,
            "bad_constraints",
            "not \"ab\"",
        ),
        (
            json!({"keep": [{"figure": 1, "regions": {"a": [[3, 0]]}}]}),
            400,
            "bad_constraints",
            "keep[0]: region 'a': cell [3, 0] is not a cell of figure 1",
        ),
        (
            json!({"keep": [{"figure": 1, "regions": {"a": [[0, 0, 0, 0]]}}]}),
            400,
            "bad_constraints",
            "is not a cell of the square lattice",
        ),
        (
            json!({"keep": [{"figure": 3, "regions": {"a": [[0, 0]]}}]}),
            400,
            "bad_constraints",
            "figure 3 does not exist",
        ),
        (
            json!({"keep": [{"figure": 0, "text": "a"}]}),
            400,
            "bad_constraints",
            "numbered from 1",
        ),
        (
            json!({"keep": [{"figure": 1, "text": "a..\n.A.\n"}]}),
            400,
            "bad_constraints",
            "keep[0]: line 2, column 2",
        ),
        (
            json!({"keep": [{"figure": 1, "text": "...\n"}]}),
            400,
            "bad_constraints",
            "no region is marked",
        ),
        (
            json!({"keep": [{"figure": 1}]}),
            400,
            "bad_constraints",
            "give either",
        ),
        (
            json!({"keep": [{"figure": 1, "letters": "a"}]}),
            400,
            "bad_json",
            "unknown field",
        ),
        (
            json!({"rank": "fastest"}),
            400,
            "bad_value",
            "unknown ranking \"fastest\"",
        ),
        (
            json!({"solutions": 0}),
            400,
            "bad_value",
            "solutions must be from 1 to",
        ),
        (
            json!({"solutions": 51}),
            400,
            "bad_value",
            "solutions must be from 1 to 50",
        ),
        // Impossible: 422 impossible_constraints.
        (
            json!({"min_piece": 4, "max_piece": 3}),
            422,
            "impossible_constraints",
            "the constraints cannot all hold: impossible: min_piece 4 is larger than max_piece 3",
        ),
        (
            json!({"min_piece": 7}),
            422,
            "impossible_constraints",
            "min_piece 7 is larger than the figures (6 cells)",
        ),
        (
            json!({"max_piece": 1, "keep": [{"figure": 1, "text": "aa.\n"}]}),
            422,
            "impossible_constraints",
            "region 'a' of figure 1 has 2 cells, more than max_piece 1",
        ),
    ];
    for (extra, status, want_code, want) in cases {
        let body = with(extra.clone());
        let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
        assert_eq!(s.as_u16(), status, "{extra}: {v}");
        assert_eq!(v["error"]["code"], want_code, "{extra}: {v}");
        let m = v["error"]["message"].as_str().unwrap();
        assert!(m.contains(want), "{extra}: {m}");
    }
}

#[tokio::test]
async fn a_checkerboard_that_cannot_hold_gets_a_clear_4xx() {
    let app = app();
    // Not on a lattice without one (hex: three hexagons meet at a corner);
    // impossible when the figures' colours differ.
    let hex = json!({"lattice": "hex", "checkerboard": true,
        "figures": [{"cells": [[0, 0], [1, 0]]}, {"cells": [[0, 0], [1, 0]]}]});
    let (s, v) = call(&app, "POST", "/api/solve", &hex.to_string()).await;
    assert_eq!(s, StatusCode::BAD_REQUEST, "{v}");
    assert!(
        v["error"]["message"]
            .as_str()
            .unwrap()
            .contains("checkerboard needs a lattice"),
        "{v}"
    );
    let colours = json!({"lattice": "square", "checkerboard": true,
        "figures": [{"text": "#.#\n.#.\n"}, {"text": "###\n"}]});
    let (s, v) = call(&app, "POST", "/api/solve", &colours.to_string()).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
    assert!(
        v["error"]["message"]
            .as_str()
            .unwrap()
            .contains("black cells"),
        "{v}"
    );
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn constraints_no_dissection_can_meet_end_without_an_answer() {
    // The whole 2×3 kept in one piece cannot become a 1×6 bar: the run ends
    // at its time limit with no dissection, never a broken one.
    let app = app();
    let done = solve(
        &app,
        json!({"lattice": "square", "time_limit": 3,
            "figures": [{"text": "###\n###\n"}, {"text": "######\n"}],
            "keep": [{"figure": 1, "text": "aaa\naaa\n"}]}),
    )
    .await;
    let r = &done["result"];
    assert_eq!(r["found"], false, "{r}");
    assert!(r["ranking"]["constraints"]["keep"].is_array(), "{r}");
}

#[tokio::test]
async fn min_level_reaches_the_solver_and_a_box_is_refused() {
    let app = app();
    // A 4×4×4 cube with a 2×2×2 cavity, twice: one piece plainly (level
    // 0); min_level 2 needs a cut into pieces that interlock.
    let cavity = "####\n####\n####\n####\n\n####\n#..#\n#..#\n####\n\n####\n#..#\n#..#\n####\n\n####\n####\n####\n####\n";
    let v = solve(
        &app,
        json!({"lattice": "cubic", "time_limit": 30, "seed": 1, "min_level": 2,
            "figures": [{"name": "a.txt", "text": cavity}, {"name": "b.txt", "text": cavity}]}),
    )
    .await;
    let result = &v["result"];
    assert_eq!(result["found"], true, "{result}");
    let s = &result["solutions"][0];
    let (_, d) = parse_solution(s["solution_text"].as_str().unwrap()).unwrap();
    let figure = parse_figure(cavity, LatticeKind::Cubic).unwrap();
    dissect_core::verify::verify(&d, &[figure.clone(), figure]).expect("a valid dissection");
    let c = Constraints::none().with_assembly(false, Some(2));
    let motions = Motions::new(LatticeKind::Cubic, true);
    assert_eq!(c.check(&motions, d.pieces()), vec![], "{s}");
    let levels = s["solution"]["levels"].as_array().expect("levels");
    assert_eq!(levels.len(), 2, "{s}");
    assert!(levels.iter().all(|l| l.as_u64() >= Some(2)), "{s}");
    assert_eq!(
        result["ranking"]["constraints"],
        json!({"assemblable": true, "min_level": 2})
    );
    // In a box no group slides before it comes free: refused at once.
    let body = json!({"lattice": "cubic", "time_limit": 5, "min_level": 2,
        "figures": [{"text": "##\n##\n\n##\n##\n"}, {"text": "####\n####\n"}]});
    let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
    assert!(
        v["error"]["message"]
            .as_str()
            .unwrap()
            .contains("min_level 2: figure 1 meets every line"),
        "{v}"
    );
}
