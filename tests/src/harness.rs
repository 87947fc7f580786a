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
            let scale = algebra.product_magnitude(&a, &b);
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
