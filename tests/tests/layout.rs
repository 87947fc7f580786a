//! The generated types hold their blades in canonical order (grade first, then
//! lexicographic on the index list), with fields named by blade, and convert to
//! `Multivector` component for component.

use ga_tests::blade::{binomial, blades_of_grades, canonical_blades, grades_of_type};
use ga_tests::harness::{dense, run};

macro_rules! layout_tests {
    (
        $alg:ident, $($path:ident)::+,
        dim = $dim:tt,
        metric = $metric:tt,
        types = [$($ty:ident),* $(,)?],
        $($rest:tt)*
    ) => {
        mod $alg {
            use super::{binomial, blades_of_grades, canonical_blades, dense, grades_of_type, run};
            use ga_tests::embed::Embed;
            use ga_tests::prop_assert_close;
            #[allow(clippy::wildcard_imports)] // every generated type is needed
            use $($path)::+::*;

            type Scalar = f64;

            #[test]
            fn fields_are_named_by_blade_in_canonical_order() {
                $(
                    let name = <$ty as Embed<Multivector>>::NAME;
                    let grades = grades_of_type(name, $dim).unwrap();
                    assert_eq!(
                        <$ty as Embed<Multivector>>::blades(),
                        blades_of_grades($dim, &grades),
                        "field order of {name}"
                    );
                )*
                assert_eq!(<Multivector as Embed<Multivector>>::blades(), canonical_blades($dim));
            }

            #[test]
            fn grade_dimension_is_the_binomial_coefficient() {
                for r in 0..=$dim {
                    assert_eq!(grade_dimension(r), binomial($dim, r), "grade {r}");
                }
            }

            #[test]
            fn multivector_from_keeps_every_component_on_its_blade() {
                run(16, &dense(1 << $dim), |x| {
                    $(
                        let value = <$ty as Embed<Multivector>>::from_reference(&x);
                        let direct = <$ty as Embed<Multivector>>::to_reference(value);
                        let expected: Vec<f64> = (0..x.len())
                            .map(|blade| {
                                let held = <$ty as Embed<Multivector>>::blades().contains(&blade);
                                if held { x[blade] } else { 0.0 }
                            })
                            .collect();
                        prop_assert_close!(
                            direct,
                            expected,
                            rel = 0.0,
                            "round trip of {}",
                            stringify!($ty),
                        );
                        prop_assert_close!(
                            ga_tests::dense!(value),
                            expected,
                            rel = 0.0,
                            "Multivector::from({})",
                            stringify!($ty),
                        );
                    )*
                    Ok(())
                });
            }
        }
    };
}

ga_tests::for_each_algebra!(layout_tests);
