//! A connection that fails once nothing has been read or written on it for
//! a while, so idle or stalled clients cannot hold connections forever; it
//! also keeps the connection's request [`Clock`]: it starts a request at
//! its first byte, answers 408 when the head has not arrived within the
//! request timeout, and ends a connection on which no request starts within
//! the wait allowed between requests.

use std::future::Future;
use std::io;
use std::pin::Pin;
use std::task::{Context, Poll};
use std::time::Duration;

use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::time::{Instant, Sleep};

use crate::deadline::{head_timeout_response, Clock, Phase};

/// How long a connection may take: idle, between requests, for a request.
#[derive(Clone, Copy, Debug)]
pub struct Timeouts {
    /// Nothing read or written.
    pub idle: Duration,
    /// No request started since the connection opened or the last answer.
    pub between: Duration,
    /// A request's head and body, from its first byte.
    pub request: Duration,
}

/// `io` with an idle timeout: a read that has waited `idle` since the last
/// byte moved either way fails with `TimedOut`; and with the request
/// deadlines of [`Timeouts`].
pub struct IdleTimeout<T> {
    io: T,
    timeouts: Timeouts,
    timer: Pin<Box<Sleep>>,
    clock: Clock,
    /// The phase deadline `phase_timer` is set to.
    armed: Option<Instant>,
    phase_timer: Pin<Box<Sleep>>,
    /// The 408 being written, and how much of it is out.
    late: Option<(Vec<u8>, usize)>,
}

impl<T> IdleTimeout<T> {
    pub fn new(io: T, timeouts: Timeouts, clock: Clock) -> IdleTimeout<T> {
        IdleTimeout {
            io,
            timeouts,
            timer: Box::pin(tokio::time::sleep(timeouts.idle)),
            clock,
            armed: None,
            phase_timer: Box::pin(tokio::time::sleep(timeouts.request)),
            late: None,
        }
    }

    fn touch(&mut self) {
        let at = Instant::now() + self.timeouts.idle;
        self.timer.as_mut().reset(at);
    }

    /// Whether the current phase's deadline has passed (polling its timer).
    fn phase_over(&mut self, cx: &mut Context<'_>) -> Option<Phase> {
        let phase = self.clock.phase();
        let deadline = match phase {
            Phase::Waiting(t) => t + self.timeouts.between,
            Phase::Head(t) => t + self.timeouts.request,
            Phase::Body(_) | Phase::Busy => return None,
        };
        if self.armed != Some(deadline) {
            self.armed = Some(deadline);
            self.phase_timer.as_mut().reset(deadline);
        }
        self.phase_timer
            .as_mut()
            .poll(cx)
            .is_ready()
            .then_some(phase)
    }
}

impl<T: AsyncWrite + Unpin> IdleTimeout<T> {
    /// Writes the 408; ready (with nothing read: the end of the stream for
    /// the HTTP parser) once it is all out.
    fn poll_send_late(&mut self, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        while let Some((bytes, sent)) = &mut self.late {
            if *sent == bytes.len() {
                return Pin::new(&mut self.io).poll_flush(cx);
            }
            match Pin::new(&mut self.io).poll_write(cx, &bytes[*sent..]) {
                Poll::Ready(Ok(0)) => return Poll::Ready(Ok(())),
                Poll::Ready(Ok(n)) => *sent += n,
                Poll::Ready(Err(e)) => return Poll::Ready(Err(e)),
                Poll::Pending => return Poll::Pending,
            }
        }
        Poll::Ready(Ok(()))
    }
}

impl<T: AsyncRead + AsyncWrite + Unpin> AsyncRead for IdleTimeout<T> {
    fn poll_read(
        mut self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        buf: &mut ReadBuf<'_>,
    ) -> Poll<io::Result<()>> {
        if self.late.is_some() {
            return self.poll_send_late(cx);
        }
        let before = buf.filled().len();
        match Pin::new(&mut self.io).poll_read(cx, buf) {
            Poll::Ready(r) => {
                if buf.filled().len() > before {
                    self.touch();
                    self.clock.bytes_read();
                }
                Poll::Ready(r)
            }
            Poll::Pending => {
                if self.timer.as_mut().poll(cx).is_ready() {
                    return Poll::Ready(Err(io::Error::new(
                        io::ErrorKind::TimedOut,
                        "connection idle for too long",
                    )));
                }
                match self.phase_over(cx) {
                    // No request: the end of the stream, quietly.
                    Some(Phase::Waiting(_)) => Poll::Ready(Ok(())),
                    Some(_) => {
                        let answer = head_timeout_response(self.timeouts.request);
                        self.late = Some((answer, 0));
                        self.poll_send_late(cx)
                    }
                    None => Poll::Pending,
                }
            }
        }
    }
}

impl<T: AsyncWrite + Unpin> AsyncWrite for IdleTimeout<T> {
    fn poll_write(
        mut self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        data: &[u8],
    ) -> Poll<io::Result<usize>> {
        let r = Pin::new(&mut self.io).poll_write(cx, data);
        if matches!(r, Poll::Ready(Ok(n)) if n > 0) {
            self.touch();
        }
        r
    }

    fn poll_flush(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.io).poll_flush(cx)
    }

    fn poll_shutdown(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.io).poll_shutdown(cx)
    }

    fn poll_write_vectored(
        mut self: Pin<&mut Self>,
        cx: &mut Context<'_>,
        bufs: &[io::IoSlice<'_>],
    ) -> Poll<io::Result<usize>> {
        let r = Pin::new(&mut self.io).poll_write_vectored(cx, bufs);
        if matches!(r, Poll::Ready(Ok(n)) if n > 0) {
            self.touch();
        }
        r
    }

    fn is_write_vectored(&self) -> bool {
        self.io.is_write_vectored()
    }
}
