//! What the no_std crate computes, checked with std's help.

use ga_engine_user::{
    principal_moments_f32, tilted_box_tensor, tumble_columns_f32, tumble_f64, tumble_slice_f32,
};

#[test]
fn the_tilted_box_has_the_boxs_principal_moments() {
    let m = principal_moments_f32().unwrap();
    let want = [5.0_f32 / 12.0, 10.0 / 12.0, 13.0 / 12.0];
    for (a, b) in m.to_array().iter().zip(want) {
        assert!((a - b).abs() < 1e-6, "{m}");
    }
    assert!((tilted_box_tensor().determinant() - 650.0 / 1728.0).abs() < 1e-12);
}

#[test]
fn a_free_body_keeps_its_world_momentum_in_f64() {
    let (q, l) = tumble_f64(1000, 0.01).unwrap();
    assert!((q.length() - 1.0).abs() < 1e-12);
    let (_, l0) = tumble_f64(0, 0.01).unwrap();
    assert_eq!(l, l0);
}

#[test]
fn torque_turns_the_momentum_only_of_the_bodies_it_acts_on_in_f32() {
    let states = tumble_slice_f32(600, 1.0 / 60.0).unwrap();
    for (i, s) in states.iter().enumerate() {
        let dz = s.angular_momentum.z - 0.05;
        if i % 2 == 1 {
            // 0.5 N m for 10 s.
            assert!((dz - 5.0).abs() < 1e-3, "{i} {dz}");
        } else {
            assert_eq!(dz, 0.0);
        }
        assert!((s.orientation.length() - 1.0).abs() < 1e-6);
    }
}

#[test]
fn body_columns_step_the_bodies_as_the_slice_does() {
    let (slice, columns) = (
        tumble_slice_f32(300, 1.0 / 60.0).unwrap(),
        tumble_columns_f32(300, 1.0 / 60.0).unwrap(),
    );
    for (a, b) in slice.iter().zip(&columns) {
        assert_eq!(a.orientation.to_array(), b.orientation.to_array());
        assert_eq!(a.angular_momentum.to_array(), b.angular_momentum.to_array());
    }
    // The bodies moved, and the torqued ones differently from the free ones.
    assert_ne!(columns[0].orientation, columns[1].orientation);
}
