//! Made-up measurements for the report's unit tests: a finished run with a given time and
//! error, and a scene holding such runs.

use std::time::Duration;

use ga_rigid::registry::{Method, StepKind};

use super::analysis::SceneKind;
use super::{Errors, Measurement, ReferenceCheck, SceneResult, Sweep, Timing};

/// A finished run of `method` at step (or tolerance) `param`, taking `steps` steps in
/// `time_us`, with largest attitude error `attitude`.
pub(super) fn run(
    method: Method,
    param: f64,
    steps: u64,
    time_us: f64,
    attitude: f64,
) -> Measurement {
    let time = Duration::from_secs_f64(time_us * 1e-6);
    Measurement {
        method,
        param_kind: if method.step_kind() == StepKind::Adaptive {
            "tol"
        } else {
            "dt"
        },
        param,
        steps,
        errors: Some(Errors {
            attitude_end: attitude,
            attitude_max: attitude,
            ..Errors::default()
        }),
        timing: Some(Timing {
            median: time,
            min: time,
            repeats: 3,
        }),
        failure: None,
        reference: Method::Exact,
    }
}

/// A scene of `kind` named "made up", `t_end = 10` at rate 1, holding `rows`.
pub(super) fn scene(kind: SceneKind, rows: Vec<Measurement>) -> SceneResult {
    SceneResult {
        name: "made up".into(),
        source: "a test".into(),
        t_end: 10.0,
        rate: 1.0,
        sweep: Sweep::WorkPrecision,
        kind,
        check: ReferenceCheck {
            primary: "exact".into(),
            secondary: "dopri".into(),
            errors: Errors::default(),
        },
        rows,
        left_out: Vec::new(),
        elapsed: Duration::ZERO,
    }
}
