//! The slice kernels compute what the one-item operations compute, item by item, on every
//! length from 0 to 100 (so every tail of every vector width is covered), on whichever
//! instruction set this CPU selects; and they refuse slices of different lengths without
//! writing anything.

use ga_core::kernels::{self, InstructionSet, LengthMismatch};

use ga_test_rng::Rng;

macro_rules! kernel_tests {
    ($module:ident, $scalar:ident, $g3:path) => {
        mod $module {
            use super::*;
            use g3::Sandwich as _;
            use $g3 as g3;

            fn rotor(rng: &mut Rng) -> g3::Rotor {
                g3::Rotor::new(
                    rng.signed() as $scalar,
                    rng.signed() as $scalar,
                    rng.signed() as $scalar,
                    rng.signed() as $scalar,
                )
            }

            fn vector(rng: &mut Rng) -> g3::Vector {
                g3::Vector::new(
                    rng.signed() as $scalar,
                    rng.signed() as $scalar,
                    rng.signed() as $scalar,
                )
            }

            #[test]
            fn every_kernel_equals_the_item_loop_for_lengths_0_to_100() {
                let mut rng = Rng::new(11);
                for len in 0..=100 {
                    let a: Vec<g3::Rotor> = (0..len).map(|_| rotor(&mut rng)).collect();
                    let b: Vec<g3::Rotor> = (0..len).map(|_| rotor(&mut rng)).collect();
                    let x: Vec<g3::Vector> = (0..len).map(|_| vector(&mut rng)).collect();
                    let r = rotor(&mut rng);

                    let mut products = vec![g3::Rotor::ZERO; len];
                    kernels::$scalar::mul_pairs(&a, &b, &mut products).unwrap();
                    for i in 0..len {
                        assert_eq!(
                            products[i],
                            a[i] * b[i],
                            "mul_pairs, length {len}, item {i}"
                        );
                    }

                    let mut rotated = vec![g3::Vector::ZERO; len];
                    kernels::$scalar::sandwich_pairs(&a, &x, &mut rotated).unwrap();
                    for i in 0..len {
                        assert_eq!(
                            rotated[i],
                            a[i].sandwich(x[i]),
                            "sandwich_pairs, length {len}, item {i}"
                        );
                    }

                    let mut all = vec![g3::Vector::ZERO; len];
                    kernels::$scalar::sandwich_all(r, &x, &mut all).unwrap();
                    let mut in_place = x.clone();
                    r.sandwich_vectors(&mut in_place);
                    // Fused multiply-adds round once where the item loop rounds twice.
                    let tolerance = 8.0 * <$scalar>::EPSILON;
                    for i in 0..len {
                        let scale = r.norm_squared() * (1.0 + x[i].norm());
                        assert!(
                            (all[i] - in_place[i]).norm() <= tolerance * scale,
                            "sandwich_all against sandwich_vectors, length {len}, item {i}"
                        );
                        let direct = r.sandwich(x[i]);
                        assert!(
                            (all[i] - direct).norm() <= tolerance * scale,
                            "sandwich_all against sandwich, length {len}, item {i}"
                        );
                    }
                }
            }

            /// Every copy of `mul_pairs` this CPU can run (not only the one it picks),
            /// bit for bit against the one-item product, with special values in the
            /// inputs (signed zeros, infinities, NaN) where a wrong operation order or a
            /// fused multiply-add would show.
            #[test]
            fn every_copy_of_mul_pairs_equals_the_one_item_product() {
                let mut rng = Rng::new(13);
                let specials = [0.0, -0.0, 1.0, <$scalar>::INFINITY, <$scalar>::MAX, 1e-30];
                for set in [
                    InstructionSet::Avx512f,
                    InstructionSet::Avx2Fma,
                    InstructionSet::Baseline,
                ] {
                    for len in [0, 1, 3, 4, 5, 7, 8, 9, 15, 16, 17, 31, 33, 64, 100] {
                        let mut a: Vec<g3::Rotor> = (0..len).map(|_| rotor(&mut rng)).collect();
                        let b: Vec<g3::Rotor> = (0..len).map(|_| rotor(&mut rng)).collect();
                        for (i, item) in a.iter_mut().enumerate().step_by(3) {
                            let mut parts = item.to_array();
                            parts[i % 4] = specials[i % specials.len()];
                            *item = g3::Rotor::from_array(parts);
                        }
                        let mut out = vec![g3::Rotor::ZERO; len];
                        let ran = kernels::$scalar::mul_pairs_on(set, &a, &b, &mut out).unwrap();
                        let expected_set = if set.is_available() {
                            set
                        } else {
                            InstructionSet::Baseline
                        };
                        assert_eq!(ran, expected_set, "{set:?}");
                        for i in 0..len {
                            let expected = a[i] * b[i];
                            let same = out[i]
                                .to_array()
                                .iter()
                                .zip(expected.to_array())
                                .all(|(x, y)| x.to_bits() == y.to_bits());
                            assert!(
                                same,
                                "{set:?}, length {len}, item {i}: {:?} against {expected:?}",
                                out[i]
                            );
                        }
                    }
                }
            }

            /// Every copy of `mul_pairs` against the one-item product, bit for bit, on every
            /// pair of rotors with components in {+0, -0, 1, -1}: where two products cancel
            /// exactly, `-(p + q)` and `(-p) + (-q)` differ in the sign of the zero, so any
            /// regrouping or negation that the one-item product does not do shows here.
            #[test]
            fn every_copy_of_mul_pairs_keeps_the_sign_of_zero() {
                let values: [$scalar; 4] = [0.0, -0.0, 1.0, -1.0];
                let rotors: Vec<g3::Rotor> = (0..256)
                    .map(|code: usize| {
                        g3::Rotor::from_array([0, 1, 2, 3].map(|k| values[(code >> (2 * k)) & 3]))
                    })
                    .collect();
                // All 65,536 ordered pairs, in one slice each, so that every copy runs its
                // full-width rounds on them.
                let a: Vec<g3::Rotor> = rotors
                    .iter()
                    .flat_map(|&p| rotors.iter().map(move |_| p))
                    .collect();
                let b: Vec<g3::Rotor> =
                    rotors.iter().flat_map(|_| rotors.iter().copied()).collect();
                for set in [
                    InstructionSet::Avx512f,
                    InstructionSet::Avx2Fma,
                    InstructionSet::Baseline,
                ] {
                    let mut out = vec![g3::Rotor::ZERO; a.len()];
                    kernels::$scalar::mul_pairs_on(set, &a, &b, &mut out).unwrap();
                    let mut differing = 0;
                    let mut first = None;
                    for i in 0..a.len() {
                        let expected = a[i] * b[i];
                        let same = out[i]
                            .to_array()
                            .iter()
                            .zip(expected.to_array())
                            .all(|(x, y)| x.to_bits() == y.to_bits());
                        if !same {
                            differing += 1;
                            first.get_or_insert((a[i], b[i], out[i], expected));
                        }
                    }
                    assert_eq!(
                        differing, 0,
                        "{set:?}: {differing} pairs differ, first (a, b, kernel, a * b): {first:?}"
                    );
                }
            }

            #[test]
            fn mismatched_lengths_are_refused_and_nothing_is_written() {
                let mut rng = Rng::new(12);
                let a: Vec<g3::Rotor> = (0..5).map(|_| rotor(&mut rng)).collect();
                let x: Vec<g3::Vector> = (0..4).map(|_| vector(&mut rng)).collect();
                let mut out = vec![g3::Rotor::ONE; 5];
                assert_eq!(
                    kernels::$scalar::mul_pairs(&a, &a[..4], &mut out),
                    Err(LengthMismatch { input: 5, other: 4 })
                );
                assert!(out.iter().all(|&r| r == g3::Rotor::ONE));
                let mut vectors = vec![g3::Vector::E1; 5];
                assert!(kernels::$scalar::sandwich_pairs(&a, &x, &mut vectors).is_err());
                assert!(kernels::$scalar::sandwich_all(a[0], &x, &mut vectors).is_err());
                assert!(vectors.iter().all(|&v| v == g3::Vector::E1));
            }
        }
    };
}

kernel_tests!(single, f32, ga_core::f32::g3);
kernel_tests!(double, f64, ga_core::f64::g3);

#[test]
fn the_instruction_set_is_named() {
    let set = kernels::instruction_set();
    assert!(["avx512f", "avx2+fma", "baseline"].contains(&set), "{set}");
    let message = LengthMismatch { input: 3, other: 2 }.to_string();
    assert!(message.contains('3') && message.contains('2'), "{message}");
}
