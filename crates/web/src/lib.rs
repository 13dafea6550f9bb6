//! The browser studio of `dissect`: an HTTP server with a small JSON API and
//! an embedded page (figure editor, solver with live progress, solution
//! viewer and downloads).
//!
//! Architecture invariant: this is the only crate that knows HTTP. It uses
//! the core library for everything about figures and dissections; the page's
//! assets are compiled into the binary, so nothing is fetched at run time.
//! Every request that is not understood gets a JSON error (see
//! [`error::ApiError`]); nothing a client sends makes the server panic.

pub mod error;
pub mod export;
pub mod figures;
pub mod jobs;
pub mod limits;
pub mod picture;

mod assets;
mod examples;
mod routes;

pub use error::ApiError;
pub use limits::Limits;
pub use routes::router;

use std::net::SocketAddr;

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

/// A bound, not yet running studio server.
pub struct Server {
    listener: tokio::net::TcpListener,
    limits: Limits,
}

impl Server {
    /// Binds `addr` (port 0 picks a free port).
    pub async fn bind(addr: SocketAddr, limits: Limits) -> Result<Server, ServeError> {
        let listener = tokio::net::TcpListener::bind(addr)
            .await
            .map_err(|source| ServeError::Bind { addr, source })?;
        Ok(Server { listener, limits })
    }

    /// The address actually bound.
    pub fn local_addr(&self) -> Result<SocketAddr, ServeError> {
        Ok(self.listener.local_addr()?)
    }

    /// Serves until `shutdown` completes; running solves are stopped then.
    pub async fn run(
        self,
        shutdown: impl std::future::Future<Output = ()> + Send + 'static,
    ) -> Result<(), ServeError> {
        let state = routes::AppState::new(self.limits);
        let app = routes::router_with_state(state.clone());
        axum::serve(self.listener, app)
            .with_graceful_shutdown(async move {
                shutdown.await;
                state.jobs.stop_all();
            })
            .await?;
        Ok(())
    }
}

/// Runs a studio server on its own tokio runtime until Ctrl-C (or SIGTERM):
/// binds `addr`, calls `ready` with the bound address, then serves.
///
/// This is what `dissect serve` calls, so the command line needs no async
/// runtime of its own.
pub fn run_blocking(
    addr: SocketAddr,
    limits: Limits,
    ready: impl FnOnce(SocketAddr),
) -> Result<(), ServeError> {
    let runtime = tokio::runtime::Builder::new_multi_thread()
        .worker_threads(2)
        .enable_all()
        .build()?;
    runtime.block_on(async move {
        let server = Server::bind(addr, limits).await?;
        ready(server.local_addr()?);
        server.run(shutdown_signal()).await
    })
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
