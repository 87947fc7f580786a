//! Every signature (p, q, r) with p + q + r <= 3 and a sample of other orderings up to five
//! dimensions expand over `num_dual::Dual64` (the generic-scalar rewriter) to full modules
//! that compile with every operation; the f64 modules of every metric are in
//! `every_metric_compiles.rs`.
ga_macros::algebra! { pub mod m_z { metric: [0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_n { metric: [-1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_p { metric: [1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_zz { metric: [0, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_nz { metric: [-1, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_nn { metric: [-1, -1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_pz { metric: [1, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_pn { metric: [1, -1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_pp { metric: [1, 1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_zzz { metric: [0, 0, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_nzz { metric: [-1, 0, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_nnz { metric: [-1, -1, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_nnn { metric: [-1, -1, -1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_pzz { metric: [1, 0, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_pnz { metric: [1, -1, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_pnn { metric: [1, -1, -1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_ppz { metric: [1, 1, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_ppn { metric: [1, 1, -1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_ppp { metric: [1, 1, 1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_zpz { metric: [0, 1, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_pzn { metric: [1, 0, -1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_zzzz { metric: [0, 0, 0, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_zppp { metric: [0, 1, 1, 1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_pnnn { metric: [1, -1, -1, -1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_znzz { metric: [0, -1, 0, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_pzzz { metric: [1, 0, 0, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_zpzp { metric: [0, 1, 0, 1], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_zzzzz { metric: [0, 0, 0, 0, 0], scalar: num_dual::Dual64 } }
ga_macros::algebra! { pub mod m_zpppp { metric: [0, 1, 1, 1, 1], scalar: num_dual::Dual64 } }

use num_dual::Dual64;

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
