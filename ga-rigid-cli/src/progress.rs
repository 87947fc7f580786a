//! Progress on standard error. `simulate`'s line is drawn only when standard error is a
//! terminal: pipes and log files get nothing, so the one-line error rule still holds
//! there. The report, which runs for minutes, also writes plain lines off a terminal
//! ([`Ticker`]), the first only after a few seconds, so that a log shows it is alive.

use std::io::{IsTerminal as _, Write as _};
use std::time::{Duration, Instant};

/// Runs estimated at fewer steps than this finish in about a second; no progress for them.
const LONG_RUN_STEPS: f64 = 1e7;

/// How often the line is redrawn.
const INTERVAL: Duration = Duration::from_millis(250);

/// The progress display of one run; inactive unless the run is long and stderr a terminal.
pub struct Progress {
    t_end: f64,
    active: bool,
    last: Instant,
    drawn: bool,
}

impl Progress {
    /// A display for a run to `t_end` of about `steps` steps.
    pub fn new(t_end: f64, steps: f64) -> Self {
        Progress {
            t_end,
            active: steps >= LONG_RUN_STEPS && std::io::stderr().is_terminal(),
            last: Instant::now(),
            drawn: false,
        }
    }

    /// Redraw the line for time `t` if the interval has passed.
    pub fn update(&mut self, t: f64) {
        if !self.active || self.last.elapsed() < INTERVAL {
            return;
        }
        self.last = Instant::now();
        self.drawn = true;
        let percent = 100.0 * t / self.t_end;
        let _ = write!(
            std::io::stderr(),
            "\r\x1b[Ksimulate: t = {} of {} ({percent:.1}%)",
            ga_rigid::error::num(t),
            ga_rigid::error::num(self.t_end)
        );
    }

    /// Erase the line, leaving the terminal as it was.
    pub fn finish(&mut self) {
        if self.drawn {
            let _ = write!(std::io::stderr(), "\r\x1b[K");
        }
    }
}

/// How long a job runs before its first plain progress line, and between lines.
const PLAIN_INTERVAL: Duration = Duration::from_secs(5);

/// Plain progress lines (`report: 12 of 400 runs, 10 s (scene: method)`), one every
/// [`PLAIN_INTERVAL`] and none for a job shorter than that.
pub struct Ticker {
    label: &'static str,
    started: Instant,
    last: Instant,
}

impl Ticker {
    /// Lines prefixed `label`, counted from now.
    pub fn new(label: &'static str) -> Self {
        let now = Instant::now();
        Ticker {
            label,
            started: now,
            last: now,
        }
    }

    /// Say that `done` of `total` runs are finished, the last one `what`, if the interval
    /// has passed since the last line.
    pub fn tick(&mut self, done: u64, total: u64, what: &str) {
        if let Some(line) = self.line(done, total, what) {
            let _ = writeln!(std::io::stderr(), "{line}");
        }
    }

    /// The line [`Ticker::tick`] would print now, if one is due.
    fn line(&mut self, done: u64, total: u64, what: &str) -> Option<String> {
        if self.last.elapsed() < PLAIN_INTERVAL {
            return None;
        }
        self.last = Instant::now();
        Some(format!(
            "{}: {done} of {total} runs, {:.0} s ({})",
            self.label,
            self.started.elapsed().as_secs_f64(),
            ga_rigid::error::echo(what)
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_ticker_is_silent_for_short_jobs_then_writes_one_line_per_interval() {
        let mut ticker = Ticker::new("report");
        assert_eq!(ticker.line(1, 10, "a: rk4"), None);
        // As if the job had started seven seconds ago.
        let Some(past) = Instant::now().checked_sub(Duration::from_secs(7)) else {
            return; // A clock this close to its start cannot be wound back; nothing to test.
        };
        ticker.started = past;
        ticker.last = past;
        assert_eq!(
            ticker.line(3, 10, "a: rk4").as_deref(),
            Some("report: 3 of 10 runs, 7 s (a: rk4)")
        );
        assert_eq!(ticker.line(4, 10, "a: dopri"), None);
    }
}
