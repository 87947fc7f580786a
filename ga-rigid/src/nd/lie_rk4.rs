//! Runge-Kutta-Munthe-Kaas of order four (H. Munthe-Kaas, "High order Runge-Kutta methods
//! on manifolds", Appl. Numer. Math. 29, 1999) in the two-commutator form of Iserles,
//! Munthe-Kaas, Nørsett and Zanna, "Lie-group methods", Acta Numerica 9 (2000), section 5,
//! written over the algebra: the 3D `integrators::LieRk4` for G2, G3 and G4.
//!
//! The rotor obeys `dR/dt = R A`, `A = -1/2 Omega_B`, and moves only by right
//! multiplication with `exp` of a bivector (in G4 a non-simple one in general), with the
//! brackets `[a, b] = ab - ba = 2 a x b`:
//!
//! ```text
//! k1 = h A(R0)
//! k2 = h A(R0 exp(k1/2))
//! k3 = h A(R0 exp(k2/2 + [k1, k2]/8))
//! k4 = h A(R0 exp(k3))
//! R1 = R0 exp((k1 + 2 k2 + 2 k3 + k4)/6 + [k1, k4]/12)
//! ```
//!
//! while `Omega_B` takes the classical RK4 stages.

use super::algebra::Algebra;
use super::body::RigidBody;
use super::integrator::{fixed_steps, unit, Integrator};
use super::state::State;
use crate::error::Error;
use crate::integrators::check_step;

/// RKMK4 with fixed step; the rotor stays unit by construction.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LieRk4 {
    step: f64,
}

impl LieRk4 {
    /// RKMK4 with sub-steps of at most `step` (finite and positive).
    pub fn new(step: f64) -> Result<Self, Error> {
        Ok(LieRk4 {
            step: check_step(step)?,
        })
    }

    /// One RKMK4 step of length `h` from `state` at time `t`.
    #[must_use]
    pub fn step_once<A: Algebra>(body: &RigidBody<A>, t: f64, state: State<A>, h: f64) -> State<A> {
        let (r0, w0) = (state.rotor, state.omega);
        let stage = |t: f64, rotor: A::Rotor, omega: A::Bivector| {
            let s = State { rotor, omega };
            (omega * (-0.5 * h), body.omega_rate(t, &s) * h)
        };
        let (k1, l1) = stage(t, r0, w0);
        let (k2, l2) = stage(t + 0.5 * h, r0 * A::exp(k1 * 0.5), w0 + l1 * 0.5);
        let theta3 = k2 * 0.5 + A::commutator(k1, k2) * 0.25;
        let (k3, l3) = stage(t + 0.5 * h, r0 * A::exp(theta3), w0 + l2 * 0.5);
        let (k4, l4) = stage(t + h, r0 * A::exp(k3), w0 + l3);
        let theta = (k1 + (k2 + k3) * 2.0 + k4) * (1.0 / 6.0) + A::commutator(k1, k4) * (1.0 / 6.0);
        // Scaling back keeps the rounding of many exp products from walking.
        State {
            rotor: unit::<A>(r0 * A::exp(theta)),
            omega: w0 + (l1 + (l2 + l3) * 2.0 + l4) * (1.0 / 6.0),
        }
    }
}

impl<A: Algebra> Integrator<A> for LieRk4 {
    fn name(&self) -> &'static str {
        "lie-rk4"
    }

    fn advance(
        &mut self,
        body: &RigidBody<A>,
        t: f64,
        state: State<A>,
        dt: f64,
    ) -> Result<State<A>, Error> {
        fixed_steps("lie-rk4", self.step, t, state, dt, |t, s, h| {
            Ok(Self::step_once(body, t, s, h))
        })
    }
}
