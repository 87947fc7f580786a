//! The product plan: which types exist, which products and operations are emitted, and
//! for each product the exact list of non-zero terms. Plain data, no syn or quote.

pub mod collected;
pub mod cost;
mod exp_log_form;
pub mod lanes;
pub mod sandwich_form;
mod terms;
mod types;

pub use exp_log_form::ExpLogForm;
pub use lanes::{LaneProduct, Side};
pub use sandwich_form::{PairColumns, SandwichForm};
pub use terms::{bilinear, quadratic_self, sandwich, Quadratic};
pub use types::{Output, TypeId, TypeKind, Types};

use std::collections::BTreeSet;

use crate::algebra::{Metric, ProductKind};
use crate::spec::{Op, Scalar, Spec, TypeRequest};

/// Everything the emitter writes, decided up front.
pub struct Plan {
    pub metric: Metric,
    pub scalar: Scalar,
    pub types: Types,
    /// The struct types written out, in declaration order.
    pub emitted: Vec<TypeId>,
    /// The types whose pairs get products and sums (the listed types, or all).
    pub paired: Vec<TypeId>,
    /// Products between `paired` types (and the scalar).
    pub products: Vec<ProductKind>,
    /// The operations that are emitted.
    pub ops: BTreeSet<Op>,
    /// For a batch module: the number of lanes of each scalar (`wide::f32x4` for 4).
    pub lanes: Option<usize>,
    /// Whether the spec allows SIMD bodies (`simd: false` does not).
    pub simd: bool,
}

impl Plan {
    /// Whether an operation is emitted.
    pub fn has(&self, op: Op) -> bool {
        self.ops.contains(&op)
    }

    /// Builds the plan for a validated spec: the requested types plus every type their
    /// products and operations return.
    pub fn new(spec: &Spec) -> Plan {
        let metric = spec.metric.clone();
        let dimension = metric.dimension();
        let types = Types::new(dimension, spec.types.as_deref().unwrap_or(&[]));
        let ops: BTreeSet<Op> = match &spec.ops {
            Some(ops) => ops.clone(),
            None => Op::ALL.iter().copied().collect(),
        };
        let products: Vec<ProductKind> = ProductKind::ALL
            .into_iter()
            .filter(|kind| ops.contains(&product_op(*kind)))
            .collect();
        let paired: Vec<TypeId> = match &spec.types {
            None => types.builtin_ids(),
            Some(requests) => requests.iter().map(|r| types.id_of_request(r)).collect(),
        };
        let mut plan = Plan {
            metric,
            scalar: spec.scalar,
            types,
            emitted: Vec::new(),
            paired,
            products,
            ops,
            lanes: None,
            simd: spec.simd,
        };
        plan.emitted = plan.needed_types();
        plan
    }

    /// The plan of a structure-of-arrays batch module: the same types with `lanes`-wide
    /// scalars, and only the operations that are straight-line code (products, sums,
    /// involutions, duals, projections, sandwiches); nothing that branches per item.
    pub fn batch(&self, lanes: usize) -> Plan {
        const STRAIGHT_LINE: [Op; 15] = [
            Op::Geometric,
            Op::Outer,
            Op::Inner,
            Op::LeftContraction,
            Op::RightContraction,
            Op::ScalarProduct,
            Op::Commutator,
            Op::Regressive,
            Op::Add,
            Op::Reverse,
            Op::GradeInvolution,
            Op::Conjugate,
            Op::Dual,
            Op::Grade,
            Op::Sandwich,
        ];
        let ops: BTreeSet<Op> = STRAIGHT_LINE
            .into_iter()
            .filter(|op| self.has(*op))
            .collect();
        let mut batch = Plan {
            metric: self.metric.clone(),
            scalar: self.scalar,
            types: self.types.clone(),
            emitted: Vec::new(),
            paired: self.paired.clone(),
            products: self.products.clone(),
            ops,
            lanes: Some(lanes),
            simd: self.simd,
        };
        batch.emitted = batch.needed_types();
        batch
    }

    /// The paired types closed under what their products and operations return.
    fn needed_types(&self) -> Vec<TypeId> {
        let mut needed: BTreeSet<TypeId> = self.paired.iter().copied().collect();
        for (a, b) in self.operand_pairs() {
            for &kind in &self.products {
                if let Output::Type(t) = self.product_output(kind, a, b) {
                    needed.insert(t);
                }
            }
            if self.has(Op::Add) {
                if let Output::Type(t) = self.sum_output(a, b) {
                    needed.insert(t);
                }
            }
        }
        let unary_sources: Vec<TypeId> = needed.iter().copied().collect();
        for t in unary_sources {
            for extra in self.unary_needs(t) {
                needed.insert(extra);
            }
        }
        needed.remove(&TypeId::SCALAR);
        needed.into_iter().collect()
    }

    /// The operand pairs that get products and sums: the scalar and every paired type,
    /// both ways, in the order the emitters write them (scalar with scalar left out).
    pub fn operand_pairs(&self) -> Vec<(TypeId, TypeId)> {
        let operands: Vec<TypeId> = std::iter::once(TypeId::SCALAR)
            .chain(self.paired.iter().copied())
            .collect();
        let mut pairs = Vec::new();
        for &a in &operands {
            for &b in &operands {
                if !(a == TypeId::SCALAR && b == TypeId::SCALAR) {
                    pairs.push((a, b));
                }
            }
        }
        pairs
    }

    /// Types that the unary operations of `t` return or use internally.
    fn unary_needs(&self, t: TypeId) -> Vec<TypeId> {
        let n = self.metric.dimension();
        let blades = &self.types.get(t).blades;
        let mut needs = Vec::new();
        let mut push = |output: Output| {
            if let Output::Type(id) = output {
                needs.push(id);
            }
        };
        if self.has(Op::Dual) {
            push(
                self.types
                    .smallest_holding(blades.iter().map(|&b| self.metric.dual(b).1)),
            );
            push(
                self.types
                    .smallest_holding(blades.iter().map(|&b| self.metric.undual(b).1)),
            );
        }
        if self.has(Op::Grade) {
            for k in self.types.grades_of(t) {
                if k > 0 {
                    needs.push(TypeId::grade(k));
                }
            }
            if self.types.get(t).kind == TypeKind::Multivector {
                needs.extend([TypeId::even(n), TypeId::odd(n)]);
            }
        }
        if self.has(Op::Inverse) {
            if let Output::Type(id) = self.inverse_output(t) {
                needs.push(id);
            }
            if !self.has_scalar_self_product(t) {
                needs.push(TypeId::multivector(n));
            }
        }
        let kind = self.types.get(t).kind;
        if kind == TypeKind::Grade(2) && (self.has(Op::Exp) || self.has(Op::Factor)) {
            needs.push(TypeId::even(n));
            needs.push(TypeId::grade(1));
            if (4..=5).contains(&n) {
                needs.push(TypeId::grade(4));
            }
            if n >= 6 {
                needs.push(TypeId::multivector(n));
            }
        }
        if self.has(Op::Factor) && matches!(kind, TypeKind::Grade(_)) {
            needs.push(TypeId::grade(1));
            needs.push(TypeId::multivector(n));
        }
        if kind == TypeKind::Even && self.has(Op::Log) && (2..=4).contains(&n) {
            needs.push(TypeId::grade(2));
            if n == 4 {
                needs.push(TypeId::grade(4));
            }
        }
        needs
    }

    /// The output of a product of two types.
    pub fn product_output(&self, kind: ProductKind, a: TypeId, b: TypeId) -> Output {
        let terms = bilinear(
            &self.metric,
            kind,
            &self.types.get(a).blades,
            &self.types.get(b).blades,
        );
        self.types
            .smallest_holding_preferring(terms.keys().copied(), &[a, b])
    }

    /// The output of `a + b`: the smallest type holding both.
    pub fn sum_output(&self, a: TypeId, b: TypeId) -> Output {
        let blades = self
            .types
            .get(a)
            .blades
            .iter()
            .chain(&self.types.get(b).blades)
            .copied();
        self.types.smallest_holding_preferring(blades, &[a, b])
    }

    /// Whether `A ~A` is a scalar for every `A` of this type, so that the inverse is
    /// `~A / <A ~A>`.
    pub fn has_scalar_self_product(&self, t: TypeId) -> bool {
        let q = quadratic_self(
            &self.metric,
            &self.types.get(t).blades,
            crate::algebra::Involution::Reverse,
        );
        q.keys().all(|&blade| blade == 0)
    }

    /// Whether `A ~A` is `s + p I` for every `A` of this type, with `p` not always zero,
    /// in a projective algebra (3D PGA's motors and lines): `I` null, its own reverse,
    /// commuting with every blade of the type, and `A I` again of the type. Then
    /// multiplying by `a + b I` rescales `A ~A` freely, which gives the Study
    /// normalisation and the closed-form inverse (docs/derivations/study-normalisation.md).
    pub fn is_study_type(&self, t: TypeId) -> bool {
        if self.metric.projective_origin().is_none() {
            return false;
        }
        let i = self.metric.pseudoscalar();
        let blades = &self.types.get(t).blades;
        let q = quadratic_self(&self.metric, blades, crate::algebra::Involution::Reverse);
        let keys_ok = q.keys().all(|&b| b == 0 || b == i) && q.contains_key(&i);
        let central = blades.iter().all(|&d| {
            let (right, blade) = self.metric.geometric(d, i);
            right == self.metric.geometric(i, d).0 && (right == 0 || blades.contains(&blade))
        });
        keys_ok
            && central
            && self.metric.geometric(i, i).0 == 0
            && crate::algebra::Involution::Reverse.sign(i) > 0
    }

    /// The type of `A^-1`: the inverse keeps the parity of `A` and the sign reversion
    /// gives it, so only grades congruent to A's mod 4 can appear.
    pub fn inverse_output(&self, t: TypeId) -> Output {
        if self.has_scalar_self_product(t) {
            return Output::Type(t);
        }
        let def = self.types.get(t);
        match def.kind {
            TypeKind::Grade(k) => {
                let n = self.metric.dimension();
                let grades: Vec<usize> = (0..=n).filter(|g| g % 4 == k % 4).collect();
                let blades = crate::algebra::canonical_blades(n)
                    .into_iter()
                    .filter(|&b| grades.contains(&(crate::algebra::grade(b) as usize)));
                self.types.smallest_holding(blades)
            }
            _ => Output::Type(t),
        }
    }

    /// Whether SIMD bodies are written: in one-item modules, not in the batch modules
    /// (whose scalars are already vectors across items). The batch modules and the scalar
    /// bodies still follow the SIMD bodies' summation order, so all three agree bit for bit.
    pub fn emits_simd(&self) -> bool {
        self.simd && self.lanes.is_none()
    }

    /// The four-lane SIMD form of a product, where one fits and the cost model finds it
    /// cheaper than the scalar form on both port layouts (see [`cost`]). Only `f32` items:
    /// an SSE register holds four of them, and SSE2 is in every x86-64 CPU; in `f64` a
    /// register holds two, and the shuffles between the two halves of a four-component
    /// value cost more than the scalar form saves.
    pub fn lane_form(&self, kind: ProductKind, a: TypeId, b: TypeId) -> Option<LaneProduct> {
        if self.scalar != Scalar::F32 || a == TypeId::SCALAR || b == TypeId::SCALAR {
            return None;
        }
        let (lhs, rhs) = (&self.types.get(a).blades, &self.types.get(b).blades);
        let terms = bilinear(&self.metric, kind, lhs, rhs);
        let Output::Type(output) = self.product_output(kind, a, b) else {
            return None;
        };
        let output = &self.types.get(output).blades;
        let scalar = cost::scalar_product_counts(terms.values().map(Vec::len));
        [Side::Rhs, Side::Lhs]
            .into_iter()
            .filter_map(|side| LaneProduct::new(&terms, output, lhs.len(), rhs.len(), side))
            .filter(|form| form.counts().beats(&scalar))
            .min_by(|x, y| {
                let cycles = |f: &LaneProduct| {
                    let c = f.counts();
                    c.shared_ports_cycles() + c.split_pipes_cycles()
                };
                cycles(x).total_cmp(&cycles(y))
            })
    }

    /// The emitted types that act as versors in `sandwich`.
    pub fn versors(&self) -> Vec<TypeId> {
        let n = self.metric.dimension();
        [TypeId::grade(1), TypeId::even(n), TypeId::odd(n)]
            .into_iter()
            .filter(|t| self.emitted.contains(t))
            .collect()
    }
}

/// The op that switches a product on.
pub fn product_op(kind: ProductKind) -> Op {
    match kind {
        ProductKind::Geometric => Op::Geometric,
        ProductKind::Outer => Op::Outer,
        ProductKind::Inner => Op::Inner,
        ProductKind::LeftContraction => Op::LeftContraction,
        ProductKind::RightContraction => Op::RightContraction,
        ProductKind::Scalar => Op::ScalarProduct,
        ProductKind::Commutator => Op::Commutator,
        ProductKind::Regressive => Op::Regressive,
    }
}

impl Types {
    /// The id of a requested type.
    pub fn id_of_request(&self, request: &TypeRequest) -> TypeId {
        let n = self.dimension();
        match request {
            TypeRequest::Grade(k) => TypeId::grade(*k),
            TypeRequest::Even => TypeId::even(n),
            TypeRequest::Odd => TypeId::odd(n),
            TypeRequest::Multivector => TypeId::multivector(n),
            TypeRequest::User { name, .. } => self.id_by_name(name),
        }
    }
}
