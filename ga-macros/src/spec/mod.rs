//! The front end: the macro input parsed with its spans (`parse`), then checked and turned
//! into a [`Spec`] that the back end can trust (`validate`).

mod ctxt;
mod parse;
mod validate;

pub use parse::{RawAlgebra, RawDerive};
#[cfg(feature = "wgsl")]
pub use validate::check_wgsl_names;
pub use validate::{
    check_emitted, grade_type_name, validate, Integration, IntegrationKind, Math, Op, Scalar, Spec,
    TypeRequest,
};
#[cfg(test)]
pub use validate::{validate_for, BackEnds};
