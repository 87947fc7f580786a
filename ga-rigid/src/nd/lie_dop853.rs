//! The adaptive Lie Dormand-Prince 8(5,3) method written over the algebra: the 3D
//! `integrators::LieDop853` (Runge-Kutta-Munthe-Kaas, H. Munthe-Kaas, Appl. Numer. Math.
//! 29, 1999, with the 12-stage pair of Hairer, Nørsett, Wanner, *Solving Ordinary
//! Differential Equations I*, 2nd ed., Springer 1993, section II.10, and DOP853's error
//! estimate and step-size control), whose tableau it reads rather than copies.
//!
//! The rotor is `R = R0 exp(u)` with `du/dt = dexp^-1_{-u}(A)`, `A = -1/2 Omega_B`, on the
//! bivectors, where the stages are taken beside those of `Omega_B`. In G4 `ad_u` has the
//! eigenvalues `0, +-i(a + b), +-i(a - b)` for the two angles of `u`, so the 3D closed
//! form of `dexp^-1` does not carry over (as in [`super::LieDopri5`]); the Bernoulli series
//! `sum_k B_k/k! ad_(-u)^k` is taken to `ad^8`, whose remainder `O(h^10)` in the rate is
//! below the method's local error `O(h^9)`. The error estimate is DOP853's, on
//! `(u, Omega_B)`. No dense output: a run is cut at its sample times.

use super::algebra::Algebra;
use super::body::RigidBody;
use super::integrator::{check_finite, unit, Integrator};
use super::state::State;
use crate::error::{self, Error};
use crate::integrators::lie_dop853::{A, B, BHH, C, E, MAX_RATIO, MIN_RATIO, S, SAFETY, STRETCH};

/// The most tries (accepted and rejected steps) one `advance` takes, as the 3D method.
const MAX_STEPS: u64 = 1_000_000;

/// Runge-Kutta-Munthe-Kaas with the Dormand-Prince 8(5,3) pair, adaptive, in G2, G3 or G4.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LieDop853 {
    rtol: f64,
    atol: f64,
    accepted: u64,
    rejected: u64,
    next_step: Option<f64>,
}

/// One step's result: the Lie-algebra increment, the new `Omega_B` and the error norm.
struct Trial<Al: Algebra> {
    u: Al::Bivector,
    omega: Al::Bivector,
    error: f64,
}

/// `x0 + h sum_j w_j x_j` over the nonzero `w_j`.
fn combine<Al: Algebra>(x0: Al::Bivector, h: f64, w: &[f64], x: &[Al::Bivector]) -> Al::Bivector {
    let mut sum = Al::Bivector::default();
    for (&wj, &xj) in w.iter().zip(x) {
        if wj != 0.0 {
            sum = sum + xj * wj;
        }
    }
    x0 + sum * h
}

/// `dexp^-1_{-u}(a) = sum_k B_k/k! ad_(-u)^k (a)` to `ad^8`, with `ad_u(a) = [u, a] = 2 u x a`
/// (`B_0 .. B_8 = 1, -1/2, 1/6, 0, -1/30, 0, 1/42, 0, -1/30`).
fn dexp_inverse<Al: Algebra>(u: Al::Bivector, a: Al::Bivector) -> Al::Bivector {
    let ad = |x: Al::Bivector| Al::commutator(u, x) * 2.0;
    let a1 = ad(a);
    let a2 = ad(a1);
    let a4 = ad(ad(a2));
    let a6 = ad(ad(a4));
    let a8 = ad(ad(a6));
    a + a1 * 0.5 + a2 * (1.0 / 12.0) - a4 * (1.0 / 720.0) + a6 * (1.0 / 30240.0)
        - a8 * (1.0 / 1_209_600.0)
}

impl LieDop853 {
    /// The method with relative and absolute tolerances (each finite and positive).
    pub fn new(rtol: f64, atol: f64) -> Result<Self, Error> {
        Ok(LieDop853 {
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

    /// The twelve stages of one step of length `h` from `state` at `t`.
    fn trial<Al: Algebra>(
        &self,
        body: &RigidBody<Al>,
        t: f64,
        state: &State<Al>,
        h: f64,
    ) -> Trial<Al> {
        let zero = Al::Bivector::default();
        let mut ku = [zero; S];
        let mut kw = [zero; S];
        let torque = body.has_torque();
        for i in 0..S {
            let u = combine::<Al>(zero, h, A[i], &ku);
            let omega = combine::<Al>(state.omega, h, A[i], &kw);
            // Without a torque the rate of Omega_B does not depend on the attitude.
            let stage = State {
                rotor: if torque {
                    state.rotor * Al::exp(u)
                } else {
                    state.rotor
                },
                omega,
            };
            ku[i] = dexp_inverse::<Al>(u, omega * -0.5);
            kw[i] = body.omega_rate(t + C[i] * h, &stage);
        }
        let bu = combine::<Al>(zero, 1.0, &B, &ku);
        let bw = combine::<Al>(zero, 1.0, &B, &kw);
        let (u1, w1) = (bu * h, state.omega + bw * h);
        let err8 = [
            combine::<Al>(zero, 1.0, &E, &ku),
            combine::<Al>(zero, 1.0, &E, &kw),
        ];
        let third = |b: Al::Bivector, k: &[Al::Bivector; S]| {
            b - combine::<Al>(zero, 1.0, &BHH, &[k[0], k[8], k[11]])
        };
        let err3 = [third(bu, &ku), third(bw, &kw)];
        // DOP853's norm: the fifth-order estimate damped by the third-order one, scaled by
        // `atol + rtol max(|y0|, |y1|)`; `u` runs from 0 and a rotor is of order one.
        let planes = Al::PLANES.len();
        let (mut sum8, mut sum3) = (0.0, 0.0);
        for k in 0..planes {
            let scale_u = 1.0 / (self.atol + self.rtol);
            let scale_w = 1.0 / (self.atol + self.rtol * state.omega[k].abs().max(w1[k].abs()));
            for (half, scale) in [(0, scale_u), (1, scale_w)] {
                let (a8, a3) = (err8[half][k] * scale, err3[half][k] * scale);
                sum8 += a8 * a8;
                sum3 += a3 * a3;
            }
        }
        let mut deno = sum8 + 0.01 * sum3;
        if deno <= 0.0 {
            deno = 1.0;
        }
        Trial {
            u: u1,
            omega: w1,
            error: h.abs() * sum8 / ((2 * planes) as f64 * deno).sqrt(),
        }
    }

    /// One step of length `h` taken whatever its error estimate says: the method with a
    /// fixed step, for measuring its order.
    #[must_use]
    pub fn step_once<Al: Algebra>(
        &self,
        body: &RigidBody<Al>,
        t: f64,
        state: State<Al>,
        h: f64,
    ) -> State<Al> {
        let trial = self.trial(body, t, &state, h);
        State {
            rotor: state.rotor * Al::exp(trial.u),
            omega: trial.omega,
        }
    }

    /// A first step from the size of the rates (Hairer-Nørsett-Wanner II.4, order 8), as
    /// the 3D method chooses it.
    fn initial_step<Al: Algebra>(
        &self,
        body: &RigidBody<Al>,
        t: f64,
        state: &State<Al>,
        h_max: f64,
    ) -> f64 {
        let planes = Al::PLANES.len();
        let rate = body.omega_rate(t, state);
        let (mut d0, mut d1, mut spin) = (0.0, 0.0, 0.0);
        for k in 0..planes {
            let w = state.omega[k];
            let scale = self.atol + self.rtol * w.abs();
            d0 += (w / scale).powi(2);
            d1 += (rate[k] / scale).powi(2);
            spin += w * w;
        }
        let unit_scale = self.atol + self.rtol;
        d1 += planes as f64 * (0.5 * spin.sqrt() / unit_scale).powi(2);
        d0 += planes as f64 / unit_scale.powi(2);
        let h = if d0 <= 1e-10 || d1 <= 1e-10 {
            1e-6
        } else {
            0.01 * (d0 / d1).sqrt()
        };
        let h1 = (0.01 / d1.sqrt().max(1e-15) / h.max(1e-300)).powf(1.0 / 8.0) * h;
        let h0 = (100.0 * h).min(h1.max(h)).min(h_max);
        if h0 > 0.0 && h0.is_finite() {
            h0
        } else {
            // The squares overflow for rates near 1e150; start small and let the
            // controller grow the step.
            (1e-6 / spin.sqrt().max(1.0)).min(h_max)
        }
    }
}

impl<Al: Algebra> Integrator<Al> for LieDop853 {
    fn name(&self) -> &'static str {
        "lie-dop853"
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
            return check_finite("lie-dop853", state);
        }
        let t_end = t + dt;
        let dir = dt.signum();
        let (mut t, mut state) = (t, state);
        let mut attempts = 0;
        let mut h = match self.next_step {
            Some(h) => h.min(dt.abs()),
            None => self.initial_step(body, t, &state, dt.abs()),
        };
        let mut rejected_last = false;
        loop {
            attempts += 1;
            if attempts > MAX_STEPS {
                return Err(Error::invalid(
                    "lie-dop853",
                    format!(
                        "more than {MAX_STEPS} steps needed before t = {}",
                        error::num(t_end)
                    ),
                ));
            }
            let remaining = (t_end - t).abs();
            if 0.1 * h <= f64::EPSILON * t.abs() || !h.is_finite() {
                return Err(Error::invalid(
                    "lie-dop853",
                    format!("step size underflow ({h:e}) at t = {}", error::num(t)),
                ));
            }
            let last = STRETCH * h >= remaining;
            let hs = dir * if last { remaining } else { h };
            let trial = self.trial(body, t, &state, hs);
            let err = trial.error;
            if !err.is_finite() {
                return Err(Error::invalid(
                    "lie-dop853",
                    "the integrated state stopped being finite; tighten the tolerance",
                ));
            }
            // err^(1/8) by three square roots.
            let fac11 = err.sqrt().sqrt().sqrt();
            if err <= 1.0 {
                self.accepted += 1;
                let fac = (fac11 / SAFETY).clamp(1.0 / MAX_RATIO, 1.0 / MIN_RATIO);
                let mut h_new = hs.abs() / fac;
                if rejected_last {
                    h_new = h_new.min(hs.abs());
                }
                // A truncated last step says nothing about the next: keep the larger.
                self.next_step = Some(if last && h_new < h { h } else { h_new });
                state = check_finite(
                    "lie-dop853",
                    State {
                        rotor: unit::<Al>(state.rotor * Al::exp(trial.u)),
                        omega: trial.omega,
                    },
                )?;
                if last {
                    return Ok(state);
                }
                t += hs;
                h = h_new;
                rejected_last = false;
            } else {
                self.rejected += 1;
                h = hs.abs() / (fac11 / SAFETY).min(1.0 / MIN_RATIO);
                rejected_last = true;
            }
        }
    }
}
