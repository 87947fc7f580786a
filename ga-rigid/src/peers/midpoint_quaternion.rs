//! The implicit midpoint rule on the quaternion form, as a user of a general-purpose
//! implicit integrator writes it: seven unknowns, the body angular momentum `m` and a
//! quaternion `q` (body to space),
//!
//! ```text
//! m' = m x w + tau,   q' = q (0, w) / 2,   w = J^-1 m,
//! y1 = y0 + h f(t + h/2, (y0 + y1) / 2),
//! ```
//!
//! (E. Hairer, C. Lubich, G. Wanner, *Geometric Numerical Integration*, 2nd ed., Springer
//! 2006, sections II.1 and IV.2: symmetric, symplectic, of order two, and it keeps every
//! quadratic invariant, here `|m|^2`, the energy `m . J^-1 m` and `|q|^2`, to the accuracy
//! of the solve). Issue 18 names it as the rotation step of Genesis and Roblox; that
//! attribution is the issue's, not checked here against their sources.
//!
//! The seven equations are solved by Newton's method to rounding (a correction at most
//! four ulps of the unknowns). The Jacobian is exact for the free body and block
//! triangular, `[[A, 0], [C, D]]`: `A = 1 - h/2 d(m x w)/dm`, `C` the quaternion's
//! dependence on `m`, `D = 1 - h/4 [. (0, w)]`; `D` is inverted in closed form, since right
//! multiplication by a pure quaternion squares to `-|w|^2`. A torque enters the residual
//! but not the Jacobian (a quasi-Newton iteration, fixed-point in the torque), as in
//! [`crate::integrators::ImplicitMidpoint`]. The torque is read at the midpoint state, its
//! quaternion `(q0 + q1)/2` as it stands. The quaternion is renormalised only at output
//! (the end of each [`Integrator::advance`]), as a user would; between sub-steps of one
//! call it is carried as the solve leaves it.
//!
//! Unlike our `midpoint` (the same rule with the attitude part in closed form, Cayley's
//! transform, and three unknowns), this is the seven-unknown solve a user sets up.

use ga_core::f64::g3::Rotor;

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::{self, Error};
use crate::integrators::{check_finite, check_step, substeps, Integrator};

use super::buss::cross;
use super::gyroscopic_euler::solve3;

/// The most Newton iterations per step before the step is reported as failed.
const MAX_ITERATIONS: usize = 50;

/// The implicit midpoint rule on the seven-unknown quaternion form, fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct QuaternionMidpoint {
    step: f64,
    iterations: u64,
}

impl QuaternionMidpoint {
    /// The method with fixed step `h` (finite and positive).
    pub fn new(h: f64) -> Result<Self, Error> {
        Ok(Self {
            step: check_step(h)?,
            iterations: 0,
        })
    }

    /// The Newton iterations taken so far, over every step.
    #[must_use]
    pub fn iterations(&self) -> u64 {
        self.iterations
    }
}

/// The seven unknowns: body momentum and quaternion `[w, x, y, z]` (glam's components).
#[derive(Clone, Copy, Debug, PartialEq)]
struct Y {
    m: [f64; 3],
    q: [f64; 4],
}

/// `p (0, v)`, the quaternion product with a pure quaternion on the right.
fn times_pure(p: [f64; 4], v: [f64; 3]) -> [f64; 4] {
    let [w, x, y, z] = p;
    [
        -x * v[0] - y * v[1] - z * v[2],
        w * v[0] + y * v[2] - z * v[1],
        w * v[1] + z * v[0] - x * v[2],
        w * v[2] + x * v[1] - y * v[0],
    ]
}

/// The rotor of a quaternion in glam's components, as it stands (not normalised).
fn rotor_of(q: [f64; 4]) -> Rotor {
    Rotor::new(q[0], -q[3], q[2], -q[1])
}

fn to_y(body: &RigidBody, state: &State) -> Y {
    let j = body.moments();
    let w = omega_to_vector(state.omega);
    let r = state.rotor;
    Y {
        m: [j[0] * w[0], j[1] * w[1], j[2] * w[2]],
        q: [r.s, -r.e23, r.e13, -r.e12],
    }
}

/// The state at output: the quaternion normalised.
fn state_of(body: &RigidBody, y: &Y) -> State {
    let j = body.moments();
    let rotor = rotor_of(y.q);
    State {
        rotor: rotor / rotor.norm(),
        omega: omega_from_vector([y.m[0] / j[0], y.m[1] / j[1], y.m[2] / j[2]]),
    }
}

/// One midpoint step of length `h` from `y0` at time `t`, and the Newton iterations it
/// took; an error if Newton's method does not converge.
fn step_once(body: &RigidBody, t: f64, y0: Y, h: f64) -> Result<(Y, usize), Error> {
    let j = body.moments();
    let t_mid = t + 0.5 * h;
    let mut y = y0;
    let mut previous = f64::INFINITY;
    for iteration in 1..=MAX_ITERATIONS {
        let m_mid: [f64; 3] = std::array::from_fn(|k| 0.5 * (y0.m[k] + y.m[k]));
        let q_mid: [f64; 4] = std::array::from_fn(|k| 0.5 * (y0.q[k] + y.q[k]));
        let w: [f64; 3] = std::array::from_fn(|k| m_mid[k] / j[k]);
        let tau = if body.has_torque() {
            let mid = State {
                rotor: rotor_of(q_mid),
                omega: omega_from_vector(w),
            };
            omega_to_vector(body.torque(t_mid, &mid))
        } else {
            [0.0; 3]
        };
        let gyro = cross(m_mid, w);
        let dq = times_pure(q_mid, w);
        let r_m: [f64; 3] = std::array::from_fn(|k| y.m[k] - y0.m[k] - h * (gyro[k] + tau[k]));
        let r_q: [f64; 4] = std::array::from_fn(|k| y.q[k] - y0.q[k] - 0.5 * h * dq[k]);
        // A = 1 - h/2 G, G = d(m x J^-1 m)/dm = -[w]x + [m]x J^-1.
        let skew = |a: [f64; 3]| [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]];
        let (sw, sm) = (skew(w), skew(m_mid));
        let a: [[f64; 3]; 3] = std::array::from_fn(|r| {
            std::array::from_fn(|c| {
                let g = -sw[r][c] + sm[r][c] / j[c];
                f64::from(u8::from(r == c)) - 0.5 * h * g
            })
        });
        let delta_m = solve3(a, r_m).ok_or_else(|| {
            Error::invalid(
                "midpoint-quaternion",
                "the Newton matrix of the momentum equations is singular",
            )
        })?;
        // D delta_q = r_q - C delta_m, C delta_m = -h/4 q_mid (0, J^-1 delta_m), and
        // D^-1 = (1 + a W) / (1 + a^2 |w|^2) for D = 1 - a W, W p = p (0, w), a = h/4.
        let coupling = times_pure(q_mid, std::array::from_fn(|k| delta_m[k] / j[k]));
        let rhs: [f64; 4] = std::array::from_fn(|k| r_q[k] + 0.25 * h * coupling[k]);
        let aw = 0.25 * h;
        let turned = times_pure(rhs, w);
        let w2 = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
        let delta_q: [f64; 4] =
            std::array::from_fn(|k| (rhs[k] + aw * turned[k]) / (1.0 + aw * aw * w2));
        for (x, d) in y.m.iter_mut().zip(delta_m) {
            *x -= d;
        }
        for (x, d) in y.q.iter_mut().zip(delta_q) {
            *x -= d;
        }
        let norm = |v: &[f64]| v.iter().map(|x| x * x).sum::<f64>().sqrt();
        let m_scale = norm(&y.m);
        let m_size = if m_scale > 0.0 {
            norm(&delta_m) / m_scale
        } else {
            norm(&delta_m)
        };
        let size = m_size.max(norm(&delta_q) / norm(&y.q));
        // Converged to rounding, or stagnated at the rounding floor of the residual.
        if size <= 4.0 * f64::EPSILON || (size >= previous && size <= 1e-10) {
            return Ok((y, iteration));
        }
        if !size.is_finite() {
            break;
        }
        previous = size;
    }
    Err(Error::invalid(
        "midpoint-quaternion",
        format!(
            "Newton's method found no midpoint in {MAX_ITERATIONS} iterations at t = {} \
             with step {}; take a smaller step",
            error::num(t),
            error::num(h)
        ),
    ))
}

impl Integrator for QuaternionMidpoint {
    fn name(&self) -> &'static str {
        "midpoint-quaternion"
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        let (n, h) = substeps(self.step, dt)?;
        let mut y = to_y(body, &state);
        for i in 0..n {
            let (next, taken) = step_once(body, t + i as f64 * h, y, h)?;
            self.iterations += taken as u64;
            y = next;
        }
        check_finite(self.name(), state_of(body, &y))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::dynamics::Torque;
    use ga_core::f64::g3::Bivector;

    /// A body-frame torque `(cos t, sin 2t, 1 - t)`, the same in every state.
    struct Timed;

    impl Torque for Timed {
        fn torque(&self, t: f64, _rotor: Rotor, _omega: Bivector) -> Bivector {
            omega_from_vector([t.cos(), (2.0 * t).sin(), 1.0 - t])
        }
    }

    /// On a sphere (unit moments) `m x w = 0`, so `m(t) = m0 + int_0^t tau`, here
    /// `(sin t, (1 - cos 2t)/2, t - t^2/2)`. The midpoint rule reads the torque at
    /// `t + h/2`, the midpoint quadrature, of order two: the error at `t = 2` falls by four
    /// when `h` halves. A torque read at `t + h` is a rectangle rule, of order one.
    #[test]
    fn a_time_dependent_torque_is_read_at_the_midpoint_time() {
        let body = RigidBody::new([1.0, 1.0, 1.0]).unwrap().with_torque(Timed);
        let m0 = [0.3, -0.2, 0.5];
        let state = State {
            rotor: Rotor::ONE,
            omega: omega_from_vector(m0),
        };
        let t = 2.0_f64;
        let exact = [
            m0[0] + t.sin(),
            m0[1] + 0.5 * (1.0 - (2.0 * t).cos()),
            m0[2] + t - 0.5 * t * t,
        ];
        let error = |h: f64| {
            let end = QuaternionMidpoint::new(h)
                .unwrap()
                .advance(&body, 0.0, state, t)
                .unwrap();
            let m = omega_to_vector(end.omega);
            (0..3).map(|k| (m[k] - exact[k]).abs()).fold(0.0, f64::max)
        };
        let (coarse, fine) = (error(0.1), error(0.05));
        let order = (coarse / fine).log2();
        assert!(
            (order - 2.0).abs() < 0.1,
            "order {order} ({coarse:e}, {fine:e})"
        );
        assert!(coarse < 2e-3, "{coarse:e}");
    }

    /// `q (0, v)` is the rotor equation `dR/dt = -1/2 R Omega` in glam's components: the
    /// quaternion form and the rotor form describe the same motion.
    #[test]
    fn the_quaternion_product_is_the_rotor_product() {
        let q = [0.3, -0.5, 0.7, 0.1];
        let v = [1.3, -0.4, 2.0];
        let rotor = rotor_of(q);
        let expected = rotor * omega_from_vector(v) * -1.0;
        let got = rotor_of(times_pure(q, v));
        assert!((got - expected).norm() < 1e-15, "{got:?} {expected:?}");
    }

    /// The solve leaves the midpoint equation's residual at rounding, and the quadratic
    /// invariants with it.
    #[test]
    fn one_step_solves_the_midpoint_equation() {
        let body = RigidBody::new_unphysical([0.6, 0.8, 1.0]).unwrap();
        let state = State {
            rotor: Rotor::ONE,
            omega: omega_from_vector([1.8, 0.4, -0.9]),
        };
        let y0 = to_y(&body, &state);
        let h = 0.2;
        let (y1, iterations) = step_once(&body, 0.0, y0, h).unwrap();
        assert!(iterations <= 8, "{iterations}");
        let j = body.moments();
        let m: [f64; 3] = std::array::from_fn(|k| 0.5 * (y0.m[k] + y1.m[k]));
        let q: [f64; 4] = std::array::from_fn(|k| 0.5 * (y0.q[k] + y1.q[k]));
        let w: [f64; 3] = std::array::from_fn(|k| m[k] / j[k]);
        let g = cross(m, w);
        let dq = times_pure(q, w);
        let residual_m = (0..3).map(|k| (y1.m[k] - y0.m[k] - h * g[k]).abs());
        let residual_q = (0..4).map(|k| (y1.q[k] - y0.q[k] - 0.5 * h * dq[k]).abs());
        let worst = residual_m.chain(residual_q).fold(0.0, f64::max);
        assert!(worst < 1e-15, "{worst:e}");
        let q_norm = y1.q.iter().map(|x| x * x).sum::<f64>();
        assert!((q_norm - 1.0).abs() < 1e-15, "{q_norm}");
    }
}
