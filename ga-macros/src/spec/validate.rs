use std::collections::BTreeSet;

use proc_macro2::{Span, TokenStream, TokenTree};
use syn::{Attribute, Ident, Visibility};

use super::ctxt::Ctxt;
use super::parse::{
    RawEntry, RawIntegrations, RawLanes, RawMetric, RawOps, RawSignature, RawTypes,
};
use crate::algebra::{parse_blade, Blade, Metric};

/// The largest dimension the generator accepts: G6 already has 4,096 terms in one full
/// product, and each dimension more multiplies the emitted code by four.
pub const MAX_DIMENSION: usize = 6;

/// A validated request: everything the back end needs, and nothing it must re-check.
pub struct Spec {
    pub attrs: Vec<Attribute>,
    pub vis: Visibility,
    pub name: Ident,
    pub metric: Metric,
    pub scalar: Scalar,
    /// A scalar type other than `f32`/`f64` (`scalar: num_dual::Dual64`): the module is
    /// planned and written for `f64`, then rewritten for this type (see `emit::generic`),
    /// which must implement `ga_core::Scalar`. `scalar` is then `F64`.
    pub generic_scalar: Option<syn::Path>,
    pub types: Option<Vec<TypeRequest>>,
    pub ops: Option<BTreeSet<Op>>,
    /// Lane counts of the structure-of-arrays batch modules (`x4`, `x8`).
    pub lanes: Vec<usize>,
    /// Whether SIMD bodies may be written (`simd: false` keeps every body scalar, and the
    /// module free of `unsafe`).
    pub simd: bool,
    /// Where the square root and the transcendental functions come from.
    pub math: Math,
    /// The `ops` entries as written, to point at one whose method cannot be emitted.
    pub op_idents: Vec<Ident>,
    /// The names of the new types (`Name = [e12]`) as written, in order, to point at one
    /// whose WGSL names collide with another's.
    // Without the `wgsl` feature nothing reads it.
    #[cfg_attr(not(feature = "wgsl"), allow(dead_code))]
    pub type_idents: Vec<Ident>,
    /// Trait impls for other crates' traits (`derive: [serde, bytemuck, approx, mint]`).
    pub integrations: Vec<Integration>,
    /// Shader modules to emit beside the Rust (`shaders: [wgsl]`): the `#[cfg(..)]`
    /// attributes of each `wgsl` entry (one entry at most).
    // Without the `wgsl` feature nothing reads it: validation refuses a `wgsl` entry then.
    #[cfg_attr(not(feature = "wgsl"), allow(dead_code))]
    pub wgsl: Option<Vec<Attribute>>,
}

/// The optional back ends a build of ga-macros carries, one cargo feature each, so that a
/// user compiles only what their specs use; a spec that needs one that is off gets one
/// error at its token naming the feature, not code.
#[derive(Clone, Copy)]
pub struct BackEnds {
    /// `shaders: [wgsl]` (`emit/wgsl/`, feature `wgsl`).
    pub wgsl: bool,
    /// A scalar type other than `f32`/`f64` (`emit/generic.rs`, feature `generic`).
    pub generic_scalar: bool,
}

impl BackEnds {
    /// The back ends compiled into this build.
    pub const COMPILED: BackEnds = BackEnds {
        wgsl: cfg!(feature = "wgsl"),
        generic_scalar: cfg!(feature = "generic"),
    };
}

// How to turn on a missing back end: through ga-core, which most users depend on, or on
// ga-macros itself.
/// The error for `shaders: [wgsl]` without the `wgsl` feature.
const WGSL_MISSING: &str = "`shaders: [wgsl]` needs ga-macros' `wgsl` feature: enable \
     ga-core's `wgsl` feature (or ga-macros' `wgsl` feature where ga-macros is a direct \
     dependency)";
/// The error for a generic scalar without the `generic` feature.
const GENERIC_MISSING: &str = "a scalar type other than f32/f64 needs ga-macros' `generic` \
     feature: enable ga-core's `dual` feature (or ga-macros' `generic` feature where \
     ga-macros is a direct dependency)";

/// The floating-point backend of the emitted `math` module (`math: ...`).
pub enum Math {
    /// `std`'s inherent methods (the default).
    Std,
    /// The `libm` crate at this path (`::libm` unless given): for `no_std` crates.
    Libm(syn::Path),
    /// `std`'s methods when the calling crate's `std` feature is on, `libm` at this path
    /// otherwise (the crate must declare a `std` feature).
    Auto(syn::Path),
}

/// A crate whose traits or types the generated types implement or convert to.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IntegrationKind {
    Serde,
    Bytemuck,
    Approx,
    Mint,
}

impl IntegrationKind {
    const NAMES: [(&'static str, IntegrationKind); 4] = [
        ("serde", IntegrationKind::Serde),
        ("bytemuck", IntegrationKind::Bytemuck),
        ("approx", IntegrationKind::Approx),
        ("mint", IntegrationKind::Mint),
    ];

    fn from_name(name: &str) -> Option<IntegrationKind> {
        Self::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(_, kind)| kind)
    }
}

/// One entry of `derive: [...]`: which crate, the path its items are reached by in the
/// user's crate, and the `#[cfg(..)]` attributes that gate the impls.
pub struct Integration {
    pub kind: IntegrationKind,
    /// `::serde` (spanned at the user's `serde`, so a missing dependency is reported
    /// there) or the path written after `=`.
    pub path: TokenStream,
    pub cfgs: Vec<Attribute>,
    /// The entry's name as the user wrote it, where a missing crate is reported.
    pub span: Span,
}

/// The scalar type of the algebra.
#[derive(Clone, Copy, PartialEq, Eq)]
pub enum Scalar {
    F32,
    F64,
}

/// One entry of a `types: [...]` list.
#[derive(Clone, PartialEq, Eq)]
pub enum TypeRequest {
    /// A grade 1..=n.
    Grade(usize),
    /// `Even` or `Rotor`.
    Even,
    /// `Odd`.
    Odd,
    /// `Multivector`.
    Multivector,
    /// `Name = [e12, e13]`: a struct with exactly these components.
    User { name: String, blades: Vec<Blade> },
}

/// The operations that an `ops: [...]` list can name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Op {
    Geometric,
    Outer,
    Inner,
    LeftContraction,
    RightContraction,
    ScalarProduct,
    Commutator,
    Regressive,
    Add,
    Reverse,
    GradeInvolution,
    Conjugate,
    Dual,
    Norm,
    Inverse,
    Grade,
    Sandwich,
    Reflect,
    Exp,
    Log,
    Factor,
}

impl Op {
    const NAMES: [(&'static str, Op); 21] = [
        ("geometric", Op::Geometric),
        ("outer", Op::Outer),
        ("inner", Op::Inner),
        ("left_contraction", Op::LeftContraction),
        ("right_contraction", Op::RightContraction),
        ("scalar_product", Op::ScalarProduct),
        ("commutator", Op::Commutator),
        ("regressive", Op::Regressive),
        ("add", Op::Add),
        ("reverse", Op::Reverse),
        ("grade_involution", Op::GradeInvolution),
        ("conjugate", Op::Conjugate),
        ("dual", Op::Dual),
        ("norm", Op::Norm),
        ("inverse", Op::Inverse),
        ("grade", Op::Grade),
        ("sandwich", Op::Sandwich),
        ("reflect", Op::Reflect),
        ("exp", Op::Exp),
        ("log", Op::Log),
        ("factor", Op::Factor),
    ];

    /// Every operation, in the order of `NAMES`.
    pub const ALL: [Op; 21] = {
        let mut all = [Op::Geometric; 21];
        let mut i = 0;
        while i < 21 {
            all[i] = Op::NAMES[i].1;
            i += 1;
        }
        all
    };

    fn from_name(name: &str) -> Option<Op> {
        Op::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|&(_, op)| op)
    }

    fn expected() -> String {
        Op::NAMES
            .iter()
            .map(|(n, _)| *n)
            .collect::<Vec<_>>()
            .join(", ")
    }

    /// The operations whose emitted code this one calls.
    pub fn needs(self) -> &'static [Op] {
        match self {
            Op::Inverse => &[Op::Reverse, Op::Norm, Op::Geometric],
            Op::Reflect => &[Op::Sandwich, Op::Norm],
            Op::Factor => &[Op::Geometric, Op::Outer, Op::LeftContraction, Op::Inverse],
            _ => &[],
        }
    }
}

const KEYS: &str = "metric, signature, scalar, types, ops, lanes, simd, math, derive, shaders";

const GRADE_NAMES: [&str; MAX_DIMENSION] = [
    "Vector",
    "Bivector",
    "Trivector",
    "Quadvector",
    "Pentavector",
    "Hexavector",
];

/// The struct name of grade `k` (1-based).
pub fn grade_type_name(k: usize) -> &'static str {
    GRADE_NAMES[k - 1]
}

/// Whether `path` names a primitive type other than f32/f64 (`i32`, `f16`, `bool`, ...).
fn is_primitive(path: &syn::Path) -> bool {
    const PRIMITIVES: [&str; 17] = [
        "i8", "i16", "i32", "i64", "i128", "isize", "u8", "u16", "u32", "u64", "u128", "usize",
        "f16", "f128", "bool", "char", "str",
    ];
    path.get_ident()
        .is_some_and(|ident| PRIMITIVES.iter().any(|p| ident == p))
}

/// Checks the raw entries and builds the [`Spec`], reporting every problem at once.
pub fn validate(
    attrs: Vec<Attribute>,
    vis: Visibility,
    name: Ident,
    entries: Vec<RawEntry>,
) -> syn::Result<Spec> {
    validate_for(BackEnds::COMPILED, attrs, vis, name, entries)
}

/// [`validate`] for a build with the given back ends (the tests try both settings).
pub fn validate_for(
    back_ends: BackEnds,
    attrs: Vec<Attribute>,
    vis: Visibility,
    name: Ident,
    entries: Vec<RawEntry>,
) -> syn::Result<Spec> {
    let mut cx = Ctxt::default();
    let mut seen: Vec<Ident> = Vec::new();
    let (mut metric, mut signature, mut scalar, mut types, mut ops) =
        (None, None, None, None, None);
    let mut lanes: Option<RawLanes> = None;
    let mut simd = true;
    let mut math = Math::Std;
    let mut integrations: Option<RawIntegrations> = None;
    let mut shaders: Option<RawIntegrations> = None;
    let mut generic_scalar: Option<syn::Path> = None;
    for entry in entries {
        let key = entry.key.to_string();
        if seen.contains(&entry.key) {
            cx.error_spanned_by(
                &entry.key,
                format!("duplicate key `{key}`: give each key once"),
            );
            continue;
        }
        seen.push(entry.key.clone());
        let value = entry.value;
        match key.as_str() {
            "metric" | "signature" if seen.iter().any(|k| *k != entry.key && is_metric_key(k)) => {
                cx.error_spanned_by(
                    &entry.key,
                    "give either `metric` or `signature`, not both: remove one of them",
                );
            }
            "metric" => match syn::parse2::<RawMetric>(value) {
                Ok(raw) => metric = Some((entry.key, raw)),
                Err(e) => cx.syn_error(e),
            },
            "signature" => match syn::parse2::<RawSignature>(value) {
                Ok(raw) => signature = Some((entry.key, raw)),
                Err(e) => cx.syn_error(e),
            },
            "scalar" => match syn::parse2::<Ident>(value.clone()) {
                Ok(ident) if ident == "f64" => scalar = Some(Scalar::F64),
                Ok(ident) if ident == "f32" => scalar = Some(Scalar::F32),
                _ => match syn::parse2::<syn::Path>(value.clone()) {
                    // Any other type path: a generic scalar, written as f64 and rewritten
                    // (not another primitive: those have no derivative parts to carry and
                    // no `ga_core::Scalar`).
                    Ok(path) if !is_primitive(&path) => {
                        if !back_ends.generic_scalar {
                            cx.error_spanned_by(&path, GENERIC_MISSING);
                        }
                        scalar = Some(Scalar::F64);
                        generic_scalar = Some(path);
                    }
                    _ => cx.error_spanned_by(
                        value.clone(),
                        format!(
                            "unsupported scalar type `{value}`: expected f32, f64 or a type \
                             path implementing `ga_core::Scalar`"
                        ),
                    ),
                },
            },
            "types" => match syn::parse2::<RawTypes>(value) {
                Ok(raw) => types = Some(raw),
                Err(e) => cx.syn_error(e),
            },
            "ops" => match syn::parse2::<RawOps>(value) {
                Ok(raw) => ops = Some(raw),
                Err(e) => cx.syn_error(e),
            },
            "lanes" => match syn::parse2::<RawLanes>(value) {
                Ok(raw) => lanes = Some(raw),
                Err(e) => cx.syn_error(e),
            },
            "simd" => match syn::parse2::<syn::LitBool>(value.clone()) {
                Ok(flag) => simd = flag.value,
                Err(_) => cx.error_spanned_by(
                    value.clone(),
                    format!("`simd` takes `true` or `false`, not `{value}`"),
                ),
            },
            "math" => match check_math(value) {
                Ok(backend) => math = backend,
                Err(e) => cx.syn_error(e),
            },
            "derive" => match syn::parse2::<RawIntegrations>(value) {
                Ok(raw) => integrations = Some(raw),
                Err(e) => cx.syn_error(e),
            },
            // The same list syntax as `derive`: names, each with optional `#[cfg(..)]`s.
            "shaders" => match syn::parse2::<RawIntegrations>(value) {
                Ok(raw) => shaders = Some(raw),
                Err(e) => cx.syn_error(e),
            },
            _ => cx.error_spanned_by(
                &entry.key,
                format!("unknown key `{key}`: expected one of {KEYS}"),
            ),
        }
    }

    let squares = match (metric, signature) {
        (Some((_, raw)), None) => check_metric(&mut cx, raw),
        (None, Some((_, raw))) => check_signature(&mut cx, raw),
        // Both given, or given but malformed: already reported at the key or value.
        _ if seen.iter().any(is_metric_key) => None,
        _ => {
            cx.error_spanned_by(
                &name,
                "missing `metric`: give the squares of e1..en, e.g. `metric: [1, 1, 1]`, \
                 or `signature: (p, q, r)`",
            );
            None
        }
    };
    let mut type_idents = Vec::new();
    let types = match (&squares, types) {
        (Some(squares), Some(raw)) => {
            Some(check_types(&mut cx, squares.len(), raw, &mut type_idents))
        }
        _ => None,
    };
    let op_idents: Vec<Ident> = ops.as_ref().map(|raw| raw.0.clone()).unwrap_or_default();
    let ops = ops.map(|raw| check_ops(&mut cx, raw));
    let scalar = scalar.unwrap_or(Scalar::F64);
    let lanes = lanes
        .map(|raw| check_lanes(&mut cx, scalar, raw))
        .unwrap_or_default();
    let integrations = integrations
        .map(|raw| check_integrations(&mut cx, squares.as_deref(), raw))
        .unwrap_or_default();
    let wgsl = shaders.and_then(|raw| check_shaders(&mut cx, back_ends, raw));
    if wgsl.is_some() {
        for ident in &type_idents {
            let name = ident.to_string();
            if WGSL_RESERVED_TYPE_NAMES.contains(&name.as_str()) {
                cx.error_spanned_by(
                    ident,
                    format!(
                        "`{name}` is a name the WGSL module defines or WGSL predeclares \
                         (`Logarithm` is what `log_even` returns): give the new type another \
                         name"
                    ),
                );
            }
        }
    }
    if let Some(path) = &generic_scalar {
        // The generic path is the scalar code: no batch lanes, no SIMD, no other crates'
        // traits (their impls assume a float).
        if !lanes.is_empty() || !integrations.is_empty() {
            cx.error_spanned_by(
                path,
                "a scalar type other than f32/f64 takes no `lanes` and no `derive`: \
                 remove them",
            );
        }
        simd = false;
    }
    cx.check()?;
    let Some(squares) = squares else {
        return Err(syn::Error::new(
            Span::call_site(),
            "internal: metric missing after checks",
        ));
    };
    Ok(Spec {
        attrs,
        vis,
        name,
        metric: Metric::new(squares),
        scalar,
        generic_scalar,
        types,
        ops,
        lanes,
        simd,
        math,
        op_idents,
        type_idents,
        integrations,
        wgsl,
    })
}

/// `shaders: [wgsl]` (optionally `#[cfg(..)] wgsl`): the `cfg`s of the one `wgsl` entry.
fn check_shaders(
    cx: &mut Ctxt,
    back_ends: BackEnds,
    raw: RawIntegrations,
) -> Option<Vec<Attribute>> {
    let mut wgsl = None;
    for entry in raw.0 {
        if entry.name != "wgsl" || entry.path.is_some() {
            cx.error_spanned_by(
                &entry.name,
                format!("unknown shader language `{}`: expected `wgsl`", entry.name),
            );
            continue;
        }
        if wgsl.is_some() {
            cx.error_spanned_by(
                &entry.name,
                "`wgsl` is listed twice in `shaders`: list it once",
            );
            continue;
        }
        if let Some(attr) = entry.attrs.iter().find(|a| !a.path().is_ident("cfg")) {
            cx.error_spanned_by(
                attr,
                "only `#[cfg(..)]` may gate a shader entry, e.g. `#[cfg(feature = \"wgsl\")] wgsl`",
            );
            continue;
        }
        if !back_ends.wgsl {
            cx.error_spanned_by(&entry.name, WGSL_MISSING);
        }
        wgsl = Some(entry.attrs);
    }
    wgsl
}

/// Operations listed in `ops` whose methods the planned module cannot carry: `exp` is a
/// method of `Bivector` and `log` of `Even`, so listing them without those types (or in a
/// dimension without a closed form) would make them disappear silently.
pub fn check_emitted(spec: &Spec, has_bivector: bool, has_even: bool) -> syn::Result<()> {
    let n = spec.metric.dimension();
    let mut cx = Ctxt::default();
    for ident in &spec.op_idents {
        if ident == "exp" {
            if n < 2 {
                cx.error_spanned_by(
                    ident,
                    "`exp` needs bivectors, which a one-dimensional algebra does not have: \
                     remove `exp`",
                );
            } else if !has_bivector {
                cx.error_spanned_by(
                    ident,
                    "`exp` is a method of `Bivector`, which `types` leaves out: add `Bivector` \
                     to `types` (its result type `Even` comes with it)",
                );
            }
        } else if ident == "log" {
            if !(2..=4).contains(&n) {
                cx.error_spanned_by(
                    ident,
                    format!(
                        "`log` is emitted for dimensions 2 to 4 only, and this algebra has {n}: \
                         remove `log`"
                    ),
                );
            } else if !has_even {
                cx.error_spanned_by(
                    ident,
                    "`log` is a method of `Even`, which `types` leaves out: add `Even` (or \
                     `Rotor`) to `types` (its result type `Bivector` comes with it)",
                );
            }
        }
    }
    cx.check()
}

/// `shaders: [wgsl]`: refuses a new type whose WGSL function names are another's (WGSL
/// has no overloading, and its names carry the operand types in snake case, so `X` with
/// `SquaredX` both give `norm_squared_x`, and `PlaneA` with `Plane_a` every function).
/// `collisions` holds each such name with the parameter types of each function taking it;
/// the error is at the last-listed new type that only some of them take, once per type.
#[cfg(feature = "wgsl")]
pub fn check_wgsl_names(spec: &Spec, collisions: &[(String, Vec<Vec<String>>)]) -> syn::Result<()> {
    let mut cx = Ctxt::default();
    let mut blamed: Vec<&Ident> = Vec::new();
    for (function, overloads) in collisions {
        let in_all = |ty: &str| overloads.iter().all(|o| o.iter().any(|t| t == ty));
        let culprit = spec.type_idents.iter().rev().find(|ident| {
            let name = ident.to_string();
            overloads.iter().any(|o| o.contains(&name)) && !in_all(&name)
        });
        let Some(culprit) = culprit else {
            continue;
        };
        if blamed.contains(&culprit) {
            continue;
        }
        blamed.push(culprit);
        let signatures = overloads
            .iter()
            .map(|o| format!("`{function}({})`", o.join(", ")))
            .collect::<Vec<_>>()
            .join(" and ");
        cx.error_spanned_by(
            culprit,
            format!(
                "with `shaders: [wgsl]`, `{culprit}` gives the WGSL function name \
                 `{function}` to two functions ({signatures}), and WGSL has no overloading: \
                 rename the type"
            ),
        );
    }
    cx.check()
}

/// `math: std`, `math: libm`, `math: libm(path)` or `math: auto(path)`.
fn check_math(value: proc_macro2::TokenStream) -> syn::Result<Math> {
    use syn::parse::Parser;
    let parser = |input: syn::parse::ParseStream| {
        let backend: Ident = input.parse()?;
        let path = if input.peek(syn::token::Paren) {
            let content;
            syn::parenthesized!(content in input);
            Some(content.parse::<syn::Path>()?)
        } else {
            None
        };
        if !input.is_empty() {
            return Err(input.error("expected `std`, `libm`, `libm(path)` or `auto(path)`"));
        }
        Ok((backend, path))
    };
    let (backend, path) = parser.parse2(value)?;
    let libm = || syn::parse_quote!(::libm);
    match (backend.to_string().as_str(), path) {
        ("std", None) => Ok(Math::Std),
        ("std", Some(path)) => Err(syn::Error::new_spanned(
            path,
            "`math: std` takes no path: write `math: std`, or `math: libm(path)`",
        )),
        ("libm", path) => Ok(Math::Libm(path.unwrap_or_else(libm))),
        ("auto", path) => Ok(Math::Auto(path.unwrap_or_else(libm))),
        (other, _) => Err(syn::Error::new_spanned(
            &backend,
            format!(
                "unknown math backend `{other}`: expected `std` (the default), `libm` or \
                 `libm(path)` for no_std crates, or `auto(path)` (std with the crate's `std` \
                 feature, libm at `path` without it)"
            ),
        )),
    }
}

fn is_metric_key(key: &Ident) -> bool {
    key == "metric" || key == "signature"
}

/// The value of a metric entry written as `1`, `-1` or `0` (a plain decimal literal, with
/// no suffix, no radix and one sign at most); `None` for anything else.
fn metric_entry(entry: &TokenStream) -> Option<i8> {
    let tokens: Vec<TokenTree> = entry.clone().into_iter().collect();
    let (negative, literal) = match tokens.as_slice() {
        [TokenTree::Literal(lit)] => (false, lit),
        [TokenTree::Punct(minus), TokenTree::Literal(lit)] if minus.as_char() == '-' => (true, lit),
        _ => return None,
    };
    let value: i8 = match literal.to_string().as_str() {
        "0" => 0,
        "1" => 1,
        _ => return None,
    };
    Some(if negative { -value } else { value })
}

fn check_dimension(cx: &mut Ctxt, span: Span, dimension: usize, counted_as: &str) -> bool {
    if (1..=MAX_DIMENSION).contains(&dimension) {
        return true;
    }
    cx.syn_error(syn::Error::new(
        span,
        format!("the dimension must be 1 to {MAX_DIMENSION}, found {dimension} ({counted_as})"),
    ));
    false
}

fn check_metric(cx: &mut Ctxt, raw: RawMetric) -> Option<Vec<i8>> {
    let mut squares = Vec::new();
    let mut ok = true;
    for entry in &raw.entries {
        match metric_entry(entry) {
            Some(v) => squares.push(v),
            None => {
                ok = false;
                // `[1, 1 1]`: a good entry with more after it lacks a comma.
                let tokens: Vec<TokenTree> = entry.clone().into_iter().collect();
                if let Some(extra) = (1..tokens.len())
                    .find(|&i| metric_entry(&tokens[..i].iter().cloned().collect()).is_some())
                {
                    cx.error_spanned_by(&tokens[extra], "expected `,`");
                    continue;
                }
                // As written: `TokenStream`'s `Display` would space `--1` as `- - 1`.
                let written: String = tokens.iter().map(ToString::to_string).collect();
                cx.error_spanned_by(
                    entry,
                    format!(
                        "metric entry `{written}` must be written 1, -1 or 0 (the square of \
                         its generator)"
                    ),
                );
            }
        }
    }
    (check_dimension(
        cx,
        raw.bracket,
        raw.entries.len(),
        "one generator per metric entry",
    ) && ok)
        .then_some(squares)
}

fn check_signature(cx: &mut Ctxt, raw: RawSignature) -> Option<Vec<i8>> {
    if raw.counts.len() != 3 {
        cx.syn_error(syn::Error::new(
            raw.paren,
            format!(
                "`signature` takes three counts (p, q, r): the generators that square to 1, \
                 -1 and 0, found {}",
                raw.counts.len()
            ),
        ));
        return None;
    }
    let mut counts = [0usize; 3];
    for (count, lit) in counts.iter_mut().zip(&raw.counts) {
        if !lit.to_string().bytes().all(|b| b.is_ascii_digit()) {
            cx.error_spanned_by(
                lit,
                format!("signature count `{lit}` must be a plain decimal count, e.g. `3`"),
            );
            return None;
        }
        match lit.base10_parse() {
            Ok(v) => *count = v,
            Err(e) => {
                cx.syn_error(e);
                return None;
            }
        }
    }
    let [p, q, r] = counts;
    let dimension = p.saturating_add(q).saturating_add(r);
    if !check_dimension(cx, raw.paren, dimension, "p + q + r") {
        return None;
    }
    let mut squares = vec![1; p];
    squares.extend(vec![-1; q]);
    squares.extend(vec![0; r]);
    Some(squares)
}

/// Names a new type may not take, with why: a struct of one of these names would clash
/// with an item the module defines or shadow a name its code uses unqualified, and give
/// hundreds of errors inside the generated code instead of one here.
const RESERVED_TYPE_NAMES: [(&[&str], &str); 5] = [
    (
        &[
            "Sandwich",
            "SandwichUnit",
            "ScalarProduct",
            "LeftContraction",
            "RightContraction",
            "Regressive",
            "Commutator",
            "math",
            "simd",
        ],
        "an item the generated module defines",
    ),
    (
        &["Scalar"],
        "the name of the scalar operand in `TERM_COUNTS` and, in a module over a generic \
         scalar, of the module's scalar type",
    ),
    (
        &[
            "f16", "f32", "f64", "f128", "i8", "i16", "i32", "i64", "i128", "isize", "u8", "u16",
            "u32", "u64", "u128", "usize", "bool", "char", "str",
        ],
        "a primitive type, which the generated code names",
    ),
    (
        &[
            "Option",
            "Some",
            "None",
            "Result",
            "Ok",
            "Err",
            "Default",
            "Clone",
            "Copy",
            "Send",
            "Sync",
            "Sized",
            "PartialEq",
            "Eq",
            "PartialOrd",
            "Ord",
            "Iterator",
            "IntoIterator",
            "Extend",
            "From",
            "Into",
            "TryFrom",
            "TryInto",
            "AsRef",
            "AsMut",
            "Drop",
            "Fn",
            "FnMut",
            "FnOnce",
            "Box",
            "Vec",
            "String",
            "ToString",
            "ToOwned",
        ],
        "a name of Rust's prelude, which the generated code uses unqualified",
    ),
    (
        &["core", "std", "alloc", "ga_core"],
        "a crate the generated code names",
    ),
];

/// Names a new type may not take in a module with `shaders: [wgsl]`: the struct the WGSL
/// `log_even` returns, and WGSL's predeclared types that Rust does not have (one namespace
/// holds a WGSL module's types and functions).
const WGSL_RESERVED_TYPE_NAMES: [&str; 12] = [
    "Logarithm",
    "vec2",
    "vec3",
    "vec4",
    "mat2x2",
    "mat3x3",
    "mat4x4",
    "array",
    "atomic",
    "ptr",
    "sampler",
    "texture_2d",
];

/// Why `name` may not name a new type, if it may not.
fn reserved_type_name(name: &str) -> Option<&'static str> {
    RESERVED_TYPE_NAMES
        .iter()
        .find(|(names, _)| names.contains(&name))
        .map(|&(_, why)| why)
}

fn builtin(name: &str, dimension: usize) -> Option<TypeRequest> {
    match name {
        "Even" | "Rotor" => Some(TypeRequest::Even),
        "Odd" => Some(TypeRequest::Odd),
        "Multivector" => Some(TypeRequest::Multivector),
        "Pseudoscalar" => Some(TypeRequest::Grade(dimension)),
        _ => GRADE_NAMES[..dimension]
            .iter()
            .position(|n| *n == name)
            .map(|k| TypeRequest::Grade(k + 1)),
    }
}

fn check_types(
    cx: &mut Ctxt,
    dimension: usize,
    raw: RawTypes,
    user_idents: &mut Vec<Ident>,
) -> Vec<TypeRequest> {
    let mut requests: Vec<TypeRequest> = Vec::new();
    let mut names: Vec<String> = Vec::new();
    for request in raw.0 {
        let name = request.name.to_string();
        if names.contains(&name) {
            cx.error_spanned_by(
                &request.name,
                format!("type `{name}` is listed twice: list each type once"),
            );
            continue;
        }
        names.push(name.clone());
        match request.blades {
            None => match builtin(&name, dimension) {
                // `Rotor` is `Even`, and `Pseudoscalar` the top grade, under another name.
                Some(t) if requests.contains(&t) => {
                    let earlier = names
                        .iter()
                        .find(|n| builtin(n, dimension).as_ref() == Some(&t))
                        .cloned()
                        .unwrap_or_default();
                    cx.error_spanned_by(
                        &request.name,
                        format!(
                            "`{name}` is `{earlier}` under another name, and `types` lists \
                             `{earlier}` already: list it once"
                        ),
                    );
                }
                Some(t) => requests.push(t),
                None if GRADE_NAMES.contains(&name.as_str()) => cx.error_spanned_by(
                    &request.name,
                    format!(
                        "`{name}` needs more than {dimension} generators: the grades of this \
                         algebra are {}",
                        GRADE_NAMES[..dimension].join(", ")
                    ),
                ),
                None => cx.error_spanned_by(
                    &request.name,
                    format!(
                        "unknown type `{name}`: expected one of {}, Pseudoscalar, Even, Rotor, \
                         Odd, Multivector, or a new type `{name} = [e12, e13]`",
                        GRADE_NAMES[..dimension].join(", ")
                    ),
                ),
            },
            Some(blade_idents) => {
                if builtin(&name, MAX_DIMENSION).is_some() || name == "Zero" {
                    cx.error_spanned_by(
                        &request.name,
                        format!("`{name}` is a built-in type: give the new type another name"),
                    );
                    continue;
                }
                if let Some(why) = reserved_type_name(&name) {
                    cx.error_spanned_by(
                        &request.name,
                        format!("`{name}` is {why}: give the new type another name"),
                    );
                    continue;
                }
                let mut blades = Vec::new();
                for ident in &blade_idents {
                    match parse_blade(&ident.to_string(), dimension) {
                        Some(b) if blades.contains(&b) => cx.error_spanned_by(
                            ident,
                            format!(
                                "blade `{ident}` is repeated in `{name}`: list each blade once"
                            ),
                        ),
                        Some(b) => blades.push(b),
                        None => cx.error_spanned_by(ident, blade_problem(ident, dimension)),
                    }
                }
                if blade_idents.is_empty() {
                    cx.error_spanned_by(
                        &request.name,
                        format!(
                            "type `{name}` has no blades: list its components, \
                             e.g. `{name} = [e12, e13]`"
                        ),
                    );
                }
                user_idents.push(request.name.clone());
                requests.push(TypeRequest::User { name, blades });
            }
        }
    }
    requests
}

/// Why `ident` is not a blade name of a `dimension`-dimensional algebra.
fn blade_problem(ident: &Ident, dimension: usize) -> String {
    let name = ident.to_string();
    let indices: Option<Vec<u32>> = name
        .strip_prefix('e')
        .filter(|digits| !digits.is_empty())
        .and_then(|digits| digits.chars().map(|c| c.to_digit(10)).collect());
    let Some(mut indices) = indices else {
        return format!(
            "unknown blade `{name}`: write `s` or `e` followed by ascending indices from 1 to \
             {dimension}, e.g. `e12`"
        );
    };
    if let Some(&index) = indices.iter().find(|&&i| i == 0 || i as usize > dimension) {
        return format!(
            "blade `{name}` uses e{index}, but this algebra has only e1 to e{dimension}"
        );
    }
    indices.sort_unstable();
    if let Some(pair) = indices.windows(2).find(|pair| pair[0] == pair[1]) {
        return format!(
            "blade `{name}` repeats e{}: name each generator at most once, in ascending order",
            pair[0]
        );
    }
    let ascending: String = indices.iter().map(|i| i.to_string()).collect();
    format!(
        "blade `{name}` must list its indices in ascending order: write `e{ascending}` \
         (the same blade up to sign)"
    )
}

fn check_ops(cx: &mut Ctxt, raw: RawOps) -> BTreeSet<Op> {
    let mut ops = BTreeSet::new();
    for ident in raw.0 {
        match Op::from_name(&ident.to_string()) {
            Some(op) => {
                ops.insert(op);
            }
            None => cx.error_spanned_by(
                &ident,
                format!("unknown op `{ident}`: expected one of {}", Op::expected()),
            ),
        }
    }
    let mut pending: Vec<Op> = ops.iter().copied().collect();
    while let Some(op) = pending.pop() {
        for &need in op.needs() {
            if ops.insert(need) {
                pending.push(need);
            }
        }
    }
    ops
}

/// The lane counts `wide` has vector types for: f32x4, f32x8, f64x2, f64x4.
fn check_lanes(cx: &mut Ctxt, scalar: Scalar, raw: RawLanes) -> Vec<usize> {
    let allowed: &[usize] = match scalar {
        Scalar::F32 => &[4, 8],
        Scalar::F64 => &[2, 4],
    };
    let mut lanes = Vec::new();
    for lit in raw.0 {
        match lit.base10_parse::<usize>() {
            Ok(n) if lanes.contains(&n) => {
                cx.error_spanned_by(&lit, format!("lane count {n} is listed twice"))
            }
            Ok(n) if allowed.contains(&n) => lanes.push(n),
            _ => cx.error_spanned_by(
                &lit,
                format!(
                    "unsupported lane count `{lit}`: expected {} for this scalar type",
                    allowed
                        .iter()
                        .map(|n| n.to_string())
                        .collect::<Vec<_>>()
                        .join(" or ")
                ),
            ),
        }
    }
    lanes
}

/// `derive: [...]`: known crate names, each once, gated only by `#[cfg(..)]`; `mint`
/// only where its types mean something (G3's vectors, quaternions and 3x3 matrices).
fn check_integrations(
    cx: &mut Ctxt,
    squares: Option<&[i8]>,
    raw: RawIntegrations,
) -> Vec<Integration> {
    let mut out: Vec<Integration> = Vec::new();
    for entry in raw.0 {
        let name = entry.name.to_string();
        let Some(kind) = IntegrationKind::from_name(&name) else {
            cx.error_spanned_by(
                &entry.name,
                format!("unknown derive `{name}`: expected one of serde, bytemuck, approx, mint"),
            );
            continue;
        };
        if out.iter().any(|i| i.kind == kind) {
            cx.error_spanned_by(
                &entry.name,
                format!("`{name}` is listed twice in `derive`: list each crate once"),
            );
            continue;
        }
        if kind == IntegrationKind::Mint && squares.is_some_and(|s| s != [1, 1, 1]) {
            cx.error_spanned_by(
                &entry.name,
                "`mint` conversions (Vector3, Quaternion, ColumnMatrix3) exist only for \
                 Euclidean space, `metric: [1, 1, 1]`: remove `mint` here",
            );
            continue;
        }
        let mut ok = true;
        for attr in &entry.attrs {
            if !attr.path().is_ident("cfg") {
                ok = false;
                cx.error_spanned_by(
                    attr,
                    "only `#[cfg(..)]` may gate a derive entry, e.g. \
                     `#[cfg(feature = \"serde\")] serde`",
                );
            }
        }
        if !ok {
            continue;
        }
        let path = match entry.path {
            Some(path) => quote::quote!(#path),
            // Spanned at the user's token, so that a missing dependency is reported at it.
            None => {
                let ident = &entry.name;
                quote::quote_spanned!(ident.span()=> ::#ident)
            }
        };
        out.push(Integration {
            kind,
            path,
            cfgs: entry.attrs,
            span: entry.name.span(),
        });
    }
    out
}
