//! The motor toolkit of projective algebras (`normalized_study`, `sqrt`, `/` by lines
//! and motors, `constrained`, `to_matrix4x4`/`to_matrix3x4`, Euler angles) against
//! klein's own test cases (jeremyong/klein, `test/`: their numbers, ported onto this
//! crate's basis) and against independent checks: the slow reference algebra
//! (`x ~x`, products, inverses), the sandwich applied point by point, and textbook
//! rotation matrices.
//!
//! klein's 3D PGA has `e0` null and `e1, e2, e3` Euclidean; here `metric: [0, 1, 1, 1]`
//! names them `e1` and `e2, e3, e4`, so klein's `e23, e31, e12` are `e34, -e24, e23`
//! and its `e01, e02, e03, e0123` are `e12, e13, e14, e1234`. Every check is also run
//! with the null generator last (`ga_tests::algebras::pga`, `metric: [1, 1, 1, 0]`)
//! where it does not depend on klein's numbering.

use ga_tests::assert_close;
use ga_tests::reference::Algebra;

ga_macros::algebra! {
    /// klein's 3D PGA: `e1` the null generator (klein's `e0`).
    pub mod pga0 {
        metric: [0, 1, 1, 1],
        scalar: f64,
    }
}

mod embedding {
    use super::pga0::*;
    ga_tests::embed_types!(
        f64;
        Vector,
        Bivector,
        Trivector,
        Quadvector,
        Even,
        Odd,
        Multivector
    );
}

use ga_tests::embed::Embed;
use pga0::{Bivector, Even, Multivector, Sandwich, Trivector};

/// klein's `motor{a, b, c, d, e, f, g, h}`: `a + b e23 + c e31 + d e12 + e e01 + f e02
/// + g e03 + h e0123`.
#[allow(clippy::too_many_arguments, clippy::many_single_char_names)]
fn motor(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64, g: f64, h: f64) -> Even {
    Even {
        s: a,
        e12: e,
        e13: f,
        e14: g,
        e23: d,
        e24: -c,
        e34: b,
        e1234: h,
    }
}

/// klein's `line{a, b, c, d, e, f}`: `a e01 + b e02 + c e03 + d e23 + e e31 + f e12`.
#[allow(clippy::many_single_char_names)]
fn line(a: f64, b: f64, c: f64, d: f64, e: f64, f: f64) -> Bivector {
    Bivector {
        e12: a,
        e13: b,
        e14: c,
        e23: f,
        e24: -e,
        e34: d,
    }
}

/// klein's `rotor{angle, x, y, z}`: `cos(angle/2) + sin(angle/2) (x e23 + y e31 + z e12)
/// / |(x, y, z)|`.
fn rotor(angle: f64, x: f64, y: f64, z: f64) -> Even {
    let (sin, cos) = (0.5 * angle).sin_cos();
    let k = sin / (x * x + y * y + z * z).sqrt();
    motor(cos, k * x, k * y, k * z, 0.0, 0.0, 0.0, 0.0)
}

/// klein's `translator{delta, x, y, z}`: `1 - delta/2 (x e01 + y e02 + z e03) / |(x, y, z)|`.
fn translator(delta: f64, x: f64, y: f64, z: f64) -> Even {
    let k = -0.5 * delta / (x * x + y * y + z * z).sqrt();
    motor(1.0, 0.0, 0.0, 0.0, k * x, k * y, k * z, 0.0)
}

/// klein's components of a motor, in its order `(a, .., h)`.
fn klein_of(m: Even) -> [f64; 8] {
    [m.s, m.e34, -m.e24, m.e23, m.e12, m.e13, m.e14, m.e1234]
}

/// The homogeneous coordinates `(x, y, z, w)` of a trivector, read through the
/// constructor `Trivector::point` (each coordinate sits on one component, with a sign).
fn coordinates(p: Trivector) -> [f64; 4] {
    let origin = Trivector::point(0.0, 0.0, 0.0);
    let axes = [
        Trivector::point(1.0, 0.0, 0.0) - origin,
        Trivector::point(0.0, 1.0, 0.0) - origin,
        Trivector::point(0.0, 0.0, 1.0) - origin,
        origin,
    ];
    axes.map(|axis| {
        let dot: f64 = axis
            .to_array()
            .iter()
            .zip(p.to_array())
            .map(|(a, b)| a * b)
            .sum();
        dot / axis.norm_squared().abs().max(1.0)
    })
}

/// `m` (column-major `[column][row]`) times `v`.
fn apply<const R: usize>(m: [[f64; R]; 4], v: [f64; 4]) -> [f64; R] {
    let mut out = [0.0; R];
    for (column, &x) in m.iter().zip(&v) {
        for (o, &entry) in out.iter_mut().zip(column) {
            *o += entry * x;
        }
    }
    out
}

fn reference() -> Algebra {
    Algebra::new(&[0, 1, 1, 1])
}

fn dense<T: Embed<Multivector>>(x: T) -> Vec<f64> {
    x.to_reference()
}

/// `x ~x` in the reference algebra.
fn times_reverse<T: Embed<Multivector>>(x: T) -> Vec<f64> {
    let alg = reference();
    let d = dense(x);
    alg.geometric(&d, &alg.reverse(&d))
}

/// A fixed-seed stream of values in `[-1, 1)` (xorshift), for the property checks.
struct Stream(u64);

impl Stream {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 52) as f64 - 1.0
    }

    fn motor(&mut self, translation: f64) -> Even {
        let mut c = [0.0; 8];
        for (k, value) in c.iter_mut().enumerate() {
            *value = self.next()
                * if (1..=3).contains(&k) {
                    translation
                } else {
                    1.0
                };
        }
        Even::from_array(c)
    }
}

// ---- Study normalisation -------------------------------------------------------------

/// klein `test_sw.cpp` "normalize-motor": `m ~m = 1` with zero `e0123` after `normalize`.
#[test]
fn klein_normalize_motor() {
    let m = motor(1.0, 4.0, 3.0, 2.0, 5.0, 6.0, 7.0, 8.0).normalized_study();
    assert_close!(times_reverse(m), reference().scalar(1.0), rel = 1e-15);
    // The plain `normalized` divides by the scalar part only: `e0123` stays.
    let plain = motor(1.0, 4.0, 3.0, 2.0, 5.0, 6.0, 7.0, 8.0).normalized();
    assert!(times_reverse(plain)[15].abs() > 0.1);
}

/// klein `test_gp.cpp` "line-normalization": `l ~l = 1` in every component.
#[test]
fn klein_line_normalization() {
    let l = line(1.0, 2.0, 3.0, 3.0, 2.0, 1.0).normalized_study();
    assert_close!(times_reverse(l), reference().scalar(1.0), rel = 1e-15);
}

/// The Study normalisation keeps the motion (a point maps to the same point) and
/// makes `x ~x` exactly `1 + 0 I` to rounding, for random motors and lines; and a
/// motor already normalised comes back unchanged.
#[test]
fn study_normalisation_keeps_the_motion_and_makes_x_rev_x_one() {
    let mut stream = Stream(0x5eed_1234_abcd_ef01);
    let alg = reference();
    for _ in 0..200 {
        let m = stream.motor(10.0);
        let u = m.normalized_study();
        assert_close!(times_reverse(u), alg.scalar(1.0), rel = 1e-14);
        let p = Trivector::point(stream.next(), stream.next(), stream.next());
        let (a, b) = (coordinates(m.sandwich(p)), coordinates(u.sandwich(p)));
        let (a, b) = (a.map(|c| c / a[3]), b.map(|c| c / b[3]));
        assert_close!(a, b, rel = 1e-13);
        assert_close!(u.normalized_study().to_array(), u.to_array(), rel = 1e-15);
        let l = Bivector::from_array(std::array::from_fn(|k| {
            stream.next() * if k < 3 { 5.0 } else { 1.0 }
        }));
        assert_close!(
            times_reverse(l.normalized_study()),
            alg.scalar(1.0),
            rel = 1e-14
        );
    }
}

#[test]
fn study_normalisation_is_scaled_at_extreme_magnitudes_and_reports_ideal_elements() {
    let m = motor(1.0, 4.0, 3.0, 2.0, 5.0, 6.0, 7.0, 8.0);
    let unit = m.normalized_study();
    for scale in [1e-200, 1e200] {
        let big = (m * scale).normalized_study();
        assert_close!(big.to_array(), unit.to_array(), rel = 1e-15);
    }
    // A pure translation direction (klein's ideal line) has no Euclidean part.
    assert_eq!(
        line(1.0, 2.0, 3.0, 0.0, 0.0, 0.0).try_normalized_study(),
        None
    );
    assert!(unit.try_normalized_study().is_some());
}

// ---- square root --------------------------------------------------------------------

/// klein `test_exp_log.cpp` "motor-exp-log-sqrt" and "rotor-sqrt", `test_sw.cpp`
/// "motor-sqrt": `sqrt(m) sqrt(m) = m` for unit motors.
#[test]
fn klein_motor_and_rotor_sqrt() {
    let r = rotor(std::f64::consts::FRAC_PI_2, 0.3, -3.0, 1.0);
    let t = translator(12.0, -2.0, 0.4, 1.0);
    for m in [r, r * t, t] {
        let root = m.sqrt();
        assert_close!((root * root).to_array(), m.to_array(), rel = 1e-14);
    }
    let r = rotor(std::f64::consts::FRAC_PI_2, 1.0, 2.0, 3.0);
    assert_close!((r.sqrt() * r.sqrt()).to_array(), r.to_array(), rel = 1e-15);
    // klein "motor-sqrt": the screw motion about a normalised line.
    let l = line(3.0, 1.0, 2.0, 4.0, -2.0, 1.0).normalized_study();
    // klein's `motor(angle, d, l)` is `exp((-angle/2 + d/2 e0123) l)`.
    let half = Even {
        s: -std::f64::consts::FRAC_PI_4,
        e1234: 1.5,
        ..Even::ZERO
    };
    let m = (half * Even::from(l)).grade2().exp();
    assert_close!((m.sqrt() * m.sqrt()).to_array(), m.to_array(), rel = 1e-14);
}

/// The root of a non-unit motor is the root of its Study normalisation, against the
/// reference's product; and it is half the motion: applied twice to a point, it moves
/// the point as the motor does.
#[test]
fn sqrt_squares_to_the_normalised_motor() {
    let mut stream = Stream(0x0dd_ba11);
    for _ in 0..200 {
        let m = stream.motor(5.0).constrained();
        let root = m.sqrt();
        let alg = reference();
        let squared = alg.geometric(&dense(root), &dense(root));
        assert_close!(squared, dense(m.normalized_study()), rel = 1e-13);
        let p = Trivector::point(stream.next(), stream.next(), stream.next());
        let twice = coordinates(root.sandwich(root.sandwich(p)));
        let once = coordinates(m.sandwich(p));
        assert_close!(
            twice.map(|c| c / twice[3]),
            once.map(|c| c / once[3]),
            rel = 1e-12
        );
    }
}

// ---- constrained --------------------------------------------------------------------

/// klein `main.cpp` "rotor-constrain" and "motor-constrain".
#[test]
fn klein_constrain() {
    let r1 = rotor(1.0, 2.0, 3.0, 4.0);
    assert_eq!(r1.constrained(), r1);
    assert_eq!((-r1).constrained(), r1);
    let m1 = motor(1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0);
    assert_eq!(m1.constrained(), m1);
    assert_eq!((-m1).constrained(), m1);
    assert_eq!(
        klein_of((-m1).constrained()),
        [1.0, 2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0]
    );
}

// ---- division -----------------------------------------------------------------------

/// klein `test_gp.cpp` "line/line" and "motor/motor": `x / x = 1`.
#[test]
fn klein_line_and_motor_division() {
    let l = line(1.0, -2.0, 2.0, -3.0, 3.0, -4.0);
    assert_close!(
        (l / l).to_array(),
        Even::ONE.to_array(),
        scale = 1.0,
        rel = 1e-15
    );
    let m = motor(2.0, 3.0, 4.0, 5.0, 6.0, 7.0, 8.0, 9.0);
    assert_close!(
        (m / m).to_array(),
        Even::ONE.to_array(),
        scale = 1.0,
        rel = 1e-15
    );
    // klein "plane*plane": `sqrt(p1 / p2)` carries `p2` to `p1`; the quotient of two
    // planes is a motor, and dividing by it is division by an `Even`.
    let (p1, p2) = (
        pga0::Vector::plane(1.0, 2.0, 3.0, 4.0),
        pga0::Vector::plane(2.0, 3.0, -1.0, -2.0),
    );
    let q = p1 / p2;
    let carried = q.sqrt().sandwich(p2);
    let ratio = carried.to_array()[1] / p1.to_array()[1];
    assert_close!(
        (carried * (1.0 / ratio)).to_array(),
        p1.to_array(),
        rel = 1e-14
    );
    assert_close!(
        (q / q).to_array(),
        Even::ONE.to_array(),
        scale = 1.0,
        rel = 1e-14
    );
}

/// `a / b = a b^-1` with the reference's inverse (a linear solve on the dense
/// multivector), for every kind of left operand and both divisors.
#[test]
fn division_matches_the_reference_inverse() {
    let alg = reference();
    let mut stream = Stream(0xfeed_f00d);
    for _ in 0..100 {
        let m = stream.motor(3.0);
        let l = Bivector::from_array(std::array::from_fn(|_| stream.next()));
        let a = Multivector::from_array(std::array::from_fn(|_| stream.next()));
        let inv_m = alg.inverse(&dense(m)).expect("invertible");
        let inv_l = alg.inverse(&dense(l)).expect("invertible");
        assert_close!(dense(a / m), alg.geometric(&dense(a), &inv_m), rel = 1e-12);
        assert_close!(dense(a / l), alg.geometric(&dense(a), &inv_l), rel = 1e-12);
        assert_close!(dense(l / m), alg.geometric(&dense(l), &inv_m), rel = 1e-12);
        assert_close!(dense(m / l), alg.geometric(&dense(m), &inv_l), rel = 1e-12);
        assert_close!(dense(2.0 / l), alg.scale(&inv_l, 2.0), rel = 1e-12);
        // And agrees with the checked `inverse`.
        assert_close!(dense(m / m), alg.scalar(1.0), scale = 1.0, rel = 1e-13);
        assert_close!(
            dense(a / m),
            dense(a * m.inverse().expect("invertible")),
            rel = 1e-12
        );
    }
    // An ideal divisor (no Euclidean part) gives non-finite components, like 1 / 0.
    assert!(!(Even::ONE / line(1.0, 0.0, 0.0, 0.0, 0.0, 0.0)).is_finite());
}

// ---- matrices -----------------------------------------------------------------------

/// klein `test_sw.cpp` "motor-to-matrix": exact integers.
#[test]
fn klein_motor_to_matrix() {
    let m = motor(1.0, 4.0, 3.0, 2.0, 5.0, 6.0, 7.0, 8.0);
    let out = apply(m.to_matrix4x4(), [-1.0, 1.0, 2.0, 1.0]);
    assert_eq!(out, [-12.0, -86.0, -86.0, 30.0]);
}

/// klein `test_sw.cpp` "motor-to-matrix-3x4": the Study-normalised motor's affine map.
#[test]
fn klein_motor_to_matrix_3x4() {
    let m = motor(1.0, 4.0, 3.0, 2.0, 5.0, 6.0, 7.0, 8.0).normalized_study();
    let out = apply(m.to_matrix3x4(), [-1.0, 1.0, 2.0, 1.0]);
    assert_close!(out, [-12.0 / 30.0, -86.0 / 30.0, -86.0 / 30.0], rel = 1e-15);
}

/// klein `test_sw.cpp` "rotor-point" and "construct-motor": the direction of klein's
/// rotors and translators, through the matrix and through the sandwich.
#[test]
fn klein_rotor_and_motor_on_a_point() {
    let r = rotor(std::f64::consts::FRAC_PI_2, 0.0, 0.0, 1.0);
    let t = translator(1.0, 0.0, 0.0, 1.0);
    let p = Trivector::point(1.0, 0.0, 0.0);
    let expected = [
        [0.0, -1.0, 0.0, 1.0],
        [0.0, -1.0, 1.0, 1.0],
        [0.0, -1.0, 1.0, 1.0],
    ];
    for (m, expected) in [r, r * t, t * r].into_iter().zip(expected) {
        assert_close!(
            coordinates(m.sandwich(p)),
            expected,
            scale = 1.0,
            rel = 1e-15
        );
        let moved = apply(m.to_matrix4x4(), [1.0, 0.0, 0.0, 1.0]);
        assert_close!(moved, expected, scale = 1.0, rel = 1e-15);
    }
}

/// The matrix applied to a point's coordinates is the sandwich of the point, for
/// random (not normalised) motors.
#[test]
fn matrix_is_the_sandwich_on_points() {
    let mut stream = Stream(0x1234_5678);
    for _ in 0..200 {
        let m = stream.motor(4.0);
        let v = [stream.next(), stream.next(), stream.next(), stream.next()];
        let p = Trivector::point(v[0], v[1], v[2]) - Trivector::point(0.0, 0.0, 0.0)
            + Trivector::point(0.0, 0.0, 0.0) * v[3];
        assert_close!(coordinates(p), v, rel = 1e-15);
        let sandwich = coordinates(m.sandwich(p));
        assert_close!(apply(m.to_matrix4x4(), v), sandwich, rel = 1e-13);
        let u = m.normalized_study();
        let affine = apply(u.to_matrix3x4(), v);
        let exact = coordinates(u.sandwich(p));
        assert_close!(affine, [exact[0], exact[1], exact[2]], rel = 1e-13);
    }
}

/// The same with the null generator last (`metric: [1, 1, 1, 0]`).
#[test]
fn matrix_is_the_sandwich_with_the_null_generator_last() {
    use ga_tests::algebras::pga::{Even, Sandwich, Trivector};
    let mut stream = Stream(0x9876_5432);
    let coordinates = |p: Trivector| {
        let origin = Trivector::point(0.0, 0.0, 0.0);
        [
            Trivector::point(1.0, 0.0, 0.0) - origin,
            Trivector::point(0.0, 1.0, 0.0) - origin,
            Trivector::point(0.0, 0.0, 1.0) - origin,
            origin,
        ]
        .map(|axis| {
            let dot: f64 = axis
                .to_array()
                .iter()
                .zip(p.to_array())
                .map(|(a, b)| a * b)
                .sum();
            dot
        })
    };
    for _ in 0..100 {
        let m = Even::from_array(std::array::from_fn(|_| stream.next()));
        let (x, y, z) = (stream.next(), stream.next(), stream.next());
        let moved = coordinates(m.sandwich(Trivector::point(x, y, z)));
        assert_close!(apply(m.to_matrix4x4(), [x, y, z, 1.0]), moved, rel = 1e-13);
    }
}

// ---- Euler angles -------------------------------------------------------------------

/// klein `test_metric.cpp` "euler-angles": `rx * ry * rz` of unit angles is
/// `(roll, pitch, yaw) = (1, 1, 1)`, and back.
#[test]
fn klein_euler_angles() {
    let rx = rotor(1.0, 1.0, 0.0, 0.0);
    let ry = rotor(1.0, 0.0, 1.0, 0.0);
    let rz = rotor(1.0, 0.0, 0.0, 1.0);
    let r = rx * ry * rz;
    let (roll, pitch, yaw) = r.to_euler_angles();
    assert_close!([roll, pitch, yaw], [1.0, 1.0, 1.0], rel = 1e-14);
    assert_close!(
        Even::from_euler_angles(roll, pitch, yaw).to_array(),
        r.to_array(),
        rel = 1e-14
    );
}

/// klein `test_metric.cpp` "euler-angles-precision".
#[test]
fn klein_euler_angles_precision() {
    let pi = std::f64::consts::PI;
    let r = Even::from_euler_angles(0.2 * pi, 0.2 * pi, 0.0);
    let (roll, pitch, yaw) = r.to_euler_angles();
    assert_close!(
        [roll, pitch, yaw],
        [0.2 * pi, 0.2 * pi, 0.0],
        scale = 1.0,
        rel = 1e-15
    );
}

/// The 3x3 rotation of `Rx(-roll) Ry(-pitch) Rz(-yaw)` (right-handed elementary
/// rotations): klein's rotors turn by minus their angle in the right-handed sense.
fn textbook(roll: f64, pitch: f64, yaw: f64) -> [[f64; 3]; 3] {
    let mul = |a: [[f64; 3]; 3], b: [[f64; 3]; 3]| {
        let mut out = [[0.0; 3]; 3];
        for (r, row) in out.iter_mut().enumerate() {
            for (c, entry) in row.iter_mut().enumerate() {
                *entry = (0..3).map(|k| a[r][k] * b[k][c]).sum();
            }
        }
        out
    };
    let (sr, cr) = (-roll).sin_cos();
    let (sp, cp) = (-pitch).sin_cos();
    let (sy, cy) = (-yaw).sin_cos();
    let rx = [[1.0, 0.0, 0.0], [0.0, cr, -sr], [0.0, sr, cr]];
    let ry = [[cp, 0.0, sp], [0.0, 1.0, 0.0], [-sp, 0.0, cp]];
    let rz = [[cy, -sy, 0.0], [sy, cy, 0.0], [0.0, 0.0, 1.0]];
    mul(mul(rx, ry), rz)
}

/// `from_euler_angles` against the textbook matrices (row-major here, the crate's
/// matrices column-major), and `to_euler_angles` inverts it on the whole range,
/// for any scale and sign of the rotor, up to the poles `pitch = +-pi/2`, where the
/// rotation (not the angles, which are not unique there) comes back.
#[test]
fn euler_angles_match_textbook_matrices_and_invert() {
    let pi = std::f64::consts::PI;
    let mut stream = Stream(0xe1e1_e1e1);
    let mut cases: Vec<[f64; 3]> = (0..300)
        .map(|_| {
            [
                stream.next() * pi,
                stream.next() * 0.5 * pi,
                stream.next() * pi,
            ]
        })
        .collect();
    cases.extend([
        [0.3, 0.5 * pi, -1.2],
        [-2.0, -0.5 * pi, 0.7],
        [1.0, 0.5 * pi - 1e-9, 2.0],
    ]);
    cases.extend([[pi, 0.1, pi], [0.0, 0.0, 0.0], [1e-20, -1e-20, 1e-20]]);
    for [roll, pitch, yaw] in cases {
        let r = Even::from_euler_angles(roll, pitch, yaw);
        let m = r.to_matrix3x4();
        let rows = textbook(roll, pitch, yaw);
        for (c, column) in m.iter().take(3).enumerate() {
            let expected = [rows[0][c], rows[1][c], rows[2][c]];
            assert_close!(*column, expected, scale = 1.0, rel = 1e-15);
        }
        for scaled in [r, r * -3.0, r * 1e-100] {
            let (a, b, c) = scaled.to_euler_angles();
            let back = Even::from_euler_angles(a, b, c);
            let same = back
                .to_array()
                .iter()
                .zip(r.to_array())
                .map(|(x, y)| x * y)
                .sum::<f64>();
            let back = if same < 0.0 { -back } else { back };
            assert_close!(back.to_array(), r.to_array(), scale = 1.0, rel = 1e-15);
            if (pitch.abs() - 0.5 * pi).abs() > 1e-6 {
                // Near a pole roll and yaw are ill-conditioned (only their sum or
                // difference is well defined): their error grows as 1 / cos(pitch).
                let wrapped = |x: f64| if x > pi { x - 2.0 * pi } else { x };
                assert_close!(
                    [a, b, c],
                    [wrapped(roll), pitch, wrapped(yaw)],
                    scale = 1.0,
                    rel = 2e-15 / pitch.cos()
                );
            }
        }
        // Small angles keep their relative precision.
        if roll.abs() < 1e-10 {
            let (a, b, c) = r.to_euler_angles();
            assert_close!([a, b, c], [roll, pitch, yaw], rel = 1e-14);
        }
    }
    // At the poles exactly, klein's choice: yaw = 0.
    let at_pole = motor(0.5f64.sqrt(), 0.0, 0.5f64.sqrt(), 0.0, 0.0, 0.0, 0.0, 0.0);
    let (roll, pitch, yaw) = at_pole.to_euler_angles();
    assert_eq!((roll, yaw), (0.0, 0.0));
    assert_close!(pitch, 0.5 * pi, rel = 1e-15);
}

/// With the null generator last, the angles come from the same Euclidean bivectors.
#[test]
fn euler_angles_with_the_null_generator_last() {
    use ga_tests::algebras::pga::Even as Even3;
    let (roll, pitch, yaw) = (0.4, -0.3, 1.1);
    let a = Even::from_euler_angles(roll, pitch, yaw).to_matrix3x4();
    let b = Even3::from_euler_angles(roll, pitch, yaw);
    assert_close!(
        b.to_matrix3x4().concat(),
        a.concat(),
        scale = 1.0,
        rel = 1e-15
    );
    let (r, p, y) = b.to_euler_angles();
    assert_close!([r, p, y], [roll, pitch, yaw], rel = 1e-15);
}

ga_macros::algebra! {
    /// klein's 3D PGA in `f32`, klein's own precision.
    pub mod pga0_f32 {
        metric: [0, 1, 1, 1],
        scalar: f32,
    }
}

/// klein's cases at klein's precision (`doctest::Approx`: relative `1.19e-5`).
#[test]
fn klein_cases_in_f32() {
    use pga0_f32::{Bivector, Even};
    let m = Even {
        s: 1.0,
        e12: 5.0,
        e13: 6.0,
        e14: 7.0,
        e23: 2.0,
        e24: -3.0,
        e34: 4.0,
        e1234: 8.0,
    };
    let columns = m.to_matrix4x4();
    let mut out = [0.0f32; 4];
    for (column, x) in columns.iter().zip([-1.0f32, 1.0, 2.0, 1.0]) {
        for (o, entry) in out.iter_mut().zip(column) {
            *o += entry * x;
        }
    }
    assert_eq!(out, [-12.0, -86.0, -86.0, 30.0]);
    let u = m.normalized_study();
    let unit = u * u.reverse();
    assert!(
        (unit.s - 1.0).abs() < 1.2e-5 && unit.e1234.abs() < 1.2e-5,
        "{unit:?}"
    );
    let l = Bivector {
        e12: 1.0,
        e13: 2.0,
        e14: 3.0,
        e23: 1.0,
        e24: -2.0,
        e34: 3.0,
    }
    .normalized_study();
    let unit = l * l.reverse();
    assert!(
        (unit.s - 1.0).abs() < 1.2e-5 && unit.e1234.abs() < 1.2e-5,
        "{unit:?}"
    );
    let pi = std::f32::consts::PI;
    let (roll, pitch, yaw) = Even::from_euler_angles(0.2 * pi, 0.2 * pi, 0.0).to_euler_angles();
    assert!((roll - 0.2 * pi).abs() < 1.2e-5 * pi && (pitch - 0.2 * pi).abs() < 1.2e-5 * pi);
    assert!(yaw.abs() < 1.2e-5, "{yaw}");
    let q = m / m;
    assert!(
        (q.s - 1.0).abs() < 1.2e-5 && q.e1234.abs() < 1.2e-5,
        "{q:?}"
    );
    assert_eq!((-m).constrained(), m);
}
