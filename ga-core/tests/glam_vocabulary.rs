//! Every glam name ga-core carries, checked against glam 0.32 itself on glam's own edge
//! cases (zero, opposite and colinear vectors, angles near 0 and pi, non-unit input) in
//! f32 and f64; and the fixes of issue 23, each with the case that failed before.

use ga_core::EulerRot;

use ga_test_rng::Rng;

const ORDERS: [EulerRot; 24] = {
    use EulerRot::*;
    [
        ZYX, ZXY, YXZ, YZX, XYZ, XZY, ZYZ, ZXZ, YXY, YZY, XYX, XZX, ZYXEx, ZXYEx, YXZEx, YZXEx,
        XYZEx, XZYEx, ZYZEx, ZXZEx, YXYEx, YZYEx, XYXEx, XZXEx,
    ]
};

/// Whether an order repeats its first axis (proper Euler angles).
fn proper(order: EulerRot) -> bool {
    let name = format!("{order:?}");
    let name = name.as_bytes();
    name[0] == name[2]
}

macro_rules! vocabulary_tests {
    (
        $name:ident, $s:ident, $vec2:ident, $vec3:ident, $vec4:ident, $quat:ident, $mat3:ident,
        $mat4:ident, $affine3:ident, $quat_fn:ident, $vec3_fn:ident, $tol:expr
    ) => {
        mod $name {
            use super::*;
            use core::$s::consts::{FRAC_PI_2, PI};
            use ga_core::glam::{$affine3, $mat3, $mat4, $quat, $vec2, $vec3, $vec4};
            use ga_core::$s::g3::*;

            const TOL: $s = $tol;

            fn vector(rng: &mut Rng) -> Vector {
                Vector::new(rng.signed() as $s, rng.signed() as $s, rng.signed() as $s)
            }

            fn unit(rng: &mut Rng) -> Vector {
                loop {
                    let v = vector(rng);
                    if v.norm() > 0.1 {
                        return v.normalized();
                    }
                }
            }

            fn rotor(rng: &mut Rng) -> Rotor {
                Rotor::from_axis_angle(unit(rng), rng.signed() as $s * 0.999 * PI)
            }

            /// The distance between a rotor and glam's quaternion, up to the sign.
            fn gap(r: Rotor, q: $quat) -> $s {
                let q = Rotor::from(q);
                (r - q).norm().min((r + q).norm())
            }

            fn close(a: Vector, b: $vec3, tol: $s) -> bool {
                (a - Vector::from(b)).norm() <= tol * (1.0 + b.length())
            }

            /// glam's edge-case vectors: axes, zero, tiny, huge, non-unit.
            fn edge_vectors() -> Vec<Vector> {
                vec![
                    Vector::ZERO,
                    Vector::X,
                    -Vector::Y,
                    Vector::Z * 3.0,
                    Vector::new(1e-20, 0.0, 0.0),
                    Vector::new(1.0, 1.0, 1.0),
                    Vector::new(-0.5, 0.25, 2.0),
                ]
            }

            #[test]
            fn vector_vocabulary_matches_glam() {
                assert_eq!($vec3::from(Vector::X), $vec3::X);
                assert_eq!($vec3::from(Vector::Y), $vec3::Y);
                assert_eq!($vec3::from(Vector::Z), $vec3::Z);
                let mut rng = Rng::new(11);
                let mut vectors = edge_vectors();
                vectors.extend((0..200).map(|_| vector(&mut rng) * 4.0));
                for &a in &vectors {
                    let ga = $vec3::from(a);
                    assert_eq!(a.length_squared(), ga.length_squared());
                    assert!((a.length() - ga.length()).abs() <= TOL * ga.length());
                    assert_eq!(a.is_normalized(), ga.is_normalized(), "{a}");
                    let (ours, theirs) = (a.normalize(), ga.normalize());
                    if theirs.is_finite() {
                        assert!(close(ours, theirs, TOL), "{a}");
                    } else {
                        assert!(!ours.is_finite(), "{a}");
                    }
                    for &b in &vectors {
                        let gb = $vec3::from(b);
                        assert!(
                            (a.dot(b) - ga.dot(gb)).abs()
                                <= TOL * (1.0 + ga.length() * gb.length())
                        );
                        assert!(close(
                            a.cross(b),
                            ga.cross(gb),
                            TOL * (1.0 + ga.length() * gb.length())
                        ));
                    }
                    let mut slice = [0.0; 5];
                    a.write_to_slice(&mut slice[1..]);
                    let mut glam_slice = [0.0; 5];
                    ga.write_to_slice(&mut glam_slice[1..]);
                    assert_eq!(slice, glam_slice);
                    assert_eq!(Vector::from_slice(&slice[1..]), a);
                }
                for scale in [1.0, 1.0 + 9e-5, 1.0 - 9e-5, 1.0 + 2e-4, 1.01, 0.0] {
                    let v = Vector::X * scale;
                    assert_eq!(v.is_normalized(), $vec3::from(v).is_normalized(), "{scale}");
                }
            }

            #[test]
            fn elementary_rotations_match_glam_near_zero_and_pi() {
                for angle in [
                    0.0,
                    1e-8,
                    1e-4,
                    0.3,
                    FRAC_PI_2,
                    PI - 1e-6,
                    PI,
                    -PI,
                    2.0 * PI,
                    3.0,
                    -7.0,
                ] {
                    assert!(
                        gap(Rotor::from_rotation_x(angle), $quat::from_rotation_x(angle)) < TOL
                    );
                    assert!(
                        gap(Rotor::from_rotation_y(angle), $quat::from_rotation_y(angle)) < TOL
                    );
                    assert!(
                        gap(Rotor::from_rotation_z(angle), $quat::from_rotation_z(angle)) < TOL
                    );
                }
                assert_eq!($quat::from(Rotor::IDENTITY), $quat::IDENTITY);
            }

            #[test]
            fn quaternion_layout_matches_glam() {
                let mut rng = Rng::new(12);
                for _ in 0..50 {
                    let r = rotor(&mut rng) * 1.5;
                    let q = $quat::from(r);
                    assert_eq!(r.to_xyzw(), q.to_array());
                    assert_eq!(Rotor::from_xyzw(q.x, q.y, q.z, q.w), r);
                    let mut ours = [0.0; 6];
                    let mut theirs = [0.0; 6];
                    r.write_to_slice(&mut ours[2..]);
                    q.write_to_slice(&mut theirs[2..]);
                    assert_eq!(ours, theirs);
                    assert_eq!(Rotor::from_slice(&theirs[2..]), r);
                    assert_eq!(Rotor::from($quat::from_slice(&ours[2..])), r);
                    assert!((r.dot(r * 0.5) - q.dot(q * 0.5)).abs() <= 4.0 * TOL);
                    assert!((r.length_squared() - q.length_squared()).abs() <= 4.0 * TOL);
                    assert!((r.length() - q.length()).abs() <= TOL);
                    assert!(gap(r.normalize(), q.normalize()) <= TOL);
                    assert_eq!(r.is_normalized(), q.is_normalized());
                }
                for scale in [1.0, 1.0 + 9e-5, 1.0 + 2e-4, 0.9, 0.0] {
                    let r = Rotor::IDENTITY * scale;
                    assert_eq!(r.is_normalized(), $quat::from(r).is_normalized(), "{scale}");
                }
                assert!(!Rotor::ZERO.normalize().is_finite());
            }

            #[test]
            fn mul_vec3_is_glams_rotation_for_unit_and_non_unit_rotors() {
                let mut rng = Rng::new(13);
                for i in 0..300 {
                    // Non-unit rotors too: glam's formula is the sandwich for any quaternion.
                    let r = rotor(&mut rng) * if i % 3 == 0 { 1.7 } else { 1.0 };
                    let v = vector(&mut rng) * 10.0;
                    let theirs = $quat::from(r).mul_vec3(v.into());
                    assert!(close(r.mul_vec3(v), theirs, 8.0 * TOL), "{r} {v}");
                    assert!(close(
                        r.mul_vec3(v),
                        $quat::from(r) * $vec3::from(v),
                        8.0 * TOL
                    ));
                }
            }

            #[test]
            fn near_identity_agrees_with_glam_off_its_threshold() {
                // The threshold angles (f32 0.0028474 rad, f64 2.8273e-7 rad), away from
                // them by a factor, both signs of the rotor, and non-unit input.
                let threshold: $s = if core::mem::size_of::<$s>() == 4 {
                    0.002_847_144_6
                } else {
                    2.827e-7
                };
                for factor in [0.0, 0.1, 0.5, 0.9, 1.2, 2.0, 100.0] {
                    for axis in [Vector::X, Vector::new(0.0, 0.6, 0.8)] {
                        let r = Rotor::from_axis_angle(axis, threshold * factor);
                        for r in [r, -r] {
                            assert_eq!(
                                r.is_near_identity(),
                                $quat::from(r).is_near_identity(),
                                "{factor}"
                            );
                        }
                    }
                }
                assert!(Rotor::from_rotation_x(2.0 * PI).is_near_identity());
                assert!(!Rotor::from_rotation_x(PI).is_near_identity());
            }

            #[test]
            fn rotate_towards_matches_glam() {
                let mut rng = Rng::new(14);
                for _ in 0..200 {
                    let (a, b) = (rotor(&mut rng), rotor(&mut rng));
                    let (qa, qb) = ($quat::from(a), $quat::from(b));
                    for max in [0.0, 0.05, 0.5, 2.0, 10.0, -0.3] {
                        let ours = a.rotate_towards(b, max);
                        let theirs = qa.rotate_towards(qb, max);
                        assert!(
                            gap(ours, theirs) < 64.0 * TOL,
                            "{a} {b} {max}: {ours} {theirs:?}"
                        );
                    }
                    // Within 1e-4 rad: the target itself.
                    let near = a * Rotor::from_rotation_y(5e-5);
                    assert_eq!(a.rotate_towards(near, 0.0), near);
                    // Opposite signs of the same rotation: no turn at all.
                    assert!(gap(a.rotate_towards(-a, 1.0), qa) < TOL);
                }
            }

            #[test]
            fn euler_angles_match_glam_in_every_order() {
                let mut rng = Rng::new(15);
                for order in ORDERS {
                    let glam_order = ga_core::glam::EulerRot::from(order);
                    assert_eq!(EulerRot::from(glam_order), order);
                    let lock: &[$s] = if proper(order) {
                        &[0.0, PI]
                    } else {
                        &[FRAC_PI_2, -FRAC_PI_2]
                    };
                    let mut cases: Vec<($s, $s, $s)> = (0..100)
                        .map(|_| {
                            let middle = if proper(order) {
                                (rng.signed() * 0.5 + 0.5) as $s * PI
                            } else {
                                rng.signed() as $s * 1.5
                            };
                            (rng.signed() as $s * 3.1, middle, rng.signed() as $s * 3.1)
                        })
                        .collect();
                    for &b in lock {
                        cases.push((0.4, b, -0.7));
                        cases.push((0.4, b + 1e-3, -0.7));
                    }
                    cases.push((0.0, 0.0, 0.0));
                    cases.push((1e-7, 1e-7, 1e-7));
                    for (a, b, c) in cases {
                        let r = Rotor::from_euler(order, a, b, c);
                        let q = $quat::from_euler(glam_order, a, b, c);
                        assert!(gap(r, q) < 4.0 * TOL, "{order:?} {a} {b} {c}: {r} vs {q:?}");
                        let ours = r.to_euler(order);
                        let theirs = q.to_euler(glam_order);
                        // The angles give back the rotation in every case, gimbal lock included;
                        // near it the outer angles are ill-conditioned (errors grow as one over
                        // the distance to the lock), as glam's are.
                        let distance = lock
                            .iter()
                            .map(|&l| (b - l).abs())
                            .fold($s::INFINITY, $s::min);
                        let back = Rotor::from_euler(order, ours.0, ours.1, ours.2);
                        let tolerance = 64.0 * TOL / distance.max(1e-3);
                        assert!(gap(back, q) < tolerance, "{order:?} {a} {b} {c}: {ours:?}");
                        // Away from gimbal lock the angles are glam's.
                        let locked = distance < 1e-2;
                        if !locked {
                            for (x, y) in
                                [(ours.0, theirs.0), (ours.1, theirs.1), (ours.2, theirs.2)]
                            {
                                let d = (x - y).abs();
                                assert!(
                                    d.min(2.0 * PI - d) < 512.0 * TOL,
                                    "{order:?} {a} {b} {c}: {ours:?} vs {theirs:?}"
                                );
                            }
                        }
                    }
                }
            }

            #[test]
            fn rotation_arcs_match_glam_on_its_edge_cases() {
                let mut rng = Rng::new(16);
                let mut pairs = vec![
                    (Vector::X, Vector::X),
                    (Vector::X, -Vector::X),
                    (Vector::Z, -Vector::Z),
                    (Vector::Y, Vector::Z),
                ];
                for _ in 0..200 {
                    let a = unit(&mut rng);
                    pairs.push((a, unit(&mut rng)));
                    pairs.push((a, a));
                    pairs.push((a, -a));
                }
                for (from, to) in pairs {
                    let (gf, gt) = ($vec3::from(from), $vec3::from(to));
                    let ours = Rotor::from_rotation_arc(from, to);
                    let theirs = $quat::from_rotation_arc(gf, gt);
                    // Opposite vectors have many shortest arcs: what counts is where `from`
                    // goes. (glam's is the identity when `from` and `-from` are an ulp off
                    // unit length: `1 + dot` then passes its threshold and its cross
                    // product is zero; see docs/glam.md.)
                    assert!((ours.mul_vec3(from) - to).norm() < 8.0 * TOL, "{from} {to}");
                    if from.dot(to) > -0.99 {
                        assert!(gap(ours, theirs) < 8.0 * TOL, "{from} {to}");
                    }
                    let ours = Rotor::from_rotation_arc_colinear(from, to);
                    let theirs = $quat::from_rotation_arc_colinear(gf, gt);
                    assert!(
                        gap(ours, theirs) < 8.0 * TOL,
                        "{from} {to}: {ours} {theirs:?}"
                    );
                    assert!((ours.mul_vec3(from).dot(to).abs() - 1.0).abs() < 8.0 * TOL);
                    // Non-unit input counts by its direction (glam asks for unit input).
                    let scaled = Rotor::from_rotation_arc(from * 3.0, to * 0.25);
                    assert!(
                        (scaled.mul_vec3(from) - to).norm() < 8.0 * TOL,
                        "{from} {to}"
                    );
                    assert!((scaled.norm() - 1.0).abs() < 4.0 * TOL);
                }
            }

            #[test]
            fn rotation_arc_with_a_zero_input_is_zero_as_documented() {
                // Failed before: (X, ZERO) gave the identity.
                for v in [Vector::X, Vector::new(0.0, 0.6, -0.8), Vector::ZERO] {
                    assert_eq!(Rotor::from_rotation_arc(v, Vector::ZERO), Rotor::ZERO);
                    assert_eq!(Rotor::from_rotation_arc(Vector::ZERO, v), Rotor::ZERO);
                }
            }

            #[test]
            fn rotation_arc_lands_on_to_near_opposite_vectors() {
                // Failed before: the bisector form missed `to` by about 2 eps / |from + to|
                // (3.3e-4 rad in f32 at |from + to| = 1e-3). The error is measured in f64.
                let mut rng = Rng::new(17);
                let mut worst = 0.0f64;
                for _ in 0..300 {
                    let from = unit(&mut rng);
                    let side = from.cross(unit(&mut rng)).normalized();
                    for gap in [1e-2, 1e-3, 1e-4, 1e-5] {
                        let to = (-from + side * (gap as $s)).normalized();
                        use ga_core::f64::g3 as wide;
                        use wide::Sandwich as _;
                        let r = wide::Rotor::from_array(
                            Rotor::from_rotation_arc(from, to).to_array().map(f64::from),
                        );
                        let widen =
                            |v: Vector| wide::Vector::from_array(v.to_array().map(f64::from));
                        let (from, to) = (widen(from), widen(to));
                        let image = r.sandwich(from) / r.norm_squared();
                        let miss = image.normalized().cross(to.normalized()).norm();
                        worst = worst.max(miss);
                    }
                }
                assert!(worst < 8.0 * $s::EPSILON as f64, "worst miss {worst:e}");
            }

            #[test]
            fn from_matrix_refuses_what_is_not_a_rotation() {
                // Failed before: these gave a unit rotor (diag(3, 0, 0) and ones exactly 1).
                let r = Rotor::from_axis_angle(Vector::new(0.0, 0.6, 0.8), 1.1);
                let m = r.to_matrix();
                let mut with_shear = m;
                for c in 0..3 {
                    for row in 0..3 {
                        // A symmetric traceless part: diag(1, -1, 0) / 100.
                        let s = [[0.01, 0.0, 0.0], [0.0, -0.01, 0.0], [0.0, 0.0, 0.0]][c][row];
                        with_shear[c][row] += s;
                    }
                }
                let reflection = [m[0], m[1], m[2].map(|x| -x)];
                for bad in [
                    [[3.0, 0.0, 0.0], [0.0; 3], [0.0; 3]],
                    [[1.0; 3]; 3],
                    with_shear,
                    reflection,
                    [[$s::NAN; 3]; 3],
                    [[0.0; 3]; 3],
                ] {
                    assert!(Rotor::from_matrix(bad).is_none(), "{bad:?}");
                }
                let back = Rotor::from_matrix(m).unwrap();
                assert!((back - r).norm() < 4.0 * TOL);
                let glam_m = $mat3::from_quat(r.into());
                assert!(
                    gap(
                        Rotor::from_matrix(&glam_m).unwrap(),
                        $quat::from_mat3(&glam_m)
                    ) < 4.0 * TOL
                );
                assert!(gap(Rotor::from_mat3(&glam_m), $quat::from_mat3(&glam_m)) < 4.0 * TOL);
            }

            /// Rotors whose matrices take each of Shepperd's four branches with either
            /// sign of the other components: half turns about the axes (with the
            /// rounding of `cos(pi / 2)` on both sides of zero), quarter turns (the
            /// branch ties), angles near pi about oblique axes, and random rotors.
            fn matrix_edge_rotors(rng: &mut Rng) -> Vec<Rotor> {
                let mut rotors = Vec::new();
                for angle in [PI, -PI, FRAC_PI_2, -FRAC_PI_2, PI * 0.999, -PI * 0.999, 0.0] {
                    rotors.push(Rotor::from_rotation_x(angle));
                    rotors.push(Rotor::from_rotation_y(angle));
                    rotors.push(Rotor::from_rotation_z(angle));
                    for axis in [Vector::new(1.0, 1.0, 0.0), Vector::new(-1.0, 2.0, 3.0)] {
                        rotors.push(Rotor::from_axis_angle(axis.normalize(), angle));
                    }
                }
                rotors.extend((0..300).map(|_| rotor(rng)));
                rotors
            }

            #[test]
            fn from_mat3_gives_glams_quaternion_not_only_its_rotation() {
                // Failed before: `from_mat3` made the scalar non-negative, so a half turn
                // about x whose `w` rounds below zero came out as `-q` (glam: `x = 1`).
                let mut rng = Rng::new(31);
                for r in matrix_edge_rotors(&mut rng) {
                    let m = $mat3::from_quat(r.into());
                    let theirs = Rotor::from($quat::from_mat3(&m));
                    let ours = Rotor::from_mat3(&m);
                    assert!(
                        (ours - theirs).norm() <= 4.0 * TOL,
                        "{r}: {ours} vs {theirs}"
                    );
                    let from_axes = Rotor::from_rotation_axes(m.x_axis, m.y_axis, m.z_axis);
                    let theirs_axes =
                        Rotor::from($quat::from_rotation_axes(m.x_axis, m.y_axis, m.z_axis));
                    assert!((from_axes - theirs_axes).norm() <= 4.0 * TOL, "{r}");
                    // The checked form keeps its promise of a non-negative scalar.
                    let checked = Rotor::from_matrix(&m).unwrap();
                    assert!(checked.s >= 0.0, "{r}: {checked}");
                    assert!((checked - ours).norm().min((checked + ours).norm()) <= 4.0 * TOL);
                }
            }

            #[test]
            fn free_constructors_are_glams() {
                let values = [0.0, -0.0, 1.0, -2.5, 1e-30, $s::MAX, $s::INFINITY, $s::NAN];
                for &x in &values {
                    for &w in &values {
                        let (y, z) = (-x, 0.5);
                        let ours = $quat_fn(x, y, z, w).to_xyzw().map(<$s>::to_bits);
                        let theirs = ga_core::glam::$quat_fn(x, y, z, w).to_array();
                        assert_eq!(ours, theirs.map(<$s>::to_bits), "{x} {w}");
                        let ours = $vec3_fn(x, w, z).to_array().map(<$s>::to_bits);
                        let theirs = ga_core::glam::$vec3_fn(x, w, z).to_array();
                        assert_eq!(ours, theirs.map(<$s>::to_bits), "{x} {w}");
                    }
                }
                assert_eq!($quat_fn(0.0, 0.0, 0.0, 1.0), Rotor::IDENTITY);
            }

            #[test]
            fn rotor_to_vec4_is_glams_xyzw() {
                let mut rng = Rng::new(32);
                let mut rotors = vec![Rotor::ZERO, Rotor::IDENTITY, -Rotor::IDENTITY, Rotor::NAN];
                rotors.extend((0..50).map(|_| rotor(&mut rng) * 1.5));
                for r in rotors {
                    let ours = $vec4::from(r);
                    let theirs = $vec4::from($quat::from(r));
                    assert_eq!(
                        ours.to_array().map(<$s>::to_bits),
                        theirs.to_array().map(<$s>::to_bits)
                    );
                    let back = Rotor::from_vec4(ours);
                    assert_eq!(
                        back.to_array().map(<$s>::to_bits),
                        r.to_array().map(<$s>::to_bits)
                    );
                }
            }

            #[test]
            fn glam_matrix_times_vector_is_glams_product() {
                let mut rng = Rng::new(33);
                for i in 0..100 {
                    // General matrices (not rotations), some with huge or zero columns.
                    let scale = [1.0, 1e30, 0.0][i % 3];
                    let m = $mat3::from_cols(
                        $vec3::from(vector(&mut rng)) * scale,
                        $vec3::from(vector(&mut rng)),
                        $vec3::from(vector(&mut rng)) * 7.0,
                    );
                    let v = vector(&mut rng) * 3.0;
                    let theirs = m * $vec3::from(v);
                    let ours: Vector = m * v;
                    assert!(close(ours, theirs, 4.0 * TOL), "{m} {v}");
                    // Independently: the combination of the columns.
                    let by_columns = Vector::from(m.x_axis) * v.x
                        + Vector::from(m.y_axis) * v.y
                        + Vector::from(m.z_axis) * v.z;
                    let size = 1.0 + by_columns.norm() + scale * v.norm();
                    assert!((ours - by_columns).norm() <= 8.0 * TOL * size, "{m} {v}");
                    assert_eq!(&m * v, ours);
                    assert_eq!(m * &v, ours);
                    assert_eq!(&m * &v, ours);
                }
            }

            #[test]
            fn mul_vec3_takes_and_returns_glams_vectors() {
                let mut rng = Rng::new(34);
                for i in 0..100 {
                    let r = rotor(&mut rng) * if i % 4 == 0 { 0.5 } else { 1.0 };
                    let v = $vec3::from(vector(&mut rng) * 10.0);
                    let ours: $vec3 = r.mul_vec3(v);
                    let theirs = $quat::from(r).mul_vec3(v);
                    assert!(close(Vector::from(ours), theirs, 8.0 * TOL), "{r} {v}");
                    let array: [$s; 3] = r.mul_vec3(v.to_array());
                    assert_eq!(array, r.mul_vec3(Vector::from(v)).to_array());
                }
            }

            #[test]
            fn vector_rotations_match_glam_on_edge_cases() {
                let mut rng = Rng::new(35);
                let mut vectors = edge_vectors();
                vectors.extend((0..40).map(|_| vector(&mut rng) * 3.0));
                let angles = [0.0, 1e-8, FRAC_PI_2, -FRAC_PI_2, PI, -PI, 2.5, 100.0];
                for &v in &vectors {
                    let g = $vec3::from(v);
                    let size = 8.0 * TOL * (1.0 + v.norm());
                    for &angle in &angles {
                        assert!(
                            close(v.rotate_x(angle), g.rotate_x(angle), size),
                            "{v} {angle}"
                        );
                        assert!(
                            close(v.rotate_y(angle), g.rotate_y(angle), size),
                            "{v} {angle}"
                        );
                        assert!(
                            close(v.rotate_z(angle), g.rotate_z(angle), size),
                            "{v} {angle}"
                        );
                        let axis = unit(&mut rng);
                        let theirs = g.rotate_axis(axis.into(), angle);
                        assert!(
                            close(v.rotate_axis(axis, angle), theirs, size),
                            "{v} {angle}"
                        );
                    }
                    let n = unit(&mut rng);
                    let theirs = g.reject_from_normalized(n.into());
                    assert!(close(v.reject_from_normalized(n), theirs, size), "{v} {n}");
                }
            }

            #[test]
            fn vector_rotate_towards_matches_glam() {
                let mut rng = Rng::new(36);
                let mut pairs = vec![
                    (Vector::X, Vector::Y),
                    (Vector::X, Vector::X * 2.0),
                    (Vector::X, -Vector::X),
                    (Vector::Z * 3.0, Vector::new(1.0, 1.0, -1.0)),
                ];
                pairs.extend((0..60).map(|_| (vector(&mut rng) * 2.0, vector(&mut rng))));
                for (a, b) in pairs {
                    if a.norm() < 1e-3 || b.norm() < 1e-3 {
                        continue;
                    }
                    let between = $vec3::from(a).angle_between(b.into());
                    // Away from the ends of the clamp, where glam's f32 `acos` polynomial
                    // and our `atan2` angle may fall on different sides.
                    for max_angle in [0.0, 0.3, -0.3, 2.0, -2.0, 10.0, -10.0] {
                        if (max_angle - between).abs() < 1e-3
                            || (max_angle - (between - PI)).abs() < 1e-3
                        {
                            continue;
                        }
                        let ours = a.rotate_towards(b, max_angle);
                        let theirs = $vec3::from(a).rotate_towards(b.into(), max_angle);
                        // glam's f32 angle is a polynomial acos: about 1e-5 rad.
                        let tol = if TOL > 1e-10 { 1e-4 } else { 1e-12 };
                        assert!(
                            close(ours, theirs, tol * (1.0 + a.norm())),
                            "{a} {b} {max_angle}"
                        );
                    }
                }
                // glam panics on a zero input (its clamp gets NaN); ours returns it.
                assert_eq!(Vector::ZERO.rotate_towards(Vector::X, 1.0), Vector::ZERO);
                assert_eq!(Vector::X.rotate_towards(Vector::ZERO, 1.0), Vector::X);
            }

            #[test]
            #[allow(clippy::excessive_precision)] // Duff et al.'s values as published.
            fn any_orthonormal_pair_is_glams_pair() {
                // Duff et al.'s pathological inputs (as in glam's own suite), the axes
                // and their opposites, and random unit vectors.
                let mut inputs = vec![
                    Vector::new(0.00038527316, 0.00038460016, -0.99999988079).normalize(),
                    Vector::new(-0.00019813581, -0.00008946839, -0.99999988079).normalize(),
                ];
                for axis in Vector::AXES {
                    inputs.push(axis);
                    inputs.push(-axis);
                }
                let mut rng = Rng::new(37);
                inputs.extend((0..100).map(|_| unit(&mut rng)));
                for n in inputs {
                    let (a, b) = n.any_orthonormal_pair();
                    let (ga, gb) = $vec3::from(n).any_orthonormal_pair();
                    assert!(close(a, ga, 4.0 * TOL) && close(b, gb, 4.0 * TOL), "{n}");
                    // Independently: orthonormal and right-handed.
                    assert!((a.cross(b) - n).norm() < 16.0 * TOL, "{n}");
                    assert!(a.dot(n).abs() < 16.0 * TOL && b.dot(n).abs() < 16.0 * TOL);
                }
            }

            #[test]
            fn mat4_conversions_match_glam() {
                let mut rng = Rng::new(18);
                for _ in 0..100 {
                    let r = rotor(&mut rng);
                    let ours = $mat4::from(r);
                    let theirs = $mat4::from_quat(r.into());
                    assert!(ours.abs_diff_eq(theirs, 4.0 * TOL));
                    let with_translation =
                        $mat4::from_rotation_translation(r.into(), $vec3::new(1.0, 2.0, 3.0));
                    let back = Rotor::from_matrix(&with_translation).unwrap();
                    assert!(gap(back, $quat::from_mat4(&with_translation)) < 4.0 * TOL);
                }
            }

            #[test]
            fn look_constructors_match_glam() {
                let mut rng = Rng::new(19);
                for _ in 0..300 {
                    let dir = unit(&mut rng);
                    let up = unit(&mut rng);
                    if dir.cross(up).norm() < 0.05 {
                        continue;
                    }
                    let (gd, gu) = ($vec3::from(dir), $vec3::from(up));
                    assert!(
                        gap(
                            Rotor::look_to_rh(dir, up).unwrap(),
                            $quat::look_to_rh(gd, gu)
                        ) < 16.0 * TOL
                    );
                    assert!(
                        gap(
                            Rotor::look_to_lh(dir, up).unwrap(),
                            $quat::look_to_lh(gd, gu)
                        ) < 16.0 * TOL
                    );
                    let eye = vector(&mut rng) * 5.0;
                    let center = eye + dir * 2.5;
                    let (ge, gc) = ($vec3::from(eye), $vec3::from(center));
                    assert!(
                        gap(
                            Rotor::look_at_rh(eye, center, up).unwrap(),
                            $quat::look_at_rh(ge, gc, gu)
                        ) < 64.0 * TOL
                    );
                    assert!(
                        gap(
                            Rotor::look_at_lh(eye, center, up).unwrap(),
                            $quat::look_at_lh(ge, gc, gu)
                        ) < 64.0 * TOL
                    );
                    // Non-unit input (glam asks for unit): the same rotation as the unit one.
                    assert!(
                        gap(
                            Rotor::look_to_rh(dir * 7.0, up * 0.5).unwrap(),
                            $quat::look_to_rh(gd, gu)
                        ) < 16.0 * TOL
                    );
                    // The old `look_to`, now `from_forward_up`, is glam's `look_to_lh` inverted.
                    let object = Rotor::from_forward_up(dir, up).unwrap();
                    assert!(gap(object, $quat::look_to_lh(gd, gu).inverse()) < 16.0 * TOL);
                }
                assert!(Rotor::look_to_rh(Vector::ZERO, Vector::Y).is_none());
                assert!(Rotor::look_to_lh(Vector::Y, Vector::Y * -2.0).is_none());
                assert!(Rotor::look_at_rh(Vector::X, Vector::X, Vector::Y).is_none());
                assert!(Rotor::look_to_rh(Vector::new($s::NAN, 0.0, 1.0), Vector::Y).is_none());
            }

            /// Component-wise equality that counts NaN equal to NaN.
            fn same(a: Vector, b: $vec3) -> bool {
                a.to_array()
                    .iter()
                    .zip(b.to_array().iter())
                    .all(|(x, y)| x == y || (x.is_nan() && y.is_nan()))
            }

            #[test]
            fn field_names_read_and_write_glams_components() {
                let mut v = Vector::new(1.0, -2.0, 3.5);
                let g = $vec3::from(v);
                assert_eq!((v.x, v.y, v.z), (g.x, g.y, g.z));
                v.x = 4.0;
                v.y += 1.0;
                v.z *= 2.0;
                assert_eq!(v, Vector::new(4.0, -1.0, 7.0));
                let r = &mut v;
                r.z = 0.0;
                assert_eq!(v.e3, 0.0);
                assert_eq!(
                    core::mem::size_of::<Vector>(),
                    core::mem::size_of::<$vec3>()
                );
            }

            #[test]
            fn vector_constants_are_glams() {
                for (ours, theirs) in [
                    (Vector::ONE, $vec3::ONE),
                    (Vector::NEG_ONE, $vec3::NEG_ONE),
                    (Vector::NEG_X, $vec3::NEG_X),
                    (Vector::NEG_Y, $vec3::NEG_Y),
                    (Vector::NEG_Z, $vec3::NEG_Z),
                    (Vector::MIN, $vec3::MIN),
                    (Vector::MAX, $vec3::MAX),
                    (Vector::INFINITY, $vec3::INFINITY),
                    (Vector::NEG_INFINITY, $vec3::NEG_INFINITY),
                    (Vector::NAN, $vec3::NAN),
                    (Vector::splat(-2.5), $vec3::splat(-2.5)),
                ] {
                    assert!(same(ours, theirs), "{ours:?}");
                }
                for (ours, theirs) in Vector::AXES.iter().zip($vec3::AXES.iter()) {
                    assert_eq!($vec3::from(*ours), *theirs);
                }
            }

            #[test]
            fn component_wise_methods_match_glam_on_edge_cases() {
                let mut rng = Rng::new(21);
                let mut vectors = edge_vectors();
                vectors.push(Vector::new($s::NAN, 1.0, -1.0));
                vectors.push(Vector::new($s::INFINITY, 0.0, 0.0));
                vectors.push(Vector::splat($s::MAX));
                vectors.push(Vector::new(-0.0, 0.0, -0.0));
                vectors.extend((0..60).map(|_| vector(&mut rng) * 4.0));
                for &a in &vectors {
                    let ga = $vec3::from(a);
                    assert!(same(a.abs(), ga.abs()), "{a:?}");
                    assert!(same(a.normalize_or_zero(), ga.normalize_or_zero()), "{a:?}");
                    assert!(same(a.normalize_or(Vector::Y), ga.normalize_or($vec3::Y)));
                    let (min, max) = (a.min_element(), a.max_element());
                    assert!(min == ga.min_element() || (min.is_nan() && ga.min_element().is_nan()));
                    assert!(max == ga.max_element() || (max.is_nan() && ga.max_element().is_nan()));
                    assert!(same(a.any_orthogonal_vector(), ga.any_orthogonal_vector()));
                    let l = a.length_recip();
                    assert!(l == ga.length_recip() || (l.is_nan() && ga.length_recip().is_nan()));
                    assert!(same(
                        Vector::from_slice(&a.extend(7.0).to_array()),
                        $vec3::from_slice(&ga.extend(7.0).to_array())
                    ));
                    assert_eq!(a.extend(7.0).w, 7.0);
                    for &b in &vectors {
                        let gb = $vec3::from(b);
                        assert!(same(a.min(b), ga.min(gb)), "{a:?} {b:?}");
                        assert!(same(a.max(b), ga.max(gb)), "{a:?} {b:?}");
                        assert!(same(
                            a.distance_squared(b) * Vector::ONE,
                            ga.distance_squared(gb) * $vec3::ONE
                        ));
                        let d = a.distance(b);
                        let gd = ga.distance(gb);
                        assert!(
                            d == gd || (d.is_nan() && gd.is_nan()) || (d - gd).abs() <= TOL * gd
                        );
                        for s in [0.0, 0.5, 1.0, -1.0, 2.0] {
                            assert!(same(a.lerp(b, s), ga.lerp(gb, s)), "{a:?} {b:?} {s}");
                        }
                        let moderate = |v: Vector| v.length_squared() > 1e-12 && v.length() < 1e6;
                        if moderate(a) && moderate(b) {
                            let scale = TOL * (1.0 + ga.length()) * 4.0;
                            assert!(
                                close(a.project_onto(b), ga.project_onto(gb), scale),
                                "{a:?} {b:?}"
                            );
                            assert!(
                                close(a.reject_from(b), ga.reject_from(gb), scale),
                                "{a:?} {b:?}"
                            );
                            let nb = b.normalize();
                            assert!(close(
                                a.project_onto_normalized(nb),
                                ga.project_onto_normalized(nb.into()),
                                scale
                            ));
                        }
                    }
                }
                // any_orthonormal_vector: glam's vector, for unit input, including +-Z.
                let mut units = vec![
                    Vector::X,
                    Vector::Z,
                    Vector::NEG_Z,
                    Vector::new(0.0, 0.6, -0.8),
                ];
                units.extend((0..100).map(|_| unit(&mut rng)));
                for n in units {
                    let ours = n.any_orthonormal_vector();
                    assert!(
                        close(ours, $vec3::from(n).any_orthonormal_vector(), TOL),
                        "{n:?}"
                    );
                    assert!(
                        ours.dot(n).abs() < 4.0 * TOL && (ours.length() - 1.0).abs() < 4.0 * TOL
                    );
                }
                assert!(Vector::X.abs_diff_eq(Vector::X * (1.0 + TOL), 2.0 * TOL));
                assert!(!Vector::X.abs_diff_eq(Vector::Y, 0.5));
            }

            #[test]
            fn angle_between_vectors_matches_glam_and_is_accurate_near_0_and_pi() {
                let mut rng = Rng::new(22);
                for _ in 0..200 {
                    let r = rotor(&mut rng);
                    for angle in [
                        0.0,
                        1e-6,
                        1e-3,
                        0.1,
                        1.0,
                        FRAC_PI_2,
                        3.0,
                        PI - 1e-3,
                        PI - 1e-6,
                        PI,
                    ] {
                        // Non-unit input of known angle, turned anywhere.
                        let a = r.mul_vec3(Vector::X * 2.0);
                        let b = r.mul_vec3(Vector::new(angle.cos(), angle.sin(), 0.0) * 0.3);
                        let ours = a.angle_between(b);
                        let theirs = $vec3::from(a).angle_between(b.into());
                        assert!((ours - angle).abs() < 16.0 * TOL, "{angle}: {ours}");
                        // glam's acos loses half the digits near 0 and pi (and f32's is a
                        // polynomial); it agrees to that.
                        assert!(
                            (ours - theirs).abs() < 4.0 * TOL.sqrt(),
                            "{angle}: {ours} {theirs}"
                        );
                    }
                }
                for v in [Vector::ZERO, Vector::X] {
                    assert!(v.angle_between(Vector::ZERO).is_nan());
                    assert!($vec3::from(v).angle_between($vec3::ZERO).is_nan());
                }
            }

            #[test]
            fn quaternion_names_match_glam() {
                let mut rng = Rng::new(23);
                assert!(Rotor::NAN.is_nan() && $quat::NAN.is_nan());
                for i in 0..200 {
                    let (a, b) = (
                        rotor(&mut rng),
                        rotor(&mut rng) * if i % 4 == 0 { 1.5 } else { 1.0 },
                    );
                    let (qa, qb) = ($quat::from(a), $quat::from(b));
                    assert_eq!($vec3::from(a.xyz()), qa.xyz());
                    assert_eq!(a.w(), qa.w);
                    assert!((b.length_recip() - qb.length_recip()).abs() <= 4.0 * TOL);
                    // The product keeps its sign: compare exactly, not up to -1.
                    let product = Rotor::from(qa.mul_quat(qb));
                    assert!((a.mul_quat(b) - product).norm() < 4.0 * TOL);
                    assert!((a * b - Rotor::from(qa * qb)).norm() < 4.0 * TOL);
                    let b = b.normalize();
                    let qb = $quat::from(b);
                    for s in [0.0, 0.25, 0.5, 1.0] {
                        let theirs = Rotor::from(qa.lerp(qb, s));
                        assert!((a.lerp(b, s) - theirs).norm() < 4.0 * TOL, "{a} {b} {s}");
                        let theirs = Rotor::from(qa.lerp(-qb, s));
                        assert!((a.lerp(-b, s) - theirs).norm() < 4.0 * TOL, "{a} {b} {s}");
                    }
                    let v4 = $vec4::from(qb) * 2.0;
                    assert_eq!($quat::from(Rotor::from_vec4(v4)), $quat::from_vec4(v4));
                    let translation = $vec3::new(1.0, -2.0, 3.0);
                    let m = $mat4::from_rotation_translation(qa, translation);
                    assert!(gap(Rotor::from_mat4(&m), $quat::from_mat4(&m)) < 4.0 * TOL);
                    let affine = $affine3::from_rotation_translation(qa, translation);
                    assert!(
                        gap(Rotor::from_affine3(&affine), $quat::from_affine3(&affine)) < 4.0 * TOL
                    );
                    let [x, y, z] = [Vector::X, Vector::Y, Vector::Z].map(|e| a.mul_vec3(e));
                    let theirs = $quat::from_rotation_axes(x.into(), y.into(), z.into());
                    assert!(gap(Rotor::from_rotation_axes(x, y, z), theirs) < 4.0 * TOL);
                    assert_eq!(a.abs_diff_eq(b, 0.1), qa.abs_diff_eq(qb, 0.1));
                    assert!(!a.abs_diff_eq(-a, 0.1) && !qa.abs_diff_eq(-qa, 0.1));
                }
            }

            #[test]
            fn slerp_long_takes_the_long_way_with_glams_definition() {
                // glam 0.33's slerp_long is slerp without the flip of `end`: along the
                // great arc of the quaternions themselves. About a fixed axis the rotor of
                // angle `a` goes to that of `b` through the angles `a + s (b - a)` when
                // `|b - a| < 2 pi`, the long way when `|b - a| > pi`.
                let mut rng = Rng::new(24);
                for _ in 0..200 {
                    let axis = unit(&mut rng);
                    let a = rng.signed() as $s * PI;
                    let b = a + rng.signed() as $s * 1.99 * PI;
                    let (start, end) = (
                        Rotor::from_axis_angle(axis, a),
                        Rotor::from_axis_angle(axis, b),
                    );
                    for s in [0.0, 0.1, 0.5, 0.9, 1.0] {
                        let expected = Rotor::from_axis_angle(axis, a + s * (b - a));
                        let ours = start.slerp_long(end, s);
                        assert!(
                            (ours - expected).norm() < 32.0 * TOL,
                            "{a} {b} {s}: {ours} {expected}"
                        );
                        // The short way is glam's slerp and agrees where it is the same arc.
                        if start.dot(end) > 0.0 {
                            assert!((ours - start.slerp(end, s)).norm() < 32.0 * TOL);
                        }
                    }
                }
                // `end = -self`: a full turn, finite and unit throughout.
                let r = Rotor::from_rotation_x(0.7);
                for s in [0.0, 0.3, 0.5, 1.0] {
                    let q = r.slerp_long(-r, s);
                    assert!(q.is_finite() && (q.length() - 1.0).abs() < 4.0 * TOL);
                }
                assert!((r.slerp_long(-r, 1.0) + r).norm() < 8.0 * TOL);
                assert!((r.slerp_long(r, 0.5) - r).norm() < 4.0 * TOL);
            }

            #[test]
            fn rotation_arc_2d_matches_glam_on_its_edge_cases() {
                let mut rng = Rng::new(25);
                let plane = |rng: &mut Rng| {
                    let t = rng.signed() as $s * PI;
                    $vec2::new(t.cos(), t.sin())
                };
                let mut pairs = vec![
                    ($vec2::X, $vec2::X),
                    ($vec2::X, -$vec2::X),
                    ($vec2::Y, -$vec2::Y),
                    ($vec2::X, $vec2::Y),
                ];
                for _ in 0..200 {
                    let f = plane(&mut rng);
                    pairs.push((f, plane(&mut rng)));
                    pairs.push((f, f));
                    pairs.push((f, -f));
                    let near = $vec2::from_angle(PI - 1e-3).rotate(f);
                    pairs.push((f, near));
                }
                for (from, to) in pairs {
                    let ours = Rotor::from_rotation_arc_2d(from, to);
                    let theirs = $quat::from_rotation_arc_2d(from, to);
                    let (f3, t3) = (
                        Vector::new(from.x, from.y, 0.0),
                        Vector::new(to.x, to.y, 0.0),
                    );
                    assert!((ours.mul_vec3(f3) - t3).norm() < 8.0 * TOL, "{from} {to}");
                    if from.dot(to) > -0.99 || from == -to {
                        assert!(
                            gap(ours, theirs) < 8.0 * TOL,
                            "{from} {to}: {ours} {theirs:?}"
                        );
                    }
                    // Non-unit input counts by its direction; arrays are accepted too. (Up
                    // to the sign: opposite vectors scaled apart round to a turn by just
                    // under or over pi.)
                    let scaled = Rotor::from_rotation_arc_2d(from * 3.0, [to.x * 0.5, to.y * 0.5]);
                    assert!(gap(scaled, ours.into()) < 8.0 * TOL, "{from} {to}");
                }
                assert_eq!(
                    Rotor::from_rotation_arc_2d($vec2::X, $vec2::ZERO),
                    Rotor::ZERO
                );
            }

            #[test]
            fn default_rotor_is_the_algebras_zero_and_identity_is_named() {
                // Deliberately different from glam (docs/glam.md): `Rotor` is the algebra's
                // `Even`, whose `Default` is the additive zero.
                assert_eq!(Rotor::default(), Rotor::ZERO);
                assert_eq!(Rotor::IDENTITY, Rotor::ONE);
                assert_eq!($quat::from(Rotor::IDENTITY), $quat::default());
            }
        }
    };
}

vocabulary_tests!(
    f32_vocabulary,
    f32,
    Vec2,
    Vec3,
    Vec4,
    Quat,
    Mat3,
    Mat4,
    Affine3,
    quat,
    vec3,
    2e-7
);
vocabulary_tests!(
    f64_vocabulary,
    f64,
    DVec2,
    DVec3,
    DVec4,
    DQuat,
    DMat3,
    DMat4,
    DAffine3,
    dquat,
    dvec3,
    4e-16
);

#[test]
fn small_angle_series_of_from_scaled_axis_has_the_right_sign() {
    // Below 1e-4 rad `sin(a/2)/a` comes from its series `1/2 - a^2/48`. With the sign
    // flipped the bivector part is off by a relative a^2/24: 4e-10 at 1e-4 rad, which a
    // tolerance of a few ulps in f64 sees (one at 1e-6 does not: the old test's).
    use ga_core::f64::g3::*;
    let axis = Vector::new(0.48, -0.6, 0.64);
    for angle in [9.9e-5, 7e-5, 5e-5, 2e-5] {
        let ours = Rotor::from_scaled_axis(axis * angle);
        let reference = Rotor::from_axis_angle(axis, angle);
        let glam = Rotor::from(ga_core::glam::DQuat::from_scaled_axis(
            (axis * angle).into(),
        ));
        for (x, y) in ours
            .iter()
            .zip(reference.iter())
            .chain(ours.iter().zip(glam.iter()))
        {
            assert!(
                (x - y).abs() <= 4.0 * f64::EPSILON * y.abs(),
                "{angle}: {ours} vs {reference}"
            );
        }
    }
}

#[test]
fn simd_aligned_f32_inputs_match_glam() {
    use ga_core::f32::g3::*;
    use ga_core::glam::{Affine3A, Mat3A, Quat, Vec3, Vec3A};
    let mut rng = Rng::new(26);
    for _ in 0..100 {
        let axis = Vector::new(
            rng.signed() as f32,
            rng.signed() as f32,
            rng.signed() as f32 + 2.0,
        );
        let r = Rotor::from_axis_angle(axis.normalize(), rng.signed() as f32 * 3.1);
        let q = Quat::from(r);
        let v = Vec3A::new(
            rng.signed() as f32,
            rng.signed() as f32,
            rng.signed() as f32,
        );
        assert!(r.mul_vec3a(v).abs_diff_eq(q.mul_vec3a(v), 1e-6));
        assert!((-r).mul_vec3a(v).abs_diff_eq(q * v, 1e-6));
        assert_eq!(Vec3A::from(Vector::from(v)), v);
        let m = Mat3A::from_quat(q);
        assert!(Mat3A::from(r).abs_diff_eq(m, 1e-6));
        let gap = |a: Rotor, b: Quat| (a - Rotor::from(b)).norm().min((a + Rotor::from(b)).norm());
        assert!(gap(Rotor::from_mat3a(&m), Quat::from_mat3a(&m)) < 1e-6);
        assert!(gap(Rotor::from_matrix(m).unwrap(), q) < 1e-6);
        let affine = Affine3A::from_rotation_translation(q, Vec3::new(4.0, 5.0, 6.0));
        assert!(gap(Rotor::from_affine3a(&affine), Quat::from_affine3a(&affine)) < 1e-6);
        let wide = r.as_dquat();
        assert!((wide.as_quat() - r).norm() == 0.0);
        assert_eq!(Vector::from(v).as_dvec3().as_vec3(), Vector::from(v));
    }
}

/// Typical engine code written once against glam's `Quat`/`Vec3` names. Each module below
/// brings in glam's types or ga-core's under those names; the only other change is the
/// documented one, passed in as `$look_unwrap`: ga-core's `look_at_rh` returns `Option`.
/// Rotations are written `mul_vec3` (glam's name for `q * v`): in ga-core `*` is the
/// geometric product (docs/glam.md).
macro_rules! engine_code {
    ($s:ident, $($look_unwrap:tt)*) => {
        pub struct Frame {
            pub rotations: Vec<Quat>,
            pub vectors: Vec<Vec3>,
            pub scalars: Vec<$s>,
        }

        pub fn run(eye: Vec3, target: Vec3, spin: $s) -> Frame {
            let mut rotations = Vec::new();
            let mut vectors = Vec::new();
            let mut scalars = Vec::new();

            // A camera looking at a target, and where the view sends the target.
            let view = Quat::look_at_rh(eye, target, Vec3::Y) $($look_unwrap)*;
            let forward = view.mul_vec3((target - eye).normalize());
            rotations.push(view);
            vectors.push(forward);

            // An object spun about a tilted axis, then turned by the arc between two directions.
            let axis = Vec3::new(1.0, 2.0, -0.5).normalize();
            let spun = Quat::from_axis_angle(axis, spin);
            let arc = Quat::from_rotation_arc(Vec3::Z, (target - eye).normalize());
            let combined = arc * spun;
            rotations.push(combined.normalize());
            vectors.push(combined.mul_vec3(Vec3::X));

            // Interpolated orientations, and the angle between them.
            let start = Quat::from_rotation_y(0.3);
            for t in [0.0, 0.25, 0.5, 1.0] {
                rotations.push(start.slerp(combined, t));
                rotations.push(start.lerp(combined, t));
            }
            scalars.push(start.angle_between(combined));
            let (euler_axis, angle) = Quat::from_scaled_axis(axis * 0.5).to_axis_angle();
            vectors.push(euler_axis);
            scalars.push(angle);

            // Field access, component arithmetic and vector helpers.
            let mut velocity = Vec3::new(eye.x, target.y, 0.5);
            velocity.z += 1.0;
            velocity.x = -velocity.x;
            let position = eye.lerp(target, 0.25) + velocity * 0.1;
            vectors.push(position);
            vectors.push(velocity.cross(Vec3::Y).normalize_or_zero());
            vectors.push(Vec3::ZERO.normalize_or_zero());
            vectors.push(position.min(Vec3::ONE).max(Vec3::NEG_Z).abs());
            vectors.push(velocity.project_onto(Vec3::X));
            vectors.push(axis.any_orthonormal_vector());
            scalars.push(velocity.angle_between(Vec3::NEG_Z));
            scalars.push(eye.distance(target));
            scalars.push(position.max_element() + position.length() + velocity.dot(axis));
            scalars.push(Vec3::splat(2.0).length_squared());
            scalars.push(combined.xyz().length() + view.conjugate().length_recip());

            // Gameplay helpers: speed limits, steering, grid snapping, masks.
            let capped = (velocity * 40.0).clamp_length_max(5.0).with_y(0.0);
            vectors.push(capped);
            vectors.push(eye.move_towards(target, 0.5).midpoint(target));
            vectors.push((position * 3.3).round().clamp(Vec3::NEG_ONE * 2.0, Vec3::splat(2.0)));
            vectors.push(velocity.signum().mul_add(velocity.abs().sqrt(), position.fract_gl()));
            vectors.push((target - eye).try_normalize().unwrap_or(Vec3::Y));
            vectors.push(Vec3::X.slerp(velocity, 0.4));
            vectors.push(Vec3::select(position.cmplt(eye), position, eye));
            scalars.push(position.element_sum() + capped.max_position() as $s);
            Frame { rotations, vectors, scalars }
        }
    };
}

mod engine_with_glam {
    use ga_core::glam::{Quat, Vec3};
    engine_code!(f32,);
}

mod engine_with_ga_core {
    use ga_core::f32::g3::{Rotor as Quat, Vector as Vec3};
    engine_code!(f32, .unwrap());
}

#[test]
fn glam_engine_code_renamed_to_rotor_and_vector_gives_glams_results() {
    use ga_core::f32::g3::{Rotor, Vector};
    let mut rng = Rng::new(27);
    for _ in 0..100 {
        let eye = Vector::new(
            rng.signed() as f32,
            rng.signed() as f32,
            rng.signed() as f32,
        ) * 5.0;
        let target = Vector::new(
            rng.signed() as f32,
            rng.signed() as f32,
            rng.signed() as f32 - 2.0,
        );
        let spin = rng.signed() as f32 * 3.0;
        let ours = engine_with_ga_core::run(eye, target, spin);
        let theirs = engine_with_glam::run(eye.into(), target.into(), spin);
        for (a, b) in ours.rotations.iter().zip(&theirs.rotations) {
            let b = Rotor::from(*b);
            assert!((*a - b).norm().min((*a + b).norm()) < 1e-5, "{a} {b}");
        }
        for (a, b) in ours.vectors.iter().zip(&theirs.vectors) {
            assert!(
                (*a - Vector::from(*b)).norm() < 1e-5 * (1.0 + b.length()),
                "{a} {b}"
            );
        }
        for (a, b) in ours.scalars.iter().zip(&theirs.scalars) {
            // glam's f32 angles come from a polynomial acos: a few 1e-5 rad.
            assert!((a - b).abs() < 1e-4 * (1.0 + b.abs()), "{a} {b}");
        }
        let counts = |f: &engine_with_ga_core::Frame| (f.rotations.len(), f.vectors.len());
        assert_eq!(
            counts(&ours),
            (theirs.rotations.len(), theirs.vectors.len())
        );
    }
}
