//! The peers (the methods people use today, run through the registry beside ours) solve
//! the rigid body: ode_solvers' Dop853 on the quaternion form reaches the published
//! Hairer-Lubich-Wanner attitude, and the engines' steps converge at their orders
//! against the exact flow. A wrong sign in a quaternion product or a Magnus term shows up
//! as a missed reference value or a wrong order.

mod support;

use ga_core::f64::g3::*;
use ga_rigid::dynamics::{RigidBody, State};
use ga_rigid::integrators::{ExactFreeBody, Integrator};
use ga_rigid::registry::{Method, Step};
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

/// The implicit midpoint rule on the quaternion form and the discrete Moser-Veselov step
/// are of order two against the exact flow on a free asymmetric body (the Hairer-Vilmart
/// body), in the attitude and in the body momentum.
#[test]
fn the_midpoint_quaternion_and_moser_veselov_steps_are_of_order_two() {
    let (body, state) = (HAIRER_VILMART.body(), HAIRER_VILMART.state());
    let t_end = 2.0;
    let exact = ExactFreeBody::new()
        .advance(&body, 0.0, state, t_end)
        .unwrap();
    let m_exact = momentum(&body, &exact);
    for method in [Method::MidpointQuaternion, Method::MoserVeselov] {
        let errors = |h: f64| {
            let end = run(method, Step::Fixed(h), &body, state, t_end);
            (
                attitude_error(end.rotor, exact.rotor),
                distance(momentum(&body, &end), m_exact),
            )
        };
        let (coarse, fine) = (errors(0.02), errors(0.01));
        for (what, c, f) in [
            ("attitude", coarse.0, fine.0),
            ("momentum", coarse.1, fine.1),
        ] {
            let observed = (c / f).log2();
            assert!(
                (observed - 2.0).abs() < 0.1,
                "{method} {what}: order {observed} ({c:e}, {f:e})"
            );
        }
    }
}

/// The Moser-Veselov step keeps the space angular momentum of a free body to rounding
/// (its `Omega` turns the attitude and, transposed, the body momentum), whatever the step;
/// the implicit midpoint rule keeps the quadratic invariants `|m|`, the energy and `|q|` to
/// its solve's tolerance, but not the space momentum (its error is the method's).
#[test]
fn moser_veselov_keeps_the_space_momentum_and_midpoint_the_quadratic_invariants() {
    let (body, state) = (HAIRER_VILMART.body(), HAIRER_VILMART.state());
    let l0 = body.space_momentum(&state);
    let m0 = body.body_momentum(state.omega).norm();
    let e0 = body.energy(state.omega);
    for h in [0.01, 0.1, 0.2] {
        let steps = 2_000;
        let mut integrator = Method::MoserVeselov.integrator(Step::Fixed(h)).unwrap();
        let mut s = state;
        let mut worst: f64 = 0.0;
        for i in 0..steps {
            s = integrator.advance(&body, i as f64 * h, s, h).unwrap();
            worst = worst.max((body.space_momentum(&s) - l0).norm() / l0.norm());
        }
        // 2,000 steps of a few roundings each: a random walk of some 1e-15.
        assert!(worst < 2e-13, "moser-veselov h = {h}: |L| drift {worst:e}");
        let energy = (body.energy(s.omega) - e0).abs() / e0;
        assert!(
            energy < 2e-13,
            "moser-veselov h = {h}: energy drift {energy:e}"
        );

        let mut integrator = Method::MidpointQuaternion
            .integrator(Step::Fixed(h))
            .unwrap();
        let mut s = state;
        let (mut worst_m, mut worst_e): (f64, f64) = (0.0, 0.0);
        for i in 0..steps {
            s = integrator.advance(&body, i as f64 * h, s, h).unwrap();
            worst_m = worst_m.max((body.body_momentum(s.omega).norm() - m0).abs() / m0);
            worst_e = worst_e.max((body.energy(s.omega) - e0).abs() / e0);
        }
        assert!(
            worst_m < 2e-13,
            "midpoint-quaternion h = {h}: |m| drift {worst_m:e}"
        );
        assert!(
            worst_e < 2e-13,
            "midpoint-quaternion h = {h}: energy drift {worst_e:e}"
        );
    }
    // The midpoint rule's space momentum moves with its (second-order) attitude error.
    let end = run(
        Method::MidpointQuaternion,
        Step::Fixed(0.1),
        &body,
        state,
        20.0,
    );
    let drift = (body.space_momentum(&end) - l0).norm() / l0.norm();
    assert!(drift > 1e-6, "{drift:e}");
}

/// Under a torque the Moser-Veselov step is the free part of a Strang splitting with
/// torque kicks, and the midpoint rule takes the torque in its residual: both stay of
/// order two on the heavy top against a tight Dormand-Prince reference.
#[test]
fn the_new_peers_stay_of_order_two_under_a_torque() {
    use ga_rigid::dynamics::Gravity;
    let gravity = Gravity {
        mass: 1.0,
        g: Vector::new(0.0, 0.0, -9.81),
        com_offset: Vector::new(0.1, 0.0, 0.5),
    };
    let body = RigidBody::new([1.0, 1.3, 0.5])
        .unwrap()
        .with_torque(gravity);
    let state = State {
        rotor: (Bivector::E23 * -0.15).exp(),
        omega: ga_rigid::dynamics::omega_from_vector([0.5, -0.3, 8.0]),
    };
    let t_end = 1.0;
    let reference = run(Method::Dopri, Step::Tolerance(1e-13), &body, state, t_end);
    for method in [Method::MidpointQuaternion, Method::MoserVeselov] {
        let error = |h: f64| {
            let end = run(method, Step::Fixed(h), &body, state, t_end);
            attitude_error(end.rotor, reference.rotor)
        };
        let (coarse, fine) = (error(0.004), error(0.002));
        let observed = (coarse / fine).log2();
        assert!(
            (observed - 2.0).abs() < 0.1,
            "{method}: order {observed} ({coarse:e}, {fine:e})"
        );
    }
}

/// The seven-unknown Newton solve and our `midpoint` (Cayley's closed form for the
/// attitude, three unknowns) are the same rule written apart: they agree to rounding,
/// step for step, where each alone is some 1e-3 off the exact flow.
#[test]
fn midpoint_quaternion_is_our_midpoint_rule_solved_another_way() {
    let (body, state) = (HAIRER_VILMART.body(), HAIRER_VILMART.state());
    let ours = run(Method::Midpoint, Step::Fixed(0.05), &body, state, 10.0);
    let peer = run(
        Method::MidpointQuaternion,
        Step::Fixed(0.05),
        &body,
        state,
        10.0,
    );
    let apart = attitude_error(peer.rotor, ours.rotor);
    assert!(apart < 1e-12, "{apart:e}");
    let off = attitude_error(
        peer.rotor,
        ExactFreeBody::new()
            .advance(&body, 0.0, state, 10.0)
            .unwrap()
            .rotor,
    );
    assert!(off > 1e-4, "{off:e}");
}
