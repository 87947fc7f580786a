//! The implicit midpoint rule (Hairer, Lubich, Wanner, *Geometric Numerical Integration*,
//! 2nd ed., Springer 2006, sections II.1 and IV.2; for the rigid body, section VII.5) on
//! `(R, Omega_B)` as a point of R^4 x R^3:
//!
//! ```text
//! y1 = y0 + h f(t + h/2, (y0 + y1)/2)
//! ```
//!
//! Symplectic and symmetric, of order two, and it keeps every quadratic invariant: the
//! energy, `|m|` and `|R|` of the free body to the accuracy of the solve. The rotor part
//! has a closed form given the midpoint angular velocity `Z`: the Cayley transform
//! `R1 = R0 (1 - hZ/4)(1 + hZ/4)^-1`, a unit rotor. What remains is three equations for
//! `Z`, solved by Newton's method with the exact Jacobian of the gyroscopic term
//! `J^-1 ((J z) x z)`; a torque enters the residual but not the Jacobian (a quasi-Newton
//! iteration, fixed-point in the torque). Newton, unlike a plain fixed-point iteration,
//! does not stop converging near `h |w| ~ 1` (docs/references.md: fixed point diverges at 1.9);
//! it converges on the needle at `h |w| = 16.7` and on near-symmetric bodies far beyond.
//! For a strongly asymmetric body at `h |w|` of some tens the midpoint equation can have
//! no solution near `Omega(t)` (the residual has a local minimum instead of a root): the
//! step then fails with an error rather than returning a wrong state.

use ga_core::f64::g3::{Bivector, Rotor};
use ga_core::glam::{DMat3, DVec3};

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::Error;

use super::integrator::{check_step, fixed_steps, unit, Integrator};

/// The most Newton iterations per step before the step is reported as failed.
const MAX_ITERATIONS: usize = 50;

/// The implicit midpoint rule with fixed step `h`, solved by Newton's method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImplicitMidpoint {
    step: f64,
    iterations: u64,
}

impl ImplicitMidpoint {
    /// The midpoint rule with sub-steps of at most `step` (finite and positive).
    pub fn new(step: f64) -> Result<Self, Error> {
        Ok(ImplicitMidpoint {
            step: check_step(step)?,
            iterations: 0,
        })
    }

    /// The largest sub-step.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The Newton iterations taken so far, over every step.
    #[must_use]
    pub fn iterations(&self) -> u64 {
        self.iterations
    }

    /// One midpoint step of length `h` from `state` at time `t`, and the Newton iterations
    /// it took; an error if Newton's method does not converge.
    pub fn step_once(
        body: &RigidBody,
        t: f64,
        state: State,
        h: f64,
    ) -> Result<(State, usize), Error> {
        let omega0 = state.omega;
        let t_mid = t + 0.5 * h;
        let residual = |z: Bivector| {
            let mid = State {
                rotor: (state.rotor + cayley_step(state.rotor, z, h)) * 0.5,
                omega: z,
            };
            z - omega0 - body.omega_rate(t_mid, &mid) * (0.5 * h)
        };
        let mut z = omega0;
        let mut previous = f64::INFINITY;
        for iteration in 1..=MAX_ITERATIONS {
            let delta = newton_correction(body.moments(), z, h, residual(z));
            z -= delta;
            let size = delta.norm();
            let scale = z.norm();
            // Converged to rounding, or stagnated at the rounding floor of the residual.
            if size <= 4.0 * f64::EPSILON * scale
                || (size >= previous && size <= 1e-10 * scale)
                || scale == 0.0
            {
                // The Cayley factor is unit to rounding, which walks over many steps
                // (9.5e-13 over 10^6 steps on the heavy top): scale back once a step.
                let rotor1 = unit(cayley_step(state.rotor, z, h));
                let omega1 = z * 2.0 - omega0;
                return Ok((
                    State {
                        rotor: rotor1,
                        omega: omega1,
                    },
                    iteration,
                ));
            }
            if !size.is_finite() {
                break;
            }
            previous = size;
        }
        Err(Error::invalid(
            "midpoint",
            format!(
                "Newton's method found no midpoint in {MAX_ITERATIONS} iterations at t = {} \
                 with step {} (h |w| = {}); take a smaller step",
                crate::error::num(t),
                crate::error::num(h),
                crate::error::num(h.abs() * omega0.norm())
            ),
        ))
    }
}

/// `R0 (1 - B)(1 + B)^-1` with `B = h Z / 4`: as `B^2 = -|B|^2`, this is
/// `R0 ((1 - |B|^2) - 2 B) / (1 + |B|^2)`, a unit rotor when `R0` is one.
#[inline]
fn cayley_step(rotor0: Rotor, z: Bivector, h: f64) -> Rotor {
    let b = z * (0.25 * h);
    let b2 = b.e12 * b.e12 + b.e13 * b.e13 + b.e23 * b.e23;
    let cayley = Rotor::new(1.0 - b2, -2.0 * b.e12, -2.0 * b.e13, -2.0 * b.e23) / (1.0 + b2);
    rotor0 * cayley
}

/// Solve `(1 - h/2 D) delta = residual` for the Newton correction, with `D` the Jacobian of
/// `w -> J^-1 ((J w) x w)` at `z`, in the vector components `w = [w1, w2, w3]`.
#[inline]
fn newton_correction(moments: [f64; 3], z: Bivector, h: f64, residual: Bivector) -> Bivector {
    let w = omega_to_vector(z);
    let m = [moments[0] * w[0], moments[1] * w[1], moments[2] * w[2]];
    // d(m x w) = [m]x dw - [w]x J dw, row r scaled by 1/i_r.
    let cross = |a: [f64; 3]| [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]];
    let (cm, cw) = (cross(m), cross(w));
    let mut a = [[0.0; 3]; 3];
    for r in 0..3 {
        for c in 0..3 {
            let d = (cm[r][c] - cw[r][c] * moments[c]) / moments[r];
            a[r][c] = f64::from(u8::from(r == c)) - 0.5 * h * d;
        }
    }
    omega_from_vector(solve3(a, omega_to_vector(residual)))
}

/// `A^-1 b` for a row-major `A` (the 3x3 systems here are well conditioned: `1 - h/2 D`
/// with `D` a gyroscopic, nearly skew, matrix).
#[inline]
fn solve3(a: [[f64; 3]; 3], b: [f64; 3]) -> [f64; 3] {
    // glam is column-major: the rows of `a` are the columns of its transpose.
    let a = DMat3::from_cols_array_2d(&a).transpose();
    (a.inverse() * DVec3::from_array(b)).to_array()
}

impl Integrator for ImplicitMidpoint {
    fn name(&self) -> &'static str {
        "midpoint"
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        let iterations = &mut self.iterations;
        fixed_steps("midpoint", self.step, t, state, dt, |t, state, h| {
            let (next, taken) = Self::step_once(body, t, state, h)?;
            *iterations += taken as u64;
            Ok(next)
        })
    }
}
