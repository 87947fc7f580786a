//! `algebra!` writes, at compile time, every product of a fixed-dimension geometric
//! algebra as straight-line code specialised to the metric's sign table.
//!
//! ```
//! ga_macros::algebra! {
//!     /// Euclidean 3D.
//!     pub mod g3 {
//!         metric: [1, 1, 1],
//!         scalar: f64,
//!     }
//! }
//! use g3::*;
//! let r = (Bivector::E12 * (-std::f64::consts::FRAC_PI_4)).exp(); // a quarter turn
//! let y = r.sandwich(Vector::E1);
//! assert!((y - Vector::E2).norm() < 1e-15);
//! ```
//!
//! The pipeline shows in the modules: `spec` (parse and validate the input, with spans),
//! `algebra` (blades, metric signs, involutions), `plan` (types, term lists, output types),
//! `emit` (the code), with `expand` gluing them and `fallback` writing errors.
//! See `docs/generated-api.md` in the repository for everything a module contains.

mod algebra;
mod emit;
mod expand;
mod fallback;
mod names;
mod plan;
mod spec;

use proc_macro::TokenStream;
use quote::ToTokens;

/// Generates a geometric algebra module: `algebra! { pub mod g3 { metric: [1, 1, 1], scalar: f64 } }`.
///
/// Keys: `metric: [..]` (the squares of e1..en, each 1, -1 or 0; n from 1 to 6) or
/// `signature: (p, q, r)`; `scalar: f32 | f64` (default f64); optional `types: [..]`
/// (built-in names and `Name = [e12, e13]`) and `ops: [..]` to emit only part of it.
///
/// The whole reference follows (also `docs/generated-api.md` in the repository).
///
#[doc = include_str!("../../docs/generated-api.md")]
#[proc_macro]
pub fn algebra(input: TokenStream) -> TokenStream {
    let raw = syn::parse_macro_input!(input as spec::RawAlgebra);
    let stand_in = (raw.vis.to_token_stream(), raw.name.clone());
    expand::algebra(raw)
        .unwrap_or_else(|e| fallback::with_errors(e, Some((&stand_in.0, &stand_in.1))))
        .into()
}

/// The derive form: `#[derive(Algebra)] #[algebra(metric = [1, 1, 1], scalar = f64)] struct G3;`
/// emits the same items as `algebra!` into a sibling module named after the marker in
/// snake case (`g3` here), with the marker's visibility.
#[proc_macro_derive(Algebra, attributes(algebra))]
pub fn derive_algebra(input: TokenStream) -> TokenStream {
    let input = syn::parse_macro_input!(input as syn::DeriveInput);
    let module = syn::Ident::new(
        &names::snake_case(&input.ident.to_string()),
        input.ident.span(),
    );
    let vis = input.vis.to_token_stream();
    expand::derive(input)
        .unwrap_or_else(|e| fallback::with_errors(e, Some((&vis, &module))))
        .into()
}

#[cfg(test)]
mod snapshot_tests;

#[cfg(test)]
mod restriction_tests;

#[cfg(test)]
mod fuzz_tests;

#[cfg(test)]
mod feature_tests;
