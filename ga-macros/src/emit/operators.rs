//! `+`, `-`, unary `-` and division by a scalar, with their assigning forms.

use proc_macro2::TokenStream;
use quote::quote;

use super::expr::{construct, output_type, scalar_type, type_tokens, Operand};
use crate::plan::{Output, Plan, TypeId};

/// Sums and differences of every pair, negation and scalar division of every type.
pub fn emit_operators(plan: &Plan) -> TokenStream {
    let mut out = TokenStream::new();
    for (a, b) in plan.operand_pairs() {
        out.extend(sum_impl(plan, a, b, false));
        out.extend(sum_impl(plan, a, b, true));
    }
    for &t in &plan.emitted {
        out.extend(unary_operators(plan, t));
    }
    out
}

fn sum_impl(plan: &Plan, a: TypeId, b: TypeId, subtract: bool) -> TokenStream {
    let output = plan.sum_output(a, b);
    let lhs = Operand::new(quote!(self), a);
    let rhs = Operand::new(quote!(rhs), b);
    let value = construct(plan, output, |blade| {
        match (lhs.blade(plan, blade), rhs.blade(plan, blade), subtract) {
            (Some(x), Some(y), false) => Some(quote!(#x + #y)),
            (Some(x), Some(y), true) => Some(quote!(#x - #y)),
            (Some(x), None, _) => Some(x),
            (None, Some(y), false) => Some(y),
            (None, Some(y), true) => Some(quote!(-#y)),
            (None, None, _) => None,
        }
    });
    let (lhs_ty, rhs_ty, out_ty) = (
        type_tokens(plan, a),
        type_tokens(plan, b),
        output_type(plan, output),
    );
    let (op, method) = if subtract {
        (quote!(Sub), quote!(sub))
    } else {
        (quote!(Add), quote!(add))
    };
    let assign = if output == Output::Type(a) {
        let (op_assign, method_assign) = if subtract {
            (quote!(SubAssign), quote!(sub_assign))
        } else {
            (quote!(AddAssign), quote!(add_assign))
        };
        quote! {
            impl ::core::ops::#op_assign<#rhs_ty> for #lhs_ty {
                #[inline]
                fn #method_assign(&mut self, rhs: #rhs_ty) {
                    *self = ::core::ops::#op::#method(*self, rhs);
                }
            }
        }
    } else {
        quote!()
    };
    quote! {
        impl ::core::ops::#op<#rhs_ty> for #lhs_ty {
            type Output = #out_ty;
            #[inline]
            fn #method(self, rhs: #rhs_ty) -> #out_ty {
                #value
            }
        }
        #assign
    }
}

/// Negation and scalar multiplication and division only (when `add` is not requested).
pub fn emit_scaling(plan: &Plan) -> TokenStream {
    plan.emitted
        .iter()
        .map(|&t| unary_operators(plan, t))
        .collect()
}

fn unary_operators(plan: &Plan, t: TypeId) -> TokenStream {
    let name = type_tokens(plan, t);
    let s = scalar_type(plan);
    let fields: Vec<_> = plan
        .types
        .get(t)
        .blades
        .iter()
        .map(|&b| super::expr::field_ident(b))
        .collect();
    // `Mul<S>` comes from the geometric product for paired types; others need it here.
    let scale = if plan.has(crate::spec::Op::Geometric) && plan.paired.contains(&t) {
        quote!()
    } else {
        quote! {
            impl ::core::ops::Mul<#s> for #name {
                type Output = #name;
                #[inline]
                fn mul(self, rhs: #s) -> #name {
                    #name { #(#fields: self.#fields * rhs),* }
                }
            }
        }
    };
    quote! {
        impl ::core::ops::Neg for #name {
            type Output = #name;
            #[inline]
            fn neg(self) -> #name {
                #name { #(#fields: -self.#fields),* }
            }
        }

        #scale

        impl ::core::ops::Div<#s> for #name {
            type Output = #name;
            #[inline]
            fn div(self, rhs: #s) -> #name {
                let inverse = 1.0 / rhs;
                #name { #(#fields: self.#fields * inverse),* }
            }
        }

        impl ::core::ops::MulAssign<#s> for #name {
            #[inline]
            fn mul_assign(&mut self, rhs: #s) {
                #(self.#fields *= rhs;)*
            }
        }

        impl ::core::ops::DivAssign<#s> for #name {
            #[inline]
            fn div_assign(&mut self, rhs: #s) {
                *self = *self / rhs;
            }
        }
    }
}
