//! Trajectory derivatives through `lie-rk4` and the splitting on the Hairer-Lubich-Wanner
//! body (moments (2, 1, 2/3), m(0) = (cos 1.1, 0, sin 1.1)): the `f64` instantiation of
//! `gradients` against the registry's methods, and the `Dual64` derivatives of the state at
//! T = 10 with respect to each moment and each initial angular velocity component against
//! Richardson-extrapolated central differences of the registry's own `f64` runs.

use ga_rigid::dynamics::{omega_from_vector, Gravity, RigidBody, State};
use ga_rigid::gradients::{dual64, f64 as g64};
use ga_rigid::integrators::{Integrator, LieRk4, Splitting};

use ga_core::f64::g3::{Bivector, Rotor, Vector};
use ga_core::num_dual::Dual64;

const MOMENTS: [f64; 3] = [2.0, 1.0, 2.0 / 3.0];
const T: f64 = 10.0;
const STEP: f64 = 0.01;
const ORDER: [usize; 3] = [0, 1, 2];

/// The initial body angular velocity `w = I^-1 m(0)`.
fn w0(moments: [f64; 3]) -> [f64; 3] {
    let m = [1.1_f64.cos(), 0.0, 1.1_f64.sin()];
    std::array::from_fn(|k| m[k] / moments[k])
}

/// The seven numbers of a state: the rotor's four, then the bivector's three.
fn flat(state: &State) -> [f64; 7] {
    let (r, o) = (state.rotor, state.omega);
    [r.s, r.e12, r.e13, r.e23, o.e12, o.e13, o.e23]
}

/// The registry's run of `method` from the identity with moments `moments` and `w(0) = w`.
fn registry(method: &str, moments: [f64; 3], w: [f64; 3]) -> [f64; 7] {
    let body = RigidBody::new_unphysical(moments).unwrap();
    let state = State {
        rotor: Rotor::ONE,
        omega: omega_from_vector(w),
    };
    let end = match method {
        "lie-rk4" => LieRk4::new(STEP).unwrap().advance(&body, 0.0, state, T),
        _ => Splitting::new(STEP)
            .unwrap()
            .with_axis_order(ORDER)
            .unwrap()
            .advance(&body, 0.0, state, T),
    };
    flat(&end.unwrap())
}

fn dual_flat(state: &dual64::State) -> [Dual64; 7] {
    let (r, o) = (state.rotor, state.omega);
    [r.s, r.e12, r.e13, r.e23, o.e12, o.e13, o.e23]
}

/// The dual run of `method` with moments and `w(0)` given as dual numbers.
fn dual_run(method: &str, moments: [Dual64; 3], w: [Dual64; 3]) -> [Dual64; 7] {
    let body = dual64::FreeBody::new(moments).unwrap();
    let state = dual64::State::from_w(w);
    let end = match method {
        "lie-rk4" => body.lie_rk4(state, STEP, T),
        _ => body.splitting(state, STEP, T, ORDER),
    };
    dual_flat(&end.unwrap())
}

#[test]
fn the_f64_instantiation_is_the_registrys_arithmetic() {
    let w = w0(MOMENTS);
    for method in ["lie-rk4", "splitting"] {
        let body = g64::FreeBody::new(MOMENTS).unwrap();
        let state = g64::State::from_w(w);
        let ours = match method {
            "lie-rk4" => body.lie_rk4(state, STEP, T),
            _ => body.splitting(state, STEP, T, ORDER),
        }
        .unwrap();
        let ours = flat(&State {
            rotor: ours.rotor,
            omega: ours.omega,
        });
        assert_eq!(ours, registry(method, MOMENTS, w), "{method}");
    }
}

/// The derivative of the registry's run along parameter `p` (0..3 the moments, 3..6 the
/// components of w(0), moved with the moments fixed): Richardson's extrapolation of central
/// differences with relative steps `delta` and `2 delta`.
fn difference(method: &str, p: usize, delta: f64) -> [f64; 7] {
    let at = |t: f64| {
        let mut moments = MOMENTS;
        let mut w = w0(MOMENTS);
        if p < 3 {
            moments[p] += t * MOMENTS[p];
        } else {
            w[p - 3] += t;
        }
        registry(method, moments, w)
    };
    let (p1, m1, p2, m2) = (at(delta), at(-delta), at(2.0 * delta), at(-2.0 * delta));
    let scale = if p < 3 { MOMENTS[p] } else { 1.0 };
    std::array::from_fn(|k| (8.0 * (p1[k] - m1[k]) - (p2[k] - m2[k])) / (12.0 * delta * scale))
}

fn norm(x: &[f64]) -> f64 {
    x.iter().map(|v| v * v).sum::<f64>().sqrt()
}

#[test]
fn trajectory_derivatives_match_differences_of_the_f64_runs() {
    for method in ["lie-rk4", "splitting"] {
        for p in 0..6 {
            let mut moments = MOMENTS.map(|i| Dual64::new(i, 0.0));
            let mut w = w0(MOMENTS).map(|x| Dual64::new(x, 0.0));
            if p < 3 {
                moments[p].eps = 1.0;
            } else {
                w[p - 3].eps = 1.0;
            }
            let dual = dual_run(method, moments, w);
            // The values are the registry's run to rounding (num-dual divides by multiplying
            // with the reciprocal, so a quotient can differ in its last bit).
            let values = dual.map(|d| d.re);
            let reference = registry(method, MOMENTS, w0(MOMENTS));
            for (v, r) in values.iter().zip(&reference) {
                assert!((v - r).abs() <= 1e-12, "{method}: value {v} against {r}");
            }
            let derivative = dual.map(|d| d.eps);
            let fd = difference(method, p, 1e-4);
            let finer = difference(method, p, 5e-5);
            let diff: Vec<f64> = derivative.iter().zip(&fd).map(|(a, b)| a - b).collect();
            let relative = norm(&diff) / norm(&fd);
            let fd_change: Vec<f64> = fd.iter().zip(&finer).map(|(a, b)| a - b).collect();
            println!(
                "{method} d/dp{p}: |dR/dp| {:.3e}, relative to the difference {relative:.2e} \
                 (the difference's own change with its step {:.2e})",
                norm(&fd),
                norm(&fd_change) / norm(&fd)
            );
            assert!(
                relative <= 1e-8,
                "{method}, parameter {p}: dual {derivative:?} against {fd:?}: {relative:e}"
            );
        }
    }
}

/// A heavy top (moments (1, 1.2, 0.4), mass 1 under g = 9.81 down, centre of mass 0.1 up
/// the third axis, w(0) = (1, 0.5, 8)) over T = 5.
mod heavy_top {
    use super::*;

    pub const MOMENTS: [f64; 3] = [1.0, 1.2, 0.4];
    pub const W0: [f64; 3] = [1.0, 0.5, 8.0];
    pub const T: f64 = 5.0;

    /// The registry's run from `R(0) = exp(b)`, `w(0) = w`.
    pub fn registry(b: [f64; 3], w: [f64; 3]) -> [f64; 7] {
        let body = RigidBody::new(MOMENTS).unwrap().with_torque(Gravity {
            mass: 1.0,
            g: Vector::new(0.0, 0.0, -9.81),
            com_offset: Vector::new(0.0, 0.0, 0.1),
        });
        let state = State {
            rotor: Bivector::new(b[0], b[1], b[2]).exp(),
            omega: omega_from_vector(w),
        };
        flat(
            &LieRk4::new(STEP)
                .unwrap()
                .advance(&body, 0.0, state, T)
                .unwrap(),
        )
    }

    /// The dual run, with parameter `p` seeded (0..3 the bivector of R(0), 3..6 w(0)).
    pub fn dual(p: usize) -> [Dual64; 7] {
        use ga_core::dual64::g3 as d;
        let seed = |k: usize, x: f64| Dual64::new(x, if k == p { 1.0 } else { 0.0 });
        let body = dual64::FreeBody::new(MOMENTS.map(|i| Dual64::new(i, 0.0)))
            .unwrap()
            .with_gravity(
                Dual64::new(1.0, 0.0),
                d::Vector::new(
                    Dual64::new(0.0, 0.0),
                    Dual64::new(0.0, 0.0),
                    Dual64::new(-9.81, 0.0),
                ),
                d::Vector::new(
                    Dual64::new(0.0, 0.0),
                    Dual64::new(0.0, 0.0),
                    Dual64::new(0.1, 0.0),
                ),
            );
        let rotor = d::Bivector::new(seed(0, 0.0), seed(1, 0.0), seed(2, 0.0)).exp();
        let w = [0, 1, 2].map(|k| seed(k + 3, W0[k]));
        let end = body.lie_rk4(dual64::State::new(rotor, w), STEP, T).unwrap();
        dual_flat(&end)
    }
}

#[test]
fn the_f64_instantiation_with_gravity_is_the_registrys_arithmetic() {
    let body = g64::FreeBody::new(heavy_top::MOMENTS)
        .unwrap()
        .with_gravity(
            1.0,
            Vector::new(0.0, 0.0, -9.81),
            Vector::new(0.0, 0.0, 0.1),
        );
    let b = [0.2, -0.1, 0.3];
    let rotor = Bivector::new(b[0], b[1], b[2]).exp();
    let end = body
        .lie_rk4(g64::State::new(rotor, heavy_top::W0), STEP, heavy_top::T)
        .unwrap();
    let ours = flat(&State {
        rotor: end.rotor,
        omega: end.omega,
    });
    assert_eq!(ours, heavy_top::registry(b, heavy_top::W0));
}

#[test]
fn the_heavy_tops_state_transition_matrix_matches_differences() {
    for p in 0..6 {
        let dual = heavy_top::dual(p);
        let at = |t: f64| {
            let mut b = [0.0; 3];
            let mut w = heavy_top::W0;
            if p < 3 {
                b[p] += t;
            } else {
                w[p - 3] += t;
            }
            heavy_top::registry(b, w)
        };
        let values = dual.map(|d| d.re);
        let reference = at(0.0);
        for (v, r) in values.iter().zip(&reference) {
            assert!((v - r).abs() <= 1e-12, "value {v} against {r}");
        }
        let delta = 1e-5;
        let (p1, m1, p2, m2) = (at(delta), at(-delta), at(2.0 * delta), at(-2.0 * delta));
        let fd: [f64; 7] =
            std::array::from_fn(|k| (8.0 * (p1[k] - m1[k]) - (p2[k] - m2[k])) / (12.0 * delta));
        let derivative = dual.map(|d| d.eps);
        let diff: Vec<f64> = derivative.iter().zip(&fd).map(|(a, b)| a - b).collect();
        let relative = norm(&diff) / norm(&fd);
        println!(
            "heavy top column {p}: |column| {:.3e}, relative {relative:.2e}",
            norm(&fd)
        );
        assert!(
            relative <= 1e-8,
            "column {p}: {derivative:?} against {fd:?}: {relative:e}"
        );
    }
}

mod exact {
    use super::*;
    use ga_rigid::exact_flow::exact_free_body;
    use ga_rigid::exact_flow_generic::{dual64 as ed, f64 as ef};

    pub const M0: [f64; 3] = [0.4535961214255773, 0.0, 0.8912073600614354];

    pub fn flat(out: ([f64; 4], [f64; 3])) -> [f64; 7] {
        let (r, m) = out;
        [r[0], r[1], r[2], r[3], m[0], m[1], m[2]]
    }

    /// The copy's `f64` instantiation against `exact_flow` itself, on a general body (the
    /// HLW one, forwards and backwards), a symmetric one and a sphere.
    #[test]
    fn the_f64_copy_is_exact_flows_algorithm() {
        let r0 = [0.9, 0.1, -0.3, 0.2];
        let cases = [
            (MOMENTS, M0, 10.0),
            (MOMENTS, [0.3, -0.7, 0.2], -7.5),
            ([1.0, 1.0, 0.5], [0.3, 0.4, 1.2], 4.0),
            ([1.0, 1.0, 1.0], [0.3, 0.4, 1.2], 4.0),
        ];
        for (moments, m0, t) in cases {
            let ours = flat(ef::exact_free_body(moments, m0, r0, t));
            let theirs = flat(exact_free_body(moments, m0, r0, t));
            for (a, b) in ours.iter().zip(&theirs) {
                assert!(
                    (a - b).abs() <= 1e-12,
                    "{moments:?} {m0:?} {t}: {ours:?} against {theirs:?}"
                );
            }
        }
    }

    /// Derivatives of `(R(10), m(10))` on the HLW body along each moment, each component
    /// of m(0) and the time, against Richardson-extrapolated differences of `exact_flow`.
    #[test]
    fn exact_flow_derivatives_match_differences() {
        let r0 = [1.0, 0.0, 0.0, 0.0];
        for p in 0..7 {
            let seed = |j: usize, x: f64| Dual64::new(x, if j == p { 1.0 } else { 0.0 });
            let moments = [0, 1, 2].map(|j| seed(j, MOMENTS[j]));
            let m0 = [0, 1, 2].map(|j| seed(j + 3, M0[j]));
            let out = ed::exact_free_body(moments, m0, r0.map(|x| Dual64::new(x, 0.0)), seed(6, T));
            let (r, m) = out;
            let dual = [r[0], r[1], r[2], r[3], m[0], m[1], m[2]];
            let at = |d: f64| {
                let (mut moments, mut m0, mut t) = (MOMENTS, M0, T);
                match p {
                    0..=2 => moments[p] += d,
                    3..=5 => m0[p - 3] += d,
                    _ => t += d,
                }
                flat(exact_free_body(moments, m0, r0, t))
            };
            let values = dual.map(|d| d.re);
            let reference = at(0.0);
            for (v, r) in values.iter().zip(&reference) {
                assert!((v - r).abs() <= 1e-12, "value {v} against {r}");
            }
            let delta = 1e-4;
            let (p1, m1, p2, m2) = (at(delta), at(-delta), at(2.0 * delta), at(-2.0 * delta));
            let fd: [f64; 7] =
                std::array::from_fn(|j| (8.0 * (p1[j] - m1[j]) - (p2[j] - m2[j])) / (12.0 * delta));
            let derivative = dual.map(|d| d.eps);
            let diff: Vec<f64> = derivative.iter().zip(&fd).map(|(a, b)| a - b).collect();
            let relative = norm(&diff) / norm(&fd);
            println!(
                "exact flow d/dp{p}: |column| {:.3e}, relative {relative:.2e}",
                norm(&fd)
            );
            assert!(
                relative <= 1e-8,
                "parameter {p}: {derivative:?} against {fd:?}: {relative:e}"
            );
        }
    }
}
