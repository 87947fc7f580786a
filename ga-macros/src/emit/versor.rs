//! `sandwich`, `reflect`, the blade test and blade factorisation.

use std::collections::{BTreeMap, BTreeSet};

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::expr::{
    construct, construct_in, field_ident, float, mirrored_sum, scalar_type, signed_sum,
    signed_sum_linear, type_tokens, Operand, Syntax,
};
use super::products::product_value;
use crate::algebra::{blade_name, Involution, ProductKind};
use crate::plan::collected::{CollectedSums, Summand};
use crate::plan::sandwich_form::CommutatorTerms;
use crate::plan::{bilinear, sandwich, Output, PairColumns, Plan, SandwichForm, TypeId, TypeKind};

/// The `Sandwich` trait and its impls for every versor type on every emitted type, and
/// `SandwichUnit` where the unit versor has a cheaper form.
pub fn emit_sandwiches(plan: &Plan) -> TokenStream {
    let mut out = quote! {
        /// The versor product: `v x ~v` for even `v`, `v x^ ~v` for odd `v` (x^ the grade
        /// involution), in the form the generator's cost model picks (a quadratic form with
        /// like terms collected, or commutators). Returns `x`'s own type; exact for any
        /// versor, so the result is scaled by |v|^2 when `v` is not unit. Either side may
        /// be a reference (`r.sandwich(&v)`, as glam's `q * &v`).
        pub trait Sandwich<X> {
            /// `x`'s own type (the referenced type when `x` is a reference).
            type Output;
            /// `v x ~v` (even `v`) or `v x^ ~v` (odd `v`).
            #[must_use]
            fn sandwich(self, x: X) -> Self::Output;
        }
    };
    let mut unit = TokenStream::new();
    for v in plan.versors() {
        for &x in &plan.emitted {
            out.extend(sandwich_impl(plan, v, x));
            unit.extend(sandwich_unit_impl(plan, v, x));
        }
        if plan.emitted.contains(&TypeId::grade(1)) {
            out.extend(emit_sandwich_matrix(plan, v));
        }
    }
    if !unit.is_empty() {
        out.extend(quote! {
            /// The rotation by a **unit** even versor (a rotor, `v ~v = 1`), in the cheaper
            /// form that precondition allows: `((x + 2s C(x)) + C(C(x))) + C(C(x))` with
            /// `C(x) = (Bx - xB) / 2` for `v = s + B`, as glam's `Quat * Vec3` assumes a unit
            /// quaternion. For a rotor of norm `1 + e` the result is off by about `2e |x|`;
            /// [`Sandwich::sandwich`] is exact for any versor.
            ///
            /// For a unit rotor of G2 or G3, every intermediate of each grade part of `x` is
            /// at most `sqrt 2` times that part's Euclidean norm (up to rounding), so the
            /// result is finite whenever each part's norm is at most `MAX / sqrt 2` (about
            /// 1.27e308 in `f64`, 2.4e38 in `f32`); `C(C(x))` is added twice rather than
            /// doubled because `2 C(C(x))` reaches `2 |x|` for a half turn.
            pub trait SandwichUnit<X> {
                /// `v x ~v` for a unit `v`.
                #[must_use]
                fn sandwich_unit(self, x: X) -> X;
            }
            #unit
        });
    }
    out
}

pub fn is_odd(plan: &Plan, v: TypeId) -> bool {
    matches!(plan.types.get(v).kind, TypeKind::Grade(1) | TypeKind::Odd)
}

fn sandwich_impl(plan: &Plan, v: TypeId, x: TypeId) -> TokenStream {
    let (v_ty, x_ty) = (type_tokens(plan, v), type_tokens(plan, x));
    let odd = is_odd(plan, v);
    let body = match plan.sandwich_form(v, x, false) {
        Some(SandwichForm::Collected(sums)) => fused_body(plan, v, x, &sums),
        Some(SandwichForm::Commutator { terms, lanes }) => {
            commutator_body(plan, v, x, &terms, lanes.as_ref(), false)
        }
        Some(SandwichForm::Chained) | None => chained_body(plan, v, x, odd),
    };
    quote! {
        impl Sandwich<#x_ty> for #v_ty {
            type Output = #x_ty;
            #[inline]
            fn sandwich(self, x: #x_ty) -> #x_ty {
                #body
            }
        }

        impl Sandwich<&#x_ty> for #v_ty {
            type Output = #x_ty;
            #[inline]
            fn sandwich(self, x: &#x_ty) -> #x_ty {
                Sandwich::sandwich(self, *x)
            }
        }

        impl Sandwich<#x_ty> for &#v_ty {
            type Output = #x_ty;
            #[inline]
            fn sandwich(self, x: #x_ty) -> #x_ty {
                Sandwich::sandwich(*self, x)
            }
        }

        impl Sandwich<&#x_ty> for &#v_ty {
            type Output = #x_ty;
            #[inline]
            fn sandwich(self, x: &#x_ty) -> #x_ty {
                Sandwich::sandwich(*self, *x)
            }
        }
    }
}

fn sandwich_unit_impl(plan: &Plan, v: TypeId, x: TypeId) -> TokenStream {
    let Some(SandwichForm::Commutator { terms, lanes }) = plan.sandwich_form(v, x, true) else {
        return TokenStream::new();
    };
    let (v_ty, x_ty) = (type_tokens(plan, v), type_tokens(plan, x));
    let body = commutator_body(plan, v, x, &terms, lanes.as_ref(), true);
    quote! {
        impl SandwichUnit<#x_ty> for #v_ty {
            #[inline]
            fn sandwich_unit(self, x: #x_ty) -> #x_ty {
                #body
            }
        }
    }
}

/// `<v ~v> x + 2 (s c + C(c))` with `c = C(x)` (or `x + ...` for a unit versor): scalar
/// code, with a four-lane body beside it where the cost model chose one.
fn commutator_body(
    plan: &Plan,
    v: TypeId,
    x: TypeId,
    terms: &CommutatorTerms,
    lanes: Option<&PairColumns>,
    unit: bool,
) -> TokenStream {
    let scalar = commutator_scalar_body(plan, v, x, terms, lanes, unit);
    match lanes.filter(|_| plan.emits_simd()) {
        None => scalar,
        Some(lanes) => {
            let simd = super::simd::commutator_sandwich_lanes(plan, v, x, lanes, unit);
            super::simd::target_arms(simd, scalar)
        }
    }
}

/// The scalar form; where a lane form exists, each sum mirrors its columns and trees, so
/// that scalar, SIMD and batch bodies round alike.
fn commutator_scalar_body(
    plan: &Plan,
    v: TypeId,
    x: TypeId,
    terms: &CommutatorTerms,
    lanes: Option<&PairColumns>,
    unit: bool,
) -> TokenStream {
    let this = Operand::new(quote!(self), v);
    let arg = Operand::new(quote!(x), x);
    let versor = &plan.types.get(v).blades;
    let operand = &plan.types.get(x).blades;
    let local = |prefix: &str, blade: u32| format_ident!("{prefix}_{}", blade_name(blade));
    let from_x = |k: usize| arg.component(plan, k);
    let from_c = |k: usize| {
        let blade = operand[k];
        if terms.contains_key(&blade) {
            let c = local("c", blade);
            quote!(#c)
        } else {
            quote!(0.0)
        }
    };
    // The exact form's second commutator takes the doubled versor: the factor 2 of
    // `2 C(c)` is folded into components that do not depend on `x`, one addition fewer on
    // the path through it.
    let doubled = |i: usize| {
        let name = local("two", versor[i]);
        quote!(#name)
    };
    let plain = |i: usize| this.component(plan, i);
    let apply = |factor: &dyn Fn(usize) -> TokenStream,
                 input: &dyn Fn(usize) -> TokenStream,
                 blade: u32| {
        match lanes {
            Some(lanes) => {
                let lane = operand
                    .iter()
                    .position(|&b| b == blade)
                    .expect("C(x) stays in x's type");
                let leaves: Vec<_> = lanes
                    .columns
                    .iter()
                    .map(|column| {
                        column.used[lane].then(|| {
                            let (a, b) =
                                (factor(column.a_order[lane]), input(column.b_order[lane]));
                            (!column.negate[lane], quote!(#a * #b))
                        })
                    })
                    .collect();
                mirrored_sum(&leaves).unwrap_or_else(|| quote!(0.0))
            }
            None => {
                let summands: Vec<(i32, TokenStream)> = terms[&blade]
                    .iter()
                    .map(|t| {
                        let (a, b) = (factor(t.lhs), input(t.rhs));
                        (t.sign as i32, quote!(#a * #b))
                    })
                    .collect();
                signed_sum(&summands)
            }
        }
    };
    let c_lets = terms.keys().map(|&blade| {
        let name = local("c", blade);
        let value = apply(&plain, &from_x, blade);
        quote!(let #name = #value;)
    });
    let used: BTreeSet<usize> = terms.values().flatten().map(|t| t.lhs).collect();
    // A unit versor's second commutator keeps the plain versor (see below): only `2s` is
    // doubled there.
    let doubling: Vec<usize> = if used.is_empty() {
        Vec::new()
    } else if unit {
        vec![0]
    } else {
        std::iter::once(0).chain(used).collect()
    };
    let two_lets = doubling.into_iter().map(|i| {
        let (name, a) = (doubled(i), this.component(plan, i));
        quote!(let #name = #a + #a;)
    });
    // `2 C(c)` reaches `2 |x|` for a half turn, past `MAX` for `|x|` near `MAX` though the
    // result is `|x|`: a unit versor adds `C(c)` twice, `((x + 2s c) + C(c)) + C(c)`, whose
    // partial sums stay within `sqrt 2 |x|` (one addition more on the path through `x`).
    let cc_lets = if unit {
        let lets = terms.keys().map(|&blade| {
            let name = local("cc", blade);
            let value = apply(&plain, &from_c, blade);
            quote!(let #name = #value;)
        });
        quote!(#(#lets)*)
    } else {
        quote!()
    };
    let norm = if unit {
        quote!()
    } else if lanes.is_some() {
        // The lanes sum the signed squares pairwise: (0 + 1) + (2 + 3).
        let leaves: Vec<_> = versor
            .iter()
            .enumerate()
            .map(|(i, &b)| {
                let sign = plan.metric.geometric(b, b).0 * Involution::Reverse.sign(b);
                let a = this.component(plan, i);
                (sign != 0).then(|| (sign > 0, quote!(#a * #a)))
            })
            .collect();
        let value = mirrored_sum(&leaves).unwrap_or_else(|| quote!(0.0));
        quote!(let n = #value;)
    } else {
        let value = super::expr::quadratic_component(plan, &this, Involution::Reverse, 0);
        quote!(let n = #value;)
    };
    let two_s = doubled(0);
    let value = construct(plan, Output::Type(x), |blade| {
        let index = operand.iter().position(|&b| b == blade)?;
        let xk = arg.component(plan, index);
        let scaled = if unit { quote!(#xk) } else { quote!(n * #xk) };
        Some(if terms.contains_key(&blade) {
            let c = local("c", blade);
            if unit {
                let cc = local("cc", blade);
                quote!(((#scaled + #two_s * #c) + #cc) + #cc)
            } else {
                let second = apply(&doubled, &from_c, blade);
                quote!((#scaled + #two_s * #c) + (#second))
            }
        } else {
            scaled
        })
    });
    quote! {
        #(#c_lets)*
        #(#two_lets)*
        #cc_lets
        #norm
        #value
    }
}

/// The pieces of the expanded sandwich: `let`s for the products of pairs of the versor's
/// components, and for each output blade and component `k` of `x` the coefficient of
/// `x_k`: a signed sum of those products. Its sums are running sums, not the balanced
/// trees of the products: on a chain of G3 rotations the trees made the sandwich's latency
/// worse (BENCHMARKS.md, "Choices in the generated code"), the sums being short and off the
/// path through `x`.
/// A pair whose coefficients are all even is computed as `(v_i + v_i) * v_j`: the factor 2
/// costs an add once per component instead of a multiply per use. Partial sums that
/// several coefficients share are computed once ([`CollectedSums`]). See
/// docs/derivations/sandwich.md.
struct FusedParts {
    lets: TokenStream,
    coefficients: BTreeMap<(u32, usize), Vec<(i32, TokenStream)>>,
}

/// The `let`s of a collected sandwich (doubled components, pair products, shared partial
/// sums) and each coefficient as signed names of them.
fn fused_parts(plan: &Plan, v: TypeId, sums: &CollectedSums) -> FusedParts {
    let versor = &plan.types.get(v).blades;
    let this = Operand::new(quote!(self), v);
    let pair_name = |(i, j): (usize, usize)| {
        format_ident!("{}_{}", blade_name(versor[i]), blade_name(versor[j]))
    };
    let two_name = |i: usize| format_ident!("two_{}", blade_name(versor[i]));
    let doubled_components: BTreeSet<usize> = sums.doubled.iter().map(|&(i, _)| i).collect();
    let two_lets = doubled_components.iter().map(|&i| {
        let name = two_name(i);
        let a = this.component(plan, i);
        quote!(let #name = #a + #a;)
    });
    let pair_lets = sums.pairs.iter().map(|&(i, j)| {
        let name = pair_name((i, j));
        let b = this.component(plan, j);
        if sums.doubled.contains(&(i, j)) {
            let two = two_name(i);
            quote!(let #name = #two * #b;)
        } else {
            let a = this.component(plan, i);
            quote!(let #name = #a * #b;)
        }
    });
    // A shared sum is named after its summands (`s_s_minus_e12_e12`) while that stays
    // short enough to read, and numbered otherwise.
    let mut shared_names: Vec<proc_macro2::Ident> = Vec::new();
    let mut shared_lets = TokenStream::new();
    let mut numbered = 0;
    let name_of = |s: Summand, names: &[proc_macro2::Ident]| match s {
        Summand::Pair(i, j) => pair_name((i, j)),
        Summand::Shared(k) => names[k].clone(),
    };
    for shared in &sums.shared {
        let (first, second) = (
            name_of(shared.first, &shared_names),
            name_of(shared.second, &shared_names),
        );
        let (op, word) = if shared.sign > 0 {
            (quote!(+), "plus")
        } else {
            (quote!(-), "minus")
        };
        let long = format!("{first}_{word}_{second}");
        let name = if long.len() <= 32 {
            format_ident!("{long}")
        } else {
            numbered += 1;
            format_ident!("shared_{numbered}")
        };
        shared_lets.extend(quote!(let #name = #first #op #second;));
        shared_names.push(name);
    }
    let coefficients = sums
        .coefficients
        .iter()
        .map(|(&key, terms)| {
            let terms = terms
                .iter()
                .map(|&(c, s)| {
                    let name = name_of(s, &shared_names);
                    (c, quote!(#name))
                })
                .collect();
            (key, terms)
        })
        .collect();
    FusedParts {
        lets: quote!(#(#two_lets)* #(#pair_lets)* #shared_lets),
        coefficients,
    }
}

/// `x -> v x ~v` as one sum per output component over the components of `x`, in their
/// order: the sums of neighbouring outputs then line up term by term, which is how LLVM's
/// SLP vectoriser pairs them into one register in a chain of rotations. A coefficient whose
/// summands are all negative is subtracted as a positive sum, `- (p + q) x`, which saves
/// its negation, except as an output's first term, which is `-(p + q) * x` (the negated
/// sum times `x`) so that the order holds: for the G3 `f64` rotor on a vector, that first
/// term written `(-p - q) * x` made LLVM pair the outputs so that a chain of rotations took
/// much longer (BENCHMARKS.md, "Choices in the generated code").
fn fused_body(plan: &Plan, v: TypeId, x: TypeId, sums: &CollectedSums) -> TokenStream {
    let (lets, value) = fused_body_in(Syntax::Rust, plan, v, x, sums);
    quote! {
        #lets
        #value
    }
}

/// The collected sandwich as its `let`s (reading the versor as `self`) and its value.
pub fn fused_body_in(
    syntax: Syntax,
    plan: &Plan,
    v: TypeId,
    x: TypeId,
    sums: &CollectedSums,
) -> (TokenStream, TokenStream) {
    let parts = fused_parts(plan, v, sums);
    let arg = Operand::new(quote!(x), x);
    let value = construct_in(syntax, plan, Output::Type(x), |blade| {
        let mut sum = TokenStream::new();
        for (&(_, k), coefficient) in parts.coefficients.range((blade, 0)..=(blade, usize::MAX)) {
            let xk = arg.component(plan, k);
            let first = sum.is_empty();
            let (positive, term) = match coefficient.as_slice() {
                [(1, single)] => (true, quote!(#single * #xk)),
                [(-1, single)] if !first => (false, quote!(#single * #xk)),
                _ if coefficient.iter().all(|&(c, _)| c < 0) => {
                    let flipped: Vec<(i32, TokenStream)> =
                        coefficient.iter().map(|(c, t)| (-c, t.clone())).collect();
                    let inner = signed_sum_linear(&flipped);
                    if first {
                        (true, quote!(-(#inner) * #xk))
                    } else {
                        (false, quote!((#inner) * #xk))
                    }
                }
                _ => {
                    let inner = signed_sum_linear(coefficient);
                    (true, quote!((#inner) * #xk))
                }
            };
            sum.extend(match (first, positive) {
                (true, _) => term,
                (false, true) => quote!(+ #term),
                (false, false) => quote!(- #term),
            });
        }
        (!sum.is_empty()).then_some(sum)
    });
    (parts.lets, value)
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
    let parts = fused_parts(plan, v, &CollectedSums::new(&q, &blades));
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
            /// The matrix of the vector map of [`Sandwich::sandwich`] (`x -> v x ~v`, or
            /// `v x^ ~v` for an odd versor; row = output component, column = input
            /// component, canonical order): the rotation matrix of a unit rotor, a
            /// reflection's for a unit vector.
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
    let (lets, value) = chained_body_in(Syntax::Rust, plan, v, x, odd);
    quote! {
        #lets
        #value
    }
}

/// The sandwich as two chained products: the `let`s of `v x` (reading the versor as
/// `self`) and the value of `(v x) ~v` on `x`'s blades.
pub fn chained_body_in(
    syntax: Syntax,
    plan: &Plan,
    v: TypeId,
    x: TypeId,
    odd: bool,
) -> (TokenStream, TokenStream) {
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
    let value = construct_in(syntax, plan, Output::Type(x), |blade| {
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
    (quote!(#(#locals)*), value)
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
    // Where every generator squares to 0 the metric square is the literal `0.0`, whose
    // float type nothing would fix: no candidate is invertible, and `factor` of a grade
    // above one returns `None`.
    let vectors = &plan.types.get(TypeId::grade(1)).blades;
    let candidate_size = if vectors.iter().all(|&b| plan.metric.geometric(b, b).0 == 0) {
        quote!(let candidate_size: #s = #zero;)
    } else {
        quote!(let candidate_size = (#candidate_square).abs();)
    };
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
                    #candidate_size
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
