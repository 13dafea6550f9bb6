//! What the API tests share: a router with small limits, requests, and
//! waiting for a solve to end.

#![allow(dead_code)] // each test file uses its own part

use std::time::{Duration, Instant};

use axum::body::Body;
use axum::http::{Request, StatusCode};
use axum::Router;
use dissect_web::{router, Limits};
use http_body_util::BodyExt;
use serde_json::Value;
use tower::ServiceExt;

/// Small limits: 1 worker thread, at most 1 solve at a time, 200 cells.
pub fn app() -> Router {
    router(Limits::new(200, 64, 4, 1, 60.0, 1))
}

/// One JSON request; the status and the body's bytes.
pub async fn call_raw(app: &Router, method: &str, uri: &str, body: &str) -> (StatusCode, Vec<u8>) {
    let req = Request::builder()
        .method(method)
        .uri(uri)
        .header("content-type", "application/json")
        .body(Body::from(body.to_string()))
        .unwrap();
    let res = app.clone().oneshot(req).await.unwrap();
    let status = res.status();
    (
        status,
        res.into_body().collect().await.unwrap().to_bytes().to_vec(),
    )
}

/// One JSON request whose answer must be JSON.
pub async fn call(app: &Router, method: &str, uri: &str, body: &str) -> (StatusCode, Value) {
    let (s, b) = call_raw(app, method, uri, body).await;
    let v = serde_json::from_slice(&b)
        .unwrap_or_else(|_| panic!("not JSON: {}", String::from_utf8_lossy(&b)));
    (s, v)
}

/// Polls solve `id` until it is no longer running (at most `within`); its
/// last snapshot.
pub async fn wait_done(app: &Router, id: u64, within: Duration) -> Value {
    let start = Instant::now();
    loop {
        let (s, v) = call(app, "GET", &format!("/api/solve/{id}"), "").await;
        assert_eq!(s, StatusCode::OK);
        if v["state"] != "running" {
            return v;
        }
        assert!(start.elapsed() < within, "still running: {v}");
        tokio::time::sleep(Duration::from_millis(50)).await;
    }
}
