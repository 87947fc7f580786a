//! Every metric of `ga_tests::every_metric!`, the list `every_metric_compiles.rs` expands
//! in `f64`, expands over `num_dual::Dual64` (the generic-scalar rewriter) to a full module
//! that compiles with every operation. Once only the signatures up to three dimensions and
//! a sample were expanded here; now both scalars read one list.
#![allow(dead_code)]

use num_dual::Dual64;

/// Each `name: [squares]` as a `Dual64` module `name`.
macro_rules! dual_modules {
    ($($name:ident: $metric:tt),* $(,)?) => {
        $(ga_macros::algebra! { pub mod $name { metric: $metric, scalar: num_dual::Dual64 } })*
    };
}

ga_tests::every_metric!(dual_modules);

/// exp's derivative at 0 in a null, an elliptic and a hyperbolic plane.
#[test]
fn every_degenerate_metric_expands_over_dual_numbers_and_differentiates_exp() {
    // d/dt exp(t e12) at t = 0 is e12 in a plane that squares to 0, -1 or +1 alike.
    let t = Dual64::from(0.0).derivative();
    let null = (m_pzz::Bivector::E23 * t).exp();
    assert_eq!(null.e23.eps, 1.0);
    let elliptic = (m_ppp::Bivector::E12 * t).exp();
    assert_eq!(elliptic.e12.eps, 1.0);
    let hyperbolic = (m_pnz::Bivector::E12 * t).exp();
    assert_eq!(hyperbolic.e12.eps, 1.0);
    assert_eq!(m_zzz::Bivector::E12.factor(), None);
}
