//! The JSON API, request by request (no network: `tower::ServiceExt::oneshot`
//! on the router), and one real listener on 127.0.0.1 for the event stream.

use std::time::{Duration, Instant};

use axum::body::Body;
use axum::http::{Request, StatusCode};
use axum::Router;
use dissect_core::io::{parse_figure, parse_solution};
use dissect_core::LatticeKind;
use dissect_web::Limits;
use http_body_util::BodyExt;
use serde_json::{json, Value};
use tower::ServiceExt;

mod common;
use common::{app, call, wait_done};

fn code(v: &Value) -> &str {
    v["error"]["code"].as_str().unwrap_or("(no error code)")
}

fn message(v: &Value) -> &str {
    v["error"]["message"].as_str().unwrap_or("")
}

const RECT_3X4: &str = "###\n###\n###\n###\n";
const RECT_6X2: &str = "######\n######\n";
const RECT_2X5: &str = "##\n##\n##\n##\n##\n";

#[tokio::test]
async fn garbage_json_is_a_400_with_its_position() {
    let app = app();
    for body in [
        "{garbage",
        "",
        "[1,2",
        "{\"lattice\": \"square\", \"figures\": 7}",
    ] {
        let (s, v) = call(&app, "POST", "/api/solve", body).await;
        assert_eq!(s, StatusCode::BAD_REQUEST, "{body:?}: {v}");
        assert_eq!(code(&v), "bad_json", "{body:?}: {v}");
    }
    let (_, v) = call(&app, "POST", "/api/solve", "{\n  \"lattice\": ,\n}").await;
    assert_eq!(v["error"]["details"]["line"], 2, "{v}");
}

#[tokio::test]
async fn unknown_lattice_is_named() {
    let body = json!({"lattice": "hexagon", "figures": [{"text": RECT_3X4}, {"text": RECT_6X2}]});
    let (s, v) = call(&app(), "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::BAD_REQUEST);
    assert_eq!(code(&v), "unknown_lattice");
    assert!(message(&v).contains("\"hexagon\""), "{v}");
}

#[tokio::test]
async fn unequal_areas_list_every_count() {
    let body = json!({"lattice": "square", "figures": [
        {"name": "a.txt", "text": RECT_3X4},
        {"name": "b.txt", "text": RECT_2X5},
    ]});
    let (s, v) = call(&app(), "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY);
    assert_eq!(code(&v), "unequal_areas");
    assert_eq!(
        message(&v),
        "figures have different areas: a.txt: 12 cells, b.txt: 10 cells"
    );
    assert_eq!(v["error"]["details"]["areas"][1]["short_by"], 2);
}

#[tokio::test]
async fn oversized_figures_are_refused() {
    let app = app();
    // 15x15 = 225 cells > 200.
    let big = "###############\n".repeat(15);
    let body = json!({"lattice": "square", "figures": [{"text": big}, {"text": big}]});
    let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::PAYLOAD_TOO_LARGE, "{v}");
    assert_eq!(code(&v), "too_large");
    assert!(message(&v).contains("225 cells"), "{v}");
    // A cell far away.
    let body = json!({"lattice": "square", "figures": [{"cells": [[0, 0], [1000000, 0]]}, {"cells": [[0, 0], [1, 0]]}]});
    let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::UNPROCESSABLE_ENTITY, "{v}");
    assert!(message(&v).contains("out of range"), "{v}");
    // Too many figures.
    let figs: Vec<Value> = (0..5).map(|_| json!({"text": "#"})).collect();
    let body = json!({"lattice": "square", "figures": figs});
    let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::PAYLOAD_TOO_LARGE, "{v}");
    assert!(message(&v).contains("at most 4"), "{v}");
}

#[tokio::test]
async fn bad_figures_and_options_name_the_problem() {
    let app = app();
    let cases = [
        (
            json!({"lattice": "square", "figures": [{"name": "x.txt", "text": "#a#"}, {"text": "###"}]}),
            "x.txt: line 1, column 2",
        ),
        (
            json!({"lattice": "tri4", "figures": [{"cells": [[0, 0, 7]]}, {"cells": [[0, 0, 1]]}]}),
            "is not a cell of the tri4 lattice (a tri4 cell is [x, y, t] with t in 0..=3)",
        ),
        (
            json!({"lattice": "square", "figures": [{"text": "##"}, {"text": "##"}], "area_weight": -1}),
            "area_weight",
        ),
        (
            json!({"lattice": "square", "figures": [{"text": "##"}, {"text": "##"}], "time_limit": 1e9}),
            "time_limit",
        ),
        (
            json!({"lattice": "square", "figures": [{"text": "##"}]}),
            "at least two figures",
        ),
        (
            json!({"lattice": "square", "figures": [{"text": "##", "cells": [[0, 0]]}, {"text": "##"}]}),
            "either",
        ),
    ];
    for (body, want) in cases {
        let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
        assert!(s.is_client_error(), "{body}: {s}");
        assert!(message(&v).contains(want), "{body}: {v}");
    }
}

#[tokio::test]
async fn unknown_routes_and_methods_get_json_errors() {
    let app = app();
    let (s, v) = call(&app, "GET", "/api/nothing", "").await;
    assert_eq!((s, code(&v)), (StatusCode::NOT_FOUND, "not_found"));
    let (s, v) = call(&app, "GET", "/api/solve/12345", "").await;
    assert_eq!((s, code(&v)), (StatusCode::NOT_FOUND, "not_found"));
    let (s, v) = call(&app, "POST", "/api/solve/abc/stop", "").await;
    assert_eq!((s, code(&v)), (StatusCode::NOT_FOUND, "not_found"));
    let (s, v) = call(&app, "DELETE", "/api/solve", "").await;
    assert_eq!(
        (s, code(&v)),
        (StatusCode::METHOD_NOT_ALLOWED, "method_not_allowed")
    );
}

#[tokio::test]
async fn the_page_and_its_assets_are_served() {
    let app = app();
    for (uri, ty) in [
        ("/", "text/html"),
        ("/studio.js", "text/javascript"),
        ("/player.js", "text/javascript"),
        ("/palette.js", "text/javascript"),
    ] {
        let res = app
            .clone()
            .oneshot(Request::get(uri).body(Body::empty()).unwrap())
            .await
            .unwrap();
        assert_eq!(res.status(), StatusCode::OK, "{uri}");
        let got = res.headers()["content-type"].to_str().unwrap().to_string();
        assert!(got.starts_with(ty), "{uri}: {got}");
    }
}

#[tokio::test]
async fn figures_route_reads_texts_and_cells() {
    let body = json!({"lattice": "tri4", "figures": [
        {"name": "t.txt", "text": "#9\n6.\n"},
        {"cells": [[3, 3, 0], [3, 3, 1]]},
    ]});
    let (s, v) = call(&app(), "POST", "/api/figures", &body.to_string()).await;
    assert_eq!(s, StatusCode::OK, "{v}");
    assert_eq!(v["figures"][0]["count"], 8);
    assert_eq!(v["figures"][1]["count"], 2);
    // Moved to start at block (0, 0): the text and the cells agree.
    assert_eq!(v["figures"][1]["text"], "3\n");
    assert_eq!(v["figures"][1]["cells"], json!([[0, 0, 0], [0, 0, 1]]));
    assert_eq!(v["equal_areas"], false);
}

/// Every dissection the API returns passes the core verifier.
fn check(result: &Value, lattice: LatticeKind, texts: &[&str]) -> usize {
    let (_, d) = parse_solution(result["solution_text"].as_str().unwrap()).unwrap();
    let figs: Vec<_> = texts
        .iter()
        .map(|t| parse_figure(t, lattice).unwrap())
        .collect();
    dissect_core::verify::verify(&d, &figs).expect("a valid dissection")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_solve_runs_to_a_verified_dissection() {
    let app = app();
    let body = json!({"lattice": "square", "seed": 2, "time_limit": 30,
        "figures": [{"name": "a.txt", "text": RECT_3X4}, {"name": "b.txt", "text": RECT_6X2}]});
    let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let done = wait_done(&app, v["id"].as_u64().unwrap(), Duration::from_secs(30)).await;
    assert_eq!(done["state"], "done", "{done}");
    let r = &done["result"];
    assert_eq!(r["found"], true, "{done}");
    let n = check(r, LatticeKind::Square, &[RECT_3X4, RECT_6X2]);
    assert_eq!(r["pieces"], n);
    assert_eq!(r["solution"]["figures"][1]["name"], "b.txt");
}

/// 11x11 square and three squares (6, 6, 7): a long search, stopped at once.
const SQUARE_11: &str = "###########\n###########\n###########\n###########\n###########\n###########\n###########\n###########\n###########\n###########\n###########\n";
const SQUARES_6_6_7: &str = "\
######.######.#######
######.######.#######
######.######.#######
######.######.#######
######.######.#######
######.######.#######
..............#######
";

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn stop_ends_a_solve_early_and_frees_its_slot() {
    let app = app();
    let body = json!({"lattice": "square", "time_limit": 60,
        "figures": [{"text": SQUARES_6_6_7}, {"text": SQUARE_11}]});
    let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let id = v["id"].as_u64().unwrap();
    // The only slot is taken: a second solve is refused.
    let (s, v) = call(&app, "POST", "/api/solve", &body.to_string()).await;
    assert_eq!(
        (s, code(&v)),
        (StatusCode::TOO_MANY_REQUESTS, "busy"),
        "{v}"
    );

    tokio::time::sleep(Duration::from_millis(300)).await;
    let t0 = Instant::now();
    let (s, v) = call(&app, "POST", &format!("/api/solve/{id}/stop"), "").await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(v["stop_requested"], true);
    let done = wait_done(&app, id, Duration::from_secs(20)).await;
    assert!(t0.elapsed() < Duration::from_secs(20));
    assert_eq!(done["state"], "done", "{done}");
    let r = &done["result"];
    if r["found"] == true {
        check(r, LatticeKind::Square, &[SQUARES_6_6_7, SQUARE_11]);
    } else {
        assert_eq!(r["stopped"], true, "{done}");
        assert!(r["best_mismatch"].as_u64().unwrap() > 0, "{done}");
    }
    // The slot is free again.
    let small = json!({"lattice": "square", "figures": [{"text": "##"}, {"text": "#\n#"}]});
    let (s, v) = call(&app, "POST", "/api/solve", &small.to_string()).await;
    assert_eq!(s, StatusCode::ACCEPTED, "{v}");
    let done = wait_done(&app, v["id"].as_u64().unwrap(), Duration::from_secs(10)).await;
    assert_eq!(done["result"]["pieces"], 1, "{done}");
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn events_stream_progress_then_done_over_a_real_socket() {
    let server = dissect_web::Server::bind(
        "127.0.0.1:0".parse().unwrap(),
        Limits::new(200, 64, 4, 1, 60.0, 1),
    )
    .await
    .unwrap();
    let addr = server.local_addr().unwrap();
    let (tx, rx) = tokio::sync::oneshot::channel::<()>();
    let handle = tokio::spawn(server.run(async {
        let _ = rx.await;
    }));

    let http = |method: &'static str, path: String, body: String| async move {
        use tokio::io::{AsyncReadExt, AsyncWriteExt};
        let mut s = tokio::net::TcpStream::connect(addr).await.unwrap();
        let req = format!(
            "{method} {path} HTTP/1.0\r\nhost: {addr}\r\ncontent-type: application/json\r\ncontent-length: {}\r\nconnection: close\r\n\r\n{body}",
            body.len()
        );
        s.write_all(req.as_bytes()).await.unwrap();
        let mut out = String::new();
        tokio::time::timeout(Duration::from_secs(30), s.read_to_string(&mut out))
            .await
            .expect("the response ends")
            .unwrap();
        out
    };
    let body = json!({"lattice": "square", "time_limit": 30,
        "figures": [{"text": RECT_3X4}, {"text": RECT_6X2}]});
    let res = http("POST", "/api/solve".into(), body.to_string()).await;
    assert!(res.starts_with("HTTP/1.0 202"), "{res}");
    let json_start = res.find("{\"").unwrap();
    let json_end = res.rfind('}').unwrap();
    let v: Value = serde_json::from_str(&res[json_start..=json_end]).unwrap();
    let events = http("GET", v["events"].as_str().unwrap().into(), String::new()).await;
    assert!(events.contains("text/event-stream"), "{events}");
    let done: Vec<&str> = events
        .lines()
        .filter(|l| l.starts_with("event: done"))
        .collect();
    assert_eq!(done.len(), 1, "{events}");
    let last = events
        .lines()
        .rev()
        .find_map(|l| l.strip_prefix("data: "))
        .unwrap();
    let last: Value = serde_json::from_str(last).unwrap();
    assert_eq!(last["state"], "done");
    check(&last["result"], LatticeKind::Square, &[RECT_3X4, RECT_6X2]);
    let _ = tx.send(());
    handle.await.unwrap().unwrap();
}

/// A 2-piece dissection of a 2x2 square into a 4x1 bar.
const SOLUTION_2X2_TO_4X1: &str = r#"{"format": "dissection-solution/1", "lattice": "square", "mirror": true,
  "figures": [
    {"name": "a.txt", "pieces": [[[0,0],[1,0]], [[0,1],[1,1]]]},
    {"name": "b.txt", "pieces": [[[0,0],[1,0]], [[2,0],[3,0]]]}
  ]}"#;

async fn export(app: &Router, format: &str, body: &Value) -> (StatusCode, String, Vec<u8>) {
    let req = Request::post(format!("/api/export/{format}"))
        .header("content-type", "application/json")
        .body(Body::from(body.to_string()))
        .unwrap();
    let res = app.clone().oneshot(req).await.unwrap();
    let status = res.status();
    let disposition = res
        .headers()
        .get("content-disposition")
        .map(|v| v.to_str().unwrap().to_string())
        .unwrap_or_default();
    let bytes = res.into_body().collect().await.unwrap().to_bytes().to_vec();
    (status, disposition, bytes)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn exports_are_made_by_the_renderer() {
    let app = app();
    let solution: Value = serde_json::from_str(SOLUTION_2X2_TO_4X1).unwrap();
    let (s, name, svg) = export(&app, "svg", &json!({"solution": solution})).await;
    assert_eq!(s, StatusCode::OK);
    assert!(name.contains("dissection.svg"), "{name}");
    let svg = String::from_utf8(svg).unwrap();
    assert!(svg.contains("<svg") && svg.contains("</svg>"), "{svg}");
    // The solution may also come as its text.
    let (s, _, png) = export(&app, "png", &json!({"solution": SOLUTION_2X2_TO_4X1})).await;
    assert_eq!(s, StatusCode::OK);
    assert_eq!(&png[..8], b"\x89PNG\r\n\x1a\n");
    let (s, name, zip) = export(
        &app,
        "stl",
        &json!({"solution": solution, "thickness_mm": 3}),
    )
    .await;
    assert_eq!(s, StatusCode::OK);
    assert!(name.contains(".zip"), "{name}");
    assert_eq!(&zip[..2], b"PK");
    // One STL per piece: piece-01-A.stl and piece-02-B.stl are named in the archive.
    let text = String::from_utf8_lossy(&zip);
    assert!(text.contains("piece-01-A.stl") && text.contains("piece-02-B.stl"));
}

#[tokio::test]
async fn bad_export_requests_get_json_errors() {
    let app = app();
    let solution: Value = serde_json::from_str(SOLUTION_2X2_TO_4X1).unwrap();
    let cases = [
        (
            "svg",
            json!({"solution": 5}),
            StatusCode::BAD_REQUEST,
            "solution",
        ),
        (
            "svg",
            json!({"solution": "{nope"}),
            StatusCode::UNPROCESSABLE_ENTITY,
            "line 1",
        ),
        (
            "gif",
            json!({"solution": solution}),
            StatusCode::NOT_FOUND,
            "unknown export format",
        ),
        (
            "stl",
            json!({"solution": solution, "cell_mm": -1}),
            StatusCode::BAD_REQUEST,
            "",
        ),
        (
            "svg",
            json!({"solution": {"format": "dissection-solution/1", "lattice": "square", "figures": [{"pieces": [[[0, 0], [99999, 0]]]}]}}),
            StatusCode::PAYLOAD_TOO_LARGE,
            "beyond",
        ),
    ];
    for (format, body, status, want) in cases {
        let (s, _, bytes) = export(&app, format, &body).await;
        let v: Value = serde_json::from_slice(&bytes).unwrap();
        assert_eq!(s, status, "{format} {body}: {v}");
        assert!(message(&v).contains(want), "{format} {body}: {v}");
    }
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn cut_sheets_and_ldraw_models_follow_the_lattice() {
    let app = app();
    let solution: Value = serde_json::from_str(SOLUTION_2X2_TO_4X1).unwrap();
    let (s, name, sheet) = export(
        &app,
        "cut-sheet",
        &json!({"solution": solution, "cell_mm": 20}),
    )
    .await;
    assert_eq!(s, StatusCode::OK);
    assert!(name.contains("cut-sheet.svg"), "{name}");
    let sheet = String::from_utf8(sheet).unwrap();
    assert!(sheet.contains("mm"), "{sheet}");
    let (s, name, zip) = export(
        &app,
        "ldraw",
        &json!({"solution": solution, "parts": "brick"}),
    )
    .await;
    assert_eq!(s, StatusCode::OK);
    assert!(name.contains("ldraw.zip"), "{name}");
    assert_eq!(&zip[..2], b"PK");
    let (s, _, bytes) = export(
        &app,
        "ldraw",
        &json!({"solution": solution, "parts": "duplo"}),
    )
    .await;
    assert_eq!(
        s,
        StatusCode::BAD_REQUEST,
        "{}",
        String::from_utf8_lossy(&bytes)
    );
    // No LEGO triangles, no cut sheet of cubes: clear errors.
    let tri = json!({"solution": {"format": "dissection-solution/1", "lattice": "tri4", "figures": [
        {"pieces": [[[0, 0, 0]]]}, {"pieces": [[[5, 5, 0]]]}]}});
    let (s, _, bytes) = export(&app, "ldraw", &tri).await;
    let v: Value = serde_json::from_slice(&bytes).unwrap();
    assert_eq!(s, StatusCode::BAD_REQUEST, "{v}");
    assert!(message(&v).contains("LDraw"), "{v}");
    let cubes = json!({"solution": {"format": "dissection-solution/1", "lattice": "cubic", "figures": [
        {"pieces": [[[0, 0, 0]]]}, {"pieces": [[[0, 0, 1]]]}]}});
    let (s, _, bytes) = export(&app, "cut-sheet", &cubes).await;
    let v: Value = serde_json::from_slice(&bytes).unwrap();
    assert_eq!(s, StatusCode::BAD_REQUEST, "{v}");
    assert!(message(&v).contains("2D"), "{v}");
}

async fn rasterize(app: &Router, query: &str, body: &[u8]) -> (StatusCode, Value) {
    let req = Request::post(format!("/api/rasterize?{query}"))
        .body(Body::from(body.to_vec()))
        .unwrap();
    let res = app.clone().oneshot(req).await.unwrap();
    let status = res.status();
    let bytes = res.into_body().collect().await.unwrap().to_bytes();
    (status, serde_json::from_slice(&bytes).unwrap())
}

const DISC_SVG: &str = r#"<svg xmlns="http://www.w3.org/2000/svg" width="100" height="80"><circle cx="50" cy="40" r="35" fill="black"/></svg>"#;

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn pictures_are_rasterized_to_the_asked_cell_count() {
    let app = app();
    for (query, count) in [
        ("lattice=square&cells=60&name=disc.txt", 60),
        ("lattice=tri4&cells=90", 90),
        ("lattice=cubic&cells=30", 30),
    ] {
        let (s, v) = rasterize(&app, query, DISC_SVG.as_bytes()).await;
        assert_eq!(s, StatusCode::OK, "{query}: {v}");
        assert_eq!(v["count"], count, "{query}: {v}");
        assert_eq!(v["min"], json!([0, 0, 0]), "{query}: {v}");
        // The text is a figure of that many cells.
        let lattice: LatticeKind = v["lattice"].as_str().unwrap().parse().unwrap();
        let f = parse_figure(v["text"].as_str().unwrap(), lattice).unwrap();
        assert_eq!(f.len(), count);
    }
    let cases = [
        (
            "lattice=square&cells=60",
            b"not a picture".as_slice(),
            StatusCode::UNPROCESSABLE_ENTITY,
            "not a picture",
        ),
        (
            "lattice=square&cells=60",
            b"".as_slice(),
            StatusCode::BAD_REQUEST,
            "empty",
        ),
        (
            "lattice=octagon&cells=60",
            DISC_SVG.as_bytes(),
            StatusCode::BAD_REQUEST,
            "unknown lattice",
        ),
        (
            "lattice=square",
            DISC_SVG.as_bytes(),
            StatusCode::BAD_REQUEST,
            "cells",
        ),
        (
            "lattice=square&cells=0",
            DISC_SVG.as_bytes(),
            StatusCode::BAD_REQUEST,
            "at least 1",
        ),
        (
            "lattice=square&cells=100000",
            DISC_SVG.as_bytes(),
            StatusCode::PAYLOAD_TOO_LARGE,
            "200",
        ),
    ];
    for (query, body, status, want) in cases {
        let (s, v) = rasterize(&app, query, body).await;
        assert_eq!(s, status, "{query}: {v}");
        assert!(message(&v).contains(want), "{query}: {v}");
    }
}

#[tokio::test]
async fn other_sites_cannot_drive_the_studio() {
    let app = app();
    let send = |host: &'static str, ty: &'static str| {
        let app = app.clone();
        async move {
            let req = Request::post("/api/figures")
                .header("host", host)
                .header("content-type", ty)
                .body(Body::from(
                    r##"{"lattice": "square", "figures": [{"text": "#"}]}"##,
                ))
                .unwrap();
            let res = app.oneshot(req).await.unwrap();
            let status = res.status();
            let bytes = res.into_body().collect().await.unwrap().to_bytes();
            (status, serde_json::from_slice::<Value>(&bytes).unwrap())
        }
    };
    let (s, v) = send("127.0.0.1:7878", "application/json").await;
    assert_eq!(s, StatusCode::OK, "{v}");
    let (s, _) = send("localhost:7878", "application/json; charset=utf-8").await;
    assert_eq!(s, StatusCode::OK);
    let (s, _) = send("[::1]:7878", "application/json").await;
    assert_eq!(s, StatusCode::OK);
    // DNS rebinding: a foreign name that resolves to 127.0.0.1.
    let (s, v) = send("evil.example:7878", "application/json").await;
    assert_eq!((s, code(&v)), (StatusCode::FORBIDDEN, "forbidden"), "{v}");
    // A cross-site form post.
    let (s, v) = send("127.0.0.1:7878", "text/plain").await;
    assert_eq!(
        (s, code(&v)),
        (StatusCode::UNSUPPORTED_MEDIA_TYPE, "unsupported_media_type"),
        "{v}"
    );
}
