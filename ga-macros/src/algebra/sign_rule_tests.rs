//! The metric's sign rule against a second, independent computation: a blade is a list
//! of generator indices, the product of two blades is their concatenation put in order
//! by bubble sort (each swap of two different generators flips the sign) and then
//! contracted (each adjacent pair of equal generators is replaced by its square). This
//! shares nothing with `reorder_sign`'s bit counting, so a mistake in either shows up
//! here, and the metrics below have negative and zero squares, which the Euclidean
//! snapshots never exercise.

use super::{canonical_blades, Blade, Involution, Metric, ProductKind};

/// The generator indices (0-based) of a blade, ascending.
fn generators(blade: Blade) -> Vec<usize> {
    (0..32).filter(|i| blade & (1 << i) != 0).collect()
}

/// `e_A e_B` by the textbook rule: concatenate, bubble-sort counting swaps, contract
/// equal neighbours by their squares.
fn product_by_bubble_sort(squares: &[i8], a: Blade, b: Blade) -> (i8, Blade) {
    let mut word = generators(a);
    word.extend(generators(b));
    let mut sign: i8 = 1;
    for end in (1..word.len()).rev() {
        for k in 0..end {
            if word[k] > word[k + 1] {
                word.swap(k, k + 1);
                sign = -sign;
            }
        }
    }
    let mut blade = 0;
    let mut k = 0;
    while k < word.len() {
        if k + 1 < word.len() && word[k] == word[k + 1] {
            sign *= squares[word[k]];
            k += 2;
        } else {
            blade |= 1 << word[k];
            k += 1;
        }
    }
    (sign, blade)
}

/// Every metric of dimension `n` with squares in {1, -1, 0}: 3^n of them.
fn every_metric(n: usize) -> Vec<Vec<i8>> {
    (0..3usize.pow(n as u32))
        .map(|code| {
            (0..n)
                .map(|i| [1, -1, 0][code / 3usize.pow(i as u32) % 3])
                .collect()
        })
        .collect()
}

/// Metrics up to six generators with negative and zero squares in every position,
/// besides every metric of up to four generators.
fn metrics_under_test() -> Vec<Vec<i8>> {
    let mut metrics: Vec<Vec<i8>> = (1..=4).flat_map(every_metric).collect();
    metrics.extend([
        vec![1, 1, 1, 1, -1],
        vec![-1, -1, -1, -1, -1],
        vec![0, 1, -1, 0, 1],
        vec![1, -1, 0, 1, -1, 0],
        vec![0, 0, 0, 0, 0, 0],
        vec![-1, 1, 1, 1, 1, 1],
        vec![1, 1, 1, 1, 1, -1],
        vec![-1, -1, 0, -1, -1, 1],
    ]);
    metrics
}

#[test]
fn sign_of_every_blade_pair_matches_bubble_sort_in_metrics_with_negative_and_zero_squares() {
    let mut checked = 0;
    for squares in metrics_under_test() {
        let metric = Metric::new(squares.clone());
        let blades = canonical_blades(squares.len());
        for &a in &blades {
            for &b in &blades {
                assert_eq!(
                    metric.geometric(a, b),
                    product_by_bubble_sort(&squares, a, b),
                    "e_{a:b} e_{b:b} with squares {squares:?}"
                );
                checked += 1;
            }
        }
    }
    // Every metric of dimensions 1..=4 (3^n each, 4^n pairs) and eight of 5 and 6.
    let exhaustive: usize = (1..=4u32).map(|n| 3usize.pow(n) * 4usize.pow(n)).sum();
    assert_eq!(checked, exhaustive + 3 * 1024 + 5 * 4096);
}

#[test]
fn the_bubble_sort_reference_gives_the_textbook_signs() {
    // The test's own rule checked on products whose value is known by hand, so that
    // agreeing with it means something: e2 e1 = -e12, e1 e2 e1 = -e2 (G3),
    // e1 e1 = -1 in a negative metric, e4 e4 = 0 in PGA, e12 e12 = -1 in G3 but
    // e12 e12 = +1 when e2 squares to -1, e123 e123 = -1 in G3.
    assert_eq!(
        product_by_bubble_sort(&[1, 1, 1], 0b010, 0b001),
        (-1, 0b011)
    );
    assert_eq!(
        product_by_bubble_sort(&[1, 1, 1], 0b011, 0b001),
        (-1, 0b010)
    );
    assert_eq!(product_by_bubble_sort(&[-1, 1, 1], 0b001, 0b001), (-1, 0));
    assert_eq!(
        product_by_bubble_sort(&[1, 1, 1, 0], 0b1000, 0b1000),
        (0, 0)
    );
    assert_eq!(product_by_bubble_sort(&[1, 1, 1], 0b011, 0b011), (-1, 0));
    assert_eq!(product_by_bubble_sort(&[1, -1, 1], 0b011, 0b011), (1, 0));
    assert_eq!(product_by_bubble_sort(&[1, 1, 1], 0b111, 0b111), (-1, 0));
}

#[test]
fn pseudoscalar_square_matches_bubble_sort_in_every_metric_up_to_six_generators() {
    for n in 1..=6 {
        for squares in every_metric(n) {
            let metric = Metric::new(squares.clone());
            let full = metric.pseudoscalar();
            assert_eq!(
                metric.pseudoscalar_square(),
                product_by_bubble_sort(&squares, full, full).0,
                "{squares:?}"
            );
        }
    }
}

#[test]
fn product_filters_keep_the_geometric_sign_or_zero_in_degenerate_and_negative_metrics() {
    let grade = |b: Blade| b.count_ones() as i32;
    for squares in [vec![1, -1, 0, 1, -1, 0], vec![-1, -1, 0, -1, -1, 1]] {
        let metric = Metric::new(squares.clone());
        let blades = canonical_blades(squares.len());
        for &a in &blades {
            for &b in &blades {
                let (sign, out) = product_by_bubble_sort(&squares, a, b);
                let (r, s, t) = (grade(a), grade(b), grade(out));
                let commutes = product_by_bubble_sort(&squares, b, a).0 == sign;
                for kind in ProductKind::ALL {
                    let keep = match kind {
                        ProductKind::Geometric => true,
                        ProductKind::Outer => t == r + s,
                        ProductKind::Inner => t == (r - s).abs(),
                        ProductKind::LeftContraction => t == s - r,
                        ProductKind::RightContraction => t == r - s,
                        ProductKind::Scalar => t == 0,
                        ProductKind::Commutator => !commutes,
                        // Not a filter of the geometric product: checked below.
                        ProductKind::Regressive => continue,
                    };
                    let expected = if keep { sign } else { 0 };
                    assert_eq!(
                        metric.product(kind, a, b),
                        (expected, out),
                        "{kind:?} of e_{a:b} and e_{b:b} with squares {squares:?}"
                    );
                }
            }
        }
    }
}

#[test]
fn reverse_sign_matches_reversing_the_generator_list() {
    // Reversing k generators takes k(k-1)/2 swaps; counted here by bubble sort.
    for blade in canonical_blades(6) {
        let mut word = generators(blade);
        word.reverse();
        let mut swaps = 0;
        for end in (1..word.len()).rev() {
            for k in 0..end {
                if word[k] > word[k + 1] {
                    word.swap(k, k + 1);
                    swaps += 1;
                }
            }
        }
        let expected = if swaps % 2 == 0 { 1 } else { -1 };
        assert_eq!(Involution::Reverse.sign(blade), expected, "e_{blade:b}");
    }
}

#[test]
fn regressive_sign_is_the_complements_wedge_by_bubble_sort_for_every_metric() {
    // With the complement's sign from a Euclidean bubble sort (e_A e_C = +-I for disjoint
    // A and C, whatever the metric), a v b = undual(dual(a) ^ dual(b)) blade by blade.
    let n = 4;
    let euclidean = vec![1; n];
    let full: Blade = (1 << n) - 1;
    let complement = |a: Blade| {
        let c = full ^ a;
        (product_by_bubble_sort(&euclidean, a, c).0, c)
    };
    for squares in [vec![0, 1, 1, 1], vec![1, 1, 1, 0], vec![1, -1, -1, -1]] {
        let metric = Metric::new(squares.clone());
        for a in canonical_blades(n) {
            for b in canonical_blades(n) {
                let ((sa, ca), (sb, cb)) = (complement(a), complement(b));
                let expected = if ca & cb == 0 {
                    let wedge = product_by_bubble_sort(&euclidean, ca, cb).0;
                    // undual(c) = s e_A' where e_A' e_c = s I: the complement's own sign,
                    // since s = 1/s.
                    let out = full ^ (ca | cb);
                    let back = product_by_bubble_sort(&euclidean, out, ca | cb).0;
                    (sa * sb * wedge * back, out)
                } else {
                    (0, 0)
                };
                assert_eq!(
                    metric.product(ProductKind::Regressive, a, b),
                    expected,
                    "e_{a:b} v e_{b:b} with squares {squares:?}"
                );
            }
        }
    }
}
