//! Time limits: a run's step estimate turned into seconds by the method's cost per step
//! from the registry ([`crate::integrators::MethodInfo::ns_per_step`]), refused above
//! `--max-seconds` before any work is done.

use crate::error::{num, Error};
use crate::integrators::{Method, Step};

/// The default limit on a `simulate` run's estimated time in seconds (`--max-seconds`).
pub const DEFAULT_MAX_SECONDS: u64 = 60;

/// The default limit on the estimated time of the scenes `report --scenes` adds, all of
/// them together, in seconds (`--max-seconds`).
pub const DEFAULT_REPORT_MAX_SECONDS: u64 = 600;

/// A duration in seconds for a message: `0.5 s`, `42 s`, `3.1e4 s`.
#[must_use]
pub fn seconds(s: f64) -> String {
    if !s.is_finite() || s >= 1e4 {
        format!("{:.1e} s", s.min(f64::MAX))
    } else if s >= 10.0 {
        format!("{s:.0} s")
    } else {
        format!("{s:.2} s")
    }
}

/// Refuse a `simulate` run of `method` at `step` whose `steps` (from
/// [`super::simulate::check_work`]) would take more than `max_seconds`; the estimate
/// in seconds otherwise.
pub fn check_seconds(
    method: Method,
    step: Step,
    steps: f64,
    max_seconds: u64,
) -> Result<f64, Error> {
    let estimate = method.seconds_for(steps);
    if estimate.is_nan() || estimate > max_seconds as f64 {
        let (field, what) = match step {
            Step::Fixed(h) => ("--dt", format!("a step of {}", num(h))),
            Step::Tolerance(tol) => ("--tol", format!("a tolerance of {}", num(tol))),
            Step::AtSamples => ("run.samples", "one evaluation per sample".to_string()),
        };
        return Err(Error::invalid(
            field,
            format!(
                "{what} needs about {steps:.1e} steps of {}, about {} at {} ns a step, \
                 above the limit of {max_seconds} s; raise it with --max-seconds",
                method.name(),
                seconds(estimate),
                method.info().ns_per_step
            ),
        ));
    }
    Ok(estimate)
}
