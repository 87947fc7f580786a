//! Every metric of `ga_tests::every_metric!` (every metric of entries 1, -1 and 0 up to
//! three dimensions, every signature of four, a sample in five and six) expands to a full
//! `f64` module that compiles with every operation. `factor` in `metric: [0]` and
//! `signature: (0, 0, 4)`, and `log` in `(0, 1, 3)` and `(1, 0, 3)`, once did not compile.
//! An ordinary test binary rather than trybuild cases, so that the modules build once with
//! the workspace's other tests; `every_metric_compiles_over_dual.rs` expands the same list
//! over `Dual64` in a binary of its own, which builds beside this one.
#![allow(dead_code)]

/// Each `name: [squares]` as an `f64` module `name`.
macro_rules! f64_modules {
    ($($name:ident: $metric:tt),* $(,)?) => {
        $(ga_macros::algebra! { pub mod $name { metric: $metric } })*
    };
}

ga_tests::every_metric!(f64_modules);

/// In a fully null metric no vector is invertible, so no blade above grade 1 factors.
#[test]
fn a_null_metric_factors_only_vectors() {
    assert_eq!(m_zzz::Bivector::E12.factor(), None);
    assert_eq!(m_zzz::Vector::E1.factor(), Some([m_zzz::Vector::E1]));
    assert_eq!(m_ppn::Bivector::E12.factor().map(|f| f.len()), Some(2));
    assert_eq!(m_zzzz::Trivector::E123.factor(), None);
}

/// With a null pseudoscalar `log` still recovers a bivector of the plane it turns in.
#[test]
fn log_with_a_null_pseudoscalar_recovers_the_plane() {
    let b = m_pzzz::Bivector::E12 * 0.5;
    let log = b.exp().log().map(|l| l.e12);
    assert_eq!(log, Some(0.5));
}
