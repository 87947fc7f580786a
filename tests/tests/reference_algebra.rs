//! The slow reference algebra's own tests (`ga_tests`' library: blades and their signs,
//! the reference products against textbook values and hand computation, double-double
//! arithmetic, the closeness checks, reading generated types as reference multivectors).
//! An integration test rather than unit tests of the library, so that `cargo test` does not
//! compile the library (with its generated STA, PGA, CGA and dual algebras) a second time
//! as a test harness: that build took 41 CPU-seconds of the workspace's 720.

mod blade {
    use ga_tests::blade::*;

    #[test]
    fn reorder_sign_counts_swaps() {
        // e1 e2 is already sorted, e2 e1 = -e1 e2, e12 e1 = -e1 e12 -> one swap.
        assert_eq!(reorder_sign(0b01, 0b10), 1.0);
        assert_eq!(reorder_sign(0b10, 0b01), -1.0);
        assert_eq!(reorder_sign(0b11, 0b01), -1.0);
        // e23 e1: e1 passes e3 and e2, two swaps.
        assert_eq!(reorder_sign(0b110, 0b001), 1.0);
        // e3 e12: e3 passes e1 and e2 -> (e3 e1 e2) = e123, two swaps.
        assert_eq!(reorder_sign(0b100, 0b011), 1.0);
        // e2 e13 = e2 e1 e3 = -e123.
        assert_eq!(reorder_sign(0b010, 0b101), -1.0);
    }

    #[test]
    fn canonical_order_is_grade_then_lexicographic() {
        let names: Vec<String> = canonical_blades(3).into_iter().map(blade_name).collect();
        assert_eq!(names, ["s", "e1", "e2", "e3", "e12", "e13", "e23", "e123"]);
        let g4_bivectors: Vec<String> = blades_of_grades(4, &[2])
            .into_iter()
            .map(blade_name)
            .collect();
        assert_eq!(g4_bivectors, ["e12", "e13", "e14", "e23", "e24", "e34"]);
        let g5_trivectors: Vec<String> = blades_of_grades(5, &[3])
            .into_iter()
            .map(blade_name)
            .collect();
        assert_eq!(
            g5_trivectors,
            ["e123", "e124", "e125", "e134", "e135", "e145", "e234", "e235", "e245", "e345"]
        );
    }

    #[test]
    fn blade_names_round_trip() {
        assert_eq!(blade_from_name("e13"), Some(0b101));
        assert_eq!(blade_from_name("s"), Some(0));
        assert_eq!(blade_from_name("e123456"), Some(0b11_1111));
        assert_eq!(blade_from_name("e31"), None);
        assert_eq!(blade_from_name("e11"), None);
        assert_eq!(blade_from_name("e"), None);
        assert_eq!(blade_from_name("e0"), None);
        assert_eq!(blade_from_name("x1"), None);
        for n in 0..=6 {
            for blade in canonical_blades(n) {
                assert_eq!(blade_from_name(&blade_name(blade)), Some(blade));
            }
        }
    }

    #[test]
    fn grade_dimensions_are_binomial() {
        for n in 0..=6 {
            for r in 0..=n {
                assert_eq!(blades_of_grades(n, &[r]).len(), binomial(n, r));
            }
            assert_eq!(canonical_blades(n).len(), 1 << n);
        }
    }

    #[test]
    fn type_names_map_to_grades() {
        assert_eq!(grades_of_type("Even", 5), Some(vec![0, 2, 4]));
        assert_eq!(grades_of_type("Odd", 4), Some(vec![1, 3]));
        assert_eq!(grades_of_type("Quadvector", 4), Some(vec![4]));
        assert_eq!(grades_of_type("Quadvector", 3), None);
        assert_eq!(grades_of_type("Pseudoscalar", 3), Some(vec![3]));
        assert_eq!(grades_of_type("Scalar", 3), Some(vec![0]));
        assert_eq!(grades_of_type("Multivector", 2), Some(vec![0, 1, 2]));
    }
}

mod reference {
    use ga_tests::blade::{blade_from_name, blades_of_grades};
    use ga_tests::reference::*;
    use ga_tests::{assert_close, prop_assert_close};
    use proptest::prelude::*;

    fn e(name: &str) -> usize {
        blade_from_name(name).unwrap()
    }

    /// The multivector `value e_name` in `algebra`.
    fn b(algebra: &Algebra, name: &str, value: f64) -> Vec<f64> {
        algebra.basis(e(name), value)
    }

    fn g3() -> Algebra {
        Algebra::new(&[1, 1, 1])
    }

    #[test]
    fn orthogonal_vectors_anticommute_e1e2e1_is_minus_e2() {
        let g3 = g3();
        let e1 = b(&g3, "e1", 1.0);
        let e2 = b(&g3, "e2", 1.0);
        let e1e2e1 = g3.geometric(&g3.geometric(&e1, &e2), &e1);
        assert_eq!(e1e2e1, b(&g3, "e2", -1.0));
    }

    #[test]
    fn unit_bivectors_and_pseudoscalars_square_as_in_the_textbook() {
        let g3 = g3();
        let e12 = b(&g3, "e12", 1.0);
        assert_eq!(g3.geometric(&e12, &e12), g3.scalar(-1.0));
        let e123 = b(&g3, "e123", 1.0);
        assert_eq!(g3.geometric(&e123, &e123), g3.scalar(-1.0));
        let g2 = Algebra::new(&[1, 1]);
        assert_eq!(
            g2.geometric(&b(&g2, "e12", 1.0), &b(&g2, "e12", 1.0)),
            g2.scalar(-1.0)
        );
        let g4 = Algebra::new(&[1, 1, 1, 1]);
        let i4 = b(&g4, "e1234", 1.0);
        assert_eq!(g4.geometric(&i4, &i4), g4.scalar(1.0));
        let sta = Algebra::new(&[1, -1, -1, -1]);
        let i_sta = b(&sta, "e1234", 1.0);
        assert_eq!(sta.geometric(&i_sta, &i_sta), sta.scalar(-1.0));
        // A boost plane squares to +1: (g0 g1)^2 = -g0^2 g1^2 = 1.
        let boost = b(&sta, "e12", 1.0);
        assert_eq!(sta.geometric(&boost, &boost), sta.scalar(1.0));
    }

    #[test]
    fn pga_null_generator_squares_to_zero_but_still_anticommutes() {
        let pga = Algebra::new(&[1, 1, 1, 0]);
        let e0 = b(&pga, "e4", 1.0);
        assert_eq!(pga.geometric(&e0, &e0), pga.zero());
        let e1 = b(&pga, "e1", 1.0);
        assert_eq!(pga.geometric(&e1, &e0), b(&pga, "e14", 1.0));
        assert_eq!(pga.geometric(&e0, &e1), b(&pga, "e14", -1.0));
        // A translator generator squares to zero: (e1 e0)^2 = -e1^2 e0^2 = 0.
        let e14 = b(&pga, "e14", 1.0);
        assert_eq!(pga.geometric(&e14, &e14), pga.zero());
        assert_eq!(
            pga.exp(&b(&pga, "e14", 0.5)),
            pga.add(&pga.scalar(1.0), &b(&pga, "e14", 0.5))
        );
    }

    #[test]
    fn cga_has_a_null_vector_built_from_e4_and_e5() {
        let cga = Algebra::new(&[1, 1, 1, 1, -1]);
        let e5 = b(&cga, "e5", 1.0);
        assert_eq!(cga.geometric(&e5, &e5), cga.scalar(-1.0));
        let null = cga.add(&b(&cga, "e4", 1.0), &e5);
        assert_eq!(cga.geometric(&null, &null), cga.zero());
        assert!(cga.inverse(&null).is_none());
    }

    #[test]
    fn quaternion_multiplication_table_is_the_g3_even_subalgebra() {
        // i = e3e2, j = e1e3, k = e2e1 satisfy Hamilton's i^2 = j^2 = k^2 = ijk = -1.
        let g3 = g3();
        let i = b(&g3, "e23", -1.0);
        let j = b(&g3, "e13", 1.0);
        let k = b(&g3, "e12", -1.0);
        let minus_one = g3.scalar(-1.0);
        let neg = |x: &[f64]| g3.scale(x, -1.0);
        for q in [&i, &j, &k] {
            assert_eq!(g3.geometric(q, q), minus_one);
        }
        assert_eq!(g3.geometric(&g3.geometric(&i, &j), &k), minus_one);
        assert_eq!(g3.geometric(&i, &j), k);
        assert_eq!(g3.geometric(&j, &k), i);
        assert_eq!(g3.geometric(&k, &i), j);
        assert_eq!(g3.geometric(&j, &i), neg(&k));
        assert_eq!(g3.geometric(&k, &j), neg(&i));
        assert_eq!(g3.geometric(&i, &k), neg(&j));
    }

    #[test]
    fn vector_products_split_into_inner_and_outer_parts() {
        let g3 = g3();
        let a = g3.from_components(&blades_of_grades(3, &[1]), &[1.0, 2.0, 3.0]);
        let c = g3.from_components(&blades_of_grades(3, &[1]), &[4.0, 5.0, 6.0]);
        assert_eq!(g3.inner(&a, &c), g3.scalar(32.0));
        assert_eq!(g3.scalar_product(&a, &c), 32.0);
        // a ^ c = (1*5 - 2*4) e12 + (1*6 - 3*4) e13 + (2*6 - 3*5) e23.
        let wedge = g3.from_components(&blades_of_grades(3, &[2]), &[-3.0, -6.0, -3.0]);
        assert_eq!(g3.outer(&a, &c), wedge);
        assert_eq!(g3.commutator(&a, &c), wedge);
        assert_eq!(g3.geometric(&a, &c), g3.add(&g3.scalar(32.0), &wedge));
    }

    #[test]
    fn contractions_of_basis_blades_match_hand_computation() {
        let g3 = g3();
        let e12 = b(&g3, "e12", 1.0);
        assert_eq!(
            g3.left_contraction(&b(&g3, "e1", 1.0), &e12),
            b(&g3, "e2", 1.0)
        );
        assert_eq!(
            g3.left_contraction(&b(&g3, "e2", 1.0), &e12),
            b(&g3, "e1", -1.0)
        );
        assert_eq!(g3.left_contraction(&e12, &b(&g3, "e1", 1.0)), g3.zero());
        assert_eq!(
            g3.right_contraction(&e12, &b(&g3, "e2", 1.0)),
            b(&g3, "e1", 1.0)
        );
        assert_eq!(g3.right_contraction(&b(&g3, "e1", 1.0), &e12), g3.zero());
        // The lecture's inner product is symmetric in which side has the lower grade.
        assert_eq!(g3.inner(&e12, &b(&g3, "e2", 1.0)), b(&g3, "e1", 1.0));
        assert_eq!(g3.inner(&b(&g3, "e1", 1.0), &e12), b(&g3, "e2", 1.0));
        // ... and, taken literally (t = |r - s|), scales by a scalar operand.
        assert_eq!(g3.inner(&g3.scalar(2.0), &e12), b(&g3, "e12", 2.0));
        assert_eq!(
            g3.left_contraction(&g3.scalar(2.0), &e12),
            b(&g3, "e12", 2.0)
        );
        assert_eq!(g3.right_contraction(&g3.scalar(2.0), &e12), g3.zero());
        assert_eq!(g3.outer(&b(&g3, "e1", 1.0), &b(&g3, "e1", 1.0)), g3.zero());
        assert_eq!(
            g3.outer(&b(&g3, "e2", 1.0), &b(&g3, "e13", 1.0)),
            b(&g3, "e123", -1.0)
        );
    }

    #[test]
    fn commutator_vanishes_exactly_for_commuting_blades() {
        let g3 = g3();
        assert_eq!(
            g3.commutator(&b(&g3, "e12", 1.0), &b(&g3, "e3", 1.0)),
            g3.zero()
        );
        assert_eq!(
            g3.commutator(&b(&g3, "e12", 1.0), &b(&g3, "e1", 1.0)),
            b(&g3, "e2", -1.0)
        );
        // e12 e23 = e13 and e23 e12 = -e13.
        assert_eq!(
            g3.commutator(&b(&g3, "e12", 1.0), &b(&g3, "e23", 1.0)),
            b(&g3, "e13", 1.0)
        );
    }

    #[test]
    fn involutions_flip_the_textbook_grades() {
        let g4 = Algebra::new(&[1, 1, 1, 1]);
        let ones = vec![1.0; 16];
        // Grades 0..=4: reverse + + - - +, involution + - + - +, conjugate + - - + +.
        let signs = |f: &dyn Fn(&[f64]) -> Vec<f64>| -> Vec<f64> {
            let out = f(&ones);
            (0..=4).map(|r| out[blades_of_grades(4, &[r])[0]]).collect()
        };
        assert_eq!(signs(&|x| g4.reverse(x)), [1.0, 1.0, -1.0, -1.0, 1.0]);
        assert_eq!(
            signs(&|x| g4.grade_involution(x)),
            [1.0, -1.0, 1.0, -1.0, 1.0]
        );
        assert_eq!(signs(&|x| g4.conjugate(x)), [1.0, -1.0, -1.0, 1.0, 1.0]);
    }

    #[test]
    fn dual_is_the_right_complement() {
        let g3 = g3();
        assert_eq!(g3.dual(&b(&g3, "e1", 1.0)), b(&g3, "e23", 1.0));
        assert_eq!(g3.dual(&b(&g3, "e2", 1.0)), b(&g3, "e13", -1.0));
        assert_eq!(g3.dual(&b(&g3, "e12", 1.0)), b(&g3, "e3", 1.0));
        assert_eq!(g3.dual(&g3.scalar(1.0)), b(&g3, "e123", 1.0));
        assert_eq!(g3.dual(&b(&g3, "e123", 1.0)), g3.scalar(1.0));
        // Metric-free: the null generator of PGA has a dual too.
        let pga = Algebra::new(&[1, 1, 1, 0]);
        assert_eq!(pga.dual(&b(&pga, "e4", 1.0)), b(&pga, "e123", -1.0));
        for algebra in [g3, pga, Algebra::new(&[1, 1, 1, 1, -1])] {
            let i = algebra.pseudoscalar_blade();
            for blade in 0..algebra.size() {
                let x = algebra.basis(blade, 1.0);
                let wedge = algebra.outer(&x, &algebra.dual(&x));
                assert_eq!(
                    wedge,
                    algebra.basis(i, 1.0),
                    "e_A ^ dual(e_A) for A = {blade:b}"
                );
                assert_eq!(algebra.undual(&algebra.dual(&x)), x);
                assert_eq!(algebra.dual(&algebra.undual(&x)), x);
            }
        }
    }

    #[test]
    fn norm_squared_may_be_negative_or_zero() {
        let g3 = g3();
        assert_eq!(g3.norm_squared(&b(&g3, "e12", 3.0)), 9.0);
        let sta = Algebra::new(&[1, -1, -1, -1]);
        assert_eq!(sta.norm_squared(&b(&sta, "e2", 2.0)), -4.0);
        let pga = Algebra::new(&[1, 1, 1, 0]);
        assert_eq!(pga.norm_squared(&b(&pga, "e14", 2.0)), 0.0);
    }

    #[test]
    fn exp_of_a_plane_is_cos_plus_sin_and_cosh_plus_sinh() {
        let g3 = g3();
        for angle in [1e-9, 0.3, 2.0, 3.1, 30.0] {
            let rotor = g3.exp(&b(&g3, "e12", angle));
            let expected = g3.add(&g3.scalar(angle.cos()), &b(&g3, "e12", angle.sin()));
            assert_close!(rotor, expected, rel = 1e-13);
        }
        let sta = Algebra::new(&[1, -1, -1, -1]);
        for rapidity in [1e-9, 0.5, 3.0] {
            let boost = sta.exp(&b(&sta, "e12", rapidity));
            let expected = sta.add(
                &sta.scalar(rapidity.cosh()),
                &b(&sta, "e12", rapidity.sinh()),
            );
            assert_close!(boost, expected, rel = 1e-13);
        }
    }

    #[test]
    fn inverse_of_a_vector_is_the_vector_over_its_square() {
        let g3 = g3();
        let v = g3.add(&b(&g3, "e1", 1.0), &b(&g3, "e2", 1.0));
        let inverse = g3.inverse(&v).unwrap();
        assert_close!(inverse, g3.scale(&v, 0.5));
        let pga = Algebra::new(&[1, 1, 1, 0]);
        assert!(pga.inverse(&b(&pga, "e4", 1.0)).is_none());
        assert!(g3.inverse(&g3.zero()).is_none());
        // 1 + e1 is a zero divisor: (1 + e1)(1 - e1) = 0.
        assert!(g3
            .inverse(&g3.add(&g3.scalar(1.0), &b(&g3, "e1", 1.0)))
            .is_none());
    }

    #[test]
    fn term_counts_of_textbook_products() {
        let g3 = g3();
        let vector = blades_of_grades(3, &[1]);
        let bivector = blades_of_grades(3, &[2]);
        let even = blades_of_grades(3, &[0, 2]);
        assert_eq!(g3.term_count(Product::Geometric, &vector, &vector), 9);
        assert_eq!(g3.term_count(Product::Inner, &vector, &vector), 3);
        assert_eq!(g3.term_count(Product::Outer, &vector, &vector), 6);
        assert_eq!(g3.term_count(Product::Commutator, &vector, &vector), 6);
        assert_eq!(g3.term_count(Product::Commutator, &bivector, &bivector), 6);
        assert_eq!(g3.term_count(Product::Geometric, &even, &even), 16);
        assert_eq!(
            g3.term_count(Product::LeftContraction, &bivector, &vector),
            0
        );
        assert_eq!(
            g3.term_count(Product::RightContraction, &bivector, &vector),
            6
        );
        let pga = Algebra::new(&[1, 1, 1, 0]);
        let pga_vector = blades_of_grades(4, &[1]);
        assert_eq!(
            pga.term_count(Product::ScalarProduct, &pga_vector, &pga_vector),
            3
        );
    }

    const METRICS: [&[i8]; 6] = [
        &[1, 1],
        &[1, 1, 1],
        &[1, 1, 1, 1],
        &[1, -1, -1, -1],
        &[1, 1, 1, 0],
        &[1, 1, 1, 1, -1],
    ];

    fn algebra_and_two() -> impl Strategy<Value = (Algebra, Vec<f64>, Vec<f64>)> {
        (0..METRICS.len()).prop_flat_map(|k| {
            let algebra = Algebra::new(METRICS[k]);
            let size = algebra.size();
            let values = || prop::collection::vec(-4.0..4.0f64, size);
            (Just(algebra), values(), values())
        })
    }

    proptest! {
        /// The graded products, written as the lecture defines them, must agree
        /// with the blade-pair filter that term counts use.
        #[test]
        fn graded_products_agree_with_the_blade_pair_filter((algebra, a, b) in algebra_and_two()) {
            // The regressive product is no filter of the geometric product's pairs (its
            // pairs land on `A & B`); its definition is its own, through complements.
            for product in Product::ALL.into_iter().filter(|p| *p != Product::Regressive) {
                let mut expected = algebra.zero();
                for (i, x) in a.iter().enumerate() {
                    for (j, y) in b.iter().enumerate() {
                        if algebra.contributes(product, i, j) {
                            let (sign, blade) = algebra.blade_product(i, j);
                            expected[blade] += sign * x * y;
                        }
                    }
                }
                prop_assert_close!(algebra.product(product, &a, &b), expected, rel = 1e-12, "{product:?}");
            }
        }

        #[test]
        fn geometric_product_is_associative((algebra, a, b) in algebra_and_two()) {
            let c = algebra.add(&a, &algebra.reverse(&b));
            let left = algebra.geometric(&algebra.geometric(&a, &b), &c);
            let right = algebra.geometric(&a, &algebra.geometric(&b, &c));
            prop_assert_close!(left, right, rel = 1e-12);
        }

        #[test]
        fn reverse_is_an_anti_automorphism((algebra, a, b) in algebra_and_two()) {
            let left = algebra.reverse(&algebra.geometric(&a, &b));
            let right = algebra.geometric(&algebra.reverse(&b), &algebra.reverse(&a));
            prop_assert_close!(left, right, rel = 1e-12);
        }

        #[test]
        fn inverse_multiplies_to_one_on_both_sides((algebra, a, _b) in algebra_and_two()) {
            if let Some(inverse) = algebra.inverse(&a) {
                let one = algebra.scalar(1.0);
                let scale = algebra.l1_norm(&a) * algebra.l1_norm(&inverse);
                prop_assert_close!(algebra.geometric(&a, &inverse), one, scale = scale, rel = 1e-9);
                prop_assert_close!(algebra.geometric(&inverse, &a), one, scale = scale, rel = 1e-9);
            }
        }

        #[test]
        fn exp_of_a_sum_of_commuting_terms_is_the_product((algebra, a, _b) in algebra_and_two()) {
            let x = algebra.scale(&algebra.grade(&a, 2), 0.5);
            let both = algebra.exp(&algebra.scale(&x, 2.0));
            let squared = algebra.geometric(&algebra.exp(&x), &algebra.exp(&x));
            let scale = algebra.l1_norm(&both).max(1.0);
            prop_assert_close!(both, squared, scale = scale, rel = 1e-11);
        }
    }
}

mod double_double {
    use ga_tests::double_double::*;
    use ga_tests::Algebra;

    #[test]
    fn double_double_keeps_what_f64_loses() {
        let third = Dd::from_f64(1.0) / Dd::from_f64(3.0);
        let back = third * Dd::from_f64(3.0) - Dd::from_f64(1.0);
        assert!(back.to_f64().abs() < 1e-30, "{back:?}");
        // (1 + 2^-60) - 1 is 2^-60, which f64 rounds away.
        let tiny = Dd::from_f64(1.0) + Dd::from_f64(2f64.powi(-60)) - Dd::from_f64(1.0);
        assert_eq!(tiny.to_f64(), 2f64.powi(-60));
    }

    #[test]
    fn inverse_of_a_g3_multivector_times_it_is_one() {
        let algebra = Algebra::new(&[1, 1, 1]);
        let a = [0.5, 1.0, -2.0, 0.25, 3.0, 0.0, 1.5, -0.75];
        let (y, residual) = inverse(&algebra, &a).expect("invertible");
        assert!(residual < 1e-28, "{residual:e}");
        let product = algebra.geometric(&a, &y);
        assert!((product[0] - 1.0).abs() < 1e-14);
        assert!(product[1..].iter().all(|c| c.abs() < 1e-14), "{product:?}");
    }

    #[test]
    fn a_zero_divisor_has_no_inverse_or_a_huge_one() {
        // 1 + e1 is a zero divisor in G3: (1 + e1)(1 - e1) = 0.
        let algebra = Algebra::new(&[1, 1, 1]);
        let mut a = algebra.scalar(1.0);
        a[1] = 1.0;
        assert!(inverse(&algebra, &a)
            .is_none_or(|(y, _)| y.iter().any(|v| !v.is_finite() || v.abs() > 1e25)));
    }
}

mod close {
    use ga_tests::assert_close;
    use ga_tests::close::*;

    #[test]
    fn equal_values_pass_and_the_tolerance_is_relative() {
        assert!(compare(&[1e20], &[1e20 + 1e6], &[1e20], 1e-12).is_ok());
        assert!(compare(&[1.0], &[1.0 + 1e-9], &[1.0], 1e-12).is_err());
        assert!(compare(&[0.0, 0.0], &[0.0, 0.0], &[0.0, 0.0], 1e-12).is_ok());
        assert!(compare(&[f64::NAN], &[1.0], &[1.0], 1e-12).is_err());
        assert!(compare(&[1.0], &[1.0, 2.0], &[1.0], 1e-12).is_err());
    }

    #[test]
    fn the_report_names_blades_and_shows_the_difference() {
        let report = compare(
            &[1.0, 0.0, 2.0, 0.0],
            &[1.0, 0.0, 2.5, 0.0],
            &[2.5; 4],
            1e-12,
        )
        .unwrap_err();
        assert!(report.contains("e2"), "{report}");
        assert!(report.contains("-5.000e-1"), "{report}");
        assert!(report.contains("<--"), "{report}");
    }

    #[test]
    #[should_panic(expected = "which = 3")]
    fn assert_close_panics_with_its_context() {
        assert_close!(1.0, 2.0, rel = 1e-12, "which = {}", 3);
    }

    #[test]
    fn assert_close_accepts_scalars_arrays_and_vectors() {
        assert_close!(1.0, 1.0 + 1e-14);
        assert_close!([1.0, 2.0], vec![1.0, 2.0]);
        assert_close!(vec![0.0, 1e-20], [0.0, 0.0], scale = 1.0, rel = 1e-12);
    }
}

mod embed {
    use ga_tests::embed::*;

    #[test]
    fn debug_text_names_the_blade_of_every_index() {
        let text = "Odd { e1: 1.0, e2: 2.0, e3: 3.0, e123: 4.0 }";
        assert_eq!(blades_from_debug(text, 4), [0b001, 0b010, 0b100, 0b111]);
        let swapped = "Bivector { e12: 2.0, e13: 1.0 }";
        assert_eq!(blades_from_debug(swapped, 2), [0b101, 0b011]);
    }

    #[test]
    #[should_panic(expected = "no field holds 2")]
    fn a_missing_field_is_reported() {
        let _ = blades_from_debug("Vector { e1: 1.0, e2: 3.0 }", 3);
    }
}
