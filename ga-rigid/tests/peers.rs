//! The peers (the methods people use today, run through the registry beside ours) solve
//! the rigid body: ode_solvers' Dop853 on the quaternion form reaches the published
//! Hairer-Lubich-Wanner attitude, and the engines' steps converge at their orders
//! against the exact flow; Spiers's steps follow the article's equations transcribed here
//! in rotation matrices and reproduce the closed-form symmetric top. A wrong sign in a quaternion product or a Magnus term shows up
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

/// A 3x3 matrix product, for the space-frame transcription below.
fn matmul(a: &Matrix, b: &Matrix) -> Matrix {
    std::array::from_fn(|r| std::array::from_fn(|c| (0..3).map(|k| a[r][k] * b[k][c]).sum()))
}

fn apply(a: &Matrix, v: [f64; 3]) -> [f64; 3] {
    std::array::from_fn(|r| (0..3).map(|k| a[r][k] * v[k]).sum())
}

fn transpose(a: &Matrix) -> Matrix {
    std::array::from_fn(|r| std::array::from_fn(|c| a[c][r]))
}

fn cross3(a: [f64; 3], b: [f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot3(a: [f64; 3], b: [f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Rodrigues' formula, the article's `Q(phi)`: `1 + sin|phi| [n]x + (1 - cos|phi|) [n]x^2`.
fn rodrigues(phi: [f64; 3]) -> Matrix {
    let angle = dot3(phi, phi).sqrt();
    if angle == 0.0 {
        return IDENTITY;
    }
    let n = phi.map(|x| x / angle);
    let k: Matrix = [[0.0, -n[2], n[1]], [n[2], 0.0, -n[0]], [-n[1], n[0], 0.0]];
    let k2 = matmul(&k, &k);
    std::array::from_fn(|r| {
        std::array::from_fn(|c| {
            IDENTITY[r][c] + angle.sin() * k[r][c] + (1.0 - angle.cos()) * k2[r][c]
        })
    })
}

/// One free step of B. Spiers's "A better way to spin" as the article writes it, in the
/// space frame with rotation matrices (`momentum_first` chooses its "momentum-first
/// method", else its "modified Jolt method"): the world inverse inertia `J_w = R J R^T`,
/// `k = w x L`, `J' = k.J_w k / k.k`, `Omega = w - J' L`. Returns the new attitude and
/// space angular velocity.
fn spiers_by_the_article(
    moments: [f64; 3],
    r: Matrix,
    w: [f64; 3],
    h: f64,
    momentum_first: bool,
) -> (Matrix, [f64; 3]) {
    let j_body: Matrix = std::array::from_fn(|a| {
        std::array::from_fn(|b| if a == b { 1.0 / moments[a] } else { 0.0 })
    });
    let i_body: Matrix =
        std::array::from_fn(|a| std::array::from_fn(|b| if a == b { moments[a] } else { 0.0 }));
    let j_world = matmul(&matmul(&r, &j_body), &transpose(&r));
    let l = apply(&matmul(&matmul(&r, &i_body), &transpose(&r)), w);
    let k = cross3(w, l);
    let j = dot3(k, apply(&j_world, k)) / dot3(k, k);
    let spin: [f64; 3] = std::array::from_fn(|i| w[i] - j * l[i]);
    if momentum_first {
        let r1 = matmul(
            &matmul(
                &rodrigues(l.map(|x| j * x * h)),
                &rodrigues(spin.map(|x| x * h)),
            ),
            &r,
        );
        let j1 = matmul(&matmul(&r1, &j_body), &transpose(&r1));
        (r1, apply(&j1, l))
    } else {
        let l1 = apply(&rodrigues(spin.map(|x| -x * h)), l);
        let w1 = apply(&j_world, l1);
        (matmul(&rodrigues(w1.map(|x| x * h)), &r), w1)
    }
}

/// The registry's Spiers steps against the article's equations transcribed independently
/// in the space frame with rotation matrices (`spiers_by_the_article`): after 200 free
/// steps from a tilted start on the Hairer-Vilmart body at `h |w| = 0.3`, the attitude and
/// the space angular velocity agree to rounding (1e-10). A wrong sign of the turn, the precession
/// on the wrong side or `J'` from the wrong vector misses by far more.
#[test]
fn the_spiers_steps_follow_the_articles_equations() {
    let body = HAIRER_VILMART.body();
    let start = State {
        rotor: Bivector::new(0.4, -0.7, 0.2).exp(),
        omega: HAIRER_VILMART.state().omega,
    };
    let h = 0.3 / start.omega.norm();
    let steps = 200;
    for (method, momentum_first) in [
        (Method::SpiersVelocity, false),
        (Method::SpiersMomentum, true),
    ] {
        let end = run(method, Step::Fixed(h), &body, start, h * f64::from(steps));
        let mut r = matrix_from_rotor(rotor_array(start.rotor));
        let mut w = apply(&r, ga_rigid::dynamics::omega_to_vector(start.omega));
        for _ in 0..steps {
            (r, w) = spiers_by_the_article(HAIRER_VILMART.moments, r, w, h, momentum_first);
        }
        let [s, e12, e13, e23] = rotor_from_matrix(&r);
        let attitude = attitude_error(end.rotor, Rotor::new(s, e12, e13, e23));
        let mut ours = matrix_from_rotor(rotor_array(end.rotor));
        ours = transpose(&ours);
        let w_body = apply(&ours, w);
        let rate = distance(w_body, ga_rigid::dynamics::omega_to_vector(end.omega));
        // Rounding grows along the 200 steps to some 1e-11.
        assert!(
            attitude < 1e-10 && rate < 1e-10,
            "{method}: {attitude:e}, {rate:e}"
        );
    }
}

/// On a body with two equal moments Spiers's turn of the body momentum is its exact flow,
/// and the momentum-first form's precession about `L` makes the attitude exact too (the
/// article's symmetric top): against the closed-form top (`SymmetricTop`, checked against
/// the textbook precession in `tests/symmetric_top.rs`), 400 steps at `h |w| = 0.5` from a
/// tilted start stay at rounding. The velocity form's body momentum is as exact, but its
/// attitude, turned once by the new rate, is not.
#[test]
fn spiers_momentum_first_is_the_exact_symmetric_top() {
    use ga_rigid::dynamics::SymmetricTop;
    for scene in [SHORT_FAT, NEEDLE] {
        let body = RigidBody::new_unphysical(scene.moments).unwrap();
        let start = State {
            rotor: Bivector::new(0.3, -0.2, 0.5).exp(),
            omega: scene.state().omega,
        };
        let top = SymmetricTop::new(&body, start, 1e-12).unwrap();
        let h = 0.5 / start.omega.norm();
        let t_end = 400.0 * h;
        let reference = top.state(t_end);
        let rate = |s: &State| (s.omega - reference.omega).norm() / reference.omega.norm();
        let end = run(Method::SpiersMomentum, Step::Fixed(h), &body, start, t_end);
        let (attitude, omega) = (attitude_error(end.rotor, reference.rotor), rate(&end));
        assert!(
            attitude < 1e-11 && omega < 1e-11,
            "{}: {attitude:e}, {omega:e}",
            scene.name
        );
        let end = run(Method::SpiersVelocity, Step::Fixed(h), &body, start, t_end);
        let (attitude, omega) = (attitude_error(end.rotor, reference.rotor), rate(&end));
        assert!(
            omega < 1e-11,
            "{}: velocity form, omega {omega:e}",
            scene.name
        );
        // 0.8 rad on the short fat top, 5e-4 on the needle (little tilt).
        assert!(
            attitude > 1e-5,
            "{}: velocity form, attitude {attitude:e}",
            scene.name
        );
    }
}

/// On an asymmetric body both forms are of order one against the exact flow, in the
/// attitude and the body momentum (`J'` makes only the energy's second derivative vanish,
/// not the momentum's: the turn misses `h^2/2 (J - J') k x l` a step), with an energy error
/// of order two (the article's third-order energy error a step). The velocity form keeps
/// `|L|`, the momentum-first form `L` itself.
#[test]
fn the_spiers_steps_are_of_order_one_with_an_order_two_energy_error() {
    let (body, state) = (HAIRER_VILMART.body(), HAIRER_VILMART.state());
    let t_end = 2.0;
    let exact = ExactFreeBody::new()
        .advance(&body, 0.0, state, t_end)
        .unwrap();
    let (e0, l0) = (body.energy(state.omega), body.space_momentum(&state));
    let steps = [2e-3, 1e-3, 5e-4];
    for method in [Method::SpiersVelocity, Method::SpiersMomentum] {
        let (mut attitude, mut moment, mut energy) = (vec![], vec![], vec![]);
        for h in steps {
            let end = run(method, Step::Fixed(h), &body, state, t_end);
            attitude.push(attitude_error(end.rotor, exact.rotor));
            moment.push(distance(momentum(&body, &end), momentum(&body, &exact)));
            energy.push((body.energy(end.omega) - e0).abs() / e0);
            let l = body.space_momentum(&end);
            let norm_drift = (l.norm() - l0.norm()).abs() / l0.norm();
            assert!(norm_drift < 1e-12, "{method}: |L| drift {norm_drift:e}");
            let drift = (l - l0).norm() / l0.norm();
            if method == Method::SpiersMomentum {
                assert!(drift < 1e-12, "{method}: L drift {drift:e}");
            } else {
                assert!(drift > 1e-5, "{method}: L drift {drift:e}");
            }
        }
        for (what, errors, order) in [
            ("attitude", &attitude, 1.0),
            ("momentum", &moment, 1.0),
            ("energy", &energy, 2.0),
        ] {
            let observed = fitted_order(&steps, errors);
            assert!(
                (observed - order).abs() < 0.1,
                "{method}: {what} order {observed} ({errors:?})"
            );
        }
    }
}
