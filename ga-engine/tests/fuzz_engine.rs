//! Fuzzing the promise on orientations (crate docs, "Orientations"): any non-zero finite
//! quaternion is stepped as the unit one, to rounding, whatever its scale, for random
//! bodies, momenta, torques and steps, in f64 and f32, by `step`, `step_order4` and
//! `step_with`. The reference is the same call on the orientation normalised here in f64,
//! outside the engine. CI runs it briefly (`PROPTEST_CASES`).

use ga_engine::glam::{DQuat, DVec3, Quat, Vec3};
use ga_engine::{f32 as e32, f64 as e64};
use proptest::prelude::*;

/// The angle between two orientations, sign-blind, accurate for small angles too: for unit
/// quaternions of one hemisphere `|a - b| = 2 sin(theta / 4)`.
fn angle(a: DQuat, b: DQuat) -> f64 {
    let (a, b) = (a.normalize(), b.normalize());
    let b = if a.dot(b) < 0.0 { -b } else { b };
    4.0 * ((a - b).length() / 2.0).min(1.0).asin()
}

fn config() -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(64);
    // No regression file: a test crate has no src/ for proptest to put one beside.
    ProptestConfig {
        failure_persistence: None,
        ..ProptestConfig::with_cases(cases)
    }
}

fn unit_quaternion() -> impl Strategy<Value = [f64; 4]> {
    prop::array::uniform4(-1.0f64..1.0).prop_filter("not near zero", |q| {
        q.iter().map(|x| x * x).sum::<f64>() > 1e-2
    })
}

proptest! {
    #![proptest_config(config())]

    /// f64: scales from 1e-150 to 1e150.
    #[test]
    fn a_scaled_f64_orientation_is_stepped_as_the_unit_one(
        q in unit_quaternion(),
        log_scale in -150.0f64..150.0,
        moments in prop::array::uniform3(0.2f64..5.0),
        l in prop::array::uniform3(-3.0f64..3.0),
        t in prop::array::uniform3(-1.0f64..1.0),
        dt in 1e-3f64..0.1,
    ) {
        let body = e64::Body::from_principal(DVec3::from(moments), DQuat::IDENTITY).unwrap();
        let unit = DQuat::from_array(q).normalize();
        let scaled = DQuat::from_array(q) * 10f64.powf(log_scale);
        let (l, t) = (DVec3::from(l), DVec3::from(t));
        let (a, la) = e64::step(&body, scaled, l, t, dt);
        let (b, lb) = e64::step(&body, unit, l, t, dt);
        prop_assert!((a.length() - 1.0).abs() < 1e-14, "{a}");
        prop_assert!(angle(a, b) < 1e-13, "{:e}", angle(a, b));
        prop_assert!((la - lb).length() <= 1e-13 * (1.0 + lb.length()));
        let (a4, _) = e64::step_order4(&body, scaled, l, t, dt);
        let (b4, _) = e64::step_order4(&body, unit, l, t, dt);
        prop_assert!(angle(a4, b4) < 1e-13, "{:e}", angle(a4, b4));
        let spring = |q: DQuat| (q * DVec3::Z).cross(DVec3::new(0.0, 0.0, -1.0));
        let (aw, _) = e64::step_with(&body, scaled, l, spring, dt);
        let (bw, _) = e64::step_with(&body, unit, l, spring, dt);
        prop_assert!(angle(aw, bw) < 1e-13, "{:e}", angle(aw, bw));
    }

    /// f32: scales from 1e-18 to 1e18 (the squared norm stays finite and normal).
    #[test]
    fn a_scaled_f32_orientation_is_stepped_as_the_unit_one(
        q in unit_quaternion(),
        log_scale in -18.0f64..18.0,
        moments in prop::array::uniform3(0.2f32..5.0),
        l in prop::array::uniform3(-3.0f32..3.0),
        dt in 1e-3f32..0.1,
    ) {
        let body = e32::Body::from_principal(Vec3::from(moments), Quat::IDENTITY).unwrap();
        let wide = DQuat::from_array(q).normalize();
        let unit = wide.as_quat();
        let scaled = (wide * 10f64.powf(log_scale)).as_quat();
        let l = Vec3::from(l);
        let (a, _) = e32::step(&body, scaled, l, Vec3::ZERO, dt);
        let (b, _) = e32::step(&body, unit, l, Vec3::ZERO, dt);
        prop_assert!((a.length() - 1.0).abs() < 1e-6, "{a}");
        prop_assert!(angle(a.as_dquat(), b.as_dquat()) < 2e-6, "{:e}", angle(a.as_dquat(), b.as_dquat()));
    }
}
