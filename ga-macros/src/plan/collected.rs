//! The collected form's coefficients as sums of pair products, with the partial sums that
//! several coefficients share computed once.
//!
//! A collected sandwich `v x ~v` multiplies each component of `x` by a coefficient that is
//! a signed sum of products `v[i] v[j]`. The coefficients of a rotor's diagonal repeat
//! partial sums: in G3, `s s + e23 e23 - e12 e12 - e13 e13` and `s s + e13 e13 - e12 e12 -
//! e23 e23` both hold `s s - e12 e12` and `e13 e13 - e23 e23` (up to sign), so computing
//! those two once saves two additions of the nine. [`CollectedSums::new`] finds such pairs
//! greedily, the most shared first, until no pair of summands appears in two coefficients.
//! The coefficients do not depend on `x`, so sharing never lengthens the path through `x`.

use std::collections::{BTreeMap, BTreeSet, HashMap};

use super::Quadratic;
use crate::algebra::Blade;

/// One summand of a coefficient: a pair product `v[i] v[j]` (`i <= j`) or a shared sum.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Summand {
    /// `v[i] v[j]`, doubled where [`CollectedSums::doubled`] says so.
    Pair(usize, usize),
    /// The shared sum at this index of [`CollectedSums::shared`].
    Shared(usize),
}

/// A partial sum used by several coefficients: `first + sign * second`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct SharedSum {
    /// The summand taken with a plus sign.
    pub first: Summand,
    /// The other summand.
    pub second: Summand,
    /// `1` for a sum, `-1` for a difference.
    pub sign: i32,
}

/// The pieces of a collected sandwich, from which the emitter writes its `let`s.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct CollectedSums {
    /// Pairs whose every coefficient is even: computed as `(v[i] + v[i]) * v[j]`, with the
    /// factor 2 taken out of their coefficients.
    pub doubled: BTreeSet<(usize, usize)>,
    /// Every pair product some coefficient uses.
    pub pairs: BTreeSet<(usize, usize)>,
    /// Shared partial sums, each defined before its first use.
    pub shared: Vec<SharedSum>,
    /// For each output blade and component `k` of `x`, the signed summands of `x[k]`'s
    /// coefficient.
    pub coefficients: BTreeMap<(Blade, usize), Vec<(i32, Summand)>>,
}

impl CollectedSums {
    /// The coefficients of `q` for the output blades in `operand`, with shared sums taken
    /// out.
    pub fn new(q: &Quadratic, operand: &[Blade]) -> CollectedSums {
        let mut uses: BTreeMap<(usize, usize), Vec<i32>> = BTreeMap::new();
        for (blade, per_k) in q {
            if operand.contains(blade) {
                for pairs in per_k.values() {
                    for (&pair, &c) in pairs {
                        uses.entry(pair).or_default().push(c);
                    }
                }
            }
        }
        let doubled: BTreeSet<(usize, usize)> = uses
            .iter()
            .filter(|(_, cs)| cs.iter().all(|c| c % 2 == 0))
            .map(|(&pair, _)| pair)
            .collect();
        let mut coefficients = BTreeMap::new();
        for (&blade, per_k) in q {
            if !operand.contains(&blade) {
                continue;
            }
            for (&k, pairs) in per_k {
                let terms: Vec<(i32, Summand)> = pairs
                    .iter()
                    .map(|(&(i, j), &c)| {
                        let c = if doubled.contains(&(i, j)) { c / 2 } else { c };
                        (c, Summand::Pair(i, j))
                    })
                    .collect();
                coefficients.insert((blade, k), terms);
            }
        }
        let mut sums = CollectedSums {
            doubled,
            pairs: uses.keys().copied().collect(),
            shared: Vec::new(),
            coefficients,
        };
        while let Some(shared) = sums.most_shared_pair() {
            sums.take_out(shared);
        }
        sums
    }

    /// Additions to compute every coefficient: the doublings, the shared sums, and the
    /// rest of each coefficient's sum.
    pub fn additions(&self) -> usize {
        let doublings: BTreeSet<usize> = self.doubled.iter().map(|&(i, _)| i).collect();
        doublings.len()
            + self.shared.len()
            + self
                .coefficients
                .values()
                .map(|terms| terms.len().saturating_sub(1))
                .sum::<usize>()
    }

    /// The pair of unit-coefficient summands (with their relative sign) found in the most
    /// coefficients, if some pair is found in two or more; ties go to the first in order.
    fn most_shared_pair(&self) -> Option<SharedSum> {
        // A hash map: this runs once per shared sum over every coefficient of every
        // collected sandwich, at expansion time. The pick below does not depend on its order.
        let mut counts: HashMap<(Summand, Summand, i32), usize> = HashMap::new();
        for terms in self.coefficients.values() {
            for (a, &(ca, first)) in terms.iter().enumerate() {
                if ca.abs() != 1 {
                    continue;
                }
                for &(cb, second) in &terms[a + 1..] {
                    if cb.abs() != 1 {
                        continue;
                    }
                    let (first, second) = if first < second {
                        (first, second)
                    } else {
                        (second, first)
                    };
                    *counts.entry((first, second, ca * cb)).or_default() += 1;
                }
            }
        }
        let (&(first, second, sign), _) = counts
            .iter()
            .filter(|&(_, &n)| n >= 2)
            .max_by(|(key_a, n_a), (key_b, n_b)| n_a.cmp(n_b).then(key_b.cmp(key_a)))?;
        Some(SharedSum {
            first,
            second,
            sign,
        })
    }

    /// Defines `shared` and puts it in place of its two summands wherever they appear with
    /// its relative sign.
    fn take_out(&mut self, shared: SharedSum) {
        let index = self.shared.len();
        self.shared.push(shared);
        for terms in self.coefficients.values_mut() {
            let find = |s: Summand| terms.iter().position(|&(c, t)| t == s && c.abs() == 1);
            let (Some(a), Some(b)) = (find(shared.first), find(shared.second)) else {
                continue;
            };
            let (ca, cb) = (terms[a].0, terms[b].0);
            if ca * cb != shared.sign {
                continue;
            }
            // ca first + cb second = ca (first + sign second).
            terms[a] = (ca, Summand::Shared(index));
            terms.remove(b);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::Metric;
    use crate::plan::sandwich;

    /// G3's rotor on a vector: the diagonal shares `s s - e12 e12` and `e13 e13 - e23 e23`.
    #[test]
    fn the_g3_rotor_diagonal_shares_two_differences() {
        let metric = Metric::new(vec![1, 1, 1]);
        let even: Vec<Blade> = vec![0b000, 0b011, 0b101, 0b110];
        let vector: Vec<Blade> = vec![0b001, 0b010, 0b100];
        let q = sandwich(&metric, &even, false, &vector);
        let sums = CollectedSums::new(&q, &vector);
        assert_eq!(
            sums.shared,
            vec![
                SharedSum {
                    first: Summand::Pair(0, 0),
                    second: Summand::Pair(1, 1),
                    sign: -1
                },
                SharedSum {
                    first: Summand::Pair(2, 2),
                    second: Summand::Pair(3, 3),
                    sign: -1
                },
            ]
        );
        // 3 doublings, 2 shared sums, 2 for the diagonal that shares them, 3 for the one
        // that does not, 1 for each of the six off-diagonal coefficients: 16, against 18.
        assert_eq!(sums.additions(), 16);
    }

    /// Every coefficient, expanded back through its shared sums, is the quadratic form's.
    #[test]
    fn shared_sums_expand_to_the_quadratic_form() {
        for signature in [
            vec![1, 1, 1],
            vec![1, 1, 1, 1],
            vec![0, 1, 1, 1],
            vec![1, -1, -1, -1],
        ] {
            let metric = Metric::new(signature.clone());
            let n = signature.len();
            let blades: Vec<Blade> = (0..1u32 << n).collect();
            let even: Vec<Blade> = blades
                .iter()
                .copied()
                .filter(|b| b.count_ones() % 2 == 0)
                .collect();
            let vector: Vec<Blade> = blades
                .iter()
                .copied()
                .filter(|b| b.count_ones() == 1)
                .collect();
            let q = sandwich(&metric, &even, false, &vector);
            let sums = CollectedSums::new(&q, &vector);
            for ((blade, k), terms) in &sums.coefficients {
                let mut expanded: BTreeMap<(usize, usize), i32> = BTreeMap::new();
                for &(c, s) in terms {
                    expand(&sums, s, c, &mut expanded);
                }
                let mut want: BTreeMap<(usize, usize), i32> = q[blade][k].clone();
                for (pair, c) in want.iter_mut() {
                    if sums.doubled.contains(pair) {
                        *c /= 2;
                    }
                }
                expanded.retain(|_, c| *c != 0);
                assert_eq!(expanded, want, "{signature:?}, blade {blade:b}, k {k}");
            }
        }
    }

    fn expand(sums: &CollectedSums, s: Summand, c: i32, out: &mut BTreeMap<(usize, usize), i32>) {
        match s {
            Summand::Pair(i, j) => *out.entry((i, j)).or_default() += c,
            Summand::Shared(index) => {
                let shared = sums.shared[index];
                expand(sums, shared.first, c, out);
                expand(sums, shared.second, c * shared.sign, out);
            }
        }
    }
}
