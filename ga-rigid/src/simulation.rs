//! A trajectory without a hand-written time loop: a body, a state and an integrator, run
//! to an end time with evenly spaced samples.
//!
//! ```
//! use ga_core::f64::g3::{Bivector, Rotor};
//! use ga_rigid::dynamics::{RigidBody, State};
//! use ga_rigid::integrators::Rk4;
//! use ga_rigid::simulation::Simulation;
//!
//! let body = RigidBody::new([1.0, 2.0, 2.5])?;
//! let state = State { rotor: Rotor::ONE, omega: Bivector::new(0.2, -1.0, 0.1) };
//! let mut simulation = Simulation::new(body, state, Rk4::new(0.01)?);
//! let samples = simulation.run_until(10.0, 11)?;
//! assert_eq!(samples.len(), 11);
//! assert_eq!(samples[10].t, 10.0);
//! let drift = (samples[10].energy - samples[0].energy).abs();
//! assert!(drift < 1e-8 * samples[0].energy);
//! # Ok::<(), ga_rigid::error::Error>(())
//! ```

use ga_core::f64::g3::Bivector;

use crate::dynamics::{RigidBody, State};
use crate::error::{num, Error};
use crate::integrators::Integrator;

/// One sample of a trajectory, every number in it finite.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sample {
    /// The time.
    pub t: f64,
    /// The state at `t`.
    pub state: State,
    /// The total energy (kinetic plus the torque's potential).
    pub energy: f64,
    /// The angular momentum in the space frame, `L = R I(Omega_B) ~R`.
    pub momentum: Bivector,
}

/// A body, its current state and time, and the integrator that advances them.
#[derive(Debug)]
pub struct Simulation<I> {
    body: RigidBody,
    state: State,
    t: f64,
    integrator: I,
}

impl<I: Integrator> Simulation<I> {
    /// A simulation starting at time 0 from `state`.
    #[must_use]
    pub fn new(body: RigidBody, state: State, integrator: I) -> Self {
        Simulation {
            body,
            state,
            t: 0.0,
            integrator,
        }
    }

    /// The body.
    #[must_use]
    pub fn body(&self) -> &RigidBody {
        &self.body
    }

    /// The current time.
    #[must_use]
    pub fn time(&self) -> f64 {
        self.t
    }

    /// The current state.
    #[must_use]
    pub fn state(&self) -> State {
        self.state
    }

    /// The current sample: time, state, energy and momentum; an error naming the
    /// integrator if any of them is not finite.
    pub fn sample(&self) -> Result<Sample, Error> {
        let sample = Sample {
            t: self.t,
            state: self.state,
            energy: self.body.total_energy(self.t, &self.state),
            momentum: self.body.space_momentum(&self.state),
        };
        let s = &sample.state;
        let numbers = [
            ("the rotor", s.rotor.s),
            ("the rotor", s.rotor.e12),
            ("the rotor", s.rotor.e13),
            ("the rotor", s.rotor.e23),
            ("the angular velocity", s.omega.e12),
            ("the angular velocity", s.omega.e13),
            ("the angular velocity", s.omega.e23),
            ("the energy", sample.energy),
            ("the angular momentum", sample.momentum.e12),
            ("the angular momentum", sample.momentum.e13),
            ("the angular momentum", sample.momentum.e23),
        ];
        match numbers.iter().find(|(_, x)| !x.is_finite()) {
            None => Ok(sample),
            Some((what, x)) => Err(Error::invalid(
                self.integrator.name(),
                format!(
                    "{what} is not finite ({x}) at t = {}: the numbers are too large for this \
                     method",
                    num(self.t)
                ),
            )),
        }
    }

    /// Advance to time `t` and return the sample there.
    pub fn advance_to(&mut self, t: f64) -> Result<Sample, Error> {
        self.state = self
            .integrator
            .advance(&self.body, self.t, self.state, t - self.t)?;
        self.t = t;
        self.sample()
    }

    /// The samples at `samples` evenly spaced times from now to `t_end` inclusive (the
    /// first is the current state, the last exactly `t_end`), computed as the iterator is
    /// consumed; after an error it yields nothing more.
    pub fn samples(&mut self, t_end: f64, samples: usize) -> Samples<'_, I> {
        Samples {
            start: self.t,
            t_end,
            count: samples,
            next: 0,
            failed: false,
            simulation: self,
        }
    }

    /// All the samples of [`Simulation::samples`], or the first error. `t_end` must be
    /// finite and `samples` at least 2.
    pub fn run_until(&mut self, t_end: f64, samples: usize) -> Result<Vec<Sample>, Error> {
        self.samples(t_end, samples).collect()
    }
}

/// The iterator of [`Simulation::samples`].
#[derive(Debug)]
pub struct Samples<'a, I> {
    simulation: &'a mut Simulation<I>,
    start: f64,
    t_end: f64,
    count: usize,
    next: usize,
    failed: bool,
}

impl<I: Integrator> Iterator for Samples<'_, I> {
    type Item = Result<Sample, Error>;

    fn next(&mut self) -> Option<Self::Item> {
        if self.failed || self.next >= self.count {
            return None;
        }
        if self.next == 0 && (self.count < 2 || !self.t_end.is_finite()) {
            self.failed = true;
            return Some(Err(Error::invalid(
                "samples",
                format!(
                    "a run needs a finite end time and at least 2 samples, got t_end = {} \
                     and {} samples",
                    num(self.t_end),
                    self.count
                ),
            )));
        }
        let k = self.next;
        self.next += 1;
        let last = self.count - 1;
        let result = if k == 0 {
            self.simulation.sample()
        } else {
            let t = if k == last {
                self.t_end
            } else {
                let span = self.t_end - self.start;
                // Near f64::MAX `span * k` overflows: then the fraction first (the usual
                // order otherwise, so that ordinary sample times keep their last bit).
                let scaled = span * k as f64;
                if scaled.is_finite() {
                    self.start + scaled / last as f64
                } else {
                    self.start + span * (k as f64 / last as f64)
                }
            };
            self.simulation.advance_to(t)
        };
        self.failed = result.is_err();
        Some(result)
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = if self.failed {
            0
        } else {
            self.count.saturating_sub(self.next)
        };
        (0, Some(left))
    }
}

/// A boxed integrator is an integrator, so that a method chosen at run time (the command's
/// `--method`) can drive a [`Simulation`].
impl<T: Integrator + ?Sized> Integrator for Box<T> {
    fn name(&self) -> &'static str {
        (**self).name()
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        (**self).advance(body, t, state, dt)
    }

    fn accepted_steps(&self) -> Option<u64> {
        (**self).accepted_steps()
    }

    fn limit_steps(&mut self, max_steps: u64) {
        (**self).limit_steps(max_steps);
    }

    fn advance_to_each(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: State,
        times: &[f64],
    ) -> Result<Vec<State>, Error> {
        (**self).advance_to_each(body, t, state, times)
    }
}
