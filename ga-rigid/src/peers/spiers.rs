//! Spiers's gyroscopic step: B. Spiers, "A better way to spin" (blog article,
//! <https://benspiers.co.uk/Physics/A-better-way-to-spin>), proposed for avian in its pull
//! request #993 ("Implement new gyro motion integration method", 2026-06) to replace the
//! Jolt-style `solve_gyroscopic_torque`. Written here from the article's equations.
//!
//! With `J` the inverse inertia, `l` the angular momentum and `w = J l`, the free body's
//! momentum turns in the body as `dl/dt = -w x l`. Since `l x l = 0`, the same rate follows
//! from turning `l` about `Omega = w - J' l` for any scalar `J'`; the article picks
//! `J' = k.Jk / k.k` with `k = w x l`, the one for which the energy's second time derivative
//! along the turn vanishes (its energy error per step is of third order). On a body with
//! two equal moments `J'` is the repeated one and `Omega` the body's spin about its
//! symmetry axis, so the turn is the exact flow of the body momentum, and the precession
//! `J' L` about the fixed `L` completes the exact symmetric top.
//!
//! The article recommends two forms, both here:
//!
//! - `spiers-velocity`, its "modified Jolt method", the one the pull request puts in
//!   place of the Jolt-style velocity update: `l0 = I w0 + h tau`, `k = w0 x l0`,
//!   `Omega = w0 - J' l0`, `l1 = Q(-h Omega) l0`, `w1 = J l1`, then the engine's usual
//!   orientation update `R1 = Q(h w1) R0` (avian's `from_scaled_axis`, an exact turn). The
//!   body momentum follows the turn above; the attitude takes one turn by the new rate.
//! - `spiers-momentum`, its "momentum-first method": `l' = l0 + h tau`, `w' = J l'`,
//!   `R1 = Q(h J' L') Q(h Omega) R0` in the space frame (here on the right, in the body:
//!   `R1 = R0 exp(-h/2 I J' l') exp(-h/2 I Omega)`), the space momentum untouched by the
//!   turns.
//!
//! Every turn is an exact rotation (Rodrigues' formula, the article's `Q`), not the
//! article's optional rational approximation, which would not be exact for the symmetric
//! top. Where `k = 0` (`l` along a principal axis, or a sphere) the split does not matter,
//! and `J' = 0` is taken. Both forms take the torque's impulse by an explicit Euler step.

use ga_core::f64::g3::{Bivector, Rotor, Sandwich};

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::Error;
use crate::integrators::{check_step, fixed_steps, Integrator};

use super::buss::cross;

/// Which of the article's two recommended forms.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SpiersForm {
    /// The "modified Jolt method": a velocity update, then `R1 = Q(h w1) R0` (avian's pull
    /// request #993).
    Velocity,
    /// The "momentum-first method": the turn split into a precession about `L` and a spin.
    Momentum,
}

/// Spiers's gyroscopic step in one of its two forms, fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Spiers {
    step: f64,
    form: SpiersForm,
}

impl Spiers {
    /// The method in form `form` with fixed step `h` (finite and positive).
    pub fn new(h: f64, form: SpiersForm) -> Result<Self, Error> {
        Ok(Self {
            step: check_step(h)?,
            form,
        })
    }
}

/// `J' = k.Jk / k.k`, the inverse inertia along `k` (`inverse` the principal inverse
/// moments), computed on `k` scaled to a largest component of 1 so that neither square
/// overflows nor underflows; 0 where `k` is zero (or not finite), where any value gives the
/// same step.
fn inverse_inertia_along(k: [f64; 3], inverse: [f64; 3]) -> f64 {
    let largest = k.iter().fold(0.0f64, |a, x| a.max(x.abs()));
    if !(largest > 0.0 && largest.is_finite()) {
        return 0.0;
    }
    let u = k.map(|x| x / largest);
    let norm2 = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
    (u[0] * u[0] * inverse[0] + u[1] * u[1] * inverse[1] + u[2] * u[2] * inverse[2]) / norm2
}

/// One step of `form` from `state` at time `t`.
pub(crate) fn spiers_step(
    body: &RigidBody,
    t: f64,
    state: State,
    h: f64,
    form: SpiersForm,
) -> State {
    let inverse = body.moments().map(|i| 1.0 / i);
    // Both forms add the torque's impulse to the body momentum first.
    let m = body.body_momentum(state.omega) + body.torque(t, &state) * h;
    let l = omega_to_vector(m);
    // The velocity form crosses the old rate with the kicked momentum, as the article
    // writes it (`k = w0 x L0`, `Omega = w0 - J' L0`); the momentum form the kicked rate.
    let w = match form {
        SpiersForm::Velocity => omega_to_vector(state.omega),
        SpiersForm::Momentum => std::array::from_fn(|i| l[i] * inverse[i]),
    };
    let j = inverse_inertia_along(cross(w, l), inverse);
    let spin: [f64; 3] = std::array::from_fn(|i| w[i] - j * l[i]);
    // `Q(-h Omega)` as a rotor: `Q(phi)` is `exp(-1/2 I phi)`.
    let back = (omega_from_vector(spin) * (0.5 * h)).exp();
    let m1 = back.sandwich(m);
    let omega1 = body.omega_for_momentum(m1);
    let rotor = match form {
        SpiersForm::Velocity => state.rotor * (omega1 * (-0.5 * h)).exp(),
        // R0 Q(h J' l') Q(h Omega): the precession about `l'` leaves `m` as it is, the spin
        // turns it to `m1`, and `R1 m1 ~R1 = R0 m ~R0`.
        SpiersForm::Momentum => state.rotor * precession(m, j, h) * back.reverse(),
    };
    State {
        rotor,
        omega: omega1,
    }
}

/// `Q(h J' l)` as a rotor, for the body momentum bivector `m = I l`.
fn precession(m: Bivector, j: f64, h: f64) -> Rotor {
    (m * (-0.5 * h * j)).exp()
}

impl Integrator for Spiers {
    fn name(&self) -> &'static str {
        match self.form {
            SpiersForm::Velocity => "spiers-velocity",
            SpiersForm::Momentum => "spiers-momentum",
        }
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        let form = self.form;
        fixed_steps(self.name(), self.step, t, state, dt, |t, s, h| {
            Ok(spiers_step(body, t, s, h, form))
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `J'` is a Rayleigh quotient: the moment's inverse on a principal axis, the repeated
    /// one for any `k` in the plane of two equal moments, between the extremes otherwise,
    /// and the same for `k` scaled by `1e-200` or `1e200`.
    #[test]
    fn the_inverse_inertia_along_k_is_a_rayleigh_quotient() {
        let inverse = [0.5, 0.25, 0.125];
        assert_eq!(inverse_inertia_along([0.0, 3.0, 0.0], inverse), 0.25);
        assert_eq!(inverse_inertia_along([0.0; 3], inverse), 0.0);
        let k = [0.3, -1.2, 0.7];
        let j = inverse_inertia_along(k, inverse);
        let direct = (0.09 * 0.5 + 1.44 * 0.25 + 0.49 * 0.125) / (0.09 + 1.44 + 0.49);
        assert!((j - direct).abs() < 1e-15, "{j} {direct}");
        for s in [1e-200, 1e200] {
            let scaled = inverse_inertia_along(k.map(|x| x * s), inverse);
            assert!((scaled - j).abs() < 1e-15, "{s}: {scaled}");
        }
        let plane = inverse_inertia_along([0.6, -0.8, 0.0], [0.5, 0.5, 0.1]);
        assert!((plane - 0.5).abs() < 1e-15);
    }
}
