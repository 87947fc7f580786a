use proc_macro2::TokenStream;
use syn::parse::{Parse, ParseStream};
use syn::punctuated::Punctuated;
use syn::{bracketed, parenthesized, Attribute, Ident, LitInt, Token, Visibility};

/// The function-like form as written: `#[attrs] vis mod name { key: value, ... }`.
pub struct RawAlgebra {
    pub attrs: Vec<Attribute>,
    pub vis: Visibility,
    pub name: Ident,
    pub entries: Vec<RawEntry>,
}

/// The derive form: the marker type and the contents of its `#[algebra(...)]` attribute.
pub struct RawDerive {
    pub attrs: Vec<Attribute>,
    pub vis: Visibility,
    pub name: Ident,
    pub entries: Vec<RawEntry>,
}

/// One `key: value` (or `key = value` in the derive form) pair; the value is kept as
/// tokens so that an unknown key does not stop the rest from being checked.
pub struct RawEntry {
    pub key: Ident,
    pub value: TokenStream,
}

/// `metric: [1, -1, 0]`: each entry as the tokens written between the commas (not as an
/// expression: syn without its `full` feature cannot parse `+1` or `[1]`, and an
/// expression would let `--1` or `0x1` through), so that a wrong one can be pointed at.
pub struct RawMetric {
    pub bracket: proc_macro2::Span,
    pub entries: Vec<TokenStream>,
}

/// `signature: (p, q, r)`.
pub struct RawSignature {
    pub paren: proc_macro2::Span,
    pub counts: Vec<LitInt>,
}

/// One element of `types: [...]`: a built-in name, or `Name = [e12, e13]`.
pub struct RawTypeRequest {
    pub name: Ident,
    pub blades: Option<Vec<Ident>>,
}

/// `types: [...]`.
pub struct RawTypes(pub Vec<RawTypeRequest>);

/// `ops: [...]`.
pub struct RawOps(pub Vec<Ident>);

impl Parse for RawAlgebra {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let attrs = input.call(Attribute::parse_outer)?;
        let vis: Visibility = input.parse()?;
        input.parse::<Token![mod]>()?;
        let name: Ident = input.parse()?;
        let body;
        syn::braced!(body in input);
        let entries = parse_entries(&body, EntryStyle::Colon)?;
        if !input.is_empty() {
            return Err(input.error("expected one `mod` item in `algebra!`"));
        }
        Ok(RawAlgebra {
            attrs,
            vis,
            name,
            entries,
        })
    }
}

impl RawDerive {
    /// Reads the marker type of `#[derive(Algebra)]` and its `#[algebra(...)]` attribute.
    pub fn from_derive(input: syn::DeriveInput) -> syn::Result<Self> {
        let not_a_struct = match &input.data {
            syn::Data::Struct(_) => None,
            syn::Data::Enum(data) => Some(data.enum_token.span),
            syn::Data::Union(data) => Some(data.union_token.span),
        };
        if let Some(span) = not_a_struct {
            return Err(syn::Error::new(
                span,
                "`#[derive(Algebra)]` goes on a marker struct, e.g. `struct G3;`: write \
                 `struct` here",
            ));
        }
        let mut entries = Vec::new();
        let mut found = false;
        for attr in &input.attrs {
            if attr.path().is_ident("algebra") {
                found = true;
                entries.extend(attr.parse_args_with(|stream: ParseStream| {
                    parse_entries(stream, EntryStyle::Equals)
                })?);
            }
        }
        if !found {
            return Err(syn::Error::new_spanned(
                &input.ident,
                "missing `#[algebra(metric = [...], scalar = f64)]` on the marker type",
            ));
        }
        let attrs = input
            .attrs
            .into_iter()
            .filter(|a| a.path().is_ident("doc"))
            .collect();
        Ok(RawDerive {
            attrs,
            vis: input.vis,
            name: input.ident,
            entries,
        })
    }
}

enum EntryStyle {
    Colon,
    Equals,
}

fn parse_entries(input: ParseStream, style: EntryStyle) -> syn::Result<Vec<RawEntry>> {
    let mut entries = Vec::new();
    while !input.is_empty() {
        let key: Ident = input.parse()?;
        // The two forms differ only here; say which one this is, since `metric: [..]`
        // inside `#[algebra(..)]` (or `metric = [..]` in `algebra!`) is the usual slip.
        let separated = match style {
            EntryStyle::Colon => input.parse::<Token![:]>().map(drop),
            EntryStyle::Equals => input.parse::<Token![=]>().map(drop),
        };
        if let Err(e) = separated {
            let message = match style {
                EntryStyle::Colon => format!("expected `:` after `{key}`: write `{key}: value`"),
                EntryStyle::Equals => {
                    format!("expected `=` after `{key}`: the attribute form writes `{key} = value`")
                }
            };
            return Err(syn::Error::new(e.span(), message));
        }
        let mut value = TokenStream::new();
        while !input.is_empty() && !input.peek(Token![,]) {
            let tree: proc_macro2::TokenTree = input.parse()?;
            value.extend([tree]);
        }
        if value.is_empty() {
            return Err(syn::Error::new_spanned(
                &key,
                format!(
                    "`{key}` needs a value, e.g. {}",
                    example_entry(&key, &style)
                ),
            ));
        }
        entries.push(RawEntry { key, value });
        if !input.is_empty() {
            input.parse::<Token![,]>()?;
        }
    }
    Ok(entries)
}

fn example_entry(key: &Ident, style: &EntryStyle) -> String {
    let value = match key.to_string().as_str() {
        "metric" => "[1, 1, 1]",
        "signature" => "(3, 0, 0)",
        "scalar" => "f64",
        "types" => "[Rotor, Vector]",
        "ops" => "[geometric, sandwich]",
        _ => "...",
    };
    match style {
        EntryStyle::Colon => format!("`{key}: {value}`"),
        EntryStyle::Equals => format!("`{key} = {value}`"),
    }
}

impl Parse for RawMetric {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        let bracket = bracketed!(content in input);
        let mut entries = Vec::new();
        while !content.is_empty() {
            let mut entry = TokenStream::new();
            while !content.is_empty() && !content.peek(Token![,]) {
                entry.extend([content.parse::<proc_macro2::TokenTree>()?]);
            }
            if entry.is_empty() {
                return Err(content.error("expected a metric entry (1, -1 or 0) before `,`"));
            }
            entries.push(entry);
            if !content.is_empty() {
                content.parse::<Token![,]>()?;
            }
        }
        Ok(RawMetric {
            bracket: bracket.span.join(),
            entries,
        })
    }
}

impl Parse for RawSignature {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        let paren = parenthesized!(content in input);
        let counts = Punctuated::<LitInt, Token![,]>::parse_terminated(&content)?;
        Ok(RawSignature {
            paren: paren.span.join(),
            counts: counts.into_iter().collect(),
        })
    }
}

impl Parse for RawTypes {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        bracketed!(content in input);
        let mut requests = Vec::new();
        while !content.is_empty() {
            let name: Ident = content.parse()?;
            let blades = if content.peek(Token![=]) {
                content.parse::<Token![=]>()?;
                let list;
                bracketed!(list in content);
                let names = Punctuated::<Ident, Token![,]>::parse_terminated(&list)?;
                Some(names.into_iter().collect())
            } else {
                None
            };
            requests.push(RawTypeRequest { name, blades });
            if !content.is_empty() {
                content.parse::<Token![,]>()?;
            }
        }
        Ok(RawTypes(requests))
    }
}

impl Parse for RawOps {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        bracketed!(content in input);
        let names = Punctuated::<Ident, Token![,]>::parse_terminated(&content)?;
        Ok(RawOps(names.into_iter().collect()))
    }
}

/// `lanes: [4, 8]`.
pub struct RawLanes(pub Vec<LitInt>);

impl Parse for RawLanes {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        bracketed!(content in input);
        let counts = Punctuated::<LitInt, Token![,]>::parse_terminated(&content)?;
        Ok(RawLanes(counts.into_iter().collect()))
    }
}

/// One element of `derive: [...]`: `#[cfg(..)] name` or `name = path::to::crate`.
pub struct RawIntegration {
    pub attrs: Vec<Attribute>,
    pub name: Ident,
    pub path: Option<syn::Path>,
}

/// `derive: [serde, bytemuck = my::bytemuck, #[cfg(feature = "approx")] approx]`.
pub struct RawIntegrations(pub Vec<RawIntegration>);

impl Parse for RawIntegrations {
    fn parse(input: ParseStream) -> syn::Result<Self> {
        let content;
        bracketed!(content in input);
        let mut entries = Vec::new();
        while !content.is_empty() {
            let attrs = content.call(Attribute::parse_outer)?;
            let name: Ident = content.parse()?;
            let path = if content.peek(Token![=]) {
                content.parse::<Token![=]>()?;
                Some(content.call(syn::Path::parse_mod_style)?)
            } else {
                None
            };
            entries.push(RawIntegration { attrs, name, path });
            if !content.is_empty() {
                content.parse::<Token![,]>()?;
            }
        }
        Ok(RawIntegrations(entries))
    }
}
