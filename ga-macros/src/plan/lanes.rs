//! Products of small types as four-lane SIMD, planned from the sign table.
//!
//! When both operands and the result have at most four components, a product is a sum
//! over one operand's components (the *broadcast* side) of a permuted, sign-flipped copy of
//! the other operand (the *gathered* side) times that component in every lane:
//!
//! ```text
//! out = sum_j  negate_j(swizzle_j(gathered)) * splat(broadcast_j)
//! ```
//!
//! Each output lane takes at most one term from each column, because the blade of the
//! gathered factor is fixed by the output blade and the broadcast blade. This is the shape
//! of hand-written SSE quaternion products; here it falls out of the same term lists as the
//! scalar form, so no product is written by hand. [`LaneProduct::counts`] prices the form
//! for the cost model in [`super::cost`].

use super::cost::OpCounts;
use super::terms::Term;
use crate::algebra::Blade;
use std::collections::BTreeMap;

/// The lanes of one SIMD register.
pub const LANES: usize = 4;

/// Which operand is broadcast one component at a time.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// `self`.
    Lhs,
    /// `rhs`.
    Rhs,
}

/// One broadcast component and what it multiplies in each output lane.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Column {
    /// The component of the broadcast operand.
    pub broadcast: usize,
    /// For each lane, the gathered operand's lane that lands there (`None`: no term).
    pub gather: [Option<usize>; LANES],
    /// Lanes whose term has a negative sign.
    pub negate: [bool; LANES],
}

impl Column {
    /// The swizzle of the gathered register, lanes without a term filled so as to keep
    /// the identity where possible; `None` if the register is used as it is.
    pub fn swizzle(&self, gathered_len: usize) -> Option<[usize; LANES]> {
        let mut order = [0; LANES];
        for (lane, slot) in order.iter_mut().enumerate() {
            *slot = match self.gather[lane] {
                Some(source) => source,
                // A padding lane of the gathered register holds zero.
                None if gathered_len < LANES => gathered_len,
                None => lane,
            };
        }
        (order != [0, 1, 2, 3]).then_some(order)
    }

    /// Lanes that must be cleared: no term, and no zero padding to read instead.
    pub fn mask(&self, gathered_len: usize, outputs: usize) -> Option<[bool; LANES]> {
        if gathered_len < LANES {
            return None;
        }
        let keep: [bool; LANES] =
            std::array::from_fn(|lane| lane >= outputs || self.gather[lane].is_some());
        (keep != [true; LANES]).then_some(keep)
    }

    /// Whether every term of the column is negative: then it is subtracted, not flipped.
    pub fn all_negative(&self, outputs: usize) -> bool {
        (0..outputs)
            .filter(|&lane| self.gather[lane].is_some())
            .all(|lane| self.negate[lane])
    }

    /// Lanes to flip, if the signs are mixed.
    pub fn flips(&self, outputs: usize) -> Option<[bool; LANES]> {
        if self.all_negative(outputs) || self.negate.iter().all(|n| !n) {
            None
        } else {
            Some(std::array::from_fn(|lane| {
                lane < outputs && self.gather[lane].is_some() && self.negate[lane]
            }))
        }
    }
}

/// A product written as broadcast-multiply-accumulate columns.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct LaneProduct {
    /// The operand read one component at a time.
    pub broadcast: Side,
    /// The components of the gathered operand (its register is zero-padded above them).
    pub gathered_len: usize,
    /// The components of the result: lanes `0..outputs`.
    pub outputs: usize,
    /// One per broadcast component that has terms, in component order.
    pub columns: Vec<Column>,
}

impl LaneProduct {
    /// The lane form of a product with these terms (keyed by output blade), if all three
    /// types fit in one register.
    pub fn new(
        terms: &BTreeMap<Blade, Vec<Term>>,
        output: &[Blade],
        lhs_len: usize,
        rhs_len: usize,
        broadcast: Side,
    ) -> Option<LaneProduct> {
        if lhs_len > LANES || rhs_len > LANES || output.len() > LANES || terms.is_empty() {
            return None;
        }
        let gathered_len = match broadcast {
            Side::Lhs => rhs_len,
            Side::Rhs => lhs_len,
        };
        let mut columns: BTreeMap<usize, Column> = BTreeMap::new();
        for (lane, blade) in output.iter().enumerate() {
            for term in terms.get(blade).into_iter().flatten() {
                let (b, g) = match broadcast {
                    Side::Lhs => (term.lhs, term.rhs),
                    Side::Rhs => (term.rhs, term.lhs),
                };
                let column = columns.entry(b).or_insert_with(|| Column {
                    broadcast: b,
                    gather: [None; LANES],
                    negate: [false; LANES],
                });
                column.gather[lane] = Some(g);
                column.negate[lane] = term.sign < 0;
            }
        }
        Some(LaneProduct {
            broadcast,
            gathered_len,
            outputs: output.len(),
            columns: columns.into_values().collect(),
        })
    }

    /// The order in which the columns are summed (columns with mixed or positive signs
    /// first, then those subtracted whole), shared by the SIMD body and its scalar mirror.
    pub fn sum_order(&self) -> Vec<usize> {
        let (mut order, negative): (Vec<usize>, Vec<usize>) =
            (0..self.columns.len()).partition(|&k| !self.columns[k].all_negative(self.outputs));
        order.extend(negative);
        order
    }

    /// Instructions per item: packing the gathered operand when it is not a full
    /// register, a broadcast per column, a swizzle, flip or mask where the column needs
    /// one, a multiply per column, an addition between columns, and unpacking a result
    /// narrower than a register.
    pub fn counts(&self) -> OpCounts {
        let mut counts = OpCounts {
            shuffle: usize::from(self.gathered_len < LANES),
            ..OpCounts::default()
        };
        for column in &self.columns {
            counts.shuffle += 1;
            counts.shuffle += usize::from(column.swizzle(self.gathered_len).is_some());
            counts.logic += usize::from(column.flips(self.outputs).is_some());
            counts.logic += usize::from(column.mask(self.gathered_len, self.outputs).is_some());
            counts.mul += 1;
        }
        counts.add = self.columns.len().saturating_sub(1);
        if self.outputs < LANES {
            counts.shuffle += self.outputs - 1;
        }
        counts
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::algebra::{canonical_blades, grade, Metric, ProductKind};
    use crate::plan::bilinear;
    use crate::plan::cost::scalar_product_counts;

    fn even3() -> Vec<Blade> {
        canonical_blades(3)
            .into_iter()
            .filter(|&b| grade(b).is_multiple_of(2))
            .collect()
    }

    #[test]
    fn quaternion_product_is_four_columns_and_beats_the_scalar_form_on_both_layouts() {
        let even = even3();
        let terms = bilinear(
            &Metric::new(vec![1, 1, 1]),
            ProductKind::Geometric,
            &even,
            &even,
        );
        let lanes = LaneProduct::new(&terms, &even, 4, 4, Side::Rhs).expect("fits");
        assert_eq!(lanes.columns.len(), 4);
        // The scalar column multiplies the left operand as it is.
        assert_eq!(lanes.columns[0].swizzle(4), None);
        assert_eq!(lanes.columns[0].flips(4), None);
        let counts = lanes.counts();
        assert_eq!((counts.mul, counts.add), (4, 3));
        let scalar = scalar_product_counts(terms.values().map(Vec::len));
        assert!(counts.beats(&scalar));
    }

    #[test]
    fn every_term_lands_in_exactly_one_column_lane() {
        for metric in [vec![1, 1, 1], vec![1, -1, 0], vec![-1, -1, -1]] {
            let metric = Metric::new(metric);
            let even = even3();
            for kind in ProductKind::ALL {
                let terms = bilinear(&metric, kind, &even, &even);
                // The blades the product lands on (the regressive product's are odd).
                let output: Vec<Blade> = terms.keys().copied().collect();
                let Some(lanes) = LaneProduct::new(&terms, &output, 4, 4, Side::Lhs) else {
                    continue;
                };
                let placed: usize = lanes
                    .columns
                    .iter()
                    .map(|c| c.gather.iter().flatten().count())
                    .sum();
                assert_eq!(placed, terms.values().map(Vec::len).sum::<usize>());
            }
        }
    }
}
