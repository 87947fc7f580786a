//! ode_solvers' Dormand-Prince pairs on the form a physicist writes for a general solver:
//! seven unknowns, the body angular momentum `m` and a unit quaternion `q` (body to space),
//!
//! ```text
//! m' = m x w + tau,   q' = q (0, w) / 2,   w = J^-1 m,
//! ```
//!
//! with `rtol = atol = tol`, renormalising `q` only at output (as a user would), and the
//! samples of a run from the solver's own dense output. The quaternion is the rotor in
//! glam's components (`w = s, x = -e23, y = e13, z = -e12`).

use ga_core::f64::g3::Rotor;
use ode_solvers::dop_shared::IntegrationError;
use ode_solvers::{Dop853, Dopri5, OutputType, SVector, System};

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::{self, Error};
use crate::integrators::{step_limit_reached, Integrator};

/// The seven unknowns `[m1, m2, m3, qw, qx, qy, qz]`.
type Y = SVector<f64, 7>;

/// Which of ode_solvers' pairs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QuaternionSolver {
    /// `Dop853`: Dormand-Prince 8(5,3), Hairer's DOP853.
    Dop853,
    /// `Dopri5`: Dormand-Prince 5(4), Hairer's DOPRI5.
    Dopri5,
}

/// A general-purpose solver on the quaternion form, with a tolerance.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuaternionOde {
    solver: QuaternionSolver,
    tol: f64,
    accepted: u64,
    rejected: u64,
    /// The run's bound on all the steps ([`Integrator::limit_steps`]); ode_solvers' own
    /// bound per call, [`ODE_SOLVERS_MAX_STEPS`], without one.
    run_limit: Option<u64>,
}

/// ode_solvers' default bound on the steps of one integration (`n_max` in its `new`).
const ODE_SOLVERS_MAX_STEPS: u32 = 100_000;

impl QuaternionOde {
    /// `solver` at `rtol = atol = tol` (finite and positive).
    pub fn new(solver: QuaternionSolver, tol: f64) -> Result<Self, Error> {
        error::positive("tol", "tolerance", tol)?;
        Ok(Self {
            solver,
            tol,
            accepted: 0,
            rejected: 0,
            run_limit: None,
        })
    }

    /// Integrate from `state` at `t` to `t_end`; with `dx` the solver's dense output every
    /// `dx` from `t` (the output then starts with `t`), otherwise its end state only.
    fn integrate(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: State,
        t_end: f64,
        dx: Option<f64>,
    ) -> Result<(Vec<f64>, Vec<Y>), Error> {
        let form = QuaternionForm { body };
        let y0 = to_y(body, &state);
        let (output, spacing) = match dx {
            Some(dx) => (OutputType::Dense, dx),
            None => (OutputType::Sparse, t_end - t),
        };
        // ode_solvers counts its steps (accepted and rejected) in a u32 per integration.
        let n_max = match self.run_limit {
            Some(limit) => {
                let left = limit.saturating_sub(self.accepted + self.rejected);
                u32::try_from(left).unwrap_or(u32::MAX)
            }
            None => ODE_SOLVERS_MAX_STEPS,
        };
        let name = self.name();
        let run_limit = self.run_limit;
        let failed = |e: ode_solvers::dop_shared::IntegrationError| match (e, run_limit) {
            (IntegrationError::MaxNumStepReached { x, .. }, Some(limit)) if n_max < u32::MAX => {
                step_limit_reached(name, limit, x, t_end)
            }
            (IntegrationError::MaxNumStepReached { x, .. }, Some(_)) => Error::invalid(
                name,
                format!(
                    "ode_solvers takes at most {} steps in one integration: stopped at t = {} \
                     on the way to t = {}",
                    u32::MAX,
                    error::num(x),
                    error::num(t_end)
                ),
            ),
            (e, _) => Error::invalid(name, format!("ode_solvers: {e}")),
        };
        // `from_param` with the values ode_solvers' `new` uses, but `n_max`.
        let (stats, x, y) = match self.solver {
            QuaternionSolver::Dop853 => {
                let mut s = Dop853::from_param(
                    form,
                    t,
                    t_end,
                    spacing,
                    y0,
                    self.tol,
                    self.tol,
                    0.9,
                    0.0,
                    0.333,
                    6.0,
                    t_end - t,
                    0.0,
                    n_max,
                    1000,
                    output,
                );
                let stats = s.integrate().map_err(failed)?;
                (stats, s.x_out().clone(), s.y_out().clone())
            }
            QuaternionSolver::Dopri5 => {
                let mut s = Dopri5::from_param(
                    form,
                    t,
                    t_end,
                    spacing,
                    y0,
                    self.tol,
                    self.tol,
                    0.9,
                    0.04,
                    0.2,
                    10.0,
                    t_end - t,
                    0.0,
                    n_max,
                    1000,
                    output,
                );
                let stats = s.integrate().map_err(failed)?;
                (stats, s.x_out().clone(), s.y_out().clone())
            }
        };
        self.accepted += u64::from(stats.accepted_steps);
        self.rejected += u64::from(stats.rejected_steps);
        Ok((x, y))
    }
}

/// The equations of motion in the quaternion form, for ode_solvers.
struct QuaternionForm<'a> {
    body: &'a RigidBody,
}

impl System<f64, Y> for QuaternionForm<'_> {
    // Inline, so that the solver's stage loop can take it in whichever codegen unit the
    // solver lands: without it the peer's speed moved by 40 % with unrelated changes to
    // this crate, as the partition of the code moved (the race in BENCHMARKS.md).
    #[inline]
    fn system(&self, t: f64, y: &Y, dy: &mut Y) {
        let j = self.body.moments();
        let m = [y[0], y[1], y[2]];
        let w = [m[0] / j[0], m[1] / j[1], m[2] / j[2]];
        let tau = if self.body.has_torque() {
            let state = State {
                rotor: rotor_of(y),
                omega: omega_from_vector(w),
            };
            omega_to_vector(self.body.torque(t, &state))
        } else {
            [0.0; 3]
        };
        dy[0] = m[1] * w[2] - m[2] * w[1] + tau[0];
        dy[1] = m[2] * w[0] - m[0] * w[2] + tau[1];
        dy[2] = m[0] * w[1] - m[1] * w[0] + tau[2];
        // q' = q (0, w) / 2.
        let (qw, qx, qy, qz) = (y[3], y[4], y[5], y[6]);
        dy[3] = 0.5 * (-qx * w[0] - qy * w[1] - qz * w[2]);
        dy[4] = 0.5 * (qw * w[0] + qy * w[2] - qz * w[1]);
        dy[5] = 0.5 * (qw * w[1] + qz * w[0] - qx * w[2]);
        dy[6] = 0.5 * (qw * w[2] + qx * w[1] - qy * w[0]);
    }
}

/// The rotor of a quaternion in glam's components (not normalised).
fn rotor_of(y: &Y) -> Rotor {
    Rotor::new(y[3], -y[6], y[5], -y[4])
}

fn to_y(body: &RigidBody, state: &State) -> Y {
    let j = body.moments();
    let w = omega_to_vector(state.omega);
    let r = state.rotor;
    Y::from([
        j[0] * w[0],
        j[1] * w[1],
        j[2] * w[2],
        r.s,
        -r.e23,
        r.e13,
        -r.e12,
    ])
}

/// The state of a solution point, the quaternion normalised.
fn state_of(body: &RigidBody, y: &Y) -> State {
    let j = body.moments();
    let rotor = rotor_of(y);
    State {
        rotor: rotor / rotor.norm(),
        omega: omega_from_vector([y[0] / j[0], y[1] / j[1], y[2] / j[2]]),
    }
}

impl Integrator for QuaternionOde {
    fn name(&self) -> &'static str {
        match self.solver {
            QuaternionSolver::Dop853 => "dop853-quaternion",
            QuaternionSolver::Dopri5 => "dopri5-quaternion",
        }
    }

    fn accepted_steps(&self) -> Option<u64> {
        Some(self.accepted)
    }

    fn limit_steps(&mut self, max_steps: u64) {
        self.run_limit = Some(max_steps);
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        error::finite("dt", "time step", dt)?;
        if dt == 0.0 {
            return crate::integrators::check_finite(self.name(), state);
        }
        let (_, y) = self.integrate(body, t, state, t + dt, None)?;
        let end = y
            .last()
            .ok_or_else(|| Error::invalid(self.name(), "no solution point"))?;
        crate::integrators::check_finite(self.name(), state_of(body, end))
    }

    /// Evenly spaced times from `t` are read off the solver's dense output in one run;
    /// other times take one run each.
    fn advance_to_each(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: State,
        times: &[f64],
    ) -> Result<Vec<State>, Error> {
        let Some(&last) = times.last() else {
            return Ok(Vec::new());
        };
        let spacing = (last - t) / times.len() as f64;
        let even = spacing > 0.0
            && times
                .iter()
                .enumerate()
                .all(|(k, &ti)| (ti - (t + spacing * (k + 1) as f64)).abs() <= 1e-9 * spacing);
        if !even {
            let mut out = Vec::with_capacity(times.len());
            let (mut t, mut state) = (t, state);
            for &ti in times {
                state = self.advance(body, t, state, ti - t)?;
                t = ti;
                out.push(state);
            }
            return Ok(out);
        }
        // ode_solvers 0.6 adds an output at `x_end` when the next output time lies within
        // 1e-9 of it, from whatever step it is in, extrapolating past the step when that
        // step ends before `x_end`; half a spacing more puts every sample inside a step.
        let (x, y) = self.integrate(body, t, state, last + 0.5 * spacing, Some(spacing))?;
        times
            .iter()
            .map(|&ti| {
                let k = x
                    .iter()
                    .position(|&xk| (xk - ti).abs() <= 1e-6 * spacing)
                    .ok_or_else(|| {
                        Error::invalid(self.name(), format!("no dense output at t = {ti}"))
                    })?;
                crate::integrators::check_finite(self.name(), state_of(body, &y[k]))
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The run's limit replaces ode_solvers' 100000 steps, counts over calls, and the
    /// error names it.
    #[test]
    fn the_runs_step_limit_stops_the_solver_and_is_named() {
        let body = RigidBody::new([1.0, 2.0, 3.0]).unwrap();
        let state = State {
            rotor: Rotor::ONE,
            omega: omega_from_vector([0.5, 4.0, 0.3]),
        };
        for solver in [QuaternionSolver::Dop853, QuaternionSolver::Dopri5] {
            let mut ode = QuaternionOde::new(solver, 1e-8).unwrap();
            ode.limit_steps(300);
            let mid = ode.advance(&body, 0.0, state, 1.0).unwrap();
            let used = ode.accepted + ode.rejected;
            assert!(used > 0 && used < 300, "{used}");
            let e = ode.advance(&body, 1.0, mid, 1000.0).unwrap_err();
            assert_eq!(e.field(), Some("max_steps"), "{e}");
            let text = e.to_string();
            assert!(
                text.contains("needs more than 300 steps")
                    && text.contains("raise the limit with max_steps"),
                "{text}"
            );
        }
    }
}
