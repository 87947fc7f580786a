//! The torque-free symmetric top in closed form (the lecture's solution):
//! `R(t) = exp(-1/2 Omega_l t) R(0) exp(-1/2 Omega_r t)` with `Omega_l = L / i_p` and
//! `Omega_r = w_a (i_p - i_a) / i_p I e_a`, for symmetry axis `e_a` with moment `i_a` and
//! the two equal moments `i_p`. See docs/derivations/symmetric-top.md.

use ga_core::f64::g3::{Bivector, Rotor, Sandwich, Trivector, Vector};

use super::body::RigidBody;
use super::state::State;
use crate::error::Error;

/// The relative tolerance within which two moments count as equal by default.
pub const DEFAULT_SYMMETRY_TOLERANCE: f64 = 1e-12;

/// A symmetric top's motion, ready to be evaluated at any time without stepping.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SymmetricTop {
    initial: State,
    /// `-1/2 Omega_l`, the space precession generator.
    left: Bivector,
    /// `-1/2 Omega_r`, the body spin generator.
    right: Bivector,
    moments: [f64; 3],
}

impl SymmetricTop {
    /// The closed-form motion of `body` from `initial`; an error unless two moments agree to
    /// `relative_tolerance` and no torque acts.
    pub fn new(body: &RigidBody, initial: State, relative_tolerance: f64) -> Result<Self, Error> {
        if body.has_torque() {
            return Err(Error::Invalid {
                field: "method".into(),
                rule: "closed-form needs a torque-free body".into(),
            });
        }
        let Some(axis) = body.symmetry_axis(relative_tolerance) else {
            let [a, b, c] = body.moments();
            return Err(Error::Invalid {
                field: "body.moments".into(),
                rule: format!(
                    "closed-form needs a symmetric body (two moments equal to within a \
                     relative {relative_tolerance:e}), got [{a}, {b}, {c}]"
                ),
            });
        };
        let moments = body.moments();
        let i_a = moments[axis];
        let i_p = moments[(axis + 1) % 3];
        let space_momentum = body.space_momentum(&initial);
        let w = super::state::omega_to_vector(initial.omega);
        let mut e = [0.0; 3];
        e[axis] = 1.0;
        let spin_axis = Trivector::new(1.0) * Vector::new(e[0], e[1], e[2]);
        let omega_r = spin_axis * (w[axis] * (i_p - i_a) / i_p);
        Ok(SymmetricTop {
            initial,
            left: space_momentum * (-0.5 / i_p),
            right: omega_r * -0.5,
            moments,
        })
    }

    /// The attitude at time `t`.
    #[must_use]
    pub fn rotor(&self, t: f64) -> Rotor {
        (self.left * t).exp() * self.initial.rotor * (self.right * t).exp()
    }

    /// The full state at time `t`: the body momentum turns rigidly about the symmetry axis,
    /// `m(t) = exp(1/2 Omega_r t) m(0) exp(-1/2 Omega_r t)`.
    #[must_use]
    pub fn state(&self, t: f64) -> State {
        let spin = (self.right * t).exp();
        let omega = spin.reverse().sandwich(self.initial.omega);
        State {
            rotor: self.rotor(t),
            omega,
        }
    }

    /// The principal moments of the body this was built for.
    #[must_use]
    pub fn moments(&self) -> [f64; 3] {
        self.moments
    }
}
