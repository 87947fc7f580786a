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
