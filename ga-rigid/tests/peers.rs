//! The peers (the methods people use today, run through the registry beside ours) solve
//! the rigid body: ode_solvers' Dop853 on the quaternion form reaches the published
//! Hairer-Lubich-Wanner attitude, and the engines' steps converge at their orders
//! against the exact flow. A wrong sign in a quaternion product or a Magnus term shows up
//! as a missed reference value or a wrong order.

mod support;

use ga_core::f64::g3::*;
use ga_rigid::dynamics::{RigidBody, State};
use ga_rigid::integrators::{ExactFreeBody, Integrator, Method, Step};
use support::*;

fn run(method: Method, step: Step, body: &RigidBody, state: State, t_end: f64) -> State {
    let mut integrator = method.integrator(step).unwrap();
    integrator.advance(body, 0.0, state, t_end).unwrap()
}

#[test]
fn dop853_on_the_quaternion_form_reaches_the_published_attitude() {
    let body = RigidBody::new_unphysical(HLW.moments).unwrap();
    let state = HLW.state();
    for method in [Method::Dop853Quaternion, Method::Dopri5Quaternion] {
        let end = run(method, Step::Tolerance(1e-11), &body, state, 10.0);
        let [s, e12, e13, e23] = HLW_R10;
        let error = attitude_error(end.rotor, Rotor::new(s, e12, e13, e23));
        assert!(error < 1e-8, "{method}: {error:e}");
        let m = body.body_momentum(end.omega);
        let m = ga_rigid::dynamics::omega_to_vector(m);
        for k in 0..3 {
            assert!((m[k] - HLW_M10[k]).abs() < 1e-8, "{method}: m = {m:?}");
        }
    }
}

/// The samples of a run read off ode_solvers' dense output agree with runs stopped at
/// each sample.
#[test]
fn the_quaternion_peers_sample_through_their_dense_output() {
    let (body, state) = (HAIRER_VILMART.body(), HAIRER_VILMART.state());
    let times: Vec<f64> = (1..=25).map(|k| 0.4 * f64::from(k)).collect();
    let mut dense = Method::Dop853Quaternion
        .integrator(Step::Tolerance(1e-12))
        .unwrap();
    let samples = dense.advance_to_each(&body, 0.0, state, &times).unwrap();
    let exact = ExactFreeBody::new();
    for (&t, sample) in times.iter().zip(&samples) {
        let reference = exact.clone().advance(&body, 0.0, state, t).unwrap();
        let error = attitude_error(sample.rotor, reference.rotor);
        assert!(error < 1e-9, "t = {t}: {error:e}");
    }
}

/// The attitude error at `t_end` of `method` at step `h` against the exact flow.
fn error_at(method: Method, h: f64) -> f64 {
    let (body, state) = (HAIRER_VILMART.body(), HAIRER_VILMART.state());
    let t_end = 2.0;
    let end = run(method, Step::Fixed(h), &body, state, t_end);
    let exact = ExactFreeBody::new()
        .advance(&body, 0.0, state, t_end)
        .unwrap();
    attitude_error(end.rotor, exact.rotor)
}

#[test]
fn the_engine_steps_converge_at_their_orders() {
    for (method, order) in [
        (Method::EulerGyroExplicit, 1.0),
        (Method::EulerGyroImplicit, 1.0),
        (Method::Buss2, 2.0),
    ] {
        let coarse = error_at(method, 2e-3);
        let fine = error_at(method, 1e-3);
        let observed = (coarse / fine).log2();
        assert!(
            (observed - order).abs() < 0.15,
            "{method}: order {observed} ({coarse:e}, {fine:e})"
        );
    }
}

/// Buss's update keeps the space angular momentum of a free body exactly (to rounding);
/// the Euler steps do not.
#[test]
fn buss_keeps_the_space_momentum_of_a_free_body() {
    let (body, state) = (HAIRER_VILMART.body(), HAIRER_VILMART.state());
    let l0 = body.space_momentum(&state);
    let end = run(Method::Buss2, Step::Fixed(0.05), &body, state, 20.0);
    let drift = (body.space_momentum(&end) - l0).norm() / l0.norm();
    assert!(drift < 1e-10, "{drift:e}");
    let end = run(
        Method::EulerGyroExplicit,
        Step::Fixed(0.05),
        &body,
        state,
        20.0,
    );
    let drift = (body.space_momentum(&end) - l0).norm() / l0.norm();
    assert!(drift > 1e-4, "{drift:e}");
}
