//! Rotors, reflections, inverses and blades: `Bivector::exp`, `Even::log`,
//! `sandwich`, `reflect`, `inverse`, `Bivector::factor` and `is_blade`, checked
//! against the reference (Taylor-series `exp`, Gaussian-elimination `inverse`,
//! explicit `r x ~r` and `n x^ n^-1`).

use ga_tests::harness::{dense, run};
use ga_tests::Algebra;

/// The sum of the absolute values of the components.
fn l1(x: &[f64]) -> f64 {
    x.iter().map(|c| c.abs()).sum()
}

/// The reference `n x^ n^-1`, or `None` when `n` is too close to null to invert.
fn reflection(algebra: &Algebra, n: &[f64], x: &[f64]) -> Option<Vec<f64>> {
    let square = algebra.scalar_product(n, n);
    if square.abs() < 0.1 * l1(n).powi(2) / n.len() as f64 {
        return None;
    }
    let n_inverse = algebra.scale(n, 1.0 / square);
    let involuted = algebra.grade_involution(x);
    Some(algebra.geometric(&algebra.geometric(n, &involuted), &n_inverse))
}

macro_rules! push_sandwich {
    (($cases:ident), Scalar) => {};
    (($cases:ident), $ty:ident) => {
        $cases.push((stringify!($ty), |r: Even, v: Vector, x: &[f64]| {
            let value = <$ty as Embed<Multivector>>::from_reference(x);
            let by_rotor: $ty = r.sandwich(value);
            let by_vector: $ty = v.sandwich(value);
            [
                <$ty as Embed<Multivector>>::to_reference(value),
                <$ty as Embed<Multivector>>::to_reference(by_rotor),
                <$ty as Embed<Multivector>>::to_reference(by_vector),
                vec![
                    value.norm_squared(),
                    by_rotor.norm_squared(),
                    by_vector.norm_squared(),
                ],
            ]
        }));
    };
}

macro_rules! push_reflect {
    (($cases:ident), Scalar) => {};
    (($cases:ident), $ty:ident) => {
        $cases.push((stringify!($ty), |n: Vector, x: &[f64]| {
            let value = <$ty as Embed<Multivector>>::from_reference(x);
            [
                <$ty as Embed<Multivector>>::to_reference(value),
                ga_tests::dense!(value.reflect(n)),
            ]
        }));
    };
}

macro_rules! push_inverse {
    (($cases:ident), Scalar) => {};
    (($cases:ident), $ty:ident) => {
        $cases.push((stringify!($ty), |x: &[f64]| {
            let value = <$ty as Embed<Multivector>>::from_reference(x);
            let inverse = value.inverse().map(|inverse| ga_tests::dense!(inverse));
            (<$ty as Embed<Multivector>>::to_reference(value), inverse)
        }));
    };
}

macro_rules! for_types {
    ($callback:ident!$args:tt; [$($ty:ident),* $(,)?]) => {
        $( $callback!($args, $ty); )*
    };
}

/// `Trivector::factor` needs a trivector: not in G2.
macro_rules! trivector_factor {
    (2) => {};
    ($dim:tt) => {
        /// u^v^w factors into three orthogonal vectors whose product is the blade.
        #[test]
        fn trivector_factors_into_orthogonal_vectors_whose_product_is_the_blade() {
            run(64, &(dense(SIZE), dense(SIZE), dense(SIZE)), |(x, y, z)| {
                let blade = vector(&x) ^ vector(&y) ^ vector(&z);
                let factors = blade.factor();
                prop_assert!(factors.is_some(), "{blade:?} has no factors");
                let [a, b, c] = factors.unwrap();
                let norms = [a, b, c].map(|v| l1(&dense!(v)));
                let scale = norms[0] * norms[1] * norms[2];
                prop_assert_close!(
                    dense!(a * b * c),
                    dense!(blade),
                    scale = scale,
                    rel = 1e-12,
                    "abc = blade"
                );
                prop_assert_close!(
                    dense!(a ^ b ^ c),
                    dense!(blade),
                    scale = scale,
                    rel = 1e-12,
                    "a^b^c = blade"
                );
                for (p, q, pq) in [
                    (a, b, norms[0] * norms[1]),
                    (a, c, norms[0] * norms[2]),
                    (b, c, norms[1] * norms[2]),
                ] {
                    prop_assert_close!(p | q, 0.0, scale = pq, rel = 1e-12, "{p:?} . {q:?}");
                }
                Ok(())
            });
        }
    };
}

macro_rules! versor_tests {
    (
        $alg:ident, $($path:ident)::+,
        dim = $dim:tt,
        metric = $metric:tt,
        types = $types:tt,
        $($rest:tt)*
    ) => {
        mod $alg {
            use super::{dense, l1, reflection, run, Algebra};
            use ga_tests::embed::Embed;
            use ga_tests::{dense, prop_assert_close};
            use proptest::prelude::*;
            #[allow(clippy::wildcard_imports)] // every generated type is needed
            use $($path)::+::*;

            const SIZE: usize = 1 << $dim;

            fn algebra() -> Algebra {
                Algebra::new(&$metric)
            }

            fn vector(x: &[f64]) -> Vector {
                <Vector as Embed<Multivector>>::from_reference(x)
            }

            /// A bivector with components in -2..2.
            fn bivector(x: &[f64]) -> Bivector {
                let small: Vec<f64> = x.iter().map(|c| c * 0.2).collect();
                <Bivector as Embed<Multivector>>::from_reference(&small)
            }

            /// exp(B) ~exp(B) = 1, and exp(B) is the Taylor series of exp.
            #[test]
            fn bivector_exp_is_a_unit_rotor_equal_to_the_taylor_series() {
                let algebra = algebra();
                run(64, &dense(SIZE), |x| {
                    let b = bivector(&x);
                    let r: Even = b.exp();
                    let rotor = dense!(r);
                    let one = algebra.scalar(1.0);
                    prop_assert_close!(
                        dense!(r * r.reverse()),
                        one,
                        scale = l1(&rotor).powi(2),
                        rel = 1e-12,
                        "R ~R",
                    );
                    let taylor = algebra.exp(&dense!(b));
                    prop_assert_close!(
                        rotor,
                        taylor,
                        scale = l1(&taylor).max(1.0),
                        rel = 1e-12,
                        "exp({b:?})",
                    );
                    Ok(())
                });
            }

            /// r x ~r with r = exp(B) keeps x's type (checked by the compiler), equals
            /// the reference product, and keeps <x ~x>_0; likewise v x^ ~v for a unit
            /// vector v.
            #[test]
            fn sandwich_keeps_grade_and_norm() {
                type Sandwich = fn(Even, Vector, &[f64]) -> [Vec<f64>; 4];
                let algebra = algebra();
                let mut cases: Vec<(&str, Sandwich)> = Vec::new();
                for_types!(push_sandwich!(cases); $types);
                run(64, &(dense(SIZE), dense(SIZE), dense(SIZE)), |(x, y, z)| {
                    let r = bivector(&x).exp();
                    let rotor = dense!(r);
                    let v = vector(&y);
                    let square = dense!(v * v)[0];
                    if square.abs() < 0.1 * l1(&dense!(v)).powi(2) / $dim as f64 {
                        return Ok(());
                    }
                    let v = v * (1.0 / square.abs().sqrt());
                    let unit = dense!(v);
                    for (name, case) in &cases {
                        let [value, by_rotor, by_vector, norms] = case(r, v, &z);
                        let turned = algebra.geometric(&rotor, &value);
                        let expected = algebra.geometric(&turned, &algebra.reverse(&rotor));
                        let scale = l1(&rotor).powi(2) * l1(&value);
                        prop_assert_close!(
                            by_rotor,
                            expected,
                            scale = scale,
                            rel = 1e-12,
                            "R {name} ~R",
                        );
                        prop_assert_close!(
                            norms[1],
                            norms[0],
                            scale = scale.powi(2),
                            rel = 1e-12,
                            "|R {name} ~R|^2",
                        );
                        let involuted = algebra.grade_involution(&value);
                        let reflected = algebra.geometric(&unit, &involuted);
                        let expected = algebra.geometric(&reflected, &algebra.reverse(&unit));
                        let scale = l1(&unit).powi(2) * l1(&value);
                        prop_assert_close!(
                            by_vector,
                            expected,
                            scale = scale,
                            rel = 1e-12,
                            "v {name}^ ~v",
                        );
                        prop_assert_close!(
                            norms[2],
                            norms[0],
                            scale = scale.powi(2),
                            rel = 1e-12,
                            "|v {name}^ ~v|^2",
                        );
                    }
                    Ok(())
                });
            }

            /// x.reflect(n) = n x^ n^-1: -n x n^-1 for a vector, (-1)^k n x n^-1 for grade k.
            #[test]
            fn reflect_is_n_times_the_grade_involution_times_n_inverse() {
                type Reflect = fn(Vector, &[f64]) -> [Vec<f64>; 2];
                let algebra = algebra();
                let mut cases: Vec<(&str, Reflect)> = Vec::new();
                for_types!(push_reflect!(cases); $types);
                run(64, &(dense(SIZE), dense(SIZE)), |(x, y)| {
                    let n = vector(&x);
                    let normal = dense!(n);
                    for (name, case) in &cases {
                        let [value, got] = case(n, &y);
                        if let Some(expected) = reflection(&algebra, &normal, &value) {
                            let scale = l1(&expected).max(l1(&value));
                            prop_assert_close!(
                                got,
                                expected,
                                scale = scale,
                                rel = 1e-12,
                                "{name}.reflect({n:?})",
                            );
                        }
                    }
                    Ok(())
                });
            }

            /// x x^-1 = x^-1 x = 1 whenever the reference can invert x, and a generated
            /// inverse always multiplies to one.
            #[test]
            fn inverse_multiplies_to_one_whenever_the_value_is_invertible() {
                type Inverse = fn(&[f64]) -> (Vec<f64>, Option<Vec<f64>>);
                let algebra = algebra();
                let mut cases: Vec<(&str, Inverse)> = Vec::new();
                for_types!(push_inverse!(cases); $types);
                run(64, &dense(SIZE), |x| {
                    for (name, case) in &cases {
                        let (value, inverse) = case(&x);
                        let expected = algebra.inverse(&value);
                        prop_assert!(
                            expected.is_none() || inverse.is_some(),
                            "{name} {value:?} is invertible but inverse() is None"
                        );
                        if let Some(inverse) = inverse {
                            let one = algebra.scalar(1.0);
                            let scale = l1(&value) * l1(&inverse);
                            prop_assert_close!(
                                algebra.geometric(&value, &inverse),
                                one,
                                scale = scale,
                                rel = 1e-12,
                                "{name} x x^-1",
                            );
                            prop_assert_close!(
                                algebra.geometric(&inverse, &value),
                                one,
                                scale = scale,
                                rel = 1e-12,
                                "{name} x^-1 x",
                            );
                        }
                    }
                    Ok(())
                });
            }

            #[test]
            fn zero_has_no_inverse() {
                assert!(Vector::ZERO.inverse().is_none());
                assert!(Bivector::ZERO.inverse().is_none());
                assert!(Even::ZERO.inverse().is_none());
                assert!(Multivector::ZERO.inverse().is_none());
            }

            /// u^v factors into orthogonal a, b with ab = a^b = u^v.
            #[test]
            fn bivector_blade_factors_into_orthogonal_vectors_whose_product_is_the_blade() {
                run(64, &(dense(SIZE), dense(SIZE)), |(x, y)| {
                    let blade = vector(&x) ^ vector(&y);
                    prop_assert!(blade.is_blade(), "{blade:?} is u^v");
                    let factors = blade.factor();
                    prop_assert!(factors.is_some(), "{blade:?} has no factors");
                    let [a, b] = factors.unwrap();
                    let scale = l1(&dense!(a)) * l1(&dense!(b));
                    prop_assert_close!(
                        dense!(a * b),
                        dense!(blade),
                        scale = scale,
                        rel = 1e-12,
                        "ab = blade",
                    );
                    prop_assert_close!(
                        dense!(a ^ b),
                        dense!(blade),
                        scale = scale,
                        rel = 1e-12,
                        "a^b = blade",
                    );
                    prop_assert_close!(a | b, 0.0, scale = scale, rel = 1e-12, "a . b = 0");
                    Ok(())
                });
            }

            trivector_factor!($dim);
        }
    };
}

ga_tests::for_each_algebra!(versor_tests);

/// The algebras where a bivector need not be a blade.
mod non_blades {
    #[test]
    fn e12_plus_e34_is_not_a_blade() {
        use ga_core::f64::g4::Bivector as G4;
        use ga_tests::algebras::{
            cga::Bivector as Cga, pga::Bivector as Pga, sta::Bivector as Sta,
        };
        assert!(!(G4::E12 + G4::E34).is_blade());
        assert!((G4::E12 + G4::E13).is_blade());
        assert!(!(Sta::E12 + Sta::E34).is_blade());
        assert!(!(Pga::E12 + Pga::E34).is_blade());
        assert!(!(Cga::E12 + Cga::E34).is_blade());
        assert!((G4::E12 + G4::E34).factor().is_none());
    }

    #[test]
    fn every_g3_bivector_is_a_blade() {
        use ga_core::f64::g3::Bivector;
        assert!((Bivector::E12 + Bivector::E13 * 2.0 - Bivector::E23 * 3.0).is_blade());
    }
}

/// Null vectors square to zero and have no inverse.
mod null_vectors {
    #[test]
    fn pga_degenerate_generator_has_no_inverse() {
        use ga_tests::algebras::pga::Vector;
        assert_eq!(Vector::E4 | Vector::E4, 0.0);
        assert!(Vector::E4.inverse().is_none());
        assert!((Vector::E4 * 3.0).inverse().is_none());
        assert!(Vector::E1.inverse().is_some());
    }

    #[test]
    fn cga_null_vector_e4_plus_e5_has_no_inverse() {
        use ga_tests::algebras::cga::Vector;
        let null = Vector::E4 + Vector::E5;
        assert_eq!(null | null, 0.0);
        assert!(null.inverse().is_none());
    }
}

/// exp and log of G2, G3 and G4 rotors: tiny and huge angles, and the principal
/// logarithm.
macro_rules! rotor_tests {
    ($alg:ident, $($path:ident)::+, dim = $dim:tt) => {
        mod $alg {
            use super::{l1, run, Algebra};
            use ga_tests::embed::Embed;
            use ga_tests::harness::dense;
            use ga_tests::{dense, prop_assert_close};
                        #[allow(clippy::wildcard_imports)] // every generated type is needed
            use $($path)::+::*;

            const SIZE: usize = 1 << $dim;

            fn algebra() -> Algebra {
                Algebra::new(&[1; $dim])
            }

            /// `x`'s bivector part scaled to Euclidean norm `magnitude`.
            fn bivector_of_norm(x: &[f64], magnitude: f64) -> Bivector {
                let b = <Bivector as Embed<Multivector>>::from_reference(x);
                let norm = b.norm();
                b * (magnitude / norm)
            }

            /// The two angles `a >= b >= 0` of a Euclidean bivector B = a P + b Q, from
            /// B^2 = -(a^2 + b^2) +- 2ab e1234 (zero in G2 and G3).
            fn angles(b: Bivector) -> (f64, f64) {
                let algebra = algebra();
                let square = algebra.geometric(&dense!(b), &dense!(b));
                let sum = -square[0];
                let product = square[SIZE - 1].abs();
                let plus = (sum + product).max(0.0).sqrt();
                let minus = (sum - product).max(0.0).sqrt();
                ((plus + minus) / 2.0, (plus - minus) / 2.0)
            }

            /// exp(B) ~exp(B) = 1 and exp(B) matches the Taylor series for |B| = 1e-9 and 30.
            #[test]
            fn bivector_exp_is_a_unit_rotor_for_tiny_and_huge_angles() {
                let algebra = algebra();
                run(64, &dense(SIZE), |x| {
                    for magnitude in [1e-9, 30.0] {
                        let b = bivector_of_norm(&x, magnitude);
                        let r: Even = b.exp();
                        let rotor = dense!(r);
                        let one = algebra.scalar(1.0);
                        prop_assert_close!(
                            dense!(r * r.reverse()),
                            one,
                            scale = l1(&rotor).powi(2),
                            rel = 1e-12,
                            "R ~R, |B| = {magnitude}",
                        );
                        let taylor = algebra.exp(&dense!(b));
                        prop_assert_close!(rotor, taylor, scale = 1.0, rel = 1e-12, "exp({b:?})");
                        let planes = dense!(r.grade2());
                        let scale = l1(&dense!(b));
                        prop_assert_close!(
                            planes,
                            algebra.grade(&taylor, 2),
                            scale = scale,
                            rel = 1e-12,
                            "<exp({b:?})>_2",
                        );
                    }
                    Ok(())
                });
            }

            /// log(exp(B)) = B on the principal range: B = a P + b Q (P, Q orthogonal unit
            /// planes) with |a| + |b| < pi. In G2 and G3, b = 0 and that is |a| < pi. In G4
            /// the bound is on the sum, not on each angle: exp((a + pi) P + (b + pi) Q) =
            /// (-exp(aP)) (-exp(bQ)) = exp(aP + bQ), so two bivectors with both angles
            /// below pi can have the same exponential (for example a, b = -2.16, -2.41 and
            /// 0.98, 0.73), and |a| + |b| < pi picks one of them.
            #[test]
            fn even_log_inverts_exp_on_the_principal_range() {
                run(256, &(dense(SIZE), 1e-6..3.1f64), |(x, angle_sum)| {
                    let direction = bivector_of_norm(&x, 1.0);
                    let (first, second) = angles(direction);
                    let b = direction * (angle_sum / (first + second));
                    let back: Bivector = b.exp().log().expect("exp gives a unit rotor");
                    let scale = l1(&dense!(b));
                    prop_assert_close!(
                        dense!(back),
                        dense!(b),
                        scale = scale,
                        rel = 1e-12,
                        "log(exp({b:?})), angles {:?}",
                        angles(b),
                    );
                    Ok(())
                });
            }
        }
    };
}

mod rotors {
    use super::{l1, run, Algebra};
    rotor_tests!(g2, ga_core::f64::g2, dim = 2);
    rotor_tests!(g3, ga_core::f64::g3, dim = 3);
    rotor_tests!(g4, ga_core::f64::g4, dim = 4);
}
