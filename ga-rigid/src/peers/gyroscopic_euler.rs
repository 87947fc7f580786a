//! The gyroscopic Euler steps of game and robotics engines, in the body frame.
//!
//! Both advance the angular velocity first and then the orientation with the new one,
//! `q1 = normalise(q0 + h/2 q0 (0, w1))` (in rotor form `R1 = unit(R0 - h/2 R0 Omega1)`),
//! the semi-implicit Euler of engines' integrators.
//!
//! - Explicit: `w1 = w0 + h J^-1 (tau - w0 x J w0)`, the gyroscopic term as most engines
//!   had it before an implicit option (Catto, "Numerical Methods", GDC 2015, slide
//!   "Gyroscopic Torque").
//! - Implicit: the gyroscopic part solved backward, `J (w1 - w0) + h w1 x J w1 = 0`, with
//!   one Newton iteration from `w0` (Catto 2015; Bullet's
//!   `btRigidBody::computeGyroscopicImpulseImplicit_Body`, Jolt's "Compute gyroscopic
//!   forces"); the torque is then added explicitly, `w1 += h J^-1 tau`. It damps the
//!   tumbling (the Dzhanibekov flip stops) where the explicit step gains energy.

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::Error;
use crate::integrators::Integrator;

use super::buss::{cross, rotated_by_velocity};
use crate::integrators::{check_step, fixed_steps};

/// The explicit gyroscopic Euler step of engines, fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ExplicitGyroscopicEuler {
    step: f64,
}

impl ExplicitGyroscopicEuler {
    /// The method with fixed step `h` (finite and positive).
    pub fn new(h: f64) -> Result<Self, Error> {
        Ok(Self {
            step: check_step(h)?,
        })
    }
}

/// The implicit gyroscopic Euler step (one Newton iteration), fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ImplicitGyroscopicEuler {
    step: f64,
}

impl ImplicitGyroscopicEuler {
    /// The method with fixed step `h` (finite and positive).
    pub fn new(h: f64) -> Result<Self, Error> {
        Ok(Self {
            step: check_step(h)?,
        })
    }
}

/// `J^-1 v` and `J v` for the body's principal moments.
fn scale(v: [f64; 3], k: [f64; 3]) -> [f64; 3] {
    [v[0] * k[0], v[1] * k[1], v[2] * k[2]]
}

fn explicit_step(body: &RigidBody, t: f64, state: State, h: f64) -> State {
    let j = body.moments();
    let w = omega_to_vector(state.omega);
    let tau = omega_to_vector(body.torque(t, &state));
    let gyro = cross(w, scale(w, j));
    let w1: [f64; 3] = std::array::from_fn(|k| w[k] + h * (tau[k] - gyro[k]) / j[k]);
    State {
        rotor: rotated_by_velocity(state.rotor, w1, h),
        omega: omega_from_vector(w1),
    }
}

/// Solve the 3x3 system `a x = b` by Cramer's rule; `None` when `a` is singular.
pub(super) fn solve3(a: [[f64; 3]; 3], b: [f64; 3]) -> Option<[f64; 3]> {
    let det = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let d = det(a);
    if d == 0.0 || !d.is_finite() {
        return None;
    }
    Some(std::array::from_fn(|col| {
        let mut m = a;
        for (row, value) in m.iter_mut().zip(b) {
            row[col] = value;
        }
        det(m) / d
    }))
}

/// The cross-product matrix: `skew(a) b = a x b`.
fn skew(a: [f64; 3]) -> [[f64; 3]; 3] {
    [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]]
}

fn implicit_step(body: &RigidBody, t: f64, state: State, h: f64) -> Result<State, Error> {
    let j = body.moments();
    let w = omega_to_vector(state.omega);
    let jw = scale(w, j);
    // f(w) = J (w - w0) + h w x J w; f(w0) = h w0 x J w0, and
    // f'(w0) = J + h (skew(w0) J - skew(J w0)).
    let f = cross(w, jw).map(|x| h * x);
    let (sw, sjw) = (skew(w), skew(jw));
    let jacobian: [[f64; 3]; 3] = std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            let diagonal = if r == c { j[r] } else { 0.0 };
            diagonal + h * (sw[r][c] * j[c] - sjw[r][c])
        })
    });
    let delta = solve3(jacobian, f).ok_or_else(|| {
        Error::invalid(
            "euler-gyro-implicit",
            "the Newton matrix J + h (skew(w) J - skew(J w)) is singular",
        )
    })?;
    let tau = omega_to_vector(body.torque(t, &state));
    let w1: [f64; 3] = std::array::from_fn(|k| w[k] - delta[k] + h * tau[k] / j[k]);
    Ok(State {
        rotor: rotated_by_velocity(state.rotor, w1, h),
        omega: omega_from_vector(w1),
    })
}

impl Integrator for ExplicitGyroscopicEuler {
    fn name(&self) -> &'static str {
        "euler-gyro-explicit"
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        fixed_steps(self.name(), self.step, t, state, dt, |t, s, h| {
            Ok(explicit_step(body, t, s, h))
        })
    }
}

impl Integrator for ImplicitGyroscopicEuler {
    fn name(&self) -> &'static str {
        "euler-gyro-implicit"
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        fixed_steps(self.name(), self.step, t, state, dt, |t, s, h| {
            implicit_step(body, t, s, h)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solve3_inverts_a_known_system() {
        let a = [[2.0, 1.0, 0.0], [1.0, 3.0, 1.0], [0.0, 1.0, 4.0]];
        let x = [1.0, -2.0, 0.5];
        let b: [f64; 3] = std::array::from_fn(|r| (0..3).map(|c| a[r][c] * x[c]).sum());
        let y = solve3(a, b).unwrap();
        for k in 0..3 {
            assert!((y[k] - x[k]).abs() < 1e-14, "{y:?}");
        }
        assert!(solve3([[1.0, 2.0, 3.0], [2.0, 4.0, 6.0], [0.0, 0.0, 1.0]], b).is_none());
    }

    /// One Newton iteration from `w0` leaves the implicit equation's residual
    /// `J (w1 - w0) + h w1 x J w1` at `O(h^3)`: the start is `O(h)` off, Newton squares
    /// that, and the equation's curvature is `O(h)` (an explicit step would leave `O(h^2)`).
    #[test]
    fn the_newton_iteration_leaves_a_third_order_residual() {
        let body = RigidBody::new_unphysical([0.6, 0.8, 1.0]).unwrap();
        let w0 = [1.8, 0.4, -0.9];
        let state = State {
            rotor: ga_core::f64::g3::Rotor::ONE,
            omega: omega_from_vector(w0),
        };
        let residual = |h: f64| {
            let w1 = omega_to_vector(implicit_step(&body, 0.0, state, h).unwrap().omega);
            let j = body.moments();
            let g = cross(w1, scale(w1, j));
            (0..3)
                .map(|k| (j[k] * (w1[k] - w0[k]) + h * g[k]).powi(2))
                .sum::<f64>()
                .sqrt()
        };
        let ratio = residual(1e-2) / residual(5e-3);
        assert!((ratio - 8.0).abs() < 0.4, "ratio {ratio}");
    }
}
