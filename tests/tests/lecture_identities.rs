//! The identities of the lecture ("Physical applications of geometric algebra",
//! lecture 3: the axioms, and the inner and outer products built from the
//! geometric one), checked on the generated operators in all six algebras.

use ga_tests::blade::grades_of_type;
use ga_tests::harness::{dense, run};
use ga_tests::Algebra;

/// The sum of the absolute values of the components.
fn l1(x: &[f64]) -> f64 {
    x.iter().map(|c| c.abs()).sum()
}

/// One generated product of a pair of homogeneous types: the grades of the two
/// operands, the dense product, and the product of the operands' magnitudes.
type GradedProduct = fn(&[f64], &[f64]) -> (usize, usize, Vec<f64>, f64);

macro_rules! push_graded_product {
    (($cases:ident), $a:ident, $b:ident) => {
        $cases.push(|x, y| {
            let a = <$a as Embed<Multivector>>::from_reference(x);
            let b = <$b as Embed<Multivector>>::from_reference(y);
            let n = Multivector::ZERO.to_array().len().trailing_zeros() as usize;
            let r = grades_of_type(stringify!($a), n).unwrap()[0];
            let s = grades_of_type(stringify!($b), n).unwrap()[0];
            let scale = l1(&<$a as Embed<Multivector>>::to_reference(a))
                * l1(&<$b as Embed<Multivector>>::to_reference(b));
            (r, s, ga_tests::dense!(a * b), scale)
        });
    };
}

/// `a . (a1 ^ a2 ^ a3)` needs a trivector: not in G2.
macro_rules! trivector_identity {
    (2) => {};
    ($dim:tt) => {
        /// a.(a1^a2^a3) = (a.a1) a2^a3 - (a.a2) a1^a3 + (a.a3) a1^a2.
        #[test]
        fn inner_product_with_a_trivector_expands_into_bivectors() {
            let v = || dense(SIZE);
            run(64, &(v(), v(), v(), v()), |(x, y, z, w)| {
                let (a, a1, a2, a3) = (vector(&x), vector(&y), vector(&z), vector(&w));
                let left = a | (a1 ^ a2 ^ a3);
                let right = (a | a1) * (a2 ^ a3) - (a | a2) * (a1 ^ a3) + (a | a3) * (a1 ^ a2);
                let scale = l1(&x) * l1(&y) * l1(&z) * l1(&w);
                prop_assert_close!(dense!(left), dense!(right), scale = scale, rel = 1e-12);
                Ok(())
            });
        }
    };
}

macro_rules! lecture_tests {
    (
        $alg:ident, $($path:ident)::+,
        dim = $dim:tt,
        metric = $metric:tt,
        types = $types:tt,
        grade_types = [$($grade_type:ident),* $(,)?],
        $($rest:tt)*
    ) => {
        mod $alg {
            use super::{dense, grades_of_type, l1, run, Algebra, GradedProduct};
            use ga_tests::embed::Embed;
            use ga_tests::{dense, prop_assert_close};
            #[allow(clippy::wildcard_imports)] // every generated type is needed
            use $($path)::+::*;

            const SIZE: usize = 1 << $dim;

            fn algebra() -> Algebra {
                Algebra::new(&$metric)
            }

            fn mv(x: &[f64]) -> Multivector {
                <Multivector as Embed<Multivector>>::from_reference(x)
            }

            fn vector(x: &[f64]) -> Vector {
                <Vector as Embed<Multivector>>::from_reference(x)
            }

            fn vector_part(x: &[f64]) -> Vec<f64> {
                <Vector as Embed<Multivector>>::to_reference(vector(x))
            }

            /// A(BC) = (AB)C.
            #[test]
            fn geometric_product_is_associative() {
                run(64, &(dense(SIZE), dense(SIZE), dense(SIZE)), |(x, y, z)| {
                    let (a, b, c) = (mv(&x), mv(&y), mv(&z));
                    let scale = l1(&x) * l1(&y) * l1(&z);
                    prop_assert_close!(
                        dense!((a * b) * c),
                        dense!(a * (b * c)),
                        scale = scale,
                        rel = 1e-12,
                    );
                    Ok(())
                });
            }

            /// A(B + C) = AB + AC and (B + C)A = BA + CA.
            #[test]
            fn geometric_product_distributes_over_addition() {
                run(64, &(dense(SIZE), dense(SIZE), dense(SIZE)), |(x, y, z)| {
                    let (a, b, c) = (mv(&x), mv(&y), mv(&z));
                    let scale = l1(&x) * (l1(&y) + l1(&z));
                    prop_assert_close!(
                        dense!(a * (b + c)),
                        dense!(a * b + a * c),
                        scale = scale,
                        rel = 1e-12,
                    );
                    prop_assert_close!(
                        dense!((b + c) * a),
                        dense!(b * a + c * a),
                        scale = scale,
                        rel = 1e-12,
                    );
                    Ok(())
                });
            }

            /// a^2 is a scalar, the sum of the squares weighted by the metric.
            #[test]
            fn square_of_a_vector_is_a_scalar() {
                let metric: [i8; $dim] = $metric;
                run(64, &dense(SIZE), |x| {
                    let a = vector(&x);
                    let square = dense!(a * a);
                    let mut expected = vec![0.0; SIZE];
                    expected[0] = (0..$dim)
                        .map(|i| f64::from(metric[i]) * x[1 << i] * x[1 << i])
                        .sum();
                    prop_assert_close!(
                        square,
                        expected,
                        scale = l1(&vector_part(&x)).powi(2),
                        rel = 1e-12,
                    );
                    Ok(())
                });
            }

            /// ab = a.b + a^b, with a.b = (ab + ba)/2 and a^b = (ab - ba)/2.
            #[test]
            fn vector_product_is_inner_plus_outer_product() {
                let algebra = algebra();
                run(64, &(dense(SIZE), dense(SIZE)), |(x, y)| {
                    let (a, b) = (vector(&x), vector(&y));
                    let (ab, ba) = (dense!(a * b), dense!(b * a));
                    let (inner, outer) = (dense!(a | b), dense!(a ^ b));
                    let scale = l1(&vector_part(&x)) * l1(&vector_part(&y));
                    prop_assert_close!(ab, algebra.add(&inner, &outer), scale = scale, rel = 1e-12);
                    let symmetric = algebra.scale(&algebra.add(&ab, &ba), 0.5);
                    let antisymmetric = algebra.scale(&algebra.sub(&ab, &ba), 0.5);
                    prop_assert_close!(inner, symmetric, scale = scale, rel = 1e-12);
                    prop_assert_close!(outer, antisymmetric, scale = scale, rel = 1e-12);
                    Ok(())
                });
            }

            /// a.(b^c) = (a.b)c - (a.c)b.
            #[test]
            fn inner_product_with_a_bivector_expands_into_vectors() {
                run(64, &(dense(SIZE), dense(SIZE), dense(SIZE)), |(x, y, z)| {
                    let (a, b, c) = (vector(&x), vector(&y), vector(&z));
                    let left = a | (b ^ c);
                    let right = (a | b) * c - (a | c) * b;
                    let scale = l1(&x) * l1(&y) * l1(&z);
                    prop_assert_close!(dense!(left), dense!(right), scale = scale, rel = 1e-12);
                    Ok(())
                });
            }

            trivector_identity!($dim);

            /// a A_r = a.A_r + a^A_r, a.A_r = (a A_r - (-1)^r A_r a)/2 of grade r - 1,
            /// a^A_r = (a A_r + (-1)^r A_r a)/2 of grade r + 1, for r = 1..n.
            #[test]
            fn vector_times_a_grade_r_element_splits_into_lowered_and_raised_parts() {
                let algebra = algebra();
                run(64, &(dense(SIZE), dense(SIZE)), |(x, y)| {
                    let a = vector(&x);
                    $(
                        let big = <$grade_type as Embed<Multivector>>::from_reference(&y);
                        let r = grades_of_type(stringify!($grade_type), $dim).unwrap()[0];
                        let sign = if r % 2 == 0 { 1.0 } else { -1.0 };
                        let (a_big, big_a) = (dense!(a * big), dense!(big * a));
                        let (inner, outer) = (dense!(a | big), dense!(a ^ big));
                        let big_part = <$grade_type as Embed<Multivector>>::to_reference(big);
                        let scale = l1(&vector_part(&x)) * l1(&big_part);
                        let what = stringify!($grade_type);
                        prop_assert_close!(
                            a_big,
                            algebra.add(&inner, &outer),
                            scale = scale,
                            rel = 1e-12,
                            "a {what}",
                        );
                        let signed_big_a = algebra.scale(&big_a, sign);
                        let lowered = algebra.scale(&algebra.sub(&a_big, &signed_big_a), 0.5);
                        let raised = algebra.scale(&algebra.add(&a_big, &signed_big_a), 0.5);
                        prop_assert_close!(
                            inner,
                            lowered,
                            scale = scale,
                            rel = 1e-12,
                            "a . {what}",
                        );
                        prop_assert_close!(outer, raised, scale = scale, rel = 1e-12, "a ^ {what}");
                        prop_assert_close!(
                            inner,
                            algebra.grade(&inner, r - 1),
                            scale = scale,
                            rel = 1e-12,
                            "grade of a . {what}",
                        );
                        prop_assert_close!(
                            outer,
                            algebra.grade(&outer, r + 1),
                            scale = scale,
                            rel = 1e-12,
                            "grade of a ^ {what}",
                        );
                    )*
                    Ok(())
                });
            }

            /// A_r B_s = <A_r B_s>_{|r-s|} + <A_r B_s>_{|r-s|+2} + ... + <A_r B_s>_{r+s}.
            #[test]
            fn product_of_grades_r_and_s_has_grades_from_difference_to_sum_in_steps_of_two() {
                let algebra = algebra();
                let mut cases: Vec<GradedProduct> = Vec::new();
                ga_tests::cartesian!(
                    push_graded_product!(cases); [$($grade_type),*]; [$($grade_type),*]
                );
                run(64, &(dense(SIZE), dense(SIZE)), |(x, y)| {
                    for case in &cases {
                        let (r, s, product, scale) = case(&x, &y);
                        let mut allowed = vec![0.0; SIZE];
                        for t in (r.abs_diff(s)..=r + s).step_by(2) {
                            allowed = algebra.add(&allowed, &algebra.grade(&product, t));
                        }
                        prop_assert_close!(
                            product,
                            allowed,
                            scale = scale,
                            rel = 1e-12,
                            "grades {r} times {s}",
                        );
                    }
                    Ok(())
                });
            }

            /// (A ^ B) ^ C = A ^ (B ^ C).
            #[test]
            fn outer_product_is_associative() {
                run(64, &(dense(SIZE), dense(SIZE), dense(SIZE)), |(x, y, z)| {
                    let (a, b, c) = (mv(&x), mv(&y), mv(&z));
                    let scale = l1(&x) * l1(&y) * l1(&z);
                    prop_assert_close!(
                        dense!((a ^ b) ^ c),
                        dense!(a ^ (b ^ c)),
                        scale = scale,
                        rel = 1e-12,
                    );
                    Ok(())
                });
            }

            /// (AB)~ = ~B ~A.
            #[test]
            fn reverse_of_a_product_is_the_reversed_product_of_the_reverses() {
                run(64, &(dense(SIZE), dense(SIZE)), |(x, y)| {
                    let (a, b) = (mv(&x), mv(&y));
                    let scale = l1(&x) * l1(&y);
                    prop_assert_close!(
                        dense!((a * b).reverse()),
                        dense!(b.reverse() * a.reverse()),
                        scale = scale,
                        rel = 1e-12,
                    );
                    Ok(())
                });
            }
        }
    };
}

ga_tests::for_each_algebra!(lecture_tests);
