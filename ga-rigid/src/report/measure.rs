use std::time::{Duration, Instant};

use ga_core::f64::g3::Rotor;

use crate::dynamics::State;
use crate::error::Error;
use crate::integrators::{DormandPrince, ExactFreeBody, Integrator};
use crate::integrators::{Method, Step};

use super::scenes::TestScene;

/// The sign-free angle between two attitudes: `2 atan2(|<D>_2|, |<D>_0|)`, `D = ~R_ref R`.
#[must_use]
pub fn attitude_error(rotor: Rotor, reference: Rotor) -> f64 {
    let d = reference.reverse() * rotor;
    2.0 * d.grade2().norm().atan2(d.s.abs())
}

/// One run of one method on one scene.
pub struct Outcome {
    /// The end state, or the error that stopped the run.
    pub end: Result<State, Error>,
    /// The fastest wall-clock time of the repeated runs.
    pub time: Duration,
}

/// Runs `method` with `step` over the scene `repeats` times and keeps the fastest.
pub fn run(scene: &TestScene, method: Method, step: Step, repeats: u32) -> Result<Outcome, Error> {
    let mut best = Duration::MAX;
    let mut end = Err(Error::invalid("report", "no run"));
    for _ in 0..repeats.max(1) {
        let mut integrator = method.integrator(step)?;
        let start = Instant::now();
        let result = integrator.advance(&scene.body, 0.0, scene.initial, scene.t_end);
        best = best.min(start.elapsed());
        end = result;
    }
    Ok(Outcome { end, time: best })
}

/// The reference end state: the exact flow for free bodies, tight Dormand-Prince otherwise.
pub fn reference(scene: &TestScene) -> Result<State, Error> {
    if scene.body.has_torque() {
        DormandPrince::new(1e-13, 1e-15)?
            .with_max_steps(50_000_000)
            .advance(&scene.body, 0.0, scene.initial, scene.t_end)
    } else {
        ExactFreeBody::new().advance(&scene.body, 0.0, scene.initial, scene.t_end)
    }
}

/// The relative error of the body angular momentum.
#[must_use]
pub fn momentum_error(scene: &TestScene, state: &State, reference: &State) -> f64 {
    let m = scene.body.body_momentum(state.omega);
    let m_ref = scene.body.body_momentum(reference.omega);
    (m - m_ref).norm() / m_ref.norm()
}

/// The relative drift of the total energy (kinetic plus the torque's potential).
#[must_use]
pub fn energy_drift(scene: &TestScene, state: &State) -> f64 {
    let e0 = scene.body.total_energy(0.0, &scene.initial);
    (scene.body.total_energy(scene.t_end, state) - e0).abs() / e0.abs()
}
