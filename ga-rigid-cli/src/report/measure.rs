//! One run of one method on one scene: the states at the sample times, the errors against
//! a reference that is not the method itself, and a repeated timing.

use std::time::{Duration, Instant};

use ga_core::f64::g3::Rotor;

use ga_rigid::dynamics::State;
use ga_rigid::error::Error;
use ga_rigid::integrators::{ClosedForm, DormandPrince, ExactFreeBody, Integrator, LieRk4};
use ga_rigid::registry::{Method, Step, StepKind, DOPRI_ABSOLUTE_TOLERANCE_RATIO};

use super::scenes::{Sweep, TestScene, SAMPLES};

/// The least total time of the timed repetitions of one run.
pub const MIN_TOTAL_TIME: Duration = Duration::from_millis(10);
/// The least number of timed repetitions of one run (after one warm-up run).
pub const MIN_REPEATS: usize = 3;
/// Dormand-Prince's tightest tolerance: the independent check of the exact flow, and the
/// reference under a torque.
pub const TIGHTEST_TOL: f64 = 1e-13;

/// The sign-free angle between two attitudes: `2 atan2(|<D>_2|, |<D>_0|)`, `D = ~R_ref R`.
#[must_use]
pub fn attitude_error(rotor: Rotor, reference: Rotor) -> f64 {
    let d = reference.reverse() * rotor;
    2.0 * d.grade2().norm().atan2(d.s.abs())
}

/// The sample times `k t_end / SAMPLES`, `k = 1..=SAMPLES`, the last exactly `t_end`.
#[must_use]
pub fn sample_times(t_end: f64) -> Vec<f64> {
    (1..=SAMPLES)
        .map(|k| {
            if k == SAMPLES {
                t_end
            } else {
                t_end * k as f64 / SAMPLES as f64
            }
        })
        .collect()
}

/// A solution at the sample times that others are measured against.
pub struct Reference {
    /// What it is, for the page.
    pub label: String,
    /// The method that produced it: a run of this method is measured against the other
    /// reference, never against itself.
    pub method: Method,
    /// The states at [`sample_times`].
    pub states: Vec<State>,
}

/// The two references of a scene: the primary one and an independent second solution.
/// For a free body the primary is the exact flow, the second Dormand-Prince at its
/// tightest tolerance; under a torque the primary is that Dormand-Prince run, the second
/// Lie-RK4 at `h |w| = 1e-3`.
///
///
/// A [`Sweep::Long`] scene is a symmetric body, and its check is the closed form: over
/// 10^5 periods Dormand-Prince at an affordable tolerance has lost the phase.
pub fn references(scene: &TestScene) -> Result<(Reference, Reference), Error> {
    let times = sample_times(scene.t_end);
    let symmetric = scene.body.symmetry_axis(1e-12).is_some();
    if scene.sweep == Sweep::Long && symmetric && !scene.body.has_torque() {
        let closed = Reference {
            label: "the lecture's closed form of the symmetric top".into(),
            method: Method::ClosedForm,
            states: at_each_sample(&mut ClosedForm::new(), scene, &times)?,
        };
        return Ok((exact_reference(scene, &times)?, closed));
    }
    let dopri = Reference {
        label: format!("dopri at tol {TIGHTEST_TOL:.0e}"),
        method: Method::Dopri,
        states: advance_through(
            &mut DormandPrince::new(TIGHTEST_TOL, TIGHTEST_TOL * DOPRI_ABSOLUTE_TOLERANCE_RATIO)?
                .with_max_steps(100_000_000),
            scene,
            &times,
        )?,
    };
    if scene.body.has_torque() {
        let h = 1e-3 / scene.rate().max(f64::MIN_POSITIVE);
        let lie = Reference {
            label: format!("lie-rk4 at h = {h:.2e} (h |w| = 1e-3)"),
            method: Method::LieRk4,
            states: advance_through(&mut LieRk4::new(h)?, scene, &times)?,
        };
        Ok((dopri, lie))
    } else {
        Ok((exact_reference(scene, &times)?, dopri))
    }
}

/// The exact flow at each sample time.
fn exact_reference(scene: &TestScene, times: &[f64]) -> Result<Reference, Error> {
    Ok(Reference {
        label: "the exact flow (Jacobi elliptic functions)".into(),
        method: Method::Exact,
        states: at_each_sample(&mut ExactFreeBody::new(), scene, times)?,
    })
}

/// A solution evaluated at each sample straight from t = 0: no error is carried from one
/// sample to the next.
fn at_each_sample(
    solution: &mut dyn Integrator,
    scene: &TestScene,
    times: &[f64],
) -> Result<Vec<State>, Error> {
    times
        .iter()
        .map(|&t| solution.advance(&scene.body, 0.0, scene.initial, t))
        .collect()
}

/// Advance from the scene's start through each of `times`, keeping the states there: a
/// reference lands on every sample time, where a measured run may interpolate.
fn advance_through(
    integrator: &mut dyn Integrator,
    scene: &TestScene,
    times: &[f64],
) -> Result<Vec<State>, Error> {
    let mut state = scene.initial;
    let mut t = 0.0;
    let mut states = Vec::with_capacity(times.len());
    for &sample in times {
        state = integrator.advance(&scene.body, t, state, sample - t)?;
        t = sample;
        states.push(state);
    }
    Ok(states)
}

/// The errors of a run against a reference, over the samples and at the end.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Errors {
    /// The attitude error at the end time (rad).
    pub attitude_end: f64,
    /// The largest attitude error over the samples (rad).
    pub attitude_max: f64,
    /// The body momentum's error relative to its size at the end time.
    pub momentum_end: f64,
    /// The largest relative body-momentum error over the samples.
    pub momentum_max: f64,
    /// The total energy's error against the reference's, relative to the initial energy,
    /// at the end time: the drift of a conserved energy, and still the error when a
    /// turning potential (the gravity gradient) changes the energy.
    pub energy_end: f64,
    /// The largest relative energy error over the samples.
    pub energy_max: f64,
}

/// The errors of `states` against `reference` (both at [`sample_times`]).
#[must_use]
pub fn errors(scene: &TestScene, states: &[State], reference: &[State]) -> Errors {
    let times = sample_times(scene.t_end);
    let e0 = scene.body.total_energy(0.0, &scene.initial);
    let mut out = Errors::default();
    for ((state, r), &t) in states.iter().zip(reference).zip(&times) {
        let attitude = attitude_error(state.rotor, r.rotor);
        let m = scene.body.body_momentum(state.omega);
        let m_ref = scene.body.body_momentum(r.omega);
        let momentum = (m - m_ref).norm() / m_ref.norm();
        let energy =
            (scene.body.total_energy(t, state) - scene.body.total_energy(t, r)).abs() / e0.abs();
        // `max` would drop a NaN: keep it, it is the news.
        let worse = |a: f64, b: f64| if a.is_nan() || a > b { a } else { b };
        out.attitude_max = worse(attitude, out.attitude_max);
        out.momentum_max = worse(momentum, out.momentum_max);
        out.energy_max = worse(energy, out.energy_max);
        out.attitude_end = attitude;
        out.momentum_end = momentum;
        out.energy_end = energy;
    }
    out
}

/// A run's states at the sample times and the steps it took.
pub struct Run {
    /// The states at [`sample_times`].
    pub states: Vec<State>,
    /// Steps taken: fixed steps, accepted adaptive steps, or evaluations of a solution.
    pub steps: u64,
}

/// One run of `method` at `setting` (a step size or a tolerance, by the method's kind).
pub fn run_once(scene: &TestScene, method: Method, setting: f64) -> Result<Run, Error> {
    run_until(scene, method, setting, scene.t_end)
}

/// [`run_once`] over `[0, t_end]` instead of the scene's own end time.
///
/// Every method is built by the registry ([`Method::integrator`]), exactly as the command
/// and the library build it, so that a row named after a method is that method's run.
fn run_until(scene: &TestScene, method: Method, setting: f64, t_end: f64) -> Result<Run, Error> {
    let times = sample_times(t_end);
    let step = match method.step_kind() {
        StepKind::Adaptive => Step::Tolerance(setting),
        // A hair above h, so that rounding in dt / h never adds a sub-step: every
        // sample interval is a whole number of steps of exactly h.
        StepKind::Fixed => Step::Fixed(setting * (1.0 + 1e-9)),
        StepKind::AtSamples => Step::AtSamples,
    };
    let mut integrator = method.integrator(step)?;
    let states = integrator.advance_to_each(&scene.body, 0.0, scene.initial, &times)?;
    let steps = match method.step_kind() {
        StepKind::Adaptive => integrator.accepted_steps().ok_or_else(|| {
            Error::invalid(
                method.name(),
                "an adaptive method must count its accepted steps",
            )
        })?,
        StepKind::Fixed => (t_end / setting).round() as u64,
        StepKind::AtSamples => SAMPLES,
    };
    Ok(Run { states, steps })
}

/// Wall-clock times of repeated runs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Timing {
    /// The median of the timed runs.
    pub median: Duration,
    /// The fastest timed run.
    pub min: Duration,
    /// How many runs were timed (the warm-up not counted).
    pub repeats: usize,
}

/// Run `method` once to warm up (and to keep its result), then again until the timed runs
/// add up to [`MIN_TOTAL_TIME`] and number at least [`MIN_REPEATS`].
pub fn timed_run(
    scene: &TestScene,
    method: Method,
    setting: f64,
) -> (Result<Run, Error>, Option<Timing>) {
    timed(|| run_once(scene, method, setting))
}

/// The timing rule of every measured run, for any run: once to warm up (the result is
/// kept), then, if that succeeded, again until the timed runs add up to
/// [`MIN_TOTAL_TIME`] and number at least [`MIN_REPEATS`]; the median and the fastest.
pub fn timed<T>(mut run: impl FnMut() -> Result<T, Error>) -> (Result<T, Error>, Option<Timing>) {
    let first = run();
    if first.is_err() {
        return (first, None);
    }
    let mut times = Vec::new();
    let mut total = Duration::ZERO;
    while times.len() < MIN_REPEATS || total < MIN_TOTAL_TIME {
        let start = Instant::now();
        let result = run();
        let elapsed = start.elapsed();
        std::hint::black_box(&result);
        times.push(elapsed);
        total += elapsed;
    }
    times.sort();
    let timing = Timing {
        median: times[times.len() / 2],
        min: times[0],
        repeats: times.len(),
    };
    (first, Some(timing))
}

/// The estimated time of a whole run from one run over the first thousandth of the time.
pub fn estimated_run_time(scene: &TestScene, method: Method, setting: f64) -> Duration {
    let start = Instant::now();
    let _ = std::hint::black_box(run_until(scene, method, setting, scene.t_end / 1000.0));
    start.elapsed() * 1000
}
