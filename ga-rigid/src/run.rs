//! A scene run by a registry method, start to end: the body in its principal frame, the
//! integrator the method names, one row per sample turned back into the scene's frame and
//! checked finite.
//!
//! The equations run in the body's principal frame; a scene's `rotor` and `omega` describe
//! its own (mesh or point-cloud) frame, related by the principal rotor `P` (principal to
//! scene frame): the principal attitude is `R P`, the principal angular velocity
//! `~P Omega P`, and rows are turned back into the scene frame.

use ga_core::f64::g3::{Rotor, Sandwich};

use crate::csv::Row;
use crate::dynamics::omega_to_vector;
use crate::error::Error;
use crate::integrators::Integrator;
use crate::limits::DEFAULT_MAX_STEPS;
use crate::registry::{Method, Step};
use crate::scene::Scene;
use crate::simulation::{Sample, Simulation};

/// Integrate `scene` with `method` and return one row per sample time; a method that
/// chooses its own steps stops at the default step limit
/// ([`crate::limits::DEFAULT_MAX_STEPS`]).
pub fn run_simulation(scene: &Scene, method: Method, step: Step) -> Result<Vec<Row>, Error> {
    run_simulation_with_progress(scene, method, step, DEFAULT_MAX_STEPS, &mut |_| {})
}

/// [`run_simulation`] with the run's step limit `max_steps` (the one
/// [`crate::limits::plan`] checked the estimate against, [`Limits::max_steps`]), which a
/// method that chooses its own steps stops at ([`Integrator::limit_steps`]), calling
/// `progress(t)` after each sample (for a progress display).
///
/// [`Limits::max_steps`]: crate::limits::Limits::max_steps
pub fn run_simulation_with_progress(
    scene: &Scene,
    method: Method,
    step: Step,
    max_steps: u64,
    progress: &mut dyn FnMut(f64),
) -> Result<Vec<Row>, Error> {
    let body = scene.principal_body()?;
    let principal = scene.inertia.rotor();
    let mut integrator = method.integrator(step)?;
    integrator.limit_steps(max_steps);
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
