//! The studio's API on every lattice: `GET /api/lattices` describes each
//! one (the page draws from it), and the shipped `tri3` and `hex` examples
//! solve to verified dissections whose every download is made.

use std::time::Duration;

use axum::http::StatusCode;
use axum::Router;
use dissect_core::io::{parse_figure, parse_solution};
use dissect_core::LatticeKind;
use serde_json::{json, Value};

mod common;
use common::{app, call, call_raw, wait_done};

#[tokio::test]
async fn every_lattice_is_described_for_the_page() {
    let app = app();
    let (s, v) = call(&app, "GET", "/api/lattices", "").await;
    assert_eq!(s, StatusCode::OK);
    let names: Vec<&str> = v["lattices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l["lattice"].as_str().unwrap())
        .collect();
    assert_eq!(names.len(), 5, "{names:?}");
    let (_, info) = call(&app, "GET", "/api/info", "").await;
    let mut listed: Vec<&str> = info["lattices"]
        .as_array()
        .unwrap()
        .iter()
        .map(|l| l.as_str().unwrap())
        .collect();
    let mut described = names.clone();
    listed.sort();
    described.sort();
    assert_eq!(listed, described);
    // Every shipped lattice has an example.
    let (_, ex) = call(&app, "GET", "/api/examples", "").await;
    for n in &names {
        assert!(
            ex.as_array().unwrap().iter().any(|e| e["lattice"] == *n),
            "no example on {n}"
        );
    }
}

async fn solve(app: &Router, lattice: &str, figures: &Value, time_limit: f64) -> Value {
    let body = json!({"lattice": lattice, "seed": 1, "time_limit": time_limit, "figures": figures});
    let (s, v) = call(app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let v = wait_done(app, v["id"].as_u64().unwrap(), Duration::from_secs(90)).await;
    assert_eq!(v["state"], "done", "{v}");
    v["result"].clone()
}

/// The shipped tri3 and hex examples solve; the dissection passes the
/// verifier; every format the lattice lists is made, the others refused.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn tri3_and_hex_examples_solve_and_every_download_is_made() {
    let app = app();
    let (_, lattices) = call(&app, "GET", "/api/lattices", "").await;
    let (_, examples) = call(&app, "GET", "/api/examples", "").await;
    for (lattice, kind) in [("tri3", LatticeKind::Tri3), ("hex", LatticeKind::Hex)] {
        let ex = examples
            .as_array()
            .unwrap()
            .iter()
            .find(|e| e["lattice"] == lattice)
            .unwrap_or_else(|| panic!("a {lattice} example"));
        let texts: Vec<&str> = ex["figures"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f["text"].as_str().unwrap())
            .collect();
        let figures: Vec<Value> = texts.iter().map(|t| json!({"text": t})).collect();
        let r = solve(&app, lattice, &json!(figures), 5.0).await;
        assert_eq!(r["found"], true, "{lattice}: {r}");
        let (_, d) = parse_solution(r["solution_text"].as_str().unwrap()).unwrap();
        let figs: Vec<_> = texts
            .iter()
            .map(|t| parse_figure(t, kind).unwrap())
            .collect();
        let n = dissect_core::verify::verify(&d, &figs).expect("a valid dissection");
        assert_eq!(r["pieces"], n);
        let made: Vec<&str> = lattices["lattices"]
            .as_array()
            .unwrap()
            .iter()
            .find(|l| l["lattice"] == lattice)
            .unwrap()["exports"]
            .as_array()
            .unwrap()
            .iter()
            .map(|f| f.as_str().unwrap())
            .collect();
        let body = json!({"solution": r["solution"]}).to_string();
        for format in [
            "svg",
            "png",
            "cut-sheet",
            "stl",
            "html",
            "animation",
            "ldraw",
        ] {
            let (s, bytes) = call_raw(&app, "POST", &format!("/api/export/{format}"), &body).await;
            if made.contains(&format) {
                assert_eq!(
                    s,
                    StatusCode::OK,
                    "{lattice} {format}: {}",
                    String::from_utf8_lossy(&bytes)
                );
                assert!(!bytes.is_empty());
            } else {
                assert_eq!(s, StatusCode::BAD_REQUEST, "{lattice} {format} is not made");
            }
        }
        assert!(!made.contains(&"ldraw") && made.contains(&"cut-sheet") && made.contains(&"html"));
        let (_, anim) = call_raw(&app, "POST", "/api/export/animation", &body).await;
        let anim: Value = serde_json::from_slice(&anim).unwrap();
        assert_eq!(anim["lattice"], lattice);
        assert_eq!(anim["pieces"].as_array().unwrap().len(), n);
    }
}
