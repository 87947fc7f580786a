//! The classical fourth-order Runge-Kutta method (Kutta 1901; Hairer, Nørsett, Wanner,
//! *Solving Ordinary Differential Equations I*, 2nd ed., Springer 1993, Table II.1.2) on
//! `(R, Omega_B)` as a point of a vector space, the rotor scaled back to unit norm after
//! every step: the 3D `integrators::Rk4` written over the algebra.

use super::algebra::Algebra;
use super::body::RigidBody;
use super::integrator::{fixed_steps, unit, Integrator};
use super::state::State;
use crate::error::Error;
use crate::integrators::check_step;

/// Classical explicit RK4 with fixed step and rotor renormalisation.
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

    /// One RK4 step of length `h` from `state` at time `t`.
    #[must_use]
    pub fn step_once<A: Algebra>(body: &RigidBody<A>, t: f64, state: State<A>, h: f64) -> State<A> {
        let rate = |t: f64, s: &State<A>| (RigidBody::rotor_rate(s), body.omega_rate(t, s));
        let shifted = |k: &(A::Rotor, A::Bivector), a: f64| State {
            rotor: state.rotor + k.0 * a,
            omega: state.omega + k.1 * a,
        };
        let k1 = rate(t, &state);
        let k2 = rate(t + 0.5 * h, &shifted(&k1, 0.5 * h));
        let k3 = rate(t + 0.5 * h, &shifted(&k2, 0.5 * h));
        let k4 = rate(t + h, &shifted(&k3, h));
        let w = h / 6.0;
        State {
            rotor: unit::<A>(state.rotor + (k1.0 + (k2.0 + k3.0) * 2.0 + k4.0) * w),
            omega: state.omega + (k1.1 + (k2.1 + k3.1) * 2.0 + k4.1) * w,
        }
    }
}

impl<A: Algebra> Integrator<A> for Rk4 {
    fn name(&self) -> &'static str {
        "rk4"
    }

    fn advance(
        &mut self,
        body: &RigidBody<A>,
        t: f64,
        state: State<A>,
        dt: f64,
    ) -> Result<State<A>, Error> {
        fixed_steps("rk4", self.step, t, state, dt, |t, s, h| {
            Ok(Self::step_once(body, t, s, h))
        })
    }
}
