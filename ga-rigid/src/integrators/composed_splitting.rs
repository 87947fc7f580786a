//! High-order compositions of the DLM splitting of the free rigid body (A. Dullweber,
//! B. Leimkuhler, R. McLachlan, J. Chem. Phys. 107 (1997) 5840; see [`Splitting`]) by the
//! symmetric composition coefficients of [`Composition`] (Suzuki 1990, Kahan and Li
//! 1997): orders 4, 6 and 8 from the symmetric, symplectic second-order step, so the
//! composed methods keep `|m|`, `L` and `|R ~R| = 1` to rounding, as each axis flow does.
//! They are the stepping methods for a free body when one needs the state on a fine grid
//! anyway; where one only needs the end state, the exact flow is cheaper.
//!
//! A stage of length `tau` is `outer(tau/2) middle(tau/2) centre(tau) middle(tau/2)
//! outer(tau/2)`; without a torque, neighbouring outer half flows (of one Hamiltonian)
//! merge into one, so `s` stages cost `4 s + 1` axis flows. With a torque each stage is
//! wrapped in half kicks, and neighbouring kicks (same time, same attitude) merge. Each
//! axis flow is a rotor product, unit to rounding; the rotor is scaled back to unit norm
//! once a step so that the rounding of the 4 s + 1 products of a step (69 at order eight)
//! does not add up as a random walk over millions of steps.

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::Error;

use super::composition::Composition;
use super::integrator::{check_finite, check_step, substeps, unit, Integrator};
use super::splitting::Splitting;

/// The DLM splitting composed to order 4, 6 or 8, with fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ComposedSplitting {
    step: f64,
    order: [usize; 3],
    scheme: Composition,
}

impl ComposedSplitting {
    /// The splitting composed to `order` (2, 4, 6 or 8) with sub-steps of at most `step`
    /// (finite, positive), axes 1, 2, 3 from the outside in.
    pub fn new(step: f64, order: u32) -> Result<Self, Error> {
        Ok(ComposedSplitting {
            step: check_step(step)?,
            order: [0, 1, 2],
            scheme: Composition::of_order(order)?,
        })
    }

    /// The same with the axes composed as `[outer, middle, centre]` (0-based); an error
    /// unless `order` is a permutation of 0, 1, 2.
    pub fn with_axis_order(mut self, order: [usize; 3]) -> Result<Self, Error> {
        self.order = Splitting::new(self.step)?
            .with_axis_order(order)?
            .axis_order();
        Ok(self)
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
}

impl Integrator for ComposedSplitting {
    fn name(&self) -> &'static str {
        match self.scheme.order() {
            2 => "splitting-2",
            4 => "splitting-4",
            6 => "splitting-6",
            _ => "splitting-8",
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
        let [outer, middle, centre] = self.order;
        let flow = Splitting::axis_flow;
        if body.has_torque() {
            let mut owed = 0.0;
            let mut time = t;
            for i in 0..n {
                let start = t + i as f64 * h;
                let mut offset = 0.0;
                for g in self.scheme.gammas() {
                    let tau = g * h;
                    Splitting::kick(body, time, owed + 0.5 * tau, rotor, &mut m);
                    flow(moments, outer, 0.5 * tau, &mut rotor, &mut m);
                    flow(moments, middle, 0.5 * tau, &mut rotor, &mut m);
                    flow(moments, centre, tau, &mut rotor, &mut m);
                    flow(moments, middle, 0.5 * tau, &mut rotor, &mut m);
                    flow(moments, outer, 0.5 * tau, &mut rotor, &mut m);
                    offset += tau;
                    time = start + offset;
                    owed = 0.5 * tau;
                }
                rotor = unit(rotor);
                time = start + h;
            }
            Splitting::kick(body, time, owed, rotor, &mut m);
        } else {
            // The outer half flow still owed: the closing half of the last stage.
            let mut owed = 0.0;
            for _ in 0..n {
                for g in self.scheme.gammas() {
                    let tau = g * h;
                    flow(moments, outer, owed + 0.5 * tau, &mut rotor, &mut m);
                    flow(moments, middle, 0.5 * tau, &mut rotor, &mut m);
                    flow(moments, centre, tau, &mut rotor, &mut m);
                    flow(moments, middle, 0.5 * tau, &mut rotor, &mut m);
                    owed = 0.5 * tau;
                }
                rotor = unit(rotor);
            }
            flow(moments, outer, owed, &mut rotor, &mut m);
        }
        let omega = omega_from_vector(std::array::from_fn(|k| m[k] / moments[k]));
        check_finite(self.name(), State { rotor, omega })
    }
}
