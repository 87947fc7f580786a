//! Buss's second-order rotation update: S. R. Buss, "Accurate and efficient simulation of
//! rigid-body rotations", J. Comput. Phys. 164 (2000), 377-406, the "augmented second-order
//! method". The orientation turns by the rotation vector `h w~` with
//! `w~ = w + h/2 dw/dt + (h^2/12) (dw/dt) x w` (the Magnus expansion of a linearly varying
//! `w` to third order in `h`), and the angular velocity then comes from the angular
//! momentum, which the torque alone changes: `L1 = L0 + h tau` in the space frame, so a free
//! body keeps `|L|` exactly.
//!
//! Buss writes it in the space frame; here `w` is the body angular velocity and the
//! orientation is multiplied on the right (`R1 = R0 exp(-h/2 I w~)`), where the Magnus
//! term changes sign: `w~ = w + h/2 dw/dt - (h^2/12) (dw/dt) x w`.

use ga_core::f64::g3::{Rotor, Sandwich};

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::Error;
use crate::integrators::{check_step, fixed_steps, Integrator};

/// `a x b`.
pub(super) fn cross(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

/// The engines' first-order orientation update with body angular velocity `w`:
/// `R1 = unit(R0 - h/2 R0 Omega)`, the rotor form of `q1 = normalise(q0 + h/2 q0 (0, w))`.
pub(super) fn rotated_by_velocity(rotor: Rotor, w: [f64; 3], h: f64) -> Rotor {
    let moved = rotor - rotor * omega_from_vector(w) * (0.5 * h);
    moved / moved.norm()
}

/// Buss's augmented second-order method with fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Buss {
    step: f64,
}

impl Buss {
    /// The method with fixed step `h` (finite and positive).
    pub fn new(h: f64) -> Result<Self, Error> {
        Ok(Self {
            step: check_step(h)?,
        })
    }
}

fn buss_step(body: &RigidBody, t: f64, state: State, h: f64) -> State {
    let w = omega_to_vector(state.omega);
    let alpha = omega_to_vector(body.omega_rate(t, &state));
    let magnus = cross(alpha, w);
    let turn: [f64; 3] =
        std::array::from_fn(|k| w[k] + 0.5 * h * alpha[k] - h * h / 12.0 * magnus[k]);
    let rotor = state.rotor * (omega_from_vector(turn) * (-0.5 * h)).exp();
    // The space momentum changes only by the torque's impulse.
    let momentum = body.space_momentum(&state) + state.rotor.sandwich(body.torque(t, &state)) * h;
    let body_momentum = rotor.reverse().sandwich(momentum);
    State {
        rotor,
        omega: body.omega_for_momentum(body_momentum),
    }
}

impl Integrator for Buss {
    fn name(&self) -> &'static str {
        "buss-2"
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        fixed_steps(self.name(), self.step, t, state, dt, |t, s, h| {
            Ok(buss_step(body, t, s, h))
        })
    }
}
