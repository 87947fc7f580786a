//! What to emit when the input is wrong: the errors, plus an empty module of the same
//! name so that uses of it do not add a cascade of "unresolved module" errors.

use proc_macro2::TokenStream;
use quote::quote;

/// The compile errors and, when the module's name is known, an empty stand-in with the
/// given visibility (as tokens: syn's types are built without `Clone`, to compile less).
pub fn with_errors(
    error: syn::Error,
    stand_in: Option<(&TokenStream, &syn::Ident)>,
) -> TokenStream {
    let errors = error.into_compile_error();
    match stand_in {
        Some((vis, name)) => quote! {
            #errors
            #vis mod #name {}
        },
        None => errors,
    }
}
