//! Dense output of lie-dop853 (issue 11) against the matrix reference (tests/support): the
//! order of the continuous extension within a step, continuity at the step ends, unit
//! rotors, the samples of a run, and the errors for times outside a step.

mod support;

use ga_core::f64::g3::*;
use ga_rigid::dynamics::{omega_from_vector, Gravity, RigidBody, State};
use ga_rigid::error::Error;
use ga_rigid::integrators::{DenseStep, DormandPrince, Integrator, LieDop853};
use support::*;

/// A body with its matrix reference from `state` at t = 0.
struct Problem {
    name: &'static str,
    body: RigidBody,
    state: State,
    moments: [f64; 3],
    matrix0: Matrix,
    w0: [f64; 3],
    top: Option<HeavyTop>,
}

impl Problem {
    fn reference(&self, times: &[f64]) -> Vec<Solution> {
        reference(self.moments, self.matrix0, self.w0, self.top, times)
    }
}

/// The Hairer-Vilmart body, free.
fn free_body() -> Problem {
    let scene = HAIRER_VILMART;
    Problem {
        name: "Hairer-Vilmart",
        body: scene.body(),
        state: scene.state(),
        moments: scene.moments,
        matrix0: IDENTITY,
        w0: scene.w0(),
        top: None,
    }
}

/// The asymmetric heavy top of tests/high_order.rs: with a torque the stages take
/// exponentials, and the free flow is elliptic.
fn heavy_top() -> Problem {
    let (moments, com, w0, mass) = ([2.0, 2.5, 1.0], [0.05, -0.02, 0.3], [0.3, -0.2, 8.0], 1.5);
    let g = [0.0, 0.0, -9.81];
    let rotor0 = Bivector::new(0.1, -0.2, 0.35).exp();
    Problem {
        name: "asymmetric heavy top",
        body: RigidBody::new(moments).unwrap().with_torque(Gravity {
            mass,
            g: Vector::new(g[0], g[1], g[2]),
            com_offset: Vector::new(com[0], com[1], com[2]),
        }),
        state: State {
            rotor: rotor0,
            omega: omega_from_vector(w0),
        },
        moments,
        matrix0: matrix_from_rotor(rotor_array(rotor0)),
        w0,
        top: Some(HeavyTop { mass, g, com }),
    }
}

/// The attitude angle and `|m - m_ref| / max(|m_ref|, 1)`, the larger.
fn error(body: &RigidBody, state: &State, reference: &Solution) -> f64 {
    let scale = distance(reference.m, [0.0; 3]).max(1.0);
    attitude_error(state.rotor, reference.rotor())
        .max(distance(momentum(body, state), reference.m) / scale)
}

/// The interpolation points inside a step.
const THETAS: [f64; 4] = [0.2, 0.45, 0.7, 0.9];

/// The continuous extension has order seven: within one step of length `h` from the
/// exact state its error is `O(h^8)`, while the step's end is `O(h^9)`. The slope of the
/// largest error over `theta` in (0, 1) as `h` halves, fitted, is eight.
#[test]
fn dense_output_reaches_order_seven_within_a_step() {
    for (problem, steps) in [
        (free_body(), [0.4, 0.3, 0.2, 0.15]),
        (heavy_top(), [0.1, 0.08, 0.06, 0.04]),
    ] {
        let method = LieDop853::new(1e-10, 1e-10).unwrap();
        let errors: Vec<f64> = steps
            .iter()
            .map(|&h| {
                let dense = method.dense_step_once(&problem.body, 0.0, problem.state, h);
                let times = THETAS.map(|theta| theta * h);
                let reference = problem.reference(&times);
                times
                    .iter()
                    .zip(&reference)
                    .map(|(&t, r)| error(&problem.body, &dense.at(t).unwrap(), r))
                    .fold(0.0, f64::max)
            })
            .collect();
        let order = fitted_order(&steps, &errors);
        let shown: Vec<String> = errors.iter().map(|e| format!("{e:.2e}")).collect();
        let shown = shown.join(" ");
        println!(
            "{}: interpolation errors {shown}, observed order {order:.3}",
            problem.name
        );
        assert!(errors.iter().all(|&e| e > 1e-14), "{errors:?}");
        assert!((order - 8.0).abs() < 0.3, "{}: order {order}", problem.name);
    }
}

/// `theta = 0` gives the step's start and `theta = 1` its end; one step ends where the
/// next starts; every interpolated rotor is unit.
#[test]
fn dense_output_is_continuous_at_the_step_ends_and_keeps_rotors_unit() {
    for problem in [free_body(), heavy_top()] {
        let mut method = LieDop853::new(1e-10, 1e-10).unwrap();
        let (mut t, mut state) = (0.0, problem.state);
        let mut steps = 0;
        let mut worst_defect = 0.0_f64;
        while t < 5.0 {
            let step = method.step(&problem.body, t, state, 5.0).unwrap();
            assert_eq!(step.start_time(), t);
            assert_eq!(step.start_state(), state);
            let start = step.at(t).unwrap();
            let end = step.at(step.end_time()).unwrap();
            let gap = |a: State, b: State| {
                let (r, w) = (a.rotor - b.rotor, a.omega - b.omega);
                [r.s, r.e12, r.e13, r.e23, w.e12, w.e13, w.e23]
                    .into_iter()
                    .map(f64::abs)
                    .fold(0.0, f64::max)
            };
            assert!(gap(start, state) < 1e-15, "{}", gap(start, state));
            let scale = 1.0 + omega_size(step.end_state().omega);
            assert!(
                gap(end, step.end_state()) < 4e-16 * scale,
                "{}: {:e}",
                problem.name,
                gap(end, step.end_state())
            );
            for i in 1..50 {
                let ti = t + (step.end_time() - t) * f64::from(i) / 50.0;
                worst_defect = worst_defect.max(unit_defect(step.at(ti).unwrap().rotor));
            }
            (t, state) = (step.end_time(), step.end_state());
            steps += 1;
        }
        println!(
            "{}: {steps} steps to t = 5, worst |R ~R - 1| inside them {worst_defect:.1e}",
            problem.name
        );
        assert_eq!(t, 5.0);
        assert!(steps > 5);
        assert!(worst_defect < 1e-15, "{worst_defect:e}");
    }
}

fn omega_size(w: Bivector) -> f64 {
    (w.e12 * w.e12 + w.e13 * w.e13 + w.e23 * w.e23).sqrt()
}

/// A sampled run takes exactly the steps of `advance` (none cut at a sample) and its
/// samples meet the tolerance against the reference, like the step ends do.
#[test]
fn dense_advance_samples_meet_the_tolerance_and_take_the_steps_of_advance() {
    for (problem, t_end) in [(free_body(), 10.0), (heavy_top(), 2.0)] {
        let tol = 1e-11;
        let times: Vec<f64> = (0..=200).map(|i| t_end * f64::from(i) / 200.0).collect();
        let reference = problem.reference(&times);
        let mut sampled = LieDop853::new(tol, tol).unwrap();
        let mut samples = Vec::new();
        let end = sampled
            .dense_advance(&problem.body, 0.0, problem.state, t_end, &times, |t, s| {
                samples.push((t, s));
            })
            .unwrap();
        let mut plain = LieDop853::new(tol, tol).unwrap();
        let plain_end = plain
            .advance(&problem.body, 0.0, problem.state, t_end)
            .unwrap();
        assert_eq!(sampled.stats(), plain.stats(), "{}", problem.name);
        assert_eq!(end, plain_end, "{}", problem.name);
        assert_eq!(samples.len(), times.len());
        let mut worst = 0.0_f64;
        for ((&t, r), (ts, state)) in times.iter().zip(&reference).zip(&samples) {
            assert_eq!(t, *ts);
            worst = worst.max(error(&problem.body, state, r));
            assert!(unit_defect(state.rotor) < 1e-15);
        }
        let end_error = error(&problem.body, &end, reference.last().unwrap());
        println!(
            "{}: {} steps, worst sample error {worst:.2e}, end error {end_error:.2e}",
            problem.name,
            sampled.stats().accepted
        );
        assert_eq!(samples.last().unwrap().1, end);
        assert!(worst < 100.0 * tol, "{}: {worst:e}", problem.name);
        assert!(
            worst < 10.0 * end_error.max(tol),
            "{}: {worst:e}",
            problem.name
        );
    }
}

/// Dormand-Prince's samples through its continuous extension of order four
/// (`advance_to_each`, what the report runs): the same steps and end state as one
/// `advance` over the whole run, every sample within a few tolerances of the reference,
/// and far more accurate than the step ends' linear interpolation would be.
#[test]
fn dopri_samples_through_its_continuous_extension() {
    for (problem, t_end) in [(free_body(), 10.0), (heavy_top(), 2.0)] {
        let tol = 1e-9;
        let times: Vec<f64> = (1..=200).map(|i| t_end * f64::from(i) / 200.0).collect();
        let reference = problem.reference(&times);
        let mut sampled = DormandPrince::new(tol, tol).unwrap();
        let samples = sampled
            .advance_to_each(&problem.body, 0.0, problem.state, &times)
            .unwrap();
        let mut plain = DormandPrince::new(tol, tol).unwrap();
        let end = plain
            .advance(&problem.body, 0.0, problem.state, t_end)
            .unwrap();
        assert_eq!(sampled.stats(), plain.stats(), "{}", problem.name);
        assert_eq!(*samples.last().unwrap(), end, "{}", problem.name);
        let worst = samples
            .iter()
            .zip(&reference)
            .map(|(state, r)| {
                assert!(unit_defect(state.rotor) < 1e-15);
                error(&problem.body, state, r)
            })
            .fold(0.0_f64, f64::max);
        let end_error = error(&problem.body, &end, reference.last().unwrap());
        println!(
            "{}: {} steps, worst sample error {worst:.2e}, end error {end_error:.2e}",
            problem.name,
            sampled.stats().accepted
        );
        assert!(worst < 100.0 * tol, "{}: {worst:e}", problem.name);
    }
}

/// Integrating backwards samples in the direction of `dt` and returns to the start.
#[test]
fn dense_advance_runs_backwards() {
    let problem = free_body();
    let mut method = LieDop853::new(1e-12, 1e-12).unwrap();
    let forward = method
        .advance(&problem.body, 0.0, problem.state, 3.0)
        .unwrap();
    let times = [3.0, 2.5, 1.0, 0.0];
    let mut samples = Vec::new();
    let back = LieDop853::new(1e-12, 1e-12)
        .unwrap()
        .dense_advance(&problem.body, 3.0, forward, -3.0, &times, |t, s| {
            samples.push((t, s));
        })
        .unwrap();
    assert_eq!(samples.len(), 4);
    assert!(attitude_error(back.rotor, problem.state.rotor) < 1e-10);
    let reference = problem.reference(&[1.0, 2.5]);
    assert!(error(&problem.body, &samples[2].1, &reference[0]) < 1e-10);
    assert!(error(&problem.body, &samples[1].1, &reference[1]) < 1e-10);
}

/// Times outside a step or a run, out of order or not finite: typed errors naming them,
/// and nothing sampled.
#[test]
fn times_outside_the_step_or_out_of_order_are_errors() {
    let problem = free_body();
    let mut method = LieDop853::new(1e-10, 1e-10).unwrap();
    let step: DenseStep = method.step(&problem.body, 1.0, problem.state, 3.0).unwrap();
    let (t0, t1) = (step.start_time(), step.end_time());
    assert!(t0 < t1 && t1 <= 3.0);
    for t in [t0 - 1e-9, t1 + 1e-9, f64::NAN, f64::INFINITY] {
        match step.at(t) {
            Err(Error::OutOfRange {
                field,
                value,
                start,
                end,
            }) => {
                assert_eq!(field, "t");
                assert!(value.to_bits() == t.to_bits());
                assert_eq!((start, end), (t0, t1));
            }
            other => panic!("at({t}): {other:?}"),
        }
    }
    let message = step.at(t1 + 1.0).unwrap_err().to_string();
    assert!(
        message.starts_with("t: ") && message.contains("outside"),
        "{message}"
    );

    let run = |times: &[f64]| {
        let mut count = 0;
        let result = LieDop853::new(1e-10, 1e-10).unwrap().dense_advance(
            &problem.body,
            0.0,
            problem.state,
            2.0,
            times,
            |_, _| count += 1,
        );
        (result, count)
    };
    let (result, count) = run(&[0.0, 1.0, 2.5]);
    assert_eq!(count, 0);
    assert!(
        matches!(result, Err(Error::OutOfRange { ref field, .. }) if field == "times[2]"),
        "{result:?}"
    );
    let (result, count) = run(&[-0.5]);
    assert_eq!(count, 0);
    assert!(matches!(result, Err(Error::OutOfRange { .. })));
    let (result, count) = run(&[0.5, 1.5, 1.0]);
    assert_eq!(count, 0);
    let message = result.unwrap_err().to_string();
    assert!(message.starts_with("times[2]: "), "{message}");
    let (result, _) = run(&[0.5, f64::NAN]);
    assert!(matches!(result, Err(Error::NotFinite { ref field, .. }) if field == "times[1]"));
    let (result, count) = run(&[0.0, 0.0, 2.0, 2.0]);
    assert!(result.is_ok());
    assert_eq!(count, 4);

    assert!(matches!(
        method.step(&problem.body, 1.0, problem.state, 1.0),
        Err(Error::Invalid { ref field, .. }) if field == "t_end"
    ));
    assert!(method
        .step(&problem.body, 1.0, problem.state, f64::NAN)
        .is_err());
    // A zero interval samples the state at its one time.
    let mut seen = Vec::new();
    let end = LieDop853::new(1e-10, 1e-10)
        .unwrap()
        .dense_advance(
            &problem.body,
            1.0,
            problem.state,
            0.0,
            &[1.0, 1.0],
            |t, s| seen.push((t, s)),
        )
        .unwrap();
    assert_eq!(end, problem.state);
    assert_eq!(seen, vec![(1.0, problem.state); 2]);
}
