//! The one interface the n-dimensional methods implement, and their shared loop.

use super::algebra::Algebra;
use super::body::RigidBody;
use super::state::State;
use crate::error::Error;
use crate::integrators::substeps;

/// A method that advances an n-dimensional body's [`State`] in time.
///
/// Fixed-step methods split `dt` into `ceil(|dt| / h)` equal sub-steps of at most their
/// step `h`; adaptive methods choose their own steps.
pub trait Integrator<A: Algebra> {
    /// The method's name, the same string as the 3D registry's where the method is the
    /// same (`rk4`, `lie-rk4`, `midpoint`, ...).
    fn name(&self) -> &'static str;

    /// The state at time `t + dt` from `state` at time `t`; an error if `dt` is not finite,
    /// if a step fails, or if the solution stops being finite.
    fn advance(
        &mut self,
        body: &RigidBody<A>,
        t: f64,
        state: State<A>,
        dt: f64,
    ) -> Result<State<A>, Error>;
}

/// The fixed-step loop: cover `dt` from `t` with equal sub-steps of at most `h`, each
/// taken by `step(t_i, state, h_i)`, and check that the end state is finite.
pub(crate) fn fixed_steps<A: Algebra>(
    method: &'static str,
    h: f64,
    t: f64,
    mut state: State<A>,
    dt: f64,
    mut step: impl FnMut(f64, State<A>, f64) -> Result<State<A>, Error>,
) -> Result<State<A>, Error> {
    let (n, h) = substeps(h, dt)?;
    for i in 0..n {
        state = step(t + i as f64 * h, state, h)?;
    }
    check_finite(method, state)
}

/// An error naming the method unless every component of `state` is finite.
pub(crate) fn check_finite<A: Algebra>(
    method: &'static str,
    state: State<A>,
) -> Result<State<A>, Error> {
    if state.is_finite() {
        Ok(state)
    } else {
        Err(Error::invalid(
            method,
            "the integrated state stopped being finite; take a smaller step",
        ))
    }
}

/// The rotor scaled to unit norm (the sign kept).
#[inline]
pub(crate) fn unit<A: Algebra>(rotor: A::Rotor) -> A::Rotor {
    rotor * (1.0 / A::rotor_norm(rotor))
}
