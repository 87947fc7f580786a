//! `Bivector::exp` and `Even::log` in closed form. See docs/derivations/exp-log.md.

use proc_macro2::TokenStream;
use quote::quote;

use super::expr::{construct, field_ident, float, scalar_type, Operand};
use super::products::product_value;
use crate::algebra::{Blade, Involution, ProductKind};
use crate::plan::{Output, Plan, TypeId};

/// The grade-`blade` part of `A A`.
fn self_square_component(plan: &Plan, operand: &Operand, blade: Blade) -> TokenStream {
    super::expr::quadratic_component(plan, operand, Involution::Identity, blade)
}

fn grade_blades(plan: &Plan, k: usize) -> Vec<Blade> {
    plan.types.get(TypeId::grade(k)).blades.clone()
}

/// `Bivector::exp`.
pub fn emit_exp(plan: &Plan) -> TokenStream {
    let n = plan.metric.dimension();
    let s = scalar_type(plan);
    let b = Operand::new(quote!(self), TypeId::grade(2));
    let even = Output::Type(TypeId::even(n));
    let square = self_square_component(plan, &b, 0);
    let body = if n <= 3 {
        // B^2 is a scalar x: exp(B) = cosh(sqrt x) + B sinh(sqrt x)/sqrt x.
        let value = construct(plan, even, |blade| {
            if blade == 0 {
                return Some(quote!(even));
            }
            b.blade(plan, blade).map(|c| quote!(weight * #c))
        });
        quote! {
            let x: #s = #square;
            let [even, weight] = cosh_sinhc_sqrt(x);
            #value
        }
    } else if n <= 5 {
        // B^2 = s + Q with Q = B ^ B commuting with B and Q^2 = t a scalar: functions of
        // B^2 act on the two-dimensional commutative algebra {1, Q}.
        let quad = grade_blades(plan, 4);
        let q_fields: Vec<_> = quad.iter().map(|&bl| field_ident(bl)).collect();
        let q_values: Vec<_> = quad
            .iter()
            .map(|&bl| self_square_component(plan, &b, bl))
            .collect();
        let q = Operand::new(quote!(q), TypeId::grade(4));
        let t = self_square_component(plan, &q, 0);
        let (bq, bq_output) = product_value(plan, ProductKind::Geometric, &b, &q);
        let bq_operand = match bq_output {
            Output::Type(id) => Some(Operand::new(quote!(bq), id)),
            Output::Zero => None,
        };
        let value = construct(plan, even, |blade| {
            let mut parts = Vec::new();
            if blade == 0 {
                parts.push(quote!(c0));
            }
            if let Some(c) = b.blade(plan, blade) {
                parts.push(quote!(s0 * #c));
            }
            if let Some(c) = q.blade(plan, blade) {
                parts.push(quote!(c4 * #c));
            }
            if let Some(c) = bq_operand.as_ref().and_then(|o| o.blade(plan, blade)) {
                parts.push(quote!(s4 * #c));
            }
            (!parts.is_empty()).then(|| quote!(#(#parts)+*))
        });
        quote! {
            let s: #s = #square;
            let q = Quadvector { #(#q_fields: #q_values),* };
            let t: #s = #t;
            let [c0, c4, s0, s4] = exp_weights(s, t);
            let bq = #bq;
            #value
        }
    } else {
        // No closed form is emitted above five dimensions: scaling and squaring of the
        // Taylor series, in the even subalgebra.
        let bivector_fields: Vec<_> = grade_blades(plan, 2)
            .iter()
            .map(|&bl| field_ident(bl))
            .collect();
        let even_blades = plan.types.get(TypeId::even(n)).blades.clone();
        let acc = Operand::new(quote!(acc), TypeId::even(n));
        let x = Operand::new(quote!(x), TypeId::grade(2));
        let (x_acc, _) = product_value(plan, ProductKind::Geometric, &x, &acc);
        let (acc_acc, _) = product_value(plan, ProductKind::Geometric, &acc, &acc);
        let even_fields: Vec<_> = even_blades.iter().map(|&bl| field_ident(bl)).collect();
        quote! {
            let size: #s = (#(self.#bivector_fields * self.#bivector_fields)+*).sqrt();
            let mut halvings = 0;
            let mut scale: #s = 1.0;
            while size * scale > 0.25 && halvings < 2000 {
                scale *= 0.5;
                halvings += 1;
            }
            let x = self * scale;
            let mut acc = Even::ONE;
            for degree in (1..=18).rev() {
                let next: Even = #x_acc;
                let inverse_degree = 1.0 / (degree as #s);
                acc = Even { #(#even_fields: next.#even_fields * inverse_degree),* };
                acc.s += 1.0;
            }
            for _ in 0..halvings {
                acc = #acc_acc;
            }
            acc
        }
    };
    let doc = if n <= 5 {
        "`exp(B)` in closed form for every bivector and every metric: cos/sin, cosh/sinh or \
         1 + B per invariant plane (see docs/derivations/exp-log.md)."
    } else {
        "`exp(B)` by scaling and squaring of the Taylor series (no closed form is emitted \
         above five dimensions)."
    };
    quote! {
        impl Bivector {
            #[doc = #doc]
            #[inline]
            #[must_use]
            pub fn exp(self) -> Even {
                #body
            }
        }
    }
}

/// `Even::log`, for dimensions 2 to 4.
pub fn emit_log(plan: &Plan) -> TokenStream {
    let n = plan.metric.dimension();
    let s = scalar_type(plan);
    let r = Operand::new(quote!(self), TypeId::even(n));
    let bivector = TypeId::grade(2);
    let p_fields: Vec<_> = grade_blades(plan, 2)
        .iter()
        .map(|&bl| field_ident(bl))
        .collect();
    let p = Operand::new(quote!(p), bivector);
    let p_square = self_square_component(plan, &p, 0);
    let body = if n <= 3 {
        quote! {
            let p = Bivector { #(#p_fields: self.#p_fields),* };
            let p2: #s = #p_square;
            let weight = log_weight(self.s, p2);
            Bivector { #(#p_fields: weight * p.#p_fields),* }
        }
    } else {
        let pseudoscalar = plan.metric.pseudoscalar();
        let p4 = self_square_component(plan, &p, pseudoscalar);
        let c4 = r.blade(plan, pseudoscalar).unwrap_or_else(|| quote!(0.0));
        let iota = float(plan.metric.pseudoscalar_square() as f64);
        let unit = Operand::new(quote!(unit), TypeId::grade(4));
        let (p_unit, _) = product_value(plan, ProductKind::Geometric, &p, &unit);
        let unit_field = field_ident(pseudoscalar);
        quote! {
            let p = Bivector { #(#p_fields: self.#p_fields),* };
            let p0: #s = #p_square;
            let p4: #s = #p4;
            let [g0, g4] = log_weights_4d(self.s, #c4, p0, p4, #iota);
            let unit = Quadvector { #unit_field: 1.0 };
            let p_unit: Bivector = #p_unit;
            Bivector { #(#p_fields: g0 * p.#p_fields + g4 * p_unit.#p_fields),* }
        }
    };
    quote! {
        impl Even {
            /// The bivector `B` with `B.exp() == self` on the principal range (rotation
            /// angles below pi per plane); `self` must be a unit rotor.
            #[inline]
            #[must_use]
            pub fn log(self) -> Bivector {
                #body
            }
        }
    }
}

/// The scalar functions behind exp and log, emitted once per algebra. Each carries
/// `allow(dead_code)` because which of them a module calls depends on its dimension.
pub fn emit_scalar_functions(plan: &Plan) -> TokenStream {
    let s = scalar_type(plan);
    quote! {
        /// cosh(sqrt x) for x >= 0 and cos(sqrt -x) for x < 0: entire in x.
        #[allow(dead_code)]
        #[inline]
        fn cosh_sqrt(x: #s) -> #s {
            if x >= 0.0 { x.sqrt().cosh() } else { (-x).sqrt().cos() }
        }

        /// `[cosh(sqrt x), sinh(sqrt x)/sqrt x]` with one square root and one `sin_cos`
        /// (x < 0: cos and sin of sqrt -x); the ratio by its series where the root is tiny.
        #[allow(dead_code)]
        #[inline]
        fn cosh_sinhc_sqrt(x: #s) -> [#s; 2] {
            if x < 0.0 {
                let r = (-x).sqrt();
                let (sin, cos) = r.sin_cos();
                [cos, if r < 1e-4 { 1.0 + x / 6.0 } else { sin / r }]
            } else if x > 0.0 {
                let r = x.sqrt();
                [r.cosh(), if r < 1e-4 { 1.0 + x / 6.0 } else { r.sinh() / r }]
            } else {
                [1.0, 1.0]
            }
        }

        /// sinh(sqrt x)/sqrt x (sin(sqrt -x)/sqrt -x for x < 0), by its series near 0.
        #[allow(dead_code)]
        #[inline]
        fn sinhc_sqrt(x: #s) -> #s {
            if x.abs() < 1e-3 {
                1.0 + x * (1.0 / 6.0 + x * (1.0 / 120.0 + x * (1.0 / 5040.0)))
            } else if x > 0.0 {
                let r = x.sqrt();
                r.sinh() / r
            } else {
                let r = (-x).sqrt();
                r.sin() / r
            }
        }

        /// The derivative of `sinhc_sqrt`, (cosh_sqrt - sinhc_sqrt) / 2x, by its series near 0.
        #[allow(dead_code)]
        fn sinhc_sqrt_derivative(x: #s) -> #s {
            if x.abs() < 1e-2 {
                1.0 / 6.0 + x * (1.0 / 60.0 + x * (1.0 / 1680.0 + x * (1.0 / 90720.0)))
            } else {
                (cosh_sqrt(x) - sinhc_sqrt(x)) / (2.0 * x)
            }
        }

        /// cosh(sqrt z) and sinh(sqrt z)/sqrt z for complex z = (re, im).
        #[allow(dead_code)]
        fn complex_cosh_sinhc_sqrt(re: #s, im: #s) -> [#s; 4] {
            let modulus = re.hypot(im);
            if modulus < 1e-3 {
                // 1 + z/2 + z^2/24 and 1 + z/6 + z^2/120.
                let (z2r, z2i) = (re * re - im * im, 2.0 * re * im);
                return [
                    1.0 + re / 2.0 + z2r / 24.0,
                    im / 2.0 + z2i / 24.0,
                    1.0 + re / 6.0 + z2r / 120.0,
                    im / 6.0 + z2i / 120.0,
                ];
            }
            // Principal square root a + ib of re + i im.
            let a = ((modulus + re) / 2.0).sqrt();
            let b = ((modulus - re) / 2.0).sqrt().copysign(im);
            let (ch, sh, c, s) = (a.cosh(), a.sinh(), b.cos(), b.sin());
            let (cosh_r, cosh_i) = (ch * c, sh * s);
            let (sinh_r, sinh_i) = (sh * c, ch * s);
            let d = a * a + b * b;
            [cosh_r, cosh_i, (sinh_r * a + sinh_i * b) / d, (sinh_i * a - sinh_r * b) / d]
        }

        /// For B^2 = s + Q with Q^2 = t: the weights (c0, c4, s0, s4) with
        /// cosh(B) = c0 + c4 Q and sinh(B)/B = s0 + s4 Q.
        #[allow(dead_code)]
        fn exp_weights(s: #s, t: #s) -> [#s; 4] {
            if t > 0.0 {
                let r = t.sqrt();
                let (cp, cm) = (cosh_sqrt(s + r), cosh_sqrt(s - r));
                let (sp, sm) = (sinhc_sqrt(s + r), sinhc_sqrt(s - r));
                [(cp + cm) / 2.0, (cp - cm) / (2.0 * r), (sp + sm) / 2.0, (sp - sm) / (2.0 * r)]
            } else if t < 0.0 {
                let r = (-t).sqrt();
                let [cr, ci, sr, si] = complex_cosh_sinhc_sqrt(s, r);
                [cr, ci / r, sr, si / r]
            } else {
                let weight = sinhc_sqrt(s);
                [cosh_sqrt(s), weight / 2.0, weight, sinhc_sqrt_derivative(s)]
            }
        }

        /// The weight w with log(c + P) = w P, where P^2 = p2 is a scalar and c^2 - p2 = 1.
        #[allow(dead_code)]
        fn log_weight(c: #s, p2: #s) -> #s {
            if p2 < 0.0 {
                let m = (-p2).sqrt();
                m.atan2(c) / m
            } else if p2 > 0.0 {
                let m = p2.sqrt();
                if m < 1e-4 { 1.0 - p2 / 6.0 } else { m.asinh() / m }
            } else {
                1.0 / c
            }
        }

        /// For a four-dimensional rotor c0 + P + c4 I with P^2 = p0 + p4 I and I^2 = iota:
        /// the weights (g0, g4) with log = g0 P + g4 P I.
        #[allow(dead_code)]
        fn log_weights_4d(c0: #s, c4: #s, p0: #s, p4: #s, iota: #s) -> [#s; 2] {
            if iota > 0.0 {
                // Two real channels, I -> +1 and I -> -1.
                let plus = log_weight(c0 + c4, p0 + p4);
                let minus = log_weight(c0 - c4, p0 - p4);
                [(plus + minus) / 2.0, (plus - minus) / 2.0]
            } else if iota < 0.0 {
                // One complex channel, I -> i: g = y / sinh y with cosh y = c, sinh^2 y = p;
                // y = log1p(u) with u = c - 1 + sqrt p and c - 1 = p / (c + 1).
                let modulus = p0.hypot(p4);
                if modulus == 0.0 {
                    return [1.0, 0.0];
                }
                let sr = ((modulus + p0) / 2.0).sqrt();
                let si = ((modulus - p0) / 2.0).sqrt().copysign(p4);
                let (dr, di) = (c0 + 1.0, c4);
                let dd = dr * dr + di * di;
                let (qr, qi) = ((p0 * dr + p4 * di) / dd, (p4 * dr - p0 * di) / dd);
                let (ur, ui) = (qr + sr, qi + si);
                let yr = 0.5 * (2.0 * ur + ur * ur + ui * ui).ln_1p();
                let yi = ui.atan2(1.0 + ur);
                let ss = sr * sr + si * si;
                [(yr * sr + yi * si) / ss, (yi * sr - yr * si) / ss]
            } else {
                // Dual numbers, I^2 = 0: g4 = c4 (sinh y - y cosh y) / sinh^3 y.
                let g0 = log_weight(c0, p0);
                let h = if p0.abs() < 1e-12 {
                    -1.0 / 3.0
                } else if p0 < 0.0 {
                    let m = (-p0).sqrt();
                    let theta = m.atan2(c0);
                    (theta * c0 - m) / (m * m * m)
                } else {
                    let m = p0.sqrt();
                    let y = m.asinh();
                    (m - y * c0) / (m * m * m)
                };
                [g0, c4 * h]
            }
        }
    }
}
