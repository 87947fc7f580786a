//! Every generated unary operation (`reverse`, `grade_involution`, `conjugate`,
//! `dual`, `undual`, `norm_squared` and the grade projections) of every type
//! agrees with the reference in all six algebras.

use ga_tests::harness::{check_unary, Unary, UnaryCase};
use ga_tests::Algebra;

/// Pushes the case `T::method` (the plain scalar has no methods).
macro_rules! push_unary {
    (($cases:ident, $method:ident, $op:expr), Scalar) => {};
    (($cases:ident, $method:ident, $op:expr), $ty:ident) => {
        $cases.push(UnaryCase {
            ty: stringify!($ty),
            op: $op,
            eval: |x| {
                let value = <$ty as Embed<Multivector>>::from_reference(x);
                let out = value.$method();
                [
                    <$ty as Embed<Multivector>>::to_reference(value),
                    ga_tests::dense!(out),
                ]
            },
        });
    };
}

macro_rules! for_types {
    ($callback:ident!$args:tt; [$($ty:ident),* $(,)?]) => {
        $( $callback!($args, $ty); )*
    };
}

macro_rules! unary_test {
    ($name:ident, $method:ident, $op:expr, $metric:tt, $types:tt $(,)?) => {
        #[test]
        fn $name() {
            let mut cases = Vec::new();
            for_types!(push_unary!(cases, $method, $op); $types);
            check_unary(&Algebra::new(&$metric), &cases);
        }
    };
}

/// The grade a projection method keeps: `grade3` keeps 3.
fn projected_grade(method: &str) -> usize {
    method["grade".len()..].parse().unwrap()
}

macro_rules! unary_tests {
    (
        $alg:ident, $($path:ident)::+,
        dim = $dim:tt,
        metric = $metric:tt,
        types = $types:tt,
        grade_types = $grade_types:tt,
        projections = [$($ty:ident: [$($projection:ident),*]),* $(,)?],
    ) => {
        mod $alg {
            use super::{check_unary, projected_grade, Algebra, Unary, UnaryCase};
            use ga_tests::embed::Embed;
            #[allow(clippy::wildcard_imports)] // every generated type is needed
            use $($path)::+::*;

            unary_test!(
                reverse_of_every_type_matches_the_reference,
                reverse,
                Unary::Reverse,
                $metric,
                $types,
            );
            unary_test!(
                grade_involution_of_every_type_matches_the_reference,
                grade_involution,
                Unary::GradeInvolution,
                $metric,
                $types,
            );
            unary_test!(
                conjugate_of_every_type_matches_the_reference,
                conjugate,
                Unary::Conjugate,
                $metric,
                $types,
            );
            unary_test!(
                dual_of_every_type_is_the_right_complement,
                dual,
                Unary::Dual,
                $metric,
                $types,
            );
            unary_test!(
                undual_of_every_type_inverts_the_right_complement,
                undual,
                Unary::Undual,
                $metric,
                $types,
            );
            unary_test!(
                norm_squared_of_every_type_is_the_scalar_part_of_x_times_its_reverse,
                norm_squared,
                Unary::NormSquared,
                $metric,
                $types,
            );

            #[test]
            fn grade_projections_of_every_type_match_the_reference() {
                let mut cases = Vec::new();
                $($(
                    cases.push(UnaryCase {
                        ty: stringify!($ty),
                        op: Unary::Grade(projected_grade(stringify!($projection))),
                        eval: |x| {
                            let value = <$ty as Embed<Multivector>>::from_reference(x);
                            let out = value.$projection();
                            let operand = <$ty as Embed<Multivector>>::to_reference(value);
                            [operand, ga_tests::dense!(out)]
                        },
                    });
                )*)*
                check_unary(&Algebra::new(&$metric), &cases);
            }
        }
    };
}

ga_tests::for_each_algebra!(unary_tests);
