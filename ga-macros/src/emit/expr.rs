//! Building blocks for readable straight-line code: operands, signed sums, struct literals.

use std::collections::BTreeMap;

use proc_macro2::{Literal, TokenStream};
use quote::{format_ident, quote};

use crate::algebra::{blade_name, Blade};
use crate::plan::{Output, Plan, TypeId};
use crate::spec::Scalar;

/// A value in emitted code: an expression of a known type whose components can be read.
#[derive(Clone)]
pub struct Operand {
    pub expr: TokenStream,
    pub ty: TypeId,
}

impl Operand {
    /// An operand named by a plain identifier (`self`, `rhs`, a local).
    pub fn new(expr: TokenStream, ty: TypeId) -> Self {
        Operand { expr, ty }
    }

    /// The expression that reads component `index`: the operand itself for a scalar.
    pub fn component(&self, plan: &Plan, index: usize) -> TokenStream {
        let expr = &self.expr;
        if self.ty == TypeId::SCALAR {
            expr.clone()
        } else {
            let field = field_ident(plan.types.get(self.ty).blades[index]);
            quote!(#expr.#field)
        }
    }

    /// The expression that reads the component on `blade`, if the operand has it.
    pub fn blade(&self, plan: &Plan, blade: Blade) -> Option<TokenStream> {
        let index = plan
            .types
            .get(self.ty)
            .blades
            .iter()
            .position(|&b| b == blade)?;
        Some(self.component(plan, index))
    }
}

/// The field of a blade.
pub fn field_ident(blade: Blade) -> proc_macro2::Ident {
    format_ident!("{}", blade_name(blade))
}

/// The scalar type's tokens (a `wide` vector in a batch module).
pub fn scalar_type(plan: &Plan) -> TokenStream {
    match (plan.scalar, plan.lanes) {
        (Scalar::F32, None) => quote!(f32),
        (Scalar::F64, None) => quote!(f64),
        (scalar, Some(lanes)) => {
            let base = if scalar == Scalar::F32 { "f32" } else { "f64" };
            let name = format_ident!("{base}x{lanes}");
            quote!(::wide::#name)
        }
    }
}

/// The plain scalar type even in a batch module (`f32` for `wide::f32x4`).
pub fn item_scalar_type(plan: &Plan) -> TokenStream {
    match plan.scalar {
        Scalar::F32 => quote!(f32),
        Scalar::F64 => quote!(f64),
    }
}

/// The scalar type's zero, usable in constants.
pub fn zero(plan: &Plan) -> TokenStream {
    match plan.lanes {
        None => {
            let z = float(0.0);
            quote!(#z)
        }
        Some(_) => {
            let s = scalar_type(plan);
            quote!(#s::ZERO)
        }
    }
}

/// The scalar type's one, usable in constants.
pub fn one(plan: &Plan) -> TokenStream {
    match plan.lanes {
        None => {
            let o = float(1.0);
            quote!(#o)
        }
        Some(_) => {
            let s = scalar_type(plan);
            quote!(#s::ONE)
        }
    }
}

/// A float literal without suffix, so that it takes the algebra's scalar type.
pub fn float(value: f64) -> Literal {
    Literal::f64_unsuffixed(value)
}

/// The tokens naming an output type.
pub fn output_type(plan: &Plan, output: Output) -> TokenStream {
    match output {
        Output::Zero => quote!(Zero),
        Output::Type(id) => type_tokens(plan, id),
    }
}

/// The tokens naming a type (the scalar type for `TypeId::SCALAR`).
pub fn type_tokens(plan: &Plan, id: TypeId) -> TokenStream {
    if id == TypeId::SCALAR {
        scalar_type(plan)
    } else {
        let name = format_ident!("{}", plan.types.get(id).name);
        quote!(#name)
    }
}

/// `c1 * m1 + c2 * m2 + ...` with integer coefficients, written without any
/// multiplication by 0 or 1: terms are grouped by |c|, positives first in each group.
pub fn signed_sum(terms: &[(i32, TokenStream)]) -> TokenStream {
    sum_with(terms, join_signed)
}

/// [`signed_sum`] as a running sum `a + b - c`, for short sums where a tree buys no depth.
pub fn signed_sum_linear(terms: &[(i32, TokenStream)]) -> TokenStream {
    sum_with(terms, join_linear)
}

fn sum_with(
    terms: &[(i32, TokenStream)],
    join: fn(&[(bool, TokenStream)], bool) -> TokenStream,
) -> TokenStream {
    if terms.is_empty() {
        let zero = float(0.0);
        return quote!(#zero);
    }
    let mut groups: BTreeMap<i32, Vec<(bool, TokenStream)>> = BTreeMap::new();
    for (c, m) in terms {
        groups.entry(c.abs()).or_default().push((*c > 0, m.clone()));
    }
    let mut out = TokenStream::new();
    let mut first = true;
    for (magnitude, mut group) in groups {
        group.sort_by_key(|(positive, _)| !*positive);
        let all_negative = group.iter().all(|(p, _)| !p);
        let inner = join(&group, all_negative && magnitude != 1);
        if magnitude == 1 {
            if first {
                out.extend(inner);
            } else if all_negative {
                // `inner` already starts with `-`.
                out.extend(inner);
            } else {
                out.extend(quote!(+ #inner));
            }
        } else {
            let factor = float(magnitude as f64);
            let sign = match (first, all_negative) {
                (true, true) => quote!(-),
                (true, false) => quote!(),
                (false, true) => quote!(-),
                (false, false) => quote!(+),
            };
            if group.len() == 1 {
                out.extend(quote!(#sign #factor * #inner));
            } else {
                out.extend(quote!(#sign #factor * (#inner)));
            }
        }
        first = false;
    }
    out
}

fn join_linear(group: &[(bool, TokenStream)], negate_all: bool) -> TokenStream {
    let mut out = TokenStream::new();
    for (i, (positive, m)) in group.iter().enumerate() {
        match (i == 0, *positive != negate_all) {
            (true, true) => out.extend(quote!(#m)),
            (true, false) => out.extend(quote!(-#m)),
            (false, true) => out.extend(quote!(+ #m)),
            (false, false) => out.extend(quote!(- #m)),
        }
    }
    out
}

/// The signed terms of one group as a balanced tree, `(a + b) - (c + d)`: a sum of k terms
/// is then about log2(k) additions deep instead of k - 1 (the compiler may not reassociate
/// floating-point additions), and pairwise summation rounds less than a running sum.
fn join_signed(group: &[(bool, TokenStream)], negate_all: bool) -> TokenStream {
    let terms: Vec<(bool, TokenStream)> = group
        .iter()
        .map(|(positive, m)| (*positive != negate_all, m.clone()))
        .collect();
    match balanced(&terms) {
        (sum, true) => sum,
        (sum, false) if terms.len() == 1 => quote!(-#sum),
        (sum, false) => quote!(-(#sum)),
    }
}

/// `(expression, positive)` with the value `+expression` or `-expression`.
fn balanced(terms: &[(bool, TokenStream)]) -> (TokenStream, bool) {
    if let [(positive, term)] = terms {
        return (term.clone(), *positive);
    }
    let middle = terms.len().div_ceil(2);
    let (left, left_positive) = operand(&terms[..middle]);
    let (right, right_positive) = operand(&terms[middle..]);
    match (left_positive, right_positive) {
        (true, true) => (quote!(#left + #right), true),
        (true, false) => (quote!(#left - #right), true),
        (false, true) => (quote!(#right - #left), true),
        (false, false) => (quote!(#left + #right), false),
    }
}

/// A subtree as an operand: parenthesised unless it is a single term.
fn operand(terms: &[(bool, TokenStream)]) -> (TokenStream, bool) {
    let (sum, positive) = balanced(terms);
    if terms.len() == 1 {
        (sum, positive)
    } else {
        (quote!((#sum)), positive)
    }
}

/// How a value of a type is written: the Rust struct literal `Even { s: .., e12: .. }`,
/// or WGSL's constructor call `Even(.., ..)` with the components in canonical order. The
/// expressions inside are the same tokens either way (WGSL's arithmetic, field access and
/// `let` read like Rust's), which is what lets the WGSL emitter reuse the Rust bodies.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Syntax {
    Rust,
    Wgsl,
}

/// A value of type `output` whose component on each blade is given by `component`
/// (blades it returns `None` for are zero).
pub fn construct(
    plan: &Plan,
    output: Output,
    component: impl FnMut(Blade) -> Option<TokenStream>,
) -> TokenStream {
    construct_in(Syntax::Rust, plan, output, component)
}

/// [`construct`] in the given syntax.
pub fn construct_in(
    syntax: Syntax,
    plan: &Plan,
    output: Output,
    mut component: impl FnMut(Blade) -> Option<TokenStream>,
) -> TokenStream {
    match output {
        Output::Zero => quote!(Zero),
        Output::Type(id) if id == TypeId::SCALAR => component(0).unwrap_or_else(|| zero(plan)),
        Output::Type(id) if syntax == Syntax::Wgsl => {
            let name = type_tokens(plan, id);
            let values = plan
                .types
                .get(id)
                .blades
                .iter()
                .map(|&blade| component(blade).unwrap_or_else(|| zero(plan)));
            quote!(#name(#(#values),*))
        }
        Output::Type(id) => {
            let name = type_tokens(plan, id);
            let fields = plan.types.get(id).blades.iter().map(|&blade| {
                let field = field_ident(blade);
                let value = component(blade).unwrap_or_else(|| zero(plan));
                quote!(#field: #value)
            });
            quote!(#name { #(#fields,)* })
        }
    }
}

/// The component on `blade` of `A f(A)`, `f` an involution, as a signed sum of products of
/// pairs of `A`'s components with like terms collected (`A A` for exp, `A ~A` for the
/// inverse's denominator).
pub fn quadratic_component(
    plan: &Plan,
    operand: &Operand,
    involution: crate::algebra::Involution,
    blade: Blade,
) -> TokenStream {
    let q =
        crate::plan::quadratic_self(&plan.metric, &plan.types.get(operand.ty).blades, involution);
    let terms: Vec<(i32, TokenStream)> = q
        .get(&blade)
        .map(|per_k| {
            per_k[&0]
                .iter()
                .map(|(&(i, j), &c)| {
                    let (a, b) = (operand.component(plan, i), operand.component(plan, j));
                    (c, quote!(#a * #b))
                })
                .collect()
        })
        .unwrap_or_default();
    signed_sum(&terms)
}

/// A balanced sum over leaves in a fixed order, with the same split as [`signed_sum`]'s
/// trees, where a missing leaf (`None`) contributes nothing: the scalar mirror of a SIMD
/// sum whose lanes hold a term in some columns and zero in others. Adding zero is exact,
/// so the mirror rounds exactly like the SIMD sum. `None` when every leaf is missing.
pub fn mirrored_sum(leaves: &[Option<(bool, TokenStream)>]) -> Option<TokenStream> {
    fn tree(leaves: &[Option<(bool, TokenStream)>]) -> Option<(TokenStream, bool, bool)> {
        // (expression, positive, single term)
        match leaves {
            [] => None,
            [leaf] => leaf.clone().map(|(positive, term)| (term, positive, true)),
            _ => {
                let middle = leaves.len().div_ceil(2);
                match (tree(&leaves[..middle]), tree(&leaves[middle..])) {
                    (None, None) => None,
                    (Some(side), None) | (None, Some(side)) => Some(side),
                    (Some((l, lp, ls)), Some((r, rp, rs))) => {
                        let l = if ls { l } else { quote!((#l)) };
                        let r = if rs { r } else { quote!((#r)) };
                        Some(match (lp, rp) {
                            (true, true) => (quote!(#l + #r), true, false),
                            (true, false) => (quote!(#l - #r), true, false),
                            (false, true) => (quote!(#r - #l), true, false),
                            (false, false) => (quote!(#l + #r), false, false),
                        })
                    }
                }
            }
        }
    }
    tree(leaves).map(|(sum, positive, single)| match (positive, single) {
        (true, _) => sum,
        (false, true) => quote!(-#sum),
        (false, false) => quote!(-(#sum)),
    })
}
