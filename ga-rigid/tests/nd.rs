//! The n-dimensional body (`ga_rigid::nd`) against values it did not compute itself: the
//! 4D test values of docs/references.md (scipy DOP853 at rtol 1e-13), a 4x4 matrix form
//! of Euler's equations integrated here, Manakov's integrals, the 3D exact flow of
//! `ga_rigid::exact_flow`, and the closed forms of docs/derivations/symmetric-body-4d.md.

use ga_core::f64::g4;
use ga_rigid::nd::{Algebra, Integrator, LieRk4, RigidBody, Rk4, State, G4};

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
