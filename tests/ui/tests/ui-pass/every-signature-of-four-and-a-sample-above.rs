// Every signature (p, q, r) with p + q + r = 4 expands to a full module that compiles with
// every operation (`log` in `signature: (0, 1, 3)` and `(1, 0, 3)`, and `factor` in
// `(0, 0, 4)`, once did not), with a few other orderings of the zeros and a sample in five
// and six dimensions; every metric up to three dimensions is in every-metric-up-to-three.rs.
// Modules are named by their squares: p = 1, n = -1, z = 0.
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

fn main() {
    // With a null pseudoscalar `log` still recovers a bivector of the plane it turns in.
    let b = m_pzzz::Bivector::E12 * 0.5;
    let log = b.exp().log().map(|l| l.e12);
    assert_eq!(log, Some(0.5));
    assert_eq!(m_zzzz::Trivector::E123.factor(), None);
}
