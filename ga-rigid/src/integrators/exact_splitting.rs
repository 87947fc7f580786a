//! Splitting with the exact free flow for a torqued body: E. Celledoni, F. Fassò,
//! N. Säfström, A. Zanna, "The exact computation of the free rigid body motion and its use
//! in splitting methods", SIAM J. Sci. Comput. 30(4) (2008) 2084-2112, section 5.
//!
//! The Hamiltonian `H = T(m) + V(R)` splits into the kinetic energy, whose flow is the
//! exact free rigid body motion ([`crate::exact_flow`]: the closed form when two moments
//! are equal, Jacobi elliptic functions otherwise), and the potential, whose flow at fixed
//! attitude is the torque kick `m += tau(R) dt`. Strang's composition
//!
//! ```text
//! S(h) = kick(h/2) free(h) kick(h/2)
//! ```
//!
//! is symmetric, symplectic and of order two; it keeps `|R ~R| = 1` to rounding (the free
//! flow is a rotor product, the kick leaves `R` alone). Its error comes from the torque
//! alone: with no torque it is the exact flow. Blanes and Moan's Runge-Kutta-Nystrom
//! splittings ([`Nystrom`]) raise it to order 4 and 6, Kahan and Li's composition
//! ([`Composition`]) to order 8. Between two steps the closing kick of one and the
//! opening kick of the next act at the same time and attitude, so they merge into one
//! (likewise between the stages of a composition): `s` free flows cost `s` torque
//! evaluations a step, plus one at the end. The kicks are exact only when the torque does not depend on
//! `Omega` (gravity, a time-dependent couple); a time-dependent torque is read at the time
//! the kick stands at (time moves with the free flow), which keeps the method symmetric.

use ga_core::f64::g3::Rotor;

use crate::dynamics::{
    omega_from_vector, omega_to_vector, RigidBody, State, DEFAULT_SYMMETRY_TOLERANCE,
};
use crate::error::Error;
use crate::exact_flow::exact_free_body;

use super::composition::{Composition, Nystrom, MAX_HALF};
use super::integrator::{check_finite, check_step, substeps, unit, Integrator};

/// Kick, exact free flow, kick, composed to order 2, 4, 6 or 8, with fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExactSplitting {
    step: f64,
    order: u32,
    name: &'static str,
    /// The number of free flows a step, `s`.
    stages: usize,
    /// The free flows' fractions of the step, `a_1 .. a_s`.
    frees: [f64; MAX_STAGES],
    /// The kicks' fractions, `b_1 .. b_(s+1)`: kick `b_i` comes before flow `a_i`.
    kicks: [f64; MAX_STAGES + 1],
}

/// The most free flows a step of any scheme takes (Kahan and Li's seventeen).
const MAX_STAGES: usize = 2 * MAX_HALF - 1;

impl ExactSplitting {
    /// The Strang splitting (order 2) with sub-steps of at most `step` (finite, positive).
    pub fn new(step: f64) -> Result<Self, Error> {
        Self::with_order(step, 2)
    }

    /// The splitting raised to `order` (2, 4, 6 or 8): Strang's splitting for 2; for 4
    /// and 6 Blanes and Moan's Runge-Kutta-Nystrom splittings [`Nystrom::BLANES_MOAN_6`]
    /// and [`Nystrom::BLANES_MOAN_11`]; for 8 Kahan and Li's composition
    /// [`Composition::KAHAN_LI_8`] of Strang's splitting.
    ///
    /// The Nystrom splittings have their own coefficients for kicks and flows, which
    /// meet fewer order conditions because a torque that does not depend on `Omega`
    /// (the only case where the kick is exact) makes `[B, [B, [B, A]]] = 0` for the kick
    /// `B` and the free flow `A`: the kick is linear in nothing but `R`, the free flow's
    /// field quadratic in `m`. On the report's heavy top they reach 1e-10 with about a
    /// third (order 4) and two fifths (order 6) of the flows of Suzuki's and Kahan and
    /// Li's compositions. No Nystrom splitting of order eight with published coefficients
    /// is carried here, so order 8 stays a composition.
    pub fn with_order(step: f64, order: u32) -> Result<Self, Error> {
        match order {
            4 => Self::with_nystrom(step, &Nystrom::BLANES_MOAN_6, "exact-splitting-4"),
            6 => Self::with_nystrom(step, &Nystrom::BLANES_MOAN_11, "exact-splitting-6"),
            _ => Self::composed(step, order),
        }
    }

    /// Strang's splitting composed by [`Composition::of_order`] (2, 4, 6 or 8).
    pub fn composed(step: f64, order: u32) -> Result<Self, Error> {
        let step = check_step(step)?;
        let scheme = Composition::of_order(order)?;
        // Strang's kick(g/2) flow(g) kick(g/2) per stage, the touching kicks merged.
        let stages = scheme.stages();
        let mut frees = [0.0; MAX_STAGES];
        let mut kicks = [0.0; MAX_STAGES + 1];
        for (i, g) in scheme.gammas().enumerate() {
            frees[i] = g;
            kicks[i] += 0.5 * g;
            kicks[i + 1] += 0.5 * g;
        }
        Ok(ExactSplitting {
            step,
            order,
            name: match order {
                2 => "exact-splitting",
                4 => "exact-splitting-4",
                6 => "exact-splitting-6",
                _ => "exact-splitting-8",
            },
            stages,
            frees,
            kicks,
        })
    }

    /// The Runge-Kutta-Nystrom splitting `nystrom`, kick first, with sub-steps of at most
    /// `step`, under the method name `name`.
    pub fn with_nystrom(step: f64, nystrom: &Nystrom, name: &'static str) -> Result<Self, Error> {
        let step = check_step(step)?;
        let stages = nystrom.stages();
        let mut frees = [0.0; MAX_STAGES];
        let mut kicks = [0.0; MAX_STAGES + 1];
        for (i, free) in frees.iter_mut().enumerate().take(stages) {
            *free = nystrom.a(i);
        }
        for (i, kick) in kicks.iter_mut().enumerate().take(stages + 1) {
            *kick = nystrom.b(i);
        }
        Ok(ExactSplitting {
            step,
            order: nystrom.order(),
            name,
            stages,
            frees,
            kicks,
        })
    }

    /// The largest sub-step.
    #[must_use]
    pub fn step(&self) -> f64 {
        self.step
    }

    /// The order of the method.
    #[must_use]
    pub fn order(&self) -> u32 {
        self.order
    }

    /// The exact free flow over `tau`, on the rotor and the body momentum. `memo` holds the
    /// last spin angle this stage saw and its cosine and sine (see [`SpinMemo`]).
    #[inline(always)]
    fn free(flow: &FreeFlow, tau: f64, rotor: &mut Rotor, m: &mut [f64; 3], memo: &mut SpinMemo) {
        match *flow {
            FreeFlow::Symmetric {
                axis,
                precession,
                spin,
            } => {
                // The symmetric top's closed form (the lecture's, as in `SymmetricTop`):
                // R(tau) = exp(-L tau / 2 i_p) R exp(-Omega_r tau / 2) with
                // Omega_r = w_a (i_p - i_a) / i_p I e_a. Since L = R m ~R,
                // exp(a L) R = R exp(a m): both factors act on the right, in the body frame,
                // with no sandwich to form L (docs/derivations/symmetric-top.md).
                // Inline rather than through `exact_free_body`, which spends twice as long
                // on quaternion conversions and on classifying the body.
                let body_momentum = omega_from_vector(*m);
                let size = (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]).sqrt();
                let angle = precession * tau * size;
                // The reciprocal before the sine, so that the division overlaps it rather
                // than waiting for it.
                let inverse = 1.0 / size;
                let (sin, cos) = sin_cos(angle);
                // sin(a |m|) / |m|, which tends to a as |m| -> 0.
                let sinc = if size > 0.0 {
                    sin * inverse
                } else {
                    precession * tau
                };
                let precess = Rotor::new(
                    cos,
                    sinc * body_momentum.e12,
                    sinc * body_momentum.e13,
                    sinc * body_momentum.e23,
                );
                // exp(phi I e_a) = cos phi + sin phi I e_a, phi = spin m_a tau; the body
                // momentum turns about e_a by -2 phi, so one sine and cosine serve both
                // (the double-angle formulas).
                let (sn, cs) = memo.sin_cos(spin * m[axis] * tau);
                let mut e = [0.0; 3];
                e[axis] = sn;
                let plane = omega_from_vector(e);
                let turn = Rotor::new(cs, plane.e12, plane.e13, plane.e23);
                *rotor *= precess * turn;
                // Turned component by component, m_a stays exactly as it is (a sandwich
                // would let it drift by rounding, 1e-11 over 10^5 stages on the Lagrange
                // top).
                let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
                let (sn2, cs2) = (2.0 * sn * cs, (cs - sn) * (cs + sn));
                let (ma, mb) = (m[a], m[b]);
                m[a] = cs2 * ma - sn2 * mb;
                m[b] = sn2 * ma + cs2 * mb;
            }
            FreeFlow::Elliptic(moments) => {
                let r = *rotor;
                let (r1, m1) = exact_free_body(moments, *m, [r.s, r.e12, r.e13, r.e23], tau);
                *rotor = Rotor::new(r1[0], r1[1], r1[2], r1[3]);
                *m = m1;
            }
        }
    }

    /// The torque kick `m += tau(R) dt` at time `t`, with `Omega = I^-1 m` formed by
    /// products with the inverse moments.
    #[inline(always)]
    fn kick(body: &RigidBody, inverse: [f64; 3], t: f64, dt: f64, rotor: Rotor, m: &mut [f64; 3]) {
        let omega = omega_from_vector(std::array::from_fn(|k| m[k] * inverse[k]));
        let tau = omega_to_vector(body.torque(t, &State { rotor, omega }));
        for k in 0..3 {
            m[k] += dt * tau[k];
        }
    }
}

/// Below this angle [`sin_cos`] sums Taylor polynomials; above it, it calls the library.
const SMALL_ANGLE: f64 = 0.5;

/// `1 / n!` for `n = 0..=17` (the factorials are exact in f64, the divisions correctly
/// rounded).
const INVERSE_FACTORIALS: [f64; 18] = {
    let mut table = [1.0; 18];
    let mut factorial = 1.0;
    let mut n = 1;
    while n < 18 {
        factorial *= n as f64;
        table[n] = 1.0 / factorial;
        n += 1;
    }
    table
};

/// `(sin x, cos x)`. A sub-step's precession angle is small, where the Taylor polynomials
/// to `x^17` and `x^16` are exact to rounding (the first terms left out, `0.5^19 / 19!`
/// and `0.5^18 / 18!`, are below 1e-21) and cost one shared chain of multiply-adds
/// instead of the library's separate `sin` and `cos` calls with their range reductions;
/// larger angles go to the library.
#[inline(always)]
fn sin_cos(x: f64) -> (f64, f64) {
    if x.abs() > SMALL_ANGLE {
        return x.sin_cos();
    }
    let c = &INVERSE_FACTORIALS;
    let x2 = x * x;
    let mut sin = c[17];
    let mut cos = c[16];
    for k in (0..8).rev() {
        sin = c[2 * k + 1] - x2 * sin;
        cos = c[2 * k] - x2 * cos;
    }
    (x * sin, cos)
}

/// The cosine and sine of the last spin angle one stage of a composition saw. A stage
/// of every step flows over the same length, and under a torque with no component about
/// the symmetry axis (gravity on a Lagrange top) `m_a` does not change, so the angle
/// repeats bit for bit and its sine and cosine need not be formed again. A different angle
/// is simply computed; the values are the same either way.
#[derive(Clone, Copy, Debug)]
struct SpinMemo {
    angle: f64,
    sin: f64,
    cos: f64,
}

impl SpinMemo {
    const EMPTY: SpinMemo = SpinMemo {
        angle: 0.0,
        sin: 0.0,
        cos: 1.0,
    };

    #[inline]
    fn sin_cos(&mut self, angle: f64) -> (f64, f64) {
        if angle.to_bits() != self.angle.to_bits() {
            (self.sin, self.cos) = angle.sin_cos();
            self.angle = angle;
        }
        (self.sin, self.cos)
    }
}

/// The free flow chosen once per call: the closed form of a symmetric body, or the
/// elliptic flow.
#[derive(Clone, Copy, Debug)]
enum FreeFlow {
    Symmetric {
        /// The symmetry axis (0, 1, 2).
        axis: usize,
        /// `-1 / (2 i_p)`: `left = exp(precession tau L)`.
        precession: f64,
        /// `-(i_p - i_a) / (2 i_a i_p)`: `right = exp(spin m_a tau I e_a)`.
        spin: f64,
    },
    Elliptic([f64; 3]),
}

impl FreeFlow {
    fn of(body: &RigidBody) -> FreeFlow {
        let moments = body.moments();
        match body.symmetry_axis(DEFAULT_SYMMETRY_TOLERANCE) {
            Some(axis) => {
                let (i_a, i_p) = (moments[axis], moments[(axis + 1) % 3]);
                FreeFlow::Symmetric {
                    axis,
                    precession: -0.5 / i_p,
                    spin: -0.5 * (i_p - i_a) / (i_a * i_p),
                }
            }
            None => FreeFlow::Elliptic(moments),
        }
    }
}

impl Integrator for ExactSplitting {
    fn name(&self) -> &'static str {
        self.name
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        let (n, h) = substeps(self.step, dt)?;
        if n == 0 {
            return check_finite(self.name(), state);
        }
        let moments = body.moments();
        let w = omega_to_vector(state.omega);
        let mut m: [f64; 3] = std::array::from_fn(|k| moments[k] * w[k]);
        let mut rotor = state.rotor;
        let flow = FreeFlow::of(body);
        let inverse = moments.map(|i| 1.0 / i);
        // One memo per distinct sub-step: stage i and its mirror s - 1 - i flow alike.
        let mut memos = [SpinMemo::EMPTY; MAX_HALF];
        let stages = self.stages;
        if body.has_torque() {
            // The kick still owed at the current time: the closing kick of the last step,
            // which acts at the same time and attitude as the opening kick of the next.
            let mut owed = 0.0;
            let mut time = t;
            for i in 0..n {
                let start = t + i as f64 * h;
                let mut offset = 0.0;
                for j in 0..stages {
                    let tau = self.frees[j] * h;
                    Self::kick(body, inverse, time, owed + self.kicks[j] * h, rotor, &mut m);
                    let memo = &mut memos[j.min(stages - 1 - j)];
                    Self::free(&flow, tau, &mut rotor, &mut m, memo);
                    offset += tau;
                    time = start + offset;
                    owed = 0.0;
                }
                owed = self.kicks[stages] * h;
                // Land each step on its grid time rather than on the sum of the stages, and
                // keep the rotor unit against the rounding of the closed form's products.
                time = start + h;
                if matches!(flow, FreeFlow::Symmetric { .. }) {
                    rotor = unit(rotor);
                }
            }
            Self::kick(body, inverse, time, owed, rotor, &mut m);
        } else {
            // No kicks: the free flows of every stage compose exactly into one.
            Self::free(&flow, dt, &mut rotor, &mut m, &mut memos[0]);
        }
        let omega = omega_from_vector(std::array::from_fn(|k| m[k] / moments[k]));
        check_finite(self.name(), State { rotor, omega })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The Taylor branch agrees with the library to a rounding or two over its whole range,
    /// and larger angles go to the library.
    #[test]
    fn small_angle_sin_cos_matches_the_library() {
        let n = 10_000;
        for i in -n..=n {
            let x = SMALL_ANGLE * f64::from(i) / f64::from(n);
            let (s, c) = sin_cos(x);
            let (s_ref, c_ref) = x.sin_cos();
            assert!(
                (s - s_ref).abs() <= 2.0 * f64::EPSILON * s_ref.abs(),
                "sin {x}: {s} vs {s_ref}"
            );
            assert!((c - c_ref).abs() <= f64::EPSILON, "cos {x}: {c} vs {c_ref}");
        }
        let above = SMALL_ANGLE.next_up();
        assert_eq!(sin_cos(above), above.sin_cos());
        assert_eq!(sin_cos(-3.0), (-3.0f64).sin_cos());
    }

    #[test]
    fn the_spin_memo_recomputes_a_new_angle() {
        let mut memo = SpinMemo::EMPTY;
        assert_eq!(memo.sin_cos(0.25), 0.25f64.sin_cos());
        assert_eq!(memo.sin_cos(0.25), 0.25f64.sin_cos());
        assert_eq!(memo.sin_cos(-0.3), (-0.3f64).sin_cos());
        assert_eq!(memo.sin_cos(0.0), (0.0, 1.0));
    }
}
