//! Which form a sandwich `v x ~v` is written in, chosen by the cost model.
//!
//! - **Collected**: the quadratic form in `v` expanded with like terms collected (best when
//!   one versor meets many `x`, and the form `sandwich_matrix` builds).
//! - **Chained**: two products through locals, for versors too large to expand.
//! - **Commutator**: for an even versor `v = s + B` whose non-scalar part `B` is a bivector
//!   with a scalar square (every algebra of dimension at most 3), with `C(x) = (Bx - xB)/2`:
//!   `v x ~v = <v ~v> x + 2 (s C(x) + C(C(x)))`, and `x + 2 (s C(x) + C(C(x)))` for a unit
//!   versor. Two small commutator products instead of a quadratic form: the shape of the
//!   cross-product formula for quaternions, derived in docs/derivations/sandwich.md. In
//!   `f32` its commutators can take four SIMD lanes ([`PairColumns`]).

use std::collections::BTreeMap;

use super::collected::CollectedSums;
use super::cost::{scalar_product_counts, OpCounts};
use super::lanes::LANES;
use super::terms::{bilinear, Term};
use super::{Plan, Quadratic, TypeId, TypeKind};
use crate::algebra::{grade, Blade, ProductKind};
use crate::spec::Scalar;

/// The commutator `C(x) = B x x` of the versor's bivector part with `x`, keyed by
/// output blade; `lhs` indexes the versor's components, `rhs` those of `x`.
pub type CommutatorTerms = BTreeMap<Blade, Vec<Term>>;

/// One column of a product of two registers, both swizzled: lane `i` gets
/// `sign[i] * a[a_order[i]] * b[b_order[i]]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PairColumn {
    /// Lanes of the versor's register.
    pub a_order: [usize; LANES],
    /// Lanes of the operand's register (its padding lane, zero, where no term lands).
    pub b_order: [usize; LANES],
    /// Lanes whose term is negative.
    pub negate: [bool; LANES],
    /// Lanes that hold a term.
    pub used: [bool; LANES],
}

impl PairColumn {
    /// Whether every term is negative (the column is subtracted).
    pub fn all_negative(&self) -> bool {
        (0..LANES).filter(|&l| self.used[l]).all(|l| self.negate[l])
    }

    /// Lanes to flip when the signs are mixed.
    pub fn flips(&self) -> Option<[bool; LANES]> {
        let any = (0..LANES).any(|l| self.used[l] && self.negate[l]);
        (any && !self.all_negative())
            .then(|| std::array::from_fn(|l| self.used[l] && self.negate[l]))
    }
}

/// A commutator map `x -> C(x)` as columns of swizzled pairs, for an `x` with fewer than
/// four components (its padding lane reads zero where a column has no term).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct PairColumns {
    /// The columns.
    pub columns: Vec<PairColumn>,
    /// The components of `x` and of `C(x)`.
    pub len: usize,
}

const IDENTITY: [usize; LANES] = [0, 1, 2, 3];

impl PairColumns {
    /// The cheapest assignment of each lane's terms to columns (tried exhaustively: at
    /// most three lanes of at most three terms).
    pub fn new(terms: &CommutatorTerms, x: &[Blade]) -> Option<PairColumns> {
        let len = x.len();
        if len >= LANES {
            return None;
        }
        let lanes: Vec<Vec<Term>> = x
            .iter()
            .map(|b| terms.get(b).cloned().unwrap_or_default())
            .collect();
        let width = lanes.iter().map(Vec::len).max()?;
        if width == 0 || width > 3 {
            return None;
        }
        let mut best: Option<(usize, PairColumns)> = None;
        let mut choice = vec![0usize; len];
        let permutations = permutations(width);
        loop {
            let candidate = assemble(&lanes, &choice, &permutations, width, len);
            let cost = candidate.swizzle_count() * 2 + candidate.flip_count();
            if best.as_ref().is_none_or(|(c, _)| cost < *c) {
                best = Some((cost, candidate));
            }
            // The next choice of permutation per lane (an odometer).
            let mut lane = 0;
            loop {
                if lane == len {
                    return best.map(|(_, c)| c);
                }
                choice[lane] += 1;
                if choice[lane] < permutations.len() {
                    break;
                }
                choice[lane] = 0;
                lane += 1;
            }
        }
    }

    /// The distinct swizzles of the versor's register (computed once, shared by every
    /// application of the map) and of the operand's register (one set per application).
    pub fn swizzles(&self) -> (Vec<[usize; LANES]>, Vec<[usize; LANES]>) {
        let distinct = |orders: Vec<[usize; LANES]>| {
            let mut orders: Vec<_> = orders.into_iter().filter(|o| *o != IDENTITY).collect();
            orders.sort_unstable();
            orders.dedup();
            orders
        };
        (
            distinct(self.columns.iter().map(|c| c.a_order).collect()),
            distinct(self.columns.iter().map(|c| c.b_order).collect()),
        )
    }

    fn swizzle_count(&self) -> usize {
        let (a, b) = self.swizzles();
        a.len() + b.len()
    }

    fn flip_count(&self) -> usize {
        self.columns.iter().filter(|c| c.flips().is_some()).count()
    }
}

fn permutations(k: usize) -> Vec<Vec<usize>> {
    match k {
        1 => vec![vec![0]],
        2 => vec![vec![0, 1], vec![1, 0]],
        _ => vec![
            vec![0, 1, 2],
            vec![0, 2, 1],
            vec![1, 0, 2],
            vec![1, 2, 0],
            vec![2, 0, 1],
            vec![2, 1, 0],
        ],
    }
}

fn assemble(
    lanes: &[Vec<Term>],
    choice: &[usize],
    permutations: &[Vec<usize>],
    width: usize,
    len: usize,
) -> PairColumns {
    let pad = len;
    let mut columns: Vec<PairColumn> = (0..width)
        .map(|_| PairColumn {
            a_order: IDENTITY,
            b_order: [pad; LANES],
            negate: [false; LANES],
            used: [false; LANES],
        })
        .collect();
    for (lane, terms) in lanes.iter().enumerate() {
        let permutation = &permutations[choice[lane]];
        for (slot, column) in columns.iter_mut().enumerate() {
            let Some(term) = permutation.get(slot).and_then(|&i| terms.get(i)) else {
                continue;
            };
            column.a_order[lane] = term.lhs;
            column.b_order[lane] = term.rhs;
            column.negate[lane] = term.sign < 0;
            column.used[lane] = true;
        }
    }
    for column in &mut columns {
        // Lanes without a term read the zero padding of `x`; the versor's lane there is
        // free, so it is chosen to keep the versor's swizzle the identity if it can be.
        for lane in 0..LANES {
            if !column.used[lane] {
                column.a_order[lane] = lane;
            }
        }
        if (0..LANES).all(|l| column.b_order[l] == l || (!column.used[l] && l >= len)) {
            column.b_order = IDENTITY;
        }
    }
    PairColumns { columns, len }
}

/// The form of one sandwich.
#[derive(Clone, Debug)]
pub enum SandwichForm {
    /// The collected quadratic form, as its coefficients' sums.
    Collected(CollectedSums),
    /// Two chained products.
    Chained,
    /// Commutators, in scalar code or (with columns) in SIMD lanes.
    Commutator {
        /// The terms of `C(x)`.
        terms: CommutatorTerms,
        /// The SIMD form of `C`, when it is chosen.
        lanes: Option<PairColumns>,
    },
}

impl Plan {
    /// The terms of `C(x)` when `v = s + B` is an even versor whose bivector part squares
    /// to a scalar and `C(x)` stays within `x`'s type.
    pub fn commutator_terms(&self, v: TypeId, x: TypeId) -> Option<CommutatorTerms> {
        let versor = &self.types.get(v).blades;
        let operand = &self.types.get(x).blades;
        let shape_ok = self.types.get(v).kind == TypeKind::Even
            && self.metric.dimension() <= 3
            && versor.first() == Some(&0)
            && versor[1..].iter().all(|&b| grade(b) == 2);
        if !shape_ok {
            return None;
        }
        // The scalar component contributes nothing to a commutator: only the bivector part
        // is kept, and `lhs` keeps indexing the versor's components.
        let mut terms = bilinear(&self.metric, ProductKind::Commutator, versor, operand);
        for list in terms.values_mut() {
            list.retain(|t| t.lhs != 0);
        }
        terms.retain(|_, list| !list.is_empty());
        terms.keys().all(|b| operand.contains(b)).then_some(terms)
    }

    /// The cheapest form of `v x ~v` (exact for any versor) or, with `unit`, of the same
    /// map for a unit versor (always the commutator form, in lanes where they are cheaper):
    /// see [`pick`] for how the exact sandwich's form is chosen.
    pub fn sandwich_form(&self, v: TypeId, x: TypeId, unit: bool) -> Option<SandwichForm> {
        let commutator = self.commutator_terms(v, x);
        if unit {
            let terms = commutator?;
            let lanes = self.commutator_lanes(v, x, &terms, true);
            return Some(SandwichForm::Commutator { terms, lanes });
        }
        let mut candidates: Vec<(FormCost, SandwichForm)> = Vec::new();
        if let Some(q) = self.collected_sandwich(v, x) {
            let operand = &self.types.get(x).blades;
            let sums = CollectedSums::new(&q, operand);
            let cost = collected_cost(&sums, operand);
            candidates.push((cost, SandwichForm::Collected(sums)));
        }
        candidates.push((self.chained_cost(v, x), SandwichForm::Chained));
        if let Some(terms) = commutator {
            let scalar = self.commutator_cost(v, x, &terms, false);
            let lanes = self.commutator_lanes(v, x, &terms, false);
            let cost = lanes
                .as_ref()
                .map_or(scalar, |lanes| lane_sandwich_cost(lanes, false));
            candidates.push((cost, SandwichForm::Commutator { terms, lanes }));
        }
        pick(candidates)
    }

    /// The collected form, if small enough to expand.
    fn collected_sandwich(&self, v: TypeId, x: TypeId) -> Option<Quadratic> {
        /// Above this size (|v|^2 |x|) the symbolic expansion is not attempted: it would
        /// cost more multiplies than two chained products anyway (G6 rotors).
        const FUSED_BUDGET: usize = 2048;
        let versor = &self.types.get(v).blades;
        let operand = &self.types.get(x).blades;
        (versor.len() * versor.len() * operand.len() <= FUSED_BUDGET).then(|| {
            let odd = matches!(self.types.get(v).kind, TypeKind::Grade(1) | TypeKind::Odd);
            super::sandwich(&self.metric, versor, odd, operand)
        })
    }

    fn chained_cost(&self, v: TypeId, x: TypeId) -> FormCost {
        let versor = &self.types.get(v).blades;
        let operand = &self.types.get(x).blades;
        let first = bilinear(&self.metric, ProductKind::Geometric, versor, operand);
        let middle: Vec<Blade> = first.keys().copied().collect();
        let second = bilinear(&self.metric, ProductKind::Geometric, &middle, versor);
        let last: Vec<usize> = second
            .iter()
            .filter(|(b, _)| operand.contains(b))
            .map(|(_, t)| t.len())
            .collect();
        let mut counts = scalar_product_counts(first.values().map(Vec::len));
        let second_counts = scalar_product_counts(last.iter().copied());
        counts.mul += second_counts.mul;
        counts.add += second_counts.add;
        let widest = |lens: &mut dyn Iterator<Item = usize>| lens.max().unwrap_or(1);
        FormCost {
            counts,
            latency: arithmetic_latency(2, sum_depth(widest(&mut first.values().map(Vec::len))))
                + arithmetic_latency(0, sum_depth(widest(&mut last.iter().copied()))),
        }
    }

    fn commutator_cost(
        &self,
        v: TypeId,
        x: TypeId,
        terms: &CommutatorTerms,
        unit: bool,
    ) -> FormCost {
        let outputs = self.types.get(x).blades.len();
        let once = scalar_product_counts(terms.values().map(Vec::len));
        let versor = self.types.get(v).blades.len();
        let used = terms.len();
        let mut counts = OpCounts {
            // C(x), C(c) and 2s c; the exact form adds <v ~v> and <v ~v> x.
            mul: 2 * once.mul + used,
            // C(x), C(c), `2s` and the final sums `((x + 2s c) + C(c)) + C(c)`.
            add: 2 * once.add + 1 + 3 * used,
            ..OpCounts::default()
        };
        if !unit {
            // The doubled bivector components and `<v ~v>`; one final sum fewer.
            counts.mul += versor + outputs;
            counts.add += (versor - 1) + (versor - 1) - used;
        }
        let width = terms.values().map(Vec::len).max().unwrap_or(1);
        // c = C(x), then C(c), then the final sums (two for a unit versor).
        let final_sums = if unit { 2 } else { 1 };
        FormCost {
            counts,
            latency: arithmetic_latency(2, 2 * sum_depth(width) + final_sums),
        }
    }

    fn commutator_lanes(
        &self,
        v: TypeId,
        x: TypeId,
        terms: &CommutatorTerms,
        unit: bool,
    ) -> Option<PairColumns> {
        if self.scalar != Scalar::F32 || self.types.get(v).blades.len() != LANES {
            return None;
        }
        let lanes = PairColumns::new(terms, &self.types.get(x).blades)?;
        let cost = lane_sandwich_cost(&lanes, unit);
        cost.counts
            .beats(&self.commutator_cost(v, x, terms, unit).counts)
            .then_some(lanes)
    }
}

/// What one form costs: its instructions, and its latency along `x` in cycles.
#[derive(Clone, Copy, Debug)]
pub struct FormCost {
    /// Instructions per item.
    pub counts: OpCounts,
    /// Cycles from `x` to the result.
    pub latency: usize,
}

/// Cycles of a dependent path of shuffles and arithmetic (4 cycles a multiply or an add
/// on the shared-ports layout, 1 a shuffle).
fn arithmetic_latency(shuffles: usize, arithmetic: usize) -> usize {
    shuffles + 4 * arithmetic
}

/// The depth of a balanced sum of `terms` terms: a multiply, then the additions.
fn sum_depth(terms: usize) -> usize {
    1 + terms.next_power_of_two().trailing_zeros() as usize
}

/// Latency along `x` first: of the forms within a quarter of the lowest latency, the one
/// with the best throughput on the worse of the two port layouts. Latency leads because a
/// chain of sandwiches cannot hide it, while LLVM packs the collected form's last stage
/// (a small matrix times `x`) into vector instructions itself, which this count does not
/// see: the collected G3 `f32` form measured faster in a batch than the commutator form in
/// lanes, though the count favours the lanes (BENCHMARKS.md, "Choices in the generated
/// code").
fn pick(candidates: Vec<(FormCost, SandwichForm)>) -> Option<SandwichForm> {
    let throughput = |c: &FormCost| {
        c.counts
            .shared_ports_cycles()
            .max(c.counts.split_pipes_cycles())
    };
    let fastest_latency = candidates.iter().map(|(c, _)| c.latency).min()?;
    candidates
        .into_iter()
        .filter(|(c, _)| 4 * c.latency <= 5 * fastest_latency)
        .min_by(|(a, _), (b, _)| throughput(a).total_cmp(&throughput(b)))
        .map(|(_, form)| form)
}

/// The collected form: the pair products (one multiply each), the additions of
/// [`CollectedSums`] (doublings, shared partial sums, the rest of each coefficient), one
/// multiply per coefficient, and the sums; along `x`, one multiply and the final sum.
pub fn collected_cost(sums: &CollectedSums, operand: &[Blade]) -> FormCost {
    let mut counts = OpCounts {
        mul: sums.pairs.len() + sums.coefficients.len(),
        add: sums.additions(),
        ..OpCounts::default()
    };
    let mut widest = 1;
    for blade in operand {
        let per_blade = sums
            .coefficients
            .range((*blade, 0)..=(*blade, usize::MAX))
            .count();
        counts.add += per_blade.saturating_sub(1);
        widest = widest.max(per_blade);
    }
    FormCost {
        counts,
        latency: arithmetic_latency(0, sum_depth(widest)),
    }
}

/// The lane form: pack `x`; the versor's swizzled and signed lanes; two applications of
/// `C` (each with its own swizzles of the operand); `2s`; the final sums (three for a unit
/// versor, `((x + 2s c) + C(c)) + C(c)`); for the exact form also the doubled lanes,
/// `<v ~v>` (a multiply and a two-step horizontal sum) and its product with `x`; unpacking
/// the result. Along `x`: pack, then two rounds of swizzle, multiply and add, then the
/// final sums, then unpack.
pub fn lane_sandwich_cost(lanes: &PairColumns, unit: bool) -> FormCost {
    let (a, b) = lanes.swizzles();
    let columns = lanes.columns.len();
    let mut counts = OpCounts {
        mul: 2 * columns + 1,
        add: 2 * (columns - 1) + 4,
        shuffle: 1 + a.len() + 2 * b.len() + 1 + 1,
        logic: lanes.flip_count(),
    };
    if !unit {
        // The doubled lanes, `<v ~v>` and its product; one final sum fewer.
        counts.mul += columns + 2;
        counts.add += 1;
        counts.shuffle += 2;
    }
    let depth = sum_depth(columns);
    let final_sums = if unit { 2 } else { 1 };
    FormCost {
        counts,
        latency: arithmetic_latency(4, 2 * depth + final_sums),
    }
}
