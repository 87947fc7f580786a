//! The sandwich's matrix form and its slice form compute the same map as the sandwich.

use ga_core::f32::g3 as s3;
use ga_core::f32::g3::Sandwich as _;
use ga_core::f64::g3::*;
use ga_core::f64::g4;
use ga_core::f64::g4::Sandwich as _;

#[test]
fn rotor_matrix_and_slice_forms_equal_the_sandwich() {
    let mut vectors: Vec<Vector> = (0..50)
        .map(|i| {
            let t = f64::from(i);
            Vector::new(t.sin(), (1.7 * t).cos(), 0.3 * t - 2.0)
        })
        .collect();
    let rotor = Bivector::new(0.4, -1.1, 0.7).exp();
    let expected: Vec<Vector> = vectors.iter().map(|&v| rotor.sandwich(v)).collect();
    let m = rotor.sandwich_matrix();
    for (v, e) in vectors.iter().zip(&expected) {
        let by_matrix = Vector::new(
            m[0][0] * v.e1 + m[0][1] * v.e2 + m[0][2] * v.e3,
            m[1][0] * v.e1 + m[1][1] * v.e2 + m[1][2] * v.e3,
            m[2][0] * v.e1 + m[2][1] * v.e2 + m[2][2] * v.e3,
        );
        assert!((by_matrix - *e).norm() < 1e-14, "{by_matrix:?} vs {e:?}");
    }
    rotor.sandwich_vectors(&mut vectors);
    for (v, e) in vectors.iter().zip(&expected) {
        assert!((*v - *e).norm() < 1e-14);
    }
}

#[test]
fn the_matrix_of_a_unit_rotor_is_a_rotation() {
    let m = Bivector::new(2.0, 0.5, -0.3).exp().sandwich_matrix();
    for i in 0..3 {
        for j in 0..3 {
            let dot: f64 = (0..3).map(|k| m[k][i] * m[k][j]).sum();
            assert!((dot - f64::from(u8::from(i == j))).abs() < 1e-14);
        }
    }
    let det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
        - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
        + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
    assert!((det - 1.0).abs() < 1e-14);
}

#[test]
fn odd_versors_and_other_algebras_have_the_same_forms() {
    let n = Vector::new(0.3, -0.4, 1.2).normalized();
    let mut xs = [Vector::E1, Vector::E2, Vector::new(1.0, 2.0, 3.0)];
    let expected = xs.map(|x| n.sandwich(x));
    n.sandwich_vectors(&mut xs);
    for (x, e) in xs.iter().zip(&expected) {
        assert!((*x - *e).norm() < 1e-14);
    }
    let r4 = g4::Bivector::new(0.1, 0.2, 0.3, -0.4, 0.5, 0.6).exp();
    let mut ys = [g4::Vector::new(1.0, -1.0, 0.5, 2.0)];
    let expected4 = r4.sandwich(ys[0]);
    r4.sandwich_vectors(&mut ys);
    assert!((ys[0] - expected4).norm() < 1e-14);
    let r32 = s3::Bivector::new(0.4, -1.1, 0.7).exp();
    let mut zs = [s3::Vector::new(1.0, 2.0, 3.0)];
    let expected32 = r32.sandwich(zs[0]);
    r32.sandwich_vectors(&mut zs);
    assert!((zs[0] - expected32).norm() < 1e-6);
}
