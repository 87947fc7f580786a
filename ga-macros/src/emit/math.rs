//! The floating-point functions the emitted code calls beyond `core`, in one private module
//! per algebra, and the bounds that decide when a sum of squares may be used unscaled.

use proc_macro2::TokenStream;
use quote::quote;

use super::expr::scalar_type;
use crate::plan::Plan;

/// The functions every kernel reaches through `math::` (square root, trigonometric and
/// hyperbolic functions), written once so that the `std` methods and `libm` differ in
/// this one place, and `SQUARE_MIN`/`SQUARE_MAX`.
pub fn emit_math(plan: &Plan) -> TokenStream {
    let s = scalar_type(plan);
    let one = |name: &str| -> TokenStream {
        let ident = quote::format_ident!("{name}");
        quote!(x.#ident())
    };
    let unary = ["sqrt", "sin", "cos", "cosh", "sinh", "asinh", "ln_1p"];
    let functions = unary.iter().map(|&name| {
        let ident = quote::format_ident!("{name}");
        let body = one(name);
        quote! {
            #[inline]
            pub(super) fn #ident(x: #s) -> #s {
                #body
            }
        }
    });
    quote! {
        /// The floating-point functions beyond `core` that this algebra calls, in one place.
        #[allow(dead_code)]
        mod math {
            #(#functions)*

            #[inline]
            pub(super) fn sin_cos(x: #s) -> (#s, #s) {
                x.sin_cos()
            }

            #[inline]
            pub(super) fn atan2(y: #s, x: #s) -> #s {
                y.atan2(x)
            }

            #[inline]
            pub(super) fn hypot(x: #s, y: #s) -> #s {
                x.hypot(y)
            }
        }

        /// A sum of squares at least this large lost nothing that matters to underflow: a
        /// square in the subnormal range is off by at most half its spacing,
        /// `MIN_POSITIVE * EPSILON / 2`, below `EPSILON^2` relative to this bound.
        #[allow(dead_code)]
        const SQUARE_MIN: #s = #s::MIN_POSITIVE / #s::EPSILON;

        /// A sum of squares at most this large had no square overflow, and its reciprocal
        /// (and that of its square root) is a normal number.
        #[allow(dead_code)]
        const SQUARE_MAX: #s = #s::EPSILON / #s::MIN_POSITIVE;
    }
}
