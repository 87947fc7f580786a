//! An adaptive Lie-group Runge-Kutta method: Runge-Kutta-Munthe-Kaas (H. Munthe-Kaas, "High
//! order Runge-Kutta methods on manifolds", Appl. Numer. Math. 29, 1999) with the explicit
//! pair of order 5(4) of Dormand and Prince ("A family of embedded Runge-Kutta formulae",
//! J. Comput. Appl. Math. 6, 1980; the tableau of Hairer, Nørsett, Wanner, *Solving
//! Ordinary Differential Equations I*, 2nd ed., Springer 1993, Table II.5.2, and its
//! step-size control, section II.4), written over the algebra.
//!
//! The rotor is `R = R0 exp(u)` with `du/dt = dexp^-1_{-u}(A)`, `A = -1/2 Omega_B`: on the
//! bivectors, a vector space, where the stages are taken beside those of `Omega_B`. In G4
//! `ad_u` has the eigenvalues `0, +-i(a + b), +-i(a - b)` for the two angles of `u`, so the
//! 3D closed form of `dexp^-1` does not carry over; the Bernoulli series
//! `sum_k B_k/k! ad_(-u)^k` is taken to `ad^6`, which is exact to `O(h^7)`, beyond the
//! method's local error `O(h^6)`. The error estimate is the pair's, on `(u, Omega_B)`.

use super::algebra::Algebra;
use super::body::RigidBody;
use super::integrator::{check_finite, unit, Integrator};
use super::state::State;
use crate::error::{self, Error};

/// The nodes `c_i`.
const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];

/// The rows `a_ij`, `j < i`; row 7 is the fifth-order weights (first same as last).
const A: [&[f64]; 7] = [
    &[],
    &[1.0 / 5.0],
    &[3.0 / 40.0, 9.0 / 40.0],
    &[44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0],
    &[
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
    ],
    &[
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
    ],
    &[
        35.0 / 384.0,
        0.0,
        500.0 / 1113.0,
        125.0 / 192.0,
        -2187.0 / 6784.0,
        11.0 / 84.0,
    ],
];

/// The fifth- minus the fourth-order weights.
const E: [f64; 7] = [
    35.0 / 384.0 - 5179.0 / 57600.0,
    0.0,
    500.0 / 1113.0 - 7571.0 / 16695.0,
    125.0 / 192.0 - 393.0 / 640.0,
    -2187.0 / 6784.0 + 92097.0 / 339200.0,
    11.0 / 84.0 - 187.0 / 2100.0,
    -1.0 / 40.0,
];

/// Step-size control (Hairer, Nørsett, Wanner, section II.4).
const SAFETY: f64 = 0.9;
const MIN_RATIO: f64 = 0.2;
const MAX_RATIO: f64 = 10.0;
/// The most steps one `advance` takes before it reports the tolerance as too tight.
const MAX_STEPS: u64 = 10_000_000;

/// The adaptive Lie Dormand-Prince 5(4) method.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LieDopri5 {
    rtol: f64,
    atol: f64,
    accepted: u64,
    rejected: u64,
    next_step: Option<f64>,
}

impl LieDopri5 {
    /// The method with relative and absolute tolerances (each finite and positive).
    pub fn new(rtol: f64, atol: f64) -> Result<Self, Error> {
        Ok(LieDopri5 {
            rtol: error::positive("rtol", "tolerance", rtol)?,
            atol: error::positive("atol", "tolerance", atol)?,
            accepted: 0,
            rejected: 0,
            next_step: None,
        })
    }

    /// The steps accepted and rejected so far.
    #[must_use]
    pub fn steps(&self) -> (u64, u64) {
        (self.accepted, self.rejected)
    }

    /// One step of length `h` from `state` at `t`: the fifth-order state and the scaled
    /// error norm of the embedded pair (accept when at most 1).
    pub fn try_step<Al: Algebra>(
        &self,
        body: &RigidBody<Al>,
        t: f64,
        state: State<Al>,
        h: f64,
    ) -> (State<Al>, f64) {
        let mut k = [Al::Bivector::default(); 7];
        let mut l = [Al::Bivector::default(); 7];
        for i in 0..7 {
            let mut u = Al::Bivector::default();
            let mut omega = state.omega;
            for (j, &a) in A[i].iter().enumerate() {
                u = u + k[j] * (a * h);
                omega = omega + l[j] * (a * h);
            }
            let stage = State {
                rotor: state.rotor * Al::exp(u),
                omega,
            };
            k[i] = dexp_inverse::<Al>(u, omega * -0.5);
            l[i] = body.omega_rate(t + C[i] * h, &stage);
        }
        let mut u = Al::Bivector::default();
        let mut omega = state.omega;
        let mut eu = Al::Bivector::default();
        let mut ew = Al::Bivector::default();
        for i in 0..7 {
            let b = if i < 6 { A[6][i] } else { 0.0 };
            u = u + k[i] * (b * h);
            omega = omega + l[i] * (b * h);
            eu = eu + k[i] * (E[i] * h);
            ew = ew + l[i] * (E[i] * h);
        }
        let p = Al::PLANES.len();
        let mut sum = 0.0;
        for j in 0..p {
            let su = self.atol + self.rtol;
            let sw = self.atol + self.rtol * state.omega[j].abs().max(omega[j].abs());
            sum += (eu[j] / su).powi(2) + (ew[j] / sw).powi(2);
        }
        let next = State {
            rotor: unit::<Al>(state.rotor * Al::exp(u)),
            omega,
        };
        (next, (sum / (2 * p) as f64).sqrt())
    }
}

/// `dexp^-1_{-u}(a) = sum_k B_k/k! ad_(-u)^k (a)` to `ad^6`, with `ad_u(a) = [u, a] = 2 u x a`.
fn dexp_inverse<Al: Algebra>(u: Al::Bivector, a: Al::Bivector) -> Al::Bivector {
    let ad = |x: Al::Bivector| Al::commutator(u, x) * 2.0;
    let a1 = ad(a);
    let a2 = ad(a1);
    let a4 = ad(ad(a2));
    let a6 = ad(ad(a4));
    a + a1 * 0.5 + a2 * (1.0 / 12.0) - a4 * (1.0 / 720.0) + a6 * (1.0 / 30240.0)
}

impl<Al: Algebra> Integrator<Al> for LieDopri5 {
    fn name(&self) -> &'static str {
        "lie-dopri5"
    }

    fn advance(
        &mut self,
        body: &RigidBody<Al>,
        t: f64,
        state: State<Al>,
        dt: f64,
    ) -> Result<State<Al>, Error> {
        error::finite("dt", "time step", dt)?;
        if dt == 0.0 {
            return Ok(state);
        }
        let end = t + dt;
        let direction = dt.signum();
        let rate = (0..Al::PLANES.len())
            .map(|k| state.omega[k] * state.omega[k])
            .sum::<f64>()
            .sqrt();
        let mut h = self
            .next_step
            .unwrap_or_else(|| 0.5 * self.rtol.powf(0.2) / rate.max(1e-3))
            .min(dt.abs());
        let (mut t, mut state) = (t, state);
        let mut steps = 0;
        while (end - t) * direction > 0.0 {
            steps += 1;
            if steps > MAX_STEPS || h < 1e-14 * t.abs().max(1.0) {
                return Err(Error::invalid(
                    "lie-dopri5",
                    format!(
                        "the step fell below what the tolerance {} allows at t = {}",
                        error::num(self.rtol),
                        error::num(t)
                    ),
                ));
            }
            let last = h >= (end - t).abs();
            let step = if last { end - t } else { h * direction };
            let (next, err) = self.try_step(body, t, state, step);
            let ratio = if err == 0.0 {
                MAX_RATIO
            } else {
                (SAFETY * err.powf(-0.2)).clamp(MIN_RATIO, MAX_RATIO)
            };
            if err <= 1.0 {
                self.accepted += 1;
                t = if last { end } else { t + step };
                state = check_finite("lie-dopri5", next)?;
                if !last {
                    h *= ratio;
                }
                self.next_step = Some(h);
            } else {
                self.rejected += 1;
                h = step.abs() * ratio.min(1.0);
            }
        }
        Ok(state)
    }
}
