//! Every metric of entries 1, -1 and 0 expands to a full module that compiles with every
//! operation: every metric in one to three dimensions (each position of the zeros included:
//! it decides which blades are null), every signature (p, q, r) of four dimensions with a
//! few other orderings of the zeros, and a sample in five and six. `factor` in
//! `metric: [0]` and `signature: (0, 0, 4)`, and `log` in `(0, 1, 3)` and `(1, 0, 3)`,
//! once did not compile. An ordinary test binary rather than a trybuild case, so that the
//! modules build once with the workspace's other tests. Modules are named by their
//! squares: p = 1, n = -1, z = 0; `every_metric_compiles_over_dual.rs` does the same over
//! `Dual64`.
#![allow(dead_code)]

ga_macros::algebra! { pub mod m_p { metric: [1] } }
ga_macros::algebra! { pub mod m_n { metric: [-1] } }
ga_macros::algebra! { pub mod m_z { metric: [0] } }
ga_macros::algebra! { pub mod m_pp { metric: [1, 1] } }
ga_macros::algebra! { pub mod m_pn { metric: [1, -1] } }
ga_macros::algebra! { pub mod m_pz { metric: [1, 0] } }
ga_macros::algebra! { pub mod m_np { metric: [-1, 1] } }
ga_macros::algebra! { pub mod m_nn { metric: [-1, -1] } }
ga_macros::algebra! { pub mod m_nz { metric: [-1, 0] } }
ga_macros::algebra! { pub mod m_zp { metric: [0, 1] } }
ga_macros::algebra! { pub mod m_zn { metric: [0, -1] } }
ga_macros::algebra! { pub mod m_zz { metric: [0, 0] } }
ga_macros::algebra! { pub mod m_ppp { metric: [1, 1, 1] } }
ga_macros::algebra! { pub mod m_ppn { metric: [1, 1, -1] } }
ga_macros::algebra! { pub mod m_ppz { metric: [1, 1, 0] } }
ga_macros::algebra! { pub mod m_pnp { metric: [1, -1, 1] } }
ga_macros::algebra! { pub mod m_pnn { metric: [1, -1, -1] } }
ga_macros::algebra! { pub mod m_pnz { metric: [1, -1, 0] } }
ga_macros::algebra! { pub mod m_pzp { metric: [1, 0, 1] } }
ga_macros::algebra! { pub mod m_pzn { metric: [1, 0, -1] } }
ga_macros::algebra! { pub mod m_pzz { metric: [1, 0, 0] } }
ga_macros::algebra! { pub mod m_npp { metric: [-1, 1, 1] } }
ga_macros::algebra! { pub mod m_npn { metric: [-1, 1, -1] } }
ga_macros::algebra! { pub mod m_npz { metric: [-1, 1, 0] } }
ga_macros::algebra! { pub mod m_nnp { metric: [-1, -1, 1] } }
ga_macros::algebra! { pub mod m_nnn { metric: [-1, -1, -1] } }
ga_macros::algebra! { pub mod m_nnz { metric: [-1, -1, 0] } }
ga_macros::algebra! { pub mod m_nzp { metric: [-1, 0, 1] } }
ga_macros::algebra! { pub mod m_nzn { metric: [-1, 0, -1] } }
ga_macros::algebra! { pub mod m_nzz { metric: [-1, 0, 0] } }
ga_macros::algebra! { pub mod m_zpp { metric: [0, 1, 1] } }
ga_macros::algebra! { pub mod m_zpn { metric: [0, 1, -1] } }
ga_macros::algebra! { pub mod m_zpz { metric: [0, 1, 0] } }
ga_macros::algebra! { pub mod m_znp { metric: [0, -1, 1] } }
ga_macros::algebra! { pub mod m_znn { metric: [0, -1, -1] } }
ga_macros::algebra! { pub mod m_znz { metric: [0, -1, 0] } }
ga_macros::algebra! { pub mod m_zzp { metric: [0, 0, 1] } }
ga_macros::algebra! { pub mod m_zzn { metric: [0, 0, -1] } }
ga_macros::algebra! { pub mod m_zzz { metric: [0, 0, 0] } }
ga_macros::algebra! { pub mod m_zzzz { metric: [0, 0, 0, 0] } }
ga_macros::algebra! { pub mod m_nzzz { metric: [-1, 0, 0, 0] } }
ga_macros::algebra! { pub mod m_nnzz { metric: [-1, -1, 0, 0] } }
ga_macros::algebra! { pub mod m_nnnz { metric: [-1, -1, -1, 0] } }
ga_macros::algebra! { pub mod m_nnnn { metric: [-1, -1, -1, -1] } }
ga_macros::algebra! { pub mod m_pzzz { metric: [1, 0, 0, 0] } }
ga_macros::algebra! { pub mod m_pnzz { metric: [1, -1, 0, 0] } }
ga_macros::algebra! { pub mod m_pnnz { metric: [1, -1, -1, 0] } }
ga_macros::algebra! { pub mod m_pnnn { metric: [1, -1, -1, -1] } }
ga_macros::algebra! { pub mod m_ppzz { metric: [1, 1, 0, 0] } }
ga_macros::algebra! { pub mod m_ppnz { metric: [1, 1, -1, 0] } }
ga_macros::algebra! { pub mod m_ppnn { metric: [1, 1, -1, -1] } }
ga_macros::algebra! { pub mod m_pppz { metric: [1, 1, 1, 0] } }
ga_macros::algebra! { pub mod m_pppn { metric: [1, 1, 1, -1] } }
ga_macros::algebra! { pub mod m_pppp { metric: [1, 1, 1, 1] } }
ga_macros::algebra! { pub mod m_zppp { metric: [0, 1, 1, 1] } }
ga_macros::algebra! { pub mod m_pznp { metric: [1, 0, -1, 1] } }
ga_macros::algebra! { pub mod m_nzzp { metric: [-1, 0, 0, 1] } }
ga_macros::algebra! { pub mod m_znzn { metric: [0, -1, 0, -1] } }
ga_macros::algebra! { pub mod m_zzzzz { metric: [0, 0, 0, 0, 0] } }
ga_macros::algebra! { pub mod m_pzzzz { metric: [1, 0, 0, 0, 0] } }
ga_macros::algebra! { pub mod m_zpppp { metric: [0, 1, 1, 1, 1] } }
ga_macros::algebra! { pub mod m_nnzzp { metric: [-1, -1, 0, 0, 1] } }
ga_macros::algebra! { pub mod m_zppppp { metric: [0, 1, 1, 1, 1, 1] } }

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
