//! The n-dimensional body (`ga_rigid::nd`) against values it did not compute itself: the
//! 4D test values of docs/references.md (scipy DOP853 at rtol 1e-13), a 4x4 matrix form
//! of Euler's equations integrated here, Manakov's integrals, the 3D exact flow of
//! `ga_rigid::exact_flow`, and the closed forms of docs/derivations/symmetric-body-4d.md.

use ga_core::f64::g4;
use ga_core::f64::{g2, g3};
use ga_rigid::nd::{
    planar, Algebra, BodyTorque, ImplicitMidpoint, Integrator, LieDop853, LieDopri5, LieRk4,
    PlaneSplitting, RigidBody, Rk4, SpaceTorque, State, SymmetricBody4, G2, G3, G4,
};

/// The 4D test body of docs/references.md: second moments and `Omega_B(0)`, `R(0) = 1`.
const L4: [f64; 4] = [0.5, 0.9, 1.4, 2.0];
const OMEGA0: [f64; 6] = [1.0, 0.0, 0.4, -0.6, 0.2, 0.8];
/// At t = 10 (docs/references.md): R in the order s, e12, e13, e14, e23, e24, e34, e1234.
const R10: [f64; 8] = [
    -0.845752127571,
    -0.001654495749,
    0.054382309786,
    -0.187793734963,
    0.290305428646,
    -0.103803029126,
    -0.384930676753,
    0.057032816706,
];
const OMEGA10: [f64; 6] = [
    0.920363924980,
    -0.406450762844,
    0.521437788334,
    -0.488898046121,
    0.219223377642,
    0.776749436333,
];
const M0: [f64; 6] = [1.4, 0.0, 1.0, -1.38, 0.58, 2.72];

fn reference_body() -> (RigidBody<G4>, State<G4>) {
    let body = RigidBody::<G4>::new(&L4).unwrap();
    (
        body,
        State::new(g4::Rotor::ONE, g4::Bivector::from_array(OMEGA0)),
    )
}

fn max_difference(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

fn distance_to_reference(state: &State<G4>) -> (f64, f64) {
    (
        max_difference(&state.rotor.to_array(), &R10),
        max_difference(&state.omega.to_array(), &OMEGA10),
    )
}

#[test]
fn lie_rk4_and_rk4_reach_the_reference_state_at_t_10() {
    let (body, s0) = reference_body();
    for (name, state) in [
        (
            "lie-rk4",
            LieRk4::new(1e-3)
                .unwrap()
                .advance(&body, 0.0, s0, 10.0)
                .unwrap(),
        ),
        (
            "rk4",
            Rk4::new(1e-3)
                .unwrap()
                .advance(&body, 0.0, s0, 10.0)
                .unwrap(),
        ),
    ] {
        let (dr, dw) = distance_to_reference(&state);
        eprintln!("{name}: |dR| {dr:e} |dOmega| {dw:e}");
        assert!(dr < 1e-11 && dw < 1e-11, "{name}: {dr:e} {dw:e}");
    }
}

/// The reference values at t = 0 (docs/references.md): `M(0)`, the energy and the two
/// Casimirs, `<M M>_0` and the e1234 part of `M M`.
const ENERGY: f64 = 2.46;
const CASIMIR_SCALAR: f64 = -12.5992;
const CASIMIR_PSEUDOSCALAR: f64 = 4.856;

/// `<M M>_0` and `<M M>_4` with G4's geometric product.
fn casimirs(m: g4::Bivector) -> (f64, f64) {
    let square = m * m;
    (square.s, square.e1234)
}

// ---------- A 4x4 matrix form of Euler's equations, integrated here ----------

type Mat = [[f64; 4]; 4];

fn mat_mul(a: &Mat, b: &Mat) -> Mat {
    let mut c = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            c[i][j] = (0..4).map(|k| a[i][k] * b[k][j]).sum();
        }
    }
    c
}

fn mat_add(a: &Mat, b: &Mat, s: f64) -> Mat {
    let mut c = *a;
    for i in 0..4 {
        for j in 0..4 {
            c[i][j] += s * b[i][j];
        }
    }
    c
}

/// The planes in canonical order, as index pairs.
const PLANES: [(usize, usize); 6] = [(0, 1), (0, 2), (0, 3), (1, 2), (1, 3), (2, 3)];

/// The angular-velocity matrix `W` with `W x = x . Omega`: `W[j][i] = w_ij = -W[i][j]`.
fn w_matrix(omega: &[f64; 6]) -> Mat {
    let mut w = [[0.0; 4]; 4];
    for (k, &(i, j)) in PLANES.iter().enumerate() {
        w[j][i] = omega[k];
        w[i][j] = -omega[k];
    }
    w
}

/// Manakov's form `M' = [M, W]`, `Q' = Q W`, with `M = J W + W J`, `J = diag(l)`.
fn matrix_rate(l: &[f64; 4], m: &Mat, q: &Mat) -> (Mat, Mat) {
    let mut w = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            if i != j {
                w[i][j] = m[i][j] / (l[i] + l[j]);
            }
        }
    }
    let mw = mat_mul(m, &w);
    let wm = mat_mul(&w, m);
    (mat_add(&mw, &wm, -1.0), mat_mul(q, &w))
}

/// Classical RK4 on `(M, Q)` with `n` steps to time `t`.
fn matrix_rk4(l: &[f64; 4], omega0: &[f64; 6], q0: &Mat, t: f64, n: usize) -> (Mat, Mat) {
    let w0 = w_matrix(omega0);
    let mut m = [[0.0; 4]; 4];
    for i in 0..4 {
        for j in 0..4 {
            m[i][j] = (l[i] + l[j]) * w0[i][j];
        }
    }
    let mut q = *q0;
    let h = t / n as f64;
    for _ in 0..n {
        let (a1, b1) = matrix_rate(l, &m, &q);
        let (a2, b2) = matrix_rate(l, &mat_add(&m, &a1, h / 2.0), &mat_add(&q, &b1, h / 2.0));
        let (a3, b3) = matrix_rate(l, &mat_add(&m, &a2, h / 2.0), &mat_add(&q, &b2, h / 2.0));
        let (a4, b4) = matrix_rate(l, &mat_add(&m, &a3, h), &mat_add(&q, &b3, h));
        for (y, k) in [(&mut m, [a1, a2, a3, a4]), (&mut q, [b1, b2, b3, b4])] {
            for i in 0..4 {
                for j in 0..4 {
                    y[i][j] +=
                        h / 6.0 * (k[0][i][j] + 2.0 * (k[1][i][j] + k[2][i][j]) + k[3][i][j]);
                }
            }
        }
    }
    (m, q)
}

/// The matrix reference at `t`: RK4 with `n` and `2n` steps, Richardson-extrapolated
/// (`(16 y_(h/2) - y_h) / 15`); returns `Omega(t)` (from `W`) and `Q(t)`.
fn matrix_reference(
    l: &[f64; 4],
    omega0: &[f64; 6],
    q0: &Mat,
    t: f64,
    n: usize,
) -> ([f64; 6], Mat) {
    let (m1, q1) = matrix_rk4(l, omega0, q0, t, n);
    let (m2, q2) = matrix_rk4(l, omega0, q0, t, 2 * n);
    let m = mat_add(&m2, &mat_add(&m2, &m1, -1.0), 1.0 / 15.0);
    let q = mat_add(&q2, &mat_add(&q2, &q1, -1.0), 1.0 / 15.0);
    let mut omega = [0.0; 6];
    for (k, &(i, j)) in PLANES.iter().enumerate() {
        omega[k] = m[j][i] / (l[i] + l[j]);
    }
    (omega, q)
}

/// The matrix of `x -> R x ~R`: column `c` is the image of `e_(c+1)`.
fn rotor_matrix(r: g4::Rotor) -> Mat {
    let mut q = [[0.0; 4]; 4];
    for c in 0..4 {
        let mut e = [0.0; 4];
        e[c] = 1.0;
        let y = G4::rotate(r, e);
        for row in 0..4 {
            q[row][c] = y[row];
        }
    }
    q
}

fn flat(m: &Mat) -> Vec<f64> {
    m.iter().flatten().copied().collect()
}

const IDENTITY: Mat = [
    [1.0, 0.0, 0.0, 0.0],
    [0.0, 1.0, 0.0, 0.0],
    [0.0, 0.0, 1.0, 0.0],
    [0.0, 0.0, 0.0, 1.0],
];

#[test]
fn matrix_reference_reproduces_the_scipy_values() {
    // The harness itself against docs/references.md, before it judges anything else.
    let (omega, q) = matrix_reference(&L4, &OMEGA0, &IDENTITY, 10.0, 4000);
    let expected_q = rotor_matrix(g4::Rotor::from_array(R10));
    let dq = max_difference(&flat(&q), &flat(&expected_q));
    let dw = max_difference(&omega, &OMEGA10);
    eprintln!("matrix reference: |dQ| {dq:e} |dOmega| {dw:e}");
    assert!(dq < 2e-12 && dw < 1e-12, "{dq:e} {dw:e}");
}

#[test]
fn initial_momentum_energy_and_casimirs_match_the_reference() {
    let (body, s0) = reference_body();
    let m = body.body_momentum(s0.omega);
    assert!(max_difference(&m.to_array(), &M0) < 1e-15);
    assert!((body.energy(s0.omega) - ENERGY).abs() < 1e-15);
    let (c0, c4) = casimirs(m);
    assert!((c0 - CASIMIR_SCALAR).abs() < 1e-14 && (c4 - CASIMIR_PSEUDOSCALAR).abs() < 1e-14);
}

#[test]
fn lie_dopri5_at_tolerance_1e_12_reaches_the_reference_state() {
    let (body, s0) = reference_body();
    let mut method = LieDopri5::new(1e-12, 1e-12).unwrap();
    let state = method.advance(&body, 0.0, s0, 10.0).unwrap();
    let (dr, dw) = distance_to_reference(&state);
    eprintln!(
        "lie-dopri5: |dR| {dr:e} |dOmega| {dw:e}, steps {:?}",
        method.steps()
    );
    assert!(dr < 1e-10 && dw < 1e-10, "{dr:e} {dw:e}");
}

/// Energy, both Casimirs and the space momentum along a run of `method`, each against the
/// reference value at t = 0; returns the largest drift of each.
fn invariant_drift(
    method: &mut dyn Integrator<G4>,
    body: &RigidBody<G4>,
    s0: State<G4>,
) -> [f64; 4] {
    let mut state = s0;
    let mut drift = [0.0_f64; 4];
    for k in 0..10 {
        state = method.advance(body, f64::from(k), state, 1.0).unwrap();
        let m = body.body_momentum(state.omega);
        let (c0, c4) = casimirs(m);
        let l = body.space_momentum(&state);
        drift[0] = drift[0].max((body.energy(state.omega) - ENERGY).abs());
        drift[1] = drift[1].max((c0 - CASIMIR_SCALAR).abs());
        drift[2] = drift[2].max((c4 - CASIMIR_PSEUDOSCALAR).abs());
        // R(0) = 1, so L = M(0) throughout.
        drift[3] = drift[3].max(max_difference(&l.to_array(), &M0));
    }
    drift
}

#[test]
fn every_method_keeps_energy_casimirs_and_space_momentum_of_the_free_body() {
    let (body, s0) = reference_body();
    let cases: Vec<(Box<dyn Integrator<G4>>, [f64; 4])> = vec![
        (Box::new(Rk4::new(1e-2).unwrap()), [1e-8; 4]),
        (Box::new(LieRk4::new(1e-2).unwrap()), [1e-8; 4]),
        (Box::new(LieDopri5::new(1e-12, 1e-12).unwrap()), [1e-10; 4]),
        // The midpoint rule keeps every quadratic invariant to the solve; its L drifts
        // with its O(h^2) error in R.
        (
            Box::new(ImplicitMidpoint::new(1e-2).unwrap()),
            [1e-13, 1e-13, 1e-13, 1e-3],
        ),
        // The splitting keeps L and the Casimirs to rounding (a walk over 1000 steps of
        // six turns each), the energy to O(h^2).
        (
            Box::new(PlaneSplitting::new(1e-2).unwrap()),
            [1e-4, 1e-11, 1e-11, 1e-11],
        ),
    ];
    for (mut method, bound) in cases {
        let drift = invariant_drift(method.as_mut(), &body, s0);
        eprintln!(
            "{}: drift of energy, <MM>_0, <MM>_4, L: {drift:?}",
            method.name()
        );
        for (d, b) in drift.iter().zip(bound) {
            assert!(*d < b, "{}: {drift:?}", method.name());
        }
    }
}

/// `M` as the antisymmetric 4x4 matrix `M[i][j] = m_ij`.
fn momentum_matrix(m: g4::Bivector) -> Mat {
    let mut out = [[0.0; 4]; 4];
    for (k, &(i, j)) in PLANES.iter().enumerate() {
        out[i][j] = m[k];
        out[j][i] = -m[k];
    }
    out
}

/// Manakov's integral `tr((M + lambda J^2)^k)`.
fn manakov(m: g4::Bivector, lambda: f64, k: usize) -> f64 {
    let mut a = momentum_matrix(m);
    for (i, row) in a.iter_mut().enumerate() {
        row[i] += lambda * L4[i] * L4[i];
    }
    let mut p = a;
    for _ in 1..k {
        p = mat_mul(&p, &a);
    }
    (0..4).map(|i| p[i][i]).sum()
}

#[test]
fn manakov_integrals_stay_constant() {
    let (body, s0) = reference_body();
    let lambdas = [-1.3, 0.4, 2.0];
    let initial: Vec<f64> = lambdas
        .iter()
        .flat_map(|&lambda| [2, 3].map(|k| manakov(body.body_momentum(s0.omega), lambda, k)))
        .collect();
    // The k = 3 integral is not a function of the energy and Casimirs alone at these lambda.
    assert!(initial.iter().all(|v| v.abs() > 0.1), "{initial:?}");
    let mut state = s0;
    let mut method = LieRk4::new(2e-3).unwrap();
    let mut worst = 0.0_f64;
    for step in 0..10 {
        state = method.advance(&body, f64::from(step), state, 1.0).unwrap();
        let now: Vec<f64> = lambdas
            .iter()
            .flat_map(|&lambda| [2, 3].map(|k| manakov(body.body_momentum(state.omega), lambda, k)))
            .collect();
        for (a, b) in now.iter().zip(&initial) {
            worst = worst.max((a - b).abs() / b.abs());
        }
    }
    eprintln!("Manakov integrals: largest relative change {worst:e}");
    assert!(worst < 1e-11, "{worst:e}");
}

#[test]
fn rk4_and_lie_rk4_converge_at_order_four_in_four_dimensions() {
    let (body, s0) = reference_body();
    let (omega_ref, q_ref) = matrix_reference(&L4, &OMEGA0, &IDENTITY, 2.0, 2000);
    let error = |state: State<G4>| {
        max_difference(&flat(&rotor_matrix(state.rotor)), &flat(&q_ref))
            .max(max_difference(&state.omega.to_array(), &omega_ref))
    };
    for name in ["rk4", "lie-rk4"] {
        let run = |h: f64| {
            let state = if name == "rk4" {
                Rk4::new(h).unwrap().advance(&body, 0.0, s0, 2.0).unwrap()
            } else {
                LieRk4::new(h)
                    .unwrap()
                    .advance(&body, 0.0, s0, 2.0)
                    .unwrap()
            };
            error(state)
        };
        let errors = [0.1, 0.05, 0.025].map(run);
        let orders = [
            (errors[0] / errors[1]).log2(),
            (errors[1] / errors[2]).log2(),
        ];
        eprintln!("{name}: errors {errors:?}, orders {orders:.3?}");
        assert!(
            orders.iter().all(|p| (3.7..4.4).contains(p)),
            "{name}: {orders:?}"
        );
    }
}

#[test]
fn a_constant_space_torque_changes_the_space_momentum_linearly() {
    let torque = g4::Bivector::new(0.3, -0.2, 0.1, 0.5, 0.0, -0.4);
    let (free, s0) = reference_body();
    let body = free.clone().with_torque(SpaceTorque(torque));
    let mut state = s0;
    let mut method = LieRk4::new(1e-3).unwrap();
    let mut worst = 0.0_f64;
    for k in 1..=5 {
        state = method.advance(&body, f64::from(k - 1), state, 1.0).unwrap();
        let t = f64::from(k);
        let expected: Vec<f64> = M0
            .iter()
            .zip(torque.to_array())
            .map(|(m, tq)| m + t * tq)
            .collect();
        worst = worst.max(max_difference(
            &body.space_momentum(&state).to_array(),
            &expected,
        ));
    }
    eprintln!("space torque: |L - (L0 + t T)| {worst:e}");
    assert!(worst < 1e-11, "{worst:e}");
    // A body-fixed torque does not: L turns with the body.
    let spun = free.with_torque(BodyTorque(torque));
    let end = LieRk4::new(1e-3)
        .unwrap()
        .advance(&spun, 0.0, s0, 5.0)
        .unwrap();
    let linear: Vec<f64> = M0
        .iter()
        .zip(torque.to_array())
        .map(|(m, tq)| m + 5.0 * tq)
        .collect();
    assert!(max_difference(&spun.space_momentum(&end).to_array(), &linear) > 0.1);
}

// ---------- The symmetric body's closed form ----------

fn symmetric_case() -> (RigidBody<G4>, State<G4>) {
    let body = RigidBody::<G4>::new(&[0.6, 0.6, 1.7, 1.7]).unwrap();
    let r0 = g4::Bivector::new(0.2, -0.5, 0.3, 0.7, -0.1, 0.4).exp();
    let omega0 = g4::Bivector::new(0.9, -0.7, 0.5, 0.3, 1.1, -0.6);
    (body, State::new(r0, omega0))
}

#[test]
fn symmetric_body_closed_form_matches_the_matrix_reference_at_t_10() {
    let (body, s0) = symmetric_case();
    let closed = SymmetricBody4::new(&body, 1e-12).unwrap();
    let l = [0.6, 0.6, 1.7, 1.7];
    let (omega_ref, q_ref) = matrix_reference(
        &l,
        &s0.omega.to_array(),
        &rotor_matrix(s0.rotor),
        10.0,
        8000,
    );
    let state = closed.at(s0, 10.0);
    let dq = max_difference(&flat(&rotor_matrix(state.rotor)), &flat(&q_ref));
    let dw = max_difference(&state.omega.to_array(), &omega_ref);
    eprintln!("symmetric body vs matrix reference at t = 10: |dQ| {dq:e} |dOmega| {dw:e}");
    assert!(dq < 1e-12 && dw < 1e-12, "{dq:e} {dw:e}");
    // And against RKMK4 at a small step, rotor components included.
    let stepped = LieRk4::new(1e-3)
        .unwrap()
        .advance(&body, 0.0, s0, 10.0)
        .unwrap();
    let dr = max_difference(&state.rotor.to_array(), &stepped.rotor.to_array());
    assert!(dr < 1e-11, "{dr:e}");
    // The closed form keeps R a unit rotor and L fixed.
    let l0 = body.space_momentum(&s0);
    let l10 = body.space_momentum(&state);
    assert!(max_difference(&l0.to_array(), &l10.to_array()) < 1e-13);
}

#[test]
fn symmetric_body_closed_form_refuses_other_bodies() {
    let (body, _) = reference_body();
    assert!(SymmetricBody4::new(&body, 1e-12).is_err());
}

// ---------- The 3D body inside the 4D one ----------

#[test]
fn a_motion_inside_e123_is_the_3d_exact_flow_with_moments_l2_l3_l1_l3_l1_l2() {
    let l = [0.5, 0.9, 1.4, 2.0];
    let body = RigidBody::<G4>::new(&l).unwrap();
    let moments = [l[1] + l[2], l[0] + l[2], l[0] + l[1]];
    // Omega in e12, e13, e23 only; R(0) in the even algebra of e1, e2, e3.
    let omega0 = g4::Bivector::new(0.7, -1.1, 0.0, 0.4, 0.0, 0.0);
    let r0 = g4::Bivector::new(0.3, 0.2, 0.0, -0.5, 0.0, 0.0).exp();
    let s0 = State::new(r0, omega0);
    // The 3D convention: Omega_B = w1 e23 - w2 e13 + w3 e12, m = J w.
    let w = [omega0.e23, -omega0.e13, omega0.e12];
    let m0 = [moments[0] * w[0], moments[1] * w[1], moments[2] * w[2]];
    let r3 = [r0.s, r0.e12, r0.e13, r0.e23];
    let mut method = LieDopri5::new(1e-13, 1e-13).unwrap();
    let mut state = s0;
    let mut worst = 0.0_f64;
    for k in 1..=10 {
        let t = f64::from(k);
        state = method.advance(&body, t - 1.0, state, 1.0).unwrap();
        let (r, m) = ga_rigid::exact_flow::exact_free_body(moments, m0, r3, t);
        let omega = [
            m[2] / moments[2],
            -m[1] / moments[1],
            0.0,
            m[0] / moments[0],
            0.0,
            0.0,
        ];
        let rotor = [r[0], r[1], r[2], 0.0, r[3], 0.0, 0.0, 0.0];
        worst = worst
            .max(max_difference(&state.omega.to_array(), &omega))
            .max(max_difference(&state.rotor.to_array(), &rotor));
    }
    eprintln!("4D in e123 vs 3D exact flow: {worst:e}");
    assert!(worst < 1e-10, "{worst:e}");
}

#[test]
fn the_g3_body_is_the_3d_body_of_dynamics() {
    // The mapping itself: nd over G3 with second moments l has the 3D body's equations
    // with moments (l2 + l3, l1 + l3, l1 + l2), in the 3D crate's Omega = I w convention.
    let l = [0.5, 0.9, 1.4];
    let nd_body = RigidBody::<G3>::new(&l).unwrap();
    let body3 =
        ga_rigid::dynamics::RigidBody::new([l[1] + l[2], l[0] + l[2], l[0] + l[1]]).unwrap();
    let w = [0.3, -1.2, 2.5];
    let omega = ga_rigid::dynamics::omega_from_vector(w);
    let rotor = g3::Bivector::new(0.2, -0.4, 0.9).exp();
    let rate_nd = nd_body.omega_rate(0.0, &State::new(rotor, omega));
    let rate3 = body3.omega_rate(0.0, &ga_rigid::dynamics::State { rotor, omega });
    assert!(max_difference(&rate_nd.to_array(), &rate3.to_array()) < 1e-15);
    assert!((nd_body.energy(omega) - body3.energy(omega)).abs() < 1e-15);
    // Euler's equations in vector form, w1' = (i2 - i3) w2 w3 / i1, and so on.
    let i = [l[1] + l[2], l[0] + l[2], l[0] + l[1]];
    let expected = [
        (i[1] - i[2]) * w[1] * w[2] / i[0],
        (i[2] - i[0]) * w[2] * w[0] / i[1],
        (i[0] - i[1]) * w[0] * w[1] / i[2],
    ];
    let got = ga_rigid::dynamics::omega_to_vector(rate_nd);
    assert!(
        max_difference(&got, &expected) < 1e-15,
        "{got:?} {expected:?}"
    );
}

// ---------- G2 ----------

#[test]
fn the_planar_body_turns_at_a_constant_rate() {
    let body = RigidBody::<G2>::from_box(2.0, &[1.0, 0.3]).unwrap();
    let s0 = State::new(g2::Bivector::new(0.4).exp(), g2::Bivector::new(1.7));
    let t = 7.5;
    // The textbook rotation: angle 0.8 - 1.7 t... as R = exp(-theta e12 / 2), so the
    // e1 axis turns to cos(theta) e1 + sin(theta) e2 with theta = 1.7 t - 0.8.
    let theta: f64 = 1.7 * t - 0.8;
    let closed = planar(s0, t);
    let e1 = G2::rotate(closed.rotor, [1.0, 0.0, 0.0, 0.0]);
    assert!((e1[0] - theta.cos()).abs() < 1e-14 && (e1[1] - theta.sin()).abs() < 1e-14);
    let methods: Vec<Box<dyn Integrator<G2>>> = vec![
        Box::new(Rk4::new(0.002).unwrap()),
        Box::new(LieRk4::new(0.1).unwrap()),
        Box::new(PlaneSplitting::new(0.1).unwrap()),
        Box::new(LieDopri5::new(1e-12, 1e-12).unwrap()),
    ];
    for mut method in methods {
        let state = method.advance(&body, 0.0, s0, t).unwrap();
        let d = max_difference(&state.rotor.to_array(), &closed.rotor.to_array());
        let dw = (state.omega.e12 - s0.omega.e12).abs();
        eprintln!("G2 {}: |dR| {d:e} |dOmega| {dw:e}", method.name());
        assert!(d < 1e-10 && dw < 1e-13, "{}: {d:e} {dw:e}", method.name());
    }
}

#[test]
fn the_planar_midpoint_rule_turns_by_the_cayley_angle() {
    // The midpoint rule's rotor step is the Cayley transform of h Omega / 4: in the plane
    // a turn by 4 atan(h w / 4) a step instead of h w (the rate itself stays exact).
    let body = RigidBody::<G2>::new(&[0.2, 0.7]).unwrap();
    let s0 = State::new(g2::Rotor::ONE, g2::Bivector::new(1.7));
    let (h, n) = (0.1, 75);
    let state = ImplicitMidpoint::new(h)
        .unwrap()
        .advance(&body, 0.0, s0, h * f64::from(n))
        .unwrap();
    let angle = f64::from(n) * 4.0 * (h * 1.7 / 4.0).atan();
    let expected = g2::Bivector::new(-0.5 * angle).exp();
    let d = max_difference(&state.rotor.to_array(), &expected.to_array());
    assert!(d < 1e-13 && state.omega == s0.omega, "{d:e}");
}

// ---------- Mass properties ----------

#[test]
fn box_and_ball_have_the_textbook_moments() {
    // 3D: the cuboid's i1 = m (b^2 + c^2) / 12, the ball's 2/5 m r^2; 2D: the disc's m r^2 / 2;
    // 4D: the 4-ball's l = m r^2 / 6.
    let cuboid = RigidBody::<G3>::from_box(3.0, &[1.0, 2.0, 0.5]).unwrap();
    let i = cuboid.plane_moments();
    assert!((i.e23 - 3.0 * (4.0 + 0.25) / 12.0).abs() < 1e-15);
    assert!((i.e12 - 3.0 * (1.0 + 4.0) / 12.0).abs() < 1e-15);
    let ball = RigidBody::<G3>::from_ball(2.0, 0.5).unwrap();
    assert!((ball.plane_moments().e12 - 0.4 * 2.0 * 0.25).abs() < 1e-15);
    let disc = RigidBody::<G2>::from_ball(2.0, 0.5).unwrap();
    assert!((disc.plane_moments().e12 - 0.5 * 2.0 * 0.25).abs() < 1e-15);
    let ball4 = RigidBody::<G4>::from_ball(3.0, 2.0).unwrap();
    assert!(ball4
        .second_moments()
        .iter()
        .all(|&l| (l - 2.0).abs() < 1e-15));
    assert!(RigidBody::<G4>::new(&[1.0, 2.0, 3.0]).is_err());
    assert!(RigidBody::<G4>::new(&[1.0, -2.0, 3.0, 1.0]).is_err());
    assert!(RigidBody::<G4>::new(&[0.0, 0.0, 3.0, 1.0]).is_err());
}

#[test]
fn point_masses_give_second_moments_and_the_principal_rotor() {
    // Pairs of masses at +-a_k along a turned frame R e_k (and shifted by c): the second
    // moments are 2 m a_k^2 and the principal axes R e_k, whatever R the points were made
    // with; the solver only sees the coordinates.
    let turn = g4::Bivector::new(0.4, -0.9, 0.3, 1.2, 0.2, -0.5).exp();
    let c = [0.3, -1.0, 2.0, 0.5];
    let (m, a) = (0.5, [1.0, 1.5, 0.5, 2.0]);
    let mut points = Vec::new();
    for k in 0..4 {
        let mut e = [0.0; 4];
        e[k] = a[k];
        let y = G4::rotate(turn, e);
        for sign in [1.0, -1.0] {
            points.push((m, [0, 1, 2, 3].map(|i| c[i] + sign * y[i])));
        }
    }
    let (body, frame) = RigidBody::<G4>::from_point_masses(&points).unwrap();
    let expected = [0.25, 1.0, 2.25, 4.0].map(|x: f64| 2.0 * m * x);
    assert!(
        max_difference(body.second_moments(), &expected) < 1e-14,
        "{body:?}"
    );
    assert!(max_difference(&frame.centre, &c) < 1e-15 && (frame.mass - 4.0).abs() < 1e-15);
    // Sorted ascending: axes 2, 0, 1, 3 of the turned frame, each up to sign.
    for (k, axis) in [2, 0, 1, 3].into_iter().enumerate() {
        let mut e = [0.0; 4];
        e[k] = 1.0;
        let got = G4::rotate(frame.rotor, e);
        let mut f = [0.0; 4];
        f[axis] = 1.0;
        let want = G4::rotate(turn, f);
        let dot: f64 = got.iter().zip(want).map(|(x, y)| x * y).sum();
        assert!((dot.abs() - 1.0).abs() < 1e-14, "axis {k}: {dot}");
    }
    assert!((G4::rotor_norm(frame.rotor) - 1.0).abs() < 1e-14);
}

#[test]
fn midpoint_and_splitting_converge_at_order_two_in_four_dimensions() {
    let (body, s0) = reference_body();
    let (omega_ref, q_ref) = matrix_reference(&L4, &OMEGA0, &IDENTITY, 2.0, 2000);
    let error = |state: State<G4>| {
        max_difference(&flat(&rotor_matrix(state.rotor)), &flat(&q_ref))
            .max(max_difference(&state.omega.to_array(), &omega_ref))
    };
    for name in ["midpoint", "splitting"] {
        let run = |h: f64| {
            let mut method: Box<dyn Integrator<G4>> = if name == "midpoint" {
                Box::new(ImplicitMidpoint::new(h).unwrap())
            } else {
                Box::new(PlaneSplitting::new(h).unwrap())
            };
            error(method.advance(&body, 0.0, s0, 2.0).unwrap())
        };
        let errors = [0.02, 0.01, 0.005].map(run);
        let orders = [
            (errors[0] / errors[1]).log2(),
            (errors[1] / errors[2]).log2(),
        ];
        eprintln!("{name}: errors {errors:?}, orders {orders:?}");
        assert!(
            orders.iter().all(|p| (1.9..2.1).contains(p)),
            "{name}: {orders:?}"
        );
    }
}

#[test]
fn a_time_dependent_torque_on_an_isotropic_body_adds_its_integral() {
    // All second moments l: I = 2l, Omega x I(Omega) = 0, so I(Omega)' = T(t) and with
    // T = t T0 (a closure), Omega(t) = Omega(0) + t^2 T0 / (4 l).
    let l = 0.8;
    let t0 = g4::Bivector::new(0.2, -0.1, 0.4, 0.3, -0.5, 0.1);
    let body = RigidBody::<G4>::new(&[l; 4])
        .unwrap()
        .with_torque(move |t: f64, _: &State<G4>| t0 * t);
    let s0 = State::<G4>::new(
        g4::Rotor::ONE,
        g4::Bivector::new(0.5, 0.0, 0.3, -0.2, 0.0, 0.9),
    );
    let t = 3.0;
    let expected = (s0.omega + t0 * (t * t / (4.0 * l))).to_array();
    let methods: Vec<Box<dyn Integrator<G4>>> = vec![
        Box::new(Rk4::new(0.1).unwrap()),
        Box::new(LieRk4::new(0.1).unwrap()),
        Box::new(LieDopri5::new(1e-12, 1e-12).unwrap()),
    ];
    for mut method in methods {
        let state = method.advance(&body, 0.0, s0, t).unwrap();
        let d = max_difference(&state.omega.to_array(), &expected);
        assert!(d < 1e-13, "{}: {d:e}", method.name());
    }
}

// ---------- lie-dop853 in four dimensions ----------

#[test]
fn lie_dop853_at_tolerance_1e_12_reaches_the_reference_state() {
    let (body, s0) = reference_body();
    let mut method = LieDop853::new(1e-12, 1e-12).unwrap();
    let state = method.advance(&body, 0.0, s0, 10.0).unwrap();
    let (dr, dw) = distance_to_reference(&state);
    eprintln!(
        "lie-dop853: |dR| {dr:e} |dOmega| {dw:e}, steps {:?}",
        method.steps()
    );
    assert!(dr < 1e-10 && dw < 1e-10, "{dr:e} {dw:e}");
}

/// The target: at `tol 1e-12` over t = 100 both Casimirs and Manakov's integrals
/// (k = 2, 3 at three lambdas) stay within 1e-11 of their start, relative.
#[test]
fn lie_dop853_keeps_casimirs_and_manakov_integrals_over_t_100() {
    let (body, s0) = reference_body();
    let lambdas = [-1.3, 0.4, 2.0];
    let integrals = |m: g4::Bivector| -> Vec<f64> {
        let (c0, c4) = casimirs(m);
        let mut all = vec![c0, c4];
        all.extend(
            lambdas
                .iter()
                .flat_map(|&lambda| [2, 3].map(|k| manakov(m, lambda, k))),
        );
        all
    };
    let initial = integrals(body.body_momentum(s0.omega));
    let mut method = LieDop853::new(1e-12, 1e-12).unwrap();
    let mut state = s0;
    let mut worst = 0.0_f64;
    for step in 0..100 {
        state = method.advance(&body, f64::from(step), state, 1.0).unwrap();
        let now = integrals(body.body_momentum(state.omega));
        for (a, b) in now.iter().zip(&initial) {
            worst = worst.max((a - b).abs() / b.abs());
        }
    }
    eprintln!(
        "lie-dop853 over t = 100: largest relative change {worst:e}, steps {:?}",
        method.steps()
    );
    assert!(worst < 1e-11, "{worst:e}");
}

#[test]
fn lie_dop853_converges_at_order_eight_in_four_dimensions() {
    let (body, s0) = reference_body();
    let method = LieDop853::new(1.0, 1.0).unwrap();
    let run = |n: u32| {
        let h = 8.0 / f64::from(n);
        let mut state = s0;
        for k in 0..n {
            state = method.step_once(&body, f64::from(k) * h, state, h);
        }
        state
    };
    let reference = run(256);
    let error = |n: u32| {
        let s = run(n);
        max_difference(&s.rotor.to_array(), &reference.rotor.to_array()).max(max_difference(
            &s.omega.to_array(),
            &reference.omega.to_array(),
        ))
    };
    let (coarse, fine) = (error(16), error(32));
    let order = (coarse / fine).log2();
    eprintln!("lie-dop853 fixed step: errors {coarse:e} {fine:e}, order {order:.2}");
    assert!(order > 7.3, "{order}");
}
