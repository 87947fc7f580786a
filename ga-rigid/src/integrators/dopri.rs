//! The adaptive explicit Runge-Kutta pair of order 5(4) of J. R. Dormand and
//! P. J. Prince, "A family of embedded Runge-Kutta formulae", J. Comput. Appl. Math. 6
//! (1980), 19-26, with the step-size control of E. Hairer, S. P. Nørsett, G. Wanner,
//! *Solving Ordinary Differential Equations I*, 2nd ed., Springer 1993, sections II.4
//! (error norm, initial step) and II.5 (the DOPRI5 code: safety factor 0.9, step ratio in
//! [0.2, 10], Lund stabilisation beta = 0.04, no growth right after a rejection).
//!
//! The method acts on `(R, Omega_B)` as a point of R^4 x R^3 and scales the rotor back to
//! unit norm after every accepted step. The error of a step is the root mean square of
//! `err_i / (atol + rtol max(|y0_i|, |y1_i|))` over the seven components.

use crate::dynamics::{RigidBody, State};
use crate::error::{self, Error};

use super::integrator::{check_finite, scaled_norm, step_limit_reached, Integrator};

/// The state as seven numbers: the rotor `[s, e12, e13, e23]` then `Omega_B`
/// `[e12, e13, e23]`.
type Y = [f64; 7];

const C: [f64; 7] = [0.0, 1.0 / 5.0, 3.0 / 10.0, 4.0 / 5.0, 8.0 / 9.0, 1.0, 1.0];
const A2: [f64; 1] = [1.0 / 5.0];
const A3: [f64; 2] = [3.0 / 40.0, 9.0 / 40.0];
const A4: [f64; 3] = [44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0];
const A5: [f64; 4] = [
    19372.0 / 6561.0,
    -25360.0 / 2187.0,
    64448.0 / 6561.0,
    -212.0 / 729.0,
];
const A6: [f64; 5] = [
    9017.0 / 3168.0,
    -355.0 / 33.0,
    46732.0 / 5247.0,
    49.0 / 176.0,
    -5103.0 / 18656.0,
];
/// The fifth-order weights (also the seventh stage: first same as last).
const B: [f64; 6] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
];
/// The fifth- minus the fourth-order weights.
const E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// The weights of the continuous extension of order four (Hairer, Nørsett, Wanner,
/// section II.6, the DOPRI5 code's `CONTD5`): with `theta = (t - t0) / h`,
/// `y(t) = y0 + theta (dy + (1 - theta) (b + theta (c + (1 - theta) d)))`, where
/// `dy = y1 - y0`, `b = h k1 - dy`, `c = dy - h k7 - b` and `d = h sum_j D_j k_j`.
const D: [f64; 7] = [
    -12715105075.0 / 11282082432.0,
    0.0,
    87487479700.0 / 32700410799.0,
    -10690763975.0 / 1880347072.0,
    701980252875.0 / 199316789632.0,
    -1453857185.0 / 822651844.0,
    69997945.0 / 29380423.0,
];

const SAFETY: f64 = 0.9;
const MIN_RATIO: f64 = 0.2;
const MAX_RATIO: f64 = 10.0;
const BETA: f64 = 0.04;

/// Counts of the work done so far by a [`DormandPrince`] integrator.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct DormandPrinceStats {
    /// Steps accepted.
    pub accepted: u64,
    /// Steps rejected and retried with a smaller step.
    pub rejected: u64,
    /// Evaluations of the right-hand side.
    pub evaluations: u64,
}

/// Adaptive Dormand-Prince 5(4) with relative and absolute tolerances.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DormandPrince {
    rtol: f64,
    atol: f64,
    max_steps: u64,
    /// The run's bound on all its steps ([`Integrator::limit_steps`]), counted in `stats`
    /// (from construction); it replaces `max_steps`.
    run_limit: Option<u64>,
    /// The step size the controller proposes next (its magnitude), once known.
    next_step: Option<f64>,
    /// The previous accepted error, for the Lund stabilisation.
    previous_error: f64,
    stats: DormandPrinceStats,
}

impl DormandPrince {
    /// The pair with tolerances `rtol` and `atol` (finite and positive) and at most 10^6
    /// steps per call of [`Integrator::advance`].
    pub fn new(rtol: f64, atol: f64) -> Result<Self, Error> {
        error::positive("rtol", "tolerance", rtol)?;
        error::positive("atol", "tolerance", atol)?;
        Ok(DormandPrince {
            rtol,
            atol,
            max_steps: 1_000_000,
            run_limit: None,
            next_step: None,
            previous_error: 1e-4,
            stats: DormandPrinceStats::default(),
        })
    }

    /// The same with a different bound on the steps (accepted and rejected) of one call.
    #[must_use]
    pub fn with_max_steps(mut self, max_steps: u64) -> Self {
        self.max_steps = max_steps;
        self
    }

    /// The relative and absolute tolerances.
    #[must_use]
    pub fn tolerances(&self) -> (f64, f64) {
        (self.rtol, self.atol)
    }

    /// The work done so far.
    #[must_use]
    pub fn stats(&self) -> DormandPrinceStats {
        self.stats
    }

    /// Forget the step-size history, so the next call chooses its initial step afresh.
    pub fn reset(&mut self) {
        self.next_step = None;
        self.previous_error = 1e-4;
    }

    fn rate(&mut self, body: &RigidBody, t: f64, y: &Y) -> Y {
        self.stats.evaluations += 1;
        let state = to_state(y);
        let r = RigidBody::rotor_rate(&state);
        let w = body.omega_rate(t, &state);
        [r.s, r.e12, r.e13, r.e23, w.e12, w.e13, w.e23]
    }

    fn scale(&self, a: f64, b: f64) -> f64 {
        self.atol + self.rtol * a.abs().max(b.abs())
    }

    /// The initial step of Hairer, Nørsett, Wanner (II.4), for order 5.
    fn initial_step(
        &mut self,
        body: &RigidBody,
        t: f64,
        y: &Y,
        f0: &Y,
        dir: f64,
        h_max: f64,
    ) -> f64 {
        let mut dnf = 0.0;
        let mut dny = 0.0;
        for i in 0..7 {
            let sk = self.scale(y[i], y[i]);
            dnf += (f0[i] / sk).powi(2);
            dny += (y[i] / sk).powi(2);
        }
        let mut h = if dnf <= 1e-10 || dny <= 1e-10 {
            1e-6
        } else {
            0.01 * (dny / dnf).sqrt()
        };
        h = h.min(h_max);
        let y1: Y = std::array::from_fn(|i| y[i] + dir * h * f0[i]);
        let f1 = self.rate(body, t + dir * h, &y1);
        let mut der2 = 0.0;
        for i in 0..7 {
            der2 += ((f1[i] - f0[i]) / self.scale(y[i], y[i])).powi(2);
        }
        let der2 = der2.sqrt() / h;
        let der12 = der2.max(dnf.sqrt());
        let h1 = if der12 <= 1e-15 {
            (h * 1e-3).max(1e-6)
        } else {
            (0.01 / der12).powf(0.2)
        };
        let h0 = (100.0 * h).min(h1).min(h_max);
        if h0 > 0.0 && h0.is_finite() {
            return h0;
        }
        // The squares above overflow when |w| is near 1e80 (its rate near 1e160), which
        // left h = 0; the same first estimate from norms taken with scaling. The
        // controller corrects it from there.
        let nf = scaled_norm(&std::array::from_fn::<f64, 7, _>(|i| {
            f0[i] / self.scale(y[i], y[i])
        }));
        let ny = scaled_norm(&std::array::from_fn::<f64, 7, _>(|i| {
            y[i] / self.scale(y[i], y[i])
        }));
        let h = if nf <= 1e-5 || ny <= 1e-5 {
            1e-6
        } else {
            0.01 * ny / nf
        };
        let h1 = (0.01 / nf.max(1e-15)).powf(0.2);
        (100.0 * h).min(h1).min(h_max)
    }
}

fn to_state(y: &Y) -> State {
    use ga_core::f64::g3::{Bivector, Rotor};
    State {
        rotor: Rotor::new(y[0], y[1], y[2], y[3]),
        omega: Bivector::new(y[4], y[5], y[6]),
    }
}

fn from_state(state: &State) -> Y {
    let (r, w) = (state.rotor, state.omega);
    [r.s, r.e12, r.e13, r.e23, w.e12, w.e13, w.e23]
}

/// `y + h sum_j a_j k_j`.
#[inline]
fn combine(y: &Y, h: f64, a: &[f64], k: &[Y; 7]) -> Y {
    std::array::from_fn(|i| {
        let mut sum = 0.0;
        for (j, aj) in a.iter().enumerate() {
            sum += aj * k[j][i];
        }
        y[i] + h * sum
    })
}

impl Integrator for DormandPrince {
    fn name(&self) -> &'static str {
        "dopri"
    }

    fn accepted_steps(&self) -> Option<u64> {
        Some(self.stats.accepted)
    }

    fn limit_steps(&mut self, max_steps: u64) {
        self.run_limit = Some(max_steps);
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        error::finite("dt", "time step", dt)?;
        if dt == 0.0 {
            return check_finite(self.name(), state);
        }
        self.integrate(body, t, state, dt, |_, _, _, _, _| {})
    }

    fn advance_to_each(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: State,
        times: &[f64],
    ) -> Result<Vec<State>, Error> {
        let Some(&last) = times.last() else {
            return Ok(Vec::new());
        };
        error::finite("dt", "time step", last - t)?;
        let dir = if last < t { -1.0 } else { 1.0 };
        if let Some((i, &ti)) = times
            .iter()
            .enumerate()
            .find(|&(i, &ti)| (ti - t) * dir < 0.0 || (i > 0 && (ti - times[i - 1]) * dir < 0.0))
        {
            return Err(Error::invalid(
                format!("times[{i}]"),
                format!(
                    "sample times must follow the direction of travel from {}, got {}",
                    error::num(t),
                    error::num(ti)
                ),
            ));
        }
        let mut out = Vec::with_capacity(times.len());
        let mut pending = times;
        if last == t {
            out.resize(times.len(), check_finite(self.name(), state)?);
            return Ok(out);
        }
        let end = self.integrate(body, t, state, last - t, |t0, h, y0, y1, k| {
            while let Some((&ti, rest)) = pending.split_first() {
                if (ti - t0) * dir > h.abs() || rest.is_empty() {
                    break;
                }
                out.push(to_state(&dense(t0, h, y0, y1, k, ti)));
                pending = rest;
            }
        })?;
        // The last sample is the end state itself, not its interpolation.
        out.resize(times.len(), end);
        for state in &mut out {
            *state = check_finite(self.name(), *state)?;
        }
        Ok(out)
    }
}

/// The continuous extension at `t` inside the step from `(t0, y0)` of length `h` to `y1`
/// with stages `k`, its rotor scaled to unit norm.
fn dense(t0: f64, h: f64, y0: &Y, y1: &Y, k: &[Y; 7], t: f64) -> Y {
    let theta = (t - t0) / h;
    let rest = 1.0 - theta;
    let mut y: Y = std::array::from_fn(|i| {
        let dy = y1[i] - y0[i];
        let b = h * k[0][i] - dy;
        let c = dy - h * k[6][i] - b;
        let d = h * (0..7).map(|j| D[j] * k[j][i]).sum::<f64>();
        y0[i] + theta * (dy + rest * (b + theta * (c + rest * d)))
    });
    let norm = (y[0] * y[0] + y[1] * y[1] + y[2] * y[2] + y[3] * y[3]).sqrt();
    for x in &mut y[..4] {
        *x /= norm;
    }
    y
}

impl DormandPrince {
    /// Integrate from `state` at `t` over `dt` (finite, non-zero), calling
    /// `accepted(t0, h, y0, y1, k)` for each accepted step before its rotor is scaled.
    fn integrate(
        &mut self,
        body: &RigidBody,
        t: f64,
        state: State,
        dt: f64,
        mut accepted: impl FnMut(f64, f64, &Y, &Y, &[Y; 7]),
    ) -> Result<State, Error> {
        let dir = dt.signum();
        let t_end = t + dt;
        let mut t = t;
        let mut y = from_state(&state);
        let mut k: [Y; 7] = [[0.0; 7]; 7];
        k[0] = self.rate(body, t, &y);
        let mut h = match self.next_step {
            Some(h) => h.min(dt.abs()),
            None => self.initial_step(body, t, &y, &k[0], dir, dt.abs()),
        };
        let mut rejected_last = false;
        let mut steps = 0_u64;
        loop {
            let remaining = (t_end - t) * dir;
            if remaining <= 0.0 {
                break;
            }
            steps += 1;
            if let Some(limit) = self.run_limit {
                if self.stats.accepted + self.stats.rejected >= limit {
                    return Err(step_limit_reached(self.name(), limit, t, t_end));
                }
            } else if steps > self.max_steps {
                return Err(Error::invalid(
                    "dopri",
                    format!(
                        "more than {} steps needed before t = {t_end}",
                        self.max_steps
                    ),
                ));
            }
            if 0.1 * h <= f64::EPSILON * t.abs() || !h.is_finite() {
                return Err(Error::invalid(
                    "dopri",
                    format!("step size underflow ({h:e}) at t = {}", error::num(t)),
                ));
            }
            // Land on t_end exactly; the proposal survives for the next call.
            let last = h >= remaining;
            let hs = dir * if last { remaining } else { h };
            k[1] = self.rate(body, t + C[1] * hs, &combine(&y, hs, &A2, &k));
            k[2] = self.rate(body, t + C[2] * hs, &combine(&y, hs, &A3, &k));
            k[3] = self.rate(body, t + C[3] * hs, &combine(&y, hs, &A4, &k));
            k[4] = self.rate(body, t + C[4] * hs, &combine(&y, hs, &A5, &k));
            k[5] = self.rate(body, t + C[5] * hs, &combine(&y, hs, &A6, &k));
            let y1 = combine(&y, hs, &B, &k);
            let t1 = if last { t_end } else { t + hs };
            k[6] = self.rate(body, t1, &y1);
            let mut err = 0.0;
            for i in 0..7 {
                let mut e = 0.0;
                for (j, ej) in E.iter().enumerate() {
                    e += ej * k[j][i];
                }
                err += (hs * e / self.scale(y[i], y1[i])).powi(2);
            }
            let err = (err / 7.0).sqrt();
            if !err.is_finite() {
                return Err(Error::NotFinite {
                    field: "dopri".to_string(),
                    what: "the integrated state",
                    value: err,
                });
            }
            let fac11 = err.powf(0.2 - 0.75 * BETA);
            if err <= 1.0 {
                // Lund-stabilised proposal, step ratio within [MIN_RATIO, MAX_RATIO].
                let fac = (fac11 / self.previous_error.powf(BETA) / SAFETY)
                    .clamp(1.0 / MAX_RATIO, 1.0 / MIN_RATIO);
                let mut h_new = hs.abs() / fac;
                if rejected_last {
                    h_new = h_new.min(hs.abs());
                }
                self.previous_error = err.max(1e-4);
                self.stats.accepted += 1;
                accepted(t, hs, &y, &y1, &k);
                // Scale the rotor back to unit norm; its rate is linear in R, so the FSAL
                // stage scales with it unless a torque reads the attitude.
                let norm = (y1[0] * y1[0] + y1[1] * y1[1] + y1[2] * y1[2] + y1[3] * y1[3]).sqrt();
                y = y1;
                for x in &mut y[..4] {
                    *x /= norm;
                }
                t = t1;
                if body.has_torque() {
                    k[0] = self.rate(body, t, &y);
                } else {
                    k[0] = k[6];
                    for x in &mut k[0][..4] {
                        *x /= norm;
                    }
                }
                // A truncated last step says nothing about the next: keep the larger.
                if !(last && h_new < h) {
                    h = h_new;
                }
                rejected_last = false;
            } else {
                h = hs.abs() / (fac11 / SAFETY).min(1.0 / MIN_RATIO);
                self.stats.rejected += 1;
                rejected_last = true;
            }
        }
        self.next_step = Some(h);
        check_finite(self.name(), to_state(&y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::omega_from_vector;
    use ga_core::f64::g3::Rotor;

    /// The run's limit replaces the bound per call: it lets a call take more steps than
    /// `with_max_steps` allows, and stops the run, naming `max_steps`, once all its calls
    /// together reach it.
    #[test]
    fn the_runs_step_limit_replaces_the_bound_per_call() {
        let body = RigidBody::new([1.0, 2.0, 3.0]).unwrap();
        let state = State {
            rotor: Rotor::ONE,
            omega: omega_from_vector([0.5, 4.0, 0.3]),
        };
        let mut dopri = DormandPrince::new(1e-8, 1e-11).unwrap().with_max_steps(10);
        assert!(dopri.advance(&body, 0.0, state, 5.0).is_err());
        dopri.limit_steps(400);
        let mid = dopri.advance(&body, 0.0, state, 5.0).unwrap();
        let used = dopri.stats.accepted + dopri.stats.rejected;
        assert!(used > 10 && used < 400, "{used}");
        let e = dopri.advance(&body, 5.0, mid, 1000.0).unwrap_err();
        assert_eq!(e.field(), Some("max_steps"), "{e}");
        assert!(
            e.to_string().contains("dopri needs more than 400 steps"),
            "{e}"
        );
    }
}
