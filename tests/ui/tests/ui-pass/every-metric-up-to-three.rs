// Every metric of entries 1, -1 and 0 in one to three dimensions, each position of the
// zeros included (it decides which blades are null), expands to a full module that
// compiles with every operation: `factor` in `metric: [0]` and `log` in `[0, 1, 1, 1]`
// once did not. Modules are named by their squares: p = 1, n = -1, z = 0.
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

fn main() {
    // In a fully null metric no vector is invertible, so no blade above grade 1 factors.
    assert_eq!(m_zzz::Bivector::E12.factor(), None);
    assert_eq!(m_zzz::Vector::E1.factor(), Some([m_zzz::Vector::E1]));
    assert_eq!(m_ppn::Bivector::E12.factor().map(|f| f.len()), Some(2));
}
