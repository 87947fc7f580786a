//! The limits a run is checked against before any work is done: the step control when
//! none is given ([`default_step`]), the stability of a fixed step ([`check_stability`]),
//! the phase rounding alone loses by `t_end` ([`check_phase_error`]), and the work in
//! steps, output and seconds ([`check_work`], [`check_seconds`]). [`plan`] runs them all
//! in order; the command and other front ends call it and rename the fields (`dt`,
//! `max_steps`, ...) to their own words at their edge.

use crate::dynamics::omega_to_vector;
use crate::error::{num, Error};
use crate::registry::{Method, Step, StepKind};
use crate::scene::Scene;

/// The limits of one run; [`Limits::default`] gives the command's defaults.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Limits {
    /// The most steps (or solution evaluations) a run may be estimated to take.
    pub max_steps: u64,
    /// The most megabytes of CSV its samples may take.
    pub max_output_mb: u64,
    /// The most seconds it may be estimated to take in a release build.
    pub max_seconds: u64,
    /// The most attitude (rad) rounding alone may lose by `t_end`; infinity turns the
    /// check off.
    pub max_phase_error: f64,
    /// Run a fixed step beyond the method's stability limit instead of refusing it.
    pub allow_unstable: bool,
}

impl Default for Limits {
    fn default() -> Self {
        Limits {
            max_steps: DEFAULT_MAX_STEPS,
            max_output_mb: DEFAULT_MAX_OUTPUT_MB,
            max_seconds: DEFAULT_MAX_SECONDS,
            max_phase_error: DEFAULT_MAX_PHASE_ERROR,
            allow_unstable: false,
        }
    }
}

/// A run that passed its checks: the step control, where it came from and what it costs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plan {
    /// The step control to run with.
    pub step: Step,
    /// Where the step control came from.
    pub source: StepSource,
    /// The estimated steps and output.
    pub work: Work,
    /// The estimated seconds in a release build.
    pub seconds: f64,
}

/// Check a run of `scene` by `method` before it starts, in the order a user fixes them:
/// the step control ([`Method::given_step`], or the scene's default when neither `dt`
/// nor `tol` is given), the phase error bound, the stability of a fixed step (unless
/// `allow_unstable`), the work and the time. `given` is the result of
/// [`Method::given_step`], which a front end may call earlier to report a bad step before
/// it reads the scene.
pub fn plan(
    scene: &Scene,
    method: Method,
    given: Option<Step>,
    limits: &Limits,
) -> Result<Plan, Error> {
    let (step, source) = match given {
        Some(step) => (step, StepSource::Given),
        None => default_step(scene, method),
    };
    if limits.max_phase_error.is_nan() || limits.max_phase_error <= 0.0 {
        return Err(Error::invalid(
            "max_phase_error",
            format!(
                "the bound must be positive (infinity turns the check off), got {}",
                num(limits.max_phase_error)
            ),
        ));
    }
    check_phase_error(scene, limits.max_phase_error)?;
    if !limits.allow_unstable {
        check_stability(scene, method, step)?;
    }
    let work = check_work(scene, step, limits.max_steps, limits.max_output_mb)?;
    let seconds = check_seconds(method, step, work.steps, limits.max_seconds)?;
    Ok(Plan {
        step,
        source,
        work,
        seconds,
    })
}

/// The default limit on the estimated number of steps ([`Limits::max_steps`]): 25 s of `rk4` but
/// 300 s of `splitting-8` in a release build, so time has its own limit
/// ([`Limits::max_seconds`]); 10^14 steps would take months.
pub const DEFAULT_MAX_STEPS: u64 = 100_000_000;

/// The default limit on the estimated CSV size in megabytes ([`Limits::max_output_mb`]).
pub const DEFAULT_MAX_OUTPUT_MB: u64 = 1024;

/// The most bytes one CSV row can take: twelve numbers of at most 24 characters
/// (`-1.2345678901234567e-300`) and their separators.
pub const MAX_ROW_BYTES: u64 = 12 * 25;

/// What a run will cost, estimated before it starts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Work {
    /// The number of steps (or solution evaluations), an upper estimate for fixed steps and
    /// a rough one for the adaptive method.
    pub steps: f64,
    /// The size of the CSV in bytes, an upper bound.
    pub output_bytes: f64,
}

/// A bound on the body's angular speed over the run, in radians per unit time, from the
/// rates it can actually reach. A free body keeps its kinetic energy `E` and `|L|`, so
/// `|w|^2 = sum L_k^2 / i_k^2` is bounded by its largest value on the set of `L` with those
/// two invariants (found exactly: [`free_rate_bound`]); a needle spinning about its axis is
/// bounded by that spin, not by `|L| / i_min`, which is a million times more for moments
/// (1, 1, 1e-6). Under gravity the kinetic energy can grow by at most `2 m |g| |c|`, and
/// `|w|^2 <= 2 E_kin / i_min`.
#[must_use]
pub fn angular_speed_bound(scene: &Scene) -> f64 {
    let moments = scene.inertia.moments();
    let w = omega_to_vector(scene.principal_state().omega);
    let squares = [0, 1, 2].map(|k| (moments[k] * w[k]) * (moments[k] * w[k]));
    let two_e: f64 = (0..3).map(|k| squares[k] / moments[k]).sum();
    let smallest = moments.iter().copied().fold(f64::INFINITY, f64::min);
    match scene.torque {
        None => free_rate_bound(moments, squares, two_e)
            .max(w.iter().map(|x| x * x).sum::<f64>().sqrt()),
        Some(gravity) => {
            let mass = scene.inertia.mass().unwrap_or(1.0);
            let potential = mass * gravity.g.norm() * gravity.com_offset.norm();
            ((two_e + 4.0 * potential) / smallest).sqrt()
        }
    }
}

/// The largest `|w|` a free body with principal moments `i` reaches, from its squared body
/// momenta `L_k^2` and twice its energy. With `x_k = L_k^2 >= 0`, `sum x_k = |L|^2` and
/// `sum x_k / i_k = 2E` fix a segment, and `|w|^2 = sum x_k / i_k^2` is linear on it, so its
/// largest value is at an end of the segment, where at most two `x_k` are non-zero.
#[must_use]
pub fn free_rate_bound(i: [f64; 3], squares: [f64; 3], two_e: f64) -> f64 {
    let l2: f64 = squares.iter().sum();
    let smallest = i.iter().copied().fold(f64::INFINITY, f64::min);
    // Rounding may put an end a hair outside `x >= 0`.
    let slack = 1e-9 * l2;
    let mut best: Option<f64> = None;
    for (a, b) in [(0, 1), (0, 2), (1, 2)] {
        let (ja, jb) = (1.0 / i[a], 1.0 / i[b]);
        if (ja - jb).abs() <= 1e-12 * ja.max(jb) {
            continue;
        }
        let xa = (two_e - l2 * jb) / (ja - jb);
        let xb = l2 - xa;
        if xa >= -slack && xb >= -slack {
            let w2 = xa.max(0.0) * ja * ja + xb.max(0.0) * jb * jb;
            best = Some(best.map_or(w2, |b: f64| b.max(w2)));
        }
    }
    // A sphere has no ends (`|w|` is constant); `|w|^2 <= 2E / i_min` always holds.
    let fallback = two_e / smallest;
    best.unwrap_or(fallback).min(fallback).sqrt()
}

/// The attitude error rounding alone causes by the end of a run when
/// [`Limits::max_phase_error`] is not set (rad).
pub const DEFAULT_MAX_PHASE_ERROR: f64 = 1e-3;

/// The phase every method loses to rounding by `t_end`: the angle `|w|max t_end` is known
/// to about one part in `2^52`, so even the exact flow is off by about `|w|max t_end eps`.
#[must_use]
pub fn phase_error(scene: &Scene) -> f64 {
    angular_speed_bound(scene) * scene.run.t_end * f64::EPSILON
}

/// Refuse a run whose attitude at `t_end` rounding alone would put more than
/// `max_phase_error` rad off ([`phase_error`]), whatever the method: 17 digits of a random
/// attitude look like a result.
pub fn check_phase_error(scene: &Scene, max_phase_error: f64) -> Result<f64, Error> {
    let error = phase_error(scene);
    if error.is_nan() || error > max_phase_error {
        return Err(Error::invalid(
            "run.t_end",
            format!(
                "t_end = {} at |w|max = {} loses about {:.1e} rad of attitude to rounding \
                 (|w|max t_end eps), above the bound {}; shorten the run or raise \
                 max_phase_error",
                short(scene.run.t_end),
                short(angular_speed_bound(scene)),
                error,
                short(max_phase_error)
            ),
        ));
    }
    Ok(error)
}

/// A number to three significant digits, for messages: `5.01`, `0.399`, `1.1e16`.
fn short(x: f64) -> String {
    if x != 0.0 && (x.abs() < 1e-3 || x.abs() >= 1e6) || !x.is_finite() {
        return format!("{x:.2e}");
    }
    let digits = (2 - x.abs().log10().floor() as i32).max(0) as usize;
    let text = format!("{x:.digits$}");
    if text.contains('.') {
        text.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        text
    }
}

/// The time between samples, `t_end / (samples - 1)`: the longest step a fixed-step method
/// takes, whatever its `dt` ([`crate::integrators::Integrator::advance`] cuts each sample
/// interval into equal steps of at most `dt`).
#[must_use]
pub fn sample_spacing(scene: &Scene) -> f64 {
    scene.run.t_end / (scene.run.samples.max(2) - 1) as f64
}

/// Refuse a fixed step beyond the method's stability limit `h |w|max` (the registry's
/// [`crate::registry::StepLimit`]), naming the limit and the largest stable step. The step
/// checked is the one taken: `dt`, or the sample spacing where that is shorter.
pub fn check_stability(scene: &Scene, method: Method, step: Step) -> Result<(), Error> {
    let (Step::Fixed(h), Some(limit)) = (step, method.stable_step_rate(scene.torque.is_some()))
    else {
        return Ok(());
    };
    let rate = angular_speed_bound(scene);
    // Each sample interval is cut into equal steps of at most `dt`, so no step is longer
    // than the sample spacing.
    let h = h.min(sample_spacing(scene));
    stable_step(method, h, rate, limit)
}

/// The stability rule itself, in any dimension: a fixed step `h` at angular speeds up to
/// `rate` is refused when `h rate` is beyond the method's `limit` (or NaN), naming the limit
/// and the largest stable step.
pub(crate) fn stable_step(method: Method, h: f64, rate: f64, limit: f64) -> Result<(), Error> {
    let hw = h * rate;
    if hw.is_nan() || hw > limit {
        return Err(Error::invalid(
            "dt",
            format!(
                "h |w|max = {} is beyond {}'s stability limit {} (|w|max = {}): take dt <= {} \
                 or pass allow_unstable",
                short(hw),
                method.name(),
                short(limit),
                short(rate),
                short(limit / rate)
            ),
        ));
    }
    Ok(())
}

/// Estimate the steps and output size of a run: `t_end / dt` plus one per sample for
/// fixed steps; for Dormand-Prince, whose local error grows as `(h |w|)^5`, about
/// `tol^(-1/5)` steps per radian turned; one evaluation per sample otherwise.
#[must_use]
pub fn estimate_work(scene: &Scene, step: Step) -> Work {
    let samples = scene.run.samples as f64;
    let steps = match step {
        Step::Fixed(h) => scene.run.t_end / h + samples,
        Step::Tolerance(tol) => {
            let radians = scene.run.t_end * angular_speed_bound(scene);
            radians * tol.powf(-0.2) + samples
        }
        Step::AtSamples => samples,
    };
    Work {
        steps,
        output_bytes: (samples + 1.0) * MAX_ROW_BYTES as f64,
    }
}

/// Refuse a run whose estimated work is above the limits, naming the option that set it.
pub fn check_work(
    scene: &Scene,
    step: Step,
    max_steps: u64,
    max_output_mb: u64,
) -> Result<Work, Error> {
    use crate::error::num;
    let work = estimate_work(scene, step);
    // NaN steps (never expected) count as too many.
    if work.steps.is_nan() || work.steps > max_steps as f64 {
        let (field, what) = match step {
            Step::Fixed(h) => ("dt", format!("a step of {}", num(h))),
            Step::Tolerance(tol) => ("tol", format!("a tolerance of {}", num(tol))),
            Step::AtSamples => ("run.samples", "one evaluation per sample".to_string()),
        };
        return Err(Error::invalid(
            field,
            format!(
                "{what} needs about {} steps to reach t_end = {}, above the limit {}; \
                 raise it with max_steps",
                if work.steps.is_finite() {
                    format!("{:.1e}", work.steps)
                } else {
                    "1e308".to_string()
                },
                num(scene.run.t_end),
                max_steps
            ),
        ));
    }
    let megabytes = work.output_bytes / 1e6;
    if megabytes > max_output_mb as f64 {
        return Err(Error::invalid(
            "run.samples",
            format!(
                "{} rows may take {megabytes:.0} MB of CSV, above the limit {max_output_mb} MB; \
                 raise it with max_output_mb",
                scene.run.samples
            ),
        ));
    }
    Ok(work)
}

/// Fixed steps per period of the fastest rotation when `dt` is not given: RK4's error
/// per period is then about (2 pi / 200)^4 ~ 1e-6 relative, the splitting's a few 1e-4.
pub const DEFAULT_STEPS_PER_PERIOD: f64 = 200.0;

/// The relative tolerance of the adaptive methods when `tol` is not given.
pub const DEFAULT_TOLERANCE: f64 = 1e-9;

/// Where the step control of a run came from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StepSource {
    /// `dt` or `tol` as given (or no step control at all).
    Given,
    /// Chosen from the scene; the text says how.
    Default(&'static str),
}

/// The step control when none is given: `dt = period / 200` with the period `2 pi / w`
/// of the fastest rotation the body can reach ([`angular_speed_bound`]), or `t_end / 200`
/// for a body at rest; [`DEFAULT_TOLERANCE`] for `dopri`.
#[must_use]
pub fn default_step(scene: &Scene, method: Method) -> (Step, StepSource) {
    match method.step_kind() {
        StepKind::Fixed => {
            let speed = angular_speed_bound(scene);
            let period = std::f64::consts::TAU / speed;
            if period.is_finite() && period > 0.0 {
                (
                    Step::Fixed(period / DEFAULT_STEPS_PER_PERIOD),
                    StepSource::Default("the period 2 pi / |w|max over 200"),
                )
            } else {
                (
                    Step::Fixed(scene.run.t_end / DEFAULT_STEPS_PER_PERIOD),
                    StepSource::Default("t_end / 200 for a body at rest"),
                )
            }
        }
        StepKind::Adaptive => (
            Step::Tolerance(DEFAULT_TOLERANCE),
            StepSource::Default("the default relative tolerance"),
        ),
        StepKind::AtSamples => (Step::AtSamples, StepSource::Given),
    }
}

/// The default limit on a `simulate` run's estimated time in seconds ([`Limits::max_seconds`]).
pub const DEFAULT_MAX_SECONDS: u64 = 60;

/// The default limit on the estimated time of the scenes a report adds, all of them
/// together, in seconds.
pub const DEFAULT_REPORT_MAX_SECONDS: u64 = 600;

/// A duration in seconds for a message: `0.5 s`, `42 s`, `3.1e4 s`, `9.3e-5 s` (never
/// `0.00 s` for a time that is not zero).
#[must_use]
pub fn seconds(s: f64) -> String {
    if !s.is_finite() || s >= 1e4 || (s != 0.0 && s < 0.01) {
        format!("{:.1e} s", s.min(f64::MAX))
    } else if s >= 10.0 {
        format!("{s:.0} s")
    } else {
        format!("{s:.2} s")
    }
}

/// Refuse a run of `method` at `step` whose `steps` (from
/// [`check_work`]) would take more than `max_seconds`; the estimate
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
            Step::Fixed(h) => ("dt", format!("a step of {}", num(h))),
            Step::Tolerance(tol) => ("tol", format!("a tolerance of {}", num(tol))),
            Step::AtSamples => ("run.samples", "one evaluation per sample".to_string()),
        };
        return Err(Error::invalid(
            field,
            format!(
                "{what} needs about {steps:.1e} steps of {}, about {} at {} ns a step, \
                 above the limit of {max_seconds} s; raise it with max_seconds",
                method.name(),
                seconds(estimate),
                method.info().ns_per_step
            ),
        ));
    }
    Ok(estimate)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A free body turning at about 10 rad/s for 1 s, sampled `samples` times.
    fn spinning(samples: usize) -> Scene {
        let text = format!(
            "[body]\nmoments = [1.0, 2.0, 2.5]\n[initial]\nrotor = [1, 0, 0, 0]\n\
             omega = [1.0, 10.0, 2.0]\n[run]\nt_end = 1.0\nsamples = {samples}\n"
        );
        Scene::parse(&text, std::path::Path::new("spinning.toml")).unwrap()
    }

    /// `dt = 1` on a scene sampled every 0.01 s takes steps of 0.01 s (each sample
    /// interval is cut into steps of at most `dt`): `h |w|max` about 0.1, well inside
    /// rk4's limit. Sampled only at the ends, the same `dt` is a step of 1 s, beyond it.
    #[test]
    fn the_stability_check_uses_the_step_taken_not_a_longer_dt() {
        assert!(check_stability(&spinning(101), Method::Rk4, Step::Fixed(1.0)).is_ok());
        let e = check_stability(&spinning(2), Method::Rk4, Step::Fixed(1.0)).unwrap_err();
        assert!(
            e.to_string().contains("beyond rk4's stability limit"),
            "{e}"
        );
    }

    /// A limit of 0 s is not "0.00 s": the estimate is printed with its digits.
    #[test]
    fn a_tiny_time_estimate_is_not_printed_as_zero() {
        assert_eq!(seconds(2.5e-4), "2.5e-4 s");
        assert_eq!(seconds(0.0), "0.00 s");
        assert_eq!(seconds(0.5), "0.50 s");
        let e = check_seconds(Method::Rk4, Step::Fixed(0.01), 400.0, 0).unwrap_err();
        // 400 steps of rk4 at its 250 ns a step.
        let expected = seconds(400.0 * Method::Rk4.info().ns_per_step * 1e-9);
        assert_eq!(expected, "1.0e-4 s");
        assert!(e.to_string().contains("about 1.0e-4 s"), "{e}");
    }

    #[test]
    fn short_numbers_keep_three_digits() {
        assert_eq!(short(5.008991914547277), "5.01");
        assert_eq!(short(0.3992819381863115), "0.399");
        assert_eq!(short(2.0), "2");
        assert_eq!(short(1e16), "1.00e16");
        assert_eq!(short(0.001), "0.001");
        assert_eq!(short(123.456), "123");
    }
}
