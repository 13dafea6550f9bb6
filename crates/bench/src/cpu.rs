//! Process CPU time and load average from `/proc` (Linux), so that runs on
//! a shared machine can be told apart from runs on an idle one.

use std::time::Duration;

/// Kernel clock ticks per second for `/proc/self/stat` (`USER_HZ`, 100 on
/// every Linux architecture we run on).
const TICKS_PER_SECOND: u64 = 100;

/// User plus system CPU time of this process so far (every thread, including
/// threads that have ended), or `None` where `/proc` is not available.
pub fn process_cpu_time() -> Option<Duration> {
    let stat = std::fs::read_to_string("/proc/self/stat").ok()?;
    parse_stat_cpu(&stat)
}

/// `utime + stime` of a `/proc/<pid>/stat` line.
pub fn parse_stat_cpu(stat: &str) -> Option<Duration> {
    // The command name (field 2) may hold spaces and parentheses: the
    // fields after it start after the last ')'. utime and stime are fields
    // 14 and 15, so 11 and 12 after the command.
    let rest = &stat[stat.rfind(')')? + 1..];
    let fields: Vec<&str> = rest.split_whitespace().collect();
    let utime: u64 = fields.get(11)?.parse().ok()?;
    let stime: u64 = fields.get(12)?.parse().ok()?;
    Some(Duration::from_millis(
        (utime + stime) * 1000 / TICKS_PER_SECOND,
    ))
}

/// The 1-, 5- and 15-minute load averages, or `None` where `/proc` is not
/// available.
pub fn load_average() -> Option<[f64; 3]> {
    let text = std::fs::read_to_string("/proc/loadavg").ok()?;
    let mut it = text.split_whitespace().map(|f| f.parse::<f64>().ok());
    Some([it.next()??, it.next()??, it.next()??])
}

/// Resets the process's peak resident set size (`VmHWM`) to its current
/// size, through `/proc/self/clear_refs` (Linux 4.0 and later); false where
/// that is not possible, and the peak then covers the process's whole life.
pub fn reset_peak_rss() -> bool {
    std::fs::write("/proc/self/clear_refs", "5").is_ok()
}

/// The process's peak resident set size in bytes since it started or since
/// [`reset_peak_rss`] (`VmHWM` of `/proc/self/status`), or `None` where
/// `/proc` is not available.
pub fn peak_rss() -> Option<u64> {
    parse_status_hwm(&std::fs::read_to_string("/proc/self/status").ok()?)
}

/// `VmHWM` of a `/proc/<pid>/status` text, in bytes.
pub fn parse_status_hwm(status: &str) -> Option<u64> {
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let mut it = line["VmHWM:".len()..].split_whitespace();
    let kib: u64 = it.next()?.parse().ok()?;
    (it.next() == Some("kB")).then_some(kib * 1024)
}

/// CPU time of the calling thread so far (`CLOCK_THREAD_CPUTIME_ID`, to the
/// nanosecond), or `None` off Linux.
pub fn thread_cpu_time() -> Option<Duration> {
    #[cfg(target_os = "linux")]
    {
        use rustix::time::{clock_gettime, ClockId};
        let t = clock_gettime(ClockId::ThreadCPUTime);
        let secs = u64::try_from(t.tv_sec).ok()?;
        let nanos = u32::try_from(t.tv_nsec).ok()?;
        Some(Duration::new(secs, nanos))
    }
    #[cfg(not(target_os = "linux"))]
    {
        None
    }
}
