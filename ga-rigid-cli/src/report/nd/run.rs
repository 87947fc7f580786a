//! Every method of the n-dimensional body on every four-dimensional scene, at a sweep of
//! steps or tolerances: the rows of `nd_results.csv` and of the page's "Four dimensions".

use std::time::Duration;

use ga_rigid::error::Error;
use ga_rigid::registry::StepKind;

use super::measure::{
    errors, nominal_steps, perturbation_growth, published_check, references, run_once, NdErrors,
};
use super::methods::{param_kind, NdMethod};
use super::scenes::{nd_scenes, NdTestScene, Published};
use crate::report::analysis::{fit_order, Order};
use crate::report::{timed, Size, Timing};

/// The measurements of one method at one setting.
#[derive(Clone, Debug, PartialEq)]
pub struct NdMeasurement {
    /// The method.
    pub method: NdMethod,
    /// The step, tolerance or sample spacing.
    pub param: f64,
    /// Steps taken (fixed steps, accepted adaptive steps, or evaluations).
    pub steps: u64,
    /// The errors against the reference, if the run finished.
    pub errors: Option<NdErrors>,
    /// The timing, if the run finished.
    pub timing: Option<Timing>,
    /// Why the run stopped, if it did not finish.
    pub failure: Option<String>,
    /// Which reference this run is measured against.
    pub reference: NdMethod,
}

impl NdMeasurement {
    /// `dt`, `tol` or `samples`.
    #[must_use]
    pub fn param_kind(&self) -> &'static str {
        param_kind(self.method.step_kind())
    }

    /// The median run time in microseconds.
    #[must_use]
    pub fn time_us(&self) -> Option<f64> {
        self.timing.map(|t| t.median.as_secs_f64() * 1e6)
    }

    /// The mean step `t_end / steps`.
    #[must_use]
    pub fn mean_step(&self, t_end: f64) -> f64 {
        t_end / self.steps.max(1) as f64
    }
}

/// How a scene's reference was checked.
#[derive(Clone, Debug, PartialEq)]
pub struct NdCheck {
    /// The primary reference.
    pub primary: String,
    /// The independent solution it is checked against.
    pub secondary: String,
    /// Their disagreement over the samples.
    pub errors: NdErrors,
    /// The primary's distance from published values: the values, the largest component
    /// difference of `R` and of `Omega_B`.
    pub published: Option<(Published, f64, f64)>,
    /// A perturbation of a steady double rotation on the primary reference: its size at
    /// t = 0, its largest over the samples and when.
    pub growth: Option<(f64, f64, f64)>,
}

/// Everything measured on one four-dimensional scene.
pub struct NdSceneResult {
    /// The scene's name.
    pub name: String,
    /// Where it comes from.
    pub source: String,
    /// The end time.
    pub t_end: f64,
    /// The initial `|Omega_B|`.
    pub rate: f64,
    /// The references and their agreement.
    pub check: NdCheck,
    /// One row per method and setting.
    pub rows: Vec<NdMeasurement>,
    /// The wall-clock time the scene took.
    pub elapsed: Duration,
}

/// The number of runs [`run_nd`] makes, for a progress bar.
pub fn nd_job_count(size: Size) -> Result<u64, Error> {
    Ok(nd_scenes()?
        .iter()
        .map(|s| {
            s.methods()
                .iter()
                .map(|&m| s.settings(m, size).len() as u64)
                .sum::<u64>()
        })
        .sum())
}

/// Run every method on every four-dimensional scene; `progress` hears of each finished
/// run (the scene's name and the method's).
pub fn run_nd(
    size: Size,
    progress: &mut dyn FnMut(&str, &str),
) -> Result<Vec<NdSceneResult>, Error> {
    nd_scenes()?
        .iter()
        .map(|scene| run_scene(scene, size, progress))
        .collect()
}

fn run_scene(
    scene: &NdTestScene,
    size: Size,
    progress: &mut dyn FnMut(&str, &str),
) -> Result<NdSceneResult, Error> {
    let started = std::time::Instant::now();
    let (primary, secondary) = references(scene)?;
    let check = NdCheck {
        primary: primary.label.clone(),
        secondary: secondary.label.clone(),
        errors: errors(scene, &secondary.states, &primary.states),
        published: published_check(scene, &primary)
            .and_then(|(r, w)| Some((scene.published?, r, w))),
        growth: scene
            .steady_planes
            .map(|planes| perturbation_growth(scene, &primary, planes)),
    };
    let mut rows = Vec::new();
    for method in scene.methods() {
        let reference = if method == primary.method {
            &secondary
        } else {
            &primary
        };
        for setting in scene.settings(method, size) {
            let (outcome, timing) = timed(|| run_once(scene, method, setting));
            rows.push(match outcome {
                Ok(run) => NdMeasurement {
                    method,
                    param: setting,
                    steps: run.steps,
                    errors: Some(errors(scene, &run.states, &reference.states)),
                    timing,
                    failure: None,
                    reference: reference.method,
                },
                Err(e) => NdMeasurement {
                    method,
                    param: setting,
                    steps: nominal_steps(scene, method, setting),
                    errors: None,
                    timing: None,
                    failure: Some(e.to_string()),
                    reference: reference.method,
                },
            });
            progress(&scene.name, method.name());
        }
    }
    Ok(NdSceneResult {
        name: scene.name.clone(),
        source: scene.source.clone(),
        t_end: scene.t_end,
        rate: scene.rate(),
        check,
        rows,
        elapsed: started.elapsed(),
    })
}

/// Errors below this are rounding, not truncation.
const ROUNDING_FLOOR: f64 = 1e-12;

/// An error above which a run has lost the solution.
const LOST: f64 = 0.1;

/// The error below which a scene's runs are not resolved: ten times its references'
/// disagreement, and never below 1e-12 (the 3D report's rule).
#[must_use]
pub fn nd_error_floor(scene: &NdSceneResult) -> f64 {
    (10.0 * scene.check.errors.attitude_max).max(ROUNDING_FLOOR)
}

/// The slope of log(largest attitude error) against log(mean step) over a method's runs
/// between the scene's floor and 0.1, as the 3D report fits it.
#[must_use]
pub fn nd_order(scene: &NdSceneResult, method: NdMethod) -> Order {
    let floor = nd_error_floor(scene);
    let points: Vec<(f64, f64)> = scene
        .rows
        .iter()
        .filter(|r| r.method == method)
        .filter_map(|r| {
            let e = r.errors?.attitude_max;
            (e > floor && e < LOST && e.is_finite())
                .then(|| (r.mean_step(scene.t_end).ln(), e.ln()))
        })
        .collect();
    if method.step_kind() == StepKind::AtSamples {
        return Order::TooFewPoints(0);
    }
    fit_order(&points)
}
