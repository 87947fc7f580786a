//! The exact flow of the torque-free rigid body as a method: one evaluation of the
//! closed-form solution in Jacobi elliptic functions and elliptic integrals of the third
//! kind (E. Celledoni, F. Fassò, N. Säfström, A. Zanna, "The exact computation of the free
//! rigid body motion and its use in splitting methods", SIAM J. Sci. Comput. 30(4), 2008),
//! as implemented in [`crate::exact_flow`]. There is no step: `advance` is exact up to
//! rounding for any `dt`. It refuses a body on which a torque acts.

use ga_core::f64::g3::Rotor;

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::Error;
use crate::exact_flow::exact_free_body;

use super::integrator::{check_finite, Integrator};

/// The exact solution of the free rigid body, evaluated at the end of each interval.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct ExactFreeBody;

impl ExactFreeBody {
    /// The exact method (it has no parameters).
    #[must_use]
    pub fn new() -> Self {
        ExactFreeBody
    }
}

impl Integrator for ExactFreeBody {
    fn name(&self) -> &'static str {
        "exact"
    }

    fn advance(
        &mut self,
        body: &RigidBody,
        _t: f64,
        state: State,
        dt: f64,
    ) -> Result<State, Error> {
        crate::error::finite("dt", "time step", dt)?;
        if body.has_torque() {
            return Err(Error::invalid(
                "method",
                "the exact flow needs a torque-free body; choose a stepping method",
            ));
        }
        if dt == 0.0 {
            return check_finite(self.name(), state);
        }
        let moments = body.moments();
        let w = omega_to_vector(state.omega);
        let m0 = [moments[0] * w[0], moments[1] * w[1], moments[2] * w[2]];
        let r = state.rotor;
        let (r1, m1) = exact_free_body(moments, m0, [r.s, r.e12, r.e13, r.e23], dt);
        let state = State {
            rotor: Rotor::new(r1[0], r1[1], r1[2], r1[3]),
            omega: omega_from_vector([m1[0] / moments[0], m1[1] / moments[1], m1[2] / moments[2]]),
        };
        check_finite(self.name(), state)
    }
}
