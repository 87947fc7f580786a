//! Named constructors of projective algebras (one null generator `e0`, the others
//! squaring to 1, as in 3D PGA's `metric: [0, 1, 1, 1]`): `Vector::plane` and the point
//! on the grade `n - 1` type, chosen so that `plane ^ point = (a x + b y + c z + d) I`.
//!
//! The point is the right complement of `e0 + x e_x + y e_y + z e_z` (`e_x, e_y, e_z`
//! the Euclidean generators in order), because `e_i ^ dual(e_j)` is `I` for `i = j` and
//! zero otherwise; no metric enters, so the incidence holds in any such algebra.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::expr::{field_ident, scalar_type, type_tokens};
use crate::algebra::Blade;
use crate::plan::{Plan, TypeId};

/// `Vector::plane` (`line` in 2D) and `point` on the grade `n - 1` type, where both
/// types are emitted and the metric is projective.
pub fn emit_projective_constructors(plan: &Plan) -> TokenStream {
    let Some(origin) = plan.metric.projective_origin() else {
        return TokenStream::new();
    };
    let n = plan.metric.dimension();
    let (vector, point) = (TypeId::grade(1), TypeId::grade(n - 1));
    if plan.lanes.is_some() || !plan.emitted.contains(&vector) || !plan.emitted.contains(&point) {
        return TokenStream::new();
    }
    let s = scalar_type(plan);
    let names = ["x", "y", "z", "w", "v"];
    let euclidean: Vec<usize> = (0..n).filter(|&i| i != origin).collect();
    let coords: Vec<_> = (0..n - 1).map(|k| format_ident!("{}", names[k])).collect();
    let normal: Vec<_> = (0..n - 1).map(|k| format_ident!("n{}", names[k])).collect();
    // The vector `e0 + sum x_k e_k` as (generator, value) pairs, and its complement.
    let mut plane_fields: Vec<(Blade, TokenStream)> = vec![(1 << origin, quote!(d))];
    let mut point_fields: Vec<(Blade, TokenStream)> = vec![];
    let (sign, blade) = plan.metric.dual(1 << origin);
    point_fields.push((blade, if sign < 0 { quote!(-1.0) } else { quote!(1.0) }));
    for (k, &g) in euclidean.iter().enumerate() {
        let (c, nc) = (&coords[k], &normal[k]);
        plane_fields.push((1 << g, quote!(#nc)));
        let (sign, blade) = plan.metric.dual(1 << g);
        point_fields.push((blade, if sign < 0 { quote!(-#c) } else { quote!(#c) }));
    }
    let literal = |id: TypeId, fields: &[(Blade, TokenStream)]| {
        let name = type_tokens(plan, id);
        let values = plan.types.get(id).blades.iter().map(|&b| {
            let f = field_ident(b);
            let value = fields
                .iter()
                .find(|(blade, _)| *blade == b)
                .map(|(_, v)| v.clone())
                .unwrap_or_else(|| quote!(0.0));
            quote!(#f: #value)
        });
        quote!(#name { #(#values),* })
    };
    let (plane_name, plane_word) = if n == 3 {
        (format_ident!("line"), "line")
    } else {
        (format_ident!("plane"), "plane")
    };
    let equation: Vec<String> = (0..n - 1).map(|k| format!("n{0} {0}", names[k])).collect();
    let plane_doc = format!(
        "The {plane_word} `{} + d = 0` of this projective algebra: `n` on the Euclidean \
         generators, `d` on the null one; `{plane_word} ^ point` is the equation's value times `I`.",
        equation.join(" + ")
    );
    let point_doc = format!(
        "The point `({})`, the right complement of `e0 + {}` (`e0` the null generator): \
         joined with `regressive`, points give lines and {plane_word}s.",
        names[..n - 1].join(", "),
        (0..n - 1)
            .map(|k| format!("{} e_{}", names[k], names[k]))
            .collect::<Vec<_>>()
            .join(" + ")
    );
    let (vector_name, point_name) = (type_tokens(plan, vector), type_tokens(plan, point));
    let (plane_value, point_value) = (
        literal(vector, &plane_fields),
        literal(point, &point_fields),
    );
    quote! {
        impl #vector_name {
            #[doc = #plane_doc]
            #[inline]
            #[must_use]
            // Not `const`: a point's signs are negations, which a generic scalar's types
            // (num-dual's) do not allow in a `const fn`.
            pub fn #plane_name(#(#normal: #s,)* d: #s) -> Self {
                #plane_value
            }
        }

        impl #point_name {
            #[doc = #point_doc]
            #[inline]
            #[must_use]
            pub fn point(#(#coords: #s),*) -> Self {
                #point_value
            }
        }
    }
}
