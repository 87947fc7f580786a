use std::collections::BTreeMap;

use crate::algebra::{Blade, Involution, Metric, ProductKind};

/// One term `sign * a[lhs] * b[rhs]` of a bilinear product; indices are component
/// positions in the operand types.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Term {
    pub lhs: usize,
    pub rhs: usize,
    pub sign: i8,
}

/// The non-zero terms of a product of two component lists, grouped by output blade.
/// Each pair (lhs, rhs) lands on exactly one blade, so no two terms can cancel.
pub fn bilinear(
    metric: &Metric,
    kind: ProductKind,
    lhs: &[Blade],
    rhs: &[Blade],
) -> BTreeMap<Blade, Vec<Term>> {
    let mut out: BTreeMap<Blade, Vec<Term>> = BTreeMap::new();
    for (i, &a) in lhs.iter().enumerate() {
        for (j, &b) in rhs.iter().enumerate() {
            let (sign, blade) = metric.product(kind, a, b);
            if sign != 0 {
                out.entry(blade).or_default().push(Term {
                    lhs: i,
                    rhs: j,
                    sign,
                });
            }
        }
    }
    out
}

/// A polynomial quadratic in one operand's components (and, for sandwiches, linear in a
/// second): for each output blade, for each component `k` of the second operand (always 0
/// for a self-product), the coefficient of `v[i] * v[j]` with `i <= j`.
pub type Quadratic = BTreeMap<Blade, BTreeMap<usize, BTreeMap<(usize, usize), i32>>>;

fn add_term(q: &mut Quadratic, blade: Blade, k: usize, i: usize, j: usize, coefficient: i32) {
    let key = (i.min(j), i.max(j));
    let slot = q
        .entry(blade)
        .or_default()
        .entry(k)
        .or_default()
        .entry(key)
        .or_default();
    *slot += coefficient;
}

fn drop_zeros(mut q: Quadratic) -> Quadratic {
    for per_k in q.values_mut() {
        for pairs in per_k.values_mut() {
            pairs.retain(|_, c| *c != 0);
        }
        per_k.retain(|_, pairs| !pairs.is_empty());
    }
    q.retain(|_, per_k| !per_k.is_empty());
    q
}

/// `A * f(A)` expanded symbolically with like terms collected, `f` an involution:
/// with `f` the reverse, `A ~A`, whose non-scalar parts cancel for versor-like types.
pub fn quadratic_self(metric: &Metric, blades: &[Blade], involution: Involution) -> Quadratic {
    let mut q = Quadratic::new();
    for (i, &a) in blades.iter().enumerate() {
        for (j, &b) in blades.iter().enumerate() {
            let (sign, blade) = metric.geometric(a, b);
            if sign != 0 {
                add_term(&mut q, blade, 0, i, j, (sign * involution.sign(b)) as i32);
            }
        }
    }
    drop_zeros(q)
}

/// The sandwich `v x ~v` (even `v`) or `v x^ ~v` (odd `v`, x^ the grade involution)
/// expanded symbolically: for each output blade and each component of `x`, a quadratic
/// form in `v`'s components with like terms collected.
pub fn sandwich(metric: &Metric, versor: &[Blade], odd: bool, x: &[Blade]) -> Quadratic {
    let twist = if odd {
        Involution::GradeInvolution
    } else {
        Involution::Identity
    };
    let mut q = Quadratic::new();
    for (i, &vi) in versor.iter().enumerate() {
        for (k, &xk) in x.iter().enumerate() {
            let (s1, left) = metric.geometric(vi, xk);
            if s1 == 0 {
                continue;
            }
            for (j, &vj) in versor.iter().enumerate() {
                let (s2, blade) = metric.geometric(left, vj);
                if s2 == 0 {
                    continue;
                }
                let coefficient = s1 * s2 * twist.sign(xk) * Involution::Reverse.sign(vj);
                add_term(&mut q, blade, k, i, j, coefficient as i32);
            }
        }
    }
    drop_zeros(q)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::{canonical_blades, grade};

    fn g3() -> Metric {
        Metric::new(vec![1, 1, 1])
    }

    fn of_grade(n: usize, keep: impl Fn(u32) -> bool) -> Vec<Blade> {
        canonical_blades(n)
            .into_iter()
            .filter(|&b| keep(grade(b)))
            .collect()
    }

    #[test]
    fn rotor_times_rotor_is_sixteen_terms_on_four_outputs() {
        let even = of_grade(3, |g| g % 2 == 0);
        let terms = bilinear(&g3(), ProductKind::Geometric, &even, &even);
        assert_eq!(terms.len(), 4);
        assert_eq!(terms.values().map(Vec::len).sum::<usize>(), 16);
    }

    #[test]
    fn full_products_have_n_squared_terms() {
        for n in 1..=6 {
            let all = canonical_blades(n);
            let metric = Metric::new(vec![1; n]);
            let terms = bilinear(&metric, ProductKind::Geometric, &all, &all);
            assert_eq!(terms.values().map(Vec::len).sum::<usize>(), 1 << (2 * n));
        }
    }

    #[test]
    fn rotor_reverse_self_product_is_scalar_in_g3_but_not_in_g4() {
        let even3 = of_grade(3, |g| g % 2 == 0);
        let q3 = quadratic_self(&g3(), &even3, Involution::Reverse);
        assert_eq!(q3.keys().copied().collect::<Vec<_>>(), vec![0]);
        let even4 = of_grade(4, |g| g % 2 == 0);
        let q4 = quadratic_self(&Metric::new(vec![1; 4]), &even4, Involution::Reverse);
        assert_eq!(q4.keys().copied().collect::<Vec<_>>(), vec![0, 0b1111]);
    }

    #[test]
    fn rotor_on_vector_sandwich_is_a_quadratic_form_onto_vectors() {
        let even = of_grade(3, |g| g % 2 == 0);
        let vector = of_grade(3, |g| g == 1);
        let q = sandwich(&g3(), &even, false, &vector);
        assert!(q.keys().all(|&b| grade(b) == 1));
        // e1 -> e1 picks up s^2 - e12^2 - e13^2 + e23^2.
        let diagonal = &q[&0b001][&0];
        assert_eq!(diagonal[&(0, 0)], 1);
        assert_eq!(diagonal[&(1, 1)], -1);
        assert_eq!(diagonal[&(2, 2)], -1);
        assert_eq!(diagonal[&(3, 3)], 1);
        assert_eq!(diagonal.len(), 4);
    }
}
