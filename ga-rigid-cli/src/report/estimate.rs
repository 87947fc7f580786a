//! What the suite will cost on a scene, estimated before it runs: the steps of every run
//! (the references, each method at each of its settings, the timing repeats) times each
//! method's cost per step from the registry. A rough upper estimate, for refusing a
//! scene that would run for hours before it starts.

use ga_rigid::registry::{Method, StepKind};

use super::measure::{MIN_REPEATS, MIN_TOTAL_TIME, TIGHTEST_TOL};
use super::scenes::{TestScene, SAMPLES};
use super::Size;

/// Steps of an adaptive method at tolerance `tol` over `radians` turned: about
/// `tol^(-1/5)` a radian (the estimate `simulate` uses), and one per sample.
fn adaptive_steps(radians: f64, tol: f64) -> f64 {
    radians * tol.powf(-0.2) + SAMPLES as f64
}

/// About how many seconds [`super::run`] spends on `scene` in a release build.
#[must_use]
pub fn scene_seconds(scene: &TestScene, size: Size) -> f64 {
    let radians = scene.t_end * scene.rate();
    // The references: Dormand-Prince at the tightest tolerance, and Lie-RK4 at
    // h |w| = 1e-3 under a torque.
    let mut total = Method::Dopri.seconds_for(adaptive_steps(radians, TIGHTEST_TOL));
    if scene.body.has_torque() {
        total += Method::LieRk4.seconds_for(radians / 1e-3);
    }
    let (methods, _) = scene.methods();
    for method in methods {
        for setting in scene.settings(method, size) {
            let steps = match method.step_kind() {
                StepKind::Fixed => scene.t_end / setting,
                StepKind::Adaptive => adaptive_steps(radians, setting),
                StepKind::AtSamples => SAMPLES as f64,
            };
            let once = method.seconds_for(steps);
            // A warm-up run, then timed runs until there are MIN_REPEATS of them and
            // they add up to MIN_TOTAL_TIME.
            total += once + (MIN_REPEATS as f64 * once).max(MIN_TOTAL_TIME.as_secs_f64());
        }
    }
    total
}
