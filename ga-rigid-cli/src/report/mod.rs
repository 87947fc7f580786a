//! The main job: every method on every scene of the suite, error against run time, and
//! what a person needs to choose a method: `results.csv`, one work-precision SVG per
//! scene and a page. Scenes are the test models of `docs/references.md` plus the stiff
//! and extreme cases; a scene runs only the methods that apply to it, and the report says
//! what it left out and why. This module computes and renders to strings; the command
//! writes the files.

mod analysis;
mod engine_steps;
mod escape;
mod estimate;
#[cfg(test)]
mod fixtures;
mod invariants;
mod measure;
pub mod nd;
mod page;
mod plot;
mod race;
mod results;
mod scenes;
pub mod style;

pub use analysis::{
    cost_per_step_ns, error_floor, fastest_at, fastest_over, fit_order, observed_order, order,
    scene_kind, verdict, Order, Pick, SceneKind, ERROR_LEVELS, MIN_ORDER_POINTS,
};
pub use engine_steps::{
    engine_run, engine_run_on, engine_runs, engine_runs_csv, engine_verdicts, exact_flip_period,
    EngineBody, EngineRun, ENGINE_BODIES, ENGINE_BOUNDS, ENGINE_METHODS, ENGINE_RATES,
    ENGINE_RUNS_CSV_HEADER, ENGINE_STEPS, NEAR_SYMMETRIC, T_HANDLE,
};
pub use estimate::scene_seconds;
pub use invariants::{
    long_run_count, long_runs, long_runs_csv, verdict as long_run_verdict, LongRun, Scale,
    ENERGY_GROWTH, LONG_RUNS_CSV_HEADER, MOMENTUM_BOUND, PERIODS, UNIT_DEFECT_BOUND, UNIT_STEPS,
};
pub use measure::{
    attitude_error, errors, references, sample_times, timed, timed_run, Errors, Reference, Timing,
    MIN_REPEATS, MIN_TOTAL_TIME, TIGHTEST_TOL,
};
pub use page::{html, svg_name};
pub use plot::{fastest_of_ours_to_the_peers_best, simulation_svg, svg};
pub use results::{csv, CSV_HEADER};
pub use scenes::{reference_scenes, stability_scenes, suite, Sweep, TestScene, SAMPLES};
pub use style::method_colour;

use std::fmt::Write as _;

use ga_rigid::error::Error;
use ga_rigid::registry::{Method, StepKind};

/// How much to run.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Size {
    /// Fewer steps and tolerances per method: well under a minute (what CI runs).
    Quick,
    /// The full sweep.
    Full,
}

/// The measurements of one method at one step or tolerance.
#[derive(Clone, Debug, PartialEq)]
pub struct Measurement {
    /// The method.
    pub method: Method,
    /// `dt`, `tol` or `samples` (the sample spacing of a method without steps).
    pub param_kind: &'static str,
    /// The step, tolerance or sample spacing.
    pub param: f64,
    /// Steps taken (fixed steps, accepted adaptive steps, or evaluations).
    pub steps: u64,
    /// The errors against the reference, if the run finished.
    pub errors: Option<Errors>,
    /// The timing, if the run finished.
    pub timing: Option<Timing>,
    /// Why the run stopped, if it did not finish.
    pub failure: Option<String>,
    /// Which reference this run is measured against.
    pub reference: Method,
}

impl Measurement {
    /// The mean step `t_end / steps`, for the observed order and `h |w|`.
    #[must_use]
    pub fn mean_step(&self, t_end: f64) -> f64 {
        t_end / self.steps.max(1) as f64
    }

    /// The median run time in microseconds.
    #[must_use]
    pub fn time_us(&self) -> Option<f64> {
        self.timing.map(|t| t.median.as_secs_f64() * 1e6)
    }

    /// A short label of the setting: `h=1.0e-2`, `tol=1e-8`, or `exact`.
    #[must_use]
    pub fn label(&self) -> String {
        match self.param_kind {
            "dt" => format!("h={:.1e}", self.param),
            "tol" => format!("tol={:.0e}", self.param),
            _ => "at samples".to_string(),
        }
    }
}

/// The agreement of a scene's two references over the samples.
#[derive(Clone, Debug, PartialEq)]
pub struct ReferenceCheck {
    /// The primary reference.
    pub primary: String,
    /// The independent solution it is checked against.
    pub secondary: String,
    /// Their errors against each other.
    pub errors: Errors,
}

/// Everything measured on one scene.
pub struct SceneResult {
    /// The scene's name.
    pub name: String,
    /// Where it comes from.
    pub source: String,
    /// The end time.
    pub t_end: f64,
    /// The initial `|w|`.
    pub rate: f64,
    /// How it was swept.
    pub sweep: Sweep,
    /// The kind of body and case, for the page's summary.
    pub kind: SceneKind,
    /// The references and their agreement.
    pub check: ReferenceCheck,
    /// One row per method and setting.
    pub rows: Vec<Measurement>,
    /// Methods (and settings) left out, with the reason.
    pub left_out: Vec<(String, String)>,
    /// The wall-clock time the scene took, references and repetitions included.
    pub elapsed: std::time::Duration,
}

/// The whole report.
pub struct Report {
    /// How much was run.
    pub size: Size,
    /// The CPU the times were taken on.
    pub cpu: String,
    /// One result per scene.
    pub scenes: Vec<SceneResult>,
    /// The long runs of [`long_runs`], when they were run (the command runs them after the
    /// scenes; [`run`] leaves this empty).
    pub long_runs: Vec<LongRun>,
    /// The runs at engine step sizes of [`engine_runs`], when they were run (the command
    /// runs them after the long runs; [`run`] leaves this empty).
    pub engine_runs: Vec<EngineRun>,
    /// The four-dimensional scenes of [`nd::run_nd`], when they were run (the command runs
    /// them after the engine runs; [`run`] leaves this empty).
    pub nd_scenes: Vec<nd::NdSceneResult>,
}

/// The CPU model from `/proc/cpuinfo`, or a plain statement that it is unknown.
#[must_use]
pub fn cpu_model() -> String {
    let model = std::fs::read_to_string("/proc/cpuinfo")
        .ok()
        .and_then(|text| {
            text.lines()
                .find(|l| l.starts_with("model name"))
                .and_then(|l| l.split_once(':'))
                .map(|(_, v)| v.trim().to_string())
        });
    let cores = std::thread::available_parallelism().map_or(0, usize::from);
    match model {
        Some(m) => format!("{m} ({cores} cores visible)"),
        None => format!(
            "unknown CPU ({} {}, {cores} cores visible)",
            std::env::consts::OS,
            std::env::consts::ARCH
        ),
    }
}

/// The number of runs `run` will make, for a progress bar.
#[must_use]
pub fn job_count(scenes: &[TestScene], size: Size) -> u64 {
    scenes
        .iter()
        .map(|s| {
            let (methods, _) = s.methods();
            methods
                .iter()
                .map(|&m| s.settings(m, size).len() as u64)
                .sum::<u64>()
        })
        .sum()
}

/// The per-scene budget of one run of a [`Sweep::Long`] scene.
fn long_run_budget(size: Size) -> std::time::Duration {
    match size {
        Size::Quick => std::time::Duration::from_millis(300),
        Size::Full => std::time::Duration::from_secs(3),
    }
}

/// Run every applicable method on every scene; `progress` hears of each finished run
/// (the scene's name and the method's).
pub fn run(
    scenes: &[TestScene],
    size: Size,
    progress: &mut dyn FnMut(&str, &str),
) -> Result<Report, Error> {
    run_methods(scenes, size, &Method::ALL, progress)
}

/// [`run`] with only the methods in `only` (those that apply to each scene); the others
/// are neither run nor listed as left out.
pub fn run_methods(
    scenes: &[TestScene],
    size: Size,
    only: &[Method],
    progress: &mut dyn FnMut(&str, &str),
) -> Result<Report, Error> {
    let mut results = Vec::with_capacity(scenes.len());
    for scene in scenes {
        results.push(run_scene(scene, size, only, progress)?);
    }
    Ok(Report {
        size,
        cpu: cpu_model(),
        scenes: results,
        long_runs: Vec::new(),
        engine_runs: Vec::new(),
        nd_scenes: Vec::new(),
    })
}

fn run_scene(
    scene: &TestScene,
    size: Size,
    only: &[Method],
    progress: &mut dyn FnMut(&str, &str),
) -> Result<SceneResult, Error> {
    let started = std::time::Instant::now();
    let (primary, secondary) = references(scene)?;
    let check = ReferenceCheck {
        primary: primary.label.clone(),
        secondary: secondary.label.clone(),
        errors: errors(scene, &primary.states, &secondary.states),
    };
    let (mut methods, left) = scene.methods();
    methods.retain(|m| only.contains(m));
    let mut left_out: Vec<(String, String)> = left
        .into_iter()
        .filter(|(m, _)| only.contains(m))
        .map(|(m, why)| (m.name().to_string(), why))
        .collect();
    let mut rows = Vec::new();
    for method in methods {
        let reference = if method == primary.method {
            &secondary
        } else {
            &primary
        };
        for setting in scene.settings(method, size) {
            let (param_kind, steps) = match method.step_kind() {
                StepKind::Fixed => ("dt", (scene.t_end / setting).round() as u64),
                StepKind::Adaptive => ("tol", 0),
                StepKind::AtSamples => ("samples", SAMPLES),
            };
            if scene.sweep == Sweep::Long {
                let estimate = measure::estimated_run_time(scene, method, setting);
                let budget = long_run_budget(size);
                if estimate > budget {
                    left_out.push((
                        method.name().to_string(),
                        format!(
                            "a run would take about {:.2} s (from a run over the first \
                             thousandth of the time), over this scene's budget of {:.1} s a run",
                            estimate.as_secs_f64(),
                            budget.as_secs_f64()
                        ),
                    ));
                    progress(&scene.name, method.name());
                    continue;
                }
            }
            let (outcome, timing) = timed_run(scene, method, setting);
            let row = match outcome {
                Ok(run) => Measurement {
                    method,
                    param_kind,
                    param: setting,
                    steps: run.steps,
                    errors: Some(errors(scene, &run.states, &reference.states)),
                    timing,
                    failure: None,
                    reference: reference.method,
                },
                Err(e) => Measurement {
                    method,
                    param_kind,
                    param: setting,
                    steps,
                    errors: None,
                    timing: None,
                    failure: Some(e.to_string()),
                    reference: reference.method,
                },
            };
            rows.push(row);
            progress(&scene.name, method.name());
        }
    }
    Ok(SceneResult {
        name: scene.name.clone(),
        source: scene.source.clone(),
        t_end: scene.t_end,
        rate: scene.rate(),
        sweep: scene.sweep,
        kind: scene_kind(scene),
        check,
        rows,
        left_out,
        elapsed: started.elapsed(),
    })
}

/// The short summary for standard output: per scene, the reference check and the fastest
/// method to an attitude error of 1e-6.
#[must_use]
pub fn summary(report: &Report) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "ga-rigid report ({}), {} scenes, on {}",
        match report.size {
            Size::Quick => "quick",
            Size::Full => "full",
        },
        report.scenes.len(),
        report.cpu
    );
    for scene in &report.scenes {
        let fastest = match fastest_at(scene, 1e-6) {
            Some(row) => format!(
                "fastest to 1e-6 rad: {} ({}) {:.1} us",
                row.method.name(),
                row.label(),
                row.time_us().unwrap_or(f64::NAN)
            ),
            None => "no method reached 1e-6 rad".to_string(),
        };
        let _ = writeln!(
            out,
            "- {}: reference check {:.1e} rad; {fastest} ({:.1} s)",
            scene.name,
            scene.check.errors.attitude_max,
            scene.elapsed.as_secs_f64()
        );
    }
    for scene in &report.nd_scenes {
        let fastest = scene
            .rows
            .iter()
            .filter(|r| r.errors.is_some_and(|e| e.attitude_max <= 1e-6))
            .filter_map(|r| Some((r, r.time_us()?)))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let fastest = match fastest {
            Some((row, us)) => format!(
                "fastest to 1e-6 rad: {} ({} {:.1e}) {us:.1} us",
                row.method.name(),
                row.param_kind(),
                row.param
            ),
            None => "no method reached 1e-6 rad".to_string(),
        };
        let _ = writeln!(
            out,
            "- {}: reference check {:.1e} rad; {fastest} ({:.1} s)",
            scene.name,
            scene.check.errors.attitude_max,
            scene.elapsed.as_secs_f64()
        );
    }
    if !report.long_runs.is_empty() {
        let passed = report.long_runs.iter().filter(|r| r.passes()).count();
        let seconds: f64 = report
            .long_runs
            .iter()
            .map(|r| r.elapsed.as_secs_f64())
            .sum();
        let _ = writeln!(
            out,
            "- long runs: {passed} of {} meet the bounds ({seconds:.1} s)",
            report.long_runs.len()
        );
    }
    out
}
