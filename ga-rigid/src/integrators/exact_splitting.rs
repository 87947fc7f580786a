//! Splitting with the exact free flow for a torqued body: E. Celledoni, F. Fassò,
//! N. Säfström, A. Zanna, "The exact computation of the free rigid body motion and its use
//! in splitting methods", SIAM J. Sci. Comput. 30(4) (2008) 2084-2112, section 5.
//!
//! The Hamiltonian `H = T(m) + V(R)` splits into the kinetic energy, whose flow is the
//! exact free rigid body motion ([`crate::exact_flow`]: the closed form when two moments
//! are equal, Jacobi elliptic functions otherwise), and the potential, whose flow at fixed
//! attitude is the torque kick `m += tau(R) dt`. Strang's composition
//!
//! ```text
//! S(h) = kick(h/2) free(h) kick(h/2)
//! ```
//!
//! is symmetric, symplectic and of order two; it keeps `|R ~R| = 1` to rounding (the free
//! flow is a rotor product, the kick leaves `R` alone). Its error comes from the torque
//! alone: with no torque it is the exact flow. The compositions of
//! [`Composition`] raise it to order 4, 6 and 8. Between two stages the closing kick of
//! one and the opening kick of the next act at the same time and attitude, so they merge
//! into one: a composition of `s` stages costs `s` free flows and `s + 1` torque
//! evaluations a step. The kicks are exact only when the torque does not depend on
//! `Omega` (gravity, a time-dependent couple); a time-dependent torque is read at the time
//! the kick stands at (time moves with the free flow), which keeps the method symmetric.

use ga_core::f64::g3::{Bivector, Rotor, Sandwich};

use crate::dynamics::{
    omega_from_vector, omega_to_vector, RigidBody, State, DEFAULT_SYMMETRY_TOLERANCE,
};
use crate::error::Error;
use crate::exact_flow::exact_free_body;

use super::composition::Composition;
use super::integrator::{check_finite, check_step, substeps, unit, Integrator};
use super::splitting::Splitting;

/// Kick, exact free flow, kick, composed to order 2, 4, 6 or 8, with fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExactSplitting {
    step: f64,
    scheme: Composition,
}

impl ExactSplitting {
    /// The Strang splitting (order 2) with sub-steps of at most `step` (finite, positive).
    pub fn new(step: f64) -> Result<Self, Error> {
        Self::with_order(step, 2)
    }

    /// The splitting composed to `order` (2, 4, 6 or 8, see [`Composition::of_order`]).
    pub fn with_order(step: f64, order: u32) -> Result<Self, Error> {
        Ok(ExactSplitting {
            step: check_step(step)?,
            scheme: Composition::of_order(order)?,
        })
    }

    /// The largest sub-step.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The order of the method.
    #[must_use]
    pub fn order(&self) -> u32 {
        self.scheme.order()
    }

    /// The exact free flow over `tau`, on the rotor and the body momentum.
    #[inline]
    fn free(flow: &FreeFlow, tau: f64, rotor: &mut Rotor, m: &mut [f64; 3]) {
        match *flow {
            FreeFlow::Symmetric {
                axis,
                plane,
                precession,
                spin,
            } => {
                // The symmetric top's closed form (the lecture's, as in `SymmetricTop`):
                // R(tau) = exp(-L tau / 2 i_p) R exp(-Omega_r tau / 2) with
                // Omega_r = w_a (i_p - i_a) / i_p I e_a; the body momentum turns with the
                // right factor. Inline rather than through `exact_free_body`, which spends
                // twice as long on quaternion conversions and on classifying the body.
                let body_momentum = omega_from_vector(*m);
                let left = (rotor.sandwich(body_momentum) * (precession * tau)).exp();
                let right = (plane * (spin * m[axis] * tau)).exp();
                *rotor = left * *rotor * right;
                // The body momentum turns about e_a by -spin rate * tau; turned component by
                // component, m_a stays exactly as it is (a sandwich would let it drift by
                // rounding, 1e-11 over 10^5 stages on the Lagrange top).
                let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
                let (sn, cs) = (2.0 * spin * m[axis] * tau).sin_cos();
                let (ma, mb) = (m[a], m[b]);
                m[a] = cs * ma - sn * mb;
                m[b] = sn * ma + cs * mb;
            }
            FreeFlow::Elliptic(moments) => {
                let r = *rotor;
                let (r1, m1) = exact_free_body(moments, *m, [r.s, r.e12, r.e13, r.e23], tau);
                *rotor = Rotor::new(r1[0], r1[1], r1[2], r1[3]);
                *m = m1;
            }
        }
    }
}

/// The free flow chosen once per call: the closed form of a symmetric body, or the
/// elliptic flow.
#[derive(Clone, Copy, Debug)]
enum FreeFlow {
    Symmetric {
        /// The symmetry axis (0, 1, 2).
        axis: usize,
        /// `I e_a`, the plane the body spins in.
        plane: Bivector,
        /// `-1 / (2 i_p)`: `left = exp(precession tau L)`.
        precession: f64,
        /// `-(i_p - i_a) / (2 i_a i_p)`: `right = exp(spin m_a tau I e_a)`.
        spin: f64,
    },
    Elliptic([f64; 3]),
}

impl FreeFlow {
    fn of(body: &RigidBody) -> FreeFlow {
        let moments = body.moments();
        match body.symmetry_axis(DEFAULT_SYMMETRY_TOLERANCE) {
            Some(axis) => {
                let (i_a, i_p) = (moments[axis], moments[(axis + 1) % 3]);
                let mut e = [0.0; 3];
                e[axis] = 1.0;
                FreeFlow::Symmetric {
                    axis,
                    plane: omega_from_vector(e),
                    precession: -0.5 / i_p,
                    spin: -0.5 * (i_p - i_a) / (i_a * i_p),
                }
            }
            None => FreeFlow::Elliptic(moments),
        }
    }
}

impl Integrator for ExactSplitting {
    fn name(&self) -> &'static str {
        match self.scheme.order() {
            2 => "exact-splitting",
            4 => "exact-splitting-4",
            6 => "exact-splitting-6",
            _ => "exact-splitting-8",
        }
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        let (n, h) = substeps(self.step, dt)?;
        if n == 0 {
            return check_finite(self.name(), state);
        }
        let moments = body.moments();
        let w = omega_to_vector(state.omega);
        let mut m: [f64; 3] = std::array::from_fn(|k| moments[k] * w[k]);
        let mut rotor = state.rotor;
        let flow = FreeFlow::of(body);
        if body.has_torque() {
            // The kick still owed at the current time: the closing half of the last stage.
            let mut owed = 0.0;
            let mut time = t;
            for i in 0..n {
                let start = t + i as f64 * h;
                let mut offset = 0.0;
                for g in self.scheme.gammas() {
                    let tau = g * h;
                    Splitting::kick(body, time, owed + 0.5 * tau, rotor, &mut m);
                    Self::free(&flow, tau, &mut rotor, &mut m);
                    offset += tau;
                    time = start + offset;
                    owed = 0.5 * tau;
                }
                // Land each step on its grid time rather than on the sum of the stages, and
                // keep the rotor unit against the rounding of the closed form's products.
                time = start + h;
                if matches!(flow, FreeFlow::Symmetric { .. }) {
                    rotor = unit(rotor);
                }
            }
            Splitting::kick(body, time, owed, rotor, &mut m);
        } else {
            // No kicks: the free flows of every stage compose exactly into one.
            Self::free(&flow, dt, &mut rotor, &mut m);
        }
        let omega = omega_from_vector(std::array::from_fn(|k| m[k] / moments[k]));
        check_finite(self.name(), State { rotor, omega })
    }
}
