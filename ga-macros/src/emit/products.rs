//! Every bilinear product between the paired types (and the scalar), one impl each.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::expr::{
    construct_in, mirrored_sum, output_type, signed_sum, type_tokens, Operand, Syntax,
};
use crate::algebra::ProductKind;
use crate::plan::{bilinear, LaneProduct, Output, Plan, Side, TypeId};

/// The straight-line value of `lhs (kind) rhs`, and its type.
pub fn product_value(
    plan: &Plan,
    kind: ProductKind,
    lhs: &Operand,
    rhs: &Operand,
) -> (TokenStream, Output) {
    product_value_in(Syntax::Rust, plan, kind, lhs, rhs)
}

/// [`product_value`] in the given syntax: the same sums, in the same order.
pub fn product_value_in(
    syntax: Syntax,
    plan: &Plan,
    kind: ProductKind,
    lhs: &Operand,
    rhs: &Operand,
) -> (TokenStream, Output) {
    let terms = bilinear(
        &plan.metric,
        kind,
        &plan.types.get(lhs.ty).blades,
        &plan.types.get(rhs.ty).blades,
    );
    let output = plan
        .types
        .smallest_holding_preferring(terms.keys().copied(), &[lhs.ty, rhs.ty]);
    if let Some(form) = plan.lane_form(kind, lhs.ty, rhs.ty) {
        return (
            mirror_of_lanes(syntax, plan, &form, lhs, rhs, output),
            output,
        );
    }
    let value = construct_in(syntax, plan, output, |blade| {
        let list = terms.get(&blade)?;
        let summands: Vec<(i32, TokenStream)> = list
            .iter()
            .map(|t| {
                let a = lhs.component(plan, t.lhs);
                let b = rhs.component(plan, t.rhs);
                (t.sign as i32, quote!(#a * #b))
            })
            .collect();
        Some(signed_sum(&summands))
    });
    (value, output)
}

/// The scalar body of a product that also has a lane form: each component sums its terms
/// in the lane form's column order and tree, so that the scalar body, the SIMD body and the
/// batch modules round alike.
fn mirror_of_lanes(
    syntax: Syntax,
    plan: &Plan,
    form: &LaneProduct,
    lhs: &Operand,
    rhs: &Operand,
    output: Output,
) -> TokenStream {
    let Output::Type(id) = output else {
        unreachable!("a lane form has a non-zero output")
    };
    let blades = plan.types.get(id).blades.clone();
    let order = form.sum_order();
    construct_in(syntax, plan, output, |blade| {
        let lane = blades.iter().position(|&b| b == blade)?;
        let leaves: Vec<_> = order
            .iter()
            .map(|&k| {
                let column = &form.columns[k];
                let gathered = column.gather[lane]?;
                let (l, r) = match form.broadcast {
                    Side::Rhs => (gathered, column.broadcast),
                    Side::Lhs => (column.broadcast, gathered),
                };
                let (a, b) = (lhs.component(plan, l), rhs.component(plan, r));
                Some((!column.negate[lane], quote!(#a * #b)))
            })
            .collect();
        mirrored_sum(&leaves)
    })
}

/// The number of multiply terms of a product: what `TERM_COUNTS` reports.
pub fn term_count(plan: &Plan, kind: ProductKind, lhs: TypeId, rhs: TypeId) -> usize {
    bilinear(
        &plan.metric,
        kind,
        &plan.types.get(lhs).blades,
        &plan.types.get(rhs).blades,
    )
    .values()
    .map(Vec::len)
    .sum()
}

/// The trait impls of every product, and the `TERM_COUNTS` table.
pub fn emit_products(plan: &Plan) -> TokenStream {
    let mut impls = TokenStream::new();
    let mut counts = Vec::new();
    for &kind in &plan.products {
        for (a, b) in plan.operand_pairs() {
            impls.extend(product_impl(plan, kind, a, b));
            let (kind_name, a_name, b_name) = (
                kind.name(),
                plan.types.get(a).name.clone(),
                plan.types.get(b).name.clone(),
            );
            let count = term_count(plan, kind, a, b);
            counts.push(quote!((#kind_name, #a_name, #b_name, #count)));
        }
    }
    quote! {
        #impls

        /// (product, lhs type, rhs type, number of multiply terms) for every emitted
        /// product; the scalar operand is named `Scalar`.
        pub const TERM_COUNTS: &[(&str, &str, &str, usize)] = &[#(#counts,)*];
    }
}

fn product_impl(plan: &Plan, kind: ProductKind, a: TypeId, b: TypeId) -> TokenStream {
    let lhs = Operand::new(quote!(self), a);
    let rhs = Operand::new(quote!(rhs), b);
    let (value, output) = product_value(plan, kind, &lhs, &rhs);
    let (lhs_ty, rhs_ty, out_ty) = (
        type_tokens(plan, a),
        type_tokens(plan, b),
        output_type(plan, output),
    );
    let unused = if output == Output::Zero {
        quote!(let _ = (self, rhs);)
    } else {
        quote!()
    };
    let (trait_path, method) = match kind {
        ProductKind::Geometric => (quote!(::core::ops::Mul), format_ident!("mul")),
        ProductKind::Outer => (quote!(::core::ops::BitXor), format_ident!("bitxor")),
        ProductKind::Inner => (quote!(::core::ops::BitOr), format_ident!("bitor")),
        ProductKind::LeftContraction => {
            (quote!(LeftContraction), format_ident!("left_contraction"))
        }
        ProductKind::RightContraction => {
            (quote!(RightContraction), format_ident!("right_contraction"))
        }
        ProductKind::Scalar => (quote!(ScalarProduct), format_ident!("scalar_product")),
        ProductKind::Commutator => (quote!(Commutator), format_ident!("commutator")),
        ProductKind::Regressive => (quote!(Regressive), format_ident!("regressive")),
    };
    // The commutator keeps the terms of `ab` whose blades anticommute, where (ab - ba)/2
    // counts them at full weight, so its body needs no halving.
    let body = match plan.lane_form(kind, a, b).filter(|_| plan.emits_simd()) {
        Some(form) => {
            let lanes =
                super::simd::lane_body(plan, &form, (&quote!(self), a), (&quote!(rhs), b), output);
            super::simd::target_arms(lanes, value)
        }
        None => value,
    };
    quote! {
        impl #trait_path<#rhs_ty> for #lhs_ty {
            type Output = #out_ty;
            #[inline]
            fn #method(self, rhs: #rhs_ty) -> #out_ty {
                #unused
                #body
            }
        }
    }
}

/// The per-algebra traits behind the products that have no operator.
pub fn emit_product_traits(plan: &Plan) -> TokenStream {
    let mut out = TokenStream::new();
    for &kind in &plan.products {
        let (name, method, doc) = match kind {
            ProductKind::LeftContraction => (
                quote!(LeftContraction),
                quote!(left_contraction),
                "The left contraction: the sum of <A_r B_s>_(s-r), zero where r > s.",
            ),
            ProductKind::RightContraction => (
                quote!(RightContraction),
                quote!(right_contraction),
                "The right contraction: the sum of <A_r B_s>_(r-s), zero where s > r.",
            ),
            ProductKind::Scalar => (
                quote!(ScalarProduct),
                quote!(scalar_product),
                "The scalar product <AB>_0.",
            ),
            ProductKind::Commutator => (
                quote!(Commutator),
                quote!(commutator),
                "The commutator product (AB - BA) / 2 (not the cross product).",
            ),
            ProductKind::Regressive => (
                quote!(Regressive),
                quote!(regressive),
                "The regressive product (join) undual(dual(A) ^ dual(B)), through the right complement: metric-free.",
            ),
            _ => continue,
        };
        out.extend(quote! {
            #[doc = #doc]
            pub trait #name<Rhs> {
                /// The smallest type holding every grade the product can have.
                type Output;
                #[doc = #doc]
                #[must_use]
                fn #method(self, rhs: Rhs) -> Self::Output;
            }
        });
    }
    out
}
