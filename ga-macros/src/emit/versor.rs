//! `sandwich`, `reflect`, the blade test and blade factorisation.

use std::collections::{BTreeMap, BTreeSet};

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::expr::{
    construct, field_ident, float, scalar_type, signed_sum, signed_sum_linear, type_tokens, Operand,
};
use super::products::product_value;
use crate::algebra::{blade_name, Involution, ProductKind};
use crate::plan::{bilinear, sandwich, Output, Plan, Quadratic, TypeId, TypeKind};

/// Above this size (|v|^2 |x|) the symbolic expansion is not attempted: it would cost
/// more multiplies than two chained products anyway (G6 rotors).
const FUSED_BUDGET: usize = 2048;

/// The `Sandwich` trait and its impls for every versor type on every emitted type.
pub fn emit_sandwiches(plan: &Plan) -> TokenStream {
    let mut out = quote! {
        /// The versor product: `v x ~v` for even `v`, `v x^ ~v` for odd `v` (x^ the grade
        /// involution), expanded symbolically with like terms collected. Returns `x`'s own
        /// type; `v` should be a unit versor (the result is scaled by |v|^2 otherwise).
        pub trait Sandwich<X> {
            /// `v x ~v` (even `v`) or `v x^ ~v` (odd `v`).
            #[must_use]
            fn sandwich(self, x: X) -> X;
        }
    };
    for v in plan.versors() {
        for &x in &plan.emitted {
            out.extend(sandwich_impl(plan, v, x));
        }
        if plan.emitted.contains(&TypeId::grade(1)) {
            out.extend(emit_sandwich_matrix(plan, v));
        }
    }
    out
}

fn is_odd(plan: &Plan, v: TypeId) -> bool {
    matches!(plan.types.get(v).kind, TypeKind::Grade(1) | TypeKind::Odd)
}

fn sandwich_impl(plan: &Plan, v: TypeId, x: TypeId) -> TokenStream {
    let (v_ty, x_ty) = (type_tokens(plan, v), type_tokens(plan, x));
    let versor = &plan.types.get(v).blades;
    let operand = &plan.types.get(x).blades;
    let odd = is_odd(plan, v);
    let fused = (versor.len() * versor.len() * operand.len() <= FUSED_BUDGET)
        .then(|| sandwich(&plan.metric, versor, odd, operand))
        .filter(|q| fused_multiplies(q, operand) <= chained_multiplies(plan, v, x));
    let body = match fused {
        Some(q) => fused_body(plan, v, x, &q),
        None => chained_body(plan, v, x, odd),
    };
    quote! {
        impl Sandwich<#x_ty> for #v_ty {
            #[inline]
            fn sandwich(self, x: #x_ty) -> #x_ty {
                #body
            }
        }
    }
}

fn fused_multiplies(q: &Quadratic, operand: &[u32]) -> usize {
    let mut pairs = BTreeSet::new();
    let mut entries = 0;
    for (blade, per_k) in q {
        if !operand.contains(blade) {
            continue;
        }
        for pairs_k in per_k.values() {
            entries += 1;
            pairs.extend(pairs_k.keys().copied());
        }
    }
    pairs.len() + entries
}

fn chained_multiplies(plan: &Plan, v: TypeId, x: TypeId) -> usize {
    let versor = &plan.types.get(v).blades;
    let first = bilinear(
        &plan.metric,
        ProductKind::Geometric,
        versor,
        &plan.types.get(x).blades,
    );
    let middle: Vec<u32> = first.keys().copied().collect();
    let second = bilinear(&plan.metric, ProductKind::Geometric, &middle, versor);
    let operand = &plan.types.get(x).blades;
    first.values().map(Vec::len).sum::<usize>()
        + second
            .iter()
            .filter(|(b, _)| operand.contains(b))
            .map(|(_, t)| t.len())
            .sum::<usize>()
}

/// The pieces of the expanded sandwich: `let`s for the products of pairs of the versor's
/// components, and for each output blade and component `k` of `x` the coefficient of
/// `x_k`: a signed sum of those products. Its sums are running sums, not the balanced
/// trees of the products: measured on a chain of G3 rotations, the trees made the
/// sandwich's latency 30% worse (f32), the sums being short and off the path through `x`. A pair whose coefficients are all even is
/// computed as `(v_i + v_i) * v_j`: the factor 2 costs an add once per component instead
/// of a multiply per use. See docs/derivations/sandwich.md.
struct FusedParts {
    lets: TokenStream,
    coefficients: BTreeMap<(u32, usize), Vec<(i32, TokenStream)>>,
}

fn fused_parts(plan: &Plan, v: TypeId, x: TypeId, q: &Quadratic) -> FusedParts {
    let versor = &plan.types.get(v).blades;
    let operand = &plan.types.get(x).blades;
    let this = Operand::new(quote!(self), v);
    let mut uses: BTreeMap<(usize, usize), Vec<i32>> = BTreeMap::new();
    for (blade, per_k) in q {
        if operand.contains(blade) {
            for pairs in per_k.values() {
                for (&pair, &c) in pairs {
                    uses.entry(pair).or_default().push(c);
                }
            }
        }
    }
    let doubled: BTreeSet<(usize, usize)> = uses
        .iter()
        .filter(|(_, cs)| cs.iter().all(|c| c % 2 == 0))
        .map(|(&pair, _)| pair)
        .collect();
    let doubled_components: BTreeSet<usize> = doubled.iter().map(|&(i, _)| i).collect();
    let pair_name = |(i, j): (usize, usize)| {
        format_ident!("{}_{}", blade_name(versor[i]), blade_name(versor[j]))
    };
    let two_name = |i: usize| format_ident!("two_{}", blade_name(versor[i]));
    let two_lets = doubled_components.iter().map(|&i| {
        let name = two_name(i);
        let a = this.component(plan, i);
        quote!(let #name = #a + #a;)
    });
    let pair_lets = uses.keys().map(|&(i, j)| {
        let name = pair_name((i, j));
        let b = this.component(plan, j);
        if doubled.contains(&(i, j)) {
            let two = two_name(i);
            quote!(let #name = #two * #b;)
        } else {
            let a = this.component(plan, i);
            quote!(let #name = #a * #b;)
        }
    });
    let mut coefficients = BTreeMap::new();
    for (&blade, per_k) in q {
        if !operand.contains(&blade) {
            continue;
        }
        for (&k, pairs) in per_k {
            let terms: Vec<(i32, TokenStream)> = pairs
                .iter()
                .map(|(&pair, &c)| {
                    let name = pair_name(pair);
                    (
                        if doubled.contains(&pair) { c / 2 } else { c },
                        quote!(#name),
                    )
                })
                .collect();
            coefficients.insert((blade, k), terms);
        }
    }
    FusedParts {
        lets: quote!(#(#two_lets)* #(#pair_lets)*),
        coefficients,
    }
}

fn fused_body(plan: &Plan, v: TypeId, x: TypeId, q: &Quadratic) -> TokenStream {
    let parts = fused_parts(plan, v, x, q);
    let arg = Operand::new(quote!(x), x);
    let value = construct(plan, Output::Type(x), |blade| {
        let terms: Vec<(i32, TokenStream)> = parts
            .coefficients
            .range((blade, 0)..=(blade, usize::MAX))
            .map(|(&(_, k), coefficient)| {
                let xk = arg.component(plan, k);
                match coefficient.as_slice() {
                    [(c @ (1 | -1), single)] => (*c, quote!(#single * #xk)),
                    _ => {
                        let sum = signed_sum_linear(coefficient);
                        (1, quote!((#sum) * #xk))
                    }
                }
            })
            .collect();
        (!terms.is_empty()).then(|| signed_sum_linear(&terms))
    });
    let lets = parts.lets;
    quote! {
        #lets
        #value
    }
}

/// `sandwich_matrix` and `sandwich_vectors`: the linear map `x -> v x ~v` on vectors,
/// built once and applied to many (the rotation matrix of a rotor).
pub fn emit_sandwich_matrix(plan: &Plan, v: TypeId) -> TokenStream {
    let vector = TypeId::grade(1);
    let blades = plan.types.get(vector).blades.clone();
    let n = blades.len();
    let q = sandwich(
        &plan.metric,
        &plan.types.get(v).blades,
        is_odd(plan, v),
        &blades,
    );
    let parts = fused_parts(plan, v, vector, &q);
    let s = scalar_type(plan);
    let zero = super::expr::zero(plan);
    let rows = blades.iter().map(|&blade| {
        let entries = (0..n).map(|k| {
            parts
                .coefficients
                .get(&(blade, k))
                .map_or_else(|| zero.clone(), |terms| signed_sum_linear(terms))
        });
        quote!([#(#entries),*])
    });
    let fields: Vec<_> = blades.iter().map(|&b| field_ident(b)).collect();
    let index = proc_macro2::Literal::usize_unsuffixed;
    let applied = (0..n).map(|o| {
        let terms = (0..n).map(|k| {
            let f = &fields[k];
            let (row, column) = (index(o), index(k));
            quote!(m[#row][#column] * x.#f)
        });
        let field = &fields[o];
        quote!(#field: #(#terms)+*)
    });
    let name = type_tokens(plan, v);
    let lets = parts.lets;
    let n = index(n);
    quote! {
        impl #name {
            /// The matrix of the vector map `x -> v x ~v` (row = output component, column =
            /// input component, canonical order): the rotation matrix of a unit rotor.
            #[inline]
            #[must_use]
            pub fn sandwich_matrix(self) -> [[#s; #n]; #n] {
                #lets
                [#(#rows),*]
            }

            /// Applies the sandwich to every vector in place, building its matrix once.
            #[inline]
            pub fn sandwich_vectors(self, vectors: &mut [Vector]) {
                let m = self.sandwich_matrix();
                for slot in vectors.iter_mut() {
                    let x = *slot;
                    *slot = Vector { #(#applied),* };
                }
            }
        }
    }
}

/// Two products through local variables, for versors too large to expand.
fn chained_body(plan: &Plan, v: TypeId, x: TypeId, odd: bool) -> TokenStream {
    let versor = &plan.types.get(v).blades;
    let operand = &plan.types.get(x).blades;
    let this = Operand::new(quote!(self), v);
    let arg = Operand::new(quote!(x), x);
    let first = bilinear(&plan.metric, ProductKind::Geometric, versor, operand);
    let middle: Vec<u32> = first.keys().copied().collect();
    let locals = first.iter().map(|(&blade, terms)| {
        let name = format_ident!("m_{}", blade_name(blade));
        let summands: Vec<(i32, TokenStream)> = terms
            .iter()
            .map(|t| {
                let sign = if odd {
                    Involution::GradeInvolution.sign(operand[t.rhs])
                } else {
                    1
                };
                let (a, b) = (this.component(plan, t.lhs), arg.component(plan, t.rhs));
                ((t.sign * sign) as i32, quote!(#a * #b))
            })
            .collect();
        let sum = signed_sum(&summands);
        quote!(let #name = #sum;)
    });
    let second = bilinear(&plan.metric, ProductKind::Geometric, &middle, versor);
    let value = construct(plan, Output::Type(x), |blade| {
        let terms = second.get(&blade)?;
        let summands: Vec<(i32, TokenStream)> = terms
            .iter()
            .map(|t| {
                let m = format_ident!("m_{}", blade_name(middle[t.lhs]));
                let b = this.component(plan, t.rhs);
                let sign = Involution::Reverse.sign(versor[t.rhs]);
                ((t.sign * sign) as i32, quote!(#m * #b))
            })
            .collect();
        Some(signed_sum(&summands))
    });
    quote! {
        #(#locals)*
        #value
    }
}

/// `reflect(n)` on every type, when vectors are emitted.
pub fn emit_reflect(plan: &Plan, t: TypeId) -> TokenStream {
    let name = type_tokens(plan, t);
    quote! {
        impl #name {
            /// The lecture's reflection in the hyperplane orthogonal to `n`: `-n a n^-1`
            /// for a vector, `(-1)^k n A n^-1` for grade k.
            #[inline]
            #[must_use]
            pub fn reflect(self, n: Vector) -> Self {
                Sandwich::sandwich(n, self) / n.norm_squared()
            }
        }
    }
}

/// `is_blade` on bivectors and `factor` on every grade type.
pub fn emit_blades(plan: &Plan, t: TypeId) -> TokenStream {
    let TypeKind::Grade(k) = plan.types.get(t).kind else {
        return quote!();
    };
    let name = type_tokens(plan, t);
    let s = scalar_type(plan);
    let mut methods = TokenStream::new();
    if k == 2 {
        let this = Operand::new(quote!(self), t);
        let unit = Operand::new(quote!(unit), t);
        let (wedge, output) = product_value(plan, ProductKind::Outer, &unit, &unit);
        let descaled = super::unary::descaled(plan, &this, &quote!(largest));
        let check = match output {
            // B ^ B has no components below four dimensions: every bivector is a blade.
            Output::Zero => quote!(true),
            // Squares of the components divided by the largest neither overflow nor
            // underflow, so the test means the same at every magnitude.
            _ => quote! {
                if !self.to_array().iter().all(|c| c.is_finite()) {
                    return false;
                }
                let largest = self.to_array().iter().fold(0.0 as #s, |m, c| m.max(c.abs()));
                if largest == 0.0 {
                    return true;
                }
                let unit = #descaled;
                let wedge = #wedge;
                let size = unit.to_array().iter().map(|c| c * c).sum::<#s>();
                let excess = math::sqrt(wedge.to_array().iter().map(|c| c * c).sum::<#s>());
                excess <= 64.0 * #s::EPSILON * size
            },
        };
        methods.extend(quote! {
            /// Whether this bivector is a blade `a ^ b`: `B ^ B = 0` to rounding (e12 + e34
            /// in four dimensions is not).
            #[must_use]
            pub fn is_blade(self) -> bool {
                #check
            }
        });
    }
    let k_lit = k;
    let fields = plan
        .types
        .get(TypeId::grade(1))
        .blades
        .iter()
        .map(|&b| field_ident(b))
        .collect::<Vec<_>>();
    let zero = float(0.0);
    let candidate_square =
        super::unary::norm_squared_expr(plan, &Operand::new(quote!(candidate), TypeId::grade(1)));
    let descaled_self =
        super::unary::descaled(plan, &Operand::new(quote!(self), t), &quote!(largest));
    methods.extend(quote! {
        /// Factors a blade into orthogonal vectors whose geometric product is the blade,
        /// as in the lecture: take `a` in the blade, then `b' = a^-1 (a ^ b)` and so on by
        /// induction. `None` when this is not a blade (to rounding) or a factor is null.
        #[must_use]
        pub fn factor(self) -> Option<[Vector; #k_lit]> {
            if !self.to_array().iter().all(|c| c.is_finite()) {
                return None;
            }
            // Factor the blade divided by its largest component (no square overflows or
            // underflows), then give that scale back to the first factor.
            let largest = self.to_array().iter().fold(0.0 as #s, |m, c| m.max(c.abs()));
            if !(largest > #zero) {
                return None;
            }
            let blade = Multivector::from(#descaled_self);
            let size = math::sqrt(blade.to_array().iter().map(|c| c * c).sum::<#s>());
            let mut rest = blade;
            let mut factors = [Vector::ZERO; #k_lit];
            for slot in factors.iter_mut().take(#k_lit - 1) {
                let inverse = mv_blade_inverse(rest)?;
                let mut best = Vector::ZERO;
                let mut best_size: #s = 0.0;
                for basis in [#(Vector { #fields: 1.0, ..Vector::ZERO }),*] {
                    let projected = mv_geometric(mv_left_contraction(Multivector::from(basis), rest), inverse);
                    let candidate = Vector { #(#fields: projected.#fields),* };
                    // The metric square, not the Euclidean size: in a Minkowski metric the
                    // largest projection can be nearly null, and its inverse ill-conditioned.
                    let candidate_size = (#candidate_square).abs();
                    if candidate_size > best_size {
                        best = candidate;
                        best_size = candidate_size;
                    }
                }
                let best_inverse = mv_blade_inverse(Multivector::from(best))?;
                rest = mv_geometric(best_inverse, rest);
                *slot = best;
            }
            factors[#k_lit - 1] = Vector { #(#fields: rest.#fields),* };
            let mut product = Multivector::from(factors[0]);
            for factor in &factors[1..] {
                product = mv_geometric(product, Multivector::from(*factor));
            }
            let error = product
                .to_array()
                .iter()
                .zip(blade.to_array())
                .map(|(p, b)| (p - b) * (p - b))
                .sum::<#s>();
            let error = math::sqrt(error);
            // Rounding grows with the factors' own sizes, which exceed the blade's when the
            // metric makes their products cancel (Minkowski directions).
            let scale = factors
                .iter()
                .map(|f| math::sqrt(f.to_array().iter().map(|c| c * c).sum::<#s>()))
                .product::<#s>()
                .max(size);
            if error <= 1024.0 * #s::EPSILON * scale {
                factors[0] = factors[0] * largest;
                Some(factors)
            } else {
                None
            }
        }
    });
    quote! {
        impl #name {
            #methods
        }
    }
}

/// Private full-algebra products used by runtime algorithms (never by a product impl);
/// `allow(dead_code)` because an `ops:` list may leave out the algorithms that call them.
pub fn emit_multivector_helpers(plan: &Plan) -> TokenStream {
    let n = plan.metric.dimension();
    let mv = TypeId::multivector(n);
    let a = Operand::new(quote!(a), mv);
    let b = Operand::new(quote!(b), mv);
    let (geometric, _) = product_value(plan, ProductKind::Geometric, &a, &b);
    let (contraction, _) = product_value(plan, ProductKind::LeftContraction, &a, &b);
    let reverse = super::expr::construct(plan, Output::Type(mv), |blade| {
        let x = a.blade(plan, blade)?;
        Some(if Involution::Reverse.sign(blade) > 0 {
            x
        } else {
            quote!(-#x)
        })
    });
    let norm_squared = super::unary::norm_squared_expr(plan, &a);
    let s = scalar_type(plan);
    quote! {
        /// The inverse of a blade (or any `A` with `A ~A` a scalar): `~A / <A ~A>`, exact
        /// where a general linear solve would lose digits; `None` for a null blade.
        #[allow(dead_code)]
        fn mv_blade_inverse(a: Multivector) -> Option<Multivector> {
            let norm_squared: #s = #norm_squared;
            if norm_squared == 0.0 || !norm_squared.is_finite() {
                return None;
            }
            let reverse = #reverse;
            let scale = 1.0 / norm_squared;
            Some(Multivector::from_array(reverse.to_array().map(|c| c * scale)))
        }

        #[allow(dead_code)]
        fn mv_geometric(a: Multivector, b: Multivector) -> Multivector {
            #geometric
        }

        #[allow(dead_code)]
        fn mv_left_contraction(a: Multivector, b: Multivector) -> Multivector {
            #contraction
        }
    }
}
