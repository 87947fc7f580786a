//! The structs themselves: fields, constants, constructors, conversions, `Zero`.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::expr::{field_ident, scalar_type, type_tokens};
use crate::algebra::blade_name;
use crate::plan::{Plan, TypeId, TypeKind};

fn describe(plan: &Plan, id: TypeId) -> String {
    let def = plan.types.get(id);
    let components: Vec<String> = def.blades.iter().map(|&b| blade_name(b)).collect();
    let what = match def.kind {
        TypeKind::Grade(1) => "A vector".to_owned(),
        TypeKind::Grade(k) => format!("A grade-{k} multivector"),
        TypeKind::Even => "An even multivector (a rotor when unit)".to_owned(),
        TypeKind::Odd => "An odd multivector".to_owned(),
        TypeKind::Multivector => "A general multivector".to_owned(),
        TypeKind::User | TypeKind::Scalar => format!("The user type `{}`", def.name),
    };
    format!("{what}: components {}.", components.join(", "))
}

/// One struct with its constants, constructors and conversions.
pub fn emit_struct(plan: &Plan, id: TypeId) -> TokenStream {
    let def = plan.types.get(id);
    let name = type_tokens(plan, id);
    let s = scalar_type(plan);
    let doc = describe(plan, id);
    let fields: Vec<_> = def.blades.iter().map(|&b| field_ident(b)).collect();
    let field_docs = def
        .blades
        .iter()
        .map(|&b| format!("The `{}` component.", blade_name(b)));
    let len = def.blades.len();
    let zero = super::expr::zero(plan);
    let one = super::expr::one(plan);
    let basis = def.blades.iter().enumerate().map(|(i, &blade)| {
        let constant = if blade == 0 {
            format_ident!("ONE")
        } else {
            format_ident!("{}", blade_name(blade).to_uppercase())
        };
        let values = (0..len).map(|j| if i == j { quote!(#one) } else { quote!(#zero) });
        let doc = format!("The basis blade `{}`.", blade_name(blade));
        quote! {
            #[doc = #doc]
            pub const #constant: Self = Self::new(#(#values),*);
        }
    });
    let indices: Vec<usize> = (0..len).collect();
    let zeros = vec![zero.clone(); len];
    // Widening conversions into the types that hold every blade of this one:
    // `Bivector -> Even`, `Vector -> Odd`, anything -> `Multivector` (the rest of the
    // target's components zero). Only into these three: between user types a subset
    // relation would be an accident of the blades chosen, not a promise.
    let n = plan.metric.dimension();
    let into_multivector: TokenStream = [TypeId::even(n), TypeId::odd(n), TypeId::multivector(n)]
        .into_iter()
        .filter(|&target| target != id && plan.emitted.contains(&target))
        .filter(|&target| {
            let held = &plan.types.get(target).blades;
            def.blades.iter().all(|b| held.contains(b))
        })
        .map(|target| {
            let target_name = type_tokens(plan, target);
            let values = def.blades.iter().map(|&b| {
                let f = field_ident(b);
                quote!(#f: value.#f)
            });
            quote! {
                impl ::core::convert::From<#name> for #target_name {
                    #[inline]
                    fn from(value: #name) -> #target_name {
                        #target_name { #(#values,)* ..#target_name::ZERO }
                    }
                }
            }
        })
        .collect();
    quote! {
        #[doc = #doc]
        #[derive(Clone, Copy, Debug, PartialEq, Default)]
        #[repr(C)]
        pub struct #name {
            #(#[doc = #field_docs] pub #fields: #s,)*
        }

        impl #name {
            /// The number of components.
            pub const LEN: usize = #len;
            /// All components zero.
            pub const ZERO: Self = Self::new(#(#zeros),*);
            #(#basis)*

            /// A value from its components in canonical order.
            #[inline]
            #[must_use]
            #[allow(clippy::too_many_arguments)]
            pub const fn new(#(#fields: #s),*) -> Self {
                Self { #(#fields),* }
            }

            /// A value from its components in canonical order.
            #[inline]
            #[must_use]
            pub const fn from_array(components: [#s; #len]) -> Self {
                Self { #(#fields: components[#indices]),* }
            }

            /// The components in canonical order (grade first, then lexicographic).
            #[inline]
            #[must_use]
            pub const fn to_array(self) -> [#s; #len] {
                [#(self.#fields),*]
            }
        }

        impl ::core::convert::From<Zero> for #name {
            #[inline]
            fn from(_: Zero) -> #name {
                #name::ZERO
            }
        }

        #into_multivector
    }
}

/// `Zero`, the aliases, the scalar-to-multivector conversion and `grade_dimension`.
pub fn emit_support_items(plan: &Plan) -> TokenStream {
    let n = plan.metric.dimension();
    let s = scalar_type(plan);
    let zero = super::expr::zero(plan);
    let mut out = quote! {
        /// The result of a product that is zero for every input (for example the outer
        /// product of two parallel grades that cannot fit); converts into every type.
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
        pub struct Zero;

        impl ::core::convert::From<Zero> for #s {
            #[inline]
            fn from(_: Zero) -> #s {
                #zero
            }
        }

        /// The dimension of the grade-`r` subspace: the binomial coefficient C(n, r).
        #[must_use]
        pub const fn grade_dimension(r: usize) -> usize {
            if r > #n {
                return 0;
            }
            let mut result = 1;
            let mut i = 0;
            while i < r {
                result = result * (#n - i) / (i + 1);
                i += 1;
            }
            result
        }

        /// The dimension of the algebra's vector space: the number of generators.
        pub const DIMENSION: usize = #n;
    };
    let top = TypeId::grade(n);
    if plan.emitted.contains(&top) {
        let name = type_tokens(plan, top);
        out.extend(quote! {
            /// The top grade: multiples of e1..en.
            pub type Pseudoscalar = #name;
        });
    }
    if plan.emitted.contains(&TypeId::even(n)) {
        out.extend(quote! {
            /// An even multivector used as a rotor: `y = R x ~R`, `R = exp(-B theta / 2)`.
            ///
            /// An alias, not a new type: `Debug` prints a rotor as `Even { .. }` and
            /// `Display` as its terms (`0.7 - 0.7e12`).
            pub type Rotor = Even;
        });
    }
    for target in [TypeId::even(n), TypeId::multivector(n)] {
        if plan.emitted.contains(&target) {
            let name = type_tokens(plan, target);
            out.extend(quote! {
                impl ::core::convert::From<#s> for #name {
                    #[inline]
                    fn from(value: #s) -> #name {
                        #name { s: value, ..#name::ZERO }
                    }
                }
            });
        }
    }
    out
}
