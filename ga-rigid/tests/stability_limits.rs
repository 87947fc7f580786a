//! The registry's stability limits (`StepLimit`) hold on the report's kinds of body: at
//! the limit every body keeps its energy within half of its start over 300 steps (and a
//! symmetric top its conserved `w3`), and for the explicit Runge-Kutta methods the limit
//! is not loose: at 1.5 times it some body does not.

use ga_core::f64::g3::*;
use ga_rigid::dynamics::{omega_from_vector, omega_to_vector, Gravity, RigidBody, State};
use ga_rigid::registry::{Method, Step, StepKind};

/// The bodies the limits were measured on, each with its start.
fn bodies() -> Vec<(&'static str, RigidBody, State)> {
    let start = |w: [f64; 3]| State {
        rotor: Rotor::ONE,
        omega: omega_from_vector(w),
    };
    let gravity = Gravity {
        mass: 1.0,
        g: Vector::new(0.0, 0.0, -9.81),
        com_offset: Vector::new(0.0, 0.0, 0.5),
    };
    vec![
        (
            "Hairer-Vilmart",
            RigidBody::new_unphysical([0.6, 0.8, 1.0]).unwrap(),
            start([3.0, 0.5, -0.9]),
        ),
        (
            "Dzhanibekov",
            RigidBody::new_unphysical([3.0, 5.0, 9.0]).unwrap(),
            start([0.0, 0.4, 0.01 / 9.0]),
        ),
        (
            "symmetric top",
            RigidBody::new([2.0, 2.0, 1.0]).unwrap(),
            start([0.3, 0.0, 5.0]),
        ),
        (
            "needle",
            RigidBody::new([1.0, 1.0, 1e-3]).unwrap(),
            start([0.01, 0.0, 1000.0]),
        ),
        (
            "heavy top",
            RigidBody::new([1.0, 1.0, 0.5])
                .unwrap()
                .with_torque(gravity),
            State {
                rotor: (Bivector::E23 * -0.15).exp(),
                omega: omega_from_vector([0.0, 0.0, 20.0]),
            },
        ),
    ]
}

/// Whether 300 steps of `h |w| = rate` (`|w|` the body's own rate, at most `|w|max`, so the
/// step is at least the one the limit allows) keep the energy within half of its start
/// and, on a free symmetric body, `w3` within half of its start.
fn bounded(method: Method, body: &RigidBody, start: State, rate: f64) -> bool {
    let h = rate / start.omega.norm();
    let Ok(mut integrator) = method.integrator(Step::Fixed(h)) else {
        return false;
    };
    let e0 = body.total_energy(0.0, &start);
    let w30 = omega_to_vector(start.omega)[2];
    let [i1, i2, _] = body.moments();
    let symmetric = i1 == i2 && !body.has_torque();
    let (mut t, mut state) = (0.0, start);
    for _ in 0..300 {
        match integrator.advance(body, t, state, h) {
            Ok(next) => state = next,
            Err(_) => return false,
        }
        t += h;
        let e = body.total_energy(t, &state);
        // Written so that NaN counts as unbounded.
        let energy_kept = (e - e0).abs() <= 0.5 * e0.abs();
        let w3 = omega_to_vector(state.omega)[2];
        let w3_kept = !symmetric || (w3 - w30).abs() <= 0.5 * w30.abs();
        if !(energy_kept && w3_kept) {
            return false;
        }
    }
    true
}

#[test]
fn every_fixed_step_method_is_stable_at_its_limit() {
    for method in Method::ALL {
        if method.step_kind() != StepKind::Fixed {
            assert_eq!(method.stable_step_rate(true), None, "{method}");
            continue;
        }
        for (name, body, start) in bodies() {
            let Some(limit) = method.stable_step_rate(body.has_torque()) else {
                continue;
            };
            assert!(
                bounded(method, &body, start, limit),
                "{method} is not stable on the {name} at its limit h |w| = {limit}"
            );
        }
    }
}

/// At 1.5 times `method`'s registered limit some body is not bounded: the limit is not
/// loose.
fn assert_limit_not_loose(method: Method) {
    let limit = method.stable_step_rate(false).unwrap();
    let unstable = bodies()
        .into_iter()
        .filter(|(_, body, start)| !bounded(method, body, *start, 1.5 * limit))
        .count();
    assert!(
        unstable > 0,
        "{method} is stable everywhere at 1.5 x {limit}"
    );
}

#[test]
fn the_explicit_runge_kutta_limits_are_not_loose() {
    for method in [Method::Rk4, Method::LieRk4] {
        assert_limit_not_loose(method);
    }
}

/// Without a torque an exact-splitting step is the exact free flow: no limit.
#[test]
fn exact_splitting_is_unlimited_without_a_torque() {
    for (name, body, start) in bodies().into_iter().filter(|(_, b, _)| !b.has_torque()) {
        assert_eq!(Method::ExactSplitting.stable_step_rate(false), None);
        assert!(bounded(Method::ExactSplitting, &body, start, 1e4), "{name}");
    }
}

/// The implicit midpoint rule on the quaternion form has the limit of our `midpoint` (the
/// same rule: both first lose the Dzhanibekov body between `h |w| = 3.6` and 3.7), and
/// neither limit is loose: at 1.5 times it some body is not bounded.
#[test]
fn the_implicit_midpoint_limits_are_not_loose() {
    assert_eq!(
        Method::MidpointQuaternion.stable_step_rate(false),
        Method::Midpoint.stable_step_rate(false)
    );
    for method in [Method::Midpoint, Method::MidpointQuaternion] {
        assert_limit_not_loose(method);
    }
}

/// About a principal axis the Moser-Veselov equation reads `sin(theta) J3 = h m3`: the step
/// turns by `asin(h w3)`, and beyond `h |w| = 1` there is no step to take. Its limit is
/// therefore below 1, and at 1.1 the symmetric top's step fails.
#[test]
fn moser_veselov_has_no_step_beyond_h_w_of_one() {
    let limit = Method::MoserVeselov.stable_step_rate(false).unwrap();
    assert!(limit < 1.0);
    let (_, body, start) = bodies()
        .into_iter()
        .find(|(name, _, _)| *name == "symmetric top")
        .unwrap();
    assert!(bounded(Method::MoserVeselov, &body, start, 0.99));
    assert!(!bounded(Method::MoserVeselov, &body, start, 1.1));
}

/// Spiers's two forms keep `|L|`, so their energy stays within the moments' range, and
/// their limit is where the Dzhanibekov body, near its separatrix, first moves by half its
/// energy: the limit holds (above) and is not loose.
#[test]
fn the_spiers_limits_are_not_loose() {
    for method in [Method::SpiersVelocity, Method::SpiersMomentum] {
        assert_limit_not_loose(method);
    }
}
