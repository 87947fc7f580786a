//! The user crate's own algebra: a boost against its hand-computed closed form, and the
//! serde and bytemuck impls asked for through the macro's `derive` key.

use ga_core::f64::g3::Sandwich as _;
use ga_user_crate::{boost_e2, quarter_turn, sta};
use sta::Sandwich;

#[test]
fn a_boost_mixes_time_and_space_by_cosh_and_sinh() {
    let phi = 0.8_f64;
    let y = boost_e2(phi).sandwich(sta::Vector::E1);
    let expected = [phi.cosh(), phi.sinh(), 0.0, 0.0];
    for (got, want) in y.to_array().iter().zip(expected) {
        assert!((got - want).abs() < 1e-14, "{y:?}");
    }
    // The Minkowski square survives: cosh^2 - sinh^2 = 1.
    assert!(((y | y) - 1.0).abs() < 1e-14);
}

#[test]
fn ga_core_rotations_work_alongside() {
    let y = quarter_turn().sandwich(ga_core::f64::g3::Vector::E1);
    assert!((y - ga_core::f64::g3::Vector::E2).norm() < 1e-15);
}

#[test]
fn serde_round_trip_of_the_users_own_types() {
    let r = boost_e2(0.3);
    let json = serde_json::to_string(&r).unwrap();
    assert!(
        json.starts_with(r#"{"s":"#) && json.contains(r#""e1234":"#),
        "{json}"
    );
    assert_eq!(serde_json::from_str::<sta::Even>(&json).unwrap(), r);
    let v: sta::Vector = serde_json::from_str(r#"{"e1":1,"e2":2,"e3":3,"e4":4}"#).unwrap();
    assert_eq!(v, sta::Vector::new(1.0, 2.0, 3.0, 4.0));
}

#[test]
fn a_slice_of_events_casts_to_bytes_for_a_buffer() {
    let events = [
        sta::Vector::new(1.0, 0.5, 0.0, 0.0),
        sta::Vector::new(2.0, 0.0, -1.0, 0.25),
    ];
    let bytes: &[u8] = ga_core::bytemuck::cast_slice(&events);
    assert_eq!(bytes.len(), 2 * 4 * 8);
    let expected: Vec<u8> = [1.0f64, 0.5, 0.0, 0.0, 2.0, 0.0, -1.0, 0.25]
        .iter()
        .flat_map(|x| x.to_ne_bytes())
        .collect();
    assert_eq!(bytes, expected.as_slice());
    let back: &[sta::Vector] = ga_core::bytemuck::cast_slice(bytes);
    assert_eq!(back, events);
}
