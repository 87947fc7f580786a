//! `sandwich` of every versor type (`Vector`, `Even`, `Odd`) on every type, and
//! `sandwich_matrix` / `sandwich_vectors` of every versor type, agree with the
//! reference `v x ~v` (even `v`) and `v x^ ~v` (odd `v`, `x^` the grade involution)
//! in all six algebras and in the `f32` G2, G3 and G4, for versors that are products
//! of 1 to n random vectors. An odd versor's sandwich is a reflection, which the
//! rotor tests of `versors.rs` never reach. Likewise every lane of the sandwiches of
//! the batch modules (`x4`, `x8`) of `ga_core`'s G3 and G4.
//!
//! `sandwich_unit` (even versors, dimension <= 3) is checked against the reference too,
//! not only against `sandwich`, whose derivation it shares: in G2 and G3 in both
//! precisions, and in two three-dimensional metrics generated here where the bivectors'
//! squares differ in sign ([1, 1, -1]) or vanish ([1, 1, 0]).

use ga_tests::harness::{
    check_lane_sandwich_matrices, check_lane_sandwiches, check_sandwich_matrices, check_sandwiches,
    check_unit_sandwiches, LaneMatrixCase, LaneSandwichCase, MatrixCase, SandwichCase,
};
use ga_tests::Algebra;

/// Pushes the case `V.sandwich(X)` (the scalar is not a sandwich operand).
macro_rules! push_sandwich {
    (($cases:ident), $v:ident, Scalar) => {};
    (($cases:ident), $v:ident, $x:ident) => {
        $cases.push(SandwichCase {
            versor: Versor::$v,
            operand: stringify!($x),
            eval: |v, x| {
                let v = <$v as Embed<Multivector>>::from_reference(v);
                let x = <$x as Embed<Multivector>>::from_reference(x);
                let out: $x = v.sandwich(x);
                [
                    <$v as Embed<Multivector>>::to_reference(v),
                    <$x as Embed<Multivector>>::to_reference(x),
                    <$x as Embed<Multivector>>::to_reference(out),
                ]
            },
        });
    };
}

/// Pushes the case of `V::sandwich_matrix` and `V::sandwich_vectors`.
macro_rules! push_matrix {
    ($cases:ident, $v:ident) => {
        $cases.push(MatrixCase {
            versor: Versor::$v,
            eval: |v, xs| {
                let v = <$v as Embed<Multivector>>::from_reference(v);
                let mut vectors: Vec<Vector> = xs
                    .iter()
                    .map(|x| <Vector as Embed<Multivector>>::from_reference(x))
                    .collect();
                let inputs = vectors
                    .iter()
                    .map(|&x| <Vector as Embed<Multivector>>::to_reference(x))
                    .collect();
                v.sandwich_vectors(&mut vectors);
                MatrixEval {
                    versor: <$v as Embed<Multivector>>::to_reference(v),
                    vector_blades: <Vector as Embed<Multivector>>::blades().to_vec(),
                    matrix: v
                        .sandwich_matrix()
                        .iter()
                        .map(|row| row.iter().map(|&entry| f64::from(entry)).collect())
                        .collect(),
                    inputs,
                    outputs: vectors
                        .iter()
                        .map(|&x| <Vector as Embed<Multivector>>::to_reference(x))
                        .collect(),
                }
            },
        });
    };
}

macro_rules! sandwich_tests {
    (
        $alg:ident, $($path:ident)::+,
        dim = $dim:tt,
        metric = $metric:tt,
        types = $types:tt,
        $($rest:tt)*
    ) => {
        sandwich_tests!(@scalar $alg, $($path)::+, PRODUCT_TOLERANCE, $metric, $types);
    };
    (@scalar $alg:ident, $($path:ident)::+, $tolerance:ident, $metric:tt, $types:tt) => {
        mod $alg {
            use super::{check_sandwich_matrices, check_sandwiches, Algebra};
            use super::{MatrixCase, SandwichCase};
            use ga_tests::embed::Embed;
            use ga_tests::harness::$tolerance as TOLERANCE;
            use ga_tests::harness::{MatrixEval, Versor};
            #[allow(clippy::wildcard_imports)] // `Sandwich` is a trait of the module
            use $($path)::+::*;

            #[test]
            fn sandwich_of_every_versor_type_on_every_type_matches_the_reference() {
                let mut cases = Vec::new();
                ga_tests::cartesian!(push_sandwich!(cases); [Vector, Even, Odd]; $types);
                check_sandwiches(&Algebra::new(&$metric), &cases, TOLERANCE);
            }

            #[test]
            fn sandwich_matrix_and_sandwich_vectors_of_every_versor_type_match_the_reference() {
                let mut cases = Vec::new();
                push_matrix!(cases, Vector);
                push_matrix!(cases, Even);
                push_matrix!(cases, Odd);
                check_sandwich_matrices(&Algebra::new(&$metric), &cases, TOLERANCE);
            }
        }
    };
}

ga_tests::for_each_algebra!(sandwich_tests);

/// The single-precision algebras of `ga_core::f32`, to single-precision tolerance.
mod single_precision {
    use super::{check_sandwich_matrices, check_sandwiches, Algebra};
    use super::{MatrixCase, SandwichCase};

    sandwich_tests!(
        @scalar g2, ga_core::f32::g2, F32_PRODUCT_TOLERANCE, [1, 1],
        [Scalar, Vector, Bivector, Even, Odd, Multivector]
    );
    sandwich_tests!(
        @scalar g3, ga_core::f32::g3, F32_PRODUCT_TOLERANCE, [1, 1, 1],
        [Scalar, Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    sandwich_tests!(
        @scalar g4, ga_core::f32::g4, F32_PRODUCT_TOLERANCE, [1, 1, 1, 1],
        [Scalar, Vector, Bivector, Trivector, Quadvector, Even, Odd, Multivector]
    );
}

/// Pushes the case `Even.sandwich_unit(X)`.
macro_rules! push_unit_sandwich {
    ($cases:ident, $x:ident) => {
        $cases.push(SandwichCase {
            versor: ga_tests::harness::Versor::Even,
            operand: stringify!($x),
            eval: |v, x| {
                let v = <Even as Embed<Multivector>>::from_reference(v);
                let x = <$x as Embed<Multivector>>::from_reference(x);
                let out: $x = v.sandwich_unit(x);
                [
                    <Even as Embed<Multivector>>::to_reference(v),
                    <$x as Embed<Multivector>>::to_reference(x),
                    <$x as Embed<Multivector>>::to_reference(out),
                ]
            },
        });
    };
}

/// `sandwich_unit` of a unit `Even` on each listed type, against the reference.
macro_rules! unit_sandwich_test {
    ($test:ident, $($path:ident)::+, $tolerance:ident, $metric:expr, [$($x:ident),*]) => {
        #[test]
        fn $test() {
            use ga_tests::embed::Embed;
            #[allow(clippy::wildcard_imports)] // `SandwichUnit` is a trait of the module
            use $($path)::+::*;
            let mut cases = Vec::new();
            $(push_unit_sandwich!(cases, $x);)*
            check_unit_sandwiches(&Algebra::new(&$metric), &cases, ga_tests::harness::$tolerance);
        }
    };
}

/// `sandwich_unit` in every metric that has it (even versors, dimension <= 3).
mod unit_sandwiches {
    use super::{check_unit_sandwiches, Algebra, SandwichCase};

    ga_macros::algebra! {
        /// A three-dimensional metric with one negative square: `e13` and `e23` square
        /// to +1 (boosts), `e12` to -1.
        pub mod lorentz3 {
            metric: [1, 1, -1],
            scalar: f64,
        }
    }

    ga_macros::algebra! {
        /// Two-dimensional projective geometric algebra: `e3` is null, so `e13` and
        /// `e23` square to 0 (translations).
        pub mod pga2 {
            metric: [1, 1, 0],
            scalar: f64,
        }
    }

    mod embedding {
        mod lorentz3 {
            use super::super::lorentz3::*;
            ga_tests::embed_types!(f64; Vector, Bivector, Trivector, Even, Odd, Multivector);
        }
        mod pga2 {
            use super::super::pga2::*;
            ga_tests::embed_types!(f64; Vector, Bivector, Trivector, Even, Odd, Multivector);
        }
    }

    unit_sandwich_test!(
        g2,
        ga_core::f64::g2,
        PRODUCT_TOLERANCE,
        [1, 1],
        [Vector, Bivector, Even, Odd, Multivector]
    );
    unit_sandwich_test!(
        g3,
        ga_core::f64::g3,
        PRODUCT_TOLERANCE,
        [1, 1, 1],
        [Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    unit_sandwich_test!(
        f32_g2,
        ga_core::f32::g2,
        F32_PRODUCT_TOLERANCE,
        [1, 1],
        [Vector, Bivector, Even, Odd, Multivector]
    );
    unit_sandwich_test!(
        f32_g3,
        ga_core::f32::g3,
        F32_PRODUCT_TOLERANCE,
        [1, 1, 1],
        [Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    unit_sandwich_test!(
        lorentz3_metric,
        self::lorentz3,
        PRODUCT_TOLERANCE,
        [1, 1, -1],
        [Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    unit_sandwich_test!(
        pga2_metric,
        self::pga2,
        PRODUCT_TOLERANCE,
        [1, 1, 0],
        [Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
}

/// Pushes the case `V.sandwich(X)` of batch types, lane by lane, through the item
/// types of the module in scope as `item`.
macro_rules! push_lane_sandwich {
    (($cases:ident, $lanes:literal), $v:ident, $x:ident) => {
        $cases.push(LaneSandwichCase {
            versor: Versor::$v,
            operand: stringify!($x),
            eval: |vs, xs| {
                let v: [item::$v; $lanes] = ::std::array::from_fn(|lane| {
                    <item::$v as Embed<item::Multivector>>::from_reference(&vs[lane])
                });
                let x: [item::$x; $lanes] = ::std::array::from_fn(|lane| {
                    <item::$x as Embed<item::Multivector>>::from_reference(&xs[lane])
                });
                let out: [item::$x; $lanes] =
                    Sandwich::sandwich($v::from_items(v), $x::from_items(x)).to_items();
                (0..$lanes)
                    .map(|lane| {
                        [
                            <item::$v as Embed<item::Multivector>>::to_reference(v[lane]),
                            <item::$x as Embed<item::Multivector>>::to_reference(x[lane]),
                            <item::$x as Embed<item::Multivector>>::to_reference(out[lane]),
                        ]
                    })
                    .collect()
            },
        });
    };
}

/// Pushes the case of `V::sandwich_matrix` and `V::sandwich_vectors` of batch types,
/// lane by lane, through the item types of the module in scope as `item`.
macro_rules! push_lane_matrix {
    ($cases:ident, $lanes:literal, $v:ident) => {
        $cases.push(LaneMatrixCase {
            versor: Versor::$v,
            eval: |vs, xs| {
                let v: [item::$v; $lanes] = ::std::array::from_fn(|lane| {
                    <item::$v as Embed<item::Multivector>>::from_reference(&vs[lane])
                });
                let items: Vec<[item::Vector; $lanes]> = (0..xs[0].len())
                    .map(|j| {
                        ::std::array::from_fn(|lane| {
                            <item::Vector as Embed<item::Multivector>>::from_reference(&xs[lane][j])
                        })
                    })
                    .collect();
                let mut vectors: Vec<Vector> =
                    items.iter().map(|&x| Vector::from_items(x)).collect();
                let batch = $v::from_items(v);
                batch.sandwich_vectors(&mut vectors);
                let matrix = batch.sandwich_matrix();
                let dense =
                    |x: item::Vector| <item::Vector as Embed<item::Multivector>>::to_reference(x);
                (0..$lanes)
                    .map(|lane| MatrixEval {
                        versor: <item::$v as Embed<item::Multivector>>::to_reference(v[lane]),
                        vector_blades: <item::Vector as Embed<item::Multivector>>::blades()
                            .to_vec(),
                        matrix: matrix
                            .iter()
                            .map(|row| {
                                row.iter()
                                    .map(|entry| f64::from(entry.to_array()[lane]))
                                    .collect()
                            })
                            .collect(),
                        inputs: items.iter().map(|x| dense(x[lane])).collect(),
                        outputs: vectors.iter().map(|x| dense(x.to_items()[lane])).collect(),
                    })
                    .collect()
            },
        });
    };
}

/// The sandwiches of the batch module `$path::$batch` of `$lanes` lanes.
macro_rules! lane_sandwich_tests {
    (
        $name:ident, $($path:ident)::+, $batch:ident, $lanes:literal, $tolerance:ident,
        $metric:tt, $types:tt
    ) => {
        mod $name {
            use super::{check_lane_sandwich_matrices, check_lane_sandwiches, Algebra};
            use super::{LaneMatrixCase, LaneSandwichCase};
            use ga_tests::embed::Embed;
            use ga_tests::harness::$tolerance as TOLERANCE;
            use ga_tests::harness::{MatrixEval, Versor};
            #[allow(clippy::wildcard_imports)] // `Sandwich` is a trait of the module
            use $($path)::+::$batch::*;
            use $($path)::+ as item;

            #[test]
            fn sandwich_of_every_versor_type_on_every_type_matches_the_reference_in_every_lane() {
                let mut cases = Vec::new();
                ga_tests::cartesian!(
                    push_lane_sandwich!(cases, $lanes); [Vector, Even, Odd]; $types
                );
                check_lane_sandwiches(&Algebra::new(&$metric), $lanes, &cases, TOLERANCE);
            }

            #[test]
            fn sandwich_matrix_and_sandwich_vectors_match_the_reference_in_every_lane() {
                let mut cases = Vec::new();
                push_lane_matrix!(cases, $lanes, Vector);
                push_lane_matrix!(cases, $lanes, Even);
                push_lane_matrix!(cases, $lanes, Odd);
                let algebra = Algebra::new(&$metric);
                check_lane_sandwich_matrices(&algebra, $lanes, &cases, TOLERANCE);
            }
        }
    };
}

/// The structure-of-arrays batch modules of `ga_core` (`lanes:` in its `algebra!`
/// calls), lane by lane against the reference.
mod batch {
    use super::{check_lane_sandwich_matrices, check_lane_sandwiches, Algebra};
    use super::{LaneMatrixCase, LaneSandwichCase};

    lane_sandwich_tests!(
        g3_x4,
        ga_core::f64::g3,
        x4,
        4,
        PRODUCT_TOLERANCE,
        [1, 1, 1],
        [Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    lane_sandwich_tests!(
        f32_g3_x4,
        ga_core::f32::g3,
        x4,
        4,
        F32_PRODUCT_TOLERANCE,
        [1, 1, 1],
        [Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    lane_sandwich_tests!(
        f32_g3_x8,
        ga_core::f32::g3,
        x8,
        8,
        F32_PRODUCT_TOLERANCE,
        [1, 1, 1],
        [Vector, Bivector, Trivector, Even, Odd, Multivector]
    );
    lane_sandwich_tests!(
        f32_g4_x4,
        ga_core::f32::g4,
        x4,
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
