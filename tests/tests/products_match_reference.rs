//! Every generated product (`*`, `^`, `|`, `left_contraction`,
//! `right_contraction`, `scalar_product`, `commutator`, `regressive`) of every ordered pair of
//! types, the scalar on either side included, agrees with the reference algebra
//! in all six algebras, component by component, to `1e-12` relative to the sum of
//! the magnitudes of the terms that land on the component (and in the `f32` G2, G3
//! and G4 to `1e-5`). Likewise every lane of every product of every pair of
//! non-scalar types of the batch modules (`x4`, `x8`) of `ga_core`'s G3 and G4.

use ga_tests::harness::{check_lane_products, check_products, LanePairCase, PairCase};
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
    (regressive, $a:ident, $b:ident) => {
        $a.regressive($b)
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
            product_test!(
                regressive_product_of_every_type_pair_matches_the_reference,
                regressive, Regressive, $metric, $types, TOLERANCE
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

/// Pushes the case `A product B` of batch types, lane by lane, through the item
/// types of the module in scope as `item` (the batch types' products with a lane
/// scalar are left out).
macro_rules! push_lane_case {
    (($cases:ident, $product:ident, $lanes:literal), $a:ident, $b:ident) => {
        $cases.push(LanePairCase {
            lhs: stringify!($a),
            rhs: stringify!($b),
            eval: |xs, ys| {
                let a: [item::$a; $lanes] = ::std::array::from_fn(|lane| {
                    <item::$a as Embed<item::Multivector>>::from_reference(&xs[lane])
                });
                let b: [item::$b; $lanes] = ::std::array::from_fn(|lane| {
                    <item::$b as Embed<item::Multivector>>::from_reference(&ys[lane])
                });
                let out = {
                    let (a, b) = ($a::from_items(a), $b::from_items(b));
                    Lanes::lanes(apply_product!($product, a, b))
                };
                (0..$lanes)
                    .map(|lane| {
                        [
                            <item::$a as Embed<item::Multivector>>::to_reference(a[lane]),
                            <item::$b as Embed<item::Multivector>>::to_reference(b[lane]),
                            <item::Multivector as Embed<item::Multivector>>::to_reference(
                                out[lane],
                            ),
                        ]
                    })
                    .collect()
            },
        });
    };
}

macro_rules! lane_product_test {
    ($name:ident, $product:ident, $kind:ident, $lanes:literal, $metric:tt, $types:tt) => {
        #[test]
        fn $name() {
            let mut cases = Vec::new();
            ga_tests::cartesian!(push_lane_case!(cases, $product, $lanes); $types; $types);
            let algebra = Algebra::new(&$metric);
            check_lane_products(&algebra, Product::$kind, $lanes, &cases, TOLERANCE);
        }
    };
}

/// Every product of the batch module `$path::$batch` of `$lanes` lanes of `$lane`.
macro_rules! lane_product_tests {
    (
        $name:ident, $($path:ident)::+, $batch:ident, $lane:ty, $lanes:literal, $tolerance:ident,
        $metric:tt, [$($ty:ident),* $(,)?]
    ) => {
        mod $name {
            use super::{check_lane_products, Algebra, LanePairCase, Product};
            use ga_tests::embed::Embed;
            use ga_tests::harness::$tolerance as TOLERANCE;
            #[allow(clippy::wildcard_imports)] // the products are traits of the module
            use $($path)::+::$batch::*;
            use $($path)::+ as item;

            /// A batch result (a batch type, a lane scalar or `Zero`) as one item
            /// multivector per lane.
            trait Lanes {
                fn lanes(self) -> [item::Multivector; $lanes];
            }
            $(
                impl Lanes for $ty {
                    fn lanes(self) -> [item::Multivector; $lanes] {
                        self.to_items().map(item::Multivector::from)
                    }
                }
            )*
            impl Lanes for $lane {
                fn lanes(self) -> [item::Multivector; $lanes] {
                    self.to_array().map(item::Multivector::from)
                }
            }
            impl Lanes for Zero {
                fn lanes(self) -> [item::Multivector; $lanes] {
                    [item::Multivector::ZERO; $lanes]
                }
            }

            lane_product_test!(
                geometric_product_of_every_type_pair_matches_the_reference_in_every_lane,
                geometric, Geometric, $lanes, $metric, [$($ty),*]
            );
            lane_product_test!(
                outer_product_of_every_type_pair_matches_the_reference_in_every_lane,
                outer, Outer, $lanes, $metric, [$($ty),*]
            );
            lane_product_test!(
                inner_product_of_every_type_pair_matches_the_reference_in_every_lane,
                inner, Inner, $lanes, $metric, [$($ty),*]
            );
            lane_product_test!(
                left_contraction_of_every_type_pair_matches_the_reference_in_every_lane,
                left_contraction, LeftContraction, $lanes, $metric, [$($ty),*]
            );
            lane_product_test!(
                right_contraction_of_every_type_pair_matches_the_reference_in_every_lane,
                right_contraction, RightContraction, $lanes, $metric, [$($ty),*]
            );
            lane_product_test!(
                scalar_product_of_every_type_pair_matches_the_reference_in_every_lane,
                scalar_product, ScalarProduct, $lanes, $metric, [$($ty),*]
            );
            lane_product_test!(
                commutator_of_every_type_pair_matches_the_reference_in_every_lane,
                commutator, Commutator, $lanes, $metric, [$($ty),*]
            );
            lane_product_test!(
                regressive_product_of_every_type_pair_matches_the_reference_in_every_lane,
                regressive, Regressive, $lanes, $metric, [$($ty),*]
            );
        }
    };
}

/// The structure-of-arrays batch modules of `ga_core` (`lanes:` in its `algebra!`
/// calls), lane by lane against the reference.
mod batch {
    use super::{check_lane_products, Algebra, LanePairCase, Product};

    lane_product_tests!(
        g3_x4,
        ga_core::f64::g3,
        x4,
        wide::f64x4,
        4,
        PRODUCT_TOLERANCE,
        [1, 1, 1],
        [Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    lane_product_tests!(
        f32_g3_x4,
        ga_core::f32::g3,
        x4,
        wide::f32x4,
        4,
        F32_PRODUCT_TOLERANCE,
        [1, 1, 1],
        [Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    lane_product_tests!(
        f32_g3_x8,
        ga_core::f32::g3,
        x8,
        wide::f32x8,
        8,
        F32_PRODUCT_TOLERANCE,
        [1, 1, 1],
        [Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    lane_product_tests!(
        f32_g4_x4,
        ga_core::f32::g4,
        x4,
        wide::f32x4,
        4,
        F32_PRODUCT_TOLERANCE,
        [1, 1, 1, 1],
        [
            Vector,
            Bivector,
            Trivector,
            Quadvector,
            Even,
            Odd,
            Multivector
        ]
    );
}
