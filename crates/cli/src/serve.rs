//! `dissect serve`: the browser studio (crates/web) on 127.0.0.1.

use std::io::Write;
use std::net::{IpAddr, Ipv4Addr, SocketAddr};

use anyhow::Result;
use clap::Args;
use dissect_web::{Access, Limits};

use crate::args::{positive, whole, whole_usize};
use crate::{InputError, Status};

/// A TCP port, 0 to 65535.
fn port(s: &str) -> Result<u16, String> {
    let n = whole::<0>(s)?;
    u16::try_from(n).map_err(|_| format!("must be a port from 0 to 65535, got {s}"))
}

#[derive(Args, Debug)]
#[command(allow_negative_numbers = true)]
pub struct ServeArgs {
    /// The port (0: any free port; the URL printed says which).
    #[arg(long, default_value_t = 7878, value_parser = port)]
    pub port: u16,
    /// The address to listen on. Anything but a loopback address exposes the
    /// studio (and the machine's CPU) to the network.
    #[arg(long, default_value_t = IpAddr::V4(Ipv4Addr::LOCALHOST))]
    pub host: IpAddr,
    /// The most cells a figure may have.
    #[arg(long, default_value_t = Limits::default().max_cells(), value_name = "N", value_parser = whole_usize::<1>)]
    pub max_cells: usize,
    /// The most solves running at once (more are refused with HTTP 429).
    #[arg(long, default_value_t = Limits::default().max_concurrent_solves(), value_name = "N", value_parser = whole_usize::<1>)]
    pub max_solves: usize,
    /// The longest time limit a solve may ask for, in seconds.
    #[arg(long, default_value_t = Limits::default().max_time_limit(), value_name = "SECS", value_parser = positive)]
    pub max_time_limit: f64,
    /// Require this access token on every request (at least 16 letters,
    /// digits, '-', '_', '.' or '~'). Without it, a server on an address
    /// other than loopback makes up a random token and prints it in its URL.
    #[arg(long, value_name = "TOKEN")]
    pub token: Option<String>,
    /// How long a request's head and body may take to arrive, from its
    /// first byte; a later one gets HTTP 408 and its connection is closed.
    #[arg(long, default_value_t = 30.0, value_name = "SECS", value_parser = request_timeout)]
    pub request_timeout: f64,
    /// Worker threads per solve (default: one per core).
    #[arg(long, default_value_t = 0, value_parser = crate::args::thread_count)]
    pub threads: usize,
}

/// A request timeout: more than 0 seconds, at most a day.
fn request_timeout(s: &str) -> Result<f64, String> {
    let v = positive(s)?;
    if v > 86_400.0 {
        return Err(format!("must be at most 86400 seconds (a day), got {s}"));
    }
    Ok(v)
}

pub fn run(args: ServeArgs) -> Result<Status> {
    if !(args.max_time_limit.is_finite() && args.max_time_limit > 0.0) {
        return Err(InputError(format!(
            "--max-time-limit must be a positive number of seconds, got {}",
            args.max_time_limit
        ))
        .into());
    }
    let d = Limits::default();
    let limits = Limits::new(
        args.max_cells,
        d.max_extent(),
        d.max_figures(),
        args.max_solves,
        args.max_time_limit,
        args.threads,
    );
    let addr = SocketAddr::new(args.host, args.port);
    // Beyond loopback only with a token: the one given, or a random one.
    let token = match (&args.token, args.host.is_loopback()) {
        (Some(t), _) => Some(t.clone()),
        (None, false) => Some(Access::random_token()),
        (None, true) => None,
    };
    let access = match &token {
        Some(t) => Access::with_token(t).map_err(|e| InputError(format!("--token: {e}")))?,
        None => Access::open(),
    };
    let request_timeout = std::time::Duration::from_secs_f64(args.request_timeout);
    dissect_web::run_blocking(addr, limits, access, request_timeout, |bound| {
        // The one line scripts read: where the studio is. Nothing is opened.
        match &token {
            Some(t) => println!("http://{bound}/?token={t}"),
            None => println!("http://{bound}"),
        }
        let _ = std::io::stdout().flush();
        if !bound.ip().is_loopback() {
            eprintln!(
                "dissect: warning: listening on {bound}, reachable from the network; \
                 every request needs the access token (in the URL above, or \
                 Authorization: Bearer TOKEN)"
            );
        }
        eprintln!("dissect: serving the studio; press Ctrl-C to stop");
    })
    .map_err(|e| match e {
        dissect_web::ServeError::Bind { .. } => anyhow::Error::new(InputError(e.to_string())),
        other => anyhow::Error::new(other),
    })?;
    Ok(Status::Ok)
}
