//! `Bivector::exp` and `Even::log` in closed form. See docs/derivations/exp-log.md.

use proc_macro2::TokenStream;
use quote::quote;

use super::expr::{construct, field_ident, float, scalar_type, Operand};
use super::products::product_value;
use crate::algebra::{Blade, Involution, ProductKind};
use crate::plan::{ExpLogForm, Output, Plan, TypeId};

/// The grade-`blade` part of `A A`.
fn self_square_component(plan: &Plan, operand: &Operand, blade: Blade) -> TokenStream {
    super::expr::quadratic_component(plan, operand, Involution::Identity, blade)
}

fn grade_blades(plan: &Plan, k: usize) -> Vec<Blade> {
    plan.types.get(TypeId::grade(k)).blades.clone()
}

/// `Bivector::exp` in the plan's form.
pub fn emit_exp(plan: &Plan, form: ExpLogForm) -> TokenStream {
    let n = plan.metric.dimension();
    let s = scalar_type(plan);
    let b = Operand::new(quote!(self), TypeId::grade(2));
    let even = Output::Type(TypeId::even(n));
    let square = self_square_component(plan, &b, 0);
    let body = match form {
        ExpLogForm::Plane => {
            // B^2 is a scalar x: exp(B) = cosh(sqrt x) + B sinh(sqrt x)/sqrt x.
            let value = construct(plan, even, |blade| {
                if blade == 0 {
                    return Some(quote!(even));
                }
                b.blade(plan, blade).map(|c| quote!(weight * #c))
            });
            quote! {
                let x: #s = #square;
                let [even, weight] = if x.abs() <= SERIES_MAX {
                    cosh_sinhc_series(x)
                } else {
                    let [x, root] = square_and_root(self);
                    cosh_sinhc(x, root)
                };
                #value
            }
        }
        ExpLogForm::Channels => four_dimensional_exp(plan),
        ExpLogForm::Quartic => {
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
        }
        ExpLogForm::Series => {
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
                let size: #s = math::sqrt(#(self.#bivector_fields * self.#bivector_fields)+*);
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
        }
    };
    let doc = if form != ExpLogForm::Series {
        "`exp(B)` in closed form for every bivector and every metric: cos/sin, cosh/sinh or \
         1 + B per invariant plane (see docs/derivations/exp-log.md). Angles are reduced \
         modulo 2 pi by `sin`/`cos` themselves, and `B` is scaled before squaring, so a \
         rotation bivector of any finite size gives a unit rotor."
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

/// The channels of a four-dimensional bivector whose pseudoscalar squares to +1:
/// `B+- = (B +- B I) / 2`, so that `B = B+ + B-`, `B+ B- = 0` and `B+-^2 = 2 <B+-^2>_0 P+-`
/// with the projectors `P+- = (1 +- I) / 2`. Each channel is then a problem of one plane
/// whose square is formed from its own components, without the cancellation of
/// `s +- sqrt(t)` (see docs/derivations/exp-log.md).
fn channels(plan: &Plan, of: &Operand) -> TokenStream {
    let pseudoscalar = plan.metric.pseudoscalar();
    let unit_field = field_ident(pseudoscalar);
    let unit = Operand::new(quote!(unit), TypeId::grade(4));
    let (dual, _) = product_value(plan, ProductKind::Geometric, of, &unit);
    let fields: Vec<_> = grade_blades(plan, 2)
        .iter()
        .map(|&bl| field_ident(bl))
        .collect();
    let b = &of.expr;
    quote! {
        let unit = Quadvector { #unit_field: 1.0 };
        let dual: Bivector = #dual;
        let plus = Bivector { #(#fields: (#b.#fields + dual.#fields) * 0.5),* };
        let minus = Bivector { #(#fields: (#b.#fields - dual.#fields) * 0.5),* };
    }
}

/// `Bivector::exp` in four dimensions with `I^2 = 1` (Euclidean G4): by channels,
/// `exp(B) = (C+ + C-)/2 + (C+ - C-)/2 I + S+ B+ + S- B-` with `C`, `S` the cosine and
/// sinc of each channel's angle. Nothing is divided by the difference of the two plane
/// angles, so the isoclinic case `a = b` is as accurate as any other.
fn four_dimensional_exp(plan: &Plan) -> TokenStream {
    let n = plan.metric.dimension();
    let pseudoscalar = plan.metric.pseudoscalar();
    let split = channels(plan, &Operand::new(quote!(self), TypeId::grade(2)));
    let value = construct(plan, Output::Type(TypeId::even(n)), |blade| {
        if blade == 0 {
            return Some(quote!((cp + cm) * 0.5));
        }
        if blade == pseudoscalar {
            return Some(quote!((cp - cm) * 0.5));
        }
        let f = field_ident(blade);
        Some(quote!(sp * plus.#f + sm * minus.#f))
    });
    quote! {
        #split
        // A channel's own angle is sqrt(2) times the root of its scalar square.
        let [cp, sp] = channel_cosh_sinhc(plus);
        let [cm, sm] = channel_cosh_sinhc(minus);
        #value
    }
}

/// The bivector chosen as `log(-1)`: `pi D` for the first basis bivector `D` with
/// `D^2 = -1` (e12 in Euclidean algebras), a full turn in that plane; `None` when the
/// metric has none.
fn full_turn_plane(plan: &Plan) -> Option<crate::algebra::Blade> {
    grade_blades(plan, 2)
        .into_iter()
        .find(|&bl| plan.metric.geometric(bl, bl).0 < 0)
}

/// `Even::log` in the plan's form (dimensions 2 to 4: never [`ExpLogForm::Series`]).
pub fn emit_log(plan: &Plan, form: ExpLogForm) -> TokenStream {
    let n = plan.metric.dimension();
    let s = scalar_type(plan);
    let r = Operand::new(quote!(self), TypeId::even(n));
    let bivector = TypeId::grade(2);
    let p_fields: Vec<_> = grade_blades(plan, 2)
        .iter()
        .map(|&bl| field_ident(bl))
        .collect();
    let p = Operand::new(quote!(p), bivector);
    let norm_squared = super::unary::norm_squared_expr(plan, &r);
    // Half the digits: rotors that drifted by rounding over many products pass, a value
    // that is not a rotor does not.
    let tolerance = match plan.scalar {
        crate::spec::Scalar::F64 => float(f64::EPSILON.sqrt()),
        crate::spec::Scalar::F32 => float(f64::from(f32::EPSILON.sqrt())),
    };
    let turn = full_turn_plane(plan);
    let pseudoscalar = plan.metric.pseudoscalar();
    let body = match form {
        ExpLogForm::Plane => {
            let turn_term = |blade| {
                if Some(blade) == turn {
                    quote!(+ turn)
                } else {
                    quote!()
                }
            };
            let terms = grade_blades(plan, 2).into_iter().map(|bl| {
                let f = field_ident(bl);
                let t = turn_term(bl);
                quote!(#f: weight * p.#f #t)
            });
            // Without a plane that squares to -1, -1 is no exponential: no logarithm.
            let no_plane = turn.is_none().then(|| {
                quote! {
                    if turn != 0.0 {
                        return None;
                    }
                }
            });
            quote! {
                let p = Bivector { #(#p_fields: self.#p_fields),* };
                let [x, root] = square_and_root(p);
                // Past a right angle `P` is divided by its largest component first, so
                // that a derivative near -1 is not the difference of two huge terms; the
                // other branch is the code of before, unchanged.
                if self.s < 0.0 && x < 0.0 {
                    let (u, [w, _]) = log_past_right_angle(self.s, p, 1.0);
                    Bivector { #(#p_fields: w * u.#p_fields),* }
                } else {
                    let [weight, turn] = log_weight(self.s, x, root, p == Bivector::ZERO);
                    #no_plane
                    Bivector { #(#terms),* }
                }
            }
        }
        ExpLogForm::Channels => {
            let split = channels(plan, &Operand::new(quote!(p), bivector));
            let c4 = r.blade(plan, pseudoscalar).unwrap_or_else(|| quote!(0.0));
            // The turn of each channel: pi (D +- D I) / 2, a unit angle in that channel.
            let (turn_plus, turn_minus) = match turn {
                Some(d) => {
                    let (sign, di) = plan.metric.geometric(d, pseudoscalar);
                    let half = float(0.5);
                    let signed = float(0.5 * f64::from(sign));
                    let plus = [(d, quote!(#half)), (di, quote!(#signed))];
                    let minus = [(d, quote!(#half)), (di, quote!(-#signed))];
                    (plus.to_vec(), minus.to_vec())
                }
                None => (Vec::new(), Vec::new()),
            };
            let terms = grade_blades(plan, 2).into_iter().map(|bl| {
                let f = field_ident(bl);
                let extra = |list: &[(crate::algebra::Blade, TokenStream)], name: TokenStream| {
                    list.iter()
                        .find(|(b, _)| *b == bl)
                        .map(|(_, c)| quote!(+ #c * #name))
                        .unwrap_or_default()
                };
                let tp = extra(&turn_plus, quote!(turn_plus));
                let tm = extra(&turn_minus, quote!(turn_minus));
                quote!(#f: wp * plus.#f + wm * minus.#f #tp #tm)
            });
            quote! {
                let p = Bivector { #(#p_fields: self.#p_fields),* };
                #split
                let (cp, cm) = (self.s + #c4, self.s - #c4);
                let [xp, rp] = square_and_root(plus);
                let [xm, rm] = square_and_root(minus);
                let (mp, mm) = (::core::#s::consts::SQRT_2 * rp, ::core::#s::consts::SQRT_2 * rm);
                // R ~R = 1 is each channel's c^2 - sign(x) m^2 = 1.
                let np = cp * cp - xp.signum() * mp * mp;
                let nm = cm * cm - xm.signum() * mm * mm;
                if !((np - 1.0).abs() <= #tolerance && (nm - 1.0).abs() <= #tolerance) {
                    return None;
                }
                // Past a right angle a channel is divided by its largest component first
                // (see the plane form).
                let (plus, [wp, turn_plus]) = if cp < 0.0 && xp < 0.0 {
                    log_past_right_angle(cp, plus, ::core::#s::consts::SQRT_2)
                } else {
                    (plus, log_weight(cp, xp, mp, plus == Bivector::ZERO))
                };
                let (minus, [wm, turn_minus]) = if cm < 0.0 && xm < 0.0 {
                    log_past_right_angle(cm, minus, ::core::#s::consts::SQRT_2)
                } else {
                    (minus, log_weight(cm, xm, mm, minus == Bivector::ZERO))
                };
                Bivector { #(#terms),* }
            }
        }
        ExpLogForm::Quartic => {
            let p_square = self_square_component(plan, &p, 0);
            let p4 = self_square_component(plan, &p, pseudoscalar);
            let c4 = r.blade(plan, pseudoscalar).unwrap_or_else(|| quote!(0.0));
            let iota = float(plan.metric.pseudoscalar_square() as f64);
            let unit = Operand::new(quote!(unit), TypeId::grade(4));
            // With a null pseudoscalar (`signature: (0, 1, 3)`) `p I` is zero.
            let p_unit = match product_value(plan, ProductKind::Geometric, &p, &unit) {
                (_, Output::Zero) => quote!(Bivector::ZERO),
                (value, Output::Type(_)) => value,
            };
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
        }
        ExpLogForm::Series => unreachable!("the plan has no log above four dimensions"),
    };
    quote! {
        impl Even {
            /// The bivector `B` with `B.exp() == self` on the principal range (rotation
            /// angles below pi per plane, or their sum below pi in four dimensions), or
            /// `None` when `self` is not a rotor: `<R ~R>_0` further from 1 than the
            /// square root of the machine epsilon, or a result that is not finite. Where
            /// the logarithm is not unique it is chosen: `log(-1)` is `pi e12`, a full turn
            /// in the first plane that squares to -1, and in four dimensions a channel at
            /// -1 (`log(+-e1234)` in G4) turns by pi in `(e12 -+ e34) / 2`. See
            /// docs/derivations/exp-log.md.
            #[inline]
            #[must_use]
            pub fn log(self) -> Option<Bivector> {
                let norm_squared: #s = #norm_squared;
                if !((norm_squared - 1.0).abs() <= #tolerance) {
                    return None;
                }
                let log = { #body };
                if log.to_array().iter().all(|c| c.is_finite()) {
                    Some(log)
                } else {
                    None
                }
            }
        }
    }
}

/// The scalar functions behind exp and log, emitted once per algebra. Each carries
/// `allow(dead_code)` because which of them a module calls depends on its dimension.
pub fn emit_scalar_functions(plan: &Plan) -> TokenStream {
    let s = scalar_type(plan);
    let b = Operand::new(quote!(b), TypeId::grade(2));
    let square = self_square_component(plan, &b, 0);
    let u = Operand::new(quote!(u), TypeId::grade(2));
    let unit_square = self_square_component(plan, &u, 0);
    let indices: Vec<usize> = (0..grade_blades(plan, 2).len()).collect();
    let largest = super::unary::largest_abs(plan, &b, &indices);
    let descaled = super::unary::descaled(plan, &b, &quote!(largest));
    // The largest component that enters the square: a null blade's would not bound it.
    let rotation_indices = super::unary::nondegenerate(plan, TypeId::grade(2));
    let largest_rotation = super::unary::largest_abs(plan, &b, &rotation_indices);
    let even_series = super::sin_cos::emit_even_series(plan.scalar);
    // f32 channels keep the root and the library's `sincosf`: the series (summed in f64)
    // measured 1.2x the time in batch form for the G4 exp, though faster in a chain.
    let channel_series = (plan.scalar == crate::spec::Scalar::F64).then(|| {
        quote! {
            let b = channel;
            let x: #s = 2.0 * (#square);
            if x.abs() <= SERIES_MAX {
                return cosh_sinhc_series(x);
            }
        }
    });
    super::template::fill(
        SCALAR_FUNCTIONS,
        &[
            ("even_series", &even_series),
            ("s", &s),
            ("square", &square),
            ("largest", &largest),
            ("largest_rotation", &largest_rotation),
            ("descaled", &descaled),
            ("unit_square", &unit_square),
            ("channel_series", &channel_series),
        ],
    )
}

/// The scalar functions behind exp and log (`#s` the scalar type), emitted once per algebra.
const SCALAR_FUNCTIONS: &str = r#"
#even_series

/// `[x, sqrt |x|]` for `x = <B B>_0`, the root right to a few ulps at every
/// magnitude: when the squares could overflow or underflow, `B` is first divided
/// by its largest component, and `x` then carries only the sign of `<B B>_0`.
#[allow(dead_code)]
#[inline]
fn square_and_root(b: Bivector) -> [#s; 2] {
    let x: #s = #square;
    if x.abs() >= SQUARE_MIN && x.abs() <= SQUARE_MAX {
        return [x, math::sqrt(x.abs())];
    }
    let largest: #s = #largest;
    if !(largest > 0.0 && largest < #s::INFINITY) {
        return [x, math::sqrt(x.abs())];
    }
    let u = #descaled;
    let x: #s = #unit_square;
    [x, math::sqrt(x.abs()) * largest]
}

/// `[cosh, sinhc]` of a four-dimensional channel's angle, `sqrt 2` times the root
/// of its square: in `f64` by the series where that is small, else by the root.
#[allow(dead_code)]
#[inline]
fn channel_cosh_sinhc(channel: Bivector) -> [#s; 2] {
    #channel_series
    let [x, root] = square_and_root(channel);
    cosh_sinhc(x, ::core::#s::consts::SQRT_2 * root)
}

/// cosh(sqrt x) for x >= 0 and cos(sqrt -x) for x < 0: entire in x.
#[allow(dead_code)]
#[inline]
fn cosh_sqrt(x: #s) -> #s {
    if x >= 0.0 { math::cosh(math::sqrt(x)) } else { math::cos(math::sqrt(-x)) }
}

/// `[cosh r, sinh(r)/r]` for `x > 0` and `[cos r, sin(r)/r]` for `x < 0`, where
/// `r = sqrt |x|` is given (only the sign of `x` is read); the ratio by its series
/// where `r` is tiny. `sin_cos` reduces any finite angle modulo 2 pi exactly. The
/// reciprocal of `r` is taken before the sine, so that the division runs beside
/// the series rather than after them. A NaN `x` (a bivector holding NaN) fails
/// both comparisons; `1 + x` keeps it NaN instead of the identity's `[1, 1]`.
#[allow(dead_code)]
#[inline]
fn cosh_sinhc(x: #s, r: #s) -> [#s; 2] {
    if x < 0.0 {
        let inverse = 1.0 / r;
        let (sin, cos) = math::sin_cos(r);
        [cos, if r < 1e-4 { 1.0 - r * r / 6.0 } else { sin * inverse }]
    } else if x > 0.0 {
        [math::cosh(r), if r < 1e-4 { 1.0 + r * r / 6.0 } else { math::sinh(r) / r }]
    } else {
        [1.0 + x, 1.0 + x]
    }
}

/// sinh(sqrt x)/sqrt x (sin(sqrt -x)/sqrt -x for x < 0), by its series near 0.
#[allow(dead_code)]
#[inline]
fn sinhc_sqrt(x: #s) -> #s {
    if x.abs() < 1e-3 {
        1.0 + x * (1.0 / 6.0 + x * (1.0 / 120.0 + x * (1.0 / 5040.0)))
    } else if x > 0.0 {
        let r = math::sqrt(x);
        math::sinh(r) / r
    } else {
        let r = math::sqrt(-x);
        math::sin(r) / r
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
    let modulus = math::hypot(re, im);
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
    let a = math::sqrt((modulus + re) / 2.0);
    let b = math::sqrt((modulus - re) / 2.0).copysign(im);
    let (ch, sh) = (math::cosh(a), math::sinh(a));
    let (s, c) = math::sin_cos(b);
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
        let r = math::sqrt(t);
        let (cp, cm) = (cosh_sqrt(s + r), cosh_sqrt(s - r));
        let (sp, sm) = (sinhc_sqrt(s + r), sinhc_sqrt(s - r));
        [(cp + cm) / 2.0, (cp - cm) / (2.0 * r), (sp + sm) / 2.0, (sp - sm) / (2.0 * r)]
    } else if t < 0.0 {
        let r = math::sqrt(-t);
        let [cr, ci, sr, si] = complex_cosh_sinhc_sqrt(s, r);
        [cr, ci / r, sr, si / r]
    } else {
        let weight = sinhc_sqrt(s);
        [cosh_sqrt(s), weight / 2.0, weight, sinhc_sqrt_derivative(s)]
    }
}

/// `[w, turn]` with `log(c + P) = w P + turn D`, where `P^2` has the sign of `x`,
/// `m = sqrt |P^2|` and `c^2 - P^2 = 1`; `turn` is pi for `c + P = -1` (`P` zero)
/// and `D` the plane chosen for it, with `w = 1/c` there: `-R = exp(P/c)` to
/// first order, so a `P` that is zero but has a derivative (over dual numbers)
/// carries it. NaN where no real logarithm exists (`c < 0` with `P^2 >= 0` and
/// `P` not zero).
#[allow(dead_code)]
#[inline]
fn log_weight(c: #s, x: #s, m: #s, p_is_zero: bool) -> [#s; 2] {
    if p_is_zero && c < 0.0 {
        [1.0 / c, ::core::#s::consts::PI]
    } else if x < 0.0 {
        [math::atan2(m, c) / m, 0.0]
    } else if c < 0.0 {
        [#s::NAN, 0.0]
    } else if x > 0.0 {
        [if m < 1e-4 { 1.0 - m * m / 6.0 } else { math::asinh(m) / m }, 0.0]
    } else {
        [1.0 / c, 0.0]
    }
}

/// `(u, [w, 0])` with `log(c + B) = w u` for `c < 0` and `<B B>_0 < 0` (a rotation
/// by more than a right angle): `u` is `B` divided by its largest component (one
/// of `u`'s components is then +-1, with a zero derivative over dual numbers), the
/// angle `atan2(k |B|, c)` and `w` the angle over `k |u|`; `k` is `sqrt 2` for a
/// four-dimensional channel, whose angle is `sqrt 2` times the root of its
/// square. Near -1 the plain `atan2(m, c) / m` times `B` differentiates to the
/// difference of two terms of size `pi / m`, which loses everything to rounding.
/// Out of line, so that `log`, inlined where it is called, stays as small as before
/// on the path of a rotation below a right angle.
#[allow(dead_code)]
#[inline(never)]
fn log_past_right_angle(c: #s, b: Bivector, k: #s) -> (Bivector, [#s; 2]) {
    let largest: #s = #largest_rotation;
    let u = #descaled;
    let x: #s = #unit_square;
    let root = k * math::sqrt(x.abs());
    (u, [math::atan2(root * largest, c) / root, 0.0])
}

/// The weight w with log(c + P) = w P, where P^2 = p2 is a scalar and c^2 - p2 = 1.
#[allow(dead_code)]
fn log_weight_of_square(c: #s, p2: #s) -> #s {
    if p2 < 0.0 {
        let m = math::sqrt(-p2);
        math::atan2(m, c) / m
    } else if p2 > 0.0 {
        let m = math::sqrt(p2);
        if m < 1e-4 { 1.0 - p2 / 6.0 } else { math::asinh(m) / m }
    } else {
        1.0 / c
    }
}

/// For a four-dimensional rotor c0 + P + c4 I with P^2 = p0 + p4 I and I^2 = iota
/// (-1 or 0; +1 is taken by channels in `Even::log`): the weights (g0, g4) with
/// log = g0 P + g4 P I.
#[allow(dead_code)]
fn log_weights_4d(c0: #s, c4: #s, p0: #s, p4: #s, iota: #s) -> [#s; 2] {
    if iota < 0.0 {
        // One complex channel, I -> i: g = y / sinh y with cosh y = c, sinh^2 y = p;
        // y = log1p(u) with u = c - 1 + sqrt p and c - 1 = p / (c + 1).
        let modulus = math::hypot(p0, p4);
        if modulus == 0.0 {
            return [1.0, 0.0];
        }
        let sr = math::sqrt((modulus + p0) / 2.0);
        let si = math::sqrt((modulus - p0) / 2.0).copysign(p4);
        let (dr, di) = (c0 + 1.0, c4);
        let dd = dr * dr + di * di;
        let (qr, qi) = ((p0 * dr + p4 * di) / dd, (p4 * dr - p0 * di) / dd);
        let (ur, ui) = (qr + sr, qi + si);
        let yr = 0.5 * math::ln_1p(2.0 * ur + ur * ur + ui * ui);
        let yi = math::atan2(ui, 1.0 + ur);
        let ss = sr * sr + si * si;
        [(yr * sr + yi * si) / ss, (yi * sr - yr * si) / ss]
    } else {
        // Dual numbers, I^2 = 0: g4 = c4 (sinh y - y cosh y) / sinh^3 y.
        let g0 = log_weight_of_square(c0, p0);
        let h = if p0.abs() < 1e-12 {
            -1.0 / 3.0
        } else if p0 < 0.0 {
            let m = math::sqrt(-p0);
            let theta = math::atan2(m, c0);
            (theta * c0 - m) / (m * m * m)
        } else {
            let m = math::sqrt(p0);
            let y = math::asinh(m);
            (m - y * c0) / (m * m * m)
        };
        [g0, c4 * h]
    }
}
"#;
