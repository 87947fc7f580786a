//! What an emitted form costs: instructions counted by kind, turned into cycles per item on
//! the two port layouts that x86-64 cores have today. A form is chosen only when it is
//! cheaper on both, so that a choice measured on one vendor's core cannot lose on the
//! other's.
//!
//! The layouts, from the vendors' optimisation manuals and uops.info:
//! - **Shared ports** (Intel Skylake through Sapphire Rapids): floating-point multiplies and
//!   additions, scalar or packed, issue on ports 0 and 1; shuffles on port 5 only; bitwise
//!   logic on 0, 1 and 5.
//! - **Split pipes** (AMD Zen 2 to Zen 5): two multiply pipes, two add pipes, shuffles on
//!   two pipes, logic on all four.
//!
//! Loads and stores are left out: they issue on ports of their own (two or three loads a
//! cycle) and bind neither form.

/// Instructions of one item, by the ports they need.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OpCounts {
    /// Multiplies (scalar or packed: the same port cost).
    pub mul: usize,
    /// Additions and subtractions.
    pub add: usize,
    /// Shuffles, broadcasts from a register and lane permutations.
    pub shuffle: usize,
    /// Bitwise logic: sign flips and lane masks.
    pub logic: usize,
}

impl OpCounts {
    fn total(&self) -> usize {
        self.mul + self.add + self.shuffle + self.logic
    }

    /// Cycles per item when multiplies and additions share two ports and shuffles have one.
    pub fn shared_ports_cycles(&self) -> f64 {
        let arithmetic = (self.mul + self.add) as f64 / 2.0;
        let shuffle = self.shuffle as f64;
        let all = self.total() as f64 / 3.0;
        arithmetic.max(shuffle).max(all)
    }

    /// Cycles per item with two multiply, two add and two shuffle pipes out of four.
    pub fn split_pipes_cycles(&self) -> f64 {
        let mul = self.mul as f64 / 2.0;
        let add = self.add as f64 / 2.0;
        let shuffle = self.shuffle as f64 / 2.0;
        let all = self.total() as f64 / 4.0;
        mul.max(add).max(shuffle).max(all)
    }

    /// Whether this form is cheaper than `other` on both layouts.
    pub fn beats(&self, other: &OpCounts) -> bool {
        self.shared_ports_cycles() < other.shared_ports_cycles()
            && self.split_pipes_cycles() < other.split_pipes_cycles()
    }
}

/// The straight-line scalar form of a bilinear product: one multiply per term, and per
/// output component one addition fewer than its terms.
pub fn scalar_product_counts(terms_per_output: impl IntoIterator<Item = usize>) -> OpCounts {
    let mut counts = OpCounts::default();
    for terms in terms_per_output {
        counts.mul += terms;
        counts.add += terms.saturating_sub(1);
    }
    counts
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quaternion_product_scalar_form_is_port_bound_at_fourteen_cycles_on_shared_ports() {
        let scalar = scalar_product_counts([4, 4, 4, 4]);
        assert_eq!((scalar.mul, scalar.add), (16, 12));
        assert_eq!(scalar.shared_ports_cycles(), 14.0);
        assert_eq!(scalar.split_pipes_cycles(), 8.0);
    }

    #[test]
    fn a_form_must_win_on_both_layouts() {
        // Few arithmetic ops but many shuffles: cheaper on split pipes, dearer on shared
        // ports, so it does not beat the scalar form.
        let shuffly = OpCounts {
            mul: 2,
            add: 2,
            shuffle: 8,
            logic: 0,
        };
        let scalar = scalar_product_counts([3, 3, 3]);
        assert!(shuffly.split_pipes_cycles() < scalar.split_pipes_cycles());
        assert!(!shuffly.beats(&scalar));
    }
}
