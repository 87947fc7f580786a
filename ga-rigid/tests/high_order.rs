//! The high-order steppers of issue 11 against the matrix reference (tests/support):
//! observed orders on the Hairer-Vilmart body and on heavy tops, `|R ~R| = 1`, and the
//! invariants over long runs.

mod support;

use ga_core::f64::g3::*;
use ga_rigid::dynamics::{omega_from_vector, Gravity, RigidBody, State};
use ga_rigid::integrators::{ComposedSplitting, ExactSplitting, Integrator, LieDop853};
use support::*;

/// A heavy top with its matrix reference at `times`.
struct Heavy {
    body: RigidBody,
    state: State,
    moments: [f64; 3],
    matrix0: Matrix,
    w0: [f64; 3],
    top: HeavyTop,
}

impl Heavy {
    fn reference(&self, t: f64) -> Solution {
        reference(self.moments, self.matrix0, self.w0, Some(self.top), &[t])[0]
    }
}

fn heavy(moments: [f64; 3], com: [f64; 3], w0: [f64; 3], rotor0: Rotor, mass: f64) -> Heavy {
    let g = [0.0, 0.0, -9.81];
    let body = RigidBody::new(moments).unwrap().with_torque(Gravity {
        mass,
        g: Vector::new(g[0], g[1], g[2]),
        com_offset: Vector::new(com[0], com[1], com[2]),
    });
    Heavy {
        body,
        state: State {
            rotor: rotor0,
            omega: omega_from_vector(w0),
        },
        moments,
        matrix0: matrix_from_rotor(rotor_array(rotor0)),
        w0,
        top: HeavyTop { mass, g, com },
    }
}

/// An asymmetric heavy top (the one of tests/integrators.rs): the free flow is elliptic.
fn asymmetric_top() -> Heavy {
    heavy(
        [2.0, 2.5, 1.0],
        [0.05, -0.02, 0.3],
        [0.3, -0.2, 8.0],
        Bivector::new(0.1, -0.2, 0.35).exp(),
        1.5,
    )
}

/// The report's heavy top, a Lagrange top: moments (1, 1, 0.5), centre of mass 0.5 up the
/// symmetry axis, tilted 0.3 rad, spinning at 20 rad/s.
fn lagrange_top() -> Heavy {
    heavy(
        [1.0, 1.0, 0.5],
        [0.0, 0.0, 0.5],
        [0.0, 0.0, 20.0],
        (Bivector::E23 * -0.15).exp(),
        1.0,
    )
}

/// The combined error: attitude angle and `|m - m_ref| / max(|m_ref|, 1)`.
fn error(body: &RigidBody, end: &State, reference: &Solution) -> f64 {
    let m = momentum(body, end);
    let scale = distance(reference.m, [0.0; 3]).max(1.0);
    attitude_error(end.rotor, reference.rotor()).max(distance(m, reference.m) / scale)
}

/// The slope of log error against log h over these step counts on `[0, t]`.
fn observed_order(steps: &[u32], t: f64, mut run: impl FnMut(f64, u32) -> f64, label: &str) -> f64 {
    let hs: Vec<f64> = steps.iter().map(|&n| t / f64::from(n)).collect();
    let errors: Vec<f64> = steps.iter().zip(&hs).map(|(&n, &h)| run(h, n)).collect();
    let order = fitted_order(&hs, &errors);
    let shown: Vec<String> = errors.iter().map(|e| format!("{e:.2e}")).collect();
    println!(
        "{label}: errors {}, observed order {order:.3}",
        shown.join(" ")
    );
    order
}

fn assert_order(observed: f64, expected: u32, label: &str) {
    assert_order_within(observed, expected, 0.1, label);
}

fn assert_order_within(observed: f64, expected: u32, tolerance: f64, label: &str) {
    assert!(
        (observed - f64::from(expected)).abs() < tolerance,
        "{label}: observed order {observed:.3}, expected {expected}"
    );
}

#[test]
fn composed_splittings_reach_their_order_on_the_hairer_vilmart_body() {
    let scene = HAIRER_VILMART;
    let t = 2.0;
    let reference = scene.reference(&[t])[0];
    let body = scene.body();
    for (order, steps) in [
        (2, [40, 80, 160, 320]),
        (4, [20, 40, 80, 160]),
        (6, [10, 14, 20, 28]),
        (8, [10, 12, 14, 16]),
    ] {
        let label = format!("splitting-{order} on Hairer-Vilmart");
        let observed = observed_order(
            &steps,
            t,
            |h, _| {
                let mut method = ComposedSplitting::new(h * (1.0 + 1e-12), order).unwrap();
                let end = method.advance(&body, 0.0, scene.state(), t).unwrap();
                error(&body, &end, &reference)
            },
            &label,
        );
        assert_order(observed, order, &label);
    }
}

/// `n` fixed steps of the order-8 Lie-group method, whatever its error estimate says.
fn lie_dop853_fixed(body: &RigidBody, state: State, t: f64, n: u32) -> State {
    let method = LieDop853::new(1e-10, 1e-10).unwrap();
    let h = t / f64::from(n);
    (0..n).fold(state, |s, i| method.step_once(body, f64::from(i) * h, s, h))
}

/// A step a hair longer than `t / n`, so that rounding never adds an `n + 1`-th step.
fn step_for(t: f64, n: u32) -> f64 {
    t / f64::from(n) * (1.0 + 1e-12)
}

#[test]
fn lie_dop853_reaches_order_eight_on_the_hairer_vilmart_body() {
    let scene = HAIRER_VILMART;
    let t = 2.0;
    let reference = scene.reference(&[t])[0];
    let body = scene.body();
    let observed = observed_order(
        &[4, 6, 8, 12],
        t,
        |_, n| {
            error(
                &body,
                &lie_dop853_fixed(&body, scene.state(), t, n),
                &reference,
            )
        },
        "lie-dop853 on Hairer-Vilmart",
    );
    assert_order(observed, 8, "lie-dop853 on Hairer-Vilmart");
}

/// Every torqued method on both heavy tops over `[0, 1]`: the elliptic free flow on the
/// asymmetric one, the closed form on the Lagrange top.
#[test]
fn torqued_methods_reach_their_order_on_heavy_tops() {
    let t = 1.0;
    for (name, top) in [
        ("asymmetric", asymmetric_top()),
        ("Lagrange", lagrange_top()),
    ] {
        let reference = top.reference(t);
        let cases: [(u32, [u32; 4]); 4] = [
            (2, [10, 20, 40, 80]),
            // Blanes and Moan's Nystrom splittings: at coarser steps their small leading
            // error term still competes with the next.
            (4, [40, 56, 80, 113]),
            (6, [7, 10, 14, 20]),
            (8, [10, 12, 14, 16]),
        ];
        for (order, steps) in cases {
            let label = format!("exact-splitting-{order} on the {name} top");
            let observed = observed_order(
                &steps,
                t,
                |_, n| {
                    let mut method = ExactSplitting::with_order(step_for(t, n), order).unwrap();
                    let end = method.advance(&top.body, 0.0, top.state, t).unwrap();
                    error(&top.body, &end, &reference)
                },
                &label,
            );
            // On the asymmetric top the order-eight error reaches the 1e-13 floor of the
            // elliptic flow before its local slope (8.39, 8.28, 8.15 from h = 0.2 down to
            // 0.07) has settled at eight, and so does the order-six one (6.24, 6.11, 6.05
            // from h = 0.14 to 0.05, then 6.24 at the floor): allow those cases 0.15.
            let tolerance = if (order == 8 || order == 6) && name == "asymmetric" {
                0.15
            } else {
                0.1
            };
            assert_order_within(observed, order, tolerance, &label);
        }
        let lie_steps: [u32; 4] = if name == "Lagrange" {
            [10, 14, 20, 28]
        } else {
            [7, 10, 14, 20]
        };
        let label = format!("lie-dop853 on the {name} top");
        let observed = observed_order(
            &lie_steps,
            t,
            |_, n| {
                error(
                    &top.body,
                    &lie_dop853_fixed(&top.body, top.state, t, n),
                    &reference,
                )
            },
            &label,
        );
        assert_order(observed, 8, &label);
    }
    // The DLM compositions with torque kicks, on the asymmetric top.
    let top = asymmetric_top();
    let reference = top.reference(t);
    for (order, steps) in [
        (4, [10, 20, 40, 80]),
        (6, [10, 20, 40, 80]),
        (8, [5, 7, 10, 14]),
    ] {
        let label = format!("splitting-{order} on the asymmetric top");
        let observed = observed_order(
            &steps,
            t,
            |_, n| {
                let mut method = ComposedSplitting::new(step_for(t, n), order).unwrap();
                let end = method.advance(&top.body, 0.0, top.state, t).unwrap();
                error(&top.body, &end, &reference)
            },
            &label,
        );
        assert_order(observed, order, &label);
    }
}

#[test]
fn adaptive_lie_dop853_meets_its_tolerance_on_the_heavy_top() {
    let top = asymmetric_top();
    let t = 2.0;
    let reference = top.reference(t);
    for tol in [1e-8, 1e-11] {
        let mut method = LieDop853::new(tol, tol).unwrap();
        let end = method.advance(&top.body, 0.0, top.state, t).unwrap();
        let e = error(&top.body, &end, &reference);
        println!(
            "lie-dop853 tol {tol:e}: error {e:.2e}, {:?}",
            method.stats()
        );
        assert!(e < 100.0 * tol, "tol {tol:e}: error {e:e}");
        assert!(method.stats().accepted > 0);
    }
}

/// The rotor stays unit: the Lie-group method moves it by exponentials of bivectors only,
/// the splittings by rotor products scaled back to unit norm once a step.
#[test]
fn rotors_stay_unit_over_many_steps() {
    let top = lagrange_top();
    let asym = asymmetric_top();
    let free = HAIRER_VILMART;
    let steps = 20_000;
    let h = 1e-3;
    let t = f64::from(steps) * h;
    let mut runs: Vec<(&str, State)> = Vec::new();
    for order in [2, 8] {
        let mut method = ExactSplitting::with_order(h, order).unwrap();
        runs.push((
            "exact-splitting",
            method.advance(&top.body, 0.0, top.state, t).unwrap(),
        ));
        let mut method = ComposedSplitting::new(h, order).unwrap();
        runs.push((
            "splitting-n free",
            method.advance(&free.body(), 0.0, free.state(), t).unwrap(),
        ));
    }
    let mut method = ComposedSplitting::new(h, 8).unwrap();
    runs.push((
        "splitting-8 torqued",
        method.advance(&asym.body, 0.0, asym.state, 2.0).unwrap(),
    ));
    runs.push((
        "lie-dop853 fixed",
        lie_dop853_fixed(&asym.body, asym.state, t, steps),
    ));
    let mut method = LieDop853::new(1e-12, 1e-12).unwrap();
    runs.push((
        "lie-dop853 adaptive",
        method.advance(&asym.body, 0.0, asym.state, 50.0).unwrap(),
    ));
    for (name, end) in runs {
        let defect = unit_defect(end.rotor);
        println!("{name}: |R ~R - 1| = {defect:.1e}");
        assert!(defect < 1e-13, "{name}: {defect:e}");
    }
}

/// Symplectic compositions keep the energy error bounded (no drift) and, for a free body,
/// `|m|` and `L` to rounding.
#[test]
fn invariants_stay_bounded_over_long_runs() {
    let scene = HAIRER_VILMART;
    let body = scene.body();
    let mut state = scene.state();
    let e0 = body.energy(state.omega);
    let l0 = body.space_momentum(&state);
    let mut method = ComposedSplitting::new(0.1, 6).unwrap();
    let (mut worst_e, mut worst_l) = (0.0_f64, 0.0_f64);
    // About 400 periods of the momentum (T ~ 5).
    for i in 0..2000 {
        state = method.advance(&body, f64::from(i), state, 1.0).unwrap();
        worst_e = worst_e.max((body.energy(state.omega) - e0).abs() / e0);
        let dl = body.space_momentum(&state) - l0;
        worst_l = worst_l.max((dl.e12 * dl.e12 + dl.e13 * dl.e13 + dl.e23 * dl.e23).sqrt());
    }
    println!("splitting-6, 2000 time units: energy {worst_e:.1e}, L {worst_l:.1e}");
    assert!(worst_e < 1e-6, "energy {worst_e:e}");
    assert!(worst_l < 1e-12, "L {worst_l:e}");

    let top = lagrange_top();
    let mut state = top.state;
    let e0 = top.body.total_energy(0.0, &state);
    let mut method = ExactSplitting::with_order(0.02, 4).unwrap();
    let mut errors = Vec::new();
    for i in 0..400 {
        state = method.advance(&top.body, f64::from(i), state, 1.0).unwrap();
        errors.push((top.body.total_energy(0.0, &state) - e0).abs() / e0.abs());
    }
    let first = errors[..200].iter().copied().fold(0.0, f64::max);
    let last = errors[200..].iter().copied().fold(0.0, f64::max);
    println!(
        "exact-splitting-4 on the Lagrange top, 400 s: energy error {first:.1e} then {last:.1e}"
    );
    assert!(last < 1e-5, "energy error {last:e}");
    // Bounded, not drifting: the second half no worse than twice the first.
    assert!(last < 2.0 * first + 1e-12, "drift: {first:e} then {last:e}");
}

#[test]
fn names_and_bad_orders() {
    assert_eq!(ExactSplitting::new(0.1).unwrap().name(), "exact-splitting");
    assert_eq!(
        ExactSplitting::with_order(0.1, 6).unwrap().name(),
        "exact-splitting-6"
    );
    assert_eq!(
        ComposedSplitting::new(0.1, 8).unwrap().name(),
        "splitting-8"
    );
    assert_eq!(LieDop853::new(1e-9, 1e-9).unwrap().name(), "lie-dop853");
    assert!(ExactSplitting::with_order(0.1, 5).is_err());
    assert!(ComposedSplitting::new(0.1, 10).is_err());
    assert!(ComposedSplitting::new(-0.1, 4).is_err());
    assert!(LieDop853::new(0.0, 1e-9).is_err());
    let mut method = LieDop853::new(1e-9, 1e-9).unwrap();
    let body = HAIRER_VILMART.body();
    assert!(method
        .advance(&body, 0.0, HAIRER_VILMART.state(), f64::NAN)
        .is_err());
}

/// Every new method through `simulate`'s entry point, by its `--method` name, on a heavy
/// scene: the rows agree with RK4 at a fine step.
#[test]
fn new_methods_run_through_simulate() {
    use ga_rigid::registry::{Method, Step};
    use ga_rigid::run::run_simulation;
    use ga_rigid::scene::Scene;
    use std::path::Path;
    let text = "[body]\nmoments = [2.0, 1.5, 1.0]\n[initial]\nrotor = [0.9, 0.1, -0.3, 0.2]\n\
                omega = [0.3, -0.4, 5.0]\n[run]\nt_end = 2.0\nsamples = 5\n[torque]\n\
                g = [0.0, 0.0, -9.81]\ncom_offset = [0.0, 0.0, 0.5]\n";
    let scene = Scene::parse(text, Path::new("inline.toml")).unwrap();
    let truth = run_simulation(&scene, Method::Rk4, Step::Fixed(1e-3)).unwrap();
    let cases = [
        (Method::ExactSplitting, Step::Fixed(1e-3), "exact-splitting"),
        (
            Method::ExactSplitting4,
            Step::Fixed(1e-2),
            "exact-splitting-4",
        ),
        (
            Method::ExactSplitting6,
            Step::Fixed(2e-2),
            "exact-splitting-6",
        ),
        (
            Method::ExactSplitting8,
            Step::Fixed(5e-2),
            "exact-splitting-8",
        ),
        (Method::Splitting4, Step::Fixed(1e-2), "splitting-4"),
        (Method::Splitting6, Step::Fixed(2e-2), "splitting-6"),
        (Method::Splitting8, Step::Fixed(5e-2), "splitting-8"),
        (Method::LieDop853, Step::Tolerance(1e-10), "lie-dop853"),
    ];
    for (method, step, name) in cases {
        assert_eq!(method.name(), name);
        let rows = run_simulation(&scene, method, step).unwrap();
        for (row, expected) in rows.iter().zip(&truth) {
            let (a, b) = (row.values(), expected.values());
            // Omega and the energy (entries 5 on); the rotor's sign may differ.
            let worst = (5..a.len())
                .map(|k| (a[k] - b[k]).abs())
                .fold(0.0, f64::max);
            assert!(worst < 1e-5, "{name}: {worst:e}");
        }
    }
    assert!(run_simulation(&scene, Method::LieDop853, Step::Fixed(0.1)).is_err());
}

/// Without a torque the exact-flow splitting is the exact flow: the symmetric closed form
/// and the elliptic solution, whatever the step.
#[test]
fn exact_splitting_without_torque_is_the_free_flow() {
    for scene in [SHORT_FAT.runnable().scene, HAIRER_VILMART] {
        let body = scene.body();
        let t = 3.0;
        let reference = scene.reference(&[t])[0];
        let mut method = ExactSplitting::with_order(0.5, 8).unwrap();
        let end = method.advance(&body, 0.0, scene.state(), t).unwrap();
        let e = error(&body, &end, &reference);
        assert!(e < 1e-12, "{}: {e:e}", scene.name);
    }
}
