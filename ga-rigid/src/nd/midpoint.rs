//! The implicit midpoint rule (Hairer, Lubich, Wanner, *Geometric Numerical Integration*,
//! 2nd ed., Springer 2006, sections II.1, IV.2 and VII.5) on `(R, Omega_B)`, written over
//! the algebra:
//!
//! ```text
//! y1 = y0 + h f(t + h/2, (y0 + y1)/2)
//! ```
//!
//! Symmetric, of order two, and it keeps every quadratic invariant of the free body: the
//! energy, `<M ~M>` (and in G4 the pseudoscalar part of `M M`) to the accuracy of the
//! solve. Given the midpoint angular velocity `Z` the rotor part is linear, with the
//! solution the Cayley transform `R1 = R0 (1 - hZ/4)(1 + hZ/4)^-1` (a unit rotor also in
//! G4, where `1 - B^2` is a scalar plus a pseudoscalar; see `Algebra::cayley`). `Z` solves
//! `Z = Omega_0 + h/2 I^-1(Z x I(Z) + T)` by Newton's method, with the exact Jacobian of
//! the gyroscopic term (bilinear, so built from its action on the basis planes); a torque
//! enters the residual but not the Jacobian.

// The matrix kernels index rows and columns by name, as the formulas they transcribe do.
#![allow(clippy::needless_range_loop)]

use super::algebra::Algebra;
use super::body::RigidBody;
use super::integrator::{fixed_steps, unit, Integrator};
use super::state::State;
use crate::error::{self, Error};
use crate::integrators::check_step;

/// The most Newton iterations per step before the step is reported as failed.
const MAX_ITERATIONS: usize = 50;

/// The most planes (G4's six).
const MAX_PLANES: usize = 6;

/// The implicit midpoint rule with fixed step, solved by Newton's method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImplicitMidpoint {
    step: f64,
}

impl ImplicitMidpoint {
    /// The midpoint rule with sub-steps of at most `step` (finite and positive).
    pub fn new(step: f64) -> Result<Self, Error> {
        Ok(ImplicitMidpoint {
            step: check_step(step)?,
        })
    }

    /// One midpoint step of length `h` from `state` at time `t`; an error if Newton's
    /// method does not converge.
    pub fn step_once<A: Algebra>(
        body: &RigidBody<A>,
        t: f64,
        state: State<A>,
        h: f64,
    ) -> Result<State<A>, Error> {
        let p = A::PLANES.len();
        let omega0 = state.omega;
        let t_mid = t + 0.5 * h;
        let rotor_at = |z: A::Bivector| state.rotor * A::cayley(z * (0.25 * h));
        let residual = |z: A::Bivector| {
            let mid = State {
                rotor: (state.rotor + rotor_at(z)) * 0.5,
                omega: z,
            };
            z - omega0 - body.omega_rate(t_mid, &mid) * (0.5 * h)
        };
        let mut z = omega0;
        let mut previous = f64::INFINITY;
        for _ in 0..MAX_ITERATIONS {
            let r = residual(z);
            let mut jacobian = [[0.0; MAX_PLANES]; MAX_PLANES];
            let mz = body.inertia(z);
            for c in 0..p {
                let mut d = A::Bivector::default();
                d[c] = 1.0;
                // d/dz I^-1(z x I z) along d = I^-1(d x I z + z x I d).
                let column =
                    body.inertia_inverse(A::commutator(d, mz) + A::commutator(z, body.inertia(d)));
                for (row, slot) in jacobian.iter_mut().enumerate().take(p) {
                    slot[c] = f64::from(u8::from(row == c)) - 0.5 * h * column[row];
                }
            }
            let mut rhs = [0.0; MAX_PLANES];
            for (k, slot) in rhs.iter_mut().enumerate().take(p) {
                *slot = r[k];
            }
            let delta = solve(jacobian, rhs, p);
            let mut size = 0.0;
            let mut scale = 0.0;
            for (k, dk) in delta.iter().enumerate().take(p) {
                z[k] -= dk;
                size += dk * dk;
                scale += z[k] * z[k];
            }
            let (size, scale) = (size.sqrt(), scale.sqrt());
            if size <= 4.0 * f64::EPSILON * scale
                || (size >= previous && size <= 1e-10 * scale)
                || scale == 0.0
            {
                return Ok(State {
                    rotor: unit::<A>(rotor_at(z)),
                    omega: z * 2.0 - omega0,
                });
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
                 with step {}; take a smaller step",
                error::num(t),
                error::num(h)
            ),
        ))
    }
}

/// `A^-1 b` for the leading `n x n` block, by Gaussian elimination with partial pivoting
/// (`1 - h/2 D` with `D` gyroscopic is well conditioned at the steps this method takes).
fn solve(
    mut a: [[f64; MAX_PLANES]; MAX_PLANES],
    mut b: [f64; MAX_PLANES],
    n: usize,
) -> [f64; MAX_PLANES] {
    for c in 0..n {
        let pivot = (c..n)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap_or(c);
        a.swap(pivot, c);
        b.swap(pivot, c);
        for r in c + 1..n {
            let f = a[r][c] / a[c][c];
            for k in c..n {
                a[r][k] -= f * a[c][k];
            }
            b[r] -= f * b[c];
        }
    }
    let mut x = [0.0; MAX_PLANES];
    for r in (0..n).rev() {
        let s: f64 = (r + 1..n).map(|k| a[r][k] * x[k]).sum();
        x[r] = (b[r] - s) / a[r][r];
    }
    x
}

impl<A: Algebra> Integrator<A> for ImplicitMidpoint {
    fn name(&self) -> &'static str {
        "midpoint"
    }

    fn advance(
        &mut self,
        body: &RigidBody<A>,
        t: f64,
        state: State<A>,
        dt: f64,
    ) -> Result<State<A>, Error> {
        fixed_steps("midpoint", self.step, t, state, dt, |t, s, h| {
            Self::step_once(body, t, s, h)
        })
    }
}
