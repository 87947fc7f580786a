//! `simulate`: a scene, a method, rows of CSV.
//!
//! The equations run in the body's principal frame; a scene's `rotor` and `omega` describe
//! its own (mesh or point-cloud) frame, related by the principal rotor `P` (principal to
//! scene frame): the principal attitude is `R P`, the principal angular velocity
//! `~P Omega P`, and rows are turned back into the scene frame.

use ga_core::f64::g3::{Rotor, Sandwich};

use crate::csv::Row;
use crate::dynamics::{omega_to_vector, RigidBody, State};
use crate::error::Error;
use crate::integrators::{Method, Step};
use crate::scene::Scene;

/// The body of a scene in its principal frame, with gravity when the scene has it.
pub fn principal_body(scene: &Scene) -> Result<RigidBody, Error> {
    scene.principal_body()
}

/// Integrate `scene` with `method` and return one row per sample time.
pub fn run_simulation(scene: &Scene, method: Method, step: Step) -> Result<Vec<Row>, Error> {
    let body = principal_body(scene)?;
    let principal = scene.inertia.rotor();
    let mut integrator = method.integrator(step)?;
    let mut state = scene.principal_state();
    let times = scene.run.times();
    let mut rows = Vec::with_capacity(times.len());
    let mut t = 0.0;
    for &sample in &times {
        state = integrator.advance(&body, t, state, sample - t)?;
        t = sample;
        rows.push(row(&body, principal, t, &state));
    }
    Ok(rows)
}

fn row(body: &RigidBody, principal: Rotor, t: f64, state: &State) -> Row {
    let momentum = body.space_momentum(state).undual();
    Row {
        t,
        rotor: state.rotor * principal.reverse(),
        omega: omega_to_vector(principal.sandwich(state.omega)),
        energy: body.total_energy(t, state),
        momentum: momentum.to_array(),
    }
}
