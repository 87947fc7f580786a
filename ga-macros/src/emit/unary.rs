//! Methods of one operand: involutions, duals, norms, inverse, grade projections.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::expr::{
    construct, field_ident, output_type, scalar_type, signed_sum, type_tokens, Operand,
};
use crate::algebra::Involution;
use crate::plan::{Output, Plan, TypeId, TypeKind};
use crate::spec::Op;

/// The unary methods of one type, as one inherent impl.
pub fn emit_unary(plan: &Plan, t: TypeId) -> TokenStream {
    let name = type_tokens(plan, t);
    let mut methods = TokenStream::new();
    let involutions = [
        (
            Op::Reverse,
            Involution::Reverse,
            "reverse",
            "The reverse ~A: flips grades 2 and 3 mod 4.",
        ),
        (
            Op::GradeInvolution,
            Involution::GradeInvolution,
            "grade_involution",
            "The grade involution: flips odd grades.",
        ),
        (
            Op::Conjugate,
            Involution::Conjugate,
            "conjugate",
            "The Clifford conjugate: flips grades 1 and 2 mod 4.",
        ),
    ];
    let this = Operand::new(quote!(self), t);
    for (op, involution, method, doc) in involutions {
        if !plan.has(op) {
            continue;
        }
        let method = format_ident!("{method}");
        let value = construct(plan, Output::Type(t), |blade| {
            let x = this.blade(plan, blade)?;
            Some(if involution.sign(blade) > 0 {
                x
            } else {
                quote!(-#x)
            })
        });
        methods.extend(quote! {
            #[doc = #doc]
            #[inline]
            #[must_use]
            pub fn #method(self) -> Self {
                #value
            }
        });
    }
    if plan.has(Op::Dual) {
        methods.extend(complement(plan, t, true));
        methods.extend(complement(plan, t, false));
    }
    if plan.has(Op::Norm) {
        methods.extend(norms(plan, t));
    }
    if plan.has(Op::Inverse) {
        methods.extend(inverse(plan, t));
    }
    if plan.has(Op::Grade) {
        methods.extend(projections(plan, t));
    }
    quote! {
        impl #name {
            #methods
        }
    }
}

fn complement(plan: &Plan, t: TypeId, dual: bool) -> TokenStream {
    let blades = &plan.types.get(t).blades;
    let map = |b| {
        if dual {
            plan.metric.dual(b)
        } else {
            plan.metric.undual(b)
        }
    };
    let output = plan
        .types
        .smallest_holding(blades.iter().map(|&b| map(b).1));
    let this = Operand::new(quote!(self), t);
    let value = construct(plan, output, |target| {
        blades.iter().enumerate().find_map(|(i, &b)| {
            let (sign, image) = map(b);
            (image == target).then(|| {
                let x = this.component(plan, i);
                if sign > 0 {
                    x
                } else {
                    quote!(-#x)
                }
            })
        })
    });
    let out_ty = output_type(plan, output);
    let (method, doc) = if dual {
        (quote!(dual), "The dual as the right complement: `e_A ^ e_A.dual() = e1..en` for every blade, independent of the metric (so it works for degenerate metrics).")
    } else {
        (quote!(undual), "The inverse of `dual`.")
    };
    quote! {
        #[doc = #doc]
        #[inline]
        #[must_use]
        pub fn #method(self) -> #out_ty {
            #value
        }
    }
}

/// `<A ~A>_0` as a signed sum of squares (cross terms never reach grade 0).
pub fn norm_squared_expr(plan: &Plan, operand: &Operand) -> TokenStream {
    let blades = &plan.types.get(operand.ty).blades;
    let terms: Vec<(i32, TokenStream)> = blades
        .iter()
        .enumerate()
        .filter_map(|(i, &b)| {
            let sign = plan.metric.geometric(b, b).0 * Involution::Reverse.sign(b);
            let x = operand.component(plan, i);
            (sign != 0).then(|| (sign as i32, quote!(#x * #x)))
        })
        .collect();
    signed_sum(&terms)
}

/// The indices of the components that `<A ~A>_0` sees (blades of non-zero square).
pub fn nondegenerate(plan: &Plan, t: TypeId) -> Vec<usize> {
    let blades = &plan.types.get(t).blades;
    (0..blades.len())
        .filter(|&i| plan.metric.geometric(blades[i], blades[i]).0 != 0)
        .collect()
}

/// `max |x_i|` over the given components of `operand`.
pub fn largest_abs(plan: &Plan, operand: &Operand, indices: &[usize]) -> TokenStream {
    let mut parts = indices.iter().map(|&i| {
        let x = operand.component(plan, i);
        quote!(#x.abs())
    });
    let first = parts.next().unwrap_or_else(|| quote!(0.0));
    parts.fold(first, |acc, x| quote!(#acc.max(#x)))
}

/// `operand` with every component divided by `by`, as a value of `operand`'s type.
pub fn descaled(plan: &Plan, operand: &Operand, by: &TokenStream) -> TokenStream {
    construct(plan, Output::Type(operand.ty), |blade| {
        operand.blade(plan, blade).map(|x| quote!(#x / #by))
    })
}

fn norms(plan: &Plan, t: TypeId) -> TokenStream {
    let s = scalar_type(plan);
    let this = Operand::new(quote!(self), t);
    let sum = norm_squared_expr(plan, &this);
    let indices = nondegenerate(plan, t);
    let largest = largest_abs(plan, &this, &indices);
    let descaled = descaled(plan, &this, &quote!(largest));
    super::template::fill(
        NORMS,
        &[
            ("s", &s),
            ("sum", &sum),
            ("largest", &largest),
            ("descaled", &descaled),
        ],
    )
}

/// `norm_squared`, `norm` and `normalized` of one type (`#s` the scalar type).
const NORMS: &str = r#"
/// `<A ~A>_0`: the squared norm (negative or zero for some elements of
/// non-Euclidean metrics). Computed as it stands, so it overflows once a component
/// passes the square root of the largest float; `norm` does not.
#[inline]
#[must_use]
pub fn norm_squared(self) -> #s {
    #sum
}

/// `sqrt(|<A ~A>_0|)`, right to a few ulps for every finite `A` whose norm is
/// finite: when the squares could have overflowed or underflowed, the components
/// are first divided by the largest of them (as `hypot` and LAPACK's `nrm2` do).
#[inline]
#[must_use]
pub fn norm(self) -> #s {
    let squared = self.norm_squared().abs();
    // The common case costs one comparison: the unscaled sum is exact enough.
    if squared >= SQUARE_MIN && squared <= SQUARE_MAX {
        return math::sqrt(squared);
    }
    let largest: #s = #largest;
    if !(largest > 0.0 && largest < #s::INFINITY) {
        // Zero, NaN or infinite components: the unscaled value is the answer.
        return if largest == #s::INFINITY { largest } else { math::sqrt(squared) };
    }
    let descaled = #descaled;
    math::sqrt(descaled.norm_squared().abs()) * largest
}

/// `self / self.norm()`, scaled like `norm` so that it is a unit value for every
/// finite non-null `A`; non-finite when the norm is zero or not finite (see
/// `try_normalized`).
#[inline]
#[must_use]
pub fn normalized(self) -> Self {
    let squared = self.norm_squared().abs();
    // Here 1 / sqrt(squared) is a normal number: one multiply per component.
    if squared >= SQUARE_MIN && squared <= SQUARE_MAX {
        return self * (1.0 / math::sqrt(squared));
    }
    let largest: #s = #largest;
    let descaled = #descaled;
    descaled * (1.0 / math::sqrt(descaled.norm_squared().abs()))
}

/// `self / self.norm()`, or `None` when the norm is zero (or the value null) or
/// not finite.
#[inline]
#[must_use]
pub fn try_normalized(self) -> Option<Self> {
    let normalized = self.normalized();
    if normalized.to_array().iter().all(|c| c.is_finite()) {
        Some(normalized)
    } else {
        None
    }
}
"#;

fn inverse(plan: &Plan, t: TypeId) -> TokenStream {
    let output = plan.inverse_output(t);
    let out_ty = output_type(plan, output);
    if plan.has_scalar_self_product(t) {
        let s = scalar_type(plan);
        let this = Operand::new(quote!(self), t);
        let denominator = super::expr::quadratic_component(plan, &this, Involution::Reverse, 0);
        let scaled = Operand::new(quote!(descaled), t);
        let scaled_denominator =
            super::expr::quadratic_component(plan, &scaled, Involution::Reverse, 0);
        let largest = largest_abs(plan, &this, &nondegenerate(plan, t));
        let descaled = descaled(plan, &this, &quote!(largest));
        return quote! {
            /// The inverse `~A / (A ~A)` (here `A ~A` is a scalar for every `A`), or `None`
            /// when `A ~A` is zero or the result is not finite. Right to a few ulps
            /// relative whenever the inverse is a normal number: when `A ~A` could have
            /// overflowed or underflowed, `A` is first divided by its largest component.
            #[inline]
            #[must_use]
            pub fn inverse(self) -> Option<#out_ty> {
                let denominator: #s = #denominator;
                let inverse = if denominator.abs() >= SQUARE_MIN && denominator.abs() <= SQUARE_MAX {
                    self.reverse() * (1.0 / denominator)
                } else {
                    // A^-1 = ~u / (u ~u) / m with u = A / m, m the largest component.
                    let largest: #s = #largest;
                    let descaled = #descaled;
                    let denominator: #s = #scaled_denominator;
                    descaled.reverse() * ((1.0 / denominator) / largest)
                };
                if inverse.to_array().iter().all(|c| c.is_finite()) {
                    Some(inverse.into())
                } else {
                    None
                }
            }
        };
    }
    let project = construct(plan, output, |blade| {
        let f = field_ident(blade);
        Some(quote!(inverse.#f))
    });
    let bound_doc = inverse_bound_doc(plan);
    quote! {
        /// The inverse, by solving `A X = 1` (`A ~A` is not a scalar for this type).
        #[doc = ""]
        #[doc = #bound_doc]
        #[must_use]
        pub fn inverse(self) -> Option<#out_ty> {
            let inverse = multivector_inverse(Multivector::from(self))?;
            Some(#project)
        }
    }
}

fn projections(plan: &Plan, t: TypeId) -> TokenStream {
    let n = plan.metric.dimension();
    let def = plan.types.get(t);
    let this = Operand::new(quote!(self), t);
    let mut out = TokenStream::new();
    for k in plan.types.grades_of(t) {
        let target = if k == 0 {
            TypeId::SCALAR
        } else {
            TypeId::grade(k)
        };
        let method = format_ident!("grade{k}");
        let ty = type_tokens(plan, target);
        let value = construct(plan, Output::Type(target), |blade| this.blade(plan, blade));
        let doc = format!("The grade-{k} part <A>_{k}.");
        out.extend(quote! {
            #[doc = #doc]
            #[inline]
            #[must_use]
            pub fn #method(self) -> #ty {
                #value
            }
        });
    }
    if def.kind == TypeKind::Multivector {
        for (method, target, doc) in [
            (quote!(even_part), TypeId::even(n), "The even grades."),
            (quote!(odd_part), TypeId::odd(n), "The odd grades."),
        ] {
            let ty = type_tokens(plan, target);
            let value = construct(plan, Output::Type(target), |blade| this.blade(plan, blade));
            out.extend(quote! {
                #[doc = #doc]
                #[inline]
                #[must_use]
                pub fn #method(self) -> #ty {
                    #value
                }
            });
        }
    }
    out
}

/// What a general inverse's `Some` promises, in the precision's words.
fn inverse_bound_doc(plan: &Plan) -> &'static str {
    match plan.scalar {
        crate::spec::Scalar::F64 => {
            "`Some(x)` is within 2^-26 (about 1.5e-8) of the exact inverse `X` relative to \
             it, summing absolute values: `sum |x_i - X_i| <= 2^-26 sum |X_i|`, certified \
             by the residual `A x - 1` of the value returned; `None` when `A` is singular, \
             or too ill-conditioned for that (a condition number beyond about 1e6)."
        }
        crate::spec::Scalar::F32 => {
            "`Some(x)` is within 2^-23 (`f32::EPSILON`) of the exact inverse `X` relative \
             to it, summing absolute values: `sum |x_i - X_i| <= 2^-23 sum |X_i|`, plus \
             `2^-150` per component below `f32::MIN_POSITIVE`; the solve runs in `f64`, is \
             certified to 2^-26 by its residual and then rounded. `None` when `A` is \
             singular, too ill-conditioned (a condition number beyond about 1e6), or its \
             inverse overflows `f32`."
        }
    }
}

/// The general inverse by Gaussian elimination on the left-multiplication matrix of the
/// full algebra, refined once and certified by its residual; emitted only when some type
/// needs it. The solve runs in `f64` for both precisions (for `f32` a wider work type, so
/// that the certificate is not spent on the final rounding). See
/// docs/derivations/inverse.md for the bound.
pub fn emit_multivector_inverse(plan: &Plan) -> TokenStream {
    // f64 needs no conversion: writing none keeps the f64 code free of `f64::from` and
    // `as f64`, which a generic scalar's rewrite of it (emit/generic.rs) would lift.
    let to_f64_and_back = if plan.scalar == crate::spec::Scalar::F64 {
        quote! { let x = inverse_f64(a.to_array())?; }
    } else {
        let s = scalar_type(plan);
        quote! {
            let x = inverse_f64(a.to_array().map(f64::from))?;
            let x = x.map(|v| v as #s);
        }
    };
    let n = plan.metric.dimension();
    let mv = TypeId::multivector(n);
    let blades = &plan.types.get(mv).blades;
    let len = blades.len();
    // LEFT[i][j] = (k, sign): e_i e_j = sign e_k, as component indices.
    let rows = blades.iter().map(|&a| {
        let entries = blades.iter().map(|&b| {
            let (sign, blade) = plan.metric.geometric(a, b);
            let k = blades.iter().position(|&x| x == blade).unwrap_or(0);
            quote!((#k, #sign))
        });
        quote!([#(#entries),*])
    });
    let rows = quote!([#(#rows),*]);
    let bound_doc = inverse_bound_doc(plan);
    super::template::fill(
        INVERSE_SOLVER,
        &[
            ("len", &len),
            ("rows", &rows),
            ("bound_doc", &bound_doc),
            ("to_f64_and_back", &to_f64_and_back),
        ],
    )
}

/// The general inverse in `f64`: the product table `LEFT`, the tolerance, and the solve
/// with its one refinement.
const INVERSE_SOLVER: &str = r#"
/// `LEFT[i][j] = (k, sign)`: `e_i e_j = sign e_k` by component index. Used only by
/// the general inverse, never by a product.
#[allow(dead_code)]
const LEFT: [[(usize, i8); #len]; #len] = #rows;

/// The relative error (summing absolute values) that a general inverse's `f64`
/// solution is certified to before it is returned: 2^-26, half the digits.
#[allow(dead_code)]
const INVERSE_TOLERANCE: f64 = 1.0 / 67_108_864.0;

/// `a b` in `f64` through `LEFT`: the residual's product, each component a sum of
/// `len` signed products of one component of each.
#[allow(dead_code)]
fn left_product(a: &[f64; #len], b: &[f64; #len]) -> [f64; #len] {
    let mut out = [0.0f64; #len];
    for (i, &ai) in a.iter().enumerate() {
        for (j, &(k, sign)) in LEFT[i].iter().enumerate() {
            if sign != 0 {
                out[k] += f64::from(sign) * (ai * b[j]);
            }
        }
    }
    out
}

/// Solves `A X = 1` by Gaussian elimination with partial pivoting on `A` divided by
/// its largest component, refines `X` once by the residual, and returns it only when
/// the residual certifies it. `None` when a pivot vanishes relative to the largest
/// entry (1), or when the certificate fails: the matrix is singular or too
/// ill-conditioned for the tolerance (a condition number, summing absolute
/// values, beyond about `2^-27 / ((len + 2) f64::EPSILON)`: 3e6 for 8 components).
///
/// The certificate: with `r = A X - 1`, `X - A^-1 = A^-1 r`, and the sum of absolute
/// values `|.|` is submultiplicative for a metric of squares 1, -1 and 0, so
/// `|X - A^-1| <= |A^-1| |r|`. The computed residual is off by at most
/// `(len + 1) u |A| |X|` plus the underflow of `len^2` products; `|r|`, with those
/// added twice over, must be at most half of `INVERSE_TOLERANCE`.
#[allow(dead_code)]
fn inverse_f64(a: [f64; #len]) -> Option<[f64; #len]> {
    let largest = a.iter().fold(0.0f64, |m, x| m.max(x.abs()));
    if !(largest > 0.0) || !largest.is_finite() {
        return None;
    }
    // Solve for A / largest, whose entries are at most 1, so that the elimination
    // neither overflows nor underflows; then X = (A / largest)^-1 / largest.
    let scaled = a.map(|v| v / largest);
    let mut m = [[0.0f64; #len]; #len];
    for (i, &ai) in scaled.iter().enumerate() {
        for (j, &(k, sign)) in LEFT[i].iter().enumerate() {
            m[k][j] += f64::from(sign) * ai;
        }
    }
    // LU in place: U above the diagonal, the multipliers of L below it, and the
    // row order in `order`.
    let mut order = [0usize; #len];
    for (i, slot) in order.iter_mut().enumerate() {
        *slot = i;
    }
    let tolerance = f64::EPSILON * (#len as f64);
    for col in 0..#len {
        let mut pivot = col;
        for row in col + 1..#len {
            if m[row][col].abs() > m[pivot][col].abs() {
                pivot = row;
            }
        }
        if !(m[pivot][col].abs() > tolerance) {
            return None;
        }
        m.swap(col, pivot);
        order.swap(col, pivot);
        for row in col + 1..#len {
            let factor = m[row][col] / m[col][col];
            m[row][col] = factor;
            if factor != 0.0 {
                for c in col + 1..#len {
                    m[row][c] -= factor * m[col][c];
                }
            }
        }
    }
    let solve = |rhs: &[f64; #len]| {
        let mut y = [0.0f64; #len];
        for row in 0..#len {
            let mut sum = rhs[order[row]];
            for c in 0..row {
                sum -= m[row][c] * y[c];
            }
            y[row] = sum;
        }
        for row in (0..#len).rev() {
            let mut sum = y[row];
            for c in row + 1..#len {
                sum -= m[row][c] * y[c];
            }
            y[row] = sum / m[row][row];
        }
        y
    };
    let mut one = [0.0f64; #len];
    one[0] = 1.0;
    let mut x = solve(&one);
    // One step of refinement: x += (A / largest)^-1 (1 - (A / largest) x).
    let mut residual = left_product(&scaled, &x);
    for (k, r) in residual.iter_mut().enumerate() {
        *r = one[k] - *r;
    }
    let correction = solve(&residual);
    for (v, d) in x.iter_mut().zip(correction) {
        *v += d;
    }
    let x = x.map(|v| v / largest);
    // The certificate, on the value returned and the input as given.
    let mut residual = left_product(&a, &x);
    residual[0] -= 1.0;
    let residual_sum = residual.iter().fold(0.0f64, |sum, r| sum + r.abs());
    let a_sum = a.iter().fold(0.0f64, |sum, v| sum + (v / largest).abs());
    let x_sum = x.iter().fold(0.0f64, |sum, v| sum + (v * largest).abs());
    let bound = residual_sum
        + (#len as f64 + 2.0) * f64::EPSILON * (a_sum * x_sum)
        + (#len as f64 * #len as f64) * (f64::MIN_POSITIVE * f64::EPSILON);
    if bound <= 0.5 * INVERSE_TOLERANCE && x.iter().all(|v| v.is_finite()) {
        Some(x)
    } else {
        None
    }
}

/// The inverse of any multivector, or `None`. See `inverse_f64` for the method.
#[doc = #bound_doc]
#[allow(dead_code)]
fn multivector_inverse(a: Multivector) -> Option<Multivector> {
    #to_f64_and_back
    if x.iter().all(|v| v.is_finite()) {
        Some(Multivector::from_array(x))
    } else {
        None
    }
}
"#;
