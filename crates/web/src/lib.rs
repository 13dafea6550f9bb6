//! The browser studio of `dissect`: an HTTP server with a small JSON API and
//! an embedded page (figure editor, solver with live progress, solution
//! viewer and downloads).
//!
//! Architecture invariant: this is the only crate that knows HTTP. It uses
//! the core library for everything about figures and dissections; the page's
//! assets are compiled into the binary, so nothing is fetched at run time.
//! Every request that is not understood gets a JSON error (see
//! [`error::ApiError`]); nothing a client sends makes the server panic.

pub mod enumerate;
pub mod error;
pub mod export;
pub mod figures;
pub mod jobs;
pub mod limits;
pub mod picture;
pub mod puzzle;
pub mod security;

mod assets;
mod deadline;
mod examples;
mod idle;
mod lattices;
mod routes;
mod sha256;

pub use error::ApiError;
pub use limits::Limits;
pub use routes::{router, router_with_access};
pub use security::Access;

use std::net::SocketAddr;
use std::time::Duration;

/// Occurs when the server cannot start or stops with an error.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ServeError {
    /// Occurs when the address cannot be bound (in use, not permitted).
    #[error("cannot listen on {addr}: {source}")]
    Bind {
        /// The address asked for.
        addr: SocketAddr,
        /// Why.
        source: std::io::Error,
    },
    /// Occurs when serving fails after the start.
    #[error("server error: {0}")]
    Io(#[from] std::io::Error),
}

/// How long a connection may go without starting a request: after it opens,
/// and after each answer (keep-alive).
pub const HEADER_TIMEOUT: Duration = Duration::from_secs(10);
/// How long a request's head and body may take to arrive, from its first
/// byte (`dissect serve --request-timeout`): later, the answer is 408 and
/// the connection is closed.
pub const REQUEST_TIMEOUT: Duration = Duration::from_secs(30);
/// How long a connection may stay without any byte read or written.
pub const IDLE_TIMEOUT: Duration = Duration::from_secs(60);
/// How long open connections get to finish once the server stops.
pub const SHUTDOWN_GRACE: Duration = Duration::from_secs(2);
/// The most connections served at once (more are closed at once).
pub const MAX_CONNECTIONS: usize = 256;

/// A bound, not yet running studio server.
pub struct Server {
    listener: tokio::net::TcpListener,
    limits: Limits,
    access: Access,
    header_timeout: Duration,
    idle_timeout: Duration,
    request_timeout: Duration,
}

impl Server {
    /// Binds `addr` (port 0 picks a free port); open to anyone who reaches
    /// it until [`Server::with_access`] says otherwise.
    pub async fn bind(addr: SocketAddr, limits: Limits) -> Result<Server, ServeError> {
        let listener = tokio::net::TcpListener::bind(addr)
            .await
            .map_err(|source| ServeError::Bind { addr, source })?;
        Ok(Server {
            listener,
            limits,
            access: Access::open(),
            header_timeout: HEADER_TIMEOUT,
            idle_timeout: IDLE_TIMEOUT,
            request_timeout: REQUEST_TIMEOUT,
        })
    }

    /// The same server with this access rule (an access token).
    pub fn with_access(mut self, access: Access) -> Server {
        self.access = access;
        self
    }

    /// The same server with other timeouts: for a connection to start a
    /// request and for idle connections (defaults [`HEADER_TIMEOUT`],
    /// [`IDLE_TIMEOUT`]).
    pub fn with_timeouts(mut self, header: Duration, idle: Duration) -> Server {
        self.header_timeout = header;
        self.idle_timeout = idle;
        self
    }

    /// The same server with another request timeout (default
    /// [`REQUEST_TIMEOUT`]): a request whose head and body have not arrived
    /// within it of its first byte gets 408 and its connection is closed.
    pub fn with_request_timeout(mut self, timeout: Duration) -> Server {
        self.request_timeout = timeout;
        self
    }

    /// The address actually bound.
    pub fn local_addr(&self) -> Result<SocketAddr, ServeError> {
        Ok(self.listener.local_addr()?)
    }

    /// Serves until `shutdown` completes; running solves are stopped then,
    /// and open connections get [`SHUTDOWN_GRACE`] to finish before they are
    /// dropped, so that no client (one holding a half-sent request, an
    /// event stream) can keep the server from stopping. Every connection
    /// must start a request within [`HEADER_TIMEOUT`] (of opening, of its
    /// last answer), send it whole within the request timeout (else 408),
    /// and is closed after [`IDLE_TIMEOUT`] without traffic.
    pub async fn run(
        self,
        shutdown: impl std::future::Future<Output = ()> + Send + 'static,
    ) -> Result<(), ServeError> {
        let state = routes::AppState::new(self.limits, self.access);
        let app = routes::router_with_state(state.clone());
        let (close_tx, close_rx) = tokio::sync::watch::channel(false);
        let mut conns = tokio::task::JoinSet::new();
        let mut shutdown = std::pin::pin!(shutdown);
        let timeouts = idle::Timeouts {
            idle: self.idle_timeout,
            between: self.header_timeout,
            request: self.request_timeout,
        };
        loop {
            tokio::select! {
                () = &mut shutdown => break,
                Some(_) = conns.join_next(), if !conns.is_empty() => {}
                accepted = self.listener.accept() => {
                    let stream = match accepted {
                        Ok((stream, _)) => stream,
                        Err(_) => {
                            // Out of file descriptors and the like: wait a little.
                            tokio::time::sleep(Duration::from_millis(50)).await;
                            continue;
                        }
                    };
                    if conns.len() >= MAX_CONNECTIONS {
                        continue;
                    }
                    let clock = deadline::Clock::new();
                    let service = deadline::Deadlined::new(app.clone(), clock.clone(), timeouts.request);
                    let mut closing = close_rx.clone();
                    conns.spawn(async move {
                        let io = hyper_util::rt::TokioIo::new(idle::IdleTimeout::new(stream, timeouts, clock));
                        // The head's deadline is the request clock's (408), not hyper's.
                        let conn = hyper::server::conn::http1::Builder::new()
                            .timer(hyper_util::rt::TokioTimer::new())
                            .header_read_timeout(None)
                            .serve_connection(io, service);
                        let mut conn = std::pin::pin!(conn);
                        tokio::select! {
                            _ = conn.as_mut() => {}
                            _ = async { let _ = closing.wait_for(|c| *c).await; } => {
                                conn.as_mut().graceful_shutdown();
                                let _ = tokio::time::timeout(SHUTDOWN_GRACE, conn).await;
                            }
                        }
                    });
                }
            }
        }
        drop(self.listener);
        state.jobs.stop_all();
        let _ = close_tx.send(true);
        let drained = async { while conns.join_next().await.is_some() {} };
        if tokio::time::timeout(SHUTDOWN_GRACE + Duration::from_secs(1), drained)
            .await
            .is_err()
        {
            conns.abort_all();
        }
        Ok(())
    }
}

/// Runs a studio server on its own tokio runtime until Ctrl-C (or SIGTERM):
/// binds `addr`, calls `ready` with the bound address, then serves, with
/// `request_timeout` for each request ([`Server::with_request_timeout`]). The
/// server stops within seconds of the signal, whatever its clients do.
///
/// This is what `dissect serve` calls, so the command line needs no async
/// runtime of its own.
pub fn run_blocking(
    addr: SocketAddr,
    limits: Limits,
    access: Access,
    request_timeout: Duration,
    ready: impl FnOnce(SocketAddr),
) -> Result<(), ServeError> {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        // Pictures are drawn on blocking threads: room for resvg's recursion.
        .thread_stack_size(8 << 20)
        .enable_all()
        .build()?;
    let result = runtime.block_on(async move {
        let server = Server::bind(addr, limits)
            .await?
            .with_access(access)
            .with_request_timeout(request_timeout);
        ready(server.local_addr()?);
        server.run(shutdown_signal()).await
    });
    // Solves were told to stop; do not wait long for a blocking thread.
    runtime.shutdown_timeout(Duration::from_secs(1));
    result
}

/// Completes on Ctrl-C or, on Unix, SIGTERM.
async fn shutdown_signal() {
    let ctrl_c = async {
        let _ = tokio::signal::ctrl_c().await;
    };
    #[cfg(unix)]
    let term = async {
        match tokio::signal::unix::signal(tokio::signal::unix::SignalKind::terminate()) {
            Ok(mut s) => {
                s.recv().await;
            }
            Err(_) => std::future::pending::<()>().await,
        }
    };
    #[cfg(not(unix))]
    let term = std::future::pending::<()>();
    tokio::select! {
        _ = ctrl_c => {},
        _ = term => {},
    }
}
