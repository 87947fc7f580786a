//! Structure-of-arrays batch modules (`lanes: [4]` gives `mod x4`): the same types with
//! `wide` vectors as components, so that one straight-line product works on 4 or 8 items.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::expr::{field_ident, item_scalar_type, scalar_type, type_tokens};
use crate::plan::{Plan, TypeId};

/// `pub mod x{lanes} { ... }` inside the algebra module: the `items` written from the
/// batch plan `batch`, and the conversions from and to the one-item types.
pub fn emit_batch_module(batch: &Plan, lanes: usize, items: TokenStream) -> TokenStream {
    let conversions: TokenStream = batch
        .emitted
        .iter()
        .map(|&t| item_conversions(batch, t, lanes))
        .collect();
    let name = format_ident!("x{lanes}");
    let lane = scalar_type(batch);
    let doc = format!(
        "The same types with `{lane}` components: {lanes} items at once, structure of \
         arrays, for the straight-line operations (products, sums, involutions, duals, \
         projections, sandwiches). Needs the `wide` crate."
    );
    quote! {
        #[doc = #doc]
        pub mod #name {
            #items
            #conversions
        }
    }
}

fn item_conversions(batch: &Plan, t: TypeId, lanes: usize) -> TokenStream {
    let name = type_tokens(batch, t);
    let lane = scalar_type(batch);
    let s = item_scalar_type(batch);
    let fields: Vec<_> = batch
        .types
        .get(t)
        .blades
        .iter()
        .map(|&b| field_ident(b))
        .collect();
    let indices: Vec<usize> = (0..lanes).collect();
    let per_field_gather = fields.iter().map(|f| {
        let lanes_of_field = indices.iter().map(|i| quote!(items[#i].#f));
        quote!(#f: #lane::new([#(#lanes_of_field),*]))
    });
    let per_item = indices.iter().map(|i| {
        let values = fields.iter().map(|f| quote!(#f: #f[#i]));
        quote!(super::#name { #(#values),* })
    });
    quote! {
        impl #name {
            /// Every lane holding `item`.
            #[inline]
            #[must_use]
            pub fn splat(item: super::#name) -> Self {
                Self { #(#fields: #lane::splat(item.#fields)),* }
            }

            /// Lane `i` holds `items[i]`.
            #[inline]
            #[must_use]
            pub fn from_items(items: [super::#name; #lanes]) -> Self {
                Self { #(#per_field_gather),* }
            }

            /// The items, lane by lane.
            #[inline]
            #[must_use]
            pub fn to_items(self) -> [super::#name; #lanes] {
                #(let #fields: [#s; #lanes] = self.#fields.to_array();)*
                [#(#per_item),*]
            }
        }
    }
}
