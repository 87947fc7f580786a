//! The floating-point functions the emitted code calls beyond `core`, in one private module
//! per algebra, and the bounds that decide when a sum of squares may be used unscaled.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::expr::scalar_type;
use crate::plan::Plan;
use crate::spec::{Math, Scalar};

/// The one-argument functions, as `(std method, libm function for f64)`.
const UNARY: [(&str, &str); 7] = [
    ("sqrt", "sqrt"),
    ("sin", "sin"),
    ("cos", "cos"),
    ("cosh", "cosh"),
    ("sinh", "sinh"),
    ("asinh", "asinh"),
    ("ln_1p", "log1p"),
];

/// `mod math` with `std`'s methods.
fn std_module(s: &TokenStream) -> TokenStream {
    let unary = UNARY.iter().map(|&(name, _)| {
        let ident = format_ident!("{name}");
        quote! {
            #[inline]
            pub(super) fn #ident(x: #s) -> #s {
                x.#ident()
            }
        }
    });
    quote! {
        #(#unary)*

        #[inline]
        fn sin_cos_any(x: #s) -> (#s, #s) {
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
}

/// `mod math` through the `libm` crate at `path` (`sqrtf` and so on for `f32`).
fn libm_module(s: &TokenStream, scalar: Scalar, path: &syn::Path) -> TokenStream {
    let suffix = if scalar == Scalar::F32 { "f" } else { "" };
    let libm = |name: &str| format_ident!("{name}{suffix}");
    let unary = UNARY.iter().map(|&(name, function)| {
        let ident = format_ident!("{name}");
        let function = libm(function);
        quote! {
            #[inline]
            pub(super) fn #ident(x: #s) -> #s {
                #path::#function(x)
            }
        }
    });
    let (sincos, atan2, hypot) = (libm("sincos"), libm("atan2"), libm("hypot"));
    quote! {
        #(#unary)*

        #[inline]
        fn sin_cos_any(x: #s) -> (#s, #s) {
            #path::#sincos(x)
        }

        #[inline]
        pub(super) fn atan2(y: #s, x: #s) -> #s {
            #path::#atan2(y, x)
        }

        #[inline]
        pub(super) fn hypot(x: #s, y: #s) -> #s {
            #path::#hypot(x, y)
        }
    }
}

/// The functions every kernel reaches through `math::` (square root, trigonometric and
/// hyperbolic functions), written once so that `std` and `libm` differ in this one place,
/// and `SQUARE_MIN`/`SQUARE_MAX`.
pub fn emit_math(plan: &Plan, math: &Math) -> TokenStream {
    let s = scalar_type(plan);
    let doc = "The floating-point functions beyond `core` that this algebra calls, in one \
               place (the `math:` key of `algebra!` chooses `std` or `libm`).";
    let sin_cos = super::sin_cos::emit_sin_cos(plan.scalar);
    let module = match math {
        Math::Std => {
            let body = std_module(&s);
            quote! {
                #[doc = #doc]
                #[allow(dead_code)]
                mod math { #body #sin_cos }
            }
        }
        Math::Libm(path) => {
            let body = libm_module(&s, plan.scalar, path);
            quote! {
                #[doc = #doc]
                #[allow(dead_code)]
                mod math { #body #sin_cos }
            }
        }
        Math::Auto(path) => {
            let with_std = std_module(&s);
            let without = libm_module(&s, plan.scalar, path);
            quote! {
                #[doc = #doc]
                #[cfg(feature = "std")]
                #[allow(dead_code)]
                mod math { #with_std #sin_cos }

                #[doc = #doc]
                #[cfg(not(feature = "std"))]
                #[allow(dead_code)]
                mod math { #without #sin_cos }
            }
        }
    };
    quote! {
        #module

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
