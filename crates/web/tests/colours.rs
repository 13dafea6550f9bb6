//! One palette: piece `i` has the same colour in the studio (`/palette.js`),
//! in the SVG and PNG downloads, and in the player's data and HTML page.

use std::collections::HashMap;

use axum::body::Body;
use axum::http::{Request, StatusCode};
use axum::Router;
use dissect_web::{router, Limits};
use http_body_util::BodyExt;
use serde_json::{json, Value};
use tower::ServiceExt;

fn app() -> Router {
    router(Limits::new(200, 64, 4, 1, 60.0, 1))
}

async fn fetch(app: &Router, req: Request<Body>) -> (StatusCode, Vec<u8>) {
    let res = app.clone().oneshot(req).await.unwrap();
    let status = res.status();
    (
        status,
        res.into_body().collect().await.unwrap().to_bytes().to_vec(),
    )
}

async fn export(app: &Router, format: &str, solution: &Value) -> Vec<u8> {
    let req = Request::post(format!("/api/export/{format}"))
        .header("content-type", "application/json")
        .body(Body::from(json!({ "solution": solution }).to_string()))
        .unwrap();
    let (status, bytes) = fetch(app, req).await;
    assert_eq!(
        status,
        StatusCode::OK,
        "{format}: {}",
        String::from_utf8_lossy(&bytes)
    );
    bytes
}

/// Four pieces of areas 4, 1, 3, 2 (so a picture's pixel counts tell them apart).
fn solution() -> Value {
    let pieces = json!([
        [[0, 0], [1, 0], [2, 0], [3, 0]],
        [[0, 1]],
        [[1, 1], [2, 1], [3, 1]],
        [[0, 2], [1, 2]]
    ]);
    json!({
        "format": "dissection-solution/1",
        "lattice": "square",
        "mirror": true,
        "figures": [
            {"name": "a.txt", "pieces": pieces},
            {"name": "b.txt", "pieces": pieces}
        ]
    })
}

const AREAS: [usize; 4] = [4, 1, 3, 2];

fn hex(s: &str) -> [u8; 3] {
    let v = u32::from_str_radix(s.trim_start_matches('#'), 16).unwrap();
    [(v >> 16) as u8, (v >> 8) as u8, v as u8]
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn studio_svg_png_and_page_give_piece_i_the_same_colour() {
    let app = app();
    let sol = solution();

    // The studio's colours: /palette.js, which the page imports.
    let (status, js) = fetch(
        &app,
        Request::get("/palette.js").body(Body::empty()).unwrap(),
    )
    .await;
    assert_eq!(status, StatusCode::OK);
    let js = String::from_utf8(js).unwrap();
    let studio: Vec<[u8; 3]> = js
        .split('\'')
        .filter(|s| s.starts_with('#') && s.len() == 7)
        .map(hex)
        .collect();
    assert!(studio.len() >= 20, "{js}");

    // The SVG: the first figure's piece paths, in piece order.
    let svg = String::from_utf8(export(&app, "svg", &sol).await).unwrap();
    let svg_fills: Vec<[u8; 3]> = svg
        .lines()
        .filter(|l| l.starts_with("<path") && l.contains("stroke-width=\"2.5\""))
        .filter_map(|l| l.split("fill=\"").nth(1))
        .map(|rest| hex(&rest[..7]))
        .take(4)
        .collect();

    // The PNG: the colour with the i-th largest pixel count is the i-th largest piece.
    let png = export(&app, "png", &sol).await;
    let img = image::load_from_memory(&png).unwrap().to_rgba8();
    let mut count: HashMap<[u8; 3], usize> = HashMap::new();
    for p in img.pixels() {
        if p[3] == 255 {
            *count.entry([p[0], p[1], p[2]]).or_default() += 1;
        }
    }

    // The player's data and the HTML page.
    let data: Value = serde_json::from_slice(&export(&app, "animation", &sol).await).unwrap();
    let page = String::from_utf8(export(&app, "html", &sol).await).unwrap();

    for i in 0..4 {
        let want = dissect_core::palette::piece_rgb(i);
        assert_eq!(studio[i], want, "studio, piece {i}");
        assert_eq!(svg_fills[i], want, "SVG, piece {i}");
        let colour = data["pieces"][i]["colour"].as_str().unwrap();
        assert_eq!(hex(colour), want, "player, piece {i}");
        assert!(
            page.contains(&format!("\"colour\":\"{colour}\"")),
            "page, piece {i}"
        );
        // PNG: piece i's colour covers an area in the order of the pieces' areas.
        for j in 0..4 {
            if AREAS[i] > AREAS[j] {
                let (ci, cj) = (count[&want], count[&dissect_core::palette::piece_rgb(j)]);
                assert!(ci > cj, "PNG: piece {i} ({ci} px) vs piece {j} ({cj} px)");
            }
        }
    }
    // The terminal colour is derived from the same colour.
    assert_eq!(dissect_core::palette::piece_ansi256(0), 167);
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn the_shared_page_is_self_contained() {
    let app = app();
    let page = String::from_utf8(export(&app, "html", &solution()).await).unwrap();
    assert!(page.starts_with("<!doctype html>"));
    assert!(page.contains("export function createPlayer"));
    assert!(page.contains("\"format\":\"dissect-animation/1\""));
    // Nothing is fetched: no external scripts, styles, images or imports.
    for bad in [
        "src=\"http",
        "href=\"http",
        "src=\"/",
        "href=\"/",
        "import(",
        "from '",
    ] {
        assert!(!page.contains(bad), "the page refers to {bad}");
    }
}
