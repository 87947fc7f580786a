//! The discrete Moser-Veselov step for the free rigid body: J. Moser, A. P. Veselov,
//! "Discrete versions of some classical integrable systems and factorization of matrix
//! polynomials", Comm. Math. Phys. 139 (1991) 217-243; equivalent to RATTLE on the
//! rotation matrix (McLachlan and Scovel 1995; B. Leimkuhler, S. Reich, *Simulating
//! Hamiltonian Dynamics*, Cambridge 2004, chapter 8), and revisited by R. I. McLachlan,
//! A. Zanna, "The discrete Moser-Veselov algorithm for the free rigid body, revisited",
//! Found. Comput. Math. 5 (2005) 87-123. In the form of E. Hairer, C. Lubich, G. Wanner,
//! *Geometric Numerical Integration*, 2nd ed., Springer 2006, section VII.5.3, with body
//! momentum `m`, attitude `Q` (body to space) and `D = diag(d_k)`, `d_k = tr(J)/2 - J_k`:
//!
//! ```text
//! h hat(m_n) = Omega D - D Omega^T,   Q_(n+1) = Q_n Omega,   m_(n+1) = Omega^T m_n,
//! ```
//!
//! with `Omega` orthogonal. Writing `Omega` by its unit quaternion `(e0, e)`,
//! `Omega = 1 + 2 e0 hat(e) + 2 hat(e)^2`, the first equation becomes three equations in
//! `e`: `h m_n / 2 = e0 J e + e x J e`, `e0 = sqrt(1 - |e|^2)` (`J` the principal moments;
//! docs/references.md). They are solved here by Newton's method to rounding from
//! `e = h w / 2`. The step is symmetric and of order two. It keeps the space angular
//! momentum `L = Q m` to rounding whatever the solve leaves (`Omega` is applied to `Q` and
//! its transpose to `m`, so `Q_(n+1) m_(n+1) = Q_n m_n` up to the rounding of the two
//! products), hence `|m|` too; the kinetic energy stays at rounding as well (measured in
//! `tests/peers.rs` and `engine_runs.csv`; the discrete system is integrable, Moser and
//! Veselov). Its error is in the phase: about a principal axis the equation reads
//! `sin(theta) J_3 = h m_3`, so a step turns by `asin(h w)` instead of `h w` and has no
//! solution beyond `h |w| = 1`.
//!
//! Under a torque it is the free part of Strang's splitting with a torque kick,
//! `kick(h/2) DMV(h) kick(h/2)` with `m += h/2 tau(t, R)` in the body frame (as
//! [`crate::integrators::ExactSplitting`] uses the exact free flow), symmetric and of
//! order two for a torque that does not depend on `Omega`.

use ga_core::f64::g3::Rotor;

use crate::dynamics::{omega_from_vector, omega_to_vector, RigidBody, State};
use crate::error::{self, Error};
use crate::integrators::{check_step, fixed_steps, Integrator};

use super::buss::cross;
use super::gyroscopic_euler::solve3;

/// The most Newton iterations per step before the step is reported as failed.
const MAX_ITERATIONS: usize = 50;

/// The discrete Moser-Veselov step (with torque kicks under a torque), fixed step `h`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MoserVeselov {
    step: f64,
}

impl MoserVeselov {
    /// The method with fixed step `h` (finite and positive).
    pub fn new(h: f64) -> Result<Self, Error> {
        Ok(Self {
            step: check_step(h)?,
        })
    }
}

/// The Newton correction for `e` in `h m / 2 = e0 J e + e x J e` with
/// `e0 = sqrt(1 - |e|^2)` (`target = h m / 2`), to be subtracted from `e`; `None` when
/// `|e| >= 1` or the Jacobian is singular.
fn newton_correction(j: [f64; 3], target: [f64; 3], e: [f64; 3]) -> Option<[f64; 3]> {
    let e2 = e[0] * e[0] + e[1] * e[1] + e[2] * e[2];
    if e2 >= 1.0 {
        return None;
    }
    let e0 = (1.0 - e2).sqrt();
    let je: [f64; 3] = std::array::from_fn(|k| j[k] * e[k]);
    let turn = cross(e, je);
    let residual: [f64; 3] = std::array::from_fn(|k| e0 * je[k] + turn[k] - target[k]);
    // d/de: e0 J - (J e) e^T / e0 + [e]x J - [J e]x.
    let skew = |a: [f64; 3]| [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]];
    let (se, sje) = (skew(e), skew(je));
    let jacobian: [[f64; 3]; 3] = std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            let diagonal = if r == c { e0 * j[r] } else { 0.0 };
            diagonal - je[r] * e[c] / e0 + se[r][c] * j[c] - sje[r][c]
        })
    });
    solve3(jacobian, residual)
}

/// The vector part `e` of the quaternion of `Omega` solving `h m / 2 = e0 J e + e x J e`
/// with `e0 = sqrt(1 - |e|^2) > 0`, by Newton's method; `None` when it finds no solution.
fn solve_rotation(j: [f64; 3], m: [f64; 3], h: f64) -> Option<[f64; 3]> {
    let target: [f64; 3] = std::array::from_fn(|k| 0.5 * h * m[k]);
    let mut e: [f64; 3] = std::array::from_fn(|k| target[k] / j[k]);
    let mut previous = f64::INFINITY;
    for _ in 0..MAX_ITERATIONS {
        let delta = newton_correction(j, target, e)?;
        for (x, d) in e.iter_mut().zip(delta) {
            *x -= d;
        }
        let size = (delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2]).sqrt();
        let scale = (e[0] * e[0] + e[1] * e[1] + e[2] * e[2]).sqrt();
        // Converged to rounding, or stagnated at the rounding floor of the residual.
        if size <= 4.0 * f64::EPSILON * scale
            || (size >= previous && size <= 1e-10 * scale)
            || scale == 0.0
        {
            return (scale < 1.0).then_some(e);
        }
        if !size.is_finite() {
            return None;
        }
        previous = size;
    }
    None
}

/// One free DMV step of length `h` on body momentum `m` and attitude `rotor`.
fn free_step(
    j: [f64; 3],
    rotor: Rotor,
    m: [f64; 3],
    h: f64,
    t: f64,
) -> Result<(Rotor, [f64; 3]), Error> {
    let e = solve_rotation(j, m, h).ok_or_else(|| {
        let w: [f64; 3] = std::array::from_fn(|k| m[k] / j[k]);
        let rate = h * (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]).sqrt();
        Error::invalid(
            "moser-veselov",
            format!(
                "no rotation solves the Moser-Veselov equation at t = {} with step {} \
                 (h |w| = {}; about a principal axis a step exists only for h |w| <= 1); \
                 take a smaller step",
                error::num(t),
                error::num(h),
                error::num(rate)
            ),
        )
    })?;
    let e0 = (1.0 - (e[0] * e[0] + e[1] * e[1] + e[2] * e[2])).sqrt();
    // Omega^T m = m - 2 e0 e x m + 2 e x (e x m).
    let exm = cross(e, m);
    let exexm = cross(e, exm);
    let m1: [f64; 3] = std::array::from_fn(|k| m[k] - 2.0 * e0 * exm[k] + 2.0 * exexm[k]);
    // The quaternion (e0, e) in glam's components `w = s, x = -e23, y = e13, z = -e12`.
    let turn = Rotor::new(e0, -e[2], e[1], -e[0]);
    let rotor1 = rotor * turn;
    // The product is unit to rounding, which walks over many steps: scale back once a step.
    Ok((rotor1 / rotor1.norm(), m1))
}

fn step(body: &RigidBody, t: f64, state: State, h: f64) -> Result<State, Error> {
    let j = body.moments();
    let w = omega_to_vector(state.omega);
    let mut m: [f64; 3] = std::array::from_fn(|k| j[k] * w[k]);
    let torque = body.has_torque();
    if torque {
        let tau = omega_to_vector(body.torque(t, &state));
        for (x, t) in m.iter_mut().zip(tau) {
            *x += 0.5 * h * t;
        }
    }
    let (rotor, mut m) = free_step(j, state.rotor, m, h, t)?;
    let omega = |m: [f64; 3]| omega_from_vector(std::array::from_fn(|k| m[k] / j[k]));
    if torque {
        let tau = omega_to_vector(body.torque(
            t + h,
            &State {
                rotor,
                omega: omega(m),
            },
        ));
        for (x, t) in m.iter_mut().zip(tau) {
            *x += 0.5 * h * t;
        }
    }
    Ok(State {
        rotor,
        omega: omega(m),
    })
}

impl Integrator for MoserVeselov {
    fn name(&self) -> &'static str {
        "moser-veselov"
    }

    fn advance(&mut self, body: &RigidBody, t: f64, state: State, dt: f64) -> Result<State, Error> {
        fixed_steps(self.name(), self.step, t, state, dt, |t, s, h| {
            step(body, t, s, h)
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use ga_core::f64::g3::{Sandwich, Vector};

    /// Newton's method with the exact Jacobian converges quadratically: from `e = h J^-1 m
    /// / 2` at a large step (`|e|` near 0.4, where the `(J e) e^T / e0` term of the
    /// Jacobian is not small), each residual of `h m / 2 = e0 J e + e x J e` (written
    /// again here) is at most a modest multiple of the square of the one before, until
    /// rounding. A Jacobian missing a term converges only linearly.
    #[test]
    fn newtons_method_squares_the_residual_each_iteration() {
        let j = [0.6, 0.8, 1.0];
        let m = [1.08, 0.32, -0.9];
        let h = 0.4;
        let target: [f64; 3] = std::array::from_fn(|k| 0.5 * h * m[k]);
        let residual = |e: [f64; 3]| {
            let e0 = (1.0 - e.iter().map(|x| x * x).sum::<f64>()).sqrt();
            let je = [j[0] * e[0], j[1] * e[1], j[2] * e[2]];
            let exje = [
                e[1] * je[2] - e[2] * je[1],
                e[2] * je[0] - e[0] * je[2],
                e[0] * je[1] - e[1] * je[0],
            ];
            (0..3)
                .map(|k| (e0 * je[k] + exje[k] - target[k]).powi(2))
                .sum::<f64>()
                .sqrt()
        };
        let mut e: [f64; 3] = std::array::from_fn(|k| target[k] / j[k]);
        let mut norms = vec![residual(e)];
        while norms.len() < 8 && *norms.last().unwrap() > 1e-13 {
            let delta = newton_correction(j, target, e).unwrap();
            e = std::array::from_fn(|k| e[k] - delta[k]);
            norms.push(residual(e));
        }
        assert!(norms[0] > 0.02, "{norms:?}");
        assert!(*norms.last().unwrap() <= 1e-13, "{norms:?}");
        for pair in norms.windows(2) {
            if pair[1] > 1e-13 {
                assert!(pair[1] <= 3.0 * pair[0] * pair[0], "{norms:?}");
            }
        }
        assert!(norms.len() <= 6, "{norms:?}");
    }

    /// The quaternion equation is the matrix one: `Omega D - D Omega^T = h hat(m)` with
    /// `Omega = 1 + 2 e0 hat(e) + 2 hat(e)^2` and `D = tr(J)/2 - J`, checked with matrices.
    #[test]
    fn the_solved_rotation_meets_the_matrix_equation() {
        let j = [0.6, 0.8, 1.0];
        let m = [1.08, 0.32, -0.9];
        let h = 0.3;
        let e = solve_rotation(j, m, h).unwrap();
        let e0 = (1.0 - e.iter().map(|x| x * x).sum::<f64>()).sqrt();
        let hat = |a: [f64; 3]| [[0.0, -a[2], a[1]], [a[2], 0.0, -a[0]], [-a[1], a[0], 0.0]];
        let mul = |a: [[f64; 3]; 3], b: [[f64; 3]; 3]| -> [[f64; 3]; 3] {
            std::array::from_fn(|r| {
                std::array::from_fn(|c| (0..3).map(|k| a[r][k] * b[k][c]).sum())
            })
        };
        let he = hat(e);
        let he2 = mul(he, he);
        let omega: [[f64; 3]; 3] = std::array::from_fn(|r| {
            std::array::from_fn(|c| {
                f64::from(u8::from(r == c)) + 2.0 * e0 * he[r][c] + 2.0 * he2[r][c]
            })
        });
        let trace = j.iter().sum::<f64>();
        let d: [[f64; 3]; 3] = std::array::from_fn(|r| {
            std::array::from_fn(|c| if r == c { 0.5 * trace - j[r] } else { 0.0 })
        });
        let omega_t: [[f64; 3]; 3] = std::array::from_fn(|r| std::array::from_fn(|c| omega[c][r]));
        let (od, dot) = (mul(omega, d), mul(d, omega_t));
        let hm = hat(m);
        let pairs = || (0..3).flat_map(|r| (0..3).map(move |c| (r, c)));
        for (r, c) in pairs() {
            let lhs = od[r][c] - dot[r][c];
            assert!((lhs - h * hm[r][c]).abs() < 1e-15, "{r} {c}: {lhs}");
        }
        // The rotor of (e0, e) turns vectors as Omega does.
        let turn = Rotor::new(e0, -e[2], e[1], -e[0]);
        let v = [0.3, -1.1, 0.7];
        let turned = turn.sandwich(Vector::new(v[0], v[1], v[2]));
        for (row, got) in omega.iter().zip([turned.e1, turned.e2, turned.e3]) {
            let expected: f64 = row.iter().zip(v).map(|(a, b)| a * b).sum();
            assert!((got - expected).abs() < 1e-15, "{got} {expected}");
        }
        // Omega is orthogonal.
        let gram = mul(omega_t, omega);
        for (r, c) in pairs() {
            let expected = f64::from(u8::from(r == c));
            assert!((gram[r][c] - expected).abs() < 1e-15);
        }
    }
}
