//! `exp_bivector` and `log_even` in WGSL: the closed forms of `Bivector::exp` and
//! `Even::log` (`emit/exp_log.rs`) in the plan's form ([`ExpLogForm`], the one the Rust
//! takes), the same squares (the planner's quadratic forms) and the same scalar weights,
//! ported to WGSL's built-ins. The scalar weights are `ga_*` functions emitted once beside
//! them; they are helpers, not API (docs/generated-api.md).
//!
//! Rust's `Option` has no WGSL counterpart: `log_even` returns `Logarithm { value, ok }`,
//! `ok` false exactly where the Rust returns `None` (not a rotor by the same tolerance,
//! no real logarithm, or a non-finite result), and `value` then the zero bivector.

use proc_macro2::TokenStream;
use quote::quote;

use super::text::text;
use crate::algebra::{Blade, Involution, ProductKind};
use crate::emit::expr::{construct_in, float, quadratic_component, Operand, Syntax};
use crate::emit::products::product_value_in;
use crate::emit::unary::norm_squared_expr;
use crate::plan::{ExpLogForm, Output, Plan, TypeId};

/// The helpers, `exp_bivector` and `log_even` where the module has them: in the plan's
/// closed forms (the Rust's Taylor series above five dimensions has no shader form).
pub fn emit(out: &mut String, plan: &Plan) {
    let exp = plan.exp_form().filter(|&form| form != ExpLogForm::Series);
    let log = plan.log_form();
    if exp.is_none() && log.is_none() {
        return;
    }
    out.push_str(&helpers(exp, log));
    if let Some(form) = exp {
        out.push_str(&exp_bivector(plan, form));
    }
    if let Some(form) = log {
        out.push_str(&log_even(plan, form));
    }
}

/// The `ga_*` scalar functions the module's forms call, each once.
fn helpers(exp: Option<ExpLogForm>, log: Option<ExpLogForm>) -> String {
    let mut out = String::from(
        "// Helpers of exp_bivector and log_even (not API: their names may change).\n\n",
    );
    match exp {
        Some(ExpLogForm::Quartic) => out.push_str(EXP_WEIGHTS),
        Some(_) => out.push_str(COSH_SINHC),
        None => {}
    }
    match log {
        Some(ExpLogForm::Quartic) => out.push_str(LOG_WEIGHTS_4D),
        Some(_) => out.push_str(LOG_WEIGHT),
        None => {}
    }
    out
}

/// `[cosh r, sinh(r)/r]` for `x > 0`, `[cos r, sin(r)/r]` for `x < 0` (only the sign of
/// `x` is read), the ratio by its series where `r` is tiny: Rust's `cosh_sinhc`.
const COSH_SINHC: &str = "\
fn ga_cosh_sinhc(x: f32, r: f32) -> vec2<f32> {
    if (x < 0.0) {
        if (r < 1e-4) {
            return vec2<f32>(cos(r), 1.0 - r * r / 6.0);
        }
        return vec2<f32>(cos(r), sin(r) / r);
    } else if (x > 0.0) {
        if (r < 1e-4) {
            return vec2<f32>(cosh(r), 1.0 + r * r / 6.0);
        }
        return vec2<f32>(cosh(r), sinh(r) / r);
    }
    return vec2<f32>(1.0, 1.0);
}

";

/// Rust's `cosh_sqrt`, `sinhc_sqrt`, its derivative, the complex pair and `exp_weights`:
/// for `B B = s + Q` with `Q Q = t`, the weights `(c0, c4, s0, s4)` of
/// `cosh B = c0 + c4 Q` and `sinh(B)/B = s0 + s4 Q`. WGSL has no `hypot` or `copysign`:
/// the modulus is the plain root of the squares, and the sign is chosen by `select`.
const EXP_WEIGHTS: &str = "\
fn ga_cosh_sqrt(x: f32) -> f32 {
    if (x >= 0.0) {
        return cosh(sqrt(x));
    }
    return cos(sqrt(-x));
}

fn ga_sinhc_sqrt(x: f32) -> f32 {
    if (abs(x) < 1e-3) {
        return 1.0 + x * (1.0 / 6.0 + x * (1.0 / 120.0 + x * (1.0 / 5040.0)));
    } else if (x > 0.0) {
        let r = sqrt(x);
        return sinh(r) / r;
    }
    let r = sqrt(-x);
    return sin(r) / r;
}

fn ga_sinhc_sqrt_derivative(x: f32) -> f32 {
    if (abs(x) < 1e-2) {
        return 1.0 / 6.0 + x * (1.0 / 60.0 + x * (1.0 / 1680.0 + x * (1.0 / 90720.0)));
    }
    return (ga_cosh_sqrt(x) - ga_sinhc_sqrt(x)) / (2.0 * x);
}

fn ga_complex_cosh_sinhc_sqrt(re: f32, im: f32) -> vec4<f32> {
    let modulus = sqrt(re * re + im * im);
    if (modulus < 1e-3) {
        let z2r = re * re - im * im;
        let z2i = 2.0 * re * im;
        return vec4<f32>(1.0 + re / 2.0 + z2r / 24.0, im / 2.0 + z2i / 24.0, 1.0 + re / 6.0 + z2r / 120.0, im / 6.0 + z2i / 120.0);
    }
    let a = sqrt(max((modulus + re) / 2.0, 0.0));
    let b_size = sqrt(max((modulus - re) / 2.0, 0.0));
    let b = select(b_size, -b_size, im < 0.0);
    let ch = cosh(a);
    let sh = sinh(a);
    let sn = sin(b);
    let cs = cos(b);
    let d = a * a + b * b;
    return vec4<f32>(ch * cs, sh * sn, (sh * cs * a + ch * sn * b) / d, (ch * sn * a - sh * cs * b) / d);
}

fn ga_exp_weights(s: f32, t: f32) -> vec4<f32> {
    if (t > 0.0) {
        let r = sqrt(t);
        let cp = ga_cosh_sqrt(s + r);
        let cm = ga_cosh_sqrt(s - r);
        let sp = ga_sinhc_sqrt(s + r);
        let sm = ga_sinhc_sqrt(s - r);
        return vec4<f32>((cp + cm) / 2.0, (cp - cm) / (2.0 * r), (sp + sm) / 2.0, (sp - sm) / (2.0 * r));
    } else if (t < 0.0) {
        let r = sqrt(-t);
        let w = ga_complex_cosh_sinhc_sqrt(s, r);
        return vec4<f32>(w.x, w.y / r, w.z, w.w / r);
    }
    let weight = ga_sinhc_sqrt(s);
    return vec4<f32>(ga_cosh_sqrt(s), weight / 2.0, weight, ga_sinhc_sqrt_derivative(s));
}

";

/// Rust's `log_weight`, `(w, turn, ok)` with `log(c + P) = w P + turn D`: `ok` is 0 where
/// the Rust gives NaN (no real logarithm: `c < 0` with `P P >= 0` and `P` not zero).
const LOG_WEIGHT: &str = "\
fn ga_log_weight(c: f32, x: f32, m: f32, p_is_zero: bool) -> vec3<f32> {
    if (p_is_zero && c < 0.0) {
        return vec3<f32>(1.0 / c, 3.141592653589793, 1.0);
    } else if (x < 0.0) {
        return vec3<f32>(atan2(m, c) / m, 0.0, 1.0);
    } else if (c < 0.0) {
        return vec3<f32>(0.0, 0.0, 0.0);
    } else if (x > 0.0) {
        if (m < 1e-4) {
            return vec3<f32>(1.0 - m * m / 6.0, 0.0, 1.0);
        }
        return vec3<f32>(asinh(m) / m, 0.0, 1.0);
    }
    return vec3<f32>(1.0 / c, 0.0, 1.0);
}

";

/// Rust's `log_weight_of_square` and `log_weights_4d`: the weights `(g0, g4)` of
/// `log = g0 P + g4 P I` for a four-dimensional rotor `c0 + P + c4 I` with
/// `P P = p0 + p4 I` and `I I = iota` (-1: one complex channel; 0: dual numbers, as PGA).
/// WGSL has no `log1p`: `ga_log1p` is the exact-ratio form `log(u) x / (u - 1)`.
const LOG_WEIGHTS_4D: &str = "\
fn ga_log_weight_of_square(c: f32, p2: f32) -> f32 {
    if (p2 < 0.0) {
        let m = sqrt(-p2);
        return atan2(m, c) / m;
    } else if (p2 > 0.0) {
        let m = sqrt(p2);
        if (m < 1e-4) {
            return 1.0 - p2 / 6.0;
        }
        return asinh(m) / m;
    }
    return 1.0 / c;
}

fn ga_log1p(x: f32) -> f32 {
    let u = 1.0 + x;
    if (u == 1.0) {
        return x;
    }
    return log(u) * (x / (u - 1.0));
}

fn ga_log_weights_4d(c0: f32, c4: f32, p0: f32, p4: f32, iota: f32) -> vec2<f32> {
    if (iota < 0.0) {
        let modulus = sqrt(p0 * p0 + p4 * p4);
        if (modulus == 0.0) {
            return vec2<f32>(1.0, 0.0);
        }
        let sr = sqrt(max((modulus + p0) / 2.0, 0.0));
        let si_size = sqrt(max((modulus - p0) / 2.0, 0.0));
        let si = select(si_size, -si_size, p4 < 0.0);
        let dr = c0 + 1.0;
        let di = c4;
        let dd = dr * dr + di * di;
        let qr = (p0 * dr + p4 * di) / dd;
        let qi = (p4 * dr - p0 * di) / dd;
        let ur = qr + sr;
        let ui = qi + si;
        let yr = 0.5 * ga_log1p(2.0 * ur + ur * ur + ui * ui);
        let yi = atan2(ui, 1.0 + ur);
        let ss = sr * sr + si * si;
        return vec2<f32>((yr * sr + yi * si) / ss, (yi * sr - yr * si) / ss);
    }
    let g0 = ga_log_weight_of_square(c0, p0);
    var h = -1.0 / 3.0;
    if (abs(p0) < 1e-12) {
        h = -1.0 / 3.0;
    } else if (p0 < 0.0) {
        let m = sqrt(-p0);
        let theta = atan2(m, c0);
        h = (theta * c0 - m) / (m * m * m);
    } else {
        let m = sqrt(p0);
        let y = asinh(m);
        h = (m - y * c0) / (m * m * m);
    }
    return vec2<f32>(g0, c4 * h);
}

";

fn grade_blades(plan: &Plan, k: usize) -> Vec<Blade> {
    plan.types.get(TypeId::grade(k)).blades.clone()
}

/// `let` statements and a returned value as a WGSL function.
fn function(signature: &str, lets: &[String], value: &str) -> String {
    let mut out = format!("{signature} {{\n");
    for statement in lets {
        out.push_str(&format!("    {statement}\n"));
    }
    out.push_str(&format!("    return {value};\n}}\n\n"));
    out
}

/// The grade-`blade` part of `A A` as WGSL text.
fn self_square(plan: &Plan, operand: &Operand, blade: Blade) -> String {
    text(&quadratic_component(
        plan,
        operand,
        Involution::Identity,
        blade,
    ))
}

/// A WGSL value of type `t` whose component on each blade is `component(blade)`.
fn value(plan: &Plan, t: TypeId, component: impl FnMut(Blade) -> Option<TokenStream>) -> String {
    text(&construct_in(
        Syntax::Wgsl,
        plan,
        Output::Type(t),
        component,
    ))
}

/// `let unit = Quadvector(1.0); let dual = of * unit;` and the two channels
/// `plus = (of + dual) / 2`, `minus = (of - dual) / 2` (Rust's `channels`).
fn channels(plan: &Plan, of: &str) -> Vec<String> {
    let bivector = TypeId::grade(2);
    let of_operand = Operand::new(of.parse().unwrap_or_default(), bivector);
    let unit = Operand::new(quote!(unit), TypeId::grade(4));
    let (dual, _) = product_value_in(
        Syntax::Wgsl,
        plan,
        ProductKind::Geometric,
        &of_operand,
        &unit,
    );
    let half = |op: TokenStream| {
        value(plan, bivector, |blade| {
            let f = crate::emit::expr::field_ident(blade);
            let o: TokenStream = of.parse().unwrap_or_default();
            Some(quote!((#o.#f #op dual.#f) * 0.5))
        })
    };
    vec![
        "let unit = Quadvector(1.0);".to_owned(),
        format!("let dual = {};", text(&dual)),
        format!("let plus = {};", half(quote!(+))),
        format!("let minus = {};", half(quote!(-))),
    ]
}

/// `exp_bivector(a: Bivector) -> Even`.
fn exp_bivector(plan: &Plan, form: ExpLogForm) -> String {
    let n = plan.metric.dimension();
    let even = TypeId::even(n);
    let bivector = TypeId::grade(2);
    let b = Operand::new(quote!(a), bivector);
    let signature = "fn exp_bivector(a: Bivector) -> Even";
    match form {
        ExpLogForm::Plane => {
            // B B = x, a scalar: exp(B) = cosh(sqrt x) + B sinh(sqrt x) / sqrt x.
            let result = value(plan, even, |blade| {
                if blade == 0 {
                    return Some(quote!(w.x));
                }
                b.blade(plan, blade).map(|c| quote!(w.y * #c))
            });
            let lets = vec![
                format!("let x = {};", self_square(plan, &b, 0)),
                "let w = ga_cosh_sinhc(x, sqrt(abs(x)));".to_owned(),
            ];
            function(signature, &lets, &result)
        }
        ExpLogForm::Channels => {
            let pseudoscalar = plan.metric.pseudoscalar();
            let plus = Operand::new(quote!(plus), bivector);
            let minus = Operand::new(quote!(minus), bivector);
            let mut lets = channels(plan, "a");
            // A channel's own angle is sqrt(2) times the root of its scalar square.
            lets.push(format!("let xp = {};", self_square(plan, &plus, 0)));
            lets.push(format!("let xm = {};", self_square(plan, &minus, 0)));
            lets.push("let wp = ga_cosh_sinhc(xp, 1.4142135623730951 * sqrt(abs(xp)));".into());
            lets.push("let wm = ga_cosh_sinhc(xm, 1.4142135623730951 * sqrt(abs(xm)));".into());
            let result = value(plan, even, |blade| {
                if blade == 0 {
                    return Some(quote!((wp.x + wm.x) * 0.5));
                }
                if blade == pseudoscalar {
                    return Some(quote!((wp.x - wm.x) * 0.5));
                }
                let f = crate::emit::expr::field_ident(blade);
                Some(quote!(wp.y * plus.#f + wm.y * minus.#f))
            });
            function(signature, &lets, &result)
        }
        ExpLogForm::Quartic => {
            // B B = s + Q, Q = B ^ B commuting with B and Q Q = t a scalar.
            let q = Operand::new(quote!(q), TypeId::grade(4));
            let q_value = value(plan, TypeId::grade(4), |blade| {
                Some(quadratic_component(plan, &b, Involution::Identity, blade))
            });
            let (bq, bq_output) =
                product_value_in(Syntax::Wgsl, plan, ProductKind::Geometric, &b, &q);
            let bq_operand = match bq_output {
                Output::Type(id) => Some(Operand::new(quote!(bq), id)),
                Output::Zero => None,
            };
            let mut lets = vec![
                format!("let s = {};", self_square(plan, &b, 0)),
                format!("let q = {q_value};"),
                format!("let t = {};", self_square(plan, &q, 0)),
                "let w = ga_exp_weights(s, t);".to_owned(),
            ];
            if bq_operand.is_some() {
                lets.push(format!("let bq = {};", text(&bq)));
            }
            let result = value(plan, even, |blade| {
                let mut parts = Vec::new();
                if blade == 0 {
                    parts.push(quote!(w.x));
                }
                if let Some(c) = b.blade(plan, blade) {
                    parts.push(quote!(w.z * #c));
                }
                if let Some(c) = q.blade(plan, blade) {
                    parts.push(quote!(w.y * #c));
                }
                if let Some(c) = bq_operand.as_ref().and_then(|o| o.blade(plan, blade)) {
                    parts.push(quote!(w.w * #c));
                }
                (!parts.is_empty()).then(|| quote!(#(#parts)+*))
            });
            function(signature, &lets, &result)
        }
        ExpLogForm::Series => unreachable!("WGSL has no series form of exp"),
    }
}

/// The bivector `log(-1)` turns in (Rust's `full_turn_plane`): the first basis bivector
/// that squares to -1.
fn full_turn_plane(plan: &Plan) -> Option<Blade> {
    grade_blades(plan, 2)
        .into_iter()
        .find(|&bl| plan.metric.geometric(bl, bl).0 < 0)
}

/// Rust's `log_past_right_angle` written in place: for `{c} < 0` and `{x} < 0`, the
/// bivector `{of}` divided by its largest rotation component into `var {d}` and the weight
/// `atan2(k |{of}|, {c}) / (k |{d}|)` into `var {w}` (which the caller declared), so that
/// `{w}.x * {d}` is the logarithm as the Rust computes it.
fn past_right_angle(plan: &Plan, [c, x, of, d, w, k]: [&str; 6]) -> Vec<String> {
    let blades = grade_blades(plan, 2);
    let names: Vec<String> = crate::emit::unary::nondegenerate(plan, TypeId::grade(2))
        .into_iter()
        .map(|i| format!("abs({of}.{})", crate::algebra::blade_name(blades[i])))
        .collect();
    let largest = names.iter().skip(1).fold(
        names.first().cloned().unwrap_or_else(|| "0.0".into()),
        |acc, n| format!("max({acc}, {n})"),
    );
    let divided = value(plan, TypeId::grade(2), |blade| {
        let f = crate::emit::expr::field_ident(blade);
        let o: TokenStream = of.parse().unwrap_or_default();
        Some(quote!(#o.#f / largest))
    });
    let d_operand = Operand::new(d.parse().unwrap_or_default(), TypeId::grade(2));
    vec![
        format!("var {d} = {of};"),
        format!("if ({c} < 0.0 && {x} < 0.0) {{"),
        format!("    let largest = {largest};"),
        format!("    {d} = {divided};"),
        format!(
            "    let root = {k} * sqrt(abs({}));",
            self_square(plan, &d_operand, 0)
        ),
        format!("    {w} = vec3<f32>(atan2(root * largest, {c}) / root, 0.0, 1.0);"),
        "}".to_owned(),
    ]
}

/// `struct Logarithm` and `log_even(a: Even) -> Logarithm`.
fn log_even(plan: &Plan, form: ExpLogForm) -> String {
    let n = plan.metric.dimension();
    let r = Operand::new(quote!(a), TypeId::even(n));
    let bivector = TypeId::grade(2);
    let p_value = value(plan, bivector, |blade| r.blade(plan, blade));
    let p = Operand::new(quote!(p), bivector);
    let fields: Vec<String> = grade_blades(plan, 2)
        .iter()
        .map(|&bl| crate::algebra::blade_name(bl))
        .collect();
    // The Rust's tolerance for f32: half the digits, sqrt(f32::EPSILON).
    let tolerance = f64::from(f32::EPSILON.sqrt());
    let zero = value(plan, bivector, |_| None);
    let fail = format!("return Logarithm({zero}, false);");
    let mut lets = vec![
        format!("let norm_squared = {};", text(&norm_squared_expr(plan, &r))),
        format!("if (!(abs(norm_squared - 1.0) <= {tolerance:e})) {{"),
        format!("    {fail}"),
        "}".to_owned(),
        format!("let p = {p_value};"),
    ];
    let turn = full_turn_plane(plan);
    let pseudoscalar = plan.metric.pseudoscalar();
    let log = match form {
        ExpLogForm::Plane => {
            lets.push(format!("let x = {};", self_square(plan, &p, 0)));
            lets.push(format!(
                "var w = ga_log_weight(a.s, x, sqrt(abs(x)), {});",
                fields
                    .iter()
                    .map(|f| format!("p.{f} == 0.0"))
                    .collect::<Vec<_>>()
                    .join(" && ")
            ));
            lets.extend(past_right_angle(plan, ["a.s", "x", "p", "d", "w", "1.0"]));
            // Without a plane that squares to -1, -1 is no exponential: no logarithm.
            let no_plane = if turn.is_none() { " || w.y != 0.0" } else { "" };
            lets.push(format!("if (w.z == 0.0{no_plane}) {{"));
            lets.push(format!("    {fail}"));
            lets.push("}".to_owned());
            value(plan, bivector, |blade| {
                let f = crate::emit::expr::field_ident(blade);
                Some(if Some(blade) == turn {
                    quote!(w.x * d.#f + w.y)
                } else {
                    quote!(w.x * d.#f)
                })
            })
        }
        ExpLogForm::Channels => {
            let c4 = r
                .blade(plan, pseudoscalar)
                .map_or("0.0".to_owned(), |c| text(&c));
            lets.extend(channels(plan, "p"));
            let plus = Operand::new(quote!(plus), bivector);
            let minus = Operand::new(quote!(minus), bivector);
            lets.push(format!("let cp = a.s + {c4};"));
            lets.push(format!("let cm = a.s - {c4};"));
            lets.push(format!("let xp = {};", self_square(plan, &plus, 0)));
            lets.push(format!("let xm = {};", self_square(plan, &minus, 0)));
            lets.push("let mp = 1.4142135623730951 * sqrt(abs(xp));".into());
            lets.push("let mm = 1.4142135623730951 * sqrt(abs(xm));".into());
            // R ~R = 1 is each channel's c^2 - sign(x) m^2 = 1.
            lets.push("let np = cp * cp - sign(xp) * mp * mp;".into());
            lets.push("let nm = cm * cm - sign(xm) * mm * mm;".into());
            lets.push(format!(
                "if (!(abs(np - 1.0) <= {tolerance:e} && abs(nm - 1.0) <= {tolerance:e})) {{"
            ));
            lets.push(format!("    {fail}"));
            lets.push("}".to_owned());
            let zero_test = |name: &str| {
                fields
                    .iter()
                    .map(|f| format!("{name}.{f} == 0.0"))
                    .collect::<Vec<_>>()
                    .join(" && ")
            };
            lets.push(format!(
                "var wp = ga_log_weight(cp, xp, mp, {});",
                zero_test("plus")
            ));
            lets.push(format!(
                "var wm = ga_log_weight(cm, xm, mm, {});",
                zero_test("minus")
            ));
            let root_2 = "1.4142135623730951";
            lets.extend(past_right_angle(
                plan,
                ["cp", "xp", "plus", "dp", "wp", root_2],
            ));
            lets.extend(past_right_angle(
                plan,
                ["cm", "xm", "minus", "dm", "wm", root_2],
            ));
            lets.push("if (wp.z == 0.0 || wm.z == 0.0) {".to_owned());
            lets.push(format!("    {fail}"));
            lets.push("}".to_owned());
            // The turn of each channel: pi (D +- D I) / 2, a unit angle in that channel.
            let turns: Vec<(Blade, f64, f64)> = match turn {
                Some(d) => {
                    let (sign, di) = plan.metric.geometric(d, pseudoscalar);
                    let signed = 0.5 * f64::from(sign);
                    vec![(d, 0.5, 0.5), (di, signed, -signed)]
                }
                None => Vec::new(),
            };
            value(plan, bivector, |blade| {
                let f = crate::emit::expr::field_ident(blade);
                let mut term = quote!(wp.x * dp.#f + wm.x * dm.#f);
                if let Some(&(_, tp, tm)) = turns.iter().find(|(b, _, _)| *b == blade) {
                    let (tp, tm) = (float(tp), float(tm));
                    term = quote!(#term + #tp * wp.y + #tm * wm.y);
                }
                Some(term)
            })
        }
        ExpLogForm::Quartic => {
            let c4 = r
                .blade(plan, pseudoscalar)
                .map_or("0.0".to_owned(), |c| text(&c));
            let iota = plan.metric.pseudoscalar_square();
            let unit = Operand::new(quote!(unit), TypeId::grade(4));
            let (p_unit, _) =
                product_value_in(Syntax::Wgsl, plan, ProductKind::Geometric, &p, &unit);
            lets.push(format!("let p0 = {};", self_square(plan, &p, 0)));
            lets.push(format!("let p4 = {};", self_square(plan, &p, pseudoscalar)));
            lets.push(format!(
                "let g = ga_log_weights_4d(a.s, {c4}, p0, p4, {:.1});",
                f64::from(iota)
            ));
            lets.push("let unit = Quadvector(1.0);".to_owned());
            lets.push(format!("let p_unit = {};", text(&p_unit)));
            value(plan, bivector, |blade| {
                let f = crate::emit::expr::field_ident(blade);
                Some(quote!(g.x * p.#f + g.y * p_unit.#f))
            })
        }
        ExpLogForm::Series => unreachable!("the plan has no log above four dimensions"),
    };
    lets.push(format!("let log = {log};"));
    // The Rust's finiteness check; a driver that assumes no infinities or NaNs may drop it.
    let finite: Vec<String> = fields
        .iter()
        .map(|f| format!("abs(log.{f}) <= 3.4e38"))
        .collect();
    lets.push(format!("if (!({})) {{", finite.join(" && ")));
    lets.push(format!("    {fail}"));
    lets.push("}".to_owned());
    let mut out = String::from(
        "// log_even's result: `value` is the logarithm when `ok`, the zero bivector when\n\
         // the Rust `Even::log` returns None.\n\
         struct Logarithm {\n    value: Bivector,\n    ok: bool,\n}\n\n",
    );
    out.push_str(&function(
        "fn log_even(a: Even) -> Logarithm",
        &lets,
        "Logarithm(log, true)",
    ));
    out
}
