//! `shaders: [wgsl]`: the module as WGSL source, one more back end on the same plan.

mod exp_log;
mod source;
mod text;

#[cfg(test)]
pub use source::wgsl_source;
pub use source::{colliding_functions, emit_wgsl};
