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

/// `exp` of a bivector holding a NaN must not read as a rotor: every component is NaN,
/// except where the NaN sits in a null component (PGA's `e_i4`), which enters no square:
/// there the components it reaches are NaN. Before, G2, G3 and G4 returned `s = 1`
/// exactly (the identity's scalar), as `cosh_sinhc` took a NaN square for zero.
macro_rules! exp_of_nan {
    ($test:ident, $path:path, $s:ident, metric = $metric:expr) => {
        #[test]
        fn $test() {
            use ga_tests::embed::Embed;
            use $path as alg;
            let metric: &[i8] = &$metric;
            let blades = <alg::Bivector as Embed<alg::Multivector>>::blades();
            let len = blades.len();
            for k in 0..len {
                let mut array = alg::Bivector::ZERO.to_array();
                for (i, c) in array.iter_mut().enumerate() {
                    *c = 0.25 + 0.5 * i as $s;
                }
                array[k] = $s::NAN;
                let b = alg::Bivector::from_array(array);
                let r = b.exp().to_array();
                let null =
                    (0..metric.len()).any(|bit| blades[k] & (1 << bit) != 0 && metric[bit] == 0);
                if null {
                    assert!(r.iter().any(|c| c.is_nan()), "exp({b:?}) = {r:?}");
                } else {
                    assert!(r.iter().all(|c| c.is_nan()), "exp({b:?}) = {r:?}");
                }
            }
        }
    };
}

exp_of_nan!(g2_exp_of_nan_is_nan, ga_core::f64::g2, f64, metric = [1, 1]);
exp_of_nan!(
    g3_exp_of_nan_is_nan,
    ga_core::f64::g3,
    f64,
    metric = [1, 1, 1]
);
exp_of_nan!(
    g4_exp_of_nan_is_nan,
    ga_core::f64::g4,
    f64,
    metric = [1, 1, 1, 1]
);
exp_of_nan!(
    f32_g2_exp_of_nan_is_nan,
    ga_core::f32::g2,
    f32,
    metric = [1, 1]
);
exp_of_nan!(
    f32_g3_exp_of_nan_is_nan,
    ga_core::f32::g3,
    f32,
    metric = [1, 1, 1]
);
exp_of_nan!(
    f32_g4_exp_of_nan_is_nan,
    ga_core::f32::g4,
    f32,
    metric = [1, 1, 1, 1]
);
exp_of_nan!(
    sta_exp_of_nan_is_nan,
    ga_tests::algebras::sta,
    f64,
    metric = [1, -1, -1, -1]
);
exp_of_nan!(
    pga_exp_of_nan_is_nan,
    ga_tests::algebras::pga,
    f64,
    metric = [1, 1, 1, 0]
);
exp_of_nan!(
    cga_exp_of_nan_is_nan,
    ga_tests::algebras::cga,
    f64,
    metric = [1, 1, 1, 1, -1]
);

/// The G3 multivector of issue 22, `1 + 0.6 e1 + 0.8 e2` rounded (condition number about
/// 1e15): its inverse came back with a relative error of 1e-2 and an `e12` of -5e12. Now
/// `None`, or right to the documented 2^-26 against a double-double inverse.
#[test]
fn inverse_of_a_nearly_singular_g3_multivector_is_none_or_right() {
    let array = [
        1.0,
        0.5999999999999994,
        0.7999999999999993,
        0.0,
        0.0,
        0.0,
        0.0,
        0.0,
    ];
    let a = g3::Multivector::from_array(array);
    if let Some(x) = a.inverse() {
        use ga_tests::embed::Embed;
        let algebra = ga_tests::Algebra::new(&[1, 1, 1]);
        let (exact, _) = ga_tests::double_double::inverse(&algebra, &a.to_reference())
            .expect("an inverse was returned, so the input is invertible");
        let got = x.to_reference();
        let error: f64 = got.iter().zip(&exact).map(|(x, y)| (x - y).abs()).sum();
        let size: f64 = exact.iter().map(|y| y.abs()).sum();
        assert!(error <= 2f64.powi(-26) * size, "{x:?} against {exact:?}");
    }
}

/// `sandwich_unit`'s documented range: for a unit rotor of G2 or G3 every intermediate of
/// a grade part of `x` is at most `sqrt 2` times that part's Euclidean norm, so it is
/// finite (and agrees with `sandwich`) whenever each part's norm is at most
/// `MAX / sqrt 2`. The values here give every part a norm of up to `0.95 MAX / sqrt 2`
/// (components up to `0.95 MAX / sqrt 6`), a third of them with nearly a half turn.
/// Random values rarely line up for the worst case; the half-turn tests below do, and
/// fail on the form that doubled `C(C(x))` (whose documented range ended at `MAX / 16`).
macro_rules! sandwich_unit_range {
    ($test:ident, $path:path, $s:ident, [$($x:ident),*]) => {
        #[test]
        fn $test() {
            use $path as alg;
            use alg::{Sandwich as _, SandwichUnit as _};
            let mut rng = ga_test_rng::Rng::new(0x2545_f491_4f6c_dd1d);
            let mut next = move || rng.next_f64();
            // No grade part has more than three components in G2 or G3.
            let largest = $s::MAX * 0.95 / 6.0_f64.sqrt() as $s;
            for _ in 0..2000 {
                let mut rotor = alg::Even::ZERO.to_array();
                for c in rotor.iter_mut() {
                    *c = (2.0 * next() - 1.0) as $s;
                }
                // A third of the rotors are within a few degrees of a half turn, where
                // `C(C(x))` is largest.
                if next() < 0.33 {
                    rotor[0] *= 0.03;
                }
                let r = alg::Even::from_array(rotor).normalized();
                $({
                    let mut array = alg::$x::ZERO.to_array();
                    for c in array.iter_mut() {
                        let size = largest * (0.25 + 0.75 * next() as $s);
                        *c = if next() < 0.5 { -size } else { size };
                    }
                    let x = alg::$x::from_array(array);
                    let unit = r.sandwich_unit(x).to_array();
                    let exact = r.sandwich(x).to_array();
                    assert!(
                        unit.iter().all(|c| c.is_finite()),
                        "{r:?}.sandwich_unit({x:?}) = {unit:?}"
                    );
                    for (u, e) in unit.iter().zip(exact) {
                        assert!(
                            (u - e).abs() <= 64.0 * $s::EPSILON * largest,
                            "{r:?}.sandwich_unit({x:?}) = {unit:?}, sandwich {exact:?}"
                        );
                    }
                })*
            }
        }
    };
}

/// The case of issue 22: a vector of norm near `MAX / sqrt 2` (1e308 in `f64`) turned by
/// nearly half a turn in its own plane, where `2 C(C(x))` is nearly `-2x`. Checked
/// against the rotation written with cosine and sine, not against another sandwich.
macro_rules! sandwich_unit_half_turn {
    ($test:ident, $path:path, $s:ident, $size:expr) => {
        #[test]
        fn $test() {
            use alg::SandwichUnit as _;
            use $path as alg;
            let size: $s = $size;
            for step in 0..=64 {
                // Angles from 170 to 180 degrees, and the plane e12 so that x = e1 turns
                // toward e2.
                let angle = core::f64::consts::PI * (1.0 - step as f64 / 1152.0);
                let (sin, cos) = (0.5 * angle).sin_cos();
                let mut rotor = alg::Even::ZERO.to_array();
                rotor[0] = cos as $s;
                rotor[1] = -sin as $s;
                let r = alg::Even::from_array(rotor);
                for direction in [1.0_f64, -1.0] {
                    let mut x = alg::Vector::ZERO.to_array();
                    x[0] = direction as $s * size;
                    let y = r.sandwich_unit(alg::Vector::from_array(x)).to_array();
                    let expected = [
                        direction * size as f64 * angle.cos(),
                        direction * size as f64 * angle.sin(),
                    ];
                    for k in 0..2 {
                        assert!(
                            y[k].is_finite()
                                && (y[k] as f64 - expected[k]).abs()
                                    <= 16.0 * $s::EPSILON as f64 * size as f64,
                            "a turn by {angle} of {x:?} gave {y:?}, expected {expected:?}"
                        );
                    }
                }
            }
        }
    };
}

sandwich_unit_half_turn!(g2_half_turn_of_1e308, ga_core::f64::g2, f64, 1e308);
sandwich_unit_half_turn!(g3_half_turn_of_1e308, ga_core::f64::g3, f64, 1e308);
sandwich_unit_half_turn!(
    f32_g3_half_turn_near_max_over_sqrt_2,
    ga_core::f32::g3,
    f32,
    2.3e38
);

sandwich_unit_range!(
    g2_sandwich_unit_is_finite_up_to_max_over_sqrt_2,
    ga_core::f64::g2,
    f64,
    [Vector, Bivector, Even, Odd, Multivector]
);
sandwich_unit_range!(
    g3_sandwich_unit_is_finite_up_to_max_over_sqrt_2,
    ga_core::f64::g3,
    f64,
    [Vector, Bivector, Trivector, Even, Odd, Multivector]
);
sandwich_unit_range!(
    f32_g2_sandwich_unit_is_finite_up_to_max_over_sqrt_2,
    ga_core::f32::g2,
    f32,
    [Vector, Bivector, Even, Odd, Multivector]
);
sandwich_unit_range!(
    f32_g3_sandwich_unit_is_finite_up_to_max_over_sqrt_2,
    ga_core::f32::g3,
    f32,
    [Vector, Bivector, Trivector, Even, Odd, Multivector]
);
