//! Conversions to glam are exact inverses and rotate the same way as glam does.

use ga_core::f32::g3 as s3;
use ga_core::f64::g3 as d3;
use ga_core::glam::{DMat3, DQuat, DVec3, Mat3, Quat, Vec3};

use ga_test_rng::Rng;

/// A vector with components uniform in [-1, 1).
fn vec(rng: &mut Rng) -> DVec3 {
    DVec3::new(rng.signed(), rng.signed(), rng.signed())
}

/// A rotation about a random axis by an angle in [-3, 3).
fn quat(rng: &mut Rng) -> DQuat {
    let axis = vec(rng).normalize_or(DVec3::Z);
    DQuat::from_axis_angle(axis, 3.0 * rng.signed())
}

#[test]
fn quarter_turn_in_e12_is_glams_positive_turn_about_z() {
    let r = (d3::Bivector::E12 * (-std::f64::consts::FRAC_PI_4)).exp();
    let q = DQuat::from(r);
    let expected = DQuat::from_rotation_z(std::f64::consts::FRAC_PI_2);
    assert!(q.abs_diff_eq(expected, 1e-15), "{q:?} vs {expected:?}");
}

#[test]
fn f64_rotors_rotate_vectors_like_glam_quaternions() {
    let mut rng = Rng::new(0x9e37_79b9_7f4a_7c15);
    for _ in 0..1000 {
        let q = quat(&mut rng);
        let v = vec(&mut rng);
        let r = d3::Rotor::from(q);
        let by_glam = q * v;
        let by_rotor = DVec3::from(d3::Sandwich::sandwich(r, d3::Vector::from(v)));
        assert!(
            by_glam.abs_diff_eq(by_rotor, 1e-14),
            "{by_glam} vs {by_rotor}"
        );
        let by_matrix = DMat3::from(r) * v;
        assert!(
            by_glam.abs_diff_eq(by_matrix, 1e-14),
            "{by_glam} vs {by_matrix}"
        );
    }
}

#[test]
fn f32_rotors_rotate_vectors_like_glam_quaternions() {
    let mut rng = Rng::new(0x1234_5678_9abc_def1);
    for _ in 0..1000 {
        let q = quat(&mut rng).as_quat();
        let v = vec(&mut rng).as_vec3();
        let r = s3::Rotor::from(q);
        let by_glam = q * v;
        let by_rotor = Vec3::from(s3::Sandwich::sandwich(r, s3::Vector::from(v)));
        assert!(
            by_glam.abs_diff_eq(by_rotor, 1e-5),
            "{by_glam} vs {by_rotor}"
        );
        assert!(by_glam.abs_diff_eq(Mat3::from(r) * v, 1e-5));
    }
}

#[test]
fn conversions_are_exact_inverses() {
    let mut rng = Rng::new(42);
    for _ in 0..1000 {
        let q = quat(&mut rng);
        assert_eq!(DQuat::from(d3::Rotor::from(q)), q);
        let v = vec(&mut rng);
        assert_eq!(DVec3::from(d3::Vector::from(v)), v);
        let q32 = q.as_quat();
        assert_eq!(Quat::from(s3::Rotor::from(q32)), q32);
        let r = d3::Rotor::new(rng.signed(), rng.signed(), rng.signed(), rng.signed());
        assert_eq!(d3::Rotor::from(DQuat::from(r)), r);
    }
}

#[test]
fn rotor_products_compose_like_quaternion_products() {
    let mut rng = Rng::new(7);
    for _ in 0..1000 {
        let (p, q) = (quat(&mut rng), quat(&mut rng));
        let composed = DQuat::from(d3::Rotor::from(p) * d3::Rotor::from(q));
        assert!(
            composed.abs_diff_eq(p * q, 1e-14),
            "{composed:?} vs {:?}",
            p * q
        );
    }
}

/// The other glam majors behind `glam-0-29` ... `glam-0-31` and `glam-0-33` convert exactly
/// as the default one (0.32), Euler orders included
/// (compiled only where one of them is on, as in CI's `--all-features` run: without them
/// it would check nothing).
#[cfg(any(
    feature = "glam-0-29",
    feature = "glam-0-30",
    feature = "glam-0-31",
    feature = "glam-0-33"
))]
#[test]
fn other_glam_versions_convert_like_the_default() {
    let r = (d3::Bivector::new(0.2, -0.7, 0.5) * -0.45).exp();
    let v = d3::Vector::new(1.0, -2.0, 0.5);
    let q: DQuat = r.into();
    let w: DVec3 = v.into();
    macro_rules! same {
        ($feature:literal, $glam:ident) => {
            #[cfg(feature = $feature)]
            {
                let old: ga_core::$glam::DQuat = r.into();
                assert_eq!(old.to_array(), q.to_array());
                assert_eq!(d3::Rotor::from(old), r);
                let old_v: ga_core::$glam::DVec3 = v.into();
                assert_eq!(old_v.to_array(), w.to_array());
                let m: ga_core::$glam::Mat3 = s3::Rotor::from(old.as_quat()).into();
                let m_new: Mat3 = s3::Rotor::from(q.as_quat()).into();
                assert_eq!(m.to_cols_array(), m_new.to_cols_array());
                // Each order means that version's order: its own quaternion from the
                // angles is ours (intrinsic, extrinsic, proper Euler).
                use ga_core::$glam::EulerRot as Old;
                for order in [Old::YXZ, Old::ZYXEx, Old::XZX, Old::YZYEx] {
                    let ours = d3::Rotor::from_euler(order.into(), 0.3, -1.2, 2.0);
                    let theirs = ga_core::$glam::DQuat::from_euler(order, 0.3, -1.2, 2.0);
                    let back: Old = ga_core::EulerRot::from(order).into();
                    assert_eq!(back, order);
                    assert!(
                        (ours - d3::Rotor::from(theirs)).norm() < 1e-14,
                        "{order:?}: {ours} vs {theirs:?}"
                    );
                }
            }
        };
    }
    same!("glam-0-29", glam_0_29);
    same!("glam-0-30", glam_0_30);
    same!("glam-0-31", glam_0_31);
    same!("glam-0-33", glam_0_33);
}
