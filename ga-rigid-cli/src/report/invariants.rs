//! The long runs of issue 11: does every method keep its rotor unit over 10^6 steps, and
//! do the compositions and splittings keep the momentum and a bounded energy error over
//! 10^5 periods? One table, with a verdict against the issue's bounds on each row.
//!
//! Each run advances one step per call of [`Integrator::advance`] and measures after every
//! step, so the largest value over the run is the largest over every step, not over a few
//! samples. The energy error is *bounded* when its largest value over the last tenth of
//! the run is at most [`ENERGY_GROWTH`] times that over the first tenth: a method that
//! drifts, even slowly, grows by the ratio of the times (ten at least) instead.

use std::f64::consts::PI;
use std::fmt::Write as _;
use std::time::{Duration, Instant};

use ga_core::f64::g3::{Bivector, Rotor, Vector};

use ga_rigid::dynamics::{omega_from_vector, Gravity, RigidBody, State};
use ga_rigid::error::Error;
use ga_rigid::exact_flow::free_body_orbit;
use ga_rigid::integrators::Integrator;
use ga_rigid::registry::{Method, Step, StepKind, METHODS};

use super::Size;

/// The issue's bound on `|R ~R - 1|` over [`UNIT_STEPS`] steps.
pub const UNIT_DEFECT_BOUND: f64 = 1e-13;
/// The issue's number of steps for the unit-rotor check.
pub const UNIT_STEPS: u64 = 1_000_000;
/// The issue's number of periods for the momentum and energy check.
pub const PERIODS: f64 = 1e5;
/// How much larger the energy error may be over the last tenth of a run than over the
/// first tenth and still count as bounded.
pub const ENERGY_GROWTH: f64 = 2.0;
/// The bound on the relative momentum error of the compositions: about 10^6 rounding
/// units. Every sub-flow keeps the momentum exactly, so only rounding moves it, and over
/// 10^7 sub-flows it walks to about 1e-11 (a truncation error would show at the level of
/// the energy error, 1e-4 to 1e-11 here).
pub const MOMENTUM_BOUND: f64 = 1e-10;

/// The step of the unit-rotor runs on the heavy top.
const UNIT_STEP: f64 = 1e-3;
/// The tolerance of the adaptive methods in the unit-rotor runs.
const UNIT_TOL: f64 = 1e-10;
/// Steps a period of the free body in the momentum and energy runs.
const FREE_STEPS_PER_PERIOD: f64 = 20.0;
/// The step of the heavy top's momentum and energy runs, by order: long enough that the
/// energy error of the method stays well above the random walk of rounding (about 1e-13
/// over 10^6 steps), which would otherwise grow between the first and the last tenth.
fn heavy_step(method: Method) -> f64 {
    match method {
        Method::ExactSplitting => 0.05,
        Method::ExactSplitting4 => 0.1,
        _ => 0.25,
    }
}

/// How far the runs go.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Scale {
    /// Steps of each unit-rotor run.
    pub unit_steps: u64,
    /// Periods of each momentum and energy run.
    pub periods: f64,
}

impl Scale {
    /// The issue's scale ([`UNIT_STEPS`], [`PERIODS`]) for a full report, a hundredth of it
    /// for a quick one.
    #[must_use]
    pub fn of(size: Size) -> Scale {
        match size {
            Size::Full => Scale {
                unit_steps: UNIT_STEPS,
                periods: PERIODS,
            },
            Size::Quick => Scale {
                unit_steps: UNIT_STEPS / 100,
                periods: PERIODS / 100.0,
            },
        }
    }

    /// Whether this is the issue's scale, at which the verdicts are the issue's.
    #[must_use]
    pub fn is_full(&self) -> bool {
        self.unit_steps >= UNIT_STEPS && self.periods >= PERIODS
    }
}

/// What one long run of one method measured.
#[derive(Clone, Debug, PartialEq)]
pub struct LongRun {
    /// The method.
    pub method: Method,
    /// `unit rotor` or `invariants`.
    pub check: &'static str,
    /// The scene, in words.
    pub scene: &'static str,
    /// Steps taken (calls of `advance`, one step each; an adaptive method may take more).
    pub steps: u64,
    /// The simulated time over the period of the scene.
    pub periods: f64,
    /// The largest `|R ~R - 1|` after any step.
    pub unit_defect: f64,
    /// The largest relative energy error over the first tenth of the run.
    pub energy_first: f64,
    /// The largest relative energy error over the last tenth of the run.
    pub energy_last: f64,
    /// The largest relative energy error over the run.
    pub energy_max: f64,
    /// The largest relative error of the conserved momentum (`|L - L0| / |L0|` for a free
    /// body, the vertical component of `L` for the Lagrange top) over the run.
    pub momentum_max: f64,
    /// Why the run stopped, if it did.
    pub failure: Option<String>,
    /// The run's wall-clock time.
    pub elapsed: Duration,
}

impl LongRun {
    /// Whether the run meets the bounds of its check: `|R ~R - 1| <=` [`UNIT_DEFECT_BOUND`]
    /// for every run, and for the invariant runs a bounded energy error
    /// ([`ENERGY_GROWTH`]) and a momentum error within [`MOMENTUM_BOUND`].
    #[must_use]
    pub fn passes(&self) -> bool {
        let unit = self.unit_defect <= UNIT_DEFECT_BOUND;
        let invariants = self.check != INVARIANTS
            || (self.energy_last <= ENERGY_GROWTH * self.energy_first
                && self.momentum_max <= MOMENTUM_BOUND);
        self.failure.is_none() && unit && invariants
    }
}

const UNIT: &str = "unit rotor";
const INVARIANTS: &str = "invariants";

/// The long runs at `scale`: every method of the registry over `scale.unit_steps` steps
/// (the unit-rotor check), then the compositions and splittings over `scale.periods`
/// periods (the momentum and energy check). `progress` hears of each finished run.
pub fn long_runs(scale: Scale, progress: &mut dyn FnMut(&str)) -> Result<Vec<LongRun>, Error> {
    let mut rows = Vec::new();
    for row in METHODS {
        let run = unit_run(row.method, scale.unit_steps)?;
        progress(row.name);
        rows.push(run);
    }
    for method in [
        Method::Splitting,
        Method::SplittingCayley,
        Method::SplittingCasimir,
        Method::Splitting4,
        Method::Splitting6,
        Method::Splitting8,
    ] {
        rows.push(free_invariant_run(method, scale.periods)?);
        progress(method.name());
    }
    for method in [
        Method::ExactSplitting,
        Method::ExactSplitting4,
        Method::ExactSplitting6,
        Method::ExactSplitting8,
    ] {
        rows.push(heavy_invariant_run(method, scale.periods)?);
        progress(method.name());
    }
    Ok(rows)
}

/// The number of runs [`long_runs`] makes, for a progress bar.
#[must_use]
pub fn long_run_count() -> u64 {
    METHODS.len() as u64 + 10
}

/// The report's heavy top (a Lagrange top) and its state at t = 0.
fn lagrange_top() -> Result<(RigidBody, State), Error> {
    let body = RigidBody::new([1.0, 1.0, 0.5])?.with_torque(Gravity {
        mass: 1.0,
        g: Vector::new(0.0, 0.0, -9.81),
        com_offset: Vector::new(0.0, 0.0, 0.5),
    });
    let state = State {
        rotor: (Bivector::E23 * -0.15).exp(),
        omega: omega_from_vector([0.0, 0.0, 20.0]),
    };
    Ok((body, state))
}

/// The nutation period of the fast Lagrange top, `2 pi i_p / (i_a w_a)`.
const LAGRANGE_PERIOD: f64 = 2.0 * PI * 1.0 / (0.5 * 20.0);

/// A free body and its state at t = 0 from moments and body momentum.
fn free_body(moments: [f64; 3], m: [f64; 3]) -> Result<(RigidBody, State), Error> {
    let body = RigidBody::new_unphysical(moments)?;
    let state = State {
        rotor: Rotor::ONE,
        omega: omega_from_vector([0, 1, 2].map(|k| m[k] / moments[k])),
    };
    Ok((body, state))
}

const HV_MOMENTS: [f64; 3] = [0.6, 0.8, 1.0];
const HV_MOMENTUM: [f64; 3] = [1.8, 0.4, -0.9];
const SHORT_FAT_MOMENTS: [f64; 3] = [3.0, 3.0, 9.0];
const SHORT_FAT_MOMENTUM: [f64; 3] = [0.0, 5.0, 7.0];

/// The integrator of `method` at step `h` (or [`UNIT_TOL`] for the adaptive ones).
fn integrator(method: Method, h: f64) -> Result<Box<dyn Integrator>, Error> {
    let step = match method.step_kind() {
        StepKind::Fixed => Step::Fixed(h),
        StepKind::Adaptive => Step::Tolerance(UNIT_TOL),
        StepKind::AtSamples => Step::AtSamples,
    };
    method.integrator(step)
}

/// `|R ~R - 1|`.
fn unit_defect(rotor: Rotor) -> f64 {
    let Rotor { s, e12, e13, e23 } = rotor;
    (s * s + e12 * e12 + e13 * e13 + e23 * e23 - 1.0).abs()
}

/// `steps` steps of `method` on the Lagrange top at `h = 1e-3` (the methods that cannot
/// take a torque, the closed form and the exact flow, on the free short fat top at 20
/// steps a period), measuring `|R ~R - 1|` after each.
fn unit_run(method: Method, steps: u64) -> Result<LongRun, Error> {
    let free_only = matches!(method, Method::ClosedForm | Method::Exact);
    let (body, state, h, scene, period) = if free_only {
        let (body, state) = free_body(SHORT_FAT_MOMENTS, SHORT_FAT_MOMENTUM)?;
        let period = free_body_orbit(SHORT_FAT_MOMENTS, SHORT_FAT_MOMENTUM).period;
        (body, state, period / 20.0, "short fat top (free)", period)
    } else {
        let (body, state) = lagrange_top()?;
        (body, state, UNIT_STEP, "heavy top", LAGRANGE_PERIOD)
    };
    let mut run = empty(method, UNIT, scene, steps, steps as f64 * h / period);
    let mut integrator = integrator(method, h)?;
    let started = Instant::now();
    let mut state = state;
    for i in 0..steps {
        match integrator.advance(&body, i as f64 * h, state, h) {
            Ok(next) => state = next,
            Err(e) => {
                run.failure = Some(e.to_string());
                break;
            }
        }
        run.unit_defect = run.unit_defect.max(unit_defect(state.rotor));
    }
    run.elapsed = started.elapsed();
    Ok(run)
}

fn empty(
    method: Method,
    check: &'static str,
    scene: &'static str,
    steps: u64,
    periods: f64,
) -> LongRun {
    LongRun {
        method,
        check,
        scene,
        steps,
        periods,
        unit_defect: 0.0,
        energy_first: 0.0,
        energy_last: 0.0,
        energy_max: 0.0,
        momentum_max: 0.0,
        failure: None,
        elapsed: Duration::ZERO,
    }
}

/// `method` on the Hairer-Vilmart body for `periods` periods of its momentum, at
/// [`FREE_STEPS_PER_PERIOD`] steps a period.
fn free_invariant_run(method: Method, periods: f64) -> Result<LongRun, Error> {
    let (body, state) = free_body(HV_MOMENTS, HV_MOMENTUM)?;
    let period = free_body_orbit(HV_MOMENTS, HV_MOMENTUM).period;
    let h = period / FREE_STEPS_PER_PERIOD;
    let steps = (periods * FREE_STEPS_PER_PERIOD).round() as u64;
    let l0 = body.space_momentum(&state);
    let scale = l0.norm();
    let mut run = empty(
        method,
        INVARIANTS,
        "Hairer-Vilmart body (free)",
        steps,
        periods,
    );
    let momentum = |s: &State| (body.space_momentum(s) - l0).norm() / scale;
    invariant_loop(&mut run, &body, state, h, method, momentum)?;
    Ok(run)
}

/// `method` on the Lagrange top for `periods` nutation periods at [`heavy_step`]; the
/// conserved momentum is the vertical component of `L`.
fn heavy_invariant_run(method: Method, periods: f64) -> Result<LongRun, Error> {
    let (body, state) = lagrange_top()?;
    let h = heavy_step(method);
    let steps = (periods * LAGRANGE_PERIOD / h).round() as u64;
    let l0 = body.space_momentum(&state);
    let (vertical, scale) = (l0.e12, l0.norm());
    let mut run = empty(method, INVARIANTS, "heavy top", steps, periods);
    let momentum = |s: &State| (body.space_momentum(s).e12 - vertical).abs() / scale;
    invariant_loop(&mut run, &body, state, h, method, momentum)?;
    Ok(run)
}

/// `run.steps` steps of `h`, measuring the unit defect, the energy error (by tenths) and
/// `momentum` after each.
fn invariant_loop(
    run: &mut LongRun,
    body: &RigidBody,
    mut state: State,
    h: f64,
    method: Method,
    momentum: impl Fn(&State) -> f64,
) -> Result<(), Error> {
    let mut integrator = integrator(method, h)?;
    let e0 = body.total_energy(0.0, &state);
    let tenth = (run.steps / 10).max(1);
    let started = Instant::now();
    for i in 0..run.steps {
        let t = i as f64 * h;
        match integrator.advance(body, t, state, h) {
            Ok(next) => state = next,
            Err(e) => {
                run.failure = Some(e.to_string());
                break;
            }
        }
        let energy = ((body.total_energy(t + h, &state) - e0) / e0).abs();
        run.energy_max = run.energy_max.max(energy);
        if i < tenth {
            run.energy_first = run.energy_first.max(energy);
        }
        if i >= run.steps - tenth {
            run.energy_last = run.energy_last.max(energy);
        }
        run.momentum_max = run.momentum_max.max(momentum(&state));
        run.unit_defect = run.unit_defect.max(unit_defect(state.rotor));
    }
    run.elapsed = started.elapsed();
    Ok(())
}

/// The CSV header of `long_runs.csv`.
pub const LONG_RUNS_CSV_HEADER: &str = "check,method,scene,steps,periods,unit_defect_max,\
energy_rel_first_tenth,energy_rel_last_tenth,energy_rel_max,momentum_rel_max,seconds,verdict";

/// The long runs as CSV: one row per run, the verdict `pass`, `fail` or the reason the run
/// stopped.
#[must_use]
pub fn long_runs_csv(rows: &[LongRun]) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{LONG_RUNS_CSV_HEADER}");
    for r in rows {
        let invariant = r.check == INVARIANTS;
        let cell = |x: f64| {
            if invariant {
                format!("{x:e}")
            } else {
                String::new()
            }
        };
        let _ = writeln!(
            out,
            "{},{},{},{},{:.1},{:e},{},{},{},{},{:.2},{}",
            r.check,
            r.method.name(),
            r.scene,
            r.steps,
            r.periods,
            r.unit_defect,
            cell(r.energy_first),
            cell(r.energy_last),
            cell(r.energy_max),
            cell(r.momentum_max),
            r.elapsed.as_secs_f64(),
            verdict(r)
        );
    }
    out
}

/// `pass`, `fail`, or `failed: why` when the run stopped.
#[must_use]
pub fn verdict(run: &LongRun) -> String {
    match &run.failure {
        Some(why) => format!("failed: {}", why.replace([',', '\n'], ";")),
        None if run.passes() => "pass".to_string(),
        None => "fail".to_string(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The report's table at a scale a debug test affords (a fiftieth of the issue's
    /// steps, a hundredth of its periods): every method keeps its rotor unit and every
    /// composition its invariants. The rounding walk of `|R ~R|` grows with the steps, so
    /// a method that does not scale its rotor back shows here already (the closed form
    /// chained from its own results reached 1.1e-13 in 2,000 steps before it did).
    #[test]
    fn every_method_meets_the_bounds_on_short_long_runs() {
        let scale = Scale {
            unit_steps: 20_000,
            periods: 1_000.0,
        };
        let mut heard = 0;
        let rows = long_runs(scale, &mut |_| heard += 1).unwrap();
        assert_eq!(heard, long_run_count());
        assert_eq!(rows.len() as u64, long_run_count());
        for row in &rows {
            println!(
                "{:<10} {:<18} |R~R-1| {:.1e}, energy {:.1e} then {:.1e}, momentum {:.1e}",
                row.check,
                row.method.name(),
                row.unit_defect,
                row.energy_first,
                row.energy_last,
                row.momentum_max
            );
            assert!(row.steps > 0);
        }
        let failing: Vec<&LongRun> = rows.iter().filter(|r| !r.passes()).collect();
        assert!(failing.is_empty(), "{failing:#?}");
        assert!(!scale.is_full());
        let csv = long_runs_csv(&rows);
        assert_eq!(csv.lines().count(), rows.len() + 1);
        let columns = LONG_RUNS_CSV_HEADER.split(',').count();
        assert!(
            csv.lines().all(|l| l.split(',').count() == columns),
            "{csv}"
        );
        assert!(csv.lines().skip(1).all(|l| l.ends_with(",pass")), "{csv}");
    }

    /// The bounded-energy test tells drift from oscillation: RK4, which is not symplectic,
    /// drifts on the free body, and the check says so.
    #[test]
    fn a_drifting_method_fails_the_energy_check() {
        let run = free_invariant_run(Method::Rk4, 100.0).unwrap();
        println!(
            "rk4: energy {:.1e} then {:.1e}",
            run.energy_first, run.energy_last
        );
        assert!(run.energy_last > 5.0 * run.energy_first, "{run:?}");
        assert!(!run.passes());
        assert_eq!(verdict(&run), "fail");
    }

    #[test]
    fn the_full_scale_is_the_issues() {
        assert!(Scale::of(Size::Full).is_full());
        assert_eq!(Scale::of(Size::Full).unit_steps, 1_000_000);
        assert!(!Scale::of(Size::Quick).is_full());
    }
}
