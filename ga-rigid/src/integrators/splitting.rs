//! The explicit Lie-Poisson splitting of the free rigid body: R. I. McLachlan, "Explicit
//! Lie-Poisson integration and the Euler equations", Phys. Rev. Lett. 71 (1993), and
//! A. Dullweber, B. Leimkuhler, R. McLachlan, "Symplectic splitting methods for rigid
//! body molecular dynamics", J. Chem. Phys. 107 (1997), 5840 (the "DLM" method).
//!
//! The kinetic energy splits as `H = m1^2/2i1 + m2^2/2i2 + m3^2/2i3`; the flow of one term
//! `m_k^2/2i_k` keeps `m_k`, turns the body momentum `m` about the body axis `e_k` by the
//! angle `-theta` with `theta = h m_k / i_k`, and turns the body with it:
//! `R <- R exp(-theta/2 I e_k)`. Each sub-flow is exact, so the space momentum
//! `L = R m ~R` and `|m|` are kept to rounding, `R` stays unit, and a step is stable at
//! any `h |w|` (docs/references.md: the needle case). The symmetric Strang composition
//!
//! ```text
//! outer(h/2) middle(h/2) centre(h) middle(h/2) outer(h/2)
//! ```
//!
//! is symplectic, symmetric and of order two. The axis order changes the error constant
//! by orders of magnitude (F. Fassò, "Comparison of splitting algorithms for the rigid
//! body", J. Comput. Phys. 189 (2003), 527); the default is axes 1, 2, 3 from outside in.
//! A torque enters as a half kick `m += h/2 tau` before and after the free flow (Strang
//! again); the kicks are exact, and the method of order two, when the torque does not
//! depend on `Omega`.
//!
//! [`Splitting::cayley`] ("splitting-cayley") is the same composition with each axis
//! turn written without sine and cosine, as `ga_rigid::engine`'s turns are: the turn by
//! `2 atan2(a, 1 - a^2/3)` for the half-angle `a`, whose rotor is `(1 - a^2/3) - a I e_k`
//! up to scale and whose matrix is the Cayley transform (docs/references.md derives
//! it; the engine's step is `splitting-corrected`, three such turns with corrected
//! angles). The half-angle is off by `a^5/45`, O(h^5) per turn, below the splitting's
//! O(h^3), and each turn is still the exact flow of a Hamiltonian of `m_k`, so the method
//! keeps order two, symplecticity, `|m|` to rounding and a bounded energy error, at one
//! division per turn instead of two sine-cosine pairs.

use ga_core::f64::g3::Rotor;

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::Error;

use super::integrator::{check_finite, check_step, substeps, unit, Integrator};

/// The DLM splitting with fixed step `h` and a chosen axis order.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Splitting {
    step: f64,
    order: [usize; 3],
    cayley: bool,
}

impl Splitting {
    /// The splitting with sub-steps of at most `step` (finite and positive), axes 1, 2, 3
    /// from the outside in.
    pub fn new(step: f64) -> Result<Self, Error> {
        Ok(Splitting {
            step: check_step(step)?,
            order: [0, 1, 2],
            cayley: false,
        })
    }

    /// The same splitting with rational (Cayley) axis turns: no sine or cosine.
    pub fn cayley(step: f64) -> Result<Self, Error> {
        Ok(Splitting {
            cayley: true,
            ..Self::new(step)?
        })
    }

    /// The same method with the axes (0-based: 0, 1, 2 for e1, e2, e3) composed as
    /// `[outer, middle, centre]`; an error unless `order` is a permutation of 0, 1, 2.
    pub fn with_axis_order(mut self, order: [usize; 3]) -> Result<Self, Error> {
        let mut seen = [false; 3];
        for &axis in &order {
            if axis > 2 || seen[axis] {
                return Err(Error::invalid(
                    "axis_order",
                    format!("must be a permutation of [0, 1, 2], got {order:?}"),
                ));
            }
            seen[axis] = true;
        }
        self.order = order;
        Ok(self)
    }

    /// The largest sub-step.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The axis order `[outer, middle, centre]`.
    #[must_use]
    pub fn axis_order(&self) -> [usize; 3] {
        self.order
    }

    /// The free flow of `m_k^2 / 2 i_k` for time `tau`: `m` turned about `e_k` and the
    /// rotor carried along.
    #[inline]
    pub(super) fn axis_flow(
        moments: [f64; 3],
        k: usize,
        tau: f64,
        rotor: &mut Rotor,
        m: &mut [f64; 3],
    ) {
        let theta = tau * m[k] / moments[k];
        let (a, b) = ((k + 1) % 3, (k + 2) % 3);
        let (s, c) = theta.sin_cos();
        let (ma, mb) = (m[a], m[b]);
        m[a] = c * ma + s * mb;
        m[b] = c * mb - s * ma;
        let (half_s, half_c) = (0.5 * theta).sin_cos();
        let mut axis = [0.0; 3];
        axis[k] = -half_s;
        let plane = omega_from_vector(axis);
        *rotor *= Rotor::new(half_c, plane.e12, plane.e13, plane.e23);
    }

    /// `n` steps of `h` from time `t` with the axis flow `flow`; `unit_before_kick` when
    /// `flow`'s rotor factors are not unit, so that the closing kick sees a unit rotor.
    #[allow(clippy::too_many_arguments)]
    #[inline(always)]
    fn steps(
        &self,
        body: &RigidBody,
        t: f64,
        n: u64,
        h: f64,
        rotor: &mut Rotor,
        m: &mut [f64; 3],
        flow: impl Fn([f64; 3], usize, f64, &mut Rotor, &mut [f64; 3]),
        unit_before_kick: bool,
    ) {
        let moments = body.moments();
        let [outer, middle, centre] = self.order;
        if body.has_torque() {
            for i in 0..n {
                let t0 = t + i as f64 * h;
                Self::kick(body, t0, 0.5 * h, *rotor, m);
                flow(moments, outer, 0.5 * h, rotor, m);
                flow(moments, middle, 0.5 * h, rotor, m);
                flow(moments, centre, h, rotor, m);
                flow(moments, middle, 0.5 * h, rotor, m);
                flow(moments, outer, 0.5 * h, rotor, m);
                if unit_before_kick {
                    *rotor = unit(*rotor);
                }
                Self::kick(body, t0 + h, 0.5 * h, *rotor, m);
                // Five unit factors a step, each unit to rounding: scaled back once a step
                // the rotor keeps |R ~R| = 1 to a rounding (it walked to 3.7e-13 over 10^6
                // steps on the heavy top without).
                if !unit_before_kick {
                    *rotor = unit(*rotor);
                }
            }
        } else {
            // Without kicks the outer half flows of neighbouring steps merge into one flow
            // of h (the same Hamiltonian's flow composes exactly): four flows a step.
            flow(moments, outer, 0.5 * h, rotor, m);
            for i in 0..n {
                flow(moments, middle, 0.5 * h, rotor, m);
                flow(moments, centre, h, rotor, m);
                flow(moments, middle, 0.5 * h, rotor, m);
                let tau = if i + 1 == n { 0.5 * h } else { h };
                flow(moments, outer, tau, rotor, m);
                *rotor = unit(*rotor);
            }
        }
    }

    /// The torque kick `m += tau_k * dt` at time `t`.
    #[inline]
    pub(super) fn kick(body: &RigidBody, t: f64, dt: f64, rotor: Rotor, m: &mut [f64; 3]) {
        let omega = omega_from_vector(std::array::from_fn(|k| m[k] / body.moments()[k]));
        let tau = omega_to_vector(body.torque(t, &State { rotor, omega }));
        for k in 0..3 {
            m[k] += dt * tau[k];
        }
    }
}

/// The flow of `coefficient m_k^2 / 2` for time `tau` with the rational angle: `m` turned
/// about `e_k` by `2 atan2(a, 1 - a^2/3)`, `a = tau coefficient m_k / 2` the half-angle
/// (the half-angle off by `a^5/45`), and the rotor turned with it (not normalised).
#[inline(always)]
pub(super) fn cayley_turn(
    coefficient: f64,
    k: usize,
    tau: f64,
    rotor: &mut Rotor,
    m: &mut [f64; 3],
) {
    let a = 0.5 * tau * m[k] * coefficient;
    // Beyond |a| = 64 the angle is saturated and a^2 could overflow.
    let a = a.clamp(-64.0, 64.0);
    let p = 1.0 - (a * a) * (1.0 / 3.0);
    let (p2, a2) = (p * p, a * a);
    let r = 1.0 / (p2 + a2);
    let (c, s) = ((p2 - a2) * r, 2.0 * p * a * r);
    let (ka, kb) = ((k + 1) % 3, (k + 2) % 3);
    let (ma, mb) = (m[ka], m[kb]);
    m[ka] = c * ma + s * mb;
    m[kb] = c * mb - s * ma;
    *rotor = turned_about_axis(*rotor, k, p, a);
}

/// `rotor (p - a I e_k)`, the one-plane product written out: 8 products where the full
/// rotor product takes 16 (`I e1 = e23`, `I e2 = -e13`, `I e3 = e12`).
#[inline(always)]
pub(super) fn turned_about_axis(r: Rotor, k: usize, p: f64, a: f64) -> Rotor {
    let (s, x12, x13, x23) = (r.s, r.e12, r.e13, r.e23);
    match k {
        0 => {
            let b = -a; // the e23 component
            Rotor::new(
                s * p - x23 * b,
                x12 * p - x13 * b,
                x13 * p + x12 * b,
                s * b + x23 * p,
            )
        }
        1 => {
            let b = a; // the e13 component
            Rotor::new(
                s * p - x13 * b,
                x12 * p + x23 * b,
                s * b + x13 * p,
                x23 * p - x12 * b,
            )
        }
        _ => {
            let b = -a; // the e12 component
            Rotor::new(
                s * p - x12 * b,
                s * b + x12 * p,
                x13 * p - x23 * b,
                x23 * p + x13 * b,
            )
        }
    }
}

impl Integrator for Splitting {
    fn name(&self) -> &'static str {
        if self.cayley {
            "splitting-cayley"
        } else {
            "splitting"
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
        if self.cayley {
            // The turn of `axis_flow` by the rational angle (`cayley_turn`), the inverse
            // moments taken once rather than a division a turn. Its rotor factors are not
            // unit: the torque must see a unit rotor.
            let inverse = moments.map(|i| 1.0 / i);
            let turn = |_: [f64; 3], k: usize, tau: f64, rotor: &mut Rotor, m: &mut [f64; 3]| {
                cayley_turn(inverse[k], k, tau, rotor, m);
            };
            self.steps(body, t, n, h, &mut rotor, &mut m, turn, true);
        } else {
            self.steps(body, t, n, h, &mut rotor, &mut m, Self::axis_flow, false);
        }
        let omega = omega_from_vector(std::array::from_fn(|k| m[k] / moments[k]));
        check_finite(self.name(), State { rotor, omega })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_one_plane_product_is_the_rotor_product() {
        let r = Rotor::new(0.3, -0.7, 0.2, 0.6);
        for k in 0..3 {
            let (p, a) = (0.9, 0.35);
            let mut axis = [0.0; 3];
            axis[k] = -a;
            let plane = omega_from_vector(axis);
            let full = r * Rotor::new(p, plane.e12, plane.e13, plane.e23);
            let short = turned_about_axis(r, k, p, a);
            let d = (full - short).norm();
            assert!(d <= 1e-16, "axis {k}: {full} against {short}");
        }
    }
}
