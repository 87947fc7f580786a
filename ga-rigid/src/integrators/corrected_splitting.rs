//! The corrected Casimir split, the step of the `ga_engine` crate in the registry's terms
//! (f64, on the rotor and body momentum): the free body split around `|m|^2` with the
//! largest moment as reference, the outer turns about the smallest moment's axis and the
//! middle turn about the middle one, each turn's angle corrected so that the single-axis
//! parts of the splitting's `h^2` energy error cancel, then the turn about `m`
//! (docs/derivations/corrected-splitting.md derives it and lists its tests). Each turn:
//!
//! ```text
//! outer half turn:  2 atan2(a, e_o - lambda_o a^2),  a = h alpha m_o / 4,
//! middle turn:      2 atan2(a, e_m - lambda_m a^2),  a = h beta m_m / 2,
//! e_o = 1 - h^2 |m|^2 alpha beta / 12,  e_m = 1 + h^2 |m|^2 alpha beta / 6,
//! lambda_o = (alpha - 8 beta) / 3 alpha,  lambda_m = (beta + 4 alpha) / 3 beta,
//! ```
//!
//! `alpha`, `beta` the outer and middle inverse moments less the reference's. A torque
//! enters as Strang half-kicks around the free step, as in [`Splitting`].
//!
//! [`Splitting`]: super::Splitting

use ga_core::f64::g3::Rotor;

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::Error;

use super::casimir_splitting::casimir_turn;
use super::integrator::{check_finite, check_step, substeps, unit, Integrator};
use super::splitting::{turned_about_axis, Splitting};

/// The corrected Casimir splitting with fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CorrectedSplitting {
    step: f64,
}

impl CorrectedSplitting {
    /// The splitting with sub-steps of at most `step` (finite and positive).
    pub fn new(step: f64) -> Result<Self, Error> {
        Ok(CorrectedSplitting {
            step: check_step(step)?,
        })
    }

    /// The largest sub-step.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.step
    }
}

/// The axes `[outer, middle, reference]`: the smallest moment's, the middle one's, the
/// largest's (ties by index, as the engine orders them).
fn axes(moments: [f64; 3]) -> [usize; 3] {
    let mut by_size = [0, 1, 2];
    by_size.sort_by(|&a, &b| moments[a].total_cmp(&moments[b]));
    by_size
}

/// A turn's `lambda` and the largest `|a|` it takes: `lambda` limited to `+-1e6` (1/3
/// where a zero coefficient made it 0/0; that turn does not move), `|a|` to 64 and to
/// `|lambda| a^2 <= 1365`, the engine's divided form's limits.
fn cubic_and_limit(lambda: f64) -> (f64, f64) {
    let lambda = if lambda.is_nan() {
        1.0 / 3.0
    } else {
        lambda.clamp(-1e6, 1e6)
    };
    (lambda, (1365.0 / lambda.abs()).sqrt().min(64.0))
}

/// The flow of one corrected turn about `e_k` for the half-angle parameter `a`: `m`
/// turned by `2 atan2(a, e - lambda a^2)` and the rotor with it (not normalised). `a` is
/// limited to `limit`, `e` to `[0.5, 1.5]`, as the engine's divided form limits them.
#[inline(always)]
fn corrected_turn(
    k: usize,
    a: f64,
    (limit, lambda, e): (f64, f64, f64),
    rotor: &mut Rotor,
    m: &mut [f64; 3],
) {
    let a = a.clamp(-limit, limit);
    let p = e.clamp(0.5, 1.5) - lambda * (a * a);
    let (p2, a2) = (p * p, a * a);
    let r = 1.0 / (p2 + a2);
    let (c, s) = ((p2 - a2) * r, 2.0 * p * a * r);
    let (ka, kb) = ((k + 1) % 3, (k + 2) % 3);
    let (ma, mb) = (m[ka], m[kb]);
    m[ka] = c * ma + s * mb;
    m[kb] = c * mb - s * ma;
    *rotor = turned_about_axis(*rotor, k, p, a);
}

impl Integrator for CorrectedSplitting {
    fn name(&self) -> &'static str {
        "splitting-corrected"
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        let (n, h) = substeps(self.step, dt)?;
        if n == 0 {
            return check_finite(self.name(), state);
        }
        let moments = body.moments();
        let inverse = moments.map(|i| 1.0 / i);
        let [o, c, r] = axes(moments);
        let (alpha, beta) = (inverse[o] - inverse[r], inverse[c] - inverse[r]);
        let (outer_cubic, outer_limit) = cubic_and_limit((alpha - 8.0 * beta) / (3.0 * alpha));
        let (middle_cubic, middle_limit) = cubic_and_limit((beta + 4.0 * alpha) / (3.0 * beta));
        let w = omega_to_vector(state.omega);
        let mut m: [f64; 3] = std::array::from_fn(|k| moments[k] * w[k]);
        let mut rotor = state.rotor;
        for i in 0..n {
            let t0 = t + i as f64 * h;
            Splitting::kick(body, t0, 0.5 * h, rotor, &mut m);
            let hh_m2 = h * h * (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
            let outer = (outer_limit, outer_cubic, 1.0 - hh_m2 * alpha * beta / 12.0);
            let middle = (middle_limit, middle_cubic, 1.0 + hh_m2 * alpha * beta / 6.0);
            corrected_turn(o, 0.25 * h * alpha * m[o], outer, &mut rotor, &mut m);
            corrected_turn(c, 0.5 * h * beta * m[c], middle, &mut rotor, &mut m);
            corrected_turn(o, 0.25 * h * alpha * m[o], outer, &mut rotor, &mut m);
            casimir_turn(inverse[r], h, &mut rotor, &m);
            // The torque must see a unit rotor.
            rotor = unit(rotor);
            Splitting::kick(body, t0 + h, 0.5 * h, rotor, &mut m);
        }
        let omega = omega_from_vector(std::array::from_fn(|k| m[k] / moments[k]));
        check_finite(self.name(), State { rotor, omega })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::omega_from_vector;
    use ga_core::f64::g3::{Bivector, Sandwich};

    /// A turn whose half-angle parameter is beyond the limit `|lambda| a^2 <= 1365` (the
    /// engine's `MAX_CUBIC_TERM`, docs/derivations/corrected-splitting.md) turns by
    /// `2 atan2(a*, e - lambda a*^2)` with `a* = sqrt(1365 / |lambda|)`, computed here with
    /// `cos` and `sin`; the momentum in space, `R m ~R`, is kept.
    #[test]
    fn a_turn_beyond_the_cubic_limit_turns_by_the_limited_angle() {
        let lambda = 10.0;
        let e = 1.0;
        let (cubic, limit) = cubic_and_limit(lambda);
        assert_eq!(cubic, lambda);
        let a_star = (1365.0_f64 / lambda).sqrt();
        let angle = 2.0 * a_star.atan2(e - lambda * a_star * a_star);
        let m0 = [0.7, -1.3, 0.4];
        for k in 0..3 {
            let mut m = m0;
            let rotor0 = Bivector::new(0.2, -0.4, 0.3).exp();
            let mut rotor = rotor0;
            corrected_turn(k, 50.0, (limit, cubic, e), &mut rotor, &mut m);
            let (ka, kb) = ((k + 1) % 3, (k + 2) % 3);
            let (c, s) = (angle.cos(), angle.sin());
            let expected_a = c * m0[ka] + s * m0[kb];
            let expected_b = c * m0[kb] - s * m0[ka];
            assert!((m[ka] - expected_a).abs() < 1e-12, "{k}: {m:?}");
            assert!((m[kb] - expected_b).abs() < 1e-12, "{k}: {m:?}");
            assert_eq!(m[k], m0[k]);
            let space = |r: Rotor, m: [f64; 3]| (r / r.norm()).sandwich(omega_from_vector(m));
            let moved = space(rotor, m) - space(rotor0, m0);
            assert!(moved.norm() < 1e-12, "{k}: {moved:?}");
        }
    }
}
