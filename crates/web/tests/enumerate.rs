//! "All solutions" (issue 29): `POST /api/solve` with `"enumerate": true`
//! counts every dissection with the fewest pieces, as the engine's
//! `enumerate` does (the engine's own count is the reference: it is tested
//! against a brute force in `dissect-exact`); each listed class's solution
//! verifies; the count so far is in the snapshot; Stop and the time limit
//! end it with the list marked incomplete; settings it does not take and
//! figures too large are refused with a 400.

use std::collections::HashSet;
use std::sync::atomic::AtomicBool;
use std::time::Duration;

use axum::http::StatusCode;
use axum::Router;
use dissect_core::io::{parse_figure, parse_solution};
use dissect_core::{Cell, Figure, LatticeKind};
use dissect_engine::{EnumerateConfig, TimeLimit};
use dissect_puzzle::Motions;
use serde_json::{json, Value};

mod common;
use common::{app, call, wait_done};

fn square(text: &str) -> Figure {
    parse_figure(text, LatticeKind::Square).unwrap()
}

async fn start(app: &Router, body: Value) -> u64 {
    let (s, v) = call(app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{body}: {v}");
    v["id"].as_u64().unwrap()
}

/// The class of a cut under the first figure's symmetries, as a set key.
fn canonical(motions: &Motions, figure: &Figure, cut: &[Vec<Cell>]) -> Vec<Vec<Cell>> {
    motions.canonical_cut(&motions.symmetries_of(figure.cells()), cut)
}

#[tokio::test]
async fn all_solutions_are_counted_as_the_engine_counts_them() {
    let app = app();
    // 10 dissections in 3 classes (`dissect enumerate` says the same).
    let texts = ["###\n###\n", "####\n##..\n"];
    let figures: Vec<Figure> = texts.iter().map(|t| square(t)).collect();
    let id = start(
        &app,
        json!({"lattice": "square", "enumerate": true, "time_limit": 60,
               "figures": [{"name": "rect", "text": texts[0]}, {"name": "ell", "text": texts[1]}]}),
    )
    .await;
    let v = wait_done(&app, id, Duration::from_secs(90)).await;
    assert_eq!(v["state"], "done", "{v}");
    let r = &v["result"];
    let e = &r["enumeration"];
    let names = vec!["rect".to_string(), "ell".to_string()];
    let engine = dissect_engine::enumerate(
        &figures,
        &names,
        &EnumerateConfig {
            mirror: true,
            time_limit: TimeLimit::new(60.0).unwrap(),
            ..EnumerateConfig::default()
        },
        &AtomicBool::new(false),
        &(),
    )
    .unwrap();
    assert!(engine.complete && engine.minimum);
    assert_eq!(e["complete"], true, "{e}");
    assert_eq!(e["minimum"], true);
    assert_eq!(r["stopped"], false);
    assert_eq!(r["optimal"], true);
    assert_eq!(e["pieces"], engine.pieces);
    assert_eq!(e["dissections"], engine.dissections.len());
    assert_eq!(e["classes"], engine.classes.len());
    assert!(engine.classes.len() >= 2, "a test with several classes");
    // The snapshot's count is the final one.
    assert_eq!(v["enumeration"]["dissections"], engine.dissections.len());
    assert_eq!(v["enumeration"]["classes"], engine.classes.len());
    // One solution per class, each valid, the classes distinct, their
    // sizes summing to the count.
    let list = r["solutions"].as_array().unwrap();
    assert_eq!(list.len(), engine.classes.len());
    assert_eq!(r["solution_text"], list[0]["solution_text"]);
    let motions = Motions::new(LatticeKind::Square, true);
    let mut seen = HashSet::new();
    let mut total = 0;
    for (i, s) in list.iter().enumerate() {
        assert_eq!(s["position"], i + 1);
        let (_, d) = parse_solution(s["solution_text"].as_str().unwrap()).unwrap();
        let n = dissect_core::verify::verify(&d, &figures).expect("a valid dissection");
        assert_eq!(n, engine.pieces);
        assert_eq!(s["pieces"], n);
        assert!(seen.insert(canonical(&motions, &figures[0], &d.pieces()[0])));
        total += s["class_size"].as_u64().unwrap();
        assert_eq!(s["solution"]["enumeration"]["class"], i + 1);
    }
    assert_eq!(total as usize, engine.dissections.len());
}

#[tokio::test]
async fn stop_ends_an_enumeration_with_the_count_so_far_marked_incomplete() {
    let app = app();
    // The 6x6 square into the staircase of base 8: 16 dissections, some
    // seconds of work; stopped long before the end.
    let stair: String = (1..=8).map(|n| format!("{}\n", "#".repeat(n))).collect();
    let id = start(
        &app,
        json!({"lattice": "square", "enumerate": true, "time_limit": 60,
               "figures": [{"text": "######\n".repeat(6)}, {"text": stair}]}),
    )
    .await;
    tokio::time::sleep(Duration::from_millis(300)).await;
    let (s, v) = call(&app, "GET", &format!("/api/solve/{id}"), "").await;
    assert_eq!(s, StatusCode::OK);
    assert!(v["enumeration"].is_object(), "the count so far: {v}");
    let (s, _) = call(&app, "POST", &format!("/api/solve/{id}/stop"), "").await;
    assert_eq!(s, StatusCode::OK);
    let v = wait_done(&app, id, Duration::from_secs(20)).await;
    assert_eq!(v["state"], "done", "{v}");
    let r = &v["result"];
    assert_eq!(r["stopped"], true, "{r}");
    assert_eq!(r["enumeration"]["complete"], false);
    let found = r["enumeration"]["dissections"].as_u64().unwrap();
    assert!(found < 16, "stopped before the end: {r}");
    assert_eq!(r["found"], found > 0);
}

#[tokio::test]
async fn settings_it_does_not_take_and_large_figures_are_refused() {
    let app = app();
    let figs = json!([{"text": "###\n###\n"}, {"text": "######\n"}]);
    for (extra, word) in [
        (json!({"solutions": 3}), "solutions"),
        (json!({"min_piece": 2}), "min_piece"),
        (json!({"seed": 4}), "seed"),
        (json!({"checkerboard": true}), "checkerboard"),
    ] {
        let mut body = json!({"lattice": "square", "enumerate": true, "figures": figs});
        for (k, v) in extra.as_object().unwrap() {
            body[k] = v.clone();
        }
        let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
        assert_eq!(s, StatusCode::BAD_REQUEST, "{v}");
        assert!(
            v["error"]["message"].as_str().unwrap().contains(word),
            "{v}"
        );
    }
    let big = "#############\n".repeat(12);
    let body = json!({"lattice": "square", "enumerate": true,
                      "figures": [{"text": big}, {"text": "############\n".repeat(13)}]});
    let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::BAD_REQUEST, "{v}");
    assert!(
        v["error"]["message"]
            .as_str()
            .unwrap()
            .contains("small figures"),
        "{v}"
    );
}
