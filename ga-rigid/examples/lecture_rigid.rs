//! The lecture's rigid-body examples: the inertia of a box and the symmetric top's closed
//! form `R(t) = exp(-Omega_l t / 2) R(0) exp(-Omega_r t / 2)`. Run with
//! `cargo run -p ga-rigid --example lecture_rigid`; every claim is asserted.

use ga_core::f64::g3::*;
use ga_rigid::dynamics::{
    omega_from_vector, RigidBody, State, SymmetricTop, DEFAULT_SYMMETRY_TOLERANCE,
};
use ga_rigid::inertia::Inertia;

fn main() -> Result<(), ga_rigid::error::Error> {
    box_inertia()?;
    symmetric_top()
}

/// A box of mass 2 and edges 1, 2, 3: `i1 = m (b^2 + c^2) / 12` and cyclically, checked
/// against a grid of point masses filling the box (midpoint rule, error O(1/n^2)).
fn box_inertia() -> Result<(), ga_rigid::error::Error> {
    let (mass, size) = (2.0, [1.0, 2.0, 3.0]);
    let solid = Inertia::solid_box(mass, size)?;
    let n = 24;
    let m = mass / f64::from(n * n * n);
    let cell = |k: u32, edge: f64| (f64::from(k) + 0.5) / f64::from(n) * edge - edge / 2.0;
    let mut points = Vec::new();
    for i in 0..n {
        for j in 0..n {
            for k in 0..n {
                points.push((m, [cell(i, size[0]), cell(j, size[1]), cell(k, size[2])]));
            }
        }
    }
    let grid = Inertia::from_point_masses(&points)?;
    let mut exact = solid.moments();
    let mut sampled = grid.moments();
    exact.sort_by(f64::total_cmp);
    sampled.sort_by(f64::total_cmp);
    println!("box moments {exact:?}; {n}^3 point masses give {sampled:?}");
    for (e, s) in exact.iter().zip(sampled) {
        assert!((e - s).abs() < 1e-2 * e);
    }
    // The inertia maps a bivector to a bivector: spin in the e12 plane gives momentum
    // i3 e12 about the box's long axis e3.
    let l = solid.apply(Bivector::E12);
    println!("I(e12) = {l:.4}");
    assert!((l - Bivector::E12 * (mass * (1.0 + 4.0) / 12.0)).norm() < 1e-12);
    Ok(())
}

/// A symmetric top (i1 = i2 = 2, i3 = 1) spinning fast about e3 with a small wobble.
fn symmetric_top() -> Result<(), ga_rigid::error::Error> {
    let body = RigidBody::new([2.0, 2.0, 1.0])?;
    let initial = State {
        rotor: Rotor::ONE,
        omega: omega_from_vector([0.3, 0.0, 5.0]),
    };
    let top = SymmetricTop::new(&body, initial, DEFAULT_SYMMETRY_TOLERANCE)?;
    let l0 = body.space_momentum(&initial);
    for t in [0.0, 1.0, 2.5, 10.0] {
        let state = top.state(t);
        println!("t = {t:>4}: R = {:.5}", state.rotor);
        // The space angular momentum is conserved and the rotor stays unit.
        assert!((body.space_momentum(&state) - l0).norm() < 1e-12);
        assert!((state.rotor.norm() - 1.0).abs() < 1e-14);
        // The closed form solves dR/dt = -1/2 R Omega_B (central difference).
        let h = 1e-5;
        let rate = (top.rotor(t + h) - top.rotor(t - h)) * (0.5 / h);
        let expected = state.rotor * state.omega * -0.5;
        assert!((rate - expected).norm() < 1e-8, "{rate} vs {expected}");
    }
    // The lecture's two precession rates: Omega_l = L / i1 and
    // Omega_r = w3 (i1 - i3) / i1 I e3, so R(t) for the top is the product of two exps.
    let omega_l = l0 * 0.5;
    let omega_r = Bivector::E12 * (5.0 * (2.0 - 1.0) / 2.0);
    let t = 2.5;
    let by_hand = (omega_l * (-t / 2.0)).exp() * (omega_r * (-t / 2.0)).exp();
    println!("exp(-Omega_l t/2) exp(-Omega_r t/2) at t = {t}: {by_hand:.5}");
    assert!((by_hand - top.rotor(t)).norm() < 1e-12);
    Ok(())
}
