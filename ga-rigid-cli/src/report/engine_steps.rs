//! Long runs at the step sizes engines use: the T-handle (the Dzhanibekov body) and a
//! near-symmetric body (where Spiers's step is nearly exact) stepped 10^5 times at `h |w|`
//! from 0.05 to 0.5 by the engines' steps and ours, with the largest energy and
//! angular-momentum errors and the period of the flip against the exact flow's.
//! Engines step at a fixed frame rate whatever the body does, so the question is not the
//! error at a small step but what survives a large one: does the T-handle keep flipping,
//! on time, without gaining or losing energy?

use std::fmt::Write as _;
use std::time::{Duration, Instant};

use ga_core::f64::g3::Rotor;

use ga_rigid::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use ga_rigid::error::Error;
use ga_rigid::exact_flow::free_body_orbit;
use ga_rigid::registry::{Method, Step};

use super::Size;

/// The step sizes, as `h |w(0)|`.
pub const ENGINE_RATES: [f64; 4] = [0.05, 0.1, 0.2, 0.5];
/// Steps of each run in a full report (a quick one takes a twentieth).
pub const ENGINE_STEPS: u64 = 100_000;
/// The methods compared: the engines' steps (peers) and ours.
pub const ENGINE_METHODS: [Method; 15] = [
    Method::EulerGyroExplicit,
    Method::EulerGyroImplicit,
    Method::Buss2,
    Method::MidpointQuaternion,
    Method::MoserVeselov,
    Method::SpiersVelocity,
    Method::SpiersMomentum,
    Method::Splitting,
    Method::SplittingCayley,
    Method::SplittingCasimir,
    Method::SplittingCorrected,
    Method::Splitting4,
    Method::Midpoint,
    Method::LieRk4,
    Method::Rk4,
];
/// A free body and its start for the engine runs: principal moments and body momentum,
/// with `R(0) = 1`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct EngineBody {
    /// Its name in tables.
    pub name: &'static str,
    /// Principal moments.
    pub moments: [f64; 3],
    /// Body angular momentum at the start.
    pub momentum: [f64; 3],
}

/// The T-handle: the Dzhanibekov body of the suite, moments (3, 5, 9), body momentum
/// (0, 2, 0.01), flipping about its intermediate axis e2. The report's engine table.
pub const T_HANDLE: EngineBody = EngineBody {
    name: "T-handle",
    moments: [3.0, 5.0, 9.0],
    momentum: [0.0, 2.0, 0.01],
};

/// A near-symmetric body: the two smaller moments 2% apart, its momentum 37 degrees off
/// the largest axis, so that the body momentum circles e3 (nearly the symmetric top's
/// precession, which Spiers's step makes exact) and crosses `m2 = 0` twice a period.
pub const NEAR_SYMMETRIC: EngineBody = EngineBody {
    name: "near-symmetric",
    moments: [5.0, 5.1, 9.0],
    momentum: [1.2, 0.3, 1.6],
};

/// The bodies of the report's engine runs, in the order of its tables.
pub const ENGINE_BODIES: [EngineBody; 2] = [T_HANDLE, NEAR_SYMMETRIC];

impl EngineBody {
    /// The exact flow's time between sign changes of `m2`: half the period of the body
    /// momentum.
    #[must_use]
    pub fn exact_flip_period(&self) -> f64 {
        0.5 * free_body_orbit(self.moments, self.momentum).period
    }
}

/// One run of one method at one step size.
#[derive(Clone, Debug, PartialEq)]
pub struct EngineRun {
    /// The body.
    pub body: EngineBody,
    /// The method.
    pub method: Method,
    /// `h |w(0)|`.
    pub rate: f64,
    /// Steps taken.
    pub steps: u64,
    /// The largest relative energy error over the run.
    pub energy_max: f64,
    /// The largest relative error of the space angular momentum `L` over the run.
    pub momentum_max: f64,
    /// The mean time between flips (sign changes of the body momentum on e2), when the
    /// run saw at least two.
    pub flip_period: Option<f64>,
    /// How many flips the run saw.
    pub flips: u64,
    /// Why the run stopped, if it did.
    pub failure: Option<String>,
    /// The run's wall-clock time.
    pub elapsed: Duration,
}

/// The T-handle's exact time between flips: half the period of the body momentum.
#[must_use]
pub fn exact_flip_period() -> f64 {
    T_HANDLE.exact_flip_period()
}

impl EngineRun {
    /// The flip period's error relative to the exact one, when there is a flip period.
    #[must_use]
    pub fn flip_error(&self) -> Option<f64> {
        let exact = self.body.exact_flip_period();
        self.flip_period.map(|p| (p - exact) / exact)
    }
}

/// What an engine needs of a step at its step size: `|L|` kept to `1e-9`, the energy to
/// `1e-2`, the flip period within 1% of the exact flow's.
pub const ENGINE_BOUNDS: (f64, f64, f64) = (1e-9, 1e-2, 1e-2);

impl EngineRun {
    /// Whether the run ended and met [`ENGINE_BOUNDS`].
    #[must_use]
    pub fn meets_engine_bounds(&self) -> bool {
        let (momentum, energy, flip) = ENGINE_BOUNDS;
        self.failure.is_none()
            && self.momentum_max <= momentum
            && self.energy_max <= energy
            && self.flip_error().is_some_and(|e| e.abs() <= flip)
    }
}

/// Per engine step size, one line for the page: the fastest of our runs and of the peers'
/// that meet [`ENGINE_BOUNDS`] (by the run's own time), ours that meet them with the
/// smallest energy error, and the peers that do not meet them.
///
/// Both of ours are named because they answer different questions: the fastest within the
/// bounds is what the table shows here, the most accurate within them is why `ga_engine`
/// steps with `splitting-corrected` (its energy error is several times smaller than the
/// plain Casimir split's at a similar cost in the engine's own code).
#[must_use]
pub fn engine_verdicts(rows: &[EngineRun]) -> Vec<String> {
    let within = |rate: f64, peer: bool| {
        rows.iter()
            .filter(move |r| r.rate == rate && r.method.info().peer.is_some() == peer)
            .filter(|r| r.meets_engine_bounds())
    };
    let describe = |r: &EngineRun| {
        format!(
            "{} ({:.1} ms, energy {:.1e}, flip {:+.2}%)",
            r.method.name(),
            r.elapsed.as_secs_f64() * 1e3,
            r.energy_max,
            100.0 * r.flip_error().unwrap_or(f64::NAN)
        )
    };
    ENGINE_RATES
        .iter()
        .map(|&rate| {
            let fastest = |peer| within(rate, peer).min_by(|a, b| a.elapsed.cmp(&b.elapsed));
            let ours = fastest(false).map_or("none of ours".to_string(), describe);
            let accurate = within(rate, false)
                .min_by(|a, b| a.energy_max.total_cmp(&b.energy_max))
                .map_or("none".to_string(), describe);
            let peer = fastest(true).map_or("no peer".to_string(), describe);
            let missing: Vec<&str> = rows
                .iter()
                .filter(|r| r.rate == rate && r.method.info().peer.is_some())
                .filter(|r| !r.meets_engine_bounds())
                .map(|r| r.method.name())
                .collect();
            format!(
                "h |w| = {rate}: fastest of ours {ours}; smallest energy error of ours \
                 {accurate}; fastest peer {peer}; peers outside the bounds: {}",
                if missing.is_empty() {
                    "none".to_string()
                } else {
                    missing.join(", ")
                }
            )
        })
        .collect()
}

/// Every method of [`ENGINE_METHODS`] at every rate of [`ENGINE_RATES`] on every body of
/// [`ENGINE_BODIES`], body by body.
pub fn engine_runs(size: Size, progress: &mut dyn FnMut(&str)) -> Result<Vec<EngineRun>, Error> {
    let steps = match size {
        Size::Full => ENGINE_STEPS,
        Size::Quick => ENGINE_STEPS / 20,
    };
    let mut rows = Vec::new();
    for body in ENGINE_BODIES {
        for method in ENGINE_METHODS {
            for rate in ENGINE_RATES {
                rows.push(engine_run_on(body, method, rate, steps)?);
            }
            progress(method.name());
        }
    }
    Ok(rows)
}

/// `steps` steps of `method` at `h |w(0)| = rate` on the T-handle.
pub fn engine_run(method: Method, rate: f64, steps: u64) -> Result<EngineRun, Error> {
    engine_run_on(T_HANDLE, method, rate, steps)
}

/// `steps` steps of `method` at `h |w(0)| = rate` on `on`.
pub fn engine_run_on(
    on: EngineBody,
    method: Method,
    rate: f64,
    steps: u64,
) -> Result<EngineRun, Error> {
    let body = RigidBody::new_unphysical(on.moments)?;
    let w = [0, 1, 2].map(|k| on.momentum[k] / on.moments[k]);
    let mut state = State {
        rotor: Rotor::ONE,
        omega: omega_from_vector(w),
    };
    let h = rate / state.omega.norm();
    let mut integrator = method.integrator(Step::Fixed(h))?;
    let e0 = body.energy(state.omega);
    let l0 = body.space_momentum(&state);
    let mut run = EngineRun {
        body: on,
        method,
        rate,
        steps,
        energy_max: 0.0,
        momentum_max: 0.0,
        flip_period: None,
        flips: 0,
        failure: None,
        elapsed: Duration::ZERO,
    };
    let m2 = |s: &State| omega_to_vector(body.body_momentum(s.omega))[1];
    let (mut first, mut last) = (None, 0.0);
    let started = Instant::now();
    for i in 0..steps {
        let t = i as f64 * h;
        let before = m2(&state);
        match integrator.advance(&body, t, state, h) {
            Ok(next) => state = next,
            Err(e) => {
                run.failure = Some(e.to_string());
                break;
            }
        }
        let after = m2(&state);
        if (before < 0.0) != (after < 0.0) {
            // The crossing, by linear interpolation within the step.
            let crossing = t + h * before / (before - after);
            first.get_or_insert(crossing);
            last = crossing;
            run.flips += 1;
        }
        let energy = ((body.energy(state.omega) - e0) / e0).abs();
        let momentum = (body.space_momentum(&state) - l0).norm() / l0.norm();
        // NaN stays NaN: it is the news.
        run.energy_max = if energy.is_nan() {
            energy
        } else {
            run.energy_max.max(energy)
        };
        run.momentum_max = if momentum.is_nan() {
            momentum
        } else {
            run.momentum_max.max(momentum)
        };
    }
    run.elapsed = started.elapsed();
    if let (Some(first), true) = (first, run.flips >= 2) {
        run.flip_period = Some((last - first) / (run.flips - 1) as f64);
    }
    Ok(run)
}

/// The CSV header of `engine_runs.csv` (`body`, the body's name, came last so that the
/// columns before it kept their places).
pub const ENGINE_RUNS_CSV_HEADER: &str = "method,peer,h_w,steps,energy_rel_max,momentum_rel_max,\
flips,flip_period,flip_period_exact,flip_period_rel_error,seconds,status,body";

/// The engine runs as CSV, one row per body, method and step size.
#[must_use]
pub fn engine_runs_csv(rows: &[EngineRun]) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{ENGINE_RUNS_CSV_HEADER}");
    for r in rows {
        let exact = r.body.exact_flip_period();
        let period = r.flip_period.map_or(String::new(), |p| format!("{p:e}"));
        let error = r.flip_error().map_or(String::new(), |e| format!("{e:e}"));
        let status = match &r.failure {
            Some(why) => format!("failed: {}", why.replace([',', '\n'], ";")),
            None => "ok".to_string(),
        };
        let _ = writeln!(
            out,
            "{},{},{},{},{:e},{:e},{},{period},{exact:e},{error},{:.3},{status},{}",
            r.method.name(),
            r.method.info().peer.is_some(),
            r.rate,
            r.steps,
            r.energy_max,
            r.momentum_max,
            r.flips,
            r.elapsed.as_secs_f64(),
            r.body.name,
        );
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The explicit gyroscopic Euler step gains energy at engine steps and the flip drifts;
    /// the DLM splitting keeps |L| to rounding and flips on time.
    #[test]
    fn the_splitting_keeps_the_flip_and_the_explicit_step_does_not() {
        let steps = 4_000;
        let ours = engine_run(Method::Splitting, 0.1, steps).unwrap();
        let explicit = engine_run(Method::EulerGyroExplicit, 0.1, steps).unwrap();
        println!("{ours:?}\n{explicit:?}");
        assert!(ours.momentum_max < 1e-12, "{ours:?}");
        assert!(ours.flips >= 4, "{ours:?}");
        assert!(ours.flip_error().unwrap().abs() < 0.01, "{ours:?}");
        assert!(
            explicit.energy_max > 100.0 * ours.energy_max,
            "{explicit:?}"
        );
        let csv = engine_runs_csv(&[ours, explicit]);
        let columns = ENGINE_RUNS_CSV_HEADER.split(',').count();
        assert!(
            csv.lines().all(|l| l.split(',').count() == columns),
            "{csv}"
        );
    }

    /// The near-symmetric body's runs: the engine's step keeps `|L|` and its flips come
    /// at the exact flow's period (elliptic functions); the CSV names the body last.
    #[test]
    fn the_near_symmetric_body_flips_on_time_under_the_engines_step() {
        let run = engine_run_on(NEAR_SYMMETRIC, Method::SplittingCorrected, 0.2, 4_000).unwrap();
        assert!(run.momentum_max < 1e-12, "{run:?}");
        assert!(run.flips >= 4, "{run:?}");
        assert!(run.flip_error().unwrap().abs() < 0.01, "{run:?}");
        let csv = engine_runs_csv(&[run]);
        let row = csv.lines().nth(1).unwrap();
        assert_eq!(row.rsplit(',').next(), Some("near-symmetric"), "{csv}");
        assert!(ENGINE_RUNS_CSV_HEADER.ends_with(",body"));
    }

    /// Issue 18's engine target: at `h |w| = 0.5` the Casimir split keeps the flip within
    /// 1% (the DLM splitting does not: +2.3% over 10^5 steps), and the verdict names it.
    #[test]
    fn the_casimir_split_meets_the_engine_bounds_where_dlm_does_not() {
        let steps = 20_000;
        let casimir = engine_run(Method::SplittingCasimir, 0.5, steps).unwrap();
        let dlm = engine_run(Method::Splitting, 0.5, steps).unwrap();
        let implicit = engine_run(Method::EulerGyroImplicit, 0.5, steps).unwrap();
        println!("{casimir:?}\n{dlm:?}\n{implicit:?}");
        assert!(casimir.meets_engine_bounds(), "{casimir:?}");
        assert!(!dlm.meets_engine_bounds(), "{dlm:?}");
        assert!(!implicit.meets_engine_bounds(), "{implicit:?}");
        let verdicts = engine_verdicts(&[casimir, dlm, implicit]);
        let at_half = verdicts
            .iter()
            .find(|v| v.starts_with("h |w| = 0.5"))
            .unwrap();
        assert!(at_half.contains("ours splitting-casimir"), "{at_half}");
        // The only one of ours within the bounds is also the most accurate of ours.
        assert!(
            at_half.contains("smallest energy error of ours splitting-casimir"),
            "{at_half}"
        );
        assert!(at_half.contains("fastest peer no peer"), "{at_half}");
        assert!(at_half.ends_with("euler-gyro-implicit"), "{at_half}");
    }

    /// Within the bounds, the fastest and the most accurate are picked separately: with the
    /// corrected split given the larger time, the fastest is the Casimir split and the most
    /// accurate the corrected one (its energy error is the smaller, checked here first).
    #[test]
    fn the_verdict_names_the_fastest_and_the_most_accurate_within_the_bounds() {
        let steps = 20_000;
        let mut casimir = engine_run(Method::SplittingCasimir, 0.5, steps).unwrap();
        let mut corrected = engine_run(Method::SplittingCorrected, 0.5, steps).unwrap();
        assert!(casimir.meets_engine_bounds() && corrected.meets_engine_bounds());
        assert!(
            corrected.energy_max < casimir.energy_max,
            "{corrected:?} {casimir:?}"
        );
        casimir.elapsed = Duration::from_millis(1);
        corrected.elapsed = Duration::from_millis(2);
        let verdicts = engine_verdicts(&[casimir, corrected]);
        let at_half = verdicts
            .iter()
            .find(|v| v.starts_with("h |w| = 0.5"))
            .unwrap();
        assert!(
            at_half.contains("fastest of ours splitting-casimir (1.0 ms"),
            "{at_half}"
        );
        assert!(
            at_half.contains("smallest energy error of ours splitting-corrected (2.0 ms"),
            "{at_half}"
        );
    }

    #[test]
    fn the_exact_flip_period_is_the_published_one() {
        // docs/references.md: the Principia Dzhanibekov body flips every 59.06 s.
        assert!(
            (exact_flip_period() - 59.055).abs() < 0.01,
            "{}",
            exact_flip_period()
        );
    }
}
