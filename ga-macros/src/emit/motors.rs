//! The motor toolkit of projective algebras (one null generator, the others squaring to
//! 1), with the meanings of the klein library (<https://www.jeremyong.com/klein/>) for 3D
//! PGA: Study normalisation, square root, division, the representative with a
//! non-negative scalar, the matrix of the action on points and Euler angles. Derivations
//! in docs/derivations/study-normalisation.md.
//!
//! Emitted only where the metric is projective and only on the types each operation
//! needs, so that no other algebra's expansion changes.

use proc_macro2::TokenStream;
use quote::{format_ident, quote};

use super::expr::{
    construct, field_ident, output_type, quadratic_component, scalar_type, signed_sum, type_tokens,
    Operand,
};
use super::unary::{descaled, largest_abs, nondegenerate};
use crate::algebra::{canonical_blades, grade, Blade, Involution, ProductKind};
use crate::plan::{sandwich, Output, Plan, TypeId};
use crate::spec::Op;

/// Every item of the toolkit for the emitted types of a projective algebra.
pub fn emit_motor_toolkit(plan: &Plan) -> TokenStream {
    let Some(origin) = plan.metric.projective_origin() else {
        return TokenStream::new();
    };
    if plan.lanes.is_some() {
        // The batch modules carry straight-line operations only.
        return TokenStream::new();
    }
    let mut out = TokenStream::new();
    for &t in &plan.emitted {
        let blades = &plan.types.get(t).blades;
        if blades.is_empty() {
            continue;
        }
        let study = plan.is_study_type(t);
        let rotor_like = blades.contains(&0) && blades.iter().all(|&b| grade(b).is_multiple_of(2));
        let mut methods = TokenStream::new();
        if study && plan.has(Op::Norm) {
            methods.extend(study_normalisation(plan, t));
            if rotor_like {
                methods.extend(square_root());
            }
        }
        if rotor_like && plan.has(Op::Sandwich) {
            methods.extend(constrained(plan, t));
            methods.extend(matrices(plan, t, origin));
            methods.extend(euler_angles(plan, t, origin));
        }
        if !methods.is_empty() {
            let name = type_tokens(plan, t);
            out.extend(quote! {
                impl #name { #methods }
            });
        }
    }
    out.extend(division(plan));
    out
}

/// `<x ~x>_0` and the pseudoscalar part of `x ~x`, as expressions in `operand`.
fn study_parts(plan: &Plan, operand: &Operand) -> (TokenStream, TokenStream) {
    let i = plan.metric.pseudoscalar();
    (
        quadratic_component(plan, operand, Involution::Reverse, 0),
        quadratic_component(plan, operand, Involution::Reverse, i),
    )
}

/// `x (a + b I)` (or `~x (a + b I)`), a value of `x`'s type: the types this is used on
/// are closed under multiplication by `I`, which kills every blade holding the null
/// generator and sends the others to their complements.
fn times_scalar_plus_pseudoscalar(
    plan: &Plan,
    operand: &Operand,
    reversed: bool,
    a: &TokenStream,
    b: &TokenStream,
) -> TokenStream {
    let i = plan.metric.pseudoscalar();
    let blades = plan.types.get(operand.ty).blades.clone();
    let sign = |blade: Blade| {
        if reversed {
            Involution::Reverse.sign(blade) as i32
        } else {
            1
        }
    };
    construct(plan, Output::Type(operand.ty), |c| {
        let x = operand.blade(plan, c)?;
        let scaled = if sign(c) > 0 {
            quote!(#a * #x)
        } else {
            quote!(-(#a * #x))
        };
        let dual_terms: Vec<(i32, TokenStream)> = blades
            .iter()
            .filter_map(|&d| {
                let (sigma, blade) = plan.metric.geometric(d, i);
                (sigma != 0 && blade == c).then(|| {
                    let xd = operand.blade(plan, d).expect("a blade of the type");
                    (sigma as i32 * sign(d), xd)
                })
            })
            .collect();
        if dual_terms.is_empty() {
            Some(scaled)
        } else {
            let sum = signed_sum(&dual_terms);
            Some(quote!(#scaled + #b * (#sum)))
        }
    })
}

/// `normalized_study` and `try_normalized_study`.
fn study_normalisation(plan: &Plan, t: TypeId) -> TokenStream {
    let s = scalar_type(plan);
    let this = Operand::new(quote!(self), t);
    let (s_self, p_self) = study_parts(plan, &this);
    let scaled = Operand::new(quote!(descaled), t);
    let (s_scaled, p_scaled) = study_parts(plan, &scaled);
    let largest = largest_abs(plan, &this, &nondegenerate(plan, t));
    let descaled = descaled(plan, &this, &quote!(largest));
    let x = Operand::new(quote!(x), t);
    let result = times_scalar_plus_pseudoscalar(plan, &x, false, &quote!(a), &quote!(b));
    quote! {
        /// The Study normalisation (klein's `normalized`): `self (a + b I)` with
        /// `a = s^(-1/2)`, `b = -a p / (2 s)` for `self ~self = s + p I`, so that `x ~x = 1`
        /// with a zero pseudoscalar part, the same motion (or line) as `self`. Scaled like
        /// `norm` when `s` could overflow or underflow; non-finite when `s` is zero (an
        /// ideal element); see `try_normalized_study`.
        #[inline]
        #[must_use]
        pub fn normalized_study(self) -> Self {
            let s: #s = #s_self;
            let (x, s, p): (Self, #s, #s) = if s >= SQUARE_MIN && s <= SQUARE_MAX {
                (self, s, #p_self)
            } else {
                // Dividing by the largest Euclidean component scales `s` and `p` alike,
                // and the result is the same.
                let largest: #s = #largest;
                let descaled = #descaled;
                (descaled, #s_scaled, #p_scaled)
            };
            let a = 1.0 / math::sqrt(s);
            let b = -0.5 * (p / s) * a;
            #result
        }

        /// `normalized_study`, or `None` when the result is not finite (a zero scalar
        /// part of `self ~self`, or non-finite components).
        #[inline]
        #[must_use]
        pub fn try_normalized_study(self) -> Option<Self> {
            let normalized = self.normalized_study();
            if normalized.to_array().iter().all(|c| c.is_finite()) {
                Some(normalized)
            } else {
                None
            }
        }
    }
}

/// `sqrt` (klein's `sqrt` of a motor or rotor).
fn square_root() -> TokenStream {
    let s_field = field_ident(0);
    quote! {
        /// The square root of the motion: with `u = self.normalized_study()`, the unit
        /// `(1 + u).normalized_study()`, whose square is `u` (half the screw motion, as
        /// klein's `sqrt`). Non-finite when the scalar part of `u` is -1 (a full turn,
        /// whose half is not unique); `constrained()` first avoids it.
        #[inline]
        #[must_use]
        pub fn sqrt(self) -> Self {
            let mut shifted = self.normalized_study();
            shifted.#s_field += 1.0;
            shifted.normalized_study()
        }
    }
}

/// `constrained` (klein's name): `self` or `-self`, whichever has the non-negative scalar.
fn constrained(plan: &Plan, t: TypeId) -> TokenStream {
    let s_field = field_ident(0);
    let this = Operand::new(quote!(self), t);
    let negated = construct(plan, Output::Type(t), |b| {
        let x = this.blade(plan, b)?;
        Some(quote!(-#x))
    });
    quote! {
        /// The representative of the same motion with a non-negative scalar part
        /// (klein's `constrained`): `-self` when the scalar part is negative, else `self`.
        /// `x` and `-x` act alike; this one takes the shorter path in interpolation.
        #[inline]
        #[must_use]
        pub fn constrained(self) -> Self {
            if self.#s_field < 0.0 {
                #negated
            } else {
                self
            }
        }
    }
}

/// The point coordinates `(x_1 .. x_{n-1}, w)` as (blade of the point type, sign): the
/// point `(x, y, z)` is the right complement of `e0 + x e_x + y e_y + z e_z`, so the
/// coordinate of a generator is its complement's component times the complement's sign.
fn point_coordinates(plan: &Plan, origin: usize) -> Vec<(Blade, i32)> {
    let n = plan.metric.dimension();
    (0..n)
        .filter(|&g| g != origin)
        .chain(std::iter::once(origin))
        .map(|g| {
            let (sign, blade) = plan.metric.dual(1 << g);
            (blade, sign as i32)
        })
        .collect()
}

/// `to_matrix{n}x{n}` and `to_matrix{n-1}x{n}`: the sandwich on points, column-major.
fn matrices(plan: &Plan, t: TypeId, origin: usize) -> TokenStream {
    let n = plan.metric.dimension();
    let s = scalar_type(plan);
    let versor = plan.types.get(t).blades.clone();
    let points: Vec<Blade> = canonical_blades(n)
        .into_iter()
        .filter(|&b| grade(b) as usize == n - 1)
        .collect();
    let q = sandwich(&plan.metric, &versor, false, &points);
    let coords = point_coordinates(plan, origin);
    let this = Operand::new(quote!(self), t);
    let entry = |row: usize, col: usize| -> TokenStream {
        let (row_blade, row_sign) = coords[row];
        let (col_blade, col_sign) = coords[col];
        let k = points
            .iter()
            .position(|&b| b == col_blade)
            .expect("a point blade");
        let terms: Vec<(i32, TokenStream)> = q
            .get(&row_blade)
            .and_then(|per_k| per_k.get(&k))
            .map(|pairs| {
                pairs
                    .iter()
                    .map(|(&(i, j), &c)| {
                        let (a, b) = (this.component(plan, i), this.component(plan, j));
                        (c * row_sign * col_sign, quote!(#a * #b))
                    })
                    .collect()
            })
            .unwrap_or_default();
        signed_sum(&terms)
    };
    let columns = (0..n).map(|col| {
        let rows = (0..n).map(|row| entry(row, col));
        quote!([#(#rows),*])
    });
    let full = format_ident!("to_matrix{n}x{n}");
    let affine = format_ident!("to_matrix{}x{n}", n - 1);
    let names = ["x", "y", "z", "w", "v"];
    let layout = names[..n - 1].join(", ");
    let full_doc = format!(
        "The matrix of `p -> self p ~self` on points in homogeneous coordinates `({layout}, w)` \
         (`point({layout})` has `w = 1`), column-major as klein's `mat{n}x{n}` and glam's \
         matrices: `m[column][row]`, so `m[{last}]` is the image of the origin. Exact for any \
         motor: for one with `<m ~m>_0 = s` the last row is `(0, .., 0, s)`.",
        last = n - 1
    );
    let affine_doc = format!(
        "The first {} rows of `{full}` as {n} columns (klein's `mat{}x{n}`): the affine map \
         `p -> A p + t` on `({layout})` with `t` the last column, for a motor with \
         `<m ~m>_0 = 1` (after `normalized` or `normalized_study`); otherwise every entry is \
         that scalar times the motion's.",
        n - 1,
        n - 1
    );
    let lit = proc_macro2::Literal::usize_unsuffixed;
    let (rows, n_lit) = (lit(n - 1), lit(n));
    let affine_columns = (0..n).map(|col| {
        let col = lit(col);
        let rows = (0..n - 1).map(|row| {
            let row = lit(row);
            quote!(m[#col][#row])
        });
        quote!([#(#rows),*])
    });
    quote! {
        #[doc = #full_doc]
        #[inline]
        #[must_use]
        pub fn #full(self) -> [[#s; #n_lit]; #n_lit] {
            [#(#columns),*]
        }

        #[doc = #affine_doc]
        #[inline]
        #[must_use]
        pub fn #affine(self) -> [[#s; #rows]; #n_lit] {
            let m = self.#full();
            [#(#affine_columns),*]
        }
    }
}

/// `to_euler_angles` and `from_euler_angles` in 3D PGA, on types holding the scalar and
/// the three Euclidean bivectors.
fn euler_angles(plan: &Plan, t: TypeId, origin: usize) -> TokenStream {
    if plan.metric.dimension() != 4 {
        return TokenStream::new();
    }
    let s = scalar_type(plan);
    let g: Vec<usize> = (0..4).filter(|&k| k != origin).collect();
    // klein's e23, e31, e12 in the Euclidean generators (x, y, z), as (sign, blade).
    let parts: Vec<(i8, Blade)> = [(g[1], g[2]), (g[2], g[0]), (g[0], g[1])]
        .iter()
        .map(|&(a, b)| plan.metric.geometric(1 << a, 1 << b))
        .collect();
    let blades = &plan.types.get(t).blades;
    if !parts.iter().all(|(_, b)| blades.contains(b)) {
        return TokenStream::new();
    }
    let s_field = field_ident(0);
    let read = parts.iter().map(|&(sign, blade)| {
        let f = field_ident(blade);
        if sign > 0 {
            quote!(self.#f)
        } else {
            quote!(-self.#f)
        }
    });
    let values = [quote!(x), quote!(y), quote!(z)];
    let built = construct(plan, Output::Type(t), |blade| {
        if blade == 0 {
            return Some(quote!(w));
        }
        let k = parts.iter().position(|&(_, b)| b == blade)?;
        let v = &values[k];
        Some(if parts[k].0 > 0 {
            quote!(#v)
        } else {
            quote!(-#v)
        })
    });
    quote! {
        /// klein's `euler_angles` `(roll, pitch, yaw)` of the rotation part (the scalar
        /// and the Euclidean bivectors; a motor's translation is left out), the inverse
        /// of `from_euler_angles`: `pitch` in `[-pi/2, pi/2]`, the others in `(-pi, pi]`;
        /// at `pitch = +-pi/2` exactly `yaw` is 0 (klein's choice). Any scale and sign of
        /// the rotor is allowed. Half-angle form: the rotation rebuilt from the angles is
        /// right to rounding also near the poles (docs/derivations/study-normalisation.md).
        #[inline]
        #[must_use]
        pub fn to_euler_angles(self) -> (#s, #s, #s) {
            let [w, x, y, z]: [#s; 4] = [self.#s_field, #(#read),*];
            let (sum_a, diff_a) = (w + y, z - x);
            let (sum_b, diff_b) = (w - y, z + x);
            let a2 = sum_a * sum_a + diff_a * diff_a;
            let b2 = sum_b * sum_b + diff_b * diff_b;
            let pitch = math::atan2(2.0 * (w * y - x * z), math::sqrt(a2) * math::sqrt(b2));
            // (yaw - roll) / 2 and (yaw + roll) / 2.
            let minus = math::atan2(diff_a, sum_a);
            let plus = math::atan2(diff_b, sum_b);
            let (roll, yaw) = if b2 == 0.0 {
                (-2.0 * minus, 0.0)
            } else if a2 == 0.0 {
                (2.0 * plus, 0.0)
            } else {
                (plus - minus, plus + minus)
            };
            let pi = ::core::#s::consts::PI;
            let wrap = |angle: #s| {
                if angle > pi {
                    angle - 2.0 * pi
                } else if angle <= -pi {
                    angle + 2.0 * pi
                } else {
                    angle
                }
            };
            (wrap(roll), pitch, wrap(yaw))
        }

        /// The unit rotor of klein's `euler_angles` `(roll, pitch, yaw)`, klein's
        /// `rx * ry * rz` of its rotors `rotor(angle, axis)` about `x`, `y`, `z`: the
        /// point matrix is `Rx(-roll) Ry(-pitch) Rz(-yaw)` (right-handed elementary
        /// rotations), the transpose of the aerospace `Rz(yaw) Ry(pitch) Rx(roll)`.
        #[inline]
        #[must_use]
        pub fn from_euler_angles(roll: #s, pitch: #s, yaw: #s) -> Self {
            let (sr, cr) = (math::sin(0.5 * roll), math::cos(0.5 * roll));
            let (sp, cp) = (math::sin(0.5 * pitch), math::cos(0.5 * pitch));
            let (sy, cy) = (math::sin(0.5 * yaw), math::cos(0.5 * yaw));
            let w = cr * cp * cy + sr * sp * sy;
            let x = sr * cp * cy - cr * sp * sy;
            let y = cr * sp * cy + sr * cp * sy;
            let z = cr * cp * sy - sr * sp * cy;
            #built
        }
    }
}

/// `a / b = a * b^-1` for the types whose `b ~b` is `s + p I` (3D PGA's `Even` and
/// `Bivector`), with the closed form `b^-1 = ~b (s - p I) / s^2`.
fn division(plan: &Plan) -> TokenStream {
    if !(plan.products.contains(&ProductKind::Geometric) && plan.has(Op::Inverse)) {
        return TokenStream::new();
    }
    let mut out = TokenStream::new();
    for (a, b) in plan.operand_pairs() {
        if b == TypeId::SCALAR || !plan.is_study_type(b) {
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
        let (s_expr, p_expr) = study_parts(plan, &divisor);
        let inverse = times_scalar_plus_pseudoscalar(plan, &divisor, true, &quote!(a), &quote!(b));
        out.extend(quote! {
            impl ::core::ops::Div<#rhs> for #lhs {
                type Output = #out_ty;
                /// `self * rhs^-1` with `rhs^-1 = ~rhs (s - p I) / s^2` for
                /// `rhs ~rhs = s + p I` (`I I = 0`); non-finite when `s` is zero, as for
                /// scalar division (see `inverse` for the checked form).
                #[inline]
                fn div(self, rhs: #rhs) -> #out_ty {
                    let a = 1.0 / (#s_expr);
                    let b = -(#p_expr) * a * a;
                    self * #inverse
                }
            }
        });
    }
    out
}
