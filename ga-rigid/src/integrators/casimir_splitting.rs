//! The free body split around the Casimir `|m|^2`: with `r` the axis of the middle moment,
//!
//! ```text
//! H = |m|^2 / 2 i_r  +  c_o m_o^2 / 2  +  c_c m_c^2 / 2,   c_k = 1/i_k - 1/i_r,
//! ```
//!
//! `o` and `c` the other two axes (outer: the largest moment, centre: the smallest).
//! `|m|^2` Poisson-commutes with every function of the body momentum, so its flow (the
//! body turning about its own momentum by `h |m| / i_r`, `m` unchanged) commutes with the
//! other two, and one step is that turn times the symmetric sequence
//! `o(h/2) c(h) o(h/2)`: symplectic, symmetric, order two, `|m|` kept to rounding (every
//! turn is orthogonal). McLachlan ("Explicit Lie-Poisson integration and the Euler
//! equations", Phys. Rev. Lett. 71, 1993) and Fassò ("Comparison of splitting algorithms
//! for the rigid body", J. Comput. Phys. 189, 2003) discuss this split: the non-commuting
//! parts `c_o`, `c_c` are differences of inverse moments, small where the body is near
//! symmetric, and the split is exact for a symmetric body (one `c` vanishes). Against the
//! five-turn DLM splitting on the report's T-handle (moments 3 : 5 : 9) at `h |w| = 0.5`,
//! its flip period is many times closer to the exact one and its energy error of the same
//! order, bounded in both (BENCHMARKS.md, "Library methods at engine step sizes", has the
//! figures; the report's engine table measures them again).
//!
//! Every turn is rational (`splitting::cayley_turn`: no sine or cosine, one division per
//! axis turn, none for the Casimir turn) and the rotor is normalised once a step. A
//! torque enters as Strang half-kicks around the free step, as in [`Splitting`].
//!
//! [`Splitting`]: super::Splitting

use ga_core::f64::g3::Rotor;

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::Error;

use super::integrator::{check_finite, check_step, substeps, unit, Integrator};
use super::splitting::{cayley_turn, Splitting};

/// The Casimir splitting with fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CasimirSplitting {
    step: f64,
}

impl CasimirSplitting {
    /// The splitting with sub-steps of at most `step` (finite and positive).
    pub fn new(step: f64) -> Result<Self, Error> {
        Ok(CasimirSplitting {
            step: check_step(step)?,
        })
    }

    /// The largest sub-step.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.step
    }
}

/// The axes `[r, o, c]`: the middle moment's, the largest's, the smallest's (ties by
/// index, so a symmetric body gets its odd axis as `o` or `c`).
fn axes(moments: [f64; 3]) -> [usize; 3] {
    let mut by_size = [0, 1, 2];
    by_size.sort_by(|&a, &b| moments[a].total_cmp(&moments[b]));
    let [smallest, middle, largest] = by_size;
    [middle, largest, smallest]
}

/// The Casimir's flow for time `tau`: the rotor turned about the body momentum by
/// `2 atan2(a, 1 - a^2/3)`, `a = tau |m| / 2 i_r` (the rational angle of
/// `splitting::cayley_turn`), not normalised; `m` does not change.
#[inline(always)]
pub(super) fn casimir_turn(inverse_middle: f64, tau: f64, rotor: &mut Rotor, m: &[f64; 3]) {
    let mut k = 0.5 * tau * inverse_middle;
    let mut a2 = (k * k) * (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    // Beyond a = 64 the angle is saturated and a^2 could overflow (or be NaN).
    if a2.is_nan() || a2 > 4096.0 {
        let scale = 64.0 / a2.sqrt();
        k = if scale < 1.0 { k * scale } else { 0.0 };
        a2 = 4096.0;
    }
    let p = 1.0 - a2 * (1.0 / 3.0);
    let plane = omega_from_vector([-k * m[0], -k * m[1], -k * m[2]]);
    *rotor *= Rotor::new(p, plane.e12, plane.e13, plane.e23);
}

impl Integrator for CasimirSplitting {
    fn name(&self) -> &'static str {
        "splitting-casimir"
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        let (n, h) = substeps(self.step, dt)?;
        if n == 0 {
            return check_finite(self.name(), state);
        }
        let moments = body.moments();
        let [r, o, c] = axes(moments);
        let inverse_middle = 1.0 / moments[r];
        let (c_o, c_c) = (
            1.0 / moments[o] - inverse_middle,
            1.0 / moments[c] - inverse_middle,
        );
        let w = omega_to_vector(state.omega);
        let mut m: [f64; 3] = std::array::from_fn(|k| moments[k] * w[k]);
        let mut rotor = state.rotor;
        if body.has_torque() {
            for i in 0..n {
                let t0 = t + i as f64 * h;
                Splitting::kick(body, t0, 0.5 * h, rotor, &mut m);
                cayley_turn(c_o, o, 0.5 * h, &mut rotor, &mut m);
                cayley_turn(c_c, c, h, &mut rotor, &mut m);
                cayley_turn(c_o, o, 0.5 * h, &mut rotor, &mut m);
                casimir_turn(inverse_middle, h, &mut rotor, &m);
                // The torque must see a unit rotor.
                rotor = unit(rotor);
                Splitting::kick(body, t0 + h, 0.5 * h, rotor, &mut m);
            }
        } else {
            // Without kicks the outer half turns of neighbouring steps merge into one
            // turn of h (the Casimir's turn commutes with them): two axis turns a step.
            cayley_turn(c_o, o, 0.5 * h, &mut rotor, &mut m);
            for i in 0..n {
                cayley_turn(c_c, c, h, &mut rotor, &mut m);
                let tau = if i + 1 == n { 0.5 * h } else { h };
                cayley_turn(c_o, o, tau, &mut rotor, &mut m);
                casimir_turn(inverse_middle, h, &mut rotor, &m);
                rotor = unit(rotor);
            }
        }
        let omega = omega_from_vector(std::array::from_fn(|k| m[k] / moments[k]));
        check_finite(self.name(), State { rotor, omega })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_reference_is_the_middle_moment() {
        assert_eq!(axes([3.0, 5.0, 9.0]), [1, 2, 0]);
        assert_eq!(axes([9.0, 3.0, 5.0]), [2, 0, 1]);
        // A symmetric body: the reference and one other axis share the moment, so that
        // axis's c vanishes and the odd axis (here the smallest, centre) carries the rest.
        assert_eq!(axes([2.0, 2.0, 1.0]), [0, 1, 2]);
        assert_eq!(axes([1.0, 3.0, 3.0]), [1, 2, 0]);
    }
}
