//! Fixed blocks of generated code written as text with `#name` placeholders and parsed at
//! expansion. A `quote!` compiles to one function call per token, so its large fixed
//! blocks (the scalar functions behind exp and log, the SIMD lane type, the inverse's
//! solver) were a good part of ga-macros' own build, which every user pays; as text they
//! compile to a string and take microseconds to parse. The tokens are those `quote!` would
//! give: call-site spans, and `#name` replaced by the value's tokens. No repetitions: a
//! list is built with `quote!` first and passed in as one value.

use proc_macro2::{Group, Punct, Spacing, TokenStream, TokenTree};
use quote::ToTokens;

/// The tokens of `source` with each `#name` replaced by the tokens of its value.
pub fn fill(source: &str, values: &[(&str, &dyn ToTokens)]) -> TokenStream {
    // The sources are constants of this crate, so a lexing error is a bug in the macro.
    let tokens: TokenStream = source.parse().expect("a template is valid Rust tokens");
    substitute(tokens, values)
}

fn substitute(tokens: TokenStream, values: &[(&str, &dyn ToTokens)]) -> TokenStream {
    let mut out: Vec<TokenTree> = Vec::new();
    let mut tokens = tokens.into_iter().peekable();
    while let Some(token) = tokens.next() {
        match token {
            TokenTree::Punct(hash) if hash.as_char() == '#' => {
                let value = match tokens.peek() {
                    Some(TokenTree::Ident(name)) => values.iter().find(|(n, _)| name == n),
                    _ => None,
                };
                match value {
                    Some((_, value)) => {
                        tokens.next();
                        // The lexer joined the punctuation before `#` to it (`::#s`);
                        // `quote!` leaves the last of `::` alone before a value.
                        if let Some(TokenTree::Punct(last)) = out.last_mut() {
                            if last.spacing() == Spacing::Joint {
                                let mut alone = Punct::new(last.as_char(), Spacing::Alone);
                                alone.set_span(last.span());
                                *last = alone;
                            }
                        }
                        out.extend(value.to_token_stream());
                    }
                    // An attribute's `#`.
                    None => out.push(TokenTree::Punct(hash)),
                }
            }
            TokenTree::Group(group) => {
                let inner = substitute(group.stream(), values);
                let mut filled = Group::new(group.delimiter(), inner);
                filled.set_span(group.span());
                out.push(TokenTree::Group(filled));
            }
            other => out.push(other),
        }
    }
    out.into_iter().collect()
}

#[cfg(test)]
mod tests {
    use quote::quote;

    use super::*;

    #[test]
    fn a_filled_template_is_the_tokens_quote_gives() {
        let s = quote!(f64);
        let sum = quote!(a + b);
        let filled = fill(
            "#[inline] fn f(x: #s) -> [#s; 2] { let y: #s = #sum; [x, y * #s::EPSILON] }",
            &[("s", &s), ("sum", &sum)],
        );
        let quoted = quote! {
            #[inline] fn f(x: #s) -> [#s; 2] { let y: #s = #sum; [x, y * #s::EPSILON] }
        };
        assert_eq!(filled.to_string(), quoted.to_string());
    }
}
