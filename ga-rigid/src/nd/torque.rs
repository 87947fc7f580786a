//! Applied torques on an n-dimensional body: body-frame bivectors, constant or a function
//! of time and state.

use super::algebra::Algebra;
use super::state::State;

/// A torque on the body: the body-frame bivector `T` of Euler's equations
/// `I(dOmega/dt) - Omega x I(Omega) = T` at time `t` and state `state`.
///
/// Every `Fn(f64, &State<A>) -> A::Bivector` is one.
pub trait Torque<A: Algebra> {
    /// The body-frame torque bivector.
    fn torque(&self, t: f64, state: &State<A>) -> A::Bivector;
}

impl<A: Algebra, F: Fn(f64, &State<A>) -> A::Bivector> Torque<A> for F {
    fn torque(&self, t: f64, state: &State<A>) -> A::Bivector {
        self(t, state)
    }
}

/// A constant torque fixed in the body.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct BodyTorque<A: Algebra>(pub A::Bivector);

impl<A: Algebra> Torque<A> for BodyTorque<A> {
    fn torque(&self, _: f64, _: &State<A>) -> A::Bivector {
        self.0
    }
}

/// A constant torque fixed in space, `T_space`: in the body frame `~R T_space R`. It
/// changes the space momentum linearly, `L(t) = L(0) + t T_space`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpaceTorque<A: Algebra>(pub A::Bivector);

impl<A: Algebra> Torque<A> for SpaceTorque<A> {
    fn torque(&self, _: f64, state: &State<A>) -> A::Bivector {
        A::sandwich(A::reverse(state.rotor), self.0)
    }
}
