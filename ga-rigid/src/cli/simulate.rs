//! `simulate`: a scene, a method, rows of CSV.
//!
//! The equations run in the body's principal frame; a scene's `rotor` and `omega` describe
//! its own (mesh or point-cloud) frame, related by the principal rotor `P` (principal to
//! scene frame): the principal attitude is `R P`, the principal angular velocity
//! `~P Omega P`, and rows are turned back into the scene frame.

use ga_core::f64::g3::{Rotor, Sandwich};

use crate::csv::Row;
use crate::dynamics::{omega_to_vector, RigidBody};
use crate::error::Error;
use crate::integrators::{Method, Step, StepKind};
use crate::scene::Scene;
use crate::simulation::{Sample, Simulation};

/// The body of a scene in its principal frame, with gravity when the scene has it.
pub fn principal_body(scene: &Scene) -> Result<RigidBody, Error> {
    scene.principal_body()
}

/// The default limit on the estimated number of steps (`--max-steps`): 25 s of `rk4` but
/// 300 s of `splitting-8` in a release build, so time has its own limit (`--max-seconds`,
/// in `budget.rs`); 10^14 steps would take months.
pub const DEFAULT_MAX_STEPS: u64 = 100_000_000;

/// The default limit on the estimated CSV size in megabytes (`--max-output-mb`).
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

/// The attitude error rounding alone causes by the end of a run when `--max-phase-error`
/// is not given (rad).
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
                 --max-phase-error",
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

/// Refuse a fixed step beyond the method's stability limit `h |w|max` (the registry's
/// [`crate::integrators::StepLimit`]), naming the limit and the largest stable step.
pub fn check_stability(scene: &Scene, method: Method, step: Step) -> Result<(), Error> {
    let (Step::Fixed(h), Some(limit)) = (step, method.stable_step_rate(scene.torque.is_some()))
    else {
        return Ok(());
    };
    let rate = angular_speed_bound(scene);
    let hw = h * rate;
    if hw.is_nan() || hw > limit {
        return Err(Error::invalid(
            "--dt",
            format!(
                "h |w|max = {} is beyond {}'s stability limit {} (|w|max = {}): take dt <= {} \
                 or pass --allow-unstable",
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
            Step::Fixed(h) => ("--dt", format!("a step of {}", num(h))),
            Step::Tolerance(tol) => ("--tol", format!("a tolerance of {}", num(tol))),
            Step::AtSamples => ("run.samples", "one evaluation per sample".to_string()),
        };
        return Err(Error::invalid(
            field,
            format!(
                "{what} needs about {} steps to reach t_end = {}, above the limit {}; \
                 raise it with --max-steps",
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
                 raise it with --max-output-mb",
                scene.run.samples
            ),
        ));
    }
    Ok(work)
}

/// Fixed steps per period of the fastest rotation when `--dt` is not given: RK4's error
/// per period is then about (2 pi / 200)^4 ~ 1e-6 relative, the splitting's a few 1e-4.
pub const DEFAULT_STEPS_PER_PERIOD: f64 = 200.0;

/// The relative tolerance of `dopri` when `--tol` is not given.
pub const DEFAULT_TOLERANCE: f64 = 1e-9;

/// Where the step control of a run came from.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum StepSource {
    /// `--dt` or `--tol` on the command line (or no step control at all).
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

/// The sidecar record of a CSV written with `--out FILE`: `FILE.json`.
#[must_use]
pub fn sidecar_path(out: &std::path::Path) -> std::path::PathBuf {
    let mut name = out.as_os_str().to_os_string();
    name.push(".json");
    std::path::PathBuf::from(name)
}

/// What produced a CSV: the scene file, the method, the step control and where it came
/// from, the run.
#[derive(Clone, Copy, Debug)]
pub struct Record<'a> {
    /// The scene file as given on the command line.
    pub scene: &'a std::path::Path,
    /// The method.
    pub method: Method,
    /// The step control used.
    pub step: Step,
    /// Where the step control came from.
    pub source: StepSource,
    /// The run length and sampling.
    pub run: crate::scene::Run,
}

impl Record<'_> {
    /// One sentence on the step control, for the note on standard error.
    #[must_use]
    pub fn describe_step(&self) -> String {
        let reason = match self.source {
            StepSource::Given => "as given",
            StepSource::Default(reason) => reason,
        };
        match self.step {
            Step::Fixed(h) => format!("--dt {} ({reason})", crate::error::num(h)),
            Step::Tolerance(tol) => format!("--tol {} ({reason})", crate::error::num(tol)),
            Step::AtSamples => "no step: the solution is evaluated at the samples".to_string(),
        }
    }

    /// The record as a JSON object, `csv` naming the file it describes.
    #[must_use]
    pub fn to_json(self, csv: &std::path::Path) -> String {
        let (dt, tol) = match self.step {
            Step::Fixed(h) => (format!("{h:?}"), "null".to_string()),
            Step::Tolerance(tol) => ("null".to_string(), format!("{tol:?}")),
            Step::AtSamples => ("null".to_string(), "null".to_string()),
        };
        let source = match self.source {
            StepSource::Given => "given",
            StepSource::Default(reason) => reason,
        };
        format!(
            "{{\n  \"csv\": {},\n  \"scene\": {},\n  \"method\": {},\n  \"dt\": {dt},\n  \
             \"tol\": {tol},\n  \"step_source\": {},\n  \"t_end\": {:?},\n  \"samples\": {},\n  \
             \"ga_rigid_version\": {}\n}}\n",
            json_string(&csv.display().to_string()),
            json_string(&self.scene.display().to_string()),
            json_string(self.method.name()),
            json_string(source),
            self.run.t_end,
            self.run.samples,
            json_string(env!("CARGO_PKG_VERSION")),
        )
    }
}

/// A JSON string literal (RFC 8259, section 7).
fn json_string(text: &str) -> String {
    let mut out = String::with_capacity(text.len() + 2);
    out.push('"');
    for c in text.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            c if (c as u32) < 0x20 => out.push_str(&format!("\\u{:04x}", c as u32)),
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// Integrate `scene` with `method` and return one row per sample time.
pub fn run_simulation(scene: &Scene, method: Method, step: Step) -> Result<Vec<Row>, Error> {
    run_simulation_with_progress(scene, method, step, &mut |_| {})
}

/// [`run_simulation`], calling `progress(t)` after each sample (for a progress display).
pub fn run_simulation_with_progress(
    scene: &Scene,
    method: Method,
    step: Step,
    progress: &mut dyn FnMut(f64),
) -> Result<Vec<Row>, Error> {
    let body = principal_body(scene)?;
    let principal = scene.inertia.rotor();
    let integrator = method.integrator(step)?;
    let state = scene.principal_state();
    // The dynamics name the principal moments `body.moments`; a scene may have written
    // its body as a shape, points or a mesh, and the message should name what it wrote.
    let body_field = |e: Error| {
        if e.field() == Some("body.moments") {
            e.at(scene.body_field())
        } else {
            e
        }
    };
    let mut simulation = Simulation::new(body, state, integrator);
    let mut rows = Vec::with_capacity(scene.run.samples);
    for sample in simulation.samples(scene.run.t_end, scene.run.samples) {
        let sample = sample.map_err(body_field)?;
        rows.push(scene_row(method, principal, &sample)?);
        progress(sample.t);
    }
    Ok(rows)
}

/// The row unchanged if every number in it is finite; otherwise an error naming the
/// method, the time and the first column that is not, so that no method can write `inf`
/// or `NaN` into a CSV and exit 0.
fn finite_row(method: Method, row: Row) -> Result<Row, Error> {
    let columns = crate::csv::HEADER.split(',');
    match columns.zip(row.values()).find(|(_, x)| !x.is_finite()) {
        None => Ok(row),
        Some((column, x)) => Err(Error::invalid(
            method.name(),
            format!(
                "{column} is not finite ({x}) at t = {:e}: the scene's numbers are too large \
                 for this method",
                row.t
            ),
        )),
    }
}

/// A sample as a row in the scene's frame, checked finite ([`finite_row`]): turning a
/// finite principal-frame state into the scene's frame can still overflow.
fn scene_row(method: Method, principal: Rotor, sample: &Sample) -> Result<Row, Error> {
    finite_row(method, row(principal, sample))
}

/// A sample of the principal-frame simulation as a row in the scene's frame.
fn row(principal: Rotor, sample: &Sample) -> Row {
    let state = &sample.state;
    Row {
        t: sample.t,
        rotor: state.rotor * principal.reverse(),
        omega: omega_to_vector(principal.sandwich(state.omega)),
        energy: sample.energy,
        momentum: sample.momentum.undual().to_array(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A finite principal-frame sample whose angular velocity overflows when turned into
    /// the scene's frame is an error, not a row of `inf`.
    #[test]
    fn a_sample_that_overflows_in_the_scene_frame_is_an_error() {
        use crate::dynamics::State;
        use ga_core::f64::g3::Bivector;
        let sample = Sample {
            t: 2.0,
            state: State {
                rotor: Rotor::ONE,
                omega: Bivector::new(1.5e308, 1.5e308, 0.0),
            },
            energy: 1.0,
            momentum: Bivector::new(0.0, 0.0, 1.0),
        };
        // A quarter turn in the e12-e13 plane mixes the two huge components.
        let principal = (Bivector::new(0.0, 0.0, 1.0) * -std::f64::consts::FRAC_PI_8).exp();
        let e = scene_row(Method::Rk4, principal, &sample)
            .unwrap_err()
            .to_string();
        assert!(e.starts_with("rk4: w"), "{e}");
        assert!(
            e.contains("is not finite (") && e.contains("inf) at t = 2e0"),
            "{e}"
        );
        let fine = Sample {
            state: State {
                rotor: Rotor::ONE,
                omega: Bivector::new(1.0, 1.0, 0.0),
            },
            ..sample
        };
        assert!(scene_row(Method::Rk4, principal, &fine).is_ok());
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

    #[test]
    fn a_row_with_an_infinite_energy_is_an_error_naming_the_method_and_column() {
        let good = Row {
            t: 1.0,
            rotor: Rotor::ONE,
            omega: [0.0, 0.0, 1.0],
            energy: 0.5,
            momentum: [0.0, 0.0, 1.0],
        };
        assert_eq!(finite_row(Method::Exact, good).unwrap(), good);
        let bad = Row {
            energy: f64::INFINITY,
            ..good
        };
        let e = finite_row(Method::Splitting, bad).unwrap_err().to_string();
        assert!(
            e.starts_with("splitting: energy is not finite (inf) at t = 1e0"),
            "{e}"
        );
        let nan = Row {
            omega: [0.0, f64::NAN, 1.0],
            ..good
        };
        let e = finite_row(Method::Exact, nan).unwrap_err().to_string();
        assert!(e.starts_with("exact: w2 is not finite (NaN)"), "{e}");
    }
}
