//! `simulate`: a scene, a method, rows of CSV.
//!
//! The equations run in the body's principal frame; a scene's `rotor` and `omega` describe
//! its own (mesh or point-cloud) frame, related by the principal rotor `P` (principal to
//! scene frame): the principal attitude is `R P`, the principal angular velocity
//! `~P Omega P`, and rows are turned back into the scene frame.

use ga_core::f64::g3::{Rotor, Sandwich};

use super::args::{Method, Step};
use crate::csv::Row;
use crate::dynamics::{omega_to_vector, Gravity, RigidBody, State};
use crate::error::Error;
use crate::integrators::{
    ClosedForm, ComposedSplitting, DormandPrince, ExactFreeBody, ExactSplitting, ImplicitMidpoint,
    Integrator, LieDop853, LieRk4, Rk4, Splitting,
};
use crate::scene::Scene;

/// The absolute tolerance paired with `--tol` (the relative one) for Dormand-Prince.
const DOPRI_ABSOLUTE_TOLERANCE_RATIO: f64 = 1e-3;

/// The integrator for a method and its validated step control.
pub fn integrator_for(method: Method, step: Step) -> Result<Box<dyn Integrator>, Error> {
    let fixed = |what: &str| match step {
        Step::Fixed(h) => Ok(h),
        _ => Err(Error::invalid("--dt", format!("{what} needs --dt"))),
    };
    Ok(match method {
        Method::ClosedForm => Box::new(ClosedForm::new()),
        Method::Exact => Box::new(ExactFreeBody::new()),
        Method::Rk4 => Box::new(Rk4::new(fixed("rk4")?)?),
        Method::LieRk4 => Box::new(LieRk4::new(fixed("lie-rk4")?)?),
        Method::Midpoint => Box::new(ImplicitMidpoint::new(fixed("midpoint")?)?),
        Method::Splitting => Box::new(Splitting::new(fixed("splitting")?)?),
        Method::Dopri => match step {
            Step::Tolerance(tol) => Box::new(DormandPrince::new(
                tol,
                tol * DOPRI_ABSOLUTE_TOLERANCE_RATIO,
            )?),
            _ => return Err(Error::invalid("--tol", "dopri needs --tol")),
        },
        Method::ExactSplitting => Box::new(ExactSplitting::new(fixed("exact-splitting")?)?),
        Method::ExactSplitting4 => {
            Box::new(ExactSplitting::with_order(fixed("exact-splitting-4")?, 4)?)
        }
        Method::ExactSplitting6 => {
            Box::new(ExactSplitting::with_order(fixed("exact-splitting-6")?, 6)?)
        }
        Method::ExactSplitting8 => {
            Box::new(ExactSplitting::with_order(fixed("exact-splitting-8")?, 8)?)
        }
        Method::Splitting4 => Box::new(ComposedSplitting::new(fixed("splitting-4")?, 4)?),
        Method::Splitting6 => Box::new(ComposedSplitting::new(fixed("splitting-6")?, 6)?),
        Method::Splitting8 => Box::new(ComposedSplitting::new(fixed("splitting-8")?, 8)?),
        Method::LieDop853 => match step {
            Step::Tolerance(tol) => {
                Box::new(LieDop853::new(tol, tol * DOPRI_ABSOLUTE_TOLERANCE_RATIO)?)
            }
            _ => return Err(Error::invalid("--tol", "lie-dop853 needs --tol")),
        },
    })
}

/// The body of a scene in its principal frame, with gravity when the scene has it.
pub fn principal_body(scene: &Scene) -> Result<RigidBody, Error> {
    let body = RigidBody::new_unphysical(scene.inertia.moments())?;
    Ok(match scene.torque {
        None => body,
        Some(gravity) => {
            let principal = scene.inertia.rotor();
            body.with_torque(Gravity {
                // A `moments` body has no mass: its `g` is the weight m g.
                mass: scene.inertia.mass().unwrap_or(1.0),
                g: gravity.g,
                com_offset: principal.reverse().sandwich(gravity.com_offset),
            })
        }
    })
}

/// Integrate `scene` with `method` and return one row per sample time.
pub fn run_simulation(scene: &Scene, method: Method, step: Step) -> Result<Vec<Row>, Error> {
    let body = principal_body(scene)?;
    let principal = scene.inertia.rotor();
    let mut integrator = integrator_for(method, step)?;
    let mut state = State {
        rotor: scene.initial.rotor * principal,
        omega: principal.reverse().sandwich(scene.initial.omega_bivector()),
    };
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
