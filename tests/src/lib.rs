//! The workspace's integration-test support: a slow, independent reference
//! geometric algebra to check the generated ones against.
//!
//! - [`blade`]: blades as bitmasks, reordering signs, canonical order, names;
//! - [`reference`](mod@reference): dense multivectors over any metric of squares 1, -1, 0, with
//!   every product, involution, dual, `exp` and `inverse` written from the
//!   definitions of the lecture;
//! - [`close`]: [`assert_close!`] and [`prop_assert_close!`];
//! - [`embed`]: the generated types seen as dense reference multivectors, their
//!   blades read from their field names;
//! - [`algebras`]: the six algebras under test (STA, PGA and CGA generated here)
//!   and the macros that enumerate them and their type pairs;
//! - [`double_double`]: double-double arithmetic and an inverse in it, the
//!   high-precision reference for inverses near singular input;
//! - [`dual_algebras`]: the test metrics over num-dual's `Dual64` (and G3 over
//!   `HyperDual64`), written with a user's `scalar:` path;
//! - [`harness`]: the fixed-seed proptest drivers that check tables of generated
//!   operations against the reference.
//!
//! None of this shares code with `ga-macros`: it is a second, deliberately naive
//! implementation, so that the two can only agree by both being right.

pub mod algebras;
pub mod blade;
pub mod close;
pub mod double_double;
pub mod dual_algebras;
pub mod embed;
pub mod harness;
pub mod reference;

pub use reference::{Algebra, Product};

/// The metrics that `every_metric_compiles` and `every_metric_compiles_over_dual` expand:
/// every metric of entries 1, -1 and 0 in one to three dimensions (each position of the
/// zeros: it decides which blades are null), every signature (p, q, r) of four dimensions
/// with a few other orderings of the zeros, and a sample in five and six, as
/// `name: [squares]` (p = 1, n = -1, z = 0), handed to the macro `$expand`. One list, so
/// that both scalar types see the same metrics.
#[macro_export]
macro_rules! every_metric {
    ($expand:ident) => {
        $expand! {
            m_p: [1],
            m_n: [-1],
            m_z: [0],
            m_pp: [1, 1],
            m_pn: [1, -1],
            m_pz: [1, 0],
            m_np: [-1, 1],
            m_nn: [-1, -1],
            m_nz: [-1, 0],
            m_zp: [0, 1],
            m_zn: [0, -1],
            m_zz: [0, 0],
            m_ppp: [1, 1, 1],
            m_ppn: [1, 1, -1],
            m_ppz: [1, 1, 0],
            m_pnp: [1, -1, 1],
            m_pnn: [1, -1, -1],
            m_pnz: [1, -1, 0],
            m_pzp: [1, 0, 1],
            m_pzn: [1, 0, -1],
            m_pzz: [1, 0, 0],
            m_npp: [-1, 1, 1],
            m_npn: [-1, 1, -1],
            m_npz: [-1, 1, 0],
            m_nnp: [-1, -1, 1],
            m_nnn: [-1, -1, -1],
            m_nnz: [-1, -1, 0],
            m_nzp: [-1, 0, 1],
            m_nzn: [-1, 0, -1],
            m_nzz: [-1, 0, 0],
            m_zpp: [0, 1, 1],
            m_zpn: [0, 1, -1],
            m_zpz: [0, 1, 0],
            m_znp: [0, -1, 1],
            m_znn: [0, -1, -1],
            m_znz: [0, -1, 0],
            m_zzp: [0, 0, 1],
            m_zzn: [0, 0, -1],
            m_zzz: [0, 0, 0],
            m_zzzz: [0, 0, 0, 0],
            m_nzzz: [-1, 0, 0, 0],
            m_nnzz: [-1, -1, 0, 0],
            m_nnnz: [-1, -1, -1, 0],
            m_nnnn: [-1, -1, -1, -1],
            m_pzzz: [1, 0, 0, 0],
            m_pnzz: [1, -1, 0, 0],
            m_pnnz: [1, -1, -1, 0],
            m_pnnn: [1, -1, -1, -1],
            m_ppzz: [1, 1, 0, 0],
            m_ppnz: [1, 1, -1, 0],
            m_ppnn: [1, 1, -1, -1],
            m_pppz: [1, 1, 1, 0],
            m_pppn: [1, 1, 1, -1],
            m_pppp: [1, 1, 1, 1],
            m_zppp: [0, 1, 1, 1],
            m_pznp: [1, 0, -1, 1],
            m_nzzp: [-1, 0, 0, 1],
            m_znzn: [0, -1, 0, -1],
            m_znzz: [0, -1, 0, 0],
            m_zpzp: [0, 1, 0, 1],
            m_zzzzz: [0, 0, 0, 0, 0],
            m_pzzzz: [1, 0, 0, 0, 0],
            m_zpppp: [0, 1, 1, 1, 1],
            m_nnzzp: [-1, -1, 0, 0, 1],
            m_zppppp: [0, 1, 1, 1, 1, 1],
        }
    };
}
