//! Generic scalars (`scalar: num_dual::Dual64`): the module is planned and written for
//! `f64` by the other emitters, unchanged, and this file rewrites the finished tokens for
//! the user's type, so that the f32/f64 code stays exactly what it was and no emitter has
//! to know about a third kind of scalar. The type must implement `ga_core::Scalar`.
//!
//! The rewrite, token by token:
//! - the type `f64` becomes the module's alias `Scalar` of the user's type (see
//!   [`rewrite`]; impl headers name the type itself); `f64::NAME` (`EPSILON`, `INFINITY`, `NAN`,
//!   `MIN_POSITIVE`, `MAX`) becomes `<S as Scalar>::NAME`; `f64::from(x)`,
//!   `::core::f64::consts::NAME` and `x as f64` are lifted with `Scalar::from_f64`;
//! - a float literal becomes `Scalar::ZERO`, `Scalar::ONE` (both usable in constants) or
//!   `Scalar::from_f64(literal)`;
//! - a constant item `const NAME: f64 = ...;` stays in `f64` (a generic type has no
//!   `const` constructor from a value), and each use of `NAME` is lifted;
//! - `Default` leaves the derive lists (a dual number need not have one) and each type
//!   gets a `Default` that is its `ZERO`.
//!
//! `x != 0.0` becomes `!Scalar::is_exact_zero(x)` (every part zero): such a guard skips
//! work for a zero multiplier, which must not drop a non-zero derivative.
//!
//! Other comparisons stay as written: the trait asks `PartialOrd` to compare real parts, so a
//! branch on a value (exp's series range, the scaled-norm test, the inverse's pivot)
//! takes the f64 code's path and the derivative parts follow it.

use proc_macro2::{Delimiter, Group, Literal, Punct, Spacing, TokenStream, TokenTree};
use quote::{format_ident, quote};

use crate::plan::Plan;

/// The trait every generic scalar implements, as the emitted code names it.
fn scalar_trait() -> TokenStream {
    quote!(::ga_core::Scalar)
}

/// `mod math` for a generic scalar: the trait's functions, under the names the kernels call
/// (written with `f64` like the rest and rewritten with it), and `SQUARE_MIN`/`SQUARE_MAX`.
pub fn emit_math() -> TokenStream {
    let tr = scalar_trait();
    let unary = ["sqrt", "sin", "cos", "cosh", "sinh", "asinh", "ln_1p"].map(|name| {
        let ident = format_ident!("{name}");
        quote! {
            #[inline]
            pub(super) fn #ident(x: f64) -> f64 {
                #tr::#ident(x)
            }
        }
    });
    quote! {
        /// The functions beyond arithmetic that this algebra calls, from its scalar type's
        /// `ga_core::Scalar` implementation.
        #[allow(dead_code)]
        mod math {
            #(#unary)*

            #[inline]
            pub(super) fn sin_cos(x: f64) -> (f64, f64) {
                #tr::sin_cos(x)
            }

            #[inline]
            pub(super) fn atan2(y: f64, x: f64) -> f64 {
                #tr::atan2(y, x)
            }

            #[inline]
            pub(super) fn hypot(x: f64, y: f64) -> f64 {
                #tr::hypot(x, y)
            }
        }

        /// A sum of squares at least this large lost nothing that matters to underflow.
        #[allow(dead_code)]
        const SQUARE_MIN: f64 = f64::MIN_POSITIVE / f64::EPSILON;

        /// A sum of squares at most this large had no square overflow.
        #[allow(dead_code)]
        const SQUARE_MAX: f64 = f64::EPSILON / f64::MIN_POSITIVE;
    }
}

/// `Default` for every emitted type (taken out of their derive lists by [`rewrite`]).
pub fn emit_defaults(plan: &Plan) -> TokenStream {
    let impls = plan.emitted.iter().map(|&t| {
        let name = format_ident!("{}", plan.types.get(t).name);
        quote! {
            impl ::core::default::Default for #name {
                /// Zero.
                #[inline]
                fn default() -> Self {
                    Self::ZERO
                }
            }
        }
    });
    quote!(#(#impls)*)
}

/// The module's items, written for `f64`, rewritten for the scalar type `path`.
///
/// Every item names the type through the module's alias `Scalar`, defined through
/// `ga_core`'s check: `<[S; checked::<S>()] as Element>::Type` is `S` for a type that
/// implements `ga_core::Scalar`, and for one that does not (`String`, `Vec<f64>`,
/// `num_dual::Dual32`) the bound of `checked` is the one error, at the user's token, and
/// the alias an error type about which the compiler says nothing more. Naming `S` directly
/// gave an error per use: 1106 for G3 over `String`.
pub fn rewrite(items: TokenStream, path: &syn::Path) -> TokenStream {
    let tr = scalar_trait();
    let s = quote!(Scalar);
    let mut constants = Vec::new();
    collect_f64_constants(items.clone(), &mut constants);
    let user_path = quote!(#path);
    let cx = Rewrite {
        s: &s,
        path: &user_path,
        tr: &tr,
        constants: &constants,
    };
    let body = cx.stream(items);
    let check = quote::quote_spanned! {syn::spanned::Spanned::span(path)=>
        ::ga_core::__checked_scalar::checked::<#path>()
    };
    let doc = format!(
        "The scalar type, `{}`, as this module's items name it (through a check that it \
         implements `ga_core::Scalar`, so that a type that does not gets one error).",
        quote!(#path).to_string().replace(' ', "")
    );
    quote! {
        #[allow(unused_imports)]
        use #tr as _;
        #[doc = #doc]
        pub type Scalar = <[#path; #check] as ::ga_core::__checked_scalar::Element>::Type;
        #body
    }
}

/// Whether a token after `last` begins an item: the first token, or one after an
/// attribute, a block or a `;` (so that `-> impl Trait` is not an impl header).
fn starts_item(last: Option<&TokenTree>) -> bool {
    match last {
        None => true,
        Some(TokenTree::Group(g)) => matches!(g.delimiter(), Delimiter::Brace | Delimiter::Bracket),
        Some(TokenTree::Punct(p)) => p.as_char() == ';',
        Some(TokenTree::Ident(i)) => i == "unsafe",
        Some(TokenTree::Literal(_)) => false,
    }
}

fn is_punct(t: Option<&TokenTree>, c: char) -> bool {
    matches!(t, Some(TokenTree::Punct(p)) if p.as_char() == c)
}

fn is_ident(t: Option<&TokenTree>, name: &str) -> bool {
    matches!(t, Some(TokenTree::Ident(i)) if i == name)
}

/// Whether a literal is a floating-point number (`1.0`, `6.0e-11`, `2.5f64`).
fn is_float(lit: &Literal) -> bool {
    let text = lit.to_string();
    let Some(first) = text.chars().next() else {
        return false;
    };
    if !first.is_ascii_digit() || text.starts_with("0x") || text.starts_with("0b") {
        return false;
    }
    let body = text
        .strip_suffix("f64")
        .or_else(|| text.strip_suffix("f32"))
        .unwrap_or(&text);
    let suffixed = body.len() != text.len();
    if body
        .chars()
        .any(|c| c.is_ascii_alphabetic() && c != 'e' && c != 'E')
    {
        return false;
    }
    suffixed || body.contains(['.', 'e', 'E'])
}

/// `<S as Scalar>::from_f64(inner)`.
fn lift(s: &TokenStream, tr: &TokenStream, inner: TokenStream) -> TokenStream {
    quote!(<#s as #tr>::from_f64(#inner))
}

/// The names of the `const NAME: f64 = ...;` items anywhere in `stream`.
fn collect_f64_constants(stream: TokenStream, names: &mut Vec<String>) {
    let tokens: Vec<TokenTree> = stream.into_iter().collect();
    for (i, t) in tokens.iter().enumerate() {
        match t {
            TokenTree::Group(g) => collect_f64_constants(g.stream(), names),
            TokenTree::Ident(k) if k == "const" => {
                if let (Some(TokenTree::Ident(name)), true, true) = (
                    tokens.get(i + 1),
                    is_punct(tokens.get(i + 2), ':'),
                    is_ident(tokens.get(i + 3), "f64"),
                ) {
                    names.push(name.to_string());
                }
            }
            _ => {}
        }
    }
}

/// What the rewrite needs: the scalar type, the trait, the `f64` constants' names.
struct Rewrite<'a> {
    s: &'a TokenStream,
    /// The user's path, which impl headers name instead of `s`: `impl From<Scalar> for
    /// Even` with `Scalar` an error type might overlap `impl<T> From<T> for T`, an error
    /// more when the scalar is not one.
    path: &'a TokenStream,
    tr: &'a TokenStream,
    constants: &'a [String],
}

impl Rewrite<'_> {
    fn stream(&self, input: TokenStream) -> TokenStream {
        let (s, tr) = (self.s, self.tr);
        let tokens: Vec<TokenTree> = input.into_iter().collect();
        let mut out: Vec<TokenTree> = Vec::with_capacity(tokens.len());
        let mut i = 0;
        // Between an item's `impl` and its body.
        let mut impl_header = false;
        while i < tokens.len() {
            let token = &tokens[i];
            let next = tokens.get(i + 1);
            match token {
                TokenTree::Ident(ident) if ident == "impl" && starts_item(out.last()) => {
                    impl_header = true;
                    out.push(token.clone());
                    i += 1;
                }
                TokenTree::Ident(ident) if ident == "f64" && impl_header => {
                    out.extend(self.path.clone());
                    i += 1;
                }
                TokenTree::Group(group) => {
                    if group.delimiter() == Delimiter::Brace {
                        impl_header = false;
                    }
                    let inner = if group.delimiter() == Delimiter::Bracket
                        && is_ident(group.stream().into_iter().next().as_ref(), "derive")
                        && is_punct(out.last(), '#')
                    {
                        without_default(group.stream())
                    } else if group.delimiter() == Delimiter::Brace
                        && is_ident(out.get(out.len().wrapping_sub(2)), "mod")
                    {
                        // A nested module (`mod math`) names the alias one level up.
                        let s = self.s;
                        let inner = Rewrite {
                            s: &quote!(super::#s),
                            ..*self
                        };
                        inner.stream(group.stream())
                    } else {
                        self.stream(group.stream())
                    };
                    let mut g = Group::new(group.delimiter(), inner);
                    g.set_span(group.span());
                    out.push(TokenTree::Group(g));
                    i += 1;
                }
                // `::core::f64::consts::NAME`: an f64 constant, lifted.
                TokenTree::Punct(p)
                    if p.as_char() == ':'
                        && is_punct(next, ':')
                        && is_ident(tokens.get(i + 2), "core")
                        && is_ident(tokens.get(i + 5), "f64")
                        && is_ident(tokens.get(i + 8), "consts")
                        && tokens.get(i + 11).is_some() =>
                {
                    let constant: TokenStream = tokens[i..i + 12].iter().cloned().collect();
                    out.extend(lift(s, tr, constant));
                    i += 12;
                }
                // `x != 0.0` guards skip work for a zero multiplier (the inverse's elimination):
                // with derivative parts the work is skipped only when every part is zero.
                TokenTree::Punct(p)
                    if p.as_char() == '!'
                        && is_punct(next, '=')
                        && matches!(out.last(), Some(TokenTree::Ident(_)))
                        && matches!(tokens.get(i + 2), Some(TokenTree::Literal(l))
                        if is_float(l) && l.to_string().parse::<f64>() == Ok(0.0)) =>
                {
                    let operand: TokenStream = out.pop().into_iter().collect();
                    out.extend(quote!(!<#s as #tr>::is_exact_zero(#operand)));
                    i += 3;
                }
                // `const NAME: f64 = ...;` stays as written, in f64.
                TokenTree::Ident(ident)
                    if ident == "const"
                        && is_punct(tokens.get(i + 2), ':')
                        && is_ident(tokens.get(i + 3), "f64") =>
                {
                    while i < tokens.len() {
                        let end = is_punct(tokens.get(i), ';');
                        out.push(tokens[i].clone());
                        i += 1;
                        if end {
                            break;
                        }
                    }
                }
                TokenTree::Ident(ident)
                    if self.constants.iter().any(|c| ident == c) && !is_punct(out.last(), ':') =>
                {
                    out.extend(lift(s, tr, quote!(#ident)));
                    i += 1;
                }
                TokenTree::Ident(ident) if ident == "as" && is_ident(next, "f64") => {
                    // `x as f64`: the operand is the one token tree before.
                    let operand: TokenStream = out.pop().into_iter().collect();
                    out.extend(lift(s, tr, quote!(#operand as f64)));
                    i += 2;
                }
                TokenTree::Ident(ident) if ident == "f64" && is_punct(next, ':') => {
                    // `f64::from(x)` lifts an f64; `f64::NAME` is the trait's constant.
                    if is_ident(tokens.get(i + 3), "from") {
                        let call: TokenStream = tokens[i..i + 5].iter().cloned().collect();
                        out.extend(lift(s, tr, call));
                        i += 5;
                    } else {
                        out.extend(quote!(<#s as #tr>));
                        i += 1;
                    }
                }
                TokenTree::Ident(ident) if ident == "f64" => {
                    out.extend(s.clone());
                    i += 1;
                }
                // Display's exponent form needs `LowerExp`, which num-dual's types (and a
                // user's) need not have: a generic scalar prints in the plain form.
                TokenTree::Literal(lit)
                    if ["\"{:.*e}\"", "\"{:e}\""].contains(&lit.to_string().as_str()) =>
                {
                    let plain = if lit.to_string() == "\"{:e}\"" {
                        "{}"
                    } else {
                        "{:.*}"
                    };
                    let mut replaced = Literal::string(plain);
                    replaced.set_span(lit.span());
                    out.push(TokenTree::Literal(replaced));
                    i += 1;
                }
                TokenTree::Literal(lit) if is_float(lit) && !is_punct(out.last(), '.') => {
                    let value: Option<f64> = lit
                        .to_string()
                        .trim_end_matches("f64")
                        .trim_end_matches("f32")
                        .replace('_', "")
                        .parse()
                        .ok();
                    match value {
                        Some(0.0) => out.extend(quote!(<#s as #tr>::ZERO)),
                        Some(1.0) => out.extend(quote!(<#s as #tr>::ONE)),
                        _ => {
                            let plain = Literal::f64_unsuffixed(value.unwrap_or(f64::NAN));
                            out.extend(lift(s, tr, quote!(#plain)));
                        }
                    }
                    // `0.0 as f64`: the cast is now the lift's.
                    if is_ident(next, "as") && is_ident(tokens.get(i + 2), "f64") {
                        i += 3;
                    } else {
                        i += 1;
                    }
                }
                other => {
                    out.push(other.clone());
                    i += 1;
                }
            }
        }
        out.into_iter().collect()
    }
}

/// A `derive(...)` attribute's contents without `Default`.
fn without_default(stream: TokenStream) -> TokenStream {
    let mut tokens = stream.into_iter();
    let mut out: Vec<TokenTree> = Vec::new();
    for t in tokens.by_ref() {
        match t {
            TokenTree::Group(g) if g.delimiter() == Delimiter::Parenthesis => {
                let kept: Vec<TokenTree> = g
                    .stream()
                    .into_iter()
                    .collect::<Vec<_>>()
                    .split(|t| is_punct(Some(t), ','))
                    .filter(|part| !(part.len() == 1 && is_ident(part.first(), "Default")))
                    .map(|part| part.to_vec())
                    .collect::<Vec<_>>()
                    .join(&TokenTree::Punct(Punct::new(',', Spacing::Alone)));
                let mut ng = Group::new(Delimiter::Parenthesis, kept.into_iter().collect());
                ng.set_span(g.span());
                out.push(TokenTree::Group(ng));
            }
            other => out.push(other),
        }
    }
    out.into_iter().collect()
}
