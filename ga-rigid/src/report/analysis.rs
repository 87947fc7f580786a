//! What the page says about the measurements: the fastest method at each error level,
//! each method's observed order, and its stability verdict.

use crate::integrators::{Method, StepKind};

use super::{Measurement, SceneResult};

/// The attitude errors (rad, largest over the run) the page asks each method to reach.
pub const ERROR_LEVELS: [f64; 5] = [1e-2, 1e-4, 1e-6, 1e-8, 1e-10];

/// An error (rad or relative) above which a run has lost the solution.
const LOST: f64 = 0.1;

/// Errors below this are rounding, not truncation: left out of the order fit.
const ROUNDING_FLOOR: f64 = 1e-12;

/// The fastest row (by median time) whose largest attitude error is at most `level`.
#[must_use]
pub fn fastest_at(scene: &SceneResult, level: f64) -> Option<&Measurement> {
    scene
        .rows
        .iter()
        .filter(|r| r.errors.is_some_and(|e| e.attitude_max <= level))
        .filter(|r| r.time_us().is_some())
        .min_by(|a, b| {
            a.time_us()
                .unwrap_or(0.0)
                .total_cmp(&b.time_us().unwrap_or(0.0))
        })
}

/// The least-squares slope of log(largest attitude error) against log(mean step) over a
/// method's runs whose error lies between rounding (1e-12) and 0.1; `None` with fewer than
/// two such runs.
#[must_use]
pub fn observed_order(scene: &SceneResult, method: Method) -> Option<f64> {
    let points: Vec<(f64, f64)> = scene
        .rows
        .iter()
        .filter(|r| r.method == method)
        .filter_map(|r| {
            let e = r.errors?.attitude_max;
            (e > ROUNDING_FLOOR && e < LOST && e.is_finite())
                .then(|| (r.mean_step(scene.t_end).ln(), e.ln()))
        })
        .collect();
    if points.len() < 2 {
        return None;
    }
    let n = points.len() as f64;
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(a, b), (x, y)| (a + x / n, b + y / n));
    let (sxy, sxx) = points.iter().fold((0.0, 0.0), |(a, b), (x, y)| {
        (a + (x - mx) * (y - my), b + (x - mx) * (x - mx))
    });
    (sxx > 0.0).then(|| sxy / sxx)
}

/// The median cost of one step (or evaluation) over a method's finished runs, in ns.
#[must_use]
pub fn cost_per_step_ns(scene: &SceneResult, method: Method) -> Option<f64> {
    let mut costs: Vec<f64> = scene
        .rows
        .iter()
        .filter(|r| r.method == method && r.steps > 0)
        .filter_map(|r| Some(r.time_us()? * 1e3 / r.steps as f64))
        .collect();
    costs.sort_by(f64::total_cmp);
    costs.get(costs.len() / 2).copied()
}

/// Whether a method kept the solution at the steps it ran: accurate (attitude and momentum
/// errors below 0.1 over the whole run), inaccurate, or failed, by `h |w|`.
#[must_use]
pub fn verdict(scene: &SceneResult, method: Method) -> String {
    let rows: Vec<&Measurement> = scene.rows.iter().filter(|r| r.method == method).collect();
    if rows.is_empty() {
        return "not run".to_string();
    }
    let good = |r: &Measurement| {
        r.errors
            .is_some_and(|e| e.attitude_max < LOST && e.momentum_max < LOST)
    };
    if method.step_kind() == StepKind::AtSamples {
        return match rows.iter().find_map(|r| r.failure.as_ref()) {
            Some(why) => format!("fails: {why}"),
            None if rows.iter().all(|r| good(r)) => {
                "no steps: the solution is evaluated at each sample".to_string()
            }
            None => "evaluated at each sample, but off the reference by more than 0.1".to_string(),
        };
    }
    let hw = |r: &Measurement| r.mean_step(scene.t_end) * scene.rate;
    let bad: Vec<&&Measurement> = rows.iter().filter(|r| !good(r)).collect();
    let coarsest_good = rows
        .iter()
        .filter(|r| good(r))
        .map(|r| hw(r))
        .fold(f64::NAN, f64::max);
    if bad.is_empty() {
        return format!(
            "stable: keeps the solution at every step tried, up to h|w| = {coarsest_good:.3}"
        );
    }
    let failed = bad.iter().filter(|r| r.failure.is_some()).count();
    let least_bad = bad.iter().map(|r| hw(r)).fold(f64::NAN, f64::min);
    let most_bad = bad.iter().map(|r| hw(r)).fold(f64::NAN, f64::max);
    let what = if failed == bad.len() {
        "fails"
    } else if failed == 0 {
        "loses the solution (error > 0.1)"
    } else {
        "fails or loses the solution"
    };
    if coarsest_good.is_nan() {
        if least_bad == most_bad {
            format!("{what} at the one step tried (h|w| = {least_bad:.3})")
        } else {
            format!("{what} at every step tried (h|w| from {least_bad:.3} to {most_bad:.3})")
        }
    } else {
        format!("{what} from h|w| = {least_bad:.3}; keeps it up to h|w| = {coarsest_good:.3}")
    }
}
