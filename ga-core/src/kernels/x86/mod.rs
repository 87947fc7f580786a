//! The x86-64 copies of the kernels, each compiled for the instruction set its name gives
//! and called only after the CPU was checked for it.

mod matrix;
mod rotor_product;

/// The `f32` kernels.
#[cfg(feature = "f32")]
pub mod f32 {
    pub use super::matrix::f32::apply_matrix;
    pub use super::rotor_product::f32::{mul_pairs_avx2, mul_pairs_avx512};
}

/// The `f64` kernels.
#[cfg(feature = "f64")]
pub mod f64 {
    pub use super::matrix::f64::apply_matrix;
    pub use super::rotor_product::f64::{mul_pairs_avx2, mul_pairs_avx512};
}
