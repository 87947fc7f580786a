//! The workspace's integration-test support: a slow, independent reference
//! geometric algebra to check the generated ones against.
//!
//! - [`blade`]: blades as bitmasks, reordering signs, canonical order, names;
//! - [`reference`]: dense multivectors over any metric of squares 1, -1, 0, with
//!   every product, involution, dual, `exp` and `inverse` written from the
//!   definitions of the lecture;
//! - [`close`]: [`assert_close!`] and [`prop_assert_close!`];
//! - [`harness`]: the fixed-seed proptest drivers that check tables of generated
//!   operations against the reference.
//!
//! None of this shares code with `ga-macros`: it is a second, deliberately naive
//! implementation, so that the two can only agree by both being right.

pub mod blade;
pub mod close;
pub mod harness;
pub mod reference;

pub use reference::{Algebra, Product};
