//! What users of glam and nalgebra reach for on every type: `Display`, indexing,
//! iteration, array conversions, `Sum`/`Product`, operators on references, finiteness
//! checks and division by an invertible value. None of it adds arithmetic of its own:
//! every operator here forwards to the by-value impls of `products.rs`/`operators.rs`.

use proc_macro2::TokenStream;
use quote::quote;

use super::expr::{
    field_ident, one, output_type, quadratic_component, scalar_type, type_tokens, Operand,
};
use crate::algebra::{blade_name, Involution, ProductKind};
use crate::plan::{Output, Plan, TypeId};
use crate::spec::Op;

/// The conveniences of every emitted type, and the module-level helpers they share.
pub fn emit_conveniences(plan: &Plan) -> TokenStream {
    let batch = plan.lanes.is_some();
    let mut out = TokenStream::new();
    if !batch {
        out.extend(display_helper(plan));
    }
    for &t in &plan.emitted {
        out.extend(components(plan, t));
        if !batch {
            out.extend(display(plan, t));
            out.extend(finiteness(plan, t));
        }
        out.extend(folds(plan, t));
    }
    out.extend(reference_operators(plan));
    if !batch {
        out.extend(division(plan));
    }
    out
}

/// Types whose geometric square stays in the type (`Even`, `Multivector`): they get
/// `MulAssign<Self>`, and `Product` when they also hold the scalar (for `ONE`).
fn closed_under_geometric(plan: &Plan, t: TypeId) -> bool {
    plan.products.contains(&ProductKind::Geometric)
        && plan.paired.contains(&t)
        && plan.product_output(ProductKind::Geometric, t, t) == Output::Type(t)
}

fn display_helper(plan: &Plan) -> TokenStream {
    let s = scalar_type(plan);
    super::template::fill(DISPLAY_HELPER, &[("s", &s)])
}

/// The `Display` helper (`#s` the scalar type).
const DISPLAY_HELPER: &str = r#"
/// Writes `1 + 2 e1 - 0.5 e12`: each non-zero component, a space, its blade (the
/// scalar without one; the space keeps `1 e12` apart from ten to the twelfth),
/// honouring the formatter's precision; at a precision `p`, terms that would print
/// as zero are left out. Magnitudes below `1e-5` or from `1e16` print in exponent
/// form (`5e-324`, not 324 digits), except below `1e-5` at a precision, where the
/// fixed form shows what rounds away. Zero prints as `0`.
fn display_terms(
    f: &mut ::core::fmt::Formatter<'_>,
    terms: &[(#s, &str)],
) -> ::core::fmt::Result {
    /// Notes whether a non-zero digit is written: a term "prints as zero" exactly
    /// when the formatter's own rounding leaves none (no buffer, so `no_std`).
    struct NonZeroDigit(bool);
    impl ::core::fmt::Write for NonZeroDigit {
        fn write_str(&mut self, s: &str) -> ::core::fmt::Result {
            self.0 |= s.bytes().any(|b| (b'1'..=b'9').contains(&b));
            Ok(())
        }
    }
    let mut first = true;
    for &(value, blade) in terms {
        let magnitude = value.abs();
        if magnitude == 0.0 {
            continue;
        }
        // NaN and infinities print as they are, in the plain form.
        let large = magnitude >= 1e16 && magnitude.is_finite();
        let small = magnitude < 1e-5;
        let exponent = large || (small && f.precision().is_none());
        if let (Some(p), false) = (f.precision(), exponent || !magnitude.is_finite()) {
            let mut digits = NonZeroDigit(false);
            ::core::fmt::write(&mut digits, format_args!("{:.*}", p, magnitude))?;
            if !digits.0 {
                continue;
            }
        }
        let negative = value.is_sign_negative() && !value.is_nan();
        match (first, negative) {
            (true, true) => f.write_str("-")?,
            (true, false) => {}
            (false, true) => f.write_str(" - ")?,
            (false, false) => f.write_str(" + ")?,
        }
        match (f.precision(), exponent) {
            (Some(p), true) => write!(f, "{:.*e}", p, magnitude)?,
            (Some(p), false) => write!(f, "{:.*}", p, magnitude)?,
            (None, true) => write!(f, "{:e}", magnitude)?,
            (None, false) => write!(f, "{}", magnitude)?,
        }
        if !blade.is_empty() {
            write!(f, " {}", blade)?;
        }
        first = false;
    }
    if first {
        f.write_str("0")?;
    }
    Ok(())
}
"#;

fn display(plan: &Plan, t: TypeId) -> TokenStream {
    let name = type_tokens(plan, t);
    let terms = plan.types.get(t).blades.iter().map(|&b| {
        let field = field_ident(b);
        let label = if b == 0 { String::new() } else { blade_name(b) };
        quote!((self.#field, #label))
    });
    quote! {
        impl ::core::fmt::Display for #name {
            fn fmt(&self, f: &mut ::core::fmt::Formatter<'_>) -> ::core::fmt::Result {
                display_terms(f, &[#(#terms),*])
            }
        }
    }
}

/// Indexing, iteration and array conversions, all by canonical component position.
fn components(plan: &Plan, t: TypeId) -> TokenStream {
    let def = plan.types.get(t);
    let name = type_tokens(plan, t);
    let type_name = &def.name;
    let s = scalar_type(plan);
    let len = def.blades.len();
    let indices: Vec<usize> = (0..len).collect();
    let fields: Vec<_> = def.blades.iter().map(|&b| field_ident(b)).collect();
    let out_of_range = format!("index {{}} out of range for `{type_name}` ({len} components)");
    quote! {
        impl ::core::ops::Index<usize> for #name {
            type Output = #s;
            /// The component at canonical position `index`; panics past `LEN`, like an array.
            #[inline]
            fn index(&self, index: usize) -> &#s {
                match index {
                    #(#indices => &self.#fields,)*
                    _ => panic!(#out_of_range, index),
                }
            }
        }

        impl ::core::ops::IndexMut<usize> for #name {
            /// The component at canonical position `index`; panics past `LEN`, like an array.
            #[inline]
            fn index_mut(&mut self, index: usize) -> &mut #s {
                match index {
                    #(#indices => &mut self.#fields,)*
                    _ => panic!(#out_of_range, index),
                }
            }
        }

        impl #name {
            /// The components in canonical order, by value.
            #[inline]
            pub fn iter(&self) -> ::core::array::IntoIter<#s, #len> {
                self.to_array().into_iter()
            }
        }

        impl ::core::iter::IntoIterator for #name {
            type Item = #s;
            type IntoIter = ::core::array::IntoIter<#s, #len>;
            #[inline]
            fn into_iter(self) -> Self::IntoIter {
                self.to_array().into_iter()
            }
        }

        impl ::core::convert::From<[#s; #len]> for #name {
            #[inline]
            fn from(components: [#s; #len]) -> #name {
                #name::from_array(components)
            }
        }

        impl ::core::convert::From<#name> for [#s; #len] {
            #[inline]
            fn from(value: #name) -> [#s; #len] {
                value.to_array()
            }
        }
    }
}

fn finiteness(plan: &Plan, t: TypeId) -> TokenStream {
    let name = type_tokens(plan, t);
    let fields: Vec<_> = plan
        .types
        .get(t)
        .blades
        .iter()
        .map(|&b| field_ident(b))
        .collect();
    quote! {
        impl #name {
            /// Whether every component is finite (neither infinite nor NaN).
            #[inline]
            #[must_use]
            pub fn is_finite(self) -> bool {
                #(self.#fields.is_finite())&&*
            }

            /// Whether any component is NaN.
            #[inline]
            #[must_use]
            pub fn is_nan(self) -> bool {
                #(self.#fields.is_nan())||*
            }
        }
    }
}

/// `Sum` (types with `+`), `Product` and `MulAssign<Self>` (types closed under `*`).
fn folds(plan: &Plan, t: TypeId) -> TokenStream {
    let name = type_tokens(plan, t);
    let mut out = TokenStream::new();
    if plan.has(Op::Add) && plan.paired.contains(&t) {
        out.extend(quote! {
            impl ::core::iter::Sum for #name {
                #[inline]
                fn sum<I: ::core::iter::Iterator<Item = #name>>(iter: I) -> #name {
                    iter.fold(#name::ZERO, |total, x| total + x)
                }
            }

            impl<'a> ::core::iter::Sum<&'a #name> for #name {
                #[inline]
                fn sum<I: ::core::iter::Iterator<Item = &'a #name>>(iter: I) -> #name {
                    iter.fold(#name::ZERO, |total, x| total + *x)
                }
            }
        });
    }
    if closed_under_geometric(plan, t) {
        out.extend(quote! {
            impl ::core::ops::MulAssign<#name> for #name {
                #[inline]
                fn mul_assign(&mut self, rhs: #name) {
                    *self = *self * rhs;
                }
            }
        });
        if plan.types.get(t).blades.contains(&0) {
            out.extend(quote! {
                impl ::core::iter::Product for #name {
                    #[inline]
                    fn product<I: ::core::iter::Iterator<Item = #name>>(iter: I) -> #name {
                        iter.fold(#name::ONE, |total, x| total * x)
                    }
                }

                impl<'a> ::core::iter::Product<&'a #name> for #name {
                    #[inline]
                    fn product<I: ::core::iter::Iterator<Item = &'a #name>>(iter: I) -> #name {
                        iter.fold(#name::ONE, |total, x| total * *x)
                    }
                }
            });
        }
    }
    out
}

/// `&a op &b` for every operator the by-value impls have, over the same operand pairs,
/// and `-&a`: each forwards to the by-value impl (all types are `Copy`). Outside the batch
/// modules also the mixed forms glam has (`&a op b`, `a op &b`), the assigning forms with
/// a reference (`a += &b`, `r *= &q`, `a *= &s`, `a /= &s`) and scalar division by and of
/// references (`&a / s`, `a / &s`, `&a / &s`); the batch modules keep the first two, whose
/// impls are a quarter of the count.
///
/// An operand on the left by reference is one impl per type and operator, generic over the
/// right operand (`&a op x` wherever `a op x` is implemented), not one per pair: the
/// compiler checks every impl whose self type is a reference against every other impl of
/// the same trait with a reference self type, the whole crate's together, so per-pair
/// impls made that check quadratic in the number of types times algebras (BENCHMARKS.md,
/// "Reference operators, one impl per type"). The scalar on the left keeps impls per
/// pair: a generic impl for `&f64` would break the orphan rule.
fn reference_operators(plan: &Plan) -> TokenStream {
    let batch = plan.lanes.is_some();
    let mut operators = Vec::new();
    for &kind in &plan.products {
        match kind {
            ProductKind::Geometric => operators.push((quote!(Mul), quote!(mul))),
            ProductKind::Outer => operators.push((quote!(BitXor), quote!(bitxor))),
            ProductKind::Inner => operators.push((quote!(BitOr), quote!(bitor))),
            _ => {}
        }
    }
    if plan.has(Op::Add) {
        operators.push((quote!(Add), quote!(add)));
        operators.push((quote!(Sub), quote!(sub)));
    }
    let mut out = TokenStream::new();
    // `&a op x` for each type `a` (not the scalar), generic over `x`: outside the batch
    // modules `x` is any right operand, by value or by reference (`a op &b` is below);
    // in the batch modules, which have no `a op &b`, any reference to a right operand.
    for &a in &plan.paired {
        let lhs = type_tokens(plan, a);
        for (op, method) in &operators {
            out.extend(if batch {
                quote! {
                    impl<'r, Rhs: ::core::marker::Copy> ::core::ops::#op<&'r Rhs> for &#lhs
                    where
                        #lhs: ::core::ops::#op<Rhs>,
                    {
                        type Output = <#lhs as ::core::ops::#op<Rhs>>::Output;
                        #[inline]
                        fn #method(self, rhs: &'r Rhs) -> Self::Output {
                            ::core::ops::#op::#method(*self, *rhs)
                        }
                    }
                }
            } else {
                quote! {
                    impl<Rhs> ::core::ops::#op<Rhs> for &#lhs
                    where
                        #lhs: ::core::ops::#op<Rhs>,
                    {
                        type Output = <#lhs as ::core::ops::#op<Rhs>>::Output;
                        #[inline]
                        fn #method(self, rhs: Rhs) -> Self::Output {
                            ::core::ops::#op::#method(*self, rhs)
                        }
                    }
                }
            });
        }
    }
    for (a, b) in plan.operand_pairs() {
        let (lhs, rhs) = (type_tokens(plan, a), type_tokens(plan, b));
        for (op, method) in &operators {
            if a == TypeId::SCALAR {
                out.extend(quote! {
                    impl ::core::ops::#op<&#rhs> for &#lhs {
                        type Output = <#lhs as ::core::ops::#op<#rhs>>::Output;
                        #[inline]
                        fn #method(self, rhs: &#rhs) -> Self::Output {
                            ::core::ops::#op::#method(*self, *rhs)
                        }
                    }
                });
                if !batch {
                    out.extend(quote! {
                        impl ::core::ops::#op<#rhs> for &#lhs {
                            type Output = <#lhs as ::core::ops::#op<#rhs>>::Output;
                            #[inline]
                            fn #method(self, rhs: #rhs) -> Self::Output {
                                ::core::ops::#op::#method(*self, rhs)
                            }
                        }
                    });
                }
            }
            if !batch {
                out.extend(quote! {
                    impl ::core::ops::#op<&#rhs> for #lhs {
                        type Output = <#lhs as ::core::ops::#op<#rhs>>::Output;
                        #[inline]
                        fn #method(self, rhs: &#rhs) -> Self::Output {
                            ::core::ops::#op::#method(self, *rhs)
                        }
                    }
                });
            }
        }
        if !batch
            && a != TypeId::SCALAR
            && plan.has(Op::Add)
            && plan.sum_output(a, b) == Output::Type(a)
        {
            out.extend(quote! {
                impl ::core::ops::AddAssign<&#rhs> for #lhs {
                    #[inline]
                    fn add_assign(&mut self, rhs: &#rhs) {
                        *self += *rhs;
                    }
                }

                impl ::core::ops::SubAssign<&#rhs> for #lhs {
                    #[inline]
                    fn sub_assign(&mut self, rhs: &#rhs) {
                        *self -= *rhs;
                    }
                }
            });
        }
    }
    let s = scalar_type(plan);
    for &t in &plan.emitted {
        let name = type_tokens(plan, t);
        out.extend(quote! {
            impl ::core::ops::Neg for &#name {
                type Output = #name;
                #[inline]
                fn neg(self) -> #name {
                    -*self
                }
            }
        });
        if batch {
            continue;
        }
        out.extend(quote! {
            impl ::core::ops::Div<#s> for &#name {
                type Output = #name;
                #[inline]
                fn div(self, rhs: #s) -> #name {
                    *self / rhs
                }
            }

            impl ::core::ops::Div<&#s> for #name {
                type Output = #name;
                #[inline]
                fn div(self, rhs: &#s) -> #name {
                    self / *rhs
                }
            }

            impl ::core::ops::Div<&#s> for &#name {
                type Output = #name;
                #[inline]
                fn div(self, rhs: &#s) -> #name {
                    *self / *rhs
                }
            }

            impl ::core::ops::MulAssign<&#s> for #name {
                #[inline]
                fn mul_assign(&mut self, rhs: &#s) {
                    *self *= *rhs;
                }
            }

            impl ::core::ops::DivAssign<&#s> for #name {
                #[inline]
                fn div_assign(&mut self, rhs: &#s) {
                    *self /= *rhs;
                }
            }
        });
        if closed_under_geometric(plan, t) {
            out.extend(quote! {
                impl ::core::ops::MulAssign<&#name> for #name {
                    #[inline]
                    fn mul_assign(&mut self, rhs: &#name) {
                        *self *= *rhs;
                    }
                }
            });
        }
    }
    out
}

/// `a / b = a * b^-1` for every `b` whose inverse is `~b / <b ~b>` (blades and versors of
/// Euclidean G2/G3, G3's rotors): like scalar division, a zero `<b ~b>` gives non-finite
/// components. Types whose inverse needs a linear solve that can fail (a general
/// multivector, a G4 even element) have no `/`: an operator cannot report the failure,
/// so they keep the checked `inverse()`.
fn division(plan: &Plan) -> TokenStream {
    if !(plan.products.contains(&ProductKind::Geometric) && plan.has(Op::Inverse)) {
        return TokenStream::new();
    }
    let one = one(plan);
    let mut out = TokenStream::new();
    for (a, b) in plan.operand_pairs() {
        if b == TypeId::SCALAR || !plan.has_scalar_self_product(b) {
            continue;
        }
        let output = plan.product_output(ProductKind::Geometric, a, b);
        if output == Output::Zero {
            continue;
        }
        let (lhs, rhs, out_ty) = (
            type_tokens(plan, a),
            type_tokens(plan, b),
            output_type(plan, output),
        );
        let divisor = Operand::new(quote!(rhs), b);
        let denominator = quadratic_component(plan, &divisor, Involution::Reverse, 0);
        let inverse_fields = plan.types.get(b).blades.iter().map(|&blade| {
            let f = field_ident(blade);
            if Involution::Reverse.sign(blade) > 0 {
                quote!(#f: rhs.#f * scale)
            } else {
                quote!(#f: -rhs.#f * scale)
            }
        });
        out.extend(quote! {
            impl ::core::ops::Div<#rhs> for #lhs {
                type Output = #out_ty;
                /// `self * rhs^-1` with `rhs^-1 = ~rhs / <rhs ~rhs>`; non-finite when
                /// `<rhs ~rhs>` is zero (see `inverse` for the checked form).
                #[inline]
                fn div(self, rhs: #rhs) -> #out_ty {
                    let scale = #one / (#denominator);
                    self * #rhs { #(#inverse_fields),* }
                }
            }
        });
    }
    out
}
