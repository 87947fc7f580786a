//! The symmetric top's closed form (the lecture's solution, [`SymmetricTop`]) behind the
//! [`Integrator`] trait: exact at any step, no stepping.

use super::integrator::{check_finite, unit, Integrator};
use crate::dynamics::{RigidBody, State, SymmetricTop, DEFAULT_SYMMETRY_TOLERANCE};
use crate::error::Error;

/// `R(t) = exp(-1/2 Omega_l t) R(0) exp(-1/2 Omega_r t)` for a torque-free symmetric body;
/// an error for any other body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosedForm {
    relative_tolerance: f64,
}

impl ClosedForm {
    /// Accepts bodies whose two equal moments agree to [`DEFAULT_SYMMETRY_TOLERANCE`].
    #[must_use]
    pub fn new() -> Self {
        ClosedForm {
            relative_tolerance: DEFAULT_SYMMETRY_TOLERANCE,
        }
    }
}

impl Default for ClosedForm {
    fn default() -> Self {
        Self::new()
    }
}

impl Integrator for ClosedForm {
    fn name(&self) -> &'static str {
        "closed-form"
    }

    fn advance(
        &mut self,
        body: &RigidBody,
        _t: f64,
        state: State,
        dt: f64,
    ) -> Result<State, Error> {
        let top = SymmetricTop::new(body, state, self.relative_tolerance)?;
        // Called again and again from its own result, the two exponentials' rounding
        // would walk |R ~R| away from one (5.8e-11 over 10^6 calls on the short fat top).
        let end = top.state(dt);
        check_finite(
            self.name(),
            State {
                rotor: unit(end.rotor),
                omega: end.omega,
            },
        )
    }
}
