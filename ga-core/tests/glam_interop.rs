//! Conversions to glam are exact inverses and rotate the same way as glam does.

use ga_core::f32::g3 as s3;
use ga_core::f64::g3 as d3;
use ga_core::glam::{DMat3, DQuat, DVec3, Mat3, Quat, Vec3};

/// A small deterministic generator (xorshift64*), so failures reproduce.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        let bits = self.0.wrapping_mul(0x2545_f491_4f6c_dd1d) >> 11;
        bits as f64 / (1u64 << 53) as f64 * 2.0 - 1.0
    }

    fn vec(&mut self) -> DVec3 {
        DVec3::new(self.next(), self.next(), self.next())
    }

    fn quat(&mut self) -> DQuat {
        let axis = self.vec().normalize_or(DVec3::Z);
        DQuat::from_axis_angle(axis, 3.0 * self.next())
    }
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
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    for _ in 0..1000 {
        let q = rng.quat();
        let v = rng.vec();
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
    let mut rng = Rng(0x1234_5678_9abc_def1);
    for _ in 0..1000 {
        let q = rng.quat().as_quat();
        let v = rng.vec().as_vec3();
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
    let mut rng = Rng(42);
    for _ in 0..1000 {
        let q = rng.quat();
        assert_eq!(DQuat::from(d3::Rotor::from(q)), q);
        let v = rng.vec();
        assert_eq!(DVec3::from(d3::Vector::from(v)), v);
        let q32 = q.as_quat();
        assert_eq!(Quat::from(s3::Rotor::from(q32)), q32);
        let r = d3::Rotor::new(rng.next(), rng.next(), rng.next(), rng.next());
        assert_eq!(d3::Rotor::from(DQuat::from(r)), r);
    }
}

#[test]
fn rotor_products_compose_like_quaternion_products() {
    let mut rng = Rng(7);
    for _ in 0..1000 {
        let (p, q) = (rng.quat(), rng.quat());
        let composed = DQuat::from(d3::Rotor::from(p) * d3::Rotor::from(q));
        assert!(
            composed.abs_diff_eq(p * q, 1e-14),
            "{composed:?} vs {:?}",
            p * q
        );
    }
}

/// The older glam majors behind `glam-0-29` ... `glam-0-31` convert exactly as the newest.
#[test]
fn older_glam_versions_convert_like_the_newest() {
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
            }
        };
    }
    same!("glam-0-29", glam_0_29);
    same!("glam-0-30", glam_0_30);
    same!("glam-0-31", glam_0_31);
}
