//! Every generated product (`*`, `^`, `|`, `left_contraction`,
//! `right_contraction`, `scalar_product`, `commutator`) of every ordered pair of
//! types, the scalar on either side included, agrees with the reference algebra
//! in all six algebras, component by component, to `1e-12` relative to the sum of
//! the magnitudes of the terms that land on the component (and in the `f32` G2, G3
//! and G4 to `1e-5`).

use ga_tests::harness::{check_products, PairCase};
use ga_tests::{Algebra, Product};

/// Applies the product named as in `TERM_COUNTS`.
macro_rules! apply_product {
    (geometric, $a:ident, $b:ident) => {
        $a * $b
    };
    (outer, $a:ident, $b:ident) => {
        $a ^ $b
    };
    (inner, $a:ident, $b:ident) => {
        $a | $b
    };
    (left_contraction, $a:ident, $b:ident) => {
        $a.left_contraction($b)
    };
    (right_contraction, $a:ident, $b:ident) => {
        $a.right_contraction($b)
    };
    (scalar_product, $a:ident, $b:ident) => {
        $a.scalar_product($b)
    };
    (commutator, $a:ident, $b:ident) => {
        $a.commutator($b)
    };
}

/// Pushes the case `A product B` (the product of two plain scalars is Rust's own).
macro_rules! push_case {
    (($cases:ident, $product:ident), Scalar, Scalar) => {};
    (($cases:ident, $product:ident), $a:ident, $b:ident) => {
        $cases.push(PairCase {
            lhs: stringify!($a),
            rhs: stringify!($b),
            eval: |x, y| {
                let a = <$a as Embed<Multivector>>::from_reference(x);
                let b = <$b as Embed<Multivector>>::from_reference(y);
                let out = apply_product!($product, a, b);
                [
                    <$a as Embed<Multivector>>::to_reference(a),
                    <$b as Embed<Multivector>>::to_reference(b),
                    ga_tests::dense!(out),
                ]
            },
        });
    };
}

macro_rules! product_test {
    ($name:ident, $product:ident, $kind:ident, $metric:tt, $types:tt, $tolerance:expr) => {
        #[test]
        fn $name() {
            let mut cases = Vec::new();
            ga_tests::cartesian!(push_case!(cases, $product); $types; $types);
            check_products(&Algebra::new(&$metric), Product::$kind, &cases, $tolerance);
        }
    };
}

macro_rules! product_tests {
    (
        $alg:ident, $($path:ident)::+,
        dim = $dim:tt,
        metric = $metric:tt,
        types = $types:tt,
        $($rest:tt)*
    ) => {
        product_tests!(@scalar $alg, $($path)::+, f64, PRODUCT_TOLERANCE, $metric, $types);
    };
    (@scalar $alg:ident, $($path:ident)::+, $scalar:ident, $tolerance:ident, $metric:tt, $types:tt) => {
        mod $alg {
            use super::{check_products, Algebra, PairCase, Product};
            use ga_tests::embed::Embed;
            use ga_tests::harness::$tolerance as TOLERANCE;
            #[allow(clippy::wildcard_imports)] // the products are traits of the module
            use $($path)::+::*;

            type Scalar = $scalar;

            product_test!(
                geometric_product_of_every_type_pair_matches_the_reference,
                geometric, Geometric, $metric, $types, TOLERANCE
            );
            product_test!(
                outer_product_of_every_type_pair_matches_the_reference,
                outer, Outer, $metric, $types, TOLERANCE
            );
            product_test!(
                inner_product_of_every_type_pair_matches_the_reference,
                inner, Inner, $metric, $types, TOLERANCE
            );
            product_test!(
                left_contraction_of_every_type_pair_matches_the_reference,
                left_contraction, LeftContraction, $metric, $types, TOLERANCE
            );
            product_test!(
                right_contraction_of_every_type_pair_matches_the_reference,
                right_contraction, RightContraction, $metric, $types, TOLERANCE
            );
            product_test!(
                scalar_product_of_every_type_pair_matches_the_reference,
                scalar_product, ScalarProduct, $metric, $types, TOLERANCE
            );
            product_test!(
                commutator_of_every_type_pair_matches_the_reference,
                commutator, Commutator, $metric, $types, TOLERANCE
            );
        }
    };
}

ga_tests::for_each_algebra!(product_tests);

/// The single-precision algebras of `ga_core::f32`, to single-precision tolerance.
mod single_precision {
    use super::{check_products, Algebra, PairCase, Product};

    product_tests!(
        @scalar g2, ga_core::f32::g2, f32, F32_PRODUCT_TOLERANCE, [1, 1],
        [Scalar, Vector, Bivector, Even, Odd, Multivector]
    );
    product_tests!(
        @scalar g3, ga_core::f32::g3, f32, F32_PRODUCT_TOLERANCE, [1, 1, 1],
        [Scalar, Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    product_tests!(
        @scalar g4, ga_core::f32::g4, f32, F32_PRODUCT_TOLERANCE, [1, 1, 1, 1],
        [Scalar, Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector]
    );
}
