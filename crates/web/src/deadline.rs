//! A deadline for a whole request (`dissect serve --request-timeout`): the
//! head and the body of a request must have arrived within the request
//! timeout of its first byte, or the answer is 408 and the connection is
//! closed, so a client that sends a byte a second cannot hold a connection.
//!
//! Each connection has one [`Clock`], shared by the connection's reader
//! ([`crate::idle::IdleTimeout`], which sees the first byte of a request
//! and answers 408 itself while the head is still arriving, since no
//! handler exists yet) and by the service ([`Deadlined`], which gives the
//! handler a body that fails at the deadline and turns the handler's answer
//! into a 408).

use std::convert::Infallible;
use std::future::Future;
use std::pin::Pin;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Arc, Mutex};
use std::task::{Context, Poll};
use std::time::Duration;

use axum::body::{Body, Bytes};
use axum::http::{header, HeaderValue, Request, Response, StatusCode};
use axum::Router;
use hyper::body::{Body as HttpBody, Frame, Incoming, SizeHint};
use hyper::service::Service;
use hyper_util::service::TowerToHyperService;
use tokio::time::{Instant, Sleep};

use crate::error::ApiError;

/// Where a connection is in its current request.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Phase {
    /// No request has started since this instant (the connection opened,
    /// or the last answer was sent).
    Waiting(Instant),
    /// A request's head is arriving; its first byte came at this instant.
    Head(Instant),
    /// The head is in, the body is arriving; the request started then.
    Body(Instant),
    /// The request is in; the answer is being made or sent.
    Busy,
}

/// The phase of one connection, shared by its reader and its service.
#[derive(Clone, Debug)]
pub(crate) struct Clock(Arc<Mutex<Phase>>);

impl Clock {
    /// A clock for a connection accepted now.
    pub(crate) fn new() -> Clock {
        Clock(Arc::new(Mutex::new(Phase::Waiting(Instant::now()))))
    }

    fn with<T>(&self, f: impl FnOnce(&mut Phase) -> T) -> T {
        let mut p = self.0.lock().unwrap_or_else(|e| e.into_inner());
        f(&mut p)
    }

    /// The current phase.
    pub(crate) fn phase(&self) -> Phase {
        self.with(|p| *p)
    }

    /// Bytes were read: a waiting connection starts a request now.
    pub(crate) fn bytes_read(&self) {
        self.with(|p| {
            if let Phase::Waiting(_) = p {
                *p = Phase::Head(Instant::now());
            }
        });
    }

    /// The head was parsed: the instant the request started.
    fn head_arrived(&self) -> Instant {
        self.with(|p| {
            let since = match *p {
                Phase::Head(t) | Phase::Body(t) => t,
                Phase::Waiting(_) | Phase::Busy => Instant::now(),
            };
            *p = Phase::Body(since);
            since
        })
    }

    /// The whole body has arrived.
    fn body_done(&self) {
        self.with(|p| {
            if let Phase::Body(_) = p {
                *p = Phase::Busy;
            }
        });
    }

    /// The answer was sent (or dropped): the connection waits again.
    fn answered(&self) {
        self.with(|p| *p = Phase::Waiting(Instant::now()));
    }
}

/// The answer to a request whose head did not arrive in time, written by
/// the reader straight onto the connection (the same JSON error and
/// security headers as every other answer).
pub(crate) fn head_timeout_response(timeout: Duration) -> Vec<u8> {
    let e = ApiError::RequestTimeout(message(timeout));
    let body = e.body().to_string();
    format!(
        "HTTP/1.1 408 Request Timeout\r\ncontent-type: application/json\r\n\
         content-length: {}\r\nconnection: close\r\n\
         content-security-policy: {}\r\nx-frame-options: DENY\r\n\
         x-content-type-options: nosniff\r\nreferrer-policy: no-referrer\r\n\r\n{body}",
        body.len(),
        crate::security::content_security_policy(),
    )
    .into_bytes()
}

fn message(timeout: Duration) -> String {
    format!(
        "the request did not arrive within {} s (--request-timeout)",
        timeout.as_secs_f64()
    )
}

/// The router behind one connection, with the request deadline.
#[derive(Clone)]
pub(crate) struct Deadlined {
    app: TowerToHyperService<Router>,
    clock: Clock,
    timeout: Duration,
}

impl Deadlined {
    pub(crate) fn new(app: Router, clock: Clock, timeout: Duration) -> Deadlined {
        Deadlined {
            app: TowerToHyperService::new(app),
            clock,
            timeout,
        }
    }
}

impl Service<Request<Incoming>> for Deadlined {
    type Response = Response<Body>;
    type Error = Infallible;
    type Future = Pin<Box<dyn Future<Output = Result<Response<Body>, Infallible>> + Send>>;

    fn call(&self, req: Request<Incoming>) -> Self::Future {
        let since = self.clock.head_arrived();
        let late = Arc::new(AtomicBool::new(false));
        let (parts, body) = req.into_parts();
        if body.is_end_stream() {
            self.clock.body_done();
        }
        let body = Timed {
            inner: body,
            sleep: Box::pin(tokio::time::sleep_until(since + self.timeout)),
            clock: self.clock.clone(),
            late: Arc::clone(&late),
        };
        let req = Request::from_parts(parts, Body::new(body));
        let (app, clock, timeout) = (self.app.clone(), self.clock.clone(), self.timeout);
        Box::pin(async move {
            let res = match app.call(req).await {
                Ok(res) => res,
                Err(never) => match never {},
            };
            let mut res = if late.load(Ordering::SeqCst) {
                too_late(res, timeout)
            } else {
                res
            };
            if clock.phase() != Phase::Busy {
                // The body was not read to its end (or came too late):
                // close the connection rather than wait for the rest.
                res.headers_mut()
                    .insert(header::CONNECTION, HeaderValue::from_static("close"));
            }
            Ok(res.map(|inner| Body::new(Answered { inner, clock })))
        })
    }
}

/// The handler's answer to a request whose body came too late, as a 408
/// (keeping the headers every answer has).
fn too_late(res: Response<Body>, timeout: Duration) -> Response<Body> {
    let (mut parts, _) = res.into_parts();
    let body = ApiError::RequestTimeout(message(timeout))
        .body()
        .to_string();
    parts.status = StatusCode::REQUEST_TIMEOUT;
    parts.headers.remove(header::CONTENT_LENGTH);
    parts.headers.insert(
        header::CONTENT_TYPE,
        HeaderValue::from_static("application/json"),
    );
    Response::from_parts(parts, Body::from(body))
}

/// A request body that fails once the request's deadline has passed with
/// the body still arriving.
struct Timed {
    inner: Incoming,
    sleep: Pin<Box<Sleep>>,
    clock: Clock,
    late: Arc<AtomicBool>,
}

impl HttpBody for Timed {
    type Data = Bytes;
    type Error = axum::BoxError;

    fn poll_frame(
        mut self: Pin<&mut Self>,
        cx: &mut Context<'_>,
    ) -> Poll<Option<Result<Frame<Bytes>, axum::BoxError>>> {
        let this = &mut *self;
        match Pin::new(&mut this.inner).poll_frame(cx) {
            Poll::Ready(None) => {
                this.clock.body_done();
                Poll::Ready(None)
            }
            Poll::Ready(Some(Ok(frame))) => {
                if this.inner.is_end_stream() {
                    this.clock.body_done();
                }
                Poll::Ready(Some(Ok(frame)))
            }
            Poll::Ready(Some(Err(e))) => Poll::Ready(Some(Err(e.into()))),
            Poll::Pending => match this.sleep.as_mut().poll(cx) {
                Poll::Ready(()) => {
                    this.late.store(true, Ordering::SeqCst);
                    Poll::Ready(Some(Err("the request body came too late".into())))
                }
                Poll::Pending => Poll::Pending,
            },
        }
    }

    fn is_end_stream(&self) -> bool {
        self.inner.is_end_stream()
    }

    fn size_hint(&self) -> SizeHint {
        self.inner.size_hint()
    }
}

/// An answer's body that marks the connection as waiting again once it is
/// sent (dropped).
struct Answered {
    inner: Body,
    clock: Clock,
}

impl HttpBody for Answered {
    type Data = Bytes;
    type Error = axum::Error;

    fn poll_frame(
        mut self: Pin<&mut Self>,
        cx: &mut Context<'_>,
    ) -> Poll<Option<Result<Frame<Bytes>, axum::Error>>> {
        Pin::new(&mut self.inner).poll_frame(cx)
    }

    fn is_end_stream(&self) -> bool {
        self.inner.is_end_stream()
    }

    fn size_hint(&self) -> SizeHint {
        self.inner.size_hint()
    }
}

impl Drop for Answered {
    fn drop(&mut self) {
        self.clock.answered();
    }
}
