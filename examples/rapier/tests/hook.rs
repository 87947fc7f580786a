//! The hook that hands ga-engine's step to rapier, checked inside rapier: the momentum the
//! engine keeps, the flip period against the exact free flow (ga-rigid's elliptic
//! functions), rapier's pose against the orientation the step asked for, and the top's
//! conserved quantities. A minute of simulated time each (3600 steps), a few seconds in a
//! debug build.

use ga_rapier_example::{run_t_handle, run_top, t_handle, Method, Scene};

const MINUTE: usize = 3600;

#[test]
fn engine_step_in_rapier_keeps_l_and_the_flip_period() {
    let r = run_t_handle(Method::RapierWithEngineStep, MINUTE);
    assert!(
        r.momentum.worst <= 1e-12,
        "|L| drifted by {:e}",
        r.momentum.worst
    );
    let exact = t_handle::exact_period();
    assert!(r.flips >= 3, "only {} flips in a minute", r.flips);
    let error = (r.period / exact - 1.0).abs();
    assert!(
        error < 0.01,
        "flip period {} s against the exact {exact} s",
        r.period
    );
    // The energy of the second-order step at 60 Hz stays near its start (no drift).
    assert!(
        r.energy.worst < 1e-4,
        "energy moved by {:e}",
        r.energy.worst
    );
}

#[test]
fn rapier_lands_on_the_orientation_the_step_asked_for() {
    // rapier's substeps turn by 2 atan(|w| h / 2), not |w| h: the landing velocity undoes
    // that, so the pose rapier integrates is the step's orientation to f32 rounding. The
    // plain `angle / dt` misses by about 1e-5 rad a step here (9.4e-6 when swapped in).
    let r = run_t_handle(Method::RapierWithEngineStep, 600);
    assert!(
        r.landing < 2e-6,
        "rapier's pose missed by {:e} rad",
        r.landing
    );
}

#[test]
fn engine_step_in_rapier_keeps_the_tops_invariants() {
    let r = run_top(Scene::Top, Method::RapierWithEngineStep, MINUTE);
    // Gravity's torque about the tip is horizontal: L_z is kept to the bit.
    assert_eq!(r.vertical.worst, 0.0, "L_z drifted");
    assert!(r.spin.worst < 1e-5, "spin moved by {:e}", r.spin.worst);
    assert!(
        r.energy.worst < 1e-5,
        "energy moved by {:e}",
        r.energy.worst
    );
    // The centre of mass is put where the orientation puts it above the tip.
    assert!(r.tip < 1e-5, "the tip left its point by {} m", r.tip);
}

#[test]
fn rapiers_own_step_loses_the_spin_of_a_free_symmetric_body() {
    // What the README says of rapier alone: a symmetric body spun about its smallest
    // moment, whose spin is constant in the exact motion, loses much of it within ten
    // seconds under rapier's explicit gyroscopic term; with the engine's step it keeps it.
    let rapier = run_top(Scene::SpinningFree, Method::Rapier, 600);
    assert!(
        rapier.spin.end < -0.1,
        "rapier kept the spin: {:e}",
        rapier.spin.end
    );
    let engine = run_top(Scene::SpinningFree, Method::RapierWithEngineStep, 600);
    assert!(
        engine.spin.worst < 1e-5,
        "spin moved by {:e}",
        engine.spin.worst
    );
}
