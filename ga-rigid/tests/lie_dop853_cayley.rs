//! lie-dop853 in Cayley coordinates (`LieDop853::cayley`) against the matrix reference
//! (tests/support): order eight on the Hairer-Vilmart body and a heavy top, dense output of
//! order seven, the tolerance met, rotors unit.

mod support;

use ga_core::f64::g3::*;
use ga_rigid::dynamics::{omega_from_vector, Gravity, RigidBody, State};
use ga_rigid::integrators::{Integrator, LieDop853};
use support::*;

fn error(body: &RigidBody, state: &State, reference: &Solution) -> f64 {
    let scale = distance(reference.m, [0.0; 3]).max(1.0);
    attitude_error(state.rotor, reference.rotor())
        .max(distance(momentum(body, state), reference.m) / scale)
}

/// The asymmetric heavy top of tests/high_order.rs, with its reference at `t`.
fn heavy_top(t: f64) -> (RigidBody, State, Solution) {
    let (moments, com, w0, mass) = ([2.0, 2.5, 1.0], [0.05, -0.02, 0.3], [0.3, -0.2, 8.0], 1.5);
    let g = [0.0, 0.0, -9.81];
    let rotor0 = Bivector::new(0.1, -0.2, 0.35).exp();
    let body = RigidBody::new(moments).unwrap().with_torque(Gravity {
        mass,
        g: Vector::new(g[0], g[1], g[2]),
        com_offset: Vector::new(com[0], com[1], com[2]),
    });
    let state = State {
        rotor: rotor0,
        omega: omega_from_vector(w0),
    };
    let top = HeavyTop { mass, g, com };
    let matrix0 = matrix_from_rotor(rotor_array(rotor0));
    let reference = reference(moments, matrix0, w0, Some(top), &[t])[0];
    (body, state, reference)
}

/// `n` fixed steps over `[0, t]`.
fn fixed(body: &RigidBody, state: State, t: f64, n: u32) -> State {
    let method = LieDop853::cayley(1e-10, 1e-10).unwrap();
    let h = t / f64::from(n);
    (0..n).fold(state, |s, i| method.step_once(body, f64::from(i) * h, s, h))
}

/// Order eight in the asymptotic range (the Cayley coordinates' error constant is larger
/// than exp's at `h |Omega| > 1`, so the steps start smaller than exp's order test).
#[test]
fn cayley_lie_dop853_reaches_order_eight() {
    let scene = HAIRER_VILMART;
    let t = 2.0;
    let reference = scene.reference(&[t])[0];
    let body = scene.body();
    let steps = [12, 16, 20, 24];
    let hs: Vec<f64> = steps.iter().map(|&n| t / f64::from(n)).collect();
    let errors: Vec<f64> = steps
        .iter()
        .map(|&n| error(&body, &fixed(&body, scene.state(), t, n), &reference))
        .collect();
    let order = fitted_order(&hs, &errors);
    println!("cayley on Hairer-Vilmart: errors {errors:?}, order {order:.3}");
    // The local slopes climb to eight from below (7.78, 7.86, 7.92 from h = 0.25 down to
    // 0.083) and the errors reach the reference's floor before they settle: allow 0.15.
    assert!((order - 8.0).abs() < 0.15, "order {order}");

    let t = 1.0;
    let (body, state, reference) = heavy_top(t);
    let steps = [7, 10, 14, 20];
    let hs: Vec<f64> = steps.iter().map(|&n| t / f64::from(n)).collect();
    let errors: Vec<f64> = steps
        .iter()
        .map(|&n| error(&body, &fixed(&body, state, t, n), &reference))
        .collect();
    let order = fitted_order(&hs, &errors);
    println!("cayley on the heavy top: errors {errors:?}, order {order:.3}");
    assert!((order - 8.0).abs() < 0.1, "order {order}");
}

/// The dense output's local error is `O(h^8)`, and its rotors unit.
#[test]
fn cayley_dense_output_reaches_order_seven_within_a_step() {
    let scene = HAIRER_VILMART;
    let body = scene.body();
    let method = LieDop853::cayley(1e-10, 1e-10).unwrap();
    let hs = [0.3, 0.2, 0.15, 0.1];
    let errors: Vec<f64> = hs
        .iter()
        .map(|&h| {
            let dense = method.dense_step_once(&body, 0.0, scene.state(), h);
            let times = [0.2 * h, 0.45 * h, 0.7 * h, 0.9 * h];
            times
                .iter()
                .zip(scene.reference(&times))
                .map(|(&t, r)| {
                    let s = dense.at(t).unwrap();
                    assert!(unit_defect(s.rotor) < 1e-15);
                    error(&body, &s, &r)
                })
                .fold(0.0, f64::max)
        })
        .collect();
    let order = fitted_order(&hs, &errors);
    println!("cayley dense output: errors {errors:?}, order {order:.3}");
    assert!((order - 8.0).abs() < 0.3, "order {order}");
}

/// The adaptive method meets its tolerance, and the rotor stays unit over a long run.
#[test]
fn adaptive_cayley_lie_dop853_meets_its_tolerance_and_keeps_rotors_unit() {
    let t = 2.0;
    let (body, state, reference) = heavy_top(t);
    for tol in [1e-8, 1e-11] {
        let mut method = LieDop853::cayley(tol, tol).unwrap();
        let end = method.advance(&body, 0.0, state, t).unwrap();
        let e = error(&body, &end, &reference);
        println!("cayley tol {tol:e}: error {e:.2e}, {:?}", method.stats());
        assert!(e < 100.0 * tol, "tol {tol:e}: error {e:e}");
    }
    let mut method = LieDop853::cayley(1e-12, 1e-12).unwrap();
    let end = method.advance(&body, 0.0, state, 50.0).unwrap();
    assert!(unit_defect(end.rotor) < 1e-13);
    // Its own name in the registry, so that the report's rows say which coordinates ran.
    assert_eq!(method.name(), "lie-dop853-cayley");
}
