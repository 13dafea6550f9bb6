//! Hostile requests (issue 17): the server answers every one with a JSON
//! error and keeps serving; other sites cannot drive it; slow or stuck
//! clients cannot hold it open.

use std::time::{Duration, Instant};

use axum::body::Body;
use axum::http::{Request, StatusCode};
use axum::Router;
use dissect_testkit::{nested_svg, png_claiming, HUGE_SVG};
use dissect_web::{router, router_with_access, Access, Limits};
use http_body_util::BodyExt;
use serde_json::{json, Value};
use tokio::io::{AsyncReadExt, AsyncWriteExt};
use tower::ServiceExt;

fn app() -> Router {
    router(Limits::new(200, 64, 4, 1, 60.0, 1))
}

async fn send(app: &Router, req: Request<Body>) -> (StatusCode, axum::http::HeaderMap, Vec<u8>) {
    let res = app.clone().oneshot(req).await.unwrap();
    let status = res.status();
    let headers = res.headers().clone();
    let bytes = res.into_body().collect().await.unwrap().to_bytes().to_vec();
    (status, headers, bytes)
}

fn code(body: &[u8]) -> String {
    let v: Value = serde_json::from_slice(body)
        .unwrap_or_else(|_| panic!("not JSON: {}", String::from_utf8_lossy(body)));
    v["error"]["code"].as_str().unwrap_or("").to_string()
}

const FIGURES: &str = r##"{"lattice": "square", "figures": [{"text": "#"}]}"##;
const SOLUTION: &str = r#"{"format": "dissection-solution/1", "lattice": "square",
  "figures": [{"pieces": [[[0,0],[1,0]], [[0,1],[1,1]]]}, {"pieces": [[[0,0],[1,0]], [[2,0],[3,0]]]}]}"#;

#[tokio::test]
async fn json_routes_need_exactly_application_json() {
    let app = app();
    let solve =
        json!({"lattice": "square", "figures": [{"text": "##"}, {"text": "#\n#"}]}).to_string();
    let export =
        json!({ "solution": serde_json::from_str::<Value>(SOLUTION).unwrap() }).to_string();
    for (path, body) in [
        ("/api/figures", FIGURES.to_string()),
        ("/api/solve", solve),
        ("/api/export/svg", export.clone()),
    ] {
        for ty in [
            None,
            Some("application/jsonx"),
            Some("text/plain"),
            Some("application/json-seq"),
        ] {
            let mut req = Request::post(path);
            if let Some(ty) = ty {
                req = req.header("content-type", ty);
            }
            let (s, _, b) = send(&app, req.body(Body::from(body.clone())).unwrap()).await;
            assert_eq!(s, StatusCode::UNSUPPORTED_MEDIA_TYPE, "{path} {ty:?}");
            assert_eq!(code(&b), "unsupported_media_type");
        }
    }
    let req = Request::post("/api/export/svg")
        .header("content-type", "Application/JSON; charset=utf-8")
        .body(Body::from(export))
        .unwrap();
    let (s, _, _) = send(&app, req).await;
    assert_eq!(s, StatusCode::OK);
}

fn picture(ty: &str, origin: Option<&str>, site: Option<&str>, body: &[u8]) -> Request<Body> {
    let mut req = Request::post("/api/rasterize?lattice=square&cells=4")
        .header("host", "127.0.0.1:7878")
        .header("content-type", ty);
    if let Some(o) = origin {
        req = req.header("origin", o);
    }
    if let Some(s) = site {
        req = req.header("sec-fetch-site", s);
    }
    req.body(Body::from(body.to_vec())).unwrap()
}

const SQUARE_SVG: &[u8] =
    br#"<svg xmlns="http://www.w3.org/2000/svg" width="20" height="20"><rect width="20" height="20"/></svg>"#;

#[tokio::test]
async fn other_sites_cannot_rasterize() {
    let app = app();
    let ok = send(
        &app,
        picture(
            "image/svg+xml",
            Some("http://127.0.0.1:7878"),
            Some("same-origin"),
            SQUARE_SVG,
        ),
    )
    .await;
    assert_eq!(ok.0, StatusCode::OK, "{}", String::from_utf8_lossy(&ok.2));
    // Scripts (no Origin) are fine too.
    assert_eq!(
        send(
            &app,
            picture("application/octet-stream", None, None, SQUARE_SVG)
        )
        .await
        .0,
        StatusCode::OK
    );
    for (ty, origin, site, want) in [
        (
            "image/svg+xml",
            Some("http://evil.example"),
            None,
            StatusCode::FORBIDDEN,
        ),
        ("image/svg+xml", Some("null"), None, StatusCode::FORBIDDEN),
        (
            "image/svg+xml",
            None,
            Some("cross-site"),
            StatusCode::FORBIDDEN,
        ),
        ("text/plain", None, None, StatusCode::UNSUPPORTED_MEDIA_TYPE),
        (
            "multipart/form-data; boundary=x",
            None,
            None,
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
        ),
        (
            "application/x-www-form-urlencoded",
            None,
            None,
            StatusCode::UNSUPPORTED_MEDIA_TYPE,
        ),
    ] {
        let (s, _, b) = send(&app, picture(ty, origin, site, SQUARE_SVG)).await;
        assert_eq!(
            s,
            want,
            "{ty} {origin:?} {site:?}: {}",
            String::from_utf8_lossy(&b)
        );
    }
    // The same Origin check guards the JSON routes.
    let req = Request::post("/api/figures")
        .header("host", "localhost:7878")
        .header("origin", "http://evil.example")
        .header("content-type", "application/json")
        .body(Body::from(FIGURES))
        .unwrap();
    assert_eq!(send(&app, req).await.0, StatusCode::FORBIDDEN);
}

#[tokio::test]
async fn picture_bombs_get_413_and_the_server_keeps_serving() {
    let app = app();
    let big = HUGE_SVG.as_bytes();
    let nested = nested_svg(50_000);
    // The 1e9 SVG is drawn small: 4 cells of it are fine.
    let (s, _, b) = send(&app, picture("image/svg+xml", None, None, big)).await;
    assert_eq!(s, StatusCode::OK, "{}", String::from_utf8_lossy(&b));
    for (body, says) in [
        (nested.into_bytes(), "nests elements"),
        (png_claiming(20_000, 20_000), "20000x20000"),
    ] {
        let (s, _, b) = send(&app, picture("application/octet-stream", None, None, &body)).await;
        assert_eq!(
            s,
            StatusCode::PAYLOAD_TOO_LARGE,
            "{}",
            String::from_utf8_lossy(&b)
        );
        assert_eq!(code(&b), "too_large");
        assert!(String::from_utf8_lossy(&b).contains(says));
    }
    let (s, _, _) = send(&app, Request::get("/api/info").body(Body::empty()).unwrap()).await;
    assert_eq!(s, StatusCode::OK);
}

#[tokio::test]
async fn a_seventy_piece_stl_download_is_a_zip_of_seventy_files() {
    let app = router(Limits::new(200, 100, 4, 1, 60.0, 1));
    let cells: Vec<Value> = (0..70).map(|x| json!([[x, 0]])).collect();
    let sol = json!({"format": "dissection-solution/1", "lattice": "square",
        "figures": [{"pieces": cells}, {"pieces": cells}]});
    let req = Request::post("/api/export/stl")
        .header("content-type", "application/json")
        .body(Body::from(json!({ "solution": sol }).to_string()))
        .unwrap();
    let (s, _, zip) = send(&app, req).await;
    assert_eq!(s, StatusCode::OK, "{}", String::from_utf8_lossy(&zip));
    let text = String::from_utf8_lossy(&zip);
    for name in [
        "piece-01-A.stl",
        "piece-27-a.stl",
        "piece-63.stl",
        "piece-70.stl",
    ] {
        assert!(text.contains(name), "{name} missing");
    }
}

#[tokio::test]
async fn every_answer_has_a_content_security_policy_and_may_not_be_framed() {
    let app = app();
    for path in ["/", "/studio.js", "/api/info", "/nothing"] {
        let (_, h, _) = send(&app, Request::get(path).body(Body::empty()).unwrap()).await;
        let csp = h["content-security-policy"].to_str().unwrap();
        assert!(csp.contains("script-src 'self'"), "{path}: {csp}");
        let scripts = csp
            .split(';')
            .find(|d| d.trim().starts_with("script-src"))
            .expect("a script-src directive");
        assert!(!scripts.contains("unsafe-inline"), "{path}: {csp}");
        assert!(csp.contains("frame-ancestors 'none'"), "{path}: {csp}");
        assert_eq!(h["x-frame-options"], "DENY", "{path}");
        assert_eq!(h["x-content-type-options"], "nosniff", "{path}");
    }
}

#[tokio::test]
async fn with_a_token_every_request_needs_it() {
    let token = "0123456789abcdef0123";
    let app = router_with_access(
        Limits::new(200, 64, 4, 1, 60.0, 1),
        Access::with_token(token).unwrap(),
    );
    let get = |uri: &str, header: Option<(&str, String)>| {
        let mut r = Request::get(uri).header("host", "192.168.1.5:7878");
        if let Some((k, v)) = header {
            r = r.header(k, v);
        }
        r.body(Body::empty()).unwrap()
    };
    let (s, _, b) = send(&app, get("/api/info", None)).await;
    assert_eq!(
        (s, code(&b).as_str()),
        (StatusCode::UNAUTHORIZED, "unauthorized")
    );
    let (s, _, _) = send(&app, get("/", None)).await;
    assert_eq!(s, StatusCode::UNAUTHORIZED);
    let (s, _, _) = send(
        &app,
        get(
            "/api/info",
            Some(("authorization", "Bearer wrong-token-wrong-token".into())),
        ),
    )
    .await;
    assert_eq!(s, StatusCode::UNAUTHORIZED);
    let (s, _, _) = send(
        &app,
        get(
            "/api/info",
            Some(("authorization", format!("Bearer {token}"))),
        ),
    )
    .await;
    assert_eq!(s, StatusCode::OK);
    // The printed URL sets the cookie the page's own requests then carry.
    let (s, h, _) = send(&app, get(&format!("/?token={token}"), None)).await;
    assert_eq!(s, StatusCode::OK);
    let cookie = h["set-cookie"].to_str().unwrap();
    assert!(
        cookie.starts_with(&format!("dissect_token={token}")),
        "{cookie}"
    );
    assert!(
        cookie.contains("HttpOnly") && cookie.contains("SameSite=Strict"),
        "{cookie}"
    );
    let (s, _, _) = send(
        &app,
        get(
            "/api/info",
            Some(("cookie", format!("a=b; dissect_token={token}"))),
        ),
    )
    .await;
    assert_eq!(s, StatusCode::OK);
}

async fn start(
    header: Duration,
    idle: Duration,
    request: Duration,
) -> (
    std::net::SocketAddr,
    tokio::sync::oneshot::Sender<()>,
    tokio::task::JoinHandle<Result<(), dissect_web::ServeError>>,
) {
    let server = dissect_web::Server::bind(
        "127.0.0.1:0".parse().unwrap(),
        Limits::new(200, 64, 4, 1, 60.0, 1),
    )
    .await
    .unwrap()
    .with_timeouts(header, idle)
    .with_request_timeout(request);
    let addr = server.local_addr().unwrap();
    let (tx, rx) = tokio::sync::oneshot::channel::<()>();
    let handle = tokio::spawn(server.run(async {
        let _ = rx.await;
    }));
    (addr, tx, handle)
}

/// Reads until the server closes the connection; the time it took.
async fn closed_after(s: &mut tokio::net::TcpStream, within: Duration) -> Duration {
    let t = Instant::now();
    let mut buf = Vec::new();
    tokio::time::timeout(within, s.read_to_end(&mut buf))
        .await
        .expect("the server closes the connection")
        .ok();
    t.elapsed()
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn slow_and_idle_clients_are_cut_off() {
    let (addr, tx, handle) = start(
        Duration::from_millis(500),
        Duration::from_secs(1),
        Duration::from_millis(500),
    )
    .await;
    // Half a request, then nothing.
    let mut half = tokio::net::TcpStream::connect(addr).await.unwrap();
    half.write_all(b"GET /api/info HTTP/1.1\r\nhost: 127.0.0.1\r\n")
        .await
        .unwrap();
    assert!(closed_after(&mut half, Duration::from_secs(10)).await < Duration::from_secs(5));
    // A keep-alive connection after its answer, idle.
    let mut idle = tokio::net::TcpStream::connect(addr).await.unwrap();
    idle.write_all(b"GET /api/info HTTP/1.1\r\nhost: 127.0.0.1\r\n\r\n")
        .await
        .unwrap();
    assert!(closed_after(&mut idle, Duration::from_secs(10)).await < Duration::from_secs(5));
    // A connection that sends nothing at all.
    let mut silent = tokio::net::TcpStream::connect(addr).await.unwrap();
    assert!(closed_after(&mut silent, Duration::from_secs(10)).await < Duration::from_secs(5));
    let _ = tx.send(());
    handle.await.unwrap().unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn shutdown_is_quick_whatever_clients_do() {
    // Long timeouts: only the shutdown may end these connections.
    let long = Duration::from_secs(600);
    let (addr, tx, handle) = start(long, long, long).await;
    let mut half = tokio::net::TcpStream::connect(addr).await.unwrap();
    half.write_all(b"POST /api/figures HTTP/1.1\r\nhost: 127.0.0.1\r\ncontent-type: application/json\r\ncontent-length: 1000\r\n\r\n{\"lat").await.unwrap();
    let mut headers = tokio::net::TcpStream::connect(addr).await.unwrap();
    headers
        .write_all(b"GET / HTTP/1.1\r\nhost: 12")
        .await
        .unwrap();
    tokio::time::sleep(Duration::from_millis(200)).await;
    let t = Instant::now();
    let _ = tx.send(());
    tokio::time::timeout(Duration::from_secs(10), handle)
        .await
        .expect("the server stops")
        .unwrap()
        .unwrap();
    assert!(t.elapsed() < Duration::from_secs(5), "{:?}", t.elapsed());
    // And nobody is listening any more.
    assert!(tokio::net::TcpStream::connect(addr).await.is_err());
}

/// Sends `bytes` one a second on a fresh connection to `addr` while reading
/// the answer: the answer, and when the server closed the connection after
/// the first byte.
async fn trickle(addr: std::net::SocketAddr, head: &[u8], bytes: &[u8]) -> (String, Duration) {
    let stream = tokio::net::TcpStream::connect(addr).await.unwrap();
    let (mut r, mut w) = stream.into_split();
    w.write_all(head).await.unwrap();
    let t = Instant::now();
    let bytes = bytes.to_vec();
    let writer = tokio::spawn(async move {
        for b in bytes {
            if w.write_all(&[b]).await.is_err() {
                break;
            }
            tokio::time::sleep(Duration::from_secs(1)).await;
        }
        w
    });
    let mut answer = Vec::new();
    let mut buf = [0u8; 4096];
    loop {
        match tokio::time::timeout(Duration::from_secs(20), r.read(&mut buf)).await {
            Ok(Ok(0)) | Ok(Err(_)) => break,
            Ok(Ok(n)) => answer.extend_from_slice(&buf[..n]),
            Err(_) => panic!("the server kept a slow client for 20 s"),
        }
    }
    let took = t.elapsed();
    writer.abort();
    (String::from_utf8_lossy(&answer).into_owned(), took)
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn a_request_that_does_not_arrive_within_the_request_timeout_gets_408() {
    // Short waits elsewhere would hide the request timeout: 60 s for them.
    let long = Duration::from_secs(60);
    let (addr, tx, handle) = start(long, long, Duration::from_secs(2)).await;
    // The head, a byte a second (each byte resets the idle timer).
    let head =
        b"GET /api/info HTTP/1.1\r\nhost: 127.0.0.1\r\nx-slow: aaaaaaaaaaaaaaaaaaaaaaaaaa\r\n\r\n";
    let (answer, took) = trickle(addr, b"", head).await;
    assert!(answer.starts_with("HTTP/1.1 408 "), "{answer}");
    assert!(answer.contains("\"request_timeout\""), "{answer}");
    assert!(answer.contains("content-security-policy"), "{answer}");
    assert!(
        took >= Duration::from_millis(1500) && took < Duration::from_secs(4),
        "{took:?}"
    );
    // The head at once, the body a byte a second.
    let body = br###"{"lattice": "square", "figures": [{"text": "##"}]}"###;
    let head = format!(
        "POST /api/figures HTTP/1.1\r\nhost: 127.0.0.1\r\ncontent-type: application/json\r\ncontent-length: {}\r\n\r\n",
        body.len()
    );
    let (answer, took) = trickle(addr, head.as_bytes(), body).await;
    assert!(answer.starts_with("HTTP/1.1 408 "), "{answer}");
    assert!(answer.contains("\"request_timeout\""), "{answer}");
    assert!(
        answer.to_ascii_lowercase().contains("connection: close"),
        "{answer}"
    );
    assert!(answer.contains("content-security-policy"), "{answer}");
    assert!(took < Duration::from_secs(4), "{took:?}");
    // Requests that arrive in time are served, twice on one connection,
    // even with a pause longer than the request timeout between them.
    let mut s = tokio::net::TcpStream::connect(addr).await.unwrap();
    let post = format!("{head}{}", String::from_utf8_lossy(body));
    for _ in 0..2 {
        s.write_all(post.as_bytes()).await.unwrap();
        let mut buf = vec![0u8; 1 << 16];
        let n = tokio::time::timeout(Duration::from_secs(10), s.read(&mut buf))
            .await
            .unwrap()
            .unwrap();
        let answer = String::from_utf8_lossy(&buf[..n]);
        assert!(answer.starts_with("HTTP/1.1 200 "), "{answer}");
        tokio::time::sleep(Duration::from_millis(2500)).await;
    }
    let _ = tx.send(());
    handle.await.unwrap().unwrap();
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn slow_clients_do_not_hold_the_server() {
    let long = Duration::from_secs(60);
    let (addr, tx, handle) = start(long, long, Duration::from_secs(2)).await;
    let head =
        b"GET /api/info HTTP/1.1\r\nhost: 127.0.0.1\r\nx-slow: aaaaaaaaaaaaaaaaaaaaaaaaaa\r\n\r\n";
    let slow: Vec<_> = (0..20)
        .map(|_| tokio::spawn(async move { trickle(addr, b"", head).await }))
        .collect();
    tokio::time::sleep(Duration::from_millis(300)).await;
    // Meanwhile a quick request is answered at once.
    let t = Instant::now();
    let mut s = tokio::net::TcpStream::connect(addr).await.unwrap();
    s.write_all(b"GET /api/info HTTP/1.1\r\nhost: 127.0.0.1\r\nconnection: close\r\n\r\n")
        .await
        .unwrap();
    let mut answer = Vec::new();
    tokio::time::timeout(Duration::from_secs(5), s.read_to_end(&mut answer))
        .await
        .unwrap()
        .unwrap();
    assert!(answer.starts_with(b"HTTP/1.1 200 "));
    assert!(t.elapsed() < Duration::from_secs(1), "{:?}", t.elapsed());
    for h in slow {
        let (answer, took) = h.await.unwrap();
        assert!(answer.starts_with("HTTP/1.1 408 "), "{answer}");
        assert!(took < Duration::from_secs(4), "{took:?}");
    }
    let _ = tx.send(());
    handle.await.unwrap().unwrap();
}
