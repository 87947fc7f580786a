//! The one interface every method implements, and the checks they share.

use ga_core::f64::g3::{Bivector, Rotor};

use crate::dynamics::{RigidBody, State};
use crate::error::{self, Error};

/// A method that advances a rigid body's [`State`] in time.
///
/// Fixed-step methods split `dt` into `ceil(|dt| / h)` equal sub-steps of at most their
/// step `h`; adaptive methods choose their own steps. A step allocates nothing.
pub trait Integrator {
    /// A short lowercase name for tables and scene files (`rk4`, `splitting`, ...).
    fn name(&self) -> &'static str;

    /// The state at time `t + dt` from `state` at time `t`. `dt` may be zero (the state
    /// comes back unchanged) or negative where the method supports it; an error if `dt` is
    /// not finite, if the method cannot treat this body, or if the solution stops being
    /// finite.
    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error>;

    /// The steps accepted so far by a method that chooses its own steps; `None` for
    /// methods whose steps follow from their step size (or that take none). The report
    /// reads its step counts here, so that what it counts is what the named method did.
    fn accepted_steps(&self) -> Option<u64> {
        None
    }

    /// Bound the steps (accepted and rejected, over every later call) of a method that
    /// chooses its own steps: the run's limit ([`crate::limits::Limits::max_steps`]), which
    /// replaces the method's own bound per call. A method that reaches it stops with an
    /// error naming `max_steps`. Methods whose steps follow from their step size ignore it:
    /// [`crate::limits::check_work`] counts their steps before they start.
    fn limit_steps(&mut self, _max_steps: u64) {}

    /// The states at each of `times` (in order, in the direction of travel from `t`),
    /// starting from `state` at `t`. By default one [`Integrator::advance`] to each time;
    /// adaptive methods with a continuous extension override it so that the sample times
    /// do not cut their steps, as a user asking for dense output would run them (the
    /// report measures every method through this call).
    fn advance_to_each(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: State,
        times: &[f64],
    ) -> Result<Vec<State>, Error> {
        let mut out = Vec::with_capacity(times.len());
        let (mut t, mut state) = (t, state);
        for &ti in times {
            state = self.advance(body, t, state, ti - t)?;
            t = ti;
            out.push(state);
        }
        Ok(out)
    }
}

/// The Euclidean norm `sqrt(sum x_i^2)` taken with scaling by the largest entry, so that
/// it stays finite where the squares would overflow (entries above about 1e154), for the
/// adaptive methods' first step when `|w|` is near 1e80 and its rate near 1e160.
pub(crate) fn scaled_norm(x: &[f64]) -> f64 {
    let m = x.iter().fold(0.0_f64, |m, v| m.max(v.abs()));
    if m == 0.0 || !m.is_finite() {
        return m;
    }
    m * x.iter().map(|v| (v / m) * (v / m)).sum::<f64>().sqrt()
}

/// The error of an adaptive method that reached the run's step limit
/// ([`Integrator::limit_steps`]) at `t` on its way to `t_end`.
pub(crate) fn step_limit_reached(method: &str, limit: u64, t: f64, t_end: f64) -> Error {
    Error::invalid(
        "max_steps",
        format!(
            "{method} needs more than {limit} steps (accepted and rejected) to reach t = {}: \
             stopped at t = {}; raise the limit with max_steps or loosen tol",
            error::num(t_end),
            error::num(t)
        ),
    )
}

/// Check a method's step size: finite and positive.
pub(crate) fn check_step(h: f64) -> Result<f64, Error> {
    error::positive("step", "step", h)
}

/// The number of equal sub-steps of at most `h` that cover `dt`, and their signed length.
pub(crate) fn substeps(h: f64, dt: f64) -> Result<(u64, f64), Error> {
    error::finite("dt", "time step", dt)?;
    if dt == 0.0 {
        return Ok((0, 0.0));
    }
    let n = (dt.abs() / h).ceil().max(1.0);
    if n > u64::MAX as f64 {
        return Err(Error::invalid(
            "dt",
            format!(
                "{} needs more than 2^64 sub-steps of {}",
                error::num(dt),
                error::num(h)
            ),
        ));
    }
    // `as` saturates and `n` is a positive whole number below 2^64 here.
    Ok((n as u64, dt / n))
}

/// The one fixed-step loop: cover `dt` from `t` with equal sub-steps of at most `h`,
/// each taken by `step(t_i, state, h_i)`, and check the end state is finite.
#[inline]
pub(crate) fn fixed_steps(
    method: &'static str,
    h: f64,
    t: f64,
    mut state: State,
    dt: f64,
    mut step: impl FnMut(f64, State, f64) -> Result<State, Error>,
) -> Result<State, Error> {
    let (n, h) = substeps(h, dt)?;
    for i in 0..n {
        state = step(t + i as f64 * h, state, h)?;
    }
    check_finite(method, state)
}

/// An error naming the method unless every component of `state` is finite.
pub(crate) fn check_finite(method: &'static str, state: State) -> Result<State, Error> {
    let Rotor { s, e12, e13, e23 } = state.rotor;
    let Bivector {
        e12: o12,
        e13: o13,
        e23: o23,
    } = state.omega;
    for value in [s, e12, e13, e23, o12, o13, o23] {
        if !value.is_finite() {
            return Err(Error::NotFinite {
                field: method.to_string(),
                what: "the integrated state",
                value,
            });
        }
    }
    Ok(state)
}

/// The rotor scaled to unit norm (the sign kept).
#[inline]
#[must_use]
pub(crate) fn unit(rotor: Rotor) -> Rotor {
    rotor / rotor.norm()
}
