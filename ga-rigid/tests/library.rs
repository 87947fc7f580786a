//! ga-rigid as a library (issue 9): a trajectory without a hand-written time loop,
//! conversions between `Inertia` and `RigidBody`, and scenes built in code.

use std::path::Path;

use ga_core::f64::g3::{Bivector, Rotor};
use ga_rigid::dynamics::{RigidBody, State, SymmetricTop};
use ga_rigid::inertia::{Inertia, Solid};
use ga_rigid::integrators::{Integrator, Rk4, Splitting};
use ga_rigid::scene::{BodySpec, Initial, Run, Scene};
use ga_rigid::simulation::Simulation;

fn top_state() -> State {
    State {
        rotor: Rotor::new(0.9, 0.1, -0.3, 0.2) / Rotor::new(0.9, 0.1, -0.3, 0.2).norm(),
        omega: Bivector::new(5.0, 0.4, 0.3),
    }
}

#[test]
fn run_until_follows_the_symmetric_tops_closed_form() {
    let body = RigidBody::new([2.0, 2.0, 1.0]).unwrap();
    let top = SymmetricTop::new(&body, top_state(), 1e-12).unwrap();
    let mut simulation = Simulation::new(body, top_state(), Rk4::new(1e-3).unwrap());
    let samples = simulation.run_until(10.0, 21).unwrap();
    assert_eq!(samples.len(), 21);
    for (k, sample) in samples.iter().enumerate() {
        assert_eq!(sample.t, 10.0 * k as f64 / 20.0);
        let exact = top.state(sample.t);
        let rotor_error = (sample.state.rotor - exact.rotor).norm();
        let omega_error = (sample.state.omega - exact.omega).norm();
        assert!(rotor_error < 1e-9, "t = {}: {rotor_error}", sample.t);
        assert!(omega_error < 1e-9, "t = {}: {omega_error}", sample.t);
    }
    assert_eq!(simulation.time(), 10.0);
}

#[test]
fn run_until_matches_a_hand_written_loop_bit_for_bit() {
    let body = RigidBody::new([1.0, 2.0, 2.5]).unwrap();
    let mut simulation = Simulation::new(body, top_state(), Splitting::new(0.01).unwrap());
    let samples = simulation.run_until(3.0, 7).unwrap();
    let body = RigidBody::new([1.0, 2.0, 2.5]).unwrap();
    let mut integrator = Splitting::new(0.01).unwrap();
    let mut state = top_state();
    let mut t = 0.0;
    for sample in &samples {
        state = integrator.advance(&body, t, state, sample.t - t).unwrap();
        t = sample.t;
        assert_eq!(sample.state, state);
        assert_eq!(sample.energy, body.total_energy(t, &state));
    }
}

#[test]
fn samples_continue_from_the_current_time_and_stop_after_an_error() {
    let body = RigidBody::new([1.0, 2.0, 2.5]).unwrap();
    let mut simulation = Simulation::new(body, top_state(), Rk4::new(0.01).unwrap());
    simulation.run_until(1.0, 2).unwrap();
    let later = simulation.run_until(3.0, 3).unwrap();
    let times: Vec<f64> = later.iter().map(|s| s.t).collect();
    assert_eq!(times, [1.0, 2.0, 3.0]);

    let e = simulation.run_until(4.0, 1).unwrap_err().to_string();
    assert!(e.starts_with("samples: "), "{e}");
    let e = simulation.run_until(f64::NAN, 3).unwrap_err().to_string();
    assert!(e.starts_with("samples: "), "{e}");

    // Huge speeds overflow RK4's stages: an error naming the method, then nothing more.
    let body = RigidBody::new([1.0, 2.0, 2.5]).unwrap();
    let fast = State {
        rotor: Rotor::ONE,
        omega: Bivector::new(1e153, 1e153, 1e153),
    };
    let mut simulation = Simulation::new(body, fast, Rk4::new(1e-152).unwrap());
    let mut samples = simulation.samples(1e-150, 5);
    assert!(samples.next().unwrap().is_ok());
    let e = samples.next().unwrap().unwrap_err().to_string();
    assert!(e.starts_with("rk4: "), "{e}");
    assert!(samples.next().is_none());
}

#[test]
fn a_boxed_integrator_drives_a_simulation() {
    let body = RigidBody::new([1.0, 2.0, 2.5]).unwrap();
    let integrator: Box<dyn Integrator> = Box::new(Rk4::new(0.01).unwrap());
    let mut simulation = Simulation::new(body, top_state(), integrator);
    assert_eq!(simulation.run_until(1.0, 3).unwrap().len(), 3);
}

#[test]
fn inertia_and_rigid_body_convert_both_ways() {
    let boxed = Inertia::solid_box(2.0, [1.0, 2.0, 3.0]).unwrap();
    let body = RigidBody::from(&boxed);
    // The textbook box: m (b^2 + c^2) / 12 and so on.
    let expected = [
        2.0 * (4.0 + 9.0) / 12.0,
        2.0 * (1.0 + 9.0) / 12.0,
        2.0 * (1.0 + 4.0) / 12.0,
    ];
    let mut moments = body.moments();
    moments.sort_by(|a, b| b.total_cmp(a));
    for (m, e) in moments.iter().zip(expected) {
        assert!((m - e).abs() < 1e-14 * e, "{m} vs {e}");
    }
    assert!(!body.has_torque());

    let back = Inertia::from(&body);
    assert_eq!(back.moments(), body.moments());
    assert_eq!(back.rotor(), Rotor::ONE);
    assert_eq!(back.mass(), None);
    assert_eq!(RigidBody::from(back).moments(), body.moments());
}

#[test]
fn a_scene_built_in_code_equals_the_same_scene_read_from_toml() {
    let built = Scene::new(
        BodySpec::Moments([1.0, 2.0, 2.5]),
        Initial {
            rotor: Rotor::new(2.0, 0.0, 0.0, 0.0),
            omega: [0.1, 1.0, 0.2],
        },
        Run {
            t_end: 10.0,
            samples: 11,
        },
        None,
    )
    .unwrap();
    let read = Scene::parse(
        "[body]\nmoments = [1, 2, 2.5]\n[initial]\nrotor = [2, 0, 0, 0]\n\
         omega = [0.1, 1.0, 0.2]\n[run]\nt_end = 10\nsamples = 11\n",
        Path::new("scene.toml"),
    )
    .unwrap();
    assert_eq!(built, read);
    assert_eq!(built.initial.rotor, Rotor::ONE);
}

#[test]
fn a_scene_built_in_code_is_checked_like_a_file() {
    let initial = Initial {
        rotor: Rotor::ONE,
        omega: [0.1, 1.0, 0.2],
    };
    let run = Run {
        t_end: 10.0,
        samples: 11,
    };
    let field = |r: Result<Scene, ga_rigid::error::Error>| {
        r.unwrap_err().field().unwrap_or_default().to_string()
    };
    let unphysical = BodySpec::Moments([2.0, 1.0, 2.0 / 3.0]);
    assert_eq!(
        field(Scene::new(unphysical.clone(), initial, run, None)),
        "body.moments"
    );
    let inertia = Inertia::from_principal_unphysical([2.0, 1.0, 2.0 / 3.0]).unwrap();
    assert!(Scene::with_inertia(unphysical, inertia, initial, run, None).is_ok());
    let good = BodySpec::Moments([1.0, 2.0, 2.5]);
    let nan_omega = Initial {
        omega: [f64::NAN, 0.0, 0.0],
        ..initial
    };
    assert_eq!(
        field(Scene::new(good.clone(), nan_omega, run, None)),
        "initial.omega"
    );
    let one_sample = Run { samples: 1, ..run };
    assert_eq!(
        field(Scene::new(good.clone(), initial, one_sample, None)),
        "run.samples"
    );
    let solid = BodySpec::Shape(Solid::Box {
        mass: 2.0,
        size: [1.0, 2.0, 3.0],
    });
    assert!(Scene::new(solid, initial, run, None).is_ok());
}

#[cfg(feature = "serde")]
#[test]
fn scene_parts_survive_a_serde_round_trip_and_build_the_same_scene() {
    #[derive(serde::Serialize, serde::Deserialize, PartialEq, Debug)]
    struct Parts {
        body: BodySpec,
        initial: Initial,
        run: Run,
        torque: Option<ga_rigid::scene::GravitySpec>,
    }
    let parts = Parts {
        body: BodySpec::Shape(Solid::Box {
            mass: 2.0,
            size: [1.0, 2.0, 3.0],
        }),
        initial: Initial {
            rotor: Rotor::new(0.5, 0.5, -0.5, 0.5),
            omega: [0.1, 1.0, 0.2],
        },
        run: Run {
            t_end: 10.0,
            samples: 11,
        },
        torque: Some(ga_rigid::scene::GravitySpec {
            g: ga_core::f64::g3::Vector::new(0.0, 0.0, -9.81),
            com_offset: ga_core::f64::g3::Vector::new(0.0, 0.0, 0.1),
        }),
    };
    let text = toml::to_string(&parts).unwrap();
    assert!(text.contains("rotor = [0.5, 0.5, -0.5, 0.5]"), "{text}");
    let back: Parts = toml::from_str(&text).unwrap();
    assert_eq!(back, parts);
    let scene = Scene::new(back.body, back.initial, back.run, back.torque).unwrap();
    assert_eq!(scene.inertia.mass(), Some(2.0));
    let points = BodySpec::Points(vec![(1.0, [1.0, 0.0, 0.0]), (2.0, [0.0, 1.0, 0.0])]);
    let text = toml::to_string(&Parts {
        body: points.clone(),
        ..parts
    })
    .unwrap();
    assert_eq!(toml::from_str::<Parts>(&text).unwrap().body, points);
}

/// `RigidBody: Clone` (issue 23): a clone keeps the moments and the shared torque, so a
/// cloned heavy top steps exactly as the original does.
#[test]
fn a_cloned_heavy_top_steps_exactly_as_the_original() {
    use ga_core::f64::g3::Vector;
    use ga_rigid::dynamics::Gravity;
    let body = RigidBody::new([2.0, 2.0, 1.0])
        .unwrap()
        .with_torque(Gravity {
            mass: 1.5,
            g: Vector::new(0.0, 0.0, -9.81),
            com_offset: Vector::new(0.0, 0.0, 0.3),
        });
    let clone = body.clone();
    assert_eq!(clone.moments(), body.moments());
    assert!(clone.has_torque());
    let state = top_state();
    assert_ne!(body.torque(0.0, &state), Bivector::ZERO);
    assert_eq!(clone.torque(0.0, &state), body.torque(0.0, &state));
    let mut a = Rk4::new(1e-3).unwrap();
    let mut b = Rk4::new(1e-3).unwrap();
    let from_original = a.advance(&body, 0.0, state, 0.5).unwrap();
    let from_clone = b.advance(&clone, 0.0, state, 0.5).unwrap();
    assert_eq!(from_clone, from_original);
}
