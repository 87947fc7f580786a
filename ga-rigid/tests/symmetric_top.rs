//! The closed-form symmetric top (`SymmetricTop`) against the matrix reference
//! (tests/support): bodies symmetric about each of the three axes, long runs, its
//! invariants, Principia's "short fat" top, and the bodies it must refuse.

mod support;

use ga_core::f64::g3::*;
use ga_rigid::dynamics::{
    omega_from_vector, Gravity, RigidBody, State, SymmetricTop, DEFAULT_SYMMETRY_TOLERANCE,
};
use ga_rigid::error::Error;
use support::*;

/// Symmetric bodies (about e3, e1, e2, oblate and prolate) and initial states, some with a
/// tilted start.
fn cases() -> Vec<([f64; 3], [f64; 3], Rotor)> {
    let tilted = Bivector::new(0.3, -0.7, 0.2).exp();
    vec![
        ([2.0, 2.0, 1.0], [0.4, -0.3, 2.5], Rotor::ONE),
        ([1.0, 1.0, 1.5], [1.2, 0.5, -0.8], tilted),
        ([1.5, 2.0, 2.0], [3.0, 0.2, -0.6], Rotor::ONE),
        ([1.5, 2.0, 2.0], [-0.5, 1.1, 0.9], tilted),
        ([2.0, 0.8, 2.0], [0.3, 2.2, 0.4], tilted),
        ([2.0, 3.5, 2.0], [0.7, -0.4, 1.3], Rotor::ONE),
    ]
}

#[test]
fn closed_form_matches_matrix_reference_for_symmetry_about_each_axis() {
    let times: Vec<f64> = (1..=10).map(|k| 10.0 * f64::from(k)).collect();
    for (moments, w0, rotor0) in cases() {
        let body = RigidBody::new(moments).unwrap();
        let initial = State {
            rotor: rotor0,
            omega: omega_from_vector(w0),
        };
        let top = SymmetricTop::new(&body, initial, DEFAULT_SYMMETRY_TOLERANCE).unwrap();
        let reference = reference(
            moments,
            matrix_from_rotor(rotor_array(rotor0)),
            w0,
            None,
            &times,
        );
        let mut worst = 0.0_f64;
        for point in &reference {
            let state = top.state(point.t);
            let dm = distance(momentum(&body, &state), point.m);
            worst = worst
                .max(dm)
                .max(attitude_error(state.rotor, point.rotor()));
            // The rotor alone agrees with the state's.
            assert_eq!(top.rotor(point.t), state.rotor);
        }
        println!("moments {moments:?}, w0 {w0:?}: worst error to t = 100 {worst:.3e}");
        assert!(worst < 1e-10, "{moments:?} {w0:?}: {worst:e}");
    }
}

#[test]
fn closed_form_matches_matrix_reference_on_the_needle() {
    // 1000 rad/s about the symmetry axis, to t = 10.
    let body = NEEDLE.body();
    let top = SymmetricTop::new(&body, NEEDLE.state(), DEFAULT_SYMMETRY_TOLERANCE).unwrap();
    let reference = NEEDLE.reference(&[2.5, 5.0, 10.0]);
    for point in &reference {
        let state = top.state(point.t);
        let dm = distance(momentum(&body, &state), point.m);
        let da = attitude_error(state.rotor, point.rotor());
        println!(
            "needle t = {}: |m - m_ref| {dm:.3e}, attitude {da:.3e}",
            point.t
        );
        assert!(dm < 1e-11 && da < 1e-9, "t = {}: {dm:e} {da:e}", point.t);
    }
}

#[test]
fn closed_form_keeps_energy_and_space_momentum() {
    for (moments, w0, rotor0) in cases() {
        let body = RigidBody::new(moments).unwrap();
        let initial = State {
            rotor: rotor0,
            omega: omega_from_vector(w0),
        };
        let top = SymmetricTop::new(&body, initial, DEFAULT_SYMMETRY_TOLERANCE).unwrap();
        let energy0 = body.energy(initial.omega);
        let space0 = body.space_momentum(&initial);
        for k in 0..=100 {
            let t = f64::from(k);
            let state = top.state(t);
            let de = (body.energy(state.omega) - energy0).abs() / energy0;
            let dl = (body.space_momentum(&state) - space0).norm() / space0.norm();
            let dn = (body.space_momentum(&state).norm() - space0.norm()).abs() / space0.norm();
            assert!(de < 1e-14, "{moments:?} t = {t}: energy {de:e}");
            assert!(
                dl < 1e-13 && dn < 1e-14,
                "{moments:?} t = {t}: L {dl:e}, |L| {dn:e}"
            );
            assert!(unit_defect(state.rotor) < 1e-14);
        }
    }
}

#[test]
fn short_fat_momentum_turns_at_minus_fourteen_ninths() {
    // Principia: moments (3, 3, 9), m(0) = (0, 5, 7): m(t) = (5 sin Wt, 5 cos Wt, 7),
    // W = -14/9. `runnable` swaps in a body with the same m(t) if (3, 3, 9) is refused.
    let runnable = SHORT_FAT.runnable();
    let scene = runnable.scene;
    let body = scene.body();
    let top = SymmetricTop::new(&body, scene.state(), DEFAULT_SYMMETRY_TOLERANCE).unwrap();
    let space = body.space_momentum(&scene.state());
    let w = -14.0 / 9.0;
    for k in 0..=200 {
        let t = 0.5 * f64::from(k);
        let expected = [5.0 * (w * t).sin(), 5.0 * (w * t).cos(), 7.0];
        // m(t) from the attitude alone: the constant space momentum pulled back.
        let pulled = top.rotor(t).reverse().sandwich(space);
        let from_rotor = [pulled.e23, -pulled.e13, pulled.e12];
        let from_state = momentum(&body, &top.state(t));
        assert!(
            distance(from_rotor, expected) < 1e-12,
            "t = {t}: {from_rotor:?}"
        );
        assert!(
            distance(from_state, expected) < 1e-12,
            "t = {t}: {from_state:?}"
        );
    }
    println!(
        "short fat run with moments {:?} (shift {})",
        scene.moments, runnable.shift
    );
}

#[test]
fn asymmetric_or_driven_bodies_are_refused() {
    let body = HAIRER_VILMART.body();
    let e = SymmetricTop::new(&body, HAIRER_VILMART.state(), DEFAULT_SYMMETRY_TOLERANCE);
    match e {
        Err(e @ Error::Invalid { .. }) => {
            assert_eq!(e.field(), Some("body.moments"));
            println!("{e}");
        }
        other => panic!("expected an error, got {other:?}"),
    }
    let driven = RigidBody::new([2.0, 2.0, 1.0])
        .unwrap()
        .with_torque(Gravity {
            mass: 1.0,
            g: Vector::new(0.0, 0.0, -9.81),
            com_offset: Vector::new(0.0, 0.0, 0.2),
        });
    let state = State {
        rotor: Rotor::ONE,
        omega: omega_from_vector([0.1, 0.0, 3.0]),
    };
    assert!(SymmetricTop::new(&driven, state, DEFAULT_SYMMETRY_TOLERANCE).is_err());
}
