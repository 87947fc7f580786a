//! The classical fourth-order Runge-Kutta method (Kutta 1901; Hairer, Nørsett, Wanner,
//! *Solving Ordinary Differential Equations I*, 2nd ed., Springer 1993, Table II.1.2)
//! applied to `(R, Omega_B)` as a point of R^4 x R^3, with the rotor scaled back to unit
//! norm after every step. Not geometric: energy and `|m|` drift at order four, and it
//! blows up once `h |w|` passes its stability bound (about 2.8).

use ga_core::f64::g3::{Bivector, Rotor};

use crate::dynamics::{RigidBody, State};
use crate::error::Error;

use super::integrator::{check_step, fixed_steps, unit, Integrator};

/// Classical explicit RK4 with fixed step `h` and rotor renormalisation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Rk4 {
    step: f64,
}

impl Rk4 {
    /// RK4 with sub-steps of at most `step` (finite and positive).
    pub fn new(step: f64) -> Result<Self, Error> {
        Ok(Rk4 {
            step: check_step(step)?,
        })
    }

    /// The largest sub-step.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.step
    }

    /// One RK4 step of length `h` from `state` at time `t`.
    #[inline]
    #[must_use]
    pub fn step_once(body: &RigidBody, t: f64, state: State, h: f64) -> State {
        let rate = |t: f64, s: &State| (RigidBody::rotor_rate(s), body.omega_rate(t, s));
        let shifted = |k: &(Rotor, Bivector), a: f64| State {
            rotor: state.rotor + k.0 * a,
            omega: state.omega + k.1 * a,
        };
        let k1 = rate(t, &state);
        let k2 = rate(t + 0.5 * h, &shifted(&k1, 0.5 * h));
        let k3 = rate(t + 0.5 * h, &shifted(&k2, 0.5 * h));
        let k4 = rate(t + h, &shifted(&k3, h));
        let w = h / 6.0;
        State {
            rotor: unit(state.rotor + (k1.0 + (k2.0 + k3.0) * 2.0 + k4.0) * w),
            omega: state.omega + (k1.1 + (k2.1 + k3.1) * 2.0 + k4.1) * w,
        }
    }
}

impl Integrator for Rk4 {
    fn name(&self) -> &'static str {
        "rk4"
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        fixed_steps(self.name(), self.step, t, state, dt, |t, state, h| {
            Ok(Self::step_once(body, t, state, h))
        })
    }
}
