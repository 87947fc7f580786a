//! Drivers shared by the test binaries: a fixed-seed proptest configuration,
//! random dense multivectors, and tables of generated operations checked against
//! [`Algebra`] case by case.
//!
//! A table entry evaluates one generated operation on random dense inputs: it
//! converts them to the generated operand types (keeping only the blades each type
//! holds), applies the operation, and returns the operands and the result as dense
//! reference multivectors. The driver computes the same operation with the
//! reference and compares.

use crate::prop_assert_close;
use crate::reference::{Algebra, Product};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed, TestRunner};

/// The relative tolerance of a generated `f64` product against the reference,
/// per component, relative to the sum of the absolute values of the terms that
/// land on that component ([`Algebra::product_magnitude`]).
pub const PRODUCT_TOLERANCE: f64 = 1e-12;

/// [`PRODUCT_TOLERANCE`] for `f32` algebras: a sum of at most 32 rounded
/// products is within `33 u = 2e-6` (`u = 2^-24`) of the exact value relative to
/// the sum of the magnitudes of its terms; `1e-5` leaves room for a different
/// association of the sum.
pub const F32_PRODUCT_TOLERANCE: f64 = 1e-5;

/// The proptest configuration of every property test: `cases` cases from a fixed
/// seed, so that a run is reproducible, and no regression files.
#[must_use]
pub fn config(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(0x6a5f_0c7e_11a9_2b3d),
        failure_persistence: None,
        ..Config::default()
    }
}

/// Runs `test` on values of `strategy` with [`config`]`(cases)`, and panics with
/// proptest's report (the shrunk input and the reason) if a case fails.
///
/// # Panics
/// When a case fails.
pub fn run<S: Strategy>(
    cases: u32,
    strategy: &S,
    test: impl Fn(S::Value) -> Result<(), TestCaseError>,
) {
    let mut runner = TestRunner::new(config(cases));
    if let Err(error) = runner.run(strategy, test) {
        panic!("{error}");
    }
}

/// Dense multivectors of `size` components, each in `-10..10`.
pub fn dense(size: usize) -> impl Strategy<Value = Vec<f64>> + Clone {
    prop::collection::vec(-10.0..10.0f64, size)
}

/// One generated binary operation on one ordered pair of types.
#[derive(Clone, Copy)]
pub struct PairCase {
    /// The left operand's type name (`Scalar` for the scalar).
    pub lhs: &'static str,
    /// The right operand's type name.
    pub rhs: &'static str,
    /// From two dense multivectors: the two operands as the generated types hold
    /// them, and the result, all dense.
    pub eval: fn(&[f64], &[f64]) -> [Vec<f64>; 3],
}

/// Checks that every case of a generated `product` agrees with the reference on
/// random operands, to `tolerance` ([`PRODUCT_TOLERANCE`] for `f64`).
///
/// # Panics
/// On the first disagreement, naming the product, the types and the metric.
pub fn check_products(algebra: &Algebra, product: Product, cases: &[PairCase], tolerance: f64) {
    assert!(!cases.is_empty(), "no {} products to check", product.name());
    let size = algebra.size();
    run(64, &(dense(size), dense(size)), |(x, y)| {
        for case in cases {
            let [a, b, got] = (case.eval)(&x, &y);
            let expected = algebra.product(product, &a, &b);
            let scale = algebra.magnitude_of(product, &a, &b);
            prop_assert_close!(
                got,
                expected,
                scale = scale,
                rel = tolerance,
                "for {} {} {} with metric {:?}",
                case.lhs,
                product.name(),
                case.rhs,
                algebra.metric()
            );
        }
        Ok(())
    });
}

/// The unary operations every generated type has.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unary {
    /// `~x`.
    Reverse,
    /// Grade `r` times `(-1)^r`.
    GradeInvolution,
    /// The Clifford conjugate.
    Conjugate,
    /// The right complement.
    Dual,
    /// The inverse of the right complement.
    Undual,
    /// `<x ~x>_0`.
    NormSquared,
    /// `<x>_r`.
    Grade(usize),
}

impl Unary {
    /// The reference value of the operation on `x`.
    #[must_use]
    pub fn reference(self, algebra: &Algebra, x: &[f64]) -> Vec<f64> {
        match self {
            Unary::Reverse => algebra.reverse(x),
            Unary::GradeInvolution => algebra.grade_involution(x),
            Unary::Conjugate => algebra.conjugate(x),
            Unary::Dual => algebra.dual(x),
            Unary::Undual => algebra.undual(x),
            Unary::NormSquared => algebra.scalar(algebra.norm_squared(x)),
            Unary::Grade(r) => algebra.grade(x, r),
        }
    }
}

/// One generated unary operation on one type.
#[derive(Clone, Copy)]
pub struct UnaryCase {
    /// The operand's type name.
    pub ty: &'static str,
    /// The operation.
    pub op: Unary,
    /// From a dense multivector: the operand as the generated type holds it and
    /// the result, both dense.
    pub eval: fn(&[f64]) -> [Vec<f64>; 2],
}

/// Checks that every unary case agrees with the reference on random operands.
/// The involutions, duals and projections only move or negate components, so
/// they must agree exactly up to rounding of `norm_squared`'s sum.
///
/// # Panics
/// On the first disagreement, naming the operation, the type and the metric.
pub fn check_unary(algebra: &Algebra, cases: &[UnaryCase]) {
    assert!(!cases.is_empty(), "no unary operations to check");
    run(64, &dense(algebra.size()), |x| {
        for case in cases {
            let [a, got] = (case.eval)(&x);
            let expected = case.op.reference(algebra, &a);
            let scale = algebra.l1_norm(&a).powi(2).max(algebra.l1_norm(&a));
            prop_assert_close!(
                got,
                expected,
                scale = scale,
                rel = PRODUCT_TOLERANCE,
                "for {:?} of {} with metric {:?}",
                case.op,
                case.ty,
                algebra.metric()
            );
        }
        Ok(())
    });
}

/// Which versor type a sandwich case applies: its values are products of how many
/// vectors.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Versor {
    /// `Vector`: one vector, a reflection.
    Vector,
    /// `Even`: products of 2, 4, ... vectors.
    Even,
    /// `Odd`: products of 1, 3, ... vectors.
    Odd,
}

impl Versor {
    /// How many vectors the versors of this type are built from, in an algebra of
    /// dimension `dim`: every count of the type's parity up to `dim`, which by the
    /// Cartan-Dieudonne theorem reaches every versor of the algebra's orthogonal group
    /// (for non-degenerate metrics; in PGA the products of vectors are still versors).
    #[must_use]
    pub fn vector_counts(self, dim: usize) -> Vec<usize> {
        match self {
            Versor::Vector => vec![1],
            Versor::Even => (2..=dim).step_by(2).collect(),
            Versor::Odd => (1..=dim).step_by(2).collect(),
        }
    }

    /// Whether `sandwich` applies the grade involution to its operand: `v x^ ~v` for
    /// an odd `v`.
    #[must_use]
    pub fn is_odd(self) -> bool {
        matches!(self, Versor::Vector | Versor::Odd)
    }
}

/// The product of the grade-1 parts of `factors`, in order: a versor.
#[must_use]
pub fn product_of_vectors(algebra: &Algebra, factors: &[Vec<f64>]) -> Vec<f64> {
    factors.iter().fold(algebra.scalar(1.0), |acc, factor| {
        algebra.geometric(&acc, &algebra.grade(factor, 1))
    })
}

/// The reference versor product, computed from the definition: `v x ~v` for even `v`,
/// `v x^ ~v` for odd `v` (`x^` the grade involution).
#[must_use]
pub fn reference_sandwich(algebra: &Algebra, versor: Versor, v: &[f64], x: &[f64]) -> Vec<f64> {
    let x = if versor.is_odd() {
        algebra.grade_involution(x)
    } else {
        x.to_vec()
    };
    algebra.geometric(&algebra.geometric(v, &x), &algebra.reverse(v))
}

/// For every output blade, the sum of `|v_i x_k v_j|` over the terms of `v x ~v` that
/// land on it: the magnitude a sandwich's rounding error is relative to.
#[must_use]
pub fn sandwich_magnitude(algebra: &Algebra, v: &[f64], x: &[f64]) -> Vec<f64> {
    algebra.product_magnitude(&algebra.product_magnitude(v, x), v)
}

/// One generated `sandwich` of one versor type on one operand type.
#[derive(Clone, Copy)]
pub struct SandwichCase {
    /// The versor type.
    pub versor: Versor,
    /// The operand's type name.
    pub operand: &'static str,
    /// From a dense versor and a dense multivector: the versor and the operand as the
    /// generated types hold them, and `versor.sandwich(operand)`, all dense.
    pub eval: fn(&[f64], &[f64]) -> [Vec<f64>; 3],
}

/// The random inputs of the sandwich checks: `dim` factors (their grade-1 parts make
/// the versors) and one operand, each a dense multivector.
fn sandwich_inputs(size: usize, dim: usize) -> impl Strategy<Value = (Vec<Vec<f64>>, Vec<f64>)> {
    (prop::collection::vec(dense(size), dim), dense(size))
}

/// Checks that every case's `sandwich` equals the reference `v x ~v` (`v x^ ~v` for
/// odd `v`) for versors `v` that are products of 1 to `dim` random vectors, whole:
/// the result must also have nothing outside the operand's type.
///
/// # Panics
/// On the first disagreement, naming the versor, the operand type, the number of
/// vectors and the metric.
pub fn check_sandwiches(algebra: &Algebra, cases: &[SandwichCase], tolerance: f64) {
    assert!(!cases.is_empty(), "no sandwiches to check");
    let dim = algebra.dim();
    run(64, &sandwich_inputs(algebra.size(), dim), |(factors, x)| {
        for case in cases {
            for count in case.versor.vector_counts(dim) {
                let v = product_of_vectors(algebra, &factors[..count]);
                let [v, x, got] = (case.eval)(&v, &x);
                let expected = reference_sandwich(algebra, case.versor, &v, &x);
                prop_assert_close!(
                    got,
                    expected,
                    scale = sandwich_magnitude(algebra, &v, &x),
                    rel = tolerance,
                    "for {:?}.sandwich({}), a product of {count} vectors, with metric {:?}",
                    case.versor,
                    case.operand,
                    algebra.metric()
                );
            }
        }
        Ok(())
    });
}

/// Checks every case's `sandwich_unit` against the reference `v x ~v` for **unit** even
/// versors `v`: products of two random vectors divided by `sqrt(<v ~v>)`, where that is
/// well above zero (a versor with `<v ~v>` negative or nearly null has no scaling to
/// `v ~v = 1`, and is skipped; at least a quarter of the cases must be checked).
///
/// # Panics
/// On the first disagreement, naming the operand type and the metric, or when too few
/// versors could be made unit.
pub fn check_unit_sandwiches(algebra: &Algebra, cases: &[SandwichCase], tolerance: f64) {
    assert!(!cases.is_empty(), "no unit sandwiches to check");
    let checked = std::cell::Cell::new(0u32);
    run(64, &sandwich_inputs(algebra.size(), 2), |(factors, x)| {
        let v = product_of_vectors(algebra, &factors);
        let unit = algebra.geometric(&v, &algebra.reverse(&v))[0];
        let size: f64 = v.iter().map(|c| c * c).sum();
        // Also skips a NaN, which no versor built from finite vectors has.
        if unit.partial_cmp(&(1e-3 * size)) != Some(std::cmp::Ordering::Greater) {
            return Ok(());
        }
        checked.set(checked.get() + 1);
        let v = algebra.scale(&v, 1.0 / unit.sqrt());
        for case in cases {
            let [v, x, got] = (case.eval)(&v, &x);
            let expected = reference_sandwich(algebra, Versor::Even, &v, &x);
            prop_assert_close!(
                got,
                expected,
                scale = sandwich_magnitude(algebra, &v, &x),
                rel = tolerance,
                "for the unit {:?}.sandwich_unit({}), with metric {:?}",
                v,
                case.operand,
                algebra.metric()
            );
        }
        Ok(())
    });
    assert!(
        checked.get() >= 16,
        "only {} of 64 versors could be made unit with metric {:?}",
        checked.get(),
        algebra.metric()
    );
}

/// What a versor type's `sandwich_matrix` and `sandwich_vectors` give, in the
/// reference's terms.
pub struct MatrixEval {
    /// The versor as the generated type holds it, dense.
    pub versor: Vec<f64>,
    /// The blade of each vector component, in `to_array` order (the matrix's row and
    /// column order).
    pub vector_blades: Vec<usize>,
    /// `sandwich_matrix()`, widened to `f64`.
    pub matrix: Vec<Vec<f64>>,
    /// The vectors given to `sandwich_vectors` as the generated type holds them, dense.
    pub inputs: Vec<Vec<f64>>,
    /// What `sandwich_vectors` left in their place, dense.
    pub outputs: Vec<Vec<f64>>,
}

/// One versor type's `sandwich_matrix` and `sandwich_vectors`.
#[derive(Clone, Copy)]
pub struct MatrixCase {
    /// The versor type.
    pub versor: Versor,
    /// From a dense versor and dense vectors: what the generated type makes of them.
    pub eval: fn(&[f64], &[Vec<f64>]) -> MatrixEval,
}

/// Checks every case's `sandwich_matrix` column by column against the reference
/// sandwich of each basis vector (the same map as `sandwich`: `v x^ ~v = -v x ~v` for
/// odd `v`), and `sandwich_vectors` on slices of 0 to 5 random vectors against the
/// reference sandwich of each, for versors built as in [`check_sandwiches`].
///
/// # Panics
/// On the first disagreement, naming the versor, the entry or vector, and the metric.
pub fn check_sandwich_matrices(algebra: &Algebra, cases: &[MatrixCase], tolerance: f64) {
    assert!(!cases.is_empty(), "no sandwich matrices to check");
    let dim = algebra.dim();
    let size = algebra.size();
    let inputs = (
        prop::collection::vec(dense(size), dim),
        prop::collection::vec(dense(size), 0..=5),
    );
    run(64, &inputs, |(factors, vectors)| {
        let vectors: Vec<Vec<f64>> = vectors.iter().map(|x| algebra.grade(x, 1)).collect();
        for case in cases {
            for count in case.versor.vector_counts(dim) {
                let v = product_of_vectors(algebra, &factors[..count]);
                let eval = (case.eval)(&v, &vectors);
                check_matrix_eval(algebra, case.versor, &eval, vectors.len(), tolerance).map_err(
                    |e| TestCaseError::fail(format!("{e}, a product of {count} vectors")),
                )?;
            }
        }
        Ok(())
    });
}

/// Checks one [`MatrixEval`] against the reference (see [`check_sandwich_matrices`]).
///
/// # Errors
/// The first disagreement, naming the versor, the entry or vector, and the metric.
fn check_matrix_eval(
    algebra: &Algebra,
    versor: Versor,
    eval: &MatrixEval,
    vectors: usize,
    tolerance: f64,
) -> Result<(), TestCaseError> {
    let v = &eval.versor;
    prop_assert_eq!(eval.matrix.len(), algebra.dim());
    for (column, &blade) in eval.vector_blades.iter().enumerate() {
        let basis = algebra.basis(blade, 1.0);
        let image = reference_sandwich(algebra, versor, v, &basis);
        let scale = sandwich_magnitude(algebra, v, &basis);
        let got: Vec<f64> = eval.matrix.iter().map(|row| row[column]).collect();
        prop_assert_close!(
            got,
            algebra.components(&image, &eval.vector_blades),
            scale = algebra.components(&scale, &eval.vector_blades),
            rel = tolerance,
            "column {column} of {versor:?}::sandwich_matrix with metric {:?}",
            algebra.metric()
        );
    }
    prop_assert_eq!(eval.outputs.len(), vectors);
    for (k, (x, got)) in eval.inputs.iter().zip(&eval.outputs).enumerate() {
        prop_assert_close!(
            got,
            reference_sandwich(algebra, versor, v, x),
            scale = sandwich_magnitude(algebra, v, x),
            rel = tolerance,
            "vector {k} of {vectors} in {versor:?}::sandwich_vectors with metric {:?}",
            algebra.metric()
        );
    }
    Ok(())
}

/// One generated binary operation on one ordered pair of the structure-of-arrays
/// batch types (`x4`, `x8`): `lanes` items at once.
#[derive(Clone, Copy)]
pub struct LanePairCase {
    /// The left operand's type name.
    pub lhs: &'static str,
    /// The right operand's type name.
    pub rhs: &'static str,
    /// From one pair of dense multivectors per lane: for each lane, the two operands
    /// as the item types hold them and that lane of the batch result, all dense.
    pub eval: LaneEval,
}

/// [`LanePairCase::eval`]: per-lane operands in, per-lane `[lhs, rhs, result]` out.
pub type LaneEval = fn(&[Vec<f64>], &[Vec<f64>]) -> Vec<[Vec<f64>; 3]>;

/// [`check_products`] for batch types: every lane of every case agrees with the
/// reference on its own random operands. `64 / lanes` cases, so that a batch module
/// costs as many reference products as an item module.
///
/// # Panics
/// On the first disagreement, naming the product, the types, the lane and the metric.
pub fn check_lane_products(
    algebra: &Algebra,
    product: Product,
    lanes: usize,
    cases: &[LanePairCase],
    tolerance: f64,
) {
    assert!(!cases.is_empty(), "no {} products to check", product.name());
    let size = algebra.size();
    let operands = prop::collection::vec(dense(size), lanes);
    let cases_to_run = u32::try_from(64 / lanes).unwrap_or(1).max(1);
    run(cases_to_run, &(operands.clone(), operands), |(xs, ys)| {
        for case in cases {
            for (lane, [a, b, got]) in (case.eval)(&xs, &ys).into_iter().enumerate() {
                let expected = algebra.product(product, &a, &b);
                let scale = algebra.magnitude_of(product, &a, &b);
                prop_assert_close!(
                    got,
                    expected,
                    scale = scale,
                    rel = tolerance,
                    "for lane {lane} of {} {} {} with metric {:?}",
                    case.lhs,
                    product.name(),
                    case.rhs,
                    algebra.metric()
                );
            }
        }
        Ok(())
    });
}

/// One generated `sandwich` of one versor type of a batch module on one operand type.
#[derive(Clone, Copy)]
pub struct LaneSandwichCase {
    /// The versor type.
    pub versor: Versor,
    /// The operand's type name.
    pub operand: &'static str,
    /// From one dense versor and one dense multivector per lane: for each lane, the
    /// versor and the operand as the item types hold them and that lane of
    /// `versor.sandwich(operand)`, all dense.
    pub eval: LaneEval,
}

/// [`check_sandwiches`] for batch types: every lane of every case against the
/// reference, each lane with its own versor and operand, `64 / lanes` cases.
///
/// # Panics
/// On the first disagreement, naming the versor, the operand type, the lane, the
/// number of vectors and the metric.
pub fn check_lane_sandwiches(
    algebra: &Algebra,
    lanes: usize,
    cases: &[LaneSandwichCase],
    tolerance: f64,
) {
    assert!(!cases.is_empty(), "no sandwiches to check");
    let dim = algebra.dim();
    let inputs = prop::collection::vec(sandwich_inputs(algebra.size(), dim), lanes);
    let cases_to_run = u32::try_from(64 / lanes).unwrap_or(1).max(1);
    run(cases_to_run, &inputs, |per_lane| {
        let xs: Vec<Vec<f64>> = per_lane.iter().map(|(_, x)| x.clone()).collect();
        for case in cases {
            for count in case.versor.vector_counts(dim) {
                let vs: Vec<Vec<f64>> = per_lane
                    .iter()
                    .map(|(factors, _)| product_of_vectors(algebra, &factors[..count]))
                    .collect();
                for (lane, [v, x, got]) in (case.eval)(&vs, &xs).into_iter().enumerate() {
                    let expected = reference_sandwich(algebra, case.versor, &v, &x);
                    prop_assert_close!(
                        got,
                        expected,
                        scale = sandwich_magnitude(algebra, &v, &x),
                        rel = tolerance,
                        "for lane {lane} of {:?}.sandwich({}), a product of {count} vectors, \
                         with metric {:?}",
                        case.versor,
                        case.operand,
                        algebra.metric()
                    );
                }
            }
        }
        Ok(())
    });
}

/// One versor type's `sandwich_matrix` and `sandwich_vectors` in a batch module.
#[derive(Clone, Copy)]
pub struct LaneMatrixCase {
    /// The versor type.
    pub versor: Versor,
    /// From one dense versor per lane and, per lane, the same number of dense
    /// vectors (lane `i` of the `j`-th batch vector is `vectors[i][j]`): what the
    /// batch type makes of them, lane by lane.
    pub eval: LaneMatrixEval,
}

/// [`LaneMatrixCase::eval`]: per-lane versors and vectors in, per-lane results out.
pub type LaneMatrixEval = fn(&[Vec<f64>], &[Vec<Vec<f64>>]) -> Vec<MatrixEval>;

/// [`check_sandwich_matrices`] for batch types: every lane against the reference,
/// each lane with its own versor and vectors, on slices of 0 to 3 batch vectors,
/// `64 / lanes` cases.
///
/// # Panics
/// On the first disagreement, naming the versor, the lane, the entry or vector, and
/// the metric.
pub fn check_lane_sandwich_matrices(
    algebra: &Algebra,
    lanes: usize,
    cases: &[LaneMatrixCase],
    tolerance: f64,
) {
    assert!(!cases.is_empty(), "no sandwich matrices to check");
    let dim = algebra.dim();
    let size = algebra.size();
    let inputs = (0..=3usize).prop_flat_map(move |len| {
        prop::collection::vec(
            (
                prop::collection::vec(dense(size), dim),
                prop::collection::vec(dense(size), len),
            ),
            lanes,
        )
    });
    let cases_to_run = u32::try_from(64 / lanes).unwrap_or(1).max(1);
    run(cases_to_run, &inputs, |per_lane| {
        let vectors: Vec<Vec<Vec<f64>>> = per_lane
            .iter()
            .map(|(_, xs)| xs.iter().map(|x| algebra.grade(x, 1)).collect())
            .collect();
        let len = vectors[0].len();
        for case in cases {
            for count in case.versor.vector_counts(dim) {
                let vs: Vec<Vec<f64>> = per_lane
                    .iter()
                    .map(|(factors, _)| product_of_vectors(algebra, &factors[..count]))
                    .collect();
                for (lane, eval) in (case.eval)(&vs, &vectors).iter().enumerate() {
                    check_matrix_eval(algebra, case.versor, eval, len, tolerance).map_err(|e| {
                        TestCaseError::fail(format!(
                            "{e}, lane {lane}, a product of {count} vectors"
                        ))
                    })?;
                }
            }
        }
        Ok(())
    });
}
