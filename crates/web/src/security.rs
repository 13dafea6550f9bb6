//! What keeps other web sites, and other machines, from driving the studio:
//!
//! * a `Host` header must be an IP address or `localhost` (DNS rebinding);
//! * a request that changes something (not GET/HEAD) must not come from
//!   another origin: its `Origin` header, when present, must be this
//!   server, and `Sec-Fetch-Site` must not say `cross-site` or `same-site`;
//! * JSON bodies must be sent as `content-type: application/json` (exactly
//!   that media type; 415 otherwise), which no cross-site form can send;
//!   `/api/rasterize` refuses the form content types;
//! * with an access token (a server reachable beyond loopback must have
//!   one), every request must carry it: `Authorization: Bearer TOKEN`, the
//!   `dissect_token` cookie, or `?token=TOKEN` (which sets the cookie, so the
//!   printed URL opens the page);
//! * every response has a content security policy (scripts only from this
//!   server, plus the page's own inline import map by its hash), and may
//!   not be framed.

use std::sync::OnceLock;

use axum::http::{header, HeaderMap, HeaderValue, Method};
use axum::response::{IntoResponse, Response};

use crate::error::ApiError;

/// The cookie that carries the access token.
pub const TOKEN_COOKIE: &str = "dissect_token";

/// Who may use the server.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Access {
    token: Option<String>,
}

impl Access {
    /// Anyone who reaches the socket (for loopback servers).
    pub fn open() -> Access {
        Access { token: None }
    }

    /// Only requests with this token. Fails on a token that could not be
    /// sent in a cookie or a URL unescaped (letters, digits, `-`, `_`, `.`,
    /// `~`; 16 to 256 characters).
    pub fn with_token(token: &str) -> Result<Access, String> {
        let ok = (16..=256).contains(&token.len())
            && token
                .bytes()
                .all(|b| b.is_ascii_alphanumeric() || b"-_.~".contains(&b));
        if !ok {
            return Err(
                "a token must be 16 to 256 letters, digits, '-', '_', '.' or '~'".to_string(),
            );
        }
        Ok(Access {
            token: Some(token.to_string()),
        })
    }

    /// A fresh random token of 32 hex digits (128 bits from the operating
    /// system).
    pub fn random_token() -> String {
        let mut bytes = [0u8; 16];
        let read = std::fs::File::open("/dev/urandom")
            .and_then(|mut f| std::io::Read::read_exact(&mut f, &mut bytes));
        if read.is_err() {
            // No /dev/urandom: the standard library's per-process random keys.
            use std::hash::{BuildHasher, Hasher};
            for (i, chunk) in bytes.chunks_mut(8).enumerate() {
                let mut h = std::collections::hash_map::RandomState::new().build_hasher();
                h.write_usize(i);
                h.write_u128(
                    std::time::SystemTime::now()
                        .duration_since(std::time::UNIX_EPOCH)
                        .map_or(0, |d| d.as_nanos()),
                );
                chunk.copy_from_slice(&h.finish().to_le_bytes());
            }
        }
        bytes.iter().map(|b| format!("{b:02x}")).collect()
    }

    /// The token, if one is required.
    pub fn token(&self) -> Option<&str> {
        self.token.as_deref()
    }

    /// Whether the request carries the token (always, without one); and
    /// whether it came in the URL (so the answer should set the cookie).
    fn admits(&self, req: &axum::extract::Request) -> (bool, bool) {
        let Some(token) = &self.token else {
            return (true, false);
        };
        let h = req.headers();
        let bearer = h
            .get_all(header::AUTHORIZATION)
            .iter()
            .filter_map(|v| v.to_str().ok())
            .filter_map(|v| v.strip_prefix("Bearer "))
            .any(|t| same(t.trim(), token));
        let cookie = h
            .get_all(header::COOKIE)
            .iter()
            .filter_map(|v| v.to_str().ok())
            .flat_map(|v| v.split(';'))
            .filter_map(|c| c.trim().split_once('='))
            .any(|(k, v)| k == TOKEN_COOKIE && same(v, token));
        let query = req
            .uri()
            .query()
            .unwrap_or("")
            .split('&')
            .filter_map(|kv| kv.split_once('='))
            .any(|(k, v)| k == "token" && same(v, token));
        (bearer || cookie || query, query && !cookie)
    }
}

/// Compares without stopping at the first difference.
fn same(a: &str, b: &str) -> bool {
    a.len() == b.len()
        && a.bytes()
            .zip(b.bytes())
            .fold(0u8, |acc, (x, y)| acc | (x ^ y))
            == 0
}

/// The `Content-Security-Policy` of every response: the page's inline
/// scripts (its import map) are allowed by their SHA-256 hashes, computed
/// once from the page as it is built in.
pub fn content_security_policy() -> &'static str {
    static CSP: OnceLock<String> = OnceLock::new();
    CSP.get_or_init(|| {
        let page = crate::assets::find("index.html")
            .map(|(_, b)| String::from_utf8_lossy(b).into_owned())
            .unwrap_or_default();
        let hashes: Vec<String> = inline_scripts(&page)
            .iter()
            .map(|s| {
                format!(
                    " 'sha256-{}'",
                    crate::sha256::base64(&crate::sha256::sha256(s.as_bytes()))
                )
            })
            .collect();
        format!(
            "default-src 'self'; script-src 'self'{}; style-src 'self' 'unsafe-inline'; \
             img-src 'self' data: blob:; connect-src 'self'; object-src 'none'; \
             base-uri 'none'; form-action 'self'; frame-ancestors 'none'",
            hashes.concat()
        )
    })
}

/// The contents of the `<script>` elements without `src` in a page.
fn inline_scripts(page: &str) -> Vec<&str> {
    let mut out = Vec::new();
    let mut rest = page;
    while let Some(i) = rest.find("<script") {
        let Some(j) = rest[i..].find('>') else { break };
        let tag = &rest[i..i + j];
        let body_start = i + j + 1;
        let Some(k) = rest[body_start..].find("</script>") else {
            break;
        };
        if !tag.contains(" src=") {
            out.push(&rest[body_start..body_start + k]);
        }
        rest = &rest[body_start + k..];
    }
    out
}

/// The media type of a `Content-Type` value, lowercase, without parameters.
fn media_type(h: &HeaderMap) -> Option<String> {
    h.get(header::CONTENT_TYPE).map(|v| {
        v.to_str()
            .unwrap_or("")
            .split(';')
            .next()
            .unwrap_or("")
            .trim()
            .to_ascii_lowercase()
    })
}

/// The POST routes whose body is JSON.
fn takes_json(path: &str) -> bool {
    matches!(path, "/api/figures" | "/api/solve") || path.starts_with("/api/export/")
}

/// Checks a request (see the module's comment); `None` lets it through.
fn refuse(access: &Access, req: &axum::extract::Request) -> Option<ApiError> {
    let h = req.headers();
    // With a token, a foreign host name is no risk (DNS rebinding gains
    // nothing without the token): the server may be reached by any name.
    let host_checked = access.token.is_none();
    if let Some(host) = h.get(header::HOST).filter(|_| host_checked) {
        let host = host.to_str().unwrap_or("");
        let name = if host.starts_with('[') {
            host.split(']').next().map(|h| &h[1..]).unwrap_or("")
        } else {
            host.split(':').next().unwrap_or("")
        };
        let ok = name.eq_ignore_ascii_case("localhost") || name.parse::<std::net::IpAddr>().is_ok();
        if !ok {
            return Some(ApiError::Forbidden(format!(
                "host {host:?} refused: open the studio by its IP address or as localhost"
            )));
        }
    }
    if !access.admits(req).0 {
        return Some(ApiError::Unauthorized(
            "this server needs its access token: open the URL it printed (with ?token=...), \
             or send Authorization: Bearer TOKEN"
                .into(),
        ));
    }
    let safe = matches!(*req.method(), Method::GET | Method::HEAD | Method::OPTIONS);
    if !safe {
        if let Some(origin) = h.get(header::ORIGIN) {
            let origin = origin.to_str().unwrap_or("");
            let host = h
                .get(header::HOST)
                .and_then(|v| v.to_str().ok())
                .unwrap_or("");
            let ours = !host.is_empty()
                && ["http://", "https://"]
                    .iter()
                    .any(|s| origin.eq_ignore_ascii_case(&format!("{s}{host}")));
            if !ours {
                return Some(ApiError::Forbidden(format!(
                    "cross-site request from origin {origin:?} refused"
                )));
            }
        }
        if let Some(site) = h.get("sec-fetch-site").and_then(|v| v.to_str().ok()) {
            if site.eq_ignore_ascii_case("cross-site") || site.eq_ignore_ascii_case("same-site") {
                return Some(ApiError::Forbidden(format!(
                    "{site} request refused: use the studio's own page"
                )));
            }
        }
        let path = req.uri().path();
        let ty = media_type(h);
        if *req.method() == Method::POST
            && takes_json(path)
            && ty.as_deref() != Some("application/json")
        {
            return Some(ApiError::UnsupportedMediaType(format!(
                "send JSON with content-type: application/json (got {})",
                ty.map_or("no content-type".to_string(), |t| format!("{t:?}"))
            )));
        }
        if path == "/api/rasterize"
            && matches!(
                ty.as_deref(),
                Some("text/plain" | "multipart/form-data" | "application/x-www-form-urlencoded")
            )
        {
            return Some(ApiError::UnsupportedMediaType(
                "send the picture's bytes as image/png, image/jpeg, image/svg+xml or application/octet-stream"
                    .into(),
            ));
        }
    }
    None
}

/// The middleware: refuses what `refuse` refuses, and adds the security
/// headers (and the token cookie) to every answer.
pub async fn guard(
    axum::extract::State(access): axum::extract::State<std::sync::Arc<Access>>,
    req: axum::extract::Request,
    next: axum::middleware::Next,
) -> Response {
    let set_cookie = access.admits(&req).1;
    let mut res = match refuse(&access, &req) {
        Some(e) => e.into_response(),
        None => next.run(req).await,
    };
    let h = res.headers_mut();
    h.insert(
        header::CONTENT_SECURITY_POLICY,
        HeaderValue::from_static(content_security_policy()),
    );
    h.insert(header::X_FRAME_OPTIONS, HeaderValue::from_static("DENY"));
    h.insert(
        header::X_CONTENT_TYPE_OPTIONS,
        HeaderValue::from_static("nosniff"),
    );
    h.insert(
        header::REFERRER_POLICY,
        HeaderValue::from_static("no-referrer"),
    );
    if set_cookie {
        if let Some(Ok(v)) = access.token().map(|t| {
            HeaderValue::from_str(&format!(
                "{TOKEN_COOKIE}={t}; Path=/; HttpOnly; SameSite=Strict"
            ))
        }) {
            h.append(header::SET_COOKIE, v);
        }
    }
    res
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_inline_script_is_allowed_by_its_hash() {
        let csp = content_security_policy();
        let page = String::from_utf8_lossy(crate::assets::find("index.html").unwrap().1);
        let scripts = inline_scripts(&page);
        assert_eq!(
            inline_scripts("<script>a()</script><script src=\"x.js\"></script>"),
            ["a()"]
        );
        assert_eq!(csp.matches("'sha256-").count(), scripts.len(), "{csp}");
        assert!(csp.contains("frame-ancestors 'none'"));
    }

    #[test]
    fn tokens() {
        assert!(Access::with_token("short").is_err());
        assert!(Access::with_token("with space in the token!").is_err());
        assert!(Access::with_token("0123456789abcdef").is_ok());
        let a = Access::random_token();
        let b = Access::random_token();
        assert_eq!(a.len(), 32);
        assert_ne!(a, b);
    }
}
