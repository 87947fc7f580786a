//! The engine on another glam is the same engine: `ga_engine::glam_0_33` (rapier3d 0.36's
//! glam) steps a T-handle to the same bits as `ga_engine::f32`/`f64` (glam 0.32), in both
//! precisions, one body at a time and in slices.

use ga_engine::glam_0_33 as e33;
use ga_engine::{f32 as e32, f64 as e64, glam};
use glam_0_33 as g33;

#[test]
fn glam_0_33_steps_to_the_same_bits_as_glam_0_32() {
    let body32 =
        e32::Body::from_principal(glam::Vec3::new(1.0, 2.0, 3.0), glam::Quat::IDENTITY).unwrap();
    let body33 =
        e33::f32::Body::from_principal(g33::Vec3::new(1.0, 2.0, 3.0), g33::Quat::IDENTITY).unwrap();
    let (mut q32, mut l32) = (
        glam::Quat::from_xyzw(0.1, 0.2, -0.3, 0.9).normalize(),
        glam::Vec3::new(0.02, 2.0, 0.1),
    );
    let (mut q33, mut l33) = (
        g33::Quat::from_array(q32.to_array()),
        g33::Vec3::from_array(l32.to_array()),
    );
    let t = (
        glam::Vec3::new(0.0, 0.1, -0.2),
        g33::Vec3::new(0.0, 0.1, -0.2),
    );
    for _ in 0..600 {
        (q32, l32) = e32::step(&body32, q32, l32, t.0, 1.0 / 60.0);
        (q33, l33) = e33::f32::step(&body33, q33, l33, t.1, 1.0 / 60.0);
    }
    assert_eq!(
        q32.to_array().map(f32::to_bits),
        q33.to_array().map(f32::to_bits)
    );
    assert_eq!(
        l32.to_array().map(f32::to_bits),
        l33.to_array().map(f32::to_bits)
    );

    let body64 =
        e64::Body::from_principal(glam::DVec3::new(1.0, 2.0, 3.0), glam::DQuat::IDENTITY).unwrap();
    let body33 =
        e33::f64::Body::from_principal(g33::DVec3::new(1.0, 2.0, 3.0), g33::DQuat::IDENTITY)
            .unwrap();
    let mut a: Vec<_> = (0..9)
        .map(|k| {
            let q = glam::DQuat::from_rotation_z(0.3 * f64::from(k));
            e64::BodyState::new(body64, q, glam::DVec3::new(0.1 * f64::from(k), 2.0, 0.3))
        })
        .collect();
    let mut b: Vec<_> = a
        .iter()
        .map(|s| {
            e33::f64::BodyState::new(
                body33,
                g33::DQuat::from_array(s.orientation.to_array()),
                g33::DVec3::from_array(s.angular_momentum.to_array()),
            )
        })
        .collect();
    for _ in 0..600 {
        e64::step_slice(&mut a, 0.01);
        e33::f64::step_slice(&mut b, 0.01);
    }
    for (x, y) in a.iter().zip(&b) {
        assert_eq!(
            x.orientation.to_array().map(f64::to_bits),
            y.orientation.to_array().map(f64::to_bits)
        );
        assert_eq!(
            x.angular_momentum.to_array().map(f64::to_bits),
            y.angular_momentum.to_array().map(f64::to_bits)
        );
    }
}
