//! Norms, normalisation, inverses, `exp`, the blade test and factorisation at every
//! magnitude: components log-uniform over 1e-300..1e300 (`f64`) and 1e-38..1e38 (`f32`),
//! either one magnitude for all components or one per component (1e200 beside 1e-200),
//! for every type of G2, G3 and G4 in both precisions.
//!
//! The reference is the slow algebra of `tests/src/reference.rs` in `f64`, applied to the
//! input divided by the power of two nearest its largest component (exact), the result
//! then scaled back by that power. Errors are normwise (the Euclidean length of the error
//! over that of the exact result) and bounded per operation, in units of the algebra's
//! epsilon `u`, for `len` components:
//!
//! | operation | bound |
//! |---|---|
//! | `norm` | `(len/2 + 3) u` |
//! | `normalized`, `try_normalized` | `(len/2 + 4) u`, and always `Some` |
//! | `inverse`, closed form or well conditioned (`|A| |A^-1| <= 1e3`) | `4 len u |A| |A^-1|`, and always `Some` |
//! | `inverse`, ill-conditioned | `Some` only with a residual `|A X - 1| <= 64 len u |A| |X|` |
//! | `exp` | a unit rotor: `|R ~R - 1| <= 16 u`, at every size of `B` |
//! | `is_blade` (G4) | true for `M a ^ b`, false when `|B ^ B| >= |B|^2 / 4` |
//! | `factor` | the product of the factors is the blade to `1024 u` |
//!
//! Where a result falls below the smallest normal number (an `f32` inverse of a value
//! near 1e38) its last digits are gone by representation; the bound then adds a few
//! units of the subnormal spacing, `MIN_POSITIVE * u`.

use ga_tests::harness::run;
use ga_tests::Algebra;
use proptest::prelude::*;

/// Cases per type and operation.
const CASES: u32 = 192;

/// `len` components: log-uniform magnitudes in `10^lo..10^hi` with random signs, either
/// one magnitude times uniform factors in -1..1 (common) or one magnitude per component.
fn components(len: usize, lo: f64, hi: f64) -> impl Strategy<Value = Vec<f64>> {
    (
        lo..hi,
        prop::collection::vec((-1.0..1.0f64, lo..hi, any::<bool>()), len),
        any::<bool>(),
    )
        .prop_map(|(common, parts, shared)| {
            parts
                .into_iter()
                .map(|(factor, exponent, negative)| {
                    if shared {
                        factor * 10f64.powf(common)
                    } else {
                        let x = 10f64.powf(exponent);
                        if negative {
                            -x
                        } else {
                            x
                        }
                    }
                })
                .collect()
        })
}

/// The Euclidean length of a dense multivector.
fn length(x: &[f64]) -> f64 {
    x.iter().map(|c| c * c).sum::<f64>().sqrt()
}

/// The Euclidean length of `a - b`.
fn distance(a: &[f64], b: &[f64]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(x, y)| (x - y) * (x - y))
        .sum::<f64>()
        .sqrt()
}

/// `x` divided by the power of two `2^k` nearest below its largest component, and `2^k`:
/// both exact, so that the reference works on numbers near 1.
fn descale(x: &[f64]) -> (Vec<f64>, f64) {
    let largest = x.iter().fold(0.0f64, |m, c| m.max(c.abs()));
    if largest == 0.0 {
        return (x.to_vec(), 1.0);
    }
    let k = largest.log2().floor() as i32;
    // Two factors: 2^-k alone overflows for the smallest subnormal inputs.
    let (half, rest) = (k / 2, k - k / 2);
    let scaled = x
        .iter()
        .map(|c| c * 2f64.powi(-half) * 2f64.powi(-rest))
        .collect();
    (scaled, 2f64.powi(half) * 2f64.powi(rest))
}

macro_rules! magnitude_tests {
    (
        $module:ident, $path:path, $s:ident, dim = $dim:expr, lo = $lo:expr, hi = $hi:expr,
        types = [$($ty:ident),*], blade_test = $blade_test:expr $(,)?
    ) => {
        mod $module {
            use super::*;
            use $path::*;
            use ga_tests::embed::Embed;

            /// The algebra's epsilon.
            const U: f64 = $s::EPSILON as f64;
            /// The spacing of the subnormals.
            const TINY: f64 = ($s::MIN_POSITIVE as f64) * U;

            fn algebra() -> Algebra {
                Algebra::new(&[1; $dim])
            }

            #[test]
            fn norm_is_right_to_a_few_ulps_at_every_magnitude() {
                let algebra = algebra();
                $({
                    let len = <$ty>::ZERO.to_array().len();
                    run(CASES, &components(len, $lo, $hi), |x| {
                        let mut array = <$ty>::ZERO.to_array();
                        for (a, c) in array.iter_mut().zip(&x) {
                            *a = *c as $s;
                        }
                        let value = <$ty>::from_array(array);
                        let (scaled, power) = descale(&value.to_reference());
                        let expected = algebra.norm_squared(&scaled).abs().sqrt();
                        if expected * power > f64::from($s::MAX) {
                            // The norm itself is not representable (16 components of 1e38).
                            return Ok(());
                        }
                        let got = f64::from(value.norm()) / power;
                        let bound = (len as f64 / 2.0 + 3.0) * U * expected
                            + len as f64 * f64::EPSILON * expected
                            + 4.0 * TINY / power;
                        prop_assert!(
                            (got - expected).abs() <= bound,
                            "{}::norm of {:?}: {} * 2^k, expected {} (error {:e} > {:e})",
                            stringify!($ty), value, got, expected, (got - expected).abs(), bound
                        );
                        Ok(())
                    });
                })*
            }

            #[test]
            fn normalized_is_a_unit_value_at_every_magnitude() {
                let algebra = algebra();
                $({
                    let len = <$ty>::ZERO.to_array().len();
                    run(CASES, &components(len, $lo, $hi), |x| {
                        let mut array = <$ty>::ZERO.to_array();
                        for (a, c) in array.iter_mut().zip(&x) {
                            *a = *c as $s;
                        }
                        let value = <$ty>::from_array(array);
                        let (scaled, _) = descale(&value.to_reference());
                        let norm = algebra.norm_squared(&scaled).abs().sqrt();
                        let expected: Vec<f64> = scaled.iter().map(|c| c / norm).collect();
                        let got = value.normalized().to_reference();
                        let bound = (len as f64 / 2.0 + 4.0) * U + len as f64 * f64::EPSILON;
                        prop_assert!(
                            distance(&got, &expected) <= bound,
                            "{}::normalized of {:?} is {:?} (error {:e} > {:e})",
                            stringify!($ty), value, got, distance(&got, &expected), bound
                        );
                        let tried = value.try_normalized();
                        prop_assert!(
                            tried == Some(value.normalized()),
                            "{}::try_normalized of {:?} is {:?}",
                            stringify!($ty), value, tried
                        );
                        Ok(())
                    });
                })*
            }

            #[test]
            fn inverse_is_right_or_none_never_a_wrong_value_at_every_magnitude() {
                let algebra = algebra();
                $({
                    let len = <$ty>::ZERO.to_array().len();
                    run(CASES, &components(len, $lo, $hi), |x| {
                        let mut array = <$ty>::ZERO.to_array();
                        for (a, c) in array.iter_mut().zip(&x) {
                            *a = *c as $s;
                        }
                        let value = <$ty>::from_array(array);
                        let (scaled, power) = descale(&value.to_reference());
                        let got = value.inverse().map(|i| {
                            Multivector::from(i)
                                .to_reference()
                                .iter()
                                .map(|c| c * power)
                                .collect::<Vec<f64>>()
                        });
                        let exact = algebra.inverse(&scaled);
                        let condition = exact
                            .as_ref()
                            .map_or(f64::INFINITY, |e| length(&scaled) * length(e));
                        let representable = exact
                            .as_ref()
                            .is_some_and(|e| length(e) / power < f64::from($s::MAX) / 4.0);
                        if condition <= 1e3 && representable {
                            let exact = exact.unwrap_or_default();
                            let Some(got) = got else {
                                return Err(TestCaseError::fail(format!(
                                    "{}::inverse of the invertible {:?} is None",
                                    stringify!($ty), value
                                )));
                            };
                            let bound = 4.0 * len as f64 * U * condition * length(&exact)
                                + 8.0 * len as f64 * TINY * power;
                            prop_assert!(
                                distance(&got, &exact) <= bound,
                                "{}::inverse of {:?}: {:?} * 2^-k, expected {:?} (error {:e} > {:e})",
                                stringify!($ty), value, got, exact, distance(&got, &exact), bound
                            );
                        } else if let Some(got) = got {
                            let mut residual = algebra.geometric(&scaled, &got);
                            residual[0] -= 1.0;
                            let bound = 64.0 * len as f64 * U * length(&scaled) * length(&got);
                            prop_assert!(
                                length(&residual) <= bound,
                                "{}::inverse of {:?}: |A X - 1| = {:e} > {:e}",
                                stringify!($ty), value, length(&residual), bound
                            );
                        }
                        Ok(())
                    });
                })*
            }

            #[test]
            fn exp_of_a_bivector_of_any_size_is_a_unit_rotor() {
                let algebra = algebra();
                let len = Bivector::ZERO.to_array().len();
                run(CASES, &components(len, $lo, $hi), |x| {
                    let mut array = Bivector::ZERO.to_array();
                    for (a, c) in array.iter_mut().zip(&x) {
                        *a = *c as $s;
                    }
                    let b = Bivector::from_array(array);
                    let r = b.exp().to_reference();
                    let mut unit = algebra.geometric(&r, &algebra.reverse(&r));
                    unit[0] -= 1.0;
                    prop_assert!(
                        length(&unit) <= 16.0 * U,
                        "exp({:?}) = {:?}: |R ~R - 1| = {:e}",
                        b, r, length(&unit)
                    );
                    Ok(())
                });
            }

            #[test]
            fn blade_test_and_factor_mean_the_same_at_every_magnitude() {
                if !$blade_test {
                    return;
                }
                let algebra = algebra();
                let vector_blades = <Vector as Embed<Multivector>>::blades();
                let strategy = (
                    prop::collection::vec(-1.0..1.0f64, 4 * $dim),
                    // One decade below the top: a sum of two blades must stay finite.
                    $lo..$hi - 1.0,
                );
                run(CASES, &strategy, |(x, exponent)| {
                    let vector = |k: usize| {
                        algebra.from_components(vector_blades, &x[k * $dim..(k + 1) * $dim])
                    };
                    let magnitude = 10f64.powf(exponent);
                    let blade = algebra.outer(&vector(0), &vector(1));
                    let sum = algebra.add(&blade, &algebra.outer(&vector(2), &vector(3)));
                    let wedge = algebra.outer(&sum, &sum);
                    let at = |dense: &[f64]| {
                        let scaled: Vec<f64> = dense.iter().map(|c| c * magnitude).collect();
                        Bivector::from_reference(&scaled)
                    };
                    let value = at(&blade);
                    prop_assert!(value.is_blade(), "{:?} is a blade", value);
                    if length(&wedge) >= length(&sum).powi(2) / 4.0 {
                        prop_assert!(!at(&sum).is_blade(), "{:?} is not a blade", at(&sum));
                    }
                    let factors = value.factor();
                    let Some([a, b]) = factors else {
                        return Err(TestCaseError::fail(format!("{value:?} has no factors")));
                    };
                    let (target, power) = descale(&value.to_reference());
                    let a: Vec<f64> = a.to_reference().iter().map(|c| c / power).collect();
                    let product = algebra.geometric(&a, &b.to_reference());
                    prop_assert!(
                        distance(&product, &target) <= 1024.0 * U * length(&target),
                        "{:?} factors into {:?}",
                        value, factors
                    );
                    Ok(())
                });
            }
        }
    };
}

magnitude_tests!(
    g2_f64,
    ga_core::f64::g2,
    f64,
    dim = 2,
    lo = -300.0,
    hi = 300.0,
    types = [Vector, Bivector, Even, Odd, Multivector],
    blade_test = true
);
magnitude_tests!(
    g3_f64,
    ga_core::f64::g3,
    f64,
    dim = 3,
    lo = -300.0,
    hi = 300.0,
    types = [Vector, Bivector, Trivector, Even, Odd, Multivector],
    blade_test = true
);
magnitude_tests!(
    g4_f64,
    ga_core::f64::g4,
    f64,
    dim = 4,
    lo = -300.0,
    hi = 300.0,
    types = [
        Vector,
        Bivector,
        Trivector,
        Quadvector,
        Even,
        Odd,
        Multivector
    ],
    blade_test = true
);
magnitude_tests!(
    g2_f32,
    ga_core::f32::g2,
    f32,
    dim = 2,
    lo = -38.0,
    hi = 38.0,
    types = [Vector, Bivector, Even, Odd, Multivector],
    blade_test = true
);
magnitude_tests!(
    g3_f32,
    ga_core::f32::g3,
    f32,
    dim = 3,
    lo = -38.0,
    hi = 38.0,
    types = [Vector, Bivector, Trivector, Even, Odd, Multivector],
    blade_test = true
);
magnitude_tests!(
    g4_f32,
    ga_core::f32::g4,
    f32,
    dim = 4,
    lo = -38.0,
    hi = 38.0,
    types = [
        Vector,
        Bivector,
        Trivector,
        Quadvector,
        Even,
        Odd,
        Multivector
    ],
    blade_test = true
);

/// The norm's rescaling in a degenerate metric (PGA, `e4` null): only the components that
/// enter `<A ~A>_0` may decide the scale. Counting a null component would divide a norm
/// of 1e-200 by a null 1e300 and return 0; the reference is the norm of the non-null part,
/// descaled as above.
mod degenerate_metric {
    use super::*;
    use ga_tests::algebras::pga::*;
    use ga_tests::embed::Embed;

    const U: f64 = f64::EPSILON;
    /// `e4`'s bit: a blade holding it squares to 0.
    const NULL: usize = 1 << 3;

    /// `value`'s reference norm from its non-null components only, descaled.
    fn expected_norm(value: &[f64]) -> f64 {
        let algebra = Algebra::new(&[1, 1, 1, 0]);
        let non_null: Vec<f64> = value
            .iter()
            .enumerate()
            .map(|(blade, &c)| if blade & NULL == 0 { c } else { 0.0 })
            .collect();
        let (scaled, power) = descale(&non_null);
        algebra.norm_squared(&scaled).abs().sqrt() * power
    }

    macro_rules! pga_norms {
        ($($ty:ident),*) => {
            #[test]
            fn a_null_1e300_beside_1e_200_leaves_the_norm_1e_200() {
                $({
                    let blades = <$ty as Embed<Multivector>>::blades();
                    let mut array = <$ty>::ZERO.to_array();
                    let first = blades.iter().position(|&b| b & NULL == 0);
                    let null = blades.iter().position(|&b| b & NULL != 0);
                    if let (Some(first), Some(null)) = (first, null) {
                        array[first] = 1e-200;
                        array[null] = 1e300;
                        let value = <$ty>::from_array(array);
                        assert_eq!(value.norm(), 1e-200, "{}: {:?}", stringify!($ty), value);
                    }
                })*
            }

            #[test]
            fn norm_rescales_by_the_non_null_components_only_at_every_magnitude() {
                $({
                    let len = <$ty>::ZERO.to_array().len();
                    run(CASES, &components(len, -300.0, 300.0), |x| {
                        let value = <$ty>::from_array(::std::array::from_fn(|k| x[k]));
                        let expected = expected_norm(&value.to_reference());
                        if !expected.is_finite() {
                            return Ok(());
                        }
                        let got = value.norm();
                        let bound = (len as f64 / 2.0 + 3.0) * U * expected
                            + 4.0 * f64::MIN_POSITIVE * U;
                        prop_assert!(
                            (got - expected).abs() <= bound,
                            "{}::norm of {:?} is {:e}, expected {:e}",
                            stringify!($ty), value, got, expected
                        );
                        Ok(())
                    });
                })*
            }
        };
    }

    pga_norms!(
        Vector,
        Bivector,
        Trivector,
        Quadvector,
        Even,
        Odd,
        Multivector
    );
}
