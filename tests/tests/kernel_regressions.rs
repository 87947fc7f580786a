//! The cases of the kernels found wrong at extreme magnitudes (each failed before the
//! kernels scaled before squaring): inverses that came back as `Some(0)` or `None`,
//! normalisation that gave inf/NaN or a vector off unit length, `exp` that gave NaN or lost
//! unit norm in the isoclinic case, and a blade test that accepted `e12 + e34`.

use ga_core::f64::{g3, g4};

/// The largest component of `x`'s distance from `y`.
fn off(x: &[f64], y: &[f64]) -> f64 {
    x.iter()
        .zip(y)
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max)
}

const U: f64 = f64::EPSILON;

#[test]
fn inverse_of_vector_bivector_and_even_is_right_at_1e160_and_1e300() {
    for scale in [1e160, 1e300, 1e-160, 1e-300] {
        let v = g3::Vector::new(1.0, 2.0, -0.5) * scale;
        let inverse = v.inverse().expect("an invertible vector");
        assert!(
            off(&(v * inverse).to_array(), &g3::Even::ONE.to_array()) <= 4.0 * U,
            "{v:?}"
        );
        let b = g3::Bivector::new(1.0, 2.0, -0.5) * scale;
        let inverse = b.inverse().expect("an invertible bivector");
        assert!(
            off(&(b * inverse).to_array(), &g3::Even::ONE.to_array()) <= 4.0 * U,
            "{b:?}"
        );
        let r = g3::Even::new(0.3, 1.0, 2.0, -0.5) * scale;
        let inverse = r.inverse().expect("an invertible even value");
        assert!(
            off(&(r * inverse).to_array(), &g3::Even::ONE.to_array()) <= 4.0 * U,
            "{r:?}"
        );
    }
}

#[test]
fn inverse_with_components_1e200_and_1e_200_is_right() {
    let v = g3::Vector::new(1e200, 1e-200, -1e200);
    let inverse = v.inverse().expect("an invertible vector");
    assert!(off(&(v * inverse).to_array(), &g3::Even::ONE.to_array()) <= 4.0 * U);
    let r = g3::Even::new(1e-200, 1e200, 0.0, 1e200);
    let inverse = r.inverse().expect("an invertible even value");
    assert!(off(&(r * inverse).to_array(), &g3::Even::ONE.to_array()) <= 4.0 * U);
}

#[test]
fn f32_inverse_is_right_at_1e20_and_1e_20() {
    use ga_core::f32::g3 as g;
    for scale in [1e20f32, 1e30, 1e-20, 1e-30] {
        let v = g::Vector::new(1.0, 2.0, -0.5) * scale;
        let inverse = v.inverse().expect("an invertible vector");
        let residual = (v * inverse - g::Even::ONE).norm();
        assert!(residual <= 4.0 * f32::EPSILON, "{v:?}: {residual}");
    }
}

#[test]
fn normalized_is_unit_for_tiny_and_huge_vectors() {
    assert_eq!(
        g3::Vector::new(1e-300, 0.0, 0.0).normalized(),
        g3::Vector::E1
    );
    let v = g3::Vector::new(3e-160, 0.0, 0.0).normalized();
    assert!((v.e1 - 1.0).abs() <= U, "{v:?}");
    assert_eq!(
        g3::Vector::new(1e160, 0.0, 0.0).try_normalized(),
        Some(g3::Vector::E1)
    );
    assert_eq!(g3::Vector::new(1e160, 0.0, 0.0).norm(), 1e160);
    assert_eq!(g3::Vector::new(1e-300, 0.0, 0.0).norm(), 1e-300);
}

#[test]
fn exp_of_a_huge_bivector_is_a_unit_rotor() {
    for scale in [1e160, 1e300] {
        let r = (g3::Bivector::new(1.0, 2.0, -0.5) * scale).exp();
        assert!((r.norm() - 1.0).abs() <= 4.0 * U, "{r:?}");
    }
    let r = (ga_core::f32::g3::Bivector::new(1.0, 2.0, -0.5) * 1e20).exp();
    assert!((r.norm() - 1.0).abs() <= 4.0 * f32::EPSILON, "{r:?}");
}

#[test]
fn g4_isoclinic_exp_stays_unit_at_large_angles() {
    for angle in [1e12, 1e16, 1e160] {
        let isoclinic = g4::Bivector::new(angle, 0.0, 0.0, 0.0, 0.0, angle).exp();
        let other = g4::Bivector::new(angle, 0.0, 0.0, 0.0, 0.0, 0.5 * angle).exp();
        for r in [isoclinic, other] {
            let unit = r * r.reverse() - g4::Even::ONE;
            assert!(unit.norm() <= 8.0 * U, "{angle}: {r:?}");
        }
    }
}

#[test]
fn blade_test_rejects_e12_plus_e34_at_every_magnitude() {
    for scale in [1e-300, 1e-160, 1.0, 1e160, 1e300] {
        let b = g4::Bivector::new(1.0, 0.0, 0.0, 0.0, 0.0, 1.0) * scale;
        assert!(!b.is_blade(), "{b:?}");
        let blade = g4::Bivector::new(1.0, 2.0, 0.0, 0.0, 0.0, 0.0) * scale;
        assert!(blade.is_blade(), "{blade:?}");
    }
}
