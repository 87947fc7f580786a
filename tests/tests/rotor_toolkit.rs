//! The G3 rotor toolkit against glam's `Quat` (same operation, independent code) where
//! glam has the operation, and against the reference algebra or closed forms elsewhere;
//! edge cases: opposite vectors, half turns, nearly equal rotors, zero and non-finite
//! input. Written once as a macro and run in f32 and f64.

use ga_test_rng::Rng;

macro_rules! toolkit_tests {
    ($name:ident, $s:ident, $quat:ty, $vec3:ty, $mat3:ty, $tol:expr) => {
        mod $name {
            use super::Rng;
            use ga_core::$s::g3::*;

            const TOL: $s = $tol;
            const PI: $s = core::$s::consts::PI;

            fn unit(values: &mut Rng) -> Vector {
                loop {
                    let v = Vector::new(
                        values.signed() as $s,
                        values.signed() as $s,
                        values.signed() as $s,
                    );
                    if v.norm() > 0.1 {
                        return v.normalized();
                    }
                }
            }

            fn rotor(values: &mut Rng) -> Rotor {
                let axis = unit(values);
                Rotor::from_axis_angle(axis, values.signed() as $s * PI)
            }

            fn quat(r: Rotor) -> $quat {
                r.into()
            }

            /// The largest component difference between two rotations given as rotors
            /// or quaternions, up to the sign that does not change the rotation.
            fn rotation_gap(a: [$s; 4], b: [$s; 4]) -> $s {
                let minus = a
                    .iter()
                    .zip(&b)
                    .map(|(x, y)| (x - y).abs())
                    .fold(0.0, $s::max);
                let plus = a
                    .iter()
                    .zip(&b)
                    .map(|(x, y)| (x + y).abs())
                    .fold(0.0, $s::max);
                minus.min(plus)
            }

            fn q_array(q: $quat) -> [$s; 4] {
                q.to_array()
            }

            #[test]
            fn from_axis_angle_matches_glam() {
                let mut values = Rng::new(11);
                for _ in 0..200 {
                    let axis = unit(&mut values);
                    let angle = values.signed() as $s * 2.0 * PI;
                    let ours = quat(Rotor::from_axis_angle(axis, angle));
                    let glam = <$quat>::from_axis_angle(<$vec3>::from(axis), angle);
                    let gap = q_array(ours)
                        .iter()
                        .zip(q_array(glam))
                        .map(|(x, y)| (x - y).abs())
                        .fold(0.0, $s::max);
                    assert!(gap < TOL, "{axis:?} {angle}: {ours:?} vs {glam:?}");
                }
            }

            #[test]
            fn from_axis_angle_turns_e1_toward_e2_about_e3() {
                let r = Rotor::from_axis_angle(Vector::E3, 0.5 * PI);
                assert!((r.sandwich(Vector::E1) - Vector::E2).norm() < TOL);
                assert!((r.sandwich(Vector::E2) + Vector::E1).norm() < TOL);
            }

            #[test]
            fn scaled_axis_matches_glam_and_round_trips() {
                let mut values = Rng::new(12);
                for _ in 0..200 {
                    let axis = unit(&mut values);
                    let angle = values.signed().abs() as $s * PI;
                    let v = axis * angle;
                    let ours = quat(Rotor::from_scaled_axis(v));
                    let glam = <$quat>::from_scaled_axis(<$vec3>::from(v));
                    assert!(rotation_gap(q_array(ours), q_array(glam)) < TOL);
                    let back = Rotor::from_scaled_axis(v).to_scaled_axis();
                    assert!((back - v).norm() < 4.0 * TOL, "{v:?} -> {back:?}");
                    // glam's angle reaches 2 pi; with w >= 0 both take the shorter way.
                    let g = if glam.w < 0.0 { -glam } else { glam };
                    let glam_back = Vector::from(g.to_scaled_axis());
                    assert!((back - glam_back).norm() < 4.0 * TOL);
                    let r = Rotor::from_scaled_axis(v);
                    assert!(((-r).to_scaled_axis() - v).norm() < 4.0 * TOL);
                    assert!(((r * 3.0).to_scaled_axis() - v).norm() < 4.0 * TOL);
                }
            }

            #[test]
            fn scaled_axis_edge_cases() {
                assert_eq!(Rotor::from_scaled_axis(Vector::ZERO), Rotor::ONE);
                assert_eq!(Rotor::ONE.to_scaled_axis(), Vector::ZERO);
                assert_eq!(Rotor::ZERO.to_scaled_axis(), Vector::ZERO);
                let tiny = Vector::new(1e-7, -2e-7, 3e-8);
                let back = Rotor::from_scaled_axis(tiny).to_scaled_axis();
                assert!((back - tiny).norm() < 1e-6 * tiny.norm());
                // A half turn: the scalar is zero and the angle pi.
                let half = Rotor::from_axis_angle(Vector::E2, PI);
                // At pi the axis and its negative are the same rotation; which one comes
                // back depends on the rounding of cos(pi / 2).
                let back = half.to_scaled_axis();
                let gap = (back - Vector::E2 * PI)
                    .norm()
                    .min((back + Vector::E2 * PI).norm());
                assert!(gap < 4.0 * TOL, "{back:?}");
                let (axis, angle) = half.to_axis_angle();
                let axis_gap = (axis - Vector::E2).norm().min((axis + Vector::E2).norm());
                assert!(axis_gap < TOL && (angle - PI).abs() < 4.0 * TOL);
                assert!(!Rotor::from_scaled_axis(Vector::new($s::NAN, 0.0, 0.0)).is_finite());
            }

            #[test]
            fn rotation_arc_matches_glam_and_maps_from_to_to() {
                let mut values = Rng::new(13);
                for _ in 0..200 {
                    let (a, b) = (unit(&mut values), unit(&mut values));
                    let r = Rotor::from_rotation_arc(a, b);
                    let glam = <$quat>::from_rotation_arc(a.into(), b.into());
                    assert!(rotation_gap(q_array(quat(r)), q_array(glam)) < 8.0 * TOL);
                    assert!((r.sandwich(a) - b).norm() < 8.0 * TOL);
                    assert!((r.norm() - 1.0).abs() < 4.0 * TOL);
                    // The shorter way: the rotation angle is the angle between a and b.
                    let between = (a | b).clamp(-1.0, 1.0).acos();
                    assert!((Rotor::ONE.angle_between(r) - between).abs() < 1e-3);
                }
            }

            #[test]
            fn rotation_arc_is_stable_for_opposite_and_nearly_opposite_vectors() {
                let mut values = Rng::new(14);
                for basis in [Vector::E1, Vector::E2, Vector::E3, -Vector::E3] {
                    let r = Rotor::from_rotation_arc(basis, -basis);
                    assert!((r.sandwich(basis) + basis).norm() < TOL, "{basis:?}");
                    assert!((r.norm() - 1.0).abs() < TOL);
                }
                for _ in 0..200 {
                    let a = unit(&mut values);
                    let r = Rotor::from_rotation_arc(a, -a);
                    assert!((r.sandwich(a) + a).norm() < 4.0 * TOL);
                    assert!((r.norm() - 1.0).abs() < 4.0 * TOL);
                    for delta in [1e-2, 1e-3, 1e-5, 1e-8] {
                        let b = (-a + unit(&mut values) * delta as $s).normalized();
                        let r = Rotor::from_rotation_arc(a, b);
                        // Accurate to sqrt(EPSILON) at worst, in the switch-over band.
                        let bound = 4.0 * $s::EPSILON.sqrt();
                        assert!((r.sandwich(a) - b).norm() < bound, "{delta}: {r:?}");
                        assert!((r.norm() - 1.0).abs() < 4.0 * TOL);
                    }
                }
            }

            #[test]
            fn rotation_arc_edge_cases() {
                assert!(
                    (Rotor::from_rotation_arc(Vector::E1, Vector::E1) - Rotor::ONE).norm() < TOL
                );
                assert_eq!(
                    Rotor::from_rotation_arc(Vector::ZERO, Vector::ZERO),
                    Rotor::ZERO
                );
                let nan = Vector::new($s::NAN, 0.0, 0.0);
                assert!(Rotor::from_rotation_arc(Vector::E1, nan).is_nan());
                assert!(Rotor::from_rotation_arc(nan, Vector::E1).is_nan());
            }

            #[test]
            fn matrix_round_trips_match_glam() {
                let mut values = Rng::new(15);
                for _ in 0..200 {
                    let r = rotor(&mut values);
                    let glam_matrix = <$mat3>::from_quat(quat(r));
                    let ours = r.to_matrix();
                    let theirs = glam_matrix.to_cols_array_2d();
                    for c in 0..3 {
                        for row in 0..3 {
                            assert!((ours[c][row] - theirs[c][row]).abs() < 4.0 * TOL);
                        }
                    }
                    let from_glam = Rotor::from_matrix(glam_matrix).unwrap();
                    let from_array = Rotor::from_matrix(theirs).unwrap();
                    assert_eq!(from_glam, from_array);
                    assert!(from_array.s >= 0.0);
                    assert!(rotation_gap(from_array.to_array(), r.to_array()) < 4.0 * TOL);
                    let glam_back = <$quat>::from_mat3(&glam_matrix);
                    assert!(
                        rotation_gap(q_array(quat(from_array)), q_array(glam_back)) < 4.0 * TOL
                    );
                }
            }

            #[test]
            fn from_matrix_is_accurate_near_and_at_a_half_turn() {
                let mut values = Rng::new(16);
                for _ in 0..200 {
                    let axis = unit(&mut values);
                    for angle in [PI, PI - 1e-3, PI - 1e-6, -PI + 1e-6] {
                        let r = Rotor::from_axis_angle(axis, angle);
                        let back = Rotor::from_matrix(r.to_matrix()).unwrap();
                        assert!(
                            rotation_gap(back.to_array(), r.to_array()) < 8.0 * TOL,
                            "{axis:?} {angle}: {back:?} vs {r:?}"
                        );
                    }
                }
            }

            #[test]
            fn slerp_matches_glam_along_the_shorter_arc() {
                let mut values = Rng::new(17);
                for _ in 0..200 {
                    let (a, b) = (rotor(&mut values), rotor(&mut values));
                    let t = (values.signed() as $s + 1.0) / 2.0;
                    let ours = a.slerp(b, t);
                    let glam = quat(a).slerp(quat(b), t);
                    assert!(rotation_gap(q_array(quat(ours)), q_array(glam)) < 16.0 * TOL);
                    assert!(rotation_gap(a.slerp(-b, t).to_array(), ours.to_array()) < 4.0 * TOL);
                    assert!(rotation_gap(a.slerp(b, 0.0).to_array(), a.to_array()) < 4.0 * TOL);
                    assert!(rotation_gap(a.slerp(b, 1.0).to_array(), b.to_array()) < 4.0 * TOL);
                }
            }

            #[test]
            fn slerp_and_angle_between_are_accurate_for_nearly_equal_rotors() {
                let mut values = Rng::new(18);
                for _ in 0..100 {
                    let a = rotor(&mut values);
                    let axis = unit(&mut values);
                    for small in [1e-3, 1e-5, 1e-7] {
                        let small = small as $s;
                        let b = a * Rotor::from_axis_angle(axis, small);
                        let half = a.slerp(b, 0.5);
                        let expected = a * Rotor::from_axis_angle(axis, 0.5 * small);
                        assert!(rotation_gap(half.to_array(), expected.to_array()) < 4.0 * TOL);
                        let angle = a.angle_between(b);
                        // Relative accuracy down to the rounding of `b` itself: acos of
                        // the dot product would give 0 or sqrt(EPSILON)-sized noise here.
                        let bound = 1e-2 * small + 4.0 * TOL;
                        assert!((angle - small).abs() < bound, "{small}: {angle}");
                    }
                    assert_eq!(a.angle_between(a), 0.0);
                    assert_eq!(a.slerp(a, 0.3), a * Rotor::ONE);
                }
            }

            #[test]
            fn nlerp_and_angle_between_match_glam() {
                let mut values = Rng::new(19);
                for _ in 0..200 {
                    let (a, b) = (rotor(&mut values), rotor(&mut values));
                    let t = (values.signed() as $s + 1.0) / 2.0;
                    let ours = quat(a.nlerp(b, t));
                    let glam = quat(a).lerp(quat(b), t);
                    assert!(rotation_gap(q_array(ours), q_array(glam)) < 4.0 * TOL);
                    let between = a.angle_between(b);
                    let glam_between = quat(a).angle_between(quat(b));
                    // glam's acos loses digits near 0 and pi; compare away from them.
                    if between > 0.1 && between < PI - 0.1 {
                        assert!((between - glam_between).abs() < 16.0 * TOL);
                    }
                    assert!((between - a.angle_between(-b)).abs() < 4.0 * TOL);
                }
            }

            #[test]
            fn from_forward_up_points_e3_along_dir_with_e2_up() {
                let mut values = Rng::new(20);
                for _ in 0..200 {
                    let dir = unit(&mut values) * 3.0;
                    let up = unit(&mut values);
                    let Some(r) = Rotor::from_forward_up(dir, up) else {
                        continue;
                    };
                    let forward = dir.normalized();
                    assert!((r.sandwich(Vector::E3) - forward).norm() < 8.0 * TOL);
                    let up_perp = (up - forward * (up | forward)).normalized();
                    assert!((r.sandwich(Vector::E2) - up_perp).norm() < 8.0 * TOL);
                    // Right-handed: e1 goes to up x forward, computed here through glam.
                    let right = Vector::from(<$vec3>::from(up_perp).cross(forward.into()));
                    assert!((r.sandwich(Vector::E1) - right).norm() < 8.0 * TOL);
                }
                assert!(Rotor::from_forward_up(Vector::ZERO, Vector::E2).is_none());
                assert!(Rotor::from_forward_up(Vector::E3, Vector::E3 * -2.0).is_none());
                assert!(
                    Rotor::from_forward_up(Vector::new($s::NAN, 0.0, 1.0), Vector::E2).is_none()
                );
                assert!(
                    Rotor::from_forward_up(Vector::E3, Vector::new($s::INFINITY, 0.0, 0.0))
                        .is_none()
                );
            }

            #[test]
            fn non_finite_input_gives_non_finite_output() {
                let nan = Rotor::new($s::NAN, 0.0, 0.0, 0.0);
                let r = Rotor::from_axis_angle(Vector::E1, 0.3);
                assert!(Rotor::from_axis_angle(Vector::new($s::NAN, 0.0, 0.0), 1.0).is_nan());
                assert!(Rotor::from_axis_angle(Vector::E1, $s::INFINITY).is_nan());
                assert!(r.slerp(nan, 0.5).is_nan() && nan.slerp(r, 0.5).is_nan());
                assert!(r.nlerp(nan, 0.5).is_nan());
                assert!(r.angle_between(nan).is_nan());
                assert!(nan.to_matrix().iter().flatten().any(|c| c.is_nan()));
                let mut m = r.to_matrix();
                m[1][2] = $s::NAN;
                assert!(Rotor::from_matrix(m).is_none());
                assert!(Rotor::from_mat3(m).is_nan());
                assert!(nan.to_scaled_axis().is_nan());
                assert!(nan.to_axis_angle().1.is_nan());
                let wrong = Rotor::new(0.0, 0.0, $s::NAN, 0.0);
                assert!(wrong.to_scaled_axis().is_nan());
            }

            #[test]
            fn g2_angle_functions_follow_the_e12_plane_of_g3() {
                use ga_core::$s::g2;
                let mut values = Rng::new(21);
                for _ in 0..200 {
                    let angle = values.signed() as $s * PI;
                    let r2 = g2::Rotor::from_angle(angle);
                    let r3 = Rotor::from_axis_angle(Vector::E3, angle);
                    assert!((r2.s - r3.s).abs() < TOL && (r2.e12 - r3.e12).abs() < TOL);
                    assert!((r2.angle() - angle).abs() < 4.0 * TOL);
                    assert!(((-r2).angle() - angle).abs() < 4.0 * TOL);
                    let other = values.signed() as $s * PI;
                    let t = (values.signed() as $s + 1.0) / 2.0;
                    let s2 = r2.slerp(g2::Rotor::from_angle(other), t);
                    let s3 = r3.slerp(Rotor::from_axis_angle(Vector::E3, other), t);
                    assert!(rotation_gap([s2.s, s2.e12, 0.0, 0.0], s3.to_array()) < 8.0 * TOL);
                    let between = r2.angle_between(g2::Rotor::from_angle(other));
                    let expected = r3.angle_between(Rotor::from_axis_angle(Vector::E3, other));
                    assert!((between - expected).abs() < 8.0 * TOL);
                }
            }
        }
    };
}

toolkit_tests!(double, f64, glam::DQuat, glam::DVec3, glam::DMat3, 1e-14);
toolkit_tests!(single, f32, glam::Quat, glam::Vec3, glam::Mat3, 2e-6);

#[test]
fn g2_from_angle_is_the_reference_exponential() {
    use ga_tests::Algebra;
    let algebra = Algebra::new(&[1, 1]);
    let mut values = Rng::new(22);
    for _ in 0..100 {
        let angle = values.signed() * std::f64::consts::PI;
        let r = ga_core::f64::g2::Rotor::from_angle(angle);
        // exp(-e12 angle / 2), blade bitmask 0b11 for e12.
        let expected = algebra.exp(&algebra.basis(0b11, -angle / 2.0));
        assert!((r.s - expected[0]).abs() < 1e-14 && (r.e12 - expected[3]).abs() < 1e-14);
    }
}
